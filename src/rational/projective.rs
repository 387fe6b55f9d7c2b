//! Projective maps of 2D rational curves (syllabus §4: projective invariance).
//!
//! A projective map of the plane is a 3×3 matrix `M` acting on homogeneous coordinates
//! `(x, y, 1)`. Applying it to the homogeneous control points `(w_i x_i, w_i y_i, w_i)` of a
//! rational curve gives the control points of the mapped curve: the image of the curve is the
//! curve of the mapped control points, with new weights `w'_i` (the third coordinate).

use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::error::ConicError;
use crate::error::{Error, Result};
use crate::prelude::*;
use glam::{DMat3, DVec2, DVec3};

/// Maps homogeneous points by `m`, checking the new weights stay > 0 (a point sent to or
/// behind the line at infinity would put a pole on the curve).
fn map_points(points: &[DVec3], m: &DMat3) -> Result<Vec<DVec2>> {
    let mapped: Vec<DVec3> = points.iter().map(|&h| *m * h).collect();
    if let Some((i, h)) = mapped
        .iter()
        .enumerate()
        .find(|(_, h)| h.z.is_nan() || h.z <= 0.0 || !h.is_finite())
    {
        return Err(Error::Conic(ConicError::MappedWeight {
            index: i,
            weight: h.z,
        }));
    }
    Ok(mapped.iter().map(|h| h.truncate() / h.z).collect())
}

fn mapped_weights(points: &[DVec3], m: &DMat3) -> Vec<f64> {
    points.iter().map(|&h| (*m * h).z).collect()
}

/// The image of a 2D (rational or polynomial) Bézier curve under the projective map `m`.
///
/// # Errors
/// [`ConicError::MappedWeight`] when a mapped weight is not > 0, [`Error::NotFinite`] for a bad
/// matrix.
pub fn projective_map_bezier(curve: &BezierCurve<DVec2>, m: &DMat3) -> Result<BezierCurve<DVec2>> {
    check_matrix(m)?;
    let h = curve.homogeneous_points();
    let points = map_points(h, m)?;
    let weights = mapped_weights(h, m);
    let (a, b) = curve.interval();
    BezierCurve::new(points, Some(&weights))?.with_interval(a, b)
}

/// The image of a 2D B-spline / NURBS curve under the projective map `m` (same knots).
///
/// # Errors
/// As [`projective_map_bezier`].
pub fn projective_map_bspline(
    curve: &BSplineCurve<DVec2>,
    m: &DMat3,
) -> Result<BSplineCurve<DVec2>> {
    check_matrix(m)?;
    let h = curve.homogeneous_points();
    let points = map_points(h, m)?;
    let weights = mapped_weights(h, m);
    BSplineCurve::new(
        points,
        curve.degree(),
        curve.knots().as_slice().to_vec(),
        Some(&weights),
    )
}

fn check_matrix(m: &DMat3) -> Result<()> {
    crate::geom::check_all_finite(&m.to_cols_array(), "matrix-entry")?;
    if m.determinant() == 0.0 {
        return Err(Error::Conic(ConicError::SingularMap {}));
    }
    Ok(())
}
