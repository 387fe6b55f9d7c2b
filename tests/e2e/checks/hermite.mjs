// Browser checks specific to the Hermite demo (run after the generic ones by run.mjs).
// Hand-computed from the default state: P₀ = (0, 0), P₁ = (3, 4), m₀ = (0, 6), m₁ = (4, 0),
// t_i = i (Δ = 1), t = 1/2. At u = 1/2: H₀ = 2/8 − 3/4 + 1 = 1/2, H₁ = −2/8 + 3/4 = 1/2,
// H₂ = 1/8 − 2/4 + 1/2 = 1/8, H₃ = 1/8 − 1/4 = −1/8, so
// P(1/2) = ½(0, 0) + ½(3, 4) + ⅛(0, 6) − ⅛(4, 0) = (3/2 − 1/2, 2 + 3/4) = (1, 11/4).
// Bézier form of piece 0: q₁ = P₀ + m₀/3 = (0, 2), q₂ = P₁ − m₁/3 = (5/3, 4).
const cell = (page, i) =>
  page.locator(`[data-table="hermite-basis"] tr[data-index="${i}"] td[data-cell="value"]`);

export default [
  [
    "the basis table at u = 1/2 reads H₀ = H₁ = 1/2, H₂ = 1/8, H₃ = −1/8",
    async (page, _h, _base, { assert }) => {
      const values = [];
      for (let i = 0; i < 4; i++) values.push(await cell(page, i).textContent());
      assert(values[0].startsWith("1/2") && values[1].startsWith("1/2"), `H₀, H₁: ${values}`);
      assert(values[2].startsWith("1/8"), `H₂: ${values[2]}`);
      assert(values[3].startsWith("-1/8") || values[3].startsWith("−1/8"), `H₃: ${values[3]}`);
    },
  ],
  [
    "P(1/2) = (1, 11/4) in the formula panel and the figure's label",
    async (page, h, _base, { assert }) => {
      const formula = await page.locator(".sl-formula").textContent();
      // KaTeX keeps the TeX source in the MathML annotation.
      assert(formula.includes("\\left(1,\\ \\tfrac{11}{4}\\right)"), formula);
      // The weights written out: ½, ½, ⅛, −⅛ (no NaN).
      assert(
        formula.includes("= \\tfrac{1}{2}\\,(0,\\,0) + \\tfrac{1}{2}\\,(3,\\,4) + (\\tfrac{1}{8})"),
        formula,
      );
      assert(!formula.includes("NaN"), formula);
      const label = await h.canvas().getAttribute("aria-label");
      assert(label.includes("(1.00, 2.75)"), `aria-label: ${label}`);
    },
  ],
  [
    "the Bézier form of piece 0: q₁ = (0, 2), q₂ = (5/3, 4)",
    async (page, _h, _base, { assert, settle }) => {
      await page.locator('[data-control="bezier"] input').check();
      await settle(page);
      const formula = await page.locator(".sl-formula").textContent();
      assert(formula.includes("= (0.000,\\,2.000)"), `q₁ in ${formula}`);
      assert(formula.includes("= (1.667,\\,4.000)"), `q₂ in ${formula}`);
    },
  ],
  [
    "the core's check reads C¹ at both joints; unlocking P₁ with λ = 2 makes it G¹ only",
    async (page, _h, _base, { assert, equal, settle }) => {
      const joints = page.locator('[data-info="joints"]');
      equal(await joints.getAttribute("data-verdicts"), "C¹;C¹", "default joints");
      await page.locator('[data-control="unlocked"] input').check();
      await settle(page);
      equal(await joints.getAttribute("data-verdicts"), "G¹ only;C¹", "P₁ unlocked, λ = 2");
      // λ = 1 makes the incoming tangent equal the outgoing one: C¹ again.
      const box = page.locator('[data-control="ratio"] .sl-value');
      await box.fill("1");
      await box.press("Enter");
      await settle(page);
      equal(await joints.getAttribute("data-verdicts"), "C¹;C¹", "λ = 1");
    },
  ],
  [
    "dragging the tip of m₁ changes the picture and keeps P₁ where it is",
    async (page, h, _base, { assert, equal, settle }) => {
      const before = await h.snapshot();
      // m₁'s tip is P₁ + m₁/2 = (5, 4); world → screen from the handles of P₀ = (0, 0) and P₁ = (3, 4).
      const [p0, p1] = await h.handles();
      const k = (p1.x - p0.x) / 3;
      await h.drag({ x: p0.x + 5 * k, y: p1.y }, 0, -30);
      await settle(page);
      assert((await h.snapshot()) !== before, "picture unchanged after dragging the tip");
      equal(JSON.stringify((await h.handles())[1]), JSON.stringify(p1), "P₁ stays");
    },
  ],
  [
    "typing m₀ = (0, 0) moves P(1/2) to ½(3, 4) − ⅛(4, 0) = (1, 2)",
    async (page, h, _base, { assert, equal, settle }) => {
      const box = page.locator('[data-control="tangents"] .sl-value');
      equal(await box.inputValue(), "0 6", "m₀ shown when no point is selected");
      await box.fill("0 0");
      await box.press("Enter");
      await settle(page);
      const label = await h.canvas().getAttribute("aria-label");
      assert(/\(1(\.00)?, 2(\.00)?\)/.test(label), `aria-label: ${label}`);
      await box.fill("nonsense");
      await box.press("Enter");
      equal(await h.statusKind(), "error", "a bad tangent is reported");
      // The box follows the selected point: End selects P₃, whose m₃ = (3, −3).
      await h.canvas().focus();
      await page.keyboard.press("End");
      await settle(page);
      equal(await box.inputValue(), "3 -3", "m₃ after selecting P₃");
    },
  ],
  [
    "Play runs t along the whole curve (0 … 3), the pieces one after the other",
    async (page, _h, _base, { assert, equal, settle, PLAY_MS }) => {
      const box = page.locator('[data-control="t"] .sl-value');
      const local = page.locator('[data-info="local"]');
      await page.locator('[data-action="play"]').click();
      await page.waitForTimeout(3 * PLAY_MS);
      await page.locator('[data-action="play"]').click();
      await settle(page);
      const t = Number(await box.inputValue());
      assert(t > 1 && t <= 3, `t = ${t}`);
      assert(
        (await local.textContent()).includes(`Piece ${Math.min(2, Math.floor(t))}`),
        await local.textContent(),
      );
      // The step buttons go by (b − a)/16 = 3/16.
      await page.locator('[data-action="step"]').click();
      await settle(page);
      equal(Number(await box.inputValue()) > t, true, "a step forward");
    },
  ],
];
