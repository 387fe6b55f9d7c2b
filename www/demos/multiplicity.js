/**
 * Demo (syllabus §3): multiplicity and continuity. A cubic B-spline over the knot ruler
 * (lib/knot-ruler.js). Raising the multiplicity r of a knot (double click / Enter on the ruler,
 * or the buttons) lowers the continuity there to C^{3−r}: C², C¹, C⁰ — the curve runs through a
 * control point with a corner — and at r = 4 it breaks. Repeating a control point 1, 2 or 3
 * times pulls the curve to it instead: the parametric continuity stays C², the geometric one
 * drops (a triple point: zero velocity, a corner, G⁰). The Croatian notes' table is shown with
 * the current cases highlighted, next to what the core measures.
 *
 * Measured continuity: the curve's `toBezier()` segments are placed on their spans with
 * `BezierCurve.withInterval(points, 2, a, b)` and each joint is checked with
 * `jointContinuity(left, right)` → `{ c, g }`; the guaranteed value is `knotContinuity()`.
 * A point drag goes through `setControlPoint` (every copy of a repeated point).
 *
 * Keeping the knot vector valid: changing how often a point is repeated changes the number of
 * control points, so the knots are replaced by the core's clamped uniform vector for the new
 * count (`knotVector(points, 2, 3, "clamped")`); knot multiplicities start again from 1.
 */
import { field, checkNumber } from "../lib/validate.js";
import { readout, actions, group } from "../lib/panel.js";
import { knotRuler, stackOf, knotText } from "../lib/knot-ruler.js";
import { knotsField, clampedKnots, setKnots, domainOf } from "../lib/bspline.js";
import { radios, el } from "../lib/controls.js";
import { clauseSeparator, subscript, pointTex } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { measuredJoints } from "../lib/joint-continuity.js";
import { JointsTable } from "../lib/joints-table.js";
import { continuityText, measuredText } from "../lib/continuity.js";
import { knotListText, knotNames } from "../lib/knot-readout.js";
import { pointsPath } from "../lib/draw.js";
import { replaceOrReport } from "../lib/wasm.js";

export const id = "multiplicity";
export const strings = "multiplicity";
export const section = 3;

/** The degree: the notes' table is for cubics. */
const P = 3;

/**
 * A cubic with eight control points and clamped uniform knots on [0, 5]: four interior knots,
 * enough to merge one of them up to multiplicity 4 (a break between two Bézier pieces).
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [1, 3],
      [3, 4],
      [4, 1],
      [6, 4],
      [7, 1],
      [9, 3],
      [10, 0],
    ].map(Object.freeze),
  ),
  knots: Object.freeze([0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5]),
  repeatPoint: 4,
  repeatTimes: 1,
});

/** Fewest and most (distinct) control points; a point is repeated at most this often. */
export const MIN_POINTS = 4;
export const MAX_POINTS = 10;
export const MAX_REPEAT = 3;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 301;
/** Two points closer than this (relative) count as the same (the curve "passes through" P_j). */
const SAME_POINT = 1e-9;

/** The notes' table (002): rows multiplicity 1–4; columns control points, knots. */
const NOTES_TABLE = Object.freeze([
  Object.freeze(["C²G²", "C²G²"]),
  Object.freeze(["C²G¹", "C¹G¹"]),
  Object.freeze(["C²G⁰", "C⁰G⁰"]),
  Object.freeze(["C²G⁰", "break"]),
]);

/** Control points of the curve: the distinct ones, the repeated one `repeatTimes` times. */
const curveCount = (s) => s.points.length + s.repeatTimes - 1;

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  repeatPoint: (s, name) =>
    checkNumber(s, name, { min: 0, max: s.points.length - 1, integer: true }),
  repeatTimes: field.number({ min: 1, max: MAX_REPEAT, integer: true }),
  knots: knotsField({ count: curveCount, degree: () => P }),
};

/** Index in the curve's control points of the first copy of base point j. */
function expandedIndex(state, j) {
  return j <= state.repeatPoint ? j : j + state.repeatTimes - 1;
}

