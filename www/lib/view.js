/**
 * A 2D figure on a canvas: sharp on high-DPI screens, world ↔ screen transform with y up,
 * fit-to-content, pan (drag on empty space) and zoom (wheel, pinch), and an accessible name.
 *
 * The visible region is a world *window* `[xmin, ymin, xmax, ymax]` that is always shown whole
 * and centred, whatever the canvas aspect; the window (not a pixel transform) is what demos
 * store in their state, so a link restores the same picture at any size.
 *
 * Pointer input is routed through *interactors* (handles.js is one): on pointer down each gets
 * a chance to claim the pointer; unclaimed drags pan, two unclaimed pointers pinch-zoom.
 */
import { sizeCanvas, watchCanvasSize } from "./canvas-size.js";
import { FigureCanvas } from "./figure-canvas.js";
import { currentTheme, onThemeChange } from "./theme.js";

/** Empty space around the content when fitting, as a fraction of the content's size per side. */
const FIT_PADDING = 0.14;
/** Smallest world extent a fit produces (a single point still gets a usable window). */
const MIN_FIT_EXTENT = 1;
/** Zoom limits: the window's larger extent stays within these world sizes. */
const MIN_EXTENT = 1e-4;
const MAX_EXTENT = 1e6;
/** Wheel zoom: the window shrinks by exp(deltaY × rate); 100 px of wheel ≈ ×1.2. */
const WHEEL_ZOOM_RATE = 0.0018;
/** A pixel delta (DOM_DELTA_PIXEL) per wheel "line" when the browser reports lines. */
const WHEEL_LINE_PX = 16;
/** After the last wheel event, wait this long before reporting the new window (ms). */
const WHEEL_SETTLE_MS = 250;
/** Window coordinates stored in state keep this many significant digits (compact links). */
const WINDOW_DIGITS = 6;

/** No canvas area reserved outside the world window (see the `insets` option). */
const NO_INSETS = Object.freeze([0, 0, 0, 0]);

/**
 * Canvases narrower than this (CSS px at text scale 1: a phone) leave out secondary labels that
 * the demo's table or panel repeats; at that size a figure shrinks ~3× and they would cover it.
 */
export const NARROW_CANVAS_PX = 560;

/**
 * The `insets` option for fixed bands of `[top, right, bottom, left]` CSS px at text scale 1
 * (a caption above the figure, a strip below it) that grow with the text in lecture mode.
 * Returns one scratch array (no allocation per layout).
 */
export function scaledInsets(top, right, bottom, left) {
  const base = [top, right, bottom, left];
  const scratch = [0, 0, 0, 0];
  return (width, height, scale) => {
    for (let i = 0; i < 4; i++) scratch[i] = base[i] * scale;
    return scratch;
  };
}

/** Rounds to `WINDOW_DIGITS` significant digits. */
function roundWindowValue(value) {
  return Number(value.toPrecision(WINDOW_DIGITS));
}

export class View extends FigureCanvas {
  /**
   * @param {HTMLElement} host element that sets the figure's CSS size; the canvas fills it.
   * @param {object} options
   * @param {(renderer: object, view: View) => void} options.draw draws one frame.
   * @param {() => number[] | null} [options.bounds] world [xmin, ymin, xmax, ymax] of the content.
   * @param {(window: number[]) => void} [options.onWindowChange] called after a pan or zoom ends.
   * @param {string} [options.label] accessible name of the figure.
   * @param {boolean} [options.wheelNeedsModifier] true in embeds: plain wheel scrolls the page,
   *   Ctrl/⌘ + wheel (and trackpad pinch) zooms.
   * @param {(width: number, height: number, scale: number) => number[]} [options.insets] CSS px
   *   of the canvas kept free of the world window, `[top, right, bottom, left]`, for a canvas
   *   of width × height at text/stroke scale `scale` (1.6 in lecture mode: a strip of labels
   *   grows with it), e.g. a plot drawn in screen space below the figure; the window is shown
   *   whole and centred in the rest. Default: none.
   */
  constructor(
    host,
    {
      draw,
      bounds = null,
      onWindowChange = null,
      label = "",
      wheelNeedsModifier = false,
      insets = null,
    },
  ) {
    super(host, { draw, bounds, onWindowChange, label, wheelNeedsModifier });
    this.insets = insets;

    // Window centre and half extents (world units), and the derived transform.
    this._cx = 0;
    this._cy = 0;
    this._hw = 1;
    this._hh = 1;
    this._scale = 1;
    this._ox = 0;
    this._oy = 0;

    this._gestures = new Map(); // pointerId -> { x, y } for pan/pinch pointers
    this._pinchDistance = 0;
    this._wheelTimer = 0;

    this._listen();
  }

  // ---------------------------------------------------------------- transform

