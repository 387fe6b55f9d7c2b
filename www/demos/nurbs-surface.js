/**
 * Demo (syllabus §6): a tensor-product B-spline / NURBS surface (`BSplineSurface`) with a degree
 * and a knot vector per direction, knot insertion in u and in v (Boehm's rule on the columns
 * adds a whole row of control points, on the rows a whole column: `insertKnotU/V`), a weight per
 * control point (`setWeight`, in place), the seams at interior knots coloured by the continuity
 * the core measures (`seams()`), iso-curves, and the point and normal at a probe (u, v).
 * Everything drawn is what the core returns; the knot vectors offered come from `knotVector`.
 */
import { field } from "../lib/validate.js";
import { slider, choice, group, actions, numberList, readout } from "../lib/panel.js";
import { showGroup, shadingChoice, shadingCurvatures } from "../lib/surface-controls.js";
import { SHADINGS } from "../lib/shading3d.js";
import { diagonalFraction, drawProbeNormal } from "../lib/probe-normal.js";
import {
  insertAtProbe,
  resetKnots,
  typedKnots,
  selectedWeight,
  netLabel,
} from "../lib/surface-net-edit.js";
import { fmt, shortNumber, pointTex, DECIMALS, listTex, listSeparator } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { boundsOf3 } from "../lib/camera3d.js";
import { netCorner } from "../lib/handle-lists3d.js";
import { netPath } from "../lib/draw3d.js";
import { continuityText } from "../lib/continuity.js";
import { knotListTex } from "../lib/knot-readout.js";
import { HUES, WIDTH, RADIUS, FONT_SIZE, themed } from "../lib/theme.js";

export const id = "nurbs-surface";
export const strings = "nurbsSurface";
export const section = 6;

/** Net size limits: insertion stops at MAX_LINES rows or columns (a readable net). */
const MIN_LINES = 2;
const MAX_LINES = 12;
const MAX_DEGREE = 4;
/** A weight's range (the slider is logarithmic over it) and its step in log10 units. */
const WEIGHT_MIN = 0.1;
const WEIGHT_MAX = 10;
const WEIGHT_LOG_STEP = 0.01;
/** The colour of the net lines an insertion made (scene curves and the legend's swatch). */
const FRESH_COLOUR = "#2B2B2B";

/** Mesh resolution, samples per drawn curve, iso-curves per direction. */
const MESH = 48;
const CURVE_SAMPLES = 64;
const ISO_LINES = 6;
/** The normal arrow's length as a fraction of the net's diagonal. */
const NORMAL_FRACTION = 0.16;
/** The fixed grid (fractions of the domain) whose points sum to `data-surface-sum`. */
const CHECK_GRID = 9;

/** Heights of the default 5 × 6 net over a 8 × 10 rectangle (P_ij = (2i, 2j, h_ij)). */
const HEIGHTS = [
  [0, 0.6, 1, 0.4, 0.2, 0],
  [0.8, 2.4, 0.2, 1.8, 1.6, 0.6],
  [0.4, -0.4, 2.8, 0.8, -0.6, 1],
  [1, 2, 0.6, -0.2, 2.2, 0.4],
  [0, 0.4, 1.2, 0.8, 0.6, 0],
];

export const defaultState = Object.freeze({
  rows: 5,
  cols: 6,
  degreeU: 3,
  degreeV: 2,
  knotsU: [0, 0, 0, 0, 1, 2, 2, 2, 2],
  knotsV: [0, 0, 0, 1, 2, 3, 4, 4, 4],
  points: HEIGHTS.flatMap((row, i) => row.map((h, j) => [2 * i, 2 * j, h])),
  weights: Array(30).fill(1),
  selected: 14,
  u: 0.8,
  v: 2.5,
  /** The rows (direction 0) or columns (1) an insertion made: [direction, first, last]; [] none. */
  fresh: [],
  net: true,
  iso: true,
  seams: true,
  normal: true,
  shading: "lit",
});

