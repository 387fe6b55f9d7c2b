/**
 * Demo (syllabus §2 "Derivatives", §1 velocity and acceleration): a draggable Bézier curve with
 * the point P(t), its velocity P′(t) (arrow), the normal, the osculating circle and the signed
 * curvature κ(t); beside it, in the same figure (so exports include it), the hodograph — the
 * curve of velocities, a Bézier curve of degree n − 1 with control points n(P_{i+1} − P_i) —
 * with the same vector P′(t) drawn from the hodograph's origin. Follows the reference demo
 * (de-casteljau.js): the curve is updated in place while dragging (`setControlPoint`), and all
 * numbers come from the core (`derivative`, `curvature`, `hodograph`, `arcLength`).
 */
import { Handles, placeLabel } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkNumbers } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, exactFraction, fractionTex, allIntegers } from "../lib/format.js";
import { HUES, WIDTH, RADIUS, POLYGON_DASH } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten } from "../lib/geometry.js";
import { pointListActions, pointButtons } from "../lib/point-list.js";
import { Player } from "../lib/player.js";
import { titledTable } from "../lib/table.js";
import { flatPath, arrow, drawCaption } from "../lib/draw.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";

export const id = "derivatives";
/** Prefix of this demo's keys in strings.js. */
export const strings = "derivatives";
export const title = t("derivatives.title");
export const summary = t("derivatives.summary");
/** Syllabus section. */
export const section = 2;

/**
 * The worked example of the Greek notes (syllabus §2) at t = 3/4, where it bends most visibly
 * (κ ≈ −0.27, an osculating circle of radius ≈ 3.7); P′(0) = 3(P₁ − P₀) = (6, 6),
 * P′(1) = (6, −6); the hodograph (drawn at 1/3 scale) sits to the right with its origin O at (11, 2).
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 2], [6, 4], [8, 2]].map(Object.freeze)),
  t: 0.75,
  hodographOrigin: Object.freeze([11, 2]),
});

/** Fewest and most control points (degree 2 … 8: the hodograph is then a curve, not a point). */
export const MIN_POINTS = 3;
export const MAX_POINTS = 9;
/** Points sampled along the curve and the hodograph (one `sampleUniform` each per change). */
const CURVE_SAMPLES = 256;
const T_SLIDER_STEP = 0.001;
/** Length of the drawn unit normal, CSS px. */
const NORMAL_PX = 36;
/**
 * The osculating circle is left out when its radius exceeds this many times the size of the
 * control polygon (κ ≈ 0: "straight here").
 */
const STRAIGHT_RADIUS_FACTOR = 1e3;
/** Narrowest the hodograph's caption wraps to (CSS px at text scale 1). */
const HODOGRAPH_CAPTION_MIN_PX = 160;
/** Margin of the caption texts from the canvas edges and from the hodograph's box (CSS px). */
const TEXT_MARGIN_PX = 12;

// Styles of this demo's own marks (theme hues are the same in light and dark mode).
const VELOCITY_STYLE = Object.freeze({ stroke: HUES.vermillion, width: 2.5, cap: "round", join: "round" });
const NORMAL_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 2, cap: "round", join: "round" });
const CIRCLE_STYLE = Object.freeze({ stroke: HUES.orange, width: 1.5 });
const CENTRE_STYLE = Object.freeze({ fill: HUES.orange, radius: RADIUS.constructionPoint });
const HODOGRAPH_STYLE = Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.curve, join: "round", cap: "round" });
const HODOGRAPH_POLYGON_STYLE = Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.polygon, dash: POLYGON_DASH });
const HODOGRAPH_POINT_STYLE = Object.freeze({ fill: HUES.bluishGreen, radius: RADIUS.constructionPoint + 0.5 });

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "t", "hodographOrigin"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "t", { min: 0, max: 1 });
  checkNumbers(state, "hodographOrigin", { min: 2, max: 2 });
}

