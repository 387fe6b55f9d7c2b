/**
 * The common demo layout and its plumbing (ui.md "Demo view"): title and toolbar (undo, redo,
 * reset, fit, lecture, share link, export SVG/PNG/JSON, import), the figure (≥ 60 % of the
 * width), the side panel of controls, a status line (role="status"), the formula panel, then
 * *What you see* / *Try this*. The shell owns the state history, validation, the view window,
 * exports and imports; the demo only draws and reports changes. The gallery page, the embed
 * element and the tests all mount demos through `mountDemo`.
 */
import { History, exportJson, parseJsonFile, STATE_VERSION } from "./state.js";
import { View } from "./view.js";
import { View3D } from "./view3d.js";
import {
  download,
  figureToPng,
  figureToSvg,
  figureToTikz,
  jsonBlob,
  svgBlob,
  texBlob,
} from "./export.js";
import { keepView, viewFits } from "./figure-kind.js";
import { el, button } from "./controls.js";
import { formatNumber, has, t } from "./strings.js";
import { prefersReducedMotion } from "./theme.js";
import { mountDeclared, validateDeclared } from "./demo.js";
import { errorText } from "./core-errors.js";

/** Info messages clear themselves after this many ms; errors stay until replaced. */
const INFO_MESSAGE_MS = 8000;
/**
 * Imported JSON files above this many bytes are refused before they are read: a state is a few
 * kilobytes (a 1000-point curve ~30 KB), and reading and validating megabytes would freeze the
 * page.
 */
export const MAX_IMPORT_BYTES = 1024 ** 2;
const ONE_DECIMAL = Object.freeze({ maximumFractionDigits: 1, useGrouping: false });
/** Most "Try this" items a demo may list (strings `<prefix>.try1` … `.tryN`). */
const MAX_TRY_ITEMS = 6;

/**
 * A full state (defaults for missing fields) from untrusted input, validated; throws an Error
 * naming the bad field. `view` is the shell's own field and is checked here.
 */
export function validateState(demo, candidate) {
  const validate = (s) => validateDeclared(demo, s);
  let state = candidate;
  if (state !== null && typeof state === "object" && !Array.isArray(state)) {
    state = { ...structuredClone(demo.defaultState), ...state };
  }
  if (state && typeof state === "object" && "view" in state) {
    const { view, ...rest } = state;
    // A 3D figure's `view` is its camera (camera3d.js), a 2D one's the world window; a demo
    // with both figures drops a view of the other kind (figure-kind.js).
    if (typeof demo.dimension !== "function") keepView(demo, rest, view);
    validate(rest);
    if (typeof demo.dimension === "function" && !keepView(demo, rest, view)) state = rest;
  } else {
    validate(state);
  }
  return state;
}

/** The toolbar's buttons: key (words `toolbar.<key>` and `toolbar.<key>.title`) → action name. */
const TOOLS = {
  undo: "undo",
  redo: "redo",
  reset: "reset",
  fit: "fit",
  lecture: "lecture",
  share: "share",
  svg: "export-svg",
  tikz: "export-tikz",
  png: "export-png",
  json: "export-json",
  import: "import",
};

/** The toolbar laid out in its groups from `buttons` (by TOOLS key) and the import's file input. */
function toolbarOf(buttons, fileInput) {
  return el(
    "div",
    { class: "sl-toolbar", role: "toolbar", "aria-label": t("toolbar.label") },
    el(
      "span",
      { class: "sl-tool-group" },
      buttons.undo,
      buttons.redo,
      buttons.reset,
      buttons.fit,
      buttons.lecture,
    ),
    el("span", { class: "sl-tool-group" }, buttons.share),
    el(
      "span",
      { class: "sl-tool-group" },
      el("span", { class: "sl-tool-label", text: t("toolbar.export") }),
      buttons.svg,
      buttons.tikz,
      buttons.png,
      buttons.json,
    ),
    el("span", { class: "sl-tool-group" }, buttons.import, fileInput),
  );
}

