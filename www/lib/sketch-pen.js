/**
 * Freehand drawing on a View (the sketch demo): an interactor that claims a press on the figure
 * (after the handles, which are asked first; Shift + drag is left to the figure's pan) and
 * collects the pointer's path in canvas CSS px — every coalesced event of a pen or a fast mouse
 * (`getCoalescedEvents`), samples closer than `minStep` px to the last one dropped — then hands
 * it over on release: `done(flat, pointerType)`. `draw(r, style)` paints the path while it is
 * drawn. The canvas has `touch-action: none` (figure-canvas.js), so a finger draws, not scrolls;
 * a second finger turns the stroke into a pinch or a two-finger pan (`View#toGesture`).
 */

/** Samples kept at least this far apart, CSS px (the link stays short; a fit needs no more). */
export const MIN_STEP_PX = 2;
/** Most samples of one stroke (a long scribble is cut there). */
export const MAX_SAMPLES = 4000;

export class SketchPen {
  constructor(view, { done, minStep = MIN_STEP_PX, enabled = () => true }) {
    this.view = view;
    this.done = done;
    this.minStep = minStep;
    this.enabled = enabled;
    /** The path being drawn, flat [x0, y0, …] in canvas CSS px (empty when idle). */
    this.points = [];
    this.pointerId = null;
    this.pointerType = "mouse";
    view.addInteractor(this);
  }

  get drawing() {
    return this.pointerId !== null;
  }

  _add(x, y) {
    const n = this.points.length;
    if (n >= 2 * MAX_SAMPLES) return;
    if (n > 0 && Math.hypot(x - this.points[n - 2], y - this.points[n - 1]) < this.minStep) return;
    this.points.push(x, y);
  }

  pointerDown(event, x, y) {
    if (this.drawing && event.pointerType === "touch" && this.pointerType === "touch") {
      // A second finger: the stroke was the start of a pinch or a two-finger pan. The first
      // finger goes back to the figure (`toGesture`), the new one joins it there.
      const n = this.points.length;
      this.view.toGesture(this.pointerId, this.points[n - 2], this.points[n - 1]);
      this.pointerId = null;
      this.points = [];
      this.view.requestDraw();
      return false;
    }
    if (this.drawing || event.shiftKey || !this.enabled()) return false;
    this.pointerId = event.pointerId;
    this.pointerType = event.pointerType || "mouse";
    this.points = [x, y];
    this.view.canvas.focus({ preventScroll: true });
    this.view.requestDraw();
    return true;
  }

  pointerMove(event, x, y) {
    if (event.pointerId !== this.pointerId) return;
    const events = event.getCoalescedEvents?.() ?? [];
    if (events.length > 1) {
      for (const e of events) {
        const [cx, cy] = this.view.eventPosition(e);
        this._add(cx, cy);
      }
    } else {
      this._add(x, y);
    }
    this.view.requestDraw();
  }

  pointerUp(event, x, y) {
    if (event.pointerId !== this.pointerId) return;
    if (event.type !== "pointercancel") this._add(x, y);
    const points = this.points;
    const type = this.pointerType;
    this.pointerId = null;
    this.points = [];
    this.view.requestDraw();
    if (event.type !== "pointercancel") this.done(points, type);
  }

  hover() {
    return this.enabled() ? "crosshair" : null;
  }

  leave() {}

  /** The path being drawn, in `style`. */
  draw(r, style) {
    const p = this.points;
    if (p.length < 4) return;
    r.beginPath();
    r.moveTo(p[0], p[1]);
    for (let k = 2; k < p.length; k += 2) r.lineTo(p[k], p[k + 1]);
    r.paint(style);
  }
}
