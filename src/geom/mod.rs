//! Shared geometry: the point trait that lets one implementation of de Casteljau, de Boor and
//! knot insertion serve 2D, 3D and homogeneous (rational) points, plus flat-array conversion.
//!
//! One file per idea: [`point`] (the traits), [`bounding_box`], [`params`] (parameter lists),
//! [`check`] (shared input checks) and [`limits`] (the named caps).

pub mod bounding_box;
pub mod check;
pub mod limits;
pub mod params;
pub mod point;

pub use bounding_box::BoundingBox;
pub use check::{
    check_all_coordinates, check_all_finite, check_dim, check_flat, check_out_len,
    check_result_bytes, check_table_count, check_weights, check_work, points_from_flat, result_len,
};
pub use limits::{
    MAX_COORDINATE, MAX_DEGREE, MAX_DERIVATIVE_ORDER, MAX_RESULT_BYTES, MAX_SAMPLES,
    MAX_SAMPLE_WORK, STACK_DEGREE,
};
pub use params::Params;
pub use point::{curvature, rational_derivative, Cartesian, Point};

/// `(sin x, cos x)`: JavaScript's `Math.sin`/`Math.cos` in the browser build, [`f64::sin_cos`]
/// elsewhere (see [`crate::platform::sin_cos`]).
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    crate::platform::sin_cos(x)
}

/// Binomial coefficient `C(n, k)` as `f64` (exact for the degrees curves use).
pub fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    (0..k).fold(1.0, |c, j| c * (n - j) as f64 / (j + 1) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn binomial_matches_pascal() {
        assert_eq!(binomial(4, 2), 6.0);
        assert_eq!(binomial(10, 3), 120.0);
        assert_eq!(binomial(3, 4), 0.0);
        assert_eq!(binomial(0, 0), 1.0);
    }
}
