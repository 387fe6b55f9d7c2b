/**
 * The third back end of the drawing interface (draw.js): `TikzRecorder` records a figure's draw
 * calls as TikZ/PGF for a lecturer's LaTeX notes — paths as `\draw`/`\fill` with the demo's
 * colours, widths, dashes and opacities, points as circles, labels as `\node`s. `toString()`
 * gives a standalone `.tex` document that pdflatex compiles with TeX Live's base and pgf
 * packages alone (article + geometry sized to the figure, no `standalone` class, no font
 * packages); the `tikzpicture` inside it can be pasted into any document that loads tikz.
 *
 * Coordinates: one unit is one CSS pixel, `x=0.75pt, y=-0.75pt` (96 px = 72 pt = 1 in), so
 * y points down as on the screen and a canvas arc's angles are TikZ's angles unchanged (TikZ
 * places `(a:r)` at r·(cos a · x + sin a · y), and y is the downward vector here).
 */
import { keepLabelInside, measureLabel, moveToArcStart } from "./draw.js";

const TAU = 2 * Math.PI;
/** Arcs closer than this to a full turn are drawn as full circles (radians). */
const FULL_TURN_EPSILON = 1e-9;
/** Coordinates keep this many decimals (1/100 px). */
const DECIMALS = 2;
/** One CSS pixel in TeX points. */
const PT_PER_PX = 0.75;
/** TikZ anchors of a label for each [align][baseline] of the drawing interface. */
const ANCHOR = {
  left: { top: "north west", middle: "west", bottom: "south west", alphabetic: "base west" },
  center: { top: "north", middle: "center", bottom: "south", alphabetic: "base" },
  right: { top: "north east", middle: "east", bottom: "south east", alphabetic: "base east" },
};

/** A coordinate or length with at most DECIMALS decimals. */
function num(value) {
  return String(Number(value.toFixed(DECIMALS)));
}

/** A page side in whole TeX points that holds `px` CSS pixels (the picture's side). */
const pagePt = (px) => Math.ceil(px * PT_PER_PX) + 1;

/** Degrees for TikZ's arc options. */
const degrees = (radians) => num((radians * 180) / Math.PI);

/** Characters pdflatex reads as commands, and how to print them as text. */
const TEX_SPECIAL = {
  "\\": "\\textbackslash{}",
  "{": "\\{",
  "}": "\\}",
  $: "\\$",
  "&": "\\&",
  "#": "\\#",
  "^": "\\textasciicircum{}",
  _: "\\_",
  "%": "\\%",
  "~": "\\textasciitilde{}",
  // The default OT1 text fonts print these three as "—", "¡" and "¿".
  "|": "\\textbar{}",
  "<": "\\textless{}",
  ">": "\\textgreater{}",
};
const GREEK = "αβγδεζηθικλμνξοπρστυφχψω";
const GREEK_NAMES =
  "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi o pi rho sigma tau upsilon phi chi psi omega".split(
    " ",
  );
const GREEK_UPPER = { Γ: "Gamma", Δ: "Delta", Θ: "Theta", Λ: "Lambda", Ξ: "Xi", Π: "Pi" };
Object.assign(GREEK_UPPER, { Σ: "Sigma", Φ: "Phi", Ψ: "Psi", Ω: "Omega" });
/** Symbols of the labels outside pdflatex's default input encoding, as LaTeX. */
const SYMBOLS = {
  "−": "\\ensuremath{-}",
  "×": "\\ensuremath{\\times}",
  "·": "\\ensuremath{\\cdot}",
  "≤": "\\ensuremath{\\le}",
  "≥": "\\ensuremath{\\ge}",
  "≈": "\\ensuremath{\\approx}",
  "≠": "\\ensuremath{\\ne}",
  "→": "\\ensuremath{\\to}",
  "←": "\\ensuremath{\\leftarrow}",
  "∞": "\\ensuremath{\\infty}",
  "∈": "\\ensuremath{\\in}",
  "∑": "\\ensuremath{\\sum}",
  "∂": "\\ensuremath{\\partial}",
  "√": "\\ensuremath{\\surd}",
  "±": "\\ensuremath{\\pm}",
  "°": "\\ensuremath{^\\circ}",
  "′": "\\ensuremath{'}",
  "″": "\\ensuremath{''}",
  "‖": "\\ensuremath{\\|}",
  "⊥": "\\ensuremath{\\perp}",
  "∥": "\\ensuremath{\\parallel}",
  "½": "\\ensuremath{\\frac{1}{2}}",
  "…": "\\dots{}",
  "–": "--",
  "—": "---",
  "“": "``",
  "”": "''",
  "‘": "`",
  "’": "'",
  "\u00a0": "~",
  "\u2009": "\\,",
  "\u202f": "\\,",
};
const SUBSCRIPTS = "₀₁₂₃₄₅₆₇₈₉";
const SUPERSCRIPTS = "⁰¹²³⁴⁵⁶⁷⁸⁹";
const SUB_LETTERS = { ᵢ: "i", ⱼ: "j", ₖ: "k", ₙ: "n", ₚ: "p", ᵤ: "u", ᵥ: "v", ₓ: "x" };

