/**
 * The tables under a figure (details slot): a visible title that labels the table, the table in
 * a wrapper that scrolls sideways, and the "exact value, decimals underneath" cell used for
 * fractions.
 *
 *   const { title, table, wrap } = titledTable("de-casteljau");
 *   ctx.slots.details.append(title, wrap);
 *   …
 *   setText(title, t("deCasteljau.tableCaption", { t: "1/4" }));
 */
import { el, setText } from "./controls.js";
import { t } from "./strings.js";
import { scrollRegion } from "./scroll-region.js";

let nextId = 0;

/**
 * A `<p class="sl-table-title">` and a `<table class="sl-table" data-table="name">` labelled by it
 * (`aria-labelledby`, an id unique on the page), the table inside a `.sl-table-wrap` (which, when
 * the table is too wide, is a tab stop named by the title: scroll-region.js).
 * `caption`: the title's text when it never changes; `children`: the table's first contents.
 * Returns `{ title, table, wrap }`; append `title` and `wrap` where the table goes.
 */
export function titledTable(name, { caption, children = [] } = {}) {
  nextId += 1;
  const title = el("p", { class: "sl-table-title", id: `sl-table-${nextId}`, text: caption });
  const table = el(
    "table",
    { class: "sl-table", dataset: { table: name }, "aria-labelledby": title.id },
    children,
  );
  const wrap = scrollRegion(
    el("div", { class: "sl-table-wrap" }, table),
    { labelledBy: title.id },
    [table],
  );
  return { title, table, wrap };
}

/**
 * A titled table in a declarative demo's details slot (`ui`, see demo.js) whose contents are
 * made by `build(key, table)` only when `key` (the degree, say) changed: `cellsFor(key)` returns
 * what `build` returned, for the caller to fill. `title` is the table's visible title.
 */
export function detailsTable(ui, name, build) {
  const { title, table, wrap } = titledTable(name);
  ui.ctx.slots.details.append(title, wrap);
  let shownKey;
  let cells = null;
  return {
    title,
    table,
    cellsFor(key) {
      if (key !== shownKey) {
        shownKey = key;
        cells = build(key, table);
      }
      return cells;
    },
  };
}

/** A header row: a `<th scope="col">` per key, reading `t(prefix + key)`. */
export function headerRow(prefix, keys) {
  return el(
    "tr",
    {},
    keys.map((key) => el("th", { scope: "col", text: t(`${prefix}${key}`) })),
  );
}

/**
 * A table of named values, one row per key: `<th scope="row">` reading `t(prefix + key)`, then
 * an empty `<td>` with the data attribute `attribute` (a dataset name: "quantity" →
 * `data-quantity`) set to the key. Returns `{ rows, cells }`, the cells by key, for the demo to fill.
 */
export function namedRows(prefix, keys, attribute) {
  const cells = {};
  const rows = keys.map((key) => {
    cells[key] = el("td", { dataset: { [attribute]: key } });
    return el("tr", {}, el("th", { scope: "row", text: t(`${prefix}${key}`) }), cells[key]);
  });
  return { rows, cells };
}

/** The two spans of a value cell: `exact` (a fraction, or the decimals) and `decimal` under it. */
export function valueSpans() {
  return {
    exact: el("span", { class: "sl-cell-value" }),
    decimal: el("span", { class: "sl-cell-decimal" }),
  };
}

/**
 * Fills `valueSpans()`: the exact text first, then "≈ decimals" underneath when they say
 * something different (nothing underneath when `exactText` is already the decimals).
 */
export function setValueSpans(spans, exactText, decimalText) {
  setText(spans.exact, exactText);
  setText(spans.decimal, exactText === decimalText ? "" : `≈ ${decimalText}`);
}
