/**
 * Demo (syllabus §4): exact circles, arcs and ellipses as NURBS,
 * C(u) = Σ N_{i,2}(u) w_i P_i / Σ N_{i,2}(u) w_i. The core builds them (`circle`, `circularArc`,
 * `ellipse`, `ellipseArc`): degree 2, the sweep cut into pieces of at most 90°, middle weights
 * cos(Δ/2). The figure shows the control polygon with every weight, the pieces' joints on the
 * curve, and the demo measures how round the result is: the largest | |C(u) − c| − r | over
 * 2000 samples, which reads 0 or a few 1e-16 (rounding).
 *
 * Dragging the centre translates the control points in place (`setControlPoint`); the sliders
 * build a new curve from the core. The measurement is the only number the demo computes itself.
 */
import { checkNumber, field } from "../lib/validate.js";
import { slider, checkbox, readout, actions, group, shownWhen } from "../lib/panel.js";
import {
  fmt,
  subscript,
  simpleFraction,
  fractionText,
  fractionTex,
  fmtTex,
  pointText,
  DECIMALS,
  fmtMachine,
  listTex,
  listText,
  localeDecimal,
  texDecimal,
  texListSeparator,
} from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatPath } from "../lib/draw.js";
import { el, setText } from "../lib/controls.js";
import { titledTable } from "../lib/table.js";

export const id = "nurbs-circle";
export const strings = "nurbsCircle";
export const section = 4;

/** Ranges of the sliders (lengths in model units, angles in degrees). */
export const LENGTH_MIN = 0.1;
export const LENGTH_MAX = 10;
const LENGTH_STEP = 0.01;
export const ANGLE_MAX = 360;
const ANGLE_STEP = 1;
/** Where the radius label sits along the radius, from the centre (fraction of its length). */
const RADIUS_LABEL_AT = 0.6;
/** Samples of the curve: drawn, and measured against the exact circle (ellipse). */
const SAMPLES = 2000;
/** Weights this close to √2/2 or 1 are written as such. */
const EXACT_WEIGHT = 1e-12;
const RADIANS = Math.PI / 180;
/** Errors below this are written in exponent form. */
const SMALL = 1e-3;
/** The fitted window is this many radii wide on each side (labels beside the control points). */
const LABEL_ROOM = 1.6;
/** Radius of the rings that mark the pieces' joints on the curve, CSS px. */
const JOINT_RING_PX = 8;
/** Gap between a control point and its weight label, and the label's extra drop (CSS px). */
const WEIGHT_LABEL_GAP_PX = 10;
const WEIGHT_LABEL_DROP_PX = 7;

/** The full circle of radius 2 about the origin: the 9-point NURBS of the syllabus. */
export const defaultState = Object.freeze({
  points: Object.freeze([Object.freeze([0, 0])]),
  radius: 2,
  start: 0,
  sweep: 360,
  ellipse: false,
  rx: 3,
  ry: 2,
  rotation: 0,
});

/** A length in [LENGTH_MIN, LENGTH_MAX], refused first when it is not > 0. */
function length(state, name) {
  checkNumber(state, name);
  if (state[name] <= 0)
    throw new Error(t("nurbsCircle.notPositive", { field: name, value: state[name] }));
  checkNumber(state, name, { min: LENGTH_MIN, max: LENGTH_MAX });
}
const angle = field.number({ min: -ANGLE_MAX, max: ANGLE_MAX });

export const fields = {
  points: field.points({ min: 1, max: 1 }),
  radius: length,
  rx: length,
  ry: length,
  start: angle,
  sweep: angle,
  ellipse: field.boolean(),
  rotation: angle,
};

/** An arc needs a sweep. */
export function check(s) {
  if (s.sweep === 0) throw new Error(t("nurbsCircle.zeroSweep"));
}

/** True when the state asks for the whole closed curve starting at angle 0. */
function isFull(s) {
  return s.start === 0 && s.sweep === ANGLE_MAX;
}

/** The NURBS of a state, from the core's constructors (throws their message on bad input). */
function buildCurve(sl, s) {
  const [cx, cy] = s.points[0];
  const start = s.start * RADIANS;
  const sweep = s.sweep * RADIANS;
  if (!s.ellipse)
    return isFull(s) ? sl.circle(cx, cy, s.radius) : sl.circularArc(cx, cy, s.radius, start, sweep);
  const rotation = s.rotation * RADIANS;
  if (isFull(s)) return sl.ellipse(cx, cy, s.rx, s.ry, rotation);
  const c = Math.cos(rotation);
  const sin = Math.sin(rotation);
  const axisX = new Float64Array([s.rx * c, s.rx * sin]);
  const axisY = new Float64Array([-s.ry * sin, s.ry * c]);
  return sl.ellipseArc(new Float64Array([cx, cy]), axisX, axisY, start, sweep);
}

