// Seeded random-call fuzzing of the whole exported JS API (api.mjs enumerates it): a pool of
// live objects made by the constructors, statics and functions (well-formed arguments most of
// the time, so calls go deep), on which random methods and getters are called with arguments
// from values.mjs; results that are objects join the pool, objects get freed and stay in reach.
// Every call either returns or throws a plain `Error` with a non-empty message: never a
// WebAssembly.RuntimeError (a Rust panic or a bad memory access), never a TypeError or
// RangeError from the glue. Every `batch` calls a sanity call checks the module still works.
// Environment-agnostic (Node runner: run.mjs); the caller passes the initialised module.

import { enumerateApi } from "./api.mjs";
import { argument, random, shape, values } from "./values.mjs";

/** What a call on a freed object (or with one as argument) must say: the glue names the class. */
export const FREED_MESSAGE = /was freed/;

/** Live objects kept for method calls; past this the oldest is freed. */
const POOL = 24;
/** Freed objects kept in reach, to call methods on and pass as arguments. */
const FREED = 8;

/** How a thrown value breaks the contract, or null when it is a plain Error with a message. */
export function verdict(e, freed) {
  if (e instanceof WebAssembly.RuntimeError) return `trap (WebAssembly.RuntimeError)`;
  if (!(e instanceof Error)) return `threw a non-Error (${typeof e})`;
  if (e.constructor !== Error) return `threw a ${e.constructor.name}, not a plain Error`;
  if (typeof e.message !== "string" || e.message.trim() === "") return "an Error without message";
  if (freed && !FREED_MESSAGE.test(e.message))
    return `freed-object message ${JSON.stringify(e.message)}`;
  return null;
}

/** JS source for `value` (numbers keep NaN, ±Infinity and -0; pool objects by name). */
function source(value, names) {
  if (names.has(value)) return names.get(value);
  if (value === undefined) return "undefined";
  if (typeof value === "number") return Object.is(value, -0) ? "-0" : String(value);
  if (typeof value === "string") return JSON.stringify(value);
  if (typeof value === "function") return String(value);
  if (value instanceof Date) return `new Date(${value.getTime()})`;
  if (ArrayBuffer.isView(value)) {
    const items = Array.from(value);
    const same = items.length > 64 && items.every((x) => Object.is(x, items[0]));
    return same
      ? `new ${value.constructor.name}(${items.length}).fill(${source(items[0], names)})`
      : `new ${value.constructor.name}([${items.map((x) => source(x, names)).join(", ")}])`;
  }
  if (Array.isArray(value)) return `[${value.map((x) => source(x, names)).join(", ")}]`;
  if (value && typeof value === "object") {
    const ctor = value.constructor?.name;
    if (ctor && ctor !== "Object") return `new sl.${ctor}() /* no pointer */`;
    return `{ ${Object.entries(value)
      .map(([k, x]) => `${k}: ${source(x, names)}`)
      .join(", ")} }`;
  }
  return String(value);
}

/**
 * Runs `calls` fuzzed calls. Returns { calls, errors, findings, coverage, ms, memoryBytes }.
 * `progress` (optional Int32Array over a SharedArrayBuffer) receives the index of the call in
 * flight, for a watchdog in another thread; from call `traceFrom` on each call is logged first.
 * `useFreed: false` never calls a freed object nor passes one (to look past the freed-object
 * shadow-stack leak, see run.mjs); `freedSoak` > 0 ends with that many calls on a freed curve.
 */
