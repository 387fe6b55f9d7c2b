/**
 * Demo (syllabus §1 "Parametric curves", issue 24): a curve typed as formulas x(t), y(t) and
 * optionally z(t) on an interval [a, b] whose ends are formulas too ("2pi"). The curve library
 * parses and differentiates the texts (`sl.parametricCurve`); every other name in them
 * (`sl.expressionNames`) is a parameter with a slider, its value in the state and set in place
 * (`setParameter`). The point P(t) runs along the curve (player) with its velocity P′(t) and
 * acceleration P″(t), the speed |P′|, the curvature κ and the osculating circle; the hodograph
 * (the curve of velocities) is drawn from a draggable origin O beside it, as in derivatives.js.
 * The curve is the core's adaptive plot (`plot(tolerance, box)`: runs split where the curve is
 * undefined or jumps, e.g. at the poles of tan t).
 *
 * A space curve (z given) is shown in the 3D figure (`figure3d`: orbit, pan, zoom, the camera
 * in the link): the plot's runs and the osculating circle as scene curves, the Frenet frame
 * T, N, B from the core (`frame(t)`) at P(t), and the torsion τ. `dimension(state)` tells the
 * runtime which figure a state needs; it makes the figure anew when that changes.
 *
 * A polynomial curve offers its exact Bézier form (`toBezier(0)`, `bezierFractions(0)`): the
 * control polygon on the same figure, the fractions listed, and a link into de-casteljau.
 */
import { field } from "../lib/validate.js";
import { slider, checkbox, readout, group, actions, shownWhen } from "../lib/panel.js";
import {
  fmt,
  fmtTex,
  fmtMachine,
  localeDecimal,
  pointTex,
  shortNumber,
  texDecimal,
} from "../lib/format.js";
import { t } from "../lib/strings.js";
import { errorText } from "../lib/core-errors.js";
import { formulaFields, infoLine, parameterSliders } from "../lib/expression-fields.js";
import {
  TEXTS,
  WITH_PARAMS,
  curveOf,
  isSpaceState,
  paramsField,
  textField,
  withPreset,
  withTexts,
} from "../lib/typed-curve.js";
import { originBeside, planeBounds, wholeCurve } from "../lib/hodograph.js";
import { bezierFormOf, bezierList, deCasteljauLink } from "../lib/bezier-form.js";
import { drawPlaneFigure } from "../lib/curve-figure.js";
import { drawSpaceLayer, osculatingCircle, spaceBounds, spaceScene } from "../lib/curve-space.js";
import { addPlotPicker } from "../lib/plot-picker.js";
import { plotRuns } from "../lib/curve-view.js";
import { PRESETS } from "./presets/parametric-curve.js";

export const id = "parametric-curve";
export const strings = "parametricCurve";
export const section = 1;

/** The osculating circle is left out beyond a radius of this many curve sizes (κ ≈ 0). */
const STRAIGHT_RADIUS_FACTOR = 1e4;
/** Below this speed (relative to the curve's size) P′ = 0: a cusp. */
const CUSP_SPEED = 1e-12;

/** The circle x = cos t, y = sin t on [0, 2π] (syllabus §1), its hodograph to the right. */
export const defaultState = Object.freeze({
  x: "cos(t)",
  y: "sin(t)",
  z: "",
  from: "0",
  to: "2pi",
  params: Object.freeze({}),
  t: 1,
  bezier: false,
  hodograph: Object.freeze([Object.freeze([2.1, 0])]),
});

export const fields = {
  x: textField(strings),
  y: textField(strings),
  z: textField(strings),
  from: textField(strings),
  to: textField(strings),
  params: paramsField(strings),
  t: field.number({ min: -1e9, max: 1e9 }),
  bezier: field.boolean(),
  hodograph: field.points({ min: 1, max: 1 }),
};

/** A plane curve in the 2D figure (with its hodograph), a space curve in the 3D one. */
export const dimension = (s) => (isSpaceState(s) ? 3 : 2);

