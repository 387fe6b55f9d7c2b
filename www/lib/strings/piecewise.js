/** The English strings of www/demos/piecewise.js (keys start with the demo's `strings` prefix "piecewise"). */
export const PIECEWISE = {
  "piecewise.title": "Piecewise curves and their joints",
  "piecewise.summary":
    "Type each piece's x(t), y(t) and interval; the core names every joint Cᵏ or Gᵏ, proves it where it can, and shows the one-sided values side by side.",
  "piecewise.aria": "A curve of {count} pieces typed as formulas; joints: {joints}",
  "piecewise.ariaNoJoints": "A curve of one piece typed as formulas: no joint",
  "piecewise.whatYouSee":
    "Each piece Pᵢ(t) = (x(t), y(t)) is drawn in its own colour on its interval; where one interval ends the next begins (syllabus section 1: pieces on [0, 1) and [1, 2]). At every joint the arrows are the velocities arriving, P′(t⁻), and leaving, P′(t⁺); the table under the figure lists the one-sided values x(t⁻), x(t⁺), x′(t⁻), x′(t⁺), … and the first order where they differ. The verdict Cᵏ (the derivatives up to k agree) or Gᵏ (only the shape: direction, then curvature) is the core's, proven in exact arithmetic for polynomial pieces.",
  "piecewise.try1":
    "Press “C⁰, not C¹”: x′(1⁻) = −2 but x′(1⁺) = 0, so the velocity jumps and the curve has a corner. Then press “C¹”: x′ agrees, only x″ jumps.",
  "piecewise.try2":
    "In piece 2 type x(t) = t^2 - 4t + 3 yourself, then change the 3 into 4: the joint breaks (not C⁰), and the figure shows the gap.",
  "piecewise.try3":
    "Press “G¹, not C¹”: the second piece is the same parabola run at double speed, so the shape is smooth (G¹ and more) though P′ doubles at t = 1.",
  "piecewise.pieces": "Pieces",
  "piecewise.piece": "Piece {i}",
  "piecewise.field.x": "x(t) =",
  "piecewise.field.y": "y(t) =",
  "piecewise.field.from": "from t =",
  "piecewise.field.to": "to t =",
  "piecewise.field.name": "{field} of piece {i}",
  "piecewise.fieldName.x": "x(t)",
  "piecewise.fieldName.y": "y(t)",
  "piecewise.fieldName.from": "start of the interval",
  "piecewise.fieldName.to": "end of the interval",
  "piecewise.addPiece": "Add a piece",
  "piecewise.addPiece.title": "Add a piece after the last one, starting where it ends",
  "piecewise.removePiece": "Remove the last piece",
  "piecewise.removePiece.title": "Remove the last piece (one piece stays at least)",
  "piecewise.maxPieces": "this demo allows at most {max} pieces",
  "piecewise.minPieces": "a curve needs at least one piece",
  "piecewise.typingError": "Piece {i}, {field}: {message}",
  "piecewise.presets": "The notes' exercise and more",
  "piecewise.preset.title": "Replace the pieces by this example",
  "piecewise.preset.notC0": "Not C⁰",
  "piecewise.preset.c1": "C¹",
  "piecewise.preset.c0": "C⁰, not C¹",
  "piecewise.preset.g1": "G¹, not C¹",
  "piecewise.jointsLegend": "Joints",
  "piecewise.noJoints": "One piece: no joint to check.",
  "piecewise.joint": "t = {t}: {verdict}",
  "piecewise.verdict": "{c}, {g}",
  "piecewise.verdict.broken": "not C⁰: the pieces do not meet",
  "piecewise.verdict.infinite": "C∞: both sides are one polynomial",
  "piecewise.proven": "proven (exact arithmetic)",
  "piecewise.measured": "measured (floating point)",
  "piecewise.breakProven":
    "measured (floating point); that order {order} differs is proven (interval arithmetic)",
  "piecewise.figureVerdict": "t = {t}: {verdict} ({how})",
  "piecewise.tag": "t = {t}",
  "piecewise.leftArrow": "P′({t}⁻)",
  "piecewise.rightArrow": "P′({t}⁺)",
  "piecewise.incomplete":
    "Part of the curve could not be refined within the work budget; it is drawn coarser there.",
  "piecewise.tableCaption": "Joint at t = {t}: {verdict}, {how}",
  "piecewise.col.quantity": "Value",
  "piecewise.col.left": "from the left (t⁻)",
  "piecewise.col.right": "from the right (t⁺)",
  "piecewise.col.agree": "Agree?",
  "piecewise.agree.yes": "yes",
  "piecewise.agree.no": "no",
  "piecewise.undefined": "undefined",
  "piecewise.formula.joint": "joint at",
  "piecewise.formula.proven": "proven",
  "piecewise.formula.measured": "measured",
  "piecewise.formula.breakProven": "measured; order {order} differs: proven",
  "piecewise.formula.notC0": "not C⁰",
  "piecewise.badPiece":
    "field “{field}”: piece {index} must be [x, y, from, to] with texts of at most 1000 characters",

  // The section 1 exercise on this demo (www/exercises/index.js).
  "exercise.piecewise-c1.title": "Type a C¹ second piece",
  "exercise.piecewise-c1.task":
    "Piece 1 is x = 1 − t², y = t on [0, 1]. Type x(t) and y(t) of piece 2 on [1, 2] so that the joint at t = 1 is C¹: the same point and the same velocity from both sides.",
  "exercise.piecewise-c1.hint":
    "At t = 1 piece 1 is at (0, 1) with velocity (−2, 1). Keep y = t and look for x = t² + bt + c with x(1) = 0 and x′(1) = 2 + b = −2.",
  "exercise.piecewise-c1.notYet": "Not yet. The core’s verdict at t = 1: {detail}.",
};
