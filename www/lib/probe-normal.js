/**
 * The point and unit normal at a probe (u, v) on a surface, drawn on a 3D figure's 2D layer
 * (bezier-patch, nurbs-surface): the point S(u, v), and the arrow from it to
 * S(u, v) + length · n with its label beyond the tip. Both from the core (`evaluate`, `normal`).
 */
import { arrow } from "./draw.js";
import { boundsOf3 } from "./camera3d.js";
import { placeLabelFrom } from "./handles.js";
import { HUES, WIDTH } from "./theme.js";

/** A vector of a 3D figure's 2D layer (a normal, an extrusion's direction): a vermillion arrow. */
export const VECTOR_ARROW = Object.freeze({
  stroke: HUES.vermillion,
  width: WIDTH.construction,
  fill: HUES.vermillion,
});

/** An arrow length: `fraction` of the diagonal of the points' bounding box. */
export function diagonalFraction(points, fraction) {
  const [x0, y0, z0, x1, y1, z1] = boundsOf3(points);
  return fraction * Math.hypot(x1 - x0, y1 - y0, z1 - z0);
}

const at = new Float64Array(3);
const tip = new Float64Array(3);

/**
 * The probe point `p` (the theme's point on a curve) and, when `normal` is given, the arrow
 * p → p + length·normal labelled `label` (already translated) beyond its tip.
 */
export function drawProbeNormal(r, v, p, normal, length, label) {
  v.project(p[0], p[1], p[2], at);
  if (normal) {
    const n = normal;
    v.project(p[0] + length * n[0], p[1] + length * n[1], p[2] + length * n[2], tip);
    arrow(r, at[0], at[1], tip[0], tip[1], VECTOR_ARROW);
    placeLabelFrom(r, label, tip[0], tip[1], at[0], at[1], r.theme.labelPoint, 4);
  }
  r.point(at[0], at[1], r.theme.pointOnCurve);
}
