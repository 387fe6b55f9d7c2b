// The built site offline (issue 26; the worker is www/sw.js, filled in by
// scripts/service-worker.mjs). Builds the site into a folder of its own (scripts/dist.mjs, as
// `make dist` does), serves it with scripts/serve.mjs on one extra page of the run's browser
// (its own origin, so its worker touches no other suite), and:
// 1. loads a demo once, waits until the worker is activated (its install = the whole precache),
//    checks that Chromium finds the site installable (manifest, icons: Page.getInstallability-
//    Errors) and that the cache holds every HTML page, embed.js, the manifest and icons, and
//    every hashed file of the site but the KaTeX fallback fonts (listed from disk, not taken
//    from the worker);
// 2. takes the network away twice over (the context's offline mode, and the server closed),
//    reloads, and uses a 2D demo (drags a handle: the canvas changes), a 3D demo and a Greek
//    lecture, with a drawn canvas, no console error, no CSP violation, no failed request;
// 3. deploys a rebuild with a changed stylesheet (new hashed names, the old one gone from the
//    host): the update check installs version 2 beside version 1; the open page, reloaded, is
//    still wholly version 1 (its old stylesheet, from the cache); once it is closed version 2
//    takes over, the next page is wholly version 2 and version 1's cache is deleted;
// 4. serves www/ (`make serve`) on the same origin: the first page still comes from the built
//    site's cache, but www/sw.js (the pass-through) replaces that worker, deletes its cache and
//    unregisters; the reloaded page is www/'s own, with no worker;
// 5. a host sending an index.html other than the build's beside its sw.js: the install fails
//    and stores nothing; with the right page it succeeds.
import { cp, mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join, relative } from "node:path";
import { WWW, buildSite, listFiles } from "../../scripts/dist.mjs";
import { startServer } from "../../scripts/serve.mjs";

/** Distinct colours in a canvas (2D; the 3D figures copy their render into one too). */
function distinctColours(canvas) {
  const { width, height } = canvas;
  const data = canvas.getContext("2d").getImageData(0, 0, width, height).data;
  const seen = new Set();
  for (let i = 0; i < data.length && seen.size < 1000; i += 4 * 7)
    seen.add((data[i] << 24) | (data[i + 1] << 16) | (data[i + 2] << 8) | data[i + 3]);
  return seen.size;
}

/** The version a built sw.js carries (its BUILD line). */
async function builtVersion(site) {
  const source = await readFile(join(site, "sw.js"), "utf8");
  const m = source.match(/^const BUILD = (\{.*\});$/m);
  if (!m) throw new Error("sw.js has no filled-in BUILD line");
  return JSON.parse(m[1]).version;
}

/** Closes `server` and every connection it holds (the browser's keep-alive ones too). */
function stop(server) {
  return new Promise((done) => {
    server.close(() => done());
    server.closeAllConnections();
  });
}

/** The state of this origin's worker and caches, as the page sees them. */
function workerState(page) {
  return page.evaluate(async () => {
    const reg = await navigator.serviceWorker.getRegistration();
    return {
      active: reg?.active?.state ?? null,
      waiting: reg?.waiting?.state ?? null,
      installing: reg?.installing?.state ?? null,
      controlled: Boolean(navigator.serviceWorker.controller),
      caches: (await caches.keys()).filter((k) => k.startsWith("splinelab-")).sort(),
    };
  });
}

/** Polls `fn(arg)` in `page` (it may be async) until it is truthy; throws after `ms`. */
async function until(page, what, fn, arg = null, ms = 20_000) {
  const end = Date.now() + ms;
  for (;;) {
    // A page that navigates meanwhile loses its context: ask again.
    if (await page.evaluate(fn, arg).catch(() => false)) return;
    if (Date.now() > end) throw new Error(`timed out waiting for ${what}`);
    await new Promise((done) => setTimeout(done, 100));
  }
}

