/** Fixtures and checks for the plane cut. */
import { expect } from 'vitest';
import { buildMesh } from '../../src/core/build.js';
import { type PlaneCutOptions, planeCut, type Plane, unitPlane } from '../../src/core/cut/index.js';
import { boundingBox, signedVolume } from '../../src/core/geometry.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { type Phase, type PhaseElements, phaseElements } from '../../src/core/change/operation.js';
import { uvSphere, voxelSurface } from '../../src/core/shapes.js';
import { mergeSoups, type PolygonSoup, soupFromArrays } from '../../src/core/soup.js';
import { validate } from '../../src/core/validate.js';

export function meshOf(soup: PolygonSoup): HalfedgeMesh {
  const { mesh, report } = buildMesh(soup);
  expect(report.repairs).toEqual([]);
  return mesh;
}

/** Steps through the cut, checking the mesh after every phase; returns the phases. */
export function stepCut(mesh: HalfedgeMesh, plane: Plane, options: PlaneCutOptions = {}): CutPhase[] {
  const phases: CutPhase[] = [];
  for (const phase of planeCut(mesh, plane, options)) {
    expect(validate(mesh), `after "${phase.name}"`).toEqual([]);
    phases.push({ ...phase, ...phaseElements(phase.change!) });
  }
  return phases;
}

/** A phase of the cut with what its record says it created, moved, rewired and removed. */
export type CutPhase = Phase & PhaseElements;

/** Volumes of the capped halves above and below the plane, each cut from a copy of `mesh`. */
export function halfVolumes(mesh: HalfedgeMesh, plane: Plane): [number, number] {
  return (['above', 'below'] as const).map((keep) => {
    const half = mesh.clone();
    stepCut(half, plane, { keep });
    return signedVolume(half);
  }) as [number, number];
}

/** Length of the bounding-box diagonal. */
export function size(mesh: HalfedgeMesh): number {
  const { min, max } = boundingBox(mesh)!;
  return Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
}

/** Largest distance from the plane of a corner of the faces the cap phase made. */
export function capDistance(mesh: HalfedgeMesh, phases: CutPhase[], plane: Plane): number {
  const { nx, ny, nz, d } = unitPlane(plane);
  let worst = 0;
  for (const f of phases[5].created?.faces ?? []) {
    let h = mesh.fHalfedge[f];
    do {
      const [x, y, z] = mesh.position(mesh.heVertex[h]);
      worst = Math.max(worst, Math.abs(nx * x + ny * y + nz * z + d));
      h = mesh.heNext[h];
    } while (h !== mesh.fHalfedge[f]);
  }
  return worst;
}

/** The faces of a soup turned inside out. */
function inverted(soup: PolygonSoup, scale: number): PolygonSoup {
  const faces: number[][] = [];
  for (let f = 0; f + 1 < soup.faceStarts.length; f++) {
    faces.push(Array.from(soup.faceIndices.subarray(soup.faceStarts[f], soup.faceStarts[f + 1])).reverse());
  }
  return soupFromArrays(Array.from(soup.positions, (x) => scale * x), faces);
}

/** A ball with a ball-shaped cavity: the outer sphere faces out, the inner one (radius 0.5) in. */
export function hollowBall(): PolygonSoup {
  return mergeSoups([uvSphere(10, 16), inverted(uvSphere(8, 12), 0.5)]);
}

/** The lower half of a sphere (its rim on z = 0): open, one boundary loop. */
export function bowl(): PolygonSoup {
  const sphere = uvSphere(8, 12);
  const ids = new Map<number, number>();
  const positions: number[] = [];
  const faces: number[][] = [];
  for (let f = 0; f + 1 < sphere.faceStarts.length; f++) {
    const corners = Array.from(sphere.faceIndices.subarray(sphere.faceStarts[f], sphere.faceStarts[f + 1]));
    if (!corners.every((v) => sphere.positions[3 * v + 2] <= 0)) continue;
    faces.push(
      corners.map((v) => {
        if (!ids.has(v)) {
          ids.set(v, ids.size);
          positions.push(...sphere.positions.subarray(3 * v, 3 * v + 3));
        }
        return ids.get(v)!;
      }),
    );
  }
  return soupFromArrays(positions, faces);
}

/** A U-shaped prism, 1 high: each of its U faces is crossed twice by the plane y = 2. */
export function uPrism(): PolygonSoup {
  const u = [0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3];
  const positions = [0, 1].flatMap((z) => Array.from({ length: 8 }, (_, i) => [u[2 * i], u[2 * i + 1], z]).flat());
  const faces = [
    [7, 6, 5, 4, 3, 2, 1, 0],
    [8, 9, 10, 11, 12, 13, 14, 15],
    ...Array.from({ length: 8 }, (_, i) => [i, (i + 1) % 8, 8 + ((i + 1) % 8), 8 + i]),
  ];
  return soupFromArrays(positions, faces);
}

/** Four voxels in a 2 × 2 slab with one more on top of a corner: volume 5. */
export function steppedBlock(): PolygonSoup {
  return voxelSurface([
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 0],
    [0, 0, 1],
  ]);
}
