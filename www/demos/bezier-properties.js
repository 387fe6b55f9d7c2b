/**
 * Demo (syllabus §2, "Properties to demonstrate"): one draggable Bézier curve and, one at a
 * time, the property it has: the convex hull, affine invariance, symmetry (reversed order),
 * degree elevation and variation diminishing. Everything drawn about the curve comes from the
 * core — samples, `reversed()`, `elevate()`, `intersectLine`, `polygonLineCrossings`, and a
 * second `BezierCurve` of the mapped control points. JS only does drawing support: the hull
 * polygon of the control points (`convexHull` in lib/geometry.js), the 2×2 matrix applied to
 * points, and the distances reported as checks.
 */
import { NOTES_CUBIC } from "../lib/examples.js";
import { field } from "../lib/validate.js";
import { slider, choice, pointButtons, readout, group, shownWhen } from "../lib/panel.js";
import {
  fmt,
  subscript,
  degreeName,
  exactFraction,
  fractionText,
  fractionTex,
  allIntegers,
  pointTex,
  pointText,
  fmtMachine,
  fmtTex,
  listTex,
  texListSeparator,
} from "../lib/format.js";
import { HUES, WIDTH, SECOND_CURVE } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf, convexHull, largestGap } from "../lib/geometry.js";
import { affineMap, affineMatrix, centroid } from "../lib/affine-map.js";
import {
  chevron,
  flatDots,
  flatPath,
  indexedPolygonPath,
  linePath,
  pointsPath,
} from "../lib/draw.js";
import { el, setText } from "../lib/controls.js";
import { titledTable } from "../lib/table.js";

export const id = "bezier-properties";
export const strings = "bezierProperties";
export const section = 2;

/** The properties, in the order of the radio buttons. */
export const PROPERTIES = Object.freeze(["hull", "affine", "reversed", "elevation", "variation"]);
/** Fewest and most control points (degree 1 … 8). */
export const MIN_POINTS = 2;
export const MAX_POINTS = 9;
/** Most degree elevations in a row. */
export const MAX_ELEVATIONS = 8;
/** Slider ranges of the affine map: rotation in degrees, uniform scale, shear factor. */
const ROTATION_RANGE = [-180, 180];
const SCALE_RANGE = [0.25, 2];
const SHEAR_RANGE = [-1, 1];
/** Points sampled along a curve for drawing (one `sampleUniform` call per curve and change). */
const CURVE_SAMPLES = 256;
/** Points of the original curve mapped in JS to show they land on the mapped curve. */
const MAPPED_DOTS = 17;
const DOT_TS = new Float64Array(MAPPED_DOTS).map((_, k) => k / (MAPPED_DOTS - 1));
/** Direction chevrons along the curve and the reversed curve, at these parameters. */
const ARROW_TS = Object.freeze([0.2, 0.6]);
/** Distance (model units) within which `intersectLine` reports a hit. */
const INTERSECT_TOLERANCE = 1e-9;

// Styles of this demo's own marks (theme hues are the same in light and dark mode).
const DOT_STYLE = Object.freeze({ fill: HUES.vermillion, radius: 2.5 });
const REVERSED_DASH = Object.freeze([8, 6]);
const REVERSED_STYLE = Object.freeze({
  stroke: HUES.orange,
  width: WIDTH.curve,
  dash: REVERSED_DASH,
  cap: "butt",
});
const FORWARD_CHEVRON = Object.freeze({
  stroke: HUES.blue,
  width: 2.5,
  cap: "round",
  join: "round",
});
const REVERSED_CHEVRON = Object.freeze({
  stroke: HUES.orange,
  width: 2.5,
  cap: "round",
  join: "round",
});
const LINE_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 1.5 });

/**
 * The worked example of the Greek notes (syllabus §2), an affine map that visibly rotates,
 * shrinks and shears it (its image stays in the same window), two elevations, and the line
 * y = 3, which crosses the polygon twice and misses the curve (its highest point is y = 2√2 ≈ 2.83).
 */