/** The curve in wasm; a parameter's slider sets it in place. */
export const derive = {
  from: TEXTS,
  build(s, sl, { first = false } = {}) {
    const { curve, params } = curveOf(sl, s);
    s.params = params;
    const domain = curve.domain();
    s.t = Math.min(Math.max(s.t, domain[0]), domain[1]);
    // A page or embed that gives another curve but no O: the hodograph goes beside that curve.
    const [o] = defaultState.hodograph;
    const [p] = s.hodograph;
    const other = TEXTS.some((name) => s[name] !== defaultState[name]);
    if (first && other && p[0] === o[0] && p[1] === o[1])
      s.hodograph = [originBeside(wholeCurve(curve, domain, strings))];
    return { curve };
  },
  inPlace: {
    params(m, s) {
      for (const [name, value] of Object.entries(s.params)) m.curve.setParameter(name, value);
    },
  },
};

/** P(t), P′(t), P″(t) and the core's frame (curvature, torsion); `defined` false at a gap. */
function valuesAt(curve, tt, whole) {
  let point = null;
  let d1 = null;
  let d2 = null;
  let frame = null;
  try {
    point = curve.evaluate(tt);
    d1 = curve.derivative(tt, 1);
    d2 = curve.derivative(tt, 2);
    frame = curve.frame(tt);
  } catch {
    frame = null;
  }
  const finite = (v) => v?.every(Number.isFinite);
  const defined = finite(point) && finite(d1);
  const speed = defined ? Math.hypot(...d1) : Number.NaN;
  const cusp = defined && !(speed > CUSP_SPEED * Math.max(1, whole.size));
  // At a cusp (P′ = 0) the curvature grows without bound: ∞, not the rounding's number.
  const curvature = frame && Number.isFinite(frame.curvature) ? frame.curvature : Number.NaN;
  const kappa = cusp ? Number.POSITIVE_INFINITY : curvature;
  const straight =
    Number.isFinite(kappa) && !(Math.abs(kappa) * STRAIGHT_RADIUS_FACTOR * whole.size > 1);
  const kappaMachine = Number.isFinite(kappa) ? fmtMachine(kappa) : "∞";
  return {
    defined,
    point,
    d1,
    d2,
    frame: finite(frame?.tangent ?? null) ? frame : null,
    speed,
    kappa,
    cusp,
    straight,
    kappaMachine,
    kappaText: localeDecimal(kappaMachine),
    kappaTex: texDecimal(kappaMachine),
    tau: frame && Number.isFinite(frame.torsion) ? frame.torsion : Number.NaN,
  };
}

export const compute = {
  // A bound may name a parameter ("2pi/a"): the domain follows the sliders too.
  domain: [WITH_PARAMS, (s, d) => d.curve.domain()],
  whole: [WITH_PARAMS, (s, d) => wholeCurve(d.curve, d.domain, strings)],
  tex: [TEXTS, (s, d) => d.curve.tex(0)],
  bezierForm: [[...WITH_PARAMS, "bezier"], (s, d) => bezierFormOf(d.curve, s.bezier)],
  at: [
    [...WITH_PARAMS, "t"],
    (s, d) => valuesAt(d.curve, Math.min(Math.max(s.t, d.domain[0]), d.domain[1]), d.whole),
  ],
  /** The osculating circle in space (a scene curve). */
  circle: [[...WITH_PARAMS, "t"], (s, d) => osculatingCircle(d.at)],
  /** The adaptive plot, made when first drawn: for the window in 2D, once in 3D. */
  plot: [WITH_PARAMS, () => ({ key: "", result: null, runs: [] })],
};

// ------------------------------------------------------------------ panel

/** After a new curve: O beside it (the final change), then the figure fits it. */
function settleNewCurve(ui) {
  ui.set("hodograph", [originBeside(ui.data.whole)], true);
  ui.fit();
}

/** Shows a new state from the panel (typed texts, an example), or the core's refusal. */
function showCurve(ui, next) {
  ui.replace(next, false); // throws the refusal before anything changes
  settleNewCurve(ui);
}

/** The readout under the speed: the circle's radius, or why there is none. */
function radiusNote(d) {
  const at = d.at;
  if (!at.defined) return "";
  if (at.cusp) return t("parametricCurve.cusp");
  if (at.straight || !Number.isFinite(at.kappa)) return t("parametricCurve.straight");
  return t("parametricCurve.radius", { r: fmt(1 / Math.abs(at.kappa)) });
}

