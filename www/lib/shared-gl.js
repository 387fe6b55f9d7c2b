/**
 * ONE WebGL renderer for every 3D figure of a page (browsers cap the live WebGL contexts, ~16 in
 * Chromium). It draws on an off-screen canvas; a figure renders its scene into the lower-left
 * `width × height` device pixels and copies them into its own 2D canvas at once
 * (`drawImage`, in the same task, so the drawing buffer need not be preserved). The off-screen
 * canvas only grows, to the largest figure asked for; a smaller figure uses a viewport of it.
 * It is made at the first render, multisampled when the page's pixel ratio is below
 * `MSAA_BELOW_DPR` then.
 */
import { loadedThree } from "./three-loader.js";

let shared = null;
/** The shared renderer multisamples (antialias) when the page's pixel ratio is below this. */
export const MSAA_BELOW_DPR = 2;

/**
 * Makes the shared renderer (its WebGL context, three.js's state) now if it is not made yet
 * (three.js must be loaded): a task of its own before the first 3D figure's first frame
 * (three-loader.js `prepareFigure`), ~20 ms a phone need not spend inside that frame. True
 * when it made it.
 */
export function warmSharedRenderer() {
  if (shared) return false;
  const { THREE } = loadedThree();
  const canvas = document.createElement("canvas");
  // Multisampling only below 2 device px per CSS px: at DPR ≥ 2 the pixels are fine enough,
  // and 4× MSAA of a 4× larger image costs weak GPUs (and SwiftShader) dearly.
  const antialias = (window.devicePixelRatio || 1) < MSAA_BELOW_DPR;
  const renderer = new THREE.WebGLRenderer({ canvas, antialias, alpha: true });
  renderer.setPixelRatio(1);
  renderer.setClearColor(0x000000, 0);
  renderer.setScissorTest(false);
  shared = {
    canvas,
    renderer,
    width: 0,
    height: 0,
    out: { canvas, x: 0, y: 0, width: 0, height: 0 },
  };
  return true;
}

/** True once the shared renderer is made. */
export const sharedRendererMade = () => shared !== null;

/** The shared three.js `WebGLRenderer` (made now if it is not made yet). */
export function sharedRenderer() {
  warmSharedRenderer();
  return shared.renderer;
}

/**
 * Renders `scene` through `camera` at `width × height` device pixels (integers ≥ 1) with a
 * transparent background and returns the source rectangle to copy:
 * `{ canvas, x, y, width, height }` (top-left origin, as `drawImage` reads it).
 */
export function renderShared(scene, camera, width, height) {
  warmSharedRenderer();
  if (width > shared.width || height > shared.height) {
    shared.width = Math.max(width, shared.width);
    shared.height = Math.max(height, shared.height);
    shared.renderer.setSize(shared.width, shared.height, false);
  }
  shared.renderer.setViewport(0, 0, width, height);
  shared.renderer.clear();
  shared.renderer.render(scene, camera);
  const out = shared.out;
  out.x = 0;
  out.y = shared.height - height; // GL's viewport starts at the bottom-left
  out.width = width;
  out.height = height;
  return out;
}
