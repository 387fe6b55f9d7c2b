/**
 * A knot ruler: the knot vector u₀ … u_m of a B-spline drawn as a horizontal ruler in its own
 * band of a demo's figure (same renderer, so SVG/PNG exports include it), one square handle per
 * knot labelled uᵢ. Knots are dragged along the ruler but cannot pass their neighbours (knot i
 * stays in [u_{i−1}, u_{i+1}]; that range is shown while it is dragged or selected). Equal knots
 * are stacked upwards (lowest index at the bottom), with the multiplicity beside their value;
 * the domain [u_p, u_{n+1}] is a shaded bar with its own caption, and each distinct interior
 * knot carries the continuity C^{p−r} the curve has there (from `curve.knotContinuity()`).
 *
 * Raising a multiplicity: a double click (double tap) on a knot, or Enter on the selected knot,
 * asks the demo to `raise(i)`; `raiseMultiplicity()` below is the rule the demos use: the next
 * knot after the stack is merged onto it (or the previous one when the next is the end of the
 * domain). Delete / Backspace asks to `lower(i)` (`lowerMultiplicity()`: the top copy moves half
 * way to the next distinct knot).
 *
 * Keyboard, as handles.js: when chained with the control-point `Handles`, Tab from the last
 * control point enters the knots, Tab / Shift+Tab walk through them (Shift+Tab from u₀ goes back
 * to the last control point), Home / End jump to the first / last knot, ← → move the selected
 * knot by one display step (about a pixel; Shift: ten), Escape deselects.
 *
 * Like `Handles`, the ruler owns no data; the demo answers `knots()`, `degree()`,
 * `continuity()` and is told `move(i, u)` (preview) and `commit(kind, i, merge)` (final). The
 * draw path allocates nothing: label strings are cached, styles are made once per theme.
 */
import { HIT_RADIUS_MOUSE, HIT_RADIUS_TOUCH } from "./handles.js";
import { NudgeGroups } from "./handle-keys.js";
import { HUES, WIDTH, FONT_SIZE } from "./theme.js";
import { localeDecimal, subscript, texDecimal } from "./format.js";
import { formatNumber, t } from "./strings.js";
import { setKnots } from "./bspline.js";
import { continuityText } from "./continuity.js";

/** Default ends of the ruler line inside the canvas (left, right), CSS px at text scale 1. */
export const RULER_LEFT = 40;
export const RULER_RIGHT = 34;
/** Vertical distance between stacked (equal) knots, CSS px at scale 1. */
export const STACK_PX = 16;
/** Half the side of a knot's square handle, CSS px (hovered / selected: a little larger). */
const KNOT_HALF = 4.5;
const KNOT_HALF_HOVER = 6;
/** Rows of the band, CSS px at scale 1: continuity caption, gap under the stacks, values, domain. */
const ROW_CONTINUITY = 20;
const GAP_LINE = 6;
const ROW_VALUE = 19;
const ROW_DOMAIN = 19;
const PAD_BOTTOM = 4;
/** Height of the domain bar and of the constraint-range bar around the ruler line, CSS px. */
const DOMAIN_BAR_PX = 7;
const RANGE_BAR_PX = 4;
/** A dragged knot snaps to a multiple of 1/2 this close to it (CSS px). */
const SNAP_PX = 6;
const SNAP_STEP = 0.5;
/** Two taps on the same knot within this many ms, without a drag, raise its multiplicity. */
const DOUBLE_TAP_MS = 400;
/** A press that moves less than this (CSS px) is a tap, not a drag. */
const TAP_SLOP_PX = 3;
/** Nudges with Shift move this many display steps. */
const NUDGE_LARGE = 10;
/** Value labels closer than this (CSS px) to the previous one are left out. */
const LABEL_GAP_PX = 6;
/** Cached value labels are dropped when there are more than this many (long drags). */
const LABEL_CACHE_LIMIT = 400;

