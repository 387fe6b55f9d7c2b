/**
 * Demo (syllabus §5): Lagrange interpolation and Aitken's triangle. One polynomial of degree n
 * through the n + 1 data points p_i at the parameters t_i (uniform, chord or centripetal, from
 * the core's `parameterize`),
 *
 *   P(t) = Σ L_i(t) p_i,   L_i(t) = Π_{j≠i} (t − t_j)/(t_i − t_j),
 *
 * against the C2 natural cubic spline through the same points at the same parameters. P(t) is
 * built by Aitken's recurrence, drawn like de Casteljau's triangle,
 *
 *   p_i^r = (t_{i+r} − t)/(t_{i+r} − t_i) p_i^{r−1} + (t − t_i)/(t_{i+r} − t_i) p_{i+1}^{r−1},
 *
 * whose weights leave [0, 1] as soon as t is outside [t_i, t_{i+r}]: the new point lies on the
 * line of its leg but beyond it (that extension is drawn dotted) — no convex hull. Under the
 * figure, every L_i over the domain (they sum to 1 and go negative); a count that puts that many
 * points on Runge's bell, at uniform parameters, shows the wiggle growing with the degree.
 *
 * From the core: the curves' samples (`sampleUniform`), the triangle (`aitken(t)`), the basis
 * at t (`basis(t)`) and the basis graphs — L_i is the polynomial through the data δ_ij, so each
 * pair L_i, L_{i+1} is one `lagrange(…).sampleUniform` through the 2D points (δ_ij, δ_{i+1,j}),
 * asked again only when the parameters change. Both curves are given the kind of parameters, so
 * a drag moves them in place (`setPoint`) and chord or centripetal parameters follow the points.
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, choice, pointButtons, readout, group } from "../lib/panel.js";
import { fmt, shortNumber, subscript } from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, paddedBounds, nearestGraph } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import {
  drawLevels,
  levelStart,
  LevelLabels,
  LegLabelPlacer,
  screenCentroid,
} from "../lib/triangle.js";
import { drawCornerLegend, LEGEND_ROW_PX } from "../lib/legend.js";
import { SECOND_CURVE, HELPER_DASH, themed } from "../lib/theme.js";
import { replaceOrReport } from "../lib/wasm.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";
import { BasisPlotPointer, followHighlight } from "../lib/basis-plot.js";
import { SignedBasisPlot } from "../lib/signed-basis-plot.js";
import { PARAM_KINDS, withTIn } from "../lib/data-params.js";
import { countSlider } from "../lib/runge.js";
import { exactness, lagrangeFormula, LagrangeTables } from "../lib/aitken-text.js";
import { errorText } from "../lib/core-errors.js";

export const id = "lagrange";
export const strings = "lagrange";
export const section = 5;

/** Fewest and most data points (degree 2 … 15). */
export const MIN_POINTS = 3;
export const MAX_POINTS = 16;
/** Samples along each curve and each basis graph (sample k at s = k/(SAMPLES − 1) of the domain). */
const SAMPLES = 241;
/** Slider resolution: this fraction of the domain. */
const T_RESOLUTION = 0.001;
/** Intermediate points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_LEVELS_MAX_DEGREE = 4;
/** Fitting leaves this fraction of the width / height free for labels and the wiggle. */
const ROOM_X = 0.05;
const ROOM_Y = 0.25;
/** The key: two rows in the top-left corner (a band of this many CSS px at scale 1). */
const LEGEND_BAND = 2 * LEGEND_ROW_PX + 8;
/** A press in the plot snaps to a data parameter within this many CSS px. */
const SNAP_PX = 6;
/** A pointer this close (CSS px, vertically) to a basis graph highlights it. */
const PLOT_HOVER_PX = 12;
/** The plot of the L_i: 0.34 of the canvas (at least 150 px), values shown down to −2, up to 3. */
const plot = new SignedBasisPlot({ fraction: 0.34, minPx: 150, shortFraction: 0.5, cap: 2 });

/**
 * Five integer points at uniform parameters 0 … 4 and t = 3/2: L_i(3/2) = −5/128, 15/32, 45/64,
 * −5/32, 3/128 and P(3/2) = (67/16, 65/16), above every data point (no convex hull); level 1
 * already leaves its legs (p_0^1 = (3, 9/2) past p_1, p_3^1 = (2, 5/2) before p_3).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [2, 3],
      [6, 4],
      [8, 1],
      [12, 0],
    ].map(Object.freeze),
  ),
  params: "uniform",
  t: 1.5,
  construction: true,
});

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  params: field.choice(PARAM_KINDS),
  t: field.number({ min: -1e12, max: 1e12 }),
  construction: field.boolean(),
};

/**
 * The polynomial and the natural spline of a state, both given the kind of parameters (the core
 * computes them from the points, and again after every `setPoint`), and those parameters.
 */
