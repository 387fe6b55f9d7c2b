/**
 * Demo (syllabus §3): knot vector types. One control polygon, three B-splines of the same degree
 * overlaid in distinct styles: clamped ("open") knots — uniform, chord-length or centripetal
 * interior spacing, from `knotVector(points, dim, p, kind)` —, unclamped uniform knots
 * (`knotVector(…, "uniform")`) and the closed curve of `BSplineCurve.closed`. The knot values
 * are listed for each, and each curve's end points are read back from the core (`evaluate`).
 *
 * Drags go through `setControlPoint` on every curve, in place. The one exception: chord and
 * centripetal knots are a function of the points, so that curve's knot vector changes with a
 * drag and the curve is rebuilt (once per applied move) — the core has no "set knots in place".
 */
import { field, checkNumber } from "../lib/validate.js";
import { slider, checkbox, choice, pointButtons, readout, group } from "../lib/panel.js";
import {
  fmt,
  degreeName,
  fmtTex,
  fmtMachine,
  listSeparator,
  pointText,
  texListSeparator,
  listTex,
  pointTex,
} from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { titledTable } from "../lib/table.js";
import { flatPath, pointsPath } from "../lib/draw.js";
import { el, setText } from "../lib/controls.js";
import { replaceOrReport } from "../lib/wasm.js";
import { errorText } from "../lib/core-errors.js";

export const id = "knot-vectors";
export const strings = "knotVectors";
export const section = 3;

