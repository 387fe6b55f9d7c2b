/**
 * Demo (syllabus §6): surfaces made from curves, in four modes over one state.
 *
 * - torus: `sl.revolve` of the exact NURBS circle (`ellipseArc`, centre (R, 0, 0), radius r, in
 *   the xz plane) about the z axis by an angle: a rational biquadratic surface (NURBS Book A8.1);
 *   the check shown is the largest distance from the torus of the core's `sampleGrid` points.
 * - vase: a clamped cubic profile in the xz plane (points [x, z], handles held in y = 0),
 *   revolved by 360°; every drag frame sets the moved profile point in place and calls
 *   `sl.revolve` again (a new surface: the revolved net changes wholesale).
 * - extrude: the same profile laid into the xy plane (points [x, y] → (x, y, 0)), `sl.extrude`
 *   along `direction`, whose tip is a handle at P₀ + d.
 * - ruled: `sl.ruled` between a quadratic A and a cubic B (Bézier curves, free 3D points); the
 *   core raises A to degree 3 first (the net's first column), the rulings are the iso-curves
 *   at constant u, straight lines.
 * Everything drawn is what the core returns: meshes, iso-curves, nets, curves, evaluations.
 */
import { field } from "../lib/validate.js";
import {
  pointButtons,
  slider,
  choice,
  group,
  readout,
  shownWhen,
  INTEGER_SLIDER,
} from "../lib/panel.js";
import { fmt, fmtTex, pointTex, subscript, pointText, texListSeparator } from "../lib/format.js";
import { t, formatNumber } from "../lib/strings.js";
import { boundsOf3 } from "../lib/camera3d.js";
import { pointsPath3 } from "../lib/draw3d.js";
import { arrow } from "../lib/draw.js";
import { VECTOR_ARROW } from "../lib/probe-normal.js";
import { showGroup } from "../lib/surface-controls.js";
import { HUES, WIDTH, RADIUS, SECOND_CURVE, themed } from "../lib/theme.js";
import { flatNetPath, segmentPath3 } from "../lib/net-path3.js";
import {
  Construction,
  MODES,
  R_RANGE,
  torusDistance,
  GRID_CHECK,
  sciTex,
  sciText,
  weightTex,
} from "../lib/revolution-model.js";

export const id = "surface-revolution";
export const strings = "surfaceRevolution";
export const section = 6;

/** Mesh quads around the axis / along the curve, samples per drawn curve, iso-curves per direction. */
const MESH_U = 72;
const MESH_V = 36;
const CURVE_SAMPLES = 96;
const ISO_LINES = 8;
const RULINGS = 12;
/** The profile's control points: a clamped cubic with 5 to 7. */
const PROFILE_MIN = 5;
const PROFILE_MAX = 7;

export const defaultState = Object.freeze({
  mode: "vase",
  R: 3,
  r: 1,
  angle: 360,
  profile: [
    [0, 0],
    [2, 0],
    [2.8, 1.4],
    [0.9, 2.6],
    [1.1, 3.8],
    [2, 4.4],
  ],
  direction: [0.8, -0.6, 2.4],
  curveA: [
    [-3, -2.5, 0],
    [0, -2.5, 2.2],
    [3, -2.5, 0],
  ],
  curveB: [
    [-3, 2.5, 2.5],
    [-1, 2.5, -0.5],
    [1, 2.5, 3.5],
    [3, 2.5, 1],
  ],
  net: true,
  iso: true,
  wireframe: false,
});

export const fields = {
  mode: field.choice(MODES),
  R: field.number({ min: R_RANGE[0], max: R_RANGE[1] }),
  r: field.number({ min: 0.1, max: 3 }),
  angle: field.number({ min: 1, max: 360 }),
  profile: field.points({ min: PROFILE_MIN, max: PROFILE_MAX }),
  direction: field.numbers({ min: 3, max: 3 }),
  curveA: field.points3d({ min: 3, max: 3 }),
  curveB: field.points3d({ min: 4, max: 4 }),
  net: field.boolean(),
  iso: field.boolean(),
  wireframe: field.boolean(),
};