/**
 * The toolbar as a poster page shows it (lib/posters.js `posterPage`) until the demo mounts:
 * the same words, so it wraps as the demo's will and the poster sits where the figure will be;
 * inert (nothing to press yet), undo and redo greyed as in a fresh demo.
 */
export function toolbarStandIn() {
  const buttons = Object.fromEntries(
    Object.keys(TOOLS).map((key) => [key, button({ label: t(`toolbar.${key}`) })]),
  );
  buttons.undo.disabled = true;
  buttons.redo.disabled = true;
  const bar = toolbarOf(buttons, null);
  bar.inert = true;
  bar.removeAttribute("role");
  bar.removeAttribute("aria-label");
  return bar;
}

/**
 * Mounts `demo` inside `root` (emptied first).
 * @param {HTMLElement | ShadowRoot} root
 * @param {object} demo a module of www/demos/ (see lib/README.md).
 * @param {object} options
 * @param {object} options.sl the initialised wasm package.
 * @param {object} options.state initial state, already validated (see validateState).
 * @param {"page" | "embed"} [options.mode] embeds fold the about text and need Ctrl for wheel zoom.
 * @param {(state: object) => void} [options.onCommit] after every recorded change (page: URL hash).
 * @param {(state: object) => string} options.shareUrl the link that restores a state.
 * @param {string} [options.headingLevel] "h1" on the playground page, "h2" in embeds.
 * @param {boolean} [options.lecture] start in lecture mode (large type; a lecture's scenes).
 * @param {"full" | "minimal" | "none"} [options.controls] a course page's choice: everything;
 *   the figure with Reset, Fit and Share link only; or the figure alone (shell.css).
 * @param {"auto" | "light" | "dark"} [options.theme] a course page's colours: the reader's
 *   preference, or always light / dark (figures read it through `currentTheme(node)`).
 * @param {((fn: Function) => void) | null} [options.later] a staged mount (lib/task-queue.js,
 *   while a poster covers the figure): the figure now, the controls, the formula panel with the
 *   demo's tables, and the about section each in a later task.
 * @returns {{ state: object, accept: Function, status: Function, destroy: Function,
 *   figure: View | null, element: HTMLElement }}
 */
