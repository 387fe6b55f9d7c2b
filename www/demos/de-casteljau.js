/**
 * Demo 1 (syllabus §2): de Casteljau's algorithm. The reference demo of the declarative
 * contract (lib/demo.js): the state's fields and the controls bound to them are declared; the
 * curve lives in wasm (`derive`) and is updated in place while dragging (`setControlPoint`);
 * the triangle and the samples are what the core returns (`compute`); `draw` and `formula`
 * read them. Everything else (undo, links, files, syncing the slider) is the shell's.
 */
import { NOTES_CUBIC } from "../lib/examples.js";
import { field } from "../lib/validate.js";
import { slider, checkbox, pointButtons, readout, group } from "../lib/panel.js";
import { BEZIER_POINTS } from "../lib/point-list.js";
import {
  fmt,
  subscript,
  superscript,
  degreeName,
  exactNumbers,
  pointTex,
  pointText,
  listTex,
} from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { drawLevels, legLabel, levelStart, LevelLabels, screenCentroid } from "../lib/triangle.js";
import { el, setText } from "../lib/controls.js";
import { titledTable, valueSpans, setValueSpans } from "../lib/table.js";

export const id = "de-casteljau";
export const strings = "deCasteljau";
export const section = 2;

/** Points sampled along the curve for drawing. */
const CURVE_SAMPLES = 256;
/** Intermediate points are labelled up to this degree (beyond, labels crowd; the table has them). */
const LABEL_LEVELS_MAX_DEGREE = 4;

/** The worked example of the Greek notes (syllabus §2): P(1/4) = (29/16, 23/16). */
export const defaultState = Object.freeze({
  points: NOTES_CUBIC,
  t: 0.25,
  construction: true,
});

export const fields = {
  points: field.points(BEZIER_POINTS),
  t: field.number({ min: 0, max: 1 }),
  construction: field.boolean(),
};

/** The curve, in wasm; a dragged point moves it in place. */
export const derive = {
  from: ["points"],
  build: (s, sl) => ({ curve: new sl.BezierCurve(flatten(s.points), 2) }),
  moved: (m, i, xy) => m.curve.setControlPoint(i, xy),
};

/** What the core returns: the samples of the curve and the whole triangle at t. */
export const compute = {
  samples: [["points"], (s, d) => d.curve.sampleUniform(CURVE_SAMPLES)],
  triangle: [["points", "t"], (s, d) => d.curve.deCasteljau(s.t)],
};

export const controls = [
  group(null, slider("t", { label: "control.t", min: 0, max: 1, step: 0.001, player: true })),
  group(
    null,
    readout("degree", (s) =>
      t("deCasteljau.degree", { n: s.points.length - 1, count: s.points.length }),
    ),
    pointButtons("points", { ...BEZIER_POINTS, prefix: strings }),
  ),
  group(null, checkbox("construction", { label: "control.construction" })),
];

export const figure = {
  bounds: (s) => boundsOf(s.points),
  handles: { field: "points" },
};

const labels = new LevelLabels("p");
const centre = new Float64Array(2);

/** The polygon, the curve, the levels of the triangle at t, the handles and P(t). */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const n = s.points.length - 1;
  pointsPath(r, v, s.points, 0, n + 1);
  r.paint(theme.polygon);
  flatPath(r, v, d.samples, 0, CURVE_SAMPLES);
  r.paint(theme.curve);
  screenCentroid(v, s.points, centre);
  if (s.construction)
    drawLevels(r, v, d.triangle, n, centre, n <= LABEL_LEVELS_MAX_DEGREE ? labels : null);
  d.handles.draw(r, v);
  // P(t) = p₀ⁿ, the apex, labelled beside the last leg (away from the polygon).
  const apex = levelStart(n, n);
  r.point(v.sx(d.triangle[2 * apex]), v.sy(d.triangle[2 * apex + 1]), theme.pointOnCurve);
  legLabel(
    r,
    v,
    d.triangle,
    n,
    n,
    0,
    t("deCasteljau.pointLabel"),
    centre,
    theme.labelPoint,
    theme.pointOnCurve.radius * r.scale,
  );
}

/** The recurrence, the Bernstein form with the core's weights, the point (exact when it can be). */
export function formula(s, d) {
  const n = s.points.length - 1;
  const apex = 2 * levelStart(n, n);
  const x = d.triangle[apex];
  const y = d.triangle[apex + 1];
  const num = exactNumbers(s.t, s.points.flat());
  const weights = [];
  for (let i = 0; i <= n; i++)
    weights.push(`${num.value(d.sl.bernstein(n, i, s.t), n, true)}\\,P_{${i}}`);
  const approx =
    num.exact && (!Number.isInteger(x) || !Number.isInteger(y))
      ? `\\approx ${pointTex([x, y])}`
      : "";
  return [
    `p_i^{r} = (1-t)\\,p_i^{r-1} + t\\,p_{i+1}^{r-1},\\quad r = 1,\\dots,${n},\\quad t = ${num.param(true)}`,
    `P(t) = \\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,P_i = ${weights.join(" + ")}`,
    `P(${num.param(true)}) = p_0^{${n}} = ` +
      `\\left(${listTex([num.value(x, n, true), num.value(y, n, true)])}\\right) ${approx}`,
  ];
}

/** "cubic Bézier curve with 4 control points, t = 0.250, P(t) = (1.81, 1.44)". */
export function label(s, d) {
  const n = s.points.length - 1;
  const apex = 2 * levelStart(n, n);
  return t("deCasteljau.aria", {
    kind: degreeName(n),
    count: n + 1,
    t: fmt(s.t),
    x: fmt(d.triangle[apex], 2),
    y: fmt(d.triangle[apex + 1], 2),
  });
}

/** The table of the triangle: one row per level r, cells p_i^r (fraction and decimals). */
export function setup(ui) {
  const { title, table, wrap } = titledTable("de-casteljau");
  ui.ctx.slots.details.append(title, wrap);
  let degree = -1;
  let cells = [];

  function build(n) {
    degree = n;
    cells = [];
    const rows = [];
    for (let level = 0; level <= n; level++) {
      const row = [el("th", { scope: "row", text: t("deCasteljau.tableLevel", { r: level }) })];
      for (let i = 0; i <= n - level; i++) {
        const name =
          level === 0 ? `P${subscript(i)} = ` : `p${subscript(i)}${superscript(level)} = `;
        const spans = valueSpans();
        cells.push(spans);
        row.push(
          el(
            "td",
            { dataset: { level: String(level), index: String(i) } },
            el("span", { class: "sl-cell-name", text: name }),
            spans.exact,
            spans.decimal,
          ),
        );
      }
      rows.push(el("tr", {}, row));
    }
    table.replaceChildren(el("tbody", {}, rows));
  }

  return {
    update(s, d) {
      const n = s.points.length - 1;
      if (degree !== n) build(n);
      const num = exactNumbers(s.t, s.points.flat());
      setText(title, t("deCasteljau.tableCaption", { t: num.param() }));
      let k = 0;
      for (let level = 0; level <= n; level++) {
        for (let i = 0; i <= n - level; i++, k++) {
          const x = d.triangle[2 * k];
          const y = d.triangle[2 * k + 1];
          const decimals = pointText([x, y]);
          const exact = num.exact
            ? pointText([num.value(x, level), num.value(y, level)])
            : decimals;
          setValueSpans(cells[k], exact, decimals);
        }
      }
    },
  };
}
