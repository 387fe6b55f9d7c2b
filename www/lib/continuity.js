/**
 * The continuity of a curve at a joint as text: C^k for a curve whose derivatives up to order k
 * agree on both sides ("C²"; "C∞" inside a polynomial piece), the break word when the pieces do
 * not even meet (k < 0, e.g. a knot of multiplicity p + 1 between interior spans); with the
 * geometric order G^g: "C¹ G¹". The numbers come from the core (`knotContinuity()`,
 * `jointContinuity(left, right)` → `{ c, g }`).
 */
import { superscript } from "./format.js";
import { t } from "./strings.js";

/** A continuity order as text, "C¹" / "G²" / "C∞" (k = Infinity): `letter` and k in superscript. */
export function orderText(letter, k) {
  return k === Infinity ? `${letter}∞` : `${letter}${superscript(k)}`;
}

/** The same in TeX: "\\text{C}^{1}", "\\text{C}^{\\infty}". */
export function orderTex(letter, k) {
  return k === Infinity ? `\\text{${letter}}^{\\infty}` : `\\text{${letter}}^{${k}}`;
}

/** "C²", "C⁰", "C∞", or the break word for continuity k < 0. */
export function continuityText(k) {
  return k < 0 ? t("knotRuler.break") : orderText("C", k);
}

/** "C¹ G¹" for a measured joint `{ c, g }`, the break word when c < 0, "—" without a joint. */
export function measuredText(joint) {
  if (!joint) return "—";
  return joint.c < 0
    ? t("knotRuler.break")
    : `${continuityText(joint.c)} ${orderText("G", joint.g)}`;
}
