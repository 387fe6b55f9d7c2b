/**
 * A plot of a piecewise function of the parameter under a figure — a spline's C″(t) or C‴(t),
 * piece by piece — drawn in screen space in a band of the canvas (reserve it with the View's
 * `insets`; exports hold it). Several plots stack in one band and share the t axis, whose
 * ticks (the joins t_i) are labelled under the lowest one.
 *
 * Each piece [t_j, t_{j+1}] has its own colour (`CYCLE[j mod 4]`); a vector's x component is
 * drawn solid, y dashed (never colour alone); a dot at each end of each piece shows whether the
 * pieces meet at a join (continuity) or jump there. The joins are vertical lines; the value
 * axis is symmetric about 0, ±M with M the largest |value| (rounded up), written at the left.
 *
 * The samples are what the core returns for `pieceParameters(params, perPiece)`: `perPiece`
 * parameters per piece, from t_j to just before t_{j+1} (a spline is right-continuous, so the
 * value *at* a join belongs to the next piece; the left piece's limit is read just inside it).
 *
 *   const ts = pieceParameters(spline.params(), 2);          // C″ is linear per piece: 2 suffice
 *   const values = spline.sampleDerivatives(ts, 2);          // flat [x, y] per parameter
 *   plot.place(x0, x1, top, bottom, scale, true);                  // true: t labels under it
 *   plot.draw(r, { values, dim: 2, perPiece: 2, params, title: "C″(t)" });
 */
import { CYCLE, themed } from "./theme.js";
import { shortNumber } from "./format.js";

/** The last sample of a piece sits this fraction of the piece's length before its end. */
export const PIECE_END_INSET = 1e-9;
/** Dash of the y component (CSS px at scale 1). */
const Y_DASH = Object.freeze([6, 4]);
/** Margins of the plot box inside its part of the band (CSS px at scale 1). */
const MARGIN = Object.freeze({ top: 22, right: 18, bottom: 8, left: 56, ticks: 24 });
/** Tick length and the least gap between tick labels (CSS px at scale 1). */
const TICK_PX = 5;
const TICK_LABEL_GAP_PX = 10;

const stylesFor = themed((theme) => ({
  pieces: CYCLE.map((colour) => [
    Object.freeze({ stroke: colour, width: 2, join: "round", cap: "round" }),
    Object.freeze({ stroke: colour, width: 2, join: "round", dash: Y_DASH }),
  ]),
  ends: CYCLE.map((colour) =>
    Object.freeze({ fill: colour, stroke: theme.background, width: 1, radius: 3 }),
  ),
  join: Object.freeze({ stroke: theme.helper, width: 1, dash: Object.freeze([2, 3]) }),
  zero: Object.freeze({ stroke: theme.polygon, width: 1 }),
  key: Object.freeze([
    Object.freeze({ stroke: theme.text, width: 2 }),
    Object.freeze({ stroke: theme.text, width: 2, dash: Y_DASH }),
  ]),
}));

/**
 * The parameters to sample a piecewise function at: for each piece j of `params` (t_0 < … <
 * t_m), `perPiece` ≥ 2 values t_j + Δ_j·k/(perPiece − 1), the last one moved inside by
 * PIECE_END_INSET·Δ_j. Written into `out` when it has the right length, else a new array.
 */
export function pieceParameters(params, perPiece, out = null) {
  const pieces = params.length - 1;
  const ts = out && out.length === pieces * perPiece ? out : new Float64Array(pieces * perPiece);
  for (let j = 0; j < pieces; j++) {
    const a = params[j];
    const delta = params[j + 1] - a;
    for (let k = 0; k < perPiece; k++) {
      const u = k === perPiece - 1 ? 1 - PIECE_END_INSET : k / (perPiece - 1);
      ts[j * perPiece + k] = a + delta * u;
    }
  }
  return ts;
}

/** The smallest "nice" number (1, 2 or 5 × 10^k) at least `value` (> 0). */
export function niceCeiling(value) {
  if (!(value > 0)) return 1;
  const power = 10 ** Math.floor(Math.log10(value));
  for (const step of [1, 2, 5, 10]) if (step * power >= value * (1 - 1e-12)) return step * power;
  return 10 * power;
}

export class PiecePlot {
  constructor() {
    this.x0 = 0;
    this.x1 = 0;
    this.y0 = 0;
    this.y1 = 0;
    this.top = 0;
    this.bottom = 0;
    this.tickLabels = false;
    this.a = 0;
    this.b = 1;
    this.limit = 1;
  }

  /**
   * Places the plot in the part [top, bottom] of the band (canvas px) between x0 and x1 (the
   * band's side edges); `tickLabels` leaves room under it for the t axis labels.
   */
  place(left, right, top, bottom, scale, tickLabels = false) {
    this.top = top;
    this.bottom = bottom;
    this.tickLabels = tickLabels;
    this.x0 = left + MARGIN.left * scale;
    this.x1 = right - MARGIN.right * scale;
    this.y1 = top + MARGIN.top * scale;
    this.y0 = bottom - (tickLabels ? MARGIN.ticks : MARGIN.bottom) * scale;
  }

