/**
 * Demo 4 (syllabus §2): adaptive flattening. A cubic is drawn as the polyline that the core's
 * `flatten(ε)` returns, with its vertices, the segment count, and the count for ε/2 (one more
 * `flatten` call) to show that halving the tolerance multiplies the segments by about √2. The
 * optional tolerance band is the polyline stroked 2ε wide: the curve never leaves it.
 *
 * Same shape as the reference demo (de-casteljau.js): the curve lives in wasm and is updated in
 * place while dragging (`setControlPoint`), the polyline is what the core returns (no
 * subdivision in JS), nothing is allocated per frame in the draw path, and replaced wasm
 * objects are freed.
 */
import { Handles, pointHandles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, button, checkbox, group, el, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkBoolean } from "../lib/validate.js";
import { fmt } from "../lib/format.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf } from "../lib/geometry.js";
import { flatPath } from "../lib/draw.js";
import { scaledInsets } from "../lib/view.js";

export const id = "flattening";
/** Prefix of this demo's keys in strings.js. */
export const strings = "flattening";
export const title = t("flattening.title");
export const summary = t("flattening.summary");
/** Syllabus section. */
export const section = 2;

/** Smallest and largest tolerance ε (world units); the slider is logarithmic between them. */
export const MIN_TOLERANCE = 0.001;
export const MAX_TOLERANCE = 1;

/**
 * Integer shapes that show the adaptivity well: the S-curve (the default) bends at both ends
 * and is almost straight in the middle, the loop and the cusp concentrate curvature in one
 * place (the cusp, a symmetric polygon whose legs P₀P₁ and P₂P₃ mirror each other with
 * |P₁P₂| = the legs' width, has P′(1/2) = 0), and the nearly straight curve needs almost no
 * segments.
 */
export const PRESETS = Object.freeze({
  s: Object.freeze([[0, 0], [2, 6], [6, -2], [8, 4]].map(Object.freeze)),
  loop: Object.freeze([[1, 0], [10, 6], [-2, 6], [7, 0]].map(Object.freeze)),
  cusp: Object.freeze([[1, 0], [7, 6], [1, 6], [7, 0]].map(Object.freeze)),
  straight: Object.freeze([[0, 0], [3, 1], [5, 1], [8, 2]].map(Object.freeze)),
});
/** Preset keys in button order. */
const PRESET_ORDER = ["s", "loop", "cusp", "straight"];

/**
 * ε = 0.1 rather than a smaller value: at the default zoom the band is then about 10 px wide, so
 * the curve is seen inside it; 7 segments, 9 at ε/2.
 */
export const defaultState = Object.freeze({
  points: PRESETS.s,
  tolerance: 0.1,
  band: true,
});

/** A cubic: four control points. */
const POINT_COUNT = 4;
/** Points sampled along the curve for drawing (one `sampleUniform` call per change). */
const CURVE_SAMPLES = 256;
/** Slider resolution in log10 units (about 230 positions from 0.001 to 1). */
const LOG_STEP = 0.01;
/** Slider values are rounded to this many significant digits (0.05, 0.063, …): short links. */
const SLIDER_DIGITS = 2;
/** Typed values are shown with up to this many significant digits. */
const SHOWN_DIGITS = 3;
/** Opacity of the tolerance band (helper grey, translucent so the curve shows through). */
const BAND_ALPHA = 0.6;
/** Position of the segment count drawn in the figure's corner, CSS px from the top left. */
const COUNT_LABEL_INSET = 12;
/** Height of the band kept free for the count above the world window, CSS px at scale 1. */
const COUNT_BAND_PX = 34;

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "tolerance", "band"]);
  checkPoints(state, "points", { min: POINT_COUNT, max: POINT_COUNT });
  checkNumber(state, "tolerance", { min: MIN_TOLERANCE, max: MAX_TOLERANCE });
  checkBoolean(state, "band");
}

/** A coordinate for labels: integers as they are, others with 2 decimals. */
function coord(x) {
  return Number.isInteger(x) ? String(x) : fmt(x, 2);
}

/** A tolerance as typed or shown: "0.05", "0.0015" (no trailing zeros, no float noise). */
function formatTolerance(value) {
  return String(Number(value.toPrecision(SHOWN_DIGITS)));
}

/** Segments of a flat 2D polyline (vertices − 1). */
function segmentCount(polyline) {
  return polyline.length / 2 - 1;
}

/**
 * Mounts the demo. `ctx` comes from the shell (lib/shell.js): `sl` (wasm), `slots`,
 * `createFigure`, `preview`, `commit`, `status`.
 */
