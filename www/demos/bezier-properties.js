/**
 * Demo (syllabus §2, "Properties to demonstrate"): one draggable Bézier curve and, one at a
 * time, the property it has: the convex hull, affine invariance, symmetry (reversed order),
 * degree elevation and variation diminishing. Follows the reference demo (de-casteljau.js):
 * the curve is updated in place while dragging (`setControlPoint`), and everything drawn about
 * the curve comes from the core — samples, `reversed()`, `elevate()`, `intersectLine`,
 * `polygonLineCrossings`, and a second `BezierCurve` built from the mapped control points.
 * JS only does drawing support: the hull polygon of the control points (`convexHull` in
 * lib/geometry.js, a documented monotone chain), the 2×2 matrix applied to points, and the
 * distances reported as checks.
 */
import { Handles } from "../lib/handles.js";
import { FormulaPanel } from "../lib/formula.js";
import { slider, group, el, radios, setText } from "../lib/controls.js";
import { checkObject, checkPoints, checkNumber, checkChoice } from "../lib/validate.js";
import { fmt, subscript, exactFraction, fractionText, fractionTex, allIntegers } from "../lib/format.js";
import { HUES, WIDTH, RADIUS, POLYGON_DASH } from "../lib/theme.js";
import { t } from "../lib/strings.js";
import { flatten, boundsOf, convexHull } from "../lib/geometry.js";
import { pointListActions, pointButtons } from "../lib/point-list.js";
import { titledTable } from "../lib/table.js";
import { flatPath } from "../lib/draw.js";

export const id = "bezier-properties";
/** Prefix of this demo's keys in strings.js. */
export const strings = "bezierProperties";
export const title = t("bezierProperties.title");
export const summary = t("bezierProperties.summary");
/** Syllabus section. */
export const section = 2;

/** The properties, in the order of the radio buttons. */
export const PROPERTIES = Object.freeze(["hull", "affine", "reversed", "elevation", "variation"]);

/**
 * The worked example of the Greek notes (syllabus §2), an affine map that visibly rotates,
 * shrinks and shears it (its image stays in the same window), two elevations, and the line y = 3, which crosses the polygon twice
 * and misses the curve (its highest point is y = 2√2 ≈ 2.83).
 */
export const defaultState = Object.freeze({
  points: Object.freeze([[0, 0], [2, 2], [6, 4], [8, 2]].map(Object.freeze)),
  property: "hull",
  rotation: 20,
  scale: 0.8,
  shear: -0.3,
  elevations: 2,
  line: Object.freeze([[-1, 3], [9, 3]].map(Object.freeze)),
});

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
/** Direction chevrons along the curve and the reversed curve, at these parameters. */
const ARROW_TS = Object.freeze([0.2, 0.6]);
/** Chevron size (CSS px) and half-angle (radians). */
const CHEVRON_PX = 11;
const CHEVRON_ANGLE = 0.5;
/** Distance (model units) within which `intersectLine` reports a hit. */
const INTERSECT_TOLERANCE = 1e-9;

// Styles of this demo's own marks (theme hues are the same in light and dark mode).
const MAPPED_CURVE_STYLE = Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.curve, join: "round", cap: "round" });
const MAPPED_POLYGON_STYLE = Object.freeze({ stroke: HUES.bluishGreen, width: WIDTH.polygon, dash: POLYGON_DASH });
const MAPPED_POINT_STYLE = Object.freeze({ fill: HUES.bluishGreen, radius: RADIUS.constructionPoint });
const DOT_STYLE = Object.freeze({ fill: HUES.vermillion, radius: 2.5 });
const REVERSED_STYLE = Object.freeze({ stroke: HUES.orange, width: WIDTH.curve, dash: Object.freeze([8, 6]), cap: "butt" });
const FORWARD_CHEVRON = Object.freeze({ stroke: HUES.blue, width: 2.5, cap: "round", join: "round" });
const REVERSED_CHEVRON = Object.freeze({ stroke: HUES.orange, width: 2.5, cap: "round", join: "round" });
const LINE_STYLE = Object.freeze({ stroke: HUES.reddishPurple, width: 1.5 });

