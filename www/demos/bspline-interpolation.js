/**
 * Demo (syllabus §5): global B-spline interpolation, after the Croatian notes (002). Data points
 * p₀ … pₙ (the handles) at parameters t₀ < … < tₙ (uniform, chord or centripetal, from the
 * core's `parameterize`), and optionally the derivatives C′(t₀) = D₀ and C′(tₙ) = Dₙ with respect
 * to the parameter (arrows from p₀ and pₙ, drawn at full length: the tip is p₀ + D₀). The core
 * (`interpolateBSpline`) finds the control points r₀ … r_m of a degree-p B-spline
 *   C(u) = Σ_j N_{j,p}(u) r_j   with   C(t_i) = p_i,   C′(t₀) = D₀,   C′(tₙ) = Dₙ,
 * one condition per unknown; `bsplineInterpolationSystem` returns that square system A r = b,
 * which the table shows row by row with the condition it states, and the solution r_j.
 *
 * The default state is the notes' worked example: 5 points, t = 0 … 4, p = 2, a start
 * derivative, knots 0 0 0 1 2 3 4 4 4 given explicitly: rows 1, −2 2, ½ ½ …, 1 (a 6 × 6 system).
 * The notes give no coordinates: their example is any five points with that set-up, so moving
 * the points or D₀ keeps the notes' knots (the matrix stays theirs, b and r change); a change
 * of the set-up (count, degree, parameters, end conditions) or unticking "the notes' knots"
 * passes no knots: the core's default rule (averaged parameters).
 *
 * There is no "move one data point in place" for a global interpolant (every control point
 * depends on every data point), so a drag re-solves: the model is rebuilt once per frame.
 */
import { field } from "../lib/validate.js";
import {
  choice,
  checkbox,
  pointButtons,
  readout,
  actions,
  group,
  shownWhen,
} from "../lib/panel.js";
import { degreeButtons } from "../lib/degree-buttons.js";
import { knotVectorReadout, knotListText } from "../lib/knot-readout.js";
import {
  subscript,
  degreeName,
  exactText,
  pointText,
  DECIMALS,
  listTex,
  listText,
  pointTex,
  exactTex,
  clauseSeparator,
} from "../lib/format.js";
import { HUES, RADIUS, WIDTH, themed } from "../lib/theme.js";
import { t, tp } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { placeLabelFrom } from "../lib/handles.js";
import { flatPath } from "../lib/draw.js";
import { vectorTip, vectorArrow, tipOf } from "../lib/vector-handle.js";
import { NARROW_CANVAS_PX, scaledInsets } from "../lib/view.js";
import { drawCornerLegend } from "../lib/legend.js";
import { SystemTable, rowPoint } from "../lib/system-table.js";

export const id = "bspline-interpolation";
export const strings = "bsplineInterpolation";
export const section = 5;

/** Fewest and most data points. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 16;
/** Degrees offered (the core interpolates degree 1 … 10). */
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 10;
/** Parametrisations (the `kind` of `parameterize`). */
export const PARAMS = Object.freeze(["uniform", "chord", "centripetal"]);
/** The notes' knot vector for their example (5 points, t = 0 … 4, p = 2, start derivative). */
export const NOTES_KNOTS = Object.freeze([0, 0, 0, 1, 2, 3, 4, 4, 4]);
/** The table shows systems up to this many unknowns (beyond, a note says how many there are). */
export const TABLE_MAX_UNKNOWNS = 12;
/** Points sampled along the curve (one `sampleUniform` per change). */
const CURVE_SAMPLES = 256;
/** A matrix entry closer than this to 0 is shown as 0 (round-off of the basis values). */
const ZERO_TOLERANCE = 1e-12;
/** Terms of a row written out in the formula panel before "+ …". */
const FORMULA_TERMS = 4;
/** Half the side of a ghosted control point's square, CSS px. */
const GHOST_HALF_PX = 3;
/** Control point labels are left out above this many (the table lists them). */
const GHOST_LABELS_MAX = 12;
/** The key's band at the top of the figure (three rows), CSS px. */
const LEGEND_PX = 70;

