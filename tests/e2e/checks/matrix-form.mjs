// Browser checks specific to the matrix-form demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected matrices are the syllabus §3 / Croatian notes' ones: quadratic periodic segment
// [[1/2, −1, 1/2], [−1, 1, 0], [1/2, 1/2, 0]], cubic 1/6·[[−1, 3, −3, 1], [3, −6, 3, 0], [−3, 0, 3, 0],
// [1, 4, 1, 0]], and the first segment of the clamped quadratic 0 0 0 1 2 3 4 4 4:
// [[1, −3/2, 1/2], [−2, 2, 0], [1, 0, 0]].

/** The matrix table's entries as rows of text, "a b c / d e f / …". */
async function matrixText(page) {
  return page
    .locator('.sl-table[data-table="matrix"] tbody tr')
    .evaluateAll((rows) =>
      rows
        .map((row) =>
          [...row.querySelectorAll("td[data-col]")].map((td) => td.textContent).join(" "),
        )
        .join(" / "),
    );
}

const factor = (page) =>
  page.locator('.sl-table[data-table="matrix"] td[data-cell="factor"]').getAttribute("data-factor");
const result = (page, which) =>
  page.locator(`.sl-table[data-table="result"] td[data-result="${which}"]`).textContent();

export default [
  [
    "quadratic: M = [[1/2, -1, 1/2], [-1, 1, 0], [1/2, 1/2, 0]], the periodic matrix",
    async (page, _h, _base, { equal }) => {
      equal(await matrixText(page), "1/2 -1 1/2 / -1 1 0 / 1/2 1/2 0", "matrix entries");
      equal(await factor(page), "1", "no factor for p = 2");
      equal(
        await page.locator('[data-info="periodic"]').getAttribute("data-periodic"),
        "true",
        "periodic segment",
      );
      // Segment 2 uses P₁, P₂, P₃ (the notes' P_{i−1}, P_i, P_{i+1}).
      const heads = await page
        .locator('.sl-table[data-table="matrix"] thead th[data-col]')
        .allTextContents();
      equal(heads.join(" "), "P₁ P₂ P₃", "columns");
    },
  ],
  [
    "cubic: M = 1/6 [[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]]",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="degree"] [data-choice="3"] label').click();
      await settle(page);
      equal(
        await matrixText(page),
        "-1 3 -3 1 / 3 -6 3 0 / -3 0 3 0 / 1 4 1 0",
        "matrix entries × 6",
      );
      equal(await factor(page), "1/6", "factor");
      assert((await h.canvas().getAttribute("aria-label")).startsWith("cubic"), "cubic now");
      assert(
        (await page.locator(".sl-formula").textContent()).includes("16"),
        "formula shows the 1/6 factor",
      );
    },
  ],
  [
    "the matrix product equals evaluate(u) to 3 decimals (by hand: (23/4, 21/4))",
    async (page, h, _base, { equal, settle }) => {
      // t = 1/2: [1/4 1/2 1] M = [1/8, 3/4, 1/8]; (1/8)(2, 5) + (3/4)(6, 6) + (1/8)(8, 1) = (23/4, 21/4).
      equal(await result(page, "product"), "(5.750, 5.250)", "matrix product");
      equal(await result(page, "evaluate"), "(5.750, 5.250)", "evaluate(u)");
      // After a drag and a typed t, in the cubic: still the same numbers.
      await page.locator('[data-control="degree"] [data-choice="3"] label').click();
      const box = page.locator('[data-control="t"] .sl-value');
      await box.fill("1/3");
      await box.press("Enter");
      const [, p1] = await h.handles();
      await h.drag(p1, 25, -15);
      await settle(page);
      const product = await result(page, "product");
      equal(await result(page, "evaluate"), product, "evaluate(u) after a drag, p = 3, t = 1/3");
    },
  ],
  [
    "clamped knots: segment 1 has its own matrix, segment 2 the periodic one (the notes' example)",
    async (page, _h, _base, { equal, settle }) => {
      await page.locator('[data-control="knots"] [data-choice="clamped"] label').click();
      await settle(page);
      equal(
        await matrixText(page),
        "1/2 -1 1/2 / -1 1 0 / 1/2 1/2 0",
        "segment 2 of 0 0 0 1 2 3 4 4 4",
      );
      equal(
        await page.locator('[data-info="periodic"]').getAttribute("data-periodic"),
        "true",
        "segment 2 periodic",
      );
      const segment = page.locator('[data-control="segment"] .sl-value');
      await segment.fill("1");
      await segment.press("Enter");
      await settle(page);
      equal(
        await matrixText(page),
        "1 -3/2 1/2 / -2 2 0 / 1 0 0",
        "segment 1 of 0 0 0 1 2 3 4 4 4",
      );
      equal(
        await page.locator('[data-info="periodic"]').getAttribute("data-periodic"),
        "false",
        "segment 1 not periodic",
      );
      equal(
        await result(page, "product"),
        await result(page, "evaluate"),
        "product = evaluate on an end segment",
      );
    },
  ],
  [
    "a link with a segment beyond n - p + 1 names the field",
    async (page, h, base, { assert, openDemo }) => {
      const state = {
        points: [
          [0, 0],
          [2, 5],
          [6, 6],
          [8, 1],
        ],
        degree: 2,
        knots: "uniform",
        segment: 3,
        t: 0.5,
      };
      h = await openDemo(
        page,
        base,
        "matrix-form",
        `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`,
      );
      const status = await h.status();
      assert(/“segment”/.test(status), `status: ${status}`);
    },
  ],
];
