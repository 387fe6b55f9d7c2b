// Memory soak of the built package (www/pkg) in Node, run with `node --expose-gc` (issue 15):
// drag frames and create/free cycles leave the wasm memory where it was, and objects a page
// forgets to free() are reclaimed through wasm-bindgen's FinalizationRegistry (on by default
// since wasm-bindgen 0.2.91, which feature-detects it; 0.2.130 has no --weak-refs flag).
//
// The measure is `memory.buffer.byteLength`: the wasm memory only grows (64 KiB pages), and
// the allocator reuses freed blocks, so a leak of one result or one object per frame grows it
// within the loops below. Each check has a control that holds its objects and must grow it,
// so the measure is shown to be sensitive. Ends with "memory: N passed, M failed"; exits 1 on
// failure.
//
//   node --expose-gc tests/e2e/memory.mjs   (make test runs it after the build; not a browser test)
import { readFileSync } from "node:fs";
import { setTimeout as sleep } from "node:timers/promises";
import init, * as sl from "../../www/pkg/splinelab.js";

const ROOT = new URL("../../", import.meta.url);
const wasm = await init({
  module_or_path: readFileSync(new URL("www/pkg/splinelab_bg.wasm", ROOT)),
});
const bytes = () => wasm.memory.buffer.byteLength;

if (typeof globalThis.gc !== "function") {
  console.error("memory: run with node --expose-gc");
  process.exit(2);
}

/** Frames of each drag loop and create/free cycles per class (issue 15's numbers). */
const DRAG_FRAMES = 10_000;
const CYCLES = 2_000;
/** Warm-up iterations before the memory is read: the allocator's free lists fill up. */
const WARM_UP = 200;

let passed = 0;
let failed = 0;
function check(name, ok, detail) {
  if (ok) passed++;
  else failed++;
  console.log(`${ok ? "ok  " : "FAIL"} ${name}: ${detail}`);
}

/** Runs the garbage collector until FinalizationRegistry callbacks have run (they are queued
 * as tasks after a collection). */
async function settle() {
  for (let i = 0; i < 4; i++) {
    globalThis.gc();
    await sleep(5);
  }
}

/** Seeded points of a random walk: `count` points of `dim` coordinates. */
function walk(count, dim, seed = 1) {
  let s = seed >>> 0;
  const random = () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 4294967296;
  };
  const out = new Float64Array(count * dim);
  for (let i = 0; i < out.length; i++) out[i] = (i >= dim ? out[i - dim] : 0) + random() - 0.5;
  return out;
}

function clampedKnots(count, p) {
  const knots = [];
  for (let i = 0; i <= p; i++) knots.push(0);
  for (let i = 1; i < count - p; i++) knots.push(i);
  for (let i = 0; i <= p; i++) knots.push(count - p);
  return Float64Array.from(knots);
}

const nurbsPoints = walk(1000, 2);
const nurbsKnots = clampedKnots(1000, 3);
const nurbsWeights = Float64Array.from({ length: 1000 }, (_, i) => 0.5 + (i % 7) / 4);
const net = walk(16 * 16, 3, 2);
const netKnots = clampedKnots(16, 3);
const netWeights = Float64Array.from({ length: 256 }, (_, i) => 0.5 + (i % 5) / 3);

/** One of every class, built from small seeded inputs. */
const makers = {
  BezierCurve: () => new sl.BezierCurve(walk(4, 2), 2),
  BSplineCurve: () => new sl.BSplineCurve(walk(50, 2), 2, 3, clampedKnots(50, 3)),
  BezierSurface: () => new sl.BezierSurface(walk(16, 3), 4, 4),
  BSplineSurface: () =>
    new sl.BSplineSurface(walk(64, 3), 8, 8, 3, 3, clampedKnots(8, 3), clampedKnots(8, 3)),
  CompositeBezier: () => new sl.CompositeBezier(walk(8, 2), 2, [3, 3]),
  CubicSpline: () => sl.cubicSpline(walk(20, 2), 2, "chord"),
  LagrangeCurve: () => sl.lagrange(walk(6, 2), 2, "uniform"),
};

// ---- Drag frames: setControlPoint + sampleUniform on a NURBS, and a surface tessellate ----
{
  const curve = new sl.BSplineCurve(nurbsPoints, 2, 3, nurbsKnots, nurbsWeights);
  const surface = new sl.BSplineSurface(net, 16, 16, 3, 3, netKnots, netKnots, netWeights);
  const frame = (f) => {
    curve.setControlPoint(500, [Math.cos(0.01 * f), Math.sin(0.01 * f)]);
    curve.sampleUniform(4000);
    surface.setControlPoint(8, 8, [0.5, 0.5, Math.sin(0.01 * f)]);
    surface.tessellate(32, 32);
  };
  for (let f = 0; f < WARM_UP; f++) frame(f);
  await settle();
  const before = bytes();
  for (let f = 0; f < DRAG_FRAMES; f++) frame(f);
  await settle();
  check(
    `${DRAG_FRAMES} drag frames`,
    bytes() === before,
    `wasm memory ${before} → ${bytes()} bytes`,
  );
  curve.free();
  surface.free();
}

// ---- Create/free cycles of every class -----------------------------------------------------
for (const [name, make] of Object.entries(makers)) {
  for (let i = 0; i < WARM_UP; i++) make().free();
  const before = bytes();
  for (let i = 0; i < CYCLES; i++) {
    const object = make();
    object.free();
  }
  check(
    `${CYCLES} create/free cycles of ${name}`,
    bytes() === before,
    `${before} → ${bytes()} bytes`,
  );
}

// Control: the same objects held, not freed, must grow the memory, or the measure is blind.
{
  const before = bytes();
  const held = [];
  for (const make of Object.values(makers)) for (let i = 0; i < CYCLES; i++) held.push(make());
  check("control: held objects grow the memory", bytes() > before, `${before} → ${bytes()} bytes`);
  for (const object of held) object.free();
}

// ---- Objects a page forgets to free() ------------------------------------------------------
// Each round forgets 2000 1000-point NURBS, ~48 MB in wasm (24 bytes per homogeneous point):
// without the FinalizationRegistry the memory would grow by that much in every round.
{
  const ROUNDS = 3;
  const PER_ROUND = 2000;
  const make = () => new sl.BSplineCurve(nurbsPoints, 2, 3, nurbsKnots, nurbsWeights);
  const forget = () => {
    for (let i = 0; i < PER_ROUND; i++) make();
  };
  forget();
  await settle();
  const before = bytes();
  for (let round = 0; round < ROUNDS; round++) {
    forget();
    await settle();
  }
  check(
    `${ROUNDS} × ${PER_ROUND} forgotten NURBS are reclaimed`,
    bytes() - before < PER_ROUND * 24_000,
    `${before} → ${bytes()} bytes`,
  );

  // Control: as many held grow the memory by at least their size.
  const start = bytes();
  const held = [];
  for (let i = 0; i < ROUNDS * PER_ROUND; i++) held.push(make());
  await settle();
  check(
    `control: ${ROUNDS} × ${PER_ROUND} held NURBS grow the memory`,
    bytes() - start >= (ROUNDS - 1) * PER_ROUND * 24_000,
    `${start} → ${bytes()} bytes`,
  );
  for (const c of held) c.free();
}

console.log(`memory: ${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
