/**
 * Orbit, pan and zoom of a 3D figure's camera by pointer and wheel, on the camera's numbers
 * `[azimuth, elevation, distance, tx, ty, tz]` (camera3d.js), as three.js' OrbitControls does
 * with its defaults (screen-space panning, no damping), so the page needs no three.js for it:
 *
 * - rotate (left button, one finger): a drag of (dx, dy) CSS px on a canvas h px tall turns the
 *   azimuth by −360·dx/h degrees and the elevation by +360·dy/h (a drag across the height is a
 *   full turn), the elevation kept within ±MAX_ELEVATION;
 * - pan (right button, or left with Shift, Ctrl or ⌘; two fingers' middle): the target moves by
 *   2·tan(fov/2)·distance / h world units per px, against the pointer along the camera's right
 *   and with it along its up, so the picture follows the pointer;
 * - zoom (wheel, middle-button drag, pinch): the distance is multiplied by 0.95^(|Δ|/100) per
 *   wheel or drag delta Δ px (nearer for a wheel turned up / a drag up), and by the ratio of the
 *   fingers' distances before and after in a pinch.
 *
 * `change(camera)` gets each new camera (unrounded), `end()` when a gesture or a wheel turn is
 * over.
 */
import { MAX_ELEVATION } from "./camera3d.js";

const DEG = Math.PI / 180;
/** Distance factor per 100 px of wheel or middle-drag delta. */
const ZOOM_PER_100PX = 0.95;
/** Pixels per wheel delta unit, by `deltaMode` (pixels, lines, pages). */
const WHEEL_UNIT = [1, 16, 100];

export class OrbitGesture {
  /**
   * @param {object} o
   * @param {() => number[]} o.camera the camera now.
   * @param {() => number} o.height the canvas' CSS height.
   * @param {() => number} o.fov the vertical field of view, degrees.
   * @param {import("./view-camera.js").ViewCamera} o.view the camera's axes (pan).
   * @param {(camera: number[]) => void} o.change
   * @param {() => void} o.end
   */
  constructor({ camera, height, fov, view, change, end }) {
    Object.assign(this, { camera, height, fov, view, change, end });
    /** Pointer id → last [x, y] CSS px, of the pointers in the gesture. */
    this.pointers = new Map();
    this.mode = null;
  }

  /** True while a pointer gesture runs. */
  get active() {
    return this.pointers.size > 0;
  }

  /** A pointer went down on empty space at (x, y): starts or extends the gesture. */
  down(event, x, y) {
    this.pointers.set(event.pointerId, [x, y]);
    if (this.pointers.size === 2) this.mode = "pinch";
    else if (this.pointers.size === 1) {
      const panKey = event.shiftKey || event.ctrlKey || event.metaKey;
      this.mode = event.button === 1 ? "dolly" : event.button === 2 || panKey ? "pan" : "rotate";
    }
  }

  move(event, x, y) {
    const last = this.pointers.get(event.pointerId);
    if (!last) return false;
    if (this.mode === "pinch") {
      const [a, b] = [...this.pointers.values()];
      const before = [Math.hypot(a[0] - b[0], a[1] - b[1]), (a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      last[0] = x;
      last[1] = y;
      const after = [Math.hypot(a[0] - b[0], a[1] - b[1]), (a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      const panned = this._pan(this.camera(), after[1] - before[1], after[2] - before[2]);
      if (after[0] > 0 && before[0] > 0) panned[2] *= before[0] / after[0];
      this.change(panned);
      return true;
    }
    const dx = x - last[0];
    const dy = y - last[1];
    last[0] = x;
    last[1] = y;
    if (this.mode === "rotate") this.change(this._rotate(this.camera(), dx, dy));
    else if (this.mode === "pan") this.change(this._pan(this.camera(), dx, dy));
    else if (this.mode === "dolly") this.change(this._zoom(this.camera(), dy));
    return true;
  }

  /** A pointer of the gesture went up (or was cancelled): true when that ended the gesture. */
  up(event) {
    if (!this.pointers.delete(event.pointerId)) return false;
    if (this.pointers.size === 1) this.mode = "rotate"; // a pinch's last finger turns the view
    if (this.pointers.size) return false;
    this.mode = null;
    this.end();
    return true;
  }

  /** A wheel turn: zooms towards the target (upwards: nearer). */
  wheel(event) {
    const delta = event.deltaY * (WHEEL_UNIT[event.deltaMode] ?? 1);
    if (!delta) return;
    this.change(this._zoom(this.camera(), delta));
    this.end();
  }

  _rotate([a, e, ...rest], dx, dy) {
    const h = Math.max(this.height(), 1);
    const elevation = Math.max(-MAX_ELEVATION, Math.min(MAX_ELEVATION, e + (360 * dy) / h));
    return [a - (360 * dx) / h, elevation, ...rest];
  }

  _pan([a, e, d, tx, ty, tz], dx, dy) {
    const perPixel = (2 * Math.tan((this.fov() / 2) * DEG) * d) / Math.max(this.height(), 1);
    const { right, up } = this.view;
    return [
      a,
      e,
      d,
      tx + perPixel * (-dx * right[0] + dy * up[0]),
      ty + perPixel * (-dx * right[1] + dy * up[1]),
      tz + perPixel * (-dx * right[2] + dy * up[2]),
    ];
  }

  _zoom([a, e, d, ...target], delta) {
    const factor = ZOOM_PER_100PX ** (Math.abs(delta) / 100);
    return [a, e, delta < 0 ? d * factor : d / factor, ...target];
  }
}
