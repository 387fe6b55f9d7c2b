/**
 * Demo (syllabus §4): projective invariance of rational curves. A cubic Bézier curve lives in
 * the square [0, 4]²; dragging the four corners Q₀ … Q₃ of the square's image defines a
 * perspective map H (a 3×3 homography, lib/homography.js). The core maps the curve
 * (`projectiveMap(H)`: control points and new weights w′ᵢ = wᵢ (h₃₁xᵢ + h₃₂yᵢ + h₃₃)); the
 * demo maps the original curve's samples one by one with the same H, as a dotted check, and the
 * two coincide to rounding. For contrast, the mapped control points with the *old* weights give
 * a different curve: forgetting the new weights is not invariant. When H would send a weight to
 * ≤ 0 the core refuses; its message is shown and the last good quadrilateral stays.
 */
import { field, checkNumbers } from "../lib/validate.js";
import { actions, readout, group } from "../lib/panel.js";
import { weightSliders, weightText } from "../lib/weight-sliders.js";
import {
  fmt,
  subscript,
  fmtTex,
  pointText,
  listText,
  localeDecimal,
  texDecimal,
  texListSeparator,
  shownNumbers,
} from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf, distanceToPolyline } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { drawCornerLegend } from "../lib/legend.js";
import { squareToQuad, applyHomography, denominator } from "../lib/homography.js";
import { scaledInsets, NARROW_CANVAS_PX } from "../lib/view.js";
import { errorText } from "../lib/core-errors.js";

export const id = "projective";
export const strings = "projective";
export const section = 4;

/** Side of the source square [0, SIZE]²; its corners S₀ … S₃ go to Q₀ … Q₃. */
export const SIZE = 4;

/**
 * A polynomial S-shaped cubic (all weights 1) inside the square, and a trapezoid as the image:
 * by hand (Heckbert's formulas), H = [[3/2, 9/4, 6], [0, 2, 0], [0, 1/4, 1]], so
 * w′ = w·(1 + y/4) and the mapped weights are 9/8, 15/8, 9/8, 15/8.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0.5, 0.5],
      [1, 3.5],
      [3, 0.5],
      [3.5, 3.5],
    ].map(Object.freeze),
  ),
  weights: Object.freeze([1, 1, 1, 1]),
  corners: Object.freeze(
    [
      [6, 0],
      [12, 0],
      [10.5, 4],
      [7.5, 4],
    ].map(Object.freeze),
  ),
});

/** Number of control points (a cubic). */
const POINTS = 4;
/** Range of a weight (log sliders), slider step in log10 units. */
export const WEIGHT_MIN = 0.1;
export const WEIGHT_MAX = 10;
const WEIGHT_LOG_STEP = 0.01;
/** Samples per curve, and every how many samples the dotted check shows a dot. */
const SAMPLES = 256;
const DOT_EVERY = 8;
/** Grid lines per side of the square (and of its image). */
const GRID = 4;
/** Below this a mapped denominator counts as 0 (the square crosses the line at infinity). */
const DENOMINATOR_EPSILON = 1e-12;
/** Small distances are written in exponent form. */
const SMALL = 1e-3;
/** Height of the band at the top kept for the three-line key, CSS px at text scale 1. */
const LEGEND_PX = 70;
/** The source square's corners S₀ … S₃, flat, and their labels. */
const SQUARE = Object.freeze([0, 0, SIZE, 0, SIZE, SIZE, 0, SIZE]);
const SQUARE_LABELS = Object.freeze(["S₀", "S₁", "S₂", "S₃"]);
/** Handles: the control points P₀ … P₃, then the corners Q₀ … Q₃. */
const HANDLE_LABELS = Object.freeze(
  ["P", "Q"].flatMap((name) => [0, 1, 2, 3].map((i) => `${name}${subscript(i)}`)),
);

