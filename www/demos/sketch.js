/**
 * Demo (syllabus §7 "Interactive design", issue 25): "a curve more or less like this". Draw a
 * stroke with a mouse, pen or finger; on release the core fits it (`fitCurveReport`: cubic
 * Bézier pieces, as few as keep every sample within the tolerance ε, corners kept as G⁰ joints,
 * the others G¹ or C¹; or `fitBSplineReport`: a B-spline of degree p with the fewest control
 * points), drawn over the ghosted stroke:
 *
 *   every sample p_j:  dist(p_j, C) ≤ ε,   ε = (tolerance in px) / (px per unit).
 *
 * The fit's decisions are shown on request: the corners (with the turn there), the split
 * points, each piece's measured largest error and the sample where it is reached, the control
 * polygons, and a curvature comb (κ from C′ and C″: is it fair? where does κ jump?). The curve
 * is edited without starting over: drag a control point (a joint carries its neighbours, a
 * smooth joint stays smooth: lib/composite-handles.js), or draw over a part of it — a stroke
 * that starts on the curve replaces that part (`oversketchReport`), the rest does not move.
 * A stroke that ends where it began gives a closed curve.
 *
 * The state is the stroke (lib/stroke-code.js), the px per unit it was drawn at, the tolerance
 * in px, the output and the edits in order (oversketch strokes, handle moves): a link rebuilds
 * the same curve by replaying them. Sample strokes (presets/sketch.js) stand in for drawing.
 */
import { field } from "../lib/validate.js";
import {
  actions,
  checkbox,
  choice,
  group,
  readout,
  shownWhen,
  slider,
  INTEGER_SLIDER,
} from "../lib/panel.js";
import { t, tp } from "../lib/strings.js";
import { fmt, fmtMachine, fmtTex, subscript } from "../lib/format.js";
import { HUES, WIDTH, RADIUS, FONT_SIZE, themed } from "../lib/theme.js";
import { flatPath } from "../lib/draw.js";
import { distanceToPolyline } from "../lib/geometry.js";
import { errorText } from "../lib/core-errors.js";
import { Handles, pointLabel } from "../lib/handles.js";
import { decodeStroke, encodeStroke, gridExponent } from "../lib/stroke-code.js";
import { compositeHandles, moveCompositeHandle } from "../lib/composite-handles.js";
import { SketchPen } from "../lib/sketch-pen.js";
import { PRESET_NAMES, PRESET_SCALE, presetStroke } from "./presets/sketch.js";

export const id = "sketch";
export const strings = "sketch";
export const section = 7;

/** The outputs: Bézier pieces with G¹ or C¹ smooth joints, or one B-spline of degree p. */
export const OUTPUTS = Object.freeze(["G1", "C1", "bspline"]);
/** Tolerance range, screen px (at the px per unit the stroke was drawn at). */
export const MIN_TOLERANCE = 0.25;
export const MAX_TOLERANCE = 20;
/** B-spline degrees offered. */
export const MIN_DEGREE = 2;
export const MAX_DEGREE = 5;
/** Most samples of a stroke, and most edits kept. */
export const MAX_SAMPLES = 4000;
export const MAX_EDITS = 200;
/** A stroke starting this near the curve (CSS px; touch: the touch hit radius) oversketches. */
export const NEAR_PX = 12;
const NEAR_TOUCH_PX = 18;
/** Curve samples per piece (one `sampleUniform` per change), and the total's cap. */
const SAMPLES_PER_PIECE = 48;
const MAX_CURVE_SAMPLES = 6000;
/** Comb teeth per piece, and the longest tooth (CSS px at the stroke's scale). */
const COMB_PER_PIECE = 24;
const COMB_PX = 45;
/** The replaced part is highlighted this long after an oversketch (ms). */
const HIGHLIGHT_MS = 1600;

export const defaultState = Object.freeze({
  stroke: presetStroke("corners"),
  scale: PRESET_SCALE,
  tolerance: 2,
  output: "G1",
  degree: 3,
  edits: Object.freeze([]),
  corners: true,
  breaks: true,
  errors: false,
  polygon: true,
  comb: false,
  oversketch: true,
});

const strokeMessage = () => t("sketch.badStroke");
const decode = (text) => decodeStroke(text, { min: 2, max: MAX_SAMPLES, message: strokeMessage() });

