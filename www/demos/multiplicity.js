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
 * Same habits as the reference demo: a point drag goes through `setControlPoint` (every copy of
 * a repeated point), knot changes rebuild the curve (the old one is freed), the draw path
 * allocates nothing.
 *
 * Keeping the knot vector valid: changing how often a point is repeated changes the number of
 * control points, so the knots are replaced by the core's clamped uniform vector for the new
 * count (`knotVector(points, 2, 3, "clamped")`); knot multiplicities start again from 1.
 */
import { Handles, pointHandles } from "../lib/handles.js";
import { KnotRuler, raiseMultiplicity, lowerMultiplicity, stackOf, knotText } from "../lib/knot-ruler.js";
import { FormulaPanel } from "../lib/formula.js";
import { button, group, el, radios, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkNumbers } from "../lib/validate.js";
import { fmt, subscript, superscript } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { pointsPath } from "../lib/draw.js";
import { buildOrReport } from "../lib/wasm.js";

export const id = "multiplicity";
/** Prefix of this demo's keys in strings.js. */
export const strings = "multiplicity";
export const title = t("multiplicity.title");
export const summary = t("multiplicity.summary");
/** Syllabus section. */
export const section = 3;

/** The degree: the notes' table is for cubics. */
const P = 3;

/**
 * A cubic with eight control points and clamped uniform knots on [0, 5]: four interior knots,
 * enough to merge one of them up to multiplicity 4 (a break between two Bézier pieces).
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [1, 3], [3, 4], [4, 1], [6, 4], [7, 1], [9, 3], [10, 0]].map(Object.freeze)),
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

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "knots", "repeatPoint", "repeatTimes"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "repeatPoint", { min: 0, max: state.points.length - 1, integer: true });
  checkNumber(state, "repeatTimes", { min: 1, max: MAX_REPEAT, integer: true });
  checkNumbers(state, "knots");
  const count = state.points.length + state.repeatTimes - 1;
  const need = count + P + 1;
  if (state.knots.length !== need) throw new Error(t("multiplicity.knotCount", { count, need, got: state.knots.length }));
  for (let i = 1; i < need; i++) {
    if (state.knots[i] < state.knots[i - 1]) throw new Error(t("multiplicity.knotOrder", { i: i - 1, a: state.knots[i - 1], j: i, b: state.knots[i] }));
  }
}

/** Index in the curve's control points of the first copy of base point j. */
function expandedIndex(state, j) {
  return j <= state.repeatPoint ? j : j + state.repeatTimes - 1;
}

