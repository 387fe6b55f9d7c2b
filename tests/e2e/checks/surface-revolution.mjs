// Browser checks of the surface-revolution demo (run after the generic ones by run.mjs): the torus
// is exact and its net has the NURBS Book's row count (A8.1: 1, 2, 3 or 4 arcs → 3, 5, 7, 9 rows),
// the extrusion's two edges differ by the direction, a ruled surface's middle is the midpoint of
// its curves (hand-computed Bézier points), and a mode switch keeps a valid URL that restores.
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
import { hashOf, typeInto, urlState } from "./helpers3d.mjs";

/** The default state with some fields changed (no camera: the demo fits one). */
async function stateWith(page, changes) {
  const state = { ...(await urlState(page)), ...changes };
  delete state.view;
  return state;
}

/** The readout's published numbers: data-rows, data-distance, data-s0 … as numbers / lists. */
async function published(page) {
  return page.locator('[data-info="check"]').evaluate((node) => {
    const out = {};
    for (const [key, value] of Object.entries(node.dataset)) {
      if (key === "info") continue;
      out[key] = value.includes(",") ? value.split(",").map(Number) : Number(value);
    }
    return out;
  });
}

const near = (a, b, tolerance) => a.every((x, k) => Math.abs(x - b[k]) <= tolerance);