export const controls = [
  formulaFields({
    legend: "parametricCurve.control.curve",
    rows: [
      [{ field: "x", label: "parametricCurve.control.x" }],
      [{ field: "y", label: "parametricCurve.control.y" }],
      [{ field: "z", label: "parametricCurve.control.z" }],
      [
        { field: "from", label: "parametricCurve.control.from" },
        { field: "to", label: "parametricCurve.control.to" },
      ],
    ],
    help: "parametricCurve.control.help",
    check(ui, texts) {
      curveOf(ui.sl, withTexts(ui.state, texts)).curve.free();
    },
    apply(ui, texts) {
      const next = withTexts(ui.state, texts);
      if (TEXTS.some((name) => next[name] !== ui.state[name])) showCurve(ui, next);
    },
  }),
  parameterSliders("params", {
    legend: "parametricCurve.control.params",
    input: "parametricCurve.control.param.input",
  }),
  group(
    "parametricCurve.atT",
    slider("t", {
      label: "parametricCurve.control.t",
      range: (s, d) => d.domain ?? d.curve.domain(),
      step: (a, b) => (b - a) / 1000,
      player: true,
    }),
    readout(
      "speed",
      (s, d) =>
        d.at.defined
          ? t("parametricCurve.speed", { speed: fmt(d.at.speed) })
          : t("parametricCurve.undefined", { t: fmt(s.t) }),
      { data: (s, d) => ({ speed: fmtMachine(d.at.speed) }) },
    ),
    readout(
      "curvature",
      (s, d) => (d.at.defined ? t("parametricCurve.curvature", { kappa: d.at.kappaText }) : ""),
      { live: true, data: (s, d) => ({ kappa: d.at.kappaMachine }) },
    ),
    readout("radius", (s, d) => radiusNote(d)),
    shownWhen(
      (s) => isSpaceState(s),
      readout("torsion", (s, d) =>
        Number.isFinite(d.at.tau) ? t("parametricCurve.torsion", { tau: fmt(d.at.tau) }) : "",
      ),
    ),
  ),
  shownWhen(
    (s, d) => d.whole.polynomial,
    group(
      null,
      checkbox("bezier", { label: "parametricCurve.control.bezier" }),
      infoLine(
        "bezier-points",
        (s, d) => bezierList(d.bezierForm, d.domain, strings),
        (s, d) => deCasteljauLink(d.bezierForm, d.domain, s.t, strings),
      ),
    ),
  ),
  actions(
    PRESETS.map((preset) => ({
      name: `preset-${preset.name}`,
      label: `parametricCurve.preset.${preset.name}`,
      run(ui) {
        try {
          showCurve(ui, withPreset(ui.state, preset));
        } catch (err) {
          ui.status(errorText(err), "error");
        }
      },
    })),
    { title: "parametricCurve.control.examples" },
  ),
];

// ------------------------------------------------------------------ figures

/** The plane figure: the curve's box (its visible part near a pole) and the hodograph's. */
export const figure = {
  bounds(s, d) {
    const b = planeBounds(d.whole, s.hodograph[0]);
    const form = d.bezierForm;
    for (let k = 0; form && k < form.points.length; k += form.dim) {
      b[0] = Math.min(b[0], form.points[k]);
      b[1] = Math.min(b[1], form.points[k + 1]);
      b[2] = Math.max(b[2], form.points[k]);
      b[3] = Math.max(b[3], form.points[k + 1]);
    }
    return b;
  },
  handles: { field: "hodograph", label: () => t("parametricCurve.originLabel"), polygon: false },
};

/** The space figure: the plot and the osculating circle in WebGL, the frame on the 2D layer. */
export const figure3d = {
  bounds: (s, d) => spaceBounds(d.whole, d.bezierForm),
  camera: { azimuth: -60, elevation: 25 },
  scene: (s, d) => spaceScene(d),
  handles: [], // no points to drag: the arrow keys orbit the camera
};

/** Plane: axes, hodograph, Bézier form, circle, curve, P′ and P″ at P(t); space: the frame. */
export function draw(r, v, s, d) {
  if (v.is3d) drawSpaceLayer(r, v, s, d, strings);
  else drawPlaneFigure(r, v, s, d, strings);
}

