/**
 * The Cox–de Boor triangle at u as a table (`data-table="cox-de-boor"`): for the span k with
 * u ∈ [u_k, u_{k+1}), row r (degree r = 0 … p) holds N_{k−r,r}(u) … N_{k,r}(u) under the columns
 * i = k − p … k — the core's `curve.basisTable(u).levels[r][j]` = N_{k−r+j,r}(u); the cells left
 * of the triangle stay empty. Each N_{i,r} follows from the two above it by the recurrence
 * N_{i,r} = (u − u_i)/(u_{i+r} − u_i) N_{i,r−1} + (u_{i+r+1} − u)/(u_{i+r+1} − u_{i+1}) N_{i+1,r−1}.
 */
import { el, setText } from "./controls.js";
import { fmt, subscript } from "./format.js";
import { t } from "./strings.js";
import { titledTable } from "./table.js";

export class BasisTriangleTable {
  /**
   * @param {string} prefix the demo's strings.js prefix: `<prefix>.triangleCorner` (corner
   *   header) and `<prefix>.triangleRow` (row header, given `{ r }`).
   */
  constructor(prefix) {
    const { title, table, wrap } = titledTable("cox-de-boor");
    this.prefix = prefix;
    this.title = title;
    this.table = table;
    /** Append these two to the demo's details. */
    this.wrap = wrap;
    this.shape = ""; // "p/k" the table was built for
    this.cells = []; // per level r, per j: the value span
  }

  /** Shows the triangle of degree p on span k (`levels` from `basisTable(u)`) under `caption`. */
  show(p, k, levels, caption) {
    if (this.shape !== `${p}/${k}`) this._build(p, k);
    setText(this.title, caption);
    for (let r = 0; r <= p; r++) {
      for (let j = 0; j <= r; j++) setText(this.cells[r][j], fmt(levels[r][j]));
    }
  }

  _build(p, k) {
    this.shape = `${p}/${k}`;
    this.cells = [];
    const head = [el("th", { scope: "col", text: t(`${this.prefix}.triangleCorner`) })];
    for (let i = k - p; i <= k; i++) head.push(el("th", { scope: "col", text: `i = ${i}` }));
    const body = [];
    for (let r = 0; r <= p; r++) {
      const cells = [el("th", { scope: "row", text: t(`${this.prefix}.triangleRow`, { r }) })];
      const level = [];
      for (let i = k - p; i <= k; i++) {
        if (i < k - r) {
          cells.push(el("td", { class: "sl-cell-empty" }));
          continue;
        }
        const value = el("span", { class: "sl-cell-value" });
        level.push(value);
        const name = el("span", {
          class: "sl-cell-name",
          text: `N${subscript(i)},${subscript(r)} = `,
        });
        cells.push(el("td", { dataset: { r: String(r), i: String(i) } }, name, value));
      }
      this.cells.push(level);
      body.push(el("tr", {}, cells));
    }
    this.table.replaceChildren(el("thead", {}, el("tr", {}, head)), el("tbody", {}, body));
  }
}
