/**
 * Demo (syllabus §3): de Boor's algorithm. The B-spline counterpart of the de Casteljau demo and
 * built the same way: the curve lives in wasm and is updated in place while dragging
 * (`setControlPoint`); the construction is what the core returns (`deBoor(u)`, `deBoorAlphas(u)`,
 * `span(u)`, one `sampleUniform` per change). A strip under the figure shows the knot vector
 * with the active span [u_k, u_{k+1}) and the parameter u; pressing or dragging there sets u.
 *
 * The recurrence on the p + 1 active points d_j^0 = P_{j+k−p}, j = 0 … p:
 *   d_j^r = (1 − α_j^r) d_{j−1}^{r−1} + α_j^r d_j^{r−1},
 *   α_j^r = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p}),   r = 1 … p, j = r … p;   C(u) = d_p^p.
 */
import { field, checkNumber, checkNumbers } from "../lib/validate.js";
import {
  slider,
  checkbox,
  pointButtons,
  readout,
  actions,
  numberList,
  group,
} from "../lib/panel.js";
import { parameterStrip } from "../lib/param-strip.js";
import { bsplineCurve, clampedKnots, domainOf, clampInto } from "../lib/bspline.js";
import { replaceOrReport } from "../lib/wasm.js";
import {
  fmt,
  subscript,
  degreeName,
  pointTex,
  DECIMALS,
  listTex,
  fractionOrDecimals,
} from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { boundsOf } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { drawLevels, levelStart, LevelLabels, LegLabelPlacer } from "../lib/triangle.js";
import { DeBoorTable } from "../lib/de-boor-table.js";
import { alphasByLevel, deBoorExact } from "../lib/de-boor-exact.js";
import { drawKnotSpanStrip, knotSpanLabels } from "../lib/knot-span-strip.js";
import { scaledInsets } from "../lib/view.js";
import { errorText } from "../lib/core-errors.js";

export const id = "de-boor";
export const strings = "deBoor";
export const section = 3;

/**
 * A cubic clamped uniform B-spline with 7 integer control points (syllabus §3 conventions:
 * p + 1 zeros, 1 … n − p, p + 1 copies of n − p + 1), at u = 5/4 in the span [u₄, u₅) = [1, 2).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [2, 7],
      [8, 9],
      [10, 1],
      [16, 0],
      [18, 7],
      [23, 6],
    ].map(Object.freeze),
  ),
  degree: 3,
  knots: Object.freeze([0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4]),
  u: 1.25,
  construction: true,
});

/** Fewest and most control points. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 11;
/** Highest degree offered. */
export const MAX_DEGREE = 5;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Slider (and strip) resolution as a fraction of the domain. */
const U_RESOLUTION = 1 / 1000;
/** Intermediate points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_LEVELS_MAX_DEGREE = 4;
/** The knot strip under the figure, CSS px (× lecture scale): height, side margins, the line's row. */
const STRIP_PX = 78;
const STRIP_MARGIN = 30;
const LINE_ROW = 34;
/** Presses count down to this far below the line and beyond its ends (CSS px). */
const STRIP_HIT_PX = 22;

// ------------------------------------------------------------------ the state and its checks

/** The knots u₀ … u_m, m + 1 = n + p + 2: non-decreasing, at most p + 1 equal, a domain. */
function checkKnots(s, name) {
  const count = s.points.length;
  const p = s.degree;
  const m = count + p + 1;
  checkNumbers(s, name, { min: 0, max: Infinity });
  const knots = s[name];
  if (knots.length !== m)
    throw new Error(t("deBoor.error.knotCount", { expected: m, count, p, got: knots.length }));
  let run = 0;
  for (let i = 0; i < knots.length; i++) {
    if (i > 0 && knots[i] < knots[i - 1]) {
      throw new Error(
        t("deBoor.error.knotOrder", { index: i, value: knots[i], previous: knots[i - 1] }),
      );
    }
  }
  for (let i = 0; i < knots.length; i++) {
    run = i > 0 && knots[i] === knots[i - 1] ? run + 1 : 1;
    if (run > p + 1)
      throw new Error(t("deBoor.error.multiplicity", { value: knots[i], max: p + 1 }));
  }
  const [a, b] = domainOf(knots, p);
  if (!(a < b)) throw new Error(t("deBoor.error.domain", { a, b, p, n1: count }));
}

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  degree(s, name) {
    checkNumber(s, name, { min: 1, max: MAX_DEGREE, integer: true });
    const count = s.points.length;
    if (s.degree > count - 1) throw new Error(t("deBoor.error.degree", { p: s.degree, count }));
  },
  knots: checkKnots,
  u: field.number((s) => {
    const [min, max] = domainOf(s.knots, s.degree);
    return { min, max };
  }),
  construction: field.boolean(),
};

