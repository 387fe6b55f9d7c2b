/** The English strings of www/demos/patch-subdivision.js (keys start with "patchSubdivision"). */
export const PATCH_SUBDIVISION = {
  "patchSubdivision.title": "Patch subdivision",
  "patchSubdivision.summary":
    "A bicubic patch split into four patches of the same degree at (u₀, v₀), and drawn adaptively: split again until each net is flat enough.",
  "patchSubdivision.ariaSplit":
    "Bicubic Bézier patch split at u₀ = {u}, v₀ = {v} into four patches with their nets, meeting at S(u₀, v₀) = ({x}, {y}, {z})",
  "patchSubdivision.ariaAdaptive":
    "Bicubic Bézier patch tessellated adaptively at tolerance {tolerance}: {triangles} triangles; a uniform grid as fine as the finest cell has {uniform}",
  "patchSubdivision.control.mode": "Show",
  "patchSubdivision.control.split": "Split at (u₀, v₀)",
  "patchSubdivision.control.adaptive": "Adaptive tessellation",
  "patchSubdivision.control.u0": "u₀",
  "patchSubdivision.control.u0.input": "u₀ value (decimal or fraction such as 1/3)",
  "patchSubdivision.control.v0": "v₀",
  "patchSubdivision.control.v0.input": "v₀ value (decimal or fraction such as 1/3)",
  "patchSubdivision.control.nets": "The four control nets",
  "patchSubdivision.control.tolerance": "Tolerance ε (model units)",
  "patchSubdivision.control.tolerance.input": "tolerance ε, from {min} to {max}",
  "patchSubdivision.badTolerance":
    "tolerance ε: “{value}” is not a number from {min} to {max}; keeping the current value",
  "patchSubdivision.control.quadtree": "The quadtree in the (u, v) square",
  "patchSubdivision.splitNote":
    "Four bicubic patches on [0, {u}] × [0, {v}] (orange), [0, {u}] × [{v}, 1] (green), [{u}, 1] × [0, {v}] (purple) and [{u}, 1] × [{v}, 1] (vermillion).",
  "patchSubdivision.counts":
    "{triangles} triangles at ε = {tolerance}; a uniform {n} × {n} grid, as fine as the finest cell everywhere, has {uniform}.",
  "patchSubdivision.pointLabel": "S(u₀, v₀)",
  "patchSubdivision.axisU": "u",
  "patchSubdivision.axisV": "v",
  "patchSubdivision.texPieces":
    "\\text{four patches on }[0,u_0]\\times[0,v_0],\\ [0,u_0]\\times[v_0,1],\\ [u_0,1]\\times[0,v_0],\\ [u_0,1]\\times[v_0,1]",
  "patchSubdivision.texPoint": "u_0 = {u},\\ v_0 = {v}\\text{:}\\quad S(u_0, v_0) = {point}",
  "patchSubdivision.texCorner":
    "\\text{shared corner: } P^{(1)}_{33} = P^{(2)}_{30} = P^{(3)}_{03} = P^{(4)}_{00} = {corner},\\quad \\max\\lvert P - S(u_0, v_0)\\rvert = {gap}",
  "patchSubdivision.texFlat":
    "\\text{net flat: } 2\\delta + \\tfrac{1}{4}\\lvert D\\rvert \\le \\varepsilon = {tolerance} \\;\\Rightarrow\\; \\text{draw the corner quad, else split at } (\\tfrac12, \\tfrac12)",
  "patchSubdivision.texCounts":
    "\\text{{triangles} triangles}\\quad\\text{vs.}\\quad 2 \\cdot {n}^2 = {uniform} \\text{ on a uniform grid as fine as the finest cell}",
  "patchSubdivision.whatYouSee":
    "The Greek notes subdivide a Bézier surface like a curve: choose a pair (u₀, v₀); de Casteljau on every row of the net splits each row's curve into a “left” and a “right” part; de Casteljau on the columns of both parts splits each into an “upper” and a “lower” part. The result is four patches of the same type, each with its own (m + 1) × (n + 1) net (the four colours); together they are the patch, and they meet at S(u₀, v₀). In “Adaptive” the notes' drawing rule runs: if the control points are (nearly) coplanar, draw the quad of the four corner points, else subdivide into four and repeat for each piece. Here “nearly” is measured against the tolerance ε (δ bounds the net's distance from the bilinear patch of its corners, D is its twist), so every point of every triangle lies within ε of the surface. The inset shows the cells in the (u, v) square.",
  "patchSubdivision.try1":
    "Move u₀ and v₀: the four nets change, but their shared corner always lies on the patch, at S(u₀, v₀).",
  "patchSubdivision.try2":
    "Drag u₀ to 0: two pieces shrink to curves (their nets collapse onto the boundary).",
  "patchSubdivision.try3":
    "Switch to “Adaptive” and lower ε: the cells split where the patch bends, and stay large where it is nearly flat.",
  "patchSubdivision.try4":
    "In “Adaptive”, drag the bump P₂₂ down to the plane of its neighbours: the small cells around it merge into large ones.",
  "patchSubdivision.try5":
    "Compare the triangle count with a uniform grid as fine as the finest cell: the adaptive mesh spends its triangles only where the patch bends.",
};
