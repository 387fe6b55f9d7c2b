// Browser checks specific to the Lagrange / Aitken demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Expected numbers are worked out by hand in the comments (never by the code under test).

/** The state of a link, base64url JSON. */
const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;
const cell = (page, level, index) =>
  page.locator(`table[data-table="aitken"] td[data-level="${level}"][data-index="${index}"]`);
const basisValue = (page, i) =>
  page.locator(`table[data-table="lagrange-basis"] tr[data-index="${i}"] td[data-cell="value"]`);

export default [
  [
    "default: Aitken's triangle and the basis at t = 3/2, worked by hand",
    async (page, h, _base, { assert }) => {
      // Points (0,0) (2,3) (6,4) (8,1) (12,0) at t_i = 0 … 4, t = 3/2.
      // Level 1: p_0^1 = (t_1 − t) p_0 + (t − t_0) p_1 = −1/2 (0,0) + 3/2 (2,3) = (3, 9/2), past p_1;
      //          p_3^1 = (t_4 − t) p_3 + (t − t_3) p_4 = 5/2 (8,1) − 3/2 (12,0) = (2, 5/2).
      // L_i(3/2) = Π_{j≠i} (3/2 − j)/(i − j): numerators from (3/2, 1/2, −1/2, −3/2, −5/2):
      //   L_0 = (1/2)(−1/2)(−3/2)(−5/2) / 24 = −5/128,  L_1 = (3/2)(−1/2)(−3/2)(−5/2) / (−6) = 15/32,
      //   L_2 = (3/2)(1/2)(−3/2)(−5/2) / 4 = 45/64,     L_3 = (3/2)(1/2)(−1/2)(−5/2) / (−6) = −5/32,
      //   L_4 = (3/2)(1/2)(−1/2)(−3/2) / 24 = 3/128;  sum 1.
      // P = Σ L_i p_i: x = (15/32)2 + (45/64)6 − (5/32)8 + (3/128)12 = 536/128 = 67/16,
      //                y = (15/32)3 + (45/64)4 − (5/32)1 = 260/64 = 65/16 (above every data point).
      const p01 = await cell(page, 1, 0).textContent();
      assert(p01.includes("(3, 9/2)"), `p₀¹ reads ${p01}`);
      const p31 = await cell(page, 1, 3).textContent();
      assert(p31.includes("(2, 5/2)"), `p₃¹ reads ${p31}`);
      const apex = await cell(page, 4, 0).textContent();
      assert(apex.includes("(67/16, 65/16)"), `p₀⁴ reads ${apex}`);
      const expected = ["-5/128", "15/32", "45/64", "-5/32", "3/128"];
      for (const [i, value] of expected.entries()) {
        const text = await basisValue(page, i).textContent();
        assert(text.startsWith(value), `L${i}(3/2) reads ${text}, expected ${value}`);
      }
      const sum = await basisValue(page, "sum").textContent();
      assert(sum.trim() === "1", `sum reads ${sum}`);
      const note = await page.locator('[data-info="sum"]').textContent();
      assert(note.includes("-5/32") && note.includes("L₃"), `sum note: ${note}`);
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("(4.19, 4.06)"), `aria-label: ${label}`);
      assert(
        (await page.locator(".sl-formula").textContent()).includes("67"),
        "formula shows 67/16",
      );
    },
  ],
  [
    "a parabola from a link: p₁¹ falls outside its leg, L₂(1/2) = −1/8",
    async (page, h, base, { assert, openDemo }) => {
      // (0,0) (2,2) (4,0) at t = 0, 1, 2; t = 1/2:
      // p_0^1 = 1/2 p_0 + 1/2 p_1 = (1, 1);  p_1^1 = (2 − 1/2) p_1 + (1/2 − 1) p_2 = (3 − 2, 3) = (1, 3);
      // p_0^2 = (2 − 1/2)/2 p_0^1 + (1/2)/2 p_1^1 = 3/4 (1,1) + 1/4 (1,3) = (1, 3/2)
      // (the parabola x = 2t, y = 2t(2 − t) at 1/2). L_0 = 3/8, L_1 = 3/4, L_2 = −1/8.
      const state = {
        points: [
          [0, 0],
          [2, 2],
          [4, 0],
        ],
        params: "uniform",
        t: 0.5,
        construction: true,
      };
      await openDemo(page, base, "lagrange", link(state));
      assert((await cell(page, 1, 1).textContent()).includes("(1, 3)"), "p₁¹ = (1, 3)");
      assert((await cell(page, 2, 0).textContent()).includes("(1, 3/2)"), "p₀² = (1, 3/2)");
      const values = ["3/8", "3/4", "-1/8"];
      for (const [i, value] of values.entries())
        assert((await basisValue(page, i).textContent()).startsWith(value), `L${i} = ${value}`);
    },
  ],
  [
    "step buttons move t by 1/16 of the domain [0, 4]",
    async (page, _h, _base, { equal, settle }) => {
      const box = page.locator('[data-control="t"] .sl-value');
      await page.locator('[data-action="step"]').click();
      await settle(page);
      equal(await box.inputValue(), "1.750", "after one step (3/2 + 4/16)");
      await page.locator('[data-action="step-back"]').click();
      await page.locator('[data-action="step-back"]').click();
      await settle(page);
      equal(await box.inputValue(), "1.250", "after two steps back");
    },
  ],
  [
    "chord-length parameters: t_1 = √13, t keeps its place in the domain, t_1 follows a move",
    async (page, h, _base, { assert, equal, settle }) => {
      // Legs |(2,3)| = √13, |(4,1)| = √17, |(2,−3)| = √13, |(4,−1)| = √17: t_1 = √13 ≈ 3.606,
      // t_4 = 2(√13 + √17) ≈ 15.457; t = 3/2 was 3/8 of [0, 4]: 3/8 · 15.457 ≈ 5.796.
      await page.locator('[data-control="params"] [data-choice="chord"] input').first().check();
      await settle(page);
      const row = page.locator('table[data-table="lagrange-basis"] tr[data-index="1"] td').first();
      equal((await row.textContent()).trim(), "3.606", "t₁");
      const last = page.locator('table[data-table="lagrange-basis"] tr[data-index="4"] td').first();
      equal((await last.textContent()).trim(), "15.457", "t₄");
      equal(await page.locator('[data-control="t"] .sl-value').inputValue(), "5.796", "t");
      assert(page.url().includes("s="), "state in the URL");
      // Moving p₀ 10 px left lengthens the first leg: t₁ follows the point (in place).
      await h.canvas().focus();
      await page.keyboard.press("Home");
      await page.keyboard.press("Shift+ArrowLeft");
      await settle(page);
      const moved = Number((await row.textContent()).trim());
      assert(moved > 3.606, `t₁ after the move: ${moved}`);
    },
  ],
  [
    "Runge's bell: 11 equally spaced points, degree 10, uniform parameters",
    async (page, h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="count"] .sl-value');
      await box.fill("11");
      await box.press("Enter");
      await settle(page);
      equal((await h.handles()).length, 11, "handles");
      assert(
        (await page.locator('[data-info="degree"]').textContent()).includes("n = 10"),
        "degree 10",
      );
      // x = −1, −0.8, …, 1 scaled by 6; the middle point x = 0 has y = 4/(1 + 0) = 4; the first
      // x = −1: y = 4/26 = 0.154 (3 decimals).
      const point = (i) =>
        page.locator(`table[data-table="lagrange-basis"] tr[data-index="${i}"] td`).last();
      equal((await point(5).textContent()).trim(), "(0, 4)", "p₅");
      equal((await point(0).textContent()).trim(), "(-6, 0.154)", "p₀");
      // t stayed at 3/8 of the domain, now [0, 10]: 15/4.
      equal(await page.locator('[data-control="t"] .sl-value').inputValue(), "3.750", "t");
    },
  ],
  [
    "a t outside the domain in a link names the field and the domain",
    async (page, h, base, { assert, openDemo }) => {
      const state = {
        points: [
          [0, 0],
          [1, 1],
          [2, 0],
        ],
        params: "uniform",
        t: 7,
        construction: true,
      };
      h = await openDemo(page, base, "lagrange", link(state));
      const status = await h.status();
      assert(
        /“t”/.test(status) && status.includes("7") && status.includes("[0, 2]"),
        `status: ${status}`,
      );
    },
  ],
  [
    "a press on the plot at the tick of t₂ = 2 puts P(t) on p₂, L = (0, 0, 1, 0, 0)",
    async (page, h, _base, { assert, equal, settle }) => {
      // The plot's box runs from 44 px to width − 24 px (signed-basis-plot.js margins); t_2 = 2 is
      // the middle of [0, 4]. Its bottom margin is 30 px: press 50 px above the canvas bottom.
      const box = await h.canvas().boundingBox();
      const x = box.x + 44 + (box.width - 44 - 24) / 2;
      await page.mouse.click(x + 2, box.y + box.height - 50);
      await settle(page);
      equal(
        await page.locator('[data-control="t"] .sl-value').inputValue(),
        "2.000",
        "t snapped to t₂",
      );
      // At a node Aitken's apex is the data point: p₀⁴ = p₂ = (6, 4); L_2(2) = 1, the others 0.
      assert((await cell(page, 4, 0).textContent()).includes("(6, 4)"), "apex = p₂");
      for (const [i, value] of ["0", "0", "1", "0", "0"].entries())
        equal((await basisValue(page, i).textContent()).trim(), value, `L${i}(2)`);
    },
  ],
  [
    "hovering a row of the basis table highlights it",
    async (page, _h, _base, { assert, settle }) => {
      const row = page.locator('table[data-table="lagrange-basis"] tr[data-index="3"]');
      await row.hover();
      await settle(page);
      await settle(page);
      assert(await row.evaluate((r) => r.classList.contains("sl-highlight")), "row 3 highlighted");
    },
  ],
];
