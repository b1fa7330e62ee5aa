import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { type CommandTarget, commandNamed, commands, displayKey, handleKey, keyName, runCommand } from '../../src/ui/commands.js';

/** A target that writes down what the commands asked of it. */
function recording(overrides: Partial<CommandTarget> = {}): { target: CommandTarget; calls: string[] } {
  const calls: string[] = [];
  const note = (name: string) => (...args: unknown[]) => void calls.push(`${name}(${args.map((a) => JSON.stringify(a)).join(', ')})`);
  const target = {
    convention: 'origin',
    exploded: false,
    helpShown: false,
    tablesShown: true,
    presenting: false,
    explodeUnavailable: () => null,
    ...Object.fromEntries(['walk', 'back', 'select', 'frameMesh', 'frameSelection', 'toggleTopView', 'setExploded', 'toggleIds', 'toggleOverlays', 'showTables', 'toggleHelp', 'setPresentation', 'shareLink', 'request', 'askQuiz', 'say'].map((name) => [name, note(name)])),
    ...overrides,
  } as CommandTarget;
  return { target, calls };
}

const key = (key: string, modifiers: Partial<KeyboardEvent> = {}) => ({ key, altKey: false, ctrlKey: false, metaKey: false, shiftKey: false, ...modifiers }) as KeyboardEvent;

describe('the table of commands', () => {
  it('gives every key to one command, and every button an element of the layout', () => {
    const keys = commands.flatMap((c) => c.keys);
    expect(new Set(keys).size).toBe(keys.length);
    const layout = readFileSync(new URL('../../src/ui/layout.html', import.meta.url), 'utf8');
    for (const command of commands) if (command.button) expect(layout, command.name).toContain(`id="${command.button.id}"`);
    expect(new Set(commands.map((c) => c.name)).size).toBe(commands.length);
  });

  it('runs the command of a key press, with its modifiers, and nothing for a key it does not have', () => {
    const { target, calls } = recording();
    expect(handleKey(target, key('n'))).toBe(true);
    expect(handleKey(target, key('S', { shiftKey: true }))).toBe(true);
    expect(handleKey(target, key('z', { ctrlKey: true, shiftKey: true }))).toBe(true);
    expect(handleKey(target, key('?', { shiftKey: true }))).toBe(true);
    expect(handleKey(target, key('w'))).toBe(false);
    expect(handleKey(target, key('n', { altKey: true }))).toBe(false);
    expect(calls).toEqual(['walk("next")', 'request("stepBack")', 'request("redo")', 'toggleHelp()']);
    expect(keyName(key('Z', { ctrlKey: true, shiftKey: true }))).toBe('ctrl+shift+z');
    expect(displayKey('ctrl+shift+z')).toBe('Ctrl+Shift+Z');
  });

  it('walks to the vertex the naming names, and says so in its help', () => {
    const { target, calls } = recording({ convention: 'target' });
    handleKey(target, key('v'));
    expect(calls).toEqual(['walk("target")']);
    expect(commandNamed('walk-vertex')!.help('target')).toBe('target: the vertex the halfedge points to');
    // R and L turn around the vertex the halfedge leaves, whatever the naming
    expect(commandNamed('walk-twin.next')!.help('target')).toContain('the vertex the halfedge starts from');
  });

  it('does not run a command that does not apply, and says why', () => {
    const { target, calls } = recording({ explodeUnavailable: () => 'the mesh is one connected part' });
    expect(runCommand(target, commandNamed('explode')!)).toBe('the mesh is one connected part');
    expect(calls).toEqual(['say("Explode parts is not available: the mesh is one connected part.")']);
    // turning the exploded view off always applies
    const on = recording({ exploded: true, explodeUnavailable: () => 'the mesh is one connected part' });
    expect(runCommand(on.target, commandNamed('explode')!)).toBeNull();
    expect(on.calls).toEqual(['setExploded(false)']);
  });
});
