/**
 * Demo (syllabus §1): a curve typed piece by piece, P(t) = P_i(t) = (x_i(t), y_i(t)) for t in
 * [a_i, a_{i+1}), and what happens at each joint t = a_i. With one-sided limits
 *
 *   C^k:  P^{(j)}(a⁻) = P^{(j)}(a⁺) for j = 0 … k,
 *   G^k:  the same after a change of parameter on one side (G¹: P′(a⁻) = λ P′(a⁺), λ > 0),
 *
 * the core's `parametricCurve(pieces).joints()` gives per joint the largest k ≤ 3 with C^k and
 * G^k (−1: the pieces do not meet; Infinity: one polynomial on both sides), whether that is
 * proven in exact arithmetic (polynomial pieces with exact coefficients), and the first order
 * that differs. The one-sided values P^{(j)}(a⁻), P^{(j)}(a⁺) come from each piece on its own
 * closed interval (`parametricCurve([piece]).derivative(a, j)`), so neither side is a limit
 * guessed in JS. Each piece is drawn from its own `plot(tolerance, box)` (runs split at NaN).
 *
 * The notes' exercise: x = 1 − t² on [0, 1), then on [1, 2] x = 2 − t² (not C⁰),
 * t² − 4t + 3 (C¹: x′(1) = −2 on both sides, x″ jumps from −2 to 2) or t² − 2t + 1 (C⁰,
 * x′ jumps from −2 to 0); y = t throughout. A fourth case runs the same parabola at double
 * speed on [1, 3/2]: G¹ (indeed the same shape) but P′ doubles, so only C⁰.
 */
import { actions, group, readout } from "../lib/panel.js";
import { el, setText } from "../lib/controls.js";
import { exactText, shortNumber } from "../lib/format.js";
import { orderText, orderTex } from "../lib/continuity.js";
import { placeLabel, placeLabelBeside } from "../lib/handles.js";
import { CYCLE, WIDTH, RADIUS, themed } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { arrow } from "../lib/draw.js";
import { detailsTable, headerRow } from "../lib/table.js";
import { pieceFields } from "../lib/piece-fields.js";

export const id = "piecewise";
export const strings = "piecewise";
export const section = 1;

/** The fields of a piece, in the order of the panel and of the `pieces` attribute. */
export const PIECE_FIELDS = Object.freeze(["x", "y", "from", "to"]);
/** Fewest and most pieces. */
export const MIN_PIECES = 1;
export const MAX_PIECES = 6;
/** The longest text of a field (the parser's MAX_LENGTH). */
const MAX_TEXT = 1000;

const piece = (x, y, from, to) => Object.freeze({ x, y, from, to });
const FIRST = piece("1 - t^2", "t", "0", "1");

/** The notes' exercise (three cases) and the G¹-not-C¹ case: the same first piece. */
export const PRESETS = Object.freeze({
  notC0: Object.freeze([FIRST, piece("2 - t^2", "t", "1", "2")]),
  c1: Object.freeze([FIRST, piece("t^2 - 4t + 3", "t", "1", "2")]),
  c0: Object.freeze([FIRST, piece("t^2 - 2t + 1", "t", "1", "2")]),
  g1: Object.freeze([FIRST, piece("1 - (2t - 1)^2", "2t - 1", "1", "1.5")]),
});

export const defaultState = Object.freeze({ pieces: PRESETS.c1 });

/** `pieces`: 1 … MAX_PIECES records `{ x, y, from, to }` of texts (the core parses them). */
export const fields = {
  pieces(s, name) {
    const list = s[name];
    if (!Array.isArray(list)) throw new Error(t("error.notArray", { field: name }));
    if (list.length < MIN_PIECES || list.length > MAX_PIECES)
      throw new Error(
        t("error.count", { field: name, min: MIN_PIECES, max: MAX_PIECES, count: list.length }),
      );
    list.forEach((p, index) => {
      const ok =
        p !== null &&
        typeof p === "object" &&
        !Array.isArray(p) &&
        Object.keys(p).length === PIECE_FIELDS.length &&
        PIECE_FIELDS.every((f) => typeof p[f] === "string" && p[f].length <= MAX_TEXT);
      if (!ok) throw new Error(t("piecewise.badPiece", { field: name, index: index + 1 }));
    });
  },
};

