/**
 * The playground page's first module (index.html loads it before app.js). Small and with one
 * small import, it runs while app.js's modules are still on the way: a demo, lecture or exercise
 * link asks for its poster (lib/posters.js) and then the wasm and its glue (fetched here,
 * compiled by lib/wasm.js as it streams), so both arrive while the rest of the JS loads. The gallery asks for nothing (its thumbnails are posters; no wasm).
 */
import {
  NARROW_PAGE,
  lectureLinkPoster,
  loadingPoster,
  painted,
  posterShowsState,
  posterUrl,
} from "./lib/posters.js";

const hash = new URLSearchParams(location.hash.slice(1));

/** Adds `<link rel=… href=…>` to the head (a hint the browser acts on at once). */
function hint(rel, href, extra = {}) {
  const link = document.createElement("link");
  link.rel = rel;
  link.href = href;
  for (const [key, value] of Object.entries(extra)) link.setAttribute(key, value);
  document.head.append(link);
}

/**
 * The poster in the page, where the demo will be (app.js keeps it until the demo is mounted;
 * its box has the poster's own shape, which is the live figure's at this width). Not when the
 * demo is already there.
 */
function showPoster(image) {
  const main = document.getElementById("main");
  if (!main || main.querySelector(".sl-demo, .sl-poster")) return;
  const page = document.createElement("div");
  page.className = "demo-page sl-boot-poster";
  page.append(image);
  main.append(page);
}

/** The wasm and its glue, asked for now (lib/wasm.js compiles the wasm as it streams in). */
function wasmHints() {
  hint("preload", new URL("./pkg/splinelab_bg.wasm", import.meta.url).href, {
    as: "fetch",
    type: "application/wasm",
    crossorigin: "",
  });
  hint("modulepreload", new URL("./pkg/splinelab.js", import.meta.url).href);
}

const id = hash.get("demo");
const lecture = hash.get("lecture");
const lecturePoster =
  lecture && /^[a-z0-9-]+$/.test(lecture) ? lectureLinkPoster(lecture, hash.get("scene")) : null;
/** The posters' shape for this window (lib/posters.js `posterPage` chooses the same). */
const shape = matchMedia(NARROW_PAGE).matches ? "narrow" : "wide";
// Not for a link to another state than the posters' (`posterShowsState`).
const poster =
  id && /^[a-z0-9-]+$/.test(id) && posterShowsState(id, hash.get("s"))
    ? posterUrl(id, shape)
    : null;
if (poster) {
  // The poster first (a few KB, the page's largest picture), shown as soon as it is here, then
  // the wasm (~270 KB): on a slow link the two would share the bandwidth and the poster come
  // late. The wasm is asked for after the frame that paints the poster (`painted`).
  const image = new Image();
  image.alt = "";
  image.className = "sl-poster";
  image.fetchPriority = "high";
  image.dataset.demo = id;
  image.onload = () => showPoster(image);
  loadingPoster(painted(image).then(wasmHints), image);
  image.src = poster;
} else if (lecturePoster) {
  // app.js shows the scene's poster and caption, then asks for the wasm (lib/lecture.js).
  hint("preload", posterUrl(lecturePoster, shape), { as: "image", fetchpriority: "high" });
} else if (hash.has("demo") || hash.has("lecture") || hash.has("exercise")) wasmHints();