export const defaultState = Object.freeze({
  points: NOTES_CUBIC,
  property: "hull",
  rotation: 20,
  scale: 0.8,
  shear: -0.3,
  elevations: 2,
  line: Object.freeze(
    [
      [-1, 3],
      [9, 3],
    ].map(Object.freeze),
  ),
});

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  property: field.choice(PROPERTIES),
  rotation: field.number({ min: ROTATION_RANGE[0], max: ROTATION_RANGE[1] }),
  scale: field.number({ min: SCALE_RANGE[0], max: SCALE_RANGE[1] }),
  shear: field.number({ min: SHEAR_RANGE[0], max: SHEAR_RANGE[1] }),
  elevations: field.number({ min: 0, max: MAX_ELEVATIONS, integer: true }),
  line: field.points({ min: 2, max: 2 }),
};

/** The line through two equal points is no line. */
export function check(s) {
  const [[x0, y0], [x1, y1]] = s.line;
  if (x0 === x1 && y0 === y1) throw new Error(t("bezierProperties.lineDegenerate"));
}

/** The curve, and the curve of the mapped points (its points are set by `affine` below). */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({
    curve: new sl.BezierCurve(flatten(s.points), 2),
    mapped: new sl.BezierCurve(flatten(s.points), 2),
  }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/**
 * Affine invariance: the control points mapped by Φ(x) = c + A(x − c) (c: their centroid) make
 * the second curve in the core; samples of the original, mapped the same way in JS (the dots),
 * must lie on it. `distance`: the largest gap between the two at the same t.
 */
function affine(s, d) {
  // A = R(θ)·f·H(k): rotation, uniform scale, shear along x.
  const matrix = affineMatrix(s.rotation, s.scale, s.shear);
  const centre = centroid(s.points);
  const map = affineMap(matrix, centre);
  const points = s.points.map(([x, y]) => map(x, y));
  points.forEach((q, i) => d.mapped.setControlPoint(i, Float64Array.from(q)));
  const original = d.curve.sample(DOT_TS);
  const dots = new Float64Array(2 * MAPPED_DOTS);
  for (let k = 0; k < MAPPED_DOTS; k++) dots.set(map(original[2 * k], original[2 * k + 1]), 2 * k);
  const distance = largestGap(dots, d.mapped.sample(DOT_TS));
  return { matrix, centre, points, samples: d.mapped.sampleUniform(CURVE_SAMPLES), dots, distance };
}

/** Symmetry: the core's reversed curve, sampled; R(1 − t) is compared with P(t). */
function reversed(s, d) {
  const curve = d.curve.reversed();
  const samples = curve.sampleUniform(CURVE_SAMPLES);
  curve.free();
  return { samples, distance: largestGap(d.samples, samples, true) };
}

/** Degree elevation: `elevate()` applied `elevations` times; the points after one and after all. */
function elevation(s, d) {
  let first = null;
  let current = d.curve;
  for (let k = 0; k < Math.max(s.elevations, 1); k++) {
    const next = current.elevate();
    if (current !== d.curve) current.free();
    current = next;
    if (k === 0) first = current.controlPoints();
  }
  const points = s.elevations > 0 ? current.controlPoints() : d.curve.controlPoints();
  current.free();
  return { first, points };
}

/** Variation diminishing: crossings of the line with the polygon and with the curve. */
function variation(s, d) {
  const [[x0, y0], [x1, y1]] = s.line;
  const ts = d.curve.intersectLine(x0, y0, x1, y1, INTERSECT_TOLERANCE);
  return {
    polygonCrossings: d.curve.polygonLineCrossings(x0, y0, x1, y1),
    curveCrossings: ts.length,
    hits: ts.length ? d.curve.sample(ts) : null,
  };
}

/** Control points after all the elevations. */
const elevatedCount = (d) => d.elevation.points.length / 2;

/** What the core returns for the chosen property (null for the others). */
const only = (property, run) => (s, d) => (s.property === property ? run(s, d) : null);
export const compute = {
  samples: [["points"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  hull: [["points", "property"], only("hull", (s) => convexHull(s.points))],
  affine: [["points", "property", "rotation", "scale", "shear"], only("affine", affine)],
  reversed: [["points", "property"], only("reversed", reversed)],
  elevation: [["points", "property", "elevations"], only("elevation", elevation)],
  variation: [["points", "property", "line"], only("variation", variation)],
};

/**
 * Per property: the readout under the choice (text and the data attributes carrying its
 * numbers), the formula lines and the figure's accessible name.
 */
const PROPERTY = {
  hull: {
    readout: (s, d) =>
      t("bezierProperties.readout.hull", {
        k: d.hull.length,
        names: d.hull.map((i) => `P${subscript(i)}`).join(", "),
      }),
    data: (s, d) => ({ hullVertices: String(d.hull.length) }),
    formula(s, d, n) {
      const weights = [];
      for (let i = 0; i <= n; i++) {
        const b = d.sl.bernstein(n, i, 0.5);
        const f = exactFraction(b, 2 ** n);
        weights.push(f ? fractionTex(f) : fmtTex(b));
      }
      return [
        `P(t) = \\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,P_i,\\qquad B_i^{${n}}(t) \\ge 0,\\quad ` +
          `\\sum_{i=0}^{${n}} B_i^{${n}}(t) = 1`,
        `t = \\tfrac{1}{2}:\\quad B^{${n}}(\\tfrac12) = (${listTex(weights)}),\\quad ` +
          `\\text{${t("bezierProperties.formula.sum")}} = 1`,
        `\\Rightarrow\\ P(t) \\in \\operatorname{conv}\\{P_0, \\dots, P_{${n}}\\} \\quad ` +
          `(${d.hull.length}\\ \\text{${t("bezierProperties.formula.hullVertices")}})`,
      ];
    },
    aria: (s, d, kind) => t("bezierProperties.aria.hull", { kind, k: d.hull.length }),
  },
  affine: {
    readout: (s, d) => t("bezierProperties.readout.affine", { d: fmt(d.affine.distance) }),
    data: (s, d) => ({ maxDistance: fmtMachine(d.affine.distance) }),
    formula(s, d, n) {
      const {
        matrix: [a, b, c, e],
        centre,
        distance,
      } = d.affine;
      return [
        `A = R({${fmtTex(s.rotation, 0)}}^\\circ)\\cdot ${fmtTex(s.scale, 2)}\\cdot` +
          `\\begin{pmatrix}1 & ${fmtTex(s.shear, 2)}\\\\ 0 & 1\\end{pmatrix} = ` +
          `\\begin{pmatrix}${fmtTex(a)} & ${fmtTex(b)}\\\\ ${fmtTex(c)} & ${fmtTex(e)}\\end{pmatrix},\\quad ` +
          `c = ${pointTex([centre[0], centre[1]])}`,
        `\\Phi(x) = c + A(x - c):\\qquad \\Phi\\Big(\\sum_i B_i^{${n}}(t)\\,P_i\\Big) = ` +
          `\\sum_i B_i^{${n}}(t)\\,\\Phi(P_i) ` +
          `\\quad\\text{${t("bezierProperties.formula.because")}}\\ \\sum_i B_i^{${n}}(t) = 1`,
        `\\max_{t}\\ |\\Phi(P(t)) - \\tilde P(t)| = ${fmtTex(distance)}\\quad ` +
          `(${MAPPED_DOTS}\\ \\text{${t("bezierProperties.formula.samples")}})`,
      ];
    },
    aria: (s, d, kind) =>
      t("bezierProperties.aria.affine", {
        kind,
        rotation: fmt(s.rotation, 0),
        scale: fmt(s.scale, 2),
        shear: fmt(s.shear, 2),
        d: fmt(d.affine.distance),
      }),
  },
  reversed: {
    readout: (s, d) => t("bezierProperties.readout.reversed", { d: fmt(d.reversed.distance) }),
    data: (s, d) => ({ maxDistance: fmtMachine(d.reversed.distance) }),
    formula: (s, d, n) => [
      `R_i = P_{${n} - i}:\\quad R(t) = \\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,P_{${n}-i} = \\sum_{j=0}^{${n}} ` +
        `B_{${n}-j}^{${n}}(t)\\,P_j = \\sum_{j=0}^{${n}} B_j^{${n}}(1-t)\\,P_j = P(1-t)`,
      `B_j^{n}(t) = B_{n-j}^{n}(1-t),\\quad \\text{${t("bezierProperties.formula.forExample")} } ` +
        `B_0^{${n}}(\\tfrac14) = ${fmtTex(d.sl.bernstein(n, 0, 0.25))} = ` +
        `B_{${n}}^{${n}}(\\tfrac34)`,
      `\\max_{t}\\ |R(1-t) - P(t)| = ${fmtTex(d.reversed.distance)}\\quad ` +
        `(${CURVE_SAMPLES}\\ \\text{${t("bezierProperties.formula.samples")}})`,
    ],
    aria: (s, d, kind) =>
      t("bezierProperties.aria.reversed", { kind, d: fmt(d.reversed.distance) }),
  },
  elevation: {
    readout: (s, d) =>
      t("bezierProperties.readout.elevation", {
        count: elevatedCount(d),
        n: s.points.length,
        e: s.elevations,
      }),
    data: (s, d) => ({ polygonPoints: String(elevatedCount(d)) }),
    formula(s, d, n) {
      const den = n + 1;
      const ints = allIntegers(s.points.flat());
      const coord = (x) => {
        const f = ints ? exactFraction(x, den) : null;
        return f ? fractionTex(f) : fmtTex(x);
      };
      const first = d.elevation.first;
      const q = [];
      for (let i = 0; i <= n + 1; i++)
        q.push(pointTex([coord(first[2 * i]), coord(first[2 * i + 1])]));
      const count = elevatedCount(d);
      return [
        `Q_i = \\frac{i}{n+1}\\,P_{i-1} + \\Big(1 - \\frac{i}{n+1}\\Big)P_i,\\quad i = 0,\\dots,n+1,\\quad n = ${n}`,
        `Q_1 = \\tfrac{1}{${den}}\\,P_0 + \\tfrac{${n}}{${den}}\\,P_1 = ${q[1]}`,
        `Q = ${q.join(texListSeparator())}`,
        `${s.elevations}\\times:\\ ${n + 1} + ${s.elevations} = ${count}\\ ` +
          `\\text{${t("bezierProperties.formula.points")}}`,
      ];
    },
    aria: (s, d, kind) =>
      t("bezierProperties.aria.elevation", { kind, e: s.elevations, count: elevatedCount(d) }),
  },
  variation: {
    readout: (s, d) =>
      t("bezierProperties.readout.variation", {
        k: d.variation.polygonCrossings,
        j: d.variation.curveCrossings,
      }),
    data: (s, d) => ({
      polygonCrossings: String(d.variation.polygonCrossings),
      curveCrossings: String(d.variation.curveCrossings),
    }),
    formula: (s, d) => [
      `\\#\\{\\text{${t("bezierProperties.formula.lineCurve")}}\\} \\le ` +
        `\\#\\{\\text{${t("bezierProperties.formula.linePolygon")}}\\}`,
      `${d.variation.curveCrossings} \\le ${d.variation.polygonCrossings}`,
    ],
    aria: (s, d, kind) =>
      t("bezierProperties.aria.variation", {
        kind,
        k: d.variation.polygonCrossings,
        j: d.variation.curveCrossings,
      }),
  },
};

const roundTo3 = (v) => String(Math.round(v * 1000) / 1000);
export const controls = [
  group(
    "bezierProperties.propertyLegend",
    choice("property", {
      options: PROPERTIES.map((p) => ({ value: p, label: `bezierProperties.property.${p}` })),
    }),
  ),
  shownWhen(
    (s) => s.property === "affine",
    group(
      "bezierProperties.affineLegend",
      slider("rotation", {
        label: "bezierProperties.rotation",
        min: ROTATION_RANGE[0],
        max: ROTATION_RANGE[1],
        step: 1,
        format: roundTo3,
      }),
      slider("scale", {
        label: "bezierProperties.scale",
        min: SCALE_RANGE[0],
        max: SCALE_RANGE[1],
        step: 0.05,
      }),
      slider("shear", {
        label: "bezierProperties.shear",
        min: SHEAR_RANGE[0],
        max: SHEAR_RANGE[1],
        step: 0.05,
      }),
    ),
  ),
  shownWhen(
    (s) => s.property === "elevation",
    group(
      "bezierProperties.elevationLegend",
      slider("elevations", {
        label: "bezierProperties.elevations",
        min: 0,
        max: MAX_ELEVATIONS,
        step: 1,
        format: (v) => String(Math.round(v)),
        round: Math.round,
      }),
    ),
  ),
  group(
    null,
    readout("property", (s, d) => PROPERTY[s.property].readout(s, d), {
      kind: "readout",
      live: true,
      data: (s, d) => PROPERTY[s.property].data(s, d),
    }),
    readout(null, (s) => t(`bezierProperties.note.${s.property}`)),
  ),
  group(
    null,
    readout("degree", (s) =>
      t("bezierProperties.degree", { n: s.points.length - 1, count: s.points.length }),
    ),
    pointButtons("points", { min: MIN_POINTS, max: MAX_POINTS, prefix: strings }),
  ),
];

/** The line's two points A and B: handles while "variation" is chosen; they may not meet. */
const lineHandle = (index) => ({
  field: "line",
  index,
  label: index === 0 ? "bezierProperties.lineA" : "bezierProperties.lineB",
  when: (s) => s.property === "variation",
  accept: (s, x, y) => s.line[1 - index][0] !== x || s.line[1 - index][1] !== y,
});

export const figure = {
  /** The control points, plus the line or the mapped points when they are shown ("Fit"). */
  bounds(s, d) {
    if (s.property === "variation") return boundsOf(s.points.concat(s.line));
    if (s.property === "affine") return boundsOf(s.points.concat(d.affine.points));
    return boundsOf(s.points);
  },
  handles: { field: "points", extra: [lineHandle(0), lineHandle(1)] },
};

/** The hull or the line under the curve and its polygon; the property's own marks over them. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  if (s.property === "hull" && d.hull.length > 0) {
    indexedPolygonPath(r, v, s.points, d.hull);
    r.paint(theme.helperFill);
  }
  // The infinite line through the two line handles, across the whole canvas.
  if (s.property === "variation" && linePath(r, v, s.line[0], s.line[1])) r.paint(LINE_STYLE);
  pointsPath(r, v, s.points);
  r.paint(theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);

  if (s.property === "affine") {
    // The mapped polygon and curve (green) and the mapped samples of the original (dots).
    pointsPath(r, v, d.affine.points);
    r.paint(SECOND_CURVE.polygon);
    flatPath(r, v, d.affine.samples, 0, CURVE_SAMPLES);
    r.paint(SECOND_CURVE.curve);
    for (const q of d.affine.points) r.point(v.sx(q[0]), v.sy(q[1]), SECOND_CURVE.point);
    flatDots(r, v, d.affine.dots, DOT_STYLE);
  } else if (s.property === "reversed") {
    flatPath(r, v, d.reversed.samples, 0, CURVE_SAMPLES);
    r.paint(REVERSED_STYLE);
    for (const at of ARROW_TS) {
      chevron(r, v, d.samples, Math.round(at * (CURVE_SAMPLES - 1)), FORWARD_CHEVRON);
      chevron(r, v, d.reversed.samples, Math.round(at * (CURVE_SAMPLES - 1)), REVERSED_CHEVRON);
    }
  } else if (s.property === "elevation" && s.elevations > 0) {
    flatPath(r, v, d.elevation.points);
    r.paint(theme.levelStroke[0]);
    flatDots(r, v, d.elevation.points, theme.levelPoint[0]);
  } else if (s.property === "variation" && d.variation.hits) {
    flatDots(r, v, d.variation.hits, theme.pointOnCurve);
  }
  d.handles.draw(r, v);
}

export const formula = (s, d) => PROPERTY[s.property].formula(s, d, s.points.length - 1);
export const label = (s, d) => PROPERTY[s.property].aria(s, d, degreeName(s.points.length - 1));

/** The table of control points after one elevation (exact fractions for integer inputs). */
export function setup(ui) {
  const { title, table, wrap } = titledTable("elevation");
  const block = el("div", {}, title, wrap);
  ui.ctx.slots.details.append(block);
  let cells = [];

  function build(n) {
    cells = [];
    const head = [];
    for (let i = 0; i <= n + 1; i++) {
      head.push(el("th", { scope: "col", text: `Q${subscript(i)}` }));
      cells.push(el("td", { dataset: { elevated: String(i) } }));
    }
    table.replaceChildren(
      el("thead", {}, el("tr", {}, head)),
      el("tbody", {}, el("tr", {}, cells)),
    );
  }

  return {
    update(s, d) {
      block.hidden = s.property !== "elevation";
      if (block.hidden) return;
      const n = s.points.length - 1;
      setText(title, t("bezierProperties.tableCaption", { n, m: n + 1, last: subscript(n + 1) }));
      if (cells.length !== n + 2) build(n);
      const ints = allIntegers(s.points.flat());
      const first = d.elevation.first;
      for (let i = 0; i <= n + 1; i++) {
        const x = first[2 * i];
        const y = first[2 * i + 1];
        const fx = ints ? exactFraction(x, n + 1) : null;
        const fy = ints ? exactFraction(y, n + 1) : null;
        setText(cells[i], pointText(fx && fy ? [fractionText(fx), fractionText(fy)] : [x, y]));
      }
    },
  };
}
