/**
 * The continuity a B-spline really has at each of its joints, measured rather than read off the
 * knots: the curve's Bézier segments (`toBezier()`) are placed on their spans [u_k, u_{k+1}]
 * (`BezierCurve.withInterval(points, 2, u_k, u_{k+1})`, so derivatives are with respect to u) and
 * each pair of neighbours is compared at their common knot by the core's
 * `jointContinuity(left, right)` → `{ c, g }`: the highest k with C^k (derivatives up to order k
 * equal) and the geometric order G^g (tangent directions, curvature …); c < 0 where they do not
 * meet. The guaranteed value C^{p−r} at a knot of multiplicity r is `knotContinuity()`; the
 * measured one can be higher (a special polygon) or show a lower G (repeated control points).
 */

/**
 * Per joint (the distinct interior knots, in order): `{ knot, c, g, left, right, speed, label }`
 * — the two segments' points at the knot, C′(knot) of `curve` and `label(knot)` (cached text).
 */
export function measuredJoints(sl, curve, knots, label) {
  const pieces = curve.toBezier();
  const spans = curve.spans(); // span index k of each segment: [u_k, u_{k+1}]
  const placed = [];
  for (let k = 0; k < pieces.length; k++) {
    const [a, b] = [knots[spans[k]], knots[spans[k] + 1]];
    placed.push(sl.BezierCurve.withInterval(pieces[k].controlPoints(), 2, a, b));
    pieces[k].free();
  }
  const joints = [];
  for (let k = 0; k + 1 < placed.length; k++) {
    const knot = knots[spans[k + 1]];
    const { c, g } = sl.jointContinuity(placed[k], placed[k + 1]);
    joints.push({
      knot,
      c,
      g,
      left: Array.from(placed[k].evaluate(knot)),
      right: Array.from(placed[k + 1].evaluate(knot)),
      speed: Array.from(curve.derivative(knot, 1)),
      label: label(knot),
    });
  }
  for (const piece of placed) piece.free();
  return joints;
}
