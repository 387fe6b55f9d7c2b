/**
 * The Cox–de Boor recurrence as TeX lines for a formula panel. The definition:
 *   N_{i,0}(u) = 1 on [u_i, u_{i+1}), 0 otherwise;
 *   N_{i,p}(u) = (u − u_i)/(u_{i+p} − u_i) N_{i,p−1}(u)
 *              + (u_{i+p+1} − u)/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}(u),
 * with 0/0 := 0 (a side whose knot difference vanishes is dropped); and one step of it with the
 * live numbers: the two ratios at u, the values N_{i,p−1}(u), N_{i+1,p−1}(u) of the row below
 * (from the core's `basisTable(u)`) and the result N_{i,p}(u) (the core's `basis(u)`).
 */
import { fmtTex } from "./format.js";
import { knotText } from "./knot-ruler.js";

/** The definition; `otherwise` is the TeX of the word "otherwise" (`\text{…}` from strings.js). */
export function coxDeBoorDefinition(otherwise) {
  const zero = `N_{i,0}(u) = \\begin{cases} 1 & u_i \\le u < u_{i+1} \\\\ 0 & ${otherwise} \\end{cases}`;
  const recurrence =
    "N_{i,p}(u) = \\frac{u-u_i}{u_{i+p}-u_i}\\,N_{i,p-1}(u) + \\frac{u_{i+p+1}-u}{u_{i+p+1}-u_{i+1}}\\,N_{i+1,p-1}(u)";
  return `${zero},\\qquad ${recurrence},\\quad \\tfrac{0}{0} := 0`;
}

/**
 * N_{i,p}(u) = (ratio) N_{i,p−1}(u) + (ratio) N_{i+1,p−1}(u) = numbers = `value`, for `knots`,
 * u (`uTex` its TeX), `below(i)` = N_{i,p−1}(u).
 */
export function coxDeBoorStep({ knots, u, uTex, p, i, below, value }) {
  const kt = (x) => knotText(x, true);
  const uText = kt(u);
  // One side: (num / den) N_{j, p−1}(u), or 0 when den = 0 (0/0 := 0).
  const side = (num, den, j, numTex, denTex) => {
    if (den === 0) return { part: "0", numbers: "0" };
    const part = `\\frac{${numTex}}{${denTex}}\\,N_{${j},${p - 1}}(${uTex})`;
    return { part, numbers: `${fmtTex(num / den)}\\cdot ${fmtTex(below(j))}` };
  };
  const [a, b, c, e] = [knots[i], knots[i + p], knots[i + 1], knots[i + p + 1]];
  const left = side(u - a, b - a, i, `${uText}-${kt(a)}`, `${kt(b)}-${kt(a)}`);
  const right = side(e - u, e - c, i + 1, `${kt(e)}-${uText}`, `${kt(e)}-${kt(c)}`);
  const numbers = `${left.numbers} + ${right.numbers}`;
  return `N_{${i},${p}}(${uTex}) = ${left.part} + ${right.part} = ${numbers} = ${fmtTex(value)}`;
}
