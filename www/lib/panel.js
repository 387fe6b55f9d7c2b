/**
 * Declared controls of a demo's side panel (the `controls` export of a declarative demo, see
 * demo.js). Each function returns a descriptor `{ build(ui) }`; the runtime builds it with the
 * demo's `ui` (state, `set`, view, handles) and gets back `{ element, sync(state, data),
 * stop?(), destroy?() }`. A control is bound to a state field: a user change calls
 * `ui.set(field, value, final)`, and `sync` shows the field's value after any change (undo,
 * reset, link, playback), so no demo syncs its sliders by hand. Labels are strings.js keys.
 */
import { slider as sliderElement, checkbox as checkboxElement, radios, button, group as fieldset, el, setText } from "./controls.js";
import { Player } from "./player.js";
import { withPointAdded, withPointRemoved } from "./point-list.js";
import { parseNumberInput } from "./format.js";
import { t } from "./strings.js";

/** Nodes placed side by side in whatever holds the control (a fieldset or the panel). */
function fragment(...nodes) {
  const f = document.createDocumentFragment();
  f.append(...nodes);
  return f;
}

/**
 * A slider with a typed-value box (decimals or fractions) bound to a number field.
 * @param {string} field
 * @param {object} o
 * @param {string} o.label key of the visible label; `o.input` the key of the box's name
 *   (default `<label>.input`).
 * @param {number} [o.min] @param {number} [o.max] fixed range, or `o.range(state, data) → [a, b]`
 *   (e.g. a B-spline's domain, re-read after every change).
 * @param {number | ((a: number, b: number) => number)} o.step slider resolution (log10 units for
 *   `log`), or a function of the range (e.g. a thousandth of a B-spline's domain).
 * @param {boolean} [o.log] logarithmic slider; its `aria-valuetext` is the real value.
 * @param {(v: number) => string} [o.format] text in the box.
 * @param {(v: number, typed: boolean) => number} [o.round] the value kept from a slider move.
 * @param {boolean | object} [o.player] add the step / play buttons (Player options if an object).
 * @param {string | ((text: string, state) => string)} [o.error] key of the message for typed
 *   text that is out of range (given `{ value, min, max }`), or the message itself.
 * @param {(ui, value: number, final: boolean) => void} [o.set] instead of `ui.set(field, value,
 *   final)`, for a change that implies others or may be refused (e.g. through `ui.replace`);
 *   after a final change the slider shows the field's value again.
 * @param {boolean} [o.onRelease] apply the value only when the slider is released or a value is
 *   typed, not while it is dragged (a field that rebuilds the model, such as the degree).
 * @param {(v: number, state) => string | null} [o.refuse] the message when the state cannot
 *   take the value (then it is reported and the slider shows the field again), else null.
 * `o.player`'s `stepBackTitle` / `stepTitle` are strings.js keys.
 */
export function slider(field, o) {
  return {
    build(ui) {
      const fixed = o.range ? null : [o.min, o.max];
      const range = () => fixed ?? o.range(ui.state, ui.data);
      const [min, max] = range();
      const stepOf = (a, b) => (typeof o.step === "function" ? o.step(a, b) : o.step);
      let player = null;
      const control = sliderElement({
        label: t(o.label),
        inputLabel: t(o.input ?? `${o.label}.input`, o.inputParams),
        name: o.name ?? field,
        min,
        max,
        step: stepOf(min, max),
        log: o.log,
        format: o.format,
        value: ui.state[field],
        onChange: (value, final) => {
          if (o.onRelease && !final) return;
          player?.stop();
          const typed = control.typing();
          const next = o.round ? o.round(value, typed) : value;
          const refusal = o.refuse?.(next, ui.state);
          if (refusal) {
            ui.status(refusal, "error");
            control.set(ui.state[field]);
            return;
          }
          if (!o.set) return ui.set(field, next, final);
          o.set(ui, next, final);
          if (final) control.set(ui.state[field]);
        },
        onError: (text) => {
          const [a, b] = range();
          const message = typeof o.error === "function" ? o.error(text, ui.state) : t(o.error ?? "control.badNumber", { value: text, min: a, max: b });
          ui.status(message, "error");
        },
      });
      if (o.player) {
        const options = typeof o.player === "object" ? o.player : {};
        player = new Player(ui.view, {
          ...options,
          stepBackTitle: options.stepBackTitle ? t(options.stepBackTitle) : undefined,
          stepTitle: options.stepTitle ? t(options.stepTitle) : undefined,
          get: () => ui.state[field],
          set: (value, final) => ui.set(field, value, final),
          stopped: () => ui.commit(),
          range,
        });
      }
      let shownRange = [min, max];
      return {
        element: player ? fragment(control.element, player.element) : control.element,
        player,
        sync(state) {
          if (!fixed) {
            const [a, b] = range();
            if (a !== shownRange[0] || b !== shownRange[1]) {
              control.setRange(a, b, typeof o.step === "function" ? o.step(a, b) : null);
              shownRange = [a, b];
            }
          }
          control.set(state[field]);
        },
        stop: () => player?.stop(),
        destroy: () => player?.destroy(),
      };
    },
  };
}

