/**
 * Demo (syllabus §4): exact circles, arcs and ellipses as NURBS. The core builds them
 * (`circle`, `circularArc`, `ellipse`, `ellipseArc`): degree 2, the sweep cut into pieces of at
 * most 90°, middle weights cos(Δ/2). The figure shows the control polygon with every weight, the
 * pieces' joints on the curve, and the demo measures how round the result is: the largest
 * | |C(u) − c| − r | over 2000 samples, which reads 0 or a few 1e-16 (rounding).
 *
 * Dragging the centre translates the control points in place (`setControlPoint`); the sliders
 * build a new curve from the core (the old one is freed). The measurement is the only number
 * the demo computes itself.
 */
import { Handles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, checkbox, group, el } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkBoolean } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, fractionText, fractionTex } from "../lib/format.js";
import { t } from "../lib/strings.js";

export const id = "nurbs-circle";
/** Prefix of this demo's keys in strings.js. */
export const strings = "nurbsCircle";
export const title = t("nurbsCircle.title");
export const summary = t("nurbsCircle.summary");
/** Syllabus section. */
export const section = 4;

/** The full circle of radius 2 about the origin: the 9-point NURBS of the syllabus. */
export const defaultState = Object.freeze({
  points: Object.freeze([Object.freeze([0, 0])]),
  radius: 2,
  start: 0,
  sweep: 360,
  ellipse: false,
  rx: 3,
  ry: 2,
  rotation: 0,
});

/** Ranges of the sliders (lengths in model units, angles in degrees). */
export const LENGTH_MIN = 0.1;
export const LENGTH_MAX = 10;
const LENGTH_STEP = 0.01;
export const ANGLE_MAX = 360;
const ANGLE_STEP = 1;
/** Where the radius label sits along the radius, from the centre (fraction of its length). */
const RADIUS_LABEL_AT = 0.6;
/** Samples of the curve: drawn, and measured against the exact circle (ellipse). */
const SAMPLES = 2000;
/** Weights this close to √2/2 or 1 are written as such. */
const EXACT_WEIGHT = 1e-12;
const RADIANS = Math.PI / 180;
/** Errors below this are written in exponent form. */
const SMALL = 1e-3;
/** The fitted window is this many radii wide on each side (labels beside the control points). */
const LABEL_ROOM = 1.6;
/** Radius of the rings that mark the pieces' joints on the curve, CSS px. */
const JOINT_RING_PX = 8;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "radius", "start", "sweep", "ellipse", "rx", "ry", "rotation"]);
  checkPoints(state, "points", { min: 1, max: 1 });
  for (const field of ["radius", "rx", "ry"]) {
    checkNumber(state, field);
    if (state[field] <= 0) throw new Error(t("nurbsCircle.notPositive", { field, value: state[field] }));
    checkNumber(state, field, { min: LENGTH_MIN, max: LENGTH_MAX });
  }
  checkNumber(state, "start", { min: -ANGLE_MAX, max: ANGLE_MAX });
  checkNumber(state, "sweep", { min: -ANGLE_MAX, max: ANGLE_MAX });
  if (state.sweep === 0) throw new Error(t("nurbsCircle.zeroSweep"));
  checkBoolean(state, "ellipse");
  checkNumber(state, "rotation", { min: -ANGLE_MAX, max: ANGLE_MAX });
}

/** True when the state asks for the whole closed curve starting at angle 0. */
function isFull(state) {
  return state.start === 0 && state.sweep === ANGLE_MAX;
}

/** The NURBS of a state, from the core's constructors (throws their message on bad input). */
function buildCurve(sl, state) {
  const [cx, cy] = state.points[0];
  const start = state.start * RADIANS;
  const sweep = state.sweep * RADIANS;
  if (!state.ellipse) {
    return isFull(state) ? sl.circle(cx, cy, state.radius) : sl.circularArc(cx, cy, state.radius, start, sweep);
  }
  const rotation = state.rotation * RADIANS;
  if (isFull(state)) return sl.ellipse(cx, cy, state.rx, state.ry, rotation);
  const c = Math.cos(rotation);
  const s = Math.sin(rotation);
  const axisX = new Float64Array([state.rx * c, state.rx * s]);
  const axisY = new Float64Array([-state.ry * s, state.ry * c]);
  return sl.ellipseArc(new Float64Array([cx, cy]), axisX, axisY, start, sweep);
}

/** "1", "√2/2" or three decimals. */
function weightText(w) {
  if (Math.abs(w - 1) <= EXACT_WEIGHT) return "1";
  if (Math.abs(w - Math.SQRT1_2) <= EXACT_WEIGHT) return "√2/2";
  return fmt(w);
}

