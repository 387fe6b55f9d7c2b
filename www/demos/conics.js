/**
 * Demo (syllabus §4): conic sections as rational quadratic Bézier curves. Three draggable
 * points and the middle weight w₁ (w₀ = w₂ = 1): the core names the conic (`conicKind`), an
 * ellipse arc below w₁ = 1, a parabola at 1, a hyperbola above. With an isosceles control
 * triangle and w₁ = sin θ (θ half the angle at P₁) the arc is circular: the demo then draws the
 * whole circle (`circle` from the core) and measures every sample's distance from its centre.
 * "Make circular" asks the core for that weight (`circularArcBezier`).
 *
 * As in the reference demo: the curve is updated in place (`setControlPoint`, `setWeight`),
 * one `sampleUniform` per change, nothing allocated in the draw path, replaced objects freed.
 * The triangle's angle and the circle's centre are read off the three points (display and
 * measurement, not a curve algorithm).
 */
import { Handles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, group, el } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber } from "../lib/validate.js";
import { fmt } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { scaledInsets } from "../lib/view.js";

export const id = "conics";
/** Prefix of this demo's keys in strings.js. */
export const strings = "conics";
export const title = t("conics.title");
export const summary = t("conics.summary");
/** Syllabus section. */
export const section = 4;

/**
 * An isosceles triangle (|P₀P₁| = |P₁P₂| = √13) with w₁ = 1/2: an ellipse arc, a little flatter
 * than the circle it becomes at w₁ = sin θ = 2/√13 ≈ 0.555.
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 3], [4, 0]].map(Object.freeze)),
  w1: 0.5,
});

/** Range of w₁ (a logarithmic slider). */
export const W1_MIN = 0.05;
export const W1_MAX = 5;
/** Slider step in log10 units. */
const W1_LOG_STEP = 0.002;
/** Points sampled along the curve (one `sampleUniform` per change). */
const CURVE_SAMPLES = 256;
/** Points sampled along the reference circle, and for the radius measurement. */
const CIRCLE_SAMPLES = 181;
/** Relative tolerance for |P₀P₁| = |P₁P₂| and for w₁ = sin θ (a circle is exact or it is not). */
const CIRCLE_TOLERANCE = 1e-9;
/** Below this cos θ the triangle is flat (the circle's centre is at infinity). */
const FLAT_COS = 1e-9;
/** Degrees per radian, for the angle readouts. */
const DEGREES = 180 / Math.PI;
/** Radius errors below this are written in exponent form. */
const SMALL = 1e-3;
/** Height of the band at the top kept for the conic's name and the key, CSS px at text scale 1. */
const LEGEND_PX = 52;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "w1"]);
  checkPoints(state, "points", { min: 3, max: 3 });
  checkNumber(state, "w1", { min: W1_MIN, max: W1_MAX });
}

/** A small number to print precision: "0", "3.3e-16" or 3 decimals. */
function smallText(x) {
  return x === 0 ? "0" : x < SMALL ? x.toExponential(1) : fmt(x);
}

/**
 * The control triangle's measures: legs |P₁P₀|, |P₁P₂|, half the angle at P₁, and when the legs
 * are equal the circle tangent to both legs at P₀ and P₂ (centre on the bisector at |P₁P₀|/cos θ
 * from P₁, radius |P₁P₀|·tan θ).
 */
