/**
 * `<halfedge-view src="torus.off" select="h17" naming="target" panels="walk,inspector">`: the live
 * view, with its own worker, in any page (a slide, a course page). Importing this module defines
 * the element. Each element is a whole app of its own in a shadow root: its `.lab` has the members
 * of `window.halfedgeLab`, scoped to that view, and it takes the keys while it has the focus.
 * See docs/embed.md.
 */
import { gltfBufferUris } from '../core/io/index.js';
import { App } from './app.js';
import { automation, type HalfedgeLabAutomation } from './automation.js';
import { parsePanels, unknownPanelsMessage } from './embed.js';
import layout from './layout.html?raw';
import { parseElementName } from './selection.js';
import styles from './styles.css?inline';

/** One style sheet, shared by every element of the page. */
let sheet: CSSStyleSheet | null = null;

export class HalfedgeViewElement extends HTMLElement {
  static readonly observedAttributes = ['src', 'select', 'naming'];

  #app: App | null = null;
  #lab: HalfedgeLabAutomation | null = null;
  /** Counts the opened sources: a src replaced while its file is on the way is not opened late. */
  #opens = 0;

  /** The members of `window.halfedgeLab` (docs/automation.md), for this view only. */
  get lab(): HalfedgeLabAutomation {
    if (!this.#lab) throw new Error('<halfedge-view> starts when it is added to the page');
    return this.#lab;
  }

  connectedCallback(): void {
    if (this.#app) return; // moved within the page: the view goes on
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0; // focusable, to take the keys
    const shadow = this.shadowRoot ?? this.attachShadow({ mode: 'open' });
    if (!sheet) {
      sheet = new CSSStyleSheet();
      sheet.replaceSync(styles);
    }
    shadow.adoptedStyleSheets = [sheet];
    const frame = document.createElement('div');
    frame.className = 'frame';
    // the project's own markup, the same the page is built from; no text from outside goes in here
    frame.innerHTML = layout;
    shadow.replaceChildren(frame);

    const { panels, unknown } = parsePanels(this.getAttribute('panels'));
    this.#app = new App({ root: shadow, frame, input: this, panels });
    this.#lab = automation(this.#app);
    if (unknown.length > 0) this.#app.say(unknownPanelsMessage(unknown), 'alert');
    this.#applyNaming();
    void this.#open();
  }

  disconnectedCallback(): void {
    // a move is a removal and an insertion in one task: stop only if the element stays out
    queueMicrotask(() => {
      if (this.isConnected || !this.#app) return;
      this.#app.dispose();
      this.#app = null;
      this.#lab = null;
    });
  }

  attributeChangedCallback(name: string, before: string | null, after: string | null): void {
    if (!this.#app) return;
    // select and naming set again to the same value apply again: the view may have moved away
    // since (a deselect, a walk, the naming switched through .lab); the same src is not fetched again
    if (name === 'src') {
      if (before !== after) void this.#open();
    } else if (name === 'select') this.#applySelection();
    else this.#applyNaming();
  }

  /** Fetches `src` (relative to the page) and opens it; a `.gltf` with the buffers it names beside it. */
  async #open(): Promise<void> {
    const app = this.#app;
    const src = this.getAttribute('src');
    if (!app || !src) return;
    const open = ++this.#opens;
    const url = new URL(src, document.baseURI);
    const name = decodeURIComponent(url.pathname.split('/').pop() || 'mesh');
    try {
      const bytes = await fetchBytes(url);
      const resources = /\.gltf$/i.test(name) ? await gltfBuffers(bytes, url) : undefined;
      if (open !== this.#opens || app !== this.#app) return;
      if (await app.opening.openBytes(bytes, name, null, { resources })) this.#applySelection();
    } catch (error) {
      if (open !== this.#opens || app !== this.#app) return;
      app.say(`Could not open ${src}: ${(error as Error).message}.`, 'alert');
      app.showError(`Could not open ${src}`, (error as Error).message);
    }
  }

  #applySelection(): void {
    const text = this.getAttribute('select');
    if (!this.#app?.mesh || text === null) return;
    const selection = parseElementName(text);
    if (!selection) this.#app.say(`select="${text}" is not an element name like h17, v4, f5 or e8.`, 'alert');
    else this.#app.select(selection);
  }

  #applyNaming(): void {
    const naming = this.getAttribute('naming');
    if (naming === 'origin' || naming === 'target') this.#app?.setConvention(naming);
    else if (naming !== null) this.#app?.say(`naming="${naming}" is neither origin nor target.`, 'alert');
  }
}

async function fetchBytes(url: URL): Promise<Uint8Array<ArrayBuffer>> {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`the server answered ${response.status} for ${url.href}`);
  return new Uint8Array(await response.arrayBuffer());
}

/** The external buffers a `.gltf` names, fetched from beside it, by the names it gives them. */
async function gltfBuffers(bytes: Uint8Array, url: URL): Promise<Map<string, Uint8Array<ArrayBuffer>>> {
  return new Map(await Promise.all(gltfBufferUris(bytes).map(async (uri) => [uri, await fetchBytes(new URL(uri, url))] as const)));
}

if (!customElements.get('halfedge-view')) customElements.define('halfedge-view', HalfedgeViewElement);

declare global {
  interface HTMLElementTagNameMap {
    'halfedge-view': HalfedgeViewElement;
  }
}
