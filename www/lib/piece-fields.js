/**
 * The typed pieces of a piecewise curve as a panel control (a `controls` entry of a declarative
 * demo, see demo.js): one fieldset per piece with a text box per field (x(t), y(t), from, to),
 * and Add / Remove buttons for the last piece. The state field holds `[{ x, y, from, to }, …]`
 * (texts in the expression language); piece i's `to` and piece i + 1's `from` are one joint, so
 * typing either writes both.
 *
 * Every keystroke builds the candidate state through `ui.replace` (the model first: the core's
 * parser and `parametricCurve`). A refusal is the core's coded Error with params `{ piece, field,
 * start, end }` (start/end in UTF-16 units, a JS string's indices): the box gets
 * `aria-invalid`, the characters start … end are underlined in an echo line under it, the
 * reason (lib/core-errors.js `problemText`, in the page's language; the place is named here) is
 * written under the piece and in the status line, and the state keeps the last good curve. A good text is committed with a
 * merge key per box, so one undo step takes back one box's typing.
 */
import { el, setText, button } from "./controls.js";
import { markedText } from "./refusal-mark.js";
import { t } from "./strings.js";
import { errorText, problemText } from "./core-errors.js";
import { CYCLE } from "./theme.js";

/**
 * The piece editor bound to `state[field]`. `o`: `prefix` (strings: `<prefix>.piece`,
 * `.field.<name>`, `.field.name`, `.addPiece`, `.removePiece`, `.maxPieces`, `.minPieces`,
 * `.fieldName.<name>`, `.typingError`), `names` (the fields of a piece, in order), `min`, `max` (pieces),
 * `added(state, data) → piece` (the piece Add appends).
 */
