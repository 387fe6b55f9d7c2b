/**
 * A B-spline after a list of knot insertions s₁ … s_m, kept as two curves asked from the core:
 * `previous` = the original refined by s₁ … s_{m−1} (`refine`) and `current` = `previous`
 * with s_m inserted once (`insertKnot(s_m, 1)`, Boehm's rule), so a demo can show the last
 * insertion's polygon before and after. Both are the original itself when nothing was
 * inserted. Insertion changes the control points, never the curve.
 */

/**
 * The curves for `inserted` on `base`: `{ previous, current }`. Throws (after freeing what it
 * made) when the core refuses.
 */
export function refinedCurves(base, inserted) {
  if (inserted.length === 0) return { previous: base, current: base };
  const previous =
    inserted.length > 1 ? base.refine(Float64Array.from(inserted.slice(0, -1))) : base;
  try {
    return { previous, current: previous.insertKnot(inserted[inserted.length - 1], 1) };
  } catch (err) {
    if (previous !== base) previous.free();
    throw err;
  }
}

/**
 * Puts the curves for `inserted` into the model `m` in place (`m.base` the original,
 * `m.curves` → `{ previous, current }`); `m.refined` holds those the model owns (freed here when
 * replaced, and by the runtime with the model).
 */
export function refineInto(m, inserted) {
  const next = refinedCurves(m.base, inserted);
  for (const curve of m.refined) curve.free();
  m.refined.length = 0;
  for (const curve of new Set([next.previous, next.current]))
    if (curve !== m.base) m.refined.push(curve);
  m.curves.previous = next.previous;
  m.curves.current = next.current;
}