/** The fields the surface is made from (a change rebuilds it or moves it in place). */
const GEOMETRY = ["mode", "R", "r", "angle", "profile", "direction", "curveA", "curveB"];

/**
 * The construction in wasm: a dragged curve point is set in its curve in place (`moved`: the
 * list and the index), the direction's tip changes the extrusion; either makes the surface again.
 */
export const derive = {
  from: GEOMETRY,
  build: (s, sl) => ({ geo: new Construction(s, sl) }),
  moved: (m, index, xyz, s, ui, field) => m.geo.movePoint(s, field, index, ui),
  inPlace: { direction: (m, s, ui) => m.geo.remake(s, ui) },
};

const spaced = (a, b, n) => Float64Array.from({ length: n }, (_, k) => a + ((b - a) * k) / (n - 1));
const inner = (a, b, n) =>
  Float64Array.from({ length: n - 1 }, (_, k) => a + ((b - a) * (k + 1)) / n);

/** Iso-curves: meridians / rulings (constant u, running in v) and parallels (constant v). */
function isoCurves(s, surface) {
  const [u0, u1] = surface.domainU();
  const [v0, v1] = surface.domainV();
  if (s.mode === "ruled") {
    // Each ruling is straight (degree 1 in v): its two ends are the whole line.
    return Array.from(spaced(u0, u1, RULINGS + 1), (u) => surface.sampleGrid([u], [v0, v1]));
  }
  const us = spaced(u0, u1, CURVE_SAMPLES);
  const vs = spaced(v0, v1, CURVE_SAMPLES);
  return [
    ...Array.from(inner(u0, u1, ISO_LINES), (u) => surface.sampleGrid([u], vs)),
    ...Array.from(inner(v0, v1, ISO_LINES), (v) => surface.sampleGrid(us, [v])),
  ];
}

/** The numbers the lesson reports per mode, all from the core (published for the browser checks). */
function checks(s, d) {
  const surface = d.geo.surface;
  const [u0, u1] = surface.domainU();
  const [v0, v1] = surface.domainV();
  const u = (u0 + u1) / 2;
  switch (s.mode) {
    case "torus": {
      const grid = surface.sampleGrid(spaced(u0, u1, GRID_CHECK), spaced(v0, v1, GRID_CHECK));
      return { distance: torusDistance(grid, s.R, s.r) };
    }
    case "extrude":
      return { u, s0: surface.evaluate(u, v0), s1: surface.evaluate(u, v1) };
    case "ruled":
      return {
        u,
        a: d.geo.curves[0].evaluate(u),
        b: d.geo.curves[1].evaluate(u),
        mid: surface.evaluate(u, 0.5),
      };
    default:
      return {};
  }
}

export const compute = {
  mesh: [
    GEOMETRY,
    (s, d) => {
      const start = performance.now();
      const mesh = d.geo.surface.tessellate(MESH_U, MESH_V);
      d.geo.timing.mesh = performance.now() - start;
      return mesh;
    },
  ],
  isoCurves: [GEOMETRY, (s, d) => isoCurves(s, d.geo.surface)],
  net: [
    GEOMETRY,
    (s, d) => {
      const surface = d.geo.surface;
      return {
        points: surface.controlPoints(),
        weights: surface.weights(),
        rows: surface.rows,
        cols: surface.cols,
      };
    },
  ],
  curveSamples: [GEOMETRY, (s, d) => d.geo.curves.map((c) => c.sampleUniform(CURVE_SAMPLES))],
  checks: [GEOMETRY, checks],
  // The axis of revolution (z), drawn a quarter of the height beyond the surface's ends.
  axis: [
    GEOMETRY,
    (s) => {
      if (s.mode !== "torus" && s.mode !== "vase") return null;
      const [, , z0, , , z1] = figure3d.bounds(s);
      const pad = 0.25 * (z1 - z0 || 1);
      return [z0 - pad, z1 + pad];
    },
  ],
};

