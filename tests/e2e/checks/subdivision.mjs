// Browser checks specific to the subdivision demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers: the worked example of the Greek notes (syllabus §2), de Casteljau by hand.

/** Exact text of the left or right control point i in the table. */
const cell = (page, side, i) =>
  page.locator(`.sl-table td[data-side="${side}"][data-index="${i}"] .sl-cell-value`).textContent();

/** Types a value into a slider's box (data-control name) and waits for the redraw. */
async function type(page, settle, control, text) {
  const box = page.locator(`[data-control="${control}"] .sl-value`);
  await box.fill(text);
  await box.press("Enter");
  await settle(page);
}

export default [
  [
    "t₀ = 1/4 gives the worked example's two halves",
    async (page, h, _base, { assert, equal, settle }) => {
      await type(page, settle, "t", "1/4");
      const left = ["(0, 0)", "(1/2, 1/2)", "(9/8, 1)", "(29/16, 23/16)"];
      const right = ["(29/16, 23/16)", "(31/8, 11/4)", "(13/2, 7/2)", "(8, 2)"];
      for (let i = 0; i < 4; i++) {
        equal(await cell(page, "left", i), left[i], `l${i}`);
        equal(await cell(page, "right", i), right[i], `r${i}`);
      }
      assert(
        (await page.locator(".sl-table-title").textContent()).includes("t₀ = 1/4"),
        "caption shows t₀ = 1/4",
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("t₀ = 0.250") && label.includes("(1.81, 1.44)"),
        `aria-label: ${label}`,
      );
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("29") && formula.includes("31"), "formula lists the halves");
    },
  ],
  [
    "level 3 shows 8 polygons with 32 control points",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      await type(page, settle, "levels", "1");
      assert(
        (await page.locator('[data-info="levels"]').textContent()).includes(
          "2 polygons, 8 control points (7 distinct",
        ),
        "level 1",
      );
      await type(page, settle, "levels", "3");
      const note = await page.locator('[data-info="levels"]').textContent();
      assert(
        note.includes("Level 3: 8 polygons, 32 control points (25 distinct"),
        `levels note: ${note}`,
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("level 3: 8 polygons with 32 control points"), `aria-label: ${label}`);
      assert((await h.snapshot()) !== before, "the picture shows the polygons");
      await type(page, settle, "levels", "6");
      assert(
        (await page.locator('[data-info="levels"]').textContent()).includes("64 polygons"),
        "level 6: 64 polygons",
      );
      assert(
        /[?&#]s=/.test(page.url()) && (await page.evaluate(() => location.hash)).length > 20,
        "state in the URL",
      );
    },
  ],
  [
    "changing t₀ moves the split point",
    async (page, h, _base, { assert, equal, settle }) => {
      // t₀ = 1/2: P(1/2) = (0 + 3·2 + 3·6 + 8, 0 + 3·2 + 3·4 + 2)/8 = (4, 5/2).
      equal(await cell(page, "left", 3), "(4, 5/2)", "l₃ at 1/2");
      equal(await cell(page, "right", 0), "(4, 5/2)", "r₀ at 1/2");
      const before = await h.snapshot();
      // t₀ = 3/4: weights 1/64, 9/64, 27/64, 27/64 → (396/64, 180/64) = (99/16, 45/16).
      await type(page, settle, "t", "3/4");
      equal(await cell(page, "left", 3), "(99/16, 45/16)", "l₃ at 3/4");
      equal(await cell(page, "right", 0), "(99/16, 45/16)", "r₀ at 3/4");
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("(6.19, 2.81)"),
        "aria-label follows",
      );
      assert((await h.snapshot()) !== before, "picture changed");
      await page.locator('[data-action="step"]').click();
      await settle(page);
      equal(
        await page.locator('[data-control="t"] .sl-value').inputValue(),
        "0.813",
        "t₀ after one step",
      );
    },
  ],
  [
    "an invalid level in a link names the field",
    async (page, h, base, { assert, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 1],
            [2, 0],
          ],
          t: 0.5,
          levels: 7,
          triangle: true,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "subdivision", `&s=${state}`);
      const status = await h.status();
      assert(/“levels”/.test(status) && status.includes("7"), `status: ${status}`);
    },
  ],
];
