// Browser checks specific to the projective demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
//
// Default: the square [0,4]² goes to the trapezoid (6,0), (12,0), (10.5,4), (7.5,4). By hand
// (unit square → quadrilateral): Σ = Q₀ − Q₁ + Q₂ − Q₃ = (−3, 0), Δ₁ = Q₁ − Q₂ = (1.5, −4),
// Δ₂ = Q₃ − Q₂ = (−3, 0), so g = 0, h = 1: w′ = w·(1 + y/4). The control points have
// y = 0.5, 3.5, 0.5, 3.5, so the mapped weights are 9/8, 15/8, 9/8, 15/8.

const gaps = (page) => page.locator('[data-info="gaps"]');
const mappedWeights = async (page) =>
  (await page.locator('[data-info="mapped-weights"]').getAttribute("data-weights"))
    .split(",")
    .map(Number);

export default [
  [
    "mapped curve = pointwise-mapped samples; ignoring the new weights is not invariant",
    async (page, h, _base, { assert, equal }) => {
      const ab = Number(await gaps(page).getAttribute("data-gap-ab"));
      const ac = Number(await gaps(page).getAttribute("data-gap-ac"));
      assert(ab < 1e-9, `(a) vs (b): ${ab}`);
      assert(ac > 1e-3, `(c) vs (a): ${ac}`);
      const w = await mappedWeights(page);
      equal(
        JSON.stringify(w),
        JSON.stringify([1.125, 1.875, 1.125, 1.875]),
        "mapped weights 9/8, 15/8, 9/8, 15/8",
      );
      assert(
        (await h.canvas().getAttribute("aria-label")).includes(
          "weights 1.125, 1.875, 1.125, 1.875",
        ),
        "aria-label lists the mapped weights",
      );
    },
  ],
  [
    "an affine map keeps the weights, and then the contrast curve coincides",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-action="affine"]').click();
      await settle(page);
      equal(JSON.stringify(await mappedWeights(page)), "[1,1,1,1]", "weights after an affine map");
      assert(
        Number(await gaps(page).getAttribute("data-gap-ac")) < 1e-9,
        "(c) coincides for an affine map",
      );
      assert(Number(await gaps(page).getAttribute("data-gap-ab")) < 1e-9, "(a) = (b)");
    },
  ],
  [
    "a corner dragged so a weight would cross zero shows the library's error and keeps the picture",
    async (page, h, _base, { assert, equal, settle }) => {
      const handles = await h.handles();
      const [q0, q1, q2] = [handles[4], handles[5], handles[6]];
      const scale = (q1.x - q0.x) / 6; // Q₀ = (6, 0), Q₁ = (12, 0): px per unit
      // Q₂ from (10.5, 4) to (8, 1): across the diagonal Q₁Q₃, the quadrilateral folds.
      await h.drag(q2, -2.5 * scale, 3 * scale);
      equal(await h.statusKind(), "error", "status kind");
      const status = await h.status();
      assert(status.includes("weights must stay > 0"), `status: ${status}`);
      const after = (await h.handles())[6];
      assert(
        Math.hypot(after.x - q2.x - 2.5 * scale, after.y - q2.y + 3 * scale) > scale,
        "Q₂ did not follow into the refused position",
      );
      assert(
        Number(await gaps(page).getAttribute("data-gap-ab")) < 1e-9,
        "the last good picture is still invariant",
      );
      // Still alive: a control point can be dragged, and a good corner move clears the message.
      const before = await h.snapshot();
      const [, p1] = await h.handles();
      await h.drag(p1, 10, 10);
      assert((await h.snapshot()) !== before, "still draggable");
      const q2now = (await h.handles())[6];
      await h.drag(q2now, 5, 0);
      assert(
        !(await h.status()).includes("weights must stay > 0"),
        "the message clears after a good move",
      );
    },
  ],
];
