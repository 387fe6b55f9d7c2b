/**
 * Number formatting for labels, tables and formulas: fixed decimals, exact fractions when the
 * inputs allow them, and Unicode sub/superscripts for labels such as P₀ or p₁².
 *
 * Numbers people read follow the active language (strings.js `decimalSeparator`): `fmt` writes
 * "1.250" in English and "1,250" in Greek, Croatian and Italian, and with a decimal comma a list
 * or point separates its entries with "; " ("(1,5; 2)", `pointText`) — in Greek with the ano
 * teleia "· " ("(1,5· 2)"), since ";" is the Greek question mark. TeX gets its own forms
 * (`fmtTex`, `pointTex`, the `tex` flags): KaTeX spaces a bare comma as punctuation, so a decimal
 * comma is written "1{,}5". Text a machine reads — links, JSON, SVG and TikZ coordinates, data
 * attributes of tests — takes `fmtMachine`, always with a point.
 */
import { decimalSeparator, locale, t } from "./strings.js";

/** Decimals shown for parameters and coordinates (ui.md). */
export const DECIMALS = 3;
/** A parameter counts as a "simple fraction" when its denominator is at most this. */
export const MAX_SIMPLE_DENOMINATOR = 16;
/** Largest denominator worth showing as an exact fraction (beyond it, decimals read better). */
export const MAX_EXACT_DENOMINATOR = 1 << 20;
/** Relative tolerance when recognising a float as k/den (values come from f64 arithmetic). */
const FRACTION_TOLERANCE = 1e-9;

const SUBSCRIPTS = "₀₁₂₃₄₅₆₇₈₉";
const SUPERSCRIPTS = "⁰¹²³⁴⁵⁶⁷⁸⁹";

/** Digits of a non-negative integer written with Unicode subscripts: 12 → "₁₂". */
export function subscript(n) {
  return String(n).replace(/\d/g, (d) => SUBSCRIPTS[d]);
}

/** Digits of a non-negative integer written with Unicode superscripts: 2 → "²". */
export function superscript(n) {
  return String(n).replace(/\d/g, (d) => SUPERSCRIPTS[d]);
}

/** The name of a curve's degree for labels: "linear", "quadratic", "cubic", … then "degree 7". */
export function degreeName(n) {
  return n <= 5 ? t(`curve.degree.${n}`) : t("curve.degree.n", { n });
}

/**
 * `value` with `DECIMALS` decimals and a decimal point, no "-0.000": for text a machine reads
 * (links, exports, data attributes, numbers parsed back). Shown numbers take `fmt`.
 */
export function fmtMachine(value, decimals = DECIMALS) {
  const s = value.toFixed(decimals);
  return Number(s) === 0 ? (0).toFixed(decimals) : s;
}

/**
 * `value` as people read it: `DECIMALS` decimals, no "-0.000", the decimal separator of the
 * active language ("1.250", "1,250"). For TeX use `fmtTex`.
 */
export function fmt(value, decimals = DECIMALS) {
  return localeDecimal(fmtMachine(value, decimals));
}

/** `value` for a KaTeX formula: as `fmt`, a decimal comma written "1{,}250" (no space after it). */
export function fmtTex(value, decimals = DECIMALS) {
  return texDecimal(fmtMachine(value, decimals));
}

/**
 * A number's machine text ("2.5", "-0.00031", from toFixed, toPrecision or String) with the
 * active language's decimal separator: "2,5" in Greek, Croatian and Italian.
 */
export function localeDecimal(text) {
  const sign = decimalSeparator();
  return sign === "." ? text : text.replace(".", sign);
}

/** A number's machine text as TeX in the active language: "2.5", or "2{,}5" (see `fmtTex`). */
export function texDecimal(text) {
  const sign = decimalSeparator();
  return sign === "." ? text : text.replace(".", `{${sign}}`);
}

/**
 * The sign between the entries of a list where the decimal separator is a comma (a comma between
 * numbers would read as a decimal one): ";", but in Greek, where ";" is the question mark, the
 * ano teleia "·" (Greek's own semicolon, U+00B7 as the Greek texts write it: "0,125· 0,75").
 */
function commaListSign() {
  return locale() === "el" ? "·" : ";";
}

/**
 * What separates the entries of a list or a point shown: ", " ("(1.5, 2)"), or "; " where the
 * decimal separator is a comma ("(1,5; 2)"; Greek "(1,5· 2)", see `commaListSign`).
 */
export function listSeparator() {
  return decimalSeparator() === "," ? `${commaListSign()} ` : ", ";
}

/**
 * What joins the clauses of a generated sentence (an aria label's list of joints, say): "; ",
 * in Greek "· " (`commaListSign`: ";" is the Greek question mark).
 */
export function clauseSeparator() {
  return locale() === "el" ? "· " : "; ";
}

