/**
 * The declarative demo contract: a demo module says *what* it shows and what can be changed;
 * this runtime does the wiring that every demo used to write by hand.
 *
 * A declarative demo module exports (besides `id`, `strings`, `section`, `defaultState`; the
 * table in lib/README.md shows them with a whole example):
 *
 * - `fields`: `{ name: check }`, one checker per state field (`validate.js` `field.*`), the
 *   state's validation; `check(state)` optional rules across fields (throw naming the field).
 * - `adjust(state)`: optional; after a change by the reader (`ui.set`, `ui.replace`), brings
 *   fields that depend on others back into range in place (u into a domain that shrank).
 * - `derive`: `{ from, build(state, sl, { first }), moved?, weighted?, inPlace? }`, the wasm
 *   objects. `build` runs when a field in `from` changed, or the state came from outside (it
 *   gets a copy it may bring into line; `first` at mount, where there is no last good state);
 *   every value of the model with a `free()` is freed when it is replaced.
 *   `moved(model, i, xy, state, ui)` updates the model in place while a handle is dragged
 *   (`setControlPoint`) instead of a rebuild; `weighted(model, i, w, state, ui)` likewise for
 *   `ui.setWeight(i, w)`; `inPlace: { field: (model, state, ui) }` takes a change of that field
 *   into the model in place (a slider dragged through values).
 * - `compute`: `{ name: [[fields], (state, data, ui) → value] }`, what the core returns for
 *   drawing, recomputed only when one of those fields (or the model) changed, once per frame.
 *   `data` holds the model's and the computed values by name, `sl` and `handles`.
 * - `controls`: the side panel, top to bottom: panel.js descriptors bound to state fields, and
 *   figure parts (`knotRuler`, `parameterStrip`).
 * - `figure`: `{ bounds(state, data), insets?(w, h, scale, state, data), handles?, help? }`, the View
 *   and its handles on the `[x, y]` points of `state[field]`. `handles`: `{ field, label?(i,
 *   state, data), constraint?(i, state, data), accept?(i, x, y, state), select?(i, ui),
 *   polygon?, extra? }` (`help`: the strings.js key of the line under a figure that is drawn
 *   on rather than dragged). With several fields, `field: [a, b]`, the handles run over the lists
 *   in order (P₀ … P₃, then Q₀ … Q₃; `i` counts across them) and `moved` is asked *before* the
 *   point is written: returning `false` refuses the move; `accept` may refuse it before that.
 *   `polygon: false`: the handles form no polygon (label placement). `extra: [{ field, index?,
 *   label, when?(state), accept?(state, x, y), anchor?(state), at?, place? }]` adds handles on
 *   other points (`state[field]` or `state[field][index]`; label a strings.js key), shown while
 *   `when` holds; `anchor(state)` → the [x, y] point such a handle is attached to (an arrow's
 *   foot): its label goes beyond it, and it is no neighbour of the others in label placement;
 *   `at(state, out)` / `place(state, x, y)` put a handle where the state implies (an arrow's tip
 *   p₀ + D₀ of a vector field) and write the field back from a move.
 * - `figure3d` (instead of `figure`): `{ bounds(state, data) → [xmin, ymin, zmin, xmax, ymax,
 *   zmax], scene(state, data) → { surfaces, wireframe, curves }, camera?: { azimuth, elevation }
 *   (the direction of view a state without a camera starts from: first view, Reset; the fit
 *   sets distance and target), handles? }` — a 3D figure (view3d.js; the host awaits
 *   three-loader.js `prepareFigure` first): `scene` says what WebGL draws from the core's arrays
 *   (scene3d.js). `handles`: one entry or a list (handle-lists3d.js): `{ field, axes?,
 *   plane?(state) → [nx, ny, nz, d], label?(index, state, data), showLabel?(index, state, data),
 *   shownWhen?(state), select?(index, ui) }` over the points of `state[field]`, and extra handles
 *   `{ field, at(state, out3), place(state, x, y, z), label }`; `derive.moved(model, index, xyz,
 *   state, ui, field)` gets the list's field, the index in it and a reused Float64Array(3); `+` /
 *   Delete reach the field's `pointButtons`. `draw` is then the 2D layer over the WebGL image
 *   (`view.project`).
 * - `figure` and `figure3d` both, with `dimension(state)` → 2 | 3: each state is shown in the
 *   figure it asks for; the figure, its handles and `setup` are made anew when that changes
 *   (`syncFigureKind`; controls get `viewChanged(view)`; lib/README.md "Both figures").
 * - `draw(r, view, state, data)`: the figure, on canvas and SVG alike; allocates nothing.
 * - `formula(state, data)`, `label(state, data)`: optional; the formula panel's TeX lines (only
 *   changed lines are typeset) and the figure's accessible name.
 * - `setup(ui)`: optional; what is particular to the demo (a table, an extra pointer tool);
 *   returns `{ update?(state, data), destroy?() }`.
 *
 * Changes flow one way: a control, handle or tool calls `ui.set(field, value, final)`; the field
 * is marked changed; before the next frame the runtime rebuilds the model if `derive.from`
 * names the field, recomputes the `compute` cells that depend on it, draws, then syncs the
 * controls and calls `label`, `setup`'s `update` and `formula` once (after the drawing, so the
 * document is restyled and laid out once per frame). A final change is committed (undo step,
 * URL). States from outside (undo, reset, link, file) rebuild everything, model first: when the
 * core refuses the state, nothing has changed and the shell keeps the last good one.
 */
