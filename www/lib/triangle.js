/**
 * A construction triangle as the core returns it (`deCasteljau(t)`, `deBoor(u)`, Aitken's
 * triangle): the levels concatenated, level 0 with n + 1 points first, level r with n + 1 − r,
 * the apex last. Drawing: each level a polyline in the level colours (ui.md), its points, and a
 * label beside the leg of the level below that the point divides, on the side away from the
 * construction.
 */
import { normalAwayFrom, placeLabel } from "./handles.js";
import { subscript, superscript } from "./format.js";

/** Index (in points) where `level` starts in a triangle whose level 0 has n + 1 points. */
export function levelStart(n, level) {
  // Levels 0 … level-1 hold (n+1) + n + … + (n + 2 - level) points.
  return level * (n + 1) - (level * (level - 1)) / 2;
}

/** Cached level labels such as "p₀¹" (de Casteljau) or "d₃²" (de Boor). */
export class LevelLabels {
  /**
   * @param {string} letter the point letter.
   * @param {(i: number, level: number) => number} [index] the subscript shown.
   */
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

/** Labels each point beside its leg, with no memory of the others (`legLabel`). */
const BESIDE_THE_LEG = Object.freeze({ place: legLabel, points: null });

/**
 * Draws levels 1 … n − 1 of `triangle` (flat [x, y, …]) with their points, and labels them
 * with `labels.get(i, level)` when `labels` is given. `centre` is [x, y] in canvas px: labels go
 * on the side away from it (the centroid of the control points). With a `placer`
 * (LegLabelPlacer, its `points` set to the control points) labels also keep clear of each other.
 */
export function drawLevels(r, v, triangle, n, centre, labels = null, placer = null) {
  const labeller = placer ?? BESIDE_THE_LEG;
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
      if (!labels) continue;
      const text = labels.get(j, level);
      labeller.place(
        r,
        v,
        triangle,
        n,
        level,
        j,
        text,
        centre,
        theme.labelSmall,
        style.radius * r.scale,
        labeller.points,
      );
    }
    offset += count;
  }
}

/**
 * Labels point j of level `level` (≥ 1) at its canvas position, beside the leg of level
 * `level` − 1 that it divides, on the side away from `centre`.
 */
export function legLabel(r, v, triangle, n, level, j, text, centre, style, radius) {
  legNormal(v, triangle, n, level, j, centre, normal);
  placeLabel(r, text, normal[2], normal[3], normal[0], normal[1], radius, style);
}

/** Scratch of `legNormal`: [nx, ny, x, y]. */
const normal = new Float64Array(4);

/**
 * Writes into `out` the unit normal (canvas px) of the leg of level `level` − 1 that point j
 * of `level` divides, turned away from `centre` (above left for a degenerate leg), and the
 * point's canvas position: [nx, ny, x, y].
 */
