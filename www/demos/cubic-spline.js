/**
 * Demo (syllabus §5): the end-condition lab of C2 cubic splines. Through the points p_0 … p_n at
 * parameters t_0 < … < t_n, the piecewise cubic Hermite curve whose tangents m_i = C′(t_i) solve
 *
 *   Δ_i m_{i−1} + 2(Δ_{i−1} + Δ_i) m_i + Δ_{i−1} m_{i+1}
 *       = 3(Δ_i/Δ_{i−1} (p_i − p_{i−1}) + Δ_{i−1}/Δ_i (p_{i+1} − p_i)),   Δ_i = t_{i+1} − t_i,
 *
 * (C″ continuous at t_1 … t_{n−1}) plus one equation at each end: natural, clamped, quadratic,
 * Bessel, not-a-knot or periodic. Everything comes from the core's `cubicSpline`: the curve
 * (`sampleUniform`), the system it solved (`system()`, shown as a table with the end rows
 * highlighted), the tangents, and C″ and C‴ per piece (`sampleDerivatives`) in plots under the
 * figure: C″ continuous at the joins, C‴ jumping (but not where not-a-knot forbids it).
 *
 * Rules of the picture:
 * - Periodic: the state holds the distinct points P₀ … Pₙ; the periodic spline is given
 *   P₀ … Pₙ, P₀ (its last data point *is* P₀, as the core requires), so the curve closes through
 *   P₀ and dragging P₀ moves both ends.
 * - Clamped: the arrows at P₀ and Pₙ are the end tangents drawn at a third of their piece:
 *   tip₀ = p₀ + Δ₀ m₀ / 3 (the Bézier point q₁ of the first piece) and tipₙ = pₙ + Δₙ₋₁ mₙ / 3;
 *   the state holds the tips (`tangentTips`), and an arrow rides along when its point is dragged.
 * - Drags: uniform parameters do not depend on the points, so a drag moves the point in place
 *   (`setPoint` on every spline shown); chord and centripetal parameters do, so those splines are
 *   rebuilt from the new parameters once per applied move (as knot-vectors does for its knots).
 */
import { field, checkPoints } from "../lib/validate.js";
import { checkbox, choice, pointButtons, readout, group } from "../lib/panel.js";
import { fmt, subscript, shortNumber } from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { flatPath, arrow } from "../lib/draw.js";
import { HUES, WIDTH, themed } from "../lib/theme.js";
import { legendBand } from "../lib/legend.js";
import { drawPlotStrip } from "../lib/plot-strip.js";
import { PiecePlot, pieceParameters } from "../lib/piece-plot.js";
import { pointLabel } from "../lib/handles.js";
import { SystemTable } from "../lib/system-table.js";
import {
  endRowTex,
  interiorRowTex,
  rowLabel,
  deltasTex,
  numericRowTex,
  systemEntry,
} from "../lib/spline-system.js";

export const id = "cubic-spline";
export const strings = "cubicSpline";
export const section = 5;

/** The six end conditions, in legend order (the names `cubicSpline` takes). */
export const ENDS = Object.freeze([
  "natural",
  "clamped",
  "quadratic",
  "bessel",
  "not-a-knot",
  "periodic",
]);
/** The parametrisations offered (`parameterize`'s kinds). */
export const PARAMETRIZATIONS = Object.freeze(["uniform", "chord", "centripetal"]);
/** Fewest and most data points (the core may ask for more for some conditions: it says so). */
export const MIN_POINTS = 3;
export const MAX_POINTS = 16;
/** Samples along each curve (one `sampleUniform` per curve and change). */
const CURVE_SAMPLES = 400;
/** C″ is linear and C‴ constant on each piece: two samples per piece draw them exactly. */
const PER_PIECE = 2;
/** Rows and columns of the system shown at most, normally and in lecture mode. */
const MAX_SHOWN = 9;
const MAX_SHOWN_LECTURE = 5;
/** The plot band: fraction of the canvas height (one plot, two plots), its least height (CSS px). */
const PLOT_FRACTION = Object.freeze([0.3, 0.46]);
const PLOT_MIN_PX = Object.freeze([120, 200]);
/** Room around the points for labels, as fractions of the box. */
const ROOM = Object.freeze([0.08, 0.12]);