  /** Pixels per world unit. */
  get scale() {
    return this._scale;
  }
  /** World x → canvas CSS px. */
  sx(x) {
    return this._ox + x * this._scale;
  }
  /** World y → canvas CSS px (y up in the world, down on screen). */
  sy(y) {
    return this._oy - y * this._scale;
  }
  /** Canvas CSS px → world x. */
  wx(px) {
    return (px - this._ox) / this._scale;
  }
  /** Canvas CSS px → world y. */
  wy(py) {
    return (this._oy - py) / this._scale;
  }

  /** The window `[xmin, ymin, xmax, ymax]` that is guaranteed visible. */
  getWindow() {
    return [this._cx - this._hw, this._cy - this._hh, this._cx + this._hw, this._cy + this._hh];
  }

  /** Shows the world window `[xmin, ymin, xmax, ymax]` whole and centred. */
  setWindow(win) {
    const [x0, y0, x1, y1] = win;
    this._cx = (x0 + x1) / 2;
    this._cy = (y0 + y1) / 2;
    this._hw = Math.max((x1 - x0) / 2, MIN_EXTENT / 2);
    this._hh = Math.max((y1 - y0) / 2, MIN_EXTENT / 2);
    this._layout(this.width, this.height);
    this.requestDraw();
  }

  /**
   * Fits the window to `bounds` (or to `options.bounds()`), with padding; returns the window
   * (rounded, as it would be stored in state).
   */
  fit(bounds = this.bounds?.()) {
    if (!bounds) return this.getWindow();
    const [x0, y0, x1, y1] = bounds;
    const pad = FIT_PADDING * Math.max(x1 - x0, y1 - y0, MIN_FIT_EXTENT);
    const win = [x0 - pad, y0 - pad, x1 + pad, y1 + pad].map(roundWindowValue);
    this.setWindow(win);
    return win;
  }

  /** Computes the transform for a canvas of w × h CSS px. */
  _layout(w, h) {
    const [top, right, bottom, left] =
      this.insets?.(w || 1, h || 1, this.renderer?.scale ?? 1) ?? NO_INSETS;
    const width = Math.max(1, (w || 1) - left - right);
    const height = Math.max(1, (h || 1) - top - bottom);
    this._scale = Math.min(width / (2 * this._hw), height / (2 * this._hh));
    this._ox = left + width / 2 - this._cx * this._scale;
    this._oy = top + height / 2 + this._cy * this._scale;
  }

  // ---------------------------------------------------------------- drawing

  /** Draws immediately on the screen canvas. */
  drawNow() {
    if (!this.width || !this.height) return;
    this.renderer.theme = this.theme;
    this._layout(this.width, this.height);
    this.renderer.begin(this.width, this.height, this.theme.background);
    this.drawFigure(this.renderer, this);
    this.renderer.end();
  }

  /**
   * Draws the figure into another renderer (SVG recorder, export canvas, thumbnail) of
   * `width` × `height` CSS px with `theme`; the screen transform is restored afterwards.
   */
  renderTo(renderer, width, height, theme) {
    const savedTheme = this.theme;
    this.theme = theme;
    renderer.theme = theme;
    renderer.scale = this.renderer.scale;
    this._layout(width, height);
    renderer.begin(width, height, theme.background);
    this.drawFigure(renderer, this);
    renderer.end();
    this.theme = savedTheme;
    this._layout(this.width, this.height);
  }

  /**
   * Sizes the backing store to the CSS size × devicePixelRatio. `devicePixels` (from
   * ResizeObserver's device-pixel-content-box, when the browser has it) gives the exact pixel
   * count, so one canvas pixel is one screen pixel even at fractional CSS sizes.
   */
  _resize(cssWidth, cssHeight, devicePixels = null) {
    if (!sizeCanvas(this, cssWidth, cssHeight, devicePixels)) return;
    this._layout(this.width, this.height);
    // Draw at once: a resized canvas is blank until the next draw.
    if (!this._held) this.drawNow();
  }

  // ---------------------------------------------------------------- input

  _listen() {
    const c = this.canvas;
    this._handlers = {
      pointerdown: (e) => this._down(e),
      pointermove: (e) => this._move(e),
      pointerup: (e) => this._up(e),
      pointercancel: (e) => this._up(e),
      pointerleave: () => {
        for (const it of this._interactors) it.leave?.();
      },
      wheel: (e) => this._wheel(e),
    };
    for (const [type, handler] of Object.entries(this._handlers)) {
      c.addEventListener(type, handler, type === "wheel" ? { passive: false } : undefined);
    }

    this._stopSize = watchCanvasSize(this.canvas, {
      resize: (w, h, devicePixels) => this._resize(w, h, devicePixels),
      ratioChanged: () => this._resize(this.width, this.height),
    });

    this._stopTheme = onThemeChange(() => {
      this.theme = currentTheme(this.canvas);
      this.requestDraw();
    });
  }

