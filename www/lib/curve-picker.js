/**
 * Picking a drawn curve by its samples: a press (or tap) on the curve, within a hit radius of
 * the nearest drawn sample, says which sample it was (a parameter to insert, a segment to
 * select); hovering reports the sample under the pointer. This is drawing support, not a curve
 * algorithm: the samples are the ones the core returned for drawing (`sampleUniform`). Add it
 * after the handles, so a press on a control point still drags it.
 *
 *   new CurvePicker(view, { samples: () => d.samples, count: CURVE_SAMPLES, click: (j) => insert(u(j)) });
 */
import { HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH } from "./handles.js";

/**
 * Of the `count` points of a flat `[x0, y0, x1, y1, …]` sample array (world coordinates), the
 * index of the one nearest to canvas point (x, y) within `radius` px, else -1.
 */
export function nearestSample(view, samples, count, x, y, radius) {
  let best = -1;
  let bestDistance = radius;
  for (let j = 0; j < count; j++) {
    const d = Math.hypot(view.sx(samples[2 * j]) - x, view.sy(samples[2 * j + 1]) - y);
    if (d <= bestDistance) {
      best = j;
      bestDistance = d;
    }
  }
  return best;
}

export class CurvePicker {
  /**
   * @param {View} view
   * @param {object} o
   * @param {() => ArrayLike<number>} o.samples the drawn samples, flat.
   * @param {number} o.count how many.
   * @param {number} [o.radius] hit radius in CSS px; default the handles' (larger for touch).
   * @param {(j: number) => void} [o.press] a press landed on sample j.
   * @param {(j: number) => void} [o.click] released still on the curve after pressing sample j.
   * @param {(j: number) => void} [o.hover] the sample under the pointer (-1: none).
   * @param {() => boolean} [o.ignore] hover reports -1 while this is true (a handle is hovered).
   * @param {string} [o.cursor] the cursor over the curve.
   */
  constructor(view, o) {
    const near = (x, y, pointerType) => {
      const radius = o.radius ?? (pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE);
      return nearestSample(view, o.samples(), o.count, x, y, radius);
    };
    /** The sample pressed, until the pointer is up. */
    this.pressed = -1;
    view.addInteractor({
      pointerDown: (event, x, y) => {
        const j = near(x, y, event.pointerType);
        if (j < 0) return false;
        this.pressed = j;
        o.press?.(j);
        return true;
      },
      pointerMove() {},
      pointerUp: (event, x, y) => {
        const j = this.pressed;
        this.pressed = -1;
        if (j >= 0 && near(x, y, event.pointerType) >= 0) o.click?.(j); // slid off the curve: nothing
      },
      hover: (x, y, pointerType) => {
        const j = o.ignore?.() ? -1 : near(x, y, pointerType);
        o.hover?.(j);
        return j >= 0 ? (o.cursor ?? "pointer") : null;
      },
      leave: () => o.hover?.(-1),
    });
  }
}

/**
 * The drawn sample under the pointer (what a click would pick), for the figure to mark: `index`
 * (-1: none) and its cached `label(j)`; `set(j)` (a `CurvePicker`'s press / hover) redraws the
 * view only when the sample changed.
 */
export class HoveredSample {
  constructor(view, label) {
    this.view = view;
    this.labelOf = label;
    this.index = -1;
    this.label = "";
  }

  set(j) {
    if (j === this.index) return;
    this.index = j;
    this.label = j >= 0 ? this.labelOf(j) : "";
    this.view.requestDraw();
  }
}