/**
 * The model: the whole curve (joints, TeX) and each piece alone on its closed interval (its
 * plot and its one-sided values at the joints). A text the core refuses throws here, before
 * anything changes.
 */
export const derive = {
  from: ["pieces"],
  build(s, sl) {
    const curve = sl.parametricCurve(s.pieces);
    const parts = [];
    try {
      for (const p of s.pieces) parts.push(sl.parametricCurve([p]));
    } catch (err) {
      curve.free();
      for (const part of parts) part.free();
      throw err;
    }
    return { curve, parts };
  },
};

// ------------------------------------------------------------ what the core returns

/** Samples per piece for the figure's box; the plot's tolerance and margin relative to it. */
const BOX_SAMPLES = 256;
const TOLERANCE_FRACTION = 1e-3;
const PLOT_MARGIN = 1;
/** A range wider than this many times the 5–95 % spread has a pole: the box keeps the spread. */
const POLE_SPREAD = 20;
/** The longest velocity arrow is this fraction of the box's diagonal. */
const ARROW_FRACTION = 0.22;

/** The box of the finite samples (a pole's far values left out), never empty. */
function boxOf(samples) {
  const xs = [];
  const ys = [];
  for (const flat of samples) {
    for (let k = 0; k + 1 < flat.length; k += 2) {
      if (Number.isFinite(flat[k]) && Number.isFinite(flat[k + 1])) {
        xs.push(flat[k]);
        ys.push(flat[k + 1]);
      }
    }
  }
  if (xs.length === 0) return [-1, -1, 1, 1];
  const range = (v) => {
    v.sort((a, b) => a - b);
    const lo = v[Math.floor(0.05 * (v.length - 1))];
    const hi = v[Math.ceil(0.95 * (v.length - 1))];
    const spread = hi - lo;
    return v[v.length - 1] - v[0] > POLE_SPREAD * spread && spread > 0
      ? [lo - spread, hi + spread]
      : [v[0], v[v.length - 1]];
  };
  let [x0, x1] = range(xs);
  let [y0, y1] = range(ys);
  const size = Math.max(x1 - x0, y1 - y0, 1e-9);
  if (x1 - x0 < 1e-3 * size || x1 === x0) [x0, x1] = [x0 - size / 2 || -1, x1 + size / 2 || 1];
  if (y1 - y0 < 1e-3 * size || y1 === y0) [y0, y1] = [y0 - size / 2 || -1, y1 + size / 2 || 1];
  return [x0, y0, x1, y1];
}

/** Each piece's plot (the core's adaptive polyline, runs split at NaN) and the box shown. */
function plotPieces(d) {
  const box = boxOf(d.parts.map((part) => part.sampleUniform(BOX_SAMPLES)));
  const w = box[2] - box[0];
  const h = box[3] - box[1];
  const tolerance = TOLERANCE_FRACTION * Math.hypot(w, h);
  const wide = [box[0] - PLOT_MARGIN * w, box[1] - PLOT_MARGIN * h];
  wide.push(box[2] + PLOT_MARGIN * w, box[3] + PLOT_MARGIN * h);
  const plots = d.parts.map((part) => part.plot(tolerance, wide));
  return {
    box,
    points: plots.map((p) => p.points),
    complete: plots.every((p) => p.complete),
    labels: d.parts.map((_, i) => `P${subscriptNumber(i + 1)}`),
  };
}

const subscriptNumber = (n) => String(n).replace(/\d/g, (c) => "₀₁₂₃₄₅₆₇₈₉"[c]);

