/**
 * Demo (syllabus §3): the matrix form of B-spline segments, after the Croatian notes (002).
 * A uniform (or, for comparison, clamped) B-spline of degree 2 or 3; the selected segment i
 * with its p + 1 active points is highlighted, and the formula panel writes the segment as
 * [t^p … t 1] M [P_{i−1} … P_{i+p−1}]^T with M from the core (`segmentMatrix(k, true)`, compared
 * with `uniformSegmentMatrix(p)`), the current coordinates filled in. The point at t is shown
 * twice: as the matrix product of those displayed numbers (the core's `evaluateMatrixForm(k, t)`:
 * the monomials, [t^p … 1] M and the product) and as `evaluate(u)`, so students see they agree. The curve itself is drawn from the core (`sampleUniform`, `sample`).
 */
import { Handles, placeLabel, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, group, el, radios, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkChoice } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, fractionText, fractionTex, degreeName } from "../lib/format.js";
import { CYCLE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { withPointAdded, withPointRemoved, pointButtons } from "../lib/point-list.js";
import { titledTable } from "../lib/table.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { buildOrReport } from "../lib/wasm.js";

export const id = "matrix-form";
/** Prefix of this demo's keys in strings.js. */
export const strings = "matrixForm";
export const title = t("matrixForm.title");
export const summary = t("matrixForm.summary");
/** Syllabus section. */
export const section = 3;

/** Six integer points, a uniform quadratic (the Croatian notes' example size), segment 2 at t = 1/2. */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 5], [6, 6], [8, 1], [12, 0], [14, 5]].map(Object.freeze)),
  degree: 2,
  knots: "uniform",
  segment: 2,
  t: 0.5,
});

/** Fewest and most control points. */
export const MIN_POINTS = 3;
export const MAX_POINTS = 11;
/** Degrees with a matrix form in the notes. */
export const DEGREES = Object.freeze([2, 3]);
/** Knot vectors offered: uniform (unclamped) as in the notes' periodic segments, or clamped. */
export const KNOT_KINDS = Object.freeze(["uniform", "clamped"]);
/** Points sampled along the whole curve and along the selected segment. */
const CURVE_SAMPLES = 256;
const SEGMENT_SAMPLES = 64;
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;
/** A press this close to the curve (CSS px) selects the segment under it. */
const CURVE_HIT_PX = 8;
/** Matrix entries equal within this count as the same (floating-point round-off). */
const MATRIX_TOLERANCE = 1e-9;
/** Largest common denominator factored out of a cubic matrix (1/6, 1/12, …). */
const MAX_FACTOR = 720;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "degree", "knots", "segment", "t"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "degree", { min: 2, max: 3, integer: true });
  if (state.degree > state.points.length - 1) throw new Error(t("matrixForm.error.degree", { p: state.degree, count: state.points.length }));
  checkChoice(state, "knots", KNOT_KINDS);
  checkNumber(state, "segment", { min: 1, max: segmentCount(state), integer: true });
  checkNumber(state, "t", { min: 0, max: 1 });
}

/** Number of segments n − p + 1 (one per span; no repeated interior knots here). */
function segmentCount(state) {
  return state.points.length - state.degree;
}

/** The B-spline of a state: knots from the core's `knotVector` ("uniform" or "clamped"). */
function buildCurve(sl, state) {
  const flat = flatten(state.points);
  return new sl.BSplineCurve(flat, 2, state.degree, sl.knotVector(flat, 2, state.degree, state.knots));
}

/** A number as text / TeX: integers plain, fractions with small denominators, else 3 decimals. */
function numberText(x) {
  if (Math.abs(x - Math.round(x)) < MATRIX_TOLERANCE) return String(Math.round(x) || 0);
  const f = simpleFraction(x);
  return f ? fractionText(f) : fmt(x);
}
function numberTex(x) {
  if (Math.abs(x - Math.round(x)) < MATRIX_TOLERANCE) return String(Math.round(x) || 0);
  const f = simpleFraction(x);
  return f ? fractionTex(f) : fmt(x);
}

/**
 * The smallest D ≤ MAX_FACTOR with D·m integral for every entry (to write a cubic matrix as
 * (1/D)·integers, as the notes do), or 0 when there is none.
 */
