/**
 * A 3D figure's scene description (scene3d.js: plain objects, arrays and the core's typed
 * arrays) sent to the rendering worker (gl-worker.js) frame after frame WITHOUT losing object
 * identity: `SceneContent` uploads an array only when it is not the same object as last frame,
 * and an orbit sends the same meshes again and again. So the sender names every object it sends
 * and, for an object it sent in the previous frame (or earlier in this one: a surface's mesh is
 * also its wireframe's), sends only the name:
 *
 *   an object sent before   → { "@ref": id }
 *   an object sent first    → { "@new": id, v: value }   (value: a typed array as it is, an
 *                                                          array or object with its entries encoded)
 *
 * Both sides keep exactly the previous frame's objects (the names used in it), so neither
 * grows: an object that skipped a frame is sent again whole.
 */

/** A typed array as it is, an array or plain object with `f` applied to each entry. */
function mapEntries(value, f) {
  if (ArrayBuffer.isView(value)) return value;
  if (Array.isArray(value)) return value.map(f);
  const out = {};
  for (const key of Object.keys(value)) out[key] = f(value[key]);
  return out;
}

/**
 * One side's memory of the previous frame (object → name for the sender, name → object for the
 * receiver): `_frame(root, walk)` walks a frame with a fresh memory `current`, which then
 * replaces the previous one.
 */
class FrameMemory {
  constructor() {
    this._previous = new Map();
  }

  _frame(root, walk) {
    const current = new Map();
    const out = walk(root, current);
    this._previous = current;
    return out;
  }

  /** What `key` named in this frame or the previous one (undefined: nothing). */
  _known(key, current) {
    const known = current.get(key) ?? this._previous.get(key);
    if (known !== undefined) current.set(key, known);
    return known;
  }
}

export class SceneEncoder extends FrameMemory {
  _next = 0;

  /** `spec` ready for `postMessage` (typed arrays are copied by the structured clone). */
  encode(spec) {
    const walk = (value, current) => {
      if (value === null || typeof value !== "object") return value;
      const known = this._known(value, current);
      if (known !== undefined) return { "@ref": known };
      const id = this._next++;
      current.set(value, id);
      return { "@new": id, v: mapEntries(value, (x) => walk(x, current)) };
    };
    return this._frame(spec, walk);
  }
}

export class SceneDecoder extends FrameMemory {
  /** The scene description with every named object the same object as when it came first. */
  decode(encoded) {
    const walk = (x, current) => {
      if (x === null || typeof x !== "object") return x;
      if ("@ref" in x) {
        const value = this._known(x["@ref"], current);
        if (value === undefined) throw new Error(`scene-transfer: unknown object ${x["@ref"]}`);
        return value;
      }
      const value = mapEntries(x.v, (e) => walk(e, current));
      current.set(x["@new"], value);
      return value;
    };
    return this._frame(encoded, walk);
  }
}
