/**
 * The camera of a 3D figure as plain numbers, the way the state (the URL, JSON files, the
 * `view` attribute of `<spline-lab>`) stores it: `[azimuth, elevation, distance, tx, ty, tz]`
 * with the angles in degrees. z is up (the maths convention of the notes). The camera sits at
 *
 *   target + distance · (cos e · cos a, cos e · sin a, sin e)
 *
 * looking at the target (a = azimuth from the x axis towards y, e = elevation above the xy
 * plane). Display code only.
 */

/** Vertical field of view of the perspective camera, degrees. */
export const FIELD_OF_VIEW = 30;
/**
 * The camera's frame: a rectangle of this aspect (width / height) around the target that every
 * canvas shows whole and centred, as a 2D figure shows its world window — a wider canvas shows
 * more at the sides, a narrower one (a phone) gets a taller field of view. So a camera means the
 * same picture at any size, and a fit does not depend on the screen it was made on.
 */
export const REFERENCE_ASPECT = 1.6;

/** The vertical field of view (degrees) that shows the camera's frame whole at `aspect`. */
export function verticalFieldOfView(aspect) {
  const widen = Math.max(1, REFERENCE_ASPECT / Math.max(aspect, 1e-3));
  return (2 * Math.atan(Math.tan((FIELD_OF_VIEW / 2) * DEG) * widen)) / DEG;
}

/** The starting direction: from the front right, a little above (degrees). */
export const DEFAULT_AZIMUTH = -60;
export const DEFAULT_ELEVATION = 28;
/** |elevation| stays below this (degrees): at ±90 the up direction is undefined. */
export const MAX_ELEVATION = 89;
/** Camera numbers kept in the state: this many significant digits (short links). */
const CAMERA_DIGITS = 6;
/** Empty space around the content when fitting, as a fraction of the field of view. */
const FIT_PADDING = 0.1;
/** Smallest half extent of the box a fit uses (a flat or single point still gets a usable view). */
const MIN_FIT_RADIUS = 0.5;

const DEG = Math.PI / 180;
const round = (x) => Number(x.toPrecision(CAMERA_DIGITS));

/** Whether `camera` is `[azimuth, elevation, distance, tx, ty, tz]`: finite, distance > 0, |elevation| ≤ MAX_ELEVATION. */
export function isCamera(camera) {
  return (
    Array.isArray(camera) &&
    camera.length === 6 &&
    camera.every((v) => typeof v === "number" && Number.isFinite(v)) &&
    camera[2] > 0 &&
    Math.abs(camera[1]) <= MAX_ELEVATION
  );
}

/** The camera rounded as the state keeps it (azimuth into (−180, 180]). */
export function roundCamera([azimuth, elevation, distance, tx, ty, tz]) {
  let a = azimuth % 360;
  if (a > 180) a -= 360;
  if (a <= -180) a += 360;
  const e = Math.max(-MAX_ELEVATION, Math.min(MAX_ELEVATION, elevation));
  return [round(a), round(e), round(distance), round(tx), round(ty), round(tz)];
}

/** Puts the numbers on a three.js camera (position, up = z, looking at the target). */
export function applyCamera(camera, [azimuth, elevation, distance, tx, ty, tz]) {
  const a = azimuth * DEG;
  const e = elevation * DEG;
  camera.up.set(0, 0, 1);
  camera.position.set(
    tx + distance * Math.cos(e) * Math.cos(a),
    ty + distance * Math.cos(e) * Math.sin(a),
    tz + distance * Math.sin(e),
  );
  camera.lookAt(tx, ty, tz);
  camera.near = distance / 100;
  camera.far = distance * 100;
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
}

/** The numbers of a three.js camera looking at `target` (a Vector3), unrounded. */
export function readCamera(camera, target) {
  const dx = camera.position.x - target.x;
  const dy = camera.position.y - target.y;
  const dz = camera.position.z - target.z;
  const distance = Math.hypot(dx, dy, dz);
  return [
    Math.atan2(dy, dx) / DEG,
    Math.asin(Math.max(-1, Math.min(1, dz / (distance || 1)))) / DEG,
    distance,
    target.x,
    target.y,
    target.z,
  ];
}

