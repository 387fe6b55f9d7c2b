// The built site (`make dist`, scripts/dist.mjs) in the browser, once per `make test`: builds
// dist/site/ from the fresh www/, serves it with scripts/serve.mjs as `make serve-dist` does,
// and opens the gallery, a 2D demo, a 3D demo, a lecture (Greek: a locale chunk and the
// lectures' lookup table) and the embed example on one extra page of the run's browser, with
// no console error, no CSP violation and a drawn canvas; then checks what went over the wire:
// every file compressed (br or gzip) and cached as its name says (hashed: a year, immutable;
// HTML and embed.js: no-cache), and nothing fetched under an unhashed name but the entry points.
import { request } from "node:http";
import { existsSync, readFileSync } from "node:fs";
import { extname, join, relative } from "node:path";
import { brotliDecompressSync, gunzipSync } from "node:zlib";
import { ASSETS, COMPRESSED, SITE, WWW, buildSite, listFiles } from "../../scripts/dist.mjs";
import { HASHED, IMMUTABLE, startServer } from "../../scripts/serve.mjs";
import { POSTERS } from "../../scripts/posters.mjs";

/** `make dist` must stay well under a minute (it takes ~5 s on 2 cores). */
const DIST_BUDGET_MS = 45_000;
/** The names the site keeps unhashed (its entry points, the 3D figures' rendering worker, the
 * licences, and the offline worker, web app manifest and icons: scripts/service-worker.mjs). */
const STABLE =
  /^(?:[^/]+\.html|embed\.js|gl-worker\.js|licenses\/[^/]+\.txt|sw\.js|manifest\.webmanifest|icons\/[^/]+\.(?:png|svg))$/;

/** An init script: the offline worker is not registered (tests/e2e/offline.mjs tests it), so
 * the pages measure what goes over the wire, as a first visit sees it. */
function noOfflineWorker() {
  if (window.ServiceWorkerContainer)
    ServiceWorkerContainer.prototype.register = () => new Promise(() => {});
}

/** Distinct colours in a canvas (2D; the 3D figures copy their render into one too). */
function distinctColours(canvas) {
  const { width, height } = canvas;
  const data = canvas.getContext("2d").getImageData(0, 0, width, height).data;
  const seen = new Set();
  for (let i = 0; i < data.length && seen.size < 1000; i += 4 * 7)
    seen.add((data[i] << 24) | (data[i + 1] << 16) | (data[i + 2] << 8) | data[i + 3]);
  return seen.size;
}

/** A raw GET (no decoding) with Accept-Encoding `encoding` (and `headers`): { status, headers,
 * body }. */
function rawGet(url, encoding, headers = {}) {
  return new Promise((ok, fail) => {
    request(url, { headers: { "accept-encoding": encoding, ...headers } }, (res) => {
      const parts = [];
      res.on("data", (part) => parts.push(part));
      res.on("end", () =>
        ok({ status: res.statusCode, headers: res.headers, body: Buffer.concat(parts) }),
      );
      res.on("error", fail);
    })
      .on("error", fail)
      .end();
  });
}

/**
 * Registers the dist tests with run.mjs's `test` (which skips a body when the filter does not
 * match). `tools`: { test, assert, equal, context, watchErrors, demoHelpers, settle }.
 */
