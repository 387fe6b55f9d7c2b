// The npm package as a JS developer meets it (run by `make test`): builds
// dist/splinelab-<version>.tgz, installs it into an empty temporary project, then
//   1. runs the README's "Use from npm" Node example there and compares what it prints with
//      the output the README shows under it;
//   2. type-checks a TypeScript file that uses the package with `tsc --strict`;
//   3. serves that project and opens the README's plain `<script type="module">` page in
//      Chromium: the import map resolves, the curve evaluates, `<spline-lab>` draws, no
//      console error.
// Ends with one line "package: N passed, N failed" (scripts/test-all.sh sums it).
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { CHROMIUM, CHROMIUM_ARGS } from "../../scripts/chromium.mjs";
import { build } from "../../scripts/package.mjs";
import { startServer } from "../../scripts/serve.mjs";

const root = fileURLToPath(new URL("../..", import.meta.url));
const readme = readFileSync(`${root}README.md`, "utf8");
const section = readme.split(/^(?=## )/m).find((s) => s.startsWith("## Use from npm\n"));
if (!section) throw new Error('README has no "## Use from npm" section');
/** The n-th fenced block of `lang` in the section. */
function fenced(lang, n = 0) {
  const blocks = [...section.matchAll(new RegExp(`^\`\`\`${lang}\\n([\\s\\S]*?)^\`\`\`$`, "gm"))];
  if (!blocks[n]) throw new Error(`README "Use from npm" lacks \`\`\`${lang} block ${n}`);
  return blocks[n][1];
}

/** A user's TypeScript: typed calls, and one wrong argument that must stay an error. */
const TYPESCRIPT = `import init, { BezierCurve, BSplineCurve, knotVector, type InitOutput } from "splinelab";
import "splinelab/element";

declare const bytes: Uint8Array;
const output: InitOutput = await init({ module_or_path: bytes });
const curve = new BezierCurve(new Float64Array([0, 0, 2, 2, 6, 4, 8, 2]), 2);
const point: Float64Array = curve.evaluate(0.25);
const degree: number = curve.degree;
const knots: Float64Array = knotVector([0, 0, 1, 2, 3, 3, 5, 1, 6, 3, 8, 0], 2, 2, "clamped");
const spline = new BSplineCurve([0, 0, 1, 2, 3, 3, 5, 1, 6, 3, 8, 0], 2, 2, knots);
const [left, right]: BezierCurve[] = curve.split(0.5);
const element: HTMLElementTagNameMap["spline-lab"] = document.createElement("spline-lab");
// @ts-expect-error evaluate takes a number, not a string
curve.evaluate("0.25");
export const used = [output, point, degree, spline.domain(), left, right, element];
`;
const TSCONFIG = {
  compilerOptions: {
    strict: true,
    noEmit: true,
    target: "es2022",
    module: "nodenext",
    moduleResolution: "nodenext",
    lib: ["es2022", "dom", "esnext.disposable"],
    types: [],
  },
  files: ["use.ts"],
};

const results = [];
async function check(name, body) {
  try {
    await body();
    results.push([name, null]);
    console.log(`ok   ${name}`);
  } catch (err) {
    results.push([name, err]);
    console.log(`FAIL ${name}\n     ${String(err.stack ?? err).replaceAll("\n", "\n     ")}`);
  }
}

const tarball = build();
console.log(`package: ${tarball}`);
const project = mkdtempSync(join(tmpdir(), "splinelab-package-"));
const run = (cmd, args) => execFileSync(cmd, args, { cwd: project, encoding: "utf8" });
try {
  writeFileSync(
    join(project, "package.json"),
    JSON.stringify({ name: "package-check", private: true, type: "module" }),
  );
  run("npm", ["install", "--no-audit", "--no-fund", "--prefer-offline", tarball]);

  await check("README's Node example prints what the README says", () => {
    writeFileSync(join(project, "quick.mjs"), fenced("js"));
    const printed = run(process.execPath, ["quick.mjs"]).trim();
    const expected = fenced("text").trim();
    if (printed !== expected) throw new Error(`printed\n${printed}\nexpected\n${expected}`);
  });

  await check("tsc --strict accepts typed use and rejects a wrong argument", () => {
    writeFileSync(join(project, "use.ts"), TYPESCRIPT);
    writeFileSync(join(project, "tsconfig.json"), JSON.stringify(TSCONFIG));
    const tsc = `${root}node_modules/typescript/bin/tsc`;
    try {
      run(process.execPath, [tsc, "-p", ".", "--strict"]);
    } catch (err) {
      throw new Error(`tsc --strict failed:\n${err.stdout}${err.stderr}`);
    }
  });

  await check("a plain <script type=module> page: import map, API and <spline-lab>", async () => {
    writeFileSync(join(project, "index.html"), pageHtml(fenced("html")));
    const server = await startServer(0, "127.0.0.1", project);
    const profile = mkdtempSync(join(tmpdir(), "splinelab-package-chromium-"));
    const context = await chromium.launchPersistentContext(profile, {
      executablePath: CHROMIUM,
      args: [...CHROMIUM_ARGS],
    });
    try {
      const page = await context.newPage();
      const errors = [];
      const logs = [];
      page.on("console", (m) => (m.type() === "error" ? errors : logs).push(m.text()));
      page.on("pageerror", (e) => errors.push(String(e)));
      await page.goto(`http://127.0.0.1:${server.address().port}/index.html`);
      await page.waitForFunction(
        () => document.querySelector("spline-lab")?.shadowRoot?.querySelector("canvas"),
        null,
        { timeout: 30_000 },
      );
      await page.waitForFunction(() => window.__logged, null, { timeout: 10_000 });
      const logged = await page.evaluate(() => window.__logged);
      if (logged !== "1.8125,1.4375") throw new Error(`the module logged ${logged}`);
      if (errors.length > 0) throw new Error(`console errors: ${errors.join(" | ")}`);
    } finally {
      await context.close();
      server.close();
      rmSync(profile, { recursive: true, force: true });
    }
  });
} finally {
  rmSync(project, { recursive: true, force: true });
}

const failed = results.filter(([, err]) => err).length;
console.log(`package: ${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);

/** The README's page, with a favicon (a 404 is a console error) and its log kept for the check. */
function pageHtml(body) {
  const logged = body.replace(
    "console.log(new sl.BezierCurve",
    "window.__logged = String(new sl.BezierCurve",
  );
  if (logged === body) throw new Error("the README page no longer logs the curve's point");
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,">
<title>package check</title></head><body>\n${logged}</body></html>\n`;
}