const count = (s) => s.rows * s.cols;
export const fields = {
  rows: field.number({ min: MIN_LINES, max: MAX_LINES, integer: true }),
  cols: field.number({ min: MIN_LINES, max: MAX_LINES, integer: true }),
  degreeU: field.number({ min: 1, max: MAX_DEGREE, integer: true }),
  degreeV: field.number({ min: 1, max: MAX_DEGREE, integer: true }),
  knotsU: field.numbers({ min: 2, max: MAX_LINES + MAX_DEGREE + 1 }),
  knotsV: field.numbers({ min: 2, max: MAX_LINES + MAX_DEGREE + 1 }),
  points: field.points3d((s) => ({ rows: s.rows, cols: s.cols })),
  weights: field.numbers({ min: MIN_LINES * MIN_LINES, max: MAX_LINES * MAX_LINES }),
  selected: field.number({ min: 0, max: MAX_LINES * MAX_LINES - 1, integer: true }),
  u: field.number({ min: -1e6, max: 1e6 }),
  v: field.number({ min: -1e6, max: 1e6 }),
  fresh: field.numbers({ min: 0, max: 3 }),
  net: field.boolean(),
  iso: field.boolean(),
  seams: field.boolean(),
  shading: field.choice(SHADINGS),
  normal: field.boolean(),
};

/** Rules across fields the core does not see: the selected point and the probe in range. */
export function check(s) {
  if (s.weights.length !== count(s))
    throw new Error(t("nurbsSurface.weightCount", { count: s.weights.length, points: count(s) }));
  if (s.selected >= count(s))
    throw new Error(t("nurbsSurface.badSelected", { i: s.selected, count: count(s) }));
}

/** The domain [u_p, u_rows] of a knot vector for `n` control points of degree p. */
const domainOf = (knots, p, n) => [knots[p], knots[n]];
const clampInto = (x, [a, b]) => Math.min(b, Math.max(a, x));

/** The probe and the selected point back into range after a change of knots or net. */
export function adjust(s) {
  if (s.knotsU.length === s.rows + s.degreeU + 1)
    s.u = clampInto(s.u, domainOf(s.knotsU, s.degreeU, s.rows));
  if (s.knotsV.length === s.cols + s.degreeV + 1)
    s.v = clampInto(s.v, domainOf(s.knotsV, s.degreeV, s.cols));
  if (s.selected >= count(s)) s.selected = 0;
}

const flat3 = (points) => Float64Array.from(points.flat());

/** The surface, moved in place while a point is dragged or a weight slides. */
export const derive = {
  from: ["rows", "cols", "degreeU", "degreeV", "knotsU", "knotsV", "points", "weights"],
  build: (s, sl) => ({
    surface: new sl.BSplineSurface(
      flat3(s.points),
      s.rows,
      s.cols,
      s.degreeU,
      s.degreeV,
      Float64Array.from(s.knotsU),
      Float64Array.from(s.knotsV),
      Float64Array.from(s.weights),
    ),
  }),
  moved: (m, k, xyz, s) => m.surface.setControlPoint(Math.floor(k / s.cols), k % s.cols, xyz),
  weighted: (m, k, w, s) => m.surface.setWeight(Math.floor(k / s.cols), k % s.cols, w),
};

const spread = (a, b, n) => Float64Array.from({ length: n }, (_, k) => a + ((b - a) * k) / (n - 1));
const SHAPE = ["points", "weights"];

