/**
 * A 3D figure with the contract of the 2D `View` (view.js), for surfaces: the shell and the
 * declarative runtime use it through the same methods (`fit`, `getWindow` / `setWindow`,
 * `requestDraw`, `beforeFrame`, `addInteractor`, `setLabel`, `setLecture`, `renderTo`,
 * `destroy`), only the "window" is a camera `[azimuth, elevation, distance, tx, ty, tz]`
 * (camera3d.js) and the world is 3D.
 *
 * What is on the screen is one 2D canvas (`.sl-canvas`, sharp at the device pixel ratio): the
 * lit surface, its wireframe and iso-curves rendered by WebGL and copied in, then a 2D layer
 * drawn by the demo with the usual renderer (control net, handles, labels, marks;
 * `project(x, y, z, out)` maps a point to canvas CSS px), then a small axis triad in the
 * lower-left corner. The WebGL image comes from the page's rendering worker when it runs
 * (gl-client.js: the frame is asked for, and the figure is drawn when its `ImageBitmap`
 * arrives, so the main thread never waits for the GPU), else from the page's ONE shared WebGL
 * renderer on the main thread (shared-gl.js, drawn and copied in the same task). The SVG export
 * records the same 2D layer with the wireframe and iso-curves projected as vector paths (no
 * hidden-line removal, no silhouette); PNG and thumbnails composite a WebGL image drawn on the
 * main thread at their own size (synchronous, as exports are).
 *
 * Input: pointers go to the interactors first (the 3D handles); on empty space OrbitControls
 * orbits (drag), pans (Shift-drag, two fingers) and zooms (wheel, pinch) — in embeds the wheel
 * zooms only with Ctrl/⌘, as in 2D. Nothing moves by itself (no damping, no auto-rotation), so
 * `prefers-reduced-motion` is honoured. three.js must be loaded first (three-loader.js
 * `prepareFigure`).
 */
import { sizeCanvas, watchCanvasSize } from "./canvas-size.js";
import { FigureCanvas } from "./figure-canvas.js";
import { currentTheme, onThemeChange } from "./theme.js";
import { loadedThree } from "./three-loader.js";
import { renderShared } from "./shared-gl.js";
import { SceneContent, surfaceMeshes } from "./scene3d.js";
import { RemoteFigure, glWorkerAlive } from "./gl-client.js";
import { drawTriad, drawVectorScene } from "./draw3d.js";
import { drawLegend, legendNumber } from "./curvature-legend.js";
import { segmentBlocked, triangleBlocks } from "./occlusion3d.js";
import {
  FIELD_OF_VIEW,
  verticalFieldOfView,
  applyCamera,
  readCamera,
  roundCamera,
  fitCamera,
  DEFAULT_AZIMUTH,
  DEFAULT_ELEVATION,
  MAX_ELEVATION,
} from "./camera3d.js";

const DEG = Math.PI / 180;
/** `_paint`'s WebGL image: the scene drawn now by the main thread's shared renderer … */
const LOCAL = "local";
/** … or the worker's last frame. */
const WORKER = "worker";
/** A surface closer than this (CSS px at the point's depth) to a point does not hide it. */
const OCCLUSION_MARGIN_PX = 3;

