/**
 * Demo (syllabus §1): a curve typed piece by piece, P(t) = P_i(t) = (x_i(t), y_i(t)) for t in
 * [a_i, a_{i+1}), and what happens at each joint t = a_i. With one-sided limits
 *
 *   C^k:  P^{(j)}(a⁻) = P^{(j)}(a⁺) for j = 0 … k,
 *   G^k:  the same after a change of parameter on one side (G¹: P′(a⁻) = λ P′(a⁺), λ > 0),
 *
 * the core's `parametricCurve(pieces).joints()` gives per joint the largest k ≤ 3 with C^k and
 * G^k (−1: the pieces do not meet; Infinity: one polynomial on both sides), whether that is
 * proven in exact arithmetic (polynomial pieces with exact coefficients), and the first order
 * that differs. The one-sided values P^{(j)}(a⁻), P^{(j)}(a⁺) come from each piece on its own
 * closed interval (`parametricCurve([piece]).derivative(a, j)`), so neither side is a limit
 * guessed in JS. Each piece is drawn from its own `plot(tolerance, box)` (runs split at NaN).
 *
 * The notes' exercise: x = 1 − t² on [0, 1), then on [1, 2] x = 2 − t² (not C⁰),
 * t² − 4t + 3 (C¹: x′(1) = −2 on both sides, x″ jumps from −2 to 2) or t² − 2t + 1 (C⁰,
 * x′ jumps from −2 to 0); y = t throughout. A fourth case runs the same parabola at double
 * speed on [1, 3/2]: G¹ (indeed the same shape) but P′ doubles, so only C⁰.
 *
 * State `{ pieces: [{ x, y, from, to }, …] }` (texts in the expression language, 1 … 6 pieces);
 * embedded as `<spline-lab demo="piecewise" pieces="1 - t^2, t, 0, 1; t^2 - 4t + 3, t, 1, 2">`
 * (lib/attributes.js: records separated by ";", the texts x, y, from, to by ",").
 */
import { actions, group, readout } from "../lib/panel.js";
import { clauseSeparator, shortNumber } from "../lib/format.js";
import { orderText, orderTex } from "../lib/continuity.js";
import { placeLabel, placeLabelBeside } from "../lib/handles.js";
import { CYCLE, HUES, WIDTH, RADIUS, themed } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { arrow } from "../lib/draw.js";
import {
  boxOf,
  grownBox,
  nameRun,
  plotParts,
  refineForWindow,
  runsPath,
} from "../lib/plot-runs.js";
import { agree, oneSidedTables } from "../lib/one-sided-table.js";
import { PRIMES, pairTex, pieceTex } from "../lib/piece-tex.js";
import { pieceFields } from "../lib/piece-fields.js";

export const id = "piecewise";
export const strings = "piecewise";
export const section = 1;

/** The fields of a piece, in the order of the panel and of the `pieces` attribute. */
export const PIECE_FIELDS = Object.freeze(["x", "y", "from", "to"]);
/** Fewest and most pieces. */
export const MIN_PIECES = 1;
export const MAX_PIECES = 6;
/** The longest text of a field (the parser's MAX_LENGTH). */
const MAX_TEXT = 1000;

const piece = (x, y, from, to) => Object.freeze({ x, y, from, to });
const FIRST = piece("1 - t^2", "t", "0", "1");

/** The notes' exercise (three cases) and the G¹-not-C¹ case: the same first piece. */
export const PRESETS = Object.freeze({
  notC0: Object.freeze([FIRST, piece("2 - t^2", "t", "1", "2")]),
  c1: Object.freeze([FIRST, piece("t^2 - 4t + 3", "t", "1", "2")]),
  c0: Object.freeze([FIRST, piece("t^2 - 2t + 1", "t", "1", "2")]),
  g1: Object.freeze([FIRST, piece("1 - (2t - 1)^2", "2t - 1", "1", "1.5")]),
});

export const defaultState = Object.freeze({ pieces: PRESETS.c1 });

