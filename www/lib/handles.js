/**
 * Draggable control-point handles on a View: pointer events only (capture on down,
 * `pointercancel` treated as up), hit radius larger for touch, hover and selection states,
 * keyboard access (Tab / Shift+Tab cycle, arrows nudge, Home / End, + and Delete), and
 * optional constraints (a handle that may only move along a line shows that line while
 * dragged). Pointer moves are coalesced: the newest position is applied once per animation
 * frame, just before the view draws.
 *
 * The handles own no data: the demo answers `count()`, `get(i, out)` and `label(i)` and is
 * told `move(i, x, y)` (a preview, during a drag) and `commit(kind, i)` (the change is final:
 * add it to the undo history).
 *
 * Accessibility (style.md): a figure with handles is an interactive figure — the canvas becomes
 * `role="application"` with an `aria-roledescription` — and a polite live region beside it says
 * what happened when it is final: "P₂ selected, (6, 4)" when a handle is selected, "P₂ moved to
 * (6.5, 4)" when a drag ends or a nudge is committed; never during a drag.
 */
import { subscript } from "./format.js";
import { selectionKey } from "./handle-keys.js";
import { HandleSet } from "./handle-set.js";
import { formatNumber, t } from "./strings.js";

/** Hit radius around a handle centre, in CSS px, for mouse/pen and for touch (ui.md). */
export const HIT_RADIUS_MOUSE = 10;
export const HIT_RADIUS_TOUCH = 18;
/** Keyboard nudge in CSS px: plain arrow and Shift+arrow (ui.md). */
export const NUDGE_PX = 1;
export const NUDGE_PX_LARGE = 10;
/** Consecutive nudges of one handle within this many ms make one undo step (handle-keys.js). */
export { NUDGE_MERGE_MS } from "./handle-keys.js";
/** Dragged coordinates are rounded to the decimals that still resolve a tenth of a pixel. */
const SUBPIXEL_DIGITS = 1;
/** Below this length (CSS px) a direction is considered undefined when placing labels. */
const DIRECTION_EPSILON = 1e-6;

/**
 * Rounds a world coordinate to the precision that the current zoom can show (a tenth of a
 * pixel), so states stay short in links and JSON while the picture does not change.
 */
export function roundToView(value, scale) {
  const digits = Math.max(0, Math.ceil(Math.log10(Math.max(scale, 1))) + SUBPIXEL_DIGITS);
  const factor = 10 ** digits;
  return Math.round(value * factor) / factor;
}

/** Cached handle labels P₀, P₁, … */
const POINT_LABELS = [];

/** "Pᵢ" with a subscript index (cached: the draw path allocates nothing). */
export function pointLabel(i) {
  return (POINT_LABELS[i] ??= `P${subscript(i)}`);
}

/**
 * The `count`, `get`, `label` and `move` options of `Handles` for a demo's list of [x, y]
 * control points: `points()` returns the current list (a demo may replace it); a dragged point is
 * written into it, then `moved(i, xy)` runs with `xy` a reused Float64Array [x, y] to hand to
 * `curve.setControlPoint(i, xy)` (nothing is allocated while dragging). Labels are P₀, P₁, …
 * (cached), or `label(i)` when given.
 *
 *   const handles = new Handles(view, {
 *     ...pointHandles(() => work.points, (i, xy) => {
 *       curve.setControlPoint(i, xy); // in place: no rebuild while dragging
 *       geometryDirty = true;
 *     }),
 *     commit: (kind, i, merge) => ctx.commit(work, merge),
 *   });
 */
export function pointHandles(points, moved, label = null) {
  const xy = new Float64Array(2);
  return {
    count: () => points().length,
    get: (i, out) => {
      out[0] = points()[i][0];
      out[1] = points()[i][1];
    },
    label: label ?? pointLabel,
    move: (i, x, y) => {
      points()[i][0] = x;
      points()[i][1] = y;
      xy[0] = x;
      xy[1] = y;
      moved(i, xy);
    },
  };
}

/**
 * The `count`, `get`, `label` and `move` options of `Handles` for several lists of [x, y]
 * points shown as one run of handles (a curve's P₀ … P₃, then a frame's Q₀ … Q₃): `list(k)`
 * returns list k of `lists`; handle i is the i-th point of their concatenation. A move is
 * offered first, `moved(i, xy, k) → boolean` with `xy` a reused Float64Array [x, y] and k the
 * list; the point is written into its list only when that returns true, so a move the core
 * refuses leaves it where it was. `label(i)` names handle i.
 */
