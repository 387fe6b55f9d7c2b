/**
 * Demo (syllabus §3): B-spline basis functions. The curve on top, below it in the same canvas
 * (so SVG/PNG exports hold everything) the plot of every N_{i,p} over the domain, each in the
 * colour of its control point, and under the plot the knot ruler (lib/knot-ruler.js) whose
 * knots can be dragged, merged (double click / Enter) and split (Delete). A marker at u lists
 * the values N_{i,p}(u), their sum (= 1) and the Cox–de Boor triangle (`basisTable(u)`, the
 * "lecture view" of the Italian notes); hovering a basis function (plot, table) or selecting a
 * control point highlights its support [u_i, u_{i+p+1}) in the plot and on the curve.
 *
 * Same habits as the reference demo (de-casteljau.js): the curve lives in wasm; a point drag
 * goes through `setControlPoint` (the basis does not change), a knot change rebuilds the curve
 * (the old one is freed); the plot comes from one `basisCurves(count)` call per knot change,
 * the curve from one `sampleUniform` per change, the values from `basis(u)` / `basisTable(u)`.
 * The draw path allocates nothing.
 *
 * Keeping the knot vector valid: changing the degree or the number of control points replaces
 * the knots by the clamped uniform vector of the core (`knotVector(points, 2, p, "clamped")`:
 * p + 1 zeros, 1 … n − p, p + 1 copies of n − p + 1), and u is clamped into the new domain.
 */
import { Handles, pointHandles, placeLabelAway } from "../lib/handles.js";
import { KnotRuler, raiseMultiplicity, lowerMultiplicity, knotText } from "../lib/knot-ruler.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, group, el, radios, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkNumbers } from "../lib/validate.js";
import { fmt, subscript, superscript, simpleFraction, fractionText, degreeName } from "../lib/format.js";
import { CYCLE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf, nearestGraph } from "../lib/geometry.js";
import { withPointAdded, withPointRemoved, pointButtons } from "../lib/point-list.js";
import { titledTable } from "../lib/table.js";
import { BasisPlotPointer, drawGraph } from "../lib/basis-plot.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { buildOrReport } from "../lib/wasm.js";

export const id = "bspline-basis";
/** Prefix of this demo's keys in strings.js. */
export const strings = "bsplineBasis";
export const title = t("bsplineBasis.title");
export const summary = t("bsplineBasis.summary");
/** Syllabus section. */
export const section = 3;

/**
 * The quadratic example of the Croatian notes (syllabus §3): p = 2, six control points,
 * U = [0, 0, 0, 1, 2, 3, 4, 4, 4]; at u = 5/2: N₂,₂ = 1/8, N₃,₂ = 3/4, N₄,₂ = 1/8.
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [1, 3], [3, 4], [5, 1], [7, 3], [8, 0]].map(Object.freeze)),
  degree: 2,
  knots: Object.freeze([0, 0, 0, 1, 2, 3, 4, 4, 4]),
  u: 2.5,
});

/** Fewest and most control points, and the degrees offered. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 10;
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
/**
 * Samples along the curve and along each basis function: the same count over the same domain,
 * so sample k of both is at the same u (the highlighted support on the curve uses that).
 */
