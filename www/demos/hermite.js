/**
 * Demo (syllabus §5): piecewise cubic Hermite interpolation. Data points P_i at t_i = i, a
 * tangent m_i at each (dragged by the tip of its arrow P_i → P_i + s·m_i, s = TANGENT_SCALE);
 * on [t_i, t_{i+1}] with Δ = t_{i+1} − t_i and u = (t − t_i)/Δ,
 *
 *   P(t) = H0(u) P_i + H1(u) P_{i+1} + H2(u) Δm_i + H3(u) Δm_{i+1},
 *   H0 = 2u³ − 3u² + 1,  H1 = −2u³ + 3u²,  H2 = u³ − 2u² + u,  H3 = u³ − u²,
 *
 * whose Bézier form is q0 = P_i, q1 = P_i + Δm_i/3, q2 = P_{i+1} − Δm_{i+1}/3, q3 = P_{i+1}.
 * Sharing m_i makes the curve C¹; "unlocking" an interior point gives it an incoming tangent
 * λ·m_k (parallel, another length): two `hermiteSpline`s meet there G¹ only. The verdict per
 * joint is the core's (`CompositeBezier.continuity()` of the pieces' `toBezier()`), the basis
 * the core's `hermiteBasis(u)`, the curve the core's samples.
 */
import { field, checkNumber } from "../lib/validate.js";
import {
  slider,
  checkbox,
  pointButtons,
  readout,
  group,
  shownWhen,
  INTEGER_SLIDER,
} from "../lib/panel.js";
import { pointLabel, placeLabelAtTip, placeLabelBeside } from "../lib/handles.js";
import { vectorTips, selectedVectorBox } from "../lib/vector-tips.js";
import { NARROW_CANVAS_PX } from "../lib/view.js";
import { el, setText } from "../lib/controls.js";
import {
  fmt,
  subscript,
  exactNumbers,
  shortNumber,
  fractionOrDecimals,
  DECIMALS,
  fmtTex,
  pointTex,
  listTex,
} from "../lib/format.js";
import { HUES, WIDTH, POLYGON_DASH } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { paddedBounds } from "../lib/geometry.js";
import { titledTable, headerRow, valueSpans, setValueSpans } from "../lib/table.js";
import { basisGraphs, hermitePlot, drawHermitePlot, HERMITE_NAMES } from "../lib/hermite-basis.js";
import { flatPath, arrow } from "../lib/draw.js";
import {
  hermiteParts,
  partOf,
  pieceBezier,
  jointVerdicts,
  verdictText,
  movePoint,
  applyTangents,
} from "../lib/hermite-parts.js";

export const id = "hermite";
export const strings = "hermite";
export const section = 5;

/** A tangent m_i is drawn as the arrow P_i → P_i + TANGENT_SCALE · m_i (its tip is dragged). */
export const TANGENT_SCALE = 0.5;
/** Fewest and most data points. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 8;
/** Range of λ = |m_k⁻| / |m_k⁺| at an unlocked point. */
export const RATIO_MIN = 0.2;
export const RATIO_MAX = 4;
/** Samples per piece of the curve. */
const PIECE_SAMPLES = 64;
/** Slider resolution for t and λ. */
const T_STEP = 0.001;
const RATIO_STEP = 0.01;
/** Room around the points (fractions of the box) for the arrows and labels. */
const ROOM = 0.12;

/**
 * Four points at t = 0, 1, 2, 3 with integer tangents (the first piece leaves P₀ upwards and
 * meets P₁ level: an arc); t = 1/2 is the middle of the first piece, P(1/2) = (1, 11/4).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [3, 4],
      [7, 3],
      [10, 0],
    ].map(Object.freeze),
  ),
  tangents: Object.freeze(
    [
      [0, 6],
      [4, 0],
      [3, -3],
      [3, -3],
    ].map(Object.freeze),
  ),
  t: 0.5,
  bezier: false,
  unlocked: false,
  joint: 1,
  ratio: 2,
});

const lastIndex = (s) => s.points.length - 1;

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  tangents(s, name) {
    const n = s.points.length;
    field.points({ min: n, max: n })(s, name);
  },
  t: field.number((s) => ({ min: 0, max: lastIndex(s) })),
  bezier: field.boolean(),
  unlocked: field.boolean(),
  joint(s, name) {
    checkNumber(s, name, { min: 1, max: Math.max(1, lastIndex(s) - 1), integer: true });
  },
  ratio: field.number({ min: RATIO_MIN, max: RATIO_MAX }),
};

/** After a point is added or removed: t in the domain, the joint interior, no point unlockable with 2 points. */
export function adjust(s) {
  const n = lastIndex(s);
  if (s.t > n) s.t = n;
  if (s.joint > n - 1) s.joint = Math.max(1, n - 1);
  if (n < 2 && s.unlocked) s.unlocked = false;
}