export const fields = {
  points: field.points({ min: POINTS, max: POINTS }),
  /** Four weights, each > 0 (the message says why) and in [WEIGHT_MIN, WEIGHT_MAX]. */
  weights(s, name) {
    checkNumbers(s, name, { min: POINTS, max: POINTS });
    s.weights.forEach((w, i) => {
      const wi = `w${subscript(i)}`;
      if (w <= 0) throw new Error(t("projective.notPositive", { name: wi, value: w }));
      if (w < WEIGHT_MIN || w > WEIGHT_MAX) {
        throw new Error(
          t("projective.weightRange", {
            name: wi,
            ...shownNumbers({ value: w, min: WEIGHT_MIN, max: WEIGHT_MAX }),
          }),
        );
      }
    });
  },
  /** Four corners that define a perspective map (no three on a line). */
  corners(s, name) {
    field.points({ min: 4, max: 4 })(s, name);
    if (!squareToQuad(s.corners, SIZE).every(Number.isFinite))
      throw new Error(t("projective.degenerate"));
  },
};

/**
 * The original curve, its image `projectiveMap(H)` and the contrast curve (the image's control
 * points with the old weights), all in wasm. A dragged point, corner or weight updates them in
 * place; a move the core refuses (a weight would reach ≤ 0) is undone and its message shown.
 */
export const derive = {
  from: ["points", "weights", "corners"],
  build(s, sl) {
    const matrix = squareToQuad(s.corners, SIZE);
    const curve = new sl.BezierCurve(flatten(s.points), 2, new Float64Array(s.weights));
    let mapped;
    try {
      mapped = curve.projectiveMap(matrix); // throws on a weight ≤ 0 (the shell keeps the old state)
    } catch (err) {
      curve.free();
      throw err;
    }
    const naive = new sl.BezierCurve(mapped.controlPoints(), 2, new Float64Array(s.weights));
    return { curve, mapped, naive, matrix, trial: new Float64Array(9), refusal: { shown: false } };
  },
  moved(m, i, xy, s, ui) {
    if (i < POINTS) {
      m.curve.setControlPoint(i, xy);
      if (remap(m, m.matrix, ui)) return true;
      m.curve.setControlPoint(i, new Float64Array(s.points[i])); // back where it was
      return false;
    }
    const j = i - POINTS;
    const trial = squareToQuad(
      s.corners.map((c, k) => (k === j ? xy : c)),
      SIZE,
      m.trial,
    );
    if (!trial.every(Number.isFinite)) {
      ui.status(t("projective.degenerate"), "error");
      m.refusal.shown = true;
      return false;
    }
    if (!remap(m, trial, ui)) return false;
    m.matrix.set(trial);
    return true;
  },
  weighted(m, i, w, s, ui) {
    m.curve.setWeight(i, w);
    m.naive.setWeight(i, w);
    remap(m, m.matrix, ui); // a positive factor per point: cannot fail, but ask the core
  },
};

/**
 * Asks the core for the image of the curve under `matrix` and copies it into the model's image
 * and contrast curves (in place); on refusal shows the core's message and returns false.
 */
function remap(m, matrix, ui) {
  let next;
  try {
    next = m.curve.projectiveMap(matrix);
  } catch (err) {
    ui.status(t("projective.refused", { message: errorText(err) }), "error");
    m.refusal.shown = true;
    return false;
  }
  const controls = next.controlPoints();
  const weights = next.weights();
  for (let i = 0; i < POINTS; i++) {
    const point = controls.subarray(2 * i, 2 * i + 2);
    m.mapped.setControlPoint(i, point);
    m.mapped.setWeight(i, weights[i]);
    m.naive.setControlPoint(i, point);
  }
  next.free();
  if (m.refusal.shown) {
    ui.status("", "info");
    m.refusal.shown = false;
  }
  return true;
}

/**
 * What is drawn and measured: (a) the core's image, (b) H applied to each sample of the
 * original, (c) the contrast curve; max |(a) − (b)| at equal t, and the largest distance of (c)
 * from the polyline (a) (parametrisation-free).
 */
