/**
 * Demo (syllabus §4): why the library refuses weights ≤ 0. A rational quadratic with weights
 * 1, w₁, 1 where the slider lets w₁ pass through zero:
 *   P(t) = ((1−t)² P₀ + 2t(1−t) w₁P₁ + t² P₂) / w(t),   w(t) = 1 − 2(1 − w₁) t(1 − t).
 * For w₁ > 0 the curve is the core's `BezierCurve`. For w₁ ≤ 0 the constructor throws, and the
 * demo shows its exact message; it then draws what the curve *would* be from the core's
 * teaching function `rationalPoles` (weights of any sign, no curve object): the homogeneous
 * samples (wx, wy, w), divided by w here (the central projection, display only), the t where
 * w(t) is zero, and the direction in which P(t) runs off to infinity there (a pole): the drawn
 * path breaks, and the plot underneath shows w(t) crossing zero at the core's roots.
 */
import { field } from "../lib/validate.js";
import { slider, readout, actions, group } from "../lib/panel.js";
import {
  fmt,
  fmtTex,
  pointTex,
  pointText,
  listTex,
  listText,
  localeDecimal,
} from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, boundsOf, inTriangle } from "../lib/geometry.js";
import { drawCaption, pointsPath } from "../lib/draw.js";
import { projectedPath, ExitMarks } from "../lib/clip.js";
import { PlotStrip, drawPlotStrip } from "../lib/plot-strip.js";
import { errorText } from "../lib/core-errors.js";

export const id = "negative-weights";
export const strings = "negativeWeights";
export const section = 4;

/**
 * w₁ = −2: the denominator w(t) = 1 − 6t(1 − t) vanishes at t = 1/2 ± √3/6 ≈ 0.211 and 0.789,
 * two poles; the middle piece is the hyperbola's other branch, through
 * P(1/2) = (P₀ + 2w₁P₁ + P₂)/(2 + 2w₁) = (2, 6).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [2, 3],
      [4, 0],
    ].map(Object.freeze),
  ),
  w1: -2,
});

/** Range and step of the w₁ slider (linear: it has to pass through 0). */
export const W1_MIN = -3;
export const W1_MAX = 3;
const W1_STEP = 0.01;
/** Preset buttons. */
const PRESETS = Object.freeze([1, -0.5, -1.5]);
/** The fitted window holds the triangle, P(1/2) and the curve within this many triangle sizes of its middle. */
const FIT_REACH = 1.2;
/** Samples: the real curve, and the homogeneous samples (dense: the projection races near a pole). */
const CURVE_SAMPLES = 256;
const HOM_SAMPLES = 1201;
/** |w| below this counts as zero when projecting (a pole exactly on a sample, e.g. w₁ = −1 at t = 1/2). */
const ZERO_W = 1e-12;
/** At most this many "to infinity" marks are drawn where the path leaves the figure. */
const MAX_EXITS = 8;
/** A sample this far (model units, relative to the triangle) outside the hull counts as outside. */
const HULL_TOLERANCE = 1e-9;
/**
 * The plot of w(t) below the figure (CSS px; y0 is the value lo, y1 the value hi): its strip is
 * 0.34 of the canvas height, at least 140 px, at most half a short canvas.
 */
const plot = new PlotStrip({
  fraction: 0.34,
  minPx: 140,
  shortFraction: 0.5,
  margin: Object.freeze({ top: 30, right: 24, bottom: 30, left: 50 }),
});
/** Extra room above and below the plotted values, as a fraction of their range. */
const PLOT_PAD = 0.1;
/** Length of tick marks, vertical distance between pole labels in the plot, CSS px. */
const TICK_PX = 5;
const POLE_LINE_PX = 18;
/** The path is clipped to the figure plus this margin (CSS px). */
const CLIP_MARGIN = 2;
/** "∞" marks keep this far (CSS px) from the figure's edges, and below the caption line. */
const EDGE_PX = 14;
const CAPTION_PX = 34;
/** Height (CSS px) of the band at the top kept for the caption. */
const CAPTION_BAND_PX = 30;
const HANDLE_LABELS = Object.freeze(["P₀", "P₁", "P₂"]);

export const fields = {
  points: field.points({ min: 3, max: 3 }),
  w1: field.number({ min: W1_MIN, max: W1_MAX }),
};

