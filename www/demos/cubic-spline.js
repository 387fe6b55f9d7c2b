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
 * - Drags move the point in place (`setPoint` on every spline shown; the core recomputes chord
 *   or centripetal parameters); only the clamped spline under such parameters is made again,
 *   since its tangents follow from the arrows and Δ₀, Δₙ₋₁.
 */
import { field, checkPoints } from "../lib/validate.js";
import { checkbox, choice, pointButtons, readout, group } from "../lib/panel.js";
import { subscript, shortNumber, fmtMachine, pointText } from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { flatPath, arrow } from "../lib/draw.js";
import { HUES, WIDTH, themed } from "../lib/theme.js";
import { legendBand } from "../lib/legend.js";
import {
  SplineDerivativePlots,
  derivativeBandHeight,
  derivativeFacts,
  derivativeParameters,
} from "../lib/spline-derivative-plots.js";
import { pointLabel } from "../lib/handles.js";
import { SystemTable } from "../lib/system-table.js";
import {
  endRowTex,
  endRowsNumericTex,
  interiorRowTex,
  deltasTex,
  numericRowTex,
  showSplineSystem,
} from "../lib/spline-system.js";
import { errorText } from "../lib/core-errors.js";

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
  tangentTips: Object.freeze([Object.freeze([2.5, -0.5]), Object.freeze([11.5, 3])]),
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

/** The points given to the core for condition `end`, flat: P₀ … Pₙ, and P₀ again when periodic. */
function pointsFor(s, end) {
  return flatten(end === "periodic" ? [...s.points, s.points[0]] : s.points);
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

/**
 * The core's spline for end condition `end` (throws its refusal). The parameters are given as
 * their kind, so the core computes them (and again on every `setPoint`); the clamped tangents
 * need Δ₀ and Δₙ₋₁ first (`parameterize`).
 */
function splineFor(sl, s, end) {
  const flat = pointsFor(s, end);
  if (end !== "clamped") return sl.cubicSpline(flat, 2, s.parametrization, end);
  const [m0, mn] = clampedTangents(s, sl.parameterize(flat, 2, s.parametrization));
  return sl.cubicSpline(flat, 2, s.parametrization, end, m0, mn);
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

/** Makes the model's clamped spline (index k) again from the state: its tangents are inputs. */
function remakeClamped(m, s, k) {
  const next = splineFor(m.sl, s, "clamped");
  m.curves[k].free();
  m.curves[k] = next;
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
  /**
   * A dragged point, in place: `setPoint` re-solves (and recomputes chord or centripetal
   * parameters; on the periodic spline P₀ is both ends). The clamped spline under chord or
   * centripetal parameters is made again, since its tangents follow from the arrows and Δ₀, Δₙ₋₁.
   * A refusal (coincident points under chord spacing) keeps that spline and is reported.
   */
  moved(m, i, xy, s) {
    const n = s.points.length - 1;
    if (i === 0 || i === n) {
      const at = i === 0 ? 0 : 2;
      carryTip(s, i, xy[0] - m.ends0[at], xy[1] - m.ends0[at + 1]);
      m.ends0[at] = xy[0];
      m.ends0[at + 1] = xy[1];
    }
    m.curves.forEach((spline, k) => {
      try {
        if (m.ends[k] === "clamped" && s.parametrization !== "uniform") remakeClamped(m, s, k);
        else spline.setPoint(i, xy);
      } catch (err) {
        m.refusal.message = errorText(err);
      }
    });
  },
  inPlace: {
    /** A dragged arrow: only the clamped spline is made again. */
    tangentTips(m, s) {
      const k = m.ends.indexOf("clamped");
      if (k < 0) return;
      try {
        remakeClamped(m, s, k);
      } catch (err) {
        m.refusal.message = errorText(err);
      }
    },
  },
};

const CHANGES = ["points", "end", "compare", "parametrization", "tangentTips"];

/** The chosen spline's teaching data: params, tangents, the system, C″ and C‴ per piece. */
function chosenData(s, d) {
  const spline = d.curves[chosen(s, d)];
  const params = spline.params();
  const ts = derivativeParameters(params);
  return {
    end: d.ends[chosen(s, d)],
    params,
    tangents: spline.tangents(),
    system: spline.system(),
    second: spline.sampleDerivatives(ts, 2),
    third: spline.sampleDerivatives(ts, 3),
    joints: jointContinuity(spline),
    ticks: Array.from(params, (u) => shortNumber(u)),
  };
}

/** The core's continuity check at every inner join: `[{ c, g }, …]` of the Bézier pieces. */
function jointContinuity(spline) {
  const pieces = spline.toBezier();
  const joints = pieces.continuity();
  pieces.free();
  return joints;
}

/** A number for sentences: 3 decimals at most, integers (after rounding) plain. */
const tidy = (v) => shortNumber(Number(fmtMachine(v)));
const pair = ([x, y]) => pointText([tidy(x), tidy(y)]);
/** The same with a decimal point, for data attributes. */
const tidyMachine = (v) => {
  const r = Number(fmtMachine(v));
  return Number.isInteger(r) ? String(r) : fmtMachine(r);
};
const attribute = ([x, y]) => `${tidyMachine(x)},${tidyMachine(y)}`;

/** "C″(t₀) = (0, 0), C″(t₅) = (0, 0); C‴ on the end pieces …; C‴ jumps at t₁, t₂, t₃, t₄". */
function plotNote(s, d) {
  const f = d.facts;
  const n = d.main.params.length - 1;
  const jumps = f.jumps.map((i) => `t${subscript(i)}`).join(", ");
  return t("cubicSpline.plotNote", {
    n: subscript(n),
    secondStart: pair(f.secondStart),
    secondEnd: pair(f.secondEnd),
    thirdFirst: pair(f.thirdFirst),
    thirdLast: pair(f.thirdLast),
    jumps: jumps || t("cubicSpline.noJumps"),
  });
}

export const compute = {
  samples: [CHANGES, (s, d) => d.curves.map((spline) => spline.sampleUniform(CURVE_SAMPLES))],
  main: [CHANGES, chosenData],
  facts: [CHANGES, (s, d) => derivativeFacts(d.main)],
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
  group(
    null,
    checkbox("third", { label: "cubicSpline.control.third" }),
    readout("plots", plotNote, {
      data: (s, d) => ({
        secondStart: attribute(d.facts.secondStart),
        secondEnd: attribute(d.facts.secondEnd),
        thirdFirst: attribute(d.facts.thirdFirst),
        thirdLast: attribute(d.facts.thirdLast),
        jumps: d.facts.jumps.join(","),
      }),
    }),
  ),
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
  const carried = (tip, from, to) => [tip[0] - from[0] + to[0], tip[1] - from[1] + to[1]];
  const [a, b] = before.tangentTips;
  const tips = [
    carried(a, before.points[0], next.points[0]),
    carried(b, lastPoint(before), lastPoint(next)),
  ];
  return { ...next, tangentTips: tips };
}

const showsClamped = (s) => s.compare || s.end === "clamped";
const firstPoint = (s) => s.points[0];
const lastPoint = (s) => s.points[s.points.length - 1];

/** The world window keeps at least this share of the height left by the legend (phones). */
const MIN_WORLD_SHARE = 0.45;

/** The plots' band under the figure: as derivativeBandHeight asks, less on a short canvas. */
function plotBand(height, legend, third) {
  const free = Math.max(0, height - legend);
  return Math.min(derivativeBandHeight(height, third), Math.round(free * (1 - MIN_WORLD_SHARE)));
}

const insets = [0, 0, 0, 0];
export const figure = {
  bounds: (s) =>
    paddedBounds(showsClamped(s) ? [...s.points, ...s.tangentTips] : s.points, ...ROOM),
  insets(width, height, scale, s, d) {
    insets[0] =
      s.compare && d.view ? legendBand(d.view.renderer, LEGEND, width, { draw: false }) : 0;
    insets[2] = plotBand(height, insets[0], s.third);
    return insets;
  },
  handles: {
    field: "points",
    label: (i, s) =>
      i === 0 && s.end === "periodic" && !s.compare
        ? t("cubicSpline.closingLabel", { n: subscript(s.points.length) })
        : pointLabel(i),
    extra: [
      {
        field: "tangentTips",
        index: 0,
        label: "cubicSpline.tipStart",
        when: showsClamped,
        anchor: firstPoint,
      },
      {
        field: "tangentTips",
        index: 1,
        label: "cubicSpline.tipEnd",
        when: showsClamped,
        anchor: lastPoint,
      },
    ],
  },
};

// ------------------------------------------------------------ drawing

const plots = new SplineDerivativePlots();
const plotLabels = { second: "", third: "", x: "", y: "" };

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
    const p0 = s.points[0];
    const pn = s.points[s.points.length - 1];
    const [a, b] = s.tangentTips;
    arrow(r, v.sx(p0[0]), v.sy(p0[1]), v.sx(a[0]), v.sy(a[1]), styles.tangent);
    arrow(r, v.sx(pn[0]), v.sy(pn[1]), v.sx(b[0]), v.sy(b[1]), styles.tangent);
  }
  d.handles.draw(r, v);
  const legend = s.compare ? legendBand(r, LEGEND, r.width) : 0;
  // C″ (and C‴) of the chosen spline per piece, under the figure, sharing the t axis.
  plotLabels.second = t("cubicSpline.plotSecond");
  plotLabels.third = t("cubicSpline.plotThird");
  plotLabels.x = t("cubicSpline.plotX");
  plotLabels.y = t("cubicSpline.plotY");
  plots.draw(r, d.main, s.third, plotLabels, plotBand(r.height, legend, s.third));
}

