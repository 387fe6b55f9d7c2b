// `make package`: writes dist/splinelab-<version>.tgz with `npm pack`, the npm package a JS
// developer installs. It is the built playground (www/ after `make build`: the wasm-bindgen
// glue, its .wasm and .d.ts in pkg/, the `<spline-lab>` element and its demos, and the
// vendored KaTeX and three.js), so it needs no build step on the user's side, plus a
// package.json whose `exports` name the three entries and a README made of the project
// README's JS sections (one source for both).
//
//   node scripts/package.mjs            build dist/splinelab-<version>.tgz, print its path
import { execFileSync } from "node:child_process";
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

const root = fileURLToPath(new URL("..", import.meta.url));
const stage = `${root}target/npm-package`;
const dist = `${root}dist`;

/** The crate's version: one number for the crate and the package. */
export function crateVersion() {
  const toml = readFileSync(`${root}Cargo.toml`, "utf8");
  const match = /^\[package\][^[]*?^version\s*=\s*"([^"]+)"/ms.exec(toml);
  if (!match) throw new Error("package: no version in Cargo.toml's [package]");
  return match[1];
}

/**
 * The README sections a package user needs, in order: "Use from npm", the JS API (quick start
 * through its subsections) and "Conventions"; each from its `## ` heading to the next one.
 */
export function packageReadme(readme) {
  const wanted = ["Use from npm", "JS API quick start", "Conventions"];
  const sections = readme.split(/^(?=## )/m);
  const parts = wanted.map((title) => {
    const found = sections.find((s) => s.startsWith(`## ${title}\n`));
    if (!found) throw new Error(`package: README has no section "## ${title}"`);
    return found.trimEnd();
  });
  const intro = readme.split(/^## /m)[0].split(/^\*\*splinelab\*\*/m)[1];
  if (!intro) throw new Error("package: README's introduction paragraph is missing");
  return `# splinelab\n\n**splinelab**${intro.split(/\n\n/)[0]}\n\n${parts.join("\n\n")}\n`;
}

function manifest(version) {
  return {
    name: "splinelab",
    version,
    description:
      "Parametric curves and surfaces (Bézier, B-spline, NURBS, interpolating splines, tensor-product patches) in WebAssembly, with interactive teaching demos",
    license: "MIT",
    type: "module",
    main: "./pkg/splinelab.js",
    types: "./pkg/splinelab.d.ts",
    exports: {
      ".": { types: "./pkg/splinelab.d.ts", default: "./pkg/splinelab.js" },
      "./splinelab_bg.wasm": "./pkg/splinelab_bg.wasm",
      "./element": { types: "./embed.d.ts", default: "./embed.js" },
      "./package.json": "./package.json",
    },
    sideEffects: ["./embed.js"],
    keywords: ["bezier", "b-spline", "nurbs", "spline", "curve", "surface", "wasm", "geometry"],
    engines: { node: ">=16.4" },
  };
}

export function build() {
  const pkg = `${root}www/pkg/splinelab_bg.wasm`;
  if (!existsSync(pkg)) throw new Error("package: www/pkg is missing; run `make build` first");
  if (!existsSync(`${root}www/vendor/katex`)) {
    throw new Error("package: www/vendor is missing; run `make build` first");
  }
  rmSync(stage, { recursive: true, force: true });
  cpSync(`${root}www`, stage, { recursive: true });
  // wasm-bindgen writes pkg/.gitignore ("*"), which npm pack would obey and drop the glue.
  rmSync(`${stage}/pkg/.gitignore`, { force: true });
  cpSync(`${root}scripts/package/embed.d.ts`, `${stage}/embed.d.ts`);
  cpSync(`${root}LICENSE`, `${stage}/LICENSE`);
  const version = crateVersion();
  writeFileSync(`${stage}/package.json`, `${JSON.stringify(manifest(version), null, 2)}\n`);
  writeFileSync(`${stage}/README.md`, packageReadme(readFileSync(`${root}README.md`, "utf8")));
  mkdirSync(dist, { recursive: true });
  const out = execFileSync("npm", ["pack", "--silent", "--pack-destination", dist], {
    cwd: stage,
    encoding: "utf8",
  }).trim();
  const tarball = `${dist}/${out.split("\n").pop()}`;
  if (!existsSync(tarball)) throw new Error(`package: npm pack wrote no ${tarball}`);
  return tarball;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  console.log(build());
}
