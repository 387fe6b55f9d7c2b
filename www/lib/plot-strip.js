/**
 * A plot in a strip along the bottom of a figure's canvas, drawn in screen space below the world
 * window (the View's `insets` keep the strip free of it, so SVG/PNG exports hold both). The strip
 * is `fraction` of the canvas height, at least `minPx` as long as that stays within
 * `shortFraction` of the height (a short canvas, e.g. a gallery thumbnail, keeps room for the
 * curve). Inside it the plot's box leaves `margin` free (CSS px at text scale 1; the axis labels
 * live there). The box maps linearly, in canvas px (y down):
 *
 *   x(u) = x0 + u · (x1 − x0),   u ∈ [0, 1] (the parameter),
 *   y(v) = y0 − (v − lo) / (hi − lo) · (y0 − y1),   v ∈ [lo, hi] (the value, [0, 1] unless set).
 *
 * The fields `{ x0, x1, y0, y1, top, bottom }` are what basis-plot.js `drawPlotFrame` reads.
 */
export class PlotStrip {
  /** `{ fraction, minPx, shortFraction, margin: { top, right, bottom, left } }`. */
  constructor({ fraction, minPx, shortFraction, margin }) {
    this.fraction = fraction;
    this.minPx = minPx;
    this.shortFraction = shortFraction;
    this.margin = margin;
    this.x0 = 0;
    this.x1 = 0;
    this.y0 = 0;
    this.y1 = 0;
    this.top = 0;
    this.bottom = 0;
    this.lo = 0;
    this.hi = 1;
  }

  /** Height of the strip in a canvas `height` CSS px tall. */
  height(height) {
    return Math.max(
      Math.round(height * this.fraction),
      Math.min(this.minPx, Math.round(height * this.shortFraction)),
    );
  }

  /** Lays out the strip and the plot's box for a canvas of width × height CSS px at text scale `scale`. */
  layout(width, height, scale) {
    const margin = this.margin;
    this.top = height - this.height(height);
    this.bottom = height;
    this.x0 = margin.left * scale;
    this.x1 = width - margin.right * scale;
    this.y0 = height - margin.bottom * scale; // value lo (y down on screen)
    this.y1 = this.top + margin.top * scale; // value hi
  }

  /** Canvas x of the parameter u (x0 at 0, x1 at 1). */
  x(u) {
    return this.x0 + u * (this.x1 - this.x0);
  }

  /** Canvas y of the value v (y0 at lo, y1 at hi). */
  y(v) {
    return this.y0 - ((v - this.lo) / (this.hi - this.lo)) * (this.y0 - this.y1);
  }

  /** The parameter under canvas x, clamped to [0, 1]. */
  parameterAt(x) {
    return Math.min(1, Math.max(0, (x - this.x0) / (this.x1 - this.x0)));
  }

  /**
   * The parameter under canvas x for a press or drag in the plot: the tick i/n (of n + 1 ticks)
   * when one lies within `snapPx`, else rounded to a multiple of `step` (a slider's).
   */
  snappedParameter(x, n, snapPx, step) {
    const u = this.parameterAt(x);
    const tick = Math.round(u * n);
    if (Math.abs(this.x(tick / n) - x) <= snapPx) return tick / n;
    const digits = Math.max(0, -Math.floor(Math.log10(step)));
    return Number((Math.round(u / step) * step).toFixed(digits));
  }

  /** Whether canvas (x, y) lies in the plot's box grown by `slack` px on every side. */
  contains(x, y, slack = 0) {
    return (
      x >= this.x0 - slack && x <= this.x1 + slack && y >= this.y1 - slack && y <= this.y0 + slack
    );
  }

  /**
   * The marker at parameter u: a line across the box (from just above y1 to y0), a dot at
   * y(values[i]) for every value, in `styles[i mod length]` (one per graph), and `text` above it,
   * aligned to stay inside near the ends (left below u = 0.1, right above 0.9).
   */
  drawMarker(r, u, text, values, styles) {
    const theme = r.theme;
    const mx = this.x(u);
    r.beginPath();
    r.moveTo(mx, this.y1 - 2 * r.scale);
    r.lineTo(mx, this.y0);
    r.paint(theme.marker);
    for (let i = 0; i < values.length; i++)
      r.point(mx, this.y(values[i]), styles[i % styles.length]);
    const align = u < 0.1 ? "left" : u > 0.9 ? "right" : "center";
    r.text(text, mx, this.y1 - 4 * r.scale, theme.labelPoint, align, "bottom");
  }

  /**
   * Ticks at u = i/n (i = 0 … n) below the parameter axis, `tick` CSS px long (at scale 1), and
   * under them `labels[i]`, every k-th one with the smallest k that keeps them `minGap` CSS px
   * apart (the last one always, a neighbour too close to it left out).
   */
  drawTicks(r, n, labels, { tick, minGap }) {
    const theme = r.theme;
    const labelEvery = Math.max(1, Math.ceil((minGap * r.scale) / ((this.x1 - this.x0) / n)));
    r.beginPath();
    for (let i = 0; i <= n; i++) {
      r.moveTo(this.x(i / n), this.y0);
      r.lineTo(this.x(i / n), this.y0 + tick * r.scale);
    }
    r.paint(theme.axis);
    for (let i = 0; i <= n; i++) {
      if (i !== n && (i % labelEvery !== 0 || n - i < labelEvery)) continue;
      const y = this.y0 + (tick + 2) * r.scale;
      r.text(labels[i], this.x(i / n), y, theme.labelSmall, "center", "top");
    }
  }
}

/**
 * The strip itself (canvas px): its background from `plot.top` to `plot.bottom` across the whole
 * canvas (covering anything panned into it) and the line along its top edge.
 */
export function drawPlotStrip(r, plot) {
  const theme = r.theme;
  r.beginPath();
  r.rect(0, plot.top, r.width, plot.bottom - plot.top);
  r.paint(theme.plotBackground);
  r.beginPath();
  r.moveTo(0, plot.top);
  r.lineTo(r.width, plot.top);
  r.paint(theme.axis);
}