/** Styles of the ruler, made once per theme (themes are frozen constants). */
const styleCache = new WeakMap();
function stylesOf(theme) {
  let s = styleCache.get(theme);
  if (!s) {
    s = Object.freeze({
      band: Object.freeze({ fill: theme.background }),
      separator: Object.freeze({ stroke: theme.polygon, width: WIDTH.helper }),
      line: Object.freeze({ stroke: theme.text, width: WIDTH.helper }),
      tick: Object.freeze({ stroke: theme.polygon, width: WIDTH.helper }),
      domain: Object.freeze({ fill: HUES.blue, alpha: 0.28 }),
      domainEdge: Object.freeze({ stroke: HUES.blue, width: 2 }),
      range: Object.freeze({ fill: HUES.vermillion, alpha: 0.55 }),
      rangeEdge: Object.freeze({ stroke: HUES.vermillion, width: 1.5 }),
      knot: Object.freeze({
        fill: theme.handleFill,
        stroke: theme.handleOutline,
        width: WIDTH.handleOutline,
      }),
      knotSelected: Object.freeze({ fill: theme.handleFill, stroke: HUES.vermillion, width: 2.5 }),
      label: theme.labelSmall,
      labelBold: theme.labelBold,
      continuity: Object.freeze({
        fill: theme.text,
        size: FONT_SIZE.label,
        weight: "bold",
        halo: theme.background,
      }),
      broken: Object.freeze({
        fill: HUES.vermillion,
        size: FONT_SIZE.label,
        weight: "bold",
        halo: theme.background,
      }),
      domainLabel: Object.freeze({
        fill: HUES.blue,
        size: FONT_SIZE.small,
        halo: theme.background,
      }),
    });
    styleCache.set(theme, s);
  }
  return s;
}

/** Indices [a, b] of the run of knots equal to knots[i]. */
export function stackOf(knots, i) {
  let a = i;
  let b = i;
  while (a > 0 && knots[a - 1] === knots[i]) a--;
  while (b + 1 < knots.length && knots[b + 1] === knots[i]) b++;
  return [a, b];
}

/**
 * Raises the multiplicity of the knot value at index i by one, keeping the number of knots:
 * the next knot after its run is moved onto it, or, when that one is u_{n+1} or beyond (the
 * end of the domain), the previous knot before the run (if it lies after u_p). Returns
 * `{ knots, index }` (a new array and the index of the merged copy) or `{ error }` with the
 * reason ("max": already p + 1; "ends": no interior knot left to merge).
 * @param {ArrayLike<number>} knots u₀ … u_m (m = n + p + 1)
 * @param {number} i
 * @param {number} degree p
 */
export function raiseMultiplicity(knots, i, degree) {
  const [a, b] = stackOf(knots, i);
  if (b - a + 1 >= degree + 1) return { error: "max" };
  const n = knots.length - degree - 2;
  const next = Array.from(knots);
  if (b + 1 <= n) {
    next[b + 1] = knots[i];
    return { knots: next, index: b + 1 };
  }
  if (a - 1 >= degree + 1) {
    next[a - 1] = knots[i];
    return { knots: next, index: a - 1 };
  }
  return { error: "ends" };
}

/**
 * Lowers the multiplicity of the knot value at index i by one: the top copy of its run moves
 * half way to the next distinct knot (the bottom copy half way to the previous one at the end
 * of the vector). Returns `{ knots, index }` or `{ error: "single" }` for a simple knot.
 */
export function lowerMultiplicity(knots, i) {
  const [a, b] = stackOf(knots, i);
  if (a === b) return { error: "single" };
  const next = Array.from(knots);
  if (b + 1 < knots.length) {
    next[b] = (knots[b] + knots[b + 1]) / 2;
    return { knots: next, index: b };
  }
  if (a > 0) {
    next[a] = (knots[a - 1] + knots[a]) / 2;
    return { knots: next, index: a };
  }
  return { error: "single" };
}

/**
 * A knot value as machine text: at most 3 decimals, no trailing zeros, a decimal point ("2",
 * "2.5", "1.333"), for data attributes and typed lists parsed back.
 */
export function knotMachine(u) {
  const s = u.toFixed(3).replace(/\.?0+$/, "");
  return s === "-0" ? "0" : s;
}

/**
 * A knot value as shown (or TeX with `tex`): `knotMachine` with the active language's decimal
 * separator ("2,5" in Croatian; TeX "2{,}5").
 */
export function knotText(u, tex = false) {
  const s = knotMachine(u);
  return tex ? texDecimal(s) : localeDecimal(s);
}

