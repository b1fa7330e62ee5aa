/**
 * The practice code editor: CodeMirror 6 with JavaScript and completion of the mesh API. Its own
 * module, loaded when the Practice tab first opens, so the rest of the page does not carry it.
 */
import { autocompletion, type CompletionContext } from '@codemirror/autocomplete';
import { javascript } from '@codemirror/lang-javascript';
import { basicSetup, EditorView } from 'codemirror';

export interface PracticeEditor {
  text(): string;
  setText(text: string): void;
  /** Puts the cursor on a line (1-based) and scrolls it into sight. */
  goToLine(line: number): void;
  focus(): void;
}

export function createEditor(host: HTMLElement, text: string, onChange: (text: string) => void, apiNames: readonly string[]): PracticeEditor {
  // inside a shadow root, CodeMirror's styles go in a constructed style sheet, which the page's
  // Content-Security-Policy allows (a <style> element it does not)
  const root = host.shadowRoot ?? host.attachShadow({ mode: 'open' });
  const parent = document.createElement('div');
  root.append(parent);
  const complete = (context: CompletionContext) => {
    const word = context.matchBefore(/mesh\.\w*/);
    if (!word) return null;
    return { from: word.from + 'mesh.'.length, options: apiNames.map((name) => ({ label: name, type: 'function' })) };
  };
  const view = new EditorView({
    doc: text,
    parent,
    root,
    extensions: [
      EditorView.theme({ '&': { fontSize: 'var(--practice-code-size, 0.85rem)', minHeight: '8em' }, '.cm-scroller': { fontFamily: 'ui-monospace, Menlo, Consolas, monospace' } }),
      basicSetup,
      javascript(),
      autocompletion({ override: [complete] }),
      EditorView.updateListener.of((update) => {
        if (update.docChanged) onChange(update.state.doc.toString());
      }),
      EditorView.contentAttributes.of({ 'aria-label': 'Solution code' }),
    ],
  });
  return {
    text: () => view.state.doc.toString(),
    setText: (next) => view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: next } }),
    goToLine(line) {
      const at = view.state.doc.line(Math.max(1, Math.min(line, view.state.doc.lines)));
      view.dispatch({ selection: { anchor: at.from }, scrollIntoView: true });
    },
    focus: () => view.focus(),
  };
}
