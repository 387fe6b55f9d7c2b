// Deterministic benchmark inputs: every library sees exactly these numbers.
// Shared by the Node harness (bench.mjs) and the browser page (browser.html).

/** mulberry32: a tiny seeded generator of floats in [0, 1); same seed, same sequence everywhere. */
export function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export const SEED = 20260505;

/** `count` parameters equally spaced over [a, b], ends included (the same formula as sampleUniform). */
export function uniformParams(a, b, count) {
  const us = new Float64Array(count);
  const step = (b - a) / (count - 1);
  for (let j = 0; j < count; j++) us[j] = a + step * j;
  us[count - 1] = b;
  return us;
}

/** Clamped knot vector for n + 1 points of degree p with random interior spacing in [0.5, 1.5). */
export function clampedKnots(n, p, random) {
  const knots = new Float64Array(n + p + 2);
  let u = 0;
  for (let i = p + 1; i <= n; i++) {
    u += 0.5 + random();
    knots[i] = u;
  }
  u += 0.5 + random();
  for (let i = n + 1; i < n + p + 2; i++) knots[i] = u;
  return knots;
}

/** A 2D cubic Bézier with control points in [0, 100)². */
export function cubicBezier(seed = SEED) {
  const random = rng(seed);
  const points = new Float64Array(8);
  for (let i = 0; i < 8; i++) points[i] = 100 * random();
  return points;
}

/**
 * A clamped 2D B-spline of degree p with `count` control points: a random walk (so the curve
 * wanders instead of filling a box), non-uniform knots, and weights in [0.5, 2] when rational.
 */
export function bspline(count = 1000, p = 3, rational = false, seed = SEED + 1) {
  const random = rng(seed);
  const points = new Float64Array(2 * count);
  let x = 0;
  let y = 0;
  for (let i = 0; i < count; i++) {
    x += 10 * (random() - 0.3);
    y += 10 * (random() - 0.5);
    points[2 * i] = x;
    points[2 * i + 1] = y;
  }
  const knots = clampedKnots(count - 1, p, random);
  let weights = null;
  if (rational) {
    weights = new Float64Array(count);
    for (let i = 0; i < count; i++) weights[i] = 0.5 + 1.5 * random();
  }
  return { dim: 2, degree: p, count, points, knots, weights };
}

/** A degree-(3, 3) rational surface in 3D: a wavy 32×32 sheet, weights in [0.5, 2], clamped knots. */
export function nurbsSurface(countU = 32, countV = 32, p = 3, seed = SEED + 2) {
  const random = rng(seed);
  const points = new Float64Array(3 * countU * countV); // row-major: index (i·countV + j)·3
  const weights = new Float64Array(countU * countV);
  for (let i = 0; i < countU; i++) {
    for (let j = 0; j < countV; j++) {
      const k = i * countV + j;
      points[3 * k] = i + 0.4 * (random() - 0.5);
      points[3 * k + 1] = j + 0.4 * (random() - 0.5);
      points[3 * k + 2] = Math.sin(i / 3) * Math.cos(j / 4) + 0.5 * random();
      weights[k] = 0.5 + 1.5 * random();
    }
  }
  const knotsU = clampedKnots(countU - 1, p, random);
  const knotsV = clampedKnots(countV - 1, p, random);
  return { dim: 3, degree: p, countU, countV, points, weights, knotsU, knotsV };
}

/** `count` sorted knots to insert, strictly inside the domain and away from existing knots. */
export function insertionKnots(knots, p, count, seed = SEED + 3) {
  const random = rng(seed);
  const a = knots[p];
  const b = knots[knots.length - 1 - p];
  const out = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    let u;
    do u = a + (b - a) * random();
    while (nearKnot(knots, u));
    out[i] = u;
  }
  return out.sort();
}

function nearKnot(knots, u) {
  for (let i = 0; i < knots.length; i++) if (Math.abs(knots[i] - u) < 1e-9) return true;
  return false;
}

/** `count` random 2D cubic Béziers with control points in [0, 1)², back to back (8 numbers each). */
export function randomCubics(count, seed = SEED + 4) {
  const random = rng(seed);
  const points = new Float64Array(8 * count);
  for (let i = 0; i < points.length; i++) points[i] = random();
  return points;
}