/** `pieces`: 1 … MAX_PIECES records `{ x, y, from, to }` of texts (the core parses them). */
export const fields = {
  pieces(s, name) {
    const list = s[name];
    if (!Array.isArray(list)) throw new Error(t("error.notArray", { field: name }));
    if (list.length < MIN_PIECES || list.length > MAX_PIECES)
      throw new Error(
        t("error.count", { field: name, min: MIN_PIECES, max: MAX_PIECES, count: list.length }),
      );
    list.forEach((p, index) => {
      const ok =
        p !== null &&
        typeof p === "object" &&
        !Array.isArray(p) &&
        Object.keys(p).length === PIECE_FIELDS.length &&
        PIECE_FIELDS.every((f) => typeof p[f] === "string" && p[f].length <= MAX_TEXT);
      if (!ok) throw new Error(t("piecewise.badPiece", { field: name, index: index + 1 }));
    });
  },
};

/**
 * The model: the whole curve (joints, TeX) and each piece alone on its closed interval (its
 * plot and its one-sided values at the joints). A text the core refuses throws here, before
 * anything changes.
 */
export const derive = {
  from: ["pieces"],
  build(s, sl) {
    const curve = sl.parametricCurve(s.pieces);
    const parts = [];
    try {
      for (const p of s.pieces) parts.push(sl.parametricCurve([p]));
    } catch (err) {
      curve.free();
      for (const part of parts) part.free();
      throw err;
    }
    return { curve, parts };
  },
};

// ------------------------------------------------------------ what the core returns

/** Samples per piece for the figure's box; the plot's tolerance and margin relative to it. */
const BOX_SAMPLES = 256;
const TOLERANCE_FRACTION = 1e-3;
const PLOT_MARGIN = 1;
/** The longest velocity arrow is this fraction of the box's diagonal. */
const ARROW_FRACTION = 0.22;

/**
 * Each piece's plot (the core's adaptive polyline, runs split at NaN) and the box shown; the
 * plot is made again when the reader zooms in or pans out of it (`setup`: `refineForWindow`).
 */
function plotPieces(d) {
  const box = boxOf(d.parts.map((part) => part.sampleUniform(BOX_SAMPLES)));
  const tolerance = TOLERANCE_FRACTION * Math.hypot(box[2] - box[0], box[3] - box[1]);
  const plotBox = grownBox(box, PLOT_MARGIN);
  return {
    box,
    tolerance,
    plotBox,
    ...plotParts(d.parts, tolerance, plotBox),
    labels: d.parts.map((_, i) => `P${subscriptNumber(i + 1)}`),
  };
}

const subscriptNumber = (n) => String(n).replace(/\d/g, (c) => "₀₁₂₃₄₅₆₇₈₉"[c]);

/** The highest derivative order listed per joint (0 … K: position, velocity, …). */
function shownOrder(joint) {
  if (Number.isInteger(joint.order)) return Math.min(3, Math.max(2, joint.order));
  return joint.c === Infinity ? 2 : Math.min(3, Math.max(2, joint.c));
}

/** The core's value of piece `part` at its end `t`: P (k = 0) or P^{(k)}. */
const valueAt = (part, tt, k) => (k === 0 ? part.evaluate(tt) : part.derivative(tt, k));

/**
 * Per joint: the core's verdict `{ t, c, g, exact, order }`, the one-sided values
 * `left[k]`, `right[k]` (k = 0 … K) from the two pieces on their closed intervals, and texts.
 */
function jointsOf(d) {
  return Array.from(d.curve.joints(), (j, i) => {
    const a = d.parts[i].pieceDomain(0)[1];
    const b = d.parts[i + 1].pieceDomain(0)[0];
    const top = shownOrder(j);
    const left = [];
    const right = [];
    for (let k = 0; k <= top; k++) {
      left.push(valueAt(d.parts[i], a, k));
      right.push(valueAt(d.parts[i + 1], b, k));
    }
    const verdict = verdictText(j);
    // A piece near its end bends towards its acceleration's normal part: its arrow's name goes
    // to the other side (1: the arrow's left, −1: its right, as placeLabelBeside reads it).
    const away = (v, acc) => (v[0] * acc[1] - v[1] * acc[0] > 0 ? -1 : 1);
    const how = howText(j, "piecewise.proven", "piecewise.measured", "piecewise.breakProven");
    const short = howText(
      j,
      "piecewise.formula.proven",
      "piecewise.formula.measured",
      "piecewise.formula.breakProven",
    );
    return {
      t: j.t,
      c: j.c,
      g: j.g,
      exact: Boolean(j.exact),
      order: Number.isInteger(j.order) ? j.order : null,
      left,
      right,
      verdict,
      how,
      short,
      text: t("piecewise.joint", { t: shortNumber(j.t), verdict }),
      leftSide: away(left[1], left[2]),
      rightSide: away(right[1], right[2]),
      leftArrow: t("piecewise.leftArrow", { t: shortNumber(j.t) }),
      rightArrow: t("piecewise.rightArrow", { t: shortNumber(j.t) }),
      tag: t("piecewise.tag", { t: shortNumber(j.t) }),
      figureLabel: t("piecewise.figureVerdict", {
        t: shortNumber(j.t),
        verdict: j.c < 0 ? t("piecewise.formula.notC0") : verdict,
        how: short,
      }),
    };
  });
}

