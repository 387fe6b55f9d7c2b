/**
 * Path helpers for the 2D layer of a 3D figure (view3d.js): the same renderers (canvas and SVG)
 * as 2D figures, with space points mapped to the canvas by `view.project`. Each starts a new path;
 * then `r.paint(style)`. Nothing is allocated per call (one scratch array).
 */
import { SURFACE_COLOURS, WIREFRAME_OPACITY } from "./scene3d.js";
import { HUES, WIDTH, themed } from "./theme.js";

const s = new Float64Array(3);

/** The polyline through `[x, y, z]` points `from` … `to − 1`. */
export function pointsPath3(r, view, points, from = 0, to = points.length) {
  r.beginPath();
  for (let i = from; i < to; i++) {
    const p = points[i];
    view.project(p[0], p[1], p[2], s);
    if (i === from) r.moveTo(s[0], s[1]);
    else r.lineTo(s[0], s[1]);
  }
}

/** The polyline through the vertices of a flat `[x0, y0, z0, x1, …]` array. */
export function flatPath3(r, view, flat, from = 0, to = flat.length / 3) {
  r.beginPath();
  for (let i = from; i < to; i++) {
    view.project(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2], s);
    if (i === from) r.moveTo(s[0], s[1]);
    else r.lineTo(s[0], s[1]);
  }
}

/**
 * The control net of a rows × cols grid of `[x, y, z]` points (row-major, point (i, j) at
 * i·cols + j): every row, then every column, as one path.
 */
export function netPath(r, view, points, rows, cols) {
  r.beginPath();
  const to = (k, first) => {
    const p = points[k];
    view.project(p[0], p[1], p[2], s);
    if (first) r.moveTo(s[0], s[1]);
    else r.lineTo(s[0], s[1]);
  };
  for (let i = 0; i < rows; i++) for (let j = 0; j < cols; j++) to(i * cols + j, j === 0);
  for (let j = 0; j < cols; j++) for (let i = 0; i < rows; i++) to(i * cols + j, i === 0);
}

const vectorStyles = themed(() => ({
  iso: Object.freeze({ stroke: SURFACE_COLOURS.iso, width: 1 }),
  wireframe: Object.freeze({
    stroke: SURFACE_COLOURS.wireframe,
    width: 0.5,
    strokeAlpha: WIREFRAME_OPACITY,
  }),
}));

const curveStyles = new Map();
/** The stroke of a coloured curve entry `{ points, colour, width }` (made once per pair). */
function curveStyle(colour, width) {
  const key = `${colour} ${width}`;
  let style = curveStyles.get(key);
  if (!style) {
    style = Object.freeze({ stroke: colour ?? SURFACE_COLOURS.iso, width, join: "round" });
    curveStyles.set(key, style);
  }
  return style;
}

const wireStyles = new Map();
/** The stroke of a wireframe entry with a `colour` / `opacity` (made once per pair). */
function wireStyle(colour, opacity) {
  const key = `${colour} ${opacity}`;
  let style = wireStyles.get(key);
  if (!style) {
    style = Object.freeze({
      stroke: colour ?? SURFACE_COLOURS.wireframe,
      width: 0.5,
      strokeAlpha: opacity ?? WIREFRAME_OPACITY,
    });
    wireStyles.set(key, style);
  }
  return style;
}

/**
 * The WebGL content of `spec` (scene3d.js) as vector paths, for the SVG export: every grid line
 * of each wireframe (or every triangle edge; in its colour and opacity when given), then each curve (in its colour and width when it
 * is a `{ points, colour, width }` entry), projected — no hidden lines
 * removed, no silhouette. The shaded surface itself has no vector form.
 */
export function drawVectorScene(r, view, spec) {
  const styles = vectorStyles(r.theme);
  for (const { mesh, grid, colour, opacity } of spec?.wireframe ?? []) {
    const p = mesh.positions;
    r.beginPath();
    const line = (a, b) => {
      view.project(p[3 * a], p[3 * a + 1], p[3 * a + 2], s);
      r.moveTo(s[0], s[1]);
      view.project(p[3 * b], p[3 * b + 1], p[3 * b + 2], s);
      r.lineTo(s[0], s[1]);
    };
    if (grid) {
      const [rows, cols] = grid;
      for (let a = 0; a < rows; a++) {
        view.project(p[3 * a * cols], p[3 * a * cols + 1], p[3 * a * cols + 2], s);
        r.moveTo(s[0], s[1]);
        for (let b = 1; b < cols; b++) {
          const k = 3 * (a * cols + b);
          view.project(p[k], p[k + 1], p[k + 2], s);
          r.lineTo(s[0], s[1]);
        }
      }
      for (let b = 0; b < cols; b++) {
        view.project(p[3 * b], p[3 * b + 1], p[3 * b + 2], s);
        r.moveTo(s[0], s[1]);
        for (let a = 1; a < rows; a++) {
          const k = 3 * (a * cols + b);
          view.project(p[k], p[k + 1], p[k + 2], s);
          r.lineTo(s[0], s[1]);
        }
      }
    } else {
      const idx = mesh.indices;
      for (let t = 0; t + 2 < idx.length; t += 3) {
        line(idx[t], idx[t + 1]);
        line(idx[t + 1], idx[t + 2]);
        line(idx[t + 2], idx[t]);
      }
    }
    r.paint(colour || opacity != null ? wireStyle(colour, opacity) : styles.wireframe);
  }
  for (const curve of spec?.curves ?? []) {
    if (curve.points) {
      flatPath3(r, view, curve.points);
      r.paint(curveStyle(curve.colour, curve.width ?? 1));
    } else {
      flatPath3(r, view, curve);
      r.paint(styles.iso);
    }
  }
}

/** Length of the axis triad's arms and its distance from the corner, CSS px at scale 1. */
const TRIAD_PX = 22;
const TRIAD_MARGIN_PX = 34;
const AXES = ["x", "y", "z"];

const triadStyles = themed((theme) => ({
  arms: [HUES.vermillion, HUES.bluishGreen, HUES.blue].map((stroke) =>
    Object.freeze({ stroke, width: WIDTH.construction, cap: "round" }),
  ),
  labels: [HUES.vermillion, HUES.bluishGreen, HUES.blue].map((fill) =>
    Object.freeze({ fill, size: 13, weight: "bold", halo: theme.background }),
  ),
}));

const right = new Float64Array(3);
const up = new Float64Array(3);
const forward = new Float64Array(3);
const triadOrder = [0, 1, 2];

/**
 * A small x, y, z triad in the lower-left corner turned as the camera sees the axes (x
 * vermillion, y bluish green, z blue, each labelled); the arm pointing away is drawn first.
 */
export function drawTriad(r, view) {
  const styles = triadStyles(r.theme);
  const scale = r.scale;
  const ox = TRIAD_MARGIN_PX * scale;
  const oy = r.height - TRIAD_MARGIN_PX * scale;
  const arm = TRIAD_PX * scale;
  view.screenAxes(right, up, forward);
  triadOrder.sort((a, b) => forward[b] - forward[a]);
  for (const k of triadOrder) {
    const x = ox + arm * right[k];
    const y = oy - arm * up[k];
    r.beginPath();
    r.moveTo(ox, oy);
    r.lineTo(x, y);
    r.paint(styles.arms[k]);
    const lx = ox + (arm + 8 * scale) * right[k];
    const ly = oy - (arm + 8 * scale) * up[k];
    r.text(AXES[k], lx, ly, styles.labels[k], "center", "middle");
  }
}
