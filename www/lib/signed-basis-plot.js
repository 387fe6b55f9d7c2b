/**
 * A plot strip of basis functions that are not confined to [0, 1] — Lagrange's L_i, which sum
 * to 1 but go negative and overshoot — drawn in screen space below a figure (a `PlotStrip`, so
 * exports hold it). The value range follows the graphs, [min(lo, 0), max(hi, 1)], but stops at
 * [−`cap`, 1 + `cap`]: beyond it a graph is cut at the frame (its run outside is not drawn) and
 * the frame's edge says so (“≥ 3”). The parameter axis is the normalised one,
 *
 *   x(s),   s = (t − t_0)/(t_n − t_0) ∈ [0, 1],
 *
 * with ticks at the data parameters s_i. The values come from the core (i-major samples, one
 * graph per function, `count` samples each at s = k/(count − 1)); nothing is evaluated here.
 *
 *   const plot = new SignedBasisPlot({ fraction: 0.34, minPx: 140, shortFraction: 0.5, cap: 2 });
 *   plot.layout(r.width, r.height, r.scale, values);   // also sets the value range
 *   plot.drawFrame(r, { ticks, labels });  plot.drawGraphs(r, values, n + 1, count, highlight);
 *   plot.drawMarker(r, s, text, valuesAtT);
 */
import { PlotStrip, drawPlotStrip } from "./plot-strip.js";
import { localeDecimal, shortNumber } from "./format.js";

/** Margins of the plot's box inside the strip (CSS px at text scale 1): labels live there. */
const MARGIN = Object.freeze({ top: 26, right: 24, bottom: 30, left: 44 });
/** Tick length and the least gap between tick labels (CSS px). */
const TICK_PX = 5;
const TICK_LABEL_GAP_PX = 30;

export class SignedBasisPlot {
  /** `{ fraction, minPx, shortFraction }` as `PlotStrip`'s; `cap`: how far past [0, 1] the range may grow. */
  constructor({ fraction, minPx, shortFraction, cap }) {
    this.strip = new PlotStrip({ fraction, minPx, shortFraction, margin: MARGIN });
    this.cap = cap;
    this.clipped = { lo: false, hi: false };
    /** Scratch for the marker's dots, clamped into the range. */
    this.dots = new Float64Array(0);
  }

  /** Height of the strip in a canvas `height` CSS px tall (for the View's insets). */
  height(height) {
    return this.strip.height(height);
  }

