// Browser checks of the first 3D demo (run after the generic ones by run.mjs): WebGL really
// draws (SwiftShader in headless Chromium), the camera orbits and lives in the URL, the keyboard
// moves points in depth, exports carry the surface, one rendering worker serves several 3D
// figures (the page itself draws them where it cannot start), and 2D pages never load three.js.
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
import { hashOf, urlState } from "./helpers3d.mjs";

/**
 * Counts pixels of an image (a canvas, or PNG bytes as base64) in the surface's blue family
 * (the front #0072B2 lit, the back #8EC3E6): blue well above red. Runs in the page.
 */
function countBlue({ selector, png }) {
  const measure = (source, w, h) => {
    const c = document.createElement("canvas");
    c.width = w;
    c.height = h;
    const g = c.getContext("2d");
    g.drawImage(source, 0, 0);
    const d = g.getImageData(0, 0, w, h).data;
    let blue = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 2] > 90 && d[i + 2] > d[i] + 60) blue++;
    return { blue, total: w * h, corner: [d[0], d[1], d[2], d[3]] };
  };
  if (png) {
    const img = new Image();
    img.src = `data:image/png;base64,${png}`;
    return img.decode().then(() => measure(img, img.naturalWidth, img.naturalHeight));
  }
  const canvas = document.querySelector(selector);
  return measure(canvas, canvas.width, canvas.height);
}

/** The camera's eye from its six numbers (z up; as the orbit test writes it out). */
const eyeOf = ([a, e, d, tx, ty, tz]) => {
  const r = Math.PI / 180;
  return [
    tx + d * Math.cos(e * r) * Math.cos(a * r),
    ty + d * Math.cos(e * r) * Math.sin(a * r),
    tz + d * Math.sin(e * r),
  ];
};

/** The default state with every 2D overlay off and `changes` (no camera: fitted). */
async function plainState(page, changes) {
  const state = { ...(await urlState(page)), net: false, iso: false, sweep: false, normal: false };
  delete state.view;
  return { ...state, ...changes };
}

/**
 * Pixel classes of the figure canvas (runs in the page): not background (non-white), near black,
 * vermillion-ish (red well above blue), blue-ish (blue well above red), and every 4th pixel's
 * RGB quantised to 32 levels (to compare two pictures).
 */
function pixelClasses() {
  const canvas = document.querySelector(".sl-canvas");
  const g = document.createElement("canvas");
  g.width = canvas.width;
  g.height = canvas.height;
  const x = g.getContext("2d");
  x.drawImage(canvas, 0, 0);
  const d = x.getImageData(0, 0, g.width, g.height).data;
  const out = { inked: 0, black: 0, warm: 0, cool: 0, total: g.width * g.height, sample: [] };
  for (let i = 0; i < d.length; i += 4) {
    const [r, gr, b] = [d[i], d[i + 1], d[i + 2]];
    if (r < 245 || gr < 245 || b < 245) out.inked++;
    if (r < 60 && gr < 60 && b < 60) out.black++;
    if (r > b + 60) out.warm++;
    if (b > r + 60) out.cool++;
    if (i % 16 === 0) out.sample.push((r >> 3) * 1024 + (gr >> 3) * 32 + (b >> 3));
  }
  return out;
}

