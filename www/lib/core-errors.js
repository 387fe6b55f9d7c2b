/**
 * The curve library's errors in the active language.
 *
 * Every Error the library throws has `message` (English), `code` (a stable kebab-case code per
 * kind of failure: src/error/code.rs, and the glue's "freed", "no-constructor", "out-buffer",
 * "internal") and `params` (the failure's numbers and names, camelCase). `errorText(err)`
 * writes the message again from `code` and `params` with the `coreError.<code>` template of the
 * active language (lib/strings/core-errors.js for English, lib/locales/*.js): it never reads
 * the English text, so English is the library's message word for word and a translation is
 * complete. In the text:
 * - numbers keep the digits of `String(x)` (as the English message: 0.1, 1.5e-7) with the
 *   language's decimal separator (`exactNumber`), ±Infinity and NaN by `coreError.number.*`;
 * - a subject (a field naming what went wrong: `what`, `expected`, `neededBy`, `reason`, the
 *   `name` of "in-argument" and "not-positive") is `coreError.subject.<value>` when there is
 *   one, else an API identifier shown as it is ("degree", "knotsU");
 * - lists are joined with `listSeparator()` (", ", or "; " with a decimal comma; result counts
 *   with " × ");
 * - the placeholders the English message computes (n = points − 1, p+1 = degree + 1, bytes,
 *   MiB, …) are derived here, listed per code in `DERIVED_PLACEHOLDERS`;
 * - "in-argument" is "{argument}: {message}", the cause (`params.source`) written the same way.
 * Anything else (no `code`, a code without a template, params that do not fill the template,
 * the UI's own errors, which are translated already, a thrown non-Error) gives `err.message`,
 * or `String(err)`. A pure function: no DOM, no state but the active language.
 */
import { listSeparator, localeDecimal } from "./format.js";
import { has, t, tp } from "./strings.js";

/**
 * `x` in the active language with the digits of `String(x)` (its shortest round-trip digits,
 * as the library's English message prints it), so that no value changes: "1.5" → "1,5" in
 * Croatian, "1.5e-7" → "1,5e-7"; ±Infinity and NaN in words. A BigInt is written whole.
 */
export function exactNumber(x) {
  if (Number.isNaN(x)) return t("coreError.number.nan");
  if (x === Infinity || x === -Infinity) {
    return t(x > 0 ? "coreError.number.infinity" : "coreError.number.negativeInfinity");
  }
  return localeDecimal(String(x));
}

/** u32::MAX, the largest whole number an argument may be ("not-whole-number"). */
const U32_MAX = 4294967295;

/** The fields of each code that hold a subject (src/error/phrase.rs), translated by key. */
const SUBJECT_FIELDS = {
  "too-few-points": ["what"],
  "too-few-data-points": ["what"],
  "too-large": ["what"],
  "result-too-large": ["what"],
  "singular-system": ["what"],
  "argument-type": ["expected"],
  "missing-argument": ["neededBy"],
  "conflicting-options": ["reason"],
  "not-positive": ["name"],
};

/** The list fields joined with another separator than ", ". */
const JOINED = { counts: " × " };

/**
 * The count that picks the plural form where a code's English has `.one`/`.other` (and a
 * language its own categories): the field's name.
 */
export const PLURAL_COUNT = Object.freeze({
  "too-few-points": "needed",
  "too-few-data-points": "needed",
  "insertion-multiplicity": "times",
  "join-degree": "needed",
});

/** `value` as its phrase when it is a subject key, else as it is (an identifier). */
function subject(value) {
  const key = `coreError.subject.${value}`;
  return has(key) ? t(key) : String(value);
}

/** A subject with its index when it is one of a list: "coordinate 3". */
function indexedSubject(what, index) {
  if (index === undefined || index === null) return subject(what);
  return t("coreError.indexed", { subject: subject(what), index: exactNumber(index) });
}

/** `a − b`, stopping at 0 as Rust's `saturating_sub` does. */
const minus = (a, b) => Math.max(a - b, 0);