export function pointListsHandles(lists, list, moved, label) {
  const xy = new Float64Array(2);
  /** The list holding handle i and the index in it, written into `at` (no allocation). */
  const at = { k: 0, j: 0 };
  const locate = (i) => {
    let j = i;
    let k = 0;
    while (k < lists - 1 && j >= list(k).length) j -= list(k++).length;
    at.k = k;
    at.j = j;
    return list(k)[j];
  };
  return {
    count: () => {
      let n = 0;
      for (let k = 0; k < lists; k++) n += list(k).length;
      return n;
    },
    get: (i, out) => {
      const point = locate(i);
      out[0] = point[0];
      out[1] = point[1];
    },
    label,
    move: (i, x, y) => {
      const point = locate(i);
      xy[0] = x;
      xy[1] = y;
      if (!moved(i, xy, at.k)) return;
      point[0] = x;
      point[1] = y;
    },
  };
}

export class Handles extends HandleSet {
  /**
   * @param {import("./view.js").View} view
   * @param {object} source
   * @param {() => number} source.count number of handles.
   * @param {(i: number, out: Float64Array) => void} source.get writes handle i's world x, y into out.
   * @param {(i: number) => string} source.label text next to handle i ("P₀").
   * @param {(i: number, x: number, y: number) => void} source.move handle i moved (preview).
   * @param {(kind: "drag" | "key", i: number, merge: string | null) => void} source.commit a
   *   move is finished; nudges of one handle in quick succession share a `merge` key, so they
   *   make one undo step.
   * @param {(i: number) => number[] | null} [source.constraint] world line [x0, y0, x1, y1]
   *   handle i must stay on, or null.
   * @param {(i: number) => void} [source.add] "+" pressed with handle i selected.
   * @param {(i: number) => void} [source.remove] Delete pressed with handle i selected.
   * @param {(i: number) => void} [source.select] selection changed (-1 for none).
   * @param {boolean} [source.polygon] handles form a polygon in index order (label placement).
   * @param {(i: number, out: Float64Array) => boolean} [source.anchor] for a handle attached to
   *   a point (an arrow's tip): writes that world point into out and returns true; the handle's
   *   label is then placed away from it (beyond the tip) and the handle is no polygon neighbour.
   */
  constructor(view, source) {
    super(view, source, "handles.selected");
    this.polygon = source.polygon ?? true;

    // Scratch storage, made once.
    this._p = new Float64Array(2);
    this._q = new Float64Array(2);
    this._grab = new Float64Array(2); // offset from pointer to handle centre (world)
    this._sum = new Float64Array(2); // label direction accumulator
    this._anchor = new Float64Array(2); // an anchored handle's point (label placement)
    this._published = NaN;
    this._dragStart = new Float64Array(2); // where the dragged handle was at pointer down
  }

  /** Says in the live region, politely, `key` ("{label} … ({x}, {y})") for handle i where it is now. */
  _announce(key, i) {
    this.source.get(i, this._q);
    this.announce(
      t(key, {
        label: this.source.label(i),
        x: formatNumber(this._q[0]),
        y: formatNumber(this._q[1]),
      }),
    );
  }

  /** Index of the handle under canvas point (x, y), or -1. */
  hitTest(x, y, pointerType) {
    const radius = pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE;
    const view = this.view;
    let best = -1;
    let bestDistance = radius;
    // Later handles are drawn on top, so on a tie the later one wins.
    for (let i = 0, n = this.source.count(); i < n; i++) {
      this.source.get(i, this._p);
      const d = Math.hypot(view.sx(this._p[0]) - x, view.sy(this._p[1]) - y);
      if (d <= bestDistance) {
        best = i;
        bestDistance = d;
      }
    }
    return best;
  }

  // -------------------------------------------------------------- interactor

  pointerDown(event, x, y) {
    const i = this.hitTest(x, y, event.pointerType);
    if (i < 0) return false;
    this.source.get(i, this._p);
    this._grab[0] = this._p[0] - this.view.wx(x);
    this._grab[1] = this._p[1] - this.view.wy(y);
    this._dragStart[0] = this._p[0];
    this._dragStart[1] = this._p[1];
    this.dragging = i;
    this.select(i);
    this.view.canvas.focus({ preventScroll: true });
    this.view.canvas.style.cursor = "grabbing";
    this.view.requestDraw();
    return true;
  }

