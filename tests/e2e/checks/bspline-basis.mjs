// Browser checks specific to the B-spline basis demo (run after the generic ones by run.mjs).
// Expected numbers: the Croatian quadratic example of syllabus §3, p = 2, U = [0,0,0,1,2,3,4,4,4]:
// at u = 5/2, N₂,₂ = (3 − u)²/2 = 1/8, N₃,₂ = (−2u² + 10u − 11)/2 = 3/4 (the notes' +11 is a
// typo), N₄,₂ = (u − 2)²/2 = 1/8; at u = 1/2, N₀,₂ = (1 − u)² = 1/4, N₁,₂ = u(4 − 3u)/2 = 5/8,
// N₂,₂ = u²/2 = 1/8.

/** The value cell of basis function i in the values table. */
const value = (page, i) =>
  page
    .locator(`[data-table="basis"] tr[data-index="${i}"] td[data-cell="value"] .sl-cell-value`)
    .textContent();

/** Knot handle centres (page px) from the figure's data-knots. */
async function knots(page, h) {
  const text = await page.locator(".sl-figure").first().getAttribute("data-knots");
  const origin = await h.canvas().evaluate((c) => {
    const r = c.getBoundingClientRect();
    return { x: r.left + c.clientLeft, y: r.top + c.clientTop };
  });
  return text.split(";").map((pair) => {
    const [x, y] = pair.split(",").map(Number);
    return { x: origin.x + x, y: origin.y + y };
  });
}

