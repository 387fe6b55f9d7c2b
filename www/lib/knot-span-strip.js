/**
 * The knot vector u₀ … u_m drawn on a parameter strip (lib/param-strip.js) under the figure, for
 * the evaluation of a B-spline at u: the line solid over the domain [u_p, u_{n+1}] and dashed
 * outside it, a tick at each distinct knot with its value below (labels that would touch the
 * previous one left out) and its multiplicity above when > 1, the active span [u_k, u_{k+1})
 * (the one with u_k ≤ u < u_{k+1}, from the core's `span(u)`) shaded and named, and u marked.
 */
import { knotMarks } from "./param-strip.js";
import { fractionOrDecimals } from "./format.js";

/** Half-heights of a knot tick, of the shaded span and of the u marker; label gaps (CSS px). */
const TICK = 7;
const SPAN_HALF = 11;
const MARKER_HALF = 15;
const LABEL_GAP = 6;
/** An estimate of a digit's width in em (tick labels that would touch are left out). */
const CHAR_EM = 0.62;

/**
 * Distinct knots `values`, their value labels and multiplicity labels (`multiplicity(r)` for a
 * knot r times repeated, r > 1; else "").
 */
export function knotSpanLabels(knots, multiplicity) {
  const { values, counts } = knotMarks(knots);
  const labels = Array.from(values, (u) => fractionOrDecimals(u));
  return { values, labels, multiplicity: counts.map((r) => (r > 1 ? multiplicity(r) : "")) };
}

/**
 * Draws the strip (laid out already): `marks` from `knotSpanLabels`, the knots, the span index
 * k, the domain [a, b], u, the captions `{ span, u }`, the line at `lineRow` CSS px below the top.
 */
export function drawKnotSpanStrip(r, strip, { knots, span, domain, u, marks, captions, lineRow }) {
  const theme = r.theme;
  const sc = r.scale;
  const y = strip.y(lineRow);
  const [a, b] = domain;
  // Separator between the figure and the strip.
  r.beginPath();
  r.moveTo(0, strip.top);
  r.lineTo(r.width, strip.top);
  r.paint(theme.helper);
  // The active span [u_k, u_{k+1}).
  const xs0 = strip.px(knots[span]);
  const xs1 = strip.px(knots[span + 1]);
  r.beginPath();
  r.rect(xs0, y - SPAN_HALF * sc, xs1 - xs0, 2 * SPAN_HALF * sc);
  r.paint(theme.helperFill);
  // The knot line: outside the domain dashed, the domain solid.
  r.beginPath();
  r.moveTo(strip.x0, y);
  r.lineTo(strip.x1, y);
  r.paint(theme.helper);
  r.beginPath();
  r.moveTo(strip.px(a), y);
  r.lineTo(strip.px(b), y);
  r.paint(theme.axis);
  // Ticks, values below (those that would touch the previous one left out), multiplicities above.
  const { values, labels: texts, multiplicity } = marks;
  let lastRight = -Infinity;
  const digit = theme.labelSmall.size * sc * CHAR_EM;
  for (let i = 0; i < values.length; i++) {
    const x = strip.px(values[i]);
    r.beginPath();
    r.moveTo(x, y - TICK * sc);
    r.lineTo(x, y + TICK * sc);
    r.paint(theme.axis);
    const half = (texts[i].length * digit) / 2;
    if (x - half > lastRight + LABEL_GAP * sc) {
      r.text(texts[i], x, y + (TICK + 4) * sc, theme.labelSmall, "center", "top");
      lastRight = x + half;
    }
    if (multiplicity[i])
      r.text(multiplicity[i], x, y - (TICK + 3) * sc, theme.labelSmall, "center", "bottom");
  }
  // The span's name above the shaded span; u marked on the line.
  r.text(captions.span, (xs0 + xs1) / 2, strip.top + 4 * sc, theme.labelSmall, "center", "top");
  const xu = strip.px(u);
  r.beginPath();
  r.moveTo(xu, y - MARKER_HALF * sc);
  r.lineTo(xu, y + MARKER_HALF * sc);
  r.paint(theme.marker);
  r.point(xu, y, theme.pointOnCurve);
  r.text(captions.u, xu, y + (MARKER_HALF + 14) * sc, theme.labelPoint, "center", "top");
}
