// Browser checks specific to the curve–line intersection demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.

const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

/** The t column of the intersection table. */
const tCells = async (page) =>
  page.locator('.sl-table[data-table="intersections"] td[data-field="t"]').allTextContents();
const shown = async (page, info) => page.locator(`[data-info="${info}"]`).textContent();

/** The demo's state as stored in the URL. */
async function urlState(page) {
  const s = new URLSearchParams(new URL(page.url()).hash.slice(1)).get("s");
  return JSON.parse(Buffer.from(s, "base64url").toString("utf8"));
}

export default [
  [
    "default: t = 1/3, 1/2, 2/3 (computed by hand)",
    async (page, h, _base, { assert, equal }) => {
      // P = (0,−2), (3,4), (9,−4), (12,2) is point-symmetric about P(1/2) = (6, 0); the line
      // y = 1 − x/6 passes there; P(1/3) = (34/9, 10/27) and 1 − (34/9)/6 = 10/27: t = 1/3, and 2/3 by symmetry.
      equal(
        JSON.stringify(await tCells(page)),
        JSON.stringify(["0.333 = 1/3", "0.500 = 1/2", "0.667 = 2/3"]),
        "t column",
      );
      const point = await page
        .locator('.sl-table tr[data-root="0"] td[data-field="point"]')
        .textContent();
      equal(point, "(3.778, 0.370)", "P(1/3) = (34/9, 10/27)");
      equal(await shown(page, "count"), "3 intersections", "count");
      assert(
        (await shown(page, "crossings")).includes("control polygon 3 times and the curve 3 times"),
        await shown(page, "crossings"),
      );
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("3 intersections (t = 0.333, 0.500, 0.667)"), `aria-label: ${label}`);
      assert(
        (await page.locator(".sl-formula").textContent()).includes("0.667"),
        "formula lists the t values",
      );
    },
  ],
  [
    "hand-made y = 96 (t − 1/4)(t − 1/2)(t − 3/4) meets y = 0 at 1/4, 1/2, 3/4",
    async (page, h, base, { equal, openDemo }) => {
      // x = 9t (points equally spaced in x); y's Bernstein coefficients of 96 (t − 1/4)(t − 1/2)(t − 3/4)
      // = 96t³ − 144t² + 66t − 9 are −9, −9 + 66/3 = 13, −13, 9.
      h = await openDemo(
        page,
        base,
        "line-intersection",
        link({
          points: [
            [0, -9],
            [3, 13],
            [6, -13],
            [9, 9],
          ],
          line: [
            [0, 0],
            [9, 0],
          ],
          depth: 48,
        }),
      );
      equal(
        JSON.stringify(await tCells(page)),
        JSON.stringify(["0.250 = 1/4", "0.500 = 1/2", "0.750 = 3/4"]),
        "t column",
      );
      equal(
        JSON.stringify(await page.locator('.sl-table td[data-field="point"]').allTextContents()),
        JSON.stringify(["(2.250, 0.000)", "(4.500, 0.000)", "(6.750, 0.000)"]),
        "points 9t",
      );
    },
  ],
  [
    "dragging the line away: count 0 and “no intersection”",
    async (page, h, _base, { assert, equal }) => {
      const handles = await h.handles();
      equal(handles.length, 6, "P₀…P₃, A, B");
      const box = await h.canvas().boundingBox();
      // Move A and B to the top of the figure (the line then passes above the control polygon).
      for (const index of [4, 5]) {
        const handle = (await h.handles())[index];
        await h.drag(handle, 0, box.y + 15 - handle.y);
      }
      equal(await shown(page, "count"), "no intersection", "count text");
      equal((await tCells(page)).length, 0, "table rows");
      assert(
        (await page.locator(".sl-table-title").textContent()).includes("No intersection"),
        "table caption",
      );
      assert(
        (await shown(page, "crossings")).includes("control polygon 0 times and the curve 0 times"),
        await shown(page, "crossings"),
      );
      assert(
        (await h.canvas().getAttribute("aria-label")).includes("no intersection"),
        "aria-label",
      );
      // The first box is already pruned: depth 0 of 0, nothing meets the line.
      assert(
        (await shown(page, "boxes")).includes("Boxes visited: 1; meeting the line: 0; pruned: 1"),
        await shown(page, "boxes"),
      );
    },
  ],
  [
    "both line handles are keyboard-nudgeable",
    async (page, h, _base, { assert, equal, settle }) => {
      const start = await h.handles();
      await h.canvas().focus();
      await page.keyboard.press("End"); // B, the last handle
      await page.keyboard.press("Shift+ArrowUp");
      await page.keyboard.press("Shift+Tab"); // A
      await page.keyboard.press("Shift+ArrowDown");
      await settle(page);
      const moved = await h.handles();
      assert(
        Math.abs(moved[5].y - (start[5].y - 10)) < 0.6 && Math.abs(moved[5].x - start[5].x) < 0.6,
        `B at ${JSON.stringify(moved[5])} from ${JSON.stringify(start[5])}`,
      );
      assert(
        Math.abs(moved[4].y - (start[4].y + 10)) < 0.6 && Math.abs(moved[4].x - start[4].x) < 0.6,
        `A at ${JSON.stringify(moved[4])} from ${JSON.stringify(start[4])}`,
      );
      const line = (await urlState(page)).line;
      assert(line[0][1] < 1 && line[1][1] > -1, `line in the URL state: ${JSON.stringify(line)}`);
      // The line turned about its midpoint (6, 0) = P(1/2): the middle root stays, the outer ones move.
      const ts = await tCells(page);
      equal(ts[1], "0.500 = 1/2", "middle root");
      assert(ts[0] !== "0.333 = 1/3" && ts[2] !== "0.667 = 2/3", `outer roots moved: ${ts}`);
    },
  ],
  [
    "the depth slider steps through the recursion",
    async (page, h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="depth"] .sl-value');
      const full = await h.snapshot();
      await box.fill("0");
      await box.press("Enter");
      await settle(page);
      // Depth 0: the whole curve's box only, and the line meets it.
      assert(
        (await shown(page, "boxes")).includes("Boxes visited: 1; meeting the line: 1; pruned: 0"),
        await shown(page, "boxes"),
      );
      const level0 = await h.snapshot();
      assert(level0 !== full, "fewer boxes drawn at depth 0");
      await page.locator('[data-action="depth-up"]').click();
      await settle(page);
      // Depth 1: the two halves at t = 1/2 are visited too.
      assert((await shown(page, "boxes")).startsWith("Depth 1 of"), await shown(page, "boxes"));
      assert(
        (await shown(page, "boxes")).includes("Boxes visited: 3;"),
        await shown(page, "boxes"),
      );
      equal(await box.inputValue(), "1", "slider box");
      equal((await urlState(page)).depth, 1, "depth in the URL state");
      // The roots do not depend on the boxes shown.
      equal((await tCells(page)).length, 3, "roots at depth 1");
      await box.fill("abc");
      await box.press("Enter");
      assert((await h.status()).includes("depth"), `status names the field: ${await h.status()}`);
    },
  ],
];