export class View3D extends FigureCanvas {
  /**
   * @param {HTMLElement} host the figure slot; the canvas fills it.
   * @param {object} o
   * @param {(r, view) => void} o.draw the 2D layer (canvas and SVG alike).
   * @param {() => object} o.scene the WebGL content (scene3d.js), asked once per frame.
   * @param {() => number[]} o.bounds `[xmin, ymin, zmin, xmax, ymax, zmax]` of the content.
   * @param {(camera: number[]) => void} [o.onWindowChange] after an orbit, pan or zoom ends.
   * @param {string} [o.label] accessible name.
   * @param {boolean} [o.wheelNeedsModifier] embeds: the plain wheel scrolls the page.
   * @param {{ azimuth: number, elevation: number }} [o.camera] the direction of view a state
   *   without a camera starts from (`home()`; default DEFAULT_AZIMUTH, DEFAULT_ELEVATION).
   */
  constructor(
    host,
    {
      draw,
      scene,
      bounds,
      onWindowChange = null,
      label = "",
      wheelNeedsModifier = false,
      camera = null,
    },
  ) {
    const three = loadedThree();
    if (!three) throw new Error("three.js is not loaded: await prepareFigure(demo) first");
    super(host, { draw, bounds, onWindowChange, label, wheelNeedsModifier });
    const { THREE, OrbitControls } = three;
    this.THREE = THREE;
    this.sceneOf = scene;
    this.is3d = true;
    /** The declared first direction of view, `[azimuth, elevation]` degrees. */
    this.homeDirection = [
      camera?.azimuth ?? DEFAULT_AZIMUTH,
      camera?.elevation ?? DEFAULT_ELEVATION,
    ];

    this.camera = new THREE.PerspectiveCamera(FIELD_OF_VIEW, 1, 0.01, 1000);
    /** The main thread's WebGL objects (exports; the figure itself without a worker), when made. */
    this.content = null;
    /** The meshes of the shown surfaces (`occluded` tests against them). */
    this._shownMeshes = [];
    /** Culling boxes of the shown meshes for `occluded`, by mesh; emptied when they change. */
    this._occlusionBlocks = new Map();
    /** The worker's side of this figure, or null: WebGL on the main thread. */
    this._remote = glWorkerAlive()
      ? new RemoteFigure({
          onFrame: (frame) => this._arrived(frame),
          onLost: () => {
            this._remote = null;
            this.requestDraw();
          },
        })
      : null;
    /** The worker's latest frame (ImageBitmap) and its curvature legend. */
    this._bitmap = null;
    this._legend = null;
    /** True when the canvas lost its pixels (new, resized) since its last drawing. */
    this._cleared = true;
    this._camera = fitCamera([-1, -1, -1, 1, 1, 1], ...this.homeDirection);
    this._w = 1;
    this._h = 1;
    this._vector = new THREE.Vector3();
    this._ray = new THREE.Raycaster();
    this._ndc = new THREE.Vector2();
    this._plane = new THREE.Plane();

    this._listen(); // before OrbitControls: a handle claims the pointer first
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = false;
    this.controls.screenSpacePanning = true;
    this.controls.minPolarAngle = (90 - MAX_ELEVATION) * DEG;
    this.controls.maxPolarAngle = (90 + MAX_ELEVATION) * DEG;
    this.controls.addEventListener("change", () => this.requestDraw());
    this.controls.addEventListener("end", () => this._reportCamera());
    this._apply(this._camera);
  }

  // ---------------------------------------------------------------- camera ("window")

  /** The camera numbers as the state stores them. */
  getWindow() {
    return roundCamera(readCamera(this.camera, this.controls.target));
  }

  /** Shows the camera `[azimuth, elevation, distance, tx, ty, tz]`. */
  setWindow(camera) {
    this._apply(camera);
    this.requestDraw();
  }

  /**
   * Fits the content (`bounds()`) into the camera's frame, keeping the direction of view (or
   * looking along `direction` = `[azimuth, elevation]` when given); returns the camera (rounded
   * as the state stores it).
   */
  fit(bounds = this.bounds?.(), direction = null) {
    const [azimuth, elevation] = direction ?? this._camera ?? this.homeDirection;
    const camera = roundCamera(fitCamera(bounds ?? [-1, -1, -1, 1, 1, 1], azimuth, elevation));
    this.setWindow(camera);
    return camera;
  }

  /** Fits the content looking from the declared first direction (a state without a camera, Reset). */
  home() {
    return this.fit(undefined, this.homeDirection);
  }

  /** Turns the camera around its target by the given degrees and reports it (keyboard orbit). */
  orbitBy(dAzimuth, dElevation) {
    const [a, e, ...rest] = this.getWindow();
    const elevation = Math.max(-MAX_ELEVATION, Math.min(MAX_ELEVATION, e + dElevation));
    this._apply(roundCamera([a + dAzimuth, elevation, ...rest]));
    this.requestDraw();
    this.onWindowChange?.(this._camera);
  }

