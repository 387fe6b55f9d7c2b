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
            Error::RationalJoin { .. } => "rational-join",
            Error::JoinDegree { .. } => "join-degree",
            Error::NoJointTangent { .. } => "no-joint-tangent",
            Error::BreakpointCount { .. } => "breakpoint-count",
            Error::DegenerateLine { .. } => "degenerate-line",
            Error::CurveBatchLength { .. } => "curve-batch-length",
            Error::RationalHodograph { .. } => "rational-hodograph",
            Error::MappedWeight { .. } => "mapped-weight",
            Error::SingularMap { .. } => "singular-map",
            Error::MatrixSize { .. } => "matrix-size",
            Error::DegenerateTriangle { .. } => "degenerate-triangle",
            Error::NotIsosceles { .. } => "not-isosceles",
            Error::ArcPointCount { .. } => "arc-point-count",
            Error::InvalidSweep { .. } => "invalid-sweep",
            Error::ParallelAxes { .. } => "parallel-axes",
            Error::AxisLengths { .. } => "axis-lengths",
            Error::NotPositive { .. } => "not-positive",
            Error::DimensionMismatch { .. } => "dimension-mismatch",
            Error::PiecePointCount { .. } => "piece-point-count",
            Error::BufferLength { .. } => "buffer-length",
            Error::NetCoordinateCount { .. } => "net-coordinate-count",
            Error::PatchTooSmall { .. } => "patch-too-small",
            Error::NetIndexOutOfRange { .. } => "net-index-out-of-range",
            Error::NoNormal { .. } => "no-normal",
            Error::EmptyTessellation { .. } => "empty-tessellation",
            Error::TooLarge { .. } => "too-large",
            Error::ArgumentType { .. } => "argument-type",
            Error::NotWholeNumber { .. } => "not-whole-number",
            Error::Needs2D { .. } => "needs-2d",
        }
    }
}
