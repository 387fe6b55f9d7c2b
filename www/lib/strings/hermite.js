/** The English strings of www/demos/hermite.js (keys start with the demo's `strings` prefix "hermite"). */
export const HERMITE = {
  "hermite.title": "Cubic Hermite interpolation",
  "hermite.summary":
    "A cubic piece between two data points from the points and their tangents; pieces that share tangents join C¹, an unlocked tangent only G¹.",
  "hermite.aria":
    "Piecewise cubic Hermite curve through {count} data points; t = {t}; P(t) = ({x}, {y}); joints: {joints}",
  "hermite.whatYouSee":
    "The blue curve passes through the data points P₀ … Pₙ at t = 0, 1, 2, …; at each point an orange arrow shows its tangent m (drawn at half its length; drag its tip). Between Pᵢ and Pᵢ₊₁ the curve is H₀·Pᵢ + H₁·Pᵢ₊₁ + H₂·Δmᵢ + H₃·Δmᵢ₊₁, with the four Hermite basis functions plotted below (syllabus section 5, after the Greek notes' interpolation chapter and the Croatian notes). Sharing one tangent per point makes the curve C¹; the core's continuity check names every joint.",
  "hermite.try1":
    "Press Play and watch the marker run along H₀ … H₃ below: at u = 1/2 the table reads H₀ = H₁ = 1/2 and H₂ = −H₃ = 1/8.",
  "hermite.try2":
    "Drag the tip of the tangent arrow at P₁: only the two pieces meeting at P₁ change, and the joint stays C¹.",
  "hermite.try3":
    "Tick “Unlock the tangent”, then drag the purple incoming arrow or move λ: the join becomes “G¹ only” — same direction, different speed.",
  "hermite.minPoints": "Hermite interpolation needs at least {min} data points",
  "hermite.maxPoints": "this demo allows at most {max} data points",
  "hermite.count": "{count} data points, {pieces} cubic pieces",
  "hermite.local": "Piece {i}: u = {u} (Δ = {delta})",
  "hermite.control.tangent": "Tangent m{i} of the selected point (x y)",
  "hermite.badTangent": "a tangent is two numbers such as “3 -1/2”, got “{value}”",
  "hermite.control.bezier": "Show the Bézier form of the current piece",
  "hermite.control.joinLegend": "Joins",
  "hermite.control.unlocked": "Unlock the tangent at an interior point (G¹)",
  "hermite.control.joint": "Unlocked point k",
  "hermite.control.joint.input": "index k of the unlocked point",
  "hermite.control.ratio": "λ = |m⁻| / |m⁺|",
  "hermite.control.ratio.input": "length ratio λ of the incoming to the outgoing tangent",
  "hermite.joints": "Core's check at the joints: {list}",
  "hermite.noJoints": "One piece: no joint to check",
  "hermite.g1Only": "G¹ only",
  "hermite.c0Only": "C⁰ only",
  "hermite.marker": "u = {u}",
  "hermite.formula.checker": "core's check:",
  "hermite.col.function": "Function",
  "hermite.col.polynomial": "Polynomial",
  "hermite.col.value": "Value at u",
  "hermite.col.times": "Multiplies",
  "hermite.tableCaption": "The Hermite basis at u = {u} (piece {i})",
};
