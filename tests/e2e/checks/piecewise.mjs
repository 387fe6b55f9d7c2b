// Browser checks specific to the piecewise demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected verdicts by hand (syllabus §1, the notes' exercise): piece 1 is x = 1 − t², y = t on
// [0, 1], so P(1⁻) = (0, 1), P′(1⁻) = (−2, 1), P″(1⁻) = (−2, 0). On [1, 2] with y = t:
//   x = 2 − t²        → P(1⁺) = (1, 1): not C⁰ (c = −1);
//   x = t² − 4t + 3   → (0, 1), P′ = (−2, 1), P″ = (2, 0): C¹, and not C² (x″ jumps);
//                       curvature x′y″ − y′x″ = 2 on the left, −2 on the right: G¹, not G²;
//   x = t² − 2t + 1   → (0, 1), P′ = (0, 1): C⁰, and the directions differ: G⁰;
// and x = 1 − (2t − 1)², y = 2t − 1 on [1, 3/2] is the same parabola at double speed:
// P′(1⁺) = (−4, 2) = 2 P′(1⁻): C⁰ only, G¹ at least (the same curve: G as high as it is counted).

/** The joints readout's verdicts, "c,g,exact;…" (the core's joints()). */
const verdicts = (page, scope = "") =>
  page.locator(`${scope}[data-info="joints"]`).getAttribute("data-verdicts");

/** The text box of piece i's field. */
const box = (page, i, field, scope = "") =>
  page.locator(`${scope}input[data-piece="${i}"][data-field="${field}"]`);

/** Types `text` into a box as a reader would (select all, type), then settles. */
async function typeInto(page, locator, text, settle) {
  await locator.click();
  await page.keyboard.press("Control+a");
  await page.keyboard.type(text);
  await settle(page);
}

