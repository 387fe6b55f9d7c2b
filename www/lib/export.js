/**
 * Figures and states out of the page: SVG and TikZ (recorded from the same draw calls as the
 * screen), PNG (2× scale, white background) and JSON (the state exactly as the URL holds it).
 */
import { CanvasRenderer, SvgRecorder } from "./draw.js";
import { LIGHT_THEME } from "./theme.js";
import { TikzRecorder } from "./tikz.js";

/** PNG exports are rendered at this many pixels per CSS pixel. */
export const PNG_SCALE = 2;

/** The figure of `view` as an SVG document (light theme, the screen's CSS size). */
export function figureToSvg(view) {
  const measure = document.createElement("canvas").getContext("2d");
  const recorder = new SvgRecorder({ theme: LIGHT_THEME, measureContext: measure });
  view.renderTo(recorder, view.width, view.height, LIGHT_THEME);
  return recorder.toString();
}

/** The figure of `view` as a standalone LaTeX document drawing it with TikZ (light theme). */
export function figureToTikz(view, title) {
  const measure = document.createElement("canvas").getContext("2d");
  const recorder = new TikzRecorder({ theme: LIGHT_THEME, measureContext: measure });
  view.renderTo(recorder, view.width, view.height, LIGHT_THEME);
  return recorder.toString(title);
}

/**
 * The figure of `view` on a new canvas at `scale` × its CSS size, in `theme` (exports keep the
 * light theme's white background; gallery thumbnails follow the reader's).
 */
export function figureToCanvas(
  view,
  scale = PNG_SCALE,
  width = view.width,
  height = view.height,
  theme = LIGHT_THEME,
) {
  const canvas = document.createElement("canvas");
  canvas.width = Math.round(width * scale);
  canvas.height = Math.round(height * scale);
  const renderer = new CanvasRenderer(canvas.getContext("2d"), { pixelRatio: scale, theme });
  view.renderTo(renderer, width, height, theme);
  return canvas;
}

/**
 * The figure of `view` as a PNG Blob at `scale`. Encoded at once with `toDataURL`: Chromium's
 * `toBlob` waits for idle time and, on a busy page, for its 5-second fallback (measured: 1 export
 * in 5 took 6.7 s instead of 1.1 s in the browser tests), and the download would then start
 * long after the click.
 */
export function figureToPng(view, scale = PNG_SCALE) {
  const url = figureToCanvas(view, scale).toDataURL("image/png");
  const base64 = atob(url.slice(url.indexOf(",") + 1));
  const bytes = new Uint8Array(base64.length);
  for (let i = 0; i < base64.length; i++) bytes[i] = base64.charCodeAt(i);
  return Promise.resolve(new Blob([bytes], { type: "image/png" }));
}

/** Offers `blob` as a download named `filename`. */
export function download(blob, filename) {
  const url = URL.createObjectURL(blob);
  const link = document.createElement("a");
  link.href = url;
  link.download = filename;
  link.style.display = "none";
  document.body.append(link);
  link.click();
  link.remove();
  // Give the browser time to start the download before the URL is revoked.
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Blob helpers with the right MIME types. */
export const svgBlob = (text) => new Blob([text], { type: "image/svg+xml" });
export const texBlob = (text) => new Blob([text], { type: "application/x-tex" });
export const jsonBlob = (text) => new Blob([text], { type: "application/json" });