/**
 * The placeholders a template may use beyond the code's params, as functions of the params
 * (and of the Error, for "internal"): what the English message computes.
 */
const DERIVED = {
  "coordinate-count": { firstPoint: (p) => (p.dim === 3 ? "x0, y0, z0" : "x0, y0") },
  "not-finite": { subject: (p) => indexedSubject(p.what, p.index) },
  "coordinate-too-large": { subject: (p) => indexedSubject(p.what, p.index) },
  "not-whole-number": {
    subject: (p) => indexedSubject(p.what, p.index),
    max: () => U32_MAX,
  },
  "index-out-of-range": { last: (p) => minus(p.count, 1) },
  "in-argument": {
    argument: (p) =>
      p.index === undefined || p.index === null
        ? subject(p.name)
        : `${subject(p.name)}[${exactNumber(p.index)}]`,
    message: (p) => coded(p.source?.code, p.source?.params),
  },
  "knot-count": { n: (p) => minus(p.points, 1) },
  "knot-order": { previousIndex: (p) => minus(p.index, 1) },
  "knot-multiplicity": { order: (p) => p.degree + 1 },
  "insertion-multiplicity": {
    knotValue: (p) =>
      p.name === undefined || p.name === null
        ? exactNumber(p.knot)
        : `${p.name} = ${exactNumber(p.knot)}`,
    order: (p) => p.degree + 1,
  },
  "too-few-points-for-degree": { order: (p) => p.degree + 1 },
  "coincident-points": { next: (p) => p.index + 1 },
  "breakpoint-count": { breakpoints: (p) => p.pieces + 1 },
  "net-coordinate-count": {
    // usize arithmetic of the wasm build (32 bits), saturating as in message.rs.
    total: (p) => Math.min(p.rows * p.cols * 3, U32_MAX),
  },
  "net-index-out-of-range": { lastI: (p) => minus(p.rows, 1), lastJ: (p) => minus(p.cols, 1) },
  "result-too-large": {
    bytes: (p) => p.counts.reduce((a, c) => a * BigInt(c), BigInt(p.valueBytes)),
    mib: (p) => BigInt(p.maxBytes) >> 20n,
  },
  "params-not-increasing": { previousIndex: (p) => p.index - 1 },
  "schoenberg-whitney": { hiIndex: (p) => p.index + p.degree + 1 },
  "knots-not-clamped": { order: (p) => p.degree + 1 },
  internal: { message: (_, err) => err.message },
};

/** The names of the derived placeholders per code (for tests/i18n/check.mjs). */
export const DERIVED_PLACEHOLDERS = Object.freeze(
  Object.fromEntries(Object.entries(DERIVED).map(([code, d]) => [code, Object.keys(d)])),
);

/** A param's text: numbers exact, lists joined, the few fields with words of their own. */
function paramText(code, name, value, params) {
  if (code === "coincident-points" && name === "kind") return spacing(value);
  if (typeof value === "number" || typeof value === "bigint") return exactNumber(value);
  if (Array.isArray(value)) {
    return value.map((v) => paramText(code, name, v, params)).join(JOINED[name] ?? listSeparator());
  }
  if (SUBJECT_FIELDS[code]?.includes(name)) return subject(value);
  if (code === "knots-not-clamped" && name === "end") {
    return has(`coreError.end.${value}`) ? t(`coreError.end.${value}`) : String(value);
  }
  if (code === "out-buffer" && name === "got" && value === "array") {
    return t("coreError.bufferLength", { length: exactNumber(params.length) });
  }
  return value === undefined || value === null ? value : String(value);
}

/** The names of the parametrisations with an exponent of their own (`params.kind` is α). */
const SPACINGS = new Map([
  [0, "uniform"],
  [0.5, "centripetal"],
  [1, "chord"],
]);

/** A parametrisation by its exponent α, in the language ("Chord", "alpha = 0.3"). */
function spacing(alpha) {
  const name = SPACINGS.get(alpha);
  return name
    ? t(`coreError.spacing.${name}`)
    : t("coreError.spacing.alpha", { alpha: exactNumber(alpha) });
}

