//! Gaussian and mean curvature from the exact first and second partial derivatives.

use super::BSplineSurface;
use crate::bspline::{basis_functions, BasisScratch};
use crate::error::SurfaceError;
use crate::error::{Error, Result};
use crate::geom::check_work;
use glam::{DVec3, DVec4};

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
    /// A bad `u` or `v`; [`SurfaceError::NoNormal`] naming `(u, v)` where `S_u × S_v` vanishes (a
    /// pole, a collapsed edge, a fold): the curvature is not defined by this parametrisation.
    pub fn curvature(&self, u: f64, v: f64) -> Result<[f64; 2]> {
        let (u, v) = self.check_uv(u, v)?;
        let s = self.derivatives(u, v, 2);
        curvature_from(s[1][0], s[0][1], s[2][0], s[1][1], s[0][2])
            .ok_or(Error::Surface(SurfaceError::NoNormal { u, v }))
    }

    /// [`BSplineSurface::curvature`] at every `(u, v)` pair of the flat `uvs`, written as
    /// `[K0, H0, K1, H1, …]` into `out` (resized to `uvs.len()`). Where there is no normal
    /// both numbers are NaN (no error), so a mesh through a pole can still be coloured. A
    /// value within single-precision rounding of the domain (`10⁻⁶` of its size) is clamped
    /// into it, so the `Float32Array` uvs of a mesh are accepted.
    ///
    /// # Errors
    /// [`Error::CoordinateCount`] for an odd length; [`Error::TooLarge`] for more points than
    /// the work budget [`crate::geom::MAX_SAMPLE_WORK`] allows at this degree; a parameter
    /// that is not finite or lies outside the domain (beyond the rounding allowance).
    pub fn curvatures_into(&self, uvs: &[f64], out: &mut Vec<f64>) -> Result<()> {
        if !uvs.len().is_multiple_of(2) {
            return Err(Error::CoordinateCount {
                count: uvs.len(),
                dim: 2,
            });
        }
        let (p1, q1) = (self.degree_u() + 1, self.degree_v() + 1);
        let units = 8 * (p1 * q1 + p1 * p1 + q1 * q1 + 32);
        check_work("curvature-work", uvs.len() / 2, units)?;
        out.clear();
        out.reserve(uvs.len());
        let (du, dv) = (self.knots_u.domain(), self.knots_v.domain());
        let mut scratch = SecondOrder::default();
        for pair in uvs.chunks_exact(2) {
            let (u, v) = self.check_uv(snap(pair[0], du), snap(pair[1], dv))?;
            let [su, sv, suu, suv, svv] = self.second_order(u, v, &mut scratch);
            let kh = curvature_from(su, sv, suu, suv, svv).unwrap_or([f64::NAN; 2]);
            out.extend_from_slice(&kh);
        }
        Ok(())
    }

    /// `[S_u, S_v, S_uu, S_uv, S_vv]` at a checked `(u, v)` with no allocation after the first
    /// call with `scratch`: the basis functions and their first two derivatives per direction
    /// ([`second_order_basis`]), the homogeneous partials `A_kl = Σ_a Σ_b N_a^(k) N_b^(l) (wP)_ab`
    /// (`k + l ≤ 2`), then the quotient rule (A4.4 written out to order 2), with `S = A_00/w`:
    /// `S_u = (A_10 − w_10 S)/w`, `S_uu = (A_20 − 2 w_10 S_u − w_20 S)/w`,
    /// `S_uv = (A_11 − w_10 S_v − w_01 S_u − w_11 S)/w`, and likewise in v.
    // `row` indexes the three derivative rows of `nu` at once.
    #[allow(clippy::needless_range_loop)]
    fn second_order(&self, u: f64, v: f64, scratch: &mut SecondOrder) -> [DVec3; 5] {
        let (p, q) = (self.degree_u(), self.degree_v());
        let (ku, kv) = (self.knots_u.span(u), self.knots_v.span(v));
        let SecondOrder {
            basis,
            lower,
            first,
            u: nu,
            v: nv,
        } = scratch;
        second_order_basis(self.knots_u.as_slice(), ku, u, p, basis, lower, first, nu);
        second_order_basis(self.knots_v.as_slice(), kv, v, q, basis, lower, first, nv);
        // a[k][l] = A_kl for k + l ≤ 2 (homogeneous, w last).
        let mut a = [[DVec4::ZERO; 3]; 3];
        for row in 0..=p {
            let start = (ku - p + row) * self.cols + kv - q;
            let Some(points) = self.net.get(start..start + q + 1) else {
                continue;
            };
            let mut sums = [DVec4::ZERO; 3];
            for (b, &h) in points.iter().enumerate() {
                for (l, sum) in sums.iter_mut().enumerate() {
                    *sum += nv[l][b] * h;
                }
            }
            for (k, a_k) in a.iter_mut().enumerate() {
                for (l, a_kl) in a_k.iter_mut().enumerate().take(3 - k) {
                    *a_kl += nu[k][row] * sums[l];
                }
            }
        }
        let w = a[0][0].w;
        let s = a[0][0].truncate() / w;
        let (w10, w01) = (a[1][0].w, a[0][1].w);
        let su = (a[1][0].truncate() - w10 * s) / w;
        let sv = (a[0][1].truncate() - w01 * s) / w;
        let suu = (a[2][0].truncate() - 2.0 * w10 * su - a[2][0].w * s) / w;
        let svv = (a[0][2].truncate() - 2.0 * w01 * sv - a[0][2].w * s) / w;
        let suv = (a[1][1].truncate() - w10 * sv - w01 * su - a[1][1].w * s) / w;
        [su, sv, suu, suv, svv]
    }
}

