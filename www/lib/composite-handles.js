/**
 * The control points of a composite Bézier curve (a `CompositeBezier`: piece k's points one
 * after the other) as one list of handles, each distinct point once: a joint, shared by the end
 * of piece k and the start of piece k + 1 (and the seam of a closed curve), is one handle.
 *
 * Moving a handle edits the curve in place (`setControlPoint(piece, i, point)`), the way drawing
 * programs do: a joint carries its two neighbouring points along (the tangent directions at the
 * joint stay), and an inner point next to a smooth joint turns the point on the other side of
 * the joint so that both stay on one line through it (G¹ is kept; that point keeps its distance
 * from the joint, or, at a joint whose two neighbours were at one distance, takes the moved
 * one's: with both pieces on intervals of length 1, 3(P₃ − P₂) = 3(Q₁ − Q₀) stays, C¹). A joint
 * counts as smooth when its two neighbours already lie on one line through it, turning by less
 * than `SMOOTH_DEGREES`; a corner stays a corner.
 */

/** Below this turn at a joint (degrees) the joint is smooth and kept so. */
export const SMOOTH_DEGREES = 1;
const SMOOTH_COS = Math.cos((SMOOTH_DEGREES * Math.PI) / 180);

/**
 * The handles of a curve with pieces of `degrees` (closed: the last point is the first):
 * `{ count, piece: Int32Array, index: Int32Array, offset: Int32Array }` — handle h is point
 * `index[h]` of piece `piece[h]`; `offset[k]` is where piece k starts in `controlPoints()`.
 */
export function compositeHandles(degrees, closed) {
  const n = degrees.length;
  const offset = new Int32Array(n + 1);
  for (let k = 0; k < n; k++) offset[k + 1] = offset[k] + degrees[k] + 1;
  const piece = [];
  const index = [];
  for (let k = 0; k < n; k++) {
    for (let i = k === 0 && !closed ? 0 : 1; i <= degrees[k]; i++) {
      piece.push(k);
      index.push(i);
    }
  }
  return {
    count: piece.length,
    piece: Int32Array.from(piece),
    index: Int32Array.from(index),
    offset,
    degrees: Int32Array.from(degrees),
    closed,
  };
}

const xy = new Float64Array(2);

/** Moves control point i of piece k to (x, y) in `curve` and in the flat copy `cps`. */
function put(curve, map, cps, k, i, x, y) {
  const j = 2 * (map.offset[k] + i);
  cps[j] = x;
  cps[j + 1] = y;
  xy[0] = x;
  xy[1] = y;
  curve.setControlPoint(k, i, xy);
}

/** Adds (dx, dy) to control point i of piece k. */
function shift(curve, map, cps, k, i, dx, dy) {
  const j = 2 * (map.offset[k] + i);
  put(curve, map, cps, k, i, cps[j] + dx, cps[j + 1] + dy);
}

/** [x, y] of control point i of piece k. */
function at(map, cps, k, i) {
  const j = 2 * (map.offset[k] + i);
  return [cps[j], cps[j + 1]];
}

/** The piece after k (the first after the last when closed), or −1. */
function nextPiece(map, k) {
  const n = map.degrees.length;
  if (k < n - 1) return k + 1;
  return map.closed ? 0 : -1;
}

/** The piece before k, or −1. */
function previousPiece(map, k) {
  if (k > 0) return k - 1;
  return map.closed ? map.degrees.length - 1 : -1;
}

/**
 * How the joint j between a (before) and b (after) is kept: 0 a corner (left alone), 1 smooth
 * (a, j, b turn by less than SMOOTH_DEGREES: G¹), 2 mirrored (also |j − a| = |b − j|: with
 * pieces on parameter intervals of one length that is C¹, and it stays so).
 */
function jointKind(a, j, b) {
  const ux = j[0] - a[0];
  const uy = j[1] - a[1];
  const vx = b[0] - j[0];
  const vy = b[1] - j[1];
  const lu = Math.hypot(ux, uy);
  const lv = Math.hypot(vx, vy);
  if (!(lu > 0 && lv > 0 && (ux * vx + uy * vy) / (lu * lv) > SMOOTH_COS)) return 0;
  return Math.abs(lu - lv) <= EQUAL_LENGTHS * Math.max(lu, lv) ? 2 : 1;
}
/** Two handle lengths within this fraction of each other are equal (a C¹ joint). */
const EQUAL_LENGTHS = 1e-9;

/**
 * Puts `other` on the line from `moved` through joint `j`, beyond j: at its own distance (G¹),
 * or at the moved point's distance when `mirror` (C¹).
 */
function turnOpposite(curve, map, cps, k, i, j, moved, mirror) {
  const o = at(map, cps, k, i);
  const dx = j[0] - moved[0];
  const dy = j[1] - moved[1];
  const length = Math.hypot(dx, dy);
  const keep = mirror ? length : Math.hypot(o[0] - j[0], o[1] - j[1]);
  if (length === 0 || keep === 0) return;
  put(curve, map, cps, k, i, j[0] + (dx / length) * keep, j[1] + (dy / length) * keep);
}

/**
 * Moves handle h of `map` to (x, y) in `curve` (in place), with its companions as described
 * above. `cps` is the curve's `controlPoints()` (kept up to date here).
 */
export function moveCompositeHandle(curve, map, cps, h, x, y) {
  const k = map.piece[h];
  const i = map.index[h];
  const deg = map.degrees[k];
  const [ox, oy] = at(map, cps, k, i);
  const dx = x - ox;
  const dy = y - oy;
  if (i === deg || i === 0) {
    // A joint or an end: it and the points beside it move together.
    put(curve, map, cps, k, i, x, y);
    if (deg > 1) shift(curve, map, cps, k, i === 0 ? 1 : deg - 1, dx, dy);
    const other = i === 0 ? -1 : nextPiece(map, k);
    if (other >= 0) {
      put(curve, map, cps, other, 0, x, y);
      if (map.degrees[other] > 1) shift(curve, map, cps, other, 1, dx, dy);
    }
    return;
  }
  // An inner point: keep a smooth joint beside it smooth.
  const before = [ox, oy];
  if (i === 1 && deg >= 3) {
    const p = previousPiece(map, k);
    const j = at(map, cps, k, 0);
    if (p >= 0) {
      const q = map.degrees[p];
      const kind = q >= 2 ? jointKind(at(map, cps, p, q - 1), j, before) : 0;
      put(curve, map, cps, k, i, x, y);
      if (kind > 0) turnOpposite(curve, map, cps, p, q - 1, j, [x, y], kind === 2);
      return;
    }
  }
  if (i === deg - 1 && deg >= 3) {
    const nx = nextPiece(map, k);
    const j = at(map, cps, k, deg);
    if (nx >= 0) {
      const kind = map.degrees[nx] >= 2 ? jointKind(before, j, at(map, cps, nx, 1)) : 0;
      put(curve, map, cps, k, i, x, y);
      if (kind > 0) turnOpposite(curve, map, cps, nx, 1, j, [x, y], kind === 2);
      return;
    }
  }
  put(curve, map, cps, k, i, x, y);
}