  pointerMove(event, x, y) {
    if (this.dragging < 0) return;
    this._pending[0] = this.view.wx(x) + this._grab[0];
    this._pending[1] = this.view.wy(y) + this._grab[1];
    this._hasPending = true;
    this.view.requestDraw();
  }

  pointerUp(event, x, y) {
    if (this.dragging < 0) return;
    this.pointerMove(event, x, y);
    this._flush();
    const i = this.dragging;
    this.dragging = -1;
    this.view.canvas.style.cursor = this.hitTest(x, y, event.pointerType) >= 0 ? "grab" : "";
    this.source.commit("drag", i, null);
    if (i < this.source.count()) {
      this.source.get(i, this._p);
      if (this._p[0] !== this._dragStart[0] || this._p[1] !== this._dragStart[1])
        this._announce("handles.moved", i);
    }
    this.view.requestDraw();
  }

  /** Applies the newest pointer position (once per frame). */
  _flush() {
    if (!this._hasPending || this.dragging < 0) return;
    this._hasPending = false;
    this._apply(this.dragging, this._pending[0], this._pending[1]);
  }

  /** Projects onto the handle's constraint, rounds to the view's precision, moves. */
  _apply(i, x, y) {
    const line = this.source.constraint?.(i);
    if (line) {
      const [x0, y0, x1, y1] = line;
      const dx = x1 - x0;
      const dy = y1 - y0;
      const lengthSquared = dx * dx + dy * dy;
      if (lengthSquared > 0) {
        const s = ((x - x0) * dx + (y - y0) * dy) / lengthSquared;
        x = x0 + s * dx;
        y = y0 + s * dy;
      }
    }
    const scale = this.view.scale;
    this.source.move(i, roundToView(x, scale), roundToView(y, scale));
  }

  // -------------------------------------------------------------- keyboard

  _focus(event) {
    // Keyboard focus selects a handle; a click on the figure (pan, or a drag) does not.
    if (
      this.selected >= 0 ||
      this.source.count() === 0 ||
      !this.view.canvas.matches(":focus-visible")
    )
      return;
    // Arriving backwards (Shift+Tab from an element after the canvas) selects the last handle.
    const from = event.relatedTarget;
    const fromAfter =
      from && this.view.canvas.compareDocumentPosition(from) & Node.DOCUMENT_POSITION_FOLLOWING;
    this.select(fromAfter ? this.source.count() - 1 : 0);
  }

  _key(event) {
    const n = this.source.count();
    if (n === 0 || event.ctrlKey || event.metaKey || event.altKey) return;
    if (selectionKey(event, this, n)) return;
    const i = this.selected;
    switch (event.key) {
      case "ArrowLeft":
      case "ArrowRight":
      case "ArrowUp":
      case "ArrowDown":
        if (i < 0) {
          this.select(0); // the first arrow press picks a handle, the next ones move it
          break;
        }
        this._nudge(i, event.key, event.shiftKey ? NUDGE_PX_LARGE : NUDGE_PX);
        break;
      case "+":
      case "=":
        if (!this.source.add) return;
        this.source.add(i);
        break;
      case "Delete":
      case "Backspace":
        if (!this.source.remove || i < 0) return;
        this.source.remove(i);
        break;
      default:
        return;
    }
    event.preventDefault();
  }

  /** Moves handle i by `pixels` in the arrow's direction and commits (merged while repeating). */
  _nudge(i, key, pixels) {
    const step = pixels / this.view.scale;
    this.source.get(i, this._q);
    const dx = key === "ArrowLeft" ? -step : key === "ArrowRight" ? step : 0;
    const dy = key === "ArrowDown" ? -step : key === "ArrowUp" ? step : 0;
    this._apply(i, this._q[0] + dx, this._q[1] + dy);
    this.source.commit("key", i, `nudge-${this._nudges.next(i)}`);
    if (i < this.source.count()) this._announce("handles.moved", i);
    this.view.requestDraw();
  }

  // -------------------------------------------------------------- drawing

