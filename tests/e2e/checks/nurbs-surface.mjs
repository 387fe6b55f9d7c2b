// Browser checks of the B-spline / NURBS surface demo: knot insertion adds exactly one row and
// leaves the surface where it was (a fingerprint of 81 surface points from the page, and the
// hand-computed new knot vector and new rows), seams report the continuity a knot's
// multiplicity allows (measured by the core), and a weight changes the picture.
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
import { hashOf, typeInto, urlState } from "./helpers3d.mjs";

/** The readout's data attributes: seams, rows, cols and the surface's fingerprint. */
const readout = (page) =>
  page.locator('[data-info="seams"]').evaluate((node) => ({ ...node.dataset }));

/** The default 5-row net with a sixth row appended (heights made up), for a 6 × 6 state. */
const sixRows = (points) => [
  ...points,
  ...points.slice(24, 30).map(([x, y, z]) => [x + 2, y, z + 0.3]),
];

/**
 * Pixels of the figure canvas within 40 per channel of each hex colour, outside the seam legend
 * (the top-left 150 × 120 CSS px, whose swatches are drawn on the 2D layer). Runs in the page.
 */
function colourCounts(colours) {
  const canvas = document.querySelector(".sl-canvas");
  const g = document.createElement("canvas");
  g.width = canvas.width;
  g.height = canvas.height;
  const x = g.getContext("2d");
  x.drawImage(canvas, 0, 0);
  const d = x.getImageData(0, 0, g.width, g.height).data;
  const scale = canvas.width / canvas.getBoundingClientRect().width;
  const rgb = colours.map((hex) => [1, 3, 5].map((k) => Number.parseInt(hex.slice(k, k + 2), 16)));
  const counts = colours.map(() => 0);
  for (let py = 0; py < g.height; py++)
    for (let px = 0; px < g.width; px++) {
      if (px < 150 * scale && py < 120 * scale) continue;
      const i = 4 * (py * g.width + px);
      rgb.forEach((c, k) => {
        if (c.every((v, j) => Math.abs(d[i + j] - v) < 40)) counts[k]++;
      });
    }
  return counts;
}

