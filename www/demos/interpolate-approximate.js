/**
 * Demo (syllabus §5, and §7's interactive design): one set of points, two readings. As control
 * points, the points pull an approximating B-spline (`new BSplineCurve` with clamped knots from
 * `knotVector`) that touches only the first and the last; as data, the points are met by an
 * interpolating B-spline (`interpolateBSpline`, as many control points as data points) or,
 * with fewer control points, approximated in the least-squares sense with both ends exact
 * (`approximateBSpline`, NURBS Book 9.4.1):
 *   minimise Σ_{k=1}^{n−1} |p_k − C(t_k)|²  over r₁ … r_{h−1},  r₀ = p₀, r_h = pₙ,
 * t_k the chord-length parameters of the data. The residuals p_k − C(t_k) are drawn (C(t_k)
 * from one batched `sample(params)` call), and their sum of squares and largest length shown.
 *
 * As control points a drag moves the curve in place (`setControlPoint`); as data the fit is
 * global (every control point depends on every data point), so a drag re-solves once per frame.
 */
import { field, checkNumber } from "../lib/validate.js";
import {
  choice,
  slider,
  pointButtons,
  readout,
  group,
  shownWhen,
  INTEGER_SLIDER,
} from "../lib/panel.js";
import { degreeButtons } from "../lib/degree-buttons.js";
import { fmt, subscript, degreeName, fmtTex } from "../lib/format.js";
import { HUES, RADIUS, WIDTH, themed } from "../lib/theme.js";
import { t, tp } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { pointLabel } from "../lib/handles.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { scaledInsets } from "../lib/view.js";
import { drawCornerLegend } from "../lib/legend.js";

export const id = "interpolate-approximate";
export const strings = "interpolateApproximate";
export const section = 5;

/** Fewest and most points. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 16;
/** Degrees offered. */
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
/** The two readings of the points. */
export const ROLES = Object.freeze(["control", "data"]);
/** Parameters of the data (the `kind` of `parameterize`): chord length, as the NURBS Book fits. */
export const PARAMS_KIND = "chord";
/** Points sampled along the curve (one `sampleUniform` per change). */
const CURVE_SAMPLES = 256;
/** Half the side of a ghosted control point's square, CSS px. */
const GHOST_HALF_PX = 3;
/** The key's band at the top of the figure (three rows), CSS px. */
const LEGEND_PX = 70;

/**
 * Ten points sketching one and a half waves, read as data and fitted by a cubic with 7 control
 * points: the three readings differ at a glance (cut peaks, every point met, small residuals).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [2, 4],
      [4, 5],
      [6, 2],
      [8, -3],
      [10, -5],
      [12, -2],
      [14, 3],
      [16, 5],
      [18, 3],
    ].map(Object.freeze),
  ),
  degree: 3,
  role: "data",
  count: 7,
});

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  degree: field.number({ min: MIN_DEGREE, max: MAX_DEGREE, integer: true }),
  role: field.choice(ROLES),
  count: field.number({ min: MIN_DEGREE + 1, max: MAX_POINTS, integer: true }),
};

/** The degree against the points, the number of control points between p + 1 and the points. */
export function check(s) {
  checkNumber(s, "degree", { min: MIN_DEGREE, max: s.points.length - 1, integer: true });
  checkNumber(s, "count", { min: s.degree + 1, max: s.points.length, integer: true });
}

/** A new degree or point list brings the number of control points back into [p + 1, n + 1]. */
export function adjust(s) {
  s.degree = Math.min(s.degree, s.points.length - 1);
  s.count = Math.max(s.degree + 1, Math.min(s.count, s.points.length));
}

/** True when the points are data met exactly: as many control points as data points. */
const interpolating = (s) => s.role === "data" && s.count === s.points.length;

/**
 * The curve: the points as control points (clamped uniform knots), or fitted to them as data
 * (chord-length parameters `params`). Throws the core's refusal (two equal consecutive points
 * have no chord-length parameters).
 */
