/**
 * What reading a mesh file gives: the polygon soup (faces kept as the file has them, never
 * triangulated, with their attributes), the counts the file states, its comments, and plain
 * sentences about anything the reader noticed or skipped, for the app to show beside the mesh.
 */
import type { FileLocation } from '../errors.js';
import type { PolygonSoup } from '../soup.js';

export type MeshFormat = 'ply' | 'off' | 'obj' | 'stl' | 'gltf';

export type Encoding = 'ascii' | 'binary_little_endian' | 'binary_big_endian';

export interface ReadOptions {
  /** Used only when the content does not say which format it is. */
  fileName?: string;
  /** Called now and then with the fraction of the file read (0…1). */
  onProgress?: (fraction: number) => void;
  /**
   * STL and glTF, whose files repeat a vertex per triangle or per seam: weld the vertices within
   * this distance of each other (default 0: exactly equal positions).
   */
  weldTolerance?: number;
}

export interface MeshFile {
  format: MeshFormat;
  encoding: Encoding;
  /** Faces as polygons; attributes in `vertexAttributes`, `faceAttributes`, `cornerAttributes`. */
  soup: PolygonSoup;
  /** As stated or present in the file, before any building. */
  counts: { vertices: number; faces: number };
  /** PLY `comment` and `obj_info` lines; the text of OFF and OBJ `#` comments. */
  comments: string[];
  /** What the reader noticed or skipped, as sentences. */
  notes: string[];
}

export type Progress = (fraction: number) => void;

/** The elements of a soup that values belong to. */
export type SoupElement = 'vertex' | 'face' | 'corner';

/**
 * Where in the file item `item` of element `index`'s value `name` (`position`, or an attribute's
 * name) was read. Readers find it by walking their file again to that place: it is asked only
 * for a value that is reported (see `finite.ts`), never on the way of a file that holds none.
 */
export type Locate = (element: SoupElement, name: string, index: number, item: number) => FileLocation;

/** What a reader gives `readMesh`: the file, and how to find where its values were read. */
export interface ReaderOutput {
  file: MeshFile;
  locate: Locate;
}

/**
 * Readers report progress every `PROGRESS_ROWS + 1` rows or so (a power of two, for a mask):
 * often enough for ten updates a second on the largest files, rarely enough to cost nothing.
 */
export const PROGRESS_ROWS = 0x3fff;