export default [
  [
    "a fitted camera shows every corner of the box inside its frame, one of them on the edge",
    async (_page, _h, _base, { assert }) => {
      // The camera's projection written out (look-at basis, perspective division), not through
      // camera3d.js: each corner's tangent across and up must stay within the frame's half
      // angles, tan(15°)·1.6 across and tan(15°) up.
      const { fitCamera, FIELD_OF_VIEW, REFERENCE_ASPECT } = await import(
        "../../../www/lib/camera3d.js"
      );
      const r = Math.PI / 180;
      const tanV = Math.tan((FIELD_OF_VIEW / 2) * r);
      const boxes = [
        [0, 0, -0.4, 6, 6, 3],
        [-1, -2, -3, 4, 1, 0.5],
        [10, 10, 10, 10.5, 30, 11],
      ];
      for (const box of boxes) {
        for (const [az, el] of [
          [-60, 28],
          [45, -30],
          [170, 80],
        ]) {
          const [a, e, d, tx, ty, tz] = fitCamera(box, az, el);
          const eye = [
            tx + d * Math.cos(e * r) * Math.cos(a * r),
            ty + d * Math.cos(e * r) * Math.sin(a * r),
            tz + d * Math.sin(e * r),
          ];
          const f = [tx - eye[0], ty - eye[1], tz - eye[2]].map((x) => x / d);
          const right = [f[1], -f[0], 0].map((x) => x / Math.hypot(f[0], f[1]));
          const up = [
            right[1] * f[2] - right[2] * f[1],
            right[2] * f[0] - right[0] * f[2],
            right[0] * f[1] - right[1] * f[0],
          ];
          let widest = 0;
          for (let k = 0; k < 8; k++) {
            const c = [0, 1, 2].map((i) => (k & (1 << i) ? box[i + 3] : box[i]));
            const rel = c.map((x, i) => x - eye[i]);
            const dot = (w) => rel[0] * w[0] + rel[1] * w[1] + rel[2] * w[2];
            const depth = dot(f);
            const across = Math.abs(dot(right)) / depth / (tanV * REFERENCE_ASPECT);
            const high = Math.abs(dot(up)) / depth / tanV;
            widest = Math.max(widest, across, high);
          }
          assert(
            widest <= 1 + 1e-4 && widest > 0.85,
            `box ${box} from (${az}, ${el}): the farthest corner at ${widest} of the frame`,
          );
        }
      }
    },
  ],
  [
    "WebGL draws the lit surface (non-blank pixels with every 2D overlay off)",
    async (page, h, base, { assert, openDemo }) => {
      const state = {
        ...(await urlState(page)),
        net: false,
        iso: false,
        sweep: false,
        normal: false,
      };
      delete state.view;
      await openDemo(page, base, "bezier-patch", hashOf(state));
      const { blue, total } = await page.evaluate(countBlue, { selector: ".sl-canvas" });
      assert(blue > total * 0.05, `only ${blue} of ${total} pixels are surface blue`);
    },
  ],
  [
    "where the rendering worker cannot start (its script unreachable, as on a course page of another origin) the page draws the surface itself",
    async (page, h, base, { assert, equal, openDemo }) => {
      const state = hashOf(await plainState(page, {}));
      const worker = "**/lib/gl-worker.js";
      await page.route(worker, (route) => route.abort());
      try {
        await openDemo(page, base, "bezier-patch", state);
        const { blue, total } = await page.evaluate(countBlue, { selector: ".sl-canvas" });
        assert(blue > total * 0.05, `only ${blue} of ${total} pixels are surface blue`);
        const gl = await page.evaluate(async () => ({
          alive: (await import("./lib/gl-client.js")).glWorkerAlive(),
          page: (await import("./lib/shared-gl.js")).sharedRendererMade(),
        }));
        equal(JSON.stringify(gl), JSON.stringify({ alive: false, page: true }), "renderers");
      } finally {
        await page.unroute(worker);
      }
    },
  ],
  [
    "a rendering worker that fails after drawing hands its figure to the page: the surface stays, three.js loads, and changes are drawn by the page",
    async (page, _h, base, { assert, equal, openDemo, settle }) => {
      await openDemo(page, base, "bezier-patch", hashOf(await plainState(page, {})));
      const renderers = () =>
        page.evaluate(async () => ({
          alive: (await import("./lib/gl-client.js")).glWorkerAlive(),
          page: (await import("./lib/shared-gl.js")).sharedRendererMade(),
        }));
      equal(JSON.stringify(await renderers()), '{"alive":true,"page":false}', "before");
      // The worker reports a failure, as it does when its WebGL fails (gl-worker.js "error").
      const worker = page.workers().find((w) => w.url().endsWith("/gl-worker.js"));
      assert(worker, "the rendering worker");
      await worker.evaluate(() => self.postMessage({ type: "error", message: "test: lost" }));
      // The page loads three.js, then draws the figure with its own renderer.
      let after = "";
      for (let wait = 0; wait < 100 && after !== '{"alive":false,"page":true}'; wait++) {
        await page.waitForTimeout(100);
        after = JSON.stringify(await renderers());
      }
      equal(after, '{"alive":false,"page":true}', "after");
      await settle(page);
      const { blue, total } = await page.evaluate(countBlue, { selector: ".sl-canvas" });
      assert(blue > total * 0.05, `only ${blue} of ${total} pixels are surface blue`);
      // A change after the loss: drawn by the page's renderer.
      await page.locator('[data-control="shading"] [data-choice="zebra"] input').check();
      await settle(page);
      const zebra = await page.evaluate(pixelClasses);
      assert(zebra.black > zebra.total * 0.02, `zebra after the loss: ${zebra.black} black`);
    },
  ],
  [
    "zebra, Gaussian and mean shadings draw the surface in their own pixels (and differ from lit)",
    async (page, _h, base, { assert, openDemo, settle }) => {
      const shots = {};
      await openDemo(page, base, "bezier-patch", hashOf(await plainState(page, {})));
      for (const shading of ["lit", "zebra", "gaussian", "mean"]) {
        // The panel's Shading choice (one page: the radio buttons, then a drawn frame).
        await page.locator(`[data-control="shading"] [data-choice="${shading}"] input`).check();
        await settle(page);
        shots[shading] = await page.evaluate(pixelClasses);
        const { inked, total } = shots[shading];
        assert(inked > total * 0.05, `${shading}: only ${inked} of ${total} pixels drawn`);
      }
      // Zebra: black and white bands, no blue; curvature: both ends of the scale (the default
      // patch has K and H of both signs: saddles and domes).
      assert(shots.zebra.black > shots.zebra.total * 0.02, `zebra: ${shots.zebra.black} black`);
      assert(shots.zebra.cool < shots.lit.cool / 10, `zebra: ${shots.zebra.cool} blue pixels`);
      for (const k of ["gaussian", "mean"]) {
        assert(
          shots[k].warm > 500 && shots[k].cool > 500,
          `${k}: ${shots[k].warm} warm, ${shots[k].cool} cool`,
        );
        assert(shots[k].black < shots.zebra.black / 10, `${k}: ${shots[k].black} black pixels`);
      }
      const names = Object.keys(shots);
      for (let a = 0; a < names.length; a++)
        for (let b = a + 1; b < names.length; b++) {
          const [p, q] = [shots[names[a]].sample, shots[names[b]].sample];
          let differ = 0;
          for (let i = 0; i < p.length; i++) if (p[i] !== q[i]) differ++;
          assert(
            differ > p.length * 0.03,
            `${names[a]} and ${names[b]}: ${differ} of ${p.length} samples differ`,
          );
        }
    },
  ],
  [
    "the curvature legend's end numbers are ± the largest |K| (|H|) of the core's curvatures at the mesh vertices; a flat patch shows 0",
    async (page, h, base, { assert, equal, openDemo }) => {
      const three = new Intl.NumberFormat("en", {
        maximumSignificantDigits: 3,
        useGrouping: false,
      });
      for (const [shading, which, title] of [
        ["gaussian", 0, "Gaussian curvature K"],
        ["mean", 1, "mean curvature H"],
      ]) {
        const state = await plainState(page, { shading });
        await openDemo(page, base, "bezier-patch", hashOf(state));
        const legend = JSON.parse(await page.locator(".sl-figure").getAttribute("data-legend"));
        // The core's numbers at the 41 × 41 vertices of the demo's mesh (tessellate(40, 40)).
        const [min, max] = await page.evaluate(
          async ({ points, which }) => {
            const sl = await (await import("./lib/wasm.js")).loadWasm();
            const patch = new sl.BezierSurface(points.flat(), 4, 4);
            const values = patch.curvatures(patch.tessellate(40, 40).uvs);
            patch.free();
            let lo = Infinity;
            let hi = -Infinity;
            for (let i = which; i < values.length; i += 2) {
              lo = Math.min(lo, values[i]);
              hi = Math.max(hi, values[i]);
            }
            return [lo, hi];
          },
          { points: state.points, which },
        );
        assert(min < 0 && max > 0, `${shading}: both signs on the default patch (${min}, ${max})`);
        equal(legend.shading, shading, "legend shading");
        equal(legend.min, min, `${shading} min`);
        equal(legend.max, max, `${shading} max`);
        const extent = Math.max(-min, max);
        equal(legend.extent, extent, `${shading} extent`);
        equal(
          JSON.stringify(legend.ends),
          JSON.stringify([three.format(-extent), three.format(extent)]),
          `${shading} ends`,
        );
        const svg = (await import("node:fs")).readFileSync(
          await (await h.download("export-svg")).path(),
          "utf8",
        );
        for (const text of [...legend.ends, title])
          assert(svg.includes(`>${text}<`), `${shading}: the SVG legend has "${text}"`);
      }
      // A plane (every height 0): K = H = 0 everywhere, the ends read 0 and 0.
      const flat = await plainState(page, { shading: "gaussian" });
      flat.points = flat.points.map(([x, y]) => [x, y, 0]);
      await openDemo(page, base, "bezier-patch", hashOf(flat));
      const legend = JSON.parse(await page.locator(".sl-figure").getAttribute("data-legend"));
      equal(JSON.stringify(legend.ends), JSON.stringify(["0", "0"]), "plane: legend ends");
      const lit = await plainState(page, { shading: "lit" });
      await openDemo(page, base, "bezier-patch", hashOf(lit));
      equal(
        await page.locator(".sl-figure").getAttribute("data-legend"),
        null,
        "no legend when lit",
      );
    },
  ],
  [
    "handles the surface hides are those the core's line intersection finds behind it; a click there still picks one",
    async (page, h, base, { assert, equal, openDemo }) => {
      await openDemo(page, base, "bezier-patch");
      const state = await urlState(page);
      const eye = eyeOf(state.view);
      // Exact: the surface meets the segment eye → P before P (s < 0.99) by intersectLine.
      const expected = await page.evaluate(
        async ({ points, eye }) => {
          const sl = await (await import("./lib/wasm.js")).loadWasm();
          const patch = new sl.BezierSurface(points.flat(), 4, 4);
          const hidden = [];
          points.forEach((p, i) => {
            const d = [p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]];
            const hits = patch.intersectLine(eye, d, 1e-9);
            for (let k = 2; k < hits.length; k += 3)
              if (hits[k] > 0 && hits[k] < 0.99) return void hidden.push(i);
          });
          patch.free();
          return hidden.join(",");
        },
        { points: state.points, eye },
      );
      assert(expected.length > 0, "the default view hides some handle");
      equal(
        await page.locator(".sl-figure").getAttribute("data-hidden-handles"),
        expected,
        "hidden handles",
      );
      const i = Number(expected.split(",").at(-1));
      const at = (await h.handles())[i];
      await page.mouse.click(at.x, at.y);
      await h.ready();
      const live = await page.locator(".sl-figure .sl-announcer").textContent();
      const sub = "₀₁₂₃";
      const name = `P${sub[Math.floor(i / 4)]}${sub[i % 4]}`;
      assert(live.startsWith(`${name} selected`), `announced: ${live} (expected ${name})`);
      equal((await urlState(page)).points.length, 16, "points kept");
    },
  ],
  [
    "picking: a visible handle under the pointer wins over a nearer one the surface hides",
    async (page, _h, _base, { equal }) => {
      // Handles3D against a stand-in view: projection (x, y, depth) = the point itself, and
      // `occluded` naming which points the surface hides. Both handles lie within the hit radius
      // of the pointer at (102, 100); the hidden one is nearer the camera (depth 0.2 < 0.6).
      const picks = await page.evaluate(async () => {
        const { Handles3D } = await import("./lib/handles3d.js");
        const pick = (points, hidden, occlusion = true) => {
          const host = document.createElement("div");
          const view = {
            canvas: document.createElement("canvas"),
            host,
            addInteractor() {},
            beforeFrame() {},
            requestDraw() {},
            project(x, y, z, out) {
              out[0] = x;
              out[1] = y;
              out[2] = z;
              return out;
            },
            ...(occlusion
              ? {
                  occluded: (x, y, z) => hidden.some((p) => p[0] === x && p[1] === y && p[2] === z),
                }
              : {}),
          };
          const handles = new Handles3D(view, {
            count: () => points.length,
            get: (i, out) => out.set(points[i]),
            label: (i) => `P${i}`,
            move() {},
            commit() {},
          });
          const i = handles.hitTest(102, 100, "mouse");
          handles.destroy();
          return i;
        };
        const hiddenNear = [100, 100, 0.2];
        const visibleFar = [106, 100, 0.6];
        return [
          pick([hiddenNear, visibleFar], [hiddenNear]),
          pick([hiddenNear], [hiddenNear]),
          pick([hiddenNear, visibleFar], [hiddenNear], false),
          pick([hiddenNear, visibleFar], []),
        ];
      });
      equal(picks[0], 1, "the visible handle, though farther");
      equal(picks[1], 0, "the hidden handle when it is alone under the pointer");
      equal(picks[2], 0, "without occlusion: the nearer");
      equal(picks[3], 0, "both visible: the nearer");
    },
  ],
  [
    "scene curves: { points, colour, width } entries are drawn in their colour (WebGL: a ribbon when wider than 1 px; SVG), plain arrays as iso-curves",
    async (page, _h, _base, { equal }) => {
      const out = await page.evaluate(async () => {
        const { loadThree } = await import("./lib/three-loader.js");
        const { SceneContent, SURFACE_COLOURS } = await import("./lib/scene3d.js");
        const { drawVectorScene } = await import("./lib/draw3d.js");
        const { THREE } = await loadThree();
        const content = new SceneContent(THREE);
        const line = (z) => Float64Array.from([0, 0, z, 1, 0, z, 2, 1, z]);
        const spec = (z) => ({
          curves: [{ points: line(z), colour: "#D55E00", width: 3 }, line(z)],
        });
        content.update(spec(0));
        content.update(spec(1)); // new arrays of the same length: refilled in place
        // The wide curve (width 3) is a ribbon (its colour a uniform), the plain one a line.
        const [wide, plain] = content.curveSlots;
        const rgb = wide.ribbon.material.uniforms.colour.value;
        const hex = (x) =>
          Math.round(x * 255)
            .toString(16)
            .padStart(2, "0");
        const colours = [
          `#${hex(rgb.x)}${hex(rgb.y)}${hex(rgb.z)}`,
          `#${plain.line.material.color.getHexString()}`,
        ];
        const shown = [wide.ribbon.visible, wide.line.visible, plain.line.visible];
        const z = wide.ribbon.geometry.getAttribute("position").array[2];
        const made = content.geometriesMade;
        content.dispose();
        const strokes = [];
        const r = {
          theme: {},
          beginPath() {},
          moveTo() {},
          lineTo() {},
          paint: (style) => strokes.push(`${style.stroke} ${style.width}`),
        };
        const view = {
          project(x, y, _z, o) {
            o[0] = x;
            o[1] = y;
            o[2] = 0;
            return o;
          },
        };
        drawVectorScene(r, view, spec(0));
        return { colours, shown, z, made, strokes, iso: SURFACE_COLOURS.iso };
      });
      equal(
        JSON.stringify(out.colours),
        JSON.stringify(["#d55e00", out.iso.toLowerCase()]),
        "WebGL colours",
      );
      equal(JSON.stringify(out.shown), "[true,false,true]", "ribbon, no line; the plain line");
      equal(out.z, 1, "refilled with the second arrays");
      equal(out.made, 2, "geometries made (one per curve, none on the refill)");
      equal(
        JSON.stringify(out.strokes),
        JSON.stringify(["#D55E00 3", `${out.iso} 1`]),
        "SVG strokes",
      );
    },
  ],
  [
    "an orbit (drag on empty space) changes the picture and the camera in the URL; reload restores it",
    async (page, h, _base, { assert, equal }) => {
      const before = await h.snapshot();
      const camera = (await urlState(page)).view;
      equal(camera.length, 6, "the camera has 6 numbers");
      const box = await h.canvas().boundingBox();
      await h.drag({ x: box.x + box.width - 20, y: box.y + 20 }, -120, 40);
      const after = await h.snapshot();
      assert(after !== before, "the picture is the same after an orbit");
      const orbited = (await urlState(page)).view;
      assert(orbited[0] !== camera[0], `azimuth ${camera[0]} → ${orbited[0]}`);
      // z stays up (orbit-gesture.js): a drag across the canvas' height turns a full circle, left
      // is towards a larger azimuth, down towards a larger elevation.
      const height = box.height;
      const expected = [camera[0] + (360 * 120) / height, camera[1] + (360 * 40) / height];
      assert(
        Math.abs(orbited[0] - expected[0]) < 0.5 && Math.abs(orbited[1] - expected[1]) < 0.5,
        `camera ${orbited} after a (−120, 40) px drag on ${height} px, expected ≈ ${expected}`,
      );
      await page.reload();
      await h.ready();
      equal(JSON.stringify((await urlState(page)).view), JSON.stringify(orbited), "camera");
      equal(await h.snapshot(), after, "snapshot after reload");
    },
  ],
  [
    "a drag refills the mesh and curve buffers in place: no new geometry while dragging",
    async (page, h, _base, { assert, equal }) => {
      const made = () => page.locator(".sl-figure").getAttribute("data-geometries");
      const before = await made();
      assert(Number(before) >= 15, `${before} geometries (surface and 14 iso-curves)`);
      const snapshot = await h.snapshot();
      const [, handle] = await h.handles();
      await h.drag(handle, 30, -25);
      assert((await h.snapshot()) !== snapshot, "the drag changed the picture");
      equal(await made(), before, "geometries made during the drag");
      await page.locator('[data-control="wireframe"] input').check();
      await page.waitForFunction((n) => {
        const now = document.querySelector(".sl-figure").dataset.geometries;
        return Number(now) === Number(n) + 1;
      }, before);
    },
  ],
  [
    "arrows with no point selected orbit; PageUp moves the selected point towards the viewer",
    async (page, h, _base, { assert, equal }) => {
      const start = await urlState(page);
      await h.canvas().focus();
      await page.keyboard.press("Escape");
      await page.keyboard.press("ArrowLeft");
      const orbited = await urlState(page);
      assert(orbited.view[0] !== start.view[0], `azimuth ${start.view[0]} → ${orbited.view[0]}`);
      equal(JSON.stringify(orbited.points), JSON.stringify(start.points), "points kept");
      // P₀₀ towards the camera: its distance to the camera shrinks, its screen position stays.
      const handle = (await h.handles())[0];
      await page.keyboard.press("Home");
      await page.keyboard.press("PageUp");
      const moved = await urlState(page);
      const [a, e, dist, tx, ty, tz] = moved.view;
      const r = Math.PI / 180;
      const eye = [
        tx + dist * Math.cos(e * r) * Math.cos(a * r),
        ty + dist * Math.cos(e * r) * Math.sin(a * r),
        tz + dist * Math.sin(e * r),
      ];
      const far = (p) => Math.hypot(p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]);
      assert(
        far(moved.points[0]) < far(start.points[0]),
        `P₀₀ ${start.points[0]} → ${moved.points[0]}`,
      );
      const now = (await h.handles())[0];
      assert(
        Math.hypot(now.x - handle.x, now.y - handle.y) < 1.5,
        `on the screen ${JSON.stringify(handle)} → ${JSON.stringify(now)}`,
      );
      const live = await page.locator(".sl-figure .sl-announcer").textContent();
      assert(/^P₀₀ moved to \(/.test(live), `announced: ${live}`);
    },
  ],
  [
    "play sweeps the generatrix (v advances, the picture changes), pause stops it",
    async (page, h, _base, { assert, settle, PLAY_MS }) => {
      const box = page.locator('[data-control="v"] .sl-value');
      const before = Number(await box.inputValue());
      const picture = await h.snapshot();
      await page.locator('[data-action="play"]').click();
      await page.waitForTimeout(PLAY_MS);
      await page.locator('[data-action="play"]').click();
      await settle(page); // the frame after the pause: panel and formula from the same state
      // On a loaded machine the formula may be typeset a few frames after the panel: give it
      // up to 20 frames to show the panel's v.
      let after = Number(await box.inputValue());
      let formula = "";
      for (let k = 0; k < 20; k++) {
        formula = await page.locator(".sl-formula").textContent();
        if (formula.includes(after.toFixed(3))) break;
        await settle(page);
        after = Number(await box.inputValue());
      }
      assert(after !== before, `v ${before} → ${after}`);
      assert((await h.snapshot()) !== picture, "the picture is the same");
      assert(formula.includes(after.toFixed(3)), `the formula shows v = ${after}: ${formula}`);
    },
  ],
  [
    "PNG export has the WebGL surface on white; SVG export has the projected iso-curves",
    async (page, h, _base, { assert, equal }) => {
      const png = (await import("node:fs")).readFileSync(
        await (await h.download("export-png")).path(),
      );
      const image = await page.evaluate(countBlue, { png: png.toString("base64") });
      equal(JSON.stringify(image.corner), "[255,255,255,255]", "white background");
      assert(image.blue > image.total * 0.03, `${image.blue} of ${image.total} pixels are blue`);
      const svg = (await import("node:fs")).readFileSync(
        await (await h.download("export-svg")).path(),
        "utf8",
      );
      const iso = svg.match(/stroke="#00466E"/gi)?.length ?? 0;
      assert(iso >= 14, `${iso} iso-curve paths in the SVG`);
      assert(!svg.includes("<image"), "the SVG is vector only");
    },
  ],
  [
    "two 3D embeds are drawn by the page's one rendering worker (no WebGL context and no three.js on the page); a 2D page and a 2D embed load no three.js",
    async (page, h, base, { assert, equal, settle }) => {
      const three = [];
      const watch = (request) => {
        if (request.url().includes("/vendor/three/")) three.push(new URL(request.url()).pathname);
      };
      page.on("request", watch);
      const url = `${base}/three-embed-test.html`;
      try {
        // A 2D demo page.
        await page.goto("about:blank");
        await page.goto(`${base}/index.html#demo=de-casteljau`);
        await page.locator(".sl-figure[data-handles]").waitFor({ state: "attached" });
        equal(JSON.stringify(three), "[]", "three.js files on a 2D page");
        // A course page: a 2D embed, then two 3D ones (every getContext call counted).
        const body = (demos) =>
          `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script>window.contexts = []; const get = HTMLCanvasElement.prototype.getContext; HTMLCanvasElement.prototype.getContext = function (kind, ...rest) { window.contexts.push(kind); return get.call(this, kind, ...rest); };</script><script type="module" src="embed.js"></script></head><body>${demos}</body></html>`;
        await page.route(url, (route) =>
          route.fulfill({
            contentType: "text/html",
            body: body('<spline-lab id="flat" demo="de-casteljau"></spline-lab>'),
          }),
        );
        await page.goto(url);
        await page
          .locator("spline-lab#flat .sl-figure[data-handles]")
          .waitFor({ state: "attached" });
        equal(JSON.stringify(three), "[]", "three.js files with a 2D embed");
        await page.unroute(url);
        await page.route(url, (route) =>
          route.fulfill({
            contentType: "text/html",
            body: body(
              '<spline-lab id="a" demo="bezier-patch"></spline-lab><spline-lab id="b" demo="bezier-patch" wireframe="true"></spline-lab>',
            ),
          }),
        );
        await page.goto(url);
        for (const id of ["a", "b"]) {
          await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
          await page
            .locator(`spline-lab#${id} .sl-figure[data-handles]`)
            .waitFor({ state: "attached" });
        }
        // three.js is the worker's (its requests are seen here too); the page loaded none.
        assert(
          three.some((p) => p.endsWith("three.module.js")),
          `loaded ${three.join(", ")}`,
        );
        const onPage = await page.evaluate(async () => {
          const { loadedThree } = await import("./lib/three-loader.js");
          return loadedThree() !== null;
        });
        equal(onPage, false, "three.js loaded on the page");
        // The page's rendering worker draws both (lib/gl-client.js): no WebGL on the page.
        await settle(page);
        const kinds = await page.evaluate(() => window.contexts);
        const gl = kinds.filter((k) => k.startsWith("webgl"));
        equal(gl.length, 0, `WebGL contexts on the page (${kinds.join(", ")})`);
        const drawn = await page.evaluate(() =>
          ["a", "b"].map((id) => {
            const c = document.querySelector(`spline-lab#${id}`).shadowRoot.querySelector("canvas");
            const g = document.createElement("canvas");
            g.width = c.width;
            g.height = c.height;
            const x = g.getContext("2d");
            x.drawImage(c, 0, 0);
            const d = x.getImageData(0, 0, c.width, c.height).data;
            let blue = 0;
            for (let i = 0; i < d.length; i += 4) if (d[i + 2] > 90 && d[i + 2] > d[i] + 60) blue++;
            return blue;
          }),
        );
        assert(
          drawn.every((n) => n > 1000),
          `surface pixels per embed: ${drawn}`,
        );
      } finally {
        page.off("request", watch);
        await page.unroute(url);
      }
    },
  ],
  [
    "scene entries: { mesh, colour } is lit in that colour (back lighter); a wireframe's edge list is made again only when the triangles change; wireframe colour and opacity",
    async (page, _h, _base, { equal, assert }) => {
      const out = await page.evaluate(async () => {
        const { loadThree } = await import("./lib/three-loader.js");
        const { SceneContent } = await import("./lib/scene3d.js");
        const { THREE } = await loadThree();
        const content = new SceneContent(THREE);
        const mesh = (z, indices) => ({
          positions: Float32Array.from([0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z]),
          normals: Float32Array.from([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
          uvs: Float32Array.from([0, 0, 1, 0, 1, 1, 0, 1]),
          indices: Uint32Array.from(indices),
        });
        const a = mesh(0, [0, 1, 2, 0, 2, 3]);
        content.update({
          surfaces: [{ mesh: a, colour: "#E69F00" }, a],
          wireframe: [{ mesh: a, colour: "#009E73", opacity: 1 }],
        });
        const [coloured, plain] = content.surfaceSlots.map((s) => s.object.material);
        const wire = content.wireSlots[0].lines.material;
        const edges = [content.edgeListsMade];
        // Same triangles in a fresh array, moved: the edge list stays.
        content.update({ wireframe: [{ mesh: mesh(1, [0, 1, 2, 0, 2, 3]) }] });
        edges.push(content.edgeListsMade);
        const z = content.wireSlots[0].lines.geometry.getAttribute("position").array[2];
        // Other triangles, same count: a new edge list.
        content.update({ wireframe: [{ mesh: mesh(1, [0, 1, 3, 1, 2, 3]) }] });
        edges.push(content.edgeListsMade);
        const pairs = Array.from(content.wireSlots[0].lines.geometry.index.array);
        const back = coloured.onBeforeCompile;
        content.dispose();
        return {
          colour: coloured.color.getHexString(),
          plain: plain.color.getHexString(),
          distinct: coloured !== plain,
          hasBack: typeof back === "function",
          wire: [wire.color.getHexString(), wire.opacity, wire.transparent],
          edges,
          z,
          pairs,
        };
      });
      // three.js keeps colours linear: compare through a Color made the same way.
      const expected = await page.evaluate(async () => {
        const { loadThree } = await import("./lib/three-loader.js");
        const { THREE } = await loadThree();
        return ["#E69F00", "#0072B2", "#009E73"].map((c) => new THREE.Color(c).getHexString());
      });
      equal(out.colour, expected[0], "the coloured surface's front colour");
      equal(out.plain, expected[1], "a plain mesh stays blue");
      assert(out.distinct && out.hasBack, "a material of its own with the two-sided shader");
      equal(JSON.stringify(out.wire), JSON.stringify([expected[2], 1, false]), "wireframe colour");
      equal(JSON.stringify(out.edges), "[1,1,2]", "edge lists made");
      equal(out.z, 1, "the moved positions were taken");
      // Triangles (0 1 3) and (1 2 3): edges 0-1, 1-3, 3-0, 1-2, 2-3 (each once).
      equal(JSON.stringify(out.pairs), "[0,1,1,3,3,0,1,2,2,3]", "the new edges");
    },
  ],
];