/** The mode buttons; a new mode fits the camera to its surface (and the URL keeps that camera). */
const modeChoice = choice("mode", {
  options: MODES.map((value) => ({ value, label: `surfaceRevolution.mode.${value}` })),
  set: (ui, value) => {
    ui.set("mode", value);
    ui.fit();
  },
});

/** The line of the readout under the mode: the check of the current mode, in words. */
function checkText(s, d) {
  const c = d.checks;
  const net = { rows: d.net.rows, cols: d.net.cols };
  switch (s.mode) {
    case "torus":
      return t("surfaceRevolution.check.torus", { ...net, distance: sciText(c.distance) });
    case "vase":
      return t("surfaceRevolution.check.vase", {
        ...net,
        revolve: formatNumber(d.geo.timing.surface),
        mesh: formatNumber(d.geo.timing.mesh),
      });
    case "extrude":
      return t("surfaceRevolution.check.extrude", {
        ...net,
        d: triple(c.s1.map((x, k) => x - c.s0[k])),
      });
    default:
      return t("surfaceRevolution.check.ruled", { ...net, mid: triple(c.mid) });
  }
}

const list = (p) => Array.from(p, (x) => String(x)).join(",");

/** Exact numbers for tests (`data-*` on the readout): the net's size and the mode's check. */
function checkData(s, d) {
  const c = d.checks;
  return {
    rows: String(d.net.rows),
    cols: String(d.net.cols),
    distance: s.mode === "torus" ? String(c.distance) : null,
    s0: c.s0 ? list(c.s0) : null,
    s1: c.s1 ? list(c.s1) : null,
    a: c.a ? list(c.a) : null,
    b: c.b ? list(c.b) : null,
    mid: c.mid ? list(c.mid) : null,
    u: c.u === undefined ? null : String(c.u),
  };
}

const isTorus = (s) => s.mode === "torus";
const hasProfile = (s) => s.mode === "vase" || s.mode === "extrude";
const two = (x) => fmt(x, 2);

export const controls = [
  group("surfaceRevolution.control.mode", modeChoice),
  shownWhen(
    isTorus,
    group(
      null,
      slider("R", {
        label: "surfaceRevolution.control.R",
        min: 0.5,
        max: 6,
        step: 0.01,
        format: two,
      }),
      slider("r", {
        label: "surfaceRevolution.control.r",
        min: 0.1,
        max: 3,
        step: 0.01,
        format: two,
      }),
      slider("angle", {
        label: "surfaceRevolution.control.angle",
        min: 1,
        max: 360,
        ...INTEGER_SLIDER,
      }),
    ),
  ),
  shownWhen(
    hasProfile,
    group(
      null,
      pointButtons("profile", { min: PROFILE_MIN, max: PROFILE_MAX, prefix: "surfaceRevolution" }),
    ),
  ),
  readout("check", checkText, { data: checkData }),
  showGroup(strings, ["net", "iso", "wireframe"]),
];

// ------------------------------------------------------------------ handles

const LABELS = new Map();
/** "P₂", "A₁" (made once). */
const labelOf = (letter, i) => {
  const key = `${letter}${i}`;
  if (!LABELS.has(key)) LABELS.set(key, `${letter}${subscript(i)}`);
  return LABELS.get(key);
};

/**
 * The handles per mode (lib/handle-lists3d.js): vase — the profile [x, z] as (x, 0, z), held in
 * y = 0; extrude — the same points as (x, y, 0), held in z = 0, and the direction's tip at
 * P₀ + d (free); torus — the circle's centre (R, 0, 0), held in y = 0, its x sets R; ruled — the
 * points of A and B (free). + / Delete on a profile point go through its point buttons.
 */