// ------------------------------------------------------------ formula, label

/** The interior row in general, the Δ's, row 1 with its numbers, the end rows in general and with their numbers. */
export function formula(s, d) {
  const { end, params, system } = d.main;
  const size = system.diagonal.length;
  const lines = [
    interiorRowTex(),
    deltasTex(params, t(`cubicSpline.parametrization.${s.parametrization}`)),
  ];
  if (size > 2) lines.push(`i = 1:\\ ${numericRowTex(system, 1, size)}`);
  const n = params.length - 1;
  lines.push(endRowTex(end, "start", n), endRowTex(end, "end", n));
  lines.push(endRowsNumericTex(system, size));
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
    m0: pointText([shortNumber(tangents[0]), shortNumber(tangents[1])]),
    mn: pointText([shortNumber(tangents[2 * last]), shortNumber(tangents[2 * last + 1])]),
  });
}

// ------------------------------------------------------------ the system's table

/** The taller figure, the legend's measure, the refusal notes, and the table of the system. */
export function setup(ui) {
  ui.ctx.slots.figure.classList.add("sl-figure-tall");
  ui.data.view = ui.view; // the legend's labels are measured with its renderer (insets)
  const table = new SystemTable("cubic-system", {
    headers: {
      label: t("cubicSpline.systemEquation"),
      unknown: t("cubicSpline.systemUnknown"),
      rhs: t("cubicSpline.systemRhs"),
    },
    wrapLabels: true,
  });
  ui.ctx.slots.details.append(...table.nodes);
  let lecture = ui.view.lecture;
  const fill = (s, d) =>
    showSplineSystem(table, d.main, {
      lecture: ui.view.lecture,
      parametrization: t(`cubicSpline.parametrization.${s.parametrization}`),
    });

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
