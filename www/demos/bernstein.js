/**
 * Demo 2 (syllabus §2): the Bernstein basis. A Bézier curve on top, and below it, in the same
 * canvas (so SVG/PNG exports hold both), the plot of every
 *
 *   B_i^n(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ,   t ∈ [0, 1],
 *
 * each in the colour of its control point. A marker at t lists the weights B_i^n(t) and their
 * sum (= 1); hovering a basis function (in the plot or the table) or selecting a control point
 * shows where that point acts most: the single maximum of B_i^n at t = i/n and the curve point
 * P(i/n). The plot comes from one `bernsteinBasis(n, count)` call per degree, the curve from
 * `sampleUniform`, the weights from `bernstein(n, i, t)`: nothing is evaluated in JS.
 */
import { NOTES_CUBIC } from "../lib/examples.js";
import { field } from "../lib/validate.js";
import { slider, pointButtons, readout, group } from "../lib/panel.js";
import { BEZIER_POINTS } from "../lib/point-list.js";
import { placeLabelAway } from "../lib/handles.js";
import { el, setText } from "../lib/controls.js";
import {
  fmt,
  subscript,
  superscript,
  simpleFraction,
  exactFraction,
  fractionText,
  fractionTex,
  exactNumbers,
  degreeName,
  binomial,
  fmtTex,
  pointTex,
  listTex,
  listText,
  texListSeparator,
} from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, paddedBounds, nearestGraph } from "../lib/geometry.js";
import { detailsTable, headerRow, valueSpans, setValueSpans } from "../lib/table.js";
import {
  BasisPlotPointer,
  drawBand,
  drawGraphs,
  drawPlotFrame,
  followHighlight,
  legendRow,
} from "../lib/basis-plot.js";
import { PlotStrip } from "../lib/plot-strip.js";
import { flatPath, pointsPath } from "../lib/draw.js";

export const id = "bernstein";
export const strings = "bernstein";
export const section = 2;

/**
 * Samples along the curve and along each basis function: the same count, so sample k of both
 * is at the same t = k / (SAMPLES − 1) (the highlighted band on the curve uses that).
 */
const SAMPLES = 201;
/** Fitting leaves this fraction of the height free above and below for the handles' labels (a short curve area). */
const LABEL_ROOM = 0.08;
/** Slider resolution for t. */
const T_SLIDER_STEP = 0.001;
/**
 * The plot below the curve (CSS px): t from x0 to x1, value 0 at y0 and 1 at y1. Its strip takes
 * 0.4 of the canvas height, at least 150 px, but never more than 0.55 of a short canvas (gallery
 * thumbnails); the margins of the frame inside it hold the labels.
 */
const plot = new PlotStrip({
  fraction: 0.4,
  minPx: 150,
  shortFraction: 0.55,
  margin: Object.freeze({ top: 30, right: 22, bottom: 34, left: 40 }),
});
/** Tick labels i/n on the t axis only while they are at least this far apart (CSS px). */
const TICK_LABEL_MIN_GAP = 34;
/** Curve names B_i^n are written at the peaks up to this degree (beyond, they crowd). */
const NAME_LABELS_MAX_DEGREE = 6;
/** A pointer this close (CSS px, vertically) to a basis curve highlights it. */
const PLOT_HOVER_PX = 14;
/** Dragging t in the plot snaps to a tick i/n within this many CSS px. */
const TICK_SNAP_PX = 5;
/** The band on the curve marks where the highlighted B_i^n is at least this fraction of its maximum. */
const BAND_FRACTION = 0.5;
/** Sums in the formula panel switch from fractions to decimals beyond this common denominator. */
const FORMULA_MAX_DENOMINATOR = 4096;
/** Length of a tick mark on the axes, CSS px. */
const TICK_PX = 5;

/** The worked example of the Greek notes (syllabus §2) at t = 1/4: weights 27/64, 27/64, 9/64, 1/64. */
export const defaultState = Object.freeze({
  points: NOTES_CUBIC,
  t: 0.25,
});

export const fields = {
  points: field.points(BEZIER_POINTS),
  t: field.number({ min: 0, max: 1 }),
};

