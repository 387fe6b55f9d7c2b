/**
 * Control-point handles of a 3D figure (view3d.js), styled as the 2D handles (white disc, dark
 * outline; hovered larger; selected vermillion, label bold) and drawn on the figure's 2D layer.
 *
 * Picking: the ray through the pointer against a sphere of the hit radius (10 px mouse, 18 px
 * touch, measured on the screen) around each handle; a handle the surface hides (the segment from
 * the eye to it meets a shown mesh first: the view's `occluded`) is drawn faded and is picked only
 * when no visible handle is under the pointer; among equals the one nearest the camera wins. A picked
 * handle is dragged in the plane facing the camera through the point (the pointer's ray meets
 * that plane), so it follows the pointer exactly. Keyboard: Tab / Shift+Tab, Home / End and
 * Escape as in 2D; arrows move the selected point in that plane by 1 px (Shift 10 px), PageUp /
 * PageDown by 10 px along the view direction (towards / away from the viewer); with no point
 * selected the arrows orbit the camera (the view's `orbitBy`). Changes are announced in the
 * figure's polite live region when they are final, as in 2D.
 *
 * A handle held in a plane (`source.plane(i, out)` writes `[nx, ny, nz, d]`: n·p = d, n unit)
 * is dragged where the pointer's ray meets that plane (where the plane is seen nearly edge-on,
 * `EDGE_ON`, in the camera-facing plane, then dropped onto it); the arrows move it in the
 * camera-facing plane and slide it along its line of sight onto its plane; PageUp / PageDown do
 * nothing (and announce nothing). `+` / Delete call `source.add(i)` / `source.remove(i)` (a
 * point list's buttons). Labels: the selected, dragged and hovered handles' always; the others'
 * when `source.showLabel(i)` allows (a dense net names its corners); on a phone-width figure
 * (`NARROW_CANVAS_PX`) only the selected one's. The announcements name every point.
 *
 * The handles own no data: `source` is `{ count(), get(i, out), label(i), move(i, x, y, z),
 * commit(kind, i, merge), select?(i), plane?(i, out4), showLabel?(i), add?(i), remove?(i) }`
 * (handle-lists3d.js makes it from a declarative figure's entries).
 */
import {
  placeLabelFrom,
  roundToView,
  HIT_RADIUS_MOUSE,
  HIT_RADIUS_TOUCH,
  NUDGE_PX,
  NUDGE_PX_LARGE,
} from "./handles.js";
import { selectionKey } from "./handle-keys.js";
import { HandleSet } from "./handle-set.js";
import { formatNumber, t } from "./strings.js";
import { NARROW_CANVAS_PX } from "./view.js";

/** PageUp / PageDown move a point this many px-equivalents along the view direction. */
export const DEPTH_NUDGE_PX = 10;
/** An arrow key with nothing selected orbits by this many degrees (Shift: ×3). */
export const ORBIT_STEP_DEG = 5;
/** Below this |cos| between a sight line and a handle's plane normal the plane is seen edge-on. */
export const EDGE_ON = 0.05;

/** Opacity of a handle the surface hides (its fill, and its outline a little more). */
export const HIDDEN_ALPHA = 0.35;
const fadedStyles = new WeakMap();
const dot3 = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
/** The faded form of a handle style (made once per style). */
function faded(style) {
  let out = fadedStyles.get(style);
  if (!out) {
    out = Object.freeze({ ...style, alpha: HIDDEN_ALPHA, strokeAlpha: HIDDEN_ALPHA + 0.15 });
    fadedStyles.set(style, out);
  }
  return out;
}
const fadedLabels = new WeakMap();
/** A hidden handle's label: in the net's grey (text has no opacity). */
function fadedLabel(style, theme) {
  let out = fadedLabels.get(style);
  if (!out) {
    out = Object.freeze({ ...style, fill: theme.axis.stroke });
    fadedLabels.set(style, out);
  }
  return out;
}

