/**
 * Demo (syllabus §6): de Casteljau's algorithm on a tensor-product Bézier patch, as the Greek
 * notes give it: to compute S(u, v), run de Casteljau on every row of the net in v; the m + 1
 * results are the control points of the iso-curve at that v (a Bézier curve in u); run de
 * Casteljau once more on them in u, and the apex is S(u, v). Columns first (each column in u,
 * then the row of results in v) reaches the same point. Everything drawn is what the core
 * returns: `BezierSurface.deCasteljau(u, v, order)` (each row's triangle, then the column's),
 * the iso-curve by `sampleGrid`, the point by `evaluate`. A "step" control reveals the
 * construction level by level.
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, choice, readout, group, INTEGER_SLIDER } from "../lib/panel.js";
import { fmt, subscript, fmtTex, pointTex, texDecimal } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { boundsOf3 } from "../lib/camera3d.js";
import { netPath } from "../lib/draw3d.js";
import { placeLabelFrom } from "../lib/handles.js";
import { netCorner } from "../lib/handle-lists3d.js";
import { replaceOrReport } from "../lib/wasm.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";
import { HUES, WIDTH, RADIUS, themed } from "../lib/theme.js";
import {
  apexOf,
  drawTriangle3,
  indexedPath3,
  pointsUpToLevel,
  trianglePoints,
} from "../lib/patch-levels.js";

export const id = "patch-de-casteljau";
export const strings = "patchDeCasteljau";
export const section = 6;

/** Degrees offered (a square (d + 1) × (d + 1) net; labels and levels stay readable up to 4). */
export const DEGREES = Object.freeze([1, 2, 3, 4]);
/** Side of the square the net stands on (P_ij = (SIDE·i/d, SIDE·j/d, h_ij)). */
const SIDE = 6;
/** Mesh resolution (quads per direction) and samples along the iso-curve. */
const MESH = 32;
const CURVE_SAMPLES = 64;

/** Heights h_ij of a wavy default net per degree (the bicubic one is bezier-patch's). */
const HEIGHTS = {
  1: [
    [0, 1.6],
    [1.4, 0],
  ],
  2: [
    [0, 1.2, 0.2],
    [1.2, 3, 0.6],
    [0.4, 0.8, 0],
  ],
  3: [
    [0, 1, 1.2, 0],
    [1, 3, 0.6, 0.8],
    [0.6, -0.4, 2.6, 1.2],
    [0, 1.2, 0.6, 0.2],
  ],
  4: [
    [0, 0.8, 1.2, 0.8, 0],
    [0.8, 2.4, 1, 1.4, 0.6],
    [0.6, -0.2, 2.6, 1.6, 1],
    [0.4, 1.6, 0.4, 2.2, 0.6],
    [0, 0.8, 0.6, 0.4, 0.2],
  ],
};

/** The default net of degree d × d, row-major, rows along u. */
export function netOf(d) {
  return HEIGHTS[d].flatMap((row, i) => row.map((h, j) => [(SIDE * i) / d, (SIDE * j) / d, h]));
}

/** The first camera: from high on the side of u = 1, so the rows (in v) run across the screen. */
const CAMERA = Object.freeze({ azimuth: -25, elevation: 48 });

export const defaultState = Object.freeze({
  degree: 3,
  points: netOf(3),
  u: 0.35,
  v: 0.6,
  order: "rows",
  step: 6,
  surface: true,
  net: true,
});

const ORDERS = ["rows", "columns"];

export const fields = {
  degree: field.number({ min: DEGREES[0], max: DEGREES.at(-1), integer: true }),
  points: field.points3d((s) => ({ rows: s.degree + 1, cols: s.degree + 1 })),
  u: field.number({ min: 0, max: 1 }),
  v: field.number({ min: 0, max: 1 }),
  order: field.choice(ORDERS),
  step: field.number({ min: 0, max: (s) => 2 * s.degree, integer: true }),
  surface: field.boolean(),
  net: field.boolean(),
};

/** Net side (points per row and per column). */
const sideOf = (s) => s.degree + 1;