const domain = (s) => domainOf(s.knots, s.degree);
const highestDegree = (s) => Math.min(MAX_DEGREE, s.points.length - 1);
const degreeRange = (value, s) => t("deBoor.degreeRange", { value, max: highestDegree(s) });

/**
 * Replaces points, degree or knots (`changes`); u keeps its place relative to the domain. The
 * core builds the new curve first: on a refusal the status line says why and nothing changes.
 * `reset` says that the knots became clamped uniform.
 */
function restructure(ui, changes, reset = false) {
  const next = { ...ui.state, ...changes };
  const [a, b] = domain(ui.state);
  const [a1, b1] = domain(next);
  next.u = clampInto(a1 + ((ui.state.u - a) / (b - a)) * (b1 - a1), [a1, b1]);
  if (!replaceOrReport(ui, next)) return false;
  if (reset) ui.status(t("deBoor.knotsReset"), "info");
  return true;
}

/** A new degree: the core's clamped uniform knots for it. */
function setDegree(ui, p) {
  const s = ui.state;
  if (p === s.degree) return;
  restructure(ui, { degree: p, knots: clampedKnots(ui.sl, s.points, p) }, true);
}

/** A new point list: clamped uniform knots again, the degree lowered if it must. */
function setPoints(ui, points) {
  const p = Math.min(ui.state.degree, points.length - 1);
  return restructure(ui, { points, degree: p, knots: clampedKnots(ui.sl, points, p) }, true);
}

/** Typed knots: checked like a link's (u clamped into their domain for the check), then taken. */
function typedKnots(ui, values) {
  const candidate = { ...ui.state, knots: values };
  const [a, b] = [values[ui.state.degree], values[ui.state.points.length]];
  if (a < b) candidate.u = clampInto(ui.state.u, [a, b]);
  try {
    checkKnots(candidate, "knots");
    fields.u(candidate, "u");
  } catch (err) {
    ui.status(t("status.rejected", { message: errorText(err) }), "error");
    return;
  }
  if (values.every((v, i) => v === ui.state.knots[i])) return;
  restructure(ui, { knots: values });
}

function resetKnots(ui) {
  const knots = clampedKnots(ui.sl, ui.state.points, ui.state.degree);
  if (!knots.every((v, i) => v === ui.state.knots[i])) restructure(ui, { knots });
}

// ------------------------------------------------------------------ what the core returns

