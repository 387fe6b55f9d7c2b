/**
 * Every string the UI shows: titles, button labels, help texts, aria labels and the UI's own
 * error messages, keyed, in one table per language. Demos and the toolkit call `t(key, params)`
 * and never write English inline, so a translation is one more table passed to `addLocale`.
 *
 * `{name}` in a string is replaced by `params.name`. A missing key falls back to English, and a
 * key missing in English too is shown as itself (visible in the page, easy to spot).
 *
 * Plurals: `tp(key, count, params)` picks `<key>.<category>` by `Intl.PluralRules` of the
 * active language (English has `.one` and `.other`; others add `.few`, `.many`, …), falling back
 * to `<key>.other`, then to `key` itself; `{count}` is the count. Numbers in sentences go through
 * `formatNumber` (`Intl.NumberFormat` of the active language).
 */

// Section 5's demos keep their strings in one file each (www/lib/strings/<id>.js).
import { LAGRANGE } from "./strings/lagrange.js";
import { HERMITE } from "./strings/hermite.js";
import { CARDINAL } from "./strings/cardinal.js";
import { CUBIC_SPLINE } from "./strings/cubic-spline.js";
import { PARAMETRIZATION } from "./strings/parametrization.js";
import { BSPLINE_INTERPOLATION } from "./strings/bspline-interpolation.js";
import { INTERPOLATE_APPROXIMATE } from "./strings/interpolate-approximate.js";
// Section 6 (surfaces) likewise.
import { BEZIER_PATCH } from "./strings/bezier-patch.js";
import { NURBS_SURFACE } from "./strings/nurbs-surface.js";
import { SURFACE_INTERPOLATION } from "./strings/surface-interpolation.js";
import { SURFACE_REVOLUTION } from "./strings/surface-revolution.js";
import { PATCH_DE_CASTELJAU } from "./strings/patch-de-casteljau.js";
import { PATCH_SUBDIVISION } from "./strings/patch-subdivision.js";
// Section 1 (typed parametric curves): parametric-curve.
import { PARAMETRIC_CURVE } from "./strings/parametric-curve.js";
// The curve library's errors by code (lib/core-errors.js writes them).
import { CORE_ERRORS } from "./strings/core-errors.js";
// Section 1: the typed piecewise curve.
import { PIECEWISE } from "./strings/piecewise.js";
// Section 7: the sketch demo (issue 25).
import { SKETCH } from "./strings/sketch.js";

