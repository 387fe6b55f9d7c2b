/**
 * Worked examples of the lecture notes that several demos start from (syllabus.md), frozen so a
 * demo's default state cannot be changed by accident.
 */

/** A list of [x, y] points, frozen all the way down. */
export function frozenPoints(points) {
  return Object.freeze(points.map((p) => Object.freeze([...p])));
}

/**
 * The cubic of the Greek notes (syllabus §2): P₀ = (0, 0), P₁ = (2, 2), P₂ = (6, 4), P₃ = (8, 2);
 * de Casteljau at t = 1/4 gives P(1/4) = (29/16, 23/16).
 */
export const NOTES_CUBIC = frozenPoints([
  [0, 0],
  [2, 2],
  [6, 4],
  [8, 2],
]);
