/**
 * The playground page: the gallery (no hash) and a demo view (`#demo=<id>&s=<state>`).
 * The state of the open demo is written back into the hash after every recorded change
 * (history.replaceState, so the back button is not flooded); a pasted or edited link is
 * validated and, if bad, reported while the last good picture stays.
 */
import { demos, findDemo, loadDemo } from "./demos/index.js";
import { loadFailureMessage, loadWasm, loadedWasm } from "./lib/wasm.js";
import { mountDemo, toolbarStandIn, validateState } from "./lib/shell.js";
import { prepareFigure } from "./lib/three-loader.js";
import { warmShellFonts } from "./lib/font-warmup.js";
import { parseHash, buildHash, decodeState, encodeState } from "./lib/state.js";
import { figureToCanvas } from "./lib/export.js";
import { el } from "./lib/controls.js";
import { t } from "./lib/strings.js";
import { LANGUAGES, chooseLanguage, useLanguage, withLanguage } from "./lib/language.js";
import { findLecture, lectures, loadLecture } from "./lectures/index.js";
import { playLecture } from "./lib/lecture.js";
import { exercises, findExercise } from "./exercises/index.js";
import { mountExercise } from "./lib/exercise.js";
import { currentTheme, onThemeChange } from "./lib/theme.js";
import { errorText } from "./lib/core-errors.js";
import { registerOffline } from "./lib/offline.js";
import { now, taskQueue } from "./lib/task-queue.js";
import {
  bootPoster,
  coverUntilDrawn,
  hasPosters,
  lectureLinkPoster,
  posterPage,
  posterSettled,
  posterShowsState,
  posterUrl,
} from "./lib/posters.js";

/**
 * Gallery thumbnails: shown at THUMB_WIDTH × THUMB_HEIGHT CSS px, drawn as a figure of
 * THUMB_FIGURE_WIDTH × … CSS px (so labels keep the room they have in a demo, instead of
 * crowding a small figure) scaled down to 2 image pixels per shown CSS pixel.
 */
const THUMB_WIDTH = 320;
const THUMB_HEIGHT = 200;
const THUMB_FIGURE_WIDTH = 480;
const THUMB_FIGURE_HEIGHT = (THUMB_FIGURE_WIDTH * THUMB_HEIGHT) / THUMB_WIDTH;
const THUMB_SCALE = (2 * THUMB_WIDTH) / THUMB_FIGURE_WIDTH;
/** Syllabus sections, in gallery order. */
const SECTIONS = [1, 2, 3, 4, 5, 6, 7];
/** A card's demo module is loaded and its thumbnail drawn when the card is this near the viewport. */
const THUMB_MARGIN = "300px";

const main = document.getElementById("main");
const appStatus = main.querySelector(".app-status");
let controller = null; // the mounted demo (shell controller)
let player = null; // the lecture being played (lib/lecture.js)
let currentId = null;
let lastHash = null; // the hash this page wrote itself (its hashchange is not news)
let stopThemeWatch = () => {}; // the gallery's colour-scheme listener and thumbnail observer
let routeCount = 0; // bumped by every route(): a demo that finished loading late is not shown
let early = null; // { id, load }: a lecture link's lecture, fetched while the wasm loads (start)
let wasmLoad = null; // the wasm package's promise (null on failure), made when a page first needs it

/**
 * The wasm package, loaded when a page first needs it: a demo, lecture or exercise link starts
 * it before anything else (start), the gallery of the built site never (its thumbnails are
 * posters), the development tree's gallery for its live thumbnails. Resolves to null after
 * reporting a failure.
 */
function wasm() {
  // After the poster boot.js is loading, if any (the first frame first).
  wasmLoad ??= posterSettled()
    .then(loadWasm)
    .then(
      (sl) => sl,
      (err) => {
        showAppStatus(loadFailureMessage(err), "error");
        return null;
      },
    );
  return wasmLoad;
}

function showAppStatus(message, kind = "info") {
  appStatus.textContent = message;
  appStatus.dataset.kind = kind;
}

/** Writes the state into the hash without a new history entry. */
function writeHash(id, state) {
  lastHash = buildHash(id, state);
  history.replaceState(null, "", lastHash);
}

/** The link that restores `state` of demo `id`. */
function shareUrl(id, state) {
  return new URL(buildHash(id, state), location.href).href;
}

function unmount() {
  stopThemeWatch();
  stopThemeWatch = () => {};
  player?.destroy();
  player = null;
  controller?.destroy();
  controller = null;
  currentId = null;
  main.querySelectorAll(".gallery, .demo-page").forEach((node) => node.remove());
}

