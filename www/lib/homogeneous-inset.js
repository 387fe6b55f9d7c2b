/**
 * The homogeneous picture of a rational curve, drawn as an inset of a 2D figure: the rational
 * curve P(t) = Σ Bᵢ wᵢ Pᵢ / Σ Bᵢ wᵢ is the central projection onto the plane w = 1 of the
 * polynomial curve Pʷ(t) = Σ Bᵢ (wᵢxᵢ, wᵢyᵢ, wᵢ) in (wx, wy, w) space: the point (X, Y, W)
 * projects to (X/W, Y/W, 1), along the ray from the origin O. The inset shows the axes from O,
 * the plane w = 1 with the control polygon and the rational curve on it, rays from O through a
 * few projected points to their homogeneous points (the last ray, the current t, highlighted),
 * and the homogeneous control polygon and curve with the points Pᵢʷ labelled. It sits in a
 * strip on the right of a wide canvas or at the bottom of a tall one (`insetOnRight`,
 * `insetSize`: reserve it with the View's `insets`); its oblique view is lib/projection3d.js.
 *
 * Everything it draws is the core's (samples and points of the demo's wasm curves), passed in
 * one `picture` object (build it when the data changes, not per frame):
 * `{ prefix, points, homPoints, samples, homSamples, sampleCount, rayPoints, rayHom, rayCount }`
 * — `prefix` the strings.js prefix of `.insetTitle`, `.axisX`, `.axisY`, `.axisW`, `.origin`,
 * `.plane`; `points` the [x, y] control points, `homPoints` flat (X, Y, W) triples; `samples`
 * (2D) and `homSamples` (3D) `sampleCount` each; `rayPoints` (2D) and `rayHom` (3D) at the
 * `rayCount` ray parameters, the current t last.
 */
import { ObliqueCamera } from "./projection3d.js";
import { subscript } from "./format.js";
import { boundsOf } from "./geometry.js";
import { t } from "./strings.js";

/**
 * The inset (homogeneous space): a strip on the right of a wide canvas (width / height above
 * INSET_RIGHT_ASPECT), or at the bottom of a tall one, of INSET_FRACTION of the canvas (at least
 * INSET_MIN_PX), with a margin inside.
 */
const INSET_FRACTION = 0.44;
const INSET_RIGHT_ASPECT = 1.2;
const INSET_MIN_PX = 170;
const INSET_MARGIN = Object.freeze({ top: 46, right: 18, bottom: 18, left: 18 });
/**
 * The inset's oblique view of (X, Y, W) = (wx, wy, w): X to the right, W up, Y receding by
 * RECEDING per unit. W is stretched so its extent is W_EXTENT of the XY extent: a linear map of
 * space, so rays through the origin stay rays through the origin.
 */
const RECEDING = Object.freeze([0.5, 0.32]);
const W_EXTENT = 0.85;
/** The plane w = 1 is drawn over the control points' box plus this fraction of its size. */
const PLANE_PAD = 0.12;
/** The w axis is drawn this factor beyond the largest weight. */
const AXIS_OVERSHOOT = 1.12;

/** The inset goes on the right of a wide canvas, below the curve on a squarer one (phones). */
export function insetOnRight(width, height) {
  return width >= INSET_RIGHT_ASPECT * height;
}

/** Width (on the right) or height (at the bottom) of the inset's strip, CSS px. */
export function insetSize(extent) {
  return Math.max(
    Math.round(extent * INSET_FRACTION),
    Math.min(INSET_MIN_PX, Math.round(extent / 2)),
  );
}

/** The inset's strip (CSS px), its camera, and the plane's box [x0, y0, x1, y1] (scratch). */
const inset = { x0: 0, y0: 0, x1: 0, y1: 0, right: true };
const camera = new ObliqueCamera({ receding: RECEDING });
const plane = new Float64Array(4);