/**
 * The model: the spline(s) (one, or two meeting at the unlocked point: lib/hermite-parts.js).
 * Drags go into them in place: a point through `movePoint` (`setPoint`), a tangent tip (`tips`,
 * lib/vector-tips.js) or a typed tangent through `applyTangents` (`setTangent`).
 */
export const derive = {
  from: ["points", "tangents", "unlocked", "joint", "ratio"],
  build(s, sl) {
    return hermiteParts(sl, s);
  },
  moved: (m, i, xy) => movePoint(m, i, xy),
  inPlace: {
    tangents: (m, s) => applyTangents(m, s),
    ratio: (m, s) => applyTangents(m, s),
  },
};

/**
 * At t: the piece i, u, Δ and the piece's data (lib/hermite-parts.js `partOf`), the basis values
 * H0(u) … H3(u), P(t), and the piece's samples (its band in the figure).
 */
function atT(s, d) {
  const at = partOf(d, s, s.t);
  const t0 = d.params[at.piece];
  const ts = new Float64Array(PIECE_SAMPLES);
  for (let k = 0; k < PIECE_SAMPLES; k++) ts[k] = t0 + (at.delta * k) / (PIECE_SAMPLES - 1);
  return {
    ...at,
    basis: d.sl.hermiteBasis(at.u),
    point: at.spline.evaluate(s.t),
    pieceSamples: at.spline.sample(ts),
  };
}

const SHAPE = ["points", "tangents", "unlocked", "joint", "ratio"];
export const compute = {
  /** The basis graphs (they do not depend on the state: asked of the core once). */
  graphs: [[], (s, d) => basisGraphs(d.sl)],
  samples: [
    SHAPE,
    (s, d) => d.splines.map((sp) => sp.sampleUniform(PIECE_SAMPLES * sp.pieceCount)),
  ],
  at: [[...SHAPE, "t"], atT],
  marker: [[...SHAPE, "t"], (s, d) => t("hermite.marker", { u: fmt(d.at.u) })],
  bezierPoints: [
    [...SHAPE, "t", "bezier"],
    (s, d) => (s.bezier ? pieceBezier(d, d.at.piece) : null),
  ],
  joints: [SHAPE, (s, d) => jointVerdicts(d.sl, d)],
  /** The core's verdict at the unlocked point, written beside it in the figure. */
  jointLabel: [
    SHAPE,
    (s, d) => (s.unlocked && d.joints[s.joint - 1] ? verdictText(d.joints[s.joint - 1]) : ""),
  ],
};

export const controls = [
  group(
    null,
    slider("t", {
      label: "control.t",
      range: (s) => [0, lastIndex(s)],
      step: T_STEP,
      player: true,
    }),
    readout("local", (s, d) =>
      t("hermite.local", {
        i: d.at.piece,
        u: fmt(d.at.u),
        delta: shortNumber(d.at.delta),
      }),
    ),
  ),
  group(
    null,
    readout("count", (s) => t("hermite.count", { count: s.points.length, pieces: lastIndex(s) })),
    pointButtons("points", {
      min: MIN_POINTS,
      max: MAX_POINTS,
      prefix: strings,
      companions: { tangents: [3, 0] },
      adjust: (s) => ({ ...s, tangents: s.tangents.map((m) => m.slice()) }),
    }),
    selectedVectorBox("tangents", {
      label: "hermite.control.tangent",
      error: "hermite.badTangent",
    }),
    checkbox("bezier", { label: "hermite.control.bezier" }),
  ),
  group(
    "hermite.control.joinLegend",
    checkbox("unlocked", { label: "hermite.control.unlocked" }),
    shownWhen(
      (s) => s.unlocked,
      slider("joint", {
        label: "hermite.control.joint",
        range: (s) => [1, Math.max(1, lastIndex(s) - 1)],
        ...INTEGER_SLIDER,
      }),
    ),
    shownWhen(
      (s) => s.unlocked,
      slider("ratio", {
        label: "hermite.control.ratio",
        min: RATIO_MIN,
        max: RATIO_MAX,
        step: RATIO_STEP,
      }),
    ),
    readout("joints", (s, d) => jointsNote(s, d), {
      live: true,
      data: (s, d) => ({ verdicts: d.joints.map(verdictText).join(";") }),
    }),
  ),
];

