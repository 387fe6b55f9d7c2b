/**
 * Demo (syllabus §4): conic sections as rational quadratic Bézier curves. Three draggable
 * points and the middle weight w₁ (w₀ = w₂ = 1): the core names the conic (`conicKind`) by the
 * shape factor k = w₁² / (w₀w₂): an ellipse arc below 1, a parabola at 1, a hyperbola above.
 * With an isosceles control triangle and w₁ = sin θ (θ half the angle at P₁) the arc is
 * circular: the demo then draws the whole circle (`circle` from the core) and measures every
 * sample's distance from its centre. "Make circular" asks the core for that weight
 * (`circularArcBezier`). The triangle's angle and the circle's centre are read off the three
 * points (display and measurement, not a curve algorithm).
 */
import { field } from "../lib/validate.js";
import { slider, readout, actions, group } from "../lib/panel.js";
import { fmt, fmtTex, localeDecimal, pointTex, pointText } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { drawLegend } from "../lib/legend.js";
import { scaledInsets } from "../lib/view.js";
import { el } from "../lib/controls.js";
import { titledTable } from "../lib/table.js";
import { errorText } from "../lib/core-errors.js";

export const id = "conics";
export const strings = "conics";
export const section = 4;

/** Range of w₁ (a logarithmic slider). */
export const W1_MIN = 0.05;
export const W1_MAX = 5;
/** Slider step in log10 units. */
const W1_LOG_STEP = 0.002;
/** Points sampled along the curve (one `sampleUniform` per change). */
const CURVE_SAMPLES = 256;
/** Points sampled along the reference circle. */
const CIRCLE_SAMPLES = 181;
/** Relative tolerance for |P₀P₁| = |P₁P₂| and for w₁ = sin θ (a circle is exact or it is not). */
const CIRCLE_TOLERANCE = 1e-9;
/** Below this cos θ the triangle is flat (the circle's centre is at infinity). */
const FLAT_COS = 1e-9;
/** Degrees per radian, for the angle readouts. */
const DEGREES = 180 / Math.PI;
/** Radius errors below this are written in exponent form. */
const SMALL = 1e-3;
/** Height of the band at the top kept for the conic's name and the key, CSS px at text scale 1. */
const LEGEND_PX = 52;
/** The key under the conic's name: the parabola drawn for comparison. */
const KEY = Object.freeze([
  Object.freeze({ style: (theme) => theme.compareCurve[2], label: "conics.legendParabola" }),
]);
const KINDS = Object.freeze(["ellipse", "parabola", "hyperbola"]);

/**
 * An isosceles triangle (|P₀P₁| = |P₁P₂| = √13) with w₁ = 1/2: an ellipse arc, a little flatter
 * than the circle it becomes at w₁ = sin θ = 2/√13 ≈ 0.555.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 0],
      [2, 3],
      [4, 0],
    ].map(Object.freeze),
  ),
  w1: 0.5,
});

export const fields = {
  points: field.points({ min: 3, max: 3 }),
  w1: field.number({ min: W1_MIN, max: W1_MAX }),
};

/** The weights (1, w₁, 1). */
const weightsOf = (w1) => new Float64Array([1, w1, 1]);

/** The conic and, for comparison, the parabola (w₁ = 1) of the same points; w₁ is set in place. */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({
    curve: new sl.BezierCurve(flatten(s.points), 2, weightsOf(s.w1)),
    parabola: new sl.BezierCurve(flatten(s.points), 2),
  }),
  moved(m, i, xy) {
    m.curve.setControlPoint(i, xy);
    m.parabola.setControlPoint(i, xy);
  },
  inPlace: { w1: (m, s) => m.curve.setWeight(1, s.w1) },
};

/**
 * The control triangle's measures: legs |P₁P₀|, |P₁P₂|, half the angle θ at P₁, and when the
 * legs are equal the circle tangent to both legs at P₀ and P₂ (centre on the bisector at
 * |P₁P₀|/cos θ from P₁, radius |P₁P₀|·tan θ).
 */
