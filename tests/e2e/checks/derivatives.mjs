// Browser checks specific to the derivatives demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers by hand from the syllabus (§2 Derivatives): for the worked example
// P0=(0,0), P1=(2,2), P2=(6,4), P3=(8,2): P′(0) = 3(P1 − P0) = (6, 6), P′(1) = 3(P3 − P2) = (6, −6),
// hodograph points 3(P_{i+1} − P_i) = (6,6), (12,6), (6,−6); P′(3/4) = 3[1/16 (2,2) + 6/16 (4,2) + 9/16 (2,−2)]
// = (33/4, −3/4). The parabola P0=(−1,1), P1=(0,−1), P2=(1,1) is y = x²: at t = 1/2, P′ = (2, 0),
// P″ = 2(P2 − 2P1 + P0) = (0, 8), κ = (2·8 − 0·0)/2³ = 2.

/** A table cell by its data-quantity key. */
const cell = (page, key) =>
  page.locator(`[data-table="derivatives"] td[data-quantity="${key}"]`).textContent();

/** Types t into the slider's box and presses Enter. */
async function setT(page, value) {
  const box = page.locator('[data-control="t"] .sl-value');
  await box.fill(String(value));
  await box.press("Enter");
}

const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

export default [
  [
    "worked example: P′(0) = (6, 6), P′(1) = (6, −6), P′(3/4) = (33/4, −3/4)",
    async (page, h, _base, { assert, equal, settle }) => {
      equal(await cell(page, "dp"), "(8.250, -0.750)", "P′(3/4)");
      equal(await cell(page, "dp0"), "(6, 6)", "P′(0) row");
      equal(await cell(page, "dp1"), "(6, -6)", "P′(1) row");
      await setT(page, "0");
      await settle(page);
      equal(await cell(page, "dp"), "(6, 6)", "P′(t) at t = 0");
      equal(await cell(page, "ddp"), "(12, 0)", "P″(0) = 6(P2 − 2P1 + P0)");
      await setT(page, "1");
      await settle(page);
      equal(await cell(page, "dp"), "(6, -6)", "P′(t) at t = 1");
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("(6.00, -6.00)"), `aria-label: ${label}`);
    },
  ],
  [
    "the hodograph's control points are n(P_{i+1} − P_i)",
    async (page, _h, _base, { equal }) => {
      const cells = await page
        .locator('[data-table="derivatives"] td[data-hodograph]')
        .allTextContents();
      equal(
        JSON.stringify(cells),
        JSON.stringify(["(6, 6)", "(12, 6)", "(6, -6)"]),
        "hodograph control points",
      );
    },
  ],
  [
    "the parabola y = x² has κ = 2 at its vertex; mirrored, κ = −2",
    async (page, h, base, { assert, equal, openDemo }) => {
      h = await openDemo(
        page,
        base,
        "derivatives",
        link({
          points: [
            [-1, 1],
            [0, -1],
            [1, 1],
          ],
          t: 0.5,
          hodographOrigin: [3, 0],
        }),
      );
      equal(await cell(page, "point"), "(0.000, 0.000)", "P(1/2)");
      equal(await cell(page, "dp"), "(2, 0)", "P′(1/2)");
      equal(await cell(page, "ddp"), "(0, 8)", "P″(1/2)");
      equal(await cell(page, "kappa"), "2.000", "κ(1/2)");
      equal(await cell(page, "radius"), "0.500", "radius 1/κ");
      equal(
        await page.locator('[data-info="curvature"]').getAttribute("data-kappa"),
        "2.000",
        "readout",
      );
      h = await openDemo(
        page,
        base,
        "derivatives",
        link({
          points: [
            [-1, -1],
            [0, 1],
            [1, -1],
          ],
          t: 0.5,
          hodographOrigin: [3, 0],
        }),
      );
      equal(await cell(page, "kappa"), "-2.000", "κ of the mirrored parabola");
      assert(
        (await page.locator('[data-info="radius"]').textContent()).includes("right"),
        "centre on the right when κ < 0",
      );
    },
  ],
  [
    "the worked example turns clockwise at t = 0 (κ = −1/(6√2) ≈ −0.118); mirrored it turns the other way",
    async (page, h, base, { equal, openDemo }) => {
      // κ(0) = (6·0 − 6·12)/|(6,6)|³ = −72/(6√2)³ = −1/(6√2).
      h = await openDemo(
        page,
        base,
        "derivatives",
        link({
          points: [
            [0, 0],
            [2, 2],
            [6, 4],
            [8, 2],
          ],
          t: 0,
          hodographOrigin: [11, 2],
        }),
      );
      equal(await cell(page, "kappa"), "-0.118", "κ(0)");
      h = await openDemo(
        page,
        base,
        "derivatives",
        link({
          points: [
            [0, 0],
            [2, -2],
            [6, -4],
            [8, -2],
          ],
          t: 0,
          hodographOrigin: [11, -2],
        }),
      );
      equal(await cell(page, "kappa"), "0.118", "κ(0) mirrored");
    },
  ],
  [
    "a straight curve says so instead of drawing a circle",
    async (page, h, base, { assert, equal, openDemo }) => {
      h = await openDemo(
        page,
        base,
        "derivatives",
        link({
          points: [
            [0, 0],
            [1, 1],
            [3, 3],
          ],
          t: 0.5,
          hodographOrigin: [5, 0],
        }),
      );
      equal(await cell(page, "radius"), "∞", "radius");
      assert(
        (await page.locator('[data-info="radius"]').textContent()).includes("Straight here"),
        "readout says straight",
      );
    },
  ],
];
