// Copies the front-end libraries installed from npm into www/vendor/ so the page works
// offline and loads nothing from a CDN. Re-run safe.
//
// three.js (only the 3D figures' renderers import it, lazily, see www/lib/three-loader.js and
// gl-worker.js): the module build and the core it imports (`./three.core.js`); relative imports
// only, so a course page that embeds a 3D demo needs no import map.
import { cpSync, existsSync, mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

const root = fileURLToPath(new URL("..", import.meta.url));
const vendor = `${root}www/vendor`;
const copies = [
  ["node_modules/katex/dist/katex.min.css", "katex/katex.min.css"],
  ["node_modules/katex/dist/katex.mjs", "katex/katex.mjs"],
  ["node_modules/katex/dist/fonts", "katex/fonts"],
  ["node_modules/katex/LICENSE", "katex/LICENSE"],
];
mkdirSync(vendor, { recursive: true });
for (const [from, to] of copies) {
  const src = `${root}${from}`;
  if (!existsSync(src)) throw new Error(`vendor: ${from} is missing; run npm install`);
  cpSync(src, `${vendor}/${to}`, { recursive: true });
}

// KaTeX's stylesheet, split so that an embed cannot clash with a course page's own KaTeX: the
// @font-face rules go to the document (fonts only work from there) under our own family names
// (SL_KaTeX_Main, …), and the rules for KaTeX's classes, using those names, are loaded only
// where our formulas are (the playground page, or an embed's shadow root). lib/formula.js.
const katexCss = readFileSync(`${root}node_modules/katex/dist/katex.min.css`, "utf8");
// Every family name (in font-family, the font shorthand, quoted or not), not the font files'
// names in url(fonts/KaTeX_…).
const renamed = katexCss.replace(/(?<![/\w])KaTeX_/g, "SL_KaTeX_");
const fontFaces = renamed.match(/@font-face\{[^}]*\}/g) ?? [];
if (fontFaces.length < 10 || !renamed.includes(".katex"))
  throw new Error("vendor: katex.min.css no longer has the shape this script splits");
writeFileSync(`${vendor}/katex/katex-fonts.css`, `${fontFaces.join("\n")}\n`);
writeFileSync(`${vendor}/katex/katex-scoped.css`, renamed.replace(/@font-face\{[^}]*\}/g, ""));

const threeCopies = [
  ["node_modules/three/build/three.module.js", "three/three.module.js"],
  ["node_modules/three/build/three.core.js", "three/three.core.js"],
  ["node_modules/three/LICENSE", "three/LICENSE"],
];
mkdirSync(`${vendor}/three`, { recursive: true });
for (const [from, to] of threeCopies) {
  const src = `${root}${from}`;
  if (!existsSync(src)) throw new Error(`vendor: ${from} is missing; run npm install`);
  cpSync(src, `${vendor}/${to}`);
}
console.log(
  `vendor: ${copies.length + threeCopies.length} entries copied into www/vendor/, KaTeX split`,
);