/** Flat Float64Array of the curve's control points: base points with the repeated one repeated. */
function expandedPoints(state) {
  const count = state.points.length + state.repeatTimes - 1;
  const flat = new Float64Array(count * 2);
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

/** "C²", "C⁰", "C∞", or the break word for continuity k (−1). */
function continuityText(k) {
  if (k === Infinity) return "C∞";
  return k < 0 ? t("knotRuler.break") : `C${superscript(k)}`;
}

/** "G²" … ("—" when the pieces do not meet). */
function geometricText(g, c) {
  return c < 0 ? "—" : `G${superscript(g)}`;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = build(work);

  // Derived data, recomputed when the knots or the geometry changed.
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let continuity = null; // curve.knotContinuity(): guaranteed C^{p−r} per distinct interior knot
  let joints = []; // measured per distinct interior knot: { knot, c, g, left: [x, y], right: [x, y] }
  let knotsDirty = true;
  let geometryDirty = true;
  const insetScratch = [0, 0, 0, 0];
  const domainScratch = [0, 1];
  let handleLabels = []; // "P₄ = P₅ = P₆" …, rebuilt when the repetition changes
  let studied = null; // { a, b, value, r, joint } the knot the panels talk about
  let repeatJoint = null; // { k, joint } the knot nearest the repeated point
  let studiedLabel = ""; // "C(2) = P₄" …
  let shownKey = ""; // what the panels show (knot index / selection), to resync on selection changes

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets });

  // The knot ruler, before the handles: its band is its own.
  const ruler = new KnotRuler(view, {
    knots: () => work.knots,
    degree: () => P,
    continuity: () => continuity,
    move: (i, u) => moveKnot(i, u),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    raise: (i) => changeMultiplicity(raiseMultiplicity(work.knots, i, P)),
    lower: (i) => changeMultiplicity(lowerMultiplicity(work.knots, i)),
    select: () => view.requestDraw(),
  });

  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      const first = expandedIndex(work, i);
      const copies = i === work.repeatPoint ? work.repeatTimes : 1;
      for (let c = 0; c < copies; c++) curve.setControlPoint(first + c, xy); // in place
      geometryDirty = true;
    }, (i) => (handleLabels[i] ??= pointName(i))),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    select: (i) => i >= 0 && ruler.select(-1),
  });
  ruler.source.handles = handles;

  /** The ruler's band below the world window: [top, right, bottom, left] (scratch). */
  function insets(width, height, scale) {
    insetScratch[2] = ruler.height(scale);
    return insetScratch;
  }

  /** "P₄", or "P₄ = P₅ = P₆" for the repeated point. */
  function pointName(j) {
    const first = expandedIndex(work, j);
    const copies = j === work.repeatPoint ? work.repeatTimes : 1;
    const names = [];
    for (let c = 0; c < copies; c++) names.push(`P${subscript(first + c)}`);
    return names.join(" = ");
  }

  // ------------------------------------------------------------ side panel
  const knotReadout = el("p", { class: "sl-readout", dataset: { info: "knot" } });
  const knotNote = el("p", { class: "sl-note", dataset: { info: "knot-note" } });
  const raiseButton = button({ label: t("multiplicity.raise"), title: t("multiplicity.raise.title"), name: "raise", onClick: () => studied && changeMultiplicity(raiseMultiplicity(work.knots, studied.b, P)) });
  const lowerButton = button({ label: t("multiplicity.lower"), title: t("multiplicity.lower.title"), name: "lower", onClick: () => studied && changeMultiplicity(lowerMultiplicity(work.knots, studied.b)) });
  const resetKnotsButton = button({ label: t("multiplicity.resetKnots"), title: t("multiplicity.resetKnots.title"), name: "reset-knots", onClick: () => resetKnots() });
  const repeatRadios = radios({
    name: "repeat",
    value: String(work.repeatTimes),
    options: [1, 2, 3].map((k) => ({ value: String(k), label: t("multiplicity.repeatOption", { k }) })),
    onChange: (value) => setRepeat(Number(value)),
  });
  repeatRadios.element.classList.add("sl-button-row");
  const repeatReadout = el("p", { class: "sl-note", dataset: { info: "repeat" } });
  const repeatNote = el("p", { class: "sl-note", dataset: { info: "repeat-note" } });
  ctx.slots.controls.append(
    group(t("multiplicity.knotLegend"), knotReadout, knotNote, el("div", { class: "sl-button-row" }, raiseButton, lowerButton, resetKnotsButton)),
    group(t("multiplicity.repeatLegend"), repeatRadios.element, repeatReadout, repeatNote),
  );

  // ------------------------------------------------------------ formula and tables
  const formula = new FormulaPanel(ctx.slots.formula);
  const notesCells = [];
  const notesRows = NOTES_TABLE.map((row, k) => {
    const cells = row.map((text, column) => el("td", { dataset: { column: column === 0 ? "points" : "knots", multiplicity: String(k + 1) }, text: column === 1 && k === 3 ? t("multiplicity.notesBreak") : text }));
    notesCells.push(cells);
    return el("tr", { dataset: { multiplicity: String(k + 1) } }, el("th", { scope: "row", text: String(k + 1) }), cells);
  });
  const notes = titledTable("notes", {
    caption: t("multiplicity.notesCaption"),
    children: [
      el("thead", {}, el("tr", {},
        el("th", { scope: "col", text: t("multiplicity.colMultiplicity") }),
        el("th", { scope: "col", text: t("multiplicity.colPoints") }),
        el("th", { scope: "col", text: t("multiplicity.colKnots") }))),
      el("tbody", {}, notesRows),
    ],
  });
  const { title: knotsTitle, table: knotsTable, wrap: knotsTableWrap } = titledTable("knots", { caption: t("multiplicity.knotsCaption") });
  ctx.slots.details.append(notes.title, notes.wrap, knotsTitle, knotsTableWrap);

  // ------------------------------------------------------------ edits

  /** A new wasm curve for a state (throws on invalid input). */
  function build(state) {
    return new sl.BSplineCurve(expandedPoints(state), 2, P, Float64Array.from(state.knots));
  }

  /** Replaces the curve after the knots or the repetition changed; false (and a message) if refused. */
  function rebuild() {
    const next = buildOrReport(() => build(work), ctx);
    if (!next) return false;
    curve.free();
    curve = next;
    knotsDirty = true;
    view.requestDraw();
    return true;
  }

  function moveKnot(i, u) {
    const old = work.knots[i];
    work.knots[i] = u;
    if (!rebuild()) work.knots[i] = old;
  }

  /** Applies a raised/lowered knot vector (from knot-ruler.js) or reports why not. */
  function changeMultiplicity(result) {
    if (result.error) {
      ctx.status(t(`multiplicity.multiplicity.${result.error}`, { max: P + 1 }), "error");
      return;
    }
    const old = work.knots;
    work.knots = result.knots;
    if (!rebuild()) {
      work.knots = old;
      return;
    }
    ruler.select(result.index);
    ctx.commit(work);
  }

  function clampedKnots() {
    return Array.from(sl.knotVector(expandedPoints(work), 2, P, "clamped"));
  }

  function resetKnots() {
    work.knots = clampedKnots();
    if (rebuild()) {
      ruler.forgetPointer();
      ctx.commit(work);
    }
  }

  /** Repeats the selected control point (else the last repeated one) `times` times; the knots become clamped uniform. */
  function setRepeat(times) {
    const j = handles.selected >= 0 ? handles.selected : work.repeatPoint;
    if (times === work.repeatTimes && j === work.repeatPoint) return;
    const old = { repeatPoint: work.repeatPoint, repeatTimes: work.repeatTimes, knots: work.knots };
    work.repeatPoint = j;
    work.repeatTimes = times;
    work.knots = clampedKnots();
    if (!rebuild()) {
      Object.assign(work, old);
      repeatRadios.set(String(work.repeatTimes));
      return;
    }
    handleLabels = [];
    ruler.forgetPointer();
    ruler.select(-1);
    ctx.commit(work);
  }

  // ------------------------------------------------------------ core data
  /** Asks the core for the samples, the guaranteed and the measured continuity when something changed. */
  function recompute() {
    let changed = false;
    if (knotsDirty) {
      continuity = curve.knotContinuity();
      geometryDirty = true;
    }
    if (geometryDirty) {
      samples = curve.sampleUniform(CURVE_SAMPLES);
      measure();
      changed = true;
    }
    knotsDirty = geometryDirty = false;
    const key = `${ruler.selected}/${handles.selected}`;
    if (changed || key !== shownKey) {
      shownKey = key;
      findStudied();
      syncPanels();
    }
  }

  /**
   * The measured continuity at every distinct interior knot: Bézier segments from `toBezier()`
   * placed on their spans, compared pairwise with `jointContinuity`.
   */
  function measure() {
    const knots = work.knots;
    const pieces = curve.toBezier();
    const spans = curve.spans(); // span index k of each segment: [u_k, u_{k+1}]
    const placed = [];
    for (let s = 0; s < pieces.length; s++) {
      const k = spans[s];
      placed.push(sl.BezierCurve.withInterval(pieces[s].controlPoints(), 2, knots[k], knots[k + 1]));
      pieces[s].free();
    }
    joints = [];
    for (let s = 0; s + 1 < placed.length; s++) {
      const left = placed[s];
      const right = placed[s + 1];
      const knot = knots[spans[s + 1]];
      const { c, g } = sl.jointContinuity(left, right);
      joints.push({ knot, c, g, left: Array.from(left.evaluate(knot)), right: Array.from(right.evaluate(knot)), speed: Array.from(curve.derivative(knot, 1)), label: t("multiplicity.jointLabel", { u: knotText(knot) }) });
    }
    for (const piece of placed) piece.free();
  }

  /** The joint entry at knot value u, or null. */
  function jointAt(u) {
    return joints.find((j) => j.knot === u) ?? null;
  }

  /**
   * The knot the panels talk about: the selected knot when it is interior; else the interior
   * knot of highest multiplicity (nearest the middle of the domain on a tie). And the knot
   * nearest the repeated point: u_k with k = j + p − ⌊(p − r)/2⌋ for copies P_j … P_{j+r−1}
   * (its value depends on P_{k−p} … P_{k−1}, which then hold the copies as centrally as possible).
   */
  function findStudied() {
    const knots = work.knots;
    const n = knots.length - P - 2;
    const lo = knots[P];
    const hi = knots[n + 1];
    const interior = (i) => i > P && i <= n && knots[i] > lo && knots[i] < hi;
    let pick = -1;
    if (ruler.selected >= 0 && interior(ruler.selected)) pick = ruler.selected;
    if (pick < 0) {
      const middle = (lo + hi) / 2;
      let bestR = 0;
      let bestD = Infinity;
      for (let i = P + 1; i <= n; i++) {
        if (!interior(i) || knots[i] === knots[i - 1]) continue;
        const [a, b] = stackOf(knots, i);
        const r = b - a + 1;
        const d = Math.abs(knots[i] - middle);
        if (r > bestR || (r === bestR && d < bestD - 1e-12)) {
          bestR = r;
          bestD = d;
          pick = i;
        }
      }
    }
    if (pick < 0) {
      studied = null;
    } else {
      const [a, b] = stackOf(knots, pick);
      studied = { a, b, value: knots[pick], r: b - a + 1, joint: jointAt(knots[pick]) };
    }
    repeatJoint = null;
    if (work.repeatTimes > 1) {
      const j = expandedIndex(work, work.repeatPoint);
      const k = j + P - Math.floor((P - work.repeatTimes) / 2);
      if (interior(k)) repeatJoint = { k, joint: jointAt(knots[k]) };
    }
  }

  // ------------------------------------------------------------ drawing
  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;

    // Control polygon (of the distinct points: a repeated point is one corner).
    pointsPath(r, v, pts);
    r.paint(theme.polygon);

    // The curve, from one batched sample call; at a break the pieces are not joined.
    r.beginPath();
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const x = v.sx(samples[2 * k]);
      const y = v.sy(samples[2 * k + 1]);
      if (k === 0 || jumps(k)) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.curve);

    // The joints: a small dot at every interior knot, the studied one (and its gap) in vermillion.
    for (let s = 0; s < joints.length; s++) {
      const jt = joints[s];
      r.point(v.sx(jt.right[0]), v.sy(jt.right[1]), theme.levelPoint[1]);
      if (jt !== studied?.joint) r.text(jt.label, v.sx(jt.right[0]) + 6 * r.scale, v.sy(jt.right[1]) + 6 * r.scale, theme.labelSmall, "left", "top");
    }
    handles.draw(r, v);
    if (studied?.joint) {
      const jt = studied.joint;
      const lx = v.sx(jt.left[0]);
      const ly = v.sy(jt.left[1]);
      const rx = v.sx(jt.right[0]);
      const ry = v.sy(jt.right[1]);
      if (jt.c < 0) {
        r.beginPath();
        r.moveTo(lx, ly);
        r.lineTo(rx, ry);
        r.paint(theme.helper);
        r.point(lx, ly, theme.pointOnCurve);
      }
      r.point(rx, ry, theme.pointOnCurve);
      r.text(studiedLabel, rx, ry + 12 * r.scale, theme.labelPoint, "center", "top");
    }

    // The ruler band.
    const w = r.width;
    const h = r.height;
    const sc = r.scale;
    ruler.layout(40 * sc, w - 34 * sc, h - ruler.height(sc), sc);
    ruler.draw(r);
  }

  /** True when curve sample k starts a new piece (the curve breaks between samples k − 1 and k). */
  function jumps(k) {
    for (let s = 0; s < joints.length; s++) {
      if (joints[s].c >= 0) continue;
      const [a, b] = domainOf();
      const u = a + (k / (CURVE_SAMPLES - 1)) * (b - a);
      const u0 = a + ((k - 1) / (CURVE_SAMPLES - 1)) * (b - a);
      if (u0 < joints[s].knot && u >= joints[s].knot) return true;
    }
    return false;
  }

  /** The domain [u_p, u_{n+1}] from the state's knots (no wasm call in the draw path). */
  function domainOf() {
    domainScratch[0] = work.knots[P];
    domainScratch[1] = work.knots[work.knots.length - P - 1];
    return domainScratch;
  }

  // ------------------------------------------------------------ panels (formula, tables, notes, label)
  function syncPanels() {
    const knots = work.knots;
    const names = (a, b) => {
      const list = [];
      for (let i = a; i <= b; i++) list.push(`u${subscript(i)}`);
      return list.join(" = ");
    };
    const measuredText = (jt) => (jt ? (jt.c < 0 ? t("knotRuler.break") : `${continuityText(jt.c)} ${geometricText(jt.g, jt.c)}`) : "—");

    // Knot multiplicity: the studied knot.
    let knotRow = 0;
    let through = "";
    if (studied) {
      const guaranteed = P - studied.r;
      knotRow = Math.min(studied.r, 4);
      setText(knotReadout, t("multiplicity.knotReadout", { names: names(studied.a, studied.b), u: knotText(studied.value), r: studied.r, guaranteed: continuityText(guaranteed < 0 ? -1 : guaranteed), measured: measuredText(studied.joint) }));
      through = passesThrough(studied.joint);
      setText(knotNote, through ? t("multiplicity.through", { u: knotText(studied.value), point: through }) : t("multiplicity.knotHint"));
      studiedLabel = through ? t("multiplicity.throughLabel", { u: knotText(studied.value), point: through }) : t("multiplicity.pointLabel", { u: knotText(studied.value) });
    } else {
      setText(knotReadout, t("multiplicity.noKnot"));
      setText(knotNote, t("multiplicity.knotHint"));
      studiedLabel = "";
    }
    raiseButton.disabled = !studied || studied.r >= P + 1;
    lowerButton.disabled = !studied || studied.r <= 1;

    // Control-point multiplicity.
    repeatRadios.set(String(work.repeatTimes));
    const repeated = pointName(work.repeatPoint);
    if (work.repeatTimes === 1) {
      setText(repeatReadout, t("multiplicity.repeatNone", { point: repeated }));
    } else if (repeatJoint) {
      const jt = repeatJoint.joint;
      setText(repeatReadout, t("multiplicity.repeatReadout", { points: repeated, k: subscript(repeatJoint.k), u: knotText(knots[repeatJoint.k]), measured: measuredText(jt) }));
    } else {
      setText(repeatReadout, t("multiplicity.repeatEnd", { points: repeated }));
    }
    setText(repeatNote, t("multiplicity.repeatHint"));

    // The notes' table with the current cases highlighted.
    for (let k = 0; k < 4; k++) {
      notesCells[k][0].classList.toggle("sl-highlight", work.repeatTimes > 1 && k + 1 === work.repeatTimes);
      notesCells[k][1].classList.toggle("sl-highlight", k + 1 === knotRow);
    }

    // Every distinct interior knot: multiplicity, guaranteed and measured continuity, C there.
    const head = el("tr", {},
      el("th", { scope: "col", text: t("multiplicity.colKnot") }),
      el("th", { scope: "col", text: t("multiplicity.colR") }),
      el("th", { scope: "col", text: t("multiplicity.colGuaranteed") }),
      el("th", { scope: "col", text: t("multiplicity.colMeasured") }),
      el("th", { scope: "col", text: t("multiplicity.colPoint") }),
      el("th", { scope: "col", text: t("multiplicity.colThrough") }));
    const rows = [];
    for (const entry of continuity) {
      const jt = jointAt(entry.knot);
      const [a, b] = stackOf(knots, knots.indexOf(entry.knot));
      const pointText = jt ? (jt.c < 0 ? t("multiplicity.pointBreak", { left: pair(jt.left), right: pair(jt.right) }) : pair(jt.right)) : "—";
      const hit = passesThrough(jt);
      const row = el("tr", { dataset: { knot: knotText(entry.knot) } },
        el("th", { scope: "row", text: `${names(a, b)} = ${knotText(entry.knot)}` }),
        el("td", { dataset: { cell: "multiplicity" }, text: String(entry.multiplicity) }),
        el("td", { dataset: { cell: "guaranteed" }, text: continuityText(entry.continuity) }),
        el("td", { dataset: { cell: "measured" }, text: measuredText(jt) }),
        el("td", { dataset: jt ? { cell: "point", x: String(jt.right[0]), y: String(jt.right[1]) } : { cell: "point" }, text: pointText }),
        el("td", { dataset: { cell: "through" }, text: hit || "—" }));
      if (studied && entry.knot === studied.value) row.classList.add("sl-highlight");
      rows.push(row);
    }
    knotsTable.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));

    // Formula panel.
    const lines = [`C(u) = \\sum_{i=0}^{${knots.length - P - 2}} N_{i,3}(u)\\,P_i,\\qquad \\text{${t("multiplicity.formulaRule")}}\\ r:\\ C^{\\,3-r}`];
    if (studied) {
      const g = P - studied.r;
      const idx = [];
      for (let i = studied.a; i <= studied.b; i++) idx.push(`u_{${i}}`);
      const jt = studied.joint;
      const measured = jt ? (jt.c < 0 ? `\\text{${t("knotRuler.break")}}` : `C^{${jt.c === Infinity ? "\\infty" : jt.c}},\\ G^{${jt.g}}`) : "";
      const value = jt && jt.c >= 0 ? `,\\quad C(${knotText(studied.value)}) = (${fmt(jt.right[0])},\\ ${fmt(jt.right[1])})${through ? ` = ${through.replace(/P(\S+)/, (m) => `P_{${fromSubscript(m.slice(1))}}`)}` : ""}` : "";
      lines.push(`${idx.join(" = ")} = ${knotText(studied.value)}:\\quad r = ${studied.r} \\;\\Rightarrow\\; ${g < 0 ? `\\text{${t("multiplicity.formulaBreak")}}` : `C^{3-${studied.r}} = C^{${g}}`};\\quad \\text{${t("multiplicity.formulaMeasured")}}\\ ${measured}${value}`);
    }
    if (work.repeatTimes > 1 && repeatJoint?.joint) {
      const jt = repeatJoint.joint;
      lines.push(`${repeated.replace(/P([₀-₉]+)/g, (m, s) => `P_{${fromSubscript(s)}}`)}:\\quad C'(u_{${repeatJoint.k}}) = (${fmt(jt.speed[0])},\\ ${fmt(jt.speed[1])}),\\quad \\text{${t("multiplicity.formulaMeasured")}}\\ C^{${jt.c === Infinity ? "\\infty" : jt.c}},\\ G^{${jt.g}}`);
    }
    formula.set(lines);

    // The figure's accessible name.
    const list = continuity.map((entry) => `${knotText(entry.knot)} (×${entry.multiplicity}): ${continuityText(entry.continuity)}, ${measuredText(jointAt(entry.knot))}`).join("; ");
    view.setLabel(t("multiplicity.aria", { count: knots.length - P - 1, knots: knots.map(knotText).join(", "), list, repeat: work.repeatTimes > 1 ? t("multiplicity.ariaRepeat", { points: repeated, measured: repeatJoint ? measuredText(repeatJoint.joint) : "—" }) : "", through: through ? t("multiplicity.ariaThrough", { u: knotText(studied.value), point: through }) : "" }));
  }

  /** "P₄" when the curve at the joint (right piece) equals a control point, else "". */
  function passesThrough(jt) {
    if (!jt || jt.c < 0) return "";
    const flat = expandedPoints(work);
    const scale = 1 + Math.hypot(jt.right[0], jt.right[1]);
    for (let i = 0; i < flat.length / 2; i++) {
      if (Math.hypot(flat[2 * i] - jt.right[0], flat[2 * i + 1] - jt.right[1]) <= SAME_POINT * scale) return `P${subscript(i)}`;
    }
    return "";
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = build(state); // throws before anything changes
      curve.free();
      curve = next;
      work = structuredClone(state);
      handleLabels = [];
      handles.forgetPointer();
      ruler.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      if (ruler.selected >= work.knots.length) ruler.select(-1);
      knotsDirty = geometryDirty = true;
      shownKey = "";
      view.requestDraw();
      recompute();
    },
    destroy() {
      ruler.destroy();
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** "(6.000, 4.000)". */
function pair([x, y]) {
  return `(${fmt(x)}, ${fmt(y)})`;
}

/** "₁₂" → "12". */
function fromSubscript(text) {
  return text.replace(/[₀-₉]/g, (c) => String(c.charCodeAt(0) - 0x2080));
}
