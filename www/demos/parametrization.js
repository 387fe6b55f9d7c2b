/**
 * Demo (syllabus §5): parametrisation for interpolation. The same data points interpolated
 * four times — by the C2 natural cubic spline (or Catmull–Rom, a choice) — at the parameters
 *
 *   t_0 = 0,   t_{i+1} = t_i + |p_{i+1} − p_i|^α,
 *
 * with α = 0 (uniform, blue solid), 1 (chord length, green dashed), 1/2 (centripetal, purple
 * dotted) and a fourth α from a slider (orange dash-dot: at 0, 1/2 or 1 it lies on one of the
 * three; the slider shows α = 0.5 is centripetal). The fourth curve is added, not swapped in,
 * so the three named ones stay for comparison; a checkbox hides it.
 *
 * Under the figure, the speed of each curve against the normalised parameter
 * s = (t − t_0)/(t_n − t_0), so the four share one axis:
 *
 *   |dC/ds| = (t_n − t_0) |C′(t)|,
 *
 * whose area over [0, 1] is the curve's length; chord length keeps it nearly level, uniform
 * parameters race along long legs and crawl (or loop) along short ones. Under the speed plot,
 * a row of ticks per curve at its data parameters s_i. The marker s (slider, player, or a press
 * in the plot) shows each curve's point at the same s.
 *
 * From the core: samples (`sampleUniform`), speeds (one batched `sampleDerivatives(ts, 1)` per
 * curve), parameters (`params()`), points at s (`evaluate`). Each curve is made with its kind
 * (or α) instead of a parameter list, so a drag moves it in place: `setPoint` recomputes the
 * parameters from the moved points and re-solves.
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, choice, pointButtons, readout, group } from "../lib/panel.js";
import { fmt, subscript, pointText } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { drawLegend } from "../lib/legend.js";
import { BasisPlotPointer } from "../lib/basis-plot.js";
import { SpeedPlot } from "../lib/speed-plot.js";
import { ParametrizationTable, parametrizationFormula } from "../lib/parametrization-text.js";
import { HUES, WIDTH, RADIUS, themed } from "../lib/theme.js";
import { replaceOrReport } from "../lib/wasm.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";
import { errorText } from "../lib/core-errors.js";

export const id = "parametrization";
export const strings = "parametrization";
export const section = 5;

/** Fewest and most data points. */
export const MIN_POINTS = 3;
export const MAX_POINTS = 10;
/** The interpolants offered. */
export const METHODS = Object.freeze(["cubic", "catmull-rom"]);
/** The curves in drawing and legend order: the named kinds, then the slider's α. */
const KINDS = Object.freeze(["uniform", "chord", "centripetal", "alpha"]);
/** α of the named kinds. */
const ALPHA_OF = Object.freeze({ uniform: 0, chord: 1, centripetal: 0.5 });
/** Samples along each curve and each speed graph. */
const SAMPLES = 241;
/** Slider resolutions. */
const S_STEP = 0.001;
const ALPHA_STEP = 0.01;
/** Fitting room for labels and overshoots (fractions of the points' box). */
const ROOM_X = 0.1;
const ROOM_Y = 0.2;
/**
 * The key in the top-left corner (CSS px): two columns of two rows, the second column closer on
 * a phone-width canvas (below NARROW_CANVAS_PX).
 */
const LEGEND_X = 12;
const LEGEND_Y = 16;
const LEGEND_ROW = 21;
const LEGEND_COLUMN = 230;
const LEGEND_COLUMN_NARROW = 178;
const LEGEND_BAND = 2 * LEGEND_ROW + 10;
/** A press in the plot snaps to s = 0, 1/16, …, 1 within this many CSS px. */
const SNAP_PX = 5;

const plot = new SpeedPlot({ fraction: 0.36, minPx: 170, shortFraction: 0.5, rows: KINDS.length });

/** Dash of the α curve (dash-dot), so style and not only colour tells it from the other three. */
const ALPHA_DASH = Object.freeze([12, 4, 2, 4]);
/** The curves' styles: the theme's three compared curves, then the α curve in orange. */
const CURVE_STYLES = themed((theme) =>
  Object.freeze([
    ...theme.compareCurve,
    Object.freeze({ stroke: HUES.orange, width: WIDTH.curve, join: "round", dash: ALPHA_DASH }),
  ]),
);
/** The points at s on each curve, in the curves' colours. */
const POINT_STYLES = themed((theme) =>
  Object.freeze([
    ...theme.comparePoint,
    Object.freeze({
      fill: HUES.orange,
      stroke: theme.background,
      width: 1,
      radius: RADIUS.splitPoint,
    }),
  ]),
);

