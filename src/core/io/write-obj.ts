/**
 * Writing OBJ: `v` lines (with `r g b` when vertices have colours), `vt` and `vn` lines, then
 * `f` lines whose corners are `v`, `v/vt`, `v//vn` or `v/vt/vn`, counted from 1. Texture
 * coordinates and normals come from the corners (halfedges) when they have them, each distinct
 * value written once, else from the vertices, one per vertex. OBJ numbers carry no type and read
 * back as float64, so positions are written with all the digits a float64 needs.
 */
import { attributeTypeOf } from '../attributes.js';
import { plural } from '../report.js';
import type { PolygonSoup, SoupAttribute } from '../soup.js';
import { formatFloat32, formatFloat64, numberFormat, TextOutput } from './output.js';

/** Writes a soup as OBJ with its colours, texture coordinates and normals. */
export function writeObj(soup: PolygonSoup): Uint8Array {
  const { positions, faceStarts, faceIndices } = soup;
  const vertexCount = positions.length / 3;
  const out = new TextOutput();
  out.line(`# ${plural(vertexCount, 'vertex', 'vertices')}, ${plural(faceStarts.length - 1, 'face')}`);

  const color = soup.vertexAttributes?.find((a) => a.name === 'color' && (a.itemSize === 3 || a.itemSize === 4));
  // OBJ colours are reals 0…1: uint8 ones are scaled
  const colorScale = color && attributeTypeOf(color.data) === 'uint8' ? 1 / 255 : 1;
  for (let v = 0; v < vertexCount; v++) {
    let line = 'v';
    for (let k = 0; k < 3; k++) line += ` ${formatFloat64(positions[3 * v + k])}`;
    if (color) {
      for (let k = 0; k < 3; k++) line += ` ${formatFloat32(color.data[color.itemSize * v + k] * colorScale)}`;
    }
    out.line(line);
  }
  const texcoordIds = writeValues(out, 'vt', 2, soup, 'texcoord');
  const normalIds = writeValues(out, 'vn', 3, soup, 'normal');

  for (let f = 0; f + 1 < faceStarts.length; f++) {
    let line = 'f';
    for (let c = faceStarts[f]; c < faceStarts[f + 1]; c++) {
      line += ` ${faceIndices[c] + 1}`;
      if (texcoordIds) line += `/${texcoordIds[c] + 1}`;
      else if (normalIds) line += '/';
      if (normalIds) line += `/${normalIds[c] + 1}`;
    }
    out.line(line);
  }
  return out.bytes();
}

/**
 * Writes the `vt` or `vn` lines of attribute `name` (from the corners, else the vertices) and
 * returns which of them (from 0) each face corner refers to, or null without such an attribute.
 */
function writeValues(
  out: TextOutput,
  keyword: string,
  itemSize: number,
  soup: PolygonSoup,
  name: string,
): Int32Array | null {
  const find = (list: SoupAttribute[] | undefined) => list?.find((a) => a.name === name && a.itemSize === itemSize);
  const perCorner = find(soup.cornerAttributes);
  const attribute = perCorner ?? find(soup.vertexAttributes);
  if (!attribute) return null;
  const format = numberFormat(attributeTypeOf(attribute.data));
  const text = (i: number) => Array.from(attribute.data.subarray(itemSize * i, itemSize * (i + 1)), format).join(' ');
  const cornerCount = soup.faceIndices.length;
  const ids = new Int32Array(cornerCount);
  if (perCorner) {
    // each distinct value once: corners along a smooth surface share theirs
    const idOf = new Map<string, number>();
    for (let c = 0; c < cornerCount; c++) {
      const value = text(c);
      let id = idOf.get(value);
      if (id === undefined) {
        idOf.set(value, (id = idOf.size));
        out.line(`${keyword} ${value}`);
      }
      ids[c] = id;
    }
  } else {
    for (let v = 0; v < soup.positions.length / 3; v++) out.line(`${keyword} ${text(v)}`);
    ids.set(soup.faceIndices);
  }
  return ids;
}
