// The hand-written JavaScript baseline: what a competent user writes instead of using a library.
// Flat Float64Arrays, scratch buffers made once per call (never per point), spans walked with a
// hint for sorted parameters, rational curves on homogeneous points with one division at the end.
// Conventions as splinelab's: knots u_0..u_{n+p+1}, domain [u_p, u_{n+1}], last span closed.

/** Points of a Bézier curve (any degree) at every t of `ts` by de Casteljau, into `out`. */
export function bezierSample(points, dim, ts, out) {
  const count = points.length / dim;
  const scratch = new Float64Array(points.length);
  for (let s = 0; s < ts.length; s++) {
    const t = ts[s];
    const mt = 1 - t;
    scratch.set(points);
    for (let r = 1; r < count; r++) {
      for (let i = 0; i < (count - r) * dim; i++)
        scratch[i] = mt * scratch[i] + t * scratch[i + dim];
    }
    for (let c = 0; c < dim; c++) out[s * dim + c] = scratch[c];
  }
  return out;
}

/** Points of a 2D cubic Bézier at every t of `ts`, Bernstein form unrolled (the fastest plain JS). */
export function cubicSample2d(points, ts, out) {
  const [x0, y0, x1, y1, x2, y2, x3, y3] = points;
  for (let s = 0; s < ts.length; s++) {
    const t = ts[s];
    const mt = 1 - t;
    const b0 = mt * mt * mt;
    const b1 = 3 * mt * mt * t;
    const b2 = 3 * mt * t * t;
    const b3 = t * t * t;
    out[2 * s] = b0 * x0 + b1 * x1 + b2 * x2 + b3 * x3;
    out[2 * s + 1] = b0 * y0 + b1 * y1 + b2 * y2 + b3 * y3;
  }
  return out;
}

/** One point of a 2D cubic Bézier into `out` (the per-call form of cubicSample2d). */
export function cubicPoint2d(points, t, out) {
  const mt = 1 - t;
  const b0 = mt * mt * mt;
  const b1 = 3 * mt * mt * t;
  const b2 = 3 * mt * t * t;
  const b3 = t * t * t;
  out[0] = b0 * points[0] + b1 * points[2] + b2 * points[4] + b3 * points[6];
  out[1] = b0 * points[1] + b1 * points[3] + b2 * points[5] + b3 * points[7];
  return out;
}

/**
 * A B-spline prepared for the loops below: homogeneous points `(w·P, w)` with stride dim + 1 when
 * rational, plain points with stride dim otherwise (a user would not carry weights of 1).
 */
export function prepareBSpline({ dim, degree, points, knots, weights }, capacity = 0) {
  const count = points.length / dim;
  const rational = weights != null;
  const stride = rational ? dim + 1 : dim;
  const cw = new Float64Array((count + capacity) * stride);
  for (let i = 0; i < count; i++) {
    const w = rational ? weights[i] : 1;
    for (let c = 0; c < dim; c++) cw[i * stride + c] = w * points[i * dim + c];
    if (rational) cw[i * stride + dim] = w;
  }
  const k = new Float64Array(knots.length + capacity);
  k.set(knots);
  return { dim, p: degree, n: count - 1, rational, stride, cw, knots: k };
}

/** Span k with u_k ≤ u < u_{k+1} (the last span closed), by binary search. */
export function findSpan(knots, n, p, u) {
  if (u >= knots[n + 1]) {
    let k = n;
    while (knots[k] === knots[k + 1]) k--;
    return k;
  }
  let lo = p;
  let hi = n + 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (u < knots[mid]) hi = mid;
    else lo = mid;
  }
  return lo;
}

/** The span of u starting from the previous span k: a short walk for sorted parameters. */
function spanFrom(knots, n, p, u, k) {
  if (u < knots[k] || u >= knots[n + 1]) return findSpan(knots, n, p, u);
  while (u >= knots[k + 1]) k++;
  return k;
}

/** Curve points at every u of `us` by de Boor's algorithm (NURBS Book A4.1 / eq. 5.x), into `out`. */
export function deBoorSample(curve, us, out) {
  const d = new Float64Array((curve.p + 1) * curve.stride);
  let k = curve.p;
  for (let s = 0; s < us.length; s++) {
    k = spanFrom(curve.knots, curve.n, curve.p, us[s], k);
    deBoorInSpan(curve, k, us[s], d, out, s * curve.dim);
  }
  return out;
}

/** One point by de Boor into `out` (the per-call path): a binary span search, the scratch kept
 * on the curve. */
export function deBoorPoint(curve, u, out) {
  curve.deBoorScratch ??= new Float64Array((curve.p + 1) * curve.stride);
  const k = findSpan(curve.knots, curve.n, curve.p, u);
  deBoorInSpan(curve, k, u, curve.deBoorScratch, out, 0);
  return out;
}

