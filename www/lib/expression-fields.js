/**
 * Typed formulas in a declarative demo's panel (parametric-curve): text boxes bound to string
 * fields of the state, and one slider per named parameter of the formulas.
 *
 * `formulaFields` — labelled text boxes (`data-control=<field>`), in rows. While the reader
 * types, `check(ui, texts)` asks the core about the texts (nothing changes); Enter or leaving
 * the box calls `apply(ui, texts)`, which replaces the state (and the curve) only when the core
 * accepts them. A refusal (the core's coded Error, `params.field`, `start`, `end` in UTF-16
 * units) is shown under its box: the text with the offending characters underlined, and the
 * reason in the page's language (core-errors.js `errorText`); the box is `aria-invalid` and
 * described by it. The last good state (and curve) stays. A box is rewritten from the state
 * only when the state's text changed from outside (undo, a link, an example) and the box does
 * not have the focus, so a refused text stays in its box with its mark.
 *
 * `parameterSliders(field)` — a slider per entry of the object `state[field]` (`{ a: 2, … }`),
 * `data-control=param-<name>`, made again when the names change; a move sets a new object
 * (`ui.set`), which the demo takes into its model in place (`derive.inPlace`).
 */
import { el, setText, slider as sliderElement, group as fieldset } from "./controls.js";
import { markedText } from "./refusal-mark.js";
import { errorText } from "./core-errors.js";
import { t } from "./strings.js";

/** Sliders of a parameter run over [−R, R]: R is this, or the next step above 2|value|. */
const PARAMETER_RANGE = 5;
/** Slider steps per unit of R. */
const PARAMETER_STEPS = 1000;

/** True while `node` has the focus (also inside a shadow root). */
function focused(node) {
  return document.activeElement === node || node.getRootNode().activeElement === node;
}

/**
 * @param {object} o
 * @param {string} o.legend key of the group's legend
 * @param {Array<Array<{ field: string, label: string }>>} o.rows boxes per row (label keys)
 * @param {string} [o.help] key of a help line under the boxes
 * @param {(ui, texts: object) => void} o.check throws the core's refusal of the texts
 * @param {(ui, texts: object) => void} o.apply takes the texts into the state; throws a refusal
 */
export function formulaFields({ legend, rows, help = null, check, apply }) {
  return {
    build(ui) {
      const boxes = {};
      const notes = {};
      const shown = {};
      const items = [];
      let last = null;
      const texts = () => {
        const out = {};
        for (const name of Object.keys(boxes)) out[name] = boxes[name].value;
        return out;
      };
      const clear = () => {
        for (const name of Object.keys(boxes)) {
          boxes[name].removeAttribute("aria-invalid");
          notes[name].hidden = true;
          notes[name].replaceChildren();
        }
      };
      /** The refusal under its box: the text, the characters start…end underlined, the reason. */
      const show = (err) => {
        clear();
        const p = err?.params ?? {};
        const name = p.field in boxes ? p.field : last;
        if (!name) return ui.status(errorText(err), "error");
        const text = boxes[name].value;
        // An empty range at the start of a text is about the field as a whole (an interval
        // [1, 0]): the whole text is marked.
        const whole = !(Number(p.start) || Number(p.end));
        const code = el("code", {}, ...markedText(text, p.start, whole ? text.length : p.end));
        code.style.whiteSpace = "pre-wrap";
        notes[name].replaceChildren(code, el("br"), el("span", { text: errorText(err) }));
        notes[name].hidden = false;
        boxes[name].setAttribute("aria-invalid", "true");
      };
      const run = (name, final) => {
        last = name;
        try {
          if (final) apply(ui, texts());
          else check(ui, texts());
          clear();
        } catch (err) {
          show(err);
        }
      };
      for (const row of rows) {
        const parts = row.map(({ field, label }) => {
          const id = `sl-formula-${field}-${Math.random().toString(36).slice(2, 8)}`;
          const box = el("input", {
            type: "text",
            id,
            class: "sl-value sl-wide",
            spellcheck: "false",
            autocomplete: "off",
            autocapitalize: "off",
            "aria-describedby": `${id}-error`,
            value: ui.state[field],
          });
          box.addEventListener("input", () => run(field, false));
          box.addEventListener("change", () => run(field, true));
          box.addEventListener("keydown", (event) => {
            if (event.key === "Enter") run(field, true);
          });
          const note = el("p", {
            class: "sl-note",
            id: `${id}-error`,
            hidden: true,
            dataset: { error: field },
            "aria-live": "polite",
          });
          note.style.color = "var(--sl-error-text)";
          boxes[field] = box;
          notes[field] = note;
          shown[field] = ui.state[field];
          return el(
            "div",
            { class: "sl-control", dataset: { control: field } },
            el("label", { for: id, text: t(label) }),
            box,
            note,
          );
        });
        const line = el("div", { class: "sl-formula-row" }, parts);
        if (parts.length > 1) {
          line.style.display = "grid";
          line.style.gridTemplateColumns = `repeat(${parts.length}, 1fr)`;
          line.style.gap = "0.5rem";
        }
        items.push(line);
      }
      if (help) items.push(el("p", { class: "sl-note", text: t(help) }));
      return {
        element: fieldset(t(legend), ...items),
        sync(state) {
          for (const name of Object.keys(boxes)) {
            if (state[name] === shown[name]) continue;
            shown[name] = state[name];
            if (focused(boxes[name])) continue;
            boxes[name].value = state[name];
            boxes[name].removeAttribute("aria-invalid");
            notes[name].hidden = true;
          }
        },
      };
    },
  };
}