/** The weights 1, w₁, 1. */
const weightsOf = (s) => new Float64Array([1, s.w1, 1]);

/**
 * The library's verdict on weights 1, w₁, 1: with w₁ > 0 its curve (made, or updated in place);
 * otherwise the constructor's refusal, word for word (the last accepted curve is kept).
 */
function askLibrary(library, s, sl) {
  if (s.w1 > 0) {
    library.refusal = "";
    if (library.curve) library.curve.setWeight(1, s.w1);
    else library.curve = new sl.BezierCurve(flatten(s.points), 2, weightsOf(s));
    return;
  }
  try {
    new sl.BezierCurve(flatten(s.points), 2, weightsOf(s)).free(); // never gets here
    library.refusal = "";
  } catch (err) {
    library.refusal = errorText(err);
  }
}

/**
 * What the library says (`library.curve` while it accepts the weights, else its refusal); a
 * dragged point or w₁ updates it in place.
 */
export const derive = {
  from: ["points"],
  build(s, sl) {
    sl.rationalPoles(flatten(s.points), 2, weightsOf(s), 2); // throws first on a bad state
    const library = { curve: null, refusal: "", free: () => library.curve?.free() };
    askLibrary(library, s, sl);
    return { library };
  },
  moved: (m, i, xy) => m.library.curve?.setControlPoint(i, xy),
  inPlace: { w1: (m, s, ui) => askLibrary(m.library, s, ui.sl) },
};

/** What is drawn and said: the samples, the poles, P(1/2), whether the curve leaves its hull. */
export const compute = {
  /** The core's teaching data: homogeneous samples, the roots of w(t), the pole directions. */
  teaching: [
    ["points", "w1"],
    (s, d) => d.sl.rationalPoles(flatten(s.points), 2, weightsOf(s), HOM_SAMPLES),
  ],
  hom: [["points", "w1"], (s, d) => d.teaching.samples],
  samples: [
    ["points", "w1"],
    (s, d) => (d.library.refusal ? null : d.library.curve.sampleUniform(CURVE_SAMPLES)),
  ],
  /** The roots, and the range of the sampled w(t) (the plot's scale). */
  poles: [
    ["points", "w1"],
    (s, d) => {
      const { roots, directions } = d.teaching;
      let minW = Infinity;
      let maxW = -Infinity;
      for (let k = 0; k < HOM_SAMPLES; k++) {
        minW = Math.min(minW, d.hom[3 * k + 2]);
        maxW = Math.max(maxW, d.hom[3 * k + 2]);
      }
      return { ts: roots, directions, count: roots.length, minW, maxW };
    },
  ],
  poleLabels: [
    ["points", "w1"],
    (s, d) => Array.from(d.poles.ts, (p) => t("negativeWeights.poleLabel", { t: fmt(p) })),
  ],
  /** P(1/2) by the division (null at a pole). */
  middle: [
    ["points", "w1"],
    (s, d) => {
      const mid = 3 * ((HOM_SAMPLES - 1) / 2);
      const w = d.hom[mid + 2];
      return Math.abs(w) > ZERO_W ? [d.hom[mid] / w, d.hom[mid + 1] / w] : null;
    },
  ],
  /** A pole, or a finite projected sample outside the triangle P₀P₁P₂. */
  outsideHull: [
    ["points", "w1"],
    (s, d) => {
      if (d.poles.count > 0) return true;
      for (let k = 0; k < HOM_SAMPLES; k++) {
        const w = d.hom[3 * k + 2];
        if (Math.abs(w) <= ZERO_W) continue;
        if (!inTriangle(d.hom[3 * k] / w, d.hom[3 * k + 1] / w, s.points, HULL_TOLERANCE))
          return true;
      }
      return false;
    },
  ],
  /** The plot's value range (w = 0 and w = 1 always visible) and its lowest label. */
  plotRange: [
    ["points", "w1"],
    (s, d) => {
      const { minW, maxW } = d.poles;
      const lo = Math.min(0, minW);
      const hi = Math.max(1, maxW);
      const pad = PLOT_PAD * (hi - lo);
      return { lo: lo - pad, hi: hi + pad, loLabel: fmt(Math.min(minW, 0), 2) };
    },
  ],
};

const poleList = (d) => listText(d.poles.ts);

