/**
 * Demo 5 (syllabus §2): curve–line intersection by recursive bounding boxes. A cubic and an
 * infinite line through two handles A and B; the boxes the core's recursion visited
 * (`intersectLineBoxes`), pruned ones faint, hit ones outlined, shown up to a chosen depth so a
 * lecturer can step through the levels; the intersections from `intersectLine` as points
 * labelled with t; and the variation-diminishing count (`polygonLineCrossings`).
 *
 * Same shape as the reference demo (de-casteljau.js): the curve lives in wasm and is updated in
 * place while dragging (`setControlPoint`), boxes and roots are what the core returns (no
 * recursion in JS), nothing is allocated per frame in the draw path, and replaced wasm objects
 * are freed.
 */
import { Handles, placeLabel } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber } from "../lib/validate.js";
import { fmt, subscript, simpleFraction, fractionText } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { flatPath } from "../lib/draw.js";

export const id = "line-intersection";
/** Prefix of this demo's keys in strings.js. */
export const strings = "lineIntersection";
export const title = t("lineIntersection.title");
export const summary = t("lineIntersection.summary");
/** Syllabus section. */
export const section = 2;

/** Deepest level of the core's box recursion (MAX_INTERSECTION_DEPTH in src/bezier/intersect.rs). */
export const MAX_DEPTH = 48;
/** Tolerance of the roots: each t has its point within this distance of the line. */
export const ROOT_TOLERANCE = 1e-9;
/** Tolerance of the boxes drawn: boxes stop splitting below this size (readable picture). */
export const BOX_TOLERANCE = 1e-3;

/**
 * An S-shaped cubic, point-symmetric about (6, 0) = P(1/2), and the line y = 1 − x/6 through
 * that centre: three crossings, at t = 1/3, 1/2, 2/3 exactly (by hand: P(1/3) = (34/9, 10/27)
 * and 1 − (34/9)/6 = 10/27; the symmetry gives 2/3); the control polygon is crossed three
 * times too. `depth` = MAX_DEPTH shows every level.
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, -2], [3, 4], [9, -4], [12, 2]].map(Object.freeze)),
  line: Object.freeze([[0, 1], [12, -1]].map(Object.freeze)),
  depth: MAX_DEPTH,
});

/** A cubic: four control points; then the line's two points. */
const POINT_COUNT = 4;
const LINE_HANDLES = 2;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Extra distance (CSS px) of a t label from its point: clear of the smallest boxes around it. */
const ROOT_LABEL_OFFSET = 6;
/** Label stacking: line height in em, and the average glyph width in em used to estimate widths. */
const LABEL_LINE_HEIGHT = 1.25;
const GLYPH_WIDTH_EM = 0.6;
/** Smallest distance (CSS px) between A and B on screen for the line to have a direction. */
const DIRECTION_EPSILON = 1e-6;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "line", "depth"]);
  checkPoints(state, "points", { min: POINT_COUNT, max: POINT_COUNT });
  checkPoints(state, "line", { min: LINE_HANDLES, max: LINE_HANDLES });
  const [[ax, ay], [bx, by]] = state.line;
  if (ax === bx && ay === by) throw new Error(t("lineIntersection.sameLinePoints", { x: ax, y: ay }));
  checkNumber(state, "depth", { min: 0, max: MAX_DEPTH, integer: true });
}

/** A coordinate for labels and formulas: integers as they are, others with 2 decimals. */
function coord(x) {
  return Number.isInteger(x) ? String(x) : fmt(x, 2);
}

