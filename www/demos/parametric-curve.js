/**
 * Demo (syllabus §1 "Parametric curves", issue 24): a curve typed as formulas x(t), y(t) and
 * optionally z(t) on an interval [a, b] whose ends are formulas too ("2pi"). The curve library
 * parses and differentiates the texts (`sl.parametricCurve`); every other name in them
 * (`sl.expressionNames`) is a parameter with a slider, its value in the state and set in place
 * (`setParameter`). The point P(t) runs along the curve (player) with its velocity P′(t) and
 * acceleration P″(t), the speed |P′|, the curvature κ and the osculating circle; the hodograph
 * (the curve of velocities) is drawn from a draggable origin O beside it, as in derivatives.js.
 * The curve is drawn from the core's adaptive plot (`plot(tolerance, box)`: runs split where the
 * curve is undefined or jumps, e.g. at the poles of tan t), with a tolerance of a fraction of a
 * pixel in model units and the visible window as the box.
 *
 * A space curve (z given) is drawn in the same 2D figure through an orthographic view whose
 * azimuth and elevation are state fields (sliders; dragging the figure turns it): the runtime
 * chooses a 2D View or a three.js View3D once, when the demo is mounted, and the view's state
 * (`view`: a window or a camera) is the shell's, so one demo cannot switch between them. The
 * Frenet frame T, N, B comes from the core (`frame(t)`).
 *
 * A polynomial curve offers its exact Bézier form (`toBezier(0)`, `bezierFractions(0)`): the
 * control polygon on the same figure, the fractions listed, and a link into de-casteljau.
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, readout, group, actions } from "../lib/panel.js";
import {
  fmt,
  fmtTex,
  fmtMachine,
  localeDecimal,
  pointTex,
  pointText,
  shortNumber,
  subscript,
  texDecimal,
} from "../lib/format.js";
import { HUES, RADIUS, SECOND_CURVE, themed } from "../lib/theme.js";
import { locale, t } from "../lib/strings.js";
import { drawCaption } from "../lib/draw.js";
import { HIT_RADIUS_TOUCH, placeLabel, placeLabelAtTip, placeLabelFrom } from "../lib/handles.js";
import { buildHash } from "../lib/state.js";
import { withLanguage } from "../lib/language.js";
import { errorText } from "../lib/core-errors.js";
import { BEZIER_POINTS } from "../lib/point-list.js";
import { formulaFields, infoLine, parameterSliders, shownIf } from "../lib/expression-fields.js";
import {
  CLIP_MARGIN_PX,
  clippedArrow,
  depthOf,
  depthRunsPath,
  flatRunsPath,
  nearestParameter,
  niceScale,
  penOnCanvas,
  penStart,
  penTo,
  plotRuns,
  projectionOf,
  pu,
  pw,
  robustRange,
  scaleText,
  zAt,
} from "../lib/curve-view.js";

export const id = "parametric-curve";
export const strings = "parametricCurve";
export const section = 1;

/** The typed fields the curve is built from (a parameter's value is set in place). */
const TEXTS = ["x", "y", "z", "from", "to"];
const WITH_PARAMS = [...TEXTS, "params"];
/** The longest text the core parses (src/expr/mod.rs MAX_LENGTH). */
const MAX_TEXT = 1000;
/** Parameters a state may carry. */
const MAX_PARAMS = 16;
/** A parameter that appears in a new text starts at this value. */
const DEFAULT_PARAMETER = 1;
/** The plot follows the curve within this many CSS px (converted to model units). */
const PLOT_TOLERANCE_PX = 0.25;
/** The plot's box: the canvas in world units, widened by this fraction on each side. */
const PLOT_BOX_MARGIN = 0.1;
/** Samples for the figure's bounds and the hodograph (one derivative per sample and change). */
const BOUNDS_SAMPLES = 512;
const HODOGRAPH_SAMPLES = 256;
/** The hodograph's size as a fraction of the curve's (the scale λ is the nice number below). */
const HODOGRAPH_FRACTION = 0.35;
/** The hodograph's box reaches at most this many curve sizes from O. */
const HODOGRAPH_REACH = 0.6;
/** The speed the scale is made for: this quantile of |P′| over the samples. */
const SPEED_QUANTILE = 0.5;
/** Gap between the curve's box and the hodograph's, as a fraction of the curve's size. */
const HODOGRAPH_GAP = 0.3;
/** The osculating circle is left out beyond a radius of this many curve sizes (κ ≈ 0). */
const STRAIGHT_RADIUS_FACTOR = 1e4;
/** Vertices of the drawn osculating circle (a polygon through P(t), clipped to the canvas). */
const CIRCLE_VERTICES = 192;
/** Length of the Frenet frame's unit vectors on screen, CSS px (before foreshortening). */
const FRAME_PX = 60;
/** Axes of a space curve: this fraction of the curve's size. */
const AXIS_FRACTION = 0.45;
/** Degrees turned per CSS px of a drag on a space curve. */
const DEG_PER_PX = 0.4;
/** A press this near the drawn curve (CSS px, mouse) moves the point there. */
const PICK_RADIUS_PX = 8;
const MAX_ELEVATION = 89;
/** Margin of captions from the canvas edges and the hodograph, CSS px. */
const TEXT_MARGIN_PX = 12;
const ARROW_LABEL_GAP_PX = 4;
/** Opacity of the far half of a space curve. */
const FAR_ALPHA = 0.35;