/** Lays out the strip; fits the camera to the origin, the homogeneous points, the plane, the w axis. */
function layoutInset(r, p, maxW) {
  const { width, height, scale } = r;
  const right = insetOnRight(width, height);
  inset.right = right;
  inset.x0 = right ? width - insetSize(width) : 0;
  inset.y0 = right ? 0 : height - insetSize(height);
  inset.x1 = width;
  inset.y1 = height;
  const pts = p.points;
  const h = p.homPoints;
  let xyExtent = 0;
  for (let i = 0; i < pts.length; i++) {
    xyExtent = Math.max(
      xyExtent,
      Math.abs(h[3 * i]),
      Math.abs(h[3 * i + 1]),
      Math.abs(pts[i][0]),
      Math.abs(pts[i][1]),
    );
  }
  camera.reset((W_EXTENT * Math.max(xyExtent, 1)) / maxW);
  for (let i = 0; i < pts.length; i++) camera.include(h[3 * i], h[3 * i + 1], h[3 * i + 2]);
  // The plane w = 1 over the control points' box, padded.
  boundsOf(pts, plane);
  const pad = PLANE_PAD * Math.max(plane[2] - plane[0], plane[3] - plane[1], 1);
  plane[0] -= pad;
  plane[1] -= pad;
  plane[2] += pad;
  plane[3] += pad;
  camera.include(plane[0], plane[1], 1);
  camera.include(plane[2], plane[1], 1);
  camera.include(plane[2], plane[3], 1);
  camera.include(plane[0], plane[3], 1);
  camera.include(0, 0, maxW * AXIS_OVERSHOOT); // the w axis' tip
  const m = INSET_MARGIN;
  camera.fit(
    inset.x0 + m.left * scale,
    inset.y0 + m.top * scale,
    width - m.right * scale,
    height - m.bottom * scale,
  );
}

/** moveTo / lineTo of the space point (X, Y, W) through the camera. */
function to(r, move, X, Y, W) {
  if (move) r.moveTo(camera.sx(X, Y, W), camera.sy(X, Y, W));
  else r.lineTo(camera.sx(X, Y, W), camera.sy(X, Y, W));
}

/**
 * The homogeneous picture: axes from O, the plane w = 1 with the control polygon and the
 * rational curve on it, rays from O through projected points to their homogeneous points, the
 * homogeneous control polygon and curve (a polynomial curve in space).
 */
