/**
 * Demo (syllabus §4): why the library refuses weights ≤ 0. A rational quadratic with weights
 * 1, w₁, 1 where the slider lets w₁ pass through zero. For w₁ > 0 the curve is the core's
 * `BezierCurve`. For w₁ ≤ 0 the constructor throws, and the demo shows its exact message; it
 * then draws what the curve *would* be from the core's teaching function `rationalPoles`
 * (weights of any sign, no curve object): the homogeneous samples (wx, wy, w), divided by w
 * here (the central projection, display only), and the t where w(t) = Σ Bᵢ(t) wᵢ is zero.
 * There the point runs off to infinity (a pole): the drawn path breaks, and the plot
 * underneath shows w(t) crossing zero at the core's roots.
 *
 * Drags update the curve in place (`setControlPoint`) and ask `rationalPoles` once per change;
 * the draw path allocates nothing (clipping uses scratch arrays).
 */
import { Handles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, group, el } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber } from "../lib/validate.js";
import { fmt } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { drawCaption } from "../lib/draw.js";

export const id = "negative-weights";
/** Prefix of this demo's keys in strings.js. */
export const strings = "negativeWeights";
export const title = t("negativeWeights.title");
export const summary = t("negativeWeights.summary");
/** Syllabus section. */
export const section = 4;

/**
 * w₁ = −2: the denominator w(t) = 1 − 2(1 − w₁)t(1 − t) = 1 − 6t(1 − t) vanishes at
 * t = 1/2 ± √3/6 ≈ 0.211 and 0.789, two poles; the middle piece is the hyperbola's other
 * branch, through P(1/2) = (P₀ + 2w₁P₁ + P₂)/(2 + 2w₁) = (2, 6).
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 3], [4, 0]].map(Object.freeze)),
  w1: -2,
});

/** Range and step of the w₁ slider (linear: it has to pass through 0). */
export const W1_MIN = -3;
export const W1_MAX = 3;
const W1_STEP = 0.01;
/** Preset buttons. */
const PRESETS = Object.freeze([1, -0.5, -1.5]);
/** The fitted window holds the triangle, P(1/2) and the curve within this many triangle sizes of its middle. */
const FIT_REACH = 1.2;
/** Samples: the real curve, and the homogeneous curve (dense: the projection races near a pole). */
const CURVE_SAMPLES = 256;
const HOM_SAMPLES = 1201;
/** |w| below this counts as zero when projecting (a pole exactly on a sample, e.g. w₁ = −1 at t = 1/2). */
const ZERO_W = 1e-12;
/** At most this many "to infinity" marks are drawn where the path leaves the figure. */
const MAX_EXITS = 8;
/** A sample this far (model units, relative to the triangle) outside the hull counts as outside. */
const HULL_TOLERANCE = 1e-9;
/**
 * The plot of w(t) takes this fraction of the canvas height, below the curve (at least
 * PLOT_MIN_PX, at most PLOT_FRACTION_SHORT of a short canvas).
 */
const PLOT_FRACTION = 0.34;
const PLOT_MIN_PX = 140;
const PLOT_FRACTION_SHORT = 0.5;
const PLOT_MARGIN = Object.freeze({ top: 30, right: 24, bottom: 30, left: 50 });
/** Extra room above and below the plotted values, as a fraction of their range. */
const PLOT_PAD = 0.1;
/** Length of tick marks, CSS px. */
const TICK_PX = 5;
/** Vertical distance between pole labels in the plot, CSS px. */
const POLE_LINE_PX = 18;
/** The path is clipped to the figure plus this margin (CSS px). */
const CLIP_MARGIN = 2;
/** "∞" marks keep this far (CSS px) from the figure's edges, and below the caption line. */
const EDGE_PX = 14;
const CAPTION_PX = 34;
/** Height (CSS px) of the band at the top kept for the caption. */
const CAPTION_BAND_PX = 30;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "w1"]);
  checkPoints(state, "points", { min: 3, max: 3 });
  checkNumber(state, "w1", { min: W1_MIN, max: W1_MAX });
}

