/**
 * A construction triangle as the core returns it (`deCasteljau(t)`, `deBoor(u)`, Aitken's
 * triangle): the levels concatenated, level 0 with n + 1 points first, level r with n + 1 − r,
 * the apex last. Drawing: each level a polyline in the level colours (ui.md), its points, and a
 * label beside the leg of the level below that the point divides, on the side away from the
 * construction.
 */
import { placeLabel } from "./handles.js";
import { subscript, superscript } from "./format.js";

/** Below this length (canvas px) a leg has no direction: its label goes above left. */
const DEGENERATE_LEG_PX = 1;

/** Index (in points) where `level` starts in a triangle whose level 0 has n + 1 points. */
export function levelStart(n, level) {
  // Levels 0 … level-1 hold (n+1) + n + … + (n + 2 - level) points.
  return level * (n + 1) - (level * (level - 1)) / 2;
}

/** Cached level labels such as "p₀¹" (de Casteljau) or "d₃²" (de Boor). */
export class LevelLabels {
  /** @param {string} letter the point letter. @param {(i: number, level: number) => number} [index] the subscript shown. */
  constructor(letter, index = (i) => i) {
    this.letter = letter;
    this.index = index;
    this.cache = new Map();
  }

  /** The label of point i of level `level`. */
  get(i, level) {
    const key = level * 1024 + i;
    let text = this.cache.get(key);
    if (text === undefined) {
      text = `${this.letter}${subscript(this.index(i, level))}${superscript(level)}`;
      this.cache.set(key, text);
    }
    return text;
  }
}

/**
 * Draws levels 1 … n − 1 of `triangle` (flat [x, y, …]) with their points, and labels them
 * with `labels.get(i, level)` when `labels` is given. `centre` is [x, y] in canvas px: labels go
 * on the side away from it (the centroid of the control points).
 */
export function drawLevels(r, v, triangle, n, centre, labels = null) {
  const theme = r.theme;
  let offset = n + 1; // level 1 starts after the n + 1 points of level 0
  for (let level = 1; level < n; level++) {
    const count = n + 1 - level;
    const colour = (level - 1) % theme.levelStroke.length;
    r.beginPath();
    for (let j = 0; j < count; j++) {
      const x = v.sx(triangle[2 * (offset + j)]);
      const y = v.sy(triangle[2 * (offset + j) + 1]);
      if (j === 0) r.moveTo(x, y);
      else r.lineTo(x, y);
    }
    r.paint(theme.levelStroke[colour]);
    const style = theme.levelPoint[colour];
    for (let j = 0; j < count; j++) {
      const x = v.sx(triangle[2 * (offset + j)]);
      const y = v.sy(triangle[2 * (offset + j) + 1]);
      r.point(x, y, style);
      if (labels) legLabel(r, v, triangle, n, level, j, labels.get(j, level), centre, theme.labelSmall, style.radius * r.scale);
    }
    offset += count;
  }
}

/**
 * Labels point j of level `level` (≥ 1) at its canvas position, beside the leg of level
 * `level` − 1 that it divides, on the side away from `centre`.
 */
export function legLabel(r, v, triangle, n, level, j, text, centre, style, radius) {
  const p = levelStart(n, level) + j;
  const x = v.sx(triangle[2 * p]);
  const y = v.sy(triangle[2 * p + 1]);
  const a = levelStart(n, level - 1) + j;
  let nx = v.sy(triangle[2 * a + 1]) - v.sy(triangle[2 * a + 3]);
  let ny = v.sx(triangle[2 * a + 2]) - v.sx(triangle[2 * a]);
  const length = Math.hypot(nx, ny);
  if (length < DEGENERATE_LEG_PX) {
    nx = -Math.SQRT1_2;
    ny = -Math.SQRT1_2;
  } else {
    nx /= length;
    ny /= length;
  }
  if ((x - centre[0]) * nx + (y - centre[1]) * ny < 0) {
    nx = -nx;
    ny = -ny;
  }
  placeLabel(r, text, x, y, nx, ny, radius, style);
}

/** Writes the canvas-px centroid of `points` ([[x, y], …]) into `out` and returns it. */
export function screenCentroid(v, points, out) {
  let cx = 0;
  let cy = 0;
  for (const [x, y] of points) {
    cx += v.sx(x);
    cy += v.sy(y);
  }
  out[0] = cx / points.length;
  out[1] = cy / points.length;
  return out;
}