/** The highest derivative order listed per joint (0 … K: position, velocity, …). */
function shownOrder(joint) {
  if (Number.isInteger(joint.order)) return Math.min(3, Math.max(2, joint.order));
  return joint.c === Infinity ? 2 : Math.min(3, Math.max(2, joint.c));
}

/** The core's value of piece `part` at its end `t`: P (k = 0) or P^{(k)}. */
const valueAt = (part, tt, k) => (k === 0 ? part.evaluate(tt) : part.derivative(tt, k));

/**
 * Per joint: the core's verdict `{ t, c, g, exact, order }`, the one-sided values
 * `left[k]`, `right[k]` (k = 0 … K) from the two pieces on their closed intervals, and texts.
 */
function jointsOf(d) {
  return Array.from(d.curve.joints(), (j, i) => {
    const a = d.parts[i].pieceDomain(0)[1];
    const b = d.parts[i + 1].pieceDomain(0)[0];
    const top = shownOrder(j);
    const left = [];
    const right = [];
    for (let k = 0; k <= top; k++) {
      left.push(valueAt(d.parts[i], a, k));
      right.push(valueAt(d.parts[i + 1], b, k));
    }
    const verdict = verdictText(j);
    const how = t(j.exact ? "piecewise.proven" : "piecewise.measured");
    return {
      t: j.t,
      c: j.c,
      g: j.g,
      exact: Boolean(j.exact),
      order: Number.isInteger(j.order) ? j.order : null,
      left,
      right,
      verdict,
      how,
      text: t("piecewise.joint", { t: shortNumber(j.t), verdict }),
      figureLabel: `${verdict} (${t(j.exact ? "piecewise.formula.proven" : "piecewise.formula.measured")})`,
    };
  });
}

/** "C¹, G¹", or the break / one-polynomial words. */
function verdictText(j) {
  if (j.c < 0) return t("piecewise.verdict.broken");
  if (j.c === Infinity) return t("piecewise.verdict.infinite");
  return t("piecewise.verdict", { c: orderText("C", j.c), g: orderText("G", j.g) });
}

/** One scale for every velocity arrow (world units per unit of speed): speeds compare. */
function arrowScale(d) {
  let fastest = 0;
  for (const j of d.joints) {
    for (const v of [j.left[1], j.right[1]]) {
      const speed = Math.hypot(v[0], v[1]);
      if (Number.isFinite(speed)) fastest = Math.max(fastest, speed);
    }
  }
  const [x0, y0, x1, y1] = d.shape.box;
  return fastest > 0 ? (ARROW_FRACTION * Math.hypot(x1 - x0, y1 - y0)) / fastest : 0;
}

export const compute = {
  shape: [["pieces"], (s, d) => plotPieces(d)],
  joints: [["pieces"], (s, d) => jointsOf(d)],
  arrowScale: [["pieces"], (s, d) => arrowScale(d)],
};

// ------------------------------------------------------------ the panel

/** A new last piece: the last one's formulas on an interval as long, starting where it ends. */
function addedPiece(s, d) {
  const last = s.pieces[s.pieces.length - 1];
  const [a, b] = d.parts[d.parts.length - 1].pieceDomain(0);
  const end = Number((2 * b - a).toFixed(6));
  return { x: last.x, y: last.y, from: last.to, to: String(end) };
}

const preset = (key) => ({
  name: `preset-${key}`,
  label: `piecewise.preset.${key}`,
  title: "piecewise.preset.title",
  run: (ui) => {
    ui.replace({ ...ui.state, pieces: structuredClone(PRESETS[key]) });
    ui.fit();
  },
});

