/**
 * The speed plot of curves compared on one axis (the `parametrization` demo), in a strip below
 * the figure (a `PlotStrip`, so exports hold it). Each curve c was sampled at SAMPLES equally
 * spaced values of its own parameter t ∈ [a_c, b_c]; the plot's x axis is the normalised
 *
 *   s = (t − a_c)/(b_c − a_c) ∈ [0, 1],
 *
 * and its y axis the speed with respect to s, |dC/ds| = (b_c − a_c)|C′(t)|, from 0 to the
 * largest speed shown. Under the axis, one row of ticks per curve at its data parameters s_i
 * (`ticks`), the row's style swatch at its left. The marker at s crosses the graphs and rows.
 * Everything drawn comes from the caller's `shown` entries `{ speed, ticks }` (core values).
 */
import { PlotStrip, drawPlotStrip } from "./plot-strip.js";
import { localeDecimal } from "./format.js";

/** Height of a tick row, the tick mark in it, the swatch length (CSS px at text scale 1). */
const ROW_PX = 11;
const TICK_PX = 8;
const SWATCH_PX = 30;
/** The margins of the plot's box in its strip (CSS px): the value labels left, the rows below. */
const MARGIN_TOP = 42;
const MARGIN_RIGHT = 24;
const MARGIN_LEFT = 50;
const AXIS_LABEL_PX = 18;
/** The plot's box keeps at least this height (CSS px × text scale), within MAX_FRACTION of the canvas. */
const MIN_BOX_PX = 70;
const MAX_FRACTION = 0.6;

/** Solid thin copies of the curve styles for the tick marks. */
const tickStyles = new WeakMap();

export class SpeedPlot {
  /** `{ fraction, minPx, shortFraction }` as `PlotStrip`'s; `rows`: most tick rows drawn. */
  constructor({ fraction, minPx, shortFraction, rows }) {
    this.rows = rows;
    this.strip = new PlotStrip({
      fraction,
      minPx,
      shortFraction,
      margin: Object.freeze({
        top: MARGIN_TOP,
        right: MARGIN_RIGHT,
        bottom: rows * ROW_PX + AXIS_LABEL_PX + 4,
        left: MARGIN_LEFT,
      }),
    });
  }

  /**
   * Height of the strip in a canvas `height` CSS px tall at text scale `scale` (the View's
   * bottom inset): `PlotStrip`'s, grown in lecture mode so that the box keeps MIN_BOX_PX
   * between its scaled margins.
   */
  height(height, scale = 1) {
    const margins = MARGIN_TOP + this.rows * ROW_PX + AXIS_LABEL_PX + 4;
    const needed = Math.round((margins + MIN_BOX_PX) * scale);
    return Math.max(this.strip.height(height), Math.min(needed, Math.round(height * MAX_FRACTION)));
  }

  /** Lays the strip out; the value range is [0, largest speed of the first `count` curves]. */
  layout(width, height, scale, shown, count) {
    const p = this.strip;
    p.layout(width, height, scale);
    p.top = height - this.height(height, scale);
    p.y1 = p.top + MARGIN_TOP * scale;
    let hi = 0;
    for (let c = 0; c < count; c++) for (const v of shown[c].speed) if (v > hi) hi = v;
    this.strip.lo = 0;
    this.strip.hi = hi > 0 ? hi : 1;
  }

  contains(x, y, slack = 0) {
    const p = this.strip;
    return x >= p.x0 - slack && x <= p.x1 + slack && y >= p.y1 - slack && y <= p.bottom;
  }

  /** s under canvas x: a sixteenth within `snapPx`, else a multiple of `step`. */
  snappedParameter(x, n, snapPx, step) {
    return this.strip.snappedParameter(x, n, snapPx, step);
  }

  /**
   * The frame, the speed graphs and tick rows of the first `count` curves of `shown` in
   * `styles[c]`, the marker at s (dots in `points[c]`) with `text` above; `names` `{ speed,
   * s }`: the axes' names (strings.js texts).
   */
  draw(r, shown, count, styles, points, s, text, names) {
    const theme = r.theme;
    const p = this.strip;
    const sc = r.scale;
    drawPlotStrip(r, p);
    r.beginPath();
    r.moveTo(p.x0, p.y1);
    r.lineTo(p.x0, p.y0);
    r.lineTo(p.x1, p.y0);
    r.paint(theme.axis);
    const lx = p.x0 - 6 * sc;
    r.text("0", lx, p.y0, theme.labelSmall, "right", "middle");
    r.text(
      localeDecimal(String(Number(p.hi.toPrecision(3)))),
      lx,
      p.y1,
      theme.labelSmall,
      "right",
      "middle",
    );
    r.text(names.speed, p.x0 - 6 * sc, p.top + 4 * sc, theme.labelSmall, "left", "top");
    for (let c = count - 1; c >= 0; c--) {
      const speed = shown[c].speed;
      const last = speed.length - 1;
      r.beginPath();
      for (let k = 0; k <= last; k++) {
        const x = p.x(k / last);
        const y = p.y(speed[k]);
        if (k === 0) r.moveTo(x, y);
        else r.lineTo(x, y);
      }
      r.paint(styles[c]);
    }
    // One row of ticks per curve at its data parameters, the curve's swatch on the left.
    const ticks = solidTicks(theme, styles);
    for (let c = 0; c < count; c++) {
      const y = p.y0 + (4 + c * ROW_PX) * sc;
      r.beginPath();
      r.moveTo(p.x0 - (SWATCH_PX + 8) * sc, y + (TICK_PX / 2) * sc);
      r.lineTo(p.x0 - 8 * sc, y + (TICK_PX / 2) * sc);
      r.paint(styles[c]);
      r.beginPath();
      for (const u of shown[c].ticks) {
        r.moveTo(p.x(u), y);
        r.lineTo(p.x(u), y + TICK_PX * sc);
      }
      r.paint(ticks[c]);
    }
    const below = p.y0 + (4 + count * ROW_PX + 2) * sc;
    r.text("0", p.x0, below, theme.labelSmall, "center", "top");
    // The axis name after "0", the marker's line stopping above it.
    r.text("1", p.x1, below, theme.labelSmall, "center", "top");
    r.text(names.s, p.x0 + 16 * sc, below, theme.labelSmall, "left", "top");
    // The marker: a line through graphs and rows at s, a dot on each graph.
    const mx = p.x(s);
    r.beginPath();
    r.moveTo(mx, p.y1 - 2 * sc);
    r.lineTo(mx, p.y0 + (4 + count * ROW_PX) * sc);
    r.paint(theme.marker);
    for (let c = 0; c < count; c++) {
      const speed = shown[c].speed;
      const k = Math.round(s * (speed.length - 1));
      r.point(mx, p.y(speed[k]), points[c]);
    }
    const align = s < 0.1 ? "left" : s > 0.9 ? "right" : "center";
    r.text(text, mx, p.y1 - 4 * sc, theme.labelPoint, align, "bottom");
  }
}

/** The tick styles of `styles`: their colours, solid, 1.5 px (made once per style list). */
function solidTicks(theme, styles) {
  let made = tickStyles.get(styles);
  if (!made) {
    made = styles.map((style) => Object.freeze({ stroke: style.stroke, width: 1.5 }));
    tickStyles.set(styles, made);
  }
  return made;
}
