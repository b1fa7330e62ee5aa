/**
 * A tiny element builder. Strings become text nodes, never HTML: text from a file (PLY comments,
 * names, error excerpts) cannot inject markup through here.
 *
 * @example el('button', { type: 'button', 'aria-label': 'Walk to next', onclick: go }, 'N')
 */
type Child = Node | string | number | null | undefined | false;
type Attributes = Record<string, string | number | boolean | ((event: Event) => void) | undefined>;

export function el<K extends keyof HTMLElementTagNameMap>(tag: K, attributes: Attributes = {}, ...children: Child[]): HTMLElementTagNameMap[K] {
  const element = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value === undefined || value === false) continue;
    if (typeof value === 'function') element.addEventListener(name.replace(/^on/, ''), value);
    // through the CSSOM, which a strict Content-Security-Policy allows (a style attribute it does not)
    else if (name === 'style') element.style.cssText = String(value);
    else if (value === true) element.setAttribute(name, '');
    else element.setAttribute(name, String(value));
  }
  append(element, children);
  return element;
}

export function append(parent: Element, children: Child[]): void {
  for (const child of children) {
    if (child === null || child === undefined || child === false) continue;
    parent.append(typeof child === 'object' ? child : document.createTextNode(String(child)));
  }
}

/** Replaces the children of `parent`. */
export function replace(parent: Element, ...children: Child[]): void {
  parent.replaceChildren();
  append(parent, children);
}

/** The element of an id in the page, or in an embed's shadow root. */
export function byId<T extends HTMLElement = HTMLElement>(root: Document | ShadowRoot, id: string): T {
  const element = root.getElementById(id);
  if (!element) throw new Error(`the page has no #${id}`);
  return element as T;
}

/**
 * `replace`, keeping the keyboard focus on the control of the same accessible name: a panel that
 * redraws itself under a pressed key (Next, Previous) stays in the keyboard's hands.
 */
export function replaceKeepingFocus(parent: Element, ...children: Child[]): void {
  // in an embed's shadow root, the document's active element is the embed itself
  const focused = (parent.getRootNode() as Document | ShadowRoot).activeElement;
  const name = focused instanceof HTMLElement && parent.contains(focused) ? focused.getAttribute('aria-label') : null;
  replace(parent, ...children);
  if (name) parent.querySelector<HTMLElement>(`[aria-label="${CSS.escape(name)}"]`)?.focus();
}

/** The text with its first letter in capitals, to begin a sentence. */
export function capitalized(text: string): string {
  return text.charAt(0).toUpperCase() + text.slice(1);
}
