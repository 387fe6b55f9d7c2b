// The number helpers against numbers written out by hand, in each language (run by `make test`;
// `node tests/i18n/numbers.mjs`): shown numbers take the language's decimal separator (a comma
// in Greek, Croatian and Italian), lists and points then separate their entries with "; " (in
// Greek, where ";" is the question mark, with the ano teleia "· ", in TeX `\cdotp`), TeX writes
// a decimal comma "{,}" (KaTeX would space a bare one), and machine text keeps the point.
// What a text box shows is read back by the parser it feeds. Fractions are the same everywhere.
// Ends with one line "numbers: N passed, N failed" (scripts/test-all.sh sums it).
import {
  clauseSeparator,
  exactNumbers,
  exactTex,
  exactText,
  fmt,
  fmtMachine,
  fmtTex,
  fractionOrDecimals,
  inputListSeparator,
  listTex,
  listText,
  parseNumberInput,
  pointTex,
  pointText,
  shortNumber,
  splitNumberList,
} from "../../www/lib/format.js";
import { knotMachine, knotText } from "../../www/lib/knot-ruler.js";
import { knotListTex, knotListText } from "../../www/lib/knot-readout.js";
import { DECIMAL_SIGNS, addLocale, setLocale } from "../../www/lib/strings.js";
import { LANGUAGES } from "../../www/lib/language.js";

let passed = 0;
let failed = 0;
/** One named check: `actual` must equal `expected` (compared as JSON). */
function check(name, actual, expected) {
  const [a, e] = [JSON.stringify(actual), JSON.stringify(expected)];
  if (a === e) {
    passed++;
  } else {
    failed++;
    console.log(`FAIL ${name}: ${a}, expected ${e}`);
  }
}

/** Per language, what each helper must write (by hand, not by the code under test). */
const EXPECTED = {
  en: {
    fmt: ["1.250", "-2.500", "0.000", "3.14"],
    tex: ["1.250", "-2.500", "3.14"],
    point: "(1.500, 2.000)",
    pointTex: "(1.5,\\ 2)",
    list: "0.250, 1/2, 3.000",
    listTex: "0.25,\\ \\tfrac12",
    short: ["2", "2.500", "2.500"],
    fraction: ["1/4", "0.350", "\\tfrac{1}{4}", "0.350"],
    exact: ["−3/4", "0.00031", "0", "-0.00031"],
    steps: ["9/16", "0.350"],
    knot: ["1.5", "1.5", "1.5", "2"],
    knots: ["0, 0, 1.5, 2", "0, 0, 1.5, 2"],
    typed: "0 0 1.5 2",
    clauses: "; ",
  },
  comma: {
    fmt: ["1,250", "-2,500", "0,000", "3,14"],
    tex: ["1{,}250", "-2{,}500", "3{,}14"],
    point: "(1,500; 2,000)",
    pointTex: "(1{,}5;\\ 2)",
    list: "0,250; 1/2; 3,000",
    listTex: "0{,}25;\\ \\tfrac12",
    short: ["2", "2,500", "2{,}500"],
    fraction: ["1/4", "0,350", "\\tfrac{1}{4}", "0{,}350"],
    exact: ["−3/4", "0,00031", "0", "-0{,}00031"],
    steps: ["9/16", "0{,}350"],
    knot: ["1,5", "1{,}5", "1.5", "2"],
    knots: ["0; 0; 1,5; 2", "0; 0; 1{,}5; 2"],
    typed: "0; 0; 1,5; 2",
    clauses: "; ",
  },
  el: {
    fmt: ["1,250", "-2,500", "0,000", "3,14"],
    tex: ["1{,}250", "-2{,}500", "3{,}14"],
    point: "(1,500· 2,000)",
    pointTex: "(1{,}5\\cdotp\\ 2)",
    list: "0,250· 1/2· 3,000",
    listTex: "0{,}25\\cdotp\\ \\tfrac12",
    short: ["2", "2,500", "2{,}500"],
    fraction: ["1/4", "0,350", "\\tfrac{1}{4}", "0{,}350"],
    exact: ["−3/4", "0,00031", "0", "-0{,}00031"],
    steps: ["9/16", "0{,}350"],
    knot: ["1,5", "1{,}5", "1.5", "2"],
    knots: ["0· 0· 1,5· 2", "0\\cdotp 0\\cdotp 1{,}5\\cdotp 2"],
    typed: "0· 0· 1,5· 2",
    clauses: "· ",
  },
};

