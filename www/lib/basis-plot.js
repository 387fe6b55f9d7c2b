/**
 * What the basis-function demos (Bernstein basis, B-spline basis) share about the plot of the
 * basis functions under their curve: the pointer in the plot (press or drag sets the parameter,
 * hover highlights the graph under it), which function is highlighted (the plot's hover, then a
 * table row's, then the handle in hand, hovered or selected) and one graph drawn from the
 * core's i-major samples. The plot's layout stays with each demo (Bernstein's runs over
 * t ∈ [0, 1], the B-spline's over the knot ruler's domain).
 */
import { el } from "./controls.js";
import { CYCLE } from "./theme.js";
import { drawPlotStrip } from "./plot-strip.js";

/** The pointer in a basis plot and the highlight it and the legend table set. */
export class BasisPlotPointer {
  /**
   * Registers the plot's interactor on `view`; create it before the handles, so the plot claims
   * a press inside its frame first.
   * @param {object} view the figure
   * @param {{ inPlot(x, y): boolean, graphAt(x, y): number, pick(x, final): void,
   *   press?(): void, enter?(): void }} options `graphAt` is the function whose graph passes
   *   near (x, y) or -1; `pick(x, final)` sets the parameter under x; `press()` runs before a
   *   press in the plot (stop a player), `enter()` when the pointer hovers the plot (the handles
   *   forget their hover). `before`: an interactor already on the view (the handles) that
   *   this one goes ahead of, when the plot is made after them; `first: true` ahead of all
   *   interactors added before it (the handles of a declarative demo, made before its `setup`).
   */
  constructor(
    view,
    { inPlot, graphAt, pick, press = () => {}, enter = () => {}, before = null, first = false },
  ) {
    this.view = view;
    /** The function under the pointer in the plot, or -1. */
    this.plotHover = -1;
    /** The function of the hovered legend row, or -1. */
    this.rowHover = -1;
    this.dragging = false;
    view.addInteractor(
      {
        pointerDown: (event, x, y) => {
          if (!inPlot(x, y)) return false;
          press();
          this.dragging = true;
          this.plotHover = graphAt(x, y);
          pick(x, false);
          return true;
        },
        pointerMove: (event, x) => {
          if (this.dragging) pick(x, false);
        },
        pointerUp: (event, x) => {
          if (!this.dragging) return;
          this.dragging = false;
          pick(x, true);
        },
        hover: (x, y) => {
          const inside = inPlot(x, y);
          const i = inside ? graphAt(x, y) : -1;
          if (inside) enter();
          if (i !== this.plotHover) {
            this.plotHover = i;
            view.requestDraw();
          }
          return inside ? "col-resize" : null;
        },
        leave: () => {
          if (this.plotHover >= 0) {
            this.plotHover = -1;
            view.requestDraw();
          }
        },
      },
      { before, first },
    );
  }

  /**
   * The highlighted function: plot hover, then table row, then `handles`' dragged, hovered or
   * selected one; -1 for none.
   */
  highlighted(handles) {
    if (this.plotHover >= 0) return this.plotHover;
    if (this.rowHover >= 0) return this.rowHover;
    if (handles.dragging >= 0) return handles.dragging;
    if (handles.hovered >= 0) return handles.hovered;
    return handles.selected;
  }

  /** Highlights function i from its legend row (-1 when the pointer leaves the row). */
  setRowHover(i) {
    if (this.rowHover === i) return;
    this.rowHover = i;
    this.view.requestDraw();
  }

  /** Forgets the hover and any press in progress (a new state arrived from outside). */
  reset() {
    this.plotHover = this.rowHover = -1;
    this.dragging = false;
  }
}

/**
 * For a declarative demo (demo.js): `ui.data.highlighted()` is the highlighted function now
 * (`pointer.highlighted(ui.handles)`, -1 past the last handle, e.g. just after a removal), and
 * each frame in which it differs from `ui.data.highlight` marks the pseudo-field "highlight"
 * changed. Declare the cell `highlight: [["highlight", <handles' field>], (s, d) =>
 * d.highlighted()]` and the formula, label, readouts and table follow the highlight as they
 * follow the state. Call it from `setup(ui)`: its hook runs before the runtime's refresh.
 */