// ------------------------------------------------------------------ gallery
async function showGallery(sl) {
  unmount();
  document.title = t("app.galleryTitle", { app: t("app.name"), heading: t("gallery.heading") });
  const page = el(
    "div",
    { class: "gallery" },
    el("h1", { text: t("gallery.heading") }),
    el("p", { class: "gallery-intro", text: t("app.tagline") }),
  );
  for (const section of SECTIONS) {
    const members = demos.filter((entry) => entry.section === section);
    const lecture = lectures.find((l) => l.section === section);
    const practice = exercises.some((e) => e.section === section);
    if (!members.length && !lecture && !practice) continue;
    page.append(el("h2", { text: t(`section.${section}`) }));
    if (lecture) {
      page.append(
        el(
          "p",
          { class: "section-lecture" },
          el("a", {
            href: `#lecture=${lecture.id}`,
            "data-lecture": lecture.id,
            text: t("gallery.lecture"),
          }),
        ),
      );
    }
    for (const exercise of exercises.filter((e) => e.section === section)) {
      page.append(
        el(
          "p",
          { class: "section-exercise" },
          el("a", {
            href: `#exercise=${exercise.id}`,
            "data-exercise": exercise.id,
            text: t("gallery.exercise", { title: t(`exercise.${exercise.id}.title`) }),
          }),
        ),
      );
    }
    if (members.length) {
      page.append(
        el(
          "ul",
          { class: "cards" },
          members.map((entry) => card(entry)),
        ),
      );
    }
  }
  main.append(page);
  if (!hasPosters() && sl) stopThemeWatch = watchThumbnails(page, sl);
  else if (hasPosters()) stopThemeWatch = onThemeChange(() => themeThumbnails(page));
}

/** The built gallery's thumbnails in the reader's colour scheme again, after it changed. */
function themeThumbnails(page) {
  for (const img of page.querySelectorAll("img.card-thumb[src]")) {
    const poster = posterUrl(img.dataset.demo, "thumb");
    if (poster) img.src = poster;
  }
}

/**
 * Thumbnails are a nicety drawn lazily: a card's demo module is imported when the card comes
 * near the viewport, then its default state is drawn into the card's image. A colour-scheme
 * change redraws the cards already drawn. Returns the function that stops both watches.
 */
function watchThumbnails(page, sl) {
  const shown = new Set(); // images whose card has come near the viewport
  let stopped = false;
  const draw = async (img) => {
    let demo;
    try {
      demo = await loadDemo(img.dataset.demo);
    } catch {
      return; // leave the placeholder; opening the demo reports the failure
    }
    if (stopped) return;
    try {
      // three.js for a 3D demo's card, drawn on the page (a 2D card loads none)
      await prepareFigure(demo, demo.defaultState, { exports: true });
      if (stopped) return;
      img.src = thumbnail(demo, sl);
      img.classList.remove("placeholder");
    } catch {
      // leave the placeholder (or the previous picture)
    }
  };
  const observer = new IntersectionObserver(
    (entries) => {
      for (const entry of entries) {
        if (!entry.isIntersecting || shown.has(entry.target)) continue;
        shown.add(entry.target);
        observer.unobserve(entry.target);
        draw(entry.target);
      }
    },
    { rootMargin: THUMB_MARGIN },
  );
  for (const img of page.querySelectorAll("img.card-thumb")) observer.observe(img);
  const stopTheme = onThemeChange(() => shown.forEach(draw));
  return () => {
    stopped = true;
    observer.disconnect();
    stopTheme();
  };
}

/** A gallery card: the words come from the manifest's string keys, the picture comes later. */
function card(entry) {
  const title = t(`${entry.strings}.title`);
  const poster = posterUrl(entry.id, "thumb");
  const img = el("img", {
    class: "card-thumb placeholder",
    alt: t("gallery.thumbnailAlt", { title }),
    width: String(THUMB_WIDTH),
    height: String(THUMB_HEIGHT),
    loading: poster ? "lazy" : null,
    decoding: "async",
    dataset: { demo: entry.id },
  });
  if (poster) {
    img.addEventListener("load", () => img.classList.remove("placeholder"), { once: true });
    img.src = poster;
  }
  return el(
    "li",
    {},
    el(
      "a",
      { class: "card", href: buildHash(entry.id), dataset: { demo: entry.id } },
      img,
      el(
        "span",
        { class: "card-body" },
        el("span", { class: "card-title", text: title }),
        el("span", { class: "card-line", text: t(`${entry.strings}.summary`) }),
      ),
    ),
  );
}

