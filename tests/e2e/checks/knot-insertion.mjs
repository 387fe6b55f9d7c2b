// Browser checks specific to the knot-insertion demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Default: the Croatian quadratic, p = 2, U = [0,0,0,1,2,3,4,4,4], points P₀ … P₅ =
// (0,0) (1,4) (4,5) (6,1) (9,2) (10,5), shown after inserting 1.5 (u = 2.5 ready). By hand for s = 1.5 ∈ [u₃, u₄) = [1, 2), k = 3:
// α₂ = (1.5 − u₂)/(u₄ − u₂) = 1.5/2 = 3/4, α₃ = (1.5 − u₃)/(u₅ − u₃) = 0.5/2 = 1/4;
// Q₂ = ¼P₁ + ¾P₂ = (3.25, 4.75), Q₃ = ¾P₂ + ¼P₃ = (4.5, 4).

const info = (page, name) => page.locator(`[data-info="${name}"]`);
const curveSum = async (page) => Number(await info(page, "count").getAttribute("data-curve-sum"));

async function typeU(page, settle, value) {
  const box = page.locator('[data-control="u"] .sl-value');
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

export default [
  [
    "inserting 1.5 into the Croatian example: knots, α = 3/4 and 1/4, Q₂ and Q₃, same curve",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-action="reset-knots"]').click();
      await settle(page);
      equal(
        await info(page, "knots-before").getAttribute("data-knots"),
        "0,0,0,1,2,3,4,4,4",
        "knots at the start",
      );
      const before = await curveSum(page);
      await typeU(page, settle, "3/2");
      await page.locator('[data-action="insert"]').click();
      await settle(page);
      equal(
        await info(page, "knots-after").getAttribute("data-knots"),
        "0,0,0,1,1.5,2,3,4,4,4",
        "knots after",
      );
      equal(
        await info(page, "knots-before").getAttribute("data-knots"),
        "0,0,0,1,2,3,4,4,4",
        "knots before",
      );
      equal(await info(page, "alphas").getAttribute("data-alphas"), "0.75,0.25", "α values");
      const alphas = await info(page, "alphas").textContent();
      assert(
        alphas.includes("α₂ = 3/4") && alphas.includes("α₃ = 1/4") && alphas.includes("0.750"),
        `α text: ${alphas}`,
      );
      equal(
        await info(page, "count").getAttribute("data-points"),
        "7",
        "points after one insertion",
      );
      equal(
        await page.locator('.sl-table td[data-index="2"]').textContent(),
        "(3.250, 4.750)",
        "Q₂",
      );
      equal(
        await page.locator('.sl-table td[data-index="3"]').textContent(),
        "(4.500, 4.000)",
        "Q₃",
      );
      equal(
        await page.locator('.sl-table td[data-index="6"]').textContent(),
        "(10.000, 5.000)",
        "Q₆ = P₅",
      );
      const after = await curveSum(page);
      assert(
        Math.abs(after - before) <= 1e-9 * Math.max(1, Math.abs(before)),
        `curve samples changed: ${before} → ${after}`,
      );
      assert(
        (await page.locator(".sl-formula").textContent()).includes("α") ||
          (await page.locator(".sl-formula .katex").count()) >= 3,
        "formula typeset",
      );
      // Undo and redo replay the insertion from the stored list.
      await page.keyboard.press("Control+z");
      await settle(page);
      equal(await info(page, "count").getAttribute("data-knots"), "9", "knots after undo");
      await page.keyboard.press("Control+Shift+z");
      await settle(page);
      equal(
        await info(page, "knots-after").getAttribute("data-knots"),
        "0,0,0,1,1.5,2,3,4,4,4",
        "knots after redo",
      );
    },
  ],
  [
    "clicking the curve inserts the picked parameter; the curve stays",
    async (page, h, _base, { assert, equal, settle }) => {
      // C(2) = (P₂ + P₃)/2 for this knot vector (N₂,₂(2) = N₃,₂(2) = 1/2): click there.
      const handles = await h.handles();
      const target = { x: (handles[2].x + handles[3].x) / 2, y: (handles[2].y + handles[3].y) / 2 };
      const before = await curveSum(page);
      await page.mouse.click(target.x, target.y);
      await settle(page);
      const inserted = (await info(page, "inserted").textContent()).split(",").pop().trim();
      assert(Math.abs(Number(inserted) - 2) < 0.05, `inserted ${inserted}, expected ≈ 2`);
      equal(
        await info(page, "count").getAttribute("data-knots"),
        "11",
        "one knot more (after the default 1.5)",
      );
      const after = await curveSum(page);
      assert(
        Math.abs(after - before) <= 1e-9 * Math.max(1, Math.abs(before)),
        `curve samples changed: ${before} → ${after}`,
      );
      // "Halve every span" three times: 10 → … more points, the curve still the same.
      for (let k = 0; k < 3; k++) await page.locator('[data-action="refine-all"]').click();
      await settle(page);
      assert(
        Number(await info(page, "count").getAttribute("data-points")) > 30,
        "many points after refinement",
      );
      const refined = await curveSum(page);
      assert(
        Math.abs(refined - before) <= 1e-9 * Math.max(1, Math.abs(before)),
        `curve changed by refinement: ${before} → ${refined}`,
      );
      await page.locator('[data-action="reset-knots"]').click();
      await settle(page);
      equal(
        await info(page, "count").getAttribute("data-knots"),
        "9",
        "back to the original knots",
      );
    },
  ],
  [
    "Bézier extraction: one segment per non-empty span (5, then 6; a repeated knot adds none)",
    async (page, _h, _base, { equal, settle }) => {
      await page.locator('[data-control="bezier"] input').check();
      await settle(page);
      equal(
        await info(page, "segments").getAttribute("data-segments"),
        "5",
        "default curve: spans [0,1] [1,1.5] [1.5,2] [2,3] [3,4]",
      );
      await page.locator('[data-action="insert"]').click(); // u = 2.5
      await settle(page);
      equal(await info(page, "segments").getAttribute("data-segments"), "6", "after inserting 2.5");
      await page.locator('[data-action="insert"]').click(); // 2.5 again: multiplicity 2 = p, no new span
      await settle(page);
      equal(
        await info(page, "segments").getAttribute("data-segments"),
        "6",
        "after inserting 2.5 twice",
      );
      equal(
        await info(page, "knots-after").getAttribute("data-knots"),
        "0,0,0,1,1.5,2,2.5,2.5,3,4,4,4",
        "knots with 2.5 twice",
      );
      await page.locator('[data-action="reset-knots"]').click();
      await settle(page);
      equal(
        await info(page, "segments").getAttribute("data-segments"),
        "4",
        "the original curve: spans [0,1] [1,2] [2,3] [3,4]",
      );
    },
  ],
  [
    "a link replays its insertions; bad knots and an end knot are refused",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      const state = {
        points: [
          [0, 0],
          [1, 4],
          [4, 5],
          [6, 1],
          [9, 2],
          [10, 5],
        ],
        degree: 2,
        knots: [0, 0, 0, 1, 2, 3, 4, 4, 4],
        inserted: [2.5, 0.5],
        u: 1,
        bezier: false,
      };
      h = await openDemo(
        page,
        base,
        "knot-insertion",
        `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`,
      );
      equal(
        await info(page, "knots-after").getAttribute("data-knots"),
        "0,0,0,0.5,1,2,2.5,3,4,4,4",
        "both insertions replayed",
      );
      // Last insertion 0.5 ∈ [u₂, u₃) = [0, 1), k = 2: α₁ = (0.5 − 0)/(1 − 0) = 1/2, α₂ = (0.5 − 0)/(2 − 0) = 1/4.
      equal(
        await info(page, "alphas").getAttribute("data-alphas"),
        "0.5,0.25",
        "α of the last insertion",
      );
      await typeU(page, settle, "4");
      await page.locator('[data-action="insert"]').click();
      await settle(page);
      equal(
        await h.statusKind(),
        "error",
        "inserting the end knot (already p + 1 times) is refused",
      );
      equal(await info(page, "count").getAttribute("data-knots"), "11", "knots unchanged");
      const bad = { ...state, knots: [0, 0, 0, 2, 1, 3, 4, 4, 4] };
      h = await openDemo(
        page,
        base,
        "knot-insertion",
        `&s=${Buffer.from(JSON.stringify(bad)).toString("base64url")}`,
      );
      assert((await h.status()).includes("knots"), `status names the knots: ${await h.status()}`);
    },
  ],
];
