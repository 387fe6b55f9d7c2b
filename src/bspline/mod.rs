//! B-spline curves, polynomial and rational (NURBS), in 2D and 3D (syllabus §3, §4).
//!
//! A B-spline curve of degree `p` with control points `P_0..P_n` and knots `u_0..u_{n+p+1}` is
//! `C(u) = Σ N_{i,p}(u) P_i` on the domain `[u_p, u_{n+1}]`; with weights it is rational,
//! `C(u) = Σ N_{i,p} w_i P_i / Σ N_{i,p} w_i`, evaluated on the homogeneous points
//! `(w_i P_i, w_i)` with one division at the end. Basis functions are right-continuous and
//! the last non-empty span is closed on the right, so `C(u_{n+1})` is the end of the curve
//! (`P_n` when clamped). A parameter outside the domain is an error, never clamped.
//!
//! ```
//! use glam::DVec2;
//! use splinelab::bspline::BSplineCurve;
//! // Knots 0^{p+1} 1^{p+1}: the B-spline is the Bézier curve.
//! let pts = [(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
//! let c = BSplineCurve::new(pts.to_vec(), 3, vec![0., 0., 0., 0., 1., 1., 1., 1.], None).unwrap();
//! assert_eq!(c.evaluate(0.25).unwrap(), DVec2::new(29.0 / 16.0, 23.0 / 16.0));
//! ```

mod basis;
mod construct;
mod curve;
mod de_boor;
mod evaluate;
mod insert;
mod knots;
mod matrix;
mod sample;

pub use basis::{basis_derivatives, basis_functions, BasisScratch};
pub use construct::{knot_vector, parameterize, phantom_points, KnotKind, Parameterization};
pub(crate) use curve::check_degree;
pub use de_boor::{de_boor_alpha, de_boor_alphas, de_boor_triangle, DeBoorAlpha};
pub use insert::{boehm_alpha, boehm_alphas, boehm_insert, KnotContinuity};
pub(crate) use insert::{check_insertion, refine_points};
pub use knots::KnotVector;
pub use matrix::{uniform_segment_matrix, MatrixFormPoint};

use crate::geom::Cartesian;

/// A polynomial or rational B-spline curve in 2D (`C = DVec2`) or 3D (`C = DVec3`).
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<C: Cartesian> {
    homogeneous: Vec<C::Homogeneous>,
    rational: bool,
    knots: KnotVector,
    /// For closed curves: the last `wrap` control points repeat the first `wrap` ones, and
    /// in-place edits keep them equal.
    wrap: usize,
}