/// Reusable buffers for [`BSplineSurface::second_order`].
#[derive(Default)]
struct SecondOrder {
    basis: BasisScratch,
    /// Basis functions of degree `p − 1` or `p − 2`.
    lower: Vec<f64>,
    /// First derivatives of the degree `p − 1` functions.
    first: Vec<f64>,
    /// `u[d][j] = N^(d)_{k−p+j,p}(u)`, `d = 0, 1, 2`.
    u: [Vec<f64>; 3],
    /// The same in v.
    v: [Vec<f64>; 3],
}

/// `ders[d][j] = N^(d)_{k−p+j,p}(t)` for `d = 0, 1, 2` (each `p + 1` long) from the basis
/// functions of degrees `p`, `p − 1` and `p − 2` at `t` in span `k` and the derivative rule
/// `N'_{i,p} = p (N_{i,p−1}/(u_{i+p} − u_i) − N_{i+1,p−1}/(u_{i+p+1} − u_{i+1}))` (`0/0 := 0`),
/// applied once for the first derivatives and twice for the second ([`derive`]).
#[allow(clippy::too_many_arguments)]
fn second_order_basis(
    knots: &[f64],
    k: usize,
    t: f64,
    p: usize,
    scratch: &mut BasisScratch,
    lower: &mut Vec<f64>,
    first: &mut Vec<f64>,
    ders: &mut [Vec<f64>; 3],
) {
    for d in ders.iter_mut() {
        d.clear();
        d.resize(p + 1, 0.0);
    }
    let [values, d1, d2] = ders;
    basis_functions(knots, k, t, p, values, scratch, None);
    if p >= 1 {
        lower.clear();
        lower.resize(p, 0.0);
        basis_functions(knots, k, t, p - 1, lower, scratch, None);
        derive(knots, k, p, lower, d1);
    }
    if p >= 2 {
        lower.clear();
        lower.resize(p - 1, 0.0);
        basis_functions(knots, k, t, p - 2, lower, scratch, None);
        first.clear();
        first.resize(p, 0.0);
        derive(knots, k, p - 1, lower, first);
        derive(knots, k, p, first, d2);
    }
}

/// From `input[j] = f_{k−d+1+j}` (`d` values, the degree `d − 1` functions or their
/// derivatives non-zero on span `k`) to `out[j] = d (f_i/(u_{i+d} − u_i) −
/// f_{i+1}/(u_{i+d+1} − u_{i+1}))`, `i = k − d + j` (`d + 1` values; a zero-length interval
/// contributes 0).
fn derive(knots: &[f64], k: usize, d: usize, input: &[f64], out: &mut [f64]) {
    let term = |value: f64, lo: usize, hi: usize| -> f64 {
        let span = knots.get(hi).copied().unwrap_or(0.0) - knots.get(lo).copied().unwrap_or(0.0);
        if span > 0.0 {
            value / span
        } else {
            0.0
        }
    };
    for (j, o) in out.iter_mut().enumerate().take(d + 1) {
        let i = k - d + j;
        let a = if j >= 1 {
            input.get(j - 1).copied().unwrap_or(0.0)
        } else {
            0.0
        };
        let b = input.get(j).copied().unwrap_or(0.0);
        let b = if j < d { b } else { 0.0 };
        *o = d as f64 * (term(a, i, i + d) - term(b, i + 1, i + d + 1));
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
