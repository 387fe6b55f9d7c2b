// The translations against English (run by `make test`; `node tests/i18n/check.mjs [code]`):
// every table in www/lib/locales/<code>.js has exactly English's keys, each with the same
// placeholders ({name}) as the English string (a plural form may drop some: English's "one
// intersection"), and no string left empty. Plural keys follow the
// language: where English has `<key>.one`/`<key>.other`, a language has one key per category
// `Intl.PluralRules` gives it (Croatian adds `.few`), and no others.
// First, English against the curve library's errors (read from the Rust sources by
// rust-errors.mjs): every code (src/error/code.rs, and the glue's) has `coreError.<code>` (or
// its plural forms), every subject key of src/error/phrase.rs has `coreError.subject.<key>`,
// and a `coreError.<code>` template uses only that variant's fields (camelCase) and the
// placeholders lib/core-errors.js derives for the code (`DERIVED_PLACEHOLDERS`).
// Ends with one line "i18n: N passed, N failed" (scripts/test-all.sh sums it).
import { existsSync, readdirSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { DERIVED_PLACEHOLDERS, PLURAL_COUNT } from "../../www/lib/core-errors.js";
import { englishTable } from "../../www/lib/strings.js";
import { codeFields, phraseKeys } from "./rust-errors.mjs";

const dir = fileURLToPath(new URL("../../www/lib/locales/", import.meta.url));
const only = process.argv[2];
const english = englishTable();
const placeholders = (s) =>
  [...String(s).matchAll(/\{(\w+)\}/g)]
    .map((m) => m[1])
    .sort()
    .join(",");
/**
 * Whether `text` uses the placeholders of `english`: the same ones, or for a plural form some
 * of them (English's "one intersection" needs no {count}; Croatian's .one also serves 21).
 */
function samePlaceholders(text, english, plural) {
  const have = placeholders(text);
  const want = placeholders(english);
  if (!plural) return have === want;
  const allowed = new Set(want.split(","));
  return have === "" || have.split(",").every((p) => allowed.has(p));
}

/** English's keys turned into the keys language `code` must have. */
function expectedKeys(code) {
  const categories = new Intl.PluralRules(code).resolvedOptions().pluralCategories;
  const plural = new Set();
  for (const key of Object.keys(english)) {
    const m = /^(.*)\.(zero|one|two|few|many|other)$/.exec(key);
    if (m && `${m[1]}.other` in english && `${m[1]}.one` in english) plural.add(m[1]);
  }
  const keys = new Map(); // key → the English key whose placeholders it keeps
  for (const key of Object.keys(english)) {
    const m = /^(.*)\.(zero|one|two|few|many|other)$/.exec(key);
    if (m && plural.has(m[1])) continue;
    keys.set(key, key);
  }
  for (const base of plural) {
    for (const c of categories) keys.set(`${base}.${c}`, `${base}.other`);
  }
  return keys;
}

/** The problems of English's `coreError.*` keys against the library's errors. */
function coreErrorProblems() {
  const problems = [];
  const fields = codeFields();
  for (const [code, names] of fields) {
    const key = `coreError.${code}`;
    const plural = `${key}.other` in english;
    if (!plural && !(key in english)) problems.push(`no ${key} (code ${code})`);
    if (plural !== code in PLURAL_COUNT)
      problems.push(`${key}: plural forms ${plural ? "without" : "but no"} PLURAL_COUNT entry`);
    const allowed = new Set([...names, ...(DERIVED_PLACEHOLDERS[code] ?? [])]);
    for (const k of [key, `${key}.one`, `${key}.other`].filter((k) => k in english)) {
      for (const name of placeholders(english[k]).split(",").filter(Boolean)) {
        if (!allowed.has(name)) problems.push(`${k}: {${name}} is no field of ${code} nor derived`);
      }
    }
  }
  for (const code of Object.keys(DERIVED_PLACEHOLDERS)) {
    if (!fields.has(code)) problems.push(`DERIVED_PLACEHOLDERS names an unknown code ${code}`);
  }
  for (const key of phraseKeys()) {
    if (!(`coreError.subject.${key}` in english)) problems.push(`no coreError.subject.${key}`);
  }
  return { problems, codes: fields.size };
}

let passed = 0;
let failed = 0;
if (!only || only === "en") {
  const { problems, codes } = coreErrorProblems();
  if (problems.length) {
    failed++;
    console.log(
      `FAIL en: ${problems.length} problems\n     ${problems.slice(0, 40).join("\n     ")}`,
    );
  } else {
    passed++;
    console.log(`ok   en: the ${codes} error codes and every subject key have their templates`);
  }
}
const files = (existsSync(dir) ? readdirSync(dir) : []).filter(
  (f) => f.endsWith(".js") && (!only || f === `${only}.js`),
);
for (const file of files) {
  const code = file.replace(/\.js$/, "");
  const table = (await import(`${dir}${file}`)).default;
  const expected = expectedKeys(code);
  const problems = [];
  for (const [key, source] of expected) {
    if (!(key in table)) problems.push(`missing ${key}`);
    else if (typeof table[key] !== "string" || table[key].trim() === "")
      problems.push(`empty ${key}`);
    else if (!samePlaceholders(table[key], english[source], key !== source))
      problems.push(
        `placeholders of ${key}: {${placeholders(table[key])}} instead of {${placeholders(english[source])}}`,
      );
  }
  for (const key of Object.keys(table)) if (!expected.has(key)) problems.push(`unknown key ${key}`);
  if (problems.length) {
    failed++;
    console.log(
      `FAIL ${code}: ${problems.length} problems\n     ${problems.slice(0, 40).join("\n     ")}`,
    );
  } else {
    passed++;
    console.log(`ok   ${code}: ${expected.size} keys, placeholders as in English`);
  }
}
console.log(`i18n: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