/** De Boor's triangle in span k on the scratch `d`, the point written at out[o…]. */
function deBoorInSpan(curve, k, u, d, out, o) {
  const { dim, p, rational, stride, cw, knots } = curve;
  const base = (k - p) * stride;
  for (let i = 0; i < (p + 1) * stride; i++) d[i] = cw[base + i];
  for (let r = 1; r <= p; r++) {
    for (let j = p; j >= r; j--) {
      const i = k - p + j;
      const denom = knots[i + p - r + 1] - knots[i];
      const a = denom === 0 ? 0 : (u - knots[i]) / denom;
      const b = 1 - a;
      for (let c = 0; c < stride; c++)
        d[j * stride + c] = b * d[(j - 1) * stride + c] + a * d[j * stride + c];
    }
  }
  const last = p * stride;
  const inv = rational ? 1 / d[last + dim] : 1;
  for (let c = 0; c < dim; c++) out[o + c] = d[last + c] * inv;
}

/** The p + 1 non-zero basis values N_{k−p..k, p}(u) at span k into N (NURBS Book A2.2). */
export function basisFunctions(knots, p, k, u, N, left, right) {
  N[0] = 1;
  for (let j = 1; j <= p; j++) {
    left[j] = u - knots[k + 1 - j];
    right[j] = knots[k + j] - u;
    let saved = 0;
    for (let r = 0; r < j; r++) {
      const temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

/**
 * First derivatives at every u of `us`, into `out`: basis values and their first derivatives
 * per point (NURBS Book A2.3 with n = 1), summed; the quotient rule C' = (A' − w'C)/w for NURBS.
 */
export function deBoorFirstDerivatives(curve, us, out) {
  const scratch = derivativeScratch(curve);
  let k = curve.p;
  for (let s = 0; s < us.length; s++) {
    k = spanFrom(curve.knots, curve.n, curve.p, us[s], k);
    firstDerivativeInSpan(curve, k, us[s], scratch, out, s * curve.dim);
  }
  return out;
}

/** One first derivative into `out` (the per-call path): binary span search, scratch on the curve. */
export function firstDerivativePoint(curve, u, out) {
  curve.derivativeScratch ??= derivativeScratch(curve);
  const k = findSpan(curve.knots, curve.n, curve.p, u);
  firstDerivativeInSpan(curve, k, u, curve.derivativeScratch, out, 0);
  return out;
}

function derivativeScratch({ p, stride }) {
  const f = (n) => new Float64Array(n);
  return {
    N: f(p + 1),
    Nm: f(p + 1),
    dN: f(p + 1),
    left: f(p + 1),
    right: f(p + 1),
    A: f(stride),
    dA: f(stride),
  };
}

/** C'(u) in span k, written at out[o…]. */
function firstDerivativeInSpan(curve, k, u, { N, Nm, dN, left, right, A, dA }, out, o) {
  const { dim, p, rational, stride, cw, knots } = curve;
  // Degree p − 1 values (for the derivative), then one more Cox–de Boor step to degree p.
  basisFunctions(knots, p - 1, k, u, Nm, left, right);
  for (let j = 0; j < p; j++) N[j] = Nm[j];
  left[p] = u - knots[k + 1 - p];
  right[p] = knots[k + p] - u;
  let saved = 0;
  for (let r = 0; r < p; r++) {
    const temp = N[r] / (right[r + 1] + left[p - r]);
    N[r] = saved + right[r + 1] * temp;
    saved = left[p - r] * temp;
  }
  N[p] = saved;
  // N'_{i,p} = p/(u_{i+p} − u_i) N_{i,p−1} − p/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}, i = k − p + j.
  for (let j = 0; j <= p; j++) {
    let v = 0;
    if (j > 0) v += Nm[j - 1] / (knots[k + j] - knots[k - p + j]);
    if (j < p) v -= Nm[j] / (knots[k + j + 1] - knots[k - p + j + 1]);
    dN[j] = p * v;
  }
  A.fill(0);
  dA.fill(0);
  for (let j = 0; j <= p; j++) {
    const base = (k - p + j) * stride;
    for (let c = 0; c < stride; c++) {
      A[c] += N[j] * cw[base + c];
      dA[c] += dN[j] * cw[base + c];
    }
  }
  if (rational) {
    const w = A[dim];
    const dw = dA[dim];
    for (let c = 0; c < dim; c++) out[o + c] = (dA[c] - (dw * A[c]) / w) / w;
  } else {
    for (let c = 0; c < dim; c++) out[o + c] = dA[c];
  }
}

/**
 * Inserts knot u once, in place (Boehm; NURBS Book A5.1 with r = 1): the arrays were made with
 * spare capacity by prepareBSpline(…, capacity); the tail is shifted by one with copyWithin.
 */
export function insertKnotInPlace(curve, u) {
  const { p, n, stride, cw, knots } = curve;
  const k = findSpan(knots, n, p, u);
  // Points k..n move one slot right; then slots k..k−p+1 (downwards) blend old neighbours.
  cw.copyWithin((k + 1) * stride, k * stride, (n + 1) * stride);
  for (let i = k; i >= k - p + 1; i--) {
    const a = (u - knots[i]) / (knots[i + p] - knots[i]);
    const b = 1 - a;
    for (let c = 0; c < stride; c++)
      cw[i * stride + c] = a * cw[i * stride + c] + b * cw[(i - 1) * stride + c];
  }
  knots.copyWithin(k + 2, k + 1, n + p + 2);
  knots[k + 1] = u;
  curve.n = n + 1;
}

/** Gauss–Legendre nodes and weights on [−1, 1] by Newton's method on P_n (computed, not tabled). */
export function gaussLegendre(order) {
  const nodes = new Float64Array(order);
  const weights = new Float64Array(order);
  for (let i = 0; i < order; i++) {
    let x = Math.cos((Math.PI * (i + 0.75)) / (order + 0.5));
    let dp = 0;
    for (let iter = 0; iter < 100; iter++) {
      let p0 = 1;
      let p1 = x;
      for (let k = 2; k <= order; k++) {
        const p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = (order * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / dp;
      x -= dx;
      if (Math.abs(dx) < 1e-16) break;
    }
    nodes[i] = x;
    weights[i] = 2 / ((1 - x * x) * dp * dp);
  }
  return { nodes, weights };
}

const GL24 = gaussLegendre(24);

/** 24-point Gauss–Legendre of the speed of the cubic with hodograph differences a, b, c over [lo, hi]. */
function cubicSpeedGL24(ax, ay, bx, by, cx, cy, lo, hi) {
  const { nodes, weights } = GL24;
  const h = 0.5 * (hi - lo);
  let sum = 0;
  for (let i = 0; i < 24; i++) {
    const t = lo + h * (nodes[i] + 1);
    const mt = 1 - t;
    const b0 = mt * mt,
      b1 = 2 * mt * t,
      b2 = t * t;
    const dx = b0 * ax + b1 * bx + b2 * cx;
    const dy = b0 * ay + b1 * by + b2 * cy;
    sum += weights[i] * Math.sqrt(dx * dx + dy * dy);
  }
  return 3 * h * sum;
}

/** Arc length of each 2D cubic Bézier in `points` (8 numbers each) by 24-point Gauss–Legendre on [0, 1]. */
export function cubicArcLengthsGL24(points, out) {
  const count = points.length / 8;
  for (let c = 0; c < count; c++) {
    const o = 8 * c;
    // Differences of the control points: the hodograph's, divided by 3.
    const ax = points[o + 2] - points[o],
      ay = points[o + 3] - points[o + 1];
    const bx = points[o + 4] - points[o + 2],
      by = points[o + 5] - points[o + 3];
    const cx = points[o + 6] - points[o + 4],
      cy = points[o + 7] - points[o + 5];
    out[c] = cubicSpeedGL24(ax, ay, bx, by, cx, cy, 0, 1);
  }
  return out;
}

/** Most pending intervals of the adaptive rule below (a depth cap of 50 keeps it far lower). */
const ADAPTIVE_STACK = 256;
const adaptiveStack = new Float64Array(4 * ADAPTIVE_STACK);

/**
 * Arc length of each 2D cubic Bézier in `points` by adaptive 24-point Gauss–Legendre, as a JS
 * user who needs 1e-12 would write it: an interval is halved until its halves agree with it
 * to its share of `accuracy` × the control polygon's length (the halves are then far more
 * accurate than that), at most 50 levels deep. An explicit stack, no allocation per curve.
 */
export function cubicArcLengthsAdaptiveGL24(points, out, accuracy = 1e-13) {
  const stack = adaptiveStack;
  const count = points.length / 8;
  for (let c = 0; c < count; c++) {
    const o = 8 * c;
    const ax = points[o + 2] - points[o],
      ay = points[o + 3] - points[o + 1];
    const bx = points[o + 4] - points[o + 2],
      by = points[o + 5] - points[o + 3];
    const cx = points[o + 6] - points[o + 4],
      cy = points[o + 7] - points[o + 5];
    const polygon =
      Math.sqrt(ax * ax + ay * ay) + Math.sqrt(bx * bx + by * by) + Math.sqrt(cx * cx + cy * cy);
    let total = 0;
    stack[0] = 0;
    stack[1] = 1;
    stack[2] = cubicSpeedGL24(ax, ay, bx, by, cx, cy, 0, 1);
    stack[3] = 0;
    let top = 1;
    while (top > 0) {
      top -= 1;
      const k = 4 * top;
      const lo = stack[k],
        hi = stack[k + 1],
        whole = stack[k + 2],
        depth = stack[k + 3];
      const mid = 0.5 * (lo + hi);
      const left = cubicSpeedGL24(ax, ay, bx, by, cx, cy, lo, mid);
      const right = cubicSpeedGL24(ax, ay, bx, by, cx, cy, mid, hi);
      if (
        depth >= 50 ||
        top + 2 > ADAPTIVE_STACK ||
        Math.abs(left + right - whole) <= accuracy * polygon * (hi - lo)
      ) {
        total += left + right;
      } else {
        stack[k] = lo;
        stack[k + 1] = mid;
        stack[k + 2] = left;
        stack[k + 3] = depth + 1;
        stack[k + 4] = mid;
        stack[k + 5] = hi;
        stack[k + 6] = right;
        stack[k + 7] = depth + 1;
        top += 2;
      }
    }
    out[c] = total;
  }
  return out;
}

/**
 * Points of a rational tensor-product surface on a countU × countV grid of equally spaced
 * parameters, into `out` (row-major, 3 numbers each): the basis of every grid u and v computed
 * once, then each row collapses the u direction into one homogeneous curve of countV points
 * (p + 1 rows blended), which is evaluated at every grid v.
 */
export function surfaceGrid(s, gridU, gridV, out) {
  const { degree: p, countU, countV, points, weights, knotsU, knotsV } = s;
  const hw = new Float64Array(4 * countU * countV);
  for (let k = 0; k < countU * countV; k++) {
    const w = weights[k];
    hw[4 * k] = w * points[3 * k];
    hw[4 * k + 1] = w * points[3 * k + 1];
    hw[4 * k + 2] = w * points[3 * k + 2];
    hw[4 * k + 3] = w;
  }
  const left = new Float64Array(p + 1);
  const right = new Float64Array(p + 1);
  const tmp = new Float64Array(p + 1);
  const tabulate = (knots, count, grid) => {
    const n = count - 1;
    const us = new Float64Array(grid);
    const a = knots[p];
    const b = knots[n + 1];
    const spans = new Int32Array(grid);
    const basis = new Float64Array(grid * (p + 1));
    const step = (b - a) / (grid - 1);
    let k = p;
    for (let j = 0; j < grid; j++) {
      const u = j === grid - 1 ? b : a + step * j;
      us[j] = u;
      k = spanFrom(knots, n, p, u, k);
      spans[j] = k;
      basisFunctions(knots, p, k, u, tmp, left, right);
      basis.set(tmp, j * (p + 1));
    }
    return { spans, basis };
  };
  const U = tabulate(knotsU, countU, gridU);
  const V = tabulate(knotsV, countV, gridV);
  const row = new Float64Array(4 * countV);
  let o = 0;
  for (let i = 0; i < gridU; i++) {
    const ku = U.spans[i];
    row.fill(0);
    for (let a = 0; a <= p; a++) {
      const nu = U.basis[i * (p + 1) + a];
      const base = (ku - p + a) * countV * 4;
      for (let j = 0; j < 4 * countV; j++) row[j] += nu * hw[base + j];
    }
    for (let j = 0; j < gridV; j++) {
      const kv = V.spans[j];
      let x = 0,
        y = 0,
        z = 0,
        w = 0;
      for (let b = 0; b <= p; b++) {
        const nv = V.basis[j * (p + 1) + b];
        const r = (kv - p + b) * 4;
        x += nv * row[r];
        y += nv * row[r + 1];
        z += nv * row[r + 2];
        w += nv * row[r + 3];
      }
      const inv = 1 / w;
      out[o++] = x * inv;
      out[o++] = y * inv;
      out[o++] = z * inv;
    }
  }
  return out;
}

/**
 * The basis strip of a drag frame: N_{j,p}(u) for the p + 1 functions non-zero at each u of
 * `us`, into `out` ((p + 1) values per u) and the span of each u into `spans`.
 */
export function basisStrip(curve, us, out, spans) {
  const { p, n, knots } = curve;
  const N = new Float64Array(p + 1);
  const left = new Float64Array(p + 1);
  const right = new Float64Array(p + 1);
  let k = p;
  for (let s = 0; s < us.length; s++) {
    k = spanFrom(knots, n, p, us[s], k);
    basisFunctions(knots, p, k, us[s], N, left, right);
    spans[s] = k;
    out.set(N, s * (p + 1));
  }
}
