// axe-core (pinned in package.json) on every page of the playground, once per `make test`: the
// gallery, every demo (www/demos/index.js), every lecture (www/lectures/index.js, its first
// scene), every exercise (www/exercises/index.js), the embed example, and one Greek page. Each
// page is checked against WCAG 2.0/2.1/2.2 A and AA and axe's best practices; any violation
// fails the test, listed as its rule id and the selectors of the nodes it found.
//
// The pages' CSP (script-src 'self') blocks an injected inline <script>, so axe's source is
// evaluated through the DevTools protocol (page.evaluate), which the CSP does not govern.
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";

const AXE_SOURCE = readFileSync(
  createRequire(import.meta.url).resolve("axe-core/axe.min.js"),
  "utf8",
);
/** The rule sets every page must pass. */
const TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa", "best-practice"];

/**
 * Runs axe on the page as it is (after loading axe's source into it, once per document) and
 * returns its violations as lines: "rule-id (impact): selector, selector, …".
 */
async function violations(page) {
  if (!(await page.evaluate(() => typeof window.axe === "object")))
    await page.evaluate(`${AXE_SOURCE}\n;void 0`);
  const found = await page.evaluate(
    async (tags) =>
      (await window.axe.run(document, { runOnly: { type: "tag", values: tags } })).violations.map(
        (v) => ({
          id: v.id,
          impact: v.impact,
          targets: v.nodes.map((n) => n.target.map(String).join(" >> ")),
          summary: v.nodes[0]?.failureSummary?.split("\n").slice(1, 2).join("").trim(),
        }),
      ),
    TAGS,
  );
  return found.map(
    (v) =>
      `${v.id} (${v.impact}, ${v.targets.length} node${v.targets.length === 1 ? "" : "s"}): ${v.targets.slice(0, 6).join(", ")}${v.targets.length > 6 ? ", …" : ""}${v.summary ? ` — ${v.summary}` : ""}`,
  );
}

/**
 * Registers the axe tests with run.mjs's `test` (each named "axe: …", so the filter "axe" picks
 * them all). `tools`: { test, assert, context, base, registry, demoHelpers, settle }.
 * One page of the run's browser context is reused for every page checked.
 */
