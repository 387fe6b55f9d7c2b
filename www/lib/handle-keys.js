/**
 * The keyboard behaviour the figure's point handles share, 2D (handles.js) and 3D (handles3d.js),
 * and the knot ruler's nudges (knot-ruler.js): selection keys and undo steps of repeated nudges.
 */

/** Arrow presses on one handle closer together than this (ms) make one undo step. */
export const NUDGE_MERGE_MS = 800;

/**
 * Tab / Shift+Tab (the next / previous handle; past either end the selection is dropped and the
 * focus moves on: no trap), Home (the first), End (the last), Escape (none) on `handles`
 * (`{ selected, select(i) }`, `count` handles). True when the key was one of these (its default
 * prevented unless Tab leaves the figure); false for any other key.
 */
export function selectionKey(event, handles, count) {
  const i = handles.selected;
  switch (event.key) {
    case "Tab": {
      const next = i + (event.shiftKey ? -1 : 1);
      if (i >= 0 && next >= 0 && next < count) {
        handles.select(next);
        event.preventDefault();
      } else {
        handles.select(-1); // leave the figure: focus moves on, no trap
      }
      return true;
    }
    case "Home":
      handles.select(0);
      break;
    case "End":
      handles.select(count - 1);
      break;
    case "Escape":
      handles.select(-1);
      break;
    default:
      return false;
  }
  event.preventDefault();
  return true;
}

/**
 * Groups keyboard nudges into undo steps: `next(i)` → the group number of a nudge of item i now,
 * the previous one's when it moved the same item less than `NUDGE_MERGE_MS` ago.
 */
export class NudgeGroups {
  constructor() {
    this.index = -1;
    this.time = 0;
    this.group = 0;
  }

  next(i) {
    const now = performance.now();
    const repeat = this.index === i && now - this.time < NUDGE_MERGE_MS;
    if (!repeat) this.group += 1;
    this.index = i;
    this.time = now;
    return this.group;
  }
}
