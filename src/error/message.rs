//! The English message of every variant: it speaks to a student and carries the numbers.

use super::phrase::phrase;
use super::Error;
use std::fmt;

/// A number inside an error message, printed as JavaScript's `String(x)` prints it
/// (`Infinity`, `1e-7`, `0.1`) on every target (see [`crate::platform::number_text`]), so a
/// message is the same natively and in the browser. In the wasm build this also keeps Rust's
/// float-printing code (~20 KB) out of the module.
#[derive(Clone, Copy, Debug)]
pub(super) struct Num(pub(super) f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&crate::platform::number_text(self.0))
    }
}

/// A subject ([`super::phrase`]) in English, with its index when it is one of a list:
/// "coordinate 3", "a Bézier curve", "t".
pub(super) struct Subject<'a>(pub(super) &'a str, pub(super) Option<usize>);

impl fmt::Display for Subject<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(phrase(self.0))?;
        match self.1 {
            Some(i) => write!(f, " {i}"),
            None => Ok(()),
        }
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
            Error::NotFinite { what, index, value } => {
                write!(
                    f,
                    "{} is {}; every number must be finite",
                    Subject(what, *index),
                    Num(*value)
                )
            }
            Error::CoordinateTooLarge {
                what,
                index,
                value,
                max,
            } => write!(
                f,
                "{} is {}; a coordinate must be at most {} in magnitude, so that derivatives and lengths stay finite",
                Subject(what, *index),
                Num(*value),
                Num(*max)
            ),
            Error::TooFewPoints { needed, got, what } => write!(
                f,
                "{} needs at least {needed} control point{}, got {got}",
                phrase(what),
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
            Error::InvalidTolerance { value } => write!(
                f,
                "tolerance {} is not usable: it must be a finite number > 0",
                Num(*value)
            ),
            Error::ToleranceTooSmall {
                value,
                relative,
                size,
            } => write!(
                f,
                "tolerance {} is not usable: it is below {} × the curve's size ({}); rounding would dominate",
                Num(*value),
                Num(*relative),
                Num(*size)
            ),
            Error::FlatteningStalled { value } => write!(
                f,
                "tolerance {} is not usable: no piece of the curve is flat enough at this precision",
                Num(*value)
            ),
            Error::InvalidInterval { a, b } => {
                write!(f, "interval [{}, {}] is empty; it needs a < b", Num(*a), Num(*b))
            }
            Error::UnknownOption {
                name,
                value,
                expected,
            } => write!(f, "{name} must be one of {expected}, got \"{value}\""),
            Error::InArgument {
                name,
                index,
                source,
            } => match index {
                Some(i) => write!(f, "{}[{i}]: {source}", phrase(name)),
                None => write!(f, "{}: {source}", phrase(name)),
            },
            Error::KnotCount {
                expected,
                got,
                points,
                degree,
            } => write!(
                f,
                "knot vector must have n+p+2 = {} + {degree} + 2 = {expected} values, got {got}",
                points.saturating_sub(1)
            ),
            Error::KnotOrder {
                index,
                value,
                previous,
            } => write!(
                f,
                "knots must not decrease: u_{index} = {} comes after u_{} = {}",
                Num(*value),
                index.saturating_sub(1),
                Num(*previous)
            ),
            Error::EmptyDomain {
                a,
                b,
                degree,
                points,
            } => write!(
                f,
                "the domain [u_p, u_(n+1)] = [u_{degree}, u_{points}] = [{}, {}] is empty; it needs u_{degree} < u_{points}",
                Num(*a),
                Num(*b)
            ),
            Error::KnotMultiplicity {
                knot,
                multiplicity,
                first,
                last,
                degree,
            } => write!(
                f,
                "knot {} appears {multiplicity} times (u_{first}..u_{last}); a degree-{degree} curve allows at most p+1 = {}",
                Num(*knot),
                degree + 1
            ),
            Error::InsertionMultiplicity {
                name,
                knot,
                times,
                multiplicity,
                degree,
            } => {
                f.write_str("inserting knot ")?;
                if let Some(name) = name {
                    write!(f, "{name} = ")?;
                }
                write!(
                    f,
                    "{} {times} time(s) would give it multiplicity {multiplicity}; degree {degree} allows at most p+1 = {}",
                    Num(*knot),
                    degree + 1
                )
            }
            Error::DegreeZero {} => f.write_str("degree must be at least 1, got 0"),
            Error::DegreeOutOfRange { degree, max } => {
                write!(f, "degree must be 1..={max}, got {degree}")
            }
            Error::TooFewPointsForDegree { degree, got } => write!(
                f,
                "degree {degree} needs at least p+1 = {} control points, got {got}",
                degree + 1
            ),
            Error::CoincidentPoints { index, kind } => write!(
                f,
                "points {index} and {} coincide; {kind} spacing needs distinct consecutive points",
                index + 1
            ),
            Error::PhantomEvenDegree { degree } => write!(
                f,
                "phantom points make a uniform B-spline of odd degree pass through its ends; degree {degree} is even"
            ),
            Error::NotASpan { span, valid } => write!(
                f,
                "span {span} is not a non-empty span of the domain (valid: {valid:?})"
            ),
            Error::DegenerateLine { x, y } => write!(
                f,
                "the line needs two different points, got ({}, {}) twice",
                Num(*x),
                Num(*y)
            ),
            Error::CurveBatchLength {
                count,
                degree,
                per_curve,
            } => write!(
                f,
                "{count} coordinates do not split into curves of degree {degree} ((degree + 1)·dim = {per_curve} numbers each)"
            ),
            Error::NotPositive { name, value } => {
                write!(f, "{} must be > 0, got {}", phrase(name), Num(*value))
            }
            Error::DimensionMismatch { left, right } => write!(
                f,
                "both pieces need the same dim, got {left} and {right}"
            ),
            Error::BufferLength { len, count, needed } => write!(
                f,
                "output buffer has {len} values, {count} points need {needed}"
            ),
            Error::TooLarge { what, value, max } => {
                write!(
                    f,
                    "{} = {value} is too large; at most {max} is allowed",
                    phrase(what)
                )
            }
            Error::ResultTooLarge {
                what,
                counts,
                value_bytes,
                max_bytes,
            } => {
                let counts: Vec<String> = counts.iter().map(usize::to_string).collect();
                // u128: up to three 32-bit counts and the value size cannot overflow it.
                let bytes = counts
                    .iter()
                    .filter_map(|c| c.parse::<u128>().ok())
                    .fold(*value_bytes as u128, |a, c| a.saturating_mul(c));
                write!(
                    f,
                    "{} = {} values of {value_bytes} bytes = {bytes} bytes is too large; one \
                     result may take at most {max_bytes} bytes ({} MiB)",
                    phrase(what),
                    counts.join(" × "),
                    max_bytes >> 20
                )
            }
            Error::ArgumentType {
                name,
                expected,
                got,
            } => write!(f, "{name} must be {}, got {got}", phrase(expected)),
            Error::NotWholeNumber { what, index, value } => write!(
                f,
                "{} must be a whole number from 0 to {}, got {}",
                Subject(what, *index),
                u32::MAX,
                Num(*value)
            ),
            Error::Needs2D { operation, dim } => {
                write!(f, "{operation} works on 2D curves; this curve has dim = {dim}")
            }
            Error::Needs3D { operation, dim } => write!(
                f,
                "{operation} builds a 3D surface and needs a 3D curve; this curve has dim = {dim}"
            ),
            Error::AllWeightsZero { count } => write!(
                f,
                "all {count} weights are 0: the denominator w(t) = Σ w_i B_i(t) is 0 for every t, so there is no curve"
            ),
            Error::MissingArgument { name, needed_by } => {
                write!(f, "{} needs {name}, which was not given", phrase(needed_by))
            }
            Error::ArgumentLength {
                name,
                expected,
                got,
            } => write!(f, "{name} must have {expected} numbers, got {got}"),
            Error::TooFewDataPoints { needed, got, what } => write!(
                f,
                "{} needs at least {needed} data point{}, got {got}",
                phrase(what),
                if *needed == 1 { "" } else { "s" }
            ),
            Error::StrokeFarFromCurve {
                start_distance,
                end_distance,
                near,
            } => write!(
                f,
                "the stroke starts {} and ends {} from the curve; to redraw a part, start and end it within {} of the curve (an open curve is also extended by a stroke that starts or ends there)",
                Num(*start_distance),
                Num(*end_distance),
                Num(*near)
            ),
            Error::SingularSystem { what, row } => write!(
                f,
                "{} is singular: elimination met a zero pivot in row {row}",
                phrase(what)
            ),
            Error::ConflictingOptions {
                first,
                second,
                reason,
            } => write!(
                f,
                "{first} cannot be combined with {second}: {}",
                phrase(reason)
            ),
            Error::Expression { error } => write!(f, "{error}"),
            Error::Conic(e) => e.fmt(f),
            Error::Join(e) => e.fmt(f),
            Error::Surface(e) => e.fmt(f),
            Error::Interp(e) => e.fmt(f),
        }
    }
}