/** The curve, in wasm; a dragged point moves it in place. */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({ curve: new sl.BezierCurve(flatten(s.points), 2) }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/**
 * The basis of degree n from the core: every B_i^n at SAMPLES values of t (i-major), the
 * maxima B_i^n(i/n) and their parameters i/n. Asked again only when the degree changed.
 */
function basisOfDegree(sl, n, previous) {
  if (previous?.n === n) return previous;
  const peakTs = new Float64Array(n + 1);
  const peakValues = new Float64Array(n + 1);
  for (let i = 0; i <= n; i++) {
    peakTs[i] = i / n;
    peakValues[i] = sl.bernstein(n, i, i / n);
  }
  return { n, values: sl.bernsteinBasis(n, SAMPLES), peakTs, peakValues };
}

/** The texts of degree n: names B_i^n, ticks i/n, "max at t = i/n", "P(i/n)"; made again only for a new degree. */
function labelsOfDegree(n, previous) {
  if (previous?.n === n) return previous;
  const labels = { n, names: [], ticks: [], peaks: [], peakPoints: [] };
  for (let i = 0; i <= n; i++) {
    const tick = fractionText(exactFraction(i / n, n));
    labels.names.push(`B${subscript(i)}${superscript(n)}`);
    labels.ticks.push(tick);
    labels.peaks.push(t("bernstein.peakLabel", { t: tick }));
    labels.peakPoints.push(t("bernstein.peakPointLabel", { t: tick }));
  }
  return labels;
}

/** "t = 1/4" above the marker. */
function markerText(tValue) {
  const f = simpleFraction(tValue);
  return t("bernstein.marker", { t: f ? fractionText(f) : fmt(tValue) });
}

/** The weights at t: B_i^n(t), the mirrored B_{n−i}^n(1 − t) (symmetry) and their sum. */
function weightsAt(sl, n, tValue) {
  const values = new Float64Array(n + 1);
  const mirrored = new Float64Array(n + 1);
  let sum = 0;
  for (let i = 0; i <= n; i++) {
    values[i] = sl.bernstein(n, i, tValue);
    mirrored[i] = sl.bernstein(n, n - i, 1 - tValue);
    sum += values[i];
  }
  return { values, mirrored, sum };
}

/** What the core returns (basis, samples, P(i/n) for every i, weights, P(t)); the texts; the highlight. */
export const compute = {
  basis: [["points"], (s, d) => basisOfDegree(d.sl, s.points.length - 1, d.basis)],
  samples: [["points"], (s, d) => d.curve.sampleUniform(SAMPLES)],
  peakPoints: [["points"], (s, d) => d.curve.sample(d.basis.peakTs)],
  weights: [["points", "t"], (s, d) => weightsAt(d.sl, s.points.length - 1, s.t)],
  point: [["points", "t"], (s, d) => d.curve.evaluate(s.t)],
  labels: [["points"], (s, d) => labelsOfDegree(s.points.length - 1, d.labels)],
  marker: [["t"], (s) => markerText(s.t)],
  /** The basis function highlighted by the plot, a table row or a handle (setup's pointer), or -1. */
  highlight: [["highlight", "points"], (s, d) => d.highlighted()],
};

export const controls = [
  group(
    null,
    slider("t", { label: "control.t", min: 0, max: 1, step: T_SLIDER_STEP, player: true }),
    readout("sum", sumNote),
  ),
  group(
    null,
    readout("degree", (s) =>
      t("bernstein.degree", { n: s.points.length - 1, count: s.points.length }),
    ),
    pointButtons("points", { ...BEZIER_POINTS, prefix: strings }),
  ),
  group(
    null,
    readout("peak", (s, d) => peakNote(s, d), { live: true }),
  ),
];

export const figure = {
  bounds: (s) => paddedBounds(s.points, 0, LABEL_ROOM),
  insets: (width, height) => {
    insetScratch[2] = plot.height(height);
    return insetScratch;
  },
  handles: { field: "points" },
};

const insetScratch = [0, 0, 0, 0];
const py = (value) => plot.y(value);
const sampleX = (k) => plot.x(k / (SAMPLES - 1));

// ------------------------------------------------------------ drawing

/** The curve area: polygon, the highlighted function's band, the curve, the rings, P(t) and P(i/n). */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  const n = pts.length - 1;
  const hi = d.highlight;
  const cycle = theme.basisStroke.length;
  const { values: basis, peakValues } = d.basis;
  pointsPath(r, v, pts, 0, n + 1);
  r.paint(theme.polygon);

  // Where the highlighted B_i^n is at least half its maximum: a band in its colour under the curve.
  if (hi >= 0) {
    const threshold = BAND_FRACTION * peakValues[hi];
    const inside = (k) => basis[hi * SAMPLES + k] >= threshold;
    drawBand(r, v, d.samples, SAMPLES, inside, theme.basisBand[hi % cycle]);
  }
  flatPath(r, v, d.samples, 0, SAMPLES);
  r.paint(theme.curve);

  // Every control point ringed in its basis function's colour.
  for (let i = 0; i <= n; i++)
    r.point(v.sx(pts[i][0]), v.sy(pts[i][1]), theme.basisRing[i % cycle]);

  // The highlighted point's peak: P(i/n) on the curve, joined to P_i.
  const peakX = hi >= 0 ? v.sx(d.peakPoints[2 * hi]) : 0;
  const peakY = hi >= 0 ? v.sy(d.peakPoints[2 * hi + 1]) : 0;
  if (hi >= 0) {
    r.beginPath();
    r.moveTo(v.sx(pts[hi][0]), v.sy(pts[hi][1]));
    r.lineTo(peakX, peakY);
    r.paint(theme.helper);
  }
  d.handles.draw(r, v);

  const pointX = v.sx(d.point[0]);
  const pointY = v.sy(d.point[1]);
  r.point(pointX, pointY, theme.pointOnCurve);
  const pointRadius = theme.pointOnCurve.radius * r.scale;
  placeLabelAway(
    r,
    v,
    pts,
    t("bernstein.pointLabel"),
    pointX,
    pointY,
    theme.labelPoint,
    pointRadius,
  );
  if (hi >= 0) {
    r.point(peakX, peakY, theme.basisPoint[hi % cycle]);
    const peakRadius = theme.basisPoint[0].radius * r.scale;
    placeLabelAway(r, v, pts, d.labels.peakPoints[hi], peakX, peakY, theme.labelBold, peakRadius);
  }
  drawPlot(r, s, d);
}