/**
 * `string` as LaTeX text that pdflatex's default (utf8) input reads: TeX's special characters
 * escaped, Greek letters, sub- and superscript digits and the labels' symbols as LaTeX, Latin
 * letters with accents (é, č, ž, …) as they are; anything else becomes "?".
 */
export function texText(string) {
  let out = "";
  for (const ch of String(string)) {
    const code = ch.codePointAt(0);
    let i;
    if (TEX_SPECIAL[ch]) out += TEX_SPECIAL[ch];
    else if (code >= 0x20 && code < 0x7f) out += ch;
    else if ((i = GREEK.indexOf(ch)) >= 0) out += `\\ensuremath{\\${GREEK_NAMES[i]}}`;
    else if (ch === "ς") out += "\\ensuremath{\\varsigma}";
    else if (GREEK_UPPER[ch]) out += `\\ensuremath{\\${GREEK_UPPER[ch]}}`;
    else if ((i = SUBSCRIPTS.indexOf(ch)) >= 0) out += `\\textsubscript{${i}}`;
    else if ((i = SUPERSCRIPTS.indexOf(ch)) >= 0) out += `\\textsuperscript{${i}}`;
    else if (SUB_LETTERS[ch]) out += `\\textsubscript{${SUB_LETTERS[ch]}}`;
    else if (SYMBOLS[ch]) out += SYMBOLS[ch];
    else if (code >= 0xc0 && code <= 0x17f && code !== 0xd7 && code !== 0xf7) out += ch;
    else out += "?";
  }
  return out;
}

/** `#RRGGBB` or `#RGB` as the six hex digits xcolor's HTML model takes; black otherwise. */
function hexColour(colour) {
  const m = /^#([0-9a-f]{6}|[0-9a-f]{3})$/i.exec(String(colour).trim());
  if (!m) return "000000";
  const hex = m[1].length === 3 ? [...m[1]].map((d) => d + d).join("") : m[1];
  return hex.toUpperCase();
}

/** Records the drawing interface (draw.js) as TikZ. Only used for export. */
export class TikzRecorder {
  /** @param {{ scale?: number, theme: object, measureContext?: CanvasRenderingContext2D }} options */
  constructor({ scale = 1, theme, measureContext = null }) {
    this.scale = scale;
    this.theme = theme;
    this.width = 0;
    this.height = 0;
    this._parts = [];
    this._colours = new Map(); // hex → name
    this._path = "";
    this._x = null; // current point, null when the path has none
    this._y = null;
    this._measure = measureContext;
  }

  /** The xcolor name of `colour`, defined once per document. */
  _colour(colour) {
    const hex = hexColour(colour);
    if (!this._colours.has(hex)) this._colours.set(hex, `sl${hex}`);
    return this._colours.get(hex);
  }

  begin(width, height, background) {
    this.width = width;
    this.height = height;
    this._parts.length = 0;
    this._parts.push(
      `\\fill[${this._colour(background)}] (0,0) rectangle (${num(width)},${num(height)});`,
    );
  }

  end() {}

  beginPath() {
    this._path = "";
    this._x = this._y = null;
  }

  moveTo(x, y) {
    this._path += ` (${num(x)},${num(y)})`;
    this._x = x;
    this._y = y;
  }

  lineTo(x, y) {
    this._path += ` -- (${num(x)},${num(y)})`;
    this._x = x;
    this._y = y;
  }

  closePath() {
    if (this._x !== null) this._path += " -- cycle";
  }

  rect(x, y, w, h) {
    this._path += ` (${num(x)},${num(y)}) rectangle (${num(x + w)},${num(y + h)})`;
    this._x = x;
    this._y = y;
  }