/** What the core returns. */
export const compute = {
  domainU: [SHAPE, (s, d) => d.surface.domainU()],
  domainV: [SHAPE, (s, d) => d.surface.domainV()],
  mesh: [SHAPE, (s, d) => d.surface.tessellate(MESH, MESH)],
  // [K0, H0, K1, H1, …] at the mesh's vertices, only while a curvature shading shows them.
  curvatures: [[...SHAPE, "shading"], (s, d) => shadingCurvatures(d.surface, d.mesh, s.shading)],
  isoCurves: [
    SHAPE,
    (s, d) => {
      const [u0, u1] = d.domainU;
      const [v0, v1] = d.domainV;
      const us = spread(u0, u1, CURVE_SAMPLES);
      const vs = spread(v0, v1, CURVE_SAMPLES);
      const inner = (a, b) => spread(a, b, ISO_LINES + 2).slice(1, -1);
      return [
        ...Array.from(inner(u0, u1), (u) => d.surface.sampleGrid([u], vs)),
        ...Array.from(inner(v0, v1), (v) => d.surface.sampleGrid(us, [v])),
      ];
    },
  ],
  /** `{ u, v }`: [knot, c, …] per distinct interior knot, c measured across the seam. */
  seams: [SHAPE, (s, d) => d.surface.seams()],
  /** The seams as curves: `{ c, samples, dir, knot }`, the iso-curve at each interior knot. */
  seamCurves: [
    SHAPE,
    (s, d) => {
      const us = spread(...d.domainU, CURVE_SAMPLES);
      const vs = spread(...d.domainV, CURVE_SAMPLES);
      const out = [];
      for (let k = 0; k < d.seams.u.length; k += 2)
        out.push({
          dir: "u",
          knot: d.seams.u[k],
          c: d.seams.u[k + 1],
          samples: d.surface.sampleGrid([d.seams.u[k]], vs),
        });
      for (let k = 0; k < d.seams.v.length; k += 2)
        out.push({
          dir: "v",
          knot: d.seams.v[k],
          c: d.seams.v[k + 1],
          samples: d.surface.sampleGrid(us, [d.seams.v[k]]),
        });
      return out;
    },
  ],
  /** The net lines an insertion made, as coloured curve entries (flat xyz), or null. */
  freshLines: [
    ["points", "fresh"],
    (s) => {
      if (s.fresh.length !== 3) return null;
      const [dir, first, last] = s.fresh;
      const n = dir === 0 ? s.cols : s.rows;
      const out = [];
      for (let line = first; line <= last; line++) {
        const points = new Float64Array(3 * n);
        for (let k = 0; k < n; k++)
          points.set(s.points[dir === 0 ? line * s.cols + k : k * s.cols + line], 3 * k);
        out.push({ points, colour: FRESH_COLOUR, width: WIDTH.curve });
      }
      return out;
    },
  ],
  /** The continuities measured, each once, ascending (the legend's entries). */
  seamOrders: [
    SHAPE,
    (s, d) => [...new Set(d.seamCurves.map((curve) => curve.c))].sort((p, q) => p - q),
  ],
  /** The normal arrow's length: a fraction of the net's diagonal. */
  normalLength: [["points"], (s) => diagonalFraction(s.points, NORMAL_FRACTION)],
  point: [[...SHAPE, "u", "v"], (s, d) => d.surface.evaluate(s.u, s.v)],
  normalAt: [[...SHAPE, "u", "v"], (s, d) => d.surface.normal(s.u, s.v)],
  /** Σ (k + 1)(x + √2 y + √3 z) over a fixed 9 × 9 grid of the domain: a test's fingerprint. */
  checkSum: [
    SHAPE,
    (s, d) => {
      const grid = d.surface.sampleGrid(
        spread(...d.domainU, CHECK_GRID),
        spread(...d.domainV, CHECK_GRID),
      );
      let sum = 0;
      for (let k = 0; k < grid.length / 3; k++)
        sum +=
          (k + 1) * (grid[3 * k] + Math.SQRT2 * grid[3 * k + 1] + Math.sqrt(3) * grid[3 * k + 2]);
      return sum;
    },
  ],
};

const degreeOptions = [1, 2, 3, 4].map((p) => ({ value: p, label: `nurbsSurface.degree${p}` }));

/** The controls of one direction: degree, knots (typed or reset), insertion at the probe. */
function direction(dir) {
  const D = dir.toUpperCase();
  const lines = (s) => (dir === "u" ? s.rows : s.cols);
  return group(
    `nurbsSurface.control.direction${D}`,
    choice(`degree${D}`, {
      options: degreeOptions,
      name: `degree-${dir}`,
      refuse: (p, s) =>
        p >= lines(s) ? t("nurbsSurface.degreeTooHigh", { p, count: lines(s), dir }) : null,
      set: (ui, p) => resetKnots(ui, dir, "clamped", p),
    }),
    numberList(`knots${D}`, {
      label: `nurbsSurface.control.knots${D}`,
      name: `knots-${dir}`,
      format: (v) => shortNumber(v),
      help: (s) =>
        t("nurbsSurface.knotsHelp", {
          count: lines(s) + s[`degree${D}`] + 1,
          n: lines(s),
          p: s[`degree${D}`],
        }),
      apply: (ui, values) => typedKnots(ui, dir, values),
    }),
    actions([
      {
        name: `insert-${dir}`,
        label: `nurbsSurface.control.insert${D}`,
        run: (ui) => insertAtProbe(ui, dir, { prefix: strings, maxLines: MAX_LINES }),
        disabled: (s) => lines(s) >= MAX_LINES,
      },
      {
        name: `clamped-${dir}`,
        label: "nurbsSurface.control.clamped",
        run: (ui) => resetKnots(ui, dir, "clamped"),
      },
      {
        name: `uniform-${dir}`,
        label: "nurbsSurface.control.uniform",
        run: (ui) => resetKnots(ui, dir, "uniform"),
      },
    ]),
  );
}

