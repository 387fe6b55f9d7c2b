// Browser checks specific to the parametric-curve demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers by hand (closed forms, syllabus §1):
// - circle (cos t, sin t): |P′| = 1, κ = 1 everywhere; P(1) = (cos 1, sin 1) = (0.540, 0.841).
// - ellipse (a cos t, b sin t) at t = 0: P′ = (0, b), P″ = (−a, 0), κ = (x′y″ − y′x″)/|P′|³
//   = ab/b³ = a/b²: 2 for a = 2, b = 1; 3 for a = 3.
// - helix (cos t, sin t, ct), c = 1/5: |P′| = √(1 + c²) = 1.0198, κ = 1/(1 + c²) = 0.9615,
//   τ = c/(1 + c²) = 0.1923 (for every t).
// - y = tan t on [−π, π]: poles at ±π/2, so no run of the plot contains ±π/2.
// - the notes' polynomial x = 6.5t⁵ − 7.2t³ + 3t² − 2.1t − 5, y = t on [0, 1]: Bézier control
//   values of x −5, −271/50, −277/50, −152/25, −194/25, −24/5 (the notes), of y i/5.

import { readFileSync } from "node:fs";
import { compileTikz, hasPdflatex, inspectTikz } from "../tikz-check.mjs";

/** TeX's largest dimension, 16383.99 pt, in CSS px (the export writes 1 px = 0.75 pt). */
const TEX_MAX_PX = 16383 / 0.75;

/** The state in the page's link. */
async function linkState(page) {
  const s = new URLSearchParams(new URL(page.url()).hash.slice(1)).get("s");
  return JSON.parse(Buffer.from(s, "base64url").toString("utf8"));
}

const readoutData = (page, name, key) =>
  page.locator(`[data-info="${name}"]`).first().getAttribute(`data-${key}`);

async function typeInto(page, selector, text) {
  const box = page.locator(selector).first();
  await box.fill(text);
  await box.press("Enter");
}

async function preset(page, name, settle) {
  await page.locator(`[data-action="preset-${name}"]`).first().click();
  await settle(page);
}

