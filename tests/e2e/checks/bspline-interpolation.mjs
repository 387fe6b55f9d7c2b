// Browser checks specific to the bspline-interpolation demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Expected values by hand, from the Croatian notes' example (syllabus §5; seed 002 lines 240–300)
// with the demo's points p = (0,0) (3,4) (7,5) (11,3) (14,4), t = 0 … 4, p = 2, D₀ = (2, 6) and
// knots 0 0 0 1 2 3 4 4 4. The notes' matrix (their rows, in their order):
//   C(0) = r₀;  C′(0) = −2r₀ + 2r₁;  C(1) = r₁/2 + r₂/2;  C(2) = r₂/2 + r₃/2;  C(3) = r₃/2 + r₄/2;  C(4) = r₅.
// Solved by hand from the rows: r₀ = p₀ = (0, 0); r₁ = r₀ + D₀/2 = (1, 3); r₂ = 2p₁ − r₁ = (5, 5);
// r₃ = 2p₂ − r₂ = (9, 5); r₄ = 2p₃ − r₃ = (13, 1); r₅ = p₄ = (14, 4).

const TABLE = '.sl-table[data-table="interpolation-system"]';

/** The matrix as rows of text, "a b c / d e f / …" (entries as shown). */
async function matrixText(page) {
  return page
    .locator(`${TABLE} tbody tr`)
    .evaluateAll((rows) =>
      rows
        .map((row) =>
          [...row.querySelectorAll("td[data-col]")].map((td) => td.textContent).join(" "),
        )
        .join(" / "),
    );
}

const cell = (page, what) => page.locator(`${TABLE} td[${what}]`).first().textContent();
const knots = (page) => page.locator('[data-info="knots"]').getAttribute("data-knots");

/** A table entry as a number: "−2", "1/2", "0.667". */
function value(text) {
  const [num, den] = text.replace("−", "-").split("/").map(Number);
  return den ? num / den : num;
}

/** "(a, b)" (entries as `value` reads them) → [a, b]. */
const pair = (text) => text.trim().slice(1, -1).split(", ").map(value);

/** A link to this demo with `state` (the shell adds nothing else). */
const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

const EXAMPLE = {
  points: [
    [0, 0],
    [3, 4],
    [7, 5],
    [11, 3],
    [14, 4],
  ],
  degree: 2,
  params: "uniform",
  useStartDerivative: true,
  startDerivative: [2, 6],
  useEndDerivative: false,
  endDerivative: [4, 2],
  notesKnots: true,
};

