/**
 * Demo 3 (syllabus §2): subdivision. `curve.split(t0)` cuts a Bézier curve into two Bézier
 * curves of the same degree whose control polygons are the two outer edges of the de Casteljau
 * triangle at t0: left l_i = p_0^i(t0) (top edge), right r_i = p_i^{n−i}(t0) (hypotenuse).
 * A "levels" control repeats the split at 1/2: after k levels the 2^k polygons (from
 * 2^k − 1 `split(0.5)` calls, every intermediate wasm object freed) hug the curve.
 *
 * Same habits as the reference demo (de-casteljau.js): the curve lives in wasm and is updated in
 * place while dragging, everything drawn comes from the core (`sampleUniform`, `split`,
 * `deCasteljau`), the draw path allocates nothing and replaced wasm objects are freed.
 */
import { Handles, placeLabel, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, checkbox, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkBoolean } from "../lib/validate.js";
import { fmt, subscript, superscript, simpleFraction, exactFraction, fractionText, fractionTex, allIntegers, degreeName } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { pointListActions, pointButtons } from "../lib/point-list.js";
import { Player } from "../lib/player.js";
import { titledTable, valueSpans, setValueSpans } from "../lib/table.js";
import { flatPath, pointsPath } from "../lib/draw.js";

export const id = "subdivision";
/** Prefix of this demo's keys in strings.js. */
export const strings = "subdivision";
export const title = t("subdivision.title");
export const summary = t("subdivision.summary");
/** Syllabus section. */
export const section = 2;

/** The worked example of the Greek notes (syllabus §2), split in the middle. */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 2], [6, 4], [8, 2]].map(Object.freeze)),
  t: 0.5,
  levels: 0,
  triangle: true,
});

/** Fewest and most control points (degree 1 … 10). */
export const MIN_POINTS = 2;
export const MAX_POINTS = 11;
/** Repeated subdivision at 1/2: at most this many levels (2^6 = 64 polygons). */
export const MAX_LEVELS = 6;
/** Repeated subdivision always splits at this parameter. */
const HALF = 0.5;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Slider resolution for t0. */
const T_SLIDER_STEP = 0.001;
/** Left/right points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_MAX_DEGREE = 6;
/** Fitting leaves this fraction of the width free on each side for the long end labels "P₀ = L₀". */
const END_LABEL_ROOM = 0.12;
/** Points of the level polygons are drawn up to this level (beyond, they make a solid line). */
const LEVEL_POINTS_MAX = 3;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "t", "levels", "triangle"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "t", { min: 0, max: 1 });
  checkNumber(state, "levels", { min: 0, max: MAX_LEVELS, integer: true });
  checkBoolean(state, "triangle");
}

/**
 * The control points of the 2^levels pieces of `curve` after `levels` rounds of splitting every
 * piece at 1/2 (2^levels − 1 `split` calls), flat, piece after piece. Every intermediate wasm
 * object is freed, also when a call throws.
 */
