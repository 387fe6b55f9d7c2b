/**
 * HTML attributes ↔ state fields for `<spline-lab>`: an attribute has the name of a state field
 * and a value written the way a course-page author would type it. The field's type in the
 * demo's `defaultState` decides how the text is read:
 *
 * | default value          | attribute text           | state value              |
 * |------------------------|--------------------------|--------------------------|
 * | number                 | `t="0.25"` or `"1/4"`    | 0.25                     |
 * | boolean                | `construction="false"`   | false (present/"" = true)|
 * | string                 | `end="natural"`          | "natural"                |
 * | list of [x, y] points  | `points="0,0 2,2 6,4"`   | [[0,0],[2,2],[6,4]]      |
 * | list of [x, y, z]      | `points="0,0,0 1,0,2"`   | [[0,0,0],[1,0,2]]        |
 * | list of numbers        | `knots="0 0 0 1 2 2 2"`  | [0,0,0,1,2,2,2]          |
 *
 * Field names in camelCase map to kebab-case attributes (`startTangent` ↔ `start-tangent`);
 * `view="xmin ymin xmax ymax"` sets the window (a 3D demo: the camera
 * `view="azimuth elevation distance x y z"`, camera3d.js). The result is then validated like any state.
 */
import { parseNumberInput } from "./format.js";
import { t } from "./strings.js";
import { errorText } from "./core-errors.js";

/** `startTangent` → `start-tangent`. */
export function attributeName(field) {
  return field.replace(/[A-Z]/g, (c) => `-${c.toLowerCase()}`);
}

function parseNumber(text) {
  const value = parseNumberInput(text);
  if (!Number.isFinite(value)) throw new Error(t("control.badNumber", { value: text }));
  return value;
}

/** Numbers separated by commas and/or spaces. */
function parseList(text) {
  const parts = text
    .trim()
    .split(/[\s,]+/)
    .filter(Boolean);
  return parts.map(parseNumber);
}

/** Points "x,y x,y" (pairs separated by spaces or semicolons; triples "x,y,z" for 3D demos). */
function parsePoints(text, dimension = 2) {
  return text
    .trim()
    .split(/\s*;\s*|\s+(?=[^,\s]+\s*,)/)
    .filter(Boolean)
    .map((pair) => {
      const coords = pair.split(/\s*,\s*/).map(parseNumber);
      if (coords.length !== dimension) throw new Error(t("control.badNumber", { value: pair }));
      return coords;
    });
}

/** Reads one attribute value shaped like `example`. */
export function parseAttribute(text, example) {
  if (typeof example === "number") return parseNumber(text);
  if (typeof example === "boolean")
    return text === "" || text === "true" || text === "on" || text === "yes";
  if (typeof example === "string") return text;
  if (Array.isArray(example) && Array.isArray(example[0]))
    return parsePoints(text, example[0].length === 3 ? 3 : 2);
  if (Array.isArray(example)) return parseList(text);
  return JSON.parse(text);
}

/**
 * The state given by `element`'s attributes over `defaultState` (fields without an attribute
 * keep their default). Throws an Error naming the attribute that could not be read.
 */
export function stateFromAttributes(element, defaultState) {
  const state = structuredClone(defaultState);
  for (const [field, example] of Object.entries(defaultState)) {
    const name = attributeName(field);
    if (!element.hasAttribute(name)) continue;
    try {
      state[field] = parseAttribute(element.getAttribute(name), example);
    } catch (err) {
      throw new Error(t("error.attribute", { name, message: errorText(err) }));
    }
  }
  if (element.hasAttribute("view")) state.view = parseList(element.getAttribute("view"));
  return state;
}
