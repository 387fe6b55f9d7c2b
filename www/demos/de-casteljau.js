/**
 * Demo 1 (syllabus §2): de Casteljau's algorithm. The reference demo: later demos copy its
 * shape — state, validate, mount → { update, destroy } — and its habits: the curve lives in
 * wasm and is updated in place while dragging (`setControlPoint`), the picture is drawn from
 * what the core returns (`deCasteljau(t)`, one `sampleUniform` per change), nothing is
 * allocated per frame in the draw path, and replaced wasm objects are freed.
 */
import { Handles, roundToView, placeLabel as placeLabelAt } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, checkbox, group, el } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkBoolean } from "../lib/validate.js";
import { fmt, subscript, superscript, simpleFraction, exactFraction, fractionText, fractionTex, allIntegers } from "../lib/format.js";
import { t } from "../lib/strings.js";

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
/** Animation speed in t per second, and the step of the step buttons (ui.md). */
const PLAY_SPEED = 0.25;
const STEP = 1 / 16;
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;
/** Intermediate points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_LEVELS_MAX_DEGREE = 4;
/** A new point appended after the last goes this fraction of the last leg further on. */
const APPEND_FRACTION = 0.5;
/** Slack when snapping t to the step grid, so 0.25 counts as on the grid. */
const GRID_SLACK = 1e-9;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "t", "construction"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "t", { min: 0, max: 1 });
  checkBoolean(state, "construction");
}

/** "cubic", "quartic", … for degree n. */
function kindOf(n) {
  return n <= 5 ? t(`curve.degree.${n}`) : t("curve.degree.n", { n });
}

