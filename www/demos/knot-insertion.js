/**
 * Demo (syllabus §3): knot insertion (Boehm) and Bézier extraction. Click the curve (or set u
 * and press Insert) to insert a knot: the core's `insertKnot(u, 1)` returns a curve with one
 * more control point and the very same shape. The new polygon Q is drawn strongly with its new
 * points labelled, the polygon before the insertion ghosted; the knot vectors before and after
 * and the α_i of Boehm's rule are listed. Repeated insertions pull the polygon onto the curve;
 * "Extract Bézier segments" draws each `toBezier()` segment's control polygon.
 *
 * Boehm's rule for s ∈ [u_k, u_{k+1}): Q_i = P_i (i ≤ k − p), Q_i = P_{i−1} (i ≥ k + 1) and
 *   Q_i = (1 − α_i) P_{i−1} + α_i P_i,  α_i = (s − u_i) / (u_{i+p} − u_i),  k − p + 1 ≤ i ≤ k.
 *
 * State: the original points and knots plus the list of inserted knots, so undo, links and
 * files replay the insertions: the curve before the last insertion is `refine(all but the last)`
 * and the shown curve is that one's `insertKnot(last, 1)`. Dragging an original point goes
 * through `setControlPoint` on the original curve; the refined curves are asked from the core
 * again. JS does no curve maths: a click picks the nearest drawn sample (`sampleUniform`), and
 * the span and the α shown are the core's `insertionAlphas(s)`.
 */
import { field, checkNumber, checkNumbers } from "../lib/validate.js";
import { slider, checkbox, readout, actions, group } from "../lib/panel.js";
import { parameterStrip, knotMarks } from "../lib/param-strip.js";
import { bsplineCurve, domainOf } from "../lib/bspline.js";
import { knotText } from "../lib/knot-ruler.js";
import { placeLabel } from "../lib/handles.js";
import {
  fmt,
  subscript,
  degreeName,
  parseNumberInput,
  fractionText,
  pointTex,
  simpleFraction,
  DECIMALS,
  listSeparator,
  listTex,
  listText,
  fractionOrDecimals,
} from "../lib/format.js";
import { HUES, WIDTH, RADIUS, themed } from "../lib/theme.js";
import { t, tp } from "../lib/strings.js";
import { boundsOf } from "../lib/geometry.js";
import { CurvePicker, HoveredSample } from "../lib/curve-picker.js";
import { curveChecksum } from "../lib/curve-checksum.js";
import { InsertionTable } from "../lib/insertion-table.js";
import { refineInto } from "../lib/refined-curves.js";
import { labelOffLeg } from "../lib/leg-label.js";
import { knotListText, knotVectorReadout } from "../lib/knot-readout.js";
import { flatPath } from "../lib/draw.js";
import { scaledInsets } from "../lib/view.js";
import { errorText } from "../lib/core-errors.js";

export const id = "knot-insertion";
export const strings = "knotInsertion";
export const section = 3;

/**
 * The quadratic example of the Croatian notes (syllabus §3): p = 2, six points,
 * U = [0, 0, 0, 1, 2, 3, 4, 4, 4] (four non-empty spans), shown after inserting s = 3/2
 * (α₂ = 3/4, α₃ = 1/4: knots 0 0 0 1 1.5 2 3 4 4 4, five spans, so five Bézier segments);
 * u = 5/2 is ready to insert next.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [1, 4],
      [4, 5],
      [6, 1],
      [9, 2],
      [10, 5],
    ].map(Object.freeze),
  ),
  degree: 2,
  knots: Object.freeze([0, 0, 0, 1, 2, 3, 4, 4, 4]),
  inserted: Object.freeze([1.5]),
  u: 2.5,
  bezier: false,
});

/** Degrees and point counts accepted from links and files. */
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
export const MAX_POINTS = 12;
/** Most inserted knots (enough for four rounds of "halve every span" on the default curve). */
export const MAX_INSERTED = 64;
/** Points sampled along the curve (one `sampleUniform` per change); also the picking grid. */
const CURVE_SAMPLES = 257;
/** Slider resolution for u. */
const U_STEP = 0.01;
/** Opacity of the polygon before the last insertion. */
const GHOST_ALPHA = 0.55;
/** The knot strip under the figure: height and side margins in CSS px at scale 1. */
const STRIP_PX = 62;
const STRIP_MARGIN = 34;
/** Rows of the strip, CSS px below its top at scale 1: u label, axis, knot labels. */
const ROW = Object.freeze({ label: 12, axis: 30, ticks: 48 });
/** Half-length of a knot tick (inserted knots: longer), CSS px. */
const TICK_PX = 6;
const INSERTED_TICK_PX = 10;
/** Knot labels closer than this (CSS px) to the previous one are left out. */
const LABEL_SPACING_PX = 30;

