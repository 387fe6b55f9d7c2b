/**
 * Demo (syllabus §2, with the continuity checker of §1): joining two cubic Bézier pieces.
 * P lives on t ∈ [0, 1] and Q on t ∈ [1, 2]; a rule is kept while the points are dragged:
 *
 *   C0: Q₀ = P₃,   C1: 3(P₃ − P₂) = 3(Q₁ − Q₀) ⇒ Q₁ = 2P₃ − P₂,
 *   G1: Q₁ = Q₀ + λ(P₃ − P₂), λ > 0,   C2: C1 and Q₂ = P₁ − 4P₂ + 4P₃.
 *
 * The core's `joinBezier(left, right, rule, adjust)` moves the constrained points of the other
 * piece, and `jointContinuity(left, right)` reports what the joint really is. The dragged piece
 * is updated in place (`setControlPoint`), the following piece is the one the core returns, and
 * the picture is drawn from core data only (samples, derivatives at the joint, the verdict).
 */
import { field } from "../lib/validate.js";
import { choice, readout, group } from "../lib/panel.js";
import { placeLabel, placeLabelBeside } from "../lib/handles.js";
import { el, setText } from "../lib/controls.js";
import { shortNumber, fmtTex, pointTex, pointText } from "../lib/format.js";
import { orderText, orderTex } from "../lib/continuity.js";
import { HUES, WIDTH, RADIUS, FONT_SIZE, themed } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { boundsOf } from "../lib/geometry.js";
import { namedRows, titledTable } from "../lib/table.js";
import { JoinedPieces } from "../lib/joined-pieces.js";
import { pointsPath, flatPath, arrow, drawCaption, extendedSegmentPath } from "../lib/draw.js";

export const id = "joining";
export const strings = "joining";
export const section = 2;

/** The rules offered, in the order of the radio buttons ("none": nothing is enforced). */
export const RULES = Object.freeze(["none", "C0", "C1", "G1", "C2"]);

/**
 * Two cubics with integer points that meet C1 (Q₁ = 2P₃ − P₂ = (5, −1)) but not C2, so the
 * checker reads "C¹, G¹" at the start.
 */
export const defaultState = Object.freeze({
  left: Object.freeze(
    [
      [0, 0],
      [1, 3],
      [3, 3],
      [4, 1],
    ].map(Object.freeze),
  ),
  right: Object.freeze(
    [
      [4, 1],
      [5, -1],
      [7, 0],
      [8, 2],
    ].map(Object.freeze),
  ),
  rule: "C1",
});

/** Both pieces are cubics: four control points each. */
const POINTS_PER_PIECE = 4;
/** Degree of each piece (n = m = 3 in the formulas). */
const DEGREE = POINTS_PER_PIECE - 1;
/** Points sampled along each piece (one `sampleUniform` call per piece and change). */
const CURVE_SAMPLES = 128;
/** The tangent arrows at the joint are drawn at this fraction of P′(1) and Q′(1). */
const ARROW_SCALE = 1 / 6;
/** The tangent line P₂–P₃–Q₁ is drawn this fraction of its length beyond both ends. */
const TANGENT_LINE_OVERSHOOT = 0.25;
/** Half the side of the square marking a point the rule sets (CSS px). */
const MARK_HALF_PX = 9;
/** Margin of the verdict and caption texts from the canvas edges (CSS px). */
const TEXT_MARGIN_PX = 12;
/** Distance of an arrow's label from the arrow's middle (CSS px). */
const ARROW_LABEL_OFFSET_PX = 14;

/** Interval of each piece: P on [0, 1], Q on [1, 2] (the joint at t = 1). */
const INTERVALS = Object.freeze({ left: Object.freeze([0, 1]), right: Object.freeze([1, 2]) });
/** The global parameter at the joint. */
const JOINT_T = 1;

