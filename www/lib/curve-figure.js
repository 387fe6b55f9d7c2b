/**
 * The plane figure of a typed curve (parametric-curve) on the 2D View: the axes, the core's
 * adaptive plot for the window, the point P(t) with its velocity and acceleration at the
 * hodograph's scale λ, the osculating circle, the hodograph from its origin O, the exact
 * Bézier polygon, and the captions. A space curve shown here (while three.js loads) is its
 * shadow on the xy plane. Every point is the core's; everything is clipped to the canvas
 * (curve-view.js), so exports stay within TeX's dimensions.
 */
import { drawCaption } from "./draw.js";
import { placeLabel, placeLabelAtTip, placeLabelFrom } from "./handles.js";
import { fmt, subscript } from "./format.js";
import { HUES, RADIUS, SECOND_CURVE, themed } from "./theme.js";
import { t } from "./strings.js";
import {
  CLIP_MARGIN_PX,
  clippedArrow,
  flatRunsPath,
  penOnCanvas,
  penStart,
  penTo,
} from "./curve-view.js";

/** The plane figure shows (x, y): the map of curve-view.js's `flatRunsPath` is the identity. */
export const IDENTITY = Float64Array.of(1, 0, 0, 0, 1, 0, 0, 0, 1);
/** The plot follows the curve within this many CSS px (converted to model units). */
export const PLOT_TOLERANCE_PX = 0.25;
/** The plot's box: the canvas in world units, widened by this fraction on each side. */
const PLOT_BOX_MARGIN = 0.1;
/** Vertices of the drawn osculating circle (a polygon through P(t)). */
export const CIRCLE_VERTICES = 192;
/** Margin of captions from the canvas edges and the hodograph, CSS px. */
export const TEXT_MARGIN_PX = 12;
export const ARROW_LABEL_GAP_PX = 4;

const stroke = (colour, width) =>
  Object.freeze({ stroke: colour, width, cap: "round", join: "round" });
export const VELOCITY_STYLE = stroke(HUES.vermillion, 2.5);
export const ACCELERATION_STYLE = stroke(HUES.reddishPurple, 2);
export const BINORMAL_STYLE = stroke(HUES.skyBlue, 2);
export const CIRCLE_STYLE = Object.freeze({ stroke: HUES.orange, width: 1.5 });
export const CENTRE_STYLE = Object.freeze({ fill: HUES.orange, radius: RADIUS.constructionPoint });
/** The exact control points (not handles: they follow the formula), in the polygon's grey. */
export const bezierPoint = themed((theme) => ({
  fill: theme.polygon.stroke,
  radius: RADIUS.constructionPoint,
}));
const bezierLabels = [];
/** "P₀", "P₁", … (cached). */
export const bezierLabel = (i) => (bezierLabels[i] ??= `P${subscript(i)}`);

/** Whether the point (x, y) CSS px lies on the canvas widened by CLIP_MARGIN_PX. */
export function onCanvas(r, x, y) {
  const slack = CLIP_MARGIN_PX * r.scale;
  return x > -slack && x < r.width + slack && y > -slack && y < r.height + slack;
}

/**
 * The core's adaptive plot for this window (`cache` = `{ key, result }`, a compute cell made
 * anew with the curve): tolerance PLOT_TOLERANCE_PX in model units, the box the canvas in world
 * units; made again only when the window changes.
 */
function plotOf(r, v, curve, cache) {
  const x0 = v.wx(0);
  const x1 = v.wx(r.width);
  const y0 = v.wy(r.height);
  const y1 = v.wy(0);
  const key = `${x0} ${y0} ${x1} ${y1}`;
  if (cache.key === key) return cache.result;
  const mx = PLOT_BOX_MARGIN * (x1 - x0);
  const my = PLOT_BOX_MARGIN * (y1 - y0);
  try {
    const box = Float64Array.of(x0 - mx, y0 - my, x1 + mx, y1 + my);
    cache.result = curve.plot(PLOT_TOLERANCE_PX / v.scale, box);
  } catch {
    cache.result = null;
  }
  cache.key = key;
  return cache.result;
}