const VELOCITY_STYLE = Object.freeze({
  stroke: HUES.vermillion,
  width: 2.5,
  cap: "round",
  join: "round",
});
const ACCELERATION_STYLE = Object.freeze({
  stroke: HUES.reddishPurple,
  width: 2,
  cap: "round",
  join: "round",
});
const BINORMAL_STYLE = Object.freeze({
  stroke: HUES.skyBlue,
  width: 2,
  cap: "round",
  join: "round",
});
const CIRCLE_STYLE = Object.freeze({ stroke: HUES.orange, width: 1.5 });
const CENTRE_STYLE = Object.freeze({ fill: HUES.orange, radius: RADIUS.constructionPoint });
/** The exact control points (not handles: they follow the formula), in the polygon's grey. */
const bezierPoint = themed((theme) => ({
  fill: theme.polygon.stroke,
  radius: RADIUS.constructionPoint,
}));
/** The far part of a space curve: the curve's style, faded. */
const farCurve = themed((theme) => ({ ...theme.curve, strokeAlpha: FAR_ALPHA }));

/** The examples: the notes' circle first. `t` is where the point starts. */
export const PRESETS = Object.freeze([
  { name: "circle", x: "cos(t)", y: "sin(t)", to: "2pi", t: 1 },
  { name: "ellipse", x: "a cos(t)", y: "b sin(t)", to: "2pi", params: { a: 2, b: 1 }, t: 1 },
  { name: "lissajous", x: "sin(a t)", y: "sin(b t)", to: "2pi", params: { a: 3, b: 2 }, t: 0.5 },
  { name: "cycloid", x: "t - sin(t)", y: "1 - cos(t)", to: "4pi", t: 2 },
  { name: "cardioid", x: "2cos(t) - cos(2t)", y: "2sin(t) - sin(2t)", to: "2pi", t: 1 },
  { name: "astroid", x: "cos(t)^3", y: "sin(t)^3", to: "2pi", t: 0.5 },
  { name: "spiral", x: "t cos(t)", y: "t sin(t)", to: "4pi", t: 8 },
  { name: "helix", x: "cos(t)", y: "sin(t)", z: "t/5", to: "4pi", t: 2 },
  { name: "tan", x: "t", y: "tan(t)", from: "-pi", to: "pi", t: 0.5 },
  {
    name: "polynomial",
    x: "6.5t^5 - 7.2t^3 + 3t^2 - 2.1t - 5",
    y: "t",
    to: "1",
    t: 0.5,
    bezier: true,
  },
]);

/** The circle x = cos t, y = sin t on [0, 2π] (syllabus §1), its hodograph to the right. */
export const defaultState = Object.freeze({
  x: "cos(t)",
  y: "sin(t)",
  z: "",
  from: "0",
  to: "2pi",
  params: Object.freeze({}),
  t: 1,
  bezier: false,
  hodograph: Object.freeze([Object.freeze([2.1, 0])]),
  azimuth: -60,
  elevation: 25,
});

/** A typed formula: a string the core may read (it checks the rest). */
function textField(state, name) {
  const value = state[name];
  if (typeof value !== "string" || value.length > MAX_TEXT || (name !== "z" && !value.trim()))
    throw new Error(t("parametricCurve.error.text", { field: name, max: MAX_TEXT }));
}

/** Parameter values: `{ name: number }`, a few short names. */
function paramsField(state, name) {
  const value = state[name];
  const ok =
    value !== null &&
    typeof value === "object" &&
    !Array.isArray(value) &&
    Object.keys(value).length <= MAX_PARAMS &&
    Object.entries(value).every(
      ([k, v]) => k.length > 0 && k.length <= 24 && typeof v === "number" && Number.isFinite(v),
    );
  if (!ok) throw new Error(t("parametricCurve.error.params"));
}

export const fields = {
  x: textField,
  y: textField,
  z: textField,
  from: textField,
  to: textField,
  params: paramsField,
  t: field.number({ min: -1e9, max: 1e9 }),
  bezier: field.boolean(),
  hodograph: field.points({ min: 1, max: 1 }),
  azimuth: field.number({ min: -180, max: 180 }),
  elevation: field.number({ min: -MAX_ELEVATION, max: MAX_ELEVATION }),
};

/** The refusal of a text names its field (`expressionNames` knows no field). */
function located(err, name) {
  if (err && typeof err === "object" && err.params && err.params.field === undefined) {
    try {
      err.params.field = name;
      err.params.piece = 0;
    } catch {
      // a frozen params object keeps its own fields
    }
  }
  return err;
}

/**
 * The core's curve of the texts; its parameters are the names the texts use, each with its
 * value in `params` or DEFAULT_PARAMETER (names no text uses are dropped). Throws the refusal.
 */
function curveOf(sl, s) {
  const params = {};
  for (const name of TEXTS) {
    if (name === "z" && !s.z.trim()) continue;
    let names;
    try {
      names = sl.expressionNames(s[name]);
    } catch (err) {
      throw located(err, name);
    }
    for (const p of names)
      params[p] = s.params && Object.hasOwn(s.params, p) ? s.params[p] : DEFAULT_PARAMETER;
  }
  const piece = { x: s.x, y: s.y, from: s.from, to: s.to };
  if (s.z.trim()) piece.z = s.z;
  return { curve: sl.parametricCurve([piece], params), params };
}

/** The curve in wasm; a parameter's slider sets it in place. */
export const derive = {
  from: TEXTS,
  build(s, sl, { first = false } = {}) {
    const { curve, params } = curveOf(sl, s);
    s.params = params;
    const domain = curve.domain();
    s.t = Math.min(Math.max(s.t, domain[0]), domain[1]);
    // A page or embed that gives another curve but no O: the hodograph goes beside that curve.
    const [o] = defaultState.hodograph;
    if (
      first &&
      s.hodograph[0][0] === o[0] &&
      s.hodograph[0][1] === o[1] &&
      TEXTS.some((name) => s[name] !== defaultState[name])
    ) {
      const proj = projectionOf(s.azimuth, s.elevation, curve.dim);
      s.hodograph = [originBeside(wholeCurve({ curve, proj, domain }))];
    }
    return { curve };
  },
  inPlace: {
    params(m, s) {
      for (const [name, value] of Object.entries(s.params)) m.curve.setParameter(name, value);
    },
  },
};