export const controls = [
  group(
    "piecewise.pieces",
    pieceFields("pieces", {
      prefix: "piecewise",
      names: PIECE_FIELDS,
      min: MIN_PIECES,
      max: MAX_PIECES,
      added: addedPiece,
    }),
  ),
  actions(["notC0", "c1", "c0", "g1"].map(preset), { title: "piecewise.presets" }),
  group(
    "piecewise.jointsLegend",
    readout(
      "joints",
      (s, d) =>
        d.joints.length === 0
          ? t("piecewise.noJoints")
          : d.joints.map((j) => `${j.text} · ${j.how}`).join("\n"),
      {
        kind: "readout",
        live: true,
        data: (s, d) => ({
          verdicts: d.joints.map((j) => `${j.c},${j.g},${j.exact}`).join(";"),
        }),
      },
    ),
    readout("complete", (s, d) => (d.shape.complete ? "" : t("piecewise.incomplete"))),
  ),
];

export const figure = {
  bounds: (s, d) => {
    const [x0, y0, x1, y1] = d.shape.box;
    const padX = 0.12 * (x1 - x0);
    const padY = 0.12 * (y1 - y0);
    return [x0 - padX, y0 - padY, x1 + padX, y1 + padY];
  },
};

// ------------------------------------------------------------ drawing

const pieceStyles = Object.freeze(
  CYCLE.map((stroke) => Object.freeze({ stroke, width: WIDTH.curve, join: "round", cap: "round" })),
);
const arrowStyles = Object.freeze(
  CYCLE.map((stroke, k) =>
    Object.freeze({ stroke, width: k % 2 === 0 ? 4 : 2, cap: "round", join: "round" }),
  ),
);
const endStyles = Object.freeze(
  CYCLE.map((fill) => Object.freeze({ fill, radius: RADIUS.constructionPoint + 1 })),
);
const jointStyles = themed((theme) => ({
  text: Object.freeze({ ...theme.label, weight: "bold" }),
  point: Object.freeze({
    fill: theme.background,
    stroke: theme.name === "dark" ? "#EEEEEE" : "#222222",
    width: 1.5,
    radius: RADIUS.pointOnCurve,
  }),
}));
/** Distance of a joint's verdict from its arrow (CSS px). */
const VERDICT_OFFSET_PX = 16;
const LABEL_OFFSET_PX = 10;

/** The runs of a flat polyline with NaN vertices between them, as one path. */
function runsPath(r, v, flat) {
  r.beginPath();
  let open = false;
  for (let k = 0; k + 1 < flat.length; k += 2) {
    const x = flat[k];
    const y = flat[k + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      open = false;
      continue;
    }
    if (open) r.lineTo(v.sx(x), v.sy(y));
    else r.moveTo(v.sx(x), v.sy(y));
    open = true;
  }
}

/** A finite vertex near the middle of a flat polyline (a piece's name goes there), or -1. */
function middleVertex(flat) {
  const n = flat.length / 2;
  for (let step = 0; step < n; step++) {
    for (const k of [Math.floor(n / 2) + step, Math.floor(n / 2) - step]) {
      if (k >= 0 && k < n && Number.isFinite(flat[2 * k]) && Number.isFinite(flat[2 * k + 1]))
        return k;
    }
  }
  return -1;
}