/** Checks a state from a link, a file or attributes; throws an Error naming the bad field. */
export function validate(state) {
  checkObject(state, ["points", "property", "rotation", "scale", "shear", "elevations", "line"]);
  checkPoints(state, "points", { min: MIN_POINTS, max: MAX_POINTS });
  checkChoice(state, "property", PROPERTIES);
  checkNumber(state, "rotation", { min: ROTATION_RANGE[0], max: ROTATION_RANGE[1] });
  checkNumber(state, "scale", { min: SCALE_RANGE[0], max: SCALE_RANGE[1] });
  checkNumber(state, "shear", { min: SHEAR_RANGE[0], max: SHEAR_RANGE[1] });
  checkNumber(state, "elevations", { min: 0, max: MAX_ELEVATIONS, integer: true });
  checkPoints(state, "line", { min: 2, max: 2 });
  const [[x0, y0], [x1, y1]] = state.line;
  if (x0 === x1 && y0 === y1) throw new Error(t("bezierProperties.lineDegenerate"));
}

/** The 2×2 matrix R(θ)·sI·H(k) of the affine map: rotation, uniform scale, shear along x. */
function affineMatrix(state, out) {
  const angle = (state.rotation * Math.PI) / 180;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const k = state.shear;
  const f = state.scale;
  // R·(f·H) with H = [[1, k], [0, 1]].
  out[0] = f * c; // a
  out[1] = f * (c * k - s); // b
  out[2] = f * s; // c
  out[3] = f * (s * k + c); // d
  return out;
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
  let mapped = new sl.BezierCurve(flatten(work.points), 2); // its points are set in recompute
  let reversedCurve = null;

  // Derived data, recomputed only when the geometry or a property's setting changed.
  let samples = null;
  let dirty = true;
  let hull = [];
  let mappedSamples = null;
  const matrix = new Float64Array(4);
  const centre = new Float64Array(2);
  const mappedPoints = []; // [x, y] per control point
  const dotTs = new Float64Array(MAPPED_DOTS).map((_, k) => k / (MAPPED_DOTS - 1));
  const dots = new Float64Array(2 * MAPPED_DOTS); // original samples mapped in JS
  let mappedDistance = 0;
  let reversedSamples = null;
  let reversedDistance = 0;
  let elevatedPoints = null; // flat points after `elevations` elevations
  let firstElevation = null; // flat points after one elevation (formula and table)
  let polygonCrossings = 0;
  let curveHits = null; // flat points where the curve meets the line
  let curveCrossings = 0;
  const pointScratch = new Float64Array(2);
  const handleLabels = [];
  const LINE_LABELS = [t("bezierProperties.lineA"), t("bezierProperties.lineB")];

  // ------------------------------------------------------------ figure
  const view = ctx.createFigure({ draw, bounds: () => boundsOf(figurePoints()) });
  const handles = new Handles(view, {
    count: () => work.points.length + (work.property === "variation" ? 2 : 0),
    get: (i, out) => {
      const p = i < work.points.length ? work.points[i] : work.line[i - work.points.length];
      out[0] = p[0];
      out[1] = p[1];
    },
    label: (i) => (i < work.points.length ? (handleLabels[i] ??= `P${subscript(i)}`) : LINE_LABELS[i - work.points.length]),
    move: (i, x, y) => {
      if (i >= work.points.length) {
        // A point of the line: refuse to make the two coincide (no line through them).
        const other = work.line[1 - (i - work.points.length)];
        if (other[0] === x && other[1] === y) return;
        work.line[i - work.points.length][0] = x;
        work.line[i - work.points.length][1] = y;
      } else {
        work.points[i][0] = x;
        work.points[i][1] = y;
        pointScratch[0] = x;
        pointScratch[1] = y;
        curve.setControlPoint(i, pointScratch); // in place: no rebuild while dragging
      }
      dirty = true;
    },
    commit: (kind, i, merge) => ctx.commit(work, merge),
    add: (i) => edits.add(i),
    remove: (i) => removeControlPoint(i),
  });

  /** The points the figure should show whole ("Fit"): the control points, plus the line or the mapped points. */
  function figurePoints() {
    if (work.property === "variation") return work.points.concat(work.line);
    if (work.property === "affine") {
      dirty = true;
      recompute();
      return work.points.concat(mappedPoints);
    }
    return work.points;
  }

  // ------------------------------------------------------------ side panel
  const propertyRadios = radios({
    name: "property",
    value: work.property,
    options: PROPERTIES.map((p) => ({ value: p, label: t(`bezierProperties.property.${p}`) })),
    onChange: (p) => {
      work.property = p;
      if (handles.selected >= handles.source.count()) handles.select(-1);
      showGroups();
      dirty = true;
      view.requestDraw();
      ctx.commit(work);
    },
  });
  const badNumber = (text) => ctx.status(t("control.badNumber", { value: text }), "error");
  const setting = (field) => (value, final) => {
    work[field] = value;
    dirty = true;
    view.requestDraw();
    if (final) ctx.commit(work);
  };
  const rotationSlider = slider({
    label: t("bezierProperties.rotation"),
    inputLabel: t("bezierProperties.rotation.input"),
    name: "rotation",
    min: ROTATION_RANGE[0],
    max: ROTATION_RANGE[1],
    step: 1,
    value: work.rotation,
    format: (v) => String(Math.round(v * 1000) / 1000),
    onChange: setting("rotation"),
    onError: badNumber,
  });
  const scaleSlider = slider({
    label: t("bezierProperties.scale"),
    inputLabel: t("bezierProperties.scale.input"),
    name: "scale",
    min: SCALE_RANGE[0],
    max: SCALE_RANGE[1],
    step: 0.05,
    value: work.scale,
    onChange: setting("scale"),
    onError: badNumber,
  });
  const shearSlider = slider({
    label: t("bezierProperties.shear"),
    inputLabel: t("bezierProperties.shear.input"),
    name: "shear",
    min: SHEAR_RANGE[0],
    max: SHEAR_RANGE[1],
    step: 0.05,
    value: work.shear,
    onChange: setting("shear"),
    onError: badNumber,
  });
  const elevationSlider = slider({
    label: t("bezierProperties.elevations"),
    inputLabel: t("bezierProperties.elevations.input"),
    name: "elevations",
    min: 0,
    max: MAX_ELEVATIONS,
    step: 1,
    value: work.elevations,
    format: (v) => String(Math.round(v)),
    onChange: (value, final) => setting("elevations")(Math.round(value), final),
    onError: badNumber,
  });
  const readout = el("p", { class: "sl-readout", dataset: { info: "property" }, "aria-live": "polite" });
  const note = el("p", { class: "sl-note" });
  const degreeText = el("p", { class: "sl-note", dataset: { info: "degree" } });
  const { addButton, removeButton } = pointButtons({ add: (i) => edits.add(i), remove: (i) => removeControlPoint(i), selected: () => handles.selected });
  const groups = {
    affine: group(t("bezierProperties.affineLegend"), rotationSlider.element, scaleSlider.element, shearSlider.element),
    elevation: group(t("bezierProperties.elevationLegend"), elevationSlider.element),
  };
  ctx.slots.controls.append(
    group(t("bezierProperties.propertyLegend"), propertyRadios.element),
    groups.affine,
    groups.elevation,
    group(null, readout, note),
    group(null, degreeText, el("div", { class: "sl-button-row" }, addButton, removeButton)),
  );

  /** Shows the controls of the chosen property only. */
  function showGroups() {
    groups.affine.hidden = work.property !== "affine";
    groups.elevation.hidden = work.property !== "elevation";
  }
  showGroups();

  // ------------------------------------------------------------ formula and table
  const formula = new FormulaPanel(ctx.slots.formula);
  const { title: tableTitle, table, wrap: tableWrap } = titledTable("elevation");
  const tableBlock = el("div", {}, tableTitle, tableWrap);
  ctx.slots.details.append(tableBlock);
  let tableCells = [];

  // ------------------------------------------------------------ edits

  /** Replaces the wasm curves after the number of points changed (the old ones are freed). */
  function rebuild() {
    const next = new sl.BezierCurve(flatten(work.points), 2);
    const nextMapped = new sl.BezierCurve(flatten(work.points), 2);
    curve.free();
    mapped.free();
    curve = next;
    mapped = nextMapped;
    dirty = true;
    view.requestDraw();
  }

  const edits = pointListActions({ ctx, work, view, handles, min: MIN_POINTS, max: MAX_POINTS, strings: "bezierProperties", rebuild });
  /** Removes handle i when it is a control point (the line's points is not one). */
  const removeControlPoint = (i) => i < work.points.length && edits.remove(i);

  // ------------------------------------------------------------ recompute (core calls)
  /** Asks the core for what the chosen property shows, when something changed. */
  function recompute() {
    if (!dirty) return;
    dirty = false;
    samples = curve.sampleUniform(CURVE_SAMPLES);
    switch (work.property) {
      case "hull":
        hull = convexHull(work.points);
        break;
      case "affine":
        computeAffine();
        break;
      case "reversed":
        computeReversed();
        break;
      case "elevation":
        computeElevation();
        break;
      case "variation":
        computeVariation();
        break;
    }
    syncPanels();
  }

  /**
   * Affine invariance: the control points mapped by x ↦ c + A(x − c) (c: their centroid) make
   * a second curve in the core; samples of the original, mapped the same way in JS, must lie
   * on it. The largest distance between the two (same t) is reported.
   */
  function computeAffine() {
    const pts = work.points;
    affineMatrix(work, matrix);
    centre[0] = centre[1] = 0;
    for (const [x, y] of pts) {
      centre[0] += x / pts.length;
      centre[1] += y / pts.length;
    }
    mappedPoints.length = pts.length;
    for (let i = 0; i < pts.length; i++) {
      const q = (mappedPoints[i] ??= [0, 0]);
      mapPoint(pts[i][0], pts[i][1], q, 0);
      pointScratch[0] = q[0];
      pointScratch[1] = q[1];
      mapped.setControlPoint(i, pointScratch);
    }
    mappedSamples = mapped.sampleUniform(CURVE_SAMPLES);
    const original = curve.sample(dotTs);
    const onMapped = mapped.sample(dotTs);
    mappedDistance = 0;
    for (let k = 0; k < MAPPED_DOTS; k++) {
      mapPoint(original[2 * k], original[2 * k + 1], dots, 2 * k);
      mappedDistance = Math.max(mappedDistance, Math.hypot(dots[2 * k] - onMapped[2 * k], dots[2 * k + 1] - onMapped[2 * k + 1]));
    }
  }

  /** Writes c + A(p − c) into out[at], out[at + 1]. */
  function mapPoint(x, y, out, at) {
    const dx = x - centre[0];
    const dy = y - centre[1];
    out[at] = centre[0] + matrix[0] * dx + matrix[1] * dy;
    out[at + 1] = centre[1] + matrix[2] * dx + matrix[3] * dy;
  }

  /** Symmetry: the core's reversed curve, sampled; R(1 − t) is compared with P(t). */
  function computeReversed() {
    const next = curve.reversed();
    reversedCurve?.free();
    reversedCurve = next;
    reversedSamples = reversedCurve.sampleUniform(CURVE_SAMPLES);
    reversedDistance = 0;
    for (let k = 0; k < CURVE_SAMPLES; k++) {
      const j = CURVE_SAMPLES - 1 - k;
      reversedDistance = Math.max(reversedDistance, Math.hypot(samples[2 * k] - reversedSamples[2 * j], samples[2 * k + 1] - reversedSamples[2 * j + 1]));
    }
  }

  /** Degree elevation: `elevate()` applied `elevations` times (intermediate curves freed). */
  function computeElevation() {
    firstElevation = null;
    let current = curve;
    for (let k = 0; k < work.elevations; k++) {
      const next = current.elevate();
      if (current !== curve) current.free();
      current = next;
      if (k === 0) firstElevation = current.controlPoints();
    }
    elevatedPoints = current.controlPoints();
    if (current !== curve) current.free();
    if (!firstElevation) {
      const once = curve.elevate();
      firstElevation = once.controlPoints();
      once.free();
    }
  }

  /** Variation diminishing: crossings of the line with the polygon and with the curve. */
  function computeVariation() {
    const [[x0, y0], [x1, y1]] = work.line;
    polygonCrossings = curve.polygonLineCrossings(x0, y0, x1, y1);
    const ts = curve.intersectLine(x0, y0, x1, y1, INTERSECT_TOLERANCE);
    curveCrossings = ts.length;
    curveHits = ts.length ? curve.sample(ts) : null;
  }

  // ------------------------------------------------------------ drawing
  /** Draws the figure (screen, SVG and PNG exports all come through here). */
  function draw(r, v) {
    recompute();
    const theme = r.theme;
    const pts = work.points;

    if (work.property === "hull" && hull.length > 0) {
      r.beginPath();
      for (let k = 0; k < hull.length; k++) {
        const p = pts[hull[k]];
        if (k === 0) r.moveTo(v.sx(p[0]), v.sy(p[1]));
        else r.lineTo(v.sx(p[0]), v.sy(p[1]));
      }
      r.closePath();
      r.paint(theme.helperFill);
    }

    if (work.property === "variation") drawLine(r, v);

    // Control polygon and curve.
    r.beginPath();
    for (let i = 0; i < pts.length; i++) {
      if (i === 0) r.moveTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
      else r.lineTo(v.sx(pts[i][0]), v.sy(pts[i][1]));
    }
    r.paint(theme.polygon);
    flatPath(r, v, samples, 0, CURVE_SAMPLES);
    r.paint(theme.curve);

    switch (work.property) {
      case "affine":
        drawAffine(r, v);
        break;
      case "reversed":
        flatPath(r, v, reversedSamples, 0, CURVE_SAMPLES);
        r.paint(REVERSED_STYLE);
        for (const at of ARROW_TS) {
          chevron(r, v, samples, Math.round(at * (CURVE_SAMPLES - 1)), FORWARD_CHEVRON);
          chevron(r, v, reversedSamples, Math.round(at * (CURVE_SAMPLES - 1)), REVERSED_CHEVRON);
        }
        break;
      case "elevation":
        if (work.elevations > 0) {
          const count = elevatedPoints.length / 2;
          flatPath(r, v, elevatedPoints, 0, count);
          r.paint(theme.levelStroke[0]);
          for (let k = 0; k < count; k++) r.point(v.sx(elevatedPoints[2 * k]), v.sy(elevatedPoints[2 * k + 1]), theme.levelPoint[0]);
        }
        break;
      case "variation":
        if (curveHits) {
          for (let k = 0; k < curveCrossings; k++) r.point(v.sx(curveHits[2 * k]), v.sy(curveHits[2 * k + 1]), r.theme.pointOnCurve);
        }
        break;
    }

    handles.draw(r, v);
  }

  /** The mapped polygon and curve (green) and the mapped samples of the original (dots). */
  function drawAffine(r, v) {
    r.beginPath();
    for (let i = 0; i < mappedPoints.length; i++) {
      const q = mappedPoints[i];
      if (i === 0) r.moveTo(v.sx(q[0]), v.sy(q[1]));
      else r.lineTo(v.sx(q[0]), v.sy(q[1]));
    }
    r.paint(MAPPED_POLYGON_STYLE);
    flatPath(r, v, mappedSamples, 0, CURVE_SAMPLES);
    r.paint(MAPPED_CURVE_STYLE);
    for (let i = 0; i < mappedPoints.length; i++) r.point(v.sx(mappedPoints[i][0]), v.sy(mappedPoints[i][1]), MAPPED_POINT_STYLE);
    for (let k = 0; k < MAPPED_DOTS; k++) r.point(v.sx(dots[2 * k]), v.sy(dots[2 * k + 1]), DOT_STYLE);
  }

  /** The infinite line through the two line handles, across the whole canvas. */
  function drawLine(r, v) {
    const a = work.line[0];
    const b = work.line[1];
    const px = v.sx(a[0]);
    const py = v.sy(a[1]);
    const dx = v.sx(b[0]) - px;
    const dy = v.sy(b[1]) - py;
    const length = Math.hypot(dx, dy);
    if (length < 1e-9) return;
    const reach = (v.width + v.height) / length + 1;
    r.beginPath();
    r.moveTo(px - dx * reach, py - dy * reach);
    r.lineTo(px + dx * reach, py + dy * reach);
    r.paint(LINE_STYLE);
  }

  /** A chevron at sample k of a flat sample list, pointing to the next sample (direction of t). */
  function chevron(r, v, flat, k, style) {
    const k0 = Math.max(0, Math.min(k, CURVE_SAMPLES - 2));
    const x = v.sx(flat[2 * k0]);
    const y = v.sy(flat[2 * k0 + 1]);
    let dx = v.sx(flat[2 * k0 + 2]) - x;
    let dy = v.sy(flat[2 * k0 + 3]) - y;
    const length = Math.hypot(dx, dy);
    if (length < 1e-9) return;
    dx /= length;
    dy /= length;
    const size = CHEVRON_PX * r.scale;
    const c = Math.cos(CHEVRON_ANGLE);
    const s = Math.sin(CHEVRON_ANGLE);
    r.beginPath();
    r.moveTo(x - size * (dx * c - dy * s), y - size * (dy * c + dx * s));
    r.lineTo(x, y);
    r.lineTo(x - size * (dx * c + dy * s), y - size * (dy * c - dx * s));
    r.paint(style);
  }

  // ------------------------------------------------------------ panels (formula, readout, label)
  function syncPanels() {
    const pts = work.points;
    const n = pts.length - 1;
    const kind = n <= 5 ? t(`curve.degree.${n}`) : t("curve.degree.n", { n });
    degreeText.textContent = t("bezierProperties.degree", { n, count: n + 1 });
    addButton.disabled = n + 1 >= MAX_POINTS;
    removeButton.disabled = n + 1 <= MIN_POINTS;
    note.textContent = t(`bezierProperties.note.${work.property}`);
    tableBlock.hidden = work.property !== "elevation";
    delete readout.dataset.maxDistance;
    delete readout.dataset.polygonPoints;
    delete readout.dataset.polygonCrossings;
    delete readout.dataset.curveCrossings;
    delete readout.dataset.hullVertices;
    const ints = allIntegers(pts.flat());
    const lines = [];
    let aria = "";
    switch (work.property) {
      case "hull": {
        readout.dataset.hullVertices = String(hull.length);
        readout.textContent = t("bezierProperties.readout.hull", { k: hull.length, names: hull.map((i) => `P${subscript(i)}`).join(", ") });
        const weights = [];
        for (let i = 0; i <= n; i++) {
          const b = sl.bernstein(n, i, 0.5);
          const f = exactFraction(b, 2 ** n);
          weights.push(f ? fractionTex(f) : fmt(b));
        }
        lines.push(`P(t) = \\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,P_i,\\qquad B_i^{${n}}(t) \\ge 0,\\quad \\sum_{i=0}^{${n}} B_i^{${n}}(t) = 1`);
        lines.push(`t = \\tfrac{1}{2}:\\quad B^{${n}}(\\tfrac12) = (${weights.join(",\\ ")}),\\quad \\text{${t("bezierProperties.formula.sum")}} = 1`);
        lines.push(`\\Rightarrow\\ P(t) \\in \\operatorname{conv}\\{P_0, \\dots, P_{${n}}\\} \\quad (${hull.length}\\ \\text{${t("bezierProperties.formula.hullVertices")}})`);
        aria = t("bezierProperties.aria.hull", { kind, k: hull.length });
        break;
      }
      case "affine": {
        readout.dataset.maxDistance = fmt(mappedDistance);
        readout.textContent = t("bezierProperties.readout.affine", { d: fmt(mappedDistance) });
        const [a, b, c, d] = matrix;
        lines.push(`A = R(${fmt(work.rotation, 0)}^\\circ)\\cdot ${fmt(work.scale, 2)}\\cdot\\begin{pmatrix}1 & ${fmt(work.shear, 2)}\\\\ 0 & 1\\end{pmatrix} = \\begin{pmatrix}${fmt(a)} & ${fmt(b)}\\\\ ${fmt(c)} & ${fmt(d)}\\end{pmatrix},\\quad c = (${fmt(centre[0])},\\ ${fmt(centre[1])})`);
        lines.push(`\\Phi(x) = c + A(x - c):\\qquad \\Phi\\Big(\\sum_i B_i^{${n}}(t)\\,P_i\\Big) = \\sum_i B_i^{${n}}(t)\\,\\Phi(P_i) \\quad\\text{${t("bezierProperties.formula.because")}}\\ \\sum_i B_i^{${n}}(t) = 1`);
        lines.push(`\\max_{t}\\ |\\Phi(P(t)) - \\tilde P(t)| = ${fmt(mappedDistance)}\\quad (${MAPPED_DOTS}\\ \\text{${t("bezierProperties.formula.samples")}})`);
        aria = t("bezierProperties.aria.affine", { kind, rotation: fmt(work.rotation, 0), scale: fmt(work.scale, 2), shear: fmt(work.shear, 2), d: fmt(mappedDistance) });
        break;
      }
      case "reversed": {
        readout.dataset.maxDistance = fmt(reversedDistance);
        readout.textContent = t("bezierProperties.readout.reversed", { d: fmt(reversedDistance) });
        lines.push(`R_i = P_{${n} - i}:\\quad R(t) = \\sum_{i=0}^{${n}} B_i^{${n}}(t)\\,P_{${n}-i} = \\sum_{j=0}^{${n}} B_{${n}-j}^{${n}}(t)\\,P_j = \\sum_{j=0}^{${n}} B_j^{${n}}(1-t)\\,P_j = P(1-t)`);
        lines.push(`B_j^{n}(t) = B_{n-j}^{n}(1-t),\\quad \\text{e.g. } B_0^{${n}}(\\tfrac14) = ${fmt(sl.bernstein(n, 0, 0.25))} = B_{${n}}^{${n}}(\\tfrac34)`);
        lines.push(`\\max_{t}\\ |R(1-t) - P(t)| = ${fmt(reversedDistance)}\\quad (${CURVE_SAMPLES}\\ \\text{${t("bezierProperties.formula.samples")}})`);
        aria = t("bezierProperties.aria.reversed", { kind, d: fmt(reversedDistance) });
        break;
      }
      case "elevation": {
        const count = elevatedPoints.length / 2;
        readout.dataset.polygonPoints = String(count);
        readout.textContent = t("bezierProperties.readout.elevation", { count, n: n + 1, e: work.elevations });
        const den = n + 1;
        const coord = (x) => {
          const f = ints ? exactFraction(x, den) : null;
          return f ? fractionTex(f) : fmt(x);
        };
        const q = [];
        for (let i = 0; i <= n + 1; i++) q.push(`(${coord(firstElevation[2 * i])},\\ ${coord(firstElevation[2 * i + 1])})`);
        lines.push(`Q_i = \\frac{i}{n+1}\\,P_{i-1} + \\Big(1 - \\frac{i}{n+1}\\Big)P_i,\\quad i = 0,\\dots,n+1,\\quad n = ${n}`);
        lines.push(`Q_1 = \\tfrac{1}{${den}}\\,P_0 + \\tfrac{${n}}{${den}}\\,P_1 = ${q[1]}`);
        lines.push(`Q = ${q.join(",\\ ")}`);
        lines.push(`${work.elevations}\\times:\\ ${n + 1} + ${work.elevations} = ${count}\\ \\text{${t("bezierProperties.formula.points")}}`);
        fillElevationTable(n, ints);
        aria = t("bezierProperties.aria.elevation", { kind, e: work.elevations, count });
        break;
      }
      case "variation": {
        readout.dataset.polygonCrossings = String(polygonCrossings);
        readout.dataset.curveCrossings = String(curveCrossings);
        readout.textContent = t("bezierProperties.readout.variation", { k: polygonCrossings, j: curveCrossings });
        lines.push(`\\#\\{\\text{${t("bezierProperties.formula.lineCurve")}}\\} \\le \\#\\{\\text{${t("bezierProperties.formula.linePolygon")}}\\}`);
        lines.push(`${curveCrossings} \\le ${polygonCrossings}`);
        aria = t("bezierProperties.aria.variation", { kind, k: polygonCrossings, j: curveCrossings });
        break;
      }
    }
    formula.set(lines);
    view.setLabel(aria);
  }

  /** The table of control points after one elevation (exact fractions for integer inputs). */
  function fillElevationTable(n, ints) {
    setText(tableTitle, t("bezierProperties.tableCaption", { n, m: n + 1, last: subscript(n + 1) }));
    if (tableCells.length !== n + 2) {
      tableCells = [];
      const head = [];
      const row = [];
      for (let i = 0; i <= n + 1; i++) {
        head.push(el("th", { scope: "col", text: `Q${subscript(i)}` }));
        const cell = el("td", { dataset: { elevated: String(i) } });
        tableCells.push(cell);
        row.push(cell);
      }
      table.replaceChildren(el("thead", {}, el("tr", {}, head)), el("tbody", {}, el("tr", {}, row)));
    }
    for (let i = 0; i <= n + 1; i++) {
      const x = firstElevation[2 * i];
      const y = firstElevation[2 * i + 1];
      const fx = ints ? exactFraction(x, n + 1) : null;
      const fy = ints ? exactFraction(y, n + 1) : null;
      setText(tableCells[i], fx && fy ? `(${fractionText(fx)}, ${fractionText(fy)})` : `(${fmt(x)}, ${fmt(y)})`);
    }
  }

  recompute();

  // ------------------------------------------------------------ contract
  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = new sl.BezierCurve(flatten(state.points), 2); // throws before anything changes
      const nextMapped = new sl.BezierCurve(flatten(state.points), 2);
      curve.free();
      mapped.free();
      curve = next;
      mapped = nextMapped;
      work = structuredClone(state);
      handles.forgetPointer();
      if (handles.selected >= handles.source.count()) handles.select(-1);
      propertyRadios.set(work.property);
      rotationSlider.set(work.rotation);
      scaleSlider.set(work.scale);
      shearSlider.set(work.shear);
      elevationSlider.set(work.elevations);
      showGroups();
      dirty = true;
      view.requestDraw();
      recompute();
    },
    destroy() {
      handles.destroy();
      formula.destroy();
      curve.free();
      mapped.free();
      reversedCurve?.free();
    },
  };
}
