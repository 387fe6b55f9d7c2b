/** The English strings of www/demos/surface-interpolation.js (keys start with the demo's `strings` prefix "surfaceInterpolation"). */
export const SURFACE_INTERPOLATION = {
  "surfaceInterpolation.title": "Surface interpolation",
  "surfaceInterpolation.summary":
    "A B-spline surface through every point of a 4 × 5 grid: parameters, knots, then every column interpolated in u and every row of the result in v.",
  "surfaceInterpolation.aria":
    "B-spline surface of degrees {p} and {q} through a {rows} × {cols} grid of data points, {kind} parameters; largest miss {miss}",
  "surfaceInterpolation.control.parametrisation": "Parameters",
  "surfaceInterpolation.kind.uniform": "Uniform",
  "surfaceInterpolation.kind.chord": "Chord length",
  "surfaceInterpolation.kind.centripetal": "Centripetal",
  "surfaceInterpolation.control.degreeU": "Degree p in u",
  "surfaceInterpolation.control.degreeV": "Degree q in v",
  "surfaceInterpolation.degree1": "1",
  "surfaceInterpolation.degree2": "2",
  "surfaceInterpolation.degree3": "3",
  "surfaceInterpolation.degree4": "4",
  "surfaceInterpolation.control.show": "Show",
  "surfaceInterpolation.control.columns": "Step 1: every column interpolated in u",
  "surfaceInterpolation.control.net": "Control net of the result",
  "surfaceInterpolation.control.iso": "Iso-curves through the data",
  "surfaceInterpolation.legendColumns": "step 1: column curves, points s_il",
  "surfaceInterpolation.legendNet": "control net P_ij",
  "surfaceInterpolation.missReadout":
    "The surface passes through all {count} data points: largest miss {miss}",
  "surfaceInterpolation.texUnknowns":
    "S(\\bar u_k, \\bar v_l) = Q_{kl},\\ k = 0..{m},\\ l = 0..{n}\\text{: } {rows} \\cdot {cols} = {count} \\text{ equations for } {count} \\text{ unknown control points } P_{ij}\\ (p = {p},\\ q = {q})",
  "surfaceInterpolation.texColumns":
    "\\text{1. columns: } {cols} \\text{ curves in } u\\ ({rows} \\times {rows}\\text{, } {cols} \\text{ right sides})\\text{: } \\textstyle\\sum_i N_{i,{p}}(\\bar u_k)\\, s_{il} = Q_{kl}",
  "surfaceInterpolation.texRows":
    "\\text{2. rows: } {rows} \\text{ curves in } v\\ ({cols} \\times {cols}\\text{, } {rows} \\text{ right sides})\\text{: } \\textstyle\\sum_j N_{j,{q}}(\\bar v_l)\\, P_{ij} = s_{il}",
  "surfaceInterpolation.whatYouSee":
    "A grid of 4 × 5 data points Q_kl (the handles, a height field) and the B-spline surface through every one of them. Each data point gets parameters (ū_k, v̄_l): along every column the chosen parametrisation (uniform, chord length or centripetal) normalised to [0, 1], averaged over the columns, and likewise along the rows; the knots average the parameters. Then, as the Greek notes describe, the work is two passes of curve interpolation: first every column of the data is interpolated in u (the green curves and their control points s_il), then every row of those control points is interpolated in v, which gives the control net P_ij (purple, dotted). The surface's iso-curve at v̄_l is exactly the green column curve l. The notes' bicubic version adds end conditions (m + 3 control points per column); here the averaging knots give one control point per data point. Interpolation is global: dragging one data point moves the whole net.",
  "surfaceInterpolation.try1":
    "Turn on the iso-curves: those at v̄_l lie exactly on the green column curves of step 1, and those at ū_k run through the rows of data.",
  "surfaceInterpolation.try2":
    "Drag the highest data point up: the surface still passes through every point, but the control net moves everywhere — no local control.",
  "surfaceInterpolation.try3":
    "Switch between uniform, chord length and centripetal parameters after making one gap of the grid much longer than the others: the wiggles move.",
  "surfaceInterpolation.try4":
    "Set both degrees to 1: the surface becomes the bilinear patches through the grid, and the control net is the data itself.",
};
