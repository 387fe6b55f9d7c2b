/**
 * The sample strokes of the sketch demo (issue 25), in the order of its buttons: what a hand
 * with a mouse would draw, for readers who cannot draw (keyboard, screen reader) to explore the
 * same fits. Each is a path walked like a pointer — uneven speed (samples 3–7 px apart at the
 * presets' 60 px per unit) and a seeded jitter of ±0.4 px — and encoded as the demo stores a
 * stroke (lib/stroke-code.js). The button's words are `sketch.preset.<name>`.
 */
import { encodeStroke } from "../../lib/stroke-code.js";

/** Pixels per model unit the presets are drawn at (their tolerance in px is read with it). */
export const PRESET_SCALE = 60;
/** Their grid: 10⁻³ units (below a tenth of a pixel at 60 px per unit). */
const EXPONENT = -3;
/** Samples along the dense path, the pointer's mean step (units) and its jitter (units). */
const DENSE = 600;
const STEP = 5 / PRESET_SCALE;
const JITTER = 0.4 / PRESET_SCALE;

/** A small seeded generator (LCG): the same strokes on every page. */
function random(seed) {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

/** The polyline through `path(u)`, u ∈ [0, 1], walked by a pointer: flat [x0, y0, …]. */
function walk(path, seed) {
  const rand = random(seed);
  const dense = [];
  for (let j = 0; j <= DENSE; j++) dense.push(path(j / DENSE));
  const out = [];
  let j = 0;
  let along = 0; // distance left to walk before the next sample
  let [x, y] = dense[0];
  out.push(x, y);
  let k = 0;
  while (j < DENSE) {
    const step = STEP * (0.6 + 0.8 * (0.5 + 0.5 * Math.sin(k * 0.37)));
    along = step;
    while (j < DENSE && along > 0) {
      const [nx, ny] = dense[j + 1];
      const d = Math.hypot(nx - x, ny - y);
      if (d <= along) {
        along -= d;
        x = nx;
        y = ny;
        j++;
      } else {
        x += ((nx - x) * along) / d;
        y += ((ny - y) * along) / d;
        along = 0;
      }
    }
    out.push(x + (2 * rand() - 1) * JITTER, y + (2 * rand() - 1) * JITTER);
    k++;
  }
  const last = dense[DENSE];
  out[out.length - 2] = last[0];
  out[out.length - 1] = last[1];
  return out;
}

/** A polyline through `corners` at constant speed in u. */
function polyline(corners) {
  const lengths = [0];
  for (let i = 1; i < corners.length; i++) {
    const [ax, ay] = corners[i - 1];
    const [bx, by] = corners[i];
    lengths.push(lengths[i - 1] + Math.hypot(bx - ax, by - ay));
  }
  const total = lengths[lengths.length - 1];
  return (u) => {
    const s = u * total;
    let i = 1;
    while (i < corners.length - 1 && lengths[i] < s) i++;
    const f = (s - lengths[i - 1]) / (lengths[i] - lengths[i - 1]);
    const [ax, ay] = corners[i - 1];
    const [bx, by] = corners[i];
    return [ax + f * (bx - ax), ay + f * (by - ay)];
  };
}

const TAU = 2 * Math.PI;

const PATHS = {
  /** One and a half waves. */
  wave: (u) => [1 + 8 * u, 3 + 1.6 * Math.sin(3 * Math.PI * u)],
  /** A zigzag roof with a flat end: four corners. */
  corners: polyline([
    [1, 1.5],
    [2.5, 4.5],
    [4, 1.5],
    [5.5, 4.5],
    [7, 1.5],
    [9, 1.5],
  ]),
  /** A closed blob (the stroke returns to where it began). */
  blob: (u) => {
    const a = TAU * u;
    const r = 2.2 + 0.45 * Math.sin(3 * a) + 0.25 * Math.cos(2 * a);
    return [5 + 1.2 * r * Math.cos(a), 3 + r * Math.sin(a)];
  },
  /** Two turns of a spiral, outwards. */
  spiral: (u) => {
    const a = 4 * Math.PI * u;
    const r = 0.25 + 2.6 * u;
    return [5 + r * Math.cos(a), 3 + r * Math.sin(a)];
  },
  /** The letter S: two arcs. */
  letter: (u) => {
    if (u < 0.5) {
      const a = (20 + (250 * u) / 0.5) * (Math.PI / 180);
      return [5 + 1.4 * Math.cos(a), 4.2 + 1.2 * Math.sin(a)];
    }
    const a = (90 - (250 * (u - 0.5)) / 0.5) * (Math.PI / 180);
    return [5 + 1.4 * Math.cos(a), 1.8 + 1.2 * Math.sin(a)];
  },
};

/** The presets' names, in the order of the demo's buttons. */
export const PRESET_NAMES = Object.freeze(Object.keys(PATHS));

const strokes = new Map();

/**
 * The encoded stroke of the preset called `name`, drawn at `PRESET_SCALE`: walked on first use
 * (the five together took ~9 ms, ~35 at a phone's speed, of every page's start when they were
 * walked as the module loaded: the exercise list needs one).
 */
export function presetStroke(name) {
  if (!strokes.has(name)) {
    const seed = 7 + PRESET_NAMES.indexOf(name);
    strokes.set(name, encodeStroke(walk(PATHS[name], seed), EXPONENT));
  }
  return strokes.get(name);
}