/** A checkbox bound to a boolean field. */
export function checkbox(field, { label, name = field }) {
  return {
    build(ui) {
      const box = checkboxElement({ label: t(label), name, checked: ui.state[field], onChange: (on) => ui.set(field, on) });
      return { element: box.element, sync: (state) => box.set(state[field]) };
    },
  };
}

/**
 * One choice out of a few, bound to a field: radio buttons (`data-control=name`, each row
 * `data-choice=value`). `options`: `[{ value, label }]` with strings.js keys as labels; values
 * may be numbers (a degree), shown as text. `refuse(value, state)` → a message when the state
 * cannot take the value (reported; the buttons show the field again), else null. `set(ui,
 * value)` as for `slider` (then the buttons show the field's value again).
 */
export function choice(field, { options, name = field, refuse = null, set = null }) {
  return {
    build(ui) {
      const control = radios({
        options: options.map((option) => ({ value: String(option.value), label: t(option.label) })),
        value: String(ui.state[field]),
        name,
        onChange: (text) => {
          const value = options.find((option) => String(option.value) === text).value;
          const refusal = refuse?.(value, ui.state);
          if (refusal) ui.status(refusal, "error");
          else if (!set) return ui.set(field, value);
          else set(ui, value);
          control.set(String(ui.state[field]));
        },
      });
      return { element: control.element, sync: (state) => control.set(String(state[field])) };
    },
  };
}

/**
 * The Add point / Remove point buttons (and `+` / Delete on the figure) for the handles' point
 * list: the new list is built into a new model first (`ui.replace`), then the handle is selected.
 * A full or minimal list reports `<prefix>.maxPoints` / `.minPoints` (or the keys `maxKey` /
 * `minKey`, with `params(state)` added to `{ max }` / `{ min }`). The buttons are disabled at the
 * limits. `min` may be a function of the state (a B-spline of degree p needs p + 1 points).
 * `apply(ui, points) → boolean` replaces `ui.replace` when the new list changes more (knots
 * reset); or `adjust(state, ui) → state` amends the new state before `ui.replace`. `more`: extra
 * buttons `[{ name, label, title?, run(ui) }]` in the row; `addTitle` / `removeTitle` are keys
 * of the tooltips. The messages also get the state's fields as parameters.
 */
export function pointButtons(field, o) {
  const { min, max, prefix, minKey = `${prefix}.minPoints`, maxKey = `${prefix}.maxPoints`, params = () => ({}) } = o;
  const { addTitle = "control.addPoint.title", removeTitle = "control.removePoint.title", adjust = null, more = [] } = o;
  const least = typeof min === "function" ? min : () => min;
  return {
    build(ui) {
      const replace = (points) => {
        let state = { ...ui.state, [field]: points };
        if (adjust) state = adjust(state, ui);
        try {
          ui.replace(state);
          return true;
        } catch (err) {
          ui.status(err.message, "error");
          return false;
        }
      };
      const apply = (next) => {
        const done = o.apply ? o.apply(ui, next.points) : replace(next.points);
        if (done) ui.handles?.select(next.index);
      };
      const refuse = (key, limits) => ui.status(t(key, { ...ui.state, ...limits, ...params(ui.state) }), "error");
      ui.pointList = {
        add(i) {
          const next = withPointAdded(ui.state[field], i, max, ui.view.scale);
          if (next) apply(next);
          else refuse(maxKey, { max });
        },
        remove(i) {
          const next = withPointRemoved(ui.state[field], i, least(ui.state));
          if (next) apply(next);
          else refuse(minKey, { min: least(ui.state) });
        },
      };
      const selected = () => ui.handles?.selected ?? -1;
      const addButton = button({ label: t("control.addPoint"), title: t(addTitle), name: "add-point", onClick: () => ui.pointList.add(selected()) });
      const removeButton = button({ label: t("control.removePoint"), title: t(removeTitle), name: "remove-point", onClick: () => ui.pointList.remove(selected()) });
      const others = more.map((a) => button({ label: t(a.label), title: a.title ? t(a.title) : undefined, name: a.name, onClick: () => a.run(ui) }));
      return {
        element: el("div", { class: "sl-button-row" }, addButton, removeButton, ...others),
        sync(state) {
          const count = state[field].length;
          addButton.disabled = count >= max;
          removeButton.disabled = count <= least(state);
        },
      };
    },
  };
}

