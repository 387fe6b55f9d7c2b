/**
 * The lecture player (ui.md "Lectures"): one scene at a time — a demo in lecture mode (large
 * type) with the scene's state, its caption under the figure, a thin progress bar "k / n".
 * A presentation clicker sends PageDown/PageUp, which always step; arrows and Space step too
 * unless a control or the figure has the focus (there they move handles and play animations);
 * Home/End go to the first/last scene, `B` blanks the screen (any key brings it back), `F`
 * toggles fullscreen, Escape leaves for the demo page with the scene's state.
 */
import { el, setText } from "./controls.js";
import { mountDemo, toolbarStandIn, validateState } from "./shell.js";
import { taskQueue } from "./task-queue.js";
import { warmShellFonts } from "./font-warmup.js";
import { prepareFigure } from "./three-loader.js";
import { findDemo, loadDemo } from "../demos/index.js";
import { lecturePosterName, loadingPoster, painted, posterPage, posterSettled } from "./posters.js";
import { locale, t } from "./strings.js";
import { buildHash } from "./state.js";
import { errorText } from "./core-errors.js";

/** A caption in the active language, else English. */
export function captionOf(scene) {
  const caption = scene.caption ?? {};
  return caption[locale()] ?? caption.en ?? "";
}

/** Narrower windows (phones) show scenes without lecture mode's large type (CSS px). */
const LECTURE_TYPE_MIN_WIDTH = 900;
/**
 * Projection type (×1.6) on a projector-sized window; a phone keeps the normal size, where the
 * large type would crowd the figure.
 */
export const largeType = () => window.innerWidth >= LECTURE_TYPE_MIN_WIDTH;

/** Keys that step scenes wherever the focus is (a clicker's). */
const CLICKER = { PageDown: 1, PageUp: -1 };
/** Keys that step scenes unless a control or the figure has the focus. */
const STEPS = { ArrowRight: 1, ArrowDown: 1, " ": 1, ArrowLeft: -1, ArrowUp: -1 };

/** Whether keys pressed now belong to a demo's control or figure rather than to the player. */
function focusIsBusy(root) {
  const active = document.activeElement;
  if (!active || active === document.body || !root.contains(active)) return false;
  return active.matches("input, select, textarea, button, canvas, [tabindex], [contenteditable]");
}

/**
 * Plays `lecture` (its JSON) in `container` from scene `index` (0-based).
 * @param {object} options
 * @param {object} options.sl the initialised wasm package, or its promise (null: it failed):
 *   meanwhile the first scene's poster (built site) shows, with its caption.
 * @param {(index: number) => void} options.onScene called with each scene shown (the URL).
 * @param {(demoId: string, state: object) => void} options.onLeave Escape: open the demo page.
 * Returns `{ go(index), destroy() }`.
 */
