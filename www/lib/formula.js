/**
 * The formula panel: lines of TeX typeset with KaTeX (copied into www/vendor/ by the build;
 * nothing from a CDN). KaTeX loads once per page, on first use; until it is there (or if it
 * fails) the TeX source is shown as text, so the numbers are never missing.
 */

const KATEX_MODULE = new URL("../vendor/katex/katex.mjs", import.meta.url);
/**
 * KaTeX's stylesheet as the build splits it (scripts/vendor.mjs): its @font-face rules under our
 * own family names (SL_KaTeX_Main, …) for the document, and the rules for its classes, which
 * use those names, for where our formulas are. A course page's own KaTeX keeps its fonts and
 * its rules: nothing of ours with its names or selectors reaches the page.
 */
export const KATEX_FONTS_CSS = new URL("../vendor/katex/katex-fonts.css", import.meta.url).href;
export const KATEX_CSS = new URL("../vendor/katex/katex-scoped.css", import.meta.url).href;

let katexPromise = null;

/** KaTeX's module default export, loaded once per page. */
export function loadKatex() {
  katexPromise ??= import(KATEX_MODULE.href).then((m) => m.default);
  return katexPromise;
}

/**
 * Makes sure KaTeX's CSS applies inside `root` (a Document or a ShadowRoot): the class rules in
 * `root`, the @font-face rules in the document (fonts only take effect from there).
 */
export function ensureKatexStyles(root) {
  const add = (parent, href) => {
    if (parent.querySelector?.(`link[href="${href}"]`)) return;
    const link = document.createElement("link");
    link.rel = "stylesheet";
    link.href = href;
    parent.append(link);
  };
  add(document.head, KATEX_FONTS_CSS);
  add(root && root !== document ? root : document.head, KATEX_CSS);
}

/**
 * Smallest scale a line is shrunk to so it fits the panel's width (lecture mode's 1.6× type at
 * this scale is about the normal size); a line still too wide scrolls sideways.
 */
export const MIN_FIT_SCALE = 0.6;

export class FormulaPanel {
  /** @param {HTMLElement} element the panel; its content is owned by this object. */
  constructor(element) {
    this.element = element;
    this.element.classList.add("sl-formula");
    this._lines = [];
    this._tex = [];
    this._katex = null;
    this._destroyed = false;
    // Refit every line when the panel's width or type size changes (a resize, lecture mode),
    // in the next frame so the refit never re-enters the observer's own notification.
    this._fitKey = "";
    this._observer = new ResizeObserver(() => {
      const key = `${this.element.clientWidth} ${getComputedStyle(this.element).fontSize}`;
      if (key === this._fitKey) return;
      this._fitKey = key;
      requestAnimationFrame(() => this._fit(this._lines));
    });
    this._observer.observe(this.element);
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
    const changed = [];
    lines.forEach((tex, i) => {
      if (!all && this._tex[i] === tex) return;
      this._tex[i] = tex;
      const div = this._lines[i];
      changed.push(div);
      if (this._katex) {
        try {
          this._katex.render(tex, div, {
            displayMode: true,
            throwOnError: false,
            output: "htmlAndMathml",
          });
          return;
        } catch {
          // fall through to plain text
        }
      }
      div.textContent = tex;
    });
    this._fit(changed);
  }

  /**
   * Shrinks each of `lines` that is wider than the panel until it fits (type scale
   * `clientWidth / scrollWidth`, at least MIN_FIT_SCALE); a line that fits keeps the panel's size.
   */
  _fit(lines) {
    // Writes, then reads, then writes: one layout for all the lines, not one per line (the
    // lines change while a point is dragged).
    for (const div of lines) div.style.fontSize = "";
    const widths = lines.map((div) => [div.clientWidth, div.scrollWidth]);
    lines.forEach((div, i) => {
      const [clientWidth, scrollWidth] = widths[i];
      if (clientWidth > 0 && scrollWidth > clientWidth + 1) {
        const scale = Math.max(
          MIN_FIT_SCALE,
          Math.floor((1000 * clientWidth) / scrollWidth) / 1000,
        );
        div.style.fontSize = `${scale}em`;
      }
    });
  }

  destroy() {
    this._destroyed = true;
    this._observer.disconnect();
    this.element.textContent = "";
  }
}
