// Workloads (h) and (i) of the interpolation issue (13): solve times of the interpolants through
// many points, and one drag frame of a 1000-point C2 spline. Shared by the Node harness and the
// browser page (browser.html), so both time exactly the same code. Nothing here asserts a timing.
//
// (h) `cubicSpline` (natural ends, chord params) and `interpolateBSpline` (degree 3, averaging
//     knots) through 10 000 and 100 000 points of a random walk: the median solve time, and the
//     100k/10k ratio, which is ≈ 10 for a linear-time solve (≈ 100 for O(n²), ≈ 1000 for O(n³)).
// (i) a drag frame of a 1000-point C2 spline as the playground does it: move data point 500
//     in place (`setPoint`: new rhs, one tridiagonal solve), then resample 4000 points.
import { rng, SEED } from "./inputs.mjs";

export const SOLVE_SIZES = [10_000, 100_000];
export const SPLINE_DRAG = { points: 1000, samples: 4000, index: 500 };

/** A 2D random walk of `count` points (distinct consecutive points, so chord params exist). */
export function walk(count, seed = SEED + 7) {
  const random = rng(seed);
  const points = new Float64Array(2 * count);
  let x = 0;
  let y = 0;
  for (let i = 0; i < count; i++) {
    x += 1 + 10 * random();
    y += 10 * (random() - 0.5);
    points[2 * i] = x;
    points[2 * i + 1] = y;
  }
  return points;
}

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

/** The largest distance |C(t_i) − p_i| over the data: the solve is checked before it is timed. */
function interpolationError(curve, points, params) {
  const at = curve.sample(params);
  let worst = 0;
  for (let k = 0; k < at.length; k++) worst = Math.max(worst, Math.abs(at[k] - points[k]));
  return worst;
}

/**
 * (h): median solve times over `rounds` (the object is built and freed each round; the
 * interpolation error of the first build is reported beside the time).
 */
export function solveBench(sl, { rounds = 7, sizes = SOLVE_SIZES } = {}) {
  const contenders = [
    {
      method: 'cubicSpline(points, 2, chord params, "natural")',
      build: (points, params) => sl.cubicSpline(points, 2, params, "natural"),
    },
    {
      method: "interpolateBSpline(points, 2, 3, chord params)",
      build: (points, params) => sl.interpolateBSpline(points, 2, 3, params),
    },
  ];
  const rows = [];
  for (const c of contenders) {
    for (const n of sizes) {
      const points = walk(n);
      const params = sl.parameterize(points, 2, "chord");
      const first = c.build(points, params);
      const error = interpolationError(first, points, params);
      first.free();
      const times = [];
      for (let r = 0; r < rounds; r++) {
        const t0 = performance.now();
        const curve = c.build(points, params);
        times.push(performance.now() - t0);
        curve.free();
      }
      rows.push({ method: c.method, n, medianMs: median(times), maxError: error });
    }
  }
  return rows;
}

/** (i): drag frames of a 1000-point natural C2 spline; timings in ms and the final agreement. */
export function splineDragBench(sl, { frames = 100, warmup = 10 } = {}) {
  const { points: count, samples, index: i } = SPLINE_DRAG;
  const points = walk(count);
  const params = sl.parameterize(points, 2, "chord");
  const spline = sl.cubicSpline(points, 2, params, "natural");
  const x0 = points[2 * i];
  const y0 = points[2 * i + 1];
  // Small moves, so the chord params given at construction stay valid data for the spline.
  const position = (f) => [x0 + 0.3 * Math.cos(0.1 * f), y0 + 0.3 * Math.sin(0.1 * f)];
  const times = [];
  let last = null;
  for (let f = 0; f < warmup + frames; f++) {
    const t0 = performance.now();
    spline.setPoint(i, position(f));
    last = spline.sampleUniform(samples);
    const dt = performance.now() - t0;
    if (f >= warmup) times.push(dt);
  }
  // Agreement: the in-place spline against one rebuilt from the moved points.
  const moved = points.slice();
  [moved[2 * i], moved[2 * i + 1]] = position(warmup + frames - 1);
  const rebuilt = sl.cubicSpline(moved, 2, params, "natural");
  const fresh = rebuilt.sampleUniform(samples);
  let diff = 0;
  for (let k = 0; k < fresh.length; k++) diff = Math.max(diff, Math.abs(fresh[k] - last[k]));
  rebuilt.free();
  spline.free();
  const sorted = [...times].sort((a, b) => a - b);
  return {
    method: "setPoint(500, xy) + sampleUniform(4000)",
    medianMs: median(times),
    p95Ms: sorted[Math.min(sorted.length - 1, Math.floor(0.95 * sorted.length))],
    maxMs: sorted[sorted.length - 1],
    frames: times.length,
    agreement: diff,
  };
}
