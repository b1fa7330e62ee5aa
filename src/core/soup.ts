/**
 * A polygon soup: what a mesh file holds before anyone asks how its faces connect. Positions,
 * then each face as a list of vertex indices, counter-clockwise seen from outside.
 *
 * The faces are stored flat (CSR): face `f` uses `faceIndices[faceStarts[f] … faceStarts[f+1])`.
 * This is what the readers produce and what `buildMesh` consumes; it is cheap to transfer to a
 * worker and holds a million triangles in 16 MB of indices.
 */
import type { AttributeArray, Interpolation } from './attributes.js';
import { InvalidInputError } from './errors.js';

/** Per-element data that comes with a soup (colours, normals, texture coordinates, labels). */
export interface SoupAttribute {
  name: string;
  itemSize: number;
  data: AttributeArray;
  interpolation?: Interpolation;
}

export interface PolygonSoup {
  /** x, y, z of each vertex. */
  positions: Float64Array | Float32Array;
  /** Length = number of faces + 1; `faceStarts[0] = 0`, non-decreasing. */
  faceStarts: Uint32Array | Int32Array;
  /** Vertex index of each face corner. */
  faceIndices: Uint32Array | Int32Array;
  /** One item per vertex. */
  vertexAttributes?: SoupAttribute[];
  /** One item per face. */
  faceAttributes?: SoupAttribute[];
  /** One item per face corner (an entry of `faceIndices`), such as OBJ texture coordinates. */
  cornerAttributes?: SoupAttribute[];
}

export function soupVertexCount(soup: PolygonSoup): number {
  return Math.floor(soup.positions.length / 3);
}

export function soupFaceCount(soup: PolygonSoup): number {
  return Math.max(0, soup.faceStarts.length - 1);
}

/**
 * Makes a soup from plain arrays.
 * @example
 *   const quad = soupFromArrays([0,0,0, 1,0,0, 1,1,0, 0,1,0], [[0, 1, 2, 3]]);
 */
export function soupFromArrays(positions: ArrayLike<number>, faces: ArrayLike<ArrayLike<number>>): PolygonSoup {
  const faceStarts = new Uint32Array(faces.length + 1);
  for (let f = 0; f < faces.length; f++) faceStarts[f + 1] = faceStarts[f] + faces[f].length;
  const faceIndices = new Uint32Array(faceStarts[faces.length]);
  for (let f = 0; f < faces.length; f++) faceIndices.set(Array.from(faces[f]), faceStarts[f]);
  return { positions: Float64Array.from(positions), faceStarts, faceIndices };
}

/** Makes a soup of faces that all have `degree` corners, from one flat index array. */
export function soupFromUniformFaces(
  positions: Float64Array | Float32Array,
  indices: Uint32Array | Int32Array,
  degree = 3,
): PolygonSoup {
  if (indices.length % degree !== 0) {
    throw new InvalidInputError(`${indices.length} indices do not make whole faces of ${degree} corners`);
  }
  const faceCount = indices.length / degree;
  const faceStarts = new Uint32Array(faceCount + 1);
  for (let f = 0; f <= faceCount; f++) faceStarts[f] = f * degree;
  return { positions, faceStarts, faceIndices: indices };
}

/** Throws `InvalidInputError` unless the soup's arrays are shaped as documented. */
export function checkSoupShape(soup: PolygonSoup): void {
  const { positions, faceStarts, faceIndices } = soup;
  if (positions.length % 3 !== 0) {
    throw new InvalidInputError(`positions has ${positions.length} numbers, not a multiple of 3 (x, y, z per vertex)`);
  }
  if (faceStarts.length === 0 || faceStarts[0] !== 0) {
    throw new InvalidInputError('faceStarts must begin with 0 (and have one entry per face plus one)');
  }
  for (let f = 0; f + 1 < faceStarts.length; f++) {
    if (faceStarts[f + 1] < faceStarts[f]) {
      throw new InvalidInputError(`faceStarts decreases at face ${f}: ${faceStarts[f]} then ${faceStarts[f + 1]}`);
    }
  }
  if (faceStarts[faceStarts.length - 1] !== faceIndices.length) {
    throw new InvalidInputError(
      `faceStarts ends at ${faceStarts[faceStarts.length - 1]} but faceIndices has ${faceIndices.length} entries`,
    );
  }
  const counts = {
    vertex: positions.length / 3,
    face: faceStarts.length - 1,
    corner: faceIndices.length,
  };
  const groups = [
    ['vertex', soup.vertexAttributes],
    ['face', soup.faceAttributes],
    ['corner', soup.cornerAttributes],
  ] as const;
  for (const [kind, attributes] of groups) {
    for (const attribute of attributes ?? []) {
      if (attribute.data.length !== counts[kind] * attribute.itemSize) {
        throw new InvalidInputError(
          `${kind} attribute '${attribute.name}' has ${attribute.data.length} numbers; ` +
            `${counts[kind]} ${kind}s × ${attribute.itemSize} = ${counts[kind] * attribute.itemSize} expected`,
        );
      }
    }
  }
}

/**
 * One soup holding several, side by side (vertex ids of each shifted past the previous ones).
 * Attributes are dropped unless every soup has them with the same shape.
 * @example const scene = mergeSoups([cube(), torus(8, 6)]);
 */
export function mergeSoups(soups: PolygonSoup[]): PolygonSoup {
  const vertexCount = soups.reduce((n, s) => n + s.positions.length / 3, 0);
  const faceCount = soups.reduce((n, s) => n + s.faceStarts.length - 1, 0);
  const cornerCount = soups.reduce((n, s) => n + s.faceIndices.length, 0);
  const positions = new Float64Array(3 * vertexCount);
  const faceStarts = new Uint32Array(faceCount + 1);
  const faceIndices = new Uint32Array(cornerCount);
  let vertexOffset = 0;
  let faceOffset = 0;
  let cornerOffset = 0;
  for (const soup of soups) {
    positions.set(soup.positions, 3 * vertexOffset);
    for (let f = 1; f < soup.faceStarts.length; f++) faceStarts[faceOffset + f] = cornerOffset + soup.faceStarts[f];
    for (let i = 0; i < soup.faceIndices.length; i++) faceIndices[cornerOffset + i] = soup.faceIndices[i] + vertexOffset;
    vertexOffset += soup.positions.length / 3;
    faceOffset += soup.faceStarts.length - 1;
    cornerOffset += soup.faceIndices.length;
  }
  const merged: PolygonSoup = { positions, faceStarts, faceIndices };
  for (const key of ['vertexAttributes', 'faceAttributes', 'cornerAttributes'] as const) {
    const first = soups[0]?.[key];
    if (!first) continue;
    const attributes = first.flatMap((attribute) => {
      const parts = soups.map((s) => s[key]?.find((a) => a.name === attribute.name));
      if (parts.some((a) => !a || a.itemSize !== attribute.itemSize || a.data.constructor !== attribute.data.constructor)) {
        return [];
      }
      const length = parts.reduce((n, a) => n + a!.data.length, 0);
      const data = new (attribute.data.constructor as new (n: number) => typeof attribute.data)(length);
      let offset = 0;
      for (const part of parts) {
        data.set(part!.data, offset);
        offset += part!.data.length;
      }
      return [{ ...attribute, data }];
    });
    if (attributes.length > 0) merged[key] = attributes;
  }
  return merged;
}
