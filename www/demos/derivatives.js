/**
 * Demo (syllabus §2 "Derivatives", §1 velocity and acceleration): a draggable Bézier curve with
 * the point P(t), its velocity P′(t) (arrow), the normal, the osculating circle and the signed
 * curvature κ(t) = (x′y″ − y′x″) / |P′|³; beside it, in the same figure (so exports include it),
 * the hodograph — the curve of velocities, a Bézier curve of degree n − 1 with control points
 * n(P_{i+1} − P_i) — with the same vector P′(t) drawn from the hodograph's origin O (a handle of
 * its own). All numbers come from the core (`derivative`, `curvature`, `hodograph`, `arcLength`).
 */
import { NOTES_CUBIC } from "../lib/examples.js";
import { field } from "../lib/validate.js";
import { slider, pointButtons, readout, group } from "../lib/panel.js";
import {
  fmt,
  subscript,
  shortNumber as short,
  degreeName,
  exactFraction,
  exactNumbers,
  fmtTex,
  fractionTex,
  pointText,
  fmtMachine,
  localeDecimal,
  pointTex,
  texDecimal,
} from "../lib/format.js";
import { HUES, RADIUS, SECOND_CURVE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten } from "../lib/geometry.js";
import { placeLabel, placeLabelAtTip, placeLabelFrom } from "../lib/handles.js";
import { flatPath, pointsPath, arrow, drawCaption, vectorsPath } from "../lib/draw.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";
import { el, setText } from "../lib/controls.js";
import { namedRows, titledTable } from "../lib/table.js";

export const id = "derivatives";
export const strings = "derivatives";
export const section = 2;

/** Fewest and most control points (degree 2 … 8: the hodograph is then a curve, not a point). */
export const MIN_POINTS = 3;
export const MAX_POINTS = 9;
/** Points sampled along the curve and the hodograph (one `sampleUniform` each per change). */
const CURVE_SAMPLES = 256;
/** Length of the drawn unit normal, CSS px. */
const NORMAL_PX = 36;
/**
 * The osculating circle is left out when its radius exceeds this many times the size of the
 * control polygon (κ ≈ 0: "straight here").
 */
const STRAIGHT_RADIUS_FACTOR = 1e3;
/** Narrowest the hodograph's caption wraps to (CSS px at text scale 1). */
const HODOGRAPH_CAPTION_MIN_PX = 160;
/** Margin of the caption texts from the canvas edges and from the hodograph's box (CSS px). */
const TEXT_MARGIN_PX = 12;
/** Gap between an arrow's tip (or the normal's) and its label, CSS px. */
const ARROW_LABEL_GAP_PX = 4;

// Styles of this demo's own marks (theme hues are the same in light and dark mode).
const VELOCITY_STYLE = Object.freeze({
  stroke: HUES.vermillion,
  width: 2.5,
  cap: "round",
  join: "round",
});
const NORMAL_STYLE = Object.freeze({
  stroke: HUES.reddishPurple,
  width: 2,
  cap: "round",
  join: "round",
});
const CIRCLE_STYLE = Object.freeze({ stroke: HUES.orange, width: 1.5 });
const CENTRE_STYLE = Object.freeze({ fill: HUES.orange, radius: RADIUS.constructionPoint });
/** The hodograph's points, a little larger than construction points (they carry labels). */
const HODOGRAPH_POINT_STYLE = Object.freeze({
  ...SECOND_CURVE.point,
  radius: RADIUS.constructionPoint + 0.5,
});

/**
 * The worked example of the Greek notes (syllabus §2) at t = 3/4, where it bends most visibly
 * (κ ≈ −0.27, an osculating circle of radius ≈ 3.7); P′(0) = 3(P₁ − P₀) = (6, 6),
 * P′(1) = (6, −6); the hodograph (drawn at 1/3 scale) sits to the right with its origin O at (11, 2).
 */
export const defaultState = Object.freeze({
  points: NOTES_CUBIC,
  t: 0.75,
  hodographOrigin: Object.freeze([11, 2]),
});

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  t: field.number({ min: 0, max: 1 }),
  hodographOrigin: field.numbers({ min: 2, max: 2 }),
};

