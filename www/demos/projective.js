/**
 * Demo (syllabus §4): projective invariance of rational curves. A cubic Bézier curve lives in
 * the square [0, 4]²; dragging the four corners Q₀ … Q₃ of the square's image defines a
 * perspective map H (a 3×3 homography). The core maps the curve (`projectiveMap(H)`: control
 * points and new weights); the demo maps the original curve's samples one by one with the same
 * H, as a dotted check, and the two coincide to rounding. For contrast, the mapped control
 * points with the *old* weights give a different curve: forgetting the new weights is not
 * invariant. When H would send a weight to ≤ 0 the core refuses; its message is shown and the
 * last good quadrilateral stays.
 *
 * The homography from four point pairs is a small linear solve written below (the map, not a
 * curve algorithm); applying H to points is the map itself. Everything curved is sampled from
 * the core, one `sampleUniform` per curve per change.
 */
import { Handles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, group, el } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumbers } from "../lib/validate.js";
import { fmt, subscript } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten } from "../lib/geometry.js";
import { scaledInsets, NARROW_CANVAS_PX } from "../lib/view.js";

export const id = "projective";
/** Prefix of this demo's keys in strings.js. */
export const strings = "projective";
export const title = t("projective.title");
export const summary = t("projective.summary");
/** Syllabus section. */
export const section = 4;

/** Side of the source square [0, SIZE]²; its corners S₀ … S₃ go to Q₀ … Q₃. */
export const SIZE = 4;

/**
 * A polynomial S-shaped cubic (all weights 1) inside the square, and a trapezoid as the image:
 * by hand (Heckbert's formulas below), H = [[3/2, 9/4, 6], [0, 2, 0], [0, 1/4, 1]], so
 * w′ = w·(1 + y/4) and the mapped weights are 9/8, 15/8, 9/8, 15/8.
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0.5, 0.5], [1, 3.5], [3, 0.5], [3.5, 3.5]].map(Object.freeze)),
  weights: Object.freeze([1, 1, 1, 1]),
  corners: Object.freeze([[6, 0], [12, 0], [10.5, 4], [7.5, 4]].map(Object.freeze)),
});

/** Number of control points (a cubic). */
const POINTS = 4;
/** Range of a weight (log sliders). */
export const WEIGHT_MIN = 0.1;
export const WEIGHT_MAX = 10;
const WEIGHT_LOG_STEP = 0.01;
const WEIGHT_DIGITS = 3;
/** Samples per curve, and every how many samples the dotted check shows a dot. */
const SAMPLES = 256;
const DOT_EVERY = 8;
/** Grid lines per side of the square (and of its image). */
const GRID = 4;
/** Below this a mapped denominator counts as 0 (the square crosses the line at infinity). */
const DENOMINATOR_EPSILON = 1e-12;
/** Small distances are written in exponent form. */
const SMALL = 1e-3;
/** Height of the band at the top kept for the three-line key, CSS px at text scale 1. */
const LEGEND_PX = 70;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "weights", "corners"]);
  checkPoints(state, "points", { min: POINTS, max: POINTS });
  checkNumbers(state, "weights", { min: POINTS, max: POINTS });
  state.weights.forEach((w, i) => {
    if (w <= 0) throw new Error(t("projective.notPositive", { name: `w${subscript(i)}`, value: w }));
    if (w < WEIGHT_MIN || w > WEIGHT_MAX) throw new Error(t("projective.weightRange", { name: `w${subscript(i)}`, value: w, min: WEIGHT_MIN, max: WEIGHT_MAX }));
  });
  checkPoints(state, "corners", { min: 4, max: 4 });
  const matrix = homography(state.corners);
  if (!matrix.every(Number.isFinite)) throw new Error(t("projective.degenerate"));
}

