/**
 * Demo (syllabus §3): local control and the strong convex hull of a B-spline curve. A clamped
 * B-spline (cubic by default) with integer control points; the point P_i in hand (dragged,
 * selected with the keyboard, or chosen with the slider) lights up the part of the curve it can
 * move, the parameters [u_i, u_{i+p+1}) where N_{i,p} ≠ 0; the rest of the curve does not move.
 * A parameter u picks a span k: the p + 1 active points P_{k−p} … P_k are the only ones with a
 * non-zero basis function there, and that span's piece of the curve lies inside their convex
 * hull (filled), a much smaller region than the hull of the whole polygon (outlined).
 *
 * Everything about the curve comes from the core: the knot vector (`knotVector(…, "clamped")`),
 * the samples (one `sampleUniform` for the curve, one `sample(us)` for the highlighted range,
 * one for the knot points), `span(u)`, `basis(u)` and `evaluate(u)`. JS only adds drawing
 * support: the convex hull polygon of a handful of points (monotone chain, `convexHull` in
 * lib/geometry.js) and the knot strip under the figure (ticks on a line, picked through
 * lib/param-strip.js). Drags go through `setControlPoint`.
 */
import { Handles, placeLabel, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, exactFraction, fractionText, fractionTex, allIntegers, degreeName } from "../lib/format.js";
import { CYCLE, WIDTH, RADIUS } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf, convexHull } from "../lib/geometry.js";
import { withPointAdded, withPointRemoved, pointButtons } from "../lib/point-list.js";
import { titledTable } from "../lib/table.js";
import { flatPath } from "../lib/draw.js";
import { ParameterStrip } from "../lib/param-strip.js";
import { scaledInsets } from "../lib/view.js";

export const id = "local-control";
/** Prefix of this demo's keys in strings.js. */
export const strings = "localControl";
export const title = t("localControl.title");
export const summary = t("localControl.summary");
/** Syllabus section. */
export const section = 3;

/**
 * Nine integer points and a clamped cubic: knots 0 0 0 0 1 2 3 4 5 6 6 6 6, six spans. P₄ acts
 * on [1, 5) only, so both ends of the curve stay put while it moves; u = 5/2 lies in span
 * k = 5, whose active points P₂ … P₅ have the uniform weights 1/48, 23/48, 23/48, 1/48.
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 1], [1, 4], [3, 5], [5, 2], [7, 0], [9, 3], [11, 5], [13, 3], [14, 0]].map(Object.freeze)),
  degree: 3,
  u: 2.5,
  point: 4,
});

/** Degrees offered (the clamped knot vector needs at least degree + 1 points). */
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
/** Most control points. */
export const MAX_POINTS = 14;
/** Points sampled along the whole curve (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 241;
/** Points sampled over the highlighted range [u_i, u_{i+p+1}] (one `sample(us)` call). */
const SUPPORT_SAMPLES = 121;
/** Slider resolution for u. */
const U_STEP = 0.01;
/** The knot strip under the figure: height and side margins in CSS px at scale 1. */
const STRIP_PX = 78;
const STRIP_MARGIN = 34;
/** Rows of the strip, CSS px below its top at scale 1: u label, support bar, axis, knot labels. */
const STRIP_ROW = Object.freeze({ label: 12, bar: 28, axis: 44, ticks: 62 });
/** Half-length of a knot tick, CSS px. */
const TICK_PX = 6;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "degree", "u", "point"]);
  checkPoints(state, "points", { min: MIN_DEGREE + 1, max: MAX_POINTS });
  checkNumber(state, "degree", { min: MIN_DEGREE, max: MAX_DEGREE, integer: true });
  const count = state.points.length;
  if (count < state.degree + 1) throw new Error(t("localControl.error.tooFewPoints", { min: state.degree + 1, p: state.degree, count }));
  // Clamped knots 0 … n − p + 1: the domain of u.
  checkNumber(state, "u", { min: 0, max: count - state.degree });
  checkNumber(state, "point", { min: 0, max: count - 1, integer: true });
}

