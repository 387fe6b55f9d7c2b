/**
 * A square linear system A·m = c shown as an HTML table with its current numbers: one row per
 * equation — its label, the coefficients a_ij, the unknown m_i (with its solved value under
 * it), the right-hand side c_i. Built for the banded systems of interpolation (the C2 spline's
 * tridiagonal one, with cyclic corners when periodic), it shows any square matrix.
 *
 * Large systems are cut in the middle: at most `maxShown` rows and columns are shown, the first
 * and last ones, with one ellipsis row (⋮, ⋱ where the diagonal passes) and one ellipsis column
 * (⋯) between them, so the end rows stay legible in lecture mode (the caller picks a smaller
 * `maxShown` there). Rows can be highlighted (`tr.sl-highlight`) and single cells marked
 * (`td.sl-highlight`: the corners of a cyclic system).
 *
 *   const system = new SystemTable("tridiagonal", "cubicSpline.");
 *   ui.ctx.slots.details.append(system.title, system.wrap);
 *   system.show({ size, maxShown, entry(i, j), unknown(i), solution(i), rhs(i), label(i),
 *     highlight(i), marked(i, j) });
 *
 * Cells carry data attributes for tests: `td[data-row][data-col]` (a coefficient),
 * `td[data-unknown]`, `td[data-rhs]`, `th[data-label]`, `tr[data-row]` (−1 for the ellipsis row).
 * Header texts are strings.js keys `<prefix>systemEquation`, `.systemUnknown`, `.systemRhs`.
 */
import { el, setText } from "./controls.js";
import { shortNumber, subscript } from "./format.js";
import { t } from "./strings.js";
import { titledTable } from "./table.js";

/** Index −1 stands for the ellipsis row or column. */
export const ELLIPSIS = -1;

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

/** The ellipsis cell's text where shown row `i` meets shown column `j` (either may be ELLIPSIS). */
function ellipsisText(i, j) {
  if (i === ELLIPSIS && j === ELLIPSIS) return "⋱";
  return i === ELLIPSIS ? "⋮" : "⋯";
}

export class SystemTable {
  /** `name`: the table's `data-table`; `prefix`: the strings.js prefix of the header keys. */
  constructor(name, prefix) {
    const { title, table, wrap } = titledTable(name);
    this.title = title;
    this.table = table;
    this.wrap = wrap;
    this.prefix = prefix;
    this.key = "";
    this.rows = [];
    this.columns = [];
    this.cells = null;
  }

  /** Makes the rows and cells for `size` equations, `maxShown` at most (only when those change). */
  build(size, maxShown) {
    this.rows = shownIndices(size, maxShown);
    this.columns = this.rows;
    const head = el(
      "tr",
      {},
      el("th", { scope: "col", text: t(`${this.prefix}systemEquation`) }),
      this.columns.map((j) =>
        el("th", { scope: "col", text: j === ELLIPSIS ? "⋯" : `m${subscript(j)}` }),
      ),
      el("th", { scope: "col", text: t(`${this.prefix}systemUnknown`) }),
      el("th", { scope: "col", text: t(`${this.prefix}systemRhs`) }),
    );
    const cells = [];
    const body = this.rows.map((i) => {
      const row = { i, tr: null, label: null, entries: [], unknown: null, rhs: null };
      const dots = (j) => el("td", { class: "sl-cell-name", text: ellipsisText(i, j) });
      row.label = el("th", { scope: "row", class: "sl-cell-wrap", dataset: { label: String(i) } });
      row.entries = this.columns.map((j) =>
        i === ELLIPSIS || j === ELLIPSIS
          ? dots(j)
          : el("td", { dataset: { row: String(i), col: String(j) } }),
      );
      if (i === ELLIPSIS) {
        setText(row.label, "⋮");
        row.unknown = el("td", { class: "sl-cell-name", text: "⋮" });
        row.rhs = el("td", { class: "sl-cell-name", text: "⋮" });
      } else {
        row.name = el("span", { class: "sl-cell-value" });
        row.value = el("span", { class: "sl-cell-decimal" });
        row.unknown = el("td", { dataset: { unknown: String(i) } }, row.name, row.value);
        row.rhs = el("td", { dataset: { rhs: String(i) } });
      }
      row.tr = el(
        "tr",
        { dataset: { row: String(i) } },
        row.label,
        row.entries,
        row.unknown,
        row.rhs,
      );
      cells.push(row);
      return row.tr;
    });
    this.cells = cells;
    this.table.replaceChildren(el("thead", {}, head), el("tbody", {}, body));
  }

  /**
   * Shows a system: `size` equations, `maxShown` rows and columns at most, `entry(i, j)` → a_ij
   * (a number; zeros are shown muted), `unknown(i)` → its name, `solution(i)` → its value as text
   * (or ""), `rhs(i)` → c_i as text, `label(i)` → the equation's name, `highlight(i)` → whether
   * row i is highlighted, `marked(i, j)` → whether cell (i, j) is marked; `number(a)` → a
   * coefficient's text (default format.js `shortNumber`).
   */
  show(o) {
    const key = `${o.size}|${o.maxShown}`;
    if (key !== this.key) {
      this.key = key;
      this.build(o.size, o.maxShown);
    }
    for (const row of this.cells) {
      const i = row.i;
      if (i === ELLIPSIS) continue;
      setText(row.label, o.label(i));
      row.tr.classList.toggle("sl-highlight", Boolean(o.highlight(i)));
      this.columns.forEach((j, k) => {
        if (j === ELLIPSIS) return;
        const cell = row.entries[k];
        const a = o.entry(i, j);
        setText(cell, (o.number ?? shortNumber)(a));
        cell.classList.toggle("sl-cell-name", a === 0);
        cell.classList.toggle("sl-highlight", Boolean(o.marked?.(i, j)));
      });
      setText(row.name, o.unknown(i));
      setText(row.value, o.solution(i));
      setText(row.rhs, o.rhs(i));
    }
  }
}
