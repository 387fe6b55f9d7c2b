//! Rational curves (syllabus §4): conic sections as rational quadratic Béziers, exact circles,
//! arcs and ellipses as NURBS, and projective maps of control points.
//!
//! Rational Bézier and B-spline curves themselves are [`crate::BezierCurve`] and
//! [`crate::BSplineCurve`] with weights: `P(t) = Σ B_i w_i P_i / Σ B_i w_i`, evaluated on the
//! homogeneous points `(w_i P_i, w_i)` with one division at the end. Only the ratios of the
//! weights matter; raising `w_i` pulls the curve toward `P_i`; weights must be > 0 (a zero or
//! negative weight can make the denominator vanish: a pole).

mod basis;
mod conics;
mod poles;
mod projective;

pub use basis::rational_basis;
pub use conics::{
    circle_arc_from_triangle, circular_arc, conic_kind, ellipse, ellipse_arc, ConicKind,
    MAX_ARC_PIECE,
};
pub use poles::{
    rational_poles, RationalPoles, MAX_ROOT_DEPTH, MAX_ROOT_INTERVALS, ROOT_MERGE_DISTANCE,
};
pub use projective::{projective_map_bezier, projective_map_bspline};