/** The edits: `["o", stroke]` (an oversketch) or `["m", handle, x, y]` (a moved point). */
function checkEdits(state, name) {
  const edits = state[name];
  const bad = () => {
    throw new Error(t("sketch.badEdits"));
  };
  if (!Array.isArray(edits) || edits.length > MAX_EDITS) bad();
  for (const e of edits) {
    if (!Array.isArray(e)) bad();
    if (e[0] === "o" && e.length === 2) decode(e[1]);
    else if (
      e[0] !== "m" ||
      e.length !== 4 ||
      !Number.isInteger(e[1]) ||
      e[1] < 0 ||
      e[1] > 10 * MAX_SAMPLES ||
      !e.slice(2).every((v) => typeof v === "number" && Number.isFinite(v) && Math.abs(v) < 1e9)
    )
      bad();
  }
}

export const fields = {
  stroke: (state, name) => decode(state[name]),
  scale: field.number({ min: 1e-3, max: 1e6 }),
  tolerance: field.number({ min: MIN_TOLERANCE, max: MAX_TOLERANCE }),
  output: field.choice(OUTPUTS),
  degree: field.number({ min: MIN_DEGREE, max: MAX_DEGREE, integer: true }),
  edits: checkEdits,
  corners: field.boolean(),
  breaks: field.boolean(),
  errors: field.boolean(),
  polygon: field.boolean(),
  comb: field.boolean(),
  oversketch: field.boolean(),
};

const isBSpline = (s) => s.output === "bspline";

/** True when the flat points end where they begin (a closed composite: its seam is one handle). */
function endsAtStart(cps) {
  const n = cps.length;
  const size = 1 + Math.abs(cps[0]) + Math.abs(cps[1]);
  return n >= 4 && Math.hypot(cps[n - 2] - cps[0], cps[n - 1] - cps[1]) <= 1e-9 * size;
}

/** The handles of the model's curve and the flat control points they read. */
function handlesOf(m) {
  m.cps = m.curve.controlPoints();
  // A closed (periodic) B-spline repeats its first p points at the end: one handle each.
  m.wrap = m.bspline ? m.curve.wrapped : 0;
  if (m.bspline) m.map = null;
  else m.map = compositeHandles(Array.from(m.curve.degrees()), endsAtStart(m.cps));
}

/** Moves handle h to (x, y) in the model, in place. */
const at2 = new Float64Array(2);
function moveHandle(m, h, x, y) {
  if (m.bspline) {
    at2[0] = x;
    at2[1] = y;
    m.curve.setControlPoint(h, at2); // the core moves a wrapped copy too
    const distinct = m.cps.length / 2 - m.wrap;
    for (const j of h < m.wrap ? [h, h + distinct] : [h]) {
      m.cps[2 * j] = x;
      m.cps[2 * j + 1] = y;
    }
  } else {
    moveCompositeHandle(m.curve, m.map, m.cps, h, x, y);
  }
}

/** Where handle h's point is in the flat control points (a composite's joint is listed once). */
const handleAt = (m, h) => (m.bspline ? h : m.map.offset[m.map.piece[h]] + m.map.index[h]);

/** How many handles the model has. */
const handleCount = (m) => (m.bspline ? m.cps.length / 2 - m.wrap : m.map.count);

/**
 * The curve: the stroke fitted at ε = tolerance / scale, then the edits replayed in order
 * (an oversketch of a part, a moved point; a move of a point that no longer exists is skipped).
 */
export const derive = {
  from: ["stroke", "scale", "tolerance", "output", "degree"],
  build(s, sl) {
    const points = decode(s.stroke);
    const epsilon = s.tolerance / s.scale;
    const m = { points, epsilon, bspline: isBSpline(s), overs: [], replaced: null };
    if (m.bspline) {
      const fit = sl.fitBSplineReport(points, 2, s.degree, epsilon);
      m.curve = fit.curve;
      m.closed = fit.closed;
      m.report = { maxError: fit.maxError, worst: fit.worst, corners: [], pieces: [] };
    } else {
      const fit = sl.fitCurveReport(points, 2, epsilon, { continuity: s.output });
      m.curve = fit.curve;
      m.closed = fit.closed;
      m.report = { corners: fit.corners, breaks: fit.breaks, pieces: fit.pieces };
    }
    try {
      handlesOf(m);
      for (const e of s.edits) applyEdit(sl, m, e);
    } catch (err) {
      m.curve.free();
      throw err;
    }
    return m;
  },
};