/** The arrow P → P + s·w (model vector w) from (px, py), its label at the tip. */
function vectorArrow(r, v, px, py, w, s, style, text) {
  const x = px + v.scale * s * w[0];
  const y = py - v.scale * s * w[1];
  if (!(Math.hypot(x - px, y - py) >= 1)) return;
  if (clippedArrow(r, v, px, py, x, y, style))
    placeLabelAtTip(r, text, px, py, x, y, ARROW_LABEL_GAP_PX * r.scale, r.theme.labelPoint);
}

/** The x and y axes across the canvas (clipped: far from the origin they would run far off). */
function drawAxes(r, v) {
  r.beginPath();
  penOnCanvas(r, v);
  penTo(r, -r.width, v.sy(0));
  penTo(r, 2 * r.width, v.sy(0));
  penTo(r, Number.NaN, Number.NaN);
  penTo(r, v.sx(0), -r.height);
  penTo(r, v.sx(0), 2 * r.height);
  r.paint(r.theme.axis);
}

/** The hodograph from O: axes over its box, its caption, the curve and the vector λP′(t). */
function drawHodograph(r, v, [ox, oy], whole, at, prefix) {
  const theme = r.theme;
  const { hodograph, lambda, hbox, dim } = whole;
  const left = v.sx(ox + hbox[0]);
  const right = v.sx(ox + hbox[2]);
  const top = v.sy(oy + hbox[3]);
  const bottom = v.sy(oy + hbox[1]);
  // Nothing of it when its box is off the canvas (O dragged or panned away).
  const slack = CLIP_MARGIN_PX * r.scale;
  if (right < -slack || left > r.width + slack || bottom < -slack || top > r.height + slack) return;
  r.beginPath();
  penOnCanvas(r, v);
  penTo(r, left, v.sy(oy));
  penTo(r, right, v.sy(oy));
  penTo(r, Number.NaN, Number.NaN);
  penTo(r, v.sx(ox), bottom);
  penTo(r, v.sx(ox), top);
  r.paint(theme.helper);
  const margin = TEXT_MARGIN_PX * r.scale;
  if (onCanvas(r, left, top)) {
    const width = Math.max(right - left, r.width - left - margin);
    const caption = t(`${prefix}.hodographCaption`);
    drawCaption(r, caption, left, top - margin, theme.labelSmall, width, "bottom");
  }
  r.beginPath();
  penStart(left, top, right, bottom, 2 * Math.hypot(right - left, bottom - top));
  flatRunsPath(r, v, hodograph, dim, IDENTITY, ox, oy, lambda);
  r.paint(SECOND_CURVE.curve);
  if (!at.defined) return;
  const hx = v.sx(ox + lambda * at.d1[0]);
  const hy = v.sy(oy + lambda * at.d1[1]);
  if (Math.hypot(hx - v.sx(ox), hy - v.sy(oy)) < 1) return;
  if (clippedArrow(r, v, v.sx(ox), v.sy(oy), hx, hy, VELOCITY_STYLE)) {
    r.point(hx, hy, theme.pointOnCurve);
    const text = t(`${prefix}.velocityLabel`);
    const gap = ARROW_LABEL_GAP_PX * r.scale;
    placeLabelAtTip(r, text, v.sx(ox), v.sy(oy), hx, hy, gap, theme.labelPoint);
  }
}

/** The exact control polygon of a polynomial curve and its points P₀ … Pₙ. */
function drawBezierForm(r, v, form) {
  if (!form) return;
  r.beginPath();
  penOnCanvas(r, v);
  flatRunsPath(r, v, form.points, form.dim, IDENTITY);
  r.paint(r.theme.polygon);
  // Labels away from the polygon's middle (the curve runs inside it).
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < form.count; i++) {
    cx += v.sx(form.points[i * form.dim]) / form.count;
    cy += v.sy(form.points[i * form.dim + 1]) / form.count;
  }
  const style = bezierPoint(r.theme);
  for (let i = 0; i < form.count; i++) {
    const px = v.sx(form.points[i * form.dim]);
    const py = v.sy(form.points[i * form.dim + 1]);
    if (!onCanvas(r, px, py)) continue;
    r.point(px, py, style);
    placeLabelFrom(r, bezierLabel(i), px, py, cx, cy, r.theme.labelSmall, style.radius * r.scale);
  }
}

/**
 * The osculating circle through P(t): centre P + ρN (N the tangent turned to the side P″ bends
 * to), radius ρ = 1/|κ|, as a polygon from P clipped to the canvas, and its centre.
 */
