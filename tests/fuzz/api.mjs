// The callable surface of the wasm package, enumerated from the module itself: every exported
// function, every exported class with its constructor, statics, prototype methods and getters.
// Parameter names and types come from wasm-bindgen's .d.ts (splinelab.d.ts) so that the fuzzer
// can build well-formed arguments; a callable the .d.ts does not describe is still called, with
// `fn.length` untyped arguments. New API is therefore covered without editing the fuzzer.

/** Exports that load the module rather than use it. */
const LOADERS = new Set(["default", "initSync"]);

/** Splits `text` at top-level occurrences of `separator` (outside (), [], {}, <>). */
function splitTop(text, separator) {
  const parts = [];
  let depth = 0;
  let start = 0;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if ("([{<".includes(c)) depth++;
    else if (")]}>".includes(c)) depth--;
    else if (c === separator && depth === 0) {
      parts.push(text.slice(start, i).trim());
      start = i + 1;
    }
  }
  const last = text.slice(start).trim();
  if (last) parts.push(last);
  return parts;
}

/** The inside of the first balanced `(…)` of `text` (after `from`). */
function parenthesised(text, from = 0) {
  const open = text.indexOf("(", from);
  let depth = 0;
  for (let i = open; i < text.length; i++) {
    if (text[i] === "(") depth++;
    else if (text[i] === ")" && --depth === 0) return text.slice(open + 1, i);
  }
  return "";
}

/**
 * A type as a list of alternatives: { kind: "number" | "string" | "boolean" | "numbers" |
 * "class" | "literal" | "object" | "null" | "any", … }.
 */
export function parseType(text) {
  return splitTop(text, "|").map((alt) => {
    if (alt === "number") return { kind: "number" };
    if (alt === "string") return { kind: "string" };
    if (alt === "boolean") return { kind: "boolean" };
    if (alt === "null" || alt === "undefined") return { kind: "null" };
    if (/^(Float64Array|Float32Array|number\[\])$/.test(alt)) return { kind: "numbers" };
    if (/^"[^"]*"$/.test(alt)) return { kind: "literal", value: alt.slice(1, -1) };
    if (alt.startsWith("{")) {
      const fields = splitTop(alt.slice(1, -1), ";").map((field) => {
        const colon = field.indexOf(":");
        const name = field.slice(0, colon).trim();
        return {
          name: name.replace(/\?$/, ""),
          optional: name.endsWith("?"),
          type: parseType(field.slice(colon + 1).trim()),
        };
      });
      return { kind: "object", fields };
    }
    if (/^[A-Z]\w*$/.test(alt)) return { kind: "class", name: alt };
    return { kind: "any", text: alt };
  });
}

/** `a: number, b?: T` → [{ name, optional, type }]. */
function parseParams(text) {
  return splitTop(text, ",").map((param) => {
    const colon = param.indexOf(":");
    const name = param.slice(0, colon).trim();
    return {
      name: name.replace(/\?$/, ""),
      optional: name.endsWith("?"),
      type: parseType(param.slice(colon + 1).trim()),
    };
  });
}

/**
 * The signatures in a wasm-bindgen .d.ts: Map "Class#method" / "Class.static" /
 * "Class.constructor" / "Class#getter" / "function" → parameter list (getters: []).
 */
export function parseDts(dts) {
  const signatures = new Map();
  let cls = null;
  for (const raw of dts.split("\n")) {
    const line = raw.trimEnd();
    const head = line.match(/^export class (\w+)/);
    if (head) {
      cls = head[1];
      continue;
    }
    if (cls && line === "}") {
      cls = null;
      continue;
    }
    const fn = line.match(/^export function (\w+)\(/);
    if (fn && !cls) {
      signatures.set(fn[1], parseParams(parenthesised(line)));
      continue;
    }
    if (!cls) continue;
    const member = line.match(/^ {4}(static )?(readonly )?(\w+)(\(|\??:)/);
    if (!member) continue;
    const [, isStatic, isGetter, name] = member;
    if (isGetter) signatures.set(`${cls}#${name}`, []);
    else if (name === "constructor")
      signatures.set(`${cls}.constructor`, parseParams(parenthesised(line)));
    else signatures.set(`${cls}${isStatic ? "." : "#"}${name}`, parseParams(parenthesised(line)));
  }
  return signatures;
}

/** Whether `value` is a class (wasm-bindgen emits `class X { … }`). */
const isClass = (value) =>
  typeof value === "function" && /^class\b/.test(Function.prototype.toString.call(value));

/**
 * Every callable of `mod`: { key, kind: "function" | "constructor" | "static" | "method" |
 * "getter", cls?, name, params, typed } where `typed` says whether the .d.ts described it.
 * Internal glue members (`__wrap`, `__destroy_into_raw`) are left out.
 */
export function enumerateApi(mod, dts) {
  const signatures = parseDts(dts);
  const callables = [];
  const untyped = (fn) =>
    Array.from({ length: fn.length }, (_, i) => ({
      name: `arg${i}`,
      optional: false,
      type: [{ kind: "any" }],
    }));
  const add = (key, kind, fields, fn) => {
    const typed = signatures.has(key);
    callables.push({
      key,
      kind,
      ...fields,
      params: typed ? signatures.get(key) : untyped(fn),
      typed,
    });
  };
  for (const [name, value] of Object.entries(mod)) {
    if (LOADERS.has(name) || typeof value !== "function") continue;
    if (!isClass(value)) {
      add(name, "function", { name }, value);
      continue;
    }
    add(`${name}.constructor`, "constructor", { cls: name, name }, value);
    for (const member of Object.getOwnPropertyNames(value)) {
      if (["length", "name", "prototype"].includes(member) || member.startsWith("__")) continue;
      if (typeof value[member] === "function")
        add(`${name}.${member}`, "static", { cls: name, name: member }, value[member]);
    }
    for (const member of Object.getOwnPropertyNames(value.prototype)) {
      if (member === "constructor" || member.startsWith("__")) continue;
      const d = Object.getOwnPropertyDescriptor(value.prototype, member);
      if (d.get) add(`${name}#${member}`, "getter", { cls: name, name: member }, d.get);
      else if (typeof d.value === "function")
        add(`${name}#${member}`, "method", { cls: name, name: member }, d.value);
    }
  }
  return callables;
}