/**
 * How the verdict is known: proven in exact arithmetic, or measured in floating point — with
 * the first order that differs proven different by interval enclosures (`disjoint`) or not.
 */
function howText(j, proven, measured, breakProven) {
  if (j.exact) return t(proven);
  if (j.disjoint && Number.isInteger(j.order)) return t(breakProven, { order: j.order });
  return t(measured);
}

/** "C¹, G¹", or the break / one-polynomial words. */
function verdictText(j) {
  if (j.c < 0) return t("piecewise.verdict.broken");
  if (j.c === Infinity) return t("piecewise.verdict.infinite");
  return t("piecewise.verdict", { c: orderText("C", j.c), g: orderText("G", j.g) });
}

/**
 * Per joint the scale of its two velocity arrows (world units per unit of speed): the faster
 * one is ARROW_FRACTION of the box's diagonal, so both sides compare; 0 without a speed.
 */
function arrowScales(d) {
  const [x0, y0, x1, y1] = d.shape.box;
  const size = ARROW_FRACTION * Math.hypot(x1 - x0, y1 - y0);
  return d.joints.map((j) => {
    let fastest = 0;
    for (const v of [j.left[1], j.right[1]]) {
      const speed = Math.hypot(v[0], v[1]);
      if (Number.isFinite(speed)) fastest = Math.max(fastest, speed);
    }
    return fastest > 0 ? size / fastest : 0;
  });
}

export const compute = {
  shape: [["pieces"], (s, d) => plotPieces(d)],
  joints: [["pieces"], (s, d) => jointsOf(d)],
  arrowScales: [["pieces"], (s, d) => arrowScales(d)],
};

// ------------------------------------------------------------ the panel

/** A new last piece: the last one's formulas on an interval as long, starting where it ends. */
function addedPiece(s, d) {
  const last = s.pieces[s.pieces.length - 1];
  const [a, b] = d.parts[d.parts.length - 1].pieceDomain(0);
  const end = Number((2 * b - a).toFixed(6));
  return { x: last.x, y: last.y, from: last.to, to: String(end) };
}

const preset = (key) => ({
  name: `preset-${key}`,
  label: `piecewise.preset.${key}`,
  title: "piecewise.preset.title",
  run: (ui) => {
    ui.replace({ ...ui.state, pieces: structuredClone(PRESETS[key]) });
    ui.fit();
  },
});

/** The presets' group marked `data-presets`: an exercise hides it (it holds the answer). */
const presetGroup = (item) => ({
  build(ui) {
    const part = item.build(ui);
    part.element.dataset.presets = "";
    return part;
  },
});

export const controls = [
  group(
    "piecewise.pieces",
    pieceFields("pieces", {
      prefix: "piecewise",
      names: PIECE_FIELDS,
      min: MIN_PIECES,
      max: MAX_PIECES,
      added: addedPiece,
    }),
  ),
  presetGroup(actions(["notC0", "c1", "c0", "g1"].map(preset), { title: "piecewise.presets" })),
  group(
    "piecewise.jointsLegend",
    readout(
      "joints",
      (s, d) =>
        d.joints.length === 0
          ? t("piecewise.noJoints")
          : d.joints.map((j) => `${j.text} · ${j.how}`).join("\n"),
      {
        kind: "readout",
        live: true,
        data: (s, d) => ({
          verdicts: d.joints.map((j) => `${j.c},${j.g},${j.exact}`).join(";"),
        }),
      },
    ),
    readout("complete", (s, d) => (d.shape.complete ? "" : t("piecewise.incomplete"))),
  ),
];

export const figure = {
  bounds: (s, d) => {
    const [x0, y0, x1, y1] = d.shape.box;
    const padX = 0.12 * (x1 - x0);
    const padY = 0.12 * (y1 - y0);
    return [x0 - padX, y0 - padY, x1 + padX, y1 + padY];
  },
};

