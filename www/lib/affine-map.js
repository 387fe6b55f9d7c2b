/**
 * A plane affine map about a centre c, Φ(x) = c + A(x − c), with the 2×2 matrix
 *
 *   A = R(θ) · f · H(k) = f · [[cos θ, k cos θ − sin θ], [sin θ, k sin θ + cos θ]],
 *
 * a rotation by θ degrees after a uniform scale f and a shear H(k) = [[1, k], [0, 1]] along x.
 * Drawing support for affine invariance (the map applied to control points and to samples, to
 * compare with the core's curve of the mapped points), not a curve algorithm. A matrix is the
 * row-major array [a, b, c, d] of [[a, b], [c, d]].
 */

/** The matrix R(θ)·f·H(k) for a rotation of `rotationDegrees`, a scale `scale`, a shear `shear`. */
export function affineMatrix(rotationDegrees, scale, shear) {
  const angle = (rotationDegrees * Math.PI) / 180;
  const c = Math.cos(angle);
  const sin = Math.sin(angle);
  const k = shear;
  const f = scale;
  // R·(f·H) with H = [[1, k], [0, 1]].
  return [f * c, f * (c * k - sin), f * sin, f * (sin * k + c)];
}

/** The centroid (1/n) Σ P_i of a list of [x, y] points. */
export function centroid(points) {
  const centre = [0, 0];
  for (const [x, y] of points) {
    centre[0] += x / points.length;
    centre[1] += y / points.length;
  }
  return centre;
}

/** Φ(x) = c + A(x − c) as a function (x, y) → [x′, y′] (a new array each call). */
export function affineMap(matrix, centre) {
  return (x, y) => [
    centre[0] + matrix[0] * (x - centre[0]) + matrix[1] * (y - centre[1]),
    centre[1] + matrix[2] * (x - centre[0]) + matrix[3] * (y - centre[1]),
  ];
}
