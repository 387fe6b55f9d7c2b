/**
 * Demo (syllabus §3): knot vector types. One control polygon, three B-splines of the same degree
 * overlaid in distinct styles: clamped ("open") knots — uniform, chord-length or centripetal
 * interior spacing, from `knotVector(points, dim, p, kind)` —, unclamped uniform knots
 * (`knotVector(…, "uniform")`) and the closed curve of `BSplineCurve.closed`. The knot values
 * are listed for each, and each curve's end points are read back from the core (`evaluate`).
 *
 * Drags go through `setControlPoint` on every curve, in place. The one exception: chord and
 * centripetal knots are a function of the points, so that curve's knot vector changes with a
 * drag and the curve is rebuilt (once per frame at most, in `recompute`) — the core has no
 * "set knots in place".
 */
import { Handles, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, checkbox, group, el, radios, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkBoolean, checkChoice } from "../lib/validate.js";
import { fmt, degreeName } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { withPointAdded, withPointRemoved, pointButtons } from "../lib/point-list.js";
import { titledTable } from "../lib/table.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { buildOrReport } from "../lib/wasm.js";

export const id = "knot-vectors";
/** Prefix of this demo's keys in strings.js. */
export const strings = "knotVectors";
export const title = t("knotVectors.title");
export const summary = t("knotVectors.summary");
/** Syllabus section. */
export const section = 3;

/** Six integer points and a cubic: clamped knots 0 0 0 0 1 2 3 3 3 3 (syllabus §3 conventions). */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 1], [2, 6], [7, 7], [11, 4], [9, 0], [4, -1]].map(Object.freeze)),
  degree: 3,
  spacing: "uniform",
  clamped: true,
  unclamped: true,
  closed: true,
});

/** Fewest and most control points. */
export const MIN_POINTS = 2;
export const MAX_POINTS = 11;
/** Highest degree offered. */
export const MAX_DEGREE = 5;
/** Interior spacing of the clamped knot vector (the `kind` of `knotVector`). */
export const SPACINGS = Object.freeze(["uniform", "chord", "centripetal"]);
/** The three curves, in drawing and legend order; index = style index in `theme.compareCurve`. */
const KINDS = Object.freeze(["clamped", "unclamped", "closed"]);
/** Points sampled along each curve (one `sampleUniform` call per curve and change). */
const CURVE_SAMPLES = 256;
/** Legend layout (CSS px × lecture scale): margin, swatch length, line height, gaps. */
const LEGEND_MARGIN = 12;
const LEGEND_SWATCH = 34;
const LEGEND_LINE = 22;
const LEGEND_GAP = 8;
const LEGEND_SPACING = 22;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "degree", "spacing", "clamped", "unclamped", "closed"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkNumber(state, "degree", { min: 1, max: MAX_DEGREE, integer: true });
  if (state.degree > state.points.length - 1) throw new Error(t("knotVectors.error.degree", { p: state.degree, count: state.points.length }));
  checkChoice(state, "spacing", SPACINGS);
  checkBoolean(state, "clamped");
  checkBoolean(state, "unclamped");
  checkBoolean(state, "closed");
}

/** A knot as short text: integers plain, else 3 decimals. */
function knotText(x) {
  return Number.isInteger(x) ? String(x) : fmt(x);
}

/** A point as "(x, y)" with integers plain. */
function pointText(x, y) {
  return `(${knotText(Number(fmt(x)))}, ${knotText(Number(fmt(y)))})`;
}

/** The three curves for a state (new wasm objects; the caller frees them). Throws if the core refuses. */
function buildCurves(sl, state) {
  const flat = flatten(state.points);
  const p = state.degree;
  const made = [];
  try {
    made.push(new sl.BSplineCurve(flat, 2, p, sl.knotVector(flat, 2, p, clampedKind(state.spacing))));
    made.push(new sl.BSplineCurve(flat, 2, p, sl.knotVector(flat, 2, p, "uniform")));
    made.push(sl.BSplineCurve.closed(flat, 2, p));
  } catch (err) {
    for (const curve of made) curve.free();
    throw err;
  }
  return made;
}