// Styles of this demo's own marks (theme hues are the same in light and dark mode).
const RIGHT_CURVE_STYLE = Object.freeze({
  stroke: HUES.bluishGreen,
  width: WIDTH.curve,
  join: "round",
  cap: "round",
});
const LEFT_ARROW_STYLE = Object.freeze({
  stroke: HUES.orange,
  width: 4,
  cap: "round",
  join: "round",
});
const RIGHT_ARROW_STYLE = Object.freeze({
  stroke: HUES.reddishPurple,
  width: 2,
  cap: "round",
  join: "round",
});
/** Arrow label styles per theme (their halo is the theme's background), made once per theme. */
const arrowLabelStyles = themed((theme) => ({
  left: Object.freeze({
    fill: theme.name === "dark" ? HUES.orange : "#A86F00",
    size: FONT_SIZE.small,
    weight: "bold",
    halo: theme.background,
  }),
  right: Object.freeze({
    fill: HUES.reddishPurple,
    size: FONT_SIZE.small,
    weight: "bold",
    halo: theme.background,
  }),
}));
const MARK_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 1.5 });
const D_POINT_STYLE = Object.freeze({ fill: HUES.reddishPurple, radius: RADIUS.constructionPoint });

export const fields = {
  left: field.points({ min: POINTS_PER_PIECE, max: POINTS_PER_PIECE }),
  right: field.points({ min: POINTS_PER_PIECE, max: POINTS_PER_PIECE }),
  rule: field.choice(RULES),
};

/**
 * The pieces of a state, in wasm (lib/joined-pieces.js: P on [0, 1], Q on [1, 2], a piece made to
 * follow the rule by the core's `joinBezier`; `error` keeps the core's message for `setup`).
 * When its points break its rule (a link, a file, a new rule), the right piece follows (the
 * syllabus form); a state that obeys its rule stays exactly as it is.
 * When the core cannot establish the rule, the state is refused (the last one stays), except
 * the first one, shown as it is with the core's message.
 * Moving handle i re-establishes the rule: a point of the left piece (or Q₃) makes the right
 * piece follow, Q₀, Q₁ or Q₂ the left one; G1's Q₁, held on the tangent line, keeps P₂ and is
 * put back exactly on the ray at its new distance (the right piece follows).
 */
export const derive = {
  from: ["left", "right", "rule"],
  build(s, sl, { first = false } = {}) {
    const pieces = new JoinedPieces(sl, s, INTERVALS);
    if (s.rule !== "none" && !satisfies(s.rule, sl.jointContinuity(pieces.left, pieces.right))) {
      if (first) {
        pieces.tryFollow(s, "right");
      } else {
        try {
          pieces.follow(s, "right");
        } catch (err) {
          pieces.free();
          throw err;
        }
      }
    }
    return { pieces };
  },
  moved({ pieces }, i, xy, s) {
    const onLeft = i < POINTS_PER_PIECE;
    const k = onLeft ? i : i - POINTS_PER_PIECE;
    (onLeft ? pieces.left : pieces.right).setControlPoint(k, xy); // in place
    if (s.rule === "none") return;
    const g1Slide = s.rule === "G1" && i === POINTS_PER_PIECE + 1;
    pieces.tryFollow(s, onLeft || k === POINTS_PER_PIECE - 1 || g1Slide ? "right" : "left");
  },
};

/** The derivatives at the joint from the core, its verdict `{ c, g }` and the verdict's text. */
function jointOf(sl, { left, right }) {
  const verdict = sl.jointContinuity(left, right);
  const text =
    verdict.c < 0
      ? t("joining.verdict.broken")
      : verdict.c === Infinity
        ? t("joining.verdict.infinite")
        : t("joining.verdict", { c: orderText("C", verdict.c), g: orderText("G", verdict.g) });
  return {
    dLeft: left.derivative(JOINT_T, 1),
    dRight: right.derivative(JOINT_T, 1),
    ddLeft: left.derivative(JOINT_T, 2),
    ddRight: right.derivative(JOINT_T, 2),
    verdict,
    text,
  };
}

const samplesOf = (piece) => piece.sampleUniform(CURVE_SAMPLES);

/** What the core returns: both pieces' samples, and the joint. */
export const compute = {
  samples: [
    ["left", "right"],
    (s, { pieces }) => ({ left: samplesOf(pieces.left), right: samplesOf(pieces.right) }),
  ],
  joint: [["left", "right"], (s, d) => jointOf(d.sl, d.pieces)],
};