function fitOf(sl, s) {
  const flat = flatten(s.points);
  const lagrange = sl.lagrange(flat, 2, s.params);
  let spline;
  try {
    spline = sl.cubicSpline(flat, 2, s.params, "natural");
  } catch (err) {
    lagrange.free();
    throw err;
  }
  const fit = { lagrange, spline, params: null, domain: null };
  return withParams(fit);
}

/** Reads the parameters t_i and the domain [t_0, t_n] back from the polynomial. */
function withParams(fit) {
  fit.params = fit.lagrange.params();
  fit.domain = [fit.params[0], fit.params[fit.params.length - 1]];
  return fit;
}

/**
 * The model: `holder.fit` (the two curves, their parameters and domain), `refusal` (a move the
 * core refused during a drag — a repeated point under chord spacing — for the status line). t
 * outside the domain is refused, naming it (links and files; the controls keep it inside).
 */
export const derive = {
  from: ["points", "params"],
  build(s, sl) {
    const fit = fitOf(sl, s);
    const [a, b] = fit.domain;
    if (!(s.t >= a && s.t <= b)) {
      fit.lagrange.free();
      fit.spline.free();
      throw new Error(
        t("lagrange.error.t", { t: shortNumber(s.t), a: shortNumber(a), b: shortNumber(b) }),
      );
    }
    const holder = {
      fit,
      free() {
        this.fit.lagrange.free();
        this.fit.spline.free();
      },
    };
    return { holder, refusal: { message: null } };
  },
  /** Both curves move in place; chord or centripetal parameters follow, t stays in the domain. */
  moved(m, i, xy, s) {
    const fit = m.holder.fit;
    try {
      fit.spline.setPoint(i, xy);
      fit.lagrange.setPoint(i, xy);
    } catch (err) {
      m.refusal.message = errorText(err);
      return;
    }
    if (s.params === "uniform") return;
    withParams(fit);
    s.t = Math.min(Math.max(s.t, fit.domain[0]), fit.domain[1]);
  },
};

/**
 * The basis graphs (i-major, SAMPLES each) from the core's `basisCurves`, at the t of
 * `sampleUniform`. They depend on the parameters only: kept while those stay (a drag at uniform
 * parameters moves no graph).
 */
function basisCurves(lagrange, params, previous) {
  if (previous && previous.params.length === params.length) {
    if (previous.params.every((v, k) => v === params[k])) return previous;
  }
  return { params: Float64Array.from(params), values: lagrange.basisCurves(SAMPLES) };
}

/** The data parameters normalised to [0, 1] (the plot's ticks) and their texts. */
function ticksOf(params) {
  const a = params[0];
  const b = params[params.length - 1];
  return {
    at: Array.from(params, (v) => (v - a) / (b - a)),
    labels: Array.from(params, (v) => shortNumber(v)),
  };
}

const fitIn = (d) => d.holder.fit;
const ALL = ["points", "params"];
const AT_T = ["points", "params", "t"];

/** What the core returns: samples, basis graphs, the triangle and the basis at t, S(t). */
export const compute = {
  curve: [ALL, (s, d) => fitIn(d).lagrange.sampleUniform(SAMPLES)],
  spline: [ALL, (s, d) => fitIn(d).spline.sampleUniform(SAMPLES)],
  basisCurves: [ALL, (s, d) => basisCurves(fitIn(d).lagrange, fitIn(d).params, d.basisCurves)],
  ticks: [ALL, (s, d) => ticksOf(fitIn(d).params)],
  triangle: [AT_T, (s, d) => fitIn(d).lagrange.aitken(s.t)],
  basis: [AT_T, (s, d) => fitIn(d).lagrange.basis(s.t)],
  splinePoint: [AT_T, (s, d) => fitIn(d).spline.evaluate(s.t)],
  exact: [AT_T, (s, d) => exactness(s, fitIn(d).params)],
  highlight: [["highlight", "points"], (s, d) => d.highlighted()],
};

/** Keeps t at the same place in the new domain of a changed state (ui.replace builds it). */
const rescaled = (ui, next) => withTIn(ui.sl, next, fitIn(ui.data).domain);

