/**
 * A declared control (see panel.js) for the weights of a rational curve: one logarithmic slider
 * per entry of `state.weights` (`data-control="weight-i"`), labelled with the demo's
 * `<prefix>.weightLabel` ("Weight w₁ of P₁"), `<prefix>.weightInput` (the box's name) and
 * `<prefix>.badWeight` (typed text out of range). A log scale because only ratios of weights
 * matter: doubling w₁ moves the slider as far as halving it. A slider value keeps `digits`
 * significant digits; changes go through `ui.setWeight(i, w, final)`, so a demo with
 * `derive.weighted` updates its curve in place (`setWeight`). The sliders are rebuilt when the
 * number of weights changes (a point added or removed).
 */
import { slider, el } from "./controls.js";
import { localeDecimal, subscript, texDecimal } from "./format.js";
import { t } from "./strings.js";

/**
 * A weight as the panels show it: up to `digits` significant digits, no trailing zeros, the
 * language's decimal separator ("0.707", "0,707"); TeX with `tex` ("0{,}707").
 */
export function weightText(w, digits = 3, tex = false) {
  const s = String(Number(w.toPrecision(digits)));
  return tex ? texDecimal(s) : localeDecimal(s);
}

/**
 * @param {object} o
 * @param {string} o.prefix the demo's strings.js prefix.
 * @param {number} o.min @param {number} o.max the range of a weight (min > 0).
 * @param {number} o.step slider resolution in log10 units.
 * @param {number} [o.digits] significant digits of a slider value (default 3).
 */
export function weightSliders({ prefix, min, max, step, digits = 3 }) {
  return {
    build(ui) {
      const box = el("div", { class: "sl-weights" });
      let sliders = [];
      const format = (w) => weightText(w, digits);
      const make = (w, i) => {
        const name = `w${subscript(i)}`;
        return slider({
          label: t(`${prefix}.weightLabel`, { name, point: `P${subscript(i)}` }),
          inputLabel: t(`${prefix}.weightInput`, { name }),
          name: `weight-${i}`,
          min,
          max,
          step,
          log: true,
          value: w,
          format,
          onChange: (value, final) => ui.setWeight(i, Number(value.toPrecision(digits)), final),
          badNumber: (text) => t(`${prefix}.badWeight`, { name, value: text, min, max }),
          onError: (message) => ui.status(message, "error"),
        });
      };
      return {
        element: box,
        sync(state) {
          if (sliders.length !== state.weights.length) {
            sliders = state.weights.map(make);
            box.replaceChildren(...sliders.map((s) => s.element));
          } else {
            sliders.forEach((s, i) => s.set(state.weights[i]));
          }
        },
      };
    },
  };
}
