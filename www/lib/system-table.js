/**
 * A square linear system A x = b that the core solved, shown as an HTML table with its current
 * numbers (under the figure, the details slot): one row per equation — its label (the condition
 * or equation it states), the coefficients a_ij (zeros muted), the unknown x_i, the right-hand
 * side b_i and the solution x_i — so a student reads the equations with the numbers. Nothing is
 * solved here: the caller hands in the core's matrix, right-hand side and solution.
 *
 * Two layouts, by whether `headers.solution` is given:
 * - without it the solved value sits under the unknown's name (`m₁` over "= (3, 4)");
 * - with it the row reads as an equation, `… x_i = b_i`, followed by a solution column.
 *
 * Large systems either keep their first and last rows and columns around an ellipsis row (⋮, ⋱
 * where the diagonal passes) and column (⋯): `maxShown` at most (pass a smaller one in lecture
 * mode); or, above `maxSize` unknowns, show a note (`tooLarge`) instead of the table. Rows can
 * be highlighted (`tr.sl-highlight`: the end conditions) and single cells marked
 * (`td.sl-highlight`: the corners of a cyclic system). Cells are exact fractions or decimals as
 * the caller's `number` writes them (format.js `exactText`, `shortNumber`, …).
 *
 *   const table = new SystemTable("cubic-system", { headers: { label, unknown, rhs } });
 *   ui.ctx.slots.details.append(...table.nodes);
 *   table.show({ size, entry: (i, j) => a, unknown: (i) => "m₁", rhs: (i) => "(3, 4)",
 *     solution: (i) => "= (1, 2)", label: (i) => "C″ continuous at t₁", maxShown: 9 });
 *
 * Data attributes for tests: `tr[data-row]` (−1 for the ellipsis row) with `data-condition`
 * (`kind(i)`), `th[data-label]`, `td[data-row][data-col]` (a coefficient), `td[data-unknown]`,
 * `td[data-rhs]`, `td[data-solution]` (solution column), the note `[data-info=<name>-note]`.
 */
import { el, setText } from "./controls.js";
import { exactText, listSeparator, shortNumber } from "./format.js";
import { titledTable } from "./table.js";

/** Index −1 stands for the ellipsis row or column. */
export const ELLIPSIS = -1;

/** A coefficient closer than this to 0 is muted as a zero (round-off of the core's values). */
const ZERO_TOLERANCE = 1e-12;

/**
 * The indices shown of `size` rows (or columns) when at most `maxShown` fit: all of them, or the
 * first ⌈(maxShown − 1)/2⌉, ELLIPSIS, and the last ⌊(maxShown − 1)/2⌋.
 */
export function shownIndices(size, maxShown) {
  const all = [];
  if (size <= maxShown) {
    for (let i = 0; i < size; i++) all.push(i);
    return all;
  }
  const head = Math.ceil((maxShown - 1) / 2);
  const tail = Math.max(1, maxShown - 1 - head);
  for (let i = 0; i < head; i++) all.push(i);
  all.push(ELLIPSIS);
  for (let i = size - tail; i < size; i++) all.push(i);
  return all;
}

/**
 * Row i of a flat list of `dim`-vectors as a point, "(1, 3/2)" ("(1,5; 3/2)" with a decimal
 * comma); `number` writes a coordinate.
 */
export function rowPoint(flat, i, dim, number = exactText) {
  const parts = [];
  for (let c = 0; c < dim; c++) parts.push(number(flat[i * dim + c]));
  return `(${parts.join(listSeparator())})`;
}

/** The ellipsis cell's text where shown row `i` meets shown column `j` (either may be ELLIPSIS). */
function ellipsisText(i, j) {
  if (i === ELLIPSIS && j === ELLIPSIS) return "⋱";
  return i === ELLIPSIS ? "⋮" : "⋯";
}

const muted = (text) => el("td", { class: "sl-cell-name", text });

export class SystemTable {
  /**
   * `name`: the table's `data-table`; `headers`: the column heads as text, `{ label, unknown,
   * rhs, solution? }` (a solution column only with `solution`); `wrapLabels`: long row labels
   * (whole equations) may wrap (`th.sl-cell-wrap`), so the table stays narrow. Append `nodes`
   * (the title, the table's wrapper, the note) where the table goes.
   */
  constructor(name, { headers, wrapLabels = false }) {
    const { title, table, wrap } = titledTable(name);
    this.title = title;
    this.table = table;
    this.wrap = wrap;
    this.note = el("p", { class: "sl-note", dataset: { info: `${name}-note` }, hidden: true });
    this.nodes = [title, wrap, this.note];
    this.headers = headers;
    this.wrapLabels = wrapLabels;
    this.key = "";
    this.columns = [];
    this.cells = [];
  }

