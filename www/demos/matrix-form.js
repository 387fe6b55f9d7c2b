/**
 * Demo (syllabus §3): the matrix form of B-spline segments, after the Croatian notes (002).
 * A uniform (or, for comparison, clamped) B-spline of degree 2 or 3; the selected segment i
 * with its p + 1 active points is highlighted, and the formula panel writes the segment as
 *   C_i(t) = [t^p … t 1] M [P_{i−1} … P_{i+p−1}]^T,  u = u_k + t (u_{k+1} − u_k),  k = i + p − 1,
 * with M from the core (`segmentMatrix(k, true)`, compared with `uniformSegmentMatrix(p)`), the
 * current coordinates filled in. The point at t is shown twice: as the matrix product of those
 * displayed numbers (the core's `evaluateMatrixForm(k, t)`: the monomials, [t^p … 1] M and the
 * product) and as `evaluate(u)`, so students see they agree. The curve is drawn from the core.
 */
import { field, checkNumber } from "../lib/validate.js";
import { slider, choice, pointButtons, readout, group, INTEGER_SLIDER } from "../lib/panel.js";
import { placeLabel } from "../lib/handles.js";
import { CurvePicker } from "../lib/curve-picker.js";
import {
  fmt,
  subscript,
  simpleFraction,
  fractionText,
  fractionTex,
  degreeName,
  fmtTex,
  pointText,
  pointTex,
} from "../lib/format.js";
import { CYCLE } from "../lib/theme.js";
import { t, tp } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { el, setText } from "../lib/controls.js";

export const id = "matrix-form";
export const strings = "matrixForm";
export const section = 3;

/** Six integer points, a uniform quadratic (the Croatian notes' example size), segment 2 at t = 1/2. */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [2, 5],
      [6, 6],
      [8, 1],
      [12, 0],
      [14, 5],
    ].map(Object.freeze),
  ),
  degree: 2,
  knots: "uniform",
  segment: 2,
  t: 0.5,
});

/** Fewest and most control points. */
export const MIN_POINTS = 3;
export const MAX_POINTS = 11;
/** Degrees with a matrix form in the notes. */
export const DEGREES = Object.freeze([2, 3]);
/** Knot vectors offered: uniform (unclamped) as in the notes' periodic segments, or clamped. */
export const KNOT_KINDS = Object.freeze(["uniform", "clamped"]);
/** Points sampled along the whole curve and along the selected segment. */
const CURVE_SAMPLES = 256;
const SEGMENT_SAMPLES = 64;
/** Slider resolution for t. */
const T_STEP = 0.001;
/** A press this close to the curve (CSS px) selects the segment under it. */
const CURVE_HIT_PX = 8;
/** Matrix entries equal within this count as the same (floating-point round-off). */
const MATRIX_TOLERANCE = 1e-9;
/** Largest common denominator factored out of a cubic matrix (1/6, 1/12, …). */
const MAX_FACTOR = 720;

/** Number of segments n − p + 1 (one per span; no repeated interior knots here). */
const segmentCount = (s) => s.points.length - s.degree;
const degreeError = (p, count) => t("matrixForm.error.degree", { p, count });

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  degree(s, name) {
    checkNumber(s, name, { min: 2, max: 3, integer: true });
    if (s.degree > s.points.length - 1) throw new Error(degreeError(s.degree, s.points.length));
  },
  knots: field.choice(KNOT_KINDS),
  segment: field.number((s) => ({ min: 1, max: segmentCount(s), integer: true })),
  t: field.number({ min: 0, max: 1 }),
};

/** After a new degree or point count the segment stays in range. */
export function adjust(s) {
  s.segment = Math.min(s.segment, segmentCount(s));
}