/** Six points with uneven gaps (so chord and centripetal differ from uniform). */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [1, 3],
      [4, 4],
      [6, 1],
      [9, 0],
      [10, 3],
    ].map(Object.freeze),
  ),
  end: "natural",
  compare: false,
  parametrization: "uniform",
  tangentTips: Object.freeze([Object.freeze([1.5, -0.5]), Object.freeze([10.5, 4.5])]),
  third: true,
});

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  end: field.choice(ENDS),
  compare: field.boolean(),
  parametrization: field.choice(PARAMETRIZATIONS),
  tangentTips(s, name) {
    checkPoints(s, name, { min: 2, max: 2 });
  },
  third: field.boolean(),
};

/** Six curves in one figure: an Okabe–Ito hue and a dash pattern each (never colour alone). */
const CURVE_LOOKS = Object.freeze([
  [HUES.blue, null],
  [HUES.vermillion, [12, 6]],
  [HUES.bluishGreen, [0.5, 6]],
  [HUES.reddishPurple, [12, 5, 1, 5]],
  [HUES.orange, [5, 4]],
  [HUES.skyBlue, [14, 4, 1, 4, 1, 4]],
]);
const stylesFor = themed((theme) => ({
  curves: CURVE_LOOKS.map(([stroke, dash]) => ({
    stroke,
    width: WIDTH.curve,
    join: "round",
    cap: "round",
    ...(dash ? { dash: Object.freeze(dash) } : {}),
  })),
  tangent: Object.freeze({ stroke: HUES.vermillion, width: 2 }),
  band: theme.highlightBand,
}));
/** The legend's entries (label keys, styles), in ENDS order. */
const LEGEND = Object.freeze(
  ENDS.map((end, k) =>
    Object.freeze({
      label: `cubicSpline.end.${end}`,
      style: (theme) => stylesFor(theme).curves[k],
    }),
  ),
);

// ------------------------------------------------------------ the splines

/** The data given to the core for end condition `end`: the points (closed for periodic), their params. */
function dataFor(sl, s, end) {
  const points = end === "periodic" ? [...s.points, s.points[0]] : s.points;
  const flat = flatten(points);
  return { flat, params: sl.parameterize(flat, 2, s.parametrization) };
}

/** The clamped tangents from the arrows' tips: m₀ = 3(tip₀ − p₀)/Δ₀, mₙ = 3(tipₙ − pₙ)/Δₙ₋₁. */
function clampedTangents(s, params) {
  const n = s.points.length - 1;
  const [p0, pn] = [s.points[0], s.points[n]];
  const [a, b] = s.tangentTips;
  const first = 3 / (params[1] - params[0]);
  const last = 3 / (params[n] - params[n - 1]);
  return [
    [first * (a[0] - p0[0]), first * (a[1] - p0[1])],
    [last * (b[0] - pn[0]), last * (b[1] - pn[1])],
  ];
}

/** The core's spline for end condition `end` (throws its refusal). */
function splineFor(sl, s, end) {
  const { flat, params } = dataFor(sl, s, end);
  if (end !== "clamped") return sl.cubicSpline(flat, 2, params, end);
  const [m0, mn] = clampedTangents(s, params);
  return sl.cubicSpline(flat, 2, params, end, m0, mn);
}

/** Every spline of `ends`, or the core's refusal (none left allocated). */
function splinesFor(sl, s, ends) {
  const made = [];
  try {
    for (const end of ends) made.push(splineFor(sl, s, end));
  } catch (err) {
    for (const spline of made) spline.free();
    throw err;
  }
  return made;
}

/** Index in the model of the chosen condition's spline (the table, plots and formula show it). */
const chosen = (s, d) => Math.max(0, d.ends.indexOf(s.end));

/** The arrow tip of point `i` (0 or n) moves with it by (dx, dy). */
function carryTip(s, i, dx, dy) {
  const k = i === 0 ? 0 : 1;
  s.tangentTips[k][0] += dx;
  s.tangentTips[k][1] += dy;
}

