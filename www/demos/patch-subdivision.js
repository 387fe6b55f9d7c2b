/**
 * Demo (syllabus §6): subdivision of a Bézier patch, as the Greek notes give it. "Split at
 * (u0, v0)": `BezierSurface.split(u0, v0)` (de Casteljau on every row, then on the columns of
 * both halves) gives four patches of the same degrees, on [0, u0] × [0, v0], [0, u0] × [v0, 1],
 * [u0, 1] × [0, v0] and [u0, 1] × [v0, 1]; each is drawn with its own net and outline in its own
 * colour, all four meeting at S(u0, v0). "Adaptive": the notes' way of drawing a patch — if the
 * net is flat, draw the quad of its four corners, else split into four and do the same for each
 * piece — is `tessellateAdaptive(tolerance)`: the mesh and its triangle count, the wireframe, and
 * the quadtree in the (u, v) square. Nothing is computed here but a count read off the core's
 * mesh (its finest cell, from the uvs, for the uniform grid as fine everywhere).
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, choice, readout, group, shownWhen } from "../lib/panel.js";
import { fmt, subscript, fmtTex, pointTex, localeDecimal, texDecimal } from "../lib/format.js";
import { t, formatNumber } from "../lib/strings.js";
import { boundsOf3 } from "../lib/camera3d.js";
import { netPath } from "../lib/draw3d.js";
import { placeLabelFrom } from "../lib/handles.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";
import { HUES, WIDTH, RADIUS, POLYGON_DASH, themed } from "../lib/theme.js";
import { finestCell, drawParameterMesh, PARAMETER_INSET_PX } from "../lib/patch-quadtree.js";

export const id = "patch-subdivision";
export const strings = "patchSubdivision";
export const section = 6;

/** The net: 4 × 4 (bicubic), rows along u. */
const ROWS = 4;
const COLS = 4;
/** Quads per direction of each piece's mesh; samples along each piece's outline edge. */
const PIECE_MESH = 20;
const EDGE_SAMPLES = 32;
/** The tolerance slider's range (model units; the net spans 6 × 6 × 3) and resolution. */
export const MIN_TOLERANCE = 0.002;
export const MAX_TOLERANCE = 2;
const LOG_STEP = 0.01;
/** Slider values keep this many significant digits (short links); typed values as typed. */
const SLIDER_DIGITS = 2;

/**
 * Heights of a patch whose first two rows lie in the plane z = 0 and whose last two are wavy
 * (P_ij = (2i, 2j, h_ij)): the adaptive mesh stays coarse near u = 0, fine where it bends.
 */
const HEIGHTS = [
  [0, 0, 0, 0],
  [0, 0, 0, 0],
  [0, 0.6, 2.8, 1.2],
  [0.4, 1.6, 0.2, 2],
];

const NET = HEIGHTS.flatMap((row, i) => row.map((h, j) => [2 * i, 2 * j, h]));
/** The first camera: from the side of u = 1, high enough for all four pieces, low enough for the bump. */
const CAMERA = Object.freeze({ azimuth: -50, elevation: 30 });

export const defaultState = Object.freeze({
  points: NET,
  mode: "split",
  u0: 0.4,
  v0: 0.55,
  tolerance: 0.05,
  nets: true,
  quadtree: true,
});

const MODES = ["split", "adaptive"];

export const fields = {
  points: field.points3d({ rows: ROWS, cols: COLS }),
  mode: field.choice(MODES),
  u0: field.number({ min: 0, max: 1 }),
  v0: field.number({ min: 0, max: 1 }),
  tolerance: field.number({ min: MIN_TOLERANCE, max: MAX_TOLERANCE }),
  nets: field.boolean(),
  quadtree: field.boolean(),
};

export const derive = {
  from: ["points"],
  build: (s, sl) => ({
    patch: new sl.BezierSurface(Float64Array.from(s.points.flat()), ROWS, COLS),
  }),
  moved: (m, k, xyz) => m.patch.setControlPoint(Math.floor(k / COLS), k % COLS, xyz),
};

const SAMPLES = Float64Array.from({ length: EDGE_SAMPLES }, (_, k) => k / (EDGE_SAMPLES - 1));
const ZERO = [0];
const ONE = [1];

/**
 * The outline of a piece as one closed polyline (flat xyz): its four boundary curves from the
 * core (`sampleGrid` on the piece), v = 0 then u = 1 then v = 1 backwards then u = 0 backwards.
 */
function outlineOf(piece) {
  const bottom = piece.sampleGrid(SAMPLES, ZERO);
  const right = piece.sampleGrid(ONE, SAMPLES);
  const top = piece.sampleGrid(SAMPLES, ONE);
  const left = piece.sampleGrid(ZERO, SAMPLES);
  const n = EDGE_SAMPLES;
  const out = new Float64Array(4 * 3 * n);
  out.set(bottom, 0);
  out.set(right, 3 * n);
  for (let k = 0; k < n; k++) {
    out.set(top.subarray(3 * (n - 1 - k), 3 * (n - k)), 3 * (2 * n + k));
    out.set(left.subarray(3 * (n - 1 - k), 3 * (n - k)), 3 * (3 * n + k));
  }
  return out;
}