export class Handles3D extends HandleSet {
  /** @param {import("./view3d.js").View3D} view @param {object} source see the module comment. */
  constructor(view, source) {
    super(view, source, "handles.selected3d");
    this._p = new Float64Array(3);
    this._s = new Float64Array(3);
    this._grab = new Float64Array(3);
    this._right = new Float64Array(3);
    this._up = new Float64Array(3);
    this._sight = new Float64Array(3);
    this._plane = new Float64Array(4); // n, and the point's offset along n
    this._held = new Float64Array(4); // the plane a constrained handle stays in
    this._start = new Float64Array(3);
    this._order = new Int32Array(0);
    this._depth = new Float64Array(0);
    this._hidden = new Uint8Array(0);
    this._published = "";
  }

  /** Keyboard focus selects the first handle; a click on the figure (an orbit) does not. */
  _focus() {
    if (this.selected < 0 && this.source.count() > 0 && this.view.canvas.matches(":focus-visible"))
      this.select(0);
  }

  _announce(key, i) {
    this.source.get(i, this._p);
    this.announce(
      t(key, {
        label: this.source.label(i),
        x: formatNumber(this._p[0]),
        y: formatNumber(this._p[1]),
        z: formatNumber(this._p[2]),
      }),
    );
  }

  /** True when the surface hides handle i (drawn faded, picked after the visible ones). */
  hidden(i) {
    this.source.get(i, this._p);
    return this.view.occluded?.(this._p[0], this._p[1], this._p[2]) ?? false;
  }

  /**
   * The handle under canvas point (x, y) within the hit radius: a visible one before one the
   * surface hides, then the nearest the camera; or -1.
   */
  hitTest(x, y, pointerType) {
    const radius = pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE;
    let best = -1;
    let bestKey = Infinity;
    for (let i = 0, n = this.source.count(); i < n; i++) {
      this.source.get(i, this._p);
      this.view.project(this._p[0], this._p[1], this._p[2], this._s);
      if (this._s[2] > 1) continue; // behind the camera
      if (Math.hypot(this._s[0] - x, this._s[1] - y) > radius) continue;
      // NDC depth is < 1 in front of the far plane: a hidden handle ranks after every visible one.
      const key = this._s[2] + (this.hidden(i) ? 4 : 0);
      if (key < bestKey) {
        best = i;
        bestKey = key;
      }
    }
    return best;
  }

  // -------------------------------------------------------------- pointer

  pointerDown(event, x, y) {
    const i = this.hitTest(x, y, event.pointerType);
    if (i < 0) return false;
    this.source.get(i, this._p);
    this._start.set(this._p);
    // The handle's own plane when it has one seen well enough, else the plane facing the camera
    // through the point; and where the pointer's ray meets it.
    if (this._heldIn(i) && this._facing(this._p)) {
      this._plane.set(this._held);
    } else {
      this.view.viewDirection(this._plane);
      this._plane[3] =
        this._plane[0] * this._p[0] + this._plane[1] * this._p[1] + this._plane[2] * this._p[2];
    }
    if (this.view.rayOnPlane(x, y, this._plane, this._s)) {
      for (let k = 0; k < 3; k++) this._grab[k] = this._p[k] - this._s[k];
    } else {
      this._grab.fill(0);
    }
    this.dragging = i;
    this.select(i);
    this.view.canvas.focus({ preventScroll: true });
    this.view.canvas.style.cursor = "grabbing";
    this.view.requestDraw();
    return true;
  }

  pointerMove(event, x, y) {
    if (this.dragging < 0) return;
    this._pending[0] = x;
    this._pending[1] = y;
    this._hasPending = true;
    this.view.requestDraw();
  }

  pointerUp(event, x, y) {
    if (this.dragging < 0) return;
    this.pointerMove(event, x, y);
    this._flush();
    const i = this.dragging;
    this.dragging = -1;
    this.view.canvas.style.cursor = this.hitTest(x, y, event.pointerType) >= 0 ? "grab" : "";
    this.source.commit("drag", i, null);
    this.source.get(i, this._p);
    if (this._p.some((v, k) => v !== this._start[k])) this._announce("handles.moved3d", i);
    this.view.requestDraw();
  }