/** A PNG data URL of the demo module's default state, rendered off-screen through the normal mount. */
function thumbnail(demo, sl) {
  const holder = document.createElement("div");
  const temp = mountDemo(holder, demo, {
    sl,
    state: validateState(demo, structuredClone(demo.defaultState)),
    mode: "embed",
    shareUrl: () => "",
  });
  try {
    return figureToCanvas(
      temp.figure,
      THUMB_SCALE,
      THUMB_FIGURE_WIDTH,
      THUMB_FIGURE_HEIGHT,
      currentTheme(),
    ).toDataURL("image/png");
  } finally {
    temp.destroy();
  }
}

// ------------------------------------------------------------------ demo view
/**
 * The state a link gives (`encoded`, the hash's `s=`), validated over `start`; when there is
 * none, `start` itself; a bad link keeps `start` and says why in `linkError`.
 */
function stateFromLink(demo, start, encoded) {
  const fallback = validateState(demo, structuredClone(start));
  if (!encoded) return { state: fallback, linkError: null };
  try {
    return { state: validateState(demo, decodeState(encoded)), linkError: null };
  } catch (err) {
    return { state: fallback, linkError: errorText(err) };
  }
}

/** The state a link carries, unchecked (which figure to prepare), or undefined. */
function linkedState(encoded) {
  try {
    return encoded ? decodeState(encoded) : undefined;
  } catch {
    return undefined;
  }
}

/** A demo page in `main` (the link back to the gallery, then the slot returned for the demo). */
function demoPageRoot() {
  const root = el("div");
  main.append(
    el(
      "div",
      { class: "demo-page" },
      el("a", { class: "back", href: "#", text: t("app.backToGallery") }),
      root,
    ),
  );
  return root;
}

/**
 * Demo `entry`'s poster where its figure will be, with the page's title and toolbar around it,
 * while the wasm and the demo's module load (lib/posters.js; the built site only): the demo's
 * mount replaces it (unmount) without moving the figure. The picture boot.js asked for (shown
 * bare before the page's words were here, or still on the way) moves into it. False when there is
 * none (the development tree, or a link to another state than the poster's).
 */
function showPoster(entry) {
  // Not for a link to another state than the poster's (boot.js shows none either).
  if (!posterShowsState(entry.id, parseHash(location.hash).s)) return false;
  const boot = main.querySelector(".sl-boot-poster");
  if (!boot && main.querySelector(".sl-poster")) return true; // shown already
  const title = t(`${entry.strings}.title`);
  const poster = posterPage(entry, {
    title,
    alt: t("gallery.thumbnailAlt", { title }),
    toolbar: toolbarStandIn(),
  });
  if (!poster) return Boolean(boot);
  demoPageRoot().append(poster.element);
  // boot.js's picture itself (chosen for this width too), else the one for the box's width.
  poster.show(bootPoster(entry.id));
  boot?.remove();
  // While the wasm loads, the fonts the demo's panels will set text in (lib/font-warmup.js).
  posterSettled().then(() => warmShellFonts(main));
  return true;
}

/**
 * Shows the loaded module `demo` (manifest entry `entry`) with the state in `encoded`, if any.
 * Returns the mount's `later` (lib/task-queue.js), or `now` when it was made in one task.
 */
function showDemo(entry, demo, encoded, sl) {
  const poster = [...main.querySelectorAll("img.sl-poster")].find(
    (img) => !img.closest("[hidden]"),
  );
  unmount();
  currentId = demo.id;
  document.title = t("app.demoTitle", { title: t(`${entry.strings}.title`), app: t("app.name") });
  let { state, linkError } = stateFromLink(demo, demo.defaultState, encoded);
  const root = demoPageRoot();
  // Behind a poster the mount is made in several short tasks (figure first).
  const later = poster ? taskQueue() : null;
  try {
    controller = mountDemo(root, demo, {
      sl,
      state,
      mode: "page",
      headingLevel: "h1",
      onCommit: (s) => writeHash(demo.id, s),
      shareUrl: (s) => shareUrl(demo.id, s),
      later,
    });
  } catch (err) {
    // The wasm constructor refused a state that passed validation: fall back to the default.
    linkError = errorText(err);
    controller = mountDemo(root, demo, {
      sl,
      state: validateState(demo, structuredClone(demo.defaultState)),
      mode: "page",
      headingLevel: "h1",
      onCommit: (s) => writeHash(demo.id, s),
      shareUrl: (s) => shareUrl(demo.id, s),
    });
  }
  const shown = controller;
  (later ?? now)(() => controller === shown && writeHash(demo.id, controller.state));
  if (linkError) controller.status(t("status.badLink", { message: linkError }), "error");
  coverUntilDrawn(controller.figure, poster);
  return later ?? now;
}