/** The four pieces of `split(u0, v0)`: nets, meshes and outlines; the wasm pieces are freed. */
function piecesOf(patch, u0, v0) {
  const pieces = patch.split(u0, v0);
  try {
    return pieces.map((piece) => ({
      net: piece.controlPoints(),
      mesh: piece.tessellate(PIECE_MESH, PIECE_MESH),
      outline: outlineOf(piece),
    }));
  } finally {
    for (const piece of pieces) piece.free();
  }
}

/** The mesh of `tessellateAdaptive` with its counts (triangles; the uniform grid as fine). */
function adaptiveOf(patch, tolerance) {
  const mesh = patch.tessellateAdaptive(tolerance);
  const cells = Math.round(1 / finestCell(mesh));
  return { mesh, triangles: mesh.indices.length / 3, cells, uniform: 2 * cells * cells };
}

export const compute = {
  pieces: [
    ["points", "u0", "v0", "mode"],
    (s, d) => (s.mode === "split" ? piecesOf(d.patch, s.u0, s.v0) : null),
  ],
  point: [["points", "u0", "v0"], (s, d) => d.patch.evaluate(s.u0, s.v0)],
  adaptive: [
    ["points", "tolerance", "mode"],
    (s, d) => (s.mode === "adaptive" ? adaptiveOf(d.patch, s.tolerance) : null),
  ],
};

/** The shared corner of piece k: (1, 1), (1, 0), (0, 1), (0, 0) of its net, as "x,y,z". */
const CORNER = [ROWS * COLS - 1, (ROWS - 1) * COLS, COLS - 1, 0];
function cornersText(d) {
  if (!d.pieces) return null;
  return d.pieces
    .map(
      ({ net }, k) => `${net[3 * CORNER[k]]},${net[3 * CORNER[k] + 1]},${net[3 * CORNER[k] + 2]}`,
    )
    .join(" ");
}

function countText(s, d) {
  if (s.mode === "split") return t("patchSubdivision.splitNote", { u: fmt(s.u0), v: fmt(s.v0) });
  const a = d.adaptive;
  return t("patchSubdivision.counts", {
    triangles: formatNumber(a.triangles),
    uniform: formatNumber(a.uniform),
    n: a.cells,
    tolerance: formatNumber(s.tolerance, { maximumSignificantDigits: 3 }),
  });
}

export const controls = [
  group(
    "patchSubdivision.control.mode",
    choice("mode", {
      options: [
        { value: "split", label: "patchSubdivision.control.split" },
        { value: "adaptive", label: "patchSubdivision.control.adaptive" },
      ],
    }),
  ),
  shownWhen(
    (s) => s.mode === "split",
    group(
      null,
      slider("u0", { label: "patchSubdivision.control.u0", min: 0, max: 1, step: 0.001 }),
      slider("v0", { label: "patchSubdivision.control.v0", min: 0, max: 1, step: 0.001 }),
      checkbox("nets", { label: "patchSubdivision.control.nets" }),
    ),
  ),
  shownWhen(
    (s) => s.mode === "adaptive",
    group(
      null,
      slider("tolerance", {
        label: "patchSubdivision.control.tolerance",
        inputParams: { min: MIN_TOLERANCE, max: MAX_TOLERANCE },
        min: MIN_TOLERANCE,
        max: MAX_TOLERANCE,
        step: LOG_STEP,
        log: true,
        format: (v) => localeDecimal(String(Number(v.toPrecision(3)))),
        round: (v, typed) =>
          typed
            ? v
            : Math.min(
                MAX_TOLERANCE,
                Math.max(MIN_TOLERANCE, Number(v.toPrecision(SLIDER_DIGITS))),
              ),
        error: "patchSubdivision.badTolerance",
      }),
      checkbox("quadtree", { label: "patchSubdivision.control.quadtree" }),
    ),
  ),
  group(
    null,
    readout("counts", countText, {
      data: (s, d) => ({
        triangles: d.adaptive ? String(d.adaptive.triangles) : null,
        uniform: d.adaptive ? String(d.adaptive.uniform) : null,
        corners: cornersText(d),
        point: `${d.point[0]},${d.point[1]},${d.point[2]}`,
      }),
    }),
  ),
];

const LABELS = [];
const netLabel = (k) => (LABELS[k] ??= `P${subscript(Math.floor(k / COLS))}${subscript(k % COLS)}`);

/**
 * The four pieces' colours, Okabe–Ito: the two pairs that share only the corner S(u0, v0)
 * (pieces 0 and 3, 1 and 2) hold the two warm hues, so pieces that share an edge differ most.
 */
export const PIECE_HUES = [HUES.orange, HUES.bluishGreen, HUES.reddishPurple, HUES.vermillion];

/** The outlines are darker than their piece (a line in the piece's own colour would not show). */
const OUTLINE_HUES = ["#9A6A00", "#00604A", "#8A4A6E", "#8F3F00"];

