/**
 * The WebGL part of a 3D figure, kept in step with what a demo's `figure3d.scene(state, data)`
 * returns (the core's arrays, nothing computed here):
 *
 *   { surfaces: [surface, …], wireframe: [{ mesh, grid?: [rows, cols] }, …], curves: [curve, …] }
 *
 * A `surface` is a mesh as `tessellate` returns it (`{ positions, normals, uvs, indices }`,
 * Float32Array / Uint32Array), lit, or `{ mesh, colour }` (lit in `colour`, its back side that
 * colour lightened: the pieces of a split), or `{ mesh, shading?, curvatures? }` with `shading` one of
 * "lit" (default: blue in front, a lighter tone at the back, lit from the core's normals by the
 * ambient light, a key light from above left and a headlight, ui.md "3D figures"), "zebra"
 * (reflection lines, shading3d.js), "gaussian" / "mean" (per-vertex colours of K or H from
 * `curvatures` = the core's `curvatures(mesh.uvs)`, [K0, H0, K1, H1, …]; without it the surface
 * is lit). The first curvature-shaded surface gives the figure's `legend` (`{ shading, extent,
 * min, max }`, drawn by view3d.js). A wireframe `{ mesh, grid?, colour?, opacity? }` draws the
 * grid lines of a `grid` = [rows, cols] vertex grid (vertex a·cols + b), else every triangle edge
 * (the edge list is made again only when the mesh's indices change, compared by value: an
 * adaptive mesh dragged keeps its edges while its triangles stay), in `colour` (default the
 * surface's wireframe blue) at `opacity` (default 0.55). A `curve` is a polyline, flat xyz
 * (an iso-curve from `sampleGrid`: 1 px in the surface colour darkened), or `{ points, colour,
 * width? }` drawn in `colour` (a seam coloured by its continuity), `width` CSS px wide (default
 * 1; WebGL lines are 1 device px, so a wider curve is a screen-space ribbon, ribbon3d.js; the
 * SVG export's stroke width too). Everything is depth-tested.
 *
 * Updates are in place: a new array of the same length replaces the existing BufferAttribute's
 * array without a copy (`needsUpdate`: the core's arrays are fresh JS arrays, owned by nobody
 * else); a geometry is only made anew when the vertex count changes. An array that is the same
 * object as last frame is not uploaded again.
 */
import { HUES } from "./theme.js";
import { zebraMaterial, curvatureMaterial, fillCurvatureColours } from "./shading3d.js";
import { ribbonMaterial, ribbonMesh, ribbonGeometry, fillRibbon } from "./ribbon3d.js";

/** Colours of the 3D figure (same in light and dark mode: the hues are kept). */
export const SURFACE_COLOURS = Object.freeze({
  front: HUES.blue,
  back: "#8EC3E6",
  iso: "#00466E",
  wireframe: "#1D5A80",
});

/** How far towards white the back side of a coloured surface is (0 = the colour, 1 = white). */
export const BACK_LIGHTEN = 0.45;

/** Default opacity of a wireframe. */
export const WIREFRAME_OPACITY = 0.55;

/** Light intensities: a low ambient term so the shape reads, a key light, a headlight. */
export const LIGHTS = Object.freeze({ ambient: 0.5, key: 3.2, head: 0.6 });

/**
 * True when `array` is a `Type` with a buffer of its own (a fresh array from the core, safe to
 * keep), not a view into a larger buffer such as the wasm memory (which may move).
 */
const owned = (array, Type) =>
  array instanceof Type && array.byteOffset === 0 && array.buffer.byteLength === array.byteLength;

/**
 * The lit surface: Phong, both sides in ONE draw (the front colour where the triangle faces the
 * camera, the back colour elsewhere: `gl_FrontFacing` picks the diffuse colour; three.js flips
 * the normal of a back face itself), half the vertex work of a front and a back mesh.
 */
