/**
 * Weight rings: a circle around each control point whose radius shows its weight, and a pointer
 * tool that drags the weight by the radius (a press on the circle, outside the handle, which
 * owns the centre). The radius is RING_PX·w^RING_EXPONENT CSS px, so w = 1 is a 16 px ring and
 * w = 10 about 32 px: a power below 1 keeps large weights on the canvas, and dragging inverts
 * it, w = (d / RING_PX)^(1/RING_EXPONENT) for a pointer at distance d, clamped to the demo's
 * range. Changes go through `ui.setWeight(i, w, false)` (in place with `derive.weighted`), and
 * the gesture is committed when the pointer is released. Ring i has the colour of point i.
 */
import { HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH } from "./handles.js";

/** Radius at w = 1 (CSS px) and the exponent of the radius ↔ weight map. */
const RING_PX = 16;
const RING_EXPONENT = 0.3;
/** A press this close (CSS px) to a ring's circle grabs it (touch: the larger value). */
const RING_HIT_PX = 5;
const RING_HIT_TOUCH_PX = 9;

/** Radius (CSS px at scale 1) of the ring that shows weight w. */
export function ringRadius(w) {
  return RING_PX * w ** RING_EXPONENT;
}

/** Draws the ring of every point (`points` [x, y] world, `weights` one per point). */
export function drawWeightRings(r, v, points, weights) {
  const theme = r.theme;
  const cycle = theme.basisRing.length;
  for (let i = 0; i < points.length; i++) {
    r.beginPath();
    r.circle(v.sx(points[i][0]), v.sy(points[i][1]), ringRadius(weights[i]) * r.scale);
    r.paint(theme.basisStroke[i % cycle]);
  }
}

/**
 * The pointer tool on the demo's `ui` (declarative contract, demo.js): `state.points` and
 * `state.weights`, weights kept in [min, max]. A pressed ring selects its handle.
 */
export function weightRings(ui, { min, max }) {
  const { view } = ui;
  let dragging = -1;
  /** Index of the weight ring whose circle passes near canvas point (x, y), or -1. */
  const ringAt = (x, y, pointerType) => {
    const touch = pointerType === "touch";
    const slack = touch ? RING_HIT_TOUCH_PX : RING_HIT_PX;
    const inner = touch ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE; // the handle owns its centre
    const { points, weights } = ui.state;
    for (let i = points.length - 1; i >= 0; i--) {
      const d = Math.hypot(x - view.sx(points[i][0]), y - view.sy(points[i][1]));
      if (d > inner && Math.abs(d - ringRadius(weights[i]) * view.renderer.scale) <= slack)
        return i;
    }
    return -1;
  };
  view.addInteractor({
    pointerDown(event, x, y) {
      const i = ringAt(x, y, event.pointerType);
      if (i < 0) return false;
      dragging = i;
      ui.handles.select(i);
      return true;
    },
    pointerMove(event, x, y) {
      const point = ui.state.points[dragging];
      if (!point) return;
      const d = Math.hypot(x - view.sx(point[0]), y - view.sy(point[1])) / view.renderer.scale;
      const w = (Math.max(d, 1) / RING_PX) ** (1 / RING_EXPONENT);
      ui.setWeight(dragging, Math.min(max, Math.max(min, w)), false);
    },
    pointerUp() {
      if (dragging < 0) return;
      dragging = -1;
      ui.commit();
    },
    hover: (x, y, pointerType) => (ringAt(x, y, pointerType) >= 0 ? "ew-resize" : null),
  });
}