function drawCircle(r, v, at) {
  if (!at.defined || at.cusp || at.straight || !at.frame) return;
  const rho = 1 / Math.abs(at.kappa);
  const [px, py] = at.point;
  const [tx, ty] = at.frame.tangent;
  const side = Math.sign(at.d1[0] * at.d2[1] - at.d1[1] * at.d2[0]) || 1;
  const nx = -side * ty;
  const ny = side * tx;
  const cx = px + rho * nx;
  const cy = py + rho * ny;
  r.beginPath();
  penOnCanvas(r, v);
  for (let k = 0; k <= CIRCLE_VERTICES; k++) {
    const a = (2 * Math.PI * k) / CIRCLE_VERTICES;
    const c = -Math.cos(a) * rho;
    const s = Math.sin(a) * rho;
    penTo(r, v.sx(cx + c * nx + s * tx), v.sy(cy + c * ny + s * ty));
  }
  r.paint(CIRCLE_STYLE);
  const ccx = v.sx(cx);
  const ccy = v.sy(cy);
  if (ccx > 0 && ccx < r.width && ccy > 0 && ccy < r.height) {
    r.beginPath();
    r.moveTo(v.sx(px), v.sy(py));
    r.lineTo(ccx, ccy);
    r.paint(r.theme.helper);
    r.point(ccx, ccy, CENTRE_STYLE);
  }
}

/** The caption at the top: that the plot is approximate, else why P(t) has no arrows. */
export function topCaption(at, plot, shown, tt, prefix) {
  if (plot && !plot.complete) return t(`${prefix}.incomplete`);
  if (!at.defined) return t(`${prefix}.undefined`, { t: fmt(tt) });
  return at.cusp && shown ? t(`${prefix}.cusp`) : null;
}

/**
 * The whole plane figure: axes, hodograph, Bézier form, the circle, the curve, O's handle, the
 * arrows and P(t), then the captions. `d` holds `curve`, `whole`, `at`, `plot` (the cache),
 * `bezierForm` and `handles`; `s` holds `t` and `hodograph` ([O]).
 */
export function drawPlaneFigure(r, v, s, d, prefix) {
  const theme = r.theme;
  const at = d.at;
  drawAxes(r, v);
  drawHodograph(r, v, s.hodograph[0], d.whole, at, prefix);
  drawBezierForm(r, v, d.bezierForm);
  const px = at.defined ? v.sx(at.point[0]) : Number.NaN;
  const py = at.defined ? v.sy(at.point[1]) : Number.NaN;
  // P(t) off the canvas (near a pole): nothing is drawn at it (the panel has its numbers).
  const shown = onCanvas(r, px, py);
  if (shown) drawCircle(r, v, at);
  const plot = plotOf(r, v, d.curve, d.plot);
  if (plot) {
    r.beginPath();
    penOnCanvas(r, v);
    flatRunsPath(r, v, plot.points, d.whole.dim, IDENTITY);
    r.paint(theme.curve);
  }
  d.handles?.draw(r, v);
  if (at.defined && shown) {
    const lambda = d.whole.lambda;
    const p = (key) => t(`${prefix}.${key}`);
    vectorArrow(r, v, px, py, at.d2, lambda, ACCELERATION_STYLE, p("accelerationLabel"));
    vectorArrow(r, v, px, py, at.d1, lambda, VELOCITY_STYLE, p("velocityLabel"));
    r.point(px, py, theme.pointOnCurve);
    // The label on the side away from the centre of curvature (right of the motion for κ ≥ 0).
    const len = Math.hypot(at.d1[0], at.d1[1]);
    const side = at.kappa < 0 ? -1 : 1;
    const dx = len > 0 ? (side * at.d1[1]) / len : 0.7;
    const dy = len > 0 ? (side * at.d1[0]) / len : -0.7;
    const radius = theme.pointOnCurve.radius * r.scale;
    placeLabel(r, p("pointLabel"), px, py, dx, dy, radius, theme.labelPoint);
  }
  const margin = TEXT_MARGIN_PX * r.scale;
  const width = r.width - 2 * margin;
  const bottom = r.height - margin;
  drawCaption(r, d.whole.scaleCaption, margin, bottom, theme.labelSmall, width, "bottom");
  const caption = topCaption(at, plot, shown, s.t, prefix);
  if (caption) drawCaption(r, caption, margin, margin, theme.labelBold, width, "top");
}
