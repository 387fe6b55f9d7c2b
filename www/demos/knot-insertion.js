/**
 * Demo (syllabus §3): knot insertion (Boehm) and Bézier extraction. Click the curve (or set u
 * and press Insert) to insert a knot: the core's `insertKnot(u, 1)` returns a curve with one
 * more control point and the very same shape. The new polygon Q is drawn strongly with its new
 * points labelled, the polygon before the insertion ghosted; the knot vectors before and after
 * and the α_i of Boehm's rule are listed. Repeated insertions pull the polygon onto the curve;
 * "Extract Bézier segments" draws each `toBezier()` segment's control polygon.
 *
 * State: the original points and knots plus the list of inserted knots, so undo, links and
 * files replay the insertions: the curve before the last insertion is `refine(all but the last)`
 * and the shown curve is that one's `insertKnot(last, 1)`. Dragging an original point goes
 * through `setControlPoint` on the original curve; the refined curves are derived data and are
 * asked from the core again per change (like `deCasteljau(t)` in the reference demo).
 *
 * JS does no curve maths: picking the clicked parameter is the nearest of the drawn samples
 * (`sampleUniform`), and the span and the α_i shown are the core's `insertionAlphas(s)` (the core
 * computes the new points itself).
 */
import { Handles, placeLabel, HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, checkbox, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkNumbers, checkBoolean } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, fractionText, fractionTex, degreeName } from "../lib/format.js";
import { HUES, WIDTH, RADIUS } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { flatPath } from "../lib/draw.js";
import { ParameterStrip } from "../lib/param-strip.js";
import { scaledInsets } from "../lib/view.js";

export const id = "knot-insertion";
/** Prefix of this demo's keys in strings.js. */
export const strings = "knotInsertion";
export const title = t("knotInsertion.title");
export const summary = t("knotInsertion.summary");
/** Syllabus section. */
export const section = 3;

/**
 * The quadratic example of the Croatian notes (syllabus §3): p = 2, six points,
 * U = [0, 0, 0, 1, 2, 3, 4, 4, 4] (four non-empty spans), shown after inserting s = 3/2
 * (α₂ = 3/4, α₃ = 1/4: knots 0 0 0 1 1.5 2 3 4 4 4, five spans, so five Bézier segments);
 * u = 5/2 is ready to insert next.
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [1, 4], [4, 5], [6, 1], [9, 2], [10, 5]].map(Object.freeze)),
  degree: 2,
  knots: Object.freeze([0, 0, 0, 1, 2, 3, 4, 4, 4]),
  inserted: Object.freeze([1.5]),
  u: 2.5,
  bezier: false,
});

/** Degrees and point counts accepted from links and files. */
export const MIN_DEGREE = 1;
export const MAX_DEGREE = 5;
export const MAX_POINTS = 12;
/** Most inserted knots (enough for four rounds of "halve every span" on the default curve). */
export const MAX_INSERTED = 64;
/** Points sampled along the curve (one `sampleUniform` per change); also the picking grid. */
const CURVE_SAMPLES = 257;
/** Slider resolution for u. */
const U_STEP = 0.01;
/** Opacity of the polygon before the last insertion. */
const GHOST_ALPHA = 0.55;
/** The knot strip under the figure: height and side margins in CSS px at scale 1. */
const STRIP_PX = 62;
const STRIP_MARGIN = 34;
/** Rows of the strip, CSS px below its top at scale 1: u label, axis, knot labels. */
const STRIP_ROW = Object.freeze({ label: 12, axis: 30, ticks: 48 });
/** Half-length of a knot tick (inserted knots: longer), CSS px. */
const TICK_PX = 6;
const INSERTED_TICK_PX = 10;
/** Knot labels closer than this (CSS px) to the previous one are left out. */
const LABEL_SPACING_PX = 30;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "degree", "knots", "inserted", "u", "bezier"]);
  checkPoints(state, "points", { min: MIN_DEGREE + 1, max: MAX_POINTS });
  checkNumber(state, "degree", { min: MIN_DEGREE, max: MAX_DEGREE, integer: true });
  const count = state.points.length;
  const p = state.degree;
  if (count < p + 1) throw new Error(t("knotInsertion.error.tooFewPoints", { min: p + 1, p, count }));
  checkNumbers(state, "knots", { min: count + p + 1, max: count + p + 1 });
  for (let i = 1; i < state.knots.length; i++) {
    if (state.knots[i] < state.knots[i - 1]) throw new Error(t("knotInsertion.error.knotOrder", { i }));
  }
  const a = state.knots[p];
  const b = state.knots[count];
  if (!(a < b)) throw new Error(t("knotInsertion.error.emptyDomain"));
  checkNumbers(state, "inserted", { min: 0, max: MAX_INSERTED });
  for (const s of state.inserted) {
    if (s < a || s > b) throw new Error(t("knotInsertion.error.insertedRange", { value: s, a, b }));
  }
  checkNumber(state, "u", { min: a, max: b });
  checkBoolean(state, "bezier");
}