/** Replaces every spline of the model from the state (chord / centripetal drags). */
function rebuildAll(m, s) {
  try {
    const next = splinesFor(m.sl, s, m.ends);
    m.curves.forEach((spline) => spline.free());
    m.curves.splice(0, m.curves.length, ...next);
  } catch (err) {
    m.refusal.message = err.message;
  }
}

/** The splines shown, in wasm: one, or all six when compared. */
export const derive = {
  from: ["points", "end", "compare", "parametrization"],
  build(s, sl) {
    const ends = s.compare ? ENDS : [s.end];
    const n = s.points.length - 1;
    const ends0 = [s.points[0][0], s.points[0][1], s.points[n][0], s.points[n][1]];
    return { curves: splinesFor(sl, s, ends), ends, sl, refusal: { message: null }, ends0 };
  },
  moved(m, i, xy, s) {
    const n = s.points.length - 1;
    if (i === 0 || i === n) {
      const at = i === 0 ? 0 : 2;
      carryTip(s, i, xy[0] - m.ends0[at], xy[1] - m.ends0[at + 1]);
      m.ends0[at] = xy[0];
      m.ends0[at + 1] = xy[1];
    }
    if (s.parametrization !== "uniform") return rebuildAll(m, s);
    m.curves.forEach((spline, k) => {
      spline.setPoint(i, xy);
      if (i === 0 && m.ends[k] === "periodic") spline.setPoint(n + 1, xy);
    });
  },
  inPlace: {
    /** A dragged arrow: only the clamped spline is made again (its tangents are inputs). */
    tangentTips(m, s) {
      const k = m.ends.indexOf("clamped");
      if (k < 0) return;
      try {
        const next = splineFor(m.sl, s, "clamped");
        m.curves[k].free();
        m.curves[k] = next;
      } catch (err) {
        m.refusal.message = err.message;
      }
    },
  },
};

const CHANGES = ["points", "end", "compare", "parametrization", "tangentTips"];

/** The chosen spline's teaching data: params, tangents, the system, C″ and C‴ per piece. */
function chosenData(s, d) {
  const spline = d.curves[chosen(s, d)];
  const params = spline.params();
  const ts = pieceParameters(params, PER_PIECE);
  return {
    end: d.ends[chosen(s, d)],
    params,
    tangents: spline.tangents(),
    system: spline.system(),
    second: spline.sampleDerivatives(ts, 2),
    third: spline.sampleDerivatives(ts, 3),
    ticks: Array.from(params, (u) => shortNumber(u)),
  };
}

export const compute = {
  samples: [CHANGES, (s, d) => d.curves.map((spline) => spline.sampleUniform(CURVE_SAMPLES))],
  main: [CHANGES, chosenData],
};

export const controls = [
  group(
    "cubicSpline.control.end",
    choice("end", {
      options: ENDS.map((value) => ({ value, label: `cubicSpline.end.${value}` })),
      rebuild: true,
    }),
    checkbox("compare", { label: "cubicSpline.control.compare" }),
  ),
  group(
    "cubicSpline.control.parametrization",
    choice("parametrization", {
      options: PARAMETRIZATIONS.map((value) => ({
        value,
        label: `cubicSpline.parametrization.${value}`,
      })),
      rebuild: true,
    }),
  ),
  group(null, checkbox("third", { label: "cubicSpline.control.third" })),
  group(
    null,
    readout("points", (s) =>
      tp("cubicSpline.pointCount", s.points.length, { n: s.points.length - 1 }),
    ),
    pointButtons("points", {
      min: MIN_POINTS,
      max: MAX_POINTS,
      prefix: strings,
      // The arrows keep their vectors at the (possibly new) first and last points.
      adjust: (next, ui) => keepTips(ui.state, next),
    }),
  ),
];

/** `next` with the arrow tips at the same offsets from its first and last points as in `before`. */
function keepTips(before, next) {
  const offset = (tip, p) => [tip[0] - p[0], tip[1] - p[1]];
  const [a, b] = before.tangentTips;
  const da = offset(a, before.points[0]);
  const db = offset(b, before.points[before.points.length - 1]);
  const p0 = next.points[0];
  const pn = next.points[next.points.length - 1];
  return {
    ...next,
    tangentTips: [
      [p0[0] + da[0], p0[1] + da[1]],
      [pn[0] + db[0], pn[1] + db[1]],
    ],
  };
}

