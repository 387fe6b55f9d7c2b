//! Points, partial derivatives and unit normals of a surface.

use super::{basis, BSplineSurface};
use crate::bspline::{basis_derivatives, BasisScratch};
use crate::error::SurfaceError;
use crate::error::{Error, Result};
use crate::geom::MAX_DERIVATIVE_ORDER;
use glam::{DVec3, DVec4};

impl BSplineSurface {
    /// `(u, v)` checked against the domain; the error names `u` or `v` and the range.
    pub(super) fn check_uv(&self, u: f64, v: f64) -> Result<(f64, f64)> {
        Ok((
            self.knots_u.check_named("u", u)?,
            self.knots_v.check_named("v", v)?,
        ))
    }

    /// The homogeneous point `Σ Σ N_{i,p}(u) N_{j,q}(v) (w P)_ij` from the non-zero basis
    /// functions of the spans of `u` and `v` only: `(p + 1)(q + 1)` terms.
    fn homogeneous_at(&self, u: f64, v: f64) -> DVec4 {
        let (p, q) = (self.degree_u(), self.degree_v());
        let (ku, kv) = (self.knots_u.span(u), self.knots_v.span(v));
        let mut scratch = BasisScratch::default();
        let (mut nu, mut nv) = (vec![0.0; p + 1], vec![0.0; q + 1]);
        basis(&self.knots_u, ku, u, &mut nu, &mut scratch);
        basis(&self.knots_v, kv, v, &mut nv, &mut scratch);
        let mut sum = DVec4::ZERO;
        for (a, &na) in nu.iter().enumerate() {
            let row = (ku - p + a) * self.cols + kv - q;
            let Some(points) = self.net.get(row..row + q + 1) else {
                continue;
            };
            sum += na
                * points
                    .iter()
                    .zip(&nv)
                    .fold(DVec4::ZERO, |acc, (&h, &nb)| acc + nb * h);
        }
        sum
    }

    /// The point `S(u, v)`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for `u` or `v`.
    pub fn evaluate(&self, u: f64, v: f64) -> Result<DVec3> {
        let (u, v) = self.check_uv(u, v)?;
        let h = self.homogeneous_at(u, v);
        Ok(h.truncate() / h.w)
    }

    /// All partial derivatives `∂^{k+l} S / ∂u^k ∂v^l` with `k + l ≤ order`, as `skl[k][l]`:
    /// NURBS Book A3.6 on the homogeneous net (derivatives of the `p + 1` and `q + 1`
    /// non-zero basis functions, A2.3), then A4.4 for the quotient:
    /// `S_kl = (A_kl − Σ_{j=1..l} C(l,j) w_0j S_{k,l−j} − Σ_{i=1..k} C(k,i) w_i0 S_{k−i,l}
    ///          − Σ_{i=1..k} C(k,i) Σ_{j=1..l} C(l,j) w_ij S_{k−i,l−j}) / w`.
    pub(super) fn derivatives(&self, u: f64, v: f64, order: usize) -> Vec<Vec<DVec3>> {
        let (p, q) = (self.degree_u(), self.degree_v());
        let (ku, kv) = (self.knots_u.span(u), self.knots_v.span(v));
        let nu = basis_derivatives(self.knots_u.as_slice(), ku, u, p, order.min(p));
        let nv = basis_derivatives(self.knots_v.as_slice(), kv, v, q, order.min(q));
        // Homogeneous derivatives A_kl (and w_kl in .w); zero beyond the degrees.
        let mut h = vec![vec![DVec4::ZERO; order + 1]; order + 1];
        let mut temp = vec![DVec4::ZERO; q + 1];
        for (k, nuk) in nu.iter().enumerate() {
            for (s, t) in temp.iter_mut().enumerate() {
                *t = nuk.iter().enumerate().fold(DVec4::ZERO, |acc, (r, &n)| {
                    acc + n * self
                        .net
                        .get((ku - p + r) * self.cols + kv - q + s)
                        .copied()
                        .unwrap_or(DVec4::ZERO)
                });
            }
            for (l, nvl) in nv.iter().enumerate().take(order + 1 - k) {
                h[k][l] = nvl
                    .iter()
                    .zip(&temp)
                    .fold(DVec4::ZERO, |acc, (&n, &t)| acc + n * t);
            }
        }
        if !self.rational {
            // w ≡ 1: the homogeneous derivatives are the derivatives (exactly zero above the
            // degrees, where the quotient rule would leave rounding noise).
            return h
                .iter()
                .map(|row| row.iter().map(|a| a.truncate()).collect())
                .collect();
        }
        let binomial = |n: usize, r: usize| -> f64 {
            (1..=r).fold(1.0, |acc, i| acc * (n + 1 - i) as f64 / i as f64)
        };
        let w0 = h[0][0].w;
        let mut s = vec![vec![DVec3::ZERO; order + 1]; order + 1];
        for k in 0..=order {
            for l in 0..=order - k {
                let mut value = h[k][l].truncate();
                for j in 1..=l {
                    value -= binomial(l, j) * h[0][j].w * s[k][l - j];
                }
                for i in 1..=k {
                    value -= binomial(k, i) * h[i][0].w * s[k - i][l];
                    let mut inner = DVec3::ZERO;
                    for j in 1..=l {
                        inner += binomial(l, j) * h[i][j].w * s[k - i][l - j];
                    }
                    value -= binomial(k, i) * inner;
                }
                s[k][l] = value / w0;
            }
        }
        s
    }

