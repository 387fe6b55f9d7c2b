// Browser tests of the playground in real Chromium (playwright-core; the demos shared among two browsers, pages reused).
// Table-driven over the demo registry (www/demos/index.js): every demo gets the generic checks
// (loads cleanly, drag and keyboard change the picture, the link restores it, exports parse,
// import round-trips, bad links and files are reported without killing the page), then its own
// checks from tests/e2e/checks/<id>.mjs. Ends with one line "e2e: N passed, M failed"; exits 1 on failure.
//
//   node tests/e2e/run.mjs            all tests
//   node tests/e2e/run.mjs casteljau  only tests whose name contains "casteljau"
import { chromium } from "playwright-core";
import { mkdtempSync, readdirSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { createHash } from "node:crypto";
import { startServer } from "../../scripts/serve.mjs";
import { fuzzStates } from "./state-fuzz.mjs";
import { compileTikz, hasPdflatex, inspectTikz } from "./tikz-check.mjs";
import { CHROMIUM, CHROMIUM_ARGS } from "../../scripts/chromium.mjs";
import { encodeStroke } from "../../www/lib/stroke-code.js";
import { distSuite } from "./dist.mjs";
import { axeSuite } from "./axe.mjs";
import { offlineSuite } from "./offline.mjs";

const VIEWPORT = { width: 1280, height: 900 };
/** Longest a single test may take (ms) before it counts as failed. */
const TEST_TIMEOUT_MS = 30_000;
/** Browsers the demos' suites are shared among (E2E_WORKERS, default 2): the tests mostly wait
 * for frames and downloads, so two browsers on two cores finish in about 60 % of the time. */
const WORKERS = Math.max(1, Math.floor(Number(process.env.E2E_WORKERS ?? 2)) || 1);
/** Pixels a handle is dragged in the drag test. */
const DRAG_PX = { x: 40, y: -30 };
/** Playback runs this long (ms) in the play test. */
const PLAY_MS = 500;
const PNG_SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
const filter = process.argv[2] ?? "";
const ROOT = resolve(fileURLToPath(new URL("../..", import.meta.url)));

/** Every .js file below `dir`, except the generated pkg/ and vendor/ folders. */
function listJs(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return ["pkg", "vendor"].includes(entry.name) ? [] : listJs(path);
    return entry.name.endsWith(".js") ? [path] : [];
  });
}

let passed = 0;
let failed = 0;

/** Runs one named test with a timeout; failures are reported and counted, never thrown. */
async function test(name, body) {
  if (filter && !name.includes(filter)) return;
  const started = Date.now();
  let timer;
  try {
    await Promise.race([
      body(),
      new Promise(
        (_, reject) =>
          (timer = setTimeout(
            () => reject(new Error(`timed out after ${TEST_TIMEOUT_MS} ms`)),
            TEST_TIMEOUT_MS,
          )),
      ),
    ]);
    passed += 1;
    console.log(`ok   ${name} (${Date.now() - started} ms)`);
  } catch (err) {
    failed += 1;
    console.log(
      `FAIL ${name}\n     ${String(err.stack ?? err)
        .split("\n")
        .slice(0, 4)
        .join("\n     ")}`,
    );
  } finally {
    clearTimeout(timer);
  }
}

function assert(condition, message) {
  if (!condition) throw new Error(message);
}

function equal(actual, expected, message) {
  if (actual !== expected)
    throw new Error(
      `${message}: expected ${JSON.stringify(expected)}, got ${JSON.stringify(actual)}`,
    );
}

const digest = (text) => createHash("sha256").update(text).digest("hex").slice(0, 16);

// ------------------------------------------------------------------ page helpers

/** Console errors and uncaught exceptions of a page, collected since the last `take()`. */
function watchErrors(page) {
  const errors = [];
  page.on("console", (msg) => {
    if (msg.type() === "error") errors.push(`console: ${msg.text()}`);
  });
  page.on("pageerror", (err) => errors.push(`pageerror: ${err.message}`));
  return { take: () => errors.splice(0) };
}

/** Waits two animation frames (the coalesced draw has happened) and any 3D frame asked for. */
async function settle(page) {
  // Then, frame by frame, until no 3D figure waits for its rendering worker's frame
  // (lib/gl-client.js `<html data-gl-pending>`): one round trip to the page.
  await page.evaluate(
    () =>
      new Promise((resolve) => {
        const drawn = () =>
          document.documentElement.hasAttribute("data-gl-pending")
            ? requestAnimationFrame(drawn)
            : resolve();
        requestAnimationFrame(() => requestAnimationFrame(drawn));
      }),
  );
}

/** Scopes helpers to one demo instance (`scope` = CSS prefix, e.g. "" or "spline-lab#a "). */
function demoHelpers(page, scope = "") {
  const canvasSelector = `${scope}.sl-canvas`;
  const h = {
    canvas: () => page.locator(canvasSelector).first(),
    /**
     * Waits until the demo is mounted, drawn and its formula typeset (the handles' positions
     * written; a demo without handles, whose pieces are typed, has its canvas).
     */
    async ready() {
      await page
        .locator(`${scope}.sl-figure[data-handles], ${scope}.sl-figure:has(.sl-canvas)`)
        .first()
        .waitFor({ state: "attached" });
      // The panel typesets once a reader heads for it (lib/formula.js): as if focus went there.
      const panel = page.locator(`${scope}.sl-formula`).first();
      if (await panel.count()) await panel.dispatchEvent("focusin");
      await page.locator(`${scope}.sl-formula .katex`).first().waitFor({ state: "attached" });
      await settle(page);
    },
    /** A digest of the canvas pixels. */
    async snapshot() {
      await settle(page);
      return digest(await h.canvas().evaluate((c) => c.toDataURL("image/png")));
    },
    /** Handle centres in page coordinates (canvas box + border), as last drawn. */
    async handles() {
      await settle(page);
      const text = await page.locator(`${scope}.sl-figure`).first().getAttribute("data-handles");
      const origin = await h.canvas().evaluate((c) => {
        const r = c.getBoundingClientRect();
        return { x: r.left + c.clientLeft, y: r.top + c.clientTop };
      });
      return (text ?? "")
        .split(";")
        .filter(Boolean)
        .map((pair) => {
          const [x, y] = pair.split(",").map(Number);
          return { x: origin.x + x, y: origin.y + y };
        });
    },
    async drag(from, dx, dy) {
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      const steps = 6;
      for (let k = 1; k <= steps; k++)
        await page.mouse.move(from.x + (dx * k) / steps, from.y + (dy * k) / steps);
      await page.mouse.up();
      await settle(page);
    },
    status: () => page.locator(`${scope}.sl-status`).first().textContent(),
    async statusKind() {
      return page.locator(`${scope}.sl-status`).first().getAttribute("data-kind");
    },
    /** Clicks a toolbar/panel button by its data-action name and returns the download. */
    async download(action) {
      const [file] = await Promise.all([
        page.waitForEvent("download"),
        page.locator(`${scope}[data-action="${action}"]`).first().click(),
      ]);
      return file;
    },
    async importText(name, text) {
      await page
        .locator(`${scope}.sl-import-input`)
        .first()
        .setInputFiles({ name, mimeType: "application/json", buffer: Buffer.from(text) });
      await settle(page);
    },
  };
  return h;
}

/**
 * A fresh load of a demo (about:blank first, so a same-document hash change cannot keep state),
 * in `lang` when given (`?lang=`).
 */
async function openDemo(page, base, id, hash = "", lang = "") {
  await page.goto("about:blank");
  await page.goto(`${base}/index.html${lang ? `?lang=${lang}` : ""}#demo=${id}${hash}`);
  const h = demoHelpers(page);
  await h.ready();
  return h;
}

// ------------------------------------------------------------------ demo-specific checks

/** Demo-specific checks live in tests/e2e/checks/<id>.mjs (default export: [[what, body], …]);
 * each body gets (page, helpers, base, tools). */
async function demoChecks(id) {
  try {
    return (await import(`./checks/${id}.mjs`)).default;
  } catch (err) {
    if (err.code === "ERR_MODULE_NOT_FOUND") return [];
    throw err;
  }
}

// ------------------------------------------------------------------ one demo's suite

/** The ids of the demos whose figure has handles (filled from the registry before the suites). */
const withHandles = new Set();

