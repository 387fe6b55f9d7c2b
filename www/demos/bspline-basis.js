/**
 * Demo (syllabus §3): B-spline basis functions. The curve on top, below it in the same canvas
 * (so SVG/PNG exports hold everything) the plot of every N_{i,p} over the domain, each in the
 * colour of its control point, and under the plot the knot ruler (lib/knot-ruler.js) whose
 * knots can be dragged, merged (double click / Enter) and split (Delete). A marker at u lists
 * the values N_{i,p}(u), their sum (= 1) and the Cox–de Boor triangle (`basisTable(u)`, the
 * "lecture view" of the Italian notes); hovering a basis function (plot, table) or selecting a
 * control point highlights its support [u_i, u_{i+p+1}) in the plot and on the curve.
 *
 * A point drag goes through `setControlPoint` (the basis does not change), a knot change
 * rebuilds the curve; the plot comes from one `basisCurves(count)` call per knot change, the
 * values from `basis(u)` / `basisTable(u)`.
 *
 * Keeping the knot vector valid: changing the degree or the number of control points replaces
 * the knots by the clamped uniform vector of the core (`knotVector(points, 2, p, "clamped")`:
 * p + 1 zeros, 1 … n − p, p + 1 copies of n − p + 1), and u is clamped into the new domain.
 */
import { field, checkNumber } from "../lib/validate.js";
import { slider, pointButtons, readout, group } from "../lib/panel.js";
import { knotRuler, knotText } from "../lib/knot-ruler.js";
import {
  knotsField,
  parameterField,
  bsplineCurve,
  withClampedKnots,
  domainOf,
  clampInto,
} from "../lib/bspline.js";
import { replaceOrReport } from "../lib/wasm.js";
import { BasisPlotPointer, drawGraph, drawPlotFrame } from "../lib/basis-plot.js";
import { placeLabelAway } from "../lib/handles.js";
import {
  fmt,
  subscript,
  simpleFraction,
  fractionText,
  degreeName,
  fmtTex,
  listSeparator,
  listTex,
  listText,
  pointTex,
} from "../lib/format.js";
import { CYCLE, themed } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { boundsOf, nearestGraph } from "../lib/geometry.js";
import {
  drawAxisLabels,
  drawKnotLines,
  drawPeakNames,
  peakSamples,
} from "../lib/basis-plot-marks.js";
import { degreeButtons } from "../lib/degree-buttons.js";
import { BasisValuesTable } from "../lib/basis-values-table.js";
import { coxDeBoorDefinition, coxDeBoorStep } from "../lib/cox-de-boor-formula.js";
import { continuityText } from "../lib/continuity.js";
import { BasisTriangleTable } from "../lib/basis-triangle.js";
import { flatPath, pointsPath } from "../lib/draw.js";

export const id = "bspline-basis";
export const strings = "bsplineBasis";
export const section = 3;

/**
 * The quadratic example of the Croatian notes (syllabus §3): p = 2, six control points,
 * U = [0, 0, 0, 1, 2, 3, 4, 4, 4]; at u = 5/2: N₂,₂ = 1/8, N₃,₂ = 3/4, N₄,₂ = 1/8.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [1, 3],
      [3, 4],
      [5, 1],
      [7, 3],
      [8, 0],
    ].map(Object.freeze),
  ),
  degree: 2,
  knots: Object.freeze([0, 0, 0, 1, 2, 3, 4, 4, 4]),
  u: 2.5,
});

/** Fewest and most control points, and the degrees offered. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 10;
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
/**
 * Samples along the curve and along each basis function: the same count over the same domain,
 * so sample k of both is at the same u (the highlighted support on the curve uses that).
 */
const SAMPLES = 241;
/** Slider resolution for u, as a fraction of the domain's length. */
const U_SLIDER_RESOLUTION = 1 / 1000;
/** The plot takes this fraction of the canvas height (at least PLOT_MIN_PX), above the ruler. */
const PLOT_FRACTION = 0.27;
const PLOT_MIN_PX = 120;
/** Margins of the plot frame inside its strip, CSS px at scale 1 (labels live there). */
const PLOT_MARGIN = Object.freeze({ top: 38, bottom: 8 });
/** A pointer this close (CSS px, vertically) to a basis curve highlights it. */
const PLOT_HOVER_PX = 14;
/** Pressing in the plot snaps u to a knot this close (CSS px). */
const KNOT_SNAP_PX = 6;
/** Basis functions are named at their peaks up to this many (beyond, the names crowd). */
const NAME_LABELS_MAX = 10;
/** Fill opacity of the highlighted support in the plot. */
const SUPPORT_ALPHA = 0.14;

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  degree(s, name) {
    checkNumber(s, name, { min: MIN_DEGREE, max: MAX_DEGREE, integer: true });
    const count = s.points.length;
    if (count < s.degree + 1)
      throw new Error(t("bsplineBasis.fewPoints", { p: s.degree, need: s.degree + 1, count }));
  },
  knots: knotsField(),
  u: parameterField({ error: "bsplineBasis.uRange" }),
};