// ------------------------------------------------------------------ view and bounds

/**
 * What does not depend on t: the box of the curve in figure coordinates, the hodograph's
 * samples (the core's P′ at uniform t), its scale λ and its box around O.
 */
function wholeCurve(d) {
  const { curve, proj } = d;
  const { m } = proj;
  const dim = curve.dim;
  const [a, b] = d.domain;
  const samples = curve.sampleUniform(BOUNDS_SAMPLES);
  const us = [];
  const ws = [];
  let nearest = -Infinity;
  let farthest = Infinity;
  for (let k = 0; k + dim <= samples.length; k += dim) {
    const x = samples[k];
    const y = samples[k + 1];
    const z = zAt(samples, k, dim);
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
    us.push(pu(m, x, y, z));
    ws.push(pw(m, x, y, z));
    const here = depthOf(m, x, y, z);
    nearest = Math.max(nearest, here);
    farthest = Math.min(farthest, here);
  }
  const [u0, u1] = robustRange(us);
  const [w0, w1] = robustRange(ws);
  const box = [u0, w0, u1, w1];
  const size = Math.max(u1 - u0, w1 - w0, 1e-9);
  const hodograph = new Float64Array(HODOGRAPH_SAMPLES * dim);
  const speeds = [];
  const v = new Float64Array(dim);
  for (let k = 0; k < HODOGRAPH_SAMPLES; k++) {
    // The last sample exactly at b (a + (b − a) may round past it: outside the domain).
    const tk = k === HODOGRAPH_SAMPLES - 1 ? b : a + ((b - a) * k) / (HODOGRAPH_SAMPLES - 1);
    let ok = true;
    try {
      curve.derivativeInto(tk, 1, v);
    } catch {
      ok = false;
    }
    for (let c = 0; c < dim; c++) hodograph[k * dim + c] = ok ? v[c] : Number.NaN;
    const speed = ok ? Math.hypot(v[0], v[1], dim === 3 ? v[2] : 0) : Number.NaN;
    if (Number.isFinite(speed)) speeds.push(speed);
  }
  speeds.sort((p, q) => p - q);
  const typical = speeds.length ? speeds[Math.floor(SPEED_QUANTILE * (speeds.length - 1))] : 1;
  const lambda = niceScale((HODOGRAPH_FRACTION * size) / (typical || 1));
  // The hodograph's box relative to O (O included), from its scaled samples.
  const hu = [];
  const hw = [];
  for (let k = 0; k < HODOGRAPH_SAMPLES; k++) {
    const j = k * dim;
    const x = lambda * hodograph[j];
    const y = lambda * hodograph[j + 1];
    const z = lambda * zAt(hodograph, j, dim);
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
    hu.push(pu(m, x, y, z));
    hw.push(pw(m, x, y, z));
  }
  // At most HODOGRAPH_REACH curve sizes from O (the velocities near a pole run off).
  const reach = HODOGRAPH_REACH * size;
  const within = ([lo, hi]) => [
    Math.max(Math.min(lo, 0), -reach),
    Math.min(Math.max(hi, 0), reach),
  ];
  const [hu0, hu1] = within(robustRange(hu));
  const [hw0, hw1] = within(robustRange(hw));
  const hpad = 0.12 * Math.max(hu1 - hu0, hw1 - hw0, 1e-9);
  const hbox = [hu0 - hpad, hw0 - hpad, hu1 + hpad, hw1 + hpad];
  return {
    dim,
    box,
    size,
    depth: (nearest + farthest) / 2,
    hodograph,
    lambda,
    hbox,
    scaleCaption: t("parametricCurve.scaleCaption", { scale: scaleText(lambda) }),
    polynomial: curve.isPolynomial(0),
  };
}

/** The hodograph's origin O beside the curve: right of its box, level with its middle. */
function originBeside(whole) {
  const { box, hbox, size } = whole;
  const ox = box[2] + HODOGRAPH_GAP * size - hbox[0];
  const oy = (box[1] + box[3]) / 2 - (hbox[1] + hbox[3]) / 2;
  const round = (v) => Number(v.toPrecision(4));
  return [round(ox), round(oy)];
}

/** P(t), P′(t), P″(t) and the core's frame (curvature, torsion); `defined` false at a gap. */
function valuesAt(curve, tt, whole) {
  let point = null;
  let d1 = null;
  let d2 = null;
  let frame = null;
  try {
    point = curve.evaluate(tt);
    d1 = curve.derivative(tt, 1);
    d2 = curve.derivative(tt, 2);
    frame = curve.frame(tt);
  } catch {
    frame = null;
  }
  const finite = (v) => v?.every(Number.isFinite);
  const defined = finite(point) && finite(d1);
  const speed = defined ? Math.hypot(...d1) : Number.NaN;
  const cusp = defined && !(speed > 1e-12 * Math.max(1, whole.size));
  // At a cusp (P′ = 0) the curvature grows without bound: ∞, not the rounding's number.
  const kappa = cusp
    ? Number.POSITIVE_INFINITY
    : frame && Number.isFinite(frame.curvature)
      ? frame.curvature
      : Number.NaN;
  const straight =
    Number.isFinite(kappa) && !(Math.abs(kappa) * STRAIGHT_RADIUS_FACTOR * whole.size > 1);
  const kappaMachine = Number.isFinite(kappa) ? fmtMachine(kappa) : "∞";
  const tau = frame && Number.isFinite(frame.torsion) ? frame.torsion : Number.NaN;
  return {
    defined,
    point,
    d1,
    d2,
    frame: finite(frame?.tangent ?? null) ? frame : null,
    speed,
    kappa,
    cusp,
    straight,
    kappaMachine,
    kappaText: localeDecimal(kappaMachine),
    kappaTex: texDecimal(kappaMachine),
    tau,
  };
}

