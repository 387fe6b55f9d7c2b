// Browser checks specific to the parametrisation demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Expected numbers are worked out by hand in the comments (never by the code under test).

const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;
/** The texts of one row of the parameter table (`data-kind`). */
const row = (page, kind) =>
  page
    .locator(`table[data-table="parametrization"] tr[data-kind="${kind}"] td`)
    .allTextContents()
    .then((cells) => cells.map((c) => c.trim()));

export default [
  [
    "default: the legs and the three parametrisations, worked by hand",
    async (page, _h, _base, { equal }) => {
      // Points (0,0) (3,4) (4,4) (4,3) (8,0) (9,0): legs |(3,4)| = 5, |(1,0)| = 1, |(0,−1)| = 1,
      // |(4,−3)| = 5, |(1,0)| = 1. Uniform: 0 … 5. Chord: 0, 5, 6, 7, 12, 13.
      // Centripetal: 0, √5, √5 + 1, √5 + 2, 2√5 + 2, 2√5 + 3 with √5 ≈ 2.2360680.
      equal((await row(page, "legs")).join(" "), "5 1 1 5 1 ", "legs");
      equal((await row(page, "uniform")).join(" "), "0 1 2 3 4 5", "uniform");
      equal((await row(page, "chord")).join(" "), "0 5 6 7 12 13", "chord");
      equal(
        (await row(page, "centripetal")).join(" "),
        "0 2.236 3.236 4.236 6.472 7.472",
        "centripetal",
      );
      // α = 1/4: 5^(1/4) ≈ 1.4953488; t = 0, 1.495, 2.495, 3.495, 4.991, 5.991.
      equal((await row(page, "alpha")).join(" "), "0 1.495 2.495 3.495 4.991 5.991", "α = 1/4");
    },
  ],
  [
    "α = 0.5 is centripetal, α = 1 is chord length",
    async (page, _h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="alpha"] .sl-value');
      await box.fill("0.5");
      await box.press("Enter");
      await settle(page);
      equal(
        (await row(page, "alpha")).join(" "),
        (await row(page, "centripetal")).join(" "),
        "α = 1/2",
      );
      assert(
        (await page.locator('[data-info="alpha"]').textContent()).includes("centripetal"),
        "the note names centripetal",
      );
      await box.fill("1");
      await box.press("Enter");
      await settle(page);
      equal((await row(page, "alpha")).join(" "), "0 5 6 7 12 13", "α = 1");
      assert((await page.locator(".sl-formula").textContent()).includes("chord"), "formula");
    },
  ],
  [
    "the speed plot and the point at s follow the s slider; steps of 1/16",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      await page.locator('[data-action="step"]').click();
      await settle(page);
      equal(await page.locator('[data-control="s"] .sl-value').inputValue(), "0.563", "s = 9/16");
      assert((await h.snapshot()) !== before, "the marker moved");
      // At s = 0 every curve is at p₀ = (0, 0): the aria label says so for all three.
      await page.locator('[data-control="s"] .sl-value').fill("0");
      await page.locator('[data-control="s"] .sl-value').press("Enter");
      await settle(page);
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.split("(0.00, 0.00)").length === 4, `aria-label: ${label}`);
    },
  ],
  [
    "Catmull–Rom keeps the parameters and changes the curves",
    async (page, h, _base, { equal, assert, settle }) => {
      const before = await h.snapshot();
      await page.locator('[data-control="method"] [data-choice="catmull-rom"] input').check();
      await settle(page);
      assert((await h.snapshot()) !== before, "picture changed");
      equal((await row(page, "chord")).join(" "), "0 5 6 7 12 13", "chord");
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("Catmull"), `aria-label: ${label}`);
    },
  ],
  [
    "a repeated point is refused under chord spacing, with a message, keeping the picture",
    async (page, h, base, { assert, openDemo }) => {
      const state = {
        points: [
          [0, 0],
          [1, 1],
          [1, 1],
          [2, 0],
        ],
        method: "cubic",
        alpha: 0.25,
        alphaCurve: true,
        s: 0.5,
      };
      h = await openDemo(page, base, "parametrization", link(state));
      assert((await h.statusKind()) === "error", "status kind");
      assert((await h.status()).length > 10, `status: ${await h.status()}`);
    },
  ],
  [
    "α outside [0, 1] in a link names the field",
    async (page, h, base, { assert, openDemo }) => {
      const state = {
        points: [
          [0, 0],
          [1, 1],
          [2, 0],
        ],
        method: "cubic",
        alpha: 2,
        alphaCurve: true,
        s: 0.5,
      };
      h = await openDemo(page, base, "parametrization", link(state));
      const status = await h.status();
      assert(/“alpha”/.test(status) && status.includes("2"), `status: ${status}`);
    },
  ],
  [
    "a press in the speed plot sets s, snapped to a sixteenth",
    async (page, h, _base, { equal, settle }) => {
      // The plot's box runs from 50 px to width − 24 px (speed-plot.js margins); press at a
      // quarter of it, inside the tick rows (30 px above the canvas bottom).
      const box = await h.canvas().boundingBox();
      const x = box.x + 50 + (box.width - 50 - 24) / 4;
      await page.mouse.click(x + 1, box.y + box.height - 40);
      await settle(page);
      equal(await page.locator('[data-control="s"] .sl-value').inputValue(), "0.250", "s");
    },
  ],
];
