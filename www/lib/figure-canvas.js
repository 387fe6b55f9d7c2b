/**
 * What the 2D `View` (view.js) and the 3D `View3D` (view3d.js) share: the figure's one canvas
 * (`.sl-canvas`, focusable, an image with an accessible name until handles make it an
 * application), its 2D renderer at the device pixel ratio, the once-per-frame drawing (hooks
 * first, then `drawNow()`), lecture mode, and the list of pointer interactors. A subclass
 * calls `super(host, options)`, sets up its own transform, then listens to input; it provides
 * `drawNow()`.
 */
import { CanvasRenderer } from "./draw.js";
import { currentTheme, LECTURE_SCALE } from "./theme.js";

export class FigureCanvas {
  /**
   * @param {HTMLElement} host the figure slot; the canvas fills it.
   * @param {object} o
   * @param {(r, view) => void} o.draw draws one frame (canvas and SVG alike).
   * @param {() => number[] | null} [o.bounds] the content's bounds (Fit).
   * @param {(window: number[]) => void} [o.onWindowChange] after a pan, zoom or orbit ends.
   * @param {string} [o.label] accessible name of the figure.
   * @param {boolean} [o.wheelNeedsModifier] embeds: the plain wheel scrolls the page.
   */
  constructor(
    host,
    { draw, bounds = null, onWindowChange = null, label = "", wheelNeedsModifier = false },
  ) {
    this.host = host;
    this.drawFigure = draw;
    this.bounds = bounds;
    this.onWindowChange = onWindowChange;
    this.wheelNeedsModifier = wheelNeedsModifier;

    this.canvas = document.createElement("canvas");
    this.canvas.className = "sl-canvas";
    this.canvas.setAttribute("role", "img");
    this.canvas.tabIndex = 0;
    this.canvas.style.touchAction = "none";
    this.setLabel(label);
    host.append(this.canvas);

    /** CSS size of the canvas. */
    this.width = 0;
    this.height = 0;
    this.pixelRatio = window.devicePixelRatio || 1;
    this.theme = currentTheme(host);
    this.lecture = false;
    this.renderer = new CanvasRenderer(this.canvas.getContext("2d"), {
      pixelRatio: this.pixelRatio,
      theme: this.theme,
    });

    this._interactors = [];
    this._captured = new Map(); // pointerId -> interactor that claimed it
    this._beforeFrame = [];
    this._beforeFrameLast = [];
    this._afterFrame = [];
    this._frameRequested = false;
    this._frame = () => this._onFrame();
    this._destroyed = false;
  }

  /** Sets the accessible name of the figure (only touches the DOM when it changes). */
  setLabel(text) {
    if (this._label !== text) {
      this._label = text;
      this.canvas.setAttribute("aria-label", text);
    }
  }

  /** Lecture mode: text and strokes ×1.6. */
  setLecture(on) {
    this.lecture = on;
    this.renderer.scale = on ? LECTURE_SCALE : 1;
    this.requestDraw();
  }

  /**
   * Registers a hook run at the start of each animation frame, before drawing (coalesced input).
   * `last`: after every hook registered without it, whenever they were registered (the demo
   * runtime's refresh reads what the handles', controls' and demo's hooks wrote).
   */
  beforeFrame(hook, last = false) {
    (last ? this._beforeFrameLast : this._beforeFrame).push(hook);
  }

  /**
   * Registers a hook run at the end of each animation frame, after drawing: the page's own
   * updates (panels, tables), so the canvas draws against a document whose style is clean
   * (measuring text would otherwise recompute it) and the DOM is laid out once per frame.
   */
  afterFrame(hook) {
    this._afterFrame.push(hook);
  }

  /** Asks for one redraw at the next animation frame; many requests make one draw. */
  requestDraw() {
    if (this._frameRequested || this._destroyed) return;
    this._frameRequested = true;
    requestAnimationFrame(this._frame);
  }

  /**
   * Holds the figure's drawing: frames and resizes draw nothing until `release()`, which asks
   * for the frame they would have drawn. For a mount made in several tasks behind a poster
   * (lib/demo.js), whose figure exists a task before its model is refreshed.
   */
  hold() {
    this._held = true;
  }

  /** Ends `hold()`: the figure is drawn at the next frame. */
  release() {
    this._held = false;
    this.requestDraw();
  }

  _onFrame() {
    this._frameRequested = false;
    if (this._destroyed || this._held) return;
    for (const hook of this._beforeFrame) hook();
    for (const hook of this._beforeFrameLast) hook();
    this.drawNow();
    for (const hook of this._afterFrame) hook();
  }

  /**
   * Adds an interactor `{ pointerDown(event, x, y) → boolean, pointerMove(event, x, y),
   * pointerUp(event, x, y), hover(x, y, pointerType) → cursor | null, leave() }`; x, y are
   * canvas CSS px. The first whose pointerDown returns true owns that pointer until it is up.
   * `before` (an interactor already added) puts the new one ahead of it, `first: true` ahead of
   * all added earlier: a band or plot made after the handles still claims its presses first.
   */
  addInteractor(interactor, { first = false, before = null } = {}) {
    const at = before ? this._interactors.indexOf(before) : -1;
    if (first) this._interactors.unshift(interactor);
    else if (at >= 0) this._interactors.splice(at, 0, interactor);
    else this._interactors.push(interactor);
  }

  /** Canvas CSS px of a pointer event (border included, as the canvas box starts after it). */
  eventPosition(event) {
    const rect = this.canvas.getBoundingClientRect();
    return [
      event.clientX - rect.left - this.canvas.clientLeft,
      event.clientY - rect.top - this.canvas.clientTop,
    ];
  }
}