/** Each piece in its colour and named; at each joint the ends, the velocities and the verdict. */
export function draw(r, v, s, d) {
  const theme = r.theme;
  const { points, labels } = d.shape;
  for (let i = 0; i < points.length; i++) {
    runsPath(r, v, points[i]);
    r.paint(pieceStyles[i % CYCLE.length]);
  }
  for (let i = 0; i < points.length; i++) {
    const k = middleVertex(points[i]);
    if (k < 0) continue;
    const x = v.sx(points[i][2 * k]);
    const y = v.sy(points[i][2 * k + 1]);
    placeLabel(r, labels[i], x, y, -0.7, -0.7, LABEL_OFFSET_PX * r.scale, jointStyles(theme).text);
  }
  const scale = d.arrowScale;
  d.joints.forEach((j, i) => {
    const p = j.left[0];
    const q = j.right[0];
    const px = v.sx(p[0]);
    const py = v.sy(p[1]);
    const qx = v.sx(q[0]);
    const qy = v.sy(q[1]);
    const finite = Number.isFinite(px + py + qx + qy);
    if (finite && j.c < 0) {
      r.beginPath();
      r.moveTo(px, py);
      r.lineTo(qx, qy);
      r.paint(theme.helper);
    }
    // Velocities: P′(a⁻) arriving at the left end, P′(a⁺) leaving the right end.
    const a = j.left[1];
    const b = j.right[1];
    const lx = a[0] * scale * v.scale;
    const ly = -a[1] * scale * v.scale;
    const rx = b[0] * scale * v.scale;
    const ry = -b[1] * scale * v.scale;
    if (Number.isFinite(lx + ly + px + py)) arrow(r, px - lx, py - ly, px, py, arrowStyles[i % 4]);
    if (Number.isFinite(rx + ry + qx + qy))
      arrow(r, qx, qy, qx + rx, qy + ry, arrowStyles[(i + 1) % 4]);
    if (!finite) return;
    if (j.c < 0) {
      r.point(px, py, endStyles[i % CYCLE.length]);
      r.point(qx, qy, endStyles[(i + 1) % CYCLE.length]);
    } else {
      r.point(qx, qy, jointStyles(theme).point);
    }
    const dx = Number.isFinite(rx + ry) && Math.hypot(rx, ry) > 1 ? rx : 1;
    const dy = Number.isFinite(rx + ry) && Math.hypot(rx, ry) > 1 ? ry : 0;
    placeLabelBeside(
      r,
      j.figureLabel,
      qx,
      qy,
      dx,
      dy,
      -1,
      VERDICT_OFFSET_PX * r.scale,
      jointStyles(theme).text,
    );
  });
}

// ------------------------------------------------------------ formula, label, table

const PRIMES = Object.freeze(["", "'", "''", "'''"]);
const PRIME_TEXT = Object.freeze(["", "′", "″", "‴"]);

/** (x, y) in TeX; an undefined value as a word. */
function pairTex(p) {
  if (!Number.isFinite(p[0]) || !Number.isFinite(p[1]))
    return `\\text{${t("piecewise.undefined")}}`;
  return `\\left(${shortNumber(p[0], true)},\\ ${shortNumber(p[1], true)}\\right)`;
}

/** The core's TeX of piece i (its formulas and first derivatives), or the typed text. */
function pieceTex(s, d, i) {
  const n = s.pieces.length;
  const close = i === n - 1 ? "]" : ")";
  let tex = null;
  try {
    tex = d.curve.tex(i);
  } catch {
    tex = null;
  }
  const texOf = (f, key) => tex?.[f]?.[key] ?? null;
  const raw = (f) => `\\texttt{${s.pieces[i][f].replace(/[\\{}$&#^_%~]/g, "")}}`;
  const k = i + 1;
  const lines = [
    `P_{${k}}(t) = \\left(${texOf("x", "expr") ?? raw("x")},\\ ${texOf("y", "expr") ?? raw("y")}\\right),\\quad ` +
      `t \\in [${tex?.from ?? raw("from")},\\ ${tex?.to ?? raw("to")}${close}`,
  ];
  const dx = texOf("x", "d1");
  const dy = texOf("y", "d1");
  if (dx !== null && dy !== null) lines.push(`P_{${k}}'(t) = \\left(${dx},\\ ${dy}\\right)`);
  return lines;
}

/** Each piece's formula and velocity, then per joint the one-sided values and the verdict. */
export function formula(s, d) {
  const lines = [];
  for (let i = 0; i < s.pieces.length; i++) lines.push(...pieceTex(s, d, i));
  d.joints.forEach((j, i) => {
    const at = shortNumber(j.t, true);
    const terms = [];
    for (let k = 0; k < j.left.length && k <= Math.max(1, Math.min(j.order ?? 1, 2)); k++) {
      const same = k <= j.c;
      terms.push(
        `P_{${i + 1}}${PRIMES[k]}({${at}}^{-}) = ${pairTex(j.left[k])} ` +
          `${same ? "=" : "\\neq"} P_{${i + 2}}${PRIMES[k]}({${at}}^{+}) = ${pairTex(j.right[k])}`,
      );
    }
    lines.push(...terms);
    const found =
      j.c < 0
        ? `\\text{${t("piecewise.formula.notC0")}}`
        : j.c === Infinity
          ? orderTex("C", Infinity)
          : `${orderTex("C", j.c)},\\ ${orderTex("G", j.g)}`;
    const how = t(j.exact ? "piecewise.formula.proven" : "piecewise.formula.measured");
    lines.push(
      `\\text{${t("piecewise.formula.joint")}}\\ t = ${at}:\\ ${found}\\ \\ (\\text{${how}})`,
    );
  });
  return lines;
}

