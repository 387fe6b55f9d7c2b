/**
 * Demo 4 (syllabus §2): adaptive flattening. A cubic is drawn as the polyline that the core's
 * `flatten(ε)` returns, with its vertices, the segment count, and the count for ε/2 (one more
 * `flatten` call) to show that halving the tolerance multiplies the segments by about √2. The
 * optional tolerance band is the polyline stroked 2ε wide: the curve never leaves it.
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, readout, actions, group } from "../lib/panel.js";
import { fmt, fmtTex, listText, localeDecimal, pointText, texDecimal } from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { scaledInsets } from "../lib/view.js";
import { errorText } from "../lib/core-errors.js";

export const id = "flattening";
export const strings = "flattening";
export const section = 2;

/** Smallest and largest tolerance ε (world units); the slider is logarithmic between them. */
export const MIN_TOLERANCE = 0.001;
export const MAX_TOLERANCE = 1;

/**
 * Integer shapes that show the adaptivity well: the S-curve (the default) bends at both ends
 * and is almost straight in the middle, the loop and the cusp concentrate curvature in one
 * place (the cusp, a symmetric polygon whose legs P₀P₁ and P₂P₃ mirror each other with
 * |P₁P₂| = the legs' width, has P′(1/2) = 0), and the nearly straight curve needs almost no
 * segments.
 */
export const PRESETS = Object.freeze({
  s: Object.freeze(
    [
      [0, 0],
      [2, 6],
      [6, -2],
      [8, 4],
    ].map(Object.freeze),
  ),
  loop: Object.freeze(
    [
      [1, 0],
      [10, 6],
      [-2, 6],
      [7, 0],
    ].map(Object.freeze),
  ),
  cusp: Object.freeze(
    [
      [1, 0],
      [7, 6],
      [1, 6],
      [7, 0],
    ].map(Object.freeze),
  ),
  straight: Object.freeze(
    [
      [0, 0],
      [3, 1],
      [5, 1],
      [8, 2],
    ].map(Object.freeze),
  ),
});

/**
 * ε = 0.1 rather than a smaller value: at the default zoom the band is then about 10 px wide, so
 * the curve is seen inside it; 7 segments, 9 at ε/2.
 */
export const defaultState = Object.freeze({
  points: PRESETS.s,
  tolerance: 0.1,
  band: true,
});

/** A cubic: four control points. */
const POINT_COUNT = 4;
/** Points sampled along the curve for drawing. */
const CURVE_SAMPLES = 256;
/** Slider resolution in log10 units (about 230 positions from 0.001 to 1). */
const LOG_STEP = 0.01;
/** Slider values are rounded to this many significant digits (0.05, 0.063, …): short links. */
const SLIDER_DIGITS = 2;
/** Typed values are shown with up to this many significant digits. */
const SHOWN_DIGITS = 3;
/** Opacity of the tolerance band (helper grey, translucent so the curve shows through). */
const BAND_ALPHA = 0.6;
/** Position of the segment count drawn in the figure's corner, CSS px from the top left. */
const COUNT_LABEL_INSET = 12;
/** Height of the band kept free for the count above the world window, CSS px at scale 1. */
const COUNT_BAND_PX = 34;

export const fields = {
  points: field.points({ min: POINT_COUNT, max: POINT_COUNT }),
  tolerance: field.number({ min: MIN_TOLERANCE, max: MAX_TOLERANCE }),
  band: field.boolean(),
};

/**
 * A tolerance as typed or shown: "0.05", "0.0015" (no trailing zeros, no float noise; "0,05"
 * with a decimal comma); TeX with `tex`.
 */
function formatTolerance(value, tex = false) {
  const s = String(Number(value.toPrecision(SHOWN_DIGITS)));
  return tex ? texDecimal(s) : localeDecimal(s);
}

/** Segments of a flat 2D polyline (vertices − 1). */
function segmentCount(polyline) {
  return Math.max(0, polyline.length / 2 - 1);
}

/** The polylines for ε and ε/2; throws only for a far too small ε on a huge curve. */
function flattenBoth(curve, tolerance) {
  return {
    polyline: curve.flatten(tolerance),
    halfCount: segmentCount(curve.flatten(tolerance / 2)),
  };
}

