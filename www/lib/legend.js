/**
 * A key drawn in the figure (so exports carry it): one row per entry, a short sample of the
 * entry's line style (colour and dash), or three dots of a point style, and its label beside
 * it, rows stacked downwards from (x, y), the vertical middle of the first row. Lengths are CSS
 * px at text scale 1 (times `r.scale`); labels are strings.js keys resolved at draw time (the
 * language may change). Allocates nothing.
 *
 *   const KEY = Object.freeze([{ style: (theme) => theme.compareCurve[2], label: "conics.legendParabola" }]);
 *   drawLegend(r, KEY, 12, 42);
 */
import { t } from "./strings.js";

/** Length of an entry's sample, gap between sample and label, and row height (CSS px). */
export const LEGEND_SWATCH_PX = 26;
export const LEGEND_GAP_PX = 6;
export const LEGEND_ROW_PX = 22;
/** Where the three dots of a `dots` entry sit along the sample (CSS px from its start). */
const DOTS_PX = Object.freeze([4, 13, 22]);

/** A style given as it is or as `(theme) => style` (a style of the current theme). */
const themed = (style, theme) => (typeof style === "function" ? style(theme) : style);

/**
 * Draws `entries` with renderer `r`: `[{ label, style }]` (a stroke) or `[{ label, dots }]` (a
 * point style, drawn as three dots). Returns the height taken, CSS px at scale 1.
 */
export function drawLegend(r, entries, x, y, layout = {}) {
  const { swatch = LEGEND_SWATCH_PX, gap = LEGEND_GAP_PX, row = LEGEND_ROW_PX } = layout;
  const s = r.scale;
  for (let k = 0; k < entries.length; k++) {
    const entry = entries[k];
    const yk = (y + k * row) * s;
    if (entry.dots) {
      const style = themed(entry.dots, r.theme);
      for (const dx of DOTS_PX) r.point((x + dx) * s, yk, style);
    } else {
      r.beginPath();
      r.moveTo(x * s, yk);
      r.lineTo((x + swatch) * s, yk);
      r.paint(themed(entry.style, r.theme));
    }
    r.text(t(entry.label), (x + swatch + gap) * s, yk, r.theme.labelSmall, "left", "middle");
  }
  return entries.length * row;
}

/** The key in the figure's top-left corner: left edge, middle of the first row, row height (CSS px). */
const CORNER_X = 12;
const CORNER_Y = 16;
const CORNER_ROW_PX = 21;

/** Draws `entries` as the figure's top-left key (keep a band free for it with the View's `insets`). */
export function drawCornerLegend(r, entries) {
  return drawLegend(r, entries, CORNER_X, CORNER_Y, { row: CORNER_ROW_PX });
}
