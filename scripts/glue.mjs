// Post-processes the JS glue wasm-bindgen generates (www/pkg/splinelab.js and its .d.ts), run
// by `make build` right after wasm-bindgen: `node scripts/glue.mjs <pkg-dir>`.
//
// 1. Per-call methods without allocation. Every class with `evaluate` gains
//    `evaluateInto(…, out)` (and `derivativeInto(…, out)` beside `derivative`): one call into
//    wasm (the hidden `__evaluateScratch` / `__derivativeScratch` methods, see
//    src/wasm/scratch.rs) writes the point into a fixed buffer in the wasm memory, and the JS
//    copies its `dim` numbers from the glue's cached Float64Array of the memory (made again by
//    `getFloat64ArrayMemory0()` when the memory has grown) into the caller's `out`. The hidden
//    methods are removed from the classes; their wasm exports stay.
// 2. Freed objects. wasm-bindgen's glue passes a freed object's pointer 0 into wasm, where it
//    throws "null pointer passed to rust" from inside Rust (and leaves the wasm stack pointer
//    where the throw found it). Every read of `this.__wbg_ptr` before a call becomes
//    `livePtr(this, Class)`, which throws `Error("this Class was freed")` first; every
//    parameter whose JSDoc type is one of the classes (`left`, `curveA`, …) is checked the same
//    way ("curveA: this BSplineCurve was freed"); `free()` of a freed object does nothing.
// 3. Objects of another class as `this`. `BezierCurve.prototype.evaluate.call(aBSpline, t)`
//    would hand a B-spline's pointer to a Bézier method, which reads (or, for a setter or
//    `free()`, writes) the other object's memory as its own. `livePtr` and `free()` first
//    compare the class brand `__slClass` of the object's prototype with their class and throw
//    an "argument-type" Error naming both classes. (wasm-bindgen already checks parameters of
//    a class type: "expected instance of BezierCurve".)
//
// Reviewed against the glue of wasm-bindgen REVIEWED (the version Cargo.lock pins): another
// version stops the build until this file is checked against its glue, and every pattern
// below must be found as many times as expected, so a changed glue fails loudly instead of
// being patched half-way.
import { readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import { fileURLToPath } from "node:url";

const REVIEWED = "0.2.130";
const ROOT = fileURLToPath(new URL("..", import.meta.url));
const pkg = process.argv[2];
if (!pkg) fail("usage: node scripts/glue.mjs <pkg-dir>");

const lock = readFileSync(join(ROOT, "Cargo.lock"), "utf8");
const locked = /\nname = "wasm-bindgen"\nversion = "([^"]+)"/.exec(lock)?.[1];
if (locked !== REVIEWED) {
  fail(
    `Cargo.lock pins wasm-bindgen ${locked}, but scripts/glue.mjs was reviewed against ` +
      `${REVIEWED}: check its patterns against the new glue, then update REVIEWED`,
  );
}

function fail(message) {
  console.error(`glue.mjs: ${message}`);
  process.exit(1);
}

/** Replaces every match of `pattern` (global) in `text` by `replacement(...match)`, failing
 * when there is none, or not `count` when given. */
function replaceCounted(text, pattern, replacement, count, what) {
  let n = 0;
  const out = text.replace(pattern, (...m) => {
    n += 1;
    return replacement(...m);
  });
  if (count !== undefined && n !== count) fail(`${what}: expected ${count} matches, found ${n}`);
  if (n === 0) fail(`${what}: no match`);
  return out;
}

const jsPath = join(pkg, "splinelab.js");
const dtsPath = join(pkg, "splinelab.d.ts");
let js = readFileSync(jsPath, "utf8");
let dts = readFileSync(dtsPath, "utf8");
if (js.includes("function livePtr(")) fail(`${jsPath} was already processed`);

// ---- the classes: `export class Name {` … the next line that is exactly `}` ----------------
const classes = [];
for (const m of js.matchAll(/^export class (\w+) \{\n[\s\S]*?^\}\n/gm)) {
  classes.push({ name: m[1], start: m.index, text: m[0] });
}
if (classes.length === 0) fail("no exported class found");
const classNames = new Set(classes.map((c) => c.name));

/** A hidden scratch method's wasm export, and the text of the method (JSDoc included) removed. */
function takeScratch(c, method) {
  const re = new RegExp(
    `    /\\*\\*\\n(?:     \\*.*\\n)*?     \\*/\\n    ${method}\\(([^)]*)\\) \\{\\n` +
      "        const ret = wasm\\.(\\w+)\\(this\\.__wbg_ptr[^\\n]*\\n" +
      "        return ret >>> 0;\\n    \\}\\n",
  );
  const m = re.exec(c.text);
  if (!m) return null;
  c.text = c.text.replace(m[0], "");
  return { params: m[1], exportName: m[2] };
}