export function mountDemo(
  root,
  demo,
  {
    sl,
    state,
    mode = "page",
    onCommit = () => {},
    shareUrl,
    headingLevel = "h2",
    lecture = false,
    controls = "full",
    theme = "auto",
    later = null,
  },
) {
  const prefix = demo.strings;
  const history = new History(state);
  let figure = null;
  let statusTimer = 0;

  // ------------------------------------------------------------------ layout
  const status = el("div", { class: "sl-status", role: "status", "aria-live": "polite" });
  const figureHost = el("div", { class: "sl-figure" });
  const helpId = `sl-help-${demo.id}-${Math.random().toString(36).slice(2, 8)}`;
  /** The help under the figure: how to turn a 3D one, drag handles, or what a typed one shows. */
  const noPoints3d = Array.isArray(demo.figure3d?.handles) && demo.figure3d.handles.length === 0;
  const helpKey = (is3d) =>
    (!is3d && demo.figure?.help) ||
    (is3d
      ? noPoints3d
        ? "shell.figureHelp3dTyped"
        : "shell.figureHelp3d"
      : demo.figure?.handles || !demo.figure
        ? "shell.figureHelp"
        : "shell.figureHelpTyped");
  const help = el("p", { class: "sl-help", id: helpId, text: t(helpKey(Boolean(demo.figure3d))) });
  const panel = el("div", { class: "sl-panel", role: "group", "aria-label": t("shell.controls") });
  const formula = el("div", { class: "sl-formula" });
  const details = el("div", { class: "sl-details" });
  const fileInput = el("input", {
    type: "file",
    accept: ".json,application/json",
    hidden: true,
    class: "sl-import-input",
    "aria-hidden": "true",
    tabindex: "-1",
  });

  /** A toolbar button: its words are `toolbar.<key>` and `toolbar.<key>.title`. */
  const tool = (key, name, onClick, extra = {}) =>
    button({
      label: t(`toolbar.${key}`),
      title: t(`toolbar.${key}.title`),
      name,
      onClick,
      ...extra,
    });
  const actions = {
    undo: () => undo(),
    redo: () => redo(),
    reset: () => reset(),
    fit: () => fit(),
    lecture: () => toggleLecture(),
    share: () => share(),
    svg: () => exportSvg(),
    tikz: () => exportTikz(),
    png: () => exportPng(),
    json: () => exportState(),
    import: () => fileInput.click(),
  };
  const buttons = Object.fromEntries(
    Object.entries(TOOLS).map(([key, name]) => [
      key,
      tool(key, name, actions[key], key === "lecture" ? { pressed: false } : {}),
    ]),
  );
  const toolbar = toolbarOf(buttons, fileInput);

  // The about section's headings sit one level under the title (h1 → h2, h2 → h3): no skipped level.
  const subHeading = `h${Math.min(6, Number(headingLevel.slice(1)) + 1)}`;
  const tryItems = [];
  for (let i = 1; i <= MAX_TRY_ITEMS && has(`${prefix}.try${i}`); i++)
    tryItems.push(el("li", { text: t(`${prefix}.try${i}`) }));
  const about =
    mode === "page"
      ? el(
          "section",
          { class: "sl-about" },
          el(subHeading, { text: t("shell.whatYouSee") }),
          el("p", { text: t(`${prefix}.whatYouSee`) }),
          el(subHeading, { text: t("shell.tryThis") }),
          el("ul", {}, tryItems),
        )
      : null;

  // A staged mount shows what is under the panel once the panel is made (no layout shift).
  const below = el("div", { class: "sl-below", hidden: Boolean(later) }, status, formula, details);
  const element = el(
    "section",
    {
      class: `sl-demo sl-mode-${mode} sl-controls-${controls}`,
      dataset: { demo: demo.id },
      "data-sl-theme": theme === "light" || theme === "dark" ? theme : null,
    },
    el(
      "header",
      { class: "sl-head" },
      el(headingLevel, { class: "sl-title", text: t(`${prefix}.title`) }),
      toolbar,
    ),
    el(
      "div",
      { class: "sl-body" },
      el("div", { class: "sl-figure-wrap" }, figureHost, help),
      panel,
      below,
    ),
    later ? null : about,
  );
  root.replaceChildren(element);

  // ------------------------------------------------------------------ status
  function showStatus(message, kind = "info") {
    clearTimeout(statusTimer);
    status.textContent = message;
    status.dataset.kind = kind;
    if (kind === "info" && message)
      statusTimer = setTimeout(() => (status.textContent = ""), INFO_MESSAGE_MS);
  }

  // ------------------------------------------------------------------ state plumbing
  /** The current window, written into every state the demo reports. */
  let currentWindow = state.view ?? null;
  const withView = (s) => (currentWindow ? { ...s, view: currentWindow } : s);

  function refreshButtons() {
    buttons.undo.disabled = !history.canUndo;
    buttons.redo.disabled = !history.canRedo;
  }

  /** Applies the state's window to the figure, or fits one and stores it. */
  function syncWindow() {
    if (!figure) return;
    const s = history.current;
    if (s.view && viewFits(Boolean(figure.is3d), s.view)) {
      currentWindow = s.view;
      figure.setWindow(s.view);
    } else {
      // A 3D figure starts from its declared direction of view (`figure3d.camera`).
      currentWindow = figure.home ? figure.home() : figure.fit();
      history.replace({ ...s, view: currentWindow });
    }
  }

  /**
   * Validates and shows an outside state (URL, file, attribute, reset); on success records it.
   * On failure the message goes to the status area and the last good state stays. Returns
   * true when accepted.
   */
  function accept(candidate, { errorKey = "status.rejected", name = "" } = {}) {
    let next;
    try {
      next = validateState(demo, candidate);
    } catch (err) {
      showStatus(t(errorKey, { message: errorText(err), name }), "error");
      return false;
    }
    const previous = history.current;
    try {
      instance.update(next);
    } catch (err) {
      // The wasm constructors validate again; keep the page alive on their refusal too.
      showStatus(t(errorKey, { message: errorText(err), name }), "error");
      try {
        instance.update(previous);
      } catch {
        // previous was good before; nothing more to do
      }
      return false;
    }
    history.commit(next);
    syncWindow();
    refreshButtons();
    onCommit(history.current);
    return true;
  }

  function undo() {
    const s = history.undo();
    if (!s) return showStatus(t("status.nothingToUndo"));
    showHistory(s);
  }

  function redo() {
    const s = history.redo();
    if (!s) return showStatus(t("status.nothingToRedo"));
    showHistory(s);
  }

  /** An undone or redone state; a figure of the other kind made for it records its view. */
  function showHistory(s) {
    const before = figure;
    instance.update(s);
    if (figure !== before) recordWindow();
    refreshButtons();
    onCommit(history.current);
  }

  /** Writes the shown window into the current state (after the figure was made anew). */
  function recordWindow() {
    if (JSON.stringify(history.current.view) === JSON.stringify(currentWindow)) return;
    history.replace({ ...history.current, view: currentWindow });
    onCommit(history.current);
  }

  function reset() {
    accept(structuredClone(demo.defaultState));
  }

  function fit() {
    if (!figure) return;
    currentWindow = figure.fit();
    history.replace({ ...history.current, view: currentWindow });
    onCommit(history.current);
  }

  function toggleLecture() {
    const on = buttons.lecture.getAttribute("aria-pressed") !== "true";
    buttons.lecture.setAttribute("aria-pressed", String(on));
    element.classList.toggle("sl-lecture", on);
    figure?.setLecture(on);
  }

  async function share() {
    const url = shareUrl(history.current);
    try {
      await navigator.clipboard.writeText(url);
      showStatus(t("status.linkCopied"));
    } catch {
      showStatus(t("status.linkShown", { url }));
    }
  }

  function exportSvg() {
    if (!figure) return;
    const name = `${demo.id}.svg`;
    download(svgBlob(figureToSvg(figure)), name);
    showStatus(t("status.exported", { name }));
  }

  function exportTikz() {
    if (!figure) return;
    const name = `${demo.id}.tex`;
    download(texBlob(figureToTikz(figure, t(`${prefix}.title`))), name);
    showStatus(t("status.exported", { name }));
  }

  async function exportPng() {
    if (!figure) return;
    const name = `${demo.id}.png`;
    await figure.prepareExport?.(); // a 3D figure's WebGL image is drawn on the page
    download(await figureToPng(figure), name);
    showStatus(t("status.exported", { name }));
  }

  function exportState() {
    const name = `${demo.id}.json`;
    download(jsonBlob(exportJson(demo.id, history.current)), name);
    showStatus(t("status.exported", { name }));
  }

  fileInput.addEventListener("change", async () => {
    const file = fileInput.files?.[0];
    fileInput.value = "";
    if (!file) return;
    const name = file.name;
    if (file.size > MAX_IMPORT_BYTES) {
      const size = formatNumber(file.size / 1024 ** 2, ONE_DECIMAL);
      const max = formatNumber(MAX_IMPORT_BYTES / 1024 ** 2, ONE_DECIMAL);
      showStatus(t("status.importTooLarge", { name, size, max }), "error");
      return;
    }
    try {
      const candidate = parseJsonFile(await file.text(), demo.id);
      if (accept(candidate, { errorKey: "status.badImport", name }))
        showStatus(t("status.imported", { name }));
    } catch (err) {
      showStatus(t("status.badImport", { name, message: errorText(err) }), "error");
    }
  });

  // Ctrl+Z / Ctrl+Shift+Z (and Ctrl+Y) anywhere in the demo, except in text boxes (their own undo).
  const onKeyDown = (event) => {
    if (!(event.ctrlKey || event.metaKey) || event.altKey) return;
    const target = event.composedPath()[0];
    if (target?.tagName === "INPUT" && target.type === "text") return;
    const key = event.key.toLowerCase();
    if (key === "z" && !event.shiftKey) undo();
    else if ((key === "z" && event.shiftKey) || key === "y") redo();
    else return;
    event.preventDefault();
  };
  element.addEventListener("keydown", onKeyDown);

  // ------------------------------------------------------------------ the demo
  const ctx = {
    sl,
    mode,
    later,
    reducedMotion: prefersReducedMotion(),
    slots: { figure: figureHost, controls: panel, formula, details },
    t,
    /**
     * Creates the demo's View in the figure slot (the shell handles its window and exports).
     * Called again (a demo with both figures whose `dimension` changed), it replaces the figure:
     * `options.window` is shown when it is a view of the new kind, else the figure fits.
     */
    createFigure(options) {
      const replacing = figure !== null;
      // Focus on the old canvas moves to the new one (a keyboard user stays in the figure).
      const focused = replacing && figure.canvas.matches(":focus");
      figure?.destroy();
      const Figure = options.scene ? View3D : View;
      figure = new Figure(figureHost, {
        ...options,
        wheelNeedsModifier: mode === "embed",
        onWindowChange: (win) => {
          currentWindow = win;
          history.replace({ ...history.current, view: win });
          onCommit(history.current);
        },
      });
      figure.canvas.setAttribute("aria-describedby", helpId);
      help.textContent = t(helpKey(Boolean(options.scene)));
      if (replacing) {
        if (focused) figure.canvas.focus({ preventScroll: true });
        if (element.classList.contains("sl-lecture")) figure.setLecture(true);
        if (viewFits(Boolean(figure.is3d), options.window)) figure.setWindow(options.window);
        currentWindow = viewFits(Boolean(figure.is3d), options.window)
          ? options.window
          : figure.home
            ? figure.home()
            : figure.fit();
      }
      return figure;
    },
    /** Writes the figure's window into the current state (a figure made anew later). */
    recordWindow: () => recordWindow(),
    /** A change in progress (drag, animation frame): shown, not recorded (copied, as `commit`). */
    preview(next) {
      history.preview(withView(structuredClone(next)));
    },
    /**
     * A finished change: recorded for undo and the URL. `merge` joins repeated key presses.
     * The shell keeps its own copy, so a demo hands over its working state as it is.
     */
    commit(next, merge = null) {
      if (history.commit(withView(structuredClone(next)), merge)) {
        refreshButtons();
        onCommit(history.current);
      }
    },
    /** Shows a message in the status area ("error" messages stay). */
    status: showStatus,
    /** Fits the figure to its content and records the window (the Fit button). */
    fit: () => fit(),
  };

  const instance = mountDeclared(demo, history.current, ctx);
  syncWindow();
  refreshButtons();
  if (lecture) toggleLecture();
  // A staged mount's about section and what is under the panel come last, so nothing shown
  // moves while the panels are made.
  later?.(() => {
    below.hidden = false;
    if (about) element.append(about);
  });

  return {
    element,
    get state() {
      return history.current;
    },
    get figure() {
      return figure;
    },
    accept,
    undo,
    redo,
    status: showStatus,
    version: STATE_VERSION,
    destroy() {
      clearTimeout(statusTimer);
      element.removeEventListener("keydown", onKeyDown);
      instance.destroy();
      figure?.destroy();
      element.remove();
    },
  };
}