export default [
  [
    "the notes' exercise: not C⁰, C¹ (not C²), C⁰ not C¹, and G¹ not C¹, each proven",
    async (page, h, _base, { assert, equal, settle }) => {
      const expected = {
        notC0: (c) => c === -1,
        c1: (c, g) => c === 1 && g === 1,
        c0: (c, g) => c === 0 && g === 0,
        g1: (c, g) => c === 0 && g >= 1,
      };
      const pictures = new Set();
      for (const [key, ok] of Object.entries(expected)) {
        await page.locator(`[data-action="preset-${key}"]`).click();
        await settle(page);
        const [c, g, exact] = (await verdicts(page)).split(",");
        assert(ok(Number(c), Number(g)), `${key}: c = ${c}, g = ${g}`);
        equal(exact, "true", `${key}: polynomial pieces are proven exactly`);
        pictures.add(await h.snapshot());
        const label = await h.canvas().getAttribute("aria-label");
        assert(label.includes("t = 1"), `${key}: aria-label names the joint: ${label}`);
      }
      equal(pictures.size, 4, "four different pictures");
    },
  ],
  [
    "the one-sided values side by side: C¹ case x′(1⁻) = x′(1⁺) = −2, x″ differs first",
    async (page, _h, _base, { assert, equal, settle }) => {
      await page.locator('[data-action="preset-c1"]').click();
      await settle(page);
      const rows = page.locator('[data-table="joint"] tbody tr');
      const texts = await rows.evaluateAll((trs) =>
        trs.map((tr) => [...tr.children].map((c) => c.textContent)),
      );
      const row = (name) => texts.find((cells) => cells[0] === name);
      equal(row("x′")[1], "x′(1⁻) = −2", "x′ from the left");
      equal(row("x′")[2], "x′(1⁺) = −2", "x′ from the right");
      equal(row("x″")[1], "x″(1⁻) = −2", "x″ from the left");
      equal(row("x″")[2], "x″(1⁺) = 2", "x″ from the right");
      equal(row("x″")[3], "no", "x″ differs");
      const highlighted = await page
        .locator('[data-table="joint"] tr.sl-highlight')
        .evaluateAll((trs) => trs.map((tr) => tr.dataset.order));
      assert(
        highlighted.length > 0 && highlighted.every((k) => k === "2"),
        `the first order that differs is marked: ${highlighted}`,
      );
    },
  ],
  [
    "a typing error underlines the characters, says why and keeps the last good curve",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      const verdict = await verdicts(page);
      const x = box(page, 1, "x");
      await typeInto(page, x, "t^2 - 4t + 3)", settle);
      equal(await x.getAttribute("aria-invalid"), "true", "the box is marked invalid");
      const bad = page.locator('[data-piece="1"] .sl-expr-bad');
      equal(await bad.textContent(), ")", "the stray parenthesis is underlined");
      equal(await h.statusKind(), "error", "status kind");
      const message = await page.locator('[data-piece="1"] .sl-expr-message').textContent();
      assert(message.length > 10, `the reason under the piece: ${message}`);
      equal(await h.snapshot(), before, "the last good curve stays");
      equal(await verdicts(page), verdict, "and its verdict");
      assert(!page.url().includes(")"), "the refused text is not in the link");
      // Fixing the text takes the mark away and the curve follows.
      await page.keyboard.press("Backspace");
      await page.keyboard.type(".5");
      await settle(page);
      equal(await x.getAttribute("aria-invalid"), null, "the mark is gone");
      assert((await h.snapshot()) !== before, "the new curve is drawn");
      equal((await verdicts(page)).split(",")[0], "-1", "x(1⁺) = 0.5: not C⁰");
    },
  ],
  [
    "a typing error is explained in the page's language (Croatian)",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      const english = await (async () => {
        await typeInto(page, box(page, 1, "x"), "t^2 - 4t + 3)", settle);
        return page.locator('[data-piece="1"] .sl-expr-message').textContent();
      })();
      await openDemo(page, base, "piecewise", "", "hr");
      await typeInto(page, box(page, 1, "x"), "t^2 - 4t + 3)", settle);
      const croatian = await page.locator('[data-piece="1"] .sl-expr-message').textContent();
      assert(croatian.startsWith("Segment 2, x(t): "), `Croatian frame: ${croatian}`);
      // The core's reason too (lib/core-errors.js, coreError.<code> of the locale).
      const reason = (text) => text.slice(text.indexOf(": ") + 2);
      assert(
        reason(croatian) !== reason(english),
        `the reason is Croatian: ${reason(croatian)} (English: ${reason(english)})`,
      );
      equal(await h.statusKind(), "error", "status kind");
    },
  ],
  [
    "a bound is one joint: typing piece 1's end moves piece 2's start; undo takes it back",
    async (page, h, _base, { equal, settle }) => {
      await typeInto(page, box(page, 0, "to"), "1/2", settle);
      equal(await box(page, 1, "from").inputValue(), "1/2", "piece 2 starts where piece 1 ends");
      await h.canvas().focus();
      await page.keyboard.press("Control+z");
      await settle(page);
      equal(await box(page, 0, "to").inputValue(), "1", "undo: piece 1 ends at 1 again");
      equal(await box(page, 1, "from").inputValue(), "1", "and piece 2 starts there");
    },
  ],
  [
    "Add a piece / Remove the last piece: a third piece and a second joint, then back",
    async (page, _h, _base, { equal, settle }) => {
      const pieces = page.locator("fieldset.sl-piece");
      equal(await pieces.count(), 2, "two pieces at first");
      await page.locator('[data-action="add-piece"]').click();
      await settle(page);
      equal(await pieces.count(), 3, "three pieces");
      equal((await verdicts(page)).split(";").length, 2, "two joints");
      equal(await box(page, 2, "from").inputValue(), "2", "the new piece starts at 2");
      await page.locator('[data-action="remove-piece"]').click();
      await page.locator('[data-action="remove-piece"]').click();
      await settle(page);
      equal(await pieces.count(), 1, "one piece");
      equal(await verdicts(page), "", "no joint");
      equal(
        await page.locator('[data-action="remove-piece"]').isDisabled(),
        true,
        "one piece stays",
      );
    },
  ],
  [
    "zooming in far and out again re-plots the pieces for the window without errors",
    async (page, h, _base, { assert, settle }) => {
      const start = await h.snapshot();
      const box = await h.canvas().boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      for (let k = 0; k < 12; k++) await page.mouse.wheel(0, -240);
      await settle(page);
      const zoomed = await h.snapshot();
      assert(zoomed !== start, "the zoom changed the picture");
      for (let k = 0; k < 24; k++) await page.mouse.wheel(0, 240);
      await settle(page);
      assert((await h.snapshot()) !== zoomed, "zoomed out again");
    },
  ],
  [
    '<spline-lab demo="piecewise" pieces="…"> reads the pieces attribute',
    async (page, _h, base, { assert, equal }) => {
      const url = `${base}/piecewise-embed-test.html`;
      await page.route(url, (route) =>
        route.fulfill({
          contentType: "text/html",
          body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="p" demo="piecewise" pieces="1 - t^2, t, 0, 1; t^2 - 2t + 1, t, 1, 2"></spline-lab><spline-lab id="bad" demo="piecewise" pieces="1 - t^2, t, 0"></spline-lab></body></html>',
        }),
      );
      try {
        await page.goto(url);
        const scope = "spline-lab#p ";
        await page.locator(`${scope}.sl-formula .katex`).first().waitFor({ state: "attached" });
        const [c, g] = (await verdicts(page, scope)).split(",");
        equal(`${c},${g}`, "0,0", "C⁰ not C¹ from the attribute");
        equal(await box(page, 1, "x", scope).inputValue(), "t^2 - 2t + 1", "piece 2's x");
        const bad = "spline-lab#bad ";
        await page.locator(`${bad}.sl-status`).first().waitFor({ state: "attached" });
        await page.waitForFunction(
          () =>
            document.querySelector("spline-lab#bad")?.shadowRoot?.querySelector(".sl-status")
              ?.textContent.length > 0,
        );
        const status = await page.locator(`${bad}.sl-status`).first().textContent();
        assert(status.includes("pieces"), `a record of three texts is refused: ${status}`);
      } finally {
        await page.unroute(url);
      }
    },
  ],
];
