/**
 * Demo 2 (syllabus §2): the Bernstein basis. A Bézier curve on top, and below it, in the same
 * canvas (so SVG/PNG exports hold both), the plot of every B_i^n on t ∈ [0, 1], each in the
 * colour of its control point. A marker at t lists the weights B_i^n(t) and their sum (= 1);
 * hovering a basis function (in the plot or the table) or selecting a control point shows where
 * that point acts most: the single maximum of B_i^n at t = i/n and the curve point P(i/n).
 *
 * Same habits as the reference demo (de-casteljau.js): the curve lives in wasm and is updated in
 * place while dragging, the plot comes from one `bernsteinBasis(n, count)` call per degree, the
 * curve from one `sampleUniform` per change, weights from `bernstein(n, i, t)`; the draw path
 * allocates nothing and replaced wasm objects are freed.
 */
import { Handles, pointHandles, placeLabelAway } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber } from "../lib/validate.js";
import { fmt, subscript, superscript, simpleFraction, exactFraction, fractionText, fractionTex, allIntegers, degreeName } from "../lib/format.js";
import { CYCLE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf, nearestGraph } from "../lib/geometry.js";
import { pointListActions, pointButtons } from "../lib/point-list.js";
import { Player } from "../lib/player.js";
import { titledTable } from "../lib/table.js";
import { BasisPlotPointer, drawGraph } from "../lib/basis-plot.js";
import { flatPath, pointsPath } from "../lib/draw.js";

export const id = "bernstein";
/** Prefix of this demo's keys in strings.js. */
export const strings = "bernstein";
export const title = t("bernstein.title");
export const summary = t("bernstein.summary");
/** Syllabus section. */
export const section = 2;

/** The worked example of the Greek notes (syllabus §2) at t = 1/4: weights 27/64, 27/64, 9/64, 1/64. */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 2], [6, 4], [8, 2]].map(Object.freeze)),
  t: 0.25,
});

/** Fewest and most control points (degree 1 … 10). */
export const MIN_POINTS = 2;
export const MAX_POINTS = 11;
/**
 * Samples along the curve and along each basis function: the same count, so sample k of both
 * is at the same t = k / (SAMPLES − 1) (the highlighted band on the curve uses that).
 */
const SAMPLES = 201;
/** Fitting leaves this fraction of the height free above and below for the handles' labels (the curve area is short). */
const LABEL_ROOM = 0.08;
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;

/**
 * The plot takes this fraction of the canvas height, below the curve; at least PLOT_MIN_PX,
 * but never more than PLOT_FRACTION_SHORT of a short canvas (gallery thumbnails).
 */
const PLOT_FRACTION = 0.4;
const PLOT_MIN_PX = 150;
const PLOT_FRACTION_SHORT = 0.55;
/** Margins of the plot frame inside its strip, CSS px at scale 1 (labels live there). */
const PLOT_MARGIN = Object.freeze({ top: 30, right: 22, bottom: 34, left: 40 });
/** Tick labels i/n on the t axis only while they are at least this far apart (CSS px). */
const TICK_LABEL_MIN_GAP = 34;
/** Curve names B_i^n are written at the peaks up to this degree (beyond, they crowd). */
const NAME_LABELS_MAX_DEGREE = 6;
/** A pointer this close (CSS px, vertically) to a basis curve highlights it. */
const PLOT_HOVER_PX = 14;
/** Dragging t in the plot snaps to a tick i/n within this many CSS px. */
const TICK_SNAP_PX = 5;
/** The band on the curve marks where the highlighted B_i^n is at least this fraction of its maximum. */
const BAND_FRACTION = 0.5;
/** Sums in the formula panel switch from fractions to decimals beyond this common denominator. */
const FORMULA_MAX_DENOMINATOR = 4096;
/** Length of a tick mark on the axes, CSS px. */
const TICK_PX = 5;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "t"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "t", { min: 0, max: 1 });
}