/**
 * The homography H (row-major 3×3) that sends the square's corners S₀ = (0, 0), S₁ = (SIZE, 0),
 * S₂ = (SIZE, SIZE), S₃ = (0, SIZE) to `corners` Q₀ … Q₃: the unit-square-to-quadrilateral map
 * (Heckbert 1989, "Fundamentals of texture mapping", §2.2.3) after scaling the square to the unit
 * square. With Δ₁ = Q₁ − Q₂, Δ₂ = Q₃ − Q₂, Σ = Q₀ − Q₁ + Q₂ − Q₃, the bottom row (g, h) solves
 * [Δ₁ Δ₂] (g, h)ᵀ = Σ (Cramer's rule; Σ = 0 is an affine map, g = h = 0); then
 * a = x₁ − x₀ + g x₁, b = x₃ − x₀ + h x₃, c = x₀, and likewise d, e, f with y. A point maps as
 * (x, y, 1) ↦ H (x, y, 1), divided by the third coordinate.
 */
function homography(corners) {
  const [[x0, y0], [x1, y1], [x2, y2], [x3, y3]] = corners;
  const sx = x0 - x1 + x2 - x3;
  const sy = y0 - y1 + y2 - y3;
  let g = 0;
  let h = 0;
  if (sx !== 0 || sy !== 0) {
    const dx1 = x1 - x2;
    const dx2 = x3 - x2;
    const dy1 = y1 - y2;
    const dy2 = y3 - y2;
    const det = dx1 * dy2 - dx2 * dy1;
    g = (sx * dy2 - dx2 * sy) / det;
    h = (dx1 * sy - sx * dy1) / det;
  }
  const a = x1 - x0 + g * x1;
  const b = x3 - x0 + h * x3;
  const d = y1 - y0 + g * y1;
  const e = y3 - y0 + h * y3;
  // Unit square → quadrilateral, composed with (x, y) ↦ (x, y) / SIZE.
  return new Float64Array([a / SIZE, b / SIZE, x0, d / SIZE, e / SIZE, y0, g / SIZE, h / SIZE, 1]);
}

function weightText(w) {
  return String(Number(w.toPrecision(WEIGHT_DIGITS)));
}

/** A mapped weight: three decimals, no trailing zeros (9/8 reads 1.125). */
function mappedText(w) {
  return String(Number(w.toFixed(3)));
}

