//! The interpolation family (syllabus §5) for JavaScript.

mod cubic;
mod global;
mod hermite;
mod lagrange;
mod spline;

pub use cubic::{bessel_spline, cardinal_spline, catmull_rom, cubic_spline, hermite_spline};
pub use global::{approximate_bspline, bspline_interpolation_system, interpolate_bspline};
pub use hermite::{hermite_basis_js, hermite_bezier};
pub use lagrange::{lagrange, JsLagrangeCurve};
pub use spline::JsCubicSpline;

use crate::bspline::Parameterization;
use crate::error::Error;
use crate::geom::{points_from_flat, Point};
use crate::interp::ParamChoice;
use crate::wasm::ApiError;
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

/// A `params` argument as read from JavaScript, before the points are checked: an array of
/// numbers (the documented form), or, as a convenience, a spacing kind ("uniform" | "chord" |
/// "centripetal") or an exponent α in [0, 1] for `parameterize`, computed from the points.
enum ParamArg {
    Values(Vec<f64>),
    Kind(String),
    Alpha(f64),
}

impl ParamArg {
    /// Reads the argument: a string, a number, else an array of numbers (error naming `params`).
    #[inline(never)]
    fn read(value: &JsValue) -> Result<Self, ApiError> {
        if let Some(s) = value.as_string() {
            Ok(ParamArg::Kind(s))
        } else if let Some(a) = value.as_f64() {
            Ok(ParamArg::Alpha(a))
        } else {
            Ok(ParamArg::Values(super::numbers("params", value)?))
        }
    }

    /// The parameters for the flat points `coords` of dimension `dim`, for the functions that
    /// keep no recipe (the B-spline fits): given values checked against the point count
    /// ([`crate::interp::check_params`]), or the spacing computed from the points (in 3D, z = 0
    /// for 2D: the same distances).
    fn resolve_flat(self, coords: &[f64], dim: usize) -> Result<Vec<f64>, Error> {
        match self.choice()? {
            ParamChoice::Given(values) => {
                crate::interp::check_params(&values, coords.len() / dim)?;
                Ok(values)
            }
            spacing => spacing.resolve(&lift_points(coords, dim)?),
        }
    }

    /// The parameter choice (errors for an unknown kind or α outside [0, 1]).
    #[inline(never)]
    fn choice(self) -> Result<ParamChoice, Error> {
        Ok(match self {
            ParamArg::Values(v) => ParamChoice::Given(v),
            ParamArg::Kind(s) => ParamChoice::Spacing(Parameterization::parse(&s)?),
            ParamArg::Alpha(a) => ParamChoice::Spacing(Parameterization::from_alpha(a)?),
        })
    }
}

/// A vector argument of `P::DIM` numbers ([`Error::ArgumentLength`] naming it otherwise).
fn vector_arg<P: Point>(name: &'static str, values: &[f64]) -> Result<P, Error> {
    if values.len() != P::DIM {
        return Err(Error::ArgumentLength {
            name,
            expected: P::DIM,
            got: values.len(),
        });
    }
    Ok(P::from_slice(values))
}

/// Flat coordinates of dimension `dim` (2 or 3) as 3D points, a 2D one in the plane z = 0
/// (the coordinate count and finiteness checked as [`points_from_flat`] does): the classes
/// that keep one 3D copy of the code for both dimensions.
#[inline(never)]
fn lift_points(coords: &[f64], dim: usize) -> Result<Vec<DVec3>, Error> {
    Ok(if dim == 2 {
        let points: Vec<DVec2> = points_from_flat(coords)?;
        points.into_iter().map(|p| p.extend(0.0)).collect()
    } else {
        points_from_flat(coords)?
    })
}

/// One point of `dim` numbers as a 3D point ([`Error::PointDimension`] for another count).
fn lift_point(coords: &[f64], dim: usize) -> Result<DVec3, Error> {
    if coords.len() != dim {
        return Err(Error::PointDimension {
            expected: dim,
            got: coords.len(),
        });
    }
    let mut p = [0.0; 3];
    for (slot, &v) in p.iter_mut().zip(coords) {
        *slot = v;
    }
    Ok(DVec3::from_array(p))
}

/// 3D points cut back to their first `dim` coordinates, flat.
#[inline(never)]
fn flat_points(points: &[DVec3], dim: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity(points.len() * dim);
    for p in points {
        out.extend_from_slice(p.to_array().get(..dim).unwrap_or_default());
    }
    out
}

/// Flat 3D coordinates cut back to their first `dim`, in place.
#[inline(never)]
fn narrow(mut flat: Vec<f64>, dim: usize) -> Vec<f64> {
    if dim < 3 {
        let count = flat.len() / 3;
        for i in 0..count * dim {
            let from = i / dim * 3 + i % dim;
            if let Some(&v) = flat.get(from) {
                if let Some(slot) = flat.get_mut(i) {
                    *slot = v;
                }
            }
        }
        flat.truncate(count * dim);
    }
    flat
}