/**
 * The Croatian notes' example with integer coordinates: p = (0,0) (3,4) (7,5) (11,3) (14,4),
 * D₀ = (2, 6). By hand from the rows: r₀ = p₀ = (0, 0); −2r₀ + 2r₁ = D₀ gives r₁ = p₀ + D₀/2
 * = (1, 3); then r₂ = 2p₁ − r₁ = (5, 5), r₃ = 2p₂ − r₂ = (9, 5), r₄ = 2p₃ − r₃ = (13, 1), r₅ = p₄.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [3, 4],
      [7, 5],
      [11, 3],
      [14, 4],
    ].map(Object.freeze),
  ),
  degree: 2,
  params: "uniform",
  useStartDerivative: true,
  startDerivative: Object.freeze([2, 6]),
  useEndDerivative: false,
  endDerivative: Object.freeze([4, 2]),
  notesKnots: true,
});

/** The number of end derivatives given (0, 1 or 2). */
const derivativeCount = (s) => Number(s.useStartDerivative) + Number(s.useEndDerivative);
/** The highest degree the state carries: p + 1 ≤ the number of conditions (points + derivatives). */
export const largestDegree = (s) => Math.min(MAX_DEGREE, s.points.length + derivativeCount(s) - 1);

/**
 * True when the state has the set-up of the notes' example (5 points at t = 0 … 4, p = 2, a start
 * derivative only), for which their knots 0 0 0 1 2 3 4 4 4 are defined.
 */
export const notesSetUp = (s) =>
  s.points.length === NOTES_KNOTS.length - 4 &&
  s.degree === 2 &&
  s.params === "uniform" &&
  s.useStartDerivative &&
  !s.useEndDerivative;
/** The notes' knots are passed explicitly (else none: the core's default rule). */
export const usesNotesKnots = (s) => s.notesKnots && notesSetUp(s);

const sameNumbers = (a, b) => a.length === b.length && a.every((v, i) => v === b[i]);

/** True when the state is the notes' example exactly (every field as in `defaultState`). */
export function isNotesExample(s) {
  const d = defaultState;
  return (
    s.points.length === d.points.length &&
    s.points.every((q, i) => sameNumbers(q, d.points[i])) &&
    Object.keys(d).every((key) => key === "points" || String(s[key]) === String(d[key]))
  );
}

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  degree: field.number({ min: MIN_DEGREE, max: MAX_DEGREE, integer: true }),
  params: field.choice(PARAMS),
  useStartDerivative: field.boolean(),
  startDerivative: field.numbers({ min: 2, max: 2 }),
  useEndDerivative: field.boolean(),
  endDerivative: field.numbers({ min: 2, max: 2 }),
  notesKnots: field.boolean(),
};

/** The degree against the number of conditions (the field checks see one field each). */
export function check(s) {
  const max = largestDegree(s);
  if (s.degree > max)
    throw new Error(t("bsplineInterpolation.error.degree", { p: s.degree, count: max + 1, max }));
}

/** After a derivative is switched off or a point removed, the degree comes down with them. */
export function adjust(s) {
  s.degree = Math.max(MIN_DEGREE, Math.min(s.degree, largestDegree(s)));
}

/** The options of `interpolateBSpline` / `bsplineInterpolationSystem` for the state. */
function optionsOf(s) {
  const options = {};
  if (s.useStartDerivative) options.startDerivative = Float64Array.from(s.startDerivative);
  if (s.useEndDerivative) options.endDerivative = Float64Array.from(s.endDerivative);
  if (usesNotesKnots(s)) options.knots = Float64Array.from(NOTES_KNOTS);
  return options;
}

/**
 * The interpolating curve and the system it solved, both from the core (the system object holds
 * no wasm memory). Throws the core's refusal (e.g. chord parameters of two equal points).
 */
export const derive = {
  from: Object.keys(fields),
  build(s, sl) {
    const flat = flatten(s.points);
    const params = sl.parameterize(flat, 2, s.params);
    const options = optionsOf(s);
    const curve = sl.interpolateBSpline(flat, 2, s.degree, params, options);
    try {
      const system = sl.bsplineInterpolationSystem(flat, 2, s.degree, params, options);
      return { curve, params, system, notes: Boolean(options.knots) };
    } catch (err) {
      curve.free();
      throw err;
    }
  },
};

/** The control points r_j as [x, y] pairs (drawn ghosted, listed in the table). */
function controlPointsOf(curve) {
  const flat = curve.controlPoints();
  const points = [];
  for (let j = 0; j < flat.length; j += 2) points.push([flat[j], flat[j + 1]]);
  return points;
}