export function fuzzApi({
  mod,
  dts,
  memory,
  seed,
  calls,
  slowMs = 2000,
  batch = 1000,
  traceFrom = Infinity,
  progress = null,
  useFreed = true,
  freedSoak = 0,
  log = () => {},
  onBatch = () => {},
  onFinding = () => {},
}) {
  const r = random(seed);
  const { int, pick, chance } = r;
  const api = enumerateApi(mod, dts);
  const strings = [...new Set(dts.match(/"[A-Za-z][A-Za-z0-9-]{0,15}"/g) ?? [])].map((s) =>
    s.slice(1, -1),
  );
  const classes = new Set(api.filter((c) => c.kind === "constructor").map((c) => c.cls));
  const creators = api.filter((c) => ["constructor", "static", "function"].includes(c.kind));
  const members = new Map();
  for (const c of api.filter((c) => c.kind === "method" || c.kind === "getter")) {
    if (!members.has(c.cls)) members.set(c.cls, []);
    members.get(c.cls).push(c);
  }
  const stats = new Map(api.map((c) => [c.key, { called: 0, ok: 0, ms: 0 }]));

  /** Pool entries: { id, obj, cls, freed, dim, domain, domainV, events: [{ seq, refs, text }] }. */
  let live = [];
  const freed = [];
  const entryOf = new Map();
  let nextId = 0;
  let seq = 0;
  const objects = () => (chance(0.9) || !freed.length || !useFreed ? live : [...live, ...freed]);
  const classObjects = (names) => {
    const pool = chance(0.95) || !useFreed ? live : freed;
    return pool.filter((e) => names.includes(e.cls));
  };
  const v = values(r, strings, () => objects());

  const findings = [];
  const seen = new Map();
  let index = 0;
  let errors = 0;

  /** Entries referenced by `values` (pool objects among them). */
  const refsOf = (args) => args.map((a) => entryOf.get(a)).filter(Boolean);

  /** A self-contained JS reproduction of call `call` with receiver `target` and `args`. */
  function reproduction(target, callText, args) {
    const needed = new Set([...(target ? [target] : []), ...refsOf(args)]);
    for (let grew = true; grew; ) {
      grew = false;
      for (const e of [...needed])
        for (const ev of e.events)
          for (const ref of ev.refs)
            if (!needed.has(ref)) {
              needed.add(ref);
              grew = true;
            }
    }
    const names = new Map([...entryOf.entries()].map(([obj, e]) => [obj, `o${e.id}`]));
    const lines = [...needed]
      .flatMap((e) => e.events)
      .sort((a, b) => a.seq - b.seq)
      .map((ev) => ev.text(names));
    return [...new Set(lines), callText(names)].join("\n");
  }

  function describeCall(c, target, args, foreign) {
    if (foreign) {
      const proto = `sl.${c.cls}.prototype`;
      return (names) =>
        c.kind === "getter"
          ? `Object.getOwnPropertyDescriptor(${proto}, "${c.name}").get.call(${names.get(target.obj)});`
          : `${proto}.${c.name}.call(${[target.obj, ...args].map((a) => source(a, names)).join(", ")});`;
    }
    const callee =
      c.kind === "function"
        ? `sl.${c.name}`
        : c.kind === "constructor"
          ? `new sl.${c.cls}`
          : c.kind === "static"
            ? `sl.${c.cls}.${c.name}`
            : null;
    return (names) =>
      c.kind === "getter"
        ? `${names.get(target.obj)}.${c.name};`
        : `${callee ?? `${names.get(target.obj)}.${c.name}`}(${args.map((a) => source(a, names)).join(", ")});`;
  }

  function report(kind, c, target, args, detail) {
    // One report per callable and kind of failure (numbers in the message do not count).
    const key = `${kind}|${c.key}|${detail.replace(/[-\d.e+]+/g, "#").slice(0, 80)}`;
    const earlier = seen.get(key);
    if (earlier) {
      earlier.times++;
      return;
    }
    const finding = {
      kind,
      callable: c.key,
      call: index,
      detail,
      repro: reproduction(target, describeCall(c, target, args), args),
      times: 1,
    };
    seen.set(key, finding);
    findings.push(finding);
    onFinding(finding);
  }

  /** Adds an exported-class instance to the pool, probing its dim and domain. */
  function adopt(obj, event) {
    const cls = obj?.constructor?.name;
    if (!classes.has(cls) || entryOf.has(obj)) return;
    const entry = { id: nextId++, obj, cls, freed: false, events: [] };
    entry.events.push({ ...event, seq: seq++ });
    entryOf.set(obj, entry);
    const probe = (f) => {
      try {
        return f();
      } catch (e) {
        const bad = verdict(e, false);
        if (bad) throw new Error(`probing a new ${cls}: ${bad}: ${e}`);
        return undefined;
      }
    };
    entry.dim = probe(() => obj.dim);
    const domain = probe(() => (obj.domain ?? obj.domainU)?.call(obj));
    entry.domain = domain && domain.length === 2 ? Array.from(domain) : undefined;
    const domainV = probe(() => obj.domainV?.call(obj));
    entry.domainV = domainV && domainV.length === 2 ? Array.from(domainV) : undefined;
    entry.rows = probe(() => obj.rows);
    entry.cols = probe(() => obj.cols);
    if (entry.rows !== undefined) entry.dim = 3;
    const points = probe(() => (obj.controlPoints ?? obj.points)?.call(obj));
    if (points && entry.dim) entry.count = points.length / entry.dim;
    entry.freed = typeof obj.__wbg_ptr !== "number" || obj.__wbg_ptr === 0;
    (entry.freed ? freed : live).push(entry);
    if (live.length > POOL) release(live[int(0, live.length - 1)]);
    if (freed.length > FREED) freed.shift();
  }

  function release(entry) {
    try {
      entry.obj.free();
    } catch {}
    entry.freed = true;
    entry.events.push({ seq: seq++, refs: [], text: (names) => `${names.get(entry.obj)}.free();` });
    live = live.filter((e) => e !== entry);
    freed.push(entry);
    if (freed.length > FREED) freed.shift();
  }

  function handleResult(result, c, target, args, text) {
    const refs = [...(target ? [target] : []), ...refsOf(args)];
    if (result && typeof result === "object" && classes.has(result.constructor?.name)) {
      adopt(result, { refs, text: (names) => `const ${names.get(result)} = ${text(names)}` });
    } else if (
      Array.isArray(result) &&
      result.length &&
      classes.has(result[0]?.constructor?.name)
    ) {
      const keep = int(0, result.length - 1);
      result.forEach((item, i) => {
        if (i !== keep || !chance(0.6)) {
          try {
            item.free();
          } catch {}
          return;
        }
        adopt(item, {
          refs,
          text: (names) => `const ${names.get(item)} = ${text(names).slice(0, -1)}[${i}];`,
        });
      });
    } else if (result === undefined && target && c.kind === "method") {
      // A setter or free(): part of the receiver's history.
      if (c.name === "free") {
        target.freed = true;
        live = live.filter((e) => e !== target);
        if (!freed.includes(target)) freed.push(target);
      }
      target.events.push({ seq: seq++, refs, text });
    }
  }

  /**
   * One fuzzed call of `c` (on `target` for methods and getters). `foreign`: `c` is a method of
   * another class than `target`'s, run with `target` as `this`; it must throw.
   */
  function call(c, target, foreign = false) {
    // A function taking curves sizes its other arguments after the first one it gets.
    const first = c.params.find((p) => p.type.some((t) => t.kind === "class"));
    let chosen;
    if (!target && first) {
      const names = first.type.filter((t) => t.kind === "class").map((t) => t.name);
      const same = classObjects(names);
      if (same.length) chosen = pick(same);
    }
    const s = shape(r, target ?? chosen);
    if (chosen) s.chosen = { [first.name]: chosen.obj };
    const args =
      c.kind === "getter" ? [] : c.params.map((p) => argument(r, v, p, s, classObjects, strings));
    // Drop trailing arguments now and then (optional ones, or a forgotten one).
    if (args.length && chance(0.05)) args.length = int(0, args.length - 1);
    const text = describeCall(c, target, args, foreign);
    if (index >= traceFrom) log(`#${index}:\n${reproduction(target, text, args)}`);
    // A method on a freed object must say so; a freed argument may meet another check first
    // (a number expected where it stands), so only `this` is held to the message.
    const usesFreed = !foreign && (target?.freed ?? false);
    const stat = stats.get(c.key);
    stat.called++;
    if (progress) Atomics.store(progress, 0, index);
    const start = performance.now();
    let result;
    let threw = false;
    try {
      if (foreign) result = callAs(c, target.obj, args);
      else if (c.kind === "function") result = mod[c.name](...args);
      else if (c.kind === "constructor") result = new mod[c.cls](...args);
      else if (c.kind === "static") result = mod[c.cls][c.name](...args);
      else if (c.kind === "getter") result = target.obj[c.name];
      else result = target.obj[c.name](...args);
    } catch (e) {
      threw = true;
      errors++;
      const bad = verdict(e, usesFreed);
      if (bad)
        report("contract", c, target, args, `${bad}: ${String(e?.message ?? e).slice(0, 300)}`);
      if (e instanceof WebAssembly.RuntimeError) throw new Stop();
    }
    const ms = performance.now() - start;
    stat.ms += ms;
    if (ms > slowMs)
      report("budget", c, target, args, `${Math.round(ms)} ms (budget ${slowMs} ms)`);
    index++;
    if (foreign && !threw)
      report("contract", c, target, args, "returned with an object of another class as this");
    if (threw || foreign) return;
    stat.ok++;
    handleResult(result, c, target, args, text);
  }

  /** `c` of its own class run with `obj` (of another class) as `this`. */
  function callAs(c, obj, args) {
    const proto = mod[c.cls].prototype;
    if (c.kind === "getter") return Object.getOwnPropertyDescriptor(proto, c.name).get.call(obj);
    return proto[c.name].call(obj, ...args);
  }

  class Stop extends Error {}

  function sanity(after = "") {
    let got;
    try {
      const probe = new mod.BezierCurve([0, 0, 1, 1], 2);
      got = Array.from(probe.evaluate(0.5)).join(",");
      probe.free();
    } catch (e) {
      got = String(e);
    }
    if (got !== "0.5,0.5") {
      findings.push({
        kind: "broken",
        callable: "sanity",
        call: index,
        detail: `the module stopped working${after}: ${got}`,
        repro: "",
        times: 1,
      });
      throw new Stop();
    }
  }

  /**
   * `freedSoak` calls of methods on freed objects in a row, then the sanity call: each such
   * call must leave the module as it was (wasm-bindgen's "null pointer passed to rust" is thrown
   * from inside the Rust frame, which never pops its shadow stack: ~22 000 of them trapped).
   */
  function soakFreed() {
    if (!freedSoak) return;
    const bezier = new mod.BezierCurve([0, 0, 1, 1, 2, 0], 2);
    adopt(bezier, {
      refs: [],
      text: (names) => `const ${names.get(bezier)} = new sl.BezierCurve([0, 0, 1, 1, 2, 0], 2);`,
    });
    release(entryOf.get(bezier));
    const dead = entryOf.get(bezier);
    const methods = (members.get("BezierCurve") ?? []).filter((c) => c.name !== "free");
    for (let k = 0; k < freedSoak; k++) call(pick(methods), dead);
    sanity(` after ${freedSoak} calls on a freed BezierCurve`);
  }

  const started = performance.now();
  try {
    while (index < calls) {
      const end = Math.min(calls, index + batch);
      while (index < end) {
        if (live.length < 4 || chance(0.3)) {
          call(pick(creators), null);
          continue;
        }
        const target = chance(0.04) && freed.length && useFreed ? pick(freed) : pick(live);
        // Now and then a method of another class runs on the object
        // (`sl.Other.prototype.m.call(obj, …)`): it must throw and leave the object as it was.
        if (chance(0.01)) {
          const others = [...members.keys()].filter((k) => k !== target.cls);
          const methods = others.length ? (members.get(pick(others)) ?? []) : [];
          if (methods.length) {
            call(pick(methods), target, true);
            continue;
          }
        }
        const list = members.get(target.cls) ?? [];
        if (!list.length) {
          index++;
          continue;
        }
        call(pick(list), target);
      }
      sanity();
      onBatch({ calls: index, errors, findings: findings.length, ms: performance.now() - started });
    }
    soakFreed();
  } catch (e) {
    if (!(e instanceof Stop)) throw e;
  }
  for (const e of live) {
    try {
      e.obj.free();
    } catch {}
  }
  const coverage = {
    callables: api.length,
    untyped: api.filter((c) => !c.typed).map((c) => c.key),
    neverCalled: [...stats].filter(([, s]) => s.called === 0).map(([k]) => k),
    neverOk: [...stats].filter(([, s]) => s.ok === 0).map(([k]) => k),
    slowest: [...stats]
      .sort((a, b) => b[1].ms - a[1].ms)
      .slice(0, 5)
      .map(([k, s]) => `${k} ${(s.ms / 1000).toFixed(1)} s / ${s.called}`),
  };
  return {
    calls: index,
    errors,
    findings,
    coverage,
    ms: performance.now() - started,
    memoryBytes: memory?.buffer.byteLength,
  };
}
