/**
 * The control points Q_i after inserting a knot s ∈ [u_k, u_{k+1}) into a degree-p B-spline, as
 * a table (`data-table="knot-insertion"`), each with the rule of Boehm's algorithm that made it:
 *   Q_i = P_i (i ≤ k − p),  Q_i = P_{i−1} (i ≥ k + 1),
 *   Q_i = (1 − α_i) P_{i−1} + α_i P_i (k − p + 1 ≤ i ≤ k),
 * α_i = (s − u_i)/(u_{i+p} − u_i); the rows of new points highlighted, their values (cells
 * `data-index`) the core's new polygon. The α come from the core's `insertionAlphas(s)`.
 */
import { el, setText } from "./controls.js";
import { pointText, subscript, fractionOrDecimals } from "./format.js";
import { titledTable } from "./table.js";

export class InsertionTable {
  constructor() {
    const { title, table, wrap } = titledTable("knot-insertion");
    this.title = title;
    this.table = table;
    /** Append these two to the demo's details. */
    this.wrap = wrap;
  }

  /**
   * Shows the polygon `q` (flat, the core's after the insertion) for degree p, span k and
   * `alphas` `[{ i, value }]` under `caption`; with `empty` only the caption (nothing inserted).
   */
  show(q, p, k, alphas, caption, empty) {
    setText(this.title, caption);
    const rows = [];
    for (let i = 0; !empty && i < q.length / 2; i++) {
      const alpha = alphas.find((a) => a.i === i);
      const Q = `Q${subscript(i)}`;
      let rule = `${Q} = P${subscript(i - 1)}`;
      if (i <= k - p) rule = `${Q} = P${subscript(i)}`;
      else if (alpha) {
        const [a, b] = [fractionOrDecimals(1 - alpha.value), fractionOrDecimals(alpha.value)];
        rule = `${Q} = ${a} P${subscript(i - 1)} + ${b} P${subscript(i)}`;
      }
      const value = pointText([q[2 * i], q[2 * i + 1]]);
      rows.push(
        el(
          "tr",
          { class: alpha ? "sl-highlight" : undefined },
          el("th", { scope: "row", text: Q }),
          el("td", { text: rule }),
          el("td", { dataset: { index: String(i) }, text: value }),
        ),
      );
    }
    this.table.replaceChildren(el("tbody", {}, rows));
  }
}
