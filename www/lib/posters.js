/**
 * Posters (issue 26): a picture of every demo's default state, drawn at build time by
 * scripts/posters.mjs into www/posters/ and content-hashed by `make dist`, shown where the
 * figure will be until the wasm has arrived and the live figure replaces it. The gallery's cards
 * show the thumbnails, so the gallery loads no wasm and no KaTeX.
 *
 * In the development tree (`make serve`) there are no hashed posters: `posterUrl` returns null
 * and the pages draw as before (live thumbnails, no poster).
 */
// No imports: boot.js loads this module before the rest of the page's.

/** A new `tag` element: `props` as lib/controls.js `el` takes them (class, text, dataset, attributes). */
function el(tag, props, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(props)) {
    if (key === "class") node.className = value;
    else if (key === "text") node.textContent = value;
    else if (key === "dataset") Object.assign(node.dataset, value);
    else node.setAttribute(key, value);
  }
  node.append(...children);
  return node;
}

/** A hashed site file (scripts/dist.mjs): `…/name-XXXXXXXX.svg`. */
const HASHED = /-[A-Z2-7]{8}\.svg$/;
/** Containers at most this many rem wide use the narrow layout (lib/shell.css @container). */
const NARROW_REM = 46;
/** A page at most this wide has a demo container that narrow (main's padding, style.css). */
export const NARROW_PAGE = "(max-width: 50rem)";

/** The longest the wasm waits for the poster. */
const POSTER_WAIT_MS = 3000;
let posterLoad = Promise.resolve();
let bootPicture = null;

/**
 * Set by boot.js to the poster it is loading (`promise`: until it is painted) and its `<img>`:
 * the wasm waits for it (`posterSettled`), so on a slow link the poster (the first frame) does
 * not share the bandwidth with the ~270 KB wasm.
 */
export function loadingPoster(promise, picture = null) {
  // Not longer than POSTER_WAIT_MS: a poster stuck on the way must not hold the wasm back.
  const limit = new Promise((resolve) => setTimeout(resolve, POSTER_WAIT_MS));
  posterLoad = Promise.race([promise.catch(() => {}), limit]);
  bootPicture = picture;
}

/**
 * The `<img>` of boot.js's poster (arrived or still on the way) if it is demo `id`'s, once: the
 * poster page shows it as it is (`show(picture)`) rather than ask again.
 */
export function bootPoster(id) {
  const picture = bootPicture?.dataset.demo === id ? bootPicture : null;
  bootPicture = null;
  return picture;
}

/** Resolves once the poster boot.js asked for has arrived or failed (at once when none). */
export function posterSettled() {
  return posterLoad;
}

/** The reader's colour scheme is dark (the figures' theme when no page forces one: lib/theme.js). */
export const prefersDark = () =>
  typeof matchMedia === "function" && matchMedia("(prefers-color-scheme: dark)").matches;

/**
 * The URL of poster `shape` ("wide", "narrow" or "thumb") of demo `id` in the light or the dark
 * theme (default: the reader's colour scheme, as the live figure will be), or null (none built).
 */
export function posterUrl(id, shape, dark = prefersDark()) {
  // One placeholder: make dist makes it a lookup table of the files in posters/.
  const name = `${id}-${shape}${dark ? "-dark" : ""}`;
  const url = new URL(`../posters/${name}.svg`, import.meta.url).href;
  return HASHED.test(url) ? url : null;
}

/**
 * A short fingerprint of a link's encoded state (its `s`, lib/state.js `encodeState`): the
 * 32-bit FNV-1a hash of its characters, in hex. The build records the default state's
 * (scripts/posters.mjs); a page compares a link's with it, without the state itself.
 */
export function stateFingerprint(encoded) {
  let h = 0x811c9dc5;
  for (let i = 0; i < encoded.length; i++) h = Math.imul(h ^ encoded.charCodeAt(i), 0x01000193);
  return (h >>> 0).toString(16).padStart(8, "0");
}

/**
 * Whether demo `id`'s posters show the state of a link whose `s` is `encoded`: yes without one
 * (the default state), or when it is the default state's own encoding (a copied link of a demo
 * nobody changed), which `make dist` records by its fingerprint (SPLINELAB_POSTER_STATES, an
 * esbuild `define`: scripts/dist.mjs). A link to any other state gets no poster, so the reader
 * never sees a figure the link did not ask for: the live one appears as soon as it can, as in
 * an embed whose attributes change the state.
 */
export function posterShowsState(id, encoded) {
  if (!encoded) return true;
  if (typeof SPLINELAB_POSTER_STATES === "undefined") return false;
  return (
    Object.hasOwn(SPLINELAB_POSTER_STATES, id) &&
    SPLINELAB_POSTER_STATES[id] === stateFingerprint(encoded)
  );
}

/** True when the site has posters (the built site; the development tree has none). */
export function hasPosters() {
  return posterUrl("de-casteljau", "thumb") !== null;
}

/**
 * The page a demo will have, with its poster where the figure will be: the same classes as
 * lib/shell.js `mountDemo` (`.sl-demo` › `.sl-head` › title, `.sl-body` › `.sl-figure`), so the
 * figure's box has the live figure's size. Null when the site has no such poster. `entry` is the
 * manifest entry (demos/index.js), `title` and `alt` the words to show, `name` the poster's
 * (`entry.id`, or a lecture scene's: `lecturePosterName`), `lecture` the large type of a
 * lecture's scene, `toolbar` the demo's toolbar as it will be (lib/shell.js `toolbarStandIn`),
 * so the figure's box is where the live one will be.
 */