function smallText(x) {
  return x === 0 ? "0" : x < SMALL ? x.toExponential(1) : fmt(x);
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  let work = structuredClone(initialState);
  let matrix = homography(work.corners);
  let curve = new sl.BezierCurve(flatten(work.points), 2, new Float64Array(work.weights));
  let mapped = curve.projectiveMap(matrix); // throws on a weight ≤ 0 (the shell keeps the old state)
  // The contrast: the mapped control points with the old weights (updated in place).
  let naive = new sl.BezierCurve(mapped.controlPoints(), 2, new Float64Array(work.weights));

  // Derived data, recomputed when anything changed.
  let source = null; // curve.sampleUniform
  let image = null; // mapped.sampleUniform: (a)
  const pointwise = new Float64Array(2 * SAMPLES); // H applied to each source sample: (b)
  let naiveSamples = null; // (c)
  let mappedControls = null;
  let mappedWeights = null;
  let gapAB = 0; // max |(a) − (b)| at equal t
  let gapAC = 0; // max distance of (c) from the polyline (a)
  let squareVisible = true; // the whole square maps with positive denominators
  let dirty = true;
  let showingError = false;
  const pointScratch = new Float64Array(2);
  const mapScratch = new Float64Array(2);
  const handleLabels = [];
  const mappedLabels = [];
  const sourceLabels = ["S₀", "S₁", "S₂", "S₃"];

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work), insets: scaledInsets(LEGEND_PX, 0, 0, 0) });
  const handles = new Handles(view, {
    count: () => POINTS + 4,
    get: (i, out) => {
      const p = i < POINTS ? work.points[i] : work.corners[i - POINTS];
      out[0] = p[0];
      out[1] = p[1];
    },
    label: (i) => (handleLabels[i] ??= i < POINTS ? `P${subscript(i)}` : `Q${subscript(i - POINTS)}`),
    move: (i, x, y) => (i < POINTS ? movePoint(i, x, y) : moveCorner(i - POINTS, x, y)),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    polygon: false,
  });

  // ------------------------------------------------------------ side panel
  const weightSliders = work.weights.map((w, i) => {
    const name = `w${subscript(i)}`;
    return slider({
      label: t("projective.weightLabel", { name, point: `P${subscript(i)}` }),
      inputLabel: t("projective.weightInput", { name }),
      name: `weight-${i}`,
      min: WEIGHT_MIN,
      max: WEIGHT_MAX,
      step: WEIGHT_LOG_STEP,
      log: true,
      value: w,
      format: weightText,
      onChange: (value, final) => setWeight(i, Number(value.toPrecision(WEIGHT_DIGITS)), final),
      badNumber: (text) => t("projective.badWeight", { name, value: text, min: WEIGHT_MIN, max: WEIGHT_MAX }),
      onError: (message) => ctx.status(message, "error"),
    });
  });
  const squareButton = button({ label: t("projective.affine"), title: t("projective.affine.title"), name: "affine", onClick: () => setCorners(affineCorners()) });
  const gapText = el("p", { class: "sl-note", dataset: { info: "gaps" }, "aria-live": "polite" });
  const weightsText = el("p", { class: "sl-note", dataset: { info: "mapped-weights" } });
  ctx.slots.controls.append(
    group(t("projective.resultLegend"), gapText, weightsText, el("div", { class: "sl-button-row" }, squareButton)),
    group(t("projective.weightsLegend"), ...weightSliders.map((s) => s.element)),
  );

  // ------------------------------------------------------------ formula
  const formula = new FormulaPanel(ctx.slots.formula);

  // ------------------------------------------------------------ edits

  /** Asks the core for the image under `m`; on refusal shows its message and returns null. */
  function tryMap(m) {
    try {
      return curve.projectiveMap(m);
    } catch (err) {
      ctx.status(t("projective.refused", { message: err.message }), "error");
      showingError = true;
      return null;
    }
  }

  /** Takes a new image (the old one is freed) and copies its control points into the contrast curve. */
  function accept(next) {
    mapped.free();
    mapped = next;
    const controls = mapped.controlPoints();
    for (let i = 0; i < POINTS; i++) naive.setControlPoint(i, controls.subarray(2 * i, 2 * i + 2));
    if (showingError) {
      ctx.status("", "info");
      showingError = false;
    }
    dirty = true;
    view.requestDraw();
  }

  /** A control point moved: in place, then the image; refused moves are undone. */
  function movePoint(i, x, y) {
    const old = work.points[i];
    pointScratch[0] = x;
    pointScratch[1] = y;
    curve.setControlPoint(i, pointScratch);
    const next = tryMap(matrix);
    if (!next) {
      pointScratch[0] = old[0];
      pointScratch[1] = old[1];
      curve.setControlPoint(i, pointScratch);
      return;
    }
    old[0] = x;
    old[1] = y;
    accept(next);
  }

  /** A corner moved: a new homography; refused when it sends a weight to ≤ 0 (the corner stays). */
  function moveCorner(j, x, y) {
    const corners = work.corners.map((c, k) => (k === j ? [x, y] : c));
    const m = homography(corners);
    if (!m.every(Number.isFinite)) {
      ctx.status(t("projective.degenerate"), "error");
      showingError = true;
      return;
    }
    const next = tryMap(m);
    if (!next) return;
    work.corners[j][0] = x;
    work.corners[j][1] = y;
    matrix = m;
    accept(next);
  }

  function setCorners(corners) {
    const m = homography(corners);
    const next = tryMap(m);
    if (!next) return;
    work.corners = corners;
    matrix = m;
    accept(next);
    ctx.commit(work);
  }

  /** The parallelogram spanned by Q₀, Q₁, Q₃ (an affine map: the contrast curve then coincides). */
  function affineCorners() {
    const [q0, q1, , q3] = work.corners;
    return [[q0[0], q0[1]], [q1[0], q1[1]], [q1[0] + q3[0] - q0[0], q1[1] + q3[1] - q0[1]], [q3[0], q3[1]]];
  }

  function setWeight(i, w, final) {
    work.weights[i] = w;
    curve.setWeight(i, w);
    naive.setWeight(i, w);
    weightSliders[i].set(w);
    const next = tryMap(matrix); // a positive factor per point: cannot fail, but ask the core
    if (next) accept(next);
    if (final) ctx.commit(work);
  }

  // ------------------------------------------------------------ drawing
  function recompute() {
    if (!dirty) return;
    dirty = false;
    source = curve.sampleUniform(SAMPLES);
    image = mapped.sampleUniform(SAMPLES);
    naiveSamples = naive.sampleUniform(SAMPLES);
    mappedControls = mapped.controlPoints();
    mappedWeights = mapped.weights();
    // (b): the same H applied to every sample of the original curve.
    gapAB = 0;
    for (let k = 0; k < SAMPLES; k++) {
      mapPoint(source[2 * k], source[2 * k + 1], mapScratch);
      pointwise[2 * k] = mapScratch[0];
      pointwise[2 * k + 1] = mapScratch[1];
      gapAB = Math.max(gapAB, Math.hypot(mapScratch[0] - image[2 * k], mapScratch[1] - image[2 * k + 1]));
    }
    // (c) against (a): each sample's distance to the polyline (a) (parametrisation-free).
    gapAC = 0;
    for (let k = 0; k < SAMPLES; k++) gapAC = Math.max(gapAC, distanceToPolyline(naiveSamples[2 * k], naiveSamples[2 * k + 1], image));
    squareVisible = true;
    for (let k = 0; k < 4; k++) {
      if (matrix[6] * SQUARE[2 * k] + matrix[7] * SQUARE[2 * k + 1] + matrix[8] <= DENOMINATOR_EPSILON) squareVisible = false;
    }
    mappedLabels.length = 0;
    for (let i = 0; i < POINTS; i++) mappedLabels.push(t("projective.mappedLabel", { i: subscript(i), w: mappedText(mappedWeights[i]) }));
    syncPanels();
  }

  /** H applied to (x, y): the projective map, divided by the third coordinate. */
  function mapPoint(x, y, out) {
    const m = matrix;
    const w = m[6] * x + m[7] * y + m[8];
    out[0] = (m[0] * x + m[1] * y + m[2]) / w;
    out[1] = (m[3] * x + m[4] * y + m[5]) / w;
  }

  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const s = r.scale;

    // The source square with its grid, and (when the map keeps it finite) its image.
    r.beginPath();
    r.rect(v.sx(0), v.sy(SIZE), SIZE * v.scale, SIZE * v.scale);
    r.paint(theme.helperFill);
    r.beginPath();
    for (let k = 1; k < GRID; k++) {
      const c = (k * SIZE) / GRID;
      r.moveTo(v.sx(c), v.sy(0));
      r.lineTo(v.sx(c), v.sy(SIZE));
      r.moveTo(v.sx(0), v.sy(c));
      r.lineTo(v.sx(SIZE), v.sy(c));
    }
    r.paint(theme.helper);
    if (squareVisible) {
      r.beginPath();
      for (let k = 0; k <= 4; k++) moveOrLine(r, v, k === 0, SQUARE[2 * (k % 4)], SQUARE[2 * (k % 4) + 1]);
      r.paint(theme.helperFill);
      r.beginPath();
      for (let k = 1; k < GRID; k++) {
        const c = (k * SIZE) / GRID;
        moveOrLine(r, v, true, c, 0);
        moveOrLine(r, v, false, c, SIZE);
        moveOrLine(r, v, true, 0, c);
        moveOrLine(r, v, false, SIZE, c);
      }
      r.paint(theme.helper);
    }
    for (let k = 0; k < 4; k++) {
      const x = SQUARE[2 * k];
      const y = SQUARE[2 * k + 1];
      r.text(sourceLabels[k], v.sx(x) + (x > 0 ? 6 : -6) * s, v.sy(y) + (y > 0 ? -6 : 6) * s, theme.labelSmall, x > 0 ? "left" : "right", y > 0 ? "bottom" : "top");
    }

    // The original curve and its control polygon.
    polyline(r, v, work.points, theme.polygon);
    strokeSamples(r, v, source, theme.curve);

    // The image: control polygon with the new weights, (c) dashed, (a) solid, (b) dots.
    r.beginPath();
    for (let i = 0; i < POINTS; i++) {
      if (i === 0) r.moveTo(v.sx(mappedControls[0]), v.sy(mappedControls[1]));
      else r.lineTo(v.sx(mappedControls[2 * i]), v.sy(mappedControls[2 * i + 1]));
    }
    r.paint(theme.polygon);
    strokeSamples(r, v, naiveSamples, theme.compareCurve[1]);
    strokeSamples(r, v, image, theme.curve);
    for (let k = 0; k < SAMPLES; k += DOT_EVERY) r.point(v.sx(pointwise[2 * k]), v.sy(pointwise[2 * k + 1]), theme.levelPoint[0]);
    // Mapped control points, labelled with their new weights on the side away from the polygon's
    // middle; not on a phone (the key names the dashed curve, the panel lists the weights).
    const labelled = v.width >= NARROW_CANVAS_PX * s;
    let mx = 0;
    for (let i = 0; i < POINTS; i++) mx += mappedControls[2 * i] / POINTS;
    for (let i = 0; i < POINTS; i++) {
      const x = v.sx(mappedControls[2 * i]);
      const y = v.sy(mappedControls[2 * i + 1]);
      r.point(x, y, theme.comparePoint[0]);
      const left = mappedControls[2 * i] < mx;
      if (labelled) r.text(mappedLabels[i], x + (left ? -8 : 8) * s, y, theme.labelSmall, left ? "right" : "left", "middle");
    }
    // The contrast curve's name at its middle sample.
    const mid = SAMPLES >> 1;
    if (labelled) r.text(t("projective.naiveLabel"), v.sx(naiveSamples[2 * mid]) + 10 * s, v.sy(naiveSamples[2 * mid + 1]), theme.labelSmall, "left", "middle");

    handles.draw(r, v);
    drawLegend(r, theme);
  }

  /** moveTo/lineTo of H(x, y) on screen. */
  function moveOrLine(r, v, move, x, y) {
    mapPoint(x, y, mapScratch);
    if (move) r.moveTo(v.sx(mapScratch[0]), v.sy(mapScratch[1]));
    else r.lineTo(v.sx(mapScratch[0]), v.sy(mapScratch[1]));
  }

  function polyline(r, v, pts, style) {
    r.beginPath();
    for (let i = 0; i < pts.length; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(style);
  }

  function strokeSamples(r, v, flat, style) {
    r.beginPath();
    for (let k = 0; k < SAMPLES; k++) {
      const x = v.sx(flat[2 * k]);
      const y = v.sy(flat[2 * k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(style);
  }

  /** Top-left key: (a) solid, (b) dots, (c) dashed. */
  function drawLegend(r, theme) {
    const s = r.scale;
    const x = 12 * s;
    const line = 26 * s;
    const gap = 21 * s;
    let y = 16 * s;
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + line, y);
    r.paint(theme.curve);
    r.text(t("projective.legendMapped"), x + line + 6 * s, y, theme.labelSmall, "left", "middle");
    y += gap;
    r.point(x + 4 * s, y, theme.levelPoint[0]);
    r.point(x + 13 * s, y, theme.levelPoint[0]);
    r.point(x + 22 * s, y, theme.levelPoint[0]);
    r.text(t("projective.legendPointwise"), x + line + 6 * s, y, theme.labelSmall, "left", "middle");
    y += gap;
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + line, y);
    r.paint(theme.compareCurve[1]);
    r.text(t("projective.legendNaive"), x + line + 6 * s, y, theme.labelSmall, "left", "middle");
  }

  // ------------------------------------------------------------ panels
  function syncPanels() {
    gapText.textContent = t("projective.gaps", { ab: smallText(gapAB), ac: smallText(gapAC) });
    gapText.dataset.gapAb = String(gapAB);
    gapText.dataset.gapAc = String(gapAC);
    const mw = Array.from(mappedWeights, mappedText);
    weightsText.textContent = t("projective.mappedWeights", { weights: mw.join(", ") });
    weightsText.dataset.weights = Array.from(mappedWeights).join(",");

    const m = matrix;
    const affine = Math.abs(m[6]) < DENOMINATOR_EPSILON && Math.abs(m[7]) < DENOMINATOR_EPSILON;
    view.setLabel(t("projective.aria", {
      corners: work.corners.map(([x, y]) => `(${fmt(x, 2)}, ${fmt(y, 2)})`).join(", "),
      kind: t(affine ? "projective.affineMap" : "projective.perspectiveMap"),
      weights: mw.join(", "),
      ab: smallText(gapAB),
      ac: smallText(gapAC),
    }));

    const row = (k) => `${fmt(m[3 * k])} & ${fmt(m[3 * k + 1])} & ${fmt(m[3 * k + 2])}`;
    // One worked product (for P₀) keeps the line inside the panel; the next line lists them all.
    const [x0, y0] = work.points[0];
    const product0 = `${weightText(work.weights[0])}\\,(${fmt(m[6])}\\cdot ${fmt(x0)} + ${fmt(m[7])}\\cdot ${fmt(y0)} + 1) = ${mw[0]}`;
    formula.set([
      `H = \\begin{pmatrix} ${row(0)} \\\\ ${row(1)} \\\\ ${row(2)} \\end{pmatrix},\\qquad (w_iP_i,\\ w_i) \\;\\mapsto\\; H\\,(w_ix_i,\\ w_iy_i,\\ w_i)^{\\mathsf T} = (w'_iP'_i,\\ w'_i)`,
      `w'_i = w_i\\,(h_{31}x_i + h_{32}y_i + h_{33}):\\qquad w'_0 = ${product0}`,
      `(w'_0, \\dots, w'_{${POINTS - 1}}) = (${mw.join(",\\ ")})\\quad\\text{(affine map: } h_{31} = h_{32} = 0 \\text{, weights unchanged)}`,
      `\\max_t \\lVert (a) - (b) \\rVert = ${texNumber(gapAB)} \\quad\\text{(invariant)},\\qquad \\max \\operatorname{dist}\\big((c), (a)\\big) = ${texNumber(gapAC)} \\quad\\text{(weights ignored)}`,
    ]);
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    update(state) {
      const nextMatrix = homography(state.corners);
      const nextCurve = new sl.BezierCurve(flatten(state.points), 2, new Float64Array(state.weights)); // throws first
      let nextMapped;
      try {
        nextMapped = nextCurve.projectiveMap(nextMatrix);
      } catch (err) {
        nextCurve.free();
        throw err;
      }
      const nextNaive = new sl.BezierCurve(nextMapped.controlPoints(), 2, new Float64Array(state.weights));
      curve.free();
      mapped.free();
      naive.free();
      curve = nextCurve;
      mapped = nextMapped;
      naive = nextNaive;
      matrix = nextMatrix;
      work = structuredClone(state);
      handles.forgetPointer();
      weightSliders.forEach((s, i) => s.set(work.weights[i]));
      dirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
      mapped.free();
      naive.free();
    },
  };
}

/** The source square's corners S₀ … S₃, flat. */
const SQUARE = Object.freeze([0, 0, SIZE, 0, SIZE, SIZE, 0, SIZE]);

/** Distance from (x, y) to the polyline through flat points `flat`. */
function distanceToPolyline(x, y, flat) {
  let best = Infinity;
  for (let k = 0; k + 3 < flat.length; k += 2) {
    const ax = flat[k];
    const ay = flat[k + 1];
    const dx = flat[k + 2] - ax;
    const dy = flat[k + 3] - ay;
    const length2 = dx * dx + dy * dy;
    const s = length2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / length2)) : 0;
    best = Math.min(best, Math.hypot(x - ax - s * dx, y - ay - s * dy));
  }
  return best;
}

/** TeX of a measured distance: 0, m × 10^e, or 3 decimals. */
function texNumber(x) {
  if (x === 0) return "0";
  if (x >= SMALL) return fmt(x);
  const [m, e] = x.toExponential(1).split("e");
  return `${m} \\times 10^{${Number(e)}}`;
}

/** The square and the quadrilateral together (the curves lie inside or near them). */
function boundsOf(state) {
  let x0 = 0;
  let y0 = 0;
  let x1 = SIZE;
  let y1 = SIZE;
  for (const [x, y] of [...state.corners, ...state.points]) {
    x0 = Math.min(x0, x);
    y0 = Math.min(y0, y);
    x1 = Math.max(x1, x);
    y1 = Math.max(y1, y);
  }
  return [x0, y0, x1, y1];
}
