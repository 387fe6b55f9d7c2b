/**
 * Demo 1 (syllabus §2): de Casteljau's algorithm. The reference demo: later demos copy its
 * shape — state, validate, mount → { update, destroy } — and its habits: the curve lives in
 * wasm and is updated in place while dragging (`setControlPoint`), the picture is drawn from
 * what the core returns (`deCasteljau(t)`, one `sampleUniform` per change), nothing is
 * allocated per frame in the draw path, and replaced wasm objects are freed. What several demos
 * need is in lib/ (see lib/README.md), not copied here: `Player` animates t, `pointHandles` and
 * `pointListActions`/`pointButtons` add and remove control points, `titledTable` the table,
 * `pointsPath`/`flatPath` the polylines.
 */
import { Handles, placeLabel as placeLabelAt, pointHandles } from "../lib/handles.js";
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

export const id = "de-casteljau";
/** Prefix of this demo's keys in strings.js. */
export const strings = "deCasteljau";
export const title = t("deCasteljau.title");
export const summary = t("deCasteljau.summary");
/** Syllabus section. */
export const section = 2;

/** The worked example of the Greek notes (syllabus §2): P(1/4) = (29/16, 23/16). */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 2], [6, 4], [8, 2]].map(Object.freeze)),
  t: 0.25,
  construction: true,
});

