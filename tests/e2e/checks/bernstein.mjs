// Browser checks specific to the Bernstein basis demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers are B_i^n(t) = C(n,i) t^i (1-t)^(n-i) worked by hand (syllabus §2).

/** Exact text of the B_i^n(t) cell of row i ("sum" for the sum row). */
const valueCell = (page, i) =>
  page
    .locator(`.sl-table tr[data-index="${i}"] td[data-cell="value"] .sl-cell-value`)
    .textContent();
const mirrorCell = (page, i) =>
  page
    .locator(`.sl-table tr[data-index="${i}"] td[data-cell="mirror"] .sl-cell-value`)
    .textContent();

/** Types a value into the t box and waits for the redraw. */
async function typeT(page, settle, text) {
  const box = page.locator('[data-control="t"] .sl-value');
  await box.fill(text);
  await box.press("Enter");
  await settle(page);
}

export default [
  [
    "t = 1/4 lists 27/64, 27/64, 9/64, 1/64 and the sum 1",
    async (page, h, _base, { assert, equal, settle }) => {
      await typeT(page, settle, "0.5"); // move away first, so the values really follow t
      equal(await valueCell(page, 1), "3/8", "B₁³(1/2)");
      await typeT(page, settle, "1/4");
      const expected = ["27/64", "27/64", "9/64", "1/64"];
      for (let i = 0; i < 4; i++) equal(await valueCell(page, i), expected[i], `B${i}³(1/4)`);
      equal(await valueCell(page, "sum"), "1", "sum of the weights");
      assert(
        (await page.locator('[data-info="sum"]').textContent()).includes(": 1"),
        "sum note reads 1",
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("0.422, 0.422, 0.141, 0.016") && label.includes("(1.81, 1.44)"),
        `aria-label: ${label}`,
      );
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("27") && formula.includes("64"), "formula shows 27/64");
    },
  ],
  [
    "selecting P₂ marks the maximum of B₂³ at t = 2/3 and P(2/3)",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      await h.canvas().focus();
      await page.keyboard.press("Home");
      await page.keyboard.press("Tab");
      await page.keyboard.press("Tab");
      await settle(page);
      const note = await page.locator('[data-info="peak"]').textContent();
      // P(2/3) = (1·P₀ + 6·P₁ + 12·P₂ + 8·P₃)/27 = (148/27, 76/27).
      assert(
        note.includes("B₂³") && note.includes("t = 2/3") && note.includes("(148/27, 76/27)"),
        `peak note: ${note}`,
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("B₂³ highlighted: largest at t = 2/3") && label.includes("(5.48, 2.81)"),
        `aria-label: ${label}`,
      );
      equal(
        await page.locator(".sl-table tr.sl-highlight").getAttribute("data-index"),
        "2",
        "highlighted row",
      );
      assert(
        (
          await page.locator('.sl-table tr[data-index="2"] td[data-cell="peak"]').textContent()
        ).includes("4/9 at t = 2/3"),
        "maximum 4/9 at 2/3",
      );
      assert((await h.snapshot()) !== before, "the figure marks the maximum");
    },
  ],
  [
    "symmetry: B₁³ at t equals B₂³ at 1 − t",
    async (page, _h, _base, { assert, equal, settle }) => {
      await typeT(page, settle, "0.3");
      const b1 = await valueCell(page, 1);
      equal(b1, "441/1000", "B₁³(0.3) = 3 · 0.3 · 0.7²");
      equal(await mirrorCell(page, 1), b1, "B₂³(1 − 0.3) in the symmetry column");
      await typeT(page, settle, "0.7");
      equal(await valueCell(page, 2), b1, "B₂³(0.7)");
      equal(await valueCell(page, "sum"), "1", "sum at 0.7");
      for (let i = 0; i < 4; i++)
        equal(await mirrorCell(page, i), await valueCell(page, i), `row ${i}: Bᵢ(t) = Bₙ₋ᵢ(1 − t)`);
    },
  ],
  [
    "hovering a table row highlights its control point's maximum",
    async (page, _h, _base, { assert, settle }) => {
      await page.locator('.sl-table tr[data-index="1"]').hover();
      await settle(page);
      const note = await page.locator('[data-info="peak"]').textContent();
      assert(note.includes("P₁") && note.includes("t = 1/3"), `peak note: ${note}`);
      await page.mouse.move(1, 1);
      await settle(page);
      assert(
        !(await page.locator('[data-info="peak"]').textContent()).includes("P₁"),
        "highlight cleared on leave",
      );
    },
  ],
  [
    "hovering a basis graph in the plot highlights its control point",
    async (page, h, _base, { assert, settle }) => {
      // At t = 1/3 the cubic's B₁ = 4/9 stands ≥ 0.148 above the others: hover its graph there.
      // Plot frame as in bernstein.js: margins 30/22/34/40 px, height max(40 %, min(150 px, 55 %)).
      const box = await h.canvas().boundingBox();
      const height = Math.max(
        Math.round(box.height * 0.4),
        Math.min(150, Math.round(box.height * 0.55)),
      );
      const y0 = box.height - 34;
      const y1 = box.height - height + 30;
      const x = box.x + 40 + (box.width - 40 - 22) / 3;
      await page.mouse.move(x, box.y + y0 - (4 / 9) * (y0 - y1));
      await settle(page);
      const note = await page.locator('[data-info="peak"]').textContent();
      assert(note.includes("P₁"), `peak note while hovering B₁: ${note}`);
      await page.mouse.move(1, 1);
      await settle(page);
    },
  ],
  [
    "clicking the plot at the tick 1/3 sets t = 1/3",
    async (page, h, _base, { assert, equal, settle }) => {
      // The plot strip: the bottom 40 % (≥ 150 px) of the canvas; frame 40 px from the left,
      // 22 px from the right, its t axis 34 px above the bottom (bernstein.js PLOT_* constants).
      const box = await h.canvas().boundingBox();
      const x = box.x + 40 + (box.width - 40 - 22) / 3;
      const y = box.y + box.height - 34 - 20;
      await page.mouse.click(x + 2, y); // within the snapping distance of the tick
      await settle(page);
      equal(await page.locator('[data-control="t"] .sl-value').inputValue(), "0.333", "t box");
      const expected = ["8/27", "4/9", "2/9", "1/27"];
      for (let i = 0; i < 4; i++) equal(await valueCell(page, i), expected[i], `B${i}³(1/3)`);
      assert(page.url().includes("s="), "state in the URL");
    },
  ],
  [
    "+ raises the degree: five weights at t = 1/4",
    async (page, h, _base, { assert, equal, settle }) => {
      await h.canvas().focus();
      await page.keyboard.press("End");
      await page.keyboard.press("+");
      await settle(page);
      equal((await h.handles()).length, 5, "points after +");
      assert(
        (await page.locator('[data-info="degree"]').textContent()).includes("n = 4"),
        "degree 4",
      );
      const expected = ["81/256", "27/64", "27/128", "3/64", "1/256"];
      for (let i = 0; i < 5; i++) equal(await valueCell(page, i), expected[i], `B${i}⁴(1/4)`);
      equal(await valueCell(page, "sum"), "1", "sum");
      await page.keyboard.press("Delete");
      await settle(page);
      equal(
        await page.locator(".sl-table tbody tr").count(),
        5,
        "four rows and the sum after Delete",
      );
    },
  ],
  [
    "invalid t in a link names the field",
    async (page, h, base, { assert, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 1],
          ],
          t: -1,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "bernstein", `&s=${state}`);
      const status = await h.status();
      assert(/“t”/.test(status) && status.includes("-1"), `status: ${status}`);
    },
  ],
];
