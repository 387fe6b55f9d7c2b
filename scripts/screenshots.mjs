// A PNG of every demo (default state) at DPR 1 and 2, plus the gallery and the embed example,
// into screenshots/ (git-ignored). Used by `make screenshots` and to look at the UI by eye.
//   node scripts/screenshots.mjs            all
//   node scripts/screenshots.mjs --narrow   also a phone-width shot of each demo
//   node scripts/screenshots.mjs bezier-patch   only the demos whose id contains this (no gallery)
import { chromium } from "playwright-core";
import { mkdirSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { startServer } from "./serve.mjs";
import { CHROMIUM, CHROMIUM_ARGS } from "./chromium.mjs";

const OUT = fileURLToPath(new URL("../screenshots/", import.meta.url));
const DESKTOP = { width: 1280, height: 900 };
const PHONE = { width: 390, height: 844 };
const narrow = process.argv.includes("--narrow");
const only = process.argv.slice(2).find((arg) => !arg.startsWith("--")) ?? "";

/** Waits until a demo (in the page or a shadow root, by CSS prefix) is drawn and typeset. */
async function demoReady(page, scope = "") {
  // The handles' positions are written once mounted; a demo without handles has its canvas.
  await page
    .locator(`${scope}.sl-figure[data-handles], ${scope}.sl-figure:has(.sl-canvas)`)
    .first()
    .waitFor({ state: "attached" });
  // KaTeX loads when the formula panel nears the viewport (below the fold on a phone).
  const formula = page.locator(`${scope}.sl-formula`).first();
  await formula.scrollIntoViewIfNeeded();
  await formula.locator(".katex").first().waitFor({ state: "attached" });
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.evaluate(() => document.fonts.ready);
  await page.evaluate(
    () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))),
  );
  // 3D figures: their rendering worker's frames have arrived (lib/gl-client.js).
  await page.waitForFunction(() => !document.documentElement.hasAttribute("data-gl-pending"));
}

mkdirSync(OUT, { recursive: true });
const server = await startServer(0);
const base = `http://127.0.0.1:${server.address().port}`;
const written = [];

for (const [scale, viewport] of [[1, DESKTOP], [2, DESKTOP], ...(narrow ? [[2, PHONE]] : [])]) {
  const profile = mkdtempSync(join(tmpdir(), "splinelab-shots-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    args: [...CHROMIUM_ARGS],
    viewport,
    deviceScaleFactor: scale,
  });
  const page = context.pages()[0] ?? (await context.newPage());
  page.on("pageerror", (err) => console.error(`page error: ${err.message}`));
  const suffix = viewport === PHONE ? "phone" : `dpr${scale}`;
  try {
    await page.goto(`${base}/index.html`);
    const ids = (
      await page.evaluate(async () => (await import("./demos/index.js")).demos.map((d) => d.id))
    ).filter((id) => id.includes(only));
    if (viewport !== PHONE && !only) {
      // The cards appear once the wasm has loaded; a thumbnail is drawn when its card comes
      // near the viewport: wait for the cards, then pass every card by.
      await page.waitForSelector(".card");
      for (const card of await page.locator(".card").all()) {
        await card.scrollIntoViewIfNeeded();
        await card.locator("img").evaluate(
          (img) =>
            new Promise((resolve) => {
              const check = () =>
                img.src.startsWith("data:") ? resolve() : requestAnimationFrame(check);
              check();
            }),
        );
      }
      await page.evaluate(() => window.scrollTo(0, 0));
      await page.screenshot({ path: `${OUT}gallery-${suffix}.png`, fullPage: true });
      written.push(`gallery-${suffix}.png`);
    }
    for (const id of ids) {
      await page.goto("about:blank");
      await page.goto(`${base}/index.html#demo=${id}`);
      await demoReady(page);
      await page.screenshot({ path: `${OUT}${id}-${suffix}.png`, fullPage: true });
      written.push(`${id}-${suffix}.png`);
    }
    if (viewport !== PHONE && !only) {
      await page.goto(`${base}/embed-example.html`);
      for (const el of await page.locator("spline-lab").all()) {
        await el.scrollIntoViewIfNeeded();
        await el.locator(".sl-figure[data-handles]").waitFor({ state: "attached" });
      }
      await demoReady(page, "spline-lab ");
      await page.evaluate(() => window.scrollTo(0, 0));
      await page.screenshot({ path: `${OUT}embed-example-${suffix}.png`, fullPage: true });
      written.push(`embed-example-${suffix}.png`);
    }
  } finally {
    await context.close();
    rmSync(profile, { recursive: true, force: true });
  }
}
server.close();
console.log(`screenshots: ${written.length} PNGs in screenshots/\n  ${written.join("\n  ")}`);
