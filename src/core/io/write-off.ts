/**
 * Writing OFF: the keyword names what each vertex line carries (`[ST][C][N]OFF`), then each
 * vertex as `x y z [nx ny nz] [r g b [a]] [s t]` and each face as its corner count, its vertex
 * ids and its colour if faces have one. Colours keep their kind: uint8 ones are written as
 * integers 0…255, float ones always with a decimal point, which is how a reader tells them apart.
 * OFF numbers carry no type and read back as float64, so positions are written with all the
 * digits a float64 needs.
 */
import { attributeTypeOf } from '../attributes.js';
import type { PolygonSoup, SoupAttribute } from '../soup.js';
import { formatFloat64, numberFormat, TextOutput } from './output.js';

/**
 * Writes a soup as text OFF with vertex normals, colours and texture coordinates and face
 * colours when it has them.
 */
export function writeOff(soup: PolygonSoup): Uint8Array {
  const { positions, faceStarts, faceIndices } = soup;
  const vertexCount = positions.length / 3;
  const faceCount = faceStarts.length - 1;
  const find = (list: SoupAttribute[] | undefined, name: string, sizes: number[]) =>
    list?.find((a) => a.name === name && sizes.includes(a.itemSize));
  const normal = find(soup.vertexAttributes, 'normal', [3]);
  const vertexColor = find(soup.vertexAttributes, 'color', [3, 4]);
  const texcoord = find(soup.vertexAttributes, 'texcoord', [2]);
  const faceColor = find(soup.faceAttributes, 'color', [3, 4]);

  const out = new TextOutput();
  out.line(`${texcoord ? 'ST' : ''}${vertexColor ? 'C' : ''}${normal ? 'N' : ''}OFF`);
  out.line(`${vertexCount} ${faceCount} 0`);
  const parts: string[] = [];
  const append = (attribute: SoupAttribute | undefined, i: number, format: (x: number) => string) => {
    if (!attribute) return;
    const { itemSize, data } = attribute;
    for (let k = 0; k < itemSize; k++) parts.push(format(data[itemSize * i + k]));
  };
  const formatFloat32 = numberFormat('float32');
  const formatVertexColor = colorFormat(vertexColor);
  const formatFaceColor = colorFormat(faceColor);
  for (let v = 0; v < vertexCount; v++) {
    parts.length = 0;
    for (let k = 0; k < 3; k++) parts.push(formatFloat64(positions[3 * v + k]));
    append(normal, v, formatFloat32);
    append(vertexColor, v, formatVertexColor);
    append(texcoord, v, formatFloat32);
    out.line(parts.join(' '));
  }
  for (let f = 0; f < faceCount; f++) {
    parts.length = 0;
    parts.push(String(faceStarts[f + 1] - faceStarts[f]));
    for (let c = faceStarts[f]; c < faceStarts[f + 1]; c++) parts.push(String(faceIndices[c]));
    append(faceColor, f, formatFaceColor);
    out.line(parts.join(' '));
  }
  return out.bytes();
}

/** uint8 colours as integers; any other type as numbers with a decimal point ("1.0", not "1"). */
function colorFormat(color: SoupAttribute | undefined): (x: number) => string {
  if (!color || attributeTypeOf(color.data) === 'uint8') return String;
  const format = numberFormat(attributeTypeOf(color.data));
  return (x) => {
    const text = format(x);
    return /^-?\d+$/.test(text) ? `${text}.0` : text;
  };
}
