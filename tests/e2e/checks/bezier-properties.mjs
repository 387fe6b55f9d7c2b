// Browser checks specific to the Bézier properties demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers by hand from the syllabus' worked example P0=(0,0), P1=(2,2), P2=(6,4), P3=(8,2):
// its y(t) = 6t − 4t³ rises to 2√2 ≈ 2.83 at t = 1/√2 and ends at 2.

/** The readout in the side panel (its data attributes carry the numbers). */
const readout = (page) => page.locator('[data-info="property"]');

/** A link state: the default with some fields replaced. */
function link(fields) {
  const state = {
    points: [
      [0, 0],
      [2, 2],
      [6, 4],
      [8, 2],
    ],
    property: "hull",
    rotation: 20,
    scale: 0.8,
    shear: -0.3,
    elevations: 2,
    line: [
      [-1, 3],
      [9, 3],
    ],
    ...fields,
  };
  return `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;
}

/** Types a value into a slider's box and presses Enter. */
async function typeInto(page, control, value) {
  const box = page.locator(`[data-control="${control}"] .sl-value`);
  await box.fill(String(value));
  await box.press("Enter");
}

export default [
  [
    "degree elevation adds one control point per elevation; one step gives the hand-computed Q_i",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="property"] input[value="elevation"]').check();
      await settle(page);
      equal(
        await readout(page).getAttribute("data-polygon-points"),
        "6",
        "4 points + 2 elevations",
      );
      for (const [count, expected] of [
        [5, "9"],
        [8, "12"],
        [0, "4"],
        [1, "5"],
      ]) {
        await typeInto(page, "elevations", count);
        await settle(page);
        equal(
          await readout(page).getAttribute("data-polygon-points"),
          expected,
          `${count} elevations`,
        );
      }
      // Q_i = i/4 P_{i−1} + (1 − i/4) P_i: (0,0), (3/2,3/2), (4,3), (13/2,7/2), (8,2).
      const cells = await page.locator('[data-table="elevation"] td').allTextContents();
      equal(
        JSON.stringify(cells),
        JSON.stringify(["(0, 0)", "(3/2, 3/2)", "(4, 3)", "(13/2, 7/2)", "(8, 2)"]),
        "after one elevation",
      );
      equal((await h.handles()).length, 4, "the control points themselves stay");
    },
  ],
  [
    "variation diminishing: crossing counts for horizontal lines through the worked example",
    async (page, h, base, { assert, equal, openDemo }) => {
      // y = 3: the polygon rises through it on P1P2 and falls on P2P3; the curve peaks at 2.83.
      // y = 2.5: polygon twice, curve twice (up to 2.83, down to 2). y = 1.5: once each (on P0P1; the curve ends at 2).
      for (const [y, polygon, curve] of [
        [3, "2", "0"],
        [2.5, "2", "2"],
        [1.5, "1", "1"],
      ]) {
        h = await openDemo(
          page,
          base,
          "bezier-properties",
          link({
            property: "variation",
            line: [
              [-1, y],
              [9, y],
            ],
          }),
        );
        equal(
          await readout(page).getAttribute("data-polygon-crossings"),
          polygon,
          `polygon crossings for y = ${y}`,
        );
        equal(
          await readout(page).getAttribute("data-curve-crossings"),
          curve,
          `curve crossings for y = ${y}`,
        );
        const text = await readout(page).textContent();
        assert(
          text.includes(`polygon ${polygon} times`) && text.includes(`curve ${curve} times`),
          `readout: ${text}`,
        );
        equal((await h.handles()).length, 6, "four control points and the line's two");
      }
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("1 times and the curve 1 times"), `aria-label: ${label}`);
    },
  ],
  [
    "reversed order draws the same curve: largest gap 0.000, also after a drag",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="property"] input[value="reversed"]').check();
      await settle(page);
      equal(
        await readout(page).getAttribute("data-max-distance"),
        "0.000",
        "largest gap between P(t) and R(1 − t)",
      );
      const [, p1] = await h.handles();
      await h.drag(p1, 35, -45);
      equal(await readout(page).getAttribute("data-max-distance"), "0.000", "after dragging P1");
    },
  ],
  [
    "affine map: mapped curve points lie on the curve of the mapped points",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="property"] input[value="affine"]').check();
      await settle(page);
      equal(await readout(page).getAttribute("data-max-distance"), "0.000", "default map");
      const before = await h.snapshot();
      await typeInto(page, "shear", 1);
      await typeInto(page, "rotation", -135);
      await settle(page);
      assert((await h.snapshot()) !== before, "the map changed the picture");
      equal(
        await readout(page).getAttribute("data-max-distance"),
        "0.000",
        "after shear 1 and rotation −135°",
      );
    },
  ],
  [
    "convex hull: 4 vertices for the worked example, 3 when a point is inside",
    async (page, h, base, { equal, openDemo }) => {
      equal(await readout(page).getAttribute("data-hull-vertices"), "4", "worked example");
      // (4, 1) lies inside the triangle (0,0), (2,4), (8,0).
      h = await openDemo(
        page,
        base,
        "bezier-properties",
        link({
          points: [
            [0, 0],
            [4, 1],
            [2, 4],
            [8, 0],
          ],
        }),
      );
      equal(await readout(page).getAttribute("data-hull-vertices"), "3", "one point inside");
    },
  ],
];
