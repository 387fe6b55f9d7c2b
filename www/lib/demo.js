/**
 * The declarative demo contract: a demo module says *what* it shows and what can be changed;
 * this runtime does the wiring that every demo used to write by hand.
 *
 * A declarative demo module exports (besides `id`, `strings`, `section`, `defaultState`):
 *
 * | export | what |
 * |---|---|
 * | `fields` | `{ name: check }` — one checker per state field (`validate.js` `field.*`); the state's validation |
 * | `check(state)` | optional: rules across fields (throw an Error naming the field) |
 * | `derive` | `{ from: [fields], build(state, sl) → model, moved?(model, i, xy, state) }`: the wasm objects. `build` runs when a field in `from` changed (or the state came from outside); every value of the model with a `free()` is freed when it is replaced. `moved` updates the model in place while a handle is dragged (`setControlPoint`), instead of a rebuild |
 * | `compute` | `{ name: [[fields], (state, data, ui) → value] }`: what the core returns for drawing, recomputed only when one of those fields (or the model) changed, at most once per frame. `data` holds the model's and the computed values by name |
 * | `controls` | the side panel, top to bottom: descriptors from `panel.js` (`slider`, `checkbox`, `choice`, `pointButtons`, `readout`, `actions`, `group` …) bound to state fields |
 * | `figure` | `{ bounds(state, data), insets?(w, h, scale, state, data), handles?: { field, label?(i), constraint?(i) } }`: the View (see view.js) and its handles on the list of `[x, y]` points in `state[field]` |
 * | `draw(r, view, state, data)` | the figure, on canvas and SVG alike; allocates nothing |
 * | `formula(state, data)` | optional: the formula panel's TeX lines (only changed lines are typeset) |
 * | `label(state, data)` | optional: the figure's accessible name |
 * | `setup(ui)` | optional escape hatch: builds what is particular to the demo (a table, an extra pointer tool) and returns `{ update?(state, data), destroy?() }` |
 *
 * Changes flow one way: a control, handle or tool calls `ui.set(field, value, final)`; the field
 * is marked changed; before the next frame the runtime rebuilds the model if `derive.from`
 * names the field, recomputes the `compute` cells that depend on it, syncs the controls, and
 * calls `formula`, `label` and `setup`'s `update` once. A final change is committed (undo step,
 * URL). States from outside (undo, reset, link, file) rebuild everything, model first: when the
 * core refuses the state, nothing has changed and the shell keeps the last good one.
 */
import { FormulaPanel } from "./formula.js";
import { Handles, pointHandles } from "./handles.js";
import { t } from "./strings.js";

/** True for a module written to this contract (rather than an old-style `mount`). */
export function isDeclarative(demo) {
  return typeof demo.mount !== "function" && typeof demo.draw === "function";
}

/** The validation of a declarative demo: every field checked, no unknown field, then `check`. */
export function validateDeclared(demo, state) {
  if (state === null || typeof state !== "object" || Array.isArray(state)) throw new Error(t("error.notObject"));
  for (const name of Object.keys(state)) {
    if (!(name in demo.fields)) throw new Error(t("error.unknownField", { field: name }));
  }
  for (const [name, check] of Object.entries(demo.fields)) check(state, name);
  demo.check?.(state);
}

/** Frees every value of a model that has a `free()` (wasm objects); arrays of them too. */
function freeModel(model) {
  if (!model) return;
  for (const value of Object.values(model)) {
    if (Array.isArray(value)) value.forEach((item) => item?.free?.());
    else value?.free?.();
  }
}

/**
 * Mounts a declarative demo in the shell's slots; returns `{ update(state), destroy() }` as an
 * old-style `mount` does.
 */
