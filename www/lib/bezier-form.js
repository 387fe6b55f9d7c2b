/**
 * The exact Bézier form of a polynomial typed curve (parametric-curve): the core's control
 * points (`toBezier(0)`) and their exact coordinates (`bezierFractions(0)`, "-271/50"), listed
 * as text, and a link that opens them in de-casteljau (a plane curve it can take).
 */
import { pointText, shortNumber, subscript } from "./format.js";
import { locale, t } from "./strings.js";
import { buildHash } from "./state.js";
import { withLanguage } from "./language.js";
import { BEZIER_POINTS } from "./point-list.js";

/**
 * `{ points (flat, dim per point), count, dim, fractions (or null) }` of piece 0 of `curve` on
 * its own interval, or null when `shown` is false or the curve is not a polynomial.
 */
export function bezierFormOf(curve, shown) {
  if (!shown || !curve.isPolynomial(0)) return null;
  const bezier = curve.toBezier(0);
  let points;
  try {
    points = bezier.controlPoints();
  } finally {
    bezier.free();
  }
  const dim = curve.dim;
  let fractions = null;
  try {
    fractions = curve.bezierFractions(0);
  } catch {
    fractions = null;
  }
  return { points, count: points.length / dim, dim, fractions };
}

/**
 * The link into de-casteljau with the control points and t mapped onto [0, 1] (`{ text, href }`),
 * its refusal (`href` null) for a space curve or a degree it does not take, or null (no form).
 */
export function deCasteljauLink(form, [a, b], tt, prefix) {
  if (!form) return null;
  if (form.dim !== 2 || form.count < BEZIER_POINTS.min || form.count > BEZIER_POINTS.max)
    return { text: t(`${prefix}.bezierLinkOff`), href: null };
  const points = [];
  for (let i = 0; i < form.count; i++) points.push([form.points[2 * i], form.points[2 * i + 1]]);
  const u = b > a ? Math.min(Math.max((tt - a) / (b - a), 0), 1) : 0;
  const state = { points, t: Number(u.toFixed(6)), construction: true };
  const url = new URL(`../index.html${buildHash("de-casteljau", state)}`, import.meta.url).href;
  return {
    text: t(`${prefix}.bezierLink`),
    href: locale() === "en" ? url : withLanguage(url, locale()),
  };
}

/** "P₀ = (−5, 0), P₁ = (−271/50, 1/5), …": the exact control points (decimals without them). */
export function bezierList(form, [a, b], prefix) {
  if (!form) return "";
  const items = [];
  for (let i = 0; i < form.count; i++) {
    const coords = [];
    for (let c = 0; c < form.dim; c++) {
      const exact = form.fractions?.[i * form.dim + c];
      coords.push(exact ? exact.replace(/^-/, "−") : form.points[i * form.dim + c]);
    }
    items.push(`P${subscript(i)} = ${pointText(coords)}`);
  }
  return t(`${prefix}.bezierPoints`, {
    a: shortNumber(a),
    b: shortNumber(b),
    list: items.join(", "),
  });
}