/**
 * A line of text computed from the state and data (`text(state, data)`), `data-info=name`;
 * `kind` "note" (default) or "readout" (the larger figure of merit); `live` makes it a polite
 * live region; `data(state, data)` → `{ name: value }` sets data attributes (hooks for tests;
 * null removes one). Built outside the panel (`readout(…).build(ui)`), it can fill other slots.
 */
export function readout(name, text, { kind = "note", live = false, data = null } = {}) {
  return {
    build(ui) {
      const node = el("p", { class: kind === "readout" ? "sl-readout" : "sl-note", dataset: { info: name }, "aria-live": live ? "polite" : null });
      return {
        element: node,
        sync(state, values) {
          setText(node, text(state, values, ui));
          if (!data) return;
          for (const [key, value] of Object.entries(data(state, values))) {
            if (value === null || value === undefined) delete node.dataset[key];
            else node.dataset[key] = value;
          }
        },
      };
    },
  };
}

/**
 * A row of buttons, `[{ name, label, title?, run(ui), disabled?(state, data) }]`
 * (`data-action=name`); `title` (legend key) makes it a titled group. `disabled` is re-read
 * after every change.
 */
export function actions(list, { title = null } = {}) {
  return {
    build(ui) {
      const buttons = list.map((a) => button({ label: t(a.label), title: a.title ? t(a.title) : undefined, name: a.name, onClick: () => a.run(ui) }));
      const row = el("div", { class: "sl-button-row" }, buttons);
      return {
        element: title ? fieldset(t(title), row) : row,
        sync(state, data) {
          list.forEach((a, k) => {
            if (a.disabled) buttons[k].disabled = Boolean(a.disabled(state, data));
          });
        },
      };
    },
  };
}

/**
 * A typed list of numbers bound to a field (a knot vector): a labelled text box
 * (`data-control=name`) showing `state[field]` as `format(v)` joined by spaces, and a help line
 * `help(state)` under it. Enter (or leaving the box) reads numbers or fractions separated by
 * spaces, commas or semicolons; a part that is no number is reported (`control.badNumber`), else
 * `apply(ui, values)` (default `ui.set(field, values)`) gets the list. The box is not rewritten
 * while it has the focus.
 */
export function numberList(field, { label, name = field, format = String, help = null, apply = null }) {
  return {
    build(ui) {
      const id = `sl-${name}-${Math.random().toString(36).slice(2, 8)}`;
      const input = el("input", {
        type: "text", id, class: "sl-value sl-wide", inputmode: "decimal", spellcheck: "false",
        "aria-describedby": help ? `${id}-help` : null,
      });
      const note = help ? el("p", { class: "sl-note", id: `${id}-help` }) : null;
      const read = () => {
        const parts = input.value.trim().split(/[\s,;]+/).filter(Boolean);
        const values = parts.map(parseNumberInput);
        const bad = parts.find((part, i) => !Number.isFinite(values[i]));
        if (bad !== undefined) ui.status(t("control.badNumber", { value: bad }), "error");
        else if (apply) apply(ui, values);
        else ui.set(field, values);
      };
      input.addEventListener("change", read);
      input.addEventListener("keydown", (event) => {
        if (event.key === "Enter") read();
      });
      const focused = () => document.activeElement === input || input.getRootNode().activeElement === input;
      const row = el("div", { class: "sl-control", dataset: { control: name } }, el("label", { for: id, text: t(label) }), input);
      return {
        element: fragment(row, ...(note ? [note] : [])),
        sync(state) {
          const text = state[field].map(format).join(" ");
          if (input.value !== text && !focused()) input.value = text;
          if (note) setText(note, help(state));
        },
      };
    },
  };
}

/** A group (fieldset) of controls, with an optional legend key. */
export function group(title, ...items) {
  return {
    build(ui) {
      const parts = items.map((item) => item.build(ui));
      return {
        element: fieldset(title ? t(title) : null, ...parts.map((part) => part.element)),
        sync: (state, data) => parts.forEach((part) => part.sync?.(state, data)),
        stop: () => parts.forEach((part) => part.stop?.()),
        destroy: () => parts.forEach((part) => part.destroy?.()),
      };
    },
  };
}
