/**
 * The formula panel's lines of a typed piecewise curve (www/demos/piecewise.js): each piece and
 * its velocity as the core writes them in TeX (`ParametricCurve.tex(i)`), and a pair of
 * one-sided values. Strings under `piecewise.`.
 */
import { pointTex, shortNumber, texListSeparator } from "./format.js";
import { t } from "./strings.js";

/** The primes of P, P′, P″, P‴ in TeX. */
export const PRIMES = Object.freeze(["", "'", "''", "'''"]);

/** (x, y) in TeX (the language's separator); an undefined value as a word. */
export function pairTex(p) {
  if (!Number.isFinite(p[0]) || !Number.isFinite(p[1]))
    return `\\text{${t("piecewise.undefined")}}`;
  return pointTex([shortNumber(p[0], true), shortNumber(p[1], true)]);
}

/**
 * Piece i of `curve` (typed as `pieces`) in TeX: `P_k(t) = (x, y), t ∈ [from, to)` (the last
 * piece's interval closed) and `P_k'(t)`, from the core's `tex(i)`; the typed text where the
 * core gives none, the velocity left out when its TeX is too large.
 */
export function pieceTex(curve, pieces, i) {
  const n = pieces.length;
  const close = i === n - 1 ? "]" : ")";
  let tex = null;
  try {
    tex = curve.tex(i);
  } catch {
    tex = null;
  }
  const texOf = (f, key) => tex?.[f]?.[key] ?? null;
  const raw = (f) => `\\texttt{${pieces[i][f].replace(/[\\{}$&#^_%~]/g, "")}}`;
  const k = i + 1;
  const sep = texListSeparator(); // ",\\ ", or ";\\ " with a decimal comma
  const x = texOf("x", "expr") ?? raw("x");
  const y = texOf("y", "expr") ?? raw("y");
  const lines = [
    `P_{${k}}(t) = \\left(${x}${sep}${y}\\right),\\quad ` +
      `t \\in [${tex?.from ?? raw("from")}${sep}${tex?.to ?? raw("to")}${close}`,
  ];
  const dx = texOf("x", "d1");
  const dy = texOf("y", "d1");
  if (dx !== null && dy !== null) lines.push(`P_{${k}}'(t) = \\left(${dx}${sep}${dy}\\right)`);
  return lines;
}