  _apply(camera) {
    this._camera = camera;
    this.controls?.target.set(camera[3], camera[4], camera[5]);
    applyCamera(this.camera, camera);
  }

  /** After an orbit, pan or zoom: rounds the camera as the state stores it, applies, reports. */
  _reportCamera() {
    const camera = this.getWindow();
    this._apply(camera);
    this.requestDraw();
    this.onWindowChange?.(camera);
  }

  // ---------------------------------------------------------------- projection

  /** Writes canvas CSS px [x, y] and the NDC depth (−1 near … 1 far; > 1 behind) of (x, y, z). */
  project(x, y, z, out) {
    const v = this._vector.set(x, y, z).project(this.camera);
    out[0] = ((v.x + 1) / 2) * this._w;
    out[1] = ((1 - v.y) / 2) * this._h;
    out[2] = v.z;
    return out;
  }

  /** The unit direction the camera looks along (world). */
  viewDirection(out) {
    const e = this.camera.matrixWorld.elements;
    const n = Math.hypot(e[8], e[9], e[10]) || 1;
    out[0] = -e[8] / n;
    out[1] = -e[9] / n;
    out[2] = -e[10] / n;
    return out;
  }

  /** The camera's unit right, up and forward directions (world). */
  screenAxes(right, up, forward) {
    const e = this.camera.matrixWorld.elements;
    for (let k = 0; k < 3; k++) {
      right[k] = e[k];
      up[k] = e[4 + k];
    }
    this.viewDirection(forward);
  }

  /** The unit direction from the camera through (x, y, z): its line of sight. */
  sightLine(x, y, z, out) {
    const p = this.camera.position;
    const n = Math.hypot(x - p.x, y - p.y, z - p.z) || 1;
    out[0] = (x - p.x) / n;
    out[1] = (y - p.y) / n;
    out[2] = (z - p.z) / n;
    return out;
  }

  /** World length of one CSS pixel at the depth of (x, y, z) (perspective). */
  worldPerPixel(x, y, z) {
    const d = this.viewDirection(this._dir ?? (this._dir = new Float64Array(3)));
    const p = this.camera.position;
    const depth = Math.max((x - p.x) * d[0] + (y - p.y) * d[1] + (z - p.z) * d[2], 1e-9);
    return (2 * depth * Math.tan((this.camera.fov / 2) * DEG)) / Math.max(this._h, 1);
  }

  /**
   * Where the pointer's ray through canvas (x, y) meets the plane n·p = d (`plane` = [nx, ny, nz,
   * d]): written into `out`, true; false when the ray runs parallel to it or away.
   */
  rayOnPlane(x, y, plane, out) {
    this._ndc.set((x / this._w) * 2 - 1, 1 - (y / this._h) * 2);
    this._ray.setFromCamera(this._ndc, this.camera);
    this._plane.normal.set(plane[0], plane[1], plane[2]);
    this._plane.constant = -plane[3];
    const hit = this._ray.ray.intersectPlane(this._plane, this._vector);
    if (!hit) return false;
    out[0] = hit.x;
    out[1] = hit.y;
    out[2] = hit.z;
    return true;
  }

  /**
   * True when a shown surface lies between the camera and (x, y, z) (the drawn meshes, more than
   * 3 px before the point: a point on the surface is not hidden by it; occlusion3d.js).
   */
  occluded(x, y, z) {
    const eye = this.camera.position;
    const margin = OCCLUSION_MARGIN_PX * this.worldPerPixel(x, y, z);
    for (const mesh of this._shownMeshes) {
      let blocks = this._occlusionBlocks.get(mesh);
      if (!blocks) {
        blocks = triangleBlocks(mesh);
        this._occlusionBlocks.set(mesh, blocks);
      }
      if (segmentBlocked(mesh, eye.x, eye.y, eye.z, x, y, z, margin, blocks)) return true;
    }
    return false;
  }