export const compute = {
  source: [["points", "weights"], (s, d) => d.curve.sampleUniform(SAMPLES)],
  image: [["points", "weights", "corners"], (s, d) => d.mapped.sampleUniform(SAMPLES)],
  naiveSamples: [["points", "weights", "corners"], (s, d) => d.naive.sampleUniform(SAMPLES)],
  mappedControls: [["points", "weights", "corners"], (s, d) => d.mapped.controlPoints()],
  mappedWeights: [["points", "weights", "corners"], (s, d) => d.mapped.weights()],
  check: [["points", "weights", "corners"], (s, d) => invarianceCheck(d)],
  squareVisible: [["corners"], (s, d) => squareIsFinite(d.matrix)],
  mappedLabels: [
    ["points", "weights", "corners"],
    (s, d) =>
      Array.from(d.mappedWeights, (w, i) =>
        t("projective.mappedLabel", { i: subscript(i), w: mappedText(w) }),
      ),
  ],
};

/** The dotted check (b) and the two gaps of the readout. */
function invarianceCheck({ source, image, naiveSamples, matrix }) {
  const pointwise = new Float64Array(2 * SAMPLES);
  let ab = 0;
  for (let k = 0; k < SAMPLES; k++) {
    const p = applyHomography(
      matrix,
      source[2 * k],
      source[2 * k + 1],
      pointwise.subarray(2 * k, 2 * k + 2),
    );
    ab = Math.max(ab, Math.hypot(p[0] - image[2 * k], p[1] - image[2 * k + 1]));
  }
  let ac = 0;
  for (let k = 0; k < SAMPLES; k++) {
    ac = Math.max(ac, distanceToPolyline(naiveSamples[2 * k], naiveSamples[2 * k + 1], image));
  }
  return { pointwise, ab, ac };
}

/** True when the whole square maps with positive denominators (its image is a finite quadrilateral). */
function squareIsFinite(matrix) {
  for (let k = 0; k < 4; k++) {
    if (denominator(matrix, SQUARE[2 * k], SQUARE[2 * k + 1]) <= DENOMINATOR_EPSILON) return false;
  }
  return true;
}

/** The parallelogram spanned by Q₀, Q₁, Q₃ (an affine map: the contrast curve then coincides). */
function makeAffine(ui) {
  const [q0, q1, , q3] = ui.state.corners;
  const corners = [
    [q0[0], q0[1]],
    [q1[0], q1[1]],
    [q1[0] + q3[0] - q0[0], q1[1] + q3[1] - q0[1]],
    [q3[0], q3[1]],
  ];
  const shown = ui.data.refusal.shown;
  try {
    ui.replace({ ...ui.state, corners });
  } catch (err) {
    ui.status(t("projective.refused", { message: errorText(err) }), "error");
    return;
  }
  if (shown) ui.status("", "info");
}

export const controls = [
  group(
    "projective.resultLegend",
    readout(
      "gaps",
      (s, d) => t("projective.gaps", { ab: smallText(d.check.ab), ac: smallText(d.check.ac) }),
      {
        live: true,
        data: (s, d) => ({ gapAb: String(d.check.ab), gapAc: String(d.check.ac) }),
      },
    ),
    readout(
      "mapped-weights",
      (s, d) => t("projective.mappedWeights", { weights: listText(mappedList(d)) }),
      {
        data: (s, d) => ({ weights: Array.from(d.mappedWeights).join(",") }),
      },
    ),
    actions([
      {
        name: "affine",
        label: "projective.affine",
        title: "projective.affine.title",
        run: makeAffine,
      },
    ]),
  ),
  group(
    "projective.weightsLegend",
    weightSliders({ prefix: strings, min: WEIGHT_MIN, max: WEIGHT_MAX, step: WEIGHT_LOG_STEP }),
  ),
];

export const figure = {
  /** The square and the quadrilateral together (the curves lie inside or near them). */
  bounds: (s) => boundsOf([[0, 0], [SIZE, SIZE], ...s.corners, ...s.points]),
  insets: scaledInsets(LEGEND_PX, 0, 0, 0),
  handles: { field: ["points", "corners"], label: (i) => HANDLE_LABELS[i], polygon: false },
};