/** Rounds of re-centring in `fitCamera` (each moves the target to the projected box's middle). */
export const FIT_CENTRING_ROUNDS = 4;

/**
 * The camera that shows the box `[x0, y0, z0, x1, y1, z1]` whole in its frame (of
 * `REFERENCE_ASPECT`, so on every canvas), seen from `azimuth`, `elevation`: the nearest
 * distance at which every corner of the box projects inside both fields of view, each shrunk
 * by the padding. A corner at (x, y) across and z towards the camera (camera axes, from the
 * target) needs depth d − z ≥ |x| / tan(half horizontal angle) and ≥ |y| / tan(half vertical).
 * The target starts at the box's centre and is then moved across the view (a few rounds) to
 * the middle of the corners' projections, so the box's picture is centred in the frame rather
 * than its centre point (a flat box seen from above fills the frame, not half of it).
 */
export function fitCamera(bounds, azimuth = DEFAULT_AZIMUTH, elevation = DEFAULT_ELEVATION) {
  const [x0, y0, z0, x1, y1, z1] = bounds;
  const a = azimuth * DEG;
  const e = elevation * DEG;
  // Towards the camera (b), right (r = up × b normalised, up = z) and the camera's up (b × r... u).
  const back = [Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)];
  const right = [-Math.sin(a), Math.cos(a), 0];
  const up = [
    back[1] * right[2] - back[2] * right[1],
    back[2] * right[0] - back[0] * right[2],
    back[0] * right[1] - back[1] * right[0],
  ];
  const tanV = Math.tan((FIELD_OF_VIEW / 2) * DEG) * (1 - FIT_PADDING);
  const tanH = Math.tan((FIELD_OF_VIEW / 2) * DEG) * REFERENCE_ASPECT * (1 - FIT_PADDING);
  const middle = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2];
  const half = [
    Math.max((x1 - x0) / 2, MIN_FIT_RADIUS),
    Math.max((y1 - y0) / 2, MIN_FIT_RADIUS),
    Math.max((z1 - z0) / 2, MIN_FIT_RADIUS),
  ];
  const corners = Array.from({ length: 8 }, (_, corner) =>
    [0, 1, 2].map((k) => middle[k] + (corner & (1 << k) ? half[k] : -half[k])),
  );
  const target = [...middle];
  /** The distance for `target`, and the middle of the corners' projections (tangent units). */
  const fitAt = () => {
    let distance = 0;
    const rel = corners.map((c) => [c[0] - target[0], c[1] - target[1], c[2] - target[2]]);
    const dot = (c, w) => c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
    for (const c of rel) {
      const toward = dot(c, back);
      distance = Math.max(
        distance,
        toward + Math.abs(dot(c, right)) / tanH,
        toward + Math.abs(dot(c, up)) / tanV,
      );
    }
    let [xMin, xMax, yMin, yMax] = [Infinity, -Infinity, Infinity, -Infinity];
    for (const c of rel) {
      const depth = distance - dot(c, back);
      const x = dot(c, right) / depth;
      const y = dot(c, up) / depth;
      [xMin, xMax, yMin, yMax] = [
        Math.min(xMin, x),
        Math.max(xMax, x),
        Math.min(yMin, y),
        Math.max(yMax, y),
      ];
    }
    return { distance, dx: (xMin + xMax) / 2, dy: (yMin + yMax) / 2 };
  };
  let fit = fitAt();
  for (let round = 0; round < FIT_CENTRING_ROUNDS; round++) {
    // Move the target across the view by the offset at its depth (the distance).
    for (let k = 0; k < 3; k++) target[k] += fit.distance * (fit.dx * right[k] + fit.dy * up[k]);
    fit = fitAt();
  }
  return roundCamera([azimuth, elevation, fit.distance, ...target]);
}

/** `[xmin, ymin, zmin, xmax, ymax, zmax]` of `[x, y, z]` points. */
export function boundsOf3(points) {
  const b = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const p of points) {
    for (let k = 0; k < 3; k++) {
      b[k] = Math.min(b[k], p[k]);
      b[k + 3] = Math.max(b[k + 3], p[k]);
    }
  }
  return b;
}
