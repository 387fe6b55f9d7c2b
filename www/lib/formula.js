/**
 * The formula panel: lines of TeX typeset with KaTeX (copied into www/vendor/ by the build;
 * nothing from a CDN). KaTeX loads once per page, on first use; until it is there (or if it
 * fails) the TeX source is shown as text, so the numbers are never missing.
 */

const KATEX_MODULE = new URL("../vendor/katex/katex.mjs", import.meta.url);
/** URL of KaTeX's stylesheet, for `<link>`s in the document and in shadow roots. */
export const KATEX_CSS = new URL("../vendor/katex/katex.min.css", import.meta.url).href;

let katexPromise = null;

/** KaTeX's module default export, loaded once per page. */
export function loadKatex() {
  katexPromise ??= import(KATEX_MODULE.href).then((m) => m.default);
  return katexPromise;
}

/**
 * Makes sure KaTeX's CSS applies inside `root` (a Document or a ShadowRoot). Fonts declared by
 * @font-face only take effect from the document, so the document always gets a copy too.
 */
export function ensureKatexStyles(root) {
  const add = (parent) => {
    if (parent.querySelector?.(`link[href="${KATEX_CSS}"]`)) return;
    const link = document.createElement("link");
    link.rel = "stylesheet";
    link.href = KATEX_CSS;
    parent.append(link);
  };
  add(document.head);
  if (root && root !== document) add(root);
}

export class FormulaPanel {
  /** @param {HTMLElement} element the panel; its content is owned by this object. */
  constructor(element) {
    this.element = element;
    this.element.classList.add("sl-formula");
    this._lines = [];
    this._tex = [];
    this._katex = null;
    this._destroyed = false;
    loadKatex()
      .then((katex) => {
        if (this._destroyed) return;
        this._katex = katex;
        this._render(true);
      })
      .catch(() => {}); // TeX source stays visible
  }

  /** Shows `lines` (an array of TeX strings); only lines whose TeX changed are typeset again. */
  set(lines) {
    this._next = lines;
    this._render(false);
  }

  _render(all) {
    const lines = this._next ?? [];
    while (this._lines.length < lines.length) {
      const div = document.createElement("div");
      div.className = "sl-formula-line";
      this.element.append(div);
      this._lines.push(div);
      this._tex.push(null);
    }
    while (this._lines.length > lines.length) {
      this._lines.pop().remove();
      this._tex.pop();
    }
    lines.forEach((tex, i) => {
      if (!all && this._tex[i] === tex) return;
      this._tex[i] = tex;
      const div = this._lines[i];
      if (this._katex) {
        try {
          this._katex.render(tex, div, { displayMode: true, throwOnError: false, output: "htmlAndMathml" });
          return;
        } catch {
          // fall through to plain text
        }
      }
      div.textContent = tex;
    });
  }

  destroy() {
    this._destroyed = true;
    this.element.textContent = "";
  }
}
