/**
 * The handles of the surface-revolution demo per mode (lib/plane-handles.js `entryHandles`):
 * torus — the profile circle's centre C = (R, 0, 0), dragged in the plane y = 0, its x sets R;
 * vase — the profile points [x, z] as (x, 0, z), held in y = 0; extrude — the same points as
 * (x, y, 0), held in z = 0, and the direction's tip at P₀ + d (free in space); ruled — the points
 * of A and B (free). A point held in a plane slides along its line of sight onto it, so it stays
 * under the pointer (`ontoPlane`). Entries are made once per mode and point count.
 */
import { subscript } from "./format.js";
import { ontoPlane } from "./plane-handles.js";
import { R_RANGE } from "./revolution-model.js";

const LABELS = new Map();
const labelOf = (letter, i) => {
  const key = `${letter}${i}`;
  if (!LABELS.has(key)) LABELS.set(key, i < 0 ? letter : `${letter}${subscript(i)}`);
  return LABELS.get(key);
};

/** A profile point held in a coordinate plane: [a, b] ↔ (a, 0, b) (vase) or (a, b, 0) (extrude). */
const profileEntry = (i, inXz) => ({
  label: labelOf("P", i),
  get(s, out) {
    const [a, b] = s.profile[i];
    out[0] = a;
    out[1] = inXz ? 0 : b;
    out[2] = inXz ? b : 0;
  },
  move(s, p, view) {
    ontoPlane(view, p, inXz ? 1 : 2, 0);
    s.profile[i][0] = p[0];
    s.profile[i][1] = inXz ? p[2] : p[1];
    return "profile";
  },
});

/** The extrusion direction's tip at P₀ + d (P₀ = C(0) of the clamped profile, in z = 0). */
const tipEntry = {
  label: labelOf("d", -1),
  get(s, out) {
    out[0] = s.profile[0][0] + s.direction[0];
    out[1] = s.profile[0][1] + s.direction[1];
    out[2] = s.direction[2];
  },
  move(s, p) {
    s.direction[0] = p[0] - s.profile[0][0];
    s.direction[1] = p[1] - s.profile[0][1];
    s.direction[2] = p[2];
    return "direction";
  },
};

/** A free point of curve A or B. */
const curveEntry = (name, letter, i) => ({
  label: labelOf(letter, i),
  get(s, out) {
    out.set(s[name][i]);
  },
  move(s, p) {
    s[name][i] = [p[0], p[1], p[2]];
    return name;
  },
});

/** The torus' profile circle's centre (R, 0, 0): dragged in y = 0, its x sets R. */
const centreEntry = {
  label: labelOf("C", -1),
  get(s, out) {
    out[0] = s.R;
    out[1] = 0;
    out[2] = 0;
  },
  move(s, p, view) {
    ontoPlane(view, p, 1, 0);
    s.R = Math.min(R_RANGE[1], Math.max(R_RANGE[0], Math.round(p[0] * 100) / 100));
    return "R";
  },
};

/** The handles of each mode, made once per mode and point count (drawing allocates nothing). */
const entryCache = new Map();
function entriesOf(s) {
  const key = `${s.mode}:${s.profile.length}`;
  if (!entryCache.has(key)) {
    const n = s.profile.length;
    const profile = (inXz) => Array.from({ length: n }, (_, i) => profileEntry(i, inXz));
    const lists = {
      torus: () => [centreEntry],
      vase: () => profile(true),
      extrude: () => [...profile(false), tipEntry],
      ruled: () => [
        ...[0, 1, 2].map((i) => curveEntry("curveA", "A", i)),
        ...[0, 1, 2, 3].map((i) => curveEntry("curveB", "B", i)),
      ],
    };
    entryCache.set(key, lists[s.mode]());
  }
  return entryCache.get(key);
}

/** The entries with the view bound into their `move` (the plane constraint needs the camera). */
const bound = new WeakMap();
function entriesOfView(s, view) {
  const list = entriesOf(s);
  if (!bound.has(list))
    bound.set(
      list,
      list.map((e) => ({ label: e.label, get: e.get, move: (state, p) => e.move(state, p, view) })),
    );
  return bound.get(list);
}

/** `entries(state)` for `entryHandles`: the current mode's handles, bound to the view. */
export function modeHandles(view) {
  return (s) => entriesOfView(s, view);
}