/** What the core says about a curve and a line (every call that can throw, together). */
function intersect(curve, [[ax, ay], [bx, by]]) {
  const roots = curve.intersectLine(ax, ay, bx, by, ROOT_TOLERANCE);
  return {
    roots,
    points: roots.length ? curve.sample(roots) : new Float64Array(0),
    boxes: curve.intersectLineBoxes(ax, ay, bx, by, BOX_TOLERANCE),
    polygonCrossings: curve.polygonLineCrossings(ax, ay, bx, by),
  };
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

  // Derived data, recomputed only when the curve or the line changed.
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let found = { roots: new Float64Array(0), points: new Float64Array(0), boxes: new Float64Array(0), polygonCrossings: 0 };
  let deepest = 0; // deepest level in found.boxes
  let geometryDirty = true;
  let depthDirty = true;
  const pointScratch = new Float64Array(2);
  const handleLabels = ["P₀", "P₁", "P₂", "P₃", t("lineIntersection.handleA"), t("lineIntersection.handleB")];
  let rootLabels = []; // "t = 0.266" per root, made when the roots change

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf([...work.points, ...work.line]) });
  const handles = new Handles(view, {
    count: () => POINT_COUNT + LINE_HANDLES,
    get: (i, out) => {
      const p = i < POINT_COUNT ? work.points[i] : work.line[i - POINT_COUNT];
      out[0] = p[0];
      out[1] = p[1];
    },
    label: (i) => handleLabels[i],
    move: (i, x, y) => {
      if (i < POINT_COUNT) {
        work.points[i][0] = x;
        work.points[i][1] = y;
        pointScratch[0] = x;
        pointScratch[1] = y;
        curve.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
      } else {
        const [ox, oy] = work.line[LINE_HANDLES - 1 - (i - POINT_COUNT)];
        if (x === ox && y === oy) return; // A = B gives no line: stay where it was
        work.line[i - POINT_COUNT][0] = x;
        work.line[i - POINT_COUNT][1] = y;
      }
      geometryDirty = true;
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
  });

  // ------------------------------------------------------------ side panel
  const countText = el("p", { class: "sl-readout", dataset: { info: "count" } });
  const crossingsText = el("p", { class: "sl-note", dataset: { info: "crossings" } });
  const depthSlider = slider({
    label: t("lineIntersection.depth"),
    inputLabel: t("lineIntersection.depth.input", { max: MAX_DEPTH }),
    name: "depth",
    min: 0,
    max: MAX_DEPTH,
    step: 1,
    value: work.depth,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => setDepth(Math.round(value), final),
    onError: (text) => ctx.status(t("lineIntersection.badDepth", { value: text, max: MAX_DEPTH }), "error"),
  });
  const shallowerButton = button({ label: t("lineIntersection.shallower"), title: t("lineIntersection.shallower.title"), name: "depth-down", onClick: () => stepDepth(-1) });
  const deeperButton = button({ label: t("lineIntersection.deeper"), title: t("lineIntersection.deeper.title"), name: "depth-up", onClick: () => stepDepth(1) });
  const boxesText = el("p", { class: "sl-note", dataset: { info: "boxes" } });
  ctx.slots.controls.append(
    group(null, countText, crossingsText),
    group(null, depthSlider.element, el("div", { class: "sl-button-row" }, shallowerButton, deeperButton), boxesText),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("intersections");
  ctx.slots.details.append(tableTitle, tableWrap);
  let tableCells = null; // per intersection: { t, point } cells

  // ------------------------------------------------------------ edits

  /** Depth shown: the state's depth, at most the deepest level the recursion reached. */
  function shownDepth() {
    return Math.min(work.depth, deepest);
  }

  /** Moving the slider to the deepest level means "every level" (MAX_DEPTH), so it stays so while dragging. */
  function setDepth(value, final) {
    work.depth = value >= deepest ? MAX_DEPTH : value;
    depthSlider.set(shownDepth());
    depthDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  function stepDepth(direction) {
    setDepth(Math.max(0, Math.min(deepest, shownDepth() + direction)), true);
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for the samples, roots, boxes and polygon crossings when something changed. */
  function recompute() {
    if (geometryDirty) {
      samples = curve.sampleUniform(CURVE_SAMPLES);
      try {
        adopt(intersect(curve, work.line));
      } catch (err) {
        // Cannot happen from a drag (A = B is refused in move); keep the last result, say why.
        ctx.status(t("lineIntersection.failed", { message: err.message }), "error");
      }
    }
    if (geometryDirty || depthDirty) syncPanels();
    geometryDirty = depthDirty = false;
  }

  /** Takes a result of `intersect`: the deepest level, the t labels, the slider's range. */
  function adopt(result) {
    found = result;
    deepest = 0;
    for (let k = 0; k < found.boxes.length; k += 6) deepest = Math.max(deepest, found.boxes[k]);
    rootLabels = Array.from(found.roots, (root) => t("lineIntersection.rootLabel", { t: fmt(root) }));
    depthSlider.range.max = String(deepest);
    depthSlider.set(shownDepth());
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const boxes = found.boxes;
    const depth = shownDepth();

    // Boxes up to the shown depth: pruned ones faint (one path), hit ones outlined (one path).
    for (let hit = 0; hit <= 1; hit++) {
      r.beginPath();
      for (let k = 0; k < boxes.length; k += 6) {
        if (boxes[k] > depth || boxes[k + 5] !== hit) continue;
        const x0 = v.sx(boxes[k + 1]);
        const y1 = v.sy(boxes[k + 2]);
        r.rect(x0, v.sy(boxes[k + 4]), v.sx(boxes[k + 3]) - x0, y1 - v.sy(boxes[k + 4]));
      }
      r.paint(hit ? theme.levelStroke[0] : theme.helperFill);
    }

    // Control polygon.
    r.beginPath();
    for (let i = 0; i < pts.length; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(theme.polygon);

    // The curve, from one batched sample call.
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // The infinite line through A and B, across the whole figure.
    const [[ax, ay], [bx, by]] = work.line;
    const pax = v.sx(ax);
    const pay = v.sy(ay);
    const dx = v.sx(bx) - pax;
    const dy = v.sy(by) - pay;
    const length = Math.hypot(dx, dy);
    // Unit normal of the line on screen, pointing up: the side the t labels go.
    let nx = 0;
    let ny = -1;
    if (length > DIRECTION_EPSILON) {
      const reach = (v.width + v.height + Math.hypot(pax, pay)) / length;
      r.beginPath();
      r.moveTo(pax - dx * reach, pay - dy * reach);
      r.lineTo(pax + dx * reach, pay + dy * reach);
      r.paint(theme.levelStroke[1]);
      nx = dy / length;
      ny = -dx / length;
      if (ny > 0) {
        nx = -nx;
        ny = -ny;
      }
    }

    handles.draw(r, v);

    // The intersections, labelled with their t on alternate sides of the line (neighbours
    // along the line do not collide); a label too close to the previous one on its side is
    // moved one line further out.
    const hits = found.points;
    const style = theme.labelPoint;
    const lineHeight = style.size * LABEL_LINE_HEIGHT * r.scale;
    let lastPlus = -Infinity;
    let lastMinus = -Infinity;
    let levelPlus = 0;
    let levelMinus = 0;
    for (let k = 0; k < rootLabels.length; k++) {
      const x = v.sx(hits[2 * k]);
      const y = v.sy(hits[2 * k + 1]);
      const plus = k % 2 === 0;
      const width = rootLabels[k].length * style.size * GLYPH_WIDTH_EM * r.scale; // an estimate: no measuring per frame
      let level;
      if (plus) {
        levelPlus = Math.abs(x - lastPlus) < width ? levelPlus + 1 : 0;
        lastPlus = x;
        level = levelPlus;
      } else {
        levelMinus = Math.abs(x - lastMinus) < width ? levelMinus + 1 : 0;
        lastMinus = x;
        level = levelMinus;
      }
      const side = plus ? 1 : -1;
      r.point(x, y, theme.pointOnCurve);
      placeLabel(r, rootLabels[k], x, y, side * nx, side * ny, (theme.pointOnCurve.radius + ROOT_LABEL_OFFSET) * r.scale + level * lineHeight, style);
    }
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    const roots = found.roots;
    const count = roots.length;
    const depth = shownDepth();
    const tList = Array.from(roots, (root) => fmt(root)).join(", ");
    const countMessage = count === 0 ? t("lineIntersection.none") : t(count === 1 ? "lineIntersection.count.one" : "lineIntersection.count", { count });
    setText(countText, countMessage);
    setText(crossingsText, t("lineIntersection.crossings", { polygon: found.polygonCrossings, curve: count }));

    // Boxes up to the shown depth: visited, hit, pruned.
    let visited = 0;
    let hit = 0;
    for (let k = 0; k < found.boxes.length; k += 6) {
      if (found.boxes[k] > depth) continue;
      visited += 1;
      if (found.boxes[k + 5] === 1) hit += 1;
    }
    setText(boxesText, t("lineIntersection.boxes", { depth, deepest, visited, hit, pruned: visited - hit, tolerance: BOX_TOLERANCE }));
    shallowerButton.disabled = depth <= 0;
    deeperButton.disabled = depth >= deepest;

    const [[ax, ay], [bx, by]] = work.line;
    view.setLabel(t("lineIntersection.aria", {
      points: work.points.map(([x, y]) => `(${coord(x)}, ${coord(y)})`).join(", "),
      a: `(${coord(ax)}, ${coord(ay)})`,
      b: `(${coord(bx)}, ${coord(by)})`,
      result: count === 0 ? t("lineIntersection.none") : `${countMessage} (t = ${tList})`,
      polygon: found.polygonCrossings,
      depth,
      deepest,
    }));

    // Formula panel: signed distance to the line, the pruning rule, the roots.
    const pointTex = (x, y) => `(${coord(x)},\\ ${coord(y)})`;
    const rootsTex = count === 0 ? "\\varnothing" : `\\{${Array.from(roots, (root) => fmt(root)).join(",\\ ")}\\}`;
    formula.set([
      `d(P) = \\frac{(B - A) \\times (P - A)}{\\lvert B - A \\rvert}, \\qquad A = ${pointTex(ax, ay)},\\ B = ${pointTex(bx, by)}`,
      `d(c_1), \\dots, d(c_4)\\ \\text{${t("lineIntersection.formula.miss")}} \\;\\Rightarrow\\; \\text{${t("lineIntersection.formula.pruned")}}`,
      `\\text{${t("lineIntersection.formula.split")}}\\ t = \\tfrac12 \\text{${t("lineIntersection.formula.until")}}\\ 10^{${Math.round(Math.log10(BOX_TOLERANCE))}}`,
      `t \\in ${rootsTex}, \\qquad \\#\\text{${t("lineIntersection.formula.curve")}} = ${count} \\;\\le\\; \\#\\text{${t("lineIntersection.formula.polygon")}} = ${found.polygonCrossings}`,
    ]);

    // Table: one row per intersection, t and P(t); rows rebuilt only when the count changed.
    setText(tableTitle, count === 0 ? t("lineIntersection.tableNone") : t("lineIntersection.tableCaption", { tolerance: ROOT_TOLERANCE }));
    if (tableCells === null || tableCells.length !== count) buildTable(count);
    for (let k = 0; k < count; k++) {
      // Exact fractions too when t is a simple one (1/3, 1/2 …): the hand-made cases read so.
      const fraction = simpleFraction(roots[k]);
      setText(tableCells[k].t, fraction && fraction.den > 1 ? `${fmt(roots[k])} = ${fractionText(fraction)}` : fmt(roots[k]));
      setText(tableCells[k].point, `(${fmt(found.points[2 * k])}, ${fmt(found.points[2 * k + 1])})`);
    }
  }

  /** Rebuilds the table's rows for `count` intersections. */
  function buildTable(count) {
    tableCells = [];
    const rows = [];
    for (let k = 0; k < count; k++) {
      const cells = { t: el("td", { dataset: { field: "t" } }), point: el("td", { dataset: { field: "point" } }) };
      tableCells.push(cells);
      rows.push(el("tr", { dataset: { root: String(k) } }, el("th", { scope: "row", text: `t${subscript(k + 1)}` }), cells.t, cells.point));
    }
    const head = el("thead", {}, el("tr", {},
      el("th", { scope: "col", text: t("lineIntersection.tableRoot") }),
      el("th", { scope: "col", text: "t" }),
      el("th", { scope: "col", text: t("lineIntersection.tablePoint") })));
    table.hidden = count === 0;
    table.replaceChildren(head, el("tbody", {}, rows));
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      let nextFound;
      try {
        nextFound = intersect(next, state.line);
      } catch (err) {
        next.free();
        throw err;
      }
      curve.free();
      curve = next;
      work = structuredClone(state);
      handles.forgetPointer();
      samples = curve.sampleUniform(CURVE_SAMPLES);
      adopt(nextFound);
      geometryDirty = depthDirty = false;
      syncPanels();
      view.requestDraw();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}
