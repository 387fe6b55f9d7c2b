/**
 * A plane homography (projective map) H as a row-major 3×3 Float64Array: the point (x, y) maps
 * to (x′, y′) = ((h₁₁x + h₁₂y + h₁₃) / d, (h₂₁x + h₂₂y + h₂₃) / d) with the denominator
 * d = h₃₁x + h₃₂y + h₃₃; in homogeneous coordinates (x, y, 1) ↦ H (x, y, 1)ᵀ. This is the map
 * itself (display and checks of the projective-invariance demo), not a curve algorithm: the
 * core maps curves (`BezierCurve#projectiveMap(H)`).
 */

/**
 * The homography sending the square [0, size]²'s corners S₀ = (0, 0), S₁ = (size, 0),
 * S₂ = (size, size), S₃ = (0, size) to `corners` Q₀ … Q₃ (a list of four [x, y]): the
 * unit-square-to-quadrilateral map (Heckbert 1989, "Fundamentals of texture mapping", §2.2.3)
 * after scaling the square to the unit square. With Δ₁ = Q₁ − Q₂, Δ₂ = Q₃ − Q₂ and
 * Σ = Q₀ − Q₁ + Q₂ − Q₃, the bottom row (g, h) solves [Δ₁ Δ₂] (g, h)ᵀ = Σ (Cramer's rule;
 * Σ = 0 is an affine map, g = h = 0); then a = x₁ − x₀ + g x₁, b = x₃ − x₀ + h x₃, c = x₀, and
 * likewise d, e, f with y. Three corners on a line give non-finite entries (the caller checks
 * `every(Number.isFinite)`). Writes into `out` when given.
 */
export function squareToQuad(corners, size, out = new Float64Array(9)) {
  const [[x0, y0], [x1, y1], [x2, y2], [x3, y3]] = corners;
  const sx = x0 - x1 + x2 - x3;
  const sy = y0 - y1 + y2 - y3;
  let g = 0;
  let h = 0;
  if (sx !== 0 || sy !== 0) {
    const dx1 = x1 - x2;
    const dx2 = x3 - x2;
    const dy1 = y1 - y2;
    const dy2 = y3 - y2;
    const det = dx1 * dy2 - dx2 * dy1;
    g = (sx * dy2 - dx2 * sy) / det;
    h = (dx1 * sy - sx * dy1) / det;
  }
  const a = x1 - x0 + g * x1;
  const b = x3 - x0 + h * x3;
  const d = y1 - y0 + g * y1;
  const e = y3 - y0 + h * y3;
  // Unit square → quadrilateral, composed with (x, y) ↦ (x, y) / size.
  out.set([a / size, b / size, x0, d / size, e / size, y0, g / size, h / size, 1]);
  return out;
}

/** The denominator d = h₃₁x + h₃₂y + h₃₃ of H at (x, y) (≤ 0: beyond the line at infinity). */
export function denominator(m, x, y) {
  return m[6] * x + m[7] * y + m[8];
}

/** H applied to (x, y), divided by the third coordinate, written into `out` [x′, y′]. */
export function applyHomography(m, x, y, out) {
  const w = denominator(m, x, y);
  out[0] = (m[0] * x + m[1] * y + m[2]) / w;
  out[1] = (m[3] * x + m[4] * y + m[5]) / w;
  return out;
}
