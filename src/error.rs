//! The crate's one error type. Every message speaks to a student and carries the numbers.

use std::fmt;

/// Everything that can go wrong when building or querying a curve.
///
/// Constructors validate their input in a fixed order — dimension, coordinate count, finite
/// numbers, number of points against the degree, knots, weights — so the first problem found
/// is always the same one for the same input.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// `dim` is not 2 or 3: `BezierCurve::from_flat(&[0.0; 4], 4, None)`.
    InvalidDimension {
        /// The dimension that was given.
        dim: usize,
    },
    /// The flat coordinate array does not split into whole points.
    CoordinateCount {
        /// Number of coordinates given.
        count: usize,
        /// Dimension of one point.
        dim: usize,
    },
    /// A coordinate, weight, parameter or tolerance is NaN or infinite.
    NotFinite {
        /// What the number is ("coordinate 3", "t", "weight 1").
        what: String,
        /// The offending value.
        value: f64,
    },
    /// Not enough control points for the requested object.
    TooFewPoints {
        /// Minimum number of points needed.
        needed: usize,
        /// Number of points given.
        got: usize,
        /// What needs them ("a Bézier curve").
        what: &'static str,
    },
    /// Wrong number of weights.
    WeightCount {
        /// Number of control points (= number of weights expected).
        expected: usize,
        /// Number of weights given.
        got: usize,
    },
    /// A weight is zero or negative.
    NonPositiveWeight {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A parameter lies outside the curve's domain.
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
    /// A control point index is out of range.
    IndexOutOfRange {
        /// The index given.
        index: usize,
        /// Number of control points.
        count: usize,
    },
    /// A point argument has the wrong number of coordinates.
    PointDimension {
        /// Expected number of coordinates.
        expected: usize,
        /// Number given.
        got: usize,
    },
    /// A tolerance is not a positive finite number, or is too small to honour.
    InvalidTolerance {
        /// The tolerance given.
        value: f64,
        /// Why it was rejected.
        reason: String,
    },
    /// An interval `[a, b]` is empty or reversed.
    InvalidInterval {
        /// Start.
        a: f64,
        /// End.
        b: f64,
    },
    /// An argument that must be one of a few words was something else.
    UnknownOption {
        /// Argument name.
        name: &'static str,
        /// The value given.
        value: String,
        /// The accepted values.
        expected: &'static str,
    },
    /// Two objects that must match (dimension, joint) do not.
    Mismatch {
        /// What does not match, with numbers.
        message: String,
    },
    /// A count (samples, degree, segments) exceeds a documented cap.
    TooLarge {
        /// What is too large.
        what: &'static str,
        /// The value asked for.
        value: usize,
        /// The cap.
        max: usize,
    },
    /// An argument from JavaScript has the wrong type: `null` or `undefined` for an array, a
    /// number for a string.
    ArgumentType {
        /// The argument's name ("points", "kind").
        name: &'static str,
        /// What it must be ("a string").
        expected: &'static str,
        /// What it is ("null or undefined", "number").
        got: String,
    },
    /// A count, index, degree, order or dimension given from JavaScript is not a whole number
    /// from 0 to `u32::MAX` (2.5, −1, NaN, a missing argument).
    NotWholeNumber {
        /// What the number is ("count", "i", "degree 1").
        what: String,
        /// The value given.
        value: f64,
    },
    /// An operation needs a 2D curve.
    Needs2D {
        /// The operation.
        operation: &'static str,
        /// The curve's dimension.
        dim: usize,
    },
}

/// A number inside an error message, printed as JavaScript's `String(x)` prints it
/// (`Infinity`, `1e-7`, `0.1`) on every target (see [`crate::platform::number_text`]), so a
/// message is the same natively and in the browser. In the wasm build this also keeps Rust's
/// float-printing code (~20 KB) out of the module.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&crate::platform::number_text(self.0))
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidDimension { dim } => write!(f, "dim must be 2 or 3, got {dim}"),
            Error::CoordinateCount { count, dim } => write!(
                f,
                "coordinate count {count} is not a multiple of dim = {dim}; points are given as flat [x0, y0{}, x1, …]",
                if *dim == 3 { ", z0" } else { "" }
            ),
            Error::NotFinite { what, value } => {
                write!(f, "{what} is {}; every number must be finite", Num(*value))
            }
            Error::TooFewPoints { needed, got, what } => write!(
                f,
                "{what} needs at least {needed} control point{}, got {got}",
                if *needed == 1 { "" } else { "s" }
            ),
            Error::WeightCount { expected, got } => write!(
                f,
                "weights must have one value per control point ({expected}), got {got}"
            ),
            Error::NonPositiveWeight { index, value } => write!(
                f,
                "weight {index} is {}; weights must be > 0 (zero or negative weights can put poles on the curve)",
                Num(*value)
            ),
            Error::ParameterOutOfRange {
                name,
                value,
                min,
                max,
            } => write!(
                f,
                "{name} = {} is outside the domain [{}, {}]",
                Num(*value),
                Num(*min),
                Num(*max)
            ),
            Error::IndexOutOfRange { index, count } => write!(
                f,
                "control point index {index} is out of range: the curve has {count} points (0..={})",
                count.saturating_sub(1)
            ),
            Error::PointDimension { expected, got } => write!(
                f,
                "a point needs {expected} coordinates, got {got}"
            ),
            Error::InvalidTolerance { value, reason } => {
                write!(f, "tolerance {} is not usable: {reason}", Num(*value))
            }
            Error::InvalidInterval { a, b } => {
                write!(f, "interval [{}, {}] is empty; it needs a < b", Num(*a), Num(*b))
            }
            Error::UnknownOption {
                name,
                value,
                expected,
            } => write!(f, "{name} must be one of {expected}, got \"{value}\""),
            Error::Mismatch { message } => f.write_str(message),
            Error::TooLarge { what, value, max } => {
                write!(f, "{what} = {value} is too large; at most {max} is allowed")
            }
            Error::ArgumentType {
                name,
                expected,
                got,
            } => write!(f, "{name} must be {expected}, got {got}"),
            Error::NotWholeNumber { what, value } => write!(
                f,
                "{what} must be a whole number from 0 to {}, got {}",
                u32::MAX,
                Num(*value)
            ),
            Error::Needs2D { operation, dim } => {
                write!(f, "{operation} works on 2D curves; this curve has dim = {dim}")
            }
        }
    }
}

impl std::error::Error for Error {}

/// Shorthand for results in this crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that `value` is finite; `what` names it in the error.
pub(crate) fn check_finite(what: impl FnOnce() -> String, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite {
            what: what(),
            value,
        })
    }
}

/// Checks a tolerance: finite and > 0.
pub(crate) fn check_tolerance(value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidTolerance {
            value,
            reason: "it must be a finite number > 0".into(),
        })
    }
}
