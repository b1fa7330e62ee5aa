/**
 * One of the surface's arrays on the GPU, put there by the page a slice per animation frame
 * rather than by three.js whole. Three.js uploads a new array in the frame that first draws it,
 * and a subdivision step of a million-triangle mesh arrives as arrays of a hundred megabytes and
 * more: half a second of one task on a software renderer, the page frozen meanwhile. Here a new
 * array goes up a slice at a time (see SliceSize), the last one's buffer still drawn until it is all there;
 * ranges the page rewrote in place (a patch) go up the same way.
 *
 *   set(array)          a new array: a new buffer, filled slice by slice
 *   rewrote(start, n)   entries the page changed in the array it holds
 *   upload(gl, bytes)   the next slice, at most `bytes` (or a new buffer made); the geometry
 *                       switches to the new buffer once it holds all of the array
 */
import { GLBufferAttribute } from 'three';

/**
 * Bytes put on the GPU per animation frame, as `SliceSize` adjusts them: 16 MB took about 5 ms of
 * the page's time while the GPU's process kept up, and up to 63 ms while it shared the two cores
 * with a worker's full checks (32 MB saved no time in all).
 */
export const SLICE_BYTES = { least: 2 << 20, most: 16 << 20 };
/** A slice that keeps the page's thread longer than this makes the next one half as large; one under a quarter of it, twice. */
const SLICE_MS = 20;

/** The size of the next slice, from how long the last one took. */
export class SliceSize {
  bytes = SLICE_BYTES.most;

  took(ms: number): void {
    if (ms > SLICE_MS) this.bytes = Math.max(SLICE_BYTES.least, this.bytes / 2);
    else if (ms < SLICE_MS / 4) this.bytes = Math.min(SLICE_BYTES.most, this.bytes * 2);
  }
}

type GpuTypedArray = Float32Array | Uint32Array;

export class GpuArray {
  /** The newest array; the GPU holds it all once `current`. */
  private array: GpuTypedArray | null = null;
  /** The buffer the geometry draws from. */
  private drawn: WebGLBuffer | null = null;
  /** The buffer being filled with `array` (allocated on its first slice), and how many entries of it are. */
  private filling: { buffer: WebGLBuffer | null; done: number } | null = null;
  /** Ranges of `array` rewritten since they went up, as [start, end) entries. */
  private rewritten: Array<[number, number]> = [];
  /** Buffers half filled with an array a newer one replaced, to give back. */
  private dropped: WebGLBuffer[] = [];

  /**
   * `index`: triangle, line or point corners (an element buffer); else three floats per vertex.
   * `use` puts the attribute for a buffer that holds all of the array into the geometries.
   */
  constructor(
    private readonly index: boolean,
    private readonly use: (attribute: GLBufferAttribute) => void,
  ) {}

  /** A new array to draw from, once it is all on the GPU. */
  set(array: GpuTypedArray): void {
    if (this.filling?.buffer) this.dropped.push(this.filling.buffer);
    this.array = array;
    this.filling = { buffer: null, done: 0 };
    this.rewritten = [];
  }

  /** The page rewrote entries `start … start + count − 1` of the array it holds. */
  rewrote(start: number, count: number): void {
    // the part of an array not yet up goes up as it is now
    if (this.filling && start >= this.filling.done) return;
    this.rewritten.push([start, start + count]);
  }

  /** Whether the GPU holds all of the newest array as it is now. */
  get current(): boolean {
    return this.filling === null && this.rewritten.length === 0;
  }

  /**
   * Uploads up to `bytes` of what the GPU lacks (the rewritten ranges first, then the new array)
   * and returns the bytes used (all of them when it made the new array's buffer). The caller has reset three.js's GL state, so that binding an
   * element buffer here changes no vertex array object of three.js's.
   */
  upload(gl: WebGL2RenderingContext, bytes: number): number {
    for (const buffer of this.dropped.splice(0)) gl.deleteBuffer(buffer);
    const array = this.array;
    if (!array) return 0;
    const target = this.index ? gl.ELEMENT_ARRAY_BUFFER : gl.ARRAY_BUFFER;
    const entries = Math.floor(bytes / array.BYTES_PER_ELEMENT);
    let used = 0;
    // rewritten ranges go to the buffer being filled when there is one: the drawn one is dropped with it
    const destination = this.filling ? this.filling.buffer : this.drawn;
    while (this.rewritten.length > 0 && used < entries && destination) {
      const range = this.rewritten[this.rewritten.length - 1];
      const end = Math.min(range[1], range[0] + entries - used);
      gl.bindBuffer(target, destination);
      gl.bufferSubData(target, range[0] * array.BYTES_PER_ELEMENT, array, range[0], end - range[0]);
      used += end - range[0];
      if (end === range[1]) this.rewritten.pop();
      else range[0] = end;
    }
    const filling = this.filling;
    if (filling && used < entries) {
      if (!filling.buffer) {
        // a slice of its own: the GPU's process clears the new buffer, and data sent meanwhile
        // would wait for that on the page's thread (70 ms for 63 MB on a software renderer)
        filling.buffer = gl.createBuffer();
        gl.bindBuffer(target, filling.buffer);
        gl.bufferData(target, array.byteLength, gl.STATIC_DRAW);
        return bytes;
      }
      const end = Math.min(array.length, filling.done + entries - used);
      gl.bindBuffer(target, filling.buffer);
      if (end > filling.done) gl.bufferSubData(target, filling.done * array.BYTES_PER_ELEMENT, array, filling.done, end - filling.done);
      used += end - filling.done;
      filling.done = end;
      if (end === array.length) {
        if (this.drawn) gl.deleteBuffer(this.drawn);
        this.drawn = filling.buffer;
        this.filling = null;
        this.use(
          this.index
            ? new GLBufferAttribute(this.drawn, gl.UNSIGNED_INT, 1, 4, array.length)
            : new GLBufferAttribute(this.drawn, gl.FLOAT, 3, 4, array.length / 3),
        );
      }
    }
    return used * array.BYTES_PER_ELEMENT;
  }
}