const showsClamped = (s) => s.compare || s.end === "clamped";

/** The plot band's height in a canvas `height` CSS px tall. */
function plotBand(height, third) {
  const k = third ? 1 : 0;
  return Math.min(
    Math.round(height * 0.6),
    Math.max(Math.round(height * PLOT_FRACTION[k]), PLOT_MIN_PX[k]),
  );
}

const insets = [0, 0, 0, 0];
export const figure = {
  bounds: (s) =>
    paddedBounds(showsClamped(s) ? [...s.points, ...s.tangentTips] : s.points, ...ROOM),
  insets(width, height, scale, s, d) {
    insets[0] =
      s.compare && d.view ? legendBand(d.view.renderer, LEGEND, width, { draw: false }) : 0;
    insets[2] = plotBand(height, s.third);
    return insets;
  },
  handles: {
    field: "points",
    label: (i, s) =>
      i === 0 && s.end === "periodic" && !s.compare
        ? t("cubicSpline.closingLabel", { n: subscript(s.points.length) })
        : pointLabel(i),
    extra: [
      { field: "tangentTips", index: 0, label: "cubicSpline.tipStart", when: showsClamped },
      { field: "tangentTips", index: 1, label: "cubicSpline.tipEnd", when: showsClamped },
    ],
  },
};

// ------------------------------------------------------------ drawing

const upper = new PiecePlot();
const lower = new PiecePlot();

/** The curves (the chosen one on a band, on top), the clamped arrows, the handles, the legend, the plots. */
export function draw(r, v, s, d) {
  const styles = stylesFor(r.theme);
  const k0 = chosen(s, d);
  const styleOf = (k) =>
    d.curves.length > 1 ? styles.curves[ENDS.indexOf(d.ends[k])] : r.theme.curve;
  if (d.curves.length > 1) {
    flatPath(r, v, d.samples[k0], 0, CURVE_SAMPLES);
    r.paint(styles.band);
  }
  for (let k = d.curves.length - 1; k >= 0; k--) {
    if (k === k0) continue;
    flatPath(r, v, d.samples[k], 0, CURVE_SAMPLES);
    r.paint(styleOf(k));
  }
  flatPath(r, v, d.samples[k0], 0, CURVE_SAMPLES);
  r.paint(styleOf(k0));
  if (showsClamped(s)) {
    const n = s.points.length - 1;
    for (const [p, tip] of [
      [s.points[0], s.tangentTips[0]],
      [s.points[n], s.tangentTips[1]],
    ])
      arrow(r, v.sx(p[0]), v.sy(p[1]), v.sx(tip[0]), v.sy(tip[1]), styles.tangent);
  }
  d.handles.draw(r, v);
  if (s.compare) legendBand(r, LEGEND, r.width);
  drawPlots(r, s, d);
}

/** C″ (and C‴) of the chosen spline per piece, in the band under the figure, sharing the t axis. */
function drawPlots(r, s, d) {
  const band = plotBand(r.height, s.third);
  const top = r.height - band;
  drawPlotStrip(r, { top, bottom: r.height });
  const { params, second, third, ticks } = d.main;
  const key = [t("cubicSpline.plotX"), t("cubicSpline.plotY")];
  const common = { dim: 2, perPiece: PER_PIECE, params, key };
  const middle = s.third ? top + band * 0.47 : r.height;
  upper.place(0, r.width, top, middle, r.scale, { tickLabels: !s.third });
  upper.draw(r, { ...common, values: second, title: t("cubicSpline.plotSecond") });
  if (s.third) {
    lower.place(0, r.width, middle, r.height, r.scale, { tickLabels: true });
    lower.draw(r, { ...common, values: third, title: t("cubicSpline.plotThird") });
  }
  (s.third ? lower : upper).drawTicks(r, params, ticks);
}

