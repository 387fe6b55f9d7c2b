/**
 * The WebGL part of a 3D figure, kept in step with what a demo's `figure3d.scene(state, data)`
 * returns (the core's arrays, nothing computed here):
 *
 *   { surfaces: [mesh, …], wireframe: [{ mesh, grid?: [rows, cols] }, …], curves: [flat, …] }
 *
 * `mesh` is what `tessellate` returns (`{ positions, normals, indices }`, Float32Array /
 * Uint32Array); a surface is lit from the core's normals, blue in front and a lighter tone at the
 * back (ui.md "3D figures"). A wireframe draws the grid lines of a `grid` = [rows, cols] vertex
 * grid (vertex a·cols + b), else every triangle edge. `curves` are polylines (flat xyz: an
 * iso-curve from `sampleGrid`), 1 px in the surface colour darkened. Everything is depth-tested.
 *
 * Updates are in place: a new array of the same length is copied into the existing
 * BufferAttribute (`needsUpdate`); a geometry is only made anew when the vertex count changes.
 * An array that is the same object as last frame is not uploaded again.
 */
import { HUES } from "./theme.js";

/** Colours of the 3D figure (same in light and dark mode: the hues are kept). */
export const SURFACE_COLOURS = Object.freeze({
  front: HUES.blue,
  back: "#8EC3E6",
  iso: "#00466E",
  wireframe: "#1D5A80",
});

