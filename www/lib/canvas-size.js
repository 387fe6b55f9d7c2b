/**
 * A figure canvas sized in device pixels (View and View3D share it): the backing store is the CSS
 * size × devicePixelRatio, or exactly the device-pixel-content-box ResizeObserver reports when the
 * browser has it and it agrees (one canvas pixel is one screen pixel even at fractional CSS sizes); a media
 * query on the current ratio, re-armed after each change, covers browsers without it (a window
 * moved to another screen, page zoom).
 */

/**
 * Gives `figure` (`{ canvas, renderer, width, height, pixelRatio }`) a backing store for
 * `cssWidth` × `cssHeight` CSS px (`devicePixels`: ResizeObserver's device-pixel box size, or
 * null). Writes width, height, pixelRatio, the canvas size and the renderer's ratio; false (and
 * nothing written) when nothing changed.
 */
export function sizeCanvas(figure, cssWidth, cssHeight, devicePixels = null) {
  const w = Math.max(0, cssWidth);
  const h = Math.max(0, cssHeight);
  const dpr = window.devicePixelRatio || 1;
  const pixelWidth = devicePixelSize(devicePixels?.inlineSize, w, dpr);
  const pixelHeight = devicePixelSize(devicePixels?.blockSize, h, dpr);
  const canvas = figure.canvas;
  if (
    w === figure.width &&
    h === figure.height &&
    pixelWidth === canvas.width &&
    pixelHeight === canvas.height
  )
    return false;
  figure.width = w;
  figure.height = h;
  figure.pixelRatio = w > 0 ? pixelWidth / w : dpr;
  canvas.width = pixelWidth;
  canvas.height = pixelHeight;
  figure.renderer.pixelRatio = figure.pixelRatio;
  return true;
}

/** Device pixels a reported device-pixel box may differ from CSS size × ratio by (snapping). */
const DEVICE_PIXEL_SLACK = 2;

/**
 * The backing store's size for `css` CSS px: the device-pixel box's `reported` size when it
 * agrees with `css × dpr` (within snapping, DEVICE_PIXEL_SLACK), else `css × dpr` rounded.
 * Chromium's device emulation (DevTools' phone view, Lighthouse, headless browsers given a
 * scale factor) reports the device-pixel box in CSS px while devicePixelRatio is the emulated
 * ratio: trusting it there drew a blurry figure.
 */
function devicePixelSize(reported, css, dpr) {
  const scaled = Math.round(css * dpr);
  return reported !== undefined && Math.abs(reported - css * dpr) <= DEVICE_PIXEL_SLACK
    ? reported
    : scaled;
}

/**
 * Watches `canvas`'s size and the page's pixel ratio: `resize(cssWidth, cssHeight,
 * devicePixels | null)` on every observed size, `ratioChanged()` when devicePixelRatio changes.
 * Returns `stop()` (disconnects the observer and the media query).
 */
export function watchCanvasSize(canvas, { resize, ratioChanged }) {
  const observer = new ResizeObserver((entries) => {
    const entry = entries[entries.length - 1];
    resize(
      entry.contentRect.width,
      entry.contentRect.height,
      entry.devicePixelContentBoxSize?.[0] ?? null,
    );
  });
  try {
    observer.observe(canvas, { box: "device-pixel-content-box" });
  } catch {
    observer.observe(canvas); // browsers without device-pixel boxes
  }
  let query = null;
  const onChange = () => {
    // The ResizeObserver reports the new device-pixel size; this covers browsers without it.
    ratioChanged();
    watch();
  };
  const watch = () => {
    query?.removeEventListener("change", onChange);
    query = matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`);
    query.addEventListener("change", onChange);
  };
  watch();
  return () => {
    observer.disconnect();
    query?.removeEventListener("change", onChange);
  };
}