export const figure3d = {
  bounds: (s) => boundsOf3(s.points),
  camera: CAMERA,
  handles: { field: "points", label: (k) => netLabel(k) },
  // Split: each piece lit in its colour, its outline a scene curve (depth-tested with the
  // surface); adaptive: the mesh and its triangle edges.
  scene: (s, d) =>
    s.mode === "split"
      ? {
          surfaces: d.pieces.map((p, k) => ({ mesh: p.mesh, colour: PIECE_HUES[k] })),
          wireframe: [],
          curves: d.pieces.map((p, k) => ({
            points: p.outline,
            colour: OUTLINE_HUES[k],
            width: WIDTH.curve,
          })),
        }
      : { surfaces: [d.adaptive.mesh], wireframe: [{ mesh: d.adaptive.mesh }], curves: [] },
};

const stylesFor = themed((theme) => ({
  net: PIECE_HUES.map((stroke) =>
    Object.freeze({ stroke, width: WIDTH.polygon, dash: POLYGON_DASH }),
  ),
  netPoint: PIECE_HUES.map((fill) =>
    Object.freeze({ fill, stroke: theme.background, width: 1, radius: RADIUS.constructionPoint }),
  ),
}));

const a = new Float64Array(3);
const q = new Float64Array(3);

/** The net of piece k (flat xyz, 4 × 4) as a path of its rows then its columns. */
function pieceNetPath(r, v, net) {
  r.beginPath();
  for (let pass = 0; pass < 2; pass++) {
    for (let i = 0; i < ROWS; i++) {
      for (let j = 0; j < COLS; j++) {
        const k = 3 * (pass === 0 ? i * COLS + j : j * COLS + i);
        v.project(net[k], net[k + 1], net[k + 2], q);
        if (j === 0) r.moveTo(q[0], q[1]);
        else r.lineTo(q[0], q[1]);
      }
    }
  }
}

/** Split: the pieces' nets and points, the shared corner (the pieces are WebGL); adaptive: the quadtree. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  netPath(r, v, s.points, ROWS, COLS);
  r.paint(theme.polygon);
  if (s.mode === "split") {
    if (s.nets) {
      d.pieces.forEach((piece, k) => {
        pieceNetPath(r, v, piece.net);
        r.paint(styles.net[k]);
        for (let i = 0; i < ROWS * COLS; i++) {
          v.project(piece.net[3 * i], piece.net[3 * i + 1], piece.net[3 * i + 2], q);
          r.point(q[0], q[1], styles.netPoint[k]);
        }
      });
    }
  } else if (s.quadtree) {
    drawParameterMesh(r, d.adaptive.mesh, PARAMETER_INSET_PX, {
      u: t("patchSubdivision.axisU"),
      v: t("patchSubdivision.axisV"),
    });
  }
  d.handles.draw(r, v);
  if (s.mode === "split") {
    const p = d.point;
    v.project(p[0], p[1], p[2], a);
    r.point(a[0], a[1], theme.pointOnCurve);
    // A phone leaves the name out: the formula gives S(u₀, v₀).
    if (v.width >= NARROW_CANVAS_PX * r.scale)
      placeLabelFrom(
        r,
        t("patchSubdivision.pointLabel"),
        a[0],
        a[1],
        a[0],
        a[1] - 1,
        theme.labelPoint,
        theme.pointOnCurve.radius * r.scale,
      );
  }
}

const triple = (p, k = 0) => pointTex([p[k], p[k + 1], p[k + 2]]);

export function formula(s, d) {
  if (s.mode === "split") {
    const params = { u: fmtTex(s.u0), v: fmtTex(s.v0) };
    const p = d.point;
    let gap = 0;
    for (const [k, { net }] of d.pieces.entries()) {
      const c = 3 * CORNER[k];
      gap = Math.max(gap, Math.hypot(net[c] - p[0], net[c + 1] - p[1], net[c + 2] - p[2]));
    }
    return [
      t("patchSubdivision.texPieces", params),
      t("patchSubdivision.texPoint", { ...params, point: triple(p) }),
      t("patchSubdivision.texCorner", {
        corner: triple(d.pieces[0].net, 3 * CORNER[0]),
        gap:
          gap === 0
            ? "0"
            : texDecimal(gap.toExponential(1)).replace(/e([+-]\d+)/, "\\cdot 10^{$1}"),
      }),
    ];
  }
  const a = d.adaptive;
  return [
    t("patchSubdivision.texFlat", {
      tolerance: formatNumber(s.tolerance, { maximumSignificantDigits: 3 }),
    }),
    t("patchSubdivision.texCounts", { triangles: a.triangles, uniform: a.uniform, n: a.cells }),
  ];
}

export function label(s, d) {
  if (s.mode === "split") {
    const [x, y, z] = d.point;
    return t("patchSubdivision.ariaSplit", {
      u: fmt(s.u0),
      v: fmt(s.v0),
      x: fmt(x, 2),
      y: fmt(y, 2),
      z: fmt(z, 2),
    });
  }
  return t("patchSubdivision.ariaAdaptive", {
    tolerance: formatNumber(s.tolerance, { maximumSignificantDigits: 3 }),
    triangles: d.adaptive.triangles,
    uniform: d.adaptive.uniform,
  });
}