export default [
  [
    "the notes' 6 × 6 system: rows 1; −2 2; ½ ½ …; 1, each named by its condition",
    async (page, _h, _base, { assert, equal }) => {
      equal(
        await matrixText(page),
        [
          "1 0 0 0 0 0",
          "−2 2 0 0 0 0",
          "0 1/2 1/2 0 0 0",
          "0 0 1/2 1/2 0 0",
          "0 0 0 1/2 1/2 0",
          "0 0 0 0 0 1",
        ].join(" / "),
        "the notes' matrix",
      );
      const conditions = await page
        .locator(`${TABLE} tbody tr`)
        .evaluateAll((rows) => rows.map((row) => row.dataset.condition).join(" "));
      equal(
        conditions,
        "point start-derivative point point point point",
        "row conditions in the notes' order",
      );
      const names = await page.locator(`${TABLE} tbody th`).allTextContents();
      equal(
        names.join(" | "),
        "C(0) = p₀ | C′(0) = D₀ | C(1) = p₁ | C(2) = p₂ | C(3) = p₃ | C(4) = p₄",
        "names",
      );
      equal(await cell(page, 'data-rhs="1"'), "(2, 6)", "right-hand side of row 1 is D₀");
      equal(await cell(page, 'data-rhs="2"'), "(3, 4)", "right-hand side of row 2 is p₁");
      equal(await knots(page), "0,0,0,1,2,3,4,4,4", "the notes' knots");
      assert(
        (await page.locator(`${TABLE}`).getAttribute("aria-labelledby")).length > 0,
        "the table has a title",
      );
    },
  ],
  [
    "the solution by hand: r₀ = p₀, r₁ = p₀ + D₀/2 = (1, 3), r₂ = 2p₁ − r₁ … r₅ = p₄",
    async (page, h, _base, { assert, equal }) => {
      const expected = ["(0, 0)", "(1, 3)", "(5, 5)", "(9, 5)", "(13, 1)", "(14, 4)"];
      for (let j = 0; j < 6; j++) {
        const text = await cell(page, `data-solution="${j}"`);
        assert(text.endsWith(expected[j]), `r${j} reads ${text}, expected ${expected[j]}`);
      }
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        /quadratic/.test(label) && label.includes("0 0 0 1 2 3 4 4 4"),
        `aria-label: ${label}`,
      );
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("r") && formula.includes("D"), `formula: ${formula}`);
    },
  ],
  [
    "dragging D₀'s tip keeps the notes' matrix; by hand r₁ = p₀ + D₀/2 with the new D₀",
    async (page, h, _base, { assert, equal }) => {
      const before = await matrixText(page);
      const handles = await h.handles();
      equal(handles.length, 6, "five data points and D₀'s tip");
      await h.drag(handles[5], 30, 20);
      equal(await matrixText(page), before, "the notes' matrix after the drag");
      equal(await knots(page), "0,0,0,1,2,3,4,4,4", "the notes' knots after the drag");
      const d0 = pair(await cell(page, 'data-rhs="1"'));
      const r1 = pair((await cell(page, 'data-solution="1"')).split("=")[1]);
      assert(d0[0] !== 2 || d0[1] !== 6, `D₀ moved: ${d0}`);
      assert(
        Math.abs(r1[0] - d0[0] / 2) < 2e-3 && Math.abs(r1[1] - d0[1] / 2) < 2e-3,
        `r₁ = ${r1}, p₀ + D₀/2 = ${d0.map((v) => v / 2)}`,
      );
      const button = page.locator('[data-action="notes-example"]');
      assert(!(await button.isDisabled()), "the example button is enabled away from the example");
    },
  ],
  [
    "another degree: the core's default knots, the derivative row by hand from them; back to the example",
    async (page, _h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="degree"] [data-choice="3"] label').click();
      await settle(page);
      const after = await knots(page);
      assert(after !== "0,0,0,1,2,3,4,4,4", `knots follow the default rule: ${after}`);
      assert(
        (await page.locator('[data-info="knots"]').textContent()).includes("default"),
        "the readout says the knots are the core's default",
      );
      assert(
        await page.locator('[data-control="notesKnots"]').isHidden(),
        "no notes' knots to tick for another set-up",
      );
      // Syllabus §3 (derivative of a clamped B-spline at its start): C′(u_p) = p/(u_{p+1} − u₁)·(r₁ − r₀),
      // so the derivative row of A reads −3/(u₄ − u₁), 3/(u₄ − u₁), 0 … for p = 3.
      const u = after.split(",").map(Number);
      const a = 3 / (u[4] - u[1]);
      const row = await page
        .locator(`${TABLE} tr[data-condition="start-derivative"] td[data-col]`)
        .allTextContents();
      assert(Math.abs(value(row[0]) + a) < 1e-3, `A(1, 0) = ${row[0]}, expected ${-a}`);
      assert(Math.abs(value(row[1]) - a) < 1e-3, `A(1, 1) = ${row[1]}, expected ${a}`);
      assert(
        row.slice(2).every((text) => text === "0"),
        `the rest of the row: ${row}`,
      );
      const button = page.locator('[data-action="notes-example"]');
      await button.click();
      await settle(page);
      equal(await knots(page), "0,0,0,1,2,3,4,4,4", "knots after the example button");
      assert(await button.isDisabled(), "the example button is disabled on the example");
    },
  ],
  [
    "unticking the notes' knots gives the default rule on the same set-up",
    async (page, _h, _base, { assert, settle }) => {
      await page.locator('[data-control="notesKnots"] input').uncheck();
      await settle(page);
      const u = (await knots(page)).split(",").map(Number);
      assert(u.join(",") !== "0,0,0,1,2,3,4,4,4", `default knots: ${u}`);
      const a = 2 / (u[3] - u[1]);
      const row = await page
        .locator(`${TABLE} tr[data-condition="start-derivative"] td[data-col]`)
        .allTextContents();
      assert(Math.abs(value(row[1]) - a) < 1e-3, `A(1, 1) = ${row[1]}, expected ${a}`);
    },
  ],
  [
    "an end derivative adds a condition, a control point and a handle",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="useEndDerivative"] input').check();
      await settle(page);
      equal((await h.handles()).length, 7, "five points and two tips");
      equal(await page.locator(`${TABLE} tbody tr`).count(), 7, "7 conditions");
      equal(
        await page.locator(`${TABLE} tr[data-condition="end-derivative"]`).count(),
        1,
        "one end-derivative row",
      );
      // The last row by hand (clamped end): C′(t_n) = p/(u_{m−1} − u_{m−p−1})·(r_h − r_{h−1}).
      const u = (await knots(page)).split(",").map(Number);
      const m = u.length - 1;
      const a = 2 / (u[m - 1] - u[m - 3]);
      const row = await page
        .locator(`${TABLE} tr[data-condition="end-derivative"] td[data-col]`)
        .allTextContents();
      assert(Math.abs(value(row[5]) + a) < 1e-3, `A(end, 5) = ${row[5]}, expected ${-a}`);
      assert(Math.abs(value(row[6]) - a) < 1e-3, `A(end, 6) = ${row[6]}, expected ${a}`);
    },
  ],
  [
    "degrees the conditions cannot carry are disabled; a link asking for one is refused",
    async (page, _h, base, { assert, equal, openDemo }) => {
      // 5 points + D₀ = 6 conditions: degree 5 at most.
      const disabled = await page.locator('[data-control="degree"] input').evaluateAll((inputs) =>
        inputs
          .filter((i) => i.disabled)
          .map((i) => i.value)
          .join(" "),
      );
      equal(disabled, "6 7 8 9 10", "disabled degrees");
      const h = await openDemo(
        page,
        base,
        "bspline-interpolation",
        link({ ...EXAMPLE, degree: 7 }),
      );
      equal(await h.statusKind(), "error", "status kind");
      assert(/degree/.test(await h.status()), `message names the degree: ${await h.status()}`);
    },
  ],
  [
    "a system above 12 unknowns gets a note instead of the table",
    async (page, _h, base, { assert, openDemo }) => {
      const points = [];
      for (let i = 0; i < 14; i++) points.push([i, (i * 7) % 5]);
      const h = await openDemo(
        page,
        base,
        "bspline-interpolation",
        link({ ...EXAMPLE, points, degree: 3 }),
      );
      assert(await page.locator(TABLE).isHidden(), "table hidden");
      const note = await page.locator('[data-info="interpolation-system-note"]').textContent();
      assert(note.includes("15") && note.includes("12"), `note: ${note}`);
      assert((await h.canvas().getAttribute("aria-label")).includes("15"), "15 unknowns");
    },
  ],
];