/** Registers the offline tests with run.mjs's `test` (see distSuite for `tools`). */
export async function offlineSuite({
  test,
  assert,
  equal,
  context,
  watchErrors,
  demoHelpers,
  settle,
}) {
  let dir = null;
  let site = "";
  let server = null;
  let port = 0;
  let base = "";
  let page = null;
  let errors = null;
  let version = "";
  const failedRequests = [];
  const needSite = () => assert(page, "the site was not built (see the first offline test)");

  async function newPage() {
    const p = await context.newPage();
    p.on("requestfailed", (r) => {
      if (r.url().startsWith(base)) failedRequests.push(`${r.url()}: ${r.failure()?.errorText}`);
    });
    await p.addInitScript(() => {
      window.__violations = [];
      document.addEventListener("securitypolicyviolation", (e) =>
        window.__violations.push(`CSP: ${e.violatedDirective} ${e.blockedURI}`),
      );
    });
    return p;
  }

  /** Waits for a figure, then asserts a drawn canvas and nothing wrong on the page. */
  async function checkPage(what, h) {
    await h.ready();
    await settle(page);
    const colours = await h.canvas().evaluate(distinctColours);
    assert(colours >= 4, `${what}: the canvas has ${colours} colours (not drawn)`);
    const problems = [
      ...errors.take(),
      ...(await page.evaluate(() => window.__violations)),
      ...failedRequests.splice(0),
    ];
    assert(problems.length === 0, `${what}:\n${problems.join("\n")}`);
  }

  /** Waits until this origin's worker is activated, with nothing installing or waiting. */
  async function settledWorker(p) {
    await until(p, "the worker to be activated", async () => {
      const reg = await navigator.serviceWorker.getRegistration();
      return reg?.active?.state === "activated" && !reg.installing && !reg.waiting;
    });
  }

  try {
    await test("offline: make dist builds the site with its worker", async () => {
      dir = await mkdtemp(join(tmpdir(), "splinelab-offline-"));
      site = join(dir, "site");
      await buildSite({ out: site });
      version = await builtVersion(site);
      server = await startServer(0, "127.0.0.1", site);
      port = server.address().port;
      base = `http://127.0.0.1:${port}`;
      page = await newPage();
      errors = watchErrors(page);
    });

    await test("offline: the built site installs its worker, which precaches the whole site", async () => {
      needSite();
      await page.goto(`${base}/index.html#demo=de-casteljau`);
      await checkPage("de-casteljau, online", demoHelpers(page));
      await settledWorker(page);
      const state = await workerState(page);
      equal(state.caches.join(), `splinelab-${version}`, "the one cache is this build's");
      // Installable: Chromium's own verdict on the manifest, its icons and the worker.
      const cdp = await context.newCDPSession(page);
      try {
        const manifest = await cdp.send("Page.getAppManifest");
        equal(manifest.url, `${base}/manifest.webmanifest`, "the page's manifest");
        equal(JSON.stringify(manifest.errors), "[]", "manifest errors");
        const { installabilityErrors } = await cdp.send("Page.getInstallabilityErrors");
        equal(JSON.stringify(installabilityErrors), "[]", "installability errors");
      } finally {
        await cdp.detach();
      }
      // Each PNG icon is as large as the manifest says (its IHDR chunk).
      const { icons } = JSON.parse(await readFile(join(site, "manifest.webmanifest"), "utf8"));
      for (const icon of icons.filter((i) => i.type === "image/png")) {
        const png = await readFile(join(site, icon.src));
        equal(`${png.readUInt32BE(16)}x${png.readUInt32BE(20)}`, icon.sizes, icon.src);
      }
      assert(
        icons.some((i) => i.purpose === "maskable") &&
          ["192x192", "512x512"].every((size) => icons.some((i) => i.sizes === size)),
        "icons of 192 and 512 px and a maskable one",
      );
      equal(state.controlled, false, "the first page is not taken over (no clients.claim)");

      // What must be there, listed from disk: every page, embed.js, the manifest and icons, and
      // every hashed file but the .woff/.ttf that the .woff2 beside them makes unnecessary.
      const files = (await listFiles(site)).map((f) => relative(site, f).split("\\").join("/"));
      const wanted = files.filter(
        (f) =>
          /^(?:[^/]+\.html|embed\.js|manifest\.webmanifest|icons\/[^/]+\.(?:png|svg))$/.test(f) ||
          (/^assets\/[^/]+-[A-Z2-7]{8}\.[a-z0-9]+$/.test(f) && !/\.(woff|ttf)$/.test(f)),
      );
      for (const kind of [".wasm", ".css", ".woff2", ".json", ".html", ".png"])
        assert(
          wanted.some((f) => f.endsWith(kind)),
          `the site has a ${kind} file`,
        );
      const cached = await page.evaluate(async (name) => {
        const cache = await caches.open(name);
        const scope = (await navigator.serviceWorker.getRegistration()).scope;
        return (await cache.keys()).map((r) => r.url.slice(scope.length));
      }, `splinelab-${version}`);
      const missing = wanted.filter((f) => !cached.includes(f));
      assert(missing.length === 0, `not precached: ${missing.join(", ")}`);
    });

    await test("offline: with no network, a 2D demo, a 3D demo and a lecture work from the cache", async () => {
      needSite();
      await context.setOffline(true);
      await stop(server);
      server = null;
      try {
        await page.reload();
        const h = demoHelpers(page);
        await checkPage("de-casteljau, offline", h);
        equal((await workerState(page)).controlled, true, "the reloaded page is the worker's");
        const before = await h.snapshot();
        const [handle] = await h.handles();
        await h.drag(handle, 40, -30);
        assert((await h.snapshot()) !== before, "dragging a handle offline redraws the curve");
        for (const [what, path] of [
          ["bezier-patch (3D), offline", "index.html#demo=bezier-patch"],
          ["a Greek lecture, offline", "index.html?lang=el#lecture=bezier-curves&scene=2"],
        ]) {
          await page.goto("about:blank");
          await page.goto(`${base}/${path}`);
          await checkPage(what, demoHelpers(page));
          if (what.includes("3D"))
            assert(
              page.workers().some((w) => w.url().endsWith("/gl-worker.js")),
              "the 3D figure's rendering worker runs offline (not the page's fallback)",
            );
        }
        equal(
          await page.evaluate(() => document.documentElement.lang),
          "el",
          "the lecture's language",
        );
        await page.goto("about:blank");
        await page.goto(`${base}/embed-example.html`);
        await checkPage("the embed example, offline", demoHelpers(page, "spline-lab#worked "));
      } finally {
        await context.setOffline(false);
      }
    });

    await test("offline: a new deployment takes over once the old version's pages are closed, and its cache goes", async () => {
      needSite();
      // Version 2: the same www/ with one more rule in its stylesheet.
      const www2 = join(dir, "www");
      await cp(WWW, www2, { recursive: true, dereference: true });
      const css = join(www2, "style.css");
      await writeFile(css, `${await readFile(css, "utf8")}\n:root { --sl-offline-test: 2; }\n`);
      await buildSite({ www: www2, out: site });
      const version2 = await builtVersion(site);
      assert(version2 !== version, "a changed stylesheet makes a new version");
      server = await startServer(port, "127.0.0.1", site);

      await page.goto("about:blank");
      await page.goto(`${base}/index.html#demo=de-casteljau`);
      await checkPage("version 1 before the update", demoHelpers(page));
      const styleV1 = await page.evaluate(() =>
        [...document.styleSheets].map((s) => s.href).find((h) => /\/style-/.test(h)),
      );
      await page.evaluate(async () => (await navigator.serviceWorker.getRegistration()).update());
      await until(
        page,
        "version 2 to be installed",
        async () =>
          (await navigator.serviceWorker.getRegistration()).waiting?.state === "installed",
      );
      let state = await workerState(page);
      equal(
        state.caches.join(),
        [`splinelab-${version}`, `splinelab-${version2}`].sort().join(),
        "both versions cached while version 2 waits",
      );
      // The host no longer has version 1's stylesheet; the reloaded page still gets all of it.
      await page.reload();
      await checkPage("version 1, reloaded while version 2 waits", demoHelpers(page));
      const reloaded = await page.evaluate(() =>
        [...document.styleSheets].map((s) => ({ href: s.href, rules: s.cssRules.length })),
      );
      const v1Sheet = reloaded.find((s) => s.href === styleV1);
      assert(
        v1Sheet?.rules > 0,
        `the reloaded page keeps version 1's stylesheet: ${JSON.stringify(reloaded)}`,
      );

      // Close every page of version 1: version 2 activates and deletes version 1's cache. The
      // browser lets go of a closed page's worker a moment later: a page opened meanwhile is
      // still version 1's (and holds it), so close and open again until the page is version 2's.
      const sheet = () =>
        page.evaluate(() =>
          [...document.styleSheets].map((s) => s.href).find((h) => /\/style-/.test(h)),
        );
      for (let attempt = 1; ; attempt++) {
        await page.close();
        await new Promise((done) => setTimeout(done, 300 * attempt));
        page = await newPage();
        errors = watchErrors(page);
        await page.goto(`${base}/index.html#demo=de-casteljau`);
        if ((await sheet()) !== styleV1) break;
        assert(attempt < 6, "version 2 never took over");
      }
      await checkPage("version 2", demoHelpers(page));
      await settledWorker(page);
      await until(
        page,
        "version 1's cache to be deleted",
        async (name) =>
          (await caches.keys()).filter((k) => k.startsWith("splinelab-")).join() === name,
        `splinelab-${version2}`,
      );
      state = await workerState(page);
      equal(state.controlled, true, "the new page is controlled");
      const styleV2 = await sheet();
      assert(styleV2 && styleV2 !== styleV1, `version 2's stylesheet: ${styleV2} (was ${styleV1})`);
      equal(
        await page.evaluate(() =>
          getComputedStyle(document.documentElement).getPropertyValue("--sl-offline-test").trim(),
        ),
        "2",
        "version 2's rule applies",
      );
    });

    await test("offline: development (www/) on the same origin retires a built site's worker", async () => {
      needSite();
      // `make serve` where `make serve-dist` ran: same port, www/ with its pass-through sw.js.
      await stop(server);
      server = await startServer(port, "127.0.0.1", WWW);
      await page.goto("about:blank");
      await page.goto(`${base}/index.html#demo=de-casteljau`);
      await until(
        page,
        "the built site's worker and cache to be gone",
        async () =>
          !(await navigator.serviceWorker.getRegistration()) &&
          (await caches.keys()).filter((k) => k.startsWith("splinelab-")).length === 0,
      );
      await page.reload();
      await checkPage("de-casteljau from www/", demoHelpers(page));
      equal(
        await page.evaluate(
          () => document.querySelector('script[type="module"][src$="app.js"]')?.src,
        ),
        `${base}/app.js`,
        "the page is www/'s",
      );
      equal((await workerState(page)).controlled, false, "development pages are not controlled");
    });

    await test("offline: a page that is not the build's fails the install, and stores nothing", async () => {
      needSite();
      // A host (or CDN) still sending an older index.html beside the new sw.js and assets.
      const page2 = await newPage();
      const errors2 = watchErrors(page2);
      const other = await startServer(0, "127.0.0.1", site);
      // index.html and its .br/.gz (the server sends those when the browser takes them).
      const index = join(site, "index.html");
      const original = await Promise.all(["", ".br", ".gz"].map((ext) => readFile(index + ext)));
      const restore = () =>
        Promise.all(["", ".br", ".gz"].map((ext, k) => writeFile(index + ext, original[k])));
      try {
        const at = `http://127.0.0.1:${other.address().port}`;
        /** Registers sw.js from the embed example (which registers nothing itself) and resolves
         * to the state its worker ends in. */
        const install = () =>
          page2.evaluate(async () => {
            const reg = await navigator.serviceWorker.register("sw.js");
            const worker = reg.installing ?? reg.waiting ?? reg.active;
            const end = ["redundant", "activated"];
            if (!end.includes(worker.state))
              await new Promise((done) =>
                worker.addEventListener("statechange", () => end.includes(worker.state) && done()),
              );
            const names = await caches.keys();
            return { state: worker.state, caches: names.filter((k) => k.startsWith("splinelab-")) };
          });
        await writeFile(index, Buffer.concat([original[0], Buffer.from("<!-- older -->\n")]));
        await rm(`${index}.br`);
        await rm(`${index}.gz`);
        await page2.goto(`${at}/embed-example.html`);
        const failed = await install();
        equal(failed.state, "redundant", "the worker with an unexpected page");
        equal(failed.caches.length, 0, "no cache is left behind");
        // The control: the same worker with the build's page installs.
        await restore();
        const installed = await install();
        equal(installed.state, "activated", "the worker with the build's page");
        equal(installed.caches.join(), `splinelab-${await builtVersion(site)}`, "its cache");
        errors2.take(); // the failed install's message, expected
      } finally {
        await restore();
        await page2.close();
        await stop(other);
      }
    });
  } finally {
    await page?.close();
    if (server) await stop(server);
    if (dir) await rm(dir, { recursive: true, force: true });
  }
}