/** Fewest and most control points (degree 1 … 10). */
export const MIN_POINTS = 2;
export const MAX_POINTS = 11;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;
/** Intermediate points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_LEVELS_MAX_DEGREE = 4;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "t", "construction"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "t", { min: 0, max: 1 });
  checkBoolean(state, "construction");
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags and animation, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = new sl.BezierCurve(flatten(work.points), 2);

  // Derived data, recomputed only when the geometry or t changed.
  let triangle = null; // curve.deCasteljau(t): levels concatenated
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let geometryDirty = true;
  let tDirty = true;
  const levelLabels = []; // "p₀¹" … cached per (i, r)

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points) });
  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => edits.add(i),
    remove: (i) => edits.remove(i),
  });

  // ------------------------------------------------------------ side panel
  const tSlider = slider({
    label: t("control.t"),
    inputLabel: t("control.t.input"),
    name: "t",
    min: 0,
    max: 1,
    step: T_SLIDER_STEP,
    value: work.t,
    onChange: (value, final) => {
      player.stop();
      setT(value, final);
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const player = new Player(view, { get: () => work.t, set: (value, final) => setT(value, final), stopped: () => ctx.commit(work) });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: (i) => edits.add(i), remove: (i) => edits.remove(i), selected: () => handles.selected });
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
    group(null, tSlider.element, player.element),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
    group(null, constructionBox.element),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("de-casteljau");
  ctx.slots.details.append(tableTitle, tableWrap);
  let tableDegree = -1;
  let tableCells = []; // per triangle point: { exact, decimal } spans

  function setT(value, final) {
    work.t = value;
    tSlider.set(value);
    tDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  // ------------------------------------------------------------ edits

  /** Replaces the wasm curve after the number of points changed (the old one is freed). */
  function rebuild() {
    const next = new sl.BezierCurve(flatten(work.points), 2);
    curve.free();
    curve = next;
    geometryDirty = true;
    view.requestDraw();
  }

  const edits = pointListActions({ ctx, work, view, handles, min: MIN_POINTS, max: MAX_POINTS, strings: "deCasteljau", rebuild });

  // ------------------------------------------------------------ drawing
  /** Asks the core for the triangle and the samples when something changed. */
  function recompute() {
    if (geometryDirty) {
      samples = curve.sampleUniform(CURVE_SAMPLES);
    }
    if (geometryDirty || tDirty) {
      triangle = curve.deCasteljau(work.t);
      syncPanels();
    }
    geometryDirty = tDirty = false;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;

    // Control polygon.
    pointsPath(r, v, pts, 0, n + 1);
    r.paint(theme.polygon);

    // The curve, from one batched sample call.
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // The triangle: level r has n + 1 - r points, stored after the levels before it.
    const finalOffset = levelStart(n, n); // p_0^n, the last point of the triangle
    const px = v.sx(triangle[2 * finalOffset]);
    const py = v.sy(triangle[2 * finalOffset + 1]);
    // Centroid of the control points on screen: labels go on the side away from it.
    let cx = 0;
    let cy = 0;
    for (let i = 0; i <= n; i++) {
      cx += v.sx(pts[i][0]);
      cy += v.sy(pts[i][1]);
    }
    cx /= n + 1;
    cy /= n + 1;
    if (work.construction) {
      let offset = n + 1; // level 1 starts after the n + 1 control points
      for (let level = 1; level < n; level++) {
        const count = n + 1 - level;
        const colour = (level - 1) % theme.levelStroke.length;
        r.beginPath();
        for (let j = 0; j < count; j++) {
          const x = v.sx(triangle[2 * (offset + j)]);
          const y = v.sy(triangle[2 * (offset + j) + 1]);
          if (j === 0) r.moveTo(x, y);
          else r.lineTo(x, y);
        }
        r.paint(theme.levelStroke[colour]);
        for (let j = 0; j < count; j++) {
          const x = v.sx(triangle[2 * (offset + j)]);
          const y = v.sy(triangle[2 * (offset + j) + 1]);
          r.point(x, y, theme.levelPoint[colour]);
          if (n <= LABEL_LEVELS_MAX_DEGREE) drawLegLabel(r, v, n, level, j, levelLabel(j, level), x, y, cx, cy, theme.labelSmall, theme.levelPoint[colour].radius * r.scale);
        }
        offset += count;
      }
    }

    handles.draw(r, v);

    // The point P(t), labelled beside the last construction leg (away from the polygon).
    r.point(px, py, theme.pointOnCurve);
    drawLegLabel(r, v, n, n, 0, t("deCasteljau.pointLabel"), px, py, cx, cy, theme.labelPoint, theme.pointOnCurve.radius * r.scale);
  }

  /** "p₀¹" for point i of level r (cached strings). */
  function levelLabel(i, level) {
    const key = level * (MAX_POINTS + 1) + i;
    return (levelLabels[key] ??= `p${subscript(i)}${superscript(level)}`);
  }

  /**
   * Labels point j of level r (r ≥ 1) beside the leg of level r − 1 that it divides, on the
   * side away from the control points' centroid (cx, cy): outside the construction.
   */
  function drawLegLabel(r, v, n, level, j, text, x, y, cx, cy, style, radius) {
    const a = levelStart(n, level - 1) + j;
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
    placeLabelAt(r, text, x, y, nx, ny, radius, style);
  }

  /** Index (in points) where level `level` starts in a degree-n triangle. */
  function levelStart(n, level) {
    // Levels 0 … level-1 hold (n+1) + n + … + (n + 2 - level) points.
    return level * (n + 1) - (level * (level - 1)) / 2;
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    if (!triangle) return;
    const pts = work.points;
    const n = pts.length - 1;
    const last = 2 * levelStart(n, n);
    const x = triangle[last];
    const y = triangle[last + 1];
    view.setLabel(t("deCasteljau.aria", { kind: degreeName(n), count: n + 1, t: fmt(work.t), x: fmt(x, 2), y: fmt(y, 2) }));
    degreeText.textContent = t("deCasteljau.degree", { n, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;

    // Exact fractions when t is a simple fraction and every input is an integer.
    const tFraction = simpleFraction(work.t);
    const exact = tFraction && allIntegers(pts.flat()) ? tFraction : null;
    const tTex = exact ? fractionTex(exact) : fmt(work.t);
    const coord = (value, level, tex) => {
      const f = exact ? exactFraction(value, exact.den ** level) : null;
      if (!f) return fmt(value);
      return tex ? fractionTex(f) : fractionText(f);
    };

    // Formula panel: the recurrence, the Bernstein form with the core's weights, the point.
    const weights = [];
    for (let i = 0; i <= n; i++) {
      const b = sl.bernstein(n, i, work.t);
      const f = exact ? exactFraction(b, exact.den ** n) : null;
      weights.push(`${f ? fractionTex(f) : fmt(b)}\\,P_{${i}}`);
    }
    const point = `\\left(${coord(x, n, true)},\\ ${coord(y, n, true)}\\right)`;
    const approx = exact && (!Number.isInteger(x) || !Number.isInteger(y)) ? `\\approx (${fmt(x)},\\ ${fmt(y)})` : "";
    formula.set([
      `p_i^{r} = (1-t)\\,p_i^{r-1} + t\\,p_{i+1}^{r-1},\\quad r = 1,\\dots,${n},\\quad t = ${tTex}`,
      `P(t) = \\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,P_i = ${weights.join(" + ")}`,
      `P(${tTex}) = p_0^{${n}} = ${point} ${approx}`,
    ]);

    // Table: one row per level r, cells p_i^r (fraction and decimals).
    if (tableDegree !== n) buildTable(n);
    setText(tableTitle, t("deCasteljau.tableCaption", { t: exact ? fractionText(exact) : fmt(work.t) }));
    let k = 0;
    for (let level = 0; level <= n; level++) {
      for (let i = 0; i <= n - level; i++, k++) {
        const px = triangle[2 * k];
        const py = triangle[2 * k + 1];
        const decimalText = `(${fmt(px)}, ${fmt(py)})`;
        const exactText = exact ? `(${coord(px, level, false)}, ${coord(py, level, false)})` : decimalText;
        // Exact value first; the decimals underneath when they say something different.
        setValueSpans(tableCells[k], exactText, decimalText);
      }
    }
  }

  /** Rebuilds the table's rows for degree n (only when the degree changed). */
  function buildTable(n) {
    tableDegree = n;
    tableCells = [];
    const rows = [];
    for (let level = 0; level <= n; level++) {
      const cells = [el("th", { scope: "row", text: t("deCasteljau.tableLevel", { r: level }) })];
      for (let i = 0; i <= n - level; i++) {
        const name = `${level === 0 ? "P" : "p"}${subscript(i)}${level === 0 ? "" : superscript(level)} = `;
        const spans = valueSpans();
        tableCells.push(spans);
        cells.push(el("td", { dataset: { level: String(level), index: String(i) } }, el("span", { class: "sl-cell-name", text: name }), spans.exact, spans.decimal));
      }
      rows.push(el("tr", {}, cells));
    }
    table.replaceChildren(el("tbody", {}, rows));
  }

  syncPanels();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      player.stop();
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      tSlider.set(work.t);
      constructionBox.set(work.construction);
      geometryDirty = tDirty = true;
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
