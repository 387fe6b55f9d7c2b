/**
 * The page's WebGL rendering, in a module worker (gl-client.js starts it): three.js draws every
 * 3D figure's scene on ONE `OffscreenCanvas` and sends each frame back as an `ImageBitmap`,
 * which the figure copies under its 2D layer (view3d.js). The page's main thread never waits
 * for the GPU: linking the shaders, the first draw and the wait for each frame's pixels (on a
 * phone's GPU and in the software GPU of a headless browser, 100–800 ms of a first frame) all
 * happen here.
 *
 * Messages in:
 *   { type: "start", antialias }                    make the renderer, draw a tiny scene in the
 *                                                   figures' materials (their programs linked and
 *                                                   drawn once), answer { type: "ready", programs }
 *   { type: "frame", id, seq, width, height, camera, scene }
 *                                                   figure `id`'s scene (scene-transfer.js) seen by
 *                                                   `camera` (`{ view, fov, aspect }`: camera3d.js'
 *                                                   numbers, degrees, w / h) at width × height px;
 *                                                   answer { type: "frame", id, seq, bitmap,
 *                                                   legend, geometriesMade, programs }
 *   { type: "drop", id }                            forget figure `id`
 * Out, on any failure: { type: "error", message } (the page then renders on its main thread).
 */
import * as THREE from "../vendor/three/three.module.js";
import { SceneContent } from "./scene3d.js";
import { applyCamera } from "./camera3d.js";
import { SceneDecoder } from "./scene-transfer.js";
import { warmScene } from "./warm-scene.js";

let renderer = null;
let canvas = null;
/** Figure id → { content, camera, decoder }. */
const figures = new Map();

function start(antialias) {
  canvas = new OffscreenCanvas(1, 1);
  renderer = new THREE.WebGLRenderer({ canvas, antialias, alpha: true });
  renderer.setPixelRatio(1);
  renderer.setClearColor(0x000000, 0);
  // The programs of the figures' materials, linked and drawn once, kept for the figures.
  const { content, camera } = warmScene(THREE);
  renderer.setSize(4, 4, false);
  renderer.render(content.scene, camera);
  renderer.getContext().finish();
}

function figure(id) {
  let f = figures.get(id);
  if (!f) {
    const camera = new THREE.PerspectiveCamera();
    const content = new SceneContent(THREE);
    content.attachLight(camera);
    f = { content, camera, decoder: new SceneDecoder() };
    figures.set(id, f);
  }
  return f;
}

function frame({ id, seq, width, height, camera: c, scene }) {
  const { content, camera, decoder } = figure(id);
  content.update(decoder.decode(scene));
  applyCamera(camera, c.view);
  camera.fov = c.fov;
  camera.aspect = c.aspect;
  camera.updateProjectionMatrix();
  if (canvas.width !== width || canvas.height !== height) renderer.setSize(width, height, false);
  renderer.render(content.scene, camera);
  const bitmap = canvas.transferToImageBitmap();
  const reply = {
    type: "frame",
    id,
    seq,
    bitmap,
    legend: content.legend,
    geometriesMade: content.geometriesMade,
    programs: renderer.info.programs.length,
  };
  self.postMessage(reply, [bitmap]);
}

self.onmessage = ({ data }) => {
  try {
    if (data.type === "start") {
      start(data.antialias);
      self.postMessage({ type: "ready", programs: renderer.info.programs.length });
    } else if (data.type === "frame") {
      frame(data);
    } else if (data.type === "drop") {
      figures.get(data.id)?.content.dispose();
      figures.delete(data.id);
    }
  } catch (error) {
    self.postMessage({ type: "error", message: String(error?.message ?? error) });
  }
};
