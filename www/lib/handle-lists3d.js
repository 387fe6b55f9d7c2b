/**
 * The `Handles3D` source of a declarative 3D figure (`figure3d.handles`, demo.js): one entry or a
 * list of entries, shown in order (i counts across them), each either
 *
 * - a point list `{ field, axes?(state), plane?(state), label?(index, state, data),
 *   showLabel?(index, state, data), shownWhen?(state), select?(index, ui) }`: the points of
 *   `state[field]`, `[x, y, z]`, or `[p, q]` pairs placed at coordinates `axes(state)` = `[a, b]`
 *   (0, 1, 2 for x, y, z; the third coordinate 0: a profile `[x, z]` in the xz plane is
 *   `axes: () => [0, 2]`);
 * - or one extra handle `{ field, at(state, out3), place(state, x, y, z), label, plane?,
 *   showLabel?(state, data), shownWhen? }` placed where the state implies (an arrow's tip) and
 *   writing `field` back from a move (`label`: a strings.js key, or a function of the state).
 *
 * `plane(state)` → `[nx, ny, nz, d]` holds the point in the plane n·p = d (n a coordinate axis,
 * or unit): Handles3D drags it where the pointer's ray meets the plane, and PageUp / PageDown do
 * nothing. A point of `axes` lies in the coordinate plane of the third axis (its plane unless
 * `plane` says otherwise). A list point's move is written into the list in place, then
 * `moved(field, index, xyz)` (the runtime: `derive.moved(model, index, xyz, state, ui, field)`
 * or `derive.inPlace[field]`); an extra handle's move calls `place`, then `placed(field)`.
 */
import { pointLabel } from "./handles.js";
import { t } from "./strings.js";

/**
 * @param {object[]} entries the list above
 * @param {{ state(): object, data: object, ui: object, moved(field, index, xyz), placed(field) }} env
 */
export function listHandles3(entries, env) {
  const { state, data, ui } = env;
  const xyz = new Float64Array(3);
  const shown = (e) => !e.shownWhen || e.shownWhen(state());
  const size = (e) => (e.at ? 1 : state()[e.field].length);
  /** Entry and index of handle i (a reused record), or null past the end. */
  const slot = { entry: null, index: -1 };
  function locate(i) {
    let first = 0;
    for (const e of entries) {
      if (!shown(e)) continue;
      const n = size(e);
      if (i < first + n) {
        slot.entry = e;
        slot.index = i - first;
        return slot;
      }
      first += n;
    }
    return null;
  }
  /** The plane an entry holds its points in: `plane(state)`, else the one `axes` implies. */
  function planeOf(e, out) {
    if (e.plane) {
      const q = e.plane(state());
      for (let k = 0; k < 4; k++) out[k] = q[k];
      return true;
    }
    if (!e.axes) return false;
    const [a, b] = e.axes(state());
    out.fill(0);
    out[3 - a - b] = 1;
    return true;
  }
  return {
    count() {
      let n = 0;
      for (const e of entries) if (shown(e)) n += size(e);
      return n;
    },
    get(i, out) {
      const { entry: e, index } = locate(i);
      const s = state();
      if (e.at) return e.at(s, out);
      const p = s[e.field][index];
      if (e.axes) {
        const [a, b] = e.axes(s);
        out.fill(0);
        out[a] = p[0];
        out[b] = p[1];
      } else {
        out[0] = p[0];
        out[1] = p[1];
        out[2] = p[2];
      }
    },
    label(i) {
      const { entry: e, index } = locate(i);
      if (e.at) return typeof e.label === "function" ? e.label(state(), data) : t(e.label);
      return e.label ? e.label(index, state(), data) : pointLabel(i);
    },
    showLabel(i) {
      const { entry: e, index } = locate(i);
      if (!e.showLabel) return true;
      return e.at ? e.showLabel(state(), data) : e.showLabel(index, state(), data);
    },
    plane(i, out) {
      const found = locate(i);
      return found ? planeOf(found.entry, out) : false;
    },
    move(i, x, y, z) {
      const { entry: e, index } = locate(i);
      const s = state();
      if (e.at) {
        e.place(s, x, y, z);
        env.placed(e.field);
        return;
      }
      const p = s[e.field][index];
      xyz[0] = x;
      xyz[1] = y;
      xyz[2] = z;
      if (e.axes) {
        const [a, b] = e.axes(s);
        p[0] = xyz[a];
        p[1] = xyz[b];
      } else {
        p[0] = x;
        p[1] = y;
        p[2] = z;
      }
      env.moved(e.field, index, xyz);
    },
    select(i) {
      const found = i >= 0 ? locate(i) : null;
      for (const e of entries) {
        if (!e.select) continue;
        e.select(found?.entry === e ? found.index : -1, ui);
      }
    },
    /** "+" on handle i: a point after it in its list, through `pointButtons` of that field. */
    add(i) {
      if (i < 0) {
        if (ui.pointList && this.handleOf(ui.pointList.field, 0) >= 0) ui.pointList.add(-1);
        return;
      }
      const found = locate(i);
      if (found && !found.entry.at && ui.pointList?.field === found.entry.field)
        ui.pointList.add(found.index);
    },
    /** Delete on handle i: removes it from its list (`pointButtons` of that field). */
    remove(i) {
      const found = locate(i);
      if (found && !found.entry.at && ui.pointList?.field === found.entry.field)
        ui.pointList.remove(found.index);
    },
    /** The handle index of point `index` of list `field` (-1 when that list is not shown). */
    handleOf(field, index) {
      let first = 0;
      for (const e of entries) {
        if (!shown(e)) continue;
        if (!e.at && e.field === field) return first + index;
        first += size(e);
      }
      return -1;
    },
  };
}

/** Is point k (row-major) a corner of a rows × cols net? (`showLabel` of a dense net.) */
export function netCorner(k, rows, cols) {
  const i = Math.floor(k / cols);
  const j = k % cols;
  return (i === 0 || i === rows - 1) && (j === 0 || j === cols - 1);
}