export const controls = [
  group(
    null,
    slider("t", {
      label: "lagrange.control.t",
      range: (s, d) => fitIn(d).domain,
      step: (a, b) => (b - a) * T_RESOLUTION,
      player: {
        stepBackTitle: "lagrange.control.stepBack.title",
        stepTitle: "lagrange.control.step.title",
      },
    }),
    readout("sum", (s, d) => sumNote(s, d)),
  ),
  group(
    "lagrange.control.params",
    choice("params", {
      options: PARAM_KINDS.map((value) => ({ value, label: `lagrange.params.${value}` })),
      set: (ui, kind) =>
        kind !== ui.state.params &&
        replaceOrReport(ui, rescaled(ui, { ...ui.state, params: kind })),
    }),
  ),
  group(
    "lagrange.control.runge",
    countSlider({ prefix: strings, min: MIN_POINTS, max: MAX_POINTS, rescaled }),
    readout("degree", (s) => tp("lagrange.degree", s.points.length, { n: s.points.length - 1 })),
  ),
  group(
    null,
    pointButtons("points", {
      min: MIN_POINTS,
      max: MAX_POINTS,
      prefix: strings,
      adjust: (s, ui) => rescaled(ui, s),
    }),
    checkbox("construction", { label: "control.construction" }),
  ),
];

const insetScratch = [0, 0, 0, 0];

export const figure = {
  bounds: (s) => paddedBounds(s.points, ROOM_X, ROOM_Y),
  insets(width, height, scale) {
    insetScratch[0] = LEGEND_BAND * scale;
    insetScratch[2] = plot.height(height);
    return insetScratch;
  },
  handles: { field: "points", label: (i) => `p${subscript(i)}` },
};

/** The key in the top-left corner. */
const LEGEND = Object.freeze([
  { label: "lagrange.legendPolynomial", style: (theme) => theme.curve },
  { label: "lagrange.legendSpline", style: SECOND_CURVE.curve },
]);
/** Dotted copies of the level colours for a leg's extension up to a point beyond it. */
const extensionStyles = themed((theme) =>
  [theme.helper].concat(theme.levelStroke.map((style) => ({ ...style, dash: HELPER_DASH }))),
);
const labels = new LevelLabels("p");
/** A level's label that cannot keep this far (px) from the points and other labels is left out. */
const LABEL_CLEARANCE_PX = 16;
const placer = new LegLabelPlacer(32, LABEL_CLEARANCE_PX);
/** Where P(t)'s label goes: chosen before the levels' labels (they keep clear of it), drawn last. */
const apexLabel = new Float64Array(4);
const centre = new Float64Array(2);

/** Data polygon, spline, polynomial, the triangle at t, handles, P(t) and S(t), key, plot. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const n = s.points.length - 1;
  if (s.construction) {
    pointsPath(r, v, s.points);
    r.paint(theme.polygon);
  }
  flatPath(r, v, d.spline, 0, SAMPLES);
  r.paint(SECOND_CURVE.curve);
  flatPath(r, v, d.curve, 0, SAMPLES);
  r.paint(theme.curve);
  screenCentroid(v, s.points, centre);
  placer.reset();
  placer.points = s.points;
  const radius = theme.pointOnCurve.radius * r.scale;
  placer.choose(r, v, d.triangle, n, n, 0, centre, radius, s.points);
  apexLabel.set(placer.chosen);
  if (s.construction) {
    drawExtensions(r, v, d.triangle, fitIn(d).params, s.t, n);
    // On a phone the labels crowd: the table names every point.
    const narrow = v.width < NARROW_CANVAS_PX * r.scale;
    const named = n <= LABEL_LEVELS_MAX_DEGREE && !narrow ? labels : null;
    drawLevels(r, v, d.triangle, n, centre, named, placer);
  }
  d.handles.draw(r, v);
  const sx = v.sx(d.splinePoint[0]);
  const sy = v.sy(d.splinePoint[1]);
  r.point(sx, sy, theme.comparePoint[1]);
  const apex = 2 * levelStart(n, n);
  r.point(v.sx(d.triangle[apex]), v.sy(d.triangle[apex + 1]), theme.pointOnCurve);
  placer.draw(r, t("lagrange.pointLabel"), theme.labelPoint, radius, apexLabel);
  // The key's band (the figure's top inset) covers whatever runs into it: a wild polynomial.
  r.beginPath();
  r.rect(0, 0, r.width, LEGEND_BAND * r.scale);
  r.paint(theme.plotBackground);
  drawCornerLegend(r, LEGEND);
  drawPlot(r, s, d);
}

/**
 * For every point p_i^r of the triangle whose weight (t − t_i)/(t_{i+r} − t_i) is outside
 * [0, 1]: the dotted continuation of its leg from the nearer end of the leg to the point.
 */
