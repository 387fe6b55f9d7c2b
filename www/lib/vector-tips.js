/**
 * A pointer tool that drags the tips of vectors drawn from points (tangent arrows P_i → P_i +
 * s·m_i): a press within the handles' hit radius of a tip grabs it (the point handles, added
 * earlier to the view, keep the points themselves), a move hands the pointer's world position to
 * the demo, release commits. Tips are not point handles, so they add nothing to the point list
 * (Add / Remove point, Tab order) — the demo offers another way to set the vectors by keyboard
 * or number if it needs one.
 *
 *   vectorTips(ui, { count(state), tip(state, k, out), drag(ui, k, x, y) })
 *
 * `tip` writes tip k's world position into `out` ([x, y]); `drag` sets the vector from the
 * pointer's world position (x, y) (`ui.set(…, false)` or a change in place and `ui.touch`).
 */
import { HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH } from "./handles.js";

export function vectorTips(ui, { count, tip, drag }) {
  const { view } = ui;
  const at = new Float64Array(2);
  let dragging = -1;
  /** The tip nearest canvas (x, y) within the hit radius, or -1. */
  const tipAt = (x, y, pointerType) => {
    const radius = pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE;
    let best = -1;
    let bestDistance = radius * view.renderer.scale;
    for (let k = count(ui.state) - 1; k >= 0; k--) {
      tip(ui.state, k, at);
      const d = Math.hypot(x - view.sx(at[0]), y - view.sy(at[1]));
      if (d <= bestDistance) {
        best = k;
        bestDistance = d;
      }
    }
    return best;
  };
  view.addInteractor({
    pointerDown(event, x, y) {
      dragging = tipAt(x, y, event.pointerType);
      if (dragging < 0) return false;
      ui.stop();
      return true;
    },
    pointerMove(event, x, y) {
      if (dragging < 0 || dragging >= count(ui.state)) return;
      drag(ui, dragging, view.wx(x), view.wy(y));
    },
    pointerUp() {
      if (dragging < 0) return;
      dragging = -1;
      ui.commit();
    },
    hover: (x, y, pointerType) => (tipAt(x, y, pointerType) >= 0 ? "move" : null),
  });
}