/**
 * The forms of a typed-expression message other than its code's own template, picked by the
 * params as src/expr/error.rs's Display does: code → (params) → suffix or "".
 */
export const EXPRESSION_FORMS = Object.freeze({
  "unexpected-character": (p) => ({ ",": ".comma", "|": ".bar" })[p.character] ?? "",
  "expected-operand": (p) => (p.found === "" ? ".end" : ""),
  "function-power": (p) => (["sin", "cos", "tan"].includes(p.name) ? ".trig" : ""),
});

/** Whether the params are a typed expression's (src/expr/error.rs: the place and the range). */
const isExpression = (p) => typeof p?.start === "number" && typeof p?.end === "number";

/**
 * A typed expression's error: its place ("pieces[1].y, characters 3–4", as ExprError's
 * Display) then the problem's message; null when the problem has no template.
 */
function expressionText(code, params) {
  const message = problemOf(code, params);
  if (message === null) return null;
  const piece = params.piece ?? null;
  const field = params.field ?? null;
  let place;
  if (piece !== null && field !== null) place = t("coreError.place.pieceField", { piece, field });
  else if (piece !== null) place = t("coreError.place.piece", { piece });
  else if (field !== null) place = t("coreError.place.field", { field });
  else place = t("coreError.place.none");
  if (params.end > params.start) {
    place = t("coreError.place.range", {
      place,
      start: exactNumber(params.start),
      end: exactNumber(params.end),
    });
  }
  return t("coreError.place.at", { place, message });
}

/** A typed expression's problem in words (its code's form for these params), or null. */
function problemOf(code, params) {
  const form = EXPRESSION_FORMS[code]?.(params) ?? "";
  const key = has(`coreError.${code}${form}`) ? `${code}${form}` : code;
  return coded(key, params, {}, false);
}

/**
 * A typed expression's problem alone, without its place ('this ")" has no "(" before it'), for
 * a page that shows the place itself (the characters underlined, the piece and field named);
 * any other error as `errorText`.
 */
export function problemText(err) {
  if (err !== null && typeof err === "object" && isExpression(err.params)) {
    const message = problemOf(err.code, err.params);
    if (message !== null) return message;
  }
  return errorText(err);
}

/**
 * The text of `code` with `params` in the active language, or null when there is no template
 * or the params do not fill it. `err` is the thrown Error (for "internal"); `placed` false for
 * a typed expression's problem alone (without its place).
 */
function coded(code, params = {}, err = {}, placed = true) {
  if (typeof code !== "string") return null;
  if (placed && isExpression(params)) return expressionText(code, params);
  const key = `coreError.${code}`;
  const plural = has(`${key}.other`);
  if (!plural && !has(key)) return null;
  const values = {};
  for (const [name, value] of Object.entries(params ?? {})) {
    const text = paramText(code, name, value, params);
    if (text !== undefined && text !== null) values[name] = text;
  }
  for (const [name, derive] of Object.entries(DERIVED[code] ?? {})) {
    let value;
    try {
      value = derive(params ?? {}, err);
    } catch {
      return null; // params of another shape than this code's
    }
    if (value === null || value === undefined) return null;
    values[name] = typeof value === "string" ? value : exactNumber(value);
  }
  const text = plural ? tp(key, params?.[PLURAL_COUNT[code]] ?? 0, values) : t(key, values);
  return /\{\w+\}/.test(text) ? null : text;
}

/**
 * The message of `err` in the active language: from its `code` and `params` when it is one of
 * the library's errors (see the module's comment), else `err.message` (or `String(err)` for a
 * thrown value that is no Error).
 */
export function errorText(err) {
  const fallback = err instanceof Error ? err.message : String(err?.message ?? err);
  if (err === null || typeof err !== "object") return fallback;
  return coded(err.code, err.params, err) ?? fallback;
}
