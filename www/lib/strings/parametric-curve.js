/** The English strings of www/demos/parametric-curve.js (keys start with its `strings` prefix "parametricCurve"). */
export const PARAMETRIC_CURVE = {
  "parametricCurve.title": "Parametric curves from formulas",
  "parametricCurve.summary":
    "Type x(t), y(t) (and z(t)) and watch a point run along P(t) with its velocity, acceleration, curvature and osculating circle, the hodograph beside it.",
  "parametricCurve.aria":
    "Parametric curve x(t) = {x}, y(t) = {y} for t from {a} to {b}; t = {t}; P(t) = ({px}, {py}); speed {speed}; curvature κ = {kappa}; the hodograph is drawn beside it",
  "parametricCurve.aria3d":
    "Space curve x(t) = {x}, y(t) = {y}, z(t) = {z} for t from {a} to {b}; t = {t}; P(t) = ({px}, {py}, {pz}); speed {speed}; curvature κ = {kappa}; torsion τ = {tau}; the Frenet frame T, N, B is drawn at P(t)",
  "parametricCurve.ariaUndefined":
    "Parametric curve x(t) = {x}, y(t) = {y} for t from {a} to {b}; at t = {t} the curve is undefined",
  "parametricCurve.whatYouSee":
    "A curve is a point that moves: P(t) = (x(t), y(t)) for t in [a, b] (syllabus section 1, the circle x = cos t, y = sin t on [0, 2π] of the notes). The vermillion arrow is the velocity P′(t), the purple one the acceleration P″(t); the orange circle is the osculating circle of radius 1/|κ|. On the right the hodograph collects every velocity P′(t), drawn from the point O. Every formula is parsed and differentiated by the curve library; a name other than t becomes a slider.",
  "parametricCurve.try1":
    "Press Play, then pick “Cycloid”: at every cusp the speed drops to 0 and the velocity arrow vanishes, while the hodograph passes through O.",
  "parametricCurve.try2":
    "Pick “Ellipse” and move the sliders a and b: the osculating circle is smallest at the ends of the long axis.",
  "parametricCurve.try3":
    "Pick “y = tan t”: the plot breaks at the poles t = ±π/2 instead of joining the branches.",
  "parametricCurve.try4":
    "Pick “The notes' polynomial” and tick “Show the Bézier form”: the control points are exact fractions such as −271/50.",
  "parametricCurve.try5":
    "Type sin(t) into z(t): the curve leaves the plane, and the Frenet frame T, N, B appears at P(t). Drag the figure to turn it.",
  "parametricCurve.control.curve": "Curve P(t)",
  "parametricCurve.control.x": "x(t) =",
  "parametricCurve.control.y": "y(t) =",
  "parametricCurve.control.z": "z(t) = (empty: a plane curve)",
  "parametricCurve.control.from": "t from",
  "parametricCurve.control.to": "to",
  "parametricCurve.control.help":
    "Formulas in t such as 2cos(t), t^2 - 1, e^(-t/5)sin(3t); π as pi. Any other letter (a, b, ω, a_1) is a parameter with a slider.",
  "parametricCurve.control.params": "Parameters",
  "parametricCurve.control.param.input": "value of the parameter {name}",
  "parametricCurve.control.t": "t",
  "parametricCurve.control.t.input": "parameter value t",
  "parametricCurve.control.examples": "Examples",
  "parametricCurve.preset.circle": "Circle",
  "parametricCurve.preset.ellipse": "Ellipse",
  "parametricCurve.preset.lissajous": "Lissajous",
  "parametricCurve.preset.cycloid": "Cycloid",
  "parametricCurve.preset.cardioid": "Cardioid",
  "parametricCurve.preset.astroid": "Astroid",
  "parametricCurve.preset.spiral": "Spiral",
  "parametricCurve.preset.helix": "Helix (3D)",
  "parametricCurve.preset.tan": "y = tan t",
  "parametricCurve.preset.polynomial": "The notes' polynomial",
  "parametricCurve.control.bezier": "Show the Bézier form (a polynomial curve)",
  "parametricCurve.bezierPoints": "Control points on [{a}, {b}], exact: {list}",
  "parametricCurve.bezierLink": "Open these control points in de Casteljau's algorithm",
  "parametricCurve.bezierLinkOff": "de Casteljau's demo takes plane curves of degree 1 to 10 only.",
  "parametricCurve.atT": "At t",
  "parametricCurve.speed": "Speed |P′(t)| = {speed}",
  "parametricCurve.curvature": "Curvature κ(t) = {kappa}",
  "parametricCurve.radius": "Osculating circle of radius {r}",
  "parametricCurve.torsion": "Torsion τ(t) = {tau}",
  "parametricCurve.undefined": "The curve is undefined at t = {t} (a pole or a gap)",
  "parametricCurve.cusp": "P′(t) = 0: no direction of motion, κ is undefined",
  "parametricCurve.straight": "Straight here (κ ≈ 0): no osculating circle",
  "parametricCurve.pointLabel": "P(t)",
  "parametricCurve.velocityLabel": "P′(t)",
  "parametricCurve.accelerationLabel": "P″(t)",
  "parametricCurve.originLabel": "O",
  "parametricCurve.tangentLabel": "T",
  "parametricCurve.normalLabel": "N",
  "parametricCurve.binormalLabel": "B",
  "parametricCurve.hodographCaption": "Hodograph P′(t), origin O",
  "parametricCurve.scaleCaption": "Arrows and hodograph at scale {scale}",
  "parametricCurve.frameCaption": "Frenet frame T, N, B at P(t); drag to turn, Shift+drag to pan",
  "parametricCurve.incomplete":
    "Drawn approximately: the curve wiggles faster than the plot could follow somewhere",
  "parametricCurve.formula.undefined": "undefined",
  "parametricCurve.formula.tooLong": "too long to show",
  "parametricCurve.error.text": "field “{field}”: a formula is text of at most {max} characters",
  "parametricCurve.error.params":
    'field “params”: parameter values are finite numbers by name, such as {"a": 2}',
};
