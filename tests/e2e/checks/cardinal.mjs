// Browser checks specific to the cardinal / Catmull–Rom demo (run after the generic ones).
// Hand-computed from the default points P₀ = (0, 0), P₁ = (6, 8), P₂ = (7, 8), P₃ = (13, 0):
// - centripetal (α = ½): t₁ = |P₁ − P₀|^½ = 10^½ ≈ 3.162, t₂ = t₁ + 1 ≈ 4.162; with d₀ = √10,
//   d₁ = 1 Barry–Goldman's m₁ = (6, 8)/√10 − (7, 8)/(√10 + 1) + (1, 0)
//   = (1.897367 − 1.681760 + 1, 2.529822 − 1.922025) ≈ (1.216, 0.608);
// - uniform (α = 0): m₁ = (P₂ − P₀)/2 = (7/2, 4), m₂ = (P₃ − P₁)/2 = (7/2, −4); the Bézier points
//   q₁ = P₁ + m₁/3 = (43/6, 28/3) and q₂ = P₂ − m₂/3 = (35/6, 28/3) cross, so segment 1 loops;
//   the matrix form at t = 1/2: [1/8 1/4 1/2 1]·M = (−1/16, 9/16, 9/16, −1/16), so
//   P(1/2) = (−0 + 54 + 63 − 13, −0 + 72 + 72 − 0)/16 = (13/2, 9);
// - cardinal, c = 1/2, t_i = i: m₁ = (1 − 1/2)(P₂ − P₀)/2 = (7/4, 2).
const tangent = (page, i) =>
  page.locator(`[data-table="tangents"] tr[data-index="${i}"] td[data-cell="tangent"]`);
const param = (page, i) =>
  page.locator(`[data-table="tangents"] tr[data-index="${i}"] td[data-cell="param"]`);

async function typeValue(page, control, value, settle) {
  const box = page.locator(`[data-control="${control}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

export default [
  [
    "centripetal parameters t₁ = √10 ≈ 3.162, t₂ ≈ 4.162 and tangent m₁ ≈ (1.216, 0.608)",
    async (page, _h, _base, { equal }) => {
      equal(await param(page, 1).textContent(), "3.162", "t₁");
      equal(await param(page, 2).textContent(), "4.162", "t₂");
      equal(await tangent(page, 1).textContent(), "(1.216, 0.608)", "centripetal m₁");
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
    "uniform Catmull–Rom tangents m₁ = (7/2, 4), m₂ = (7/2, −4) and P(1/2) = (13/2, 9)",
    async (page, _h, _base, { assert, equal, settle }) => {
      await typeValue(page, "alpha", "0", settle);
      equal(await tangent(page, 1).textContent(), "(7/2, 4)", "m₁");
      equal(await tangent(page, 2).textContent(), "(7/2, -4)", "m₂");
      const formula = await page.locator(".sl-formula").textContent();
      // KaTeX keeps the TeX source in the MathML annotation.
      assert(formula.includes("(\\tfrac{13}{2},\\ 9)"), `P(1/2) = (13/2, 9) in ${formula}`);
    },
  ],
  [
    "cardinal with tension c = 1/2: m₁ = (7/4, 2), no loop",
    async (page, _h, _base, { equal, settle }) => {
      await page.locator('[data-control="mode"] [data-choice="cardinal"] input').check();
      await settle(page);
      await typeValue(page, "tension", "0.5", settle);
      equal(await tangent(page, 1).textContent(), "(7/4, 2)", "m₁");
      equal(await page.locator('[data-info="loop"]').getAttribute("data-loop"), "none", "loop");
    },
  ],
];
