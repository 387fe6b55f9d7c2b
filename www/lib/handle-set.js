/**
 * What the 2D and 3D point handles (handles.js, handles3d.js) share: the selection, hover and
 * drag indices, the pointer position kept for the next frame, the figure turned from a picture
 * into an application with a polite live region for announcements, and the listeners a
 * subclass answers (`_key(event)`, `_focus(event)`, `_flush()` once per frame before drawing).
 */
import { NudgeGroups } from "./handle-keys.js";
import { t } from "./strings.js";

export class HandleSet {
  /**
   * @param {object} view a View or View3D.
   * @param {object} source the handles' points (`count()`, `get(i, out)`, `label(i)`, `select?(i)` …).
   * @param {string} selectedKey the strings.js key announcing a selection ("{label} … ").
   */
  constructor(view, source, selectedKey) {
    this.view = view;
    this.source = source;
    this.selected = -1;
    this.hovered = -1;
    this.dragging = -1;
    this._selectedKey = selectedKey;
    this._pending = new Float64Array(2); // the newest pointer position, applied once per frame
    this._hasPending = false;
    this._nudges = new NudgeGroups();

    const canvas = view.canvas;
    canvas.setAttribute("role", "application");
    canvas.setAttribute("aria-roledescription", t("handles.roleDescription"));
    this.announcer = document.createElement("div");
    this.announcer.className = "sl-announcer";
    this.announcer.setAttribute("aria-live", "polite");
    this.announcer.setAttribute("aria-atomic", "true");
    view.host.append(this.announcer);

    view.addInteractor(this);
    view.beforeFrame(() => this._flush());
    this._onKey = (e) => this._key(e);
    this._onFocus = (e) => this._focus(e);
    canvas.addEventListener("keydown", this._onKey);
    canvas.addEventListener("focus", this._onFocus);
  }

  /** Selects handle i (-1: none), announces it and redraws. */
  select(i) {
    const next = i >= 0 && i < this.source.count() ? i : -1;
    if (next === this.selected) return;
    this.selected = next;
    this.source.select?.(next);
    if (next >= 0) this._announce(this._selectedKey, next);
    this.view.requestDraw();
  }

  /** Says `text` in the figure's polite live region (a chained tool, e.g. the knot ruler). */
  announce(text) {
    this.announcer.textContent = text;
  }

  hover(x, y, pointerType) {
    const i = this.hitTest(x, y, pointerType);
    if (i !== this.hovered) {
      this.hovered = i;
      this.view.requestDraw();
    }
    return i >= 0 ? "grab" : null;
  }

  leave() {
    if (this.hovered >= 0) {
      this.hovered = -1;
      this.view.requestDraw();
    }
  }

  /** Forgets hover and drag state (the demo's points were replaced, e.g. by undo). */
  forgetPointer() {
    this.hovered = -1;
    this.dragging = -1;
    this._hasPending = false;
  }

  /** Removes the listeners and the live region (the view removes its own); the figure is a picture again. */
  destroy() {
    const canvas = this.view.canvas;
    canvas.removeEventListener("keydown", this._onKey);
    canvas.removeEventListener("focus", this._onFocus);
    canvas.setAttribute("role", "img");
    canvas.removeAttribute("aria-roledescription");
    this.announcer.remove();
  }
}
