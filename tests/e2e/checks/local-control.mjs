// Browser checks specific to the local-control demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Default: 9 points, clamped cubic, knots 0 0 0 0 1 2 3 4 5 6 6 6 6 (by hand: p + 1 zeros,
// 1 … n − p = 5, p + 1 sixes), so N_{0,3} is non-zero on [u_0, u_4) = [0, 1) only.

/** Types a value into a slider's box (data-control name) and confirms it. */
async function type(page, settle, name, value) {
  const box = page.locator(`[data-control="${name}"] .sl-value`);
  await box.fill(value);
  await box.press("Enter");
  await settle(page);
}

const support = (page) => page.locator('[data-info="support"]');
const span = (page) => page.locator('[data-info="span"]');

export default [
  [
    "moving P₀ leaves every sample with u ≥ u₄ = 1 unchanged",
    async (page, h, _base, { assert, equal, settle }) => {
      await h.canvas().focus();
      await page.keyboard.press("Home"); // selects P₀: its range is shown
      await settle(page);
      equal(await support(page).getAttribute("data-support"), "0,1", "range of P₀ = [u₀, u₄)");
      assert((await support(page).textContent()).includes("[0, 1)"), "range text [0, 1)");
      const outside = await support(page).getAttribute("data-outside-sum");
      const inside = await support(page).getAttribute("data-inside-sum");
      for (let k = 0; k < 3; k++) await page.keyboard.press("Shift+ArrowUp");
      await page.keyboard.press("Shift+ArrowLeft");
      await settle(page);
      const outsideAfter = await support(page).getAttribute("data-outside-sum");
      const insideAfter = await support(page).getAttribute("data-inside-sum");
      assert(
        Math.abs(Number(outsideAfter) - Number(outside)) <= 1e-9,
        `samples with u ≥ 1 changed: ${outside} → ${outsideAfter}`,
      );
      assert(
        Math.abs(Number(insideAfter) - Number(inside)) > 1,
        `samples with u < 1 should move: ${inside} → ${insideAfter}`,
      );
      // And the far part of the curve really is the same picture: P₄ moved instead changes it.
      await page.keyboard.press("Tab");
      await page.keyboard.press("Tab");
      await page.keyboard.press("Tab");
      await page.keyboard.press("Tab");
      await settle(page);
      equal(await support(page).getAttribute("data-support"), "1,5", "range of P₄ = [u₄, u₈)");
      const farBefore = await support(page).getAttribute("data-outside-sum");
      await page.keyboard.press("Shift+ArrowDown");
      await settle(page);
      equal(
        await support(page).getAttribute("data-outside-sum"),
        farBefore,
        "outside [1, 5) after moving P₄",
      );
    },
  ],
  [
    "u = 5/2 typed by hand: span 5, active P₂ … P₅, weights 1/48, 23/48, 23/48, 1/48",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "u", "0.5");
      equal(
        await span(page).getAttribute("data-span"),
        "3",
        "span of u = 0.5 (u₃ = 0 ≤ u < u₄ = 1)",
      );
      equal(await span(page).getAttribute("data-active"), "0 1 2 3", "active points at u = 0.5");
      await type(page, settle, "u", "5/2");
      equal(await span(page).getAttribute("data-span"), "5", "span of u = 2.5");
      equal(await span(page).getAttribute("data-active"), "2 3 4 5", "active points at u = 2.5");
      assert((await span(page).textContent()).includes("P₂, P₃, P₄, P₅"), "readout names P₂ … P₅");
      const values = await page.locator('.sl-table td[data-column="value"]').allTextContents();
      equal(
        JSON.stringify(values),
        JSON.stringify(["0", "0", "1/48", "23/48", "23/48", "1/48", "0", "0", "0"]),
        "basis values at u = 5/2",
      );
      const active = await page.locator(".sl-table tbody tr.sl-highlight").count();
      equal(active, 4, "highlighted rows (p + 1)");
      // C(5/2) = (3 + 23·5 + 23·7 + 9)/48, (5 + 23·2 + 0 + 3)/48 = (6, 9/8).
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("(6.00, 1.13)") && label.includes("span 5"), `aria-label: ${label}`);
      await type(page, settle, "u", "6");
      equal(
        await span(page).getAttribute("data-active"),
        "5 6 7 8",
        "at the right end the last span is closed",
      );
    },
  ],
  [
    "hull of the active points has the hand-counted vertex count",
    async (page, _h, base, { equal, settle, openDemo }) => {
      // Quadratic, 6 points: at u = 1.5 (span k = 3) the active points are P₁, P₂, P₃; at u = 2.5
      // (k = 4) they are P₂, P₃, P₄ with P₃ = (4, 0) on the segment P₂P₄ → a 2-vertex "hull";
      // with all 6 points the hull is (0,0), (6,0), (8,4), (0,4): 4 vertices.
      const state = {
        points: [
          [0, 0],
          [0, 4],
          [2, 0],
          [4, 0],
          [6, 0],
          [8, 4],
        ],
        degree: 2,
        u: 1.5,
        point: 0,
      };
      const s = Buffer.from(JSON.stringify(state)).toString("base64url");
      await openDemo(page, base, "local-control", `&s=${s}`);
      equal(await span(page).getAttribute("data-active"), "1 2 3", "active at u = 1.5");
      equal(
        await span(page).getAttribute("data-hull-vertices"),
        "3",
        "hull of P₁ P₂ P₃ (a triangle)",
      );
      equal(
        await span(page).getAttribute("data-whole-hull-vertices"),
        "4",
        "hull of all points (P₂, P₃, P₄ lie on the bottom edge)",
      );
      await type(page, settle, "u", "2.5");
      equal(await span(page).getAttribute("data-active"), "2 3 4", "active at u = 2.5");
      equal(
        await span(page).getAttribute("data-hull-vertices"),
        "2",
        "P₂ P₃ P₄ collinear: a segment",
      );
    },
  ],
  [
    "degree slider and a bad link name their fields",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      await type(page, settle, "degree", "1");
      equal(
        await span(page).getAttribute("data-active"),
        "2 3",
        "degree 1 at u = 2.5: P₂, P₃ (knots 0 0 1 2 3 …, span k = 3)",
      );
      await type(page, settle, "degree", "5");
      equal(
        (await span(page).getAttribute("data-active")).split(" ").length,
        6,
        "degree 5: six active points",
      );
      const s = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 1],
            [2, 0],
          ],
          degree: 3,
          u: 0,
          point: 0,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "local-control", `&s=${s}`);
      const status = await h.status();
      assert(status.includes("points") && status.includes("4"), `status: ${status}`);
    },
  ],
];