export default [
  [
    "torus: the core's grid lies on the torus to 1e-12; 9 net rows at 360°, 3 at 90°, 5 at 180°",
    async (page, _h, base, { assert, equal, openDemo, settle }) => {
      await openDemo(
        page,
        base,
        "surface-revolution",
        hashOf(await stateWith(page, { mode: "torus", R: 2.5, r: 0.75 })),
      );
      let p = await published(page);
      assert(p.distance < 1e-12, `max distance to the torus ${p.distance}`);
      // Four 90° arcs → 2·4 + 1 = 9 points around; the circle profile has 9 too.
      equal(p.rows, 9, "rows at 360°");
      equal(p.cols, 9, "columns (the circle's 9 points)");
      const formula = await page.locator(".sl-formula").textContent();
      assert(
        /10\s*[−-]\s*1[4-7]/.test(formula),
        `the formula shows the measured distance: ${formula}`,
      );
      for (const [angle, rows] of [
        [90, 3],
        [180, 5],
        [270, 7],
      ]) {
        await typeInto(page, "angle", angle);
        await settle(page);
        p = await published(page);
        equal(p.rows, rows, `rows at ${angle}°`);
        assert(p.distance < 1e-12, `max distance at ${angle}°: ${p.distance}`);
      }
    },
  ],
  [
    "torus: dragging the circle's centre C changes R; the surface stays on the new torus",
    async (page, h, base, { assert, openDemo }) => {
      await openDemo(
        page,
        base,
        "surface-revolution",
        hashOf(await stateWith(page, { mode: "torus" })),
      );
      const before = await urlState(page);
      const [centre] = await h.handles();
      await h.drag(centre, 40, 0);
      const after = await urlState(page);
      assert(after.R !== before.R, `R ${before.R} → ${after.R}`);
      const box = page.locator('[data-control="R"] .sl-value');
      assert(Number(await box.inputValue()) === after.R, "the R slider follows");
      const p = await published(page);
      assert(p.distance < 1e-12, `max distance to the torus with R = ${after.R}: ${p.distance}`);
    },
  ],
  [
    "vase: from an orbited camera a profile point stays under the pointer in y = 0, mesh buffers refilled in place",
    async (page, h, _base, { assert, equal }) => {
      const box = await h.canvas().boundingBox();
      // Azimuth −60° → about −100°: the plane y = 0 seen well from the front.
      await h.drag({ x: box.x + 20, y: box.y + 20 }, 60, 30);
      const made = () => page.locator(".sl-figure").getAttribute("data-geometries");
      const geometries = await made();
      const start = await urlState(page);
      const handle = (await h.handles())[3];
      await h.drag(handle, 30, -20);
      const moved = (await h.handles())[3];
      assert(
        Math.abs(moved.x - handle.x - 30) < 1.5 && Math.abs(moved.y - handle.y + 20) < 1.5,
        `P₃ at ${JSON.stringify(moved)}, expected ${JSON.stringify(handle)} + (30, −20)`,
      );
      const now = await urlState(page);
      assert(now.profile[3][0] !== start.profile[3][0], "the profile point moved");
      equal(now.profile[3].length, 2, "a profile point is [x, z]");
      equal(await made(), geometries, "geometries made during the drag");
      const p = await published(page);
      equal(p.rows, 9, "rows around the axis");
      equal(p.cols, 6, "one column per profile point");
    },
  ],
  [
    "extrude: S(u, 1) − S(u, 0) equals the direction, also after dragging its tip",
    async (page, h, base, { assert, openDemo }) => {
      const direction = [1.5, -2, 0.75];
      await openDemo(
        page,
        base,
        "surface-revolution",
        hashOf(await stateWith(page, { mode: "extrude", direction })),
      );
      let p = await published(page);
      const difference = (q) => q.s1.map((x, k) => x - q.s0[k]);
      assert(near(difference(p), direction, 1e-12), `S(u,1) − S(u,0) = ${difference(p)}`);
      // The tip handle d is the last one; drag it and compare with the direction in the URL.
      const handles = await h.handles();
      await h.drag(handles[handles.length - 1], 30, -20);
      const moved = (await urlState(page)).direction;
      assert(!near(moved, direction, 1e-9), `the direction changed: ${moved}`);
      p = await published(page);
      assert(near(difference(p), moved, 1e-12), `after the drag ${difference(p)} vs ${moved}`);
    },
  ],
  [
    "ruled: S(u, ½) is the midpoint of A(u) and B(u), both as the Bézier formulas give them",
    async (page, _h, base, { assert, equal, openDemo }) => {
      const curveA = [
        [0, 0, 0],
        [2, 4, 2],
        [4, 0, 0],
      ];
      const curveB = [
        [0, 0, 4],
        [1, -3, 4],
        [3, 3, 4],
        [4, 0, 8],
      ];
      await openDemo(
        page,
        base,
        "surface-revolution",
        hashOf(await stateWith(page, { mode: "ruled", curveA, curveB })),
      );
      const p = await published(page);
      equal(p.u, 0.5, "u of the check");
      // A(½) = (A0 + 2A1 + A2)/4 = (2, 2, 1); B(½) = (B0 + 3B1 + 3B2 + B3)/8 = (2, 0, 4.5).
      assert(near(p.a, [2, 2, 1], 1e-12), `A(½) = ${p.a}`);
      assert(near(p.b, [2, 0, 4.5], 1e-12), `B(½) = ${p.b}`);
      assert(near(p.mid, [2, 1, 2.75], 1e-12), `S(½, ½) = ${p.mid}`);
      // A quadratic and a cubic made compatible: degree 3, so 4 rows; degree 1 in v, 2 columns.
      equal(p.rows, 4, "rows");
      equal(p.cols, 2, "columns");
    },
  ],
  [
    "a mode switch keeps every mode's points in a valid URL that restores; switching back gives the first picture",
    async (page, h, _base, { assert, equal, settle }) => {
      const start = await urlState(page);
      equal(start.mode, "vase", "default mode");
      const first = await h.snapshot();
      await page.locator('[data-control="mode"] input[value="torus"]').check();
      await settle(page);
      const torus = await urlState(page);
      equal(torus.mode, "torus", "mode in the URL");
      equal(JSON.stringify(torus.profile), JSON.stringify(start.profile), "profile kept");
      equal(JSON.stringify(torus.curveB), JSON.stringify(start.curveB), "curve B kept");
      equal((await published(page)).rows, 9, "the torus net");
      const picture = await h.snapshot();
      assert(picture !== first, "the picture changed with the mode");
      await page.reload();
      await h.ready();
      equal((await urlState(page)).mode, "torus", "mode after reload");
      equal(await h.snapshot(), picture, "snapshot after reload");
      for (const mode of ["extrude", "ruled", "vase"]) {
        await page.locator(`[data-control="mode"] input[value="${mode}"]`).check();
        equal((await urlState(page)).mode, mode, `mode ${mode} in the URL`);
      }
      equal(await h.snapshot(), first, "the vase again, under the same camera");
      assert((await h.statusKind()) !== "error", `no error: ${await h.status()}`);
    },
  ],
  [
    "extrude: dragging P₂ moves only P₂ (the direction and the other points unchanged), the profile stays in z = 0",
    async (page, h, base, { assert, equal, openDemo }) => {
      await openDemo(
        page,
        base,
        "surface-revolution",
        hashOf(await stateWith(page, { mode: "extrude" })),
      );
      const before = await urlState(page);
      await h.drag((await h.handles())[2], 25, -15);
      const after = await urlState(page);
      assert(
        JSON.stringify(after.profile[2]) !== JSON.stringify(before.profile[2]),
        `P₂ moved: ${after.profile[2]}`,
      );
      for (const k of [0, 1, 3, 4, 5])
        equal(JSON.stringify(after.profile[k]), JSON.stringify(before.profile[k]), `P${k}`);
      equal(JSON.stringify(after.direction), JSON.stringify(before.direction), "direction");
      // S(u, 0) is a point of the profile curve: in the plane z = 0 exactly.
      equal((await published(page)).s0[2], 0, "z of S(u, 0) after the drag");
    },
  ],
  [
    "ruled: dragging A₁ moves only A₁; curve B unchanged",
    async (page, h, base, { assert, equal, openDemo }) => {
      await openDemo(
        page,
        base,
        "surface-revolution",
        hashOf(await stateWith(page, { mode: "ruled" })),
      );
      const before = await urlState(page);
      await h.drag((await h.handles())[1], 30, 20);
      const after = await urlState(page);
      assert(
        JSON.stringify(after.curveA[1]) !== JSON.stringify(before.curveA[1]),
        `A₁ moved: ${after.curveA[1]}`,
      );
      equal(JSON.stringify(after.curveA[0]), JSON.stringify(before.curveA[0]), "A₀");
      equal(JSON.stringify(after.curveA[2]), JSON.stringify(before.curveA[2]), "A₂");
      equal(JSON.stringify(after.curveB), JSON.stringify(before.curveB), "curve B");
    },
  ],
  [
    "vase: + after P₂ adds P₃ in the middle of P₂P₃ (selected), Delete removes it again",
    async (page, h, _base, { assert, equal, settle }) => {
      const start = await urlState(page);
      const handle = (await h.handles())[2];
      await page.mouse.click(handle.x, handle.y);
      await page.keyboard.press("+");
      await settle(page);
      const added = await urlState(page);
      equal(added.profile.length, 7, "profile points after +");
      const [a, b] = [start.profile[2], start.profile[3]];
      // The middle of the leg, rounded to what the view resolves.
      const middle = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      assert(
        near(added.profile[3], middle, 0.01),
        `the new point ${added.profile[3]} vs ${middle}`,
      );
      equal((await h.handles()).length, 7, "handles after +");
      const live = await page.locator(".sl-figure .sl-announcer").textContent();
      equal(live.split(" ")[0], "P₃", `the new point is selected: ${live}`);
      await page.keyboard.press("Delete");
      await settle(page);
      equal(
        JSON.stringify((await urlState(page)).profile),
        JSON.stringify(start.profile),
        "after Delete",
      );
    },
  ],
  [
    "vase: PageUp / PageDown on a profile point (held in y = 0) change nothing and announce nothing",
    async (page, h, _base, { equal, settle }) => {
      const handle = (await h.handles())[3];
      await page.mouse.click(handle.x, handle.y);
      await settle(page);
      const before = await urlState(page);
      const announcer = page.locator(".sl-figure .sl-announcer");
      const said = await announcer.textContent();
      for (const key of ["PageUp", "PageUp", "PageDown"]) await page.keyboard.press(key);
      await settle(page);
      equal(JSON.stringify(await urlState(page)), JSON.stringify(before), "the state");
      equal(await announcer.textContent(), said, "the announcement");
      // An arrow still moves it (in its plane).
      await page.keyboard.press("ArrowRight");
      await settle(page);
      const after = await urlState(page);
      equal(after.profile[3].length, 2, "still [x, z]");
      equal(after.profile[3][0] !== before.profile[3][0], true, "ArrowRight moved P₃");
    },
  ],
];
