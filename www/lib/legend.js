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
  for (let k = 0; k < entries.length; k++) drawEntry(r, entries[k], x, y + k * row, swatch, gap);
  return entries.length * row;
}

/** One entry of a key: its sample from (x, y) (CSS px at scale 1, the row's middle), its label. */
function drawEntry(r, entry, x, y, swatch = LEGEND_SWATCH_PX, gap = LEGEND_GAP_PX) {
  const s = r.scale;
  const yk = y * s;
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

/** The key in the figure's top-left corner: left edge, middle of the first row, row height (CSS px). */
const CORNER_X = 12;
const CORNER_Y = 16;
const CORNER_ROW_PX = 21;

/** Draws `entries` as the figure's top-left key (keep a band free for it with the View's `insets`). */
export function drawCornerLegend(r, entries) {
  return drawLegend(r, entries, CORNER_X, CORNER_Y, { row: CORNER_ROW_PX });
}

/** The key laid across the top of the figure: margin, row height, gap between columns (CSS px). */
const BAND_MARGIN_PX = 10;
const BAND_ROW_PX = 22;
const BAND_COLUMN_GAP_PX = 18;

/**
 * A key across the top of a figure `width` canvas px wide, in rows of equal columns (as wide as
 * the widest entry; as many as fit), filled left to right: returns the band's height in canvas
 * px, and draws it (with a line under it) when `draw` is true. Call it with `draw: false` from
 * the View's `insets` (any renderer of the view measures the labels), then again in `draw`.
 */
export function legendBand(r, entries, width, { draw = true } = {}) {
  if (entries.length === 0) return 0;
  const s = r.scale;
  let widest = 0;
  for (const entry of entries)
    widest = Math.max(widest, r.measure(t(entry.label), r.theme.labelSmall));
  const column = (LEGEND_SWATCH_PX + LEGEND_GAP_PX + BAND_COLUMN_GAP_PX) * s + widest;
  const columns = Math.max(1, Math.floor((width - BAND_MARGIN_PX * s) / column));
  const rows = Math.ceil(entries.length / columns);
  const height = (2 * BAND_MARGIN_PX + rows * BAND_ROW_PX) * s;
  if (!draw) return height;
  for (let k = 0; k < entries.length; k++) {
    const x = BAND_MARGIN_PX + ((k % columns) * column) / s;
    const y = BAND_MARGIN_PX + (Math.floor(k / columns) + 0.5) * BAND_ROW_PX;
    drawEntry(r, entries[k], x, y);
  }
  r.beginPath();
  r.moveTo(0, height);
  r.lineTo(width, height);
  r.paint(r.theme.helper);
  return height;
}