export default [
  [
    "the circle of the notes: |P′| = 1 and κ = 1; P(1) = (cos 1, sin 1)",
    async (page, h, _base, { assert, equal }) => {
      equal(await readoutData(page, "speed", "speed"), "1.000", "speed");
      equal(await readoutData(page, "curvature", "kappa"), "1.000", "κ");
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("(0.54, 0.84)") && label.includes("cos(t)"), `aria-label: ${label}`);
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("0.540") && formula.includes("0.841"), `formula: ${formula}`);
    },
  ],
  [
    "a press on the curve moves the point there: the circle's leftmost point is t = π",
    async (page, h, _base, { assert, settle }) => {
      // The scale from a drag of O by 40 px (O is at (2.1, 0), on the circle's row), then undone.
      const [o] = await h.handles();
      const before = (await linkState(page)).hodograph[0][0];
      await h.drag(o, 40, 0);
      const scale = 40 / ((await linkState(page)).hodograph[0][0] - before);
      await page.keyboard.press("Control+z");
      await page.keyboard.press("Escape");
      await settle(page);
      await page.mouse.click(o.x - (before + 1) * scale, o.y);
      await settle(page);
      const t = (await linkState(page)).t;
      assert(Math.abs(t - Math.PI) < 0.03, `t = ${t} (scale ${scale} px per unit)`);
    },
  ],
  [
    "ellipse: a and b become sliders; κ(0) = a/b² follows the slider a",
    async (page, _h, _base, { equal, settle }) => {
      await preset(page, "ellipse", settle);
      equal(await page.locator('[data-control="param-a"]').count(), 1, "slider a");
      equal(await page.locator('[data-control="param-b"]').count(), 1, "slider b");
      await typeInto(page, '[data-control="t"] .sl-value', "0");
      await settle(page);
      equal(await readoutData(page, "curvature", "kappa"), "2.000", "κ(0) for a = 2, b = 1");
      await typeInto(page, '[data-control="param-a"] .sl-value', "3");
      await settle(page);
      equal(await readoutData(page, "curvature", "kappa"), "3.000", "κ(0) for a = 3");
      equal(JSON.stringify((await linkState(page)).params), '{"a":3,"b":1}', "params in the link");
    },
  ],
  [
    "a typing error is underlined under its box, explained, and the last good curve stays",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      const url = page.url();
      await typeInto(page, '[data-control="x"] input', "2cos(t");
      await settle(page);
      const note = page.locator('[data-error="x"]');
      equal(await note.isVisible(), true, "the note under x(t) shows");
      const mark = note.locator("u");
      const start = Number(await mark.getAttribute("data-start"));
      const end = Number(await mark.getAttribute("data-end"));
      assert(start >= 0 && end >= start && end <= 6, `underlined ${start}…${end}`);
      assert((await note.textContent()).length > 8, "a reason is given");
      equal(
        await page.locator('[data-control="x"] input').getAttribute("aria-invalid"),
        "true",
        "aria-invalid",
      );
      equal(await h.snapshot(), before, "the picture is the last good curve");
      equal(page.url(), url, "nothing recorded");
      // Fixed, the mark goes and the curve is the new one.
      await typeInto(page, '[data-control="x"] input', "2cos(t)");
      await settle(page);
      equal(await note.isVisible(), false, "the note is gone");
      equal((await linkState(page)).x, "2cos(t)", "the new text in the link");
    },
  ],
  [
    "a new name becomes a slider at 1; undo takes it away again",
    async (page, h, _base, { equal, settle }) => {
      await typeInto(page, '[data-control="x"] input', "k cos(t)");
      await settle(page);
      equal(await page.locator('[data-control="param-k"]').count(), 1, "slider k");
      equal(JSON.stringify((await linkState(page)).params), '{"k":1}', "params");
      await h.canvas().focus();
      await page.keyboard.press("Control+z");
      await settle(page);
      equal(await page.locator('[data-control="param-k"]').count(), 0, "slider k after undo");
      equal(await page.locator('[data-control="x"] input').inputValue(), "cos(t)", "x after undo");
    },
  ],
  [
    "y = tan t: the plot breaks at the poles ±π/2 (no run crosses one)",
    async (page, _h, _base, { assert, settle }) => {
      await preset(page, "tan", settle);
      const runs = JSON.parse(await page.locator(".sl-figure").getAttribute("data-plot-runs"));
      const half = Math.PI / 2;
      for (const [a, b] of runs) {
        assert(!(a < half && b > half) && !(a < -half && b > -half), `run ${a}…${b}`);
      }
      assert(
        runs.some(([a]) => a < -half) &&
          runs.some(([a, b]) => a > -half && b < half) &&
          runs.some(([, b]) => b > half),
        `all three branches: ${JSON.stringify(runs)}`,
      );
    },
  ],
  [
    "the notes' polynomial: the exact Bézier control values and a link into de Casteljau",
    async (page, _h, base, { assert, equal, settle }) => {
      await preset(page, "polynomial", settle);
      const text = await page.locator('[data-info="bezier-points"]').textContent();
      for (const value of ["(−5, 0)", "−271/50", "−277/50", "−152/25", "−194/25", "(−24/5, 1)"])
        assert(text.includes(value), `${value} in ${text}`);
      const href = await page.locator('[data-link="bezier-points"]').getAttribute("href");
      const hash = new URLSearchParams(new URL(href).hash.slice(1));
      equal(hash.get("demo"), "de-casteljau", "linked demo");
      const state = JSON.parse(Buffer.from(hash.get("s"), "base64url").toString("utf8"));
      const want = [-5, -271 / 50, -277 / 50, -152 / 25, -194 / 25, -24 / 5];
      equal(state.points.length, 6, "control points");
      state.points.forEach(([x, y], i) => {
        assert(Math.abs(x - want[i]) < 1e-12 && Math.abs(y - i / 5) < 1e-12, `P${i} = ${x}, ${y}`);
      });
      await page.goto("about:blank");
      await page.goto(href);
      await page.locator(".sl-figure[data-handles]").waitFor({ state: "attached" });
      const handles = await page.locator(".sl-figure").getAttribute("data-handles");
      equal(handles.split(";").filter(Boolean).length, 6, "de Casteljau's handles");
      assert(base.length > 0, "base");
    },
  ],
  [
    "helix: κ = 1/(1 + c²), τ = c/(1 + c²); the 3D view mounts and a drag orbits it",
    async (page, h, _base, { assert, equal, settle }) => {
      await preset(page, "helix", settle);
      await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
      await settle(page);
      equal(await readoutData(page, "curvature", "kappa"), "0.962", "κ");
      equal(await readoutData(page, "speed", "speed"), "1.020", "speed");
      const torsion = await page.locator('[data-info="torsion"]').textContent();
      assert(torsion.includes("0.192"), `torsion: ${torsion}`);
      const before = (await linkState(page)).view;
      equal(before.length, 6, `a camera in the link: ${JSON.stringify(before)}`);
      assert(
        Number(await page.locator(".sl-figure").getAttribute("data-geometries")) > 0,
        "scene curves made",
      );
      const box = await h.canvas().boundingBox();
      await h.drag({ x: box.x + 20, y: box.y + 20 }, 60, 0);
      const after = (await linkState(page)).view;
      assert(after[0] !== before[0], `azimuth ${before[0]} → ${after[0]}`);
      const runs = JSON.parse(await page.locator(".sl-figure").getAttribute("data-plot-runs"));
      equal(runs.length, 1, "the helix is one run");
    },
  ],
  [
    "the circle's page loads no three.js file; the helix example loads it and shows the 3D view",
    async (page, _h, base, { equal, settle }) => {
      const three = [];
      const watch = (request) => {
        if (request.url().includes("/vendor/three/")) three.push(request.url());
      };
      page.on("request", watch);
      try {
        await page.goto("about:blank");
        await page.goto(`${base}/index.html#demo=parametric-curve`);
        await page.locator(".sl-figure[data-handles]").waitFor({ state: "attached" });
        await settle(page);
        equal(three.length, 0, "three.js files on the circle's page");
        const help = () => page.locator(".sl-help").first().textContent();
        const plane = await help();
        await preset(page, "helix", settle);
        await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
        equal(three.length > 0, true, "three.js loaded for the helix");
        equal((await linkState(page)).view.length, 6, "the camera recorded");
        const space = await help();
        equal(space !== plane && space.length > 20, true, `help: ${plane} → ${space}`);
      } finally {
        page.off("request", watch);
      }
    },
  ],
  [
    "helix → circle: the 2D figure with its hodograph comes back; undo shows the 3D view again",
    async (page, h, _base, { assert, equal, settle }) => {
      await preset(page, "helix", settle);
      await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
      await preset(page, "circle", settle);
      await settle(page);
      const figure = page.locator(".sl-figure");
      equal(await figure.getAttribute("data-geometries"), null, "no 3D figure");
      equal((await h.handles()).length, 1, "the hodograph's O is a handle");
      equal((await linkState(page)).view.length, 4, "a window in the link");
      equal(await page.locator(".sl-figure canvas").count(), 1, "one canvas");
      await h.canvas().focus();
      await page.keyboard.press("Control+z");
      await settle(page);
      await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
      const state = await linkState(page);
      assert(state.z === "t/5" && state.view.length === 6, `after undo: ${JSON.stringify(state)}`);
      // Deleting z(t) by typing gives the plane figure again.
      await typeInto(page, '[data-control="z"] input', "");
      await settle(page);
      equal((await linkState(page)).view.length, 4, "a window after z is deleted");
      equal(await page.locator(".sl-figure canvas").count(), 1, "one canvas");
    },
  ],
  [
    "the link of the helix restores its camera; a 2D window in a helix link is dropped",
    async (page, h, base, { assert, equal, openDemo, settle }) => {
      await preset(page, "helix", settle);
      await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
      const box = await h.canvas().boundingBox();
      await h.drag({ x: box.x + 20, y: box.y + 20 }, 40, 30);
      const state = await linkState(page);
      const encoded = Buffer.from(JSON.stringify(state)).toString("base64url");
      h = await openDemo(page, base, "parametric-curve", `&s=${encoded}`);
      await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
      await settle(page);
      equal(JSON.stringify((await linkState(page)).view), JSON.stringify(state.view), "camera");
      const flat = { ...state, view: [-1, -1, 1, 1] };
      const link = Buffer.from(JSON.stringify(flat)).toString("base64url");
      h = await openDemo(page, base, "parametric-curve", `&s=${link}`);
      await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
      await settle(page);
      const view = (await linkState(page)).view;
      assert(view.length === 6, `fitted camera: ${JSON.stringify(view)}`);
      equal(await h.statusKind(), null, "no error shown");
    },
  ],
  [
    "the TikZ export of a pole (tan t, zoomed out) and of the helix compiles: everything is clipped",
    async (page, h, _base, { assert, equal, settle }) => {
      for (const name of ["tan", "helix"]) {
        await preset(page, name, settle);
        // Near the pole P(t) and P′(t) are ~10⁴ and ~10⁸ units away; zoomed out, the
        // branches and the osculating circle run far off the canvas.
        if (name === "tan") await typeInto(page, '[data-control="t"] .sl-value', "1.5707");
        // The 3D figure replaces the plane one once three.js has loaded.
        else await page.locator(".sl-figure[data-geometries]").waitFor({ state: "attached" });
        const box = await h.canvas().boundingBox();
        await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
        for (let k = 0; k < 4; k++) await page.mouse.wheel(0, 400);
        await settle(page);
        const file = await h.download("export-tikz");
        const tex = readFileSync(await file.path(), "utf8");
        const found = inspectTikz(tex);
        equal(found.problems.join("; "), "", `${name}: problems`);
        const far = [...tex.matchAll(/\((-?[\d.]+),\s*(-?[\d.]+)\)/g)].some(
          (m) => Math.abs(Number(m[1])) > TEX_MAX_PX || Math.abs(Number(m[2])) > TEX_MAX_PX,
        );
        assert(!far, `${name}: a coordinate beyond TeX's 16383 pt`);
        if (hasPdflatex) {
          const compiled = compileTikz(tex);
          assert(compiled.ok, `${name}: pdflatex failed:\n${compiled.log}`);
        }
      }
    },
  ],
  [
    "keyboard: arrows move t on its slider; Space on the figure plays",
    async (page, h, _base, { assert, settle, PLAY_MS }) => {
      const box = page.locator('[data-control="t"] .sl-value');
      const t0 = await box.inputValue();
      await page.locator('[data-control="t"] input[type="range"]').focus();
      await page.keyboard.press("ArrowRight");
      await settle(page);
      const t1 = await box.inputValue();
      assert(t1 !== t0, `t ${t0} → ${t1}`);
      await h.canvas().focus();
      await page.keyboard.press(" ");
      await page.waitForTimeout(PLAY_MS);
      await page.keyboard.press(" ");
      await settle(page);
      assert((await box.inputValue()) !== t1, "t moved while playing");
    },
  ],
  [
    "embed: <spline-lab demo=parametric-curve x=… y=… to=…> shows that curve",
    async (page, _h, base, { assert, equal }) => {
      const url = `${base}/parametric-embed-test.html`;
      await page.route(url, (route) =>
        route.fulfill({
          contentType: "text/html",
          body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="e" demo="parametric-curve" x="cos(t)" y="sin(2t)" to="2pi"></spline-lab></body></html>',
        }),
      );
      try {
        await page.goto(url);
        await page.locator("spline-lab#e .sl-figure[data-handles]").waitFor({ state: "attached" });
        equal(
          await page.locator('spline-lab#e [data-control="y"] input').inputValue(),
          "sin(2t)",
          "y(t) box",
        );
        const label = await page.locator("spline-lab#e .sl-canvas").getAttribute("aria-label");
        assert(label.includes("sin(2t)"), `aria-label: ${label}`);
      } finally {
        await page.unroute(url);
      }
    },
  ],
  [
    "embed: a z attribute mounts the 3D figure at once; a Bézier form of a space polynomial",
    async (page, _h, base, { assert, equal, settle }) => {
      const url = `${base}/parametric-embed-3d.html`;
      await page.route(url, (route) =>
        route.fulfill({
          contentType: "text/html",
          body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="e" demo="parametric-curve" x="t" y="t^2" z="t^3" to="1" bezier></spline-lab></body></html>',
        }),
      );
      try {
        await page.goto(url);
        await page
          .locator("spline-lab#e .sl-figure[data-geometries]")
          .waitFor({ state: "attached" });
        await settle(page);
        const text = await page.locator('spline-lab#e [data-info="bezier-points"]').textContent();
        assert(text.includes("(1/3, 0, 0)") && text.includes("(1, 1, 1)"), `points: ${text}`);
        equal(
          await page.locator('spline-lab#e [data-link="bezier-points"]').getAttribute("href"),
          null,
          "no link into de Casteljau for a space curve",
        );
      } finally {
        await page.unroute(url);
      }
    },
  ],
  [
    "Croatian: the panel speaks Croatian and a refusal is explained in Croatian under the box",
    async (page, h, base, { assert, openDemo, settle }) => {
      const refusal = async () => {
        await typeInto(page, '[data-control="x"] input', "cos(t");
        await settle(page);
        assert(await page.locator('[data-error="x"]').isVisible(), "the note shows");
        return page.locator('[data-error="x"] span').textContent();
      };
      const english = await refusal();
      h = await openDemo(page, base, "parametric-curve", "", "hr");
      const legend = await page.locator(".sl-panel legend").first().textContent();
      assert(legend !== "Curve P(t)", `legend: ${legend}`);
      const croatian = await refusal();
      assert(croatian.length > 8 && croatian !== english, `hr “${croatian}”, en “${english}”`);
    },
  ],
];
