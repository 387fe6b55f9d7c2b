/**
 * The space figure of a typed curve (parametric-curve, z(t) given) on a 3D figure (view3d.js):
 * what WebGL draws — the core's plot, one polyline per run (a pole or gap ends a run), and the
 * osculating circle in its plane, both depth-tested — and the 2D layer over it: the point P(t),
 * the Frenet frame T, N, B from the core (`frame(t)`), FRAME_PX long on screen, the centre of
 * curvature, the exact Bézier polygon of a polynomial, and the captions. Every point is the
 * core's; nothing here computes the curve.
 */
import { drawCaption } from "./draw.js";
import { placeLabel, placeLabelAtTip, placeLabelFrom } from "./handles.js";
import { HUES, WIDTH } from "./theme.js";
import { t } from "./strings.js";
import {
  ACCELERATION_STYLE,
  ARROW_LABEL_GAP_PX,
  BINORMAL_STYLE,
  CENTRE_STYLE,
  CIRCLE_STYLE,
  CIRCLE_VERTICES,
  TEXT_MARGIN_PX,
  VELOCITY_STYLE,
  bezierLabel,
  bezierPoint,
  onCanvas,
  topCaption,
} from "./curve-figure.js";
import { arrow } from "./draw.js";

/** The plot's tolerance: this fraction of the curve's size (~0.15 px when the figure fits it). */
const PLOT_TOLERANCE_FRACTION = 1 / 4000;
/** Length of the Frenet frame's unit vectors on screen, CSS px (at P's depth). */
const FRAME_PX = 60;
/** … and at most this fraction of the figure's smaller side (a phone). */
const FRAME_FRACTION = 0.12;
/** Captions start right of the axis triad in the lower-left corner (draw3d.js), CSS px. */
const TRIAD_CLEAR_PX = 76;
const CURVE_COLOUR = HUES.blue;

/**
 * The core's plot of a space curve (no box: the camera sees all of it) in the cache `{ key,
 * result }` (the same cell the plane figure keeps its plot in), and its runs as polylines for
 * the scene (`{ points, colour, width }`, made once per plot).
 */
export function spacePlot(curve, whole, cache) {
  if (cache.key !== "space") {
    cache.key = "space";
    cache.runs = [];
    try {
      cache.result = curve.plot(PLOT_TOLERANCE_FRACTION * whole.size);
    } catch {
      cache.result = null;
    }
    const points = cache.result?.points ?? [];
    let start = 0;
    for (let k = 0; k <= points.length; k += 3) {
      if (k < points.length && Number.isFinite(points[k])) continue;
      if (k - start >= 6)
        cache.runs.push({
          points: points.subarray(start, k),
          colour: CURVE_COLOUR,
          width: WIDTH.curve,
        });
      start = k + 3;
    }
  }
  return cache;
}

/**
 * The osculating circle at P(t) in space (centre P + ρN, radius ρ = 1/κ, in the plane of T and
 * N), a closed polyline of CIRCLE_VERTICES + 1 points; null without one (a cusp, κ ≈ 0).
 */
export function osculatingCircle(at) {
  if (!at.defined || at.cusp || at.straight || !at.frame || at.point.length < 3) return null;
  const rho = 1 / Math.abs(at.kappa);
  const { tangent: T, normal: N } = at.frame;
  if (!N?.every(Number.isFinite)) return null;
  const out = new Float64Array((CIRCLE_VERTICES + 1) * 3);
  for (let k = 0; k <= CIRCLE_VERTICES; k++) {
    const a = (2 * Math.PI * k) / CIRCLE_VERTICES;
    const c = (1 - Math.cos(a)) * rho;
    const s = Math.sin(a) * rho;
    for (let i = 0; i < 3; i++) out[3 * k + i] = at.point[i] + c * N[i] + s * T[i];
  }
  return out;
}

/** What WebGL draws: the plot's runs and the osculating circle (`d.circle`). */
export function spaceScene(d) {
  const curves = [...spacePlot(d.curve, d.whole, d.plot).runs];
  if (d.circle) curves.push({ points: d.circle, colour: CIRCLE_STYLE.stroke, width: 1.5 });
  return { surfaces: [], wireframe: [], curves };
}

/** The box the camera fits: the curve's, and the Bézier polygon's when it is shown. */
export function spaceBounds(whole, form) {
  const b = [...whole.box3];
  for (let k = 0; form && k < form.points.length; k += 3) {
    for (let i = 0; i < 3; i++) {
      b[i] = Math.min(b[i], form.points[k + i]);
      b[3 + i] = Math.max(b[3 + i], form.points[k + i]);
    }
  }
  return b;
}

const p0 = new Float64Array(3);
const p1 = new Float64Array(3);
/** The screen direction P(t)'s name goes: away from the arrows T and N drawn (−T − N). */
const away = new Float64Array(2);

