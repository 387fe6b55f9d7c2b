/**
 * A typed text with the characters a refusal names underlined: the core's coded Errors of a
 * typed expression carry `params.start`/`params.end` in UTF-16 code units (what `slice`
 * counts). Returns the nodes `before, <u class="sl-expr-bad" data-start data-end>, after` to put
 * in an echo line under the box; an empty range (something missing at that place) underlines
 * one space there. Used by expression-fields.js and piece-fields.js.
 */
import { el } from "./controls.js";

export function markedText(text, start, end) {
  const a = Math.max(0, Math.min(Number(start) || 0, text.length));
  const b = Math.max(a, Math.min(Number(end) || a, text.length));
  const mark = el("u", {
    class: "sl-expr-bad",
    dataset: { start: String(a), end: String(b) },
    text: text.slice(a, b) || "\u00a0",
  });
  return [text.slice(0, a), mark, text.slice(b)];
}