/** One edit on the model: an oversketch (Bézier output) or a moved handle. */
function applyEdit(sl, m, e) {
  if (e[0] === "o") {
    if (m.bspline) return;
    const stroke = decode(e[1]);
    const over = sl.oversketchReport(m.curve, stroke, 2, m.epsilon);
    m.curve.free();
    m.curve = over.curve;
    m.overs.push(stroke);
    m.replaced = { first: over.newPieces[0], last: over.newPieces[1] };
    handlesOf(m);
  } else if (e[1] < handleCount(m)) {
    moveHandle(m, e[1], e[2], e[3]);
  }
}

/** Pieces of the model's curve (B-spline: its polynomial spans). */
function piecesOf(s, d) {
  return d.bspline ? Math.max(1, d.cps.length / 2 - s.degree) : d.curve.pieceCount;
}

/** The curve's samples (one call) and how many. */
function samplesOf(s, d) {
  const count = Math.min(MAX_CURVE_SAMPLES, SAMPLES_PER_PIECE * piecesOf(s, d) + 1);
  return d.curve.sampleUniform(count);
}

/**
 * The curvature comb: per piece, points C(t) with teeth along the normal, of length κ·L
 * (κ = (x′y″ − y′x″)/|C′|³ from the core's derivatives), drawn on the outer side (away from the
 * centre of curvature); L makes the largest tooth COMB_PX at the stroke's scale. Flat
 * [x, y, tipX, tipY, …] per tooth, and the number of teeth per piece.
 */
function combOf(s, d) {
  if (!s.comb) return null;
  const curve = d.curve;
  const [a, b] = d.bspline ? curve.domain() : [0, curve.pieceCount];
  const pieces = piecesOf(s, d);
  const per = COMB_PER_PIECE;
  const n = pieces * per;
  const out = new Float64Array(4 * n);
  const kappa = new Float64Array(n);
  const p = new Float64Array(2);
  const d1 = new Float64Array(2);
  const d2 = new Float64Array(2);
  let largest = 0;
  for (let k = 0; k < pieces; k++) {
    for (let j = 0; j < per; j++) {
      const q = k * per + j;
      const tt = a + ((b - a) * (k + j / (per - 1))) / pieces;
      curve.evaluateInto(Math.min(tt, b), p);
      curve.derivativeInto(Math.min(tt, b), 1, d1);
      curve.derivativeInto(Math.min(tt, b), 2, d2);
      const speed = Math.hypot(d1[0], d1[1]);
      const c = speed > 0 ? (d1[0] * d2[1] - d1[1] * d2[0]) / speed ** 3 : 0;
      kappa[q] = Number.isFinite(c) ? c : 0;
      largest = Math.max(largest, Math.abs(kappa[q]));
      out[4 * q] = p[0];
      out[4 * q + 1] = p[1];
      // The unit normal (−y′, x′)/|C′| points to the centre when κ > 0: teeth go the other way.
      out[4 * q + 2] = speed > 0 ? d1[1] / speed : 0;
      out[4 * q + 3] = speed > 0 ? -d1[0] / speed : 0;
    }
  }
  const length = largest > 0 ? COMB_PX / s.scale / largest : 0;
  for (let q = 0; q < n; q++) {
    out[4 * q + 2] = out[4 * q] + out[4 * q + 2] * kappa[q] * length;
    out[4 * q + 3] = out[4 * q + 1] + out[4 * q + 3] * kappa[q] * length;
  }
  return { teeth: out, per, pieces, largest };
}

const FIT = ["stroke", "scale", "tolerance", "output", "degree", "edits"];
export const compute = {
  samples: [FIT, samplesOf],
  comb: [[...FIT, "comb"], combOf],
  pieces: [FIT, piecesOf],
};

// ------------------------------------------------------------------ words

