/**
 * Demo (syllabus §6): global interpolation of a grid of data points by a B-spline surface
 * (`sl.interpolateSurface`, NURBS Book §9.2.5): parameters per column and row by the chosen
 * kind (`sl.interpolateSurfaceParams`), averaging knots, every column interpolated in u, then
 * every row of the result in v. The data points are the handles; a drag rebuilds the surface
 * (interpolation is global: every control point depends on every data point) once per frame.
 * The intermediate step is shown literally: each column of the data interpolated in u with
 * `sl.interpolateBSpline` on the surface's u parameters, with its control points s_il — the
 * surface's iso-curve at v = v̄_l is that same curve, because the second pass makes
 * Σ_j N_j(v̄_l) P_ij = s_il.
 */
import { field } from "../lib/validate.js";
import { choice, group, readout } from "../lib/panel.js";
import { showGroup } from "../lib/surface-controls.js";
import { subscript, listTex, localeDecimal } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { boundsOf3 } from "../lib/camera3d.js";
import { netCorner } from "../lib/handle-lists3d.js";
import { netPath, flatPath3 } from "../lib/draw3d.js";
import { knotListTex } from "../lib/knot-readout.js";
import { HUES, WIDTH, RADIUS, FONT_SIZE, themed } from "../lib/theme.js";

export const id = "surface-interpolation";
export const strings = "surfaceInterpolation";
export const section = 6;

/** The data grid: ROWS × COLS points, rows along u. */
const ROWS = 4;
const COLS = 5;
/** Mesh resolution and samples per drawn curve. */
const MESH = 48;
const CURVE_SAMPLES = 64;

/** A height field over an uneven grid: x at 0, 2, 5, 7; y at 0, 2, 3.5, 6, 8. */
const XS = [0, 2, 5, 7];
const YS = [0, 2, 3.5, 6, 8];
const HEIGHTS = [
  [0, 0.4, 0.7, 0.5, 0],
  [0.3, 1.2, 1.6, 1.1, 0.4],
  [0.4, 1.3, 1.8, 1.2, 0.5],
  [0, 0.5, 0.8, 0.6, 0.2],
];

export const defaultState = Object.freeze({
  points: HEIGHTS.flatMap((row, i) => row.map((h, j) => [XS[i], YS[j], h])),
  degreeU: 3,
  degreeV: 3,
  kind: "chord",
  columns: true,
  net: true,
  iso: false,
});

const KINDS = ["uniform", "chord", "centripetal"];

export const fields = {
  points: field.points3d({ rows: ROWS, cols: COLS }),
  degreeU: field.number({ min: 1, max: ROWS - 1, integer: true }),
  degreeV: field.number({ min: 1, max: COLS - 1, integer: true }),
  kind: field.choice(KINDS),
  columns: field.boolean(),
  net: field.boolean(),
  iso: field.boolean(),
};

const flat3 = (points) => Float64Array.from(points.flat());

/**
 * The interpolating surface and the parameters it used. No `moved`: a dragged data point marks
 * the points changed and the runtime rebuilds the model once per frame (a refusal — two data
 * points of a column made to coincide — keeps the last surface and says why).
 */
export const derive = {
  from: ["points", "degreeU", "degreeV", "kind"],
  build: (s, sl) => {
    const flat = flat3(s.points);
    const surface = sl.interpolateSurface(flat, ROWS, COLS, s.degreeU, s.degreeV, s.kind);
    try {
      return { surface, params: sl.interpolateSurfaceParams(flat, ROWS, COLS, s.kind) };
    } catch (err) {
      surface.free();
      throw err;
    }
  },
};

const uniform = (n) => Float64Array.from({ length: n }, (_, k) => k / (n - 1));
const SAMPLES = uniform(CURVE_SAMPLES);

/** Column l of the data, flat xyz (the points of the first pass's curve l). */
const columnFlat = (points, l) =>
  Float64Array.from({ length: 3 * ROWS }, (_, k) => points[Math.floor(k / 3) * COLS + l][k % 3]);

