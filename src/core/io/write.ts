/**
 * Writing meshes to files. A mesh is first flattened back into a polygon soup (`meshToSoup`):
 * live vertices numbered densely, each live face as the loop of its halfedges from
 * `fHalfedge[f]` along `next`, halfedge attributes as corner attributes. Each format's writer
 * then writes the soup with the attributes the format can carry, so reading the file back gives
 * the same soup again.
 */
import { attributeArrayTypes, type AttributeArray, type AttributeSet, type AttributeType } from '../attributes.js';
import { InvalidInputError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { PolygonSoup, SoupAttribute } from '../soup.js';
import { firstNonFiniteValue } from './finite.js';
import { writeObj } from './write-obj.js';
import { writeOff } from './write-off.js';
import { writePly } from './write-ply.js';

export type WriteFormat = 'ply' | 'ply-binary' | 'off' | 'obj';

/**
 * Writes a mesh as PLY (ascii or binary little-endian), OFF or OBJ. Deleted elements are left
 * out and the vertices renumbered densely.
 * @example
 *   const bytes = writeMesh(mesh, writeFormatFromFileName('out.ply') ?? 'ply');
 * @throws InvalidInputError when a face loop does not close or uses a deleted vertex, or a value is
 *   NaN or infinite.
 */
export function writeMesh(mesh: HalfedgeMesh, format: WriteFormat): Uint8Array {
  return writeSoup(meshToSoup(mesh), format);
}

/**
 * Writes a polygon soup, with the attributes the format can carry.
 * @example
 *   const bytes = writeSoup(uvSphere(8, 16), 'ply-binary');
 * @throws InvalidInputError when a value is NaN or infinite: no reader takes it back.
 */
export function writeSoup(soup: PolygonSoup, format: WriteFormat): Uint8Array {
  const nonFinite = firstNonFiniteValue(soup);
  if (nonFinite) throw new InvalidInputError(`cannot write the mesh: ${nonFinite}; no reader would take it back`);
  switch (format) {
    case 'ply':
      return writePly(soup, 'ascii');
    case 'ply-binary':
      return writePly(soup, 'binary_little_endian');
    case 'off':
      return writeOff(soup);
    case 'obj':
      return writeObj(soup);
  }
}

/**
 * Writes PLY, OFF, OBJ (as `writeMesh`) or a binary glTF (`'glb'`, see `writeGlb`), whose writer
 * loads on demand.
 * @example
 *   const glb = await writeMeshAsync(mesh, 'glb');
 */
export async function writeMeshAsync(mesh: HalfedgeMesh, format: WriteFormat | 'glb'): Promise<Uint8Array> {
  if (format !== 'glb') return writeMesh(mesh, format);
  const nonFinite = firstNonFiniteValue(meshToSoup(mesh));
  if (nonFinite) throw new InvalidInputError(`cannot write the mesh: ${nonFinite}; no reader would take it back`);
  const { writeGlb } = await import('./gltf.js');
  return writeGlb(mesh);
}

/**
 * `.ply` → 'ply' (ascii), `.off` → 'off', `.obj` → 'obj'; undefined for any other name.
 * @example
 *   writeFormatFromFileName('bunny.PLY'); // 'ply'
 */
export function writeFormatFromFileName(name: string): WriteFormat | undefined {
  const extension = /\.([a-z]+)$/i.exec(name)?.[1].toLowerCase();
  return extension === 'ply' || extension === 'off' || extension === 'obj' ? extension : undefined;
}

/**
 * The mesh as a polygon soup: live vertices renumbered densely (in id order), live faces in id
 * order, each from its `fHalfedge` along `next`; vertex, face and halfedge attributes (the last
 * per face corner). Edge attributes have no place in a soup and are left out.
 * @example
 *   const soup = meshToSoup(mesh); // buildMesh(soup) gives the mesh back, renumbered densely
 * @throws InvalidInputError when a face loop does not close or uses a deleted vertex.
 */
export function meshToSoup(mesh: HalfedgeMesh): PolygonSoup {
  const { heNext, heVertex, fHalfedge, vDeleted, fDeleted } = mesh;
  const vertexIds = new Int32Array(mesh.vertexSlots).fill(-1);
  let vertexCount = 0;
  for (let v = 0; v < mesh.vertexSlots; v++) if (vDeleted[v] === 0) vertexIds[v] = vertexCount++;
  const liveFaces: number[] = [];
  for (let f = 0; f < mesh.faceSlots; f++) if (fDeleted[f] === 0) liveFaces.push(f);

  // corners: one per halfedge of each face loop, walked with a bound so a broken loop cannot hang
  const faceStarts = new Uint32Array(liveFaces.length + 1);
  const corners = new Uint32Array(mesh.halfedgeSlots);
  const halfedges: number[] = [];
  liveFaces.forEach((f, i) => {
    const first = fHalfedge[f];
    let h = first;
    do {
      // every halfedge lies on one loop at most, so more corners than halfedges means a broken loop
      if (!(h >= 0 && h < mesh.halfedgeSlots) || halfedges.length === mesh.halfedgeSlots) {
        throw new InvalidInputError(`the loop of face ${f} does not close (it reaches halfedge ${h})`);
      }
      const v = vertexIds[heVertex[h]];
      if (v === undefined || v < 0) {
        throw new InvalidInputError(`face ${f} uses vertex ${heVertex[h]}, which is deleted or missing`);
      }
      corners[halfedges.length] = v;
      halfedges.push(h);
      h = heNext[h];
    } while (h !== first);
    faceStarts[i + 1] = halfedges.length;
  });

  const liveVertices: number[] = [];
  for (let v = 0; v < mesh.vertexSlots; v++) if (vertexIds[v] >= 0) liveVertices.push(v);
  return {
    positions: pick(mesh.positions, 3, liveVertices, 'float64') as Float64Array,
    faceStarts,
    faceIndices: corners.slice(0, halfedges.length),
    vertexAttributes: attributesOf(mesh.vertexAttributes, liveVertices, 'position'),
    faceAttributes: attributesOf(mesh.faceAttributes, liveFaces),
    cornerAttributes: attributesOf(mesh.halfedgeAttributes, halfedges),
  };
}

function attributesOf(set: AttributeSet, elements: number[], except?: string): SoupAttribute[] {
  const attributes: SoupAttribute[] = [];
  for (const { name, type, itemSize, interpolation, data } of set) {
    if (name !== except) attributes.push({ name, itemSize, interpolation, data: pick(data, itemSize, elements, type) });
  }
  return attributes;
}

/** Items `elements[0], elements[1], …` of `data`, `itemSize` numbers each, in a new array. */
function pick(
  data: Float64Array | AttributeArray,
  itemSize: number,
  elements: number[],
  type: AttributeType,
): AttributeArray {
  const out = new attributeArrayTypes[type](itemSize * elements.length);
  // item by item: a view of the source for each element would cost more than the copy
  elements.forEach((e, i) => {
    for (let k = 0; k < itemSize; k++) out[itemSize * i + k] = data[itemSize * e + k];
  });
  return out;
}
