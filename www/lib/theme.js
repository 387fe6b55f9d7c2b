/**
 * The visual language of every figure (ui.md): Okabe–Ito colours, stroke widths, radii and
 * font sizes, in one place. Demos never write a colour or a width inline; they pick a named
 * style from the theme that `currentTheme()` returns.
 *
 * Sizes are CSS pixels at scale 1. Lecture mode multiplies text, strokes and radii by
 * `LECTURE_SCALE`; the renderer applies that factor, so the styles below stay constant objects
 * (made once, never per frame).
 */

/** Okabe–Ito hues, kept in light and dark mode. */
export const HUES = Object.freeze({
  blue: "#0072B2",
  vermillion: "#D55E00",
  orange: "#E69F00",
  bluishGreen: "#009E73",
  reddishPurple: "#CC79A7",
  skyBlue: "#56B4E9",
});

/** Construction levels (de Casteljau, de Boor, Aitken) and per-point colours cycle through these. */
export const CYCLE = Object.freeze([
  HUES.orange,
  HUES.bluishGreen,
  HUES.reddishPurple,
  HUES.skyBlue,
]);

/** Stroke widths in CSS px (ui.md "Colours" table). */
export const WIDTH = Object.freeze({
  curve: 2.5,
  polygon: 1,
  construction: 1.5,
  handleOutline: 1.5,
  helper: 1,
  basisHover: 3,
  basisRing: 2.5,
  basisBand: 8,
  highlightBand: 12,
  split: 2,
});

/** Radii in CSS px. */
export const RADIUS = Object.freeze({
  handle: 5,
  handleHover: 7,
  pointOnCurve: 5,
  constructionPoint: 3.5,
  basisRing: 9.5,
  splitPoint: 4,
});

/** Font sizes in CSS px; nothing on a canvas is smaller than 13 px at DPR 1. */
export const FONT_SIZE = Object.freeze({ label: 15, small: 14 });

/** Font stack shared by canvas text and SVG `<text>`, so exports match the screen. */
export const FONT_FAMILY =
  'system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif';

/** Dash pattern of the control polygon, in CSS px. */
export const POLYGON_DASH = Object.freeze([5, 4]);

/**
 * A second curve beside the first, with its own control polygon and points (a hodograph, the
 * image of the curve under a map): bluish green, the same in light and dark mode.
 */
export const SECOND_CURVE = Object.freeze({
  curve: Object.freeze({
    stroke: HUES.bluishGreen,
    width: WIDTH.curve,
    join: "round",
    cap: "round",
  }),
  polygon: Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.polygon, dash: POLYGON_DASH }),
  point: Object.freeze({ fill: HUES.bluishGreen, radius: RADIUS.constructionPoint }),
});

/** Dash pattern of the right half of a subdivided curve's control polygon, in CSS px. */
export const SPLIT_DASH = Object.freeze([7, 4]);

/**
 * Curves compared in one figure (e.g. one control polygon under several knot vectors): solid,
 * dashed and dotted, so the style and not only the colour tells them apart (`compareCurve[i]`).
 */
export const COMPARE_DASH = Object.freeze([null, Object.freeze([10, 6]), Object.freeze([0.5, 6])]);

/** Dash pattern of helper geometry such as the line a constrained handle moves along. */
export const HELPER_DASH = Object.freeze([2, 3]);

/** Opacity of helper fills (boxes, hulls). */
export const HELPER_FILL_ALPHA = 0.15;

/** All text and strokes grow by this factor in lecture mode (ui.md). */
export const LECTURE_SCALE = 1.6;

/** Gap between a point and its label, in CSS px. */
export const LABEL_GAP = 9;

const LIGHT = Object.freeze({
  name: "light",
  background: "#FFFFFF",
  text: "#222222",
  polygon: "#8A8A8A",
  handleFill: "#FFFFFF",
  handleOutline: "#222222",
  helper: "#BBBBBB",
  grid: "#EEEEEE",
});