function weightTex(w) {
  if (Math.abs(w - 1) <= EXACT_WEIGHT) return "1";
  if (Math.abs(w - Math.SQRT1_2) <= EXACT_WEIGHT) return "\\tfrac{\\sqrt2}{2}";
  return fmt(w);
}

/** A knot as a fraction when it is one (1/4), else three decimals. */
function knotText(u) {
  const f = simpleFraction(u);
  return f ? fractionText(f) : fmt(u);
}

function knotTex(u) {
  const f = simpleFraction(u);
  return f ? fractionTex(f) : fmt(u);
}

/** A measured error to print precision: "0", "3.3e-16", or 3 decimals when large. */
function errorText(x) {
  return x === 0 ? "0" : x < SMALL ? x.toExponential(1) : fmt(x);
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  let work = structuredClone(initialState);
  let curve = buildCurve(sl, work);

  // Per curve (rebuilt with it): control points at build time and the centre they were built about.
  let base = null;
  const builtAt = new Float64Array(2);
  let weights = null;
  let knots = null;
  let pieces = 0;
  // Per change.
  let samples = null;
  let controls = null;
  let joints = null; // the curve at its distinct knots (the pieces' ends)
  let jointParams = null;
  let error = 0;
  let dirty = true;
  const pointScratch = new Float64Array(2);
  const weightLabels = []; // "w = √2/2" per control point
  let centreLabel = "";
  let radiusLabel = "";

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work) });
  const handles = new Handles(view, {
    count: () => 1,
    get: (i, out) => {
      out[0] = work.points[0][0];
      out[1] = work.points[0][1];
    },
    label: () => centreLabel,
    move: (i, x, y) => {
      work.points[0][0] = x;
      work.points[0][1] = y;
      // A translation: every control point moves by the same vector, in place.
      const dx = x - builtAt[0];
      const dy = y - builtAt[1];
      for (let k = 0; k < base.length / 2; k++) {
        pointScratch[0] = base[2 * k] + dx;
        pointScratch[1] = base[2 * k + 1] + dy;
        curve.setControlPoint(k, pointScratch);
      }
      dirty = true;
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
  });

  // ------------------------------------------------------------ side panel
  const lengthSlider = (field) => slider({
    label: t(`nurbsCircle.${field}`),
    inputLabel: t(`nurbsCircle.${field}.input`),
    name: field,
    min: LENGTH_MIN,
    max: LENGTH_MAX,
    step: LENGTH_STEP,
    value: work[field],
    onChange: (value, final) => change(field, value, final),
    badNumber: (text) => t("nurbsCircle.badLength", { field, value: text, min: LENGTH_MIN, max: LENGTH_MAX }),
    onError: (message) => ctx.status(message, "error"),
  });
  const angleSlider = (field) => slider({
    label: t(`nurbsCircle.${field}`),
    inputLabel: t(`nurbsCircle.${field}.input`),
    name: field,
    min: -ANGLE_MAX,
    max: ANGLE_MAX,
    step: ANGLE_STEP,
    value: work[field],
    format: (v) => String(Number(v.toFixed(2))),
    onChange: (value, final) => change(field, value, final),
    badNumber: (text) => t("nurbsCircle.badAngle", { field, value: text, max: ANGLE_MAX }),
    onError: (message) => ctx.status(message, "error"),
  });
  const sliders = {
    radius: lengthSlider("radius"),
    rx: lengthSlider("rx"),
    ry: lengthSlider("ry"),
    rotation: angleSlider("rotation"),
    start: angleSlider("start"),
    sweep: angleSlider("sweep"),
  };
  const ellipseBox = checkbox({
    label: t("nurbsCircle.ellipseMode"),
    name: "ellipse",
    checked: work.ellipse,
    onChange: (on) => change("ellipse", on, true),
  });
  const circleGroup = group(t("nurbsCircle.circleLegend"), sliders.radius.element);
  const ellipseGroup = group(t("nurbsCircle.ellipseLegend"), sliders.rx.element, sliders.ry.element, sliders.rotation.element);
  const fullButton = button({ label: t("nurbsCircle.full"), title: t("nurbsCircle.full.title"), name: "full", onClick: () => setFull() });
  const countText = el("p", { class: "sl-note", dataset: { info: "count" } });
  const knotsText = el("p", { class: "sl-note", dataset: { info: "knots" } });
  const errorReadout = el("p", { class: "sl-readout", dataset: { info: "error" }, "aria-live": "polite" });
  const errorNote = el("p", { class: "sl-note" });
  ctx.slots.controls.append(
    group(null, ellipseBox.element),
    circleGroup,
    ellipseGroup,
    group(t("nurbsCircle.arcLegend"), sliders.start.element, sliders.sweep.element, el("div", { class: "sl-button-row" }, fullButton)),
    group(t("nurbsCircle.resultLegend"), errorReadout, errorNote, countText, knotsText),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const tableTitle = el("p", { class: "sl-table-title", id: `sl-nurbs-circle-${Math.random().toString(36).slice(2, 8)}` });
  const table = el("table", { class: "sl-table", dataset: { table: "nurbs-circle" }, "aria-labelledby": tableTitle.id });
  ctx.slots.details.append(tableTitle, el("div", { class: "sl-table-wrap" }, table));

  // ------------------------------------------------------------ edits

  /**
   * A control changed: build the new curve from the core; on refusal (e.g. a zero sweep) show
   * the core's message and keep the last good curve.
   */
  function change(field, value, final) {
    const next = { ...work, [field]: value };
    let nextCurve;
    try {
      if (field === "sweep" && value === 0) throw new Error(t("nurbsCircle.zeroSweep"));
      nextCurve = buildCurve(sl, next);
    } catch (err) {
      ctx.status(t("nurbsCircle.refused", { message: err.message }), "error");
      if (final) sliders[field]?.set(work[field]);
      return;
    }
    curve.free();
    curve = nextCurve;
    work[field] = value;
    sliders[field]?.set(value);
    curveChanged();
    if (final) ctx.commit(work);
  }

  function setFull() {
    const nextCurve = buildCurve(sl, { ...work, start: 0, sweep: ANGLE_MAX });
    curve.free();
    curve = nextCurve;
    work.start = 0;
    work.sweep = ANGLE_MAX;
    sliders.start.set(0);
    sliders.sweep.set(ANGLE_MAX);
    curveChanged();
    ctx.commit(work);
  }

  /** Reads what stays fixed for a curve (control points at build, weights, knots, pieces). */
  function curveChanged() {
    base = curve.controlPoints();
    builtAt[0] = work.points[0][0];
    builtAt[1] = work.points[0][1];
    weights = curve.weights();
    knots = curve.knots();
    pieces = curve.spans().length;
    const distinct = [];
    for (const u of knots) if (distinct.length === 0 || u !== distinct[distinct.length - 1]) distinct.push(u);
    jointParams = new Float64Array(distinct);
    weightLabels.length = 0;
    const last = base.length - 2;
    const closed = Math.abs(base[0] - base[last]) <= EXACT_WEIGHT && Math.abs(base[1] - base[last + 1]) <= EXACT_WEIGHT;
    for (let i = 0; i < weights.length; i++) {
      const name = i === 0 && closed ? `P₀ = P${subscript(weights.length - 1)}` : `P${subscript(i)}`;
      weightLabels.push(`${name}: w = ${weightText(weights[i])}`);
    }
    circleGroup.hidden = work.ellipse;
    ellipseGroup.hidden = !work.ellipse;
    dirty = true;
    view.requestDraw();
  }

  // ------------------------------------------------------------ drawing
  function recompute() {
    if (!dirty) return;
    dirty = false;
    samples = curve.sampleUniform(SAMPLES);
    controls = curve.controlPoints();
    joints = curve.sample(jointParams);
    error = measure();
    centreLabel = t("nurbsCircle.centreLabel");
    radiusLabel = work.ellipse ? t("nurbsCircle.axesLabel", { rx: fmt(work.rx), ry: fmt(work.ry) }) : t("nurbsCircle.radiusLabel", { r: fmt(work.radius) });
    syncPanels();
  }

  /**
   * The measurement: circle, max | |C(u) − c| − r |; ellipse, max | (x′/rx)² + (y′/ry)² − 1 |
   * in the ellipse's own axes (x′, y′), over the samples.
   */
  function measure() {
    const [cx, cy] = work.points[0];
    let worst = 0;
    if (!work.ellipse) {
      for (let k = 0; k < SAMPLES; k++) {
        worst = Math.max(worst, Math.abs(Math.hypot(samples[2 * k] - cx, samples[2 * k + 1] - cy) - work.radius));
      }
      return worst;
    }
    const c = Math.cos(work.rotation * RADIANS);
    const s = Math.sin(work.rotation * RADIANS);
    for (let k = 0; k < SAMPLES; k++) {
      const dx = samples[2 * k] - cx;
      const dy = samples[2 * k + 1] - cy;
      const x = (dx * c + dy * s) / work.rx;
      const y = (-dx * s + dy * c) / work.ry;
      worst = Math.max(worst, Math.abs(x * x + y * y - 1));
    }
    return worst;
  }

  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const count = controls.length / 2;
    const cx = v.sx(work.points[0][0]);
    const cy = v.sy(work.points[0][1]);

    // Control polygon.
    r.beginPath();
    for (let i = 0; i < count; i++) {
      if (i === 0) r.moveTo(v.sx(controls[0]), v.sy(controls[1]));
      else r.lineTo(v.sx(controls[2 * i]), v.sy(controls[2 * i + 1]));
    }
    r.paint(theme.polygon);

    // Radius (or the first semi-axis) from the centre to the start of the curve.
    r.beginPath();
    r.moveTo(cx, cy);
    r.lineTo(v.sx(samples[0]), v.sy(samples[1]));
    r.paint(theme.helper);
    // Its label 60 % of the way out: clear of the centre's own label on a small circle too.
    r.text(radiusLabel, cx + RADIUS_LABEL_AT * (v.sx(samples[0]) - cx), cy + RADIUS_LABEL_AT * (v.sy(samples[1]) - cy) - 6 * r.scale, theme.labelSmall, "center", "bottom");

    // The curve.
    r.beginPath();
    for (let k = 0; k < SAMPLES; k++) {
      const x = v.sx(samples[2 * k]);
      const y = v.sy(samples[2 * k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.curve);

    // The pieces' joints (the curve at each distinct knot), as rings around the curve.
    r.beginPath();
    for (let j = 0; j < jointParams.length; j++) r.circle(v.sx(joints[2 * j]), v.sy(joints[2 * j + 1]), JOINT_RING_PX * r.scale);
    r.paint(theme.levelStroke[1]);

    // Control points with their weights, labelled outward from the centre (a repeated end point once).
    for (let i = 0; i < count; i++) {
      const x = v.sx(controls[2 * i]);
      const y = v.sy(controls[2 * i + 1]);
      const repeat = i === count - 1 && Math.abs(x - v.sx(controls[0])) < 0.5 && Math.abs(y - v.sy(controls[1])) < 0.5;
      r.point(x, y, theme.basisPoint[i % theme.basisPoint.length]);
      if (repeat) continue;
      let dx = x - cx;
      let dy = y - cy;
      const length = Math.hypot(dx, dy) || 1;
      dx /= length;
      dy /= length;
      const gap = 10 * r.scale;
      let align = dx > 0.35 ? "left" : dx < -0.35 ? "right" : "center";
      let tx = x + dx * gap;
      let ty = y + dy * gap + dy * 7 * r.scale;
      if (align !== "center") {
        // No room beside the point (a narrow canvas): above or below it (below on the x axis,
        // clear of the radius label) instead of pushed back over the point by the frame's edge.
        const width = r.measure(weightLabels[i], theme.labelSmall);
        if (align === "left" ? tx + width > v.width : tx - width < 0) {
          align = "center";
          tx = x;
          ty = y + (dy < 0 ? -1 : 1) * (gap + 7 * r.scale);
        }
      }
      r.text(weightLabels[i], tx, ty, theme.labelSmall, align, "middle");
    }

    handles.draw(r, v);
  }

  // ------------------------------------------------------------ panels
  function syncPanels() {
    const count = controls.length / 2;
    const knotList = Array.from(knots, knotText).join(", ");
    const weightList = Array.from(weights, weightText).join(", ");
    const errorString = errorText(error);
    errorReadout.textContent = t(work.ellipse ? "nurbsCircle.errorEllipse" : "nurbsCircle.errorCircle", { error: errorString });
    errorReadout.dataset.error = String(error);
    errorNote.textContent = t(work.ellipse ? "nurbsCircle.errorEllipseNote" : "nurbsCircle.errorCircleNote", { samples: SAMPLES });
    countText.textContent = t("nurbsCircle.count", { count, pieces });
    countText.dataset.points = String(count);
    countText.dataset.pieces = String(pieces);
    knotsText.textContent = t("nurbsCircle.knots", { knots: knotList });
    knotsText.dataset.knots = Array.from(knots, knotText).join(" ");

    const [x, y] = work.points[0];
    const shape = work.ellipse
      ? t("nurbsCircle.ariaEllipse", { rx: fmt(work.rx, 2), ry: fmt(work.ry, 2), rotation: fmt(work.rotation, 1) })
      : t("nurbsCircle.ariaCircle", { r: fmt(work.radius, 2) });
    view.setLabel(t("nurbsCircle.aria", {
      shape,
      x: fmt(x, 2),
      y: fmt(y, 2),
      arc: isFull(work) ? t("nurbsCircle.ariaFull") : t("nurbsCircle.ariaArc", { start: fmt(work.start, 1), sweep: fmt(work.sweep, 1) }),
      count,
      weights: weightList,
      knots: knotList,
      pieces,
      error: errorString,
    }));

    // Formula panel: the NURBS, the textbook circle, this curve's numbers, the measurement.
    const delta = Math.abs(work.sweep) / pieces;
    const middle = Math.cos((delta / 2) * RADIANS);
    formula.set([
      `C(u) = \\frac{\\sum_{i} N_{i,2}(u)\\,w_i\\,P_i}{\\sum_{i} N_{i,2}(u)\\,w_i}`,
      `\\text{circle: } P_i = c + r\\,\\{(1,0), (1,1), (0,1), (-1,1), (-1,0), (-1,-1), (0,-1), (1,-1), (1,0)\\}`,
      `w_i = 1, \\tfrac{\\sqrt2}{2}, 1, \\tfrac{\\sqrt2}{2}, 1, \\tfrac{\\sqrt2}{2}, 1, \\tfrac{\\sqrt2}{2}, 1,\\qquad U = \\{0,0,0,\\tfrac14,\\tfrac14,\\tfrac12,\\tfrac12,\\tfrac34,\\tfrac34,1,1,1\\}`,
      `\\text{here: } ${pieces} \\text{ piece${pieces === 1 ? "" : "s"} of } \\Delta = \\tfrac{${fmt(Math.abs(work.sweep), 0)}^\\circ}{${pieces}} = ${fmt(delta, 2)}^\\circ \\le 90^\\circ,\\ \\text{middle weights } \\cos\\tfrac{\\Delta}{2} = ${weightTex(middle)},\\ U = \\{${Array.from(knots, knotTex).join(", ")}\\}`,
      work.ellipse
        ? `\\max_u \\left| \\left(\\tfrac{x'(u)}{r_x}\\right)^2 + \\left(\\tfrac{y'(u)}{r_y}\\right)^2 - 1 \\right| = ${errorTex(error)}\\quad (${SAMPLES} \\text{ samples})`
        : `\\max_u \\big|\\, \\lVert C(u) - c \\rVert - r \\,\\big| = ${errorTex(error)}\\quad (${SAMPLES} \\text{ samples})`,
    ]);

    // Table: the control points and weights.
    setText(tableTitle, t("nurbsCircle.tableCaption", { count }));
    const rows = [];
    for (let i = 0; i < count; i++) {
      rows.push(el("tr", { dataset: { index: String(i) } },
        el("th", { scope: "row", text: `P${subscript(i)}` }),
        el("td", { text: `(${fmt(controls[2 * i])}, ${fmt(controls[2 * i + 1])})` }),
        el("td", { dataset: { column: "weight" }, text: weightText(weights[i]) })));
    }
    table.replaceChildren(
      el("thead", {}, el("tr", {}, el("th", { scope: "col", text: "i" }), el("th", { scope: "col", text: t("nurbsCircle.column.point") }), el("th", { scope: "col", text: t("nurbsCircle.column.weight") }))),
      el("tbody", {}, rows));
  }

  function setText(node, text) {
    if (node.textContent !== text) node.textContent = text;
  }

  curveChanged();
  recompute();

  // ------------------------------------------------------------ contract
  return {
    update(state) {
      const next = buildCurve(sl, state); // throws before anything changes
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      for (const [field, s] of Object.entries(sliders)) s.set(work[field]);
      ellipseBox.set(work.ellipse);
      curveChanged();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** TeX of a measured error: 0 or m × 10^e. */
function errorTex(x) {
  if (x === 0) return "0";
  if (x >= SMALL) return fmt(x);
  const [m, e] = x.toExponential(1).split("e");
  return `${m} \\times 10^{${Number(e)}}`;
}

/**
 * The whole circle or ellipse's box (arcs lie inside it), wider by LABEL_ROOM so the weight
 * labels beside the corner control points stay in the window.
 */
function boundsOf(state) {
  const [cx, cy] = state.points[0];
  const r = state.ellipse ? Math.max(state.rx, state.ry) : state.radius;
  return [cx - r * LABEL_ROOM, cy - r, cx + r * LABEL_ROOM, cy + r];
}