export function followHighlight(ui, pointer) {
  ui.data.highlighted = () => {
    const i = pointer.highlighted(ui.handles);
    return i < ui.handles.source.count() ? i : -1;
  };
  ui.view.beforeFrame(() => {
    if (ui.data.highlighted() !== ui.data.highlight) ui.touch("highlight");
  });
}

/**
 * Paths and paints graph `i` of i-major samples `values` (`count` per function): sample k at
 * canvas (`x(k)`, `y(values[i·count + k])`).
 */
export function drawGraph(r, values, i, count, x, y, style) {
  const offset = i * count;
  r.beginPath();
  for (let k = 0; k < count; k++) {
    const px = x(k);
    const py = y(values[offset + k]);
    if (k === 0) r.moveTo(px, py);
    else r.lineTo(px, py);
  }
  r.paint(style);
}

/**
 * The frame of a basis plot in its strip (canvas px): the strip's background and top edge from
 * `plot.top` to `plot.bottom` across the canvas, the value axis from 0 (`plot.y0`) to 1
 * (`plot.y1`) at `plot.x0`, the parameter axis to `plot.x1`, and a dashed line at value 1
 * (the partition of unity's bound); with `labels` `{ zero, one, tick }`, the value labels left
 * of the value axis, `tick` CSS px (at scale 1) away from it.
 */
export function drawPlotFrame(r, plot, labels = null) {
  const theme = r.theme;
  drawPlotStrip(r, plot);
  r.beginPath();
  r.moveTo(plot.x0, plot.y1);
  r.lineTo(plot.x0, plot.y0);
  r.lineTo(plot.x1, plot.y0);
  r.paint(theme.axis);
  r.beginPath();
  r.moveTo(plot.x0, plot.y1);
  r.lineTo(plot.x1, plot.y1);
  r.paint(theme.helper);
  if (!labels) return;
  const x = plot.x0 - (labels.tick + 2) * r.scale;
  r.text(labels.zero, x, plot.y0, theme.labelSmall, "right", "middle");
  r.text(labels.one, x, plot.y1, theme.labelSmall, "right", "middle");
}

/**
 * A row of a basis legend table for function i: focusable, `data-index=i`, a swatch in the
 * function's colour (`CYCLE[i mod 4]`) before `name` in its header cell, then `cells`; hovering
 * or focusing it highlights the function through `pointer.setRowHover`.
 */
export function legendRow(pointer, i, name, ...cells) {
  const swatch = el("span", { class: "sl-swatch", "aria-hidden": "true" });
  swatch.style.background = CYCLE[i % CYCLE.length];
  const row = el(
    "tr",
    { tabindex: "0", dataset: { index: String(i) } },
    el("th", { scope: "row" }, swatch, name),
    ...cells,
  );
  const enter = () => pointer.setRowHover(i);
  const leave = () => pointer.setRowHover(-1);
  row.addEventListener("pointerenter", enter);
  row.addEventListener("pointerleave", leave);
  row.addEventListener("focus", enter);
  row.addEventListener("blur", leave);
  return row;
}

/**
 * Draws graphs 0 … `functions` − 1 of i-major samples `values` (`count` per function) in the
 * basis colours, the highlighted one (`highlight`, or -1) last and thicker, on top.
 */
export function drawGraphs(r, values, functions, count, x, y, highlight) {
  const theme = r.theme;
  const cycle = theme.basisStroke.length;
  for (let i = 0; i < functions; i++) {
    if (i !== highlight) drawGraph(r, values, i, count, x, y, theme.basisStroke[i % cycle]);
  }
  if (highlight >= 0)
    drawGraph(r, values, highlight, count, x, y, theme.basisHover[highlight % cycle]);
}

/**
 * Where a highlighted function acts on the curve: paths the runs of curve samples `samples`
 * (flat [x, y, …] in world units, `count` of them) for which `inside(k)` holds, and paints them
 * with `style` (the band under the curve, in the function's colour).
 */
export function drawBand(r, v, samples, count, inside, style) {
  let open = false;
  r.beginPath();
  for (let k = 0; k < count; k++) {
    if (inside(k)) {
      const x = v.sx(samples[2 * k]);
      const y = v.sy(samples[2 * k + 1]);
      if (open) r.lineTo(x, y);
      else r.moveTo(x, y);
      open = true;
    } else {
      open = false;
    }
  }
  r.paint(style);
}