function subdivide(curve, levels) {
  if (levels === 0) return curve.controlPoints();
  let pieces = curve.split(HALF);
  try {
    for (let level = 2; level <= levels; level++) {
      const next = [];
      try {
        for (const piece of pieces) next.push(...piece.split(HALF));
      } catch (err) {
        for (const piece of next) piece.free();
        throw err;
      }
      for (const piece of pieces) piece.free();
      pieces = next;
    }
    const perPiece = 2 * (curve.degree + 1);
    const flat = new Float64Array(pieces.length * perPiece);
    pieces.forEach((piece, j) => flat.set(piece.controlPoints(), j * perPiece));
    return flat;
  } finally {
    for (const piece of pieces) piece.free();
  }
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = new sl.BezierCurve(flatten(work.points), 2);

  // Derived data, recomputed only when the geometry, t0 or the level changed.
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let left = null; // control points of split(t0)[0], flat
  let right = null; // control points of split(t0)[1], flat
  let triangle = null; // curve.deCasteljau(t0)
  let pieces = null; // subdivide(curve, levels): 2^levels polygons, flat
  let geometryDirty = true;
  let tDirty = true;
  let levelsDirty = true;
  const handleLabels = []; // "P₀", or "P₀ = L₀" at the ends while the split is shown
  const sideLabels = []; // "L₁", "R₂" … cached per (side, i)
  let splitLabel = ""; // "L₃ = R₀"

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => paddedBounds(work.points, END_LABEL_ROOM) });
  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }, handleLabel),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => edits.add(i),
    remove: (i) => edits.remove(i),
  });

  // ------------------------------------------------------------ side panel
  const tSlider = slider({
    label: t("subdivision.control.t"),
    inputLabel: t("subdivision.control.t.input"),
    name: "t",
    min: 0,
    max: 1,
    step: T_SLIDER_STEP,
    value: work.t,
    onChange: (value, final) => setT(value, final),
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const stepper = new Player(view, {
    get: () => work.t,
    set: (value, final) => setT(value, final),
    playable: false,
    stepBackTitle: t("subdivision.control.stepBack.title"),
    stepTitle: t("subdivision.control.stepForward.title"),
  });
  const levelsSlider = slider({
    label: t("subdivision.control.levels"),
    inputLabel: t("subdivision.control.levels.input"),
    name: "levels",
    min: 0,
    max: MAX_LEVELS,
    step: 1,
    value: work.levels,
    format: (v) => String(v),
    onChange: (value, final) => setLevels(Math.round(value), final),
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const levelsText = el("p", { class: "sl-note", dataset: { info: "levels" } });
  const triangleBox = checkbox({
    label: t("subdivision.control.triangle"),
    name: "triangle",
    checked: work.triangle,
    onChange: (on) => {
      work.triangle = on;
      view.requestDraw();
      ctx.commit(work);
    },
  });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: (i) => edits.add(i), remove: (i) => edits.remove(i), selected: () => handles.selected });
  ctx.slots.controls.append(
    group(null, tSlider.element, stepper.element, triangleBox.element),
    group(null, levelsSlider.element, levelsText),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("subdivision");
  ctx.slots.details.append(tableTitle, tableWrap);
  let tableDegree = -1;
  let tableCells = []; // per i: { left: { exact, decimal }, right: { exact, decimal } }

  // ------------------------------------------------------------ edits
  function setT(value, final) {
    work.t = value;
    tSlider.set(value);
    tDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  function setLevels(value, final) {
    const levels = Math.min(MAX_LEVELS, Math.max(0, value));
    if (levels !== work.levels) {
      work.levels = levels;
      levelsDirty = true;
      view.requestDraw();
    }
    levelsSlider.set(levels);
    if (final) ctx.commit(work);
  }

  /** Replaces the wasm curve after the number of points changed (the old one is freed). */
  function rebuild() {
    const next = new sl.BezierCurve(flatten(work.points), 2);
    curve.free();
    curve = next;
    geometryDirty = true;
    view.requestDraw();
  }

  const edits = pointListActions({ ctx, work, view, handles, min: MIN_POINTS, max: MAX_POINTS, strings: "subdivision", rebuild });

  // ------------------------------------------------------------ core data
  /** Asks the core for the samples, the split, the triangle and the levels when something changed. */
  function recompute() {
    if (geometryDirty) samples = curve.sampleUniform(CURVE_SAMPLES);
    if (geometryDirty || tDirty) {
      const [l, r] = curve.split(work.t);
      left = l.controlPoints();
      right = r.controlPoints();
      l.free();
      r.free();
      triangle = curve.deCasteljau(work.t);
    }
    if (geometryDirty || levelsDirty) pieces = subdivide(curve, work.levels);
    if (geometryDirty || tDirty || levelsDirty) syncPanels();
    geometryDirty = tDirty = levelsDirty = false;
  }

  // ------------------------------------------------------------ drawing
  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;
    const showSplit = work.levels === 0;

    // The de Casteljau triangle at t0, faint: its inner levels (the outer edges are L and R).
    if (showSplit && work.triangle) {
      let offset = n + 1;
      r.beginPath();
      for (let level = 1; level < n; level++) {
        const count = n + 1 - level;
        for (let j = 0; j < count; j++) {
          const x = v.sx(triangle[2 * (offset + j)]);
          const y = v.sy(triangle[2 * (offset + j) + 1]);
          if (j === 0) r.moveTo(x, y);
          else r.lineTo(x, y);
        }
        offset += count;
      }
      r.paint(theme.helper);
    }

    // The original control polygon.
    pointsPath(r, v, pts, 0, n + 1);
    r.paint(theme.polygon);

    // The curve, from one batched sample call.
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // Repeated subdivision: 2^k polygons in two alternating colours, over
    // the curve so that their approach to it stays visible.
    if (!showSplit) {
      const perPiece = n + 1;
      const count = pieces.length / (2 * perPiece);
      for (let j = 0; j < count; j++) {
        const colour = j % 2;
        pathOf(r, v, pieces, j * perPiece, perPiece);
        r.paint(theme.levelStroke[colour]);
        if (work.levels <= LEVEL_POINTS_MAX) {
          for (let i = 0; i < perPiece; i++) {
            const k = 2 * (j * perPiece + i);
            r.point(v.sx(pieces[k]), v.sy(pieces[k + 1]), theme.levelPoint[colour]);
          }
        }
      }
    }

    // The two halves' control polygons: left solid with dots, right dashed with squares.
    if (showSplit) {
      pathOf(r, v, left, 0, n + 1);
      r.paint(theme.splitLeft);
      pathOf(r, v, right, 0, n + 1);
      r.paint(theme.splitRight);
      for (let i = 0; i <= n; i++) {
        r.point(v.sx(left[2 * i]), v.sy(left[2 * i + 1]), theme.splitLeftPoint);
        const size = theme.splitRightPoint.radius * r.scale;
        r.beginPath();
        r.rect(v.sx(right[2 * i]) - size, v.sy(right[2 * i + 1]) - size, 2 * size, 2 * size);
        r.paint(theme.splitRightPoint);
      }
    }

    handles.draw(r, v);

    // Centroid of the control points on screen: labels go on the side away from it.
    let cx = 0;
    let cy = 0;
    for (let i = 0; i <= n; i++) {
      cx += v.sx(pts[i][0]);
      cy += v.sy(pts[i][1]);
    }
    cx /= n + 1;
    cy /= n + 1;
    if (showSplit && n <= LABEL_MAX_DEGREE) {
      for (let i = 1; i < n; i++) {
        labelOutward(r, v, sideLabel(0, i), left, i, n, cx, cy, theme.labelSmall, theme.splitLeftPoint.radius * r.scale);
        labelOutward(r, v, sideLabel(1, i), right, i, n, cx, cy, theme.labelSmall, theme.splitRightPoint.radius * r.scale);
      }
    }

    // The split point P(t0) = l_n = r_0.
    const sx = v.sx(right[0]);
    const sy = v.sy(right[1]);
    r.point(sx, sy, theme.pointOnCurve);
    labelAway(r, showSplit ? splitLabel : t("subdivision.splitPointLabel"), sx, sy, cx, cy, theme.labelPoint, theme.pointOnCurve.radius * r.scale);
  }

  /** Starts a path along `count` points of the flat array `flat` from point `start` (the caller paints it). */
  function pathOf(r, v, flat, start, count) {
    r.beginPath();
    for (let i = 0; i < count; i++) {
      const k = 2 * (start + i);
      const x = v.sx(flat[k]);
      const y = v.sy(flat[k + 1]);
      if (i === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
  }

  /**
   * Labels inner point i of a half's polygon (flat, n + 1 points) outside it: perpendicular to
   * the chord from its first to its last point, on the side the point lies (the half's curve
   * runs between the polygon and that chord). Points on the chord fall back to `labelAway`.
   */
  function labelOutward(r, v, text, flat, i, n, cx, cy, style, radius) {
    const x = v.sx(flat[2 * i]);
    const y = v.sy(flat[2 * i + 1]);
    const ax = v.sx(flat[0]);
    const ay = v.sy(flat[1]);
    let nx = ay - v.sy(flat[2 * n + 1]);
    let ny = v.sx(flat[2 * n]) - ax;
    const length = Math.hypot(nx, ny);
    const side = length > 0 ? ((x - ax) * nx + (y - ay) * ny) / length : 0;
    if (Math.abs(side) < 1) {
      labelAway(r, text, x, y, cx, cy, style, radius);
      return;
    }
    nx /= side > 0 ? length : -length;
    ny /= side > 0 ? length : -length;
    placeLabel(r, text, x, y, nx, ny, radius, style);
  }

  /** Labels the point (x, y) on the side away from the screen point (cx, cy). */
  function labelAway(r, text, x, y, cx, cy, style, radius) {
    let dx = x - cx;
    let dy = y - cy;
    const length = Math.hypot(dx, dy);
    if (length < 1) {
      dx = 0; // at the centroid: above
      dy = -1;
    } else {
      dx /= length;
      dy /= length;
    }
    placeLabel(r, text, x, y, dx, dy, radius, style);
  }

  /** "L₁" (side 0) or "R₁" (side 1), cached. */
  function sideLabel(side, i) {
    const k = side * (MAX_POINTS + 1) + i;
    return (sideLabels[k] ??= t(side === 0 ? "subdivision.leftLabel" : "subdivision.rightLabel", { i: subscript(i) }));
  }

  /** P₀ … Pₙ; while the split is shown the ends also name what they are: P₀ = L₀, Pₙ = Rₙ. */
  function handleLabel(i) {
    const n = work.points.length - 1;
    const end = work.levels === 0 && (i === 0 || i === n);
    const k = (end ? MAX_POINTS + 1 : 0) + i;
    return (handleLabels[k] ??= end
      ? t(i === 0 ? "subdivision.firstLabel" : "subdivision.lastLabel", { p: `P${subscript(i)}`, l: `L${subscript(0)}`, r: `R${subscript(i)}` })
      : `P${subscript(i)}`);
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    const pts = work.points;
    const n = pts.length - 1;
    const k = work.levels;
    degreeText.textContent = t("subdivision.degree", { n, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;
    splitLabel = t("subdivision.splitLabel", { l: `L${subscript(n)}`, r: `R${subscript(0)}` });

    // Exact fractions when t0 is a simple fraction and every input is an integer: every point
    // of the triangle is then k / den^n.
    const tFraction = simpleFraction(work.t);
    const exact = tFraction && allIntegers(pts.flat()) ? tFraction : null;
    const den = exact ? exact.den ** n : 0;
    const tTex = tFraction ? fractionTex(tFraction) : fmt(work.t);
    const tText = tFraction ? fractionText(tFraction) : fmt(work.t);
    const coord = (value, tex) => {
      const f = den ? exactFraction(value, den) : null;
      if (!f) return fmt(value);
      return tex ? fractionTex(f) : fractionText(f);
    };
    const pointTex = (flat, i) => `\\left(${coord(flat[2 * i], true)},\\ ${coord(flat[2 * i + 1], true)}\\right)`;
    const list = (flat) => {
      const parts = [];
      for (let i = 0; i <= n; i++) parts.push(pointTex(flat, i));
      return parts.join(",\\ ");
    };

    // Levels: 2^k polygons of n + 1 points; neighbours share their end points.
    const polygons = pieces.length / (2 * (n + 1));
    const total = polygons * (n + 1);
    const distinct = polygons * n + 1;
    setText(levelsText, t(k === 0 ? "subdivision.levelsNote0" : "subdivision.levelsNote", { k, polygons, total, distinct }));

    const oneMinusTex = tFraction ? fractionTex({ num: tFraction.den - tFraction.num, den: tFraction.den }) : fmt(1 - work.t);
    formula.set([
      `l_i = p_0^{\\,i}(t_0),\\qquad r_i = p_i^{\\,${n}-i}(t_0),\\qquad i = 0,\\dots,${n},\\qquad t_0 = ${tTex}`,
      `l_{${n}} = r_0 = p_0^{${n}}(${tTex}) = P(${tTex}) = ${pointTex(right, 0)}`,
      `L:\\ ${list(left)}`,
      `R:\\ ${list(right)}`,
      `L(u) = P(${tTex}\\,u),\\qquad R(u) = P\\!\\left(${tTex} + ${oneMinusTex}\\,u\\right),\\qquad 0 \\le u \\le 1`,
      `k = ${k}:\\quad 2^{${k}} = ${polygons}\\ \\text{${t(polygons === 1 ? "subdivision.formulaPolygon" : "subdivision.formulaPolygons")}},\\quad ${polygons} \\cdot ${n + 1} = ${total}\\ \\text{${t("subdivision.formulaPoints")}}`,
    ]);

    // Table: one row per i with l_i and r_i.
    if (tableDegree !== n) buildTable(n);
    setText(tableTitle, t("subdivision.tableCaption", { t: tText }));
    for (let i = 0; i <= n; i++) {
      fillCell(tableCells[i].left, left, i, coord);
      fillCell(tableCells[i].right, right, i, coord);
    }

    const levelsAria = k === 0 ? "" : t("subdivision.ariaLevels", { k, polygons, total });
    view.setLabel(
      t("subdivision.aria", { kind: degreeName(n), count: n + 1, t: fmt(work.t), n: subscript(n), x: fmt(right[0], 2), y: fmt(right[1], 2) }) + levelsAria,
    );
  }

  /** Writes point i of `flat` into a cell: exact value first, decimals under it when different. */
  function fillCell(cell, flat, i, coord) {
    const decimalText = `(${fmt(flat[2 * i])}, ${fmt(flat[2 * i + 1])})`;
    const exactText = `(${coord(flat[2 * i], false)}, ${coord(flat[2 * i + 1], false)})`;
    setValueSpans(cell, exactText, decimalText);
  }

  /** Rebuilds the table's rows for degree n (only when the degree changed). */
  function buildTable(n) {
    tableDegree = n;
    tableCells = [];
    const head = el("tr", {},
      el("th", { scope: "col", text: t("subdivision.colIndex") }),
      el("th", { scope: "col", text: t("subdivision.colLeft") }),
      el("th", { scope: "col", text: t("subdivision.colRight") }));
    const rows = [];
    for (let i = 0; i <= n; i++) {
      const cells = {
        left: valueSpans(),
        right: valueSpans(),
      };
      tableCells.push(cells);
      const leftName = `l${subscript(i)} = p${subscript(0)}${superscript(i)} = `;
      const rightName = `r${subscript(i)} = p${subscript(i)}${superscript(n - i)} = `;
      rows.push(el("tr", {},
        el("th", { scope: "row", text: String(i) }),
        el("td", { dataset: { side: "left", index: String(i) } }, el("span", { class: "sl-cell-name", text: leftName }), cells.left.exact, cells.left.decimal),
        el("td", { dataset: { side: "right", index: String(i) } }, el("span", { class: "sl-cell-name", text: rightName }), cells.right.exact, cells.right.decimal)));
    }
    table.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      tSlider.set(work.t);
      levelsSlider.set(work.levels);
      triangleBox.set(work.triangle);
      geometryDirty = tDirty = levelsDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      stepper.destroy();
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** The points' bounding box (the curve lies in their convex hull), widened left and right by `room` × the width. */
function paddedBounds(points, room) {
  const [x0, y0, x1, y1] = boundsOf(points);
  const pad = room * (x1 - x0);
  return [x0 - pad, y0, x1 + pad, y1];
}