export function mountDeclared(demo, initialState, ctx) {
  const { sl } = ctx;
  const derive = demo.derive;
  const cells = Object.entries(demo.compute ?? {});
  let work = structuredClone(initialState);
  let model = derive.build(work, sl);
  /**
   * What draw and the panels read: the model's values and the computed cells by name, and
   * `sl` (the wasm package) and `handles` (drawn by the demo where it wants them).
   */
  const data = { ...model, sl, handles: null };
  /** Fields changed since the last frame; `null` after an outside state (everything changed). */
  let changed = null;
  let modelStale = false;
  let built = [];

  const figureSpec = demo.figure;
  const view = ctx.createFigure({
    draw: (r, v) => demo.draw(r, v, work, data),
    bounds: () => figureSpec.bounds(work, data),
    label: "",
    insets: figureSpec.insets ? (w, h, scale) => figureSpec.insets(w, h, scale, work, data) : null,
  });

  /** What controls, handles and tools get: the state, its setter and the shell's services. */
  const ui = {
    sl,
    ctx,
    view,
    get state() {
      return work;
    },
    data,
    handles: null,
    /** Sets a field; `final` commits it (undo step, URL). `merge` joins repeated key presses. */
    set(field, value, final = true, merge = null) {
      work[field] = value;
      markChanged(field);
      if (final) ctx.commit(work, merge);
    },
    /** Marks a field changed after mutating it in place (a dragged point). */
    touch: markChanged,
    /** Records the working state as it is now. */
    commit: (merge = null) => ctx.commit(work, merge),
    /** Replaces the whole working state (after an add/remove): the model is rebuilt first. */
    replace(next, final = true) {
      const nextModel = derive.build(next, sl); // throws before anything changes
      swapModel(nextModel);
      work = next;
      changed = null;
      view.requestDraw();
      refresh();
      if (final) ctx.commit(work);
    },
    status: ctx.status,
    requestDraw: () => view.requestDraw(),
  };

  function markChanged(field) {
    if (changed) changed.add(field);
    if (derive.from.includes(field)) modelStale = true;
    view.requestDraw();
  }

  function swapModel(nextModel) {
    const old = model;
    model = nextModel;
    for (const key of Object.keys(old)) delete data[key];
    Object.assign(data, model);
    freeModel(old);
  }

  const touches = (deps) => changed === null || deps.some((field) => changed.has(field));

  /** Brings the model, the cells, the controls and the panels up to date (once per frame). */
  function refresh() {
    if (changed !== null && changed.size === 0 && !modelStale) return;
    if (modelStale) {
      modelStale = false;
      try {
        swapModel(derive.build(work, sl));
      } catch (err) {
        ctx.status(err.message, "error");
      }
      changed = null;
    }
    for (const [name, [deps, run]] of cells) {
      if (touches(deps)) data[name] = run(work, data, ui);
    }
    for (const control of built) control.sync?.(work, data);
    if (demo.formula) formula.set(demo.formula(work, data));
    if (demo.label) view.setLabel(demo.label(work, data));
    extra.update?.(work, data);
    changed = new Set();
  }

  // ------------------------------------------------------------ figure parts, handles, panel
  const handleSpec = figureSpec.handles;
  if (handleSpec) {
    const moved = derive.moved
      ? (i, xy) => {
          derive.moved(model, i, xy, work);
          if (changed) changed.add(handleSpec.field);
          view.requestDraw();
        }
      : () => markChanged(handleSpec.field);
    ui.handles = new Handles(view, {
      ...pointHandles(() => work[handleSpec.field], moved, handleSpec.label ?? null),
      constraint: handleSpec.constraint,
      commit: (kind, i, merge) => ctx.commit(work, merge),
      add: (i) => ui.pointList?.add(i),
      remove: (i) => ui.pointList?.remove(i),
    });
    data.handles = ui.handles;
  }
  built = (demo.controls ?? []).map((descriptor) => descriptor.build(ui));
  ctx.slots.controls.append(...built.map((control) => control.element).filter(Boolean));
  const formula = demo.formula ? new FormulaPanel(ctx.slots.formula) : null;
  const extra = demo.setup?.(ui) ?? {};
  // After the handles' hook, which applies the newest pointer position first.
  view.beforeFrame(() => refresh());
  refresh();

  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const nextModel = derive.build(state, sl); // throws before anything changes
      for (const control of built) control.stop?.();
      swapModel(nextModel);
      modelStale = false;
      work = structuredClone(state);
      if (ui.handles) {
        ui.handles.forgetPointer();
        if (ui.handles.selected >= ui.handles.source.count()) ui.handles.select(-1);
      }
      changed = null;
      view.requestDraw();
      refresh();
    },
    destroy() {
      extra.destroy?.();
      for (const control of built) control.destroy?.();
      ui.handles?.destroy();
      formula?.destroy();
      freeModel(model);
    },
  };
}
