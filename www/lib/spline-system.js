/**
 * The tangent system of a C2 cubic spline (`CubicSpline.system()`): its entries, and its
 * equations written out for the formula panel (TeX) and the table's row labels (text), with the current numbers where they help. The unknowns are
 * the tangents m_i = C′(t_i); Δ_i = t_{i+1} − t_i; d_i = (p_{i+1} − p_i)/Δ_i. Interior row i
 * (C″ continuous at t_i):
 *
 *   Δ_i m_{i−1} + 2(Δ_{i−1} + Δ_i) m_i + Δ_{i−1} m_{i+1} = 3(Δ_i d_{i−1} + Δ_{i−1} d_i).
 *
 * End rows, derived from the Hermite form (the Greek notes print the far-end rows of the natural
 * and quadratic conditions with wrong factors; these are the derived ones):
 * - natural, C″(t_0) = 0:              2m_0 + m_1 = 3 d_0;         m_{n−1} + 2m_n = 3 d_{n−1}
 * - quadratic, C″(t_0) = C″(t_1):      m_0 + m_1 = 2 d_0;          m_{n−1} + m_n = 2 d_{n−1}
 * - clamped:                           m_0, m_n given
 * - Bessel (the parabola through the first / last three points):
 *     m_0 = ((2Δ_0 + Δ_1) d_0 − Δ_0 d_1)/(Δ_0 + Δ_1), likewise mirrored at the end
 * - not-a-knot, C‴ continuous at t_1 (and t_{n−1}), m_2 eliminated with row 1 so the system
 *   stays tridiagonal: Δ_1 m_0 + (Δ_0 + Δ_1) m_1 = ((3Δ_0 + 2Δ_1) Δ_1 d_0 + Δ_0² d_1)/(Δ_0 + Δ_1)
 * - periodic (p_N = p_0, m_N = m_0): row 0 is the interior row at t_0 ≡ t_N, wrapping to
 *   m_{N−1} (a corner of the cyclic matrix), likewise row N − 1 wraps to m_0.
 * The numbers in the rows shown come from the core's `system()`; nothing is solved here.
 */
import { fmt, pointTex, shortNumber, subscript, texListSeparator } from "./format.js";
import { t } from "./strings.js";
import { rowPoint } from "./system-table.js";

/** Δ's written out at most this many; more are elided in the middle. */
const MAX_DELTAS = 8;

const text = (key) => `\\text{${t(key)}}`;

/** Whose end rows condition `end` has with `n` pieces: not-a-knot with 3 points is the parabola (quadratic's). */
const rowsOf = (end, n) => (end === "not-a-knot" && n === 2 ? "quadratic" : end);

/** The interior row in general (syllabus §5). */
export function interiorRowTex() {
  return (
    "\\Delta_i m_{i-1} + 2(\\Delta_{i-1}+\\Delta_i)\\,m_i + \\Delta_{i-1} m_{i+1} = " +
    "3\\Big(\\tfrac{\\Delta_i}{\\Delta_{i-1}}(p_i-p_{i-1}) + " +
    "\\tfrac{\\Delta_{i-1}}{\\Delta_i}(p_{i+1}-p_i)\\Big)"
  );
}

/** "Δ_i = t_{i+1} − t_i: 1, 1, …, 1 (uniform)" with the current params. */
export function deltasTex(params, kindName) {
  const deltas = [];
  for (let i = 0; i + 1 < params.length; i++)
    deltas.push(shortNumber(params[i + 1] - params[i], true));
  const shown =
    deltas.length <= MAX_DELTAS
      ? deltas
      : [...deltas.slice(0, MAX_DELTAS - 3), "\\dots", ...deltas.slice(-2)];
  return `\\Delta_i = t_{i+1} - t_i:\\ ${shown.join(texListSeparator())}\\quad (${text("cubicSpline.tex.params")}\\ ${`\\text{${kindName}}`})`;
}

/** A coefficient times m_j, signed for a sum ("+ 4\,m_1", "− 0.5\,m_2"); "" for a zero. */
function term(a, j, first) {
  if (a === 0) return "";
  const sign = a < 0 ? "-" : first ? "" : "+";
  return `${sign} ${shortNumber(Math.abs(a), true)}\\,m_{${j}}`;
}

