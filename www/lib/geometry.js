/**
 * Point lists for the demos: the flat array the wasm constructors take, the bounding box a
 * figure fits, and — as drawing support only, not a curve algorithm — the convex hull that the
 * hull-property demos shade. Curve algorithms belong to the core (src/), never here.
 */

/** Flat Float64Array [x0, y0, x1, y1, …] of a list of [x, y] points (for the wasm constructors). */
export function flatten(points) {
  const flat = new Float64Array(points.length * 2);
  points.forEach(([x, y], i) => {
    flat[2 * i] = x;
    flat[2 * i + 1] = y;
  });
  return flat;
}

/**
 * The points' bounding box (`boundsOf`) grown on each side by `roomX` × its width left and right
 * and `roomY` × its height below and above: room for the handles' labels around a fitted curve.
 */
export function paddedBounds(points, roomX, roomY) {
  const [x0, y0, x1, y1] = boundsOf(points);
  const padX = roomX * (x1 - x0);
  const padY = roomY * (y1 - y0);
  return [x0 - padX, y0 - padY, x1 + padX, y1 + padY];
}

/**
 * [xmin, ymin, xmax, ymax] of a list of [x, y] points (a curve lies in its control points' hull),
 * written into `out` when given (no allocation while drawing).
 */
export function boundsOf(points, out = null) {
  let x0 = Infinity;
  let y0 = Infinity;
  let x1 = -Infinity;
  let y1 = -Infinity;
  for (const [x, y] of points) {
    x0 = Math.min(x0, x);
    y0 = Math.min(y0, y);
    x1 = Math.max(x1, x);
    y1 = Math.max(y1, y);
  }
  if (!out) return [x0, y0, x1, y1];
  out[0] = x0;
  out[1] = y0;
  out[2] = x1;
  out[3] = y1;
  return out;
}

/**
 * The convex hull of some of the points — drawing support for the (strong) convex hull
 * property, not a curve algorithm: Andrew's monotone chain. `indices` (default: all points) are
 * indices into `points`; they are sorted by x (then y), the lower chain is built left to right
 * and the upper chain right to left, popping the last vertex while it does not make a strict
 * left turn (cross product ≤ 0, so collinear points are dropped). Returns the hull's vertex
 * indices counter-clockwise from the leftmost point; one index when all points coincide, two
 * when they are collinear. O(n log n) for the few points of a demo.
 */
export function convexHull(points, indices = points.map((_, i) => i)) {
  const order = indices
    .slice()
    .sort((a, b) => points[a][0] - points[b][0] || points[a][1] - points[b][1]);
  const cross = (o, a, b) =>
    (points[a][0] - points[o][0]) * (points[b][1] - points[o][1]) -
    (points[a][1] - points[o][1]) * (points[b][0] - points[o][0]);
  const chain = (list) => {
    const out = [];
    for (const i of list) {
      while (out.length >= 2 && cross(out[out.length - 2], out[out.length - 1], i) <= 0) out.pop();
      out.push(i);
    }
    out.pop(); // the last vertex starts the other chain
    return out;
  };
  const hull = chain(order).concat(chain(order.slice().reverse()));
  if (hull.length === 0) return order.slice(0, 1); // all points equal (or a single point)
  const same = (a, b) => points[a][0] === points[b][0] && points[a][1] === points[b][1];
  return hull.length === 2 && same(hull[0], hull[1]) ? hull.slice(0, 1) : hull;
}

/**
 * Of `count` sampled functions stored function-major (`values[i·samples + k]`), the one whose
 * graph passes nearest to canvas height `y` at sample `k` — within `maxDistance` px, else -1.
 * `toY(value)` maps a function value to canvas y. For hovering a plot of basis functions.
 */
export function nearestGraph(values, count, samples, k, y, toY, maxDistance) {
  let best = -1;
  let bestDistance = maxDistance;
  for (let i = 0; i < count; i++) {
    const d = Math.abs(toY(values[i * samples + k]) - y);
    if (d <= bestDistance) {
      best = i;
      bestDistance = d;
    }
  }
  return best;
}

/**
 * Distance from (x, y) to the polyline through the flat points `flat` [x0, y0, x1, y1, …]: the
 * least distance to one of its segments, each the clamped projection of the point onto it.
 * A measurement between two sampled curves that does not depend on their parametrisations.
 */
export function distanceToPolyline(x, y, flat) {
  let best = Infinity;
  for (let k = 0; k + 3 < flat.length; k += 2) {
    const ax = flat[k];
    const ay = flat[k + 1];
    const dx = flat[k + 2] - ax;
    const dy = flat[k + 3] - ay;
    const length2 = dx * dx + dy * dy;
    const s = length2 > 0 ? Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / length2)) : 0;
    best = Math.min(best, Math.hypot(x - ax - s * dx, y - ay - s * dy));
  }
  return best;
}

/**
 * True when (x, y) lies in the triangle of the three [x, y] `points`, edges included — drawing
 * support for the convex hull property of a quadratic. Each edge's cross product with the point
 * has the sign of the triangle's area when the point is on its inner side; `tolerance` (relative
 * to the area) lets points on an edge count as inside despite rounding.
 */
export function inTriangle(x, y, points, tolerance) {
  const [[x0, y0], [x1, y1], [x2, y2]] = points;
  const area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  const scale = Math.abs(area) || 1;
  const d0 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) * Math.sign(area || 1);
  const d1 = ((x2 - x1) * (y - y1) - (x - x1) * (y2 - y1)) * Math.sign(area || 1);
  const d2 = ((x0 - x2) * (y - y2) - (x - x2) * (y0 - y2)) * Math.sign(area || 1);
  const eps = -tolerance * scale;
  return d0 >= eps && d1 >= eps && d2 >= eps;
}

/**
 * The largest distance max_k |a_k − b_k| between two flat sample lists [x0, y0, …] of the same
 * length taken at the same parameters — or, with `reversed`, max_k |a_k − b_{m−1−k}| (m samples:
 * a curve against a reversed one, R(1 − t) against P(t)). A check that two curves agree, reported
 * beside the core's results; not a curve algorithm.
 */
export function largestGap(a, b, reversed = false) {
  const count = a.length / 2;
  let distance = 0;
  for (let k = 0; k < count; k++) {
    const j = reversed ? count - 1 - k : k;
    distance = Math.max(distance, Math.hypot(a[2 * k] - b[2 * j], a[2 * k + 1] - b[2 * j + 1]));
  }
  return distance;
}