/**
 * The arrow from P (projected in `p0`) along the unit vector w, `s` world units, labelled;
 * `avoid`: P's name keeps away from it.
 */
function frameArrow(r, v, point, w, s, style, text, avoid = true) {
  if (!w?.every(Number.isFinite)) return;
  v.project(point[0] + s * w[0], point[1] + s * w[1], point[2] + s * w[2], p1);
  if (!(Math.hypot(p1[0] - p0[0], p1[1] - p0[1]) >= 1) || p1[2] > 1) return;
  arrow(r, p0[0], p0[1], p1[0], p1[1], style);
  if (avoid) {
    away[0] -= p1[0] - p0[0];
    away[1] -= p1[1] - p0[1];
  }
  const gap = ARROW_LABEL_GAP_PX * r.scale;
  placeLabelAtTip(r, text, p0[0], p0[1], p1[0], p1[1], gap, r.theme.labelPoint);
}

/** The exact control polygon of a polynomial space curve and its points, projected. */
function drawBezierForm(r, v, form) {
  if (form?.dim !== 3) return;
  r.beginPath();
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < form.count; i++) {
    v.project(form.points[3 * i], form.points[3 * i + 1], form.points[3 * i + 2], p1);
    if (i === 0) r.moveTo(p1[0], p1[1]);
    else r.lineTo(p1[0], p1[1]);
    cx += p1[0] / form.count;
    cy += p1[1] / form.count;
  }
  r.paint(r.theme.polygon);
  const style = bezierPoint(r.theme);
  for (let i = 0; i < form.count; i++) {
    v.project(form.points[3 * i], form.points[3 * i + 1], form.points[3 * i + 2], p1);
    r.point(p1[0], p1[1], style);
    const radius = style.radius * r.scale;
    placeLabelFrom(r, bezierLabel(i), p1[0], p1[1], cx, cy, r.theme.labelSmall, radius);
  }
}

/**
 * The 2D layer over the WebGL image: the Bézier polygon, the radius to the centre of
 * curvature, P(t) with T (vermillion), N (purple), B (sky blue), then the captions.
 */
export function drawSpaceLayer(r, v, s, d, prefix) {
  const theme = r.theme;
  const at = d.at;
  drawBezierForm(r, v, d.bezierForm);
  const shown = at.defined && at.point.length === 3;
  if (shown) v.project(at.point[0], at.point[1], at.point[2], p0);
  const visible = shown && onCanvas(r, p0[0], p0[1]) && p0[2] <= 1;
  if (visible && d.circle) {
    // The centre of curvature: the circle's point opposite P (vertex CIRCLE_VERTICES / 2).
    const k = 3 * (CIRCLE_VERTICES / 2);
    const [x, y, z] = at.point;
    v.project((d.circle[k] + x) / 2, (d.circle[k + 1] + y) / 2, (d.circle[k + 2] + z) / 2, p1);
    r.beginPath();
    r.moveTo(p0[0], p0[1]);
    r.lineTo(p1[0], p1[1]);
    r.paint(theme.helper);
    r.point(p1[0], p1[1], CENTRE_STYLE);
  }
  if (visible) {
    const frame = at.frame;
    away[0] = 0;
    away[1] = 0;
    if (frame && !at.cusp) {
      const px = Math.min(FRAME_PX, FRAME_FRACTION * Math.min(r.width, r.height));
      const length = px * v.worldPerPixel(at.point[0], at.point[1], at.point[2]);
      const label = (key) => t(`${prefix}.${key}`);
      frameArrow(r, v, at.point, frame.tangent, length, VELOCITY_STYLE, label("tangentLabel"));
      if (!at.straight) {
        const { normal, binormal } = frame;
        frameArrow(r, v, at.point, normal, length, ACCELERATION_STYLE, label("normalLabel"));
        frameArrow(r, v, at.point, binormal, length, BINORMAL_STYLE, label("binormalLabel"), false);
      }
    }
    r.point(p0[0], p0[1], theme.pointOnCurve);
    const radius = theme.pointOnCurve.radius * r.scale;
    const norm = Math.hypot(away[0], away[1]);
    const dx = norm > 0 ? away[0] / norm : 0.7;
    const dy = norm > 0 ? away[1] / norm : 0.7;
    placeLabel(r, t(`${prefix}.pointLabel`), p0[0], p0[1], dx, dy, radius, theme.labelPoint);
  }
  const margin = TEXT_MARGIN_PX * r.scale;
  const left = TRIAD_CLEAR_PX * r.scale;
  const footer = t(`${prefix}.frameCaption`);
  const bottom = r.height - margin;
  drawCaption(r, footer, left, bottom, theme.labelSmall, r.width - left - margin, "bottom");
  const caption = topCaption(at, d.plot.result, visible, s.t, prefix);
  if (caption)
    drawCaption(r, caption, margin, margin, theme.labelBold, r.width - 2 * margin, "top");
}