/** The curve, and its polylines for the state's ε (so a refused ε refuses the state). */
export const derive = {
  from: ["points"],
  build(s, sl) {
    const curve = new sl.BezierCurve(flatten(s.points), 2);
    try {
      flattenBoth(curve, s.tolerance);
    } catch (err) {
      curve.free();
      throw err;
    }
    return { curve };
  },
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/** An empty polyline: what is shown before the first one (never, unless ε is refused at once). */
const NOTHING = Object.freeze({ polyline: new Float64Array(0), halfCount: 0 });

export const compute = {
  samples: [["points"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  flattened: [
    ["points", "tolerance"],
    (s, d, ui) => {
      try {
        return flattenBoth(d.curve, s.tolerance);
      } catch (err) {
        // Only a far too small ε for a huge curve: keep the last polyline, say why.
        ui.status(t("flattening.flattenFailed", { message: errorText(err) }), "error");
        return d.flattened ?? NOTHING;
      }
    },
  ],
  countLabel: [
    ["points", "tolerance"],
    (s, d) =>
      t("flattening.countLabel", {
        count: segmentCount(d.flattened.polyline),
        tolerance: formatTolerance(s.tolerance),
      }),
  ],
};

/** Moves the four points to a preset shape. */
const preset = (key) => ({
  name: `preset-${key}`,
  label: `flattening.preset.${key}`,
  title: "flattening.preset.title",
  run: (ui) => ui.set("points", structuredClone(PRESETS[key])),
});

export const controls = [
  group(
    null,
    readout("segments", (s, d) => tp("flattening.segments", segmentCount(d.flattened.polyline)), {
      kind: "readout",
    }),
    readout("half", (s, d) => {
      const count = segmentCount(d.flattened.polyline);
      const ratio = count > 0 ? fmt(d.flattened.halfCount / count, 2) : "?";
      return t("flattening.half", {
        tolerance: formatTolerance(s.tolerance / 2),
        count: d.flattened.halfCount,
        ratio,
      });
    }),
  ),
  group(
    null,
    slider("tolerance", {
      label: "flattening.tolerance",
      inputParams: { min: MIN_TOLERANCE, max: MAX_TOLERANCE },
      min: MIN_TOLERANCE,
      max: MAX_TOLERANCE,
      step: LOG_STEP,
      log: true,
      format: (v) => formatTolerance(v),
      // The range moves in powers of ten: keep two significant digits; typed values as typed.
      round: (v, typed) =>
        typed
          ? v
          : Math.min(MAX_TOLERANCE, Math.max(MIN_TOLERANCE, Number(v.toPrecision(SLIDER_DIGITS)))),
      error: "flattening.badTolerance",
    }),
    checkbox("band", { label: "flattening.band" }),
  ),
  actions(["s", "loop", "cusp", "straight"].map(preset), { title: "flattening.presets" }),
];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  insets: scaledInsets(COUNT_BAND_PX, 0, 0, 0),
  handles: { field: "points" },
};

/** The band's style: helper grey, width 2ε in world units (set per draw, made once). */
const bandStyle = { stroke: "", strokeAlpha: BAND_ALPHA, width: 1, join: "round", cap: "round" };

/** The band, the polygon, the curve, the polyline with its vertices, the handles, the count. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const { polyline } = d.flattened;
  const vertices = polyline.length / 2;
  // The polyline stroked 2ε wide: round joins and caps make it exactly the points within ε.
  if (s.band) {
    bandStyle.stroke = theme.helper.stroke;
    bandStyle.width = (2 * s.tolerance * v.scale) / r.scale; // the renderer multiplies by r.scale
    flatPath(r, v, polyline, 0, vertices);
    r.paint(bandStyle);
  }
  pointsPath(r, v, s.points, 0, POINT_COUNT);
  r.paint(theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  flatPath(r, v, polyline, 0, vertices);
  r.paint(theme.levelStroke[0]);
  for (let k = 0; k < vertices; k++)
    r.point(v.sx(polyline[2 * k]), v.sy(polyline[2 * k + 1]), theme.levelPoint[0]);
  d.handles.draw(r, v);
  // The count in the corner, so projections and exports carry it too.
  r.text(
    d.countLabel,
    COUNT_LABEL_INSET * r.scale,
    COUNT_LABEL_INSET * r.scale,
    theme.label,
    "left",
    "top",
  );
}

/**
 * The flatness test of the whole curve (the core's first test): distances of the inner control
 * points to the chord P₀P₃, d_i = |(P₃ − P₀) × (P₃ − P_i)| / |P₃ − P₀|, a formula on the four
 * numbers shown beside the segment counts.
 */
export function formula(s, d) {
  const [x0, y0] = s.points[0];
  const [x3, y3] = s.points[3];
  const cx = x3 - x0;
  const cy = y3 - y0;
  const chord = Math.hypot(cx, cy);
  const distance = ([x, y]) =>
    chord > 0 ? Math.abs(cx * (y3 - y) - cy * (x3 - x)) / chord : Math.hypot(x - x0, y - y0);
  const d1 = distance(s.points[1]);
  const d2 = distance(s.points[2]);
  const flat = Math.max(d1, d2) <= s.tolerance;
  const eps = formatTolerance(s.tolerance, true);
  const halfEps = formatTolerance(s.tolerance / 2, true);
  const count = segmentCount(d.flattened.polyline);
  const half = d.flattened.halfCount;
  const ratio = count > 0 ? fmtTex(half / count, 2) : "?";
  const segments = t("flattening.formula.segments");
  const verdict = flat ? "flattening.formula.flat" : "flattening.formula.split";
  return [
    `d_i = \\frac{\\lvert (P_3 - P_0) \\times (P_3 - P_i) \\rvert}{\\lvert P_3 - P_0 \\rvert} ` +
      `\\le \\varepsilon, \\quad i = 1, 2, \\qquad \\varepsilon = ${eps}`,
    `\\text{${t("flattening.formula.whole")}}\\ d_1 = ${fmtTex(d1)},\\ d_2 = ${fmtTex(d2)}\\ ` +
      `${flat ? "\\le" : ">"}\\ \\varepsilon \\;\\Rightarrow\\; \\text{${t(verdict)}}`,
    `\\text{${t("flattening.formula.until")}}`,
    `\\varepsilon = ${eps}:\\ \\mathbf{${count}}\\ \\text{${segments}};\\qquad ` +
      `\\tfrac{\\varepsilon}{2} = ${halfEps}:\\ \\mathbf{${half}}\\ \\text{${segments}} ` +
      `\\quad (\\times ${ratio} \\approx \\sqrt{2})`,
  ];
}

/** A coordinate for labels: integers as they are, others with 2 decimals. */
const coord = (x) => (Number.isInteger(x) ? String(x) : fmt(x, 2));

/** The figure's accessible name: the points, ε, and both segment counts. */
export function label(s, d) {
  const count = segmentCount(d.flattened.polyline);
  const eps = formatTolerance(s.tolerance);
  return t("flattening.aria", {
    tolerance: eps,
    count,
    vertices: count + 1,
    half: formatTolerance(s.tolerance / 2),
    halfCount: d.flattened.halfCount,
    points: listText(s.points.map(([x, y]) => pointText([coord(x), coord(y)]))),
  });
}
