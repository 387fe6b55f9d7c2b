/**
 * Demo (syllabus §3): de Boor's algorithm. The B-spline counterpart of the de Casteljau demo and
 * built the same way: the curve lives in wasm and is updated in place while dragging
 * (`setControlPoint`), the construction is what the core returns (`deBoor(u)`, `deBoorAlphas(u)`, `span(u)`, one
 * `sampleUniform` per change), nothing is allocated per frame in the draw path, and replaced
 * wasm objects are freed. A strip under the figure shows the knot vector with the active span
 * [u_k, u_{k+1}) and the parameter u; pressing or dragging there sets u.
 */
import { Handles, placeLabel as placeLabelAt, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, checkbox, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkNumbers, checkBoolean } from "../lib/validate.js";
import { fmt, subscript, superscript, simpleFraction, exactFraction, fractionText, fractionTex, allIntegers, parseNumberInput, MAX_EXACT_DENOMINATOR, degreeName } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { withPointAdded, withPointRemoved } from "../lib/point-list.js";
import { Player } from "../lib/player.js";
import { titledTable } from "../lib/table.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { buildOrReport } from "../lib/wasm.js";
import { scaledInsets } from "../lib/view.js";

export const id = "de-boor";
/** Prefix of this demo's keys in strings.js. */
export const strings = "deBoor";
export const title = t("deBoor.title");
export const summary = t("deBoor.summary");
/** Syllabus section. */
export const section = 3;

/**
 * A cubic clamped uniform B-spline with 7 integer control points (syllabus §3 conventions:
 * p + 1 zeros, 1 … n − p, p + 1 copies of n − p + 1), at u = 5/4 in the span [u₄, u₅) = [1, 2).
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 7], [8, 9], [10, 1], [16, 0], [18, 7], [23, 6]].map(Object.freeze)),
  degree: 3,
  knots: Object.freeze([0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4]),
  u: 1.25,
  construction: true,
});

/** Fewest and most control points. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 11;
/** Highest degree offered. */
export const MAX_DEGREE = 5;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Slider resolution as a fraction of the domain. */
const U_SLIDER_RESOLUTION = 1 / 1000;
/** Intermediate points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_LEVELS_MAX_DEGREE = 4;
/**
 * Candidate label directions around a construction point, as (normal, leg) components and a
 * bonus in px for the plain normals; a label's centre is probed this far from its point.
 */
const LABEL_DIRECTIONS = Object.freeze([1, 0, 4, -1, 0, 4, Math.SQRT1_2, Math.SQRT1_2, 0, Math.SQRT1_2, -Math.SQRT1_2, 0, -Math.SQRT1_2, Math.SQRT1_2, 0, -Math.SQRT1_2, -Math.SQRT1_2, 0]);
const LABEL_PROBE_PX = 14;
/** Height of the knot strip under the figure, CSS px. */
const STRIP_PX = 78;
/** Knot strip layout, CSS px (× lecture scale): side margins, line below the strip's top. */
const STRIP_MARGIN_X = 30;
const STRIP_LINE_Y = 34;
const STRIP_TICK = 7;
const STRIP_SPAN_HALF = 11;
const STRIP_MARKER_HALF = 15;
/** Gap between tick value labels (CSS px), and an estimate of a digit's width in em. */
const STRIP_LABEL_GAP = 6;
const CHAR_EM = 0.62;
/** Pointer slack around the knot line, CSS px. */
const STRIP_HIT_PX = 22;
const FIELDS = ["points", "degree", "knots", "u", "construction"];

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, FIELDS);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "degree", { min: 1, max: MAX_DEGREE, integer: true });
  const count = state.points.length;
  const p = state.degree;
  if (p > count - 1) throw new Error(t("deBoor.error.degree", { p, count }));
  const m = count + p + 1; // knots u_0 … u_m with m = n + p + 1: m + 1 = count + p + 1 values
  checkNumbers(state, "knots", { min: 0, max: Infinity });
  const knots = state.knots;
  if (knots.length !== m) throw new Error(t("deBoor.error.knotCount", { expected: m, count, p, got: knots.length }));
  for (let i = 1; i < knots.length; i++) {
    if (knots[i] < knots[i - 1]) throw new Error(t("deBoor.error.knotOrder", { index: i, value: knots[i], previous: knots[i - 1] }));
  }
  // Multiplicity: at most p + 1 (the wasm constructor says the same; checked here so that a
  // link never reaches mount with knots the core refuses).
  let run = 0;
  for (let i = 0; i < knots.length; i++) {
    run = i > 0 && knots[i] === knots[i - 1] ? run + 1 : 1;
    if (run > p + 1) throw new Error(t("deBoor.error.multiplicity", { value: knots[i], max: p + 1 }));
  }
  const a = knots[p];
  const b = knots[count];
  if (!(a < b)) throw new Error(t("deBoor.error.domain", { a, b, p, n1: count }));
  checkNumber(state, "u", { min: a, max: b });
  checkBoolean(state, "construction");
}