export default [
  [
    "insert u at the probe adds exactly one row (the p rows of Boehm's rule highlighted) and keeps the surface",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await readout(page);
      const start = await urlState(page);
      equal(start.rows, 5, "rows");
      equal(start.u, 0.8, "the probe u");
      await page.locator('[data-action="insert-u"]').click();
      await settle(page);
      const after = await readout(page);
      const state = await urlState(page);
      equal(state.rows, 6, "rows after one insertion");
      equal(state.cols, 6, "columns after an insertion in u");
      equal(state.points.length, 36, "control points");
      equal(state.weights.length, 36, "weights");
      // u = 0.8 lies in [u_3, u_4) = [0, 1): the knot goes between 0 and 1, and Boehm's rule
      // recomputes rows k − p + 1 … k = 1 … 3 (p = 3 of them, from the 2 old rows 1 … 2).
      equal(JSON.stringify(state.knotsU), JSON.stringify([0, 0, 0, 0, 0.8, 1, 2, 2, 2, 2]), "U");
      equal(JSON.stringify(state.fresh), JSON.stringify([0, 1, 3]), "the new rows");
      equal(JSON.stringify(state.points[0]), JSON.stringify(start.points[0]), "row 0 kept");
      equal(JSON.stringify(state.points[35]), JSON.stringify(start.points[29]), "last row shifted");
      const a = Number(before.surfaceSum);
      const b = Number(after.surfaceSum);
      assert(Math.abs(a - b) <= 1e-9 * Math.abs(a), `surface fingerprint ${a} → ${b}`);
      equal(after.rows, "6", "readout rows");
      const formula = await page.locator(".sl-formula").textContent();
      assert(/rows\s*1\s*–\s*3/.test(formula), `the formula names the new rows: ${formula}`);
      // An insertion in v adds a column instead.
      await page.locator('[data-action="insert-v"]').click();
      await settle(page);
      const more = await urlState(page);
      equal(`${more.rows} × ${more.cols}`, "6 × 7", "net after inserting in v");
      equal(more.fresh[0], 1, "columns highlighted");
      const last = await readout(page);
      assert(
        Math.abs(Number(last.surfaceSum) - a) <= 1e-9 * Math.abs(a),
        `fingerprint after v: ${last.surfaceSum}`,
      );
    },
  ],
  [
    "seams: a clamped uniform bicubic is C² at every interior knot; a doubled knot gives C¹",
    async (page, h, base, { equal, openDemo }) => {
      const start = await urlState(page);
      const bicubic = {
        ...start,
        degreeV: 3,
        knotsV: [0, 0, 0, 0, 1, 2, 3, 3, 3, 3],
        v: 1.5,
      };
      delete bicubic.view;
      await openDemo(page, base, "nurbs-surface", hashOf(bicubic));
      let seams = await readout(page);
      equal(seams.seamsU, "1:2", "seams in u (knot:continuity)");
      equal(seams.seamsV, "1:2 2:2", "seams in v");
      // A new surface on a doubled knot u = 1 (a sixth row): C¹ across it.
      const doubled = {
        ...bicubic,
        rows: 6,
        knotsU: [0, 0, 0, 0, 1, 1, 2, 2, 2, 2],
        points: sixRows(bicubic.points),
        weights: Array(36).fill(1),
      };
      await openDemo(page, base, "nurbs-surface", hashOf(doubled));
      seams = await readout(page);
      equal(seams.seamsU, "1:1", "a double knot in a bicubic");
      // Inserting u = 1 into the C² surface doubles the knot but keeps the surface: still C².
      await openDemo(page, base, "nurbs-surface", hashOf({ ...bicubic, u: 1 }));
      await page.locator('[data-action="insert-u"]').click();
      seams = await readout(page);
      const inserted = await urlState(page);
      equal(JSON.stringify(inserted.knotsU), JSON.stringify([0, 0, 0, 0, 1, 1, 2, 2, 2, 2]), "U");
      equal(seams.seamsU, "1:2", "measured after inserting an existing knot");
    },
  ],
  [
    "weights: selecting a handle and raising its weight changes the picture and the surface",
    async (page, h, _base, { assert, equal, settle }) => {
      const picture = await h.snapshot();
      const before = await readout(page);
      const handles = await h.handles();
      const target = handles[8]; // P₁,₂
      await page.mouse.move(target.x, target.y);
      await page.mouse.down();
      await page.mouse.up();
      await settle(page);
      const label = await page.locator('[data-control="weight"] label').textContent();
      assert(label.includes("P₁,₂"), `the weight slider names the point: ${label}`);
      await typeInto(page, "weight", 4);
      await settle(page);
      const state = await urlState(page);
      equal(state.weights[8], 4, "weight of P₁,₂");
      equal(state.weights.filter((w) => w !== 1).length, 1, "other weights");
      assert((await h.snapshot()) !== picture, "the picture is the same after the weight");
      const after = await readout(page);
      assert(after.surfaceSum !== before.surfaceSum, "the surface did not move");
    },
  ],
  [
    "degree 4 on 5 rows gets clamped knots with no interior knot (no u seams); uniform knots shrink the domain",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="degree-u"] [data-choice="4"] input').check();
      await settle(page);
      let state = await urlState(page);
      equal(state.degreeU, 4, "degree");
      // 5 points of degree 4: n + p + 2 = 10 knots, 5 at each end, a single Bézier piece in u.
      equal(JSON.stringify(state.knotsU), JSON.stringify([0, 0, 0, 0, 0, 1, 1, 1, 1, 1]), "U");
      equal((await readout(page)).seamsU, "", "seams in u");
      await page.locator('[data-action="uniform-v"]').click();
      await settle(page);
      state = await urlState(page);
      // Uniform knots for 6 points of degree 2: 9 knots 0 … 8, domain [u_2, u_6] = [2, 6].
      equal(JSON.stringify(state.knotsV), JSON.stringify([0, 1, 2, 3, 4, 5, 6, 7, 8]), "V");
      assert(state.v >= 2 && state.v <= 6, `v = ${state.v} in the new domain`);
    },
  ],
  [
    "typed knots: a valid vector is taken (the seams follow), a wrong count is refused with the core's message",
    async (page, h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="knots-u"] input');
      await box.fill("0 0 0 0 0.5 2 2 2 2");
      await box.press("Enter");
      await settle(page);
      equal(JSON.stringify((await urlState(page)).knotsU), "[0,0,0,0,0.5,2,2,2,2]", "U");
      equal((await readout(page)).seamsU, "0.5:2", "the seam moved to the new knot");
      await box.fill("0 0 1 1");
      await box.press("Enter");
      await settle(page);
      equal(await h.statusKind(), "error", "status kind");
      const status = await h.status();
      assert(/knot/i.test(status), `the core's message: ${status}`);
      equal(JSON.stringify((await urlState(page)).knotsU), "[0,0,0,0,0.5,2,2,2,2]", "U kept");
    },
  ],
  [
    "a dense net names its corners and the selected point only (SVG export too); the announcement names every point",
    async (page, h, _base, { assert, equal, settle }) => {
      await h.canvas().focus();
      await page.keyboard.press("Home");
      for (let k = 0; k < 8; k++) await page.keyboard.press("Tab");
      await settle(page);
      // Point 8 of the 5 × 6 net: row 1, column 2.
      const live = await page.locator(".sl-figure .sl-announcer").textContent();
      assert(live.startsWith("P₁,₂ selected"), `announced: ${live}`);
      const file = await h.download("export-svg");
      const { readFileSync } = await import("node:fs");
      const svg = readFileSync(await file.path(), "utf8");
      const texts = [...svg.matchAll(/<text[^>]*>([^<]*)<\/text>/g)].map((m) => m[1]);
      const names = texts.filter((x) => /^P[₀-₉]+,[₀-₉]+$/.test(x)).sort();
      equal(names.join(" "), ["P₀,₀", "P₀,₅", "P₁,₂", "P₄,₀", "P₄,₅"].sort().join(" "), "names");
      // Another point selected: its name, announced, replaces the first one's.
      await h.canvas().focus();
      await page.keyboard.press("Tab");
      await settle(page);
      const next = await page.locator(".sl-figure .sl-announcer").textContent();
      assert(next.startsWith("P₁,₃ selected"), `announced: ${next}`);
    },
  ],
  [
    "seams are WebGL curves in their continuity's colour (C¹ orange, C² bluish green), gone with the Seams box",
    async (page, _h, base, { assert, openDemo }) => {
      const state = await urlState(page);
      const plain = { ...state, net: false, iso: false, normal: false };
      const colours = ["#E69F00", "#009E73"];
      await openDemo(page, base, "nurbs-surface", hashOf({ ...plain, seams: true }));
      const shown = await page.evaluate(colourCounts, colours);
      await openDemo(page, base, "nurbs-surface", hashOf({ ...plain, seams: false }));
      const hidden = await page.evaluate(colourCounts, colours);
      for (const k of [0, 1])
        assert(
          shown[k] > 100 && hidden[k] < shown[k] / 5,
          `${colours[k]}: ${shown[k]} pixels with seams, ${hidden[k]} without`,
        );
    },
  ],
  [
    "the Shading choice: zebra changes the picture, Gaussian K gives the curvature legend",
    async (page, h, _base, { assert, equal, settle }) => {
      const lit = await h.snapshot();
      await page.locator('[data-control="shading"] [data-choice="zebra"] input').check();
      await settle(page);
      assert((await h.snapshot()) !== lit, "zebra draws another picture");
      await page.locator('[data-control="shading"] [data-choice="gaussian"] input').check();
      await settle(page);
      const legend = JSON.parse(await page.locator(".sl-figure").getAttribute("data-legend"));
      equal(legend.shading, "gaussian", "legend shading");
      assert(legend.extent > 0, `legend extent ${legend.extent}`);
      equal((await urlState(page)).shading, "gaussian", "the shading in the URL");
    },
  ],
];
