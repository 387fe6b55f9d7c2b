/**
 * The scene a WebGL renderer draws once before the first 3D figure (gl-warmup.js on the main
 * thread, gl-worker.js in the rendering worker): drawing it links the programs of the figures'
 * own materials (three.js keys them the same), so the first figure's frame links none.
 */
import { SceneContent } from "./scene3d.js";

/** A unit square (two triangles) as `tessellate` returns meshes. */
function squareMesh() {
  return {
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]),
    normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
    uvs: new Float32Array([0, 0, 1, 0, 0, 1, 1, 1]),
    indices: new Uint32Array([0, 1, 2, 2, 1, 3]),
  };
}

/**
 * The tiny scene of the warm-up: a unit square lit, as a wireframe and an iso-curve, in the
 * figures' materials (scene3d.js), and a camera looking at it.
 */
export function warmScene(THREE) {
  const content = new SceneContent(THREE);
  const camera = new THREE.PerspectiveCamera(30, 1, 0.1, 100);
  camera.position.set(0.5, 0.5, 4);
  content.attachLight(camera);
  const mesh = squareMesh();
  content.update({
    surfaces: [mesh],
    wireframe: [{ mesh, grid: [2, 2] }],
    curves: [new Float32Array([0, 0, 0, 1, 1, 0])],
  });
  return { content, camera };
}