function litMaterial(
  THREE,
  offset,
  front = SURFACE_COLOURS.front,
  backColour = SURFACE_COLOURS.back,
) {
  const material = new THREE.MeshPhongMaterial({
    color: front,
    side: THREE.DoubleSide,
    shininess: 40,
    specular: 0x333333,
    ...offset,
  });
  const back = { value: new THREE.Color(backColour) };
  material.onBeforeCompile = (shader) => {
    shader.uniforms.backDiffuse = back;
    shader.fragmentShader = shader.fragmentShader
      .replace("uniform vec3 diffuse;", "uniform vec3 diffuse;\nuniform vec3 backDiffuse;")
      .replace(
        "vec4 diffuseColor = vec4( diffuse, opacity );",
        "vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );",
      );
  };
  material.customProgramCacheKey = () => "splinelab-lit-two-colours";
  return material;
}

/** A scene entry of `surfaces` as `{ mesh, shading, curvatures, colour }`. */
const surfaceEntry = (entry) =>
  entry && !entry.positions
    ? {
        mesh: entry.mesh,
        shading: entry.shading ?? "lit",
        curvatures: entry.curvatures ?? null,
        colour: entry.colour ?? null,
      }
    : entry
      ? { mesh: entry, shading: "lit", curvatures: null, colour: null }
      : null;

/** The meshes of a scene description's surfaces, in order. */
export const surfaceMeshes = (spec) =>
  (spec?.surfaces ?? []).map((entry) => surfaceEntry(entry)?.mesh).filter(Boolean);

/** True when two index arrays hold the same numbers (the same triangles). */
function sameIndices(a, b) {
  if (a === b) return true;
  if (!a || !b || a.length !== b.length) return false;
  for (let k = 0; k < a.length; k++) if (a[k] !== b[k]) return false;
  return true;
}