/** "Joints: P₁ C¹ · P₂ G¹ only" (the core's check). */
function jointsNote(s, d) {
  if (d.joints.length === 0) return t("hermite.noJoints");
  const list = d.joints.map((j, k) => `${pointLabel(k + 1)} ${verdictText(j)}`).join(" · ");
  return t("hermite.joints", { list });
}

/** The tips of the tangent arrows are in the box too. */
function figureBounds(s) {
  const all = s.points.slice();
  s.points.forEach((p, i) => {
    const m = s.tangents[i];
    all.push([p[0] + TANGENT_SCALE * m[0], p[1] + TANGENT_SCALE * m[1]]);
  });
  return paddedBounds(all, ROOM, ROOM);
}

const insetScratch = [0, 0, 0, 0];

export const figure = {
  bounds: figureBounds,
  /** A newly selected point: the tangent box shows its m_i (a change the panel syncs to). */
  handles: { field: "points", select: (i, ui) => ui.touch("selection") },
  insets: (width, height) => {
    insetScratch[2] = hermitePlot.height(height);
    return insetScratch;
  },
};

// ------------------------------------------------------------ drawing

const INCOMING_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 2, cap: "round" });
const TANGENT_STYLE = Object.freeze({ stroke: HUES.orange, width: 2, cap: "round" });
const BEZIER_STYLE = Object.freeze({
  stroke: HUES.bluishGreen,
  width: WIDTH.polygon,
  dash: POLYGON_DASH,
});
const BEZIER_POINT = Object.freeze({ fill: HUES.bluishGreen, radius: 4 });
const PIECE_STYLE = Object.freeze({ stroke: HUES.blue, width: 9, strokeAlpha: 0.2, cap: "round" });
const Q_NAMES = Object.freeze(["q₀", "q₁", "q₂", "q₃"]);

/** The current piece's band, the curve, the Bézier polygon, the tangent arrows, handles, P(t), the plot. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  flatPath(r, v, d.at.pieceSamples); // the current piece: a translucent band under it
  r.paint(PIECE_STYLE);
  for (let k = 0; k < d.samples.length; k++) {
    const flat = d.samples[k];
    flatPath(r, v, flat);
    r.paint(theme.curve);
  }
  if (s.bezier) drawBezier(r, v, d.bezierPoints);
  drawTangents(r, v, s, d.jointLabel);
  d.handles.draw(r, v);
  r.point(v.sx(d.at.point[0]), v.sy(d.at.point[1]), theme.pointOnCurve);
  drawHermitePlot(r, d.graphs, d.at.u, d.at.basis, d.marker);
}

/** The Bézier polygon q0 q1 q2 q3 of the current piece (the core's `toBezier()`), q1 and q2 named. */
function drawBezier(r, v, q) {
  r.beginPath();
  for (let k = 0; k < 4; k++) {
    if (k === 0) r.moveTo(v.sx(q[0]), v.sy(q[1]));
    else r.lineTo(v.sx(q[2 * k]), v.sy(q[2 * k + 1]));
  }
  r.paint(BEZIER_STYLE);
  for (let k = 1; k < 3; k++) {
    const x = v.sx(q[2 * k]);
    const y = v.sy(q[2 * k + 1]);
    r.point(x, y, BEZIER_POINT);
    r.text(Q_NAMES[k], x + 8 * r.scale, y - 8 * r.scale, r.theme.labelSmall, "left", "bottom");
  }
}

/** m₀ … m₇ and the incoming tangent's names, made once. */
const TIP_NAMES = Object.freeze(Array.from({ length: MAX_POINTS }, (_, i) => `m${subscript(i)}`));
const INCOMING_NAMES = Object.freeze(
  Array.from({ length: MAX_POINTS }, (_, i) => `m${subscript(i)}⁻`),
);
const TIP_POINT = Object.freeze({ fill: HUES.orange, radius: 5 });
const INCOMING_POINT = Object.freeze({ fill: HUES.reddishPurple, radius: 5 });
const TIP_LABEL_GAP_PX = 10;
/** The tangent line at an unlocked point runs this fraction of the two arrows' length beyond them. */
const LINE_OVERSHOOT = 0.25;
/** Distance of the joint's verdict from the unlocked point, CSS px. */
const VERDICT_OFFSET_PX = 18;

