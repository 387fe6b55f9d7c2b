/**
 * The page's side of the rendering worker (gl-worker.js): three.js renders the 3D figures'
 * WebGL layer off the main thread, so a figure's frame never holds the page while the GPU links
 * shaders or rasterises (the first 3D frame was the page's longest task: 300–800 ms on a phone
 * at load). `startGlWorker()` starts it once per page (three-loader.js `prepareFigure`); each
 * View3D then asks for its frames through a `RemoteFigure` and draws the returned `ImageBitmap`
 * under its 2D layer.
 *
 * Where the worker cannot run — no `OffscreenCanvas`, a page on another origin than the worker
 * script (a course page embedding `<spline-lab>`), a CSP without workers, no WebGL in workers —
 * it reports failure and the figures render on the main thread as before (shared-gl.js); a worker
 * that fails later hands its figures back the same way (`onLost`).
 */
import { SceneEncoder } from "./scene-transfer.js";
import { MSAA_BELOW_DPR } from "./shared-gl.js";

/** The longest `prepareFigure` waits for the worker's warm-up before mounting anyway (ms). */
export const READY_WAIT_MS = 3000;

let worker = null;
/** Resolves true once the worker has drawn its warm-up scene, false when it cannot run. */
let ready = null;
let failed = false;
let nextId = 1;
/** Figure id → RemoteFigure, for the replies. */
const figures = new Map();
/** three.js programs the worker linked: after its warm-up, after its latest frame (tests). */
const programs = { warmed: 0, now: 0 };
/** The figures with a frame asked for and not yet shown. */
const waiting = new Set();

/**
 * A hook for tests and screenshots: `<html data-gl-pending>` while any figure waits for a frame
 * (set and removed only when that changes, not per frame).
 */
function markPending(figure, pending) {
  const before = waiting.size;
  if (pending) waiting.add(figure);
  else waiting.delete(figure);
  const root = globalThis.document?.documentElement;
  if (!root || before > 0 === waiting.size > 0) return;
  if (waiting.size) root.dataset.glPending = "";
  else delete root.dataset.glPending;
}

/**
 * Starts the worker if it is not started (memoised). Resolves true once it is ready (its
 * renderer made, the figures' programs linked and drawn once), false when it cannot run.
 */
export function startGlWorker() {
  ready ??= new Promise((resolve) => {
    if (typeof OffscreenCanvas !== "function" || typeof Worker !== "function")
      return resolve(fail());
    try {
      worker = new Worker(new URL("./gl-worker.js", import.meta.url), { type: "module" });
    } catch {
      return resolve(fail());
    }
    worker.onmessage = ({ data }) => {
      if (data.type === "ready") {
        programs.warmed = programs.now = data.programs;
        resolve(true);
      } else if (data.type === "frame") {
        programs.now = data.programs;
        const figure = figures.get(data.id);
        if (figure) figure._arrived(data);
        else data.bitmap.close(); // the figure went while its frame was on its way
      } else if (data.type === "error") resolve(fail());
    };
    worker.onerror = (event) => {
      event.preventDefault?.(); // reported by falling back, not as a page error
      resolve(fail());
    };
    worker.postMessage({
      type: "start",
      antialias: (globalThis.devicePixelRatio || 1) < MSAA_BELOW_DPR,
    });
  });
  return ready;
}

/** `startGlWorker()`, but resolves after at most `READY_WAIT_MS` (the frames queue meanwhile). */
export function glWorkerReady() {
  const waited = new Promise((resolve) => setTimeout(() => resolve(!failed), READY_WAIT_MS));
  return Promise.race([startGlWorker(), waited]);
}

/** True while the worker is started and has not failed: new figures render through it. */
export const glWorkerAlive = () => worker !== null && !failed;

/** The worker's three.js programs `{ warmed, now }`: after its warm-up, now (0 before). */
export const workerPrograms = () => ({ ...programs });

function fail() {
  if (failed) return false;
  failed = true;
  worker?.terminate();
  for (const figure of figures.values()) figure._lost();
  figures.clear();
  for (const figure of [...waiting]) markPending(figure, false);
  return false;
}

/**
 * One figure's frames through the worker. `render(scene, camera, width, height)` asks for a
 * frame; at most one is in flight, a newer request replaces a waiting one (a drag never
 * queues stale frames). `onFrame({ bitmap, legend, geometriesMade, programs, scene })` gets each
 * frame (the bitmap is the figure's to close); `onLost()` when the worker failed.
 */
export class RemoteFigure {
  constructor({ onFrame, onLost }) {
    this.id = nextId++;
    this.onFrame = onFrame;
    this.onLost = onLost;
    this._encoder = new SceneEncoder();
    this._seq = 0;
    this._inFlight = null;
    this._waiting = null;
    figures.set(this.id, this);
  }

  /** True while a frame is asked for and not yet arrived. */
  get pending() {
    return this._inFlight !== null || this._waiting !== null;
  }

  /**
   * Asks for a frame of `scene` at `width × height` device px seen by `camera` = `{ view, fov,
   * aspect }`: the camera numbers `[azimuth, elevation, distance, tx, ty, tz]` (camera3d.js),
   * the vertical field of view in degrees and width / height.
   */
  render(scene, camera, width, height) {
    this._waiting = { scene, width, height, camera };
    if (!this._inFlight) this._post();
    markPending(this, true);
  }

  _post() {
    const request = this._waiting;
    this._waiting = null;
    this._inFlight = request;
    worker.postMessage({
      type: "frame",
      id: this.id,
      seq: ++this._seq,
      width: request.width,
      height: request.height,
      camera: request.camera,
      scene: this._encoder.encode(request.scene),
    });
  }

  _arrived(reply) {
    const { scene } = this._inFlight;
    this._inFlight = null;
    if (this._waiting) this._post(); // the worker starts on the next frame while this one shows
    this.onFrame({ ...reply, scene });
    if (!this.pending) markPending(this, false);
  }

  _lost() {
    this._inFlight = this._waiting = null;
    this.onLost();
  }

  /** Forgets the figure (the worker frees its geometries). */
  dispose() {
    if (!figures.delete(this.id)) return;
    this._inFlight = this._waiting = null;
    markPending(this, false);
    worker?.postMessage({ type: "drop", id: this.id });
  }
}