export const controls = [
  group(
    "joining.ruleLegend",
    choice("rule", {
      options: RULES.map((rule) => ({ value: rule, label: `joining.rule.${rule}` })),
      rebuild: true,
    }),
  ),
  group(
    "joining.checkerLegend",
    readout("verdict", (s, d) => d.joint.text, {
      kind: "readout",
      live: true,
      data: (s, d) => ({ c: String(d.joint.verdict.c), g: String(d.joint.verdict.g) }),
    }),
    readout("legend", (s) => t(`joining.legend.${s.rule}`)),
    readout("free", (s) => t(`joining.free.${s.rule}`)),
  ),
];

const HANDLE_LABELS = Object.freeze(["P₀", "P₁", "P₂", "P₃", "Q₀", "Q₁", "Q₂", "Q₃"]);
const JOINT_LABEL = "P₃ = Q₀";

/** True when P₃ and Q₀ are the same point (one handle on screen, one label). */
function jointShared(s) {
  const a = s.left[POINTS_PER_PIECE - 1];
  const b = s.right[0];
  return a[0] === b[0] && a[1] === b[1];
}

export const figure = {
  bounds: (s) => boundsOf(s.left.concat(s.right)),
  /** P₀ … P₃, then Q₀ … Q₃; G1: Q₁ only slides along the tangent line P₂P₃ (its distance is free). */
  handles: {
    field: ["left", "right"],
    label: (i, s) => {
      if (jointShared(s) && i === POINTS_PER_PIECE - 1) return JOINT_LABEL;
      if (jointShared(s) && i === POINTS_PER_PIECE) return "";
      return HANDLE_LABELS[i];
    },
    constraint: (i, s) => {
      if (s.rule !== "G1" || i !== POINTS_PER_PIECE + 1) return null;
      const p2 = s.left[POINTS_PER_PIECE - 2];
      const p3 = s.left[POINTS_PER_PIECE - 1];
      return [p2[0], p2[1], p3[0], p3[1]];
    },
  },
};

/**
 * Which points the rule sets from the left piece (the syllabus form): Q₀ for every rule, Q₁ for
 * C1, G1 and C2, Q₂ for C2. They are marked with a square.
 */
function ruleSets(rule, i) {
  const k = i - POINTS_PER_PIECE;
  switch (rule) {
    case "C0":
      return k === 0;
    case "C1":
    case "G1":
      return k === 0 || k === 1;
    case "C2":
      return k >= 0 && k <= 2;
    default:
      return false;
  }
}

// ------------------------------------------------------------ drawing

