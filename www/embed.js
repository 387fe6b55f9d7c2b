/**
 * `<spline-lab demo="de-casteljau" points="0,0 2,2 6,4 8,2" t="0.25">`: one demo in a course
 * page. Load this file as a module (`<script type="module" src=".../embed.js">`); put as many
 * elements on the page as you like. Each lives in its own shadow root (the page's CSS does not
 * leak in), the wasm package is loaded once per page, and a demo starts only when it comes
 * near the viewport, and then loads only its own demo module. Attributes are the demo's state
 * fields (see lib/attributes.js); changing an attribute later updates the figure.
 * `view="xmin ymin xmax ymax"` fixes the window. `controls="minimal"` keeps the figure with Reset,
 * Fit and Share link; `controls="none"` the figure alone (default "full"). `theme="light" |
 * "dark"` fixes the colours (default "auto": the reader's preference).
 * `exercise="<id>"` (exercises/index.js) shows that exercise around its demo instead of `demo`.
 * `lang="el" | "hr" | "it" | "en"` chooses the language. A page speaks one language in all its
 * embeds (the strings are one table per page), chosen once: the page's `?lang=` (a reader's
 * choice), else the `lang` of the first `<spline-lab>` that has one (the author's), else the
 * browser's languages, else English (`pageLanguage`).
 */
import { findDemo, loadDemo } from "./demos/index.js";
import { loadFailureMessage, loadWasm } from "./lib/wasm.js";
import { mountDemo, validateState } from "./lib/shell.js";
import { taskQueue } from "./lib/task-queue.js";
import { prepareFigure } from "./lib/three-loader.js";
import { stateFromAttributes } from "./lib/attributes.js";
import { buildHash, encodeState } from "./lib/state.js";
import { t } from "./lib/strings.js";
import { chooseLanguage, useLanguage } from "./lib/language.js";
import { findExercise } from "./exercises/index.js";
import { mountExercise } from "./lib/exercise.js";
import { errorText } from "./lib/core-errors.js";
import { coverUntilDrawn, posterUrl, prefersDark } from "./lib/posters.js";

const SHELL_CSS = new URL("./lib/shell.css", import.meta.url).href;
const PLAYGROUND = new URL("./index.html", import.meta.url).href;
/** The values of the `controls` attribute (anything else is "full"). */
const CONTROLS = ["full", "minimal", "none"];
/** Start a demo when it is this close to the viewport. */
const START_MARGIN = "200px";
/** Attributes that leave the demo's starting state as it is (any other may change it). */
const STATELESS = new Set(["demo", "controls", "theme", "lang", "id", "class", "style", "title"]);
/** An embed at most this many rem wide has the narrow layout (lib/shell.css @container). */
const NARROW_REM = 46;

const HOST_CSS = `
:host { display: block; margin: 1rem 0; }
:host([hidden]) { display: none; }
/* About the live embed's height (a full one is 50–73rem tall at 412–1350 px), so the text after
   it does not move when it comes; a minimal or bare one is mostly its figure. */
.sl-embed-placeholder {
  min-height: min(50rem, 100vh); display: grid; place-items: center; border: 1px dashed #8a8a8a;
  border-radius: 6px; color: #5a5a5a; font: 15px system-ui, sans-serif;
}
:host([controls="minimal"]) .sl-embed-placeholder, :host([controls="none"]) .sl-embed-placeholder {
  min-height: 16rem;
}
.sl-embed-placeholder:has(.sl-embed-poster) { place-items: start stretch; border: none; }
.sl-embed-poster { display: block; width: 100%; height: auto; }
.sl-embed-error { color: #b34f00; font: 600 15px system-ui, sans-serif; }
@media (prefers-color-scheme: dark) { .sl-embed-error { color: #e8772e; } }
.sl-embed-error::before { content: "⚠ "; }
`;

/** The language every embed of the page speaks, loaded once (see the header). */
let pageChoice = null;
function pageLanguage() {
  pageChoice ??= useLanguage(
    chooseLanguage(
      new URLSearchParams(location.search).get("lang") ??
        document.querySelector("spline-lab[lang]")?.getAttribute("lang"),
    ),
  );
  return pageChoice;
}

/** The element's own styles, one CSSStyleSheet for every embed of the page (made when needed). */
let hostSheet = null;

class SplineLabElement extends HTMLElement {
  connectedCallback() {
    if (!this.shadowRoot) {
      const shadow = this.attachShadow({ mode: "open" });
      // A constructed sheet, shared by every embed: no <style> element, so a page whose
      // Content-Security-Policy forbids inline styles still shows the element.
      hostSheet ??= new CSSStyleSheet();
      if (hostSheet.cssRules.length === 0) hostSheet.replaceSync(HOST_CSS);
      shadow.adoptedStyleSheets = [hostSheet];
      const link = document.createElement("link");
      link.rel = "stylesheet";
      link.href = SHELL_CSS;
      this._root = document.createElement("div");
      this._root.className = "sl-embed-placeholder";
      this._root.textContent = t("app.loading");
      shadow.append(link, this._root);
      this._showPoster();
    }
    if (this._controller || this._observer) return;
    this._observer = new IntersectionObserver(
      (entries) => {
        if (entries.some((e) => e.isIntersecting)) {
          this._observer.disconnect();
          this._observer = null;
          this._start();
        }
      },
      { rootMargin: START_MARGIN },
    );
    this._observer.observe(this);
  }