  /** A pixel scale for code written for the 2D View (a point list's rounding): px per unit at the target. */
  get scale() {
    const [, , , tx, ty, tz] = this._camera;
    return 1 / this.worldPerPixel(tx, ty, tz);
  }

  // ---------------------------------------------------------------- drawing

  /** Sets the projection for a frame of w × h CSS px. */
  _layout(w, h) {
    this._w = w;
    this._h = h;
    this.camera.aspect = w / h;
    this.camera.fov = verticalFieldOfView(w / h); // the camera's frame whole at any aspect
    this.camera.updateProjectionMatrix();
  }

  drawNow() {
    if (!this.width || !this.height) return;
    this.renderer.theme = this.theme;
    const scene = this.sceneOf();
    if (!this._remote) {
      this._show(scene);
      this._paint(this.renderer, this.width, this.height, this.theme, scene, LOCAL);
      this._publish(this.content.geometriesMade, this.content.legend);
      return;
    }
    // Through the worker: drawn when the frame arrives (`_arrived`). A resized canvas, which
    // lost its pixels, is drawn at once meanwhile with the last frame's image scaled; a new
    // one stays empty until its first frame (not a figure without its surface for a moment).
    this._layout(this.width, this.height);
    this._remote.render(scene, this.camera, this.canvas.width, this.canvas.height);
    if (this._cleared && this._bitmap)
      this._paint(this.renderer, this.width, this.height, this.theme, null, WORKER);
  }

  /** The worker's frame: shown with the 2D layer of the state as it is now. */
  _arrived({ bitmap, legend, geometriesMade, scene }) {
    this._bitmap?.close();
    this._bitmap = bitmap;
    this._legend = legend;
    this._show(scene);
    this._publish(geometriesMade, legend);
    if (this.width && this.height && !this._destroyed)
      this._paint(this.renderer, this.width, this.height, this.theme, null, WORKER);
  }

  /** The surfaces `occluded` tests against: those of `scene`. */
  _show(scene) {
    const meshes = surfaceMeshes(scene);
    if (meshes.some((m, k) => m !== this._shownMeshes[k])) this._occlusionBlocks.clear();
    this._shownMeshes = meshes;
  }

  /** The main thread's WebGL objects, brought in line with `scene`. */
  _local(scene) {
    if (!this.content) {
      this.content = new SceneContent(this.THREE);
      this.content.attachLight(this.camera);
    }
    this.content.update(scene);
    return this.content;
  }

  /** Hooks for tests: geometries made so far (a drag refills, makes none) and the legend. */
  _publish(geometriesMade, legend) {
    const made = String(geometriesMade);
    if (this.host.dataset.geometries !== made) this.host.dataset.geometries = made;
    // The curvature legend's numbers (extent = max |value|, the ends ±extent).
    const published = legend
      ? JSON.stringify({
          shading: legend.shading,
          extent: legend.extent,
          min: legend.min,
          max: legend.max,
          ends: [legendNumber(-legend.extent), legendNumber(legend.extent)],
        })
      : "";
    if ((this.host.dataset.legend ?? "") !== published) {
      if (published) this.host.dataset.legend = published;
      else delete this.host.dataset.legend;
    }
  }

  /**
   * One frame into `r` (canvas or SVG) of w × h CSS px: the WebGL image, the 2D layer, the
   * triad. The WebGL image of a canvas is `scene` drawn now on the main thread (`LOCAL`) or the
   * worker's last frame, if any (`WORKER`); an SVG gets `scene` as vector paths.
   */
  _paint(r, w, h, theme, scene, source) {
    this._layout(w, h);
    r.begin(w, h, theme.background);
    const context = r.context;
    let legend = this._legend;
    if (context?.drawImage) {
      const pw = context.canvas.width;
      const ph = context.canvas.height;
      context.save();
      context.setTransform(1, 0, 0, 1, 0, 0);
      if (source === LOCAL) {
        const content = this._local(scene);
        legend = content.legend;
        const image = renderShared(content.scene, this.camera, pw, ph);
        context.drawImage(image.canvas, image.x, image.y, image.width, image.height, 0, 0, pw, ph);
      } else if (this._bitmap) {
        context.drawImage(this._bitmap, 0, 0, pw, ph);
      }
      context.restore();
    } else {
      legend = this._local(scene).legend;
      drawVectorScene(r, this, scene);
    }
    this.drawFigure(r, this);
    if (legend) drawLegend(r, legend);
    drawTriad(r, this);
    r.end();
    if (r === this.renderer) this._cleared = false;
  }

