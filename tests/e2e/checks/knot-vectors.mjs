// Browser checks specific to the knot-vector demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected knots are written out by hand from the syllabus §3 / design.md conventions:
//   clamped: p + 1 zeros, 1 … n − p, p + 1 copies of n − p + 1; unclamped uniform: u_i = i;
//   chord: interior knot j at the length of the first j legs, end knots at the first n − p + 1 legs.

/** A link state (base64url JSON), as the page writes it. */
const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

/** Legs 5, 3, 10, 5, 4 (3-4-5 and 6-8-10 triangles and two axis-parallel legs). */
const LEGS = [
  [0, 0],
  [3, 4],
  [3, 7],
  [9, 15],
  [12, 11],
  [12, 7],
];

const row = (page, curve) => page.locator(`.sl-table tr[data-curve="${curve}"]`);
const cell = (page, curve, name) =>
  page.locator(`.sl-table tr[data-curve="${curve}"] td[data-cell="${name}"]`).textContent();

export default [
  [
    "6 points, p = 3: clamped knots 0 0 0 0 1 2 3 3 3 3, unclamped 0 … 9, closed 0 … 12",
    async (page, _h, _base, { equal }) => {
      equal(await cell(page, "clamped", "knots"), "0 0 0 0 1 2 3 3 3 3", "clamped knots");
      equal(await cell(page, "clamped", "domain"), "[0, 3]", "clamped domain");
      equal(await cell(page, "unclamped", "knots"), "0 1 2 3 4 5 6 7 8 9", "unclamped knots");
      equal(await cell(page, "unclamped", "domain"), "[3, 6]", "unclamped domain [u₃, u₆]");
      // Closed: P₀ … P₅ then P₀ … P₂ again: 9 points, 13 knots, domain [p, n + p + 1] = [3, 9].
      equal(await cell(page, "closed", "knots"), "0 1 2 3 4 5 6 7 8 9 10 11 12", "closed knots");
      equal(await cell(page, "closed", "domain"), "[3, 9]", "closed domain");
      equal(
        await row(page, "closed").getAttribute("data-start"),
        await row(page, "closed").getAttribute("data-end"),
        "closed curve ends where it starts",
      );
    },
  ],
  [
    "the clamped curve starts at P₀, the unclamped one at (P₀ + 4P₁ + P₂)/6",
    async (page, h, _base, { assert, equal }) => {
      equal(
        await row(page, "clamped").getAttribute("data-start"),
        "0.000,1.000",
        "clamped start = P₀ = (0, 1)",
      );
      equal(
        await row(page, "clamped").getAttribute("data-start-is-p0"),
        "true",
        "clamped start is P₀",
      );
      equal(
        await row(page, "clamped").getAttribute("data-end"),
        "4.000,-1.000",
        "clamped end = P₅ = (4, −1)",
      );
      // Uniform cubic at a knot: (P₀ + 4P₁ + P₂)/6 = ((0 + 8 + 7)/6, (1 + 24 + 7)/6) = (2.5, 16/3).
      equal(
        await row(page, "unclamped").getAttribute("data-start"),
        "2.500,5.333",
        "unclamped start",
      );
      equal(
        await row(page, "unclamped").getAttribute("data-start-is-p0"),
        "false",
        "unclamped start is not P₀",
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("(0, 1)") && label.includes("(2.500, 5.333)"), `aria-label: ${label}`);
      assert(
        (await page.locator(".sl-formula").textContent()).includes("≠"),
        "formula says the unclamped start is not P₀",
      );
    },
  ],
  [
    "chord knots of 3-4-5 legs are the cumulative sums 5, 8, 18",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      h = await openDemo(
        page,
        base,
        "knot-vectors",
        link({
          points: LEGS,
          degree: 3,
          spacing: "chord",
          clamped: true,
          unclamped: true,
          closed: false,
        }),
      );
      // n = 5, p = 3: interior knots after 1 and 2 legs (5, 5 + 3), end knots after 3 legs (5 + 3 + 10).
      equal(await cell(page, "clamped", "knots"), "0 0 0 0 5 8 18 18 18 18", "chord knots");
      equal(
        await page.locator('[data-control="spacing"] input[value="chord"]').isChecked(),
        true,
        "chord selected",
      );
      assert(
        (await page.locator(".sl-formula").textContent()).includes("5,"),
        "formula lists the legs",
      );
      // Centripetal: square roots of the legs, 0 0 0 0 √5 √5+√3 … (decimals).
      await page.locator('[data-control="spacing"] [data-choice="centripetal"] label').click();
      await settle(page);
      equal(
        await cell(page, "clamped", "knots"),
        "0 0 0 0 2.236 3.968 7.130 7.130 7.130 7.130",
        "centripetal knots",
      );
      // Back to chord, then drag P₁: the chord knots follow the points during the drag.
      await page.locator('[data-control="spacing"] [data-choice="chord"] label').click();
      await settle(page);
      const [, p1] = await h.handles();
      await h.drag(p1, 30, 0);
      assert(
        (await cell(page, "clamped", "knots")) !== "0 0 0 0 5 8 18 18 18 18",
        "knots changed with the drag",
      );
      equal(
        await row(page, "clamped").getAttribute("data-start"),
        "0.000,0.000",
        "still starts at P₀",
      );
    },
  ],
  [
    "degree 1: every curve is the polygon, so the unclamped one starts at P₀ too",
    async (page, _h, _base, { equal, settle }) => {
      const degree = page.locator('[data-control="degree"] .sl-value');
      await degree.fill("1");
      await degree.press("Enter");
      await settle(page);
      // n = 5, p = 1: two zeros, 1 … 4, two copies of 5.
      equal(await cell(page, "clamped", "knots"), "0 0 1 2 3 4 5 5", "clamped knots for p = 1");
      equal(
        await row(page, "unclamped").getAttribute("data-start"),
        "0.000,1.000",
        "unclamped start at p = 1",
      );
      equal(
        await row(page, "unclamped").getAttribute("data-start-is-p0"),
        "true",
        "unclamped start is P₀ at p = 1",
      );
      await degree.fill("6");
      await degree.press("Enter");
      await settle(page);
      equal(await degree.inputValue(), "1", "degree 6 refused");
    },
  ],
  [
    "a link with a degree too high for its points names the field",
    async (page, h, base, { assert, openDemo }) => {
      h = await openDemo(
        page,
        base,
        "knot-vectors",
        link({
          points: [
            [0, 0],
            [1, 1],
            [2, 0],
          ],
          degree: 3,
          spacing: "uniform",
          clamped: true,
          unclamped: true,
          closed: true,
        }),
      );
      const status = await h.status();
      assert(/“degree”/.test(status), `status: ${status}`);
    },
  ],
];
