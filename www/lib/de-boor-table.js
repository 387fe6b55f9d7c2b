/**
 * De Boor's triangle at u as a table (`data-table="de-boor"`): row r (level r = 0 … p) holds the
 * points d_j^r, j = r … p (cells `data-level`, `data-index`), each as an exact pair when the
 * numbers allow (lib/de-boor-exact.js) with "≈ decimals" under it when they say more, level 0
 * named after its control point d_j^0 = P_{j+k−p}, and the α_j^r of
 * d_j^r = (1 − α_j^r) d_{j−1}^{r−1} + α_j^r d_j^{r−1} that made the cell (`data-alpha`).
 */
import { el, setText } from "./controls.js";
import { fmtMachine, pointText, subscript, superscript } from "./format.js";
import { t } from "./strings.js";
import { titledTable } from "./table.js";

export class DeBoorTable {
  /**
   * @param {string} prefix the demo's strings.js prefix: `.tableLevel` ({ r }) for a row's
   *   header, `.alphaCell` ({ value }) for the α under a cell.
   */
  constructor(prefix) {
    const { title, table, wrap } = titledTable("de-boor");
    this.prefix = prefix;
    this.title = title;
    this.table = table;
    /** Append these two to the demo's details. */
    this.wrap = wrap;
    this.degree = -1;
    this.cells = []; // level by level, per point: { name, exact, decimal, alpha }
  }

  /**
   * Shows the triangle of degree p on span k under `caption`: `triangle` the core's flat points
   * level by level (`deBoor(u)`), `alphas` by level, `num` from `deBoorExact`.
   */
  show(p, k, triangle, alphas, num, caption) {
    if (this.degree !== p) this._build(p);
    setText(this.title, caption);
    let c = 0;
    for (let level = 0; level <= p; level++) {
      for (let i = 0; i <= p - level; i++, c++) {
        const j = level + i;
        const x = triangle[2 * c];
        const y = triangle[2 * c + 1];
        const decimals = pointText([x, y]);
        const exact = num.exact
          ? pointText([num.coord(x, level, i, false), num.coord(y, level, i, false)])
          : decimals;
        const spans = this.cells[c];
        const name = `d${subscript(j)}${superscript(level)} = `;
        setText(spans.name, level === 0 ? `${name}P${subscript(j + k - p)} ` : name);
        setText(spans.exact, exact);
        // Decimals underneath only when they say something the exact value does not.
        setText(
          spans.decimal,
          exact === decimals || /^\(-?\d+[,;] -?\d+\)$/.test(exact) ? "" : `≈ ${decimals}`,
        );
        if (level > 0) {
          const alpha = alphas[level - 1][i];
          setText(spans.alpha, t(`${this.prefix}.alphaCell`, { value: num.alpha(alpha, false) }));
          spans.alpha.dataset.alpha = fmtMachine(alpha.value);
        }
      }
    }
  }

  _build(p) {
    this.degree = p;
    this.cells = [];
    const rows = [];
    for (let level = 0; level <= p; level++) {
      const row = [el("th", { scope: "row", text: t(`${this.prefix}.tableLevel`, { r: level }) })];
      for (let j = level; j <= p; j++) {
        const spans = {
          name: el("span", { class: "sl-cell-name" }),
          exact: el("span", { class: "sl-cell-value" }),
          decimal: el("span", { class: "sl-cell-decimal" }),
          alpha: el("span", { class: "sl-cell-decimal" }),
        };
        this.cells.push(spans);
        const dataset = { level: String(level), index: String(j) };
        const alpha = level > 0 ? spans.alpha : null;
        row.push(el("td", { dataset }, spans.name, spans.exact, spans.decimal, alpha));
      }
      rows.push(el("tr", {}, row));
    }
    this.table.replaceChildren(el("tbody", {}, rows));
  }
}