function triangleOf(points) {
  const [[x0, y0], [x1, y1], [x2, y2]] = points;
  const a = Math.hypot(x0 - x1, y0 - y1);
  const b = Math.hypot(x2 - x1, y2 - y1);
  const result = { a, b, theta: NaN, sin: NaN, isosceles: false, centre: null, radius: NaN };
  if (a === 0 || b === 0) return result;
  const cos = ((x0 - x1) * (x2 - x1) + (y0 - y1) * (y2 - y1)) / (a * b);
  result.theta = Math.acos(Math.min(1, Math.max(-1, cos))) / 2;
  result.sin = Math.sin(result.theta);
  result.isosceles = Math.abs(a - b) <= CIRCLE_TOLERANCE * Math.max(a, b);
  const cosTheta = Math.cos(result.theta);
  if (result.isosceles && cosTheta > FLAT_COS && result.sin > FLAT_COS) {
    const mx = (x0 + x2) / 2 - x1;
    const my = (y0 + y2) / 2 - y1;
    const m = Math.hypot(mx, my);
    const d = a / cosTheta;
    result.centre = [x1 + (mx / m) * d, y1 + (my / m) * d];
    result.radius = a * Math.tan(result.theta);
  }
  return result;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  let work = structuredClone(initialState);
  let curve = new sl.BezierCurve(flatten(work.points), 2, weightsOf(work.w1));
  let parabola = new sl.BezierCurve(flatten(work.points), 2); // w₁ = 1, for comparison
  let circle = null; // sl.circle(centre, radius) when the arc is circular

  // Derived data, recomputed when the points or w₁ changed.
  let samples = null;
  let parabolaSamples = null;
  let circleSamples = null;
  let shoulder = null; // P(1/2)
  let kind = "";
  let triangle = null;
  let circular = false;
  let radiusError = NaN; // max | |P(t) − O| − R | over the samples, when isosceles
  let dirty = true;
  const pointScratch = new Float64Array(2);
  const handleLabels = ["P₀", "P₁", "P₂"];
  let kindLabel = "";

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets: scaledInsets(LEGEND_PX, 0, 0, 0) });
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
      curve.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
      parabola.setControlPoint(i, pointScratch);
      dirty = true;
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
  });

  // ------------------------------------------------------------ side panel
  const wSlider = slider({
    label: t("conics.w1"),
    inputLabel: t("conics.w1.input"),
    name: "w1",
    min: W1_MIN,
    max: W1_MAX,
    step: W1_LOG_STEP,
    log: true,
    value: work.w1,
    onChange: (value, final) => setW1(value, final),
    badNumber: (text) => t("conics.badWeight", { value: text, min: W1_MIN, max: W1_MAX }),
    onError: (message) => ctx.status(message, "error"),
  });
  const kindText = el("p", { class: "sl-readout", dataset: { info: "kind" }, "aria-live": "polite" });
  const shapeText = el("p", { class: "sl-note", dataset: { info: "shape" } });
  const triangleText = el("p", { class: "sl-note", dataset: { info: "triangle" } });
  const circleText = el("p", { class: "sl-note", dataset: { info: "circle" } });
  const circleButton = button({ label: t("conics.makeCircular"), title: t("conics.makeCircular.title"), name: "make-circular", onClick: () => makeCircular() });
  ctx.slots.controls.append(
    group(null, wSlider.element, kindText, shapeText),
    group(t("conics.circleLegend"), triangleText, circleText, el("div", { class: "sl-button-row" }, circleButton)),
  );

  // ------------------------------------------------------------ formula and table of cases
  const formula = new FormulaPanel(ctx.slots.formula);
  const tableTitle = el("p", { class: "sl-table-title", id: `sl-conics-${Math.random().toString(36).slice(2, 8)}`, text: t("conics.tableCaption") });
  const caseCells = {};
  const caseRows = ["ellipse", "parabola", "hyperbola"].map((name) => {
    caseCells[name] = el("td", { dataset: { kind: name }, text: t(`conics.kind.${name}`) });
    return el("tr", {}, caseCells[name], el("td", { text: t(`conics.rule.${name}`) }));
  });
  const table = el("table", { class: "sl-table", dataset: { table: "conics" }, "aria-labelledby": tableTitle.id },
    el("thead", {}, el("tr", {}, el("th", { scope: "col", text: t("conics.column.kind") }), el("th", { scope: "col", text: t("conics.column.rule") }))),
    el("tbody", {}, caseRows));
  ctx.slots.details.append(tableTitle, el("div", { class: "sl-table-wrap" }, table));

  // ------------------------------------------------------------ edits

  function setW1(value, final) {
    work.w1 = value;
    curve.setWeight(1, value);
    wSlider.set(value);
    dirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  /**
   * Makes the arc circular: P₂ slides along the ray P₁P₂ until |P₁P₂| = |P₁P₀| (the triangle
   * becomes isosceles), then the core's `circularArcBezier` gives w₁ = sin θ.
   */
  function makeCircular() {
    const [p0, p1, p2] = work.points;
    const a = Math.hypot(p0[0] - p1[0], p0[1] - p1[1]);
    const b = Math.hypot(p2[0] - p1[0], p2[1] - p1[1]);
    const q = b > 0 && a !== b ? [p1[0] + ((p2[0] - p1[0]) * a) / b, p1[1] + ((p2[1] - p1[1]) * a) / b] : [p2[0], p2[1]];
    let w;
    try {
      const arc = sl.circularArcBezier(flatten([p0, p1, q]));
      w = arc.weights()[1];
      arc.free();
    } catch (err) {
      ctx.status(t("conics.notCircular", { message: err.message }), "error");
      return;
    }
    if (w < W1_MIN) {
      ctx.status(t("conics.tooFlat", { w: fmt(w), min: W1_MIN }), "error");
      return;
    }
    work.points[2] = q;
    pointScratch[0] = q[0];
    pointScratch[1] = q[1];
    curve.setControlPoint(2, pointScratch);
    parabola.setControlPoint(2, pointScratch);
    setW1(w, true);
    ctx.status(t("conics.madeCircular", { w: fmt(w) }), "info");
  }

  // ------------------------------------------------------------ drawing
  function recompute() {
    if (!dirty) return;
    dirty = false;
    samples = curve.sampleUniform(CURVE_SAMPLES);
    parabolaSamples = parabola.sampleUniform(CURVE_SAMPLES);
    shoulder = curve.evaluate(0.5);
    kind = sl.conicKind(1, work.w1, 1);
    triangle = triangleOf(work.points);
    circular = !!triangle.centre && Math.abs(work.w1 - triangle.sin) <= CIRCLE_TOLERANCE;
    // Measurement against the circle tangent to both legs (only an isosceles triangle has one).
    radiusError = NaN;
    circle?.free();
    circle = null;
    circleSamples = null;
    if (triangle.centre) {
      const [cx, cy] = triangle.centre;
      radiusError = 0;
      for (let k = 0; k < CURVE_SAMPLES; k++) {
        radiusError = Math.max(radiusError, Math.abs(Math.hypot(samples[2 * k] - cx, samples[2 * k + 1] - cy) - triangle.radius));
      }
      if (circular) {
        circle = sl.circle(cx, cy, triangle.radius);
        circleSamples = circle.sampleUniform(CIRCLE_SAMPLES);
      }
    }
    kindLabel = circular ? t("conics.figureCircle", { kind: t(`conics.kind.${kind}`) }) : t(`conics.kind.${kind}`);
    syncPanels();
  }

  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;

    // The whole circle (dashed) and its centre, when the arc is circular.
    if (circleSamples) {
      strokeSamples(r, v, circleSamples, CIRCLE_SAMPLES, theme.helper);
      const ox = v.sx(triangle.centre[0]);
      const oy = v.sy(triangle.centre[1]);
      r.point(ox, oy, theme.comparePoint[0]);
      r.text(t("conics.centre"), ox + 8 * r.scale, oy, theme.labelSmall, "left", "middle");
    }

    // Control triangle, the chord P₀P₂ and the line from its midpoint M to P₁ (the shoulder lies on it).
    r.beginPath();
    r.moveTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
    r.lineTo(v.sx(pts[1][0]), v.sy(pts[1][1]));
    r.lineTo(v.sx(pts[2][0]), v.sy(pts[2][1]));
    r.paint(theme.polygon);
    const mx = v.sx((pts[0][0] + pts[2][0]) / 2);
    const my = v.sy((pts[0][1] + pts[2][1]) / 2);
    r.beginPath();
    r.moveTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
    r.lineTo(v.sx(pts[2][0]), v.sy(pts[2][1]));
    r.moveTo(mx, my);
    r.lineTo(v.sx(pts[1][0]), v.sy(pts[1][1]));
    r.paint(theme.helper);
    r.point(mx, my, theme.comparePoint[2]);
    r.text(t("conics.midpoint"), mx, my + 8 * r.scale, theme.labelSmall, "center", "top");

    // The parabola (w₁ = 1) for comparison, then the conic.
    strokeSamples(r, v, parabolaSamples, CURVE_SAMPLES, theme.compareCurve[2]);
    strokeSamples(r, v, samples, CURVE_SAMPLES, theme.curve);

    handles.draw(r, v);
    const sx = v.sx(shoulder[0]);
    const sy = v.sy(shoulder[1]);
    r.point(sx, sy, theme.pointOnCurve);
    r.text(t("conics.shoulder"), sx + 9 * r.scale, sy, theme.labelPoint, "left", "bottom");

    // The kind, large, top left; the legend under it.
    const s = r.scale;
    r.text(kindLabel, 12 * s, 18 * s, theme.labelBold, "left", "middle");
    r.beginPath();
    r.moveTo(12 * s, 42 * s);
    r.lineTo(38 * s, 42 * s);
    r.paint(theme.compareCurve[2]);
    r.text(t("conics.legendParabola"), 44 * s, 42 * s, theme.labelSmall, "left", "middle");
  }

  function strokeSamples(r, v, flat, count, style) {
    r.beginPath();
    for (let k = 0; k < count; k++) {
      const x = v.sx(flat[2 * k]);
      const y = v.sy(flat[2 * k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(style);
  }

  // ------------------------------------------------------------ panels
  function syncPanels() {
    const w1 = work.w1;
    const factor = w1 * w1; // w₁² / (w₀ w₂) with w₀ = w₂ = 1
    const kindName = t(`conics.kind.${kind}`);
    kindText.textContent = circular ? t("conics.readoutCircle", { kind: kindName }) : kindName;
    kindText.dataset.kind = kind;
    kindText.dataset.circle = String(circular);
    const relation = kind === "ellipse" ? "<" : kind === "parabola" ? "=" : ">";
    shapeText.textContent = t("conics.shape", { w: fmt(w1), k: fmt(factor), relation });
    shapeText.dataset.factor = String(factor);
    for (const name of Object.keys(caseCells)) caseCells[name].classList.toggle("sl-highlight", name === kind);

    const tri = triangle;
    const angle = Number.isFinite(tri.theta) ? fmt(2 * tri.theta * DEGREES, 2) : "—";
    triangleText.textContent = Number.isFinite(tri.theta)
      ? t(tri.isosceles ? "conics.triangleIsosceles" : "conics.triangle", { a: fmt(tri.a), b: fmt(tri.b), angle, sin: fmt(tri.sin) })
      : t("conics.triangleDegenerate");
    triangleText.dataset.sin = String(tri.sin);
    if (circular) circleText.textContent = t("conics.circleYes", { error: smallText(radiusError), r: fmt(tri.radius) });
    else if (tri.centre) circleText.textContent = t("conics.circleNo", { sin: fmt(tri.sin), error: smallText(radiusError) });
    else circleText.textContent = t("conics.circleNeedsIsosceles");
    circleText.dataset.radiusError = Number.isNaN(radiusError) ? "" : String(radiusError);
    circleText.dataset.circle = String(circular);

    const [p0, p1, p2] = work.points;
    view.setLabel(t("conics.aria", {
      kind: t(`conics.article.${kind}`),
      p0: `(${fmt(p0[0], 2)}, ${fmt(p0[1], 2)})`,
      p1: `(${fmt(p1[0], 2)}, ${fmt(p1[1], 2)})`,
      p2: `(${fmt(p2[0], 2)}, ${fmt(p2[1], 2)})`,
      w: fmt(w1),
      k: fmt(factor),
      circle: circular ? t("conics.ariaCircle", { r: fmt(tri.radius, 2), x: fmt(tri.centre[0], 2), y: fmt(tri.centre[1], 2) }) : "",
      sx: fmt(shoulder[0], 2),
      sy: fmt(shoulder[1], 2),
    }));

    const kindTex = `\\text{${kindName}}`;
    const circleLine = `\\text{circular arc} \\iff |P_0P_1| = |P_1P_2| \\text{ and } w_1 = \\sin\\theta,\\quad \\theta = \\tfrac12\\angle P_0P_1P_2`;
    const circleNumbers = Number.isFinite(tri.theta)
      ? `|P_0P_1| = ${fmt(tri.a)},\\ |P_1P_2| = ${fmt(tri.b)},\\ \\theta = ${fmt(tri.theta * DEGREES, 2)}^\\circ,\\ \\sin\\theta = ${fmt(tri.sin)}\\quad ${circular ? "\\Rightarrow\\ \\text{circle!}" : `(w_1 = ${fmt(w1)})`}`
      : `|P_0P_1| = ${fmt(tri.a)},\\ |P_1P_2| = ${fmt(tri.b)}`;
    formula.set([
      `P(t) = \\frac{(1-t)^2\\,w_0P_0 + 2t(1-t)\\,w_1P_1 + t^2\\,w_2P_2}{(1-t)^2\\,w_0 + 2t(1-t)\\,w_1 + t^2\\,w_2},\\qquad w_0 = w_2 = 1,\\ w_1 = ${fmt(w1)}`,
      `k = \\frac{w_1^2}{w_0\\,w_2} = ${fmt(factor)} ${relation} 1 \\;\\Rightarrow\\; ${kindTex}\\qquad (k < 1 \\text{ ellipse},\\ k = 1 \\text{ parabola},\\ k > 1 \\text{ hyperbola})`,
      circleLine,
      circleNumbers,
      `P(\\tfrac12) = \\frac{M + w_1P_1}{1 + w_1} = (${fmt(shoulder[0])},\\ ${fmt(shoulder[1])}),\\quad M = \\tfrac12(P_0 + P_2)`,
    ]);
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    update(state) {
      const nextCurve = new sl.BezierCurve(flatten(state.points), 2, weightsOf(state.w1)); // throws first
      const nextParabola = new sl.BezierCurve(flatten(state.points), 2);
      curve.free();
      parabola.free();
      curve = nextCurve;
      parabola = nextParabola;
      work = structuredClone(state);
      handles.forgetPointer();
      wSlider.set(work.w1);
      dirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
      parabola.free();
      circle?.free();
    },
  };
}

/** The weights (1, w₁, 1). */
function weightsOf(w1) {
  return new Float64Array([1, w1, 1]);
}