/** Product over r = 1..p of lcm(1..r): with integer knot gaps ≤ r at level r, it clears every
 * Cox–de Boor denominator apart from u's own (used to show basis values as exact fractions). */
function basisDenominator(p) {
  const lcm = [1, 1, 2, 6, 12, 60];
  let d = 1;
  for (let r = 1; r <= p; r++) d *= lcm[r];
  return d;
}

/** A knot value as text: integers plain, else up to 3 decimals. */
function knotText(value) {
  return Number.isInteger(value) ? String(value) : String(Number(value.toFixed(3)));
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let knots = sl.knotVector(flatten(work.points), 2, work.degree, "clamped");
  let curve = new sl.BSplineCurve(flatten(work.points), 2, work.degree, knots);

  // Derived data, recomputed only when something changed.
  let geometryDirty = true; // points moved
  let structureDirty = true; // knots, degree or point count changed
  let supportDirty = true; // the point whose range is shown changed
  let uDirty = true;
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let supportSamples = null; // curve.sample(supportUs)
  let knotSamples = null; // curve.sample(distinct knots): the joints of the segments
  let distinct = new Float64Array(0); // distinct knot values
  let multiplicity = []; // their multiplicities
  const supportUs = new Float64Array(SUPPORT_SAMPLES);
  let supportLo = 0; // u_i
  let supportHi = 0; // u_{i+p+1}
  let span = 0; // k with u_k ≤ u < u_{k+1}
  let basis = null; // curve.basis(u)
  let point = null; // curve.evaluate(u)
  let activeHull = []; // hull vertex indices of P_{k−p} … P_k
  let wholeHull = []; // hull vertex indices of all points
  let knotLabels = []; // "0 ×4" … per distinct knot
  let uLabel = "";
  let knotStyles = null; // per theme: { dot, tick }
  let knotStylesTheme = null;

  // ------------------------------------------------------------ figure
  // The canvas strip below the world window.
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets: scaledInsets(0, 0, STRIP_PX, 0) });

  const uRange = [0, 1]; // the strip's [a, b], reused (no allocation per frame)
  // The knot strip claims the pointer before the handles: press or drag there to set u.
  const strip = new ParameterStrip(view, {
    height: STRIP_PX,
    margin: STRIP_MARGIN,
    step: U_STEP,
    range: () => {
      uRange[1] = domainEnd();
      return uRange;
    },
    pick: (u, final) => setU(u, final),
    over: () => handles.leave(), // the pointer left the handles' area (they are not asked while it is here)
  });

  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
    // The point in hand is the one whose range is lit; it is recorded with the next change.
    select: (i) => {
      if (i < 0 || i === work.point) return;
      work.point = i;
      pointSlider.set(i);
      supportDirty = true;
      ctx.preview(work);
      view.requestDraw();
    },
  });

  // ------------------------------------------------------------ side panel
  const uSlider = slider({
    label: t("localControl.control.u"),
    inputLabel: t("localControl.control.u.input"),
    name: "u",
    min: 0,
    max: MAX_POINTS - MIN_DEGREE,
    step: U_STEP,
    value: work.u,
    onChange: (value, final) => setU(value, final),
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const pointSlider = slider({
    label: t("localControl.control.point"),
    inputLabel: t("localControl.control.point.input"),
    name: "point",
    min: 0,
    max: MAX_POINTS - 1,
    step: 1,
    value: work.point,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => setPoint(Math.round(value), final),
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const degreeSlider = slider({
    label: t("localControl.control.degree"),
    inputLabel: t("localControl.control.degree.input"),
    name: "degree",
    min: MIN_DEGREE,
    max: MAX_DEGREE,
    step: 1,
    value: work.degree,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => {
      if (final) setDegree(Math.round(value));
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const spanText = el("p", { class: "sl-readout", dataset: { info: "span" }, "aria-live": "polite" });
  const hullText = el("p", { class: "sl-note", dataset: { info: "hull" } });
  const supportText = el("p", { class: "sl-note", dataset: { info: "support" } });
  const { addButton, removeButton } = pointButtons({ add: addPoint, remove: removePoint, selected: () => handles.selected });
  ctx.slots.controls.append(
    group(null, uSlider.element, spanText, hullText),
    group(null, pointSlider.element, supportText),
    group(null, degreeSlider.element, el("div", { class: "sl-button-row" }, addButton, removeButton)),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("local-control");
  ctx.slots.details.append(tableTitle, tableWrap);
  let tableShape = "";
  let tableRows = []; // per i: { row, value, support }

  // ------------------------------------------------------------ edits

  /** The clamped domain [0, n − p + 1] of the current state. */
  function domainEnd() {
    return work.points.length - work.degree;
  }

  function setU(value, final) {
    work.u = Math.min(domainEnd(), Math.max(0, value));
    uSlider.set(work.u);
    uDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  function setPoint(i, final) {
    work.point = Math.min(work.points.length - 1, Math.max(0, i));
    pointSlider.set(work.point);
    supportDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  function setDegree(p) {
    if (work.points.length < p + 1) {
      ctx.status(t("localControl.error.tooFewPoints", { min: p + 1, p, count: work.points.length }), "error");
      degreeSlider.set(work.degree);
      return;
    }
    work.degree = p;
    rebuild();
    ctx.commit(work);
  }

  /** Builds the wasm curve for the current points and degree (the old one is freed). */
  function rebuild() {
    const nextKnots = sl.knotVector(flatten(work.points), 2, work.degree, "clamped");
    const next = new sl.BSplineCurve(flatten(work.points), 2, work.degree, nextKnots);
    curve.free();
    curve = next;
    knots = nextKnots;
    work.u = Math.min(work.u, domainEnd());
    work.point = Math.min(work.point, work.points.length - 1);
    syncControls();
    geometryDirty = structureDirty = supportDirty = uDirty = true;
    view.requestDraw();
  }

  /** Shows the state's values in the controls (without firing them). */
  function syncControls() {
    uSlider.range.max = String(domainEnd());
    pointSlider.range.max = String(work.points.length - 1);
    uSlider.set(work.u);
    pointSlider.set(work.point);
    degreeSlider.set(work.degree);
  }

  /** Adds a point after handle i (at the end when none is selected). */
  function addPoint(i) {
    const next = withPointAdded(work.points, i, MAX_POINTS, view.scale);
    if (!next) return ctx.status(t("localControl.maxPoints", { max: MAX_POINTS }), "error");
    work.points = next.points;
    rebuild();
    handles.select(next.index);
    ctx.commit(work);
  }

  /** Removes handle i (the last one when none is selected). */
  function removePoint(i) {
    const next = withPointRemoved(work.points, i, work.degree + 1);
    if (!next) return ctx.status(t("localControl.error.tooFewPoints", { min: work.degree + 1, p: work.degree, count: work.points.length - 1 }), "error");
    work.points = next.points;
    rebuild();
    handles.select(next.index);
    ctx.commit(work);
  }

  // ------------------------------------------------------------ knot strip
  // ------------------------------------------------------------ the core's answers
  /** Asks the core for samples, span, basis and point when something changed. */
  function recompute() {
    const p = work.degree;
    const n = work.points.length - 1;
    if (structureDirty) {
      // Distinct knots and their multiplicities (for the strip and the joints on the curve).
      const values = [];
      multiplicity = [];
      for (const value of knots) {
        if (values.length && values[values.length - 1] === value) multiplicity[multiplicity.length - 1] += 1;
        else {
          values.push(value);
          multiplicity.push(1);
        }
      }
      distinct = Float64Array.from(values);
      knotLabels = values.map((value, j) => (multiplicity[j] > 1 ? `${knotText(value)} ×${multiplicity[j]}` : knotText(value)));
    }
    if (structureDirty || supportDirty) {
      const i = work.point;
      supportLo = knots[i];
      supportHi = knots[i + p + 1];
      for (let j = 0; j < SUPPORT_SAMPLES; j++) supportUs[j] = supportLo + ((supportHi - supportLo) * j) / (SUPPORT_SAMPLES - 1);
    }
    if (geometryDirty || structureDirty) {
      samples = curve.sampleUniform(CURVE_SAMPLES);
      knotSamples = curve.sample(distinct);
      const all = [];
      for (let i = 0; i <= n; i++) all.push(i);
      wholeHull = convexHull(work.points, all);
    }
    if (geometryDirty || structureDirty || supportDirty) {
      supportSamples = curve.sample(supportUs); // the whole highlighted range in one call
      publishChecksums();
    }
    if (geometryDirty || structureDirty || uDirty) {
      span = curve.span(work.u);
      basis = curve.basis(work.u);
      point = curve.evaluate(work.u);
      const active = [];
      for (let i = span - p; i <= span; i++) active.push(i);
      activeHull = convexHull(work.points, active);
      uLabel = `u = ${knotText(work.u)}`;
    }
    if (geometryDirty || structureDirty || supportDirty || uDirty) syncPanels();
    geometryDirty = structureDirty = supportDirty = uDirty = false;
  }

  /**
   * Writes weighted sums of the uniform samples inside and outside the lit range to the span
   * readout (`data-inside-sum`, `data-outside-sum`): moving P_i must leave the outside sum
   * exactly as it was (a hook for tests and curious readers).
   */
  function publishChecksums() {
    const [a, b] = [0, domainEnd()];
    // The last span is closed on the right: the point u = b belongs to a range ending at b.
    let inside = 0;
    let outside = 0;
    for (let j = 0; j < CURVE_SAMPLES; j++) {
      const u = a + ((b - a) * j) / (CURVE_SAMPLES - 1);
      const value = (j + 1) * (samples[2 * j] + Math.SQRT2 * samples[2 * j + 1]);
      const within = u >= supportLo && (u < supportHi || (supportHi === b && u === b));
      if (within) inside += value;
      else outside += value;
    }
    supportText.dataset.support = `${supportLo},${supportHi}`;
    supportText.dataset.insideSum = String(inside);
    supportText.dataset.outsideSum = String(outside);
  }

  // ------------------------------------------------------------ drawing
  /** The knot dot and tick styles of a theme (made once per theme, not per frame). */
  function stylesFor(theme) {
    if (knotStylesTheme !== theme) {
      knotStylesTheme = theme;
      knotStyles = {
        dot: Object.freeze({ fill: theme.text, stroke: theme.background, width: WIDTH.helper, radius: RADIUS.constructionPoint }),
        tick: Object.freeze({ stroke: theme.text, width: WIDTH.construction }),
      };
    }
    return knotStyles;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const styles = stylesFor(theme);
    const pts = work.points;
    const n = pts.length - 1;
    const colour = work.point % CYCLE.length;

    // The hull of the whole polygon (outline only) and the hull of the active points (filled).
    polygonPath(r, v, wholeHull);
    r.paint(theme.helper);
    polygonPath(r, v, activeHull);
    r.paint(theme.helperFill);

    // Control polygon.
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(theme.polygon);

    // The range P_i acts on: a band in P_i's colour under the curve, from one sample(us) call.
    flatPath(r, v, supportSamples, 0, SUPPORT_SAMPLES);
    r.paint(theme.basisBand[colour]);

    // The curve.
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // The joints C(u_j) at the distinct knots.
    for (let j = 0; j < distinct.length; j++) r.point(v.sx(knotSamples[2 * j]), v.sy(knotSamples[2 * j + 1]), styles.dot);

    // A ring in the same colour around the point whose range is lit.
    r.point(v.sx(pts[work.point][0]), v.sy(pts[work.point][1]), theme.basisRing[colour]);
    handles.draw(r, v);

    // C(u), labelled on the side away from the active hull's centre.
    const px = v.sx(point[0]);
    const py = v.sy(point[1]);
    r.point(px, py, theme.pointOnCurve);
    let cx = 0;
    let cy = 0;
    for (let i = span - work.degree; i <= span; i++) {
      cx += v.sx(pts[i][0]);
      cy += v.sy(pts[i][1]);
    }
    cx /= work.degree + 1;
    cy /= work.degree + 1;
    let dx = px - cx;
    let dy = py - cy;
    const length = Math.hypot(dx, dy);
    if (length < 1) {
      dx = 0;
      dy = -1;
    } else {
      dx /= length;
      dy /= length;
    }
    placeLabel(r, t("localControl.pointLabel"), px, py, dx, dy, theme.pointOnCurve.radius * r.scale, theme.labelPoint);

    drawStrip(r, theme, styles, colour);
  }

  /** Adds the closed polygon through points `indices` to the path. */
  function polygonPath(r, v, indices) {
    r.beginPath();
    for (let k = 0; k < indices.length; k++) {
      const q = work.points[indices[k]];
      if (k === 0) r.moveTo(v.sx(q[0]), v.sy(q[1]));
      else r.lineTo(v.sx(q[0]), v.sy(q[1]));
    }
    r.closePath();
  }

  /** The parameter line under the figure: knots as ticks, the lit range, the span of u, u. */
  function drawStrip(r, theme, styles, colour) {
    const s = r.scale;
    strip.layout(r.width, r.height, s);
    const top = strip.top;
    const axisY = top + STRIP_ROW.axis * s;
    // The span of u, shaded like the active hull.
    r.beginPath();
    r.rect(strip.px(knots[span]), axisY - TICK_PX * 1.6 * s, strip.px(knots[span + 1]) - strip.px(knots[span]), TICK_PX * 3.2 * s);
    r.paint(theme.helperFill);
    // The range of P_i, as a bar in its colour.
    r.beginPath();
    r.moveTo(strip.px(supportLo), top + STRIP_ROW.bar * s);
    r.lineTo(strip.px(supportHi), top + STRIP_ROW.bar * s);
    r.paint(theme.basisBand[colour]);
    // The axis and the knots.
    r.beginPath();
    r.moveTo(strip.x0, axisY);
    r.lineTo(strip.x1, axisY);
    r.paint(theme.axis);
    r.beginPath();
    for (let j = 0; j < distinct.length; j++) {
      const x = strip.px(distinct[j]);
      r.moveTo(x, axisY - TICK_PX * s);
      r.lineTo(x, axisY + TICK_PX * s);
    }
    r.paint(styles.tick);
    for (let j = 0; j < distinct.length; j++) r.text(knotLabels[j], strip.px(distinct[j]), top + STRIP_ROW.ticks * s, theme.labelSmall, "center", "middle");
    // u itself.
    const x = strip.px(work.u);
    r.point(x, axisY, theme.pointOnCurve);
    const align = x < strip.x0 + 40 * s ? "left" : x > strip.x1 - 40 * s ? "right" : "center";
    r.text(uLabel, x, top + STRIP_ROW.label * s, theme.labelPoint, align, "middle");
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    if (!basis) return;
    const pts = work.points;
    const p = work.degree;
    const n = pts.length - 1;
    const k = span;
    const i = work.point;

    // Exact fractions when u is a simple fraction and the points are integers (knots always are).
    const uFraction = simpleFraction(work.u);
    const exact = uFraction && allIntegers(pts.flat()) ? uFraction : null;
    const den = exact ? exact.den ** p * basisDenominator(p) : 0;
    const valueTex = (value) => {
      const f = exact ? exactFraction(value, den) : null;
      return f ? fractionTex(f) : fmt(value);
    };
    const valueText = (value) => {
      const f = exact ? exactFraction(value, den) : null;
      return f ? fractionText(f) : fmt(value);
    };
    const uTex = exact ? fractionTex(exact) : fmt(work.u);

    const activeNames = [];
    const terms = [];
    for (let j = k - p; j <= k; j++) {
      activeNames.push(`P${subscript(j)}`);
      terms.push(`${valueTex(basis[j])}\\,P_{${j}}`);
    }
    const x = point[0];
    const y = point[1];
    const coords = `\\left(${valueTex(x)},\\ ${valueTex(y)}\\right)`;
    const approx = exact && (!Number.isInteger(x) || !Number.isInteger(y)) && exactFraction(x, den) ? `\\approx (${fmt(x)},\\ ${fmt(y)})` : "";
    const lo = knotText(supportLo);
    const hi = knotText(supportHi);
    const closing = supportHi === domainEnd() ? "]" : ")";
    formula.set([
      `u = ${uTex} \\in [u_{${k}}, u_{${k + 1}}) = [${knotText(knots[k])}, ${knotText(knots[k + 1])}),\\quad k = ${k},\\quad p = ${p}`,
      `C(u) = \\sum_{i=k-p}^{k} N_{i,${p}}(u)\\,P_i = ${terms.join(" + ")}`,
      `C(${uTex}) = ${coords} ${approx}`,
      `N_{${i},${p}}(u) \\ne 0 \\iff u \\in [u_{${i}}, u_{${i + p + 1}}) = [${lo}, ${hi}${closing}\\quad\\Rightarrow\\quad \\text{${t("localControl.formula.only")}}\\ P_{${i}}`,
      `C([u_{${k}}, u_{${k + 1}}]) \\subset \\operatorname{conv}\\{P_{${k - p}}, \\dots, P_{${k}}\\}\\quad (${activeHull.length}\\ \\text{${t("localControl.formula.vertices")}})`,
    ]);

    setText(spanText, t("localControl.readout.span", { k, names: activeNames.join(", ") }));
    setText(hullText, t("localControl.readout.hull", { hull: activeHull.length }));
    spanText.dataset.span = String(k);
    spanText.dataset.active = activeNames.map((_, j) => k - p + j).join(" ");
    spanText.dataset.hullVertices = String(activeHull.length);
    spanText.dataset.wholeHullVertices = String(wholeHull.length);
    supportText.textContent = t("localControl.readout.support", { name: `P${subscript(i)}`, lo, hi: `${hi}${closing}` });
    view.setLabel(t("localControl.aria", {
      kind: degreeName(p), count: n + 1, name: `P${subscript(i)}`, lo, hi: `${hi}${closing}`,
      u: fmt(work.u), k, names: activeNames.join(", "), x: fmt(x, 2), y: fmt(y, 2), hull: activeHull.length,
    }));
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= p + 1;

    // Table: every basis function at u and its support; the active ones highlighted.
    const shape = `${n}/${p}`;
    if (tableShape !== shape) buildTable(n);
    tableTitle.textContent = t("localControl.tableCaption", { u: exact ? fractionText(exact) : fmt(work.u), p });
    for (let j = 0; j <= n; j++) {
      const rowData = tableRows[j];
      setText(rowData.value, valueText(basis[j]));
      const end = knots[j + p + 1] === domainEnd() ? "]" : ")";
      setText(rowData.support, `[${knotText(knots[j])}, ${knotText(knots[j + p + 1])}${end}`);
      rowData.row.classList.toggle("sl-highlight", j >= k - p && j <= k);
      rowData.row.dataset.active = String(j >= k - p && j <= k);
    }
  }

  /** Rebuilds the table's rows for n + 1 points (only when the count or degree changed). */
  function buildTable(n) {
    tableShape = `${n}/${work.degree}`;
    tableRows = [];
    const head = el("tr", {},
      el("th", { scope: "col", text: t("localControl.table.point") }),
      el("th", { scope: "col", text: t("localControl.table.value", { p: subscript(work.degree) }) }),
      el("th", { scope: "col", text: t("localControl.table.support") }));
    const rows = [];
    for (let j = 0; j <= n; j++) {
      const value = el("td", { dataset: { index: String(j), column: "value" } });
      const support = el("td", { dataset: { index: String(j), column: "support" } });
      const row = el("tr", {}, el("th", { scope: "row", text: `P${subscript(j)}` }), value, support);
      tableRows.push({ row, value, support });
      rows.push(row);
    }
    table.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));
  }

  syncControls();
  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const nextKnots = sl.knotVector(flatten(state.points), 2, state.degree, "clamped");
      const next = new sl.BSplineCurve(flatten(state.points), 2, state.degree, nextKnots); // throws before anything changes
      curve.free();
      curve = next;
      knots = nextKnots;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      strip.dragging = false;
      syncControls();
      geometryDirty = structureDirty = supportDirty = uDirty = true;
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
