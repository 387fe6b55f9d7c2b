/**
 * Demo (syllabus §5): automatic tangents for a piecewise cubic Hermite curve through data points.
 * Two ways, one at a time:
 *
 *   cardinal (tension c), t_i = i:  m_i = (1 − c)(P_{i+1} − P_{i−1}) / (t_{i+1} − t_{i−1})
 *   Catmull–Rom (α), t_{i+1} − t_i = d_i = |P_{i+1} − P_i|^α (0 uniform, ½ centripetal, 1 chord):
 *     m_i = (P_i − P_{i−1})/d_{i−1} − (P_{i+1} − P_{i−1})/(d_{i−1} + d_i) + (P_{i+1} − P_i)/d_i
 *
 * (`sl.cardinalSpline`, `sl.catmullRom`). The tangents drawn are the core's `tangents()`, as
 * the Bézier handle P_i → P_i + Δ·m_i/3. The default points are unevenly spaced: uniform
 * Catmull–Rom (α = 0) makes a loop in the short segment, centripetal does not; with α ≠ 0 the
 * α = 0 curve is drawn dashed and a loop inside one of its segments is marked (found on the
 * core's samples, lib/polyline-loops.js). The formula panel writes the current segment in the
 * Croatian notes' matrix form P(t) = [t³ t² t 1] M [P_{i−1} P_i P_{i+1} P_{i+2}]ᵀ.
 */
import { field } from "../lib/validate.js";
import {
  slider,
  checkbox,
  choice,
  pointButtons,
  readout,
  group,
  shownWhen,
  INTEGER_SLIDER,
} from "../lib/panel.js";
import { el, setText } from "../lib/controls.js";
import {
  fmt,
  subscript,
  shortNumber,
  fractionOrDecimals,
  DECIMALS,
  fmtTex,
  pointTex,
  pointText,
} from "../lib/format.js";
import { HUES, themed } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { titledTable, headerRow } from "../lib/table.js";
import { flatPath, arrow } from "../lib/draw.js";
import { drawCornerLegend } from "../lib/legend.js";
import { scaledInsets } from "../lib/view.js";
import { stretchCrossing } from "../lib/polyline-loops.js";

export const id = "cardinal";
export const strings = "cardinal";
export const section = 5;

export const MODES = Object.freeze(["cardinal", "catmull-rom"]);
export const MIN_POINTS = 3;
export const MAX_POINTS = 10;
/** Samples per segment (the loop search looks at one segment's samples). */
const SEGMENT_SAMPLES = 64;
/** Slider resolution for c and α. */
const STEP = 0.01;

/**
 * Uneven spacing: the short leg P₁P₂ between two long ones. Uniform Catmull–Rom's tangents
 * m₁ = (P₂ − P₀)/2 = (7/2, 4) and m₂ = (P₃ − P₁)/2 = (7/2, −4) are long against the chord
 * (1, 0): the Bézier points q₁ = P₁ + m₁/3 = (43/6, 28/3) and q₂ = P₂ − m₂/3 = (35/6, 28/3)
 * cross, and segment 1 loops. Centripetal (the default α = ½) does not.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [6, 8],
      [7, 8],
      [13, 0],
    ].map(Object.freeze),
  ),
  mode: "catmull-rom",
  tension: 0,
  alpha: 0.5,
  closed: false,
  segment: 1,
});

/** Segments: n for an open curve, n + 1 for a closed one (the last back to P₀). */
const segmentCount = (s) => s.points.length - 1 + (s.mode === "catmull-rom" && s.closed ? 1 : 0);
const isRom = (s) => s.mode === "catmull-rom";

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  mode: field.choice(MODES),
  tension: field.number({ min: -1, max: 1 }),
  alpha: field.number({ min: 0, max: 1 }),
  closed: field.boolean(),
  segment: field.number((s) => ({ min: 0, max: segmentCount(s) - 1, integer: true })),
};

/** The segment stays in range after a point is removed or the curve is opened. */
export function adjust(s) {
  s.segment = Math.min(s.segment, segmentCount(s) - 1);
}

