/** The English strings of www/demos/sketch.js (keys start with the demo's `strings` prefix "sketch") and its exercise. */
export const SKETCH = {
  "sketch.title": "Sketch a curve",
  "sketch.summary":
    "Draw a stroke: the fewest Bézier pieces (or B-spline control points) that stay within the tolerance, corners kept; then edit by dragging points or drawing over a part.",
  "sketch.aria": "Sketched curve: {fit}",
  "sketch.figureHelp":
    "Draw on the figure with the mouse, a pen or a finger; a stroke that starts on the curve redraws that part. Drag a point, or press Tab to select one and the arrow keys to move it (Shift: 10 px). Shift-drag pans; wheel or pinch zooms.",
  "sketch.outputLegend": "The curve is",
  "sketch.output.G1": "Bézier pieces, G¹ joints",
  "sketch.output.C1": "Bézier pieces, C¹ joints",
  "sketch.output.bspline": "a B-spline of degree p",
  "sketch.control.degree": "Degree p",
  "sketch.control.degree.input": "degree of the B-spline",
  "sketch.control.tolerance": "Tolerance (screen px)",
  "sketch.control.tolerance.input": "tolerance in screen pixels",
  "sketch.showLegend": "Show",
  "sketch.control.corners": "corners (and the turn there)",
  "sketch.control.breaks": "split points (joints)",
  "sketch.control.errors": "each piece's largest error and its sample",
  "sketch.control.polygon": "control polygons and points (drag them)",
  "sketch.control.comb": "curvature comb",
  "sketch.control.oversketch": "A stroke that starts on the curve redraws that part",
  "sketch.oversketchBezier":
    "Oversketching edits Bézier pieces: with a B-spline every stroke is a new drawing.",
  "sketch.control.presets": "Sample strokes",
  "sketch.preset.wave": "Wave",
  "sketch.preset.corners": "Zigzag with corners",
  "sketch.preset.blob": "Closed blob",
  "sketch.preset.spiral": "Spiral",
  "sketch.preset.letter": "Letter S",
  "sketch.pieces.one": "{count} piece",
  "sketch.pieces.other": "{count} pieces",
  "sketch.corners.one": "{count} corner",
  "sketch.corners.other": "{count} corners",
  "sketch.controlPoints.one": "{count} control point",
  "sketch.controlPoints.other": "{count} control points",
  "sketch.fitPieces":
    "{pieces}, {corners}; largest error {error} (tolerance {tolerance} px); {shape}.",
  "sketch.fitBSpline":
    "B-spline of degree {p} with {control}; largest error {error} (tolerance {tolerance} px); {shape}.",
  "sketch.px": "{value} px",
  "sketch.notMeasured": "not measured",
  "sketch.open": "open",
  "sketch.closed": "closed",
  "sketch.edited": "Edited since the fit: the marks and errors are the fit's, before the edits.",
  "sketch.handle": "piece {piece}, {name}",
  "sketch.badStroke": "the stroke is not a valid stroke code (2 to 4000 points)",
  "sketch.badEdits": "the list of edits is not valid",
  "sketch.whatYouSee":
    "The light wide line is what you drew; the blue curve is the core's fit: cubic Bézier pieces, as few as keep every sample of the stroke within the tolerance ε (measured, not estimated), or one B-spline of degree p with as few control points as possible. Where the stroke turns sharply the fit keeps a corner (a G⁰ joint, the square mark with its turning angle); every other joint is smooth, G¹ or C¹. The green dots are the split points, the dashed lines each piece's control polygon, and the comb shows the curvature κ along the curve. Syllabus section 7 (interactive design): “a curve more or less like this”, edited without starting over.",
  "sketch.try1":
    "Draw a quick zigzag, then slide the tolerance from 1 px to 10 px: the pieces merge, but the corners stay.",
  "sketch.try2":
    "Draw a loop that ends where it began: the curve closes, smooth at the seam. Turn on the curvature comb: where does κ jump?",
  "sketch.try3":
    "Start a short stroke on the curve and end it on the curve further on: only that part is redrawn. Then drag a control point and press Ctrl+Z.",
  "exercise.sketch-pieces.title": "A shape in few pieces",
  "exercise.sketch-pieces.task":
    "Draw a closed shape with at least one corner (a drop, a leaf, a house) that the fit at 3 px tolerance makes with at most 6 Bézier pieces.",
  "exercise.sketch-pieces.hint":
    "Return to where you started so the curve closes; draw calmly (a wobbly stroke needs more pieces), give it one sharp turn, and keep the tolerance at 3 px or above.",
  "exercise.sketch-pieces.notYet": "Not yet: {detail}.",
  "exercise.sketch-pieces.detail": "{pieces}, {corners}, {shape}",
};
