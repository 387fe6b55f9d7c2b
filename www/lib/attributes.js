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
 * | list of records of texts | `pieces="1-t^2, t, 0, 1; t^2-4t+3, t, 1, 2"` | [{x:"1-t^2", y:"t", from:"0", to:"1"}, …] |
 *
 * A list of records (a piecewise curve's pieces) is written record by record, separated by
 * ";", each record's texts separated by "," in the order of the default's first record's keys
 * (`x, y, from, to`); the texts are trimmed. The expression language has neither "," nor ";"
 * (no decimal comma, one-argument functions), so a formula never needs escaping.
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

/** Records "a, b, c; d, e, f" with the keys of `keys`, in order (texts trimmed). */
function parseRecords(text, keys) {
  return text
    .split(";")
    .map((part) => part.trim())
    .filter(Boolean)
    .map((part) => {
      const values = part.split(",").map((value) => value.trim());
      if (values.length !== keys.length)
        throw new Error(t("error.recordShape", { value: part, fields: keys.join(", ") }));
      return Object.fromEntries(keys.map((key, i) => [key, values[i]]));
    });
}

const isRecord = (v) => v !== null && typeof v === "object" && !Array.isArray(v);

/** Reads one attribute value shaped like `example`. */
export function parseAttribute(text, example) {
  if (typeof example === "number") return parseNumber(text);
  if (typeof example === "boolean")
    return text === "" || text === "true" || text === "on" || text === "yes";
  if (typeof example === "string") return text;
  if (Array.isArray(example) && Array.isArray(example[0]))
    return parsePoints(text, example[0].length === 3 ? 3 : 2);
  if (Array.isArray(example) && isRecord(example[0]))
    return parseRecords(text, Object.keys(example[0]));
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
