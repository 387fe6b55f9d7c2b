/**
 * Editing a tensor-product B-spline surface's net through the core, for declarative demos
 * whose state is `{ rows, cols, degreeU, degreeV, knotsU, knotsV, points, weights, selected, u,
 * v, fresh }` and whose model is `{ surface }` (a `BSplineSurface`): knot insertion at the probe
 * (`insertKnotU/V`, the new net read back into the state, the lines Boehm's rule made marked in
 * `fresh`), knot vectors from the core's `knotVector`, typed knots (the core decides), and a
 * logarithmic slider for the weight of the selected control point (`ui.setWeight`). Messages
 * are the demo's strings (`<prefix>.netFull`, `.insertedU`, `.insertedV`, `.control.weight`,
 * `.control.weight.input`, `.badWeight`).
 */
import { slider as sliderElement, setText } from "./controls.js";
import { shortNumber, subscript } from "./format.js";
import { t } from "./strings.js";
import { weightText } from "./weight-sliders.js";
import { errorText } from "./core-errors.js";

const LABELS = new Map();
/** "P₂,₃": row i (along u), column j (along v), for a net of `cols` columns (cached). */
export function netLabel(k, cols) {
  const key = k * 100 + cols;
  if (!LABELS.has(key))
    LABELS.set(key, `P${subscript(Math.floor(k / cols))},${subscript(k % cols)}`);
  return LABELS.get(key);
}

/**
 * Inserts one knot at the probe, in u (`dir` "u") or v, and replaces the state with the core's
 * new net (`maxLines` caps rows and columns).
 */
export function insertAtProbe(ui, dir, { prefix, maxLines }) {
  const s = ui.state;
  const limit = dir === "u" ? s.rows : s.cols;
  if (limit >= maxLines) {
    ui.status(t(`${prefix}.netFull`, { max: maxLines }), "error");
    return;
  }
  let refined = null;
  try {
    refined = dir === "u" ? ui.data.surface.insertKnotU(s.u) : ui.data.surface.insertKnotV(s.v);
    const flat = refined.controlPoints();
    const points = Array.from({ length: flat.length / 3 }, (_, k) => [
      flat[3 * k],
      flat[3 * k + 1],
      flat[3 * k + 2],
    ]);
    const next = {
      ...s,
      rows: refined.rows,
      cols: refined.cols,
      knotsU: Array.from(refined.knotsU()),
      knotsV: Array.from(refined.knotsV()),
      points,
      weights: Array.from(refined.weights()),
      fresh: freshLines(s, points, refined.rows, refined.cols, dir),
    };
    ui.replace(next);
    ui.status(
      t(`${prefix}.inserted${dir.toUpperCase()}`, {
        at: shortNumber(dir === "u" ? s.u : s.v),
        rows: next.rows,
        cols: next.cols,
      }),
    );
  } catch (err) {
    ui.status(errorText(err), "error");
  } finally {
    refined?.free();
  }
}

/**
 * The rows (or columns) of the new net that are neither the old line at the same index (before
 * the insertion span) nor the old line one index back (after it): the lines Boehm's rule made.
 * Drawing support (a comparison of the core's two nets), `[direction, first, last]`.
 */
function freshLines(old, points, rows, cols, dir) {
  const lines = dir === "u" ? rows : cols;
  const at = (list, c, line, k) => (dir === "u" ? list[line * c + k] : list[k * c + line]);
  const along = dir === "u" ? cols : rows;
  const same = (line, oldLine) => {
    if (oldLine < 0 || oldLine >= lines - 1) return false;
    for (let k = 0; k < along; k++) {
      const a = at(points, cols, line, k);
      const b = at(old.points, old.cols, oldLine, k);
      if (a[0] !== b[0] || a[1] !== b[1] || a[2] !== b[2]) return false;
    }
    return true;
  };
  const made = [];
  for (let line = 0; line < lines; line++)
    if (!same(line, line) && !same(line, line - 1)) made.push(line);
  return made.length ? [dir === "u" ? 0 : 1, made[0], made[made.length - 1]] : [];
}

/** New knots of `kind` ("clamped" | "uniform") for direction `dir` from the core's `knotVector`. */
export function resetKnots(ui, dir, kind, degree = null) {
  const s = ui.state;
  const p = degree ?? (dir === "u" ? s.degreeU : s.degreeV);
  const n = dir === "u" ? s.rows : s.cols;
  try {
    const knots = Array.from(ui.sl.knotVector(new Float64Array(2 * n), 2, p, kind));
    ui.replace({
      ...s,
      ...(dir === "u" ? { degreeU: p, knotsU: knots } : { degreeV: p, knotsV: knots }),
      fresh: [],
    });
  } catch (err) {
    ui.status(errorText(err), "error");
  }
}

/** Knots typed into a box: the core decides (its message in the status line). */
export function typedKnots(ui, dir, values) {
  try {
    ui.replace({ ...ui.state, [dir === "u" ? "knotsU" : "knotsV"]: values, fresh: [] });
  } catch (err) {
    ui.status(errorText(err), "error");
  }
}

/**
 * The weight of the selected control point: one logarithmic slider over [min, max] (`step` in
 * log10 units), labelled with the point's name.
 */
export function selectedWeight({ prefix, min, max, step }) {
  return {
    build(ui) {
      const control = sliderElement({
        label: t(`${prefix}.control.weight`, { name: "" }),
        inputLabel: t(`${prefix}.control.weight.input`),
        name: "weight",
        min,
        max,
        step,
        log: true,
        value: ui.state.weights[ui.state.selected],
        format: (w) => weightText(w),
        onChange: (w, final) => ui.setWeight(ui.state.selected, Number(w.toPrecision(3)), final),
        badNumber: (text) => t(`${prefix}.badWeight`, { value: text, min, max }),
        onError: (message) => ui.status(message, "error"),
      });
      const labelNode = control.element.querySelector("label");
      return {
        element: control.element,
        sync(state) {
          setText(
            labelNode,
            t(`${prefix}.control.weight`, { name: netLabel(state.selected, state.cols) }),
          );
          control.set(state.weights[state.selected]);
        },
      };
    },
  };
}