export const derive = {
  from: ["points", "degree", "role", "count"],
  build(s, sl) {
    const flat = flatten(s.points);
    const p = s.degree;
    if (s.role === "control")
      return { curve: new sl.BSplineCurve(flat, 2, p, sl.knotVector(flat, 2, p, "clamped")) };
    const params = sl.parameterize(flat, 2, PARAMS_KIND);
    const curve = interpolating(s)
      ? sl.interpolateBSpline(flat, 2, p, params)
      : sl.approximateBSpline(flat, 2, p, s.count, params);
    return { curve, params };
  },
  /** Control points move the curve in place; data points are refitted (a rebuild this frame). */
  moved(m, i, xy, s, ui) {
    if (s.role === "control") m.curve.setControlPoint(i, xy);
    else ui.touch("points");
  },
};

/** The residuals: C(t_k) for every data point (one batched call), Σ|p_k − C(t_k)|², the largest. */
function residualsOf(s, d) {
  if (s.role !== "data") return null;
  const at = d.curve.sample(d.params);
  const lengths = s.points.map(([x, y], k) => Math.hypot(x - at[2 * k], y - at[2 * k + 1]));
  let sum = 0;
  let worst = 0;
  lengths.forEach((length, k) => {
    sum += length * length;
    if (length > lengths[worst]) worst = k;
  });
  const max = lengths[worst];
  return { at, sum, max, worst, first: lengths[0], last: lengths[lengths.length - 1] };
}

/** The fitted control points as [x, y] pairs (drawn ghosted). */
function controlPointsOf(s, d) {
  if (s.role !== "data") return null;
  const flat = d.curve.controlPoints();
  const points = [];
  for (let j = 0; j < flat.length; j += 2) points.push([flat[j], flat[j + 1]]);
  return points;
}