/** The half-width of a parameter slider's range for a value. */
function reachOf(value) {
  const need = 2 * Math.abs(value);
  if (need <= PARAMETER_RANGE) return PARAMETER_RANGE;
  return 10 ** Math.ceil(Math.log10(need));
}

/**
 * @param {string} field the state's object of parameter values
 * @param {object} o
 * @param {string} o.legend key of the group's legend (hidden while there is no parameter)
 * @param {string} o.input key of a box's accessible name, given `{ name }`
 */
export function parameterSliders(field, { legend, input }) {
  return {
    build(ui) {
      const body = el("div");
      const element = fieldset(t(legend), body);
      let names = "";
      let sliders = new Map();
      const make = (values) => {
        sliders = new Map();
        const rows = [];
        for (const [name, value] of Object.entries(values)) {
          const reach = reachOf(value);
          const control = sliderElement({
            label: name,
            inputLabel: t(input, { name }),
            name: `param-${name}`,
            min: -reach,
            max: reach,
            step: reach / PARAMETER_STEPS,
            value,
            onChange: (v, final) => ui.set(field, { ...ui.state[field], [name]: v }, final),
            onError: (text) => ui.status(t("control.badNumber", { value: text }), "error"),
          });
          sliders.set(name, { control, reach });
          rows.push(control.element);
        }
        body.replaceChildren(...rows);
      };
      return {
        element,
        sync(state) {
          const values = state[field];
          const now = Object.keys(values).join(" ");
          if (now !== names) {
            names = now;
            make(values);
          }
          element.hidden = names === "";
          for (const [name, { control, reach }] of sliders) {
            const v = values[name];
            if (Math.abs(v) > reach) {
              const r = reachOf(v);
              control.setRange(-r, r, r / PARAMETER_STEPS);
              sliders.get(name).reach = r;
            }
            control.set(v);
          }
        },
      };
    },
  };
}

/** A paragraph (and an optional link) written from the state and data: `text(state, data)`. */
export function infoLine(name, text, link = null) {
  return {
    build() {
      const line = el("span");
      const anchor = link ? el("a", { dataset: { link: name } }) : null;
      const node = el("p", { class: "sl-note", dataset: { info: name } }, line);
      if (anchor) node.append(el("br"), anchor);
      return {
        element: node,
        sync(state, data) {
          setText(line, text(state, data));
          if (!anchor) return;
          const target = link(state, data);
          anchor.hidden = !target;
          if (!target) return;
          setText(anchor, target.text);
          // No href (a refusal: the text says why): the anchor is plain text, not a link.
          if (!target.href) anchor.removeAttribute("href");
          else if (anchor.getAttribute("href") !== target.href)
            anchor.setAttribute("href", target.href);
        },
      };
    },
  };
}
