/**
 * The legend, everywhere the same (Okabe–Ito: readable by colour-blind students and on a
 * projector). See DESIGN.md.
 */
export const colors = {
  selected: '#E69F00',
  next: '#56B4E9',
  prev: '#0072B2',
  twin: '#D55E00',
  face: '#009E73',
  origin: '#CC79A7',
  boundary: '#8a8a8a',
  problem: '#D55E00',
  /** Edges where a file split its vertices (the File tab's seams). */
  seam: '#7B2CBF',
  halfedge: '#4a4a4a',
  surface: '#dfe3e8',
  surfaceBack: '#9aa5b1',
  edge: '#2b2b2b',
  background: '#f7f7f5',
} as const;

/** What a phase of an operation did, in the stepper and the view. */
export const phaseColors = { created: colors.face, moved: colors.selected, rewired: colors.next } as const;

export type PointerRole = 'selected' | 'next' | 'prev' | 'twin' | 'face' | 'origin';

/**
 * Arrows drawn hollow (a white core inside the colour): the second cue for the two pairs whose
 * colours come close on a washed-out projector or for a colour-blind student — selected (orange)
 * and twin (vermillion), next (sky blue) and prev (blue). tests/ui/palette.test.ts checks it.
 */
export const hollowRoles: ReadonlySet<PointerRole> = new Set(['prev', 'twin']);

/** The style of a legend swatch for a role: filled, or hollow like its arrows. */
export function swatchStyle(role: PointerRole): string {
  return hollowRoles.has(role) ? `background:#fff;box-shadow:inset 0 0 0 3px ${colors[role]}` : `background:${colors[role]}`;
}

export const legend: Array<{ role: PointerRole; label: string }> = [
  { role: 'selected', label: 'selected halfedge' },
  { role: 'next', label: 'next' },
  { role: 'prev', label: 'prev' },
  { role: 'twin', label: 'twin' },
  { role: 'face', label: 'face' },
  { role: 'origin', label: 'origin vertex' },
];