const HANDLES = [
  {
    field: "profile",
    shownWhen: hasProfile,
    axes: (s) => (s.mode === "vase" ? [0, 2] : [0, 1]),
    label: (i) => labelOf("P", i),
  },
  {
    field: "direction",
    shownWhen: (s) => s.mode === "extrude",
    label: () => "d",
    at(s, out) {
      out[0] = s.profile[0][0] + s.direction[0];
      out[1] = s.profile[0][1] + s.direction[1];
      out[2] = s.direction[2];
    },
    place(s, x, y, z) {
      s.direction[0] = x - s.profile[0][0];
      s.direction[1] = y - s.profile[0][1];
      s.direction[2] = z;
    },
  },
  {
    field: "R",
    shownWhen: isTorus,
    label: () => "C",
    plane: () => [0, 1, 0, 0],
    at(s, out) {
      out[0] = s.R;
      out[1] = 0;
      out[2] = 0;
    },
    place(s, x) {
      s.R = Math.min(R_RANGE[1], Math.max(R_RANGE[0], Math.round(x * 100) / 100));
    },
  },
  { field: "curveA", shownWhen: (s) => s.mode === "ruled", label: (i) => labelOf("A", i) },
  { field: "curveB", shownWhen: (s) => s.mode === "ruled", label: (i) => labelOf("B", i) },
];

// ------------------------------------------------------------------ figure

export const figure3d = {
  handles: HANDLES,
  bounds(s) {
    switch (s.mode) {
      case "torus": {
        const out = s.R + s.r;
        return [-out, -out, -s.r, out, out, s.r];
      }
      case "vase": {
        const reach = Math.max(...s.profile.map((p) => Math.abs(p[0])));
        const zs = s.profile.map((p) => p[1]);
        return [-reach, -reach, Math.min(...zs), reach, reach, Math.max(...zs)];
      }
      case "extrude": {
        const base = s.profile.map(([x, y]) => [x, y, 0]);
        return boundsOf3([
          ...base,
          ...base.map(([x, y]) => [x + s.direction[0], y + s.direction[1], s.direction[2]]),
        ]);
      }
      default:
        return boundsOf3([...s.curveA, ...s.curveB]);
    }
  },
  // The profile (torus, vase: the meridian u = 0), the extruded curve (the edge v = 0) and A, B
  // (the edges v = 0, 1) lie on the surface's boundary: scene curves, depth-tested with it.
  scene: (s, d) => {
    const [first, second] = d.curveSamples;
    const curves = s.iso ? [...d.isoCurves] : [];
    curves.push({ points: first, colour: CURVE_COLOURS.first, width: WIDTH.curve });
    if (s.mode === "ruled")
      curves.push({ points: second, colour: CURVE_COLOURS.second, width: WIDTH.curve });
    return {
      surfaces: [d.mesh],
      wireframe: s.wireframe ? [{ mesh: d.mesh, grid: [MESH_U + 1, MESH_V + 1] }] : [],
      curves,
    };
  },
};

/**
 * The curves' colours on the blue surface: the profile / A orange (blue would not read on it),
 * B the second curve's bluish green; their control polygons on the 2D layer match.
 */
export const CURVE_COLOURS = Object.freeze({
  first: HUES.orange,
  second: SECOND_CURVE.curve.stroke,
});

const stylesFor = themed((theme) => ({
  raised: Object.freeze({
    fill: CURVE_COLOURS.first,
    stroke: theme.background,
    width: 1,
    radius: RADIUS.constructionPoint,
  }),
  secondPolygon: SECOND_CURVE.polygon,
  firstPolygon: Object.freeze({ ...theme.polygon, stroke: CURVE_COLOURS.first }),
}));

const a = new Float64Array(3);
const b = new Float64Array(3);

