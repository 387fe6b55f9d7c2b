// Argument generators for the API fuzzer: well-formed values often enough to go deep (points
// whose count matches `dim` and the degree, sorted knots of the right count, parameters inside
// the receiver's domain), and hostile ones (NaN, ±Infinity, huge, negative and fractional
// numbers, wrong types, null/undefined, arrays of random lengths, strings, freed objects and
// objects of the wrong class). Deterministic for a given random source.

import { expression, parameters, pieces } from "./expressions.mjs";

/** A seeded random source (mulberry32): rnd() in [0, 1). */
export function random(seed) {
  let a = seed >>> 0;
  const rnd = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const int = (lo, hi) => lo + Math.floor(rnd() * (hi - lo + 1));
  const pick = (list) => list[Math.floor(rnd() * list.length)];
  return { rnd, int, pick, chance: (p) => rnd() < p };
}

/** Numbers that break naive code. */
const SPECIAL = [
  0,
  -0,
  1,
  -1,
  0.5,
  2.5,
  -2.5,
  NaN,
  Infinity,
  -Infinity,
  1e308,
  -1e308,
  5e-324,
  1e-300,
  2 ** 31,
  2 ** 32,
  2 ** 32 - 1,
  2 ** 53,
  1e9,
  0.999999999,
  1.000000001,
];
/** Counts a caller might pass: small, large, and ones whose product overflows 32 bits. */
const COUNTS = [0, 1, 2, 3, 5, 17, 100, 1000, 65_537, 2 ** 31, 2 ** 32, 1e9, 1e12, 1e300];
/** Counts the API may accept but that take ~1 s (tens of millions of numbers): rarer. */
const HUGE_COUNTS = [1e6, 2 ** 24, 2 ** 24 + 1];

/**
 * The generator for one fuzz run. `strings` is the pool of strings the API documents (kinds,
 * end conditions, rules); `objects()` returns the live pool entries ({ obj, cls, freed }).
 */
export function values(r, strings, objects) {
  const { rnd, int, pick, chance } = r;
  const special = () => pick(SPECIAL);
  const real = (scale = 10) => (chance(0.15) ? special() : (rnd() - 0.5) * scale);
  const reals = (n, scale = 10) => Float64Array.from({ length: n }, () => real(scale));
  /** Mostly ordinary reals; a few special values inside, now and then. */
  const mostlyFinite = (n, scale = 10) =>
    Float64Array.from({ length: n }, () => (chance(0.97) ? (rnd() - 0.5) * scale : special()));
  const increasing = (n, from = 0) => {
    let x = from;
    return Float64Array.from({ length: n }, () => (x += chance(0.1) ? 0 : 0.1 + rnd()));
  };
  /** A clamped knot vector for `count` points of degree `p` (n + p + 2 knots, n = count − 1). */
  const clamped = (count, p) => {
    const inner = Math.max(0, count - p - 1);
    const interior = increasing(inner).map((x) => x / (inner + 1));
    const knots = [
      ...Array(p + 1).fill(0),
      ...Array.from(interior).sort((a, b) => a - b),
      ...Array(p + 1).fill(1),
    ];
    return Float64Array.from(knots);
  };
  const knotsFor = (count, p) => {
    const n = count + p + 1;
    if (chance(0.55)) return clamped(count, p);
    if (chance(0.6)) return increasing(n);
    // wrong count or unsorted
    return chance(0.5) ? increasing(n + pick([-2, -1, 1, 2])) : mostlyFinite(n);
  };
  const plainArray = (a) => Array.from(a);
  /** Any value of a wrong or hostile kind. */
  const hostile = () => {
    switch (int(0, 13)) {
      case 0:
      case 1:
        return special();
      case 2:
        return pick(COUNTS);
      case 3:
        return null;
      case 4:
        return undefined;
      case 5:
        return pick(strings.length ? [...strings, "", "x"] : ["", "x"]);
      case 6:
        return pick([true, false, {}, [], () => 1, new Date(0), { length: 3 }]);
      case 7:
        return reals(int(0, 12));
      case 8:
        return plainArray(reals(int(0, 12)));
      case 9:
        return pick([new Float32Array(int(0, 9)), new Uint8Array(int(0, 9)), new Int32Array(3)]);
      case 10:
        return chance(0.1) ? new Float64Array(int(1e4, 1e5)).fill(rnd()) : reals(int(0, 40));
      case 11:
      case 12: {
        const pool = objects();
        return pool.length ? pick(pool).obj : null;
      }
      default:
        return [NaN, "1", null, undefined, {}];
    }
  };
  return { real, reals, mostlyFinite, increasing, clamped, knotsFor, hostile, special, plainArray };
}

