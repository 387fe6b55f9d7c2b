//! A stable code per variant, for matching and translation.

use super::Error;

impl Error {
    /// A stable kebab-case code naming the kind of failure (`"knot-count"`,
    /// `"parameter-out-of-range"`), one per variant: with the variant's fields it is all a
    /// translated message needs. [`Error::InArgument`] has its own code; its `source` has the
    /// cause's.
    pub fn code(&self) -> &'static str {
        match self {
            Error::InvalidDimension { .. } => "invalid-dimension",
            Error::CoordinateCount { .. } => "coordinate-count",
            Error::NotFinite { .. } => "not-finite",
            Error::CoordinateTooLarge { .. } => "coordinate-too-large",
            Error::TooFewPoints { .. } => "too-few-points",
            Error::WeightCount { .. } => "weight-count",
            Error::NonPositiveWeight { .. } => "non-positive-weight",
            Error::ParameterOutOfRange { .. } => "parameter-out-of-range",
            Error::IndexOutOfRange { .. } => "index-out-of-range",
            Error::PointDimension { .. } => "point-dimension",
            Error::InvalidTolerance { .. } => "invalid-tolerance",
            Error::ToleranceTooSmall { .. } => "tolerance-too-small",
            Error::FlatteningStalled { .. } => "flattening-stalled",
            Error::InvalidInterval { .. } => "invalid-interval",
            Error::UnknownOption { .. } => "unknown-option",
            Error::InArgument { .. } => "in-argument",
            Error::KnotCount { .. } => "knot-count",
            Error::KnotOrder { .. } => "knot-order",
            Error::EmptyDomain { .. } => "empty-domain",
            Error::KnotMultiplicity { .. } => "knot-multiplicity",
            Error::InsertionMultiplicity { .. } => "insertion-multiplicity",
            Error::DegreeZero { .. } => "degree-zero",
            Error::DegreeOutOfRange { .. } => "degree-out-of-range",
            Error::TooFewPointsForDegree { .. } => "too-few-points-for-degree",
            Error::CoincidentPoints { .. } => "coincident-points",
            Error::PhantomEvenDegree { .. } => "phantom-even-degree",
            Error::NotASpan { .. } => "not-a-span",
            Error::DegenerateLine { .. } => "degenerate-line",
            Error::CurveBatchLength { .. } => "curve-batch-length",
            Error::NotPositive { .. } => "not-positive",
            Error::DimensionMismatch { .. } => "dimension-mismatch",
            Error::BufferLength { .. } => "buffer-length",
            Error::TooLarge { .. } => "too-large",
            Error::ResultTooLarge { .. } => "result-too-large",
            Error::ArgumentType { .. } => "argument-type",
            Error::NotWholeNumber { .. } => "not-whole-number",
            Error::Needs2D { .. } => "needs-2d",
            Error::Needs3D { .. } => "needs-3d",
            Error::AllWeightsZero { .. } => "all-weights-zero",
            Error::MissingArgument { .. } => "missing-argument",
            Error::ArgumentLength { .. } => "argument-length",
            Error::TooFewDataPoints { .. } => "too-few-data-points",
            Error::StrokeFarFromCurve { .. } => "stroke-far-from-curve",
            Error::SingularSystem { .. } => "singular-system",
            Error::ConflictingOptions { .. } => "conflicting-options",
            // One code per problem of a typed expression (src/expr/error.rs).
            Error::Expression { error } => error.problem.code(),
            Error::Conic(e) => e.code(),
            Error::Join(e) => e.code(),
            Error::Surface(e) => e.code(),
            Error::Interp(e) => e.code(),
        }
    }
}