const ALL = Object.keys(fields);
export const compute = {
  samples: [ALL, (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  knots: [ALL, (s, d) => d.curve.knots()],
  control: [ALL, (s, d) => controlPointsOf(d.curve)],
  sites: [ALL, (s, d) => sitesOf(d.system.rows, s.points.length - 1)],
};

const numberText = exactText;
/** TeX of a number: a fraction as \tfrac, else as the table writes it. */
const numberTex = exactTex;
const pairText = (x, y) => pointText([numberText(x), numberText(y)]);
const pairTex = (x, y) => pointTex([numberTex(x), numberTex(y)]);

/** Row i's data index: the k-th point row is p_k at t_k; derivative rows sit at t₀ and tₙ. */
function sitesOf(rows, n) {
  let k = 0;
  return rows.map((kind) =>
    kind === "start-derivative" ? 0 : kind === "end-derivative" ? n : k++,
  );
}

/** "C(1) = p₁", "C′(0) = D₀", "C′(4) = D₄": row i's condition. */
function conditionText(i, d) {
  const k = d.sites[i];
  const key =
    { point: "row.point", "start-derivative": "row.start" }[d.system.rows[i]] ?? "row.end";
  return t(`bsplineInterpolation.${key}`, { t: numberText(d.params[k]), i: subscript(k) });
}

export const controls = [
  group(
    "bsplineInterpolation.degreeLegend",
    degreeButtons({
      prefix: strings,
      min: MIN_DEGREE,
      max: MAX_DEGREE,
      limit: largestDegree,
      apply: (ui, p) => ui.set("degree", p),
    }),
  ),
  group(
    "bsplineInterpolation.paramsLegend",
    choice("params", {
      options: PARAMS.map((value) => ({ value, label: `bsplineInterpolation.params.${value}` })),
    }),
    readout("params", (s, d) =>
      t("bsplineInterpolation.paramsNote", { list: listText(Array.from(d.params, numberText)) }),
    ),
  ),
  group(
    "bsplineInterpolation.derivativesLegend",
    checkbox("useStartDerivative", { label: "bsplineInterpolation.control.start" }),
    checkbox("useEndDerivative", { label: "bsplineInterpolation.control.end" }),
    readout("derivatives", (s) => derivativesNote(s)),
  ),
  group(
    null,
    shownWhen(
      notesSetUp,
      checkbox("notesKnots", { label: "bsplineInterpolation.control.notesKnots" }),
    ),
    knotVectorReadout(
      "knots",
      (s, d) =>
        t(d.notes ? "bsplineInterpolation.knotsNotes" : "bsplineInterpolation.knotsDefault", {
          list: knotListText(d.knots),
        }),
      (s, d) => d.knots,
    ),
    readout("size", (s, d) =>
      t("bsplineInterpolation.sizeNote", {
        points: tp("bsplineInterpolation.dataPoints", s.points.length),
        unknowns: tp("bsplineInterpolation.controlPoints", d.system.size),
      }),
    ),
  ),
  group(
    null,
    pointButtons("points", {
      min: (s) => Math.max(MIN_POINTS, s.degree + 1 - derivativeCount(s)),
      max: MAX_POINTS,
      prefix: strings,
      params: (s) => ({ p: s.degree }),
    }),
    actions([
      {
        name: "notes-example",
        label: "bsplineInterpolation.notesExample",
        title: "bsplineInterpolation.notesExample.title",
        run: (ui) => ui.replace(structuredClone(defaultState)),
        disabled: (s) => isNotesExample(s),
      },
    ]),
  ),
];

/** "D₀ = (2, 6)" and/or "Dₙ = …", or that none is given. */
function derivativesNote(s) {
  const parts = [];
  const n = s.points.length - 1;
  if (s.useStartDerivative) {
    const [x, y] = s.startDerivative;
    parts.push(t("bsplineInterpolation.startValue", { xy: pairText(x, y) }));
  }
  if (s.useEndDerivative) {
    const [x, y] = s.endDerivative;
    parts.push(t("bsplineInterpolation.endValue", { n: subscript(n), xy: pairText(x, y) }));
  }
  return parts.length ? parts.join(clauseSeparator()) : t("bsplineInterpolation.noDerivatives");
}

/** The anchors of the two derivative arrows: p₀ and pₙ. */
const first = (s) => s.points[0];
const last = (s) => s.points[s.points.length - 1];
const tipScratch = new Float64Array(2);

/** Labels p₀, p₁, … of the data points (cached). */
const DATA_LABELS = [];
const dataLabel = (i) => (DATA_LABELS[i] ??= `p${subscript(i)}`);
/** The end points are also control points (clamped knots): "p₀ = r₀", "p₄ = r₅" (cached). */
const END_LABELS = new Map();
function handleLabel(i, s) {
  const n = s.points.length - 1;
  if (i !== 0 && i !== n) return dataLabel(i);
  const j = i === 0 ? 0 : n + derivativeCount(s);
  const key = `${i},${j}`;
  if (!END_LABELS.has(key)) END_LABELS.set(key, `${dataLabel(i)} = ${controlLabel(j)}`);
  return END_LABELS.get(key);
}
/** Labels r₀, r₁, … of the control points (cached). */
const CONTROL_LABELS = [];
const controlLabel = (j) => (CONTROL_LABELS[j] ??= `r${subscript(j)}`);

export const figure = {
  /** The data points and the tips of the derivative arrows shown (control points may roam). */
  bounds(s) {
    const points = s.points.slice();
    if (s.useStartDerivative)
      points.push(Array.from(tipOf(first(s), s.startDerivative, tipScratch)));
    if (s.useEndDerivative) points.push(Array.from(tipOf(last(s), s.endDerivative, tipScratch)));
    return paddedBounds(points, 0.08, 0.15);
  },
  insets: scaledInsets(LEGEND_PX, 0, 0, 0),
  handles: {
    field: "points",
    label: handleLabel,
    extra: [
      vectorTip({
        field: "startDerivative",
        label: "bsplineInterpolation.startLabel",
        when: (s) => s.useStartDerivative,
        anchor: first,
      }),
      vectorTip({
        field: "endDerivative",
        label: "bsplineInterpolation.endLabel",
        when: (s) => s.useEndDerivative,
        anchor: last,
      }),
    ],
  },
};

/** This demo's own marks: the derivative arrows and the ghosted control points. */
const ARROW_STYLE = Object.freeze({
  stroke: HUES.vermillion,
  width: WIDTH.curve,
  cap: "round",
  join: "round",
});
const stylesFor = themed((theme) => ({ ghost: { fill: theme.polygon.stroke } }));

/** The key: the interpolant, the computed control polygon, the derivative arrows. */
const KEY = Object.freeze([
  { label: "bsplineInterpolation.legendCurve", style: (theme) => theme.curve },
  { label: "bsplineInterpolation.legendPolygon", style: (theme) => theme.polygon },
  { label: "bsplineInterpolation.legendDerivative", style: ARROW_STYLE },
]);

/**
 * The ghosted control polygon and points r_j (grey squares: not handles), the curve, the
 * derivative arrows p → p + D, then the data points' handles (and the arrows' tips) on top.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  const control = d.control;
  r.beginPath();
  for (let j = 0; j < control.length; j++) {
    const x = v.sx(control[j][0]);
    const y = v.sy(control[j][1]);
    if (j === 0) r.moveTo(x, y);
    else r.lineTo(x, y);
  }
  r.paint(theme.polygon);
  const half = GHOST_HALF_PX * r.scale;
  r.beginPath();
  for (const [x, y] of control) r.rect(v.sx(x) - half, v.sy(y) - half, 2 * half, 2 * half);
  r.paint(styles.ghost);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  if (s.useStartDerivative) vectorArrow(r, v, first(s), s.startDerivative, ARROW_STYLE);
  if (s.useEndDerivative) vectorArrow(r, v, last(s), s.endDerivative, ARROW_STYLE);
  // Control point labels away from the polygon's centroid; none on a phone (the table has them).
  if (v.width >= NARROW_CANVAS_PX * r.scale && control.length <= GHOST_LABELS_MAX) {
    let cx = 0;
    let cy = 0;
    for (const [x, y] of control) {
      cx += v.sx(x) / control.length;
      cy += v.sy(y) / control.length;
    }
    // The first and last are the end points, named on their handles ("p₀ = r₀").
    for (let j = 1; j < control.length - 1; j++) {
      const x = v.sx(control[j][0]);
      const y = v.sy(control[j][1]);
      placeLabelFrom(r, controlLabel(j), x, y, cx, cy, theme.labelSmall, half + RADIUS.handle);
    }
  }
  d.handles.draw(r, v);
  drawCornerLegend(r, KEY);
}

/** Σ-form of one row of A: "−2 r₀ + 2 r₁" (the non-zero entries, the first few). */
function rowTex(matrix, size, i) {
  const terms = [];
  let more = false;
  for (let j = 0; j < size; j++) {
    const a = matrix[i * size + j];
    if (Math.abs(a) < ZERO_TOLERANCE) continue;
    if (terms.length === FORMULA_TERMS) {
      more = true;
      break;
    }
    const sign = a < 0 ? "-" : terms.length ? "+" : "";
    const magnitude = Math.abs(Math.abs(a) - 1) < ZERO_TOLERANCE ? "" : numberTex(Math.abs(a));
    terms.push(`${sign} ${magnitude}\\,r_{${j}}`);
  }
  return terms.join(" ") + (more ? " + \\dots" : "");
}

/** The curve, its conditions, and two rows of the system with the current numbers (a line each). */
export function formula(s, d) {
  const p = s.degree;
  const n = s.points.length - 1;
  const { size, matrix, rhs, rows } = d.system;
  const [a, b] = d.curve.domain();
  const lines = [
    `C(u) = \\sum_{j=0}^{${size - 1}} N_{j,${p}}(u)\\, r_j,\\quad u \\in [${listTex([numberTex(a), numberTex(b)], DECIMALS, " ")}]`,
  ];
  const conditions = [`C(t_i) = p_i\\ (i = 0,\\dots,${n})`];
  if (s.useStartDerivative) conditions.push("C'(t_0) = D_0");
  if (s.useEndDerivative) conditions.push(`C'(t_{${n}}) = D_{${n}}`);
  lines.push(conditions.join(",\\quad "));
  // A derivative row when there is one, and the row of p₁, with their numbers.
  const derivative = rows.findIndex((kind) => kind !== "point");
  const shown = [derivative, rows.indexOf("point", 1)].filter((i) => i >= 0);
  const parts = shown.map((i) => {
    const u = numberTex(d.params[d.sites[i]]);
    const head = rows[i] === "point" ? `C(${u})` : `C'(${u})`;
    return `${head} = ${rowTex(matrix, size, i)} = ${pairTex(rhs[2 * i], rhs[2 * i + 1])}`;
  });
  lines.push(...parts);
  return lines;
}

/** "quadratic B-spline through 5 data points with a start derivative: 6 control points; knots …". */
export function label(s, d) {
  const ends = [];
  if (s.useStartDerivative) ends.push(t("bsplineInterpolation.aria.start"));
  if (s.useEndDerivative) ends.push(t("bsplineInterpolation.aria.end"));
  return t("bsplineInterpolation.aria", {
    kind: degreeName(s.degree),
    count: s.points.length,
    params: t(`bsplineInterpolation.params.${s.params}`),
    ends: ends.length ? ends.join(", ") : t("bsplineInterpolation.aria.noEnds"),
    size: d.system.size,
    knots: knotListText(d.knots, " "),
  });
}

/** The solved system as a table (lib/system-table.js): each row named by its condition. */
export function setup(ui) {
  const table = new SystemTable("interpolation-system", {
    headers: {
      label: t("bsplineInterpolation.col.condition"),
      unknown: t("bsplineInterpolation.col.unknown"),
      rhs: t("bsplineInterpolation.col.rhs"),
      solution: t("bsplineInterpolation.col.solution"),
    },
  });
  ui.ctx.slots.details.append(...table.nodes);
  return {
    update(s, d) {
      const { size, matrix, rhs, solution, rows } = d.system;
      const key = d.notes ? "tableCaptionNotes" : "tableCaption";
      table.show({
        size,
        maxSize: TABLE_MAX_UNKNOWNS,
        tooLarge: t("bsplineInterpolation.tableTooLarge", { size, max: TABLE_MAX_UNKNOWNS }),
        caption: t(`bsplineInterpolation.${key}`, { size }),
        number: exactText,
        entry: (i, j) => matrix[i * size + j],
        unknown: controlLabel,
        rhs: (i) => rowPoint(rhs, i, 2),
        solution: (i) => `${controlLabel(i)} = ${rowPoint(solution, i, 2)}`,
        label: (i) => conditionText(i, d),
        kind: (i) => rows[i],
      });
    },
  };
}