  disconnectedCallback() {
    this._observer?.disconnect();
    this._observer = null;
    this._attributes?.disconnect();
    this._controller?.destroy();
    this._controller = null;
    if (this._root) {
      this._root.className = "sl-embed-placeholder";
      this._root.textContent = t("app.loading");
    }
  }

  /**
   * The demo's poster (lib/posters.js: its default state, drawn at build time) in the
   * placeholder until the live figure comes, when no attribute may change that state; in the
   * theme the figure will have (the `theme` attribute's, else the reader's colour scheme).
   */
  _showPoster() {
    const id = this.getAttribute("demo");
    if (!id || !findDemo(id)) return;
    for (const name of this.getAttributeNames())
      if (!STATELESS.has(name) && !/^(aria|data)-/.test(name)) return;
    const rem = Number.parseFloat(getComputedStyle(document.documentElement).fontSize) || 16;
    const narrow = this.getBoundingClientRect().width <= NARROW_REM * rem;
    const theme = this.getAttribute("theme");
    const dark = theme === "dark" || (theme !== "light" && prefersDark());
    const url = posterUrl(id, narrow ? "narrow" : "wide", dark);
    if (!url) return;
    const img = document.createElement("img");
    img.className = "sl-embed-poster";
    img.alt = "";
    img.src = url;
    this._root.replaceChildren(img);
  }

  /** Loads the wasm (shared by the page) and the demo's module (shared too), then mounts the demo. */
  async _start() {
    // The wasm (fetched and compiled as it streams) while the language and the demo load.
    loadWasm().catch(() => {}); // reported below
    await pageLanguage();
    const exerciseId = this.getAttribute("exercise");
    const exercise = exerciseId === null ? null : findExercise(exerciseId);
    if (exerciseId !== null && !exercise)
      return this._fail(t("exercise.unknown", { id: exerciseId }));
    const id = exercise?.demo ?? this.getAttribute("demo") ?? "";
    if (!findDemo(id)) return this._fail(t("app.unknownDemo", { id }));
    let sl;
    let demo;
    try {
      sl = await loadWasm();
    } catch (err) {
      return this._fail(loadFailureMessage(err));
    }
    try {
      demo = await loadDemo(id);
    } catch (err) {
      return this._fail(errorText(err));
    }
    // An exercise starts from its own state; attributes may still change fields of it.
    const start = validateState(demo, structuredClone(exercise?.state ?? demo.defaultState));
    let state = start;
    let problem = null;
    try {
      state = validateState(demo, stateFromAttributes(this, start));
    } catch (err) {
      problem = errorText(err);
    }
    try {
      await prepareFigure(demo, state); // three.js, for a 3D state only
    } catch (err) {
      return this._fail(errorText(err));
    }
    if (!this.isConnected || this._controller) return;
    const poster = this._root.querySelector(".sl-embed-poster");
    const root = document.createElement("div");
    this._root.replaceWith(root);
    this._root = root;
    const controls = this.getAttribute("controls") ?? "full";
    const options = {
      sl,
      mode: "embed",
      controls: CONTROLS.includes(controls) ? controls : "full",
      theme: this.getAttribute("theme") ?? "auto",
      headingLevel: "h2",
      shareUrl: (s) =>
        exercise
          ? `${PLAYGROUND}#exercise=${exercise.id}&s=${encodeState(s)}`
          : `${PLAYGROUND}${buildHash(demo.id, s)}`,
    };
    // Behind a poster the demo's mount is made in several short tasks (figure first).
    const later = poster ? taskQueue() : null;
    const mount = (s) =>
      exercise
        ? mountExercise(root, exercise, demo, { ...options, state: s })
        : mountDemo(root, demo, { ...options, state: s, later });
    try {
      this._controller = mount(state);
    } catch (err) {
      problem = errorText(err); // refused by the wasm constructor: show the start instead
      this._controller = mount(start);
    }
    if (problem) this._controller.status(t("status.rejected", { message: problem }), "error");
    else coverUntilDrawn(this._controller.figure, poster);

    // Attribute edits after start update the figure (validated like any state).
    this._attributes = new MutationObserver(() => {
      try {
        this._controller?.accept(stateFromAttributes(this, start));
      } catch (err) {
        this._controller?.status(t("status.rejected", { message: errorText(err) }), "error");
      }
    });
    this._attributes.observe(this, { attributes: true });
  }

  _fail(message) {
    this._root.className = "sl-embed-error";
    this._root.setAttribute("role", "status");
    this._root.textContent = message;
  }
}

if (!customElements.get("spline-lab")) customElements.define("spline-lab", SplineLabElement);
