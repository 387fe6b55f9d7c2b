/**
 * Building blocks for a demo's `validate(state)`: each checks one field and throws an `Error`
 * whose message names the field and the bad value (strings.js "error.*"). Validation is strict
 * (unknown fields are refused) because states arrive from links and files written by anyone.
 * The wasm constructors validate the geometry again.
 */
import { t } from "./strings.js";
import { isCamera } from "./camera3d.js";
import { localeDecimal, shownNumbers } from "./format.js";

/** Shows a value in an error message without flooding it. */
function show(value) {
  const text =
    typeof value === "string"
      ? t("format.quoted", { value })
      : typeof value === "number"
        ? localeDecimal(String(value))
        : JSON.stringify(value);
  return text === undefined ? String(value) : text.length > 40 ? `${text.slice(0, 37)}…` : text;
}

/** Throws unless `state` is a plain object whose fields are all listed in `allowed`. */
export function checkObject(state, allowed) {
  if (state === null || typeof state !== "object" || Array.isArray(state))
    throw new Error(t("error.notObject"));
  for (const field of Object.keys(state)) {
    if (!allowed.includes(field)) throw new Error(t("error.unknownField", { field }));
  }
}

function present(state, field) {
  if (!(field in state)) throw new Error(t("error.missingField", { field }));
  return state[field];
}

/** Throws unless `state[field]` is a finite number in [min, max] (and an integer if asked). */
export function checkNumber(
  state,
  field,
  { min = -Infinity, max = Infinity, integer = false } = {},
) {
  const value = present(state, field);
  if (typeof value !== "number" || !Number.isFinite(value))
    throw new Error(t("error.notFinite", { field, value: show(value) }));
  if (integer && !Number.isInteger(value))
    throw new Error(t("error.notInteger", { field, value: show(value) }));
  if (value < min || value > max)
    throw new Error(t("error.range", { field, ...shownNumbers({ min, max }), value: show(value) }));
}

/** Throws unless `state[field]` is a boolean. */
export function checkBoolean(state, field) {
  const value = present(state, field);
  if (typeof value !== "boolean")
    throw new Error(t("error.notBoolean", { field, value: show(value) }));
}

/** Throws unless `state[field]` is one of the strings in `choices`. */
export function checkChoice(state, field, choices) {
  const value = present(state, field);
  if (!choices.includes(value))
    throw new Error(
      t("error.notString", { field, choices: choices.join(", "), value: show(value) }),
    );
}

/** Throws unless `state[field]` is a list of [x, y] pairs of finite numbers, min..max of them. */
export function checkPoints(state, field, { min = 0, max = Infinity } = {}) {
  const value = present(state, field);
  if (!Array.isArray(value)) throw new Error(t("error.notArray", { field }));
  if (value.length < min || value.length > max)
    throw new Error(t("error.count", { field, min, max, count: value.length }));
  value.forEach((point, index) => {
    if (!Array.isArray(point) || point.length !== 2)
      throw new Error(t("error.pointShape", { field, index }));
    if (!point.every((c) => typeof c === "number" && Number.isFinite(c)))
      throw new Error(t("error.pointFinite", { field, index }));
  });
}

/**
 * Throws unless `state[field]` is a list of [x, y, z] triples of finite numbers: min..max of
 * them, or exactly rows × cols (a surface's control net, row-major) when `rows`, `cols` are given.
 */
export function checkPoints3(state, field, { min = 0, max = Infinity, rows = 0, cols = 0 } = {}) {
  const value = present(state, field);
  if (!Array.isArray(value)) throw new Error(t("error.notArray", { field }));
  if (rows > 0 && cols > 0 && value.length !== rows * cols)
    throw new Error(
      t("error.gridCount", { field, rows, cols, expected: rows * cols, count: value.length }),
    );
  if (value.length < min || value.length > max)
    throw new Error(t("error.count", { field, min, max, count: value.length }));
  value.forEach((point, index) => {
    if (!Array.isArray(point) || point.length !== 3)
      throw new Error(t("error.pointShape3", { field, index }));
    if (!point.every((c) => typeof c === "number" && Number.isFinite(c)))
      throw new Error(t("error.pointFinite", { field, index }));
  });
}

/** Throws unless `camera` is a 3D figure's camera (camera3d.js), the `view` of a 3D demo. */
export function checkCamera(camera) {
  if (!isCamera(camera)) throw new Error(t("error.camera"));
}

/** Throws unless `state[field]` is a list of finite numbers, min..max of them. */
export function checkNumbers(state, field, { min = 0, max = Infinity } = {}) {
  const value = present(state, field);
  if (!Array.isArray(value)) throw new Error(t("error.notArray", { field }));
  if (value.length < min || value.length > max)
    throw new Error(t("error.count", { field, min, max, count: value.length }));
  value.forEach((v) => {
    if (typeof v !== "number" || !Number.isFinite(v))
      throw new Error(t("error.notFinite", { field, value: show(v) }));
  });
}

/** Throws unless `win` is a view window [xmin, ymin, xmax, ymax] (the shell's `view` field). */
export function checkWindow(win) {
  const ok =
    Array.isArray(win) &&
    win.length === 4 &&
    win.every((v) => typeof v === "number" && Number.isFinite(v)) &&
    win[0] < win[2] &&
    win[1] < win[3];
  if (!ok) throw new Error(t("error.window"));
}

/**
 * Field checkers for a declarative demo's `fields` export (see demo.js): each is
 * `(state, name) => void` and throws like the functions above.
 *
 *   export const fields = { points: field.points({ min: 2, max: 11 }), t: field.number({ min: 0, max: 1 }) };
 */
export const field = Object.freeze({
  /** `options` may be a function of the state: `field.number((s) => ({ min: 0, max: s.points.length - 1 }))`. */
  number: (options) => (state, name) =>
    checkNumber(state, name, typeof options === "function" ? options(state) : options),
  boolean: () => (state, name) => checkBoolean(state, name),
  choice: (choices) => (state, name) => checkChoice(state, name, choices),
  points: (options) => (state, name) => checkPoints(state, name, options),
  /** A surface's control net: `field.points3d({ rows: 4, cols: 4 })` (options may be a function of the state). */
  points3d: (options) => (state, name) =>
    checkPoints3(state, name, typeof options === "function" ? options(state) : options),
  numbers: (options) => (state, name) => checkNumbers(state, name, options),
});
