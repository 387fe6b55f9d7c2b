/**
 * Demo (syllabus §3): local control and the strong convex hull of a B-spline curve. A clamped
 * B-spline (cubic by default) with integer control points; the point P_i in hand (dragged,
 * selected with the keyboard, or chosen with the slider) lights up the part of the curve it can
 * move, the parameters [u_i, u_{i+p+1}) where N_{i,p} ≠ 0; the rest of the curve does not move.
 * A parameter u picks a span k: the p + 1 active points P_{k−p} … P_k are the only ones with a
 * non-zero basis function there, and that span's piece of the curve lies inside their convex
 * hull (filled), a much smaller region than the hull of the whole polygon (outlined).
 *
 * Everything about the curve comes from the core: the knot vector (`knotVector(…, "clamped")`),
 * the samples (one `sampleUniform` for the curve, one `sample(us)` for the lit range, one for
 * the knot points), `span(u)`, `basis(u)` and `evaluate(u)`. JS only adds drawing support: the
 * convex hull polygon of a handful of points (`convexHull`, lib/geometry.js) and the knot strip
 * under the figure (lib/param-strip.js). Drags go through `setControlPoint`.
 */
import { field, checkNumber } from "../lib/validate.js";
import { slider, readout, pointButtons, group, INTEGER_SLIDER } from "../lib/panel.js";
import { parameterStrip, knotMarks } from "../lib/param-strip.js";
import { knotText } from "../lib/knot-ruler.js";
import { placeLabel } from "../lib/handles.js";
import {
  fmt,
  subscript,
  exactFraction,
  exactNumbers,
  degreeName,
  listSeparator,
  listTex,
  pointTex,
  texListSeparator,
} from "../lib/format.js";
import { CYCLE, WIDTH, RADIUS, themed } from "../lib/theme.js";
import { t, tp } from "../lib/strings.js";
import { boundsOf, convexHull } from "../lib/geometry.js";
import { bsplineCurve, clampedKnots } from "../lib/bspline.js";
import { flatPath, indexedPolygonPath, pointsPath } from "../lib/draw.js";
import { titledTable } from "../lib/table.js";
import { el, setText } from "../lib/controls.js";
import { scaledInsets } from "../lib/view.js";

export const id = "local-control";
export const strings = "localControl";
export const section = 3;

/** Degrees offered (the clamped knot vector needs at least degree + 1 points). */
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
/** Most control points. */
export const MAX_POINTS = 14;
/** Points sampled along the whole curve (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 241;
/** Points sampled over the lit range [u_i, u_{i+p+1}] (one `sample(us)` call). */
const SUPPORT_SAMPLES = 121;
/** Slider resolution for u. */
const U_STEP = 0.01;
/** The knot strip under the figure: height and side margins in CSS px at scale 1. */
const STRIP_PX = 78;
const STRIP_MARGIN = 34;
/** Rows of the strip, CSS px below its top at scale 1: u label, support bar, axis, knot labels. */
const ROW = Object.freeze({ label: 12, bar: 28, axis: 44, ticks: 62 });
/** Half-length of a knot tick, CSS px; the span of u is shaded 1.6 times as high. */
const TICK_PX = 6;
const SPAN_SHADE = 1.6;

/**
 * Nine integer points and a clamped cubic: knots 0 0 0 0 1 2 3 4 5 6 6 6 6, six spans. P₄ acts
 * on [1, 5) only, so both ends of the curve stay put while it moves; u = 5/2 lies in span
 * k = 5, whose active points P₂ … P₅ have the uniform weights 1/48, 23/48, 23/48, 1/48.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 1],
      [1, 4],
      [3, 5],
      [5, 2],
      [7, 0],
      [9, 3],
      [11, 5],
      [13, 3],
      [14, 0],
    ].map(Object.freeze),
  ),
  degree: 3,
  u: 2.5,
  point: 4,
});

/** The clamped knots run 0 … n − p + 1: the domain of u ends at (n + 1) − p. */
const domainEnd = (s) => s.points.length - s.degree;

const tooFewPoints = (p, count) => t("localControl.error.tooFewPoints", { min: p + 1, p, count });

export const fields = {
  points: field.points({ min: MIN_DEGREE + 1, max: MAX_POINTS }),
  degree(s, name) {
    checkNumber(s, name, { min: MIN_DEGREE, max: MAX_DEGREE, integer: true });
    if (s.points.length < s.degree + 1) throw new Error(tooFewPoints(s.degree, s.points.length));
  },
  u: field.number((s) => ({ min: 0, max: domainEnd(s) })),
  point: field.number((s) => ({ min: 0, max: s.points.length - 1, integer: true })),
};