  _flush() {
    if (!this._hasPending || this.dragging < 0) return;
    this._hasPending = false;
    if (!this.view.rayOnPlane(this._pending[0], this._pending[1], this._plane, this._s)) return;
    for (let k = 0; k < 3; k++) this._s[k] += this._grab[k];
    this._apply(this.dragging, this._s);
  }

  /** Writes handle i's plane into `_held`; false when it moves freely. */
  _heldIn(i) {
    return Boolean(this.source.plane?.(i, this._held));
  }

  /** The sight line through p (into `_sight`) meets the held plane well away from edge-on. */
  _facing(p) {
    this.view.sightLine(p[0], p[1], p[2], this._sight);
    return Math.abs(dot3(this._held, this._sight)) >= EDGE_ON;
  }

  /**
   * Rounds to what a tenth of a pixel resolves at the point's depth, then moves. A handle held
   * in a plane first slides along its line of sight onto it (it stays where it is seen), or
   * straight onto it when the plane is edge-on, and is put exactly into it after the rounding.
   */
  _apply(i, p) {
    const held = this._heldIn(i);
    const h = this._held;
    const off = () => dot3(h, p) - h[3];
    if (held && this._facing(p)) {
      const s = -off() / dot3(h, this._sight);
      for (let k = 0; k < 3; k++) p[k] += s * this._sight[k];
    }
    const perPixel = this.view.worldPerPixel(p[0], p[1], p[2]);
    const scale = 1 / perPixel;
    for (let k = 0; k < 3; k++) p[k] = roundToView(p[k], scale);
    if (held) {
      const e = off();
      for (let k = 0; k < 3; k++) p[k] -= e * h[k];
    }
    this.source.move(i, p[0], p[1], p[2]);
  }

  // -------------------------------------------------------------- keyboard

  _key(event) {
    const n = this.source.count();
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    // A figure with no points (a curve alone, `handles: []`): the arrows still orbit.
    if (n === 0 && !event.key.startsWith("Arrow")) return;
    if (n > 0 && selectionKey(event, this, n)) return;
    const i = this.selected;
    switch (event.key) {
      case "ArrowLeft":
      case "ArrowRight":
      case "ArrowUp":
      case "ArrowDown": {
        const px = event.shiftKey ? NUDGE_PX_LARGE : NUDGE_PX;
        const dx = event.key === "ArrowLeft" ? -1 : event.key === "ArrowRight" ? 1 : 0;
        const dy = event.key === "ArrowDown" ? -1 : event.key === "ArrowUp" ? 1 : 0;
        if (i < 0) {
          const step = ORBIT_STEP_DEG * (event.shiftKey ? 3 : 1);
          this.view.orbitBy(-dx * step, -dy * step);
        } else {
          this._nudge(i, dx * px, dy * px, 0);
        }
        break;
      }
      case "PageUp":
      case "PageDown":
        if (i < 0) return;
        // A handle held in a plane cannot leave it: nothing moves, nothing is announced.
        if (this._heldIn(i)) break;
        this._nudge(i, 0, 0, event.key === "PageUp" ? DEPTH_NUDGE_PX : -DEPTH_NUDGE_PX);
        break;
      case "+":
      case "=":
        if (!this.source.add) return;
        this.source.add(i);
        break;
      case "Delete":
      case "Backspace":
        if (!this.source.remove || i < 0) return;
        this.source.remove(i);
        break;
      default:
        return;
    }
    event.preventDefault();
  }

