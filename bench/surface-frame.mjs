// Workload (k) in the browser: one drag frame of the 16×16 bicubic NURBS patch of surface.mjs as
// a 3D figure draws it — `setControlPoint(8, 8, p)` + `tessellate(64, 64)` (positions, normals,
// uvs, indices) + the playground's scene3d.js update (the new arrays put into the existing
// BufferAttributes, no new geometry) + a render through the page's one shared WebGL renderer
// (shared-gl.js) + `drawImage` of its image into the figure's 2D canvas, as view3d.js does.
// Loaded only by browser.html (served with www/lib and www/vendor by browser-run.mjs).
//
// Two timings per frame: "issued" ends when the JavaScript of the frame returns (what a
// requestAnimationFrame callback costs the main thread; the GPU process may still be drawing),
// "completed" adds a 1-pixel getImageData of the 2D canvas, which waits for the whole frame (an
// upper bound: the playground never reads pixels back).
import { loadThree } from "/lib/three-loader.js";
import { SceneContent } from "/lib/scene3d.js";
import { renderShared } from "/lib/shared-gl.js";
import { fitCamera, applyCamera, verticalFieldOfView, FIELD_OF_VIEW } from "/lib/camera3d.js";
import { dragPatch, SURFACE_DRAG } from "/bench/surface.mjs";

/** The figure's canvas in device px: the playground's desktop figure at DPR 1 and at DPR 2. */
export const FRAME_SIZES = Object.freeze([
  [840, 525],
  [1680, 1050],
]);

function stats(times) {
  const s = [...times].sort((a, b) => a - b);
  const m = s.length >> 1;
  return {
    medianMs: s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]),
    p95Ms: s[Math.min(s.length - 1, Math.floor(0.95 * s.length))],
    maxMs: s[s.length - 1],
    frames: s.length,
  };
}

/** Drag frames at each of FRAME_SIZES; timings in ms. */
export async function surfaceFrameBench(sl, { frames = 100, warmup = 10 } = {}) {
  const { THREE } = await loadThree();
  const { net, quads, row, col } = SURFACE_DRAG;
  const { surface, points } = dragPatch(sl);
  const k = 3 * (row * net + col);
  const p = new Float64Array(3);
  const content = new SceneContent(THREE);
  const camera = new THREE.PerspectiveCamera(FIELD_OF_VIEW, 1.6, 0.01, 1000);
  content.attachLight(camera);
  applyCamera(camera, fitCamera([0, 0, -2, net - 1, net - 1, 2]));
  const rows = [];
  try {
    for (const [width, height] of FRAME_SIZES) {
      camera.aspect = width / height;
      camera.fov = verticalFieldOfView(width / height);
      camera.updateProjectionMatrix();
      const canvas = document.createElement("canvas");
      canvas.width = width;
      canvas.height = height;
      document.body.append(canvas);
      const context = canvas.getContext("2d");
      const issued = [];
      const completed = [];
      const stages = { core: [], upload: [], render: [], copy: [] };
      let made = -1;
      for (let f = 0; f < warmup + frames; f++) {
        const t0 = performance.now();
        p[0] = points[k];
        p[1] = points[k + 1];
        p[2] = points[k + 2] + Math.sin(0.1 * f);
        surface.setControlPoint(row, col, p);
        const mesh = surface.tessellate(quads, quads);
        const ta = performance.now();
        content.update({ surfaces: [mesh] });
        const tb = performance.now();
        const image = renderShared(content.scene, camera, width, height);
        const tc = performance.now();
        context.drawImage(image.canvas, image.x, image.y, width, height, 0, 0, width, height);
        const t1 = performance.now();
        context.getImageData(0, 0, 1, 1);
        const t2 = performance.now();
        if (f === warmup) made = content.geometriesMade;
        if (f >= warmup) {
          issued.push(t1 - t0);
          completed.push(t2 - t0);
          stages.core.push(ta - t0);
          stages.upload.push(tb - ta);
          stages.render.push(tc - tb);
          stages.copy.push(t1 - tc);
        }
      }
      canvas.remove();
      rows.push({
        size: `${width}×${height}`,
        issued: stats(issued),
        completed: stats(completed),
        // Medians of the frame's parts: the core (setControlPoint + tessellate), the scene update,
        // renderer.render (WebGL calls issued), drawImage (waits for the GPU image).
        stageMedians: Object.fromEntries(
          Object.entries(stages).map(([name, times]) => [name, stats(times).medianMs]),
        ),
        // A drag makes no geometry after the first frame: the buffers are refilled in place.
        geometriesDuringDrag: content.geometriesMade - made,
      });
    }
  } finally {
    surface.free();
    content.dispose();
  }
  return {
    method: `setControlPoint(${row}, ${col}, p) + tessellate(${quads}, ${quads}) + scene3d update + shared-renderer render + drawImage`,
    vertices: (quads + 1) * (quads + 1),
    rows,
  };
}