/** Row i of the system with its numbers: "i = 1: 1 m₀ + 4 m₁ + 1 m₂ = (x, y)". */
export function numericRowTex(system, i, size) {
  const terms = [];
  for (let j = 0; j < size; j++) {
    const a = systemEntry(system, size, i, j);
    const part = term(a, j, terms.length === 0);
    if (part) terms.push(part);
  }
  const rhs = pointTex([
    shortNumber(system.rhs[2 * i], true),
    shortNumber(system.rhs[2 * i + 1], true),
  ]);
  return `${terms.join(" ")} = ${rhs}`;
}

/** The start (`side` "start") or end row of condition `end` in general, with its indices. */
function endEquationTex(end, side, n) {
  const start = side === "start";
  // Indices: the end point b, its neighbour a, the next one c (a Bessel parabola's third point).
  const [b, a, c] = start ? [0, 1, 2] : [n, n - 1, n - 2];
  const [da, dc] = start
    ? ["\\Delta_0", "\\Delta_1"]
    : [`\\Delta_{${n - 1}}`, `\\Delta_{${n - 2}}`];
  const [pa, pb] = start ? ["p_1 - p_0", "p_0"] : [`p_{${n}} - p_{${n - 1}}`, `p_{${n}}`];
  const d = (k) => `d_{${k}}`;
  const near = start ? 0 : n - 1;
  const far = start ? 1 : n - 2;
  switch (end) {
    case "natural":
      return start
        ? `C''(t_0) = 0:\\ 2m_0 + m_1 = \\tfrac{3}{${da}}(${pa})`
        : `C''(t_{${n}}) = 0:\\ m_{${a}} + 2m_{${b}} = \\tfrac{3}{${da}}(${pa})`;
    case "quadratic":
      return `C''(t_{${b}}) = C''(t_{${a}}):\\ m_{${Math.min(a, b)}} + m_{${Math.max(a, b)}} = \\tfrac{2}{${da}}(${pa})`;
    case "clamped":
      return `m_{${b}}\\ ${text("cubicSpline.tex.given")}\\ (${text("cubicSpline.tex.arrow")}\\ ${pb})`;
    case "bessel":
      return (
        `m_{${b}} = \\frac{(2${da} + ${dc})\\,${d(near)} - ${da}\\,${d(far)}}{${da} + ${dc}},\\ ` +
        `d_i = \\tfrac{p_{i+1}-p_i}{\\Delta_i}\\ (${text("cubicSpline.tex.parabola")}\\ p_{${Math.min(b, c)}}, p_{${a}}, p_{${Math.max(b, c)}})`
      );
    case "not-a-knot":
      return start
        ? "C'''(t_1^-) = C'''(t_1^+):\\ \\Delta_1 m_0 + (\\Delta_0+\\Delta_1)\\,m_1 = " +
            "\\frac{(3\\Delta_0+2\\Delta_1)\\Delta_1 d_0 + \\Delta_0^2 d_1}{\\Delta_0+\\Delta_1}"
        : `C'''(t_{${a}}^-) = C'''(t_{${a}}^+):\\ (${dc} + ${da})\\,m_{${a}} + ${dc}\\,m_{${n}} = ` +
            `\\frac{(3${da} + 2${dc})${dc}\\,${d(near)} + ${da}^2\\,${d(far)}}{${da} + ${dc}}`;
    default:
      return start
        ? `m_{${n}} = m_0,\\ C''(t_0^+) = C''(t_{${n}}^-)`
        : `C''\\ ${text("cubicSpline.tex.continuous")}\\ t_{${n - 1}},\\ m_{${n}} = m_0`;
  }
}

/**
 * The formula line of an end row in general: "start: C″(t₀) = 0: 2m₀ + m₁ = 3/Δ₀ (p₁ − p₀)"
 * (`side` "start" or "end", `n` pieces).
 */
