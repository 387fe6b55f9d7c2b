//! Surfaces of revolution as exact NURBS (NURBS Book §8.5, A8.1).

use super::{check_direction, check_vector, curve_3d, from_homogeneous, homogeneous};
use crate::bspline::BSplineCurve;
use crate::error::ConicError;
use crate::error::{check_finite, Error, Result};
use crate::geom::{sin_cos, Cartesian};
use crate::surface::BSplineSurface;
use glam::{DVec3, DVec4};
use std::f64::consts::{FRAC_PI_2, TAU};

/// The largest sweep of one rational quadratic arc of a revolution (90°): 1 arc up to 90°,
/// 2 up to 180°, 3 up to 270°, else 4.
pub const MAX_REVOLUTION_ARC: f64 = FRAC_PI_2;

/// The surface swept by `profile` turning by `angle` radians (default a full turn, `2π`)
/// about the axis through `axis_point` along `axis_direction`, counter-clockwise seen from
/// the tip of the direction (the right-hand rule). NURBS Book A8.1:
///
/// - u runs around the axis: degree 2, `arcs = ⌈angle / 90°⌉` rational quadratic arcs of
///   sweep `Δ = angle / arcs` joined by double knots on `[0, 1]` (`0,0,0,½,½,1,1,1` for two);
/// - v runs along the profile: its degree, knots and weights.
///
/// Each profile control point `P_j` (weight `w_j`) at distance `r_j` from the axis (foot
/// `O_j`, unit radial `X_j`, `Y_j = T × X_j`) gives the row points
/// `P_{2k, j} = O_j + r_j (cos kΔ X_j + sin kΔ Y_j)` (weight `w_j`) and the corners
/// `P_{2k−1, j} = O_j + (r_j / cos(Δ/2)) (cos (k−½)Δ X_j + sin (k−½)Δ Y_j)` (weight
/// `w_j cos(Δ/2)`); a point on the axis stays put. Every circle of the surface is exact: a
/// circle profile gives a torus.
///
/// # Errors
/// In this order: [`Error::Needs3D`] for a 2D profile, a non-finite axis point or direction,
/// [`crate::error::SurfaceError::ZeroDirection`] for a zero direction, [`Error::NotFinite`] or
/// [`ConicError::InvalidSweep`] for an angle ≤ 0 or above `2π`.
pub fn revolve<C: Cartesian>(
    profile: &BSplineCurve<C>,
    axis_point: DVec3,
    axis_direction: DVec3,
    angle: f64,
) -> Result<BSplineSurface> {
    let profile = curve_3d(profile, "revolve")?;
    check_vector("axisPoint", axis_point)?;
    check_direction("axisDirection", axis_direction)?;
    check_finite("angle", None, angle)?;
    if !(angle > 0.0 && angle <= TAU * (1.0 + 1e-12)) {
        return Err(Error::Conic(ConicError::InvalidSweep { sweep: angle }));
    }
    let angle = angle.min(TAU);
    let full_turn = angle == TAU;
    let arcs = ((angle / MAX_REVOLUTION_ARC) - 1e-9).ceil().clamp(1.0, 4.0) as usize;
    let delta = angle / arcs as f64;
    let w_mid = sin_cos(0.5 * delta).1;
    let axis = axis_direction.normalize();
    let profile_net = homogeneous(&profile);
    let (rows, cols) = (2 * arcs + 1, profile_net.len());
    let mut net = vec![DVec4::ZERO; rows * cols];
    // The directions of the row points: (cos, sin, distance factor, weight factor).
    let mut frames = Vec::with_capacity(rows);
    for i in 0..rows {
        let (theta, scale, weight) = if i % 2 == 0 {
            ((i / 2) as f64 * delta, 1.0, 1.0)
        } else {
            ((i as f64 * 0.5) * delta, 1.0 / w_mid, w_mid)
        };
        let (sin, cos) = if i + 1 == rows && full_turn {
            (0.0, 1.0)
        } else if i + 1 == rows {
            sin_cos(angle)
        } else {
            sin_cos(theta)
        };
        frames.push((cos, sin, scale, weight));
    }
    for (j, h) in profile_net.iter().enumerate() {
        let (p, w) = (h.truncate() / h.w, h.w);
        let foot = axis_point + axis * (p - axis_point).dot(axis);
        let radial = p - foot;
        let r = radial.length();
        let (x, y) = if r > 0.0 {
            let x = radial / r;
            (x, axis.cross(x))
        } else {
            (DVec3::ZERO, DVec3::ZERO)
        };
        for (i, &(cos, sin, scale, weight)) in frames.iter().enumerate() {
            let point = if i == 0 || (i + 1 == rows && full_turn) {
                p
            } else {
                foot + r * scale * (cos * x + sin * y)
            };
            let wi = w * weight;
            net[i * cols + j] = (point * wi).extend(wi);
        }
    }
    let mut knots_u = vec![0.0; 3];
    for k in 1..arcs {
        let t = k as f64 / arcs as f64;
        knots_u.extend([t, t]);
    }
    knots_u.extend([1.0; 3]);
    from_homogeneous(
        &net,
        rows,
        cols,
        (2, knots_u),
        (profile.degree(), profile.knots().as_slice().to_vec()),
    )
}
