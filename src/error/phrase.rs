//! The phrases inside messages, by key. A field of an [`Error`](super::Error) that names what
//! went wrong (a *subject*: `TooFewPoints::what`, `TooLarge::what`, `NotFinite::what`,
//! `ArgumentType::expected`, …) holds either the name of an API argument or identifier
//! (`"degree"`, `"knotsU"`, `"t"`: shown as it is in every language, like the notation) or one
//! of the keys below. The English message shows the key's phrase; a translation looks the key
//! up in its own table (`coreError.subject.<key>` in www/lib/strings.js and the locales), so no
//! translation ever matches English text.

/// `(key, English phrase)` for every subject that is not an identifier, sorted by key.
pub const PHRASES: &[(&str, &str)] = &[
    ("adaptive-depth", "adaptive subdivision depth (the tolerance is near rounding)"),
    ("adaptive-vertices", "adaptive mesh vertices"),
    ("adaptive-vertices-leaves", "adaptive mesh vertices (at least one per leaf)"),
    ("adaptive-vertices-patches", "adaptive mesh vertices (at least one per Bézier patch)"),
    ("basis-sample-count", "count (samples per basis function: one value per function each)"),
    ("bessel-spline", "a Bessel spline"),
    ("bezier-curve", "a Bézier curve"),
    ("boolean", "a boolean"),
    ("bspline-interpolation-system", "the B-spline interpolation system"),
    ("cardinal-spline", "a cardinal spline"),
    ("catmull-rom-spline", "a Catmull–Rom spline"),
    ("clamped-end-condition", "the \"clamped\" end condition"),
    ("closed-has-no-ends", "a closed curve has no ends"),
    ("closed-interpolating-bspline", "a closed interpolating B-spline of this degree (p + 1, at least 3)"),
    ("closed-knots-computed", "a closed curve's knots are the periodic ones computed from the params"),
    ("composite-curve", "a composite curve (pieces)"),
    ("coordinate", "coordinate"),
    ("cubic-spline", "a cubic spline"),
    ("cubic-spline-system", "the cubic spline's tangent system"),
    ("curvature-work", "curvature points for this degree (work budget 2^28)"),
    ("curve", "a BSplineCurve or BezierCurve"),
    ("data-point-count", "number of data points"),
    ("degree-u-rows", "degreeU (rows along u)"),
    ("degree-v-columns", "degreeV (columns along v)"),
    ("derivative-order", "derivative order"),
    ("every-piece", "every piece (degree >= 1)"),
    ("flattening-segments", "number of flattening segments"),
    ("flattening-segments-estimated", "number of flattening segments (estimated before flattening: lower the degree or raise the tolerance)"),
    ("grid-points", "grid points us.length·vs.length"),
    ("hermite-spline", "a Hermite spline"),
    ("interpolating-bspline", "an interpolating B-spline of this degree (p + 1 − end derivatives, at least 2)"),
    ("interpolating-surface", "an interpolating surface of this degree (degree + 1 per direction)"),
    ("interpolation-system-size", "the interpolation system's size (unknowns)"),
    ("knot", "knot"),
    ("knot-to-insert", "knot to insert"),
    ("lagrange-curve", "a Lagrange curve"),
    ("lagrange-point-count", "number of points of a Lagrange curve"),
    ("least-squares-bspline", "a least-squares B-spline of this degree (p + 1, at least 2)"),
    ("least-squares-system", "the least-squares normal equations"),
    ("length", "its length"),
    ("matrix-entry", "matrix entry"),
    ("new-point-coordinate", "the new point's coordinate"),
    ("numbers", "an array of numbers (Float64Array or number[])"),
    ("object", "an object"),
    ("parameter", "parameter"),
    ("parametrisation", "a parametrisation"),
    ("phantom-points", "phantom points of this degree"),
    ("polynomial", "a polynomial"),
    ("rational-bezier-curve", "a rational Bézier curve"),
    ("rational-derivative-order", "derivative order of a rational curve"),
    ("refine-result", "refine: (control points + us.length) × homogeneous coordinates"),
    ("sample-count", "sample count"),
    ("sample-derivatives-result", "sampleDerivatives: us.length × coordinates"),
    ("sample-grid-result", "sampleGrid: us.length × vs.length × 3 coordinates"),
    ("sample-params-result", "sample: params.length × coordinates"),
    ("sample-ts-result", "sample: ts.length × coordinates"),
    ("sample-uniform-result", "sampleUniform: count × coordinates"),
    ("sample-uniform-view-result", "sampleUniformView: count × coordinates"),
    ("sample-view-result", "sampleView: params.length × coordinates"),
    ("sample-work", "sample count for this degree (work budget 2^28)"),
    ("samples-result", "samples (points × coordinates)"),
    ("start-angle", "start angle"),
    ("string", "a string"),
    ("stroke", "a stroke"),
    ("surface-derivative-order", "derivative order du + dv"),
    ("tessellation-vertices", "tessellation vertices (nu + 1)(nv + 1)"),
    ("tessellation-work", "tessellation vertices (nu + 1)(nv + 1) for this degree (work budget 2^28)"),
    ("weight", "weight"),
];

/// The English phrase of `subject`: its entry in [`PHRASES`], or the subject itself (an
/// identifier such as `"degree"` or `"knotsU"`).
pub fn phrase(subject: &str) -> &str {
    PHRASES
        .iter()
        .find(|(key, _)| *key == subject)
        .map_or(subject, |(_, english)| english)
}
