// Browser checks specific to the joining demo (run after the generic ones by run.mjs).
// Each entry: [what, async (page, helpers, base, tools)]; tools = { assert, equal, settle, openDemo, PLAY_MS }.
// Expected numbers by hand from the syllabus (§2, joining two Béziers): the default pieces are
// P = (0,0) (1,3) (3,3) (4,1) and Q = (4,1) (5,-1) (7,0) (8,2); C1 for two cubics on [0,1] and
// [1,2] means Q1 - Q0 = P3 - P2; C2 adds Q2 = P1 - 4P2 + 4P3.

/** The checker's verdict: { c, g, text } from the readout in the side panel. */
async function verdict(page) {
  const readout = page.locator('[data-info="verdict"]');
  return {
    c: await readout.getAttribute("data-c"),
    g: await readout.getAttribute("data-g"),
    text: await readout.textContent(),
  };
}

/** The text of a table cell by its data-vector key ("p3-p2", "q1-q0", "dp", "dq", "ddp", "ddq"). */
const cell = (page, key) =>
  page.locator(`[data-table="joining"] td[data-vector="${key}"]`).textContent();

/** Handle indices: P0..P3 are 0..3, Q0..Q3 are 4..7. */
const Q0 = 4;
const Q1 = 5;

export default [
  [
    "C1: the checker reads C1 and Q1 − Q0 = P3 − P2, also after dragging P2",
    async (page, h, _base, { assert, equal, settle }) => {
      let v = await verdict(page);
      equal(v.c, "1", "checker c");
      equal(v.g, "1", "checker g");
      assert(v.text.includes("C¹, G¹"), `verdict text: ${v.text}`);
      equal(await cell(page, "p3-p2"), "(1, -2)", "P3 − P2");
      equal(await cell(page, "q1-q0"), "(1, -2)", "Q1 − Q0");
      equal(await cell(page, "dp"), "(3, -6)", "P′(1) = 3(P3 − P2)");
      equal(await cell(page, "dq"), "(3, -6)", "Q′(1) = 3(Q1 − Q0)");
      // Drag P2: Q1 mirrors it through the joint; the joint stays C1.
      const handles = await h.handles();
      await h.drag(handles[2], 30, 24);
      await settle(page);
      v = await verdict(page);
      equal(v.c, "1", "checker c after dragging P2");
      const left = await cell(page, "p3-p2");
      assert(left !== "(1, -2)", `P3 − P2 changed: ${left}`);
      equal(await cell(page, "q1-q0"), left, "Q1 − Q0 follows P3 − P2");
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("C¹, G¹"), `aria-label: ${label}`);
    },
  ],
  [
    "none: dragging Q0 away from P3 reports not C0",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="rule"] input[value="none"]').check();
      await settle(page);
      equal((await verdict(page)).c, "1", "switching to none changes nothing yet");
      const before = await h.handles();
      await h.drag(before[Q0], 40, 30); // P3 and Q0 coincide: the later handle, Q0, is grabbed
      const after = await h.handles();
      equal(JSON.stringify(after[3]), JSON.stringify(before[3]), "P3 stays");
      const v = await verdict(page);
      equal(v.c, "-1", "checker c");
      assert(v.text.includes("not even C⁰"), `verdict text: ${v.text}`);
      assert(
        (await page.locator(".sl-formula").textContent()).includes("not C⁰"),
        "formula panel says not C0",
      );
    },
  ],
  [
    "G1 with different lengths reports G1 but only C0; Q1 slides on the tangent line",
    async (page, h, base, { assert, equal, settle, openDemo }) => {
      // Q1 = P3 + 2 (P3 − P2) = (6, −3): same direction as P3 − P2, twice as long.
      const state = {
        left: [
          [0, 0],
          [1, 3],
          [3, 3],
          [4, 1],
        ],
        right: [
          [4, 1],
          [6, -3],
          [7, 0],
          [8, 2],
        ],
        rule: "G1",
      };
      h = await openDemo(
        page,
        base,
        "joining",
        `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`,
      );
      let v = await verdict(page);
      equal(v.c, "0", "checker c");
      equal(v.g, "1", "checker g");
      assert(v.text.includes("C⁰, G¹"), `verdict text: ${v.text}`);
      equal(await cell(page, "dp"), "(3, -6)", "P′(1)");
      equal(await cell(page, "dq"), "(6, -12)", "Q′(1) = 2 P′(1)");
      assert(
        (await page.locator(".sl-formula").textContent()).includes("2.000"),
        "λ = 2 in the formula panel",
      );
      // Dragging Q1 sideways: it stays on the ray, so the joint stays G1.
      const handles = await h.handles();
      await h.drag(handles[Q1], 30, 10);
      v = await verdict(page);
      equal(v.g, "1", "still G1 after dragging Q1");
      const [dx, dy] = (await cell(page, "q1-q0")).slice(1, -1).split(", ").map(Number);
      assert(
        Math.abs(dx * -2 - dy) < 2e-3 && dx > 0,
        `Q1 − Q0 = (${dx}, ${dy}) is a positive multiple of (1, −2)`,
      );
    },
  ],
  [
    "C2 fixes Q2 = P1 − 4P2 + 4P3 and the checker reads C2",
    async (page, h, _base, { assert, equal, settle }) => {
      await page.locator('[data-control="rule"] input[value="C2"]').check();
      await settle(page);
      const v = await verdict(page);
      equal(v.c, "2", "checker c");
      equal(await cell(page, "ddp"), "(-6, -12)", "P″(1) = 6(P3 − 2P2 + P1)");
      equal(await cell(page, "ddq"), "(-6, -12)", "Q″(1) equals P″(1)");
      assert(page.url().includes("s="), "the rule change is in the URL");
      // Q2 = (1,3) − 4(3,3) + 4(4,1) = (5, −5): on screen 1 unit right of Q1 = (5, −1) … 4 units below.
      const handles = await h.handles();
      const unit = handles[1].x - handles[0].x; // P1 − P0 is one unit to the right
      assert(
        Math.abs(handles[6].x - handles[Q1].x) < 0.6 &&
          Math.abs(handles[6].y - handles[Q1].y - 4 * unit) < 0.6,
        `Q2 at ${JSON.stringify(handles[6])}, Q1 at ${JSON.stringify(handles[Q1])}`,
      );
    },
  ],
];
