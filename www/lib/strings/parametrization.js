/** The English strings of www/demos/parametrization.js (keys start with the demo's `strings` prefix "parametrization"). */
export const PARAMETRIZATION = {
  "parametrization.title": "Parametrisation: uniform, chord length, centripetal",
  "parametrization.summary":
    "The same points interpolated at uniform, chord-length and centripetal parameters, with each curve's speed and parameter ticks: uneven spacing makes the uniform curve overshoot.",
  "parametrization.aria":
    "{method} through {count} data points at uniform, chord-length, centripetal and α = {alpha} parameters; at s = {s}: uniform {uniform}, chord {chord}, centripetal {centripetal}; their speeds are plotted below",
  "parametrization.control.s": "Normalised parameter s",
  "parametrization.control.s.input": "s value from 0 to 1 (decimal or fraction)",
  "parametrization.control.alphaGroup": "A fourth curve: tᵢ₊₁ = tᵢ + |pᵢ₊₁ − pᵢ|^α",
  "parametrization.control.alpha": "Exponent α",
  "parametrization.control.alpha.input": "α from 0 to 1",
  "parametrization.control.alphaCurve": "Show the α curve (orange, dash-dot)",
  "parametrization.alphaIs.uniform": "α = {alpha}: the uniform parameters (on the blue curve)",
  "parametrization.alphaIs.chord": "α = {alpha}: the chord-length parameters (on the green curve)",
  "parametrization.alphaIs.centripetal":
    "α = {alpha}: the centripetal parameters (on the purple curve)",
  "parametrization.alphaBetween": "α = {alpha}: 0 is uniform, 0.5 centripetal, 1 chord length",
  "parametrization.control.method": "Interpolating curve",
  "parametrization.method.cubic": "C² natural cubic spline",
  "parametrization.method.catmull-rom": "Catmull–Rom spline (C¹)",
  "parametrization.methodName.cubic": "natural cubic splines",
  "parametrization.methodName.catmull-rom": "Catmull–Rom splines",
  "parametrization.minPoints": "an interpolating spline here needs at least {min} points",
  "parametrization.maxPoints": "this demo allows at most {max} points",
  "parametrization.legend.uniform": "uniform (α = 0)",
  "parametrization.legend.chord": "chord (α = 1)",
  "parametrization.legend.centripetal": "centripetal (α = ½)",
  "parametrization.legend.alpha": "α of the slider",
  "parametrization.marker": "s = {s}",
  "parametrization.axisSpeed": "speed |dC/ds|",
  "parametrization.axisS": "s = (t − t₀)/(tₙ − t₀)",
  "parametrization.tex.uniform": "uniform",
  "parametrization.tex.chord": "chord",
  "parametrization.tex.centripetal": "centripetal",
  "parametrization.tableCaption":
    "The legs of the data polygon and the parameters tᵢ of each parametrisation",
  "parametrization.colKind": "i",
  "parametrization.rowLegs": "|pᵢ₊₁ − pᵢ|",
  "parametrization.row.uniform": "uniform tᵢ",
  "parametrization.row.chord": "chord length tᵢ",
  "parametrization.row.centripetal": "centripetal tᵢ",
  "parametrization.row.alpha": "α = {alpha}: tᵢ",
  "parametrization.whatYouSee":
    "Four interpolating curves through the same points, differing only in the parameters tᵢ given to the points: uniform (blue, solid), chord length (green, dashed), centripetal (purple, dotted) and any α from the slider (orange, dash-dot). Under the figure, each curve's speed against the normalised parameter s, and a row of ticks per curve where its data parameters fall. Uniform parameters give a long leg as little parameter as a short one, so the curve rushes along the long leg and overshoots or loops at the short ones. From the Greek notes' interpolation half, section 5 of the syllabus.",
  "parametrization.try1":
    "Press Play: the four dots start and end together, but the blue (uniform) one rushes along the long legs while the green (chord) one keeps a nearly even pace — compare their speed graphs.",
  "parametrization.try2":
    "Slide α from 0 to 1: the orange curve passes through the blue one (α = 0), the purple one (α = 0.5) and the green one (α = 1), and its ticks move with it.",
  "parametrization.try3":
    "Drag p₃ close to p₂ so that one leg is very short: the uniform curve makes a loop there, the centripetal one does not. Then switch to Catmull–Rom and do the same.",
};
