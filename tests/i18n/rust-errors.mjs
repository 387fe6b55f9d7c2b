// What the curve library's errors are, read from the Rust sources (for tests/i18n/check.mjs):
// the code of every variant (src/error/code.rs, and the families' enums nested in it:
// `FAMILY_FILES`), the subject keys (src/error/phrase.rs) and every variant's fields as the
// thrown Error's `params` name them (src/error/mod.rs and the family files, camelCase), plus the
// errors the JS glue throws itself (scripts/glue.mjs).
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

const source = (path) =>
  readFileSync(fileURLToPath(new URL(`../../src/error/${path}`, import.meta.url)), "utf8");
const expressionSource = () =>
  readFileSync(fileURLToPath(new URL("../../src/expr/error.rs", import.meta.url)), "utf8");

/**
 * The families of errors nested in `Error` (`Error::Conic(ConicError)` …): file → enum name. Each
 * file has its enum and its `code()` (`ConicError::X { .. } => "code"`); a nested error's
 * `params` are its variant's fields, as for `Error`'s own variants.
 */
const FAMILY_FILES = {
  "conic.rs": "ConicError",
  "interp.rs": "InterpError",
  "join.rs": "JoinError",
  "surface.rs": "SurfaceError",
};

/** The params every typed-expression error carries besides its problem's fields. */
export const EXPRESSION_PLACE = ["piece", "field", "start", "end"];

/**
 * The typed-expression problems (src/expr/error.rs): code → the camelCase names of its
 * fields, `EXPRESSION_PLACE` first (`Error::Expression` has one code per `Problem`).
 */
export function expressionCodes() {
  const text = expressionSource();
  const codes = new Map();
  for (const m of text.matchAll(/Problem::(\w+) \{ \.\. \} => "([a-z0-9-]+)"/g))
    codes.set(m[1], m[2]);
  const body = /pub enum Problem \{\n([\s\S]*?)\n\}\n/.exec(text);
  if (!body || codes.size < 10) throw new Error("Problem codes not found in src/expr/error.rs");
  return variantFields(body[1], codes, "Problem", EXPRESSION_PLACE);
}

/**
 * The camelCase field names of every variant of an enum's body (struct variants at 4 spaces,
 * fields at 8), by code, each list starting with `first`; `Error::Expression` is skipped (its
 * codes and fields are the problems', `expressionCodes`).
 */
function variantFields(body, codes, name, first = []) {
  const fields = new Map();
  let variant = null;
  for (const line of body.split("\n")) {
    const start = /^ {4}(\w+) \{(\},?)?$/.exec(line);
    if (start?.[1] === "Expression") {
      variant = null;
      continue;
    }
    if (start) {
      variant = start[1];
      if (!codes.has(variant)) throw new Error(`${name}::${variant} has no code`);
      fields.set(codes.get(variant), [...first]);
      if (start[2]) variant = null;
      continue;
    }
    if (/^ {4}\},?$/.test(line)) variant = null;
    const field = /^ {8}(\w+): /.exec(line);
    if (variant && field) fields.get(codes.get(variant)).push(camel(field[1]));
  }
  return fields;
}

/** The errors of scripts/glue.mjs and the bindings (code → params' names). */
export const GLUE_ERRORS = {
  freed: ["className"],
  "no-constructor": ["className", "makers"],
  "out-buffer": ["dim", "got"],
  internal: [],
};

/** `needed_by` → `neededBy` (serde's rename_all_fields = "camelCase"). */
const camel = (name) => name.replace(/_([a-z0-9])/g, (_, c) => c.toUpperCase());

/** Variant name → code, from `Error::Name { .. } => "code"` in code.rs and the family files. */
export function variantCodes() {
  const codes = new Map();
  for (const file of ["code.rs", ...Object.keys(FAMILY_FILES)]) {
    for (const m of source(file).matchAll(/Error::(\w+) \{ \.\. \} => "([a-z0-9-]+)"/g)) {
      codes.set(m[1], m[2]);
    }
  }
  if (codes.size < 70) throw new Error(`only ${codes.size} codes read from src/error/code.rs`);
  return codes;
}

/** The keys of `PHRASES` in phrase.rs: `("key", "English")`. */
export function phraseKeys() {
  const body = /pub const PHRASES[^=]*= &\[([\s\S]*?)\n\];/.exec(source("phrase.rs"));
  if (!body) throw new Error("PHRASES not found in src/error/phrase.rs");
  const keys = [...body[1].matchAll(/^\s*\("([^"]+)",/gm)].map((m) => m[1]);
  if (keys.length < 10) throw new Error(`only ${keys.length} phrase keys read`);
  return keys;
}

/** Code → the camelCase names of its variant's fields (Error and the families), glue's included. */
export function codeFields() {
  const codes = variantCodes();
  const body = /pub enum Error \{\n([\s\S]*?)\n\}\n/.exec(source("mod.rs"));
  if (!body) throw new Error("enum Error not found in src/error/mod.rs");
  const fields = new Map([
    ...Object.entries(GLUE_ERRORS),
    ...variantFields(body[1], codes, "Error"),
  ]);
  for (const [file, name] of Object.entries(FAMILY_FILES)) {
    const family = new RegExp(`pub enum ${name} \\{\\n([\\s\\S]*?)\\n\\}\\n`).exec(source(file));
    if (!family) throw new Error(`enum ${name} not found in src/error/${file}`);
    for (const [code, names] of variantFields(family[1], codes, name)) fields.set(code, names);
  }
  for (const code of codes.values()) {
    if (!fields.has(code)) throw new Error(`code ${code}: variant not found in src/error/`);
  }
  for (const [code, names] of expressionCodes()) fields.set(code, names);
  return fields;
}
