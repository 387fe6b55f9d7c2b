/** The English strings of www/demos/surface-revolution.js (keys start with the demo's `strings` prefix "surfaceRevolution"). */
export const SURFACE_REVOLUTION = {
  "surfaceRevolution.title": "Revolution, extrusion, ruled surfaces",
  "surfaceRevolution.summary":
    "Surfaces made from curves: an exact NURBS torus, a vase turned from an editable profile, a profile extruded along a vector, and the ruled surface between a quadratic and a cubic.",
  "surfaceRevolution.aria.torus":
    "A torus (R = {R}, r = {r}) swept by {angle}° from an exact NURBS circle: a rational biquadratic surface with a {rows} × {cols} control net",
  "surfaceRevolution.aria.vase":
    "A vase: a cubic B-spline profile of {count} points in the xz plane revolved by 360° about the z axis; {rows} × {cols} control net",
  "surfaceRevolution.aria.extrude":
    "The cubic B-spline profile of {count} points in the xy plane extruded along the vector d; {rows} × {cols} control net",
  "surfaceRevolution.aria.ruled":
    "The ruled surface between a quadratic curve A and a cubic curve B, with its straight rulings; {rows} × {cols} control net",
  "surfaceRevolution.control.mode": "Surface",
  "surfaceRevolution.mode.torus": "Torus (revolve a circle)",
  "surfaceRevolution.mode.vase": "Vase (revolve a profile)",
  "surfaceRevolution.mode.extrude": "Extrude the profile",
  "surfaceRevolution.mode.ruled": "Ruled surface between two curves",
  "surfaceRevolution.control.R": "Distance R of the circle from the axis",
  "surfaceRevolution.control.R.input": "R value",
  "surfaceRevolution.control.r": "Radius r of the circle",
  "surfaceRevolution.control.r.input": "r value",
  "surfaceRevolution.control.angle": "Angle of revolution (°)",
  "surfaceRevolution.control.angle.input": "angle in degrees, up to 360",
  "surfaceRevolution.control.show": "Show",
  "surfaceRevolution.minPoints": "the profile needs at least {min} control points",
  "surfaceRevolution.maxPoints": "the profile takes at most {max} control points here",
  "surfaceRevolution.control.net": "Control net of the surface",
  "surfaceRevolution.control.iso": "Iso-curves",
  "surfaceRevolution.control.wireframe": "Wireframe",
  "surfaceRevolution.check.torus":
    "Net {rows} × {cols}. Largest distance from the torus over the core's sample grid: {distance} — exact up to rounding.",
  "surfaceRevolution.check.vase":
    "Net {rows} × {cols}. Each drag frame makes the surface again with sl.revolve ({revolve} ms) and meshes it ({mesh} ms).",
  "surfaceRevolution.check.extrude": "Net {rows} × {cols}. S(u, 1) − S(u, 0) = {d} = d at every u.",
  "surfaceRevolution.check.ruled":
    "Net {rows} × {cols}. S(u, ½) = {mid}, the midpoint of A(u) and B(u).",
  "surfaceRevolution.tex.circle":
    "C(v) = (R + r\\cos\\varphi,\\ 0,\\ r\\sin\\varphi),\\ R = {R},\\ r = {r}\\text{: the exact NURBS circle (9 points)}",
  "surfaceRevolution.tex.revolve":
    "S(u, v) = \\mathrm{Rot}_z(u\\,\\theta)\\, C(v),\\ \\theta = {angle}^\\circ\\text{: net } {rows} \\times {cols}\\text{, degree } 2 \\times 2\\text{ (A8.1)}",
  "surfaceRevolution.tex.weights": "\\text{arc weights } w_{i0} = {weights}",
  "surfaceRevolution.tex.rational":
    "S(u, v) = \\frac{\\sum_i \\sum_j N_{i,2}(u)\\, N_{j,{q}}(v)\\, w_{ij} P_{ij}}{\\sum_i \\sum_j N_{i,2}(u)\\, N_{j,{q}}(v)\\, w_{ij}},\\quad w_{ij} = w_i\\, w_j",
  "surfaceRevolution.tex.torusCheck":
    "\\max_{{n} \\times {n}\\text{ grid}} \\Bigl|\\sqrt{\\bigl(\\sqrt{x^2+y^2} - {R}\\bigr)^2 + z^2} - {r}\\Bigr| = {distance}\\text{: exact}",
  "surfaceRevolution.tex.profile":
    "C(v) = \\sum_{j=0}^{{n}} N_{j,3}(v)\\,(x_j,\\ 0,\\ z_j)\\text{: clamped cubic}",
  "surfaceRevolution.tex.revolveVase":
    "S(u, v) = \\bigl(x(v)\\cos 2\\pi u,\\ x(v)\\sin 2\\pi u,\\ z(v)\\bigr)\\text{: net } {rows} \\times {cols}\\text{ (A8.1)}",
  "surfaceRevolution.tex.vaseNet":
    "P_{ij} = P_j\\text{ turned by } i \\cdot 45^\\circ\\text{, odd } i\\text{ moved out by } \\sqrt2\\ (1/\\cos 45^\\circ)",
  "surfaceRevolution.tex.extrude":
    "S(u, v) = C(u) + v\\,\\mathbf d,\\quad v \\in [0, 1],\\quad \\mathbf d = {d}",
  "surfaceRevolution.tex.extrudeNet":
    "P_{i0} = P_i,\\ P_{i1} = P_i + \\mathbf d\\text{: net } {rows} \\times {cols}\\text{, degree 3 in } u\\text{, 1 in } v\\text{ (§10.3)}",
  "surfaceRevolution.tex.extrudeCheck": "S({u}, 1) - S({u}, 0) = {d}",
  "surfaceRevolution.tex.ruled":
    "S(u, v) = (1 - v)\\,A(u) + v\\,B(u),\\quad A\\text{ quadratic},\\ B\\text{ cubic}",
  "surfaceRevolution.tex.ruledNet":
    "\\text{compatible first: } A_i' = \\tfrac{i}{3} A_{i-1} + \\bigl(1 - \\tfrac{i}{3}\\bigr) A_i\\text{ (degree 2} \\to 3\\text{), net } {rows} \\times {cols}\\text{ (§10.3)}",
  "surfaceRevolution.tex.ruledCheck": "A({u}) = {a},\\ B({u}) = {b},\\ S({u}, \\tfrac12) = {mid}",
  "surfaceRevolution.whatYouSee":
    "Surfaces the core makes from curves, each with its control net (grey, dashed) and iso-curves. Revolution turns a profile curve about the z axis: every control point Pⱼ becomes a circle of 9 control points (four exact quadratic arcs, weights 1, √2/2, 1, …), so a circle profile gives a torus exactly and the vase is exact in every direction around. Extrusion sweeps the profile along a vector d: two columns, Pᵢ and Pᵢ + d. The ruled surface joins a quadratic A and a cubic B by straight segments (the rulings): the core first raises A to degree 3 so both have the same degree and knots.",
  "surfaceRevolution.try1":
    "Torus: drag the angle down to 90° and watch the net go from 9 rows to 3 (one arc); at 180°, 5.",
  "surfaceRevolution.try2":
    "Torus: the check line stays near 10⁻¹⁶ for any R, r and angle — a rational surface is exact, a polynomial one could only approximate the circle.",
  "surfaceRevolution.try3":
    "Vase: drag a profile point; it moves in the xz plane only, and the whole surface turns with it. Move P₀ off the axis to open the bottom.",
  "surfaceRevolution.try4":
    "Extrude: drag the tip d of the arrow to slant the wall; every ruling of the extrusion is a copy of d.",
  "surfaceRevolution.try5":
    "Ruled: compare the four orange dots (the first column of the net) with A's three points — the core raised A to a cubic with four points that draw the same curve, so A and B can share one net.",
};