// ------------------------------------------------------------ formula, label

/** The interior row in general, the Δ's, row 1 with its numbers, and the two end rows. */
export function formula(s, d) {
  const { end, params, system } = d.main;
  const size = system.diagonal.length;
  const lines = [
    interiorRowTex(),
    deltasTex(params, t(`cubicSpline.parametrization.${s.parametrization}`)),
  ];
  if (size > 2) lines.push(`i = 1:\\ ${numericRowTex(system, 1, size)}`);
  const n = params.length - 1;
  lines.push(endRowTex(end, "start", n, system, size));
  lines.push(endRowTex(end, "end", n, system, size));
  return lines;
}

/** "C2 cubic spline through 6 points, natural ends, uniform parameters; m₀ = (…)". */
export function label(s, d) {
  const { tangents } = d.main;
  const last = tangents.length / 2 - 1;
  return t("cubicSpline.aria", {
    count: s.points.length,
    end: t(`cubicSpline.end.${d.main.end}`),
    parametrization: t(`cubicSpline.parametrization.${s.parametrization}`),
    m0: `(${shortNumber(tangents[0])}, ${shortNumber(tangents[1])})`,
    mn: `(${shortNumber(tangents[2 * last])}, ${shortNumber(tangents[2 * last + 1])})`,
  });
}

// ------------------------------------------------------------ the system's table

/** A number in lecture mode's table: an integer plain, else two decimals. */
function lectureNumber(v) {
  const r = Math.round(v);
  return Math.abs(v - r) < 1e-9 ? String(r) : fmt(v, 2);
}

/** The taller figure, the legend's measure, the refusal notes, and the table of the system. */
export function setup(ui) {
  ui.ctx.slots.figure.classList.add("sl-figure-tall");
  ui.data.view = ui.view; // the legend's labels are measured with its renderer (insets)
  const table = new SystemTable("cubic-system", "cubicSpline.");
  ui.ctx.slots.details.append(table.title, table.wrap);
  let lecture = ui.view.lecture;

  function fill(s, d) {
    const { end, system, tangents, params } = d.main;
    const size = system.diagonal.length;
    // Lecture mode: fewer rows, two decimals, no solved values under the unknowns (the table fits).
    const lecturing = ui.view.lecture;
    const maxShown = lecturing ? MAX_SHOWN_LECTURE : MAX_SHOWN;
    const number = lecturing ? lectureNumber : shortNumber;
    const vector = (flat, i) => `(${number(flat[2 * i])}, ${number(flat[2 * i + 1])})`;
    table.table.dataset.end = end;
    table.show({
      size,
      maxShown,
      number,
      entry: (i, j) => systemEntry(system, size, i, j),
      unknown: (i) => `m${subscript(i)}`,
      solution: (i) => (lecturing ? "" : `= ${vector(tangents, i)}`),
      rhs: (i) => vector(system.rhs, i),
      label: (i) => rowLabel(end, i, size, params.length - 1),
      highlight: (i) => i === 0 || i === size - 1,
      // The corners of the cyclic system (periodic): a_{0,N−1} and a_{N−1,0}.
      marked: (i, j) => end === "periodic" && size > 2 && Math.abs(i - j) === size - 1,
    });
    const shown = Math.min(size, maxShown);
    table.title.textContent = t(`cubicSpline.tableCaption${end === "periodic" ? "Cyclic" : ""}`, {
      size,
      end: t(`cubicSpline.end.${end}`),
      parametrization: t(`cubicSpline.parametrization.${s.parametrization}`),
      hidden: size > shown ? t("cubicSpline.tableHidden", { count: size - shown + 1 }) : "",
    });
  }

  // Lecture mode changes the rows shown: checked before each frame (the shell's toggle redraws).
  ui.view.beforeFrame(() => {
    if (ui.view.lecture !== lecture) {
      lecture = ui.view.lecture;
      fill(ui.state, ui.data);
    }
  });

  return {
    update(s, d) {
      if (d.refusal.message) {
        ui.status(t("status.rejected", { message: d.refusal.message }), "error");
        d.refusal.message = null;
      }
      fill(s, d);
    },
  };
}