  _down(event) {
    if (event.button !== undefined && event.button > 0) return;
    const [x, y] = this.eventPosition(event);
    for (const it of this._interactors) {
      if (it.pointerDown(event, x, y)) {
        this._captured.set(event.pointerId, it);
        this.canvas.setPointerCapture(event.pointerId);
        event.preventDefault();
        return;
      }
    }
    // Empty space: pan with one pointer, pinch with two.
    this._gestures.set(event.pointerId, { x, y });
    this.canvas.setPointerCapture(event.pointerId);
    this.canvas.style.cursor = "grabbing";
    if (this._gestures.size === 2) this._pinchDistance = this._gestureDistance();
    event.preventDefault();
  }

  _move(event) {
    const [x, y] = this.eventPosition(event);
    const owner = this._captured.get(event.pointerId);
    if (owner) {
      owner.pointerMove(event, x, y);
      return;
    }
    const gesture = this._gestures.get(event.pointerId);
    if (!gesture) {
      let cursor = null;
      for (const it of this._interactors) cursor ??= it.hover(x, y, event.pointerType);
      this.canvas.style.cursor = cursor ?? "";
      return;
    }
    if (this._gestures.size === 1) {
      this._cx -= (x - gesture.x) / this._scale;
      this._cy += (y - gesture.y) / this._scale;
    } else if (this._gestures.size === 2) {
      gesture.x = x;
      gesture.y = y;
      const distance = this._gestureDistance();
      if (this._pinchDistance > 0 && distance > 0) {
        const [mx, my] = this._gestureMidpoint();
        this._zoomAt(mx, my, distance / this._pinchDistance);
      }
      this._pinchDistance = distance;
      return;
    }
    gesture.x = x;
    gesture.y = y;
    this._layout(this.width, this.height);
    this.requestDraw();
  }

  /**
   * Hands pointer `pointerId`, claimed by an interactor, over to pan and pinch from canvas
   * point (x, y): a freehand pen whose one-finger stroke became a two-finger gesture
   * (sketch-pen.js) gives its finger back, so the second one pinches with it.
   */
  toGesture(pointerId, x, y) {
    if (!this._captured.delete(pointerId)) return;
    this._gestures.set(pointerId, { x, y });
  }

  _up(event) {
    const [x, y] = this.eventPosition(event);
    const owner = this._captured.get(event.pointerId);
    if (owner) {
      this._captured.delete(event.pointerId);
      owner.pointerUp(event, x, y);
      return;
    }
    if (this._gestures.delete(event.pointerId)) {
      this.canvas.style.cursor = "";
      this._pinchDistance = this._gestures.size === 2 ? this._gestureDistance() : 0;
      if (this._gestures.size === 0) this._reportWindow();
    }
  }

  _wheel(event) {
    if (this.wheelNeedsModifier && !event.ctrlKey && !event.metaKey) return;
    event.preventDefault();
    const [x, y] = this.eventPosition(event);
    const delta = event.deltaMode === 1 ? event.deltaY * WHEEL_LINE_PX : event.deltaY;
    this._zoomAt(x, y, Math.exp(-delta * WHEEL_ZOOM_RATE));
    clearTimeout(this._wheelTimer);
    this._wheelTimer = setTimeout(() => this._reportWindow(), WHEEL_SETTLE_MS);
  }

  /** Zooms by `factor` (> 1 magnifies) keeping the world point under (px, py) fixed. */
  _zoomAt(px, py, factor) {
    const extent = 2 * Math.max(this._hw, this._hh);
    const clamped = Math.min(Math.max(extent / factor, MIN_EXTENT), MAX_EXTENT);
    const f = extent / clamped;
    const wx = this.wx(px);
    const wy = this.wy(py);
    this._cx = wx + (this._cx - wx) / f;
    this._cy = wy + (this._cy - wy) / f;
    this._hw /= f;
    this._hh /= f;
    this._layout(this.width, this.height);
    this.requestDraw();
  }

  _gestureDistance() {
    const [a, b] = this._gestures.values();
    return Math.hypot(a.x - b.x, a.y - b.y);
  }

  _gestureMidpoint() {
    const [a, b] = this._gestures.values();
    return [(a.x + b.x) / 2, (a.y + b.y) / 2];
  }

  /** Rounds the window as state stores it, applies that, and reports it. */
  _reportWindow() {
    const win = this.getWindow().map(roundWindowValue);
    this.setWindow(win);
    this.onWindowChange?.(win);
  }

  /** Removes every listener and observer and the canvas. */
  destroy() {
    this._destroyed = true;
    clearTimeout(this._wheelTimer);
    for (const [type, handler] of Object.entries(this._handlers))
      this.canvas.removeEventListener(type, handler);
    this._stopSize();
    this._stopTheme();
    this.canvas.remove();
  }
}
