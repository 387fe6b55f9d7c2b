// Browser checks specific to the de Casteljau demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
export default [
  [
    "worked example shows (29/16, 23/16)",
    async (page, h, _base, { assert, equal, settle }) => {
      const last = await page.locator('.sl-table td[data-level="3"][data-index="0"]').textContent();
      assert(last.includes("(29/16, 23/16)"), `last cell reads ${last}`);
      const level1 = await page
        .locator('.sl-table td[data-level="1"][data-index="1"]')
        .textContent();
      assert(level1.includes("(3, 5/2)"), `p₁¹ reads ${level1}`);
      const label = await h.canvas().getAttribute("aria-label");
      assert(/cubic/.test(label) && label.includes("(1.81, 1.44)"), `aria-label: ${label}`);
      assert(
        (await page.locator(".sl-formula").textContent()).includes("29"),
        "formula shows 29/16",
      );
    },
  ],
  [
    "step buttons move t by 1/16",
    async (page, h, _base, { assert, equal, settle }) => {
      // The controls show the state at the next frame: settle before reading them.
      const box = page.locator('[data-control="t"] .sl-value');
      await page.locator('[data-action="step"]').click();
      await settle(page);
      equal(await box.inputValue(), "0.313", "after one step");
      await page.locator('[data-action="step-back"]').click();
      await page.locator('[data-action="step-back"]').click();
      await settle(page);
      equal(await box.inputValue(), "0.188", "after two steps back");
      assert(
        (await page.locator(".sl-table-title").textContent()).includes("3/16"),
        "caption shows t = 3/16",
      );
    },
  ],
  [
    "play advances t and pause stops it",
    async (page, _h, _base, { assert, equal, settle, PLAY_MS }) => {
      const box = page.locator('[data-control="t"] .sl-value');
      const before = Number(await box.inputValue());
      await page.locator('[data-action="play"]').click();
      await page.waitForTimeout(PLAY_MS);
      await page.locator('[data-action="play"]').click();
      await settle(page);
      const after = Number(await box.inputValue());
      assert(after > before, `t went from ${before} to ${after}`);
      await page.waitForTimeout(100);
      equal(Number(await box.inputValue()), after, "t after pause");
    },
  ],
  [
    "typed fraction 1/3 is accepted",
    async (page, _h, _base, { assert, equal, settle, PLAY_MS }) => {
      const box = page.locator('[data-control="t"] .sl-value');
      await box.fill("1/3");
      await box.press("Enter");
      await settle(page);
      assert(
        (await page.locator(".sl-table-title").textContent()).includes("1/3"),
        "caption shows t = 1/3",
      );
      assert(page.url().includes("s="), "state in the URL");
    },
  ],
  [
    "+ adds a point, Delete removes it, undo/redo",
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
      await page.keyboard.press("Delete");
      await settle(page);
      equal((await h.handles()).length, 4, "points after Delete");
      await page.keyboard.press("Control+z");
      await settle(page);
      equal((await h.handles()).length, 5, "points after undo");
      await page.keyboard.press("Control+Shift+z");
      await settle(page);
      equal((await h.handles()).length, 4, "points after redo");
    },
  ],
  [
    "invalid t in a link names the field",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 1],
          ],
          t: 7,
          construction: true,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "de-casteljau", `&s=${state}`);
      const status = await h.status();
      assert(/“t”/.test(status) && status.includes("7"), `status: ${status}`);
    },
  ],
];
