/**
 * The demo shell's text styles resolved while the page waits for the network, not in the
 * mount's layout. The first layout that sets text in a face at a new size or weight resolves
 * that font (in Chromium on Linux a round trip to the browser process for the face and one for
 * its size: 1–4 ms each on this project's test machine, unthrottled). In traces of the Bézier
 * patch demo's load, the layout after the mount resolved eight fonts and took 11–48 ms (a warm
 * relayout of the whole page: under 1.5 ms); after the warm-up it resolves none.
 *
 * `warmShellFonts(host)` lays out one hidden sample of each text style the shell's panels,
 * help, status, tables and about section use (shell.css; in lecture mode at its larger type),
 * one style per task, and removes it. The browser keeps the resolved fonts for the page. Run it
 * while a poster is shown and the wasm loads; the work then falls in time the page would
 * otherwise spend idle. (The figures' canvas labels still resolve a font at their first frame:
 * drawing their styles beforehand on a canvas of the figure's pixel ratio left that call in
 * each of 4 traces, so it is not done.)
 *
 *   posterSettled().then(() => warmShellFonts(main));
 */
import { el } from "./controls.js";
import { taskQueue } from "./task-queue.js";

/** One sample per text style of the mounted shell (its classes and nesting, as shell.css styles them). */
const SAMPLES = [
  () => el("p", { class: "sl-help", text: "Aa" }),
  () => el("fieldset", { class: "sl-group" }, el("legend", { text: "Aa" })),
  () => el("div", { class: "sl-control" }, el("label", { text: "Aa" })),
  () => el("input", { class: "sl-value", value: "0.5", tabindex: "-1" }),
  () => el("div", { class: "sl-status", text: "Aa" }),
  () =>
    el(
      "div",
      {},
      el("p", { class: "sl-table-title", text: "Aa" }),
      el(
        "table",
        { class: "sl-table" },
        el(
          "tbody",
          {},
          el("tr", {}, el("td", {}, el("span", { class: "sl-cell-decimal", text: "0.5" }))),
        ),
      ),
    ),
  () => el("p", { class: "sl-readout", text: "0.5" }),
  () => el("section", { class: "sl-about" }, el("h2", { text: "Aa" }), el("p", { text: "Aa" })),
];

let warmed = false;

/**
 * Lays out the samples in `host`, a task each, inside a hidden frame with the demo's type
 * (`lecture`: lecture mode's larger type), and removes them. Once per page; resolves when done.
 */
export function warmShellFonts(host, { lecture = false } = {}) {
  if (warmed) return Promise.resolve();
  warmed = true;
  const later = taskQueue();
  const frame = el("div", {
    class: `sl-font-warmup${lecture ? " sl-lecture" : ""}`,
    "aria-hidden": "true",
    inert: "",
  });
  host.append(frame);
  for (const sample of SAMPLES)
    later(() => {
      frame.replaceChildren(sample());
      void frame.offsetHeight; // the layout that resolves the sample's font, in this task
    });
  return new Promise((resolve) => later(resolve)).finally(() => frame.remove());
}
