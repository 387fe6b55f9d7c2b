/** The English strings of www/demos/lagrange.js (keys start with the demo's `strings` prefix "lagrange"). */
export const LAGRANGE = {
  "lagrange.title": "Lagrange interpolation and Aitken's triangle",
  "lagrange.summary":
    "One polynomial through all the points against a cubic spline; Aitken's triangle builds P(t) and leaves the convex hull; the wiggle grows with the number of points.",
  "lagrange.aria":
    "Lagrange polynomial of degree {n} through {count} data points at {params} parameters, and the natural cubic spline through the same points; t = {t}; P(t) = ({x}, {y}); the spline at t: ({sx}, {sy})",
  "lagrange.error.t": "field “t”: {t} is outside the parameter domain [{a}, {b}] of these points",
  "lagrange.control.t": "Parameter t",
  "lagrange.control.t.input": "t value (decimal or fraction such as 3/2)",
  "lagrange.control.stepBack.title": "t − 1/16 of the domain",
  "lagrange.control.step.title": "t + 1/16 of the domain",
  "lagrange.control.params": "Parameters tᵢ of the data points",
  "lagrange.params.uniform": "uniform: tᵢ = i",
  "lagrange.params.chord": "chord length: sums of |pᵢ₊₁ − pᵢ|",
  "lagrange.params.centripetal": "centripetal: sums of √|pᵢ₊₁ − pᵢ|",
  "lagrange.paramsName.uniform": "uniform",
  "lagrange.paramsName.chord": "chord-length",
  "lagrange.paramsName.centripetal": "centripetal",
  "lagrange.control.runge": "Runge's example",
  "lagrange.control.count": "Points equally spaced on Runge's bell",
  "lagrange.control.count.input": "number of points ({min} to {max})",
  "lagrange.countRange":
    "the number of points must be a whole number from {min} to {max}, got “{value}”",
  "lagrange.degree.one": "{count} point: degree n = {n}",
  "lagrange.degree.other": "{count} points: a polynomial of degree n = {n}",
  "lagrange.minPoints": "Lagrange interpolation here needs at least {min} points",
  "lagrange.maxPoints": "this demo allows at most {max} points",
  "lagrange.legendPolynomial": "Lagrange polynomial P(t)",
  "lagrange.legendSpline": "natural cubic spline S(t)",
  "lagrange.pointLabel": "P(t)",
  "lagrange.axisT": "t",
  "lagrange.marker": "t = {t}",
  "lagrange.sumNote": "Σ Lᵢ(t) = {sum}; every Lᵢ(t) ≥ 0 here",
  "lagrange.sumNegative":
    "Σ Lᵢ(t) = {sum}, but L{i}(t) = {value} < 0: P(t) is no convex combination of the points",
  "lagrange.colFunction": "Basis function",
  "lagrange.colParam": "tᵢ",
  "lagrange.colValue": "Lᵢ(t)",
  "lagrange.colPoint": "Data point pᵢ",
  "lagrange.sumRow": "Sum",
  "lagrange.basisCaption": "The Lagrange basis at t = {t}: the weight of each data point in P(t)",
  "lagrange.triangleCaption": "Aitken's triangle at t = {t}: row r holds the points of level r",
  "lagrange.tableLevel": "r = {r}",
  "lagrange.whatYouSee":
    "The blue curve is the one polynomial P(t) of degree n through all n + 1 data points; the green curve is the natural cubic spline through the same points at the same parameters. The coloured levels are Aitken's triangle at t: each new point divides the line of its leg in the ratio of the parameters, like de Casteljau's, but falls outside the leg (dotted) when t is outside the leg's parameter range, and the basis functions Lᵢ(t) under the figure sum to 1 but go negative. From the interpolation half of the Greek notes, section 5 of the syllabus.",
  "lagrange.try1":
    "Slide “Points equally spaced on Runge's bell” from 5 to 11: the polynomial swings wider and wider near the ends while the spline stays on the bell.",
  "lagrange.try2":
    "Press Play and watch P(t) and its triangle: between the data parameters the points of a level stay near their legs, near the ends they shoot past them.",
  "lagrange.try3":
    "Drag p₂ upwards: the whole polynomial moves, even far from p₂, while the spline moves mostly near p₂. Then choose chord-length parameters and compare.",
};
