// Workload (m) of the typed-curves issue (24): how fast typed formulas evaluate. Six curves —
// the circle, the notes' polynomial, a Lissajous figure, tan (a pole), a nested composition
// and a 20-term sum — each as text for splinelab and math.js and as a hand-written JS closure
// (the baseline no parser beats). Shared by the Node harness; nothing here asserts a timing.
//
// Contenders, per curve (2 coordinates a point, points per second):
// - splinelab f64 tape: `sample(ts)` of N parameters (one call), and `evaluateInto` per point;
// - splinelab jets of order 3: `derivativeInto(t, 3, out)` per point (value to x‴ computed);
// - math.js 15: `compile(text)` once, then `evaluate({ t })` per coordinate per point;
// - JS closures: `(t) => Math.cos(t)` per coordinate per point.
// Also the re-plot after a slider change of a 4-piece curve (`setParameter` + `plot` at 0.5 px
// in a 600 px window), the path the `piecewise` and `parametric-curve` demos take.

const SUM = Array.from({ length: 20 }, (_, k) => `sin(${k + 1}t)/${k + 1}`).join(" + ");
const SUM_JS = Array.from({ length: 20 }, (_, k) => `sin(${k + 1} * t) / ${k + 1}`).join(" + ");

/** The six curves: splinelab texts, math.js texts, closures. */
export const CURVES = [
  {
    name: "circle",
    x: "cos(t)",
    y: "sin(t)",
    mx: "cos(t)",
    my: "sin(t)",
    fx: (t) => Math.cos(t),
    fy: (t) => Math.sin(t),
    to: 2 * Math.PI,
  },
  {
    name: "notes' polynomial",
    x: "6.5t^5 - 7.2t^3 + 3t^2 - 2.1t - 5",
    y: "t",
    mx: "6.5 * t^5 - 7.2 * t^3 + 3 * t^2 - 2.1 * t - 5",
    my: "t",
    fx: (t) => 6.5 * t ** 5 - 7.2 * t ** 3 + 3 * t ** 2 - 2.1 * t - 5,
    fy: (t) => t,
    to: 1,
  },
  {
    name: "Lissajous",
    x: "sin(3t)",
    y: "cos(2t)",
    mx: "sin(3 * t)",
    my: "cos(2 * t)",
    fx: (t) => Math.sin(3 * t),
    fy: (t) => Math.cos(2 * t),
    to: 2 * Math.PI,
  },
  {
    name: "tan",
    x: "t",
    y: "tan(t)",
    mx: "t",
    my: "tan(t)",
    fx: (t) => t,
    fy: (t) => Math.tan(t),
    to: Math.PI,
  },
  {
    name: "nested",
    x: "exp(sin(t^2))",
    y: "sqrt(1 + cos(t)^2) atan(t)",
    mx: "exp(sin(t^2))",
    my: "sqrt(1 + cos(t)^2) * atan(t)",
    fx: (t) => Math.exp(Math.sin(t * t)),
    fy: (t) => Math.sqrt(1 + Math.cos(t) ** 2) * Math.atan(t),
    to: 2,
  },
  {
    name: "20-term sum",
    x: "t",
    y: SUM,
    mx: "t",
    my: SUM_JS,
    fx: (t) => t,
    fy: (t) => {
      let s = 0;
      for (let k = 1; k <= 20; k++) s += Math.sin(k * t) / k;
      return s;
    },
    to: 2 * Math.PI,
  },
];

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

/** Points per second of `run(n)` (which evaluates n points), median of `rounds`. */
function rate(run, n, rounds) {
  run(Math.min(n, 1000)); // warm up
  const times = [];
  for (let r = 0; r < rounds; r++) {
    const t0 = performance.now();
    run(n);
    times.push(performance.now() - t0);
  }
  return n / (median(times) / 1000);
}