/** The 2D layer: the axis, the result's control net (dashed), the curves, the direction, handles. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  if (d.axis) {
    segmentPath3(r, v, 0, 0, d.axis[0], 0, 0, d.axis[1]);
    r.paint(theme.helper);
  }
  if (s.net) {
    flatNetPath(r, v, d.net.points, d.net.rows, d.net.cols);
    r.paint(theme.polygon);
  }
  // The curves themselves are scene curves (figure3d.scene): depth-tested with the surface.
  if (s.mode === "ruled") {
    pointsPath3(r, v, s.curveA);
    r.paint(styles.firstPolygon);
    pointsPath3(r, v, s.curveB);
    r.paint(styles.secondPolygon);
  }
  if (s.mode === "ruled") {
    // The compatibility step: the net's first column is A raised to degree 3 (A′₀ … A′₃).
    const { points, rows, cols } = d.net;
    for (let i = 0; i < rows; i++) {
      const k = 3 * i * cols;
      v.project(points[k], points[k + 1], points[k + 2], a);
      r.point(a[0], a[1], styles.raised);
    }
  }
  if (s.mode === "extrude") {
    const [x, y] = s.profile[0];
    v.project(x, y, 0, a);
    v.project(x + s.direction[0], y + s.direction[1], s.direction[2], b);
    arrow(r, a[0], a[1], b[0], b[1], VECTOR_ARROW);
  }
  d.handles.draw(r, v);
}

// ------------------------------------------------------------------ formula and label

const triple = (p) => pointText(Array.from(p, (x) => formatNumber(x)));
const texTriple = (p) => pointTex([p[0], p[1], p[2]]);

/** The weights of the net's first column, w_{i0}: the arcs' pattern (the profile's w_0 = 1). */
function arcWeights(d) {
  const { weights, rows, cols } = d.net;
  return Array.from({ length: rows }, (_, i) => weightTex(weights[i * cols])).join(
    texListSeparator(),
  );
}

export function formula(s, d) {
  const net = { rows: d.net.rows, cols: d.net.cols };
  switch (s.mode) {
    case "torus":
      return [
        t("surfaceRevolution.tex.circle", { R: fmtTex(s.R), r: fmtTex(s.r) }),
        t("surfaceRevolution.tex.revolve", { angle: fmtTex(s.angle, 0), ...net }),
        t("surfaceRevolution.tex.rational", { q: 2 }),
        t("surfaceRevolution.tex.weights", { weights: arcWeights(d) }),
        t("surfaceRevolution.tex.torusCheck", {
          R: fmtTex(s.R),
          r: fmtTex(s.r),
          n: GRID_CHECK,
          distance: sciTex(d.checks.distance),
        }),
      ];
    case "vase":
      return [
        t("surfaceRevolution.tex.profile", { n: s.profile.length - 1 }),
        t("surfaceRevolution.tex.revolveVase", net),
        t("surfaceRevolution.tex.vaseNet"),
        t("surfaceRevolution.tex.rational", { q: 3 }),
        t("surfaceRevolution.tex.weights", { weights: arcWeights(d) }),
      ];
    case "extrude": {
      const c = d.checks;
      return [
        t("surfaceRevolution.tex.extrude", { d: texTriple(s.direction) }),
        t("surfaceRevolution.tex.extrudeNet", net),
        t("surfaceRevolution.tex.extrudeCheck", {
          u: fmtTex(c.u),
          d: texTriple(c.s1.map((x, k) => x - c.s0[k])),
        }),
      ];
    }
    default: {
      const c = d.checks;
      return [
        t("surfaceRevolution.tex.ruled"),
        t("surfaceRevolution.tex.ruledNet", net),
        t("surfaceRevolution.tex.ruledCheck", {
          u: fmtTex(c.u),
          a: texTriple(c.a),
          b: texTriple(c.b),
          mid: texTriple(c.mid),
        }),
      ];
    }
  }
}

export function label(s, d) {
  return t(`surfaceRevolution.aria.${s.mode}`, {
    rows: d.net.rows,
    cols: d.net.cols,
    R: fmt(s.R, 2),
    r: fmt(s.r, 2),
    angle: fmt(s.angle, 0),
    count: s.profile.length,
  });
}