/** The `knotVector` kind of the clamped curve: "clamped" (uniform interior), "chord" or "centripetal". */
function clampedKind(spacing) {
  return spacing === "uniform" ? "clamped" : spacing;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  /** [clamped, unclamped, closed] wasm curves. */
  let curves = buildCurves(sl, work);

  // Derived data, recomputed only when the geometry changed.
  const samples = [null, null, null]; // per curve: sampleUniform(CURVE_SAMPLES)
  const ends = new Float64Array(12); // per curve: start x, y, end x, y
  let knotLists = [[], [], []]; // per curve: knots() as plain arrays (panels)
  let geometryDirty = true;
  let clampedKnotsDirty = false; // chord/centripetal knots follow the points: rebuild that curve
  const legendLabels = KINDS.map((kind) => t(`knotVectors.legend.${kind}`)); // [0] follows the spacing
  const domains = new Float64Array(6); // per curve: a, b

  // ------------------------------------------------------------ figure
  const legendWidths = new Float64Array(KINDS.length); // label widths, CSS px at scale 1
  const legendAt = new Float64Array(2 * KINDS.length); // laid-out swatch starts (x, y), CSS px
  const insetScratch = [0, 0, 0, 0];
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets });
  // A taller figure than the default 16:10: the legend takes a strip at the top.
  ctx.slots.figure.style.aspectRatio = "3 / 2";

  /** The legend's strip above the world window: [top, right, bottom, left] (no allocation). */
  function insets(width, height, scale) {
    insetScratch[0] = layoutLegend(width, scale);
    return insetScratch;
  }

  /**
   * Flows the shown legend entries into rows across a canvas `width` CSS px wide; writes their
   * positions to `legendAt` and returns the height taken (CSS px).
   */
  function layoutLegend(width, scale) {
    let x = LEGEND_MARGIN * scale;
    let y = (LEGEND_MARGIN + LEGEND_LINE / 2) * scale;
    let any = false;
    for (let c = 0; c < KINDS.length; c++) {
      if (!work[KINDS[c]]) continue;
      const w = (LEGEND_SWATCH + LEGEND_GAP + legendWidths[c]) * scale;
      if (any && x + w > width - LEGEND_MARGIN * scale) {
        x = LEGEND_MARGIN * scale;
        y += LEGEND_LINE * scale;
      }
      legendAt[2 * c] = x;
      legendAt[2 * c + 1] = y;
      x += w + LEGEND_SPACING * scale;
      any = true;
    }
    return any ? y + (LEGEND_LINE / 2 + LEGEND_MARGIN / 2) * scale : 0;
  }

  /** Measures the legend labels (when they change; not per frame). */
  function measureLegend() {
    const r = view.renderer;
    for (let c = 0; c < KINDS.length; c++) legendWidths[c] = r.measure(legendLabels[c], r.theme.labelSmall) / r.scale;
  }
  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      // In place on every curve (the closed curve's repeated copy follows in the core).
      for (const curve of curves) curve.setControlPoint(i, xy);
      if (work.spacing !== "uniform") clampedKnotsDirty = true;
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => addPoint(i),
    remove: (i) => removePoint(i),
  });

  // ------------------------------------------------------------ side panel
  const degreeSlider = slider({
    label: t("knotVectors.control.degree"),
    inputLabel: t("knotVectors.control.degree.input"),
    name: "degree",
    min: 1,
    max: MAX_DEGREE,
    step: 1,
    value: work.degree,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => {
      if (final) setDegree(Math.round(value));
    },
    onError: (text) => ctx.status(t("knotVectors.degreeRange", { value: text, max: Math.min(MAX_DEGREE, work.points.length - 1) }), "error"),
  });
  const spacingRadios = radios({
    name: "spacing",
    value: work.spacing,
    options: SPACINGS.map((value) => ({ value, label: t(`knotVectors.spacing.${value}`) })),
    onChange: (value) => setSpacing(value),
  });
  const showBoxes = KINDS.map((kind) =>
    checkbox({
      label: t(`knotVectors.show.${kind}`),
      name: `show-${kind}`,
      checked: work[kind],
      onChange: (on) => {
        work[kind] = on;
        syncPanels();
        view.requestDraw();
        ctx.commit(work);
      },
    }),
  );
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: addPoint, remove: removePoint, selected: () => handles.selected });
  ctx.slots.controls.append(
    group(null, degreeSlider.element),
    group(t("knotVectors.control.spacing"), spacingRadios.element),
    group(t("knotVectors.control.show"), ...showBoxes.map((box) => box.element)),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
  );

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("knot-vectors", { caption: t("knotVectors.tableCaption") });
  const tableRows = KINDS.map((kind, index) => {
    const cells = {
      knots: el("td", { dataset: { cell: "knots" } }),
      domain: el("td", { dataset: { cell: "domain" } }),
      start: el("td", { dataset: { cell: "start" } }),
      end: el("td", { dataset: { cell: "end" } }),
    };
    const row = el("tr", { dataset: { curve: kind } },
      el("th", { scope: "row" }, el("span", { class: "sl-cell-name", text: legendLabels[index] }), el("span", { class: "sl-cell-decimal", text: t(`knotVectors.style.${kind}`) })),
      cells.knots, cells.domain, cells.start, cells.end);
    return { row, cells, name: row.querySelector(".sl-cell-name") };
  });
  table.append(
    el("thead", {}, el("tr", {}, ["curve", "knots", "domain", "start", "end"].map((key) => el("th", { scope: "col", text: t(`knotVectors.column.${key}`) })))),
    el("tbody", {}, tableRows.map((r) => r.row)),
  );
  ctx.slots.details.append(tableTitle, tableWrap);

  // ------------------------------------------------------------ edits

  /**
   * Replaces all three curves for `next` (points, degree, spacing): builds first (the core may
   * refuse, e.g. chord spacing with two equal consecutive points), then frees the old ones.
   */
  function rebuild(next) {
    const built = buildOrReport(() => buildCurves(sl, next), ctx);
    if (!built) return false;
    for (const curve of curves) curve.free();
    curves = built;
    work.points = next.points;
    work.degree = next.degree;
    work.spacing = next.spacing;
    clampedKnotsDirty = false;
    geometryDirty = true;
    view.requestDraw();
    return true;
  }

  function setDegree(p) {
    const max = Math.min(MAX_DEGREE, work.points.length - 1);
    if (p < 1 || p > max) {
      ctx.status(t("knotVectors.degreeRange", { value: p, max }), "error");
      degreeSlider.set(work.degree);
      return;
    }
    if (p === work.degree) return;
    if (rebuild({ ...work, degree: p })) ctx.commit(work);
    else degreeSlider.set(work.degree);
  }

  function setSpacing(spacing) {
    if (spacing === work.spacing) return;
    if (rebuild({ ...work, spacing })) ctx.commit(work);
    else spacingRadios.set(work.spacing);
  }

  /** Adds a point after handle i (at the end when none is selected). */
  function addPoint(i) {
    const next = withPointAdded(work.points, i, MAX_POINTS, view.scale);
    if (!next) return ctx.status(t("knotVectors.maxPoints", { max: MAX_POINTS }), "error");
    if (!rebuild({ ...work, points: next.points })) return;
    handles.select(next.index);
    ctx.commit(work);
  }

  /** Removes handle i (the last one when none is selected); the degree drops if it must. */
  function removePoint(i) {
    const next = withPointRemoved(work.points, i, MIN_POINTS);
    if (!next) return ctx.status(t("knotVectors.minPoints", { min: MIN_POINTS }), "error");
    const degree = Math.min(work.degree, next.points.length - 1);
    if (!rebuild({ ...work, points: next.points, degree })) return;
    degreeSlider.set(degree);
    handles.select(next.index);
    ctx.commit(work);
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for samples, knots and end points when something changed. */
  function recompute() {
    if (clampedKnotsDirty) {
      // Chord/centripetal knots depend on the points: a new knot vector, so a new curve.
      clampedKnotsDirty = false;
      try {
        const flat = flatten(work.points);
        const next = new sl.BSplineCurve(flat, 2, work.degree, sl.knotVector(flat, 2, work.degree, work.spacing));
        curves[0].free();
        curves[0] = next;
      } catch (err) {
        ctx.status(t("status.rejected", { message: err.message }), "error");
      }
    }
    if (geometryDirty) {
      for (let c = 0; c < KINDS.length; c++) {
        samples[c] = curves[c].sampleUniform(CURVE_SAMPLES);
        const [a, b] = curves[c].domain();
        domains[2 * c] = a;
        domains[2 * c + 1] = b;
        ends.set(curves[c].evaluate(a), 4 * c);
        ends.set(curves[c].evaluate(b), 4 * c + 2);
      }
      knotLists = curves.map((curve) => Array.from(curve.knots()));
      syncPanels();
    }
    geometryDirty = false;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const n = pts.length - 1;

    // Control polygon (closed with a dashed leg back to P₀ when the closed curve is shown).
    pointsPath(r, v, pts, 0, n + 1);
    if (work.closed) r.lineTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
    r.paint(theme.polygon);

    // The curves, each from one batched sample call, back to front; their end points marked.
    for (let c = KINDS.length - 1; c >= 0; c--) {
      if (!work[KINDS[c]]) continue;
      const s = samples[c];
      flatPath(r, v, s, 0, CURVE_SAMPLES);
      r.paint(theme.compareCurve[c]);
    }
    for (let c = 0; c < KINDS.length; c++) {
      if (!work[KINDS[c]]) continue;
      r.point(v.sx(ends[4 * c]), v.sy(ends[4 * c + 1]), theme.comparePoint[c]);
      r.point(v.sx(ends[4 * c + 2]), v.sy(ends[4 * c + 3]), theme.comparePoint[c]);
    }

    handles.draw(r, v);
    drawLegend(r, theme);
  }

  /** The legend, in the strip above the figure: a stretch of each curve's style and its name. */
  function drawLegend(r, theme) {
    const s = r.scale;
    const bottom = layoutLegend(r.width, s);
    for (let c = 0; c < KINDS.length; c++) {
      if (!work[KINDS[c]]) continue;
      const x = legendAt[2 * c];
      const y = legendAt[2 * c + 1];
      r.beginPath();
      r.moveTo(x, y);
      r.lineTo(x + LEGEND_SWATCH * s, y);
      r.paint(theme.compareCurve[c]);
      r.text(legendLabels[c], x + (LEGEND_SWATCH + LEGEND_GAP) * s, y, theme.labelSmall, "left", "middle");
    }
    if (bottom > 0) {
      r.beginPath();
      r.moveTo(0, bottom);
      r.lineTo(r.width, bottom);
      r.paint(theme.helper);
    }
  }

  // ------------------------------------------------------------ panels (formula, table, label)
  function syncPanels() {
    const pts = work.points;
    const n = pts.length - 1;
    const p = work.degree;
    degreeText.textContent = t("knotVectors.degree", { p, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;
    degreeSlider.set(p);
    if (legendLabels[0] !== t(`knotVectors.legend.clamped.${work.spacing}`) || legendWidths[0] === 0) {
      legendLabels[0] = t(`knotVectors.legend.clamped.${work.spacing}`);
      measureLegend();
    }
    setText(tableRows[0].name, legendLabels[0]);

    // Table: knots, domain and end points of each curve, from the core.
    for (let c = 0; c < KINDS.length; c++) {
      const { row, cells } = tableRows[c];
      setText(cells.knots, knotLists[c].map(knotText).join(" "));
      setText(cells.domain, `[${knotText(domains[2 * c])}, ${knotText(domains[2 * c + 1])}]`);
      const start = pointText(ends[4 * c], ends[4 * c + 1]);
      const end = pointText(ends[4 * c + 2], ends[4 * c + 3]);
      setText(cells.start, start);
      setText(cells.end, end);
      row.dataset.start = `${fmt(ends[4 * c])},${fmt(ends[4 * c + 1])}`;
      row.dataset.end = `${fmt(ends[4 * c + 2])},${fmt(ends[4 * c + 3])}`;
      row.dataset.startIsP0 = String(Math.hypot(ends[4 * c] - pts[0][0], ends[4 * c + 1] - pts[0][1]) < 1e-9);
    }

    // Formula panel: each knot vector written out with its live values.
    const clamped = knotLists[0].map(knotText).join(",\\,");
    const lines = [];
    if (work.spacing === "uniform") {
      lines.push(`U_{\\text{${t("knotVectors.tex.clamped")}}} = (\\underbrace{0,\\dots,0}_{p+1},\\ 1,\\dots,n-p,\\ \\underbrace{n-p+1,\\dots,n-p+1}_{p+1})`);
    } else {
      // The legs of the control polygon, from the points (display of the formula's numbers).
      const legs = [];
      for (let i = 0; i < n - p + 1; i++) {
        const d = Math.hypot(pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1]);
        const term = work.spacing === "chord" ? d : Math.sqrt(d);
        legs.push(Number.isInteger(term) ? String(term) : fmt(term));
      }
      const leg = work.spacing === "chord" ? "|P_{i+1}-P_i|" : "|P_{i+1}-P_i|^{1/2}";
      lines.push(`U_{\\text{${t(`knotVectors.tex.${work.spacing}`)}}}:\\ u_0 = \\dots = u_{p} = 0,\\quad u_{p+j} = \\sum_{i=0}^{j-1} ${leg}\\ \\ (j = 1,\\dots,${n - p + 1};\\ \\text{${t("knotVectors.tex.lastRepeated")}})`);
      lines.push(`\\text{${t("knotVectors.tex.legs")}}\\ ${legs.join(",\\ ")}`);
    }
    lines.push(`\\phantom{U} = (${clamped}),\\quad n = ${n},\\ p = ${p}`);
    lines.push(`U_{\\text{${t("knotVectors.tex.unclamped")}}}:\\ u_i = i,\\ i = 0,\\dots,n+p+1 = ${n + p + 1};\\quad \\text{${t("knotVectors.tex.domain")}}\\ [u_{${p}}, u_{${n + 1}}] = [${p}, ${n + 1}]`);
    lines.push(`U_{\\text{${t("knotVectors.tex.closed")}}}:\\ P_0,\\dots,P_{${n}},\\,P_0,\\dots,P_{${p - 1}};\\ u_i = i,\\ i = 0,\\dots,${n + 2 * p + 1};\\quad C^{${p - 1}}\\ \\text{${t("knotVectors.tex.seam")}}`);
    const c0 = pointText(ends[0], ends[1]);
    const u0 = pointText(ends[4], ends[5]);
    const p0 = pointText(pts[0][0], pts[0][1]);
    lines.push(`C_{\\text{${t("knotVectors.tex.clamped")}}}(u_{${p}}) = ${c0} ${c0 === p0 ? "= P_0" : "\\ne P_0"},\\qquad C_{\\text{${t("knotVectors.tex.unclamped")}}}(u_{${p}}) = ${u0} ${u0 === p0 ? "= P_0" : "\\ne P_0"}`);
    formula.set(lines);

    view.setLabel(t("knotVectors.aria", { kind: degreeName(p), count: n + 1, clamped: knotLists[0].map(knotText).join(" "), c0, u0, p0 }));
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = buildCurves(sl, state); // throws before anything changes
      for (const curve of curves) curve.free();
      curves = next;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= work.points.length) handles.select(-1);
      degreeSlider.set(work.degree);
      spacingRadios.set(work.spacing);
      KINDS.forEach((kind, c) => showBoxes[c].set(work[kind]));
      clampedKnotsDirty = false;
      geometryDirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      for (const curve of curves) curve.free();
    },
  };
}
