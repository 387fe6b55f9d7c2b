/**
 * Declared controls of a demo's side panel (the `controls` export of a declarative demo, see
 * demo.js). Each function returns a descriptor `{ build(ui) }`; the runtime builds it with the
 * demo's `ui` (state, `set`, view, handles) and gets back `{ element, sync(state, data),
 * stop?(), destroy?() }`. A control is bound to a state field: a user change calls
 * `ui.set(field, value, final)`, and `sync` shows the field's value after any change (undo,
 * reset, link, playback), so no demo syncs its sliders by hand. Labels are strings.js keys.
 */
import {
  slider as sliderElement,
  checkbox as checkboxElement,
  radios,
  button,
  group as fieldset,
  el,
  setText,
} from "./controls.js";
import { Player } from "./player.js";
import { pointIndex, withPointAdded, withPointRemoved } from "./point-list.js";
import {
  inputListSeparator,
  localeDecimal,
  parseNumberInput,
  splitNumberList,
  shownNumbers,
} from "./format.js";
import { t } from "./strings.js";
import { errorText } from "./core-errors.js";

/** Nodes placed side by side in whatever holds the control (a fieldset or the panel). */
function fragment(...nodes) {
  const f = document.createDocumentFragment();
  f.append(...nodes);
  return f;
}

/** A slider's options for a whole-number field (a count, a degree): steps of 1, written and kept as integers. */
export const INTEGER_SLIDER = Object.freeze({
  step: 1,
  format: (v) => String(Math.round(v)),
  round: Math.round,
});

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
 * @param {boolean | object} [o.player] add the step / play buttons (Player options if an
 *   object; `stepBackTitle` / `stepTitle` are strings.js keys, resolved at build time).
 * @param {string | ((text: string, state) => string)} [o.error] key of the message for typed
 *   text that is out of range (given `{ value, min, max, field }`), or the message itself.
 * @param {boolean} [o.onRelease] apply the value only when the slider is released or a value is
 *   typed, not while it is dragged (a field that rebuilds the model, such as the degree).
 * @param {(v: number, state) => string | null} [o.refuse] the message when the state cannot
 *   take the value (then it is reported and the slider shows the field again), else null.
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
        inputLabel: t(o.input ?? `${o.label}.input`, o.inputParams && shownNumbers(o.inputParams)),
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
          const message =
            typeof o.error === "function"
              ? o.error(text, ui.state)
              : t(o.error ?? "control.badNumber", { value: text, min: a, max: b, field });
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
        viewChanged: (view) => player?.attach(view),
        destroy: () => player?.destroy(),
      };
    },
  };
}

/** A checkbox bound to a boolean field. */
export function checkbox(field, { label, name = field }) {
  return {
    build(ui) {
      const box = checkboxElement({
        label: t(label),
        name,
        checked: ui.state[field],
        onChange: (on) => ui.set(field, on),
      });
      return { element: box.element, sync: (state) => box.set(state[field]) };
    },
  };
}

/**
 * One choice out of a few, bound to a field: radio buttons (`data-control=name`, each row
 * `data-choice=value`). `options`: `[{ value, label }]` with strings.js keys as labels; values
 * may be numbers (a degree), shown as text. `refuse(value, state)` → a message when the state
 * cannot take the value (reported; the buttons show the field again), else null. `set(ui,
 * value)` as for `slider` (then the buttons show the field's value again). `rebuild: true`: a
 * choice the model is built from (a rule it enforces on the state): the new state is built
 * first (`ui.replace`) and recorded only when the core accepts it.
 */