const EN = {
  // Application and gallery
  "app.name": "splinelab",
  "app.galleryTitle": "{app} — {heading}",
  "app.demoTitle": "{title} — {app}",
  "app.language": "Language",
  "app.tagline": "Parametric curves you can drag: every algorithm of the course as a live figure.",
  "app.backToGallery": "← All demos",
  "app.loading": "Loading the curve library…",
  "app.noSimd":
    "This browser cannot run the curve library: it needs WebAssembly SIMD (Chrome or Edge 91, Firefox 89, Safari 16.4 or newer).",
  "app.wasmFailed":
    "The curve library could not be loaded ({message}). Run `make build`, then reload.",
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
  "section.7": "7 · Interactive design",
  "gallery.lecture": "Lecture: this section scene by scene, for projection",
  "gallery.exercise": "Exercise: {title}",
  "exercise.label": "Exercise",
  "exercise.check": "Check",
  "exercise.hint": "Hint",
  "exercise.solved": "Solved: the core confirms it.",
  "exercise.unknown": "There is no exercise “{id}”.",
  "exercise.close-the-gap.title": "Close the gap",
  "exercise.close-the-gap.task":
    "The two cubics do not meet. Drag Q₀ onto P₃ so that the curve is continuous (C⁰).",
  "exercise.close-the-gap.hint":
    "C⁰ asks only that the last point of the first piece is the first point of the second: Q₀ = P₃ = (4, 1).",
  "exercise.close-the-gap.notYet": "Not yet: Q₀ is {detail} away from P₃.",
  "exercise.make-it-c1.title": "Make the joint C¹",
  "exercise.make-it-c1.task":
    "The pieces meet, but with a corner. Move Q₁ so that the joint is C¹: the same derivative on both sides.",
  "exercise.make-it-c1.hint":
    "For two cubics C¹ means 3(P₃ − P₂) = 3(Q₁ − Q₀), so Q₁ = 2P₃ − P₂ = (5, −1).",
  "exercise.make-it-c1.notYet": "Not yet: the core measures C{detail} at the joint.",
  "exercise.bezier-pieces.title": "Cut the curve into Bézier segments",
  "exercise.bezier-pieces.task":
    "Insert knots until every interior knot has multiplicity p = 2: then the curve falls apart into quadratic Bézier segments.",
  "exercise.bezier-pieces.hint":
    "The interior knots are 1, 2 and 3, each once. Insert each of them once more: set u to the knot and press Insert.",
  "exercise.bezier-pieces.notYet": "Not yet: the curve is still C¹ at {detail} interior knots.",
  "exercise.quarter-circle.title": "A quarter of a circle",
  "exercise.quarter-circle.task":
    "The control points (4, 0), (4, 4), (0, 4) form an isosceles triangle. Choose the weight w₁ so that the arc is exactly a quarter of the circle of radius 4 about (0, 0).",
  "exercise.quarter-circle.hint":
    "For a circular arc w₁ is the cosine of half the sweep: here the sweep is 90°, so w₁ = cos 45° = √2/2 ≈ 0.7071.",
  "exercise.quarter-circle.notYet": "Not yet: the radius varies by {detail} % along the arc.",
  "exercise.natural-ends.title": "A natural spline",
  "exercise.natural-ends.task":
    "This spline uses the not-a-knot end condition. Change it so that the spline is natural: no bending at its ends.",
  "exercise.natural-ends.hint":
    "Natural means C″ = 0 at both ends: choose the end condition “natural”.",
  "exercise.natural-ends.notYet": "Not yet: |C″| at the ends is {detail}.",
  "exercise.horn-torus.title": "A horn torus",
  "exercise.horn-torus.task":
    "Change the torus so that its tube touches the axis of revolution: a horn torus.",
  "exercise.horn-torus.hint":
    "The tube's circle has its centre at (R, 0, 0) and radius r; it touches the z axis when R = r.",
  "exercise.horn-torus.notYet": "Not yet: the tube stays {detail} away from the axis.",
  "exercise.through-every-point.title": "Through every point",
  "exercise.through-every-point.task":
    "The curve touches only the first and the last point. Without moving any point, make it pass through all of them.",
  "exercise.through-every-point.hint":
    "Read the points as data instead of control points, with as many control points as data points: interpolation instead of approximation.",
  "exercise.through-every-point.notYet": "Not yet: the curve meets {detail} of the points.",
  "lecture.label": "Lecture",
  "lecture.previous": "← Previous",
  "lecture.next": "Next →",
  "lecture.counter": "{k} / {n}",
  "lecture.unknown": "There is no lecture “{id}”.",
  "lecture.loadFailed": "The lecture “{id}” could not be loaded (HTTP {status}).",

  // Toolbar
  "toolbar.label": "Demo tools",
  "toolbar.undo": "Undo",
  "toolbar.undo.title": "Undo (Ctrl+Z)",
  "toolbar.redo": "Redo",
  "toolbar.redo.title": "Redo (Ctrl+Shift+Z)",
  "toolbar.reset": "Reset",
  "toolbar.reset.title": "Back to the starting picture",
  "toolbar.fit": "Fit",
  "toolbar.fit.title":
    "Fit the view to the figure (drag empty space to pan, wheel or pinch to zoom)",
  "toolbar.share": "Share link",
  "toolbar.share.title": "Copy a link that restores this exact picture",
  "toolbar.svg": "SVG",
  "toolbar.svg.title": "Export the figure as SVG",
  "toolbar.tikz": "TikZ",
  "toolbar.tikz.title": "Export the figure as TikZ/PGF: a .tex file that pdflatex compiles",
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
  "shell.formula": "Formula",
  "shell.whatYouSee": "What you see",
  "shell.tryThis": "Try this",
  "shell.figureHelp3d":
    "Drag a point (in the plane facing you), or press Tab to select one: arrow keys move it (Shift: 10 px), PageUp/PageDown towards or away from you. Drag empty space to orbit, Shift-drag, right-drag or two fingers to pan, wheel or pinch to zoom; with no point selected the arrow keys orbit.",
  "shell.figureHelp3dTyped":
    "The curve follows the formulas typed in the panel. Drag to orbit, Shift-drag, right-drag or two fingers to pan, wheel or pinch to zoom; the arrow keys orbit.",
  "shell.figureHelp":
    "Drag a point, or press Tab to select one and the arrow keys to move it (Shift: 10 px). Drag empty space to pan; wheel or pinch to zoom.",
  "shell.figureHelpTyped":
    "The curve follows the formulas typed in the panel. Drag the figure to pan; wheel or pinch to zoom.",
  "shell.openInPlayground": "Open in the playground",

  // Handles (figure accessibility: role description, live-region announcements)
  "handles.roleDescription": "interactive figure",
  "handles.selected": "{label} selected, ({x}, {y})",
  "handles.moved": "{label} moved to ({x}, {y})",
  "handles.selected3d": "{label} selected, ({x}, {y}, {z})",
  "handles.moved3d": "{label} moved to ({x}, {y}, {z})",
  "scene3d.legend.gaussian": "Gaussian curvature K",
  "scene3d.legend.mean": "mean curvature H",

  // Status messages
  "status.linkCopied": "Link copied to the clipboard.",
  "status.linkShown": "Copy this link: {url}",
  "status.imported": "Imported “{name}”.",
  "status.exported": "Saved {name}.",
  "status.badLink": "This link could not be read ({message}); keeping the current picture.",
  "status.importTooLarge":
    "“{name}” is {size} MB; files above {max} MB are not imported (a state is a few kilobytes).",
  "status.badImport": "“{name}” could not be imported ({message}); keeping the current picture.",
  "status.rejected": "That change was refused: {message}",
  "status.nothingToUndo": "Nothing to undo.",
  "status.nothingToRedo": "Nothing to redo.",

  // Validation and encoding (messages name the bad field)
  "format.quoted": "“{value}”",
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
  "error.pointShape3": "field “{field}”: point {index} must be a triple [x, y, z]",
  "error.gridCount":
    "field “{field}” must have {rows} × {cols} = {expected} points (rows along u), got {count}",
  "error.camera":
    "field “view” must be a camera [azimuth, elevation, distance, x, y, z]: finite numbers, distance > 0, |elevation| ≤ 89°",
  "error.pointFinite":
    "field “{field}”: point {index} has a coordinate that is not a finite number",
  "error.knots": "field “{field}”: {message}",
  "error.window":
    "field “view” must be four finite numbers [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax",
  "error.badEncoding": "the state in the link is not valid (damaged or cut off)",
  "error.badJson": "not valid JSON: {message}",
  "error.version": "unsupported file version {version} (this page reads version {expected})",
  "error.wrongDemo": "the file is for the demo “{found}”, not “{expected}”",
  "error.attribute": "attribute “{name}”: {message}",
  "error.recordShape": "“{value}” must have one text for each of {fields}, separated by commas",
  "error.unknownDemo": "there is no demo called “{id}”",

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
  "deCasteljau.summary":
    "Repeated linear interpolation builds the point P(t) of a Bézier curve; every level of the triangle is drawn.",
  "deCasteljau.aria":
    "{kind} Bézier curve with {count} control points; t = {t}; point P(t) = ({x}, {y})",
  "deCasteljau.degree": "Degree n = {n} ({count} control points)",
  "deCasteljau.tableCaption":
    "The de Casteljau triangle at t = {t}: row r holds the points of level r",
  "deCasteljau.tableLevel": "r = {r}",
  "deCasteljau.pointLabel": "P(t)",
  "deCasteljau.minPoints": "a Bézier curve here needs at least {min} control points",
  "deCasteljau.maxPoints": "this demo allows at most {max} control points",
  "deCasteljau.whatYouSee":
    "A Bézier curve (blue) and its control polygon (grey, dashed). For the parameter t, each leg of the polygon is cut in the ratio t : (1 − t); the new points (level 1) form a shorter polygon that is cut again, until one point is left: the point P(t) on the curve (vermillion). The starting picture is the worked example of the Greek notes (section 2 of the syllabus): P₀ = (0, 0), P₁ = (2, 2), P₂ = (6, 4), P₃ = (8, 2) at t = 1/4 gives P(t) = (29/16, 23/16).",
  "deCasteljau.try1":
    "Press Play and watch the construction slide along the polygon while P(t) traces the curve.",
  "deCasteljau.try2":
    "Drag P₂ and watch which part of the curve moves most: the Bernstein weight of P₂ peaks at t = 2/3.",
  "deCasteljau.try3":
    "Select a point with Tab and press + to add one: the degree rises and the triangle grows a level.",

  // Demo: bernstein (strings of www/demos/bernstein.js; keys start with the demo's `strings` prefix)
  "bernstein.title": "Bernstein basis",
  "bernstein.summary":
    "The weights behind a Bézier curve: every Bᵢⁿ(t) plotted under the curve, summing to 1, each largest at t = i/n.",
  "bernstein.aria":
    "{kind} Bézier curve with {count} control points, and its {count} Bernstein basis functions of degree {n} plotted below; t = {t}; weights {values} (sum {sum}); point P(t) = ({x}, {y})",
  "bernstein.ariaPeak": "; {b} highlighted: largest at t = {t}, where the curve is at ({x}, {y})",
  "bernstein.degree": "Degree n = {n} ({count} control points, {count} basis functions)",
  "bernstein.pointLabel": "P(t)",
  "bernstein.peakPointLabel": "P({t})",
  "bernstein.peakLabel": "max at t = {t}",
  "bernstein.marker": "t = {t}",
  "bernstein.axisT": "t",
  "bernstein.axisValue0": "0",
  "bernstein.axisValue1": "1",
  "bernstein.formulaPeak": "largest at",
  "bernstein.tableCaption":
    "Bernstein weights of degree {n} at t = {t} (hover or focus a row to highlight its control point)",
  "bernstein.colFunction": "Basis function",
  "bernstein.colValue": "Bᵢⁿ(t)",
  "bernstein.colMirror": "Bₙ₋ᵢⁿ(1 − t) (symmetry)",
  "bernstein.colPeak": "Maximum",
  "bernstein.rowName": "{b}, weight of {p}",
  "bernstein.peakCell": "{value} at t = {t}",
  "bernstein.sumRow": "Sum",
  "bernstein.sumNote": "Sum of the {count} weights at t = {t}: {sum}",
  "bernstein.peakNote":
    "{b}, the weight of {p}, is largest at t = {t}: moving {p} moves the curve most around P({t}) = ({x}, {y}).",
  "bernstein.peakHint":
    "Hover a basis function in the plot or a row of the table, or select a control point (Tab), to see where it acts most.",
  "bernstein.minPoints": "a Bézier curve here needs at least {min} control points",
  "bernstein.maxPoints": "this demo allows at most {max} control points",
  "bernstein.whatYouSee":
    "A Bézier curve (blue) with its control polygon, and under it the graphs of its Bernstein basis functions Bᵢⁿ(t) on 0 ≤ t ≤ 1, each in the colour of the ring around its control point Pᵢ. The point P(t) (vermillion) is the sum of the Pᵢ weighted by the values where the marker crosses the graphs; these weights are never negative and always add up to 1. Bᵢⁿ has a single maximum, at t = i/n: that is where moving Pᵢ changes the curve most (highlighted band and P(i/n)). The starting picture is the cubic worked example of the Greek notes (section 2 of the syllabus) at t = 1/4, with weights 27/64, 27/64, 9/64, 1/64.",
  "bernstein.try1":
    "Hover the green graph B₁³ (or select P₁ with Tab): its maximum is at t = 1/3, and the band on the curve shows where P₁ pulls hardest; now drag P₁ and watch that part move.",
  "bernstein.try2":
    "Drag the marker in the plot (or press Play): the weights change, but the Sum row of the table always reads 1. Compare the two middle columns: Bᵢⁿ(t) equals Bₙ₋ᵢⁿ(1 − t) (symmetry).",
  "bernstein.try3":
    "Press + to add control points: the graphs get narrower and lower, each still peaking at i/n, so every point acts more locally.",

  // Demo: subdivision (strings of www/demos/subdivision.js; keys start with the demo's `strings` prefix)
  "subdivision.title": "Subdivision",
  "subdivision.summary":
    "Split a Bézier curve at t₀ into two Bézier curves: their control polygons are the edges of the de Casteljau triangle; repeated halving converges to the curve.",
  "subdivision.aria":
    "{kind} Bézier curve with {count} control points split at t₀ = {t} into a left polygon L₀…L{n} and a right polygon R₀…R{n}; split point ({x}, {y})",
  "subdivision.ariaLevels":
    "; repeated subdivision at 1/2, level {k}: {polygons} polygons with {total} control points",
  "subdivision.control.t": "Split at t₀",
  "subdivision.control.t.input": "t₀ value (decimal or fraction such as 1/3)",
  "subdivision.control.stepBack.title": "t₀ − 1/16",
  "subdivision.control.stepForward.title": "t₀ + 1/16",
  "subdivision.control.levels": "Repeated halving: levels",
  "subdivision.control.levels.input": "Number of levels of subdivision at 1/2 (0 to 6)",
  "subdivision.control.triangle": "Show the de Casteljau triangle",
  "subdivision.levelsNote":
    "Level {k}: {polygons} polygons, {total} control points ({distinct} distinct: neighbours share an end point).",
  "subdivision.levelsNote0":
    "Level 0: 1 polygon (the curve's own), {total} control points. Raise the levels to halve every piece again and again at 1/2.",
  "subdivision.degree": "Degree n = {n} ({count} control points)",
  "subdivision.leftLabel": "L{i}",
  "subdivision.rightLabel": "R{i}",
  "subdivision.firstLabel": "{p} = {l}",
  "subdivision.lastLabel": "{p} = {r}",
  "subdivision.splitLabel": "{l} = {r}",
  "subdivision.splitPointLabel": "P(t₀)",
  "subdivision.formulaPolygons.one": "polygon",
  "subdivision.formulaPolygons.other": "polygons",
  "subdivision.formulaPoints": "control points",
  "subdivision.tableCaption":
    "Control points of the two halves at t₀ = {t}: left lᵢ (top edge of the triangle), right rᵢ (hypotenuse)",
  "subdivision.colIndex": "i",
  "subdivision.colLeft": "Left half, on [0, t₀]",
  "subdivision.colRight": "Right half, on [t₀, 1]",
  "subdivision.minPoints": "a Bézier curve here needs at least {min} control points",
  "subdivision.maxPoints": "this demo allows at most {max} control points",
  "subdivision.whatYouSee":
    "A Bézier curve (blue) cut at t₀ (vermillion point) into two Bézier curves of the same degree. The left piece has the control points L₀ … Lₙ (green, solid), the first point of every level of the de Casteljau triangle (its top edge); the right piece has R₀ … Rₙ (purple, dashed, squares), the last point of every level (the hypotenuse); the rest of the triangle is drawn faintly. With levels above 0, every piece is halved again and again at 1/2: after k levels 2ᵏ small polygons hug the curve, which is why repeated subdivision converges to it. The starting picture is the cubic worked example of the Greek notes (section 2 of the syllabus); at t₀ = 1/4 the halves meet at (29/16, 23/16).",
  "subdivision.try1":
    "Type 1/4 for t₀: the table shows the worked example's left points (0, 0), (1/2, 1/2), (9/8, 1), (29/16, 23/16) and right points (29/16, 23/16), (31/8, 11/4), (13/2, 7/2), (8, 2).",
  "subdivision.try2":
    "Raise the levels to 3: eight polygons, already close to the curve; at 5 or 6 they are hard to tell from it.",
  "subdivision.try3":
    "Drag t₀ towards 0: the left polygon shrinks to the point P₀ while the right polygon becomes the original one.",

  // Demo: flattening (strings of www/demos/flattening.js; keys start with the demo's `strings` prefix)
  "flattening.title": "Adaptive flattening",
  "flattening.summary":
    "A Bézier curve drawn as a polyline that stays within a tolerance ε: short segments where it bends, long ones where it is straight.",
  "flattening.tolerance": "Tolerance ε (world units)",
  "flattening.tolerance.input": "tolerance ε, from {min} to {max}",
  "flattening.badTolerance":
    "tolerance ε: “{value}” is not a number from {min} to {max}; keeping the current value",
  "flattening.flattenFailed":
    "the polyline could not be computed ({message}); showing the last one",
  "flattening.band": "Show the tolerance band (width 2ε)",
  "flattening.presets": "Shapes",
  "flattening.preset.title": "Move the four control points to this shape",
  "flattening.preset.s": "S-curve",
  "flattening.preset.loop": "Loop",
  "flattening.preset.cusp": "Cusp",
  "flattening.preset.straight": "Nearly straight",
  "flattening.segments.one": "{count} segment",
  "flattening.segments.other": "{count} segments",
  "flattening.half": "With ε/2 = {tolerance}: {count} segments (× {ratio}; √2 ≈ 1.41)",
  "flattening.countLabel": "{count} segments at ε = {tolerance}",
  "flattening.aria":
    "cubic Bézier curve with control points {points}, flattened with tolerance {tolerance}: a polyline of {count} segments ({vertices} vertices); with tolerance {half}: {halfCount} segments",
  "flattening.formula.whole": "whole curve:",
  "flattening.formula.flat": "flat: one segment",
  "flattening.formula.split": "split",
  "flattening.formula.until": "split until each piece passes, then draw the chords:",
  "flattening.formula.segments": "segments",
  "flattening.whatYouSee":
    "The blue cubic is drawn as the orange polyline that the library returns for the tolerance ε: every point of the curve lies within ε of it, so the curve never leaves the grey band of width 2ε. The test is the one of the Greek notes (section 2 of the syllabus, “adaptive drawing”): a piece is flat enough when its inner control points are within ε of the chord P₀P₃; otherwise the piece is cut shorter and tested again (the library halves or doubles each piece's parameter step until the test brackets, so it needs few segments). Where the curve bends the pieces are short, where it is nearly straight one long chord suffices, and halving ε multiplies the number of segments by about √2.",
  "flattening.try1":
    "Drag the tolerance slider from 1 down to 0.001 and watch the segments crowd where the curve bends most.",
  "flattening.try2":
    "Press “Loop” and “Cusp”: the short segments gather at the loop and at the sharp tip, while the flat ends get long ones.",
  "flattening.try3":
    "Press “Nearly straight”, then drag P₁ away from the line: the count jumps from a few segments to many.",

  // Demo: line-intersection (strings of www/demos/line-intersection.js; keys start with the demo's `strings` prefix)
  "lineIntersection.title": "Curve–line intersection",
  "lineIntersection.summary":
    "Where a line meets a Bézier curve, found by splitting the curve and throwing away every box the line misses.",
  "lineIntersection.handleA": "A",
  "lineIntersection.handleB": "B",
  "lineIntersection.sameLinePoints":
    "field “line”: the two points must differ, got ({x}, {y}) twice",
  "lineIntersection.failed":
    "the intersections could not be computed ({message}); showing the last ones",
  "lineIntersection.depth": "Recursion depth shown",
  "lineIntersection.depth.input": "depth, a whole number from 0 to {max}",
  "lineIntersection.badDepth":
    "depth: “{value}” is not a whole number from 0 to {max}; keeping the current depth",
  "lineIntersection.shallower": "◀ Level",
  "lineIntersection.shallower.title": "Show one level fewer",
  "lineIntersection.deeper": "Level ▶",
  "lineIntersection.deeper.title": "Show one level more",
  "lineIntersection.boxes":
    "Depth {depth} of {deepest}. Boxes visited: {visited}; meeting the line: {hit}; pruned: {pruned}. Boxes stop splitting below {tolerance}.",
  "lineIntersection.none": "no intersection",
  "lineIntersection.count.one": "1 intersection",
  "lineIntersection.count.other": "{count} intersections",
  "lineIntersection.crossings":
    "The line crosses the control polygon {polygon} times and the curve {curve} times: a line never crosses the curve more often than its polygon (variation diminishing).",
  "lineIntersection.rootLabel": "t = {t}",
  "lineIntersection.aria":
    "cubic Bézier curve with control points {points} and the line through A = {a} and B = {b}: {result}; the line crosses the control polygon {polygon} times; boxes of the recursion shown up to depth {depth} of {deepest}",
  "lineIntersection.tableCaption":
    "Intersections, sorted by t (each point within {tolerance} of the line)",
  "lineIntersection.tableNone": "No intersection: the line misses the curve.",
  "lineIntersection.tableRoot": "root",
  "lineIntersection.tablePoint": "P(t)",
  "lineIntersection.formula.miss": "one sign at the box corners",
  "lineIntersection.formula.pruned": "line misses box: pruned",
  "lineIntersection.formula.until": ", until the box is below",
  "lineIntersection.formula.split": "else split at",
  "lineIntersection.formula.curve": "curve",
  "lineIntersection.formula.polygon": "polygon",
  "lineIntersection.whatYouSee":
    "A cubic (blue) and the infinite line through A and B (green). The search of the Greek notes (section 2 of the syllabus): take the box around the control points; if the line misses it, no part of the curve inside can meet the line and the box is pruned (faint grey); otherwise split the curve at t = 1/2 and look at both halves, until the boxes (orange outlines) are smaller than 0.001. The vermillion points are the intersections the library returns (refined to within 10⁻⁹ of the line), labelled with their t; as the variation-diminishing property promises, there are never more of them than crossings of the control polygon.",
  "lineIntersection.try1":
    "Set the depth to 0 and press “Level ▶” step by step: boxes away from the line drop out, the rest shrink onto the three crossings.",
  "lineIntersection.try2":
    "Drag B upwards until the line leaves the curve: the count falls to 1, then to “no intersection”, and the first box is already pruned.",
  "lineIntersection.try3":
    "Drag P₁ and P₂ to flatten the control polygon: the polygon crossings fall, and the curve crossings never exceed them.",

  // Demo: joining (strings of www/demos/joining.js; keys start with the demo's `strings` prefix)
  "joining.title": "Joining two curves",
  "joining.summary":
    "Two cubic Bézier pieces meet at a joint; a rule (C0, C1, G1, C2) keeps them joined while you drag, and a checker reports the continuity.",
  "joining.aria":
    "Two cubic Bézier pieces, P on t in [0, 1] and Q on t in [1, 2]; rule {rule}; checker: {verdict}; P′(1) = {dp}, Q′(1) = {dq}",
  "joining.ruleLegend": "Rule at the joint",
  "joining.rule.none": "none (drag freely)",
  "joining.rule.C0": "C⁰: the pieces meet",
  "joining.rule.C1": "C¹: equal velocity",
  "joining.rule.G1": "G¹: same tangent line",
  "joining.rule.C2": "C²: equal acceleration too",
  "joining.checkerLegend": "The continuity checker",
  "joining.verdict": "{c}, {g} at the joint",
  "joining.verdict.broken": "not even C⁰: the pieces do not meet",
  "joining.verdict.infinite": "C∞: one polynomial",
  "joining.legend.none":
    "Nothing is enforced: every point moves on its own, and the checker reports whatever the joint has become.",
  "joining.legend.C0": "The square marks the point the rule sets: Q₀ = P₃. Drag it and P₃ follows.",
  "joining.legend.C1":
    "Squares mark the points the rule sets: Q₀ = P₃ and Q₁ = 2P₃ − P₂ (P₂ mirrored in the joint). Drag a square and the left piece follows instead.",
  "joining.legend.G1":
    "Squares mark the points the rule sets: Q₀ = P₃, and Q₁ on the ray from P₂ through P₃. Q₁ slides only along that line: its distance is free, so the speed may jump.",
  "joining.legend.C2":
    "Squares mark the points the rule sets: Q₀, Q₁ and Q₂ = P₁ − 4P₂ + 4P₃. The legs P₁P₂ and Q₂Q₁ extended meet in one point D (the A-frame).",
  "joining.free.none": "Free: all eight points.",
  "joining.free.C0": "Free: P₀, P₁, P₂, Q₁, Q₂, Q₃ and the joint.",
  "joining.free.C1": "Free: P₀, P₁, Q₂, Q₃, the joint and one of P₂, Q₁.",
  "joining.free.G1": "Free: P₀, P₁, P₂, Q₂, Q₃, the joint and the length of Q₀Q₁.",
  "joining.free.C2":
    "For two cubics C² leaves only P₀ and Q₃ free-ish: P₁, P₂ and the joint fix Q₁ and Q₂.",
  "joining.leftArrow": "P′(1)",
  "joining.rightArrow": "Q′(1)",
  "joining.pointD": "D",
  "joining.arrowCaption":
    "Arrows: velocity P′(1) arriving and Q′(1) leaving the joint, drawn at 1/6 length",
  "joining.tableCaption":
    "At the joint t = 1 (derivatives from the core, P on [0, 1], Q on [1, 2])",
  "joining.row.p3-p2": "P₃ − P₂",
  "joining.row.q1-q0": "Q₁ − Q₀",
  "joining.row.dp": "P′(1)",
  "joining.row.dq": "Q′(1)",
  "joining.row.ddp": "P″(1)",
  "joining.row.ddq": "Q″(1)",
  "joining.formula.none":
    "No rule: the checker compares P(1), P′(1), P″(1) with Q(1), Q′(1), Q″(1)",
  "joining.formula.rule": "rule:",
  "joining.formula.anyLength": "any length",
  "joining.formula.notG1": "the tangent directions differ (or the pieces do not meet)",
  "joining.formula.checker": "checker:",
  "joining.formula.notC0": "not C⁰",
  "joining.whatYouSee":
    "Two cubic Bézier pieces: P (blue) on t ∈ [0, 1] and Q (green) on t ∈ [1, 2], joined at P₃ = Q₀. The chosen rule from section 2 of the syllabus (the Greek notes) is kept while you drag: the points it fixes (squares) follow, and the continuity checker of section 1 reports what the joint really is. The two arrows are the velocities arriving at and leaving the joint: for C¹ they are equal, for G¹ they only point the same way. For two cubics C² leaves only P₀ and Q₃ free-ish.",
  "joining.try1":
    "With C¹, drag P₂ and watch Q₁ mirror it through the joint; then pick G¹ and slide Q₁ along the dashed line: the checker drops to C⁰, G¹ as the arrows get different lengths.",
  "joining.try2":
    "Pick “none” and drag the joint’s Q₀ away from P₃: the checker reports that the pieces do not even meet.",
  "joining.try3":
    "Pick C² and drag P₁: Q₂ moves along with it through the A-frame point D, and only P₀ and Q₃ stay where you put them.",

  // Demo: bezier-properties (strings of www/demos/bezier-properties.js; keys start with the demo's `strings` prefix)
  "bezierProperties.title": "Properties of Bézier curves",
  "bezierProperties.summary":
    "Convex hull, affine invariance, symmetry, degree elevation and variation diminishing, each shown on one draggable curve.",
  "bezierProperties.propertyLegend": "Property",
  "bezierProperties.property.hull": "Convex hull",
  "bezierProperties.property.affine": "Affine map",
  "bezierProperties.property.reversed": "Reversed order (symmetry)",
  "bezierProperties.property.elevation": "Degree elevation",
  "bezierProperties.property.variation": "Variation diminishing",
  "bezierProperties.affineLegend": "The affine map (about the centroid c)",
  "bezierProperties.rotation": "Rotation (degrees)",
  "bezierProperties.rotation.input": "rotation in degrees",
  "bezierProperties.scale": "Scale",
  "bezierProperties.scale.input": "scale factor",
  "bezierProperties.shear": "Shear (x += k·y)",
  "bezierProperties.shear.input": "shear factor k",
  "bezierProperties.elevationLegend": "Degree elevation",
  "bezierProperties.elevations": "Elevations",
  "bezierProperties.elevations.input": "number of elevations (0 to 8)",
  "bezierProperties.lineA": "A",
  "bezierProperties.lineB": "B",
  "bezierProperties.lineDegenerate": "field “line”: its two points must differ",
  "bezierProperties.maxPoints": "this demo allows at most {max} control points",
  "bezierProperties.minPoints": "a Bézier curve here needs at least {min} control points",
  "bezierProperties.degree": "Degree n = {n} ({count} control points)",
  "bezierProperties.note.hull":
    "The grey region is the convex hull of the control points: every point of the curve is a weighted average of them, with weights ≥ 0 that sum to 1.",
  "bezierProperties.note.affine":
    "Green: the curve of the mapped control points (built by the core). Red dots: points of the blue curve mapped one by one with the same matrix. They lie on the green curve.",
  "bezierProperties.note.reversed":
    "Orange, dashed: the curve of the control points in reverse order Pₙ … P₀. Same points, opposite direction (the chevrons).",
  "bezierProperties.note.elevation":
    "Orange: the control polygon after the elevations. Same curve, one more point per elevation; the polygon creeps towards the curve.",
  "bezierProperties.note.variation":
    "Drag A and B to move the line: it never crosses the curve more often than it crosses the control polygon.",
  "bezierProperties.readout.hull": "Hull: {k} vertices ({names})",
  "bezierProperties.readout.affine": "Largest gap: {d}",
  "bezierProperties.readout.reversed": "Largest gap: {d}",
  "bezierProperties.readout.elevation": "{count} control points ({n} + {e})",
  "bezierProperties.readout.variation":
    "The line crosses the polygon {k} times, the curve {j} times",
  "bezierProperties.formula.sum": "sum",
  "bezierProperties.formula.hullVertices": "hull vertices",
  "bezierProperties.formula.because": "because",
  "bezierProperties.formula.samples": "samples",
  "bezierProperties.formula.forExample": "e.g.",
  "bezierProperties.formula.points": "control points",
  "bezierProperties.formula.lineCurve": "line ∩ curve",
  "bezierProperties.formula.linePolygon": "line ∩ polygon",
  "bezierProperties.tableCaption":
    "After one elevation: degree {n} → {m}, control points Q₀ … Q{last}",
  "bezierProperties.aria.hull":
    "{kind} Bézier curve inside the convex hull of its control points ({k} hull vertices)",
  "bezierProperties.aria.affine":
    "{kind} Bézier curve and its image under rotation {rotation}°, scale {scale}, shear {shear}; mapped curve points lie on the mapped curve (largest gap {d})",
  "bezierProperties.aria.reversed":
    "{kind} Bézier curve and the curve of its reversed control points drawn dashed over it (largest gap {d})",
  "bezierProperties.aria.elevation":
    "{kind} Bézier curve elevated {e} times: {count} control points, same curve",
  "bezierProperties.aria.variation":
    "{kind} Bézier curve and a line: the line crosses the control polygon {k} times and the curve {j} times",
  "bezierProperties.whatYouSee":
    "One Bézier curve (blue) and, one at a time, the properties listed in section 2 of the syllabus (from the Greek notes): it stays inside the convex hull of its control points; mapping the control points by an affine map maps the whole curve; the points in reverse order give the same curve run backwards; degree elevation adds a control point without changing the curve; and a line crosses the curve no more often than the control polygon. The start is the worked example P₀ = (0, 0), P₁ = (2, 2), P₂ = (6, 4), P₃ = (8, 2).",
  "bezierProperties.try1":
    "Pick “Affine map” and move the shear slider: the red dots (mapped curve points) stay on the green curve (built from the mapped control points).",
  "bezierProperties.try2":
    "Pick “Degree elevation” and raise the count to 8: the orange polygon has 12 points and hugs the curve.",
  "bezierProperties.try3":
    "Pick “Variation diminishing” and drag A and B so the line cuts the polygon as often as you can: the curve is crossed at most that often.",

  // Demo: derivatives (strings of www/demos/derivatives.js; keys start with the demo's `strings` prefix)
  "derivatives.title": "Derivatives and curvature",
  "derivatives.summary":
    "The velocity P′(t), the normal, the osculating circle and the signed curvature of a Bézier curve, with its hodograph beside it.",
  "derivatives.aria":
    "{kind} Bézier curve; t = {t}; P(t) = ({x}, {y}); velocity P′(t) = ({dx}, {dy}); curvature κ = {kappa}; the hodograph is drawn to the right",
  "derivatives.originLabel": "origin O",
  "derivatives.pointLabel": "P(t)",
  "derivatives.velocityLabel": "P′(t)",
  "derivatives.normalLabel": "N",
  "derivatives.straight": "Straight here (κ ≈ 0): no osculating circle",
  "derivatives.cusp": "Cusp: P′(t) = 0, the curvature is infinite",
  "derivatives.cuspShort": "a cusp",
  "derivatives.hodographCaption": "Hodograph P′(t) (degree {m}), origin O",
  "derivatives.scaleCaption": "Velocity arrows and the hodograph drawn at 1/{n} scale",
  "derivatives.curvatureLegend": "Curvature at t",
  "derivatives.readout": "κ(t) = {kappa}",
  "derivatives.radius":
    "Osculating circle of radius {r}, centre on the {side} of the direction of travel",
  "derivatives.left": "left (κ > 0: turning counter-clockwise)",
  "derivatives.right": "right (κ < 0: turning clockwise)",
  "derivatives.length": "Arc length L = {length}",
  "derivatives.degree": "Degree n = {n} ({count} control points)",
  "derivatives.minPoints": "this demo needs at least {min} control points (a quadratic or higher)",
  "derivatives.maxPoints": "this demo allows at most {max} control points",
  "derivatives.tableCaption":
    "Derivatives from the core at t = {t}, and the hodograph's control points",
  "derivatives.row.point": "P(t)",
  "derivatives.row.dp": "P′(t)",
  "derivatives.row.ddp": "P″(t)",
  "derivatives.row.kappa": "κ(t)",
  "derivatives.row.radius": "radius 1/|κ|",
  "derivatives.row.dp0": "P′(0)",
  "derivatives.row.dp1": "P′(1)",
  "derivatives.row.length": "arc length",
  "derivatives.row.hodograph": "H{i} = {label}",
  "derivatives.whatYouSee":
    "A Bézier curve (blue) with the point P(t), its velocity P′(t) (vermillion arrow), the unit normal N and the osculating circle (orange), the circle that hugs the curve at P(t), of radius 1/|κ|. To the right is the hodograph (green, section 2 of the syllabus, from the Greek notes): the curve traced by the velocity, a Bézier curve of one degree less whose control points are n(P₁ − P₀), n(P₂ − P₁), …; the arrow from its origin O is the same vector P′(t). The start is the worked example P₀ = (0, 0), P₁ = (2, 2), P₂ = (6, 4), P₃ = (8, 2).",
  "derivatives.try1":
    "Set t to 0 and then to 1: the velocity is 3(P₁ − P₀) = (6, 6) at the start and 3(P₃ − P₂) = (6, −6) at the end — the first and last legs of the hodograph's polygon.",
  "derivatives.try2":
    "Drag P₂ below the line P₀P₃: the curve turns the other way, κ changes sign and the circle jumps to the other side.",
  "derivatives.try3":
    "Press Play and watch the hodograph's arrow sweep along its curve while the tangent arrow rides along the curve: they are always the same vector.",

  // Demo: bspline-basis (strings of www/demos/bspline-basis.js; keys start with the demo's `strings` prefix)
  // (and the knot ruler of lib/knot-ruler.js, shared by the B-spline demos: keys "knotRuler.*")
  "knotRuler.selected": "knot {label} selected, {u}",
  "knotRuler.moved": "knot {label} moved to {u}",
  "knotRuler.valueMultiple": "{u} (×{r})",
  "knotRuler.break": "break",
  "knotRuler.domain": "domain [u{p}, u{n1}] = [{a}, {b}]",
  "bsplineBasis.title": "B-spline basis functions",
  "bsplineBasis.summary":
    "Every Nᵢ,ₚ from the Cox–de Boor recurrence, plotted under the curve over a knot ruler you can drag: local support, sum 1, and the triangle of values at u.",
  "bsplineBasis.aria":
    "{kind} B-spline with {count} control points and knots [{knots}]; at u = {u} (span [{a}, {b})) the non-zero basis functions are {values}, sum {sum}; point C(u) = ({x}, {y}); all basis functions are plotted under the curve, above the knot ruler",
  "bsplineBasis.ariaContinuity": "; continuity at the interior knots: {list}",
  "bsplineBasis.ariaSupport": "; {name} highlighted: support [{a}, {b})",
  "bsplineBasis.degreeLegend": "Degree p",
  "bsplineBasis.degreeOption": "{p}",
  "bsplineBasis.control.u": "Parameter u",
  "bsplineBasis.control.u.input": "u value in the domain (decimal or fraction such as 5/2)",
  "bsplineBasis.sumNote": "Σ Nᵢ,ₚ({u}) = {sum}",
  "bsplineBasis.knotNote":
    "{count} control points, degree p = {p}: {m} knots u₀ … u{last} (m + 1 = n + p + 2). Changing the degree or the number of points resets the knots to the clamped uniform vector.",
  "bsplineBasis.resetKnots": "Clamped uniform knots",
  "bsplineBasis.resetKnots.title":
    "Replace the knots by p + 1 equal end knots and equally spaced interior knots",
  "bsplineBasis.rulerHelp":
    "Knot ruler (under the plot): drag a knot — it cannot pass its neighbours; double-click it or press Enter to merge the next knot onto it; Delete splits a stack. Tab past the last control point selects the knots.",
  "bsplineBasis.minPoints": "a degree-{degree} B-spline needs at least {min} control points",
  "bsplineBasis.maxPoints": "this demo allows at most {max} control points",
  "bsplineBasis.fewPoints":
    "field “points”: a degree-{p} B-spline needs at least {need} control points, got {count}",
  "bsplineBasis.uRange": "field “u” must lie in the domain [{a}, {b}], got {u}",
  "bsplineBasis.multiplicity.max": "u{i} already has the largest multiplicity, p + 1 = {max}",
  "bsplineBasis.multiplicity.ends": "no interior knot is left to merge onto u{i}",
  "bsplineBasis.multiplicity.single": "u{i} is a simple knot: nothing to split",
  "bsplineBasis.pointLabel": "C(u)",
  "bsplineBasis.marker": "u = {u}",
  "bsplineBasis.axisValue0": "0",
  "bsplineBasis.axisValue1": "1",
  "bsplineBasis.axisU": "u",
  "bsplineBasis.formulaOtherwise": "otherwise",
  "bsplineBasis.tableCaption":
    "Basis functions of degree {p} at u = {u} (hover or focus a row to highlight its support)",
  "bsplineBasis.colFunction": "Basis function",
  "bsplineBasis.colSupport": "Support [uᵢ, uᵢ₊ₚ₊₁)",
  "bsplineBasis.colValue": "Nᵢ,ₚ(u)",
  "bsplineBasis.rowName": "{name}, weight of {point}",
  "bsplineBasis.supportCell": "[u{i}, u{j}) = [{a}, {b})",
  "bsplineBasis.sumRow": "Sum",
  "bsplineBasis.triangleCaption":
    "Cox–de Boor triangle at u = {u}: span k = {k}, [u{kSub}, u{k1Sub}) = [{a}, {b}); row r holds the degree-r values of i = k − r … k, each made from the two above it",
  "bsplineBasis.triangleCorner": "degree r",
  "bsplineBasis.triangleRow": "r = {r}",
  "bsplineBasis.whatYouSee":
    "A B-spline curve (blue) over its control polygon; under it, the graphs of its basis functions Nᵢ,ₚ(u), each in the colour of the ring around its control point Pᵢ; under the plot, the knot ruler with the knots u₀ … u_m and the domain [uₚ, uₙ₊₁] (blue bar). The point C(u) is the sum of the Pᵢ weighted by the values where the marker crosses the graphs: at most p + 1 of them are non-zero and they always add up to 1. Each Nᵢ,ₚ is zero outside its support [uᵢ, uᵢ₊ₚ₊₁), so Pᵢ only moves that piece of the curve. The start is the quadratic example of the Croatian notes (section 3 of the syllabus): U = [0, 0, 0, 1, 2, 3, 4, 4, 4], where at u = 5/2 the values are 1/8, 3/4, 1/8 — N₃,₂ = (−2u² + 10u − 11)/2 there (the notes misprint +11).",
  "bsplineBasis.try1":
    "Hover the purple graph N₂,₂ (or select P₂ with Tab): its support [0, 3) is shaded, and dragging P₂ moves only that part of the curve.",
  "bsplineBasis.try2":
    "Drag u₄ (the knot at 2) on the ruler towards u₅: the graphs around it stretch and squeeze, it stops at 3, and the label above it turns from C¹ to C⁰ when the two knots meet — or double-click u₄ to merge them in one step.",
  "bsplineBasis.try3":
    "Pick degree 3: the knots become [0, 0, 0, 0, 1, 2, 3, 3, 3, 3], every graph widens to four spans, and the triangle grows a row — the sum still reads 1.",

  // Demo: de-boor (strings of www/demos/de-boor.js; keys start with the demo's `strings` prefix)
  "deBoor.title": "de Boor's algorithm",
  "deBoor.summary":
    "Repeated interpolation of the p + 1 active control points builds the point C(u) of a B-spline; the knots decide every ratio α.",
  "deBoor.aria":
    "{kind} B-spline with {count} control points, knots {knots}; u = {u} in span k = {k}, [{uk}, {uk1}); point C(u) = ({x}, {y})",
  "deBoor.degree": "Degree p = {p}, {count} control points, {segments}",
  "deBoor.spans.one": "{count} non-empty span",
  "deBoor.spans.other": "{count} non-empty spans",
  "deBoor.span": "k = {k}: u ∈ [u{ks}, u{ks1}) = [{uk}, {uk1})",
  "deBoor.spanCaption": "span [u{k}, u{k1})",
  "deBoor.uCaption": "u = {u}",
  "deBoor.multiplicity": "×{r}",
  "deBoor.tableCaption":
    "The de Boor triangle at u = {u} (span k = {k}): row r holds dⱼʳ, j = r … p, with the α of its step",
  "deBoor.tableLevel": "r = {r}",
  "deBoor.alphaCell": "α = {value}",
  "deBoor.pointLabel": "C(u)",
  "deBoor.control.u": "Parameter u",
  "deBoor.control.u.input": "u value (decimal or fraction such as 3/2)",
  "deBoor.control.stepBack.title": "u − 1/16 of the domain",
  "deBoor.control.stepForward.title": "u + 1/16 of the domain",
  "deBoor.control.degree": "Degree p",
  "deBoor.control.degree.input": "degree p (1 to 5)",
  "deBoor.control.knots": "Knot vector U (type and press Enter)",
  "deBoor.knotsHelp":
    "{m} non-decreasing knots for {count} points of degree {p} (m + 1 = n + p + 2).",
  "deBoor.control.clamped": "Clamped uniform knots",
  "deBoor.control.clamped.title": "p + 1 equal knots at each end, 1, 2, … between",
  "deBoor.control.addPoint.title":
    "Add a point after the selected one (+); the knots become clamped uniform",
  "deBoor.control.removePoint.title":
    "Remove the selected point (Delete); the knots become clamped uniform",
  "deBoor.knotsReset": "The knot vector was reset to clamped uniform for the new points or degree.",
  "deBoor.degreeRange": "the degree must be a whole number from 1 to {max}, got “{value}”",
  "deBoor.minPoints": "a B-spline here needs at least {min} control points",
  "deBoor.maxPoints": "this demo allows at most {max} control points",
  "deBoor.error.degree":
    "field “degree” is {p}, but {count} control points allow at most degree {count} − 1",
  "deBoor.error.knotCount":
    "field “knots” must have n + p + 2 = {expected} entries for {count} points of degree {p}, got {got}",
  "deBoor.error.knotOrder":
    "field “knots” must not decrease: entry {index} is {value} after {previous}",
  "deBoor.error.multiplicity":
    "field “knots”: the knot {value} appears more than p + 1 = {max} times",
  "deBoor.error.domain": "field “knots”: the domain [u{p}, u{n1}] = [{a}, {b}] is empty",
  "deBoor.whatYouSee":
    "The dashed grey polygon holds all control points; only the p + 1 active ones of the span containing u (solid grey) take part. Each coloured level interpolates the one before it with its own ratio α, read off the knot vector, until one point C(u) remains — de Boor's algorithm from syllabus section 3 (the Croatian and Italian notes' convention). With knots 0 0 0 0 1 1 1 1 every α equals u and it is de Casteljau's construction.",
  "deBoor.try1":
    "Press Play and watch the active points jump when u crosses a knot on the strip below the figure.",
  "deBoor.try2":
    "Remove points until four remain, then type the knots 0 0 0 0 1 1 1 1 and u = 1/4: every α equals 1/4 and the triangle is de Casteljau's (for P₀ … P₃ = (0,0), (2,2), (6,4), (8,2) it ends at (29/16, 23/16)).",
  "deBoor.try3":
    "Type a repeated interior knot, e.g. 0 0 0 0 1 2 2 4 4 4 4: some α become 0 or 1 and the curve passes closer to a control point.",

  // Demo: knot-vectors (strings of www/demos/knot-vectors.js; keys start with the demo's `strings` prefix)
  "knotVectors.title": "Knot vector types",
  "knotVectors.summary":
    "One control polygon, three knot vectors: clamped curves start at P₀, unclamped ones do not, closed ones loop back smoothly.",
  "knotVectors.aria":
    "{kind} B-splines on {count} control points: clamped knots {clamped}, the clamped curve starts at {c0}; the unclamped uniform curve starts at {u0}; P₀ = {p0}; a closed curve loops through the cycle of points",
  "knotVectors.degree": "Degree p = {p}, {count} control points",
  "knotVectors.degreeRange": "the degree must be a whole number from 1 to {max}, got “{value}”",
  "knotVectors.minPoints": "a B-spline here needs at least {min} control points",
  "knotVectors.maxPoints": "this demo allows at most {max} control points",
  "knotVectors.error.degree":
    "field “degree” is {p}, but {count} control points allow at most degree {count} − 1",
  "knotVectors.control.degree": "Degree p",
  "knotVectors.control.degree.input": "degree p (1 to 5)",
  "knotVectors.control.spacing": "Interior knots of the clamped vector",
  "knotVectors.control.show": "Curves shown",
  "knotVectors.spacing.uniform": "uniform: 1, 2, …, n − p",
  "knotVectors.spacing.chord": "chord length: sums of |Pᵢ₊₁ − Pᵢ|",
  "knotVectors.spacing.centripetal": "centripetal: sums of √|Pᵢ₊₁ − Pᵢ|",
  "knotVectors.show.clamped": "Clamped (open) — solid blue",
  "knotVectors.show.unclamped": "Unclamped uniform — dashed green",
  "knotVectors.show.closed": "Closed (periodic) — dotted purple",
  "knotVectors.legend.clamped": "clamped (open)",
  "knotVectors.legend.clamped.uniform": "clamped (open) uniform",
  "knotVectors.legend.clamped.chord": "clamped, chord-length spacing",
  "knotVectors.legend.clamped.centripetal": "clamped, centripetal spacing",
  "knotVectors.legend.unclamped": "unclamped uniform",
  "knotVectors.legend.closed": "closed (periodic)",
  "knotVectors.style.clamped": "solid",
  "knotVectors.style.unclamped": "dashed",
  "knotVectors.style.closed": "dotted",
  "knotVectors.column.curve": "Curve",
  "knotVectors.column.knots": "Knot vector u₀ … uₘ",
  "knotVectors.column.domain": "Domain [uₚ, uₙ₊₁]",
  "knotVectors.column.start": "Start C(uₚ)",
  "knotVectors.column.end": "End C(uₙ₊₁)",
  "knotVectors.tableCaption":
    "The knot vectors, as the core builds them, and where each curve starts and ends",
  "knotVectors.tex.clamped": "clamped",
  "knotVectors.tex.chord": "chord",
  "knotVectors.tex.centripetal": "centripetal",
  "knotVectors.tex.unclamped": "unclamped",
  "knotVectors.tex.closed": "closed",
  "knotVectors.tex.domain": "domain",
  "knotVectors.tex.seam": "at the seam",
  "knotVectors.tex.lastRepeated": "the last one p + 1 times",
  "knotVectors.tex.legs": "terms:",
  "knotVectors.whatYouSee":
    "The same control points carry three B-splines of one degree. Clamped (open) knots repeat the end values p + 1 times, so that curve starts at P₀ and ends at Pₙ; equally spaced unclamped knots give a curve that starts and ends inside the polygon; the closed curve repeats the first p points after the last, so it loops with the full continuity C^(p−1) at the seam (on the spans where it uses the same points as the unclamped curve the two coincide: dots over dashes). Chord-length and centripetal spacing move the interior knots in proportion to the legs of the polygon — syllabus section 3, after the Greek and Croatian notes.",
  "knotVectors.try1":
    "Set the degree to 1: every curve becomes the polygon (the closed one with its closing leg); raise it to 5 and watch the unclamped and closed curves shrink inside the polygon.",
  "knotVectors.try2":
    "Choose chord length and drag P₂ far away: the interior knots in the table grow with the legs next to it.",
  "knotVectors.try3":
    "Drag P₀: the clamped curve's start follows it exactly, the unclamped curve's start moves only by a sixth of the drag (for a cubic).",

  // Demo: local-control (strings of www/demos/local-control.js; keys start with the demo's `strings` prefix)
  "localControl.title": "Local control and the strong convex hull",
  "localControl.summary":
    "Moving one control point of a B-spline changes only p + 1 spans; each span stays inside the hull of its p + 1 active points.",
  "localControl.control.u": "Parameter u",
  "localControl.control.u.input": "u value (decimal or fraction such as 5/2)",
  "localControl.control.point": "Light the range of Pᵢ, i =",
  "localControl.control.point.input": "index i of the point whose range is shown",
  "localControl.control.degree": "Degree p",
  "localControl.control.degree.input": "degree p (1 to 5)",
  "localControl.error.tooFewPoints":
    "field “points”: degree {p} needs at least {min} control points, got {count}",
  "localControl.maxPoints": "this demo allows at most {max} control points",
  "localControl.pointLabel": "C(u)",
  "localControl.formula.only": "only this part moves with",
  "localControl.formula.vertices.one": "hull vertex",
  "localControl.formula.vertices.other": "hull vertices",
  "localControl.readout.span": "Span k = {k}: {names}",
  "localControl.readout.hull.one":
    "Only these p + 1 points have Nᵢ,ₚ(u) ≠ 0 here; their hull (shaded, {count} vertex) holds this whole piece of the curve.",
  "localControl.readout.hull.other":
    "Only these p + 1 points have Nᵢ,ₚ(u) ≠ 0 here; their hull (shaded, {count} vertices) holds this whole piece of the curve.",
  "localControl.readout.support":
    "Moving {name} changes C(u) only for u in [{lo}, {hi}; the rest of the curve stays put.",
  "localControl.aria":
    "clamped {kind} B-spline with {count} control points; {name} moves only the part for u in [{lo}, {hi}; u = {u} lies in span {k}, active points {names}, hull with {hull}; point C(u) = ({x}, {y})",
  "localControl.vertices.one": "{count} vertex",
  "localControl.vertices.other": "{count} vertices",
  "localControl.tableCaption":
    "Every basis function at u = {u} (degree {p}): only the highlighted p + 1 rows are non-zero",
  "localControl.table.point": "point",
  "localControl.table.value": "Nᵢ,{p}(u)",
  "localControl.table.support": "non-zero for u in",
  "localControl.whatYouSee":
    "A clamped cubic B-spline (blue), its control polygon (grey, dashed) and, under the figure, its knots as ticks on the parameter line. The coloured band marks the part of the curve that the ringed point P_i can move: the parameters [u_i, u_{i+p+1}) where its basis function N_i,p is not zero; outside it the curve does not move at all (local control, syllabus section 3; the Croatian notes: moving one point changes at most p + 1 segments). The grey filled region is the convex hull of the p + 1 active points of the span that holds u: that whole piece of the curve lies inside it (strong convex hull), a much tighter region than the hull of the whole polygon (outlined).",
  "localControl.try1":
    "Drag P₄ and watch the ends of the curve: for u in [0, 1] and [5, 6] nothing moves, exactly where the band stops.",
  "localControl.try2":
    "Type 5/2 for u: the span is k = 5, the active points are P₂ … P₅ with weights 1/48, 23/48, 23/48, 1/48, and C(u) sits inside their shaded hull.",
  "localControl.try3":
    "Set the degree to 1 and then 5: the band and the active hull grow with p (p + 1 spans, p + 1 points), and at degree 1 the curve is the polygon itself.",

  // Demo: knot-insertion (strings of www/demos/knot-insertion.js; keys start with the demo's `strings` prefix)
  "knotInsertion.title": "Knot insertion (Boehm) and Bézier extraction",
  "knotInsertion.summary":
    "Insert a knot and the curve keeps its shape while the control polygon gains a point and moves closer; insert enough and the curve falls apart into Bézier segments.",
  "knotInsertion.control.u": "Knot to insert, u",
  "knotInsertion.control.u.input": "u value (decimal or fraction such as 3/2)",
  "knotInsertion.control.insert": "Insert",
  "knotInsertion.control.insert.title": "Insert the knot u once (or click the curve)",
  "knotInsertion.control.refine": "Halve every span",
  "knotInsertion.control.refine.title": "Insert the midpoint of every non-empty span",
  "knotInsertion.control.reset": "Back to the original",
  "knotInsertion.control.reset.title":
    "Remove every inserted knot (the original points stay as they are)",
  "knotInsertion.control.bezier": "Extract Bézier segments",
  "knotInsertion.error.tooFewPoints":
    "field “points”: degree {p} needs at least {min} control points, got {count}",
  "knotInsertion.error.knotOrder":
    "field “knots” must not decrease (knot {i} is smaller than the one before)",
  "knotInsertion.error.emptyDomain": "field “knots”: the domain [u_p, u_n+1] is empty",
  "knotInsertion.error.insertedRange": "field “inserted”: {value} is outside the domain [{a}, {b}]",
  "knotInsertion.outside": "u = {value} is outside the domain [{a}, {b}]",
  "knotInsertion.refused": "that knot cannot be inserted: {message}",
  "knotInsertion.maxInserted":
    "this demo inserts at most {max} knots; press “Back to the original” to start again",
  "knotInsertion.hoverLabel": "insert u = {u}",
  "knotInsertion.formula.preview": "Insert would use:",
  "knotInsertion.readout": "{count} control points, {knots} knots",
  "knotInsertion.segments.one": "{count} Bézier segment (one per non-empty span)",
  "knotInsertion.segments.other": "{count} Bézier segments (one per non-empty span)",
  "knotInsertion.segmentsOff": "Tick the box to draw each Bézier segment’s polygon.",
  "knotInsertion.knotsNow": "Knots: {knots}",
  "knotInsertion.knotsNone": "No knot inserted yet: click the curve or press Insert.",
  "knotInsertion.knotsBefore": "Knots before inserting {s}: {knots}",
  "knotInsertion.knotsAfter": "Knots after: {knots}",
  "knotInsertion.alphasPreview": "Inserting {s} would use {alphas}",
  "knotInsertion.alphasUsed": "α used: {alphas}",
  "knotInsertion.insertedList": "Inserted knots ({count}), in order: {knots}",
  "knotInsertion.insertedNone": "Inserted knots: none",
  "knotInsertion.tableCaption":
    "The new control points after inserting {s}: the highlighted ones are new, the others are copied",
  "knotInsertion.tableEmpty": "The new control points appear here after an insertion.",
  "knotInsertion.aria":
    "{kind} B-spline with {count} control points and {knots} knots after inserting u = {s} with α = {alphas}; the curve is unchanged{segments}",
  "knotInsertion.ariaNone":
    "{kind} B-spline with {count} control points and {knots} knots; inserting u = {s} would use α = {alphas}{segments}",
  "knotInsertion.ariaSegments.one": "; {count} Bézier segment shown",
  "knotInsertion.ariaSegments.other": "; {count} Bézier segments shown",
  "knotInsertion.whatYouSee":
    "The quadratic B-spline of the Croatian notes' example (p = 2, knots 0 0 0 1 2 3 4 4 4; syllabus section 3), after inserting the knot 1.5. Inserting a knot s with Boehm's rule keeps the first points, replaces p of them by points Qᵢ on the legs of the old polygon (in the ratio αᵢ), and shifts the rest: the curve (blue) does not change at all, but the new polygon (dark, new points in vermillion) has one point more and lies closer to it; the old polygon stays ghosted. Inserting every interior knot until it has multiplicity p gives the curve's Bézier segments, one per non-empty span.",
  "knotInsertion.try1":
    "The picture opens after inserting u = 1.5: the knots became 0, 0, 0, 1, 1.5, 2, 3, 4, 4, 4 and α₂ = 3/4, α₃ = 1/4 cut the legs P₁P₂ and P₂P₃. Press “Back to the original”, then Insert with u = 1.5 to see it happen.",
  "knotInsertion.try2":
    "Click the curve in several places, or press “Halve every span” three times: the polygon closes in on the curve.",
  "knotInsertion.try3":
    "Tick “Extract Bézier segments”: 5 segments, one per non-empty span ([0,1], [1,1.5], [1.5,2], [2,3], [3,4]); insert 1.5 again and nothing is added, since that span is already there.",

  // Demo: multiplicity (strings of www/demos/multiplicity.js; keys start with the demo's `strings` prefix)
  "multiplicity.title": "Multiplicity and continuity",
  "multiplicity.summary":
    "Merge knots of a cubic B-spline and watch the continuity drop C², C¹, C⁰ (a corner at a control point), then a break; repeat a control point and the curve is pulled into it.",
  "multiplicity.aria":
    "Cubic B-spline with {count} control points and knots [{knots}]; at the interior knots (multiplicity: guaranteed, measured): {list}{through}{repeat}",
  "multiplicity.ariaThrough": "; the curve passes through {point} at u = {u}",
  "multiplicity.ariaRepeat": "; control point repeated: {points}, measured {measured}",
  "multiplicity.knotLegend": "Knot multiplicity",
  "multiplicity.knotReadout":
    "{names} = {u} · r = {r} · guaranteed {guaranteed} · measured {measured}",
  "multiplicity.noKnot": "No interior knot",
  "multiplicity.knotHint":
    "Select a knot on the ruler (click it, or Tab past the last control point) to study it; double-click it or press Enter to merge the next knot onto it.",
  "multiplicity.through":
    "At r = 3 the curve runs through a control point: C({u}) = {point}, with a corner.",
  "multiplicity.throughLabel": "C({u}) = {point}",
  "multiplicity.pointLabel": "C({u})",
  "multiplicity.jointLabel": "u = {u}",
  "multiplicity.raise": "Raise r (Enter)",
  "multiplicity.raise.title": "Merge the next knot onto the studied knot",
  "multiplicity.lower": "Lower r (Delete)",
  "multiplicity.lower.title": "Move the top copy of the studied knot half way to the next knot",
  "multiplicity.resetKnots": "Clamped uniform knots",
  "multiplicity.resetKnots.title":
    "Replace the knots by 4 equal end knots and equally spaced interior knots",
  "multiplicity.multiplicity.max": "the knot already has the largest multiplicity, p + 1 = {max}",
  "multiplicity.multiplicity.ends": "no interior knot is left to merge onto this one",
  "multiplicity.multiplicity.single": "this is a simple knot: nothing to split",
  "multiplicity.repeatLegend": "Control-point multiplicity",
  "multiplicity.repeatOption": "×{k}",
  "multiplicity.repeatNone":
    "{point} appears once. Select a control point and pick ×2 or ×3 to repeat it.",
  "multiplicity.repeatReadout": "{points}: at u{k} = {u} measured {measured}",
  "multiplicity.repeatEnd": "{points}: too close to an end of the curve for an interior knot",
  "multiplicity.repeatHint":
    "Repeating a point adds control points, so the knots become clamped uniform again.",
  "multiplicity.notesCaption":
    "The Croatian notes' table for cubics (the current cases highlighted)",
  "multiplicity.notesBreak": "break (separate pieces)",
  "multiplicity.colMultiplicity": "Multiplicity",
  "multiplicity.colPoints": "Control points",
  "multiplicity.colKnots": "Knots",
  "multiplicity.knotsCaption":
    "Every interior knot: guaranteed C^(p − r) from the knot vector, and what the core measures at the joint of the Bézier pieces",
  "multiplicity.colKnot": "Knot",
  "multiplicity.colR": "r",
  "multiplicity.colGuaranteed": "Guaranteed",
  "multiplicity.colMeasured": "Measured",
  "multiplicity.colPoint": "C(u)",
  "multiplicity.colThrough": "Through",
  "multiplicity.pointBreak": "left piece ends {left}, right starts {right}",
  "multiplicity.formulaRule": "at a knot of multiplicity",
  "multiplicity.formulaBreak": "break",
  "multiplicity.formulaMeasured": "measured:",
  "multiplicity.whatYouSee":
    "A cubic B-spline (blue) over eight control points and, under it, its knot ruler: 0 0 0 0 1 2 3 4 5 5 5 5. Merging knots raises the multiplicity r of a knot and the continuity there falls to C^(3 − r): at r = 2 the curve is C¹, at r = 3 only C⁰ — it runs through a control point and makes a corner — and at r = 4 it breaks into two separate Bézier pieces. Repeating a control point instead keeps the parametric C², but a triple point stops the curve (zero velocity) and gives a corner, G⁰. The table is the one of the Croatian notes (section 3 of the syllabus); “measured” is what the core finds by comparing the derivatives of the Bézier pieces at each joint. For a double point the notes write G¹; the measurement gives G², because the curvature stays continuous (it drops to zero at the two knots beside the point).",
  "multiplicity.try1":
    "Click u₅ (the knot at 2) on the ruler and press Enter three times: the readout goes C¹, C⁰ — the curve now passes through P₄ with a corner — and then “break”.",
  "multiplicity.try2":
    "Select P₄ and pick ×3: the curve is pulled into the point and turns there with a corner, measured C² G⁰; with ×2 it only comes closer.",
  "multiplicity.try3":
    "Drag a knot on the ruler onto its neighbour: the continuity written above it drops as soon as the two meet.",

  // Demo: matrix-form (strings of www/demos/matrix-form.js; keys start with the demo's `strings` prefix)
  "matrixForm.title": "Matrix form of uniform segments",
  "matrixForm.summary":
    "Each segment of a uniform B-spline is [tᵖ … t 1] · M · (its p + 1 points), with the same matrix M for every interior segment.",
  "matrixForm.aria":
    "{kind} B-spline, {knots}, {count} control points; segment {i} at t = {t}: point ({x}, {y}); {periodic}",
  "matrixForm.aria.periodic": "its matrix is the periodic one",
  "matrixForm.aria.notPeriodic": "its matrix differs from the periodic one",
  "matrixForm.degree.2": "quadratic (p = 2)",
  "matrixForm.degree.3": "cubic (p = 3)",
  "matrixForm.knots.uniform": "uniform knots (unclamped)",
  "matrixForm.knots.clamped": "clamped knots",
  "matrixForm.control.degree": "Degree",
  "matrixForm.control.knots": "Knot vector",
  "matrixForm.control.segment": "Segment i (or click the curve)",
  "matrixForm.control.segment.input": "segment number i",
  "matrixForm.control.t": "Local parameter t",
  "matrixForm.segmentRange": "the segment must be a whole number from 1 to {max}, got “{value}”",
  "matrixForm.periodic.yes": "Segment {i}: periodic matrix",
  "matrixForm.periodic.no": "Segment {i}: its own matrix",
  "matrixForm.degree": "Degree p = {p}, {count} control points, {segments}; knots {knots}",
  "matrixForm.segments.one": "{count} segment",
  "matrixForm.segments.other": "{count} segments",
  "matrixForm.maxPoints": "this demo allows at most {max} control points",
  "matrixForm.minPoints": "degree {p} needs at least {min} control points here",
  "matrixForm.error.degree":
    "field “degree” is {p}, but {count} control points allow at most degree {count} − 1",
  "matrixForm.matrixCaption":
    "M of segment {i} (span k = {k}), from segmentMatrix(k): row = power of t, column = the point it multiplies",
  "matrixForm.resultCaption":
    "The point at t, twice: the product of the numbers above, and the core's evaluate(u)",
  "matrixForm.result.product": "[tᵖ … 1] · M · points",
  "matrixForm.result.evaluate": "evaluate(u)",
  "matrixForm.pointLabel": "C{i}(t)",
  "matrixForm.tex.periodic": "(periodic segment: uniformSegmentMatrix(p))",
  "matrixForm.tex.notPeriodic": "uniformSegmentMatrix(p): an end segment of clamped knots",
  "matrixForm.tex.evaluate": "core:",
  "matrixForm.whatYouSee":
    "On one span a B-spline is a polynomial in the local parameter t, so each segment can be written as a row of powers of t, times a matrix M, times the p + 1 points that act there — the Croatian notes' matrix form (syllabus section 3). With uniform knots every segment has the same M (the notes call them periodic segments): [[1/2, −1, 1/2], [−1, 1, 0], [1/2, 1/2, 0]] for quadratics, 1/6·[[−1, 3, −3, 1], [3, −6, 3, 0], [−3, 0, 3, 0], [1, 4, 1, 0]] for cubics. With clamped knots the end segments get matrices of their own.",
  "matrixForm.try1":
    "Move the segment slider: the highlighted stretch and its coloured points move along, but M stays the same.",
  "matrixForm.try2":
    "Switch to clamped knots and pick segment 1: M changes (the curve must start at P₀); with 6 points and p = 2 segments 2 and 3 keep the periodic matrix, as in the notes' example.",
  "matrixForm.try3":
    "Drag one of the ringed points and compare the two rows of the result table: the matrix product and evaluate(u) agree to every decimal.",

  // Demo: weights (strings of www/demos/weights.js; keys start with the demo's `strings` prefix)
  "weights.title": "Weights of a rational curve",
  "weights.summary":
    "Raise a weight and the curve is pulled toward its control point; the homogeneous picture shows why: a polynomial curve in (wx, wy, w) projected onto w = 1.",
  "weights.whatYouSee":
    "A rational cubic Bézier curve (blue) and the same control points with every weight 1 (dotted): the ring around each point grows with its weight wᵢ, and raising wᵢ pulls the curve toward Pᵢ. The inset shows the homogeneous picture of the Greek notes (section 4 of the syllabus): the points (wᵢxᵢ, wᵢyᵢ, wᵢ) span an ordinary polynomial Bézier curve in space (green), and the rays from the origin project it onto the plane w = 1, where it is the rational curve. Multiplying every weight by the same number moves the green curve along the rays but not its projection: only the ratios of the weights matter.",
  "weights.try1":
    "Drag the w₁ slider (or the ring around P₁) from 0.1 to 10 and watch P(1/2) slide toward P₁; the table's last column shows the distance shrinking.",
  "weights.try2":
    "Press “All weights × 2”: the green curve in the inset moves, the blue curve does not.",
  "weights.try3":
    "Press “All weights 1”: the rational curve falls onto the dotted polynomial curve.",
  "weights.handleLabel": "P{i} (w{i} = {w})",
  "weights.countMismatch":
    "field “weights” must have one weight per point: {count} weights for {points} points",
  "weights.notPositive": "field “weights”: {name} = {value} is refused; weights must be > 0",
  "weights.outOfRange": "field “weights”: {name} must be between {min} and {max}, got {value}",
  "weights.weightsLegend": "Weights (log scale)",
  "weights.weightLabel": "Weight {name} of {point}",
  "weights.weightInput": "Weight {name} (a number between 0.1 and 10)",
  "weights.badWeight":
    "weight {name} = “{value}” refused: a weight must be > 0 (here between {min} and {max})",
  "weights.allOne": "All weights 1",
  "weights.allOne.title": "Set every weight to 1: the polynomial Bézier curve",
  "weights.scaleAll": "All weights × {factor}",
  "weights.scaleAll.title": "Multiply every weight by the same number: the curve does not change",
  "weights.cannotScale": "the weights cannot all be doubled or halved within {min} … {max}",
  "weights.scaled":
    "Every weight {factor}: the blue curve stays where it was (only ratios matter); the homogeneous curve in the inset moved along the rays.",
  "weights.showHomogeneous": "Show the homogeneous space (inset)",
  "weights.maxPoints": "this demo allows at most {max} control points",
  "weights.minPoints": "this demo needs at least {min} control points",
  "weights.degree": "Degree n = {n} ({count} control points)",
  "weights.pointLabel": "P({t})",
  "weights.ghostPointLabel": "t = {t}, all wᵢ = 1",
  "weights.legendRational": "rational curve",
  "weights.legendPolynomial": "all weights 1",
  "weights.insetTitle": "Homogeneous space (wx, wy, w)",
  "weights.axisX": "wx",
  "weights.axisY": "wy",
  "weights.axisW": "w",
  "weights.origin": "O",
  "weights.plane": "w = 1",
  "weights.readout": "P({t}) = ({x}, {y}); largest distance from the polynomial curve: {gap}",
  "weights.tableCaption":
    "Control points, weights, homogeneous points (wᵢxᵢ, wᵢyᵢ, wᵢ), the share Bᵢ(t)wᵢ / Σ Bⱼ(t)wⱼ of each point at t = {t}, and the distance |P(t) − Pᵢ|",
  "weights.column.point": "Pᵢ",
  "weights.column.weight": "wᵢ",
  "weights.column.homogeneous": "Pᵢʷ = (wᵢxᵢ, wᵢyᵢ, wᵢ)",
  "weights.column.share": "share at t",
  "weights.column.distance": "|P(t) − Pᵢ|",
  "weights.tex.ratios": "only ratios matter: ",
  "weights.tex.same": " gives the same curve",
  "weights.aria":
    "Rational {kind} Bézier curve with weights ({weights}) and, dotted, the polynomial curve with all weights 1; at t = {t} the point P(t) = ({x}, {y}) (all weights 1: ({gx}, {gy})), {distance} from the heaviest point {heaviest}; inset: the homogeneous control points, their polynomial curve in (wx, wy, w) and rays from the origin projecting it onto the plane w = 1",

  // Demo: conics (strings of www/demos/conics.js; keys start with the demo's `strings` prefix)
  "conics.title": "Conic sections",
  "conics.summary":
    "A rational quadratic Bézier curve is a conic: an ellipse arc for w₁ < 1, a parabola at w₁ = 1, a hyperbola above; with an isosceles triangle and w₁ = sin θ, a circular arc.",
  "conics.whatYouSee":
    "A rational quadratic Bézier curve (blue) with weights 1, w₁, 1 and, dotted, the parabola it is at w₁ = 1. The core names the conic from the shape factor k = w₁²/(w₀w₂): below 1 an ellipse arc, equal to 1 a parabola, above 1 a hyperbola; the shoulder point P(1/2) slides along the line from the chord's midpoint M to P₁. When the triangle is isosceles and w₁ = sin θ, θ half the angle at P₁, the arc is exactly circular: the whole circle appears, dashed, with its centre. This is the conics part of the Greek notes (section 4 of the syllabus).",
  "conics.try1":
    "Type 0.5, 1 and 2 into the w₁ box: the name changes from ellipse to parabola to hyperbola, and the table row follows.",
  "conics.try2":
    "Press “Make circular”: w₁ becomes sin θ and the dashed circle appears; then drag P₂ and watch “circle!” go away.",
  "conics.try3":
    "Drag w₁ up to 5: the shoulder point runs toward P₁ and the hyperbola hugs the control triangle.",
  "conics.w1": "Middle weight w₁ (log scale)",
  "conics.w1.input": "Weight w₁ (a number between 0.05 and 5)",
  "conics.badWeight":
    "weight w₁ = “{value}” refused: w₁ must be > 0 (here between {min} and {max})",
  "conics.makeCircular": "Make circular",
  "conics.makeCircular.title":
    "Make the triangle isosceles (P₂ slides along P₁P₂) and set w₁ = sin θ, the weight of a circular arc",
  "conics.circleLegend": "Circular arc",
  "conics.notCircular": "no circular arc for this triangle: {message}",
  "conics.tooFlat": "the circular arc needs w₁ = {w}, below this demo's smallest weight {min}",
  "conics.madeCircular": "w₁ = sin θ = {w}: a circular arc.",
  "conics.kind.ellipse": "ellipse",
  "conics.kind.parabola": "parabola",
  "conics.kind.hyperbola": "hyperbola",
  "conics.article.ellipse": "an ellipse",
  "conics.article.parabola": "a parabola",
  "conics.article.hyperbola": "a hyperbola",
  "conics.rule.ellipse": "k = w₁²/(w₀w₂) < 1",
  "conics.rule.parabola": "k = 1 (w₁ = 1: the polynomial Bézier curve)",
  "conics.rule.hyperbola": "k > 1",
  "conics.column.kind": "conic",
  "conics.column.rule": "rule (w₀ = w₂ = 1)",
  "conics.tableCaption": "Which conic: the shape factor k decides (the current one is highlighted)",
  "conics.figureCircle": "{kind}: circle!",
  "conics.readoutCircle": "{kind}: circle!",
  "conics.centre": "O",
  "conics.midpoint": "M",
  "conics.shoulder": "P(1/2)",
  "conics.legendParabola": "w₁ = 1 (parabola)",
  "conics.formula.circularArc": "circular arc",
  "conics.formula.and": "and",
  "conics.formula.circle": "circle!",
  "conics.shape": "w₁ = {w}; shape factor k = w₁²/(w₀w₂) = {k} {relation} 1",
  "conics.triangle":
    "|P₀P₁| = {a}, |P₁P₂| = {b} (not isosceles); angle at P₁ = {angle}°, sin θ = {sin}",
  "conics.triangleIsosceles":
    "|P₀P₁| = |P₁P₂| = {a} (isosceles); angle at P₁ = {angle}°, sin θ = {sin}",
  "conics.triangleDegenerate": "Two points coincide: no angle at P₁.",
  "conics.circleYes":
    "circle! radius {r}; every sample's distance from the centre O differs from it by at most {error}.",
  "conics.circleNo":
    "Not circular yet: the arc needs w₁ = sin θ = {sin} (largest distance from that circle now: {error}).",
  "conics.circleNeedsIsosceles":
    "Not circular: a circular arc needs |P₀P₁| = |P₁P₂| (press “Make circular”).",
  "conics.aria":
    "Rational quadratic Bézier curve with P₀ = {p0}, P₁ = {p1}, P₂ = {p2} and weights 1, {w}, 1: an arc of {kind} (shape factor {k}){circle}; shoulder point P(1/2) = ({sx}, {sy}); dotted: the parabola with w₁ = 1",
  "conics.ariaCircle": ", a circular arc of radius {r} about ({x}, {y})",

  // Demo: nurbs-circle (strings of www/demos/nurbs-circle.js; keys start with the demo's `strings` prefix)
  "nurbsCircle.title": "NURBS circles and arcs",
  "nurbsCircle.summary":
    "An exact circle as a degree-2 NURBS: 9 control points, weights 1 and √2/2, knots 0,0,0,¼,¼,½,½,¾,¾,1,1,1; arcs in pieces of at most 90°, ellipses as their affine images.",
  "nurbsCircle.whatYouSee":
    "A circle (or an arc, or an ellipse) built by the core as a NURBS of degree 2 (blue), its control polygon with each point's weight, and the joints of its pieces (green rings). The full circle is the syllabus' 9-point NURBS (section 4, from the Greek and Italian notes): the corners of the square carry weight √2/2, the knots are 0,0,0,¼,¼,½,½,¾,¾,1,1,1. An arc is cut into pieces of at most 90° whose middle weights are cos(Δ/2). The readout measures how far 2000 samples are from the exact circle: 0 or a few 10⁻¹⁶, rounding only — no polynomial curve can do that.",
  "nurbsCircle.try1":
    "Set the sweep to 200°: the arc has 3 pieces of 66.7° and middle weights cos 33.3° ≈ 0.835; the radius error still reads about 1e-16.",
  "nurbsCircle.try2":
    "Tick “Ellipse” and turn the rotation: the same weights and knots, the control points stretched — an affine image of the circle.",
  "nurbsCircle.try3": "Drag the centre c: the whole circle moves and stays exact.",
  "nurbsCircle.notPositive": "field “{field}” must be > 0, got {value}",
  "nurbsCircle.zeroSweep": "field “sweep” must not be 0 (an arc needs a non-zero sweep)",
  "nurbsCircle.radius": "Radius r",
  "nurbsCircle.radius.input": "Radius (a number > 0, up to 10)",
  "nurbsCircle.rx": "Semi-axis rx",
  "nurbsCircle.rx.input": "Semi-axis rx (a number > 0, up to 10)",
  "nurbsCircle.ry": "Semi-axis ry",
  "nurbsCircle.ry.input": "Semi-axis ry (a number > 0, up to 10)",
  "nurbsCircle.rotation": "Rotation (degrees)",
  "nurbsCircle.rotation.input": "Rotation of the ellipse in degrees",
  "nurbsCircle.start": "Start angle (degrees)",
  "nurbsCircle.start.input": "Start angle in degrees",
  "nurbsCircle.sweep": "Sweep (degrees, negative: clockwise)",
  "nurbsCircle.sweep.input": "Sweep in degrees, −360 to 360, not 0",
  "nurbsCircle.badLength":
    "{field} = “{value}” refused: {field} must be > 0 (here between {min} and {max})",
  "nurbsCircle.badAngle": "{field} = “{value}” refused: an angle between −{max}° and {max}°",
  "nurbsCircle.ellipseMode": "Ellipse (semi-axes and rotation)",
  "nurbsCircle.circleLegend": "Circle",
  "nurbsCircle.ellipseLegend": "Ellipse",
  "nurbsCircle.arcLegend": "Arc",
  "nurbsCircle.resultLegend": "The NURBS",
  "nurbsCircle.full": "Full turn",
  "nurbsCircle.full.title": "Start 0°, sweep 360°: the closed 9-point curve",
  "nurbsCircle.refused": "refused by the library: {message}",
  "nurbsCircle.centreLabel": "c",
  "nurbsCircle.radiusLabel": "r = {r}",
  "nurbsCircle.axesLabel": "rx = {rx}, ry = {ry}",
  "nurbsCircle.errorCircle": "radius error {error}",
  "nurbsCircle.errorEllipse": "ellipse error {error}",
  "nurbsCircle.errorCircleNote":
    "max | |C(u) − c| − r | over {samples} samples (rounding only: the curve is exact)",
  "nurbsCircle.errorEllipseNote":
    "max | (x′/rx)² + (y′/ry)² − 1 | over {samples} samples, x′, y′ along the axes",
  "nurbsCircle.count": "{count} control points, {pieces} pieces (≤ 90° each)",
  "nurbsCircle.knots": "Knots: {knots}",
  "nurbsCircle.ariaCircle": "circle of radius {r}",
  "nurbsCircle.ariaEllipse": "ellipse with semi-axes {rx} and {ry} turned {rotation}°",
  "nurbsCircle.ariaFull": "the whole curve",
  "nurbsCircle.ariaArc": "an arc from {start}° sweeping {sweep}°",
  "nurbsCircle.aria":
    "NURBS {shape} about ({x}, {y}), {arc}: degree 2, {count} control points with weights {weights}, knots {knots}, {pieces} pieces; measured error {error}",
  "nurbsCircle.tableCaption": "The {count} control points and their weights",
  "nurbsCircle.column.point": "Pᵢ",
  "nurbsCircle.column.weight": "wᵢ",
  "nurbsCircle.formula.circle": "circle",
  "nurbsCircle.formula.here": "here",
  "nurbsCircle.formula.pieces.one": "piece of",
  "nurbsCircle.formula.pieces.other": "pieces of",
  "nurbsCircle.formula.middleWeights": "middle weights",
  "nurbsCircle.formula.samples": "samples",

  // Demo: projective (strings of www/demos/projective.js; keys start with the demo's `strings` prefix)
  "projective.title": "Projective invariance",
  "projective.summary":
    "Map a rational curve by a perspective: mapping its control points and weights gives exactly the mapped curve; mapping the points and keeping the old weights does not.",
  "projective.whatYouSee":
    "On the left a cubic Bézier curve in the square S₀S₁S₂S₃; on the right its image under the perspective map H that sends the square to the quadrilateral Q₀Q₁Q₂Q₃ (drag the corners). The core maps the curve's homogeneous control points (wᵢPᵢ, wᵢ) by H, which gives new points and new weights (solid blue); the orange dots are the original curve's samples mapped one by one by the same H, and they sit exactly on it — rational curves are invariant under projective maps, as the Greek notes say (section 4 of the syllabus). The dashed curve uses the mapped points with the old weights: it misses, because a perspective changes the weights.",
  "projective.try1":
    "Drag Q₂ toward Q₃: the perspective grows stronger, the mapped weights spread apart, and the dashed curve drifts further from the dots, which stay on the solid curve.",
  "projective.try2":
    "Press “Make it affine”: the quadrilateral becomes a parallelogram, every mapped weight is the old one, and the dashed curve joins the others.",
  "projective.try3":
    "Drag Q₂ across the diagonal Q₁Q₃: the map would put a control point beyond the line at infinity (a weight ≤ 0); the library refuses and the last good picture stays.",
  "projective.notPositive": "field “weights”: {name} = {value} is refused; weights must be > 0",
  "projective.weightRange": "field “weights”: {name} must be between {min} and {max}, got {value}",
  "projective.degenerate":
    "field “corners”: the four corners do not define a perspective map (three of them on a line?)",
  "projective.weightsLegend": "Original weights (log scale)",
  "projective.weightLabel": "Weight {name} of {point}",
  "projective.weightInput": "Weight {name} (a number between 0.1 and 10)",
  "projective.badWeight":
    "weight {name} = “{value}” refused: a weight must be > 0 (here between {min} and {max})",
  "projective.affine": "Make it affine",
  "projective.affine.title":
    "Move Q₂ so the quadrilateral is a parallelogram: an affine map, weights unchanged",
  "projective.resultLegend": "Invariance check",
  "projective.refused": "the library refused this map: {message}",
  "projective.mappedLabel": "w′{i} = {w}",
  "projective.naiveLabel": "not invariant: weights ignored",
  "projective.legendMapped": "curve.projectiveMap(H)",
  "projective.legendPointwise": "H applied to each sample",
  "projective.legendNaive": "mapped points, old weights",
  "projective.gaps": "Solid vs dots: largest gap {ab} (the same curve). Dashed vs solid: {ac}.",
  "projective.mappedWeights": "Mapped weights w′ᵢ: {weights}",
  "projective.affineMap": "an affine map",
  "projective.perspectiveMap": "a perspective map",
  "projective.tex.affine": "(affine map: ",
  "projective.tex.unchanged": ", weights unchanged)",
  "projective.tex.invariant": "(invariant)",
  "projective.tex.ignored": "(weights ignored)",
  "projective.aria":
    "A cubic Bézier curve in the square [0, 4]² and its image under {kind} sending the square's corners to {corners}: the mapped curve has weights {weights}; the original samples mapped one by one lie on it (largest gap {ab}); the mapped points with the old weights give a different curve (up to {ac} away)",

  // Demo: negative-weights (strings of www/demos/negative-weights.js; keys start with the demo's `strings` prefix)
  "negativeWeights.title": "Why non-positive weights are rejected",
  "negativeWeights.summary":
    "Drag a weight through zero: the library refuses, and the demo shows what the curve would do — leave its convex hull and run off to infinity where the denominator w(t) vanishes.",
  "negativeWeights.whatYouSee":
    "A rational quadratic Bézier curve with weights 1, w₁, 1 over its control triangle (the convex hull, shaded). While w₁ > 0 the library builds the curve (blue) and it stays in the triangle. At w₁ ≤ 0 the library refuses, and its message is shown word for word; the dashed curve is what the formula would give: the homogeneous curve (wx, wy, w) is still an ordinary polynomial curve, and dividing by w projects it back. Below, the denominator w(t) = Σ Bᵢ(t)wᵢ: where it crosses zero the point runs off to infinity (a pole), and any negative weight already pushes the curve out of its convex hull. This is the warning of the Greek notes (section 4 of the syllabus): negative weights break the convex hull property and can create poles.",
  "negativeWeights.try1":
    "Press “w₁ = −0.5”: the library refuses, the curve turns inside out below the chord P₀P₂ and leaves the triangle, but w(t) stays above 0 — no pole yet.",
  "negativeWeights.try2":
    "Drag w₁ slowly from 0 down to −3: at w₁ = −1 the plot touches zero at t = 1/2, below it crosses twice and the curve splits at two poles.",
  "negativeWeights.try3":
    "Press “w₁ = 1”: the message goes away and the ordinary parabola comes back.",
  "negativeWeights.w1": "Middle weight w₁ (may go ≤ 0 here)",
  "negativeWeights.w1.input": "Weight w₁ (a number between −3 and 3)",
  "negativeWeights.badWeight":
    "weight w₁ = “{value}” refused: this demo takes w₁ between {min} and {max}",
  "negativeWeights.preset": "w₁ = {w}",
  "negativeWeights.libraryLegend": "What the library says",
  "negativeWeights.resultLegend": "What the formula would give",
  "negativeWeights.refused": "the library refuses weights 1, w₁, 1: {message}",
  "negativeWeights.accepted": "The library accepts these weights.",
  "negativeWeights.libraryRefuses": "new BezierCurve(points, 2, weights) throws: “{message}”",
  "negativeWeights.libraryAccepts":
    "new BezierCurve(points, 2, weights) accepts these weights: every wᵢ > 0.",
  "negativeWeights.poles.one": "1 pole, at t ≈ {list}",
  "negativeWeights.poles.other": "{count} poles, at t ≈ {list}",
  "negativeWeights.noPoles": "no pole: w(t) > 0 on [0, 1]",
  "negativeWeights.outside": "The curve leaves its convex hull (the control triangle).",
  "negativeWeights.inside": "The curve stays in its convex hull (the control triangle).",
  "negativeWeights.poleLabel": "pole t ≈ {t}",
  "negativeWeights.infinity": "∞",
  "negativeWeights.middleLabel": "P(1/2)",
  "negativeWeights.figureAccepted": "weights > 0: the library's curve",
  "negativeWeights.figureRefused": "refused by the library (dashed: the formula)",
  "negativeWeights.tickHalf": "1/2",
  "negativeWeights.axisT": "t",
  "negativeWeights.plotTitle": "denominator w(t) = Σ Bᵢ(t) wᵢ",
  "negativeWeights.tex.poles": "(poles)",
  "negativeWeights.tex.noPole": "(no pole; ",
  "negativeWeights.tex.needs": " needs ",
  "negativeWeights.tex.coefficients": "the coefficients ",
  "negativeWeights.tex.sumToOne": " sum to 1: ",
  "negativeWeights.tex.staysInHull": " stays in the convex hull; ",
  "negativeWeights.tex.breaks": " breaks that",
  "negativeWeights.aria":
    "Rational quadratic Bézier curve with P₀ = {p0}, P₁ = {p1}, P₂ = {p2} and weights 1, {w}, 1: {verdict}; {poles}; {hull}; below, the plot of the denominator w(t)",
  "negativeWeights.ariaRefused":
    "the library refuses it ({message}), the dashed curve is the formula's projection of the homogeneous curve",
  "negativeWeights.ariaAccepted": "the library accepts it",
  "negativeWeights.ariaPoles":
    "w(t) reaches zero at t ≈ {list} ({count} in all): poles, where the curve runs off to infinity",
  "negativeWeights.ariaNoPoles": "w(t) stays positive (smallest value {min})",
  "negativeWeights.ariaOutside": "the curve leaves its convex hull",
  "negativeWeights.ariaInside": "the curve stays in its convex hull",
  ...LAGRANGE,
  ...BEZIER_PATCH,
  ...NURBS_SURFACE,
  ...SURFACE_INTERPOLATION,
  ...SURFACE_REVOLUTION,
  ...PATCH_DE_CASTELJAU,
  ...PATCH_SUBDIVISION,
  ...HERMITE,
  ...CARDINAL,
  ...CUBIC_SPLINE,
  ...PARAMETRIZATION,
  ...BSPLINE_INTERPOLATION,
  ...INTERPOLATE_APPROXIMATE,
  ...CORE_ERRORS,
  ...PIECEWISE,
  ...SKETCH,
  // Section 1: parametric-curve.
  ...PARAMETRIC_CURVE,
};