/** The curve, in wasm; a dragged point moves it in place (the basis does not change). */
export const derive = {
  from: ["points", "degree", "knots"],
  build: (s, sl) => ({ curve: bsplineCurve(sl, s) }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

const BASIS = ["degree", "knots"];
/** What the core returns: every N_{i,p} sampled, the continuity, the curve, the values at u. */
export const compute = {
  basis: [BASIS, (s, d) => d.curve.basisCurves(SAMPLES)], // i-major: every N_{i,p} at SAMPLES u values
  peaks: [BASIS, (s, d) => peakSamples(d.basis, s.points.length, SAMPLES)],
  continuity: [BASIS, (s, d) => d.curve.knotContinuity()],
  domain: [BASIS, (s, d) => d.curve.domain()],
  samples: [["points", ...BASIS], (s, d) => d.curve.sampleUniform(SAMPLES)],
  point: [["points", ...BASIS, "u"], (s, d) => d.curve.evaluate(s.u)],
  values: [[...BASIS, "u"], (s, d) => d.curve.basis(s.u)],
  sum: [[...BASIS, "u"], (s, d) => d.values.reduce((sum, value) => sum + value, 0)], // partition of unity: 1
  table: [[...BASIS, "u"], (s, d) => d.curve.basisTable(s.u)], // { span, levels }
  marker: [
    ["u"],
    (s) => {
      const f = simpleFraction(s.u);
      return t("bsplineBasis.marker", { u: f && f.den > 1 ? fractionText(f) : knotText(s.u) });
    },
  ],
};

/** u clamped into the domain, snapped to a knot within KNOT_SNAP_PX on the ruler, else to the slider's step. */
function snapToKnot(s, d, u) {
  const [a, b] = d.domain;
  const clamped = clampInto(u, d.domain);
  for (const knot of s.knots) {
    if (knot >= a && knot <= b && Math.abs(d.ruler.px(knot) - d.ruler.px(clamped)) <= KNOT_SNAP_PX)
      return knot;
  }
  const step = (b - a) * U_SLIDER_RESOLUTION;
  return clampInto(a + Math.round((clamped - a) / step) * step, d.domain);
}

export const controls = [
  knotRuler("knots", {
    refused: (error, i, s) =>
      t(`bsplineBasis.multiplicity.${error}`, { i: subscript(i), max: s.degree + 1 }),
    pick: (ui, u, final) => ui.set("u", snapToKnot(ui.state, ui.data, u), final),
  }),
  group(
    "bsplineBasis.degreeLegend",
    degreeButtons({ prefix: strings, min: MIN_DEGREE, max: MAX_DEGREE }),
  ),
  group(
    null,
    slider("u", {
      label: "bsplineBasis.control.u",
      range: (s) => domainOf(s.knots, s.degree),
      step: (a, b) => (b - a) * U_SLIDER_RESOLUTION,
    }),
    readout("sum", (s, d) => t("bsplineBasis.sumNote", { u: knotText(s.u), sum: fmt(d.sum) }), {
      kind: "readout",
    }),
  ),
  group(
    null,
    readout("count", (s) => {
      const m = s.knots.length - 1;
      return t("bsplineBasis.knotNote", {
        count: s.points.length,
        p: s.degree,
        m: m + 1,
        last: subscript(m),
      });
    }),
    pointButtons("points", {
      min: (s) => Math.max(MIN_POINTS, s.degree + 1),
      max: MAX_POINTS,
      prefix: strings,
      adjust: (s, ui) => withClampedKnots(ui.sl, s),
      more: [
        {
          name: "reset-knots",
          label: "bsplineBasis.resetKnots",
          title: "bsplineBasis.resetKnots.title",
          run: (ui) => replaceOrReport(ui, withClampedKnots(ui.sl, ui.state)),
        },
      ],
    }),
    readout("ruler-help", () => t("bsplineBasis.rulerHelp")),
  ),
];

/** Scratch of the figure's insets (read at once by the view). */
const PLOT_INSETS = [0, 0, 0, 0];

function plotHeight(height) {
  return Math.max(PLOT_MIN_PX, Math.round(height * PLOT_FRACTION));
}

export const figure = {
  bounds: (s) => boundsOf(s.points),
  /** The plot's strip below the world window (the ruler's band is added under it). */
  insets: (width, height) => {
    PLOT_INSETS[2] = plotHeight(height);
    return PLOT_INSETS;
  },
  handles: { field: "points" },
};

/** Lays out the ruler and the plot frame `d.plot` for a canvas of width × height CSS px at text scale `scale`. */
function layoutBands(d, width, height, scale) {
  const { plot, ruler } = d;
  ruler.atBottom(width, height, scale);
  const rulerTop = height - ruler.height(scale);
  plot.bottom = rulerTop;
  plot.top = rulerTop - plotHeight(height);
  plot.x0 = ruler.px(d.domain[0]);
  plot.x1 = ruler.px(d.domain[1]);
  plot.y0 = rulerTop - PLOT_MARGIN.bottom * scale; // value 0 (y down on screen)
  plot.y1 = plot.top + PLOT_MARGIN.top * scale; // value 1
}

/** Styles of the plot that the theme does not have: the supports' fills. */
const supportFill = themed(() =>
  CYCLE.map((colour) => Object.freeze({ fill: colour, alpha: SUPPORT_ALPHA })),
);

/** "N₃,₂" (cached per degree and index). */
const basisNames = [];
function basisName(p, i) {
  return (basisNames[p * (MAX_POINTS + 1) + i] ??= `N${subscript(i)},${subscript(p)}`);
}

/** The curve (with the highlighted support), the plot of the basis with the marker at u, the ruler. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  const n = pts.length - 1;
  const p = s.degree;
  const hi = highlighted(s, d);
  const cycle = theme.basisStroke.length;
  const knots = s.knots;
  const u0 = d.domain[0];
  const u1 = d.domain[1];
  const sampleU = (k) => u0 + (k / (SAMPLES - 1)) * (u1 - u0);

  // ---- the curve area (world window, above the plot)
  pointsPath(r, v, pts, 0, n + 1);
  r.paint(theme.polygon);
  // The highlighted function's support [u_i, u_{i+p+1}) on the curve: a band in its colour.
  if (hi >= 0) {
    let k0 = 0;
    while (k0 < SAMPLES && sampleU(k0) < knots[hi]) k0++;
    let k1 = k0;
    while (k1 < SAMPLES && sampleU(k1) <= knots[hi + p + 1]) k1++;
    flatPath(r, v, d.samples, k0, k1);
    r.paint(theme.basisBand[hi % cycle]);
  }
  flatPath(r, v, d.samples, 0, SAMPLES);
  r.paint(theme.curve);
  // Every control point ringed in its basis function's colour.
  for (let i = 0; i <= n; i++)
    r.point(v.sx(pts[i][0]), v.sy(pts[i][1]), theme.basisRing[i % cycle]);
  d.handles.draw(r, v);
  const pointX = v.sx(d.point[0]);
  const pointY = v.sy(d.point[1]);
  r.point(pointX, pointY, theme.pointOnCurve);
  const radius = theme.pointOnCurve.radius * r.scale;
  placeLabelAway(r, v, pts, t("bsplineBasis.pointLabel"), pointX, pointY, theme.labelPoint, radius);

  // ---- the plot strip and the ruler (screen space, below the world window)
  const { plot, ruler } = d;
  const sc = r.scale;
  layoutBands(d, r.width, r.height, sc);
  const py = (value) => plot.y0 - value * (plot.y0 - plot.y1);
  drawPlotFrame(r, plot);
  // The highlighted support, shaded (before the curves).
  if (hi >= 0) {
    const a = ruler.px(Math.max(knots[hi], u0));
    const b = ruler.px(Math.min(knots[hi + p + 1], u1));
    r.beginPath();
    r.rect(a, plot.y1, Math.max(0, b - a), plot.y0 - plot.y1);
    r.paint(supportFill(theme)[hi % cycle]);
  }
  drawKnotLines(r, plot, knots, u0, u1, (u) => ruler.px(u));
  drawAxisLabels(r, plot, {
    zero: "bsplineBasis.axisValue0",
    one: "bsplineBasis.axisValue1",
    parameter: "bsplineBasis.axisU",
  });

  // The basis functions, from the core's table (highlighted one last, on top).
  const sampleX = (k) => ruler.px(sampleU(k));
  for (let i = 0; i <= n; i++) {
    if (i !== hi) drawGraph(r, d.basis, i, SAMPLES, sampleX, py, theme.basisStroke[i % cycle]);
  }
  if (hi >= 0) drawGraph(r, d.basis, hi, SAMPLES, sampleX, py, theme.basisHover[hi % cycle]);
  // The marker at u, under the names (their halo keeps them readable where it crosses).
  const mx = ruler.px(s.u);
  r.beginPath();
  r.moveTo(mx, plot.top + 18 * sc);
  r.lineTo(mx, plot.y0);
  r.paint(theme.marker);
  // Names at the peaks.
  if (n + 1 <= NAME_LABELS_MAX) {
    const name = (i) => basisName(p, i);
    drawPeakNames(r, d.basis, d.peaks, n + 1, SAMPLES, sampleX, py, name, hi);
  }
  // The values N_{i,p}(u) as dots on the marker, and its label.
  for (let i = 0; i <= n; i++)
    if (d.values[i] > 0) r.point(mx, py(d.values[i]), theme.basisPoint[i % cycle]);
  const markerAlign = mx < plot.x0 + 40 * sc ? "left" : mx > plot.x1 - 40 * sc ? "right" : "center";
  r.text(d.marker, mx, plot.top + 2 * sc, theme.labelPoint, markerAlign, "top");

  // The knot ruler, and u marked on its line.
  ruler.draw(r);
  const ly = ruler.lineY;
  r.beginPath();
  r.moveTo(mx, ly - 5 * sc);
  r.lineTo(mx, ly + 5 * sc);
  r.paint(theme.marker);
  r.point(mx, ly, theme.pointOnCurve);
}

/** u as TeX: a simple fraction when it is one. */
function uTexOf(u) {
  const f = simpleFraction(u);
  return f && f.den > 1 ? `\\tfrac{${f.num}}{${f.den}}` : knotText(u, true);
}

/** The recurrence; one function (highlighted, else the largest at u) with the live numbers; the sum; C(u). */
export function formula(s, d) {
  const n = s.points.length - 1;
  const p = s.degree;
  const knots = s.knots;
  const kt = (u) => knotText(u, true);
  const k = d.table.span;
  const uTex = uTexOf(s.u);
  const values = d.values;
  const hi = highlighted(s, d);
  const focus = hi >= 0 ? hi : argmax(values, n);
  // N_{i,p−1}(u) from the core's triangle (zero outside k − p + 1 … k).
  const below = (i) => {
    const j = i - (k - p + 1);
    return j >= 0 && j <= p - 1 ? d.table.levels[p - 1][j] : 0;
  };
  const step = coxDeBoorStep({ knots, u: s.u, uTex, p, i: focus, below, value: values[focus] });
  const active = [];
  const weighted = [];
  for (let i = Math.max(0, k - p); i <= Math.min(n, k); i++) {
    active.push(fmtTex(values[i]));
    weighted.push(`${fmtTex(values[i])}\\,P_{${i}}`);
  }
  const point = pointTex([d.point[0], d.point[1]]);
  const span = `[u_{${k}}, u_{${k + 1}}) = [${listTex([kt(knots[k]), kt(knots[k + 1])], 0, " ")})`;
  return [
    coxDeBoorDefinition(`\\text{${t("bsplineBasis.formulaOtherwise")}}`),
    `U = [${listTex(knots.map(kt))}],\\qquad u = ${uTex} \\in ${span}`,
    step,
    `\\sum_{i=0}^{${n}} N_{i,${p}}(${uTex}) = ${active.join(" + ")} = ${fmtTex(d.sum)}`,
    `C(u) = \\sum_{i=0}^{${n}} N_{i,${p}}(u)\\,P_i,\\qquad C(${uTex}) = ${weighted.join(" + ")} = ${point}`,
  ];
}

/**
 * The highlighted basis function (plot hover, table row, then the handle in hand, hovered or
 * selected; setup's pointer), or -1; one of the state's n + 1 functions.
 */
function highlighted(s, d) {
  const hi = d.pointer ? d.pointer.highlighted(d.handles) : -1;
  return hi < s.points.length ? hi : -1;
}

/** Index of the largest of values[0..n] (the first on a tie). */
function argmax(values, n) {
  let best = 0;
  for (let i = 1; i <= n; i++) if (values[i] > values[best]) best = i;
  return best;
}

/** The curve, its knots, the span of u, the non-zero values, C(u), the continuity, the highlight. */
export function label(s, d) {
  const kt = (u) => knotText(u);
  const p = s.degree;
  const k = d.table.span;
  const nonZero = [];
  d.values.forEach((value, i) => value > 0 && nonZero.push(`${basisName(p, i)} = ${fmt(value)}`));
  const joints = d.continuity.map((e) => `${kt(e.knot)}: ${continuityText(e.continuity)}`);
  const continuity = joints.length
    ? t("bsplineBasis.ariaContinuity", { list: joints.join(listSeparator()) })
    : "";
  const hi = highlighted(s, d);
  const ends =
    hi >= 0 ? { name: basisName(p, hi), a: kt(s.knots[hi]), b: kt(s.knots[hi + p + 1]) } : null;
  const support = ends ? t("bsplineBasis.ariaSupport", ends) : "";
  const text = t("bsplineBasis.aria", {
    kind: degreeName(p),
    count: s.points.length,
    knots: listText(s.knots.map(kt)),
    u: kt(s.u),
    a: kt(s.knots[k]),
    b: kt(s.knots[k + 1]),
    values: listText(nonZero),
    sum: fmt(d.sum),
    x: fmt(d.point[0], 2),
    y: fmt(d.point[1], 2),
  });
  return text + continuity + support;
}

/**
 * The square figure, the plot's pointer (press or drag sets u, hover highlights a graph) and
 * the highlight it and the table rows set, the values table and the Cox–de Boor triangle.
 */
export function setup(ui) {
  const { view, data } = ui;
  // A taller figure than the default 16:10: the curve, the plot and the ruler share it.
  ui.ctx.slots.figure.style.aspectRatio = "1 / 1";
  data.plot = { x0: 0, x1: 0, y0: 0, y1: 0, top: 0, bottom: 0 }; // frame (CSS px), strip top/bottom
  let shown = -1;

  const layout = () => layoutBands(data, view.width, view.height, view.renderer.scale);
  const inPlot = (x, y) => {
    layout();
    const plot = data.plot;
    return (
      x >= plot.x0 - KNOT_SNAP_PX && x <= plot.x1 + KNOT_SNAP_PX && y >= plot.top && y < plot.bottom
    );
  };
  const pointer = (data.pointer = new BasisPlotPointer(view, {
    inPlot,
    graphAt(x, y) {
      const { plot } = data;
      const raw = Math.min(1, Math.max(0, (x - plot.x0) / (plot.x1 - plot.x0)));
      const py = (value) => plot.y0 - value * (plot.y0 - plot.y1);
      const k = Math.round(raw * (SAMPLES - 1));
      return nearestGraph(data.basis, ui.state.points.length, SAMPLES, k, y, py, PLOT_HOVER_PX);
    },
    pick(x, final) {
      layout();
      ui.set("u", snapToKnot(ui.state, data, data.ruler.uAt(x)), final);
    },
    enter: () => ui.handles.leave(),
    before: ui.handles,
  }));
  // The highlight (plot hover, table row, handle) is not state: touched when it changes.
  view.beforeFrame(() => {
    const hi = highlighted(ui.state, data);
    if (hi === shown) return;
    shown = hi;
    ui.touch("highlight");
  });

  const values = new BasisValuesTable(strings, pointer, basisName);
  const triangle = new BasisTriangleTable(strings);
  ui.ctx.slots.details.append(values.title, values.wrap, triangle.title, triangle.wrap);

  return {
    update(s, d) {
      const p = s.degree;
      const kt = knotText;
      const uText = kt(s.u);
      const caption = t("bsplineBasis.tableCaption", { p, u: uText });
      values.show(p, s.knots, d.values, d.sum, highlighted(s, d), caption);
      const k = d.table.span;
      const span = {
        k,
        a: kt(s.knots[k]),
        b: kt(s.knots[k + 1]),
        kSub: subscript(k),
        k1Sub: subscript(k + 1),
      };
      triangle.show(p, k, d.table.levels, t("bsplineBasis.triangleCaption", { u: uText, ...span }));
    },
    destroy: () => pointer.reset(),
  };
}