export function drawHomogeneousInset(r, p) {
  const theme = r.theme;
  const k = r.scale;
  const pts = p.points;
  const n = pts.length - 1;
  const h = p.homPoints;
  let maxW = 1;
  for (let i = 0; i <= n; i++) maxW = Math.max(maxW, h[3 * i + 2]);
  layoutInset(r, p, maxW);

  // Background (covers anything panned under it) and the dividing line.
  r.beginPath();
  r.rect(inset.x0, inset.y0, inset.x1 - inset.x0, inset.y1 - inset.y0);
  r.paint(theme.plotBackground);
  r.beginPath();
  r.moveTo(inset.x0, inset.y0);
  if (inset.right) r.lineTo(inset.x0, inset.y1);
  else r.lineTo(inset.x1, inset.y0);
  r.paint(theme.axis);
  r.text(
    t(`${p.prefix}.insetTitle`),
    inset.x0 + 10 * k,
    inset.y0 + 8 * k,
    theme.labelSmall,
    "left",
    "top",
  );

  // Axes from the origin O.
  const ox = camera.sx(0, 0, 0);
  const oy = camera.sy(0, 0, 0);
  const ax = plane[2] > 0 ? plane[2] : 1;
  const ay = plane[3] > 0 ? plane[3] : 1;
  const top = maxW * AXIS_OVERSHOOT;
  r.beginPath();
  to(r, true, 0, 0, 0);
  to(r, false, ax, 0, 0);
  to(r, true, 0, 0, 0);
  to(r, false, 0, ay, 0);
  to(r, true, 0, 0, 0);
  to(r, false, 0, 0, top);
  r.paint(theme.axis);
  r.text(
    t(`${p.prefix}.axisX`),
    camera.sx(ax, 0, 0) + 4 * k,
    oy,
    theme.labelSmall,
    "left",
    "middle",
  );
  r.text(
    t(`${p.prefix}.axisY`),
    camera.sx(0, ay, 0) + 4 * k,
    camera.sy(0, ay, 0),
    theme.labelSmall,
    "left",
    "bottom",
  );
  r.text(
    t(`${p.prefix}.axisW`),
    ox - 5 * k,
    camera.sy(0, 0, top),
    theme.labelSmall,
    "right",
    "middle",
  );
  r.text(t(`${p.prefix}.origin`), ox - 5 * k, oy, theme.labelSmall, "right", "middle");

  // The plane w = 1, and on it the control polygon and the rational curve (the projection).
  r.beginPath();
  to(r, true, plane[0], plane[1], 1);
  to(r, false, plane[2], plane[1], 1);
  to(r, false, plane[2], plane[3], 1);
  to(r, false, plane[0], plane[3], 1);
  r.closePath();
  r.paint(theme.helperFill);
  const px = camera.sx(plane[2], plane[1], 1) + 4 * k;
  r.text(
    t(`${p.prefix}.plane`),
    px,
    camera.sy(plane[2], plane[1], 1),
    theme.labelSmall,
    "left",
    "top",
  );
  r.beginPath();
  for (let i = 0; i <= n; i++) to(r, i === 0, pts[i][0], pts[i][1], 1);
  r.paint(theme.polygon);
  r.beginPath();
  for (let j = 0; j < p.sampleCount; j++) to(r, j === 0, p.samples[2 * j], p.samples[2 * j + 1], 1);
  r.paint(theme.curve);

  // Rays from O through each projected point to its homogeneous point (the farther one ends the ray).
  const rays = p.rayCount - 1;
  const hom = p.rayHom;
  for (let j = 0; j <= rays; j++) {
    const W = hom[3 * j + 2];
    const reach = Math.max(W, 1) / W; // beyond the homogeneous point when W < 1
    r.beginPath();
    r.moveTo(ox, oy);
    to(r, false, hom[3 * j] * reach, hom[3 * j + 1] * reach, W * reach);
    r.paint(j === rays ? theme.marker : theme.helper);
  }

  // The homogeneous control polygon and curve, the points Pᵢʷ labelled.
  r.beginPath();
  for (let i = 0; i <= n; i++) to(r, i === 0, h[3 * i], h[3 * i + 1], h[3 * i + 2]);
  r.paint(theme.polygon);
  const hs = p.homSamples;
  r.beginPath();
  for (let j = 0; j < p.sampleCount; j++) to(r, j === 0, hs[3 * j], hs[3 * j + 1], hs[3 * j + 2]);
  r.paint(theme.splitLeft);
  for (let i = 0; i <= n; i++) {
    const x = camera.sx(h[3 * i], h[3 * i + 1], h[3 * i + 2]);
    const y = camera.sy(h[3 * i], h[3 * i + 1], h[3 * i + 2]);
    r.point(x, y, theme.splitLeftPoint);
    r.text(
      (HOMOGENEOUS_LABELS[i] ??= `P${subscript(i)}ʷ`),
      x,
      y - 7 * k,
      theme.labelSmall,
      "center",
      "bottom",
    );
  }
  // Ray ends: the point on the plane and the homogeneous point, the current t in vermillion.
  const q = p.rayPoints;
  for (let j = 0; j <= rays; j++) {
    const current = j === rays;
    const style = current ? theme.pointOnCurve : theme.comparePoint[0];
    r.point(camera.sx(q[2 * j], q[2 * j + 1], 1), camera.sy(q[2 * j], q[2 * j + 1], 1), style);
    if (current) {
      const [X, Y, W] = [hom[3 * j], hom[3 * j + 1], hom[3 * j + 2]];
      r.point(camera.sx(X, Y, W), camera.sy(X, Y, W), theme.splitLeftPoint);
    }
  }
}

/** "P₀ʷ", "P₁ʷ", … (cached). */
const HOMOGENEOUS_LABELS = [];
