/**
 * Vectors attached to data points (tangent arrows P_i → P_i + s·m_i), set by dragging their tips
 * or by typing the selected point's vector.
 *
 * `vectorTips(ui, { count(state), tip(state, k, out), drag(ui, k, x, y) })`: the pointer tool. A
 * press within the handles' hit radius of a tip grabs it (the point handles, added earlier to
 * the view, keep the points themselves), a move hands the pointer's world position to the demo,
 * release commits. `tip` writes tip k's world position into `out` ([x, y]); `drag` sets the
 * vector from the pointer's world position (x, y) (`ui.set(…, false)` or a change in place and
 * `ui.touch`). Tips are not point handles, so they add nothing to the point list (Add / Remove
 * point, Tab order).
 *
 * `selectedVectorBox(field, { label, error })`: the keyboard way, a declared control (panel.js)
 * with a text box (`data-control=field`) holding `state[field][i]` of the selected handle i (the
 * first point when none is; the demo's `figure.handles.select` should `ui.touch` a field so the
 * box follows the selection). Enter or leaving the box reads two numbers or fractions
 * ("3 -1/2", "(3, -0.5)") into the vector and commits; anything else reports `error` (a strings
 * key, given `{ value }`). `label` is a strings key given `{ i }` (a subscript index).
 */
import { HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH } from "./handles.js";
import { el, setText } from "./controls.js";
import {
  inputListSeparator,
  parseNumberInput,
  shortNumber,
  splitNumberList,
  subscript,
} from "./format.js";
import { t } from "./strings.js";

export function vectorTips(ui, { count, tip, drag }) {
  const { view } = ui;
  const at = new Float64Array(2);
  let dragging = -1;
  /** The tip nearest canvas (x, y) within the hit radius, or -1. */
  const tipAt = (x, y, pointerType) => {
    const radius = pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE;
    let best = -1;
    let bestDistance = radius * view.renderer.scale;
    for (let k = count(ui.state) - 1; k >= 0; k--) {
      tip(ui.state, k, at);
      const d = Math.hypot(x - view.sx(at[0]), y - view.sy(at[1]));
      if (d <= bestDistance) {
        best = k;
        bestDistance = d;
      }
    }
    return best;
  };
  view.addInteractor({
    pointerDown(event, x, y) {
      dragging = tipAt(x, y, event.pointerType);
      if (dragging < 0) return false;
      ui.stop();
      return true;
    },
    pointerMove(event, x, y) {
      if (dragging < 0 || dragging >= count(ui.state)) return;
      drag(ui, dragging, view.wx(x), view.wy(y));
    },
    pointerUp() {
      if (dragging < 0) return;
      dragging = -1;
      ui.commit();
    },
    hover: (x, y, pointerType) => (tipAt(x, y, pointerType) >= 0 ? "move" : null),
  });
}

export function selectedVectorBox(field, { label, error }) {
  return {
    build(ui) {
      const id = `sl-${field}-${Math.random().toString(36).slice(2, 8)}`;
      const input = el("input", {
        type: "text",
        id,
        class: "sl-value sl-wide",
        inputmode: "decimal",
        spellcheck: "false",
      });
      const name = el("label", { for: id });
      const row = el("div", { class: "sl-control", dataset: { control: field } }, name, input);
      const index = () => {
        const i = ui.handles?.selected ?? -1;
        return i >= 0 && i < ui.state[field].length ? i : 0;
      };
      const read = () => {
        const parts = splitNumberList(input.value, "()");
        const values = parts.map(parseNumberInput);
        if (values.length !== 2 || !values.every(Number.isFinite)) {
          ui.status(t(error, { value: input.value }), "error");
          return;
        }
        const vector = ui.state[field][index()];
        vector[0] = values[0];
        vector[1] = values[1];
        ui.set(field, ui.state[field]);
      };
      input.addEventListener("change", read);
      input.addEventListener("keydown", (event) => {
        if (event.key === "Enter") read();
      });
      const focused = () =>
        document.activeElement === input || input.getRootNode().activeElement === input;
      return {
        element: row,
        sync(state) {
          const i = index();
          setText(name, t(label, { i: subscript(i) }));
          const [x, y] = state[field][i];
          const text = `${shortNumber(x)}${inputListSeparator()}${shortNumber(y)}`;
          if (input.value !== text && !focused()) input.value = text;
        },
      };
    },
  };
}