/**
 * P_i → P_i + s·m_i for every point, a dot on the (draggable) tip, its name beyond it; at an
 * unlocked point also P_k − s·λ·m_k → P_k (the incoming tangent λ·m_k, its tip behind P_k).
 */
function drawTangents(r, v, s, jointLabel) {
  const gap = TIP_LABEL_GAP_PX * r.scale;
  const named = v.width >= NARROW_CANVAS_PX * r.scale; // a phone: the names would cover the points
  for (let i = 0; i < s.points.length; i++) {
    const p = s.points[i];
    const m = s.tangents[i];
    const x = v.sx(p[0]);
    const y = v.sy(p[1]);
    const tx = v.sx(p[0] + TANGENT_SCALE * m[0]);
    const ty = v.sy(p[1] + TANGENT_SCALE * m[1]);
    arrow(r, x, y, tx, ty, TANGENT_STYLE);
    r.point(tx, ty, TIP_POINT);
    if (named) placeLabelAtTip(r, TIP_NAMES[i], x, y, tx, ty, gap, r.theme.labelSmall);
    if (s.unlocked && i === s.joint) {
      const k = TANGENT_SCALE * s.ratio;
      const bx = v.sx(p[0] - k * m[0]);
      const by = v.sy(p[1] - k * m[1]);
      // The line both tangents keep (the incoming tip slides on it), the core's verdict beside P_k.
      r.beginPath();
      r.moveTo(bx - (tx - bx) * LINE_OVERSHOOT, by - (ty - by) * LINE_OVERSHOOT);
      r.lineTo(tx + (tx - bx) * LINE_OVERSHOOT, ty + (ty - by) * LINE_OVERSHOOT);
      r.paint(r.theme.helper);
      placeLabelBeside(
        r,
        jointLabel,
        x,
        y,
        tx - x,
        ty - y,
        -1,
        VERDICT_OFFSET_PX * r.scale,
        r.theme.labelBold,
      );
      arrow(r, bx, by, x, y, INCOMING_STYLE);
      r.point(bx, by, INCOMING_POINT);
      if (named) placeLabelAtTip(r, INCOMING_NAMES[i], x, y, bx, by, gap, r.theme.labelSmall);
    }
  }
}

// ------------------------------------------------------------ formula, label

/** (x, y) in TeX, exact where the numbers allow. */
const pairTex = (num, x, y, level) =>
  `\\left(${listTex([num.value(x, level, true), num.value(y, level, true)])}\\right)`;

/** The basis, the piece's formula with its numbers, the Bézier form when shown, the unlocked joint. */
export function formula(s, d) {
  const { piece: i, u, delta, p0, p1, m0, m1, basis, point } = d.at;
  const inputs = [...p0, ...p1, ...m0, ...m1, delta];
  const num = exactNumbers(u, inputs);
  const uTex = num.param(true);
  const w = Array.from(basis, (h) => num.value(h, 3, true));
  const vec = (p, scale = 1) =>
    pointTex([shortNumber(scale * p[0], true), shortNumber(scale * p[1], true)], DECIMALS, "\\,");
  const lines = [
    "H_0 = 2u^3-3u^2+1,\\ \\ H_1 = -2u^3+3u^2,\\ \\ H_2 = u^3-2u^2+u,\\ \\ H_3 = u^3-u^2",
    `P(t) = H_0 P_{${i}} + H_1 P_{${i + 1}} + H_2\\,\\Delta m_{${i}} + H_3\\,\\Delta m_{${i + 1}},\\quad ` +
      `u = \\frac{t - t_{${i}}}{\\Delta} = ${uTex},\\ \\Delta = ${shortNumber(delta, true)}`,
    `P(${fractionOrDecimals(s.t, true)}) = ${w[0]}\\,${vec(p0)} + ${w[1]}\\,${vec(p1)} + ` +
      `(${w[2]})\\,${vec(m0, delta)} + ` +
      `(${w[3]})\\,${vec(m1, delta)} = ${pairTex(num, point[0], point[1], 3)}`,
  ];
  if (s.bezier) {
    const q = d.bezierPoints;
    lines.push(
      `q_1 = P_{${i}} + \\tfrac{\\Delta}{3} m_{${i}} = ${pointTex([q[2], q[3]], DECIMALS, "\\,")},\\quad ` +
        `q_2 = P_{${i + 1}} - \\tfrac{\\Delta}{3} m_{${i + 1}} = ${pointTex([q[4], q[5]], DECIMALS, "\\,")}`,
    );
  }
  if (s.unlocked) {
    const k = s.joint;
    const verdict = d.joints[k - 1] ? verdictText(d.joints[k - 1]) : "";
    lines.push(
      `m_{${k}}^- = \\lambda\\, m_{${k}}^+,\\ \\lambda = ${fmtTex(s.ratio)}:\\quad ` +
        `\\text{${t("hermite.formula.checker")} ${verdict}}`,
    );
  }
  return lines;
}