export function pieceFields(field, { prefix, names, min, max, added }) {
  return {
    build(ui) {
      const list = el("div", { class: "sl-pieces" });
      /** Per piece: `{ set, boxes: { name: { input, echo, shown } }, message }`. */
      let rows = [];
      /** A keystroke's state is being applied (else a sync shows a change from elsewhere). */
      let typing = false;
      /** The status line shows a refusal of ours (cleared by the next accepted text). */
      let reported = false;
      const focused = (input) => input.getRootNode().activeElement === input;
      const fieldLabel = (name) => t(`${prefix}.field.${name}`);
      const fieldName = (name) => t(`${prefix}.fieldName.${name}`);

      /** Underlines `start … end` of the box's text in its echo line (an empty range: one caret). */
      function mark(box, start, end) {
        box.echo.replaceChildren(...markedText(box.input.value, start, end));
        box.echo.hidden = false;
        box.input.setAttribute("aria-invalid", "true");
      }

      function clear(row, box) {
        box.echo.hidden = true;
        box.echo.replaceChildren();
        box.input.removeAttribute("aria-invalid");
        if (!Object.values(row.boxes).some((b) => b.input.hasAttribute("aria-invalid")))
          setText(row.message, "");
      }

      function clearAll() {
        for (const row of rows) for (const box of Object.values(row.boxes)) clear(row, box);
      }

      /** The core's refusal shown on the box it names (else on the box typed in). */
      function refuse(err, i, name) {
        const p = err?.params ?? {};
        const k = Number.isInteger(p.piece) && rows[p.piece] ? p.piece : i;
        const where = rows[k].boxes[p.field] ? p.field : name;
        const box = rows[k].boxes[where];
        const start = Number.isInteger(p.start) ? p.start : 0;
        const end = Number.isInteger(p.end) ? p.end : box.input.value.length;
        mark(box, start, end);
        const message = t(`${prefix}.typingError`, {
          i: k + 1,
          field: fieldName(where),
          message: problemText(err),
        });
        setText(rows[k].message, message);
        ui.status(message, "error");
        reported = true;
      }

      /** The state with box (i, name) holding `text` (and the joint's other bound with it). */
      function candidate(i, name, text) {
        const pieces = structuredClone(ui.state[field]);
        pieces[i][name] = text;
        if (name === "to" && i + 1 < pieces.length) pieces[i + 1].from = text;
        if (name === "from" && i > 0) pieces[i - 1].to = text;
        return { ...ui.state, [field]: pieces };
      }

      function typed(i, name) {
        const row = rows[i];
        const box = row.boxes[name];
        typing = true;
        try {
          ui.replace(candidate(i, name, box.input.value), false);
        } catch (err) {
          refuse(err, i, name);
          return;
        } finally {
          typing = false;
        }
        // Accepted: every box that now shows the state's text is clean again.
        for (const [k, r] of rows.entries()) {
          for (const [n, b] of Object.entries(r.boxes)) {
            if (b.input.value === ui.state[field][k][n]) clear(r, b);
          }
        }
        if (reported) ui.status("", "info");
        reported = false;
        ui.commit(`${field}-${i}-${name}`);
      }

      function makeRow(i) {
        const boxes = {};
        const message = el("p", {
          class: "sl-note sl-expr-message",
          id: `sl-piece-msg-${Math.random().toString(36).slice(2, 8)}-${i}`,
          "aria-live": "polite",
        });
        const parts = names.map((name) => {
          const id = `sl-piece-${Math.random().toString(36).slice(2, 8)}-${i}-${name}`;
          const input = el("input", {
            type: "text",
            id,
            class: `sl-value sl-expr sl-expr-${name}`,
            spellcheck: "false",
            autocomplete: "off",
            autocapitalize: "off",
            dataset: { piece: String(i), field: name },
            "aria-label": t(`${prefix}.field.name`, { field: fieldName(name), i: i + 1 }),
            "aria-describedby": message.id,
          });
          const echo = el("div", { class: "sl-expr-echo", "aria-hidden": "true", hidden: true });
          boxes[name] = { input, echo, shown: null };
          input.addEventListener("input", () => typed(i, name));
          input.addEventListener("keydown", (event) => {
            if (event.key === "Enter") typed(i, name);
          });
          return el(
            "div",
            { class: `sl-expr-cell sl-expr-cell-${name}` },
            el("label", { for: id, text: fieldLabel(name) }),
            input,
            echo,
          );
        });
        const swatch = el("span", { class: `sl-swatch sl-swatch-${i % CYCLE.length}` });
        const set = el(
          "fieldset",
          { class: "sl-piece", dataset: { piece: String(i) } },
          el("legend", {}, swatch, t(`${prefix}.piece`, { i: i + 1 })),
          el("div", { class: "sl-expr-grid" }, parts),
          message,
        );
        return { set, boxes, message };
      }

      const addButton = button({
        label: t(`${prefix}.addPiece`),
        title: t(`${prefix}.addPiece.title`),
        name: "add-piece",
        onClick: () => change(+1),
      });
      const removeButton = button({
        label: t(`${prefix}.removePiece`),
        title: t(`${prefix}.removePiece.title`),
        name: "remove-piece",
        onClick: () => change(-1),
      });

      function change(step) {
        const pieces = structuredClone(ui.state[field]);
        if (step > 0 && pieces.length >= max)
          return ui.status(t(`${prefix}.maxPieces`, { max }), "error");
        if (step < 0 && pieces.length <= min)
          return ui.status(t(`${prefix}.minPieces`, { min }), "error");
        if (step > 0) pieces.push(added(ui.state, ui.data));
        else pieces.pop();
        try {
          ui.replace({ ...ui.state, [field]: pieces });
        } catch (err) {
          ui.status(errorText(err), "error");
          return;
        }
        ui.fit();
        const last = rows[rows.length - 1];
        if (step > 0 && last) last.boxes[names[0]].input.focus();
      }

      return {
        element: el(
          "div",
          { class: "sl-control", dataset: { control: field } },
          list,
          el("div", { class: "sl-button-row" }, addButton, removeButton),
        ),
        sync(state) {
          const pieces = state[field];
          if (rows.length !== pieces.length) {
            rows = pieces.map((_, i) => makeRow(i));
            list.replaceChildren(...rows.map((row) => row.set));
          }
          pieces.forEach((piece, i) => {
            const row = rows[i];
            for (const name of names) {
              const box = row.boxes[name];
              const text = piece[name] ?? "";
              // A change from elsewhere (undo, reset, preset, link, Add / Remove) shows the
              // state's texts everywhere. While the reader types, only the boxes whose text the
              // state changed follow (the joint's other bound); a refused text stays, underlined.
              const changed = box.shown !== text;
              box.shown = text;
              if (!typing || (changed && !focused(box.input))) {
                if (box.input.value !== text) box.input.value = text;
                clear(row, box);
              } else if (box.input.value === text) clear(row, box);
            }
          });
          addButton.disabled = pieces.length >= max;
          removeButton.disabled = pieces.length <= min;
        },
        destroy: clearAll,
      };
    },
  };
}