function drawExtensions(r, v, triangle, params, tValue, n) {
  const styles = extensionStyles(r.theme);
  for (let level = 1; level <= n; level++) {
    const below = levelStart(n, level - 1);
    const here = levelStart(n, level);
    r.beginPath();
    for (let i = 0; i + level <= n; i++) {
      const lambda = (tValue - params[i]) / (params[i + level] - params[i]);
      if (lambda >= 0 && lambda <= 1) continue;
      const from = 2 * (below + i + (lambda > 1 ? 1 : 0));
      r.moveTo(v.sx(triangle[from]), v.sy(triangle[from + 1]));
      r.lineTo(v.sx(triangle[2 * (here + i)]), v.sy(triangle[2 * (here + i) + 1]));
    }
    r.paint(level === 1 ? styles[0] : styles[1 + ((level - 2) % (styles.length - 1))]);
  }
}

/** The plot of every L_i over the normalised parameter, the data parameters ticked, t marked. */
function drawPlot(r, s, d) {
  const n = s.points.length - 1;
  const [a, b] = fitIn(d).domain;
  plot.layout(r.width, r.height, r.scale, d.basisCurves.values);
  plot.drawFrame(r, d.ticks.at, d.ticks.labels, t("lagrange.axisT"));
  plot.drawGraphs(r, d.basisCurves.values, n + 1, SAMPLES, d.highlight);
  const marker = t("lagrange.marker", { t: d.exact.param() });
  plot.drawMarker(r, (s.t - a) / (b - a), marker, d.basis);
}

/** "Σ L_i(t) = 1; smallest L_3(t) = −0.125 < 0". */
function sumNote(s, d) {
  let sum = 0;
  let low = 0;
  for (let i = 0; i < d.basis.length; i++) {
    sum += d.basis[i];
    if (d.basis[i] < d.basis[low]) low = i;
  }
  const n = s.points.length - 1;
  const params = {
    sum: d.exact.basis(sum, n),
    i: subscript(low),
    value: d.exact.basis(d.basis[low], n),
  };
  return t(d.basis[low] < 0 ? "lagrange.sumNegative" : "lagrange.sumNote", params);
}

/** The Lagrange form, Aitken's recurrence and its last step with the current numbers. */
export const formula = (s, d) => lagrangeFormula(s, d, fitIn(d));

/** "Lagrange polynomial of degree 4 through 5 points (uniform parameters); t = 0.5; P(t) = …". */
export function label(s, d) {
  const n = s.points.length - 1;
  const apex = 2 * levelStart(n, n);
  return t("lagrange.aria", {
    n,
    count: n + 1,
    params: t(`lagrange.paramsName.${s.params}`),
    t: fmt(s.t),
    x: fmt(d.triangle[apex], 2),
    y: fmt(d.triangle[apex + 1], 2),
    sx: fmt(d.splinePoint[0], 2),
    sy: fmt(d.splinePoint[1], 2),
  });
}

/**
 * The taller figure, the plot's pointer (press or drag sets t, snapped to a data parameter
 * nearby; hover highlights a graph and its row) and the tables: the basis at t, Aitken's levels.
 */
export function setup(ui) {
  const view = ui.view;
  ui.ctx.slots.figure.classList.add("sl-figure-tall");
  const inPlot = (x, y) => {
    plot.layout(view.width, view.height, view.renderer.scale, ui.data.basisCurves.values);
    return plot.contains(x, y, SNAP_PX);
  };
  /** t under canvas x: a data parameter within SNAP_PX, else rounded to the slider's step. */
  const tAt = (x) => {
    const [a, b] = fitIn(ui.data).domain;
    const u = plot.parameterAt(x);
    const ticks = ui.data.ticks.at;
    for (let i = 0; i < ticks.length; i++) {
      if (Math.abs(plot.x(ticks[i]) - x) <= SNAP_PX * view.renderer.scale)
        return fitIn(ui.data).params[i];
    }
    const step = (b - a) * T_RESOLUTION;
    return Math.min(b, a + Math.round((u * (b - a)) / step) * step);
  };
  const pointer = new BasisPlotPointer(view, {
    inPlot,
    graphAt: (x, y) => {
      const k = Math.round(plot.parameterAt(x) * (SAMPLES - 1));
      const values = ui.data.basisCurves.values;
      return nearestGraph(
        values,
        ui.state.points.length,
        SAMPLES,
        k,
        y,
        (w) => plot.y(w),
        PLOT_HOVER_PX,
      );
    },
    pick: (x, final) => ui.set("t", tAt(x), final),
    press: () => ui.stop(),
    enter: () => ui.handles.leave(),
    first: true,
  });
  followHighlight(ui, pointer);
  const tables = new LagrangeTables(ui, pointer);
  return {
    update(s, d) {
      if (d.refusal.message) {
        ui.status(t("status.rejected", { message: d.refusal.message }), "error");
        d.refusal.message = null;
      }
      tables.show(s, d, fitIn(d));
    },
  };
}