export function choice(
  field,
  { options, name = field, refuse = null, set = null, rebuild = false },
) {
  return {
    build(ui) {
      const choose = (value) => {
        if (!rebuild) {
          ui.set(field, value);
          return;
        }
        const next = structuredClone(ui.state);
        next[field] = value;
        try {
          ui.replace(next);
        } catch (err) {
          control.set(ui.state[field]);
          ui.status(errorText(err), "error");
        }
      };
      const control = radios({
        options: options.map((option) => ({ value: String(option.value), label: t(option.label) })),
        value: String(ui.state[field]),
        name,
        onChange: (text) => {
          const value = options.find((option) => String(option.value) === text).value;
          const refusal = refuse?.(value, ui.state);
          if (refusal) ui.status(refusal, "error");
          else if (set) set(ui, value);
          else return choose(value);
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
 * of the tooltips. The messages also get the state's fields as parameters. `companions:
 * { weights: 1 }` names lists with one entry per point (a rational curve's weights): a new
 * point gets the value given, a removed point takes its entry along.
 */
export function pointButtons(field, o) {
  const {
    min,
    max,
    prefix,
    minKey = `${prefix}.minPoints`,
    maxKey = `${prefix}.maxPoints`,
    params = () => ({}),
  } = o;
  const {
    addTitle = "control.addPoint.title",
    removeTitle = "control.removePoint.title",
    adjust = null,
    more = [],
  } = o;
  const { companions = {} } = o;
  const least = typeof min === "function" ? min : () => min;
  return {
    build(ui) {
      /** Copies of the companion lists with their value inserted at `at` (`insert`), or entry `at` removed. */
      const alongside = (at, insert) => {
        const lists = {};
        for (const [name, value] of Object.entries(companions)) {
          lists[name] = ui.state[name].slice();
          if (insert) lists[name].splice(at, 0, value);
          else lists[name].splice(at, 1);
        }
        return lists;
      };
      const replace = (points, lists) => {
        let state = { ...ui.state, ...lists, [field]: points };
        if (adjust) state = adjust(state, ui);
        try {
          ui.replace(state);
          return true;
        } catch (err) {
          ui.status(errorText(err), "error");
          return false;
        }
      };
      const apply = (next, lists = {}) => {
        const done = o.apply ? o.apply(ui, next.points) : replace(next.points, lists);
        // A 3D figure's handles may run over several lists: the new point's handle index.
        const handle = ui.handles?.source.handleOf?.(field, next.index) ?? next.index;
        if (done) ui.handles?.select(handle);
      };
      const refuse = (key, limits) =>
        ui.status(t(key, { ...ui.state, ...limits, ...params(ui.state) }), "error");
      ui.pointList = {
        field,
        add(i) {
          const next = withPointAdded(ui.state[field], i, max, ui.view.scale);
          if (next) apply(next, alongside(next.index, true));
          else refuse(maxKey, { max });
        },
        remove(i) {
          const next = withPointRemoved(ui.state[field], i, least(ui.state));
          if (next) apply(next, alongside(pointIndex(ui.state[field], i), false));
          else refuse(minKey, { min: least(ui.state) });
        },
      };
      const selected = () => ui.handles?.selected ?? -1;
      const addButton = button({
        label: t("control.addPoint"),
        title: t(addTitle),
        name: "add-point",
        onClick: () => ui.pointList.add(selected()),
      });
      const removeButton = button({
        label: t("control.removePoint"),
        title: t(removeTitle),
        name: "remove-point",
        onClick: () => ui.pointList.remove(selected()),
      });
      const others = more.map((a) =>
        button({
          label: t(a.label),
          title: a.title ? t(a.title) : undefined,
          name: a.name,
          onClick: () => a.run(ui),
        }),
      );
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
 * A line of text computed from the state and data (`text(state, data)`), `data-info=name` (none
 * when `name` is null); `kind` "note" (default) or "readout" (the larger figure of merit); `live`
 * makes it a polite live region; `data(state, values)` → `{ key: text }` sets data attributes
 * beside the text (exact numbers for tests, e.g. `data-gap-ab`), removing those it no longer
 * returns.
 */
export function readout(name, text, { kind = "note", live = false, data = null } = {}) {
  return {
    build(ui) {
      const className = kind === "readout" ? "sl-readout" : "sl-note";
      const node = el("p", {
        class: className,
        dataset: name ? { info: name } : null,
        "aria-live": live ? "polite" : null,
      });
      let keys = [];
      return {
        element: node,
        sync(state, values) {
          setText(node, text(state, values, ui));
          if (!data) return;
          const attributes = data(state, values);
          for (const key of keys) if (!(key in attributes)) delete node.dataset[key];
          for (const [key, value] of Object.entries(attributes)) {
            if (value === null || value === undefined) delete node.dataset[key];
            else node.dataset[key] = value;
          }
          keys = Object.keys(attributes);
        },
      };
    },
  };
}

/**
 * A control shown only while `when(state, data)` holds (e.g. the settings of the chosen option,
 * or what only a computed value allows: the Bézier form of a polynomial curve).
 */
export function shownWhen(when, item) {
  return {
    build(ui) {
      const part = item.build(ui);
      return {
        ...part,
        sync(state, data) {
          part.element.hidden = !when(state, data);
          part.sync?.(state, data);
        },
      };
    },
  };
}

/**
 * A row of buttons, `[{ name, label, params?, title?, run(ui), disabled?(state, data) }]`
 * (`data-action=name`; `params` fill the label's placeholders); `title` (legend key) makes it a
 * titled group. `disabled` is re-read after every change.
 */
export function actions(list, { title = null } = {}) {
  return {
    build(ui) {
      const buttons = list.map((a) =>
        button({
          label: t(a.label, a.params),
          title: a.title ? t(a.title) : undefined,
          name: a.name,
          onClick: () => a.run(ui),
        }),
      );
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
 * (`data-control=name`) showing `state[field]` as `format(v)` (default: the number with the
 * language's decimal separator) joined by spaces ("; " with a decimal comma), and a help line
 * `help(state)` under it. Enter (or leaving the box) reads numbers or fractions separated by
 * spaces, commas or semicolons; a part that is no number is reported (`control.badNumber`), else
 * `apply(ui, values)` (default `ui.set(field, values)`) gets the list. The box is not rewritten
 * while it has the focus.
 */
export function numberList(
  field,
  { label, name = field, format = (v) => localeDecimal(String(v)), help = null, apply = null },
) {
  return {
    build(ui) {
      const id = `sl-${name}-${Math.random().toString(36).slice(2, 8)}`;
      const input = el("input", {
        type: "text",
        id,
        class: "sl-value sl-wide",
        inputmode: "decimal",
        spellcheck: "false",
        "aria-describedby": help ? `${id}-help` : null,
      });
      const note = help ? el("p", { class: "sl-note", id: `${id}-help` }) : null;
      const read = () => {
        const parts = splitNumberList(input.value);
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
      const focused = () =>
        document.activeElement === input || input.getRootNode().activeElement === input;
      const row = el(
        "div",
        { class: "sl-control", dataset: { control: name } },
        el("label", { for: id, text: t(label) }),
        input,
      );
      return {
        element: fragment(row, ...(note ? [note] : [])),
        sync(state) {
          const text = state[field].map((v) => format(v)).join(inputListSeparator());
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
