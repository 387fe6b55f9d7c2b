/**
 * Handles of a 3D figure whose points do not all live in the same list, or must stay in a
 * coordinate plane (a profile curve in the xz plane): a `Handles3D` source built from a list of
 * entries the demo chooses per state (surface-revolution switches them with its mode), and the
 * small drawing helpers such a figure needs beside draw3d.js.
 *
 * A point held in the plane `x_axis = value` (axis 0, 1, 2 for x, y, z) is dragged in the
 * camera-facing plane by Handles3D, then slid along its own line of sight onto the plane: the
 * point stays exactly under the pointer, wherever the camera is, unless the plane is seen edge-on
 * (the sight line within `EDGE_ON` of it), where the coordinate is simply set (the point then
 * moves in the plane as directly as it can).
 */
import { Handles3D } from "./handles3d.js";
import { roundToView } from "./handles.js";

/** Below this |cos| between the sight line and the plane's normal the plane counts as edge-on. */
export const EDGE_ON = 0.05;

const sight = new Float64Array(3);

/**
 * Moves `p` (a Float64Array or list [x, y, z], written in place) along the camera's sight line
 * through it onto the plane p[axis] = value, rounded to what a tenth of a pixel resolves there.
 */
export function ontoPlane(view, p, axis, value) {
  view.sightLine(p[0], p[1], p[2], sight);
  if (Math.abs(sight[axis]) >= EDGE_ON) {
    const s = (value - p[axis]) / sight[axis];
    const scale = 1 / view.worldPerPixel(p[0], p[1], p[2]);
    for (let k = 0; k < 3; k++) p[k] = roundToView(p[k] + s * sight[k], scale);
  }
  p[axis] = value;
  return p;
}

/**
 * A Handles3D on `ui.view` whose handles are `entries(state)` → a list of `{ get(state, out),
 * move(state, xyz) → field changed (or null: refused), label }`, read afresh for every count,
 * get and move (the list may change with the state). A move writes the state through the entry,
 * then `ui.touch(field)` (the demo's `derive.inPlace[field]` takes it into the model); a drag's
 * end or a key press commits. The handles are registered as `ui.handles` and `data.handles`, so
 * the runtime forgets a selection past the end and destroys them with the demo.
 */
export function entryHandles(ui, entries) {
  const p = new Float64Array(3);
  const source = {
    count: () => entries(ui.state).length,
    get: (i, out) => entries(ui.state)[i].get(ui.state, out),
    label: (i) => entries(ui.state)[i].label,
    move(i, x, y, z) {
      p[0] = x;
      p[1] = y;
      p[2] = z;
      const field = entries(ui.state)[i].move(ui.state, p);
      if (field) ui.touch(field);
    },
    commit: (kind, i, merge) => ui.commit(merge),
  };
  const handles = new Handles3D(ui.view, source);
  ui.handles = handles;
  ui.data.handles = handles;
  return handles;
}

const a = new Float64Array(3);

/**
 * The control net of a rows × cols grid of points in a flat xyz array (what `controlPoints()`
 * returns, row-major): every row, then every column, as one path (draw3d's `netPath` takes
 * `[x, y, z]` lists).
 */
export function flatNetPath(r, view, flat, rows, cols) {
  r.beginPath();
  const to = (k, first) => {
    view.project(flat[3 * k], flat[3 * k + 1], flat[3 * k + 2], a);
    if (first) r.moveTo(a[0], a[1]);
    else r.lineTo(a[0], a[1]);
  };
  for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) to(i * cols + j, j === 0);
  for (let j = 0; j < cols; j++) for (let i = 0; i < rows; i++) to(i * cols + j, i === 0);
}

/** The segment between two space points, as a new path. */
export function segmentPath3(r, view, x0, y0, z0, x1, y1, z1) {
  r.beginPath();
  view.project(x0, y0, z0, a);
  r.moveTo(a[0], a[1]);
  view.project(x1, y1, z1, a);
  r.lineTo(a[0], a[1]);
}
