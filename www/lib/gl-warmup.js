/**
 * The GPU's first-use work for the 3D figures, done before the first figure mounts and without
 * holding the page's main thread. A WebGL program's first draw costs far more than the next: the
 * driver links the shaders and builds its pipeline for them (on a phone's GPU, and in the
 * software GPU of a headless browser, ~250 ms of a 660 × 500 first frame against ~60 for the
 * next). The first figure's frame then copies its image at once (shared-gl.js), so that wait
 * would fall inside the frame's task.
 *
 * `warmPipelines()` draws a tiny scene in the figures' own materials (the lit surface, a
 * wireframe, an iso-curve: scene3d.js `SceneContent`, so three.js keys its programs the same)
 * into a 4 × 4 corner of the shared renderer: the shaders are linked in parallel
 * (`compileAsync`, KHR_parallel_shader_compile where there is one), the draw is flushed, and a
 * fence (WebGL2 `fenceSync`) is polled from short tasks until the GPU has done it, for at most
 * `WARM_WAIT_MS`. The tiny scene is kept, so three.js keeps its programs for the figures.
 *
 * This is the warm-up of the main thread's renderer, used where the rendering worker cannot run
 * (gl-client.js); the worker warms its own renderer with the same scene (warm-scene.js).
 */
import { loadedThree } from "./three-loader.js";
import { renderShared, sharedRenderer } from "./shared-gl.js";
import { warmScene } from "./warm-scene.js";

/** The longest the warm-up waits for the GPU before the figure mounts anyway (ms). */
export const WARM_WAIT_MS = 1500;
/** How often the fence is asked (ms): about a frame, so the asking costs next to nothing. */
export const POLL_MS = 16;

let warmed = null;

/**
 * Resolves once the figures' programs are linked and drawn once on the GPU (or after
 * `WARM_WAIT_MS`, or at once when it was done before or WebGL failed: the figure then pays
 * the first use itself, as it did before this existed). Three.js must be loaded.
 */
export function warmPipelines() {
  warmed ??= warm().catch(() => {});
  return warmed;
}

async function warm() {
  const { THREE } = loadedThree();
  const renderer = sharedRenderer();
  const { content, camera } = warmScene(THREE);
  await renderer.compileAsync(content.scene, camera);
  renderShared(content.scene, camera, 4, 4);
  const gl = renderer.getContext();
  const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl.flush();
  const until = performance.now() + WARM_WAIT_MS;
  while (gl.getSyncParameter(fence, gl.SYNC_STATUS) !== gl.SIGNALED && performance.now() < until)
    await new Promise((resolve) => setTimeout(resolve, POLL_MS));
  gl.deleteSync(fence);
  return content;
}
