/**
 * A band along the bottom of a figure where a parameter u in [a, b] is shown and picked: press
 * or drag in the band to set u. The strip lays the band out, handles the pointer (ahead of the
 * handles: create it first, or pass them as `before`) and draws the usual marks (axis, knot ticks and labels,
 * u itself); the demo chooses which marks its band shows (knots, spans, supports …) with
 * `top`, `y(row)`, `x0`, `x1` and `px(u)`, and reserves the band with the View's `insets`
 * (`height × scale` CSS px at the bottom). For a knot vector the reader edits, with a handle
 * per knot, use knot-ruler.js instead.
 *
 * In a declarative demo (demo.js) the strip is a `controls` entry bound to a number field:
 *
 *   export const controls = [parameterStrip("u", { height: STRIP_PX, margin: STRIP_MARGIN, step: U_STEP,
 *     range: (s, d) => d.domain }), …];
 *   export const figure = { insets: scaledInsets(0, 0, STRIP_PX, 0), … };
 *   // in draw(r, v, s, d): d.strip.layout(r.width, r.height, r.scale); d.strip.drawAxis(r, ROW.axis, theme.axis) …
 */
import { knotText } from "./knot-ruler.js";

/** The u label sits left- or right-aligned when u is closer than this to an end (CSS px). */
const END_LABEL_PX = 40;

/**
 * The distinct values of a knot vector, how often each occurs, and their labels, "0 ×4" for a
 * value repeated 4 times (a knot vector's ticks on a strip).
 * @param {ArrayLike<number>} knots non-decreasing
 * @returns {{ values: Float64Array, counts: number[], labels: string[] }}
 */
export function knotMarks(knots) {
  const values = [];
  const counts = [];
  for (const value of knots) {
    if (values.length && values[values.length - 1] === value) counts[counts.length - 1] += 1;
    else {
      values.push(value);
      counts.push(1);
    }
  }
  const labels = values.map((value, j) =>
    counts[j] > 1 ? `${knotText(value)} ×${counts[j]}` : knotText(value),
  );
  return { values: Float64Array.from(values), counts, labels };
}

/**
 * The strip of a declarative demo, bound to the number field `field`: pressing or dragging in
 * it calls `ui.set(field, u, final)`. It has no element in the side panel; the ParameterStrip
 * is `data[as]` (default `data.strip`) for `draw`.
 * @param {string} field
 * @param {object} o the ParameterStrip options `height`, `margin`, `hit`, and
 * @param {number | ((state, data) => number)} o.step the rounding of a picked u.
 * @param {(state, data) => [number, number]} o.range the parameter range (e.g. the domain).
 * @param {(state, data) => [number, number]} [o.clampTo] where picked u stay (the domain,
 *   when `range` is the whole knot vector).
 * @param {(ui) => void} [o.over] the pointer hovers over the band (the handles are left already).
 * @param {string} [o.as] the name of the strip in `data`.
 */
export function parameterStrip(field, o) {
  const { height, margin, step, range, clampTo = null, hit = null, over = null, as = "strip" } = o;
  return {
    build(ui) {
      const strip = new ParameterStrip(ui.view, {
        height,
        margin,
        step: typeof step === "function" ? () => step(ui.state, ui.data) : step,
        range: () => range(ui.state, ui.data),
        clampTo: clampTo ? () => clampTo(ui.state, ui.data) : null,
        hit,
        press: () => ui.stop(), // the press takes u over from a playing animation
        pick: (u, final) => ui.set(field, u, final),
        over: () => {
          ui.handles?.leave(); // the pointer left the handles' area (they are not asked while it is here)
          over?.(ui);
        },
        before: ui.handles,
      });
      ui.data[as] = strip;
      return {
        element: null,
        stop: () => {
          strip.dragging = false;
        },
      };
    },
  };
}

