/**
 * A key drawn in the figure (so exports carry it): one row per entry, a short stroke in the
 * entry's line style (colour and dash) and its label beside it, rows stacked downwards from
 * (x, y), the vertical middle of the first row. Lengths are CSS px at text scale 1 (times
 * `r.scale`); labels are strings.js keys resolved at draw time. Allocates nothing.
 *
 *   const KEY = Object.freeze([{ style: (theme) => theme.compareCurve[2], label: "conics.legendParabola" }]);
 *   drawLegend(r, KEY, 12, 42);
 */
import { t } from "./strings.js";

/** Length of an entry's stroke, gap between stroke and label, and row height (CSS px). */
export const LEGEND_SWATCH_PX = 26;
export const LEGEND_GAP_PX = 6;
export const LEGEND_ROW_PX = 22;

/**
 * Draws `entries` (`[{ style, label }]`: `style` a stroke style, or `(theme) => style` for a
 * style of the current theme; `label` a strings.js key) with renderer `r`.
 * Returns the height taken, CSS px at scale 1.
 */
export function drawLegend(r, entries, x, y, layout = {}) {
  const { swatch = LEGEND_SWATCH_PX, gap = LEGEND_GAP_PX, row = LEGEND_ROW_PX } = layout;
  const s = r.scale;
  for (let k = 0; k < entries.length; k++) {
    const { style, label } = entries[k];
    const yk = (y + k * row) * s;
    r.beginPath();
    r.moveTo(x * s, yk);
    r.lineTo((x + swatch) * s, yk);
    r.paint(typeof style === "function" ? style(r.theme) : style);
    r.text(t(label), (x + swatch + gap) * s, yk, r.theme.labelSmall, "left", "middle");
  }
  return entries.length * row;
}
