// Posters: every demo's default state drawn at build time (`make dist` calls renderPosters
// before bundling), so a page shows the figure before the wasm arrives (issue 26). Run alone:
//   node scripts/posters.mjs            (needs `make build`; writes www/posters/, git-ignored)
//
// Each demo is mounted in headless Chromium exactly as the playground mounts it (lib/shell.js
// mountDemo, the default state) and its figure recorded through the SVG export's recorder
// (lib/export.js: the same draw calls as the screen), in three shapes:
//   <id>-wide.svg    the figure as the playground draws it at 1280 CSS px (16:10, tall 4:3)
//   <id>-narrow.svg  … at 412 CSS px, Lighthouse's phone (4:3, tall 1:1: the narrow layout)
//   <id>-thumb.svg   the gallery card: a 480 × 300 figure (as the live thumbnails were drawn)
// and each lecture's first scene, as lib/lecture.js mounts it (its state, its figure's height
// cap, the large type at 1280 px), in the first two shapes: lecture-<lecture id>-1-wide.svg, ….
// Each in the light theme and, as <name>-<shape>-dark.svg, in the dark one (lib/theme.js), so a
// reader whose colour scheme is dark sees the figure in the colours the live one will have.
// A 3D figure's surface is a WebGL image the SVG recorder cannot draw, so a 3D poster is an SVG
// holding one WebP (the whole figure at 2 image px per CSS px, a thumbnail 2 per shown px); a 2D poster is the vector SVG,
// unless the same SVG-wrapped WebP is smaller after brotli (it never was: see the summary line,
// which prints both sizes). lib/posters.js finds the files (make dist hashes them).
// Beside them, states.json: each demo's default state's fingerprint as a link carries it, so a
// page opened from a link to another state shows no poster (lib/posters.js posterShowsState).
import { mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { brotliCompressSync, constants } from "node:zlib";
import { chromium } from "playwright-core";
import { CHROMIUM, CHROMIUM_ARGS } from "./chromium.mjs";
import { startServer } from "./serve.mjs";

const ROOT = resolve(fileURLToPath(new URL("..", import.meta.url)));
export const POSTERS = join(ROOT, "www", "posters");
/** Beside the posters: `{ <demo id>: fingerprint of its default state }` (dist.mjs defines it
 * as SPLINELAB_POSTER_STATES for lib/posters.js). */
export const STATES = "states.json";
/** The viewports of the two page shapes (CSS px); the thumbnail's figure size. */
const SHAPES = { wide: 1280, narrow: 412 };
const THUMB = { width: 480, height: 300 };
/** Image px per CSS px of a raster poster: 2, and a thumbnail's 2 per shown px (320 × 200). */
const THUMB_SCALE = (2 * 320) / THUMB.width;
/** WebP quality of a raster poster (3D): 0.8 keeps edges clean at 2 px per CSS px. */
const WEBP_QUALITY = 0.8;

const brotliSize = (text) =>
  brotliCompressSync(Buffer.from(text), {
    params: { [constants.BROTLI_PARAM_QUALITY]: 11 },
  }).length;

/** The page the posters are drawn in: the playground's styles and layout, nothing else. */
const PAGE = `<!doctype html><html lang="en"><head><meta charset="utf-8">
<link rel="stylesheet" href="lib/shell.css"><link rel="stylesheet" href="style.css"></head>
<body><main><div class="demo-page"><div id="slot"></div></div></main></body></html>`;

/**
 * In the page: mounts demo `id` in #slot, in `state` (null: its default) and, for a lecture's
 * scene (`lecture`), as lib/lecture.js mounts it; records its figure.
 */
async function drawInPage({ id, state, lecture, thumb, quality, scale, dark }) {
  const [
    { loadDemo, demos },
    { loadWasm },
    shell,
    { prepareFigure },
    draw,
    theme,
    exp,
    lectures,
    { encodeState },
    { stateFingerprint },
  ] = await Promise.all([
    import("./demos/index.js"),
    import("./lib/wasm.js"),
    import("./lib/shell.js"),
    import("./lib/three-loader.js"),
    import("./lib/draw.js"),
    import("./lib/theme.js"),
    import("./lib/export.js"),
    import("./lib/lecture.js"),
    import("./lib/state.js"),
    import("./lib/posters.js"),
  ]);
  const sl = await loadWasm();
  const demo = await loadDemo(id);
  await prepareFigure(demo, state, { exports: true }); // a 3D poster's image is drawn on the page
  const slot = document.getElementById("slot");
  if (lecture) slot.className = "lecture"; // its figure's height cap (style.css)
  const controller = shell.mountDemo(slot, demo, {
    sl,
    state: shell.validateState(demo, structuredClone(state ?? demo.defaultState)),
    mode: "page",
    headingLevel: lecture ? "h2" : "h1",
    lecture: lecture && lectures.largeType(),
    shareUrl: () => "",
  });
  await document.fonts.ready;
  await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
  const view = controller.figure;
  const box = slot.querySelector(".sl-figure");
  const tall = box.classList.contains("sl-figure-tall");
  const entry = demos.find((d) => d.id === id);
  const measure = document.createElement("canvas").getContext("2d");
  const look = dark ? theme.DARK_THEME : theme.LIGHT_THEME;
  const record = (width, height) => {
    const recorder = new draw.SvgRecorder({ theme: look, measureContext: measure });
    view.renderTo(recorder, width, height, look);
    return recorder.toString();
  };
  const raster = (width, height) => {
    const url = exp
      .figureToCanvas(view, scale, width, height, look)
      .toDataURL("image/webp", quality);
    return (
      `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" ` +
      `viewBox="0 0 ${width} ${height}"><image width="${width}" height="${height}" href="${url}"/></svg>\n`
    );
  };
  const [width, height] = thumb ?? [view.width, view.height];
  const out = {
    tall,
    manifestTall: Boolean(entry?.tall),
    is3d: Boolean(view.is3d),
    width,
    height,
    svg: view.is3d ? null : record(width, height),
    webp: raster(width, height),
    // The state as the playground's link carries it (app.js writes the mounted state).
    fingerprint: stateFingerprint(encodeState(controller.state)),
  };
  controller.destroy();
  return out;
}

/**
 * The first scene of every lecture (www/lectures/*.json), under the poster name
 * lib/posters.js `lecturePosterName` gives it: `lecture-<id>-1`.
 */
function lectureScenes() {
  const dir = join(ROOT, "www", "lectures");
  return readdirSync(dir)
    .filter((file) => file.endsWith(".json"))
    .map((file) => {
      const lecture = JSON.parse(readFileSync(join(dir, file), "utf8"));
      const scene = lecture.scenes[0];
      return { id: scene.demo, name: `lecture-${lecture.id}-1`, state: scene.state, lecture: true };
    });
}

/**
 * Draws every demo's posters into `out` (replaced whole). Resolves to the list of
 * { id, shape, file, bytes, svgBrotli, webpBrotli } written.
 */
export async function renderPosters({ out = POSTERS, only = "" } = {}) {
  const server = await startServer(0, "127.0.0.1", join(ROOT, "www"));
  const base = `http://127.0.0.1:${server.address().port}`;
  const profile = mkdtempSync(join(tmpdir(), "splinelab-posters-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    args: [...CHROMIUM_ARGS],
    viewport: { width: SHAPES.wide, height: 900 },
  });
  const written = [];
  const problems = [];
  /** Each demo's default state's fingerprint (lib/posters.js `posterShowsState`). */
  const fingerprints = {};
  try {
    await context.route(`${base}/__posters__.html`, (route) =>
      route.fulfill({ contentType: "text/html", body: PAGE }),
    );
    const page = context.pages()[0] ?? (await context.newPage());
    page.on("pageerror", (err) => problems.push(err.message));
    await page.goto(`${base}/__posters__.html`);
    const ids = (
      await page.evaluate(async () => (await import("./demos/index.js")).demos.map((d) => d.id))
    ).filter((id) => id.includes(only));
    rmSync(out, { recursive: true, force: true });
    mkdirSync(out, { recursive: true });
    // Each demo's default state, and each lecture's first scene (lib/lecture.js shows it).
    const figures = [
      ...ids.map((id) => ({ id, name: id, state: null, lecture: false })),
      ...lectureScenes().filter((f) => f.name.includes(only) || f.id.includes(only)),
    ];
    for (const [shape, width] of [...Object.entries(SHAPES), ["thumb", SHAPES.wide]]) {
      await page.setViewportSize({ width, height: 900 });
      for (const { id, name, state, lecture, dark } of figures.flatMap((f) => [
        { ...f, dark: false },
        { ...f, dark: true },
      ])) {
        if (lecture && shape === "thumb") continue;
        await page.goto(`${base}/__posters__.html`);
        const r = await page.evaluate(drawInPage, {
          id,
          state,
          lecture,
          thumb: shape === "thumb" ? [THUMB.width, THUMB.height] : null,
          quality: WEBP_QUALITY,
          scale: shape === "thumb" ? THUMB_SCALE : 2,
          dark,
        });
        if (r.tall !== r.manifestTall)
          problems.push(
            `${id}: the figure is ${r.tall ? "" : "not "}tall but demos/index.js says tall: ${r.manifestTall}`,
          );
        const svgBrotli = r.svg ? brotliSize(r.svg) : Number.POSITIVE_INFINITY;
        const webpBrotli = brotliSize(r.webp);
        const body = svgBrotli <= webpBrotli ? r.svg : r.webp;
        if (!lecture) fingerprints[id] = r.fingerprint;
        const file = `${name}-${shape}${dark ? "-dark" : ""}.svg`;
        writeFileSync(join(out, file), body);
        written.push({
          id,
          shape,
          file,
          bytes: body.length,
          kind: body === r.svg ? "vector" : "webp",
          svgBrotli,
          webpBrotli,
        });
      }
    }
  } finally {
    await context.close();
    rmSync(profile, { recursive: true, force: true });
    server.close();
  }
  if (problems.length) throw new Error(`posters:\n  ${problems.join("\n  ")}`);
  writeFileSync(join(out, STATES), `${JSON.stringify(fingerprints, null, 1)}\n`);
  return written;
}

/** One line: how many posters, of which kind, and their brotli sizes against WebP's. */
export function summary(written) {
  const kb = (n) => (n / 1024).toFixed(1);
  const sum = (list, key) => list.reduce((s, w) => s + (Number.isFinite(w[key]) ? w[key] : 0), 0);
  const vector = written.filter((w) => w.kind === "vector");
  const raster = written.filter((w) => w.kind === "webp");
  return (
    `posters: ${written.length} in www/posters/ (${vector.length} vector SVG, ${raster.length} WebP in SVG); ` +
    `vector ones ${kb(sum(vector, "svgBrotli"))} KiB brotli against ${kb(sum(vector, "webpBrotli"))} KiB as WebP, ` +
    `WebP ones ${kb(sum(raster, "webpBrotli"))} KiB`
  );
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const started = Date.now();
  const only = process.argv.slice(2).find((a) => !a.startsWith("--")) ?? "";
  const written = await renderPosters({ only });
  console.log(`${summary(written)}, ${((Date.now() - started) / 1000).toFixed(1)} s`);
  if (process.argv.includes("--list"))
    for (const w of written)
      console.log(`  ${w.file}: ${w.kind}, svg ${w.svgBrotli} B br, webp ${w.webpBrotli} B br`);
}
