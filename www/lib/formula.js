/**
 * The formula panel: lines of TeX typeset with KaTeX (copied into www/vendor/ by the build;
 * nothing from a CDN). KaTeX loads once per page, when a panel first nears the viewport (on a
 * phone the panel is below the figure, and the figure comes first); until it is there (or if
 * it fails) the TeX source is shown as text, so the numbers are never missing.
 *
 * While a point is dragged the lines change in their numbers only, every frame. Typesetting
 * them again (a new KaTeX tree of hundreds of elements, its style and layout) cost 2–20 ms a
 * frame, so a line is typeset once per *shape* — its TeX with every run of digits written
 * "0" — and later lines of the same shape only rewrite the digits in the text nodes they
 * reach (template.js-like, see `typesetTemplate`): the tree, its style and most of its layout
 * stay. KaTeX lays digits out the same whatever they are (all digits share one width, height
 * and class in its fonts), so the picture is the one a full typeset gives.
 */
import { t } from "./strings.js";
import { markScrollable, scrollRegion } from "./scroll-region.js";

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
 * `root`, the @font-face rules in the document (fonts only take effect from there). Resolves
 * when both stylesheets have loaded (or failed).
 */
export function ensureKatexStyles(root) {
  const add = (parent, href) => {
    let link = parent.querySelector?.(`link[href="${href}"]`);
    if (link?.sheet) return Promise.resolve();
    if (!link) {
      link = document.createElement("link");
      link.rel = "stylesheet";
      link.href = href;
      parent.append(link);
    }
    return new Promise((resolve) => {
      link.addEventListener("load", resolve, { once: true });
      link.addEventListener("error", resolve, { once: true });
    });
  };
  return Promise.all([
    add(document.head, KATEX_FONTS_CSS),
    add(root && root !== document ? root : document.head, KATEX_CSS),
  ]);
}

/**
 * Smallest scale a line is shrunk to so it fits the panel's width (lecture mode's 1.6× type at
 * this scale is about the normal size); a line still too wide scrolls sideways.
 */
export const MIN_FIT_SCALE = 0.6;
/** The MathML of a line follows its picture once the digits rest this long (ms); see `settle`. */
const SPOKEN_DELAY_MS = 250;
/**
 * When the panel counts as near the viewport (IntersectionObserver options): on screen, or
 * within this margin below it.
 */
const NEAR_VIEWPORT = { rootMargin: "0px 0px 48px 0px" };
/** A shrunk line that fits grows again only by more than this (no flicker between frames). */
const REFIT_SLACK = 0.02;

/**
 * A number that may change from one frame of a formula to the next: digits with an optional
 * decimal part ("7" and "6.156" are laid out alike: one run of digits and points, which KaTeX
 * sets as one box and one <mn>). A run that is a token of TeX's syntax rather than a number
 * shown is left in the shape: a one-character argument (`x^2`, `P_1`, `\\frac12`: after `^`,
 * `_` or a letter), a number before `^` or `_` (`1.5^3` raises the 5 alone; write `{1.5}^3`), a
 * colour (`#1f77b4`) and a dimension (`4pt`, `0.5em`). A sign is part of the shape (a minus is
 * a box of its own, spaced as a sign or an operation).
 */
