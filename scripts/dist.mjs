// `make dist`: writes the static site dist/site/ from www/ (after `make build`), ready for any
// static host. Run: node scripts/dist.mjs
//
// - The HTML entry points (www/*.html) keep their names and places, so `index.html#demo=…` links
//   stay valid; `embed.js` stays at the site root under its own name (a course page references
//   it): it is a one-line module importing the hashed embed bundle. The module workers
//   (`WORKERS`: the 3D figures' rendering worker) are entries of the same bundle, so they share
//   its chunks (three.js is fetched once for the page and its worker), and each is started from a
//   one-line module at the site root under its own name, as embed.js (a chunk cannot name a
//   hashed file the same build makes: its own hash would not cover that name).
// - Everything else lives flat in assets/ under a content-hashed name (`name-XXXXXXXX.ext`, 8
//   base-32 characters), so a host may cache it for a year: the JS (app and embed bundled by
//   esbuild with code splitting, minified; one chunk per demo, locale and three.js as before),
//   the CSS (minified), the wasm and its glue, KaTeX (minified) and its fonts, the lectures' JSON.
//   A file's hash covers the hashed names it references, so a change anywhere renames every file
//   that leads to it.
// - References are rewritten, never resolved at run time: `new URL("…", import.meta.url)` in the
//   JS (a template literal with `${…}` inside the path becomes a lookup table of the files it can
//   name), `<script src>`/`<link href>` in the HTML, `url(…)` in the CSS. No import map (the
//   pages' CSP allows no inline script), no absolute path (the site works from any folder).
// - Beside every text file and the wasm: a `.gz` (zlib level 9) and a `.br` (brotli quality 11),
//   for hosts and scripts/serve.mjs to send as they are.
import * as esbuild from "esbuild";
import { createHash } from "node:crypto";
import { mkdir, readdir, readFile, rename, rm, writeFile, copyFile, stat } from "node:fs/promises";
import { existsSync, statSync } from "node:fs";
import { basename, dirname, extname, join, relative, resolve, sep } from "node:path";
import { fileURLToPath } from "node:url";
import { promisify } from "node:util";
import { brotliCompress, constants, gzip } from "node:zlib";
import { SERVICE_WORKER_DEFINE, writeServiceWorker } from "./service-worker.mjs";
import { STATES, renderPosters, summary as postersSummary } from "./posters.mjs";

const ROOT = resolve(fileURLToPath(new URL("..", import.meta.url)));
export const WWW = join(ROOT, "www");
export const SITE = join(ROOT, "dist", "site");
/** The .gz and .br of earlier builds, by the SHA-256 of what they compress (see compressAll). */
const CACHE = join(ROOT, "target", "dist-compressed");
/** The folder of the hashed files, under the site root (scripts/serve.mjs caches it for a year). */
export const ASSETS = "assets";
/** The browsers the wasm needs anyway (WebAssembly SIMD, README): the JS is lowered to them. */
const TARGET = ["chrome91", "edge91", "firefox89", "safari16.4"];
/** Files that get a .gz and a .br beside them. */
export const COMPRESSED = new Set([".html", ".js", ".mjs", ".css", ".json", ".svg", ".wasm"]);
const BASE32 = "ABCDEFGHIJKLMNOPQRSTUVWXYZ234567";

/** 8 base-32 characters of the SHA-256 of `body` (the alphabet and length esbuild's [hash] uses). */
function contentHash(body) {
  const digest = createHash("sha256").update(body).digest();
  let bits = 0n;
  for (const byte of digest.subarray(0, 5)) bits = (bits << 8n) | BigInt(byte);
  let out = "";
  for (let k = 7; k >= 0; k--) out += BASE32[Number((bits >> BigInt(5 * k)) & 31n)];
  return out;
}

/** `path` relative to `from` as a URL path ("./x" or "../x"). */
function urlFrom(from, path) {
  const rel = relative(from, path).split(sep).join("/");
  return rel.startsWith("../") ? rel : `./${rel}`;
}

/** The module workers (`new Worker(new URL("…", import.meta.url))`), as paths under www/. */
const WORKERS = ["lib/gl-worker.js"];