  /** The figure into another renderer (SVG recorder, export canvas, thumbnail); then back. */
  renderTo(renderer, width, height, theme) {
    const savedTheme = this.theme;
    this.theme = theme;
    renderer.theme = theme;
    renderer.scale = this.renderer.scale;
    this._paint(renderer, width, height, theme, this.sceneOf(), LOCAL);
    this.theme = savedTheme;
    if (this.width && this.height) this._layout(this.width, this.height);
  }

  /** Sizes the backing store in device pixels (canvas-size.js) and draws at once. */
  _resize(cssWidth, cssHeight, devicePixels = null) {
    if (!sizeCanvas(this, cssWidth, cssHeight, devicePixels)) return;
    this._cleared = true;
    this.drawNow();
  }

  // ---------------------------------------------------------------- input

  _listen() {
    const c = this.canvas;
    this._handlers = {
      pointerdown: (e) => this._down(e),
      pointermove: (e) => this._move(e),
      pointerup: (e) => this._up(e),
      pointercancel: (e) => this._up(e),
      pointerleave: () => this._interactors.forEach((it) => it.leave?.()),
      wheel: (e) => {
        // Embeds: a plain wheel scrolls the page; OrbitControls never sees it.
        if (this.wheelNeedsModifier && !e.ctrlKey && !e.metaKey) e.stopImmediatePropagation();
      },
    };
    for (const [type, handler] of Object.entries(this._handlers))
      c.addEventListener(type, handler, type === "wheel" ? { passive: true } : undefined);
    this._stopSize = watchCanvasSize(this.canvas, {
      resize: (w, h, devicePixels) => this._resize(w, h, devicePixels),
      ratioChanged: () => this._resize(this.width, this.height),
    });
    this._stopTheme = onThemeChange(() => {
      this.theme = currentTheme(this.canvas);
      this.requestDraw();
    });
  }

  _down(event) {
    if (event.button !== undefined && event.button > 0) return;
    const [x, y] = this.eventPosition(event);
    for (const it of this._interactors) {
      if (it.pointerDown(event, x, y)) {
        this._captured.set(event.pointerId, it);
        this.canvas.setPointerCapture(event.pointerId);
        event.preventDefault();
        event.stopImmediatePropagation(); // not an orbit
        return;
      }
    }
  }

  _move(event) {
    const [x, y] = this.eventPosition(event);
    const owner = this._captured.get(event.pointerId);
    if (owner) {
      owner.pointerMove(event, x, y);
      return;
    }
    if (event.buttons) return; // an orbit in progress
    let cursor = null;
    for (const it of this._interactors) cursor ??= it.hover(x, y, event.pointerType);
    this.canvas.style.cursor = cursor ?? "grab";
  }

  _up(event) {
    const owner = this._captured.get(event.pointerId);
    if (!owner) return;
    const [x, y] = this.eventPosition(event);
    this._captured.delete(event.pointerId);
    owner.pointerUp(event, x, y);
  }

  destroy() {
    this._destroyed = true;
    this.controls.dispose();
    for (const [type, handler] of Object.entries(this._handlers))
      this.canvas.removeEventListener(type, handler);
    this._stopSize();
    this._stopTheme();
    this._remote?.dispose();
    this._bitmap?.close();
    this.content?.dispose();
    this.canvas.remove();
  }
}