// ------------------------------------------------------------ drawing

const pieceStyles = Object.freeze(
  CYCLE.map((stroke) => Object.freeze({ stroke, width: WIDTH.curve, join: "round", cap: "round" })),
);
/**
 * The velocity arriving, P′(a⁻) (vermillion, wide, under), and leaving, P′(a⁺) (blue, narrow,
 * over): hues no piece uses, so an arrow along its piece still shows; equal arrows show both.
 */
const ARRIVING = Object.freeze({ stroke: HUES.vermillion, width: 4, cap: "round", join: "round" });
const LEAVING = Object.freeze({ stroke: HUES.blue, width: 2, cap: "round", join: "round" });
const endStyles = Object.freeze(
  CYCLE.map((fill) => Object.freeze({ fill, radius: RADIUS.constructionPoint + 1 })),
);
const jointStyles = themed((theme) => ({
  text: Object.freeze({ ...theme.label, weight: "bold" }),
  point: Object.freeze({
    fill: theme.background,
    stroke: theme.name === "dark" ? "#EEEEEE" : "#222222",
    width: 1.5,
    radius: RADIUS.pointOnCurve,
  }),
}));
/** |unit(P′(a⁻)) − unit(P′(a⁺))| above this is a corner (the tag goes opposite both arrows). */
const CORNER = 0.5;
/** Distance of a joint's tag "t = 1" from the joint (CSS px). */
const TAG_OFFSET_PX = 8;
/** Margin of the verdicts from the canvas corner (CSS px), and their line height (font sizes). */
const TEXT_MARGIN_PX = 12;
const VERDICT_LINE_HEIGHT = 1.35;
const LABEL_OFFSET_PX = 10;
/** Distance of an arrow's name from the arrow's middle (CSS px). */
const ARROW_LABEL_OFFSET_PX = 14;

/** Each piece in its colour and named; at each joint the ends, the velocities and the verdict. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const style = jointStyles(theme).text;
  const { points, labels } = d.shape;
  for (let i = 0; i < points.length; i++) {
    runsPath(r, v, points[i]);
    r.paint(pieceStyles[i % CYCLE.length]);
  }
  for (let i = 0; i < points.length; i++)
    nameRun(r, v, points[i], labels[i], style, LABEL_OFFSET_PX * r.scale);
  const named = d.joints.length > 1; // one joint: the verdict at the top names it
  for (let i = 0; i < d.joints.length; i++)
    drawJoint(r, v, d.joints[i], i, d.arrowScales[i], named);
  // The verdicts, top left.
  const margin = TEXT_MARGIN_PX * r.scale;
  const step = VERDICT_LINE_HEIGHT * theme.label.size * r.scale;
  for (let i = 0; i < d.joints.length; i++)
    r.text(d.joints[i].figureLabel, margin, margin + i * step, style, "left", "top");
}

/**
 * Joint i: the gap between the ends when they differ, the velocity arriving, P′(a⁻), at the
 * left end and leaving, P′(a⁺), from the right end (each named on the side away from its
 * piece's bend, or from the other end when the ends are apart), the joint's point, and with
 * several joints its tag "t = a".
 */
