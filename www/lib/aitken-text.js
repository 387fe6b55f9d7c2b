/**
 * Lagrange interpolation and Aitken's triangle as text: exact numbers, the formula panel's
 * lines and the two tables of the `lagrange` demo. Nothing is evaluated here; the numbers are
 * the core's (`aitken(t)`, `basis(t)`), written as fractions when they are fractions.
 *
 * Exact text: when t = a/d is a simple fraction and the parameters and points are integers, a
 * value that combines the nodes t_i … t_{i+r},
 *
 *   p_i^r = Σ_{j=i}^{i+r} ℓ_j(t) p_j,   ℓ_j(t) = Π_{k≠j} (t − t_k)/(t_j − t_k),
 *
 * has a denominator dividing d^r · lcm_j Π_{k≠j} |t_j − t_k| (r factors (a − d t_k)/d above, an
 * integer below); `exactFraction` with that bound recognises it, else 3 decimals are shown.
 */
import { el, setText } from "./controls.js";
import {
  fmt,
  fmtTex,
  pointTex,
  pointText,
  texListSeparator,
  subscript,
  superscript,
  simpleFraction,
  exactFraction,
  fractionText,
  fractionTex,
  allIntegers,
  shortNumber,
} from "./format.js";
import { t } from "./strings.js";
import { titledTable, headerRow, valueSpans, setValueSpans } from "./table.js";
import { legendRow } from "./basis-plot.js";
import { levelStart } from "./triangle.js";

/** The formula lists this many parameters, then “…” and the last one. */
const LISTED_PARAMS = 7;

const gcd = (a, b) => {
  let x = Math.abs(a);
  let y = Math.abs(b);
  while (y) [x, y] = [y, x % y];
  return x;
};

/** d^r · lcm_j Π_{k≠j} |t_j − t_k| over the nodes i … i + r (Infinity when it grows past 2^53). */
function nodesDenominator(params, i, r, d) {
  let l = 1;
  for (let j = i; j <= i + r; j++) {
    let product = 1;
    for (let k = i; k <= i + r; k++) if (k !== j) product *= Math.abs(params[j] - params[k]);
    l = (l / gcd(l, product)) * product;
  }
  const den = d ** r * l;
  return Number.isSafeInteger(den) ? den : Infinity;
}

/**
 * Texts of t and of the numbers at t: `param(tex)`; `level(x, i, r, tex)` a coordinate of
 * p_i^r; `basis(x, n, tex)` an L_i(t) (or their sum); `weight(x, i, r, tex)` an Aitken weight
 * (t − t_i)/(t_{i+r} − t_i) or its complement. Fractions when `exact` (see the module's doc).
 */
export function exactness(s, params) {
  const f = simpleFraction(s.t);
  const exact = f && allIntegers(params) && allIntegers(s.points.flat()) ? f : null;
  const text = (x, den, tex) => {
    const g = exact ? exactFraction(x, den) : null;
    if (!g) return tex ? fmtTex(x) : fmt(x);
    return tex ? fractionTex(g) : fractionText(g);
  };
  return {
    exact,
    param: (tex = false) =>
      exact ? (tex ? fractionTex(exact) : fractionText(exact)) : tex ? fmtTex(s.t) : fmt(s.t),
    level: (x, i, r, tex = false) =>
      text(x, exact ? nodesDenominator(params, i, r, exact.den) : 1, tex),
    basis: (x, n, tex = false) =>
      text(x, exact ? nodesDenominator(params, 0, n, exact.den) : 1, tex),
    weight: (x, i, r, tex = false) =>
      text(x, exact ? exact.den * (params[i + r] - params[i]) : 1, tex),
  };
}

/** The parameters as TeX: t_0 … t_n, the long lists cut after LISTED_PARAMS. */
function paramsTex(params) {
  const n = params.length - 1;
  const shown = Array.from(params.slice(0, Math.min(n + 1, LISTED_PARAMS)), (x) =>
    shortNumber(x, true),
  );
  if (n + 1 > LISTED_PARAMS) shown.push("\\dots", shortNumber(params[n], true));
  return `(t_0, \\dots, t_{${n}}) = (${shown.join(texListSeparator())})`;
}

/** A point of the triangle as TeX "(x, y)". */
function trianglePointTex(num, triangle, n, i, r) {
  const k = 2 * (levelStart(n, r) + i);
  return pointTex([num.level(triangle[k], i, r, true), num.level(triangle[k + 1], i, r, true)]);
}

/**
 * The formula panel: the Lagrange form with the parameters, Aitken's recurrence, its last step
 * p_0^n from p_0^{n−1} and p_1^{n−1} with the weights at t, and the sum and sign of the L_i(t).
 */
