/**
 * The demo registry: every demo module, in gallery order. The gallery, the playground, the
 * `<spline-lab>` element and the browser tests all find demos here (see lib/README.md for the
 * module contract). To add a demo: write `www/demos/<id>.js`, import it below, add it to the list.
 */
import * as deCasteljau from "./de-casteljau.js";
import * as bernstein from "./bernstein.js";
import * as subdivision from "./subdivision.js";
import * as flattening from "./flattening.js";
import * as lineIntersection from "./line-intersection.js";
import * as joining from "./joining.js";
import * as bezierProperties from "./bezier-properties.js";
import * as derivatives from "./derivatives.js";
import * as bsplineBasis from "./bspline-basis.js";
import * as deBoor from "./de-boor.js";
import * as knotVectors from "./knot-vectors.js";
import * as localControl from "./local-control.js";
import * as knotInsertion from "./knot-insertion.js";
import * as multiplicity from "./multiplicity.js";
import * as matrixForm from "./matrix-form.js";
import * as weights from "./weights.js";
import * as conics from "./conics.js";
import * as nurbsCircle from "./nurbs-circle.js";
import * as projective from "./projective.js";
import * as negativeWeights from "./negative-weights.js";

/** All demos, in the order the gallery shows them within their section. */
export const demos = [deCasteljau, bernstein, subdivision, flattening, lineIntersection, joining, bezierProperties, derivatives, bsplineBasis, deBoor, knotVectors, localControl, knotInsertion, multiplicity, matrixForm, weights, conics, nurbsCircle, projective, negativeWeights];

/** The demo with this id, or undefined. */
export function findDemo(id) {
  return demos.find((demo) => demo.id === id);
}