/** The exact Bézier form of a polynomial curve while it is asked for, else null. */
function bezierFormOf(s, d) {
  if (!s.bezier || !d.whole.polynomial) return null;
  const bezier = d.curve.toBezier(0);
  let points;
  try {
    points = bezier.controlPoints();
  } finally {
    bezier.free();
  }
  const dim = d.curve.dim;
  let fractions = null;
  try {
    fractions = d.curve.bezierFractions(0);
  } catch {
    fractions = null;
  }
  return { points, count: points.length / dim, dim, fractions };
}

export const compute = {
  // A bound may name a parameter ("2pi/a"): the domain follows the sliders too.
  domain: [WITH_PARAMS, (s, d) => d.curve.domain()],
  proj: [
    [...TEXTS, "azimuth", "elevation"],
    (s, d) => projectionOf(s.azimuth, s.elevation, d.curve.dim),
  ],
  whole: [[...WITH_PARAMS, "azimuth", "elevation"], (s, d) => wholeCurve(d)],
  tex: [TEXTS, (s, d) => d.curve.tex(0)],
  bezierForm: [[...WITH_PARAMS, "bezier"], (s, d) => bezierFormOf(s, d)],
  at: [
    [...WITH_PARAMS, "t"],
    (s, d) => valuesAt(d.curve, Math.min(Math.max(s.t, d.domain[0]), d.domain[1]), d.whole),
  ],
  /** The adaptive plot, made again in `draw` when the window changes (see `plotOf`). */
  plot: [WITH_PARAMS, () => ({ key: "", result: null })],
};

// ------------------------------------------------------------------ panel

/** A new state from typed texts, or the core's refusal (nothing changes). */
function withTexts(ui, texts) {
  const next = structuredClone(ui.state);
  Object.assign(next, texts);
  return next;
}

/** After a new curve: O beside it (the final change), then the window fits it. */
function settleNewCurve(ui) {
  ui.set("hodograph", [originBeside(ui.data.whole)], true);
  ui.fit();
}

function applyPreset(ui, preset) {
  const next = {
    ...structuredClone(ui.state),
    x: preset.x,
    y: preset.y,
    z: preset.z ?? "",
    from: preset.from ?? "0",
    to: preset.to,
    params: { ...(preset.params ?? {}) },
    t: preset.t,
    bezier: preset.bezier ?? false,
  };
  try {
    ui.replace(next, false);
  } catch (err) {
    ui.status(errorText(err), "error");
    return;
  }
  settleNewCurve(ui);
}

/** The link into de-casteljau with the control points (a plane curve it can take), else null. */
function deCasteljauLink(s, d) {
  const form = d.bezierForm;
  if (!form) return null;
  if (form.dim !== 2 || form.count < BEZIER_POINTS.min || form.count > BEZIER_POINTS.max)
    return { text: t("parametricCurve.bezierLinkOff"), href: null };
  const points = [];
  for (let i = 0; i < form.count; i++) points.push([form.points[2 * i], form.points[2 * i + 1]]);
  const [a, b] = d.domain;
  const u = b > a ? Math.min(Math.max((s.t - a) / (b - a), 0), 1) : 0;
  const state = { points, t: Number(u.toFixed(6)), construction: true };
  const url = new URL(`../index.html${buildHash("de-casteljau", state)}`, import.meta.url).href;
  return {
    text: t("parametricCurve.bezierLink"),
    href: locale() === "en" ? url : withLanguage(url, locale()),
  };
}

/** "P₀ = (−5, 0), P₁ = (−271/50, 1/5), …": the exact control points (decimals without them). */
function bezierList(s, d) {
  const form = d.bezierForm;
  if (!form) return "";
  const items = [];
  for (let i = 0; i < form.count; i++) {
    const coords = [];
    for (let c = 0; c < form.dim; c++) {
      const exact = form.fractions?.[i * form.dim + c];
      coords.push(exact ? exact.replace(/^-/, "−") : form.points[i * form.dim + c]);
    }
    items.push(`P${subscript(i)} = ${pointText(coords)}`);
  }
  const [a, b] = d.domain;
  return t("parametricCurve.bezierPoints", {
    a: shortNumber(a),
    b: shortNumber(b),
    list: items.join(", "),
  });
}

/** The readout under the speed: the circle's radius, or why there is none. */
function radiusNote(d) {
  const at = d.at;
  if (!at.defined) return "";
  if (at.cusp) return t("parametricCurve.cusp");
  if (at.straight || !Number.isFinite(at.kappa)) return t("parametricCurve.straight");
  return t("parametricCurve.radius", { r: fmt(1 / Math.abs(at.kappa)) });
}

const isSpace = (s, d) => d.curve.dim === 3;

