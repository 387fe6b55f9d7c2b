//! Extruded (general cylinder) and ruled surfaces: linear in v, degree 1, two columns.

use super::compatible::{clamped_unit, elevated, merged};
use super::{check_direction, curve_3d, from_homogeneous, homogeneous};
use crate::bspline::BSplineCurve;
use crate::error::Result;
use crate::geom::Cartesian;
use crate::surface::BSplineSurface;
use glam::{DVec3, DVec4};

/// The extrusion `S(u, v) = C(u) + v·d`, `v ∈ [0, 1]`: u along the curve (its degree, knots
/// and weights; row `i` of the net is `P_i, P_i + d`, both with weight `w_i`), v linear
/// (degree 1, knots `0,0,1,1`).
///
/// # Errors
/// [`crate::Error::Needs3D`] for a 2D curve, a non-finite direction, then
/// [`crate::error::SurfaceError::ZeroDirection`] for `d = 0` (the surface would be the curve).
pub fn extrude<C: Cartesian>(curve: &BSplineCurve<C>, direction: DVec3) -> Result<BSplineSurface> {
    let curve = curve_3d(curve, "extrude")?;
    check_direction("direction", direction)?;
    let net: Vec<DVec4> = homogeneous(&curve)
        .into_iter()
        .flat_map(|h| [h, h + (direction * h.w).extend(0.0)])
        .collect();
    from_homogeneous(
        &net,
        net.len() / 2,
        2,
        (curve.degree(), curve.knots().as_slice().to_vec()),
        (1, vec![0.0, 0.0, 1.0, 1.0]),
    )
}

/// The ruled surface between two curves, `S(u, v) = (1 − v) A(u) + v B(u)`, `u ∈ [0, 1]`,
/// `v ∈ [0, 1]` (degree 1). The curves are made compatible first (NURBS Book §10.3): each
/// clamped and mapped onto `[0, 1]`, the lower degree raised to the higher, and the knot
/// vectors merged by knot refinement; row `i` of the net is then `A_i, B_i` with their
/// weights. For rational curves the rulings are still the segments from `A(u)` to `B(u)`, but
/// `v` runs along them linearly in homogeneous coordinates (uniformly only where the weight
/// functions of A and B agree).
///
/// # Errors
/// [`crate::Error::Needs3D`] for a 2D curve (`curveA` first); a curve with a break (an
/// interior knot of multiplicity `p + 1`) whose degree must be raised.
pub fn ruled<C: Cartesian, D: Cartesian>(
    curve_a: &BSplineCurve<C>,
    curve_b: &BSplineCurve<D>,
) -> Result<BSplineSurface> {
    let a = clamped_unit(&curve_3d(curve_a, "ruled")?)?;
    let b = clamped_unit(&curve_3d(curve_b, "ruled")?)?;
    let degree = a.degree().max(b.degree());
    let (a, b) = merged(&elevated(&a, degree)?, &elevated(&b, degree)?)?;
    let net: Vec<DVec4> = homogeneous(&a)
        .into_iter()
        .zip(homogeneous(&b))
        .flat_map(|(p, q)| [p, q])
        .collect();
    from_homogeneous(
        &net,
        net.len() / 2,
        2,
        (degree, a.knots().as_slice().to_vec()),
        (1, vec![0.0, 0.0, 1.0, 1.0]),
    )
}
