/** The English strings of www/demos/bspline-interpolation.js (keys start with the demo's `strings` prefix "bsplineInterpolation"). */
export const BSPLINE_INTERPOLATION = {
  "bsplineInterpolation.title": "B-spline interpolation",
  "bsplineInterpolation.summary":
    "A B-spline of any degree through given points, with optional end derivatives: the control points solve a square linear system, shown with its numbers.",
  "bsplineInterpolation.aria":
    "{kind} B-spline through {count} data points at {params} parameters, {ends}; the system has {size} unknowns (control points r); knots {knots}",
  "bsplineInterpolation.aria.start": "start derivative D₀ given",
  "bsplineInterpolation.aria.end": "end derivative given",
  "bsplineInterpolation.aria.noEnds": "no end derivatives",
  "bsplineInterpolation.degreeLegend": "Degree p",
  "bsplineInterpolation.degreeOption": "{p}",
  "bsplineInterpolation.minPoints":
    "degree {degree} needs at least {min} conditions (data points and end derivatives together)",
  "bsplineInterpolation.error.degree":
    "field “degree” is {p}, but {count} conditions (data points and end derivatives) carry at most degree {max}",
  "bsplineInterpolation.maxPoints": "this demo allows at most {max} data points",
  "bsplineInterpolation.paramsLegend": "Parameters tᵢ",
  "bsplineInterpolation.params.uniform": "uniform",
  "bsplineInterpolation.params.chord": "chord length",
  "bsplineInterpolation.params.centripetal": "centripetal",
  "bsplineInterpolation.paramsNote": "t = {list}",
  "bsplineInterpolation.derivativesLegend": "End derivatives (drag the arrow tips)",
  "bsplineInterpolation.control.start": "Start: C′(t₀) = D₀",
  "bsplineInterpolation.control.end": "End: C′(tₙ) = Dₙ",
  "bsplineInterpolation.startValue": "D₀ = {xy}",
  "bsplineInterpolation.endValue": "D{n} = {xy}",
  "bsplineInterpolation.noDerivatives": "no derivative conditions: one per data point only",
  "bsplineInterpolation.legendCurve": "C(u), through the data points pᵢ",
  "bsplineInterpolation.legendPolygon": "control polygon rⱼ (computed)",
  "bsplineInterpolation.legendDerivative": "end derivative D = C′(t), full length",
  "bsplineInterpolation.startLabel": "D₀",
  "bsplineInterpolation.endLabel": "Dₙ",
  "bsplineInterpolation.control.notesKnots": "The notes' knots 0 0 0 1 2 3 4 4 4",
  "bsplineInterpolation.knotsNotes": "Knots U = {list} (the notes' choice)",
  "bsplineInterpolation.knotsDefault": "Knots U = {list} (the core's default: averaged parameters)",
  "bsplineInterpolation.sizeNote": "{points} and the derivatives give {unknowns}",
  "bsplineInterpolation.dataPoints.one": "{count} data point",
  "bsplineInterpolation.dataPoints.other": "{count} data points",
  "bsplineInterpolation.controlPoints.one": "{count} control point",
  "bsplineInterpolation.controlPoints.other": "{count} control points",
  "bsplineInterpolation.notesExample": "Croatian example",
  "bsplineInterpolation.notesExample.title":
    "Back to the notes' worked example: its 5 points, t = 0 … 4, p = 2, the start derivative and the knots 0 0 0 1 2 3 4 4 4",
  "bsplineInterpolation.row.point": "C({t}) = p{i}",
  "bsplineInterpolation.row.start": "C′({t}) = D₀",
  "bsplineInterpolation.row.end": "C′({t}) = D{i}",
  "bsplineInterpolation.col.condition": "Condition",
  "bsplineInterpolation.col.unknown": "Unknown",
  "bsplineInterpolation.col.rhs": "Right-hand side",
  "bsplineInterpolation.col.solution": "Solution",
  "bsplineInterpolation.tableCaption":
    "The system A r = b from bsplineInterpolationSystem ({size} × {size}): row i is a condition, column j the weight of rⱼ in it (Nⱼ,ₚ(tᵢ) or N′ⱼ,ₚ(tᵢ))",
  "bsplineInterpolation.tableCaptionNotes":
    "The notes' {size} × {size} system A r = b (bsplineInterpolationSystem): row i is a condition, column j the weight of rⱼ in it (Nⱼ,ₚ(tᵢ) or N′ⱼ,ₚ(tᵢ))",
  "bsplineInterpolation.tableTooLarge":
    "The system has {size} unknowns; the table shows systems of up to {max}. Remove points or lower the degree to see it.",
  "bsplineInterpolation.whatYouSee":
    "The curve passes through the data points pᵢ (the round handles) at the parameters tᵢ; it is a B-spline whose control points rⱼ (the grey squares and dashed polygon) are not given but computed: each data point, and each end derivative Dᵢ (the arrows, full length, derivative with respect to t), is one linear equation in the rⱼ, and the table under the figure is that square system with its solution. The default is the Croatian notes' worked example (syllabus section 5): five points at t = 0 … 4, a quadratic, a start derivative and the knots 0 0 0 1 2 3 4 4 4, giving the 6 × 6 system with rows 1; −2 2; ½ ½ … .",
  "bsplineInterpolation.try1":
    "In the example, read the second row: −2 r₀ + 2 r₁ = D₀, so r₁ = p₀ + D₀/2 — the grey square r₁ sits halfway along the arrow. Drag the arrow's tip and watch r₁ follow it.",
  "bsplineInterpolation.try2":
    "Raise the degree step by step: the curve still passes through every point, but the rows get longer (each condition involves p + 1 control points) and the control polygon swings further out.",
  "bsplineInterpolation.try3":
    "Drag p₂ far to the right: with uniform parameters the curve swings far past p₂ and p₃. Switch to chord length: the tᵢ now grow with the legs and the swing shrinks — but D₀, a derivative with respect to t, is now far too fast for a parameter that counts length: shorten the arrow and the hook at p₀ goes away.",
};