  /** Lays the strip out for a canvas `width` × `height` and sets the value range from `values`. */
  layout(width, height, scale, values) {
    const strip = this.strip;
    strip.layout(width, height, scale);
    let lo = 0;
    let hi = 1;
    for (let k = 0; k < values.length; k++) {
      const v = values[k];
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    this.clipped.lo = lo < -this.cap;
    this.clipped.hi = hi > 1 + this.cap;
    strip.lo = Math.max(lo, -this.cap);
    strip.hi = Math.min(hi, 1 + this.cap);
  }

  /** Canvas x of the normalised parameter s and canvas y of the value v. */
  x(s) {
    return this.strip.x(s);
  }

  y(v) {
    return this.strip.y(Math.min(Math.max(v, this.strip.lo), this.strip.hi));
  }

  /** Whether canvas (x, y) lies in the plot's box grown by `slack` px. */
  contains(x, y, slack = 0) {
    return this.strip.contains(x, y, slack);
  }

  /** The normalised parameter under canvas x, clamped to [0, 1]. */
  parameterAt(x) {
    return this.strip.parameterAt(x);
  }

  /**
   * The strip, the value axis with 0 and 1 labelled (and the range's ends when beyond them), the
   * zero line, a dashed line at 1 with a dot at (s_i, 1) in the colour of L_i (each is 1 at its
   * own node), the parameter axis with a tick at every `ticks[i]` (normalised data parameters)
   * labelled `labels[i]` while labels keep apart, and `axisName` at its end.
   */
  drawFrame(r, ticks, labels, axisName) {
    const theme = r.theme;
    const p = this.strip;
    const s = r.scale;
    drawPlotStrip(r, p);
    const y0 = p.y(Math.max(0, p.lo));
    r.beginPath();
    r.moveTo(p.x0, p.y1);
    r.lineTo(p.x0, p.y0);
    r.moveTo(p.x0, y0);
    r.lineTo(p.x1, y0);
    r.paint(theme.axis);
    r.beginPath();
    r.moveTo(p.x0, p.y(1));
    r.lineTo(p.x1, p.y(1));
    r.paint(theme.helper);
    const lx = p.x0 - (TICK_PX + 2) * s;
    r.text("0", lx, y0, theme.labelSmall, "right", "middle");
    r.text("1", lx, p.y(1), theme.labelSmall, "right", "middle");
    const apart = (v, w) => Math.abs(p.y(v) - p.y(w)) > 16 * s;
    if (p.hi > 1 && apart(p.hi, 1))
      r.text(
        this.edgeText(p.hi, this.clipped.hi, "≥"),
        lx,
        p.y1,
        theme.labelSmall,
        "right",
        "middle",
      );
    if (p.lo < 0 && apart(p.lo, 0))
      r.text(
        this.edgeText(p.lo, this.clipped.lo, "≤"),
        lx,
        p.y0,
        theme.labelSmall,
        "right",
        "bottom",
      );
    // Ticks at the data parameters below the frame; labels thinned to keep apart (the last kept).
    r.beginPath();
    for (const u of ticks) {
      r.moveTo(p.x(u), p.y0);
      r.lineTo(p.x(u), p.y0 + TICK_PX * s);
    }
    r.paint(theme.axis);
    let last = -Infinity;
    const end = p.x(ticks[ticks.length - 1]);
    for (let i = 0; i < ticks.length; i++) {
      const x = p.x(ticks[i]);
      const isLast = i === ticks.length - 1;
      if (!isLast && (x - last < TICK_LABEL_GAP_PX * s || end - x < TICK_LABEL_GAP_PX * s))
        continue;
      r.text(labels[i], x, p.y0 + (TICK_PX + 2) * s, theme.labelSmall, "center", "top");
      last = x;
    }
    if (axisName)
      r.text(axisName, p.x1 + (TICK_PX + 2) * s, y0, theme.labelSmall, "left", "middle");
    // L_i(t_i) = 1: a dot in the function's colour where it touches 1 at its own node.
    for (let i = 0; i < ticks.length; i++)
      r.point(p.x(ticks[i]), p.y(1), theme.basisPoint[i % theme.basisPoint.length]);
  }

  /** "3" or "≥ 3" at a range end that cut graphs off. */
  edgeText(v, clipped, sign) {
    return clipped ? `${sign} ${shortNumber(v)}` : localeDecimal(String(Number(v.toFixed(2))));
  }

  /**
   * Graph i of i-major `values` (`count` samples): runs inside the range drawn, a run outside cut
   * at the frame's edge.
   */
  drawGraph(r, values, i, count, style) {
    const p = this.strip;
    const offset = i * count;
    let pen = false;
    let side = 0;
    let px = 0;
    let py = 0;
    r.beginPath();
    for (let k = 0; k < count; k++) {
      const v = values[offset + k];
      const out = v < p.lo ? -1 : v > p.hi ? 1 : 0;
      const x = p.x(k / (count - 1));
      const y = this.y(v);
      // A segment is drawn unless both ends lie beyond the same edge.
      if (k > 0 && (out === 0 || side === 0 || out !== side)) {
        if (!pen) r.moveTo(px, py);
        r.lineTo(x, y);
        pen = true;
      } else {
        pen = false;
      }
      side = out;
      px = x;
      py = y;
    }
    r.paint(style);
  }

  /** Every graph in the basis colours, the highlighted one (or -1) last and thicker. */
  drawGraphs(r, values, functions, count, highlight) {
    const theme = r.theme;
    const cycle = theme.basisStroke.length;
    for (let i = 0; i < functions; i++)
      if (i !== highlight) this.drawGraph(r, values, i, count, theme.basisStroke[i % cycle]);
    if (highlight >= 0)
      this.drawGraph(r, values, highlight, count, theme.basisHover[highlight % cycle]);
  }

  /** The marker at s with a dot per value of `values` (clamped into the range) and `text` above. */
  drawMarker(r, s, text, values) {
    if (this.dots.length !== values.length) this.dots = new Float64Array(values.length);
    const p = this.strip;
    for (let i = 0; i < values.length; i++)
      this.dots[i] = Math.min(Math.max(values[i], p.lo), p.hi);
    p.drawMarker(r, s, text, this.dots, r.theme.basisPoint);
  }
}
