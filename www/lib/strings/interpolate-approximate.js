/** The English strings of www/demos/interpolate-approximate.js (keys start with the demo's `strings` prefix "interpolateApproximate"). */
export const INTERPOLATE_APPROXIMATE = {
  "interpolateApproximate.title": "Interpolate or approximate",
  "interpolateApproximate.summary":
    "The same points as control points (the curve is pulled towards them), as data met exactly, or as data fitted by fewer control points in the least-squares sense.",
  "interpolateApproximate.aria.control":
    "{kind} B-spline with the {count} points as its control points (clamped knots): it passes through the first and last only",
  "interpolateApproximate.aria.data":
    "{kind} B-spline fitted to {count} data points with {control} ({fit}); largest residual {max}",
  "interpolateApproximate.aria.interpolation": "interpolation",
  "interpolateApproximate.aria.leastSquares": "least squares, ends exact",
  "interpolateApproximate.roleLegend": "The points are",
  "interpolateApproximate.role.control": "control points (approximation)",
  "interpolateApproximate.role.data": "data points (interpolation or fit)",
  "interpolateApproximate.degreeLegend": "Degree p",
  "interpolateApproximate.degreeOption": "{p}",
  "interpolateApproximate.minPoints": "a degree-{degree} B-spline needs at least {min} points",
  "interpolateApproximate.maxPoints": "this demo allows at most {max} points",
  "interpolateApproximate.control.count": "Control points (all = interpolation)",
  "interpolateApproximate.control.count.input": "number of control points",
  "interpolateApproximate.countRange":
    "the number of control points must be a whole number from {min} (degree + 1) to {max} (the points), got “{value}”",
  "interpolateApproximate.controlPoints.one": "{count} control point",
  "interpolateApproximate.controlPoints.other": "{count} control points",
  "interpolateApproximate.note.control":
    "The points are the control polygon: the curve starts at P₀, ends at Pₙ and only approaches the others.",
  "interpolateApproximate.note.interpolation":
    "Interpolation: one control point per data point, the curve meets every pₖ (largest residual {max}).",
  "interpolateApproximate.note.leastSquares":
    "Least squares, ends exact: Σ |pₖ − C(tₖ)|² = {sum}; largest residual {max} (at p{k}).",
  "interpolateApproximate.legendCurve": "the B-spline C(u)",
  "interpolateApproximate.legendGiven": "control polygon: the points",
  "interpolateApproximate.legendFitted": "control polygon rⱼ (computed)",
  "interpolateApproximate.legendResidual": "residual pₖ − C(tₖ)",
  "interpolateApproximate.tex.control": "clamped uniform knots",
  "interpolateApproximate.whatYouSee":
    "The same points can play two parts. As control points they shape a B-spline that starts at the first, ends at the last and only approaches the rest — the approximation of the notes' interactive design. As data points (with chord-length parameters tₖ) they are met exactly by an interpolating B-spline with as many control points, or, with fewer control points, fitted in the least-squares sense with both ends exact: the short segments from each point to the curve are the residuals pₖ − C(tₖ), and the grey squares on the dashed polygon the computed control points. Syllabus section 5 (interpolation and approximation), after the Croatian and Greek notes.",
  "interpolateApproximate.try1":
    "Switch between control points and data points: as control points the curve cuts inside every peak and touches only P₀ and P₉; as data it runs close to every point, and with the count at 10 through every one of them.",
  "interpolateApproximate.try2":
    "As data, slide the number of control points from 10 down to 4: the curve relaxes, the residual segments grow and the sum of squares climbs from 0 to about 78 — not at every single step (each count gets knots of its own), but the first and last points always stay exact.",
  "interpolateApproximate.try3":
    "Set the count to 10 (interpolation) and drag p₄ down sharply: the whole curve ripples to pass through it. Lower the count to 5 and drag again: the fitted curve only leans towards the point, and its residual grows instead.",
};
