import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { GLBufferAttribute } from 'three';
import { GpuArray, SLICE_BYTES, SliceSize } from '../../src/ui/scene/gpu-array.js';

/** The part of WebGL 2 an upload uses, keeping each buffer's bytes, and the bytes each call sent. */
function recordingGl() {
  const memory = new Map<object, Uint8Array>();
  let bound: object | null = null;
  const gl = {
    ARRAY_BUFFER: 0x8892,
    ELEMENT_ARRAY_BUFFER: 0x8893,
    STATIC_DRAW: 0x88e4,
    FLOAT: 0x1406,
    UNSIGNED_INT: 0x1405,
    sent: 0,
    createBuffer: () => ({}),
    deleteBuffer: (buffer: object) => void memory.delete(buffer),
    bindBuffer: (_target: number, buffer: object) => void (bound = buffer),
    bufferData: (_target: number, size: number) => void memory.set(bound!, new Uint8Array(size)),
    bufferSubData: (_target: number, at: number, source: Float32Array | Uint32Array, offset: number, length: number) => {
      const bytes = new Uint8Array(source.buffer, source.byteOffset + offset * source.BYTES_PER_ELEMENT, length * source.BYTES_PER_ELEMENT);
      memory.get(bound!)!.set(bytes, at);
      gl.sent += bytes.length;
    },
    contents: (buffer: object) => memory.get(buffer),
    buffers: () => memory.size,
  };
  return gl;
}

const bytesOf = (array: Uint32Array) => new Uint8Array(array.buffer, array.byteOffset, array.byteLength);

describe('GpuArray', () => {
  it('puts a new array on the GPU in slices, and draws from it only once all of it is there', () => {
    const gl = recordingGl();
    const used: GLBufferAttribute[] = [];
    const gpu = new GpuArray(true, (attribute) => used.push(attribute));
    const first = Uint32Array.from({ length: 1000 }, (_, i) => i);
    gpu.set(first);
    const slices: number[] = [];
    while (!gpu.current) slices.push(gpu.upload(gl as unknown as WebGL2RenderingContext, 1024));
    // the buffer is made in a slice of its own
    expect(slices).toEqual([1024, 1024, 1024, 1024, 928]);
    expect(used).toHaveLength(1);
    expect(used[0].count).toBe(1000);
    expect(gl.contents(used[0].buffer)).toEqual(bytesOf(first));

    // the next array goes to a buffer of its own: the first is drawn until it is all there
    const second = Uint32Array.from({ length: 600 }, (_, i) => 7 * i);
    gpu.set(second);
    gpu.upload(gl as unknown as WebGL2RenderingContext, 1024);
    gpu.upload(gl as unknown as WebGL2RenderingContext, 1024);
    expect(used).toHaveLength(1);
    expect(gl.contents(used[0].buffer)).toEqual(bytesOf(first));
    while (!gpu.current) gpu.upload(gl as unknown as WebGL2RenderingContext, 1024);
    expect(used).toHaveLength(2);
    expect(gl.contents(used[1].buffer)).toEqual(bytesOf(second));
    // and the first buffer is given back
    expect(gl.buffers()).toBe(1);
    expect(gpu.upload(gl as unknown as WebGL2RenderingContext, 1024)).toBe(0);
  });

  it('sends a range the page rewrote again, and only that, once the array is up', () => {
    const gl = recordingGl();
    const used: GLBufferAttribute[] = [];
    const gpu = new GpuArray(true, (attribute) => used.push(attribute));
    const array = new Uint32Array(1000);
    gpu.set(array);
    while (!gpu.current) gpu.upload(gl as unknown as WebGL2RenderingContext, 1 << 20);
    array.fill(9, 100, 110);
    gpu.rewrote(100, 10);
    expect(gpu.current).toBe(false);
    const before = gl.sent;
    gpu.upload(gl as unknown as WebGL2RenderingContext, 1 << 20);
    expect(gl.sent - before).toBe(40);
    expect(gpu.current).toBe(true);
    expect(gl.contents(used[0].buffer)).toEqual(bytesOf(array));
  });

  it('holds every array as the page last wrote it, whatever the order of new arrays, rewrites and slices', () => {
    type Step = { kind: 'set'; length: number; seed: number } | { kind: 'rewrite'; start: number; count: number; value: number } | { kind: 'upload'; bytes: number };
    const step = fc.oneof(
      fc.record({ kind: fc.constant('set' as const), length: fc.integer({ min: 1, max: 3000 }), seed: fc.nat() }),
      fc.record({ kind: fc.constant('rewrite' as const), start: fc.nat(), count: fc.integer({ min: 1, max: 400 }), value: fc.nat() }),
      fc.record({ kind: fc.constant('upload' as const), bytes: fc.integer({ min: 4, max: 5000 }) }),
    );
    fc.assert(
      fc.property(fc.array(step, { minLength: 1, maxLength: 40 }), (steps: Step[]) => {
        const gl = recordingGl();
        let drawn: GLBufferAttribute | null = null;
        let array: Uint32Array | null = null;
        // whenever the geometry switches, the buffer it draws holds all of the array as it is then
        const gpu = new GpuArray(true, (attribute) => {
          expect(gl.contents(attribute.buffer)).toEqual(bytesOf(array!));
          drawn = attribute;
        });
        for (const s of steps) {
          if (s.kind === 'set') {
            array = Uint32Array.from({ length: s.length }, (_, i) => (s.seed + 31 * i) >>> 0);
            gpu.set(array);
          } else if (s.kind === 'rewrite' && array) {
            const start = s.start % array.length;
            const count = Math.min(s.count, array.length - start);
            array.fill(s.value, start, start + count);
            gpu.rewrote(start, count);
          } else if (s.kind === 'upload') {
            const before = gl.sent;
            const used = gpu.upload(gl as unknown as WebGL2RenderingContext, s.bytes);
            // a slice sends no more than it counts, and counts no more than it may
            expect(gl.sent - before).toBeLessThanOrEqual(used);
            expect(used).toBeLessThanOrEqual(s.bytes);
          }
        }
        if (!array) return;
        for (let slices = 0; !gpu.current; slices++) {
          expect(slices).toBeLessThan(10_000);
          gpu.upload(gl as unknown as WebGL2RenderingContext, 512);
        }
        expect(gl.contents(drawn!.buffer)).toEqual(bytesOf(array));
        // the buffer drawn and none beside it
        expect(gl.buffers()).toBe(1);
      }),
      { seed: 41, numRuns: 200 },
    );
  });

  it('slices by how long the last slice took: half after a slow one, down to the least; twice after a quick one, up to the most', () => {
    const size = new SliceSize();
    expect(size.bytes).toBe(SLICE_BYTES.most);
    size.took(60);
    expect(size.bytes).toBe(SLICE_BYTES.most / 2);
    for (let i = 0; i < 10; i++) size.took(60);
    expect(size.bytes).toBe(SLICE_BYTES.least);
    size.took(10);
    expect(size.bytes).toBe(SLICE_BYTES.least);
    size.took(2);
    expect(size.bytes).toBe(2 * SLICE_BYTES.least);
    for (let i = 0; i < 10; i++) size.took(2);
    expect(size.bytes).toBe(SLICE_BYTES.most);
  });
});