  /** Makes the rows and cells for `size` equations, `maxShown` at most (only when those change). */
  _build(size, maxShown, unknown) {
    const { headers } = this;
    const rows = shownIndices(size, maxShown);
    const columns = rows;
    const equation = headers.solution != null;
    const th = (text) => el("th", { scope: "col", text });
    const head = el(
      "tr",
      {},
      th(headers.label),
      columns.map((j) => th(j === ELLIPSIS ? "⋯" : unknown(j))),
      th(headers.unknown),
      equation ? el("td") : null, // above the "=" column: heads nothing
      th(headers.rhs),
      equation ? th(headers.solution) : null,
    );
    const labelClass = this.wrapLabels ? "sl-cell-wrap" : null;
    this.cells = rows.map((i) => {
      const row = { i, entries: [] };
      const data = (key) => ({ [key]: String(i) });
      row.label = el("th", { scope: "row", class: labelClass, dataset: data("label") });
      row.entries = columns.map((j) =>
        i === ELLIPSIS || j === ELLIPSIS
          ? muted(ellipsisText(i, j))
          : el("td", { dataset: { row: String(i), col: String(j) } }),
      );
      if (i === ELLIPSIS) {
        setText(row.label, "⋮");
        row.unknown = muted("⋮");
        row.rhs = muted("⋮");
        row.solution = equation ? muted("⋮") : null;
      } else {
        row.name = el("span", { class: "sl-cell-value" });
        row.value = el("span", { class: "sl-cell-decimal" });
        row.unknown = el("td", { dataset: data("unknown") }, row.name, row.value);
        row.rhs = el("td", { dataset: data("rhs") });
        row.solution = equation ? el("td", { dataset: data("solution") }) : null;
      }
      const equals = equation ? el("td", { text: i === ELLIPSIS ? "" : "=" }) : null;
      row.tr = el(
        "tr",
        { dataset: { row: String(i) } },
        row.label,
        row.entries,
        row.unknown,
        equals,
        row.rhs,
        row.solution,
      );
      return row;
    });
    this.columns = columns;
    this.table.replaceChildren(
      el("thead", {}, head),
      el(
        "tbody",
        {},
        this.cells.map((row) => row.tr),
      ),
    );
  }

  /**
   * Shows a system of `size` equations: `entry(i, j)` → a_ij (a number), `number(a)` → its text
   * (default `shortNumber`; `exactText` for fractions), `unknown(j)` → the name of unknown j
   * (the head of matrix column j too), `rhs(i)` → b_i as text, `solution(i)` → the solved x_i as
   * text ("" for none), `label(i)` → row i's equation or condition; optional: `kind(i)` → its
   * `data-condition`, `highlight(i)` → whether row i is highlighted, `marked(i, j)` → whether
   * cell (i, j) is marked, `caption` → the title's text, `maxShown` → the most rows and columns
   * shown (an ellipsis cut), `maxSize` and `tooLarge` → above `maxSize` unknowns the note
   * `tooLarge` instead of the table.
   */
  show(o) {
    const fits = o.maxSize == null || o.size <= o.maxSize;
    this.title.hidden = !fits;
    this.wrap.hidden = !fits;
    this.note.hidden = fits;
    setText(this.note, fits ? "" : o.tooLarge);
    if (!fits) return;
    const maxShown = o.maxShown ?? Number.POSITIVE_INFINITY;
    const key = `${o.size}|${maxShown}`;
    if (key !== this.key) {
      this.key = key;
      this._build(o.size, maxShown, o.unknown);
    }
    if (o.caption != null) setText(this.title, o.caption);
    const number = o.number ?? shortNumber;
    for (const row of this.cells) {
      const i = row.i;
      if (i === ELLIPSIS) continue;
      setText(row.label, o.label(i));
      if (o.kind) row.tr.dataset.condition = o.kind(i);
      row.tr.classList.toggle("sl-highlight", Boolean(o.highlight?.(i)));
      this.columns.forEach((j, k) => {
        if (j === ELLIPSIS) return;
        const cell = row.entries[k];
        const a = o.entry(i, j);
        setText(cell, number(a));
        cell.classList.toggle("sl-cell-name", Math.abs(a) < ZERO_TOLERANCE);
        cell.classList.toggle("sl-highlight", Boolean(o.marked?.(i, j)));
      });
      setText(row.name, o.unknown(i));
      setText(row.solution ?? row.value, o.solution(i)); // its own column, or under the unknown
      setText(row.rhs, o.rhs(i));
    }
  }
}
