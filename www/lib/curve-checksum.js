/**
 * A checksum of a sampled curve for tests (a `data-curve-sum` attribute): Σ_j (j + 1)(x_j + √2 y_j)
 * over the flat samples [x₀, y₀, x₁, y₁, …]. The weights j + 1 make it depend on where along the
 * parameter each point lies and √2 mixes the coordinates, so an operation that must leave the
 * curve itself unchanged (knot insertion, degree elevation) must leave the sum unchanged too (up
 * to rounding), while a moved point changes it.
 */

/** The checksum of the first `count` samples. */
export function curveChecksum(samples, count) {
  let sum = 0;
  for (let j = 0; j < count; j++)
    sum += (j + 1) * (samples[2 * j] + Math.SQRT2 * samples[2 * j + 1]);
  return sum;
}
