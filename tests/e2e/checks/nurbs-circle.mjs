// Browser checks specific to the nurbs-circle demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// The syllabus (§4): the full circle is the 9-point NURBS of degree 2 with weights 1, √2/2, …
// and knots 0,0,0,¼,¼,½,½,¾,¾,1,1,1; every sample lies on the circle. An arc is cut into pieces
// of at most 90°: 200° needs ⌈200/90⌉ = 3 pieces of 66.7°, 7 control points, knots
// 0,0,0,⅓,⅓,⅔,⅔,1,1,1 and middle weights cos(100°/3) ≈ 0.835.

async function type(page, settle, name, value) {
  const box = page.locator(`[data-control="${name}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

const count = (page) => page.locator('[data-info="count"]');
const knots = (page) => page.locator('[data-info="knots"]');
const error = async (page) =>
  Number(await page.locator('[data-info="error"]').getAttribute("data-error"));

export default [
  [
    "the full circle has 9 control points, the syllabus' knots and weights, radius error < 1e-12",
    async (page, h, _base, { assert, equal }) => {
      equal(await count(page).getAttribute("data-points"), "9", "control points");
      equal(await count(page).getAttribute("data-pieces"), "4", "pieces");
      equal(
        await knots(page).getAttribute("data-knots"),
        "0 0 0 1/4 1/4 1/2 1/2 3/4 3/4 1 1 1",
        "knots",
      );
      const weights = await page.locator('.sl-table td[data-column="weight"]').allTextContents();
      equal(weights.join(" "), "1 √2/2 1 √2/2 1 √2/2 1 √2/2 1", "weights");
      const e = await error(page);
      assert(e < 1e-12, `radius error ${e}`);
      const shown = await page.locator('[data-info="error"]').textContent();
      assert(
        /radius error (0|\d\.\de-1[5-7])$/.test(shown),
        `the readout prints the error to print precision: ${shown}`,
      );
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("9 control points"),
        "aria-label",
      );
    },
  ],
  [
    "a 200° arc has 3 pieces, knots in thirds, middle weights cos(100°/3), radius error < 1e-12",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "sweep", "200");
      equal(await count(page).getAttribute("data-pieces"), "3", "pieces");
      equal(await count(page).getAttribute("data-points"), "7", "control points");
      equal(await knots(page).getAttribute("data-knots"), "0 0 0 1/3 1/3 2/3 2/3 1 1 1", "knots");
      const weights = await page.locator('.sl-table td[data-column="weight"]').allTextContents();
      equal(weights[1], Math.cos(((100 / 3) * Math.PI) / 180).toFixed(3), "middle weight");
      assert((await error(page)) < 1e-12, `radius error ${await error(page)}`);
      // A clockwise 30° arc: one piece, weights 1, cos 15°, 1.
      await type(page, settle, "sweep", "-30");
      equal(await count(page).getAttribute("data-pieces"), "1", "pieces of −30°");
      assert((await error(page)) < 1e-12, "−30° arc on the circle");
    },
  ],
  [
    "a radius of 0 or −1 is refused, naming the field",
    async (page, h, _base, { assert, equal, settle }) => {
      const label = await h.canvas().getAttribute("aria-label");
      for (const bad of ["0", "-1"]) {
        await type(page, settle, "radius", bad);
        equal(await h.statusKind(), "error", `status kind after ${bad}`);
        const status = await h.status();
        assert(
          status.includes("radius") && status.includes("> 0"),
          `status after ${bad}: ${status}`,
        );
        equal(
          await page.locator('[data-control="radius"] .sl-value').inputValue(),
          "2.000",
          `radius box after ${bad}`,
        );
      }
      equal(await h.canvas().getAttribute("aria-label"), label, "picture kept");
      // A zero sweep is the library's refusal (its message names the sweep).
      await type(page, settle, "sweep", "0");
      assert((await h.status()).includes("sweep"), `status after sweep 0: ${await h.status()}`);
      equal(await count(page).getAttribute("data-pieces"), "4", "the circle stays");
    },
  ],
  [
    "the ellipse mode is exact too (same weights and knots)",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="ellipse"] input').check();
      await settle(page);
      await type(page, settle, "rotation", "30");
      equal(await count(page).getAttribute("data-points"), "9", "control points");
      equal(
        await knots(page).getAttribute("data-knots"),
        "0 0 0 1/4 1/4 1/2 1/2 3/4 3/4 1 1 1",
        "knots",
      );
      assert((await error(page)) < 1e-12, `ellipse error ${await error(page)}`);
      assert(
        (await h.canvas().getAttribute("aria-label")).includes(
          "ellipse with semi-axes 3.00 and 2.00",
        ),
        "aria-label",
      );
    },
  ],
  [
    "dragging the centre keeps the circle exact",
    async (page, h, _base, { assert, equal, settle }) => {
      const [centre] = await h.handles();
      await h.drag(centre, 37, -23);
      assert((await error(page)) < 1e-12, `radius error after the drag ${await error(page)}`);
      assert(
        !(await h.canvas().getAttribute("aria-label")).includes("about (0.00, 0.00)"),
        "the centre moved",
      );
    },
  ],
];