export class KnotRuler {
  /**
   * @param {import("./view.js").View} view the demo's figure.
   * @param {object} source
   * @param {() => ArrayLike<number>} source.knots the knot vector u₀ … u_m shown.
   * @param {() => number} source.degree p (domain [u_p, u_{n+1}], at most p + 1 equal knots).
   * @param {() => { knot: number, multiplicity: number, continuity: number }[] | null} [source.continuity]
   *   the curve's `knotContinuity()` (continuity −1: the curve breaks there).
   * @param {(i: number, u: number) => void} source.move knot i moved to u (preview; already
   *   clamped to [u_{i−1}, u_{i+1}]).
   * @param {(kind: "drag" | "key", i: number, merge: string | null) => void} source.commit a
   *   move is finished (nudges in quick succession share a `merge` key: one undo step).
   * @param {(i: number) => void} [source.raise] double click / Enter on knot i.
   * @param {(i: number) => void} [source.lower] Delete / Backspace on knot i.
   * @param {(u: number, final: boolean) => void} [source.pick] press / drag on the ruler away
   *   from the knots (e.g. to set the parameter u); without it such presses are ignored.
   * @param {(i: number) => void} [source.select] selection changed (-1 for none).
   * @param {import("./handles.js").Handles} [source.handles] the control-point handles: one Tab
   *   order (points, then knots) and one selection between them. Give them `select: (i) => i >= 0
   *   && ruler.select(-1)` in their source so that picking a point deselects the knot.
   */
  constructor(view, source) {
    this.view = view;
    this.source = source;
    this.selected = -1;
    this.hovered = -1;
    this.dragging = -1;

    // Layout of the frame being drawn, and a copy of the screen's (for pointer input).
    this._x0 = 0;
    this._x1 = 1;
    this._top = 0;
    this._scale = 1;
    this._screen = { x0: 0, x1: 1, top: 0, scale: 1, valid: false };
    this._lo = 0; // ruler range, frozen while a knot is dragged
    this._hi = 1;
    this._frozen = false;

    this._pendingX = 0;
    this._hasPending = false;
    this._grabDx = 0;
    this._downX = 0;
    this._moved = false;
    this._picking = false;
    this._lastTap = { index: -1, time: 0 };
    this._nudges = new NudgeGroups();
    this._published = NaN;

    this._knotLabels = [];
    this._valueLabels = new Map();
    this._continuityLabels = new Map();
    this._domainLabel = "";
    this._domainKey = "";

    // Ahead of the chained handles when they already exist: the band is the ruler's.
    view.addInteractor(this, { before: source.handles ?? null });
    view.beforeFrame(() => this._flush());
    this._onKey = (e) => this._key(e);
    // Capture: runs before the Handles' listener on the same canvas, so a selected knot owns the keys.
    view.canvas.addEventListener("keydown", this._onKey, true);
  }

  // ------------------------------------------------------------------ layout

  /** Height of the band in CSS px at text scale `scale` (enough for p + 1 stacked knots). */
  height(scale = 1) {
    const p = this.source.degree();
    return Math.round(
      (ROW_CONTINUITY + (p + 1) * STACK_PX + GAP_LINE + ROW_VALUE + ROW_DOMAIN + PAD_BOTTOM) *
        scale,
    );
  }

  /**
   * Places the ruler for the frame being drawn: the ruler line runs from x0 to x1 (CSS px of the
   * renderer) and the band starts at `top`; `scale` is the renderer's text scale. Call it before
   * `draw`, and before `px`/`uAt` when drawing next to the ruler (e.g. a plot above it).
   */
  layout(x0, x1, top, scale = 1) {
    this._x0 = x0;
    this._x1 = x1;
    this._top = top;
    this._scale = scale;
    if (!this._frozen) this._updateRange();
  }

  /**
   * `layout` along the bottom band of a width × height canvas (CSS px) at text scale `scale`,
   * the line from `left` to `width − right` (CSS px at scale 1).
   */
  atBottom(width, height, scale = 1, left = RULER_LEFT, right = RULER_RIGHT) {
    this.layout(left * scale, width - right * scale, height - this.height(scale), scale);
  }

  /** The ruler's u range [u₀, u_m] (fixed while a knot is dragged). */
  get range() {
    return [this._lo, this._hi];
  }

  /** Canvas x of parameter u in the current layout. */
  px(u) {
    return this._x0 + ((u - this._lo) / (this._hi - this._lo)) * (this._x1 - this._x0);
  }

  /** Parameter u at canvas x in the current layout. */
  uAt(x) {
    return this._lo + ((x - this._x0) / (this._x1 - this._x0)) * (this._hi - this._lo);
  }

  /** y of the ruler line in the current layout. */
  get lineY() {
    const p = this.source.degree();
    return this._top + (ROW_CONTINUITY + (p + 1) * STACK_PX + GAP_LINE / 2) * this._scale;
  }