export async function distSuite({
  test,
  assert,
  equal,
  context,
  watchErrors,
  demoHelpers,
  settle,
}) {
  let server = null;
  let page = null;
  let errors = null;
  let base = "";
  /** Every response from the dist server: { path, status, headers }. */
  const responses = [];
  const needSite = () => assert(page, "the site was not built (see the first dist test)");

  /** A page of its own beside the suite's, with the offline worker unregistered like it: a
   * worker registered by one page would serve every later page of the context. */
  async function ownPage() {
    const own = await context.newPage();
    await own.addInitScript(noOfflineWorker);
    return own;
  }

  /**
   * Holds back every wasm request of `target` (the shared page by default; the posters stay up)
   * until the returned function is awaited, which lets them through and removes the route.
   */
  async function holdWasm(target = page) {
    let release = () => {};
    const held = new Promise((resolve) => {
      release = resolve;
    });
    const hold = async (route) => {
      await held;
      await route.continue().catch(() => {}); // a page left meanwhile
    };
    await target.route("**/*.wasm", hold);
    return async () => {
      release();
      await target.unroute("**/*.wasm", hold);
    };
  }

  /** Waits for a figure, then asserts a drawn canvas, no console error and no CSP violation. */
  async function checkPage(what, h) {
    await h.ready();
    await settle(page);
    const colours = await h.canvas().evaluate(distinctColours);
    assert(colours >= 4, `${what}: the canvas has ${colours} colours (not drawn)`);
    const problems = errors.take();
    const violations = await page.evaluate(() => window.__violations);
    assert(problems.length + violations.length === 0, [...problems, ...violations].join("\n"));
  }

  try {
    await test("dist: make dist builds the site: hashed names, and a .gz and .br that decompress to each text file", async () => {
      const { elapsed } = await buildSite();
      assert(elapsed < DIST_BUDGET_MS, `make dist took ${elapsed} ms`);
      const files = (await listFiles(SITE)).map((f) => relative(SITE, f).split("\\").join("/"));
      const plain = files.filter((f) => !/\.(gz|br)$/.test(f));
      const stray = plain.filter((f) => !HASHED.test(f) && !STABLE.test(f));
      assert(stray.length === 0, `neither hashed nor an entry point: ${stray.join(", ")}`);
      for (const page of ["index.html", "embed-example.html", "embed.js"])
        assert(plain.includes(page), `${page} is in the site`);
      for (const kind of [".wasm", ".css", ".js", ".json", ".woff2"])
        assert(
          plain.some((f) => f.startsWith(`${ASSETS}/`) && f.endsWith(kind)),
          `a hashed ${kind} file in ${ASSETS}/`,
        );
      let compressed = 0;
      for (const file of plain.filter((f) => COMPRESSED.has(extname(f)))) {
        const body = readFileSync(join(SITE, file));
        assert(
          gunzipSync(readFileSync(join(SITE, `${file}.gz`))).equals(body),
          `${file}.gz decompresses to ${file}`,
        );
        assert(
          brotliDecompressSync(readFileSync(join(SITE, `${file}.br`))).equals(body),
          `${file}.br decompresses to ${file}`,
        );
        compressed += 1;
      }
      assert(compressed > 20, `${compressed} files with .gz and .br`);

      server = await startServer(0, "127.0.0.1", SITE);
      base = `http://127.0.0.1:${server.address().port}`;
      page = await context.newPage();
      errors = watchErrors(page);
      page.on("response", (response) => {
        const url = new URL(response.url());
        if (url.origin === base)
          responses.push({
            path: url.pathname.slice(1),
            status: response.status(),
            headers: response.headers(),
          });
      });
      // Every violation of the pages' CSP is recorded (a bundle must not need an inline script).
      await page.addInitScript(noOfflineWorker);
      await page.addInitScript(() => {
        window.__violations = [];
        document.addEventListener("securitypolicyviolation", (e) =>
          window.__violations.push(`CSP: ${e.violatedDirective} ${e.blockedURI}`),
        );
      });
    });

    await test("dist: the gallery draws its thumbnails and opens a 2D demo", async () => {
      needSite();
      const from = responses.length;
      await page.goto(`${base}/index.html`);
      if (existsSync(POSTERS)) {
        // With posters (scripts/posters.mjs, run by make dist): static thumbnails, and neither
        // the wasm nor KaTeX before a demo is opened (issue 26).
        await page
          .locator("a.card img.card-thumb:not(.placeholder)[src$='.svg']")
          .first()
          .waitFor();
        await page.waitForLoadState("networkidle");
        const heavy = responses
          .slice(from)
          .map((r) => r.path)
          .filter((p) => /\.wasm$|katex|splinelab-/i.test(p));
        assert(heavy.length === 0, `the gallery fetched ${heavy.join(", ")}`);
      } else await page.locator("a.card img[src^='data:image/png']").first().waitFor();
      await page.locator('a.card[data-demo="de-casteljau"]').click();
      await checkPage("de-casteljau from the gallery", demoHelpers(page));
    });

    await test("dist: a 2D demo, two 3D demos and a Greek lecture open from their links", async () => {
      needSite();
      for (const [what, hash] of [
        ["de-boor", "index.html#demo=de-boor"],
        ["bezier-patch (3D)", "index.html#demo=bezier-patch"],
        // The core tells a curve argument's class by name: the minified glue must keep it.
        [
          "surface-revolution (3D, a curve passed to the core)",
          "index.html#demo=surface-revolution",
        ],
        ["lecture", "index.html?lang=el#lecture=bezier-curves&scene=2"],
      ]) {
        await page.goto("about:blank");
        await page.goto(`${base}/${hash}`);
        await checkPage(what, demoHelpers(page));
      }
      // The 3D figures were drawn by the rendering worker: its stable entry and hashed module.
      const worker = responses.filter((r) => /^(?:gl-worker\.js|assets\/gl-worker-)/.test(r.path));
      const seen = new Set(
        worker.map((r) => `${r.path.replace(/-[A-Z2-7]{8}\./, "-*.")} ${r.status}`),
      );
      equal(
        [...seen].sort().join(", "),
        "assets/gl-worker-*.js 200, gl-worker.js 200",
        "the rendering worker's requests",
      );
      equal(
        await page.evaluate(() => document.documentElement.lang),
        "el",
        "the lecture's language",
      );
    });

    // Posters come with `make dist` (scripts/posters.mjs, ~3.5 min of Chromium), not with
    // `make test`: this runs where they were drawn.
    if (existsSync(POSTERS))
      await test("dist: a demo link and a lecture link show their poster (the lecture its caption) before the wasm arrives", async () => {
        needSite();
        const caption = JSON.parse(
          readFileSync(join(WWW, "lectures", "bezier-curves.json"), "utf8"),
        ).scenes[0].caption.en;
        const releaseWasm = await holdWasm();
        try {
          for (const [what, hash] of [
            ["de-casteljau", "index.html#demo=de-casteljau"],
            ["lecture", "index.html#lecture=bezier-curves"],
          ]) {
            await page.goto("about:blank");
            await page.goto(`${base}/${hash}`);
            await page.waitForFunction(() =>
              [...document.querySelectorAll("img.sl-poster")].some(
                (img) => img.complete && img.naturalWidth > 0 && img.src.endsWith(".svg"),
              ),
            );
            equal(await page.locator(".sl-canvas").count(), 0, `${what}: a live figure`);
          }
          equal(
            (await page.locator(".lecture-caption").textContent()).trim(),
            caption,
            "the lecture's caption beside its poster",
          );
          const [figure, below] = await page.evaluate(() => [
            document.querySelector(".sl-figure").getBoundingClientRect().bottom,
            document.querySelector(".lecture-caption").getBoundingClientRect().top,
          ]);
          assert(below >= figure, `the caption (top ${below}) under the figure (bottom ${figure})`);
        } finally {
          await releaseWasm();
        }
        await checkPage("the lecture after its poster", demoHelpers(page));
        equal(await page.locator(".sl-poster").count(), 0, "posters left after the mount");
        equal(
          (await page.locator(".lecture-caption").textContent()).trim(),
          caption,
          "the caption",
        );
      });

    if (existsSync(POSTERS))
      await test("dist: behind a demo's or a lecture's poster the shell's fonts are warmed in a hidden frame, gone before the mount", async () => {
        needSite();
        const own = await ownPage();
        const ownErrors = watchErrors(own);
        let releaseWasm = async () => {};
        try {
          // What the page did, in order: the warm-up frame (lib/font-warmup.js) and the samples
          // laid out in it, its removal, the live figure.
          await own.addInitScript(() => {
            window.__warm = [];
            const note = (step) => window.__warm.at(-1) !== step && window.__warm.push(step);
            new MutationObserver((records) => {
              for (const r of records) {
                for (const node of r.addedNodes) {
                  if (node.classList?.contains("sl-font-warmup"))
                    note(`frame${node.classList.contains("sl-lecture") ? " (lecture type)" : ""}`);
                  else if (r.target.classList?.contains("sl-font-warmup")) note("sample");
                  else if (
                    node.querySelector?.(".sl-canvas") ||
                    node.classList?.contains("sl-canvas")
                  )
                    note("figure");
                }
                for (const node of r.removedNodes)
                  if (node.classList?.contains("sl-font-warmup")) note("removed");
              }
            }).observe(document, { subtree: true, childList: true });
          });
          for (const [what, hash, frame] of [
            ["de-casteljau", "index.html#demo=de-casteljau", "frame"],
            // A lecture in a window ≥ 900 px wide has lecture mode's type (the tests' is wider).
            ["the lecture", "index.html#lecture=bezier-curves", "frame (lecture type)"],
          ]) {
            releaseWasm = await holdWasm(own);
            await own.goto("about:blank"); // a new document, not a hash change
            await own.goto(`${base}/${hash}`);
            // The samples come while the wasm is held.
            await own.waitForFunction(() => window.__warm.includes("removed"));
            equal(
              (await own.evaluate(() => window.__warm)).join(" → "),
              `${frame} → sample → removed`,
              `${what}: before the wasm`,
            );
            const samples = await own.evaluate(() => window.__warm.length);
            await releaseWasm();
            releaseWasm = async () => {};
            await demoHelpers(own).ready();
            const steps = await own.evaluate(() => window.__warm);
            equal(steps.slice(samples).join(" → "), "figure", `${what}: after the wasm`);
            equal(await own.locator(".sl-font-warmup").count(), 0, `${what}: a frame left`);
          }
          equal(ownErrors.take().join("\n"), "", "console errors");
        } finally {
          await releaseWasm();
          await own.close();
        }
      });

    if (existsSync(POSTERS))
      await test("dist: a demo link and a lecture link ask for the wasm (and the demo's module) only after the browser has reported the poster's paint (the largest contentful paint)", async () => {
        needSite();
        const own = await ownPage();
        const ownErrors = watchErrors(own);
        try {
          await own.addInitScript(() => {
            window.__lcp = [];
            new PerformanceObserver((list) => {
              for (const e of list.getEntries()) window.__lcp.push({ url: e.url, at: e.startTime });
            }).observe({ type: "largest-contentful-paint", buffered: true });
          });
          // A race (the poster's paint reported a frame late): each link is loaded a few times.
          for (const hash of ["index.html#demo=de-casteljau", "index.html#lecture=bezier-curves"]) {
            for (let load = 1; load <= 4; load++) {
              await own.goto("about:blank"); // a new document, not a hash change
              await own.goto(`${base}/${hash}`);
              await demoHelpers(own).ready();
              const { poster, requests } = await own.evaluate(() => ({
                poster: window.__lcp.find((e) => e.url.endsWith(".svg"))?.at,
                requests: performance
                  .getEntriesByType("resource")
                  .filter((e) => /\.wasm$|\/de-casteljau-[A-Z2-7]{8}\.js$/.test(e.name))
                  .map((e) => [e.name.split("/").pop(), e.startTime]),
              }));
              assert(poster !== undefined, `${hash}: the poster was no largest paint`);
              assert(
                requests.some(([name]) => name.endsWith(".wasm")),
                `${hash}: no wasm request in ${JSON.stringify(requests)}`,
              );
              for (const [name, at] of requests)
                assert(
                  at >= poster,
                  `${hash}, load ${load}: ${name} asked for at ${at} ms, the poster's paint at ${poster} ms`,
                );
            }
          }
          equal(ownErrors.take().join("\n"), "", "console errors");
        } finally {
          await own.close();
        }
      });

    await test("dist: a demo link registers the offline worker only once its figure is shown (the precache does not share the link with the wasm)", async () => {
      needSite();
      const own = await ownPage(); // its register() never settles; this one records the call
      let releaseWasm = async () => {};
      try {
        await own.addInitScript(() => {
          const hold = ServiceWorkerContainer.prototype.register;
          ServiceWorkerContainer.prototype.register = function (...args) {
            window.__registered = { figure: document.querySelector(".sl-canvas") !== null };
            return hold.apply(this, args);
          };
        });
        releaseWasm = await holdWasm(own);
        await own.goto(`${base}/index.html#demo=de-casteljau`);
        await own.waitForFunction(() => document.readyState === "complete");
        await own.waitForTimeout(1000);
        equal(await own.evaluate(() => window.__registered ?? null), null, "registered, wasm held");
        await releaseWasm();
        releaseWasm = async () => {};
        await demoHelpers(own).ready();
        await own.waitForFunction(() => window.__registered);
        equal(
          JSON.stringify(await own.evaluate(() => window.__registered)),
          '{"figure":true}',
          "registered once the figure was there",
        );
      } finally {
        await releaseWasm();
        await own.close();
      }
    });

    if (existsSync(POSTERS))
      await test("dist: a 3D demo keeps its poster over the figure until the rendering worker's first frame, then shows the figure alone", async () => {
        needSite();
        const own = await ownPage();
        const ownErrors = watchErrors(own);
        try {
          // Each change of (canvas drawn, poster over it) in the figure box, from the mount on.
          await own.addInitScript(() => {
            window.__cover = [];
            new MutationObserver(() => {
              const box = document.querySelector(".sl-figure:has(> .sl-canvas)");
              if (!box) return;
              const step = [
                box.hasAttribute("data-handles") ? "drawn" : "empty",
                box.querySelector(":scope > img.sl-poster-cover") ? "poster" : "no poster",
              ].join(", ");
              if (window.__cover.at(-1) !== step) window.__cover.push(step);
            }).observe(document, { subtree: true, childList: true, attributes: true });
          });
          await own.goto(`${base}/index.html#demo=bezier-patch`);
          await demoHelpers(own).ready();
          await settle(own);
          equal(
            (await own.evaluate(() => window.__cover)).join(" → "),
            "empty, poster → drawn, poster → drawn, no poster",
            "the figure box from the mount to the first frame",
          );
          const cover = await own.evaluate(() => document.querySelectorAll("img.sl-poster").length);
          equal(cover, 0, "posters left after the first frame");
          // Its handles came a task after the figure (lib/demo.js): a keyboard nudge moves one
          // and the link follows.
          const h = demoHelpers(own);
          const start = (await h.handles())[0];
          const link = own.url();
          await h.canvas().focus();
          await own.keyboard.press("Home");
          await own.keyboard.press("ArrowRight");
          const moved = (await h.handles())[0];
          assert(
            Math.hypot(moved.x - start.x, moved.y - start.y) > 0.5,
            `handle nudged to ${JSON.stringify(moved)} from ${JSON.stringify(start)}`,
          );
          assert(own.url() !== link, "the link follows the nudge");
          equal(ownErrors.take().join("\n"), "", "console errors");
        } finally {
          await own.close();
        }
      });

    if (existsSync(POSTERS))
      await test("dist: a link to another state than the default shows no poster, a copied link of the default state does (2D and 3D)", async () => {
        needSite();
        const own = await ownPage();
        const ownErrors = watchErrors(own);
        const linkState = () => new URLSearchParams(new URL(own.url()).hash.slice(1)).get("s");
        const decode = (s) => JSON.parse(Buffer.from(s, "base64url").toString("utf8"));
        try {
          // Whether a poster was in the page at any moment of this load.
          await own.addInitScript(() => {
            window.__poster = false;
            new MutationObserver(() => {
              window.__poster ||= document.querySelector("img.sl-poster") !== null;
            }).observe(document, { subtree: true, childList: true });
          });
          const open = async (hash) => {
            await own.goto("about:blank");
            await own.goto(`${base}/index.html#${hash}`);
            await demoHelpers(own).ready();
            return own.evaluate(() => window.__poster);
          };
          for (const [id, field, value] of [
            ["de-casteljau", "t", 0.75],
            ["bezier-patch", "u", 0.5],
          ]) {
            equal(await open(`demo=${id}`), true, `${id}: the plain link's poster`);
            // The link the page writes for its default state, as a reader would copy it.
            const copied = linkState();
            const state = decode(copied);
            assert(state[field] !== value, `${id}: the default ${field} is not ${value}`);
            const other = Buffer.from(JSON.stringify({ ...state, [field]: value })).toString(
              "base64url",
            );
            equal(await open(`demo=${id}&s=${copied}`), true, `${id}: the copied link's poster`);
            equal(await open(`demo=${id}&s=${other}`), false, `${id}: another state's poster`);
            equal(decode(linkState())[field], value, `${id}: the state the link asked for`);
          }
          equal(ownErrors.take().join("\n"), "", "console errors");
        } finally {
          await own.close();
        }
      });

    if (existsSync(POSTERS))
      await test("dist: a reader with a dark colour scheme gets the dark posters (gallery thumbnails, a demo link)", async () => {
        needSite();
        const releaseWasm = await holdWasm(); // the posters stay
        await page.emulateMedia({ colorScheme: "dark" });
        try {
          await page.goto("about:blank");
          await page.goto(`${base}/index.html`);
          const thumbs = await page.evaluate(() =>
            [...document.querySelectorAll("img.card-thumb")].map((img) => img.getAttribute("src")),
          );
          assert(thumbs.length > 0, "gallery thumbnails");
          const light = thumbs.filter((src) => !/-thumb-dark-[A-Z2-7]{8}\.svg$/.test(src));
          equal(light.length, 0, `thumbnails not dark: ${light.slice(0, 3).join(", ")}`);
          // The reader switches to a light scheme: the thumbnails follow.
          await page.emulateMedia({ colorScheme: "light" });
          await page.waitForFunction(() =>
            [...document.querySelectorAll("img.card-thumb")].every(
              (img) => !img.getAttribute("src").includes("-thumb-dark-"),
            ),
          );
          await page.emulateMedia({ colorScheme: "dark" });
          await page.goto("about:blank");
          await page.goto(`${base}/index.html#demo=de-casteljau`);
          await page.waitForFunction(() =>
            [...document.querySelectorAll("img.sl-poster")].some(
              (img) => img.complete && img.naturalWidth > 0,
            ),
          );
          const poster = await page.evaluate(() => document.querySelector("img.sl-poster").src);
          assert(/-(wide|narrow)-dark-[A-Z2-7]{8}\.svg$/.test(poster), `the poster ${poster}`);
        } finally {
          await releaseWasm();
          await page.emulateMedia({ colorScheme: "light" });
        }
      });

    await test("dist: the embed example draws both <spline-lab> figures", async () => {
      needSite();
      await page.goto("about:blank");
      await page.goto(`${base}/embed-example.html`);
      for (const id of ["worked", "quadratic"]) {
        await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
        await checkPage(`embed #${id}`, demoHelpers(page, `spline-lab#${id} `));
      }
    });

    await test("dist: what the pages fetched was compressed and cached as its name says", async () => {
      needSite();
      const seen = responses.filter((r) => r.status === 200);
      assert(seen.length > 20, `${seen.length} responses`);
      const problems = [];
      for (const { path, headers } of seen) {
        const name = path === "" ? "index.html" : path;
        if (!HASHED.test(name) && !STABLE.test(name))
          problems.push(`${name}: fetched by an unhashed name`);
        const cache = HASHED.test(name) ? IMMUTABLE : "no-cache";
        if (headers["cache-control"] !== cache)
          problems.push(`${name}: cache-control ${headers["cache-control"]}`);
        if (COMPRESSED.has(extname(name)) && !["br", "gzip"].includes(headers["content-encoding"]))
          problems.push(`${name}: content-encoding ${headers["content-encoding"]}`);
      }
      for (const kind of [".wasm", ".js", ".css", ".json", ".woff2", ".html"])
        if (!seen.some((r) => r.path.endsWith(kind))) problems.push(`no ${kind} was fetched`);
      const wasm = seen.find((r) => r.path.endsWith(".wasm"));
      if (wasm?.headers["content-type"] !== "application/wasm")
        problems.push(`wasm content-type ${wasm?.headers["content-type"]}`);
      assert(problems.length === 0, problems.join("\n"));

      // Each encoding on request, precompressed from the files beside it.
      for (const [encoding, decode, ext] of [
        ["br", brotliDecompressSync, "br"],
        ["gzip", gunzipSync, "gz"],
      ]) {
        for (const path of [wasm.path, "index.html", "embed.js"]) {
          const got = await rawGet(`${base}/${path}`, encoding);
          equal(got.headers["content-encoding"], encoding, `${path} asked for ${encoding}`);
          assert(
            got.body.equals(readFileSync(join(SITE, `${path}.${ext}`))),
            `${path}: the .${ext} file`,
          );
          assert(decode(got.body).equals(readFileSync(join(SITE, path))), `${path}: decodes`);
        }
      }
      const identity = await rawGet(`${base}/index.html`, "identity");
      equal(identity.headers["content-encoding"], undefined, "no encoding when none is accepted");
    });
    await test("serve: www/ goes out compressed on the fly, no-cache, and 304 when unchanged", async () => {
      const dev = await startServer(0, "127.0.0.1", WWW);
      try {
        const at = `http://127.0.0.1:${dev.address().port}`;
        for (const [path, accept, encoding, decode] of [
          ["pkg/splinelab_bg.wasm", "gzip, deflate, br", "br", brotliDecompressSync],
          ["lib/shell.css", "br;q=0, gzip", "gzip", gunzipSync],
          ["app.js", "identity", undefined, (b) => b],
        ]) {
          const got = await rawGet(`${at}/${path}`, accept);
          equal(got.status, 200, `${path}: status`);
          equal(got.headers["content-encoding"], encoding, `${path} for ${accept}`);
          equal(got.headers["cache-control"], "no-cache", `${path}: cache-control`);
          assert(
            decode(got.body).equals(readFileSync(join(WWW, path))),
            `${path}: decodes to the file`,
          );
          const again = await rawGet(`${at}/${path}`, accept, {
            "if-none-match": got.headers.etag,
          });
          equal(again.status, 304, `${path}: revalidated`);
        }
        const font = await rawGet(`${at}/vendor/katex/fonts/KaTeX_Main-Regular.woff2`, "br");
        equal(font.headers["content-encoding"], undefined, "a woff2 is sent as it is");
        equal((await rawGet(`${at}/..%2fCargo.toml`, "br")).status, 404, "nothing outside www/");
      } finally {
        dev.close();
      }
    });
  } finally {
    await page?.close();
    server?.close();
  }
}
