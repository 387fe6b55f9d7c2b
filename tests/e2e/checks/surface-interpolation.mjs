// Browser checks of the surface interpolation demo: the chord-length parameters the demo
// publishes equal the ones computed here by hand from the data (per column |ΔQ| over the total,
// averaged over the columns), the core's surface evaluated at them gives every data point back
// to 1e-9, and a dragged data point is interpolated at its new position.
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
import { urlState } from "./helpers3d.mjs";

const ROWS = 4;
const COLS = 5;

const readout = (page) =>
  page.locator('[data-info="miss"]').evaluate((node) => ({ ...node.dataset }));

/**
 * Chord-length parameters written out: along each of `lines` lines of `length` points the
 * cumulative distances over their total, averaged over the lines.
 */
function chordParams(points, length, lines, at) {
  const sum = Array(length).fill(0);
  for (let l = 0; l < lines; l++) {
    const steps = [0];
    for (let k = 1; k < length; k++) {
      const [a, b] = [points[at(k - 1, l)], points[at(k, l)]];
      steps.push(Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
    const total = steps.reduce((x, y) => x + y, 0);
    let run = 0;
    for (let k = 0; k < length; k++) {
      run += steps[k];
      sum[k] += run / total / lines;
    }
  }
  return sum;
}

/** Largest |S(ū_k, v̄_l) − Q_kl| of the core's surface through `points` at the given params. */
const missInPage = (page, points, us, vs, state) =>
  page.evaluate(
    async ({ points, us, vs, state, rows, cols }) => {
      const { loadWasm } = await import("./lib/wasm.js");
      const sl = await loadWasm();
      const flat = points.flat();
      const s = sl.interpolateSurface(flat, rows, cols, state.degreeU, state.degreeV, state.kind);
      let worst = 0;
      us.forEach((u, k) =>
        vs.forEach((v, l) => {
          const p = s.evaluate(u, v);
          const q = points[k * cols + l];
          worst = Math.max(worst, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
        }),
      );
      s.free();
      return worst;
    },
    { points, us, vs, state, rows: ROWS, cols: COLS },
  );

/** The check of one state: published params = hand-computed, the surface meets every point. */
async function throughEveryPoint(page, assert) {
  const state = await urlState(page);
  const shown = await readout(page);
  const us = chordParams(state.points, ROWS, COLS, (k, l) => k * COLS + l);
  const vs = chordParams(state.points, COLS, ROWS, (k, l) => l * COLS + k);
  const published = [shown.paramsU, shown.paramsV].map((text) => text.split(" ").map(Number));
  [us, vs].forEach((mine, d) =>
    mine.forEach((x, k) =>
      assert(
        Math.abs(x - published[d][k]) < 1e-12,
        `param ${"uv"[d]}${k}: ${published[d][k]} vs ${x}`,
      ),
    ),
  );
  const miss = await missInPage(page, state.points, us, vs, state);
  assert(miss < 1e-9, `the surface misses a data point by ${miss}`);
  assert(Number(shown.miss) < 1e-9, `the demo's own check: ${shown.miss}`);
  return state;
}

export default [
  [
    "the surface passes through every data point at the published chord parameters (1e-9)",
    async (page, h, _base, { assert, equal }) => {
      const state = await throughEveryPoint(page, assert);
      equal(state.kind, "chord", "default parametrisation");
      // The control net is not the data (degrees 3): the formula counts 20 unknowns.
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("20"), `the formula counts the unknowns: ${formula}`);
    },
  ],
  [
    "a dragged data point is interpolated at its new position; the picture changes",
    async (page, h, _base, { assert }) => {
      const before = await urlState(page);
      const picture = await h.snapshot();
      const handles = await h.handles();
      await h.drag(handles[12], 25, -35); // Q₂₂, an inner point
      const after = await throughEveryPoint(page, assert);
      assert(
        JSON.stringify(after.points[12]) !== JSON.stringify(before.points[12]),
        `Q₂₂ did not move: ${after.points[12]}`,
      );
      assert((await h.snapshot()) !== picture, "the picture is the same after the drag");
    },
  ],
  [
    "step 1 (the column curves) is shown by default and toggles; uniform parameters are k/(n − 1)",
    async (page, h, _base, { assert, equal, settle }) => {
      const toggle = page.locator('[data-control="columns"] input');
      assert(await toggle.isChecked(), "step 1 is shown by default");
      const picture = await h.snapshot();
      await toggle.uncheck();
      await settle(page);
      assert((await h.snapshot()) !== picture, "hiding the column curves changed nothing");
      await toggle.check();
      await settle(page);
      equal(await h.snapshot(), picture, "showing them again");
      await page.locator('[data-control="kind"] [data-choice="uniform"] input').check();
      await settle(page);
      const shown = await readout(page);
      equal(shown.paramsU, [0, 1 / 3, 2 / 3, 1].join(" "), "ū");
      equal(shown.paramsV, [0, 0.25, 0.5, 0.75, 1].join(" "), "v̄");
      assert(Number(shown.miss) < 1e-9, `miss ${shown.miss}`);
    },
  ],
];