const SAMPLES = 241;
/** Slider resolution for u, as a fraction of the domain's length. */
const U_SLIDER_RESOLUTION = 1 / 1000;
/** The plot takes this fraction of the canvas height (at least PLOT_MIN_PX), above the ruler. */
const PLOT_FRACTION = 0.27;
const PLOT_MIN_PX = 120;
/** Margins of the plot frame inside its strip, CSS px at scale 1 (labels live there). */
const PLOT_MARGIN = Object.freeze({ top: 38, bottom: 8 });
/** Left and right ends of the plot axis and of the knot ruler, CSS px at scale 1. */
const AXIS_LEFT = 40;
const AXIS_RIGHT = 34;
/** A pointer this close (CSS px, vertically) to a basis curve highlights it. */
const PLOT_HOVER_PX = 14;
/** Pressing in the plot snaps u to a knot this close (CSS px). */
const KNOT_SNAP_PX = 6;
/** Length of a tick mark on the value axis, CSS px. */
const TICK_PX = 5;
/** Basis functions are named at their peaks up to this many (beyond, the names crowd). */
const NAME_LABELS_MAX = 10;
/** Fill opacity of the highlighted support in the plot. */
const SUPPORT_ALPHA = 0.14;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "degree", "knots", "u"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "degree", { min: MIN_DEGREE, max: MAX_DEGREE, integer: true });
  const count = state.points.length;
  const p = state.degree;
  if (count < p + 1) throw new Error(t("bsplineBasis.fewPoints", { p, need: p + 1, count }));
  checkNumbers(state, "knots");
  const need = count + p + 1;
  if (state.knots.length !== need) throw new Error(t("bsplineBasis.knotCount", { count, p, need, got: state.knots.length }));
  for (let i = 1; i < need; i++) {
    if (state.knots[i] < state.knots[i - 1]) throw new Error(t("bsplineBasis.knotOrder", { i: i - 1, a: state.knots[i - 1], j: i, b: state.knots[i] }));
  }
  checkNumber(state, "u");
  const a = state.knots[p];
  const b = state.knots[count];
  if (state.u < a || state.u > b) throw new Error(t("bsplineBasis.uRange", { a, b, u: state.u }));
}

