/**
 * Demo 5 (syllabus §2): curve–line intersection by recursive bounding boxes. A cubic and an
 * infinite line through two handles A and B. With the signed distance to the line
 *
 *   d(P) = (B − A) × (P − A) / |B − A|,
 *
 * a box whose corners all have one sign misses the line and is pruned; the others are split at
 * t = 1/2 until they are small. The figure shows the boxes the core's recursion visited
 * (`intersectLineBoxes`), pruned ones faint, hit ones outlined, up to a chosen depth so a
 * lecturer can step through the levels; the intersections from `intersectLine` as points
 * labelled with t; and the variation-diminishing count (`polygonLineCrossings`): a line never
 * crosses the curve more often than its control polygon.
 */
import { field } from "../lib/validate.js";
import { readout, group } from "../lib/panel.js";
import { placeLabel } from "../lib/handles.js";
import { slider, button, el, setText } from "../lib/controls.js";
import {
  fmt,
  subscript,
  simpleFraction,
  fractionText,
  pointText,
  listTex,
  listText,
  fmtTex,
  pointTex,
  localeDecimal,
} from "../lib/format.js";
import { t, tp } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { detailsTable } from "../lib/table.js";
import { flatPath } from "../lib/draw.js";
import { errorText } from "../lib/core-errors.js";

export const id = "line-intersection";
export const strings = "lineIntersection";
export const section = 2;

/** Deepest level of the core's box recursion (MAX_INTERSECTION_DEPTH in src/bezier/intersect.rs). */
export const MAX_DEPTH = 48;
/** Tolerance of the roots: each t has its point within this distance of the line. */
export const ROOT_TOLERANCE = 1e-9;
/** Tolerance of the boxes drawn: boxes stop splitting below this size (readable picture). */
export const BOX_TOLERANCE = 1e-3;
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
/** The core's boxes: six numbers each, [depth, x0, y0, x1, y1, hit]. */
const BOX_STRIDE = 6;

/**
 * An S-shaped cubic, point-symmetric about (6, 0) = P(1/2), and the line y = 1 − x/6 through
 * that centre: three crossings, at t = 1/3, 1/2, 2/3 exactly (by hand: P(1/3) = (34/9, 10/27)
 * and 1 − (34/9)/6 = 10/27; the symmetry gives 2/3); the control polygon is crossed three
 * times too. `depth` = MAX_DEPTH shows every level.
 */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, -2],
      [3, 4],
      [9, -4],
      [12, 2],
    ].map(Object.freeze),
  ),
  line: Object.freeze(
    [
      [0, 1],
      [12, -1],
    ].map(Object.freeze),
  ),
  depth: MAX_DEPTH,
});

/** The line's two points A and B; they must differ: a line needs a direction. */
function lineField(state, name) {
  field.points({ min: LINE_HANDLES, max: LINE_HANDLES })(state, name);
  const [[ax, ay], [bx, by]] = state[name];
  if (ax === bx && ay === by)
    throw new Error(t("lineIntersection.sameLinePoints", { x: ax, y: ay }));
}

export const fields = {
  points: field.points({ min: POINT_COUNT, max: POINT_COUNT }),
  line: lineField,
  depth: field.number({ min: 0, max: MAX_DEPTH, integer: true }),
};

/** The curve, in wasm; a dragged control point moves it in place (A and B are not in it). */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({ curve: new sl.BezierCurve(flatten(s.points), 2) }),
  moved: (m, i, xy) => {
    if (i < POINT_COUNT) m.curve.setControlPoint(i, xy);
  },
};

const NOTHING_FOUND = Object.freeze({
  roots: new Float64Array(0),
  points: new Float64Array(0),
  boxes: new Float64Array(0),
  polygonCrossings: 0,
  deepest: 0,
  labels: [],
});

/**
 * What the core says about the curve and the line: the roots t and their points, the boxes the
 * recursion visited and the deepest level it reached, the polygon's crossings; the t labels.
 * Should a call fail (A = B is refused before), the last result stays, with the `error`.
 */
