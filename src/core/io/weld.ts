/**
 * Welding: vertices at the same position become one. A glTF file (like any GPU vertex buffer)
 * splits a vertex wherever a normal or a texture coordinate differs — along UV seams and sharp
 * edges — so a mesh built from its vertices as they are is cut open along every seam. Welded, the
 * halfedge mesh is the real surface; the values that differ stay per corner.
 */

export interface Weld {
  /** For each input vertex, the welded vertex it became. */
  remap: Uint32Array;
  /** x, y, z of each welded vertex (the first input vertex's position). */
  positions: Float64Array;
}

/**
 * Welds vertices whose positions are exactly equal (`tolerance` 0, -0 equal to 0), or within
 * `tolerance` of a vertex welded before them (Euclidean distance).
 * @example
 *   weldPositions(Float64Array.of(0,0,0, 1,0,0, 0,0,0)).remap; // [0, 1, 0]
 */
export function weldPositions(positions: ArrayLike<number>, tolerance = 0): Weld {
  const count = Math.floor(positions.length / 3);
  return tolerance > 0 ? weldWithin(positions, count, tolerance) : weldExact(positions, count);
}

function weldExact(positions: ArrayLike<number>, count: number): Weld {
  const remap = new Uint32Array(count);
  const welded = new Float64Array(3 * count);
  // open addressing over a power-of-two table at most half full, keyed on the coordinates' bits
  const size = 2 ** Math.ceil(Math.log2(2 * count + 2));
  const table = new Int32Array(size).fill(-1);
  const bits = new Float64Array(3);
  const words = new Uint32Array(bits.buffer);
  let next = 0;
  for (let i = 0; i < count; i++) {
    // + 0 turns -0 into 0, so the two hash and compare alike
    const x = positions[3 * i] + 0;
    const y = positions[3 * i + 1] + 0;
    const z = positions[3 * i + 2] + 0;
    bits[0] = x;
    bits[1] = y;
    bits[2] = z;
    let hash = 0x811c9dc5;
    for (let w = 0; w < 6; w++) hash = Math.imul(hash ^ words[w], 0x01000193);
    let slot = (hash ^ (hash >>> 15)) & (size - 1);
    // the table is at most half full, so a free slot comes within `size` probes
    for (let probe = 0; probe < size; probe++) {
      const found = table[slot];
      if (found === -1) {
        table[slot] = next;
        welded[3 * next] = x;
        welded[3 * next + 1] = y;
        welded[3 * next + 2] = z;
        remap[i] = next++;
        break;
      }
      if (welded[3 * found] === x && welded[3 * found + 1] === y && welded[3 * found + 2] === z) {
        remap[i] = found;
        break;
      }
      slot = (slot + 1) & (size - 1);
    }
  }
  return { remap, positions: welded.slice(0, 3 * next) };
}

function weldWithin(positions: ArrayLike<number>, count: number, tolerance: number): Weld {
  const remap = new Uint32Array(count);
  const welded = new Float64Array(3 * count);
  // a grid of cells at least as wide as the tolerance: a vertex within it lies in one of the 27
  // cells around. A tolerance far below the coordinates' precision widens the cells (never the
  // distance that welds), so that cell numbers stay exact integers rather than one huge cell.
  let largest = 0;
  for (let i = 0; i < 3 * count; i++) if (Math.abs(positions[i]) > largest && Number.isFinite(positions[i])) largest = Math.abs(positions[i]);
  const width = Math.max(tolerance, largest * 2 ** -48);
  const cells = new Map<string, number[]>();
  const cellOf = (value: number) => Math.floor(value / width);
  const squared = tolerance * tolerance;
  let next = 0;
  for (let i = 0; i < count; i++) {
    const x = positions[3 * i];
    const y = positions[3 * i + 1];
    const z = positions[3 * i + 2];
    // NaN or infinity (which the reader refuses afterwards) welds to nothing: no cell collects them all
    if (!Number.isFinite(x + y + z)) {
      welded.set([x, y, z], 3 * next);
      remap[i] = next++;
      continue;
    }
    const [cx, cy, cz] = [cellOf(x), cellOf(y), cellOf(z)];
    let match = -1;
    for (let dx = -1; dx <= 1 && match < 0; dx++) {
      for (let dy = -1; dy <= 1 && match < 0; dy++) {
        for (let dz = -1; dz <= 1 && match < 0; dz++) {
          for (const w of cells.get(`${cx + dx},${cy + dy},${cz + dz}`) ?? []) {
            const [ex, ey, ez] = [welded[3 * w] - x, welded[3 * w + 1] - y, welded[3 * w + 2] - z];
            if (ex * ex + ey * ey + ez * ez <= squared) {
              match = w;
              break;
            }
          }
        }
      }
    }
    if (match < 0) {
      match = next++;
      welded.set([x, y, z], 3 * match);
      const key = `${cx},${cy},${cz}`;
      const cell = cells.get(key);
      if (cell) cell.push(match);
      else cells.set(key, [match]);
    }
    remap[i] = match;
  }
  return { remap, positions: welded.slice(0, 3 * next) };
}
