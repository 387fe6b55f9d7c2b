/** The English strings of www/demos/cardinal.js (keys start with the demo's `strings` prefix "cardinal"). */
export const CARDINAL = {
  "cardinal.title": "Cardinal splines and Catmull–Rom",
  "cardinal.summary":
    "Tangents chosen automatically from the neighbours: a tension c flattens them; Catmull–Rom's α (uniform, centripetal, chord) decides whether a short segment loops.",
  "cardinal.aria": "{mode} curve ({value}) through {count} data points; {loop}",
  "cardinal.whatYouSee":
    "A Hermite curve through the data points whose tangents (orange, drawn as the Bézier handles Δ·m/3) come from the neighbouring points (syllabus section 5; the Croatian notes give the Catmull–Rom matrix form shown in the formula panel). In cardinal mode the tension c scales them down; in Catmull–Rom mode the parameter steps are |Pᵢ₊₁ − Pᵢ|^α. The points are unevenly spaced, so uniform Catmull–Rom (α = 0, dashed) loops in the short segment P₁P₂, while centripetal (α = ½) does not.",
  "cardinal.try1":
    "Move α from 0.5 down to 0: the solid curve turns into the dashed one and the loop in segment 1 appears; at α = 1 (chord length) it hugs the polygon.",
  "cardinal.try2":
    "Switch to cardinal and raise the tension c towards 1: the tangents shrink to nothing and the curve becomes the polygon; c < 0 overshoots.",
  "cardinal.try3":
    "Drag P₂ away from P₁ until the segments are about equally long: the uniform curve's loop vanishes — the cusps and loops come from uneven spacing.",
  "cardinal.minPoints": "this demo needs at least {min} data points",
  "cardinal.maxPoints": "this demo allows at most {max} data points",
  "cardinal.count": "{count} data points",
  "cardinal.control.modeLegend": "Tangents",
  "cardinal.mode.cardinal": "cardinal (tension c)",
  "cardinal.mode.catmull-rom": "Catmull–Rom (α)",
  "cardinal.control.tension": "Tension c",
  "cardinal.control.tension.input": "tension c (−1 to 1)",
  "cardinal.control.alpha": "α (0 uniform, ½ centripetal, 1 chord)",
  "cardinal.control.alpha.input": "exponent α (0 to 1)",
  "cardinal.control.closed": "Closed curve",
  "cardinal.control.segment": "Segment i (from Pᵢ to Pᵢ₊₁)",
  "cardinal.control.segment.input": "segment index i",
  "cardinal.loopHere": "This curve loops inside segment {i}.",
  "cardinal.loopGhost":
    "The uniform curve (α = 0, dashed) loops inside segment {i}; this one does not.",
  "cardinal.noLoopHere": "No loop inside a segment.",
  "cardinal.noLoopGhost": "No loop inside a segment, not even for α = 0.",
  "cardinal.loopLabel": "loop",
  "cardinal.legend.curve": "this curve",
  "cardinal.legend.ghost": "uniform, α = 0",
  "cardinal.formula.ghost": "(α = 0: the dashed curve)",
  "cardinal.col.point": "Point",
  "cardinal.col.param": "Parameter tᵢ",
  "cardinal.col.tangent": "Tangent mᵢ (core)",
  "cardinal.tableCaption": "Parameters and tangents at the data points",
};