function intersect(curve, [[ax, ay], [bx, by]], previous = NOTHING_FOUND) {
  try {
    const roots = curve.intersectLine(ax, ay, bx, by, ROOT_TOLERANCE);
    const boxes = curve.intersectLineBoxes(ax, ay, bx, by, BOX_TOLERANCE);
    let deepest = 0;
    for (let k = 0; k < boxes.length; k += BOX_STRIDE) deepest = Math.max(deepest, boxes[k]);
    return {
      roots,
      points: roots.length ? curve.sample(roots) : new Float64Array(0),
      boxes,
      polygonCrossings: curve.polygonLineCrossings(ax, ay, bx, by),
      deepest,
      labels: Array.from(roots, (root) => t("lineIntersection.rootLabel", { t: fmt(root) })),
    };
  } catch (err) {
    return { ...previous, error: errorText(err) };
  }
}

/** What the core returns: the curve's samples and the intersection; the handles' names. */
export const compute = {
  samples: [["points"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  found: [["points", "line"], (s, d) => intersect(d.curve, s.line, d.found)],
  handleLabels: [
    [],
    () => ["P₀", "P₁", "P₂", "P₃", t("lineIntersection.handleA"), t("lineIntersection.handleB")],
  ],
};

/** Depth shown: the state's depth, at most the deepest level the recursion reached. */
const shownDepth = (s, d) => Math.min(s.depth, d.found.deepest);

/**
 * The depth shown: a slider over the levels reached (0 … deepest), the ◀ Level / Level ▶
 * buttons. Reaching the deepest level means "every level" (MAX_DEPTH), so it stays so while
 * the curve or the line moves; typed depths run 0 … MAX_DEPTH.
 */
function depthControl() {
  return {
    build(ui) {
      const set = (value, final) =>
        ui.set("depth", value >= ui.data.found.deepest ? MAX_DEPTH : value, final);
      const control = slider({
        label: t("lineIntersection.depth"),
        inputLabel: t("lineIntersection.depth.input", { max: MAX_DEPTH }),
        name: "depth",
        min: 0,
        max: MAX_DEPTH,
        step: 1,
        value: ui.state.depth,
        format: (v) => String(Math.round(v)),
        onChange: (value, final) => set(Math.round(value), final),
        onError: (text) =>
          ui.status(t("lineIntersection.badDepth", { value: text, max: MAX_DEPTH }), "error"),
      });
      const stepBy = (direction) => {
        const depth = shownDepth(ui.state, ui.data) + direction;
        set(Math.max(0, Math.min(ui.data.found.deepest, depth)), true);
      };
      const shallower = button({
        label: t("lineIntersection.shallower"),
        title: t("lineIntersection.shallower.title"),
        name: "depth-down",
        onClick: () => stepBy(-1),
      });
      const deeper = button({
        label: t("lineIntersection.deeper"),
        title: t("lineIntersection.deeper.title"),
        name: "depth-up",
        onClick: () => stepBy(1),
      });
      const element = document.createDocumentFragment();
      element.append(control.element, el("div", { class: "sl-button-row" }, shallower, deeper));
      return {
        element,
        sync(s, d) {
          const depth = shownDepth(s, d);
          control.range.max = String(d.found.deepest);
          control.set(depth);
          shallower.disabled = depth <= 0;
          deeper.disabled = depth >= d.found.deepest;
        },
      };
    },
  };
}

/** "3 intersections", "1 intersection" or "no intersection". */
function countText(s, d) {
  const count = d.found.roots.length;
  return count === 0 ? t("lineIntersection.none") : tp("lineIntersection.count", count);
}

/** Variation diminishing: the line crosses the curve at most as often as the control polygon. */
function crossingsText(s, d) {
  return t("lineIntersection.crossings", {
    polygon: d.found.polygonCrossings,
    curve: d.found.roots.length,
  });
}

/** Boxes up to the shown depth: visited, hit, pruned. */
function boxesText(s, d) {
  const boxes = d.found.boxes;
  const depth = shownDepth(s, d);
  let visited = 0;
  let hit = 0;
  for (let k = 0; k < boxes.length; k += BOX_STRIDE) {
    if (boxes[k] > depth) continue;
    visited += 1;
    if (boxes[k + 5] === 1) hit += 1;
  }
  const deepest = d.found.deepest;
  return t("lineIntersection.boxes", {
    depth,
    deepest,
    visited,
    hit,
    pruned: visited - hit,
    tolerance: localeDecimal(String(BOX_TOLERANCE)),
  });
}

export const controls = [
  group(
    null,
    readout("count", countText, { kind: "readout" }),
    readout("crossings", crossingsText),
  ),
  group(null, depthControl(), readout("boxes", boxesText)),
];

export const figure = {
  bounds: (s) => boundsOf([...s.points, ...s.line]),
  /** P₀ … P₃, then A and B; A = B gives no line: such a move is refused (the handle stays). */
  handles: {
    field: ["points", "line"],
    label: (i, s, d) => d.handleLabels[i],
    accept: (i, x, y, s) => {
      if (i < POINT_COUNT) return true;
      const [ox, oy] = s.line[LINE_HANDLES - 1 - (i - POINT_COUNT)];
      return x !== ox || y !== oy;
    },
  },
};

// ------------------------------------------------------------ drawing

/** The boxes up to the shown depth, the polygon, the curve, the line, the handles, the roots labelled with t. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  const { boxes, points: hits, labels } = d.found;
  const depth = shownDepth(s, d);

  // Boxes up to the shown depth: pruned ones faint (one path), hit ones outlined (one path).
  for (let hit = 0; hit <= 1; hit++) {
    r.beginPath();
    for (let k = 0; k < boxes.length; k += BOX_STRIDE) {
      if (boxes[k] > depth || boxes[k + 5] !== hit) continue;
      const x0 = v.sx(boxes[k + 1]);
      const y1 = v.sy(boxes[k + 2]);
      r.rect(x0, v.sy(boxes[k + 4]), v.sx(boxes[k + 3]) - x0, y1 - v.sy(boxes[k + 4]));
    }
    r.paint(hit ? theme.levelStroke[0] : theme.helperFill);
  }
  r.beginPath();
  for (let i = 0; i < pts.length; i++) {
    if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
  }
  r.paint(theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);

  // The infinite line through A and B, across the whole figure.
  const [[ax, ay], [bx, by]] = s.line;
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
  d.handles.draw(r, v);

  // The intersections, labelled with their t on alternate sides of the line (neighbours
  // along the line do not collide); a label too close to the previous one on its side is
  // moved one line further out.
  const style = theme.labelPoint;
  const lineHeight = style.size * LABEL_LINE_HEIGHT * r.scale;
  let lastPlus = -Infinity;
  let lastMinus = -Infinity;
  let levelPlus = 0;
  let levelMinus = 0;
  for (let k = 0; k < labels.length; k++) {
    const x = v.sx(hits[2 * k]);
    const y = v.sy(hits[2 * k + 1]);
    const plus = k % 2 === 0;
    const width = labels[k].length * style.size * GLYPH_WIDTH_EM * r.scale; // an estimate: no measuring per frame
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
    const distance = (theme.pointOnCurve.radius + ROOT_LABEL_OFFSET) * r.scale + level * lineHeight;
    r.point(x, y, theme.pointOnCurve);
    placeLabel(r, labels[k], x, y, side * nx, side * ny, distance, style);
  }
}

// ------------------------------------------------------------ formula, label, table

/** A coordinate for labels and formulas (TeX with `tex`): integers as they are, others with 2 decimals. */
function coord(x, tex = false) {
  return Number.isInteger(x) ? String(x) : tex ? fmtTex(x, 2) : fmt(x, 2);
}

/** The signed distance to the line, the pruning rule, the roots and the crossing counts. */
export function formula(s, d) {
  const { roots, polygonCrossings } = d.found;
  const [[ax, ay], [bx, by]] = s.line;
  const pairTex = (x, y) => pointTex([coord(x, true), coord(y, true)]);
  const rootsTex = roots.length === 0 ? "\\varnothing" : `\\{${listTex(roots)}\\}`;
  const text = (key) => `\\text{${t(`lineIntersection.formula.${key}`)}}`;
  return [
    `d(P) = \\frac{(B - A) \\times (P - A)}{\\lvert B - A \\rvert}, \\qquad ` +
      `A = ${pairTex(ax, ay)},\\ B = ${pairTex(bx, by)}`,
    `d(c_1), \\dots, d(c_4)\\ ${text("miss")} \\;\\Rightarrow\\; ${text("pruned")}`,
    `${text("split")}\\ t = \\tfrac12 ${text("until")}\\ 10^{${Math.round(Math.log10(BOX_TOLERANCE))}}`,
    `t \\in ${rootsTex}, \\qquad ` +
      `\\#${text("curve")} = ${roots.length} \\;\\le\\; \\#${text("polygon")} = ${polygonCrossings}`,
  ];
}

/** The curve, the line, the intersections (t), the polygon's crossings and the depth shown. */
export function label(s, d) {
  const roots = d.found.roots;
  const [[ax, ay], [bx, by]] = s.line;
  const tList = listText(roots);
  return t("lineIntersection.aria", {
    points: listText(s.points.map(([x, y]) => pointText([coord(x), coord(y)]))),
    a: pointText([coord(ax), coord(ay)]),
    b: pointText([coord(bx), coord(by)]),
    result: roots.length === 0 ? t("lineIntersection.none") : `${countText(s, d)} (t = ${tList})`,
    polygon: d.found.polygonCrossings,
    depth: shownDepth(s, d),
    deepest: d.found.deepest,
  });
}

/** The table: one row per intersection, t (with its fraction when simple) and P(t); a failed call is reported. */
export function setup(ui) {
  const details = detailsTable(ui, "intersections", (count, table) => {
    const cells = [];
    const rows = [];
    for (let k = 0; k < count; k++) {
      const row = {
        t: el("td", { dataset: { field: "t" } }),
        point: el("td", { dataset: { field: "point" } }),
      };
      cells.push(row);
      const name = el("th", { scope: "row", text: `t${subscript(k + 1)}` });
      rows.push(el("tr", { dataset: { root: String(k) } }, name, row.t, row.point));
    }
    const head = el(
      "thead",
      {},
      el(
        "tr",
        {},
        el("th", { scope: "col", text: t("lineIntersection.tableRoot") }),
        el("th", { scope: "col", text: "t" }),
        el("th", { scope: "col", text: t("lineIntersection.tablePoint") }),
      ),
    );
    table.hidden = count === 0;
    table.replaceChildren(head, el("tbody", {}, rows));
    return cells;
  });
  let reported = null;

  return {
    update(s, d) {
      const { roots, points, error } = d.found;
      if (error && d.found !== reported)
        ui.status(t("lineIntersection.failed", { message: error }), "error");
      reported = d.found;
      const count = roots.length;
      const caption = t("lineIntersection.tableCaption", {
        tolerance: localeDecimal(String(ROOT_TOLERANCE)),
      });
      setText(details.title, count === 0 ? t("lineIntersection.tableNone") : caption);
      const cells = details.cellsFor(count);
      for (let k = 0; k < count; k++) {
        // Exact fractions too when t is a simple one (1/3, 1/2 …): the hand-made cases read so.
        const fraction = simpleFraction(roots[k]);
        const decimals = fmt(roots[k]);
        setText(
          cells[k].t,
          fraction && fraction.den > 1 ? `${decimals} = ${fractionText(fraction)}` : decimals,
        );
        setText(cells[k].point, pointText([points[2 * k], points[2 * k + 1]]));
      }
    },
  };
}
