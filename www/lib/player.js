/**
 * Animation of one parameter (t of a Bézier curve, u of a B-spline) with the buttons
 * "step back", "play/pause" and "step" (ui.md: about 0.25 of the range per second, steps of
 * 1/16). Space plays and pauses while the figure has focus.
 *
 * `prefers-reduced-motion` is honoured (ui.md: nothing plays by itself): playback starts on a
 * click or Space, and `autoplay: true` is ignored when the reader asked for reduced motion.
 * The first animation frame's timestamp may be earlier than the `performance.now()` taken in
 * play(); the parameter never moves backwards.
 *
 *   const player = new Player(view, {
 *     get: () => work.t,
 *     set: (value, final) => setT(value, final), // final: a finished change, commit it
 *     stopped: () => ctx.commit(work),           // playback stopped: record where
 *   });
 *   group(null, tSlider.element, player.element);
 */
import { button, el } from "./controls.js";
import { t } from "./strings.js";
import { prefersReducedMotion } from "./theme.js";

/** Playback speed: this fraction of the range per second (ui.md: about 0.25 t per second). */
export const PLAY_FRACTION_PER_SECOND = 0.25;
/** The step buttons move to the previous/next point of a grid of this fraction of the range. */
export const STEP_FRACTION = 1 / 16;
/** Slack when snapping to the step grid, so 0.25 counts as on the grid. */
const GRID_SLACK = 1e-9;
/** The default range [0, 1] (t of a Bézier curve), one array for every call. */
const UNIT_RANGE = Object.freeze([0, 1]);

export class Player {
  /**
   * @param {View} view the figure (Space on its canvas plays/pauses).
   * @param {object} o
   * @param {() => number} o.get the parameter's current value.
   * @param {(value: number, final: boolean) => void} o.set shows a new value; `final` when it
   *   is a finished change (a step) rather than a frame of the animation.
   * @param {() => void} [o.stopped] the animation stopped (pause, end, a step): commit the state.
   * @param {() => [number, number]} [o.range] the parameter's range, default [0, 1].
   * @param {boolean} [o.playable] false: only the two step buttons (no play button, no Space).
   * @param {string} [o.stepBackTitle] @param {string} [o.stepTitle] tooltips of the step buttons.
   * @param {boolean} [o.autoplay] start playing at once — unless `prefers-reduced-motion`.
   */
  constructor(
    view,
    {
      get,
      set,
      stopped = () => {},
      range = () => UNIT_RANGE,
      playable = true,
      autoplay = false,
      stepBackTitle = t("control.stepBack.title"),
      stepTitle = t("control.stepForward.title"),
    },
  ) {
    this.view = view;
    this.get = get;
    this.set = set;
    this.stopped = stopped;
    this.range = range;
    this.playing = false;
    this.lastTime = 0;
    this.frameId = 0;
    this.backButton = button({
      label: t("control.stepBack"),
      title: stepBackTitle,
      name: "step-back",
      onClick: () => this.step(-1),
    });
    this.forwardButton = button({
      label: t("control.stepForward"),
      title: stepTitle,
      name: "step",
      onClick: () => this.step(1),
    });
    this.playButton = playable
      ? button({
          label: t("control.play"),
          name: "play",
          pressed: false,
          onClick: () => this.toggle(),
        })
      : null;
    /** The button row to place in the side panel: step back, play/pause, step. */
    this.element = el(
      "div",
      { class: "sl-button-row" },
      this.backButton,
      this.playButton,
      this.forwardButton,
    );

    this.tick = (now) => {
      if (!this.playing) return;
      // The first frame's timestamp may precede the performance.now() of play(): never step back.
      const dt = Math.max(0, now - this.lastTime) / 1000;
      this.lastTime = Math.max(this.lastTime, now);
      const [a, b] = this.range();
      const next = Math.min(b, Math.max(a, this.get() + PLAY_FRACTION_PER_SECOND * (b - a) * dt));
      this.set(next, false);
      if (next >= b) this.stop();
      else this.frameId = requestAnimationFrame(this.tick);
    };
    this.onKey = (event) => {
      if (event.key === " " && !event.ctrlKey && !event.metaKey) {
        this.toggle();
        event.preventDefault();
      }
    };
    if (playable) view.canvas.addEventListener("keydown", this.onKey);
    if (autoplay && !prefersReducedMotion()) this.play();
  }

  /** Starts playing (from the start of the range when at its end). */
  play() {
    if (this.playing || !this.playButton) return;
    const [a, b] = this.range();
    if (this.get() >= b) this.set(a, false);
    this.playing = true;
    this.playButton.textContent = t("control.pause");
    this.playButton.setAttribute("aria-pressed", "true");
    this.lastTime = performance.now();
    this.frameId = requestAnimationFrame(this.tick);
  }

  /** Stops playing and calls `stopped` (to record where); nothing when not playing. */
  stop() {
    if (!this.playing) return;
    this.playing = false;
    cancelAnimationFrame(this.frameId);
    this.playButton.textContent = t("control.play");
    this.playButton.setAttribute("aria-pressed", "false");
    this.stopped();
  }

  toggle() {
    if (this.playing) this.stop();
    else this.play();
  }

  /** Stops, then moves to the previous (−1) or next (+1) point of the grid a + k·(b − a)/16. */
  step(direction) {
    this.stop();
    const [a, b] = this.range();
    const h = (b - a) * STEP_FRACTION;
    const s = (this.get() - a) / h;
    const k = direction > 0 ? Math.floor(s + GRID_SLACK) + 1 : Math.ceil(s - GRID_SLACK) - 1;
    this.set(Math.min(b, Math.max(a, a + k * h)), true);
  }

  /** Space plays on `view`'s canvas from now on (the demo's figure was made anew). */
  attach(view) {
    this.view.canvas.removeEventListener("keydown", this.onKey);
    this.view = view;
    if (this.playButton) view.canvas.addEventListener("keydown", this.onKey);
  }

  /** Stops the animation without recording anything (the demo is going away). */
  destroy() {
    this.playing = false;
    cancelAnimationFrame(this.frameId);
    this.view.canvas.removeEventListener("keydown", this.onKey);
  }
}