for (const code of ["en", "el", "hr", "it"]) {
  if (code !== "en") addLocale(code, {});
  setLocale(code);
  const want = EXPECTED[code] ?? EXPECTED.comma;
  check(`${code} fmt`, [fmt(1.25), fmt(-2.5), fmt(-0.0001), fmt(3.1372, 2)], want.fmt);
  check(`${code} fmtTex`, [fmtTex(1.25), fmtTex(-2.5), fmtTex(3.1372, 2)], want.tex);
  check(
    `${code} fmtMachine keeps the point`,
    [fmtMachine(1.25), fmtMachine(-0.0001)],
    ["1.250", "0.000"],
  );
  check(`${code} pointText`, pointText([1.5, 2]), want.point);
  check(`${code} pointTex`, pointTex([1.5, "2"], 1), want.pointTex);
  check(`${code} listText`, listText([0.25, "1/2", 3]), want.list);
  check(`${code} listTex`, listTex([0.25, "\\tfrac12"], 2), want.listTex);
  check(
    `${code} shortNumber`,
    [shortNumber(2 + 1e-12), shortNumber(2.5), shortNumber(2.5, true)],
    want.short,
  );
  check(
    `${code} fractionOrDecimals`,
    [
      fractionOrDecimals(0.25),
      fractionOrDecimals(0.35),
      fractionOrDecimals(0.25, true),
      fractionOrDecimals(0.35, true),
    ],
    want.fraction,
  );
  check(
    `${code} exactText, exactTex`,
    [exactText(-0.75), exactText(0.000312), exactText(1e-14), exactTex(-0.000312)],
    want.exact,
  );
  check(
    `${code} exactNumbers: fractions stay, decimals follow the language`,
    [exactNumbers(0.25, [1, 2]).value(0.5625, 2), exactNumbers(0.3, [1]).value(0.35, 1, true)],
    want.steps,
  );
  check(
    `${code} knotText, knotMachine`,
    [knotText(1.5), knotText(1.5, true), knotMachine(1.5), knotText(2)],
    want.knot,
  );
  check(
    `${code} knot lists`,
    [knotListText([0, 0, 1.5, 2]), knotListTex([0, 0, 1.5, 2])],
    want.knots,
  );
  // What a box shows is what its parser reads back.
  const typed = [0, 0, 1.5, 2].map((u) => knotText(u)).join(inputListSeparator());
  check(`${code} a typed list`, typed, want.typed);
  check(`${code} clauses of a sentence`, clauseSeparator(), want.clauses);
  check(`${code} … reads back`, splitNumberList(typed).map(parseNumberInput), [0, 0, 1.5, 2]);
  check(`${code} a shown number reads back`, parseNumberInput(fmt(-2.5)), -2.5);
  // No TeX a helper writes has a bare decimal comma (KaTeX would space it as punctuation).
  const texts = [fmtTex(1.5), pointTex([1.5, 2.25]), listTex([0.5, 0.75]), knotText(0.5, true)];
  check(
    `${code} TeX has no bare comma between digits`,
    texts.filter((s) => /\d,\d/.test(s)),
    [],
  );
}
setLocale("en");

// strings.js writes our languages' decimal separators down (Intl's first use is slow at load):
// they must be the ones Intl.NumberFormat gives.
for (const [code, sign] of Object.entries(DECIMAL_SIGNS))
  check(
    `${code}: the written decimal separator is Intl's`,
    sign,
    new Intl.NumberFormat(code).formatToParts(1.5).find((p) => p.type === "decimal")?.value,
  );
check(
  "every language has its separator written",
  Object.keys(DECIMAL_SIGNS).sort(),
  [...LANGUAGES.map((l) => l.code)].sort(),
);

console.log(`numbers: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