export const controls = [
  formulaFields({
    legend: "parametricCurve.control.curve",
    rows: [
      [{ field: "x", label: "parametricCurve.control.x" }],
      [{ field: "y", label: "parametricCurve.control.y" }],
      [{ field: "z", label: "parametricCurve.control.z" }],
      [
        { field: "from", label: "parametricCurve.control.from" },
        { field: "to", label: "parametricCurve.control.to" },
      ],
    ],
    help: "parametricCurve.control.help",
    check(ui, texts) {
      const { curve } = curveOf(ui.sl, withTexts(ui, texts));
      curve.free();
    },
    apply(ui, texts) {
      const next = withTexts(ui, texts);
      if (TEXTS.every((name) => next[name] === ui.state[name])) return;
      ui.replace(next, false); // throws the refusal before anything changes
      settleNewCurve(ui);
    },
  }),
  parameterSliders("params", {
    legend: "parametricCurve.control.params",
    input: "parametricCurve.control.param.input",
  }),
  group(
    "parametricCurve.atT",
    slider("t", {
      label: "parametricCurve.control.t",
      range: (s, d) => d.domain ?? d.curve.domain(),
      step: (a, b) => (b - a) / 1000,
      player: true,
    }),
    readout(
      "speed",
      (s, d) =>
        d.at.defined
          ? t("parametricCurve.speed", { speed: fmt(d.at.speed) })
          : t("parametricCurve.undefined", { t: fmt(s.t) }),
      { data: (s, d) => ({ speed: fmtMachine(d.at.speed) }) },
    ),
    readout(
      "curvature",
      (s, d) => (d.at.defined ? t("parametricCurve.curvature", { kappa: d.at.kappaText }) : ""),
      { live: true, data: (s, d) => ({ kappa: d.at.kappaMachine }) },
    ),
    readout("radius", (s, d) => radiusNote(d)),
    shownIf(
      isSpace,
      readout("torsion", (s, d) =>
        Number.isFinite(d.at.tau) ? t("parametricCurve.torsion", { tau: fmt(d.at.tau) }) : "",
      ),
    ),
  ),
  shownIf(
    (s, d) => d.whole.polynomial,
    group(
      null,
      checkbox("bezier", { label: "parametricCurve.control.bezier" }),
      infoLine("bezier-points", bezierList, deCasteljauLink),
    ),
  ),
  shownIf(
    isSpace,
    group(
      "parametricCurve.control.view",
      slider("azimuth", {
        label: "parametricCurve.control.azimuth",
        min: -180,
        max: 180,
        step: 1,
        format: (v) => String(Math.round(v)),
        round: Math.round,
      }),
      slider("elevation", {
        label: "parametricCurve.control.elevation",
        min: -MAX_ELEVATION,
        max: MAX_ELEVATION,
        step: 1,
        format: (v) => String(Math.round(v)),
        round: Math.round,
      }),
    ),
  ),
  actions(
    PRESETS.map((preset) => ({
      name: `preset-${preset.name}`,
      label: `parametricCurve.preset.${preset.name}`,
      run: (ui) => applyPreset(ui, preset),
    })),
    { title: "parametricCurve.control.examples" },
  ),
];

export const figure = {
  /** The curve's box (its visible part near a pole) and the hodograph's around O. */
  bounds(s, d) {
    const { box, hbox } = d.whole;
    const [ox, oy] = s.hodograph[0];
    const b = [
      Math.min(box[0], ox + hbox[0]),
      Math.min(box[1], oy + hbox[1]),
      Math.max(box[2], ox + hbox[2]),
      Math.max(box[3], oy + hbox[3]),
    ];
    const form = d.bezierForm;
    if (form) {
      const { m } = d.proj;
      for (let k = 0; k < form.points.length; k += form.dim) {
        const x = form.points[k];
        const y = form.points[k + 1];
        const z = zAt(form.points, k, form.dim);
        b[0] = Math.min(b[0], pu(m, x, y, z));
        b[1] = Math.min(b[1], pw(m, x, y, z));
        b[2] = Math.max(b[2], pu(m, x, y, z));
        b[3] = Math.max(b[3], pw(m, x, y, z));
      }
    }
    return b;
  },
  handles: {
    field: "hodograph",
    label: () => t("parametricCurve.originLabel"),
    polygon: false,
  },
};

// ------------------------------------------------------------------ drawing

/**
 * The core's adaptive plot for this window: tolerance PLOT_TOLERANCE_PX in model units, the
 * box the canvas in world units (a plane curve); made again only when the window changes.
 */
function plotOf(r, v, d) {
  const cache = d.plot;
  const three = d.proj.three;
  const x0 = v.wx(0);
  const x1 = v.wx(r.width);
  const y0 = v.wy(r.height);
  const y1 = v.wy(0);
  const key = three ? String(v.scale) : `${x0} ${y0} ${x1} ${y1}`;
  if (cache.key === key) return cache.result;
  const tolerance = PLOT_TOLERANCE_PX / v.scale;
  const mx = PLOT_BOX_MARGIN * (x1 - x0);
  const my = PLOT_BOX_MARGIN * (y1 - y0);
  try {
    cache.result = three
      ? d.curve.plot(tolerance)
      : d.curve.plot(tolerance, Float64Array.of(x0 - mx, y0 - my, x1 + mx, y1 + my));
  } catch {
    cache.result = null;
  }
  cache.key = key;
  return cache.result;
}

/** The arrow P → P + s·w (model vector w, projected) from (px, py), its label at the tip. */
function vectorArrow(r, v, d, px, py, w, s, style, text) {
  const { m } = d.proj;
  const z = w.length > 2 ? w[2] : 0;
  const x = px + v.scale * s * pu(m, w[0], w[1], z);
  const y = py - v.scale * s * pw(m, w[0], w[1], z);
  if (!(Math.hypot(x - px, y - py) >= 1)) return;
  if (clippedArrow(r, v, px, py, x, y, style))
    placeLabelAtTip(r, text, px, py, x, y, ARROW_LABEL_GAP_PX * r.scale, r.theme.labelPoint);
}

/** Axes: the x and y axes across the canvas (plane), or a labelled triad at the origin (space). */
function drawAxes(r, v, d) {
  const theme = r.theme;
  r.beginPath();
  penOnCanvas(r, v);
  if (!d.proj.three) {
    // Clipped: far from the origin the axes' ends would lie far off the canvas.
    penTo(r, -r.width, v.sy(0));
    penTo(r, 2 * r.width, v.sy(0));
    penTo(r, Number.NaN, Number.NaN);
    penTo(r, v.sx(0), -r.height);
    penTo(r, v.sx(0), 2 * r.height);
    r.paint(theme.axis);
    return;
  }
  const { m } = d.proj;
  const length = AXIS_FRACTION * d.whole.size;
  const cx = v.sx(0);
  const cy = v.sy(0);
  for (let k = 0; k < 3; k++) {
    penTo(r, Number.NaN, Number.NaN);
    penTo(r, cx, cy);
    penTo(r, v.sx(length * m[k]), v.sy(length * m[3 + k]));
  }
  r.paint(theme.axis);
  if (!onCanvas(r, cx, cy)) return;
  for (let k = 0; k < 3; k++) {
    const x = v.sx(length * m[k]);
    const y = v.sy(length * m[3 + k]);
    if (onCanvas(r, x, y))
      placeLabelAtTip(
        r,
        AXIS_NAMES[k],
        cx,
        cy,
        x,
        y,
        ARROW_LABEL_GAP_PX * r.scale,
        theme.labelSmall,
      );
  }
}

