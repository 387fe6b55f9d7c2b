/**
 * Surface shadings of a 3D figure beyond the lit blue (scene3d.js uses these; ui.md "3D figures"):
 *
 * - **zebra**: reflection lines. At each pixel the view direction is reflected about the unit
 *   normal, r = d − 2 (d·n) n (view space, the normal facing the viewer on either side), and the
 *   environment is a set of parallel light bands: dark and pale by the elevation of r,
 *   asin(r_y) ∈ [−π/2, π/2], in `ZEBRA_STRIPES` pairs. A kink in the stripes shows a G¹ break,
 *   a corner in their direction a G² break (the eye reads curvature continuity from them).
 * - **gaussian** / **mean**: the core's curvatures (`curvatures(mesh.uvs)` → [K0, H0, K1, H1, …])
 *   as per-vertex colours on a diverging scale symmetric about 0: −m blue, 0 white, +m
 *   vermillion, m = max |value| over the mesh (linear in sRGB between the three). Unlit, so a
 *   colour reads exactly as the legend says (curvature-legend.js draws it in the 2D layer).
 *
 * Nothing here touches the page: the rendering worker (gl-worker.js) uses it too.
 */
import { HUES } from "./theme.js";

/** The shadings a surface entry may ask for (the first is the default). */
export const SHADINGS = Object.freeze(["lit", "zebra", "gaussian", "mean"]);
/** Black/white band pairs across the reflected elevations (−90° … 90°). */
export const ZEBRA_STRIPES = 9;
/** The zebra's light bands: a pale grey, so the patch's edge shows against a white page. */
export const ZEBRA_LIGHT = "#D9DEE2";
/** The diverging scale's ends and middle (sRGB). */
export const SCALE_COLOURS = Object.freeze({
  low: HUES.blue,
  middle: "#FFFFFF",
  high: HUES.vermillion,
});
/** Entries of the colour look-up table (odd: the middle entry is exactly white). */
const TABLE_SIZE = 257;

const ZEBRA_VERTEX = /* glsl */ `
varying vec3 vNormal;
varying vec3 vView;
void main() {
  vec4 p = modelViewMatrix * vec4(position, 1.0);
  vNormal = normalMatrix * normal;
  vView = p.xyz;
  gl_Position = projectionMatrix * p;
}`;

const ZEBRA_FRAGMENT = /* glsl */ `
uniform float stripes;
uniform vec3 dark;
uniform vec3 light;
varying vec3 vNormal;
varying vec3 vView;
void main() {
  vec3 n = normalize(vNormal) * (gl_FrontFacing ? 1.0 : -1.0);
  vec3 r = reflect(normalize(vView), n);
  float s = asin(clamp(r.y, -1.0, 1.0)) * stripes / 3.14159265;
  float f = abs(fract(s) - 0.5);                 // 0 at a band's middle, 0.5 at its edge
  float w = max(fwidth(s), 1e-4);                // one pixel, for an antialiased edge
  float band = smoothstep(0.25 - w, 0.25 + w, f);
  gl_FragColor = vec4(mix(dark, light, band), 1.0);
  #include <colorspace_fragment>
}`;

/** The zebra material (both sides). */
export function zebraMaterial(THREE, offset) {
  const colour = (hex) => new THREE.Color(hex);
  return new THREE.ShaderMaterial({
    uniforms: {
      stripes: { value: ZEBRA_STRIPES },
      dark: { value: colour("#1A1A1A") },
      light: { value: colour(ZEBRA_LIGHT) },
    },
    vertexShader: ZEBRA_VERTEX,
    fragmentShader: ZEBRA_FRAGMENT,
    side: THREE.DoubleSide,
    ...offset,
  });
}

/** The unlit per-vertex colour material of the curvature shadings (both sides). */
export function curvatureMaterial(THREE, offset) {
  return new THREE.MeshBasicMaterial({ vertexColors: true, side: THREE.DoubleSide, ...offset });
}

const hexToRgb = (hex) => [1, 3, 5].map((k) => Number.parseInt(hex.slice(k, k + 2), 16) / 255);
const toLinear = (c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);

let table = null;
/** Linear-light RGB of the scale at TABLE_SIZE points from −1 to 1 (vertex colours are linear). */
function colourTable() {
  if (table) return table;
  const low = hexToRgb(SCALE_COLOURS.low);
  const mid = hexToRgb(SCALE_COLOURS.middle);
  const high = hexToRgb(SCALE_COLOURS.high);
  table = new Float32Array(3 * TABLE_SIZE);
  for (let k = 0; k < TABLE_SIZE; k++) {
    const s = (2 * k) / (TABLE_SIZE - 1) - 1;
    const end = s < 0 ? low : high;
    const a = Math.abs(s);
    for (let c = 0; c < 3; c++) table[3 * k + c] = toLinear(mid[c] + a * (end[c] - mid[c]));
  }
  return table;
}

/** The sRGB colour of s ∈ [−1, 1] on the scale, as "#rrggbb" (the legend's swatches). */
export function scaleColour(s) {
  const low = hexToRgb(SCALE_COLOURS.low);
  const mid = hexToRgb(SCALE_COLOURS.middle);
  const high = hexToRgb(SCALE_COLOURS.high);
  const end = s < 0 ? low : high;
  const a = Math.min(Math.abs(s), 1);
  const hex = (c) =>
    Math.round(255 * (mid[c] + a * (end[c] - mid[c])))
      .toString(16)
      .padStart(2, "0");
  return `#${hex(0)}${hex(1)}${hex(2)}`;
}

/**
 * Fills `out` (Float32Array, 3 per vertex) with the scale's colours of curvature `which` (0: K,
 * 1: H) of `values` ([K0, H0, K1, H1, …]) and returns `{ min, max, extent }` of the finite
 * values (extent = max |value|, the scale's ends; a non-finite value is drawn white).
 */
export function fillCurvatureColours(values, which, out) {
  const n = out.length / 3;
  let min = Infinity;
  let max = -Infinity;
  for (let i = 0; i < n; i++) {
    const x = values[2 * i + which];
    if (!Number.isFinite(x)) continue;
    if (x < min) min = x;
    if (x > max) max = x;
  }
  if (min > max) min = max = 0;
  const extent = Math.max(Math.abs(min), Math.abs(max));
  const lut = colourTable();
  const half = (TABLE_SIZE - 1) / 2;
  for (let i = 0; i < n; i++) {
    const x = values[2 * i + which];
    const s = Number.isFinite(x) && extent > 0 ? x / extent : 0;
    const k = 3 * Math.round(half + half * s);
    out[3 * i] = lut[k];
    out[3 * i + 1] = lut[k + 1];
    out[3 * i + 2] = lut[k + 2];
  }
  return { min, max, extent };
}