/** The rule's helper geometry, both polygons and pieces, the marks, the velocities at the joint, the verdict. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const P = s.left;
  const Q = s.right;

  // Helper geometry of the rule: the tangent line P₂–P₃–Q₁ (C1, G1, C2) and for C2 the
  // A-frame P₁ → D = 2P₂ − P₁ → Q₂ (D = 2Q₁ − Q₂ exactly when the joint is C2).
  if (s.rule === "C1" || s.rule === "G1" || s.rule === "C2") {
    extendedSegmentPath(r, v, P[2], Q[1], TANGENT_LINE_OVERSHOOT);
    r.paint(theme.helper);
  }
  if (s.rule === "C2") {
    const dx = 2 * P[2][0] - P[1][0];
    const dy = 2 * P[2][1] - P[1][1];
    r.beginPath();
    r.moveTo(v.sx(P[1][0]), v.sy(P[1][1]));
    r.lineTo(v.sx(dx), v.sy(dy));
    r.lineTo(v.sx(Q[2][0]), v.sy(Q[2][1]));
    r.paint(theme.helper);
    r.point(v.sx(dx), v.sy(dy), D_POINT_STYLE);
    placeLabel(
      r,
      t("joining.pointD"),
      v.sx(dx),
      v.sy(dy),
      0,
      -1,
      D_POINT_STYLE.radius * r.scale,
      theme.labelSmall,
    );
  }

  // Control polygons.
  pointsPath(r, v, P);
  r.paint(theme.polygon);
  pointsPath(r, v, Q);
  r.paint(theme.polygon);

  // The two pieces: P blue, Q bluish green (and their labels tell them apart too).
  flatPath(r, v, d.samples.left);
  r.paint(theme.curve);
  flatPath(r, v, d.samples.right);
  r.paint(RIGHT_CURVE_STYLE);

  // Points the rule sets: a square around the handle.
  const half = MARK_HALF_PX * r.scale;
  for (let i = POINTS_PER_PIECE; i < 2 * POINTS_PER_PIECE; i++) {
    if (!ruleSets(s.rule, i)) continue;
    const p = Q[i - POINTS_PER_PIECE];
    r.beginPath();
    r.rect(v.sx(p[0]) - half, v.sy(p[1]) - half, 2 * half, 2 * half);
    r.paint(MARK_STYLE);
  }

  // Velocities at the joint, head to tail: P′(1) arriving at the joint, Q′(1) leaving it.
  const jx = v.sx(P[3][0]);
  const jy = v.sy(P[3][1]);
  const qx = v.sx(Q[0][0]);
  const qy = v.sy(Q[0][1]);
  const lx = d.joint.dLeft[0] * ARROW_SCALE * v.scale;
  const ly = -d.joint.dLeft[1] * ARROW_SCALE * v.scale;
  const rx = d.joint.dRight[0] * ARROW_SCALE * v.scale;
  const ry = -d.joint.dRight[1] * ARROW_SCALE * v.scale;
  arrow(r, jx - lx, jy - ly, jx, jy, LEFT_ARROW_STYLE);
  arrow(r, qx, qy, qx + rx, qy + ry, RIGHT_ARROW_STYLE);
  const labelStyle = arrowLabelStyles(theme);
  // P′ labelled on its arrow's left, Q′ on its right (apart even when the arrows are collinear).
  const offset = ARROW_LABEL_OFFSET_PX * r.scale;
  const leftText = t("joining.leftArrow");
  const rightText = t("joining.rightArrow");
  placeLabelBeside(r, leftText, jx - lx / 2, jy - ly / 2, lx, ly, 1, offset, labelStyle.left);
  placeLabelBeside(r, rightText, qx + rx / 2, qy + ry / 2, rx, ry, -1, offset, labelStyle.right);

  d.handles.draw(r, v);

  // The checker's verdict, top left; what the arrows are, bottom left.
  const margin = TEXT_MARGIN_PX * r.scale;
  r.text(d.joint.text, margin, margin, theme.labelBold, "left", "top");
  const captionWidth = v.width - 2 * margin;
  drawCaption(
    r,
    t("joining.arrowCaption"),
    margin,
    v.height - margin,
    theme.labelSmall,
    captionWidth,
    "bottom",
  );
}

// ------------------------------------------------------------ helpers, formula, label, table

/** True when the checker's verdict already satisfies `rule` (then the points are left alone). */
function satisfies(rule, k) {
  switch (rule) {
    case "C0":
      return k.c >= 0;
    case "C1":
      return k.c >= 1;
    case "C2":
      return k.c >= 2;
    case "G1":
      return k.c >= 0 && k.g >= 1;
    default:
      return true;
  }
}

/** The rule in the syllabus' form (degrees n = m = 3, both intervals of length 1). */
function ruleTex(rule) {
  switch (rule) {
    case "C0":
      return "\\text{C}^0:\\ P_n = Q_0";
    case "C1":
      return "\\text{C}^1:\\ n(P_n - P_{n-1}) = m(Q_1 - Q_0),\\ n = m = 3 \\;\\Rightarrow\\; Q_1 = 2P_3 - P_2";
    case "G1":
      return (
        "\\text{G}^1:\\ Q_0 = P_n,\\ \\ Q_1 = Q_0 + \\lambda\\,(P_n - P_{n-1}),\\ \\lambda > 0\\ " +
        `\\text{(${t("joining.formula.anyLength")})}`
      );
    case "C2":
      return (
        "\\text{C}^2:\\ n(n-1)(P_n - 2P_{n-1} + P_{n-2}) = m(m-1)(Q_2 - 2Q_1 + Q_0) " +
        "\\;\\Rightarrow\\; Q_2 = P_1 - 4P_2 + 4P_3"
      );
    default:
      return `\\text{${t("joining.formula.none")}}`;
  }
}

/** "(x, y)" with short numbers. */
function pair(x, y) {
  return pointText([shortNumber(x), shortNumber(y)]);
}