  _updateRange() {
    const k = this.source.knots();
    this._lo = k[0];
    this._hi = k[k.length - 1] > k[0] ? k[k.length - 1] : k[0] + 1;
  }

  /** Switches px/uAt/lineY to the screen's layout (pointer input between frames). */
  _useScreen() {
    const s = this._screen;
    if (!s.valid) return false;
    this._x0 = s.x0;
    this._x1 = s.x1;
    this._top = s.top;
    this._scale = s.scale;
    return true;
  }

  /** Centre of knot i's handle (canvas px, current layout) into out[0], out[1]. */
  _knotCentre(knots, i, out) {
    let level = 0;
    while (i - level - 1 >= 0 && knots[i - level - 1] === knots[i]) level++;
    out[0] = this.px(knots[i]);
    out[1] = this.lineY - (level + 0.5) * STACK_PX * this._scale;
  }

  // ------------------------------------------------------------------ selection

  /** Selects knot i (-1: none); a selected knot deselects the chained control point. */
  select(i) {
    const count = this.source.knots().length;
    const next = i >= 0 && i < count ? i : -1;
    if (next === this.selected) return;
    this.selected = next;
    if (next >= 0) this.source.handles?.select(-1);
    this.source.select?.(next);
    if (next >= 0) this._announce("knotRuler.selected", next);
    this.view.requestDraw();
  }

  /**
   * Says `key` ("{label} … {u}") for knot i where it is now, in the live region of the chained
   * handles (on commit, never per frame; without handles there is no live region).
   */
  _announce(key, i) {
    const u = this.source.knots()[i];
    if (u !== undefined)
      this.source.handles?.announce(t(key, { label: this._knotLabel(i), u: formatNumber(u) }));
  }

  /** Forgets hover and drag state (the knot vector was replaced, e.g. by undo). */
  forgetPointer() {
    this.hovered = -1;
    this.dragging = -1;
    this._hasPending = false;
    this._frozen = false;
    this._picking = false;
    if (this.selected >= this.source.knots().length) this.selected = -1;
  }

  /** Knot under canvas point (x, y), or -1 (the nearest within the hit radius). */
  hitTest(x, y, pointerType) {
    if (!this._useScreen()) return -1;
    const radius = pointerType === "touch" ? HIT_RADIUS_TOUCH : HIT_RADIUS_MOUSE;
    const knots = this.source.knots();
    const c = this._centre;
    let best = -1;
    let bestDistance = radius;
    for (let i = 0; i < knots.length; i++) {
      this._knotCentre(knots, i, c);
      const d = Math.hypot(c[0] - x, c[1] - y);
      if (d <= bestDistance) {
        best = i;
        bestDistance = d;
      }
    }
    return best;
  }

  /** True when canvas point (x, y) lies in the ruler's band (screen layout). */
  inBand(x, y) {
    if (!this._useScreen()) return false;
    return y >= this._top && y <= this._top + this.height(this._scale);
  }

  // ------------------------------------------------------------------ pointer (View interactor)

  pointerDown(event, x, y) {
    const i = this.hitTest(x, y, event.pointerType);
    if (i < 0) {
      if (!this.inBand(x, y)) return false;
      // The band is the ruler's: no pan there, and a press may pick a parameter.
      if (this.source.pick) {
        this._picking = true;
        this.source.pick(this._clampToRange(this.uAt(x)), false);
      }
      return true;
    }
    const knots = this.source.knots();
    this.dragging = i;
    this._frozen = true;
    this._moved = false;
    this._downX = x;
    this._grabDx = this.px(knots[i]) - x;
    this.select(i);
    this.view.canvas.focus({ preventScroll: true });
    this.view.canvas.style.cursor = "grabbing";
    this.view.requestDraw();
    return true;
  }

  pointerMove(event, x) {
    if (this._picking) {
      this._useScreen();
      this.source.pick(this._clampToRange(this.uAt(x)), false);
      return;
    }
    if (this.dragging < 0) return;
    if (!this._moved && Math.abs(x - this._downX) < TAP_SLOP_PX) return;
    this._moved = true;
    this._pendingX = x + this._grabDx;
    this._hasPending = true;
    this.view.requestDraw();
  }