/** The plot strip (screen space, below the world window; covers anything panned into it). */
function drawPlot(r, s, d) {
  const theme = r.theme;
  const n = s.points.length - 1;
  const hi = d.highlight;
  const { values: basis, peakValues } = d.basis;
  plot.layout(r.width, r.height, r.scale);
  drawPlotFrame(r, plot, {
    zero: t("bernstein.axisValue0"),
    one: t("bernstein.axisValue1"),
    tick: TICK_PX,
  });
  r.text(
    t("bernstein.axisT"),
    plot.x1 + (TICK_PX + 2) * r.scale,
    plot.y0,
    theme.labelSmall,
    "left",
    "middle",
  );

  // Ticks at i/n, labelled while the labels keep TICK_LABEL_MIN_GAP apart (the last one always).
  plot.drawTicks(r, n, d.labels.ticks, { tick: TICK_PX, minGap: TICK_LABEL_MIN_GAP });

  // The basis functions from the core's table, and their names at the peaks (B_0 left, B_n right).
  drawGraphs(r, basis, n + 1, SAMPLES, sampleX, py, hi);
  const align = (i) => (i === 0 ? "left" : i === n ? "right" : "center");
  const nudge = (i, amount) => (i === 0 ? amount : i === n ? -amount : 0) * r.scale;
  if (n <= NAME_LABELS_MAX_DEGREE) {
    for (let i = 0; i <= n; i++) {
      const style = i === hi ? theme.labelBold : theme.labelSmall;
      r.text(
        d.labels.names[i],
        plot.x(i / n) + nudge(i, 4),
        py(peakValues[i]) - 5 * r.scale,
        style,
        align(i),
        "bottom",
      );
    }
  }

  // The highlighted function's maximum at t = i/n.
  if (hi >= 0) {
    const x = plot.x(hi / n);
    const y = py(peakValues[hi]);
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x, plot.y0);
    r.paint(theme.helper);
    r.point(x, y, theme.basisPoint[hi % theme.basisPoint.length]);
    r.text(
      d.labels.peaks[hi],
      x + nudge(hi, 8),
      (y + plot.y0) / 2,
      theme.labelBold,
      align(hi),
      "middle",
    );
  }

  // The marker at t, with the weights B_i^n(t) as dots.
  plot.drawMarker(r, s.t, d.marker, d.weights.values, theme.basisPoint);
}

// ------------------------------------------------------------ formula, notes, label

/**
 * Exact text when t = a/b is a simple fraction (format.js `exactNumbers`): the weights B_i^n(t)
 * are then k / bⁿ (`weights.value(w, n)`), and so is P(t) when the control points are integers.
 */
const weightNumbers = (s) => exactNumbers(s.t, []);

/**
 * The definition, one function written out with its numbers (the highlighted one, else the one
 * whose maximum i/n lies nearest t), the partition of unity and the curve point.
 */
