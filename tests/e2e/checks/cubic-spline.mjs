// Browser checks specific to the cubic-spline demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// The expected numbers are worked by hand from the default state: points p₀ … p₅ = (0, 0), (1, 3),
// (4, 4), (6, 1), (9, 0), (10, 3), uniform parameters t_i = i (so every Δ_i = 1), arrow tips
// (2.5, −0.5) at P₀ and (11.5, 3) at P₅.

const cell = (page, i, j) =>
  page.locator(`[data-table="cubic-system"] td[data-row="${i}"][data-col="${j}"]`);
const rhs = (page, i) => page.locator(`[data-table="cubic-system"] td[data-rhs="${i}"]`);
const unknown = (page, i) => page.locator(`[data-table="cubic-system"] td[data-unknown="${i}"]`);
const rowOf = (page, i) => page.locator(`[data-table="cubic-system"] tr[data-row="${i}"]`);
/** A cell's text, trimmed. */
const text = async (locator) => (await locator.textContent()).trim();

/** Chooses an end condition (radio) or parametrisation and waits for the redraw. */
async function choose(page, settle, control, value) {
  await page.locator(`[data-control="${control}"] [data-choice="${value}"] input`).check();
  await settle(page);
}

/** The demo state from the page's link (after a committed change). */
function linkState(page) {
  const s = new URL(page.url()).hash.match(/[#&]s=([\w-]+)/)[1];
  return JSON.parse(Buffer.from(s, "base64url").toString("utf8"));
}

export default [
  [
    "natural ends: the first row is 2, 1 | 3(p₁ − p₀) = (3, 9), the last 1, 2 | 3(p₅ − p₄) = (3, 9)",
    async (page, _h, _base, { assert, equal }) => {
      equal(await text(cell(page, 0, 0)), "2", "a₀₀");
      equal(await text(cell(page, 0, 1)), "1", "a₀₁");
      equal(await text(cell(page, 0, 2)), "0", "a₀₂");
      equal(await text(rhs(page, 0)), "(3, 9)", "c₀ = 3(p₁ − p₀)/Δ₀ = 3·(1, 3)");
      equal(await text(cell(page, 5, 4)), "1", "a₅₄");
      equal(await text(cell(page, 5, 5)), "2", "a₅₅");
      equal(await text(rhs(page, 5)), "(3, 9)", "c₅ = 3(p₅ − p₄)/Δ₄ = 3·(1, 3)");
      // Interior row 1 with Δ = 1: 1, 4, 1 | 3(p₂ − p₀) = 3·(4, 4).
      equal(await text(cell(page, 1, 0)), "1", "a₁₀");
      equal(await text(cell(page, 1, 1)), "4", "a₁₁");
      equal(await text(cell(page, 1, 2)), "1", "a₁₂");
      equal(await text(rhs(page, 1)), "(12, 12)", "c₁");
      const first = rowOf(page, 0);
      assert(
        await first.evaluate((r) => r.classList.contains("sl-highlight")),
        "first row highlighted",
      );
      assert(
        (await first.textContent()).includes("2m₀ + m₁ = 3(p₁ − p₀)/Δ₀"),
        "natural start equation",
      );
      assert(
        await rowOf(page, 5).evaluate((r) => r.classList.contains("sl-highlight")),
        "last row highlighted",
      );
      assert(
        !(await rowOf(page, 2).evaluate((r) => r.classList.contains("sl-highlight"))),
        "interior row not highlighted",
      );
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("start") && formula.includes("end"), "formula has the end rows");
    },
  ],
  [
    "quadratic ends: the highlighted first row becomes 1, 1 | 2(p₁ − p₀) = (2, 6)",
    async (page, _h, _base, { assert, equal, settle }) => {
      await choose(page, settle, "end", "quadratic");
      equal(await text(cell(page, 0, 0)), "1", "a₀₀");
      equal(await text(cell(page, 0, 1)), "1", "a₀₁");
      equal(await text(rhs(page, 0)), "(2, 6)", "c₀ = 2(p₁ − p₀)/Δ₀");
      equal(await text(cell(page, 5, 4)), "1", "a₅₄");
      equal(await text(cell(page, 5, 5)), "1", "a₅₅");
      equal(await text(rhs(page, 5)), "(2, 6)", "c₅ = 2(p₅ − p₄)/Δ₄");
      assert(
        (await rowOf(page, 0).textContent()).includes("m₀ + m₁ = 2(p₁ − p₀)/Δ₀"),
        "quadratic start equation",
      );
      assert(page.url().includes("s="), "the choice is in the link");
      equal(linkState(page).end, "quadratic", "state end");
    },
  ],
  [
    "clamped ends: m₀ = 3(tip₀ − p₀)/Δ₀ = (7.5, −1.5) is the first row and the solved m₀",
    async (page, _h, _base, { assert, equal, settle }) => {
      await choose(page, settle, "end", "clamped");
      equal(await text(cell(page, 0, 0)), "1", "a₀₀");
      equal(await text(cell(page, 0, 1)), "0", "a₀₁");
      equal(await text(rhs(page, 0)), "(7.500, -1.500)", "c₀");
      assert((await text(unknown(page, 0))).includes("(7.500, -1.500)"), "solved m₀");
      // mₙ = 3(tip₅ − p₅)/Δ₄ = 3·(1.5, 0).
      equal(await text(rhs(page, 5)), "(4.500, 0)", "c₅");
      // The arrows are handles: 6 points + 2 tips.
      const handles = await page.locator(".sl-figure").getAttribute("data-handles");
      equal(handles.split(";").filter(Boolean).length, 8, "handles with the two arrows");
    },
  ],
  [
    "periodic ends: P₀ closes the curve, the cyclic corners are Δ₀ = 1 and the first row's c₀ = (−27, 0)",
    async (page, _h, _base, { assert, equal, settle }) => {
      await choose(page, settle, "end", "periodic");
      // Six pieces (P₅ → P₀ closes), six unknowns m₀ … m₅ (m₆ = m₀).
      equal(await page.locator('[data-table="cubic-system"] tbody tr').count(), 6, "rows");
      equal(await text(cell(page, 0, 0)), "4", "a₀₀ = 2(Δ₅ + Δ₀)");
      equal(await text(cell(page, 0, 5)), "1", "corner a₀₅ = Δ₀");
      equal(await text(cell(page, 5, 0)), "1", "corner a₅₀ = Δ₄");
      assert(
        await cell(page, 0, 5).evaluate((c) => c.classList.contains("sl-highlight")),
        "corner marked",
      );
      // c₀ = 3(Δ₀/Δ₅ (p₀ − p₅) + Δ₅/Δ₀ (p₁ − p₀)) = 3((−10, −3) + (1, 3)) = (−27, 0).
      equal(await text(rhs(page, 0)), "(-27, 0)", "c₀");
      const label = await page.locator(".sl-canvas").getAttribute("aria-label");
      assert(label.includes("periodic"), `aria-label: ${label}`);
    },
  ],
  [
    "overlay: the legend in the figure has six entries, and a drag moves all six curves",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="compare"] input').check();
      await settle(page);
      const names = ["natural", "clamped", "quadratic", "Bessel", "not-a-knot", "periodic"];
      const file = await h.download("export-svg");
      const { readFileSync } = await import("node:fs");
      const svg = readFileSync(await file.path(), "utf8");
      const texts = [...svg.matchAll(/<text[^>]*>([^<]*)<\/text>/g)].map((m) => m[1]);
      for (const name of names) assert(texts.includes(name), `legend entry ${name}`);
      // Dragging P₁ re-solves in place; the first row's right-hand side follows 3(p₁ − p₀).
      const before = await h.snapshot();
      const [, p1] = await h.handles();
      await h.drag(p1, 30, -20);
      assert((await h.snapshot()) !== before, "picture changed");
      const s = linkState(page);
      const [[x0, y0], [x1, y1]] = s.points;
      const short = (v) =>
        Math.abs(v - Math.round(v)) < 1e-9 ? String(Math.round(v)) : v.toFixed(3);
      const expected = `(${short(3 * (x1 - x0))}, ${short(3 * (y1 - y0))})`;
      const got = await text(rhs(page, 0));
      equal(got, expected, "c₀ after the drag");
    },
  ],
  [
    "lecture mode shows at most five rows (an ellipsis row) of a larger system, all of them again after",
    async (page, _h, _base, { assert, equal, settle }) => {
      const add = page.locator('[data-action="add-point"]');
      await add.click();
      await add.click();
      await settle(page);
      const rows = page.locator('[data-table="cubic-system"] tbody tr');
      equal(await rows.count(), 8, "rows at normal size (8 points)");
      await page.locator('[data-action="lecture"]').click();
      await settle(page);
      await settle(page);
      equal(await rows.count(), 5, "rows in lecture mode");
      equal(await rowOf(page, -1).count(), 1, "the ellipsis row");
      assert(
        await rowOf(page, 7).evaluate((r) => r.classList.contains("sl-highlight")),
        "the last row is shown, highlighted",
      );
      await page.locator('[data-action="lecture"]').click();
      await settle(page);
      await settle(page);
      equal(await rows.count(), 8, "rows back at normal size");
    },
  ],
  [
    "the plots' numbers: natural C″ = 0 at both ends, quadratic C‴ = 0 on the end pieces, not-a-knot no C‴ jump at t₁, t₄",
    async (page, _h, _base, { equal, settle }) => {
      const note = page.locator('[data-info="plots"]');
      const facts = () =>
        note.evaluate((n) => ({
          secondStart: n.dataset.secondStart,
          secondEnd: n.dataset.secondEnd,
          thirdFirst: n.dataset.thirdFirst,
          thirdLast: n.dataset.thirdLast,
          jumps: n.dataset.jumps,
        }));
      let f = await facts();
      equal(f.secondStart, "0,0", "natural C″(t₀)");
      equal(f.secondEnd, "0,0", "natural C″(t₅)");
      equal(f.jumps, "1,2,3,4", "natural: C‴ jumps at every inner join");
      await choose(page, settle, "end", "quadratic");
      f = await facts();
      equal(f.thirdFirst, "0,0", "quadratic: C‴ on the first piece");
      equal(f.thirdLast, "0,0", "quadratic: C‴ on the last piece");
      await choose(page, settle, "end", "not-a-knot");
      f = await facts();
      equal(f.jumps, "2,3", "not-a-knot: no jump at t₁ and t₄");
    },
  ],
  [
    "chord parameters on a repeated point are refused in the status line; the picture and the choice stay",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      const state = {
        points: [
          [0, 0],
          [1, 3],
          [1, 3],
          [6, 1],
          [9, 0],
        ],
        end: "natural",
        compare: false,
        parametrization: "uniform",
        tangentTips: [
          [2, 0],
          [10, 1],
        ],
        third: true,
      };
      const encoded = Buffer.from(JSON.stringify(state)).toString("base64url");
      h = await openDemo(page, base, "cubic-spline", `&s=${encoded}`);
      const before = await h.snapshot();
      const row = await text(rowOf(page, 0));
      // A click (not `check`: the refused radio goes back to uniform at once).
      await page.locator('[data-control="parametrization"] [data-choice="chord"] input').click();
      await settle(page);
      equal(await h.statusKind(), "error", "status kind");
      assert((await h.status()).length > 10, `a message: ${await h.status()}`);
      equal(await h.snapshot(), before, "picture kept");
      equal(await text(rowOf(page, 0)), row, "table kept");
      assert(
        await page
          .locator('[data-control="parametrization"] [data-choice="uniform"] input')
          .isChecked(),
        "uniform still chosen",
      );
    },
  ],
];