/** The key: (a) solid, (b) dots, (c) dashed. */
const KEY = Object.freeze([
  { label: "projective.legendMapped", style: (theme) => theme.curve },
  { label: "projective.legendPointwise", dots: (theme) => theme.levelPoint[0] },
  { label: "projective.legendNaive", style: (theme) => theme.compareCurve[1] },
]);
const mapScratch = new Float64Array(2);

/** The square and its image, the original curve, the image (a), (b), (c), the handles, the key. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const k = r.scale;
  drawSquares(r, v, d);
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  flatPath(r, v, d.source, 0, SAMPLES);
  r.paint(theme.curve);

  // The image: control polygon with the new weights, (c) dashed, (a) solid, (b) dots.
  const controls = d.mappedControls;
  flatPath(r, v, controls, 0, POINTS);
  r.paint(theme.polygon);
  flatPath(r, v, d.naiveSamples, 0, SAMPLES);
  r.paint(theme.compareCurve[1]);
  flatPath(r, v, d.image, 0, SAMPLES);
  r.paint(theme.curve);
  const dots = d.check.pointwise;
  for (let j = 0; j < SAMPLES; j += DOT_EVERY)
    r.point(v.sx(dots[2 * j]), v.sy(dots[2 * j + 1]), theme.levelPoint[0]);
  // Mapped control points, labelled with their new weights on the side away from the polygon's
  // middle; not on a phone (the key names the dashed curve, the panel lists the weights).
  const labelled = v.width >= NARROW_CANVAS_PX * k;
  let mx = 0;
  for (let i = 0; i < POINTS; i++) mx += controls[2 * i] / POINTS;
  for (let i = 0; i < POINTS; i++) {
    const x = v.sx(controls[2 * i]);
    const y = v.sy(controls[2 * i + 1]);
    r.point(x, y, theme.comparePoint[0]);
    const left = controls[2 * i] < mx;
    if (labelled) {
      r.text(
        d.mappedLabels[i],
        x + (left ? -8 : 8) * k,
        y,
        theme.labelSmall,
        left ? "right" : "left",
        "middle",
      );
    }
  }
  // The contrast curve's name at its middle sample.
  const mid = SAMPLES >> 1;
  const naive = d.naiveSamples;
  if (labelled) {
    const x = v.sx(naive[2 * mid]) + 10 * k;
    r.text(
      t("projective.naiveLabel"),
      x,
      v.sy(naive[2 * mid + 1]),
      theme.labelSmall,
      "left",
      "middle",
    );
  }

  d.handles.draw(r, v);
  drawCornerLegend(r, KEY);
}

/** The source square with its grid and labels, and (when H keeps it finite) its image. */
function drawSquares(r, v, d) {
  const theme = r.theme;
  r.beginPath();
  r.rect(v.sx(0), v.sy(SIZE), SIZE * v.scale, SIZE * v.scale);
  r.paint(theme.helperFill);
  r.beginPath();
  for (let k = 1; k < GRID; k++) {
    const c = (k * SIZE) / GRID;
    r.moveTo(v.sx(c), v.sy(0));
    r.lineTo(v.sx(c), v.sy(SIZE));
    r.moveTo(v.sx(0), v.sy(c));
    r.lineTo(v.sx(SIZE), v.sy(c));
  }
  r.paint(theme.helper);
  if (d.squareVisible) {
    const to = (move, x, y) => {
      applyHomography(d.matrix, x, y, mapScratch);
      if (move) r.moveTo(v.sx(mapScratch[0]), v.sy(mapScratch[1]));
      else r.lineTo(v.sx(mapScratch[0]), v.sy(mapScratch[1]));
    };
    r.beginPath();
    for (let k = 0; k <= 4; k++) to(k === 0, SQUARE[2 * (k % 4)], SQUARE[2 * (k % 4) + 1]);
    r.paint(theme.helperFill);
    r.beginPath();
    for (let k = 1; k < GRID; k++) {
      const c = (k * SIZE) / GRID;
      to(true, c, 0);
      to(false, c, SIZE);
      to(true, 0, c);
      to(false, SIZE, c);
    }
    r.paint(theme.helper);
  }
  const s = r.scale;
  for (let k = 0; k < 4; k++) {
    const x = SQUARE[2 * k];
    const y = SQUARE[2 * k + 1];
    const dx = (x > 0 ? 6 : -6) * s;
    const dy = (y > 0 ? -6 : 6) * s;
    const align = x > 0 ? "left" : "right";
    r.text(
      SQUARE_LABELS[k],
      v.sx(x) + dx,
      v.sy(y) + dy,
      theme.labelSmall,
      align,
      y > 0 ? "bottom" : "top",
    );
  }
}