/** The curve the state asks for; Catmull–Rom with α ≠ 0 also the uniform one (the dashed ghost). */
export const derive = {
  from: ["points", "mode", "tension", "alpha", "closed"],
  build(s, sl) {
    const flat = flatten(s.points);
    if (!isRom(s)) {
      const params = sl.parameterize(flat, 2, "uniform");
      return { spline: sl.cardinalSpline(flat, 2, params, s.tension), ghost: null };
    }
    const spline = sl.catmullRom(flat, 2, s.alpha, s.closed);
    try {
      return { spline, ghost: s.alpha === 0 ? null : sl.catmullRom(flat, 2, 0, s.closed) };
    } catch (err) {
      spline.free();
      throw err;
    }
  },
  moved(m, i, xy) {
    m.spline.setPoint(i, xy);
    m.ghost?.setPoint(i, xy);
  },
};

/**
 * One `sampleUniform` with SEGMENT_SAMPLES per segment, uniform in t: on a curve with t_i = i
 * (the uniform one) segment j holds about samples j·S … (j + 1)·S − 1.
 */
const samplesOf = (spline) =>
  spline ? spline.sampleUniform(SEGMENT_SAMPLES * spline.pieceCount) : null;

/** The first loop inside one segment of the uniform curve's samples (`samplesOf`), with its crossing, or null. */
function loopOf(flat, count) {
  if (!flat) return null;
  const out = [0, 0];
  for (let j = 0; j < count; j++) {
    if (stretchCrossing(flat, j * SEGMENT_SAMPLES, (j + 1) * SEGMENT_SAMPLES, out))
      return { segment: j, x: out[0], y: out[1] };
  }
  return null;
}

/** The current segment: its parameter interval, samples, the middle point of the uniform curve. */
function segmentOf(s, d) {
  const params = d.spline.params();
  const i = s.segment;
  const t0 = params[i];
  const t1 = params[i + 1];
  const ts = new Float64Array(SEGMENT_SAMPLES);
  for (let k = 0; k < SEGMENT_SAMPLES; k++) ts[k] = t0 + ((t1 - t0) * k) / (SEGMENT_SAMPLES - 1);
  const uniform = d.ghost ?? d.spline;
  const u = uniform.params();
  return {
    i,
    t0,
    t1,
    samples: d.spline.sample(ts),
    middle: uniform.evaluate((u[i] + u[i + 1]) / 2),
  };
}

const SHAPE = ["points", "mode", "tension", "alpha", "closed"];
export const compute = {
  samples: [SHAPE, (s, d) => samplesOf(d.spline)],
  ghostSamples: [SHAPE, (s, d) => samplesOf(d.ghost)],
  tangents: [SHAPE, (s, d) => d.spline.tangents()],
  params: [SHAPE, (s, d) => d.spline.params()],
  loop: [
    SHAPE,
    (s, d) => loopOf(d.ghost ? d.ghostSamples : isUniform(s) ? d.samples : null, segmentCount(s)),
  ],
  segment: [[...SHAPE, "segment"], segmentOf],
};

/** Whether the drawn curve is itself the notes' uniform one (cardinal with t_i = i, or α = 0). */
const isUniform = (s) => !isRom(s) || s.alpha === 0;

export const controls = [
  group(
    "cardinal.control.modeLegend",
    choice("mode", { options: MODES.map((value) => ({ value, label: `cardinal.mode.${value}` })) }),
    shownWhen(
      (s) => !isRom(s),
      slider("tension", { label: "cardinal.control.tension", min: -1, max: 1, step: STEP }),
    ),
    shownWhen(
      (s) => isRom(s),
      slider("alpha", { label: "cardinal.control.alpha", min: 0, max: 1, step: STEP }),
    ),
    shownWhen((s) => isRom(s), checkbox("closed", { label: "cardinal.control.closed" })),
  ),
  group(
    null,
    slider("segment", {
      label: "cardinal.control.segment",
      range: (s) => [0, segmentCount(s) - 1],
      ...INTEGER_SLIDER,
    }),
    readout("loop", (s, d) => loopNote(s, d), {
      live: true,
      data: (s, d) => ({ loop: d.loop ? String(d.loop.segment) : "none" }),
    }),
  ),
  group(
    null,
    readout("count", (s) => t("cardinal.count", { count: s.points.length })),
    pointButtons("points", { min: MIN_POINTS, max: MAX_POINTS, prefix: strings }),
  ),
];

