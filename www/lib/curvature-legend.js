/**
 * The legend of a 3D figure's curvature shading (shading3d.js): a bar of the diverging scale in
 * the figure's 2D layer (canvas and SVG alike) with −m, 0 and +m under it and the title above.
 */
import { scaleColour } from "./shading3d.js";
import { formatNumber, t } from "./strings.js";

/** Legend size in CSS px at text scale 1, and its segments (SVG has no gradients here). */
const LEGEND = Object.freeze({ width: 132, height: 10, margin: 14, segments: 33, gap: 4 });
/** Numbers at the legend's ends: 3 significant digits. */
const LEGEND_NUMBER = Object.freeze({
  maximumSignificantDigits: 3,
  useGrouping: false,
  signDisplay: "negative",
});

/** The text at a legend end (also the test hook `data-legend`). */
export const legendNumber = (x) => formatNumber(x, LEGEND_NUMBER);

/**
 * The legend of a curvature shading in the upper-right corner of the 2D layer (the fitted
 * camera's frame leaves it free more often than the lower corners, where the near net lies): its
 * title ("Gaussian curvature K"), the bar from −m (blue) through 0 (white) to +m (vermillion),
 * and −m, 0, +m under it. `legend` = `{ shading, extent }`.
 */
export function drawLegend(r, legend) {
  const theme = r.theme;
  const sc = r.scale;
  const label = theme.labelSmall;
  const size = label.size * sc;
  const w = Math.min(LEGEND.width * sc, 0.45 * r.width);
  const h = LEGEND.height * sc;
  const x0 = r.width - LEGEND.margin * sc - w;
  const title = LEGEND.margin * sc;
  const y0 = title + size + LEGEND.gap * sc; // the bar's top
  r.text(t(`scene3d.legend.${legend.shading}`), x0 + w, title, label, "right", "top");
  const step = w / LEGEND.segments;
  for (let k = 0; k < LEGEND.segments; k++) {
    const s = (2 * (k + 0.5)) / LEGEND.segments - 1;
    r.beginPath();
    r.rect(x0 + k * step, y0, step + 0.5, h);
    r.paint(swatch(s));
  }
  r.beginPath();
  r.rect(x0, y0, w, h);
  r.paint(theme.axis);
  const ty = y0 + h + LEGEND.gap * sc;
  r.text(legendNumber(-legend.extent), x0, ty, label, "left", "top");
  r.text(legendNumber(0), x0 + w / 2, ty, label, "center", "top");
  r.text(legendNumber(legend.extent), x0 + w, ty, label, "right", "top");
}

const swatches = new Map();
/** The fill style of the legend's segment at s (made once). */
function swatch(s) {
  let style = swatches.get(s);
  if (!style) {
    style = Object.freeze({ fill: scaleColour(s) });
    swatches.set(s, style);
  }
  return style;
}