/** A number as short text: integers plain, simple fractions as a/b, else 3 decimals. */
function numberText(x) {
  if (Number.isInteger(x)) return String(x);
  const f = simpleFraction(x);
  return f ? fractionText(f) : fmt(x);
}

/** The same as TeX. */
function numberTex(x) {
  if (Number.isInteger(x)) return String(x);
  const f = simpleFraction(x);
  return f ? fractionTex(f) : fmt(x);
}

/** Greatest common divisor / least common multiple of positive integers (fraction display). */
function gcd(a, b) {
  while (b) [a, b] = [b, a % b];
  return a;
}
function lcm(a, b) {
  return (a / gcd(a, b)) * b;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags and animation, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = new sl.BSplineCurve(flatten(work.points), 2, work.degree, work.knots);

  // Derived data, recomputed only when the geometry or u changed.
  let triangle = null; // curve.deBoor(u): levels concatenated, the p + 1 active points first
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let span = 0; // curve.span(u): u_k <= u < u_{k+1}
  let alphaData = null; // curve.deBoorAlphas(u): [r, j, lo, hi, u_hi − u_lo, α] per step
  let geometryDirty = true;
  let uDirty = true;
  const levelLabels = []; // "d₂¹" … cached per (j, r)
  const placed = new Float64Array(2 * 32); // centres of the labels placed in this draw
  let placedCount = 0;
  // The knot strip: distinct knots, their multiplicities and value labels (rebuilt on knot changes).
  const distinct = new Float64Array(MAX_POINTS + MAX_DEGREE + 1);
  const multiplicity = new Uint8Array(MAX_POINTS + MAX_DEGREE + 1);
  let distinctCount = 0;
  let distinctLabels = []; // "1", "3/2" …
  let multiplicityLabels = []; // "×4" …
  let spanCaption = ""; // "[u₄, u₅)" (rebuilt when the span changes)
  let uCaption = ""; // "u = 3/2"
  let knotsKey = ""; // the knot vector the strip arrays were built for

  // ------------------------------------------------------------ figure
  // The knot strip below the world window.
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets: scaledInsets(0, 0, STRIP_PX, 0) });
  // A taller figure than the default 16:10: the curve and the knot strip share it.
  ctx.slots.figure.style.aspectRatio = "4 / 3";

  // The knot strip claims the pointer before the handles: press or drag there to set u.
  let draggingU = false;
  view.addInteractor({
    pointerDown(event, x, y) {
      if (!inStrip(x, y)) return false;
      player.stop();
      draggingU = true;
      setU(uAtPixel(x), false);
      return true;
    },
    pointerMove(event, x) {
      if (draggingU) setU(uAtPixel(x), false);
    },
    pointerUp(event, x) {
      if (!draggingU) return;
      draggingU = false;
      setU(uAtPixel(x), true);
    },
    hover(x, y) {
      if (!inStrip(x, y)) return null;
      handles.leave();
      return "col-resize";
    },
    leave() {},
  });

  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
  });

  // ------------------------------------------------------------ side panel
  const [a0, b0] = domainOf(work);
  const uSlider = slider({
    label: t("deBoor.control.u"),
    inputLabel: t("deBoor.control.u.input"),
    name: "u",
    min: a0,
    max: b0,
    step: (b0 - a0) * U_SLIDER_RESOLUTION,
    value: work.u,
    onChange: (value, final) => {
      player.stop();
      setU(value, final);
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const player = new Player(view, {
    get: () => work.u,
    set: (value, final) => setU(value, final),
    stopped: () => ctx.commit(work),
    range: () => domainOf(work),
    stepBackTitle: t("deBoor.control.stepBack.title"),
    stepTitle: t("deBoor.control.stepForward.title"),
  });
  const spanText = el("p", { class: "sl-readout", dataset: { info: "span" }, "aria-live": "polite" });
  const degreeSlider = slider({
    label: t("deBoor.control.degree"),
    inputLabel: t("deBoor.control.degree.input"),
    name: "degree",
    min: 1,
    max: MAX_DEGREE,
    step: 1,
    value: work.degree,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => {
      if (final) setDegree(Math.round(value));
    },
    onError: (text) => ctx.status(t("deBoor.degreeRange", { value: text, max: Math.min(MAX_DEGREE, work.points.length - 1) }), "error"),
  });
  const knotsLabelId = `sl-knots-${Math.random().toString(36).slice(2, 8)}`;
  const knotsInput = el("input", { type: "text", id: knotsLabelId, class: "sl-value sl-wide", inputmode: "decimal", spellcheck: "false", "aria-describedby": `${knotsLabelId}-help` });
  const knotsHelp = el("p", { class: "sl-note", id: `${knotsLabelId}-help` });
  knotsInput.addEventListener("change", () => applyTypedKnots());
  knotsInput.addEventListener("keydown", (event) => {
    if (event.key === "Enter") applyTypedKnots();
  });
  const clampedButton = button({ label: t("deBoor.control.clamped"), title: t("deBoor.control.clamped.title"), name: "clamped-knots", onClick: () => resetKnots() });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const addButton = button({ label: t("control.addPoint"), title: t("deBoor.control.addPoint.title"), name: "add-point", onClick: () => addPoint(handles.selected) });
  const removeButton = button({ label: t("control.removePoint"), title: t("deBoor.control.removePoint.title"), name: "remove-point", onClick: () => removePoint(handles.selected) });
  const constructionBox = checkbox({
    label: t("control.construction"),
    name: "construction",
    checked: work.construction,
    onChange: (on) => {
      work.construction = on;
      view.requestDraw();
      ctx.commit(work);
    },
  });
  ctx.slots.controls.append(
    group(null, uSlider.element, player.element, spanText),
    group(
      null,
      degreeSlider.element,
      el("div", { class: "sl-control", dataset: { control: "knots" } }, el("label", { for: knotsLabelId, text: t("deBoor.control.knots") }), knotsInput),
      knotsHelp,
      el("div", { class: "sl-button-row" }, clampedButton),
    ),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
    group(null, constructionBox.element),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("de-boor");
  ctx.slots.details.append(tableTitle, tableWrap);
  let tableDegree = -1;
  let tableCells = []; // per triangle point: { name, exact, decimal, alpha } spans

  function setU(value, final) {
    work.u = value;
    uSlider.set(value);
    uDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  // ------------------------------------------------------------ edits

  /**
   * Replaces the wasm curve after the points, degree or knots changed; `next` holds the new
   * points/degree/knots. Builds first (the core may refuse), then frees the old curve.
   * Returns false (and says why) when the core refused.
   */
  function rebuild(next) {
    const built = buildOrReport(() => new sl.BSplineCurve(flatten(next.points), 2, next.degree, next.knots), ctx);
    if (!built) return false;
    player.stop();
    curve.free();
    curve = built;
    const [a, b] = domainOf(work);
    work.points = next.points;
    work.degree = next.degree;
    work.knots = next.knots;
    // Keep u at the same place relative to the domain.
    const [a1, b1] = domainOf(work);
    work.u = Math.min(b1, Math.max(a1, a1 + ((work.u - a) / (b - a)) * (b1 - a1)));
    syncDomain();
    geometryDirty = uDirty = true;
    view.requestDraw();
    return true;
  }

  /** The clamped uniform knot vector for these points and degree, from the core. */
  function clampedKnots(points, p) {
    return Array.from(sl.knotVector(flatten(points), 2, p, "clamped"));
  }

  function setDegree(p) {
    const max = Math.min(MAX_DEGREE, work.points.length - 1);
    if (p < 1 || p > max) {
      ctx.status(t("deBoor.degreeRange", { value: p, max }), "error");
      degreeSlider.set(work.degree);
      return;
    }
    if (p === work.degree) return;
    if (rebuild({ points: work.points, degree: p, knots: clampedKnots(work.points, p) })) {
      ctx.status(t("deBoor.knotsReset"), "info");
      ctx.commit(work);
    } else degreeSlider.set(work.degree);
  }

  /** Reads the typed knot vector (numbers or fractions, separated by spaces or commas). */
  function applyTypedKnots() {
    const parts = knotsInput.value.trim().split(/[\s,;]+/).filter(Boolean);
    const values = parts.map(parseNumberInput);
    const bad = parts.find((part, i) => !Number.isFinite(values[i]));
    if (bad !== undefined) {
      ctx.status(t("control.badNumber", { value: bad }), "error");
      return;
    }
    const candidate = { ...structuredClone(work), knots: values };
    const [a, b] = [values[work.degree], values[work.points.length]];
    if (a < b) candidate.u = Math.min(b, Math.max(a, work.u));
    try {
      validate(candidate);
    } catch (err) {
      ctx.status(t("status.rejected", { message: err.message }), "error");
      return;
    }
    if (values.every((v, i) => v === work.knots[i])) return;
    if (rebuild({ points: work.points, degree: work.degree, knots: values })) ctx.commit(work);
  }

  function resetKnots() {
    const knots = clampedKnots(work.points, work.degree);
    if (knots.every((v, i) => v === work.knots[i])) return;
    if (rebuild({ points: work.points, degree: work.degree, knots })) ctx.commit(work);
  }

  /** Adds a point after handle i (at the end when none is selected); knots become clamped uniform. */
  function addPoint(i) {
    const next = withPointAdded(work.points, i, MAX_POINTS, view.scale);
    if (!next) return ctx.status(t("deBoor.maxPoints", { max: MAX_POINTS }), "error");
    if (!rebuild({ points: next.points, degree: work.degree, knots: clampedKnots(next.points, work.degree) })) return;
    handles.select(next.index);
    ctx.status(t("deBoor.knotsReset"), "info");
    ctx.commit(work);
  }

  /** Removes handle i (the last one when none is selected); the degree drops if it must. */
  function removePoint(i) {
    const next = withPointRemoved(work.points, i, MIN_POINTS);
    if (!next) return ctx.status(t("deBoor.minPoints", { min: MIN_POINTS }), "error");
    const p = Math.min(work.degree, next.points.length - 1);
    if (!rebuild({ points: next.points, degree: p, knots: clampedKnots(next.points, p) })) return;
    handles.select(next.index);
    ctx.status(t("deBoor.knotsReset"), "info");
    ctx.commit(work);
  }

  /** Slider range, degree and knot text follow the state's knots and degree. */
  function syncDomain() {
    const [a, b] = domainOf(work);
    uSlider.setRange(a, b, (b - a) * U_SLIDER_RESOLUTION);
    uSlider.set(work.u);
    degreeSlider.set(work.degree);
    const text = work.knots.map(numberText).join(" ");
    if (knotsInput.value !== text && document.activeElement !== knotsInput && knotsInput.getRootNode().activeElement !== knotsInput) knotsInput.value = text;
    knotsHelp.textContent = t("deBoor.knotsHelp", { m: work.knots.length, count: work.points.length, p: work.degree });
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for the triangle, the span and the samples when something changed. */
  function recompute() {
    if (geometryDirty) {
      samples = curve.sampleUniform(CURVE_SAMPLES);
    }
    if (geometryDirty || uDirty) {
      triangle = curve.deBoor(work.u);
      span = curve.span(work.u);
      alphaData = curve.deBoorAlphas(work.u);
      syncPanels();
    }
    geometryDirty = uDirty = false;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;
    const p = work.degree;

    // Control polygon, then its active part (the p + 1 points of the span) solid.
    pointsPath(r, v, pts, 0, n + 1);
    r.paint(theme.polygon);
    if (work.construction) {
      flatPath(r, v, triangle, 0, p + 1);
      r.paint(theme.axis);
    }

    // The curve, from one batched sample call.
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // Centroid of the active points on screen: labels go on the side away from it.
    let cx = 0;
    let cy = 0;
    for (let j = 0; j <= p; j++) {
      cx += v.sx(triangle[2 * j]);
      cy += v.sy(triangle[2 * j + 1]);
    }
    cx /= p + 1;
    cy /= p + 1;
    placedCount = 0;
    const finalOffset = levelStart(p, p);
    const px = v.sx(triangle[2 * finalOffset]);
    const py = v.sy(triangle[2 * finalOffset + 1]);
    if (work.construction) {
      // Level r holds d_r^r … d_p^r (p + 1 − r points), stored after the levels before it.
      for (let level = 1; level < p; level++) {
        const offset = levelStart(p, level);
        const count = p + 1 - level;
        const colour = (level - 1) % theme.levelStroke.length;
        r.beginPath();
        for (let i = 0; i < count; i++) {
          const x = v.sx(triangle[2 * (offset + i)]);
          const y = v.sy(triangle[2 * (offset + i) + 1]);
          if (i === 0) r.moveTo(x, y);
          else r.lineTo(x, y);
        }
        r.paint(theme.levelStroke[colour]);
        for (let i = 0; i < count; i++) {
          const x = v.sx(triangle[2 * (offset + i)]);
          const y = v.sy(triangle[2 * (offset + i) + 1]);
          r.point(x, y, theme.levelPoint[colour]);
          if (p <= LABEL_LEVELS_MAX_DEGREE) drawLegLabel(r, v, p, level, i, levelLabel(level + i, level), x, y, cx, cy, theme.labelSmall, theme.levelPoint[colour].radius * r.scale);
        }
      }
    }
    handles.draw(r, v);

    // The point C(u) = d_p^p, labelled beside the last construction leg.
    r.point(px, py, theme.pointOnCurve);
    if (p >= 1) drawLegLabel(r, v, p, p, 0, t("deBoor.pointLabel"), px, py, cx, cy, theme.labelPoint, theme.pointOnCurve.radius * r.scale);

    drawStrip(r, theme);
  }

  /** "d₂¹" for d_j^r (cached strings). */
  function levelLabel(j, level) {
    const key = level * (MAX_DEGREE + 2) + j;
    return (levelLabels[key] ??= `d${subscript(j)}${superscript(level)}`);
  }

  /**
   * Labels in-level point i of level r (r ≥ 1) beside the leg of level r − 1 that it divides.
   * Of six directions (the leg's two normals and the four diagonals between normal and leg), the
   * one whose label centre keeps farthest from the other construction points, the control points
   * and the labels already placed wins, the normals slightly preferred; (cx, cy), the active
   * points' centroid, breaks ties (outside the construction).
   */
  function drawLegLabel(r, v, p, level, i, text, x, y, cx, cy, style, radius) {
    const a = levelStart(p, level - 1) + i;
    let nx = v.sy(triangle[2 * a + 1]) - v.sy(triangle[2 * a + 3]);
    let ny = v.sx(triangle[2 * a + 2]) - v.sx(triangle[2 * a]);
    const length = Math.hypot(nx, ny);
    if (length < 1) {
      nx = -Math.SQRT1_2; // degenerate leg: above left
      ny = -Math.SQRT1_2;
    } else {
      nx /= length;
      ny /= length;
    }
    if ((x - cx) * nx + (y - cy) * ny < 0) {
      nx = -nx;
      ny = -ny;
    }
    // Leg direction (unit), perpendicular to the normal.
    const lx = -ny;
    const ly = nx;
    const reach = radius + LABEL_PROBE_PX * r.scale;
    const self = levelStart(p, level) + i;
    let bestX = nx;
    let bestY = ny;
    let bestScore = -Infinity;
    for (let c = 0; c < LABEL_DIRECTIONS.length; c += 3) {
      const dx = LABEL_DIRECTIONS[c] * nx + LABEL_DIRECTIONS[c + 1] * lx;
      const dy = LABEL_DIRECTIONS[c] * ny + LABEL_DIRECTIONS[c + 1] * ly;
      const qx = x + dx * reach;
      const qy = y + dy * reach;
      let score = Infinity;
      const count = levelStart(p, p + 1);
      for (let k = 0; k < count; k++) {
        if (k !== self) score = Math.min(score, Math.hypot(v.sx(triangle[2 * k]) - qx, v.sy(triangle[2 * k + 1]) - qy));
      }
      for (let k = 0; k < work.points.length; k++) score = Math.min(score, Math.hypot(v.sx(work.points[k][0]) - qx, v.sy(work.points[k][1]) - qy));
      for (let k = 0; k < placedCount; k++) score = Math.min(score, Math.hypot(placed[2 * k] - qx, placed[2 * k + 1] - qy));
      score += LABEL_DIRECTIONS[c + 2] * r.scale;
      if (score > bestScore) {
        bestScore = score;
        bestX = dx;
        bestY = dy;
      }
    }
    if (placedCount < placed.length / 2) {
      placed[2 * placedCount] = x + bestX * reach;
      placed[2 * placedCount + 1] = y + bestY * reach;
      placedCount += 1;
    }
    placeLabelAt(r, text, x, y, bestX, bestY, radius, style);
  }

  /** Index (in points) where level `level` starts in a degree-p de Boor triangle. */
  function levelStart(p, level) {
    // Levels 0 … level-1 hold (p+1) + p + … + (p + 2 - level) points.
    return level * (p + 1) - (level * (level - 1)) / 2;
  }

  // ------------------------------------------------------------ knot strip
  const strip = { x0: 0, x1: 0, y: 0, top: 0, lo: 0, hi: 1 };

  /** Lays out the knot line for a canvas of width × height CSS px at text scale `scale`. */
  function layoutStrip(width, height, scale) {
    strip.top = height - STRIP_PX * scale;
    strip.x0 = STRIP_MARGIN_X * scale;
    strip.x1 = width - STRIP_MARGIN_X * scale;
    strip.y = strip.top + STRIP_LINE_Y * scale;
    strip.lo = work.knots[0];
    strip.hi = work.knots[work.knots.length - 1];
  }

  const kx = (u) => strip.x0 + ((u - strip.lo) / (strip.hi - strip.lo)) * (strip.x1 - strip.x0);

  function inStrip(x, y) {
    layoutStrip(view.width, view.height, view.renderer.scale);
    const reach = STRIP_HIT_PX * view.renderer.scale;
    return y >= strip.top && y <= strip.y + reach && x >= strip.x0 - reach && x <= strip.x1 + reach;
  }

  /** u under canvas x, clamped to the domain and snapped to the slider's resolution. */
  function uAtPixel(x) {
    layoutStrip(view.width, view.height, view.renderer.scale);
    const [a, b] = domainOf(work);
    const raw = strip.lo + ((x - strip.x0) / (strip.x1 - strip.x0)) * (strip.hi - strip.lo);
    const h = (b - a) * U_SLIDER_RESOLUTION;
    return Math.min(b, Math.max(a, a + Math.round((raw - a) / h) * h));
  }

  /** The knot vector on a line: domain solid, outside dashed, the active span shaded, u marked. */
  function drawStrip(r, theme) {
    layoutStrip(r.width, r.height, r.scale);
    const s = r.scale;
    const y = strip.y;
    const a = work.knots[work.degree]; // the domain [u_p, u_{n+1}]
    const b = work.knots[work.points.length];
    // Separator between the figure and the strip.
    r.beginPath();
    r.moveTo(0, strip.top);
    r.lineTo(r.width, strip.top);
    r.paint(theme.helper);
    // The active span [u_k, u_{k+1}).
    const xs0 = kx(work.knots[span]);
    const xs1 = kx(work.knots[span + 1]);
    r.beginPath();
    r.rect(xs0, y - STRIP_SPAN_HALF * s, xs1 - xs0, 2 * STRIP_SPAN_HALF * s);
    r.paint(theme.helperFill);
    // The knot line: outside the domain dashed, the domain solid.
    r.beginPath();
    r.moveTo(kx(strip.lo), y);
    r.lineTo(kx(strip.hi), y);
    r.paint(theme.helper);
    r.beginPath();
    r.moveTo(kx(a), y);
    r.lineTo(kx(b), y);
    r.paint(theme.axis);
    // Ticks, values below, multiplicities above.
    let lastRight = -Infinity;
    const digit = theme.labelSmall.size * s * CHAR_EM;
    for (let i = 0; i < distinctCount; i++) {
      const x = kx(distinct[i]);
      r.beginPath();
      r.moveTo(x, y - STRIP_TICK * s);
      r.lineTo(x, y + STRIP_TICK * s);
      r.paint(theme.axis);
      const label = distinctLabels[i];
      const half = (label.length * digit) / 2;
      if (x - half > lastRight + STRIP_LABEL_GAP * s) {
        r.text(label, x, y + (STRIP_TICK + 4) * s, theme.labelSmall, "center", "top");
        lastRight = x + half;
      }
      if (multiplicity[i] > 1) r.text(multiplicityLabels[i], x, y - (STRIP_TICK + 3) * s, theme.labelSmall, "center", "bottom");
    }
    // The span's name above the shaded span; u marked on the line.
    r.text(spanCaption, (xs0 + xs1) / 2, strip.top + 4 * s, theme.labelSmall, "center", "top");
    const xu = kx(work.u);
    r.beginPath();
    r.moveTo(xu, y - STRIP_MARKER_HALF * s);
    r.lineTo(xu, y + STRIP_MARKER_HALF * s);
    r.paint(theme.marker);
    r.point(xu, y, theme.pointOnCurve);
    r.text(uCaption, xu, y + (STRIP_MARKER_HALF + 14) * s, theme.labelPoint, "center", "top");
  }

  /** Distinct knots, multiplicities and their labels (only when the knot vector changed). */
  function syncStrip() {
    const key = work.knots.join(" ");
    if (key === knotsKey) return;
    knotsKey = key;
    distinctCount = 0;
    for (let i = 0; i < work.knots.length; i++) {
      if (distinctCount > 0 && work.knots[i] === distinct[distinctCount - 1]) multiplicity[distinctCount - 1] += 1;
      else {
        distinct[distinctCount] = work.knots[i];
        multiplicity[distinctCount] = 1;
        distinctCount += 1;
      }
    }
    distinctLabels = [];
    multiplicityLabels = [];
    for (let i = 0; i < distinctCount; i++) {
      distinctLabels.push(numberText(distinct[i]));
      multiplicityLabels.push(t("deBoor.multiplicity", { r: multiplicity[i] }));
    }
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    if (!triangle) return;
    syncStrip();
    const pts = work.points;
    const knots = work.knots;
    const n = pts.length - 1;
    const p = work.degree;
    const k = span;
    const last = 2 * levelStart(p, p);
    const x = triangle[last];
    const y = triangle[last + 1];
    const uText = numberText(work.u);
    const uTex = numberTex(work.u);
    spanCaption = t("deBoor.spanCaption", { k: subscript(k), k1: subscript(k + 1) });
    uCaption = t("deBoor.uCaption", { u: uText });

    view.setLabel(t("deBoor.aria", { kind: degreeName(p), count: n + 1, knots: knots.map(numberText).join(" "), u: fmt(work.u), k, uk: numberText(knots[k]), uk1: numberText(knots[k + 1]), x: fmt(x, 2), y: fmt(y, 2) }));
    degreeText.textContent = t("deBoor.degree", { p, count: n + 1, segments: curve.spans().length });
    spanText.textContent = t("deBoor.span", { k, ks: subscript(k), ks1: subscript(k + 1), uk: numberText(knots[k]), uk1: numberText(knots[k + 1]) });
    spanText.dataset.span = String(k);
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;

    // The α of every step, α_j^r = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p}), as the core's
    // deBoorAlphas(u) gives them (level by level, j ascending), grouped by level for display.
    const alphas = [];
    for (let a = 0; a < alphaData.length; a += 6) {
      const level = alphaData[a];
      if (alphas.length < level) alphas.push([]);
      alphas[level - 1].push({ j: alphaData[a + 1], lo: alphaData[a + 2], hi: alphaData[a + 3], width: alphaData[a + 4], value: alphaData[a + 5] });
    }

    // Exact fractions when u is a simple fraction and every point and knot is an integer: the
    // denominator of a level-r point divides the product of its α denominators (bound tracked per cell).
    const uFraction = simpleFraction(work.u);
    const exact = uFraction && allIntegers(pts.flat()) && allIntegers(knots) ? uFraction : null;
    const alphaFraction = (alpha) => (exact ? exactFraction(alpha.value, exact.den * alpha.width) : null);
    const dens = [new Array(p + 1).fill(1)];
    for (let level = 1; level <= p; level++) {
      const row = [];
      for (let i = 0; i <= p - level; i++) {
        const f = alphaFraction(alphas[level - 1][i]);
        const bound = f ? lcm(dens[level - 1][i], dens[level - 1][i + 1]) * f.den : Infinity;
        row.push(bound <= MAX_EXACT_DENOMINATOR ? bound : Infinity);
      }
      dens.push(row);
    }
    const coord = (value, level, i, tex) => {
      const den = dens[level][i];
      const f = exact && Number.isFinite(den) ? exactFraction(value, den) : null;
      if (!f) return fmt(value);
      return tex ? fractionTex(f) : fractionText(f);
    };
    const alphaText = (alpha, tex) => {
      const f = alphaFraction(alpha);
      if (f) return tex ? fractionTex(f) : fractionText(f);
      return fmt(alpha.value);
    };

    // Formula panel: the span and the active points, the recurrence, the live α, the point.
    const shift = k - p;
    const active = shift === 0 ? "P_{j}" : `P_{j${shift > 0 ? "+" : "-"}${Math.abs(shift)}}`;
    const lines = [
      `u = ${uTex} \\in [u_{${k}}, u_{${k + 1}}) = [${numberTex(knots[k])}, ${numberTex(knots[k + 1])}),\\quad k = ${k},\\quad d_j^0 = P_{j+k-p} = ${active},\\ j = 0,\\dots,${p}`,
      `d_j^r = (1-\\alpha_j^r)\\,d_{j-1}^{r-1} + \\alpha_j^r\\,d_j^{r-1},\\quad \\alpha_j^r = \\frac{u - u_{j+k-p}}{u_{j+1+k-r} - u_{j+k-p}}\\quad (r = 1,\\dots,${p};\\ j = ${p},\\dots,r)`,
    ];
    for (let level = 1; level <= p; level++) {
      const parts = alphas[level - 1].map((alpha) => `\\alpha_{${alpha.j}}^{${level}} = \\tfrac{u - u_{${alpha.lo}}}{u_{${alpha.hi}} - u_{${alpha.lo}}} = ${alphaText(alpha, true)}`);
      lines.push(`r = ${level}:\\quad ${parts.join(",\\quad ")}`);
    }
    const point = `\\left(${coord(x, p, 0, true)},\\ ${coord(y, p, 0, true)}\\right)`;
    const approx = exact && (!Number.isInteger(x) || !Number.isInteger(y)) && Number.isFinite(dens[p][0]) ? `\\approx (${fmt(x)},\\ ${fmt(y)})` : "";
    lines.push(`C(${uTex}) = d_{${p}}^{${p}} = ${point} ${approx}`);
    formula.set(lines);

    // Table: one row per level r, cells d_j^r (fraction and decimals) with the α that made them.
    if (tableDegree !== p) buildTable(p);
    setText(tableTitle, t("deBoor.tableCaption", { u: uText, k }));
    let c = 0;
    for (let level = 0; level <= p; level++) {
      for (let i = 0; i <= p - level; i++, c++) {
        const j = level + i;
        const cx = triangle[2 * c];
        const cy = triangle[2 * c + 1];
        const decimalText = `(${fmt(cx)}, ${fmt(cy)})`;
        const exactText = exact ? `(${coord(cx, level, i, false)}, ${coord(cy, level, i, false)})` : decimalText;
        const cells = tableCells[c];
        setText(cells.name, level === 0 ? `d${subscript(j)}${superscript(0)} = P${subscript(j + k - p)} ` : `d${subscript(j)}${superscript(level)} = `);
        setText(cells.exact, exactText);
        // Decimals underneath only when they say something the exact value does not.
        setText(cells.decimal, exactText === decimalText || /^\(-?\d+, -?\d+\)$/.test(exactText) ? "" : `≈ ${decimalText}`);
        if (level > 0) {
          const alpha = alphas[level - 1][i];
          setText(cells.alpha, t("deBoor.alphaCell", { value: alphaText(alpha, false) }));
          cells.alpha.dataset.alpha = fmt(alpha.value);
        }
      }
    }
  }

  /** Rebuilds the table's rows for degree p (only when the degree changed). */
  function buildTable(p) {
    tableDegree = p;
    tableCells = [];
    const rows = [];
    for (let level = 0; level <= p; level++) {
      const cells = [el("th", { scope: "row", text: t("deBoor.tableLevel", { r: level }) })];
      for (let j = level; j <= p; j++) {
        const spans = {
          name: el("span", { class: "sl-cell-name" }),
          exact: el("span", { class: "sl-cell-value" }),
          decimal: el("span", { class: "sl-cell-decimal" }),
          alpha: el("span", { class: "sl-cell-decimal" }),
        };
        tableCells.push(spans);
        cells.push(el("td", { dataset: { level: String(level), index: String(j) } }, spans.name, spans.exact, spans.decimal, level > 0 ? spans.alpha : null));
      }
      rows.push(el("tr", {}, cells));
    }
    table.replaceChildren(el("tbody", {}, rows));
  }

  syncDomain();
  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BSplineCurve(flatten(state.points), 2, state.degree, state.knots); // throws before anything changes
      player.stop();
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      constructionBox.set(work.construction);
      syncDomain();
      geometryDirty = uDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      player.destroy();
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** The domain [u_p, u_{n+1}] of a state (read off its knot vector). */
function domainOf(state) {
  return [state.knots[state.degree], state.knots[state.points.length]];
}
