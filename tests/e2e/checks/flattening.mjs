// Browser checks specific to the adaptive flattening demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.

/** The S-curve of the demo at ε = 0.05 (a link state). */
const S_CURVE = {
  points: [
    [0, 0],
    [2, 6],
    [6, -2],
    [8, 4],
  ],
  tolerance: 0.05,
  band: true,
};
const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

/** Segment counts of flatten(ε) and flatten(ε/2), computed in the page by the wasm package. */
async function coreCounts(page, points, tolerance) {
  return page.evaluate(
    async ({ points, tolerance }) => {
      const { loadWasm } = await import("./lib/wasm.js");
      const sl = await loadWasm();
      const curve = new sl.BezierCurve(points.flat(), 2);
      const counts = [
        curve.flatten(tolerance).length / 2 - 1,
        curve.flatten(tolerance / 2).length / 2 - 1,
      ];
      curve.free();
      return counts;
    },
    { points, tolerance },
  );
}

/** The demo's state as stored in the URL. */
async function urlState(page) {
  const s = new URLSearchParams(new URL(page.url()).hash.slice(1)).get("s");
  return JSON.parse(Buffer.from(s, "base64url").toString("utf8"));
}

const shown = async (page, info) => page.locator(`[data-info="${info}"]`).textContent();

export default [
  [
    "segment count equals flatten(ε).length/2 − 1 from the wasm package",
    async (page, h, base, { assert, equal, openDemo }) => {
      h = await openDemo(page, base, "flattening", link(S_CURVE));
      const [count, half] = await coreCounts(page, S_CURVE.points, 0.05);
      equal(await shown(page, "segments"), `${count} segments`, "segment count");
      assert(
        (await shown(page, "half")).includes(`ε/2 = 0.025: ${half} segments`),
        `half count: ${await shown(page, "half")}`,
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes(`tolerance 0.05: a polyline of ${count} segments (${count + 1} vertices)`),
        `aria-label: ${label}`,
      );
      assert(
        (await page.locator(".sl-formula").textContent()).includes(String(count)),
        "formula shows the count",
      );
      // The whole curve fails the syllabus test: d₁ = d₂ = |(8,4) × (8,4) − …| = 40/√80 = 4.472 > ε.
      assert(
        (await page.locator(".sl-formula").textContent()).includes("4.472"),
        "formula shows d₁ = 4.472",
      );
    },
  ],
  [
    "lowering the tolerance increases the count (about ×√2 per halving)",
    async (page, h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="tolerance"] .sl-value');
      equal(await box.inputValue(), "0.1", "default tolerance");
      const before = Number((await shown(page, "segments")).split(" ")[0]);
      await box.fill("0.001");
      await box.press("Enter");
      await settle(page);
      const after = Number((await shown(page, "segments")).split(" ")[0]);
      assert(after > before, `count went from ${before} to ${after}`);
      const state = await urlState(page);
      equal(state.tolerance, 0.001, "tolerance in the URL state");
      const [count, half] = await coreCounts(page, state.points, 0.001);
      equal(after, count, "count at ε = 0.001 against the wasm package");
      // Segments ∝ 1/√ε for a smooth curve: halving ε multiplies them by about √2.
      const ratio = half / count;
      assert(ratio > 1.3 && ratio < 1.55, `ratio ${ratio} for ε = 0.001 → 0.0005`);
    },
  ],
  [
    "typed tolerance 0 or “abc” is refused, naming the field; the picture stays",
    async (page, h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="tolerance"] .sl-value');
      const before = await h.snapshot();
      const url = page.url();
      for (const bad of ["0", "abc"]) {
        await box.fill(bad);
        await box.press("Enter");
        await settle(page);
        equal(await h.statusKind(), "error", `status kind after “${bad}”`);
        const status = await h.status();
        assert(
          status.includes("tolerance") && status.includes(bad),
          `status after “${bad}”: ${status}`,
        );
        equal(await box.inputValue(), "0.1", `box after “${bad}”`);
        equal(await h.snapshot(), before, `picture after “${bad}”`);
        equal(page.url(), url, `URL after “${bad}”`);
      }
    },
  ],
  [
    "the loop and cusp presets are a real loop and a real cusp",
    async (page, h, _base, { assert, equal, settle }) => {
      const velocity = (points) =>
        page.evaluate(async (points) => {
          const { loadWasm } = await import("./lib/wasm.js");
          const sl = await loadWasm();
          const curve = new sl.BezierCurve(points.flat(), 2);
          const v = Array.from(curve.derivative(0.5, 1));
          curve.free();
          return v;
        }, points);
      await page.locator('[data-action="preset-cusp"]').click();
      await settle(page);
      const cusp = (await urlState(page)).points;
      // P′(1/2) = 3/4 [(P₁ − P₀) + 2 (P₂ − P₁) + (P₃ − P₂)] = 3/4 [(6, 6) + 2 (−6, 0) + (6, −6)] = 0.
      equal(
        JSON.stringify(cusp),
        JSON.stringify([
          [1, 0],
          [7, 6],
          [1, 6],
          [7, 0],
        ]),
        "cusp points",
      );
      equal(JSON.stringify(await velocity(cusp)), JSON.stringify([0, 0]), "P′(1/2) of the cusp");
      await page.locator('[data-action="preset-loop"]').click();
      await settle(page);
      const loop = (await urlState(page)).points;
      // 3/4 [(9, 6) + 2 (−12, 0) + (9, −6)] = (−4.5, 0): at t = 1/2 the curve runs backwards, a loop.
      equal(JSON.stringify(await velocity(loop)), JSON.stringify([-4.5, 0]), "P′(1/2) of the loop");
      const [count] = await coreCounts(page, loop, 0.1);
      equal(await shown(page, "segments"), `${count} segments`, "count after the preset");
      await page.keyboard.press("Control+z");
      await settle(page);
      equal(
        JSON.stringify((await urlState(page)).points),
        JSON.stringify(cusp),
        "undo goes back to the cusp",
      );
    },
  ],
  [
    "the band toggle is drawn and stored",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      await page.locator('[data-control="band"] input').uncheck();
      await settle(page);
      assert((await h.snapshot()) !== before, "picture unchanged without the band");
      equal((await urlState(page)).band, false, "band in the URL state");
    },
  ],
];
