/**
 * What the builder had to change to fit a polygon soup into a halfedge mesh, and why. A halfedge
 * mesh holds an oriented manifold surface; real files often are not one, so the builder repairs
 * and reports instead of refusing. Each incident names the elements concerned, both as they were
 * in the file (`input…`) and as they are in the built mesh, so the app can highlight them.
 */

export type RepairKind =
  | 'out-of-range-index'
  | 'degenerate-face'
  | 'collapsed-repeated-vertex'
  | 'reoriented-face'
  | 'non-orientable'
  | 'non-manifold-edge'
  | 'non-manifold-vertex'
  | 'isolated-vertex'
  | 'non-finite-position';

export interface RepairIncident {
  message: string;
  inputVertices?: number[];
  inputFaces?: number[];
  vertices?: number[];
  faces?: number[];
  halfedges?: number[];
}

export interface Repair {
  kind: RepairKind;
  /** How many incidents there were (only the first `MAX_INCIDENTS` are listed). */
  count: number;
  message: string;
  incidents: RepairIncident[];
}

export interface BuildReport {
  inputVertices: number;
  inputFaces: number;
  /** False when some component could not be oriented consistently (it was cut along seams). */
  orientable: boolean;
  repairs: Repair[];
}

export const MAX_INCIDENTS = 1000;

const summaries: Record<RepairKind, (n: number) => string> = {
  'out-of-range-index': (n) => `${plural(n, 'face')} dropped: they use a vertex index that does not exist`,
  'degenerate-face': (n) => `${plural(n, 'degenerate face')} dropped: fewer than 3 distinct vertices, or a vertex used twice`,
  'collapsed-repeated-vertex': (n) =>
    `${plural(n, 'face')} listed a vertex twice in a row; the repeat was removed and the face kept`,
  'reoriented-face': (n) => `${plural(n, 'face')} flipped to agree with the orientation of their neighbours`,
  'non-orientable': (n) =>
    `the surface is non-orientable (like a Möbius strip): cut open along ${plural(n, 'edge')} so every face can run counter-clockwise`,
  'non-manifold-edge': (n) =>
    `${plural(n, 'edge')} had more than two faces; a halfedge has one twin, so the extra faces were detached`,
  'non-manifold-vertex': (n) =>
    `${plural(n, 'vertex', 'vertices')} joined several separate fans of faces; each extra fan got its own copy of the vertex`,
  'isolated-vertex': (n) => `${plural(n, 'vertex belongs', 'vertices belong')} to no face (kept as isolated vertices)`,
  'non-finite-position': (n) => `${plural(n, 'vertex has', 'vertices have')} a NaN or infinite coordinate`,
};

export function plural(n: number, one: string, many = `${one}s`): string {
  return `${n} ${n === 1 ? one : many}`;
}

/** Collects incidents by kind, keeping the first `MAX_INCIDENTS` of each. */
export class ReportBuilder {
  private readonly byKind = new Map<RepairKind, Repair>();
  orientable = true;

  add(kind: RepairKind, incident: RepairIncident): void {
    let repair = this.byKind.get(kind);
    if (!repair) {
      repair = { kind, count: 0, message: '', incidents: [] };
      this.byKind.set(kind, repair);
    }
    repair.count++;
    if (repair.incidents.length < MAX_INCIDENTS) repair.incidents.push(incident);
  }

  finish(inputVertices: number, inputFaces: number): BuildReport {
    const repairs = [...this.byKind.values()];
    for (const repair of repairs) repair.message = summaries[repair.kind](repair.count);
    return { inputVertices, inputFaces, orientable: this.orientable, repairs };
  }
}
