/**
 * Demo (syllabus §4): the weights of a rational Bézier curve
 *   P(t) = Σ Bᵢⁿ(t) wᵢ Pᵢ / Σ Bⱼⁿ(t) wⱼ = Σ Rᵢ(t) Pᵢ,   Rᵢ = wᵢ Bᵢⁿ / Σ wⱼ Bⱼⁿ.
 * A curve with a log-scaled weight slider per control point (and a ring around each point whose
 * size shows wᵢ; drag the ring to change it), the polynomial curve with all weights 1 as a
 * dotted ghost, and an inset drawing the homogeneous picture: the control points
 * (wᵢxᵢ, wᵢyᵢ, wᵢ), the polynomial curve through them in (wx, wy, w) space, the plane w = 1 and
 * rays from the origin that project curve points onto it (central projection).
 *
 * Everything drawn comes from the core: the rational curve (`BezierCurve` with weights), the
 * ghost (the same points without weights), the homogeneous curve (a 3D polynomial `BezierCurve`
 * on `homogeneousPoints()`), each updated in place while dragging, and the table's shares
 * Rᵢ(t) (`rationalBasis(t)`). The inset is lib/homogeneous-inset.js.
 */
import { field, checkNumbers } from "../lib/validate.js";
import { slider, checkbox, pointButtons, readout, actions, group } from "../lib/panel.js";
import { weightSliders, weightText } from "../lib/weight-sliders.js";
import {
  fmt,
  subscript,
  simpleFraction,
  exactFraction,
  fractionText,
  fractionTex,
  fmtTex,
  pointTex,
  pointText,
  listTex,
  listText,
  localeDecimal,
  texListSeparator,
  shownNumbers,
} from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { drawCornerLegend } from "../lib/legend.js";
import { weightRings, drawWeightRings } from "../lib/weight-rings.js";
import { el, setText } from "../lib/controls.js";
import { titledTable } from "../lib/table.js";
import { drawHomogeneousInset, insetOnRight, insetSize } from "../lib/homogeneous-inset.js";

export const id = "weights";
export const strings = "weights";
export const section = 4;

/**
 * A cubic with integer points and w₁ = 3: the curve leans toward P₁ compared with the dotted
 * polynomial ghost. At t = 1/2 (by hand from the syllabus formula): Bernstein values 1/8, 3/8,
 * 3/8, 1/8, so P(1/2) = (0·1 + 1·9 + 4·3 + 5·1, 0 + 3·9 + 3·3 + 0)/14 = (13/7, 18/7).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [1, 3],
      [4, 3],
      [5, 0],
    ].map(Object.freeze),
  ),
  weights: Object.freeze([1, 3, 1, 1]),
  t: 0.5,
  homogeneous: true,
});

/** Fewest and most control points (quadratic … quintic). */
export const MIN_POINTS = 3;
export const MAX_POINTS = 6;
/** Range of a weight (the sliders are logarithmic over it), slider step in log10 units. */
export const WEIGHT_MIN = 0.1;
export const WEIGHT_MAX = 10;
const WEIGHT_LOG_STEP = 0.01;
/** Points sampled along each curve (one `sampleUniform` call per curve per change). */
export const CURVE_SAMPLES = 256;
/** Parameters whose projection rays the inset draws (the current t is added to them). */
export const RAY_TS = Object.freeze([0, 0.25, 0.5, 0.75, 1]);
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;
/** Multiplier of the "scale all weights" button (only ratios matter: the curve stays). */
const SCALE_FACTOR = 2;
/** Distances below this are written in exponent form (rounding noise such as 2e-16). */
const SMALL_GAP = 1e-3;
/** Height (CSS px) of the band at the top kept for the key (the world window starts below it). */
const LEGEND_PX = 50;

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  /** One weight per point, each > 0 (the message says why) and in [WEIGHT_MIN, WEIGHT_MAX]. */
  weights(s, name) {
    checkNumbers(s, name, { min: MIN_POINTS, max: MAX_POINTS });
    const count = s.points.length;
    if (s.weights.length !== count) {
      throw new Error(t("weights.countMismatch", { count: s.weights.length, points: count }));
    }
    s.weights.forEach((w, i) => {
      const wi = `w${subscript(i)}`;
      if (w <= 0) throw new Error(t("weights.notPositive", { name: wi, value: w }));
      if (w < WEIGHT_MIN || w > WEIGHT_MAX) {
        throw new Error(
          t("weights.outOfRange", {
            name: wi,
            ...shownNumbers({ value: w, min: WEIGHT_MIN, max: WEIGHT_MAX }),
          }),
        );
      }
    });
  },
  t: field.number({ min: 0, max: 1 }),
  homogeneous: field.boolean(),
};

