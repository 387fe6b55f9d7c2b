/**
 * The state's `view` field read by the kind of figure that shows the state: a 2D figure's world
 * window `[x0, y0, x1, y1]` or a 3D figure's camera `[azimuth, elevation, distance, tx, ty, tz]`
 * (camera3d.js). Most demos have one kind; a demo with both figures (`figure` and `figure3d`)
 * picks one per state with `dimension(state)` (three-loader.js `figureDimension`), so a state may
 * arrive with the view of the other kind (a link made before a z(t) was typed): such a view is
 * dropped and the figure fits its content.
 */
import { checkCamera, checkWindow } from "./validate.js";
import { figureDimension } from "./three-loader.js";

/** True when `view` is a valid view of a 3D (`is3d`) or 2D figure. */
export function viewFits(is3d, view) {
  try {
    (is3d ? checkCamera : checkWindow)(view);
    return true;
  } catch {
    return false;
  }
}

/**
 * Checks `view` for the figure that shows `rest` (a state without its view, already valid):
 * returns true to keep it, false to drop it (a view of the other kind, for a demo with both
 * figures); throws the check's Error for anything else.
 */
export function keepView(demo, rest, view) {
  const is3d = figureDimension(demo, rest) === 3;
  if (viewFits(is3d, view)) return true;
  if (typeof demo.dimension === "function" && viewFits(!is3d, view)) return false;
  (is3d ? checkCamera : checkWindow)(view);
  return true;
}
