// Starts or completes a translation: prints www/lib/locales/<code>.js with every key the
// language lacks added at the end with its English text, to be translated in place (plural
// keys expanded to the language's categories, e.g. Croatian's `.few`). Keys already translated
// are kept as they are. Check the result with `node tests/i18n/check.mjs <code>`.
//
//   node scripts/locale-template.mjs hr > www/lib/locales/hr.next.js
import { existsSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { englishTable } from "../www/lib/strings.js";

const code = process.argv[2];
if (!/^[a-z]{2,3}$/.test(code ?? "")) throw new Error("usage: locale-template.mjs <language code>");
const file = fileURLToPath(new URL(`../www/lib/locales/${code}.js`, import.meta.url));
const current = existsSync(file) ? (await import(file)).default : {};
const english = englishTable();
const categories = new Intl.PluralRules(code).resolvedOptions().pluralCategories;
const entries = [];
const seen = new Set();
for (const [key, text] of Object.entries(english)) {
  const m = /^(.*)\.(one|other)$/.exec(key);
  const plural = m && `${m[1]}.one` in english && `${m[1]}.other` in english;
  const keys = plural ? categories.map((c) => `${m[1]}.${c}`) : [key];
  for (const k of keys) {
    if (seen.has(k)) continue;
    seen.add(k);
    const source = plural ? english[`${m[1]}.other`] : text;
    entries.push([k, current[k] ?? (plural && k.endsWith(".one") ? english[k] : source)]);
  }
}
const lines = entries.map(([k, v]) => `  ${JSON.stringify(k)}: ${JSON.stringify(v)},`);
console.log(
  `/** The ${new Intl.DisplayNames(["en"], { type: "language" }).of(code)} (${code}) strings of the UI: every key of English (lib/strings.js). */\nexport default {\n${lines.join("\n")}\n};`,
);