/** Styles of the plot that the theme does not have, made once per theme. */
const supportStyles = new WeakMap();
function supportFill(theme) {
  let list = supportStyles.get(theme);
  if (!list) {
    list = Object.freeze(CYCLE.map((colour) => Object.freeze({ fill: colour, alpha: SUPPORT_ALPHA })));
    supportStyles.set(theme, list);
  }
  return list;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = build(work);

  // Derived data, recomputed only when the knots, the geometry or u changed.
  let samples = null; // curve.sampleUniform(SAMPLES)
  let basis = null; // curve.basisCurves(SAMPLES), i-major
  let continuity = null; // curve.knotContinuity()
  let domain = null; // curve.domain()
  let values = null; // curve.basis(u)
  let table = null; // curve.basisTable(u): { span, levels }
  let point = null; // curve.evaluate(u)
  let knotsDirty = true;
  let geometryDirty = true;
  let uDirty = true;
  const peakK = new Int32Array(MAX_POINTS); // sample index of each N_i's maximum (label placement)
  const insetScratch = [0, 0, 0, 0];
  const plot = { x0: 0, x1: 0, y0: 0, y1: 0, top: 0, bottom: 0 }; // frame (CSS px), strip top/bottom
  const basisNames = []; // "N₀,₂" … per (p, i)
  let markerLabel = ""; // "u = 2.5", rebuilt when u changes

  // What is highlighted: a basis curve under the pointer in the plot, a table row, or a handle.
  let shownHighlight = -2; // the highlight the panels show (-2: not yet synced)

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets });
  // A taller figure than the default 16:10: the curve, the plot and the ruler share it.
  ctx.slots.figure.style.aspectRatio = "1 / 1";

  // The plot claims its frame before the handles see the pointer: press or drag there to set u.
  const plotPointer = new BasisPlotPointer(view, {
    inPlot,
    graphAt: basisAt,
    pick: (x, final) => setU(uAtPixel(x), final),
    enter: () => handles.leave(),
  });

  // The knot ruler, before the handles: its band is its own.
  const ruler = new KnotRuler(view, {
    knots: () => work.knots,
    degree: () => work.degree,
    continuity: () => continuity,
    move: (i, u) => moveKnot(i, u),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    raise: (i) => changeMultiplicity(i, raiseMultiplicity(work.knots, i, work.degree)),
    lower: (i) => changeMultiplicity(i, lowerMultiplicity(work.knots, i)),
    pick: (u, final) => setU(snapToKnot(u), final),
  });

  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: the basis does not change
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
    select: (i) => i >= 0 && ruler.select(-1),
  });
  ruler.source.handles = handles;

  /** The canvas strips below the world window: [top, right, bottom, left] (scratch, no allocation). */
  function insets(width, height) {
    insetScratch[2] = plotHeight(height) + ruler.height(view.renderer.scale);
    return insetScratch;
  }

  function plotHeight(height) {
    return Math.max(PLOT_MIN_PX, Math.round(height * PLOT_FRACTION));
  }

  /** Lays out the ruler and the plot frame for a canvas of width × height CSS px at text scale `scale`. */
  function layoutBands(width, height, scale) {
    const rulerTop = height - ruler.height(scale);
    ruler.layout(AXIS_LEFT * scale, width - AXIS_RIGHT * scale, rulerTop, scale);
    plot.bottom = rulerTop;
    plot.top = rulerTop - plotHeight(height);
    plot.x0 = ruler.px(domain[0]);
    plot.x1 = ruler.px(domain[1]);
    plot.y0 = rulerTop - PLOT_MARGIN.bottom * scale; // value 0 (y down on screen)
    plot.y1 = plot.top + PLOT_MARGIN.top * scale; // value 1
  }

  const py = (value) => plot.y0 - value * (plot.y0 - plot.y1);
  /** u of basis/curve sample k. */
  const sampleU = (k) => domain[0] + (k / (SAMPLES - 1)) * (domain[1] - domain[0]);

  function inPlot(x, y) {
    if (!domain) return false;
    layoutBands(view.width, view.height, view.renderer.scale);
    return x >= plot.x0 - KNOT_SNAP_PX && x <= plot.x1 + KNOT_SNAP_PX && y >= plot.top && y < plot.bottom;
  }

  /** u under canvas x in the plot (clamped to the domain, snapped to a knot nearby). */
  function uAtPixel(x) {
    layoutBands(view.width, view.height, view.renderer.scale);
    return snapToKnot(ruler.uAt(x));
  }

  /** Clamps u into the domain, snaps it to a knot within KNOT_SNAP_PX, else to the slider's step. */
  function snapToKnot(u) {
    const [a, b] = domain;
    const clamped = Math.min(b, Math.max(a, u));
    for (const knot of work.knots) {
      if (knot >= a && knot <= b && Math.abs(ruler.px(knot) - ruler.px(clamped)) <= KNOT_SNAP_PX) return knot;
    }
    const step = (b - a) * U_SLIDER_RESOLUTION;
    return Math.min(b, Math.max(a, a + Math.round((clamped - a) / step) * step));
  }

  /** The basis function whose graph passes nearest (vertically) to canvas point (x, y), or -1. */
  function basisAt(x, y) {
    if (!basis) return -1;
    const raw = Math.min(1, Math.max(0, (x - plot.x0) / (plot.x1 - plot.x0)));
    return nearestGraph(basis, work.points.length, SAMPLES, Math.round(raw * (SAMPLES - 1)), y, py, PLOT_HOVER_PX);
  }


  // ------------------------------------------------------------ side panel
  const degreeRadios = radios({
    name: "degree",
    value: String(work.degree),
    options: Array.from({ length: MAX_DEGREE - MIN_DEGREE + 1 }, (_, k) => {
      const p = MIN_DEGREE + k;
      return { value: String(p), label: t("bsplineBasis.degreeOption", { p, kind: degreeName(p) }) };
    }),
    onChange: (value) => setDegree(Number(value)),
  });
  degreeRadios.element.classList.add("sl-button-row");
  const uSlider = slider({
    label: t("bsplineBasis.control.u"),
    inputLabel: t("bsplineBasis.control.u.input"),
    name: "u",
    min: work.knots[work.degree],
    max: work.knots[work.points.length],
    step: (work.knots[work.points.length] - work.knots[work.degree]) * U_SLIDER_RESOLUTION,
    value: work.u,
    onChange: (value, final) => setU(Math.min(domain[1], Math.max(domain[0], value)), final),
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const sumText = el("p", { class: "sl-readout", dataset: { info: "sum" } });
  const countText = el("p", { class: "sl-note", dataset: { info: "count" } });
  const { addButton, removeButton } = pointButtons({ add: addPoint, remove: removePoint, selected: () => handles.selected });
  const resetKnotsButton = button({ label: t("bsplineBasis.resetKnots"), title: t("bsplineBasis.resetKnots.title"), name: "reset-knots", onClick: () => resetKnots() });
  const rulerHelp = el("p", { class: "sl-note", text: t("bsplineBasis.rulerHelp") });
  ctx.slots.controls.append(
    group(t("bsplineBasis.degreeLegend"), degreeRadios.element),
    group(null, uSlider.element, sumText),
    group(null, countText, el("div", { class: "sl-button-row" }, addButton, removeButton, resetKnotsButton), rulerHelp),
  );

  // ------------------------------------------------------------ formula and tables
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table: valuesTable, wrap: valuesTableWrap } = titledTable("basis");
  const { title: triangleTitle, table: triangleTable, wrap: triangleTableWrap } = titledTable("cox-de-boor");
  ctx.slots.details.append(
    tableTitle,
    valuesTableWrap,
    triangleTitle,
    triangleTableWrap,
  );
  let tableShape = ""; // "count/p" the values table was built for
  let tableRows = []; // per i: { row, support, value, exact }
  let sumCells = null;
  let triangleShape = ""; // "p/k" the triangle was built for
  let triangleCells = []; // per level r, per j: td

  // ------------------------------------------------------------ edits

  /** A new wasm curve for a state (throws on invalid input). */
  function build(state) {
    return new sl.BSplineCurve(flatten(state.points), 2, state.degree, Float64Array.from(state.knots));
  }

  /** Replaces the curve after the knots, the degree or the points changed; false (and a message) if refused. */
  function rebuild() {
    const next = buildOrReport(() => build(work), ctx);
    if (!next) return false;
    curve.free();
    curve = next;
    knotsDirty = true;
    view.requestDraw();
    return true;
  }

  /** Knot i dragged or nudged to u (already between its neighbours). */
  function moveKnot(i, u) {
    const old = work.knots[i];
    work.knots[i] = u;
    if (!rebuild()) work.knots[i] = old;
  }

  /** Applies a raised/lowered knot vector (from knot-ruler.js) or reports why not. */
  function changeMultiplicity(i, result) {
    if (result.error) {
      const max = work.degree + 1;
      ctx.status(t(`bsplineBasis.multiplicity.${result.error}`, { i: subscript(i), max }), "error");
      return;
    }
    const old = work.knots;
    work.knots = result.knots;
    if (!rebuild()) {
      work.knots = old;
      return;
    }
    ruler.select(result.index);
    ctx.commit(work);
  }

  /** The core's clamped uniform knot vector for the current points and degree. */
  function clampedKnots() {
    return Array.from(sl.knotVector(flatten(work.points), 2, work.degree, "clamped"));
  }

  function resetKnots() {
    work.knots = clampedKnots();
    if (rebuild()) ctx.commit(work);
  }

  function setDegree(p) {
    if (p === work.degree) return;
    if (work.points.length < p + 1) {
      ctx.status(t("bsplineBasis.minPoints", { min: p + 1, p }), "error");
      degreeRadios.set(String(work.degree));
      return;
    }
    const old = { degree: work.degree, knots: work.knots };
    work.degree = p;
    work.knots = clampedKnots();
    if (!rebuild()) {
      Object.assign(work, old);
      degreeRadios.set(String(work.degree));
      return;
    }
    ruler.forgetPointer();
    ctx.commit(work);
  }

  function setU(value, final) {
    work.u = value;
    uSlider.set(value);
    uDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  /** Adds a point after handle i (at the end when none is selected); the knots become clamped uniform. */
  function addPoint(i) {
    const next = withPointAdded(work.points, i, MAX_POINTS, view.scale);
    if (!next) return ctx.status(t("bsplineBasis.maxPoints", { max: MAX_POINTS }), "error");
    work.points = next.points;
    work.knots = clampedKnots();
    rebuild();
    ruler.forgetPointer();
    handles.select(next.index);
    ctx.commit(work);
  }

  /** Removes handle i (the last one when none is selected); the knots become clamped uniform. */
  function removePoint(i) {
    const min = Math.max(MIN_POINTS, work.degree + 1);
    const next = withPointRemoved(work.points, i, min);
    if (!next) return ctx.status(t("bsplineBasis.minPoints", { min, p: work.degree }), "error");
    work.points = next.points;
    work.knots = clampedKnots();
    rebuild();
    ruler.forgetPointer();
    handles.select(next.index);
    ctx.commit(work);
  }

  // ------------------------------------------------------------ core data
  /** Asks the core for the samples, the basis and the values when something changed. */
  function recompute() {
    const n = work.points.length - 1;
    let changed = false;
    if (knotsDirty) {
      basis = curve.basisCurves(SAMPLES); // one call: every N_{i,p} at SAMPLES u values
      continuity = curve.knotContinuity();
      domain = curve.domain();
      for (let i = 0; i <= n; i++) {
        let best = 0;
        for (let k = 1; k < SAMPLES; k++) if (basis[i * SAMPLES + k] > basis[i * SAMPLES + best]) best = k;
        peakK[i] = best;
      }
      // The domain may have moved (end knots dragged): keep u inside, and the slider's range on it.
      const clamped = Math.min(domain[1], Math.max(domain[0], work.u));
      if (clamped !== work.u) work.u = clamped;
      uSlider.setRange(domain[0], domain[1], (domain[1] - domain[0]) * U_SLIDER_RESOLUTION);
      uSlider.set(work.u);
      geometryDirty = uDirty = true;
    }
    if (geometryDirty) samples = curve.sampleUniform(SAMPLES);
    if (geometryDirty || uDirty) {
      point = curve.evaluate(work.u);
      if (uDirty || knotsDirty) {
        values = curve.basis(work.u);
        table = curve.basisTable(work.u);
        const f = simpleFraction(work.u);
        markerLabel = t("bsplineBasis.marker", { u: f && f.den > 1 ? fractionText(f) : knotText(work.u) });
      }
      changed = true;
    }
    knotsDirty = geometryDirty = uDirty = false;
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
    const p = work.degree;
    const hi = shownHighlight;
    const cycle = theme.basisStroke.length;
    const knots = work.knots;

    // ---- the curve area (world window, above the plot)
    pointsPath(r, v, pts, 0, n + 1);
    r.paint(theme.polygon);

    // The highlighted function's support [u_i, u_{i+p+1}) on the curve: a band in its colour.
    if (hi >= 0) {
      const lo = knots[hi];
      const up = knots[hi + p + 1];
      let open = false;
      r.beginPath();
      for (let k = 0; k < SAMPLES; k++) {
        const u = sampleU(k);
        if (u >= lo && u <= up) {
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
    handles.draw(r, v);

    const pointX = v.sx(point[0]);
    const pointY = v.sy(point[1]);
    r.point(pointX, pointY, theme.pointOnCurve);
    placeLabelAway(r, v, work.points, t("bsplineBasis.pointLabel"), pointX, pointY, theme.labelPoint, theme.pointOnCurve.radius * r.scale);

    // ---- the plot strip and the ruler (screen space, below the world window)
    const w = r.width;
    const h = r.height;
    layoutBands(w, h, r.scale);
    r.beginPath();
    r.rect(0, plot.top, w, plot.bottom - plot.top);
    r.paint(theme.plotBackground);
    r.beginPath();
    r.moveTo(0, plot.top);
    r.lineTo(w, plot.top);
    r.paint(theme.axis);

    // The highlighted support, shaded (before the curves).
    if (hi >= 0) {
      const a = ruler.px(Math.max(knots[hi], domain[0]));
      const b = ruler.px(Math.min(knots[hi + p + 1], domain[1]));
      r.beginPath();
      r.rect(a, plot.y1, Math.max(0, b - a), plot.y0 - plot.y1);
      r.paint(supportFill(theme)[hi % cycle]);
    }

    // Value axis 0 … 1 (dashed at 1) and the u axis along the domain.
    r.beginPath();
    r.moveTo(plot.x0, plot.y1);
    r.lineTo(plot.x0, plot.y0);
    r.lineTo(plot.x1, plot.y0);
    r.paint(theme.axis);
    r.beginPath();
    r.moveTo(plot.x0, plot.y1);
    r.lineTo(plot.x1, plot.y1);
    r.paint(theme.helper);
    r.beginPath();
    for (let a = 0; a < knots.length; a++) {
      if (knots[a] < domain[0] || knots[a] > domain[1] || (a > 0 && knots[a] === knots[a - 1])) continue;
      r.moveTo(ruler.px(knots[a]), plot.y1);
      r.lineTo(ruler.px(knots[a]), plot.y0);
    }
    r.paint(theme.helper);
    r.text(t("bsplineBasis.axisValue0"), plot.x0 - (TICK_PX + 2) * r.scale, plot.y0, theme.labelSmall, "right", "middle");
    r.text(t("bsplineBasis.axisValue1"), plot.x0 - (TICK_PX + 2) * r.scale, plot.y1, theme.labelSmall, "right", "middle");
    r.text(t("bsplineBasis.axisU"), plot.x1 + (TICK_PX + 2) * r.scale, plot.y0, theme.labelSmall, "left", "middle");

    // The basis functions, from the core's table (highlighted one last, on top).
    const sampleX = (k) => ruler.px(sampleU(k));
    for (let i = 0; i <= n; i++) if (i !== hi) drawGraph(r, basis, i, SAMPLES, sampleX, py, theme.basisStroke[i % cycle]);
    if (hi >= 0) drawGraph(r, basis, hi, SAMPLES, sampleX, py, theme.basisHover[hi % cycle]);

    // The marker at u, under the names (their halo keeps them readable where it crosses), with
    // the values N_{i,p}(u) as dots on top.
    const mx = ruler.px(work.u);
    r.beginPath();
    r.moveTo(mx, plot.top + 18 * r.scale);
    r.lineTo(mx, plot.y0);
    r.paint(theme.marker);

    // Names at the peaks.
    if (n + 1 <= NAME_LABELS_MAX) {
      for (let i = 0; i <= n; i++) {
        const k = peakK[i];
        const x = ruler.px(sampleU(k));
        const align = k === 0 ? "left" : k === SAMPLES - 1 ? "right" : "center";
        const dx = (k === 0 ? 4 : k === SAMPLES - 1 ? -4 : 0) * r.scale;
        r.text(basisName(p, i), x + dx, py(basis[i * SAMPLES + k]) - 4 * r.scale, i === hi ? theme.labelBold : theme.labelSmall, align, "bottom");
      }
    }

    for (let i = 0; i <= n; i++) if (values[i] > 0) r.point(mx, py(values[i]), theme.basisPoint[i % cycle]);
    const markerAlign = mx < plot.x0 + 40 * r.scale ? "left" : mx > plot.x1 - 40 * r.scale ? "right" : "center";
    r.text(markerLabel, mx, plot.top + 2 * r.scale, theme.labelPoint, markerAlign, "top");

    // The knot ruler, and u marked on its line.
    ruler.draw(r);
    const ly = ruler.lineY;
    r.beginPath();
    r.moveTo(mx, ly - 5 * r.scale);
    r.lineTo(mx, ly + 5 * r.scale);
    r.paint(theme.marker);
    r.point(mx, ly, theme.pointOnCurve);
  }

  /** "N₃,₂" (cached per degree and index). */
  function basisName(p, i) {
    return (basisNames[p * (MAX_POINTS + 1) + i] ??= `N${subscript(i)},${subscript(p)}`);
  }

  // ------------------------------------------------------------ panels (formula, tables, notes, label)
  function syncPanels(hi) {
    const pts = work.points;
    const n = pts.length - 1;
    const p = work.degree;
    const knots = work.knots;
    const m = knots.length - 1;
    const k = table.span;
    const uText = knotText(work.u);
    const uFraction = simpleFraction(work.u);
    const uTex = uFraction && uFraction.den > 1 ? `\\tfrac{${uFraction.num}}{${uFraction.den}}` : uText;
    degreeRadios.set(String(p));
    for (const input of degreeRadios.inputs) input.disabled = Number(input.value) > n;
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= Math.max(MIN_POINTS, p + 1);
    setText(countText, t("bsplineBasis.knotNote", { count: n + 1, p, m: m + 1, last: subscript(m) }));

    let sum = 0;
    for (let i = 0; i <= n; i++) sum += values[i];
    setText(sumText, t("bsplineBasis.sumNote", { u: uText, sum: fmt(sum) }));

    // Formula panel: the recurrence, one function with the live numbers, the sum, the point.
    const focus = hi >= 0 ? hi : argmax(values, n);
    const level = (r, i) => {
      // N_{i,r}(u) from the core's triangle (zero outside k − r … k).
      const j = i - (k - r);
      return j >= 0 && j <= r ? table.levels[r][j] : 0;
    };
    const term = (num, den, value, numTex, denTex) => {
      if (den === 0) return { tex: "0", factor: 0 }; // 0/0 := 0
      return { tex: `\\frac{${numTex}}{${denTex}}\\,`, factor: num / den, value };
    };
    const kt = (x) => knotText(x);
    const left = term(work.u - knots[focus], knots[focus + p] - knots[focus], level(p - 1, focus), `${uText}-${kt(knots[focus])}`, `${kt(knots[focus + p])}-${kt(knots[focus])}`);
    const right = term(knots[focus + p + 1] - work.u, knots[focus + p + 1] - knots[focus + 1], level(p - 1, focus + 1), `${kt(knots[focus + p + 1])}-${uText}`, `${kt(knots[focus + p + 1])}-${kt(knots[focus + 1])}`);
    const leftPart = left.tex === "0" ? "0" : `${left.tex}N_{${focus},${p - 1}}(${uTex})`;
    const rightPart = right.tex === "0" ? "0" : `${right.tex}N_{${focus + 1},${p - 1}}(${uTex})`;
    const leftNumbers = left.tex === "0" ? "0" : `${fmt(left.factor)}\\cdot ${fmt(level(p - 1, focus))}`;
    const rightNumbers = right.tex === "0" ? "0" : `${fmt(right.factor)}\\cdot ${fmt(level(p - 1, focus + 1))}`;
    const active = [];
    const weighted = [];
    for (let i = Math.max(0, k - p); i <= Math.min(n, k); i++) {
      active.push(fmt(values[i]));
      weighted.push(`${fmt(values[i])}\\,P_{${i}}`);
    }
    const knotList = knots.map(kt).join(",\\ ");
    formula.set([
      `N_{i,0}(u) = \\begin{cases} 1 & u_i \\le u < u_{i+1} \\\\ 0 & \\text{${t("bsplineBasis.formulaOtherwise")}} \\end{cases},\\qquad N_{i,p}(u) = \\frac{u-u_i}{u_{i+p}-u_i}\\,N_{i,p-1}(u) + \\frac{u_{i+p+1}-u}{u_{i+p+1}-u_{i+1}}\\,N_{i+1,p-1}(u),\\quad \\tfrac{0}{0} := 0`,
      `U = [${knotList}],\\qquad u = ${uTex} \\in [u_{${k}}, u_{${k + 1}}) = [${kt(knots[k])}, ${kt(knots[k + 1])})`,
      `N_{${focus},${p}}(${uTex}) = ${leftPart} + ${rightPart} = ${leftNumbers} + ${rightNumbers} = ${fmt(values[focus])}`,
      `\\sum_{i=0}^{${n}} N_{i,${p}}(${uTex}) = ${active.join(" + ")} = ${fmt(sum)}`,
      `C(u) = \\sum_{i=0}^{${n}} N_{i,${p}}(u)\\,P_i,\\qquad C(${uTex}) = ${weighted.join(" + ")} = (${fmt(point[0])},\\ ${fmt(point[1])})`,
    ]);

    // The values table: one row per basis function (the legend), then the sum.
    const shape = `${n + 1}/${p}`;
    if (tableShape !== shape) buildValuesTable(n, p, shape);
    setText(tableTitle, t("bsplineBasis.tableCaption", { p, u: uText }));
    const valueTexts = [];
    for (let i = 0; i <= n; i++) {
      const cells = tableRows[i];
      setText(cells.support, t("bsplineBasis.supportCell", { i: subscript(i), j: subscript(i + p + 1), a: kt(knots[i]), b: kt(knots[i + p + 1]) }));
      setText(cells.value, fmt(values[i]));
      const f = simpleFraction(values[i]);
      setText(cells.exact, f && f.den > 1 ? `= ${fractionText(f)}` : "");
      cells.row.classList.toggle("sl-highlight", i === hi);
      if (values[i] > 0) valueTexts.push(`${basisName(p, i)} = ${fmt(values[i])}`);
    }
    setText(sumCells.value, fmt(sum));

    // The Cox–de Boor triangle at u.
    const triShape = `${p}/${k}`;
    if (triangleShape !== triShape) buildTriangle(p, k, triShape);
    setText(triangleTitle, t("bsplineBasis.triangleCaption", { u: uText, k, a: kt(knots[k]), b: kt(knots[k + 1]), kSub: subscript(k), k1Sub: subscript(k + 1) }));
    for (let r = 0; r <= p; r++) {
      for (let j = 0; j <= r; j++) setText(triangleCells[r][j], fmt(table.levels[r][j]));
    }

    const joints = [];
    for (const entry of continuity) joints.push(`${kt(entry.knot)}: ${entry.continuity < 0 ? t("knotRuler.break") : `C${superscript(entry.continuity)}`}`);
    const ariaContinuity = joints.length ? t("bsplineBasis.ariaContinuity", { list: joints.join(", ") }) : "";
    let ariaSupport = "";
    if (hi >= 0) ariaSupport = t("bsplineBasis.ariaSupport", { name: basisName(p, hi), a: kt(knots[hi]), b: kt(knots[hi + p + 1]) });
    view.setLabel(
      t("bsplineBasis.aria", {
        kind: degreeName(p),
        count: n + 1,
        knots: knots.map(kt).join(", "),
        u: uText,
        a: kt(knots[k]),
        b: kt(knots[k + 1]),
        values: valueTexts.join(", "),
        sum: fmt(sum),
        x: fmt(point[0], 2),
        y: fmt(point[1], 2),
      }) + ariaContinuity + ariaSupport,
    );
  }

  /** Rebuilds the values table for n + 1 functions of degree p. */
  function buildValuesTable(n, p, shape) {
    tableShape = shape;
    tableRows = [];
    const head = el("tr", {},
      el("th", { scope: "col", text: t("bsplineBasis.colFunction") }),
      el("th", { scope: "col", text: t("bsplineBasis.colSupport") }),
      el("th", { scope: "col", text: t("bsplineBasis.colValue") }));
    const rows = [];
    for (let i = 0; i <= n; i++) {
      const cells = { support: el("span"), value: el("span", { class: "sl-cell-value" }), exact: el("span", { class: "sl-cell-decimal" }) };
      const swatch = el("span", { class: "sl-swatch", "aria-hidden": "true" });
      swatch.style.background = CYCLE[i % CYCLE.length];
      const row = el("tr", { tabindex: "0", dataset: { index: String(i) } },
        el("th", { scope: "row" }, swatch, t("bsplineBasis.rowName", { name: basisName(p, i), point: `P${subscript(i)}` })),
        el("td", { dataset: { cell: "support" } }, cells.support),
        el("td", { dataset: { cell: "value" } }, cells.value, cells.exact));
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
    sumCells = { value: el("span", { class: "sl-cell-value" }) };
    rows.push(el("tr", { dataset: { index: "sum" } },
      el("th", { scope: "row", text: t("bsplineBasis.sumRow") }),
      el("td", {}),
      el("td", { dataset: { cell: "value" } }, sumCells.value)));
    valuesTable.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));
  }

  /** Rebuilds the triangle for degree p on span k: row r holds N_{k−r,r} … N_{k,r} under their columns. */
  function buildTriangle(p, k, shape) {
    triangleShape = shape;
    triangleCells = [];
    const head = [el("th", { scope: "col", text: t("bsplineBasis.triangleCorner") })];
    for (let i = k - p; i <= k; i++) head.push(el("th", { scope: "col", text: `i = ${i}` }));
    const rows = [];
    for (let r = 0; r <= p; r++) {
      const cells = [el("th", { scope: "row", text: t("bsplineBasis.triangleRow", { r }) })];
      const levelCells = [];
      for (let i = k - p; i <= k; i++) {
        if (i < k - r) {
          cells.push(el("td", { class: "sl-cell-empty" }));
          continue;
        }
        const value = el("span", { class: "sl-cell-value" });
        levelCells.push(value);
        cells.push(el("td", { dataset: { r: String(r), i: String(i) } }, el("span", { class: "sl-cell-name", text: `N${subscript(i)},${subscript(r)} = ` }), value));
      }
      triangleCells.push(levelCells);
      rows.push(el("tr", {}, cells));
    }
    triangleTable.replaceChildren(el("thead", {}, el("tr", {}, head)), el("tbody", {}, rows));
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = build(state); // throws before anything changes
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      ruler.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      if (ruler.selected >= work.knots.length) ruler.select(-1);
      plotPointer.reset();
      degreeRadios.set(String(work.degree));
      knotsDirty = geometryDirty = uDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      ruler.destroy();
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** Index of the largest of values[0..n] (the first on a tie). */
function argmax(values, n) {
  let best = 0;
  for (let i = 1; i <= n; i++) if (values[i] > values[best]) best = i;
  return best;
}