/**
 * The JS method `${base}Into(params, out)` over the hidden scratch method `scratch` (`null`:
 * none), for the class named `cls`: its JSDoc and body.
 */
function intoMethod(cls, base, scratch) {
  if (!scratch) return "";
  const p = scratch.params; // "t", "u, v", "t, order" or "u, v, du, dv"
  const params = p
    .split(", ")
    .map((q) => `     * @param {number} ${q}\n`)
    .join("");
  return (
    "    /**\n" +
    `     * \`${base}(${p})\` written into \`out\` (a Float64Array or array of at least \`dim\`\n` +
    "     * numbers), which it returns: one call into wasm, nothing allocated (added by\n" +
    "     * scripts/glue.mjs).\n" +
    params +
    "     * @param {Float64Array | number[]} out\n" +
    "     * @returns {Float64Array | number[]}\n" +
    "     */\n" +
    `    ${base}Into(${p}, out) {\n` +
    `        const i = wasm.${scratch.exportName}(livePtr(this, ${JSON.stringify(cls)}), ${p});\n` +
    `        return i === 0 ? copyInto(this.${base}(${p}), out) : scratchInto(i, out);\n` +
    "    }\n"
  );
}

/** The TypeScript declaration of `${base}Into` (see intoMethod). */
function intoDeclaration(base, scratch) {
  if (!scratch) return "";
  const params = scratch.params
    .split(", ")
    .map((q) => `${q}: number`)
    .join(", ");
  return (
    `    /**\n     * \`${base}\` written into \`out\` (at least \`dim\` numbers), which it returns:\n` +
    "     * one call into wasm, nothing allocated.\n     */\n" +
    `    ${base}Into<T extends Float64Array | number[]>(${params}, out: T): T;\n`
  );
}

