// Static file server on 127.0.0.1 (no dependencies): `make serve` (www/, development),
// `make serve-dist` (dist/site/, the built site) and the browser tests.
//   node scripts/serve.mjs [--port 8000] [--root www]
// - Sends application/wasm for .wasm and never serves outside its root.
// - Compression: a text file or the wasm goes out as brotli or gzip, whichever the browser
//   accepts (br first): the precompressed `<file>.br`/`<file>.gz` beside it when there is one
//   (`make dist` writes them), else compressed on the fly (remembered until the file changes).
// - Caching: a content-hashed file (`assets/<name>-XXXXXXXX.<ext>`, see scripts/dist.mjs) is
//   `public, max-age=31536000, immutable`; everything else (HTML, embed.js, all of www/) is
//   `no-cache` with an ETag, so a reload revalidates it and gets 304 when it has not changed.
import { createServer } from "node:http";
import { readFile, stat } from "node:fs/promises";
import { extname, join, normalize, relative, resolve, sep } from "node:path";
import { fileURLToPath } from "node:url";
import { promisify } from "node:util";
import { brotliCompress, constants, gzip } from "node:zlib";

const ROOT = resolve(fileURLToPath(new URL("../www", import.meta.url)));
const TYPES = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".mjs": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".json": "application/json",
  ".wasm": "application/wasm",
  ".svg": "image/svg+xml",
  ".png": "image/png",
  ".woff2": "font/woff2",
  ".woff": "font/woff",
  ".ttf": "font/ttf",
  ".ico": "image/x-icon",
  ".txt": "text/plain; charset=utf-8",
  ".md": "text/plain; charset=utf-8",
  ".webmanifest": "application/manifest+json",
};
/** The types worth compressing (fonts and images are compressed already). */
const COMPRESSIBLE = new Set([".html", ".js", ".mjs", ".css", ".json", ".wasm", ".svg", ".txt"]);
/** A file scripts/dist.mjs named by its content, under assets/. */
export const HASHED = /^assets\/(?:[^/]+\/)*[^/]+-[A-Z2-7]{8}\.[a-z0-9]+$/;
export const IMMUTABLE = "public, max-age=31536000, immutable";
const ON_THE_FLY = {
  br: promisify((body, done) =>
    brotliCompress(body, { params: { [constants.BROTLI_PARAM_QUALITY]: 5 } }, done),
  ),
  gzip: promisify((body, done) => gzip(body, { level: 6 }, done)),
};
/** On-the-fly results kept (file, size, mtime, encoding → body); cleared when it grows past this. */
const CACHE_BYTES = 64 * 1024 * 1024;

/** The encodings `header` (Accept-Encoding) allows, in the order we prefer them. */
function accepted(header = "") {
  const allowed = new Set();
  for (const part of header.split(",")) {
    const [name, ...params] = part.trim().toLowerCase().split(";");
    const q = params.find((p) => p.trim().startsWith("q="));
    if (!q || Number(q.trim().slice(2)) > 0) allowed.add(name.trim());
  }
  return ["br", "gzip"].filter((e) => allowed.has(e));
}

const fail = (code, message) => Object.assign(new Error(message), { code });

/**
 * Starts the server; resolves to the node http.Server once it listens. Port 0 picks a free one;
 * `root` (www/ by default) is the only folder it serves.
 */
export function startServer(port = 8000, host = "127.0.0.1", root = ROOT) {
  root = resolve(root);
  const cache = new Map();
  let cached = 0;

  /** The body to send for `file` (info: its stat) in `encoding`, or null to send it as it is. */
  async function encoded(file, info, encoding) {
    const pre = await stat(`${file}.${encoding === "gzip" ? "gz" : "br"}`).catch(() => null);
    if (pre?.isFile()) return readFile(`${file}.${encoding === "gzip" ? "gz" : "br"}`);
    const key = `${file}\0${info.size}\0${info.mtimeMs}\0${encoding}`;
    if (!cache.has(key)) {
      const body = await ON_THE_FLY[encoding](await readFile(file));
      if (cached + body.length > CACHE_BYTES) {
        cache.clear();
        cached = 0;
      }
      cache.set(key, body);
      cached += body.length;
    }
    return cache.get(key);
  }

  const server = createServer(async (req, res) => {
    try {
      if (req.method !== "GET" && req.method !== "HEAD") throw fail(405, "method not allowed");
      const url = new URL(req.url, "http://localhost");
      let path = normalize(decodeURIComponent(url.pathname));
      if (path.endsWith("/") || path.endsWith(sep)) path += "index.html";
      const file = resolve(join(root, path));
      if (file !== root && !file.startsWith(root + sep)) throw fail(403, "forbidden");
      const info = await stat(file).catch(() => null);
      if (!info?.isFile()) throw fail(404, "not found");
      const ext = extname(file);
      const name = relative(root, file).split(sep).join("/");
      const headers = {
        "content-type": TYPES[ext] ?? "application/octet-stream",
        "cache-control": HASHED.test(name) ? IMMUTABLE : "no-cache",
      };
      let encoding = null;
      if (COMPRESSIBLE.has(ext)) {
        headers.vary = "Accept-Encoding";
        encoding = accepted(req.headers["accept-encoding"])[0] ?? null;
      }
      const etag = `W/"${info.size.toString(36)}-${Math.floor(info.mtimeMs).toString(36)}${encoding ? `-${encoding}` : ""}"`;
      headers.etag = etag;
      headers["last-modified"] = info.mtime.toUTCString();
      if (req.headers["if-none-match"] === etag) {
        res.writeHead(304, headers);
        res.end();
        return;
      }
      const body = encoding ? await encoded(file, info, encoding) : await readFile(file);
      if (encoding) headers["content-encoding"] = encoding;
      headers["content-length"] = body.length;
      res.writeHead(200, headers);
      res.end(req.method === "HEAD" ? undefined : body);
    } catch (err) {
      const code = [403, 404, 405].includes(err.code) ? err.code : 500;
      res.writeHead(code, {
        "content-type": "text/plain; charset=utf-8",
        "cache-control": "no-cache",
      });
      res.end(code === 500 ? "server error" : err.message);
    }
  });
  return new Promise((ok, failed) => {
    server.once("error", failed);
    server.listen(port, host, () => ok(server));
  });
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const option = (name) => {
    const i = process.argv.indexOf(name);
    return i > 0 ? process.argv[i + 1] : undefined;
  };
  const port = Number(option("--port") ?? process.env.PORT ?? 8000);
  const root = resolve(option("--root") ?? ROOT);
  const server = await startServer(port, "127.0.0.1", root);
  console.log(
    `splinelab: serving ${relative(process.cwd(), root) || "."}/ on http://127.0.0.1:${server.address().port}/`,
  );
}