/** The weights 1, w₁, 1. */
function weightsOf(w1) {
  return new Float64Array([1, w1, 1]);
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  let work = structuredClone(initialState);
  /** The rational curve: built while w₁ > 0, kept (and updated in place) afterwards. */
  let curve = null;
  /** The library's refusal of the current weights, or "" when it accepts them. */
  let refusal = "";
  let shownStatus = "";
  ensureCurve();

  // Derived data, recomputed when the points or w₁ changed.
  let samples = null; // curve.sampleUniform (w₁ > 0)
  let hom = null; // sl.rationalPoles(…).samples: X, Y, W at HOM_SAMPLES t
  let minW = 0;
  let maxW = 1;
  let poleCount = 0;
  let poles = null; // sl.rationalPoles(…).roots: t of each pole
  let poleDirections = null; // sl.rationalPoles(…).directions: unit (x, y) per pole
  const poleLabels = [];
  let outsideHull = false;
  let middle = null; // P(1/2) from the homogeneous curve, divided (NaN at a pole)
  let dirty = true;
  const pointScratch = new Float64Array(2);
  const clipScratch = new Float64Array(4);
  const exits = new Float64Array(2 * MAX_EXITS);
  let exitCount = 0;
  const insetScratch = [0, 0, 0, 0];
  const plot = { x0: 0, y0: 0, x1: 0, y1: 0, top: 0, lo: 0, hi: 1 };
  const handleLabels = ["P₀", "P₁", "P₂"];
  let loLabel = ""; // the lowest value of w(t) on the plot's axis

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => fitBounds(), insets });
  ctx.slots.figure.classList.add("sl-figure-tall");
  const handles = new Handles(view, {
    count: () => 3,
    get: (i, out) => {
      out[0] = work.points[i][0];
      out[1] = work.points[i][1];
    },
    label: (i) => handleLabels[i],
    move: (i, x, y) => {
      work.points[i][0] = x;
      work.points[i][1] = y;
      pointScratch[0] = x;
      pointScratch[1] = y;
      curve?.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
      dirty = true;
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
  });

  /** The window to fit: the triangle, P(1/2) and the projected curve near the triangle. */
  function fitBounds() {
    recompute();
    const box = boundsOf(work.points);
    const reach = FIT_REACH * Math.max(box[2] - box[0], box[3] - box[1], 1);
    const cx = (box[0] + box[2]) / 2;
    const cy = (box[1] + box[3]) / 2;
    const grow = (x, y) => {
      if (Math.abs(x - cx) > reach || Math.abs(y - cy) > reach) return;
      box[0] = Math.min(box[0], x);
      box[1] = Math.min(box[1], y);
      box[2] = Math.max(box[2], x);
      box[3] = Math.max(box[3], y);
    };
    for (let k = 0; k < HOM_SAMPLES; k++) {
      const w = hom[3 * k + 2];
      if (Math.abs(w) > ZERO_W) grow(hom[3 * k] / w, hom[3 * k + 1] / w);
    }
    if (middle) {
      box[0] = Math.min(box[0], middle[0]);
      box[1] = Math.min(box[1], middle[1]);
      box[2] = Math.max(box[2], middle[0]);
      box[3] = Math.max(box[3], middle[1]);
    }
    return box;
  }

  function insets(width, height) {
    insetScratch[0] = CAPTION_BAND_PX; // the caption line stays clear of the curve
    insetScratch[2] = plotHeight(height);
    return insetScratch;
  }

  function plotHeight(height) {
    return Math.max(Math.round(height * PLOT_FRACTION), Math.min(PLOT_MIN_PX, Math.round(height * PLOT_FRACTION_SHORT)));
  }

  // ------------------------------------------------------------ side panel
  const wSlider = slider({
    label: t("negativeWeights.w1"),
    inputLabel: t("negativeWeights.w1.input"),
    name: "w1",
    min: W1_MIN,
    max: W1_MAX,
    step: W1_STEP,
    value: work.w1,
    onChange: (value, final) => setW1(value, final),
    badNumber: (text) => t("negativeWeights.badWeight", { value: text, min: W1_MIN, max: W1_MAX }),
    onError: (message) => ctx.status(message, "error"),
  });
  const presetButtons = PRESETS.map((w) => button({ label: t("negativeWeights.preset", { w: String(w).replace("-", "−") }), name: `w1-${w}`, onClick: () => setW1(w, true) }));
  const libraryText = el("p", { class: "sl-note", dataset: { info: "library" }, "aria-live": "polite" });
  const polesText = el("p", { class: "sl-readout", dataset: { info: "poles" } });
  const hullText = el("p", { class: "sl-note", dataset: { info: "hull" } });
  ctx.slots.controls.append(
    group(null, wSlider.element, el("div", { class: "sl-button-row" }, presetButtons)),
    group(t("negativeWeights.libraryLegend"), libraryText),
    group(t("negativeWeights.resultLegend"), polesText, hullText),
  );

  // ------------------------------------------------------------ formula
  const formula = new FormulaPanel(ctx.slots.formula);

  // ------------------------------------------------------------ edits

  /**
   * Asks the library for the rational curve of the current weights: with w₁ > 0 the curve is
   * made (or updated in place); otherwise the constructor's refusal is kept, word for word.
   */
  function ensureCurve() {
    if (work.w1 > 0) {
      refusal = "";
      if (curve) curve.setWeight(1, work.w1);
      else curve = new sl.BezierCurve(flatten(work.points), 2, weightsOf(work.w1));
      return;
    }
    try {
      new sl.BezierCurve(flatten(work.points), 2, weightsOf(work.w1)).free(); // never gets here
      refusal = "";
    } catch (err) {
      refusal = err.message;
    }
  }

  /** Shows the library's refusal in the status line (only when it changed; cleared when accepted). */
  function syncStatus() {
    if (refusal === shownStatus) return;
    shownStatus = refusal;
    if (refusal) ctx.status(t("negativeWeights.refused", { message: refusal }), "error");
    else ctx.status(t("negativeWeights.accepted"), "info");
  }

  function setW1(value, final) {
    work.w1 = value;
    wSlider.set(value);
    ensureCurve();
    syncStatus();
    dirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  // ------------------------------------------------------------ drawing
  function recompute() {
    if (!dirty) return;
    dirty = false;
    const result = sl.rationalPoles(flatten(work.points), 2, weightsOf(work.w1), HOM_SAMPLES);
    hom = result.samples;
    poles = result.roots;
    poleDirections = result.directions;
    poleCount = poles.length;
    samples = refusal ? null : curve.sampleUniform(CURVE_SAMPLES);
    // The plot's value range: the extremes of the sampled w(t).
    minW = Infinity;
    maxW = -Infinity;
    for (let k = 0; k < HOM_SAMPLES; k++) {
      minW = Math.min(minW, hom[3 * k + 2]);
      maxW = Math.max(maxW, hom[3 * k + 2]);
    }
    poleLabels.length = 0;
    for (let j = 0; j < poleCount; j++) poleLabels.push(t("negativeWeights.poleLabel", { t: fmt(poles[j]) }));
    // P(1/2) by the division, and whether any finite sample leaves the triangle P₀P₁P₂.
    const mid = (HOM_SAMPLES - 1) / 2;
    const wMid = hom[3 * mid + 2];
    middle = Math.abs(wMid) > ZERO_W ? [hom[3 * mid] / wMid, hom[3 * mid + 1] / wMid] : null;
    outsideHull = poleCount > 0;
    for (let k = 0; k < HOM_SAMPLES && !outsideHull; k++) {
      const w = hom[3 * k + 2];
      if (Math.abs(w) > ZERO_W && !inTriangle(hom[3 * k] / w, hom[3 * k + 1] / w, work.points)) outsideHull = true;
    }
    syncPanels();
  }

  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const w = r.width;
    const h = r.height;
    layoutPlot(w, h, r.scale);

    // The convex hull (the control triangle) and the control polygon.
    r.beginPath();
    r.moveTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
    r.lineTo(v.sx(pts[1][0]), v.sy(pts[1][1]));
    r.lineTo(v.sx(pts[2][0]), v.sy(pts[2][1]));
    r.closePath();
    r.paint(theme.helperFill);
    r.beginPath();
    r.moveTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
    r.lineTo(v.sx(pts[1][0]), v.sy(pts[1][1]));
    r.lineTo(v.sx(pts[2][0]), v.sy(pts[2][1]));
    r.paint(theme.polygon);

    // The caption first: marks drawn later stay on top of its halo.
    const s = r.scale;
    drawCaption(r, t(samples ? "negativeWeights.figureAccepted" : "negativeWeights.figureRefused"), 12 * s, 16 * s, samples ? theme.labelSmall : theme.labelBold, r.width - 24 * s, "middle");

    exitCount = 0;
    if (samples) {
      // Accepted: the core's rational curve.
      r.beginPath();
      for (let k = 0; k < CURVE_SAMPLES; k++) {
        if (k === 0) r.moveTo(v.sx(samples[0]), v.sy(samples[1]));
        else r.lineTo(v.sx(samples[2 * k]), v.sy(samples[2 * k + 1]));
      }
      r.paint(theme.curve);
    } else {
      drawProjected(r, v, -CLIP_MARGIN, -CLIP_MARGIN, w + CLIP_MARGIN, plot.top + CLIP_MARGIN, theme.splitRight);
    }
    handles.draw(r, v);

    // Where the path runs off to infinity (below the caption line).
    for (let j = 0; j < exitCount; j++) {
      const x = Math.min(Math.max(exits[2 * j], EDGE_PX * r.scale), w - EDGE_PX * r.scale);
      const y = Math.min(Math.max(exits[2 * j + 1], CAPTION_PX * r.scale), plot.top - EDGE_PX * r.scale);
      r.text(t("negativeWeights.infinity"), x, y, theme.labelPoint, "center", "middle");
    }
    if (middle) {
      r.point(v.sx(middle[0]), v.sy(middle[1]), theme.pointOnCurve);
      r.text(t("negativeWeights.middleLabel"), v.sx(middle[0]) + 9 * r.scale, v.sy(middle[1]), theme.labelPoint, "left", "middle");
    }
    drawPlot(r, theme, w, h);
  }

  /**
   * The central projection of the homogeneous samples, (X/W, Y/W), clipped to the figure;
   * segments across a sign change of W (a pole) are left out. Where a piece leaves or enters the
   * figure is remembered (up to MAX_EXITS) for the "∞" marks.
   */
  function drawProjected(r, v, x0, y0, x1, y1, style) {
    r.beginPath();
    let pen = false;
    for (let k = 0; k + 1 < HOM_SAMPLES; k++) {
      const wa = hom[3 * k + 2];
      const wb = hom[3 * k + 5];
      if (Math.abs(wa) <= ZERO_W || Math.abs(wb) <= ZERO_W || (wa > 0) !== (wb > 0)) {
        pen = false;
        continue;
      }
      const ax = v.sx(hom[3 * k] / wa);
      const ay = v.sy(hom[3 * k + 1] / wa);
      const bx = v.sx(hom[3 * k + 3] / wb);
      const by = v.sy(hom[3 * k + 4] / wb);
      if (!clipSegment(ax, ay, bx, by, x0, y0, x1, y1, clipScratch)) {
        pen = false;
        continue;
      }
      const entered = clipScratch[0] !== ax || clipScratch[1] !== ay;
      if (!pen || entered) {
        r.moveTo(clipScratch[0], clipScratch[1]);
        if (entered) addExit(clipScratch[0], clipScratch[1]);
      }
      r.lineTo(clipScratch[2], clipScratch[3]);
      pen = clipScratch[2] === bx && clipScratch[3] === by;
      if (!pen) addExit(clipScratch[2], clipScratch[3]);
    }
    r.paint(style);
  }

  function addExit(x, y) {
    if (exitCount >= MAX_EXITS) return;
    exits[2 * exitCount] = x;
    exits[2 * exitCount + 1] = y;
    exitCount += 1;
  }

  // ------------------------------------------------------------ the plot of w(t)
  function layoutPlot(width, height, scale) {
    plot.top = height - plotHeight(height);
    plot.x0 = PLOT_MARGIN.left * scale;
    plot.x1 = width - PLOT_MARGIN.right * scale;
    plot.y0 = height - PLOT_MARGIN.bottom * scale; // value lo
    plot.y1 = plot.top + PLOT_MARGIN.top * scale; // value hi
  }

  const ptx = (tValue) => plot.x0 + tValue * (plot.x1 - plot.x0);
  const pty = (value) => plot.y0 - ((value - plot.lo) / (plot.hi - plot.lo)) * (plot.y0 - plot.y1);

  function drawPlot(r, theme, w, h) {
    const s = r.scale;
    r.beginPath();
    r.rect(0, plot.top, w, h - plot.top);
    r.paint(theme.plotBackground);
    r.beginPath();
    r.moveTo(0, plot.top);
    r.lineTo(w, plot.top);
    r.paint(theme.axis);

    // Axes: t from 0 to 1 along w = 0, the value axis on the left.
    const zero = pty(0);
    r.beginPath();
    r.moveTo(plot.x0, plot.y1);
    r.lineTo(plot.x0, plot.y0);
    r.moveTo(plot.x0, zero);
    r.lineTo(plot.x1, zero);
    for (let k = 0; k <= 2; k++) {
      r.moveTo(ptx(k / 2), zero);
      r.lineTo(ptx(k / 2), zero + TICK_PX * s);
    }
    r.paint(theme.axis);
    r.beginPath();
    r.moveTo(plot.x0, pty(1));
    r.lineTo(plot.x1, pty(1));
    r.paint(theme.helper);
    r.text("0", plot.x0 - (TICK_PX + 2) * s, zero, theme.labelSmall, "right", "middle");
    r.text("1", plot.x0 - (TICK_PX + 2) * s, pty(1), theme.labelSmall, "right", "middle");
    if (plot.lo < -PLOT_PAD) r.text(loLabel, plot.x0 - (TICK_PX + 2) * s, plot.y0, theme.labelSmall, "right", "middle");
    r.text(t("negativeWeights.tickHalf"), ptx(0.5), zero + (TICK_PX + 2) * s, theme.labelSmall, "center", "top");
    r.text(t("negativeWeights.axisT"), plot.x1 + 4 * s, zero, theme.labelSmall, "left", "middle");
    r.text(t("negativeWeights.plotTitle"), plot.x0 + 6 * s, plot.top + 8 * s, theme.labelSmall, "left", "top");

    // w(t): solid where positive, dashed where negative.
    for (let pass = 0; pass < 2; pass++) {
      r.beginPath();
      let pen = false;
      for (let k = 0; k + 1 < HOM_SAMPLES; k++) {
        const wa = hom[3 * k + 2];
        const negative = (wa + hom[3 * k + 5]) / 2 < 0;
        if (negative !== (pass === 1)) {
          pen = false;
          continue;
        }
        if (!pen) r.moveTo(ptx(k / (HOM_SAMPLES - 1)), pty(wa));
        r.lineTo(ptx((k + 1) / (HOM_SAMPLES - 1)), pty(hom[3 * k + 5]));
        pen = true;
      }
      r.paint(pass === 0 ? theme.curve : theme.splitRight);
    }

    // The poles on the t axis.
    for (let j = 0; j < poleCount; j++) {
      const x = ptx(poles[j]);
      r.beginPath();
      r.moveTo(x, plot.y1);
      r.lineTo(x, plot.y0);
      r.paint(theme.marker);
      r.point(x, zero, theme.pointOnCurve);
      // Labels point inward (toward t = 1/2), one line apart so near poles do not collide.
      const align = poles[j] < 0.5 ? "left" : "right";
      r.text(poleLabels[j], x + (align === "left" ? 6 : -6) * s, plot.y1 + (2 + POLE_LINE_PX * j) * s, theme.labelPoint, align, "top");
    }
  }

  // ------------------------------------------------------------ panels
  function syncPanels() {
    const w1 = work.w1;
    // The plot's value range: w = 0 and w = 1 always visible.
    const lo = Math.min(0, minW);
    const hi = Math.max(1, maxW);
    const pad = PLOT_PAD * (hi - lo);
    plot.lo = lo - pad;
    plot.hi = hi + pad;
    loLabel = fmt(minW < 0 ? minW : 0, 2);

    libraryText.textContent = refusal ? t("negativeWeights.libraryRefuses", { message: refusal }) : t("negativeWeights.libraryAccepts");
    libraryText.dataset.refused = String(!!refusal);
    const list = Array.from(poles, (p) => fmt(p)).join(", ");
    polesText.textContent = poleCount ? t(poleCount === 1 ? "negativeWeights.pole" : "negativeWeights.poles", { count: poleCount, list }) : t("negativeWeights.noPoles");
    polesText.dataset.poles = String(poleCount);
    polesText.dataset.poleTs = Array.from(poles).join(",");
    polesText.dataset.poleDirections = Array.from(poleDirections).join(",");
    polesText.dataset.minW = String(minW);
    hullText.textContent = t(outsideHull ? "negativeWeights.outside" : "negativeWeights.inside");
    hullText.dataset.outsideHull = String(outsideHull);
    hullText.dataset.middle = middle ? `${middle[0]},${middle[1]}` : "";

    const [p0, p1, p2] = work.points;
    view.setLabel(t("negativeWeights.aria", {
      p0: `(${fmt(p0[0], 2)}, ${fmt(p0[1], 2)})`,
      p1: `(${fmt(p1[0], 2)}, ${fmt(p1[1], 2)})`,
      p2: `(${fmt(p2[0], 2)}, ${fmt(p2[1], 2)})`,
      w: fmt(w1, 2),
      verdict: refusal ? t("negativeWeights.ariaRefused", { message: refusal }) : t("negativeWeights.ariaAccepted"),
      poles: poleCount ? t("negativeWeights.ariaPoles", { count: poleCount, list }) : t("negativeWeights.ariaNoPoles", { min: fmt(minW, 2) }),
      hull: t(outsideHull ? "negativeWeights.ariaOutside" : "negativeWeights.ariaInside"),
    }));

    // Formula: the curve, its denominator, where that vanishes, the hull argument.
    const wTex = fmt(w1, 2);
    const product = 1 / (2 * (1 - w1)); // t(1 − t) at a zero of w(t)
    const zeros = w1 <= -1 && poleCount > 0 // the values are the core's roots (a double one at w₁ = −1)
      ? `w(t) = 0 \\iff t(1-t) = \\tfrac{1}{2(1-w_1)} = ${fmt(product)} \\iff t = \\tfrac12 \\pm \\tfrac12\\sqrt{1 - 4\\cdot ${fmt(product)}} = ${fmt(poles[0])},\\ ${fmt(poles[poleCount - 1])}\\quad\\text{(poles)}`
      : `\\min_t w(t) = w(\\tfrac12) = \\tfrac{1 + w_1}{2} = ${fmt((1 + w1) / 2)} > 0\\quad\\text{(no pole; } w(t) = 0 \\text{ needs } w_1 \\le -1\\text{)}`;
    formula.set([
      `P(t) = \\frac{(1-t)^2P_0 + 2t(1-t)\\,w_1P_1 + t^2P_2}{w(t)},\\qquad w_0 = w_2 = 1,\\ w_1 = ${wTex}`,
      `w(t) = (1-t)^2 + 2t(1-t)\\,w_1 + t^2 = 1 - 2(1-w_1)\\,t(1-t)`,
      zeros,
      `P(\\tfrac12) = \\frac{P_0 + 2w_1P_1 + P_2}{2 + 2w_1} = ${middle ? `(${fmt(middle[0])},\\ ${fmt(middle[1])})` : "\\infty"}`,
      `w_i > 0 \\Rightarrow \\text{the coefficients } \\tfrac{B_i(t)\\,w_i}{w(t)} \\in [0, 1] \\text{ sum to 1: } P(t) \\text{ stays in the convex hull; } w_1 < 0 \\text{ breaks that}`,
    ]);
  }

  recompute();
  syncStatus();

  // ------------------------------------------------------------ contract
  return {
    update(state) {
      sl.rationalPoles(flatten(state.points), 2, weightsOf(state.w1), 2); // throws first
      curve?.free();
      curve = null;
      work = structuredClone(state);
      ensureCurve();
      handles.forgetPointer();
      wSlider.set(work.w1);
      dirty = true;
      view.requestDraw();
      recompute();
      syncStatus();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve?.free();
    },
  };
}

