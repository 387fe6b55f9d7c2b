/**
 * A square linear system A x = b that the core solved, as a table under the figure (the details
 * slot): one row per equation — the condition it states, the row of A (exact fractions where the
 * entries are simple ones, zeros muted), the unknown x_i, "=", the right-hand side b_i and the
 * solution x_i — so a student reads the equations with the current numbers. Every cell carries
 * data attributes for tests (`tr[data-row][data-condition]`, `td[data-row][data-col]`,
 * `td[data-rhs]`, `td[data-solution]`). Systems with more than `maxSize` unknowns get a note
 * instead (the table would not fit a page).
 *
 *   const table = new SystemTable(ui, "interpolation-system", { maxSize: 12, headers, unknown });
 *   table.show(system, { caption, tooLarge, name: (i) => "C(1) = p₁", kind: (i) => "point" });
 */
import { el, setText } from "./controls.js";
import { fractionOrDecimals } from "./format.js";
import { titledTable } from "./table.js";

/** An entry closer than this to 0 is shown as 0 (round-off of the core's values). */
const ZERO_TOLERANCE = 1e-12;

/** Below this size a non-zero entry would read "0.000" in 3 decimals: 2 significant digits. */
const SMALL = 5e-4;

/**
 * A number as text: integers plain, simple fractions ("1/2", "−3/4"), else 3 decimals (2
 * significant digits for small non-zero values, "0.00031", so they do not read as 0).
 */
export function exactText(x) {
  if (Math.abs(x) < ZERO_TOLERANCE) return "0";
  const text = Math.abs(x) < SMALL ? x.toPrecision(2) : fractionOrDecimals(x);
  return text.replace("-", "−");
}

/** A point of `dim` coordinates from a flat list at row i: "(1, 3/2)". */
export function pointText(flat, i, dim) {
  const parts = [];
  for (let c = 0; c < dim; c++) parts.push(exactText(flat[i * dim + c]));
  return `(${parts.join(", ")})`;
}

export class SystemTable {
  /**
   * `name`: the table's `data-table`; `maxSize`: the most unknowns shown; `headers`: the column
   * heads `{ condition, unknown, rhs, solution }` (text); `unknown(j)`: the name of unknown j
   * ("r₂"), also the head of matrix column j.
   */
  constructor(ui, name, { maxSize, headers, unknown }) {
    const { title, table, wrap } = titledTable(name);
    this.title = title;
    this.table = table;
    this.wrap = wrap;
    this.note = el("p", { class: "sl-note", dataset: { info: `${name}-note` } });
    this.maxSize = maxSize;
    this.headers = headers;
    this.unknown = unknown;
    this.size = -1;
    ui.ctx.slots.details.append(title, wrap, this.note);
  }

  /** Builds the rows of a size × size system (cells filled by `show`). */
  _build(size) {
    this.size = size;
    const { headers, unknown } = this;
    const head = [el("th", { scope: "col", text: headers.condition })];
    for (let j = 0; j < size; j++) head.push(el("th", { scope: "col", text: unknown(j) }));
    head.push(
      el("th", { scope: "col", text: headers.unknown }),
      el("th", { scope: "col", text: "" }),
      el("th", { scope: "col", text: headers.rhs }),
      el("th", { scope: "col", text: headers.solution }),
    );
    this.cells = { names: [], entries: [], rhs: [], solution: [], rows: [] };
    const rows = [];
    for (let i = 0; i < size; i++) {
      const name = el("th", { scope: "row" });
      const line = [name];
      for (let j = 0; j < size; j++) {
        const cell = el("td", { dataset: { row: String(i), col: String(j) } });
        this.cells.entries.push(cell);
        line.push(cell);
      }
      const rhs = el("td", { dataset: { rhs: String(i) } });
      const solution = el("td", { dataset: { solution: String(i) } });
      line.push(el("td", { text: unknown(i) }), el("td", { text: "=" }), rhs, solution);
      const row = el("tr", { dataset: { row: String(i) } }, line);
      this.cells.names.push(name);
      this.cells.rhs.push(rhs);
      this.cells.solution.push(solution);
      this.cells.rows.push(row);
      rows.push(row);
    }
    this.table.replaceChildren(el("thead", {}, el("tr", {}, head)), el("tbody", {}, rows));
  }

  /**
   * Shows `{ size, matrix (row-major), rhs, solution }` (rhs and solution: `dim` numbers per
   * row) with `caption`; `name(i)` is row i's condition, `kind(i)` its `data-condition`;
   * `tooLarge` the note's text when size exceeds `maxSize`.
   */
  show({ size, matrix, rhs, solution }, { dim, caption, tooLarge, name, kind }) {
    const fits = size <= this.maxSize;
    this.title.hidden = !fits;
    this.wrap.hidden = !fits;
    this.note.hidden = fits;
    setText(this.note, fits ? "" : tooLarge);
    if (!fits) return;
    if (size !== this.size) this._build(size);
    setText(this.title, caption);
    const { names, entries, rows } = this.cells;
    for (let i = 0; i < size; i++) {
      setText(names[i], name(i));
      rows[i].dataset.condition = kind(i);
      for (let j = 0; j < size; j++) {
        const a = matrix[i * size + j];
        setText(entries[i * size + j], exactText(a));
        entries[i * size + j].classList.toggle("sl-cell-name", Math.abs(a) < ZERO_TOLERANCE);
      }
      setText(this.cells.rhs[i], pointText(rhs, i, dim));
      setText(this.cells.solution[i], `${this.unknown(i)} = ${pointText(solution, i, dim)}`);
    }
  }
}
