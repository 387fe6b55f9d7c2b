/**
 * The `parametrization` demo's numbers as text: the formula panel's lines and the table of the
 * data parameters. The parameters are the core's (`params()` of each curve); the legs
 * |p_{i+1} − p_i| are read off the chord-length parameters (their differences), so nothing is
 * measured here. Curves are indexed as the demo's KINDS: uniform, chord, centripetal, α.
 */
import { el, setText } from "./controls.js";
import { fmt, shortNumber, fractionOrDecimals, texListSeparator } from "./format.js";
import { t } from "./strings.js";
import { titledTable } from "./table.js";

/** Lists in the formula are cut after this many entries (then “…” and the last). */
const LISTED = 7;
/** The exponents of the named parametrisations. */
const NAMED_ALPHAS = Object.freeze([0, 1, 0.5]);
const NAMES = Object.freeze(["uniform", "chord", "centripetal"]);

/** The legs |p_{i+1} − p_i|: differences of the chord-length parameters. */
export function legsOf(chordParams) {
  const legs = [];
  for (let i = 1; i < chordParams.length; i++) legs.push(chordParams[i] - chordParams[i - 1]);
  return legs;
}

/** A list as TeX "(a,\ b,\ …,\ z)" (";\ " with a decimal comma), cut after LISTED entries. */
function listTex(values) {
  const shown = values.slice(0, Math.min(values.length, LISTED)).map((x) => shortNumber(x, true));
  if (values.length > LISTED) shown.push("\\dots", shortNumber(values[values.length - 1], true));
  return `(${shown.join(texListSeparator())})`;
}

const text = (key) => `\\text{${t(`parametrization.tex.${key}`)}}`;
const alphaTex = (alpha) => fractionOrDecimals(alpha, true);

/**
 * The rule with its normalised parameter and speed, the legs, each named parametrisation's
 * parameters, and the slider's α with one step worked out on the longest leg.
 */
export function parametrizationFormula(s, shown, alphaCurve) {
  const legs = legsOf(Array.from(shown[1].params));
  const lines = [
    `t_0 = 0,\\quad t_{i+1} = t_i + |p_{i+1} - p_i|^{\\alpha},\\qquad s = \\frac{t - t_0}{t_n - t_0},\\quad \\left|\\frac{dC}{ds}\\right| = (t_n - t_0)\\,|C'(t)|`,
    `|p_{i+1} - p_i| = ${listTex(legs)}`,
  ];
  for (let c = 0; c < 3; c++) {
    lines.push(
      `${text(NAMES[c])}\\ (\\alpha = ${alphaTex(NAMED_ALPHAS[c])}):\\ \\ t = ${listTex(Array.from(shown[c].params))}`,
    );
  }
  if (!alphaCurve) return lines;
  let longest = 0;
  for (let i = 1; i < legs.length; i++) if (legs[i] > legs[longest]) longest = i;
  const params = shown[3].params;
  const i = longest;
  const a = alphaTex(s.alpha);
  const same = NAMED_ALPHAS.indexOf(s.alpha);
  const note = same >= 0 ? `\\ =\\ ${text(NAMES[same])}` : "";
  lines.push(
    `\\alpha = ${a}:\\ \\ t_{${i + 1}} = t_{${i}} + |p_{${i + 1}} - p_{${i}}|^{${a}} = ` +
      `${shortNumber(params[i], true)} + {${shortNumber(legs[i], true)}}^{${a}} = ${shortNumber(params[i + 1], true)},` +
      `\\quad t = ${listTex(Array.from(params))}${note}`,
  );
  return lines;
}

/**
 * The table under the figure: a column per data point i; a row of the legs |p_{i+1} − p_i|,
 * then one row of parameters t_i per curve (`data-kind`, cells `data-index`).
 */
export class ParametrizationTable {
  constructor(ui) {
    const { title, table, wrap } = titledTable("parametrization", {
      caption: t("parametrization.tableCaption"),
    });
    ui.ctx.slots.details.append(title, wrap);
    this.table = table;
    this.count = -1;
  }

  build(count) {
    this.count = count;
    const head = [el("th", { scope: "col", text: t("parametrization.colKind") })];
    for (let i = 0; i < count; i++) head.push(el("th", { scope: "col", text: `${i}` }));
    const row = (kind, key) => {
      const cells = [];
      for (let i = 0; i < count; i++) cells.push(el("td", { dataset: { index: String(i) } }));
      const name = el("th", { scope: "row", text: t(key) });
      return { row: el("tr", { dataset: { kind } }, name, cells), cells, name };
    };
    this.legs = row("legs", "parametrization.rowLegs");
    this.kinds = ["uniform", "chord", "centripetal", "alpha"].map((kind) =>
      row(kind, `parametrization.row.${kind}`),
    );
    this.table.replaceChildren(
      el("thead", {}, el("tr", {}, head)),
      el(
        "tbody",
        {},
        this.legs.row,
        this.kinds.map((k) => k.row),
      ),
    );
  }

  /** Fills the rows from the curves' parameters (the α row shows α, hidden with its curve). */
  show(s, shown) {
    const count = s.points.length;
    if (count !== this.count) this.build(count);
    const legs = legsOf(Array.from(shown[1].params));
    for (let i = 0; i < count; i++)
      setText(this.legs.cells[i], i < legs.length ? shortNumber(legs[i]) : "");
    this.kinds.forEach((kind, c) => {
      const params = shown[c].params;
      for (let i = 0; i < count; i++) setText(kind.cells[i], shortNumber(params[i]));
    });
    const alpha = this.kinds[3];
    setText(alpha.name, t("parametrization.row.alpha", { alpha: fmt(s.alpha, 2) }));
    alpha.row.hidden = !s.alphaCurve;
  }
}
