/**
 * The B-spline plumbing of the declarative demos (de-boor, bspline-basis, multiplicity,
 * knot-insertion …): a state holds `points`, `degree`, `knots` (and maybe `weights`, `u`); this
 * module checks the knots by asking the core, builds the wasm curve from such a state, and keeps
 * the parameter u inside the domain when the knots change.
 *
 * Conventions (syllabus §3): n + 1 control points P₀ … P_n of degree p need m + 1 = n + p + 2
 * non-decreasing knots u₀ … u_m, no value more than p + 1 times; the curve is defined on the
 * domain [u_p, u_{n+1}], which must not be empty.
 */
import { checkNumber, checkNumbers } from "./validate.js";
import { flatten } from "./geometry.js";
import { loadedWasm } from "./wasm.js";
import { t } from "./strings.js";
import { errorText } from "./core-errors.js";

/** The new wasm curve for `{ points, degree, knots, weights? }` (throws the core's refusal). */
export function bsplineCurve(sl, { points, degree, knots, weights = undefined }) {
  const flat = flatten(points);
  const u = Float64Array.from(knots);
  if (!weights) return new sl.BSplineCurve(flat, 2, degree, u);
  return new sl.BSplineCurve(flat, 2, degree, u, Float64Array.from(weights));
}

/**
 * The core's clamped uniform knot vector for these points and degree (`knotVector(…,
 * "clamped")`): p + 1 zeros, 1 … n − p, p + 1 copies of n − p + 1. `points` are `[x, y]` pairs
 * or already flat.
 */
export function clampedKnots(sl, points, degree) {
  const flat = points instanceof Float64Array ? points : flatten(points);
  return Array.from(sl.knotVector(flat, 2, degree, "clamped"));
}

/**
 * The state with the core's clamped uniform knots for its points and degree (after the number
 * of points or the degree changed) and its parameter `param` (if it has one) clamped into
 * their domain.
 */
export function withClampedKnots(sl, state, { param = "u" } = {}) {
  const knots = clampedKnots(sl, state.points, state.degree);
  const next = { ...state, knots };
  if (param && param in state) next[param] = clampInto(state[param], domainOf(knots, state.degree));
  return next;
}

/**
 * The domain [u_p, u_{n+1}] of knots u₀ … u_m of degree p (n + 1 = m − p). Read from the state,
 * a slider's `range` follows the knots: `slider("u", { range: (s) => domainOf(s.knots, s.degree) })`.
 */
export function domainOf(knots, degree) {
  return [knots[degree], knots[knots.length - degree - 1]];
}

/** u clamped into [a, b]. */
export function clampInto(u, [a, b]) {
  return Math.min(b, Math.max(a, u));
}

/** Control points and degree of a state, as the knot checks read them (overridable per demo). */
const STATE_COUNT = (s) => s.points.length;
const STATE_DEGREE = (s) => s.degree;

/**
 * Why the core refuses `knots` for `count` control points of degree p (its message: count
 * n + p + 2, order, empty domain, multiplicity above p + 1), or null when it accepts them (or
 * the package is not loaded yet; the curve's constructor checks again).
 */
export function knotsRefusal(count, degree, knots) {
  const sl = loadedWasm();
  if (!sl) return null;
  let probe = null;
  try {
    probe = new sl.BSplineCurve(new Float64Array(2 * count), 2, degree, Float64Array.from(knots));
    return null;
  } catch (err) {
    return errorText(err);
  } finally {
    probe?.free();
  }
}

/**
 * The field checker (validate.js `field` style) of a knot vector: a list of numbers that the
 * core accepts for `count(state)` control points of degree `degree(state)`, else the core's
 * message after the field's name. List it after the points and the degree in `fields` (they
 * are checked first).
 */
export function knotsField({ count = STATE_COUNT, degree = STATE_DEGREE } = {}) {
  return (state, name) => {
    checkNumbers(state, name);
    const message = knotsRefusal(count(state), degree(state), state[name]);
    if (message) throw new Error(t("error.knots", { field: name, message }));
  };
}

/**
 * The field checker of a parameter in the domain of the knots (list it after them): a finite
 * number, then `error` (a strings.js key given `{ field, a, b, u }`) outside the domain.
 */
export function parameterField({ error, knots = "knots", degree = STATE_DEGREE }) {
  return (state, name) => {
    checkNumber(state, name);
    const [a, b] = domainOf(state[knots], degree(state));
    const u = state[name];
    if (u < a || u > b) throw new Error(t(error, { field: name, a, b, u }));
  };
}

/**
 * Sets new knots through the demo's `ui` (demo.js), after asking the core: on a refusal the
 * status line says why ("That change was refused: …"), nothing changes and the result is
 * false. The parameter field `param` (if the state has it) moves into the new domain when it
 * fell outside (an end knot dragged). `final` commits (undo step, URL), `merge` joins nudges.
 */
export function setKnots(ui, knots, final = true, options = {}) {
  const {
    field = "knots",
    param = "u",
    count = STATE_COUNT,
    degree = STATE_DEGREE,
    merge = null,
  } = options;
  const message = knotsRefusal(count(ui.state), degree(ui.state), knots);
  if (message) {
    ui.status(t("status.rejected", { message }), "error");
    return false;
  }
  ui.set(field, knots, false);
  if (param && param in ui.state) {
    const u = clampInto(ui.state[param], domainOf(knots, degree(ui.state)));
    if (u !== ui.state[param]) ui.set(param, u, false);
  }
  if (final) ui.commit(merge);
  return true;
}
