/**
 * Clipping for drawing: the part of a segment inside an axis-aligned box, so a path that runs
 * off to infinity (a rational curve near a pole, drawn from its homogeneous samples) is drawn
 * only where it is on screen, and the demo knows where it leaves. Drawing support, not a curve
 * algorithm.
 */

/**
 * Liang–Barsky: clips the segment A(ax, ay)–B(bx, by) to the box [x0, x1] × [y0, y1]. With
 * P(s) = A + s (B − A), each side gives p·s ≤ q (p = ∓dx or ∓dy, q the distance of A from that
 * side): p < 0 raises the entry s₀ to q/p, p > 0 lowers the exit s₁ to q/p, p = 0 with q < 0 is
 * parallel and outside. Writes the visible part P(s₀)–P(s₁) into `out` (x, y, x, y; an end that
 * is not clipped is copied exactly, so `out[0] === ax` tells it was not) and returns false when
 * nothing is visible (s₀ > s₁).
 */
export function clipSegment(ax, ay, bx, by, x0, y0, x1, y1, out) {
  const dx = bx - ax;
  const dy = by - ay;
  let t0 = 0;
  let t1 = 1;
  for (let k = 0; k < 4; k++) {
    const p = k === 0 ? -dx : k === 1 ? dx : k === 2 ? -dy : dy;
    const q = k === 0 ? ax - x0 : k === 1 ? x1 - ax : k === 2 ? ay - y0 : y1 - ay;
    if (p === 0) {
      if (q < 0) return false;
    } else {
      const r = q / p;
      if (p < 0) t0 = Math.max(t0, r);
      else t1 = Math.min(t1, r);
      if (t0 > t1) return false;
    }
  }
  out[0] = t0 === 0 ? ax : ax + t0 * dx;
  out[1] = t0 === 0 ? ay : ay + t0 * dy;
  out[2] = t1 === 1 ? bx : ax + t1 * dx;
  out[3] = t1 === 1 ? by : ay + t1 * dy;
  return true;
}

/** Up to `max` canvas points where a clipped path leaves or enters the box (scratch, made once). */
export class ExitMarks {
  constructor(max) {
    this.xy = new Float64Array(2 * max);
    this.count = 0;
  }

  clear() {
    this.count = 0;
  }

  add(x, y) {
    if (2 * this.count >= this.xy.length) return;
    this.xy[2 * this.count] = x;
    this.xy[2 * this.count + 1] = y;
    this.count += 1;
  }
}

const segment = new Float64Array(4);

/**
 * The path of a rational curve from its homogeneous samples `hom` (X, Y, W triples, `count` of
 * them, e.g. the core's `sampleUniform` of the 3D curve on (wᵢxᵢ, wᵢyᵢ, wᵢ)): the central
 * projection (X/W, Y/W) of each sample, joined sample to sample, clipped to the canvas box
 * `box` [x0, y0, x1, y1]. A segment whose ends have |W| ≤ `zeroW` or W of opposite signs
 * crosses a pole (the point runs off to infinity and comes back from the other side): it is
 * left out, so the path breaks there. Where a piece leaves or enters the box goes into `exits`
 * (an `ExitMarks`, for "∞" marks). Starts a new path; the caller paints it.
 */
export function projectedPath(r, v, hom, count, zeroW, box, exits) {
  r.beginPath();
  let pen = false;
  for (let k = 0; k + 1 < count; k++) {
    const wa = hom[3 * k + 2];
    const wb = hom[3 * k + 5];
    if (Math.abs(wa) <= zeroW || Math.abs(wb) <= zeroW || wa > 0 !== wb > 0) {
      pen = false;
      continue;
    }
    const ax = v.sx(hom[3 * k] / wa);
    const ay = v.sy(hom[3 * k + 1] / wa);
    const bx = v.sx(hom[3 * k + 3] / wb);
    const by = v.sy(hom[3 * k + 4] / wb);
    if (!clipSegment(ax, ay, bx, by, box[0], box[1], box[2], box[3], segment)) {
      pen = false;
      continue;
    }
    const entered = segment[0] !== ax || segment[1] !== ay;
    if (!pen || entered) {
      r.moveTo(segment[0], segment[1]);
      if (entered) exits.add(segment[0], segment[1]);
    }
    r.lineTo(segment[2], segment[3]);
    pen = segment[2] === bx && segment[3] === by;
    if (!pen) exits.add(segment[2], segment[3]);
  }
}