/** The B-spline, knots from the core's `knotVector` ("uniform" or "clamped"); drags move it in place. */
export const derive = {
  from: ["points", "degree", "knots"],
  build(s, sl) {
    const flat = flatten(s.points);
    return {
      curve: new sl.BSplineCurve(flat, 2, s.degree, sl.knotVector(flat, 2, s.degree, s.knots)),
    };
  },
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/**
 * Segment i: span k = i + p − 1 (it uses P_{i−1} … P_{i+p−1}), its samples (one `sample(us)`),
 * its matrix and whether that is the periodic one.
 */
function segmentOf(s, d) {
  const p = s.degree;
  const k = s.segment + p - 1;
  const [u0, u1] = [d.knots[k], d.knots[k + 1]];
  const us = new Float64Array(SEGMENT_SAMPLES);
  for (let j = 0; j < SEGMENT_SAMPLES; j++) us[j] = u0 + ((u1 - u0) * j) / (SEGMENT_SAMPLES - 1);
  const matrix = d.curve.segmentMatrix(k, true);
  const periodic = d.sl.uniformSegmentMatrix(p);
  const same = matrix.every((m, e) => Math.abs(m - periodic[e]) <= MATRIX_TOLERANCE);
  return { k, u0, u1, first: s.segment - 1, samples: d.curve.sample(us), matrix, same };
}

/** At t: u, the core's point and tangent there, and its matrix-form evaluation. */
function atT(s, d) {
  const { k, u0, u1 } = d.segment;
  const u = u0 + s.t * (u1 - u0);
  const size = s.degree + 1;
  const form = d.curve.evaluateMatrixForm(k, s.t);
  return {
    u,
    point: d.curve.evaluate(u),
    tangent: d.curve.derivative(u, 1),
    powers: Array.from(form.subarray(0, size)),
    weights: Array.from(form.subarray(size, 2 * size)),
    product: form.subarray(2 * size, 2 * size + 2),
  };
}

const SHAPE = ["points", "degree", "knots"];
export const compute = {
  knots: [SHAPE, (s, d) => d.curve.knots()],
  samples: [SHAPE, (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  segment: [[...SHAPE, "segment"], segmentOf],
  at: [[...SHAPE, "segment", "t"], atT],
  pointLabel: [["segment"], (s) => t("matrixForm.pointLabel", { i: subscript(s.segment) })],
};

/** A number as text / TeX: integers plain, fractions with small denominators, else 3 decimals. */
function numberText(x, tex = false) {
  if (Math.abs(x - Math.round(x)) < MATRIX_TOLERANCE) return String(Math.round(x) || 0);
  const f = simpleFraction(x);
  if (f) return tex ? fractionTex(f) : fractionText(f);
  return tex ? fmtTex(x) : fmt(x);
}
const numberTex = (x) => numberText(x, true);

export const controls = [
  group(
    "matrixForm.control.degree",
    choice("degree", {
      options: DEGREES.map((p) => ({ value: p, label: `matrixForm.degree.${p}` })),
      refuse: (p, s) => (p > s.points.length - 1 ? degreeError(p, s.points.length) : null),
    }),
  ),
  group(
    "matrixForm.control.knots",
    choice("knots", {
      options: KNOT_KINDS.map((value) => ({ value, label: `matrixForm.knots.${value}` })),
    }),
  ),
  group(
    null,
    slider("segment", {
      label: "matrixForm.control.segment",
      range: (s) => [1, segmentCount(s)],
      ...INTEGER_SLIDER,
      error: (value, s) => t("matrixForm.segmentRange", { value, max: segmentCount(s) }),
    }),
    slider("t", {
      label: "matrixForm.control.t",
      input: "control.t.input",
      min: 0,
      max: 1,
      step: T_STEP,
    }),
    readout(
      "periodic",
      (s, d) => {
        return t(d.segment.same ? "matrixForm.periodic.yes" : "matrixForm.periodic.no", {
          i: s.segment,
        });
      },
      {
        kind: "readout",
        live: true,
        data: (s, d) => ({ periodic: String(d.segment.same) }),
      },
    ),
  ),
  group(
    null,
    readout("degree", (s, d) =>
      t("matrixForm.degree", {
        p: s.degree,
        count: s.points.length,
        segments: tp("matrixForm.segments", segmentCount(s)),
        knots: Array.from(d.knots, (u) => numberText(u)).join(" "),
      }),
    ),
    pointButtons("points", {
      min: (s) => Math.max(MIN_POINTS, s.degree + 1),
      max: MAX_POINTS,
      prefix: strings,
      params: (s) => ({ p: s.degree }),
    }),
  ),
];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  handles: { field: "points" },
};

/**
 * The polygon with its active part solid, the segment as a band under the curve, rings in the
 * colours of the formula's columns, the handles and C_i(t) labelled across the curve on the side
 * of the active points (inside the bend, where the polygon and its handles are not).
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const p = s.degree;
  const { first } = d.segment;
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  pointsPath(r, v, s.points, first, first + p + 1);
  r.paint(theme.axis);
  flatPath(r, v, d.segment.samples, 0, SEGMENT_SAMPLES);
  r.paint(theme.highlightBand);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  for (let j = 0; j <= p; j++) {
    const q = s.points[first + j];
    r.point(v.sx(q[0]), v.sy(q[1]), theme.basisRing[j % theme.basisRing.length]);
  }
  d.handles.draw(r, v);

  const px = v.sx(d.at.point[0]);
  const py = v.sy(d.at.point[1]);
  let cx = 0;
  let cy = 0;
  for (let j = 0; j <= p; j++) {
    cx += v.sx(s.points[first + j][0]);
    cy += v.sy(s.points[first + j][1]);
  }
  // The normal on screen (y down): (−t_y, t_x) of (t_x, −t_y).
  const length = Math.hypot(d.at.tangent[1], d.at.tangent[0]);
  let dx = length < 1e-12 ? Math.SQRT1_2 : d.at.tangent[1] / length;
  let dy = length < 1e-12 ? -Math.SQRT1_2 : d.at.tangent[0] / length;
  if ((cx / (p + 1) - px) * dx + (cy / (p + 1) - py) * dy < 0) {
    dx = -dx;
    dy = -dy;
  }
  r.point(px, py, theme.pointOnCurve);
  placeLabel(
    r,
    d.pointLabel,
    px,
    py,
    dx,
    dy,
    theme.pointOnCurve.radius * r.scale,
    theme.labelPoint,
  );
}

/**
 * The smallest D ≤ MAX_FACTOR with D·m integral for every entry (to write a cubic matrix as
 * (1/D)·integers, as the notes do), or 0 when there is none.
 */
function commonDenominator(matrix) {
  for (let den = 1; den <= MAX_FACTOR; den++) {
    if (matrix.every((m) => Math.abs(m * den - Math.round(m * den)) < MATRIX_TOLERANCE * den))
      return den;
  }
  return 0;
}

/** M as shown: a cubic with a common denominator D is written (1/D)·integers, as in the notes. */
function shownMatrix(s, d) {
  const entries = Array.from(d.segment.matrix);
  const factor = s.degree >= 3 ? commonDenominator(entries) : 1;
  return { factor, entries: factor > 1 ? entries.map((m) => m * factor) : entries };
}

/** The segment in matrix form, M against the periodic matrix, the product with numbers, evaluate(u). */
export function formula(s, d) {
  const p = s.degree;
  const size = p + 1;
  const i = s.segment;
  const { k, first, same } = d.segment;
  const { u, point, powers, weights, product } = d.at;
  const { factor, entries } = shownMatrix(s, d);
  const rowsTex = [];
  for (let row = 0; row < size; row++) {
    rowsTex.push(
      entries
        .slice(row * size, (row + 1) * size)
        .map(numberTex)
        .join(" & "),
    );
  }
  const matrix = (rows) => `\\begin{bmatrix} ${rows} \\end{bmatrix}`;
  const mTex = `${factor > 1 ? `\\frac{1}{${factor}}` : ""}${matrix(rowsTex.join(" \\\\ "))}`;
  const colour = (j, tex) => `\\textcolor{${CYCLE[j % CYCLE.length]}}{${tex}}`;
  const names = [];
  const coords = [];
  for (let j = 0; j < size; j++) {
    const [x, y] = s.points[first + j];
    names.push(colour(j, `P_{${first + j}}`));
    coords.push(`${colour(j, numberTex(x))} & ${colour(j, numberTex(y))}`);
  }
  const tPowers = ["t^3", "t^2", "t", "1"].slice(3 - p);
  const tTex = simpleFraction(s.t) ? fractionTex(simpleFraction(s.t)) : fmtTex(s.t);
  const periodic = t(same ? "matrixForm.tex.periodic" : "matrixForm.tex.notPeriodic");
  const sum = weights.map((w, j) => `${numberTex(w)}\\,${names[j]}`).join(" + ");
  return [
    `C_{${i}}(t) = ${matrix(tPowers.join(" & "))} M ${matrix(names.join(" \\\\ "))},` +
      `\\quad u = u_{${k}} + t\\,(u_{${k + 1}} - u_{${k}}),\\ t \\in [0, 1]`,
    `M = ${mTex}\\quad ${same ? "" : "\\ne"}\\ \\text{${periodic}}`,
    `C_{${i}}(${tTex}) = ${matrix(powers.map(numberTex).join(" & "))} ${mTex} ${matrix(coords.join(" \\\\ "))}`,
    `\\phantom{C_{${i}}(${tTex})} = ${sum} = ${pointTex([product[0], product[1]])}`,
    `\\text{${t("matrixForm.tex.evaluate")}}\\ C(u = ${fmtTex(u)}) = ${pointTex([point[0], point[1]])}`,
  ];
}

/** "quadratic B-spline, uniform knots (unclamped), 6 control points; segment 2 at t = 0.500: …". */
export function label(s, d) {
  const [x, y] = d.at.point;
  return t("matrixForm.aria", {
    kind: degreeName(s.degree),
    knots: t(`matrixForm.knots.${s.knots}`),
    count: s.points.length,
    i: s.segment,
    t: fmt(s.t),
    x: fmt(x, 2),
    y: fmt(y, 2),
    periodic: d.segment.same ? t("matrixForm.aria.periodic") : t("matrixForm.aria.notPeriodic"),
  });
}

/**
 * The tables (M with exact entries and its factor; the two points side by side) and the pointer
 * tool: a press on the curve picks its segment and t (the core's span of the sample's u).
 */
export function setup(ui) {
  const { title, table, wrap } = titledTable("matrix");
  const productCell = el("td", { dataset: { result: "product" } });
  const evaluateCell = el("td", { dataset: { result: "evaluate" } });
  const result = titledTable("result", {
    caption: t("matrixForm.resultCaption"),
    children: [
      el(
        "tbody",
        {},
        el("tr", {}, el("th", { scope: "row", text: t("matrixForm.result.product") }), productCell),
        el(
          "tr",
          {},
          el("th", { scope: "row", text: t("matrixForm.result.evaluate") }),
          evaluateCell,
        ),
      ),
    ],
  });
  ui.ctx.slots.details.append(title, wrap, result.title, result.wrap);

  new CurvePicker(ui.view, {
    samples: () => ui.data.samples,
    count: CURVE_SAMPLES,
    radius: CURVE_HIT_PX,
    press(j) {
      const { curve, knots } = ui.data;
      const [a, b] = curve.domain();
      const u = a + ((b - a) * j) / (CURVE_SAMPLES - 1);
      const k = curve.span(u);
      const local = Math.round((u - knots[k]) / (knots[k + 1] - knots[k]) / T_STEP) * T_STEP;
      ui.set("segment", k - ui.state.degree + 1, false);
      ui.set("t", Math.min(1, Math.max(0, local)));
    },
  });

  let size = -1;
  let cells = []; // td per entry, row-major
  let heads = []; // column heads: the points P_{i−1} … P_{i+p−1}
  let factorCell = null;

  function build(n) {
    size = n;
    cells = [];
    heads = [];
    factorCell = el("td", { rowspan: String(n), dataset: { cell: "factor" } });
    // The corner above the factor and the row names heads nothing: plain cells, not headers.
    const header = [el("td"), el("td")];
    for (let j = 0; j < n; j++) heads.push(el("th", { scope: "col", dataset: { col: String(j) } }));
    const rows = [];
    for (let row = 0; row < n; row++) {
      const line = row === 0 ? [factorCell] : [];
      line.push(el("th", { scope: "row", text: ["t³", "t²", "t", "1"][4 - n + row] }));
      for (let j = 0; j < n; j++) {
        const cell = el("td", { dataset: { row: String(row), col: String(j) } });
        cells.push(cell);
        line.push(cell);
      }
      rows.push(el("tr", {}, line));
    }
    table.replaceChildren(el("thead", {}, el("tr", {}, header, heads)), el("tbody", {}, rows));
  }

  return {
    update(s, d) {
      const n = s.degree + 1;
      if (size !== n) build(n);
      const { factor, entries } = shownMatrix(s, d);
      setText(title, t("matrixForm.matrixCaption", { i: s.segment, k: d.segment.k, p: s.degree }));
      setText(factorCell, factor > 1 ? `1/${factor} ×` : "");
      factorCell.dataset.factor = factor > 1 ? `1/${factor}` : "1";
      entries.forEach((m, e) => setText(cells[e], numberText(m)));
      heads.forEach((cell, j) => setText(cell, `P${subscript(d.segment.first + j)}`));
      const { product, point } = d.at;
      setText(productCell, pointText([product[0], product[1]]));
      setText(evaluateCell, pointText([point[0], point[1]]));
    },
  };
}
