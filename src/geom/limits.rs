//! The named caps on user-controlled sizes: degrees, derivative orders, sample counts.

/// Highest degree accepted by the curve constructors: de Casteljau and de Boor cost O(p²) per
/// point and such degrees are of no practical use (the syllabus recommends piecewise curves
/// above ~5).
pub const MAX_DEGREE: usize = 64;

/// Largest magnitude of a coordinate a curve or surface accepts (control points, data points, a
/// center or an axis, a tangent): `|x| ≤ 1e120`, else [`crate::Error::CoordinateTooLarge`].
///
/// Why a bound, and why this one: a derivative multiplies differences of control points,
/// `P^(k) = p!/(p−k)! Σ Δ^k P_i B_{i,p−k}` for a Bézier curve (de Boor's form divides by knot
/// spans `h` instead), so its size is up to `p!/(p−k)! · 2^k / h^k` times the largest coordinate,
/// and an arc length or a curvature squares a derivative (`|P′| = √(x′² + y′²)`). Squares
/// overflow above `√f64::MAX ≈ 1.34e154`, and a difference of two overflowed numbers is NaN (as
/// `derivative` and `arcLength` gave near `f64::MAX`). With coordinates up to `1e120`, a
/// derivative may grow by `1.3e34` before its square overflows: for degree 20, a first
/// derivative on knot spans down to `4e−33` (`2p/h`), a second one on spans down to `4e−16`
/// (`4p(p−1)/h²`), a third on spans down to `4e−10`; unsquared, every derivative of every order of
/// a degree-20 Bézier curve (`20! · 2^20 ≈ 2.5e24` times the coordinates) stays below `3e144`. No
/// drawing needs coordinates near the bound: it only turns overflow into a coded error.
pub const MAX_COORDINATE: f64 = 1e120;

/// Highest derivative order accepted for rational curves (whose derivatives never vanish);
/// polynomial curves accept any order (zero above the degree).
pub const MAX_DERIVATIVE_ORDER: usize = 32;

/// Degrees (and derivative orders) up to this evaluate one point in stack arrays of
/// `STACK_DEGREE + 1` entries: `evaluate(t)` and `derivative(t, order)` allocate nothing, which
/// is most of their cost per call. Above it the same formulas run on heap buffers.
pub const STACK_DEGREE: usize = 7;

/// Largest number of samples one dense call may produce (2^22: 64 MiB for a 2D curve, about
/// 0.2 s for a cubic B-spline in wasm; 2^24 points of a curve took 2–4 s, mostly memory).
pub const MAX_SAMPLES: usize = 1 << 22;

/// The work budget of one dense call, in units of about one multiply-add on a point (1–2.5 ns
/// in wasm): `count · units per item ≤ MAX_SAMPLE_WORK`, the units priced by the degree.
/// - curve points (`sample`, `sampleUniform`, their views): `(p + 1)²` (de Boor's basis, de
///   Casteljau above the Horner degree). Degrees up to 7 meet [`MAX_SAMPLES`] first; a
///   degree-64 curve gets 63 535 points (0.3–0.5 s) where 2^22 took 19 s.
/// - `sampleDerivatives` of order `k`: `(p + 1)²·(k' + 1) + 16(k' + 1)² + 64` with
///   `k' = min(k, p)`, `k' = k` when rational (`k + 1` basis rows, the quotient rule).
/// - surface mesh vertices (`tessellate`): `2(p + 1)(q + 1) + 128` (a point and two partials
///   from the basis computed once per row and column).
/// - surface curvatures: `8((p + 1)(q + 1) + (p + 1)² + (q + 1)² + 32)` (the basis and two
///   derivatives per direction at every point, five partials).
///
/// Every call within it took at most about 0.6 s in Node on the development machine; a
/// degree-(64, 64) surface's `curvatures` of 100 000 points had taken 6.7 s.
pub const MAX_SAMPLE_WORK: usize = 1 << 28;

/// Largest result one call may allocate, in bytes (256 MiB): every count from JavaScript
/// (points × coordinates, grid rows × columns × 3, mesh vertices × 8 numbers…) is multiplied
/// with `checked_mul` and refused above this before anything is allocated
/// ([`crate::Error::ResultTooLarge`]), so a page gets an `Error` instead of a wasm abort
/// when the memory runs out (a wasm32 memory holds 4 GiB at most).
pub const MAX_RESULT_BYTES: usize = 256 << 20;