/**
 * `params` for a sentence (`t(key, params)`) with every number as `String` writes it but with
 * the active language's decimal separator (0.001 → "0,001", 1e-9 stays "1e-9"); others as they are.
 */
export function shownNumbers(params) {
  const shown = {};
  for (const [key, value] of Object.entries(params))
    shown[key] = typeof value === "number" ? localeDecimal(String(value)) : value;
  return shown;
}

/**
 * What separates the numbers of a typed list a text box shows, so that `splitNumberList` reads
 * it back: " " ("0 0 1.5 2"), or "; " with a decimal comma ("0; 0; 1,5; 2"; Greek "0· 0· 1,5· 2").
 */
export function inputListSeparator() {
  return decimalSeparator() === "," ? `${commaListSign()} ` : " ";
}

/**
 * `listSeparator` for TeX, with `space` after the sign: ",\\ " or ";\\ " (TeX `,\ `, `;\ `); in
 * Greek "\\cdotp\\ " (KaTeX's punctuation dot, the ano teleia of `listSeparator`).
 */
export function texListSeparator(space = "\\ ") {
  if (decimalSeparator() !== ",") return `,${space}`;
  return `${commaListSign() === "·" ? "\\cdotp" : ";"}${space}`;
}

/**
 * Numbers and texts as a shown list: numbers written by `fmt(x, decimals)`, strings (a
 * fraction, a name) as they are, joined by `listSeparator`: "0.25, 1/2" or "0,25; 1/2".
 */
export function listText(items, decimals = DECIMALS) {
  return Array.from(items, (x) => (typeof x === "number" ? fmt(x, decimals) : x)).join(
    listSeparator(),
  );
}

/** A point (or any tuple) as shown: "(1.250, 2.000)", "(1,250; 2,000)"; entries as in `listText`. */
export function pointText(coords, decimals = DECIMALS) {
  return `(${listText(coords, decimals)})`;
}

/**
 * Numbers and TeX as a list in a formula: numbers by `fmtTex(x, decimals)`, strings as they are,
 * joined by `texListSeparator(space)`: "0.25,\\ \\tfrac12" or "0{,}25;\\ \\tfrac12".
 */
export function listTex(items, decimals = DECIMALS, space = "\\ ") {
  return Array.from(items, (x) => (typeof x === "number" ? fmtTex(x, decimals) : x)).join(
    texListSeparator(space),
  );
}

/** A point in a formula: "(1.250,\\ 2)", "(1{,}250;\\ 2)"; entries as in `listTex`. */
export function pointTex(coords, decimals = DECIMALS, space = "\\ ") {
  return `(${listTex(coords, decimals, space)})`;
}

/** Greatest common divisor of two non-negative integers. */
function gcd(a, b) {
  while (b) [a, b] = [b, a % b];
  return a;
}

/**
 * `{ num, den }` with den ≤ MAX_SIMPLE_DENOMINATOR when x is (within float accuracy) such a
 * fraction, else null. 0.25 → 1/4, 0.3333333333333333 → 1/3.
 */
export function simpleFraction(x) {
  for (let den = 1; den <= MAX_SIMPLE_DENOMINATOR; den++) {
    const num = Math.round(x * den);
    if (Math.abs(x * den - num) <= FRACTION_TOLERANCE * den) {
      const g = gcd(Math.abs(num), den) || 1;
      return { num: num / g, den: den / g };
    }
  }
  return null;
}

/**
 * `{ num, den }` if x is k / `den` for an integer k (within float accuracy), reduced; null
 * otherwise or when den is too large to be worth showing.
 */
export function exactFraction(x, den) {
  if (!Number.isFinite(x) || den > MAX_EXACT_DENOMINATOR) return null;
  const scaled = x * den;
  const num = Math.round(scaled);
  if (Math.abs(scaled - num) > FRACTION_TOLERANCE * Math.max(1, Math.abs(scaled))) return null;
  const g = gcd(Math.abs(num), den) || 1;
  return { num: num / g, den: den / g };
}

/** "29/16", "-3/4" or "2" for a fraction object. */
export function fractionText({ num, den }) {
  return den === 1 ? String(num) : `${num}/${den}`;
}

/** TeX for a fraction object: \tfrac{29}{16}, -\tfrac{3}{4}, 2. */
export function fractionTex({ num, den }) {
  if (den === 1) return String(num);
  return `${num < 0 ? "-" : ""}\\tfrac{${Math.abs(num)}}{${den}}`;
}

/** True when every number in the flat list is an integer. */
export function allIntegers(values) {
  for (const v of values) if (!Number.isInteger(v)) return false;
  return true;
}

/**
 * Parses typed parameter input: a decimal ("0.25", or "0,25" with the decimal comma of Greek,
 * Croatian and Italian) or a fraction ("1/3", "1,5/2"); a true minus sign "−" reads as "-".
 * Returns NaN when the text is neither.
 */
