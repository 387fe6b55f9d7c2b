/**
 * Demo (syllabus §6): a bicubic Bézier patch, the first 3D figure (lib/view3d.js). The patch
 * lives in wasm (`BezierSurface`), moved in place while a control point is dragged
 * (`setControlPoint`); the mesh, its normals, the iso-curves, the point and the normal at the
 * probe are what the core returns. The generatrix/directrix picture of the Croatian notes: each
 * row i of the net is a directrix D_i(v) (a cubic Bézier curve in v, `BezierCurve` of dim 3);
 * at v, the points D_0(v) … D_3(v) are the control points of the generatrix, the iso-curve at
 * that v (a cubic in u: the core's `isoCurveV(v)`), which sweeps the patch as v plays. The
 * matrix form shows A = M P Mᵀ from `matrixForm()` per coordinate; the surface can be shaded lit,
 * with zebra stripes, or by its Gaussian or mean curvature (`curvatures(mesh.uvs)`, scene3d.js).
 */
import { field } from "../lib/validate.js";
import { slider, group } from "../lib/panel.js";
import { showGroup, shadingChoice, shadingCurvatures } from "../lib/surface-controls.js";
import { SHADINGS } from "../lib/shading3d.js";
import { diagonalFraction, drawProbeNormal } from "../lib/probe-normal.js";
import { fmt, subscript, fmtTex, pointTex } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { boundsOf3 } from "../lib/camera3d.js";
import { netPath, flatPath3 } from "../lib/draw3d.js";
import { HUES, WIDTH, RADIUS, themed } from "../lib/theme.js";

export const id = "bezier-patch";
export const strings = "bezierPatch";
export const section = 6;

/** The net: 4 × 4 (bicubic), rows along u. */
const ROWS = 4;
const COLS = 4;
/** Mesh resolution (quads per direction) and samples along each drawn curve. */
const MESH = 40;
const CURVE_SAMPLES = 64;
/** Iso-curves drawn at u, v = k/ISO_LINES, k = 1 … ISO_LINES − 1. */
const ISO_LINES = 8;
/** The normal arrow's length as a fraction of the net's diagonal. */
const NORMAL_FRACTION = 0.18;

/** Heights of a wavy patch over a 6 × 6 square (P_ij = (2i, 2j, h_ij)). */
const HEIGHTS = [
  [0, 1, 1.2, 0],
  [1, 3, 0.6, 0.8],
  [0.6, -0.4, 2.6, 1.2],
  [0, 1.2, 0.6, 0.2],
];

export const defaultState = Object.freeze({
  points: HEIGHTS.flatMap((row, i) => row.map((h, j) => [2 * i, 2 * j, h])),
  u: 0.35,
  v: 0.6,
  net: true,
  iso: true,
  wireframe: false,
  sweep: true,
  normal: true,
  shading: "lit",
});

export const fields = {
  points: field.points3d({ rows: ROWS, cols: COLS }),
  u: field.number({ min: 0, max: 1 }),
  v: field.number({ min: 0, max: 1 }),
  net: field.boolean(),
  iso: field.boolean(),
  wireframe: field.boolean(),
  sweep: field.boolean(),
  normal: field.boolean(),
  shading: field.choice(SHADINGS),
};

const flat3 = (points) => Float64Array.from(points.flat());
const rowFlat = (points, i) => flat3(points.slice(i * COLS, (i + 1) * COLS));

/** The patch and its four directrices (the rows' Bézier curves in v), moved in place. */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({
    patch: new sl.BezierSurface(flat3(s.points), ROWS, COLS),
    directrices: Array.from(
      { length: ROWS },
      (_, i) => new sl.BezierCurve(rowFlat(s.points, i), 3),
    ),
  }),
  moved: (m, k, xyz) => {
    const i = Math.floor(k / COLS);
    const j = k % COLS;
    m.patch.setControlPoint(i, j, xyz);
    m.directrices[i].setControlPoint(j, xyz);
  },
};

const uniform = (n) => Float64Array.from({ length: n }, (_, k) => k / (n - 1));
const SAMPLES = uniform(CURVE_SAMPLES);
const ISO = Float64Array.from({ length: ISO_LINES - 1 }, (_, k) => (k + 1) / ISO_LINES);

/** What the core returns: mesh, iso-curves, generatrix, directrices, point and normal. */
export const compute = {
  mesh: [["points"], (s, d) => d.patch.tessellate(MESH, MESH)],
  // Iso-curves: at constant u (running in v) and at constant v (running in u).
  isoCurves: [
    ["points"],
    (s, d) => [
      ...Array.from(ISO, (u) => d.patch.sampleGrid([u], SAMPLES)),
      ...Array.from(ISO, (v) => d.patch.sampleGrid(SAMPLES, [v])),
    ],
  ],
  // The generatrix: the iso-curve at constant v (a cubic Bézier curve in u), sampled once, freed.
  generatrix: [
    ["points", "v"],
    (s, d) => {
      const curve = d.patch.isoCurveV(s.v);
      try {
        return curve.sampleUniform(CURVE_SAMPLES);
      } finally {
        curve.free();
      }
    },
  ],
  directrixCurves: [["points"], (s, d) => d.directrices.map((c) => c.sampleUniform(CURVE_SAMPLES))],
  // The generatrix's control points D_i(v): each directrix at v.
  generatrixPoints: [["points", "v"], (s, d) => d.directrices.map((c) => c.evaluate(s.v))],
  point: [["points", "u", "v"], (s, d) => d.patch.evaluate(s.u, s.v)],
  normalAt: [["points", "u", "v"], (s, d) => d.patch.normal(s.u, s.v)],
  // A = M P Mᵀ per coordinate: { basisU, basisV, coefficients } (flat 4·4·3, xyz per entry).
  matrix: [["points"], (s, d) => d.patch.matrixForm()],
  // [K0, H0, K1, H1, …] at the mesh's vertices, only while a curvature shading shows them.
  curvatures: [["points", "shading"], (s, d) => shadingCurvatures(d.patch, d.mesh, s.shading)],
};