/** The control points of the unit circle's NURBS, counter-clockwise from (1, 0). */
const UNIT_POINTS = [
  [1, 0],
  [1, 1],
  [0, 1],
  [-1, 1],
  [-1, 0],
  [-1, -1],
  [0, -1],
  [1, -1],
  [1, 0],
];

/** "1", "√2/2" or three decimals (`tex`: TeX). */
function weightText(w, tex = false) {
  if (Math.abs(w - 1) <= EXACT_WEIGHT) return "1";
  if (Math.abs(w - Math.SQRT1_2) <= EXACT_WEIGHT) return tex ? "\\tfrac{\\sqrt2}{2}" : "√2/2";
  return tex ? fmtTex(w) : fmt(w);
}

/** A knot as a fraction when it is one (1/4), else three decimals (`tex`: TeX). */
function knotText(u, tex = false) {
  const f = simpleFraction(u);
  if (!f) return tex ? fmtTex(u) : fmt(u);
  return tex ? fractionTex(f) : fractionText(f);
}

/** `knotText` with a decimal point, for the readout's data attribute. */
function knotMachine(u) {
  const f = simpleFraction(u);
  return f ? fractionText(f) : fmtMachine(u);
}

/** A measured error to print precision: "0", "3.3e-16" (TeX: 3.3 × 10^{−16}), or 3 decimals. */
function errorText(x, tex = false) {
  if (x === 0) return "0";
  if (x >= SMALL) return tex ? fmtTex(x) : fmt(x);
  if (!tex) return localeDecimal(x.toExponential(1));
  const [m, e] = x.toExponential(1).split("e");
  return `${texDecimal(m)} \\times 10^{${Number(e)}}`;
}

/**
 * The curve, and what stays fixed for it: the control points it was built with and the centre
 * they were built about (a dragged centre translates them), weights, knots, pieces, the
 * parameters of the joints (distinct knots) and the weight labels ("P₁: w = √2/2").
 */
export const derive = {
  from: ["radius", "start", "sweep", "ellipse", "rx", "ry", "rotation"],
  build(s, sl) {
    const curve = buildCurve(sl, s);
    const base = curve.controlPoints();
    const weights = curve.weights();
    const knots = curve.knots();
    const distinct = [];
    for (const u of knots)
      if (distinct.length === 0 || u !== distinct[distinct.length - 1]) distinct.push(u);
    const last = base.length - 2;
    const closed =
      Math.abs(base[0] - base[last]) <= EXACT_WEIGHT &&
      Math.abs(base[1] - base[last + 1]) <= EXACT_WEIGHT;
    const weightLabels = Array.from(weights, (w, i) => {
      const name =
        i === 0 && closed ? `P₀ = P${subscript(weights.length - 1)}` : `P${subscript(i)}`;
      return `${name}: w = ${weightText(w)}`;
    });
    return {
      curve,
      base,
      builtAt: [...s.points[0]],
      weights,
      knots,
      pieces: curve.spans().length,
      jointParams: new Float64Array(distinct),
      weightLabels,
    };
  },
  /** A translation: every control point moves by the centre's displacement, in place. */
  moved(m, i, xy) {
    const dx = xy[0] - m.builtAt[0];
    const dy = xy[1] - m.builtAt[1];
    for (let k = 0; k < m.base.length / 2; k++) {
      scratch[0] = m.base[2 * k] + dx;
      scratch[1] = m.base[2 * k + 1] + dy;
      m.curve.setControlPoint(k, scratch);
    }
  },
};
const scratch = new Float64Array(2);

/**
 * The measurement: circle, max | |C(u) − c| − r |; ellipse, max | (x′/rx)² + (y′/ry)² − 1 |
 * in the ellipse's own axes (x′, y′), over the samples.
 */
