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
 * @param {number} o.step slider resolution (log10 units for `log`).
 * @param {boolean} [o.log] logarithmic slider; its `aria-valuetext` is the real value.
 * @param {(v: number) => string} [o.format] text in the box.
 * @param {(v: number, typed: boolean) => number} [o.round] the value kept from a slider move.
 * @param {boolean | object} [o.player] add the step / play buttons (Player options if an object).
 * @param {string} [o.error] key of the message for typed text that is out of range.
 */
export function slider(field, o) {
  return {
    build(ui) {
      const fixed = o.range ? null : [o.min, o.max];
      const range = () => fixed ?? o.range(ui.state, ui.data);
      const [min, max] = range();
      let player = null;
      const control = sliderElement({
        label: t(o.label),
        inputLabel: t(o.input ?? `${o.label}.input`, o.inputParams),
        name: o.name ?? field,
        min,
        max,
        step: o.step,
        log: o.log,
        format: o.format,
        value: ui.state[field],
        onChange: (value, final) => {
          player?.stop();
          const typed = control.typing();
          ui.set(field, o.round ? o.round(value, typed) : value, final);
        },
        onError: (text) => {
          const [a, b] = range();
          ui.status(t(o.error ?? "control.badNumber", { value: text, min: a, max: b }), "error");
        },
      });
      if (o.player) {
        player = new Player(ui.view, {
          ...(typeof o.player === "object" ? o.player : {}),
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
              control.setRange(a, b);
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
 * One choice out of a few, bound to a string field: radio buttons (`data-control=name`, each row
 * `data-choice=value`). `options`: `[{ value, label }]` with strings.js keys as labels.
 */
export function choice(field, { options, name = field }) {
  return {
    build(ui) {
      const control = radios({
        options: options.map((option) => ({ value: option.value, label: t(option.label) })),
        value: ui.state[field],
        name,
        onChange: (value) => ui.set(field, value),
      });
      return { element: control.element, sync: (state) => control.set(state[field]) };
    },
  };
}

/**
 * The Add point / Remove point buttons (and `+` / Delete on the figure) for the handles' point
 * list: the new list is built into a new model first (`ui.replace`), then the handle is selected.
 * A full or minimal list reports `<prefix>.maxPoints` / `.minPoints`. The buttons are disabled at
 * the limits.
 */
export function pointButtons(field, { min, max, prefix }) {
  return {
    build(ui) {
      const apply = (next) => {
        const state = { ...ui.state, [field]: next.points };
        try {
          ui.replace(state);
        } catch (err) {
          ui.status(err.message, "error");
          return;
        }
        ui.handles?.select(next.index);
      };
      const refuse = (kind, limit) => ui.status(t(`${prefix}.${kind}Points`, { [kind]: limit }), "error");
      ui.pointList = {
        add(i) {
          const next = withPointAdded(ui.state[field], i, max, ui.view.scale);
          if (next) apply(next);
          else refuse("max", max);
        },
        remove(i) {
          const next = withPointRemoved(ui.state[field], i, min);
          if (next) apply(next);
          else refuse("min", min);
        },
      };
      const selected = () => ui.handles?.selected ?? -1;
      const addButton = button({ label: t("control.addPoint"), title: t("control.addPoint.title"), name: "add-point", onClick: () => ui.pointList.add(selected()) });
      const removeButton = button({ label: t("control.removePoint"), title: t("control.removePoint.title"), name: "remove-point", onClick: () => ui.pointList.remove(selected()) });
      return {
        element: el("div", { class: "sl-button-row" }, addButton, removeButton),
        sync(state) {
          const count = state[field].length;
          addButton.disabled = count >= max;
          removeButton.disabled = count <= min;
        },
      };
    },
  };
}

/**
 * A line of text computed from the state and data (`text(state, data)`), `data-info=name`;
 * `kind` "note" (default) or "readout" (the larger figure of merit).
 */
export function readout(name, text, { kind = "note" } = {}) {
  return {
    build(ui) {
      const node = el("p", { class: kind === "readout" ? "sl-readout" : "sl-note", dataset: { info: name } });
      return { element: node, sync: (state, data) => setText(node, text(state, data, ui)) };
    },
  };
}

/**
 * A row of buttons, `[{ name, label, title?, run(ui) }]` (`data-action=name`); `title` (legend
 * key) makes it a titled group.
 */
export function actions(list, { title = null } = {}) {
  return {
    build(ui) {
      const buttons = list.map((a) => button({ label: t(a.label), title: a.title ? t(a.title) : undefined, name: a.name, onClick: () => a.run(ui) }));
      const row = el("div", { class: "sl-button-row" }, buttons);
      return { element: title ? fieldset(t(title), row) : row };
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