const DIGITS =
  /(?<![A-Za-z#^_\d.])\d+(?:\.\d+)?(?![\d.]|\s*[\^_]|\s*(?:pt|em|ex|mu|px|cm|mm|in|bp|pc|dd|sp)(?![A-Za-z]))/g;
/** Any digits, in the typeset text. */
const ANY_DIGITS = /\d+/g;
/**
 * A template is typeset with run k written as the probe `PROBE_FIRST + k` (all probes have the
 * same number of digits, so a run KaTeX split or merged with another shows up as no probe).
 */
const PROBE_FIRST = 100;
const PROBE_LAST = 999;
const PROBE_DIGITS = 3;
/** Shapes remembered per page (each a small detached KaTeX tree), oldest dropped first. */
const MAX_TEMPLATES = 256;
const KATEX_OPTIONS = Object.freeze({
  displayMode: true,
  throwOnError: false,
  output: "htmlAndMathml",
});

/** Templates by shape (`tex` with every digit run "0"); `null`: the shape cannot be patched. */
const templates = new Map();

/** The shape of a TeX line: its digit runs written "0". */
export const texShape = (tex) => tex.replace(DIGITS, "0");

/**
 * Typesets the shape of `tex` with probes in place of its digit runs, and finds where each run
 * lands: `{ tree, slots }`, `slots` a list of `[text node index, parts, spoken]` in document
 * order, parts alternating literal text and run indices, `spoken` for a node outside the picture
 * (the MathML and its TeX annotation, which screen readers read). `null` when the runs do not come through as text
 * one for one, in the picture and in the MathML (a digit read as a dimension or an argument, a
 * TeX error): such lines are typeset whole every time.
 */
export function typesetTemplate(katex, tex) {
  const count = (tex.match(DIGITS) ?? []).length;
  if (count === 0 || PROBE_FIRST + count - 1 > PROBE_LAST) return null;
  // The digits that stay (x^2): typeset as they are, and no probe may look like them.
  const literal = tex.replace(DIGITS, " ").match(ANY_DIGITS) ?? [];
  const probeOf = (digits) => {
    const run = Number(digits) - PROBE_FIRST;
    return digits.length === PROBE_DIGITS && run >= 0 && run < count ? run : -1;
  };
  if (literal.some((digits) => probeOf(digits) >= 0)) return null;
  let k = 0;
  const probe = tex.replace(DIGITS, () => String(PROBE_FIRST + k++));
  const tree = document.createElement("div");
  katex.render(probe, tree, KATEX_OPTIONS);
  if (tree.querySelector(".katex-error")) return null;
  const html = tree.querySelector(".katex-html");
  const mathml = tree.querySelector(".katex-mathml");
  const annotation = tree.querySelector("annotation");
  const inHtml = new Set();
  const inMathml = new Set();
  const slots = [];
  const walker = document.createTreeWalker(tree, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(), index = 0; node; node = walker.nextNode(), index++) {
    const text = node.nodeValue;
    const seen = html?.contains(node)
      ? inHtml
      : mathml?.contains(node) && !annotation?.contains(node)
        ? inMathml
        : null;
    const parts = [];
    let last = 0;
    for (const m of text.matchAll(ANY_DIGITS)) {
      const run = probeOf(m[0]);
      if (run < 0) {
        // Digits of the shape itself, or a probe KaTeX split or merged: the checks below.
        if (!literal.some((digits) => digits.includes(m[0]))) return null;
        continue;
      }
      parts.push(text.slice(last, m.index), run);
      last = m.index + m[0].length;
      seen?.add(run);
    }
    if (parts.length) {
      parts.push(text.slice(last));
      slots.push([index, parts, seen !== inHtml]);
    }
  }
  // Every run must come through whole, in the picture and (when there is one) in the MathML.
  const whole = inHtml.size === count && (!mathml || inMathml.size === count);
  return whole ? { tree, slots } : null;
}

/** The template of `tex`'s shape, typeset on first use (the oldest is dropped beyond the cap). */
function templateFor(katex, shape, tex) {
  if (templates.has(shape)) {
    const template = templates.get(shape);
    templates.delete(shape); // most recently used last
    templates.set(shape, template);
    return template;
  }
  const template = typesetTemplate(katex, tex);
  templates.set(shape, template);
  if (templates.size > MAX_TEMPLATES) templates.delete(templates.keys().next().value);
  return template;
}

/** The text of a slot's parts with the digit runs of the new line. */
function slotText(parts, runs) {
  let text = parts[0];
  for (let i = 1; i < parts.length; i += 2) text += runs[parts[i]] + parts[i + 1];
  return text;
}

export class FormulaPanel {
  /** @param {HTMLElement} element the panel; its content is owned by this object. */
  constructor(element) {
    this.element = element;
    this.element.classList.add("sl-formula");
    // Lines too long even at the smallest scale scroll: the panel is then a tab stop.
    scrollRegion(this.element, { label: t("shell.formula") });
    /**
     * Per line: `{ div, tex, shape, nodes, slots, runs, spokenStale, scale }` (shape null:
     * typeset whole; `spokenStale`: its MathML still shows earlier digits).
     */
    this._lines = [];
    this._spokenTimer = 0;
    this._settleNext = false;
    this._next = [];
    this._katex = null;
    this._katexRequested = false;
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
    this._startTypesetting = this._startTypesetting.bind(this);
    // KaTeX (its module, fonts and first layout: a few hundred ms on a phone) loads only when
    // a reader heads for the panel: it nears the viewport, the page is scrolled, or focus
    // enters it. Until then the TeX source stands in, as while KaTeX loads.
    this._visibility = new IntersectionObserver((entries) => {
      if (entries.some((entry) => entry.isIntersecting)) this._startTypesetting();
    }, NEAR_VIEWPORT);
    this._visibility.observe(this.element);
    addEventListener("scroll", this._startTypesetting, { capture: true, passive: true });
    this.element.addEventListener("focusin", this._startTypesetting);
  }

  /** Loads KaTeX (once per page) and its CSS, and typesets every line when they are there. */
  _startTypesetting() {
    this._stopWaiting();
    if (this._destroyed || this._katexRequested) return;
    this._katexRequested = true;
    // Its stylesheets too (the style recalculation they bring stays out of the page's load).
    Promise.all([loadKatex(), ensureKatexStyles(this.element.getRootNode())])
      .then(([katex]) => {
        if (this._destroyed) return;
        this._katex = katex;
        this._render(true);
      })
      .catch(() => {}); // TeX source stays visible
  }

  _stopWaiting() {
    this._visibility.disconnect();
    removeEventListener("scroll", this._startTypesetting, { capture: true });
    this.element.removeEventListener("focusin", this._startTypesetting);
  }

  /**
   * Shows `lines` (an array of TeX strings); a line whose TeX is unchanged is not touched, one
   * that changed in its digits only has them rewritten in place.
   */
  set(lines) {
    this._next = lines;
    this._render(false);
  }

  /**
   * The change is final (a drag ended, a key was pressed: the demo committed it): the MathML is
   * brought up to date now and by the next `set`, not after the pause. While a point moves, only
   * the picture follows every frame; the MathML (half of the layout work) follows once the
   * numbers rest for SPOKEN_DELAY_MS, or here.
   */
  settle() {
    this._settleNext = true;
    this._syncSpoken();
  }

  _syncSpoken() {
    clearTimeout(this._spokenTimer);
    this._spokenTimer = 0;
    for (const line of this._lines) {
      if (!line.spokenStale) continue;
      line.spokenStale = false;
      if (line.shape !== null) this._write(line, true);
    }
  }

  /** Writes the line's digit runs into its picture's text nodes, or into its spoken ones. */
  _write(line, spoken) {
    for (let k = 0; k < line.nodes.length; k++) {
      const [, parts, isSpoken] = line.slots[k];
      if (isSpoken !== spoken) continue;
      const text = slotText(parts, line.runs);
      if (line.nodes[k].nodeValue !== text) line.nodes[k].nodeValue = text;
    }
  }

  _render(all) {
    const lines = this._next;
    while (this._lines.length < lines.length) {
      const div = document.createElement("div");
      div.className = "sl-formula-line";
      this.element.append(div);
      this._lines.push({
        div,
        tex: null,
        shape: null,
        nodes: null,
        slots: null,
        runs: null,
        spokenStale: false,
        scale: 1,
      });
    }
    while (this._lines.length > lines.length) this._lines.pop().div.remove();
    const changed = [];
    lines.forEach((tex, i) => {
      const line = this._lines[i];
      if (!all && line.tex === tex) return;
      line.tex = tex;
      if (all) line.shape = null; // plain text until now
      changed.push(line);
      if (this._katex) this._typeset(line, tex);
      else line.div.textContent = tex;
    });
    this._settleNext = false;
    // TeX source (before KaTeX) wraps like text: nothing to fit, and no layout read while the
    // page mounts.
    if (this._katex) this._fit(changed);
  }

  /** Typesets one line: digits rewritten when its shape is the one shown, else from the template. */
  _typeset(line, tex) {
    const shape = texShape(tex);
    const runs = tex.match(DIGITS) ?? [];
    line.runs = runs;
    line.spokenStale = false;
    if (line.shape !== shape) {
      let template = null;
      try {
        template = templateFor(this._katex, shape, tex);
      } catch {
        // typeset whole below
      }
      if (!template) {
        line.shape = null;
        try {
          this._katex.render(tex, line.div, KATEX_OPTIONS);
        } catch {
          line.div.textContent = tex;
        }
        return;
      }
      const tree = template.tree.cloneNode(true);
      const nodes = [];
      const walker = document.createTreeWalker(tree, NodeFilter.SHOW_TEXT);
      let index = 0;
      for (const [at] of template.slots) {
        while (index <= at) {
          const node = walker.nextNode();
          if (index++ === at) nodes.push(node);
        }
      }
      line.shape = shape;
      line.slots = template.slots;
      line.nodes = nodes;
      for (let k = 0; k < nodes.length; k++) nodes[k].nodeValue = slotText(line.slots[k][1], runs);
      line.div.replaceChildren(...tree.childNodes);
      return;
    }
    this._write(line, false);
    if (this._settleNext) {
      this._write(line, true);
    } else {
      line.spokenStale = true;
      clearTimeout(this._spokenTimer);
      this._spokenTimer = setTimeout(() => this._syncSpoken(), SPOKEN_DELAY_MS);
    }
  }

  /**
   * Shrinks each of `lines` that is wider than the panel until it fits (type scale
   * `clientWidth / natural width`, at least MIN_FIT_SCALE); a line that fits keeps the panel's
   * size. Reads every line first (one layout), then writes only the scales that changed: a
   * line whose digits changed usually keeps its scale, and then nothing is laid out twice.
   */
  _fit(lines) {
    const measured = lines.map((line) => [
      line.div.clientWidth,
      line.div.scrollWidth,
      naturalWidth(line),
    ]);
    lines.forEach((line, i) => {
      const [clientWidth, scrollWidth, natural] = measured[i];
      if (clientWidth <= 0) return;
      const fitting = (width) =>
        Math.max(MIN_FIT_SCALE, Math.floor((1000 * clientWidth) / width) / 1000);
      let scale = line.scale;
      if (scrollWidth > clientWidth + 1) {
        // Too wide (the scroll width counts what sticks out of KaTeX's boxes too).
        scale = fitting(Math.max(natural, scrollWidth / line.scale));
      } else if (natural <= clientWidth + 1) {
        scale = 1;
      } else if (fitting(natural) > line.scale + REFIT_SLACK) {
        scale = fitting(natural); // room to grow again
      }
      if (scale === line.scale) return;
      line.scale = scale;
      line.div.style.fontSize = scale === 1 ? "" : `${scale}em`;
    });
    markScrollable(this.element);
  }

  destroy() {
    clearTimeout(this._spokenTimer);
    this._destroyed = true;
    this._stopWaiting();
    this._observer.disconnect();
    this.element.textContent = "";
  }
}

/**
 * The width a line would take at the panel's type size: its typeset boxes' extent (the
 * children of KaTeX's `.katex-html`, sized in em) divided by the line's scale, or its scroll
 * width for plain text.
 */
function naturalWidth(line) {
  const bases = line.div.querySelector(".katex-html")?.children ?? [];
  if (bases.length === 0) return line.div.scrollWidth / line.scale;
  const left = bases[0].getBoundingClientRect().left;
  let right = left;
  for (const base of bases) right = Math.max(right, base.getBoundingClientRect().right);
  return (right - left) / line.scale;
}