export function label(s, d) {
  return t("hermite.aria", {
    count: s.points.length,
    t: fmt(s.t),
    x: fmt(d.at.point[0], 2),
    y: fmt(d.at.point[1], 2),
    joints: d.joints.map(verdictText).join(", "),
  });
}

// ------------------------------------------------------------ tangent tips and the table

/**
 * The tips of the tangent arrows, m₀ … m_n, then (unlocked) the tip of the incoming arrow at
 * P_k, which stays on the tangent's line and sets λ (lib/vector-tips.js drags them). A move
 * writes the state and marks the field; `derive.inPlace` takes it into the splines.
 */
const tips = {
  count: (s) => s.points.length + (s.unlocked ? 1 : 0),
  tip(s, k, out) {
    const incoming = k === s.points.length;
    const j = incoming ? s.joint : k;
    const scale = incoming ? -TANGENT_SCALE * s.ratio : TANGENT_SCALE;
    out[0] = s.points[j][0] + scale * s.tangents[j][0];
    out[1] = s.points[j][1] + scale * s.tangents[j][1];
  },
  drag(ui, k, x, y) {
    const s = ui.state;
    if (k < s.points.length) {
      const p = s.points[k];
      s.tangents[k][0] = (x - p[0]) / TANGENT_SCALE;
      s.tangents[k][1] = (y - p[1]) / TANGENT_SCALE;
      ui.touch("tangents");
      return;
    }
    const p = s.points[s.joint];
    const m = s.tangents[s.joint];
    const mm = m[0] * m[0] + m[1] * m[1];
    if (mm === 0) return;
    const along = -((x - p[0]) * m[0] + (y - p[1]) * m[1]) / (TANGENT_SCALE * mm);
    const ratio = Math.round(along / RATIO_STEP) * RATIO_STEP;
    ui.set("ratio", Math.min(RATIO_MAX, Math.max(RATIO_MIN, ratio)), false);
  },
};

const BASIS_POLYNOMIALS = Object.freeze(["2u³ − 3u² + 1", "−2u³ + 3u²", "u³ − 2u² + u", "u³ − u²"]);
const WEIGHTED = Object.freeze(["P₀", "P₁", "Δm₀", "Δm₁"]);

export function setup(ui) {
  ui.ctx.slots.figure.classList.add("sl-figure-tall"); // the curve and the plot share it
  vectorTips(ui, tips);

  const head = headerRow("hermite.col.", ["function", "polynomial", "value", "times"]);
  const cells = HERMITE_NAMES.map((name, i) => {
    const value = valueSpans();
    const times = el("td", { dataset: { cell: "times" } });
    const row = el(
      "tr",
      { dataset: { index: String(i) } },
      el("th", { scope: "row", text: name }),
      el("td", { text: BASIS_POLYNOMIALS[i] }),
      el("td", { dataset: { cell: "value" } }, value.exact, value.decimal),
      times,
    );
    return { row, value, times };
  });
  const { title, wrap } = titledTable("hermite-basis", {
    children: [
      el("thead", {}, head),
      el(
        "tbody",
        {},
        cells.map((c) => c.row),
      ),
    ],
  });
  ui.ctx.slots.details.append(title, wrap);
  return {
    update(s, d) {
      const { u, basis, piece } = d.at;
      const num = exactNumbers(u, []);
      setText(title, t("hermite.tableCaption", { u: num.param(), i: piece }));
      cells.forEach((c, i) => {
        setValueSpans(c.value, num.value(basis[i], 3), fmt(basis[i]));
        const name = WEIGHTED[i].replace(/[₀₁]/, (x) => subscript(piece + (x === "₀" ? 0 : 1)));
        setText(c.times, name);
      });
    },
  };
}
