/**
 * Demo (syllabus §2, with the continuity checker of §1): joining two cubic Bézier pieces.
 * P lives on t ∈ [0, 1] and Q on t ∈ [1, 2]; a rule (none, C0, C1, G1, C2) is kept while the
 * points are dragged: the core's `joinBezier(left, right, rule, adjust)` moves the constrained
 * points of the other piece, and `jointContinuity(left, right)` reports what the joint really
 * is. Follows the reference demo (de-casteljau.js): the dragged piece is updated in place
 * (`setControlPoint`), the following piece is the one the core returns, and the picture is
 * drawn from core data only (samples, derivatives at the joint, the checker's verdict).
 */
import { Handles, placeLabel } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { group, el, radios, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkChoice } from "../lib/validate.js";
import { fmt, superscript } from "../lib/format.js";
import { HUES, WIDTH, RADIUS, FONT_SIZE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { pointsPath, flatPath, arrow, drawCaption } from "../lib/draw.js";

export const id = "joining";
/** Prefix of this demo's keys in strings.js. */
export const strings = "joining";
export const title = t("joining.title");
export const summary = t("joining.summary");
/** Syllabus section. */
export const section = 2;

/** The rules offered, in the order of the radio buttons ("none": nothing is enforced). */
export const RULES = Object.freeze(["none", "C0", "C1", "G1", "C2"]);

/**
 * Two cubics with integer points that meet C1 (Q₁ = 2P₃ − P₂ = (5, −1)) but not C2, so the
 * checker reads "C¹, G¹" at the start.
 */
export const defaultState = Object.freeze({
  left: Object.freeze([[0, 0], [1, 3], [3, 3], [4, 1]].map(Object.freeze)),
  right: Object.freeze([[4, 1], [5, -1], [7, 0], [8, 2]].map(Object.freeze)),
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
const LEFT_INTERVAL = [0, 1];
const RIGHT_INTERVAL = [1, 2];
/** The global parameter at the joint. */
const JOINT_T = 1;

// Styles of this demo's own marks (theme hues are the same in light and dark mode).
const RIGHT_CURVE_STYLE = Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.curve, join: "round", cap: "round" });
const LEFT_ARROW_STYLE = Object.freeze({ stroke: HUES.orange, width: 4, cap: "round", join: "round" });
const RIGHT_ARROW_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 2, cap: "round", join: "round" });
/** Arrow label styles per theme (their halo is the theme's background), made once per theme. */
const labelStyles = new WeakMap();
function arrowLabelStyles(theme) {
  let styles = labelStyles.get(theme);
  if (!styles) {
    styles = {
      left: Object.freeze({ fill: theme.name === "dark" ? HUES.orange : "#A86F00", size: FONT_SIZE.small, weight: "bold", halo: theme.background }),
      right: Object.freeze({ fill: HUES.reddishPurple, size: FONT_SIZE.small, weight: "bold", halo: theme.background }),
    };
    labelStyles.set(theme, styles);
  }
  return styles;
}
const MARK_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 1.5 });
const D_POINT_STYLE = Object.freeze({ fill: HUES.reddishPurple, radius: RADIUS.constructionPoint });

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["left", "right", "rule"]);
  checkPoints(state, "left", { min: POINTS_PER_PIECE, max: POINTS_PER_PIECE });
  checkPoints(state, "right", { min: POINTS_PER_PIECE, max: POINTS_PER_PIECE });
  checkChoice(state, "rule", RULES);
}

/** The two wasm pieces of a state: P on [0, 1], Q on [1, 2]. */
function buildPieces(sl, state) {
  const left = sl.BezierCurve.withInterval(flatten(state.left), 2, LEFT_INTERVAL[0], LEFT_INTERVAL[1]);
  try {
    const right = sl.BezierCurve.withInterval(flatten(state.right), 2, RIGHT_INTERVAL[0], RIGHT_INTERVAL[1]);
    return { left, right };
  } catch (err) {
    left.free();
    throw err;
  }
}

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
      return `\\text{G}^1:\\ Q_0 = P_n,\\ \\ Q_1 = Q_0 + \\lambda\\,(P_n - P_{n-1}),\\ \\lambda > 0\\ \\text{(${t("joining.formula.anyLength")})}`;
    case "C2":
      return "\\text{C}^2:\\ n(n-1)(P_n - 2P_{n-1} + P_{n-2}) = m(m-1)(Q_2 - 2Q_1 + Q_0) \\;\\Rightarrow\\; Q_2 = P_1 - 4P_2 + 4P_3";
    default:
      return `\\text{${t("joining.formula.none")}}`;
  }
}