/** What the core returns. */
export const compute = {
  mesh: [["points"], (s, d) => d.surface.tessellate(MESH, MESH)],
  /** The control net P_ij (flat xyz, rows × cols as the data). */
  net: [["points"], (s, d) => d.surface.controlPoints()],
  knots: [["points"], (s, d) => ({ u: d.surface.knotsU(), v: d.surface.knotsV() })],
  /** Iso-curves through the data: at each ū_k (running in v) and each v̄_l (running in u). */
  isoCurves: [
    ["points"],
    (s, d) => [
      ...Array.from(d.params.u, (u) => d.surface.sampleGrid([u], SAMPLES)),
      ...Array.from(d.params.v, (v) => d.surface.sampleGrid(SAMPLES, [v])),
    ],
  ],
  /**
   * The first pass: every column interpolated in u on the surface's parameters ū (default
   * averaging knots, the surface's U): `{ samples, points }` per column, `points` the s_il.
   */
  columnCurves: [
    ["points", "columns"],
    (s, d) => {
      if (!s.columns) return [];
      return Array.from({ length: COLS }, (_, l) => {
        const curve = d.sl.interpolateBSpline(columnFlat(s.points, l), 3, s.degreeU, d.params.u);
        try {
          return { samples: curve.sampleUniform(CURVE_SAMPLES), points: curve.controlPoints() };
        } finally {
          curve.free();
        }
      });
    },
  ],
  /** The largest distance between S(ū_k, v̄_l) and data point Q_kl (a check beside the core's result). */
  miss: [
    ["points"],
    (s, d) => {
      const grid = d.surface.sampleGrid(d.params.u, d.params.v); // u-major: the data's order
      let worst = 0;
      s.points.forEach((q, k) => {
        const gap = Math.hypot(grid[3 * k] - q[0], grid[3 * k + 1] - q[1], grid[3 * k + 2] - q[2]);
        worst = Math.max(worst, gap);
      });
      return worst;
    },
  ],
};

const degreeChoice = (name, max) =>
  choice(name, {
    options: Array.from({ length: max }, (_, k) => ({
      value: k + 1,
      label: `surfaceInterpolation.degree${k + 1}`,
    })),
    name: name === "degreeU" ? "degree-u" : "degree-v",
    rebuild: true,
  });

export const controls = [
  group(
    "surfaceInterpolation.control.parametrisation",
    choice("kind", {
      options: KINDS.map((kind) => ({ value: kind, label: `surfaceInterpolation.kind.${kind}` })),
      rebuild: true,
    }),
  ),
  group("surfaceInterpolation.control.degreeU", degreeChoice("degreeU", ROWS - 1)),
  group("surfaceInterpolation.control.degreeV", degreeChoice("degreeV", COLS - 1)),
  showGroup(strings, ["columns", "net", "iso"]),
  readout(
    "miss",
    (s, d) =>
      t("surfaceInterpolation.missReadout", {
        count: ROWS * COLS,
        miss: localeDecimal(d.miss.toExponential(1)),
      }),
    {
      data: (s, d) => ({
        miss: String(d.miss),
        paramsU: Array.from(d.params.u).join(" "),
        paramsV: Array.from(d.params.v).join(" "),
      }),
    },
  ),
];

const LABELS = [];
/** "Q₁₂": data point of row k (along u), column l (along v). */
const dataLabel = (k) =>
  (LABELS[k] ??= `Q${subscript(Math.floor(k / COLS))}${subscript(k % COLS)}`);

export const figure3d = {
  // The data and, once built, the control net (it overshoots the data).
  bounds: (s, d) => {
    const box = boundsOf3(s.points);
    const net = d.net ?? [];
    for (let k = 0; k < net.length; k++) {
      box[k % 3] = Math.min(box[k % 3], net[k]);
      box[3 + (k % 3)] = Math.max(box[3 + (k % 3)], net[k]);
    }
    return box;
  },
  // 20 names would cover the grid: the corners (and the selected point) are named.
  handles: {
    field: "points",
    label: (k) => dataLabel(k),
    showLabel: (k) => netCorner(k, ROWS, COLS),
  },
  scene: (s, d) => ({
    surfaces: [d.mesh],
    wireframe: [],
    curves: s.iso ? d.isoCurves : [],
  }),
};