/**
 * Liang–Barsky: clips the segment (ax, ay)–(bx, by) to the box [x0, x1] × [y0, y1]; writes the
 * visible part into `out` (x, y, x, y) and returns false when nothing is visible.
 */
function clipSegment(ax, ay, bx, by, x0, y0, x1, y1, out) {
  const dx = bx - ax;
  const dy = by - ay;
  let t0 = 0;
  let t1 = 1;
  for (let k = 0; k < 4; k++) {
    const p = k === 0 ? -dx : k === 1 ? dx : k === 2 ? -dy : dy;
    const q = k === 0 ? ax - x0 : k === 1 ? x1 - ax : k === 2 ? ay - y0 : y1 - ay;
    if (p === 0) {
      if (q < 0) return false;
    } else {
      const r = q / p;
      if (p < 0) t0 = Math.max(t0, r);
      else t1 = Math.min(t1, r);
      if (t0 > t1) return false;
    }
  }
  out[0] = t0 === 0 ? ax : ax + t0 * dx;
  out[1] = t0 === 0 ? ay : ay + t0 * dy;
  out[2] = t1 === 1 ? bx : ax + t1 * dx;
  out[3] = t1 === 1 ? by : ay + t1 * dy;
  return true;
}

/** True when (x, y) lies in the triangle of the three points (edges included, with a tolerance). */
function inTriangle(x, y, points) {
  const x0 = points[0][0];
  const y0 = points[0][1];
  const x1 = points[1][0];
  const y1 = points[1][1];
  const x2 = points[2][0];
  const y2 = points[2][1];
  const area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  const scale = Math.abs(area) || 1;
  const d0 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) * Math.sign(area || 1);
  const d1 = ((x2 - x1) * (y - y1) - (x - x1) * (y2 - y1)) * Math.sign(area || 1);
  const d2 = ((x0 - x2) * (y - y2) - (x - x2) * (y0 - y2)) * Math.sign(area || 1);
  const eps = -HULL_TOLERANCE * scale;
  return d0 >= eps && d1 >= eps && d2 >= eps;
}