/** The curve, in wasm; a dragged point moves it in place. */
export const derive = {
  from: ["points", "degree", "knots"],
  build: (s, sl) => ({ curve: bsplineCurve(sl, s) }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/** A number as short text (or TeX): integers plain, simple fractions as a/b, else 3 decimals. */
const numberText = fractionOrDecimals;

const SHAPE = ["points", "degree", "knots"];
/**
 * What the core returns: the samples, the triangle at u (level by level), the span k, the α of
 * every step by level; the exact text of its numbers when u is a simple fraction and the points
 * and knots are integers (lib/de-boor-exact.js); the knot strip's labels and captions.
 */
export const compute = {
  samples: [SHAPE, (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  triangle: [[...SHAPE, "u"], (s, d) => d.curve.deBoor(s.u)],
  span: [[...SHAPE, "u"], (s, d) => d.curve.span(s.u)],
  alphas: [[...SHAPE, "u"], (s, d) => alphasByLevel(d.curve.deBoorAlphas(s.u))],
  numbers: [
    [...SHAPE, "u"],
    (s, d) => deBoorExact(s.u, [...s.points.flat(), ...s.knots], s.degree, d.alphas),
  ],
  spans: [SHAPE, (s, d) => d.curve.spans().length],
  knotStrip: [["knots"], (s) => knotSpanLabels(s.knots, (r) => t("deBoor.multiplicity", { r }))],
  captions: [
    [...SHAPE, "u"],
    (s, d) => ({
      span: t("deBoor.spanCaption", { k: subscript(d.span), k1: subscript(d.span + 1) }),
      u: t("deBoor.uCaption", { u: numberText(s.u) }),
    }),
  ],
};

// ------------------------------------------------------------------ the panel

/** The button that puts the clamped uniform knots back. */
const CLAMPED = Object.freeze({
  name: "clamped-knots",
  label: "deBoor.control.clamped",
  title: "deBoor.control.clamped.title",
  run: resetKnots,
});

const uStep = (s) => {
  const [a, b] = domain(s);
  return (b - a) * U_RESOLUTION;
};

export const controls = [
  parameterStrip("u", {
    height: STRIP_PX,
    margin: STRIP_MARGIN,
    step: uStep,
    range: (s) => [s.knots[0], s.knots[s.knots.length - 1]],
    clampTo: domain,
    hit: { bottom: LINE_ROW + STRIP_HIT_PX, slack: STRIP_HIT_PX },
  }),
  group(
    null,
    slider("u", {
      label: "deBoor.control.u",
      range: domain,
      step: (a, b) => (b - a) * U_RESOLUTION,
      player: {
        stepBackTitle: "deBoor.control.stepBack.title",
        stepTitle: "deBoor.control.stepForward.title",
      },
    }),
    readout(
      "span",
      (s, d) => {
        const k = d.span;
        const [uk, uk1] = [numberText(s.knots[k]), numberText(s.knots[k + 1])];
        return t("deBoor.span", { k, ks: subscript(k), ks1: subscript(k + 1), uk, uk1 });
      },
      { kind: "readout", live: true, data: (s, d) => ({ span: String(d.span) }) },
    ),
  ),
  group(
    null,
    slider("degree", {
      label: "deBoor.control.degree",
      min: 1,
      max: MAX_DEGREE,
      step: 1,
      format: (v) => String(Math.round(v)),
      round: Math.round,
      onRelease: true,
      refuse: (p, s) => (p < 1 || p > highestDegree(s) ? degreeRange(p, s) : null),
      error: degreeRange,
      set: setDegree,
    }),
    numberList("knots", {
      label: "deBoor.control.knots",
      format: (u) => numberText(u),
      help: (s) =>
        t("deBoor.knotsHelp", { m: s.knots.length, count: s.points.length, p: s.degree }),
      apply: typedKnots,
    }),
    actions([CLAMPED]),
  ),
  group(
    null,
    readout("degree", (s, d) => {
      return t("deBoor.degree", {
        p: s.degree,
        count: s.points.length,
        segments: tp("deBoor.spans", d.spans),
      });
    }),
    pointButtons("points", {
      min: MIN_POINTS,
      max: MAX_POINTS,
      prefix: strings,
      addTitle: "deBoor.control.addPoint.title",
      removeTitle: "deBoor.control.removePoint.title",
      apply: setPoints,
    }),
  ),
  group(null, checkbox("construction", { label: "control.construction" })),
];

// ------------------------------------------------------------------ the figure

export const figure = {
  bounds: (s) => boundsOf(s.points),
  insets: scaledInsets(0, 0, STRIP_PX, 0),
  handles: { field: "points" },
};

const labels = new LevelLabels("d", (i, level) => level + i);
const placer = new LegLabelPlacer();
const centre = new Float64Array(2);

/**
 * The polygon and its active part, the curve, the levels of the triangle at u (labels kept
 * clear of each other), the handles, C(u) = d_p^p and the knot strip.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const p = s.degree;
  const tri = d.triangle;
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  if (s.construction) {
    flatPath(r, v, tri, 0, p + 1);
    r.paint(theme.axis);
  }
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  // Labels go on the side away from the active points' centroid.
  centre[0] = 0;
  centre[1] = 0;
  for (let j = 0; j <= p; j++) {
    centre[0] += v.sx(tri[2 * j]) / (p + 1);
    centre[1] += v.sy(tri[2 * j + 1]) / (p + 1);
  }
  placer.reset();
  placer.points = s.points;
  if (s.construction)
    drawLevels(r, v, tri, p, centre, p <= LABEL_LEVELS_MAX_DEGREE ? labels : null, placer);
  d.handles.draw(r, v);
  const apex = levelStart(p, p);
  r.point(v.sx(tri[2 * apex]), v.sy(tri[2 * apex + 1]), theme.pointOnCurve);
  const radius = theme.pointOnCurve.radius * r.scale;
  placer.place(
    r,
    v,
    tri,
    p,
    p,
    0,
    t("deBoor.pointLabel"),
    centre,
    theme.labelPoint,
    radius,
    s.points,
  );
  drawStrip(r, s, d);
}

/** The knot vector on a line: domain solid, outside dashed, the active span shaded, u marked. */
function drawStrip(r, s, d) {
  d.strip.layout(r.width, r.height, r.scale);
  drawKnotSpanStrip(r, d.strip, {
    knots: s.knots,
    span: d.span,
    domain: domain(s),
    u: s.u,
    marks: d.knotStrip,
    captions: d.captions,
    lineRow: LINE_ROW,
  });
}

// ------------------------------------------------------------------ formula, label, table

/** The span and the active points, the recurrence, the live α of each level, the point. */
export function formula(s, d) {
  const p = s.degree;
  const k = d.span;
  const num = d.numbers;
  const apex = 2 * levelStart(p, p);
  const x = d.triangle[apex];
  const y = d.triangle[apex + 1];
  const uTex = numberText(s.u, true);
  const shift = k - p;
  const active = shift === 0 ? "P_{j}" : `P_{j${shift > 0 ? "+" : "-"}${Math.abs(shift)}}`;
  const spanTex = `[${listTex([numberText(s.knots[k], true), numberText(s.knots[k + 1], true)], DECIMALS, " ")})`;
  const lines = [
    `u = ${uTex} \\in [u_{${k}}, u_{${k + 1}}) = ${spanTex},\\quad k = ${k},` +
      `\\quad d_j^0 = P_{j+k-p} = ${active},\\ j = 0,\\dots,${p}`,
    `d_j^r = (1-\\alpha_j^r)\\,d_{j-1}^{r-1} + \\alpha_j^r\\,d_j^{r-1},` +
      `\\quad \\alpha_j^r = \\frac{u - u_{j+k-p}}{u_{j+1+k-r} - u_{j+k-p}}` +
      `\\quad (r = 1,\\dots,${p};\\ j = ${p},\\dots,r)`,
  ];
  for (let level = 1; level <= p; level++) {
    const parts = d.alphas[level - 1].map((alpha) => {
      const ratio = `\\tfrac{u - u_{${alpha.lo}}}{u_{${alpha.hi}} - u_{${alpha.lo}}}`;
      return `\\alpha_{${alpha.j}}^{${level}} = ${ratio} = ${num.alpha(alpha, true)}`;
    });
    lines.push(`r = ${level}:\\quad ${parts.join(",\\quad ")}`);
  }
  const point = `\\left(${listTex([num.coord(x, p, 0, true), num.coord(y, p, 0, true)])}\\right)`;
  const inexact = !Number.isInteger(x) || !Number.isInteger(y);
  const approx = num.exact && inexact && num.apexExact ? `\\approx ${pointTex([x, y])}` : "";
  lines.push(`C(${uTex}) = d_{${p}}^{${p}} = ${point} ${approx}`);
  return lines;
}

/** "cubic B-spline with 7 control points, knots 0 0 0 0 1 2 3 4 4 4 4; u = 1.250 in span k = 4, …". */
export function label(s, d) {
  const p = s.degree;
  const k = d.span;
  const apex = 2 * levelStart(p, p);
  return t("deBoor.aria", {
    kind: degreeName(p),
    count: s.points.length,
    knots: s.knots.map((u) => numberText(u)).join(" "),
    u: fmt(s.u),
    k,
    uk: numberText(s.knots[k]),
    uk1: numberText(s.knots[k + 1]),
    x: fmt(d.triangle[apex], 2),
    y: fmt(d.triangle[apex + 1], 2),
  });
}

/**
 * The table: one row per level r, cells d_j^r (fraction and decimals) with the α that made them
 * (lib/de-boor-table.js).
 */
export function setup(ui) {
  ui.ctx.slots.figure.style.aspectRatio = "4 / 3"; // the curve and the knot strip share the figure
  const table = new DeBoorTable(strings);
  ui.ctx.slots.details.append(table.title, table.wrap);
  return {
    update(s, d) {
      const caption = t("deBoor.tableCaption", { u: numberText(s.u), k: d.span });
      table.show(s.degree, d.span, d.triangle, d.alphas, d.numbers, caption);
    },
  };
}