export const derive = {
  from: ["points"],
  build: (s, sl) => ({
    patch: new sl.BezierSurface(Float64Array.from(s.points.flat()), sideOf(s), sideOf(s)),
  }),
  moved: (m, k, xyz) => {
    const side = m.patch.cols;
    m.patch.setControlPoint(Math.floor(k / side), k % side, xyz);
  },
};

const SAMPLES = Float64Array.from({ length: CURVE_SAMPLES }, (_, k) => k / (CURVE_SAMPLES - 1));

/**
 * What is shown at the current step, for order "rows" (the other order swaps the roles):
 * levels 1 … `first` of each of the `count` first triangles (degree `firstDegree`); the
 * intermediate results once `first` reaches that degree; levels 1 … `second` of the second
 * triangle (degree `secondDegree`). `points`: the construction's points on view (level 0 too:
 * the net and the intermediate results), 4 · 10 + 10 = 50 for a bicubic patch at the last step.
 */
function stageOf(s) {
  const d = s.degree; // m = n = d
  const first = Math.min(s.step, d);
  const results = s.step >= d;
  const second = results ? s.step - d : -1;
  const points = (d + 1) * pointsUpToLevel(d, first) + (results ? pointsUpToLevel(d, second) : 0);
  return { degree: d, count: d + 1, first, results, second, points };
}

/** The core's teaching data: both orders (the formula compares them), iso-curve, point, mesh. */
export const compute = {
  mesh: [["points", "surface"], (s, d) => (s.surface ? d.patch.tessellate(MESH, MESH) : null)],
  rowsFirst: [["points", "u", "v"], (s, d) => d.patch.deCasteljau(s.u, s.v, "rows")],
  columnsFirst: [["points", "u", "v"], (s, d) => d.patch.deCasteljau(s.u, s.v, "columns")],
  // Rows first: the iso-curve at v (running in u); columns first: the one at u (running in v).
  iso: [
    ["points", "u", "v", "order"],
    (s, d) =>
      s.order === "rows" ? d.patch.sampleGrid(SAMPLES, [s.v]) : d.patch.sampleGrid([s.u], SAMPLES),
  ],
  point: [["points", "u", "v"], (s, d) => d.patch.evaluate(s.u, s.v)],
  stage: [["degree", "step"], (s) => stageOf(s)],
};

/** The two arrays of the chosen order: the first triangles (all concatenated), the second one. */
const construction = (s, d) =>
  s.order === "rows"
    ? { first: d.rowsFirst.rows, second: d.rowsFirst.column }
    : { first: d.columnsFirst.columns, second: d.columnsFirst.row };

const apexScratch = new Float64Array(3);
/** S(u, v) as the apex of an order's second triangle, "x,y,z" with every digit (for tests). */
function apexText(second, degree) {
  const a = apexOf(second, 0, degree, apexScratch);
  return `${a[0]},${a[1]},${a[2]}`;
}

/** A new degree: the default net of that degree, the construction shown whole. */
function setDegree(ui, degree) {
  replaceOrReport(ui, {
    ...structuredClone(ui.state),
    degree,
    points: netOf(degree),
    step: 2 * degree,
  });
}

/** The readout of the step: what the last level shown is. */
function stepText(s, d) {
  const st = d.stage;
  const rows = s.order === "rows";
  const params = { k: s.step, of: 2 * st.degree, u: fmt(s.u), v: fmt(s.v) };
  if (s.step === 0) return t("patchDeCasteljau.step.net", params);
  if (s.step < st.degree)
    return t(rows ? "patchDeCasteljau.step.rows" : "patchDeCasteljau.step.columns", {
      ...params,
      r: s.step,
    });
  if (s.step === st.degree)
    return t(rows ? "patchDeCasteljau.step.rowResults" : "patchDeCasteljau.step.columnResults", {
      ...params,
      count: st.count,
    });
  if (s.step < 2 * st.degree)
    return t(rows ? "patchDeCasteljau.step.column" : "patchDeCasteljau.step.row", {
      ...params,
      r: s.step - st.degree,
    });
  return t(rows ? "patchDeCasteljau.step.point" : "patchDeCasteljau.step.pointColumns", params);
}