/** Flat Float64Array [x0, y0, x1, y1, …] of the state's points (for the wasm constructor). */
function flatten(points) {
  const flat = new Float64Array(points.length * 2);
  points.forEach(([x, y], i) => {
    flat[2 * i] = x;
    flat[2 * i + 1] = y;
  });
  return flat;
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
  const pointScratch = new Float64Array(2);
  const levelLabels = []; // "p₀¹" … cached per (i, r)
  const handleLabels = []; // "P₀" …

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points) });
  const handles = new Handles(view, {
    count: () => work.points.length,
    get: (i, out) => {
      out[0] = work.points[i][0];
      out[1] = work.points[i][1];
    },
    label: (i) => (handleLabels[i] ??= `P${subscript(i)}`),
    move: (i, x, y) => {
      work.points[i][0] = x;
      work.points[i][1] = y;
      pointScratch[0] = x;
      pointScratch[1] = y;
      curve.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
      geometryDirty = true;
    },
    commit: (kind, i, merge) => commitWork(merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
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
      stop();
      setT(value, final);
    },
    onError: (text) => ctx.status(t("control.badNumber", { value: text }), "error"),
  });
  const playButton = button({ label: t("control.play"), name: "play", pressed: false, onClick: () => toggle() });
  const backButton = button({ label: t("control.stepBack"), title: t("control.stepBack.title"), name: "step-back", onClick: () => step(-1) });
  const forwardButton = button({ label: t("control.stepForward"), title: t("control.stepForward.title"), name: "step", onClick: () => step(1) });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const addButton = button({ label: t("control.addPoint"), title: t("control.addPoint.title"), name: "add-point", onClick: () => addPoint(handles.selected) });
  const removeButton = button({ label: t("control.removePoint"), title: t("control.removePoint.title"), name: "remove-point", onClick: () => removePoint(handles.selected) });
  const constructionBox = checkbox({
    label: t("control.construction"),
    name: "construction",
    checked: work.construction,
    onChange: (on) => {
      work.construction = on;
      view.requestDraw();
      commitWork();
    },
  });
  ctx.slots.controls.append(
    group(null, tSlider.element, el("div", { class: "sl-button-row" }, backButton, playButton, forwardButton)),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
    group(null, constructionBox.element),
  );

  // Space plays/pauses while the figure has focus.
  const onFigureKey = (event) => {
    if (event.key === " " && !event.ctrlKey && !event.metaKey) {
      toggle();
      event.preventDefault();
    }
  };
  view.canvas.addEventListener("keydown", onFigureKey);

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const tableTitle = el("p", { class: "sl-table-title", id: `sl-triangle-${Math.random().toString(36).slice(2, 8)}` });
  const table = el("table", { class: "sl-table", dataset: { table: "de-casteljau" }, "aria-labelledby": tableTitle.id });
  ctx.slots.details.append(tableTitle, el("div", { class: "sl-table-wrap" }, table));
  let tableDegree = -1;
  let tableCells = []; // per triangle point: { exact, decimal } spans

  // ------------------------------------------------------------ animation
  let playing = false;
  let lastTime = 0;
  let frameId = 0;
  const tick = (now) => {
    if (!playing) return;
    // The first frame's timestamp may precede performance.now() taken in play(): never step back.
    const dt = Math.max(0, now - lastTime) / 1000;
    lastTime = now;
    const next = Math.min(1, work.t + PLAY_SPEED * dt);
    setT(next, false);
    if (next >= 1) stop();
    else frameId = requestAnimationFrame(tick);
  };

  function play() {
    if (playing) return;
    if (work.t >= 1) setT(0, false);
    playing = true;
    playButton.textContent = t("control.pause");
    playButton.setAttribute("aria-pressed", "true");
    lastTime = performance.now();
    frameId = requestAnimationFrame(tick);
  }

  /** Stops the animation and records where it stopped. */
  function stop() {
    if (!playing) return;
    playing = false;
    cancelAnimationFrame(frameId);
    playButton.textContent = t("control.play");
    playButton.setAttribute("aria-pressed", "false");
    commitWork();
  }

  function toggle() {
    if (playing) stop();
    else play();
  }

  /** Moves t to the previous/next multiple of 1/16. */
  function step(direction) {
    stop();
    const k = direction > 0 ? Math.floor(work.t / STEP + GRID_SLACK) + 1 : Math.ceil(work.t / STEP - GRID_SLACK) - 1;
    setT(Math.min(1, Math.max(0, k * STEP)), true);
  }

  function setT(value, final) {
    work.t = value;
    tSlider.set(value);
    tDirty = true;
    view.requestDraw();
    if (final) commitWork();
  }

  // ------------------------------------------------------------ edits
  /** Records the shown state (panels follow at the next draw, after the core recomputed). */
  function commitWork(merge = null) {
    ctx.commit(structuredClone(work), merge);
  }

  /** Replaces the wasm curve after the number of points changed (the old one is freed). */
  function rebuild() {
    const next = new sl.BezierCurve(flatten(work.points), 2);
    curve.free();
    curve = next;
    geometryDirty = true;
    view.requestDraw();
  }

  /** Adds a point after handle i (at the end when none is selected). */
  function addPoint(i) {
    const pts = work.points;
    if (pts.length >= MAX_POINTS) {
      ctx.status(t("deCasteljau.maxPoints", { max: MAX_POINTS }), "error");
      return;
    }
    const at = i >= 0 && i < pts.length ? i : pts.length - 1;
    const a = pts[at];
    const b = at + 1 < pts.length ? pts[at + 1] : null;
    const prev = pts[at - 1] ?? a;
    // Between two points: the middle of the leg; after the last: continue the last leg.
    const x = b ? (a[0] + b[0]) / 2 : a[0] + (a[0] - prev[0]) * APPEND_FRACTION;
    const y = b ? (a[1] + b[1]) / 2 : a[1] + (a[1] - prev[1]) * APPEND_FRACTION;
    pts.splice(at + 1, 0, [roundToView(x, view.scale), roundToView(y, view.scale)]);
    rebuild();
    handles.select(at + 1);
    commitWork();
  }

  /** Removes handle i (the last one when none is selected). */
  function removePoint(i) {
    const pts = work.points;
    if (pts.length <= MIN_POINTS) {
      ctx.status(t("deCasteljau.minPoints", { min: MIN_POINTS }), "error");
      return;
    }
    const at = i >= 0 && i < pts.length ? i : pts.length - 1;
    pts.splice(at, 1);
    rebuild();
    handles.select(Math.min(at, pts.length - 1));
    commitWork();
  }

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
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      const x = v.sx(pts[i][0]);
      const y = v.sy(pts[i][1]);
      if (i === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.polygon);

    // The curve, from one batched sample call.
    r.beginPath();
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const x = v.sx(samples[2 * k]);
      const y = v.sy(samples[2 * k + 1]);
      if (k === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
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
    view.setLabel(t("deCasteljau.aria", { kind: kindOf(n), count: n + 1, t: fmt(work.t), x: fmt(x, 2), y: fmt(y, 2) }));
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
        setText(tableCells[k].exact, exactText);
        setText(tableCells[k].decimal, exactText === decimalText ? "" : `≈ ${decimalText}`);
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
        const spans = { exact: el("span", { class: "sl-cell-value" }), decimal: el("span", { class: "sl-cell-decimal" }) };
        tableCells.push(spans);
        cells.push(el("td", { dataset: { level: String(level), index: String(i) } }, el("span", { class: "sl-cell-name", text: name }), spans.exact, spans.decimal));
      }
      rows.push(el("tr", {}, cells));
    }
    table.replaceChildren(el("tbody", {}, rows));
  }

  /** Sets a node's text only when it changed (no layout work for identical text). */
  function setText(node, text) {
    if (node.textContent !== text) node.textContent = text;
  }

  syncPanels();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      stop();
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
      playing = false;
      cancelAnimationFrame(frameId);
      view.canvas.removeEventListener("keydown", onFigureKey);
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}

/** [xmin, ymin, xmax, ymax] of a list of points (the curve lies in their convex hull). */
function boundsOf(points) {
  let x0 = Infinity;
  let y0 = Infinity;
  let x1 = -Infinity;
  let y1 = -Infinity;
  for (const [x, y] of points) {
    x0 = Math.min(x0, x);
    y0 = Math.min(y0, y);
    x1 = Math.max(x1, x);
    y1 = Math.max(y1, y);
  }
  return [x0, y0, x1, y1];
}
