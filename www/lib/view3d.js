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
 * Input: pointers go to the interactors first (the 3D handles); on empty space the camera
 * orbits (drag), pans (Shift-drag, right drag, two fingers) and zooms (wheel, pinch) —
 * orbit-gesture.js, OrbitControls' rules — in embeds the wheel zooms only with Ctrl/⌘, as in 2D.
 * Nothing moves by itself (no damping, no auto-rotation), so `prefers-reduced-motion` is
 * honoured. The camera is plain numbers (view-camera.js): with the rendering worker the page
 * needs no three.js at all; without it, three.js must be loaded first (three-loader.js
 * `prepareFigure`), and a PNG export loads it (`prepareExport`).
 */
import { sizeCanvas, watchCanvasSize } from "./canvas-size.js";
import { FigureCanvas } from "./figure-canvas.js";
import { currentTheme, onThemeChange } from "./theme.js";
import { loadThree, loadedThree } from "./three-loader.js";
import { renderShared } from "./shared-gl.js";
import { SceneContent, surfaceMeshes } from "./scene3d.js";
import { RemoteFigure, glWorkerAlive } from "./gl-client.js";
import { drawTriad, drawVectorScene } from "./draw3d.js";
import { drawLegend, legendNumber } from "./curvature-legend.js";
import { segmentBlocked, triangleBlocks } from "./occlusion3d.js";
import { ViewCamera } from "./view-camera.js";
import { OrbitGesture } from "./orbit-gesture.js";
import {
  verticalFieldOfView,
  applyCamera,
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
    const remote = glWorkerAlive();
    if (!remote && !loadedThree())
      throw new Error("three.js is not loaded: await prepareFigure(demo) first");
    super(host, { draw, bounds, onWindowChange, label, wheelNeedsModifier });
    this.sceneOf = scene;
    this.is3d = true;
    /** The declared first direction of view, `[azimuth, elevation]` degrees. */
    this.homeDirection = [
      camera?.azimuth ?? DEFAULT_AZIMUTH,
      camera?.elevation ?? DEFAULT_ELEVATION,
    ];

    /** The camera's pose and projection (numbers; the page's picking and 2D layer). */
    this.camera = new ViewCamera();
    /** The main thread's WebGL objects and three.js camera (exports; the figure itself without
     * a worker), when made. */
    this.content = null;
    this._glCamera = null;
    /** The meshes of the shown surfaces (`occluded` tests against them). */
    this._shownMeshes = [];
    /** Culling boxes of the shown meshes for `occluded`, by mesh; emptied when they change. */
    this._occlusionBlocks = new Map();
    /** The worker's side of this figure, or null: WebGL on the main thread. */
    this._remote = remote
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
    /** Resolves once the canvas shows the figure (`whenDrawn`). */
    this._drawn = new Promise((resolve) => (this._markDrawn = resolve));
    this._camera = fitCamera([-1, -1, -1, 1, 1, 1], ...this.homeDirection);
    this._w = 1;
    this._h = 1;
    this._ndc = new Float64Array(3);
    this._rayDirection = new Float64Array(3);
    this._orbit = new OrbitGesture({
      camera: () => this._camera,
      height: () => this._h,
      fov: () => this.camera.fov,
      view: this.camera,
      change: (camera) => {
        this._apply(camera);
        this.requestDraw();
      },
      end: () => this._reportCamera(),
    });
    this._listen();
    this._apply(this._camera);
  }

  // ---------------------------------------------------------------- camera ("window")

  /** The camera numbers as the state stores them. */
  getWindow() {
    return roundCamera(this._camera);
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
    this.camera.set(camera);
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
    const v = this.camera.project(x, y, z, this._ndc);
    out[0] = ((v[0] + 1) / 2) * this._w;
    out[1] = ((1 - v[1]) / 2) * this._h;
    out[2] = v[2];
    return out;
  }

  /** The unit direction the camera looks along (world). */
  viewDirection(out) {
    const back = this.camera.back;
    for (let k = 0; k < 3; k++) out[k] = -back[k];
    return out;
  }

  /** The camera's unit right, up and forward directions (world). */
  screenAxes(right, up, forward) {
    for (let k = 0; k < 3; k++) {
      right[k] = this.camera.right[k];
      up[k] = this.camera.up[k];
    }
    this.viewDirection(forward);
  }

  /** The unit direction from the camera through (x, y, z): its line of sight. */
  sightLine(x, y, z, out) {
    const [ex, ey, ez] = this.camera.eye;
    const n = Math.hypot(x - ex, y - ey, z - ez) || 1;
    out[0] = (x - ex) / n;
    out[1] = (y - ey) / n;
    out[2] = (z - ez) / n;
    return out;
  }

  /** World length of one CSS pixel at the depth of (x, y, z) (perspective). */
  worldPerPixel(x, y, z) {
    const d = this.viewDirection(this._dir ?? (this._dir = new Float64Array(3)));
    const [ex, ey, ez] = this.camera.eye;
    const depth = Math.max((x - ex) * d[0] + (y - ey) * d[1] + (z - ez) * d[2], 1e-9);
    return (2 * depth * Math.tan((this.camera.fov / 2) * DEG)) / Math.max(this._h, 1);
  }

  /**
   * Where the pointer's ray through canvas (x, y) meets the plane n·p = d (`plane` = [nx, ny, nz,
   * d]): written into `out`, true; false when the ray runs parallel to it or away.
   */
  rayOnPlane(x, y, plane, out) {
    const d = this.camera.rayDirection(
      (x / this._w) * 2 - 1,
      1 - (y / this._h) * 2,
      this._rayDirection,
    );
    const eye = this.camera.eye;
    const along = plane[0] * d[0] + plane[1] * d[1] + plane[2] * d[2];
    if (along === 0) return false;
    const s = (plane[3] - (plane[0] * eye[0] + plane[1] * eye[1] + plane[2] * eye[2])) / along;
    if (!(s >= 0)) return false;
    for (let k = 0; k < 3; k++) out[k] = eye[k] + s * d[k];
    return true;
  }

  /**
   * True when a shown surface lies between the camera and (x, y, z) (the drawn meshes, more than
   * 3 px before the point: a point on the surface is not hidden by it; occlusion3d.js).
   */
  occluded(x, y, z) {
    const [ex, ey, ez] = this.camera.eye;
    const margin = OCCLUSION_MARGIN_PX * this.worldPerPixel(x, y, z);
    for (const mesh of this._shownMeshes) {
      let blocks = this._occlusionBlocks.get(mesh);
      if (!blocks) {
        blocks = triangleBlocks(mesh);
        this._occlusionBlocks.set(mesh, blocks);
      }
      if (segmentBlocked(mesh, ex, ey, ez, x, y, z, margin, blocks)) return true;
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
  }

  drawNow() {
    if (!this.width || !this.height) return;
    this.renderer.theme = this.theme;
    const scene = this.sceneOf();
    if (!this._remote) {
      this._show(scene);
      this._paint(this.renderer, this.width, this.height, this.theme, scene, LOCAL);
      if (this.content) this._publish(this.content.geometriesMade, this.content.legend);
      return;
    }
    // Through the worker: drawn when the frame arrives (`_arrived`). A resized canvas, which
    // lost its pixels, is drawn at once meanwhile with the last frame's image scaled; a new
    // one stays empty until its first frame (not a figure without its surface for a moment;
    // the page and an embed keep the demo's poster over it meanwhile: posters.js coverUntilDrawn).
    this._layout(this.width, this.height);
    const { fov, aspect } = this.camera;
    this._remote.render(
      scene,
      { view: this._camera, fov, aspect },
      this.canvas.width,
      this.canvas.height,
    );
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

  /**
   * The main thread's WebGL objects, brought in line with `scene`, and its three.js camera set
   * as `camera`; null until three.js is loaded (its load is started, and the figure drawn again
   * after it: a worker lost while the page has no three.js).
   */
  _local(scene) {
    const three = loadedThree();
    if (!three) {
      this._loadingThree ??= loadThree().then(
        () => this._destroyed || this.requestDraw(),
        () => (this._loadingThree = null), // tried again at the next frame
      );
      return null;
    }
    if (!this.content) {
      this._glCamera = new three.THREE.PerspectiveCamera();
      this.content = new SceneContent(three.THREE);
      this.content.attachLight(this._glCamera);
    }
    this.content.update(scene);
    const gl = this._glCamera;
    applyCamera(gl, this._camera);
    gl.fov = this.camera.fov;
    gl.aspect = this.camera.aspect;
    gl.updateProjectionMatrix();
    return this.content;
  }

  /** Resolves when `renderTo` can draw the WebGL image into a canvas (three.js on the page). */
  prepareExport() {
    return loadThree();
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
      const content = source === LOCAL ? this._local(scene) : null;
      if (content) {
        legend = content.legend;
        const image = renderShared(content.scene, this._glCamera, pw, ph);
        context.drawImage(image.canvas, image.x, image.y, image.width, image.height, 0, 0, pw, ph);
      } else if (this._bitmap) {
        context.drawImage(this._bitmap, 0, 0, pw, ph);
      }
      context.restore();
    } else {
      // The vector paths need no WebGL; the legend is the worker's when three.js is not here.
      if (loadedThree()) legend = this._local(scene).legend;
      drawVectorScene(r, this, scene);
    }
    this.drawFigure(r, this);
    if (legend) drawLegend(r, legend);
    drawTriad(r, this);
    r.end();
    if (r === this.renderer) {
      this._cleared = false;
      this._markDrawn();
    }
  }

  /**
   * Resolves once the canvas shows the figure (with the worker: after its first frame), or once
   * the figure is destroyed before that (what covers it meanwhile then goes too).
   */
  whenDrawn() {
    return this._drawn;
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
    if (!this._held) this.drawNow();
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
        // Embeds: a plain wheel scrolls the page.
        if (this.wheelNeedsModifier && !e.ctrlKey && !e.metaKey) return;
        e.preventDefault();
        this._orbit.wheel(e);
      },
      contextmenu: (e) => e.preventDefault(), // a right drag pans
    };
    c.style.touchAction = "none"; // one finger orbits, two pan and zoom: no page gestures
    for (const [type, handler] of Object.entries(this._handlers))
      c.addEventListener(type, handler, type === "wheel" ? { passive: false } : undefined);
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
    const [x, y] = this.eventPosition(event);
    const primary = event.button === undefined || event.button === 0;
    if (primary && !this._orbit.active) {
      for (const it of this._interactors) {
        if (it.pointerDown(event, x, y)) {
          this._captured.set(event.pointerId, it);
          this.canvas.setPointerCapture(event.pointerId);
          event.preventDefault();
          return;
        }
      }
    }
    if (this._captured.size) return; // a handle's drag: a second finger does nothing
    this._orbit.down(event, x, y);
    this.canvas.setPointerCapture(event.pointerId);
  }

  _move(event) {
    const [x, y] = this.eventPosition(event);
    const owner = this._captured.get(event.pointerId);
    if (owner) {
      owner.pointerMove(event, x, y);
      return;
    }
    if (this._orbit.move(event, x, y) || event.buttons) return; // an orbit in progress
    let cursor = null;
    for (const it of this._interactors) cursor ??= it.hover(x, y, event.pointerType);
    this.canvas.style.cursor = cursor ?? "grab";
  }

  _up(event) {
    const owner = this._captured.get(event.pointerId);
    if (!owner) {
      this._orbit.up(event);
      return;
    }
    const [x, y] = this.eventPosition(event);
    this._captured.delete(event.pointerId);
    owner.pointerUp(event, x, y);
  }

  destroy() {
    this._destroyed = true;
    this._markDrawn();
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
