// What fills a page's long tasks at load: the tool for finding where issue 26's Total Blocking Time
// goes (Lighthouse gives the total, not the parts). Debian's Chromium loads the page from the built
// site (`make dist`, served by scripts/serve.mjs on 127.0.0.1) on a phone viewport (412 × 823 CSS
// px at DPR 1.75) with the CPU slowed 4× (CDP, as Lighthouse's mobile profile; `--cpu 5.5` for
// another rate), waits 9 s, and prints per run the long tasks the page saw (start and length, ms
// since navigation) and their sum of (length − 50 ms), an observed TBT. The first run of each page
// is also sampled by V8's profiler: the busy stretches of ≥ 45 ms between idle samples (the long
// tasks, as the profiler sees them) with each stretch's functions by self time and the calls that
// led to them, and the self time per file. "(program)" is the browser's own work (parsing, style,
// layout, compiling). Nothing is asserted; the profiler slows the page it samples.
//
//   node bench/long-tasks.mjs "index.html#demo=bezier-patch"        (dist/site, 3 runs)
//   node bench/long-tasks.mjs --runs 1 --root /tmp/site "index.html#demo=de-casteljau"
//
// Names in a minified build are single letters: for readable ones build a site without
// minifying (dist.mjs's esbuild `minify` option set to false) into another folder and pass it
// with --root.
import { chromium } from "playwright-core";
import { startServer } from "../scripts/serve.mjs";
import { CHROMIUM, CHROMIUM_ARGS } from "../scripts/chromium.mjs";

const PORT = 8765;
/** The long-task threshold of the Long Tasks API and of Lighthouse's TBT (ms). */
const LONG_TASK_MS = 50;
/** A profiler stretch this long or longer is listed (ms; sampling blurs the edges). */
const STRETCH_MS = 45;
/** How long each load is watched (ms). */
const WATCH_MS = 9000;
/** Functions listed per stretch. */
const TOP = 8;

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const at = args.indexOf(name);
  if (at < 0) return fallback;
  const [, value] = args.splice(at, 2);
  return value;
};
const runs = Number(option("--runs", "3"));
const root = option("--root", "dist/site");
const cpuText = option("--cpu", "4");
const cpu = Number(cpuText);
if (!(cpu >= 1)) {
  console.error(`--cpu: a slowdown rate of 1 or more, not ${cpuText}`);
  process.exit(2);
}
if (!args.length) {
  console.error(
    'usage: node bench/long-tasks.mjs [--runs N] [--root DIR] [--cpu RATE] "index.html#demo=…" …',
  );
  process.exit(2);
}

const server = await startServer(PORT, "127.0.0.1", root);
const browser = await chromium.launch({ executablePath: CHROMIUM, args: [...CHROMIUM_ARGS] });
try {
  for (const path of args) {
    for (let run = 0; run < runs; run++) {
      const { tasks, profile } = await load(path, run === 0);
      const blocking = tasks.reduce(
        (sum, [, length]) => sum + Math.max(0, length - LONG_TASK_MS),
        0,
      );
      console.log(`${path} run ${run + 1}: observed TBT ${blocking} ms, long tasks [start, ms]:`);
      console.log(`  ${JSON.stringify(tasks)}`);
      if (profile) describe(profile);
    }
  }
} finally {
  await browser.close();
  server.close();
}

/** One load of `path`: its long tasks, and its CPU profile when `profiled`. */
async function load(path, profiled) {
  const context = await browser.newContext({
    viewport: { width: 412, height: 823 },
    deviceScaleFactor: 1.75,
  });
  try {
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send("Emulation.setCPUThrottlingRate", { rate: cpu });
    if (profiled) {
      await cdp.send("Profiler.enable");
      await cdp.send("Profiler.setSamplingInterval", { interval: 200 });
      await cdp.send("Profiler.start");
    }
    await page.addInitScript(() => {
      window.__longTasks = [];
      new PerformanceObserver((list) => {
        for (const e of list.getEntries())
          window.__longTasks.push([Math.round(e.startTime), Math.round(e.duration)]);
      }).observe({ type: "longtask", buffered: true });
    });
    await page.goto(`http://127.0.0.1:${PORT}/${path}`);
    await page.waitForTimeout(WATCH_MS);
    const tasks = await page.evaluate(() => window.__longTasks);
    const profile = profiled ? (await cdp.send("Profiler.stop")).profile : null;
    return { tasks, profile };
  } finally {
    await context.close();
  }
}

/** Prints the profile's busy stretches with their top functions, then the self time per file. */
function describe(profile) {
  const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
  const parent = new Map();
  for (const n of profile.nodes) for (const child of n.children ?? []) parent.set(child, n.id);
  const file = (frame) => frame.url.split("/").pop() || frame.functionName;
  const byFile = new Map();
  const stretches = [];
  let stretch = null;
  let time = profile.startTime;
  profile.samples.forEach((id, k) => {
    const ms = (profile.timeDeltas[k] ?? 0) / 1000;
    time += profile.timeDeltas[k] ?? 0;
    const frame = nodes.get(id).callFrame;
    byFile.set(file(frame), (byFile.get(file(frame)) ?? 0) + ms);
    if (frame.functionName === "(idle)") {
      if (stretch) stretches.push(stretch);
      stretch = null;
      return;
    }
    stretch ??= { start: time, end: time, self: new Map() };
    stretch.end = time;
    // The calls that led here: the three outermost named frames under the root.
    const chain = [];
    for (let n = id; parent.has(n); n = parent.get(n))
      chain.push(nodes.get(n).callFrame.functionName || "(anonymous)");
    const key = `${frame.functionName || "(anonymous)"} ${file(frame)}:${frame.lineNumber + 1} [${chain.slice(-4, -1).reverse().join(" > ")}]`;
    stretch.self.set(key, (stretch.self.get(key) ?? 0) + ms);
  });
  if (stretch) stretches.push(stretch);
  for (const s of stretches) {
    const length = (s.end - s.start) / 1000;
    if (length < STRETCH_MS) continue;
    console.log(
      `  busy from ${((s.start - profile.startTime) / 1000).toFixed(0)} ms for ${length.toFixed(0)} ms:`,
    );
    for (const [key, ms] of [...s.self].sort((a, b) => b[1] - a[1]).slice(0, TOP))
      console.log(`    ${ms.toFixed(1).padStart(6)} ms  ${key.slice(0, 150)}`);
  }
  const files = [...byFile].filter(([name]) => name !== "(idle)").sort((a, b) => b[1] - a[1]);
  console.log(
    `  self time by file: ${files
      .slice(0, 14)
      .map(([n, ms]) => `${n} ${ms.toFixed(0)}`)
      .join(", ")}`,
  );
}
