// Runs workloads (g), (i) and (k) in headless Chromium: a tiny static server for bench/, www/pkg/
// and, for (k)'s 3D frame, www/lib/ and www/vendor/ (not the playground's pages), with
// COOP/COEP headers so performance.now() gets its fine (cross-origin-isolated) resolution.
import { createServer } from "node:http";
import { mkdtempSync, rmSync } from "node:fs";
import { readFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { extname, join, normalize, resolve, sep } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { CHROMIUM, CHROMIUM_ARGS } from "../scripts/chromium.mjs";

const ROOT = resolve(fileURLToPath(new URL("..", import.meta.url)));
const MOUNTS = {
  "/bench/": join(ROOT, "bench"),
  "/pkg/": join(ROOT, "www", "pkg"),
  // (k) renders through the playground's own 3D modules and the vendored three.js.
  "/lib/": join(ROOT, "www", "lib"),
  "/vendor/": join(ROOT, "www", "vendor"),
};
const TYPES = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript",
  ".mjs": "text/javascript",
  ".wasm": "application/wasm",
};
/** Longest the page may take to finish its frames (ms). */
const PAGE_TIMEOUT_MS = 120_000;

function startServer() {
  const server = createServer(async (req, res) => {
    try {
      const path = normalize(decodeURIComponent(new URL(req.url, "http://localhost").pathname));
      const prefix = Object.keys(MOUNTS).find((p) => path.startsWith(p));
      if (!prefix) throw new Error("not mounted");
      const dir = MOUNTS[prefix];
      const file = resolve(join(dir, path.slice(prefix.length)));
      if (!file.startsWith(dir + sep)) throw new Error("outside");
      const body = await readFile(file);
      res.writeHead(200, {
        "content-type": TYPES[extname(file)] ?? "application/octet-stream",
        "cache-control": "no-cache",
        "cross-origin-opener-policy": "same-origin",
        "cross-origin-embedder-policy": "require-corp",
      });
      res.end(body);
    } catch {
      res.writeHead(404, { "content-type": "text/plain" });
      res.end("not found");
    }
  });
  return new Promise((ok, fail) => {
    server.once("error", fail);
    server.listen(0, "127.0.0.1", () => ok(server));
  });
}

/** Drag-frame timings from headless Chromium, plus its version. */
export async function runInChromium({ frames = 100, warmup = 10, only = "" } = {}) {
  const server = await startServer();
  const profile = mkdtempSync(join(tmpdir(), "splinelab-bench-"));
  let context = null;
  try {
    context = await chromium.launchPersistentContext(profile, {
      executablePath: CHROMIUM,
      args: [...CHROMIUM_ARGS],
    });
    const page = context.pages()[0] ?? (await context.newPage());
    const errors = [];
    page.on("pageerror", (err) => errors.push(err.message));
    const url = `http://127.0.0.1:${server.address().port}/bench/browser.html?frames=${frames}&warmup=${warmup}${only ? `&only=${only}` : ""}`;
    await page.goto(url);
    await page.waitForFunction(() => window.benchResult !== undefined, null, {
      timeout: PAGE_TIMEOUT_MS,
    });
    const result = await page.evaluate(() => window.benchResult);
    if (result.error) throw new Error(result.error);
    if (errors.length) throw new Error(errors[0]);
    result.browserVersion =
      context.browser()?.version() ??
      (await page.evaluate(
        () => navigator.userAgent.match(/Chrom(e|ium)\/([\d.]+)/)?.[2] ?? "unknown",
      ));
    result.crossOriginIsolated = await page.evaluate(() => self.crossOriginIsolated);
    return result;
  } finally {
    await context?.close();
    server.close();
    rmSync(profile, { recursive: true, force: true });
  }
}