export const controls = [
  group(
    null,
    slider("w1", {
      label: "negativeWeights.w1",
      min: W1_MIN,
      max: W1_MAX,
      step: W1_STEP,
      error: "negativeWeights.badWeight",
    }),
    actions(
      PRESETS.map((w) => ({
        name: `w1-${w}`,
        label: "negativeWeights.preset",
        params: { w: localeDecimal(String(w)).replace("-", "−") },
        run: (ui) => ui.set("w1", w),
      })),
    ),
  ),
  group(
    "negativeWeights.libraryLegend",
    readout(
      "library",
      (s, d) => {
        const { refusal } = d.library;
        return refusal
          ? t("negativeWeights.libraryRefuses", { message: refusal })
          : t("negativeWeights.libraryAccepts");
      },
      { live: true, data: (s, d) => ({ refused: String(!!d.library.refusal) }) },
    ),
  ),
  group(
    "negativeWeights.resultLegend",
    readout(
      "poles",
      (s, d) => {
        const { count } = d.poles;
        return count
          ? tp("negativeWeights.poles", count, { list: poleList(d) })
          : t("negativeWeights.noPoles");
      },
      {
        kind: "readout",
        data: (s, d) => ({
          poles: String(d.poles.count),
          poleTs: Array.from(d.poles.ts).join(","),
          poleDirections: Array.from(d.poles.directions).join(","),
          minW: String(d.poles.minW),
        }),
      },
    ),
    readout(
      "hull",
      (s, d) => t(d.outsideHull ? "negativeWeights.outside" : "negativeWeights.inside"),
      {
        data: (s, d) => ({
          outsideHull: String(d.outsideHull),
          middle: d.middle ? `${d.middle[0]},${d.middle[1]}` : "",
        }),
      },
    ),
  ),
];

const insetScratch = [0, 0, 0, 0];

export const figure = {
  /** The triangle, P(1/2) and the projected curve near the triangle. */
  bounds(s, d) {
    const box = boundsOf(s.points);
    if (!d.hom) return box;
    const reach = FIT_REACH * Math.max(box[2] - box[0], box[3] - box[1], 1);
    const cx = (box[0] + box[2]) / 2;
    const cy = (box[1] + box[3]) / 2;
    const grow = (x, y) => {
      if (Math.abs(x - cx) > reach || Math.abs(y - cy) > reach) return;
      box[0] = Math.min(box[0], x);
      box[1] = Math.min(box[1], y);
      box[2] = Math.max(box[2], x);
      box[3] = Math.max(box[3], y);
    };
    for (let k = 0; k < HOM_SAMPLES; k++) {
      const w = d.hom[3 * k + 2];
      if (Math.abs(w) > ZERO_W) grow(d.hom[3 * k] / w, d.hom[3 * k + 1] / w);
    }
    if (d.middle) {
      box[0] = Math.min(box[0], d.middle[0]);
      box[1] = Math.min(box[1], d.middle[1]);
      box[2] = Math.max(box[2], d.middle[0]);
      box[3] = Math.max(box[3], d.middle[1]);
    }
    return box;
  },
  /** The caption line at the top, the plot of w(t) at the bottom. */
  insets(width, height) {
    insetScratch[0] = CAPTION_BAND_PX;
    insetScratch[2] = plot.height(height);
    return insetScratch;
  },
  handles: { field: "points", label: (i) => HANDLE_LABELS[i] },
};

/** The path's exits (scratch). */
const exits = new ExitMarks(MAX_EXITS);
const clipBox = new Float64Array(4);