  pointerUp(event, x, y) {
    if (this._picking) {
      this._picking = false;
      this._useScreen();
      this.source.pick(this._clampToRange(this.uAt(x)), true);
      return;
    }
    if (this.dragging < 0) return;
    if (this._moved) this.pointerMove(event, x);
    this._flush();
    const i = this.dragging;
    this.dragging = -1;
    this._frozen = false;
    this.view.canvas.style.cursor = this.hitTest(x, y, event.pointerType) >= 0 ? "grab" : "";
    if (this._moved) {
      this._lastTap.index = -1;
      this.source.commit("drag", i, null);
      this._announce("knotRuler.moved", i);
    } else {
      // A tap; two on the same knot in quick succession raise its multiplicity.
      const now = performance.now();
      if (this._lastTap.index === i && now - this._lastTap.time < DOUBLE_TAP_MS) {
        this._lastTap.index = -1;
        this.source.raise?.(i);
      } else {
        this._lastTap.index = i;
        this._lastTap.time = now;
      }
    }
    this.view.requestDraw();
  }

  hover(x, y, pointerType) {
    const i = this.hitTest(x, y, pointerType);
    if (i !== this.hovered) {
      this.hovered = i;
      this.view.requestDraw();
    }
    const inside = i >= 0 || this.inBand(x, y);
    // The band covers whatever lies under it: the chained handles lose their hover there (the
    // view stops asking later interactors once one answers with a cursor).
    if (inside) this.source.handles?.leave();
    if (i >= 0) return "grab";
    return inside ? (this.source.pick ? "col-resize" : "default") : null;
  }

  leave() {
    if (this.hovered >= 0) {
      this.hovered = -1;
      this.view.requestDraw();
    }
  }

  _clampToRange(u) {
    return Math.min(this._hi, Math.max(this._lo, u));
  }

  /** Applies the newest pointer position (once per frame). */
  _flush() {
    if (!this._hasPending || this.dragging < 0) return;
    this._hasPending = false;
    if (!this._useScreen()) return;
    this._apply(this.dragging, this._snap(this.uAt(this._pendingX)));
  }

  /** Snaps u to a multiple of 1/2 within SNAP_PX, else rounds it to the display step. */
  _snap(u) {
    const pxPerUnit = (this._x1 - this._x0) / (this._hi - this._lo);
    const nice = Math.round(u / SNAP_STEP) * SNAP_STEP;
    if (Math.abs(nice - u) * pxPerUnit <= SNAP_PX) return nice;
    return this._round(u);
  }

  /** The display step: a power of ten of about one to ten pixels on the ruler. */
  _step() {
    const pxPerUnit = (this._x1 - this._x0) / (this._hi - this._lo);
    return 10 ** -Math.max(0, Math.ceil(Math.log10(Math.max(pxPerUnit, 1))) - 1);
  }

  _round(u) {
    const step = this._step();
    const digits = Math.max(0, Math.round(-Math.log10(step)));
    return Number((Math.round(u / step) * step).toFixed(digits));
  }

  /** Clamps u to knot i's range [u_{i−1}, u_{i+1}] (the ruler's ends for the first and last) and moves it. */
  _apply(i, u) {
    const [lo, hi] = this.constraint(i);
    const clamped = Math.min(hi, Math.max(lo, u));
    if (clamped !== this.source.knots()[i]) this.source.move(i, clamped);
  }

  /** The range knot i may move in: [u_{i−1}, u_{i+1}] (the ruler's ends for u₀ and u_m). */
  constraint(i) {
    const knots = this.source.knots();
    const lo = i > 0 ? knots[i - 1] : this._lo;
    const hi = i + 1 < knots.length ? knots[i + 1] : this._hi;
    return [lo, hi];
  }

  // ------------------------------------------------------------------ keyboard

