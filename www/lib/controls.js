/**
 * Labelled form controls for a demo's side panel: every control has a visible label, sliders
 * show their value and accept typed input (decimals or fractions such as 1/3).
 */
import { fmt, parseNumberInput } from "./format.js";

let nextId = 0;
/** A unique id for label/input pairs (unique per page, also across shadow roots). */
function uid(prefix) {
  nextId += 1;
  return `sl-${prefix}-${nextId}`;
}

/** Creates an element with attributes/properties and children. */
export function el(tag, props = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(props)) {
    if (value === undefined || value === null || value === false) continue;
    if (key === "class") node.className = value;
    else if (key === "text") node.textContent = value;
    else if (key === "dataset") Object.assign(node.dataset, value);
    else if (key.startsWith("on") && typeof value === "function") node.addEventListener(key.slice(2), value);
    else if (key in node && typeof value !== "string") node[key] = value;
    else node.setAttribute(key, value === true ? "" : value);
  }
  node.append(...children.flat().filter((c) => c !== null && c !== undefined));
  return node;
}

/**
 * A slider with a typed-value box.
 * @param {object} o
 * @param {string} o.label visible label.
 * @param {string} o.inputLabel accessible name of the text box.
 * @param {number} o.min @param {number} o.max @param {number} o.step
 * @param {number} o.value initial value.
 * @param {(value: number, final: boolean) => void} o.onChange final=false while dragging the
 *   slider, true when released or typed.
 * @param {(message: string) => void} [o.onError] typed text that is not a number in range.
 * @param {(value: number) => string} [o.format] text shown in the box.
 * @param {string} [o.name] data-control name (tests and styling).
 */
export function slider({ label, inputLabel, min, max, step, value, onChange, onError, format = fmt, name, badNumber }) {
  const id = uid("range");
  const range = el("input", { type: "range", id, min: String(min), max: String(max), step: String(step), value: String(value) });
  const box = el("input", { type: "text", inputmode: "decimal", class: "sl-value", "aria-label": inputLabel, size: "6", value: format(value) });
  const row = el("div", { class: "sl-control sl-slider", dataset: name ? { control: name } : undefined },
    el("label", { for: id, text: label }),
    el("div", { class: "sl-slider-row" }, range, box));

  range.addEventListener("input", () => {
    const v = Number(range.value);
    box.value = format(v);
    onChange(v, false);
  });
  range.addEventListener("change", () => onChange(Number(range.value), true));
  const typed = () => {
    const v = parseNumberInput(box.value);
    if (!Number.isFinite(v) || v < min || v > max) {
      onError?.(badNumber ? badNumber(box.value) : box.value);
      box.value = format(Number(range.value));
      return;
    }
    range.value = String(v);
    onChange(v, true);
  };
  box.addEventListener("change", typed);
  box.addEventListener("keydown", (e) => {
    if (e.key === "Enter") typed();
  });

  return {
    element: row,
    range,
    box,
    /** Shows `v` without firing onChange. */
    set(v) {
      range.value = String(v);
      if (document.activeElement !== box && box.getRootNode().activeElement !== box) box.value = format(v);
    },
  };
}

/** A labelled button. */
export function button({ label, title, onClick, name, pressed }) {
  return el("button", {
    type: "button",
    class: "sl-button",
    title,
    text: label,
    onclick: onClick,
    dataset: name ? { action: name } : undefined,
    "aria-pressed": pressed === undefined ? undefined : String(pressed),
  });
}

/** A checkbox with its label. */
export function checkbox({ label, checked, onChange, name }) {
  const id = uid("check");
  const input = el("input", { type: "checkbox", id, checked });
  input.addEventListener("change", () => onChange(input.checked));
  const row = el("div", { class: "sl-control sl-check", dataset: name ? { control: name } : undefined }, input, el("label", { for: id, text: label }));
  return { element: row, input, set: (v) => (input.checked = v) };
}

/** A titled group of controls. */
export function group(title, ...children) {
  return el("fieldset", { class: "sl-group" }, title ? el("legend", { text: title }) : null, ...children);
}