// ------------------------------------------------------------------ the state and its checks

const domain = (s) => domainOf(s.knots, s.degree);

export const fields = {
  points: field.points({ min: MIN_DEGREE + 1, max: MAX_POINTS }),
  degree(s, name) {
    checkNumber(s, name, { min: MIN_DEGREE, max: MAX_DEGREE, integer: true });
    const count = s.points.length;
    const p = s.degree;
    if (count < p + 1)
      throw new Error(t("knotInsertion.error.tooFewPoints", { min: p + 1, p, count }));
  },
  knots(s, name) {
    const m = s.points.length + s.degree + 1;
    checkNumbers(s, name, { min: m, max: m });
    for (let i = 1; i < s.knots.length; i++) {
      if (s.knots[i] < s.knots[i - 1]) throw new Error(t("knotInsertion.error.knotOrder", { i }));
    }
    const [a, b] = domain(s);
    if (!(a < b)) throw new Error(t("knotInsertion.error.emptyDomain"));
  },
  inserted(s, name) {
    checkNumbers(s, name, { min: 0, max: MAX_INSERTED });
    const [a, b] = domain(s);
    for (const value of s.inserted) {
      if (value < a || value > b)
        throw new Error(t("knotInsertion.error.insertedRange", { value, a, b }));
    }
  },
  u: field.number((s) => {
    const [min, max] = domain(s);
    return { min, max };
  }),
  bezier: field.boolean(),
};

// ------------------------------------------------------------------ the curves, from the core

/** The original curve and the refined ones; an original point dragged asks for them again. */
export const derive = {
  from: ["points", "degree", "knots", "inserted"],
  build(s, sl) {
    const m = { base: bsplineCurve(sl, s), refined: [], curves: {} };
    try {
      refineInto(m, s.inserted);
    } catch (err) {
      m.base.free();
      throw err;
    }
    return m;
  },
  moved(m, i, xy, s) {
    m.base.setControlPoint(i, xy); // in place: the original curve is not rebuilt
    if (s.inserted.length > 0) refineInto(m, s.inserted);
  },
};

/**
 * The knot s of the last insertion (or the slider's u, as a preview), and from the core's
 * `insertionAlphas(s)` on the curve before it: its span k and α_i, i = k−p+1 … k. The α are
 * SHOWN, not used: the new points come from the core's insertKnot.
 */
function boehm(s, d) {
  const preview = s.inserted.length === 0;
  const at = preview ? s.u : s.inserted[s.inserted.length - 1];
  const { span: k, alphas: values } = d.curves.previous.insertionAlphas(at);
  return {
    preview,
    s: at,
    k,
    alphas: values.map((value, m) => ({ i: k - s.degree + 1 + m, value })),
  };
}

/** Each Bézier segment's control points (`toBezier()`), when they are shown. */
function segments(s, d) {
  if (!s.bezier) return [];
  return d.curves.current.toBezier().map((segment) => {
    const points = segment.controlPoints();
    segment.free();
    return points;
  });
}

const ALL = ["points", "degree", "knots", "inserted"];
export const compute = {
  samples: [ALL, (s, d) => d.curves.current.sampleUniform(CURVE_SAMPLES)],
  // A checksum of the drawn samples (`data-curve-sum`): insertion must leave it unchanged.
  curveSum: [ALL, (s, d) => curveChecksum(d.samples, CURVE_SAMPLES)],
  currentPoints: [ALL, (s, d) => d.curves.current.controlPoints()],
  previousPoints: [ALL, (s, d) => d.curves.previous.controlPoints()],
  currentKnots: [ALL, (s, d) => d.curves.current.knots()],
  previousKnots: [ALL, (s, d) => d.curves.previous.knots()],
  segments: [[...ALL, "bezier"], segments],
  marks: [ALL, (s, d) => ({ ...knotMarks(d.currentKnots), inserted: new Set(s.inserted) })],
  uPoint: [[...ALL, "u"], (s, d) => d.base.evaluate(s.u)],
  uLabel: [["u"], (s) => `u = ${knotText(s.u)}`],
  last: [[...ALL, "u"], boehm],
};

// ------------------------------------------------------------------ the panel and its actions

