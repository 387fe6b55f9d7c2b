/**
 * The cubic Hermite basis on u ∈ [0, 1] from the core, and its plot in a strip under a figure:
 *
 *   H0 = 2u³ − 3u² + 1,  H1 = −2u³ + 3u²,  H2 = u³ − 2u² + u,  H3 = u³ − u²
 *
 * (`sl.hermiteBasis(u)` → [H0, H1, H2, H3](u)). `basisGraphs(sl)` → H0 … H3 at BASIS_SAMPLES
 * values of u, function-major (basis-plot.js `drawGraph`'s layout), asked of the core once and
 * kept; `hermitePlot` (a PlotStrip, values from −1/4 to 1: H3 dips to −4/27; reserve its
 * `height` with the View's insets) and `drawHermitePlot(r, graphs, u, values, markerText)`.
 */
import { PlotStrip, drawPlotStrip } from "./plot-strip.js";
import { drawGraph } from "./basis-plot.js";

/** Samples of each basis function on [0, 1]. */
export const BASIS_SAMPLES = 121;
export const HERMITE_NAMES = Object.freeze(["H₀", "H₁", "H₂", "H₃"]);

/** The graphs, once asked of the core (they depend on nothing). */
let graphs = null;

/** H0 … H3 at BASIS_SAMPLES values of u ∈ [0, 1], function-major (from `sl.hermiteBasis`). */
export function basisGraphs(sl) {
  if (graphs) return graphs;
  const out = new Float64Array(4 * BASIS_SAMPLES);
  for (let k = 0; k < BASIS_SAMPLES; k++) {
    const h = sl.hermiteBasis(k / (BASIS_SAMPLES - 1));
    for (let i = 0; i < 4; i++) out[i * BASIS_SAMPLES + k] = h[i];
  }
  graphs = out;
  return graphs;
}

/** The plot's strip: 0.3 of the canvas, at least 130 px; u from x0 to x1, values −1/4 … 1. */
export const hermitePlot = new PlotStrip({
  fraction: 0.3,
  minPx: 130,
  shortFraction: 0.45,
  margin: Object.freeze({ top: 26, right: 30, bottom: 26, left: 40 }),
});
hermitePlot.lo = -0.25;
hermitePlot.hi = 1;

/**
 * Where each name goes, [u, H(u)], above its graph where nothing runs close above (the marker's
 * text owns the top edge): H0 at u = 3/4, H1 at u = 0.35, H2 at u = 0.15 (H1 still below it),
 * and H3 under its dip at u = 2/3.
 */
const NAME_PLACES = Object.freeze([
  [0.75, 5 / 32],
  [0.35, 0.28175],
  [0.15, 0.108375],
  [2 / 3, -4 / 27],
]);
/** Gap between a value label or a name and what it names, CSS px. */
const GAP_PX = 5;

/** H0 … H3 over u ∈ [0, 1], the axis at 0, the line at 1, the marker at u with the values. */
export function drawHermitePlot(r, graphs, u, values, markerText) {
  const theme = r.theme;
  const plot = hermitePlot;
  plot.layout(r.width, r.height, r.scale);
  drawPlotStrip(r, plot);
  r.beginPath();
  r.moveTo(plot.x0, plot.y1);
  r.lineTo(plot.x0, plot.y0);
  r.moveTo(plot.x0, plot.y(0));
  r.lineTo(plot.x1, plot.y(0));
  r.paint(theme.axis);
  r.beginPath();
  r.moveTo(plot.x0, plot.y(1));
  r.lineTo(plot.x1, plot.y(1));
  r.paint(theme.helper);
  const gap = GAP_PX * r.scale;
  r.text("0", plot.x0 - gap, plot.y(0), theme.labelSmall, "right", "middle");
  r.text("1", plot.x0 - gap, plot.y(1), theme.labelSmall, "right", "middle");
  r.text("u", plot.x1 + gap, plot.y(0), theme.labelSmall, "left", "middle");
  for (let i = 0; i < 4; i++)
    drawGraph(r, graphs, i, BASIS_SAMPLES, sampleX, plotY, theme.basisStroke[i]);
  for (let i = 0; i < 4; i++) {
    const [at, value] = NAME_PLACES[i];
    const below = i === 3;
    const y = plot.y(value) + (below ? gap : -gap);
    r.text(HERMITE_NAMES[i], plot.x(at), y, theme.labelSmall, "center", below ? "top" : "bottom");
  }
  plot.drawMarker(r, u, markerText, values, theme.basisPoint);
}

const sampleX = (k) => hermitePlot.x(k / (BASIS_SAMPLES - 1));
const plotY = (value) => hermitePlot.y(value);