/** "u = 1 C², u = 2 C¹ · v = 2 C¹": the measured seams for the readout. */
function seamsText(seams) {
  const part = (letter, list) => {
    const items = [];
    for (let k = 0; k < list.length; k += 2)
      items.push(`${letter} = ${shortNumber(list[k])} ${continuityText(list[k + 1])}`);
    return items.join(listSeparator());
  };
  const u = part("u", seams.u);
  const v = part("v", seams.v);
  if (!u && !v) return t("nurbsSurface.noSeams");
  return t("nurbsSurface.seamsReadout", { u: u || "—", v: v || "—" });
}

const seamData = (list) => {
  const items = [];
  for (let k = 0; k < list.length; k += 2) items.push(`${list[k]}:${list[k + 1]}`);
  return items.join(" ");
};

export const controls = [
  group(
    null,
    slider("u", {
      label: "nurbsSurface.control.u",
      range: (s) => domainOf(s.knotsU, s.degreeU, s.rows),
      step: (a, b) => (b - a) / 1000,
    }),
    slider("v", {
      label: "nurbsSurface.control.v",
      range: (s) => domainOf(s.knotsV, s.degreeV, s.cols),
      step: (a, b) => (b - a) / 1000,
    }),
  ),
  direction("u"),
  direction("v"),
  group(
    "nurbsSurface.control.weights",
    selectedWeight({ prefix: strings, min: WEIGHT_MIN, max: WEIGHT_MAX, step: WEIGHT_LOG_STEP }),
  ),
  showGroup(strings, ["net", "iso", "seams", "normal"]),
  shadingChoice(strings),
  readout("seams", (s, d) => seamsText(d.seams), {
    data: (s, d) => ({
      seamsU: seamData(d.seams.u),
      seamsV: seamData(d.seams.v),
      surfaceSum: String(d.checkSum),
      rows: String(s.rows),
      cols: String(s.cols),
    }),
  }),
];

export const figure3d = {
  bounds: (s) => boundsOf3(s.points),
  handles: {
    field: "points",
    label: (k, s) => netLabel(k, s.cols),
    // A dense net names its corners (and the selected point); the announcement names every one.
    showLabel: (k, s) => netCorner(k, s.rows, s.cols),
    select: (k, ui) => {
      if (k >= 0 && k !== ui.state.selected) ui.set("selected", k, false);
    },
  },
  // The seams (iso-curves at the interior knots, coloured by their measured continuity) lie on
  // the surface and the inserted net lines close to it: scene curves, depth-tested with it.
  scene: (s, d) => {
    const curves = s.iso ? [...d.isoCurves] : [];
    if (s.seams)
      for (const curve of d.seamCurves)
        curves.push({ points: curve.samples, colour: SEAM_HUES[seamIndex(curve.c)], width: 3 });
    if (d.freshLines) for (const points of d.freshLines) curves.push(points);
    return {
      surfaces: [{ mesh: d.mesh, shading: s.shading, curvatures: d.curvatures }],
      wireframe: [],
      curves,
    };
  },
};

/** Seam colours by measured continuity: a gap, C⁰, C¹, C², C³ and above. */
const SEAM_HUES = [
  HUES.reddishPurple,
  HUES.vermillion,
  HUES.orange,
  HUES.bluishGreen,
  HUES.skyBlue,
];
/** The colour index of measured continuity c (−1 a gap). */
const seamIndex = (c) => Math.min(c + 1, SEAM_HUES.length - 1);

const stylesFor = themed((theme) => ({
  swatch: SEAM_HUES.map((fill) => Object.freeze({ fill })),
  legend: Object.freeze({ fill: theme.text, size: FONT_SIZE.small, halo: theme.background }),
  fresh: Object.freeze({ stroke: FRESH_COLOUR, width: WIDTH.curve, join: "round" }),
  selectedRing: Object.freeze({ stroke: HUES.reddishPurple, width: 2, radius: RADIUS.handle + 4 }),
}));

