// Issue 15's work budgets, timed in Node on the built package: the hostile calls that used to
// freeze a page for seconds, and the ordinary calls beside them. Prints one line per call
// (median of the repetitions, after a warm-up call so V8 has compiled the wasm optimised).
// No timing is asserted; the tests check the results (tests/bspline.rs, tests/bezier.rs,
// tests/errors.rs).
//
//   node bench/budgets.mjs               the package in www/pkg (make build)
//   node bench/budgets.mjs path/to/pkg   another build of it, e.g. a copy made before a change
import { readFileSync } from "node:fs";
import { resolve } from "node:path";
import { pathToFileURL } from "node:url";

const dir = resolve(process.argv[2] ?? new URL("../www/pkg", import.meta.url).pathname);
const { default: init, ...sl } = await import(pathToFileURL(`${dir}/splinelab.js`).href);
await init({ module_or_path: readFileSync(`${dir}/splinelab_bg.wasm`) });

/** Repetitions of the ordinary calls (hostile ones run once: they took seconds). */
const REPEATS = 5;

function rng(seed) {
  let s = seed >>> 0;
  return () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 4294967296;
  };
}

/** Median time (ms) of `repeats` calls of `f` after one warm-up call, and its last result or
 * error message. */
function time(f, repeats = REPEATS) {
  const run = () => {
    const start = performance.now();
    let result;
    try {
      result = f();
    } catch (e) {
      result = e.message;
    }
    return [performance.now() - start, result];
  };
  if (repeats > 1) run();
  const runs = Array.from({ length: repeats }, run);
  const times = runs.map((r) => r[0]).sort((a, b) => a - b);
  return [times[Math.floor(times.length / 2)], runs[runs.length - 1][1]];
}

function report(name, [ms, result]) {
  console.log(`${name}: ${ms.toFixed(1)} ms — ${result}`);
}

function clampedKnots(count, p) {
  const knots = [];
  for (let i = 0; i <= p; i++) knots.push(0);
  for (let i = 1; i < count - p; i++) knots.push(i);
  for (let i = 0; i <= p; i++) knots.push(count - p);
  return Float64Array.from(knots);
}

const random = rng(7);
// A degree-64 curve: 65 random points in [0, 100]² (the flatten rows).
const degree64 = new sl.BezierCurve(
  Float64Array.from({ length: 130 }, () => 100 * random()),
  2,
);
for (const tolerance of [1e-2, 1e-3, 1e-4]) {
  report(
    `flatten(${tolerance}) of a degree-64 curve`,
    time(() => `${degree64.flatten(tolerance).length / 2 - 1} segments`),
  );
}
report(
  "flatten(3e-8) of a degree-64 curve",
  time(() => `${degree64.flatten(3e-8).length / 2 - 1} segments`, 1),
);

// toBezier of a 20 000-point cubic B-spline, and the patches of a 200 × 200 bicubic surface.
const count = 20_000;
const cubic = new sl.BSplineCurve(
  Float64Array.from({ length: 2 * count }, () => 100 * random()),
  2,
  3,
  clampedKnots(count, 3),
);
report(
  "toBezier() of a 20 000-point cubic B-spline",
  time(() => {
    const pieces = cubic.toBezier();
    for (const piece of pieces) piece.free();
    return `${pieces.length} pieces`;
  }, 1),
);
const side = 200;
const sheet = new sl.BSplineSurface(
  Float64Array.from({ length: 3 * side * side }, () => random()),
  side,
  side,
  3,
  3,
  clampedKnots(side, 3),
  clampedKnots(side, 3),
);
report(
  "toBezierPatches() of a 200 × 200 bicubic surface",
  time(() => {
    const patches = sheet.toBezierPatches();
    for (const patch of patches) patch.free();
    return `${patches.length} patches`;
  }, 1),
);

// sampleGrid 5000 × 5000 (600 MB of result).
const grid = Float64Array.from({ length: 5000 }, (_, i) => (i / 4999) * (side - 3));
report(
  "sampleGrid(5000 values, 5000 values)",
  time(() => `${sheet.sampleGrid(grid, grid).length} numbers`, 1),
);