export function formula(s, d) {
  const n = s.points.length - 1;
  const w = weightNumbers(s);
  const p = exactNumbers(s.t, s.points.flat());
  const { values, sum } = d.weights;
  const [x, y] = d.point;
  const tTex = w.param(true);
  const f = w.exact;
  const focus = d.highlight >= 0 ? d.highlight : Math.round(s.t * n);
  // Long sums read better in decimals once the common denominator grows large (the table keeps fractions).
  const compact = Boolean(f) && f.den ** n > FORMULA_MAX_DENOMINATOR;
  const terms = Array.from(values, (value) => (compact ? fmtTex(value) : w.value(value, n, true)));
  const weighted = terms.map((term, i) => `${term}\\,P_{${i}}`);
  const coordinate = (value) => (compact ? fmtTex(value) : p.value(value, n, true));
  const exactPoint = p.exact && !compact;
  const fractional = !Number.isInteger(x) || !Number.isInteger(y);
  const approx = exactPoint && fractional ? `\\approx ${pointTex([x, y])}` : "";
  // t^i and (1 − t)^(n−i) written out (exact when t is a simple fraction): display only.
  const power = (a, b, k) => (f ? fractionTex({ num: a ** k, den: b ** k }) : fmtTex((a / b) ** k));
  const tPower = f ? power(f.num, f.den, focus) : power(s.t, 1, focus);
  const sPower = f ? power(f.den - f.num, f.den, n - focus) : power(1 - s.t, 1, n - focus);
  const oneMinusTex = f ? fractionTex({ num: f.den - f.num, den: f.den }) : fmtTex(1 - s.t);
  const peak = `\\text{${t("bernstein.formulaPeak")}}\\ t = ${fractionTex(exactFraction(focus / n, n))}`;
  const B = `B_{${focus}}^{${n}}`;
  return [
    `B_i^{${n}}(t) = \\binom{${n}}{i}\\, t^{i}\\,(1-t)^{${n}-i},\\qquad ` +
      `\\max_{[0${texListSeparator("")}1]} B_i^{${n}} = B_i^{${n}}\\!\\left(\\tfrac{i}{${n}}\\right),\\qquad t = ${tTex}`,
    `${B}(${tTex}) = \\binom{${n}}{${focus}} \\left(${tTex}\\right)^{${focus}} ` +
      `\\left(${oneMinusTex}\\right)^{${n - focus}} = ` +
      `${binomial(n, focus)} \\cdot ${tPower} \\cdot ${sPower} = ${w.value(values[focus], n, true)},\\qquad ${peak}`,
    `\\sum_{i=0}^{${n}} B_i^{${n}}(${tTex}) = ${terms.join(" + ")} = ${w.value(sum, n, true)}`,
    `P(${tTex}) = \\sum_{i=0}^{${n}} B_i^{${n}}(${tTex})\\,P_i = ${weighted.join(" + ")} = ` +
      `\\left(${listTex([coordinate(x), coordinate(y)])}\\right) ${approx}`,
  ];
}

/** "Sum of the 4 weights at t = 1/4: 1". */
function sumNote(s, d) {
  const w = weightNumbers(s);
  const sum = w.value(d.weights.sum, s.points.length - 1);
  return t("bernstein.sumNote", { count: s.points.length, t: w.param(), sum });
}

/** Where the highlighted function acts most: its maximum at t = i/n and the curve point P(i/n). */
function peakNote(s, d) {
  const hi = d.highlight;
  if (hi < 0) return t("bernstein.peakHint");
  const n = s.points.length - 1;
  // P(i/n) has denominator nⁿ; fractions are shown when t and the points are exact.
  const p = exactNumbers(s.t, s.points.flat());
  const x = p.value(d.peakPoints[2 * hi], n, false, n ** n);
  const y = p.value(d.peakPoints[2 * hi + 1], n, false, n ** n);
  return t("bernstein.peakNote", {
    b: d.labels.names[hi],
    p: `P${subscript(hi)}`,
    t: d.labels.ticks[hi],
    x,
    y,
  });
}

/** The curve, its weights at t and their sum, P(t), and the highlighted function's maximum. */
export function label(s, d) {
  const n = s.points.length - 1;
  const { values, sum } = d.weights;
  const hi = d.highlight;
  const text = t("bernstein.aria", {
    kind: degreeName(n),
    count: n + 1,
    n,
    t: fmt(s.t),
    values: listText(values),
    sum: fmt(sum),
    x: fmt(d.point[0], 2),
    y: fmt(d.point[1], 2),
  });
  if (hi < 0) return text;
  const [x, y] = [d.peakPoints[2 * hi], d.peakPoints[2 * hi + 1]];
  return (
    text +
    t("bernstein.ariaPeak", {
      b: d.labels.names[hi],
      t: d.labels.ticks[hi],
      x: fmt(x, 2),
      y: fmt(y, 2),
    })
  );
}