export class ParameterStrip {
  /**
   * @param {View} view
   * @param {object} o
   * @param {number} o.height the band's height, CSS px at scale 1.
   * @param {number} o.margin free space left and right of the parameter line, CSS px at scale 1.
   * @param {() => [number, number]} o.range the parameter range [a, b] drawn across the band.
   * @param {number | (() => number)} o.step a picked u is clamped to [a, b] and rounded to a
   *   multiple of `step` (or to a + k·step with `clampTo`).
   * @param {() => [number, number]} [o.clampTo] picked u stay in this part of the range (a
   *   B-spline's domain inside its whole knot vector).
   * @param {{ bottom: number, slack: number }} [o.hit] presses count only above `bottom` (CSS px
   *   below the top at scale 1) and at most `slack` px beyond the line's ends; default the band.
   * @param {() => void} [o.press] a press in the band starts (stop an animation of u there).
   * @param {(u: number, final: boolean) => void} o.pick u was pressed or dragged to; `final`
   *   when the pointer is released.
   * @param {() => void} [o.over] the pointer hovers over the band (the cursor becomes ↔).
   * @param {object} [o.before] an interactor already on the view (the handles) that the strip
   *   goes ahead of: its presses in the band are its own.
   */
  constructor(view, o) {
    const { height, margin, range, step, pick, over = () => {}, before = null } = o;
    this.view = view;
    this.height = height;
    this.margin = margin;
    this.range = range;
    this.step = typeof step === "function" ? step : () => step;
    this.clampTo = o.clampTo ?? null;
    this.hit = o.hit ?? null;
    /** Layout in canvas CSS px (see `layout`) and the range [a, b] drawn. */
    this.top = 0;
    this.x0 = 0;
    this.x1 = 0;
    this.a = 0;
    this.b = 1;
    /** The text scale of the last layout. */
    this.scale = 1;
    /** True while a press in the band is being dragged. */
    this.dragging = false;
    view.addInteractor(
      {
        pointerDown: (event, x, y) => {
          if (!this.contains(x, y)) return false;
          o.press?.();
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
          if (!this.contains(x, y)) return null;
          over();
          return "col-resize";
        },
      },
      before,
    );
  }

  /** Lays the band out for a canvas of width × height CSS px at (lecture) scale `scale`. */
  layout(width, height, scale) {
    this.scale = scale;
    this.top = height - this.height * scale;
    this.x0 = this.margin * scale;
    this.x1 = width - this.margin * scale;
    [this.a, this.b] = this.range();
  }

  /** Canvas x of parameter u (after `layout`). */
  px(u) {
    return this.x0 + ((u - this.a) / (this.b - this.a)) * (this.x1 - this.x0);
  }

  /** True when canvas (x, y) lies in the band's pressable part (laid out for the view on screen). */
  contains(x, y) {
    this.layout(this.view.width, this.view.height, this.view.renderer.scale);
    if (y < this.top) return false;
    if (!this.hit) return true;
    const slack = this.hit.slack * this.scale;
    return y <= this.y(this.hit.bottom) && x >= this.x0 - slack && x <= this.x1 + slack;
  }

  /** u under canvas x, clamped to [a, b] (or `clampTo`) and rounded to the step. */
  uAt(x) {
    this.layout(this.view.width, this.view.height, this.view.renderer.scale);
    const raw = this.a + ((x - this.x0) / (this.x1 - this.x0)) * (this.b - this.a);
    const step = this.step();
    if (!this.clampTo) return Math.round(Math.min(this.b, Math.max(this.a, raw)) / step) * step;
    const [lo, hi] = this.clampTo();
    return Math.min(hi, Math.max(lo, lo + Math.round((raw - lo) / step) * step));
  }

  /** Canvas y of a row `row` CSS px (at scale 1) below the band's top (after `layout`). */
  y(row) {
    return this.top + row * this.scale;
  }

  /** The parameter line from x0 to x1 at `row`. */
  drawAxis(r, row, style) {
    r.beginPath();
    r.moveTo(this.x0, this.y(row));
    r.lineTo(this.x1, this.y(row));
    r.paint(style);
  }

  /**
   * A tick of half-length `half` CSS px across `row` at each of `values` (only those with
   * `keep(j)` when given), in one path.
   */
  drawTicks(r, values, row, half, style, keep = null) {
    const y = this.y(row);
    const h = half * this.scale;
    r.beginPath();
    for (let j = 0; j < values.length; j++) {
      if (keep && !keep(j)) continue;
      const x = this.px(values[j]);
      r.moveTo(x, y - h);
      r.lineTo(x, y + h);
    }
    r.paint(style);
  }

  /**
   * `labels[j]` centred under each of `values` at `row`, in `style(j)`; a label closer than
   * `spacing` CSS px to the previous one drawn is left out.
   */
  drawLabels(r, values, labels, row, style, spacing = 0) {
    const y = this.y(row);
    let last = -Infinity;
    for (let j = 0; j < values.length; j++) {
      const x = this.px(values[j]);
      if (x - last < spacing * this.scale) continue;
      r.text(labels[j], x, y, style(j), "center", "middle");
      last = x;
    }
  }

  /** u itself: a point on the axis at `axisRow` and `text` above it at `labelRow` (kept inside the band). */
  drawParameter(r, u, text, axisRow, labelRow, pointStyle, labelStyle) {
    const x = this.px(u);
    r.point(x, this.y(axisRow), pointStyle);
    const end = END_LABEL_PX * this.scale;
    const align = x < this.x0 + end ? "left" : x > this.x1 - end ? "right" : "center";
    r.text(text, x, this.y(labelRow), labelStyle, align, "middle");
  }
}
