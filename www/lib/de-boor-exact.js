/**
 * Exact values of de Boor's triangle at u. When u is a simple fraction and every control point
 * and knot is an integer, each α_j^r = (u − u_lo)/(u_hi − u_lo) has a denominator dividing
 * den(u)·(u_hi − u_lo), and a level-r point d_j^r = (1 − α) d_{j−1}^{r−1} + α d_j^{r−1} has one
 * dividing lcm(den of its two parents) · den(α). The bound is tracked per cell; beyond
 * MAX_EXACT_DENOMINATOR (or without exact inputs) the values are shown as decimals. The values
 * themselves are the core's (`deBoor(u)`, `deBoorAlphas(u)`); this only finds their fractions.
 */
import {
  fmt,
  fmtTex,
  simpleFraction,
  exactFraction,
  fractionText,
  fractionTex,
  allIntegers,
  MAX_EXACT_DENOMINATOR,
} from "./format.js";

/** Greatest common divisor / least common multiple of positive integers. */
function gcd(a, b) {
  while (b) [a, b] = [b, a % b];
  return a;
}
const lcm = (a, b) => (a / gcd(a, b)) * b;

/**
 * The core's α of every step (`deBoorAlphas(u)`: [r, j, lo, hi, u_hi − u_lo, α] per step, level
 * by level, j ascending), grouped by level r: `levels[r − 1]` = `[{ j, lo, hi, width, value }]`.
 */
export function alphasByLevel(data) {
  const levels = [];
  for (let a = 0; a < data.length; a += 6) {
    const level = data[a];
    if (levels.length < level) levels.push([]);
    const [j, lo, hi, width, value] = data.subarray(a + 1, a + 6);
    levels[level - 1].push({ j, lo, hi, width, value });
  }
  return levels;
}

/**
 * The text of the triangle's numbers for parameter `u`, integer inputs `inputs` (points and
 * knots, flat), degree `p` and `alphas` from `alphasByLevel`: `exact` (u's fraction or null),
 * `coord(value, level, i, tex)` (a coordinate of point i of level r), `alpha(alpha, tex)`,
 * `apexExact` (C(u) = d_p^p has an exact value).
 */
export function deBoorExact(u, inputs, p, alphas) {
  const f = simpleFraction(u);
  const exact = f && allIntegers(inputs) ? f : null;
  const alphaFraction = (alpha) =>
    exact ? exactFraction(alpha.value, exact.den * alpha.width) : null;
  const dens = [new Array(p + 1).fill(1)];
  for (let level = 1; level <= p; level++) {
    const row = [];
    for (let i = 0; i <= p - level; i++) {
      const g = alphaFraction(alphas[level - 1][i]);
      const bound = g ? lcm(dens[level - 1][i], dens[level - 1][i + 1]) * g.den : Infinity;
      row.push(bound <= MAX_EXACT_DENOMINATOR ? bound : Infinity);
    }
    dens.push(row);
  }
  const asText = (g, tex) => (tex ? fractionTex(g) : fractionText(g));
  return {
    exact,
    /** Point i of level r's coordinate. */
    coord(value, level, i, tex) {
      const den = dens[level][i];
      const g = exact && Number.isFinite(den) ? exactFraction(value, den) : null;
      return g ? asText(g, tex) : tex ? fmtTex(value) : fmt(value);
    },
    alpha(alpha, tex) {
      const g = alphaFraction(alpha);
      return g ? asText(g, tex) : tex ? fmtTex(alpha.value) : fmt(alpha.value);
    },
    apexExact: Number.isFinite(dens[p][0]),
  };
}
