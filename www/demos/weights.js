/**
 * Demo (syllabus §4): the weights of a rational Bézier curve. A cubic with a log-scaled weight
 * slider per control point (and a ring around each point whose size shows wᵢ; drag the ring to
 * change it), the polynomial curve with all weights 1 as a dotted ghost, and an inset drawing
 * the homogeneous picture: the control points (wᵢxᵢ, wᵢyᵢ, wᵢ), the polynomial curve through
 * them in (wx, wy, w) space, the plane w = 1 and rays from the origin that project curve points
 * onto it (central projection).
 *
 * Everything drawn comes from the core: the rational curve (`BezierCurve` with weights), the
 * ghost (the same points without weights) and the homogeneous curve (a 3D polynomial
 * `BezierCurve` built from `homogeneousPoints()`), each updated in place while dragging
 * (`setControlPoint`, `setWeight`), one `sampleUniform` per change; the table's shares are the
 * core's rational basis `rationalBasis(t)`. The inset's oblique
 * projection of 3D onto the canvas is display code only (a fixed linear map, written below).
 */
import { Handles, HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, checkbox, group, el } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkNumbers, checkBoolean } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, exactFraction, fractionText, fractionTex } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { pointIndex, withPointAdded, withPointRemoved, pointButtons } from "../lib/point-list.js";

export const id = "weights";
/** Prefix of this demo's keys in strings.js. */
export const strings = "weights";
export const title = t("weights.title");
export const summary = t("weights.summary");
/** Syllabus section. */
export const section = 4;

/**
 * A cubic with integer points and w₁ = 3: the curve leans toward P₁ compared with the dotted
 * polynomial ghost. At t = 1/2 (by hand from the syllabus formula): Bernstein values 1/8, 3/8,
 * 3/8, 1/8, so P(1/2) = (0·1 + 1·9 + 4·3 + 5·1, 0 + 3·9 + 3·3 + 0)/14 = (13/7, 18/7).
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [1, 3], [4, 3], [5, 0]].map(Object.freeze)),
  weights: Object.freeze([1, 3, 1, 1]),
  t: 0.5,
  homogeneous: true,
});

/** Fewest and most control points (quadratic … quintic). */
export const MIN_POINTS = 3;
export const MAX_POINTS = 6;
/** Range of a weight (the sliders are logarithmic over it). */
export const WEIGHT_MIN = 0.1;
export const WEIGHT_MAX = 10;
/** Slider step in log10 units, and significant digits kept of a slider weight. */
const WEIGHT_LOG_STEP = 0.01;
const WEIGHT_DIGITS = 3;
/** Points sampled along each curve (one `sampleUniform` call per curve per change). */
const CURVE_SAMPLES = 256;
/** Parameters whose projection rays the inset draws (the current t is added to them). */
const RAY_TS = Object.freeze([0, 0.25, 0.5, 0.75, 1]);
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;
/** Weight ring: radius RING_PX·w^RING_EXPONENT (CSS px), so w = 1 is a 16 px ring, w = 10 about 32 px. */
const RING_PX = 16;
const RING_EXPONENT = 0.3;
/** A press this close (CSS px) to a ring's circle grabs it (touch: the larger value). */
const RING_HIT_PX = 5;
const RING_HIT_TOUCH_PX = 9;
/** Multiplier of the "scale all weights" button (only ratios matter: the curve stays). */
const SCALE_FACTOR = 2;
/** Distances below this are written in exponent form (rounding noise such as 2e-16). */
const SMALL_GAP = 1e-3;

/**
 * The inset (homogeneous space): a strip on the right of a wide canvas, or at the bottom of a
 * tall one, of INSET_FRACTION of the canvas (at least INSET_MIN_PX), with a margin inside.
 */
const INSET_FRACTION = 0.44;
/** Width / height above which the inset sits on the right (else at the bottom). */
const INSET_RIGHT_ASPECT = 1.2;
const INSET_MIN_PX = 170;
const INSET_MARGIN = Object.freeze({ top: 46, right: 18, bottom: 18, left: 18 });
/** Height (CSS px) of the band at the top kept for the key (the world window starts below it). */
const LEGEND_PX = 50;
/**
 * The inset's fixed oblique projection of (X, Y, W) = (wx, wy, w): X to the right, W up, Y
 * receding up and to the right (PROJ_YX, PROJ_YY per unit). W is stretched by a factor chosen
 * per picture so its extent matches the XY extent (W_EXTENT of it): a linear map of space, so
 * rays through the origin stay rays through the origin.
 */
