/**
 * Adding and removing control points (the "Add point" / "Remove point" buttons, `+` and Delete
 * on a handle). `withPointAdded` / `withPointRemoved` return a new list and leave the demo's
 * list alone, so the model can be built from it first (it may refuse, or need new knots too)
 * and the old state kept on a refusal; panel.js `pointButtons` wires them into a demo.
 */
import { roundToView } from "./handles.js";

/**
 * Fewest and most control points of a Bézier demo: degree 1 … 10 (the core allows more, but
 * the construction's labels and tables crowd beyond); `field.points(BEZIER_POINTS)` and
 * `pointButtons("points", { ...BEZIER_POINTS, prefix })`.
 */
export const BEZIER_POINTS = Object.freeze({ min: 2, max: 11 });

/** A point appended after the last goes this fraction of the last leg further on. */
export const APPEND_FRACTION = 0.5;

/** The point an add/remove acts on: handle i when it names a point, else the last one. */
export function pointIndex(points, i) {
  return i >= 0 && i < points.length ? i : points.length - 1;
}

/**
 * A copy of `points` with a new point after point i (after the last when i names none):
 * between two points the middle of their leg, after the last point the last leg continued by
 * half its length; coordinates rounded to what the view shows (`scale`: px per unit).
 * Returns `{ points, index }` (index: the new point's, to select it), or null when the list
 * already holds `max` points (the caller says so in the status line).
 */
export function withPointAdded(points, i, max, scale) {
  if (points.length >= max) return null;
  const at = pointIndex(points, i);
  const a = points[at];
  const b = at + 1 < points.length ? points[at + 1] : null;
  const prev = points[at - 1] ?? a;
  const x = b ? (a[0] + b[0]) / 2 : a[0] + (a[0] - prev[0]) * APPEND_FRACTION;
  const y = b ? (a[1] + b[1]) / 2 : a[1] + (a[1] - prev[1]) * APPEND_FRACTION;
  const next = structuredClone(points);
  next.splice(at + 1, 0, [roundToView(x, scale), roundToView(y, scale)]);
  return { points: next, index: at + 1 };
}

/**
 * A copy of `points` without point i (the last when i names none). Returns `{ points, index }`
 * (index: the handle to select afterwards, the removed point's neighbour), or null when the
 * list holds only `min` points (the caller says so in the status line).
 */
export function withPointRemoved(points, i, min) {
  if (points.length <= min) return null;
  const at = pointIndex(points, i);
  const next = structuredClone(points);
  next.splice(at, 1);
  return { points: next, index: Math.min(at, next.length - 1) };
}
