/**
 * The values of every B-spline basis function at u as a legend table (`data-table="basis"`): one
 * row per N_{i,p} (swatch in its control point's colour, hover/focus highlights it through the
 * plot's pointer, lib/basis-plot.js) with its support [u_i, u_{i+p+1}) and N_{i,p}(u) — the
 * decimals, and "= a/b" under them when the value is a simple fraction — then a row with the sum
 * Σ N_{i,p}(u), which is 1 on the domain (partition of unity). Values come from the core
 * (`basis(u)`); the table only shows them.
 */
import { el, setText } from "./controls.js";
import { fmt, subscript, simpleFraction, fractionText } from "./format.js";
import { t } from "./strings.js";
import { titledTable } from "./table.js";
import { knotText } from "./knot-ruler.js";
import { legendRow } from "./basis-plot.js";

export class BasisValuesTable {
  /**
   * @param {string} prefix the demo's strings.js prefix: `.colFunction`, `.colSupport`,
   *   `.colValue`, `.rowName` ({ name, point }), `.sumRow`, `.supportCell` ({ i, j, a, b }).
   * @param {object} pointer the `BasisPlotPointer` the rows report their hover to.
   * @param {(p: number, i: number) => string} name "N₃,₂" for degree p and index i.
   */
  constructor(prefix, pointer, name) {
    const { title, table, wrap } = titledTable("basis");
    this.prefix = prefix;
    this.pointer = pointer;
    this.name = name;
    this.title = title;
    this.table = table;
    /** Append these two to the demo's details. */
    this.wrap = wrap;
    this.shape = ""; // "count/p" the table was built for
    this.rows = []; // per i: { row, support, value, exact }
    this.sumValue = null;
  }

  /**
   * Shows N_{i,p}(u) = `values[i]` for the knots `knots`, their sum `sum`, row `highlight`
   * highlighted (-1: none), under `caption`.
   */
  show(p, knots, values, sum, highlight, caption) {
    const n = values.length - 1;
    if (this.shape !== `${n + 1}/${p}`) this._build(n, p);
    setText(this.title, caption);
    this.rows.forEach((cells, i) => {
      const ends = { a: knotText(knots[i]), b: knotText(knots[i + p + 1]) };
      const sub = { i: subscript(i), j: subscript(i + p + 1) };
      setText(cells.support, t(`${this.prefix}.supportCell`, { ...sub, ...ends }));
      setText(cells.value, fmt(values[i]));
      const f = simpleFraction(values[i]);
      setText(cells.exact, f && f.den > 1 ? `= ${fractionText(f)}` : "");
      cells.row.classList.toggle("sl-highlight", i === highlight);
    });
    setText(this.sumValue, fmt(sum));
  }

  /** Rebuilds the rows for n + 1 functions of degree p. */
  _build(n, p) {
    this.shape = `${n + 1}/${p}`;
    const column = (key) => el("th", { scope: "col", text: t(`${this.prefix}.${key}`) });
    this.rows = [];
    for (let i = 0; i <= n; i++) {
      const cells = { support: el("span"), value: el("span", { class: "sl-cell-value" }) };
      cells.exact = el("span", { class: "sl-cell-decimal" });
      const point = `P${subscript(i)}`;
      const name = t(`${this.prefix}.rowName`, { name: this.name(p, i), point });
      cells.row = legendRow(
        this.pointer,
        i,
        name,
        el("td", { dataset: { cell: "support" } }, cells.support),
        el("td", { dataset: { cell: "value" } }, cells.value, cells.exact),
      );
      this.rows.push(cells);
    }
    this.sumValue = el("span", { class: "sl-cell-value" });
    const sumHead = el("th", { scope: "row", text: t(`${this.prefix}.sumRow`) });
    const sumCell = el("td", { dataset: { cell: "value" } }, this.sumValue);
    const sumRow = el("tr", { dataset: { index: "sum" } }, sumHead, el("td", {}), sumCell);
    const head = el("tr", {}, column("colFunction"), column("colSupport"), column("colValue"));
    const body = el(
      "tbody",
      {},
      this.rows.map((r) => r.row),
      sumRow,
    );
    this.table.replaceChildren(el("thead", {}, head), body);
  }
}