/** Inserts the knots `more` (once each) after those inserted so far; false when refused. */
function insertAll(ui, more) {
  const s = ui.state;
  if (s.inserted.length + more.length > MAX_INSERTED) {
    ui.status(t("knotInsertion.maxInserted", { max: MAX_INSERTED }), "error");
    return;
  }
  try {
    ui.replace({ ...s, inserted: [...s.inserted, ...more] });
  } catch (err) {
    ui.status(t("knotInsertion.refused", { message: errorText(err) }), "error");
  }
}

/** The midpoint of every non-empty span of the shown curve (one `refine` call). */
function spanMidpoints(ui) {
  const knots = ui.data.currentKnots;
  return Array.from(ui.data.curves.current.spans(), (k) => (knots[k] + knots[k + 1]) / 2);
}

/** A typed u outside the domain is named as such; other text is no number. */
function badU(text, s) {
  const value = parseNumberInput(text);
  if (!Number.isFinite(value)) return t("control.badNumber", { value: text });
  const [a, b] = domain(s).map((u) => knotText(u));
  return t("knotInsertion.outside", { value: knotText(value), a, b });
}

const ACTIONS = [
  {
    name: "insert",
    label: "knotInsertion.control.insert",
    title: "knotInsertion.control.insert.title",
    run: (ui) => insertAll(ui, [ui.state.u]),
    disabled: (s) => s.inserted.length >= MAX_INSERTED,
  },
  {
    name: "refine-all",
    label: "knotInsertion.control.refine",
    title: "knotInsertion.control.refine.title",
    run: (ui) => insertAll(ui, spanMidpoints(ui)),
  },
  {
    name: "reset-knots",
    label: "knotInsertion.control.reset",
    title: "knotInsertion.control.reset.title",
    run: (ui) => ui.state.inserted.length > 0 && ui.replace({ ...ui.state, inserted: [] }),
    disabled: (s) => s.inserted.length === 0,
  },
];

/** Control points of the shown curve. */
const pointCount = (d) => d.currentPoints.length / 2;

export const controls = [
  parameterStrip("u", {
    height: STRIP_PX,
    margin: STRIP_MARGIN,
    step: U_STEP,
    range: domain,
    over: (ui) => ui.data.hover.set(-1),
  }),
  group(
    null,
    slider("u", { label: "knotInsertion.control.u", range: domain, step: U_STEP, error: badU }),
    actions(ACTIONS),
  ),
  group(
    null,
    readout(
      "count",
      (s, d) => t("knotInsertion.readout", { count: pointCount(d), knots: d.currentKnots.length }),
      {
        kind: "readout",
        live: true,
        data: (s, d) => ({
          points: String(pointCount(d)),
          knots: String(d.currentKnots.length),
          curveSum: String(d.curveSum),
        }),
      },
    ),
    checkbox("bezier", { label: "knotInsertion.control.bezier" }),
    readout(
      "segments",
      (s, d) => {
        return s.bezier
          ? tp("knotInsertion.segments", d.segments.length)
          : t("knotInsertion.segmentsOff");
      },
      { data: (s, d) => ({ segments: s.bezier ? String(d.segments.length) : null }) },
    ),
  ),
];

// ------------------------------------------------------------------ the figure

export const figure = {
  bounds: (s) => boundsOf(s.points),
  insets: scaledInsets(0, 0, STRIP_PX, 0),
  handles: { field: "points" },
};

/** The demo's own styles of a theme. */
const stylesFor = themed((theme) => ({
  ghost: Object.freeze({ ...theme.polygon, strokeAlpha: GHOST_ALPHA }),
  strong: Object.freeze({ stroke: theme.text, width: WIDTH.construction, join: "round" }),
  q: Object.freeze({
    fill: theme.text,
    stroke: theme.background,
    width: WIDTH.helper,
    radius: RADIUS.constructionPoint,
  }),
  qNew: Object.freeze({
    fill: HUES.vermillion,
    stroke: theme.background,
    width: WIDTH.helper,
    radius: RADIUS.pointOnCurve,
  }),
  hover: Object.freeze({
    stroke: HUES.vermillion,
    width: WIDTH.construction,
    radius: RADIUS.handleHover,
  }),
  tick: Object.freeze({ stroke: theme.text, width: WIDTH.construction }),
  insertedTick: Object.freeze({ stroke: HUES.vermillion, width: WIDTH.split }),
}));

/** "Q₀" … (cached). */
const qLabels = [];
const qLabel = (i) => (qLabels[i] ??= `Q${subscript(i)}`);