export async function axeSuite({ test, assert, context, base, registry, demoHelpers, settle }) {
  let page = null;
  const open = async (path) => {
    page ??= await context.newPage();
    await page.goto("about:blank");
    await page.goto(`${base}/${path}`);
  };
  const check = async (what) => {
    await settle(page);
    const found = await violations(page);
    // Every violation on its own line (the runner shows only the head of a failure's message).
    for (const line of found) console.log(`     axe ${what}: ${line}`);
    assert(found.length === 0, `${what}: ${found.length} axe violation(s), listed above`);
  };
  const { lectures, exercises } = await (async () => {
    page ??= await context.newPage();
    await page.goto(`${base}/index.html`);
    return page.evaluate(async () => ({
      lectures: (await import("./lectures/index.js")).lectures.map((l) => l.id),
      exercises: (await import("./exercises/index.js")).exercises.map((e) => e.id),
    }));
  })();

  try {
    await test("axe: the gallery", async () => {
      await open("index.html");
      await page.locator("a.card").first().waitFor();
      await check("gallery");
    });

    for (const { id } of registry) {
      await test(`axe: demo ${id}`, async () => {
        await open(`index.html#demo=${id}`);
        await demoHelpers(page).ready();
        await check(id);
      });
    }

    for (const id of lectures) {
      await test(`axe: lecture ${id}`, async () => {
        await open(`index.html#lecture=${id}`);
        await demoHelpers(page).ready();
        await check(`lecture ${id}`);
      });
    }

    for (const id of exercises) {
      await test(`axe: exercise ${id}`, async () => {
        await open(`index.html#exercise=${id}`);
        await demoHelpers(page).ready();
        await check(`exercise ${id}`);
      });
    }

    await test("axe: the embed example", async () => {
      await open("embed-example.html");
      for (const id of ["worked", "quadratic"]) {
        await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
        await demoHelpers(page, `spline-lab#${id} `).ready();
      }
      await check("embed example");
    });

    await test("axe: the embed example and a demo at phone width (390 px: tables and formulas scroll)", async () => {
      const size = page.viewportSize();
      await page.setViewportSize({ width: 390, height: 844 });
      try {
        await open("embed-example.html");
        for (const id of ["worked", "quadratic"]) {
          await page.locator(`spline-lab#${id}`).scrollIntoViewIfNeeded();
          await demoHelpers(page, `spline-lab#${id} `).ready();
        }
        await check("embed example (phone)");
        await open("index.html#demo=bspline-interpolation");
        await demoHelpers(page).ready();
        await check("bspline-interpolation (phone)");
      } finally {
        await page.setViewportSize(size);
      }
    });

    await test("axe: a Greek demo page (?lang=el)", async () => {
      await open("index.html?lang=el#demo=de-boor");
      await demoHelpers(page).ready();
      await check("de-boor in Greek");
    });

    await test("axe: error messages, light and dark (a bad link; negative weights in dark)", async () => {
      try {
        for (const scheme of ["light", "dark"]) {
          await page.emulateMedia({ colorScheme: scheme });
          await open("index.html#demo=de-casteljau&s=not-a-state");
          await demoHelpers(page).ready();
          assert(
            (await page.locator(".sl-status").getAttribute("data-kind")) === "error",
            "the bad link is reported",
          );
          await check(`a bad link (${scheme})`);
        }
        await open("index.html#demo=negative-weights");
        await demoHelpers(page).ready();
        await check("negative-weights (dark)");
      } finally {
        await page.emulateMedia({ colorScheme: "light" });
      }
    });

    await test("axe: an unsolved exercise's result and its hint, dark and light", async () => {
      try {
        // An exercise checked before it is solved: its "not yet" line and the hint, in both schemes.
        for (const scheme of ["dark", "light"]) {
          await page.emulateMedia({ colorScheme: scheme });
          await open("index.html#exercise=close-the-gap");
          await demoHelpers(page).ready();
          await page.locator('[data-action="exercise-check"]').click();
          await page.locator('[data-action="exercise-hint"]').click();
          await page.locator(".sl-exercise-result:not(:empty)").waitFor();
          assert(
            (await page.locator(".sl-exercise-result").getAttribute("data-kind")) === "not-yet",
            "the starting state is not a solution",
          );
          await check(`an exercise's result (${scheme})`);
        }
      } finally {
        await page.emulateMedia({ colorScheme: "light" });
      }
    });

    await test("axe: a box that scrolls is a named tab stop while its content overflows, and only then", async () => {
      await open("index.html");
      const seen = await page.evaluate(async () => {
        const { scrollRegion } = await import("./lib/scroll-region.js");
        const frames = () =>
          new Promise((ok) => requestAnimationFrame(() => requestAnimationFrame(ok)));
        const title = Object.assign(document.createElement("p"), { id: "wide-title" });
        const box = document.createElement("div");
        box.style.cssText = "width: 200px; overflow-x: auto";
        const content = document.createElement("div");
        content.style.cssText = "width: 600px; height: 20px";
        box.append(content);
        document.body.append(title, box);
        scrollRegion(box, { labelledBy: title.id }, [content]);
        const attributes = () =>
          ["tabindex", "role", "aria-labelledby"].map((a) => box.getAttribute(a)).join(" ");
        await frames();
        const wide = attributes();
        content.style.width = "100px"; // now it fits
        await frames();
        const narrow = attributes();
        content.style.width = "300px"; // too wide again
        await frames();
        const again = attributes();
        box.remove();
        title.remove();
        return { wide, narrow, again };
      });
      assert(seen.wide === "0 group wide-title", `overflowing: ${seen.wide}`);
      assert(seen.narrow === "  ", `fitting: ${JSON.stringify(seen.narrow)}`);
      assert(seen.again === "0 group wide-title", `overflowing again: ${seen.again}`);
    });
  } finally {
    await page?.close();
  }
}
