/** The English strings of www/demos/bezier-patch.js (keys start with the demo's `strings` prefix "bezierPatch"). */
export const BEZIER_PATCH = {
  "bezierPatch.title": "Bézier patch",
  "bezierPatch.summary":
    "A bicubic patch with its 4 × 4 control net: a generatrix curve swept along four directrices, iso-curves, the normal at a probe point, the matrix form.",
  "bezierPatch.aria":
    "Bicubic Bézier patch with a 4 × 4 control net; probe at u = {u}, v = {v}; S(u, v) = ({x}, {y}, {z}); normal ({nx}, {ny}, {nz})",
  "bezierPatch.control.u": "Probe u",
  "bezierPatch.control.u.input": "u value (decimal or fraction such as 1/3)",
  "bezierPatch.control.v": "Probe v and the generatrix",
  "bezierPatch.control.v.input": "v value (decimal or fraction such as 1/3)",
  "bezierPatch.control.stepBack.title": "v − 1/16",
  "bezierPatch.control.step.title": "v + 1/16",
  "bezierPatch.control.show": "Show",
  "bezierPatch.control.net": "Control net",
  "bezierPatch.control.iso": "Iso-curves",
  "bezierPatch.control.wireframe": "Wireframe",
  "bezierPatch.control.sweep": "Generatrix and directrices",
  "bezierPatch.control.normal": "Normal at the probe",
  "bezierPatch.control.shading": "Shading",
  "bezierPatch.shading.lit": "Lit",
  "bezierPatch.shading.zebra": "Zebra stripes",
  "bezierPatch.shading.gaussian": "Gaussian curvature K",
  "bezierPatch.shading.mean": "Mean curvature H",
  "bezierPatch.normalLabel": "n",
  "bezierPatch.texGeneratrix":
    "\\text{generatrix at } v = {v}\\text{: control points } D_i(v) = [v^3\\ v^2\\ v\\ 1]\\,M\\,[P_{i0}\\ P_{i1}\\ P_{i2}\\ P_{i3}]^T",
  "bezierPatch.whatYouSee":
    "A bicubic Bézier patch S(u, v) = Σ Σ B_i(u) B_j(v) P_ij over its 4 × 4 control net (grey, dashed), lit from the normals the core computes. As in the Croatian notes (section 6), each row of the net defines a directrix D_i(v) (green); at a given v their points D_0(v) … D_3(v) are the control points of the generatrix (vermillion), a cubic in u that sweeps the surface as v runs. Only the first and last directrix lie on the patch. The arrow is the unit normal at the probe point S(u, v). The matrix form writes the patch as [u³ u² u 1] A [v³ v² v 1]ᵀ with A = M P Mᵀ, one 4 × 4 matrix per coordinate, computed by the core from the current net. Zebra stripes reflect parallel light bands in the surface; the curvature shadings colour each point by K or H, blue negative, white zero, vermillion positive, scaled to the largest magnitude on the patch (the legend's ends).",
  "bezierPatch.try1":
    "Press play next to v and watch the generatrix sweep the patch while its control points slide along the directrices.",
  "bezierPatch.try2":
    "Drag an inner control point such as P₁₁ (or select it and press PageUp): the surface follows it but never reaches it; drag a corner and the patch passes through it.",
  "bezierPatch.try3":
    "Orbit the figure (drag empty space) until you look along an edge of the net: the boundary curve is the Bézier curve of that edge's four points.",
  "bezierPatch.try4":
    "Choose Gaussian curvature: blue regions are saddle-shaped (K < 0), vermillion ones dome-shaped (K > 0). Drag P₂₂ up and down and watch the colours move with the bump; switch to zebra stripes and see them bend where the surface bends.",
  "bezierPatch.try5":
    "Drag a control point in one coordinate only (select it, use the arrows) and watch which of A_x, A_y, A_z change: the matrix form is linear in the net, coordinate by coordinate.",
};