export default [
  [
    "Croatian example at u = 2.5: N₃,₂ = 0.750, N₂,₂ = N₄,₂ = 0.125, sum 1",
    async (page, h, _base, { assert, equal }) => {
      equal(await value(page, 3), "0.750", "N₃,₂(2.5)");
      equal(await value(page, 2), "0.125", "N₂,₂(2.5)");
      equal(await value(page, 4), "0.125", "N₄,₂(2.5)");
      for (const i of [0, 1, 5]) equal(await value(page, i), "0.000", `N${i},₂(2.5)`);
      equal(
        await page
          .locator('[data-table="basis"] tr[data-index="sum"] .sl-cell-value')
          .textContent(),
        "1.000",
        "sum row",
      );
      assert(
        (await page.locator('[data-info="sum"]').textContent()).includes("= 1.000"),
        "sum readout",
      );
      // The triangle: N₃,₁(2.5) = 3 − u = 0.5, N₄,₁(2.5) = u − 2 = 0.5, N₄,₀ = 1 (span k = 4).
      assert(
        (
          await page.locator('[data-table="cox-de-boor"] td[data-r="1"][data-i="3"]').textContent()
        ).includes("0.500"),
        "N₃,₁",
      );
      assert(
        (
          await page.locator('[data-table="cox-de-boor"] td[data-r="2"][data-i="3"]').textContent()
        ).includes("0.750"),
        "N₃,₂ in the triangle",
      );
      assert(
        (
          await page.locator('[data-table="cox-de-boor"] td[data-r="0"][data-i="4"]').textContent()
        ).includes("1.000"),
        "N₄,₀",
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("N₃,₂ = 0.750") && label.includes("sum 1.000") && label.includes("1: C¹"),
        `aria-label: ${label}`,
      );
      // C(2.5) = (P₂ + 6 P₃ + P₄)/8 = (5, 1.625).
      assert(
        (await page.locator(".sl-formula").textContent()).includes("1.625"),
        "formula shows C(2.5)",
      );
    },
  ],
  [
    "typed u = 1/2 gives the clamped-end values 1/4, 5/8, 1/8",
    async (page, _h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="u"] .sl-value');
      await box.fill("1/2");
      await box.press("Enter");
      await settle(page);
      equal(await value(page, 0), "0.250", "N₀,₂(0.5)");
      equal(await value(page, 1), "0.625", "N₁,₂(0.5)");
      equal(await value(page, 2), "0.125", "N₂,₂(0.5)");
      equal(
        await page
          .locator('[data-table="basis"] tr[data-index="sum"] .sl-cell-value')
          .textContent(),
        "1.000",
        "sum row",
      );
      assert(page.url().includes("s="), "state in the URL");
    },
  ],
  [
    "degree 3 regenerates the clamped uniform knot vector",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="degree"] [data-choice="3"] input').check();
      await settle(page);
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("knots [0, 0, 0, 0, 1, 2, 3, 3, 3, 3]") && /cubic/.test(label),
        `aria-label: ${label}`,
      );
      equal((await knots(page, h)).length, 10, "knot handles");
      equal(
        await page.locator('[data-table="cox-de-boor"] tbody tr').count(),
        4,
        "triangle rows r = 0 … 3",
      );
      equal(
        await page
          .locator('[data-table="basis"] tr[data-index="sum"] .sl-cell-value')
          .textContent(),
        "1.000",
        "sum row",
      );
      assert(label.includes("C²"), "cubic: C² at simple knots");
      await page.keyboard.press("Control+z");
      await settle(page);
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("knots [0, 0, 0, 1, 2, 3, 4, 4, 4]"),
        "undo restores the quadratic knots",
      );
    },
  ],
  [
    "a dragged knot stops at its neighbours",
    async (page, h, _base, { assert }) => {
      let k = await knots(page, h);
      await h.drag(k[4], 400, 0); // u₄ = 2 far past u₅ = 3
      let label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("knots [0, 0, 0, 1, 3, 3, 4, 4, 4]"), `after dragging right: ${label}`);
      assert(label.includes("3: C⁰"), `a double knot gives C⁰: ${label}`);
      k = await knots(page, h);
      await h.drag(k[4], -600, 0); // and far past u₃ = 1
      label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("knots [0, 0, 0, 1, 1, 3, 4, 4, 4]"), `after dragging left: ${label}`);
    },
  ],
  [
    "Enter and a double click merge the next knot",
    async (page, h, _base, { assert, settle }) => {
      await h.canvas().focus();
      await page.keyboard.press("End"); // P₅
      await page.keyboard.press("Tab"); // u₀
      for (let i = 0; i < 3; i++) await page.keyboard.press("Tab"); // u₃ = 1
      await page.keyboard.press("Enter");
      await settle(page);
      let label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("knots [0, 0, 0, 1, 1, 3, 4, 4, 4]") && label.includes("1: C⁰"),
        `after Enter: ${label}`,
      );
      const k = await knots(page, h);
      await page.mouse.dblclick(k[5].x, k[5].y); // u₅ = 3: the next knot is the domain end, so u₄ joins it
      await settle(page);
      label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("knots [0, 0, 0, 1, 3, 3, 4, 4, 4]") && label.includes("3: C⁰"),
        `after the double click: ${label}`,
      );
    },
  ],
  [
    "pressing the plot above knot u₃ = 1 sets u = 1 (snapped to the knot)",
    async (page, h, _base, { equal, settle }) => {
      // The plot band lies right above the knot ruler, its u axis aligned with the ruler's.
      const knot = (await knots(page, h))[3];
      await page.mouse.click(knot.x + 3, knot.y - 70); // within the snapping distance of the knot
      await settle(page);
      equal(await page.locator('[data-control="u"] .sl-value').inputValue(), "1.000", "u box");
      equal(await value(page, 1), "0.500", "N₁,₂(1) = u(4 − 3u)/2");
    },
  ],
  [
    "hovering a table row highlights the support",
    async (page, h, _base, { assert, settle }) => {
      await page.locator('[data-table="basis"] tr[data-index="2"]').hover();
      await settle(page);
      await settle(page);
      assert(
        await page
          .locator('[data-table="basis"] tr[data-index="2"]')
          .evaluate((r) => r.classList.contains("sl-highlight")),
        "row highlighted",
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("N₂,₂ highlighted: support [0, 3)"), `aria-label: ${label}`);
    },
  ],
  [
    "a link with the wrong number of knots names the field",
    async (page, h, base, { assert, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 1],
            [2, 0],
          ],
          degree: 2,
          knots: [0, 0, 0, 1, 1],
          u: 0.5,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "bspline-basis", `&s=${state}`);
      const status = await h.status();
      assert(/“knots”/.test(status) && status.includes("6"), `status: ${status}`);
    },
  ],
];