  /**
   * Draws the handles, their labels (placed away from the polygon's turn) and, while a
   * constrained handle is dragged, the line it moves along.
   */
  draw(r, view) {
    const theme = r.theme;
    const n = this.source.count();
    if (this.dragging >= 0 && this.source.constraint) {
      const line = this.source.constraint(this.dragging);
      if (line) this._drawLine(r, view, line, theme.helper);
    }
    let signature = n;
    for (let i = 0; i < n; i++) {
      this.source.get(i, this._p);
      const x = view.sx(this._p[0]);
      const y = view.sy(this._p[1]);
      signature = signature * 31 + x * 7 + y * 13;
      const style =
        i === this.selected
          ? theme.handleSelected
          : i === this.hovered || i === this.dragging
            ? theme.handleHover
            : theme.handle;
      r.point(x, y, style);
      this._drawLabel(
        r,
        view,
        i,
        n,
        x,
        y,
        i === this.selected ? theme.labelBold : theme.label,
        style.radius * r.scale,
      );
    }
    if (this.dragging < 0 && signature !== this._published && r === view.renderer)
      this._publish(n, signature);
  }

  /**
   * Writes the handles' canvas positions to `data-handles` on the figure host ("x,y;x,y",
   * CSS px): a stable hook for tests and tools. Only when they changed and no drag is running.
   */
  _publish(n, signature) {
    this._published = signature;
    const parts = [];
    for (let i = 0; i < n; i++) {
      this.source.get(i, this._p);
      parts.push(`${this.view.sx(this._p[0]).toFixed(1)},${this.view.sy(this._p[1]).toFixed(1)}`);
    }
    this.view.host.dataset.handles = parts.join(";");
  }

  _drawLine(r, view, [x0, y0, x1, y1], style) {
    const px0 = view.sx(x0);
    const py0 = view.sy(y0);
    const dx = view.sx(x1) - px0;
    const dy = view.sy(y1) - py0;
    const length = Math.hypot(dx, dy);
    if (length < DIRECTION_EPSILON) return;
    const reach = (view.width + view.height) / length; // far enough to cross the whole canvas
    r.beginPath();
    r.moveTo(px0 - dx * reach, py0 - dy * reach);
    r.lineTo(px0 + dx * reach, py0 + dy * reach);
    r.paint(style);
  }

  /** Places label i on the outside of the polygon's turn at handle i. */
  _drawLabel(r, view, i, n, x, y, style, radius) {
    let dx = 0;
    let dy = 0;
    if (this._anchored(i)) {
      dx = x - view.sx(this._anchor[0]);
      dy = y - view.sy(this._anchor[1]);
    } else if (this.polygon && n > 1) {
      const previous = i > 0 && !this._anchored(i - 1);
      const next = i < n - 1 && !this._anchored(i + 1);
      if (previous) this._addAway(view, i - 1, x, y);
      if (next) this._addAway(view, i + 1, x, y);
      dx = this._sum[0];
      dy = this._sum[1];
      this._sum[0] = this._sum[1] = 0;
      if (Math.hypot(dx, dy) < 0.2 && previous && next) {
        // Straight through: put the label beside the polygon, on the screen's upper side.
        this.source.get(i + 1, this._p);
        const ax = view.sx(this._p[0]) - x;
        const ay = view.sy(this._p[1]) - y;
        const len = Math.hypot(ax, ay) || 1;
        dx = ay / len;
        dy = -ax / len;
        if (dy > 0) {
          dx = -dx;
          dy = -dy;
        }
      }
    }
    const length = Math.hypot(dx, dy);
    if (length < DIRECTION_EPSILON) {
      dx = Math.SQRT1_2;
      dy = -Math.SQRT1_2;
    } else {
      dx /= length;
      dy /= length;
    }
    placeLabel(r, this.source.label(i), x, y, dx, dy, radius, style);
  }

  /** Whether handle j is attached to a point (`source.anchor`), written into `_anchor`. */
  _anchored(j) {
    return this.source.anchor ? this.source.anchor(j, this._anchor) : false;
  }

  /** Adds the unit vector from handle j towards (x, y) to the scratch sum `_sum`. */
  _addAway(view, j, x, y) {
    this.source.get(j, this._p);
    const ax = x - view.sx(this._p[0]);
    const ay = y - view.sy(this._p[1]);
    const len = Math.hypot(ax, ay);
    if (len < DIRECTION_EPSILON) return;
    this._sum[0] += ax / len;
    this._sum[1] += ay / len;
  }
}

/**
 * Draws `text` next to the point (x, y) in the unit direction (dx, dy) (screen px, y down),
 * `radius` px from the centre plus a gap, aligned so the text grows away from the point.
 */
