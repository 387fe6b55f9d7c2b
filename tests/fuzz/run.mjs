// Runs the API fuzzer (fuzz.mjs) in Node against the built www/pkg, in a worker thread watched
// by this one: a call that never returns is reported (seed, call index, how to trace it) instead
// of hanging the run. Prints calls, errors and time; ends with "fuzz: 1 passed, 0 failed" (or
// 0 passed, 1 failed) for scripts/test-all.sh, and exits 1 on any finding, each with the seed
// and a JS reproduction.
//
//   node tests/fuzz/run.mjs [--calls 1000000] [--seed 1] [--slow-ms 2000] [--hang-s 60]
//                           [--trace-from K]   (log every call from index K on, before it runs)
//                           [--budgets warn]   (slow calls are printed but do not fail the run:
//                                               make test, where timing is not asserted)
//                           [--no-freed]       (never call or pass a freed object: each such call
//                                               leaks wasm shadow stack until percall's fix, and
//                                               ~22 000 of them make the module trap)
//                           [--freed-soak N]   (end with N calls on a freed curve, then the sanity
//                                               call: make fuzz uses 100 000)
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { Worker, isMainThread, parentPort, workerData } from "node:worker_threads";

const here = (p) => fileURLToPath(new URL(p, import.meta.url));
const PKG = here("../../www/pkg/");

if (isMainThread) await main();
else await work(workerData);

function options() {
  const args = process.argv.slice(2);
  const get = (name, fallback) => {
    const i = args.indexOf(`--${name}`);
    return i >= 0 ? Number(args[i + 1]) : fallback;
  };
  const budgets = args.indexOf("--budgets");
  return {
    calls: get("calls", 1_000_000),
    seed: get("seed", 1),
    slowMs: get("slow-ms", 2000),
    hangS: get("hang-s", 60),
    traceFrom: get("trace-from", Infinity),
    budgetsFail: budgets < 0 || args[budgets + 1] !== "warn",
    useFreed: !args.includes("--no-freed"),
    freedSoak: get("freed-soak", 0),
  };
}

async function main() {
  const opts = options();
  const progress = new Int32Array(new SharedArrayBuffer(4));
  progress[0] = -1;
  console.log(
    `fuzz: ${opts.calls} calls, seed ${opts.seed}, a call over ${opts.slowMs} ms is a budget finding`,
  );
  const worker = new Worker(fileURLToPath(import.meta.url), {
    workerData: { ...opts, progress },
    resourceLimits: { maxOldGenerationSizeMb: 2048 },
  });
  /** Findings as they happen: a hang ends the worker before it can report them. */
  const early = [];
  let lastIndex = -1;
  let lastChange = Date.now();
  let lastPrint = Date.now();
  const result = await new Promise((resolve) => {
    const watchdog = setInterval(() => {
      const now = Atomics.load(progress, 0);
      // -1 until the first call: loading the module is not a call.
      if (now !== lastIndex || now < 0) {
        lastIndex = now;
        lastChange = Date.now();
      } else if (Date.now() - lastChange > opts.hangS * 1000) {
        clearInterval(watchdog);
        worker.terminate();
        resolve({ hang: now });
      }
    }, 250);
    worker.on("message", (m) => {
      if (m.type === "batch" && Date.now() - lastPrint > 10_000) {
        lastPrint = Date.now();
        console.log(`  ${m.calls} calls, ${m.errors} errors, ${(m.ms / 1000).toFixed(1)} s`);
      } else if (m.type === "log") console.log(m.text);
      else if (m.type === "finding") early.push(m.finding);
      else if (m.type === "done") {
        clearInterval(watchdog);
        resolve(m.result);
      }
    });
    worker.on("error", (e) => {
      clearInterval(watchdog);
      resolve({ crash: String(e?.stack ?? e) });
    });
  });
  let failed = false;
  const printFindings = (findings) => {
    for (const f of findings) {
      const counts = f.kind !== "budget" || opts.budgetsFail;
      failed ||= counts;
      console.log(
        `${counts ? "FAIL" : "WARN"} ${f.kind}: ${f.callable} at call #${f.call} (seed ${opts.seed}; ${f.times} such): ${f.detail}`,
      );
      if (f.repro) console.log(`  reproduce:\n    ${f.repro.split("\n").join("\n    ")}`);
    }
  };
  if (result.hang !== undefined || result.crash) printFindings(early);
  if (result.hang !== undefined) {
    failed = true;
    console.log(
      `FAIL call #${result.hang} (seed ${opts.seed}) ran over ${opts.hangS} s: see it with\n` +
        `  node tests/fuzz/run.mjs --seed ${opts.seed} --calls ${result.hang + 1} --trace-from ${result.hang}` +
        (opts.useFreed ? "" : " --no-freed"),
    );
  } else if (result.crash) {
    failed = true;
    console.log(`FAIL the fuzz worker crashed (seed ${opts.seed}): ${result.crash}`);
  } else {
    const { calls, errors, ms, findings, coverage, memoryBytes } = result;
    console.log(
      `fuzz: ${calls} calls (${coverage.callables} callables), ${errors} threw an Error, ` +
        `${(ms / 1000).toFixed(1)} s, wasm memory ${(memoryBytes / 2 ** 20).toFixed(0)} MB`,
    );
    console.log(`  most time: ${coverage.slowest.join(", ")}`);
    if (coverage.untyped.length)
      console.log(
        `  not in the .d.ts, called with untyped arguments: ${coverage.untyped.join(" ")}`,
      );
    if (coverage.neverOk.length)
      console.log(
        `  never returned normally (arguments too hostile?): ${coverage.neverOk.join(" ")}`,
      );
    if (coverage.neverCalled.length) {
      failed = true;
      console.log(`FAIL not covered (never called): ${coverage.neverCalled.join(" ")}`);
    }
    printFindings(findings);
  }
  console.log(`fuzz: ${failed ? 0 : 1} passed, ${failed ? 1 : 0} failed`);
  process.exit(failed ? 1 : 0);
}

async function work({ calls, seed, slowMs, traceFrom, progress, useFreed, freedSoak }) {
  const { fuzzApi } = await import("./fuzz.mjs");
  const { default: init, ...mod } = await import(`${PKG}splinelab.js`);
  const exports = await init({ module_or_path: readFileSync(`${PKG}splinelab_bg.wasm`) });
  const dts = readFileSync(`${PKG}splinelab.d.ts`, "utf8");
  const result = fuzzApi({
    mod,
    dts,
    memory: exports.memory,
    seed,
    calls,
    slowMs,
    traceFrom,
    progress,
    useFreed,
    freedSoak,
    log: (text) => parentPort.postMessage({ type: "log", text }),
    onBatch: (m) => parentPort.postMessage({ type: "batch", ...m }),
    onFinding: (finding) => parentPort.postMessage({ type: "finding", finding }),
  });
  parentPort.postMessage({ type: "done", result });
}