const DARK = Object.freeze({
  name: "dark",
  background: "#16181C",
  text: "#E8E8E8",
  polygon: "#9A9A9A",
  handleFill: "#16181C",
  handleOutline: "#E8E8E8",
  helper: "#6A6A6A",
  grid: "#24272D",
});

/**
 * Builds the named styles of one colour scheme. A style is a plain object read by the
 * renderer (draw.js): `stroke`, `fill`, `width`, `dash`, `alpha`, `radius`, `font` fields.
 */
function makeTheme(base) {
  const levelStroke = CYCLE.map((colour) =>
    Object.freeze({ stroke: colour, width: WIDTH.construction }),
  );
  const levelPoint = CYCLE.map((colour) =>
    Object.freeze({ fill: colour, radius: RADIUS.constructionPoint }),
  );
  const basisStroke = CYCLE.map((colour) =>
    Object.freeze({ stroke: colour, width: WIDTH.construction, join: "round" }),
  );
  const basisHover = CYCLE.map((colour) =>
    Object.freeze({ stroke: colour, width: WIDTH.basisHover, join: "round" }),
  );
  const basisRing = CYCLE.map((colour) =>
    Object.freeze({ stroke: colour, width: WIDTH.basisRing, radius: RADIUS.basisRing }),
  );
  const basisBand = CYCLE.map((colour) =>
    Object.freeze({ stroke: colour, width: WIDTH.basisBand, join: "round", cap: "round" }),
  );
  const basisPoint = CYCLE.map((colour) =>
    Object.freeze({
      fill: colour,
      stroke: base.background,
      width: 1,
      radius: RADIUS.constructionPoint,
    }),
  );
  return Object.freeze({
    ...base,
    curve: Object.freeze({ stroke: HUES.blue, width: WIDTH.curve, join: "round", cap: "round" }),
    polygon: Object.freeze({ stroke: base.polygon, width: WIDTH.polygon, dash: POLYGON_DASH }),
    handle: Object.freeze({
      fill: base.handleFill,
      stroke: base.handleOutline,
      width: WIDTH.handleOutline,
      radius: RADIUS.handle,
    }),
    handleHover: Object.freeze({
      fill: base.handleFill,
      stroke: base.handleOutline,
      width: WIDTH.handleOutline,
      radius: RADIUS.handleHover,
    }),
    handleSelected: Object.freeze({
      fill: base.handleFill,
      stroke: HUES.vermillion,
      width: 2.5,
      radius: RADIUS.handleHover,
    }),
    pointOnCurve: Object.freeze({
      fill: HUES.vermillion,
      stroke: base.background,
      width: 1,
      radius: RADIUS.pointOnCurve,
    }),
    levelStroke: Object.freeze(levelStroke),
    levelPoint: Object.freeze(levelPoint),
    helper: Object.freeze({ stroke: base.helper, width: WIDTH.helper, dash: HELPER_DASH }),
    helperFill: Object.freeze({
      fill: base.helper,
      alpha: HELPER_FILL_ALPHA,
      stroke: base.helper,
      width: WIDTH.helper,
    }),
    label: Object.freeze({ fill: base.text, size: FONT_SIZE.label, halo: base.background }),
    labelBold: Object.freeze({
      fill: HUES.vermillion,
      size: FONT_SIZE.label,
      weight: "bold",
      halo: base.background,
    }),
    labelSmall: Object.freeze({ fill: base.text, size: FONT_SIZE.small, halo: base.background }),
    labelPoint: Object.freeze({
      fill: HUES.vermillion,
      size: FONT_SIZE.label,
      weight: "bold",
      halo: base.background,
    }),
    // Basis functions and their control points share a colour of CYCLE (index i mod CYCLE.length).
    basisStroke: Object.freeze(basisStroke),
    basisHover: Object.freeze(basisHover),
    basisRing: Object.freeze(basisRing),
    basisBand: Object.freeze(basisBand),
    basisPoint: Object.freeze(basisPoint),
    // Plot axes and frames drawn next to a figure.
    axis: Object.freeze({ stroke: base.polygon, width: WIDTH.helper }),
    plotBackground: Object.freeze({ fill: base.background }),
    // A marker line at the current parameter (the colour of the point on the curve).
    marker: Object.freeze({ stroke: HUES.vermillion, width: WIDTH.construction }),
    // The two halves of a subdivided curve: left solid, right dashed (never colour alone).
    splitLeft: Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.split }),
    splitRight: Object.freeze({ stroke: HUES.reddishPurple, width: WIDTH.split, dash: SPLIT_DASH }),
    splitLeftPoint: Object.freeze({
      fill: HUES.bluishGreen,
      stroke: base.background,
      width: 1,
      radius: RADIUS.splitPoint,
    }),
    splitRightPoint: Object.freeze({
      fill: HUES.reddishPurple,
      stroke: base.background,
      width: 1,
      radius: RADIUS.splitPoint,
    }),
    // A stretch of the curve singled out (a segment, a span): a wide translucent band under it.
    highlightBand: Object.freeze({
      stroke: HUES.blue,
      width: WIDTH.highlightBand,
      strokeAlpha: 0.25,
      join: "round",
      cap: "round",
    }),
    // Curves compared in one figure: blue solid, bluish green dashed, reddish purple dotted.
    compareCurve: Object.freeze(
      [HUES.blue, HUES.bluishGreen, HUES.reddishPurple].map((colour, i) =>
        Object.freeze({
          stroke: colour,
          width: WIDTH.curve,
          join: "round",
          cap: i === 1 ? "butt" : "round",
          ...(COMPARE_DASH[i] ? { dash: COMPARE_DASH[i] } : {}),
        }),
      ),
    ),
    comparePoint: Object.freeze(
      [HUES.blue, HUES.bluishGreen, HUES.reddishPurple].map((colour) =>
        Object.freeze({
          fill: colour,
          stroke: base.background,
          width: 1,
          radius: RADIUS.splitPoint,
        }),
      ),
    ),
  });
}