// ------------------------------------------------------------ the plot's pointer and the legend table

/**
 * The taller figure, the plot's pointer (press or drag sets t, snapped to a tick i/n; hover
 * highlights a graph) and the table: one row per basis function (the legend), then the sum.
 */
export function setup(ui) {
  const view = ui.view;
  ui.ctx.slots.figure.classList.add("sl-figure-tall"); // the curve and the plot share it
  const inPlot = (x, y) => {
    plot.layout(view.width, view.height, view.renderer.scale);
    return plot.contains(x, y, TICK_SNAP_PX);
  };
  /** t under canvas x in the plot: snapped to a tick i/n nearby, else to the slider's step. */
  const tAtPixel = (x) => {
    plot.layout(view.width, view.height, view.renderer.scale);
    return plot.snappedParameter(x, ui.state.points.length - 1, TICK_SNAP_PX, T_SLIDER_STEP);
  };
  const pointer = new BasisPlotPointer(view, {
    inPlot,
    graphAt: (x, y) => {
      const k = Math.round(plot.parameterAt(x) * (SAMPLES - 1));
      return nearestGraph(
        ui.data.basis.values,
        ui.state.points.length,
        SAMPLES,
        k,
        y,
        py,
        PLOT_HOVER_PX,
      );
    },
    pick: (x, final) => ui.set("t", tAtPixel(x), final),
    press: () => ui.stop(),
    enter: () => ui.handles.leave(),
    first: true,
  });
  followHighlight(ui, pointer);

  /** One row per basis function (the legend, hovering a row highlights it), then the sum. */
  const details = detailsTable(ui, "bernstein", (n, table) => {
    const {
      basis: { peakValues },
      labels,
    } = ui.data;
    pointer.setRowHover(-1); // the hovered row, if any, is gone
    const rows = [];
    const head = headerRow("bernstein.", ["colFunction", "colValue", "colMirror", "colPeak"]);
    for (let i = 0; i <= n; i++) {
      const cells = { value: valueSpans(), mirror: valueSpans() };
      const peakValue = exactFraction(peakValues[i], n ** n) ?? exactFraction(peakValues[i], 1);
      const peakText = t("bernstein.peakCell", {
        t: labels.ticks[i],
        value: peakValue ? fractionText(peakValue) : fmt(peakValues[i]),
      });
      cells.row = legendRow(
        pointer,
        i,
        t("bernstein.rowName", { b: labels.names[i], p: `P${subscript(i)}` }),
        el("td", { dataset: { cell: "value" } }, cells.value.exact, cells.value.decimal),
        el("td", { dataset: { cell: "mirror" } }, cells.mirror.exact, cells.mirror.decimal),
        el("td", { dataset: { cell: "peak" }, text: peakText }),
      );
      rows.push(cells);
    }
    const sum = valueSpans();
    const sumRow = el(
      "tr",
      { dataset: { index: "sum" } },
      el("th", { scope: "row", text: t("bernstein.sumRow") }),
      el("td", { dataset: { cell: "value" } }, sum.exact, sum.decimal),
      el("td", {}),
      el("td", {}),
    );
    table.replaceChildren(
      el("thead", {}, head),
      el(
        "tbody",
        {},
        rows.map((cells) => cells.row),
        sumRow,
      ),
    );
    return { rows, sum };
  });

  return {
    update(s, d) {
      const n = s.points.length - 1;
      const { rows, sum: sumCells } = details.cellsFor(n);
      const w = weightNumbers(s);
      const fill = (spans, value) => setValueSpans(spans, w.value(value, n), fmt(value));
      setText(details.title, t("bernstein.tableCaption", { n, t: w.param() }));
      for (let i = 0; i <= n; i++) {
        fill(rows[i].value, d.weights.values[i]);
        fill(rows[i].mirror, d.weights.mirrored[i]);
        rows[i].row.classList.toggle("sl-highlight", i === d.highlight);
      }
      // The sum reads "1" alone when it is exactly 1 (no "≈ 1.000" underneath).
      const sum = w.value(d.weights.sum, n);
      setValueSpans(sumCells, sum, /^\d+$/.test(sum) ? sum : fmt(d.weights.sum));
    },
  };
}