function triangleOf(points) {
  const [[x0, y0], [x1, y1], [x2, y2]] = points;
  const a = Math.hypot(x0 - x1, y0 - y1);
  const b = Math.hypot(x2 - x1, y2 - y1);
  const result = { a, b, theta: NaN, sin: NaN, isosceles: false, centre: null, radius: NaN };
  if (a === 0 || b === 0) return result;
  const cos = ((x0 - x1) * (x2 - x1) + (y0 - y1) * (y2 - y1)) / (a * b);
  result.theta = Math.acos(Math.min(1, Math.max(-1, cos))) / 2;
  result.sin = Math.sin(result.theta);
  result.isosceles = Math.abs(a - b) <= CIRCLE_TOLERANCE * Math.max(a, b);
  const cosTheta = Math.cos(result.theta);
  if (result.isosceles && cosTheta > FLAT_COS && result.sin > FLAT_COS) {
    const mx = (x0 + x2) / 2 - x1;
    const my = (y0 + y2) / 2 - y1;
    const m = Math.hypot(mx, my);
    const d = a / cosTheta;
    result.centre = [x1 + (mx / m) * d, y1 + (my / m) * d];
    result.radius = a * Math.tan(result.theta);
  }
  return result;
}

/**
 * The conic's kind from the core, the triangle, whether the arc is circular, and for an
 * isosceles triangle the largest | |P(t) − O| − R | over the samples; the whole circle's
 * samples (from the core's `circle`) when it is circular.
 */
function conicOf(s, d) {
  const samples = d.samples;
  const triangle = triangleOf(s.points);
  const circular = !!triangle.centre && Math.abs(s.w1 - triangle.sin) <= CIRCLE_TOLERANCE;
  let radiusError = NaN;
  let circleSamples = null;
  if (triangle.centre) {
    const [cx, cy] = triangle.centre;
    radiusError = 0;
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const distance = Math.hypot(samples[2 * k] - cx, samples[2 * k + 1] - cy);
      radiusError = Math.max(radiusError, Math.abs(distance - triangle.radius));
    }
    if (circular) {
      const circle = d.sl.circle(cx, cy, triangle.radius);
      circleSamples = circle.sampleUniform(CIRCLE_SAMPLES);
      circle.free();
    }
  }
  const kind = d.sl.conicKind(1, s.w1, 1);
  return { kind, shoulder: d.curve.evaluate(0.5), triangle, circular, radiusError, circleSamples };
}