/** Whether `param` takes a number / numbers / object … (any alternative of its type). */
export const accepts = (param, kind) => param.type.some((t) => t.kind === kind);

/**
 * A call's shape: the sizes its well-formed arguments agree on. `target` is the receiver entry
 * (or null): its dim, domain and sizes steer the numbers.
 */
export function shape(r, target) {
  const { int, pick, chance } = r;
  const count = target?.count ?? int(1, chance(0.9) ? 9 : 40);
  const degree = Math.max(1, Math.min(count - 1, int(1, 5)));
  const rows = target?.rows ?? int(1, 6);
  const cols = target?.cols ?? int(1, 6);
  return {
    dim: target?.dim ?? pick([2, 2, 3]),
    count,
    degree,
    rows,
    cols,
    degreeU: Math.max(1, Math.min(rows - 1, int(1, 3))),
    degreeV: Math.max(1, Math.min(cols - 1, int(1, 3))),
    domain: target?.domain ?? [0, 1],
    domainV: target?.domainV ?? target?.domain ?? [0, 1],
    target,
  };
}

/**
 * A well-formed value for parameter `param` of a call with shape `s` (by the parameter's name,
 * then its type), or a hostile one. `v` is `values(…)`.
 */
export function argument(r, v, param, s, classObjects, strings) {
  const { rnd, int, pick, chance } = r;
  if (chance(0.06)) return v.hostile();
  if (param.optional && chance(0.25)) return chance(0.5) ? undefined : null;
  const name = param.name;
  const inside = ([a, b]) => a + (b - a) * (chance(0.1) ? pick([0, 1]) : rnd());
  const inDomain = (d) => (chance(0.85) ? inside(d) : d[0] + (d[1] - d[0]) * (rnd() * 3 - 1));
  /** Parameters for a sampling call: all inside the domain, mostly. */
  const sampleParams = (length, d) => {
    const each = chance(0.8) ? inside : inDomain;
    return Float64Array.from({ length }, () => each(d));
  };
  const wrap = (a) => (chance(0.2) ? v.plainArray(a) : a);
  if (s.chosen && name in s.chosen) return s.chosen[name];
  // The typed curves' texts (expressions.mjs), by name before the types see an object.
  const typed = { pieces, parameters, text: expression };
  if (name in typed) return chance(0.95) ? typed[name](r) : v.hostile();
  if (name === "name") return chance(0.8) ? pick(["a", "b", "ω", "a_1", "q"]) : v.hostile();
  for (const t of param.type) {
    if (t.kind === "class") {
      const same = classObjects(param.type.filter((x) => x.kind === "class").map((x) => x.name));
      return same.length && chance(0.9) ? pick(same).obj : v.hostile();
    }
  }
  if (accepts(param, "literal")) return pick(param.type.filter((t) => t.kind === "literal")).value;
  if (accepts(param, "object")) {
    const object = param.type.find((t) => t.kind === "object");
    const result = {};
    for (const field of object.fields)
      if (chance(0.35)) result[field.name] = argument(r, v, field, s, classObjects, strings);
    if (chance(0.05)) result.unknownKey = 1;
    return result;
  }
  const numbers = accepts(param, "numbers");
  const n = s.count;
  switch (name) {
    case "points":
      if (!numbers) break;
      return wrap(
        v.mostlyFinite(chance(0.4) ? s.rows * s.cols * (chance(0.7) ? 3 : s.dim) : n * s.dim),
      );
    case "coefficients":
    case "tangents":
      return wrap(v.mostlyFinite(n * s.dim));
    case "point":
    case "vector":
    case "center":
    case "axis_x":
    case "axis_y":
    case "axisPoint":
    case "axisDirection":
    case "direction":
    case "origin":
    case "p0":
    case "p1":
    case "m0":
    case "m1":
    case "start_tangent":
    case "end_tangent":
      return wrap(v.mostlyFinite(chance(0.9) ? s.dim : int(0, 5)));
    case "knots":
      if (numbers) return wrap(v.knotsFor(n, s.degree));
      break;
    case "knotsU":
      return wrap(v.knotsFor(s.rows, s.degreeU));
    case "knotsV":
      return wrap(v.knotsFor(s.cols, s.degreeV));
    case "weights":
      return wrap(
        chance(0.8)
          ? Float64Array.from({ length: chance(0.5) ? n : s.rows * s.cols }, () => 0.2 + rnd() * 3)
          : v.reals(n),
      );
    case "params":
      if (chance(0.7)) return wrap(v.increasing(n));
      return chance(0.5)
        ? pick(["uniform", "chord", "centripetal", "x"])
        : pick([0, 0.5, 1, -1, NaN]);
    case "breaks":
      return wrap(v.increasing(int(1, 5)));
    case "degrees":
      return wrap(Float64Array.from({ length: int(1, 4) }, () => int(1, 4)));
    case "m":
      return wrap(v.mostlyFinite((s.dim + 1) ** 2, 4));
    case "us":
    case "ts":
      return wrap(sampleParams(int(0, 60), s.domain));
    case "vs":
      return wrap(sampleParams(int(0, 60), s.domainV));
    case "uvs": {
      const each = chance(0.8) ? inside : inDomain;
      return wrap(
        Float64Array.from({ length: 2 * int(0, 30) }, (_, i) => each(i % 2 ? s.domainV : s.domain)),
      );
    }
    case "rule":
      if (chance(0.9)) return pick(["C0", "C1", "C2", "G1"]);
      break;
    case "adjust":
      if (chance(0.9)) return pick(["left", "right"]);
      break;
    case "end":
      if (chance(0.9))
        return pick(["natural", "clamped", "quadratic", "bessel", "not-a-knot", "periodic"]);
      break;
    case "kind":
      if (chance(0.8)) return pick(["uniform", "clamped", "chord", "centripetal"]);
      break;
    case "t":
    case "u":
    case "s":
      return inDomain(s.domain);
    case "v":
      return inDomain(s.domainV);
    case "dim":
      return chance(0.95) ? s.dim : pick([0, 1, 4, 2.5, -2]);
    case "degree":
    case "p":
      return chance(0.9) ? s.degree : int(0, 12);
    case "degreeU":
      return s.degreeU;
    case "degreeV":
      return s.degreeV;
    case "rows":
      return s.rows;
    case "cols":
      return s.cols;
    case "count":
    case "nu":
    case "nv":
      if (chance(0.002)) return pick(HUGE_COUNTS);
      return chance(0.97) ? int(0, 60) : pick(COUNTS);
    case "i":
      return chance(0.9) ? int(0, Math.max(0, (s.target?.rows ?? s.count) - 1)) : pick(COUNTS);
    case "j":
      return chance(0.9) ? int(0, Math.max(0, s.cols - 1)) : pick(COUNTS);
    case "k":
    case "n":
      return chance(0.9) ? int(0, Math.max(1, s.count)) : pick(COUNTS);
    case "order":
    case "du":
    case "dv":
    case "times":
      if (accepts(param, "number")) return chance(0.9) ? int(0, 4) : pick(COUNTS);
      break;
    case "tolerance":
    case "accuracy":
      if (chance(0.9)) return 10 ** -int(1, 5);
      return pick([0, -1, NaN, Infinity, 1e-300, 1e-7, 1e-9, 1e-12, 100]);
    case "w":
    case "w0":
    case "w1":
    case "w2":
      return chance(0.8) ? 0.1 + rnd() * 3 : v.real();
    case "angle":
    case "sweep":
    case "start":
    case "start_angle":
    case "rotation":
      return chance(0.9) ? (rnd() - 0.5) * 8 : v.special();
    case "alpha":
    case "tension":
      return chance(0.9) ? rnd() : v.real();
    default:
      break;
  }
  // By type, for names without a rule (new API lands here first).
  if (accepts(param, "string") && (chance(0.7) || !accepts(param, "number")))
    return chance(0.95) ? pick(strings) : pick(["", "x", "Natural"]);
  if (accepts(param, "number")) return chance(0.8) ? (rnd() - 0.5) * 10 : v.special();
  if (accepts(param, "boolean")) return chance(0.9) ? chance(0.5) : pick([0, 1, "yes"]);
  if (numbers) return wrap(v.mostlyFinite(chance(0.5) ? n * s.dim : int(0, 12)));
  return v.hostile();
}