const locales = { en: EN };
let active = EN;
let activeCode = "en";
/** `Intl` objects of the active language, made when first needed (then reused). */
let pluralRules = null;
const numberFormats = new Map();
let decimalSign = null;

/**
 * The English table (every key the UI uses; a copy). For tools and tests, e.g. the check that
 * every translation has the same keys and placeholders (tests/i18n/check.mjs).
 */
export function englishTable() {
  return { ...EN };
}

/** Adds (or extends, also while it is active) the string table of a language. */
export function addLocale(code, table) {
  Object.assign((locales[code] ??= {}), table);
}

/**
 * Makes `code` (a BCP 47 tag such as "el" or "hr") the active language for `t`, `tp` and
 * `formatNumber`; keys it lacks fall back to English. A code without a table is English.
 */
export function setLocale(code) {
  activeCode = code in locales ? code : "en";
  active = locales[activeCode];
  pluralRules = null;
  numberFormats.clear();
  decimalSign = null;
}

/** The active language's code ("en" unless `setLocale` chose another). */
export function locale() {
  return activeCode;
}

/**
 * The decimal separators of our languages, as `Intl.NumberFormat` writes them (a test holds
 * the two together): written here because `Intl`'s first use loads the locale's data, ~17 ms
 * on a fast machine (67 ms at Lighthouse's 4× slowdown) inside the page's first task.
 */
