/**
 * An exercise (exercises/index.js) around its demo: the task above the figure, a Check button
 * that asks the core whether the current state reaches the goal (`exercise.check(sl, state)`),
 * and a Hint button. The demo is the ordinary one, mounted by the shell, so everything the
 * student does (drag, type, undo) is the demo's own; only checking is added.
 */
import { el, setText } from "./controls.js";
import { mountDemo } from "./shell.js";
import { t } from "./strings.js";
import { errorText } from "./core-errors.js";

/**
 * Mounts `exercise` with its loaded `demo` in `root`. `options` are mountDemo's (sl, state,
 * mode, headingLevel, onCommit, shareUrl, controls, theme). Returns the demo's controller with
 * `check()` (runs the check, shows and returns its result) and `destroy()`.
 */
export function mountExercise(root, exercise, demo, options) {
  const prefix = `exercise.${exercise.id}`;
  const result = el("p", { class: "sl-exercise-result", role: "status", "aria-live": "polite" });
  const hint = el("p", { class: "sl-exercise-hint", hidden: true, text: t(`${prefix}.hint`) });
  const checkButton = el("button", {
    class: "sl-button sl-exercise-check",
    type: "button",
    dataset: { action: "exercise-check" },
    text: t("exercise.check"),
    onclick: () => check(),
  });
  const hintButton = el("button", {
    class: "sl-button",
    type: "button",
    dataset: { action: "exercise-hint" },
    "aria-expanded": "false",
    text: t("exercise.hint"),
    onclick: () => {
      hint.hidden = !hint.hidden;
      hintButton.setAttribute("aria-expanded", String(!hint.hidden));
    },
  });
  const box = el(
    "section",
    { class: "sl-exercise", "aria-label": t("exercise.label") },
    el(
      "p",
      { class: "sl-exercise-title" },
      el("strong", { text: t("exercise.label") }),
      ` · ${t(`${prefix}.title`)}`,
    ),
    el("p", { class: "sl-exercise-task", text: t(`${prefix}.task`) }),
    el("div", { class: "sl-exercise-actions" }, checkButton, hintButton),
    hint,
    result,
  );
  const slot = el("div");
  root.replaceChildren(box, slot);
  const controller = mountDemo(slot, demo, options);
  // The box sits inside the demo's section so the demo's styles (and an embed's shadow root) apply.
  controller.element.prepend(box);

  function check() {
    let outcome;
    try {
      outcome = exercise.check(options.sl, controller.state);
    } catch (err) {
      outcome = { solved: false, detail: errorText(err) };
    }
    result.dataset.kind = outcome.solved ? "solved" : "not-yet";
    setText(
      result,
      outcome.solved ? t("exercise.solved") : t(`${prefix}.notYet`, { detail: outcome.detail }),
    );
    return outcome;
  }

  const destroy = controller.destroy;
  return Object.assign(controller, {
    check,
    destroy() {
      destroy();
      box.remove();
    },
  });
}
