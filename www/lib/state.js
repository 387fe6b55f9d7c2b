/**
 * Demo state as plain data: undo/redo history, the URL hash `#demo=<id>&s=<state>`, and JSON
 * files with a `version` field. Nothing here knows a demo: the same functions serve all.
 *
 * URL encoding: the state's JSON in UTF-8, written as base64url (RFC 4648 §5: A–Z a–z 0–9 - _,
 * no padding). It survives copy-paste, chat clients and e-mail without percent-escapes, and
 * decodes back to the exact numbers (JSON keeps the shortest round-trip form of each double).
 */
import { t } from "./strings.js";

/** Version written into exported JSON files; imports of other versions are refused. */
export const STATE_VERSION = 1;
/** Undo steps kept per demo. */
export const HISTORY_LIMIT = 200;
/** Fields that undo/redo leave as they are (the camera is not an edit). */
export const STICKY_FIELDS = ["view"];

/** Base64url text of a UTF-8 string. */
function toBase64Url(text) {
  const bytes = new TextEncoder().encode(text);
  let binary = "";
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

/** The UTF-8 string of base64url text; throws an Error on damaged input. */
function fromBase64Url(text) {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error(t("error.badEncoding"));
  const padded = text.replace(/-/g, "+").replace(/_/g, "/") + "===".slice((text.length + 3) % 4);
  let binary;
  try {
    binary = atob(padded);
  } catch {
    throw new Error(t("error.badEncoding"));
  }
  const bytes = Uint8Array.from(binary, (ch) => ch.charCodeAt(0));
  try {
    return new TextDecoder("utf-8", { fatal: true }).decode(bytes);
  } catch {
    throw new Error(t("error.badEncoding"));
  }
}

/** Compact, URL-safe text for a state object. */
export function encodeState(state) {
  return toBase64Url(JSON.stringify(state));
}

/** The state object from `encodeState` text; throws an Error naming the problem. */
export function decodeState(text) {
  const json = fromBase64Url(text);
  try {
    return JSON.parse(json);
  } catch {
    throw new Error(t("error.badEncoding"));
  }
}

/** `{ demo, s }` from a location hash such as "#demo=de-casteljau&s=eyJ0Ijo…" (fields may be null). */
export function parseHash(hash) {
  const params = new URLSearchParams(String(hash).replace(/^#/, ""));
  return {
    demo: params.get("demo"),
    s: params.get("s"),
    lecture: params.get("lecture"),
    scene: params.get("scene"),
    exercise: params.get("exercise"),
  };
}

/** The hash that opens demo `id` with `state`. */
export function buildHash(id, state) {
  return state
    ? `#demo=${encodeURIComponent(id)}&s=${encodeState(state)}`
    : `#demo=${encodeURIComponent(id)}`;
}

/** The JSON file text of a state: `{ version, demo, state }`, pretty-printed. */
export function exportJson(id, state) {
  return `${JSON.stringify({ version: STATE_VERSION, demo: id, state }, null, 2)}\n`;
}

/**
 * The state inside a JSON file's text (from `exportJson`); throws an Error naming what is wrong.
 * The state itself is not validated here: the demo's `validate` does that.
 */
export function parseJsonFile(text, id) {
  let data;
  try {
    data = JSON.parse(text);
  } catch (err) {
    throw new Error(t("error.badJson", { message: err.message }));
  }
  if (data === null || typeof data !== "object" || Array.isArray(data))
    throw new Error(t("error.notObject"));
  if (data.version !== STATE_VERSION)
    throw new Error(
      t("error.version", { version: JSON.stringify(data.version), expected: STATE_VERSION }),
    );
  if (data.demo !== id) throw new Error(t("error.wrongDemo", { found: data.demo, expected: id }));
  return data.state;
}

/** A deep copy of a JSON-compatible value. */
export function clone(value) {
  return structuredClone(value);
}

/** True when two JSON-compatible values are equal (compared as JSON text; fine at commit rate). */
export function sameState(a, b) {
  return JSON.stringify(a) === JSON.stringify(b);
}

/**
 * Undo/redo over whole states. `preview` changes the current state without a history entry
 * (a drag in progress, an animation frame); `commit` ends a change and records it;
 * `replace` rewrites the current entry (camera moves). `undo`/`redo` keep `STICKY_FIELDS`.
 */
export class History {
  constructor(initial) {
    this._entries = [clone(initial)];
    this._index = 0;
    this._current = this._entries[0];
    this._mergeKey = null;
  }

  /** The current state (do not mutate: pass a new object to preview/commit). */
  get current() {
    return this._current;
  }

  get canUndo() {
    return this._index > 0;
  }

  get canRedo() {
    return this._index < this._entries.length - 1;
  }

  /** Shows `state` without recording it. */
  preview(state) {
    this._current = state;
  }

  /**
   * Records `state` as a new step. With a `merge` key equal to the previous commit's, the
   * previous step is replaced instead (held arrow keys make one step). Returns false when
   * nothing changed.
   */
  commit(state, merge = null) {
    this._current = state;
    const top = this._entries[this._index];
    if (sameState(top, state)) return false;
    if (merge !== null && merge === this._mergeKey && this._index > 0) {
      this._entries[this._index] = clone(state);
    } else {
      this._entries.length = this._index + 1;
      this._entries.push(clone(state));
      if (this._entries.length > HISTORY_LIMIT) this._entries.shift();
      this._index = this._entries.length - 1;
    }
    this._mergeKey = merge;
    return true;
  }

  /** Rewrites the current entry without a new step. */
  replace(state) {
    this._current = state;
    this._entries[this._index] = clone(state);
  }

  /** Steps back; returns the state to show, or null. */
  undo() {
    return this._step(-1);
  }

  /** Steps forward; returns the state to show, or null. */
  redo() {
    return this._step(1);
  }

  _step(direction) {
    const index = this._index + direction;
    if (index < 0 || index >= this._entries.length) return null;
    this._index = index;
    this._mergeKey = null;
    const state = clone(this._entries[index]);
    for (const field of STICKY_FIELDS) {
      if (field in this._current) state[field] = this._current[field];
      else delete state[field];
    }
    this._entries[index] = clone(state);
    this._current = state;
    return state;
  }
}
