// Browser checks specific to the de Boor demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers are worked by hand from the syllabus §3 formulas:
//   span k with u_k <= u < u_{k+1}; α_j^r = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p}).

/** A link state (base64url JSON), as the page writes it. */
const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

/** The Greek notes' worked example as a clamped cubic B-spline with one span: the Bézier curve. */
const WORKED = {
  points: [
    [0, 0],
    [2, 2],
    [6, 4],
    [8, 2],
  ],
  degree: 3,
  knots: [0, 0, 0, 0, 1, 1, 1, 1],
  u: 0.25,
  construction: true,
};

export default [
  [
    "knots 0000 1111 at u = 1/4 give de Casteljau's (29/16, 23/16)",
    async (page, h, base, { assert, equal, openDemo }) => {
      h = await openDemo(page, base, "de-boor", link(WORKED));
      const last = await page.locator('.sl-table td[data-level="3"][data-index="3"]').textContent();
      assert(last.includes("(29/16, 23/16)"), `d₃³ reads ${last}`);
      // Level 1 equals de Casteljau's level 1: (1/2, 1/2), (3, 5/2), (13/2, 7/2); every α = u = 1/4.
      const level1 = await page
        .locator('.sl-table td[data-level="1"][data-index="2"]')
        .textContent();
      assert(level1.includes("(3, 5/2)"), `d₂¹ reads ${level1}`);
      const alphas = await page
        .locator(".sl-table td [data-alpha]")
        .evaluateAll((nodes) => nodes.map((n) => n.dataset.alpha));
      equal(alphas.join(" "), "0.250 0.250 0.250 0.250 0.250 0.250", "every α");
      equal(await page.locator('[data-info="span"]').getAttribute("data-span"), "3", "span k");
      const label = await h.canvas().getAttribute("aria-label");
      assert(/cubic/.test(label) && label.includes("(1.81, 1.44)"), `aria-label: ${label}`);
      assert(
        (await page.locator(".sl-formula").textContent()).includes("29"),
        "formula shows 29/16",
      );
    },
  ],
  [
    "default curve: u = 5/4 lies in span k = 4, [u₄, u₅) = [1, 2), with the hand-computed α",
    async (page, _h, _base, { assert, equal }) => {
      // Knots 0 0 0 0 1 2 3 4 4 4 4, p = 3: u_4 = 1 <= 5/4 < 2 = u_5, so k = 4, active P₁ … P₄.
      const span = page.locator('[data-info="span"]');
      equal(await span.getAttribute("data-span"), "4", "span k");
      assert(
        (await span.textContent()).includes("[1, 2)"),
        `span text: ${await span.textContent()}`,
      );
      const first = await page
        .locator('.sl-table td[data-level="0"][data-index="0"]')
        .textContent();
      assert(first.includes("P₁") && first.includes("(2, 7)"), `d₀⁰ reads ${first}`);
      // r = 1: α₁ = (5/4 − u₂)/(u₅ − u₂) = 5/8, α₂ = (5/4 − u₃)/(u₆ − u₃) = 5/12, α₃ = (5/4 − u₄)/(u₇ − u₄) = 1/12.
      const cell = (r, j) =>
        page.locator(`.sl-table td[data-level="${r}"][data-index="${j}"]`).textContent();
      assert((await cell(1, 1)).includes("α = 5/8"), `α₁¹: ${await cell(1, 1)}`);
      assert((await cell(1, 2)).includes("α = 5/12"), `α₂¹: ${await cell(1, 2)}`);
      assert((await cell(1, 3)).includes("α = 1/12"), `α₃¹: ${await cell(1, 3)}`);
      // d₁¹ = (3/8)P₁ + (5/8)P₂ = (3/8)(2, 7) + (5/8)(8, 9) = (23/4, 33/4).
      assert((await cell(1, 1)).includes("(23/4, 33/4)"), `d₁¹: ${await cell(1, 1)}`);
      // r = 2: α₂² = (5/4 − u₃)/(u₅ − u₃) = 5/8, α₃² = (5/4 − u₄)/(u₆ − u₄) = 1/8; r = 3: α₃³ = (5/4 − u₄)/(u₅ − u₄) = 1/4.
      assert((await cell(2, 2)).includes("α = 5/8"), `α₂²: ${await cell(2, 2)}`);
      assert((await cell(2, 3)).includes("α = 1/8"), `α₃²: ${await cell(2, 3)}`);
      assert((await cell(3, 3)).includes("α = 1/4"), `α₃³: ${await cell(3, 3)}`);
    },
  ],
  [
    "step buttons move u by 1/16 of the domain and the span follows",
    async (page, _h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="u"] .sl-value');
      const span = page.locator('[data-info="span"]');
      await page.locator('[data-action="step"]').click();
      await settle(page);
      equal(await box.inputValue(), "1.500", "after one step (domain [0, 4]: step 1/4)");
      equal(await span.getAttribute("data-span"), "4", "span after one step");
      await page.locator('[data-action="step"]').click();
      await page.locator('[data-action="step"]').click();
      await settle(page);
      // u = 2 = u₅ belongs to the next span (right-continuous basis): k = 5, [2, 3).
      equal(await box.inputValue(), "2.000", "after three steps");
      equal(await span.getAttribute("data-span"), "5", "span at u = 2");
      assert(
        (await span.textContent()).includes("[2, 3)"),
        `span text: ${await span.textContent()}`,
      );
      for (let i = 0; i < 5; i++) await page.locator('[data-action="step-back"]').click();
      await settle(page);
      equal(await box.inputValue(), "0.750", "after five steps back");
      equal(await span.getAttribute("data-span"), "3", "span at u = 3/4");
      assert(
        (await page.locator(".sl-table-title").textContent()).includes("3/4"),
        "caption shows u = 3/4",
      );
    },
  ],
  [
    "play advances u and pause stops it",
    async (page, _h, _base, { assert, equal, settle, PLAY_MS }) => {
      const box = page.locator('[data-control="u"] .sl-value');
      // From the start of the domain: the whole of it takes 4 s, room for a slow machine.
      await box.fill("0");
      await box.press("Enter");
      const before = Number(await box.inputValue());
      equal(before, 0, "u before play");
      const playButton = page.locator('[data-action="play"]');
      await playButton.click();
      await page.waitForTimeout(PLAY_MS);
      // On a very slow machine the run may already have reached the end and stopped by itself.
      if ((await playButton.getAttribute("aria-pressed")) === "true") await playButton.click();
      await settle(page);
      const after = Number(await box.inputValue());
      assert(after > before && after <= 4, `u went from ${before} to ${after} (domain [0, 4])`);
      await page.waitForTimeout(100);
      equal(Number(await box.inputValue()), after, "u after pause");
    },
  ],
  [
    "degree 2 gives the core's clamped knots; a decreasing knot vector is refused",
    async (page, h, _base, { assert, equal, settle }) => {
      const degree = page.locator('[data-control="degree"] .sl-value');
      await degree.fill("2");
      await degree.press("Enter");
      await settle(page);
      const knots = page.locator('[data-control="knots"] input');
      // n = 6, p = 2: three zeros, 1 … 4, three copies of 5.
      equal(await knots.inputValue(), "0 0 0 1 2 3 4 5 5 5", "clamped knots for p = 2");
      assert(
        (await h.canvas().getAttribute("aria-label")).startsWith("quadratic"),
        "quadratic now",
      );
      const good = await h.snapshot();
      await knots.fill("0 0 0 1 3 2 4 5 5 5");
      await knots.press("Enter");
      await settle(page);
      equal(await h.statusKind(), "error", "status kind");
      assert((await h.status()).includes("“knots”"), `status names the field: ${await h.status()}`);
      equal(await h.snapshot(), good, "picture kept");
      // A valid non-uniform vector is taken: u = 3/2 is then in [u₂, u₃) = [0, 2) with k = 2.
      await knots.fill("0 0 0 2 3 4 4 5 5 5");
      await knots.press("Enter");
      await settle(page);
      equal(
        await page.locator('[data-info="span"]').getAttribute("data-span"),
        "2",
        "span k in the new knots",
      );
    },
  ],
  [
    "a link with u outside the domain names the field",
    async (page, h, base, { assert, openDemo }) => {
      h = await openDemo(page, base, "de-boor", link({ ...WORKED, u: 3 }));
      const status = await h.status();
      assert(/“u”/.test(status) && status.includes("3"), `status: ${status}`);
    },
  ],
];
