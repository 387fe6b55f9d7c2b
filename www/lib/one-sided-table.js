/**
 * The one-sided values at the joints of a piecewise curve, one table per joint under the figure
 * (`table[data-table=joint]`, `data-joint=<n>`): per coordinate and derivative order k the value
 * from the left P^{(k)}(t⁻) and from the right P^{(k)}(t⁺) (the core's, each piece on its closed
 * interval), whether they agree — by the core's verdict for k ≤ c, else by the numbers — and
 * the first order that differs marked (`tr.sl-highlight`, `data-order`). Strings under
 * `piecewise.` (col.*, agree.*, tableCaption, undefined).
 */
import { el, setText } from "./controls.js";
import { exactText, shortNumber } from "./format.js";
import { t } from "./strings.js";
import { detailsTable, headerRow } from "./table.js";

const PRIME_TEXT = Object.freeze(["", "′", "″", "‴"]);

/** Text of a one-sided value: exact-looking numbers, or the undefined word. */
const valueText = (x) => (Number.isFinite(x) ? exactText(x) : t("piecewise.undefined"));

/**
 * Do two one-sided values of order k agree: the core's verdict for k ≤ c and for the first
 * order that differs (`order`), else the numbers (to rounding)?
 */
export function agree(j, k, a, b) {
  if (k <= j.c) return true;
  if (k === j.order && !(Number.isFinite(a) && Number.isFinite(b) && a === b)) return false;
  const scale = 1 + Math.max(Math.abs(a), Math.abs(b));
  return Number.isFinite(a) && Number.isFinite(b) && Math.abs(a - b) <= 1e-9 * scale;
}

/**
 * The tables in `ui`'s details slot; `update(joints)` with per joint `{ t, c, order, left,
 * right, verdict, how }` (`left[k]`, `right[k]`: the one-sided P^{(k)}).
 */
export function oneSidedTables(ui) {
  const tables = [];
  function tableFor(k, shape) {
    while (tables.length <= k) {
      tables.push(
        detailsTable(ui, "joint", (rowsKey, table) => {
          const count = Number(rowsKey);
          const body = el("tbody");
          const cells = [];
          for (let r = 0; r < count; r++) {
            const row = {
              name: el("th", { scope: "row" }),
              left: el("td", { dataset: { side: "left" } }),
              right: el("td", { dataset: { side: "right" } }),
              agree: el("td", { dataset: { cell: "agree" } }),
            };
            row.tr = el("tr", {}, row.name, row.left, row.right, row.agree);
            cells.push(row);
            body.append(row.tr);
          }
          table.replaceChildren(
            el("thead", {}, headerRow("piecewise.col.", ["quantity", "left", "right", "agree"])),
            body,
          );
          return cells;
        }),
      );
    }
    return tables[k].cellsFor(shape);
  }
  return {
    update(joints) {
      joints.forEach((j, n) => {
        const count = j.left.length * 2;
        const cells = tableFor(n, String(count));
        const table = tables[n];
        table.table.hidden = false;
        table.title.hidden = false;
        table.table.dataset.joint = String(n);
        setText(
          table.title,
          t("piecewise.tableCaption", { t: shortNumber(j.t), verdict: j.verdict, how: j.how }),
        );
        const at = shortNumber(j.t);
        for (let k = 0; k < j.left.length; k++) {
          for (let c = 0; c < 2; c++) {
            const row = cells[2 * k + c];
            const name = `${"xy"[c]}${PRIME_TEXT[k]}`;
            setText(row.name, name);
            setText(row.left, `${name}(${at}⁻) = ${valueText(j.left[k][c])}`);
            setText(row.right, `${name}(${at}⁺) = ${valueText(j.right[k][c])}`);
            const same = agree(j, k, j.left[k][c], j.right[k][c]);
            setText(row.agree, t(same ? "piecewise.agree.yes" : "piecewise.agree.no"));
            row.tr.classList.toggle("sl-highlight", k === j.order);
            row.tr.dataset.order = String(k);
          }
        }
      });
      for (let n = joints.length; n < tables.length; n++) {
        tables[n].table.hidden = true;
        tables[n].title.hidden = true;
      }
    },
  };
}