/** A knot or parameter value as text: integers plain, else up to 3 decimals. */
function knotText(value) {
  return Number.isInteger(value) ? String(value) : String(Number(value.toFixed(3)));
}

/** A number in TeX: a simple fraction when it is one, else 3 decimals. */
function numberTex(value) {
  const f = simpleFraction(value);
  return f ? fractionTex(f) : fmt(value);
}

/**
 * The curves a state shows, asked from the core: `previous` before the last insertion
 * (`refine` of the others) and `current` after it (`insertKnot(last, 1)`); both are `base`
 * itself when nothing was inserted. Throws (after freeing what it made) when the core refuses.
 */
function deriveCurves(base, inserted) {
  if (inserted.length === 0) return { previous: base, current: base };
  const previous = inserted.length > 1 ? base.refine(Float64Array.from(inserted.slice(0, -1))) : base;
  try {
    return { previous, current: previous.insertKnot(inserted[inserted.length - 1], 1) };
  } catch (err) {
    if (previous !== base) previous.free();
    throw err;
  }
}

/** Frees the derived curves that are not `base`. */
function freeCurves(curves, base) {
  if (curves.current !== base) curves.current.free();
  if (curves.previous !== base) curves.previous.free();
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let base = new sl.BSplineCurve(flatten(work.points), 2, work.degree, Float64Array.from(work.knots));
  let curves = deriveCurves(base, work.inserted);

  // Derived data, recomputed only when something changed.
  let geometryDirty = true; // points moved
  let curvesStale = false; // an original point moved: the refined curves must be asked again
  let structureDirty = true; // knots or insertions changed
  let uDirty = true;
  let samples = null; // current.sampleUniform(CURVE_SAMPLES)
  let currentPoints = null; // current.controlPoints()
  let previousPoints = null; // previous.controlPoints()
  let currentKnots = null;
  let previousKnots = null;
  let segments = []; // control points of each toBezier() segment
  let uPoint = null; // base.evaluate(u): where Insert would insert
  let last = null; // { s, k, alphas } of the last insertion, or of the slider's u (preview)
  let distinct = []; // distinct knot values of the current curve
  let knotLabels = []; // their labels ("0 ×3")
  const insertedSet = new Set(); // inserted values (strip ticks)
  const qLabels = []; // "Q₀" …
  let uLabel = "";
  let hoverIndex = -1; // the sample under the pointer (click inserts its u)
  let hoverLabel = "";
  let styles = null; // per theme, see stylesFor
  let stylesTheme = null;

  // ------------------------------------------------------------ figure
  // The canvas strip below the world window.
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets: scaledInsets(0, 0, STRIP_PX, 0) });

  // The knot strip claims the pointer before the handles: press or drag there to set u.
  const strip = new ParameterStrip(view, {
    height: STRIP_PX,
    margin: STRIP_MARGIN,
    step: U_STEP,
    range: () => domain(),
    pick: (u, final) => setU(u, final),
    over: () => {
      handles.leave(); // the pointer left the handles' area (they are not asked while it is here)
      setHover(-1);
    },
  });

  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      base.setControlPoint(i, xy); // in place: the original curve is not rebuilt
      geometryDirty = curvesStale = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
  });

  // Clicking (or tapping) the curve inserts the parameter of the nearest drawn sample. The
  // handles come first, so a press on a control point still drags it.
  let pressIndex = -1;
  view.addInteractor({
    pointerDown(event, x, y) {
      const j = sampleNear(x, y, event.pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE);
      if (j < 0) return false;
      pressIndex = j;
      setHover(j);
      return true;
    },
    pointerMove() {},
    pointerUp(event, x, y) {
      if (pressIndex < 0) return;
      const j = sampleNear(x, y, event.pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE);
      const picked = pressIndex;
      pressIndex = -1;
      if (j < 0) return; // slid off the curve: no insertion
      insert(sampleU(picked));
    },
    hover(x, y, pointerType) {
      const j = handles.hovered >= 0 ? -1 : sampleNear(x, y, pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE);
      setHover(j);
      return j >= 0 ? "copy" : null;
    },
    leave() {
      setHover(-1);
    },
  });

  // ------------------------------------------------------------ side panel
  const uSlider = slider({
    label: t("knotInsertion.control.u"),
    inputLabel: t("knotInsertion.control.u.input"),
    name: "u",
    // The typed range is checked against the curve's domain in setU (it changes with the state).
    min: -1e9,
    max: 1e9,
    step: U_STEP,
    value: work.u,
    onChange: (value, final) => setU(value, final),
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const insertButton = button({ label: t("knotInsertion.control.insert"), title: t("knotInsertion.control.insert.title"), name: "insert", onClick: () => insert(work.u) });
  const refineButton = button({ label: t("knotInsertion.control.refine"), title: t("knotInsertion.control.refine.title"), name: "refine-all", onClick: () => refineAll() });
  const resetButton = button({ label: t("knotInsertion.control.reset"), title: t("knotInsertion.control.reset.title"), name: "reset-knots", onClick: () => clearInserted() });
  const bezierBox = checkbox({
    label: t("knotInsertion.control.bezier"),
    name: "bezier",
    checked: work.bezier,
    onChange: (on) => {
      work.bezier = on;
      structureDirty = true;
      view.requestDraw();
      ctx.commit(work);
    },
  });
  const countText = el("p", { class: "sl-readout", dataset: { info: "count" }, "aria-live": "polite" });
  const segmentText = el("p", { class: "sl-note", dataset: { info: "segments" } });
  ctx.slots.controls.append(
    group(null, uSlider.element, el("div", { class: "sl-button-row" }, insertButton, refineButton, resetButton)),
    group(null, countText, bezierBox.element, segmentText),
  );

  // ------------------------------------------------------------ formula, knot lists and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const knotsBefore = el("p", { class: "sl-note", dataset: { info: "knots-before" } });
  const knotsAfter = el("p", { class: "sl-note", dataset: { info: "knots-after" } });
  const alphaText = el("p", { class: "sl-note", dataset: { info: "alphas" } });
  const insertedText = el("p", { class: "sl-note", dataset: { info: "inserted" } });
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("knot-insertion");
  ctx.slots.details.append(knotsBefore, knotsAfter, alphaText, insertedText, tableTitle, tableWrap);

  // ------------------------------------------------------------ edits

  /** The domain [u_p, u_{n+1}] of the original knots (insertion never changes it). */
  function domain() {
    return [work.knots[work.degree], work.knots[work.points.length]];
  }

  function setU(value, final) {
    const [a, b] = domain();
    if (final && (value < a || value > b)) {
      ctx.status(t("knotInsertion.outside", { value: knotText(value), a: knotText(a), b: knotText(b) }), "error");
      uSlider.set(work.u);
      return;
    }
    work.u = Math.min(b, Math.max(a, value));
    uSlider.set(work.u);
    uDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  /** Replaces the derived curves after `work.inserted` changed; false (and a message) if refused. */
  function rederive() {
    let next;
    try {
      next = deriveCurves(base, work.inserted);
    } catch (err) {
      ctx.status(t("knotInsertion.refused", { message: err.message }), "error");
      return false;
    }
    freeCurves(curves, base);
    curves = next;
    structureDirty = true;
    view.requestDraw();
    return true;
  }

  /** Inserts knot s once (the new curve is the core's `insertKnot(s, 1)`). */
  function insert(s) {
    if (work.inserted.length >= MAX_INSERTED) {
      ctx.status(t("knotInsertion.maxInserted", { max: MAX_INSERTED }), "error");
      return;
    }
    work.inserted.push(s);
    if (!rederive()) {
      work.inserted.pop();
      return;
    }
    ctx.commit(work);
  }

  /** Inserts the midpoint of every non-empty span of the shown curve (one `refine` call). */
  function refineAll() {
    const spans = curves.current.spans();
    const mids = [];
    for (const k of spans) mids.push((currentKnots[k] + currentKnots[k + 1]) / 2);
    if (work.inserted.length + mids.length > MAX_INSERTED) {
      ctx.status(t("knotInsertion.maxInserted", { max: MAX_INSERTED }), "error");
      return;
    }
    const before = work.inserted.length;
    work.inserted.push(...mids);
    if (!rederive()) {
      work.inserted.length = before;
      return;
    }
    ctx.commit(work);
  }

  function clearInserted() {
    if (work.inserted.length === 0) return;
    work.inserted = [];
    rederive();
    ctx.commit(work);
  }

  // ------------------------------------------------------------ picking (nearest drawn sample)
  /** u of uniform sample j (the grid `sampleUniform` uses: ends included, equal steps). */
  function sampleU(j) {
    const [a, b] = domain();
    return a + ((b - a) * j) / (CURVE_SAMPLES - 1);
  }

  /** Index of the sample nearest to canvas point (x, y) within `radius` px, or -1. */
  function sampleNear(x, y, radius) {
    if (!samples) return -1;
    let best = -1;
    let bestDistance = radius;
    for (let j = 0; j < CURVE_SAMPLES; j++) {
      const d = Math.hypot(view.sx(samples[2 * j]) - x, view.sy(samples[2 * j + 1]) - y);
      if (d <= bestDistance) {
        best = j;
        bestDistance = d;
      }
    }
    return best;
  }

  function setHover(j) {
    if (j === hoverIndex) return;
    hoverIndex = j;
    hoverLabel = j >= 0 ? t("knotInsertion.hoverLabel", { u: knotText(sampleU(j)) }) : "";
    view.requestDraw();
  }

  // ------------------------------------------------------------ knot strip
  // ------------------------------------------------------------ the core's answers
  function recompute() {
    if (curvesStale && work.inserted.length > 0) {
      // The refined curves follow the dragged original points: asked from the core again.
      const next = deriveCurves(base, work.inserted);
      freeCurves(curves, base);
      curves = next;
    }
    curvesStale = false;
    if (geometryDirty || structureDirty) {
      const { previous, current } = curves;
      samples = current.sampleUniform(CURVE_SAMPLES);
      currentPoints = current.controlPoints();
      previousPoints = previous.controlPoints();
      currentKnots = current.knots();
      previousKnots = previous.knots();
      segments = [];
      if (work.bezier) {
        for (const segment of current.toBezier()) {
          segments.push(segment.controlPoints());
          segment.free();
        }
      }
      publishChecksum();
    }
    if (structureDirty) {
      distinct = [];
      knotLabels = [];
      for (let i = 0; i < currentKnots.length; i++) {
        const value = currentKnots[i];
        if (distinct.length && distinct[distinct.length - 1] === value) continue;
        let r = 1;
        while (i + r < currentKnots.length && currentKnots[i + r] === value) r += 1;
        distinct.push(value);
        knotLabels.push(r > 1 ? `${knotText(value)} ×${r}` : knotText(value));
      }
      insertedSet.clear();
      for (const s of work.inserted) insertedSet.add(s);
    }
    if (geometryDirty || structureDirty || uDirty) {
      uPoint = base.evaluate(work.u);
      uLabel = `u = ${knotText(work.u)}`;
      last = boehmInfo();
      syncPanels();
    }
    geometryDirty = structureDirty = uDirty = false;
  }

  /**
   * The knot s of the last insertion (or the slider's u, as a preview), and from the core's
   * `insertionAlphas(s)` on the curve before it: its span k and α_i = (s − u_i)/(u_{i+p} − u_i),
   * i = k−p+1 … k. The α are SHOWN, not used: the new points come from the core's insertKnot.
   */
  function boehmInfo() {
    const preview = work.inserted.length === 0;
    const s = preview ? work.u : work.inserted[work.inserted.length - 1];
    const { span: k, alphas: values } = curves.previous.insertionAlphas(s);
    const alphas = values.map((value, m) => ({ i: k - work.degree + 1 + m, value }));
    return { preview, s, k, alphas };
  }

  /**
   * Writes a weighted sum of the drawn samples to the count readout (`data-curve-sum`):
   * insertion must leave it unchanged up to rounding (a hook for tests and curious readers).
   */
  function publishChecksum() {
    let sum = 0;
    for (let j = 0; j < CURVE_SAMPLES; j++) sum += (j + 1) * (samples[2 * j] + Math.SQRT2 * samples[2 * j + 1]);
    countText.dataset.curveSum = String(sum);
  }

  // ------------------------------------------------------------ drawing
  /** The demo's derived styles of a theme (made once per theme, not per frame). */
  function stylesFor(theme) {
    if (stylesTheme !== theme) {
      stylesTheme = theme;
      styles = {
        ghost: Object.freeze({ ...theme.polygon, strokeAlpha: GHOST_ALPHA }),
        strong: Object.freeze({ stroke: theme.text, width: WIDTH.construction, join: "round" }),
        q: Object.freeze({ fill: theme.text, stroke: theme.background, width: WIDTH.helper, radius: RADIUS.constructionPoint }),
        qNew: Object.freeze({ fill: HUES.vermillion, stroke: theme.background, width: WIDTH.helper, radius: RADIUS.pointOnCurve }),
        hover: Object.freeze({ stroke: HUES.vermillion, width: WIDTH.construction, radius: RADIUS.handleHover }),
        tick: Object.freeze({ stroke: theme.text, width: WIDTH.construction }),
        insertedTick: Object.freeze({ stroke: HUES.vermillion, width: WIDTH.split }),
      };
    }
    return styles;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const st = stylesFor(theme);
    const inserted = work.inserted.length > 0;

    // The polygon before the last insertion: ghosted (the original one, plain, before any).
    flatPath(r, v, previousPoints);
    r.paint(inserted ? st.ghost : theme.polygon);

    // The curve (the same before and after: drawn from the refined curve).
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    if (work.bezier) {
      // Each Bézier segment's polygon in the categorical colours.
      for (let s = 0; s < segments.length; s++) {
        const pts = segments[s];
        const colour = s % theme.levelStroke.length;
        flatPath(r, v, pts);
        r.paint(theme.levelStroke[colour]);
        for (let j = 0; j < pts.length / 2; j++) r.point(v.sx(pts[2 * j]), v.sy(pts[2 * j + 1]), theme.levelPoint[colour]);
      }
    } else if (inserted) {
      // The new polygon Q, strong; the points the last insertion made in vermillion.
      const count = currentPoints.length / 2;
      flatPath(r, v, currentPoints, 0, count);
      r.paint(st.strong);
      for (let i = 0; i < count; i++) r.point(v.sx(currentPoints[2 * i]), v.sy(currentPoints[2 * i + 1]), st.q);
    }

    handles.draw(r, v);

    if (!work.bezier && inserted) {
      const { k } = last;
      const p = work.degree;
      for (let i = k - p + 1; i <= k; i++) {
        const x = v.sx(currentPoints[2 * i]);
        const y = v.sy(currentPoints[2 * i + 1]);
        r.point(x, y, st.qNew);
        labelOffLeg(r, v, (qLabels[i] ??= `Q${subscript(i)}`), x, y, i, theme.labelPoint, st.qNew.radius * r.scale);
      }
    }

    // Where Insert would insert: C(u) on the curve, a ring (the filled vermillion dots are new points).
    r.point(v.sx(uPoint[0]), v.sy(uPoint[1]), st.hover);

    // The sample under the pointer: click to insert its u.
    if (hoverIndex >= 0 && handles.hovered < 0 && handles.dragging < 0) {
      const x = v.sx(samples[2 * hoverIndex]);
      const y = v.sy(samples[2 * hoverIndex + 1]);
      r.point(x, y, st.hover);
      placeLabel(r, hoverLabel, x, y, 0, -1, st.hover.radius * r.scale, theme.labelPoint);
    }

    drawStrip(r, theme, st);
  }

  /**
   * Labels new point Q_i beside the leg P_{i−1}P_i of the polygon before the insertion (Q_i
   * lies on it), on the side away from the polygon's centroid.
   */
  function labelOffLeg(r, v, text, x, y, i, style, radius) {
    const P = previousPoints;
    let nx = v.sy(P[2 * i + 1]) - v.sy(P[2 * i - 1]);
    let ny = v.sx(P[2 * i]) - v.sx(P[2 * i - 2]);
    const length = Math.hypot(nx, ny);
    if (length < 1) {
      nx = 0;
      ny = -1;
    } else {
      nx /= length;
      ny /= length;
    }
    let cx = 0;
    let cy = 0;
    const count = P.length / 2;
    for (let j = 0; j < count; j++) {
      cx += v.sx(P[2 * j]);
      cy += v.sy(P[2 * j + 1]);
    }
    if ((x - cx / count) * nx + (y - cy / count) * ny < 0) {
      nx = -nx;
      ny = -ny;
    }
    placeLabel(r, text, x, y, nx, ny, radius, style);
  }

  /** The parameter line under the figure: the knots as ticks (inserted ones longer, vermillion) and u. */
  function drawStrip(r, theme, st) {
    const s = r.scale;
    strip.layout(r.width, r.height, s);
    const top = strip.top;
    const axisY = top + STRIP_ROW.axis * s;
    r.beginPath();
    r.moveTo(strip.x0, axisY);
    r.lineTo(strip.x1, axisY);
    r.paint(theme.axis);
    r.beginPath();
    for (let j = 0; j < distinct.length; j++) {
      if (insertedSet.has(distinct[j])) continue;
      const x = strip.px(distinct[j]);
      r.moveTo(x, axisY - TICK_PX * s);
      r.lineTo(x, axisY + TICK_PX * s);
    }
    r.paint(st.tick);
    r.beginPath();
    for (let j = 0; j < distinct.length; j++) {
      if (!insertedSet.has(distinct[j])) continue;
      const x = strip.px(distinct[j]);
      r.moveTo(x, axisY - INSERTED_TICK_PX * s);
      r.lineTo(x, axisY + INSERTED_TICK_PX * s);
    }
    r.paint(st.insertedTick);
    let lastLabel = -Infinity;
    for (let j = 0; j < distinct.length; j++) {
      const x = strip.px(distinct[j]);
      const isEnd = j === distinct.length - 1;
      if (x - lastLabel < LABEL_SPACING_PX * s && !isEnd) continue;
      if (isEnd && x - lastLabel < LABEL_SPACING_PX * s) continue;
      r.text(knotLabels[j], x, top + STRIP_ROW.ticks * s, insertedSet.has(distinct[j]) ? theme.labelPoint : theme.labelSmall, "center", "middle");
      lastLabel = x;
    }
    const x = strip.px(work.u);
    r.point(x, axisY, theme.pointOnCurve);
    const align = x < strip.x0 + 40 * s ? "left" : x > strip.x1 - 40 * s ? "right" : "center";
    r.text(uLabel, x, top + STRIP_ROW.label * s, theme.labelPoint, align, "middle");
  }

  // ------------------------------------------------------------ panels (formula, lists, table, label)
  function syncPanels() {
    const p = work.degree;
    const { preview, s, k, alphas } = last;
    const U = previousKnots;
    const sTex = numberTex(s);
    const count = currentPoints.length / 2;

    // Boehm's rule with the live α (the Q values come from the core's new polygon).
    const alphaTex = alphas
      .map(({ i, value }) => `\\alpha_{${i}} = \\frac{${knotText(s)} - ${knotText(U[i])}}{${knotText(U[i + p])} - ${knotText(U[i])}} = ${numberTex(value)}`)
      .join(",\\quad ");
    const lines = [
      `${preview ? `\\text{${t("knotInsertion.formula.preview")}}\\ ` : ""}s = ${sTex} \\in [u_{${k}}, u_{${k + 1}}) = [${numberTex(U[k])}, ${numberTex(U[k + 1])}),\\quad k = ${k},\\quad p = ${p}`,
      `Q_i = P_i\\ (i \\le ${k - p}),\\qquad Q_i = (1-\\alpha_i)\\,P_{i-1} + \\alpha_i\\,P_i\\ (${k - p + 1} \\le i \\le ${k}),\\qquad Q_i = P_{i-1}\\ (i \\ge ${k + 1})`,
      `\\alpha_i = \\frac{s - u_i}{u_{i+p} - u_i}:\\quad ${alphaTex}`,
    ];
    if (!preview) {
      const terms = alphas.map(({ i, value }) => `Q_{${i}} = ${numberTex(1 - value)}\\,P_{${i - 1}} + ${numberTex(value)}\\,P_{${i}} = (${fmt(currentPoints[2 * i])},\\ ${fmt(currentPoints[2 * i + 1])})`);
      lines.push(terms.join(",\\quad "));
    }
    formula.set(lines);

    // Knot vectors before/after, the α used, the insertions so far.
    const list = (values) => Array.from(values, knotText).join(", ");
    const alphaList = alphas.map(({ i, value }) => {
      const f = simpleFraction(value);
      return `α${subscript(i)} = ${f ? `${fractionText(f)} (${fmt(value)})` : fmt(value)}`;
    });
    if (preview) {
      setText(knotsBefore, t("knotInsertion.knotsNow", { knots: list(currentKnots) }));
      setText(knotsAfter, t("knotInsertion.knotsNone"));
      setText(alphaText, t("knotInsertion.alphasPreview", { s: knotText(s), alphas: alphaList.join(", ") }));
    } else {
      setText(knotsBefore, t("knotInsertion.knotsBefore", { s: knotText(s), knots: list(previousKnots) }));
      setText(knotsAfter, t("knotInsertion.knotsAfter", { knots: list(currentKnots) }));
      setText(alphaText, t("knotInsertion.alphasUsed", { alphas: alphaList.join(", ") }));
    }
    knotsBefore.dataset.knots = Array.from(previousKnots, knotText).join(",");
    knotsAfter.dataset.knots = preview ? "" : Array.from(currentKnots, knotText).join(",");
    alphaText.dataset.alphas = alphas.map(({ value }) => String(value)).join(",");
    setText(insertedText, work.inserted.length ? t("knotInsertion.insertedList", { count: work.inserted.length, knots: work.inserted.map(knotText).join(", ") }) : t("knotInsertion.insertedNone"));

    setText(countText, t("knotInsertion.readout", { count, knots: currentKnots.length }));
    countText.dataset.points = String(count);
    countText.dataset.knots = String(currentKnots.length);
    if (work.bezier) {
      setText(segmentText, t("knotInsertion.segments", { count: segments.length }));
      segmentText.dataset.segments = String(segments.length);
    } else {
      setText(segmentText, t("knotInsertion.segmentsOff"));
      delete segmentText.dataset.segments;
    }
    resetButton.disabled = work.inserted.length === 0;
    insertButton.disabled = work.inserted.length >= MAX_INSERTED;

    view.setLabel(t(preview ? "knotInsertion.ariaNone" : "knotInsertion.aria", {
      kind: degreeName(p), count, knots: currentKnots.length, s: knotText(s),
      alphas: alphas.map(({ value }) => fmt(value)).join(", "),
      segments: work.bezier ? t("knotInsertion.ariaSegments", { count: segments.length }) : "",
    }));

    // Table: every new point Q_i and the rule that made it (values from the core).
    setText(tableTitle, preview ? t("knotInsertion.tableEmpty") : t("knotInsertion.tableCaption", { s: knotText(s) }));
    const rows = [];
    if (!preview) {
      for (let i = 0; i < count; i++) {
        const alpha = alphas.find((a) => a.i === i);
        const rule = i <= k - p ? `Q${subscript(i)} = P${subscript(i)}` : alpha ? `Q${subscript(i)} = ${numberText(1 - alpha.value)} P${subscript(i - 1)} + ${numberText(alpha.value)} P${subscript(i)}` : `Q${subscript(i)} = P${subscript(i - 1)}`;
        rows.push(el("tr", { class: alpha ? "sl-highlight" : undefined },
          el("th", { scope: "row", text: `Q${subscript(i)}` }),
          el("td", { text: rule }),
          el("td", { dataset: { index: String(i) }, text: `(${fmt(currentPoints[2 * i])}, ${fmt(currentPoints[2 * i + 1])})` })));
      }
    }
    table.replaceChildren(el("tbody", {}, rows));
  }

  /** A number as text: a simple fraction when it is one, else 3 decimals. */
  function numberText(value) {
    const f = simpleFraction(value);
    return f ? fractionText(f) : fmt(value);
  }

  uSlider.range.min = String(domain()[0]);
  uSlider.range.max = String(domain()[1]);
  uSlider.set(work.u);
  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      // Build everything first: the core may refuse (the shell then keeps the old state).
      const nextBase = new sl.BSplineCurve(flatten(state.points), 2, state.degree, Float64Array.from(state.knots));
      let nextCurves;
      try {
        nextCurves = deriveCurves(nextBase, state.inserted);
      } catch (err) {
        nextBase.free();
        throw err;
      }
      freeCurves(curves, base);
      base.free();
      base = nextBase;
      curves = nextCurves;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      strip.dragging = false;
      pressIndex = -1;
      hoverIndex = -1;
      uSlider.range.min = String(domain()[0]);
      uSlider.range.max = String(domain()[1]);
      uSlider.set(work.u);
      bezierBox.set(work.bezier);
      geometryDirty = structureDirty = uDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      freeCurves(curves, base);
      base.free();
    },
  };
}
