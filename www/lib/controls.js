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
    else if (key.startsWith("on") && typeof value === "function")
      node.addEventListener(key.slice(2), value);
    else if (key in node && typeof value !== "string") node[key] = value;
    else node.setAttribute(key, value === true ? "" : value);
  }
  node.append(...children.flat().filter((c) => c !== null && c !== undefined));
  return node;
}

/** Sets a node's text only when it changed (no layout work for identical text). */
export function setText(node, text) {
  if (node.textContent !== text) node.textContent = text;
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
 * @param {boolean} [o.log] logarithmic slider (min > 0): the range moves in log10 of the value
 *   with `step` in log10 units; `min`, `max`, `value` and what onChange gets stay plain values.
 */
export function slider({
  label,
  inputLabel,
  min,
  max,
  step,
  value,
  onChange,
  onError,
  format = fmt,
  name,
  badNumber,
  log = false,
}) {
  const id = uid("range");
  /** Value ↔ range position (the identity unless `log`). */
  const toRange = log ? Math.log10 : (v) => v;
  const fromRange = log ? (p) => 10 ** p : (p) => p;
  const range = el("input", {
    type: "range",
    id,
    min: String(toRange(min)),
    max: String(toRange(max)),
    step: String(step),
    value: String(toRange(value)),
  });
  const box = el("input", {
    type: "text",
    inputmode: "decimal",
    class: "sl-value",
    "aria-label": inputLabel,
    size: "6",
    value: format(value),
  });
  const row = el(
    "div",
    { class: "sl-control sl-slider", dataset: name ? { control: name } : undefined },
    el("label", { for: id, text: label }),
    el("div", { class: "sl-slider-row" }, range, box),
  );

  const typing = () => document.activeElement === box || box.getRootNode().activeElement === box;
  /** The value shown (unsnapped: a log slider's range position is rounded to its step). */
  let current = value;
  /** The accepted range (`setRange` moves it, e.g. a B-spline's domain after a knot change). */
  let lo = min;
  let hi = max;
  /** A log slider's position is not its value: say the value (ARIA `aria-valuetext`). */
  const describe = log ? (v) => range.setAttribute("aria-valuetext", format(v)) : () => {};
  describe(value);
  range.addEventListener("input", () => {
    const v = fromRange(Number(range.value));
    current = v;
    box.value = format(v);
    describe(v);
    onChange(v, false);
  });
  range.addEventListener("change", () => {
    current = fromRange(Number(range.value));
    onChange(current, true);
  });
  const typed = () => {
    const v = parseNumberInput(box.value);
    if (!Number.isFinite(v) || v < lo || v > hi) {
      onError?.(badNumber ? badNumber(box.value) : box.value);
      box.value = format(current);
      return;
    }
    current = v;
    range.value = String(toRange(v));
    describe(v);
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
    /** Shows `v` without firing onChange (nothing is written when it is already shown). */
    set(v) {
      if (v === current && !typing()) return;
      current = v;
      range.value = String(toRange(v));
      describe(v);
      if (!typing()) box.value = format(v);
    },
    /** True while the typed-value box has the focus (a typed value is kept as typed). */
    typing,
    /** Changes the accepted range (and the step when given) without firing onChange; call `set` after. */
    setRange(newMin, newMax, newStep = null) {
      lo = newMin;
      hi = newMax;
      range.min = String(toRange(newMin));
      range.max = String(toRange(newMax));
      if (newStep !== null) range.step = String(newStep);
      current = NaN; // the browser may have clamped the position: the next `set` writes it
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
  const row = el(
    "div",
    { class: "sl-control sl-check", dataset: name ? { control: name } : undefined },
    input,
    el("label", { for: id, text: label }),
  );
  return { element: row, input, set: (v) => (input.checked = v) };
}

/** A titled group of controls. */
export function group(title, ...children) {
  return el(
    "fieldset",
    { class: "sl-group" },
    title ? el("legend", { text: title }) : null,
    ...children,
  );
}

/**
 * Radio buttons for one choice, each with its visible label (arrow keys move between them, as
 * the browser does for a radio group). Put the returned rows in a `group(title, …)`.
 * @param {object} o
 * @param {{ value: string, label: string }[]} o.options
 * @param {string} o.value the choice shown first.
 * @param {(value: string) => void} o.onChange a choice was made.
 * @param {string} [o.name] data-control name (tests and styling); also the radios' name.
 * @returns {{ element: HTMLElement, inputs: HTMLInputElement[], set(value: string): void }}
 */
export function radios({ options, value, onChange, name }) {
  const groupName = uid(`radio-${name ?? "choice"}`);
  const inputs = [];
  const rows = options.map((option) => {
    const id = uid("radio");
    const input = el("input", {
      type: "radio",
      id,
      name: groupName,
      value: option.value,
      checked: option.value === value,
    });
    input.addEventListener("change", () => {
      if (input.checked) onChange(option.value);
    });
    inputs.push(input);
    return el(
      "div",
      { class: "sl-control sl-check", dataset: { choice: option.value } },
      input,
      el("label", { for: id, text: option.label }),
    );
  });
  const element = el(
    "div",
    { class: "sl-radios", role: "radiogroup", dataset: name ? { control: name } : undefined },
    rows,
  );
  return {
    element,
    inputs,
    /** Shows `v` without firing onChange. */
    set(v) {
      for (const input of inputs) input.checked = input.value === v;
    },
  };
}
