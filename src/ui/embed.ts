/**
 * Embed mode: the view and a chosen set of panels, without the toolbar or the tabs, for a frame in
 * a slide or a course page (`?embed&panels=walk,inspector`, or `<halfedge-view panels="…">`).
 */

/**
 * What an embed can show besides the view: the side panels (stacked in the order named), the
 * record tables below the view, and the legend and the counts on the view.
 */
export const panelNames = ['inspector', 'walk', 'traversal', 'operations', 'stepper', 'history', 'export', 'quiz', 'practice', 'file', 'tables', 'legend', 'hud'] as const;
export type PanelName = (typeof panelNames)[number];

/** `"walk, inspector"` → the panels named, in that order, each once; the names it does not know, for a message. */
export function parsePanels(text: string | null): { panels: PanelName[]; unknown: string[] } {
  const names = new Set(
    (text ?? '')
      .split(',')
      .map((name) => name.trim().toLowerCase())
      .filter((name) => name !== ''),
  );
  const known = (name: string): name is PanelName => (panelNames as readonly string[]).includes(name);
  return { panels: [...names].filter(known), unknown: [...names].filter((name) => !known(name)) };
}

/** The sentence that names what an embed's `panels` list got wrong. */
export function unknownPanelsMessage(unknown: string[]): string {
  return `Unknown panel${unknown.length > 1 ? 's' : ''} ${unknown.join(', ')}: the panels are ${panelNames.join(', ')}.`;
}
