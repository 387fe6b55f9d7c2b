/**
 * Runge's example as data points: `count` points at equally spaced x on the bell
 *
 *   y = 1 / (1 + 25 x²),   x ∈ [−1, 1],
 *
 * scaled to the figure (x × RUNGE_HALF_WIDTH, y × RUNGE_HEIGHT) and rounded to 3 decimals. At
 * uniform parameters x(t) is linear, so Lagrange's polynomial through them is the graph of the
 * polynomial interpolant of the bell — Runge's phenomenon: the wiggle near the ends grows with
 * the degree (visible from about 9 points). `countSlider` is the panel control that puts them in.
 */
import { slider as sliderElement } from "./controls.js";
import { t } from "./strings.js";
import { errorText } from "./core-errors.js";

export const RUNGE_HALF_WIDTH = 6;
export const RUNGE_HEIGHT = 4;

const round3 = (v) => Math.round(v * 1000) / 1000 || 0;

/** `count` ≥ 2 points [x, y] on the scaled bell, equally spaced in x from left to right. */
export function rungePoints(count) {
  const points = [];
  for (let k = 0; k < count; k++) {
    const x = -1 + (2 * k) / (count - 1);
    points.push([round3(RUNGE_HALF_WIDTH * x), round3(RUNGE_HEIGHT / (1 + 25 * x * x))]);
  }
  return points;
}

/**
 * A declared control (panel.js): a slider of the number of points, `data-control=count`,
 * showing the state's count; a new count replaces the points by that many on the bell at
 * uniform parameters (`rescaled(ui, next)` keeps t at its place in the domain), through
 * `ui.replace` (committed when the slider is released or a count is typed). Strings:
 * `<prefix>.control.count` (+ `.input`), `<prefix>.countRange` ({ value, min, max }).
 */
export function countSlider({ prefix, min, max, rescaled }) {
  return {
    build(ui) {
      const place = (count, final) => {
        const next = rescaled(ui, {
          ...ui.state,
          points: rungePoints(count),
          params: "uniform",
        });
        try {
          ui.replace(next, final);
        } catch (err) {
          ui.status(errorText(err), "error");
        }
      };
      const control = sliderElement({
        label: t(`${prefix}.control.count`),
        inputLabel: t(`${prefix}.control.count.input`, { min, max }),
        name: "count",
        min,
        max,
        step: 1,
        value: ui.state.points.length,
        format: (v) => String(Math.round(v)),
        onChange: (value, final) => {
          const count = Math.round(value);
          if (!Number.isInteger(value) || count < min || count > max) {
            ui.status(t(`${prefix}.countRange`, { value, min, max }), "error");
            control.set(ui.state.points.length);
            return;
          }
          ui.stop();
          place(count, final);
        },
        onError: (text) => ui.status(t(`${prefix}.countRange`, { value: text, min, max }), "error"),
      });
      return { element: control.element, sync: (s) => control.set(s.points.length) };
    },
  };
}
