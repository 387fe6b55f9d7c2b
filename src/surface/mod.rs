//! Tensor-product Bézier, B-spline and NURBS surfaces (syllabus §6):
//!
//! `S(u, v) = Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) w_ij P_ij / Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) w_ij`
//!
//! over the control net `P_ij` (`i = 0..rows−1` along u, `j = 0..cols−1` along v) with knot
//! vectors `U` (degree `p`) and `V` (degree `q`), evaluated on homogeneous points
//! `(w P, w)` with one division at the end, on the domain `[u_p, u_rows] × [v_q, v_cols]`.
//! Points are 3D and stored row-major: point `(i, j)` is number `i·cols + j`. A Bézier patch
//! `ΣΣ B_i^m(u) B_j^n(v) P_ij` is the case of one span, knots `0 … 0 1 … 1`
//! ([`BSplineSurface::bezier`]).

mod adaptive;
pub mod construct;
mod curvature;
mod evaluate;
mod grid;
mod insert;
mod intersect;
mod iso;
mod mesh;
mod net;
mod patches;
mod teaching;

pub use adaptive::{MAX_ADAPTIVE_DEPTH, MAX_ADAPTIVE_VERTICES};
pub use construct::{
    extrude, grid_params, interpolate_surface, revolve, ruled, MAX_REVOLUTION_ARC,
};
pub use intersect::{MAX_INTERSECTION_WORK, MAX_NEWTON_STARTS, MAX_SURFACE_INTERSECTION_DEPTH};
pub use mesh::{Mesh, MAX_LIMIT_NORMALS};
pub use patches::SEAM_TOLERANCE;
pub use teaching::{bezier_basis_matrix, PatchDeCasteljau, PatchMatrixForm};

use crate::bspline::{basis_functions, BasisScratch, KnotVector};
use crate::error::{in_argument, Error, Result};
use glam::DVec4;

/// Most vertices one [`BSplineSurface::tessellate`] call makes (2^20, about 1024 × 1024): with
/// the triangles, ~50 bytes each in the result (1.5 M vertices took 3.3 s in a fuzz call; a
/// bicubic takes 0.35 s for 2^20); above degree ~7 the work budget
/// [`crate::geom::MAX_SAMPLE_WORK`] comes first.
pub const MAX_MESH_VERTICES: usize = 1 << 20;

/// A polynomial or rational (NURBS) tensor-product B-spline surface in 3D.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface {
    /// Homogeneous control net `(w·x, w·y, w·z, w)`, row-major.
    net: Vec<DVec4>,
    rows: usize,
    cols: usize,
    rational: bool,
    knots_u: KnotVector,
    knots_v: KnotVector,
}

/// An error about element `index` of the list argument `name` (the message says
/// `name[index]: cause`).
fn in_element(name: &'static str, index: usize, err: Error) -> Error {
    Error::InArgument {
        name,
        index: Some(index),
        source: Box::new(err),
    }
}

/// `a · b`, the size of a net, grid or mesh, checked against `max` (`what` names it).
fn checked_count(what: &'static str, a: usize, b: usize, max: usize) -> Result<usize> {
    a.checked_mul(b)
        .filter(|&n| n <= max)
        .ok_or(Error::TooLarge {
            what,
            value: a.saturating_mul(b),
            max,
        })
}

/// The `p + 1` basis functions of `knots` that can be non-zero at `t` in span `k`, into `out`.
fn basis(knots: &KnotVector, k: usize, t: f64, out: &mut [f64], scratch: &mut BasisScratch) {
    basis_functions(knots.as_slice(), k, t, knots.degree(), out, scratch, None);
}