function measure(s, samples) {
  const [cx, cy] = s.points[0];
  let worst = 0;
  if (!s.ellipse) {
    for (let k = 0; k < SAMPLES; k++) {
      worst = Math.max(
        worst,
        Math.abs(Math.hypot(samples[2 * k] - cx, samples[2 * k + 1] - cy) - s.radius),
      );
    }
    return worst;
  }
  const c = Math.cos(s.rotation * RADIANS);
  const sin = Math.sin(s.rotation * RADIANS);
  for (let k = 0; k < SAMPLES; k++) {
    const dx = samples[2 * k] - cx;
    const dy = samples[2 * k + 1] - cy;
    const x = (dx * c + dy * sin) / s.rx;
    const y = (-dx * sin + dy * c) / s.ry;
    worst = Math.max(worst, Math.abs(x * x + y * y - 1));
  }
  return worst;
}

/** "r = 2.000" or "rx = 3.000, ry = 2.000", beside the radius. */
function radiusLabel(s) {
  if (s.ellipse) return t("nurbsCircle.axesLabel", { rx: fmt(s.rx), ry: fmt(s.ry) });
  return t("nurbsCircle.radiusLabel", { r: fmt(s.radius) });
}

const ALL = ["points", ...derive.from];
/** What the core returns after any change: samples, control points, the joints; the measurement. */
export const compute = {
  samples: [ALL, (s, d) => d.curve.sampleUniform(SAMPLES)],
  controls: [ALL, (s, d) => d.curve.controlPoints()],
  joints: [ALL, (s, d) => d.curve.sample(d.jointParams)],
  error: [ALL, (s, d) => measure(s, d.samples)],
  radiusLabel: [["radius", "ellipse", "rx", "ry"], radiusLabel],
};

const lengthSlider = (name) =>
  slider(name, {
    label: `nurbsCircle.${name}`,
    min: LENGTH_MIN,
    max: LENGTH_MAX,
    step: LENGTH_STEP,
    error: "nurbsCircle.badLength",
  });
const angleSlider = (name, refuse) =>
  slider(name, {
    label: `nurbsCircle.${name}`,
    min: -ANGLE_MAX,
    max: ANGLE_MAX,
    step: ANGLE_STEP,
    format: (v) => localeDecimal(String(Number(v.toFixed(2)))),
    error: "nurbsCircle.badAngle",
    refuse,
  });
/** A zero sweep is refused before it reaches the core (the last good curve stays). */
const refuseZero = (v) =>
  v === 0 ? t("nurbsCircle.refused", { message: t("nurbsCircle.zeroSweep") }) : null;
const counted = (s, d) => d.controls.length / 2;
/** The readout of the measurement: "nurbsCircle.errorCircle" or "…errorEllipse" (and its `Note`). */
const errorKey = (s) => (s.ellipse ? "nurbsCircle.errorEllipse" : "nurbsCircle.errorCircle");

export const controls = [
  group(null, checkbox("ellipse", { label: "nurbsCircle.ellipseMode" })),
  shownWhen((s) => !s.ellipse, group("nurbsCircle.circleLegend", lengthSlider("radius"))),
  shownWhen(
    (s) => s.ellipse,
    group(
      "nurbsCircle.ellipseLegend",
      lengthSlider("rx"),
      lengthSlider("ry"),
      angleSlider("rotation"),
    ),
  ),
  group(
    "nurbsCircle.arcLegend",
    angleSlider("start"),
    angleSlider("sweep", refuseZero),
    actions([
      {
        name: "full",
        label: "nurbsCircle.full",
        title: "nurbsCircle.full.title",
        run: (ui) => ui.replace({ ...ui.state, start: 0, sweep: ANGLE_MAX }),
      },
    ]),
  ),
  group(
    "nurbsCircle.resultLegend",
    readout("error", (s, d) => t(errorKey(s), { error: errorText(d.error) }), {
      kind: "readout",
      live: true,
      data: (s, d) => ({ error: String(d.error) }),
    }),
    readout(null, (s) => t(`${errorKey(s)}Note`, { samples: SAMPLES })),
    readout("count", (s, d) => t("nurbsCircle.count", { count: counted(s, d), pieces: d.pieces }), {
      data: (s, d) => ({ points: String(counted(s, d)), pieces: String(d.pieces) }),
    }),
    readout(
      "knots",
      (s, d) =>
        t("nurbsCircle.knots", { knots: listText(Array.from(d.knots, (u) => knotText(u))) }),
      {
        data: (s, d) => ({ knots: Array.from(d.knots, knotMachine).join(" ") }),
      },
    ),
  ),
];