/**
 * The polygon before the last insertion ghosted, the curve, the Bézier segments' polygons or
 * the new polygon Q with the points the insertion made, the handles, where Insert would insert,
 * the sample under the pointer, and the knot strip.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const st = stylesFor(theme);
  const inserted = s.inserted.length > 0;
  flatPath(r, v, d.previousPoints);
  r.paint(inserted ? st.ghost : theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  const q = d.currentPoints;
  if (s.bezier) {
    for (let k = 0; k < d.segments.length; k++) {
      const pts = d.segments[k];
      const colour = k % theme.levelStroke.length;
      flatPath(r, v, pts);
      r.paint(theme.levelStroke[colour]);
      const style = theme.levelPoint[colour];
      for (let j = 0; j < pts.length / 2; j++)
        r.point(v.sx(pts[2 * j]), v.sy(pts[2 * j + 1]), style);
    }
  } else if (inserted) {
    const count = q.length / 2;
    flatPath(r, v, q, 0, count);
    r.paint(st.strong);
    for (let i = 0; i < count; i++) r.point(v.sx(q[2 * i]), v.sy(q[2 * i + 1]), st.q);
  }
  d.handles.draw(r, v);
  if (!s.bezier && inserted) {
    const { k } = d.last;
    for (let i = k - s.degree + 1; i <= k; i++) {
      const x = v.sx(q[2 * i]);
      const y = v.sy(q[2 * i + 1]);
      r.point(x, y, st.qNew);
      const radius = st.qNew.radius * r.scale;
      labelOffLeg(r, v, d.previousPoints, qLabel(i), x, y, i, theme.labelPoint, radius);
    }
  }
  // Where Insert would insert: C(u) on the curve, a ring (the filled vermillion dots are new points).
  r.point(v.sx(d.uPoint[0]), v.sy(d.uPoint[1]), st.hover);
  const hover = d.hover;
  if (hover.index >= 0 && d.handles.hovered < 0 && d.handles.dragging < 0) {
    const x = v.sx(d.samples[2 * hover.index]);
    const y = v.sy(d.samples[2 * hover.index + 1]);
    r.point(x, y, st.hover);
    placeLabel(r, hover.label, x, y, 0, -1, st.hover.radius * r.scale, theme.labelPoint);
  }
  drawStrip(r, s, d, theme, st);
}

/** The parameter line under the figure: the knots as ticks (inserted ones longer, vermillion) and u. */
function drawStrip(r, s, d, theme, st) {
  const strip = d.strip;
  strip.layout(r.width, r.height, r.scale);
  const { values, labels, inserted } = d.marks;
  const isInserted = (j) => inserted.has(values[j]);
  strip.drawAxis(r, ROW.axis, theme.axis);
  strip.drawTicks(r, values, ROW.axis, TICK_PX, st.tick, (j) => !isInserted(j));
  strip.drawTicks(r, values, ROW.axis, INSERTED_TICK_PX, st.insertedTick, isInserted);
  const labelStyle = (j) => (isInserted(j) ? theme.labelPoint : theme.labelSmall);
  strip.drawLabels(r, values, labels, ROW.ticks, labelStyle, LABEL_SPACING_PX);
  strip.drawParameter(r, s.u, d.uLabel, ROW.axis, ROW.label, theme.pointOnCurve, theme.labelPoint);
}

// ------------------------------------------------------------------ formula, lists, table, label

/** A number as text (or TeX): a simple fraction when it is one, else 3 decimals. */
const numberText = fractionOrDecimals;

/** Boehm's rule with the live α (the Q values come from the core's new polygon). */
export function formula(s, d) {
  const p = s.degree;
  const { preview, s: at, k, alphas } = d.last;
  const U = d.previousKnots;
  const q = d.currentPoints;
  const alphaTex = alphas
    .map(({ i, value }) => {
      const ratio = `\\frac{${knotText(at, true)} - ${knotText(U[i], true)}}{${knotText(U[i + p], true)} - ${knotText(U[i], true)}}`;
      return `\\alpha_{${i}} = ${ratio} = ${numberText(value, true)}`;
    })
    .join(",\\quad ");
  const previewTex = preview ? `\\text{${t("knotInsertion.formula.preview")}}\\ ` : "";
  const spanTex = `[${listTex([numberText(U[k], true), numberText(U[k + 1], true)], DECIMALS, " ")})`;
  const lines = [
    `${previewTex}s = ${numberText(at, true)} \\in [u_{${k}}, u_{${k + 1}}) = ${spanTex},` +
      `\\quad k = ${k},\\quad p = ${p}`,
    `Q_i = P_i\\ (i \\le ${k - p}),\\qquad Q_i = (1-\\alpha_i)\\,P_{i-1} + \\alpha_i\\,P_i` +
      `\\ (${k - p + 1} \\le i \\le ${k}),\\qquad Q_i = P_{i-1}\\ (i \\ge ${k + 1})`,
    `\\alpha_i = \\frac{s - u_i}{u_{i+p} - u_i}:\\quad ${alphaTex}`,
  ];
  if (!preview) {
    const terms = alphas.map(({ i, value }) => {
      const sum = `${numberText(1 - value, true)}\\,P_{${i - 1}} + ${numberText(value, true)}\\,P_{${i}}`;
      return `Q_{${i}} = ${sum} = ${pointTex([q[2 * i], q[2 * i + 1]])}`;
    });
    lines.push(terms.join(",\\quad "));
  }
  return lines;
}