import { FormulaPanel } from "./formula.js";
import { Handles, pointHandles, pointLabel, pointListsHandles } from "./handles.js";
import { Handles3D } from "./handles3d.js";
import { listHandles3 } from "./handle-lists3d.js";
import { t } from "./strings.js";
import { errorText } from "./core-errors.js";
import { figureDimension, figure3dReady, prepareFigure } from "./three-loader.js";
import { now } from "./task-queue.js";

/** The validation of a declarative demo: every field checked, no unknown field, then `check`. */
export function validateDeclared(demo, state) {
  if (state === null || typeof state !== "object" || Array.isArray(state))
    throw new Error(t("error.notObject"));
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
 * Mounts a declarative demo in the shell's slots; returns `{ update(state), destroy() }`: the
 * shell calls `update` with every outside state (undo, reset, link, file) and `destroy` once.
 */
export function mountDeclared(demo, initialState, ctx) {
  const { sl } = ctx;
  const derive = demo.derive;
  const cells = Object.entries(demo.compute ?? {});
  let work = structuredClone(initialState);
  let model = derive.build(work, sl, { first: true });
  /**
   * What draw and the panels read: the model's values and the computed cells by name, and
   * `sl` (the wasm package) and `handles` (drawn by the demo where it wants them).
   */
  const data = { ...model, sl, handles: null };
  /** Fields changed since the last frame; `null` after an outside state (everything changed). */
  let changed = null;
  let modelStale = false;
  /** The panels (controls, label, tables, formula) have not shown the last refresh yet. */
  let panelsStale = false;
  /** The formula panel (made after the controls). */
  let formula = null;

  /** Records the working state (undo step, URL); the formula's MathML catches up at once. */
  function commit(merge = null) {
    ctx.commit(work, merge);
    formula?.settle();
  }
  let built = [];

  // A 3D figure (`figure3d`, view3d.js) or the 2D View (`figure`); a demo with both shows the
  // kind its `dimension(state)` asks for and makes the figure anew when that changes.
  let is3d = false;
  let figureSpec = null;
  let view = null;
  /** The 3D renderer's preparation for a 3D state shown in 2D meanwhile (`syncFigureKind`). */
  let loadingThree = null;
  let destroyed = false;
  const wanted = () => figureDimension(demo, work) === 3 && (figure3dReady() || !demo.figure);
  function createView(window) {
    is3d = wanted();
    figureSpec = is3d ? demo.figure3d : demo.figure;
    const spec = figureSpec;
    view = ctx.createFigure({
      draw: (r, v) => demo.draw(r, v, work, data),
      bounds: () => spec.bounds(work, data),
      label: "",
      insets: spec.insets ? (w, h, scale) => spec.insets(w, h, scale, work, data) : null,
      ...(is3d ? { scene: () => spec.scene(work, data), camera: spec.camera } : {}),
      window,
    });
    return view;
  }
  createView(null);

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
      adjust(work);
      if (final) commit(merge);
    },
    /**
     * Sets `state.weights[i]`: in place through `derive.weighted` when the demo has it (no
     * rebuild while a weight slider is dragged), else like `set`.
     */
    setWeight(i, w, final = true) {
      work.weights[i] = w;
      if (derive.weighted) {
        derive.weighted(model, i, w, work, ui);
        if (changed) changed.add("weights");
        view.requestDraw();
      } else {
        markChanged("weights");
      }
      if (final) commit();
    },
    /** Marks a field changed after mutating it in place (a dragged point). */
    touch: markChanged,
    /** Records the working state as it is now. */
    commit: (merge = null) => commit(merge),
    /** Replaces the whole working state (after an add/remove): the model is rebuilt first. */
    replace(next, final = true) {
      demo.adjust?.(next);
      const nextModel = derive.build(next, sl); // throws before anything changes
      swapModel(nextModel);
      work = next;
      changed = null;
      view.requestDraw();
      refresh();
      syncFigureKind(null);
      publish();
      if (final) commit();
    },
    status: ctx.status,
    /** Fits the figure to its content and writes the window into the state (the Fit button). */
    fit: () => ctx.fit?.(),
    requestDraw: () => view.requestDraw(),
    /** Stops every control's animation (a press in the figure takes the parameter over). */
    stop: () => built.forEach((control) => control.stop?.()),
  };

  /** `demo.adjust` on the working state; the fields it changed are marked. */
  function adjust(state) {
    if (!demo.adjust) return;
    const before = { ...state };
    demo.adjust(state);
    for (const name of Object.keys(state)) if (state[name] !== before[name]) markChanged(name);
  }

  function markChanged(field) {
    if (changed) changed.add(field);
    const inPlace = derive.inPlace?.[field];
    if (inPlace && !modelStale) inPlace(model, work, ui);
    else if (derive.from.includes(field)) modelStale = true;
    view.requestDraw();
  }

  function swapModel(nextModel) {
    const old = model;
    model = nextModel;
    for (const key of Object.keys(old)) delete data[key];
    Object.assign(data, model);
    freeModel(old);
  }

  /**
   * The handles of the point list, then the `extra` points shown (`when(state)`, default always):
   * `state[field]` (a single point) or `state[field][index]`; `accept(state, x, y)` may refuse a move.
   * A handle placed by the state rather than stored in it (an arrow's tip at p₀ + D₀ for a
   * vector field D₀) gives `at(state, out)` (writes its world [x, y]) and `place(state, x, y)`
   * (writes the field from the new position) instead.
   */
  function withExtraPoints(list, listed, extra) {
    const shown = (e) => !e.when || e.when(work);
    const entry = (i) => {
      let k = i - listed();
      for (const e of extra) if (shown(e) && k-- === 0) return e;
      return null;
    };
    const point = (e) => (e.index === undefined ? work[e.field] : work[e.field][e.index]);
    return {
      count() {
        let n = listed();
        for (const e of extra) if (shown(e)) n++;
        return n;
      },
      get(i, out) {
        if (i < listed()) return list.get(i, out);
        const e = entry(i);
        if (e.at) e.at(work, out);
        else out.set(point(e));
      },
      label: (i) => (i < listed() ? list.label(i) : t(entry(i).label)),
      anchor(i, out) {
        const e = i < listed() ? null : entry(i);
        if (!e?.anchor) return false;
        out.set(e.anchor(work));
        return true;
      },
      move(i, x, y) {
        if (i < listed()) return list.move(i, x, y);
        const e = entry(i);
        if (e.accept && !e.accept(work, x, y)) return;
        if (e.place) {
          e.place(work, x, y);
        } else {
          const p = point(e);
          p[0] = x;
          p[1] = y;
        }
        markChanged(e.field);
      },
    };
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
        ctx.status(errorText(err), "error");
      }
      changed = null;
    }
    for (const [name, [deps, run]] of cells) {
      if (touches(deps)) data[name] = run(work, data, ui);
    }
    if (ui.handles && ui.handles.selected >= ui.handles.source.count()) ui.handles.select(-1);
    changed = new Set();
    panelsStale = true;
  }

  /**
   * Brings the page around the figure up to date: controls, the figure's name, the demo's
   * tables, then the formula (its fit reads the layout once, after every other write). In a
   * frame this runs after the figure is drawn; it does nothing when nothing was refreshed.
   */
  function publish() {
    if (!panelsStale) return;
    panelsStale = false;
    for (const control of built) control.sync?.(work, data);
    if (demo.label) view.setLabel(demo.label(work, data));
    extra.update?.(work, data);
    formula?.set(demo.formula(work, data));
  }

  // ------------------------------------------------------------ figure parts, handles, panel
  /** The handles of the figure shown (`figure.handles` or `figure3d.handles`). */
  function makeHandles() {
    const handleSpec = figureSpec.handles;
    if (handleSpec && is3d) {
      // One entry or a list (handle-lists3d.js): point lists of `[x, y, z]` (or `[p, q]` on two
      // axes), held in a plane or free, and extra handles placed by the state. A list point's
      // move reaches `derive.moved(model, index, xyz, state, ui, field)` (index in its list),
      // else the field's `derive.inPlace`; an extra handle's `place` marks its field changed.
      const moved = derive.moved
        ? (field, index, xyz) => {
            derive.moved(model, index, xyz, work, ui, field);
            if (changed) changed.add(field);
            view.requestDraw();
          }
        : (field) => markChanged(field);
      ui.handles = new Handles3D(view, {
        ...listHandles3([].concat(handleSpec), {
          state: () => work,
          data,
          ui,
          moved,
          placed: markChanged,
        }),
        commit: (kind, i, merge) => commit(merge),
      });
      data.handles = ui.handles;
    } else if (handleSpec) {
      // One field of points, or several in a row (`field: ["points", "corners"]`).
      const handleFields = [].concat(handleSpec.field);
      const moved = derive.moved
        ? (i, xy) => {
            derive.moved(model, i, xy, work, ui);
            if (changed) changed.add(handleFields[0]);
            view.requestDraw();
          }
        : () => markChanged(handleFields[0]);
      const label = handleSpec.label ? (i) => handleSpec.label(i, work, data) : null;
      const accept = handleSpec.accept ? (i, x, y) => handleSpec.accept(i, x, y, work) : null;
      /** A move over several lists: offered to `accept` and `derive.moved` before it is written. */
      const offer = (i, xy, k) => {
        if (accept && !accept(i, xy[0], xy[1])) return false;
        if (!derive.moved) {
          markChanged(handleFields[k]);
          return true;
        }
        if (derive.moved(model, i, xy, work, ui) === false) return false;
        if (changed) changed.add(handleFields[k]);
        view.requestDraw();
        return true;
      };
      const list =
        handleFields.length === 1 && !accept
          ? pointHandles(() => work[handleFields[0]], moved, label)
          : pointListsHandles(
              handleFields.length,
              (k) => work[handleFields[k]],
              offer,
              label ?? pointLabel,
            );
      const extraPoints = handleSpec.extra ?? [];
      const listed = () => list.count();
      ui.handles = new Handles(view, {
        ...(extraPoints.length ? withExtraPoints(list, listed, extraPoints) : list),
        polygon: handleSpec.polygon,
        constraint: handleSpec.constraint ? (i) => handleSpec.constraint(i, work, data) : undefined,
        select: handleSpec.select ? (i) => handleSpec.select(i, ui) : undefined,
        commit: (kind, i, merge) => commit(merge),
        add: (i) => ui.pointList?.add(i),
        remove: (i) => i < listed() && ui.pointList?.remove(i),
      });
      data.handles = ui.handles;
    }
  }

  /** The runtime's hooks on the figure's frames. */
  function hookFrames() {
    // After every other hook (the handles' applies the newest pointer position first).
    view.beforeFrame(() => refresh(), true);
    view.afterFrame(() => publish());
  }

  /**
   * A demo with both figures (`dimension`): when the state asks for the other kind, the figure,
   * its handles and `setup` are made anew (the controls stay: `viewChanged(view)` rebinds them);
   * `window` is shown when it is a view of the new kind, else the figure fits. A 3D state is
   * shown in 2D while the 3D renderer gets ready (three-loader.js), then the 3D figure records its camera. Returns true when
   * the figure was made anew.
   */
  function syncFigureKind(window) {
    if (destroyed || typeof demo.dimension !== "function") return false;
    if (figureDimension(demo, work) === 3 && !figure3dReady() && !loadingThree) {
      const done = () => {
        loadingThree = null;
        if (syncFigureKind(work.view)) ctx.recordWindow?.();
      };
      loadingThree = prepareFigure(demo, work).then(done, () => (loadingThree = null));
    }
    if (wanted() === is3d) return false;
    if (setUp) extra.destroy?.();
    ui.handles?.destroy();
    ui.handles = null;
    data.handles = null;
    // The test hooks the old figure wrote on its slot (`data-handles`, `data-geometries`, …).
    const slot = ctx.slots.figure.dataset;
    for (const key of Object.keys(slot)) delete slot[key];
    ui.view = createView(window);
    makeHandles();
    if (setUp) extra = demo.setup?.(ui) ?? {};
    hookFrames();
    for (const control of built) control.viewChanged?.(view);
    panelsStale = true;
    view.requestDraw();
    // The new canvas is sized at the next layout (a ResizeObserver): the panels and the demo's
    // hooks follow its first drawn frame too.
    requestAnimationFrame(() => {
      if (destroyed) return;
      panelsStale = true;
      view.requestDraw();
    });
    return true;
  }

  // The figure first; the controls, then the formula panel and `setup` (the demo's tables)
  // each in a later task when the host staged the mount (`ctx.later`, lib/task-queue.js: a
  // poster covers the figure meanwhile), else at once.
  const later = ctx.later ?? now;
  /** `setup`'s hooks (`{}` until it ran). */
  let extra = {};
  /** Whether `setup` has run. */
  let setUp = false;
  /** The figure's first refresh (its data) and the panels' first look at it. */
  const firstRefresh = () => {
    refresh();
    publish();
    syncFigureKind(work.view); // readies the 3D renderer for a 3D state shown in 2D first
  };
  // A figure the poster covers until it is drawn (a 3D one: posters.js coverUntilDrawn) gets
  // its handles and data a task later still, and draws nothing until then.
  const covered = later !== now && typeof view.whenDrawn === "function";
  if (covered) {
    view.hold();
    later(() => {
      if (destroyed) return;
      makeHandles();
      hookFrames();
      firstRefresh();
      view.release();
    });
  } else {
    makeHandles();
    hookFrames();
  }
  later(() => {
    if (destroyed) return;
    built = (demo.controls ?? []).map((descriptor) => descriptor.build(ui));
    ctx.slots.controls.append(...built.map((control) => control.element).filter(Boolean));
  });
  later(() => {
    if (destroyed) return;
    formula = demo.formula ? new FormulaPanel(ctx.slots.formula) : null;
    extra = demo.setup?.(ui) ?? {};
    setUp = true;
    if (later !== now) {
      // The figure has shown the model since the first task: the panels catch up now.
      panelsStale = true;
      publish();
    }
  });
  if (!covered) firstRefresh();

  return {
    /** Shows a validated state from outside (undo, reset, link, import). */
    update(state) {
      const next = structuredClone(state); // build may bring its copy into line (a rule it keeps)
      const nextModel = derive.build(next, sl); // throws before anything changes
      for (const control of built) control.stop?.();
      swapModel(nextModel);
      modelStale = false;
      work = next;
      if (ui.handles) {
        ui.handles.forgetPointer();
        if (ui.handles.selected >= ui.handles.source.count()) ui.handles.select(-1);
      }
      changed = null;
      view.requestDraw();
      refresh();
      syncFigureKind(work.view);
      publish();
    },
    destroy() {
      destroyed = true;
      extra.destroy?.();
      for (const control of built) control.destroy?.();
      ui.handles?.destroy();
      formula?.destroy();
      freeModel(model);
    },
  };
}