/**
 * The three wasm curves: rational, its polynomial ghost, its homogeneous 3D curve. A dragged
 * point or weight updates them in place; the homogeneous point (wᵢxᵢ, wᵢyᵢ, wᵢ) is the core's.
 */
export const derive = {
  from: ["points", "weights"],
  build(s, sl) {
    const flat = flatten(s.points);
    const curve = new sl.BezierCurve(flat, 2, new Float64Array(s.weights)); // validates first
    const ghost = new sl.BezierCurve(flat, 2);
    const homogeneous = new sl.BezierCurve(curve.homogeneousPoints(), 3);
    return { curve, ghost, homogeneous };
  },
  moved(m, i, xy) {
    m.curve.setControlPoint(i, xy);
    m.ghost.setControlPoint(i, xy);
    syncHomogeneousPoint(m, i);
  },
  weighted(m, i, w) {
    m.curve.setWeight(i, w);
    syncHomogeneousPoint(m, i);
  },
};

/** Copies homogeneous control point i from the rational curve into the 3D polynomial curve. */
function syncHomogeneousPoint(m, i) {
  m.homogeneous.setControlPoint(i, m.curve.homogeneousPoints().subarray(3 * i, 3 * i + 3));
}

/** RAY_TS, then t (scratch for `sample`). */
const rayTs = new Float64Array(RAY_TS.length + 1);
rayTs.set(RAY_TS);

