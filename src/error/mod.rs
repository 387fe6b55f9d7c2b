//! The crate's one error type. Every message speaks to a student and carries the numbers.
//!
//! One variant per kind of failure, with the numbers as named fields: [`Error::code`] gives a
//! stable kebab-case code per variant (`code.rs`), `Display` the English message (`message.rs`),
//! so a translated message needs only the code and the fields.

mod check;
mod code;
mod message;
mod phrase;
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
mod serialize;

pub use phrase::{phrase, PHRASES};

pub(crate) use check::{
    check_coordinate_of, check_finite, check_in_range, check_tolerance, in_argument,
};

/// Everything that can go wrong when building or querying a curve.
///
/// Constructors validate their input in a fixed order — dimension, coordinate count, finite
/// numbers, number of points against the degree, knots, weights — so the first problem found
/// is always the same one for the same input.
#[derive(Debug, Clone, PartialEq)]
// In the wasm build the fields become a thrown Error's `params` (camelCase), see src/wasm/error.rs.
#[cfg_attr(
    all(target_arch = "wasm32", target_os = "unknown"),
    derive(serde::Serialize),
    serde(untagged, rename_all_fields = "camelCase")
)]
pub enum Error {
    /// `dim` is not 2 or 3: `geom::check_dim(4)`, or `new BezierCurve(points, 4)` from JavaScript.
    InvalidDimension {
        /// The dimension that was given.
        dim: usize,
    },
    /// The flat coordinate array does not split into whole points:
    /// `BezierCurve::<DVec2>::from_flat(&[0.0, 0.0, 1.0], None)`.
    CoordinateCount {
        /// Number of coordinates given.
        count: usize,
        /// Dimension of one point.
        dim: usize,
    },
    /// A coordinate, weight, parameter or tolerance is NaN or infinite:
    /// `BezierCurve::<DVec2>::from_flat(&[0.0, f64::NAN, 1.0, 1.0], None)`.
    NotFinite {
        /// What the number is: a subject (`phrase.rs`), "coordinate", "t", "weight".
        what: &'static str,
        /// Its index in a list ("coordinate 3"), if it is one of many.
        index: Option<usize>,
        /// The offending value.
        value: f64,
    },
    /// Not enough control points for the requested object: `BezierCurve::new(vec![p], None)`.
    TooFewPoints {
        /// Minimum number of points needed.
        needed: usize,
        /// Number of points given.
        got: usize,
        /// What needs them ("a Bézier curve").
        what: &'static str,
    },
    /// Wrong number of weights: `BezierCurve::new(two_points, Some(&[1.0]))`.
    WeightCount {
        /// Number of control points (= number of weights expected).
        expected: usize,
        /// Number of weights given.
        got: usize,
    },
    /// A weight is zero or negative: `BezierCurve::new(two_points, Some(&[1.0, 0.0]))`.
    NonPositiveWeight {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A parameter lies outside the curve's domain: `bezier.evaluate(1.5)`.
    ParameterOutOfRange {
        /// Name of the parameter ("t", "u").
        name: &'static str,
        /// The value given.
        value: f64,
        /// Start of the domain.
        min: f64,
        /// End of the domain.
        max: f64,
    },
    /// A control point index is out of range: `cubic.set_control_point(5, p)`.
    IndexOutOfRange {
        /// The index given.
        index: usize,
        /// Number of control points.
        count: usize,
    },
    /// A point argument has the wrong number of coordinates: `curve2d.setControlPoint(0, [1, 2, 3])`
    /// from JavaScript.
    PointDimension {
        /// Expected number of coordinates.
        expected: usize,
        /// Number given.
        got: usize,
    },
    /// A tolerance is not a finite number > 0: `curve.flatten(0.0)`.
    InvalidTolerance {
        /// The tolerance given.
        value: f64,
    },
    /// A flattening tolerance below rounding at the curve's size: `curve.flatten(1e-20)` on a
    /// curve of size 10.
    ToleranceTooSmall {
        /// The tolerance given.
        value: f64,
        /// The smallest tolerance allowed, relative to the size (`BezierCurve::flatten`'s
        /// `MIN_RELATIVE_TOLERANCE`).
        relative: f64,
        /// The diagonal of the control points' bounding box.
        size: f64,
    },
    /// Flattening found no piece flat enough within the tolerance before the parameter step
    /// reached rounding: a guard that keeps `flatten` from looping; no input is known to reach
    /// it, because [`Error::ToleranceTooSmall`] rejects such tolerances first.
    FlatteningStalled {
        /// The tolerance given.
        value: f64,
    },
    /// An interval `[a, b]` is empty or reversed: `curve.with_interval(2.0, 1.0)`.
    InvalidInterval {
        /// Start.
        a: f64,
        /// End.
        b: f64,
    },
    /// An argument that must be one of a few words was something else: `KnotKind::parse("even")`.
    UnknownOption {
        /// Argument name.
        name: &'static str,
        /// The value given.
        value: String,
        /// The accepted values.
        expected: &'static str,
    },
    /// Wraps an error raised while reading a named argument (`knotsU`, `us[3]`), so the message
    /// says which one: `BSplineSurface::from_flat(…, knots_u = &[0.0, 1.0], …)` gives
    /// "knotsU: knot vector must have …". [`std::error::Error::source`] returns the cause.
    InArgument {
        /// The argument's name ("knotsU", "degreeU (rows along u)", "us").
        name: &'static str,
        /// The element of the argument, when the argument is a list (`us[3]`).
        index: Option<usize>,
        /// What went wrong with it.
        #[cfg_attr(
            all(target_arch = "wasm32", target_os = "unknown"),
            serde(serialize_with = "crate::error::serialize::coded")
        )]
        source: Box<Error>,
    },
    /// A knot vector of the wrong length: `KnotVector::new(vec![0.0; 8], 3, 5)` (5 points of
    /// degree 3 need n+p+2 = 9 knots).
    KnotCount {
        /// `n + p + 2`.
        expected: usize,
        /// Number of knots given.
        got: usize,
        /// Number of control points `n + 1`.
        points: usize,
        /// The degree `p`.
        degree: usize,
    },
    /// Knots that decrease: `KnotVector::new(vec![0.0, 0.0, 2.0, 1.0], 1, 2)`.
    KnotOrder {
        /// Index `i` of the first knot smaller than its predecessor.
        index: usize,
        /// `u_i`.
        value: f64,
        /// `u_{i−1}`.
        previous: f64,
    },
    /// An empty domain `[u_p, u_{n+1}]`: `KnotVector::new(vec![0.0, 1.0, 1.0, 2.0], 1, 2)`.
    EmptyDomain {
        /// `u_p`.
        a: f64,
        /// `u_{n+1}`.
        b: f64,
        /// The degree `p`.
        degree: usize,
        /// Number of control points `n + 1` (the index of `u_{n+1}`).
        points: usize,
    },
    /// A knot repeated more than `p + 1` times:
    /// `KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0], 1, 3)`.
    KnotMultiplicity {
        /// The repeated knot.
        knot: f64,
        /// How many times it appears.
        multiplicity: usize,
        /// Index of its first copy.
        first: usize,
        /// Index of its last copy.
        last: usize,
        /// The degree `p`.
        degree: usize,
    },
    /// Knot insertion past multiplicity `p + 1`: `curve.insert_knot(u, 5)` on a cubic.
    InsertionMultiplicity {
        /// The parameter's name for a surface (`"u"`, `"v"`), `None` for a curve.
        name: Option<&'static str>,
        /// The knot inserted.
        knot: f64,
        /// How many copies were asked for.
        times: usize,
        /// The multiplicity it would reach.
        multiplicity: usize,
        /// The degree `p`.
        degree: usize,
    },
    /// Degree 0 where a curve needs at least 1: `BSplineCurve::new(points, 0, …)`.
    DegreeZero {},
    /// A degree outside `1..=max`: `uniformSegmentMatrix(0)` from JavaScript.
    DegreeOutOfRange {
        /// The degree given.
        degree: usize,
        /// The largest degree allowed.
        max: usize,
    },
    /// Fewer than `p + 1` control points: `BSplineCurve::new(three_points, 3, …)`.
    TooFewPointsForDegree {
        /// The degree `p`.
        degree: usize,
        /// Number of control points given.
        got: usize,
    },
    /// Two consecutive points coincide, so chord or centripetal spacing has a zero step:
    /// `parameterize(&[p, p, q], Parameterization::Chord)`.
    CoincidentPoints {
        /// Index `i` of the first of the two points `P_i = P_{i+1}`.
        index: usize,
        /// The spacing asked for.
        #[cfg_attr(
            all(target_arch = "wasm32", target_os = "unknown"),
            serde(serialize_with = "crate::error::serialize::alpha")
        )]
        kind: crate::bspline::Parameterization,
    },
    /// Phantom end points need an odd degree: `phantom_points(&points, 2)`.
    PhantomEvenDegree {
        /// The degree given.
        degree: usize,
    },
    /// A span index that is not a non-empty span of the domain: `curve.segment_matrix(0, true)`
    /// on a clamped cubic (whose first span is 3).
    NotASpan {
        /// The span asked for.
        span: usize,
        /// The non-empty spans of the domain.
        valid: Vec<usize>,
    },
    /// Joining rules are for polynomial pieces: `join(&rational, &right, JoinRule::C1, true)`.
    RationalJoin {},
    /// Pieces of too low degree for a joining rule: `join(&line, &line, JoinRule::C2, true)`.
    JoinDegree {
        /// The rule.
        #[cfg_attr(
            all(target_arch = "wasm32", target_os = "unknown"),
            serde(serialize_with = "crate::error::serialize::debug")
        )]
        rule: crate::bezier::JoinRule,
        /// Degree `n` of the left piece.
        left: usize,
        /// Degree `m` of the right piece.
        right: usize,
        /// The degree each piece needs (= points of the right piece the rule fixes).
        needed: usize,
    },
    /// G1 needs a tangent at the joint: `join(&left, &right, JoinRule::G1, true)` where the left
    /// piece's last two points coincide.
    NoJointTangent {},
    /// A composite curve with a wrong number of breakpoints:
    /// `CompositeCurve::new(two_pieces, &[0.0, 1.0])`.
    BreakpointCount {
        /// Number of pieces (the breakpoints needed are one more).
        pieces: usize,
        /// Number of breakpoints given.
        got: usize,
    },
    /// A line given by one point twice: `curve.intersect_line(p, p, 1e-9)`.
    DegenerateLine {
        /// x of the repeated point.
        x: f64,
        /// y of the repeated point.
        y: f64,
    },
    /// Flat coordinates that do not split into whole curves of the degree:
    /// `arc_lengths::<DVec2>(&[0.0; 10], 3, None)`.
    CurveBatchLength {
        /// Number of coordinates given.
        count: usize,
        /// The degree of every curve.
        degree: usize,
        /// `(degree + 1)·dim`, the numbers per curve.
        per_curve: usize,
    },
    /// A rational curve has no hodograph of the same form: `rational_curve.hodograph()`.
    RationalHodograph {},
    /// A projective map sends a control point to weight ≤ 0: `projective_map_bezier(&curve, &m)`
    /// with a map whose horizon crosses the control polygon.
    MappedWeight {
        /// The control point's index.
        index: usize,
        /// The weight it is sent to.
        weight: f64,
    },
    /// A singular projective map: `projective_map_bezier(&curve, &DMat3::ZERO)`.
    SingularMap {},
    /// A projective map from JavaScript that is not 9 numbers: `curve.projectiveMap([1, 0, 0])`.
    MatrixSize {
        /// Number of entries given.
        got: usize,
    },
    /// A circular arc from a degenerate triangle:
    /// `circle_arc_from_triangle(p, p, q)` (coincident or collinear points).
    DegenerateTriangle {},
    /// A circular arc from a triangle whose legs differ: `circle_arc_from_triangle(a, b, c)`
    /// with `|P0P1| ≠ |P1P2|`.
    NotIsosceles {
        /// `|P0P1|`.
        first: f64,
        /// `|P1P2|`.
        second: f64,
    },
    /// A circular arc from JavaScript with other than 3 points: `circularArcBezier([0, 0, 1, 1])`.
    ArcPointCount {
        /// Number of points given.
        got: usize,
    },
    /// An ellipse arc with a zero sweep or more than one turn: `ellipse_arc(c, x, y, 0.0, 0.0)`.
    InvalidSweep {
        /// The sweep given (radians).
        sweep: f64,
    },
    /// An ellipse whose axes are parallel or zero: `ellipse_arc(c, x, x, 0.0, 1.0)`.
    ParallelAxes {},
    /// Center and axes of different lengths from JavaScript:
    /// `ellipseArc([0, 0], [1, 0, 0], [0, 1], 0, 1)`.
    AxisLengths {
        /// Length of `center`.
        center: usize,
        /// Length of `axisX`.
        axis_x: usize,
        /// Length of `axisY`.
        axis_y: usize,
    },
    /// A radius that must be > 0 is not: `rational::circular_arc(center, 0.0, 0.0, 1.0)`.
    NotPositive {
        /// What the number is ("radius").
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// Two pieces of different dimensions: `joinBezier(curve2d, curve3d, "C1")` from JavaScript.
    DimensionMismatch {
        /// Dimension of the left piece.
        left: usize,
        /// Dimension of the right piece.
        right: usize,
    },
    /// Piece degrees that do not add up to the control points given:
    /// `compositeBezier([0, 0, 1, 1], [3], …)` from JavaScript.
    PiecePointCount {
        /// The degree of each piece.
        degrees: Vec<usize>,
        /// Control points the degrees need, `Σ (n_i + 1)`.
        needed: usize,
        /// Control points given.
        got: usize,
    },
    /// An output buffer of the wrong length: `curve.sample_into(&[0.5], &mut [0.0; 3])` for a
    /// 2D curve.
    BufferLength {
        /// Length of the buffer.
        len: usize,
        /// Number of points to write.
        count: usize,
        /// Numbers they need (`count · dim`).
        needed: usize,
    },
    /// Surface coordinates that do not fill the net: `BSplineSurface::from_flat(&[0.0; 10], 2, 2, …)`.
    NetCoordinateCount {
        /// Rows of the net.
        rows: usize,
        /// Columns of the net.
        cols: usize,
        /// Number of coordinates given.
        got: usize,
    },
    /// A Bézier patch with a single row or column: `BSplineSurface::bezier(&coords, 1, 3, None)`.
    PatchTooSmall {
        /// Rows given.
        rows: usize,
        /// Columns given.
        cols: usize,
    },
    /// A control point `(i, j)` outside the net: `surface.set_control_point(5, 0, p)` on a 4 × 4
    /// net.
    NetIndexOutOfRange {
        /// Row index.
        i: usize,
        /// Column index.
        j: usize,
        /// Rows of the net.
        rows: usize,
        /// Columns of the net.
        cols: usize,
    },
    /// No surface normal at `(u, v)`, even in the limit: `surface.normal(u, v)` on a patch whose
    /// rows all coincide.
    NoNormal {
        /// u.
        u: f64,
        /// v.
        v: f64,
    },
    /// A tessellation with no quads one way: `surface.tessellate(0, 4)`.
    EmptyTessellation {
        /// Quads along u.
        nu: usize,
        /// Quads along v.
        nv: usize,
    },
    /// A count (samples, degree, segments) exceeds a documented cap: `BSplineCurve::new(points,
    /// MAX_DEGREE + 1, …)`.
    TooLarge {
        /// What is too large.
        what: &'static str,
        /// The value asked for.
        value: usize,
        /// The cap.
        max: usize,
    },
    /// A result would take more than [`crate::geom::MAX_RESULT_BYTES`] bytes (or its size
    /// overflows): `surface.sample_grid(&us, &vs)` with 5000 values each (5000 × 5000 × 3
    /// numbers, 600 MB).
    ResultTooLarge {
        /// What the result is and what its counts are ("sampleGrid: us.length × vs.length ×
        /// 3 coordinates").
        what: &'static str,
        /// The counts asked for, multiplied together to give the number of values.
        counts: Vec<usize>,
        /// Bytes per value (8 for `f64`, 4 for `f32` and `u32`).
        value_bytes: usize,
        /// The cap in bytes.
        max_bytes: usize,
    },
    /// An argument from JavaScript has the wrong type: `null` or `undefined` for an array, a
    /// number for a string (`new BezierCurve(null, 2)`).
    ArgumentType {
        /// The argument's name ("points", "kind").
        name: &'static str,
        /// What it must be ("a string").
        expected: &'static str,
        /// What it is ("null or undefined", "number").
        got: String,
    },
    /// A count, index, degree, order or dimension given from JavaScript is not a whole number
    /// from 0 to `u32::MAX` (2.5, −1, NaN, a missing argument): `new BezierCurve(points, 2.5)`.
    NotWholeNumber {
        /// What the number is: an argument's name ("count", "i", "degrees").
        what: &'static str,
        /// Its index when the argument is a list ("degrees" 1).
        index: Option<usize>,
        /// The value given.
        value: f64,
    },
    /// An operation needs a 2D curve: `curve3d.intersectLine(0, 0, 1, 0, 1e-9)` from JavaScript.
    Needs2D {
        /// The operation.
        operation: &'static str,
        /// The curve's dimension.
        dim: usize,
    },
    /// An operation needs a 3D curve (surfaces are 3D): `surface::revolve(&curve_2d, …)`.
    Needs3D {
        /// The operation.
        operation: &'static str,
        /// The curve's dimension.
        dim: usize,
    },
    /// A direction that must not be the zero vector is: `surface::revolve(&c, o, DVec3::ZERO, τ)`.
    ZeroDirection {
        /// The argument's name ("axisDirection").
        name: &'static str,
    },
    /// An operation defined for polynomial patches only was asked of a rational one:
    /// `matrix_form()` on a patch with weights.
    NeedsPolynomial {
        /// The operation ("matrixForm").
        operation: &'static str,
    },
    /// Every weight is 0, so the denominator `Σ w_i B_i` vanishes for all parameters (only
    /// reachable where weights of any sign are allowed):
    /// `rational_poles(&[0.0, 0.0, 1.0, 1.0, 2.0, 0.0], 2, &[0.0, 0.0, 0.0], 8)`.
    AllWeightsZero {
        /// Number of weights.
        count: usize,
    },
    /// Interpolation parameters and data points of different counts:
    /// `interp::lagrange(&three_points, &[0.0, 1.0])`.
    ParamCount {
        /// Number of parameters given.
        params: usize,
        /// Number of data points.
        points: usize,
    },
    /// Interpolation parameters that do not strictly increase (`t_i ≤ t_{i−1}`):
    /// `interp::lagrange(&points, &[0.0, 1.0, 1.0])`.
    ParamsNotIncreasing {
        /// Index `i` of the first parameter not above its predecessor.
        index: usize,
        /// `t_i`.
        value: f64,
        /// `t_{i−1}`.
        previous: f64,
    },
    /// An argument the chosen option needs was not given: a clamped cubic spline without its
    /// end tangents.
    MissingArgument {
        /// The missing argument ("startTangent").
        name: &'static str,
        /// What needs it ("the \"clamped\" end condition").
        needed_by: &'static str,
    },
    /// An array argument of the wrong length: tangents for 4 points of dim 2 need 8 numbers.
    ArgumentLength {
        /// The argument's name ("tangents", "startDerivative").
        name: &'static str,
        /// The length it must have.
        expected: usize,
        /// The length given.
        got: usize,
    },
    /// Periodic interpolation needs the last data point equal to the first (as scipy's
    /// `CubicSpline(bc_type="periodic")`).
    NotClosed {
        /// Index of the last point.
        last: usize,
    },
    /// The exponent α of a parametrisation `|Δp|^α` or of Catmull–Rom outside `[0, 1]`.
    AlphaOutOfRange {
        /// The value given.
        value: f64,
    },
    /// A least-squares fit asked for a number of control points outside
    /// `[degree + 1, number of data points]`.
    ControlCountOutOfRange {
        /// The count asked for.
        count: usize,
        /// The smallest count allowed (`p + 1`).
        min: usize,
        /// The largest count allowed (the number of data points).
        max: usize,
    },
    /// Explicit knots that break the Schoenberg–Whitney condition, so the interpolation system
    /// is singular: parameter `t_index` must lie where basis function `N_{index,p}` is non-zero,
    /// `u_index < t_index < u_{index+p+1}` (or equal at a clamped end).
    SchoenbergWhitney {
        /// Index of the parameter (and of the basis function).
        index: usize,
        /// The parameter `t_index`.
        param: f64,
        /// `u_index`.
        lo: f64,
        /// `u_{index+p+1}`.
        hi: f64,
        /// The degree `p`.
        degree: usize,
    },
    /// Too few data points for an interpolation or approximation: `interp::lagrange(&[p], &[0.0])`.
    TooFewDataPoints {
        /// Minimum number of data points needed.
        needed: usize,
        /// Number of data points given.
        got: usize,
        /// What needs them ("a cubic spline", "a degree-3 interpolating B-spline").
        what: &'static str,
    },
    /// A linear system met a zero pivot: its matrix is singular (or too close to it).
    SingularSystem {
        /// Which system ("the cubic spline's tangent system").
        what: &'static str,
        /// The row where elimination stopped.
        row: usize,
    },
    /// An operation that only splines of one construction support: `setTangent` on a spline
    /// whose tangents are computed (`cubicSpline`, `catmullRom`, …), or `system()` on one that
    /// solved no system.
    SplineKind {
        /// The operation ("setTangent").
        operation: &'static str,
        /// The construction that supports it ("hermiteSpline").
        needs: &'static str,
        /// The construction of this spline ("cubicSpline").
        got: &'static str,
    },
    /// Two options that exclude each other were both given: `closed` with `startDerivative`
    /// (a closed curve has no ends) in `interp::interpolate_bspline`.
    ConflictingOptions {
        /// The first option.
        first: &'static str,
        /// The option it cannot be combined with.
        second: &'static str,
        /// Why ("a closed curve has no ends").
        reason: &'static str,
    },
    /// A least-squares fit whose ends are interpolated needs clamped knots: the first `p + 1`
    /// knots equal to `t_0` and the last `p + 1` equal to `t_m`
    /// (`interp::approximate_bspline` with explicit knots `0 0 1 2 …` for degree 2).
    KnotsNotClamped {
        /// `"first"` or `"last"`.
        end: &'static str,
        /// The end parameter the knots must equal (`t_0` or `t_m`).
        param: f64,
        /// The degree `p`.
        degree: usize,
    },
    /// A typed expression of a parametric curve (`x`, `y`, `z`, `from`, `to`, a parameter) is
    /// not usable: `sl.parametricCurve([{ x: "sin t", … }])`. Its code is the problem's own
    /// ([`crate::expr::Problem::code`]: `"unknown-name"`, `"function-needs-parentheses"` …) and
    /// its params are `piece`, `field`, `start`, `end` (the characters to underline, UTF-16
    /// units) with the problem's fields.
    Expression {
        /// Where and what.
        #[cfg_attr(all(target_arch = "wasm32", target_os = "unknown"), serde(flatten))]
        error: Box<crate::expr::ExprError>,
    },
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::InArgument { source, .. } => Some(source.as_ref()),
            _ => None,
        }
    }
}

/// Shorthand for results in this crate.
pub type Result<T> = std::result::Result<T, Error>;
