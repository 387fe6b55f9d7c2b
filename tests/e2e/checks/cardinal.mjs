// Browser checks specific to the cardinal / Catmull–Rom demo (run after the generic ones).
// Hand-computed from the default points P₀ = (0, 0), P₁ = (8, 6), P₂ = (9, 6), P₃ = (17, 0):
// - centripetal (α = ½): t₁ = |P₁ − P₀|^½ = 10^½ ≈ 3.162, t₂ = t₁ + 1 ≈ 4.162;
// - uniform (α = 0): m₁ = (P₂ − P₀)/2 = (9/2, 3), m₂ = (P₃ − P₁)/2 = (9/2, −3); the Bézier points
//   q₁ = P₁ + m₁/3 = (19/2, 7) and q₂ = P₂ − m₂/3 = (15/2, 7) cross, so segment 1 loops;
//   the matrix form at t = 1/2: [1/8 1/4 1/2 1]·M = (−1/16, 9/16, 9/16, −1/16), so
//   P(1/2) = (−0 + 72 + 81 − 17, 0 + 54 + 54 − 0)/16 = (17/2, 27/4);
// - cardinal, c = 1/2, t_i = i: m₁ = (1 − 1/2)(P₂ − P₀)/2 = (9/4, 3/2).
const tangent = (page, i) => page.locator(`[data-table="tangents"] tr[data-index="${i}"] td[data-cell="tangent"]`);
const param = (page, i) => page.locator(`[data-table="tangents"] tr[data-index="${i}"] td[data-cell="param"]`);

async function typeValue(page, control, value, settle) {
  const box = page.locator(`[data-control="${control}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

export default [
  [
    "centripetal parameters: t₁ = √10 ≈ 3.162, t₂ ≈ 4.162",
    async (page, _h, _base, { equal }) => {
      equal(await param(page, 1).textContent(), "3.162", "t₁");
      equal(await param(page, 2).textContent(), "4.162", "t₂");
    },
  ],
  [
    "the uniform curve loops in segment 1 (dashed ghost), centripetal does not",
    async (page, _h, _base, { equal, settle }) => {
      const loop = page.locator('[data-info="loop"]');
      equal(await loop.getAttribute("data-loop"), "1", "ghost's loop");
      await typeValue(page, "alpha", "0", settle);
      equal(await loop.getAttribute("data-loop"), "1", "α = 0 itself");
      await typeValue(page, "alpha", "1", settle);
      equal(await loop.getAttribute("data-loop"), "1", "still the ghost's");
    },
  ],
  [
    "uniform Catmull–Rom tangents m₁ = (9/2, 3), m₂ = (9/2, −3) and P(1/2) = (17/2, 27/4)",
    async (page, _h, _base, { assert, equal, settle }) => {
      await typeValue(page, "alpha", "0", settle);
      equal(await tangent(page, 1).textContent(), "(9/2, 3)", "m₁");
      equal(await tangent(page, 2).textContent(), "(9/2, -3)", "m₂");
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("172") && formula.includes("274"), `P(1/2) = (17/2, 27/4) in ${formula}`);
    },
  ],
  [
    "cardinal with tension c = 1/2: m₁ = (9/4, 3/2), no loop",
    async (page, _h, _base, { equal, settle }) => {
      await page.locator('[data-control="mode"] [data-choice="cardinal"] input').check();
      await settle(page);
      await typeValue(page, "tension", "0.5", settle);
      equal(await tangent(page, 1).textContent(), "(9/4, 3/2)", "m₁");
      equal(await page.locator('[data-info="loop"]').getAttribute("data-loop"), "none", "loop");
    },
  ],
];
