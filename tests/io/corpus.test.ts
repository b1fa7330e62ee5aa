/**
 * Every real-world file of the shared corpus (beside the repository, never copied into it):
 * valid files give the counts MANIFEST.tsv states and build into a mesh that passes validate();
 * broken ones raise a ParseError that names the place.
 */
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { buildMesh, ParseError, validate } from '../../src/index.js';
import { readMesh } from '../../src/core/io/index.js';
import { parseError } from './helpers.js';

const corpus = path.resolve(import.meta.dirname, '../../../shared/corpus');
const manifestPath = path.join(corpus, 'MANIFEST.tsv');
const exists = existsSync(manifestPath);
if (!exists) {
  console.warn(`io corpus tests skipped: ${manifestPath} is missing (the real-world files live in shared/corpus beside the repository)`);
}

interface Row {
  file: string;
  vertices: string;
  faces: string;
  notes: string;
}

function manifest(): Row[] {
  const [head, ...lines] = readFileSync(manifestPath, 'utf8').trim().split('\n');
  const columns = head.split('\t');
  const column = (cells: string[], name: string) => cells[columns.indexOf(name)] ?? '';
  return lines.map((line) => {
    const cells = line.split('\t');
    return {
      file: column(cells, 'file'),
      vertices: column(cells, 'vertices'),
      faces: column(cells, 'faces'),
      notes: column(cells, 'notes'),
    };
  });
}

/** The message each broken file gets: the place and what is wrong there. */
const brokenFiles: Record<string, string> = {
  'assimp__invalid_counts.off': 'off: line 6, column 1: face 0 has 0 corners; a face needs at least one',
  'assimp__invalid_empty.off': 'off: byte 0: the file is empty (0 bytes)',
  'assimp__invalid_empty.ply': 'ply: byte 0: the file is empty (0 bytes)',
  'assimp__invalid_fuzz_crash_truncated.ply': "ply: byte 159: the file ends before 'end_header': the header is cut off",
  'assimp__issue623_comment_in_header.ply':
    "ply: line 14, column 56: row 0 of element 'vertex' ends before its property 'vertex_indices'",
  'plyrs__single_elements_err.ply':
    "ply: line 5: element 'point' announces 2 rows of 2 values, but the 5 bytes of data hold at most 1 of them",
  'threejs__dolphins_binary_le_CORRUPTED_utf8.ply': 'ply: byte 10435: face 0: vertex index -1074839032 is out of range 0..854',
};

describe.skipIf(!exists)('the real-world corpus', () => {
  const rows = exists ? manifest() : [];

  it('lists every file of the folder in its manifest', () => {
    const files = readdirSync(corpus).filter((name) => name !== 'MANIFEST.tsv' && name !== 'README.md');
    expect(rows.map((r) => r.file).sort()).toEqual(files.sort());
  });

  for (const { file, vertices, faces, notes } of rows) {
    const broken = notes.includes('BROKEN');
    if (broken) {
      it(`${file} is refused with a ParseError that names the place`, () => {
        const error = parseError(() => readMesh(readFileSync(path.join(corpus, file)), { fileName: file }));
        expect(error).toBeInstanceOf(ParseError);
        expect(error.location.line ?? error.location.byteOffset).toBeTypeOf('number');
        expect(error.message).toBe(brokenFiles[file]);
      });
      continue;
    }
    it(`${file} loads with ${vertices} vertices and ${faces} faces, and builds a valid mesh`, () => {
      const read = readMesh(readFileSync(path.join(corpus, file)), { fileName: file });
      expect(read.counts).toEqual({ vertices: Number(vertices), faces: Number(faces) });
      expect(read.soup.positions.length / 3).toBe(Number(vertices));
      expect(read.soup.faceStarts.length - 1).toBe(Number(faces));
      const { mesh } = buildMesh(read.soup);
      expect(validate(mesh)).toEqual([]);
    });
  }
});
