/**
 * The degree of a B-spline as a row of radio buttons (a declared control, panel.js, in
 * `data-control="degree"`): degrees min … max, those the points cannot carry disabled (degree p
 * needs n + 1 ≥ p + 1 control points). A new degree replaces the knots by the core's clamped
 * uniform vector for it (p + 1 equal knots at each end, `withClampedKnots` in bspline.js) with u
 * clamped into the new domain; a refusal is reported in the status line.
 */
import { radios } from "./controls.js";
import { degreeName } from "./format.js";
import { t } from "./strings.js";
import { replaceOrReport } from "./wasm.js";
import { withClampedKnots } from "./bspline.js";

/**
 * `prefix`: the demo's strings.js prefix, with `.degreeOption` ({ p, kind }) for a button's
 * label and `.minPoints` ({ min, degree }) when there are too few points for the degree.
 * A demo whose degree is not that of a control polygon gives `limit(state)` → the largest
 * degree the state can carry (default: the number of points − 1; interpolation with end
 * derivatives carries one more per derivative) and `apply(ui, p)` (default: the clamped uniform
 * knots for p, `withClampedKnots`); `.minPoints` then gets `{ min: p + 1, degree: p }` as before.
 */
export function degreeButtons({ prefix, min, max, limit = null, apply = null }) {
  const largest = limit ?? ((s) => s.points.length - 1);
  return {
    build(ui) {
      const options = [];
      for (let p = min; p <= max; p++) {
        options.push({
          value: String(p),
          label: t(`${prefix}.degreeOption`, { p, kind: degreeName(p) }),
        });
      }
      const control = radios({
        name: "degree",
        value: String(ui.state.degree),
        options,
        onChange(value) {
          const p = Number(value);
          const s = ui.state;
          if (p === s.degree) return;
          if (p > largest(s))
            ui.status(t(`${prefix}.minPoints`, { min: p + 1, degree: p }), "error");
          else if (apply) apply(ui, p);
          else replaceOrReport(ui, withClampedKnots(ui.sl, { ...s, degree: p }));
          control.set(String(ui.state.degree));
        },
      });
      control.element.classList.add("sl-button-row");
      return {
        element: control.element,
        sync(s) {
          control.set(String(s.degree));
          for (const input of control.inputs) input.disabled = Number(input.value) > largest(s);
        },
      };
    },
  };
}