// ------------------------------------------------------------------ lecture view
/**
 * Plays lecture `id` from scene `scene` (1-based, from the link); the scene follows in the hash.
 * The scene's poster and caption (lib/lecture.js) show before the wasm; if the wasm fails, the
 * gallery (with the failure reported).
 */
async function showLecture(id, scene) {
  const routed = routeCount;
  let lecture;
  try {
    lecture = await (early?.id === id ? early.load : loadLecture(id));
    early = null;
  } catch (err) {
    showAppStatus(errorText(err), "error");
    return;
  }
  if (routed !== routeCount) return;
  unmount();
  currentId = null;
  document.title = t("app.demoTitle", {
    title: t(`section.${lecture.section}`),
    app: t("app.name"),
  });
  const holder = el("div", { class: "demo-page lecture-page" });
  main.append(holder);
  const first = Math.max(0, Math.min(lecture.scenes.length - 1, (Number(scene) || 1) - 1));
  let wasmLoaded = () => {};
  const wasmLoading = new Promise((resolve) => {
    wasmLoaded = resolve;
  });
  player = playLecture(holder, lecture, {
    sl: wasmLoading,
    index: first,
    onScene: (k) => {
      lastHash = `#lecture=${encodeURIComponent(id)}&scene=${k + 1}`;
      history.replaceState(null, "", lastHash);
    },
    onLeave: (demoId, state) => {
      location.hash = buildHash(demoId, state);
    },
  });
  // Asked for now: after the first scene's poster, if playLecture showed one (posterSettled).
  const sl = await wasm();
  wasmLoaded(sl);
  if (!sl && routed === routeCount) await showGallery(null);
}

// ------------------------------------------------------------------ exercise view
/** Shows exercise `entry` with the state in `encoded` (else its starting state). */
async function showExercise(entry, encoded, sl) {
  const routed = routeCount;
  let demo;
  try {
    demo = await loadDemo(entry.demo);
    await prepareFigure(demo, linkedState(encoded) ?? entry.state);
  } catch (err) {
    showAppStatus(errorText(err), "error");
    return;
  }
  if (routed !== routeCount) return;
  unmount();
  document.title = t("app.demoTitle", {
    title: t(`exercise.${entry.id}.title`),
    app: t("app.name"),
  });
  const { state, linkError } = stateFromLink(demo, entry.state, encoded);
  const write = (s) => {
    lastHash = `#exercise=${encodeURIComponent(entry.id)}&s=${encodeState(s)}`;
    history.replaceState(null, "", lastHash);
  };
  const root = demoPageRoot();
  controller = mountExercise(root, entry, demo, {
    sl,
    state,
    mode: "page",
    headingLevel: "h1",
    onCommit: write,
    shareUrl: (s) => new URL(`#exercise=${entry.id}&s=${encodeState(s)}`, location.href).href,
  });
  write(controller.state);
  if (linkError) controller.status(t("status.badLink", { message: linkError }), "error");
}

// ------------------------------------------------------------------ routing
async function route() {
  const routed = ++routeCount;
  const { demo: id, s, lecture, scene, exercise } = parseHash(location.hash);
  // A demo opened from the gallery before the wasm is here: its poster meanwhile.
  const opening = id && !lecture && !exercise && currentId !== id ? findDemo(id) : null;
  if (opening && !loadedWasm() && !main.querySelector(".sl-poster")) {
    unmount();
    showPoster(opening);
  }
  if (lecture && !exercise && findLecture(lecture)) {
    // The lecture's first frame (its poster and caption) comes before the wasm.
    if (player && player.lectureId === lecture) {
      await wasm();
      if (routed === routeCount) player.go((Number(scene) || 1) - 1);
      return;
    }
    return showLecture(lecture, scene);
  }
  const sl = id || lecture || exercise || !hasPosters() ? await wasm() : null;
  if (routed !== routeCount) return;
  if (exercise) {
    const entry = findExercise(exercise);
    if (entry && sl) return showExercise(entry, s, sl);
    await showGallery(sl);
    if (!entry) showAppStatus(t("exercise.unknown", { id: exercise }), "error");
    return;
  }
  if (lecture && !findLecture(lecture)) {
    await showGallery(sl);
    showAppStatus(t("lecture.unknown", { id: lecture }), "error");
    return;
  }
  if (!id) return showGallery(sl);
  const entry = findDemo(id);
  if (!entry) {
    await showGallery(sl);
    showAppStatus(t("app.unknownDemo", { id }), "error");
    return;
  }
  if (!sl) return showGallery(sl);
  let demo;
  try {
    demo = await loadDemo(id);
    await prepareFigure(demo, linkedState(s)); // three.js, for a 3D state only
  } catch (err) {
    if (routed === routeCount) showAppStatus(errorText(err), "error");
    return;
  }
  if (routed !== routeCount) return; // another link was followed while this module loaded
  if (controller && currentId === id) {
    // Same demo, new link: validate and apply (no state: the starting picture); a bad one
    // keeps the current picture.
    try {
      controller.accept(s ? decodeState(s) : structuredClone(demo.defaultState), {
        errorKey: "status.badLink",
      });
    } catch (err) {
      controller.status(t("status.badLink", { message: errorText(err) }), "error");
    }
    writeHash(id, controller.state);
    return;
  }
  const whenMounted = showDemo(entry, demo, s, sl);
  window.scrollTo(0, 0);
  // Focus to the new page (a reader who followed a link) once it is mounted (behind a poster,
  // after the mount's last task) and laid out in a frame: focusing sooner forces that layout
  // inside a task (~25 ms, 100 at a phone's speed), and a staged mount's next parts undo it.
  whenMounted(() =>
    requestAnimationFrame(() =>
      setTimeout(() => {
        if (routed === routeCount) main.focus({ preventScroll: true });
      }),
    ),
  );
}