function legNormal(v, triangle, n, level, j, centre, out) {
  const p = levelStart(n, level) + j;
  const a = levelStart(n, level - 1) + j;
  out[2] = v.sx(triangle[2 * p]);
  out[3] = v.sy(triangle[2 * p + 1]);
  const ax = v.sx(triangle[2 * a]);
  const ay = v.sy(triangle[2 * a + 1]);
  const bx = v.sx(triangle[2 * a + 2]);
  const by = v.sy(triangle[2 * a + 3]);
  return normalAwayFrom(ax, ay, bx, by, out[2], out[3], centre[0], centre[1], out);
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

/**
 * Candidate label directions around a construction point, as (normal, leg) components and a
 * bonus in px for the plain normals; a label's centre is probed `LABEL_PROBE_PX` from its point.
 */
const LABEL_DIRECTIONS = Object.freeze([
  1,
  0,
  4,
  -1,
  0,
  4,
  Math.SQRT1_2,
  Math.SQRT1_2,
  0,
  Math.SQRT1_2,
  -Math.SQRT1_2,
  0,
  -Math.SQRT1_2,
  Math.SQRT1_2,
  0,
  -Math.SQRT1_2,
  -Math.SQRT1_2,
  0,
]);
const LABEL_PROBE_PX = 14;

/**
 * Leg labels that keep clear of each other (the de Boor triangle, where legs cross): of six
 * directions (the leg's two normals and the four diagonals between normal and leg), the one
 * whose label centre keeps farthest from the other triangle points, the control points and the
 * labels already placed in this frame wins, the normals slightly preferred; the side away from
 * `centre` breaks ties. With `minClearance` (CSS px at text scale 1), a label whose best place
 * comes nearer than that to any of them is left out (a table names every point). `reset()` at
 * the start of each frame; nothing is allocated per label.
 */
export class LegLabelPlacer {
  /**
   * @param {number} capacity most labels remembered per frame.
   * @param {number} minClearance labels that cannot keep this far (px) are left out; 0: none.
   */
  constructor(capacity = 32, minClearance = 0) {
    this.placed = new Float64Array(2 * capacity);
    this.count = 0;
    this.minClearance = minClearance;
    /** The last `choose`: the direction [dx, dy] (unit, canvas px) and the point [x, y]. */
    this.chosen = new Float64Array(4);
  }

  reset() {
    this.count = 0;
  }

  /**
   * Labels point j of level `level` (≥ 1) of a triangle whose level 0 has n + 1 points, keeping
   * clear of `points` ([[x, y], …] world) too; left out (false) when it cannot keep
   * `minClearance` clear.
   */
  place(r, v, triangle, n, level, j, text, centre, style, radius, points) {
    if (!this.choose(r, v, triangle, n, level, j, centre, radius, points, false)) return false;
    this.draw(r, text, style, radius);
    return true;
  }

  /**
   * Picks the place of point j's label and remembers it, without drawing it (`draw` draws the
   * last choice): reserve a label that must be drawn later (on top) before the others are placed.
   * `always` ignores `minClearance`. False when the label is left out.
   */
  choose(r, v, triangle, n, level, j, centre, radius, points, always = true) {
    const self = levelStart(n, level) + j;
    legNormal(v, triangle, n, level, j, centre, normal);
    const nx = normal[0];
    const ny = normal[1];
    const x = normal[2];
    const y = normal[3];
    const lx = -ny; // the leg's direction
    const ly = nx;
    const reach = radius + LABEL_PROBE_PX * r.scale;
    const all = levelStart(n, n + 1);
    let bestX = nx;
    let bestY = ny;
    let bestScore = -Infinity;
    let bestClearance = 0;
    for (let c = 0; c < LABEL_DIRECTIONS.length; c += 3) {
      const dx = LABEL_DIRECTIONS[c] * nx + LABEL_DIRECTIONS[c + 1] * lx;
      const dy = LABEL_DIRECTIONS[c] * ny + LABEL_DIRECTIONS[c + 1] * ly;
      const qx = x + dx * reach;
      const qy = y + dy * reach;
      let clearance = Infinity;
      for (let k = 0; k < all; k++) {
        if (k !== self)
          clearance = Math.min(
            clearance,
            Math.hypot(v.sx(triangle[2 * k]) - qx, v.sy(triangle[2 * k + 1]) - qy),
          );
      }
      for (const [px, py] of points)
        clearance = Math.min(clearance, Math.hypot(v.sx(px) - qx, v.sy(py) - qy));
      for (let k = 0; k < this.count; k++)
        clearance = Math.min(
          clearance,
          Math.hypot(this.placed[2 * k] - qx, this.placed[2 * k + 1] - qy),
        );
      const score = clearance + LABEL_DIRECTIONS[c + 2] * r.scale;
      if (score > bestScore) {
        bestScore = score;
        bestClearance = clearance;
        bestX = dx;
        bestY = dy;
      }
    }
    if (!always && bestClearance < this.minClearance * r.scale) return false;
    if (this.count < this.placed.length / 2) {
      this.placed[2 * this.count] = x + bestX * reach;
      this.placed[2 * this.count + 1] = y + bestY * reach;
      this.count += 1;
    }
    const chosen = this.chosen;
    chosen[0] = bestX;
    chosen[1] = bestY;
    chosen[2] = x;
    chosen[3] = y;
    return true;
  }

  /** Draws `text` at the last `choose`, or at a copy of an earlier one (`chosen`). */
  draw(r, text, style, radius, chosen = this.chosen) {
    placeLabel(r, text, chosen[2], chosen[3], chosen[0], chosen[1], radius, style);
  }
}