/** The fit's largest measured error in px, or NaN when the core did not measure it. */
function worstPx(s, d) {
  if (d.bspline) return d.report.maxError * s.scale;
  let worst = Number.NaN;
  for (const p of d.report.pieces) {
    if (Number.isFinite(p.maxError))
      worst = Number.isNaN(worst) ? p.maxError : Math.max(worst, p.maxError);
  }
  return worst * s.scale;
}

/** "1.3 px", or "not measured". */
const pxText = (v) =>
  Number.isFinite(v) ? t("sketch.px", { value: fmt(v, 2) }) : t("sketch.notMeasured");

/** The fit in one line: pieces, corners, largest error, closed, edited. */
function fitText(s, d) {
  const edited = s.edits.length > 0;
  const shape = t(d.closed ? "sketch.closed" : "sketch.open");
  const error = pxText(worstPx(s, d));
  const tolerance = fmt(s.tolerance, 2);
  const main = d.bspline
    ? t("sketch.fitBSpline", {
        p: s.degree,
        control: tp("sketch.controlPoints", handleCount(d)),
        error,
        tolerance,
        shape,
      })
    : t("sketch.fitPieces", {
        pieces: tp("sketch.pieces", d.pieces),
        corners: tp("sketch.corners", d.report.corners.length),
        error,
        tolerance,
        shape,
      });
  return edited ? `${main} ${t("sketch.edited")}` : main;
}

// ------------------------------------------------------------------ panel

/**
 * A new tolerance, output or degree refits the stroke and replays the oversketches; the moved
 * points are dropped (they belonged to pieces that the new fit does not have; undo has them).
 */
function refit(ui, field, value, final) {
  const edits = ui.state.edits;
  const kept = edits.filter((e) => e[0] === "o");
  if (kept.length !== edits.length) {
    ui.state.edits = kept;
    ui.touch("edits");
  }
  ui.set(field, value, final);
}

/** A sample stroke: drawn at the presets' scale, no edits; the figure fits it. */
function loadPreset(ui, name) {
  const next = {
    ...structuredClone(ui.state),
    stroke: presetStroke(name),
    scale: PRESET_SCALE,
    edits: [],
  };
  try {
    ui.replace(next, false);
    ui.fit();
  } catch (err) {
    ui.status(errorText(err), "error");
  }
}

export const controls = [
  group(
    "sketch.outputLegend",
    choice("output", {
      options: OUTPUTS.map((value) => ({ value, label: `sketch.output.${value}` })),
      set: (ui, value) => refit(ui, "output", value, true),
    }),
    shownWhen(
      isBSpline,
      slider("degree", {
        label: "sketch.control.degree",
        min: MIN_DEGREE,
        max: MAX_DEGREE,
        ...INTEGER_SLIDER,
        onRelease: true,
        set: (ui, value, final) => refit(ui, "degree", value, final),
      }),
    ),
  ),
  group(
    null,
    slider("tolerance", {
      label: "sketch.control.tolerance",
      min: MIN_TOLERANCE,
      max: MAX_TOLERANCE,
      step: 0.05,
      format: (v) => fmt(v, 2),
      set: (ui, value, final) => refit(ui, "tolerance", value, final),
    }),
    readout("fit", fitText, {
      live: true,
      data: (s, d) => ({
        pieces: String(d.pieces),
        corners: String(d.report.corners.length),
        closed: String(d.closed),
        handles: String(handleCount(d)),
        maxErrorPx: Number.isFinite(worstPx(s, d)) ? fmtMachine(worstPx(s, d)) : "",
        edits: String(s.edits.length),
        replaced: d.replaced ? `${d.replaced.first},${d.replaced.last}` : "",
      }),
    }),
  ),
  group(
    "sketch.showLegend",
    // A B-spline has no corners or joints of its own to show.
    shownWhen((s) => !isBSpline(s), checkbox("corners", { label: "sketch.control.corners" })),
    shownWhen((s) => !isBSpline(s), checkbox("breaks", { label: "sketch.control.breaks" })),
    checkbox("errors", { label: "sketch.control.errors" }),
    checkbox("polygon", { label: "sketch.control.polygon" }),
    checkbox("comb", { label: "sketch.control.comb" }),
  ),
  group(
    null,
    checkbox("oversketch", { label: "sketch.control.oversketch" }),
    shownWhen(
      isBSpline,
      readout("oversketch-note", () => t("sketch.oversketchBezier")),
    ),
  ),
  actions(
    PRESET_NAMES.map((name) => ({
      name: `preset-${name}`,
      label: `sketch.preset.${name}`,
      run: (ui) => loadPreset(ui, name),
    })),
    { title: "sketch.control.presets" },
  ),
];

