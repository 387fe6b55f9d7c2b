// Copies the front-end libraries installed from npm into www/vendor/ so the page works
// offline and loads nothing from a CDN. Re-run safe.
import { cpSync, existsSync, mkdirSync } from "node:fs";
import { fileURLToPath } from "node:url";

const root = fileURLToPath(new URL("..", import.meta.url));
const vendor = `${root}www/vendor`;
const copies = [
  ["node_modules/katex/dist/katex.min.css", "katex/katex.min.css"],
  ["node_modules/katex/dist/katex.mjs", "katex/katex.mjs"],
  ["node_modules/katex/dist/fonts", "katex/fonts"],
];
mkdirSync(vendor, { recursive: true });
for (const [from, to] of copies) {
  const src = `${root}${from}`;
  if (!existsSync(src)) throw new Error(`vendor: ${from} is missing; run npm install`);
  cpSync(src, `${vendor}/${to}`, { recursive: true });
}
console.log(`vendor: ${copies.length} entries copied into www/vendor/`);