const PROJ_YX = 0.5;
const PROJ_YY = 0.32;
const W_EXTENT = 0.85;
/** The plane w = 1 is drawn over the control points' box plus this fraction of its size. */
const PLANE_PAD = 0.12;
/** The w axis is drawn this factor beyond the largest weight. */
const AXIS_OVERSHOOT = 1.12;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "weights", "t", "homogeneous"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumbers(state, "weights", { min: MIN_POINTS, max: MAX_POINTS });
  checkWeights(state.weights, state.points.length);
  checkNumber(state, "t", { min: 0, max: 1 });
  checkBoolean(state, "homogeneous");
}

/** One weight per point, each in [WEIGHT_MIN, WEIGHT_MAX] (> 0 first: the message says why). */
function checkWeights(weights, count) {
  if (weights.length !== count) throw new Error(t("weights.countMismatch", { count: weights.length, points: count }));
  weights.forEach((w, i) => {
    if (w <= 0) throw new Error(t("weights.notPositive", { name: `w${subscript(i)}`, value: w }));
    if (w < WEIGHT_MIN || w > WEIGHT_MAX) throw new Error(t("weights.outOfRange", { name: `w${subscript(i)}`, value: w, min: WEIGHT_MIN, max: WEIGHT_MAX }));
  });
}

/** "cubic", "quartic", … for degree n. */
function kindOf(n) {
  return n <= 5 ? t(`curve.degree.${n}`) : t("curve.degree.n", { n });
}

/** A weight as the panels show it: up to 3 significant digits, no trailing zeros. */
function weightText(w) {
  return String(Number(w.toPrecision(WEIGHT_DIGITS)));
}