// ------------------------------------------------------------------ formula and label

const COORDS = Object.freeze(["x", "y", "z"]);
/** Negative numbers in brackets as "({-}…" (see derivatives.js: the panel patches digits). */
const guarded = (line) => line.replace(/\(-/g, "({-}");

/**
 * The typed formulas and their derivatives as the core echoes them (`tex(0)`), the interval and
 * the parameters, then the numbers at t₀: P, P′, P″, the speed and κ (τ in space).
 */
export function formula(s, d) {
  const tex = d.tex;
  const dim = d.whole.dim;
  const tooLong = `\\text{(${t("parametricCurve.formula.tooLong")})}`;
  const lines = [];
  for (let c = 0; c < dim; c++) {
    const name = COORDS[c];
    const e = tex[name];
    if (!e) continue;
    lines.push(
      `${name}(t) = ${e.expr},\\qquad ${name}'(t) = ${e.d1 ?? tooLong},\\qquad ${name}''(t) = ${e.d2 ?? tooLong}`,
    );
  }
  const params = Object.entries(s.params)
    .map(([name, value]) => `${name.replace(/_(.+)$/, "_{$1}")} = ${shortNumber(value, true)}`)
    .join(",\\ ");
  lines.push(`t \\in [${tex.from},\\ ${tex.to}]${params ? `,\\qquad ${params}` : ""}`);
  const at = d.at;
  const t0 = `t_0 = ${fmtTex(s.t)}`;
  if (!at.defined) {
    lines.push(`${t0}:\\quad P(t_0)\\ \\text{${t("parametricCurve.formula.undefined")}}`);
    return lines;
  }
  // Three short lines rather than one long one (a narrow embed shrinks a line only so far).
  lines.push(
    guarded(`${t0}:\\quad P(t_0) = ${pointTex(at.point)},\\quad P'(t_0) = ${pointTex(at.d1)}`),
  );
  lines.push(guarded(`P''(t_0) = ${pointTex(at.d2)},\\quad |P'(t_0)| = ${fmtTex(at.speed)}`));
  const kappaRule =
    dim === 3 ? "\\frac{|P' \\times P''|}{|P'|^3}" : "\\frac{x'y'' - y'x''}{|P'|^3}";
  const kappa = Number.isFinite(at.kappa) ? at.kappaTex : "\\infty";
  const tau = dim === 3 && Number.isFinite(at.tau) ? `,\\quad \\tau(t_0) = ${fmtTex(at.tau)}` : "";
  lines.push(`\\kappa(t_0) = ${kappaRule} = ${kappa}${tau}`);
  return lines;
}

export function label(s, d) {
  const [a, b] = d.domain;
  const at = d.at;
  const common = { x: s.x, y: s.y, z: s.z, a: fmt(a), b: fmt(b), t: fmt(s.t) };
  if (!at.defined) return t("parametricCurve.ariaUndefined", common);
  const values = {
    ...common,
    px: fmt(at.point[0], 2),
    py: fmt(at.point[1], 2),
    speed: fmt(at.speed, 2),
    kappa: at.kappaText,
  };
  if (d.whole.dim !== 3) return t("parametricCurve.aria", values);
  return t("parametricCurve.aria3d", {
    ...values,
    pz: fmt(at.point[2], 2),
    tau: Number.isFinite(at.tau) ? fmt(at.tau) : "—",
  });
}

/** A press on the drawn curve (or a drag along it) moves the point there, in 2D and 3D. */
export function setup(ui) {
  addPlotPicker(ui, {
    field: "t",
    plot: () => ui.data.plot.result,
    dim: () => ui.data.curve.dim,
    domain: () => ui.data.domain,
  });
  // For tests: the plot's runs as [first t, last t] (a pole or gap ends a run).
  const host = ui.ctx.slots.figure;
  let shown = null;
  return {
    update(s, d) {
      const plot = d.plot.result;
      if (!plot || plot === shown) return;
      shown = plot;
      host.dataset.plotRuns = JSON.stringify(plotRuns(plot.ts));
    },
  };
}
