// Browser checks specific to the conics demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Rational quadratic with weights 1, w₁, 1 (syllabus §4): shape factor k = w₁², an ellipse for
// k < 1, a parabola for k = 1, a hyperbola for k > 1. Circular arc: isosceles triangle and
// w₁ = sin θ, θ half the angle at P₁. For P₀ = (1,0), P₁ = (1,1), P₂ = (0,1): the angle is 90°,
// w₁ = sin 45° = √2/2 and the arc is the unit circle about the origin. For the default triangle
// (0,0), (2,3), (4,0): cos 2θ = 5/13, so sin θ = √((1 − 5/13)/2) = 2/√13.

async function type(page, settle, name, value) {
  const box = page.locator(`[data-control="${name}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

const kind = (page) => page.locator('[data-info="kind"]');
const circleInfo = (page) => page.locator('[data-info="circle"]');

export default [
  [
    "w₁ = 0.5, 1, 2 read ellipse, parabola, hyperbola",
    async (page, h, _base, { assert, equal, settle }) => {
      for (const [w, name, factor] of [
        ["0.5", "ellipse", 0.25],
        ["1", "parabola", 1],
        ["2", "hyperbola", 4],
      ]) {
        await type(page, settle, "w1", w);
        equal(await kind(page).getAttribute("data-kind"), name, `kind at w₁ = ${w}`);
        assert((await kind(page).textContent()).startsWith(name), `readout at w₁ = ${w}`);
        equal(
          Number(await page.locator('[data-info="shape"]').getAttribute("data-factor")),
          factor,
          `shape factor at w₁ = ${w}`,
        );
        equal(
          await page.locator(`.sl-table td[data-kind="${name}"]`).getAttribute("class"),
          "sl-highlight",
          `table row of ${name}`,
        );
        assert(
          (await h.canvas().getAttribute("aria-label")).includes(name),
          `aria-label names the ${name}`,
        );
      }
    },
  ],
  [
    "the circle button on (1,0), (1,1), (0,1) sets w₁ = 0.707 and every sample is at distance 1 from the origin",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [1, 0],
            [1, 1],
            [0, 1],
          ],
          w1: 0.5,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "conics", `&s=${state}`);
      equal(
        await circleInfo(page).getAttribute("data-circle"),
        "false",
        "not circular at w₁ = 0.5",
      );
      await page.locator('[data-action="make-circular"]').click();
      await settle(page);
      equal(await page.locator('[data-control="w1"] .sl-value').inputValue(), "0.707", "w₁ box");
      equal(await circleInfo(page).getAttribute("data-circle"), "true", "circular");
      const error = Number(await circleInfo(page).getAttribute("data-radius-error"));
      assert(error < 1e-12, `max | |P(t)| − 1 | = ${error}`);
      assert((await kind(page).textContent()).includes("circle!"), "the readout says circle!");
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("radius 1.00 about (0.00, 0.00)"),
        "aria-label: unit circle about the origin",
      );
      equal(await kind(page).getAttribute("data-kind"), "ellipse", "a circle is an ellipse");
    },
  ],
  [
    "make circular on the default triangle gives w₁ = 2/√13; moving P₂ ends the circle",
    async (page, h, _base, { assert, equal, settle }) => {
      const sin = Number(await page.locator('[data-info="triangle"]').getAttribute("data-sin"));
      assert(Math.abs(sin - 2 / Math.sqrt(13)) < 1e-12, `sin θ = ${sin}, expected 2/√13`);
      await page.locator('[data-action="make-circular"]').click();
      await settle(page);
      equal(
        await page.locator('[data-control="w1"] .sl-value').inputValue(),
        "0.555",
        "w₁ = 2/√13 ≈ 0.555",
      );
      equal(await circleInfo(page).getAttribute("data-circle"), "true", "circular");
      assert(
        Number(await circleInfo(page).getAttribute("data-radius-error")) < 1e-12,
        "on the circle",
      );
      await h.canvas().focus();
      await page.keyboard.press("End"); // P₂
      await page.keyboard.press("Shift+ArrowRight");
      await settle(page);
      equal(
        await circleInfo(page).getAttribute("data-circle"),
        "false",
        "not circular after moving P₂",
      );
      assert(
        !(await kind(page).textContent()).includes("circle!"),
        "the readout no longer says circle!",
      );
    },
  ],
  [
    "a typed w₁ of 0 is refused, naming w₁",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "w1", "0");
      equal(await h.statusKind(), "error", "status kind");
      assert((await h.status()).includes("w₁"), `status: ${await h.status()}`);
      equal(await kind(page).getAttribute("data-kind"), "ellipse", "the default ellipse stays");
    },
  ],
];