// ------------------------------------------------------------------ figure

/** The stroke's box and the control points', padded. */
export const figure = {
  bounds(s, d) {
    let x0 = Infinity;
    let y0 = Infinity;
    let x1 = -Infinity;
    let y1 = -Infinity;
    const grow = (flat) => {
      for (let k = 0; k + 1 < flat.length; k += 2) {
        x0 = Math.min(x0, flat[k]);
        x1 = Math.max(x1, flat[k]);
        y0 = Math.min(y0, flat[k + 1]);
        y1 = Math.max(y1, flat[k + 1]);
      }
    };
    grow(d.points);
    grow(d.cps);
    return [x0, y0, x1, y1];
  },
  help: "sketch.figureHelp",
};

const GHOST_STYLE = Object.freeze({
  stroke: HUES.skyBlue,
  width: 7,
  strokeAlpha: 0.35,
  join: "round",
  cap: "round",
});
const LIVE_STYLE = Object.freeze({
  stroke: HUES.vermillion,
  width: 2,
  join: "round",
  cap: "round",
});
const HIGHLIGHT_STYLE = Object.freeze({
  stroke: HUES.orange,
  width: WIDTH.highlightBand,
  strokeAlpha: 0.45,
  join: "round",
  cap: "round",
});
const COMB_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 1 });
const COMB_EDGE_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 1.5 });
const SPLIT_STYLE = Object.freeze({ fill: HUES.bluishGreen, radius: RADIUS.splitPoint });
const SPLIT_IN_HANDLE_STYLE = Object.freeze({ fill: HUES.bluishGreen, radius: 3 });
const CORNER_STYLE = Object.freeze({ stroke: HUES.vermillion, width: 2 });
const WORST_STYLE = Object.freeze({ fill: HUES.vermillion, radius: RADIUS.constructionPoint });
const labelStyles = themed((theme) => ({
  corner: Object.freeze({
    fill: HUES.vermillion,
    size: FONT_SIZE.small,
    weight: "bold",
    halo: theme.background,
  }),
  error: Object.freeze({ fill: theme.text, size: FONT_SIZE.small, halo: theme.background }),
}));
/** Where the error labels of one frame went (canvas px, made once), and their least spacing. */
const LABELS_AT = new Float64Array(2 * 256);
const LABEL_SPACING_PX = 36;
/** Half the side of a corner's square mark, CSS px. */
const CORNER_HALF_PX = 6;

/** The flat points [from, to] of `flat` as one path. */
function strokePath(r, v, flat) {
  r.beginPath();
  r.moveTo(v.sx(flat[0]), v.sy(flat[1]));
  for (let k = 2; k + 1 < flat.length; k += 2) r.lineTo(v.sx(flat[k]), v.sy(flat[k + 1]));
}

/** The control polygon of each piece (or the B-spline's). */
function polygonPath(r, v, d) {
  const cps = d.cps;
  r.beginPath();
  if (d.bspline) {
    r.moveTo(v.sx(cps[0]), v.sy(cps[1]));
    for (let k = 2; k < cps.length; k += 2) r.lineTo(v.sx(cps[k]), v.sy(cps[k + 1]));
    return;
  }
  const { offset } = d.map;
  for (let k = 0; k + 1 < offset.length; k++) {
    const j = 2 * offset[k];
    r.moveTo(v.sx(cps[j]), v.sy(cps[j + 1]));
    for (let i = offset[k] + 1; i < offset[k + 1]; i++)
      r.lineTo(v.sx(cps[2 * i]), v.sy(cps[2 * i + 1]));
  }
}