export function playLecture(container, lecture, { sl, index = 0, onScene, onLeave }) {
  const scenes = lecture.scenes;
  const title = el("h1", { class: "lecture-title", text: t(`section.${lecture.section}`) });
  const counter = el("span", { class: "lecture-counter", "aria-live": "polite" });
  const bar = el("div", { class: "lecture-progress-bar" });
  const stage = el("div", { class: "lecture-stage" });
  const caption = el("p", { class: "lecture-caption" });
  const blank = el("div", { class: "lecture-blank", hidden: true, "aria-hidden": "true" });
  const prev = el("button", {
    class: "sl-button",
    type: "button",
    text: t("lecture.previous"),
    dataset: { action: "lecture-previous" },
    onclick: () => go(current - 1),
  });
  const next = el("button", {
    class: "sl-button",
    type: "button",
    text: t("lecture.next"),
    dataset: { action: "lecture-next" },
    onclick: () => go(current + 1),
  });
  const root = el(
    "div",
    { class: "lecture", role: "region", "aria-label": t("lecture.label") },
    el("div", { class: "lecture-head" }, title, prev, counter, next),
    el("div", { class: "lecture-progress", "aria-hidden": "true" }, bar),
    stage,
    blank,
  );
  container.append(root);

  let current = -1;
  let controller = null;
  /** The first scene's poster is on the stage (built site). */
  let posterShown = false;
  let loading = 0; // bumped per go(): a scene whose demo loaded late is not shown

  async function go(target) {
    const k = Math.max(0, Math.min(scenes.length - 1, target));
    if (k === current && controller) return;
    const ticket = ++loading;
    const scene = scenes[k];
    if (!controller) showPoster(scene, k);
    let demo;
    let wasm;
    try {
      // After the poster's paint, as the wasm (at once when none is loading).
      demo = await posterSettled().then(() => loadDemo(scene.demo));
      await prepareFigure(demo, scene.state);
      wasm = await sl;
    } catch (err) {
      setText(caption, errorText(err));
      return;
    }
    if (ticket !== loading || !wasm) return;
    current = k;
    controller?.destroy();
    stage.replaceChildren();
    let problem = null;
    let state;
    try {
      state = validateState(demo, scene.state ?? {});
    } catch (err) {
      problem = errorText(err);
      state = validateState(demo, structuredClone(demo.defaultState));
    }
    const slot = el("div");
    stage.append(slot);
    // After the first scene's poster the mount is made in several short tasks (figure first).
    const later = posterShown ? taskQueue() : null;
    posterShown = false;
    controller = mountDemo(slot, demo, {
      later,
      sl: wasm,
      state,
      mode: "page",
      headingLevel: "h2",
      lecture: largeType(),
      shareUrl: (s) => new URL(buildHash(demo.id, s), location.href).href,
    });
    if (problem) controller.status(t("status.rejected", { message: problem }), "error");
    // The caption sits right under the figure (ui.md), inside the demo's layout.
    const figure = controller.element.querySelector(".sl-figure");
    if (figure) figure.after(caption);
    else stage.append(caption);
    setText(caption, captionOf(scene));
    showProgress(k);
    onScene?.(k);
  }

  /** Scene k's poster (a lecture's first scene, on the built site) and caption, until it mounts. */
  function showPoster(scene, k) {
    const entry = findDemo(scene.demo);
    const title = entry ? t(`${entry.strings}.title`) : "";
    const poster =
      entry &&
      posterPage(entry, {
        title,
        alt: t("gallery.thumbnailAlt", { title }),
        headingLevel: "h2",
        name: lecturePosterName(lecture.id, k),
        lecture: largeType(),
        toolbar: toolbarStandIn(),
      });
    if (!poster) return;
    const shown = painted(poster.image);
    loadingPoster(shown); // the wasm after it (app.js)
    // While the wasm loads, the fonts the scene's panels will set text in (font-warmup.js).
    shown.then(() => warmShellFonts(stage, { lecture: largeType() }));
    stage.replaceChildren(poster.element);
    poster.figure.after(caption);
    setText(caption, captionOf(scene));
    showProgress(k);
    poster.show();
    posterShown = true;
  }

  function showProgress(k) {
    setText(counter, t("lecture.counter", { k: k + 1, n: scenes.length }));
    bar.style.width = `${((k + 1) / scenes.length) * 100}%`;
    prev.disabled = k === 0;
    next.disabled = k === scenes.length - 1;
  }

  function onKey(event) {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    if (!blank.hidden) {
      blank.hidden = true; // any key brings the picture back
      event.preventDefault();
      return;
    }
    const typing = document.activeElement?.matches?.("input, select, textarea");
    const busy = focusIsBusy(root);
    let step = CLICKER[event.key];
    if (step === undefined && !busy) step = STEPS[event.key];
    if (step !== undefined) {
      event.preventDefault();
      go(current + step);
      return;
    }
    if (typing || busy) return;
    const key = event.key.toLowerCase();
    if (event.key === "Home") go(0);
    else if (event.key === "End") go(scenes.length - 1);
    else if (key === "b") blank.hidden = false;
    else if (key === "f") {
      if (document.fullscreenElement) document.exitFullscreen?.();
      else root.requestFullscreen?.().catch(() => {});
    } else if (event.key === "Escape" && controller)
      onLeave?.(scenes[current].demo, controller.state);
    else return;
    event.preventDefault();
  }
  document.addEventListener("keydown", onKey);
  go(index);

  return {
    lectureId: lecture.id,
    go,
    get index() {
      return current;
    },
    destroy() {
      document.removeEventListener("keydown", onKey);
      controller?.destroy();
      root.remove();
    },
  };
}