/** "The uniform curve (α = 0) loops in segment 2" / "no loop". */
function loopNote(s, d) {
  if (d.loop)
    return t(isUniform(s) ? "cardinal.loopHere" : "cardinal.loopGhost", { i: d.loop.segment });
  return t(isUniform(s) ? "cardinal.noLoopHere" : "cardinal.noLoopGhost");
}

/** The band at the top kept free for the key (two rows), CSS px at text scale 1. */
const LEGEND_PX = 52;
const legendInsets = scaledInsets(LEGEND_PX, 0, 0, 0);

export const figure = {
  bounds: (s) => paddedBounds(s.points, 0.1, 0.15),
  insets: legendInsets,
  handles: { field: "points" },
};

// ------------------------------------------------------------ drawing

const TANGENT_STYLE = Object.freeze({ stroke: HUES.orange, width: 2, cap: "round" });
const LOOP_STYLE = Object.freeze({ stroke: HUES.vermillion, width: 2.5 });
const SEGMENT_STYLE = Object.freeze({
  stroke: HUES.blue,
  width: 10,
  strokeAlpha: 0.2,
  cap: "round",
});
const LOOP_RADIUS_PX = 12;
/** The key: this curve, and the uniform one when it is drawn too. */
const legendEntries = themed((theme) => {
  const both = [
    { label: "cardinal.legend.curve", style: theme.compareCurve[0] },
    { label: "cardinal.legend.ghost", style: theme.compareCurve[1] },
  ];
  return { both, one: both.slice(0, 1) };
});

export function draw(r, v, s, d) {
  const theme = r.theme;
  flatPath(r, v, d.segment.samples);
  r.paint(SEGMENT_STYLE);
  if (d.ghostSamples) {
    flatPath(r, v, d.ghostSamples);
    r.paint(theme.compareCurve[1]);
  }
  flatPath(r, v, d.samples);
  r.paint(theme.compareCurve[0]);
  drawTangents(r, v, s, d);
  if (d.loop) {
    const x = v.sx(d.loop.x);
    const y = v.sy(d.loop.y);
    r.beginPath();
    r.circle(x, y, LOOP_RADIUS_PX * r.scale);
    r.paint(LOOP_STYLE);
    r.text(
      t("cardinal.loopLabel"),
      x,
      y - (LOOP_RADIUS_PX + 4) * r.scale,
      theme.labelBold,
      "center",
      "bottom",
    );
  }
  d.handles.draw(r, v);
  const key = legendEntries(theme);
  drawCornerLegend(r, d.ghostSamples ? key.both : key.one);
}

/**
 * The core's tangents as Bézier handles P_i → P_i + Δ·m_i/3 (Δ of the segment leaving P_i, the
 * last segment's at the end).
 */
function drawTangents(r, v, s, d) {
  const m = d.tangents;
  const params = d.params;
  const last = params.length - 1;
  for (let i = 0; i < s.points.length; i++) {
    const j = Math.min(i, last - 1);
    const k = (params[j + 1] - params[j]) / 3;
    const p = s.points[i];
    arrow(
      r,
      v.sx(p[0]),
      v.sy(p[1]),
      v.sx(p[0] + k * m[2 * i]),
      v.sy(p[1] + k * m[2 * i + 1]),
      TANGENT_STYLE,
    );
  }
}

// ------------------------------------------------------------ formula, label, table

/** The notes' matrix for cardinal tangents with s = (1 − c)/2 (c = 0: ½[[−1, 3, −3, 1], …], Catmull–Rom). */
function cardinalMatrix(c) {
  const k = (1 - c) / 2;
  return [
    [-k, 2 - k, k - 2, k],
    [2 * k, k - 3, 3 - 2 * k, -k],
    [-k, 0, k, 0],
    [0, 1, 0, 0],
  ];
}

/** P_j's name and numbers for the matrix: a phantom (open Catmull–Rom ends) or a wrapped index (closed). */
function neighbour(s, j) {
  const n = s.points.length - 1;
  const pair = (p) => pointTex([shortNumber(p[0], true), shortNumber(p[1], true)], DECIMALS, "\\,");
  if (j >= 0 && j <= n) return `P_{${j}} = ${pair(s.points[j])}`;
  if (isRom(s) && s.closed) {
    const w = (j + n + 1) % (n + 1);
    return `P_{${j}} = P_{${w}} = ${pair(s.points[w])}`;
  }
  const [a, b] = j < 0 ? [0, 1] : [n, n - 1];
  const p = s.points[a].map((x, k) => 2 * x - s.points[b][k]);
  return `P_{${j}} = 2P_{${a}} - P_{${b}} = ${pair(p)}`;
}