export function lagrangeFormula(s, d, fit) {
  const n = s.points.length - 1;
  const num = d.exact;
  const params = fit.params;
  const tTex = num.param(true);
  const wRight = (s.t - params[0]) / (params[n] - params[0]);
  const lines = [
    `P(t) = \\sum_{i=0}^{${n}} L_i(t)\\,p_i,\\quad L_i(t) = \\prod_{j \\ne i} \\frac{t - t_j}{t_i - t_j},\\quad ${paramsTex(params)}`,
    `p_i^{r} = \\frac{t_{i+r} - t}{t_{i+r} - t_i}\\,p_i^{r-1} + \\frac{t - t_i}{t_{i+r} - t_i}\\,p_{i+1}^{r-1},\\quad p_i^0 = p_i,\\quad t = ${tTex}`,
    `P(${tTex}) = p_0^{${n}} = ${num.weight(1 - wRight, 0, n, true)}\\,p_0^{${n - 1}} + ${wrapSign(num.weight(wRight, 0, n, true))}\\,p_1^{${n - 1}}` +
      ` = ${trianglePointTex(num, d.triangle, n, 0, n)}`,
  ];
  let sum = 0;
  let low = 0;
  for (let i = 0; i <= n; i++) {
    sum += d.basis[i];
    if (d.basis[i] < d.basis[low]) low = i;
  }
  const sign = d.basis[low] < 0 ? "< 0" : "\\ge 0";
  lines.push(
    `\\sum_i L_i(${tTex}) = ${num.basis(sum, n, true)},\\qquad \\min_i L_i(${tTex}) = L_{${low}}(${tTex}) = ${num.basis(d.basis[low], n, true)} ${sign}`,
  );
  return lines;
}

/** A negative coefficient in brackets after "+". */
const wrapSign = (tex) => (tex.startsWith("-") ? `\\left(${tex}\\right)` : tex);

/**
 * The two tables under the figure: the basis at t (one legend row per L_i: t_i, L_i(t), p_i;
 * then the sum) and Aitken's triangle (row r: the points p_i^r). Rows are rebuilt only when the
 * number of points changed.
 */
export class LagrangeTables {
  constructor(ui, pointer) {
    this.pointer = pointer;
    this.count = -1;
    const basis = titledTable("lagrange-basis");
    const triangle = titledTable("aitken");
    ui.ctx.slots.details.append(basis.title, basis.wrap, triangle.title, triangle.wrap);
    this.basis = basis;
    this.triangle = triangle;
  }

  /** Rows for n + 1 points. */
  build(n) {
    this.count = n + 1;
    this.rows = [];
    const head = headerRow("lagrange.", ["colFunction", "colParam", "colValue", "colPoint"]);
    for (let i = 0; i <= n; i++) {
      const cells = { param: el("td"), value: valueSpans(), point: el("td") };
      cells.row = legendRow(
        this.pointer,
        i,
        `L${subscript(i)}`,
        cells.param,
        el("td", { dataset: { cell: "value" } }, cells.value.exact, cells.value.decimal),
        cells.point,
      );
      this.rows.push(cells);
    }
    this.sum = valueSpans();
    const sumRow = el(
      "tr",
      { dataset: { index: "sum" } },
      el("th", { scope: "row", text: t("lagrange.sumRow") }),
      el("td"),
      el("td", { dataset: { cell: "value" } }, this.sum.exact, this.sum.decimal),
      el("td"),
    );
    this.basis.table.replaceChildren(
      el("thead", {}, head),
      el(
        "tbody",
        {},
        this.rows.map((c) => c.row),
        sumRow,
      ),
    );
    this.cells = [];
    const levels = [];
    for (let r = 0; r <= n; r++) {
      const row = [el("th", { scope: "row", text: t("lagrange.tableLevel", { r }) })];
      for (let i = 0; i + r <= n; i++) {
        const spans = valueSpans();
        this.cells.push(spans);
        const name = r === 0 ? `p${subscript(i)} = ` : `p${subscript(i)}${superscript(r)} = `;
        row.push(
          el(
            "td",
            { dataset: { level: String(r), index: String(i) } },
            el("span", { class: "sl-cell-name", text: name }),
            spans.exact,
            spans.decimal,
          ),
        );
      }
      levels.push(el("tr", {}, row));
    }
    this.triangle.table.replaceChildren(el("tbody", {}, levels));
  }

  /** Fills both tables from the state and the core's numbers at t. */
  show(s, d, fit) {
    const n = s.points.length - 1;
    if (this.count !== n + 1) this.build(n);
    const num = d.exact;
    setText(this.basis.title, t("lagrange.basisCaption", { t: num.param() }));
    let sum = 0;
    for (let i = 0; i <= n; i++) {
      const value = d.basis[i];
      sum += value;
      const cells = this.rows[i];
      setText(cells.param, shortNumber(fit.params[i]));
      const exact = num.basis(value, n);
      setValueSpans(cells.value, exact, /^-?\d+$/.test(exact) ? exact : fmt(value));
      setText(cells.point, pointText([shortNumber(s.points[i][0]), shortNumber(s.points[i][1])]));
      cells.row.classList.toggle("sl-highlight", i === d.highlight);
      cells.row.classList.toggle("sl-negative", value < 0);
    }
    const sumText = num.basis(sum, n);
    setValueSpans(this.sum, sumText, /^\d+$/.test(sumText) ? sumText : fmt(sum));
    setText(this.triangle.title, t("lagrange.triangleCaption", { t: num.param() }));
    let k = 0;
    for (let r = 0; r <= n; r++) {
      for (let i = 0; i + r <= n; i++, k++) {
        const x = d.triangle[2 * k];
        const y = d.triangle[2 * k + 1];
        const decimals = pointText([x, y]);
        const exact = num.exact ? pointText([num.level(x, i, r), num.level(y, i, r)]) : decimals;
        setValueSpans(this.cells[k], exact, decimals);
      }
    }
  }
}