export const figure = {
  /**
   * The whole circle or ellipse's box (arcs lie inside it), wider by LABEL_ROOM so the weight
   * labels beside the corner control points stay in the window.
   */
  bounds(s) {
    const [cx, cy] = s.points[0];
    const r = s.ellipse ? Math.max(s.rx, s.ry) : s.radius;
    return [cx - r * LABEL_ROOM, cy - r, cx + r * LABEL_ROOM, cy + r];
  },
  handles: { field: "points", label: () => t("nurbsCircle.centreLabel") },
};

/**
 * The weight labels of the control points, outward from the centre (a repeated end point once);
 * where there is no room beside a point (a narrow canvas), above or below it instead (below on
 * the x axis, clear of the radius label) rather than pushed back over it by the frame's edge.
 */
function drawWeights(r, v, s, d) {
  const theme = r.theme;
  const controls = d.controls;
  const count = controls.length / 2;
  const cx = v.sx(s.points[0][0]);
  const cy = v.sy(s.points[0][1]);
  const gap = WEIGHT_LABEL_GAP_PX * r.scale;
  const drop = WEIGHT_LABEL_DROP_PX * r.scale;
  for (let i = 0; i < count; i++) {
    const x = v.sx(controls[2 * i]);
    const y = v.sy(controls[2 * i + 1]);
    const repeat =
      i === count - 1 &&
      Math.abs(x - v.sx(controls[0])) < 0.5 &&
      Math.abs(y - v.sy(controls[1])) < 0.5;
    r.point(x, y, theme.basisPoint[i % theme.basisPoint.length]);
    if (repeat) continue;
    const length = Math.hypot(x - cx, y - cy) || 1;
    const dx = (x - cx) / length;
    const dy = (y - cy) / length;
    let align = dx > 0.35 ? "left" : dx < -0.35 ? "right" : "center";
    let tx = x + dx * gap;
    let ty = y + dy * gap + dy * drop;
    if (align !== "center") {
      const width = r.measure(d.weightLabels[i], theme.labelSmall);
      if (align === "left" ? tx + width > v.width : tx - width < 0) {
        align = "center";
        tx = x;
        ty = y + (dy < 0 ? -1 : 1) * (gap + drop);
      }
    }
    r.text(d.weightLabels[i], tx, ty, theme.labelSmall, align, "middle");
  }
}

/** The control polygon, the radius to the curve's start, the curve, the joints, the weights. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const { controls, samples } = d;
  flatPath(r, v, controls);
  r.paint(theme.polygon);

  const cx = v.sx(s.points[0][0]);
  const cy = v.sy(s.points[0][1]);
  const ex = v.sx(samples[0]);
  const ey = v.sy(samples[1]);
  r.beginPath();
  r.moveTo(cx, cy);
  r.lineTo(ex, ey);
  r.paint(theme.helper);
  // Its label 60 % of the way out: clear of the centre's own label on a small circle too.
  const lx = cx + RADIUS_LABEL_AT * (ex - cx);
  const ly = cy + RADIUS_LABEL_AT * (ey - cy) - 6 * r.scale;
  r.text(d.radiusLabel, lx, ly, theme.labelSmall, "center", "bottom");

  flatPath(r, v, samples, 0, SAMPLES);
  r.paint(theme.curve);

  // The pieces' joints (the curve at each distinct knot), as rings around the curve.
  r.beginPath();
  for (let j = 0; j < d.jointParams.length; j++) {
    r.circle(v.sx(d.joints[2 * j]), v.sy(d.joints[2 * j + 1]), JOINT_RING_PX * r.scale);
  }
  r.paint(theme.levelStroke[1]);

  drawWeights(r, v, s, d);
  d.handles.draw(r, v);
}

/** The NURBS, the textbook circle, this curve's pieces, weights and knots, the measurement. */
export function formula(s, d) {
  const { pieces } = d;
  const delta = Math.abs(s.sweep) / pieces;
  const middle = Math.cos((delta / 2) * RADIANS);
  const samples = `(${SAMPLES} \\text{ ${t("nurbsCircle.formula.samples")}})`;
  const error = errorText(d.error, true);
  // The unit circle's nine points, weights and knots (";" between entries with a decimal comma).
  const comma = texListSeparator("");
  const unit = UNIT_POINTS.map(([x, y]) => `(${x}${comma}${y})`).join(texListSeparator(" "));
  const r2 = "\\tfrac{\\sqrt2}{2}";
  const weights = [1, r2, 1, r2, 1, r2, 1, r2, 1].join(texListSeparator(" "));
  const knots = ["0", "0", "0", "\\tfrac14", "\\tfrac14", "\\tfrac12", "\\tfrac12", "\\tfrac34"];
  const knotList = [...knots, "\\tfrac34", "1", "1", "1"].join(comma);
  return [
    `C(u) = \\frac{\\sum_{i} N_{i,2}(u)\\,w_i\\,P_i}{\\sum_{i} N_{i,2}(u)\\,w_i}`,
    `\\text{${t("nurbsCircle.formula.circle")}: } P_i = c + r\\,\\{${unit}\\}`,
    `w_i = ${weights},\\qquad U = \\{${knotList}\\}`,
    `\\text{${t("nurbsCircle.formula.here")}: } ${pieces} \\text{ ${tp("nurbsCircle.formula.pieces", pieces)} } ` +
      `\\Delta = \\tfrac{{${fmtTex(Math.abs(s.sweep), 0)}}^\\circ}{${pieces}} = {${fmtTex(delta, 2)}}^\\circ \\le 90^\\circ,\\ ` +
      `\\text{${t("nurbsCircle.formula.middleWeights")} } \\cos\\tfrac{\\Delta}{2} = ${weightText(middle, true)},\\ ` +
      `U = \\{${listTex(
        Array.from(d.knots, (u) => knotText(u, true)),
        DECIMALS,
        " ",
      )}\\}`,
    s.ellipse
      ? `\\max_u \\left| \\left(\\tfrac{x'(u)}{r_x}\\right)^2 + \\left(\\tfrac{y'(u)}{r_y}\\right)^2 - 1 \\right| = ` +
        `${error}\\quad ${samples}`
      : `\\max_u \\big|\\, \\lVert C(u) - c \\rVert - r \\,\\big| = ${error}\\quad ${samples}`,
  ];
}