/** Six integer points and a cubic: clamped knots 0 0 0 0 1 2 3 3 3 3 (syllabus §3 conventions). */
export const defaultState = Object.freeze({
  points: Object.freeze(
    [
      [0, 1],
      [2, 6],
      [7, 7],
      [11, 4],
      [9, 0],
      [4, -1],
    ].map(Object.freeze),
  ),
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

export const fields = {
  points: field.points({ min: MIN_POINTS, max: MAX_POINTS }),
  degree(s, name) {
    checkNumber(s, name, { min: 1, max: MAX_DEGREE, integer: true });
    const count = s.points.length;
    if (s.degree > count - 1)
      throw new Error(t("knotVectors.error.degree", { p: s.degree, count }));
  },
  spacing: field.choice(SPACINGS),
  clamped: field.boolean(),
  unclamped: field.boolean(),
  closed: field.boolean(),
};

/** The clamped curve: "clamped" (uniform interior), "chord" or "centripetal" knots. */
function clampedCurve(sl, s) {
  const flat = flatten(s.points);
  const kind = s.spacing === "uniform" ? "clamped" : s.spacing;
  return new sl.BSplineCurve(flat, 2, s.degree, sl.knotVector(flat, 2, s.degree, kind));
}

/** The three curves, in wasm. A drag moves them in place; chord and centripetal knots follow the points. */
export const derive = {
  from: ["points", "degree", "spacing"],
  build(s, sl) {
    const flat = flatten(s.points);
    const made = [];
    try {
      made.push(clampedCurve(sl, s));
      made.push(
        new sl.BSplineCurve(flat, 2, s.degree, sl.knotVector(flat, 2, s.degree, "uniform")),
      );
      made.push(sl.BSplineCurve.closed(flat, 2, s.degree));
    } catch (err) {
      for (const curve of made) curve.free();
      throw err;
    }
    // `refusal` holds a rebuild refused during a drag, for setup to say in the status line.
    return { curves: made, refusal: { message: null }, sl };
  },
  moved(m, i, xy, s) {
    // In place on every curve (the closed curve's repeated copy follows in the core).
    for (const curve of m.curves) curve.setControlPoint(i, xy);
    if (s.spacing === "uniform") return;
    // Chord/centripetal knots depend on the points: a new knot vector, so a new curve.
    try {
      const next = clampedCurve(m.sl, s);
      m.curves[0].free();
      m.curves[0] = next;
    } catch (err) {
      m.refusal.message = errorText(err);
    }
  },
};

/** What the core returns per curve: samples, knots, domain [a, b] and the end points C(a), C(b). */
export const compute = {
  shown: [
    ["points", "degree", "spacing"],
    (s, d) =>
      d.curves.map((curve) => {
        const [a, b] = curve.domain();
        const samples = curve.sampleUniform(CURVE_SAMPLES);
        return {
          samples,
          knots: Array.from(curve.knots()),
          a,
          b,
          start: curve.evaluate(a),
          end: curve.evaluate(b),
        };
      }),
  ],
};

/** Degree p (on release): 1 … min(MAX_DEGREE, n). */
function setDegree(ui, p) {
  const max = Math.min(MAX_DEGREE, ui.state.points.length - 1);
  if (p < 1 || p > max) return ui.status(t("knotVectors.degreeRange", { value: p, max }), "error");
  if (p !== ui.state.degree) replaceOrReport(ui, { ...ui.state, degree: p });
}

const showBox = (kind) =>
  checkbox(kind, { label: `knotVectors.show.${kind}`, name: `show-${kind}` });

export const controls = [
  group(
    null,
    slider("degree", {
      label: "knotVectors.control.degree",
      min: 1,
      max: MAX_DEGREE,
      step: 1,
      format: (v) => String(Math.round(v)),
      set: (ui, value, final) => final && setDegree(ui, Math.round(value)),
      error: (text, s) =>
        t("knotVectors.degreeRange", {
          value: text,
          max: Math.min(MAX_DEGREE, s.points.length - 1),
        }),
    }),
  ),
  group(
    "knotVectors.control.spacing",
    choice("spacing", {
      options: SPACINGS.map((value) => ({ value, label: `knotVectors.spacing.${value}` })),
      set: (ui, spacing) =>
        spacing !== ui.state.spacing && replaceOrReport(ui, { ...ui.state, spacing }),
    }),
  ),
  group("knotVectors.control.show", ...KINDS.map(showBox)),
  group(
    null,
    readout("degree", (s) => t("knotVectors.degree", { p: s.degree, count: s.points.length })),
    // Removing a point lowers the degree when it must (in the points' field check order).
    pointButtons("points", {
      min: MIN_POINTS,
      max: MAX_POINTS,
      prefix: strings,
      adjust: (s) => ({ ...s, degree: Math.min(s.degree, s.points.length - 1) }),
    }),
  ),
];

/** The legend's layout: label widths (measured by setup), swatch starts, the strip's height. */
function newLegend() {
  return {
    labels: KINDS.map((kind) => t(`knotVectors.legend.${kind}`)),
    widths: new Float64Array(KINDS.length),
    at: new Float64Array(2 * KINDS.length),
    insets: [0, 0, 0, 0],
  };
}

/**
 * Flows the shown legend entries into rows across a canvas `width` CSS px wide; writes their
 * positions to `legend.at` and returns the height taken (CSS px).
 */
function layoutLegend(legend, s, width, scale) {
  let x = LEGEND_MARGIN * scale;
  let y = (LEGEND_MARGIN + LEGEND_LINE / 2) * scale;
  let any = false;
  for (let c = 0; c < KINDS.length; c++) {
    if (!s[KINDS[c]]) continue;
    const w = (LEGEND_SWATCH + LEGEND_GAP + legend.widths[c]) * scale;
    if (any && x + w > width - LEGEND_MARGIN * scale) {
      x = LEGEND_MARGIN * scale;
      y += LEGEND_LINE * scale;
    }
    legend.at[2 * c] = x;
    legend.at[2 * c + 1] = y;
    x += w + LEGEND_SPACING * scale;
    any = true;
  }
  return any ? y + (LEGEND_LINE / 2 + LEGEND_MARGIN / 2) * scale : 0;
}

export const figure = {
  bounds: (s) => boundsOf(s.points),
  /** The legend's strip above the world window. */
  insets(width, height, scale, s, d) {
    if (!d.legend) return [0, 0, 0, 0];
    d.legend.insets[0] = layoutLegend(d.legend, s, width, scale);
    return d.legend.insets;
  },
  handles: { field: "points" },
};

/** The polygon (closed when the closed curve is shown), the curves back to front, their ends, the legend. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const pts = s.points;
  pointsPath(r, v, pts);
  if (s.closed) r.lineTo(v.sx(pts[0][0]), v.sy(pts[0][1]));
  r.paint(theme.polygon);
  for (let c = KINDS.length - 1; c >= 0; c--) {
    if (!s[KINDS[c]]) continue;
    flatPath(r, v, d.shown[c].samples, 0, CURVE_SAMPLES);
    r.paint(theme.compareCurve[c]);
  }
  for (let c = 0; c < KINDS.length; c++) {
    if (!s[KINDS[c]]) continue;
    const { start, end } = d.shown[c];
    r.point(v.sx(start[0]), v.sy(start[1]), theme.comparePoint[c]);
    r.point(v.sx(end[0]), v.sy(end[1]), theme.comparePoint[c]);
  }
  d.handles.draw(r, v);

  // The legend, in the strip above the figure: a stretch of each curve's style and its name.
  const sc = r.scale;
  const bottom = layoutLegend(d.legend, s, r.width, sc);
  for (let c = 0; c < KINDS.length; c++) {
    if (!s[KINDS[c]]) continue;
    const x = d.legend.at[2 * c];
    const y = d.legend.at[2 * c + 1];
    r.beginPath();
    r.moveTo(x, y);
    r.lineTo(x + LEGEND_SWATCH * sc, y);
    r.paint(theme.compareCurve[c]);
    r.text(
      d.legend.labels[c],
      x + (LEGEND_SWATCH + LEGEND_GAP) * sc,
      y,
      theme.labelSmall,
      "left",
      "middle",
    );
  }
  if (bottom > 0) {
    r.beginPath();
    r.moveTo(0, bottom);
    r.lineTo(r.width, bottom);
    r.paint(theme.helper);
  }
}

/** A knot as short text (TeX with `tex`): integers plain, else 3 decimals. */
function knotText(x, tex = false) {
  return Number.isInteger(x) ? String(x) : tex ? fmtTex(x) : fmt(x);
}

/** A point as "(x, y)" with integers plain (TeX with `tex`). */
function pointLabel(x, y, tex = false) {
  const [a, b] = [x, y].map((v) => knotText(Number(fmtMachine(v)), tex));
  return tex ? pointTex([a, b]) : pointText([a, b]);
}

const tex = (key) => `\\text{${t(`knotVectors.tex.${key}`)}}`;

/** Each knot vector written out with its live values; where the clamped and unclamped curves start. */
export function formula(s, d) {
  const pts = s.points;
  const n = pts.length - 1;
  const p = s.degree;
  const lines = [];
  if (s.spacing === "uniform") {
    const ends = (value) => `\\underbrace{${value},\\dots,${value}}_{p+1}`;
    lines.push(`U_{${tex("clamped")}} = (${ends(0)},\\ 1,\\dots,n-p,\\ ${ends("n-p+1")})`);
  } else {
    // The legs of the control polygon, from the points (display of the formula's numbers).
    const legs = [];
    for (let i = 0; i < n - p + 1; i++) {
      const length = Math.hypot(pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1]);
      const term = s.spacing === "chord" ? length : Math.sqrt(length);
      legs.push(Number.isInteger(term) ? String(term) : fmtTex(term));
    }
    const leg = s.spacing === "chord" ? "|P_{i+1}-P_i|" : "|P_{i+1}-P_i|^{1/2}";
    const range = `(j = 1,\\dots,${n - p + 1};\\ ${tex("lastRepeated")})`;
    const sum = `u_{p+j} = \\sum_{i=0}^{j-1} ${leg}`;
    lines.push(`U_{${tex(s.spacing)}}:\\ u_0 = \\dots = u_{p} = 0,\\quad ${sum}\\ \\ ${range}`);
    lines.push(`${tex("legs")}\\ ${legs.join(texListSeparator())}`);
  }
  lines.push(
    `\\phantom{U} = (${d.shown[0].knots.map((u) => knotText(u, true)).join(texListSeparator("\\,"))}),\\quad n = ${n},\\ p = ${p}`,
  );
  const domain = `${tex("domain")}\\ [u_{${p}}, u_{${n + 1}}] = [${listTex([String(p), String(n + 1)], 0, " ")}]`;
  lines.push(
    `U_{${tex("unclamped")}}:\\ u_i = i,\\ i = 0,\\dots,n+p+1 = ${n + p + 1};\\quad ${domain}`,
  );
  const closedKnots = `u_i = i,\\ i = 0,\\dots,${n + 2 * p + 1}`;
  const closedPoints = `P_0,\\dots,P_{${n}},\\,P_0,\\dots,P_{${p - 1}}`;
  lines.push(
    `U_{${tex("closed")}}:\\ ${closedPoints};\\ ${closedKnots};\\quad C^{${p - 1}}\\ ${tex("seam")}`,
  );
  const { c0, u0, p0 } = starts(s, d, true);
  const clampedStart = `C_{${tex("clamped")}}(u_{${p}}) = ${c0} ${c0 === p0 ? "= P_0" : "\\ne P_0"}`;
  lines.push(
    `${clampedStart},\\qquad C_{${tex("unclamped")}}(u_{${p}}) = ${u0} ${u0 === p0 ? "= P_0" : "\\ne P_0"}`,
  );
  return lines;
}

/** Start points of the clamped and unclamped curves, and P₀, as text (TeX with `tex`). */
function starts(s, d, tex = false) {
  const [c, u] = d.shown;
  const [x0, y0] = s.points[0];
  return {
    c0: pointLabel(c.start[0], c.start[1], tex),
    u0: pointLabel(u.start[0], u.start[1], tex),
    p0: pointLabel(x0, y0, tex),
  };
}

/** "cubic B-splines with 6 control points; clamped knots …; the clamped curve starts at …". */
export function label(s, d) {
  const clamped = d.shown[0].knots.map((u) => knotText(u)).join(" ");
  return t("knotVectors.aria", {
    kind: degreeName(s.degree),
    count: s.points.length,
    clamped,
    ...starts(s, d),
  });
}

/**
 * The figure's 3:2 shape (the legend takes a strip at the top), the legend's measured labels,
 * and the table: knots, domain and end points of each curve, from the core.
 */
export function setup(ui) {
  // A taller figure than the default 16:10.
  ui.ctx.slots.figure.style.aspectRatio = "3 / 2";
  const legend = (ui.data.legend = newLegend());
  const { title, table, wrap } = titledTable("knot-vectors", {
    caption: t("knotVectors.tableCaption"),
  });
  const rows = KINDS.map((kind, index) => {
    const cells = {};
    for (const key of ["knots", "domain", "start", "end"])
      cells[key] = el("td", { dataset: { cell: key } });
    const name = el("span", { class: "sl-cell-name", text: legend.labels[index] });
    const row = el(
      "tr",
      { dataset: { curve: kind } },
      el(
        "th",
        { scope: "row" },
        name,
        el("span", { class: "sl-cell-decimal", text: t(`knotVectors.style.${kind}`) }),
      ),
      cells.knots,
      cells.domain,
      cells.start,
      cells.end,
    );
    return { row, cells, name };
  });
  const column = (key) => el("th", { scope: "col", text: t(`knotVectors.column.${key}`) });
  const columns = ["curve", "knots", "domain", "start", "end"].map(column);
  table.append(
    el("thead", {}, el("tr", {}, columns)),
    el(
      "tbody",
      {},
      rows.map((r) => r.row),
    ),
  );
  ui.ctx.slots.details.append(title, wrap);

  return {
    update(s, d) {
      if (d.refusal.message) {
        ui.status(t("status.rejected", { message: d.refusal.message }), "error");
        d.refusal.message = null;
      }
      const first = t(`knotVectors.legend.clamped.${s.spacing}`);
      if (legend.labels[0] !== first || legend.widths[0] === 0) {
        legend.labels[0] = first;
        const r = ui.view.renderer;
        legend.labels.forEach(
          (text, c) => (legend.widths[c] = r.measure(text, r.theme.labelSmall) / r.scale),
        );
      }
      setText(rows[0].name, legend.labels[0]);
      const p0 = s.points[0];
      rows.forEach(({ row, cells }, c) => {
        const { knots, a, b, start, end } = d.shown[c];
        setText(cells.knots, knots.map((u) => knotText(u)).join(" "));
        setText(cells.domain, `[${knotText(a)}${listSeparator()}${knotText(b)}]`);
        setText(cells.start, pointLabel(start[0], start[1]));
        setText(cells.end, pointLabel(end[0], end[1]));
        row.dataset.start = `${fmtMachine(start[0])},${fmtMachine(start[1])}`;
        row.dataset.end = `${fmtMachine(end[0])},${fmtMachine(end[1])}`;
        row.dataset.startIsP0 = String(Math.hypot(start[0] - p0[0], start[1] - p0[1]) < 1e-9);
      });
    },
  };
}
