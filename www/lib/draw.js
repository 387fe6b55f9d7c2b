/**
 * One drawing interface, two back ends (the d3-path idea): `CanvasRenderer` paints on a 2D
 * canvas context, `SvgRecorder` records the very same calls as SVG markup. A demo's draw
 * function receives either and cannot tell them apart, so the SVG export is the drawing on
 * the screen, labels included (as `<text>`).
 *
 * Coordinates are CSS pixels with y down (the View converts from world coordinates).
 * Path calls follow the canvas API: `beginPath`, `moveTo`, `lineTo`, `arc`, `rect`,
 * `closePath`; then `paint(style)` strokes and/or fills the path. Styles are the constant
 * objects of theme.js: `{ stroke, fill, width, dash, alpha, strokeAlpha, join, cap, radius }`
 * (`alpha` is the fill's opacity, `strokeAlpha` the stroke's, both 1 when absent) and for text
 * `{ fill, size, weight, halo }`. `scale` (lecture mode) multiplies widths, radii, dashes
 * and font sizes.
 */
import { FONT_FAMILY } from "./theme.js";

const TAU = 2 * Math.PI;
/** Arcs closer than this to a full turn are drawn as full circles (radians). */
const FULL_TURN_EPSILON = 1e-9;
/** Width of the background-coloured halo around labels, in CSS px at scale 1. */
const HALO_WIDTH = 3;
/** SVG coordinates are written with this many decimals (1/100 px is invisible). */
const SVG_DECIMALS = 2;
const NO_DASH = Object.freeze([]);

/** Canvas `textBaseline` / SVG `dominant-baseline` for each vertical anchor we use. */
const SVG_BASELINE = {
  middle: "central",
  top: "hanging",
  bottom: "text-after-edge",
  alphabetic: "alphabetic",
};
const SVG_ANCHOR = { left: "start", center: "middle", right: "end" };

/** Labels of anchors inside the frame keep this far from its edges (CSS px). */
const LABEL_MARGIN = 2;
/** Fraction of a label's width left of its anchor, per `align`. */
const ALIGN_LEFT = { left: 0, center: 0.5, right: 1 };
/** Fraction of a label's height (≈ its font size) above its anchor, per `baseline`. */
const BASELINE_ABOVE = { top: 0, middle: 0.5, bottom: 1, alphabetic: 0.8 };

/** The shift that moves [start, start + size] inside [LABEL_MARGIN, limit − LABEL_MARGIN]. */
function shiftInside(start, size, limit) {
  if (start < LABEL_MARGIN) return LABEL_MARGIN - start;
  const over = start + size - (limit - LABEL_MARGIN);
  return over > 0 ? -Math.min(over, start - LABEL_MARGIN) : 0;
}

/** Scratch result of `keepLabelInside` (drawing allocates nothing per label). */
const labelAt = [0, 0];

/**
 * Where renderer `r` draws `string` anchored at (x, y) so that the frame's edge never cuts it:
 * a label whose anchor lies in the frame is moved inside (a label wider than the frame keeps
 * its left end in). An anchor outside the frame keeps its label where it is, so no label stands
 * at the edge for a point that is not shown. Only labels near an edge are measured: no glyph is
 * wider than 1 em, so one farther than `length` em from the sides cannot cross them.
 * Returns a scratch `[x, y]`, overwritten by the next call.
 */
export function keepLabelInside(r, string, style, x, y, align, baseline) {
  labelAt[0] = x;
  labelAt[1] = y;
  const { width: frameWidth, height: frameHeight } = r;
  if (!(x >= 0 && x <= frameWidth && y >= 0 && y <= frameHeight)) return labelAt;
  const height = style.size * r.scale;
  const reach = string.length * height + LABEL_MARGIN;
  if (
    x >= reach &&
    x <= frameWidth - reach &&
    y >= height + LABEL_MARGIN &&
    y <= frameHeight - height - LABEL_MARGIN
  )
    return labelAt;
  const width = r.measure(string, style);
  labelAt[0] += shiftInside(x - width * (ALIGN_LEFT[align] ?? 0), width, frameWidth);
  labelAt[1] += shiftInside(y - height * (BASELINE_ABOVE[baseline] ?? 0.5), height, frameHeight);
  return labelAt;
}