export function endRowTex(condition, side, n) {
  const end = rowsOf(condition, n);
  return `${text(`cubicSpline.tex.${side}`)}:\\ ${endEquationTex(end, side, n)}`;
}

/** The first and last rows as the core built them: "i = 0: 2 m₀ + 1 m₁ = (3, 9); i = 5: …". */
export function endRowsNumericTex(system, size) {
  const row = (i) => `i = ${i}:\\ ${numericRowTex(system, i, size)}`;
  return `${row(0)};\\qquad ${row(size - 1)}`;
}

/**
 * The label of row i (of `size`) in the system's table for condition `end` (`n` pieces):
 * the equation of an end row, "C″ continuous at tᵢ" for the others.
 */
export function rowLabel(condition, i, size, n) {
  const end = rowsOf(condition, n);
  const sub = (k) => subscript(k);
  if (i > 0 && i < size - 1) return t("cubicSpline.row.interior", { i: sub(i) });
  const side = i === 0 ? "start" : "end";
  return t(`cubicSpline.row.${side}.${end}`, {
    n: sub(n),
    a: sub(n - 1),
    c: sub(n - 2),
    last: sub(size - 1),
  });
}

/**
 * Entry (i, j) of the matrix of `system()` (`size` equations): the diagonal, the bands beside it
 * (`lower[i − 1]` is a_{i,i−1}, `upper[i]` is a_{i,i+1}) and, for a cyclic (periodic) system,
 * the corners `corners` = [a_{0,N−1}, a_{N−1,0}]; 0 elsewhere.
 */
export function systemEntry(system, size, i, j) {
  if (i === j) return system.diagonal[i];
  if (j === i + 1) return system.upper[i];
  if (j === i - 1) return system.lower[i - 1];
  const corners = system.corners ?? [];
  if (corners.length === 2 && i === 0 && j === size - 1) return corners[0];
  if (corners.length === 2 && i === size - 1 && j === 0) return corners[1];
  return 0;
}

/** Rows and columns of the table shown at most, normally and in lecture mode. */
export const MAX_SHOWN = 9;
export const MAX_SHOWN_LECTURE = 5;

/** A number in lecture mode's table: an integer plain, else two decimals. */
function lectureNumber(v) {
  const r = Math.round(v);
  return Math.abs(v - r) < 1e-9 ? String(r) : fmt(v, 2);
}

/**
 * Shows the system a cubicSpline solved in a `SystemTable` (system-table.js) and its title:
 * `main` = `{ end, system, params }` (`system()`, `params()`), the end rows highlighted and
 * labelled with their equation, the corners of the cyclic (periodic) system marked. In lecture
 * mode fewer rows, two decimals and no solved values under the unknowns, so the table fits.
 * `parametrization`: the parameters' name for the title.
 */
export function showSplineSystem(table, { end, system, params }, { lecture, parametrization }) {
  const size = system.diagonal.length;
  const maxShown = lecture ? MAX_SHOWN_LECTURE : MAX_SHOWN;
  const number = lecture ? lectureNumber : shortNumber;
  const hidden = size > maxShown ? size - maxShown + 1 : 0;
  table.table.dataset.end = end;
  table.show({
    size,
    maxShown,
    number,
    entry: (i, j) => systemEntry(system, size, i, j),
    unknown: (i) => `m${subscript(i)}`,
    solution: (i) => (lecture ? "" : `= ${rowPoint(system.solution, i, 2, number)}`),
    rhs: (i) => rowPoint(system.rhs, i, 2, number),
    label: (i) => rowLabel(end, i, size, params.length - 1),
    highlight: (i) => i === 0 || i === size - 1,
    // The corners of the cyclic system: a_{0,N−1} and a_{N−1,0}.
    marked: (i, j) => end === "periodic" && size > 2 && Math.abs(i - j) === size - 1,
    caption: t(`cubicSpline.tableCaption${end === "periodic" ? "Cyclic" : ""}`, {
      size,
      end: t(`cubicSpline.end.${end}`),
      parametrization,
      hidden: hidden ? t("cubicSpline.tableHidden", { count: hidden }) : "",
    }),
  });
}
