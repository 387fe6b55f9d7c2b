/**
 * A band along the bottom of a figure where a parameter u in [a, b] is shown and picked: press
 * or drag in the band to set u. The strip only lays the band out and handles the pointer; the
 * demo draws what its band shows (knots, spans, supports …) with `top`, `x0`, `x1` and `px(u)`,
 * and reserves the band with the View's `insets` (`height × scale` CSS px at the bottom).
 * For a knot vector the reader edits, with a handle per knot, use knot-ruler.js instead.
 *
 *   const strip = new ParameterStrip(view, {
 *     height: STRIP_PX, margin: STRIP_MARGIN, step: U_STEP,
 *     range: () => domain(),
 *     pick: (u, final) => setU(u, final),
 *     over: () => handles.leave(),
 *   });
 *   // in draw(r, v): strip.layout(r.width, r.height, r.scale); then r.moveTo(strip.px(u), strip.top + …)
 *
 * Create it before the Handles: its interactor claims presses in the band first.
 */
export class ParameterStrip {
  /**
   * @param {View} view
   * @param {object} o
   * @param {number} o.height the band's height, CSS px at scale 1.
   * @param {number} o.margin free space left and right of the parameter line, CSS px at scale 1.
   * @param {() => [number, number]} o.range the parameter range [a, b] drawn across the band.
   * @param {number} o.step a picked u is clamped to [a, b] and rounded to a multiple of `step`.
   * @param {(u: number, final: boolean) => void} o.pick u was pressed or dragged to; `final`
   *   when the pointer is released.
   * @param {() => void} [o.over] the pointer hovers over the band (the cursor becomes ↔).
   */
  constructor(view, { height, margin, range, step, pick, over = () => {} }) {
    this.view = view;
    this.height = height;
    this.margin = margin;
    this.range = range;
    this.step = step;
    /** Layout in canvas CSS px (see `layout`) and the range [a, b] drawn. */
    this.top = 0;
    this.x0 = 0;
    this.x1 = 0;
    this.a = 0;
    this.b = 1;
    /** True while a press in the band is being dragged. */
    this.dragging = false;
    view.addInteractor({
      pointerDown: (event, x, y) => {
        if (!this.contains(y)) return false;
        this.dragging = true;
        pick(this.uAt(x), false);
        return true;
      },
      pointerMove: (event, x) => {
        if (this.dragging) pick(this.uAt(x), false);
      },
      pointerUp: (event, x) => {
        if (!this.dragging) return;
        this.dragging = false;
        pick(this.uAt(x), true);
      },
      hover: (x, y) => {
        if (!this.contains(y)) return null;
        over();
        return "col-resize";
      },
    });
  }

  /** Lays the band out for a canvas of width × height CSS px at (lecture) scale `scale`. */
  layout(width, height, scale) {
    this.top = height - this.height * scale;
    this.x0 = this.margin * scale;
    this.x1 = width - this.margin * scale;
    [this.a, this.b] = this.range();
  }

  /** Canvas x of parameter u (after `layout`). */
  px(u) {
    return this.x0 + ((u - this.a) / (this.b - this.a)) * (this.x1 - this.x0);
  }

  /** True when canvas y lies in the band (laid out for the view on screen). */
  contains(y) {
    this.layout(this.view.width, this.view.height, this.view.renderer.scale);
    return y >= this.top;
  }

  /** u under canvas x, clamped to [a, b] and rounded to a multiple of `step`. */
  uAt(x) {
    this.layout(this.view.width, this.view.height, this.view.renderer.scale);
    const raw = this.a + ((x - this.x0) / (this.x1 - this.x0)) * (this.b - this.a);
    return Math.round(Math.min(this.b, Math.max(this.a, raw)) / this.step) * this.step;
  }
}