/** Whether the point (x, y) CSS px lies on the canvas widened by CLIP_MARGIN_PX. */
function onCanvas(r, x, y) {
  const slack = CLIP_MARGIN_PX * r.scale;
  return x > -slack && x < r.width + slack && y > -slack && y < r.height + slack;
}
const AXIS_NAMES = Object.freeze(["x", "y", "z"]);

/** The hodograph from O: axes over its box, its caption, the curve and the vector λP′(t). */
function drawHodograph(r, v, s, d) {
  const theme = r.theme;
  const { hodograph, lambda, hbox, dim } = d.whole;
  const { m } = d.proj;
  const [ox, oy] = s.hodograph[0];
  const left = v.sx(ox + hbox[0]);
  const right = v.sx(ox + hbox[2]);
  const top = v.sy(oy + hbox[3]);
  const bottom = v.sy(oy + hbox[1]);
  // Nothing of it when its box is off the canvas (O dragged or panned away).
  const slack = CLIP_MARGIN_PX * r.scale;
  if (right < -slack || left > r.width + slack || bottom < -slack || top > r.height + slack) return;
  r.beginPath();
  penOnCanvas(r, v);
  penTo(r, left, v.sy(oy));
  penTo(r, right, v.sy(oy));
  penTo(r, Number.NaN, Number.NaN);
  penTo(r, v.sx(ox), bottom);
  penTo(r, v.sx(ox), top);
  r.paint(theme.helper);
  if (onCanvas(r, left, top))
    drawCaption(
      r,
      t("parametricCurve.hodographCaption"),
      left,
      top - TEXT_MARGIN_PX * r.scale,
      theme.labelSmall,
      Math.max(right - left, r.width - left - TEXT_MARGIN_PX * r.scale),
      "bottom",
    );
  r.beginPath();
  penStart(left, top, right, bottom, 2 * Math.hypot(right - left, bottom - top));
  flatRunsPath(r, v, hodograph, dim, m, ox, oy, lambda);
  r.paint(SECOND_CURVE.curve);
  const { d1, defined } = d.at;
  if (!defined) return;
  const z = dim === 3 ? d1[2] : 0;
  const hx = v.sx(ox + lambda * pu(m, d1[0], d1[1], z));
  const hy = v.sy(oy + lambda * pw(m, d1[0], d1[1], z));
  if (Math.hypot(hx - v.sx(ox), hy - v.sy(oy)) < 1) return;
  if (clippedArrow(r, v, v.sx(ox), v.sy(oy), hx, hy, VELOCITY_STYLE)) {
    r.point(hx, hy, theme.pointOnCurve);
    placeLabelAtTip(
      r,
      t("parametricCurve.velocityLabel"),
      v.sx(ox),
      v.sy(oy),
      hx,
      hy,
      ARROW_LABEL_GAP_PX * r.scale,
      theme.labelPoint,
    );
  }
}

/** The exact control polygon of a polynomial curve and its points P₀ … Pₙ. */
function drawBezierForm(r, v, d) {
  const form = d.bezierForm;
  if (!form) return;
  const { m } = d.proj;
  r.beginPath();
  penOnCanvas(r, v);
  flatRunsPath(r, v, form.points, form.dim, m);
  r.paint(r.theme.polygon);
  // Labels away from the polygon's middle (the curve runs inside it).
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < form.count; i++) {
    const k = i * form.dim;
    const z = zAt(form.points, k, form.dim);
    cx += v.sx(pu(m, form.points[k], form.points[k + 1], z)) / form.count;
    cy += v.sy(pw(m, form.points[k], form.points[k + 1], z)) / form.count;
  }
  const style = bezierPoint(r.theme);
  for (let i = 0; i < form.count; i++) {
    const k = i * form.dim;
    const z = zAt(form.points, k, form.dim);
    const px = v.sx(pu(m, form.points[k], form.points[k + 1], z));
    const py = v.sy(pw(m, form.points[k], form.points[k + 1], z));
    if (!onCanvas(r, px, py)) continue;
    r.point(px, py, style);
    placeLabelFrom(r, bezierLabel(i), px, py, cx, cy, r.theme.labelSmall, style.radius * r.scale);
  }
}
const bezierLabels = [];
const bezierLabel = (i) => (bezierLabels[i] ??= `P${subscript(i)}`);

/**
 * The osculating circle through P(t): centre P + ρN (N towards the centre: the tangent turned
 * to the side P″ bends to in the plane, the core's N in space), radius ρ = 1/|κ|, as a polygon
 * from P clipped to the canvas, and its centre.
 */