export function posterPage(
  entry,
  {
    title,
    alt,
    headingLevel = "h1",
    mode = "page",
    name = entry.id,
    lecture = false,
    toolbar = null,
  },
) {
  if (!posterUrl(name, "wide")) return null;
  const img = el("img", { class: "sl-poster", alt, decoding: "async", fetchpriority: "high" });
  const box = el("div", { class: `sl-figure${entry.tall ? " sl-figure-tall" : ""}` }, img);
  const section = el(
    "section",
    {
      class: `sl-demo sl-mode-${mode} sl-controls-full sl-poster-page${lecture ? " sl-lecture" : ""}`,
      dataset: { demo: entry.id },
    },
    el(
      "header",
      { class: "sl-head" },
      el(headingLevel, { class: "sl-title", text: title }),
      ...(toolbar ? [toolbar] : []),
    ),
    el("div", { class: "sl-body" }, el("div", { class: "sl-figure-wrap" }, box)),
  );
  return {
    element: section,
    figure: box,
    image: img,
    /**
     * Shows `picture`, a poster `<img>` of this page's shape already made (boot.js's, arrived
     * or on the way), moved into the box as it is: nothing is fetched or decoded again and no
     * layout is read. Without one, the poster of the box's shape (call once the element is in
     * the document: its width is read).
     */
    show(picture = null) {
      if (picture) {
        picture.className = img.className;
        picture.alt = img.alt;
        img.replaceWith(picture);
        this.image = picture;
        return;
      }
      const rem = Number.parseFloat(getComputedStyle(document.documentElement).fontSize) || 16;
      const narrow = section.clientWidth <= NARROW_REM * rem;
      img.src = posterUrl(name, narrow ? "narrow" : "wide");
    },
  };
}

/**
 * A live figure drawn some time after its mount (a 3D one waits for the rendering worker's
 * first frame: View3D `whenDrawn`) keeps `image`, the poster shown before it, over its canvas
 * until then instead of an empty box; decorative meanwhile (the canvas carries the figure's
 * name). Nothing happens for a figure drawn at once (a 2D one) or a poster not loaded.
 */
export function coverUntilDrawn(figure, image) {
  if (!image?.complete || !image.naturalWidth || !figure?.whenDrawn) return;
  image.alt = "";
  image.className = "sl-poster sl-poster-cover";
  figure.host.append(image);
  figure.whenDrawn().then(() => image.remove());
}

/**
 * The poster name of scene `index` (0-based) of lecture `lectureId`: the build draws each
 * lecture's first scene (scripts/posters.mjs), the scene a lecture link opens.
 */
export function lecturePosterName(lectureId, index) {
  return `lecture-${lectureId}-${index + 1}`;
}

/**
 * The poster name of the scene a lecture link opens (`scene`: its 1-based number, absent for
 * the first), or null when the build drew none: with one, lib/lecture.js shows it and the
 * scene's caption before the wasm loads.
 */
export function lectureLinkPoster(lectureId, scene) {
  const name = lecturePosterName(lectureId, Math.max(0, (Number(scene) || 1) - 1));
  return posterUrl(name, "wide") ? name : null;
}

/** Whether the browser reports largest-contentful-paint entries (Chromium; not Safari). */
const REPORTS_LCP =
  typeof PerformanceObserver === "function" &&
  (PerformanceObserver.supportedEntryTypes ?? []).includes("largest-contentful-paint");
/** The longest `painted` waits, after the poster's frame, for the browser to report its paint. */
const LCP_REPORT_WAIT_MS = 500;
/** Input after which the browser reports no more largest paints. */
const INPUT_EVENTS = ["pointerdown", "keydown", "wheel"];

/**
 * Resolves once `image` has been painted (or failed): for `loadingPoster`, so the wasm's
 * request starts after the first frame's paint (for Lighthouse's simulation, a request started
 * before the page's largest paint is one that paint waited for). Where the browser reports the
 * largest contentful paint, once it reports `image`'s: the frame after the load is not enough,
 * since the time the browser gives the paint can be a later frame's (in traces of Lighthouse's
 * loads, the one after app.js's first layout, ~100 ms on), and that time is what counts. Not
 * longer than LCP_REPORT_WAIT_MS after that frame (a larger paint may come first), nor after the
 * reader's first input (none is reported after it).
 */
export function painted(image) {
  return new Promise((resolve) => {
    const observer = REPORTS_LCP
      ? new PerformanceObserver((list) => {
          const ours = (entry) => entry.element === image || (entry.url && entry.url === image.src);
          if (list.getEntries().some(ours)) done();
        })
      : null;
    const done = () => {
      observer?.disconnect();
      for (const type of INPUT_EVENTS) removeEventListener(type, done, true);
      resolve();
    };
    if (observer) {
      observer.observe({ type: "largest-contentful-paint", buffered: true });
      for (const type of INPUT_EVENTS)
        addEventListener(type, done, { capture: true, passive: true });
    }
    // The frame after the load, and where the browser reports paints, its report or the cap.
    const afterFrame = observer ? () => setTimeout(done, LCP_REPORT_WAIT_MS) : done;
    image.addEventListener("load", () => requestAnimationFrame(() => setTimeout(afterFrame)), {
      once: true,
    });
    image.addEventListener("error", done, { once: true });
  });
}
