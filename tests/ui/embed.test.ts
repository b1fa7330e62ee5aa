import { describe, expect, it } from 'vitest';
import { panelNames, parsePanels, unknownPanelsMessage } from '../../src/ui/embed.js';

describe('an embed’s panels list', () => {
  it('keeps the order it names, each panel once, whatever the case and spacing', () => {
    expect(parsePanels(' Walk, inspector ,walk,,TABLES')).toEqual({ panels: ['walk', 'inspector', 'tables'], unknown: [] });
  });

  it('is empty when absent or blank: the view alone', () => {
    expect(parsePanels(null)).toEqual({ panels: [], unknown: [] });
    expect(parsePanels(' , ')).toEqual({ panels: [], unknown: [] });
  });

  it('reports the names it does not know, and the message lists the ones there are', () => {
    const { panels, unknown } = parsePanels('walk,inspecter,<b>x</b>');
    expect(panels).toEqual(['walk']);
    expect(unknown).toEqual(['inspecter', '<b>x</b>']);
    const message = unknownPanelsMessage(unknown);
    expect(message).toContain('inspecter, <b>x</b>');
    for (const name of panelNames) expect(message).toContain(name);
  });
});
