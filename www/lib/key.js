/**
 * A figure's key in its top-left corner, in screen space (CSS px × the text scale): one line per
 * entry, a short sample of the stroke (or three dots) and its text, as the compared-curves demos
 * draw it (the figure's `insets` keep a band free for it). Entries are constant objects
 * `{ text, stroke(theme) }` (a line style of theme.js) or `{ text, dots(theme) }` (a point
 * style), `text` a strings.js key resolved while drawing (the locale may change).
 */
import { t } from "./strings.js";

/** Left edge and first baseline of the key, sample length, line spacing, text gap (CSS px). */
const KEY_X = 12;
const KEY_Y = 16;
const SAMPLE_PX = 26;
const LINE_PX = 21;
const TEXT_GAP_PX = 6;
/** Where the three dots of a `dots` entry sit along the sample (CSS px from its start). */
const DOTS_PX = Object.freeze([4, 13, 22]);

/** Draws `entries` (see above) top to bottom. */
export function drawKey(r, entries) {
  const theme = r.theme;
  const s = r.scale;
  const x = KEY_X * s;
  let y = KEY_Y * s;
  for (const entry of entries) {
    if (entry.dots) {
      for (const dx of DOTS_PX) r.point(x + dx * s, y, entry.dots(theme));
    } else {
      r.beginPath();
      r.moveTo(x, y);
      r.lineTo(x + SAMPLE_PX * s, y);
      r.paint(entry.stroke(theme));
    }
    r.text(t(entry.text), x + (SAMPLE_PX + TEXT_GAP_PX) * s, y, theme.labelSmall, "left", "middle");
    y += LINE_PX * s;
  }
}