function drawCircle(r, v, d) {
  const at = d.at;
  if (!at.defined || at.cusp || at.straight || !at.frame) return;
  const { m } = d.proj;
  const dim = d.whole.dim;
  const rho = 1 / Math.abs(at.kappa);
  const p = at.point;
  const T = at.frame.tangent;
  let nx;
  let ny;
  let nz = 0;
  if (dim === 3) {
    [nx, ny, nz] = at.frame.normal;
  } else {
    const side = Math.sign(at.d1[0] * at.d2[1] - at.d1[1] * at.d2[0]) || 1;
    nx = -side * T[1];
    ny = side * T[0];
  }
  const tz = dim === 3 ? T[2] : 0;
  const pz = zAt(p, 0, dim);
  const cx = p[0] + rho * nx;
  const cy = p[1] + rho * ny;
  const cz = pz + rho * nz;
  r.beginPath();
  penOnCanvas(r, v);
  for (let k = 0; k <= CIRCLE_VERTICES; k++) {
    const a = (2 * Math.PI * k) / CIRCLE_VERTICES;
    const c = -Math.cos(a) * rho;
    const sn = Math.sin(a) * rho;
    const x = cx + c * nx + sn * T[0];
    const y = cy + c * ny + sn * T[1];
    const z = cz + c * nz + sn * tz;
    penTo(r, v.sx(pu(m, x, y, z)), v.sy(pw(m, x, y, z)));
  }
  r.paint(CIRCLE_STYLE);
  const ccx = v.sx(pu(m, cx, cy, cz));
  const ccy = v.sy(pw(m, cx, cy, cz));
  if (ccx > 0 && ccx < r.width && ccy > 0 && ccy < r.height) {
    r.beginPath();
    r.moveTo(v.sx(pu(m, p[0], p[1], pz)), v.sy(pw(m, p[0], p[1], pz)));
    r.lineTo(ccx, ccy);
    r.paint(r.theme.helper);
    r.point(ccx, ccy, CENTRE_STYLE);
  }
}

/** The Frenet frame T, N, B at P(t) of a space curve, FRAME_PX long before foreshortening. */
function drawFrame(r, v, d, px, py) {
  const frame = d.at.frame;
  if (!frame || d.at.cusp) return;
  const s = (FRAME_PX * r.scale) / v.scale;
  vectorArrow(r, v, d, px, py, frame.tangent, s, VELOCITY_STYLE, t("parametricCurve.tangentLabel"));
  if (frame.normal?.every(Number.isFinite) && !d.at.straight)
    vectorArrow(
      r,
      v,
      d,
      px,
      py,
      frame.normal,
      s,
      ACCELERATION_STYLE,
      t("parametricCurve.normalLabel"),
    );
  if (frame.binormal?.every(Number.isFinite) && !d.at.straight)
    vectorArrow(
      r,
      v,
      d,
      px,
      py,
      frame.binormal,
      s,
      BINORMAL_STYLE,
      t("parametricCurve.binormalLabel"),
    );
}