export const controls = [
  group(
    null,
    slider("u", { label: "bezierPatch.control.u", min: 0, max: 1, step: 0.001 }),
    slider("v", {
      label: "bezierPatch.control.v",
      min: 0,
      max: 1,
      step: 0.001,
      player: {
        stepBackTitle: "bezierPatch.control.stepBack.title",
        stepTitle: "bezierPatch.control.step.title",
      },
    }),
  ),
  showGroup(strings, ["net", "iso", "wireframe", "sweep", "normal"]),
  shadingChoice(strings),
];

const LABELS = [];
/** "P₁₂": row i (along u), column j (along v). */
const netLabel = (k) => (LABELS[k] ??= `P${subscript(Math.floor(k / COLS))}${subscript(k % COLS)}`);

export const figure3d = {
  bounds: (s) => boundsOf3(s.points),
  handles: { field: "points", label: (k) => netLabel(k) },
  scene: (s, d) => ({
    surfaces: [{ mesh: d.mesh, shading: s.shading, curvatures: d.curvatures }],
    wireframe: s.wireframe ? [{ mesh: d.mesh, grid: [MESH + 1, MESH + 1] }] : [],
    curves: s.iso ? d.isoCurves : [],
  }),
};

const stylesFor = themed((theme) => ({
  directrix: Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.construction, dash: [6, 4] }),
  generatrix: Object.freeze({ stroke: HUES.vermillion, width: WIDTH.curve, join: "round" }),
  generatrixPolygon: Object.freeze({ stroke: HUES.vermillion, width: 1, dash: [3, 3] }),
  generatrixPoint: Object.freeze({
    fill: HUES.bluishGreen,
    stroke: theme.background,
    width: 1,
    radius: RADIUS.constructionPoint,
  }),
}));

const a = new Float64Array(3);

/** The 2D layer over the lit patch: net, directrices, generatrix, probe and normal, handles. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  if (s.net) {
    netPath(r, v, s.points, ROWS, COLS);
    r.paint(theme.polygon);
  }
  if (s.sweep) {
    for (const curve of d.directrixCurves) {
      flatPath3(r, v, curve);
      r.paint(styles.directrix);
    }
    r.beginPath();
    d.generatrixPoints.forEach((p, i) => {
      v.project(p[0], p[1], p[2], a);
      if (i === 0) r.moveTo(a[0], a[1]);
      else r.lineTo(a[0], a[1]);
    });
    r.paint(styles.generatrixPolygon);
    flatPath3(r, v, d.generatrix);
    r.paint(styles.generatrix);
    for (const p of d.generatrixPoints) {
      v.project(p[0], p[1], p[2], a);
      r.point(a[0], a[1], styles.generatrixPoint);
    }
  }
  const length = s.normal ? diagonalFraction(s.points, NORMAL_FRACTION) : 0;
  const normal = s.normal ? d.normalAt : null;
  drawProbeNormal(r, v, d.point, normal, length, t("bezierPatch.normalLabel"));
  d.handles.draw(r, v);
}

/** A matrix entry as TeX: up to 3 decimals, trailing zeros dropped ("6", "−1.25", "−1{,}25"). */
const entry = (x) => fmtTex(x).replace(/(?:\.|\{,\})?0+$/, "");

/** A 4 × 4 matrix as TeX from `at(i, j)`. */
const matrixTex = (at) =>
  `\\begin{bmatrix} ${[0, 1, 2, 3]
    .map((i) => [0, 1, 2, 3].map((j) => entry(at(i, j))).join(" & "))
    .join(" \\\\ ")} \\end{bmatrix}`;

/** The basis matrix M_U from the core (flat (m+1)², row-major: the Bernstein coefficients). */
const basisTex = (m) => `M = ${matrixTex((i, j) => m.basisU[4 * i + j])}`;

/** Coordinate c (0 x, 1 y, 2 z) of A = M P Mᵀ as a matrix. */
const coefficientTex = (m, c) => matrixTex((i, j) => m.coefficients[3 * (4 * i + j) + c]);

const triple = (p) => pointTex([p[0], p[1], p[2]]);

export function formula(s, d) {
  return [
    `S(u, v) = [u^3\\ u^2\\ u\\ 1]\\, A \\,[v^3\\ v^2\\ v\\ 1]^T,\\quad A = M\\, P\\, M^T,\\quad ${basisTex(d.matrix)}`,
    `A_x = ${coefficientTex(d.matrix, 0)},\\quad A_y = ${coefficientTex(d.matrix, 1)}`,
    `A_z = ${coefficientTex(d.matrix, 2)}`,
    t("bezierPatch.texGeneratrix", { v: fmtTex(s.v) }),
    `S${pointTex([s.u, s.v])} = ${triple(d.point)},\\quad n = \\frac{S_u \\times S_v}{\\lvert S_u \\times S_v \\rvert} = ${triple(d.normalAt)}`,
  ];
}

export function label(s, d) {
  const [x, y, z] = d.point;
  const [nx, ny, nz] = d.normalAt;
  return t("bezierPatch.aria", {
    u: fmt(s.u),
    v: fmt(s.v),
    x: fmt(x, 2),
    y: fmt(y, 2),
    z: fmt(z, 2),
    nx: fmt(nx, 2),
    ny: fmt(ny, 2),
    nz: fmt(nz, 2),
  });
}