export class SceneContent {
  /** @param {object} THREE the three.js module. */
  constructor(THREE) {
    this.THREE = THREE;
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.AmbientLight(0xffffff, LIGHTS.ambient));
    /** Geometries made for data so far (not refills): a drag must leave this unchanged. */
    this.geometriesMade = 0;
    /** The curvature legend of the first curvature-shaded surface, or null. */
    this.legend = null;
    this.surfaceSlots = [];
    this.wireSlots = [];
    this.curveSlots = [];
    const offset = { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 };
    this.offset = offset;
    this.materials = {
      lit: litMaterial(THREE, offset),
      zebra: zebraMaterial(THREE, offset),
      curvature: curvatureMaterial(THREE, offset),
      iso: new THREE.LineBasicMaterial({ color: SURFACE_COLOURS.iso }),
      wireframe: new THREE.LineBasicMaterial({
        color: SURFACE_COLOURS.wireframe,
        transparent: true,
        opacity: WIREFRAME_OPACITY,
      }),
    };
    /** Line materials of coloured curves, one per colour. */
    this.curveMaterials = new Map();
    /** Ribbon materials of wide curves, one per colour and width. */
    this.ribbonMaterials = new Map();
    /** Lit materials of coloured surfaces, one per colour. */
    this.surfaceMaterials = new Map();
    /** Materials of coloured or translucent wireframes, one per colour and opacity. */
    this.wireMaterials = new Map();
    /** Triangle-edge lists made so far (a drag that keeps the triangles leaves this unchanged). */
    this.edgeListsMade = 0;
  }

  /**
   * The lights that move with `camera` (adds the camera to the scene): a key light from above
   * left and a weaker headlight from the viewer, so both sides of a surface read as shaped.
   */
  attachLight(camera) {
    const key = new this.THREE.DirectionalLight(0xffffff, LIGHTS.key);
    key.position.set(-1.6, 1.6, 0.5);
    key.target.position.set(0, 0, -1);
    const head = new this.THREE.DirectionalLight(0xffffff, LIGHTS.head);
    head.position.set(0, 0, 0);
    head.target.position.set(0, 0, -1);
    camera.add(key, key.target, head, head.target);
    this.scene.add(camera);
  }

  /** Brings the WebGL objects in line with the demo's scene description. */
  update(spec) {
    const surfaces = spec?.surfaces ?? [];
    const wires = spec?.wireframe ?? [];
    const curves = spec?.curves ?? [];
    this.legend = null;
    for (let k = 0; k < Math.max(surfaces.length, this.surfaceSlots.length); k++)
      this._surface(k, surfaceEntry(surfaces[k]));
    for (let k = 0; k < Math.max(wires.length, this.wireSlots.length); k++)
      this._wire(k, wires[k] ?? null);
    for (let k = 0; k < Math.max(curves.length, this.curveSlots.length); k++)
      this._curve(k, curves[k] ?? null);
  }

  /** Puts `array` into the attribute (no copy) when it has the same count; false when not. */
  static _refill(attribute, array) {
    if (!attribute || attribute.array.length !== array.length) return false;
    if (attribute.array !== array) {
      if (owned(array, attribute.array.constructor)) attribute.array = array;
      else attribute.array.set(array);
    }
    attribute.needsUpdate = true;
    return true;
  }

  /** A new BufferAttribute on `array` (typed to `Type`, copied only when it is not one). */
  _attribute(array, Type, size) {
    return new this.THREE.BufferAttribute(owned(array, Type) ? array : Type.from(array), size);
  }

  _surface(k, entry) {
    const THREE = this.THREE;
    let slot = this.surfaceSlots[k];
    if (!entry) {
      if (slot) slot.object.visible = false;
      return;
    }
    const { mesh, shading } = entry;
    const curvature =
      (shading === "gaussian" || shading === "mean") && entry.curvatures ? shading : null;
    if (!slot) {
      const geometry = new THREE.BufferGeometry();
      slot = {
        geometry,
        mesh: null,
        curvatures: null,
        colours: "",
        object: new THREE.Mesh(geometry, this.materials.lit),
      };
      slot.object.frustumCulled = false;
      this.scene.add(slot.object);
      this.surfaceSlots[k] = slot;
    }
    // One double-sided draw per surface in every shading.
    slot.object.material =
      shading === "zebra"
        ? this.materials.zebra
        : curvature
          ? this.materials.curvature
          : entry.colour
            ? this._surfaceMaterial(entry.colour)
            : this.materials.lit;
    slot.object.visible = true;
    if (slot.mesh !== mesh) {
      slot.mesh = mesh;
      slot.colours = "";
      this._fillSurface(slot, mesh);
    }
    if (curvature) this._colour(slot, entry.curvatures, curvature);
  }

  /** The lit material of a surface in `colour` (front), its back that colour lightened. */
  _surfaceMaterial(colour) {
    let material = this.surfaceMaterials.get(colour);
    if (!material) {
      const THREE = this.THREE;
      const back = new THREE.Color(colour).lerp(new THREE.Color(0xffffff), BACK_LIGHTEN);
      material = litMaterial(THREE, this.offset, colour, back);
      this.surfaceMaterials.set(colour, material);
    }
    return material;
  }

  /** The mesh's positions, normals and indices into the slot's geometry (in place if it fits). */
  _fillSurface(slot, mesh) {
    const THREE = this.THREE;
    const g = slot.geometry;
    const inPlace =
      SceneContent._refill(g.getAttribute("position"), mesh.positions) &&
      SceneContent._refill(g.getAttribute("normal"), mesh.normals) &&
      g.index?.array.length === mesh.indices.length;
    if (inPlace) {
      SceneContent._refill(g.index, mesh.indices);
      g.boundingSphere = g.boundingBox = null;
      return;
    }
    // A new vertex count: a new geometry (the old one's GPU buffers are freed).
    const next = new THREE.BufferGeometry();
    this.geometriesMade += 1;
    next.setAttribute("position", this._attribute(mesh.positions, Float32Array, 3));
    next.setAttribute("normal", this._attribute(mesh.normals, Float32Array, 3));
    next.setIndex(this._attribute(mesh.indices, Uint32Array, 1));
    slot.object.geometry = next;
    slot.geometry = next;
    g.dispose();
  }

  /** Per-vertex colours of curvature `shading` from the core's [K, H, …] (once per change). */
  _colour(slot, curvatures, shading) {
    const g = slot.geometry;
    const n = g.getAttribute("position").count;
    let colours = g.getAttribute("color");
    if (!colours || colours.count !== n) {
      colours = new this.THREE.BufferAttribute(new Float32Array(3 * n), 3);
      g.setAttribute("color", colours);
      slot.colours = "";
    }
    if (curvatures.length < 2 * n) return;
    if (slot.curvatures !== curvatures || slot.colours !== shading) {
      slot.curvatures = curvatures;
      slot.colours = shading;
      slot.range = fillCurvatureColours(curvatures, shading === "gaussian" ? 0 : 1, colours.array);
      colours.needsUpdate = true;
    }
    this.legend ??= { shading, ...slot.range };
  }

  /** The line material of a wireframe: the default, or one per colour and opacity. */
  _wireMaterial(colour, opacity) {
    if (!colour && opacity == null) return this.materials.wireframe;
    const c = colour ?? SURFACE_COLOURS.wireframe;
    const o = opacity ?? WIREFRAME_OPACITY;
    const key = `${c}/${o}`;
    let material = this.wireMaterials.get(key);
    if (!material) {
      material = new this.THREE.LineBasicMaterial({ color: c, transparent: o < 1, opacity: o });
      this.wireMaterials.set(key, material);
    }
    return material;
  }

  _wire(k, entry) {
    const THREE = this.THREE;
    let slot = this.wireSlots[k];
    if (!entry) {
      if (slot) slot.lines.visible = false;
      return;
    }
    if (!slot) {
      slot = {
        mesh: null,
        key: "",
        indices: null,
        lines: new THREE.LineSegments(new THREE.BufferGeometry()),
      };
      slot.lines.frustumCulled = false;
      this.scene.add(slot.lines);
      this.wireSlots[k] = slot;
    }
    slot.lines.material = this._wireMaterial(entry.colour, entry.opacity);
    slot.lines.visible = true;
    const { mesh, grid } = entry;
    if (slot.mesh === mesh) return;
    slot.mesh = mesh;
    const g = slot.lines.geometry;
    // The edges depend on the grid, or on the triangles (compared by value: a fresh array from
    // the core with the same triangles keeps the edge list).
    const key = grid ? `${grid[0]}x${grid[1]}` : "triangles";
    const sameEdges = key === slot.key && (grid || sameIndices(slot.indices, mesh.indices));
    if (sameEdges && SceneContent._refill(g.getAttribute("position"), mesh.positions)) return;
    slot.key = key;
    const next = new THREE.BufferGeometry();
    this.geometriesMade += 1;
    next.setAttribute("position", this._attribute(mesh.positions, Float32Array, 3));
    if (sameEdges && g.index) {
      next.setIndex(g.index);
    } else {
      this.edgeListsMade += 1;
      next.setIndex(new THREE.BufferAttribute(grid ? gridEdges(grid) : triangleEdges(mesh), 1));
    }
    // A copy: the mesh's own array may be adopted and refilled by a surface slot.
    if (!sameEdges) slot.indices = grid ? null : Uint32Array.from(mesh.indices);
    slot.lines.geometry = next;
    g.dispose();
  }

  /** The line material of a curve entry: the iso colour, or one per given colour. */
  _curveMaterial(colour) {
    if (!colour) return this.materials.iso;
    let material = this.curveMaterials.get(colour);
    if (!material) {
      material = new this.THREE.LineBasicMaterial({ color: colour });
      this.curveMaterials.set(colour, material);
    }
    return material;
  }

  _curve(k, entry) {
    const THREE = this.THREE;
    let slot = this.curveSlots[k];
    if (!entry) {
      if (slot) slot.line.visible = false;
      if (slot?.ribbon) slot.ribbon.visible = false;
      return;
    }
    const points = entry.points ?? entry;
    if (!slot) {
      slot = {
        points: null,
        line: new THREE.Line(new THREE.BufferGeometry(), this.materials.iso),
        ribbon: null,
        ribbonPoints: null,
      };
      slot.line.frustumCulled = false;
      this.scene.add(slot.line);
      this.curveSlots[k] = slot;
    }
    // A coloured curve wider than 1 px is a ribbon (ribbon3d.js); else a 1 px line.
    const width = entry.points ? (entry.width ?? 1) : 1;
    if (width > 1) {
      slot.line.visible = false;
      this._ribbon(slot, points, entry.colour ?? SURFACE_COLOURS.iso, width);
      return;
    }
    if (slot.ribbon) slot.ribbon.visible = false;
    slot.line.visible = true;
    slot.line.material = this._curveMaterial(entry.points ? entry.colour : null);
    if (slot.points === points) return;
    slot.points = points;
    const g = slot.line.geometry;
    if (SceneContent._refill(g.getAttribute("position"), points)) return;
    const next = new THREE.BufferGeometry();
    this.geometriesMade += 1;
    next.setAttribute("position", this._attribute(points, Float32Array, 3));
    slot.line.geometry = next;
    g.dispose();
  }

  /** A wide curve: the slot's ribbon in `colour`, `width` CSS px (filled in place if it fits). */
  _ribbon(slot, points, colour, width) {
    if (!slot.ribbon) {
      slot.ribbon = ribbonMesh(this.THREE);
      this.scene.add(slot.ribbon);
    }
    slot.ribbon.visible = true;
    const key = `${colour} ${width}`;
    let material = this.ribbonMaterials.get(key);
    if (!material) {
      material = ribbonMaterial(this.THREE, colour, width);
      this.ribbonMaterials.set(key, material);
    }
    slot.ribbon.material = material;
    if (slot.ribbonPoints === points) return;
    slot.ribbonPoints = points;
    const g = slot.ribbon.geometry;
    if (fillRibbon(g, points)) return;
    this.geometriesMade += 1;
    slot.ribbon.geometry = ribbonGeometry(this.THREE, points);
    g.dispose();
  }

  /** Frees every geometry and material (the shared renderer stays). */
  dispose() {
    for (const slot of this.surfaceSlots) slot.geometry.dispose();
    for (const slot of this.wireSlots) slot.lines.geometry.dispose();
    for (const slot of this.curveSlots) {
      slot.line.geometry.dispose();
      slot.ribbon?.geometry.dispose();
    }
    for (const material of Object.values(this.materials)) material.dispose();
    for (const material of this.curveMaterials.values()) material.dispose();
    for (const material of this.surfaceMaterials.values()) material.dispose();
    for (const material of this.wireMaterials.values()) material.dispose();
    for (const material of this.ribbonMaterials.values()) material.dispose();
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

/** Index pairs of every triangle edge of a mesh, each edge once (keyed a·n + b, a < b). */
export function triangleEdges({ indices }) {
  let n = 0;
  for (let k = 0; k < indices.length; k++) n = Math.max(n, indices[k] + 1);
  const seen = new Set();
  const pairs = [];
  for (let t = 0; t + 2 < indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const a = indices[t + e];
      const b = indices[t + ((e + 1) % 3)];
      const key = a < b ? a * n + b : b * n + a;
      if (seen.has(key)) continue;
      seen.add(key);
      pairs.push(a, b);
    }
  }
  return Uint32Array.from(pairs);
}
