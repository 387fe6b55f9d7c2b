// Browser checks specific to the multiplicity demo (run after the generic ones by run.mjs).
// Expected: the Croatian notes' table for cubics (syllabus §3) — knot multiplicity 2 → C¹,
// 3 → C⁰ (the curve passes through a control point: with U = 0⁴ 1 2 2 2 5⁴ the knot 2 is
// u₅ = u₆ = u₇, so C(2) = P_{7−3} = P₄ = (6, 4)), 4 → break; a triple control point → G⁰.

const readout = (page, what) => page.locator(`[data-info="${what}"]`).textContent();
const highlighted = (page, column, r) =>
  page
    .locator(`[data-table="notes"] td[data-column="${column}"][data-multiplicity="${r}"]`)
    .evaluate((c) => c.classList.contains("sl-highlight"));

/** Knot handle centres (page px) from the figure's data-knots. */
async function knots(page, h) {
  const text = await page.locator(".sl-figure").first().getAttribute("data-knots");
  const origin = await h.canvas().evaluate((c) => {
    const r = c.getBoundingClientRect();
    return { x: r.left + c.clientLeft, y: r.top + c.clientTop };
  });
  return text.split(";").map((pair) => {
    const [x, y] = pair.split(",").map(Number);
    return { x: origin.x + x, y: origin.y + y };
  });
}

export default [
  [
    "knot multiplicity 2, 3, 4 reads C¹, C⁰ through P₄, break",
    async (page, h, _base, { assert, equal, settle }) => {
      assert(
        (await readout(page, "knot")).includes("measured C² G²"),
        `start: ${await readout(page, "knot")}`,
      );
      assert(await highlighted(page, "knots", 1), "row 1 highlighted at the start");
      await h.canvas().focus();
      await page.keyboard.press("End"); // P₇
      await page.keyboard.press("Tab"); // u₀
      for (let i = 0; i < 5; i++) await page.keyboard.press("Tab"); // u₅ = 2
      await page.keyboard.press("Enter");
      await settle(page);
      let text = await readout(page, "knot");
      assert(
        text.includes("r = 2") && text.includes("guaranteed C¹") && text.includes("measured C¹ G¹"),
        `r = 2: ${text}`,
      );
      assert(await highlighted(page, "knots", 2), "row 2 highlighted");
      await page.keyboard.press("Enter");
      await settle(page);
      text = await readout(page, "knot");
      assert(
        text.includes("r = 3") && text.includes("guaranteed C⁰") && text.includes("measured C⁰ G⁰"),
        `r = 3: ${text}`,
      );
      assert(await highlighted(page, "knots", 3), "row 3 highlighted");
      const cell = page.locator('[data-table="knots"] tr[data-knot="2"] td[data-cell="point"]');
      const x = Number(await cell.getAttribute("data-x"));
      const y = Number(await cell.getAttribute("data-y"));
      assert(
        Math.abs(x - 6) < 1e-9 && Math.abs(y - 4) < 1e-9,
        `C(2) = (${x}, ${y}), expected P₄ = (6, 4)`,
      );
      equal(
        await page
          .locator('[data-table="knots"] tr[data-knot="2"] td[data-cell="through"]')
          .textContent(),
        "P₄",
        "through cell",
      );
      await page.keyboard.press("Enter");
      await settle(page);
      text = await readout(page, "knot");
      assert(text.includes("r = 4") && text.includes("measured break"), `r = 4: ${text}`);
      assert(await highlighted(page, "knots", 4), "row 4 highlighted");
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("knots [0, 0, 0, 0, 2, 2, 2, 2, 5, 5, 5, 5]") &&
          label.includes("2 (×4): break"),
        `aria-label: ${label}`,
      );
    },
  ],
  [
    "a triple control point reads G⁰ and the curve passes through it",
    async (page, h, _base, { assert, settle }) => {
      await h.canvas().focus();
      await page.keyboard.press("Home");
      for (let i = 0; i < 4; i++) await page.keyboard.press("Tab"); // P₄
      await page.locator('[data-control="repeat"] [data-choice="3"] input').check();
      await settle(page);
      const text = await readout(page, "repeat");
      assert(text.includes("P₄ = P₅ = P₆") && text.includes("C² G⁰"), `×3: ${text}`);
      assert(await highlighted(page, "points", 3), "control points row 3 highlighted");
      // Ten control points, clamped uniform knots 0⁴ 1 … 6 7⁴: the triple point sits at u₇ = 4.
      const label = await h.canvas().getAttribute("aria-label");
      assert(
        label.includes("knots [0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 7, 7, 7]"),
        `aria-label: ${label}`,
      );
      const cell = page.locator('[data-table="knots"] tr[data-knot="4"] td[data-cell="point"]');
      const x = Number(await cell.getAttribute("data-x"));
      const y = Number(await cell.getAttribute("data-y"));
      assert(
        Math.abs(x - 6) < 1e-9 && Math.abs(y - 4) < 1e-9,
        `C(4) = (${x}, ${y}), expected P₄ = (6, 4)`,
      );
      await page.locator('[data-control="repeat"] [data-choice="2"] input').check();
      await settle(page);
      const double = await readout(page, "repeat");
      assert(double.includes("P₄ = P₅") && double.includes("C²"), `×2: ${double}`);
    },
  ],
  [
    "a double click on a ruler knot raises its multiplicity",
    async (page, h, _base, { assert, settle }) => {
      const k = await knots(page, h);
      await page.mouse.dblclick(k[6].x, k[6].y); // u₆ = 3: u₇ = 4 joins it
      await settle(page);
      const text = await readout(page, "knot");
      assert(
        text.includes("u₆ = u₇ = 3") && text.includes("measured C¹ G¹"),
        `after the double click: ${text}`,
      );
    },
  ],
  [
    "a link with the wrong number of knots names the field",
    async (page, h, base, { assert, openDemo }) => {
      const state = Buffer.from(
        JSON.stringify({
          points: [
            [0, 0],
            [1, 1],
            [2, 0],
            [3, 1],
          ],
          knots: [0, 0, 0, 0, 1, 1, 1],
          repeatPoint: 0,
          repeatTimes: 1,
        }),
      ).toString("base64url");
      h = await openDemo(page, base, "multiplicity", `&s=${state}`);
      const status = await h.status();
      assert(/“knots”/.test(status) && status.includes("8"), `status: ${status}`);
    },
  ],
];
