// Browser checks specific to the weights demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Default: P = (0,0), (1,3), (4,3), (5,0), weights 1, 3, 1, 1, t = 1/2. By hand (syllabus §4,
// P(t) = Σ Bᵢ wᵢ Pᵢ / Σ Bᵢ wᵢ with B = 1/8, 3/8, 3/8, 1/8 at t = 1/2):
//   all wᵢ = 1:  P(1/2) = ((0 + 3 + 12 + 5)/8, (0 + 9 + 9 + 0)/8) = (5/2, 9/4), |P − P₁| = √(1.5² + 0.75²)
//   w₁ = 3:      P(1/2) = ((9 + 12 + 5)/14, (27 + 9)/14) = (13/7, 18/7), |P − P₁| = √45 / 7
//   w₁ = 10:     P(1/2) = ((30 + 12 + 5)/35, (90 + 9)/35) = (47/35, 99/35), |P − P₁| = √180 / 35

/** Types a value into a slider's box (data-control name) and confirms it. */
async function type(page, settle, name, value) {
  const box = page.locator(`[data-control="${name}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

const readout = (page) => page.locator('[data-info="curve"]');
async function pointAt(page) {
  return (await readout(page).getAttribute("data-point")).split(",").map(Number);
}
async function distanceToP1(page) {
  return Number(
    await page
      .locator('.sl-table tr[data-index="1"] td[data-column="distance"]')
      .getAttribute("data-value"),
  );
}
const close = (a, b, tolerance = 1e-12) => Math.abs(a - b) <= tolerance;

export default [
  [
    "all weights 2 give the same curve as all weights 1 (only ratios matter)",
    async (page, h, _base, { assert, equal, settle }) => {
      for (let i = 0; i < 4; i++) await type(page, settle, `weight-${i}`, "2");
      const twos = await pointAt(page);
      const gapTwos = Number(await readout(page).getAttribute("data-max-gap"));
      await page.locator('[data-action="weights-one"]').click();
      await settle(page);
      const ones = await pointAt(page);
      equal(
        await page.locator('[data-control="weight-1"] .sl-value').inputValue(),
        "1",
        "w₁ after “All weights 1”",
      );
      assert(
        close(twos[0], ones[0]) && close(twos[1], ones[1]),
        `P(1/2) with all 2: ${twos}, with all 1: ${ones}`,
      );
      assert(
        close(ones[0], 5 / 2) && close(ones[1], 9 / 4),
        `P(1/2) with all 1 should be (5/2, 9/4), got ${ones}`,
      );
      // Equal weights: the rational curve is the polynomial one at every sample.
      assert(gapTwos <= 1e-12, `all 2: largest distance from the polynomial curve ${gapTwos}`);
      assert(
        Number(await readout(page).getAttribute("data-max-gap")) <= 1e-12,
        "all 1: the curves coincide",
      );
      // And the × 2 button (every weight doubled) leaves the default curve where it was.
      await page.locator('[data-action="reset"]').click();
      await settle(page);
      const before = await pointAt(page);
      await page.locator('[data-action="weights-scale"]').click();
      await settle(page);
      equal(
        await page.locator('[data-control="weight-1"] .sl-value').inputValue(),
        "6",
        "w₁ after × 2",
      );
      const after = await pointAt(page);
      assert(
        close(before[0], after[0]) && close(before[1], after[1]),
        `× 2 moved P(1/2) from ${before} to ${after}`,
      );
    },
  ],
  [
    "raising w₁ pulls P(1/2) toward P₁ (distances by hand)",
    async (page, h, _base, { assert, equal, settle }) => {
      const at3 = await distanceToP1(page);
      const p3 = await pointAt(page);
      assert(
        close(p3[0], 13 / 7) && close(p3[1], 18 / 7),
        `P(1/2) at w₁ = 3 should be (13/7, 18/7), got ${p3}`,
      );
      assert(close(at3, Math.sqrt(45) / 7), `|P(1/2) − P₁| at w₁ = 3: ${at3}, expected √45/7`);
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("(1.86, 2.57)"),
        "aria-label gives P(1/2) = (1.86, 2.57)",
      );
      await type(page, settle, "weight-1", "1");
      const at1 = await distanceToP1(page);
      assert(close(at1, Math.hypot(1.5, 0.75)), `|P(1/2) − P₁| at w₁ = 1: ${at1}`);
      await type(page, settle, "weight-1", "10");
      const at10 = await distanceToP1(page);
      assert(
        close(at10, Math.sqrt(180) / 35),
        `|P(1/2) − P₁| at w₁ = 10: ${at10}, expected √180/35`,
      );
      assert(at1 > at3 && at3 > at10, `distance should fall as w₁ rises: ${at1}, ${at3}, ${at10}`);
      // The other points' distances grow: the pull is toward P₁ only.
      const toP3 = Number(
        await page
          .locator('.sl-table tr[data-index="3"] td[data-column="distance"]')
          .getAttribute("data-value"),
      );
      assert(toP3 > 3.5, `|P(1/2) − P₃| at w₁ = 10 should be large, got ${toP3}`);
    },
  ],
  [
    "a typed weight of 0 or −1 is refused, naming the weight",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await pointAt(page);
      for (const bad of ["0", "-1"]) {
        await type(page, settle, "weight-1", bad);
        equal(await h.statusKind(), "error", `status kind after ${bad}`);
        const status = await h.status();
        assert(
          status.includes("w₁") && status.includes("> 0") && status.includes(bad),
          `status after ${bad}: ${status}`,
        );
        equal(
          await page.locator('[data-control="weight-1"] .sl-value').inputValue(),
          "3",
          `the box shows the kept weight after ${bad}`,
        );
      }
      const after = await pointAt(page);
      assert(close(before[0], after[0]) && close(before[1], after[1]), "the curve is unchanged");
    },
  ],
  [
    "a link with a negative weight names the weight",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 3],
            [4, 3],
            [5, 0],
          ],
          weights: [1, -1, 1, 1],
          t: 0.5,
          homogeneous: true,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "weights", `&s=${state}`);
      const status = await h.status();
      assert(status.includes("w₁") && status.includes("weights must be > 0"), `status: ${status}`);
    },
  ],
];