/** The curve, in wasm; a dragged point moves it in place. */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({ curve: new sl.BezierCurve(flatten(s.points), 2) }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/** What the core returns: the geometry of the curve and its hodograph, and the values at t. */
export const compute = {
  samples: [["points"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  hodograph: [["points"], (s, d) => hodographOf(d.curve)],
  whole: [["points"], (s, d) => wholeCurve(s, d.curve)],
  at: [["points", "t"], (s, d) => valuesAt(d.curve, s.t, d.whole)],
};

/** The hodograph's samples and control points n(P_{i+1} − P_i) (flat), and their box (with O). */
function hodographOf(curve) {
  const hodograph = curve.hodograph();
  try {
    const points = hodograph.controlPoints();
    const s = 1 / (points.length / 2); // drawn at 1/n scale: its control points are then the legs
    const box = [0, 0, 0, 0];
    for (let k = 0; k < points.length; k += 2) {
      box[0] = Math.min(box[0], s * points[k]);
      box[1] = Math.min(box[1], s * points[k + 1]);
      box[2] = Math.max(box[2], s * points[k]);
      box[3] = Math.max(box[3], s * points[k + 1]);
    }
    return { samples: hodograph.sampleUniform(CURVE_SAMPLES), points, scale: s, box };
  } finally {
    hodograph.free();
  }
}

/** What does not depend on t: the arc length, the end velocities, the size, the captions. */
function wholeCurve(s, curve) {
  const box = curve.boundingBox();
  const n = s.points.length - 1;
  return {
    arcLength: curve.arcLength(),
    d1At0: curve.derivative(0, 1),
    d1At1: curve.derivative(1, 1),
    polygonSize: Math.max(Math.hypot(box[2] - box[0], box[3] - box[1]), 1e-9),
    hodographCaption: t("derivatives.hodographCaption", { m: n - 1 }),
    scaleCaption: t("derivatives.scaleCaption", { n }),
  };
}

/** P(t), P′(t), P″(t) and the signed curvature κ(t); `straight` when 1/|κ| is beyond reason. */
function valuesAt(curve, tt, whole) {
  const kappa = curve.curvature(tt);
  const straight =
    Number.isFinite(kappa) && 1 / Math.abs(kappa) > STRAIGHT_RADIUS_FACTOR * whole.polygonSize;
  // Machine text (a decimal point) for the readout's data-kappa; shown and TeX forms from it.
  const kappaMachine = Number.isFinite(kappa) ? fmtMachine(kappa) : "∞";
  const radiusMachine = !Number.isFinite(kappa)
    ? "0"
    : straight
      ? "∞"
      : fmtMachine(1 / Math.abs(kappa));
  const kappaText = localeDecimal(kappaMachine);
  const radiusText = localeDecimal(radiusMachine);
  return {
    point: curve.evaluate(tt),
    d1: curve.derivative(tt, 1),
    d2: curve.derivative(tt, 2),
    kappa,
    straight,
    kappaMachine,
    kappaText,
    kappaTex: texDecimal(kappaMachine),
    radiusText,
    radiusTex: texDecimal(radiusMachine),
  };
}

/** The readout under "Curvature at t": the radius and the side of the centre, or why there is none. */
function radiusNote(at) {
  if (!Number.isFinite(at.kappa)) return t("derivatives.cusp");
  if (at.straight) return t("derivatives.straight");
  const side = t(at.kappa > 0 ? "derivatives.left" : "derivatives.right");
  return t("derivatives.radius", { r: at.radiusText, side });
}

export const controls = [
  group(null, slider("t", { label: "control.t", min: 0, max: 1, step: 0.001, player: true })),
  group(
    "derivatives.curvatureLegend",
    readout("curvature", (s, d) => t("derivatives.readout", { kappa: d.at.kappaText }), {
      kind: "readout",
      live: true,
      data: (s, d) => ({ kappa: d.at.kappaMachine }),
    }),
    readout("radius", (s, d) => radiusNote(d.at)),
    readout("arc-length", (s, d) => t("derivatives.length", { length: fmt(d.whole.arcLength) })),
  ),
  group(
    null,
    readout("degree", (s) =>
      t("derivatives.degree", { n: s.points.length - 1, count: s.points.length }),
    ),
    pointButtons("points", { min: MIN_POINTS, max: MAX_POINTS, prefix: strings }),
  ),
];

export const figure = {
  /** The control points and the hodograph's (drawn from O at 1/n scale), for "Fit". */
  bounds(s, d) {
    const [ox, oy] = s.hodographOrigin;
    const { box } = d.hodograph;
    const b = [ox + box[0], oy + box[1], ox + box[2], oy + box[3]];
    for (const [x, y] of s.points) {
      b[0] = Math.min(b[0], x);
      b[1] = Math.min(b[1], y);
      b[2] = Math.max(b[2], x);
      b[3] = Math.max(b[3], y);
    }
    return b;
  },
  handles: {
    field: "points",
    extra: [{ field: "hodographOrigin", label: "derivatives.originLabel" }],
  },
};

/** Labels "3(P₁−P₀)" of the hodograph's control points, made once per (n, i). */
const hodographLabels = [];
function hodographLabel(i, n) {
  return (hodographLabels[n * (MAX_POINTS + 1) + i] ??=
    `${n}(P${subscript(i + 1)}−P${subscript(i)})`);
}

/** Labels an arrow at its tip, continuing its direction. */
function labelAtTip(r, text, x0, y0, x1, y1, style) {
  placeLabelAtTip(r, text, x0, y0, x1, y1, ARROW_LABEL_GAP_PX * r.scale, style);
}

/**
 * The hodograph: axes through O, its caption, polygon, curve and labelled control points, and
 * the vector O → P′(t). On a phone its control points go unlabelled (the table lists them) and
 * the caption wraps.
 */
function drawHodograph(r, v, s, d) {
  const theme = r.theme;
  const n = s.points.length - 1;
  const [ox, oy] = s.hodographOrigin;
  const { points, samples, scale, box } = d.hodograph;
  const pad = 0.15 * Math.max(box[2] - box[0], box[3] - box[1], 1e-9);
  const left = v.sx(ox + box[0] - pad);
  const right = v.sx(ox + box[2] + pad);
  const top = v.sy(oy + box[3] + pad);
  r.beginPath();
  r.moveTo(left, v.sy(oy));
  r.lineTo(right, v.sy(oy));
  r.moveTo(v.sx(ox), v.sy(oy + box[1] - pad));
  r.lineTo(v.sx(ox), top);
  r.paint(theme.helper);
  const narrow = v.width < NARROW_CANVAS_PX * r.scale;
  const captionWidth = narrow
    ? Math.max(right - left, HODOGRAPH_CAPTION_MIN_PX * r.scale)
    : Infinity;
  const captionY = top - TEXT_MARGIN_PX * r.scale;
  drawCaption(
    r,
    d.whole.hodographCaption,
    left,
    captionY,
    theme.labelSmall,
    captionWidth,
    "bottom",
  );

  vectorsPath(r, v, points, n, ox, oy, scale);
  r.paint(SECOND_CURVE.polygon);
  vectorsPath(r, v, samples, CURVE_SAMPLES, ox, oy, scale);
  r.paint(SECOND_CURVE.curve);
  const cx = v.sx(ox + (box[0] + box[2]) / 2);
  const cy = v.sy(oy + (box[1] + box[3]) / 2);
  for (let i = 0; i < n; i++) {
    const x = v.sx(ox + scale * points[2 * i]);
    const y = v.sy(oy + scale * points[2 * i + 1]);
    r.point(x, y, HODOGRAPH_POINT_STYLE);
    if (narrow) continue;
    // Labelled away from the hodograph's middle.
    const radius = HODOGRAPH_POINT_STYLE.radius * r.scale;
    placeLabelFrom(r, hodographLabel(i, n), x, y, cx, cy, theme.labelSmall, radius);
  }
  // The hodograph at t is P′(t).
  const { d1 } = d.at;
  const hx = v.sx(ox + scale * d1[0]);
  const hy = v.sy(oy + scale * d1[1]);
  arrow(r, v.sx(ox), v.sy(oy), hx, hy, VELOCITY_STYLE);
  r.point(hx, hy, theme.pointOnCurve);
  labelAtTip(r, t("derivatives.velocityLabel"), v.sx(ox), v.sy(oy), hx, hy, theme.labelPoint);
}

/**
 * The osculating circle at P(t) (centre P + N/κ, N the unit tangent turned 90° counter-clockwise,
 * κ signed) with its radius, and the normal N; returns the caption to show instead when there is
 * no circle (straight, or a cusp), else null.
 */
function drawCurvature(r, v, d, px, py) {
  const { point, d1, kappa, straight } = d.at;
  const speed = Math.hypot(d1[0], d1[1]);
  if (!(speed > 0 && Number.isFinite(kappa))) return t("derivatives.cusp");
  const nx = -d1[1] / speed;
  const ny = d1[0] / speed;
  if (!straight) {
    const cx = v.sx(point[0] + nx / kappa);
    const cy = v.sy(point[1] + ny / kappa);
    r.beginPath();
    r.circle(cx, cy, v.scale / Math.abs(kappa));
    r.paint(CIRCLE_STYLE);
    r.beginPath();
    r.moveTo(px, py);
    r.lineTo(cx, cy);
    r.paint(r.theme.helper);
    r.point(cx, cy, CENTRE_STYLE);
  }
  const tipX = px + nx * NORMAL_PX * r.scale;
  const tipY = py - ny * NORMAL_PX * r.scale;
  arrow(r, px, py, tipX, tipY, NORMAL_STYLE);
  // Beside the tip, on the side the curve comes from (clear of the arrow and the circle).
  const gap = ARROW_LABEL_GAP_PX * r.scale;
  placeLabel(
    r,
    t("derivatives.normalLabel"),
    tipX,
    tipY,
    -d1[0] / speed,
    d1[1] / speed,
    gap,
    r.theme.labelSmall,
  );
  return straight ? t("derivatives.straight") : null;
}

/** The hodograph, then the curve with its polygon, the circle, the normal and the velocity at t. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  drawHodograph(r, v, s, d);
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);

  const { point, d1 } = d.at;
  const scale = d.hodograph.scale;
  const px = v.sx(point[0]);
  const py = v.sy(point[1]);
  const caption = drawCurvature(r, v, d, px, py);
  const vx = v.sx(point[0] + scale * d1[0]);
  const vy = v.sy(point[1] + scale * d1[1]);
  arrow(r, px, py, vx, vy, VELOCITY_STYLE);
  labelAtTip(r, t("derivatives.velocityLabel"), px, py, vx, vy, theme.labelPoint);

  d.handles.draw(r, v);
  r.point(px, py, theme.pointOnCurve);
  const speed = Math.hypot(d1[0], d1[1]);
  const radius = theme.pointOnCurve.radius * r.scale;
  if (speed > 0) {
    placeLabel(
      r,
      t("derivatives.pointLabel"),
      px,
      py,
      d1[1] / speed,
      d1[0] / speed,
      radius,
      theme.labelPoint,
    );
  }

  const margin = TEXT_MARGIN_PX * r.scale;
  const width = v.width - 2 * margin;
  drawCaption(
    r,
    d.whole.scaleCaption,
    margin,
    v.height - margin,
    theme.labelSmall,
    width,
    "bottom",
  );
  if (caption) drawCaption(r, caption, margin, margin, theme.labelBold, width, "top");
}

/**
 * P′(t) as n Σ B_i^{n−1}(t)(P_{i+1} − P_i) with the core's Bernstein weights, the end velocities,
 * P″(t), κ(t) with its numbers, and the arc length L = ∫|P′|; exact fractions when t is a simple
 * fraction and every input an integer.
 */
export function formula(s, d) {
  const pts = s.points;
  const n = pts.length - 1;
  const { d1, d2, kappa, straight, kappaTex, radiusTex } = d.at;
  const shortTex = (x) => short(x, true);
  const { d1At0, d1At1, arcLength } = d.whole;
  const num = exactNumbers(s.t, pts.flat());
  const value = (x, power) => {
    const f = num.exact ? exactFraction(x, num.exact.den ** power) : null;
    return f ? fractionTex(f) : shortTex(x);
  };
  const vec = (x, y, power) => pointTex([value(x, power), value(y, power)]);
  const legs = [];
  for (let i = 0; i < n; i++) {
    const b = num.value(d.sl.bernstein(n - 1, i, s.t), n - 1, true);
    legs.push(
      `${b}\\,${pointTex([shortTex(pts[i + 1][0] - pts[i][0]), shortTex(pts[i + 1][1] - pts[i][1])])}`,
    );
  }
  const tTex = num.param(true);
  const speed = fmtTex(Math.hypot(d1[0], d1[1]));
  const kappaLine = Number.isFinite(kappa)
    ? `\\kappa(t) = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{(${shortTex(d1[0])})(${shortTex(d2[1])}) - (${shortTex(d1[1])})` +
      `(${shortTex(d2[0])})}{{${speed}}^3} = ${kappaTex}${straight ? "" : `,\\quad \\rho = 1/|\\kappa| = ${radiusTex}`}`
    : `P'(t) = 0:\\ \\kappa = \\infty\\ \\text{(${t("derivatives.cuspShort")})}`;
  const lines = [
    `P'(t) = n\\sum_{i=0}^{n-1} B_i^{n-1}(t)\\,(P_{i+1} - P_i) = ${n}\\,\\big[${legs.join(" + ")}\\big] = ` +
      `${vec(d1[0], d1[1], n - 1)},\\quad t = ${tTex}`,
    `P'(0) = n(P_1 - P_0) = ${vec(d1At0[0], d1At0[1], 0)},\\qquad P'(1) = n(P_n - P_{n-1}) = ` +
      vec(d1At1[0], d1At1[1], 0),
    `P''(t) = n(n-1)\\sum_{i=0}^{n-2} B_i^{n-2}(t)\\,(P_{i+2} - 2P_{i+1} + P_i) = ` +
      vec(d2[0], d2[1], Math.max(n - 2, 0)),
    kappaLine,
    `L = \\int_0^1 |P'(t)|\\,dt = ${fmtTex(arcLength)}`,
  ];
  return lines.map((line) => line.replace(/\(-/g, "({-}"));
}

/** "cubic Bézier curve; t = 0.750; P(t) = …; velocity P′(t) = …; curvature κ = …". */
export function label(s, d) {
  const { point, d1, kappaText } = d.at;
  return t("derivatives.aria", {
    kind: degreeName(s.points.length - 1),
    t: fmt(s.t),
    x: fmt(point[0], 2),
    y: fmt(point[1], 2),
    dx: fmt(d1[0], 2),
    dy: fmt(d1[1], 2),
    kappa: kappaText,
  });
}

/** Rows of the table of values, by their `data-quantity` key. */
const QUANTITIES = ["point", "dp", "ddp", "kappa", "radius", "dp0", "dp1", "length"];
const pair = (p) => pointText([short(p[0]), short(p[1])]);

/** The table: the values at t, the end velocities, the arc length, the hodograph's points. */
export function setup(ui) {
  const { rows, cells } = namedRows("derivatives.row.", QUANTITIES, "quantity");
  const hodographBody = el("tbody");
  const { title, wrap } = titledTable("derivatives", {
    children: [el("tbody", {}, rows), hodographBody],
  });
  ui.ctx.slots.details.append(title, wrap);
  let hodographCells = [];

  function buildHodographRows(n) {
    hodographCells = [];
    const hodographRows = [];
    for (let i = 0; i < n; i++) {
      const cell = el("td", { dataset: { hodograph: String(i) } });
      hodographCells.push(cell);
      const name = t("derivatives.row.hodograph", { i: subscript(i), label: hodographLabel(i, n) });
      hodographRows.push(el("tr", {}, el("th", { scope: "row", text: name }), cell));
    }
    hodographBody.replaceChildren(...hodographRows);
  }

  return {
    update(s, d) {
      const { point, d1, d2, kappaText, radiusText } = d.at;
      setText(title, t("derivatives.tableCaption", { t: fmt(s.t) }));
      setText(cells.point, pointText([point[0], point[1]]));
      setText(cells.dp, pair(d1));
      setText(cells.ddp, pair(d2));
      setText(cells.kappa, kappaText);
      setText(cells.radius, radiusText);
      setText(cells.dp0, pair(d.whole.d1At0));
      setText(cells.dp1, pair(d.whole.d1At1));
      setText(cells.length, fmt(d.whole.arcLength));
      const n = s.points.length - 1;
      if (hodographCells.length !== n) buildHodographRows(n);
      const h = d.hodograph.points;
      for (let i = 0; i < n; i++) setText(hodographCells[i], pair([h[2 * i], h[2 * i + 1]]));
    },
  };
}
