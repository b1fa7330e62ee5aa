/** What render buffers draw, for comparing a patched copy with a fresh layout. */
import type { RenderBuffers } from '../../src/workers/protocol.js';

/** What the buffers draw, whatever range each face's triangles sit in: sorted triangles (as sorted corner triples) with their faces, sorted edges, the dots. */
export function drawn(render: RenderBuffers) {
  const triangles: string[] = [];
  for (let t = 0; t < render.counts.triangles; t++) {
    const corners = [render.triangles[3 * t], render.triangles[3 * t + 1], render.triangles[3 * t + 2]];
    if (render.triangleFace[t] === -1) continue; // a triangle of no area, where a face was
    triangles.push(`${[...corners].sort((a, b) => a - b).join(' ')} f${render.triangleFace[t]}`);
  }
  const edges: string[] = [];
  for (let e = 0; e < render.counts.edges; e++) {
    const [a, b] = [render.edges[2 * e], render.edges[2 * e + 1]];
    if (a !== b) edges.push(`${Math.min(a, b)} ${Math.max(a, b)}`);
  }
  const dots = new Set(Array.from(render.vertices.subarray(0, render.counts.vertices)));
  const positions = Array.from(render.positions.subarray(0, 3 * render.counts.vertices));
  return { triangles: triangles.sort(), edges: edges.sort(), dots: [...dots].sort((a, b) => a - b), positions };
}