export function label(s, d) {
  if (d.joints.length === 0) return t("piecewise.ariaNoJoints");
  return t("piecewise.aria", {
    count: s.pieces.length,
    joints: d.joints.map((j) => `${j.text}, ${j.how}`).join("; "),
  });
}

/** Text of a one-sided value: exact-looking numbers, or the undefined word. */
const valueText = (x) => (Number.isFinite(x) ? exactText(x) : t("piecewise.undefined"));

/** Do two one-sided values agree (the core's verdict for orders ≤ c, else the numbers)? */
function agree(j, k, a, b) {
  if (k <= j.c) return true;
  const scale = 1 + Math.max(Math.abs(a), Math.abs(b));
  return Number.isFinite(a) && Number.isFinite(b) && Math.abs(a - b) <= 1e-9 * scale;
}

/** Per joint a table: x, y and their derivatives from each side, which agree, the first that differs. */
export function setup(ui) {
  const tables = [];
  function tableFor(k, shape) {
    while (tables.length <= k) {
      tables.push(
        detailsTable(ui, "joint", (rowsKey, table) => {
          const [count] = rowsKey.split(":").map(Number);
          const body = el("tbody");
          const cells = [];
          for (let r = 0; r < count; r++) {
            const row = {
              name: el("th", { scope: "row" }),
              left: el("td", { dataset: { side: "left" } }),
              right: el("td", { dataset: { side: "right" } }),
              agree: el("td", { dataset: { cell: "agree" } }),
            };
            row.tr = el("tr", {}, row.name, row.left, row.right, row.agree);
            cells.push(row);
            body.append(row.tr);
          }
          table.replaceChildren(
            el("thead", {}, headerRow("piecewise.col.", ["quantity", "left", "right", "agree"])),
            body,
          );
          return cells;
        }),
      );
    }
    return tables[k].cellsFor(shape);
  }
  return {
    update(s, d) {
      d.joints.forEach((j, n) => {
        const count = j.left.length * 2;
        const cells = tableFor(n, `${count}:${n}`);
        const table = tables[n];
        table.table.hidden = false;
        table.title.hidden = false;
        table.table.dataset.joint = String(n);
        setText(
          table.title,
          t("piecewise.tableCaption", { t: shortNumber(j.t), verdict: j.verdict, how: j.how }),
        );
        const at = shortNumber(j.t);
        for (let k = 0; k < j.left.length; k++) {
          for (let c = 0; c < 2; c++) {
            const row = cells[2 * k + c];
            const name = `${"xy"[c]}${PRIME_TEXT[k]}`;
            setText(row.name, name);
            setText(row.left, `${name}(${at}⁻) = ${valueText(j.left[k][c])}`);
            setText(row.right, `${name}(${at}⁺) = ${valueText(j.right[k][c])}`);
            const same = agree(j, k, j.left[k][c], j.right[k][c]);
            setText(row.agree, t(same ? "piecewise.agree.yes" : "piecewise.agree.no"));
            row.tr.classList.toggle("sl-highlight", k === j.order);
            row.tr.dataset.order = String(k);
          }
        }
      });
      for (let n = d.joints.length; n < tables.length; n++) {
        tables[n].table.hidden = true;
        tables[n].title.hidden = true;
      }
    },
  };
}
