/**
 * The perspective camera of a 3D figure on the page, as plain numbers: where it is, which way it
 * looks and how it projects, without three.js (which the page loads only where it renders WebGL
 * itself: no rendering worker, exports). It follows three.js' `PerspectiveCamera` conventions,
 * so the page's projection and the worker's WebGL image agree to rounding:
 *
 * - pose (camera3d.js `applyCamera`): the eye at target + distance · (cos e cos a, cos e sin a,
 *   sin e), looking at the target with z up; `back` = (eye − target) / distance, `right` =
 *   (z × back) normalised, `up` = back × right; near = distance / 100, far = distance · 100;
 * - projection of a point with camera coordinates (x, y, z) = ((p − eye)·right, (p − eye)·up,
 *   (p − eye)·back), depth = −z: NDC x = x / (depth · tan(fov/2) · aspect), y = y / (depth ·
 *   tan(fov/2)), z = (f + n)/(f − n) − 2fn / ((f − n) · depth) (−1 at near, 1 at far, > 1 behind).
 */

const DEG = Math.PI / 180;

export class ViewCamera {
  constructor() {
    this.eye = new Float64Array(3);
    this.right = new Float64Array(3);
    this.up = new Float64Array(3);
    /** From the target towards the eye (the camera looks along −back). */
    this.back = new Float64Array(3);
    /** Vertical field of view, degrees, and width / height. */
    this.fov = 30;
    this.aspect = 1;
    this.near = 0.01;
    this.far = 1000;
  }

  /** Puts the camera at `[azimuth, elevation, distance, tx, ty, tz]` (camera3d.js). */
  set([azimuth, elevation, distance, tx, ty, tz]) {
    const a = azimuth * DEG;
    const e = elevation * DEG;
    const b = this.back;
    b[0] = Math.cos(e) * Math.cos(a);
    b[1] = Math.cos(e) * Math.sin(a);
    b[2] = Math.sin(e);
    this.eye[0] = tx + distance * b[0];
    this.eye[1] = ty + distance * b[1];
    this.eye[2] = tz + distance * b[2];
    // right = z × back, normalised (|elevation| < 90°: never zero).
    const n = Math.hypot(b[0], b[1]) || 1;
    this.right[0] = -b[1] / n;
    this.right[1] = b[0] / n;
    this.right[2] = 0;
    const r = this.right;
    this.up[0] = b[1] * r[2] - b[2] * r[1];
    this.up[1] = b[2] * r[0] - b[0] * r[2];
    this.up[2] = b[0] * r[1] - b[1] * r[0];
    this.near = distance / 100;
    this.far = distance * 100;
  }

  /** Writes NDC [x, y, z] of world point (x, y, z) into `out` (see the header). */
  project(x, y, z, out) {
    const dx = x - this.eye[0];
    const dy = y - this.eye[1];
    const dz = z - this.eye[2];
    const b = this.back;
    const depth = -(dx * b[0] + dy * b[1] + dz * b[2]);
    const tan = Math.tan((this.fov / 2) * DEG);
    const cx = dx * this.right[0] + dy * this.right[1] + dz * this.right[2];
    const cy = dx * this.up[0] + dy * this.up[1] + dz * this.up[2];
    const { near: n, far: f } = this;
    out[0] = cx / (depth * tan * this.aspect);
    out[1] = cy / (depth * tan);
    out[2] = (f + n) / (f - n) - (2 * f * n) / ((f - n) * depth);
    return out;
  }

  /** The unit direction from the eye through NDC (x, y), written into `out`. */
  rayDirection(x, y, out) {
    const tan = Math.tan((this.fov / 2) * DEG);
    const sx = x * tan * this.aspect;
    const sy = y * tan;
    for (let k = 0; k < 3; k++) out[k] = sx * this.right[k] + sy * this.up[k] - this.back[k];
    const n = Math.hypot(out[0], out[1], out[2]);
    for (let k = 0; k < 3; k++) out[k] /= n;
    return out;
  }
}