  /** Canvas arc semantics: from angle a0 to a1, clockwise on the screen unless told otherwise. */
  arc(x, y, r, a0, a1, counterClockwise = false) {
    moveToArcStart(this, x, y, r, a0);
    if (!r) return;
    let sweep = counterClockwise ? a0 - a1 : a1 - a0;
    sweep = sweep >= TAU - FULL_TURN_EPSILON ? TAU : ((sweep % TAU) + TAU) % TAU;
    const a1Drawn = counterClockwise ? a0 - sweep : a0 + sweep;
    this._path += ` arc[start angle=${degrees(a0)}, end angle=${degrees(a1Drawn)}, radius=${num(r)}]`;
    this._x = x + r * Math.cos(a1Drawn);
    this._y = y + r * Math.sin(a1Drawn);
  }

  circle(x, y, r) {
    this.moveTo(x + r, y);
    this.arc(x, y, r, 0, TAU);
  }

  paint(style) {
    if (!this._path) return;
    const options = [];
    if (style.fill) {
      options.push(`fill=${this._colour(style.fill)}`);
      if (style.alpha !== undefined && style.alpha !== 1)
        options.push(`fill opacity=${style.alpha}`);
    }
    if (style.stroke) {
      options.push(
        `draw=${this._colour(style.stroke)}`,
        `line width=${num((style.width ?? 1) * this.scale * PT_PER_PX)}pt`,
      );
      if (style.join) options.push(`line join=${style.join}`);
      if (style.cap) options.push(`line cap=${style.cap === "square" ? "rect" : style.cap}`);
      if (style.dash?.length) {
        const dash = style.dash.length % 2 ? [...style.dash, ...style.dash] : style.dash;
        const pattern = dash.map(
          (d, i) => `${i % 2 ? "off" : "on"} ${num(d * this.scale * PT_PER_PX)}pt`,
        );
        options.push(`dash pattern=${pattern.join(" ")}`);
      }
      if (style.strokeAlpha !== undefined && style.strokeAlpha !== 1)
        options.push(`draw opacity=${style.strokeAlpha}`);
    }
    if (options.length === 0) return;
    this._parts.push(`\\path[${options.join(", ")}]${this._path};`);
  }

  point(x, y, style) {
    this.beginPath();
    this.circle(x, y, style.radius * this.scale);
    this.paint(style);
  }

  text(string, x, y, style, align = "left", baseline = "middle") {
    [x, y] = keepLabelInside(this, string, style, x, y, align, baseline);
    const size = style.size * this.scale * PT_PER_PX;
    const font = `\\fontsize{${num(size)}}{${num(size * 1.2)}}\\selectfont\\sffamily${style.weight && style.weight !== "normal" ? "\\bfseries" : ""}`;
    const options = [
      `anchor=${ANCHOR[align]?.[baseline] ?? "west"}`,
      "inner sep=0pt",
      `text=${this._colour(style.fill)}`,
      `font=${font}`,
    ];
    // The screen's halo (a stroke in the background colour behind the glyphs) as a backing box.
    if (style.halo)
      options.push(`fill=${this._colour(style.halo)}`, "fill opacity=0.8", "text opacity=1");
    this._parts.push(
      `\\node[${options.join(", ")}] at (${num(x)},${num(y)}) {${texText(string)}};`,
    );
  }

  measure(string, style) {
    return measureLabel(this._measure, string, style, this.scale);
  }

  /** The recorded drawing as a standalone LaTeX document; `title` goes into its first comment. */
  toString(title = "splinelab figure") {
    const w = num(this.width);
    const h = num(this.height);
    const colours = [...this._colours].map(([hex, name]) => `\\definecolor{${name}}{HTML}{${hex}}`);
    return [
      `% ${String(title).replace(/[\r\n]+/g, " ")} — exported from splinelab as TikZ/PGF.`,
      "% Compile with pdflatex; or paste the tikzpicture (and the colours) into notes that load tikz.",
      "% One unit is one pixel of the screen figure (0.75 pt), y pointing down.",
      "\\documentclass{article}",
      "\\usepackage{tikz}",
      // The page is the figure plus under 1 pt: a page even 0.01 pt smaller than the picture
      // pushes it onto a second page.
      `\\usepackage[paperwidth=${pagePt(this.width)}pt,paperheight=${pagePt(this.height)}pt,margin=0pt]{geometry}`,
      "\\pagestyle{empty}",
      "\\begin{document}",
      "\\noindent",
      "\\begin{tikzpicture}[x=0.75pt, y=-0.75pt]",
      ...colours,
      `\\useasboundingbox (0,0) rectangle (${w},${h});`,
      `\\clip (0,0) rectangle (${w},${h});`,
      ...this._parts,
      "\\end{tikzpicture}",
      "\\end{document}",
      "",
    ].join("\n");
  }
}
