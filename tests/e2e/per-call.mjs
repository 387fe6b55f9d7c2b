// Checks of what scripts/glue.mjs adds to the generated glue, run in Node on the built
// www/pkg by run.mjs: the per-call `evaluateInto` / `derivativeInto` methods (against
// `evaluate` / `derivative` and against closed forms), their errors, a wasm memory that grows
// between calls, and the "this X was freed" errors of freed objects and freed arguments.
// Default export: [[what, body], …].
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

const pkg = (p) => fileURLToPath(new URL(`../../www/pkg/${p}`, import.meta.url));
const sl = await import(pkg("splinelab.js"));
const exports = sl.initSync({ module: readFileSync(pkg("splinelab_bg.wasm")) });

function assert(ok, message) {
  if (!ok) throw new Error(message);
}
function near(got, want, tol, what) {
  assert(got.length >= want.length, `${what}: got ${got.length} numbers, want ${want.length}`);
  for (let k = 0; k < want.length; k++) {
    const d = Math.abs(got[k] - want[k]);
    assert(d <= tol, `${what}[${k}]: got ${got[k]}, want ${want[k]} (|diff| ${d} > ${tol})`);
  }
}
function throwsWith(f, pattern, what) {
  let err = null;
  try {
    f();
  } catch (e) {
    err = e;
  }
  assert(err !== null, `${what}: no error`);
  assert(err instanceof Error, `${what}: threw ${err}, not an Error`);
  assert(pattern.test(err.message), `${what}: message "${err.message}" does not match ${pattern}`);
}

// The syllabus worked example: P0 = (0,0), P1 = (2,2), P2 = (6,4), P3 = (8,2).
const P = [0, 0, 2, 2, 6, 4, 8, 2];
// One of each class with evaluate: [name, make(), parameters inside the domain].
const curves = () => [
  ["BezierCurve 2D", new sl.BezierCurve(P, 2), [0, 0.25, 0.5, 0.9, 1]],
  [
    "BezierCurve 3D rational",
    new sl.BezierCurve([0, 0, 0, 1, 2, 1, 3, 0, 2], 3, [1, 3, 0.5]),
    [0, 0.3, 1],
  ],
  [
    "BSplineCurve NURBS",
    new sl.BSplineCurve(
      [0, 0, 1, 2, 3, 3, 4, 0, 6, 1, 7, 3],
      2,
      3,
      [0, 0, 0, 0, 1, 2.5, 4, 4, 4, 4],
      [1, 2, 0.5, 1, 1.5, 1],
    ),
    [0, 0.5, 1, 2.5, 3.9, 4],
  ],
  [
    "BSplineCurve 3D",
    new sl.BSplineCurve([0, 0, 0, 1, 1, 1, 2, 0, 2, 3, 1, 0], 3, 2, [0, 0, 0, 1, 2, 2, 2]),
    [0, 0.7, 1, 2],
  ],
  [
    "CompositeBezier",
    new sl.CompositeBezier([0, 0, 1, 1, 2, 0, 2, 0, 3, 1, 4, 0], 2, [2, 2]),
    [0, 0.4, 1, 1.6, 2],
  ],
  ["CubicSpline", sl.cubicSpline([0, 0, 1, 2, 3, 1, 4, 4], 2, "chord", "natural"), null],
  [
    "LagrangeCurve",
    sl.lagrange([0, 0, 1, 2, 3, 1, 4, 4, 5, 0, 1, 2], 3, [0, 1, 2, 3]),
    [0, 0.5, 2.2, 3],
  ],
];