/** H, the weight rule with one worked product (for P₀), the mapped weights, the two gaps. */
export function formula(s, d) {
  const m = d.matrix;
  const mw = mappedList(d, true);
  const tx = (key) => `\\text{${t(`projective.tex.${key}`)}}`;
  const row = (k) => `${fmtTex(m[3 * k])} & ${fmtTex(m[3 * k + 1])} & ${fmtTex(m[3 * k + 2])}`;
  const [x0, y0] = s.points[0];
  const w0 = weightText(s.weights[0], 3, true);
  const product0 = `${w0}\\,(${fmtTex(m[6])}\\cdot ${fmtTex(x0)} + ${fmtTex(m[7])}\\cdot ${fmtTex(y0)} + 1) = ${mw[0]}`;
  const matrix = `\\begin{pmatrix} ${row(0)} \\\\ ${row(1)} \\\\ ${row(2)} \\end{pmatrix}`;
  const lift = `(w_iP_i,\\ w_i) \\;\\mapsto\\; H\\,(w_ix_i,\\ w_iy_i,\\ w_i)^{\\mathsf T} = (w'_iP'_i,\\ w'_i)`;
  return [
    `H = ${matrix},\\qquad ${lift}`,
    `w'_i = w_i\\,(h_{31}x_i + h_{32}y_i + h_{33}):\\qquad w'_0 = ${product0}`,
    `(w'_0, \\dots, w'_{${POINTS - 1}}) = (${mw.join(texListSeparator())})\\quad` +
      `${tx("affine")} h_{31} = h_{32} = 0 ${tx("unchanged")}`,
    `\\max_t \\lVert (a) - (b) \\rVert = ${texNumber(d.check.ab)} \\quad${tx("invariant")},\\qquad ` +
      `\\max \\operatorname{dist}\\big((c), (a)\\big) = ${texNumber(d.check.ac)} \\quad${tx("ignored")}`,
  ];
}

/** The figure's name: the map, its corners, the mapped weights and the two gaps. */
export function label(s, d) {
  const m = d.matrix;
  const affine = Math.abs(m[6]) < DENOMINATOR_EPSILON && Math.abs(m[7]) < DENOMINATOR_EPSILON;
  return t("projective.aria", {
    corners: listText(s.corners.map(([x, y]) => pointText([x, y], 2))),
    kind: t(affine ? "projective.affineMap" : "projective.perspectiveMap"),
    weights: listText(mappedList(d)),
    ab: smallText(d.check.ab),
    ac: smallText(d.check.ac),
  });
}

/** A mapped weight: three decimals, no trailing zeros (9/8 reads 1.125); TeX with `tex`. */
function mappedText(w, tex = false) {
  const s = String(Number(w.toFixed(3)));
  return tex ? texDecimal(s) : localeDecimal(s);
}

/** The mapped weights as the panels show them (TeX with `tex`). */
function mappedList(d, tex = false) {
  return Array.from(d.mappedWeights, (w) => mappedText(w, tex));
}

/** A measured distance: 0, exponent form when small, else 3 decimals. */
function smallText(x) {
  return x === 0 ? "0" : x < SMALL ? localeDecimal(x.toExponential(1)) : fmt(x);
}

/** TeX of a measured distance: 0, m × 10^e, or 3 decimals. */
function texNumber(x) {
  if (x === 0) return "0";
  if (x >= SMALL) return fmtTex(x);
  const [mantissa, e] = x.toExponential(1).split("e");
  return `${texDecimal(mantissa)} \\times 10^{${Number(e)}}`;
}