/** The hull and polygon, the caption, the curve (the library's or the projection), ∞ marks, P(1/2), the plot. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  const w = r.width;
  const h = r.height;
  const k = r.scale;
  plot.layout(w, h, k);
  plot.lo = d.plotRange.lo;
  plot.hi = d.plotRange.hi;

  // The convex hull (the control triangle) and the control polygon.
  pointsPath(r, v, pts);
  r.closePath();
  r.paint(theme.helperFill);
  pointsPath(r, v, pts);
  r.paint(theme.polygon);

  // The caption first: marks drawn later stay on top of its halo.
  const accepted = d.samples !== null;
  const caption = t(accepted ? "negativeWeights.figureAccepted" : "negativeWeights.figureRefused");
  drawCaption(
    r,
    caption,
    12 * k,
    16 * k,
    accepted ? theme.labelSmall : theme.labelBold,
    r.width - 24 * k,
    "middle",
  );

  exits.clear();
  if (accepted) {
    r.beginPath();
    for (let j = 0; j < CURVE_SAMPLES; j++) {
      if (j === 0) r.moveTo(v.sx(d.samples[0]), v.sy(d.samples[1]));
      else r.lineTo(v.sx(d.samples[2 * j]), v.sy(d.samples[2 * j + 1]));
    }
    r.paint(theme.curve);
  } else {
    clipBox[0] = clipBox[1] = -CLIP_MARGIN;
    clipBox[2] = w + CLIP_MARGIN;
    clipBox[3] = plot.top + CLIP_MARGIN;
    projectedPath(r, v, d.hom, HOM_SAMPLES, ZERO_W, clipBox, exits);
    r.paint(theme.splitRight);
  }
  d.handles.draw(r, v);

  // Where the path runs off to infinity (below the caption line).
  for (let j = 0; j < exits.count; j++) {
    const x = Math.min(Math.max(exits.xy[2 * j], EDGE_PX * k), w - EDGE_PX * k);
    const y = Math.min(Math.max(exits.xy[2 * j + 1], CAPTION_PX * k), plot.top - EDGE_PX * k);
    r.text(t("negativeWeights.infinity"), x, y, theme.labelPoint, "center", "middle");
  }
  if (d.middle) {
    const [mx, my] = d.middle;
    r.point(v.sx(mx), v.sy(my), theme.pointOnCurve);
    r.text(
      t("negativeWeights.middleLabel"),
      v.sx(mx) + 9 * k,
      v.sy(my),
      theme.labelPoint,
      "left",
      "middle",
    );
  }
  drawPlot(r, theme, d);
}

// ------------------------------------------------------------ the plot of w(t)
/** The band under the figure: axes, w = 1, w(t) (solid where positive, dashed where negative), the poles. */
function drawPlot(r, theme, d) {
  const s = r.scale;
  drawPlotStrip(r, plot);

  // Axes: t from 0 to 1 along w = 0, the value axis on the left.
  const zero = plot.y(0);
  r.beginPath();
  r.moveTo(plot.x0, plot.y1);
  r.lineTo(plot.x0, plot.y0);
  r.moveTo(plot.x0, zero);
  r.lineTo(plot.x1, zero);
  for (let k = 0; k <= 2; k++) {
    r.moveTo(plot.x(k / 2), zero);
    r.lineTo(plot.x(k / 2), zero + TICK_PX * s);
  }
  r.paint(theme.axis);
  r.beginPath();
  r.moveTo(plot.x0, plot.y(1));
  r.lineTo(plot.x1, plot.y(1));
  r.paint(theme.helper);
  const left = plot.x0 - (TICK_PX + 2) * s;
  r.text("0", left, zero, theme.labelSmall, "right", "middle");
  r.text("1", left, plot.y(1), theme.labelSmall, "right", "middle");
  if (plot.lo < -PLOT_PAD)
    r.text(d.plotRange.loLabel, left, plot.y0, theme.labelSmall, "right", "middle");
  r.text(
    t("negativeWeights.tickHalf"),
    plot.x(0.5),
    zero + (TICK_PX + 2) * s,
    theme.labelSmall,
    "center",
    "top",
  );
  r.text(t("negativeWeights.axisT"), plot.x1 + 4 * s, zero, theme.labelSmall, "left", "middle");
  r.text(
    t("negativeWeights.plotTitle"),
    plot.x0 + 6 * s,
    plot.top + 8 * s,
    theme.labelSmall,
    "left",
    "top",
  );

  // w(t) = W of the homogeneous samples: solid where positive, dashed where negative.
  const hom = d.hom;
  for (let pass = 0; pass < 2; pass++) {
    r.beginPath();
    let pen = false;
    for (let k = 0; k + 1 < HOM_SAMPLES; k++) {
      const wa = hom[3 * k + 2];
      const negative = (wa + hom[3 * k + 5]) / 2 < 0;
      if (negative !== (pass === 1)) {
        pen = false;
        continue;
      }
      if (!pen) r.moveTo(plot.x(k / (HOM_SAMPLES - 1)), plot.y(wa));
      r.lineTo(plot.x((k + 1) / (HOM_SAMPLES - 1)), plot.y(hom[3 * k + 5]));
      pen = true;
    }
    r.paint(pass === 0 ? theme.curve : theme.splitRight);
  }

  // The poles on the t axis; labels point inward (toward t = 1/2), one line apart.
  const poles = d.poles.ts;
  for (let j = 0; j < poles.length; j++) {
    const x = plot.x(poles[j]);
    r.beginPath();
    r.moveTo(x, plot.y1);
    r.lineTo(x, plot.y0);
    r.paint(theme.marker);
    r.point(x, zero, theme.pointOnCurve);
    const align = poles[j] < 0.5 ? "left" : "right";
    const y = plot.y1 + (2 + POLE_LINE_PX * j) * s;
    r.text(d.poleLabels[j], x + (align === "left" ? 6 : -6) * s, y, theme.labelPoint, align, "top");
  }
}

