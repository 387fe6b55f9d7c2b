/**
 * Pressing on a typed curve's drawn plot moves its point there (parametric-curve): the nearest
 * point of the plot's polyline on screen (a 2D View's `sx`/`sy`, or a 3D figure's `project`),
 * its t interpolated between the segment's ends (the plot is within a fraction of a pixel of
 * the curve). A press farther than the hit radius is left to the figure (pan, or orbit in 3D).
 * Picking support, not a curve algorithm: the points are the core's `plot`.
 */
import { HIT_RADIUS_TOUCH } from "./handles.js";

/** A press this near the drawn curve (CSS px, mouse) moves the point there. */
const PICK_RADIUS_PX = 8;
const q = new Float64Array(3);

/** The canvas point of the plot's vertex j (`q`), false when it is a gap or behind the eye. */
function screenPoint(view, points, dim, j) {
  const k = j * dim;
  const z = dim === 3 ? points[k + 2] : 0;
  if (view.project) {
    view.project(points[k], points[k + 1], z, q);
    if (q[2] > 1) return false;
  } else {
    q[0] = view.sx(points[k]);
    q[1] = view.sy(points[k + 1]);
  }
  return Number.isFinite(q[0]) && Number.isFinite(q[1]);
}

/** `{ t, distance }` (CSS px) of the plot's point nearest canvas (x, y), or null. */
export function nearestOnPlot(view, plot, dim, x, y) {
  const { points, ts } = plot;
  let best = null;
  let px = Number.NaN;
  let py = Number.NaN;
  for (let j = 0; j < ts.length; j++) {
    if (!(screenPoint(view, points, dim, j) && Number.isFinite(ts[j]))) {
      px = Number.NaN;
      continue;
    }
    const qx = q[0];
    const qy = q[1];
    const joined = Number.isFinite(px);
    const dx = qx - px;
    const dy = qy - py;
    const length2 = dx * dx + dy * dy;
    const s =
      joined && length2 > 0
        ? Math.min(Math.max(((x - px) * dx + (y - py) * dy) / length2, 0), 1)
        : 1;
    const cx = joined ? px + s * dx : qx;
    const cy = joined ? py + s * dy : qy;
    const distance = Math.hypot(x - cx, y - cy);
    if (!best || distance < best.distance)
      best = { t: joined ? ts[j - 1] + s * (ts[j] - ts[j - 1]) : ts[j], distance };
    px = qx;
    py = qy;
  }
  return best;
}

/**
 * Adds the interactor to `ui.view`: `plot()` → the drawn plot (or null), `dim`, `domain()` →
 * [a, b]; a press or drag near the curve sets `field` (a preview), the release commits.
 */
export function addPlotPicker(ui, { field, plot, dim, domain }) {
  let picking = false;
  const near = (x, y) => {
    const drawn = plot();
    return drawn ? nearestOnPlot(ui.view, drawn, dim(), x, y) : null;
  };
  const pick = (x, y) => {
    const hit = near(x, y);
    if (!hit) return;
    const [a, b] = domain();
    ui.set(field, Math.min(Math.max(hit.t, a), b), false);
  };
  ui.view.addInteractor({
    pointerDown(event, x, y) {
      const hit = near(x, y);
      const radius = event.pointerType === "touch" ? HIT_RADIUS_TOUCH : PICK_RADIUS_PX;
      if (!hit || hit.distance > radius) return false;
      ui.stop();
      picking = true;
      pick(x, y);
      return true;
    },
    pointerMove(event, x, y) {
      if (picking) pick(x, y);
    },
    pointerUp() {
      if (!picking) return;
      picking = false;
      ui.commit();
    },
    hover(x, y) {
      const hit = near(x, y);
      return hit && hit.distance <= PICK_RADIUS_PX ? "pointer" : null;
    },
    leave() {},
  });
}