/**
 * The page in the chosen language (`?lang=`, else the browser's, else English): `<html lang>`,
 * the static texts marked `data-i18n`, and the language menu in the header, which reloads the
 * page with the new `?lang=` (the hash, so the demo and its state, stays).
 */
async function applyLanguage() {
  const code = await useLanguage(chooseLanguage(new URLSearchParams(location.search).get("lang")));
  document.documentElement.lang = code;
  for (const node of document.querySelectorAll("[data-i18n]"))
    node.textContent = t(node.dataset.i18n);
  const menu = el(
    "select",
    { class: "language-menu", "aria-label": t("app.language"), name: "language" },
    ...LANGUAGES.map((l) => el("option", { value: l.code, lang: l.code, text: l.name })),
  );
  menu.value = code;
  menu.addEventListener("change", () => location.assign(withLanguage(location.href, menu.value)));
  document.querySelector(".site-head").append(menu);
}

async function start() {
  // What the first frame needs first: a demo, lecture or exercise link fetches and compiles the
  // wasm (and the demo's module) while the language loads; its poster shows meanwhile.
  const { demo: id, lecture, scene, exercise } = parseHash(location.hash);
  const entry = id ? findDemo(id) : null;
  // (A lecture whose scene has a poster asks for it after the poster: showLecture.)
  const posterFirst = lecture && findLecture(lecture) && lectureLinkPoster(lecture, scene) !== null;
  if (id || (lecture && !posterFirst) || exercise || !hasPosters()) wasm();
  // The demo's module after the poster's paint too (at once without a poster): for Lighthouse's
  // simulation, a request started before the largest paint is one that paint waited for.
  if (entry) posterSettled().then(() => loadDemo(id).catch(() => {})); // reported by route
  if (lecture && findLecture(lecture)) {
    early = { id: lecture, load: loadLecture(lecture) };
    early.load.catch(() => {}); // reported by showLecture
  }
  await applyLanguage();
  document.querySelector(".site-foot").textContent = t("app.footer");
  if (!(entry && showPoster(entry)) && wasmLoad) {
    showAppStatus(t("app.loading"));
    wasmLoad.then((sl) => sl && showAppStatus(""));
  }
  await route();
  window.addEventListener("hashchange", () => {
    if (location.hash === lastHash) return;
    if (location.hash === "" || location.hash === "#") showAppStatus("");
    route().catch((err) => showAppStatus(errorText(err), "error"));
  });
  // Ctrl+Z / Ctrl+Shift+Z also work when nothing in the demo has focus.
  document.addEventListener("keydown", (event) => {
    if (!controller || !(event.ctrlKey || event.metaKey) || event.altKey) return;
    if (event.defaultPrevented) return; // the demo took it (its figure may have been replaced)
    if (document.activeElement !== document.body && document.activeElement !== main) return;
    const key = event.key.toLowerCase();
    if (key === "z") controller[event.shiftKey ? "redo" : "undo"]();
    else if (key === "y") controller.redo();
    else return;
    event.preventDefault();
  });
}

// The page the link asked for, then the offline worker (lib/offline.js waits for it).
const started = start();
started.catch((err) => {
  showAppStatus(errorText(err), "error");
  throw err; // reported in the console as before
});
registerOffline(started);
