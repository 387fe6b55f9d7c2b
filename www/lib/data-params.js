/**
 * The parametrisations of interpolation's data points (syllabus §5), as the core's
 * `parameterize(points, dim, kind)` computes them: t_0 = 0, t_{i+1} = t_i + |p_{i+1} − p_i|^α
 * with α = 0 ("uniform"), 1 ("chord") or 1/2 ("centripetal"). Here only what a demo's state needs
 * around them: the kinds a state field may take, and keeping a parameter at the same place of
 * the domain [t_0, t_n] when the points or the kind change.
 */
import { flatten } from "./geometry.js";

/** The named kinds, in the order the controls list them. */
export const PARAM_KINDS = Object.freeze(["uniform", "chord", "centripetal"]);

/** Rounding of a rescaled parameter: 12 significant digits (1/2 stays 0.5, not 0.49999999999). */
const SIGNIFICANT = 12;

/**
 * `next` with `next.t` moved from the domain `[a, b]` to the same fraction (t − a)/(b − a) of the
 * domain of `next` (its points and `next.params`), as the core parametrises them. When the core
 * refuses the new points (a repeated point under chord spacing), `next` is returned unchanged:
 * the rebuild that follows reports the refusal.
 */
export function withTIn(sl, next, [a, b]) {
  let params;
  try {
    params = sl.parameterize(flatten(next.points), 2, next.params);
  } catch {
    return next;
  }
  const a2 = params[0];
  const b2 = params[params.length - 1];
  const fraction = b > a ? (next.t - a) / (b - a) : 0;
  const value = Number((a2 + fraction * (b2 - a2)).toPrecision(SIGNIFICANT));
  next.t = Math.min(Math.max(value, a2), b2);
  return next;
}