  _key(event) {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    const knots = this.source.knots();
    const count = knots.length;
    const handles = this.source.handles;
    const i = this.selected;
    if (i < 0) {
      // Tab from the last control point walks on into the knots.
      if (
        event.key === "Tab" &&
        !event.shiftKey &&
        handles &&
        handles.selected >= 0 &&
        handles.selected === handles.source.count() - 1
      ) {
        this.select(0);
        this._consume(event);
      }
      return;
    }
    switch (event.key) {
      case "Tab": {
        const next = i + (event.shiftKey ? -1 : 1);
        if (next >= 0 && next < count) {
          this.select(next);
          this._consume(event);
        } else if (next < 0 && handles && handles.source.count() > 0) {
          this.select(-1);
          handles.select(handles.source.count() - 1);
          this._consume(event);
        } else {
          this.select(-1); // leave the figure: focus moves on, no trap
          event.stopImmediatePropagation();
        }
        return;
      }
      case "Home":
        this.select(0);
        break;
      case "End":
        this.select(count - 1);
        break;
      case "Escape":
        this.select(-1);
        break;
      case "ArrowLeft":
      case "ArrowDown":
      case "ArrowRight":
      case "ArrowUp": {
        if (!this._useScreen()) break;
        const sign = event.key === "ArrowLeft" || event.key === "ArrowDown" ? -1 : 1;
        const step = this._step() * (event.shiftKey ? NUDGE_LARGE : 1);
        this._apply(i, this._round(knots[i] + sign * step));
        this.source.commit("key", i, `knot-nudge-${this._nudges.next(i)}`);
        this._announce("knotRuler.moved", i);
        break;
      }
      case "Enter":
        if (!this.source.raise) return;
        this.source.raise(i);
        break;
      case "Delete":
      case "Backspace":
        if (!this.source.lower) return;
        this.source.lower(i);
        break;
      default:
        return;
    }
    this._consume(event);
    this.view.requestDraw();
  }

  _consume(event) {
    event.preventDefault();
    event.stopImmediatePropagation();
  }

  // ------------------------------------------------------------------ drawing

  /** Draws the band (call `layout` first). Screen frames also refresh the pointer layout. */
  draw(r) {
    if (r === this.view.renderer) {
      const s = this._screen;
      s.x0 = this._x0;
      s.x1 = this._x1;
      s.top = this._top;
      s.scale = this._scale;
      s.valid = true;
    }
    const st = stylesOf(r.theme);
    const sc = this._scale;
    const knots = this.source.knots();
    const p = this.source.degree();
    const m = knots.length - 1;
    const top = this._top;
    const bottom = top + this.height(sc);
    const lineY = this.lineY;

    // Band background (covers anything panned into it) and a separator.
    r.beginPath();
    r.rect(0, top, r.width, bottom - top);
    r.paint(st.band);
    r.beginPath();
    r.moveTo(0, top);
    r.lineTo(r.width, top);
    r.paint(st.separator);

    // The domain [u_p, u_{n+1}]: a shaded bar on the line, edged at both ends.
    const n = m - p - 1;
    const d0 = this.px(knots[p]);
    const d1 = this.px(knots[n + 1]);
    const half = (DOMAIN_BAR_PX / 2) * sc;
    r.beginPath();
    r.rect(d0, lineY - half, d1 - d0, 2 * half);
    r.paint(st.domain);
    r.beginPath();
    r.moveTo(d0, lineY - half - 3 * sc);
    r.lineTo(d0, lineY + half + 3 * sc);
    r.moveTo(d1, lineY - half - 3 * sc);
    r.lineTo(d1, lineY + half + 3 * sc);
    r.paint(st.domainEdge);

    // The ruler line.
    r.beginPath();
    r.moveTo(this._x0, lineY);
    r.lineTo(this._x1, lineY);
    r.paint(st.line);

    // The range the dragged (or selected) knot may move in.
    const active = this.dragging >= 0 ? this.dragging : this.selected;
    if (active >= 0 && active <= m) {
      const [lo, hi] = this.constraint(active);
      const a = this.px(lo);
      const b = this.px(hi);
      const rh = (RANGE_BAR_PX / 2) * sc;
      r.beginPath();
      r.rect(a, lineY + half, b - a, 2 * rh);
      r.paint(st.range);
      r.beginPath();
      r.moveTo(a, lineY - half);
      r.lineTo(a, lineY + half + 2 * rh + 3 * sc);
      r.moveTo(b, lineY - half);
      r.lineTo(b, lineY + half + 2 * rh + 3 * sc);
      r.paint(st.rangeEdge);
    }

    // Distinct values: a tick, the value (× multiplicity) under the line, the continuity above.
    const continuity = this.source.continuity?.() ?? null;
    let lastRight = -Infinity;
    const valueY = lineY + (GAP_LINE / 2 + 3) * sc + (active >= 0 ? RANGE_BAR_PX * sc : 0);
    for (let a = 0; a <= m; ) {
      let b = a;
      while (b + 1 <= m && knots[b + 1] === knots[a]) b++;
      const x = this.px(knots[a]);
      const r0 = b - a + 1;
      r.beginPath();
      r.moveTo(x, lineY);
      r.lineTo(x, lineY + 4 * sc);
      r.paint(st.tick);
      const text = this._valueLabel(knots[a], r0);
      const w = r.measure(text, st.label);
      let lx = x - w / 2;
      lx = Math.max(lx, 2 * sc);
      lx = Math.min(lx, r.width - w - 2 * sc);
      if (lx >= lastRight + LABEL_GAP_PX * sc) {
        r.text(text, lx, valueY, st.label, "left", "top");
        lastRight = lx + w;
      }
      if (continuity && a > p && b <= n) {
        const entry = findEntry(continuity, knots[a]);
        if (entry) {
          const style = entry.continuity < 0 ? st.broken : st.continuity;
          r.text(
            this._continuityLabel(entry.continuity),
            x,
            lineY - r0 * STACK_PX * sc - 3 * sc,
            style,
            "center",
            "bottom",
          );
        }
      }
      a = b + 1;
    }

    // The domain's caption under the values.
    r.text(
      this._domainCaption(knots, p, n),
      (d0 + d1) / 2,
      valueY + ROW_VALUE * sc,
      st.domainLabel,
      "center",
      "top",
    );

    // The knots: squares stacked upwards, labelled uᵢ on the right.
    const c = this._centre;
    for (let i = 0; i <= m; i++) {
      this._knotCentre(knots, i, c);
      const big = i === this.selected || i === this.hovered || i === this.dragging;
      const h = (big ? KNOT_HALF_HOVER : KNOT_HALF) * sc;
      r.beginPath();
      r.rect(c[0] - h, c[1] - h, 2 * h, 2 * h);
      r.paint(i === this.selected ? st.knotSelected : st.knot);
      r.text(
        this._knotLabel(i),
        c[0] + h + 3 * sc,
        c[1],
        i === this.selected ? st.labelBold : st.label,
        "left",
        "middle",
      );
    }

    if (this.dragging < 0 && r === this.view.renderer) this._publish(knots);
  }