export class SceneContent {
  /** @param {object} THREE the three.js module. */
  constructor(THREE) {
    this.THREE = THREE;
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.AmbientLight(0xffffff, 1.1));
    /** Geometries made for data so far (not refills): a drag must leave this unchanged. */
    this.geometriesMade = 0;
    this.surfaceSlots = [];
    this.wireSlots = [];
    this.curveSlots = [];
    const offset = { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 };
    this.materials = {
      front: new THREE.MeshPhongMaterial({
        color: SURFACE_COLOURS.front,
        side: THREE.FrontSide,
        shininess: 40,
        specular: 0x333333,
        ...offset,
      }),
      back: new THREE.MeshPhongMaterial({
        color: SURFACE_COLOURS.back,
        side: THREE.BackSide,
        shininess: 10,
        specular: 0x111111,
        ...offset,
      }),
      iso: new THREE.LineBasicMaterial({ color: SURFACE_COLOURS.iso }),
      wireframe: new THREE.LineBasicMaterial({
        color: SURFACE_COLOURS.wireframe,
        transparent: true,
        opacity: 0.55,
      }),
    };
  }

  /** A headlight fixed to `camera` (from above left, behind the viewer); adds the camera. */
  attachLight(camera) {
    const light = new this.THREE.DirectionalLight(0xffffff, 2.2);
    light.position.set(-1, 1.2, 1);
    light.target.position.set(0, 0, -1);
    camera.add(light, light.target);
    this.scene.add(camera);
  }

  /** Brings the WebGL objects in line with the demo's scene description. */
  update(spec) {
    const surfaces = spec?.surfaces ?? [];
    const wires = spec?.wireframe ?? [];
    const curves = spec?.curves ?? [];
    for (let k = 0; k < Math.max(surfaces.length, this.surfaceSlots.length); k++)
      this._surface(k, surfaces[k] ?? null);
    for (let k = 0; k < Math.max(wires.length, this.wireSlots.length); k++)
      this._wire(k, wires[k] ?? null);
    for (let k = 0; k < Math.max(curves.length, this.curveSlots.length); k++)
      this._curve(k, curves[k] ?? null);
  }

  /** Copies `array` into the attribute when it fits the same count; false when it does not. */
  static _refill(attribute, array) {
    if (!attribute || attribute.array.length !== array.length) return false;
    attribute.array.set(array);
    attribute.needsUpdate = true;
    return true;
  }

  _surface(k, mesh) {
    const THREE = this.THREE;
    let slot = this.surfaceSlots[k];
    if (!mesh) {
      if (slot) slot.front.visible = slot.back.visible = false;
      return;
    }
    if (!slot) {
      const geometry = new THREE.BufferGeometry();
      slot = {
        geometry,
        mesh: null,
        front: new THREE.Mesh(geometry, this.materials.front),
        back: new THREE.Mesh(geometry, this.materials.back),
      };
      slot.front.frustumCulled = slot.back.frustumCulled = false;
      this.scene.add(slot.front, slot.back);
      this.surfaceSlots[k] = slot;
    }
    slot.front.visible = slot.back.visible = true;
    if (slot.mesh === mesh) return;
    slot.mesh = mesh;
    const g = slot.geometry;
    const inPlace =
      SceneContent._refill(g.getAttribute("position"), mesh.positions) &&
      SceneContent._refill(g.getAttribute("normal"), mesh.normals) &&
      g.index?.array.length === mesh.indices.length;
    if (inPlace) {
      g.index.array.set(mesh.indices);
      g.index.needsUpdate = true;
      return;
    }
    // A new vertex count: a new geometry (the old one's GPU buffers are freed).
    const next = new THREE.BufferGeometry();
    this.geometriesMade += 1;
    next.setAttribute("position", new THREE.BufferAttribute(Float32Array.from(mesh.positions), 3));
    next.setAttribute("normal", new THREE.BufferAttribute(Float32Array.from(mesh.normals), 3));
    next.setIndex(new THREE.BufferAttribute(Uint32Array.from(mesh.indices), 1));
    slot.front.geometry = slot.back.geometry = next;
    slot.geometry = next;
    g.dispose();
  }

  _wire(k, entry) {
    const THREE = this.THREE;
    let slot = this.wireSlots[k];
    if (!entry) {
      if (slot) slot.lines.visible = false;
      return;
    }
    if (!slot) {
      slot = { mesh: null, key: "", lines: new THREE.LineSegments(new THREE.BufferGeometry()) };
      slot.lines.material = this.materials.wireframe;
      slot.lines.frustumCulled = false;
      this.scene.add(slot.lines);
      this.wireSlots[k] = slot;
    }
    slot.lines.visible = true;
    const { mesh, grid } = entry;
    if (slot.mesh === mesh) return;
    slot.mesh = mesh;
    const key = grid ? `${grid[0]}x${grid[1]}` : `t${mesh.indices.length}`;
    const g = slot.lines.geometry;
    if (key === slot.key && SceneContent._refill(g.getAttribute("position"), mesh.positions))
      return;
    slot.key = key;
    const next = new THREE.BufferGeometry();
    this.geometriesMade += 1;
    next.setAttribute("position", new THREE.BufferAttribute(Float32Array.from(mesh.positions), 3));
    next.setIndex(new THREE.BufferAttribute(grid ? gridEdges(grid) : triangleEdges(mesh), 1));
    slot.lines.geometry = next;
    g.dispose();
  }

  _curve(k, points) {
    const THREE = this.THREE;
    let slot = this.curveSlots[k];
    if (!points) {
      if (slot) slot.line.visible = false;
      return;
    }
    if (!slot) {
      slot = { points: null, line: new THREE.Line(new THREE.BufferGeometry(), this.materials.iso) };
      slot.line.frustumCulled = false;
      this.scene.add(slot.line);
      this.curveSlots[k] = slot;
    }
    slot.line.visible = true;
    if (slot.points === points) return;
    slot.points = points;
    const g = slot.line.geometry;
    if (SceneContent._refill(g.getAttribute("position"), points)) return;
    const next = new THREE.BufferGeometry();
    this.geometriesMade += 1;
    next.setAttribute("position", new THREE.BufferAttribute(Float32Array.from(points), 3));
    slot.line.geometry = next;
    g.dispose();
  }

  /** Frees every geometry and material (the shared renderer stays). */
  dispose() {
    for (const slot of this.surfaceSlots) slot.geometry.dispose();
    for (const slot of this.wireSlots) slot.lines.geometry.dispose();
    for (const slot of this.curveSlots) slot.line.geometry.dispose();
    for (const material of Object.values(this.materials)) material.dispose();
    this.scene.clear();
  }
}

/** Index pairs of the grid lines of a rows × cols vertex grid (vertex a·cols + b). */
export function gridEdges([rows, cols]) {
  const out = new Uint32Array(2 * (rows * (cols - 1) + cols * (rows - 1)));
  let n = 0;
  for (let a = 0; a < rows; a++) {
    for (let b = 0; b < cols; b++) {
      const v = a * cols + b;
      if (b + 1 < cols) {
        out[n++] = v;
        out[n++] = v + 1;
      }
      if (a + 1 < rows) {
        out[n++] = v;
        out[n++] = v + cols;
      }
    }
  }
  return out;
}

/** Index pairs of every triangle edge of a mesh, each edge once. */
export function triangleEdges({ indices }) {
  const seen = new Set();
  const pairs = [];
  for (let t = 0; t + 2 < indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const a = indices[t + e];
      const b = indices[t + ((e + 1) % 3)];
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      if (seen.has(key)) continue;
      seen.add(key);
      pairs.push(a, b);
    }
  }
  return Uint32Array.from(pairs);
}