/** Flat Float64Array of the curve's control points: base points with the repeated one repeated. */
function expandedPoints(state) {
  const flat = new Float64Array(curveCount(state) * 2);
  let k = 0;
  state.points.forEach(([x, y], j) => {
    const copies = j === state.repeatPoint ? state.repeatTimes : 1;
    for (let c = 0; c < copies; c++, k++) {
      flat[2 * k] = x;
      flat[2 * k + 1] = y;
    }
  });
  return flat;
}

/** The curve on the repeated points, in wasm; a dragged point moves all its copies in place. */
export const derive = {
  from: ["points", "knots", "repeatPoint", "repeatTimes"],
  build: (s, sl) => ({
    curve: new sl.BSplineCurve(expandedPoints(s), 2, P, Float64Array.from(s.knots)),
  }),
  moved(m, i, xy, s) {
    const copies = i === s.repeatPoint ? s.repeatTimes : 1;
    for (let c = 0; c < copies; c++) m.curve.setControlPoint(expandedIndex(s, i) + c, xy);
  },
};

const SHAPE = ["points", "knots", "repeatPoint", "repeatTimes"];
/** What the core returns: samples, guaranteed continuity, measured joints; the knot studied. */
export const compute = {
  samples: [SHAPE, (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  continuity: [["knots", "repeatPoint", "repeatTimes"], (s, d) => d.curve.knotContinuity()],
  joints: [SHAPE, (s, d) => measure(s, d)],
  names: [["points", "repeatPoint", "repeatTimes"], (s) => s.points.map((_, j) => pointName(s, j))],
  // "selection": the ruler's or the handles' selection changed (touched by the demo's setup).
  studied: [[...SHAPE, "selection"], (s, d) => findStudied(s, d)],
};

/**
 * The measured continuity at every distinct interior knot: Bézier segments from `toBezier()`
 * placed on their spans, compared pairwise with `jointContinuity` (lib/joint-continuity.js).
 */
function measure(s, d) {
  const label = (u) => t("multiplicity.jointLabel", { u: knotText(u) });
  return measuredJoints(d.sl, d.curve, s.knots, label);
}

const jointAt = (d, u) => d.joints.find((j) => j.knot === u) ?? null;

/**
 * The knot the panels talk about: the selected knot when it is interior; else the interior
 * knot of highest multiplicity (nearest the middle of the domain on a tie). And the knot
 * nearest the repeated point: u_k with k = j + p − ⌊(p − r)/2⌋ for copies P_j … P_{j+r−1}
 * (its value depends on P_{k−p} … P_{k−1}, which then hold the copies as centrally as possible).
 */
function findStudied(s, d) {
  const knots = s.knots;
  const n = knots.length - P - 2;
  const [lo, hi] = domainOf(knots, P);
  const interior = (i) => i > P && i <= n && knots[i] > lo && knots[i] < hi;
  const selected = d.ruler?.selected ?? -1;
  let pick = interior(selected) ? selected : -1;
  if (pick < 0) {
    const middle = (lo + hi) / 2;
    let bestR = 0;
    let bestD = Infinity;
    for (let i = P + 1; i <= n; i++) {
      if (!interior(i) || knots[i] === knots[i - 1]) continue;
      const [a, b] = stackOf(knots, i);
      const dist = Math.abs(knots[i] - middle);
      if (b - a + 1 > bestR || (b - a + 1 === bestR && dist < bestD - 1e-12)) {
        bestR = b - a + 1;
        bestD = dist;
        pick = i;
      }
    }
  }
  let knot = null;
  if (pick >= 0) {
    const [a, b] = stackOf(knots, pick);
    const joint = jointAt(d, knots[pick]);
    const through = passesThrough(s, joint);
    const u = knotText(knots[pick]);
    const label = through
      ? t("multiplicity.throughLabel", { u, point: through })
      : t("multiplicity.pointLabel", { u });
    knot = { a, b, value: knots[pick], r: b - a + 1, joint, through, label };
  }
  let repeat = null;
  if (s.repeatTimes > 1) {
    const k = expandedIndex(s, s.repeatPoint) + P - Math.floor((P - s.repeatTimes) / 2);
    if (interior(k)) repeat = { k, joint: jointAt(d, knots[k]) };
  }
  return { knot, repeat };
}

/** "P₄" when the curve at the joint (right piece) equals a control point, else "". */
function passesThrough(s, jt) {
  if (!jt || jt.c < 0) return "";
  const flat = expandedPoints(s);
  const scale = 1 + Math.hypot(jt.right[0], jt.right[1]);
  for (let i = 0; i < flat.length / 2; i++) {
    const gap = Math.hypot(flat[2 * i] - jt.right[0], flat[2 * i + 1] - jt.right[1]);
    if (gap <= SAME_POINT * scale) return `P${subscript(i)}`;
  }
  return "";
}

/** "P₄", or "P₄ = P₅ = P₆" for the repeated point. */
function pointName(s, j) {
  const copies = j === s.repeatPoint ? s.repeatTimes : 1;
  const names = [];
  for (let c = 0; c < copies; c++) names.push(`P${subscript(expandedIndex(s, j) + c)}`);
  return names.join(" = ");
}

/** The knots, replaced by the core's clamped uniform vector for the state's repeated points. */
const uniformKnots = (ui, s) => clampedKnots(ui.sl, expandedPoints(s), P);
const RULER = { count: curveCount, degree: () => P, param: null };

/** The repetition radios: the selected point (else the last repeated one) `k` times, clamped uniform knots. */
const repeatChoice = {
  build(ui) {
    const control = radios({
      name: "repeat",
      value: String(ui.state.repeatTimes),
      options: [1, 2, 3].map((k) => ({
        value: String(k),
        label: t("multiplicity.repeatOption", { k }),
      })),
      onChange(value) {
        const s = ui.state;
        const j = ui.handles.selected >= 0 ? ui.handles.selected : s.repeatPoint;
        if (Number(value) === s.repeatTimes && j === s.repeatPoint) return;
        const next = { ...s, repeatPoint: j, repeatTimes: Number(value) };
        if (replaceOrReport(ui, { ...next, knots: uniformKnots(ui, next) })) {
          ui.data.ruler.forgetPointer();
          ui.data.ruler.select(-1);
        }
        control.set(String(ui.state.repeatTimes));
      },
    });
    control.element.classList.add("sl-button-row");
    return { element: control.element, sync: (s) => control.set(String(s.repeatTimes)) };
  },
};

export const controls = [
  knotRuler("knots", {
    ...RULER,
    refused: (error) => t(`multiplicity.multiplicity.${error}`, { max: P + 1 }),
    select: (ui) => ui.touch("selection"),
  }),
  group(
    "multiplicity.knotLegend",
    readout(
      "knot",
      (s, d) => {
        const k = d.studied.knot;
        if (!k) return t("multiplicity.noKnot");
        const guaranteed = continuityText(P - k.r < 0 ? -1 : P - k.r);
        const names = knotNames(k.a, k.b);
        const measured = measuredText(k.joint);
        return t("multiplicity.knotReadout", {
          names,
          u: knotText(k.value),
          r: k.r,
          guaranteed,
          measured,
        });
      },
      { kind: "readout" },
    ),
    readout("knot-note", (s, d) => {
      const k = d.studied.knot;
      if (!k?.through) return t("multiplicity.knotHint");
      return t("multiplicity.through", { u: knotText(k.value), point: k.through });
    }),
    actions([
      {
        name: "raise",
        label: "multiplicity.raise",
        title: "multiplicity.raise.title",
        disabled: (s, d) => !d.studied.knot || d.studied.knot.r >= P + 1,
        run: (ui) => ui.data.studied.knot && ui.data.ruler.source.raise(ui.data.studied.knot.b),
      },
      {
        name: "lower",
        label: "multiplicity.lower",
        title: "multiplicity.lower.title",
        disabled: (s, d) => !d.studied.knot || d.studied.knot.r <= 1,
        run: (ui) => ui.data.studied.knot && ui.data.ruler.source.lower(ui.data.studied.knot.b),
      },
      {
        name: "reset-knots",
        label: "multiplicity.resetKnots",
        title: "multiplicity.resetKnots.title",
        run: (ui) =>
          setKnots(ui, uniformKnots(ui, ui.state), true, RULER) && ui.data.ruler.forgetPointer(),
      },
    ]),
  ),
  group(
    "multiplicity.repeatLegend",
    repeatChoice,
    readout("repeat", (s, d) => {
      const points = d.names[s.repeatPoint];
      const rep = d.studied.repeat;
      if (s.repeatTimes === 1) return t("multiplicity.repeatNone", { point: points });
      if (!rep) return t("multiplicity.repeatEnd", { points });
      const u = knotText(s.knots[rep.k]);
      return t("multiplicity.repeatReadout", {
        points,
        k: subscript(rep.k),
        u,
        measured: measuredText(rep.joint),
      });
    }),
    readout("repeat-note", () => t("multiplicity.repeatHint")),
  ),
];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  handles: { field: "points" },
};

/** True when curve sample k starts a new piece (the curve breaks between samples k − 1 and k). */
function jumps(s, d, k) {
  for (const joint of d.joints) {
    if (joint.c >= 0) continue;
    const a = s.knots[P];
    const b = s.knots[s.knots.length - P - 1];
    const u = a + (k / (CURVE_SAMPLES - 1)) * (b - a);
    const u0 = a + ((k - 1) / (CURVE_SAMPLES - 1)) * (b - a);
    if (u0 < joint.knot && u >= joint.knot) return true;
  }
  return false;
}

/** The distinct points' polygon, the curve (not joined at a break), the joints, the ruler. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  r.beginPath();
  for (let k = 0; k < CURVE_SAMPLES; k++) {
    const x = v.sx(d.samples[2 * k]);
    const y = v.sy(d.samples[2 * k + 1]);
    if (k === 0 || jumps(s, d, k)) r.moveTo(x, y);
    else r.lineTo(x, y);
  }
  r.paint(theme.curve);

  // The joints: a small dot at every interior knot, the studied one (and its gap) in vermillion.
  const studied = d.studied.knot;
  for (const jt of d.joints) {
    r.point(v.sx(jt.right[0]), v.sy(jt.right[1]), theme.levelPoint[1]);
    if (jt === studied?.joint) continue;
    const offset = 6 * r.scale;
    r.text(
      jt.label,
      v.sx(jt.right[0]) + offset,
      v.sy(jt.right[1]) + offset,
      theme.labelSmall,
      "left",
      "top",
    );
  }
  d.handles.draw(r, v);
  if (studied?.joint) {
    const jt = studied.joint;
    const rx = v.sx(jt.right[0]);
    const ry = v.sy(jt.right[1]);
    if (jt.c < 0) {
      r.beginPath();
      r.moveTo(v.sx(jt.left[0]), v.sy(jt.left[1]));
      r.lineTo(rx, ry);
      r.paint(theme.helper);
      r.point(v.sx(jt.left[0]), v.sy(jt.left[1]), theme.pointOnCurve);
    }
    r.point(rx, ry, theme.pointOnCurve);
    r.text(studied.label, rx, ry + 12 * r.scale, theme.labelPoint, "center", "top");
  }
  d.ruler.atBottom(r.width, r.height, r.scale);
  d.ruler.draw(r);
}

/** "₁₂" → "12". */
function fromSubscript(text) {
  return text.replace(/[₀-₉]/g, (c) => String(c.charCodeAt(0) - 0x2080));
}

/** C(u) = Σ N_{i,3} P_i and the rule; the studied knot: r, guaranteed and measured; the repeated point's speed. */
export function formula(s, d) {
  const n = s.knots.length - P - 2;
  const measuredWord = `\\text{${t("multiplicity.formulaMeasured")}}`;
  const general = `\\text{${t("multiplicity.formulaRule")}}\\ r:\\ C^{\\,3-r}`;
  const lines = [`C(u) = \\sum_{i=0}^{${n}} N_{i,3}(u)\\,P_i,\\qquad ${general}`];
  const cTex = (jt) => `C^{${jt.c === Infinity ? "\\infty" : jt.c}},\\ G^{${jt.g}}`;
  const k = d.studied.knot;
  if (k) {
    const g = P - k.r;
    const idx = [];
    for (let i = k.a; i <= k.b; i++) idx.push(`u_{${i}}`);
    const jt = k.joint;
    const measured = jt ? (jt.c < 0 ? `\\text{${t("knotRuler.break")}}` : cTex(jt)) : "";
    const through = k.through
      ? ` = ${k.through.replace(/P(\S+)/, (m) => `P_{${fromSubscript(m.slice(1))}}`)}`
      : "";
    const at = jt
      ? `C(${knotText(k.value, true)}) = ${pointTex([jt.right[0], jt.right[1]])}${through}`
      : "";
    const value = jt && jt.c >= 0 ? `,\\quad ${at}` : "";
    const rule = g < 0 ? `\\text{${t("multiplicity.formulaBreak")}}` : `C^{3-${k.r}} = C^{${g}}`;
    const head = `${idx.join(" = ")} = ${knotText(k.value, true)}:\\quad r = ${k.r}`;
    lines.push(`${head} \\;\\Rightarrow\\; ${rule};\\quad ${measuredWord}\\ ${measured}${value}`);
  }
  const rep = d.studied.repeat;
  if (s.repeatTimes > 1 && rep?.joint) {
    const jt = rep.joint;
    const names = d.names[s.repeatPoint].replace(
      /P([₀-₉]+)/g,
      (m, sub) => `P_{${fromSubscript(sub)}}`,
    );
    const speed = `C'(u_{${rep.k}}) = ${pointTex([jt.speed[0], jt.speed[1]])}`;
    lines.push(`${names}:\\quad ${speed},\\quad ${measuredWord}\\ ${cTex(jt)}`);
  }
  return lines;
}

/** The knots, each interior knot's continuity (guaranteed, measured), the repetition. */
export function label(s, d) {
  const entry = (e) => {
    const measured = measuredText(jointAt(d, e.knot));
    return `${knotText(e.knot)} (×${e.multiplicity}): ${continuityText(e.continuity)}, ${measured}`;
  };
  const list = d.continuity.map(entry).join(clauseSeparator());
  const k = d.studied.knot;
  const rep = d.studied.repeat;
  return t("multiplicity.aria", {
    count: s.knots.length - P - 1,
    knots: knotListText(s.knots),
    list,
    repeat:
      s.repeatTimes > 1
        ? t("multiplicity.ariaRepeat", {
            points: d.names[s.repeatPoint],
            measured: measuredText(rep?.joint),
          })
        : "",
    through: k?.through
      ? t("multiplicity.ariaThrough", { u: knotText(k.value), point: k.through })
      : "",
  });
}

/**
 * The handles' names (repeated points), a selection hook, the notes' table with the current
 * cases highlighted and the table of every distinct interior knot.
 */
export function setup(ui) {
  const source = ui.handles.source;
  source.label = (i) => ui.data.names[i];
  const selectPoint = source.select;
  source.select = (i) => {
    selectPoint?.(i);
    ui.touch("selection");
  };
  const notesCells = [];
  const notesRows = NOTES_TABLE.map((row, k) => {
    const cells = row.map((text, column) =>
      el("td", {
        dataset: { column: column === 0 ? "points" : "knots", multiplicity: String(k + 1) },
        text: column === 1 && k === 3 ? t("multiplicity.notesBreak") : text,
      }),
    );
    notesCells.push(cells);
    const head = el("th", { scope: "row", text: String(k + 1) });
    return el("tr", { dataset: { multiplicity: String(k + 1) } }, head, cells);
  });
  const column = (key) => el("th", { scope: "col", text: t(`multiplicity.${key}`) });
  const columns = (...keys) => el("tr", {}, keys.map(column));
  const notes = titledTable("notes", {
    caption: t("multiplicity.notesCaption"),
    children: [
      el("thead", {}, columns("colMultiplicity", "colPoints", "colKnots")),
      el("tbody", {}, notesRows),
    ],
  });
  const knotsTable = new JointsTable(strings);
  ui.ctx.slots.details.append(notes.title, notes.wrap, knotsTable.title, knotsTable.wrap);

  return {
    update(s, d) {
      const studied = d.studied.knot;
      const knotRow = studied ? Math.min(studied.r, 4) : 0;
      for (let k = 0; k < 4; k++) {
        notesCells[k][0].classList.toggle(
          "sl-highlight",
          s.repeatTimes > 1 && k + 1 === s.repeatTimes,
        );
        notesCells[k][1].classList.toggle("sl-highlight", k + 1 === knotRow);
      }
      const jointOf = (u) => jointAt(d, u);
      const through = (jt) => passesThrough(s, jt);
      knotsTable.show(s.knots, d.continuity, jointOf, through, studied?.value);
    },
  };
}