/** Binomial coefficient C(n, i), for the formula panel only (the weights come from the core). */
function binomial(n, i) {
  let c = 1;
  for (let k = 1; k <= i; k++) c = (c * (n - i + k)) / k;
  return Math.round(c);
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags and animation, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = new sl.BezierCurve(flatten(work.points), 2);

  // Derived data, recomputed only when the geometry, the degree or t changed.
  let samples = null; // curve.sampleUniform(SAMPLES)
  let basis = null; // sl.bernsteinBasis(n, SAMPLES), i-major
  let basisDegree = -1;
  let peakTs = null; // [0, 1/n, …, 1], made per degree
  let peakPoints = null; // curve.sample(peakTs): P(i/n)
  let point = null; // curve.evaluate(t)
  let geometryDirty = true;
  let tDirty = true;
  const values = new Float64Array(MAX_POINTS); // B_i^n(t), from the core
  const mirrored = new Float64Array(MAX_POINTS); // B_{n-i}^n(1 - t), from the core
  const peakValues = new Float64Array(MAX_POINTS); // B_i^n(i/n), from the core
  const insetScratch = [0, 0, 0, 0];
  const plot = { x0: 0, y0: 0, x1: 0, y1: 0, top: 0 }; // frame (CSS px) and the strip's top
  const handleLabels = []; // "P₀" …
  const basisNames = []; // "B₀³" … per (n, i)
  const peakLabels = []; // "max at t = 1/3" per (n, i)
  const peakPointLabels = []; // "P(1/3)" per (n, i)
  const tickLabels = []; // "1/3" per (n, i)
  let markerLabel = ""; // "t = 1/4", rebuilt when t changes

  // What is highlighted: a basis curve under the pointer in the plot, a table row, or a handle.
  let shownHighlight = -2; // the highlight the panels show (-2: not yet synced)

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => paddedBounds(work.points, LABEL_ROOM), insets });
  // A taller figure than the default: the curve and the plot share it.
  ctx.slots.figure.classList.add("sl-figure-tall");

  // The plot claims its frame before the handles see the pointer (a handle hidden under the
  // plot cannot be grabbed there; pan to reach it): press or drag there to set t.
  const plotPointer = new BasisPlotPointer(view, {
    inPlot,
    graphAt: basisAt,
    pick: (x, final) => setT(tAtPixel(x), final),
    press: () => player.stop(),
    enter: () => handles.leave(),
  });

  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => edits.add(i),
    remove: (i) => edits.remove(i),
  });

  /** The canvas strip below the world window: [top, right, bottom, left] (scratch, no allocation). */
  function insets(width, height) {
    insetScratch[2] = plotHeight(height);
    return insetScratch;
  }

  /** Height of the plot strip: PLOT_FRACTION of the canvas, at least PLOT_MIN_PX while that leaves the curve half. */
  function plotHeight(height) {
    return Math.max(Math.round(height * PLOT_FRACTION), Math.min(PLOT_MIN_PX, Math.round(height * PLOT_FRACTION_SHORT)));
  }

  /** Lays out the plot frame for a canvas of width × height CSS px at text scale `scale`. */
  function layoutPlot(width, height, scale) {
    plot.top = height - plotHeight(height);
    plot.x0 = PLOT_MARGIN.left * scale;
    plot.x1 = width - PLOT_MARGIN.right * scale;
    plot.y0 = height - PLOT_MARGIN.bottom * scale; // value 0 (y down on screen)
    plot.y1 = plot.top + PLOT_MARGIN.top * scale; // value 1
  }

  const px = (tValue) => plot.x0 + tValue * (plot.x1 - plot.x0);
  const py = (value) => plot.y0 - value * (plot.y0 - plot.y1);

  function inPlot(x, y) {
    layoutPlot(view.width, view.height, view.renderer.scale);
    return x >= plot.x0 - TICK_SNAP_PX && x <= plot.x1 + TICK_SNAP_PX && y >= plot.y1 - TICK_SNAP_PX && y <= plot.y0 + TICK_SNAP_PX;
  }

  /** t under canvas x in the plot: snapped to a tick i/n nearby, else to the slider's step. */
  function tAtPixel(x) {
    layoutPlot(view.width, view.height, view.renderer.scale);
    const n = work.points.length - 1;
    const raw = Math.min(1, Math.max(0, (x - plot.x0) / (plot.x1 - plot.x0)));
    const tick = Math.round(raw * n);
    if (Math.abs(px(tick / n) - x) <= TICK_SNAP_PX) return tick / n;
    return Number((Math.round(raw / T_SLIDER_STEP) * T_SLIDER_STEP).toFixed(3));
  }

  /** The basis function whose graph passes nearest (vertically) to canvas point (x, y), or -1. */
  function basisAt(x, y) {
    if (!basis) return -1;
    const raw = Math.min(1, Math.max(0, (x - plot.x0) / (plot.x1 - plot.x0)));
    return nearestGraph(basis, work.points.length, SAMPLES, Math.round(raw * (SAMPLES - 1)), y, py, PLOT_HOVER_PX);
  }


  // ------------------------------------------------------------ side panel
  const tSlider = slider({
    label: t("control.t"),
    inputLabel: t("control.t.input"),
    name: "t",
    min: 0,
    max: 1,
    step: T_SLIDER_STEP,
    value: work.t,
    onChange: (value, final) => {
      player.stop();
      setT(value, final);
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const player = new Player(view, { get: () => work.t, set: (value, final) => setT(value, final), stopped: () => ctx.commit(work) });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: (i) => edits.add(i), remove: (i) => edits.remove(i), selected: () => handles.selected });
  const sumText = el("p", { class: "sl-note", dataset: { info: "sum" } });
  const peakText = el("p", { class: "sl-note", dataset: { info: "peak" }, "aria-live": "polite" });
  ctx.slots.controls.append(
    group(null, tSlider.element, player.element, sumText),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
    group(null, peakText),
  );

  // ------------------------------------------------------------ formula and table (the legend)
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("bernstein");
  ctx.slots.details.append(tableTitle, tableWrap);
  let tableDegree = -1;
  let tableRows = []; // per i: { row, value, valueDecimal, mirror, mirrorDecimal, peak }
  let sumCells = null;

  function setT(value, final) {
    work.t = value;
    tSlider.set(value);
    tDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  // ------------------------------------------------------------ edits

  /** Replaces the wasm curve after the number of points changed (the old one is freed). */
  function rebuild() {
    const next = new sl.BezierCurve(flatten(work.points), 2);
    curve.free();
    curve = next;
    geometryDirty = true;
    view.requestDraw();
  }

  const edits = pointListActions({ ctx, work, view, handles, min: MIN_POINTS, max: MAX_POINTS, strings: "bernstein", rebuild });

  // ------------------------------------------------------------ core data
  /** Asks the core for the samples, the basis and the weights when something changed. */
  function recompute() {
    const n = work.points.length - 1;
    let changed = false;
    if (basisDegree !== n) {
      basis = sl.bernsteinBasis(n, SAMPLES); // one call: every B_i^n at SAMPLES t values
      basisDegree = n;
      const ts = new Float64Array(n + 1);
      for (let i = 0; i <= n; i++) {
        ts[i] = i / n;
        peakValues[i] = sl.bernstein(n, i, i / n);
      }
      peakTs = ts;
      geometryDirty = true;
    }
    if (geometryDirty) {
      samples = curve.sampleUniform(SAMPLES);
      peakPoints = curve.sample(peakTs); // P(i/n) for every i, one call
    }
    if (geometryDirty || tDirty) {
      point = curve.evaluate(work.t);
      for (let i = 0; i <= n; i++) {
        values[i] = sl.bernstein(n, i, work.t);
        mirrored[i] = sl.bernstein(n, n - i, 1 - work.t);
      }
      const f = simpleFraction(work.t);
      markerLabel = t("bernstein.marker", { t: f ? fractionText(f) : fmt(work.t) });
      changed = true;
    }
    geometryDirty = tDirty = false;
    const hi = plotPointer.highlighted(handles);
    if (changed || hi !== shownHighlight) {
      shownHighlight = hi;
      syncPanels(hi);
    }
  }

  // ------------------------------------------------------------ drawing
  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;
    const hi = shownHighlight;
    const cycle = theme.basisStroke.length;

    // ---- the curve area (world window, above the plot)
    pointsPath(r, v, pts, 0, n + 1);
    r.paint(theme.polygon);

    // Where the highlighted B_i^n is at least half its maximum: a band in its colour under the curve.
    if (hi >= 0) {
      const threshold = BAND_FRACTION * peakValues[hi];
      const offset = hi * SAMPLES;
      let open = false;
      r.beginPath();
      for (let k = 0; k < SAMPLES; k++) {
        if (basis[offset + k] >= threshold) {
          const x = v.sx(samples[2 * k]);
          const y = v.sy(samples[2 * k + 1]);
          if (open) r.lineTo(x, y);
          else r.moveTo(x, y);
          open = true;
        } else {
          open = false;
        }
      }
      r.paint(theme.basisBand[hi % cycle]);
    }

    flatPath(r, v, samples, 0, SAMPLES);
    r.paint(theme.curve);

    // Every control point ringed in its basis function's colour.
    for (let i = 0; i <= n; i++) r.point(v.sx(pts[i][0]), v.sy(pts[i][1]), theme.basisRing[i % cycle]);

    // The highlighted point's peak: P(i/n) on the curve, joined to P_i.
    let peakX = 0;
    let peakY = 0;
    if (hi >= 0) {
      peakX = v.sx(peakPoints[2 * hi]);
      peakY = v.sy(peakPoints[2 * hi + 1]);
      r.beginPath();
      r.moveTo(v.sx(pts[hi][0]), v.sy(pts[hi][1]));
      r.lineTo(peakX, peakY);
      r.paint(theme.helper);
    }

    handles.draw(r, v);

    const pointX = v.sx(point[0]);
    const pointY = v.sy(point[1]);
    r.point(pointX, pointY, theme.pointOnCurve);
    placeLabelAway(r, v, work.points, t("bernstein.pointLabel"), pointX, pointY, theme.labelPoint, theme.pointOnCurve.radius * r.scale);
    if (hi >= 0) {
      r.point(peakX, peakY, theme.basisPoint[hi % cycle]);
      placeLabelAway(r, v, work.points, peakPointLabel(n, hi), peakX, peakY, theme.labelBold, theme.basisPoint[0].radius * r.scale);
    }

    // ---- the plot strip (screen space, below the world window; covers anything panned into it)
    const w = r.width;
    const h = r.height;
    layoutPlot(w, h, r.scale);
    r.beginPath();
    r.rect(0, plot.top, w, h - plot.top);
    r.paint(theme.plotBackground);
    r.beginPath();
    r.moveTo(0, plot.top);
    r.lineTo(w, plot.top);
    r.paint(theme.axis);

    // Axes: t from 0 to 1, value from 0 to 1, a dashed line at 1, ticks at i/n.
    r.beginPath();
    r.moveTo(plot.x0, plot.y1);
    r.lineTo(plot.x0, plot.y0);
    r.lineTo(plot.x1, plot.y0);
    r.paint(theme.axis);
    r.beginPath();
    r.moveTo(plot.x0, plot.y1);
    r.lineTo(plot.x1, plot.y1);
    r.paint(theme.helper);
    const tickGap = (plot.x1 - plot.x0) / n;
    const labelEvery = Math.max(1, Math.ceil((TICK_LABEL_MIN_GAP * r.scale) / tickGap));
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      r.moveTo(px(i / n), plot.y0);
      r.lineTo(px(i / n), plot.y0 + TICK_PX * r.scale);
    }
    r.paint(theme.axis);
    for (let i = 0; i <= n; i++) {
      // Every labelEvery-th tick and the last one (dropping a labelled tick too close to it).
      if (i !== n && (i % labelEvery !== 0 || n - i < labelEvery)) continue;
      r.text(tickLabel(n, i), px(i / n), plot.y0 + (TICK_PX + 2) * r.scale, theme.labelSmall, "center", "top");
    }
    r.text(t("bernstein.axisValue0"), plot.x0 - (TICK_PX + 2) * r.scale, plot.y0, theme.labelSmall, "right", "middle");
    r.text(t("bernstein.axisValue1"), plot.x0 - (TICK_PX + 2) * r.scale, plot.y1, theme.labelSmall, "right", "middle");
    r.text(t("bernstein.axisT"), plot.x1 + (TICK_PX + 2) * r.scale, plot.y0, theme.labelSmall, "left", "middle");

    // The basis functions, from the core's table (highlighted one last, on top).
    const sampleX = (k) => px(k / (SAMPLES - 1));
    for (let i = 0; i <= n; i++) if (i !== hi) drawGraph(r, basis, i, SAMPLES, sampleX, py, theme.basisStroke[i % cycle]);
    if (hi >= 0) drawGraph(r, basis, hi, SAMPLES, sampleX, py, theme.basisHover[hi % cycle]);

    // Names at the peaks (B_0 at the left end, B_n at the right end).
    if (n <= NAME_LABELS_MAX_DEGREE) {
      for (let i = 0; i <= n; i++) {
        const align = i === 0 ? "left" : i === n ? "right" : "center";
        const x = px(i / n) + (i === 0 ? 4 : i === n ? -4 : 0) * r.scale;
        r.text(basisName(n, i), x, py(peakValues[i]) - 5 * r.scale, i === hi ? theme.labelBold : theme.labelSmall, align, "bottom");
      }
    }

    // The highlighted function's maximum at t = i/n.
    if (hi >= 0) {
      const x = px(hi / n);
      const y = py(peakValues[hi]);
      r.beginPath();
      r.moveTo(x, y);
      r.lineTo(x, plot.y0);
      r.paint(theme.helper);
      r.point(x, y, theme.basisPoint[hi % cycle]);
      const align = hi === 0 ? "left" : hi === n ? "right" : "center";
      const dx = (hi === 0 ? 8 : hi === n ? -8 : 0) * r.scale;
      r.text(peakLabel(n, hi), x + dx, (y + plot.y0) / 2, theme.labelBold, align, "middle");
    }

    // The marker at t, with the weights B_i^n(t) as dots.
    const mx = px(work.t);
    r.beginPath();
    r.moveTo(mx, plot.y1 - 2 * r.scale);
    r.lineTo(mx, plot.y0);
    r.paint(theme.marker);
    for (let i = 0; i <= n; i++) r.point(mx, py(values[i]), theme.basisPoint[i % cycle]);
    const markerAlign = work.t < 0.1 ? "left" : work.t > 0.9 ? "right" : "center";
    r.text(markerLabel, mx, plot.y1 - 4 * r.scale, theme.labelPoint, markerAlign, "bottom");
  }

  /** Cached label strings, keyed by (n, i). */
  const key = (n, i) => n * (MAX_POINTS + 1) + i;
  function basisName(n, i) {
    return (basisNames[key(n, i)] ??= `B${subscript(i)}${superscript(n)}`);
  }
  function tickLabel(n, i) {
    return (tickLabels[key(n, i)] ??= fractionText(exactFraction(i / n, n)));
  }
  function peakLabel(n, i) {
    return (peakLabels[key(n, i)] ??= t("bernstein.peakLabel", { t: tickLabel(n, i) }));
  }
  function peakPointLabel(n, i) {
    return (peakPointLabels[key(n, i)] ??= t("bernstein.peakPointLabel", { t: tickLabel(n, i) }));
  }

  // ------------------------------------------------------------ panels (formula, table, notes, label)
  function syncPanels(hi) {
    const pts = work.points;
    const n = pts.length - 1;
    degreeText.textContent = t("bernstein.degree", { n, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;

    // Exact fractions when t is a simple fraction: B_i^n(t) is then k / den^n. The point needs
    // integer control points too.
    const tFraction = simpleFraction(work.t);
    const weightDen = tFraction ? tFraction.den ** n : 0;
    const exactPoints = tFraction && allIntegers(pts.flat());
    const tTex = tFraction ? fractionTex(tFraction) : fmt(work.t);
    const tText = tFraction ? fractionText(tFraction) : fmt(work.t);
    const weight = (value, tex) => {
      const f = tFraction ? exactFraction(value, weightDen) : null;
      if (!f) return fmt(value);
      return tex ? fractionTex(f) : fractionText(f);
    };
    const coordinate = (value, den, tex) => {
      const f = den ? exactFraction(value, den) : null;
      if (!f) return fmt(value);
      return tex ? fractionTex(f) : fractionText(f);
    };
    let sum = 0;
    for (let i = 0; i <= n; i++) sum += values[i];

    // Formula panel: the definition, one function with its numbers, the sum, the curve point.
    const oneMinusTex = tFraction ? fractionTex({ num: tFraction.den - tFraction.num, den: tFraction.den }) : fmt(1 - work.t);
    // The highlighted function, else the one whose maximum i/n lies nearest t.
    const focus = hi >= 0 ? hi : Math.round(work.t * n);
    const terms = [];
    const weighted = [];
    // Long sums read better in decimals once the common denominator grows large (the table keeps fractions).
    const compact = weightDen > FORMULA_MAX_DENOMINATOR;
    for (let i = 0; i <= n; i++) {
      const w = compact ? fmt(values[i]) : weight(values[i], true);
      terms.push(w);
      weighted.push(`${w}\\,P_{${i}}`);
    }
    const pointDen = exactPoints && !compact ? weightDen : 0;
    const pointTex = `\\left(${coordinate(point[0], pointDen, true)},\\ ${coordinate(point[1], pointDen, true)}\\right)`;
    const approx = pointDen && (!Number.isInteger(point[0]) || !Number.isInteger(point[1])) ? `\\approx (${fmt(point[0])},\\ ${fmt(point[1])})` : "";
    const peakT = fractionTex(exactFraction(focus / n, n));
    // t^i and (1 − t)^(n−i) written out (exact when t is a simple fraction): display only.
    const power = (num, den, k) => (tFraction ? fractionTex({ num: num ** k, den: den ** k }) : fmt((num / den) ** k));
    const tPower = tFraction ? power(tFraction.num, tFraction.den, focus) : power(work.t, 1, focus);
    const sPower = tFraction ? power(tFraction.den - tFraction.num, tFraction.den, n - focus) : power(1 - work.t, 1, n - focus);
    formula.set([
      `B_i^{${n}}(t) = \\binom{${n}}{i}\\, t^{i}\\,(1-t)^{${n}-i},\\qquad \\max_{[0,1]} B_i^{${n}} = B_i^{${n}}\\!\\left(\\tfrac{i}{${n}}\\right),\\qquad t = ${tTex}`,
      `B_{${focus}}^{${n}}(${tTex}) = \\binom{${n}}{${focus}} \\left(${tTex}\\right)^{${focus}} \\left(${oneMinusTex}\\right)^{${n - focus}} = ${binomial(n, focus)} \\cdot ${tPower} \\cdot ${sPower} = ${weight(values[focus], true)},\\qquad \\text{${t("bernstein.formulaPeak")}}\\ t = ${peakT}`,
      `\\sum_{i=0}^{${n}} B_i^{${n}}(${tTex}) = ${terms.join(" + ")} = ${weight(sum, true)}`,
      `P(${tTex}) = \\sum_{i=0}^{${n}} B_i^{${n}}(${tTex})\\,P_i = ${weighted.join(" + ")} = ${pointTex} ${approx}`,
    ]);

    // Table: one row per basis function (the legend), then the sum.
    if (tableDegree !== n) buildTable(n);
    setText(tableTitle, t("bernstein.tableCaption", { n, t: tText }));
    const valueTexts = [];
    for (let i = 0; i <= n; i++) {
      const cells = tableRows[i];
      const exact = weight(values[i], false);
      const decimal = fmt(values[i]);
      setText(cells.value, exact);
      setText(cells.valueDecimal, exact === decimal ? "" : `≈ ${decimal}`);
      const mirrorExact = weight(mirrored[i], false);
      const mirrorDecimal = fmt(mirrored[i]);
      setText(cells.mirror, mirrorExact);
      setText(cells.mirrorDecimal, mirrorExact === mirrorDecimal ? "" : `≈ ${mirrorDecimal}`);
      cells.row.classList.toggle("sl-highlight", i === hi);
      valueTexts.push(fmt(values[i]));
    }
    const sumExact = weight(sum, false);
    setText(sumCells.value, sumExact);
    setText(sumCells.valueDecimal, sumExact === fmt(sum) || /^\d+$/.test(sumExact) ? "" : `≈ ${fmt(sum)}`);
    setText(sumText, t("bernstein.sumNote", { count: n + 1, t: tText, sum: sumExact }));

    // Where the highlighted function acts most.
    let ariaPeak = "";
    if (hi >= 0) {
      const peakDen = exactPoints ? n ** n : 0;
      const x = coordinate(peakPoints[2 * hi], peakDen, false);
      const y = coordinate(peakPoints[2 * hi + 1], peakDen, false);
      setText(peakText, t("bernstein.peakNote", { b: basisName(n, hi), p: handleLabels[hi] ?? `P${subscript(hi)}`, t: tickLabel(n, hi), x, y }));
      ariaPeak = t("bernstein.ariaPeak", { b: basisName(n, hi), t: tickLabel(n, hi), x: fmt(peakPoints[2 * hi], 2), y: fmt(peakPoints[2 * hi + 1], 2) });
    } else {
      setText(peakText, t("bernstein.peakHint"));
    }
    view.setLabel(
      t("bernstein.aria", { kind: degreeName(n), count: n + 1, n, t: fmt(work.t), values: valueTexts.join(", "), sum: fmt(sum), x: fmt(point[0], 2), y: fmt(point[1], 2) }) + ariaPeak,
    );
  }

  /** Rebuilds the table's rows for degree n (only when the degree changed). */
  function buildTable(n) {
    tableDegree = n;
    tableRows = [];
    const head = el("tr", {},
      el("th", { scope: "col", text: t("bernstein.colFunction") }),
      el("th", { scope: "col", text: t("bernstein.colValue") }),
      el("th", { scope: "col", text: t("bernstein.colMirror") }),
      el("th", { scope: "col", text: t("bernstein.colPeak") }));
    const rows = [];
    for (let i = 0; i <= n; i++) {
      const cells = {
        value: el("span", { class: "sl-cell-value" }),
        valueDecimal: el("span", { class: "sl-cell-decimal" }),
        mirror: el("span", { class: "sl-cell-value" }),
        mirrorDecimal: el("span", { class: "sl-cell-decimal" }),
      };
      const peakValue = exactFraction(peakValues[i], n ** n) ?? exactFraction(peakValues[i], 1);
      const swatch = el("span", { class: "sl-swatch", "aria-hidden": "true" });
      swatch.style.background = CYCLE[i % CYCLE.length];
      const row = el("tr", { tabindex: "0", dataset: { index: String(i) } },
        el("th", { scope: "row" }, swatch, t("bernstein.rowName", { b: basisName(n, i), p: `P${subscript(i)}` })),
        el("td", { dataset: { cell: "value" } }, cells.value, cells.valueDecimal),
        el("td", { dataset: { cell: "mirror" } }, cells.mirror, cells.mirrorDecimal),
        el("td", { dataset: { cell: "peak" }, text: t("bernstein.peakCell", { t: tickLabel(n, i), value: peakValue ? fractionText(peakValue) : fmt(peakValues[i]) }) }));
      const enter = () => plotPointer.setRowHover(i);
      const leave = () => plotPointer.setRowHover(-1);
      row.addEventListener("pointerenter", enter);
      row.addEventListener("pointerleave", leave);
      row.addEventListener("focus", enter);
      row.addEventListener("blur", leave);
      cells.row = row;
      tableRows.push(cells);
      rows.push(row);
    }
    sumCells = { value: el("span", { class: "sl-cell-value" }), valueDecimal: el("span", { class: "sl-cell-decimal" }) };
    rows.push(el("tr", { dataset: { index: "sum" } },
      el("th", { scope: "row", text: t("bernstein.sumRow") }),
      el("td", { dataset: { cell: "value" } }, sumCells.value, sumCells.valueDecimal),
      el("td", {}),
      el("td", {})));
    table.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      player.stop();
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      plotPointer.reset();
      tSlider.set(work.t);
      geometryDirty = tDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      player.destroy();
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** The points' bounding box (the curve lies in their convex hull), taller by `room` × the height above and below. */
function paddedBounds(points, room) {
  const [x0, y0, x1, y1] = boundsOf(points);
  const pad = room * (y1 - y0);
  return [x0, y0 - pad, x1, y1 + pad];
}