export function formula(s, d) {
  const i = s.segment;
  const c = isRom(s) ? 0 : s.tension;
  const half = c === 0;
  const M = cardinalMatrix(c).map((row) => row.map((x) => (half ? 2 * x : x)));
  const rows = M.map((row) => row.map((x) => fractionOrDecimals(x, true)).join(" & ")).join(
    " \\\\ ",
  );
  const names = [-1, 0, 1, 2].map((k) => neighbour(s, i + k)).join(" \\\\ ");
  const factor = half ? "\\tfrac{1}{2}" : "";
  const which = isRom(s) && s.alpha !== 0 ? `\\text{${t("cardinal.formula.ghost")}}` : "";
  const m = d.tangents;
  const mid = d.segment.middle;
  const tangents =
    `m_{${i}} = ${pointTex([m[2 * i], m[2 * i + 1]], DECIMALS, "\\,")},\\ ` +
    `m_{${i + 1}} = ${pointTex([m[2 * i + 2], m[2 * i + 3]], DECIMALS, "\\,")}`;
  const lines = [
    isRom(s)
      ? "m_i = \\frac{P_i - P_{i-1}}{d_{i-1}} - \\frac{P_{i+1} - P_{i-1}}{d_{i-1} + d_i} + " +
        "\\frac{P_{i+1} - P_i}{d_i}"
      : "m_i = (1 - c)\\,\\frac{P_{i+1} - P_{i-1}}{t_{i+1} - t_{i-1}}",
    isRom(s)
      ? `d_i = |P_{i+1} - P_i|^{\\alpha},\\ \\alpha = ${fmtTex(s.alpha)}:\\quad ${tangents}`
      : `t_i = i,\\ c = ${fmtTex(s.tension)}:\\quad ${tangents}`,
    `P(t) = \\begin{bmatrix} t^3 & t^2 & t & 1 \\end{bmatrix} ${factor}\\begin{bmatrix} ${rows} \\end{bmatrix}` +
      `\\begin{bmatrix} ${names} \\end{bmatrix}`,
    `P(\\tfrac{1}{2}) = ${pointTex([fractionOrDecimals(mid[0], true), fractionOrDecimals(mid[1], true)])}\\quad ${which}`,
  ];
  return lines;
}

export function label(s, d) {
  return t("cardinal.aria", {
    mode: t(`cardinal.mode.${s.mode}`),
    value: isRom(s) ? `α = ${fmt(s.alpha)}` : `c = ${fmt(s.tension)}`,
    count: s.points.length,
    loop: loopNote(s, d),
  });
}

/** The table: every data point's parameter t_i and the core's tangent m_i. */
export function setup(ui) {
  const head = headerRow("cardinal.col.", ["point", "param", "tangent"]);
  const body = el("tbody", {});
  const { title, wrap } = titledTable("tangents", {
    caption: t("cardinal.tableCaption"),
    children: [el("thead", {}, head), body],
  });
  ui.ctx.slots.details.append(title, wrap);
  let rows = [];
  return {
    update(s, d) {
      const n = s.points.length;
      if (rows.length !== n) {
        rows = Array.from({ length: n }, (_, i) => ({
          row: el("tr", { dataset: { index: String(i) } }),
          name: el("th", { scope: "row", text: `P${subscript(i)}` }),
          param: el("td", { dataset: { cell: "param" } }),
          tangent: el("td", { dataset: { cell: "tangent" } }),
        }));
        rows.forEach((r) => r.row.append(r.name, r.param, r.tangent));
        body.replaceChildren(...rows.map((r) => r.row));
      }
      const m = d.tangents;
      rows.forEach((r, i) => {
        setText(r.param, fractionOrDecimals(d.params[i]));
        setText(
          r.tangent,
          pointText([fractionOrDecimals(m[2 * i]), fractionOrDecimals(m[2 * i + 1])]),
        );
      });
    },
  };
}