  /** Writes the knots' canvas positions to `data-knots` on the figure host ("x,y;x,y", CSS px), for tests. */
  _publish(knots) {
    const c = this._centre;
    let signature = knots.length;
    for (let i = 0; i < knots.length; i++) {
      this._knotCentre(knots, i, c);
      signature = signature * 31 + c[0] * 7 + c[1] * 13;
    }
    if (signature === this._published) return;
    this._published = signature;
    const parts = [];
    for (let i = 0; i < knots.length; i++) {
      this._knotCentre(knots, i, c);
      parts.push(`${c[0].toFixed(1)},${c[1].toFixed(1)}`);
    }
    this.view.host.dataset.knots = parts.join(";");
  }

  get _centre() {
    return (this.__centre ??= new Float64Array(2));
  }

  _knotLabel(i) {
    return (this._knotLabels[i] ??= `u${subscript(i)}`);
  }

  _valueLabel(u, multiplicity) {
    if (this._valueLabels.size > LABEL_CACHE_LIMIT) this._valueLabels.clear();
    const key = u * 16 + multiplicity; // multiplicity ≤ 16 never collides for a fixed u
    let text = this._valueLabels.get(key);
    if (text === undefined) {
      text =
        multiplicity > 1
          ? t("knotRuler.valueMultiple", { u: knotText(u), r: multiplicity })
          : knotText(u);
      this._valueLabels.set(key, text);
    }
    return text;
  }

  _continuityLabel(k) {
    let text = this._continuityLabels.get(k);
    if (text === undefined) {
      text = continuityText(k);
      this._continuityLabels.set(k, text);
    }
    return text;
  }

  _domainCaption(knots, p, n) {
    const a = knots[p];
    const b = knots[n + 1];
    // Rebuilt only when the domain or its indices change.
    if (this._domainA !== a || this._domainB !== b || this._domainP !== p || this._domainN !== n) {
      this._domainA = a;
      this._domainB = b;
      this._domainP = p;
      this._domainN = n;
      this._domainLabel = t("knotRuler.domain", {
        p: subscript(p),
        n1: subscript(n + 1),
        a: knotText(a),
        b: knotText(b),
      });
    }
    return this._domainLabel;
  }

  /** Removes the key listener (the view removes its own). */
  destroy() {
    this.view.canvas.removeEventListener("keydown", this._onKey, true);
  }
}

