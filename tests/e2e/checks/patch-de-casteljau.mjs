// Browser checks of the patch de Casteljau demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers are independent of the core: the Bernstein double sum written out below, a
// point worked by hand (S(1/2, 1/2) of the default net), bilinear interpolation for degree 1,
// and the construction's point counts counted by hand.
import { bernsteinSum, gap, type, urlState } from "./helpers3d.mjs";

/** The numbers the demo publishes on its step readout: "x,y,z" → [x, y, z]. */
async function published(page) {
  const data = await page.locator('[data-info="step"]').evaluate((n) => ({ ...n.dataset }));
  const xyz = (text) => text.split(",").map(Number);
  return {
    levelPoints: Number(data.levelPoints),
    rowsFirst: xyz(data.rowsFirst),
    columnsFirst: xyz(data.columnsFirst),
    evaluate: xyz(data.evaluate),
  };
}

export default [
  [
    "S(u, v) from both orders equals evaluate and the Bernstein double sum; S(1/2, 1/2) by hand",
    async (page, _h, _base, { assert, settle }) => {
      const state = await urlState(page);
      let got = await published(page);
      const expected = bernsteinSum(state.points, state.u, state.v);
      for (const key of ["rowsFirst", "columnsFirst", "evaluate"])
        assert(gap(got[key], expected) < 1e-12, `${key} ${got[key]} vs Σ Σ ${expected}`);
      assert(gap(got.rowsFirst, got.columnsFirst) < 1e-14, "rows first = columns first");
      // The default net P_ij = (2i, 2j, h_ij) at (1/2, 1/2): x = y = 3 (linear precision) and
      // z = Σ Σ C(3,i) C(3,j) h_ij / 64 = (6.6 + 3·12.6 + 3·8.4 + 5.6) / 64 = 75.2 / 64.
      await type(page, settle, "u", "1/2");
      await type(page, settle, "v", "1/2");
      got = await published(page);
      const hand = [3, 3, 75.2 / 64];
      assert(gap(got.rowsFirst, hand) < 1e-12, `rows first ${got.rowsFirst} vs ${hand}`);
      assert(gap(got.columnsFirst, hand) < 1e-12, `columns first ${got.columnsFirst}`);
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("3.000") && formula.includes("1.175"), `formula: ${formula}`);
    },
  ],
  [
    "the steps reveal 16, 28, 36, 44, 47, 49, 50 construction points of the bicubic patch",
    async (page, h, _base, { assert, equal, settle }) => {
      // Rows first: the 4 × 4 net (16); each row's levels 1, 2, 3 add 3, 2, 1 points per row
      // (28, 36, 40), the column's level 0 is the 4 row results (44), then 3, 2, 1 (47, 49, 50).
      const counts = [16, 28, 36, 44, 47, 49, 50];
      equal((await published(page)).levelPoints, 50, "points at the default (last) step");
      const pictures = new Set();
      for (let k = 0; k <= 6; k++) {
        await type(page, settle, "step", String(k));
        equal((await published(page)).levelPoints, counts[k], `points at step ${k}`);
        const note = await page.locator('[data-info="step"]').textContent();
        assert(note.startsWith(`Step ${k} of 6`), `step note: ${note}`);
        pictures.add(await h.snapshot());
      }
      equal(pictures.size, 7, "a different picture at every step");
    },
  ],
  [
    "columns first draws another construction and reaches the same point",
    async (page, h, _base, { assert, settle }) => {
      const before = await h.snapshot();
      const rows = await published(page);
      await page.locator('[data-control="order"] [data-choice="columns"] input').check();
      await settle(page);
      assert((await h.snapshot()) !== before, "the picture is the same in the other order");
      const columns = await published(page);
      assert(gap(columns.columnsFirst, rows.rowsFirst) < 1e-14, "the same point");
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("columns first"), `aria-label: ${label}`);
      const formula = await page.locator(".sl-formula").textContent();
      assert(
        formula.includes("rows first") && formula.includes("columns first"),
        `the formula names both orders: ${formula}`,
      );
      assert((await urlState(page)).order === "columns", "order in the URL");
    },
  ],
  [
    "degree 1 × 1 is bilinear interpolation of the four corners (9 construction points)",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="degree"] [data-choice="1"] input').check();
      await settle(page);
      equal((await h.handles()).length, 4, "handles of a 2 × 2 net");
      const { points, u, v } = await urlState(page);
      const [a, b, c, d] = points; // P00, P01, P10, P11
      const bilinear = [0, 1, 2].map(
        (k) => (1 - u) * (1 - v) * a[k] + (1 - u) * v * b[k] + u * (1 - v) * c[k] + u * v * d[k],
      );
      const got = await published(page);
      assert(gap(got.rowsFirst, bilinear) < 1e-12, `S ${got.rowsFirst} vs ${bilinear}`);
      // 2 rows × 3 + 3 for the column.
      equal(got.levelPoints, 9, "construction points");
      equal((await urlState(page)).step, 2, "the whole construction is shown");
    },
  ],
];
