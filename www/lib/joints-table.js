/**
 * Every distinct interior knot of a B-spline as a row of a table (`data-table="knots"`, rows
 * `data-knot`): its names u_a = … = u_b and value, its multiplicity r, the continuity the knots
 * guarantee (C^{p−r}, `knotContinuity()`), the one measured at the joint (lib/joint-continuity.js),
 * the curve's point there (both sides where it breaks) and the control point it passes through,
 * if any. Cells `data-cell`: multiplicity, guaranteed, measured, point (`data-x`, `data-y`), through.
 */
import { el } from "./controls.js";
import { pointText } from "./format.js";
import { t } from "./strings.js";
import { titledTable } from "./table.js";
import { knotMachine, knotText, stackOf } from "./knot-ruler.js";
import { knotNames } from "./knot-readout.js";
import { continuityText, measuredText } from "./continuity.js";

/** "(6.000, 4.000)"; "(6,000; 4,000)" with a decimal comma. */
const pair = ([x, y]) => pointText([x, y]);

const COLUMNS = ["colKnot", "colR", "colGuaranteed", "colMeasured", "colPoint", "colThrough"];

export class JointsTable {
  /**
   * @param {string} prefix the demo's strings.js prefix: `.knotsCaption`, the `COLUMNS` headers,
   *   `.pointBreak` ({ left, right }) for the two points of a break.
   */
  constructor(prefix) {
    const { title, table, wrap } = titledTable("knots", { caption: t(`${prefix}.knotsCaption`) });
    this.prefix = prefix;
    this.title = title;
    this.table = table;
    /** Append these two to the demo's details. */
    this.wrap = wrap;
  }

  /**
   * One row per `continuity` entry (`knotContinuity()`) of `knots`; `jointAt(u)` the measured
   * joint or null, `through(joint)` "P₄" or "", the row of knot `highlight` highlighted.
   */
  show(knots, continuity, jointAt, through, highlight) {
    const rows = continuity.map((entry) => {
      const jt = jointAt(entry.knot);
      const [a, b] = stackOf(knots, knots.indexOf(entry.knot));
      let point = "—";
      let pointData = { cell: "point" };
      if (jt) {
        pointData = { cell: "point", x: String(jt.right[0]), y: String(jt.right[1]) };
        const sides = { left: pair(jt.left), right: pair(jt.right) };
        point = jt.c >= 0 ? sides.right : t(`${this.prefix}.pointBreak`, sides);
      }
      const row = el(
        "tr",
        { dataset: { knot: knotMachine(entry.knot) } },
        el("th", { scope: "row", text: `${knotNames(a, b)} = ${knotText(entry.knot)}` }),
        el("td", { dataset: { cell: "multiplicity" }, text: String(entry.multiplicity) }),
        el("td", { dataset: { cell: "guaranteed" }, text: continuityText(entry.continuity) }),
        el("td", { dataset: { cell: "measured" }, text: measuredText(jt) }),
        el("td", { dataset: pointData, text: point }),
        el("td", { dataset: { cell: "through" }, text: through(jt) || "—" }),
      );
      if (entry.knot === highlight) row.classList.add("sl-highlight");
      return row;
    });
    const column = (key) => el("th", { scope: "col", text: t(`${this.prefix}.${key}`) });
    const head = el("tr", {}, COLUMNS.map(column));
    this.table.replaceChildren(el("thead", {}, head), el("tbody", {}, rows));
  }
}
