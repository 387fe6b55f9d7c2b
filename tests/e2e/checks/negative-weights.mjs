// Browser checks specific to the negative-weights demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Weights 1, w₁, 1 on P₀ = (0,0), P₁ = (2,3), P₂ = (4,0). By hand: the denominator
// w(t) = (1−t)² + 2w₁t(1−t) + t² = 1 − 2(1 − w₁)t(1−t) has its minimum (1 + w₁)/2 at t = 1/2, so
// it vanishes on [0, 1] only for w₁ ≤ −1, at t(1−t) = 1/(2(1 − w₁)):
//   w₁ = −0.5: no pole (w(1/2) = 1/4), but P(1/2) = (P₀ + 2w₁P₁ + P₂)/(2 + 2w₁) = P₀ + P₂ − P₁
//              = (2, −3), outside the triangle: the convex hull property is gone;
//   w₁ = −1.5: t(1−t) = 1/5, poles at t = 1/2 ± √5/10;
//   w₁ = −2 (default): t(1−t) = 1/6, poles at t = 1/2 ± √3/6.

async function type(page, settle, name, value) {
  const box = page.locator(`[data-control="${name}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

const poles = (page) => page.locator('[data-info="poles"]');
const hull = (page) => page.locator('[data-info="hull"]');
const poleTs = async (page) =>
  (await poles(page).getAttribute("data-pole-ts")).split(",").filter(Boolean).map(Number);

export default [
  [
    "w₁ = −0.5: the library's message, the hull broken (P(1/2) = (2, −3)), w(t) ≥ 1/4",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "w1", "-0.5");
      equal(await h.statusKind(), "error", "status kind");
      const status = await h.status();
      assert(
        status.includes("weights must be > 0") && status.includes("-0.5"),
        `status: ${status}`,
      );
      assert(
        (await page.locator('[data-info="library"]').textContent()).includes("weights must be > 0"),
        "panel quotes the library",
      );
      equal(await hull(page).getAttribute("data-outside-hull"), "true", "outside the convex hull");
      const [x, y] = (await hull(page).getAttribute("data-middle")).split(",").map(Number);
      assert(
        Math.abs(x - 2) < 1e-12 && Math.abs(y + 3) < 1e-12,
        `P(1/2) = (${x}, ${y}), expected (2, −3)`,
      );
      equal(await poles(page).getAttribute("data-poles"), "0", "no pole above w₁ = −1");
      assert(
        Math.abs(Number(await poles(page).getAttribute("data-min-w")) - 0.25) < 1e-12,
        "min w(t) = 1/4",
      );
    },
  ],
  [
    "w₁ = −1.5: w(t) changes sign twice, poles at t = 1/2 ± √5/10",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "w1", "-1.5");
      assert((await h.status()).includes("weights must be > 0"), `status: ${await h.status()}`);
      equal(await poles(page).getAttribute("data-poles"), "2", "poles");
      const [a, b] = await poleTs(page);
      assert(
        Math.abs(a - (0.5 - Math.sqrt(5) / 10)) < 1e-6 &&
          Math.abs(b - (0.5 + Math.sqrt(5) / 10)) < 1e-6,
        `poles at ${a}, ${b}`,
      );
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("0.276, 0.724"),
        "aria-label names the poles",
      );
      equal(await hull(page).getAttribute("data-outside-hull"), "true", "outside the hull");
    },
  ],
  [
    "the default w₁ = −2 has poles at t = 1/2 ± √3/6",
    async (page, h, _base, { assert, equal }) => {
      equal(await poles(page).getAttribute("data-poles"), "2", "poles");
      const [a, b] = await poleTs(page);
      assert(
        Math.abs(a - (0.5 - Math.sqrt(3) / 6)) < 1e-6 &&
          Math.abs(b - (0.5 + Math.sqrt(3) / 6)) < 1e-6,
        `poles at ${a}, ${b}`,
      );
    },
  ],
  [
    "moving w₁ back to 1 gives the library's curve and no message",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "w1", "1");
      assert((await h.statusKind()) !== "error", "no error in the status line");
      assert(!(await h.status()).includes("weights must be > 0"), `status: ${await h.status()}`);
      equal(
        await page.locator('[data-info="library"]').getAttribute("data-refused"),
        "false",
        "the library accepts",
      );
      equal(await poles(page).getAttribute("data-poles"), "0", "no pole");
      equal(await hull(page).getAttribute("data-outside-hull"), "false", "inside the hull");
      const [x, y] = (await hull(page).getAttribute("data-middle")).split(",").map(Number);
      assert(
        Math.abs(x - 2) < 1e-12 && Math.abs(y - 1.5) < 1e-12,
        `P(1/2) of the parabola = (2, 3/2), got (${x}, ${y})`,
      );
      // Dragging through zero again with the preset button: refused once more.
      await page.locator('[data-action="w1--0.5"]').click();
      await settle(page);
      assert((await h.status()).includes("weights must be > 0"), "refused again at −0.5");
    },
  ],
];