export function parseNumberInput(text) {
  const trimmed = String(text)
    .trim()
    .replace(/^\u2212/, "-")
    .replace(/^([-+]?\d+),(\d+)/, "$1.$2");
  const fraction = /^(-?\d+(?:\.\d+)?)\s*\/\s*(\d+(?:[.,]\d+)?)$/.exec(trimmed);
  if (fraction) return Number(fraction[1]) / Number(fraction[2].replace(",", "."));
  if (trimmed === "") return NaN;
  return Number(trimmed);
}

/**
 * The entries of a typed list of numbers: separated by semicolons (or the Greek ano teleia "·",
 * U+00B7 or U+0387) when the text has one (then a comma is a decimal comma: "0; 0; 1,5; 2",
 * "0· 0· 1,5· 2"), else by commas and spaces ("0, 0, 1.5, 2"). `extra` holds more separator
 * characters (e.g. "()" for a point "(1, 2)").
 */
export function splitNumberList(text, extra = "") {
  const escaped = extra.replace(/[\]\\^-]/g, "\\$&");
  const separators = /[;\u00b7\u0387]/.test(String(text))
    ? `;\u00b7\u0387\\s${escaped}`
    : `,\\s${escaped}`;
  return String(text)
    .trim()
    .split(new RegExp(`[${separators}]+`))
    .filter(Boolean);
}

/**
 * Exact text for numbers computed from integer inputs and a parameter that is a simple fraction
 * (ui.md: the worked example reads (29/16, 23/16)). `parameter` is t (or u); `inputs` the
 * numbers it was combined with. When t = a/b and every input is an integer, a value made by
 * `level` convex combinations has a denominator dividing b^level, so it is shown as a fraction;
 * otherwise everything is shown with 3 decimals.
 * @returns {{ exact: { num: number, den: number } | null, param(tex?: boolean): string,
 *   value(x: number, level: number, tex?: boolean, den?: number): string }}
 */
export function exactNumbers(parameter, inputs) {
  const f = simpleFraction(parameter);
  const exact = f && allIntegers(inputs) ? f : null;
  return {
    exact,
    /** The parameter: "1/4" (or TeX \tfrac{1}{4}) when exact, else 3 decimals. */
    param: (tex = false) =>
      exact
        ? tex
          ? fractionTex(exact)
          : fractionText(exact)
        : tex
          ? fmtTex(parameter)
          : fmt(parameter),
    /** x after `level` steps: a fraction over (a divisor of) den^level when exact, else decimals. */
    value(x, level, tex = false, den = exact ? exact.den ** level : 1) {
      const g = exact ? exactFraction(x, den) : null;
      if (!g) return tex ? fmtTex(x) : fmt(x);
      return tex ? fractionTex(g) : fractionText(g);
    },
  };
}

/**
 * A number as short text (or TeX with `tex`): an integer (within 1e-9) without decimals, else
 * `DECIMALS` decimals.
 */
export function shortNumber(v, tex = false) {
  const r = Math.round(v);
  if (Math.abs(v - r) < 1e-9) return String(r);
  return tex ? fmtTex(v) : fmt(v);
}

/**
 * A number as short text (or TeX with `tex`): a simple fraction when it is one (integers plain,
 * "3/2", \tfrac{3}{2}), else `DECIMALS` decimals — knots and parameters in sentences and formulas.
 */
export function fractionOrDecimals(x, tex = false) {
  const f = simpleFraction(x);
  return f ? (tex ? fractionTex(f) : fractionText(f)) : tex ? fmtTex(x) : fmt(x);
}

/** Below this size a non-zero number would read "0.000" in 3 decimals: 2 significant digits. */
const SMALL = 5e-4;

/**
 * A number as text for a table of exact values (a solved system): 0 within 1e-12 (round-off),
 * integers plain, simple fractions ("1/2", "−3/4"), else 3 decimals (2 significant digits for
 * small non-zero values, "0.00031", so they do not read as 0); a true minus sign.
 */
export function exactText(x) {
  if (Math.abs(x) < 1e-12) return "0";
  const text = Math.abs(x) < SMALL ? localeDecimal(x.toPrecision(2)) : fractionOrDecimals(x);
  return text.replace("-", "−");
}

/** `exactText` as TeX: fractions as \tfrac, a decimal comma as "{,}", a TeX minus. */
export function exactTex(x) {
  if (Math.abs(x) < 1e-12) return "0";
  return Math.abs(x) < SMALL ? texDecimal(x.toPrecision(2)) : fractionOrDecimals(x, true);
}

/**
 * The binomial coefficient C(n, i) = n! / (i! (n − i)!), as the product Π_{k=1}^{i} (n − i + k) / k
 * rounded to the integer: for writing a formula out (Bernstein's B_i^n), never for evaluating a
 * curve (the core does that).
 */
export function binomial(n, i) {
  let c = 1;
  for (let k = 1; k <= i; k++) c = (c * (n - i + k)) / k;
  return Math.round(c);
}