const b = new Float64Array(3);
const NONE = Object.freeze([]);

/** The legend of the seam colours, top left: one swatch and word per continuity shown. */
function drawLegend(r, styles, orders, fresh) {
  if (!orders.length && fresh.length !== 3) return;
  const size = FONT_SIZE.small * r.scale;
  const x = 12 * r.scale;
  const swatch = 18 * r.scale;
  let y = 12 * r.scale + size / 2;
  r.text(t("nurbsSurface.legend"), x, y, styles.legend, "left", "middle");
  for (const c of orders) {
    y += size * 1.5;
    r.beginPath();
    r.rect(x, y - size / 3, swatch, (2 * size) / 3);
    r.paint(styles.swatch[seamIndex(c)]);
    r.text(continuityText(c), x + swatch + 6 * r.scale, y, styles.legend, "left", "middle");
  }
  if (fresh.length === 3) {
    y += size * 1.5;
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + swatch, y);
    r.paint(styles.fresh);
    const key = fresh[0] === 0 ? "nurbsSurface.legendFreshRows" : "nurbsSurface.legendFreshColumns";
    r.text(t(key), x + swatch + 6 * r.scale, y, styles.legend, "left", "middle");
  }
}

/** The 2D layer: net (new lines highlighted), seams by continuity, probe and normal, handles. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  if (s.net) {
    netPath(r, v, s.points, s.rows, s.cols);
    r.paint(theme.polygon);
  }
  // The seams and the inserted lines are scene curves (figure3d.scene); their legend stays here.
  drawLegend(r, styles, s.seams ? d.seamOrders : NONE, s.fresh);
  const normal = s.normal ? d.normalAt : null;
  drawProbeNormal(r, v, d.point, normal, d.normalLength, t("nurbsSurface.normalLabel"));
  const selected = s.points[s.selected];
  if (selected) {
    v.project(selected[0], selected[1], selected[2], b);
    r.point(b[0], b[1], styles.selectedRing);
  }
  d.handles.draw(r, v);
}

const triple = (p) => pointTex([p[0], p[1], p[2]]);
const knotsTex = (knots) => `(${knotListTex(knots)})`;

export function formula(s, d) {
  const [u0, u1] = d.domainU;
  const [v0, v1] = d.domainV;
  const lines = [
    `S(u, v) = \\frac{\\sum_{i=0}^{${s.rows - 1}} \\sum_{j=0}^{${s.cols - 1}} N_{i,${s.degreeU}}(u)\\, N_{j,${s.degreeV}}(v)\\, w_{ij} P_{ij}}{\\sum_i \\sum_j N_{i,${s.degreeU}}(u)\\, N_{j,${s.degreeV}}(v)\\, w_{ij}}`,
    `U = ${knotsTex(s.knotsU)},\\ u \\in [${listTex([shortNumber(u0, true), shortNumber(u1, true)], DECIMALS, " ")}]`,
    `V = ${knotsTex(s.knotsV)},\\ v \\in [${listTex([shortNumber(v0, true), shortNumber(v1, true)], DECIMALS, " ")}]`,
    t("nurbsSurface.texNet", {
      rows: s.rows,
      cols: s.cols,
      count: s.rows * s.cols,
      p: s.degreeU,
      q: s.degreeV,
    }),
    `S${pointTex([s.u, s.v])} = ${triple(d.point)},\\quad n = ${triple(d.normalAt)}`,
  ];
  if (s.fresh.length === 3)
    lines.push(
      t(s.fresh[0] === 0 ? "nurbsSurface.texInsertedU" : "nurbsSurface.texInsertedV", {
        first: s.fresh[1],
        last: s.fresh[2],
      }),
    );
  return lines;
}

export function label(s, d) {
  const [x, y, z] = d.point;
  return t("nurbsSurface.aria", {
    rows: s.rows,
    cols: s.cols,
    p: s.degreeU,
    q: s.degreeV,
    u: fmt(s.u),
    v: fmt(s.v),
    x: fmt(x, 2),
    y: fmt(y, 2),
    z: fmt(z, 2),
    seams: seamsText(d.seams),
  });
}