export function mount(container, initialState, ctx) {
  const { sl } = ctx;
  /** The state shown; mutated in place during drags, committed as a copy. */
  let work = structuredClone(initialState);
  let curve = new sl.BezierCurve(flatten(work.points), 2);

  // Derived data, recomputed only when the geometry or the tolerance changed.
  let samples = null; // curve.sampleUniform(CURVE_SAMPLES)
  let polyline = new Float64Array(0); // curve.flatten(ε): flat vertices, ends included
  let halfCount = 0; // segments of curve.flatten(ε / 2)
  let geometryDirty = true;
  let toleranceDirty = true;
  let countLabel = "";
  const pointScratch = new Float64Array(2);
  /** The band's style: helper grey, width 2ε in world units (set per draw, made once). */
  const bandStyle = { stroke: "", strokeAlpha: BAND_ALPHA, width: 1, join: "round", cap: "round" };

  // ------------------------------------------------------------ figure
  // The count's band above the world window.
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(work.points), insets: scaledInsets(COUNT_BAND_PX, 0, 0, 0) });
  const handles = new Handles(view, {
    ...pointHandles(() => work.points, (i, xy) => {
      curve.setControlPoint(i, xy); // in place: no rebuild while dragging
      geometryDirty = true;
    }),
    commit: (kind, i, merge) => ctx.commit(work, merge),
  });

  // ------------------------------------------------------------ side panel
  const segmentsText = el("p", { class: "sl-readout", dataset: { info: "segments" } });
  const halfText = el("p", { class: "sl-note", dataset: { info: "half" } });
  const toleranceSlider = slider({
    label: t("flattening.tolerance"),
    inputLabel: t("flattening.tolerance.input", { min: MIN_TOLERANCE, max: MAX_TOLERANCE }),
    name: "tolerance",
    min: MIN_TOLERANCE,
    max: MAX_TOLERANCE,
    step: LOG_STEP,
    log: true,
    value: work.tolerance,
    format: formatTolerance,
    onChange: (value, final) => {
      // The range moves in powers of ten: keep two significant digits; typed values as typed.
      const typed = document.activeElement === toleranceSlider.box || toleranceSlider.box.getRootNode().activeElement === toleranceSlider.box;
      const v = typed ? value : Math.min(MAX_TOLERANCE, Math.max(MIN_TOLERANCE, Number(value.toPrecision(SLIDER_DIGITS))));
      setTolerance(v, final);
    },
    onError: (text) => ctx.status(t("flattening.badTolerance", { value: text, min: MIN_TOLERANCE, max: MAX_TOLERANCE }), "error"),
  });
  const bandBox = checkbox({
    label: t("flattening.band"),
    name: "band",
    checked: work.band,
    onChange: (on) => {
      work.band = on;
      view.requestDraw();
      ctx.commit(work);
    },
  });
  const presetButtons = PRESET_ORDER.map((key) =>
    button({ label: t(`flattening.preset.${key}`), title: t("flattening.preset.title"), name: `preset-${key}`, onClick: () => applyPreset(key) }));
  ctx.slots.controls.append(
    group(null, segmentsText, halfText),
    group(null, toleranceSlider.element, bandBox.element),
    group(t("flattening.presets"), el("div", { class: "sl-button-row" }, presetButtons)),
  );

  // ------------------------------------------------------------ formula
  const formula = new FormulaPanel(ctx.slots.formula);

  // ------------------------------------------------------------ edits

  function setTolerance(value, final) {
    work.tolerance = value;
    toleranceSlider.set(value);
    toleranceDirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  }

  /** Moves the four points to a preset shape (in place: same number of points). */
  function applyPreset(key) {
    PRESETS[key].forEach(([x, y], i) => {
      work.points[i][0] = x;
      work.points[i][1] = y;
      pointScratch[0] = x;
      pointScratch[1] = y;
      curve.setControlPoint(i, pointScratch);
    });
    geometryDirty = true;
    view.requestDraw();
    ctx.commit(work);
  }

  // ------------------------------------------------------------ drawing
  /** Asks the core for the samples and both polylines when something changed. */
  function recompute() {
    if (geometryDirty) samples = curve.sampleUniform(CURVE_SAMPLES);
    if (geometryDirty || toleranceDirty) {
      try {
        polyline = curve.flatten(work.tolerance);
        halfCount = segmentCount(curve.flatten(work.tolerance / 2));
      } catch (err) {
        // Only a far too small ε for a huge curve: keep the last polyline, say why.
        ctx.status(t("flattening.flattenFailed", { message: err.message }), "error");
      }
      syncPanels();
    }
    geometryDirty = toleranceDirty = false;
  }

  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;
    const vertices = polyline.length / 2;

    // The tolerance band under everything: the polyline stroked 2ε wide (round joins and caps
    // make it exactly the set of points within ε of the polyline).
    if (work.band) {
      bandStyle.stroke = theme.helper.stroke;
      bandStyle.width = (2 * work.tolerance * v.scale) / r.scale; // the renderer multiplies by r.scale
      flatPath(r, v, polyline, 0, vertices);
      r.paint(bandStyle);
    }

    // Control polygon.
    r.beginPath();
    for (let i = 0; i < pts.length; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(theme.polygon);

    // The curve, from one batched sample call.
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    // The polyline from flatten(ε) and its vertices.
    flatPath(r, v, polyline, 0, vertices);
    r.paint(theme.levelStroke[0]);
    for (let k = 0; k < vertices; k++) r.point(v.sx(polyline[2 * k]), v.sy(polyline[2 * k + 1]), theme.levelPoint[0]);

    handles.draw(r, v);

    // The count in the corner, so projections and exports carry it too.
    r.text(countLabel, COUNT_LABEL_INSET * r.scale, COUNT_LABEL_INSET * r.scale, theme.label, "left", "top");
  }

  // ------------------------------------------------------------ panels (formula, label)
  function syncPanels() {
    const pts = work.points;
    const count = Math.max(0, segmentCount(polyline));
    const eps = formatTolerance(work.tolerance);
    const halfEps = formatTolerance(work.tolerance / 2);
    const ratio = count > 0 ? fmt(halfCount / count, 2) : "?";
    countLabel = t("flattening.countLabel", { count, tolerance: eps });
    setText(segmentsText, t(count === 1 ? "flattening.segments.one" : "flattening.segments", { count }));
    setText(halfText, t("flattening.half", { tolerance: halfEps, count: halfCount, ratio }));
    view.setLabel(t("flattening.aria", {
      tolerance: eps,
      count,
      vertices: count + 1,
      half: halfEps,
      halfCount,
      points: pts.map(([x, y]) => `(${coord(x)}, ${coord(y)})`).join(", "),
    }));

    // The flatness test of the whole curve (the first test the core makes): distances of the
    // inner control points to the chord P₀P₃ — a formula on the four numbers, not the algorithm.
    const [x0, y0] = pts[0];
    const [x3, y3] = pts[3];
    const cx = x3 - x0;
    const cy = y3 - y0;
    const chord = Math.hypot(cx, cy);
    const distance = ([x, y]) => (chord > 0 ? Math.abs(cx * (y3 - y) - cy * (x3 - x)) / chord : Math.hypot(x - x0, y - y0));
    const d1 = distance(pts[1]);
    const d2 = distance(pts[2]);
    const flat = Math.max(d1, d2) <= work.tolerance;
    formula.set([
      `d_i = \\frac{\\lvert (P_3 - P_0) \\times (P_3 - P_i) \\rvert}{\\lvert P_3 - P_0 \\rvert} \\le \\varepsilon, \\quad i = 1, 2, \\qquad \\varepsilon = ${eps}`,
      `\\text{${t("flattening.formula.whole")}}\\ d_1 = ${fmt(d1)},\\ d_2 = ${fmt(d2)}\\ ${flat ? "\\le" : ">"}\\ \\varepsilon \\;\\Rightarrow\\; \\text{${t(flat ? "flattening.formula.flat" : "flattening.formula.split")}}`,
      `\\text{${t("flattening.formula.until")}}`,
      `\\varepsilon = ${eps}:\\ \\mathbf{${count}}\\ \\text{${t("flattening.formula.segments")}};\\qquad \\tfrac{\\varepsilon}{2} = ${halfEps}:\\ \\mathbf{${halfCount}}\\ \\text{${t("flattening.formula.segments")}} \\quad (\\times ${ratio} \\approx \\sqrt{2})`,
    ]);
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      let nextPolyline;
      let nextHalf;
      try {
        nextPolyline = next.flatten(state.tolerance);
        nextHalf = segmentCount(next.flatten(state.tolerance / 2));
      } catch (err) {
        next.free();
        throw err;
      }
      curve.free();
      curve = next;
      polyline = nextPolyline;
      halfCount = nextHalf;
      work = structuredClone(state);
      handles.forgetPointer();
      toleranceSlider.set(work.tolerance);
      bandBox.set(work.band);
      geometryDirty = true;
      toleranceDirty = false;
      samples = curve.sampleUniform(CURVE_SAMPLES);
      geometryDirty = false;
      syncPanels();
      view.requestDraw();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
    },
  };
}