export const DECIMAL_SIGNS = { en: ".", el: ",", hr: ",", it: "," };

/**
 * The active language's decimal separator: "." in English, "," in Greek, Croatian and Italian
 * (format.js writes every shown number with it); another language's from `Intl.NumberFormat`.
 */
export function decimalSeparator() {
  decimalSign ??=
    DECIMAL_SIGNS[activeCode] ??
    new Intl.NumberFormat(activeCode).formatToParts(1.5).find((p) => p.type === "decimal")?.value ??
    ".";
  return decimalSign;
}

/** The string for `key` with `{name}` placeholders replaced from `params`. */
export function t(key, params) {
  const template = active[key] ?? EN[key] ?? key;
  if (!params) return template;
  return template.replace(/\{(\w+)\}/g, (whole, name) =>
    name in params ? String(params[name]) : whole,
  );
}

/**
 * The plural form of `key` for `count`: `<key>.one`, `<key>.other` (or `.zero`, `.two`, `.few`,
 * `.many` where the language has them), chosen by `Intl.PluralRules` of the active language, with
 * `{count}` and the other `params` filled in. Falls back to `<key>.other`, then to `key`:
 *
 *   "flattening.segments.one": "{count} segment",  "flattening.segments.other": "{count} segments"
 *   tp("flattening.segments", 1)  // "1 segment";  tp("flattening.segments", 12) // "12 segments"
 *
 * `{count}` shows `params.count` when given (a formatted number), else `count` as it is.
 */
export function tp(key, count, params) {
  pluralRules ??= new Intl.PluralRules(activeCode);
  const all = { count, ...params };
  const exact = `${key}.${pluralRules.select(count)}`;
  if (has(exact)) return t(exact, all);
  return t(has(`${key}.other`) ? `${key}.other` : key, all);
}

/**
 * `value` written in the active language (`Intl.NumberFormat`, e.g. "1.81", "1,81" in Greek);
 * `options` as for `Intl.NumberFormat` (default: up to 3 decimals, no grouping, no "−0"). The formats are
 * cached per options object, so pass a constant.
 */
export function formatNumber(value, options = NUMBER_OPTIONS) {
  let format = numberFormats.get(options);
  if (!format) {
    format = new Intl.NumberFormat(activeCode, options);
    numberFormats.set(options, format);
  }
  return format.format(value);
}

/** Default `formatNumber` options: coordinates and parameters (ui.md: 3 decimals). */
const NUMBER_OPTIONS = Object.freeze({
  maximumFractionDigits: 3,
  useGrouping: false,
  signDisplay: "negative",
});

/** True when a key exists (used for optional demo texts such as a third "Try this"). */
export function has(key) {
  return key in active || key in EN;
}
