//! Gaussian and mean curvature from the exact first and second partial derivatives.

use super::BSplineSurface;
use crate::error::{Error, Result};
use glam::DVec3;

/// `[K, H]` from the partials at one point: with `N = S_u × S_v / |S_u × S_v|`, the first
/// fundamental form `E = S_u·S_u`, `F = S_u·S_v`, `G = S_v·S_v` and the second
/// `L = S_uu·N`, `M = S_uv·N`, `N' = S_vv·N`:
/// `K = (L N' − M²) / (E G − F²)`, `H = (E N' − 2 F M + G L) / (2 (E G − F²))`.
/// `None` where there is no normal: one partial vanishes next to the other (`|S_u| ≤ 10⁻¹⁰
/// |S_v|` or the reverse, as [`BSplineSurface::normal`] decides it: a pole, a collapsed edge)
/// or `|S_u × S_v| ≤ 10⁻¹² |S_u| |S_v|` (parallel partials, a fold).
fn curvature_from(su: DVec3, sv: DVec3, suu: DVec3, suv: DVec3, svv: DVec3) -> Option<[f64; 2]> {
    let (a, b) = (su.length(), sv.length());
    let cross = su.cross(sv);
    let length = cross.length();
    let degenerate = a.min(b) <= 1e-10 * a.max(b) || length <= 1e-12 * a * b;
    if degenerate || !length.is_finite() {
        return None;
    }
    let n = cross / length;
    let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
    let (l, m, nn) = (suu.dot(n), suv.dot(n), svv.dot(n));
    let det = e * g - f * f;
    Some([
        (l * nn - m * m) / det,
        (e * nn - 2.0 * f * m + g * l) / (2.0 * det),
    ])
}

impl BSplineSurface {
    /// `[K, H]` at `(u, v)`: the Gaussian curvature `K = κ₁κ₂` and the mean curvature
    /// `H = (κ₁ + κ₂)/2` from the exact first and second partial derivatives (A3.6/A4.4), `H`
    /// signed with the normal `S_u × S_v` normalised (positive where the surface bends towards
    /// it: a sphere whose normal points outwards has `H = −1/r`).
    ///
    /// # Errors
    /// A bad `u` or `v`; [`Error::NoNormal`] naming `(u, v)` where `S_u × S_v` vanishes (a
    /// pole, a collapsed edge, a fold): the curvature is not defined by this parametrisation.
    pub fn curvature(&self, u: f64, v: f64) -> Result<[f64; 2]> {
        let (u, v) = self.check_uv(u, v)?;
        let s = self.derivatives(u, v, 2);
        curvature_from(s[1][0], s[0][1], s[2][0], s[1][1], s[0][2]).ok_or(Error::NoNormal { u, v })
    }

    /// [`BSplineSurface::curvature`] at every `(u, v)` pair of the flat `uvs`, written as
    /// `[K0, H0, K1, H1, …]` into `out` (resized to `uvs.len()`). Where there is no normal
    /// both numbers are NaN (no error), so a mesh through a pole can still be coloured. A
    /// value within single-precision rounding of the domain (`10⁻⁶` of its size) is clamped
    /// into it, so the `Float32Array` uvs of a mesh are accepted.
    ///
    /// # Errors
    /// [`Error::CoordinateCount`] for an odd length; a parameter that is not finite or lies
    /// outside the domain (beyond the rounding allowance).
    pub fn curvatures_into(&self, uvs: &[f64], out: &mut Vec<f64>) -> Result<()> {
        if !uvs.len().is_multiple_of(2) {
            return Err(Error::CoordinateCount {
                count: uvs.len(),
                dim: 2,
            });
        }
        out.clear();
        out.reserve(uvs.len());
        let (du, dv) = (self.knots_u.domain(), self.knots_v.domain());
        for pair in uvs.chunks_exact(2) {
            let (u, v) = self.check_uv(snap(pair[0], du), snap(pair[1], dv))?;
            let s = self.derivatives(u, v, 2);
            let kh = curvature_from(s[1][0], s[0][1], s[2][0], s[1][1], s[0][2])
                .unwrap_or([f64::NAN; 2]);
            out.extend_from_slice(&kh);
        }
        Ok(())
    }
}

/// `t` clamped into `[a, b]` when it lies within `10⁻⁶·max(|a|, |b|, b − a)` of it (single
/// precision rounding of a mesh's uvs); anything else unchanged (and checked by the caller).
fn snap(t: f64, (a, b): (f64, f64)) -> f64 {
    let slack = 1e-6 * a.abs().max(b.abs()).max(b - a);
    if t < a && t >= a - slack {
        a
    } else if t > b && t <= b + slack {
        b
    } else {
        t
    }
}
