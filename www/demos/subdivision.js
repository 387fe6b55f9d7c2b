/**
 * Demo 3 (syllabus §2): subdivision. `curve.split(t0)` cuts a Bézier curve into two Bézier
 * curves of the same degree whose control polygons are the two outer edges of the de Casteljau
 * triangle at t0:
 *
 *   left  l_i = p_0^i(t0)      (top edge),    L(u) = P(t0·u),
 *   right r_i = p_i^{n−i}(t0)  (hypotenuse),  R(u) = P(t0 + (1 − t0)·u),   u ∈ [0, 1].
 *
 * A "levels" control repeats the split at 1/2: after k levels the 2^k polygons (from
 * 2^k − 1 `split(0.5)` calls, every intermediate wasm object freed) hug the curve.
 */
import { NOTES_CUBIC } from "../lib/examples.js";
import { field } from "../lib/validate.js";
import { slider, checkbox, pointButtons, readout, group } from "../lib/panel.js";
import { BEZIER_POINTS } from "../lib/point-list.js";
import { placeLabel, placeLabelFrom } from "../lib/handles.js";
import { el, setText } from "../lib/controls.js";
import {
  fmt,
  subscript,
  superscript,
  degreeName,
  exactNumbers,
  fractionTex,
  fmtTex,
  pointText,
  listTex,
  texListSeparator,
} from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, paddedBounds } from "../lib/geometry.js";
import { detailsTable, valueSpans, setValueSpans } from "../lib/table.js";
import { screenCentroid } from "../lib/triangle.js";
import { flatPath, pointsPath } from "../lib/draw.js";

export const id = "subdivision";
export const strings = "subdivision";
export const section = 2;

/** Repeated subdivision at 1/2: at most this many levels (2^6 = 64 polygons). */
export const MAX_LEVELS = 6;
/** Repeated subdivision always splits at this parameter. */
const HALF = 0.5;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Slider resolution for t0. */
const T_SLIDER_STEP = 0.001;
/** Left/right points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_MAX_DEGREE = 6;
/** Fitting leaves this fraction of the width free on each side for the long end labels "P₀ = L₀". */
const END_LABEL_ROOM = 0.12;
/** Points of the level polygons are drawn up to this level (beyond, they make a solid line). */
const LEVEL_POINTS_MAX = 3;

/** The worked example of the Greek notes (syllabus §2), split in the middle. */
export const defaultState = Object.freeze({
  points: NOTES_CUBIC,
  t: 0.5,
  levels: 0,
  triangle: true,
});

export const fields = {
  points: field.points(BEZIER_POINTS),
  t: field.number({ min: 0, max: 1 }),
  levels: field.number({ min: 0, max: MAX_LEVELS, integer: true }),
  triangle: field.boolean(),
};

