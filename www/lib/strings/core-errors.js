/**
 * The English messages of the curve library's errors, by code (lib/core-errors.js turns a
 * thrown Error's `code` and `params` into text with them). Each `coreError.<code>` reproduces
 * the library's English message (src/error/message.rs; the glue's in scripts/glue.mjs) word for
 * word: its placeholders are the error's `params` (camelCase field names) or the values
 * lib/core-errors.js derives from them (`DERIVED_PLACEHOLDERS`: n = points − 1, order = degree
 * + 1, …). Where English writes "point(s)" or pluralises on a count, the key has `.one` and
 * `.other` (chosen by the count named in `PLURAL_COUNT`), so that a language can decline.
 * `coreError.subject.<key>` is the phrase of every subject key of src/error/phrase.rs.
 */
export const CORE_ERRORS = {
  // Helpers: a number the library cannot write as digits, a subject with its index, the
  // parametrisations named by "coincident-points", the ends named by "knots-not-clamped", an
  // `out` buffer's length ("out-buffer").
  "coreError.number.nan": "NaN",
  "coreError.number.infinity": "Infinity",
  "coreError.number.negativeInfinity": "-Infinity",
  "coreError.indexed": "{subject} {index}",
  "coreError.spacing.uniform": "Uniform",
  "coreError.spacing.chord": "Chord",
  "coreError.spacing.centripetal": "Centripetal",
  "coreError.spacing.alpha": "alpha = {alpha}",
  "coreError.end.first": "first",
  "coreError.end.last": "last",
  "coreError.bufferLength": "length {length}",

  // One message per code (src/error/code.rs), in the order of src/error/mod.rs.
  "coreError.invalid-dimension": "dim must be 2 or 3, got {dim}",
  "coreError.coordinate-count":
    "coordinate count {count} is not a multiple of dim = {dim}; points are given as flat [{firstPoint}, x1, …]",
  "coreError.not-finite": "{subject} is {value}; every number must be finite",
  "coreError.coordinate-too-large":
    "{subject} is {value}; a coordinate must be at most {max} in magnitude, so that derivatives and lengths stay finite",
  "coreError.too-few-points.one": "{what} needs at least {needed} control point, got {got}",
  "coreError.too-few-points.other": "{what} needs at least {needed} control points, got {got}",
  "coreError.weight-count": "weights must have one value per control point ({expected}), got {got}",
  "coreError.non-positive-weight":
    "weight {index} is {value}; weights must be > 0 (zero or negative weights can put poles on the curve)",
  "coreError.parameter-out-of-range": "{name} = {value} is outside the domain [{min}, {max}]",
  "coreError.index-out-of-range":
    "control point index {index} is out of range: the curve has {count} points (0..={last})",
  "coreError.point-dimension": "a point needs {expected} coordinates, got {got}",
  "coreError.invalid-tolerance": "tolerance {value} is not usable: it must be a finite number > 0",
  "coreError.tolerance-too-small":
    "tolerance {value} is not usable: it is below {relative} × the curve's size ({size}); rounding would dominate",
  "coreError.flattening-stalled":
    "tolerance {value} is not usable: no piece of the curve is flat enough at this precision",
  "coreError.invalid-interval": "interval [{a}, {b}] is empty; it needs a < b",
  "coreError.unknown-option": '{name} must be one of {expected}, got "{value}"',
  "coreError.in-argument": "{argument}: {message}",
  "coreError.knot-count":
    "knot vector must have n+p+2 = {n} + {degree} + 2 = {expected} values, got {got}",
  "coreError.knot-order":
    "knots must not decrease: u_{index} = {value} comes after u_{previousIndex} = {previous}",
  "coreError.empty-domain":
    "the domain [u_p, u_(n+1)] = [u_{degree}, u_{points}] = [{a}, {b}] is empty; it needs u_{degree} < u_{points}",
  "coreError.knot-multiplicity":
    "knot {knot} appears {multiplicity} times (u_{first}..u_{last}); a degree-{degree} curve allows at most p+1 = {order}",
  "coreError.insertion-multiplicity.one":
    "inserting knot {knotValue} {times} time(s) would give it multiplicity {multiplicity}; degree {degree} allows at most p+1 = {order}",
  "coreError.insertion-multiplicity.other":
    "inserting knot {knotValue} {times} time(s) would give it multiplicity {multiplicity}; degree {degree} allows at most p+1 = {order}",
  "coreError.degree-zero": "degree must be at least 1, got 0",
  "coreError.degree-out-of-range": "degree must be 1..={max}, got {degree}",
  "coreError.too-few-points-for-degree":
    "degree {degree} needs at least p+1 = {order} control points, got {got}",
  "coreError.coincident-points":
    "points {index} and {next} coincide; {kind} spacing needs distinct consecutive points",
  "coreError.phantom-even-degree":
    "phantom points make a uniform B-spline of odd degree pass through its ends; degree {degree} is even",
  "coreError.not-a-span": "span {span} is not a non-empty span of the domain (valid: [{valid}])",
  "coreError.rational-join":
    "the joining rules are for polynomial Bézier pieces; these have weights",
  "coreError.join-degree.one":
    "rule {rule} fixes {needed} point(s) of the right piece; degrees {left} and {right} are too low (each piece needs degree >= {needed})",
  "coreError.join-degree.other":
    "rule {rule} fixes {needed} point(s) of the right piece; degrees {left} and {right} are too low (each piece needs degree >= {needed})",
  "coreError.no-joint-tangent":
    "G1 needs a tangent at the joint, but the left piece's last two points coincide",
  "coreError.breakpoint-count": "{pieces} pieces need {breakpoints} breakpoints, got {got}",
  "coreError.degenerate-line": "the line needs two different points, got ({x}, {y}) twice",
  "coreError.curve-batch-length":
    "{count} coordinates do not split into curves of degree {degree} ((degree + 1)·dim = {perCurve} numbers each)",
  "coreError.rational-hodograph":
    "the hodograph of a rational curve is not a Bézier curve of degree n − 1; sample derivative(t, 1) instead",
  "coreError.mapped-weight":
    "the map sends control point {index} to weight {weight}; weights must stay > 0 (the point would cross the line at infinity)",
  "coreError.singular-map": "the projective map is singular (determinant 0)",
  "coreError.matrix-size": "a projective map is a 3×3 matrix (9 numbers, row by row), got {got}",
  "coreError.degenerate-triangle":
    "a circular arc needs a proper triangle P0 P1 P2 (no coincident or collinear points)",
  "coreError.not-isosceles":
    "a circular arc needs an isosceles triangle: |P0P1| = {first} but |P1P2| = {second}",
  "coreError.arc-point-count": "a circular arc needs 3 control points (6 numbers), got {got}",
  "coreError.invalid-sweep":
    "the sweep must be non-zero and at most one full turn (2π), got {sweep}",
  "coreError.parallel-axes": "the two axes of an ellipse must not be parallel or zero",
  "coreError.axis-lengths":
    "center, axisX and axisY need the same length, got {center}, {axisX}, {axisY}",
  "coreError.not-positive": "{name} must be > 0, got {value}",
  "coreError.dimension-mismatch": "both pieces need the same dim, got {left} and {right}",
  "coreError.piece-point-count":
    "degrees [{degrees}] need {needed} control points in all (n + 1 per piece), got {got}",
  "coreError.buffer-length": "output buffer has {len} values, {count} points need {needed}",
  "coreError.net-coordinate-count":
    "points must hold rows·cols·3 = {rows}·{cols}·3 = {total} coordinates, got {got}",
  "coreError.patch-too-small":
    "a Bézier patch needs at least 2 rows and 2 columns (degree ≥ 1 each way), got {rows} × {cols}",
  "coreError.net-index-out-of-range":
    "control point (i, j) = ({i}, {j}) is out of range: the net has {rows} × {cols} points (i in 0..={lastI}, j in 0..={lastJ})",
  "coreError.no-normal":
    "the surface has no normal at (u, v) = ({u}, {v}): ∂S/∂u × ∂S/∂v = 0 there, even in the limit from inside the domain",
  "coreError.empty-tessellation":
    "tessellate needs at least 1 quad each way, got nu = {nu}, nv = {nv}",
  "coreError.too-large": "{what} = {value} is too large; at most {max} is allowed",
  "coreError.result-too-large":
    "{what} = {counts} values of {valueBytes} bytes = {bytes} bytes is too large; one result may take at most {maxBytes} bytes ({mib} MiB)",
  "coreError.argument-type": "{name} must be {expected}, got {got}",
  "coreError.not-whole-number": "{subject} must be a whole number from 0 to {max}, got {value}",
  "coreError.needs-2d": "{operation} works on 2D curves; this curve has dim = {dim}",
  "coreError.needs-3d":
    "{operation} builds a 3D surface and needs a 3D curve; this curve has dim = {dim}",
  "coreError.zero-direction": "{name} must not be the zero vector (it gives no direction)",
  "coreError.needs-polynomial":
    "{operation} works on polynomial patches; this one has weights (a rational patch has a denominator)",
  "coreError.all-weights-zero":
    "all {count} weights are 0: the denominator w(t) = Σ w_i B_i(t) is 0 for every t, so there is no curve",
  "coreError.param-count": "params must have one value per point ({points}), got {params}",
  "coreError.params-not-increasing":
    "params must increase strictly: t_{index} = {value} is not above t_{previousIndex} = {previous}",
  "coreError.missing-argument": "{neededBy} needs {name}, which was not given",
  "coreError.argument-length": "{name} must have {expected} numbers, got {got}",
  "coreError.not-closed":
    "periodic interpolation needs the last point (point {last}) equal to the first",
  "coreError.alpha-out-of-range":
    "alpha = {value} is outside [0, 1] (0 uniform, 0.5 centripetal, 1 chord)",
  "coreError.control-count-out-of-range":
    "count = {count} control points is outside [degree + 1, number of points] = [{min}, {max}]",
  "coreError.schoenberg-whitney":
    "the interpolation system is singular: t_{index} = {param} must lie inside the support (u_{index}, u_{hiIndex}) = ({lo}, {hi}) of N_{index},{degree} (Schoenberg–Whitney condition)",
  "coreError.too-few-data-points.one": "{what} needs at least {needed} data point, got {got}",
  "coreError.too-few-data-points.other": "{what} needs at least {needed} data points, got {got}",
  "coreError.stroke-far-from-curve":
    "the stroke starts {startDistance} and ends {endDistance} from the curve; to redraw a part, start and end it within {near} of the curve (an open curve is also extended by a stroke that starts or ends there)",
  "coreError.singular-system": "{what} is singular: elimination met a zero pivot in row {row}",
  "coreError.spline-kind":
    "{operation} works on splines built by {needs}; this one was built by {got}",
  "coreError.conflicting-options": "{first} cannot be combined with {second}: {reason}",
  "coreError.knots-not-clamped":
    "a least-squares fit with exact ends needs clamped knots: the {end} p+1 = {order} knots must equal {param}",

  // The glue's own errors (scripts/glue.mjs) and the bindings' internal failures.
  "coreError.freed": "this {className} was freed",
  "coreError.no-constructor":
    "new {className}() is not available: a {className} comes from {makers}",
  "coreError.out-buffer":
    "out must be a Float64Array or number[] of at least dim = {dim} numbers, got {got}",
  "coreError.internal": "{message}",

  // The subjects (src/error/phrase.rs PHRASES), sorted by key.
  // Typed expressions (src/expr/error.rs): the place ("pieces[1].y, characters 3–4"), then
  // one message per problem code; `.comma`, `.bar`, `.end`, `.trig` are the forms
  // lib/core-errors.js picks by the params (EXPRESSION_FORMS).
  "coreError.place.pieceField": "pieces[{piece}].{field}",
  "coreError.place.piece": "pieces[{piece}]",
  "coreError.place.field": "{field}",
  "coreError.place.none": "expression",
  "coreError.place.range": "{place}, characters {start}–{end}",
  "coreError.place.at": "{place}: {message}",
  "coreError.expression-empty": "nothing is typed; write an expression in t, such as cos(t)",
  "coreError.expression-too-long":
    "the expression has {length} characters; at most {max} are allowed",
  "coreError.expression-too-deep":
    "parentheses, powers and functions are nested more than {max} deep",
  "coreError.expression-too-large":
    "the expression has more than {max} numbers, names and operations",
  "coreError.unexpected-character":
    '"{character}" is not part of the language; use numbers, t, + − * / ^ and parentheses',
  "coreError.unexpected-character.comma": '"," is not used: write decimals with a point (2.5)',
  "coreError.unexpected-character.bar": '"|" is not used: write abs(t)',
  "coreError.expected-operand": 'a number, a name or "(" is needed before "{found}"',
  "coreError.expected-operand.end": 'the expression ends where a number, a name or "(" is needed',
  "coreError.missing-operator":
    'an operator is missing before "{found}" (write * or + between them)',
  "coreError.unclosed-parenthesis": 'this "(" is never closed; add ")"',
  "coreError.unmatched-parenthesis": 'this ")" has no "(" before it',
  "coreError.unknown-name":
    'unknown name "{name}"; use t, pi, e, a function such as sin(t), or a parameter',
  "coreError.function-needs-parentheses": "{name} needs parentheses: write {name}(t)",
  "coreError.function-power":
    "{name}^ needs a whole number ≥ 1 before the parentheses: {name}^2(t) means ({name}(t))^2",
  "coreError.function-power.trig":
    "{name}^ needs a whole number ≥ 1 (sin^2(t)); the inverse is a{name}(t)",
  "coreError.ambiguous-division": '"{text}" is ambiguous: write {product} or {quotient}',
  "coreError.number-after-name": "a number after a name: write {number}{name} or {name}^{number}",
  "coreError.scientific-notation":
    '"{text}" is not read as a power of ten (e is Euler\'s number): write the decimal, such as 0.001, or a product such as 2.5*10^3',
  "coreError.invalid-number": '"{text}" is not a number',
  "coreError.invalid-parameter-name":
    '"{name}" cannot be a parameter: use one letter other than t and e (a, b, ω) or a letter with a subscript (a_1)',
  "coreError.unknown-parameter": 'the curve has no parameter "{name}"',
  "coreError.not-finite-value": "the value is {value}; it must be a finite number",
  "coreError.empty-piece-interval": "the interval [{from}, {to}] is empty; it needs from < to",
  "coreError.pieces-do-not-join":
    "starts at {from} but the previous piece ends at {previous}; pieces join in t",
  "coreError.not-polynomial": "this piece is not a polynomial in t, so it has no Bézier form",
  "coreError.bound-uses-t":
    "a bound is a number and cannot depend on t; write it with numbers, pi, e and parameters",
  "coreError.missing-field":
    "this field is missing; every piece needs x, y, from and to (and z on every piece or none)",
  "coreError.piece-count": "a curve needs 1 to {max} pieces, got {count}",

  "coreError.subject.adaptive-depth": "adaptive subdivision depth (the tolerance is near rounding)",
  "coreError.subject.adaptive-vertices": "adaptive mesh vertices",
  "coreError.subject.adaptive-vertices-leaves": "adaptive mesh vertices (at least one per leaf)",
  "coreError.subject.adaptive-vertices-patches":
    "adaptive mesh vertices (at least one per Bézier patch)",
  "coreError.subject.basis-sample-count":
    "count (samples per basis function: one value per function each)",
  "coreError.subject.bessel-spline": "a Bessel spline",
  "coreError.subject.bezier-curve": "a Bézier curve",
  "coreError.subject.boolean": "a boolean",
  "coreError.subject.bspline-interpolation-system": "the B-spline interpolation system",
  "coreError.subject.cardinal-spline": "a cardinal spline",
  "coreError.subject.catmull-rom-spline": "a Catmull–Rom spline",
  "coreError.subject.clamped-end-condition": 'the "clamped" end condition',
  "coreError.subject.closed-has-no-ends": "a closed curve has no ends",
  "coreError.subject.closed-interpolating-bspline":
    "a closed interpolating B-spline of this degree (p + 1, at least 3)",
  "coreError.subject.closed-knots-computed":
    "a closed curve's knots are the periodic ones computed from the params",
  "coreError.subject.composite-curve": "a composite curve (pieces)",
  "coreError.subject.coordinate": "coordinate",
  "coreError.subject.cubic-spline": "a cubic spline",
  "coreError.subject.cubic-spline-system": "the cubic spline's tangent system",
  "coreError.subject.curvature-work": "curvature points for this degree (work budget 2^28)",
  "coreError.subject.curve": "a BSplineCurve or BezierCurve",
  "coreError.subject.data-point-count": "number of data points",
  "coreError.subject.degree-u-rows": "degreeU (rows along u)",
  "coreError.subject.degree-v-columns": "degreeV (columns along v)",
  "coreError.subject.derivative-order": "derivative order",
  "coreError.subject.every-piece": "every piece (degree >= 1)",
  "coreError.subject.flattening-segments": "number of flattening segments",
  "coreError.subject.flattening-segments-estimated":
    "number of flattening segments (estimated before flattening: lower the degree or raise the tolerance)",
  "coreError.subject.grid-points": "grid points us.length·vs.length",
  "coreError.subject.hermite-spline": "a Hermite spline",
  "coreError.subject.interpolating-bspline":
    "an interpolating B-spline of this degree (p + 1 − end derivatives, at least 2)",
  "coreError.subject.interpolating-surface":
    "an interpolating surface of this degree (degree + 1 per direction)",
  "coreError.subject.interpolation-system-size": "the interpolation system's size (unknowns)",
  "coreError.subject.knot": "knot",
  "coreError.subject.knot-to-insert": "knot to insert",
  "coreError.subject.lagrange-curve": "a Lagrange curve",
  "coreError.subject.lagrange-point-count": "number of points of a Lagrange curve",
  "coreError.subject.least-squares-bspline":
    "a least-squares B-spline of this degree (p + 1, at least 2)",
  "coreError.subject.least-squares-system": "the least-squares normal equations",
  "coreError.subject.length": "its length",
  "coreError.subject.matrix-entry": "matrix entry",
  "coreError.subject.new-point-coordinate": "the new point's coordinate",
  "coreError.subject.numbers": "an array of numbers (Float64Array or number[])",
  "coreError.subject.object": "an object",
  "coreError.subject.parameter": "parameter",
  "coreError.subject.parametrisation": "a parametrisation",
  "coreError.subject.phantom-points": "phantom points of this degree",
  "coreError.subject.polynomial": "a polynomial",
  "coreError.subject.rational-bezier-curve": "a rational Bézier curve",
  "coreError.subject.rational-derivative-order": "derivative order of a rational curve",
  "coreError.subject.refine-result":
    "refine: (control points + us.length) × homogeneous coordinates",
  "coreError.subject.sample-count": "sample count",
  "coreError.subject.sample-work": "sample count for this degree (work budget 2^28)",
  "coreError.subject.sample-derivatives-result": "sampleDerivatives: us.length × coordinates",
  "coreError.subject.sample-grid-result": "sampleGrid: us.length × vs.length × 3 coordinates",
  "coreError.subject.sample-params-result": "sample: params.length × coordinates",
  "coreError.subject.sample-ts-result": "sample: ts.length × coordinates",
  "coreError.subject.sample-uniform-result": "sampleUniform: count × coordinates",
  "coreError.subject.sample-uniform-view-result": "sampleUniformView: count × coordinates",
  "coreError.subject.sample-view-result": "sampleView: params.length × coordinates",
  "coreError.subject.samples-result": "samples (points × coordinates)",
  "coreError.subject.start-angle": "start angle",
  "coreError.subject.string": "a string",
  "coreError.subject.stroke": "a stroke",
  "coreError.subject.surface-derivative-order": "derivative order du + dv",
  "coreError.subject.tessellation-vertices": "tessellation vertices (nu + 1)(nv + 1)",
  "coreError.subject.tessellation-work":
    "tessellation vertices (nu + 1)(nv + 1) for this degree (work budget 2^28)",
  "coreError.subject.weight": "weight",
};
