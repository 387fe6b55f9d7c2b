import { t } from "../lib/strings.js";

/**
 * The lectures: one per syllabus section, each a JSON list of scenes (`<id>.json`: `{ id,
 * section, scenes: [{ demo, state?, caption: { en, el?, hr?, it? } }] }`; a scene's `state`
 * holds only the fields it changes from the demo's starting picture). Played at
 * `index.html#lecture=<id>&scene=<k>` (lib/lecture.js); titled by their section's name.
 */
export const lectures = Object.freeze(
  [
    { id: "parametric-curves", section: 1 },
    { id: "bezier-curves", section: 2 },
    { id: "bspline-curves", section: 3 },
    { id: "rational-curves", section: 4 },
    { id: "interpolating-curves", section: 5 },
    { id: "surfaces", section: 6 },
    { id: "interactive-design", section: 7 },
  ].map(Object.freeze),
);

/** The manifest entry of lecture `id`, or undefined. */
export function findLecture(id) {
  return lectures.find((l) => l.id === id);
}

/** The lecture's scenes, read from its JSON file next to this module. */
export async function loadLecture(id) {
  const entry = findLecture(id);
  if (!entry) throw new Error(t("lecture.unknown", { id }));
  const response = await fetch(new URL(`./${id}.json`, import.meta.url));
  if (!response.ok) throw new Error(t("lecture.loadFailed", { id, status: response.status }));
  return response.json();
}
