/**
 * Every string the UI shows: titles, button labels, help texts, aria labels and the UI's own
 * error messages, keyed, in one table per language. Demos and the toolkit call `t(key, params)`
 * and never write English inline, so a translation is one more table passed to `addLocale`.
 *
 * `{name}` in a string is replaced by `params.name`. A missing key falls back to English, and a
 * key missing in English too is shown as itself (visible in the page, easy to spot).
 */

const EN = {
  // Application and gallery
  "app.name": "splinelab",
  "app.tagline": "Parametric curves you can drag: every algorithm of the course as a live figure.",
  "app.backToGallery": "← All demos",
  "app.loading": "Loading the curve library…",
  "app.wasmFailed": "The curve library could not be loaded ({message}). Run `make build`, then reload.",
  "app.unknownDemo": "There is no demo called “{id}”. Showing the gallery.",
  "app.footer": "All computation runs in your browser (Rust compiled to WebAssembly).",
  "gallery.heading": "Demos, by syllabus section",
  "gallery.open": "Open the demo",
  "gallery.thumbnailAlt": "Preview of {title}",
  "section.1": "1 · Parametric curves",
  "section.2": "2 · Bézier curves",
  "section.3": "3 · B-spline curves",
  "section.4": "4 · Rational curves and NURBS",
  "section.5": "5 · Interpolating curves",
  "section.6": "6 · Surfaces",

  // Toolbar
  "toolbar.label": "Demo tools",
  "toolbar.undo": "Undo",
  "toolbar.undo.title": "Undo (Ctrl+Z)",
  "toolbar.redo": "Redo",
  "toolbar.redo.title": "Redo (Ctrl+Shift+Z)",
  "toolbar.reset": "Reset",
  "toolbar.reset.title": "Back to the starting picture",
  "toolbar.fit": "Fit",
  "toolbar.fit.title": "Fit the view to the figure (drag empty space to pan, wheel or pinch to zoom)",
  "toolbar.share": "Share link",
  "toolbar.share.title": "Copy a link that restores this exact picture",
  "toolbar.svg": "SVG",
  "toolbar.svg.title": "Export the figure as SVG",
  "toolbar.png": "PNG",
  "toolbar.png.title": "Export the figure as PNG (2×, white background)",
  "toolbar.json": "JSON",
  "toolbar.json.title": "Export the state as JSON",
  "toolbar.import": "Import",
  "toolbar.import.title": "Load a state from a JSON file",
  "toolbar.lecture": "Lecture",
  "toolbar.lecture.title": "Large text and strokes for projection",
  "toolbar.export": "Export:",

  // Shell
  "shell.controls": "Controls",
  "shell.whatYouSee": "What you see",
  "shell.tryThis": "Try this",
  "shell.figureHelp": "Drag a point, or press Tab to select one and the arrow keys to move it (Shift: 10 px). Drag empty space to pan; wheel or pinch to zoom.",
  "shell.openInPlayground": "Open in the playground",

  // Status messages
  "status.linkCopied": "Link copied to the clipboard.",
  "status.linkShown": "Copy this link: {url}",
  "status.imported": "Imported “{name}”.",
  "status.exported": "Saved {name}.",
  "status.badLink": "This link could not be read ({message}); keeping the current picture.",
  "status.badImport": "“{name}” could not be imported ({message}); keeping the current picture.",
  "status.rejected": "That change was refused: {message}",
  "status.nothingToUndo": "Nothing to undo.",
  "status.nothingToRedo": "Nothing to redo.",

  // Validation and encoding (messages name the bad field)
  "error.notObject": "the state must be a JSON object",
  "error.unknownField": "unknown field “{field}”",
  "error.missingField": "field “{field}” is missing",
  "error.notFinite": "field “{field}” must be a finite number, got {value}",
  "error.notInteger": "field “{field}” must be a whole number, got {value}",
  "error.range": "field “{field}” must be between {min} and {max}, got {value}",
  "error.notBoolean": "field “{field}” must be true or false, got {value}",
  "error.notString": "field “{field}” must be one of {choices}, got {value}",
  "error.notArray": "field “{field}” must be a list",
  "error.count": "field “{field}” must have between {min} and {max} entries, got {count}",
  "error.pointShape": "field “{field}”: point {index} must be a pair [x, y]",
  "error.pointFinite": "field “{field}”: point {index} has a coordinate that is not a finite number",
  "error.window": "field “view” must be four finite numbers [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax",
  "error.badEncoding": "the state in the link is not valid (damaged or cut off)",
  "error.badJson": "not valid JSON: {message}",
  "error.version": "unsupported file version {version} (this page reads version {expected})",
  "error.wrongDemo": "the file is for the demo “{found}”, not “{expected}”",
  "error.attribute": "attribute “{name}”: {message}",

  // Shared controls
  "control.t": "Parameter t",
  "control.t.input": "t value (decimal or fraction such as 1/3)",
  "control.play": "Play",
  "control.pause": "Pause",
  "control.stepBack": "Step back",
  "control.stepForward": "Step",
  "control.stepBack.title": "t − 1/16",
  "control.stepForward.title": "t + 1/16",
  "control.addPoint": "Add point",
  "control.addPoint.title": "Add a point after the selected one (+)",
  "control.removePoint": "Remove point",
  "control.removePoint.title": "Remove the selected point (Delete)",
  "control.construction": "Show the construction",
  "control.badNumber": "“{value}” is not a number",

  // Curve words
  "curve.degree.1": "linear",
  "curve.degree.2": "quadratic",
  "curve.degree.3": "cubic",
  "curve.degree.4": "quartic",
  "curve.degree.5": "quintic",
  "curve.degree.n": "degree {n}",

  // Demo: de Casteljau
  "deCasteljau.title": "de Casteljau's algorithm",
  "deCasteljau.summary": "Repeated linear interpolation builds the point P(t) of a Bézier curve; every level of the triangle is drawn.",
  "deCasteljau.aria": "{kind} Bézier curve with {count} control points; t = {t}; point P(t) = ({x}, {y})",
  "deCasteljau.degree": "Degree n = {n} ({count} control points)",
  "deCasteljau.tableCaption": "The de Casteljau triangle at t = {t}: row r holds the points of level r",
  "deCasteljau.tableLevel": "r = {r}",
  "deCasteljau.pointLabel": "P(t)",
  "deCasteljau.minPoints": "a Bézier curve here needs at least {min} control points",
  "deCasteljau.maxPoints": "this demo allows at most {max} control points",
  "deCasteljau.whatYouSee":
    "A Bézier curve (blue) and its control polygon (grey, dashed). For the parameter t, each leg of the polygon is cut in the ratio t : (1 − t); the new points (level 1) form a shorter polygon that is cut again, until one point is left: the point P(t) on the curve (vermillion). The starting picture is the worked example of the Greek notes (section 2 of the syllabus): P₀ = (0, 0), P₁ = (2, 2), P₂ = (6, 4), P₃ = (8, 2) at t = 1/4 gives P(t) = (29/16, 23/16).",
  "deCasteljau.try1": "Press Play and watch the construction slide along the polygon while P(t) traces the curve.",
  "deCasteljau.try2": "Drag P₂ and watch which part of the curve moves most: the Bernstein weight of P₂ peaks at t = 2/3.",
  "deCasteljau.try3": "Select a point with Tab and press + to add one: the degree rises and the triangle grows a level.",

  // Demo: bernstein (strings of www/demos/bernstein.js; keys start with the demo's `strings` prefix)

  // Demo: subdivision (strings of www/demos/subdivision.js; keys start with the demo's `strings` prefix)

  // Demo: flattening (strings of www/demos/flattening.js; keys start with the demo's `strings` prefix)

  // Demo: line-intersection (strings of www/demos/line-intersection.js; keys start with the demo's `strings` prefix)

  // Demo: joining (strings of www/demos/joining.js; keys start with the demo's `strings` prefix)

  // Demo: bezier-properties (strings of www/demos/bezier-properties.js; keys start with the demo's `strings` prefix)

  // Demo: derivatives (strings of www/demos/derivatives.js; keys start with the demo's `strings` prefix)
};

const locales = { en: EN };
let active = EN;

/** Adds (or extends) the string table of a language. */
export function addLocale(code, table) {
  locales[code] = { ...(locales[code] ?? {}), ...table };
}

/** Makes `code` the active language (falls back to English for missing keys). */
export function setLocale(code) {
  active = locales[code] ?? EN;
}

/** The string for `key` with `{name}` placeholders replaced from `params`. */
export function t(key, params) {
  const template = active[key] ?? EN[key] ?? key;
  if (!params) return template;
  return template.replace(/\{(\w+)\}/g, (whole, name) => (name in params ? String(params[name]) : whole));
}

/** True when a key exists (used for optional demo texts such as a third "Try this"). */
export function has(key) {
  return key in active || key in EN;
}