/** The light theme; exports (SVG, PNG) always use it, on a white background. */
export const LIGHT_THEME = makeTheme(LIGHT);
/** The dark theme: background and greys swapped, hues kept. */
export const DARK_THEME = makeTheme(DARK);

const DARK_QUERY = "(prefers-color-scheme: dark)";

/**
 * The theme for a figure inside `node`: the one its demo was told to use (`data-sl-theme="light"
 * | "dark"` on an ancestor: a course page's `<spline-lab theme>`), else the reader's colour-scheme
 * preference right now.
 */
export function currentTheme(node = null) {
  const forced = node?.closest?.("[data-sl-theme]")?.getAttribute("data-sl-theme");
  if (forced === "dark") return DARK_THEME;
  if (forced === "light") return LIGHT_THEME;
  const dark = typeof matchMedia === "function" && matchMedia(DARK_QUERY).matches;
  return dark ? DARK_THEME : LIGHT_THEME;
}

/** Calls `callback` when the colour-scheme preference changes; returns a function that stops it. */
export function onThemeChange(callback) {
  if (typeof matchMedia !== "function") return () => {};
  const query = matchMedia(DARK_QUERY);
  query.addEventListener("change", callback);
  return () => query.removeEventListener("change", callback);
}

/** True when the reader asked for reduced motion: then nothing plays by itself. */
export function prefersReducedMotion() {
  return typeof matchMedia === "function" && matchMedia("(prefers-reduced-motion: reduce)").matches;
}

/**
 * A demo's own styles derived from a theme, made once per theme (never per frame):
 * `const stylesFor = themed((theme) => ({ tick: Object.freeze({ stroke: theme.text, … }) }));`
 * then `stylesFor(r.theme).tick` in `draw`.
 */
export function themed(make) {
  const cache = new WeakMap();
  return (theme) => {
    let styles = cache.get(theme);
    if (!styles) {
      styles = Object.freeze(make(theme));
      cache.set(theme, styles);
    }
    return styles;
  };
}
