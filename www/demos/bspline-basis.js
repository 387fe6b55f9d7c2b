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
import { BasisPlotPointer, drawGraph, drawPlotFrame, legendRow } from "../lib/basis-plot.js";
import { placeLabelAway } from "../lib/handles.js";
import { radios, el, setText } from "../lib/controls.js";
import {
  fmt,
  subscript,
  superscript,
  simpleFraction,
  fractionText,
  degreeName,
} from "../lib/format.js";
import { CYCLE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { boundsOf, nearestGraph } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { BasisTriangleTable } from "../lib/basis-triangle.js";
import { flatPath, pointsPath } from "../lib/draw.js";

export const id = "bspline-basis";
/** Prefix of this demo's keys in strings.js. */
export const strings = "bsplineBasis";
/** Syllabus section. */
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
/** Length of a tick mark on the value axis, CSS px. */
const TICK_PX = 5;
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

/** Sample index of each N_i's maximum (where its name goes). */
function peaks(basis, count) {
  const peak = new Int32Array(count);
  for (let i = 0; i < count; i++) {
    for (let k = 1; k < SAMPLES; k++)
      if (basis[i * SAMPLES + k] > basis[i * SAMPLES + peak[i]]) peak[i] = k;
  }
  return peak;
}

const BASIS = ["degree", "knots"];
/** What the core returns: every N_{i,p} sampled, the continuity, the curve, the values at u. */
export const compute = {
  basis: [BASIS, (s, d) => d.curve.basisCurves(SAMPLES)], // i-major: every N_{i,p} at SAMPLES u values
  peaks: [BASIS, (s, d) => peaks(d.basis, s.points.length)],
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

/** The degree buttons: 1 … 5, those above n disabled; a new degree gets clamped uniform knots. */
const degreeButtons = {
  build(ui) {
    const options = [];
    for (let p = MIN_DEGREE; p <= MAX_DEGREE; p++) {
      options.push({
        value: String(p),
        label: t("bsplineBasis.degreeOption", { p, kind: degreeName(p) }),
      });
    }
    const control = radios({
      name: "degree",
      value: String(ui.state.degree),
      options,
      onChange(value) {
        const p = Number(value);
        const s = ui.state;
        if (p === s.degree) return;
        if (s.points.length < p + 1)
          ui.status(t("bsplineBasis.minPoints", { min: p + 1, degree: p }), "error");
        else replaceOrReport(ui, withClampedKnots(ui.sl, { ...s, degree: p }));
        control.set(String(ui.state.degree));
      },
    });
    control.element.classList.add("sl-button-row");
    return {
      element: control.element,
      sync(s) {
        control.set(String(s.degree));
        for (const input of control.inputs)
          input.disabled = Number(input.value) > s.points.length - 1;
      },
    };
  },
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
  group("bsplineBasis.degreeLegend", degreeButtons),
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

/** Styles of the plot that the theme does not have, made once per theme. */
const supportStyles = new WeakMap();
function supportFill(theme) {
  let list = supportStyles.get(theme);
  if (!list) {
    list = Object.freeze(
      CYCLE.map((colour) => Object.freeze({ fill: colour, alpha: SUPPORT_ALPHA })),
    );
    supportStyles.set(theme, list);
  }
  return list;
}

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
  // A line at each distinct knot in the domain.
  r.beginPath();
  for (let a = 0; a < knots.length; a++) {
    if (knots[a] < u0 || knots[a] > u1 || (a > 0 && knots[a] === knots[a - 1])) continue;
    r.moveTo(ruler.px(knots[a]), plot.y1);
    r.lineTo(ruler.px(knots[a]), plot.y0);
  }
  r.paint(theme.helper);
  const tick = (TICK_PX + 2) * sc;
  r.text(
    t("bsplineBasis.axisValue0"),
    plot.x0 - tick,
    plot.y0,
    theme.labelSmall,
    "right",
    "middle",
  );
  r.text(
    t("bsplineBasis.axisValue1"),
    plot.x0 - tick,
    plot.y1,
    theme.labelSmall,
    "right",
    "middle",
  );
  r.text(t("bsplineBasis.axisU"), plot.x1 + tick, plot.y0, theme.labelSmall, "left", "middle");

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
    for (let i = 0; i <= n; i++) {
      const k = d.peaks[i];
      const align = k === 0 ? "left" : k === SAMPLES - 1 ? "right" : "center";
      const dx = (k === 0 ? 4 : k === SAMPLES - 1 ? -4 : 0) * sc;
      const style = i === hi ? theme.labelBold : theme.labelSmall;
      r.text(
        basisName(p, i),
        sampleX(k) + dx,
        py(d.basis[i * SAMPLES + k]) - 4 * sc,
        style,
        align,
        "bottom",
      );
    }
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
  return f && f.den > 1 ? `\\tfrac{${f.num}}{${f.den}}` : knotText(u);
}

/** The recurrence; one function (highlighted, else the largest at u) with the live numbers; the sum; C(u). */
export function formula(s, d) {
  const n = s.points.length - 1;
  const p = s.degree;
  const knots = s.knots;
  const kt = knotText;
  const k = d.table.span;
  const uText = kt(s.u);
  const uTex = uTexOf(s.u);
  const values = d.values;
  const hi = highlighted(s, d);
  const focus = hi >= 0 ? hi : argmax(values, n);
  // N_{i,r}(u) from the core's triangle (zero outside k − r … k).
  const level = (r, i) => {
    const j = i - (k - r);
    return j >= 0 && j <= r ? d.table.levels[r][j] : 0;
  };
  // One side of the recurrence: (num / den) N_{i, p−1}(u), or 0 when den = 0 (0/0 := 0).
  const side = (num, den, i, numTex, denTex) => {
    if (den === 0) return { part: "0", numbers: "0" };
    const part = `\\frac{${numTex}}{${denTex}}\\,N_{${i},${p - 1}}(${uTex})`;
    return { part, numbers: `${fmt(num / den)}\\cdot ${fmt(level(p - 1, i))}` };
  };
  const [a, b, c, e] = [knots[focus], knots[focus + p], knots[focus + 1], knots[focus + p + 1]];
  const left = side(s.u - a, b - a, focus, `${uText}-${kt(a)}`, `${kt(b)}-${kt(a)}`);
  const right = side(e - s.u, e - c, focus + 1, `${kt(e)}-${uText}`, `${kt(e)}-${kt(c)}`);
  const active = [];
  const weighted = [];
  for (let i = Math.max(0, k - p); i <= Math.min(n, k); i++) {
    active.push(fmt(values[i]));
    weighted.push(`${fmt(values[i])}\\,P_{${i}}`);
  }
  const otherwise = `\\text{${t("bsplineBasis.formulaOtherwise")}}`;
  const zero = `N_{i,0}(u) = \\begin{cases} 1 & u_i \\le u < u_{i+1} \\\\ 0 & ${otherwise} \\end{cases}`;
  const recurrence =
    "N_{i,p}(u) = \\frac{u-u_i}{u_{i+p}-u_i}\\,N_{i,p-1}(u) + \\frac{u_{i+p+1}-u}{u_{i+p+1}-u_{i+1}}\\,N_{i+1,p-1}(u)";
  const point = `(${fmt(d.point[0])},\\ ${fmt(d.point[1])})`;
  const span = `[u_{${k}}, u_{${k + 1}}) = [${kt(knots[k])}, ${kt(knots[k + 1])})`;
  const numbers = `${left.numbers} + ${right.numbers}`;
  return [
    `${zero},\\qquad ${recurrence},\\quad \\tfrac{0}{0} := 0`,
    `U = [${knots.map(kt).join(",\\ ")}],\\qquad u = ${uTex} \\in ${span}`,
    `N_{${focus},${p}}(${uTex}) = ${left.part} + ${right.part} = ${numbers} = ${fmt(values[focus])}`,
    `\\sum_{i=0}^{${n}} N_{i,${p}}(${uTex}) = ${active.join(" + ")} = ${fmt(d.sum)}`,
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
  const kt = knotText;
  const p = s.degree;
  const k = d.table.span;
  const nonZero = [];
  d.values.forEach((value, i) => value > 0 && nonZero.push(`${basisName(p, i)} = ${fmt(value)}`));
  const continuityText = (e) =>
    e.continuity < 0 ? t("knotRuler.break") : `C${superscript(e.continuity)}`;
  const joints = d.continuity.map((e) => `${kt(e.knot)}: ${continuityText(e)}`);
  const continuity = joints.length
    ? t("bsplineBasis.ariaContinuity", { list: joints.join(", ") })
    : "";
  const hi = highlighted(s, d);
  const ends =
    hi >= 0 ? { name: basisName(p, hi), a: kt(s.knots[hi]), b: kt(s.knots[hi + p + 1]) } : null;
  const support = ends ? t("bsplineBasis.ariaSupport", ends) : "";
  const text = t("bsplineBasis.aria", {
    kind: degreeName(p),
    count: s.points.length,
    knots: s.knots.map(kt).join(", "),
    u: kt(s.u),
    a: kt(s.knots[k]),
    b: kt(s.knots[k + 1]),
    values: nonZero.join(", "),
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

  const values = titledTable("basis");
  const triangle = new BasisTriangleTable(strings);
  ui.ctx.slots.details.append(values.title, values.wrap, triangle.title, triangle.wrap);
  let valuesShape = ""; // "count/p" the values table was built for
  let rows = []; // per i: { row, support, value, exact }
  let sumValue = null;

  /** Rebuilds the values table for n + 1 functions of degree p. */
  function buildValues(n, p) {
    const column = (key) => el("th", { scope: "col", text: t(`bsplineBasis.${key}`) });
    rows = [];
    for (let i = 0; i <= n; i++) {
      const cells = { support: el("span"), value: el("span", { class: "sl-cell-value" }) };
      cells.exact = el("span", { class: "sl-cell-decimal" });
      const name = t("bsplineBasis.rowName", { name: basisName(p, i), point: `P${subscript(i)}` });
      cells.row = legendRow(
        pointer,
        i,
        name,
        el("td", { dataset: { cell: "support" } }, cells.support),
        el("td", { dataset: { cell: "value" } }, cells.value, cells.exact),
      );
      rows.push(cells);
    }
    sumValue = el("span", { class: "sl-cell-value" });
    const sumHead = el("th", { scope: "row", text: t("bsplineBasis.sumRow") });
    const sumCell = el("td", { dataset: { cell: "value" } }, sumValue);
    const sumRow = el("tr", { dataset: { index: "sum" } }, sumHead, el("td", {}), sumCell);
    const head = el("tr", {}, column("colFunction"), column("colSupport"), column("colValue"));
    values.table.replaceChildren(
      el("thead", {}, head),
      el(
        "tbody",
        {},
        rows.map((r) => r.row),
        sumRow,
      ),
    );
  }

  return {
    update(s, d) {
      const n = s.points.length - 1;
      const p = s.degree;
      const kt = knotText;
      const uText = kt(s.u);
      if (valuesShape !== `${n + 1}/${p}`) {
        valuesShape = `${n + 1}/${p}`;
        buildValues(n, p);
      }
      setText(values.title, t("bsplineBasis.tableCaption", { p, u: uText }));
      const hi = highlighted(s, d);
      rows.forEach((cells, i) => {
        const ends = { a: kt(s.knots[i]), b: kt(s.knots[i + p + 1]) };
        setText(
          cells.support,
          t("bsplineBasis.supportCell", { i: subscript(i), j: subscript(i + p + 1), ...ends }),
        );
        setText(cells.value, fmt(d.values[i]));
        const f = simpleFraction(d.values[i]);
        setText(cells.exact, f && f.den > 1 ? `= ${fractionText(f)}` : "");
        cells.row.classList.toggle("sl-highlight", i === hi);
      });
      setText(sumValue, fmt(d.sum));
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