/** The CSS font shorthand for a text style at a given scale. */
function fontOf(style, scale) {
  return `${style.weight ?? "normal"} ${style.size * scale}px ${FONT_FAMILY}`;
}

/**
 * The width in CSS px of `string` in `style` at `scale`, measured on `context` (a 2D canvas
 * context) when there is one, else estimated at an average glyph of 0.6 em. For the recorders
 * (SVG, TikZ), which draw nothing themselves.
 */
export function measureLabel(context, string, style, scale) {
  if (!context) return string.length * style.size * scale * 0.6;
  context.font = fontOf(style, scale);
  return context.measureText(string).width;
}

/** Paints on a CanvasRenderingContext2D whose units are CSS pixels. */
export class CanvasRenderer {
  /**
   * @param {CanvasRenderingContext2D} context
   * @param {{ pixelRatio?: number, scale?: number, theme: object }} options pixelRatio is the
   *   backing-store pixels per CSS pixel; scale the lecture-mode factor.
   */
  constructor(context, { pixelRatio = 1, scale = 1, theme }) {
    this.context = context;
    this.pixelRatio = pixelRatio;
    this.scale = scale;
    this.theme = theme;
    this.width = 0;
    this.height = 0;
    /** Scaled dash arrays per style, made once (no allocation per frame). */
    this._dashCache = new WeakMap();
    /** Font strings per text style, made once per scale. */
    this._fontCache = new WeakMap();
  }

  /** Starts a frame of `width` × `height` CSS px, filled with `background`. */
  begin(width, height, background) {
    const c = this.context;
    this.width = width;
    this.height = height;
    // Fill the whole backing store (a fractional CSS size would leave a half-covered last row).
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.globalAlpha = 1;
    c.fillStyle = background;
    c.fillRect(0, 0, c.canvas.width, c.canvas.height);
    c.setTransform(this.pixelRatio, 0, 0, this.pixelRatio, 0, 0);
  }

  /** Ends the frame (nothing to flush on a canvas). */
  end() {}

  beginPath() {
    this.context.beginPath();
  }
  moveTo(x, y) {
    this.context.moveTo(x, y);
  }
  lineTo(x, y) {
    this.context.lineTo(x, y);
  }
  closePath() {
    this.context.closePath();
  }
  rect(x, y, w, h) {
    this.context.rect(x, y, w, h);
  }
  /** Same arguments as CanvasRenderingContext2D.arc (angles in radians, y down). */
  arc(x, y, r, a0, a1, counterClockwise = false) {
    this.context.arc(x, y, r, a0, a1, counterClockwise);
  }

  /** Adds a full circle of radius `r` to the path. */
  circle(x, y, r) {
    this.context.moveTo(x + r, y);
    this.context.arc(x, y, r, 0, TAU);
  }

  /** Fills then strokes the current path with a style (either part may be absent). */
  paint(style) {
    const c = this.context;
    c.globalAlpha = style.alpha ?? 1;
    if (style.fill) {
      c.fillStyle = style.fill;
      c.fill();
    }
    c.globalAlpha = style.strokeAlpha ?? 1;
    if (style.stroke) {
      c.strokeStyle = style.stroke;
      c.lineWidth = (style.width ?? 1) * this.scale;
      c.lineJoin = style.join ?? "miter";
      c.lineCap = style.cap ?? "butt";
      c.setLineDash(this._dash(style));
      c.stroke();
      c.setLineDash(NO_DASH);
    }
    c.globalAlpha = 1;
  }

  /** A dot of the style's radius (scaled), filled/stroked with the style. */
  point(x, y, style) {
    this.beginPath();
    this.circle(x, y, style.radius * this.scale);
    this.paint(style);
  }

