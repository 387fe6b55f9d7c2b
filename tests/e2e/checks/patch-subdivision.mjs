// Browser checks of the patch subdivision demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers are independent of the core: S(u0, v0) by the Bernstein double sum written
// out below and by hand at (1/2, 1/2); a plane with an affine net needs exactly 2 triangles.
import { bernsteinSum, gap, hashOf, type, urlState } from "./helpers3d.mjs";

/** What the demo publishes on its readout: the four corners, S(u0, v0), the counts. */
async function published(page) {
  const data = await page.locator('[data-info="counts"]').evaluate((n) => ({ ...n.dataset }));
  const xyz = (text) => text.split(",").map(Number);
  return {
    corners: data.corners ? data.corners.split(" ").map(xyz) : null,
    point: xyz(data.point),
    triangles: data.triangles === undefined ? null : Number(data.triangles),
    uniform: data.uniform === undefined ? null : Number(data.uniform),
  };
}

/**
 * Pixel classes of the figure canvas (runs in the page): warm (red well above blue: the orange
 * and vermillion pieces), green (green well above red and a little above blue: the bluish-green
 * piece), cool (blue well above red: the single blue surface of "Adaptive").
 */
function pixelClasses() {
  const canvas = document.querySelector(".sl-canvas");
  const g = document.createElement("canvas");
  g.width = canvas.width;
  g.height = canvas.height;
  const x = g.getContext("2d");
  x.drawImage(canvas, 0, 0);
  const d = x.getImageData(0, 0, g.width, g.height).data;
  const out = { warm: 0, green: 0, cool: 0, total: g.width * g.height };
  for (let i = 0; i < d.length; i += 4) {
    const [r, gr, b] = [d[i], d[i + 1], d[i + 2]];
    if (r > b + 60) out.warm++;
    if (gr > r + 60 && gr > b + 10) out.green++;
    if (b > r + 60 && b > gr + 10) out.cool++;
  }
  return out;
}

export default [
  [
    "the four nets share one corner, S(u0, v0) (Bernstein double sum; by hand at (1/2, 1/2))",
    async (page, _h, _base, { assert, equal, settle }) => {
      const state = await urlState(page);
      let got = await published(page);
      equal(got.corners.length, 4, "four nets");
      const expected = bernsteinSum(state.points, state.u0, state.v0);
      assert(gap(got.point, expected) < 1e-12, `S ${got.point} vs Σ Σ ${expected}`);
      for (const [k, corner] of got.corners.entries())
        assert(gap(corner, expected) < 1e-12, `net ${k}'s corner ${corner} vs ${expected}`);
      // The default net P_ij = (2i, 2j, h_ij), rows 0 and 1 flat: at (1/2, 1/2) x = y = 3 and
      // z = Σ Σ C(3,i) C(3,j) h_ij / 64 = (3·11.4 + 7.8) / 64 = 42 / 64.
      await type(page, settle, "u0", "1/2");
      await type(page, settle, "v0", "1/2");
      got = await published(page);
      const hand = [3, 3, 42 / 64];
      for (const [k, corner] of got.corners.entries())
        assert(gap(corner, hand) < 1e-12, `net ${k}'s corner ${corner} vs ${hand}`);
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("0.656"), `the formula shows z = 0.656: ${formula}`);
    },
  ],
  [
    "a plane with an affine net gives 2 triangles at every tolerance",
    async (page, _h, base, { assert, equal, settle, openDemo }) => {
      const state = await urlState(page);
      // P_ij = (2i, 2j, 1 + 0.5 i − 0.25 j): every row and column evenly spaced on a line.
      const points = [];
      for (let i = 0; i < 4; i++)
        for (let j = 0; j < 4; j++) points.push([2 * i, 2 * j, 1 + 0.5 * i - 0.25 * j]);
      await openDemo(
        page,
        base,
        "patch-subdivision",
        hashOf({ ...state, points, mode: "adaptive" }),
      );
      for (const tolerance of ["2", "0.3", "0.01", "0.002"]) {
        await type(page, settle, "tolerance", tolerance);
        const { triangles } = await published(page);
        equal(triangles, 2, `triangles at ε = ${tolerance}`);
        const note = await page.locator('[data-info="counts"]').textContent();
        assert(note.startsWith("2 triangles"), `note: ${note}`);
      }
    },
  ],
  [
    "lowering the tolerance never lowers the triangle count of the default patch",
    async (page, h, _base, { assert, settle }) => {
      await page.locator('[data-control="mode"] [data-choice="adaptive"] input').check();
      await settle(page);
      assert(await page.locator('[data-control="u0"]').isHidden(), "u0 hidden in adaptive mode");
      const counts = [];
      const pictures = new Set();
      for (const tolerance of ["2", "1", "0.5", "0.2", "0.1", "0.05", "0.02", "0.01", "0.005"]) {
        await type(page, settle, "tolerance", tolerance);
        const { triangles, uniform } = await published(page);
        counts.push(triangles);
        assert(uniform >= 2, `uniform count ${uniform}`);
        pictures.add(await h.snapshot());
      }
      for (let k = 1; k < counts.length; k++)
        assert(counts[k] >= counts[k - 1], `counts fall as ε falls: ${counts.join(", ")}`);
      assert(counts.at(-1) > 4 * counts[0], `the mesh refines: ${counts.join(", ")}`);
      assert(pictures.size >= 5, `${pictures.size} different pictures`);
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes(`${counts.at(-1)} triangles`), `aria-label: ${label}`);
    },
  ],
  [
    "the four pieces are WebGL surfaces in their colours (nets off: no 2D drawing in those hues)",
    async (page, _h, base, { assert, openDemo }) => {
      const state = await urlState(page);
      await openDemo(page, base, "patch-subdivision", hashOf({ ...state, nets: false }));
      const split = await page.evaluate(pixelClasses);
      assert(split.warm > split.total * 0.05, `warm pieces: ${split.warm} of ${split.total}`);
      assert(
        split.green > split.total * 0.005,
        `bluish-green piece: ${split.green} of ${split.total}`,
      );
      await openDemo(
        page,
        base,
        "patch-subdivision",
        hashOf({ ...state, nets: false, mode: "adaptive", quadtree: false }),
      );
      const adaptive = await page.evaluate(pixelClasses);
      assert(adaptive.warm < split.warm / 10, `adaptive: ${adaptive.warm} warm pixels`);
      assert(adaptive.green < split.green / 10, `adaptive: ${adaptive.green} green pixels`);
      assert(adaptive.cool > split.total * 0.05, `adaptive: ${adaptive.cool} blue pixels`);
    },
  ],
  [
    "figure3d.camera: the first view and Reset after an orbit look from the declared direction",
    async (page, h, _base, { equal, assert, settle }) => {
      const declared = [-50, 30];
      const first = (await urlState(page)).view;
      equal(JSON.stringify(first.slice(0, 2)), JSON.stringify(declared), "first view");
      const box = await h.canvas().boundingBox();
      await h.drag({ x: box.x + box.width - 20, y: box.y + 20 }, -120, 40);
      const orbited = (await urlState(page)).view;
      assert(orbited[0] !== declared[0], `orbited to ${orbited}`);
      await page.locator('[data-action="reset"]').click();
      await settle(page);
      const reset = (await urlState(page)).view;
      equal(JSON.stringify(reset.slice(0, 2)), JSON.stringify(declared), "after Reset");
      equal(JSON.stringify(reset), JSON.stringify(first), "the same fitted camera");
    },
  ],
];