function commonDenominator(matrix) {
  for (let d = 1; d <= MAX_FACTOR; d++) {
    if (matrix.every((m) => Math.abs(m * d - Math.round(m * d)) < MATRIX_TOLERANCE * d)) return d;
  }
  return 0;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = buildCurve(sl, work);

  // Derived data, recomputed only when the geometry, the segment or t changed.
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let segmentSamples = null; // curve.sample(segmentUs)
  const segmentUs = new Float64Array(SEGMENT_SAMPLES); // u over the selected span (parameters)
  let matrix = null; // curve.segmentMatrix(k, true)
  let periodic = null; // sl.uniformSegmentMatrix(p)
  let evaluated = null; // curve.evaluate(u)
  let tangent = null; // curve.derivative(u, 1): the label goes beside the curve, not along it
  let matrixForm = null; // curve.evaluateMatrixForm(k, t): [t^p … 1], [t^p … 1] M, the product
  let geometryDirty = true;
  let segmentDirty = true;
  let pointLabel = ""; // "C₂(t)", rebuilt when the segment changes

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points) });
  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
  });
  // After the handles (they get the pointer first): a press on the curve picks its segment and t.
  view.addInteractor({
    pointerDown(event, x, y) {
      const s = nearestSample(x, y);
      if (s < 0) return false;
      pickSample(s);
      return true;
    },
    pointerMove() {},
    pointerUp() {},
    hover(x, y) {
      return nearestSample(x, y) >= 0 ? "pointer" : null;
    },
    leave() {},
  });

  /** Index of the curve sample within CURVE_HIT_PX of canvas (x, y), or -1. */
  function nearestSample(x, y) {
    if (!samples) return -1;
    let best = -1;
    let bestDistance = CURVE_HIT_PX;
    for (let s = 0; s < CURVE_SAMPLES; s++) {
      const d = Math.hypot(view.sx(samples[2 * s]) - x, view.sy(samples[2 * s + 1]) - y);
      if (d <= bestDistance) {
        best = s;
        bestDistance = d;
      }
    }
    return best;
  }

  /** Selects the segment (and t) of curve sample s: its u, then the core's span of u. */
  function pickSample(s) {
    const [a, b] = curve.domain();
    const u = a + ((b - a) * s) / (CURVE_SAMPLES - 1);
    const k = curve.span(u);
    const knots = curve.knots();
    work.segment = k - work.degree + 1;
    work.t = Math.min(1, Math.max(0, Math.round((u - knots[k]) / (knots[k + 1] - knots[k]) / T_SLIDER_STEP) * T_SLIDER_STEP));
    segmentSlider.set(work.segment);
    tSlider.set(work.t);
    segmentDirty = true;
    view.requestDraw();
    ctx.commit(work);
  }

  // ------------------------------------------------------------ side panel
  const degreeRadios = radios({
    name: "degree",
    value: String(work.degree),
    options: DEGREES.map((p) => ({ value: String(p), label: t(`matrixForm.degree.${p}`) })),
    onChange: (value) => setShape({ degree: Number(value) }),
  });
  const knotRadios = radios({
    name: "knots",
    value: work.knots,
    options: KNOT_KINDS.map((value) => ({ value, label: t(`matrixForm.knots.${value}`) })),
    onChange: (value) => setShape({ knots: value }),
  });
  const segmentSlider = slider({
    label: t("matrixForm.control.segment"),
    inputLabel: t("matrixForm.control.segment.input"),
    name: "segment",
    min: 1,
    max: segmentCount(work),
    step: 1,
    value: work.segment,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => {
      const i = Math.round(value);
      if (i !== work.segment) {
        work.segment = i;
        segmentDirty = true;
        view.requestDraw();
      }
      if (final) ctx.commit(work);
    },
    onError: (text) => ctx.status(t("matrixForm.segmentRange", { value: text, max: segmentCount(work) }), "error"),
  });
  const tSlider = slider({
    label: t("matrixForm.control.t"),
    inputLabel: t("control.t.input"),
    name: "t",
    min: 0,
    max: 1,
    step: T_SLIDER_STEP,
    value: work.t,
    onChange: (value, final) => {
      work.t = value;
      segmentDirty = true;
      view.requestDraw();
      if (final) ctx.commit(work);
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const periodicText = el("p", { class: "sl-readout", dataset: { info: "periodic" }, "aria-live": "polite" });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: addPoint, remove: removePoint, selected: () => handles.selected });
  ctx.slots.controls.append(
    group(t("matrixForm.control.degree"), degreeRadios.element),
    group(t("matrixForm.control.knots"), knotRadios.element),
    group(null, segmentSlider.element, tSlider.element, periodicText),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
  );

  // ------------------------------------------------------------ formula and tables
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: matrixTitle, table: matrixTable, wrap: matrixTableWrap } = titledTable("matrix");
  const productCell = el("td", { dataset: { result: "product" } });
  const evaluateCell = el("td", { dataset: { result: "evaluate" } });
  const result = titledTable("result", {
    caption: t("matrixForm.resultCaption"),
    children: [
      el("tbody", {},
        el("tr", {}, el("th", { scope: "row", text: t("matrixForm.result.product") }), productCell),
        el("tr", {}, el("th", { scope: "row", text: t("matrixForm.result.evaluate") }), evaluateCell)),
    ],
  });
  ctx.slots.details.append(matrixTitle, matrixTableWrap, result.title, result.wrap);
  let matrixSize = -1;
  let matrixCells = []; // td per entry, row-major
  let factorCell = null;
  let headerCells = []; // column heads: the points P_{i−1} … P_{i+p−1}

  // ------------------------------------------------------------ edits

  /**
   * Replaces the curve for `next` (new points, degree or knot kind): built first (the core may
   * refuse), then the old one is freed; the segment stays in range.
   */
  function rebuild(next) {
    const built = buildOrReport(() => buildCurve(sl, next), ctx);
    if (!built) return false;
    curve.free();
    curve = built;
    work = next;
    work.segment = Math.min(work.segment, segmentCount(work));
    syncControls();
    geometryDirty = segmentDirty = true;
    view.requestDraw();
    return true;
  }

  /** Degree or knot kind changed. */
  function setShape(change) {
    const next = { ...structuredClone(work), ...change };
    if (next.degree > next.points.length - 1) {
      ctx.status(t("matrixForm.error.degree", { p: next.degree, count: next.points.length }), "error");
      syncControls();
      return;
    }
    if (rebuild(next)) ctx.commit(work);
    else syncControls();
  }

  /** Adds a point after handle i (at the end when none is selected). */
  function addPoint(i) {
    const next = withPointAdded(work.points, i, MAX_POINTS, view.scale);
    if (!next) return ctx.status(t("matrixForm.maxPoints", { max: MAX_POINTS }), "error");
    if (!rebuild({ ...structuredClone(work), points: next.points })) return;
    handles.select(next.index);
    ctx.commit(work);
  }

  /** Removes handle i (the last one when none is selected); a cubic needs four points. */
  function removePoint(i) {
    const min = Math.max(MIN_POINTS, work.degree + 1);
    const next = withPointRemoved(work.points, i, min);
    if (!next) return ctx.status(t("matrixForm.minPoints", { min, p: work.degree }), "error");
    if (!rebuild({ ...structuredClone(work), points: next.points })) return;
    handles.select(next.index);
    ctx.commit(work);
  }

  /** Radios and sliders show the state (segment range follows the number of points). */
  function syncControls() {
    degreeRadios.set(String(work.degree));
    knotRadios.set(work.knots);
    segmentSlider.setRange(1, segmentCount(work), 1);
    segmentSlider.set(work.segment);
    tSlider.set(work.t);
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for samples, the matrix and the point when something changed. */
  function recompute() {
    const p = work.degree;
    const k = work.segment + p - 1; // segment i uses P_{i−1} … P_{i+p−1}: span k = i + p − 1
    if (geometryDirty) samples = curve.sampleUniform(CURVE_SAMPLES);
    if (geometryDirty || segmentDirty) {
      const knots = curve.knots();
      const u0 = knots[k];
      const u1 = knots[k + 1];
      for (let s = 0; s < SEGMENT_SAMPLES; s++) segmentUs[s] = u0 + ((u1 - u0) * s) / (SEGMENT_SAMPLES - 1);
      segmentSamples = curve.sample(segmentUs);
      matrix = curve.segmentMatrix(k, true);
      matrixForm = curve.evaluateMatrixForm(k, work.t);
      periodic = sl.uniformSegmentMatrix(p);
      evaluated = curve.evaluate(u0 + work.t * (u1 - u0));
      tangent = curve.derivative(u0 + work.t * (u1 - u0), 1);
      syncPanels(k, knots);
    }
    geometryDirty = segmentDirty = false;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;
    const p = work.degree;
    const first = work.segment - 1; // P_{i−1}, the first active point

    // Control polygon, then the active part solid.
    pointsPath(r, v, pts, 0, n + 1);
    r.paint(theme.polygon);
    r.beginPath();
    for (let j = 0; j <= p; j++) {
      const x = v.sx(pts[first + j][0]);
      const y = v.sy(pts[first + j][1]);
      if (j === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.axis);

    // The selected segment as a band under the curve; the curve from one batched sample call.
    flatPath(r, v, segmentSamples, 0, SEGMENT_SAMPLES);
    r.paint(theme.highlightBand);
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // Rings around the active points, in the colours of their column in the formula.
    for (let j = 0; j <= p; j++) r.point(v.sx(pts[first + j][0]), v.sy(pts[first + j][1]), theme.basisRing[j % theme.basisRing.length]);

    handles.draw(r, v);

    // The point C_i(t) from the core, labelled across the curve on the side of the active
    // points' centre: inside the bend, where the polygon (and its handles) is not.
    const px = v.sx(evaluated[0]);
    const py = v.sy(evaluated[1]);
    let cx = 0;
    let cy = 0;
    for (let j = 0; j <= p; j++) {
      cx += v.sx(pts[first + j][0]);
      cy += v.sy(pts[first + j][1]);
    }
    let dx = tangent[1]; // the normal on screen (y down): (−t_y, t_x) of (t_x, −t_y)
    let dy = tangent[0];
    const length = Math.hypot(dx, dy);
    if (length < 1e-12) {
      dx = Math.SQRT1_2;
      dy = -Math.SQRT1_2;
    } else {
      dx /= length;
      dy /= length;
    }
    if ((cx / (p + 1) - px) * dx + (cy / (p + 1) - py) * dy < 0) {
      dx = -dx;
      dy = -dy;
    }
    r.point(px, py, theme.pointOnCurve);
    placeLabel(r, pointLabel, px, py, dx, dy, theme.pointOnCurve.radius * r.scale, theme.labelPoint);
  }

  // ------------------------------------------------------------ panels (formula, tables, label)
  function syncPanels(k, knots) {
    const pts = work.points;
    const n = pts.length - 1;
    const p = work.degree;
    const i = work.segment;
    const size = p + 1;
    const first = i - 1;
    const u = knots[k] + work.t * (knots[k + 1] - knots[k]);
    pointLabel = t("matrixForm.pointLabel", { i: subscript(i) });

    // Is this segment's matrix the periodic one (the notes' "periodic segment")?
    let same = true;
    for (let e = 0; e < size * size; e++) if (Math.abs(matrix[e] - periodic[e]) > MATRIX_TOLERANCE) same = false;
    periodicText.textContent = t(same ? "matrixForm.periodic.yes" : "matrixForm.periodic.no", { i });
    periodicText.dataset.periodic = String(same);
    degreeText.textContent = t("matrixForm.degree", { p, count: n + 1, segments: segmentCount(work), knots: Array.from(knots).map(numberText).join(" ") });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= Math.max(MIN_POINTS, p + 1);

    // The matrix product [t^p … 1] M [P_{i−1} … P_{i+p−1}]^T of the numbers shown, from the core:
    // the monomials, their row times M (one weight per active point) and the point.
    const powers = Array.from(matrixForm.subarray(0, size));
    const weights = Array.from(matrixForm.subarray(size, 2 * size));
    const product = matrixForm.subarray(2 * size, 2 * size + 2);

    // Matrix text: a cubic with a common denominator D is written (1/D)·integers, as in the notes.
    const entries = Array.from(matrix);
    const factor = p >= 3 ? commonDenominator(entries) : 1;
    const scaled = factor > 1 ? entries.map((m) => m * factor) : entries;
    const factorTex = factor > 1 ? `\\frac{1}{${factor}}` : "";
    const rowsTex = [];
    for (let row = 0; row < size; row++) rowsTex.push(scaled.slice(row * size, row * size + size).map(numberTex).join(" & "));
    const mTex = `${factorTex}\\begin{bmatrix} ${rowsTex.join(" \\\\ ")} \\end{bmatrix}`;
    const colour = (j, tex) => `\\textcolor{${CYCLE[j % CYCLE.length]}}{${tex}}`;
    const names = [];
    for (let j = 0; j < size; j++) names.push(colour(j, `P_{${first + j}}`));
    const tPowers = ["t^3", "t^2", "t", "1"].slice(3 - p);
    const tTex = simpleFraction(work.t) ? fractionTex(simpleFraction(work.t)) : fmt(work.t);
    const powersTex = powers.map(numberTex);
    const coords = [];
    for (let j = 0; j < size; j++) coords.push(`${colour(j, numberTex(pts[first + j][0]))} & ${colour(j, numberTex(pts[first + j][1]))}`);
    const pointTex = (x, y) => `(${fmt(x)},\\ ${fmt(y)})`;

    formula.set([
      `C_{${i}}(t) = \\begin{bmatrix} ${tPowers.join(" & ")} \\end{bmatrix} M \\begin{bmatrix} ${names.join(" \\\\ ")} \\end{bmatrix},\\quad u = u_{${k}} + t\\,(u_{${k + 1}} - u_{${k}}),\\ t \\in [0, 1]`,
      `M = ${mTex}\\quad ${same ? "" : "\\ne"}\\ \\text{${t(same ? "matrixForm.tex.periodic" : "matrixForm.tex.notPeriodic")}}`,
      `C_{${i}}(${tTex}) = \\begin{bmatrix} ${powersTex.join(" & ")} \\end{bmatrix} ${mTex} \\begin{bmatrix} ${coords.join(" \\\\ ")} \\end{bmatrix}`,
      `\\phantom{C_{${i}}(${tTex})} = ${weights.map((w) => numberTex(w)).map((w, j) => `${w}\\,${names[j]}`).join(" + ")} = ${pointTex(product[0], product[1])}`,
      `\\text{${t("matrixForm.tex.evaluate")}}\\ C(u = ${fmt(u)}) = ${pointTex(evaluated[0], evaluated[1])}`,
    ]);

    // Tables: M (exact entries, the factor beside) and the two points side by side.
    if (matrixSize !== size) buildMatrixTable(size);
    setText(matrixTitle, t("matrixForm.matrixCaption", { i, k, p }));
    setText(factorCell, factor > 1 ? `1/${factor} ×` : "");
    factorCell.dataset.factor = factor > 1 ? `1/${factor}` : "1";
    for (let e = 0; e < size * size; e++) setText(matrixCells[e], numberText(scaled[e]));
    for (let j = 0; j < size; j++) setText(headerCells[j], `P${subscript(first + j)}`);
    setText(productCell, `(${fmt(product[0])}, ${fmt(product[1])})`);
    setText(evaluateCell, `(${fmt(evaluated[0])}, ${fmt(evaluated[1])})`);

    view.setLabel(t("matrixForm.aria", { kind: degreeName(p), knots: t(`matrixForm.knots.${work.knots}`), count: n + 1, i, t: fmt(work.t), x: fmt(evaluated[0], 2), y: fmt(evaluated[1], 2), periodic: t(same ? "matrixForm.aria.periodic" : "matrixForm.aria.notPeriodic") }));
  }

  /** Rebuilds the matrix table for (p + 1) × (p + 1) entries (only when the size changed). */
  function buildMatrixTable(size) {
    matrixSize = size;
    matrixCells = [];
    factorCell = el("td", { rowspan: String(size), dataset: { cell: "factor" } });
    const header = [el("th", { scope: "col", text: "" }), el("th", { scope: "col", text: "" })];
    headerCells = [];
    for (let j = 0; j < size; j++) {
      const cell = el("th", { scope: "col", dataset: { col: String(j) } });
      headerCells.push(cell);
      header.push(cell);
    }
    const rows = [];
    for (let row = 0; row < size; row++) {
      const cells = [];
      if (row === 0) cells.push(factorCell);
      cells.push(el("th", { scope: "row", text: ["t³", "t²", "t", "1"][4 - size + row] }));
      for (let j = 0; j < size; j++) {
        const cell = el("td", { dataset: { row: String(row), col: String(j) } });
        matrixCells.push(cell);
        cells.push(cell);
      }
      rows.push(el("tr", {}, cells));
    }
    matrixTable.replaceChildren(el("thead", {}, el("tr", {}, header)), el("tbody", {}, rows));
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = buildCurve(sl, state); // throws before anything changes
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      syncControls();
      geometryDirty = segmentDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}
