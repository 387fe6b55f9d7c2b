// What each late family adds to the wasm, for the budgets of issues 24 (typed parametric curves:
// ≤ 40 KB gzipped added) and 25 (sketching: ≤ 30 KB gzipped added). The release wasm is built
// three times, as `make build` builds it (cargo release, wasm-bindgen, scripts/glue.mjs,
// `wasm-opt -O`): with every family, without the typed curves' bindings (Cargo feature
// `typed-curves` off) and without the fitters' (`sketching` off). A family's core code is
// reached only from its bindings, so the link drops it with them: the difference of the sizes
// is what the family adds (its code, the std code only it uses, its bindings and glue).
// Sizes: bytes after wasm-opt, `gzip -9`, brotli (quality 11, as make dist writes).
//
//   node bench/wasm-size.mjs          (needs the tools of make build; ~5 min cold, 3 builds)
//   CARGO_PROFILE_RELEASE_OPT_LEVEL=z node bench/wasm-size.mjs   (the same at another opt-level)
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { brotliCompressSync, constants } from "node:zlib";

const ROOT = fileURLToPath(new URL("..", import.meta.url));
const TARGET = "wasm32-unknown-unknown";

/** The build variants: a name and the cargo feature arguments. */
const VARIANTS = [
  { name: "every family", features: [] },
  { name: "without typed curves", features: ["--no-default-features", "--features", "sketching"] },
  { name: "without sketching", features: ["--no-default-features", "--features", "typed-curves"] },
];

const run = (cmd, args) =>
  execFileSync(cmd, args, { cwd: ROOT, stdio: ["ignore", "ignore", "inherit"] });

/** Builds one variant into a temporary folder and returns its wasm's sizes. */
function build({ features }) {
  run("cargo", ["build", "--release", "--lib", "--target", TARGET, ...features]);
  const out = mkdtempSync(join(tmpdir(), "splinelab-size-"));
  try {
    const wasm = join(ROOT, "target", TARGET, "release", "splinelab.wasm");
    run(join(ROOT, ".tools/bin/wasm-bindgen"), [
      "--target",
      "web",
      "--out-dir",
      out,
      "--out-name",
      "splinelab",
      wasm,
    ]);
    execFileSync("node", [join(ROOT, "scripts/glue.mjs"), out], { stdio: "ignore" });
    const file = join(out, "splinelab_bg.wasm");
    run(join(ROOT, "node_modules/.bin/wasm-opt"), ["-O", file, "-o", file]);
    const bytes = readFileSync(file);
    return {
      raw: bytes.length,
      // The gzip program, as the README has always measured (zlib's level 9 differs slightly).
      gzip: execFileSync("gzip", ["-9c", file], { maxBuffer: 1 << 26 }).length,
      brotli: brotliCompressSync(bytes, {
        params: { [constants.BROTLI_PARAM_QUALITY]: 11 },
      }).length,
    };
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}

const kb = (n) => (n / 1000).toFixed(1);
const sizes = VARIANTS.map((v) => {
  process.stderr.write(`building: ${v.name}\n`);
  return build(v);
});
const [all, noCurves, noSketch] = sizes;
console.log("| build | wasm KB | gzip -9 KB | brotli KB |");
console.log("|---|---|---|---|");
VARIANTS.forEach((v, i) =>
  console.log(
    `| ${v.name} | ${kb(sizes[i].raw)} | ${kb(sizes[i].gzip)} | ${kb(sizes[i].brotli)} |`,
  ),
);
const added = (without) =>
  ["raw", "gzip", "brotli"].map((k) => kb(all[k] - without[k])).join(" / ");
console.log(
  `typed curves add ${added(noCurves)} KB (wasm / gzip / brotli); issue 24's budget: ≤ 40 KB gzipped`,
);
console.log(
  `sketching adds ${added(noSketch)} KB (wasm / gzip / brotli); issue 25's budget: ≤ 30 KB gzipped`,
);