/** The three wasm curves of a state: rational, its polynomial ghost, its homogeneous 3D curve. */
function buildCurves(sl, state) {
  const flat = flatten(state.points);
  const curve = new sl.BezierCurve(flat, 2, new Float64Array(state.weights)); // validates first
  const ghost = new sl.BezierCurve(flat, 2);
  const homogeneous = new sl.BezierCurve(curve.homogeneousPoints(), 3);
  return { curve, ghost, homogeneous };
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let { curve, ghost, homogeneous } = buildCurves(sl, work);

  // Derived data, recomputed only when the geometry, a weight or t changed.
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let ghostSamples = null; // ghost.sampleUniform(CURVE_SAMPLES)
  let homSamples = null; // homogeneous.sampleUniform(CURVE_SAMPLES), (X, Y, W) each
  let homPoints = null; // curve.homogeneousPoints()
  let rayPoints = null; // curve.sample(rayTs): the projected points
  let rayHom = null; // homogeneous.sample(rayTs): the points in (X, Y, W)
  let point = null; // P(t)
  let ghostPoint = null; // the polynomial curve at t
  let maxGap = 0; // max distance rational ↔ polynomial over the samples (measurement)
  let dirty = true;
  const rayTs = new Float64Array(RAY_TS.length + 1); // RAY_TS, then t
  rayTs.set(RAY_TS);
  const pointScratch = new Float64Array(2);
  const insetScratch = [0, 0, 0, 0];
  const inset = { x0: 0, y0: 0, x1: 0, y1: 0, right: true }; // strip (CSS px)
  const proj = { k: 1, ox: 0, oy: 0, sw: 1 }; // inset projection: scale, origin, W stretch
  const extent = { u0: 0, u1: 0, v0: 0, v1: 0 }; // projected bounds (scratch)
  const handleLabels = []; // "P₁ (w₁ = 3)", rebuilt when a weight changes
  const homLabels = []; // "P₁ʷ"
  let pointLabel = "";
  let ghostLabel = "";

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets });
  // A taller figure than the default: the curve and the inset share it.
  ctx.slots.figure.classList.add("sl-figure-tall");
  const handles = new Handles(view, {
    count: () => work.points.length,
    get: (i, out) => {
      out[0] = work.points[i][0];
      out[1] = work.points[i][1];
    },
    label: (i) => (handleLabels[i] ??= t("weights.handleLabel", { i: subscript(i), w: weightText(work.weights[i]) })),
    move: (i, x, y) => {
      work.points[i][0] = x;
      work.points[i][1] = y;
      pointScratch[0] = x;
      pointScratch[1] = y;
      curve.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
      ghost.setControlPoint(i, pointScratch);
      syncHomogeneousPoint(i);
      dirty = true;
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
  });

  // The weight rings: pressing on a ring's circle (outside the handle) drags wᵢ (radius ↔ weight).
  let ringDrag = -1;
  view.addInteractor({
    pointerDown(event, x, y) {
      const i = ringAt(x, y, event.pointerType);
      if (i < 0) return false;
      ringDrag = i;
      handles.select(i);
      return true;
    },
    pointerMove(event, x, y) {
      if (ringDrag < 0) return;
      const i = ringDrag;
      const d = Math.hypot(x - view.sx(work.points[i][0]), y - view.sy(work.points[i][1])) / view.renderer.scale;
      const w = (Math.max(d, 1) / RING_PX) ** (1 / RING_EXPONENT);
      setWeight(i, Math.min(WEIGHT_MAX, Math.max(WEIGHT_MIN, w)), false);
    },
    pointerUp() {
      if (ringDrag < 0) return;
      ringDrag = -1;
      ctx.commit(work);
    },
    hover(x, y, pointerType) {
      return ringAt(x, y, pointerType) >= 0 ? "ew-resize" : null;
    },
  });

  /** Index of the weight ring whose circle passes near canvas point (x, y), or -1. */
  function ringAt(x, y, pointerType) {
    const touch = pointerType === "touch";
    const slack = touch ? RING_HIT_TOUCH_PX : RING_HIT_PX;
    const inner = touch ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE; // the handle owns its centre
    for (let i = work.points.length - 1; i >= 0; i--) {
      const d = Math.hypot(x - view.sx(work.points[i][0]), y - view.sy(work.points[i][1]));
      const radius = ringRadius(work.weights[i]) * view.renderer.scale;
      if (d > inner && Math.abs(d - radius) <= slack) return i;
    }
    return -1;
  }

  /** The [top, right, bottom, left] strip of the inset (scratch, no allocation). */
  function insets(width, height) {
    insetScratch[0] = LEGEND_PX; // the key, top left, stays clear of the curve
    insetScratch[1] = insetScratch[2] = 0;
    if (!work.homogeneous) return insetScratch;
    if (insetOnRight(width, height)) insetScratch[1] = insetSize(width);
    else insetScratch[2] = insetSize(height);
    return insetScratch;
  }

  /** The inset goes on the right of a wide canvas, below the curve on a squarer one (phones). */
  function insetOnRight(width, height) {
    return width >= INSET_RIGHT_ASPECT * height;
  }

  function insetSize(extent) {
    return Math.max(Math.round(extent * INSET_FRACTION), Math.min(INSET_MIN_PX, Math.round(extent / 2)));
  }

  // ------------------------------------------------------------ side panel
  const weightBox = el("div", { class: "sl-weights" });
  let weightSliders = [];
  const weightGroup = group(t("weights.weightsLegend"), weightBox,
    el("div", { class: "sl-button-row" },
      button({ label: t("weights.allOne"), title: t("weights.allOne.title"), name: "weights-one", onClick: () => setAllWeights(() => 1) }),
      button({ label: t("weights.scaleAll", { factor: SCALE_FACTOR }), title: t("weights.scaleAll.title"), name: "weights-scale", onClick: () => scaleAll() })));
  const tSlider = slider({
    label: t("control.t"),
    inputLabel: t("control.t.input"),
    name: "t",
    min: 0,
    max: 1,
    step: T_SLIDER_STEP,
    value: work.t,
    onChange: (value, final) => {
      work.t = value;
      dirty = true;
      view.requestDraw();
      if (final) ctx.commit(work);
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: addPoint, remove: removePoint, selected: () => handles.selected });
  const homogeneousBox = checkbox({
    label: t("weights.showHomogeneous"),
    name: "homogeneous",
    checked: work.homogeneous,
    onChange: (on) => {
      work.homogeneous = on;
      view.requestDraw();
      ctx.commit(work);
    },
  });
  const readout = el("p", { class: "sl-note", dataset: { info: "curve" }, "aria-live": "polite" });
  ctx.slots.controls.append(
    weightGroup,
    group(null, tSlider.element, readout),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
    group(null, homogeneousBox.element),
  );

  /** One log slider per weight (rebuilt when the number of points changes). */
  function buildWeightSliders() {
    weightSliders = work.weights.map((w, i) => {
      const name = `w${subscript(i)}`;
      return slider({
        label: t("weights.weightLabel", { name, point: `P${subscript(i)}` }),
        inputLabel: t("weights.weightInput", { name }),
        name: `weight-${i}`,
        min: WEIGHT_MIN,
        max: WEIGHT_MAX,
        step: WEIGHT_LOG_STEP,
        log: true,
        value: w,
        format: weightText,
        onChange: (value, final) => setWeight(i, Number(value.toPrecision(WEIGHT_DIGITS)), final),
        badNumber: (text) => t("weights.badWeight", { name, value: text, min: WEIGHT_MIN, max: WEIGHT_MAX }),
        onError: (message) => ctx.status(message, "error"),
      });
    });
    weightBox.replaceChildren(...weightSliders.map((s) => s.element));
  }
  buildWeightSliders();

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const tableTitle = el("p", { class: "sl-table-title", id: `sl-weights-${Math.random().toString(36).slice(2, 8)}` });
  const table = el("table", { class: "sl-table", dataset: { table: "weights" }, "aria-labelledby": tableTitle.id });
  ctx.slots.details.append(tableTitle, el("div", { class: "sl-table-wrap" }, table));
  let tableRows = -1;
  let tableCells = []; // per point: { point, weight, homogeneous, share, distance }

  // ------------------------------------------------------------ edits

  /** Copies homogeneous control point i from the rational curve into the 3D polynomial curve. */
  function syncHomogeneousPoint(i) {
    const hp = curve.homogeneousPoints();
    homogeneous.setControlPoint(i, hp.subarray(3 * i, 3 * i + 3));
  }

  /** Sets weight i (already in range) in place: the rational curve and the homogeneous point. */
  function setWeight(i, w, final) {
    work.weights[i] = w;
    curve.setWeight(i, w);
    syncHomogeneousPoint(i);
    handleLabels[i] = undefined;
    weightSliders[i]?.set(w);
    dirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  /** Sets every weight to f(w) (one undo step). */
  function setAllWeights(f) {
    work.weights.forEach((w, i) => setWeight(i, f(w), false));
    ctx.commit(work);
  }

  /** Multiplies every weight by SCALE_FACTOR (or divides, when that would leave the range). */
  function scaleAll() {
    const max = Math.max(...work.weights);
    const min = Math.min(...work.weights);
    const factor = max * SCALE_FACTOR <= WEIGHT_MAX ? SCALE_FACTOR : min / SCALE_FACTOR >= WEIGHT_MIN ? 1 / SCALE_FACTOR : 0;
    if (!factor) {
      ctx.status(t("weights.cannotScale", { min: WEIGHT_MIN, max: WEIGHT_MAX }), "error");
      return;
    }
    setAllWeights((w) => w * factor);
    recompute();
    ctx.status(t("weights.scaled", { factor: factor > 1 ? `× ${factor}` : `÷ ${1 / factor}` }), "info");
  }

  /** Replaces the wasm curves after the number of points changed (the old ones are freed). */
  function rebuild() {
    const next = buildCurves(sl, work);
    freeCurves();
    ({ curve, ghost, homogeneous } = next);
    handleLabels.length = 0;
    buildWeightSliders();
    dirty = true;
    view.requestDraw();
  }

  function freeCurves() {
    curve.free();
    ghost.free();
    homogeneous.free();
  }

  /** Adds a point (weight 1) after handle i (at the end when none is selected). */
  function addPoint(i) {
    const next = withPointAdded(work.points, i, MAX_POINTS, view.scale);
    if (!next) return ctx.status(t("weights.maxPoints", { max: MAX_POINTS }), "error");
    work.points = next.points;
    work.weights.splice(next.index, 0, 1);
    rebuild();
    handles.select(next.index);
    ctx.commit(work);
  }

  /** Removes handle i (the last one when none is selected) and its weight. */
  function removePoint(i) {
    const at = pointIndex(work.points, i);
    const next = withPointRemoved(work.points, i, MIN_POINTS);
    if (!next) return ctx.status(t("weights.minPoints", { min: MIN_POINTS }), "error");
    work.points = next.points;
    work.weights.splice(at, 1);
    rebuild();
    handles.select(next.index);
    ctx.commit(work);
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for the samples and points when something changed. */
  function recompute() {
    if (!dirty) return;
    dirty = false;
    samples = curve.sampleUniform(CURVE_SAMPLES);
    ghostSamples = ghost.sampleUniform(CURVE_SAMPLES);
    homSamples = homogeneous.sampleUniform(CURVE_SAMPLES);
    homPoints = curve.homogeneousPoints();
    rayTs[RAY_TS.length] = work.t;
    rayPoints = curve.sample(rayTs);
    rayHom = homogeneous.sample(rayTs);
    point = rayPoints.subarray(2 * RAY_TS.length);
    ghostPoint = ghost.evaluate(work.t);
    // Measurement: how far the rational curve is from the polynomial one (0 when all wᵢ are equal).
    maxGap = 0;
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      maxGap = Math.max(maxGap, Math.hypot(samples[2 * k] - ghostSamples[2 * k], samples[2 * k + 1] - ghostSamples[2 * k + 1]));
    }
    pointLabel = t("weights.pointLabel", { t: tText() });
    ghostLabel = t("weights.ghostPointLabel", { t: tText() });
    syncPanels();
  }

  function tText() {
    const f = simpleFraction(work.t);
    return f ? fractionText(f) : fmt(work.t);
  }

  function maxGapText() {
    return maxGap === 0 ? "0" : maxGap < SMALL_GAP ? maxGap.toExponential(1) : fmt(maxGap);
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;
    const cycle = theme.basisRing.length;

    // Control polygon.
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(theme.polygon);

    // Weight rings: radius grows with wᵢ (RING_PX at w = 1).
    for (let i = 0; i <= n; i++) {
      r.beginPath();
      r.circle(v.sx(pts[i][0]), v.sy(pts[i][1]), ringRadius(work.weights[i]) * r.scale);
      r.paint(theme.basisStroke[i % cycle]);
    }

    // The polynomial ghost (all weights 1), then the rational curve on top.
    strokeSamples(r, v, ghostSamples, theme.compareCurve[2]);
    strokeSamples(r, v, samples, theme.curve);

    // Where the ghost is at t, joined to P(t): the pull of the weights.
    const gx = v.sx(ghostPoint[0]);
    const gy = v.sy(ghostPoint[1]);
    const px = v.sx(point[0]);
    const py = v.sy(point[1]);
    r.beginPath();
    r.moveTo(gx, gy);
    r.lineTo(px, py);
    r.paint(theme.helper);
    r.point(gx, gy, theme.comparePoint[2]);

    handles.draw(r, v);
    r.point(px, py, theme.pointOnCurve);
    // Labels below/above the two points, on the side away from each other.
    const below = py >= gy;
    r.text(pointLabel, px, py + (below ? 1 : -1) * 12 * r.scale, theme.labelPoint, "center", below ? "top" : "bottom");
    r.text(ghostLabel, gx, gy + (below ? -1 : 1) * 12 * r.scale, theme.labelSmall, "center", below ? "bottom" : "top");

    drawLegend(r, theme);
    if (work.homogeneous) drawInset(r, theme);
  }

  /** A polyline through flat 2D samples. */
  function strokeSamples(r, v, flat, style) {
    r.beginPath();
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const x = v.sx(flat[2 * k]);
      const y = v.sy(flat[2 * k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(style);
  }

  /** Top-left key: the rational curve (solid blue) and the polynomial ghost (dotted). */
  function drawLegend(r, theme) {
    const s = r.scale;
    const x = 12 * s;
    let y = 16 * s;
    const line = 26 * s;
    const gap = 21 * s;
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + line, y);
    r.paint(theme.curve);
    r.text(t("weights.legendRational"), x + line + 6 * s, y, theme.labelSmall, "left", "middle");
    y += gap;
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + line, y);
    r.paint(theme.compareCurve[2]);
    r.text(t("weights.legendPolynomial"), x + line + 6 * s, y, theme.labelSmall, "left", "middle");
  }

  // ------------------------------------------------------------ the homogeneous inset
  /** Inset strip and projection for a canvas of width × height CSS px. */
  function layoutInset(width, height, scale) {
    const right = insetOnRight(width, height);
    inset.right = right;
    inset.x0 = right ? width - insetSize(width) : 0;
    inset.y0 = right ? 0 : height - insetSize(height);
    inset.x1 = width;
    inset.y1 = height;
    // Bounds of the projected picture: origin, homogeneous control points, the plane's corners.
    const pts = work.points;
    let maxW = 1;
    let xyExtent = 0;
    for (let i = 0; i < pts.length; i++) {
      maxW = Math.max(maxW, homPoints[3 * i + 2]);
      xyExtent = Math.max(xyExtent, Math.abs(homPoints[3 * i]), Math.abs(homPoints[3 * i + 1]), Math.abs(pts[i][0]), Math.abs(pts[i][1]));
    }
    proj.sw = (W_EXTENT * Math.max(xyExtent, 1)) / maxW;
    extent.u0 = extent.u1 = extent.v0 = extent.v1 = 0; // the origin
    for (let i = 0; i < pts.length; i++) extend(homPoints[3 * i], homPoints[3 * i + 1], homPoints[3 * i + 2]);
    planeBox();
    extend(plane[0], plane[1], 1);
    extend(plane[2], plane[1], 1);
    extend(plane[2], plane[3], 1);
    extend(plane[0], plane[3], 1);
    extend(0, 0, maxW * AXIS_OVERSHOOT); // the w axis' tip
    const { u0, u1, v0, v1 } = extent;
    const bx0 = inset.x0 + INSET_MARGIN.left * scale;
    const bx1 = inset.x1 - INSET_MARGIN.right * scale;
    const by0 = inset.y0 + INSET_MARGIN.top * scale;
    const by1 = inset.y1 - INSET_MARGIN.bottom * scale;
    proj.k = Math.min((bx1 - bx0) / Math.max(u1 - u0, 1e-9), (by1 - by0) / Math.max(v1 - v0, 1e-9));
    proj.ox = (bx0 + bx1) / 2 - ((u0 + u1) / 2) * proj.k;
    proj.oy = (by0 + by1) / 2 + ((v0 + v1) / 2) * proj.k;
  }

  /** Grows the projected extent (scratch `extent`) by the space point (X, Y, W). */
  function extend(X, Y, W) {
    const u = X + PROJ_YX * Y;
    const w = proj.sw * W + PROJ_YY * Y;
    extent.u0 = Math.min(extent.u0, u);
    extent.u1 = Math.max(extent.u1, u);
    extent.v0 = Math.min(extent.v0, w);
    extent.v1 = Math.max(extent.v1, w);
  }

  /** The plane w = 1 is drawn over the control points' box [x0, y0, x1, y1], padded. */
  const plane = new Float64Array(4);
  function planeBox() {
    let x0 = Infinity;
    let y0 = Infinity;
    let x1 = -Infinity;
    let y1 = -Infinity;
    for (let i = 0; i < work.points.length; i++) {
      const x = work.points[i][0];
      const y = work.points[i][1];
      x0 = Math.min(x0, x);
      y0 = Math.min(y0, y);
      x1 = Math.max(x1, x);
      y1 = Math.max(y1, y);
    }
    const pad = PLANE_PAD * Math.max(x1 - x0, y1 - y0, 1);
    plane[0] = x0 - pad;
    plane[1] = y0 - pad;
    plane[2] = x1 + pad;
    plane[3] = y1 + pad;
  }

  /** Canvas x, y of the space point (X, Y, W) in the inset. */
  const ix = (X, Y) => proj.ox + (X + PROJ_YX * Y) * proj.k;
  const iy = (Y, W) => proj.oy - (proj.sw * W + PROJ_YY * Y) * proj.k;

  function drawInset(r, theme) {
    const s = r.scale;
    layoutInset(r.width, r.height, s);
    const pts = work.points;
    const n = pts.length - 1;

    // Background (covers anything panned under it) and the dividing line.
    r.beginPath();
    r.rect(inset.x0, inset.y0, inset.x1 - inset.x0, inset.y1 - inset.y0);
    r.paint(theme.plotBackground);
    r.beginPath();
    if (inset.right) {
      r.moveTo(inset.x0, inset.y0);
      r.lineTo(inset.x0, inset.y1);
    } else {
      r.moveTo(inset.x0, inset.y0);
      r.lineTo(inset.x1, inset.y0);
    }
    r.paint(theme.axis);
    r.text(t("weights.insetTitle"), inset.x0 + 10 * s, inset.y0 + 8 * s, theme.labelSmall, "left", "top");

    // Axes from the origin O.
    let maxW = 1;
    for (let i = 0; i <= n; i++) maxW = Math.max(maxW, homPoints[3 * i + 2]);
    const ox = ix(0, 0);
    const oy = iy(0, 0);
    const axisX = plane[2] > 0 ? plane[2] : 1;
    const axisY = plane[3] > 0 ? plane[3] : 1;
    r.beginPath();
    r.moveTo(ox, oy);
    r.lineTo(ix(axisX, 0), iy(0, 0));
    r.moveTo(ox, oy);
    r.lineTo(ix(0, axisY), iy(axisY, 0));
    r.moveTo(ox, oy);
    r.lineTo(ox, iy(0, maxW * AXIS_OVERSHOOT));
    r.paint(theme.axis);
    r.text(t("weights.axisX"), ix(axisX, 0) + 4 * s, iy(0, 0), theme.labelSmall, "left", "middle");
    r.text(t("weights.axisY"), ix(0, axisY) + 4 * s, iy(axisY, 0), theme.labelSmall, "left", "bottom");
    r.text(t("weights.axisW"), ox - 5 * s, iy(0, maxW * AXIS_OVERSHOOT), theme.labelSmall, "right", "middle");
    r.text(t("weights.origin"), ox - 5 * s, oy, theme.labelSmall, "right", "middle");

    // The plane w = 1.
    r.beginPath();
    r.moveTo(ix(plane[0], plane[1]), iy(plane[1], 1));
    r.lineTo(ix(plane[2], plane[1]), iy(plane[1], 1));
    r.lineTo(ix(plane[2], plane[3]), iy(plane[3], 1));
    r.lineTo(ix(plane[0], plane[3]), iy(plane[3], 1));
    r.closePath();
    r.paint(theme.helperFill);
    r.text(t("weights.plane"), ix(plane[2], plane[1]) + 4 * s, iy(plane[1], 1), theme.labelSmall, "left", "top");

    // On the plane: the control polygon and the rational curve (the projection).
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      if (i === 0) r.moveTo(ix(pts[i][0], pts[i][1]), iy(pts[i][1], 1));
      else r.lineTo(ix(pts[i][0], pts[i][1]), iy(pts[i][1], 1));
    }
    r.paint(theme.polygon);
    r.beginPath();
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const x = ix(samples[2 * k], samples[2 * k + 1]);
      const y = iy(samples[2 * k + 1], 1);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.curve);

    // Rays from O through each projected point to its homogeneous point (the farther one ends the ray).
    const rays = RAY_TS.length;
    for (let j = 0; j <= rays; j++) {
      const X = rayHom[3 * j];
      const Y = rayHom[3 * j + 1];
      const W = rayHom[3 * j + 2];
      const reach = Math.max(W, 1) / W; // beyond the homogeneous point when W < 1
      r.beginPath();
      r.moveTo(ox, oy);
      r.lineTo(ix(X * reach, Y * reach), iy(Y * reach, W * reach));
      r.paint(j === rays ? theme.marker : theme.helper);
    }

    // The homogeneous control polygon and curve (a polynomial curve in space).
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      const x = ix(homPoints[3 * i], homPoints[3 * i + 1]);
      const y = iy(homPoints[3 * i + 1], homPoints[3 * i + 2]);
      if (i === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.polygon);
    r.beginPath();
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const x = ix(homSamples[3 * k], homSamples[3 * k + 1]);
      const y = iy(homSamples[3 * k + 1], homSamples[3 * k + 2]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.splitLeft);
    for (let i = 0; i <= n; i++) {
      const x = ix(homPoints[3 * i], homPoints[3 * i + 1]);
      const y = iy(homPoints[3 * i + 1], homPoints[3 * i + 2]);
      r.point(x, y, theme.splitLeftPoint);
      r.text((homLabels[i] ??= `P${subscript(i)}ʷ`), x, y - 7 * s, theme.labelSmall, "center", "bottom");
    }
    // Ray ends: the point on the plane and the homogeneous point, the current t in vermillion.
    for (let j = 0; j <= rays; j++) {
      const current = j === rays;
      r.point(ix(rayPoints[2 * j], rayPoints[2 * j + 1]), iy(rayPoints[2 * j + 1], 1), current ? theme.pointOnCurve : theme.comparePoint[0]);
      if (current) r.point(ix(rayHom[3 * j], rayHom[3 * j + 1]), iy(rayHom[3 * j + 1], rayHom[3 * j + 2]), theme.splitLeftPoint);
    }
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    const pts = work.points;
    const n = pts.length - 1;
    const ws = work.weights;
    const [x, y] = point;
    const distances = pts.map(([qx, qy]) => Math.hypot(x - qx, y - qy));
    const heaviest = ws.indexOf(Math.max(...ws));
    view.setLabel(t("weights.aria", {
      kind: kindOf(n),
      weights: ws.map(weightText).join(", "),
      t: tText(),
      x: fmt(x, 2),
      y: fmt(y, 2),
      gx: fmt(ghostPoint[0], 2),
      gy: fmt(ghostPoint[1], 2),
      heaviest: `P${subscript(heaviest)}`,
      distance: fmt(distances[heaviest], 2),
    }));
    degreeText.textContent = t("weights.degree", { n, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;
    readout.textContent = t("weights.readout", { t: tText(), x: fmt(x), y: fmt(y), gap: maxGapText() });
    readout.dataset.point = `${x},${y}`;
    readout.dataset.maxGap = String(maxGap);

    // Formula panel: the definition with the live weights, the point at t, the ratio remark.
    const tFraction = simpleFraction(work.t);
    const tTex = tFraction ? fractionTex(tFraction) : fmt(work.t);
    const b = [];
    for (let i = 0; i <= n; i++) {
      const value = sl.bernstein(n, i, work.t);
      const f = tFraction ? exactFraction(value, tFraction.den ** n) : null;
      b.push(f ? fractionTex(f) : fmt(value));
    }
    const wTex = ws.map(weightText);
    const numerator = b.map((bi, i) => `${bi}\\cdot ${wTex[i]}\\,P_{${i}}`).join(" + ");
    const denominator = b.map((bi, i) => `${bi}\\cdot ${wTex[i]}`).join(" + ");
    const hom = rayHom.subarray(3 * RAY_TS.length);
    const ratios = ws.map((w) => weightText(w / ws[0])).join(" : ");
    formula.set([
      `P(t) = \\frac{\\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,w_i\\,P_i}{\\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,w_i},\\qquad (w_0, \\dots, w_{${n}}) = (${wTex.join(",\\ ")})`,
      `P(${tTex}) = \\frac{${numerator}}{${denominator}} = (${fmt(x)},\\ ${fmt(y)})`,
      `P^w(${tTex}) = \\sum_i B_i^{${n}}(${tTex})\\,(w_iP_i,\\ w_i) = (${fmt(hom[0])},\\ ${fmt(hom[1])},\\ ${fmt(hom[2])}) \\;\\mapsto\\; \\left(\\tfrac{${fmt(hom[0])}}{${fmt(hom[2])}},\\ \\tfrac{${fmt(hom[1])}}{${fmt(hom[2])}}\\right)`,
      `\\text{only ratios matter: } w_0 : \\dots : w_{${n}} = ${ratios};\\quad \\lambda w_i\\ (\\lambda > 0) \\text{ gives the same curve}`,
    ]);

    // Table: one row per control point.
    if (tableRows !== n + 1) buildTable(n);
    setText(tableTitle, t("weights.tableCaption", { t: tText() }));
    const shares = curve.rationalBasis(work.t); // R_i(t) = w_i B_i(t) / Σ_j w_j B_j(t)
    for (let i = 0; i <= n; i++) {
      const cells = tableCells[i];
      setText(cells.point, `(${fmt(pts[i][0])}, ${fmt(pts[i][1])})`);
      setText(cells.weight, weightText(ws[i]));
      setText(cells.homogeneous, `(${fmt(homPoints[3 * i])}, ${fmt(homPoints[3 * i + 1])}, ${fmt(homPoints[3 * i + 2])})`);
      setText(cells.share, fmt(shares[i]));
      setText(cells.distance, fmt(distances[i]));
      cells.distance.dataset.value = String(distances[i]);
    }
  }

  /** Rebuilds the table's rows for n + 1 points (only when the count changed). */
  function buildTable(n) {
    tableRows = n + 1;
    tableCells = [];
    const head = ["point", "weight", "homogeneous", "share", "distance"].map((c) => el("th", { scope: "col", text: t(`weights.column.${c}`) }));
    const rows = [];
    for (let i = 0; i <= n; i++) {
      const cells = {
        point: el("td", { dataset: { column: "point" } }),
        weight: el("td", { dataset: { column: "weight" } }),
        homogeneous: el("td", { dataset: { column: "homogeneous" } }),
        share: el("td", { dataset: { column: "share" } }),
        distance: el("td", { dataset: { column: "distance" } }),
      };
      tableCells.push(cells);
      rows.push(el("tr", { dataset: { index: String(i) } }, el("th", { scope: "row", text: `P${subscript(i)}` }), cells.point, cells.weight, cells.homogeneous, cells.share, cells.distance));
    }
    table.replaceChildren(el("thead", {}, el("tr", {}, el("th", { scope: "col", text: "" }), head)), el("tbody", {}, rows));
  }

  /** Sets a node's text only when it changed. */
  function setText(node, text) {
    if (node.textContent !== text) node.textContent = text;
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = buildCurves(sl, state); // throws before anything changes
      const countChanged = state.points.length !== work.points.length;
      freeCurves();
      ({ curve, ghost, homogeneous } = next);
      work = structuredClone(state);
      handles.forgetPointer();
      ringDrag = -1;
      if (handles.selected >= work.points.length) handles.select(-1);
      handleLabels.length = 0;
      if (countChanged) buildWeightSliders();
      else weightSliders.forEach((s, i) => s.set(work.weights[i]));
      tSlider.set(work.t);
      homogeneousBox.set(work.homogeneous);
      dirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      freeCurves();
    },
  };
}

/** Radius (CSS px at scale 1) of the ring that shows weight w. */
function ringRadius(w) {
  return RING_PX * w ** RING_EXPONENT;
}