/** What the core returns for drawing, and one measurement (rational ↔ polynomial). */
export const compute = {
  samples: [["points", "weights"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  ghostSamples: [["points"], (s, d) => d.ghost.sampleUniform(CURVE_SAMPLES)],
  homSamples: [["points", "weights"], (s, d) => d.homogeneous.sampleUniform(CURVE_SAMPLES)],
  homPoints: [["points", "weights"], (s, d) => d.curve.homogeneousPoints()],
  /** The projected points at RAY_TS and t, and the same parameters on the homogeneous curve. */
  rays: [
    ["points", "weights", "t"],
    (s, d) => {
      rayTs[RAY_TS.length] = s.t;
      const points = d.curve.sample(rayTs);
      return {
        points,
        hom: d.homogeneous.sample(rayTs),
        point: points.subarray(2 * RAY_TS.length),
      };
    },
  ],
  ghostPoint: [["points", "t"], (s, d) => d.ghost.evaluate(s.t)],
  /** The shares Rᵢ(t) = wᵢ Bᵢ(t) / Σ wⱼ Bⱼ(t). */
  shares: [["points", "weights", "t"], (s, d) => d.curve.rationalBasis(s.t)],
  /** How far the rational curve is from the polynomial one (0 when all wᵢ are equal). */
  maxGap: [["points", "weights"], (s, d) => largestGap(d.samples, d.ghostSamples)],
  handleLabels: [
    ["points", "weights"],
    (s) => s.weights.map((w, i) => t("weights.handleLabel", { i: subscript(i), w: weightText(w) })),
  ],
  /** What the homogeneous inset draws (lib/homogeneous-inset.js). */
  inset: [
    ["points", "weights", "t"],
    (s, d) => ({
      prefix: strings,
      points: s.points,
      homPoints: d.homPoints,
      samples: d.samples,
      homSamples: d.homSamples,
      sampleCount: CURVE_SAMPLES,
      rayPoints: d.rays.points,
      rayHom: d.rays.hom,
      rayCount: rayTs.length,
    }),
  ],
  pointLabels: [
    ["t"],
    (s) => ({
      point: t("weights.pointLabel", { t: tText(s) }),
      ghost: t("weights.ghostPointLabel", { t: tText(s) }),
    }),
  ],
};

function largestGap(a, b) {
  let gap = 0;
  for (let k = 0; k < CURVE_SAMPLES; k++) {
    gap = Math.max(gap, Math.hypot(a[2 * k] - b[2 * k], a[2 * k + 1] - b[2 * k + 1]));
  }
  return gap;
}

/** Sets every weight to f(w) (one undo step). */
function setAllWeights(ui, f) {
  ui.state.weights.forEach((w, i) => ui.setWeight(i, f(w), false));
  ui.commit();
}

const allOne = (ui) => setAllWeights(ui, () => 1);

/** Multiplies every weight by SCALE_FACTOR (or divides, when that would leave the range). */
function scaleAll(ui) {
  const max = Math.max(...ui.state.weights);
  const min = Math.min(...ui.state.weights);
  const up = max * SCALE_FACTOR <= WEIGHT_MAX;
  const factor = up ? SCALE_FACTOR : min / SCALE_FACTOR >= WEIGHT_MIN ? 1 / SCALE_FACTOR : 0;
  if (!factor) {
    ui.status(
      t("weights.cannotScale", shownNumbers({ min: WEIGHT_MIN, max: WEIGHT_MAX })),
      "error",
    );
    return;
  }
  setAllWeights(ui, (w) => w * factor);
  ui.status(
    t("weights.scaled", { factor: factor > 1 ? `× ${factor}` : `÷ ${1 / factor}` }),
    "info",
  );
}

export const controls = [
  group(
    "weights.weightsLegend",
    weightSliders({ prefix: strings, min: WEIGHT_MIN, max: WEIGHT_MAX, step: WEIGHT_LOG_STEP }),
    actions([
      { name: "weights-one", label: "weights.allOne", title: "weights.allOne.title", run: allOne },
      {
        name: "weights-scale",
        label: "weights.scaleAll",
        params: { factor: SCALE_FACTOR },
        title: "weights.scaleAll.title",
        run: scaleAll,
      },
    ]),
  ),
  group(
    null,
    slider("t", { label: "control.t", min: 0, max: 1, step: T_SLIDER_STEP }),
    readout(
      "curve",
      (s, d) => {
        const [x, y] = d.rays.point;
        return t("weights.readout", { t: tText(s), x: fmt(x), y: fmt(y), gap: gapText(d.maxGap) });
      },
      {
        live: true,
        data: (s, d) => ({
          point: `${d.rays.point[0]},${d.rays.point[1]}`,
          maxGap: String(d.maxGap),
        }),
      },
    ),
  ),
  group(
    null,
    readout("degree", (s) =>
      t("weights.degree", { n: s.points.length - 1, count: s.points.length }),
    ),
    pointButtons("points", {
      min: MIN_POINTS,
      max: MAX_POINTS,
      prefix: strings,
      companions: { weights: 1 },
    }),
  ),
  group(null, checkbox("homogeneous", { label: "weights.showHomogeneous" })),
];

const insetScratch = [0, 0, 0, 0];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  /** The key's band at the top, and the inset's strip on the right of a wide canvas or at the bottom. */
  insets(width, height, scale, s) {
    insetScratch[0] = LEGEND_PX;
    insetScratch[1] = insetScratch[2] = 0;
    if (!s.homogeneous) return insetScratch;
    if (insetOnRight(width, height)) insetScratch[1] = insetSize(width);
    else insetScratch[2] = insetSize(height);
    return insetScratch;
  },
  handles: { field: "points", label: (i, s, d) => d.handleLabels[i] },
};

/** The key: the rational curve (solid blue) and the polynomial ghost (dotted). */
const KEY = Object.freeze([
  { label: "weights.legendRational", style: (theme) => theme.curve },
  { label: "weights.legendPolynomial", style: (theme) => theme.compareCurve[2] },
]);

/** The polygon, the weight rings, the ghost and the curve, P(t) and the ghost's point, the inset. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  pointsPath(r, v, pts);
  r.paint(theme.polygon);
  drawWeightRings(r, v, pts, s.weights);
  // The polynomial ghost (all weights 1), then the rational curve on top.
  flatPath(r, v, d.ghostSamples, 0, CURVE_SAMPLES);
  r.paint(theme.compareCurve[2]);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);

  // Where the ghost is at t, joined to P(t): the pull of the weights.
  const gx = v.sx(d.ghostPoint[0]);
  const gy = v.sy(d.ghostPoint[1]);
  const px = v.sx(d.rays.point[0]);
  const py = v.sy(d.rays.point[1]);
  r.beginPath();
  r.moveTo(gx, gy);
  r.lineTo(px, py);
  r.paint(theme.helper);
  r.point(gx, gy, theme.comparePoint[2]);
  d.handles.draw(r, v);
  r.point(px, py, theme.pointOnCurve);
  // Labels below/above the two points, on the side away from each other.
  const below = py >= gy;
  const gap = 12 * r.scale;
  r.text(
    d.pointLabels.point,
    px,
    py + (below ? gap : -gap),
    theme.labelPoint,
    "center",
    below ? "top" : "bottom",
  );
  r.text(
    d.pointLabels.ghost,
    gx,
    gy + (below ? -gap : gap),
    theme.labelSmall,
    "center",
    below ? "bottom" : "top",
  );

  drawCornerLegend(r, KEY);
  if (s.homogeneous) drawHomogeneousInset(r, d.inset);
}

/** The definition with the live weights, the point at t, its homogeneous point, the ratio remark. */
export function formula(s, d) {
  const n = s.points.length - 1;
  const tFraction = simpleFraction(s.t);
  const tTex = tFraction ? fractionTex(tFraction) : fmtTex(s.t);
  const b = [];
  for (let i = 0; i <= n; i++) {
    const value = d.sl.bernstein(n, i, s.t);
    const f = tFraction ? exactFraction(value, tFraction.den ** n) : null;
    b.push(f ? fractionTex(f) : fmtTex(value));
  }
  const wTex = s.weights.map((w) => weightText(w, 3, true));
  const numerator = b.map((bi, i) => `${bi}\\cdot ${wTex[i]}\\,P_{${i}}`).join(" + ");
  const denominator = b.map((bi, i) => `${bi}\\cdot ${wTex[i]}`).join(" + ");
  const [x, y] = d.rays.point;
  const [X, Y, W] = Array.from(d.rays.hom.subarray(3 * RAY_TS.length), (c) => fmtTex(c));
  const ratios = s.weights.map((w) => weightText(w / s.weights[0], 3, true)).join(" : ");
  const sum = (body) => `\\sum_{i=0}^{${n}} B_i^{${n}}(t)${body}`;
  return [
    `P(t) = \\frac{${sum("\\,w_i\\,P_i")}}{${sum("\\,w_i")}},\\qquad (w_0, \\dots, w_{${n}}) = (${wTex.join(texListSeparator())})`,
    `P(${tTex}) = \\frac{${numerator}}{${denominator}} = ${pointTex([x, y])}`,
    `P^w(${tTex}) = \\sum_i B_i^{${n}}(${tTex})\\,(w_iP_i,\\ w_i) = ${pointTex([X, Y, W])} \\;\\mapsto\\; ` +
      `\\left(${listTex([`\\tfrac{${X}}{${W}}`, `\\tfrac{${Y}}{${W}}`])}\\right)`,
    `\\text{${t("weights.tex.ratios")}} w_0 : \\dots : w_{${n}} = ${ratios};\\quad ` +
      `\\lambda w_i\\ (\\lambda > 0) \\text{${t("weights.tex.same")}}`,
  ];
}

/** The figure's name: kind, weights, P(t) and the ghost's point, the pull toward the heaviest point. */
export function label(s, d) {
  const [x, y] = d.rays.point;
  const heaviest = s.weights.indexOf(Math.max(...s.weights));
  const [hx, hy] = s.points[heaviest];
  const n = s.points.length - 1;
  return t("weights.aria", {
    kind: n <= 5 ? t(`curve.degree.${n}`) : t("curve.degree.n", { n }),
    weights: listText(s.weights.map((w) => weightText(w))),
    t: tText(s),
    x: fmt(x, 2),
    y: fmt(y, 2),
    gx: fmt(d.ghostPoint[0], 2),
    gy: fmt(d.ghostPoint[1], 2),
    heaviest: `P${subscript(heaviest)}`,
    distance: fmt(Math.hypot(x - hx, y - hy), 2),
  });
}

/** The taller figure, the weight rings as a pointer tool, and the table (one row per point). */
export function setup(ui) {
  ui.ctx.slots.figure.classList.add("sl-figure-tall");
  weightRings(ui, { min: WEIGHT_MIN, max: WEIGHT_MAX });
  const { title, table, wrap } = titledTable("weights");
  ui.ctx.slots.details.append(title, wrap);
  const columns = ["point", "weight", "homogeneous", "share", "distance"];
  let rows = [];

  function build(count) {
    const head = columns.map((c) => el("th", { scope: "col", text: t(`weights.column.${c}`) }));
    rows = [];
    const body = [];
    for (let i = 0; i < count; i++) {
      const cells = Object.fromEntries(
        columns.map((c) => [c, el("td", { dataset: { column: c } })]),
      );
      rows.push(cells);
      const name = el("th", { scope: "row", text: `P${subscript(i)}` });
      body.push(el("tr", { dataset: { index: String(i) } }, name, Object.values(cells)));
    }
    const corner = el("td"); // above the row names: heads nothing
    table.replaceChildren(el("thead", {}, el("tr", {}, corner, head)), el("tbody", {}, body));
  }

  return {
    update(s, d) {
      if (rows.length !== s.points.length) build(s.points.length);
      setText(title, t("weights.tableCaption", { t: tText(s) }));
      const [x, y] = d.rays.point;
      const h = d.homPoints;
      rows.forEach((cells, i) => {
        const [px, py] = s.points[i];
        const distance = Math.hypot(x - px, y - py);
        setText(cells.point, pointText([px, py]));
        setText(cells.weight, weightText(s.weights[i]));
        setText(cells.homogeneous, pointText([h[3 * i], h[3 * i + 1], h[3 * i + 2]]));
        setText(cells.share, fmt(d.shares[i]));
        setText(cells.distance, fmt(distance));
        cells.distance.dataset.value = String(distance);
      });
    },
  };
}

function tText(s) {
  const f = simpleFraction(s.t);
  return f ? fractionText(f) : fmt(s.t);
}

function gapText(gap) {
  return gap === 0 ? "0" : gap < SMALL_GAP ? localeDecimal(gap.toExponential(1)) : fmt(gap);
}