/** The exported functions documented to return class `name`: "sl.cubicSpline(…), sl.…(…)". */
function makersOf(name) {
  const makers = [...js.matchAll(/@returns \{(\w+)\}\n\s*\*\/\nexport function (\w+)\(/g)]
    .filter((m) => m[1] === name)
    .map((m) => `sl.${m[2]}(…)`);
  return makers.length ? makers.join(", ") : "the library's functions";
}

let intoCount = 0;
for (const c of classes) {
  const original = c.text;
  const ev = takeScratch(c, "__evaluateScratch");
  const der = takeScratch(c, "__derivativeScratch");
  if (ev || der) {
    intoCount += 1;
    const methods = intoMethod(c.name, "evaluate", ev) + intoMethod(c.name, "derivative", der);
    c.text = c.text.replace(/\}\n$/, `${methods}}\n`);
    const dm = new RegExp(`^export class ${c.name} \\{\\n[\\s\\S]*?^\\}\\n`, "m").exec(dts);
    if (!dm) fail(`class ${c.name} missing from the .d.ts`);
    const declarations = intoDeclaration("evaluate", ev) + intoDeclaration("derivative", der);
    dts = dts.replace(dm[0], dm[0].replace(/\}\n$/, `${declarations}}\n`));
  }
  if (/^ {4}__(evaluate|derivative)Scratch\(/m.test(c.text))
    fail(`${c.name}: a scratch method was left`);
  // Freed objects: every call that passes `this.__wbg_ptr` checks it first.
  c.text = replaceCounted(
    c.text,
    /wasm\.(\w+)\(this\.__wbg_ptr\b/g,
    (_, f) => `wasm.${f}(livePtr(this, ${JSON.stringify(c.name)})`,
    undefined,
    `${c.name}: calls with this.__wbg_ptr`,
  );
  // `free()` twice does nothing (the glue would pass pointer 0 to the Rust destructor).
  c.text = replaceCounted(
    c.text,
    / {4}free\(\) \{\n( {8}const ptr = this\.__destroy_into_raw\(\);\n {8})(wasm\.__wbg_\w+_free\(ptr, 0\);)/g,
    (_, destroy, call) =>
      `    free() {\n        checkThis(this, ${JSON.stringify(c.name)});\n${destroy}if (ptr) ${call}`,
    1,
    `${c.name}: free()`,
  );
  // A class the library only returns (no wasm constructor): `new` would make an object with
  // no pointer; it says where such objects come from instead.
  if (!/^ {4}constructor\(/m.test(c.text)) {
    c.text = c.text.replace(
      `export class ${c.name} {\n`,
      `export class ${c.name} {\n` +
        "    constructor() {\n" +
        `        throw codedError(${JSON.stringify(`new ${c.name}() is not available: a ${c.name} comes from ${makersOf(c.name)}`)}, "no-constructor", ${JSON.stringify({ className: c.name, makers: makersOf(c.name) })});\n` +
        "    }\n",
    );
  }
  js = js.replace(original, c.text);
}
if (intoCount < 5) fail(`only ${intoCount} classes have scratch methods`);

// Parameters typed as one of the classes, in functions and methods: checked on entry.
js = replaceCounted(
  js,
  /(\/\*\*\n(?:\s*\*.*\n)*?\s*\*\/\n)(\s*)(export function |static )?(\w+)\(([^)]*)\) \{\n/g,
  (whole, doc, indent, kw, name, params) => {
    const checks = [];
    for (const [, type, param] of doc.matchAll(/@param \{([^}]*)\} \[?(\w+)/g)) {
      const types = type.split("|").map((s) => s.trim());
      if (
        types.some((t) => classNames.has(t)) &&
        types.every((t) => classNames.has(t) || t === "null")
      ) {
        checks.push(`${indent}    liveArg(${param}, ${JSON.stringify(param)});\n`);
      }
    }
    return checks.length ? whole + checks.join("") : whole;
  },
  undefined,
  "documented functions",
);
if (!js.includes('liveArg(curveA, "curveA")') || !js.includes('liveArg(left, "left")')) {
  fail("class-typed parameters (curveA, left) not found");
}

js += `
// ---- added by scripts/glue.mjs (reviewed against wasm-bindgen ${REVIEWED}) ----

/** An Error with \`code\` and \`params\`, like the ones the library throws (src/wasm/error.rs). */
function codedError(message, code, params) {
    const error = new Error(message);
    error.code = code;
    error.params = params;
    return error;
}

// Each class's prototype carries its name as \`__slClass\` (set at the end of this file, inherited
// by subclasses): comparing it with the expected name is one property load that V8 caches per
// call site, where \`instanceof\` with a class passed in halved the per-call rates.

/** Throws unless \`obj\` is of class \`name\` (a method called on another class's object). */
function checkThis(obj, name) {
    if (obj?.__slClass !== name) throw wrongThis(obj, name);
}

/** The Error for a method of class \`name\` run with \`obj\` as \`this\`. */
function wrongThis(obj, name) {
    const got = obj === null || obj === undefined ? String(obj) : (obj.constructor?.name ?? typeof obj);
    return codedError(\`this must be \${name}, got \${got}\`, "argument-type", {
        name: "this",
        expected: name,
        got,
    });
}

/** The pointer of a live object of class \`name\`, or an Error: another class, or freed. */
function livePtr(obj, name) {
    checkThis(obj, name);
    const ptr = obj.__wbg_ptr;
    if (!ptr) throw codedError(\`this \${name} was freed\`, "freed", { className: name });
    return ptr;
}

/** Throws if \`value\` is an object of one of the classes that was freed. */
function liveArg(value, param) {
    if (value !== null && typeof value === "object" && value.__wbg_ptr === 0) {
        const className = value.constructor.name;
        throw codedError(\`\${param}: this \${className} was freed\`, "in-argument", {
            name: param,
            source: { code: "freed", params: { className } },
        });
    }
}

/** The Error for an \`out\` that cannot take \`dim\` numbers. */
function outError(out, dim) {
    const array = Array.isArray(out) || ArrayBuffer.isView(out);
    const got = out === null ? "null" : array ? "array" : typeof out;
    const params = array ? { dim, got, length: out.length } : { dim, got };
    return codedError(\`out must be a Float64Array or number[] of at least dim = \${dim} numbers, got \${array ? \`length \${out.length}\` : got}\`, "out-buffer", params);
}

/** Copies the point the scratch buffer holds at index \`i\` ([dim, x, y, z]) into \`out\`. */
function scratchInto(i, out) {
    const m = getFloat64ArrayMemory0();
    const dim = m[i];
    if (out === null || typeof out !== "object" || !(out.length >= dim)) throw outError(out, dim);
    out[0] = m[i + 1];
    out[1] = m[i + 2];
    if (dim === 3) out[2] = m[i + 3];
    return out;
}

// A Bézier curve's point at t in JavaScript, on a copy of its homogeneous control points kept
// on the object (made at the first call, dropped by setControlPoint, setWeight and free()): a
// call into wasm alone costs ~5 ns, a sixth of what a cubic costs in a JS library, so for
// degree ≤ 7 the per-point path stays in JS, with the core's formula and operation order
// (src/bezier/de_casteljau.rs bernstein_small: Σ P_i · (C(m,i) s^i · (1 − s)^{m−i}) over a
// Pascal table, then the product with 1/w), so it returns the very same numbers as evaluate(t).
const BEZIER_JS_DEGREE = 7;
const PASCAL = [[1]];
for (let m = 1; m <= BEZIER_JS_DEGREE; m++) {
    PASCAL.push(PASCAL[m - 1].map((c, i) => c + (i > 0 ? PASCAL[m - 1][i - 1] : 0)).concat(1));
}
const powersOfR = new Float64Array(BEZIER_JS_DEGREE + 1);

/** The curve's mirror { degree, dim, rational, a, b, h } (h: homogeneous points, dim + 1 each). */
function bezierMirror(curve) {
    const degree = curve.degree;
    if (degree > BEZIER_JS_DEGREE) return (curve.__jsMirror = null);
    const [a, b] = curve.domain();
    const dim = curve.dim;
    const rational = curve.rational;
    const h = curve.homogeneousPoints();
    // The plain planar cubic, the common case, unrolled below: its numbers by name.
    const cubic = degree === 3 && dim === 2 && !rational ? [h[0], h[1], h[3], h[4], h[6], h[7], h[9], h[10]] : null;
    return (curve.__jsMirror = { degree, dim, rational, a, b, h, cubic });
}

{
    const viaWasm = BezierCurve.prototype.evaluateInto;
    BezierCurve.prototype.evaluateInto = function evaluateInto(t, out) {
        // Only a live BezierCurve gets a mirror (checked when it is made) and free() drops it,
        // so a call that finds one needs no check of its own.
        let m = this.__jsMirror;
        if (m === undefined) {
            livePtr(this, "BezierCurve");
            m = bezierMirror(this);
        }
        // Anything unusual (a high degree, t outside, a short out) takes the checked wasm path.
        if (m === null || !(t >= m.a && t <= m.b) || out === null || typeof out !== "object" || !(out.length >= m.dim)) {
            return viaWasm.call(this, t, out);
        }
        const s = m.a === 0 && m.b === 1 ? t : Math.min(Math.max((t - m.a) / (m.b - m.a), 0), 1);
        const q = m.cubic;
        if (q !== null) {
            // bernstein_small for m = 3 written out, the same products in the same order.
            const r = 1 - s;
            const r2 = r * r;
            const s2 = s * s;
            const b0 = 1 * 1 * (r2 * r);
            const b1 = 3 * s * r2;
            const b2 = 3 * s2 * r;
            const b3 = 1 * (s2 * s) * 1;
            out[0] = 0 + q[0] * b0 + q[2] * b1 + q[4] * b2 + q[6] * b3;
            out[1] = 0 + q[1] * b0 + q[3] * b1 + q[5] * b2 + q[7] * b3;
            return out;
        }
        const n = m.degree;
        const r = 1 - s;
        powersOfR[0] = 1;
        for (let k = 1; k <= n; k++) powersOfR[k] = powersOfR[k - 1] * r;
        const binom = PASCAL[n];
        const h = m.h;
        const stride = m.dim + 1;
        let x = 0;
        let y = 0;
        let z = 0;
        let w = 0;
        let sPow = 1;
        for (let i = 0, j = 0; i <= n; i++, j += stride) {
            const basis = binom[i] * sPow * powersOfR[n - i];
            x = x + h[j] * basis;
            y = y + h[j + 1] * basis;
            if (stride === 4) {
                z = z + h[j + 2] * basis;
                w = w + h[j + 3] * basis;
            } else {
                w = w + h[j + 2] * basis;
            }
            sPow *= s;
        }
        if (m.rational) {
            const inverse = 1 / w; // the core multiplies by 1/w (Cartesian::project)
            x *= inverse;
            y *= inverse;
            z *= inverse;
        }
        out[0] = x;
        out[1] = y;
        if (m.dim === 3) out[2] = z;
        return out;
    };
    for (const name of ["setControlPoint", "setWeight", "free"]) {
        const method = BezierCurve.prototype[name];
        BezierCurve.prototype[name] = function (...args) {
            this.__jsMirror = undefined;
            return method.apply(this, args);
        };
    }
    if (Symbol.dispose) BezierCurve.prototype[Symbol.dispose] = BezierCurve.prototype.free;
}

/** Copies \`values\` into \`out\` (the rare path: the scratch call failed but evaluate did not). */
function copyInto(values, out) {
    if (out === null || typeof out !== "object" || !(out.length >= values.length)) {
        throw outError(out, values.length);
    }
    for (let k = 0; k < values.length; k++) out[k] = values[k];
    return out;
}

// The class brands checkThis and livePtr compare (not enumerable, not writable).
${[...classNames].map((name) => `Object.defineProperty(${name}.prototype, "__slClass", { value: ${JSON.stringify(name)} });`).join("\n")}
`;

writeFileSync(jsPath, js);
writeFileSync(dtsPath, dts);
console.log(
  `glue.mjs: ${intoCount} classes with …Into methods, freed-object checks on ${classes.length}`,
);
