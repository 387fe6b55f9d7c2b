/** The English strings of www/demos/nurbs-surface.js (keys start with the demo's `strings` prefix "nurbsSurface"). */
export const NURBS_SURFACE = {
  "nurbsSurface.title": "B-spline and NURBS surfaces",
  "nurbsSurface.summary":
    "A tensor-product B-spline surface with a degree and knots per direction: knot insertion adds a whole row or column of control points, weights pull the surface, seams coloured by their measured continuity.",
  "nurbsSurface.aria":
    "B-spline surface with a {rows} × {cols} control net, degrees {p} in u and {q} in v; probe at u = {u}, v = {v}: S = ({x}, {y}, {z}); {seams}",
  "nurbsSurface.control.u": "Probe u",
  "nurbsSurface.control.u.input": "u value (decimal or fraction such as 1/3)",
  "nurbsSurface.control.v": "Probe v",
  "nurbsSurface.control.v.input": "v value (decimal or fraction such as 1/3)",
  "nurbsSurface.control.directionU": "Direction u (rows of the net)",
  "nurbsSurface.control.directionV": "Direction v (columns of the net)",
  "nurbsSurface.degree1": "1",
  "nurbsSurface.degree2": "2",
  "nurbsSurface.degree3": "3",
  "nurbsSurface.degree4": "4",
  "nurbsSurface.control.knotsU": "Knots U",
  "nurbsSurface.control.knotsV": "Knots V",
  "nurbsSurface.knotsHelp":
    "{count} knots for {n} control points of degree {p}; type a vector and press Enter",
  "nurbsSurface.control.insertU": "Insert u at the probe (adds a row)",
  "nurbsSurface.control.insertV": "Insert v at the probe (adds a column)",
  "nurbsSurface.control.clamped": "Clamped uniform",
  "nurbsSurface.control.uniform": "Uniform (unclamped)",
  "nurbsSurface.control.weights": "Weight of the selected point (select a handle)",
  "nurbsSurface.control.weight": "Weight of {name}",
  "nurbsSurface.control.weight.input": "weight of the selected control point",
  "nurbsSurface.control.show": "Show",
  "nurbsSurface.control.net": "Control net",
  "nurbsSurface.control.iso": "Iso-curves",
  "nurbsSurface.control.seams": "Seams by continuity",
  "nurbsSurface.control.normal": "Normal at the probe",
  "nurbsSurface.control.shading": "Shading",
  "nurbsSurface.shading.lit": "Lit",
  "nurbsSurface.shading.zebra": "Zebra stripes",
  "nurbsSurface.shading.gaussian": "Gaussian curvature K",
  "nurbsSurface.shading.mean": "Mean curvature H",
  "nurbsSurface.badWeight": "weight “{value}” must be a number in [{min}, {max}]",
  "nurbsSurface.badSelected":
    "field “selected”: point {i} does not exist in a net of {count} points",
  "nurbsSurface.weightCount": "field “weights”: {count} weights for {points} control points",
  "nurbsSurface.netFull": "this demo stops at {max} rows or columns",
  "nurbsSurface.degreeTooHigh":
    "degree {p} in {dir} needs at least {p} + 1 control points in that direction, the net has {count}",
  "nurbsSurface.insertedU":
    "Knot u = {at} inserted: Boehm's rule on every column, the net is now {rows} × {cols}",
  "nurbsSurface.insertedV":
    "Knot v = {at} inserted: Boehm's rule on every row, the net is now {rows} × {cols}",
  "nurbsSurface.noSeams": "No interior knots: one polynomial (or rational) patch, no seams",
  "nurbsSurface.seamsReadout": "Seams measured by the core: {u} · {v}",
  "nurbsSurface.legend": "Seams",
  "nurbsSurface.legendFreshRows": "new rows",
  "nurbsSurface.legendFreshColumns": "new columns",
  "nurbsSurface.normalLabel": "n",
  "nurbsSurface.texNet":
    "\\text{net } {rows} \\times {cols} = {count} \\text{ points},\\ \\text{degrees } p = {p},\\ q = {q}\\text{: a seam at a knot of multiplicity } r \\text{ is } C^{p-r}",
  "nurbsSurface.texInsertedU":
    "\\text{after } \\texttt{insertKnotU}\\text{: rows } {first}\\text{–}{last} \\text{ are new (Boehm on every column), one row more}",
  "nurbsSurface.texInsertedV":
    "\\text{after } \\texttt{insertKnotV}\\text{: columns } {first}\\text{–}{last} \\text{ are new (Boehm on every row), one column more}",
  "nurbsSurface.whatYouSee":
    "A tensor-product B-spline surface S(u, v) = Σ Σ N_i,p(u) N_j,q(v) P_ij (with weights w_ij a NURBS surface) over its control net (grey, dashed). Each direction has its own degree and knot vector, and the domain is [u_p, u_m+1] × [v_q, v_n+1]. As the Greek notes say, a knot can be inserted in either vector on its own: inserting in u applies Boehm's algorithm to every column of the net, which adds a whole row of control points without changing the surface (the rows Boehm's rule made are drawn dark); in v it works on the rows and adds a column. The coloured lines are the seams, the iso-curves at interior knots, coloured by the continuity the core measures across them (C^(p−r) for a knot of multiplicity r). Moving one control point changes the surface only over (p + 1) × (q + 1) spans: local control. Unlike curves, surfaces have no variation-diminishing property. The Shading choice shows zebra stripes (a kink in them is a break in tangent continuity) or the Gaussian or mean curvature, from the core's exact derivatives.",
  "nurbsSurface.try1":
    "Press “Insert u at the probe”: a new row of points appears and the surface stays exactly where it was; the seams legend gains the new knot.",
  "nurbsSurface.try2":
    "Type 1 into Probe u and insert: the knot 1 is now double, yet the seam stays C², because insertion keeps the surface. Now drag a point of the new rows: the seam drops to C¹, all that a double knot guarantees at degree 3.",
  "nurbsSurface.try3":
    "Select an inner handle and raise its weight: the surface is pulled towards it, and only near it (local control).",
  "nurbsSurface.try4":
    "Drag a corner point, then an inner one: the clamped surface passes through the corners but never through the inner points.",
  "nurbsSurface.try5":
    "Switch a direction to uniform (unclamped) knots: the surface shrinks away from the boundary of its net.",
};
