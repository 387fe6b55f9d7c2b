/**
 * The marks around the graphs of a basis plot (lib/basis-plot.js) over a knot vector: a line at
 * each distinct knot u_j in the domain (where the pieces of every N_{i,p} meet), the value axis
 * labelled 0 and 1 (the basis functions lie in [0, 1]) and the parameter axis's name, and each
 * function's name at its peak (the sample where it is largest). Drawing support only: the
 * samples are the core's `basisCurves(count)` (i-major).
 */
import { t } from "./strings.js";

/** Length of a tick mark on the value axis, CSS px. */
const TICK_PX = 5;

/** Sample index of each function's maximum (i-major `values`, `samples` per function). */
export function peakSamples(values, count, samples) {
  const peak = new Int32Array(count);
  for (let i = 0; i < count; i++) {
    for (let k = 1; k < samples; k++)
      if (values[i * samples + k] > values[i * samples + peak[i]]) peak[i] = k;
  }
  return peak;
}

/** A line from the plot's value 1 to 0 at each distinct knot in [u0, u1]; `px(u)` its x. */
export function drawKnotLines(r, plot, knots, u0, u1, px) {
  r.beginPath();
  for (let a = 0; a < knots.length; a++) {
    if (knots[a] < u0 || knots[a] > u1 || (a > 0 && knots[a] === knots[a - 1])) continue;
    r.moveTo(px(knots[a]), plot.y1);
    r.lineTo(px(knots[a]), plot.y0);
  }
  r.paint(r.theme.helper);
}

/** "0" and "1" left of the value axis, the parameter's name right of the plot (strings.js keys). */
export function drawAxisLabels(r, plot, { zero, one, parameter }) {
  const style = r.theme.labelSmall;
  const tick = (TICK_PX + 2) * r.scale;
  r.text(t(zero), plot.x0 - tick, plot.y0, style, "right", "middle");
  r.text(t(one), plot.x0 - tick, plot.y1, style, "right", "middle");
  r.text(t(parameter), plot.x1 + tick, plot.y0, style, "left", "middle");
}

/**
 * `name(i)` of each of `count` functions just above its peak `peaks[i]` (bold when it is
 * `highlight`); names at the ends are aligned inwards. `x(k)`, `y(value)`: canvas px.
 */
export function drawPeakNames(r, values, peaks, count, samples, x, y, name, highlight) {
  const theme = r.theme;
  const sc = r.scale;
  for (let i = 0; i < count; i++) {
    const k = peaks[i];
    const align = k === 0 ? "left" : k === samples - 1 ? "right" : "center";
    const dx = (k === 0 ? 4 : k === samples - 1 ? -4 : 0) * sc;
    const style = i === highlight ? theme.labelBold : theme.labelSmall;
    r.text(name(i), x(k) + dx, y(values[i * samples + k]) - 4 * sc, style, align, "bottom");
  }
}
