// Seeded random-argument fuzzing of the public JS API, run in the page by run.mjs: every call
// with random numbers (NaN, ±Infinity, huge, negative, fractional), arrays of random lengths,
// null, undefined, strings, objects and other curves either returns or throws a plain `Error`
// (never a WebAssembly.RuntimeError from a Rust panic or a bad memory access, never a glue
// TypeError), and the module keeps working afterwards. Self-contained: page.evaluate sends its
// source to the browser.

/** Runs `iterations` rounds (a random curve, 6 random method calls, 1 random free function). */
export async function fuzzApi({ seedValue, iterations }) {
  const mod = await import("/pkg/splinelab.js");
  await mod.default();
  let seed = seedValue;
  const rnd = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  const pick = (a) => a[Math.floor(rnd() * a.length)];
  const specials = [
    0,
    1,
    2,
    3,
    -1,
    0.5,
    1.5,
    NaN,
    Infinity,
    -Infinity,
    1e308,
    -1e308,
    1e-308,
    5e-324,
    2 ** 32,
    2 ** 31,
    1e9,
    4,
    7,
    0.999999999,
    1.000000001,
    -0,
  ];
  const num = () => (rnd() < 0.5 ? pick(specials) : (rnd() - 0.5) * 10 * (rnd() < 0.2 ? 1e6 : 1));
  const small = () => pick([0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 33, -1, 2.5, NaN, 1e9, 2 ** 32]);
  const arr = (n = Math.floor(rnd() * 14)) => {
    const a = new Float64Array(n);
    for (let i = 0; i < n; i++) a[i] = rnd() < 0.9 ? (rnd() - 0.5) * 10 : num();
    return a;
  };
  const sorted = (n) => {
    const a = arr(n).map(Math.abs);
    a.sort();
    return a;
  };
  const anyArg = () =>
    pick([num(), small(), arr(), sorted(Math.floor(rnd() * 12)), null, undefined, "x", [1, 2], {}]);
  const strs = [
    "uniform",
    "clamped",
    "chord",
    "centripetal",
    "C0",
    "C1",
    "G1",
    "C2",
    "left",
    "right",
    "open",
    "natural",
    "periodic",
    "not-a-knot",
    "",
  ];
  /** A random options object for the B-spline fits (keys right or wrong). */
  const options = () =>
    pick([
      undefined,
      {},
      { knots: sorted(Math.floor(rnd() * 14)) },
      { startDerivative: arr(pick([1, 2, 3])) },
      { endDerivative: arr(pick([2, 3])), startDerivative: anyArg() },
      { closed: pick([true, false, 1, "yes"]) },
      { knots: anyArg(), closed: true },
      { unknownKey: 1 },
      "options",
    ]);
  /** A random valid-looking curve (its construction may still be refused: that is fine). */
  function make() {
    const kind = pick([
      "bez",
      "bez",
      "bsp",
      "bsp",
      "comp",
      "surf",
      "bezsurf",
      "lag",
      "fit",
      "cubic",
      "cubic",
    ]);
    const dim = pick([2, 2, 3]);
    if (kind === "lag" || kind === "cubic" || kind === "fit") {
      // Interpolation (section 5): data points at increasing params, or a spacing.
      const n = 2 + Math.floor(rnd() * 6);
      const params =
        rnd() < 0.6
          ? Float64Array.from({ length: n }, (_, i) => i + rnd() * 0.9)
          : pick(["chord", 0.5, 0]);
      const points = arr(n * dim);
      if (kind === "lag") return mod.lagrange(points, dim, params);
      if (kind === "fit") {
        const p = pick([1, 2, 3, 5, small()]);
        return rnd() < 0.6
          ? mod.interpolateBSpline(points, dim, p, params, options())
          : mod.approximateBSpline(points, dim, p, small(), params, options());
      }
      return pick([
        () =>
          mod.cubicSpline(
            points,
            dim,
            params,
            pick(["natural", "quadratic", "bessel", "not-a-knot", "periodic"]),
          ),
        () => mod.cubicSpline(points, dim, params, "clamped", arr(dim), arr(dim)),
        () => mod.hermiteSpline(points, dim, params, arr(n * dim)),
        () => mod.cardinalSpline(points, dim, params, num()),
        () => mod.catmullRom(points, dim, rnd(), rnd() < 0.5),
        () => mod.besselSpline(points, dim, params),
      ])();
    }
    const weights = (count) => (rnd() < 0.3 ? arr(count).map((x) => Math.abs(x) + 0.1) : undefined);
    if (kind === "bez") {
      const n = 1 + Math.floor(rnd() * 8);
      return new mod.BezierCurve(arr((n + 1) * dim), dim, weights(n + 1));
    }
    if (kind === "bsp") {
      const p = 1 + Math.floor(rnd() * 4);
      const n = p + Math.floor(rnd() * 6);
      const clamped = Float64Array.from({ length: n + p + 2 }, (_, i) =>
        Math.min(Math.max(i - p, 0), n + 1 - p),
      );
      return new mod.BSplineCurve(
        arr((n + 1) * dim),
        dim,
        p,
        rnd() < 0.5 ? sorted(n + p + 2) : clamped,
        weights(n + 1),
      );
    }
    if (kind === "bezsurf") {
      const [rows, cols] = [1 + Math.floor(rnd() * 5), 1 + Math.floor(rnd() * 5)];
      return new mod.BezierSurface(arr(rows * cols * 3), rows, cols, weights(rows * cols));
    }
    if (kind === "surf") {
      const [p, q] = [1 + Math.floor(rnd() * 3), 1 + Math.floor(rnd() * 6)];
      const [rows, cols] = [p + 1 + Math.floor(rnd() * 4), q + 1 + Math.floor(rnd() * 4)];
      const clamped = (n, d) =>
        Float64Array.from({ length: n + d + 1 }, (_, i) => Math.min(Math.max(i - d, 0), n - d));
      const knots = (n, d) => (rnd() < 0.5 ? sorted(n + d + 1) : clamped(n, d));
      return new mod.BSplineSurface(
        arr(rows * cols * 3),
        rows,
        cols,
        p,
        q,
        knots(rows, p),
        knots(cols, q),
        weights(rows * cols),
      );
    }
    const degrees = [1 + Math.floor(rnd() * 3), 1 + Math.floor(rnd() * 3)];
    return new mod.CompositeBezier(arr((degrees[0] + degrees[1] + 2) * dim), dim, degrees);
  }
  let calls = 0,
    errors = 0;
  const bad = [];
  for (let iter = 0; iter < iterations; iter++) {
    let obj;
    try {
      obj = make();
    } catch (e) {
      if (!(e instanceof Error) || e instanceof WebAssembly.RuntimeError) {
        bad.push(["make", e]);
        break;
      }
      continue;
    }
    const proto = Object.getPrototypeOf(obj);
    const methods = Object.getOwnPropertyNames(proto).filter(
      (m) =>
        m !== "constructor" &&
        m !== "free" &&
        typeof Object.getOwnPropertyDescriptor(proto, m).value === "function",
    );
    for (let k = 0; k < 6; k++) {
      const m = pick(methods);
      const args = Array.from({ length: 1 + Math.floor(rnd() * 5) }, () =>
        rnd() < 0.4
          ? small()
          : rnd() < 0.5
            ? num()
            : rnd() < 0.6
              ? arr()
              : rnd() < 0.5
                ? pick(strs)
                : anyArg(),
      );
      calls++;
      try {
        const r = obj[m](...args);
        if (r && typeof r.free === "function") r.free();
        if (Array.isArray(r)) r.forEach((x) => x?.free?.());
      } catch (e) {
        errors++;
        if (
          !(e instanceof Error) ||
          e instanceof WebAssembly.RuntimeError ||
          e.constructor.name !== "Error"
        ) {
          bad.push([m, args, e]);
        }
      }
    }
    // free functions
    const fns = [
      "arcLengths",
      "besselSpline",
      "bernstein",
      "bernsteinBasis",
      "cardinalSpline",
      "catmullRom",
      "circle",
      "circularArc",
      "circularArcBezier",
      "conicKind",
      "cubicSpline",
      "ellipse",
      "ellipseArc",
      "hermiteBasis",
      "hermiteBezier",
      "hermiteSpline",
      "jointContinuity",
      "joinBezier",
      "knotVector",
      "lagrange",
      "interpolateBSpline",
      "approximateBSpline",
      "bsplineInterpolationSystem",
      "parameterize",
      "phantomPoints",
      "uniformSegmentMatrix",
      "revolve",
      "extrude",
      "ruled",
      "interpolateSurface",
    ];
    const f = pick(fns);
    const args = Array.from({ length: 1 + Math.floor(rnd() * 5) }, () =>
      rnd() < 0.3
        ? small()
        : rnd() < 0.4
          ? num()
          : rnd() < 0.5
            ? arr()
            : rnd() < 0.5
              ? pick(strs)
              : rnd() < 0.5
                ? obj
                : rnd() < 0.3
                  ? options()
                  : anyArg(),
    );
    calls++;
    try {
      const r = mod[f](...args);
      r?.free?.();
    } catch (e) {
      errors++;
      if (
        !(e instanceof Error) ||
        e instanceof WebAssembly.RuntimeError ||
        e.constructor.name !== "Error"
      )
        bad.push([f, args, e]);
    }
    try {
      obj.free();
    } catch {}
    if (bad.length > 5) break;
  }
  const c = new mod.BezierCurve([0, 0, 1, 1], 2);
  const alive = c.evaluate(0.5).join(",");
  c.free();
  const describe = (v) =>
    JSON.stringify(v, (k, x) =>
      x instanceof Float64Array
        ? Array.from(x)
        : typeof x === "number" && !Number.isFinite(x)
          ? String(x)
          : x,
    );
  return {
    calls,
    errors,
    alive,
    bad: bad
      .slice(0, 5)
      .map(
        ([m, args, e]) =>
          `${m}(${describe(args)?.slice(0, 200)}) -> ${e?.constructor?.name}: ${String(e?.message ?? e).slice(0, 160)}`,
      ),
  };
}
