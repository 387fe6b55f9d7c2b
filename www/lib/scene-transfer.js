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

/** One side's memory of the previous frame: object → name (sender) or name → object (receiver). */
export class SceneEncoder {
  constructor() {
    this._previous = new Map();
    this._next = 0;
  }

  /** `spec` ready for `postMessage` (typed arrays are copied by the structured clone). */
  encode(spec) {
    const current = new Map();
    const out = this._encode(spec, current);
    this._previous = current;
    return out;
  }

  _encode(value, current) {
    if (value === null || typeof value !== "object") return value;
    const known = current.get(value) ?? this._previous.get(value);
    if (known !== undefined) {
      current.set(value, known);
      return { "@ref": known };
    }
    const id = this._next++;
    current.set(value, id);
    if (ArrayBuffer.isView(value)) return { "@new": id, v: value };
    if (Array.isArray(value)) return { "@new": id, v: value.map((x) => this._encode(x, current)) };
    const v = {};
    for (const key of Object.keys(value)) v[key] = this._encode(value[key], current);
    return { "@new": id, v };
  }
}

export class SceneDecoder {
  constructor() {
    this._previous = new Map();
  }

  /** The scene description with every named object the same object as when it came first. */
  decode(encoded) {
    const current = new Map();
    const out = this._decode(encoded, current);
    this._previous = current;
    return out;
  }

  _decode(x, current) {
    if (x === null || typeof x !== "object") return x;
    if ("@ref" in x) {
      const id = x["@ref"];
      const value = current.get(id) ?? this._previous.get(id);
      if (value === undefined) throw new Error(`scene-transfer: unknown object ${id}`);
      current.set(id, value);
      return value;
    }
    const id = x["@new"];
    const { v } = x;
    let value;
    if (ArrayBuffer.isView(v)) value = v;
    else if (Array.isArray(v)) value = v.map((e) => this._decode(e, current));
    else {
      value = {};
      for (const key of Object.keys(v)) value[key] = this._decode(v[key], current);
    }
    current.set(id, value);
    return value;
  }
}