/** "quadratic B-spline with 7 control points and 10 knots after inserting u = 1.5 with α = …". */
export function label(s, d) {
  const { preview, s: at, alphas } = d.last;
  return t(preview ? "knotInsertion.ariaNone" : "knotInsertion.aria", {
    kind: degreeName(s.degree),
    count: d.currentPoints.length / 2,
    knots: d.currentKnots.length,
    s: knotText(at),
    alphas: listText(alphas.map(({ value }) => value)),
    segments: s.bezier ? tp("knotInsertion.ariaSegments", d.segments.length) : "",
  });
}

/** The knot vectors before and after, the α used, the insertions so far (under the figure). */
const LISTS = [
  knotVectorReadout(
    "knots-before",
    (s, d) => {
      const { preview, s: at } = d.last;
      if (preview) return t("knotInsertion.knotsNow", { knots: knotListText(d.currentKnots) });
      const knots = knotListText(d.previousKnots);
      return t("knotInsertion.knotsBefore", { s: knotText(at), knots });
    },
    (s, d) => d.previousKnots,
  ),
  knotVectorReadout(
    "knots-after",
    (s, d) => {
      if (d.last.preview) return t("knotInsertion.knotsNone");
      return t("knotInsertion.knotsAfter", { knots: knotListText(d.currentKnots) });
    },
    (s, d) => (d.last.preview ? null : d.currentKnots),
  ),
  readout(
    "alphas",
    (s, d) => {
      const { preview, s: at, alphas } = d.last;
      const list = alphas
        .map(({ i, value }) => {
          const f = simpleFraction(value);
          return `α${subscript(i)} = ${f ? `${fractionText(f)} (${fmt(value)})` : fmt(value)}`;
        })
        .join(listSeparator());
      if (preview) return t("knotInsertion.alphasPreview", { s: knotText(at), alphas: list });
      return t("knotInsertion.alphasUsed", { alphas: list });
    },
    { data: (s, d) => ({ alphas: d.last.alphas.map(({ value }) => String(value)).join(",") }) },
  ),
  readout("inserted", (s) =>
    s.inserted.length
      ? t("knotInsertion.insertedList", {
          count: s.inserted.length,
          knots: listText(s.inserted.map((u) => knotText(u))),
        })
      : t("knotInsertion.insertedNone"),
  ),
];

/**
 * The lists and the table of the new points Q_i with the rule that made each (values from the
 * core), and the pointer tool: a click (or tap) on the curve inserts the parameter of the
 * nearest drawn sample; the handles come first, so a press on a control point still drags it.
 */
export function setup(ui) {
  const lists = LISTS.map((part) => part.build(ui));
  const table = new InsertionTable();
  ui.ctx.slots.details.append(...lists.map((part) => part.element), table.title, table.wrap);

  const view = ui.view;
  const sampleU = (j) => {
    const [a, b] = domain(ui.state);
    return a + ((b - a) * j) / (CURVE_SAMPLES - 1);
  };
  /** The sample under the pointer (a click inserts its u), shared with draw. */
  const hover = new HoveredSample(view, (j) =>
    t("knotInsertion.hoverLabel", { u: knotText(sampleU(j)) }),
  );
  ui.data.hover = hover;
  new CurvePicker(view, {
    samples: () => ui.data.samples,
    count: CURVE_SAMPLES,
    press: (j) => hover.set(j),
    click: (j) => insertAll(ui, [sampleU(j)]),
    hover: (j) => hover.set(j),
    ignore: () => ui.handles.hovered >= 0,
    cursor: "copy",
  });

  return {
    update(s, d) {
      lists.forEach((part) => part.sync(s, d));
      const { preview, s: at, k, alphas } = d.last;
      const caption = preview
        ? t("knotInsertion.tableEmpty")
        : t("knotInsertion.tableCaption", { s: knotText(at) });
      table.show(d.currentPoints, s.degree, k, alphas, caption, preview);
    },
  };
}