  /**
   * Moves point i by (right, up) px in the plane facing the camera and `toward` px-equivalents
   * towards the viewer, then commits (repeated presses make one undo step).
   */
  _nudge(i, right, up, toward) {
    this.source.get(i, this._p);
    const perPixel = this.view.worldPerPixel(this._p[0], this._p[1], this._p[2]);
    this.view.screenAxes(this._right, this._up, this._sight);
    // Towards the viewer along the line of sight through the point: it stays where it is seen.
    this.view.sightLine(this._p[0], this._p[1], this._p[2], this._sight);
    for (let k = 0; k < 3; k++)
      this._p[k] +=
        perPixel * (right * this._right[k] + up * this._up[k] - toward * this._sight[k]);
    this._apply(i, this._p);
    this.source.commit("key", i, `nudge-${this._nudges.next(i)}`);
    this._announce("handles.moved3d", i);
    this.view.requestDraw();
  }

  // -------------------------------------------------------------- drawing

  /** Draws the handles far to near (a nearer one on top) and their labels, away from the centre. */
  draw(r, view) {
    const theme = r.theme;
    const n = this.source.count();
    if (this._order.length !== n) {
      this._order = new Int32Array(n);
      this._depth = new Float64Array(3 * n);
      this._hidden = new Uint8Array(n);
    }
    let cx = 0;
    let cy = 0;
    for (let i = 0; i < n; i++) {
      this.source.get(i, this._p);
      view.project(this._p[0], this._p[1], this._p[2], this._s);
      this._depth[3 * i] = this._s[0];
      this._depth[3 * i + 1] = this._s[1];
      this._depth[3 * i + 2] = this._s[2];
      cx += this._s[0] / n;
      cy += this._s[1] / n;
      this._order[i] = i;
      this._hidden[i] = view.occluded?.(this._p[0], this._p[1], this._p[2]) ? 1 : 0;
    }
    // Insertion sort by depth, farthest first (n is small: a control net).
    for (let a = 1; a < n; a++) {
      const k = this._order[a];
      let b = a - 1;
      while (b >= 0 && this._depth[3 * this._order[b] + 2] < this._depth[3 * k + 2]) {
        this._order[b + 1] = this._order[b];
        b--;
      }
      this._order[b + 1] = k;
    }
    // A phone-width figure names only the selected point; else the source chooses (and the
    // selected, dragged and hovered points are always named).
    const narrow = view.width < NARROW_CANVAS_PX * r.scale;
    for (let a = 0; a < n; a++) {
      const i = this._order[a];
      const x = this._depth[3 * i];
      const y = this._depth[3 * i + 1];
      const hidden = this._hidden[i] === 1;
      const shown =
        i === this.selected
          ? theme.handleSelected
          : i === this.hovered || i === this.dragging
            ? theme.handleHover
            : theme.handle;
      const style = hidden ? faded(shown) : shown;
      r.point(x, y, style);
      const named =
        i === this.selected ||
        i === this.dragging ||
        (!narrow && (i === this.hovered || (this.source.showLabel?.(i) ?? true)));
      if (!named) continue;
      const label = i === this.selected ? theme.labelBold : theme.label;
      placeLabelFrom(
        r,
        this.source.label(i),
        x,
        y,
        cx,
        cy,
        hidden && i !== this.selected ? fadedLabel(label, theme) : label,
        style.radius * r.scale,
      );
    }
    if (this.dragging < 0 && r === view.renderer) this._publish(n);
  }

  /**
   * `data-handles` on the figure host: "x,y;x,y" canvas CSS px, and `data-hidden-handles`: the
   * indices the surface hides, "3,7" (hooks for tests), when changed.
   */
  _publish(n) {
    const parts = [];
    const hidden = [];
    for (let i = 0; i < n; i++) {
      parts.push(`${this._depth[3 * i].toFixed(1)},${this._depth[3 * i + 1].toFixed(1)}`);
      if (this._hidden[i]) hidden.push(i);
    }
    const text = `${parts.join(";")}|${hidden.join(",")}`;
    if (text === this._published) return;
    this._published = text;
    this.view.host.dataset.handles = parts.join(";");
    this.view.host.dataset.hiddenHandles = hidden.join(",");
  }
}