function drawJoint(r, v, j, i, scale, named) {
  const theme = r.theme;
  const style = jointStyles(theme).text;
  const px = v.sx(j.left[0][0]);
  const py = v.sy(j.left[0][1]);
  const qx = v.sx(j.right[0][0]);
  const qy = v.sy(j.right[0][1]);
  const finite = Number.isFinite(px + py + qx + qy);
  if (finite && j.c < 0) {
    r.beginPath();
    r.moveTo(px, py);
    r.lineTo(qx, qy);
    r.paint(theme.helper);
  }
  const a = j.left[1];
  const b = j.right[1];
  const lx = a[0] * scale * v.scale;
  const ly = -a[1] * scale * v.scale;
  const rx = b[0] * scale * v.scale;
  const ry = -b[1] * scale * v.scale;
  const ll = Math.hypot(lx, ly);
  const rl = Math.hypot(rx, ry);
  if (Number.isFinite(ll + px + py)) arrow(r, px - lx, py - ly, px, py, ARRIVING);
  if (Number.isFinite(rl + qx + qy)) arrow(r, qx, qy, qx + rx, qy + ry, LEAVING);
  if (!finite) return;
  if (j.c < 0) {
    r.point(px, py, endStyles[i % CYCLE.length]);
    r.point(qx, qy, endStyles[(i + 1) % CYCLE.length]);
  } else {
    r.point(qx, qy, jointStyles(theme).point);
  }
  const offset = ARROW_LABEL_OFFSET_PX * r.scale;
  // Apart ends: each name away from the other end (the gap); else away from its piece's bend.
  const apart = j.c < 0 && Math.hypot(qx - px, qy - py) > 1;
  const leftSide = apart ? (ly * (qx - px) - lx * (qy - py) > 0 ? -1 : 1) : j.leftSide;
  const rightSide = apart ? (ry * (px - qx) - rx * (py - qy) > 0 ? -1 : 1) : j.rightSide;
  if (ll > 1) {
    placeLabelBeside(r, j.leftArrow, px - lx / 2, py - ly / 2, lx, ly, leftSide, offset, style);
  }
  if (rl > 1) {
    placeLabelBeside(r, j.rightArrow, qx + rx / 2, qy + ry / 2, rx, ry, rightSide, offset, style);
  }
  if (!named) return;
  // The tag where neither arrow is: at a corner opposite both (the arriving arrow lies behind
  // the joint, the leaving one ahead), along a smooth joint across it on the outer side.
  const ux = ll > 1 ? lx / ll : 0;
  const uy = ll > 1 ? ly / ll : 0;
  const wx = rl > 1 ? rx / rl : 0;
  const wy = rl > 1 ? ry / rl : 0;
  let dx = ux - wx;
  let dy = uy - wy;
  let m = Math.hypot(dx, dy);
  if (m < CORNER) {
    // Smooth: the left normal of the mean direction, turned to the outer side.
    dx = j.leftSide * (uy + wy);
    dy = -j.leftSide * (ux + wx);
    m = Math.hypot(dx, dy);
  }
  if (!(m > 1e-6)) [dx, dy, m] = [0, -1, 1];
  const tx = j.c < 0 ? (px + qx) / 2 : qx;
  const ty = j.c < 0 ? (py + qy) / 2 : qy;
  placeLabel(r, j.tag, tx, ty, dx / m, dy / m, TAG_OFFSET_PX * r.scale, style);
}

// ------------------------------------------------------------ formula, label, table

/** Each piece's formula and velocity, then per joint the one-sided values and the verdict. */
export function formula(s, d) {
  const lines = [];
  for (let i = 0; i < s.pieces.length; i++) lines.push(...pieceTex(d.curve, s.pieces, i));
  d.joints.forEach((j, i) => {
    const at = shortNumber(j.t, true);
    const terms = [];
    for (let k = 0; k < j.left.length && k <= Math.max(1, Math.min(j.order ?? 1, 2)); k++) {
      const same = [0, 1].every((c) => agree(j, k, j.left[k][c], j.right[k][c]));
      terms.push(
        `P_{${i + 1}}${PRIMES[k]}({${at}}^{-}) = ${pairTex(j.left[k])} ` +
          `${same ? "=" : "\\neq"} P_{${i + 2}}${PRIMES[k]}({${at}}^{+}) = ${pairTex(j.right[k])}`,
      );
    }
    lines.push(...terms);
    const found =
      j.c < 0
        ? `\\text{${t("piecewise.formula.notC0")}}`
        : j.c === Infinity
          ? orderTex("C", Infinity)
          : `${orderTex("C", j.c)},\\ ${orderTex("G", j.g)}`;
    const how = j.short;
    lines.push(
      `\\text{${t("piecewise.formula.joint")}}\\ t = ${at}:\\ ${found}\\ \\ (\\text{${how}})`,
    );
  });
  return lines;
}

export function label(s, d) {
  if (d.joints.length === 0) return t("piecewise.ariaNoJoints");
  return t("piecewise.aria", {
    count: s.pieces.length,
    joints: d.joints.map((j) => `${j.text}, ${j.how}`).join(clauseSeparator()),
  });
}

/** The tables of one-sided values under the figure, one per joint. */
export function setup(ui) {
  ui.view.beforeFrame(() => {
    if (ui.data.shape && ui.data.parts) refineForWindow(ui.view, ui.data.parts, ui.data.shape);
  });
  const tables = oneSidedTables(ui);
  return { update: (s, d) => tables.update(d.joints) };
}