/** Every test of one demo, in order, on one worker's page: the generic checks, then its own. */
async function demoSuite({ page, errors }, demo) {
  const name = (what) => `${demo.id}: ${what}`;
  let h = demoHelpers(page);
  /**
   * Whether the demo's figure has handles. A demo without (its curve is typed: piecewise) is
   * changed by panning instead of dragging a handle, and skips the handle tests.
   */
  const hasHandles = withHandles.has(demo.id);
  /** Changes the picture: drags the first handle, or pans the view of a demo without handles. */
  const changePicture = async (dx, dy) => {
    const [handle] = await h.handles();
    if (hasHandles) return h.drag(handle, dx, dy);
    const box = await h.canvas().boundingBox();
    await h.drag({ x: box.x + box.width / 2, y: box.y + box.height / 2 }, dx, dy);
  };

  await test(name("opens from the gallery without console errors"), async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html`);
    await page.locator(`a.card[data-demo="${demo.id}"]`).click();
    await h.ready();
    // Every demo with handles has keyboard handles: an interactive figure, not a picture.
    if (hasHandles) {
      equal(await h.canvas().getAttribute("role"), "application", "canvas role");
      assert(
        (await h.canvas().getAttribute("aria-roledescription"))?.length > 3,
        "canvas has an aria-roledescription",
      );
    }
    assert((await h.canvas().getAttribute("aria-label")).length > 10, "canvas has an aria-label");
    const size = await h
      .canvas()
      .evaluate((c) => ({ w: c.width, cw: c.clientWidth, ratio: devicePixelRatio }));
    assert(
      Math.abs(size.w - size.cw * size.ratio) <= 1,
      `backing store ${size.w} px for ${size.cw} CSS px at DPR ${size.ratio}`,
    );
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test(name("dragging a handle changes the picture"), async () => {
    if (!hasHandles) return; // typed pieces: its own checks drive the text boxes
    h = await openDemo(page, base, demo.id);
    const before = await h.snapshot();
    const [first, second] = await h.handles();
    const handle = second ?? first;
    assert(handle, "the demo has handles");
    await h.drag(handle, DRAG_PX.x, DRAG_PX.y);
    const after = await h.snapshot();
    assert(before !== after, "canvas unchanged after drag");
    const moved = (await h.handles())[second ? 1 : 0];
    assert(
      Math.abs(moved.x - handle.x - DRAG_PX.x) < 1.5 &&
        Math.abs(moved.y - handle.y - DRAG_PX.y) < 1.5,
      `handle at ${JSON.stringify(moved)}, expected ${JSON.stringify(handle)} + drag`,
    );
    // Undo puts the handle back; Escape clears the selection: the first picture again.
    await page.keyboard.press("Control+z");
    await page.keyboard.press("Escape");
    await page.mouse.move(1, 1);
    equal(
      JSON.stringify((await h.handles())[second ? 1 : 0]),
      JSON.stringify(handle),
      "handle after undo",
    );
    equal(await h.snapshot(), before, "snapshot after undo");
  });

  await test(name("keyboard nudge changes the picture"), async () => {
    if (!hasHandles) return;
    h = await openDemo(page, base, demo.id);
    const before = await h.snapshot();
    const start = (await h.handles())[0];
    await h.canvas().focus();
    await page.keyboard.press("Home");
    await page.keyboard.press("ArrowRight");
    await page.keyboard.press("Shift+ArrowUp");
    const after = await h.snapshot();
    assert(before !== after, "canvas unchanged after arrow keys");
    const moved = (await h.handles())[0];
    assert(
      Math.abs(moved.x - start.x - 1) < 0.6 && Math.abs(moved.y - start.y + 10) < 0.6,
      `nudged to ${JSON.stringify(moved)} from ${JSON.stringify(start)}`,
    );
  });

  await test(name("the Add point / Remove point buttons add and remove a handle"), async () => {
    h = await openDemo(page, base, demo.id);
    const add = page.locator('[data-action="add-point"]');
    if ((await add.count()) === 0) return; // a demo without an editable point list
    const count = (await h.handles()).length;
    const before = await h.snapshot();
    await add.first().click();
    await settle(page);
    equal((await h.handles()).length, count + 1, "handles after Add point");
    assert((await h.snapshot()) !== before, "canvas unchanged after Add point");
    // The new point is selected: Remove point takes it away again.
    await page.locator('[data-action="remove-point"]').first().click();
    await settle(page);
    equal((await h.handles()).length, count, "handles after Remove point");
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test(
    name("Remove point stops at the minimum (button disabled, Delete refused with a message)"),
    async () => {
      h = await openDemo(page, base, demo.id);
      const remove = page.locator('[data-action="remove-point"]').first();
      if ((await remove.count()) === 0) return; // a demo without an editable point list
      for (let k = 0; k < 40 && !(await remove.isDisabled()); k++) {
        await remove.click();
        await settle(page);
      }
      assert(await remove.isDisabled(), "Remove point is disabled at the minimum");
      const count = (await h.handles()).length;
      assert(count >= 2, `${count} handles left`);
      // The keyboard path is refused too, with a message naming the limit.
      await h.canvas().focus();
      await page.keyboard.press("Home");
      await page.keyboard.press("Delete");
      await settle(page);
      equal((await h.handles()).length, count, "handles after Delete at the minimum");
      equal(await h.statusKind(), "error", "status kind");
      assert(/\d/.test(await h.status()), `the message names the limit: ${await h.status()}`);
      // Still interactive: Add point works again.
      await page.locator('[data-action="add-point"]').first().click();
      await settle(page);
      equal((await h.handles()).length, count + 1, "handles after Add point");
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    },
  );

  await test(name("the URL restores the same picture after reload"), async () => {
    h = await openDemo(page, base, demo.id);
    await changePicture(-25, 35);
    // Pan on empty space too: the view is part of the picture.
    const box = await h.canvas().boundingBox();
    await h.drag({ x: box.x + 12, y: box.y + box.height - 12 }, 30, -20);
    await page.keyboard.press("Escape"); // the selection is not part of the state
    const before = await h.snapshot();
    const url = page.url();
    assert(/#demo=[\w-]+&s=[\w-]+$/.test(url), `URL ${url}`);
    await page.reload();
    await h.ready();
    equal(page.url(), url, "URL after reload");
    equal(await h.snapshot(), before, "snapshot after reload");
  });

  await test(name("SVG export parses and has paths and labels"), async () => {
    h = await openDemo(page, base, demo.id);
    const file = await h.download("export-svg");
    equal(file.suggestedFilename(), `${demo.id}.svg`, "file name");
    const text = readFileSync(await file.path(), "utf8");
    const parsed = await page.evaluate((svg) => {
      const doc = new DOMParser().parseFromString(svg, "image/svg+xml");
      return {
        error: doc.querySelector("parsererror")?.textContent ?? null,
        root: doc.documentElement.nodeName,
        paths: doc.querySelectorAll("path").length,
        texts: doc.querySelectorAll("text").length,
      };
    }, text);
    equal(parsed.error, null, "parser error");
    equal(parsed.root, "svg", "root element");
    assert(parsed.paths > 3, `only ${parsed.paths} paths`);
    assert(parsed.texts > 0, "no text labels");
  });

  await test(name("TikZ export is a LaTeX document that compiles"), async () => {
    h = await openDemo(page, base, demo.id);
    const file = await h.download("export-tikz");
    equal(file.suggestedFilename(), `${demo.id}.tex`, "file name");
    const tex = readFileSync(await file.path(), "utf8");
    const found = inspectTikz(tex);
    equal(found.problems.join("; "), "", "problems");
    assert(found.paths > 3, `only ${found.paths} paths`);
    assert(found.nodes > 0, "no labels");
    if (hasPdflatex) {
      const compiled = compileTikz(tex);
      assert(compiled.ok, `pdflatex failed:\n${compiled.log}`);
      equal(compiled.pages, 1, "PDF pages");
    }
  });

  await test(name("PNG export is a PNG at 2x"), async () => {
    h = await openDemo(page, base, demo.id);
    const file = await h.download("export-png");
    const bytes = readFileSync(await file.path());
    assert(bytes.subarray(0, 8).equals(PNG_SIGNATURE), "PNG signature");
    const cssWidth = await h.canvas().evaluate((c) => c.clientWidth);
    equal(bytes.readUInt32BE(16), cssWidth * 2, "PNG width = 2 × CSS width");
  });

  await test(name("JSON export round-trips through import"), async () => {
    h = await openDemo(page, base, demo.id);
    await changePicture(20, 20);
    const exported = await h.snapshot();
    const file = await h.download("export-json");
    const text = readFileSync(await file.path(), "utf8");
    const data = JSON.parse(text);
    equal(data.version, 1, "version");
    equal(data.demo, demo.id, "demo");
    await page.locator('[data-action="reset"]').click();
    assert((await h.snapshot()) !== exported, "reset changed the picture");
    await h.importText(`${demo.id}.json`, text);
    equal(await h.snapshot(), exported, "snapshot after import");
    assert((await h.status()).includes(`${demo.id}.json`), "import confirmed in the status area");
  });

  await test(name("a malformed link shows a message and the page lives"), async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html#demo=${demo.id}&s=%%%not-base64!!`);
    h = demoHelpers(page);
    await h.ready();
    equal(await h.statusKind(), "error", "status kind");
    assert((await h.status()).length > 10, "a message is shown");
    // A bad hash edited into a working page keeps the last good picture.
    const good = await h.snapshot();
    await page.evaluate(
      () =>
        (location.hash =
          "#demo=" +
          new URLSearchParams(location.hash.slice(1)).get("demo") +
          "&s=eyJwb2ludHMiOjN9"),
    );
    await page.waitForFunction(() =>
      document.querySelector(".sl-status")?.textContent.includes("points"),
    );
    equal(await h.snapshot(), good, "picture kept");
    const problems = errors.take().filter((e) => !e.includes("404"));
    assert(problems.length === 0, problems.join("\n"));
  });

  await test(name("a malformed JSON import shows a message and keeps the picture"), async () => {
    h = await openDemo(page, base, demo.id);
    const good = await h.snapshot();
    await h.importText("broken.json", "{ this is not json");
    equal(await h.statusKind(), "error", "status kind");
    assert((await h.status()).includes("broken.json"), "message names the file");
    await h.importText(
      "wrong.json",
      JSON.stringify({ version: 1, demo: demo.id, state: { points: "nope" } }),
    );
    assert((await h.status()).includes("points"), `message names the field: ${await h.status()}`);
    equal(await h.snapshot(), good, "picture kept");
    // Still interactive.
    await changePicture(15, 0);
    assert((await h.snapshot()) !== good, "still draggable");
  });

  await test(
    name("formula lines shrink to fit the panel in lecture mode (1280 px wide)"),
    async () => {
      // At 1.6× type 16 of the 20 demos had lines running out of the panel; each line now
      // shrinks until it fits (never below MIN_FIT_SCALE), and a line that fits keeps its size.
      await openDemo(page, base, demo.id);
      const measure = () =>
        page.evaluate(() =>
          [...document.querySelectorAll(".sl-formula-line")].map((l) => ({
            client: l.clientWidth,
            scroll: l.scrollWidth,
            size: l.style.fontSize,
          })),
        );
      // At normal size every line fits at 1280 px: none is shrunk.
      const normal = await measure();
      assert(
        normal.every((l) => l.size === "" && l.scroll <= l.client + 1),
        `normal-size lines ${JSON.stringify(normal)}`,
      );
      await page.locator('[data-action="lecture"]').first().click();
      // The refit follows the panel's resize (ResizeObserver), a frame or more after the click.
      const fits = () =>
        [...document.querySelectorAll(".sl-formula-line")].every(
          (l) => l.scrollWidth <= l.clientWidth + 1 || l.style.fontSize === "0.6em",
        );
      if (
        !(await page.waitForFunction(fits, null, { timeout: 3000 }).then(
          () => true,
          () => false,
        ))
      ) {
        const lines = (await measure()).map(
          (l, i) => `line ${i}: ${l.scroll} px in ${l.client} px at ${l.size || "full size"}`,
        );
        throw new Error(`lines still overflow in lecture mode:\n${lines.join("\n")}`);
      }
      // Back to normal size: the panel refits (its type size changed) and nothing stays shrunk.
      await page.locator('[data-action="lecture"]').first().click();
      await page.waitForFunction(
        () =>
          [...document.querySelectorAll(".sl-formula-line")].every((l) => l.style.fontSize === ""),
        null,
        { timeout: 3000 },
      );
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    },
  );

  for (const [what, body] of await demoChecks(demo.id)) {
    await test(name(what), async () => {
      h = await openDemo(page, base, demo.id);
      await body(page, h, base, { assert, equal, settle, openDemo, PLAY_MS });
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    });
  }
}

// ------------------------------------------------------------------ run

/** A browser of its own (profile, context, page and its error watch) for a share of the demos. */
async function launchWorker() {
  const profile = mkdtempSync(join(tmpdir(), "splinelab-e2e-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    args: [...CHROMIUM_ARGS],
    viewport: VIEWPORT,
    deviceScaleFactor: 1,
    acceptDownloads: true,
  });
  const page = context.pages()[0] ?? (await context.newPage());
  return { profile, context, page, errors: watchErrors(page) };
}

async function closeWorker({ profile, context }) {
  await context.close();
  rmSync(profile, { recursive: true, force: true });
}

const server = await startServer(0);
const base = `http://127.0.0.1:${server.address().port}`;
const main = await launchWorker();
const { context, page, errors } = main;
const extraWorkers = [];