    /// The partial derivative `∂^{du+dv} S / ∂u^du ∂v^dv` at `(u, v)` (`S` itself for 0, 0).
    /// Orders above the degree give the zero vector on a polynomial surface.
    ///
    /// # Errors
    /// A bad `u` or `v`, and [`Error::TooLarge`] for `du + dv` above
    /// [`MAX_DERIVATIVE_ORDER`].
    pub fn derivative(&self, u: f64, v: f64, du: usize, dv: usize) -> Result<DVec3> {
        let (u, v) = self.check_uv(u, v)?;
        let order = du.saturating_add(dv);
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "surface-derivative-order",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        let s = self.derivatives(u, v, order);
        Ok(s.get(du)
            .and_then(|row| row.get(dv))
            .copied()
            .unwrap_or(DVec3::ZERO))
    }

    /// The unit normal `(S_u × S_v) / |S_u × S_v|` at `(u, v)`.
    ///
    /// Where one partial derivative vanishes — an edge collapsed to a point (a pole, the apex
    /// of a cone) or a degenerate corner — the normal is the limit from inside the domain: if
    /// `S_v = 0` along the line `u = const`, then `S_v(u + ε, v) ≈ ε S_uv` and the normal is
    /// `±S_u × S_uv` (the sign of `ε` that stays in the domain); likewise `±S_uv × S_v` where
    /// `S_u = 0`.
    ///
    /// # Errors
    /// A bad `u` or `v`, and [`SurfaceError::NoNormal`] where even the limit gives no direction:
    /// both partial derivatives vanish, or they are parallel (a fold).
    pub fn normal(&self, u: f64, v: f64) -> Result<DVec3> {
        let (u, v) = self.check_uv(u, v)?;
        let s = self.derivatives(u, v, 2);
        let (su, sv, suv) = (s[1][0], s[0][1], s[1][1]);
        // "Vanishes": rounding of a sum of equal points, far below the other derivative.
        let tiny = 1e-10 * su.length().max(sv.length());
        let inward = |at_end: bool| if at_end { -1.0 } else { 1.0 };
        let (a, b) = if sv.length() <= tiny {
            (inward(u >= self.knots_u.domain().1) * su, suv)
        } else if su.length() <= tiny {
            (inward(v >= self.knots_v.domain().1) * suv, sv)
        } else {
            (su, sv)
        };
        let cross = a.cross(b);
        if cross.length() <= 1e-12 * a.length() * b.length() {
            return Err(Error::Surface(SurfaceError::NoNormal { u, v }));
        }
        Ok(cross / cross.length())
    }
}