/** The largest |a − b| relative to max(1, |b|) over two flat arrays (NaN-aware). */
function agreement(a, b) {
  let worst = 0;
  for (let k = 0; k < a.length; k++) {
    if (Number.isNaN(a[k]) && Number.isNaN(b[k])) continue;
    worst = Math.max(worst, Math.abs(a[k] - b[k]) / Math.max(1, Math.abs(b[k])));
  }
  return worst;
}

/**
 * (m): rows { curve, contender, pointsPerSecond, agreement } for every curve and contender;
 * `math` is the math.js module (or null when it is not installed).
 */
export function expressionBench(sl, math, { n = 200_000, rounds = 5 } = {}) {
  const rows = [];
  for (const c of CURVES) {
    const curve = sl.parametricCurve([{ x: c.x, y: c.y, from: "0", to: String(c.to) }]);
    const ts = Float64Array.from({ length: n }, (_, k) => (c.to * k) / (n - 1));
    const reference = new Float64Array(2 * n);
    for (let k = 0; k < n; k++) {
      reference[2 * k] = c.fx(ts[k]);
      reference[2 * k + 1] = c.fy(ts[k]);
    }
    const out = new Float64Array(2);
    const got = new Float64Array(2 * n);
    const contenders = [
      ["splinelab sample(ts)", (m) => got.set(curve.sample(m === n ? ts : ts.subarray(0, m)))],
      [
        "splinelab evaluateInto",
        (m) => {
          for (let k = 0; k < m; k++) {
            curve.evaluateInto(ts[k], out);
            got[2 * k] = out[0];
            got[2 * k + 1] = out[1];
          }
        },
      ],
      [
        "splinelab derivativeInto(t, 3)",
        (m) => {
          for (let k = 0; k < m; k++) curve.derivativeInto(ts[k], 3, out);
        },
      ],
      [
        "JS closures",
        (m) => {
          for (let k = 0; k < m; k++) {
            got[2 * k] = c.fx(ts[k]);
            got[2 * k + 1] = c.fy(ts[k]);
          }
        },
      ],
    ];
    if (math) {
      const cx = math.compile(c.mx);
      const cy = math.compile(c.my);
      const scope = { t: 0 };
      contenders.push([
        "math.js compile/evaluate",
        (m) => {
          for (let k = 0; k < m; k++) {
            scope.t = ts[k];
            got[2 * k] = cx.evaluate(scope);
            got[2 * k + 1] = cy.evaluate(scope);
          }
        },
      ]);
    }
    for (const [contender, run] of contenders) {
      got.fill(Number.NaN);
      const pointsPerSecond = rate(run, n, rounds);
      const checked = contender.includes("derivative") ? null : agreement(got, reference);
      rows.push({ curve: c.name, contender, pointsPerSecond, agreement: checked });
    }
    curve.free();
  }
  return rows;
}

/** The re-plot of a 4-piece curve after a slider move: `setParameter` + `plot`, in ms. */
export function replotBench(sl, { rounds = 200 } = {}) {
  const pieces = [
    { x: "a cos(t)", y: "sin(t)", from: "0", to: "pi/2" },
    { x: "a cos(t)", y: "sin(t) + (t - pi/2)^2", from: "pi/2", to: "pi" },
    { x: "-a + (t - pi)^3", y: "pi^2/4 + sin(t)", from: "pi", to: "4" },
    { x: "-a + (4 - pi)^3 + t - 4", y: "pi^2/4 + sin(t) - (t - 4)^2", from: "4", to: "5" },
  ];
  const curve = sl.parametricCurve(pieces, { a: 2 });
  const box = [-4, -2, 4, 6]; // a 600 px window over 8 units: 0.5 px is 1/150
  const tolerance = 8 / 1200;
  const times = [];
  let vertices = 0;
  for (let r = 0; r < rounds; r++) {
    const t0 = performance.now();
    curve.setParameter("a", 1.5 + (r % 10) / 10);
    const plot = curve.plot(tolerance, box);
    times.push(performance.now() - t0);
    vertices = plot.ts.length;
  }
  curve.free();
  return { medianMs: median(times), vertices };
}