try {
  // The registry, as the page sees it.
  await page.goto(`${base}/index.html`);
  const registry = await page.evaluate(async () =>
    (await import("./demos/index.js")).demos.map(({ id, section, strings }) => ({
      id,
      section,
      strings,
    })),
  );
  // Which demos have handles (a demo whose curve is typed has none: see demoSuite).
  for (const id of await page.evaluate(
    async (ids) => {
      const { loadDemo } = await import("./demos/index.js");
      const modules = await Promise.all(ids.map((id) => loadDemo(id).catch(() => null)));
      return ids.filter((id, k) => {
        const m = modules[k];
        return !m || Boolean((m.figure ?? m.figure3d)?.handles) || !(m.figure ?? m.figure3d);
      });
    },
    registry.map((d) => d.id),
  ))
    withHandles.add(id);

  await test("registry: every manifest entry loads its module, which agrees on id, section and strings", async () => {
    const problems = await page.evaluate(async () => {
      const { demos, findDemo, loadDemo } = await import("./demos/index.js");
      const found = [];
      for (const entry of demos) {
        const demo = await loadDemo(entry.id);
        if (demo !== (await loadDemo(entry.id)))
          found.push(`${entry.id}: loadDemo is not memoised`);
        if (findDemo(entry.id) !== entry) found.push(`${entry.id}: findDemo`);
        for (const field of ["id", "section", "strings"]) {
          if (demo[field] !== entry[field])
            found.push(
              `${entry.id}: ${field} ${JSON.stringify(demo[field])} in the module, ${JSON.stringify(entry[field])} in the manifest`,
            );
        }
        // The declarative contract (lib/demo.js): no mount/update, no title at import.
        const exports = ["defaultState", "fields", "derive", "draw"];
        for (const old of ["mount", "validate", "title", "summary"]) {
          if (old in demo) found.push(`${entry.id}: an old-style ${old} export`);
        }
        for (const name of exports)
          if (!(name in demo)) found.push(`${entry.id}: no ${name} export`);
      }
      const refused = await loadDemo("no-such-demo").then(
        () => "loaded",
        (err) => err.message,
      );
      if (!refused.includes("no-such-demo")) found.push(`an unknown id: ${refused}`);
      if (findDemo("no-such-demo") !== undefined) found.push("findDemo of an unknown id");
      return found;
    });
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("the embeds of a page speak one language: ?lang=, else the first lang attribute", async () => {
    const pageUrl = `${base}/lang-embed-test.html`;
    const body =
      '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="a" demo="de-casteljau" controls="minimal"></spline-lab><spline-lab id="b" demo="de-casteljau" controls="minimal" lang="it"></spline-lab><spline-lab id="c" demo="de-casteljau" controls="minimal" lang="hr"></spline-lab></body></html>';
    const resets = async () => {
      for (const id of ["a", "b", "c"]) {
        await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
        await demoHelpers(page, `spline-lab#${id} `).ready();
      }
      return page.evaluate(() =>
        ["a", "b", "c"]
          .map((id) =>
            document
              .getElementById(id)
              .shadowRoot.querySelector('[data-action="reset"]')
              .textContent.trim(),
          )
          .join(","),
      );
    };
    await page.route(`${pageUrl}*`, (route) => route.fulfill({ contentType: "text/html", body }));
    try {
      await page.goto("about:blank");
      await page.goto(pageUrl);
      equal(await resets(), "Reimposta,Reimposta,Reimposta", "the first lang attribute (it)");
      await page.goto("about:blank");
      await page.goto(`${pageUrl}?lang=el`);
      equal(await resets(), "Επαναφορά,Επαναφορά,Επαναφορά", "?lang=el, the reader's choice");
    } finally {
      await page.unroute(`${pageUrl}*`);
    }
  });

  await test('<spline-lab controls="minimal" | "none"> keeps the figure with three buttons, or alone', async () => {
    const pageUrl = `${base}/controls-embed-test.html`;
    await page.goto("about:blank");
    await page.route(pageUrl, (route) =>
      route.fulfill({
        contentType: "text/html",
        body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="min" demo="de-casteljau" controls="minimal"></spline-lab><spline-lab id="none" demo="bspline-basis" controls="none"></spline-lab><spline-lab id="full" demo="de-casteljau"></spline-lab></body></html>',
      }),
    );
    try {
      await page.goto(pageUrl);
      for (const id of ["min", "none", "full"]) {
        await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
        await demoHelpers(page, `spline-lab#${id} `).ready();
      }
      const seen = await page.evaluate(() =>
        Object.fromEntries(
          ["min", "none", "full"].map((id) => {
            const root = document.getElementById(id).shadowRoot;
            const visible = (el) => el && el.getClientRects().length > 0;
            const buttons = [...root.querySelectorAll(".sl-toolbar .sl-button")].filter(visible);
            return [
              id,
              {
                buttons: buttons.map((b) => b.dataset.action).join(","),
                panel: visible(root.querySelector(".sl-panel")),
                canvas: visible(root.querySelector(".sl-figure canvas")),
                figureWidth: Math.round(
                  root.querySelector(".sl-figure").getBoundingClientRect().width,
                ),
                width: Math.round(root.querySelector(".sl-demo").getBoundingClientRect().width),
              },
            ];
          }),
        ),
      );
      equal(seen.min.buttons, "reset,fit,share", "minimal: three buttons");
      equal(seen.none.buttons, "", "none: no buttons");
      assert(!seen.min.panel && !seen.none.panel, "no side panel");
      assert(seen.full.panel && seen.full.buttons.split(",").length > 8, "full: everything");
      for (const id of ["min", "none"]) {
        assert(seen[id].canvas, `${id}: the figure is drawn`);
        assert(seen[id].figureWidth >= seen[id].width - 4, `${id}: the figure takes the width`);
      }
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    } finally {
      await page.unroute(pageUrl);
    }
  });

  await test('<spline-lab theme="dark" | "light"> fixes the colours whatever the reader prefers', async () => {
    const pageUrl = `${base}/theme-embed-test.html`;
    await page.goto("about:blank");
    await page.route(pageUrl, (route) =>
      route.fulfill({
        contentType: "text/html",
        body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="dark" demo="de-casteljau" theme="dark"></spline-lab><spline-lab id="light" demo="de-casteljau" theme="light"></spline-lab><spline-lab id="auto" demo="de-casteljau"></spline-lab></body></html>',
      }),
    );
    /** Mean brightness of a figure's top-left 4×4 device pixels (its background), per embed. */
    const brightness = () =>
      page.evaluate(() =>
        Object.fromEntries(
          ["dark", "light", "auto"].map((id) => {
            const canvas = document
              .getElementById(id)
              .shadowRoot.querySelector(".sl-figure canvas");
            const data = canvas.getContext("2d").getImageData(2, 2, 4, 4).data;
            let sum = 0;
            for (let i = 0; i < data.length; i += 4)
              sum += (data[i] + data[i + 1] + data[i + 2]) / 3;
            return [id, Math.round(sum / 16)];
          }),
        ),
      );
    try {
      for (const scheme of ["light", "dark"]) {
        await page.emulateMedia({ colorScheme: scheme });
        await page.goto(pageUrl);
        for (const id of ["dark", "light", "auto"]) {
          await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
          await demoHelpers(page, `spline-lab#${id} `).ready();
        }
        await settle(page);
        const seen = await brightness();
        assert(seen.dark < 60, `${scheme} preference: theme="dark" is dark (${seen.dark})`);
        assert(seen.light > 200, `${scheme} preference: theme="light" is light (${seen.light})`);
        const autoDark = seen.auto < 60;
        equal(
          autoDark,
          scheme === "dark",
          `${scheme} preference: the default follows it (${seen.auto})`,
        );
      }
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    } finally {
      await page.emulateMedia({ colorScheme: "light" });
      await page.unroute(pageUrl);
    }
  });

  await test("an imported JSON file above the size cap is refused at once and the picture stays", async () => {
    const h = await openDemo(page, base, "de-casteljau");
    const before = await h.snapshot();
    const big = JSON.stringify({
      version: 1,
      demo: "de-casteljau",
      state: {},
      pad: "x".repeat(1.5 * 1024 ** 2),
    });
    await h.importText("huge.json", big);
    assert((await h.status()).includes("huge.json"), `status: ${await h.status()}`);
    equal(await h.statusKind(), "error", "status kind");
    assert(/\b1[.,]5\b/.test(await h.status()), `the size is named: ${await h.status()}`);
    equal(await h.snapshot(), before, "the picture stays");
  });

  await test("under the pages' Content-Security-Policy (no inline script or style, no eval) nothing is refused", async () => {
    // Every violation of the pages' CSP meta (index.html, embed-example.html) is recorded.
    const record = () => {
      window.__violations = [];
      document.addEventListener("securitypolicyviolation", (e) =>
        window.__violations.push(
          `${e.violatedDirective} ${e.blockedURI} ${e.sourceFile}:${e.lineNumber}`,
        ),
      );
    };
    await page.addInitScript(record);
    const visits = [
      "index.html",
      "index.html#demo=de-boor",
      "index.html#demo=bezier-patch",
      "index.html#lecture=bezier-curves&scene=2",
      "index.html#exercise=quarter-circle",
      "embed-example.html",
    ];
    const found = [];
    for (const path of visits) {
      await page.goto("about:blank");
      await page.goto(`${base}/${path}`);
      if (path.startsWith("embed")) {
        await page.locator("spline-lab#worked").scrollIntoViewIfNeeded();
        await demoHelpers(page, "spline-lab#worked ").ready();
      } else if (path.includes("#")) await demoHelpers(page).ready();
      else await page.locator("a.card img[src^='data:image/png']").first().waitFor();
      await page.waitForFunction(
        () => !document.querySelector(".sl-formula") || document.querySelector(".katex"),
      );
      await settle(page);
      const csp = await page.evaluate(
        () => document.querySelector('meta[http-equiv="Content-Security-Policy"]')?.content ?? "",
      );
      assert(
        /script-src 'self' 'wasm-unsafe-eval';/.test(csp) &&
          !/unsafe-inline|unsafe-eval'/.test(csp.replace("wasm-unsafe-eval", "")),
        `${path}: CSP ${csp}`,
      );
      for (const v of await page.evaluate(() => window.__violations)) found.push(`${path}: ${v}`);
    }
    const problems = errors.take();
    assert(found.length === 0, found.join("\n"));
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("an embed's KaTeX styles and fonts leave a course page's own KaTeX alone", async () => {
    const pageUrl = `${base}/katex-page-test.html`;
    await page.goto("about:blank");
    await page.route(pageUrl, (route) =>
      route.fulfill({
        contentType: "text/html",
        body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><p><span class="katex" id="own">x</span></p><spline-lab id="one" demo="de-casteljau"></spline-lab></body></html>',
      }),
    );
    try {
      await page.goto(pageUrl);
      const before = await page.evaluate(() => {
        const own = getComputedStyle(document.getElementById("own"));
        return { family: own.fontFamily, size: own.fontSize };
      });
      await demoHelpers(page, "spline-lab#one ").ready();
      await page.locator("spline-lab#one .sl-formula .katex").first().waitFor();
      const after = await page.evaluate(() => {
        const own = getComputedStyle(document.getElementById("own"));
        const inside = document
          .getElementById("one")
          .shadowRoot.querySelector(".sl-formula .katex");
        return {
          family: own.fontFamily,
          size: own.fontSize,
          insideFamily: getComputedStyle(inside).fontFamily,
          families: [...document.fonts].map((f) => f.family.replaceAll('"', "")),
          pageLinks: [...document.querySelectorAll("link[rel=stylesheet]")].map((l) =>
            l.href.split("/").pop(),
          ),
        };
      });
      equal(after.family, before.family, "the page's .katex font family");
      equal(after.size, before.size, "the page's .katex font size");
      assert(
        after.insideFamily.includes("SL_KaTeX_Main"),
        `the embed's formulas use our fonts: ${after.insideFamily}`,
      );
      assert(
        after.families.length > 0 && after.families.every((f) => f.startsWith("SL_KaTeX_")),
        `font faces added to the page: ${after.families}`,
      );
      equal(after.pageLinks.join(), "katex-fonts.css", "the only stylesheet the page gets");
    } finally {
      await page.unroute(pageUrl);
    }
  });

  await test("formula panel: a line changed in its digits only is the line KaTeX typesets, patched in place", async () => {
    // KaTeX's own typesetting of each final line is the reference; the panel rewrites digits in
    // the tree it showed (same element) when the shape is kept, and typesets whole otherwise;
    // the picture follows at once, the MathML once the change is final (settle()).
    const problems = await page.evaluate(async () => {
      const { FormulaPanel, loadKatex } = await import("./lib/formula.js");
      const katex = await loadKatex();
      const host = document.createElement("div");
      host.style.width = "600px";
      document.body.append(host);
      const panel = new FormulaPanel(host);
      host.dispatchEvent(new FocusEvent("focusin")); // typeset now, wherever the panel is
      panel.set(["x"]);
      while (!host.querySelector(".katex")) await new Promise((resolve) => setTimeout(resolve, 10));
      const options = { displayMode: true, throwOnError: false, output: "htmlAndMathml" };
      const pairs = [
        ["P(0.250) = (2.000,\\ 3.125)", "P(0.75) = (12.5,\\ 3.125)", true],
        ["(7,\\ 8) + 0.5\\,(1, 2)", "(6.156,\\ 8.02) + 0.25\\,(1.5, 2)", true], // whole or decimal
        ["0.5em + 4pt \\hspace{0.5em} 3", "0.5em + 4pt \\hspace{0.5em} 7.25", true], // units stay
        [
          "\\frac{1}{3} + x_{2}^{10} = \\sqrt[3]{27}",
          "\\frac{7}{9} + x_{5}^{11} = \\sqrt[4]{256}",
          true,
        ],
        [
          "\\begin{pmatrix} 1 & 2 \\\\ 3 & 4 \\end{pmatrix}",
          "\\begin{pmatrix} 10 & 0 \\\\ 3 & 44 \\end{pmatrix}",
          true,
        ],
        ["\\text{step 3 of 10}: t = 0.5", "\\text{step 4 of 10}: t = 0.625", true],
        ["x^23 + 1", "x^45 + 1", false], // a digit after ^ is TeX's syntax: another shape
        ["|P'|^3 = {1.5}^3", "|P'|^3 = {12.25}^3", true], // … and stays while the number changes
        ["1.5^3", "1.75^3", false], // ^ raises the last digit alone: it is part of the shape
        ["\\frac12 + 0.5", "\\frac12 + 0.75", true],
        ["\\hspace{3pt} 5", "\\hspace{9pt} 5", false], // a dimension: typeset whole
        ["-1.5", "2.5", false], // another shape
        // A decimal comma as TeX writes it (format.js fmtTex): "{,}" between two runs of digits,
        // which KaTeX sets as one number; the shape keeps the comma, the digits change.
        ["P(0{,}250) = (2{,}000;\\ 3{,}125)", "P(0{,}75) = (12{,}5;\\ 3{,}125)", true],
        [
          "\\begin{pmatrix} 1{,}5 & 0 \\\\ 2 & 0{,}25 \\end{pmatrix}",
          "\\begin{pmatrix} 10{,}75 & 3 \\\\ 2 & 1{,}5 \\end{pmatrix}",
          true,
        ],
        ["x = 1{,}5", "x = 2", false], // a decimal became a whole number: another shape
      ];
      const found = [];
      for (const [first, second, kept] of pairs) {
        panel.set([first, "a = 1"]);
        const tree = host.querySelector(".sl-formula-line .katex");
        panel.set([second, "a = 2"]);
        const reference = document.createElement("div");
        const compare = (what, part) => {
          for (const [i, tex] of [second, "a = 2"].entries()) {
            katex.render(tex, reference, options);
            const line = host.querySelectorAll(".sl-formula-line")[i];
            const shown = part ? line.querySelector(part).outerHTML : line.innerHTML;
            const expected = part ? reference.querySelector(part).outerHTML : reference.innerHTML;
            if (shown !== expected) found.push(`${what}, ${tex}: ${shown} is not ${expected}`);
          }
        };
        compare("the picture at once", ".katex-html");
        panel.settle(); // the change is final: the MathML follows
        compare("the whole line after settle()", null);
        const same = host.querySelector(".sl-formula-line .katex") === tree;
        if (same !== kept) found.push(`${first} → ${second}: tree ${same ? "kept" : "replaced"}`);
      }
      panel.destroy();
      host.remove();
      return found;
    });
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("formula panel: after a drag the panel is the one a link to the same state typesets afresh", async () => {
    // Every frame of the drag rewrote digits in place; the reload typesets each line whole.
    // … also with decimal commas ("{,}" in the TeX: Croatian).
    for (const [id, lang] of [
      ["conics", "en"],
      ["de-boor", "en"],
      ["cardinal", "en"],
      ["bezier-patch", "en"],
      ["de-boor", "hr"],
      ["conics", "hr"],
    ]) {
      const h = await openDemo(page, base, id, "", lang);
      const handles = await h.handles();
      const start = handles[1] ?? handles[0];
      await page.mouse.move(start.x, start.y);
      await page.mouse.down();
      for (let k = 1; k <= 12; k++) {
        await page.mouse.move(start.x + 3 * k, start.y - 2 * k);
        await settle(page);
      }
      await page.mouse.up();
      await settle(page);
      const formula = page.locator(".sl-formula").first();
      const patched = await formula.evaluate((e) => e.innerHTML);
      if (lang === "hr")
        assert(/<mn>\d+,\d+<\/mn>/.test(patched), `${id} (hr): decimal commas in the formula`);
      await page.reload();
      await h.ready();
      equal(
        await formula.evaluate((e) => e.innerHTML),
        patched,
        `${id} (${lang}): the formula panel`,
      );
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("formula panel: on a phone, below the figure, KaTeX loads only once the page is scrolled", async () => {
    // Issue 26: KaTeX's module, fonts and first layout are not part of a phone's first load.
    const katexModules = () =>
      page.evaluate(
        () =>
          performance.getEntriesByType("resource").filter((r) => r.name.includes("katex.mjs"))
            .length,
      );
    await page.setViewportSize({ width: 412, height: 823 });
    try {
      await page.goto("about:blank");
      await page.goto(`${base}/index.html#demo=de-casteljau`);
      await page.locator(".sl-figure[data-handles]").first().waitFor({ state: "attached" });
      await settle(page);
      const panel = page.locator(".sl-formula").first();
      const below = await panel.evaluate((e) => e.getBoundingClientRect().top - innerHeight);
      assert(below > 48, `the panel starts ${below} px below the viewport`);
      equal(await katexModules(), 0, "KaTeX modules fetched before scrolling");
      equal(await panel.locator(".katex").count(), 0, "lines typeset before scrolling");
      assert((await panel.textContent()).includes("\\"), "the TeX source stands in");
      await page.evaluate(() => scrollBy(0, 100));
      await panel.locator(".katex").first().waitFor({ state: "attached" });
      equal(await katexModules(), 1, "KaTeX modules fetched after scrolling");
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    } finally {
      await page.setViewportSize(VIEWPORT);
    }
  });

  await test("occlusion: culling by triangle blocks gives the full test's answer on 3000 random segments", async () => {
    const counts = await page.evaluate(async () => {
      const { segmentBlocked, triangleBlocks } = await import("./lib/occlusion3d.js");
      const { loadWasm } = await import("./lib/wasm.js");
      const sl = await loadWasm();
      // A wavy bicubic patch (4×4 net, rows along u), tessellated as a 3D figure shows it.
      const net = [];
      for (let i = 0; i < 4; i++)
        for (let j = 0; j < 4; j++) net.push(i, j, ((i * 7 + j * 3) % 5) - 2);
      const patch = new sl.BezierSurface(net, 4, 4);
      const mesh = patch.tessellate(40, 40);
      patch.free();
      const blocks = triangleBlocks(mesh);
      let seed = 7;
      const random = () => {
        seed = (seed * 16807) % 2147483647;
        return seed / 2147483647;
      };
      const found = { blocked: 0, clear: 0, differ: 0 };
      for (let k = 0; k < 3000; k++) {
        const eye = [-4 + 11 * random(), -4 + 11 * random(), -6 + 12 * random()];
        const point = [3 * random(), 3 * random(), -2 + 4 * random()];
        const args = [mesh, ...eye, ...point, 1e-3];
        const full = segmentBlocked(...args);
        if (segmentBlocked(...args, blocks) !== full) found.differ++;
        found[full ? "blocked" : "clear"]++;
      }
      return found;
    });
    equal(counts.differ, 0, "segments where the culled test differs");
    assert(counts.blocked > 300 && counts.clear > 300, `a mix of cases: ${JSON.stringify(counts)}`);
  });

  await test("an embed of one demo requests no other demo module", async () => {
    // A course page with one <spline-lab>, served beside embed.js; every request is watched.
    const pageUrl = `${base}/one-embed-test.html`;
    const modules = [];
    const watch = (request) => {
      const path = new URL(request.url()).pathname;
      if (/^\/demos\/[^/]+\.js$/.test(path)) modules.push(path);
    };
    await page.goto("about:blank");
    await page.route(pageUrl, (route) =>
      route.fulfill({
        contentType: "text/html",
        body: '<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="one" demo="de-casteljau" points="0,0 2,2 6,4 8,2" t="0.25"></spline-lab></body></html>',
      }),
    );
    page.on("request", watch);
    try {
      await page.goto(pageUrl);
      await demoHelpers(page, "spline-lab#one ").ready();
      equal(
        (await demoHelpers(page, "spline-lab#one ").handles()).length,
        4,
        "the embed's handles",
      );
    } finally {
      page.off("request", watch);
      await page.unroute(pageUrl);
    }
    equal(
      JSON.stringify([...new Set(modules)].sort()),
      JSON.stringify(["/demos/de-casteljau.js", "/demos/index.js"]),
      "demo modules requested",
    );
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("the lib/README example is a whole demo that mounts and draws", async () => {
    // The code block of www/lib/README.md's contract section, served as a demo module.
    const readme = readFileSync(join(ROOT, "www/lib/README.md"), "utf8");
    const section = readme.slice(readme.indexOf("## The demo module contract"));
    const start = section.indexOf("```js\n") + 6;
    const code = section.slice(start, section.indexOf("\n```", start));
    const moduleUrl = `${base}/demos/readme-example.js`;
    await page.goto(`${base}/index.html`);
    await page.route(moduleUrl, (route) =>
      route.fulfill({ contentType: "text/javascript", body: code }),
    );
    try {
      const shown = await page.evaluate(async () => {
        const demo = await import("./demos/readme-example.js");
        const { mountDemo, validateState } = await import("./lib/shell.js");
        const { loadWasm } = await import("./lib/wasm.js");
        const sl = await loadWasm();
        const host = document.createElement("div");
        document.body.append(host);
        const state = validateState(demo, structuredClone(demo.defaultState));
        const mounted = mountDemo(host, demo, { sl, state, shareUrl: () => "" });
        await new Promise((resolve) => setTimeout(resolve, 300));
        const result = {
          handles: host.querySelector(".sl-figure").dataset.handles,
          formula: host.querySelector(".sl-formula").textContent,
          label: host.querySelector("canvas").getAttribute("aria-label"),
        };
        mounted.destroy();
        host.remove();
        return result;
      });
      assert(shown.handles?.length > 0, "the example has handles");
      assert(shown.formula.includes("1.813"), `P(1/4) in the formula: ${shown.formula}`);
      assert(shown.label.includes("0.25"), `t in the label: ${shown.label}`);
    } finally {
      await page.unroute(moduleUrl);
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("the lib/README 3D example is a whole demo that mounts and draws with WebGL", async () => {
    const readme = readFileSync(join(ROOT, "www/lib/README.md"), "utf8");
    const section = readme.slice(readme.indexOf("## 3D figures"));
    const start = section.indexOf("```js\n") + 6;
    const code = section.slice(start, section.indexOf("\n```", start));
    const moduleUrl = `${base}/demos/readme-example-3d.js`;
    await page.goto(`${base}/index.html`);
    await page.route(moduleUrl, (route) =>
      route.fulfill({ contentType: "text/javascript", body: code }),
    );
    try {
      const shown = await page.evaluate(async () => {
        const demo = await import("./demos/readme-example-3d.js");
        const { mountDemo, validateState } = await import("./lib/shell.js");
        const { loadWasm } = await import("./lib/wasm.js");
        const { prepareFigure } = await import("./lib/three-loader.js");
        const sl = await loadWasm();
        await prepareFigure(demo);
        const host = document.createElement("div");
        document.body.append(host);
        const state = validateState(demo, structuredClone(demo.defaultState));
        const mounted = mountDemo(host, demo, { sl, state, shareUrl: () => "" });
        await new Promise((resolve) => setTimeout(resolve, 300));
        const canvas = host.querySelector("canvas");
        const copy = document.createElement("canvas");
        copy.width = canvas.width;
        copy.height = canvas.height;
        const g = copy.getContext("2d");
        g.drawImage(canvas, 0, 0);
        const d = g.getImageData(0, 0, copy.width, copy.height).data;
        let blue = 0;
        for (let i = 0; i < d.length; i += 4) if (d[i + 2] > 90 && d[i + 2] > d[i] + 60) blue++;
        const result = {
          handles: host.querySelector(".sl-figure").dataset.handles,
          view: mounted.state.view,
          blue,
        };
        mounted.destroy();
        host.remove();
        return result;
      });
      equal(shown.handles?.split(";").length, 4, "handles of the 2 × 2 net");
      equal(shown.view?.length, 6, "a camera in the state");
      assert(shown.blue > 1000, `${shown.blue} surface pixels`);
    } finally {
      await page.unroute(moduleUrl);
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("3D: a scene crosses to the rendering worker with its objects' identity kept, and neither side keeps more than the last frame", async () => {
    const { SceneEncoder, SceneDecoder } = await import("../../www/lib/scene-transfer.js");
    const encoder = new SceneEncoder();
    const decoder = new SceneDecoder();
    // As postMessage does: a structured clone of the encoded frame.
    const send = (spec) => decoder.decode(structuredClone(encoder.encode(spec)));
    /** Typed arrays in a message (what a frame copies to the worker). */
    const arrays = (message) =>
      ArrayBuffer.isView(message)
        ? 1
        : message && typeof message === "object"
          ? Object.values(message).reduce((n, v) => n + arrays(v), 0)
          : 0;
    const mesh = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
      indices: new Uint32Array([0, 1, 2]),
    };
    const iso = new Float32Array([0, 0, 0, 1, 1, 1]);
    const frame = (m, curves) => ({
      surfaces: [{ mesh: m, shading: "lit" }],
      wireframe: [{ mesh: m, grid: [2, 2] }],
      curves,
    });
    const message = encoder.encode(frame(mesh, [iso]));
    equal(arrays(message), 3, "typed arrays in the first frame (positions, indices, the curve)");
    const first = decoder.decode(structuredClone(message));
    equal(
      first.wireframe[0].mesh,
      first.surfaces[0].mesh,
      "one mesh for the surface and its wireframe",
    );
    equal(
      JSON.stringify([...first.surfaces[0].mesh.positions]),
      JSON.stringify([...mesh.positions]),
      "positions",
    );
    equal(first.surfaces[0].shading, "lit", "a string field");
    equal(JSON.stringify(first.wireframe[0].grid), "[2,2]", "an array of numbers");
    // The same mesh again (an orbit): the same object on the other side, sent by name only.
    const again = encoder.encode(frame(mesh, [iso]));
    equal(arrays(again), 0, "typed arrays in an unchanged frame");
    const second = decoder.decode(structuredClone(again));
    equal(second.surfaces[0].mesh, first.surfaces[0].mesh, "the unchanged mesh is the same object");
    equal(second.curves[0], first.curves[0], "the unchanged curve is the same object");
    // A new mesh (a drag): a new object; the curve left out for one frame is sent whole after.
    const moved = { ...mesh, positions: new Float32Array([0, 0, 1, 1, 0, 0, 0, 1, 0]) };
    const third = send(frame(moved, []));
    assert(third.surfaces[0].mesh !== second.surfaces[0].mesh, "a changed mesh is a new object");
    equal(third.surfaces[0].mesh.positions[2], 1, "its new positions");
    const back = encoder.encode(frame(moved, [iso]));
    equal(arrays(back), 1, "typed arrays sent: the curve absent for a frame, whole (not the mesh)");
    const fourth = decoder.decode(structuredClone(back));
    equal(JSON.stringify([...fourth.curves[0]]), JSON.stringify([...iso]), "the curve's points");
    equal(fourth.surfaces[0].mesh, third.surfaces[0].mesh, "the mesh kept from the last frame");
    // A name the receiver never got is an error, not a wrong picture.
    let refused = "";
    try {
      new SceneDecoder().decode({ "@ref": 7 });
    } catch (err) {
      refused = err.message;
    }
    assert(refused.includes("unknown object 7"), `refused: ${refused}`);
  });

  await test("3D: a figure has at most one frame in flight: requests made meanwhile collapse into the newest", async () => {
    await page.goto(`${base}/index.html`);
    const out = await page.evaluate(async () => {
      const { startGlWorker, RemoteFigure } = await import("./lib/gl-client.js");
      await startGlWorker();
      const frames = [];
      let done;
      const finished = new Promise((resolve) => {
        done = resolve;
      });
      const figure = new RemoteFigure({
        onFrame: (frame) => {
          frames.push({
            curves: frame.scene.curves.length,
            size: [frame.bitmap.width, frame.bitmap.height],
          });
          frame.bitmap.close();
          if (!figure.pending) done();
        },
        onLost: () => done(),
      });
      const camera = { view: [-90, 0, 5, 0, 0, 0], fov: 30, aspect: 1 };
      // Five requests in one task, each with one more curve than the last.
      for (let n = 1; n <= 5; n++) {
        const curves = Array.from({ length: n }, (_, k) => new Float32Array([0, k, 0, 1, k, 0]));
        figure.render({ curves }, camera, 16 + n, 8);
      }
      const pendingAtOnce = figure.pending;
      await finished;
      figure.dispose();
      return {
        frames,
        pendingAtOnce,
        pendingAfter: document.documentElement.hasAttribute("data-gl-pending"),
      };
    });
    equal(out.pendingAtOnce, true, "pending while frames are on their way");
    equal(
      JSON.stringify(out.frames),
      JSON.stringify([
        { curves: 1, size: [17, 8] },
        { curves: 5, size: [21, 8] },
      ]),
      "frames drawn: the first request, then only the newest",
    );
    equal(out.pendingAfter, false, "<html data-gl-pending> once every frame arrived");
  });

  await test("3D: the page's camera (view-camera.js) projects and casts rays as three.js' PerspectiveCamera does; orbit gestures follow OrbitControls' rules", async () => {
    await page.goto(`${base}/index.html`);
    const out = await page.evaluate(async () => {
      const { loadThree } = await import("./lib/three-loader.js");
      const { ViewCamera } = await import("./lib/view-camera.js");
      const { OrbitGesture } = await import("./lib/orbit-gesture.js");
      const { applyCamera } = await import("./lib/camera3d.js");
      const { THREE } = await loadThree();
      let seed = 7;
      const random = () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 2 - 1;
      let worst = 0;
      let worstRay = 0;
      for (let k = 0; k < 50; k++) {
        const numbers = [
          180 * random(),
          85 * random(),
          1 + 9 * Math.abs(random()),
          random(),
          random(),
          random(),
        ];
        const fov = 20 + 40 * Math.abs(random());
        const aspect = 0.5 + 2 * Math.abs(random());
        const mine = new ViewCamera();
        mine.set(numbers);
        mine.fov = fov;
        mine.aspect = aspect;
        const theirs = new THREE.PerspectiveCamera(fov, aspect);
        applyCamera(theirs, numbers);
        const point = [3 * random(), 3 * random(), 3 * random()];
        const a = mine.project(...point, new Float64Array(3));
        const b = new THREE.Vector3(...point).project(theirs);
        worst = Math.max(
          worst,
          Math.abs(a[0] - b.x),
          Math.abs(a[1] - b.y),
          Math.abs(a[2] - b.z) / Math.max(1, Math.abs(b.z)),
        );
        const ndc = [random(), random()];
        const ray = new THREE.Raycaster();
        ray.setFromCamera(new THREE.Vector2(...ndc), theirs);
        const d = mine.rayDirection(...ndc, new Float64Array(3));
        const e = ray.ray.direction;
        worstRay = Math.max(
          worstRay,
          Math.abs(d[0] - e.x),
          Math.abs(d[1] - e.y),
          Math.abs(d[2] - e.z),
        );
      }
      // Gestures on a 400 px tall canvas, fov 30°: a drag across the height turns a full circle;
      // a pan of 40 px moves the target's picture 40 px (it follows the pointer); wheel up nears.
      let camera = [0, 10, 4, 0, 0, 0];
      const view = new ViewCamera();
      view.set(camera);
      view.fov = 30;
      view.aspect = 1.5;
      let ends = 0;
      const gesture = new OrbitGesture({
        camera: () => camera,
        height: () => 400,
        fov: () => 30,
        view,
        change: (c) => {
          camera = c;
          view.set(c);
        },
        end: () => ends++,
      });
      const move = (id, x, y) => gesture.move({ pointerId: id }, x, y);
      gesture.down({ pointerId: 1, button: 0 }, 100, 100);
      move(1, 200, 150);
      gesture.up({ pointerId: 1 });
      const rotated = [...camera];
      // The target (at the distance's depth) before and after the pan.
      const before = view.project(0, 0, 0, new Float64Array(3));
      gesture.down({ pointerId: 2, button: 0, shiftKey: true }, 100, 100);
      move(2, 140, 100);
      gesture.up({ pointerId: 2 });
      const after = view.project(0, 0, 0, new Float64Array(3));
      // NDC x to px on a 600 × 400 canvas: (x + 1) / 2 · 600.
      const panPx = ((after[0] - before[0]) / 2) * 600;
      const d0 = camera[2];
      gesture.wheel({ deltaY: -100, deltaMode: 0 });
      const nearer = camera[2] / d0;
      gesture.wheel({ deltaY: 100, deltaMode: 0 });
      const back = camera[2] / d0;
      // A pinch: fingers 100 px apart, then 200, then 250: the distance × 100/250.
      const d1 = camera[2];
      gesture.down({ pointerId: 3, button: 0 }, 100, 200);
      gesture.down({ pointerId: 4, button: 0 }, 200, 200);
      move(4, 300, 200);
      move(3, 50, 200);
      gesture.up({ pointerId: 3 });
      gesture.up({ pointerId: 4 });
      return { worst, worstRay, rotated, panPx, nearer, back, pinched: camera[2] / d1, ends };
    });
    assert(out.worst < 1e-9, `projection differs from three.js by ${out.worst}`);
    assert(out.worstRay < 1e-9, `ray direction differs from three.js by ${out.worstRay}`);
    equal(
      JSON.stringify(out.rotated.slice(0, 2).map((v) => Math.round(v * 1e9) / 1e9)),
      JSON.stringify([-90, 55]),
      "a 100 × 50 px drag on 400 px: azimuth −90°, elevation +45°",
    );
    assert(
      Math.abs(out.panPx - 40) < 1e-6,
      `a 40 px pan moved the target's picture ${out.panPx} px`,
    );
    assert(Math.abs(out.nearer - 0.95) < 1e-12, `wheel up 100 px: distance × ${out.nearer}`);
    assert(Math.abs(out.back - 1) < 1e-12, `wheel down 100 px after: distance × ${out.back}`);
    assert(
      Math.abs(out.pinched - 100 / 250) < 1e-12,
      `pinch from 100 to 250 px apart: distance × ${out.pinched}`,
    );
    equal(out.ends, 5, "an end after each drag, wheel turn and pinch");
  });

  await test("3D: the rendering worker's warm-up links every program a patch's first frame draws with; the page's main thread makes no WebGL context", async () => {
    await page.goto(`${base}/index.html`);
    const out = await page.evaluate(async () => {
      const { loadDemo } = await import("./demos/index.js");
      const { mountDemo, validateState } = await import("./lib/shell.js");
      const { loadWasm } = await import("./lib/wasm.js");
      const { prepareFigure } = await import("./lib/three-loader.js");
      const { workerPrograms } = await import("./lib/gl-client.js");
      const { sharedRendererMade } = await import("./lib/shared-gl.js");
      const sl = await loadWasm();
      const demo = await loadDemo("bezier-patch");
      await prepareFigure(demo);
      const host = document.createElement("div");
      host.style.width = "640px";
      document.body.append(host);
      const state = validateState(demo, structuredClone(demo.defaultState));
      const mounted = mountDemo(host, demo, { sl, state, shareUrl: () => "" });
      const shown = () => host.querySelector(".sl-figure[data-geometries]");
      for (let k = 0; k < 100 && !shown(); k++) await new Promise((r) => setTimeout(r, 50));
      const drawn = Boolean(shown()) && host.querySelector("canvas").width;
      const programs = workerPrograms();
      const mainThreadGl = sharedRendererMade();
      mounted.destroy();
      host.remove();
      return { programs, drawn, mainThreadGl };
    });
    assert(out.drawn > 0, "the figure was drawn");
    const { warmed, now } = out.programs;
    assert(warmed >= 2, `${warmed} programs after the warm-up (surface, lines)`);
    equal(now, warmed, "programs after the figure's first frame");
    equal(out.mainThreadGl, false, "a WebGL renderer on the page's main thread");
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("strings: every key the UI asks for exists in English", async () => {
    // Literal keys t("…") anywhere in www/, plus the keys the shell builds from each demo's prefix.
    const missingDemoKeys = await page.evaluate(async () => {
      const strings = await import("./lib/strings.js");
      const { demos } = await import("./demos/index.js");
      const keys = demos.flatMap((d) =>
        ["title", "summary", "whatYouSee", "try1"].map((k) => `${d.strings}.${k}`),
      );
      return keys.filter((k) => !strings.has(k));
    });
    assert(missingDemoKeys.length === 0, `missing demo keys: ${missingDemoKeys.join(", ")}`);
    const missing = [];
    const strings = await import("../../www/lib/strings.js");
    for (const file of listJs(join(ROOT, "www"))) {
      for (const [, fn, key] of readFileSync(file, "utf8").matchAll(/\b(tp?)\("([\w.]+)"/g)) {
        if (!strings.has(key) && !(fn === "tp" && strings.has(`${key}.other`)))
          missing.push(`${file.slice(ROOT.length + 1)}: ${key}`);
      }
    }
    assert(missing.length === 0, `keys missing from strings.js:\n${missing.join("\n")}`);
  });

  await test("strings: tp() picks the plural form by Intl.PluralRules of the active language", async () => {
    const { addLocale, setLocale, locale, tp, t, formatNumber } = await import(
      "../../www/lib/strings.js"
    );
    // A made-up key in English and in Croatian (one: 1, 21, …; few: 2–4, 22–24, …; other: the rest).
    addLocale("en", { "test.apples.one": "{count} apple", "test.apples.other": "{count} apples" });
    addLocale("hr", {
      "test.apples.one": "{count} jabuka",
      "test.apples.few": "{count} jabuke",
      "test.apples.other": "{count} jabuka",
      "test.only.other": "samo {count}",
    });
    try {
      equal(tp("test.apples", 1), "1 apple", "en one");
      equal(tp("test.apples", 0), "0 apples", "en zero is other");
      equal(
        tp("test.apples", 3, { count: formatNumber(3) }),
        "3 apples",
        "en other, formatted count",
      );
      equal(
        tp("test.missing", 2, { n: 2 }),
        "test.missing",
        "no forms: the key itself, as t() does",
      );
      setLocale("hr");
      equal(locale(), "hr", "active language");
      equal(
        [1, 3, 5, 21, 22].map((n) => tp("test.apples", n)).join(", "),
        "1 jabuka, 3 jabuke, 5 jabuka, 21 jabuka, 22 jabuke",
        "hr forms",
      );
      equal(tp("test.only", 3), "samo 3", "a missing category falls back to .other");
      equal(formatNumber(1.8125), "1,813", "hr decimal comma, 3 decimals");
      equal(
        t("gallery.heading"),
        "Demos, by syllabus section",
        "a key the table lacks falls back to English",
      );
    } finally {
      setLocale("en");
    }
    equal(formatNumber(-0.0001), "0", "no minus zero");
  });

  // What scripts/glue.mjs adds to the glue (…Into methods, freed objects), checked in Node.
  for (const [what, body] of (await import("./per-call.mjs")).default) {
    await test(`per-call glue: ${what}`, async () => body());
  }

  await test("the TypeScript declarations type every public parameter and result (no `any`)", async () => {
    // The package's .d.ts as a JS developer's editor reads it; the raw wasm exports after
    // `InitInput` are wasm-bindgen's own.
    const dts = readFileSync(join(ROOT, "www/pkg/splinelab.d.ts"), "utf8");
    const publicPart = dts.slice(0, dts.indexOf("export type InitInput"));
    const code = publicPart.split("\n").filter((line) => !/^\s*(\/\*\*|\*)/.test(line));
    const loose = code.filter((line) => /\bany\b/.test(line));
    assert(
      publicPart.includes("class BSplineSurface") &&
        publicPart.includes("basisNonZero(u: number): Float64Array") &&
        publicPart.includes(
          "evaluateInto<T extends Float64Array | number[]>(t: number, out: T): T;",
        ) &&
        !publicPart.includes("Scratch"),
      "declarations of this build",
    );
    assert(loose.length === 0, `untyped declarations:\n${loose.join("\n")}`);
  });

  await test("gallery lists every demo with its title, summary, a #demo= link and a thumbnail drawn near the viewport", async () => {
    // A fresh gallery, its requests watched: demo modules are imported only for cards near the viewport.
    const modules = new Set();
    const watch = (request) => {
      const path = new URL(request.url()).pathname;
      if (/^\/demos\/[^/]+\.js$/.test(path) && !path.endsWith("/index.js")) modules.add(path);
    };
    page.on("request", watch);
    try {
      await page.goto("about:blank");
      await page.goto(`${base}/index.html`);
      await page.locator(".card").first().waitFor();
      await page.waitForFunction(() =>
        document.querySelector("a.card img")?.src.startsWith("data:image/png"),
      );
      await settle(page);
      const early = modules.size;
      assert(
        early > 0 && early < registry.length,
        `${early} of ${registry.length} demo modules imported before scrolling`,
      );
      const words = await page.evaluate(async () => {
        const { t } = await import("./lib/strings.js");
        const { demos } = await import("./demos/index.js");
        return demos.map((d) => [d.id, t(`${d.strings}.title`), t(`${d.strings}.summary`)]);
      });
      for (const [id, title, summary] of words) {
        const card = page.locator(`a.card[href="#demo=${id}"]`);
        equal(await card.count(), 1, `card for ${id}`);
        equal(await card.locator(".card-title").textContent(), title, `${id} title`);
        equal(await card.locator(".card-line").textContent(), summary, `${id} summary`);
        await card.scrollIntoViewIfNeeded();
        await page.waitForFunction(
          (id) =>
            document
              .querySelector(`a.card[data-demo="${id}"] img`)
              ?.src.startsWith("data:image/png"),
          id,
        );
      }
      equal(
        modules.size,
        registry.length,
        "every module imported once its card was near the viewport",
      );
    } finally {
      page.off("request", watch);
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  for (const code of ["el", "hr", "it"]) {
    await test(`${code}: ?lang=${code} speaks the language in the gallery and a demo (<html lang>, labels, numbers with a decimal comma)`, async () => {
      const table = (await import(join(ROOT, `www/lib/locales/${code}.js`))).default;
      const english = (await import(join(ROOT, "www/lib/strings.js"))).englishTable();
      const keys = ["gallery.heading", "deCasteljau.title", "toolbar.reset", "toolbar.export"];
      for (const key of keys)
        assert(table[key] && table[key] !== english[key], `${code} translates ${key}`);
      await page.goto("about:blank");
      await page.goto(`${base}/index.html?lang=${code}`);
      await page.locator(".card").first().waitFor();
      equal(await page.evaluate(() => document.documentElement.lang), code, "<html lang>");
      equal(
        await page.locator("main h1").first().textContent(),
        table["gallery.heading"],
        "gallery heading",
      );
      equal(
        await page.locator('a.card[href="#demo=de-casteljau"] .card-title').textContent(),
        table["deCasteljau.title"],
        "card title",
      );
      equal(await page.locator(".language-menu").inputValue(), code, "the menu shows the language");
      await page.goto("about:blank");
      await page.goto(`${base}/index.html?lang=${code}#demo=de-casteljau`);
      const h = demoHelpers(page);
      await h.ready();
      equal(
        await page.locator("h1.sl-title").textContent(),
        table["deCasteljau.title"],
        "demo title",
      );
      equal(
        await page.locator('[data-action="reset"]').textContent(),
        table["toolbar.reset"],
        "a toolbar button",
      );
      const shown = await page.evaluate(async () =>
        (await import("./lib/strings.js")).formatNumber(0.25),
      );
      equal(shown, "0,25", "a number in the language");
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    });
  }

  // Numbers people read follow the language; what machines read does not. The default De
  // Casteljau figure, worked out by hand: P = (0, 0), (2, 2), (6, 4), (8, 2), t = 1/4, so
  // p₀¹ = (0.5, 0.5) and P(1/4) = (29/16, 23/16) = (1.8125, 1.4375): "1.813" in a formula,
  // "1.81" in the figure's name. With a decimal comma the entries of a point are separated by
  // "; " ("(1,81; 1,44)") and KaTeX gets "1{,}813", which it sets as one number (one <mn>).
  /** The link's state, P₁ nudged right by the keyboard, and the announcement that followed. */
  const nudged = async (live, canvas) => {
    await canvas.focus(); // keyboard focus selects P₀
    await page.keyboard.press("Tab");
    await page.keyboard.press("Shift+ArrowRight");
    await settle(page);
    return live.textContent();
  };
  // Greek separates with the ano teleia ("; " would read as a question mark): "· " in text,
  // KaTeX's punctuation dot \cdotp ("⋅") in a formula.
  for (const [code, dot, sep, texSep = sep] of [
    ["en", ".", ", "],
    ["hr", ",", "; "],
    ["el", ",", "· ", "⋅ "],
    ["it", ",", "; "],
  ]) {
    await test(`${code}: numbers read in the language: a table cell, the formula (KaTeX), the figure's name, an announcement (${dot === "," ? `decimal comma, “${sep.trim()}” between coordinates` : "decimal point"})`, async () => {
      const local = (text, between = sep) => text.replaceAll(".", dot).replaceAll(", ", between);
      await page.goto("about:blank");
      await page.goto(`${base}/index.html?lang=${code}#demo=de-casteljau`);
      const h = demoHelpers(page);
      await h.ready();
      const cell = await page
        .locator('[data-table="de-casteljau"] td[data-level="1"][data-index="0"]')
        .textContent();
      assert(cell.includes(local("≈ (0.500, 0.500)")), `table cell p₀¹: ${cell}`);
      const formula = await page
        .locator(".sl-formula")
        .first()
        .evaluate((panel) => {
          const lines = [...panel.querySelectorAll(".katex")];
          return {
            numbers: lines.flatMap((k) => [...k.querySelectorAll("mn")].map((n) => n.textContent)),
            shown: lines.map((k) => k.querySelector(".katex-html").textContent).join("\n"),
          };
        });
      const shown = formula.shown.replace(/\u00a0/g, " ");
      for (const n of ["1.813", "1.438"])
        assert(
          formula.numbers.includes(local(n)),
          `KaTeX sets ${local(n)} as one number: ${formula.numbers.join(" | ")}`,
        );
      assert(
        shown.includes(local("(1.813, 1.438)", texSep)),
        `the formula shows ${local("(1.813, 1.438)", texSep)}: ${shown}`,
      );
      const name = await h.canvas().getAttribute("aria-label");
      assert(name.includes(local("(1.81, 1.44)")), `the figure's name: ${name}`);
      const live = page.locator(".sl-figure .sl-announcer");
      const moved = await nudged(live, h.canvas());
      const coordinate = dot === "," ? "\\d+,\\d+" : "\\d+\\.\\d+";
      assert(new RegExp(`\\(${coordinate}${sep}2\\)$`).test(moved), `announced: ${moved}`);
      const problems = errors.take();
      assert(problems.length === 0, problems.join("\n"));
    });
  }

  await test("hr: the link, the JSON export, the SVG path data and the TikZ coordinates keep the decimal point (the same as in English)", async () => {
    /** The nudged state's link and its exports in language `code`. */
    const exportsIn = async (code, hash) => {
      await page.goto("about:blank");
      await page.goto(`${base}/index.html?lang=${code}#demo=de-casteljau${hash}`);
      const h = demoHelpers(page);
      await h.ready();
      const read = async (action) => readFileSync(await (await h.download(action)).path(), "utf8");
      return {
        hash: new URL(page.url()).hash,
        json: await read("export-json"),
        svg: await read("export-svg"),
        tikz: await read("export-tikz"),
      };
    };
    await page.goto("about:blank");
    await page.goto(`${base}/index.html?lang=hr#demo=de-casteljau`);
    const h = demoHelpers(page);
    await h.ready();
    await nudged(page.locator(".sl-figure .sl-announcer"), h.canvas());
    const hash = new URL(page.url()).hash.replace(/^#demo=de-casteljau/, "");
    const state = await page.evaluate(async () => {
      const { parseHash, decodeState } = await import("./lib/state.js");
      return decodeState(parseHash(location.hash).s);
    });
    const x = state.points[1][0];
    assert(x > 2 && !Number.isInteger(x), `P₁ nudged off the grid: ${x}`);
    const hr = await exportsIn("hr", hash);
    const en = await exportsIn("en", hash);
    equal(hr.hash, en.hash, "the link");
    assert(hr.json.includes(`${x}`) && `${x}`.includes("."), `the JSON holds ${x} with a point`);
    equal(hr.json, en.json, "the JSON export");
    const paths = (svg) => [...svg.matchAll(/ d="([^"]*)"/g)].map((m) => m[1]);
    assert(
      paths(hr.svg).some((d) => /\d\.\d/.test(d)),
      "the SVG paths have decimals",
    );
    equal(paths(hr.svg).join("\n"), paths(en.svg).join("\n"), "the SVG path data");
    const coordinates = (tikz) => [...tikz.matchAll(/\((-?[\d.,]+)\)/g)].map((m) => m[1]);
    assert(coordinates(hr.tikz).length > 10, "TikZ coordinates found");
    equal(coordinates(hr.tikz).join(" "), coordinates(en.tikz).join(" "), "the TikZ coordinates");
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  // Each exercise's goal reached by hand: the values a student would reach, worked out on paper.
  const SOLUTIONS = {
    "close-the-gap": (s) => ({ right: [[4, 1], ...s.right.slice(1)] }),
    "make-it-c1": (s) => ({ right: [s.right[0], [5, -1], ...s.right.slice(2)] }),
    "piecewise-c1": (s) => ({ pieces: [s.pieces[0], { ...s.pieces[1], x: "t^2 - 4t + 3" }] }),
    "bezier-pieces": () => ({ inserted: [1, 2, 3] }),
    "quarter-circle": () => ({ w1: Math.SQRT1_2 }),
    "natural-ends": () => ({ end: "natural" }),
    "horn-torus": () => ({ R: 2, r: 2 }),
    "through-every-point": (s) => ({ role: "data", count: s.points.length }),
    // A teardrop drawn once round, back to its start: x = sin t · sin(t/2), y = cos t (a corner
    // at the top, where both x′ and y′ vanish from either side at different angles), 2.5 units
    // tall at 60 px per unit: one corner, closed, a few pieces at 3 px.
    "sketch-pieces": () => {
      const flat = [];
      for (let k = 0; k <= 120; k++) {
        const u = (2 * Math.PI * k) / 120;
        flat.push(5 + 2.5 * Math.sin(u) * Math.sin(u / 2), 3 + 2.5 * Math.cos(u));
      }
      return { stroke: encodeStroke(flat, -3), scale: 60, tolerance: 3, output: "G1", edits: [] };
    },
  };

  await test("every exercise: its start is not solved, the worked solution is, checked by the core (#exercise=…)", async () => {
    const list = await page.evaluate(async () => {
      const { exercises } = await import("./exercises/index.js");
      return exercises.map((e) => ({ id: e.id, section: e.section }));
    });
    equal(
      list
        .map((e) => e.id)
        .sort()
        .join(),
      Object.keys(SOLUTIONS).sort().join(),
      "exercises with a worked solution",
    );
    equal(new Set(list.map((e) => e.section)).size, 7, "one per syllabus section at least");
    const check = async () => {
      await page.locator('[data-action="exercise-check"]').click();
      return page.locator(".sl-exercise-result").getAttribute("data-kind");
    };
    for (const { id } of list) {
      await page.goto("about:blank");
      await page.goto(`${base}/index.html#exercise=${id}`);
      await demoHelpers(page).ready();
      equal(await check(), "not-yet", `${id}: the start is not solved`);
      assert(
        (await page.locator(".sl-exercise-result").textContent()).length > 10,
        `${id}: says why`,
      );
      const start = await page.evaluate(async (id) => {
        const { findExercise } = await import("./exercises/index.js");
        const { loadDemo } = await import("./demos/index.js");
        const exercise = findExercise(id);
        const demo = await loadDemo(exercise.demo);
        return { ...structuredClone(demo.defaultState), ...structuredClone(exercise.state) };
      }, id);
      const solved = { ...start, ...SOLUTIONS[id](start) };
      const hash = await page.evaluate(
        async ([id, state]) => {
          const { encodeState } = await import("./lib/state.js");
          return `#exercise=${id}&s=${encodeState(state)}`;
        },
        [id, solved],
      );
      await page.goto("about:blank");
      await page.goto(`${base}/index.html${hash}`);
      await demoHelpers(page).ready();
      equal(await check(), "solved", `${id}: the worked solution`);
      await page.locator('[data-action="exercise-hint"]').click();
      assert(await page.locator(".sl-exercise-hint").isVisible(), `${id}: the hint shows`);
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test('<spline-lab exercise="quarter-circle"> embeds the exercise; attributes change its state', async () => {
    const pageUrl = `${base}/exercise-embed-test.html`;
    await page.goto("about:blank");
    await page.route(pageUrl, (route) =>
      route.fulfill({
        contentType: "text/html",
        body: `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><script type="module" src="embed.js"></script></head><body><spline-lab id="ex" exercise="quarter-circle" w1="${Math.SQRT1_2}"></spline-lab><spline-lab id="bad" exercise="no-such-thing"></spline-lab></body></html>`,
      }),
    );
    try {
      await page.goto(pageUrl);
      await demoHelpers(page, "spline-lab#ex ").ready();
      await page.locator('spline-lab#ex [data-action="exercise-check"]').click();
      equal(
        await page.locator("spline-lab#ex .sl-exercise-result").getAttribute("data-kind"),
        "solved",
        "w1 = √2/2 from the attribute",
      );
      await page.locator("spline-lab#bad .sl-embed-error").waitFor();
      assert(
        (await page.locator("spline-lab#bad .sl-embed-error").textContent()).includes(
          "no-such-thing",
        ),
        "an unknown exercise is named",
      );
      await page.goto("about:blank");
      await page.goto(`${base}/index.html`);
      await page.locator("a[data-exercise]").first().waitFor();
      equal(await page.locator("a[data-exercise]").count(), 9, "the gallery lists the exercises");
    } finally {
      await page.unroute(pageUrl);
    }
  });

  await test("every lecture's scenes name a demo and a state it accepts, with an English caption", async () => {
    const problems = await page.evaluate(async () => {
      const { lectures, loadLecture } = await import("./lectures/index.js");
      const { loadDemo } = await import("./demos/index.js");
      const { validateState } = await import("./lib/shell.js");
      const found = [];
      const sections = new Set();
      for (const entry of lectures) {
        const lecture = await loadLecture(entry.id);
        if (lecture.id !== entry.id || lecture.section !== entry.section)
          found.push(`${entry.id}: id/section differ from the manifest`);
        sections.add(lecture.section);
        if (lecture.scenes.length < 5)
          found.push(`${entry.id}: only ${lecture.scenes.length} scenes`);
        for (const [k, scene] of lecture.scenes.entries()) {
          try {
            const demo = await loadDemo(scene.demo);
            validateState(demo, scene.state ?? {});
          } catch (err) {
            found.push(`${entry.id} scene ${k + 1}: ${err.message}`);
          }
          if (!scene.caption?.en) found.push(`${entry.id} scene ${k + 1}: no English caption`);
        }
      }
      if (sections.size !== 7) found.push(`lectures cover sections ${[...sections]}`);
      return found;
    });
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("a lecture plays: PageDown and arrows step, the scene is in the link, B blanks, Escape leaves with the state", async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html`);
    await page.locator('a[data-lecture="bezier-curves"]').click();
    await page.locator(".lecture .sl-figure canvas").first().waitFor();
    const caption = () => page.locator(".lecture-caption").textContent();
    assert((await caption()).includes("29/16, 23/16"), `scene 1 caption: ${await caption()}`);
    equal(await page.locator(".lecture-counter").textContent(), "1 / 8", "counter");
    assert(
      await page.locator(".sl-demo.sl-lecture, .sl-lecture").first().isVisible(),
      "the scene is in lecture mode",
    );
    await page.keyboard.press("PageDown");
    await page.waitForFunction(() => location.hash.endsWith("scene=2"));
    await page.locator('h2.sl-title:has-text("Bernstein")').waitFor();
    await page.keyboard.press("ArrowRight");
    await page.waitForFunction(() => location.hash.endsWith("scene=3"));
    await page.keyboard.press("PageUp");
    await page.waitForFunction(() => location.hash.endsWith("scene=2"));
    const second = await caption();
    await page.reload();
    await page.locator(".lecture .sl-figure canvas").first().waitFor();
    equal(await caption(), second, "the link restores the scene");
    await page.keyboard.press("b");
    assert(await page.locator(".lecture-blank").isVisible(), "B blanks the screen");
    await page.keyboard.press("x");
    assert(!(await page.locator(".lecture-blank").isVisible()), "any key brings the picture back");
    await page.keyboard.press("Escape");
    await page.waitForFunction(() => location.hash.startsWith("#demo=bernstein&s="));
    await demoHelpers(page).ready();
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("hr: a refusal of the curve library is worded in Croatian from its code and numbers", async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html?lang=hr#demo=knot-insertion`);
    await demoHelpers(page).ready();
    // u = 2.5 into the quadratic: multiplicity 1, 2, 3 = p + 1 are allowed, a fourth is not.
    for (let k = 0; k < 4; k++) {
      await page.locator('[data-action="insert"]').click();
      await settle(page);
    }
    const status = await page.locator(".sl-status").first().textContent();
    assert(
      status.includes("umetanje uzla 2,5") &&
        status.includes("višestrukost 4") &&
        !/would give/.test(status),
      `status: ${status}`,
    );
  });

  await test("typed numbers take a decimal point or comma; a list with semicolons keeps its decimal commas", async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html?lang=hr#demo=de-boor`);
    await demoHelpers(page).ready();
    const parsed = await page.evaluate(async () => {
      const { parseNumberInput: p, splitNumberList: s } = await import("./lib/format.js");
      return [
        [p("0,25"), p("0.25"), p("\u22120,5"), p("1,5/2"), p("1,5,6")],
        [s("0; 0; 1,5; 2"), s("0, 0, 1.5, 2"), s("(1,5; 2)", "()")],
      ];
    });
    equal(JSON.stringify(parsed[0]), "[0.25,0.25,-0.5,0.75,null]", "numbers (NaN → null)");
    equal(
      JSON.stringify(parsed[1]),
      '[["0","0","1,5","2"],["0","0","1.5","2"],["1,5","2"]]',
      "lists",
    );
    const box = page.locator('[data-control="u"] .sl-value');
    await box.fill("1,5");
    await box.press("Enter");
    await settle(page);
    const linked = async () =>
      page.evaluate(async () => {
        const { parseHash, decodeState } = await import("./lib/state.js");
        return decodeState(parseHash(location.hash).s);
      });
    equal((await linked()).u, 1.5, "u typed with a decimal comma");
    const knots = page.locator('[data-control="knots"] input');
    await knots.fill("0; 0; 0; 0; 0,5; 2; 3; 4; 4; 4; 4");
    await knots.press("Enter");
    await settle(page);
    assert(/0\.5|0,5/.test(await knots.inputValue()), `knots: ${await knots.inputValue()}`);
    equal((await linked()).knots[4], 0.5, "the link holds a locale-free 0.5");
  });

  await test("the language menu reloads the page in the chosen language and keeps the demo's link", async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html#demo=de-casteljau`);
    await demoHelpers(page).ready();
    const hash = new URL(page.url()).hash;
    await page.locator(".language-menu").selectOption("it");
    await page.waitForFunction(() => document.documentElement.lang === "it");
    await demoHelpers(page).ready();
    const url = new URL(page.url());
    equal(url.searchParams.get("lang"), "it", "?lang= in the address");
    equal(url.hash, hash, "the demo and its state");
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("gallery thumbnails follow the colour scheme, also when it changes", async () => {
    // Mean brightness (0–255) of the first thumbnail's top-left 8×8 image pixels (its
    // background), once it is drawn; null before.
    const corner = () => {
      const img = document.querySelector("img.card-thumb");
      if (!img?.complete || !img.src.startsWith("data:")) return null;
      const c = document.createElement("canvas");
      c.width = c.height = 8;
      const g = c.getContext("2d");
      g.drawImage(img, 0, 0, 8, 8, 0, 0, 8, 8);
      const d = g.getImageData(0, 0, 8, 8).data;
      let sum = 0;
      for (let i = 0; i < d.length; i += 4) sum += (d[i] + d[i + 1] + d[i + 2]) / 3;
      return sum / 64;
    };
    // Polled from here: a string predicate would need eval, which the page's CSP forbids.
    const waitFor = async (test) => {
      const wanted = (v) => v !== null && (test === "> 240" ? v > 240 : v < 60);
      let value = null;
      for (const end = Date.now() + 5000; Date.now() < end; await page.waitForTimeout(50)) {
        value = await page.evaluate(corner);
        if (wanted(value)) return;
      }
      throw new Error(`thumbnail background ${value}, expected ${test}`);
    };
    try {
      await page.emulateMedia({ colorScheme: "light" });
      await page.goto("about:blank");
      await page.goto(`${base}/index.html`);
      await waitFor("> 240");
      await page.emulateMedia({ colorScheme: "dark" });
      await waitFor("< 60");
    } finally {
      await page.emulateMedia({ colorScheme: null });
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("labels of points in the frame are kept inside it (canvas and SVG)", async () => {
    const result = await page.evaluate(async () => {
      const { SvgRecorder } = await import("./lib/draw.js");
      const { LIGHT_THEME } = await import("./lib/theme.js");
      const measure = document.createElement("canvas").getContext("2d");
      const style = LIGHT_THEME.label;
      const r = new SvgRecorder({ theme: LIGHT_THEME, measureContext: measure });
      r.begin(200, 100, "#fff");
      r.text("a long label", 190, 50, style, "left"); // would run off the right edge
      r.text("top", 100, 1, style, "center", "bottom"); // would stand above the top edge
      r.text("outside", 250, 50, style, "left"); // anchor outside: left alone
      const width = r.measure("a long label", style);
      const xs = [...r.toString().matchAll(/<text x="([-\d.]+)" y="([-\d.]+)"/g)].map((m) => [
        Number(m[1]),
        Number(m[2]),
      ]);
      return { width, xs, size: style.size };
    });
    const [[x0], [, y1], [x2]] = result.xs;
    assert(
      x0 + result.width <= 200 && x0 >= 0,
      `right edge: label at ${x0}, width ${result.width}`,
    );
    assert(y1 - result.size >= 0, `top edge: baseline at ${y1}`);
    equal(x2, 250, "a label of a point outside the frame stays put");
  });

  await test("long canvas captions wrap to the frame's width (phones), short ones stay one line", async () => {
    const result = await page.evaluate(async () => {
      const { SvgRecorder, drawCaption } = await import("./lib/draw.js");
      const { LIGHT_THEME } = await import("./lib/theme.js");
      const style = LIGHT_THEME.labelSmall;
      const r = new SvgRecorder({
        theme: LIGHT_THEME,
        measureContext: document.createElement("canvas").getContext("2d"),
      });
      r.begin(200, 300, "#fff");
      const sentence =
        "Arrows: velocity P′(1) arriving and Q′(1) leaving the joint, drawn at 1/6 length";
      const lines = drawCaption(r, sentence, 10, 290, style, 180, "bottom");
      const short = drawCaption(r, "C¹ at the joint", 10, 10, style, 180, "top");
      const texts = [
        ...r.toString().matchAll(/<text x="([-\d.]+)" y="([-\d.]+)"[^>]*>([^<]*)<\/text>/g),
      ].map((m) => ({ y: Number(m[2]), text: m[3], width: r.measure(m[3], style) }));
      return { lines, short, texts, whole: r.measure(sentence, style) };
    });
    assert(result.whole > 180, `the sentence is wider than the frame (${result.whole} px)`);
    equal(result.short, 1, "a caption that fits is one line");
    assert(result.lines >= 2, `${result.lines} lines`);
    const wrapped = result.texts.slice(0, result.lines);
    assert(
      wrapped.every((l) => l.width <= 180),
      `line widths ${wrapped.map((l) => l.width.toFixed(1)).join(", ")}`,
    );
    equal(
      wrapped.map((l) => l.text).join(" "),
      "Arrows: velocity P′(1) arriving and Q′(1) leaving the joint, drawn at 1/6 length",
      "the words, in order",
    );
    equal(wrapped[wrapped.length - 1].y, 290, "the last line sits on the anchor (baseline bottom)");
    assert(
      wrapped.every((l, i) => i === 0 || l.y > wrapped[i - 1].y),
      "lines go down the frame",
    );
  });

  // The demos' suites, shared out among the workers (each its own browser): a demo's tests run
  // in order on one page, and the demos run side by side.
  const queue = [...registry];
  const workers = [main];
  for (let w = 1; w < WORKERS; w++) workers.push(await launchWorker());
  extraWorkers.push(...workers.slice(1));
  await Promise.all(
    workers.map(async (worker) => {
      for (let demo = queue.shift(); demo; demo = queue.shift()) await demoSuite(worker, demo);
    }),
  );

  await test("random states from links and files are refused with an Error or mount cleanly (every demo × 60)", async () => {
    await page.goto("about:blank");
    await page.goto(`${base}/index.html`);
    const result = await page.evaluate(fuzzStates, { seedValue: 7, rounds: 60 });
    assert(result.bad.length === 0, result.bad.join("\n"));
    assert(
      result.accepted > 100 && result.refused > 100,
      `accepted ${result.accepted}, refused ${result.refused}`,
    );
    await settle(page);
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("lecture mode draws text and strokes 1.6× larger, in the SVG export too, and toggles back", async () => {
    const h = await openDemo(page, base, "de-casteljau");
    const lecture = page.locator('[data-action="lecture"]').first();
    // The font sizes and stroke widths of the SVG export (the drawing on the screen).
    const sizes = async () => {
      const svg = readFileSync(await (await h.download("export-svg")).path(), "utf8");
      const fonts = [...svg.matchAll(/font-size="([\d.]+)"/g)].map((m) => Number(m[1]));
      const strokes = [...svg.matchAll(/stroke-width="([\d.]+)"/g)].map((m) => Number(m[1]));
      return { font: Math.max(...fonts), stroke: Math.max(...strokes) };
    };
    const normal = await sizes();
    const before = await h.snapshot();
    equal(await lecture.getAttribute("aria-pressed"), "false", "off at first");
    await lecture.click();
    equal(await lecture.getAttribute("aria-pressed"), "true", "pressed");
    assert((await h.snapshot()) !== before, "the picture changes");
    const large = await sizes();
    assert(Math.abs(large.font / normal.font - 1.6) < 1e-9, `font ${normal.font} → ${large.font}`);
    assert(
      Math.abs(large.stroke / normal.stroke - 1.6) < 1e-9,
      `stroke ${normal.stroke} → ${large.stroke}`,
    );
    await lecture.click();
    equal(await lecture.getAttribute("aria-pressed"), "false", "released");
    equal(await h.snapshot(), before, "the picture is as before");
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("a11y: Tab selects a handle and an arrow nudge is announced in the polite live region", async () => {
    const h = await openDemo(page, base, "de-casteljau");
    const canvas = h.canvas();
    equal(await canvas.getAttribute("role"), "application", "canvas role");
    equal(
      await canvas.getAttribute("aria-roledescription"),
      "interactive figure",
      "role description",
    );
    const live = page.locator(".sl-figure .sl-announcer");
    equal(await live.count(), 1, "one live region");
    equal(await live.getAttribute("aria-live"), "polite", "aria-live");
    // Tab from the top of the page until the figure has focus (keyboard focus selects P₀).
    await page.evaluate(() => document.activeElement?.blur());
    let focused = false;
    for (let k = 0; k < 40 && !focused; k++) {
      await page.keyboard.press("Tab");
      focused = await canvas.evaluate((c) => document.activeElement === c);
    }
    assert(focused, "Tab reaches the figure");
    equal(await live.textContent(), "P₀ selected, (0, 0)", "announced on selection");
    await page.keyboard.press("Tab");
    equal(await live.textContent(), "P₁ selected, (2, 2)", "Tab selects the next handle");
    // Dragging frames announce nothing; the committed nudge does, with the new coordinates.
    await page.keyboard.press("Shift+ArrowRight");
    const moved = await live.textContent();
    const [, x] = moved.match(/^P₁ moved to \((\d+(?:\.\d+)?), 2\)$/) ?? [];
    assert(Number(x) > 2, `announced after the nudge: ${moved}`);
    const state = await page.evaluate(() =>
      JSON.parse(
        atob(
          new URLSearchParams(location.hash.slice(1))
            .get("s")
            .replace(/-/g, "+")
            .replace(/_/g, "/"),
        ),
      ),
    );
    equal(Number(x), Number(state.points[1][0].toFixed(3)), "the announced x is the committed one");
    // A drag is announced once, when it ends.
    const [p0] = await h.handles();
    await page.mouse.move(p0.x, p0.y);
    await page.mouse.down();
    equal(await live.textContent(), "P₀ selected, (0, 0)", "pointer down selects");
    await page.mouse.move(p0.x + 20, p0.y);
    await settle(page);
    equal(await live.textContent(), "P₀ selected, (0, 0)", "nothing said while dragging");
    await page.mouse.up();
    assert(
      /^P₀ moved to \(\d/.test(await live.textContent()),
      `after the drag: ${await live.textContent()}`,
    );
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("a11y: the knot ruler announces a selected knot and a committed nudge", async () => {
    const h = await openDemo(page, base, "bspline-basis");
    const canvas = h.canvas();
    const live = page.locator(".sl-figure .sl-announcer");
    await page.evaluate(() => document.activeElement?.blur());
    let focused = false;
    for (let k = 0; k < 60 && !focused; k++) {
      await page.keyboard.press("Tab");
      focused = await canvas.evaluate((c) => document.activeElement === c);
    }
    assert(focused, "Tab reaches the figure");
    // End selects the last control point; Tab from it walks on into the knots.
    await page.keyboard.press("End");
    equal(await live.textContent(), "P₅ selected, (8, 0)", "the last control point");
    await page.keyboard.press("Tab");
    equal(await live.textContent(), "knot u₀ selected, 0", "Tab enters the knots");
    for (let k = 0; k < 3; k++) await page.keyboard.press("Tab");
    equal(await live.textContent(), "knot u₃ selected, 1", "Tab walks the knots");
    await page.keyboard.press("Shift+ArrowRight");
    const moved = await live.textContent();
    const [, u] = moved.match(/^knot u₃ moved to (\d+(?:\.\d+)?)$/) ?? [];
    assert(Number(u) > 1 && Number(u) <= 2, `announced after the nudge: ${moved}`);
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("embed example: two independent demos in shadow roots", async () => {
    await page.goto(`${base}/embed-example.html`);
    const a = demoHelpers(page, "spline-lab#worked ");
    const b = demoHelpers(page, "spline-lab#quadratic ");
    await page.locator("spline-lab#worked").scrollIntoViewIfNeeded();
    await a.ready();
    await page.locator("spline-lab#quadratic").scrollIntoViewIfNeeded();
    await b.ready();
    const shadow = await page.evaluate(() =>
      [...document.querySelectorAll("spline-lab")].map(
        (e) => !!e.shadowRoot?.querySelector("canvas"),
      ),
    );
    equal(JSON.stringify(shadow), "[true,true]", "both rendered in shadow roots");
    equal((await a.handles()).length, 4, "worked example points");
    equal((await b.handles()).length, 3, "quadratic points");
    const cell = await page
      .locator('spline-lab#worked td[data-level="3"][data-index="0"]')
      .textContent();
    assert(cell.includes("29/16, 23/16"), `worked example cell: ${cell}`);
    const caption = await page.locator("spline-lab#quadratic .sl-table-title").textContent();
    assert(caption.includes("1/2"), `quadratic caption: ${caption}`);
    // Dragging in one leaves the other alone.
    const otherBefore = await a.snapshot();
    const [p0] = await b.handles();
    const before = await b.snapshot();
    await b.drag(p0, 20, -20);
    assert((await b.snapshot()) !== before, "second embed reacts to a drag");
    equal(await a.snapshot(), otherBefore, "first embed unchanged");
    const loads = await page.evaluate(
      () => performance.getEntriesByType("resource").filter((r) => r.name.endsWith(".wasm")).length,
    );
    equal(loads, 1, "wasm fetched once per page");
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("on a phone-width canvas, derivatives and projective leave out the labels their tables repeat", async () => {
    // The SVG export draws what the canvas shows, at its size.
    const labels = async (id, pattern) => {
      const h = await openDemo(page, base, id);
      const svg = readFileSync(await (await h.download("export-svg")).path(), "utf8");
      return [...svg.matchAll(/<text[^>]*>([^<]*)<\/text>/g)].filter((m) => pattern.test(m[1]))
        .length;
    };
    const cases = [
      ["derivatives", /^3\(P/],
      ["projective", /^w′/],
    ];
    const desktop = [];
    for (const [id, pattern] of cases) desktop.push(await labels(id, pattern));
    await page.setViewportSize({ width: 390, height: 844 });
    try {
      for (const [k, [id, pattern]] of cases.entries()) {
        assert(desktop[k] >= 3, `${id}: ${desktop[k]} labels at 1280 px`);
        equal(await labels(id, pattern), 0, `${id}: labels at 390 px`);
      }
    } finally {
      await page.setViewportSize(VIEWPORT);
    }
    const problems = errors.take();
    assert(problems.length === 0, problems.join("\n"));
  });

  await test("at 2 device px per CSS px (device emulation, as DevTools and Lighthouse do it) a 2D and a 3D figure draw 2 canvas px per CSS px", async () => {
    // Chromium's emulation reports ResizeObserver's device-pixel box in CSS px: canvas-size.js
    // must not trust it then (the figures were drawn at half resolution and scaled up).
    const sharp = await context.newPage();
    const sharpErrors = watchErrors(sharp);
    const cdp = await context.newCDPSession(sharp);
    try {
      await cdp.send("Emulation.setDeviceMetricsOverride", {
        width: 412,
        height: 823,
        deviceScaleFactor: 2,
        mobile: true,
      });
      for (const id of ["de-casteljau", "bezier-patch"]) {
        await sharp.goto("about:blank");
        await sharp.goto(`${base}/index.html#demo=${id}`);
        const h = demoHelpers(sharp);
        await h.ready();
        const size = await h.canvas().evaluate((c) => ({
          w: c.width,
          h: c.height,
          cw: c.getBoundingClientRect().width,
          ch: c.getBoundingClientRect().height,
          ratio: devicePixelRatio,
        }));
        equal(size.ratio, 2, `${id}: devicePixelRatio`);
        assert(
          Math.abs(size.w - 2 * size.cw) <= 2 && Math.abs(size.h - 2 * size.ch) <= 2,
          `${id}: a backing store of ${size.w} × ${size.h} for ${size.cw} × ${size.ch} CSS px`,
        );
      }
      const problems = sharpErrors.take();
      assert(problems.length === 0, problems.join("\n"));
    } finally {
      await cdp.detach().catch(() => {});
      await sharp.close();
    }
  });

  await test("a browser without WebAssembly SIMD is told so, on the page and in embeds", async () => {
    // The package is built with SIMD128; an old browser's WebAssembly.validate refuses the probe.
    const old = await context.newPage();
    const oldErrors = watchErrors(old);
    try {
      await old.addInitScript(() => {
        WebAssembly.validate = () => false;
      });
      const noSimd = /needs WebAssembly SIMD \(Chrome or Edge 91, Firefox 89, Safari 16\.4/;
      await old.goto(`${base}/index.html#demo=de-casteljau`);
      await old.waitForFunction(
        () => document.querySelector(".app-status")?.dataset.kind === "error",
      );
      const status = await old.locator(".app-status").textContent();
      assert(noSimd.test(status), `app status: ${status}`);
      assert(
        !status.includes("make build"),
        `no build advice for a browser that is too old: ${status}`,
      );
      await old.goto(`${base}/embed-example.html`);
      await old.locator("spline-lab#worked .sl-embed-error").waitFor();
      const embedText = await old.locator("spline-lab#worked .sl-embed-error").textContent();
      assert(noSimd.test(embedText), `embed: ${embedText}`);
      const wasmLoads = await old.evaluate(
        () =>
          performance.getEntriesByType("resource").filter((r) => r.name.endsWith(".wasm")).length,
      );
      equal(wasmLoads, 0, "the wasm is not fetched");
      const problems = oldErrors.take().filter((p) => !p.includes("Failed to load resource"));
      assert(problems.length === 0, problems.join("\n"));
    } finally {
      await old.close();
    }
  });

  // axe-core on every page (gallery, demos, lectures, exercises, embed example, one Greek page).
  await axeSuite({ test, assert, context, base, registry, demoHelpers, settle });

  // The built site (make dist), served as a host would: on one more page of this browser.
  await distSuite({ test, assert, equal, context, watchErrors, demoHelpers, settle });
  // The built site offline: its service worker, precache and update (its own build and origin).
  await offlineSuite({ test, assert, equal, context, watchErrors, demoHelpers, settle });
} catch (err) {
  failed += 1;
  console.log(`FAIL runner: ${err.stack ?? err}`);
} finally {
  await Promise.all([main, ...extraWorkers].map(closeWorker));
  server.close();
}

console.log(`e2e: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