/** After a new degree or point count: u stays in the domain, the lit point in the list. */
export function adjust(s) {
  s.u = Math.min(s.u, domainEnd(s));
  s.point = Math.min(s.point, s.points.length - 1);
}

/** The clamped knot vector (the core's), the curve on it and the knots' ticks. */
export const derive = {
  from: ["points", "degree"],
  build(s, sl) {
    const knots = clampedKnots(sl, s.points, s.degree);
    const curve = bsplineCurve(sl, { points: s.points, degree: s.degree, knots });
    return { knots, marks: knotMarks(knots), curve, domain: [0, domainEnd(s)] };
  },
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/**
 * The range P_i acts on, [u_i, u_{i+p+1}], sampled in one `sample(us)` call, and the sums of the
 * uniform samples inside and outside it (`data-inside-sum`, `data-outside-sum`): moving P_i
 * must leave the outside sum exactly as it was (a hook for tests and curious readers). The last
 * span is closed on the right: u = b belongs to a range ending at b.
 */
function support(s, d) {
  const lo = d.knots[s.point];
  const hi = d.knots[s.point + s.degree + 1];
  const us = new Float64Array(SUPPORT_SAMPLES);
  for (let j = 0; j < SUPPORT_SAMPLES; j++) us[j] = lo + ((hi - lo) * j) / (SUPPORT_SAMPLES - 1);
  const b = domainEnd(s);
  let inside = 0;
  let outside = 0;
  for (let j = 0; j < CURVE_SAMPLES; j++) {
    const u = (b * j) / (CURVE_SAMPLES - 1);
    const value = (j + 1) * (d.samples[2 * j] + Math.SQRT2 * d.samples[2 * j + 1]);
    if (u >= lo && (u < hi || (hi === b && u === b))) inside += value;
    else outside += value;
  }
  const closing = hi === b ? "]" : ")";
  return {
    lo,
    hi,
    samples: d.curve.sample(us),
    inside,
    outside,
    range: [knotText(lo), `${knotText(hi)}${closing}`],
    rangeTex: [knotText(lo, true), `${knotText(hi, true)}${closing}`],
  };
}

/** The span k of u, the basis there, C(u), the active points P_{k−p} … P_k and their hull. */
function atU(s, d) {
  const k = d.curve.span(s.u);
  const active = [];
  for (let i = k - s.degree; i <= k; i++) active.push(i);
  return {
    k,
    active,
    basis: d.curve.basis(s.u),
    point: d.curve.evaluate(s.u),
    hull: convexHull(s.points, active),
  };
}

/** What the core returns, recomputed when its fields changed. */
export const compute = {
  samples: [["points", "degree"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  joints: [["points", "degree"], (s, d) => d.curve.sample(d.marks.values)],
  wholeHull: [["points"], (s) => convexHull(s.points)],
  support: [["points", "degree", "point"], support],
  at: [["points", "degree", "u"], atU],
  uLabel: [["u"], (s) => `u = ${knotText(s.u)}`],
};

/** An integer slider: whole numbers in the box and in the state. */

const names = (indices) => indices.map((i) => `P${subscript(i)}`).join(", ");

export const controls = [
  parameterStrip("u", {
    height: STRIP_PX,
    margin: STRIP_MARGIN,
    step: U_STEP,
    range: (s, d) => d.domain,
  }),
  group(
    null,
    slider("u", { label: "localControl.control.u", range: (s, d) => d.domain, step: U_STEP }),
    readout(
      "span",
      (s, d) => t("localControl.readout.span", { k: d.at.k, names: names(d.at.active) }),
      {
        kind: "readout",
        live: true,
        data: (s, d) => ({
          span: String(d.at.k),
          active: d.at.active.join(" "),
          hullVertices: String(d.at.hull.length),
          wholeHullVertices: String(d.wholeHull.length),
        }),
      },
    ),
    readout("hull", (s, d) => tp("localControl.readout.hull", d.at.hull.length)),
  ),
  group(
    null,
    slider("point", {
      label: "localControl.control.point",
      range: (s) => [0, s.points.length - 1],
      ...INTEGER_SLIDER,
    }),
    readout(
      "support",
      (s, d) => {
        const [lo, hi] = d.support.range;
        return t("localControl.readout.support", { name: `P${subscript(s.point)}`, lo, hi });
      },
      {
        data: (s, { support: { lo, hi, inside, outside } }) => ({
          support: `${lo},${hi}`,
          insideSum: String(inside),
          outsideSum: String(outside),
        }),
      },
    ),
  ),
  group(
    null,
    slider("degree", {
      label: "localControl.control.degree",
      min: MIN_DEGREE,
      max: MAX_DEGREE,
      ...INTEGER_SLIDER,
      onRelease: true,
      refuse: (p, s) => (s.points.length < p + 1 ? tooFewPoints(p, s.points.length) : null),
    }),
    pointButtons("points", {
      min: (s) => s.degree + 1,
      max: MAX_POINTS,
      prefix: strings,
      minKey: "localControl.error.tooFewPoints",
      params: (s) => ({ p: s.degree, count: s.points.length - 1 }),
    }),
  ),
];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  insets: scaledInsets(0, 0, STRIP_PX, 0),
  handles: {
    field: "points",
    // The point in hand is the one whose range is lit; it is recorded with the next change.
    select(i, ui) {
      if (i < 0 || i === ui.state.point) return;
      ui.set("point", i, false);
      ui.ctx.preview(ui.state);
    },
  },
};

/** The knot joints on the curve and the knot ticks on the strip. */
const stylesFor = themed((theme) => ({
  dot: Object.freeze({
    fill: theme.text,
    stroke: theme.background,
    width: WIDTH.helper,
    radius: RADIUS.constructionPoint,
  }),
  tick: Object.freeze({ stroke: theme.text, width: WIDTH.construction }),
}));

/**
 * The hulls (whole polygon outlined, active points filled), the polygon, the lit range as a
 * band in P_i's colour, the curve and its knot joints, the handles, C(u) labelled away from the
 * active points' centre, and the knot strip.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const styles = stylesFor(theme);
  const colour = s.point % CYCLE.length;
  indexedPolygonPath(r, v, s.points, d.wholeHull);
  r.paint(theme.helper);
  indexedPolygonPath(r, v, s.points, d.at.hull);
  r.paint(theme.helperFill);
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  flatPath(r, v, d.support.samples, 0, SUPPORT_SAMPLES);
  r.paint(theme.basisBand[colour]);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  for (let j = 0; j < d.marks.values.length; j++)
    r.point(v.sx(d.joints[2 * j]), v.sy(d.joints[2 * j + 1]), styles.dot);
  const lit = s.points[s.point];
  r.point(v.sx(lit[0]), v.sy(lit[1]), theme.basisRing[colour]);
  d.handles.draw(r, v);

  const px = v.sx(d.at.point[0]);
  const py = v.sy(d.at.point[1]);
  r.point(px, py, theme.pointOnCurve);
  let cx = 0;
  let cy = 0;
  for (const i of d.at.active) {
    cx += v.sx(s.points[i][0]);
    cy += v.sy(s.points[i][1]);
  }
  const dx = px - cx / d.at.active.length;
  const dy = py - cy / d.at.active.length;
  const length = Math.hypot(dx, dy);
  const [ux, uy] = length < 1 ? [0, -1] : [dx / length, dy / length];
  placeLabel(
    r,
    t("localControl.pointLabel"),
    px,
    py,
    ux,
    uy,
    theme.pointOnCurve.radius * r.scale,
    theme.labelPoint,
  );

  drawStrip(r, s, d, theme, styles, colour);
}

/** The parameter line under the figure: the span of u shaded, the lit range as a bar, the knots, u. */
function drawStrip(r, s, d, theme, styles, colour) {
  const strip = d.strip;
  strip.layout(r.width, r.height, r.scale);
  const shade = TICK_PX * SPAN_SHADE * r.scale;
  const x0 = strip.px(d.knots[d.at.k]);
  r.beginPath();
  r.rect(x0, strip.y(ROW.axis) - shade, strip.px(d.knots[d.at.k + 1]) - x0, 2 * shade);
  r.paint(theme.helperFill);
  r.beginPath();
  r.moveTo(strip.px(d.support.lo), strip.y(ROW.bar));
  r.lineTo(strip.px(d.support.hi), strip.y(ROW.bar));
  r.paint(theme.basisBand[colour]);
  strip.drawAxis(r, ROW.axis, theme.axis);
  strip.drawTicks(r, d.marks.values, ROW.axis, TICK_PX, styles.tick);
  strip.drawLabels(r, d.marks.values, d.marks.labels, ROW.ticks, () => theme.labelSmall);
  strip.drawParameter(r, s.u, d.uLabel, ROW.axis, ROW.label, theme.pointOnCurve, theme.labelPoint);
}

/**
 * Product over r = 1..p of lcm(1..r): with integer knot gaps ≤ r at level r, it clears every
 * Cox–de Boor denominator apart from u's own (used to show basis values as exact fractions).
 */
function basisDenominator(p) {
  const lcm = [1, 1, 2, 6, 12, 60];
  let den = 1;
  for (let r = 1; r <= p; r++) den *= lcm[r];
  return den;
}

/** Exact text for values at u (fractions when u is simple and the points integers), and den. */
function numbers(s) {
  const num = exactNumbers(s.u, s.points.flat());
  const den = num.exact ? num.exact.den ** s.degree * basisDenominator(s.degree) : 1;
  return { num, den, value: (x, tex = false) => num.value(x, s.degree, tex, den) };
}

/** The span of u, the sum over the active points, C(u), the range of P_i and the hull property. */
export function formula(s, d) {
  const p = s.degree;
  const { k, basis, point } = d.at;
  const i = s.point;
  const { num, den, value } = numbers(s);
  const terms = d.at.active.map((j) => `${value(basis[j], true)}\\,P_{${j}}`);
  const [x, y] = point;
  const inexact = !Number.isInteger(x) || !Number.isInteger(y);
  const approx =
    num.exact && inexact && exactFraction(x, den) ? `\\approx ${pointTex([x, y])}` : "";
  const [lo, hi] = d.support.rangeTex;
  const comma = texListSeparator(" ");
  const only = t("localControl.formula.only");
  const vertices = tp("localControl.formula.vertices", d.at.hull.length);
  const spanTex = `[${knotText(d.knots[k], true)}${comma}${knotText(d.knots[k + 1], true)})`;
  return [
    `u = ${num.param(true)} \\in [u_{${k}}, u_{${k + 1}}) = ${spanTex},\\quad k = ${k},\\quad p = ${p}`,
    `C(u) = \\sum_{i=k-p}^{k} N_{i,${p}}(u)\\,P_i = ${terms.join(" + ")}`,
    `C(${num.param(true)}) = \\left(${listTex([value(x, true), value(y, true)])}\\right) ${approx}`,
    `N_{${i},${p}}(u) \\ne 0 \\iff u \\in [u_{${i}}, u_{${i + p + 1}}) = [${lo}${comma}${hi}` +
      `\\quad\\Rightarrow\\quad \\text{${only}}\\ P_{${i}}`,
    `C([u_{${k}}, u_{${k + 1}}]) \\subset \\operatorname{conv}\\{P_{${k - p}}, \\dots, P_{${k}}\\}` +
      `\\quad (${d.at.hull.length}\\ \\text{${vertices}})`,
  ];
}

/** "clamped cubic B-spline with 9 control points; P₄ moves only the part for u in [1, 5); …". */
export function label(s, d) {
  const [lo, hi] = d.support.range;
  const { k, active, point, hull } = d.at;
  return t("localControl.aria", {
    kind: degreeName(s.degree),
    count: s.points.length,
    name: `P${subscript(s.point)}`,
    lo,
    hi,
    u: fmt(s.u),
    k,
    names: names(active),
    x: fmt(point[0], 2),
    y: fmt(point[1], 2),
    hull: tp("localControl.vertices", hull.length),
  });
}

/** The table: every basis function at u and its support; the p + 1 active rows highlighted. */
export function setup(ui) {
  const { title, table, wrap } = titledTable("local-control");
  ui.ctx.slots.details.append(title, wrap);
  let shape = "";
  let rows = [];

  function build(n, p) {
    shape = `${n}/${p}`;
    const head = el(
      "tr",
      {},
      el("th", { scope: "col", text: t("localControl.table.point") }),
      el("th", { scope: "col", text: t("localControl.table.value", { p: subscript(p) }) }),
      el("th", { scope: "col", text: t("localControl.table.support") }),
    );
    rows = [];
    for (let j = 0; j <= n; j++) {
      const value = el("td", { dataset: { index: String(j), column: "value" } });
      const range = el("td", { dataset: { index: String(j), column: "support" } });
      const row = el("tr", {}, el("th", { scope: "row", text: `P${subscript(j)}` }), value, range);
      rows.push({ row, value, range });
    }
    table.replaceChildren(
      el("thead", {}, head),
      el(
        "tbody",
        {},
        rows.map((row) => row.row),
      ),
    );
  }

  return {
    update(s, d) {
      const n = s.points.length - 1;
      const p = s.degree;
      if (shape !== `${n}/${p}`) build(n, p);
      const { num, value } = numbers(s);
      setText(title, t("localControl.tableCaption", { u: num.param(), p }));
      const { k, basis } = d.at;
      for (let j = 0; j <= n; j++) {
        const row = rows[j];
        const end = d.knots[j + p + 1] === domainEnd(s) ? "]" : ")";
        setText(row.value, value(basis[j]));
        const ends = [knotText(d.knots[j]), `${knotText(d.knots[j + p + 1])}${end}`];
        setText(row.range, `[${ends.join(listSeparator())}`);
        row.row.classList.toggle("sl-highlight", j >= k - p && j <= k);
        row.row.dataset.active = String(j >= k - p && j <= k);
      }
    },
  };
}
