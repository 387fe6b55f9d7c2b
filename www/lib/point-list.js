/**
 * Adding and removing control points (the "Add point" / "Remove point" buttons, `+` and Delete
 * on a handle). `withPointAdded` / `withPointRemoved` return a new list and leave the demo's
 * list alone, so a demo that must first build its new wasm curve (which may refuse, or needs
 * new knots too) keeps its old state on a refusal. A demo whose curve follows from the list
 * alone takes `pointListActions`; every demo gets its two buttons from `pointButtons`:
 *
 *   const edits = pointListActions({
 *     points: () => work.points, setPoints: (p) => (work.points = p), min: MIN_POINTS, max: MAX_POINTS,
 *     scale: () => view.scale, rebuild, select: (i) => handles.select(i), commit: () => ctx.commit(work),
 *     refuse: (kind, limit) => ctx.status(t(`deCasteljau.${kind}Points`, { [kind]: limit }), "error"),
 *   });
 *   const { addButton, removeButton } = pointButtons({ add: edits.add, remove: edits.remove, selected: () => handles.selected });
 */
import { roundToView } from "./handles.js";
import { button } from "./controls.js";
import { t, tp } from "./strings.js";

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

/**
 * The add / remove actions of a demo whose curve follows from its point list `work.points`
 * alone: the new list from `withPointAdded` / `withPointRemoved` replaces the old one, then
 * `rebuild()` makes the new wasm curve from it, the new (or neighbouring) handle is selected
 * and `ctx.commit(work)` records the change. A full or minimal list reports the demo's string
 * `<strings>.maxPoints` / `<strings>.minPoints` (with `{max}` / `{min}`) in the status line
 * instead. New points are rounded to the view's scale at the time of the action.
 */
export function pointListActions({ ctx, work, view, handles, min, max, strings, rebuild }) {
  const apply = (next) => {
    work.points = next.points;
    rebuild();
    handles.select(next.index);
    ctx.commit(work);
  };
  const refuse = (kind, limit) =>
    ctx.status(tp(`${strings}.${kind}Points`, limit, { [kind]: limit }), "error");
  return {
    /** Adds a point after handle i (at the end when none is selected). */
    add(i) {
      const next = withPointAdded(work.points, i, max, view.scale);
      if (next) apply(next);
      else refuse("max", max);
    },
    /** Removes handle i (the last one when none is selected). */
    remove(i) {
      const next = withPointRemoved(work.points, i, min);
      if (next) apply(next);
      else refuse("min", min);
    },
  };
}

/** The "Add point" and "Remove point" buttons: `add(i)` / `remove(i)` on the `selected()` handle. */
export function pointButtons({ add, remove, selected }) {
  return {
    addButton: button({
      label: t("control.addPoint"),
      title: t("control.addPoint.title"),
      name: "add-point",
      onClick: () => add(selected()),
    }),
    removeButton: button({
      label: t("control.removePoint"),
      title: t("control.removePoint.title"),
      name: "remove-point",
      onClick: () => remove(selected()),
    }),
  };
}