export const controls = [
  group(
    null,
    slider("u", {
      label: "patchDeCasteljau.control.u",
      min: 0,
      max: 1,
      step: 0.001,
      player: {
        stepBackTitle: "patchDeCasteljau.control.stepBackU.title",
        stepTitle: "patchDeCasteljau.control.stepU.title",
      },
    }),
    slider("v", {
      label: "patchDeCasteljau.control.v",
      min: 0,
      max: 1,
      step: 0.001,
      player: {
        stepBackTitle: "patchDeCasteljau.control.stepBackV.title",
        stepTitle: "patchDeCasteljau.control.stepV.title",
      },
    }),
  ),
  group(
    "patchDeCasteljau.control.order",
    choice("order", {
      options: [
        { value: "rows", label: "patchDeCasteljau.control.rowsFirst" },
        { value: "columns", label: "patchDeCasteljau.control.columnsFirst" },
      ],
    }),
  ),
  group(
    null,
    slider("step", {
      ...INTEGER_SLIDER,
      label: "patchDeCasteljau.control.step",
      range: (s) => [0, 2 * s.degree],
    }),
    readout("step", stepText, {
      data: (s, d) => ({
        levelPoints: String(d.stage.points),
        rowsFirst: apexText(d.rowsFirst.column, s.degree),
        columnsFirst: apexText(d.columnsFirst.row, s.degree),
        evaluate: `${d.point[0]},${d.point[1]},${d.point[2]}`,
      }),
    }),
  ),
  group(
    "patchDeCasteljau.control.degree",
    choice("degree", {
      options: DEGREES.map((p) => ({ value: p, label: `patchDeCasteljau.degree${p}` })),
      set: setDegree,
    }),
  ),
  group(
    "patchDeCasteljau.control.show",
    checkbox("surface", { label: "patchDeCasteljau.control.surface" }),
    checkbox("net", { label: "patchDeCasteljau.control.net" }),
  ),
];

const LABELS = new Map();
/** "P₁₂": row i (along u), column j (along v). */
function netLabel(k, side) {
  const key = k * 16 + side;
  let text = LABELS.get(key);
  if (text === undefined) {
    text = `P${subscript(Math.floor(k / side))}${subscript(k % side)}`;
    LABELS.set(key, text);
  }
  return text;
}
const RESULT_LABELS = [];
/** Q₀ … (rows first: points of the iso-curve at v), R₀ … (columns first: at u). */
const resultLabel = (letter, i) =>
  (RESULT_LABELS[i + (letter === "Q" ? 0 : 8)] ??= `${letter}${subscript(i)}`);

export const figure3d = {
  bounds: (s) => boundsOf3(s.points),
  camera: CAMERA,
  // While the construction is shown its points carry the names: the net names its corners only.
  handles: {
    field: "points",
    label: (k, s) => netLabel(k, sideOf(s)),
    showLabel: (k, s) => s.step === 0 || netCorner(k, sideOf(s), sideOf(s)),
  },
  // The iso-curve through the row (column) results lies on the surface: a scene curve,
  // depth-tested with it, once the results are on view.
  scene: (s, d) => ({
    surfaces: d.mesh ? [d.mesh] : [],
    wireframe: [],
    curves: d.stage.results ? [{ points: d.iso, colour: HUES.vermillion, width: WIDTH.curve }] : [],
  }),
};

const stylesFor = themed((theme) => ({
  isoPolygon: Object.freeze({ stroke: HUES.vermillion, width: WIDTH.construction, dash: [4, 3] }),
  result: Object.freeze({
    fill: HUES.vermillion,
    stroke: theme.background,
    width: 1.5,
    radius: RADIUS.constructionPoint + 1,
  }),
}));

const a = new Float64Array(3);
const b = new Float64Array(3);
const centre = new Float64Array(3);