/** The comb: teeth, and the line through their tips, broken at every joint. */
function drawComb(r, v, comb) {
  const { teeth, per, pieces } = comb;
  r.beginPath();
  for (let q = 0; q < per * pieces; q++) {
    r.moveTo(v.sx(teeth[4 * q]), v.sy(teeth[4 * q + 1]));
    r.lineTo(v.sx(teeth[4 * q + 2]), v.sy(teeth[4 * q + 3]));
  }
  r.paint(COMB_STYLE);
  r.beginPath();
  for (let k = 0; k < pieces; k++) {
    for (let j = 0; j < per; j++) {
      const q = k * per + j;
      const x = v.sx(teeth[4 * q + 2]);
      const y = v.sy(teeth[4 * q + 3]);
      if (j === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
  }
  r.paint(COMB_EDGE_STYLE);
}

/** The report's marks, for an unedited fit: corners, worst samples. */
function drawReport(r, v, s, d) {
  const labels = labelStyles(r.theme);
  const pts = d.points;
  if (s.corners) {
    const half = CORNER_HALF_PX * r.scale;
    for (const c of d.report.corners) {
      const x = v.sx(pts[2 * c.index]);
      const y = v.sy(pts[2 * c.index + 1]);
      r.beginPath();
      r.rect(x - half, y - half, 2 * half, 2 * half);
      r.paint(CORNER_STYLE);
      if (Number.isFinite(c.angle))
        r.text(
          `${Math.round((c.angle * 180) / Math.PI)}°`,
          x + half + 3 * r.scale,
          y - half,
          labels.corner,
          "left",
          "bottom",
        );
    }
  }
  if (s.errors) {
    const worst = d.bspline
      ? [{ maxError: d.report.maxError, worst: d.report.worst }]
      : d.report.pieces;
    let placed = 0;
    for (const p of worst) {
      if (!Number.isFinite(p.maxError) || !(p.worst >= 0 && 2 * p.worst + 1 < pts.length)) continue;
      const x = v.sx(pts[2 * p.worst]);
      const y = v.sy(pts[2 * p.worst + 1]);
      r.point(x, y, WORST_STYLE);
      // A label too near one already written is left out (tiny pieces): the dot stays.
      let free = true;
      for (let q = 0; q < placed && free; q++)
        free =
          Math.hypot(x - LABELS_AT[2 * q], y - LABELS_AT[2 * q + 1]) > LABEL_SPACING_PX * r.scale;
      if (!free) continue;
      if (placed < LABELS_AT.length / 2) {
        LABELS_AT[2 * placed] = x;
        LABELS_AT[2 * placed + 1] = y;
        placed++;
      }
      r.text(
        t("sketch.px", { value: fmt(p.maxError * s.scale, 1) }),
        x + 6 * r.scale,
        y + 6 * r.scale,
        labels.error,
        "left",
        "top",
      );
    }
  }
}

/**
 * Ghosted strokes, the comb, polygons, the replaced part, the curve, the report's marks, the
 * handles, the split points, the stroke being drawn.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  strokePath(r, v, d.points);
  r.paint(GHOST_STYLE);
  for (const over of d.overs) {
    strokePath(r, v, over);
    r.paint(GHOST_STYLE);
  }
  if (d.comb) drawComb(r, v, d.comb);
  if (s.polygon) {
    polygonPath(r, v, d);
    r.paint(theme.polygon);
  }
  const fresh = d.replaced && d.highlightUntil > performance.now();
  if (fresh && !d.bspline) {
    const per = d.samples.length / 2 / d.pieces;
    const from = Math.floor(d.replaced.first * per);
    const to = Math.min(d.samples.length / 2, Math.ceil(d.replaced.last * per) + 1);
    if (to > from + 1) {
      flatPath(r, v, d.samples, from, to);
      r.paint(HIGHLIGHT_STYLE);
    }
  }
  flatPath(r, v, d.samples);
  r.paint(theme.curve);
  if (s.polygon) d.handles?.draw(r, v);
  if (s.edits.length === 0) drawReport(r, v, s, d);
  // The split points over the handles: a joint's handle gets a green centre.
  if (s.breaks && !d.bspline) {
    const { offset } = d.map;
    const cps = d.cps;
    const style = s.polygon ? SPLIT_IN_HANDLE_STYLE : SPLIT_STYLE;
    for (let k = 0; k < offset.length; k++) {
      const j = k === offset.length - 1 ? 2 * (offset[k] - 1) : 2 * offset[k];
      r.point(v.sx(cps[j]), v.sy(cps[j + 1]), style);
    }
  }
  d.pen?.draw(r, LIVE_STYLE);
}

// ------------------------------------------------------------------ formula, label

export function formula(s, d) {
  const eps = `\\varepsilon = ${fmtTex(s.tolerance, 2)}\\ \\text{px} = ${fmtTex(d.epsilon)}`;
  const worst = worstPx(s, d);
  const measured = Number.isFinite(worst)
    ? `\\max_j \\operatorname{dist}(p_j, C) = ${fmtTex(worst / s.scale)} \\le \\varepsilon`
    : `\\max_j \\operatorname{dist}(p_j, C) \\le \\varepsilon`;
  if (d.bspline) {
    const n = d.cps.length / 2 - 1;
    return [`C(u) = \\sum_{i=0}^{${n}} N_{i,${s.degree}}(u)\\, P_i`, eps, measured];
  }
  return [
    `C(t) = \\sum_{i=0}^{3} B_{i,3}(t - k)\\, P_{k,i}`,
    `t \\in [k, k+1],\\quad k = 0, \\dots, ${d.pieces - 1}`,
    eps,
    measured,
  ];
}

export function label(s, d) {
  return t("sketch.aria", { fit: fitText(s, d) });
}

// ------------------------------------------------------------------ drawing and dragging

/** "piece 2, P₁" (cached per handle). */
function handleName(d, h) {
  if (d.bspline) return pointLabel(h);
  return t("sketch.handle", { piece: d.map.piece[h] + 1, name: `P${subscript(d.map.index[h])}` });
}

/**
 * The pen (a new stroke, or an oversketch when it starts on the curve) and the handles on the
 * model's control points; a drag records `["m", handle, x, y]` (one edit per drag of a handle).
 */
export function setup(ui) {
  const view = ui.view;
  const data = ui.data;
  let dragged = -1;
  const handles = new Handles(view, {
    count: () => (ui.state.polygon ? handleCount(data) : 0),
    get: (h, out) => {
      const j = 2 * handleAt(data, h);
      out[0] = data.cps[j];
      out[1] = data.cps[j + 1];
    },
    label: (h) => (h === handles.selected || h === handles.dragging ? handleName(data, h) : ""),
    move(h, x, y) {
      moveHandle(data, h, x, y);
      const edits = ui.state.edits;
      const last = edits[edits.length - 1];
      if (dragged === h && last && last[0] === "m" && last[1] === h) {
        last[2] = x;
        last[3] = y;
      } else if (edits.length < MAX_EDITS) {
        edits.push(["m", h, x, y]);
        dragged = h;
      }
      ui.touch("edits");
    },
    commit: (kind, h, merge) => {
      ui.commit(merge);
      if (kind === "drag") dragged = -1;
    },
    polygon: false,
  });
  ui.handles = handles;
  data.handles = handles;

  const pen = new SketchPen(view, {
    done(px, pointerType) {
      if (px.length < 6) return; // a click, not a stroke
      const s = ui.state;
      const world = new Float64Array(px.length);
      for (let k = 0; k < px.length; k += 2) {
        world[k] = view.wx(px[k]);
        world[k + 1] = view.wy(px[k + 1]);
      }
      const near = pointerType === "touch" ? NEAR_TOUCH_PX : NEAR_PX;
      const onCurve =
        s.oversketch &&
        !isBSpline(s) &&
        s.edits.length < MAX_EDITS &&
        distanceToPolyline(world[0], world[1], data.samples) * view.scale <= near;
      const next = structuredClone(s);
      if (onCurve) {
        next.edits.push(["o", encodeStroke(world, gridExponent(s.scale))]);
      } else {
        next.stroke = encodeStroke(world, gridExponent(view.scale));
        next.scale = Number(view.scale.toPrecision(4));
        next.edits = [];
      }
      try {
        ui.replace(next);
        if (onCurve) {
          data.highlightUntil = performance.now() + HIGHLIGHT_MS;
          setTimeout(() => view.requestDraw(), HIGHLIGHT_MS + 50);
        }
      } catch (err) {
        ui.status(errorText(err), "error");
      }
    },
  });
  data.pen = pen;
  return {
    update() {
      data.pen = pen;
      data.handles = handles;
    },
    destroy() {
      handles.destroy();
    },
  };
}