/** Each condition with the numbers, "=" or "≠" as the checker found it; λ for G1; the verdict. */
export function formula(s, d) {
  const P = s.left;
  const Q = s.right;
  const {
    dLeft,
    dRight,
    ddLeft,
    ddRight,
    verdict: { c, g },
  } = d.joint;
  const rel = (holds) => (holds ? "\\;=\\;" : "\\;\\neq\\;");
  const tex = (x, y) => pointTex([shortNumber(x, true), shortNumber(y, true)]).replace(/-/g, "{-}");
  const n = DEGREE;
  const lines = [`\\text{${t("joining.formula.rule")}}\\quad ${ruleTex(s.rule)}`];
  lines.push(
    `\\text{C}^0:\\ P_{${n}} = ${tex(P[3][0], P[3][1])} ${rel(c >= 0)} Q_0 = ${tex(Q[0][0], Q[0][1])}`,
  );
  lines.push(
    `\\text{C}^1:\\ ${n}(P_{${n}} - P_{${n - 1}}) = ${tex(dLeft[0], dLeft[1])} ${rel(c >= 1)} ` +
      `${n}(Q_1 - Q_0) = ${tex(dRight[0], dRight[1])}`,
  );
  lines.push(
    `\\text{C}^2:\\ ${n * (n - 1)}(P_{${n}} - 2P_{${n - 1}} + P_{${n - 2}}) = ` +
      `${tex(ddLeft[0], ddLeft[1])} ${rel(c >= 2)} ` +
      `${n * (n - 1)}(Q_2 - 2Q_1 + Q_0) = ${tex(ddRight[0], ddRight[1])}`,
  );
  if (c >= 0 && g >= 1) {
    const lambda = Math.hypot(dRight[0], dRight[1]) / Math.hypot(dLeft[0], dLeft[1]);
    lines.push(
      `\\text{G}^1:\\ Q_1 - Q_0 = \\lambda\\,(P_{${n}} - P_{${n - 1}}),\\quad ` +
        `\\lambda = \\frac{|Q'(1)|}{|P'(1)|} = ${fmtTex(lambda)} > 0`,
    );
  } else {
    lines.push(`\\text{G}^1:\\ \\text{${t("joining.formula.notG1")}}`);
  }
  const found =
    c < 0 ? `\\text{${t("joining.formula.notC0")}}` : `${orderTex("C", c)},\\ ${orderTex("G", g)}`;
  lines.push(`\\text{${t("joining.formula.checker")}}\\ ${found}`);
  return lines;
}

/** The rule, the verdict and the velocities at the joint. */
export function label(s, d) {
  const { dLeft, dRight, text } = d.joint;
  const rule = t(`joining.rule.${s.rule}`);
  return t("joining.aria", {
    rule,
    verdict: text,
    dp: pair(dLeft[0], dLeft[1]),
    dq: pair(dRight[0], dRight[1]),
  });
}

/** The table of what the rules compare (differences, the core's derivatives at the joint); the core's refusals. */
export function setup(ui) {
  const rowKeys = ["p3-p2", "q1-q0", "dp", "dq", "ddp", "ddq"];
  const { rows, cells } = namedRows("joining.row.", rowKeys, "vector");
  const caption = t("joining.tableCaption");
  const { title, wrap } = titledTable("joining", { caption, children: [el("tbody", {}, rows)] });
  ui.ctx.slots.details.append(title, wrap);
  return {
    update(s, d) {
      const pieces = d.pieces;
      if (pieces.error) ui.status(pieces.error, "error"); // shown as given (e.g. G1 with P₂ = P₃)
      pieces.error = null;
      const P = s.left;
      const Q = s.right;
      const { dLeft, dRight, ddLeft, ddRight } = d.joint;
      setText(cells["p3-p2"], pair(P[3][0] - P[2][0], P[3][1] - P[2][1]));
      setText(cells["q1-q0"], pair(Q[1][0] - Q[0][0], Q[1][1] - Q[0][1]));
      setText(cells.dp, pair(dLeft[0], dLeft[1]));
      setText(cells.dq, pair(dRight[0], dRight[1]));
      setText(cells.ddp, pair(ddLeft[0], ddLeft[1]));
      setText(cells.ddq, pair(ddRight[0], ddRight[1]));
    },
  };
}