/**
 * Six integer points with legs 5, 1, 1, 5, 1 (3-4-5 triangles): chord parameters 0, 5, 6, 7, 12,
 * 13. The uniform spline gives each short leg as much parameter as a long one and loops at the
 * corner p₁p₂p₃ and hooks past p₅; chord length bulges along the long legs; centripetal does neither.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [3, 4],
      [4, 4],
      [4, 3],
      [8, 0],
      [9, 0],
    ].map(Object.freeze),
  ),
  method: "cubic",
  alpha: 0.25,
  alphaCurve: true,
  s: 0.5,
});

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  method: field.choice(METHODS),
  alpha: field.number({ min: 0, max: 1 }),
  alphaCurve: field.boolean(),
  s: field.number({ min: 0, max: 1 }),
};

/**
 * One interpolant through `flat` with exponent α: the parameters are given as the kind (or α),
 * so the core computes them from the points — and again after every `setPoint`.
 */
function curveOf(sl, flat, kind, s) {
  const alpha = kind === "alpha" ? s.alpha : ALPHA_OF[kind];
  if (s.method === "catmull-rom") return sl.catmullRom(flat, 2, alpha);
  return sl.cubicSpline(flat, 2, kind === "alpha" ? alpha : kind, "natural");
}

/** The curves of KINDS (all or none: a refusal frees those made). */
function curvesOf(sl, s) {
  const flat = flatten(s.points);
  const made = [];
  try {
    for (const kind of KINDS) made.push(curveOf(sl, flat, kind, s));
  } catch (err) {
    for (const curve of made) curve.free();
    throw err;
  }
  return made;
}

/**
 * The model: `curves` (one per KINDS entry) and `refusal` (a move the core refused during a
 * drag — a repeated point under chord spacing — for the status line). A drag moves every curve
 * in place: `setPoint` recomputes its parameters from the moved points and re-solves.
 */
export const derive = {
  from: ["points", "method", "alpha"],
  build: (s, sl) => ({ curves: curvesOf(sl, s), refusal: { message: null } }),
  moved(m, i, xy) {
    for (const curve of m.curves) {
      try {
        curve.setPoint(i, xy);
      } catch (err) {
        m.refusal.message = errorText(err);
      }
    }
  },
};

/** Each curve's samples, domain, parameters (normalised for the ticks) and speed over s. */
function shownOf(curve) {
  const [a, b] = curve.domain();
  const ts = new Float64Array(SAMPLES);
  for (let k = 0; k < SAMPLES; k++) ts[k] = Math.min(b, a + (k / (SAMPLES - 1)) * (b - a));
  const derivatives = curve.sampleDerivatives(ts, 1);
  const speed = new Float64Array(SAMPLES);
  for (let k = 0; k < SAMPLES; k++)
    speed[k] = (b - a) * Math.hypot(derivatives[2 * k], derivatives[2 * k + 1]);
  const params = curve.params();
  return {
    a,
    b,
    samples: curve.sampleUniform(SAMPLES),
    params,
    ticks: Array.from(params, (v) => (v - a) / (b - a)),
    speed,
  };
}

const CURVES = ["points", "method", "alpha"];

export const compute = {
  shown: [CURVES, (s, d) => d.curves.map(shownOf)],
  at: [
    [...CURVES, "s"],
    (s, d) =>
      d.curves.map((curve, c) => {
        const { a, b } = d.shown[c];
        return curve.evaluate(Math.min(b, a + s.s * (b - a)));
      }),
  ],
};

export const controls = [
  group(
    null,
    slider("s", {
      label: "parametrization.control.s",
      min: 0,
      max: 1,
      step: S_STEP,
      player: true,
    }),
  ),
  group(
    "parametrization.control.alphaGroup",
    slider("alpha", { label: "parametrization.control.alpha", min: 0, max: 1, step: ALPHA_STEP }),
    readout("alpha", (s) => alphaNote(s)),
    checkbox("alphaCurve", { label: "parametrization.control.alphaCurve" }),
  ),
  group(
    "parametrization.control.method",
    choice("method", {
      options: METHODS.map((value) => ({ value, label: `parametrization.method.${value}` })),
      set: (ui, method) =>
        method !== ui.state.method && replaceOrReport(ui, { ...ui.state, method }),
    }),
  ),
  group(null, pointButtons("points", { min: MIN_POINTS, max: MAX_POINTS, prefix: strings })),
];