const NEW_URL = /new URL\(\s*(["'`])((?:\\.|(?!\1)[^\\])*)\1\s*,\s*import\.meta\.url\s*\)/g;
const STAR = "\0";

/**
 * SPLINELAB_POSTER_STATES for esbuild's `define`: the default states' fingerprints that
 * scripts/posters.mjs wrote beside the posters (lib/posters.js `posterShowsState`); nothing when
 * there are no posters.
 */
async function posterStatesDefine(www) {
  const file = join(www, "posters", STATES);
  if (!existsSync(file)) return {};
  return { SPLINELAB_POSTER_STATES: JSON.stringify(JSON.parse(await readFile(file, "utf8"))) };
}

/**
 * Builds the site from `www` into `out` (replaced whole at the end, so a server never sees half
 * a site). Resolves to { files, bytes, elapsed } for the summary line.
 */
export async function buildSite({ www = WWW, out = SITE } = {}) {
  const started = Date.now();
  for (const needed of ["pkg/splinelab.js", "vendor/katex/katex.mjs"])
    if (!existsSync(join(www, needed)))
      throw new Error(`dist: www/${needed} is missing; run make build`);
  const next = `${out}-next`;
  await rm(next, { recursive: true, force: true });
  const assetDir = join(next, ASSETS);
  await mkdir(assetDir, { recursive: true });

  const inside = (file) => file.startsWith(www + sep);
  const workers = new Map(WORKERS.map((path) => [join(www, path), basename(path)]));
  /** www file → promise of its hashed path in the site (relative to the site root). */
  const emitted = new Map();
  const emit = (file) => {
    if (!emitted.has(file)) emitted.set(file, emitAsset(file));
    return emitted.get(file);
  };

  async function writeHashed(file, body) {
    const given = extname(file);
    // .mjs becomes .js: a host that knows no .mjs would send a type a module script may not have.
    const ext = given === ".mjs" ? ".js" : given;
    const name = `${basename(file, given)}-${contentHash(body)}${ext}`;
    await writeFile(join(assetDir, name), body);
    return `${ASSETS}/${name}`;
  }

  async function emitAsset(file) {
    if (!inside(file) || !existsSync(file))
      throw new Error(`dist: ${file} is referenced but missing`);
    const ext = extname(file);
    if (ext === ".css") return writeHashed(file, await cssAsset(file));
    if (ext === ".js" || ext === ".mjs") return writeHashed(file, await urlModule(file));
    if (ext === ".json")
      return writeHashed(file, JSON.stringify(JSON.parse(await readFile(file, "utf8"))));
    return writeHashed(file, await readFile(file));
  }

  /** The site path a reference to www file `target` becomes (HTML pages keep theirs). */
  async function sitePath(target) {
    if (!inside(target)) throw new Error(`dist: ${target} is outside www/`);
    if (extname(target) === ".html") return relative(www, target).split(sep).join("/");
    return emit(target);
  }

  /** `source` (www file `file`) with every `new URL("…", import.meta.url)` pointing into the site
   * as seen from assets/ (where every JS file of the site lives). */
  async function rewriteUrls(source, file) {
    const from = assetDir;
    const jobs = [];
    for (const m of source.matchAll(NEW_URL)) {
      const [whole, quote, text] = m;
      jobs.push(
        (async () => {
          const dynamic = quote === "`" && text.includes("${");
          const cut = text.search(dynamic ? /[?#]|\$\{/ : /[?#]/);
          const path = cut < 0 ? text : text.slice(0, cut);
          const rest = cut < 0 ? "" : text.slice(cut);
          const target = resolve(dirname(file), path);
          const isWorker = /new Worker\(\s*$/.test(
            source.slice(Math.max(0, m.index - 20), m.index),
          );
          if (isWorker !== workers.has(target))
            throw new Error(
              `dist: ${relative(www, file)}: ${path} is a worker only if WORKERS says so`,
            );
          if (isWorker) {
            const spec = urlFrom(from, join(next, workers.get(target)));
            return [whole, `new URL(${quote}${spec}${rest}${quote}, import.meta.url)`];
          }
          if (!dynamic || statSync(target, { throwIfNoEntry: false })?.isFile()) {
            const spec = urlFrom(from, join(next, await sitePath(target)));
            return [whole, `new URL(${quote}${spec}${rest}${quote}, import.meta.url)`];
          }
          return [whole, await lookupTable(file, text, from)];
        })(),
      );
    }
    let result = source;
    for (const [whole, replacement] of await Promise.all(jobs))
      result = result.replace(whole, () => replacement);
    return result;
  }

  /** `new URL(\`./${id}.json\`, import.meta.url)` → a table from every name the template can
   * make (the files of that folder that fit it) to the hashed one, indexed by the template. */
  async function lookupTable(file, text, from) {
    const pattern = text.replace(/\$\{[^}]*\}/g, STAR);
    const dir = resolve(dirname(file), dirname(pattern));
    // A folder the build makes that is not there (www/posters/ before scripts/posters.mjs ran):
    // the lookup finds nothing (lib/posters.js then shows no poster).
    if (!existsSync(dir)) return 'new URL("data:,", import.meta.url)';
    if (pattern.includes("?") || pattern.includes("#") || dirname(pattern).includes(STAR))
      throw new Error(`dist: ${relative(www, file)}: cannot resolve new URL(\`${text}\`)`);
    const [head, tail] = basename(pattern).split(STAR);
    const names = (await readdir(dir)).filter(
      (n) => n.startsWith(head) && n.endsWith(tail) && n.length >= head.length + tail.length,
    );
    if (names.length === 0)
      throw new Error(`dist: no file fits \`${text}\` in ${relative(www, file)}`);
    const entries = await Promise.all(
      names.map(async (n) => {
        const key = `${dirname(text) === "." ? "." : dirname(text)}/${n}`;
        return [key, urlFrom(from, join(next, await sitePath(join(dir, n))))];
      }),
    );
    return `new URL(${JSON.stringify(Object.fromEntries(entries))}[\`${text}\`], import.meta.url)`;
  }

  /** A CSS file minified, its url(…)s pointing at hashed files beside it in assets/. */
  async function cssAsset(file) {
    const source = await readFile(file, "utf8");
    const jobs = [];
    for (const m of source.matchAll(/url\(\s*(["']?)([^"')]+)\1\s*\)/g)) {
      const ref = m[2];
      if (/^(data:|[a-z]+:|#|\/)/i.test(ref)) continue;
      const [path] = ref.split(/[?#]/);
      jobs.push(
        sitePath(resolve(dirname(file), path)).then((p) => [
          m[0],
          `url(${urlFrom(assetDir, join(next, p))})`,
        ]),
      );
    }
    let css = source;
    for (const [whole, replacement] of await Promise.all(jobs))
      css = css.replaceAll(whole, replacement);
    const { code } = await esbuild.transform(css, {
      loader: "css",
      minify: true,
      charset: "utf8",
      target: TARGET,
    });
    return code;
  }

  const urlPlugin = {
    name: "splinelab-urls",
    setup(build) {
      build.onLoad({ filter: /\.m?js$/ }, async (args) => {
        const source = await readFile(args.path, "utf8");
        if (!source.includes("import.meta.url")) return undefined;
        return { contents: await rewriteUrls(source, args.path), loader: "js" };
      });
    },
  };
  const common = {
    bundle: true,
    format: "esm",
    minify: true,
    target: TARGET,
    plugins: [urlPlugin],
    logLevel: "silent",
    legalComments: "eof",
    charset: "utf8",
    absWorkingDir: ROOT,
    define: { ...SERVICE_WORKER_DEFINE, ...(await posterStatesDefine(www)) },
  };

  /** A module the site imports by URL (`import(url.href)`: the wasm glue, KaTeX), bundled alone.
   * Its classes keep their names: the core tells a curve argument's class by its constructor's
   * name (src/wasm/surface_build.rs `curve_arg`: revolve, extrude, ruled surfaces). */
  async function urlModule(file) {
    const result = await esbuild.build({
      ...common,
      keepNames: true,
      entryPoints: [file],
      write: false,
      outdir: assetDir,
    });
    return result.outputFiles[0].contents;
  }

  // The HTML entry points, their module scripts and stylesheets.
  const pages = (await readdir(www)).filter((n) => n.endsWith(".html"));
  const scripts = new Set([join(www, "embed.js"), ...workers.keys()]);
  const htmlSources = new Map();
  for (const page of pages) {
    const html = await readFile(join(www, page), "utf8");
    htmlSources.set(page, html);
    for (const m of html.matchAll(/<script\b[^>]*\btype="module"[^>]*\bsrc="([^"]+)"/g))
      scripts.add(resolve(www, m[1]));
  }
  const bundle = await esbuild.build({
    ...common,
    entryPoints: [...scripts],
    outdir: assetDir,
    splitting: true,
    entryNames: "[name]-[hash]",
    chunkNames: "[name]-[hash]",
    metafile: true,
  });
  const entryOut = new Map();
  for (const [output, meta] of Object.entries(bundle.metafile.outputs))
    if (meta.entryPoint)
      entryOut.set(resolve(ROOT, meta.entryPoint), relative(next, resolve(ROOT, output)));
  for (const [file, name] of [[join(www, "embed.js"), "embed.js"], ...workers]) {
    const output = entryOut.get(file).split(sep).join("/");
    await writeFile(join(next, name), `import "./${output}";\n`);
  }

  for (const [page, html] of htmlSources) {
    const jobs = [];
    for (const m of html.matchAll(/<(script|link)\b[^>]*\b(src|href)="([^"]+)"[^>]*>/g)) {
      const ref = m[3];
      if (/^(data:|[a-z]+:|#|\/)/i.test(ref)) continue;
      const target = resolve(www, ref);
      let path;
      if (m[1] === "script")
        path = target === join(www, "embed.js") ? "embed.js" : entryOut.get(target);
      else if (/\brel="stylesheet"/.test(m[0])) path = await sitePath(target);
      else continue;
      if (!path) throw new Error(`dist: ${page}: no output for ${ref}`);
      jobs.push([m[0], m[0].replace(`"${ref}"`, `"${path.split(sep).join("/")}"`)]);
    }
    let rewritten = html;
    for (const [whole, replacement] of jobs) rewritten = rewritten.replace(whole, replacement);
    await writeFile(join(next, page), rewritten);
  }
  await Promise.all([...emitted.values()]);

  // The licences of the vendored libraries (minified copies keep only their banner comments).
  const vendor = join(www, "vendor");
  await mkdir(join(next, "licenses"), { recursive: true });
  for (const lib of await readdir(vendor))
    if (existsSync(join(vendor, lib, "LICENSE")))
      await copyFile(join(vendor, lib, "LICENSE"), join(next, "licenses", `${lib}.txt`));

  await writeServiceWorker(next, www); // manifest, icons, sw.js (scripts/service-worker.mjs)
  const files = await listFiles(next);
  await compressAll(files);
  let bytes = 0;
  for (const f of files) bytes += (await stat(f)).size;
  await rm(out, { recursive: true, force: true });
  await mkdir(dirname(out), { recursive: true });
  await rename(next, out);
  return { files: files.length, bytes, elapsed: Date.now() - started };
}

/** Every file below `dir`. */
export async function listFiles(dir) {
  const found = [];
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) found.push(...(await listFiles(path)));
    else found.push(path);
  }
  return found;
}

const gzipAsync = promisify(gzip);
const brotliAsync = promisify(brotliCompress);

/**
 * Writes `<file>.gz` and `<file>.br` beside every file whose extension is in COMPRESSED. Brotli
 * at quality 11 is most of the build's time (~2.5 s of CPU for the site on an idle core, 10× that
 * on a busy machine), so both are kept in `cache` by the SHA-256 of what they compress; a rebuild
 * compresses only what changed, and the entries this build did not use are removed.
 */
async function compressAll(files, cache = CACHE) {
  await mkdir(cache, { recursive: true });
  const used = new Set();
  // One compression per content: two files with the same bytes (a lecture's first poster is its
  // demo's when the scene shows the default state) must not write the same `.part` at once.
  const making = new Map();
  const keep = (kept, make) => {
    if (!making.has(kept))
      making.set(
        kept,
        existsSync(kept)
          ? Promise.resolve()
          : make().then(async (bytes) => {
              await writeFile(`${kept}.part`, bytes);
              await rename(`${kept}.part`, kept);
            }),
      );
    return making.get(kept);
  };
  const text = files.filter((f) => COMPRESSED.has(extname(f)));
  await Promise.all(
    text.map(async (file) => {
      const body = await readFile(file);
      const key = createHash("sha256").update(body).digest("hex");
      for (const [ext, make] of [
        ["gz", () => gzipAsync(body, { level: 9 })],
        [
          "br",
          () =>
            brotliAsync(body, {
              params: {
                [constants.BROTLI_PARAM_QUALITY]: 11,
                [constants.BROTLI_PARAM_SIZE_HINT]: body.length,
                [constants.BROTLI_PARAM_MODE]:
                  extname(file) === ".wasm"
                    ? constants.BROTLI_MODE_GENERIC
                    : constants.BROTLI_MODE_TEXT,
              },
            }),
        ],
      ]) {
        const kept = join(cache, `${key}.${ext}`);
        used.add(`${key}.${ext}`);
        await keep(kept, make);
        // Another build pruning the cache meanwhile: compress it here.
        await copyFile(kept, `${file}.${ext}`).catch(async () =>
          writeFile(`${file}.${ext}`, await make()),
        );
      }
    }),
  );
  for (const name of await readdir(cache))
    if (!used.has(name)) await rm(join(cache, name), { force: true });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  console.log(postersSummary(await renderPosters()));
  const { files, bytes, elapsed } = await buildSite();
  console.log(
    `dist: ${files} files (${(bytes / 1024).toFixed(0)} KiB before .gz/.br) in ${relative(ROOT, SITE)}/, ${(elapsed / 1000).toFixed(1)} s`,
  );
}