export function placeLabel(r, text, x, y, dx, dy, radius, style) {
  const gap = radius + LABEL_GAP_PX * r.scale;
  const tx = x + dx * gap;
  const ty = y + dy * gap;
  const align =
    dx > LABEL_ALIGN_THRESHOLD ? "left" : dx < -LABEL_ALIGN_THRESHOLD ? "right" : "center";
  // Vertical: shift by half a line in the direction's vertical sense so the text clears the point.
  const shift = dy * (style.size * r.scale) * 0.5;
  r.text(text, tx, ty + shift, style, align, "middle");
}

/** Gap between a point's edge and its label, CSS px. */
const LABEL_GAP_PX = 5;
/** A segment shorter than this (canvas px) has no direction: its normal is taken as above left. */
const DEGENERATE_SEGMENT_PX = 1;

/**
 * Writes into `out` [nx, ny] the unit normal (canvas px) of the segment from (ax, ay) to
 * (bx, by), turned so that it points from the centre (cx, cy) towards (x, y): the side of a
 * polygon's leg away from the polygon, where a label on the leg stays clear of both.
 */
export function normalAwayFrom(ax, ay, bx, by, x, y, cx, cy, out) {
  let nx = ay - by;
  let ny = bx - ax;
  const length = Math.hypot(nx, ny);
  if (length < DEGENERATE_SEGMENT_PX) {
    nx = -Math.SQRT1_2;
    ny = -Math.SQRT1_2;
  } else {
    nx /= length;
    ny /= length;
  }
  const away = (x - cx) * nx + (y - cy) * ny < 0 ? -1 : 1;
  out[0] = away * nx;
  out[1] = away * ny;
  return out;
}
/** |dx| above this aligns the label's near edge to the point; below, the label is centred. */
const LABEL_ALIGN_THRESHOLD = 0.35;

/**
 * Draws `text` next to the screen point (x, y) on the side away from the screen point (cx, cy)
 * (a centroid computed once for many labels); straight above when (x, y) is at it.
 */
export function placeLabelFrom(r, text, x, y, cx, cy, style, radius) {
  let dx = x - cx;
  let dy = y - cy;
  const length = Math.hypot(dx, dy);
  if (length < 1) {
    dx = 0;
    dy = -1;
  } else {
    dx /= length;
    dy /= length;
  }
  placeLabel(r, text, x, y, dx, dy, radius, style);
}

/**
 * Draws `text` next to the screen point (x, y) on the side away from the centroid of `points`
 * (world [x, y] points, e.g. the control points, mapped with `view`): outside the construction.
 * Straight up-left when (x, y) is at the centroid. Allocates nothing.
 */
export function placeLabelAway(r, view, points, text, x, y, style, radius) {
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < points.length; i++) {
    cx += view.sx(points[i][0]);
    cy += view.sy(points[i][1]);
  }
  cx /= points.length;
  cy /= points.length;
  let dx = x - cx;
  let dy = y - cy;
  const length = Math.hypot(dx, dy);
  if (length < 1) {
    dx = -Math.SQRT1_2;
    dy = -Math.SQRT1_2;
  } else {
    dx /= length;
    dy /= length;
  }
  placeLabel(r, text, x, y, dx, dy, radius, style);
}

/**
 * Labels a vector drawn from its middle (mx, my) with screen direction (dx, dy) (y down) on one
 * side of it: its left for `side` = 1, its right for −1 — the unit normal side·(dy, −dx)/|d|,
 * straight up or down when it is shorter than a pixel — `offset` px away. Two collinear arrows
 * labelled on opposite sides never put their labels on top of each other.
 */
export function placeLabelBeside(r, text, mx, my, dx, dy, side, offset, style) {
  const length = Math.hypot(dx, dy);
  let nx = 0;
  let ny = -side;
  if (length >= 1) {
    nx = (side * dy) / length;
    ny = (-side * dx) / length;
  }
  placeLabel(r, text, mx, my, nx, ny, offset, style);
}

/**
 * Labels an arrow from (x0, y0) to (x1, y1) (screen px) at its tip, continuing its direction,
 * `gap` px beyond it; nothing when the arrow is shorter than a pixel (no direction).
 */
export function placeLabelAtTip(r, text, x0, y0, x1, y1, gap, style) {
  const dx = x1 - x0;
  const dy = y1 - y0;
  const length = Math.hypot(dx, dy);
  if (length < 1) return;
  placeLabel(r, text, x1, y1, dx / length, dy / length, gap, style);
}
