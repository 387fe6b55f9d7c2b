//! Bézier curves, polynomial and rational, in 2D and 3D (syllabus §1–2, rational form §4).
//!
//! A Bézier curve of degree `n` with control points `P_0..P_n` on the interval `[a, b]` is
//! `P(t) = Σ B_i^n(s) P_i` with the local parameter `s = (t − a)/(b − a)` and the Bernstein
//! polynomials `B_i^n(s) = C(n, i) s^i (1 − s)^(n − i)`. With weights `w_i > 0` it is rational:
//! `P(t) = Σ B_i^n(s) w_i P_i / Σ B_i^n(s) w_i`, evaluated as the polynomial curve of the
//! homogeneous points `(w_i P_i, w_i)` followed by one division. The default interval is `[0, 1]`;
//! a parameter outside the interval is an [`crate::Error::ParameterOutOfRange`], never clamped.
//!
//! ```
//! use glam::DVec2;
//! use splinelab::bezier::BezierCurve;
//! // The worked example of the Greek notes (syllabus §2).
//! let pts = [(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
//! let curve = BezierCurve::new(pts.to_vec(), None).unwrap();
//! assert_eq!(curve.evaluate(0.25).unwrap(), DVec2::new(29.0 / 16.0, 23.0 / 16.0));
//! ```

mod arc_length;
mod bernstein;
mod bounds;
mod composite;
mod curve;
mod de_casteljau;
mod derivative;
mod evaluate;
mod flatten;
mod intersect;

pub use arc_length::{arc_lengths, FAST_PATH_RELATIVE_ERROR, RULE_RHO, RULE_RHO_BY_ACCURACY};
pub use bernstein::{bernstein_basis, try_bernstein};
pub use composite::{
    check_continuity, from_polynomial, join, CompositeCurve, Continuity, JoinRule,
    DEFAULT_CONTINUITY_TOLERANCE,
};
pub use de_casteljau::{
    bernstein, de_casteljau_point, de_casteljau_triangle, differences, elevate_points, horner,
    horner_fixed, horner_with_derivative_fixed, power_coefficients, split_points,
    subsegment_points, to_power_form,
};
pub(crate) use de_casteljau::{horner_run, PowerForm};
pub use flatten::MAX_FLATTEN_SEGMENTS;
pub use intersect::{LineIntersection, VisitedBox, MAX_INTERSECTION_DEPTH};

use crate::geom::Cartesian;

pub use crate::geom::{MAX_DEGREE, MAX_SAMPLES};

/// Highest degree sampled by Horner's rule on the power basis; the power form's coefficients
/// grow like `C(n, k) 2^k` and would lose digits to cancellation at high degrees.
pub const HORNER_MAX_DEGREE: usize = de_casteljau::DENSE_MAX_DEGREE;

/// A polynomial or rational Bézier curve in 2D (`C = DVec2`) or 3D (`C = DVec3`).
///
/// Control points are stored in homogeneous form `(w_i P_i, w_i)`; a polynomial curve has all
/// weights 1 and is evaluated without the final division, so integer examples stay exact.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<C: Cartesian> {
    homogeneous: Vec<C::Homogeneous>,
    rational: bool,
    a: f64,
    b: f64,
}
