/** The English strings of www/demos/patch-de-casteljau.js (keys start with "patchDeCasteljau"). */
export const PATCH_DE_CASTELJAU = {
  "patchDeCasteljau.title": "De Casteljau on a patch",
  "patchDeCasteljau.summary":
    "The point S(u, v) of a Bézier patch built with curves only: de Casteljau on every row in v, then once more in u on the results. Columns first gives the same point.",
  "patchDeCasteljau.aria":
    "De Casteljau's construction on a Bézier patch of degree {degree} × {degree}, {order}, step {step} of {of}; u = {u}, v = {v}; S(u, v) = ({x}, {y}, {z})",
  "patchDeCasteljau.ariaRows": "rows first",
  "patchDeCasteljau.ariaColumns": "columns first",
  "patchDeCasteljau.control.u": "u (the column's triangle)",
  "patchDeCasteljau.control.u.input": "u value (decimal or fraction such as 1/3)",
  "patchDeCasteljau.control.v": "v (each row's triangle)",
  "patchDeCasteljau.control.v.input": "v value (decimal or fraction such as 1/3)",
  "patchDeCasteljau.control.stepBackU.title": "u − 1/16",
  "patchDeCasteljau.control.stepU.title": "u + 1/16",
  "patchDeCasteljau.control.stepBackV.title": "v − 1/16",
  "patchDeCasteljau.control.stepV.title": "v + 1/16",
  "patchDeCasteljau.control.order": "Order",
  "patchDeCasteljau.control.rowsFirst": "Rows first (in v, then u)",
  "patchDeCasteljau.control.columnsFirst": "Columns first (in u, then v)",
  "patchDeCasteljau.control.step": "Step (levels shown)",
  "patchDeCasteljau.control.step.input": "step, a whole number",
  "patchDeCasteljau.control.degree": "Degree of the patch",
  "patchDeCasteljau.degree1": "1 × 1 (bilinear)",
  "patchDeCasteljau.degree2": "2 × 2 (biquadratic)",
  "patchDeCasteljau.degree3": "3 × 3 (bicubic)",
  "patchDeCasteljau.degree4": "4 × 4",
  "patchDeCasteljau.control.show": "Show",
  "patchDeCasteljau.control.surface": "Surface",
  "patchDeCasteljau.control.net": "Control net",
  "patchDeCasteljau.pointLabel": "S(u, v)",
  "patchDeCasteljau.step.net": "Step {k} of {of}: the control net only.",
  "patchDeCasteljau.step.rows":
    "Step {k} of {of}: level {r} of every row's de Casteljau triangle in v = {v}.",
  "patchDeCasteljau.step.columns":
    "Step {k} of {of}: level {r} of every column's de Casteljau triangle in u = {u}.",
  "patchDeCasteljau.step.rowResults":
    "Step {k} of {of}: the {count} row results Q₀ … are the control points of the iso-curve at v = {v}.",
  "patchDeCasteljau.step.columnResults":
    "Step {k} of {of}: the {count} column results R₀ … are the control points of the iso-curve at u = {u}.",
  "patchDeCasteljau.step.column": "Step {k} of {of}: level {r} of de Casteljau on Q₀ … in u = {u}.",
  "patchDeCasteljau.step.row": "Step {k} of {of}: level {r} of de Casteljau on R₀ … in v = {v}.",
  "patchDeCasteljau.step.point":
    "Step {k} of {of}: the apex of the last triangle is the point S(u, v) of the patch.",
  "patchDeCasteljau.step.pointColumns":
    "Step {k} of {of}: the apex of the last triangle is the point S(u, v) of the patch.",
  "patchDeCasteljau.texRows":
    "\\text{each row } i\\text{ in } v = {v}\\text{:}\\ \\ P_{ij}^{r} = (1-v)\\,P_{ij}^{r-1} + v\\,P_{i,j+1}^{r-1},\\quad Q_i = P_{i0}^{{n}}",
  "patchDeCasteljau.texColumn":
    "\\text{then in } u = {u}\\text{:}\\ \\ Q_{i}^{r} = (1-u)\\,Q_{i}^{r-1} + u\\,Q_{i+1}^{r-1},\\quad S(u, v) = Q_0^{{m}}",
  "patchDeCasteljau.texColumns":
    "\\text{each column } j\\text{ in } u = {u}\\text{:}\\ \\ P_{ij}^{r} = (1-u)\\,P_{ij}^{r-1} + u\\,P_{i+1,j}^{r-1},\\quad R_j = P_{0j}^{{m}}",
  "patchDeCasteljau.texRow":
    "\\text{then in } v = {v}\\text{:}\\ \\ R_{j}^{r} = (1-v)\\,R_{j}^{r-1} + v\\,R_{j+1}^{r-1},\\quad S(u, v) = R_0^{{n}}",
  "patchDeCasteljau.texBoth":
    "S({u}, {v}) = \\underbrace{{rows}}_{\\text{rows first}} = \\underbrace{{columns}}_{\\text{columns first}},\\quad \\lvert\\Delta\\rvert = {gap}",
  "patchDeCasteljau.whatYouSee":
    "The Greek notes compute a point of a Bézier surface with curves only. De Casteljau's algorithm runs on every row of the control net with respect to v (the level colours of the curve demo); it gives m + 1 points Q₀ … Qₘ (vermillion), the control points of the isoparametric curve that belongs to v (the vermillion curve on the patch). De Casteljau once more on these points, with respect to u, ends at the point S(u, v). Columns first (each column in u, then the row of results in v) ends at the same point: the formula shows both.",
  "patchDeCasteljau.try1":
    "Set the step to 0 and raise it one by one: the rows' levels, their results on the iso-curve, then the last triangle down to S(u, v).",
  "patchDeCasteljau.try2":
    "Switch to “Columns first”: the triangles turn the other way and the iso-curve runs across, yet S(u, v) stays where it was.",
  "patchDeCasteljau.try3":
    "Press play next to v: the row results slide along the rows' Bézier curves and their iso-curve sweeps the patch.",
  "patchDeCasteljau.try4":
    "Drag an inner point such as P₁₁: every triangle of its row changes, the other rows' triangles stay.",
  "patchDeCasteljau.try5":
    "Choose degree 1 × 1: one level per direction, and S(u, v) is bilinear interpolation of the four corners.",
};
