/**
 * A curve typed as formulas in a declarative demo's state (parametric-curve): the texts
 * `x`, `y`, optional `z` and the interval's ends `from`, `to`, and the parameters' values
 * `params` (`{ a: 2, … }`). Their checkers for `fields`, the core's curve of a state
 * (`sl.parametricCurve`, every other name a parameter: `sl.expressionNames`), and a preset or
 * typed texts laid over a state. The core parses and checks the texts; nothing here reads them.
 */
import { t } from "./strings.js";

/** The typed fields the curve is built from (a parameter's value is set in place). */
export const TEXTS = Object.freeze(["x", "y", "z", "from", "to"]);
/** The fields the curve's numbers depend on: the texts and the parameters. */
export const WITH_PARAMS = Object.freeze([...TEXTS, "params"]);
/** The longest text the core parses (src/expr/mod.rs MAX_LENGTH). */
const MAX_TEXT = 1000;
/** Parameters a state may carry, and the longest name. */
const MAX_PARAMS = 16;
const MAX_NAME = 24;
/** A parameter that appears in a new text starts at this value. */
const DEFAULT_PARAMETER = 1;

/** A checker of a typed formula: a string the core may read (z may be empty: a plane curve). */
export function textField(prefix) {
  return (state, name) => {
    const value = state[name];
    if (typeof value !== "string" || value.length > MAX_TEXT || (name !== "z" && !value.trim()))
      throw new Error(t(`${prefix}.error.text`, { field: name, max: MAX_TEXT }));
  };
}

/** A checker of parameter values: `{ name: number }`, a few short names, finite numbers. */
export function paramsField(prefix) {
  return (state, name) => {
    const value = state[name];
    const ok =
      value !== null &&
      typeof value === "object" &&
      !Array.isArray(value) &&
      Object.keys(value).length <= MAX_PARAMS &&
      Object.entries(value).every(
        ([k, v]) =>
          k.length > 0 && k.length <= MAX_NAME && typeof v === "number" && Number.isFinite(v),
      );
    if (!ok) throw new Error(t(`${prefix}.error.params`));
  };
}

/** True when the state has a z(t): a space curve. */
export const isSpaceState = (s) => typeof s.z === "string" && s.z.trim() !== "";

/** The refusal of a text names its field (`expressionNames` knows no field). */
function located(err, name) {
  if (err && typeof err === "object" && err.params && err.params.field === undefined) {
    try {
      err.params.field = name;
      err.params.piece = 0;
    } catch {
      // a frozen params object keeps its own fields
    }
  }
  return err;
}

/**
 * The core's curve of the state's texts; its parameters are the names the texts use, each with
 * its value in `params` or DEFAULT_PARAMETER (names no text uses are dropped). Returns
 * `{ curve, params }`; throws the core's refusal (its `field` set).
 */
export function curveOf(sl, s) {
  const params = {};
  for (const name of TEXTS) {
    if (name === "z" && !isSpaceState(s)) continue;
    let names;
    try {
      names = sl.expressionNames(s[name]);
    } catch (err) {
      throw located(err, name);
    }
    for (const p of names)
      params[p] = s.params && Object.hasOwn(s.params, p) ? s.params[p] : DEFAULT_PARAMETER;
  }
  const piece = { x: s.x, y: s.y, from: s.from, to: s.to };
  if (isSpaceState(s)) piece.z = s.z;
  return { curve: sl.parametricCurve([piece], params), params };
}

/** A copy of `state` with typed `texts` (`{ x: "…", … }`) laid over it. */
export function withTexts(state, texts) {
  return Object.assign(structuredClone(state), texts);
}

/** A copy of `state` showing a preset `{ x, y, z?, from?, to, params?, t, bezier? }`. */
export function withPreset(state, preset) {
  return {
    ...structuredClone(state),
    x: preset.x,
    y: preset.y,
    z: preset.z ?? "",
    from: preset.from ?? "0",
    to: preset.to,
    params: { ...(preset.params ?? {}) },
    t: preset.t,
    bezier: preset.bezier ?? false,
  };
}