/**
 * The knot ruler of a declarative demo (demo.js), as a `controls` entry in the panel.js style:
 * `knotRuler("knots", options)` returns `{ build(ui) }`, which makes a `KnotRuler` on `ui.view`
 * bound to `state[field]`, chained with the control-point handles (one Tab order, one
 * selection), and reserves its band at the bottom of the figure (added to the demo's own
 * `figure.insets`). It has no panel element. A moved knot, a raised or lowered multiplicity
 * goes through `setKnots` (lib/bspline.js): the core is asked first, u is kept in the domain,
 * a drag is committed when it ends.
 *
 * The ruler is `data[name]` (default `data.ruler`) for the demo's `draw`, which places it
 * (`data.ruler.atBottom(r.width, r.height, r.scale)`, before drawing next to it with `px(u)`)
 * and draws it (`data.ruler.draw(r)`) where the band belongs in its picture.
 * @param {string} field the knot vector's state field.
 * @param {object} [o]
 * @param {(state) => number} [o.degree] p (default `state.degree`).
 * @param {(state) => number} [o.count] control points of the curve (default `state.points.length`).
 * @param {(state, data) => object[] | null} [o.continuity] the curve's `knotContinuity()`
 *   (default `data.continuity`).
 * @param {string | null} [o.param] the parameter field kept inside the domain (default "u").
 * @param {(error: string, i: number, state) => string} [o.refused] the message when a
 *   multiplicity cannot be raised or lowered (`raiseMultiplicity`'s error); without it, no
 *   double click / Enter / Delete.
 * @param {(ui, u: number, final: boolean) => void} [o.pick] press / drag on the ruler off the knots.
 * @param {(ui, i: number) => void} [o.select] the selected knot changed.
 * @param {string} [o.name] its key in `data`.
 */
export function knotRuler(field, o = {}) {
  const degree = o.degree ?? ((s) => s.degree);
  const count = o.count ?? ((s) => s.points.length);
  const continuity = o.continuity ?? ((s, d) => d.continuity ?? null);
  const param = o.param === undefined ? "u" : o.param;
  const name = o.name ?? "ruler";
  return {
    build(ui) {
      const options = { field, param, count, degree };
      const multiplicity = (i, result) => {
        if (result.error) {
          ui.status(o.refused(result.error, i, ui.state), "error");
          return;
        }
        if (setKnots(ui, result.knots, true, options)) ruler.select(result.index);
      };
      const ruler = new KnotRuler(ui.view, {
        knots: () => ui.state[field],
        degree: () => degree(ui.state),
        continuity: () => continuity(ui.state, ui.data),
        move(i, u) {
          const next = Array.from(ui.state[field]);
          next[i] = u;
          setKnots(ui, next, false, options);
        },
        commit: (kind, i, merge) => ui.commit(merge),
        raise: o.refused
          ? (i) => multiplicity(i, raiseMultiplicity(ui.state[field], i, degree(ui.state)))
          : undefined,
        lower: o.refused
          ? (i) => multiplicity(i, lowerMultiplicity(ui.state[field], i))
          : undefined,
        pick: o.pick ? (u, final) => o.pick(ui, u, final) : undefined,
        select: (i) => {
          o.select?.(ui, i);
          ui.requestDraw();
        },
        handles: ui.handles ?? undefined,
      });
      const handles = ui.handles;
      if (handles) {
        // Picking a control point deselects the knot.
        const selectPoint = handles.source.select;
        handles.source.select = (i) => {
          selectPoint?.(i);
          if (i >= 0) ruler.select(-1);
        };
      }
      // The band below the world window, under whatever the demo reserves itself.
      const demoInsets = ui.view.insets;
      const insets = [0, 0, 0, 0];
      ui.view.insets = (width, height, scale) => {
        const own = demoInsets?.(width, height, scale);
        for (let k = 0; k < 4; k++) insets[k] = own ? own[k] : 0;
        insets[2] += ruler.height(scale);
        return insets;
      };
      ui.data[name] = ruler;
      let length = ui.state[field].length;
      return {
        element: null,
        sync(state) {
          // A new knot vector length (degree, points): the old selection and drag mean nothing.
          if (state[field].length !== length) {
            length = state[field].length;
            ruler.forgetPointer();
          }
        },
        stop: () => ruler.forgetPointer(),
        destroy: () => ruler.destroy(),
      };
    },
  };
}

/** The knotContinuity() entry for knot value u, or null. */
function findEntry(list, u) {
  for (let k = 0; k < list.length; k++) if (list[k].knot === u) return list[k];
  return null;
}