export const compute = {
  samples: [["points", "w1"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  parabolaSamples: [["points"], (s, d) => d.parabola.sampleUniform(CURVE_SAMPLES)],
  conic: [["points", "w1"], conicOf],
};

/** A small number to print precision: "0", "3.3e-16" or 3 decimals. */
function smallText(x) {
  return x === 0 ? "0" : x < SMALL ? localeDecimal(x.toExponential(1)) : fmt(x);
}
const relationOf = (kind) => (kind === "ellipse" ? "<" : kind === "parabola" ? "=" : ">");

/** "w₁ = 0.500; shape factor k = w₁²/(w₀w₂) = 0.250 < 1". */
const shapeText = (w1, kind) =>
  t("conics.shape", { w: fmt(w1), k: fmt(w1 * w1), relation: relationOf(kind) });

/**
 * Makes the arc circular: P₂ slides along the ray P₁P₂ until |P₁P₂| = |P₁P₀| (the triangle
 * becomes isosceles), then the core's `circularArcBezier` gives w₁ = sin θ.
 */
function makeCircular(ui) {
  const [p0, p1, p2] = ui.state.points;
  const a = Math.hypot(p0[0] - p1[0], p0[1] - p1[1]);
  const b = Math.hypot(p2[0] - p1[0], p2[1] - p1[1]);
  const q =
    b > 0 && a !== b
      ? [p1[0] + ((p2[0] - p1[0]) * a) / b, p1[1] + ((p2[1] - p1[1]) * a) / b]
      : [p2[0], p2[1]];
  let w;
  try {
    const arc = ui.sl.circularArcBezier(flatten([p0, p1, q]));
    w = arc.weights()[1];
    arc.free();
  } catch (err) {
    ui.status(t("conics.notCircular", { message: errorText(err) }), "error");
    return;
  }
  if (w < W1_MIN) {
    ui.status(t("conics.tooFlat", { w: fmt(w), min: localeDecimal(String(W1_MIN)) }), "error");
    return;
  }
  ui.replace({ ...ui.state, points: [p0, p1, q], w1: w });
  ui.status(t("conics.madeCircular", { w: fmt(w) }), "info");
}

/** "|P₀P₁| = 3.606, |P₁P₂| = 3.606 (isosceles); angle at P₁ = 67.38°, sin θ = 0.555". */
function triangleText(tri) {
  if (!Number.isFinite(tri.theta)) return t("conics.triangleDegenerate");
  const angle = fmt(2 * tri.theta * DEGREES, 2);
  const key = tri.isosceles ? "conics.triangleIsosceles" : "conics.triangle";
  return t(key, { a: fmt(tri.a), b: fmt(tri.b), angle, sin: fmt(tri.sin) });
}

/** Whether the arc is circular, with the measured error, or what it lacks. */
function circleText({ circular, triangle: tri, radiusError }) {
  if (circular) return t("conics.circleYes", { error: smallText(radiusError), r: fmt(tri.radius) });
  if (tri.centre) return t("conics.circleNo", { sin: fmt(tri.sin), error: smallText(radiusError) });
  return t("conics.circleNeedsIsosceles");
}

export const controls = [
  group(
    null,
    slider("w1", {
      label: "conics.w1",
      min: W1_MIN,
      max: W1_MAX,
      step: W1_LOG_STEP,
      log: true,
      error: "conics.badWeight",
    }),
    readout("kind", (s, d) => kindLabel(d.conic, "conics.readoutCircle"), {
      kind: "readout",
      live: true,
      data: (s, d) => ({ kind: d.conic.kind, circle: String(d.conic.circular) }),
    }),
    readout("shape", (s, d) => shapeText(s.w1, d.conic.kind), {
      data: (s) => ({ factor: String(s.w1 * s.w1) }),
    }),
  ),
  group(
    "conics.circleLegend",
    readout("triangle", (s, d) => triangleText(d.conic.triangle), {
      data: (s, d) => ({ sin: String(d.conic.triangle.sin) }),
    }),
    readout("circle", (s, d) => circleText(d.conic), {
      data: (s, d) => ({
        radiusError: Number.isNaN(d.conic.radiusError) ? "" : String(d.conic.radiusError),
        circle: String(d.conic.circular),
      }),
    }),
    actions([
      {
        name: "make-circular",
        label: "conics.makeCircular",
        title: "conics.makeCircular.title",
        run: makeCircular,
      },
    ]),
  ),
];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  insets: scaledInsets(LEGEND_PX, 0, 0, 0),
  handles: { field: "points" },
};

/** The conic's name, with "circle!" (`circleKey`) when the arc is circular. */
function kindLabel(conic, circleKey) {
  const name = t(`conics.kind.${conic.kind}`);
  return conic.circular ? t(circleKey, { kind: name }) : name;
}

/**
 * The whole circle (when circular), the control triangle with the chord P₀P₂ and the line from
 * its midpoint M to P₁ (the shoulder P(1/2) lies on it), the parabola, the conic, the shoulder;
 * the conic's name and the key in the band at the top.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  const { triangle, circleSamples, shoulder } = d.conic;
  if (circleSamples) {
    flatPath(r, v, circleSamples, 0, CIRCLE_SAMPLES);
    r.paint(theme.helper);
    const ox = v.sx(triangle.centre[0]);
    const oy = v.sy(triangle.centre[1]);
    r.point(ox, oy, theme.comparePoint[0]);
    r.text(t("conics.centre"), ox + 8 * r.scale, oy, theme.labelSmall, "left", "middle");
  }

  pointsPath(r, v, pts);
  r.paint(theme.polygon);
  const mx = v.sx((pts[0][0] + pts[2][0]) / 2);
  const my = v.sy((pts[0][1] + pts[2][1]) / 2);
  r.beginPath();
  r.moveTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
  r.lineTo(v.sx(pts[2][0]), v.sy(pts[2][1]));
  r.moveTo(mx, my);
  r.lineTo(v.sx(pts[1][0]), v.sy(pts[1][1]));
  r.paint(theme.helper);
  r.point(mx, my, theme.comparePoint[2]);
  r.text(t("conics.midpoint"), mx, my + 8 * r.scale, theme.labelSmall, "center", "top");

  flatPath(r, v, d.parabolaSamples, 0, CURVE_SAMPLES);
  r.paint(theme.compareCurve[2]);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);

  d.handles.draw(r, v);
  const sx = v.sx(shoulder[0]);
  const sy = v.sy(shoulder[1]);
  r.point(sx, sy, theme.pointOnCurve);
  r.text(t("conics.shoulder"), sx + 9 * r.scale, sy, theme.labelPoint, "left", "bottom");

  r.text(
    kindLabel(d.conic, "conics.figureCircle"),
    12 * r.scale,
    18 * r.scale,
    theme.labelBold,
    "left",
    "middle",
  );
  drawLegend(r, KEY, 12, 42);
}

/** The rational quadratic, the shape factor and its verdict, the circle condition, the shoulder. */
export function formula(s, d) {
  const { kind, triangle: tri, circular, shoulder } = d.conic;
  const w1 = fmtTex(s.w1);
  const text = (key) => `\\text{${t(key)}}`;
  const legs = `|P_0P_1| = ${fmtTex(tri.a)},\\ |P_1P_2| = ${fmtTex(tri.b)}`;
  const circleNumbers = Number.isFinite(tri.theta)
    ? `${legs},\\ \\theta = {${fmtTex(tri.theta * DEGREES, 2)}}^\\circ,\\ \\sin\\theta = ${fmtTex(tri.sin)}\\quad ` +
      (circular ? `\\Rightarrow\\ ${text("conics.formula.circle")}` : `(w_1 = ${w1})`)
    : legs;
  return [
    `P(t) = \\frac{(1-t)^2\\,w_0P_0 + 2t(1-t)\\,w_1P_1 + t^2\\,w_2P_2}{(1-t)^2\\,w_0 + 2t(1-t)\\,w_1 + t^2\\,w_2},` +
      `\\qquad w_0 = w_2 = 1,\\ w_1 = ${w1}`,
    `k = \\frac{w_1^2}{w_0\\,w_2} = ${fmtTex(s.w1 * s.w1)} ${relationOf(kind)} 1 \\;\\Rightarrow\\; ` +
      text(`conics.kind.${kind}`) +
      `\\qquad (k < 1 \\text{ ${t("conics.kind.ellipse")}},\\ k = 1 \\text{ ${t("conics.kind.parabola")}},\\ ` +
      `k > 1 \\text{ ${t("conics.kind.hyperbola")}})`,
    `${text("conics.formula.circularArc")} \\iff |P_0P_1| = |P_1P_2| \\text{ ${t("conics.formula.and")} } ` +
      `w_1 = \\sin\\theta,\\quad \\theta = \\tfrac12\\angle P_0P_1P_2`,
    circleNumbers,
    `P(\\tfrac12) = \\frac{M + w_1P_1}{1 + w_1} = ${pointTex([shoulder[0], shoulder[1]])},\\quad ` +
      `M = \\tfrac12(P_0 + P_2)`,
  ];
}

/** "Rational quadratic Bézier curve with P₀ = …, weights 1, 0.500, 1: an arc of an ellipse …". */
export function label(s, d) {
  const { kind, triangle: tri, circular, shoulder } = d.conic;
  const point = (p) => pointText([p[0], p[1]], 2);
  const [p0, p1, p2] = s.points;
  return t("conics.aria", {
    kind: t(`conics.article.${kind}`),
    p0: point(p0),
    p1: point(p1),
    p2: point(p2),
    w: fmt(s.w1),
    k: fmt(s.w1 * s.w1),
    circle: circular
      ? t("conics.ariaCircle", {
          r: fmt(tri.radius, 2),
          x: fmt(tri.centre[0], 2),
          y: fmt(tri.centre[1], 2),
        })
      : "",
    sx: fmt(shoulder[0], 2),
    sy: fmt(shoulder[1], 2),
  });
}

/** The table of the three cases, the current one highlighted. */
export function setup(ui) {
  const cells = {};
  const rows = KINDS.map((name) => {
    cells[name] = el("td", { dataset: { kind: name }, text: t(`conics.kind.${name}`) });
    return el("tr", {}, cells[name], el("td", { text: t(`conics.rule.${name}`) }));
  });
  const head = el(
    "tr",
    {},
    ["kind", "rule"].map((c) => el("th", { scope: "col", text: t(`conics.column.${c}`) })),
  );
  const { title, wrap } = titledTable("conics", {
    caption: t("conics.tableCaption"),
    children: [el("thead", {}, head), el("tbody", {}, rows)],
  });
  ui.ctx.slots.details.append(title, wrap);
  return {
    update(s, d) {
      for (const name of KINDS) cells[name].classList.toggle("sl-highlight", name === d.conic.kind);
    },
  };
}
