// The curve library's errors in every language (run by `make test`; `node tests/i18n/core-errors.mjs`):
// loads the built package (www/pkg, `make build`), makes the library throw one real error per
// case below, and checks lib/core-errors.js `errorText` on each:
//   en: errorText(err) === err.message, the library's own English (message.rs, the glue): the
//       independent check that the templates and derived values reproduce it word for word;
//   el, hr, it: the text differs from English, has no `{placeholder}` left, and every decimal
//       number of the English message appears with the language's decimal comma (1.5 → "1,5").
// A case whose error has no `code` (an older glue without codes) is skipped, with a note.
// Ends with one line "i18n: N passed, N failed" (scripts/test-all.sh sums it).
import { existsSync, readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { errorText } from "../../www/lib/core-errors.js";
import { addLocale, setLocale } from "../../www/lib/strings.js";

const www = fileURLToPath(new URL("../../www/", import.meta.url));
if (!existsSync(`${www}pkg/splinelab_bg.wasm`)) {
  console.log("no www/pkg: run `make build` first\ni18n: 0 passed, 1 failed");
  process.exit(1);
}
const { default: init, ...sl } = await import(`${www}pkg/splinelab.js`);
await init({ module_or_path: readFileSync(`${www}pkg/splinelab_bg.wasm`) });
const LANGUAGES = ["el", "hr", "it"];
for (const code of LANGUAGES) {
  addLocale(code, (await import(`${www}lib/locales/${code}.js`)).default);
}

const bezier = () => new sl.BezierCurve([0, 0, 1, 2, 3, 1, 4, 0], 2);
const bspline = () =>
  new sl.BSplineCurve([0, 0, 1, 1, 2, 0, 3, 1, 4, 0], 2, 2, [0, 0, 0, 1, 2, 3, 3, 3]);
/** A rows × cols net of xyz points (flat, row-major), not flat. */
const net = (rows, cols) =>
  Array.from({ length: rows * cols }, (_, k) => [
    Math.floor(k / cols),
    k % cols,
    (k * 7) % 3,
  ]).flat();
const patch = () => new sl.BezierSurface(net(3, 3), 3, 3);
const freed = () => {
  const c = bezier();
  c.free();
  return c;
};

/** [the code the library must throw, the call that throws it]. */
/** A typed curve of one piece with the texts given (issue 24), or of the pieces given. */
const typed = (x, y = "t", from = "0", to = "1") => sl.parametricCurve([{ x, y, from, to }]);

const CASES = [
  ["expression-empty", () => typed(" ")],
  ["expression-too-long", () => typed("t+".repeat(600))],
  ["expression-too-deep", () => typed(`${"(".repeat(70)}t${")".repeat(70)}`)],
  ["unexpected-character", () => typed("t # 2")],
  ["unexpected-character", () => typed("2,5t")],
  ["unexpected-character", () => typed("|t|")],
  ["expected-operand", () => typed("t + * 2")],
  ["expected-operand", () => typed("t +")],
  ["missing-operator", () => typed("2 3")],
  ["unclosed-parenthesis", () => typed("sin(t")],
  ["unmatched-parenthesis", () => typed("t)")],
  ["unknown-name", () => typed("t + q")],
  ["function-needs-parentheses", () => typed("sin t")],
  ["function-power", () => typed("sin^-1(t)")],
  ["function-power", () => typed("exp^x(t)")],
  ["ambiguous-division", () => typed("1/2t")],
  ["number-after-name", () => typed("t2")],
  ["invalid-number", () => typed("1.2.3")],
  ["scientific-notation", () => typed("1e-3 t")],
  [
    "invalid-parameter-name",
    () => sl.parametricCurve([{ x: "t", y: "t", from: 0, to: 1 }], { tt: 1 }),
  ],
  ["unknown-parameter", () => typed("t").setParameter("a", 1)],
  ["not-finite-value", () => typed("t", "t", "0", "ln(0)")],
  ["empty-piece-interval", () => typed("t", "t", "1.5", "1.5")],
  [
    "pieces-do-not-join",
    () =>
      sl.parametricCurve([
        { x: "t", y: "t", from: "0", to: "1" },
        { x: "t", y: "t", from: "1.5", to: "2" },
      ]),
  ],
  ["missing-field", () => sl.parametricCurve([{ x: "t", from: "0", to: "1" }])],
  ["piece-count", () => sl.parametricCurve([])],
  ["not-polynomial", () => typed("cos(t)").toBezier(0)],
  ["bound-uses-t", () => typed("t", "t", "0", "2t")],
  ["invalid-dimension", () => new sl.BezierCurve([0, 0, 0, 0, 1, 1, 1, 1], 4)],
  ["coordinate-count", () => new sl.BezierCurve([0, 0, 1, 1, 2], 2)],
  ["coordinate-count", () => new sl.BezierCurve([0, 0, 1, 1, 2], 3)],
  ["not-finite", () => new sl.BezierCurve([0, Number.NaN, 1, 1], 2)],
  ["not-finite", () => new sl.BezierCurve([0, -Infinity, 1, 1], 2)],
  ["coordinate-too-large", () => new sl.BezierCurve([0, 1e200, 1, 1], 2)],
  ["coordinate-too-large", () => bspline().setControlPoint(1, [-Number.MAX_VALUE, 0])],
  ["not-finite", () => bezier().evaluate(Number.NaN)],
  ["too-few-points", () => new sl.BezierCurve([0, 0], 2)],
  ["too-few-points", () => sl.BezierCurve.fromPolynomial([], 2, 0, 1)],
  ["weight-count", () => new sl.BezierCurve([0, 0, 1, 1], 2, [1])],
  ["non-positive-weight", () => new sl.BezierCurve([0, 0, 1, 1], 2, [1, -0.25])],
  ["parameter-out-of-range", () => bezier().evaluate(1.5)],
  ["index-out-of-range", () => bezier().setControlPoint(7, [1, 1])],
  ["point-dimension", () => bezier().setControlPoint(0, [1, 1, 1])],
  ["invalid-tolerance", () => bezier().flatten(0)],
  ["tolerance-too-small", () => bezier().flatten(1e-20)],
  ["invalid-interval", () => sl.BezierCurve.withInterval([0, 0, 1, 1], 2, 2.5, 1)],
  ["unknown-option", () => sl.knotVector([0, 0, 1, 1, 2, 0], 2, 1, "even")],
  ["in-argument", () => sl.interpolateSurface([0, 0, 0, 1, 0, 0], 1, 2, 1, 1)],
  ["in-argument", () => sl.revolve(bezier(), [0, 0, 0], [0, 0, 1])],
  ["in-argument", () => patch().intersectLine([0, 0, 5], [0, 0, 0], 1e-9)],
  [
    "knot-count",
    () => new sl.BSplineCurve([0, 0, 1, 1, 2, 0, 3, 1, 4, 0], 2, 3, [0, 0, 0, 0, 1, 1, 1, 1]),
  ],
  ["knot-order", () => new sl.BSplineCurve([0, 0, 1, 1, 2, 0], 2, 1, [0, 0, 2.5, 1.5, 3])],
  ["empty-domain", () => new sl.BSplineCurve([0, 0, 1, 1], 2, 1, [0, 1, 1, 2])],
  ["knot-multiplicity", () => new sl.BSplineCurve([0, 0, 1, 1, 2, 0], 2, 1, [0, 0, 0, 1, 1])],
  ["insertion-multiplicity", () => bspline().insertKnot(0.5, 5)],
  [
    "insertion-multiplicity",
    () =>
      new sl.BSplineCurve(
        net(6, 1).filter((_, k) => k % 3 !== 2),
        2,
        2,
        [0, 0, 0, 1, 1, 1, 3, 3, 3],
      ).insertKnot(1, 1),
  ],
  [
    "insertion-multiplicity",
    () => sl.interpolateSurface(net(3, 3), 3, 3, 2, 2).insertKnotU(0.5, 5),
  ],
  ["degree-zero", () => new sl.BSplineCurve([0, 0, 1, 1], 2, 0, [0, 1, 2])],
  ["degree-out-of-range", () => sl.uniformSegmentMatrix(0)],
  [
    "too-few-points-for-degree",
    () => new sl.BSplineCurve([0, 0, 1, 1, 2, 0], 2, 3, [0, 0, 0, 0, 1, 1, 1]),
  ],
  ["coincident-points", () => sl.parameterize([0, 0, 1, 1, 1, 1, 2, 0], 2, "chord")],
  ["coincident-points", () => sl.parameterize([0, 0, 1, 1, 1, 1, 2, 0], 2, 0.3)],
  ["phantom-even-degree", () => sl.phantomPoints([0, 0, 1, 1, 2, 0, 3, 1], 2, 2)],
  ["not-a-span", () => bspline().segmentMatrix(0)],
  [
    "rational-join",
    () => sl.joinBezier(new sl.BezierCurve([0, 0, 1, 1, 2, 0], 2, [1, 2, 1]), bezier(), "C1"),
  ],
  [
    "join-degree",
    () =>
      sl.joinBezier(new sl.BezierCurve([0, 0, 1, 1], 2), new sl.BezierCurve([1, 1, 2, 0], 2), "C2"),
  ],
  [
    "no-joint-tangent",
    () =>
      sl.joinBezier(
        new sl.BezierCurve([0, 0, 1, 1, 1, 1], 2),
        new sl.BezierCurve([1, 1, 2, 0, 3, 1], 2),
        "G1",
      ),
  ],
  ["breakpoint-count", () => new sl.CompositeBezier(net(2, 2).slice(0, 12), 2, [2, 2], [0, 1])],
  ["degenerate-line", () => bezier().intersectLine(0.5, 0.5, 0.5, 0.5, 1e-9)],
  ["curve-batch-length", () => sl.arcLengths(new Array(10).fill(0), 2, 3)],
  ["rational-hodograph", () => new sl.BezierCurve([0, 0, 1, 1, 2, 0], 2, [1, 2, 1]).hodograph()],
  ["mapped-weight", () => bezier().projectiveMap([1, 0, 0, 0, 1, 0, -1, 0, 1.5])],
  ["singular-map", () => bezier().projectiveMap([0, 0, 0, 0, 0, 0, 0, 0, 0])],
  ["matrix-size", () => bezier().projectiveMap([1, 0, 0])],
  ["degenerate-triangle", () => sl.circularArcBezier([0, 0, 0, 0, 1, 1])],
  ["not-isosceles", () => sl.circularArcBezier([0, 0, 1, 0, 1, 2.5])],
  ["arc-point-count", () => sl.circularArcBezier([0, 0, 1, 1])],
  ["invalid-sweep", () => sl.circularArc(0, 0, 1, 0, 7.5)],
  ["parallel-axes", () => sl.ellipseArc([0, 0], [1, 0], [2, 0], 0, 1)],
  ["axis-lengths", () => sl.ellipseArc([0, 0], [1, 0, 0], [0, 1], 0, 1)],
  ["not-positive", () => sl.circle(0, 0, -0.5)],
  [
    "dimension-mismatch",
    () => sl.joinBezier(bezier(), new sl.BezierCurve([0, 0, 0, 1, 1, 1], 3), "C1"),
  ],
  ["piece-point-count", () => new sl.CompositeBezier([0, 0, 1, 1], 2, [3])],
  ["net-coordinate-count", () => new sl.BezierSurface(new Array(10).fill(0), 2, 2)],
  ["patch-too-small", () => new sl.BezierSurface(new Array(9).fill(0), 1, 3)],
  ["net-index-out-of-range", () => patch().setControlPoint(5, 0, [0, 0, 0])],
  [
    "no-normal",
    () => new sl.BezierSurface([0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0], 2, 2).normal(0.5, 0.25),
  ],
  ["empty-tessellation", () => patch().tessellate(0, 4)],
  ["too-large", () => bezier().sampleUniform(1e9)],
  // The work budget priced by the degree (subject "sample-work"): 2^28 / 65² = 63 535 points.
  [
    "too-large",
    () =>
      new sl.BezierCurve(
        new Float64Array(130).map((_, i) => i % 7),
        2,
      ).sampleUniform(1e5),
  ],
  ["too-large", () => new sl.BezierSurface(net(40, 40), 40, 40).curvatures(new Float64Array(2e5))],
  ["result-too-large", () => patch().sampleGrid(new Float64Array(20000), new Float64Array(20000))],
  ["argument-type", () => new sl.BezierCurve(null, 2)],
  ["argument-type", () => sl.knotVector([0, 0, 1, 1], 2, 1, 5)],
  ["not-whole-number", () => new sl.BezierCurve([0, 0, 1, 1], 2.5)],
  ["not-whole-number", () => new sl.CompositeBezier([0, 0, 1, 1, 2, 0], 2, [1, 0.5])],
  ["needs-2d", () => new sl.BezierCurve([0, 0, 0, 1, 1, 1], 3).intersectLine(0, 0, 1, 0, 1e-9)],
  [
    "zero-direction",
    () => sl.revolve(new sl.BezierCurve([1, 0, 0, 2, 0, 1], 3), [0, 0, 0], [0, 0, 0]),
  ],
  ["needs-polynomial", () => new sl.BezierSurface(net(2, 2), 2, 2, [1, 2, 1, 1]).matrixForm()],
  ["all-weights-zero", () => sl.rationalPoles([0, 0, 1, 1, 2, 0], 2, [0, 0, 0], 8)],
  ["param-count", () => sl.lagrange([0, 0, 1, 1, 2, 0], 2, [0, 1])],
  ["params-not-increasing", () => sl.lagrange([0, 0, 1, 1, 2, 0], 2, [0, 1.5, 1.5])],
  ["missing-argument", () => sl.cubicSpline([0, 0, 1, 1, 2, 0], 2, "chord", "clamped")],
  ["argument-length", () => sl.hermiteSpline([0, 0, 1, 1, 2, 0], 2, "uniform", [1, 0])],
  ["not-closed", () => sl.cubicSpline([0, 0, 1, 1, 2, 0], 2, "chord", "periodic")],
  ["alpha-out-of-range", () => sl.parameterize([0, 0, 1, 1, 2, 0], 2, 1.5)],
  [
    "control-count-out-of-range",
    () => sl.approximateBSpline([0, 0, 1, 1, 2, 0, 3, 1], 2, 2, 9, "chord"),
  ],
  [
    "schoenberg-whitney",
    () =>
      sl.interpolateBSpline(
        net(5, 1).filter((_, k) => k % 3 !== 2),
        2,
        2,
        [0, 0.8, 0.85, 0.9, 1],
        { knots: [0, 0, 0, 0.2, 0.5, 1, 1, 1] },
      ),
  ],
  ["too-few-data-points", () => sl.cubicSpline([0, 0], 2, "chord")],
  [
    "stroke-far-from-curve",
    () => sl.oversketch(sl.fitCurve([0, 0, 1, 0, 2, 0], 2, 0.1), [0, 5, 1, 5, 2, 5], 2, 0.1),
  ],
  [
    "singular-system",
    () => sl.interpolateBSpline([0, 0, 1, 1, 2, 0, 3, 1], 2, 3, [0, 1e-300, 2e-300, 1]),
  ],
  ["spline-kind", () => sl.cubicSpline([0, 0, 1, 1, 2, 0], 2, "chord").setTangent(0, [1, 0])],
  [
    "conflicting-options",
    () =>
      sl.interpolateBSpline([0, 0, 1, 1, 2, 0, 0, 0], 2, 2, "chord", {
        closed: true,
        startDerivative: [1, 0],
      }),
  ],
  [
    "knots-not-clamped",
    () =>
      sl.approximateBSpline(
        net(5, 1).filter((_, k) => k % 3 !== 2),
        2,
        2,
        4,
        [0, 1, 2, 3, 4],
        { knots: [0, 0, 1, 3, 4, 4, 4] },
      ),
  ],
  ["freed", () => freed().evaluate(0.5)],
  ["in-argument", () => sl.joinBezier(freed(), bezier(), "C1")],
  ["no-constructor", () => new sl.CubicSpline()],
  ["out-buffer", () => bezier().evaluateInto(0.5, [1])],
];

/** The thrown value of `run`, or null when it returned. */
function thrown(run) {
  try {
    run();
    return null;
  } catch (err) {
    return err;
  }
}

/**
 * Typed-expression problems whose decimals are the student's own text or the syntax to type
 * ("write decimals with a point (2.5)", "1.2.3" is not a number): they keep the point.
 */
const TYPED_DECIMALS = new Set(["unexpected-character", "invalid-number", "scientific-notation"]);

/** The problems of `errorText(err)` in every language. */
function problems(err) {
  const found = [];
  setLocale("en");
  const english = errorText(err);
  if (english !== err.message) found.push(`en: ${JSON.stringify(english)}`);
  const decimals = TYPED_DECIMALS.has(err.code) ? [] : (err.message.match(/\d+\.\d+/g) ?? []);
  // A pair of numbers in brackets ("[0, 1]", "(1.5, 2)") separates them with "; " where the
  // decimal separator is a comma (in Greek, where ";" is the question mark, with "· ").
  const pair = /[[(]-?[\d.e+-]+, -?[\d.e+-]+[\])]/.test(err.message);
  for (const code of LANGUAGES) {
    setLocale(code);
    const text = errorText(err);
    if (text === err.message) found.push(`${code}: the English message`);
    const left = text.match(/\{\w+\}/);
    if (left) found.push(`${code}: ${left[0]} left in ${JSON.stringify(text)}`);
    const sign = code === "el" ? "·" : ";";
    if (pair && !new RegExp(`[[(][^\\])]*\\d${sign} -?\\d[^\\])]*[\\])]`).test(text)) {
      found.push(`${code}: no "${sign} " between the numbers of a pair in ${JSON.stringify(text)}`);
    }
    for (const d of decimals) {
      const local = d.replace(".", ",");
      if (!text.includes(local)) found.push(`${code}: no ${local} in ${JSON.stringify(text)}`);
    }
  }
  setLocale("en");
  return found;
}

let passed = 0;
let failed = 0;
const covered = new Set();
const skipped = [];
for (const [code, run] of CASES) {
  const err = thrown(run);
  if (err && err.code === undefined) {
    skipped.push(code);
    continue;
  }
  const found =
    err?.code === code ? problems(err) : [`threw ${err?.code ?? "nothing"}: ${err?.message}`];
  if (found.length) {
    failed++;
    console.log(`FAIL ${code}: ${err?.message}\n     ${found.join("\n     ")}`);
  } else {
    passed++;
    covered.add(code);
    if (code === "in-argument") covered.add(err.params.source.code); // the cause, translated too
  }
}
if (skipped.length) console.log(`skipped (the error has no code yet): ${skipped.join(", ")}`);
console.log(`codes covered (${covered.size}): ${[...covered].sort().join(", ")}`);
console.log(`i18n: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