/** "NURBS circle of radius 2.00 about (0.00, 0.00), the whole curve: degree 2, 9 control points …". */
export function label(s, d) {
  const [x, y] = s.points[0];
  const shape = s.ellipse
    ? t("nurbsCircle.ariaEllipse", {
        rx: fmt(s.rx, 2),
        ry: fmt(s.ry, 2),
        rotation: fmt(s.rotation, 1),
      })
    : t("nurbsCircle.ariaCircle", { r: fmt(s.radius, 2) });
  const arc = isFull(s)
    ? t("nurbsCircle.ariaFull")
    : t("nurbsCircle.ariaArc", { start: fmt(s.start, 1), sweep: fmt(s.sweep, 1) });
  return t("nurbsCircle.aria", {
    shape,
    x: fmt(x, 2),
    y: fmt(y, 2),
    arc,
    count: counted(s, d),
    weights: listText(Array.from(d.weights, (w) => weightText(w))),
    knots: listText(Array.from(d.knots, (u) => knotText(u))),
    pieces: d.pieces,
    error: errorText(d.error),
  });
}

/** The table of the control points and their weights. */
export function setup(ui) {
  const { title, table, wrap } = titledTable("nurbs-circle");
  ui.ctx.slots.details.append(title, wrap);
  const columns = ["i", t("nurbsCircle.column.point"), t("nurbsCircle.column.weight")];
  const head = el(
    "thead",
    {},
    el(
      "tr",
      {},
      columns.map((text) => el("th", { scope: "col", text })),
    ),
  );
  let cells = [];

  function build(count) {
    cells = [];
    const rows = [];
    for (let i = 0; i < count; i++) {
      const point = el("td");
      const weight = el("td", { dataset: { column: "weight" } });
      cells.push([point, weight]);
      const name = el("th", { scope: "row", text: `P${subscript(i)}` });
      rows.push(el("tr", { dataset: { index: String(i) } }, name, point, weight));
    }
    table.replaceChildren(head, el("tbody", {}, rows));
  }

  return {
    update(s, d) {
      const count = counted(s, d);
      setText(title, t("nurbsCircle.tableCaption", { count }));
      if (cells.length !== count) build(count);
      for (let i = 0; i < count; i++) {
        setText(cells[i][0], pointText([d.controls[2 * i], d.controls[2 * i + 1]]));
        setText(cells[i][1], weightText(d.weights[i]));
      }
    },
  };
}