const ALL = ["points", "degree", "role", "count"];
export const compute = {
  samples: [ALL, (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  residuals: [ALL, residualsOf],
  control: [ALL, controlPointsOf],
};

/** What the fit does, in words: interpolation, or least squares with its residuals. */
function fitNote(s, d) {
  if (s.role === "control") return t("interpolateApproximate.note.control");
  if (interpolating(s))
    return t("interpolateApproximate.note.interpolation", { max: fmt(d.residuals.max) });
  return t("interpolateApproximate.note.leastSquares", {
    sum: fmt(d.residuals.sum),
    max: fmt(d.residuals.max),
    k: subscript(d.residuals.worst),
  });
}

export const controls = [
  group(
    "interpolateApproximate.roleLegend",
    choice("role", {
      options: ROLES.map((value) => ({ value, label: `interpolateApproximate.role.${value}` })),
    }),
  ),
  group(
    "interpolateApproximate.degreeLegend",
    degreeButtons({
      prefix: strings,
      min: MIN_DEGREE,
      max: MAX_DEGREE,
      apply: (ui, p) => ui.set("degree", p),
    }),
  ),
  shownWhen(
    (s) => s.role === "data",
    group(
      null,
      slider("count", {
        label: "interpolateApproximate.control.count",
        range: (s) => [s.degree + 1, s.points.length],
        ...INTEGER_SLIDER,
        error: (value, s) =>
          t("interpolateApproximate.countRange", {
            value,
            min: s.degree + 1,
            max: s.points.length,
          }),
      }),
    ),
  ),
  group(
    null,
    readout("fit", fitNote, {
      live: true,
      data: (s, d) =>
        d.residuals
          ? {
              residualMax: String(d.residuals.max),
              residualSum: String(d.residuals.sum),
              residualEnds: `${d.residuals.first},${d.residuals.last}`,
            }
          : {},
    }),
  ),
  group(
    null,
    pointButtons("points", {
      min: (s) => Math.max(MIN_POINTS, s.degree + 1),
      max: MAX_POINTS,
      prefix: strings,
      params: (s) => ({ p: s.degree }),
      // An interpolation stays one: the control points follow the number of points.
      adjust: (next, ui) =>
        ui.state.count === ui.state.points.length ? { ...next, count: next.points.length } : next,
    }),
  ),
];

/** P₀ … as control points, p₀ … as data (cached). */
const DATA_LABELS = [];
const dataLabel = (i) => (DATA_LABELS[i] ??= `p${subscript(i)}`);

export const figure = {
  /** The points and, as data, the fitted control points (a least-squares polygon reaches out). */
  bounds: (s, d) => paddedBounds(d.control ? s.points.concat(d.control) : s.points, 0.05, 0.1),
  insets: scaledInsets(LEGEND_PX, 0, 0, 0),
  handles: {
    field: "points",
    label: (i, s) => (s.role === "control" ? pointLabel(i) : dataLabel(i)),
  },
};

const RESIDUAL_STYLE = Object.freeze({ stroke: HUES.vermillion, width: WIDTH.construction });
const FOOT_STYLE = Object.freeze({ fill: HUES.vermillion, radius: RADIUS.constructionPoint - 1 });
const stylesFor = themed((theme) => ({ ghost: { fill: theme.polygon.stroke } }));

/** The keys: as control points (curve, their polygon), as data (curve, fitted polygon, residuals). */
const CONTROL_KEY = Object.freeze([
  { label: "interpolateApproximate.legendCurve", style: (theme) => theme.curve },
  { label: "interpolateApproximate.legendGiven", style: (theme) => theme.polygon },
]);
const DATA_KEY = Object.freeze([
  { label: "interpolateApproximate.legendCurve", style: (theme) => theme.curve },
  { label: "interpolateApproximate.legendFitted", style: (theme) => theme.polygon },
  { label: "interpolateApproximate.legendResidual", style: RESIDUAL_STYLE },
]);

/**
 * As control points: the polygon and the curve. As data: the fitted control polygon ghosted
 * (dashed, grey squares), the curve, the residual segments p_k → C(t_k) with a dot at C(t_k).
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  if (s.role === "control") {
    pointsPath(r, v, s.points);
    r.paint(theme.polygon);
  } else {
    pointsPath(r, v, d.control);
    r.paint(theme.polygon);
    const half = GHOST_HALF_PX * r.scale;
    r.beginPath();
    for (const [x, y] of d.control) r.rect(v.sx(x) - half, v.sy(y) - half, 2 * half, 2 * half);
    r.paint(styles.ghost);
  }
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  if (d.residuals) {
    const { at } = d.residuals;
    r.beginPath();
    s.points.forEach(([x, y], k) => {
      r.moveTo(v.sx(x), v.sy(y));
      r.lineTo(v.sx(at[2 * k]), v.sy(at[2 * k + 1]));
    });
    r.paint(RESIDUAL_STYLE);
    for (let k = 0; k < s.points.length; k++)
      r.point(v.sx(at[2 * k]), v.sy(at[2 * k + 1]), FOOT_STYLE);
  }
  d.handles.draw(r, v);
  drawCornerLegend(r, s.role === "control" ? CONTROL_KEY : DATA_KEY);
}

/** The curve and what its control points are: given, interpolating, or least squares. */
export function formula(s, d) {
  const p = s.degree;
  const n = s.points.length - 1;
  if (s.role === "control") {
    return [
      `C(u) = \\sum_{i=0}^{${n}} N_{i,${p}}(u)\\, P_i,\\quad ` +
        `\\text{${t("interpolateApproximate.tex.control")}}`,
      `C(0) = P_0,\\quad C(${n - p + 1}) = P_{${n}}`,
    ];
  }
  const h = s.count - 1;
  const curve = `C(u) = \\sum_{j=0}^{${h}} N_{j,${p}}(u)\\, r_j`;
  if (interpolating(s)) {
    return [
      `${curve},\\quad C(t_k) = p_k\\ (k = 0,\\dots,${n})`,
      `\\max_k |p_k - C(t_k)| = ${fmtTex(d.residuals.max)}`,
    ];
  }
  return [
    `${curve},\\quad r_0 = p_0,\\ r_{${h}} = p_{${n}}`,
    `\\min_{r_1,\\dots,r_{${h - 1}}} \\sum_{k=1}^{${n - 1}} |p_k - C(t_k)|^2 = ${fmtTex(d.residuals.sum)}`,
    `\\max_k |p_k - C(t_k)| = ${fmtTex(d.residuals.max)}\\ (k = ${d.residuals.worst})`,
  ];
}

/** "cubic B-spline fitted to 10 data points with 6 control points (least squares), …". */
export function label(s, d) {
  const kind = degreeName(s.degree);
  if (s.role === "control")
    return t("interpolateApproximate.aria.control", { kind, count: s.points.length });
  return t("interpolateApproximate.aria.data", {
    kind,
    count: s.points.length,
    control: tp("interpolateApproximate.controlPoints", s.count),
    fit: t(
      interpolating(s)
        ? "interpolateApproximate.aria.interpolation"
        : "interpolateApproximate.aria.leastSquares",
    ),
    max: fmt(d.residuals.max, 2),
  });
}
