//! Surfaces built from curves: revolution (exact NURBS), extrusion, ruled surfaces, and global
//! interpolation of a grid of points.

mod compatible;
mod interpolate;
mod revolve;
mod sweep;

pub use interpolate::{check_grid, grid_params, interpolate_surface};
pub use revolve::{revolve, MAX_REVOLUTION_ARC};
pub use sweep::{extrude, ruled};

use crate::bspline::BSplineCurve;
use crate::error::SurfaceError;
use crate::error::{check_coordinate_of, Error, Result};
use crate::geom::Cartesian;
use crate::prelude::*;
use glam::{DVec3, DVec4};

/// `curve` as a 3D curve, or [`Error::Needs3D`] naming `operation` (surfaces are 3D).
fn curve_3d<C: Cartesian>(
    curve: &BSplineCurve<C>,
    operation: &'static str,
) -> Result<BSplineCurve<DVec3>> {
    if C::DIM != 3 {
        return Err(Error::Needs3D {
            operation,
            dim: C::DIM,
        });
    }
    let points = curve
        .control_points()
        .iter()
        .map(|p| DVec3::new(p.coord(0), p.coord(1), p.coord(2)))
        .collect();
    let weights = curve.weights();
    BSplineCurve::new(
        points,
        curve.degree(),
        curve.knots().as_slice().to_vec(),
        curve.is_rational().then_some(&weights[..]),
    )
}

/// A 3D vector argument: every coordinate finite (the error names `name` and the coordinate).
fn check_vector(name: &'static str, v: DVec3) -> Result<()> {
    for (k, c) in v.to_array().into_iter().enumerate() {
        check_coordinate_of(name, k, c)?;
    }
    Ok(())
}

/// A direction argument: finite and not the zero vector ([`SurfaceError::ZeroDirection`]).
fn check_direction(name: &'static str, v: DVec3) -> Result<()> {
    check_vector(name, v)?;
    if v.length() == 0.0 || !v.length().is_finite() {
        return Err(Error::Surface(SurfaceError::ZeroDirection { name }));
    }
    Ok(())
}

/// The homogeneous control points `(w P, w)` of a 3D curve.
fn homogeneous(curve: &BSplineCurve<DVec3>) -> Vec<DVec4> {
    curve.homogeneous_points().to_vec()
}

/// A surface from a homogeneous net (row-major), the degrees and knots.
fn from_homogeneous(
    net: &[DVec4],
    rows: usize,
    cols: usize,
    (degree_u, knots_u): (usize, Vec<f64>),
    (degree_v, knots_v): (usize, Vec<f64>),
) -> Result<super::BSplineSurface> {
    let coords: Vec<f64> = net
        .iter()
        .flat_map(|h| (h.truncate() / h.w).to_array())
        .collect();
    let weights: Vec<f64> = net.iter().map(|h| h.w).collect();
    let rational = weights.iter().any(|&w| w != 1.0);
    super::BSplineSurface::from_flat(
        &coords,
        rows,
        cols,
        degree_u,
        degree_v,
        knots_u,
        knots_v,
        rational.then_some(&weights[..]),
    )
}