  /**
   * Draws `string` at (x, y). `align` is "left" | "center" | "right", `baseline`
   * "middle" | "top" | "bottom" | "alphabetic". A halo in the background colour keeps the
   * label readable where it crosses a line; a label of a point in the frame is kept inside it
   * (see `keepLabelInside`).
   */
  text(string, x, y, style, align = "left", baseline = "middle") {
    const c = this.context;
    c.font = this._font(style);
    c.textAlign = align;
    c.textBaseline = baseline;
    [x, y] = keepLabelInside(this, string, style, x, y, align, baseline);
    if (style.halo) {
      c.strokeStyle = style.halo;
      c.lineWidth = HALO_WIDTH * this.scale;
      c.lineJoin = "round";
      c.strokeText(string, x, y);
    }
    c.fillStyle = style.fill;
    c.fillText(string, x, y);
  }

  /** Width of `string` in CSS px with a text style (for label placement). */
  measure(string, style) {
    this.context.font = this._font(style);
    return this.context.measureText(string).width;
  }

  _dash(style) {
    if (!style.dash) return NO_DASH;
    if (this.scale === 1) return style.dash;
    let cached = this._dashCache.get(style);
    if (!cached || cached.scale !== this.scale) {
      cached = { scale: this.scale, dash: style.dash.map((d) => d * this.scale) };
      this._dashCache.set(style, cached);
    }
    return cached.dash;
  }

  _font(style) {
    let cached = this._fontCache.get(style);
    if (!cached || cached.scale !== this.scale) {
      cached = { scale: this.scale, font: fontOf(style, this.scale) };
      this._fontCache.set(style, cached);
    }
    return cached.font;
  }
}

