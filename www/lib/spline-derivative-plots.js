/**
 * C″ (and optionally C‴) of a piecewise cubic plane curve, piece by piece, in a band along the
 * bottom of the figure (reserve it with the View's `insets`: `derivativeBandHeight`), the two
 * plots sharing the t axis (piece-plot.js). What it shows is what the core returns: one
 * `sampleDerivatives(ts, 2)` and one `(ts, 3)` at `derivativeParameters(params)`. A C2 spline's
 * C″ is continuous at the joins and its C‴ jumps; a C1 spline's C″ jumps too.
 *
 *   const ts = derivativeParameters(spline.params());
 *   const data = { params, second: spline.sampleDerivatives(ts, 2), third: …(ts, 3), joints, ticks };
 *   plots.draw(r, data, showThird, labels);          // labels: { second, third, x, y }
 *   derivativeFacts(data) → { secondStart, secondEnd, thirdFirst, thirdLast, jumps }
 */
import { drawPlotStrip } from "./plot-strip.js";
import { PiecePlot, pieceParameters } from "./piece-plot.js";

/** C″ is linear and C‴ constant on a cubic piece: two samples per piece draw them exactly. */
export const PER_PIECE = 2;
/** The band: fraction of the canvas height (C″ alone, C″ and C‴) and least height (CSS px). */
const BAND_FRACTION = Object.freeze([0.3, 0.46]);
const BAND_MIN_PX = Object.freeze([120, 200]);
/** The band never takes more than this fraction of the canvas. */
const BAND_MAX_FRACTION = 0.6;
/** Share of the band the upper (C″) plot takes when both are shown. */
const UPPER_SHARE = 0.47;

/** Where to sample the derivatives: two parameters per piece (pieceParameters). */
export function derivativeParameters(params) {
  return pieceParameters(params, PER_PIECE);
}

/** The band's height (CSS px) in a canvas `height` CSS px tall, with C‴ (`third`) or without. */
export function derivativeBandHeight(height, third) {
  const k = third ? 1 : 0;
  const wanted = Math.max(Math.round(height * BAND_FRACTION[k]), BAND_MIN_PX[k]);
  return Math.min(Math.round(height * BAND_MAX_FRACTION), wanted);
}

/**
 * What the plots show, read off the samples (flat [x, y] per parameter): C″ at t₀ and tₙ, C‴ on
 * the first and last piece; and the inner joins i where C‴ jumps, from the core's continuity
 * check of the pieces (`joints`: `CompositeBezier.continuity()`, joint i − 1 at t_i): c < 3.
 */
export function derivativeFacts({ params, second, third, joints }) {
  const last = (params.length - 1) * PER_PIECE - 1;
  const at = (values, k) => [values[2 * k], values[2 * k + 1]];
  return {
    secondStart: at(second, 0),
    secondEnd: at(second, last),
    thirdFirst: at(third, 0),
    thirdLast: at(third, last),
    jumps: joints.flatMap(({ c }, k) => (c < 3 ? [k + 1] : [])),
  };
}

export class SplineDerivativePlots {
  constructor() {
    this.upper = new PiecePlot();
    this.lower = new PiecePlot();
    this.strip = { top: 0, bottom: 0 };
    this.key = ["", ""];
    this.args = { values: null, dim: 2, perPiece: PER_PIECE, params: null, title: "", key: null };
  }

  /**
   * Draws the band: C″ (`data.second`), and C‴ (`data.third`) under it when `third`, the t axis
   * with `data.ticks` (one label per param) under the lowest. `labels`: `{ second, third, x, y }`
   * (the plots' titles, the names of the solid and dashed components); `band` the band's height
   * (CSS px; default `derivativeBandHeight`, the View's insets must agree). Allocates nothing.
   */
  draw(r, data, third, labels, band = derivativeBandHeight(r.height, third)) {
    const { strip, args, key } = this;
    strip.top = r.height - band;
    strip.bottom = r.height;
    drawPlotStrip(r, strip);
    key[0] = labels.x;
    key[1] = labels.y;
    args.key = key;
    args.params = data.params;
    const middle = third ? strip.top + band * UPPER_SHARE : r.height;
    this.upper.place(0, r.width, strip.top, middle, r.scale, !third);
    args.values = data.second;
    args.title = labels.second;
    this.upper.draw(r, args);
    if (third) {
      this.lower.place(0, r.width, middle, r.height, r.scale, true);
      args.values = data.third;
      args.title = labels.third;
      this.lower.draw(r, args);
    }
    (third ? this.lower : this.upper).drawTicks(r, data.params, data.ticks);
  }
}
