// The offline part of `make dist` (issue 26; the worker itself is www/sw.js, whose header says
// how it caches and updates). scripts/dist.mjs calls, while the site is still being written:
// - SERVICE_WORKER_DEFINE, in esbuild's `define`: the worker's URL as the bundles in assets/ see
//   it, which makes www/lib/offline.js register it (in development it stays undefined);
// - writeServiceWorker(site): copies the web app manifest and its icons to the site root under
//   their own names (the manifest names them, an installed app keeps its manifest URL), then
//   writes `sw.js` at the root: www/sw.js with BUILD filled in, i.e. the precache list and a
//   version that is the hash of every listed path with its content, so any change to the site
//   makes a new worker and a new cache. sw.js is unhashed; hosts must send it no-cache (as
//   scripts/serve.mjs does for every unhashed file).
import { createHash } from "node:crypto";
import { copyFile, mkdir, readFile, readdir, writeFile } from "node:fs/promises";
import { join, relative, sep } from "node:path";

/** The worker's URL from assets/ (where every bundle lives): `sw.js` at the site root. */
export const SERVICE_WORKER_DEFINE = { SPLINELAB_SERVICE_WORKER: JSON.stringify("../sw.js") };
/** What the manifest brings along from www/ (www/index.html links it). */
const MANIFEST = "manifest.webmanifest";
const ICONS = "icons";
/** The line of www/sw.js the build replaces. */
const BUILD_LINE = /^const BUILD = \{ version: "dev", files: \[\] \};$/m;

/** Every file below `dir`, as site paths ("a/b.js"). */
async function sitePaths(dir, root = dir) {
  const found = [];
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) found.push(...(await sitePaths(path, root)));
    else found.push(relative(root, path).split(sep).join("/"));
  }
  return found;
}

/**
 * Whether the worker precaches `path`: the whole site but the licences (texts nobody needs
 * offline), the worker itself, and the KaTeX fonts' .woff and .ttf: every browser the wasm runs
 * in (README: Chrome/Edge 91, Firefox 89, Safari 16.4) takes the .woff2 listed first in KaTeX's
 * @font-face, so the other two would triple the fonts' share of the precache for nothing (they
 * stay on the host, fetched if ever asked for).
 */
export function precached(path) {
  if (path === "sw.js" || path.startsWith("licenses/") || /\.(gz|br)$/.test(path)) return false;
  return !/\.(woff|ttf)$/.test(path);
}

/** Writes the manifest, icons and sw.js into `site` (from `www`); resolves to { version, files }. */
export async function writeServiceWorker(site, www) {
  await copyFile(join(www, MANIFEST), join(site, MANIFEST));
  await mkdir(join(site, ICONS), { recursive: true });
  for (const name of await readdir(join(www, ICONS)))
    await copyFile(join(www, ICONS, name), join(site, ICONS, name));

  const files = (await sitePaths(site)).filter(precached).sort();
  const source = await readFile(join(www, "sw.js"), "utf8");
  if (!BUILD_LINE.test(source)) throw new Error("dist: www/sw.js has no BUILD line to fill in");
  // The worker's own code counts too: a changed worker gets a fresh cache.
  const version = createHash("sha256").update(source);
  /** SHA-256 (hex) of each file whose name does not say its content: the worker checks what it
   * fetched against them, so a host or CDN still sending an old page cannot mix versions. */
  const digests = {};
  for (const path of files) {
    const digest = createHash("sha256")
      .update(await readFile(join(site, path)))
      .digest("hex");
    version.update(`${path}\0${digest}\n`);
    if (!path.startsWith("assets/")) digests[path] = digest;
  }
  const build = { version: version.digest("hex").slice(0, 16), files, digests };
  await writeFile(
    join(site, "sw.js"),
    source.replace(BUILD_LINE, () => `const BUILD = ${JSON.stringify(build)};`),
  );
  return build;
}