/** Axes, hodograph, Bézier form, the curve, the circle and arrows at P(t), then the captions. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const { m, three } = d.proj;
  const dim = d.whole.dim;
  drawAxes(r, v, d);
  drawHodograph(r, v, s, d);
  drawBezierForm(r, v, d);
  const at = d.at;
  const p = at.defined ? at.point : null;
  const px = p ? v.sx(pu(m, p[0], p[1], zAt(p, 0, dim))) : Number.NaN;
  const py = p ? v.sy(pw(m, p[0], p[1], zAt(p, 0, dim))) : Number.NaN;
  // P(t) off the canvas (near a pole): nothing is drawn at it (the panel has its numbers).
  const shown = onCanvas(r, px, py);
  if (at.defined && shown) drawCircle(r, v, d);
  const plot = plotOf(r, v, d);
  if (plot && three) {
    // The far half (by depth) faded, then the near half: which loop is in front reads at once.
    const { depth } = d.whole;
    r.beginPath();
    penOnCanvas(r, v);
    depthRunsPath(r, v, plot.points, m, depth, false);
    r.paint(farCurve(theme));
    r.beginPath();
    penOnCanvas(r, v);
    depthRunsPath(r, v, plot.points, m, depth, true);
    r.paint(theme.curve);
  } else if (plot) {
    r.beginPath();
    penOnCanvas(r, v);
    flatRunsPath(r, v, plot.points, dim, m);
    r.paint(theme.curve);
  }
  d.handles.draw(r, v);
  const margin = TEXT_MARGIN_PX * r.scale;
  const width = r.width - 2 * margin;
  let caption = plot && !plot.complete ? t("parametricCurve.incomplete") : null;
  if (at.defined && shown) {
    if (three) {
      drawFrame(r, v, d, px, py);
    } else {
      const lambda = d.whole.lambda;
      vectorArrow(
        r,
        v,
        d,
        px,
        py,
        at.d2,
        lambda,
        ACCELERATION_STYLE,
        t("parametricCurve.accelerationLabel"),
      );
      vectorArrow(
        r,
        v,
        d,
        px,
        py,
        at.d1,
        lambda,
        VELOCITY_STYLE,
        t("parametricCurve.velocityLabel"),
      );
    }
    r.point(px, py, theme.pointOnCurve);
    // The label on the side away from the centre of curvature (right of the motion for κ ≥ 0).
    const z1 = dim === 3 ? at.d1[2] : 0;
    const tx = pu(m, at.d1[0], at.d1[1], z1);
    const ty = -pw(m, at.d1[0], at.d1[1], z1);
    const len = Math.hypot(tx, ty);
    const side = !three && at.kappa < 0 ? -1 : 1;
    const [dx, dy] = len > 0 ? [(-side * ty) / len, (side * tx) / len] : [0.7, -0.7];
    placeLabel(
      r,
      t("parametricCurve.pointLabel"),
      px,
      py,
      dx,
      dy,
      theme.pointOnCurve.radius * r.scale,
      theme.labelPoint,
    );
    if (at.cusp) caption ??= t("parametricCurve.cusp");
  } else if (!at.defined) {
    caption ??= t("parametricCurve.undefined", { t: fmt(s.t) });
  }
  const footer = three ? t("parametricCurve.frameCaption") : d.whole.scaleCaption;
  drawCaption(r, footer, margin, r.height - margin, theme.labelSmall, width, "bottom");
  if (caption) drawCaption(r, caption, margin, margin, theme.labelBold, width, "top");
}

// ------------------------------------------------------------------ formula and label

const COORDS = Object.freeze(["x", "y", "z"]);
/** Negative numbers in brackets as "({-}…" (see derivatives.js: the panel patches digits). */
const guarded = (line) => line.replace(/\(-/g, "({-}");

/**
 * The typed formulas and their derivatives as the core echoes them (`tex(0)`), the interval and
 * the parameters, then the numbers at t₀: P, P′, P″, the speed and κ (τ in space).
 */
export function formula(s, d) {
  const tex = d.tex;
  const dim = d.whole.dim;
  const tooLong = `\\text{(${t("parametricCurve.formula.tooLong")})}`;
  const lines = [];
  for (let c = 0; c < dim; c++) {
    const name = COORDS[c];
    const e = tex[name];
    if (!e) continue;
    lines.push(
      `${name}(t) = ${e.expr},\\qquad ${name}'(t) = ${e.d1 ?? tooLong},\\qquad ${name}''(t) = ${e.d2 ?? tooLong}`,
    );
  }
  const params = Object.entries(s.params)
    .map(([name, value]) => `${name.replace(/_(.+)$/, "_{$1}")} = ${shortNumber(value, true)}`)
    .join(",\\ ");
  lines.push(`t \\in [${tex.from},\\ ${tex.to}]${params ? `,\\qquad ${params}` : ""}`);
  const at = d.at;
  const t0 = `t_0 = ${fmtTex(s.t)}`;
  if (!at.defined) {
    lines.push(`${t0}:\\quad P(t_0)\\ \\text{${t("parametricCurve.formula.undefined")}}`);
    return lines;
  }
  // Three short lines rather than one long one (a narrow embed shrinks a line only so far).
  lines.push(
    guarded(`${t0}:\\quad P(t_0) = ${pointTex(at.point)},\\quad P'(t_0) = ${pointTex(at.d1)}`),
  );
  lines.push(guarded(`P''(t_0) = ${pointTex(at.d2)},\\quad |P'(t_0)| = ${fmtTex(at.speed)}`));
  const kappaRule =
    dim === 3 ? "\\frac{|P' \\times P''|}{|P'|^3}" : "\\frac{x'y'' - y'x''}{|P'|^3}";
  const kappa = Number.isFinite(at.kappa) ? at.kappaTex : "\\infty";
  const tau = dim === 3 && Number.isFinite(at.tau) ? `,\\quad \\tau(t_0) = ${fmtTex(at.tau)}` : "";
  lines.push(`\\kappa(t_0) = ${kappaRule} = ${kappa}${tau}`);
  return lines;
}

export function label(s, d) {
  const [a, b] = d.domain;
  const at = d.at;
  const common = { x: s.x, y: s.y, z: s.z, a: fmt(a), b: fmt(b), t: fmt(s.t) };
  if (!at.defined) return t("parametricCurve.ariaUndefined", common);
  const values = {
    ...common,
    px: fmt(at.point[0], 2),
    py: fmt(at.point[1], 2),
    speed: fmt(at.speed, 2),
    kappa: at.kappaText,
  };
  if (d.whole.dim !== 3) return t("parametricCurve.aria", values);
  return t("parametricCurve.aria3d", {
    ...values,
    pz: fmt(at.point[2], 2),
    tau: Number.isFinite(at.tau) ? fmt(at.tau) : "—",
  });
}

// ------------------------------------------------------------------ turning a space curve

/** Dragging empty space turns a space curve (Shift+drag pans, as in the 3D figures). */
export function setup(ui) {
  // Pressing on the curve (or dragging along it) moves the point there.
  let picking = false;
  const near = (x, y) => {
    const plot = ui.data.plot.result;
    if (!plot) return null;
    return nearestParameter(ui.view, plot, ui.data.curve.dim, ui.data.proj.m, x, y);
  };
  const pick = (x, y, final) => {
    const hit = near(x, y);
    if (!hit) return;
    const [a, b] = ui.data.domain;
    ui.set("t", Math.min(Math.max(hit.t, a), b), final);
  };
  const picker = {
    pointerDown(event, x, y) {
      const hit = near(x, y);
      const radius = event.pointerType === "touch" ? HIT_RADIUS_TOUCH : PICK_RADIUS_PX;
      if (!hit || hit.distance > radius) return false;
      ui.stop();
      picking = true;
      pick(x, y, false);
      return true;
    },
    pointerMove(event, x, y) {
      if (picking) pick(x, y, false);
    },
    pointerUp() {
      if (!picking) return;
      picking = false;
      ui.commit();
    },
    hover(x, y) {
      const hit = near(x, y);
      return hit && hit.distance <= PICK_RADIUS_PX ? "pointer" : null;
    },
    leave() {},
  };
  ui.view.addInteractor(picker);
  let drag = null;
  const orbit = {
    pointerDown(event, x, y) {
      if (ui.data.curve.dim !== 3 || event.shiftKey) return false;
      drag = { x, y, azimuth: ui.state.azimuth, elevation: ui.state.elevation };
      return true;
    },
    pointerMove(event, x, y) {
      if (!drag) return;
      let azimuth = Math.round(drag.azimuth - (x - drag.x) * DEG_PER_PX);
      azimuth = ((((azimuth + 180) % 360) + 360) % 360) - 180;
      const elevation = Math.round(
        Math.min(
          Math.max(drag.elevation + (y - drag.y) * DEG_PER_PX, -MAX_ELEVATION),
          MAX_ELEVATION,
        ),
      );
      ui.set("azimuth", azimuth, false);
      ui.set("elevation", elevation, false);
    },
    pointerUp() {
      if (!drag) return;
      drag = null;
      ui.commit();
    },
    hover: () => (ui.data.curve.dim === 3 ? "grab" : null),
    leave() {},
  };
  ui.view.addInteractor(orbit);
  // For tests: the plot's runs as [first t, last t] (a pole or gap ends a run).
  const host = ui.ctx.slots.figure;
  let shown = null;
  return {
    update(s, d) {
      const plot = d.plot.result;
      if (!plot || plot === shown) return;
      shown = plot;
      host.dataset.plotRuns = JSON.stringify(plotRuns(plot.ts));
    },
  };
}