/** A number as short text: integers without decimals, else 3 decimals. */
function short(v) {
  const r = Math.round(v);
  return Math.abs(v - r) < 1e-9 ? String(r) : fmt(v);
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
  let hodograph = curve.hodograph();

  // Derived data: geometry (per change of the points) and the values at t.
  let samples = null;
  let hodographSamples = null;
  let hodographPoints = null; // the core's n(P_{i+1} − P_i), flat
  let arcLength = 0;
  let polygonSize = 1;
  let point = null; // P(t)
  let d1 = null; // P′(t)
  let d2 = null; // P″(t)
  let hodographPoint = null; // the hodograph at t (= P′(t))
  let kappa = 0;
  let d1At0 = null;
  let d1At1 = null;
  let geometryDirty = true;
  let tDirty = true;
  const pointScratch = new Float64Array(2);
  const handleLabels = [];
  const hodographLabels = [];
  const ORIGIN_LABEL = t("derivatives.originLabel");
  const POINT_LABEL = t("derivatives.pointLabel");
  const VELOCITY_LABEL = t("derivatives.velocityLabel");
  const NORMAL_LABEL = t("derivatives.normalLabel");
  const STRAIGHT_TEXT = t("derivatives.straight");
  const CUSP_TEXT = t("derivatives.cusp");
  let hodographCaption = "";
  let scaleCaption = "";

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => figureBounds() });
  const handles = new Handles(view, {
    count: () => work.points.length + 1,
    get: (i, out) => {
      const p = i < work.points.length ? work.points[i] : work.hodographOrigin;
      out[0] = p[0];
      out[1] = p[1];
    },
    label: (i) => (i < work.points.length ? (handleLabels[i] ??= `P${subscript(i)}`) : ORIGIN_LABEL),
    move: (i, x, y) => {
      if (i === work.points.length) {
        work.hodographOrigin[0] = x;
        work.hodographOrigin[1] = y;
      } else {
        work.points[i][0] = x;
        work.points[i][1] = y;
        pointScratch[0] = x;
        pointScratch[1] = y;
        curve.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
        geometryDirty = true;
      }
      view.requestDraw();
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => edits.add(i),
    remove: (i) => removeControlPoint(i),
  });

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
  const readout = el("p", { class: "sl-readout", dataset: { info: "curvature" }, "aria-live": "polite" });
  const readoutNote = el("p", { class: "sl-note", dataset: { info: "radius" } });
  const lengthText = el("p", { class: "sl-note", dataset: { info: "arc-length" } });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: (i) => edits.add(i), remove: (i) => removeControlPoint(i), selected: () => handles.selected });
  ctx.slots.controls.append(
    group(null, tSlider.element, player.element),
    group(t("derivatives.curvatureLegend"), readout, readoutNote, lengthText),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const quantityKeys = ["point", "dp", "ddp", "kappa", "radius", "dp0", "dp1", "length"];
  const cells = {};
  const quantityRows = quantityKeys.map((key) => {
    cells[key] = el("td", { dataset: { quantity: key } });
    return el("tr", {}, el("th", { scope: "row", text: t(`derivatives.row.${key}`) }), cells[key]);
  });
  const hodographBody = el("tbody");
  const { title: tableTitle, wrap: tableWrap } = titledTable("derivatives", { children: [el("tbody", {}, quantityRows), hodographBody] });
  ctx.slots.details.append(tableTitle, tableWrap);
  let hodographCells = [];

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

  const edits = pointListActions({ ctx, work, view, handles, min: MIN_POINTS, max: MAX_POINTS, strings: "derivatives", rebuild });
  /** Removes handle i when it is a control point (the origin is not one). */
  const removeControlPoint = (i) => i < work.points.length && edits.remove(i);

  // ------------------------------------------------------------ recompute (core calls)
  function recompute() {
    if (geometryDirty) {
      samples = curve.sampleUniform(CURVE_SAMPLES);
      const next = curve.hodograph();
      hodograph.free();
      hodograph = next;
      hodographSamples = hodograph.sampleUniform(CURVE_SAMPLES);
      hodographPoints = hodograph.controlPoints();
      arcLength = curve.arcLength();
      d1At0 = curve.derivative(0, 1);
      d1At1 = curve.derivative(1, 1);
      const box = curve.boundingBox();
      polygonSize = Math.max(Math.hypot(box[2] - box[0], box[3] - box[1]), 1e-9);
      const n = work.points.length - 1;
      hodographCaption = t("derivatives.hodographCaption", { m: n - 1 });
      scaleCaption = t("derivatives.scaleCaption", { n });
    }
    if (geometryDirty || tDirty) {
      point = curve.evaluate(work.t);
      d1 = curve.derivative(work.t, 1);
      d2 = curve.derivative(work.t, 2);
      hodographPoint = hodograph.evaluate(work.t);
      kappa = curve.curvature(work.t);
      syncPanels();
    }
    geometryDirty = tDirty = false;
  }

  /** World box of the curve's control points and the hodograph (for "Fit"). */
  function figureBounds() {
    recompute();
    const pts = work.points;
    const s = 1 / (pts.length - 1);
    const [ox, oy] = work.hodographOrigin;
    let x0 = ox;
    let y0 = oy;
    let x1 = ox;
    let y1 = oy;
    for (const [x, y] of pts) {
      x0 = Math.min(x0, x);
      y0 = Math.min(y0, y);
      x1 = Math.max(x1, x);
      y1 = Math.max(y1, y);
    }
    for (let k = 0; k < hodographPoints.length; k += 2) {
      x0 = Math.min(x0, ox + s * hodographPoints[k]);
      y0 = Math.min(y0, oy + s * hodographPoints[k + 1]);
      x1 = Math.max(x1, ox + s * hodographPoints[k]);
      y1 = Math.max(y1, oy + s * hodographPoints[k + 1]);
    }
    return [x0, y0, x1, y1];
  }

  // ------------------------------------------------------------ drawing
  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;
    const s = 1 / n; // arrows and the hodograph at 1/n scale: its control points are then the legs
    const ox = work.hodographOrigin[0];
    const oy = work.hodographOrigin[1];

    // ---- the hodograph: axes through O, polygon, curve, control points, the vector O → P′(t)
    let hx0 = 0;
    let hy0 = 0;
    let hx1 = 0;
    let hy1 = 0;
    for (let k = 0; k < hodographPoints.length; k += 2) {
      hx0 = Math.min(hx0, s * hodographPoints[k]);
      hy0 = Math.min(hy0, s * hodographPoints[k + 1]);
      hx1 = Math.max(hx1, s * hodographPoints[k]);
      hy1 = Math.max(hy1, s * hodographPoints[k + 1]);
    }
    const pad = 0.15 * Math.max(hx1 - hx0, hy1 - hy0, 1e-9);
    r.beginPath();
    r.moveTo(v.sx(ox + hx0 - pad), v.sy(oy));
    r.lineTo(v.sx(ox + hx1 + pad), v.sy(oy));
    r.moveTo(v.sx(ox), v.sy(oy + hy0 - pad));
    r.lineTo(v.sx(ox), v.sy(oy + hy1 + pad));
    r.paint(theme.helper);
    // On a phone: no labels on its control points (the table lists them), the caption wrapped.
    const narrow = v.width < NARROW_CANVAS_PX * r.scale;
    const boxLeft = v.sx(ox + hx0 - pad);
    const captionWidth = narrow ? Math.max(v.sx(ox + hx1 + pad) - boxLeft, HODOGRAPH_CAPTION_MIN_PX * r.scale) : Infinity;
    drawCaption(r, hodographCaption, boxLeft, v.sy(oy + hy1 + pad) - TEXT_MARGIN_PX * r.scale, theme.labelSmall, captionWidth, "bottom");

    r.beginPath();
    for (let k = 0; k < hodographPoints.length; k += 2) {
      const x = v.sx(ox + s * hodographPoints[k]);
      const y = v.sy(oy + s * hodographPoints[k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(HODOGRAPH_POLYGON_STYLE);
    r.beginPath();
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const x = v.sx(ox + s * hodographSamples[2 * k]);
      const y = v.sy(oy + s * hodographSamples[2 * k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(HODOGRAPH_STYLE);
    const hcx = v.sx(ox + (hx0 + hx1) / 2);
    const hcy = v.sy(oy + (hy0 + hy1) / 2);
    for (let i = 0; i < n; i++) {
      const x = v.sx(ox + s * hodographPoints[2 * i]);
      const y = v.sy(oy + s * hodographPoints[2 * i + 1]);
      r.point(x, y, HODOGRAPH_POINT_STYLE);
      // Label away from the hodograph's middle.
      let dx = x - hcx;
      let dy = y - hcy;
      const length = Math.hypot(dx, dy);
      if (length < 1) {
        dx = 0;
        dy = -1;
      } else {
        dx /= length;
        dy /= length;
      }
      if (!narrow) placeLabel(r, hodographLabel(i, n), x, y, dx, dy, HODOGRAPH_POINT_STYLE.radius * r.scale, theme.labelSmall);
    }
    const hpx = v.sx(ox + s * hodographPoint[0]);
    const hpy = v.sy(oy + s * hodographPoint[1]);
    arrow(r, v.sx(ox), v.sy(oy), hpx, hpy, VELOCITY_STYLE);
    r.point(hpx, hpy, theme.pointOnCurve);
    labelBeside(r, VELOCITY_LABEL, v.sx(ox), v.sy(oy), hpx, hpy, theme.labelPoint);

    // ---- the curve, its polygon, the osculating circle, normal and velocity at t
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(theme.polygon);
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    const px = v.sx(point[0]);
    const py = v.sy(point[1]);
    const speed = Math.hypot(d1[0], d1[1]);
    let caption = null;
    if (speed > 0 && Number.isFinite(kappa)) {
      // Unit normal N: the unit tangent turned 90° counter-clockwise (world), so the centre of
      // curvature is P + N/κ for the signed κ of the core.
      const nx = -d1[1] / speed;
      const ny = d1[0] / speed;
      const radius = 1 / Math.abs(kappa);
      if (radius <= STRAIGHT_RADIUS_FACTOR * polygonSize) {
        const cx = point[0] + nx / kappa;
        const cy = point[1] + ny / kappa;
        r.beginPath();
        r.circle(v.sx(cx), v.sy(cy), radius * v.scale);
        r.paint(CIRCLE_STYLE);
        r.beginPath();
        r.moveTo(px, py);
        r.lineTo(v.sx(cx), v.sy(cy));
        r.paint(theme.helper);
        r.point(v.sx(cx), v.sy(cy), CENTRE_STYLE);
      } else {
        caption = STRAIGHT_TEXT;
      }
      const tipX = px + nx * NORMAL_PX * r.scale;
      const tipY = py - ny * NORMAL_PX * r.scale;
      arrow(r, px, py, tipX, tipY, NORMAL_STYLE);
      // Beside the tip, on the side the curve comes from (clear of the arrow and the circle).
      placeLabel(r, NORMAL_LABEL, tipX, tipY, -d1[0] / speed, d1[1] / speed, 4 * r.scale, theme.labelSmall);
    } else {
      caption = CUSP_TEXT;
    }
    const vx = v.sx(point[0] + s * d1[0]);
    const vy = v.sy(point[1] + s * d1[1]);
    arrow(r, px, py, vx, vy, VELOCITY_STYLE);
    labelBeside(r, VELOCITY_LABEL, px, py, vx, vy, theme.labelPoint);

    handles.draw(r, v);
    r.point(px, py, theme.pointOnCurve);
    if (speed > 0) placeLabel(r, POINT_LABEL, px, py, d1[1] / speed, d1[0] / speed, theme.pointOnCurve.radius * r.scale, theme.labelPoint);

    const margin = TEXT_MARGIN_PX * r.scale;
    drawCaption(r, scaleCaption, margin, v.height - margin, theme.labelSmall, v.width - 2 * margin, "bottom");
    if (caption) drawCaption(r, caption, margin, margin, theme.labelBold, v.width - 2 * margin, "top");
  }

  /** "3(P₁−P₀)" for hodograph control point i (cached strings). */
  function hodographLabel(i, n) {
    const key = n * (MAX_POINTS + 1) + i;
    return (hodographLabels[key] ??= `${n}(P${subscript(i + 1)}−P${subscript(i)})`);
  }

  /** Labels an arrow at its tip, continuing its direction. */
  function labelBeside(r, text, x0, y0, x1, y1, style) {
    const dx = x1 - x0;
    const dy = y1 - y0;
    const length = Math.hypot(dx, dy);
    if (length < 1) return;
    placeLabel(r, text, x1, y1, dx / length, dy / length, 4 * r.scale, style);
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    const pts = work.points;
    const n = pts.length - 1;
    const kind = n <= 5 ? t(`curve.degree.${n}`) : t("curve.degree.n", { n });
    const straight = Number.isFinite(kappa) && 1 / Math.abs(kappa) > STRAIGHT_RADIUS_FACTOR * polygonSize;
    const kappaText = Number.isFinite(kappa) ? fmt(kappa) : "∞";
    const radiusText = !Number.isFinite(kappa) ? "0" : straight ? "∞" : fmt(1 / Math.abs(kappa));
    readout.textContent = t("derivatives.readout", { kappa: kappaText });
    readout.dataset.kappa = kappaText;
    readoutNote.textContent = !Number.isFinite(kappa) ? CUSP_TEXT : straight ? STRAIGHT_TEXT : t("derivatives.radius", { r: radiusText, side: t(kappa > 0 ? "derivatives.left" : "derivatives.right") });
    lengthText.textContent = t("derivatives.length", { length: fmt(arcLength) });
    degreeText.textContent = t("derivatives.degree", { n, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;
    view.setLabel(
      t("derivatives.aria", { kind, t: fmt(work.t), x: fmt(point[0], 2), y: fmt(point[1], 2), dx: fmt(d1[0], 2), dy: fmt(d1[1], 2), kappa: kappaText }),
    );

    // Exact fractions when t is a simple fraction and every input is an integer.
    const tFraction = simpleFraction(work.t);
    const exact = tFraction && allIntegers(pts.flat()) ? tFraction : null;
    const tTex = exact ? fractionTex(exact) : fmt(work.t);
    const num = (value, power) => {
      const f = exact ? exactFraction(value, exact.den ** power) : null;
      return f ? fractionTex(f) : short(value);
    };
    const vec = (x, y, power) => `(${num(x, power)},\\ ${num(y, power)})`;
    const legs = [];
    for (let i = 0; i < n; i++) {
      const b = sl.bernstein(n - 1, i, work.t);
      const f = exact ? exactFraction(b, exact.den ** (n - 1)) : null;
      const dx = pts[i + 1][0] - pts[i][0];
      const dy = pts[i + 1][1] - pts[i][1];
      legs.push(`${f ? fractionTex(f) : fmt(b)}\\,(${short(dx)},\\ ${short(dy)})`);
    }
    const lines = [
      `P'(t) = n\\sum_{i=0}^{n-1} B_i^{n-1}(t)\\,(P_{i+1} - P_i) = ${n}\\,\\big[${legs.join(" + ")}\\big] = ${vec(d1[0], d1[1], n - 1)},\\quad t = ${tTex}`,
      `P'(0) = n(P_1 - P_0) = ${vec(d1At0[0], d1At0[1], 0)},\\qquad P'(1) = n(P_n - P_{n-1}) = ${vec(d1At1[0], d1At1[1], 0)}`,
      `P''(t) = n(n-1)\\sum_{i=0}^{n-2} B_i^{n-2}(t)\\,(P_{i+2} - 2P_{i+1} + P_i) = ${vec(d2[0], d2[1], Math.max(n - 2, 0))}`,
      Number.isFinite(kappa)
        ? `\\kappa(t) = \\frac{x'y'' - y'x''}{|P'|^3} = \\frac{(${short(d1[0])})(${short(d2[1])}) - (${short(d1[1])})(${short(d2[0])})}{${fmt(Math.hypot(d1[0], d1[1]))}^3} = ${kappaText}${straight ? "" : `,\\quad \\rho = 1/|\\kappa| = ${radiusText}`}`
        : `P'(t) = 0:\\ \\kappa = \\infty\\ \\text{(${t("derivatives.cuspShort")})}`,
      `L = \\int_0^1 |P'(t)|\\,dt = ${fmt(arcLength)}`,
    ];
    formula.set(lines.map((line) => line.replace(/\(-/g, "({-}")));

    // Table: the values at t, the end velocities, the arc length, the hodograph's points.
    setText(tableTitle, t("derivatives.tableCaption", { t: fmt(work.t) }));
    setText(cells.point, `(${fmt(point[0])}, ${fmt(point[1])})`);
    setText(cells.dp, `(${short(d1[0])}, ${short(d1[1])})`);
    setText(cells.ddp, `(${short(d2[0])}, ${short(d2[1])})`);
    setText(cells.kappa, kappaText);
    setText(cells.radius, radiusText);
    setText(cells.dp0, `(${short(d1At0[0])}, ${short(d1At0[1])})`);
    setText(cells.dp1, `(${short(d1At1[0])}, ${short(d1At1[1])})`);
    setText(cells.length, fmt(arcLength));
    if (hodographCells.length !== n) {
      hodographCells = [];
      const rows = [];
      for (let i = 0; i < n; i++) {
        const cell = el("td", { dataset: { hodograph: String(i) } });
        hodographCells.push(cell);
        rows.push(el("tr", {}, el("th", { scope: "row", text: t("derivatives.row.hodograph", { i: subscript(i), label: hodographLabel(i, n) }) }), cell));
      }
      hodographBody.replaceChildren(...rows);
    }
    for (let i = 0; i < n; i++) setText(hodographCells[i], `(${short(hodographPoints[2 * i])}, ${short(hodographPoints[2 * i + 1])})`);
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
      if (handles.selected > work.points.length) handles.select(-1);
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
      hodograph.free();
    },
  };
}
