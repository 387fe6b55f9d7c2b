/**
 * A piecewise cubic Hermite curve with one tangent per data point, or with one interior point
 * "unlocked" (a G¹ join): since `hermiteSpline` carries one tangent per point, the unlocked curve
 * is two core splines meeting at P_k, the left one ending with the incoming tangent
 * m_k⁻ = λ·m_k (λ = `state.ratio`), the right one starting with m_k⁺ = m_k. State:
 * `{ points, tangents, unlocked, joint: k, ratio: λ }`, parameters t_i = i (the core's
 * uniform `parameterize`).
 *
 * `hermiteParts(sl, state)` → `{ splines, firsts, params }`: the core splines, the index of the
 * first point of each, the parameters; `partOf(model, state, t)` → the spline that holds t (the
 * right one at the joint) and the piece's data; `pieceBezier(model, i)` → q0 … q3 of piece i from
 * the core's `toBezier()`; `jointVerdicts(sl, model)` → the core's `{ c, g }` at every interior
 * point (`CompositeBezier.continuity()` of all the pieces), `verdictText(joint)` its words ("C¹",
 * "G¹ only"); `movePoint` / `applyTangents` take a moved point / the state's tangents into the
 * splines in place (`setPoint`, `setTangent`).
 */
import { flatten } from "./geometry.js";
import { orderText } from "./continuity.js";
import { t } from "./strings.js";

/** Whether the state has a G¹ point: unlocked and an interior point to unlock. */
const split = (s) => s.unlocked && s.points.length > 2;

/** The core spline(s) of the state; see the module doc. */
export function hermiteParts(sl, s) {
  const n = s.points.length - 1;
  const params = Float64Array.from(sl.parameterize(flatten(s.points), 2, "uniform"));
  if (!split(s))
    return {
      splines: [sl.hermiteSpline(flatten(s.points), 2, params, flatten(s.tangents))],
      firsts: [0],
      params,
    };
  const k = s.joint;
  const incoming = s.tangents
    .slice(0, k + 1)
    .map((m, i) => (i === k ? [s.ratio * m[0], s.ratio * m[1]] : m));
  const left = sl.hermiteSpline(
    flatten(s.points.slice(0, k + 1)),
    2,
    params.slice(0, k + 1),
    flatten(incoming),
  );
  try {
    const right = sl.hermiteSpline(
      flatten(s.points.slice(k)),
      2,
      params.slice(k, n + 1),
      flatten(s.tangents.slice(k)),
    );
    return { splines: [left, right], firsts: [0, k], params };
  } catch (err) {
    left.free();
    throw err;
  }
}

/**
 * The part holding t (the right one at the joint), the piece i with t_i ≤ t < t_{i+1} (the last
 * one at the end), u, Δ and the data the piece is made of: P_i, P_{i+1}, m_i and m_{i+1} (λ·m_k
 * when P_{i+1} is the unlocked point).
 */
export function partOf(m, s, t) {
  const { params, firsts, splines } = m;
  const n = params.length - 1;
  let i = 0;
  while (i < n - 1 && t >= params[i + 1]) i++;
  const index = firsts.length > 1 && i >= firsts[1] ? 1 : 0;
  const delta = params[i + 1] - params[i];
  const incoming = split(s) && i + 1 === s.joint ? s.ratio : 1;
  const m1 = s.tangents[i + 1];
  return {
    index,
    spline: splines[index],
    piece: i,
    local: i - firsts[index],
    u: (t - params[i]) / delta,
    delta,
    p0: s.points[i],
    p1: s.points[i + 1],
    m0: s.tangents[i],
    m1: [incoming * m1[0], incoming * m1[1]],
  };
}

/** q0 … q3 (flat, 8 numbers) of piece i, from the core's Bézier form of its spline. */
export function pieceBezier(m, i) {
  const index = m.firsts.length > 1 && i >= m.firsts[1] ? 1 : 0;
  const composite = m.splines[index].toBezier();
  try {
    const piece = composite.piece(i - m.firsts[index]);
    const points = piece.controlPoints();
    piece.free();
    return points;
  } finally {
    composite.free();
  }
}

/** The core's continuity `{ c, g }` at P_1 … P_{n−1}: every piece's Bézier form in one `CompositeBezier`. */
export function jointVerdicts(sl, m) {
  const points = [];
  for (const spline of m.splines) {
    const composite = spline.toBezier();
    for (let j = 0; j < composite.pieceCount; j++) {
      const piece = composite.piece(j);
      points.push(...piece.controlPoints());
      piece.free();
    }
    composite.free();
  }
  const count = m.params.length - 1;
  if (count < 2) return [];
  const whole = new sl.CompositeBezier(
    new Float64Array(points),
    2,
    new Float64Array(count).fill(3),
    m.params,
  );
  try {
    return whole.continuity();
  } finally {
    whole.free();
  }
}

/** "C¹", "G¹ only", "C⁰ only" or the break word: the core's verdict at one joint. */
export function verdictText({ c, g }) {
  if (c >= 1) return orderText("C", c);
  if (c === 0 && g >= 1) return t("hermite.g1Only");
  if (c === 0) return t("hermite.c0Only");
  return t("knotRuler.break");
}

const scratch = new Float64Array(2);

/** Point i moved to `xy`: `setPoint` in the spline(s) holding it (both at the unlocked point). */
export function movePoint(m, i, xy) {
  m.splines.forEach((spline, index) => {
    const first = m.firsts[index];
    const next = index + 1 < m.firsts.length ? m.firsts[index + 1] : Infinity;
    if (i >= first && i <= next) spline.setPoint(i - first, xy);
  });
}

/** The state's tangents (and λ at the unlocked point) into the splines (in place: `setTangent`). */
export function applyTangents(m, s) {
  m.splines.forEach((spline, index) => {
    const first = m.firsts[index];
    const last = index + 1 < m.firsts.length ? m.firsts[index + 1] : s.points.length - 1;
    for (let i = first; i <= last; i++) {
      const factor = index === 0 && m.firsts.length > 1 && i === last ? s.ratio : 1;
      scratch[0] = factor * s.tangents[i][0];
      scratch[1] = factor * s.tangents[i][1];
      spline.setTangent(i - first, scratch);
    }
  });
}
