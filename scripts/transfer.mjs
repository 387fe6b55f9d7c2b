// What a first visit transfers: the gallery, a 2D demo, a 3D demo and the embed example, each
// in a fresh browser context (empty cache), loaded from www/ sent uncompressed (what `make
// serve` sent before it compressed), www/ compressed on the fly (`make serve` now) and
// dist/site/ (`make serve-dist`: minified, precompressed). Sums the Resource Timing sizes of the
// navigation and every resource once the figure (or the gallery's thumbnails) is drawn and the
// network is idle. Needs `make dist` first.
//   node scripts/transfer.mjs
import { chromium } from "playwright-core";
import { CHROMIUM, CHROMIUM_ARGS } from "./chromium.mjs";
import { startServer } from "./serve.mjs";
import { SITE, WWW } from "./dist.mjs";

const PAGES = [
  ["gallery", "index.html", "a.card img[src^='data:image/png']"],
  ["2D demo (de-casteljau)", "index.html#demo=de-casteljau", ".sl-formula .katex"],
  ["3D demo (bezier-patch)", "index.html#demo=bezier-patch", ".sl-formula .katex"],
  ["embed example", "embed-example.html", "spline-lab .sl-canvas"],
];
const SOURCES = [
  ["www, uncompressed", WWW, { "accept-encoding": "identity" }],
  ["www, on the fly (br)", WWW, {}],
  ["dist/site (br)", SITE, {}],
];

const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS] });
const rows = [];
try {
  for (const [source, root, headers] of SOURCES) {
    const server = await startServer(0, "127.0.0.1", root);
    const base = `http://127.0.0.1:${server.address().port}`;
    for (const [name, path, ready] of PAGES) {
      const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
      await context.setExtraHTTPHeaders(headers);
      const page = await context.newPage();
      await page.goto(`${base}/${path}`);
      await page.locator(ready).first().waitFor({ state: "attached", timeout: 30_000 });
      await page.waitForLoadState("networkidle");
      const sizes = await page.evaluate(() => {
        const entries = [
          ...performance.getEntriesByType("navigation"),
          ...performance.getEntriesByType("resource"),
        ].filter((e) => e.name.startsWith(location.origin));
        return {
          files: entries.length,
          encoded: entries.reduce((s, e) => s + e.encodedBodySize, 0),
          decoded: entries.reduce((s, e) => s + e.decodedBodySize, 0),
        };
      });
      rows.push({ source, name, ...sizes });
      await context.close();
    }
    server.close();
  }
} finally {
  await browser.close();
}

const kb = (n) => `${(n / 1024).toFixed(0)} KiB`;
console.log("| page | served from | files | transferred (bodies) | decoded |");
console.log("|---|---|---:|---:|---:|");
for (const r of rows)
  console.log(`| ${r.name} | ${r.source} | ${r.files} | ${kb(r.encoded)} | ${kb(r.decoded)} |`);