  /** Canvas x of parameter t. */
  px(t) {
    return this.x0 + ((t - this.a) / (this.b - this.a)) * (this.x1 - this.x0);
  }

  /** Canvas y of value v (0 in the middle, ±limit at the edges). */
  py(v) {
    const middle = (this.y0 + this.y1) / 2;
    return middle - (v / this.limit) * ((this.y0 - this.y1) / 2);
  }

  /**
   * Draws the plot: `values` (flat, `dim` per parameter, `perPiece` parameters per piece, as
   * sampled at `pieceParameters(params, perPiece)`), the joins at `params`, the title at the
   * top left, `key` (two labels, x and y) at the top right.
   */
  draw(r, { values, dim, perPiece, params, title, key }) {
    const theme = r.theme;
    const styles = stylesFor(theme);
    const s = r.scale;
    const pieces = params.length - 1;
    this.a = params[0];
    this.b = params[pieces];
    let largest = 0;
    for (let k = 0; k < values.length; k++) largest = Math.max(largest, Math.abs(values[k]));
    this.limit = niceCeiling(largest);
    // Frame: the value axis, the zero line, the joins.
    r.beginPath();
    r.moveTo(this.x0, this.y1);
    r.lineTo(this.x0, this.y0);
    r.paint(theme.axis);
    r.beginPath();
    r.moveTo(this.x0, this.py(0));
    r.lineTo(this.x1, this.py(0));
    r.paint(styles.zero);
    r.beginPath();
    for (let j = 0; j <= pieces; j++) {
      r.moveTo(this.px(params[j]), this.y1);
      r.lineTo(this.px(params[j]), this.y0);
    }
    r.paint(styles.join);
    const labelX = this.x0 - 6 * s;
    const limitText = shortNumber(this.limit);
    r.text(limitText, labelX, this.y1, theme.labelSmall, "right", "middle");
    r.text("0", labelX, this.py(0), theme.labelSmall, "right", "middle");
    r.text(`−${limitText}`, labelX, this.y0, theme.labelSmall, "right", "middle");
    r.text(title, this.x0 + 6 * s, this.top + 4 * s, theme.label, "left", "top");
    if (key) this.drawKey(r, key, styles);
    // The pieces, component by component, and their end dots.
    for (let j = 0; j < pieces; j++) {
      const colour = j % CYCLE.length;
      for (let c = 0; c < dim; c++) {
        r.beginPath();
        for (let k = 0; k < perPiece; k++) {
          const index = j * perPiece + k;
          const t = params[j] + ((params[j + 1] - params[j]) * k) / (perPiece - 1);
          const px = this.px(t);
          const py = this.py(values[index * dim + c]);
          if (k === 0) r.moveTo(px, py);
          else r.lineTo(px, py);
        }
        r.paint(styles.pieces[colour][Math.min(c, 1)]);
      }
      for (let c = 0; c < dim; c++) {
        const first = j * perPiece;
        const last = first + perPiece - 1;
        r.point(this.px(params[j]), this.py(values[first * dim + c]), styles.ends[colour]);
        r.point(this.px(params[j + 1]), this.py(values[last * dim + c]), styles.ends[colour]);
      }
    }
  }

  /** "— x  - - y" at the top right of the plot. */
  drawKey(r, key, styles) {
    const s = r.scale;
    const y = this.top + 12 * s;
    let x = this.x1;
    for (let c = key.length - 1; c >= 0; c--) {
      const width = r.measure(key[c], r.theme.labelSmall);
      r.text(key[c], x, y, r.theme.labelSmall, "right", "middle");
      x -= width + 6 * s;
      r.beginPath();
      r.moveTo(x - 22 * s, y);
      r.lineTo(x, y);
      r.paint(styles.key[c]);
      x -= 22 * s + 14 * s;
    }
  }

  /**
   * The t axis under the plot: a tick at every join t_i, labelled `labels[i]` while the labels
   * keep apart (the first and last always).
   */
  drawTicks(r, params, labels) {
    const theme = r.theme;
    const s = r.scale;
    r.beginPath();
    r.moveTo(this.x0, this.y0);
    r.lineTo(this.x1, this.y0);
    for (let i = 0; i < params.length; i++) {
      r.moveTo(this.px(params[i]), this.y0);
      r.lineTo(this.px(params[i]), this.y0 + TICK_PX * s);
    }
    r.paint(theme.axis);
    let right = -Infinity;
    const last = params.length - 1;
    const lastLeft = this.px(params[last]) - r.measure(labels[last], theme.labelSmall) / 2;
    for (let i = 0; i <= last; i++) {
      const x = this.px(params[i]);
      const half = r.measure(labels[i], theme.labelSmall) / 2;
      const gap = TICK_LABEL_GAP_PX * s;
      if (i !== last && (x - half < right + gap || x + half > lastLeft - gap)) continue;
      r.text(labels[i], x, this.y0 + (TICK_PX + 2) * s, theme.labelSmall, "center", "top");
      right = x + half;
    }
  }
}