const stylesFor = themed((theme) => ({
  net: Object.freeze({ stroke: HUES.reddishPurple, width: WIDTH.polygon, dash: [2, 4] }),
  netPoint: Object.freeze({ fill: HUES.reddishPurple, radius: RADIUS.constructionPoint }),
  column: Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.curve, join: "round" }),
  columnPolygon: Object.freeze({ stroke: HUES.bluishGreen, width: 1, dash: [5, 3] }),
  legend: Object.freeze({ fill: theme.text, size: FONT_SIZE.small, halo: theme.background }),
  columnPoint: Object.freeze({
    fill: theme.background,
    stroke: HUES.bluishGreen,
    width: 1.5,
    radius: RADIUS.constructionPoint,
  }),
}));

const a = new Float64Array(3);
const NET_POINTS = ROWS * COLS;

/** The 2D layer: the control net (dotted purple), the column curves of the first pass, the data. */
export function draw(r, v, s, d) {
  const styles = stylesFor(r.theme);
  if (s.net) {
    r.beginPath();
    for (let i = 0; i < ROWS; i++)
      for (let j = 0; j < COLS; j++) line(r, v, d.net, i * COLS + j, j === 0);
    for (let j = 0; j < COLS; j++)
      for (let i = 0; i < ROWS; i++) line(r, v, d.net, i * COLS + j, i === 0);
    r.paint(styles.net);
    for (let k = 0; k < NET_POINTS; k++) {
      v.project(d.net[3 * k], d.net[3 * k + 1], d.net[3 * k + 2], a);
      r.point(a[0], a[1], styles.netPoint);
    }
  }
  for (const curve of d.columnCurves) {
    flatPath3(r, v, curve.points);
    r.paint(styles.columnPolygon);
    flatPath3(r, v, curve.samples);
    r.paint(styles.column);
    for (let k = 0; k < curve.points.length / 3; k++) {
      v.project(curve.points[3 * k], curve.points[3 * k + 1], curve.points[3 * k + 2], a);
      r.point(a[0], a[1], styles.columnPoint);
    }
  }
  drawLegend(r, styles, s);
  if (!s.net) {
    // The data grid itself, thin, so the handles read as a grid without the net.
    netPath(r, v, s.points, ROWS, COLS);
    r.paint(r.theme.polygon);
  }
  d.handles.draw(r, v);
}

/** The legend, top left: the column curves of step 1 and the control net, when shown. */
function drawLegend(r, styles, s) {
  const size = FONT_SIZE.small * r.scale;
  const x = 12 * r.scale;
  const swatch = 18 * r.scale;
  let y = 12 * r.scale + size / 2;
  const entry = (lineStyle, pointStyle, key) => {
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + swatch, y);
    r.paint(lineStyle);
    r.point(x + swatch / 2, y, pointStyle);
    r.text(t(key), x + swatch + 6 * r.scale, y, styles.legend, "left", "middle");
    y += size * 1.5;
  };
  if (s.columns) entry(styles.column, styles.columnPoint, "surfaceInterpolation.legendColumns");
  if (s.net) entry(styles.net, styles.netPoint, "surfaceInterpolation.legendNet");
}

/** Moves to or draws a line to net point k (flat xyz). */
function line(r, v, flat, k, first) {
  v.project(flat[3 * k], flat[3 * k + 1], flat[3 * k + 2], a);
  if (first) r.moveTo(a[0], a[1]);
  else r.lineTo(a[0], a[1]);
}

export function formula(s, d) {
  const m = ROWS - 1;
  const n = COLS - 1;
  return [
    t("surfaceInterpolation.texUnknowns", {
      rows: ROWS,
      cols: COLS,
      count: ROWS * COLS,
      m,
      n,
      p: s.degreeU,
      q: s.degreeV,
    }),
    `\\bar u = (${listTex(d.params.u)}),\\quad \\bar v = (${listTex(d.params.v)})`,
    `U = (${knotListTex(d.knots.u)}),\\quad V = (${knotListTex(d.knots.v)})`,
    t("surfaceInterpolation.texColumns", { cols: COLS, rows: ROWS, m, p: s.degreeU }),
    t("surfaceInterpolation.texRows", { cols: COLS, rows: ROWS, n, q: s.degreeV }),
  ];
}

export function label(s, d) {
  return t("surfaceInterpolation.aria", {
    rows: ROWS,
    cols: COLS,
    p: s.degreeU,
    q: s.degreeV,
    kind: t(`surfaceInterpolation.kind.${s.kind}`),
    miss: localeDecimal(d.miss.toExponential(1)),
  });
}
