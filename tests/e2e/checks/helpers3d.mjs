// Helpers shared by the browser checks of the section-6 (surface) demos: the URL state, a link's
// state, typing into a control's box, and the Bernstein double sum written out (the expected
// values the patch checks compare the core with). Not a demo's checks: run.mjs imports
// checks/<id>.mjs by demo id only.

/** The demo state in the page's URL (`#demo=<id>&s=…`, base64url JSON). */
export const urlState = (page) =>
  page.evaluate(() => {
    const s = new URLSearchParams(location.hash.slice(1)).get("s");
    const bytes = Uint8Array.from(atob(s.replace(/-/g, "+").replace(/_/g, "/")), (c) =>
      c.charCodeAt(0),
    );
    return JSON.parse(new TextDecoder().decode(bytes));
  });

/** `&s=…` for a state (base64url JSON). */
export const hashOf = (state) => `&s=${Buffer.from(JSON.stringify(state)).toString("base64url")}`;

/** Types `value` into the box of the control `name` (data-control) and presses Enter. */
export async function typeInto(page, name, value) {
  const box = page.locator(`[data-control="${name}"] .sl-value`);
  await box.fill(String(value));
  await box.press("Enter");
}

/** Types a value into a control's box (data-control name) and waits for the redraw. */
export async function type(page, settle, control, text) {
  await typeInto(page, control, text);
  await settle(page);
}

const binomial = (n, k) => (k === 0 || k === n ? 1 : binomial(n - 1, k - 1) + binomial(n - 1, k));
const bernstein = (n, i, t) => binomial(n, i) * t ** i * (1 - t) ** (n - i);

/** S(u, v) = Σ_i Σ_j B_i^m(u) B_j^n(v) P_ij, the definition (square net, rows along u). */
export function bernsteinSum(points, u, v) {
  const side = Math.round(Math.sqrt(points.length));
  const d = side - 1;
  const s = [0, 0, 0];
  for (let i = 0; i <= d; i++)
    for (let j = 0; j <= d; j++) {
      const w = bernstein(d, i, u) * bernstein(d, j, v);
      for (let c = 0; c < 3; c++) s[c] += w * points[i * side + j][c];
    }
  return s;
}

/** The largest coordinate difference of two points. */
export const gap = (a, b) => Math.max(...a.map((x, c) => Math.abs(x - b[c])));
