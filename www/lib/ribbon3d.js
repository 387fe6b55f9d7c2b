/**
 * Wide scene curves: WebGL draws `LINE_STRIP`s 1 device px wide whatever the material says, so
 * a curve entry with `width > 1` (a seam, a piece's outline) is drawn as a ribbon — two
 * vertices per polyline point, pushed apart on the screen by ±width/2 px across the polyline's
 * projected direction (the mean of the directions to its neighbours) in the vertex shader —
 * depth-tested like every line. `width` is in CSS px (the SVG export's stroke width), times the
 * page's pixel ratio on the canvas. Unlit, in the exact colour (no colour-space conversion).
 */

const VERTEX = `
uniform vec2 resolution;
uniform float width;
attribute vec3 prev;
attribute vec3 next;
attribute float side;
vec2 onScreen(vec4 clip) { return clip.xy / clip.w * resolution * 0.5; }
vec2 unit(vec2 d) { float l = length(d); return l > 1e-6 ? d / l : vec2(0.0); }
void main() {
  mat4 m = projectionMatrix * modelViewMatrix;
  vec4 here = m * vec4(position, 1.0);
  vec2 s = onScreen(here);
  vec2 dir = unit(s - onScreen(m * vec4(prev, 1.0))) + unit(onScreen(m * vec4(next, 1.0)) - s);
  dir = length(dir) > 1e-6 ? normalize(dir) : vec2(1.0, 0.0);
  vec2 across = vec2(-dir.y, dir.x) * side * width * 0.5;
  here.xy += across / (resolution * 0.5) * here.w;
  gl_Position = here;
}`;

const FRAGMENT = `
uniform vec3 colour;
void main() { gl_FragColor = vec4(colour, 1.0); }`;

/** The ribbon material of `colour` ("#rrggbb") and `width` CSS px. */
export function ribbonMaterial(THREE, colour, width) {
  const hex = Number.parseInt(colour.slice(1, 7), 16);
  const rgb = [(hex >> 16) / 255, ((hex >> 8) & 255) / 255, (hex & 255) / 255];
  return new THREE.ShaderMaterial({
    uniforms: {
      resolution: { value: new THREE.Vector2(1, 1) },
      width: { value: width },
      colour: { value: new THREE.Vector3(...rgb) },
    },
    vertexShader: VERTEX,
    fragmentShader: FRAGMENT,
    side: THREE.DoubleSide,
    userData: { cssWidth: width },
  });
}

/**
 * A ribbon mesh (material set by the caller) whose `resolution` and device width follow the
 * viewport it is drawn into (the shared renderer's, device px).
 */
export function ribbonMesh(THREE) {
  const mesh = new THREE.Mesh(new THREE.BufferGeometry());
  mesh.frustumCulled = false;
  const viewport = new THREE.Vector4();
  mesh.onBeforeRender = (renderer, _scene, _camera, _geometry, material) => {
    renderer.getCurrentViewport(viewport);
    material.uniforms.resolution.value.set(viewport.z, viewport.w);
    material.uniforms.width.value = material.userData.cssWidth * (globalThis.devicePixelRatio || 1);
  };
  return mesh;
}

/**
 * Writes the ribbon of a flat xyz polyline of n points into `geometry` when it has room for
 * exactly n points (in place; true), else returns false: 2n vertices (point k at 2k and 2k + 1,
 * sides −1 and +1) with their neighbours (an end is its own neighbour), 2(n − 1) triangles.
 */
export function fillRibbon(geometry, points) {
  const n = Math.floor(points.length / 3);
  const attribute = geometry.getAttribute("position");
  if (!attribute || attribute.count !== 2 * n) return false;
  const position = attribute.array;
  const prev = geometry.getAttribute("prev").array;
  const next = geometry.getAttribute("next").array;
  for (let k = 0; k < n; k++) {
    const p = Math.max(k - 1, 0);
    const q = Math.min(k + 1, n - 1);
    for (let c = 0; c < 3; c++) {
      position[6 * k + c] = position[6 * k + 3 + c] = points[3 * k + c];
      prev[6 * k + c] = prev[6 * k + 3 + c] = points[3 * p + c];
      next[6 * k + c] = next[6 * k + 3 + c] = points[3 * q + c];
    }
  }
  for (const name of ["position", "prev", "next"]) geometry.getAttribute(name).needsUpdate = true;
  return true;
}

/** A new ribbon geometry for a flat xyz polyline (see `fillRibbon`). */
export function ribbonGeometry(THREE, points) {
  const n = Math.floor(points.length / 3);
  const g = new THREE.BufferGeometry();
  for (const name of ["position", "prev", "next"])
    g.setAttribute(name, new THREE.BufferAttribute(new Float32Array(6 * n), 3));
  const side = new Float32Array(2 * n);
  for (let k = 0; k < n; k++) {
    side[2 * k] = -1;
    side[2 * k + 1] = 1;
  }
  g.setAttribute("side", new THREE.BufferAttribute(side, 1));
  const index = new Uint32Array(Math.max(6 * (n - 1), 0));
  for (let k = 0; k + 1 < n; k++) {
    const v = 2 * k;
    index.set([v, v + 1, v + 2, v + 1, v + 3, v + 2], 6 * k);
  }
  g.setIndex(new THREE.BufferAttribute(index, 1));
  fillRibbon(g, points);
  return g;
}