const checks = [
  [
    "evaluateInto and derivativeInto: the worked example's point (29/16, 23/16) and derivatives at t = 1/4",
    () => {
      const c = new sl.BezierCurve(P, 2);
      const out = new Float64Array(2);
      assert(c.evaluateInto(0.25, out) === out, "returns out");
      // de Casteljau on dyadic numbers is exact.
      assert(out[0] === 29 / 16 && out[1] === 23 / 16, `point ${out}`);
      // P'(t) = 3[(1−t)²(P1−P0) + 2t(1−t)(P2−P1) + t²(P3−P2)] = 3·(2.75, 1.75).
      near(c.derivativeInto(0.25, 1, [0, 0]), [8.25, 5.25], 1e-14, "P'(1/4)");
      // P''(t) = 6[(1−t)(P2 − 2P1 + P0) + t(P3 − 2P2 + P1)] = 6[¾(2, 0) + ¼(−2, −4)] = (6, −6).
      near(c.derivativeInto(0.25, 2, [0, 0]), [6, -6], 1e-13, "P''(1/4)");
      // P''' = 6(P3 − 3P2 + 3P1 − P0) = 6(−4, −4); above the degree, zero.
      near(c.derivativeInto(0.7, 3, [0, 0]), [-24, -24], 1e-12, "P'''");
      near(c.derivativeInto(0.7, 4, [9, 9]), [0, 0], 0, "order 4");
      // The clamped B-spline with the same points is the same curve.
      const b = new sl.BSplineCurve(P, 2, 3, [0, 0, 0, 0, 1, 1, 1, 1]);
      near(b.evaluateInto(0.25, [0, 0]), [29 / 16, 23 / 16], 1e-15, "B-spline point");
      near(b.derivativeInto(0.25, 1, [0, 0]), [8.25, 5.25], 1e-13, "B-spline P'");
      near(b.derivativeInto(0.25, 2, [0, 0]), [6, -6], 1e-12, "B-spline P''");
      c.free();
      b.free();
    },
  ],
  [
    "evaluateInto and derivativeInto on a NURBS quarter circle: on the circle, C'(0) = (0, 2w₁/w₀) = (0, √2)",
    () => {
      const h = Math.SQRT1_2;
      const arc = new sl.BSplineCurve([1, 0, 1, 1, 0, 1], 2, 2, [0, 0, 0, 1, 1, 1], [1, h, 1]);
      const out = [0, 0];
      for (const u of [0, 0.1, 0.37, 0.5, 0.8, 1]) {
        arc.evaluateInto(u, out);
        assert(
          Math.abs(Math.hypot(out[0], out[1]) - 1) < 1e-15,
          `|C(${u})| = ${Math.hypot(...out)}`,
        );
        // The tangent is perpendicular to the radius.
        const d = arc.derivativeInto(u, 1, [0, 0]);
        assert(Math.abs(d[0] * out[0] + d[1] * out[1]) < 1e-14, `C'·C at ${u}`);
      }
      near(arc.evaluateInto(0.5, out), [h, h], 1e-15, "C(1/2)");
      near(arc.derivativeInto(0, 1, out), [0, Math.SQRT2], 1e-15, "C'(0)");
      near(arc.derivativeInto(1, 1, out), [-Math.SQRT2, 0], 1e-15, "C'(1)");
      arc.free();
    },
  ],
  [
    "BezierCurve.evaluateInto (computed in JS up to degree 7) returns evaluate's very numbers: degrees 1–9, 2D and 3D, rational, on [a, b], after setControlPoint and setWeight",
    () => {
      let seed = 7;
      const rnd = () => {
        seed = (seed * 1103515245 + 12345) % 2147483648;
        return seed / 2147483648;
      };
      const out = new Float64Array(3);
      let cases = 0;
      for (let degree = 1; degree <= 9; degree++) {
        for (const dim of [2, 3]) {
          for (const rational of [false, true]) {
            const points = Array.from({ length: (degree + 1) * dim }, () => 20 * rnd() - 10);
            const weights = rational
              ? Array.from({ length: degree + 1 }, () => 0.2 + 3 * rnd())
              : undefined;
            const [a, b] = rnd() < 0.5 ? [0, 1] : [-2 + rnd(), 1 + 3 * rnd()];
            const c = sl.BezierCurve.withInterval(points, dim, a, b, weights);
            const check = (what) => {
              for (const t of [a, b, a + (b - a) * rnd(), a + (b - a) * rnd(), (a + b) / 2]) {
                near(
                  c.evaluateInto(t, out).subarray(0, dim),
                  c.evaluate(t),
                  0,
                  `${what} degree ${degree} ${dim}D${rational ? " rational" : ""} t = ${t}`,
                );
                cases++;
              }
            };
            check("as built");
            c.setControlPoint(
              degree,
              Array.from({ length: dim }, () => 5 * rnd()),
            );
            check("after setControlPoint");
            c.setWeight(0, 2.5);
            check("after setWeight");
            c.free();
          }
        }
      }
      assert(cases === 9 * 2 * 2 * 15, `${cases} comparisons`);
    },
  ],
  [
    "evaluateInto / derivativeInto agree with evaluate / derivative on every curve class (2D, 3D, rational; typed array and array)",
    () => {
      for (const [name, c, given] of curves()) {
        const [a, b] = c.domain ? Array.from(c.domain()) : [0, 1];
        const params = given ?? [a, a + 0.3 * (b - a), (a + b) / 2, b];
        const dim = c.evaluate(params[0]).length;
        for (const t of params) {
          for (const out of [new Float64Array(dim), new Array(dim).fill(0)]) {
            near(c.evaluateInto(t, out), c.evaluate(t), 0, `${name} point at ${t}`);
          }
          if (c.derivativeInto) {
            for (const order of [0, 1, 2, 3, 5]) {
              const want = c.derivative(t, order);
              near(
                c.derivativeInto(t, order, new Float64Array(dim)),
                want,
                1e-12 * (1 + Math.hypot(...want)),
                `${name} order ${order} at ${t}`,
              );
            }
          }
        }
        // A longer out keeps what lies past dim.
        const long = new Float64Array(5).fill(7);
        c.evaluateInto(params[0], long);
        assert(
          long.slice(dim).every((x) => x === 7),
          `${name}: wrote past dim`,
        );
        c.free();
      }
    },
  ],
  [
    "surfaces: evaluateInto(u, v, out) and derivativeInto(u, v, du, dv, out) agree with evaluate / derivative",
    () => {
      const net = [0, 0, 0, 0, 1, 1, 0, 2, 0, 1, 0, 1, 1, 1, 3, 1, 2, 1, 2, 0, 0, 2, 1, 1, 2, 2, 0];
      const bez = new sl.BezierSurface(net, 3, 3);
      const bsp = new sl.BSplineSurface(net, 3, 3, 2, 2, [0, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1]);
      for (const s of [bez, bsp]) {
        for (const [u, v] of [
          [0, 0],
          [0.3, 0.8],
          [1, 0.5],
        ]) {
          near(s.evaluateInto(u, v, new Float64Array(3)), s.evaluate(u, v), 0, `S(${u}, ${v})`);
          near(
            s.derivativeInto(u, v, 1, 1, [0, 0, 0]),
            s.derivative(u, v, 1, 1),
            1e-12,
            `S_uv(${u}, ${v})`,
          );
        }
      }
      // A biquadratic Bézier patch at (½, ½): Σ B_i(½) B_j(½) P_ij with weights ¼, ½, ¼.
      const w = [0.25, 0.5, 0.25];
      const want = [0, 0, 0];
      for (let i = 0; i < 3; i++)
        for (let j = 0; j < 3; j++)
          for (let c = 0; c < 3; c++) want[c] += w[i] * w[j] * net[(i * 3 + j) * 3 + c];
      near(bez.evaluateInto(0.5, 0.5, [0, 0, 0]), want, 1e-15, "patch centre");
      throwsWith(() => bez.evaluateInto(0.5, 1.5, [0, 0, 0]), /v = 1\.5/, "v outside");
      throwsWith(
        () => bez.evaluateInto(0.5, 0.5, [0, 0]),
        /at least dim = 3 numbers, got length 2/,
        "short out",
      );
      bez.free();
      bsp.free();
    },
  ],
  [
    "evaluateInto / derivativeInto errors name the value: t outside or not finite, a bad order, a short or missing out",
    () => {
      const c = new sl.BezierCurve(P, 2);
      const b = new sl.BSplineCurve(P, 2, 3, [0, 0, 0, 0, 2, 2, 2, 2]);
      throwsWith(() => c.evaluateInto(1.5, [0, 0]), /t = 1\.5 is outside .*\[0, 1\]/, "t outside");
      throwsWith(() => b.evaluateInto(-1, [0, 0]), /u = -1 is outside .*\[0, 2\]/, "u outside");
      throwsWith(() => c.evaluateInto(Number.NaN, [0, 0]), /t is NaN/, "NaN");
      throwsWith(
        () => b.derivativeInto(1, 1, [0, 0]) && b.derivativeInto(Infinity, 1, [0, 0]),
        /u is Infinity/,
        "Infinity",
      );
      throwsWith(() => c.derivativeInto(0.5, -1, [0, 0]), /order .*got -1/, "order −1");
      throwsWith(() => c.derivativeInto(0.5, 1.5, [0, 0]), /order .*got 1\.5/, "order 1.5");
      throwsWith(
        () => c.evaluateInto(0.5, [0]),
        /out must be .* at least dim = 2 numbers, got length 1/,
        "short out",
      );
      throwsWith(() => c.evaluateInto(0.5, new Float64Array(1)), /got length 1/, "short typed out");
      throwsWith(() => c.evaluateInto(0.5, null), /out must be .*got null/, "null out");
      throwsWith(() => c.evaluateInto(0.5), /out must be .*got undefined/, "no out");
      throwsWith(() => c.derivativeInto(0.5, 1, 7), /out must be .*got number/, "number out");
      // A failed call leaves out as it was, and the next call works.
      const out = [3, 4];
      throwsWith(() => c.evaluateInto(2, out), /outside/, "t outside");
      assert(out[0] === 3 && out[1] === 4, "out untouched by a failed call");
      near(c.evaluateInto(0.25, out), [29 / 16, 23 / 16], 0, "after errors");
      c.free();
      b.free();
    },
  ],
  [
    "evaluateInto reads the right numbers after the wasm memory grows between calls (the view is made again)",
    () => {
      const c = new sl.BezierCurve(P, 2);
      const out = new Float64Array(2);
      c.evaluateInto(0.5, out);
      const before = exports.memory.buffer;
      exports.memory.grow(1); // detaches every view of the old buffer
      assert(exports.memory.buffer !== before && before.byteLength === 0, "memory grew");
      near(c.evaluateInto(0.25, out), [29 / 16, 23 / 16], 0, "after memory.grow");
      // Growth from inside wasm: a large result, then per-point calls again.
      const big = c.sampleUniform(1 << 20);
      near(c.derivativeInto(0.25, 1, out), [8.25, 5.25], 1e-14, "after a large sample");
      assert(big.length === 2 << 20, "sample length");
      c.free();
    },
  ],
  [
    "new on a class the library only returns (CubicSpline, LagrangeCurve) throws an Error naming the functions that make one",
    () => {
      throwsWith(
        () => new sl.CubicSpline(),
        /sl\.cubicSpline\(…\).*|.*sl\.cubicSpline/,
        "CubicSpline",
      );
      throwsWith(() => new sl.LagrangeCurve(), /comes from sl\.lagrange\(…\)/, "LagrangeCurve");
      throwsWith(
        () => new sl.ParametricCurve(),
        /comes from sl\.parametricCurve\(…\)/,
        "ParametricCurve",
      );
      const spline = sl.cubicSpline([0, 0, 1, 1, 2, 0], 2, [0, 1, 2], "natural");
      assert(spline instanceof sl.CubicSpline, "the functions still make them");
      near(spline.evaluate(1), [1, 1], 1e-15, "through its middle point");
      spline.free();
    },
  ],
  [
    'a method on a freed object of every class throws Error("this <Class> was freed"); free() twice does nothing',
    () => {
      const net = new Float64Array(27).map((_, k) => k % 5);
      const made = [
        [
          "BSplineCurve",
          new sl.BSplineCurve(P, 2, 3, [0, 0, 0, 0, 1, 1, 1, 1]),
          (o) => o.evaluate(0.5),
        ],
        [
          "BSplineSurface",
          new sl.BSplineSurface(net, 3, 3, 2, 2, [0, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1]),
          (o) => o.evaluate(0.5, 0.5),
        ],
        ["BezierCurve", new sl.BezierCurve(P, 2), (o) => o.controlPoints()],
        ["BezierSurface", new sl.BezierSurface(net, 3, 3), (o) => o.normal(0.5, 0.5)],
        [
          "CompositeBezier",
          new sl.CompositeBezier([0, 0, 1, 1, 2, 0, 2, 0, 3, 1, 4, 0], 2, [2, 2]),
          (o) => o.sample([0.5]),
        ],
        [
          "CubicSpline",
          sl.cubicSpline([0, 0, 1, 2, 3, 1, 4, 4], 2, "chord", "natural"),
          (o) => o.tangents(),
        ],
        ["LagrangeCurve", sl.lagrange([0, 0, 1, 2, 3, 1], 2, [0, 1, 2]), (o) => o.aitken(0.5)],
        [
          "ParametricCurve",
          sl.parametricCurve([{ x: "cos(t)", y: "sin(t)", from: "0", to: "2pi" }]),
          (o) => o.joints(),
        ],
      ];
      const classes = Object.entries(sl).filter(
        ([, v]) => typeof v === "function" && /^class /.test(String(v)),
      );
      assert(
        classes.length === made.length && classes.every(([name]) => made.some(([m]) => m === name)),
        `exported classes ${classes.map(([n]) => n)} are not the ones checked`,
      );
      for (const [name, obj, call] of made) {
        call(obj); // works while alive
        obj.free();
        const freed = new RegExp(`^this ${name} was freed$`);
        throwsWith(() => call(obj), freed, `${name} method`);
        if ("dim" in obj) throwsWith(() => obj.dim, freed, `${name} getter`);
        if (obj.evaluateInto)
          throwsWith(() => obj.evaluateInto(0.5, [0, 0, 0]), freed, `${name}.evaluateInto`);
        obj.free(); // a second free is a no-op
      }
    },
  ],
  [
    "a Bézier curve freed (or disposed) after evaluateInto made its JS mirror: evaluateInto says it was freed",
    () => {
      for (const end of ["free", Symbol.dispose]) {
        const c = new sl.BezierCurve(P, 2);
        near(c.evaluateInto(0.25, new Float64Array(2)), [29 / 16, 23 / 16], 0, "mirror made");
        c[end]();
        throwsWith(
          () => c.evaluateInto(0.25, new Float64Array(2)),
          /^this BezierCurve was freed$/,
          `after ${String(end)}`,
        );
      }
    },
  ],
  [
    "a method called on an object of another class throws naming both classes and leaves that object as it was",
    () => {
      const bezier = new sl.BezierCurve(P, 2);
      const bspline = new sl.BSplineCurve([0, 0, 1, 3, 2, 0, 3, 1], 2, 2, [0, 0, 0, 0.5, 1, 1, 1]);
      const patch = new sl.BezierSurface([0, 0, 0, 1, 0, 1, 0, 1, 1, 1, 1, 0], 2, 2);
      const before = Array.from(bspline.controlPoints());
      const at = Array.from(bspline.evaluate(0.3));
      const B = sl.BezierCurve.prototype;
      const calls = [
        ["evaluate", () => B.evaluate.call(bspline, 0.5)],
        ["evaluateInto", () => B.evaluateInto.call(bspline, 0.5, new Float64Array(2))],
        ["setControlPoint", () => B.setControlPoint.call(bspline, 0, [9, 9])],
        ["dim getter", () => Object.getOwnPropertyDescriptor(B, "dim").get.call(bspline)],
        ["free", () => B.free.call(bspline)],
        ["a surface method", () => sl.BezierSurface.prototype.normal.call(bezier, 0.5, 0.5)],
        ["a plain object", () => B.evaluate.call({ __wbg_ptr: 8 }, 0.5)],
        ["an unbound method", () => B.evaluate.call(undefined, 0.5)],
      ];
      for (const [what, call] of calls) {
        let err = null;
        try {
          call();
        } catch (e) {
          err = e;
        }
        assert(err instanceof Error, `${what}: no Error`);
        assert(
          /^this must be Bezier(Curve|Surface), got (BSplineCurve|BezierCurve|Object|undefined)$/.test(
            err.message,
          ),
          `${what}: message "${err.message}"`,
        );
        assert(err.code === "argument-type" && err.params.name === "this", `${what}: code`);
      }
      near(bspline.controlPoints(), before, 0, "the B-spline's points are untouched");
      near(bspline.evaluate(0.3), at, 0, "and it evaluates as before");
      near(bezier.evaluate(0.25), [29 / 16, 23 / 16], 1e-15, "the Bézier curve still works");
      for (const o of [bezier, bspline, patch]) o.free();
    },
  ],
  [
    "a freed object passed as an argument is named: jointContinuity, joinBezier, ruled, extrude, revolve",
    () => {
      const a = new sl.BezierCurve(P, 2);
      const live = new sl.BezierCurve([8, 2, 10, 0, 12, 1], 2);
      const a3 = new sl.BSplineCurve([0, 0, 0, 1, 1, 0, 2, 0, 1], 3, 2, [0, 0, 0, 1, 1, 1]);
      const b3 = new sl.BSplineCurve([0, 1, 0, 1, 1, 1, 2, 1, 1], 3, 2, [0, 0, 0, 1, 1, 1]);
      a.free();
      a3.free();
      throwsWith(
        () => sl.jointContinuity(a, live),
        /^left: this BezierCurve was freed$/,
        "jointContinuity",
      );
      throwsWith(
        () => sl.jointContinuity(live, a),
        /^right: this BezierCurve was freed$/,
        "jointContinuity right",
      );
      throwsWith(
        () => sl.joinBezier(a, live, "C1"),
        /^left: this BezierCurve was freed$/,
        "joinBezier",
      );
      throwsWith(() => sl.ruled(a3, b3), /^curveA: this BSplineCurve was freed$/, "ruled");
      throwsWith(() => sl.ruled(b3, a3), /^curveB: this BSplineCurve was freed$/, "ruled B");
      throwsWith(
        () => sl.extrude(a3, [0, 0, 1]),
        /^curve: this BSplineCurve was freed$/,
        "extrude",
      );
      throwsWith(
        () => sl.revolve(a3, [0, 0, 0], [0, 0, 1]),
        /^profile: this BSplineCurve was freed$/,
        "revolve",
      );
      // Live arguments still work.
      const s = sl.ruled(b3, b3);
      near(s.evaluate(0.5, 0.5), b3.evaluate(0.5), 1e-15, "ruled surface of one curve");
      s.free();
      live.free();
      b3.free();
    },
  ],
  [
    "100 000 calls on freed objects leave the module working: the wasm memory is as it was and results are right",
    () => {
      const c = new sl.BezierCurve(P, 2);
      const gone = new sl.BSplineCurve(P, 2, 3, [0, 0, 0, 0, 1, 1, 1, 1]);
      gone.free();
      const bytes = exports.memory.buffer.byteLength;
      let errors = 0;
      for (let k = 0; k < 100_000; k++) {
        try {
          if (k % 2) gone.evaluate(0.5);
          else gone.derivativeInto(0.5, 1, [0, 0]);
        } catch {
          errors += 1;
        }
      }
      assert(errors === 100_000, `${errors} errors`);
      assert(exports.memory.buffer.byteLength === bytes, "memory grew");
      // Deep work on the wasm stack still right: a degree-40 curve's de Casteljau triangle.
      const pts = Array.from({ length: 82 }, (_, k) => (k % 2 ? 1 : k / 2));
      const big = new sl.BezierCurve(pts, 2);
      assert(big.deCasteljau(0.5).length === ((41 * 42) / 2) * 2, "triangle size");
      near(c.evaluateInto(0.25, [0, 0]), [29 / 16, 23 / 16], 0, "per-call after");
      near(c.evaluate(0.25), [29 / 16, 23 / 16], 0, "evaluate after");
      big.free();
      c.free();
    },
  ],
];

export default checks;