/** "α = 0.5: the centripetal parameters (the purple curve)". */
function alphaNote(s) {
  const named = KINDS.slice(0, 3).find((kind) => ALPHA_OF[kind] === s.alpha);
  return named
    ? t(`parametrization.alphaIs.${named}`, { alpha: fmt(s.alpha, 2) })
    : t("parametrization.alphaBetween", { alpha: fmt(s.alpha, 2) });
}

const insetScratch = [0, 0, 0, 0];

export const figure = {
  bounds: (s) => paddedBounds(s.points, ROOM_X, ROOM_Y),
  insets(width, height, scale) {
    insetScratch[0] = LEGEND_BAND * scale;
    insetScratch[2] = plot.height(height, scale);
    return insetScratch;
  },
  handles: { field: "points", label: (i) => `p${subscript(i)}` },
};

/** The legend's entries: per column, two curves (the α curve's label carries α). */
const LEFT_KEY = [
  { label: "parametrization.legend.uniform", style: (theme) => CURVE_STYLES(theme)[0] },
  { label: "parametrization.legend.chord", style: (theme) => CURVE_STYLES(theme)[1] },
];
const RIGHT_KEY = [
  { label: "parametrization.legend.centripetal", style: (theme) => CURVE_STYLES(theme)[2] },
  { label: "parametrization.legend.alpha", style: (theme) => CURVE_STYLES(theme)[3] },
];
const RIGHT_KEY_NO_ALPHA = RIGHT_KEY.slice(0, 1);

/** The speed plot's axis names (strings.js texts, read at draw time: the language may change). */
const axisNames = {
  get speed() {
    return t("parametrization.axisSpeed");
  },
  get s() {
    return t("parametrization.axisS");
  },
};

/** The data polygon, the curves back to front, the points at s, the handles, the key, the plot. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = CURVE_STYLES(theme);
  const points = POINT_STYLES(theme);
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  const shown = s.alphaCurve ? KINDS.length : KINDS.length - 1;
  for (let c = shown - 1; c >= 0; c--) {
    flatPath(r, v, d.shown[c].samples, 0, SAMPLES);
    r.paint(styles[c]);
  }
  d.handles.draw(r, v);
  for (let c = 0; c < shown; c++) r.point(v.sx(d.at[c][0]), v.sy(d.at[c][1]), points[c]);
  const narrow = r.width < NARROW_CANVAS_PX * r.scale;
  const rightX = LEGEND_X + (narrow ? LEGEND_COLUMN_NARROW : LEGEND_COLUMN);
  drawLegend(r, LEFT_KEY, LEGEND_X, LEGEND_Y, { row: LEGEND_ROW });
  drawLegend(r, s.alphaCurve ? RIGHT_KEY : RIGHT_KEY_NO_ALPHA, rightX, LEGEND_Y, {
    row: LEGEND_ROW,
  });
  plot.layout(r.width, r.height, r.scale, d.shown, shown);
  const marker = t("parametrization.marker", { s: fmt(s.s) });
  plot.draw(r, d.shown, shown, styles, points, s.s, marker, axisNames);
}

export const formula = (s, d) => parametrizationFormula(s, d.shown, s.alphaCurve);

/** "4 natural cubic splines through 6 points …; at s = 0.5: uniform (…), chord (…) …". */
export function label(s, d) {
  const at = (c) => pointText([d.at[c][0], d.at[c][1]], 2);
  return t("parametrization.aria", {
    method: t(`parametrization.methodName.${s.method}`),
    count: s.points.length,
    alpha: fmt(s.alpha, 2),
    s: fmt(s.s),
    uniform: at(0),
    chord: at(1),
    centripetal: at(2),
  });
}

/** The taller figure, the plot's pointer (press or drag sets s), the table of parameters. */
export function setup(ui) {
  const view = ui.view;
  ui.ctx.slots.figure.classList.add("sl-figure-tall");
  const layout = () => {
    const shown = ui.state.alphaCurve ? KINDS.length : KINDS.length - 1;
    plot.layout(view.width, view.height, view.renderer.scale, ui.data.shown, shown);
  };
  new BasisPlotPointer(view, {
    inPlot: (x, y) => {
      layout();
      return plot.contains(x, y, SNAP_PX);
    },
    graphAt: () => -1,
    pick: (x, final) => {
      layout();
      ui.set("s", plot.snappedParameter(x, 16, SNAP_PX * view.renderer.scale, S_STEP), final);
    },
    press: () => ui.stop(),
    enter: () => ui.handles.leave(),
    first: true,
  });
  const table = new ParametrizationTable(ui);
  return {
    update(s, d) {
      if (d.refusal.message) {
        ui.status(t("status.rejected", { message: d.refusal.message }), "error");
        d.refusal.message = null;
      }
      table.show(s, d.shown);
    },
  };
}
