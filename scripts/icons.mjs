// Renders the app icons the web app manifest (www/manifest.webmanifest) names from their SVG
// sources in www/icons/, with the Chromium the browser tests use (no extra dependency): run it
// after changing an SVG and commit the PNGs (a few KB each).
//   node scripts/icons.mjs
import { chromium } from "playwright-core";
import { readFileSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { CHROMIUM, CHROMIUM_ARGS } from "./chromium.mjs";

const ICONS = resolve(fileURLToPath(new URL("../www/icons", import.meta.url)));
/** [source SVG, size in px, output PNG]: the "any" icon at the two sizes installers ask for,
 * and the maskable one (full-bleed, its drawing inside the central 80 % circle). */
const RENDERS = [
  ["icon.svg", 192, "icon-192.png"],
  ["icon.svg", 512, "icon-512.png"],
  ["icon-maskable.svg", 512, "icon-maskable-512.png"],
];

const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS] });
try {
  const page = await browser.newPage({ deviceScaleFactor: 1 });
  for (const [source, size, output] of RENDERS) {
    const svg = readFileSync(join(ICONS, source), "utf8");
    await page.setViewportSize({ width: size, height: size });
    await page.setContent(
      `<style>html,body{margin:0;background:transparent}img{display:block}</style>` +
        `<img width="${size}" height="${size}" src="data:image/svg+xml;base64,${Buffer.from(svg).toString("base64")}">`,
    );
    await page.locator("img").evaluate((img) => img.decode());
    const png = await page.screenshot({ omitBackground: true, type: "png" });
    writeFileSync(join(ICONS, output), png);
    console.log(`icons: ${output} (${size}×${size}, ${png.length} bytes)`);
  }
} finally {
  await browser.close();
}