/** The curve, its denominator, where that vanishes (or its minimum), P(1/2), the hull argument. */
export function formula(s, d) {
  const w1 = s.w1;
  const tx = (key) => `\\text{${t(`negativeWeights.tex.${key}`)}}`;
  const product = 1 / (2 * (1 - w1)); // t(1 − t) at a zero of w(t)
  const { ts, count } = d.poles; // the core's roots (a double one at w₁ = −1)
  const zeros =
    w1 <= -1 && count > 0
      ? `w(t) = 0 \\iff t(1-t) = \\tfrac{1}{2(1-w_1)} = ${fmtTex(product)} \\iff t = \\tfrac12 \\pm ` +
        `\\tfrac12\\sqrt{1 - 4\\cdot ${fmtTex(product)}} = ${listTex([ts[0], ts[count - 1]])}\\quad${tx("poles")}`
      : `\\min_t w(t) = w(\\tfrac12) = \\tfrac{1 + w_1}{2} = ${fmtTex((1 + w1) / 2)} > 0\\quad` +
        `${tx("noPole")} w(t) = 0 ${tx("needs")} w_1 \\le -1\\text{)}`;
  const middle = d.middle ? pointTex([d.middle[0], d.middle[1]]) : "\\infty";
  return [
    `P(t) = \\frac{(1-t)^2P_0 + 2t(1-t)\\,w_1P_1 + t^2P_2}{w(t)},\\qquad w_0 = w_2 = 1,\\ w_1 = ${fmtTex(w1, 2)}`,
    `w(t) = (1-t)^2 + 2t(1-t)\\,w_1 + t^2 = 1 - 2(1-w_1)\\,t(1-t)`,
    zeros,
    `P(\\tfrac12) = \\frac{P_0 + 2w_1P_1 + P_2}{2 + 2w_1} = ${middle}`,
    `w_i > 0 \\Rightarrow ${tx("coefficients")} \\tfrac{B_i(t)\\,w_i}{w(t)} \\in [0, 1] ${tx("sumToOne")} P(t) ` +
      `${tx("staysInHull")} w_1 < 0 ${tx("breaks")}`,
  ];
}

/** The figure's name: the points and weights, the library's verdict, the poles, the hull. */
export function label(s, d) {
  const [p0, p1, p2] = s.points.map(([x, y]) => pointText([x, y], 2));
  const { refusal } = d.library;
  const { count, minW } = d.poles;
  return t("negativeWeights.aria", {
    p0,
    p1,
    p2,
    w: fmt(s.w1, 2),
    verdict: refusal
      ? t("negativeWeights.ariaRefused", { message: refusal })
      : t("negativeWeights.ariaAccepted"),
    poles: count
      ? t("negativeWeights.ariaPoles", { count, list: poleList(d) })
      : t("negativeWeights.ariaNoPoles", { min: fmt(minW, 2) }),
    hull: t(d.outsideHull ? "negativeWeights.ariaOutside" : "negativeWeights.ariaInside"),
  });
}

/** The taller figure, and the library's refusal in the status line (when it changes). */
export function setup(ui) {
  ui.ctx.slots.figure.classList.add("sl-figure-tall");
  let shown = "";
  return {
    update(s, d) {
      const { refusal } = d.library;
      if (refusal === shown) return;
      shown = refusal;
      if (refusal) ui.status(t("negativeWeights.refused", { message: refusal }), "error");
      else ui.status(t("negativeWeights.accepted"), "info");
    },
  };
}