/** The curve, in wasm; a dragged point moves it in place. */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({ curve: new sl.BezierCurve(flatten(s.points), 2) }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/** The control points of the two halves of `curve.split(t0)`, flat; the halves are freed. */
function halves(curve, t0) {
  const [l, r] = curve.split(t0);
  try {
    return { left: l.controlPoints(), right: r.controlPoints() };
  } finally {
    l.free();
    r.free();
  }
}

/**
 * The control points of the 2^levels pieces of `curve` after `levels` rounds of splitting every
 * piece at 1/2 (2^levels − 1 `split` calls), flat, piece after piece. Every intermediate wasm
 * object is freed, also when a call throws.
 */
function subdivide(curve, levels) {
  if (levels === 0) return curve.controlPoints();
  let pieces = curve.split(HALF);
  try {
    for (let level = 2; level <= levels; level++) {
      const next = [];
      try {
        for (const piece of pieces) next.push(...piece.split(HALF));
      } catch (err) {
        for (const piece of next) piece.free();
        throw err;
      }
      for (const piece of pieces) piece.free();
      pieces = next;
    }
    const perPiece = 2 * (curve.degree + 1);
    const flat = new Float64Array(pieces.length * perPiece);
    pieces.forEach((piece, j) => flat.set(piece.controlPoints(), j * perPiece));
    return flat;
  } finally {
    for (const piece of pieces) piece.free();
  }
}

/**
 * The figure's texts for degree n: handles P₀ … Pₙ (while the split is shown, the ends also
 * name what they are: P₀ = L₀, Pₙ = Rₙ), the halves' points L₁, R₁ … and the split point
 * Lₙ = R₀. Made again only when the degree or the split's visibility changed.
 */
function labelsOf(n, split, previous) {
  if (previous?.n === n && previous.split === split) return previous;
  const p = (i) => `P${subscript(i)}`;
  const handles = [];
  for (let i = 0; i <= n; i++) handles.push(p(i));
  if (split) {
    handles[0] = t("subdivision.firstLabel", {
      p: p(0),
      l: `L${subscript(0)}`,
      r: `R${subscript(0)}`,
    });
    handles[n] = t("subdivision.lastLabel", {
      p: p(n),
      l: `L${subscript(0)}`,
      r: `R${subscript(n)}`,
    });
  }
  const left = [];
  const right = [];
  for (let i = 0; i <= n; i++) {
    left.push(t("subdivision.leftLabel", { i: subscript(i) }));
    right.push(t("subdivision.rightLabel", { i: subscript(i) }));
  }
  const point = split
    ? t("subdivision.splitLabel", { l: `L${subscript(n)}`, r: `R${subscript(0)}` })
    : t("subdivision.splitPointLabel");
  return { n, split, handles, left, right, point };
}

/** What the core returns: the samples, the two halves and the triangle at t0, the level polygons; the texts. */
export const compute = {
  samples: [["points"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  halves: [["points", "t"], (s, d) => halves(d.curve, s.t)],
  triangle: [["points", "t"], (s, d) => d.curve.deCasteljau(s.t)],
  pieces: [["points", "levels"], (s, d) => subdivide(d.curve, s.levels)],
  labels: [["points", "levels"], (s, d) => labelsOf(s.points.length - 1, s.levels === 0, d.labels)],
};

export const controls = [
  group(
    null,
    slider("t", {
      label: "subdivision.control.t",
      min: 0,
      max: 1,
      step: T_SLIDER_STEP,
      player: {
        playable: false,
        stepBackTitle: "subdivision.control.stepBack.title",
        stepTitle: "subdivision.control.stepForward.title",
      },
    }),
    checkbox("triangle", { label: "subdivision.control.triangle" }),
  ),
  group(
    null,
    slider("levels", {
      label: "subdivision.control.levels",
      min: 0,
      max: MAX_LEVELS,
      step: 1,
      format: (v) => String(v),
      round: (v) => Math.min(MAX_LEVELS, Math.max(0, Math.round(v))),
    }),
    readout("levels", (s, d) => levelsNote(s, d)),
  ),
  group(
    null,
    readout("degree", (s) =>
      t("subdivision.degree", { n: s.points.length - 1, count: s.points.length }),
    ),
    pointButtons("points", { ...BEZIER_POINTS, prefix: strings }),
  ),
];

export const figure = {
  bounds: (s) => paddedBounds(s.points, END_LABEL_ROOM, 0), // widened left and right
  handles: { field: "points", label: (i, s, d) => d.labels.handles[i] },
};

// ------------------------------------------------------------ drawing

const centre = new Float64Array(2);

/**
 * The faint triangle at t0, the polygon, the curve, then either the two halves' polygons (left
 * solid with dots, right dashed with squares) or the 2^k level polygons; the split point.
 */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const n = s.points.length - 1;
  const showSplit = s.levels === 0;
  const { left, right } = d.halves;

  // The de Casteljau triangle at t0, faint: its inner levels (the outer edges are L and R).
  if (showSplit && s.triangle) {
    let offset = n + 1;
    r.beginPath();
    for (let level = 1; level < n; level++) {
      const count = n + 1 - level;
      for (let j = 0; j < count; j++) {
        const x = v.sx(d.triangle[2 * (offset + j)]);
        const y = v.sy(d.triangle[2 * (offset + j) + 1]);
        if (j === 0) r.moveTo(x, y);
        else r.lineTo(x, y);
      }
      offset += count;
    }
    r.paint(theme.helper);
  }
  pointsPath(r, v, s.points, 0, n + 1);
  r.paint(theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);

  if (showSplit) {
    flatPath(r, v, left, 0, n + 1);
    r.paint(theme.splitLeft);
    flatPath(r, v, right, 0, n + 1);
    r.paint(theme.splitRight);
    const size = theme.splitRightPoint.radius * r.scale;
    for (let i = 0; i <= n; i++) {
      r.point(v.sx(left[2 * i]), v.sy(left[2 * i + 1]), theme.splitLeftPoint);
      r.beginPath();
      r.rect(v.sx(right[2 * i]) - size, v.sy(right[2 * i + 1]) - size, 2 * size, 2 * size);
      r.paint(theme.splitRightPoint);
    }
  } else {
    // 2^k polygons in two alternating colours, over the curve so that their approach stays visible.
    const perPiece = n + 1;
    const count = d.pieces.length / (2 * perPiece);
    for (let j = 0; j < count; j++) {
      const colour = j % 2;
      flatPath(r, v, d.pieces, j * perPiece, (j + 1) * perPiece);
      r.paint(theme.levelStroke[colour]);
      if (s.levels > LEVEL_POINTS_MAX) continue;
      for (let i = 0; i < perPiece; i++) {
        const k = 2 * (j * perPiece + i);
        r.point(v.sx(d.pieces[k]), v.sy(d.pieces[k + 1]), theme.levelPoint[colour]);
      }
    }
  }
  d.handles.draw(r, v);

  // Labels go on the side away from the control points' centroid on screen.
  screenCentroid(v, s.points, centre);
  if (showSplit && n <= LABEL_MAX_DEGREE) {
    for (let i = 1; i < n; i++) {
      labelOutward(
        r,
        v,
        d.labels.left[i],
        left,
        i,
        n,
        theme.labelSmall,
        theme.splitLeftPoint.radius * r.scale,
      );
      labelOutward(
        r,
        v,
        d.labels.right[i],
        right,
        i,
        n,
        theme.labelSmall,
        theme.splitRightPoint.radius * r.scale,
      );
    }
  }
  // The split point P(t0) = l_n = r_0.
  const sx = v.sx(right[0]);
  const sy = v.sy(right[1]);
  r.point(sx, sy, theme.pointOnCurve);
  const radius = theme.pointOnCurve.radius * r.scale;
  placeLabelFrom(r, d.labels.point, sx, sy, centre[0], centre[1], theme.labelPoint, radius);
}

/**
 * Labels inner point i of a half's polygon (flat, n + 1 points) outside it: perpendicular to
 * the chord from its first to its last point, on the side the point lies (the half's curve
 * runs between the polygon and that chord). Points on the chord are labelled away from the centroid.
 */
function labelOutward(r, v, text, flat, i, n, style, radius) {
  const x = v.sx(flat[2 * i]);
  const y = v.sy(flat[2 * i + 1]);
  const ax = v.sx(flat[0]);
  const ay = v.sy(flat[1]);
  let nx = ay - v.sy(flat[2 * n + 1]);
  let ny = v.sx(flat[2 * n]) - ax;
  const length = Math.hypot(nx, ny);
  const side = length > 0 ? ((x - ax) * nx + (y - ay) * ny) / length : 0;
  if (Math.abs(side) < 1) {
    placeLabelFrom(r, text, x, y, centre[0], centre[1], style, radius);
    return;
  }
  nx /= side > 0 ? length : -length;
  ny /= side > 0 ? length : -length;
  placeLabel(r, text, x, y, nx, ny, radius, style);
}

// ------------------------------------------------------------ formula, notes, label

/** Level k: 2^k polygons of n + 1 points; neighbours share their end points. */
function levelCounts(s, d) {
  const perPiece = s.points.length;
  const polygons = d.pieces.length / (2 * perPiece);
  return {
    k: s.levels,
    polygons,
    total: polygons * perPiece,
    distinct: polygons * (perPiece - 1) + 1,
  };
}

function levelsNote(s, d) {
  return t(
    s.levels === 0 ? "subdivision.levelsNote0" : "subdivision.levelsNote",
    levelCounts(s, d),
  );
}

/**
 * Exact text when t0 is a simple fraction and every control point is an integer: every point of
 * the triangle is then k / den^n. The parameter itself is a fraction whenever it is a simple one.
 */
const pointNumbers = (s) => exactNumbers(s.t, s.points.flat());
const paramText = (s, tex = false) => exactNumbers(s.t, []).param(tex);

/** The two edges of the triangle, the split point, both halves, their reparametrisation, the level count. */
export function formula(s, d) {
  const n = s.points.length - 1;
  const num = pointNumbers(s);
  const { left, right } = d.halves;
  const tTex = paramText(s, true);
  const f = exactNumbers(s.t, []).exact;
  const oneMinusTex = f ? fractionTex({ num: f.den - f.num, den: f.den }) : fmtTex(1 - s.t);
  const coordinate = (value) => num.value(value, n, true);
  const pointAt = (flat, i) =>
    `\\left(${listTex([coordinate(flat[2 * i]), coordinate(flat[2 * i + 1])])}\\right)`;
  const list = (flat) =>
    Array.from({ length: n + 1 }, (_, i) => pointAt(flat, i)).join(texListSeparator());
  const { k, polygons, total } = levelCounts(s, d);
  const polygonWord = `\\text{${tp("subdivision.formulaPolygons", polygons)}}`;
  return [
    `l_i = p_0^{\\,i}(t_0),\\qquad r_i = p_i^{\\,${n}-i}(t_0),\\qquad i = 0,\\dots,${n},\\qquad t_0 = ${tTex}`,
    `l_{${n}} = r_0 = p_0^{${n}}(${tTex}) = P(${tTex}) = ${pointAt(right, 0)}`,
    `L:\\ ${list(left)}`,
    `R:\\ ${list(right)}`,
    `L(u) = P(${tTex}\\,u),\\qquad R(u) = P\\!\\left(${tTex} + ${oneMinusTex}\\,u\\right),\\qquad 0 \\le u \\le 1`,
    `k = ${k}:\\quad 2^{${k}} = ${polygons}\\ ${polygonWord},\\quad ` +
      `${polygons} \\cdot ${n + 1} = ${total}\\ \\text{${t("subdivision.formulaPoints")}}`,
  ];
}

/** The curve, t0, the halves and the split point; the level polygons when shown. */
export function label(s, d) {
  const n = s.points.length - 1;
  const { right } = d.halves;
  const { k, polygons, total } = levelCounts(s, d);
  const levels = k === 0 ? "" : t("subdivision.ariaLevels", { k, polygons, total });
  const x = fmt(right[0], 2);
  const y = fmt(right[1], 2);
  return (
    t("subdivision.aria", {
      kind: degreeName(n),
      count: n + 1,
      t: fmt(s.t),
      n: subscript(n),
      x,
      y,
    }) + levels
  );
}

// ------------------------------------------------------------ the table

/** The table: one row per i with l_i = p_0^i and r_i = p_i^{n−i} (fraction and decimals). */
export function setup(ui) {
  const details = detailsTable(ui, "subdivision", (n, table) => {
    const columns = ["colIndex", "colLeft", "colRight"];
    const head = el(
      "tr",
      {},
      columns.map((key) => el("th", { scope: "col", text: t(`subdivision.${key}`) })),
    );
    const cell = (side, i, name, spans) => {
      const nameSpan = el("span", { class: "sl-cell-name", text: name });
      return el(
        "td",
        { dataset: { side, index: String(i) } },
        nameSpan,
        spans.exact,
        spans.decimal,
      );
    };
    const cells = [];
    const rows = [];
    for (let i = 0; i <= n; i++) {
      const row = { left: valueSpans(), right: valueSpans() };
      cells.push(row);
      rows.push(
        el(
          "tr",
          {},
          el("th", { scope: "row", text: String(i) }),
          cell("left", i, `l${subscript(i)} = p${subscript(0)}${superscript(i)} = `, row.left),
          cell(
            "right",
            i,
            `r${subscript(i)} = p${subscript(i)}${superscript(n - i)} = `,
            row.right,
          ),
        ),
      );
    }
    table.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));
    return cells;
  });

  return {
    update(s, d) {
      const n = s.points.length - 1;
      const cells = details.cellsFor(n);
      const num = pointNumbers(s);
      /** Point i of `flat` in a cell: exact value first, decimals under it when different. */
      const fill = (spans, flat, i) => {
        const [x, y] = [flat[2 * i], flat[2 * i + 1]];
        setValueSpans(spans, pointText([num.value(x, n), num.value(y, n)]), pointText([x, y]));
      };
      setText(details.title, t("subdivision.tableCaption", { t: paramText(s) }));
      for (let i = 0; i <= n; i++) {
        fill(cells[i].left, d.halves.left, i);
        fill(cells[i].right, d.halves.right, i);
      }
    },
  };
}