/**
 * The net, the first triangles (rows in v, or columns in u) level by level, their results with
 * the iso-curve they control, the second triangle, the handles and S(u, v).
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  const side = sideOf(s);
  const st = d.stage;
  const { first, second } = construction(s, d);
  const per = trianglePoints(st.degree);
  // A phone leaves the names of Q₀ … and S(u, v) out: the formula lists them.
  const named = v.width >= NARROW_CANVAS_PX * r.scale;
  if (s.net) {
    netPath(r, v, s.points, side, side);
    r.paint(theme.polygon);
  }
  if (st.results) {
    // The iso-curve itself is a scene curve (figure3d.scene).
    indexedPath3(r, v, second, st.count, (j) => j);
    r.paint(styles.isoPolygon);
  }
  for (let i = 0; i < st.count; i++) drawTriangle3(r, v, first, i * per, st.degree, st.first);
  if (st.results) drawTriangle3(r, v, second, 0, st.degree, st.second);
  d.handles.draw(r, v);
  if (st.results) {
    // The intermediate results, labelled away from the point S(u, v).
    const apex = apexOf(second, 0, st.degree, b);
    v.project(apex[0], apex[1], apex[2], centre);
    const letter = s.order === "rows" ? "Q" : "R";
    for (let i = 0; i < st.count; i++) {
      v.project(second[3 * i], second[3 * i + 1], second[3 * i + 2], a);
      r.point(a[0], a[1], styles.result);
      if (!named) continue;
      placeLabelFrom(
        r,
        resultLabel(letter, i),
        a[0],
        a[1],
        centre[0],
        centre[1],
        theme.labelSmall,
        styles.result.radius * r.scale,
      );
    }
  }
  if (st.second === st.degree) {
    const p = d.point;
    v.project(p[0], p[1], p[2], a);
    r.point(a[0], a[1], theme.pointOnCurve);
    if (named)
      placeLabelFrom(
        r,
        t("patchDeCasteljau.pointLabel"),
        a[0],
        a[1],
        a[0] - 1,
        a[1] - 3,
        theme.labelPoint,
        theme.pointOnCurve.radius * r.scale,
      );
  }
}

const triple = (p, k = 0) => pointTex([p[k], p[k + 1], p[k + 2]]);

/** The recurrences of the chosen order, its intermediate results, and both orders' S(u, v). */
export function formula(s, d) {
  const deg = s.degree;
  const rows = s.order === "rows";
  const { second } = construction(s, d);
  const letter = rows ? "Q" : "R";
  // The results two to a line (a line wider than the panel would shrink its type).
  const results = [];
  for (let i = 0; i <= deg; i += 2) {
    const pair = [`${letter}_{${i}} = ${triple(second, 3 * i)}`];
    if (i + 1 <= deg) pair.push(`${letter}_{${i + 1}} = ${triple(second, 3 * (i + 1))}`);
    results.push(pair.join(",\\ "));
  }
  const byRows = apexOf(d.rowsFirst.column, 0, deg, a);
  const byColumns = apexOf(d.columnsFirst.row, 0, deg, b);
  const gap = Math.hypot(
    byRows[0] - byColumns[0],
    byRows[1] - byColumns[1],
    byRows[2] - byColumns[2],
  );
  const params = { u: fmtTex(s.u), v: fmtTex(s.v), n: deg, m: deg };
  return [
    t(rows ? "patchDeCasteljau.texRows" : "patchDeCasteljau.texColumns", params),
    t(rows ? "patchDeCasteljau.texColumn" : "patchDeCasteljau.texRow", params),
    ...results,
    t("patchDeCasteljau.texBoth", {
      ...params,
      rows: triple(byRows),
      columns: triple(byColumns),
      gap:
        gap === 0 ? "0" : texDecimal(gap.toExponential(1)).replace(/e([+-]\d+)/, "\\cdot 10^{$1}"),
    }),
  ];
}

export function label(s, d) {
  const [x, y, z] = d.point;
  return t("patchDeCasteljau.aria", {
    degree: s.degree,
    u: fmt(s.u),
    v: fmt(s.v),
    order: t(s.order === "rows" ? "patchDeCasteljau.ariaRows" : "patchDeCasteljau.ariaColumns"),
    step: s.step,
    of: 2 * s.degree,
    x: fmt(x, 2),
    y: fmt(y, 2),
    z: fmt(z, 2),
  });
}