/** A number as short text: integers without decimals, else 3 decimals. */
function short(v) {
  const r = Math.round(v);
  return Math.abs(v - r) < 1e-9 ? String(r) : fmt(v);
}

/** "(x, y)" with short numbers. */
function pair(x, y) {
  return `(${short(x)}, ${short(y)})`;
}

/** "C¹" / "C∞" for a continuity order. */
function order(letter, k) {
  return k === Infinity ? `${letter}∞` : `${letter}${superscript(k)}`;
}

/** TeX "C^{1}" / "C^{\infty}". */
function orderTex(letter, k) {
  return k === Infinity ? `\\text{${letter}}^{\\infty}` : `\\text{${letter}}^{${k}}`;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let { left, right } = buildPieces(sl, work);
  try {
    enforceIfBroken();
  } catch (err) {
    ctx.status(err.message, "error"); // shown as given (e.g. G1 with P₂ = P₃)
  }

  // Derived data, recomputed only when the geometry changed.
  let leftSamples = null;
  let rightSamples = null;
  let dLeft = null; // P′(1), P″(1)
  let dRight = null; // Q′(1), Q″(1)
  let ddLeft = null;
  let ddRight = null;
  let verdict = { c: 0, g: 0 };
  let verdictText = "";
  let dirty = true;
  const pointScratch = new Float64Array(2);
  const HANDLE_LABELS = ["P₀", "P₁", "P₂", "P₃", "Q₀", "Q₁", "Q₂", "Q₃"];
  const JOINT_LABEL = "P₃ = Q₀";
  const EMPTY_LABEL = "";
  const LEFT_ARROW_TEXT = t("joining.leftArrow");
  const RIGHT_ARROW_TEXT = t("joining.rightArrow");
  const D_LABEL = t("joining.pointD");
  const ARROW_CAPTION = t("joining.arrowCaption");

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.left.concat(work.right)) });
  const handles = new Handles(view, {
    count: () => 2 * POINTS_PER_PIECE,
    get: (i, out) => {
      const p = i < POINTS_PER_PIECE ? work.left[i] : work.right[i - POINTS_PER_PIECE];
      out[0] = p[0];
      out[1] = p[1];
    },
    label: (i) => {
      if (jointShared()) {
        if (i === POINTS_PER_PIECE - 1) return JOINT_LABEL;
        if (i === POINTS_PER_PIECE) return EMPTY_LABEL;
      }
      return HANDLE_LABELS[i];
    },
    move: (i, x, y) => movePoint(i, x, y),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    constraint: (i) => constraintOf(i),
  });

  // ------------------------------------------------------------ side panel
  const ruleRadios = radios({
    name: "rule",
    value: work.rule,
    options: RULES.map((rule) => ({ value: rule, label: t(`joining.rule.${rule}`) })),
    onChange: (rule) => setRule(rule),
  });
  const readout = el("p", { class: "sl-readout", dataset: { info: "verdict" }, "aria-live": "polite" });
  const legend = el("p", { class: "sl-note", dataset: { info: "legend" } });
  const freeText = el("p", { class: "sl-note", dataset: { info: "free" } });
  ctx.slots.controls.append(
    group(t("joining.ruleLegend"), ruleRadios.element),
    group(t("joining.checkerLegend"), readout, legend, freeText),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const rowKeys = ["p3-p2", "q1-q0", "dp", "dq", "ddp", "ddq"];
  const cells = {};
  const rows = rowKeys.map((key) => {
    cells[key] = el("td", { dataset: { vector: key } });
    return el("tr", {}, el("th", { scope: "row", text: t(`joining.row.${key}`) }), cells[key]);
  });
  const { title: tableTitle, wrap: tableWrap } = titledTable("joining", { caption: t("joining.tableCaption"), children: [el("tbody", {}, rows)] });
  ctx.slots.details.append(tableTitle, tableWrap);

  // ------------------------------------------------------------ edits

  /** True when P₃ and Q₀ are the same point (one handle on screen, one label). */
  function jointShared() {
    const a = work.left[POINTS_PER_PIECE - 1];
    const b = work.right[0];
    return a[0] === b[0] && a[1] === b[1];
  }

  /**
   * Which points the rule sets from the left piece (the syllabus form): Q₀ for every rule,
   * Q₁ for C1, G1 and C2, Q₂ for C2. They are marked with a square.
   */
  function ruleSets(i) {
    const k = i - POINTS_PER_PIECE;
    switch (work.rule) {
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

  /** G1: Q₁ may only slide along the tangent line P₂P₃ (its distance is the free choice). */
  function constraintOf(i) {
    if (work.rule !== "G1" || i !== POINTS_PER_PIECE + 1) return null;
    const p2 = work.left[POINTS_PER_PIECE - 2];
    const p3 = work.left[POINTS_PER_PIECE - 1];
    return [p2[0], p2[1], p3[0], p3[1]];
  }

  /**
   * Moves handle i (a preview during a drag or a nudge), then lets the core re-establish the
   * rule: a point of the left piece (or Q₃) makes the right piece follow ("right"); Q₀, Q₁ or
   * Q₂ make the left piece follow ("left"). Exception: G1's Q₁, already held on the tangent
   * line, keeps P₂ and is put back exactly on the ray at its new distance ("right").
   */
  function movePoint(i, x, y) {
    pointScratch[0] = x;
    pointScratch[1] = y;
    const onLeft = i < POINTS_PER_PIECE;
    const k = onLeft ? i : i - POINTS_PER_PIECE;
    (onLeft ? work.left : work.right)[k][0] = x;
    (onLeft ? work.left : work.right)[k][1] = y;
    (onLeft ? left : right).setControlPoint(k, pointScratch); // in place
    if (work.rule !== "none") {
      const g1Slide = work.rule === "G1" && i === POINTS_PER_PIECE + 1;
      const adjust = onLeft || k === POINTS_PER_PIECE - 1 || g1Slide ? "right" : "left";
      try {
        applyRule(adjust);
      } catch (err) {
        ctx.status(err.message, "error"); // e.g. G1 with P₂ = P₃: no tangent to follow
      }
    }
    dirty = true;
  }

  /**
   * `joinBezier` with the given side following: the following piece is replaced by the one the
   * core returns (the other returned copy is freed at once), and its points copied to `work`.
   */
  function applyRule(adjust) {
    const [l, r] = sl.joinBezier(left, right, work.rule, adjust);
    if (adjust === "right") {
      l.free();
      right.free();
      right = r;
      copyPoints(right, work.right);
    } else {
      r.free();
      left.free();
      left = l;
      copyPoints(left, work.left);
    }
  }

  /** Copies a curve's control points into a state's point list (same length). */
  function copyPoints(curve, points) {
    const flat = curve.controlPoints();
    for (let i = 0; i < points.length; i++) {
      points[i][0] = flat[2 * i];
      points[i][1] = flat[2 * i + 1];
    }
  }

  /**
   * For a state from outside (link, file, attributes): when its points break its rule, the
   * right piece is made to follow (the syllabus form). States recorded by this demo already
   * obey their rule and stay exactly as they are.
   */
  function enforceIfBroken() {
    if (work.rule === "none") return;
    if (satisfies(work.rule, sl.jointContinuity(left, right))) return;
    applyRule("right");
  }

  /** A rule chosen with the radio buttons: the right piece follows, then the change is recorded. */
  function setRule(rule) {
    const previous = work.rule;
    work.rule = rule;
    if (rule !== "none") {
      try {
        applyRule("right");
      } catch (err) {
        work.rule = previous;
        ruleRadios.set(previous);
        ctx.status(err.message, "error");
        return;
      }
    }
    dirty = true;
    view.requestDraw();
    ctx.commit(work);
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for samples, joint derivatives and the verdict when something changed. */
  function recompute() {
    if (!dirty) return;
    leftSamples = left.sampleUniform(CURVE_SAMPLES);
    rightSamples = right.sampleUniform(CURVE_SAMPLES);
    dLeft = left.derivative(JOINT_T, 1);
    dRight = right.derivative(JOINT_T, 1);
    ddLeft = left.derivative(JOINT_T, 2);
    ddRight = right.derivative(JOINT_T, 2);
    verdict = sl.jointContinuity(left, right);
    verdictText =
      verdict.c < 0
        ? t("joining.verdict.broken")
        : verdict.c === Infinity
          ? t("joining.verdict.infinite")
          : t("joining.verdict", { c: order("C", verdict.c), g: order("G", verdict.g) });
    dirty = false;
    syncPanels();
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const P = work.left;
    const Q = work.right;

    // Helper geometry of the rule: the tangent line P₂–P₃–Q₁ (C1, G1, C2) and for C2 the
    // A-frame P₁ → D = 2P₂ − P₁ → Q₂ (D = 2Q₁ − Q₂ exactly when the joint is C2).
    if (work.rule === "C1" || work.rule === "G1" || work.rule === "C2") {
      const ax = P[2][0];
      const ay = P[2][1];
      const bx = Q[1][0];
      const by = Q[1][1];
      r.beginPath();
      r.moveTo(v.sx(ax - (bx - ax) * TANGENT_LINE_OVERSHOOT), v.sy(ay - (by - ay) * TANGENT_LINE_OVERSHOOT));
      r.lineTo(v.sx(bx + (bx - ax) * TANGENT_LINE_OVERSHOOT), v.sy(by + (by - ay) * TANGENT_LINE_OVERSHOOT));
      r.paint(theme.helper);
    }
    if (work.rule === "C2") {
      const dx = 2 * P[2][0] - P[1][0];
      const dy = 2 * P[2][1] - P[1][1];
      r.beginPath();
      r.moveTo(v.sx(P[1][0]), v.sy(P[1][1]));
      r.lineTo(v.sx(dx), v.sy(dy));
      r.lineTo(v.sx(Q[2][0]), v.sy(Q[2][1]));
      r.paint(theme.helper);
      r.point(v.sx(dx), v.sy(dy), D_POINT_STYLE);
      placeLabel(r, D_LABEL, v.sx(dx), v.sy(dy), 0, -1, D_POINT_STYLE.radius * r.scale, theme.labelSmall);
    }

    // Control polygons.
    pointsPath(r, v, P);
    r.paint(theme.polygon);
    pointsPath(r, v, Q);
    r.paint(theme.polygon);

    // The two pieces: P blue, Q bluish green (and their labels tell them apart too).
    flatPath(r, v, leftSamples);
    r.paint(theme.curve);
    flatPath(r, v, rightSamples);
    r.paint(RIGHT_CURVE_STYLE);

    // Points the rule sets: a square around the handle.
    const half = MARK_HALF_PX * r.scale;
    for (let i = POINTS_PER_PIECE; i < 2 * POINTS_PER_PIECE; i++) {
      if (!ruleSets(i)) continue;
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
    const lx = dLeft[0] * ARROW_SCALE * v.scale;
    const ly = -dLeft[1] * ARROW_SCALE * v.scale;
    const rx = dRight[0] * ARROW_SCALE * v.scale;
    const ry = -dRight[1] * ARROW_SCALE * v.scale;
    arrow(r, jx - lx, jy - ly, jx, jy, LEFT_ARROW_STYLE);
    arrow(r, qx, qy, qx + rx, qy + ry, RIGHT_ARROW_STYLE);
    const labelStyle = arrowLabelStyles(theme);
    arrowLabel(r, LEFT_ARROW_TEXT, jx - lx / 2, jy - ly / 2, lx, ly, 1, labelStyle.left);
    arrowLabel(r, RIGHT_ARROW_TEXT, qx + rx / 2, qy + ry / 2, rx, ry, -1, labelStyle.right);

    handles.draw(r, v);

    // The checker's verdict, top left; what the arrows are, bottom left.
    const margin = TEXT_MARGIN_PX * r.scale;
    r.text(verdictText, margin, margin, theme.labelBold, "left", "top");
    drawCaption(r, ARROW_CAPTION, margin, v.height - margin, theme.labelSmall, v.width - 2 * margin, "bottom");
  }

  /**
   * Labels an arrow beside its middle: P′ on the arrow's left, Q′ on its right (so the two
   * labels never sit on top of each other when the arrows are collinear).
   */
  function arrowLabel(r, text, mx, my, dx, dy, side, style) {
    const length = Math.hypot(dx, dy);
    let nx = 0;
    let ny = -side;
    if (length >= 1) {
      nx = (side * dy) / length;
      ny = (-side * dx) / length;
    }
    placeLabel(r, text, mx, my, nx, ny, ARROW_LABEL_OFFSET_PX * r.scale, style);
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    const P = work.left;
    const Q = work.right;
    const { c, g } = verdict;
    const headline = verdictText;
    readout.textContent = headline;
    readout.dataset.c = String(c);
    readout.dataset.g = String(g);
    legend.textContent = t(`joining.legend.${work.rule}`);
    freeText.textContent = t(`joining.free.${work.rule}`);
    view.setLabel(
      t("joining.aria", {
        rule: t(`joining.rule.${work.rule}`),
        verdict: headline,
        dp: pair(dLeft[0], dLeft[1]),
        dq: pair(dRight[0], dRight[1]),
      }),
    );

    // Table: the differences the rules compare, and the core's derivatives at the joint.
    setText(cells["p3-p2"], pair(P[3][0] - P[2][0], P[3][1] - P[2][1]));
    setText(cells["q1-q0"], pair(Q[1][0] - Q[0][0], Q[1][1] - Q[0][1]));
    setText(cells.dp, pair(dLeft[0], dLeft[1]));
    setText(cells.dq, pair(dRight[0], dRight[1]));
    setText(cells.ddp, pair(ddLeft[0], ddLeft[1]));
    setText(cells.ddq, pair(ddRight[0], ddRight[1]));

    // Formula panel: the rule (syllabus form), then each condition with the numbers; "=" or
    // "≠" as the checker found it.
    const rel = (holds) => (holds ? "\\;=\\;" : "\\;\\neq\\;");
    const tex = (x, y) => `(${short(x)},\\ ${short(y)})`.replace(/-/g, "{-}");
    const n = DEGREE;
    const lines = [`\\text{${t("joining.formula.rule")}}\\quad ${ruleTex(work.rule)}`];
    lines.push(`\\text{C}^0:\\ P_{${n}} = ${tex(P[3][0], P[3][1])} ${rel(c >= 0)} Q_0 = ${tex(Q[0][0], Q[0][1])}`);
    lines.push(`\\text{C}^1:\\ ${n}(P_{${n}} - P_{${n - 1}}) = ${tex(dLeft[0], dLeft[1])} ${rel(c >= 1)} ${n}(Q_1 - Q_0) = ${tex(dRight[0], dRight[1])}`);
    lines.push(
      `\\text{C}^2:\\ ${n * (n - 1)}(P_{${n}} - 2P_{${n - 1}} + P_{${n - 2}}) = ${tex(ddLeft[0], ddLeft[1])} ${rel(c >= 2)} ${n * (n - 1)}(Q_2 - 2Q_1 + Q_0) = ${tex(ddRight[0], ddRight[1])}`,
    );
    if (c >= 0 && g >= 1) {
      const lambda = Math.hypot(dRight[0], dRight[1]) / Math.hypot(dLeft[0], dLeft[1]);
      lines.push(`\\text{G}^1:\\ Q_1 - Q_0 = \\lambda\\,(P_{${n}} - P_{${n - 1}}),\\quad \\lambda = \\frac{|Q'(1)|}{|P'(1)|} = ${fmt(lambda)} > 0`);
    } else {
      lines.push(`\\text{G}^1:\\ \\text{${t("joining.formula.notG1")}}`);
    }
    lines.push(`\\text{${t("joining.formula.checker")}}\\ ${c < 0 ? `\\text{${t("joining.formula.notC0")}}` : `${orderTex("C", c)},\\ ${orderTex("G", g)}`}`);
    formula.set(lines);
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = buildPieces(sl, state); // throws before anything changes
      const oldLeft = left;
      const oldRight = right;
      const oldWork = work;
      left = next.left;
      right = next.right;
      work = structuredClone(state);
      try {
        enforceIfBroken();
      } catch (err) {
        left.free();
        right.free();
        left = oldLeft;
        right = oldRight;
        work = oldWork;
        throw err;
      }
      oldLeft.free();
      oldRight.free();
      handles.forgetPointer();
      ruleRadios.set(work.rule);
      dirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      left.free();
      right.free();
    },
  };
}