/** Escapes text for SVG content and attribute values. */
function escapeXml(string) {
  return String(string).replace(/[&<>"']/g, (ch) => `&#${ch.charCodeAt(0)};`);
}

/** Formats an SVG coordinate with at most SVG_DECIMALS decimals. */
function num(value) {
  return String(Number(value.toFixed(SVG_DECIMALS)));
}

/**
 * A recorder's path moved (or, with a current point elsewhere, lined) to where the canvas arc
 * of centre (x, y), radius r starts at angle a0, as CanvasRenderingContext2D.arc does; returns
 * that start [x0, y0]. For SvgRecorder and TikzRecorder (`_x`/`_y` their current point).
 */
export function moveToArcStart(recorder, x, y, r, a0) {
  const x0 = x + r * Math.cos(a0);
  const y0 = y + r * Math.sin(a0);
  if (recorder._x === null) recorder.moveTo(x0, y0);
  else if (Math.abs(recorder._x - x0) > 1e-6 || Math.abs(recorder._y - y0) > 1e-6)
    recorder.lineTo(x0, y0);
  return [x0, y0];
}

/**
 * Records the drawing interface as an SVG document. Only used for export, so it may build
 * strings freely.
 */
export class SvgRecorder {
  /** @param {{ scale?: number, theme: object, measureContext?: CanvasRenderingContext2D }} options */
  constructor({ scale = 1, theme, measureContext = null }) {
    this.scale = scale;
    this.theme = theme;
    this.width = 0;
    this.height = 0;
    this._parts = [];
    this._d = "";
    this._x = null; // current point, null when the path has none
    this._y = null;
    this._measure = measureContext;
  }

  begin(width, height, background) {
    this.width = width;
    this.height = height;
    this._parts.length = 0;
    this._parts.push(`<rect width="${num(width)}" height="${num(height)}" fill="${background}"/>`);
  }

  end() {}

  beginPath() {
    this._d = "";
    this._x = this._y = null;
  }

  moveTo(x, y) {
    this._d += `M${num(x)},${num(y)}`;
    this._x = x;
    this._y = y;
  }

  lineTo(x, y) {
    this._d += `L${num(x)},${num(y)}`;
    this._x = x;
    this._y = y;
  }

  closePath() {
    if (this._x !== null) this._d += "Z";
  }

  rect(x, y, w, h) {
    this._d += `M${num(x)},${num(y)}h${num(w)}v${num(h)}h${num(-w)}Z`;
    this._x = x;
    this._y = y;
  }

  /** Canvas arc semantics written as SVG elliptical arcs (a full turn becomes two halves). */
  arc(x, y, r, a0, a1, counterClockwise = false) {
    const [x0, y0] = moveToArcStart(this, x, y, r, a0);
    if (!r) return;
    let da = counterClockwise ? a0 - a1 : a1 - a0;
    const sweep = counterClockwise ? 0 : 1;
    if (da >= TAU - FULL_TURN_EPSILON) {
      const xm = x - r * Math.cos(a0);
      const ym = y - r * Math.sin(a0);
      this._d += `A${num(r)},${num(r)},0,1,${sweep},${num(xm)},${num(ym)}`;
      this._d += `A${num(r)},${num(r)},0,1,${sweep},${num(x0)},${num(y0)}`;
      this._x = x0;
      this._y = y0;
      return;
    }
    da = ((da % TAU) + TAU) % TAU;
    const x1 = x + r * Math.cos(a1);
    const y1 = y + r * Math.sin(a1);
    this._d += `A${num(r)},${num(r)},0,${da > Math.PI ? 1 : 0},${sweep},${num(x1)},${num(y1)}`;
    this._x = x1;
    this._y = y1;
  }

  circle(x, y, r) {
    this.moveTo(x + r, y);
    this.arc(x, y, r, 0, TAU);
  }

  paint(style) {
    if (!this._d) return;
    const attrs = [`d="${this._d}"`];
    if (style.fill) {
      attrs.push(`fill="${style.fill}"`);
      if (style.alpha !== undefined && style.alpha !== 1)
        attrs.push(`fill-opacity="${style.alpha}"`);
    } else {
      attrs.push('fill="none"');
    }
    if (style.stroke) {
      attrs.push(
        `stroke="${style.stroke}"`,
        `stroke-width="${num((style.width ?? 1) * this.scale)}"`,
      );
      if (style.join) attrs.push(`stroke-linejoin="${style.join}"`);
      if (style.cap) attrs.push(`stroke-linecap="${style.cap}"`);
      if (style.dash)
        attrs.push(`stroke-dasharray="${style.dash.map((d) => num(d * this.scale)).join(" ")}"`);
      if (style.strokeAlpha !== undefined && style.strokeAlpha !== 1)
        attrs.push(`stroke-opacity="${style.strokeAlpha}"`);
    }
    this._parts.push(`<path ${attrs.join(" ")}/>`);
  }

  point(x, y, style) {
    this.beginPath();
    this.circle(x, y, style.radius * this.scale);
    this.paint(style);
  }

  text(string, x, y, style, align = "left", baseline = "middle") {
    [x, y] = keepLabelInside(this, string, style, x, y, align, baseline);
    const attrs = [
      `x="${num(x)}"`,
      `y="${num(y)}"`,
      `font-size="${num(style.size * this.scale)}"`,
      `fill="${style.fill}"`,
      `text-anchor="${SVG_ANCHOR[align]}"`,
      `dominant-baseline="${SVG_BASELINE[baseline]}"`,
    ];
    if (style.weight) attrs.push(`font-weight="${style.weight}"`);
    if (style.halo) {
      attrs.push(
        `stroke="${style.halo}"`,
        `stroke-width="${num(HALO_WIDTH * this.scale)}"`,
        'stroke-linejoin="round"',
        'paint-order="stroke"',
      );
    }
    this._parts.push(`<text ${attrs.join(" ")}>${escapeXml(string)}</text>`);
  }

  measure(string, style) {
    return measureLabel(this._measure, string, style, this.scale);
  }

  /** The recorded drawing as a standalone SVG document. */
  toString() {
    const w = num(this.width);
    const h = num(this.height);
    return (
      `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}" ` +
      `font-family="${escapeXml(FONT_FAMILY)}">\n${this._parts.join("\n")}\n</svg>\n`
    );
  }
}

/**
 * Starts a new path: the polyline through points `from` … `to − 1` of a list of [x, y] world
 * points (`view` maps them to CSS px, e.g. a control polygon). Paint it with `r.paint(style)`.
 * Allocates nothing, so draw functions may call it every frame.
 */
export function pointsPath(r, view, points, from = 0, to = points.length) {
  r.beginPath();
  for (let i = from; i < to; i++) {
    const x = view.sx(points[i][0]);
    const y = view.sy(points[i][1]);
    if (i === from) r.moveTo(x, y);
    else r.lineTo(x, y);
  }
}

/**
 * Starts a new path: the polyline through vertices `from` … `to − 1` of a flat world array
 * [x0, y0, x1, y1, …] such as `sampleUniform` returns (default: all of it). Paint it with
 * `r.paint(style)`. Allocates nothing.
 */
export function flatPath(r, view, flat, from = 0, to = flat.length / 2) {
  r.beginPath();
  for (let k = from; k < to; k++) {
    const x = view.sx(flat[2 * k]);
    const y = view.sy(flat[2 * k + 1]);
    if (k === from) r.moveTo(x, y);
    else r.lineTo(x, y);
  }
}

/**
 * Starts a new path: the polyline through O + s·v_k for the first `count` vectors v_k of a flat
 * world array [x0, y0, x1, y1, …], drawn from the origin O = (ox, oy) at scale s (a hodograph
 * beside its curve). Paint it with `r.paint(style)`. Allocates nothing.
 */
export function vectorsPath(r, view, flat, count, ox, oy, s) {
  r.beginPath();
  for (let k = 0; k < count; k++) {
    const x = view.sx(ox + s * flat[2 * k]);
    const y = view.sy(oy + s * flat[2 * k + 1]);
    if (k === 0) r.moveTo(x, y);
    else r.lineTo(x, y);
  }
}

/**
 * Starts a new path: the closed polygon through `points[indices[0]]`, `points[indices[1]]`, …
 * (world [x, y] points, e.g. a convex hull's vertices from geometry.js `convexHull`). Paint it
 * with `r.paint(style)`. Allocates nothing.
 */
export function indexedPolygonPath(r, view, points, indices) {
  r.beginPath();
  for (let k = 0; k < indices.length; k++) {
    const q = points[indices[k]];
    if (k === 0) r.moveTo(view.sx(q[0]), view.sy(q[1]));
    else r.lineTo(view.sx(q[0]), view.sy(q[1]));
  }
  r.closePath();
}

/**
 * Starts a new path: the segment from world point a to b extended beyond both ends by
 * `overshoot` × its length, a − o(b − a) to b + o(b − a) (a tangent line through a and b).
 * Paint it with `r.paint(style)`.
 */
export function extendedSegmentPath(r, view, a, b, overshoot) {
  const [ax, ay] = a;
  const [bx, by] = b;
  r.beginPath();
  r.moveTo(view.sx(ax - (bx - ax) * overshoot), view.sy(ay - (by - ay) * overshoot));
  r.lineTo(view.sx(bx + (bx - ax) * overshoot), view.sy(by + (by - ay) * overshoot));
}

/** A dot with `style` at every vertex of a flat world array [x0, y0, x1, y1, …]. */
export function flatDots(r, view, flat, style) {
  for (let k = 0; k < flat.length; k += 2) r.point(view.sx(flat[k]), view.sy(flat[k + 1]), style);
}

/**
 * Starts a new path: the whole line through world points a and b, a + s·(b − a), drawn across
 * the canvas (|s| up to (width + height) / |b − a| + 1 in CSS px, past every edge). Returns
 * false, with no path, when a and b meet on screen (no direction). Paint it with `r.paint(style)`.
 */
export function linePath(r, view, a, b) {
  const px = view.sx(a[0]);
  const py = view.sy(a[1]);
  const dx = view.sx(b[0]) - px;
  const dy = view.sy(b[1]) - py;
  const length = Math.hypot(dx, dy);
  if (length < 1e-9) return false;
  const reach = (view.width + view.height) / length + 1;
  r.beginPath();
  r.moveTo(px - dx * reach, py - dy * reach);
  r.lineTo(px + dx * reach, py + dy * reach);
  return true;
}

/** Chevrons showing a curve's direction: arm length (CSS px at scale 1) and half-angle (radians). */
export const CHEVRON_PX = 11;
export const CHEVRON_ANGLE = 0.5;

/**
 * Paints a chevron (an arrow head without its shaft) at vertex k of flat world samples
 * [x0, y0, …], pointing along the chord to vertex k + 1 — the direction of increasing parameter
 * (k is clamped to the last chord); nothing where the chord has no length on screen.
 */
export function chevron(r, view, flat, k, style) {
  const k0 = Math.max(0, Math.min(k, flat.length / 2 - 2));
  const x = view.sx(flat[2 * k0]);
  const y = view.sy(flat[2 * k0 + 1]);
  let dx = view.sx(flat[2 * k0 + 2]) - x;
  let dy = view.sy(flat[2 * k0 + 3]) - y;
  const length = Math.hypot(dx, dy);
  if (length < 1e-9) return;
  dx /= length;
  dy /= length;
  const size = CHEVRON_PX * r.scale;
  const c = Math.cos(CHEVRON_ANGLE);
  const s = Math.sin(CHEVRON_ANGLE);
  r.beginPath();
  r.moveTo(x - size * (dx * c - dy * s), y - size * (dy * c + dx * s));
  r.lineTo(x, y);
  r.lineTo(x - size * (dx * c + dy * s), y - size * (dy * c - dx * s));
  r.paint(style);
}

/** Arrow heads: length (CSS px at scale 1) and half-angle (radians). */
export const ARROW_HEAD_PX = 10;
export const ARROW_HEAD_ANGLE = 0.45;

/**
 * Paints an arrow from (x0, y0) to (x1, y1), canvas CSS px, with `style` (a vector such as a
 * derivative); nothing when it is shorter than a pixel. The head is at most half the arrow.
 */
export function arrow(r, x0, y0, x1, y1, style) {
  const dx = x1 - x0;
  const dy = y1 - y0;
  const length = Math.hypot(dx, dy);
  if (length < 1) return;
  const head = Math.min(ARROW_HEAD_PX * r.scale, length / 2);
  const ux = dx / length;
  const uy = dy / length;
  const c = Math.cos(ARROW_HEAD_ANGLE);
  const s = Math.sin(ARROW_HEAD_ANGLE);
  r.beginPath();
  r.moveTo(x0, y0);
  r.lineTo(x1, y1);
  r.moveTo(x1 - head * (ux * c - uy * s), y1 - head * (uy * c + ux * s));
  r.lineTo(x1, y1);
  r.lineTo(x1 - head * (ux * c + uy * s), y1 - head * (uy * c - ux * s));
  r.paint(style);
}

/** Line spacing of wrapped captions, in font sizes. */
const CAPTION_LINE_HEIGHT = 1.25;

/**
 * Draws a sentence with renderer `r` left-aligned at (x, y), broken at spaces into lines no
 * wider than `maxWidth` CSS px (a word wider than that keeps a line of its own), so a caption
 * written for a desktop canvas still reads whole on a phone. `baseline` is each line's; the
 * lines stack downwards from y, or upwards with "bottom" (the last line then sits at y).
 * A caption that fits is one `r.text` call and allocates nothing. Returns the line count.
 */
export function drawCaption(r, string, x, y, style, maxWidth, baseline = "top") {
  if (!string) return 0;
  if (r.measure(string, style) <= maxWidth) {
    r.text(string, x, y, style, "left", baseline);
    return 1;
  }
  const lines = [];
  let line = "";
  for (const word of string.split(" ")) {
    const candidate = line ? `${line} ${word}` : word;
    if (line && r.measure(candidate, style) > maxWidth) {
      lines.push(line);
      line = word;
    } else {
      line = candidate;
    }
  }
  lines.push(line);
  const step = CAPTION_LINE_HEIGHT * style.size * r.scale;
  const top = baseline === "bottom" ? y - (lines.length - 1) * step : y;
  lines.forEach((text, i) => r.text(text, x, top + i * step, style, "left", baseline));
  return lines.length;
}
