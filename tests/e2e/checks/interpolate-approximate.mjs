// Browser checks specific to the interpolate-approximate demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Expected values by hand: with as many control points as data points the fit interpolates
// (every residual 0); a degree-1 fit with 2 control points and both ends exact has no freedom
// left: it is the chord p₀pₙ traversed in proportion to the chord-length parameters, so
// C(t_k) = p₀ + (t_k / t_n)(pₙ − p₀) and each residual is computed here from the points alone.

const POINTS = [
  [0, 0],
  [2, 4],
  [4, 5],
  [6, 2],
  [8, -3],
  [10, -5],
  [12, -2],
  [14, 3],
  [16, 5],
  [18, 3],
];

const link = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;
const fit = (page) => page.locator('[data-info="fit"]');
const residualMax = async (page) => Number(await fit(page).getAttribute("data-residual-max"));
const residualSum = async (page) => Number(await fit(page).getAttribute("data-residual-sum"));

export default [
  [
    "as many control points as points: interpolation, the largest residual is ~0",
    async (page, h, _base, { assert, settle }) => {
      const least = await residualMax(page);
      assert(least > 0.05, `the default fit (6 control points) has residuals: ${least}`);
      const box = page.locator('[data-control="count"] .sl-value');
      await box.fill("10");
      await box.press("Enter");
      await settle(page);
      const max = await residualMax(page);
      assert(max < 1e-9, `largest residual at count = 10: ${max}`);
      assert((await fit(page).textContent()).includes("Interpolation"), "the panel says so");
      // A drag re-solves: the curve still meets every point, the dragged one included.
      const handles = await h.handles();
      await h.drag(handles[4], 0, 60);
      const after = await residualMax(page);
      assert(after < 1e-9, `largest residual after dragging p₄: ${after}`);
      assert((await h.canvas().getAttribute("aria-label")).includes("interpolation"), "aria");
    },
  ],
  [
    "least squares keeps both ends exact: the first and last residuals are 0",
    async (page, _h, _base, { assert, settle }) => {
      const box = page.locator('[data-control="count"] .sl-value');
      for (const count of [4, 5, 7]) {
        await box.fill(String(count));
        await box.press("Enter");
        await settle(page);
        const ends = (await fit(page).getAttribute("data-residual-ends")).split(",").map(Number);
        assert(
          ends.every((e) => e < 1e-9),
          `end residuals at ${count}: ${ends}`,
        );
        assert((await residualMax(page)) > 0.05, `a fit with ${count} control points misses`);
      }
    },
  ],
  [
    "degree 1 with 2 control points is the chord p₀p₉: residuals by hand",
    async (page, _h, base, { assert, openDemo }) => {
      await openDemo(
        page,
        base,
        "interpolate-approximate",
        link({ points: POINTS, degree: 1, role: "data", count: 2 }),
      );
      const t = [0];
      for (let k = 1; k < POINTS.length; k++) {
        const [x0, y0] = POINTS[k - 1];
        const [x1, y1] = POINTS[k];
        t.push(t[k - 1] + Math.hypot(x1 - x0, y1 - y0));
      }
      const n = POINTS.length - 1;
      const [ex, ey] = POINTS[n];
      let max = 0;
      let sum = 0;
      POINTS.forEach(([x, y], k) => {
        const s = t[k] / t[n];
        const d = Math.hypot(x - s * ex, y - s * ey);
        max = Math.max(max, d);
        sum += d * d;
      });
      const shownMax = await residualMax(page);
      const shownSum = await residualSum(page);
      assert(Math.abs(shownMax - max) < 1e-9, `largest residual ${shownMax}, by hand ${max}`);
      assert(Math.abs(shownSum - sum) < 1e-9, `Σ residual² ${shownSum}, by hand ${sum}`);
    },
  ],
  [
    "as control points: no residuals, no count slider, handles named P₀ …",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="role"] [data-choice="control"] label').click();
      await settle(page);
      assert(await page.locator('[data-control="count"]').isHidden(), "count slider hidden");
      equal(await fit(page).getAttribute("data-residual-max"), null, "no residuals");
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("control points"), `aria-label: ${label}`);
      assert((await page.locator(".sl-formula").textContent()).includes("P"), "formula in P_i");
    },
  ],
  [
    "an interpolation stays one when a point is added",
    async (page, h, _base, { equal, settle }) => {
      const box = page.locator('[data-control="count"] .sl-value');
      await box.fill("10");
      await box.press("Enter");
      await settle(page);
      await page.locator('[data-action="add-point"]').click();
      await settle(page);
      equal((await h.handles()).length, 11, "points");
      equal(await box.inputValue(), "11", "control points follow");
    },
  ],
];
