/**
 * Which language the UI speaks, and loading its table. The choice, first that applies: `?lang=`
 * in the page's address, the `lang` attribute of a `<spline-lab>` element, the browser's
 * preferred languages (`navigator.languages`, "hr-HR" counts as "hr"), else English. A language's
 * table (www/lib/locales/<code>.js) is loaded only when chosen; keys it lacks fall back to
 * English (lib/strings.js). Numbers follow the language (`formatNumber`); links and JSON state
 * stay locale-free.
 */
import { addLocale, setLocale } from "./strings.js";

/** The languages with a table, in the order the menu lists them, each named in itself. */
export const LANGUAGES = Object.freeze([
  { code: "en", name: "English" },
  { code: "el", name: "Ελληνικά" },
  { code: "hr", name: "Hrvatski" },
  { code: "it", name: "Italiano" },
]);
const CODES = new Set(LANGUAGES.map((l) => l.code));

/** The supported code for a BCP 47 tag ("hr-HR" → "hr"), or null. */
export function supportedLanguage(tag) {
  const code = String(tag ?? "")
    .trim()
    .toLowerCase()
    .split(/[-_]/)[0];
  return CODES.has(code) ? code : null;
}

/**
 * The language to use: `requested` (a `?lang=` value or a `lang` attribute) when supported,
 * else the first supported of `preferred` (the browser's languages), else "en".
 */
export function chooseLanguage(requested, preferred = globalThis.navigator?.languages ?? []) {
  const asked = supportedLanguage(requested);
  if (asked) return asked;
  for (const tag of preferred) {
    const code = supportedLanguage(tag);
    if (code) return code;
  }
  return "en";
}

const loaded = new Map([["en", Promise.resolve()]]);

/** Loads the table of `code` (once) and makes it the active language of `t`, `tp`, `formatNumber`. */
export async function useLanguage(code) {
  const chosen = supportedLanguage(code) ?? "en";
  if (!loaded.has(chosen)) {
    loaded.set(
      chosen,
      import(`./locales/${chosen}.js`).then((module) => addLocale(chosen, module.default)),
    );
  }
  try {
    await loaded.get(chosen);
    setLocale(chosen);
    return chosen;
  } catch {
    loaded.delete(chosen); // a failed load (offline copy without the file): English, retry later
    setLocale("en");
    return "en";
  }
}

/** `href` with its `lang` query parameter set to `code` (the hash, the demo's state, kept). */
export function withLanguage(href, code) {
  const url = new URL(href);
  url.searchParams.set("lang", code);
  return url.href;
}
