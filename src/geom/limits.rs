//! The named caps on user-controlled sizes: degrees, derivative orders, sample counts.

/// Highest degree accepted by the curve constructors: de Casteljau and de Boor cost O(p²) per
/// point and such degrees are of no practical use (the syllabus recommends piecewise curves
/// above ~5).
pub const MAX_DEGREE: usize = 64;

/// Highest derivative order accepted for rational curves (whose derivatives never vanish);
/// polynomial curves accept any order (zero above the degree).
pub const MAX_DERIVATIVE_ORDER: usize = 32;

/// Degrees (and derivative orders) up to this evaluate one point in stack arrays of
/// `STACK_DEGREE + 1` entries: `evaluate(t)` and `derivative(t, order)` allocate nothing, which
/// is most of their cost per call. Above it the same formulas run on heap buffers.
pub const STACK_DEGREE: usize = 7;

/// Largest number of samples one dense call may produce.
pub const MAX_SAMPLES: usize = 1 << 24;

/// Largest result one call may allocate, in bytes (256 MiB): every count from JavaScript
/// (points × coordinates, grid rows × columns × 3, mesh vertices × 8 numbers…) is multiplied
/// with `checked_mul` and refused above this before anything is allocated
/// ([`crate::Error::ResultTooLarge`]), so a page gets an `Error` instead of a wasm abort
/// when the memory runs out (a wasm32 memory holds 4 GiB at most).
pub const MAX_RESULT_BYTES: usize = 256 << 20;
