//! The crate's one error type. Every message speaks to a student and carries the numbers.
//!
//! One variant per kind of failure, with the numbers as named fields: [`Error::code`] gives a
//! stable kebab-case code per variant (`code.rs`), `Display` the English message (`message.rs`),
//! so a translated message needs only the code and the fields. The failures of a few families
//! are enums of their own, nested in one variant each with their codes and messages beside them
//! ([`Error::Conic`] in `conic.rs`, [`Error::Join`] in `join.rs`, [`Error::Surface`] in
//! `surface.rs`, [`Error::Interp`] in `interp.rs`); a nested error's code and params are its
//! variant's, as if it were `Error`'s own.

mod check;
mod code;
mod conic;
mod interp;
mod join;
mod message;
mod phrase;
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
mod serialize;
mod surface;

pub use conic::ConicError;
pub use interp::InterpError;
pub use join::JoinError;
pub use surface::SurfaceError;

pub use phrase::{phrase, PHRASES};

pub(crate) use check::{
    check_coordinate, check_coordinate_of, check_finite, check_in_range, check_tolerance,
    in_argument,
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
    /// A coordinate is finite but larger in magnitude than [`crate::geom::MAX_COORDINATE`]
    /// (`1e120`), where derivatives and lengths would overflow:
    /// `BezierCurve::<DVec2>::from_flat(&[0.0, 1e200, 1.0, 1.0], None)`. Checked with finiteness,
    /// coordinate by coordinate.
    CoordinateTooLarge {
        /// What the number is: a subject (`phrase.rs`), "coordinate", "new-point-coordinate".
        what: &'static str,
        /// Its index in a list ("coordinate 3"), if it is one of many.
        index: Option<usize>,
        /// The offending value.
        value: f64,
        /// The largest magnitude allowed, [`crate::geom::MAX_COORDINATE`].
        max: f64,
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
    /// Joining pieces or building a composite curve failed: [`JoinError`].
    Join(JoinError),
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
    /// A rational or conic construction failed (projective maps, circular and elliptic arcs,
    /// rational hodographs): [`ConicError`].
    Conic(ConicError),
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
    /// A surface could not be built or queried: [`SurfaceError`].
    Surface(SurfaceError),
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
    /// Every weight is 0, so the denominator `Σ w_i B_i` vanishes for all parameters (only
    /// reachable where weights of any sign are allowed):
    /// `rational_poles(&[0.0, 0.0, 1.0, 1.0, 2.0, 0.0], 2, &[0.0, 0.0, 0.0], 8)`.
    AllWeightsZero {
        /// Number of weights.
        count: usize,
    },
    /// Interpolation or a least-squares fit refused its parameters: [`InterpError`].
    Interp(InterpError),
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
    /// Too few data points for an interpolation or approximation: `interp::lagrange(&[p], &[0.0])`.
    TooFewDataPoints {
        /// Minimum number of data points needed.
        needed: usize,
        /// Number of data points given.
        got: usize,
        /// What needs them ("a cubic spline", "a degree-3 interpolating B-spline").
        what: &'static str,
    },
    /// An oversketch stroke that neither starts nor ends near the curve (on a closed curve:
    /// not both), so nothing says which part it redraws: `fit::oversketch(&curve, &far, 0.5)`.
    StrokeFarFromCurve {
        /// Distance from the stroke's first sample to the curve.
        start_distance: f64,
        /// Distance from its last sample to the curve.
        end_distance: f64,
        /// How near an end must be.
        near: f64,
    },
    /// A linear system met a zero pivot: its matrix is singular (or too close to it).
    SingularSystem {
        /// Which system ("the cubic spline's tangent system").
        what: &'static str,
        /// The row where elimination stopped.
        row: usize,
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
