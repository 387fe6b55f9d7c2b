//! Points by de Casteljau (one at a time, or dense by Horner on the power form), the
//! construction triangle, subdivision and degree elevation.

use super::de_casteljau::bernstein_small;
use super::{
    de_casteljau_point, de_casteljau_triangle, elevate_points, horner_run, split_points,
    to_power_form, BezierCurve, PowerForm, HORNER_MAX_DEGREE, MAX_DEGREE,
};
use crate::error::{check_finite, Error, Result};
use crate::geom::{check_out_len, Cartesian, Params, STACK_DEGREE};
use crate::prelude::*;

impl<C: Cartesian> BezierCurve<C> {
    /// The point `P(t)` by de Casteljau's algorithm (O(n²)).
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `t`.
    pub fn evaluate(&self, t: f64) -> Result<C> {
        let s = self.local_parameter(t)?;
        let n = self.degree();
        if n <= STACK_DEGREE {
            // One point allocates nothing: the Bernstein form on the stack.
            let h = &self.homogeneous;
            return Ok(self.project(bernstein_small(n, s, |i| h[i])));
        }
        let mut scratch = Vec::new();
        Ok(self.evaluate_local(s, &mut scratch))
    }

    /// `P` at the local parameter `s ∈ [0, 1]`, with a reusable scratch buffer (no checks).
    #[inline]
    pub(crate) fn evaluate_local(&self, s: f64, scratch: &mut Vec<C::Homogeneous>) -> C {
        self.project(de_casteljau_point(&self.homogeneous, s, scratch))
    }

    /// Writes `P(t)` for every `t` of `ts` into `out` (`ts.len()·DIM` values, point-major).
    /// Every parameter is validated before anything is written; one scratch buffer serves all.
    ///
    /// # Errors
    /// As [`BezierCurve::evaluate`], naming the index of the first bad parameter;
    /// [`Error::BufferLength`] when `out` has the wrong length.
    pub fn sample_into(&self, ts: &[f64], out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), ts.len(), C::DIM, self.degree())?;
        for (i, &t) in ts.iter().enumerate() {
            check_finite("parameter", Some(i), t)?;
            self.local_parameter(t)?;
        }
        if self.a == 0.0 && self.b == 1.0 {
            self.sample_local_into(Params::Slice(ts), out);
        } else {
            let local: Vec<f64> = ts.iter().map(|&t| self.to_local(t)).collect();
            self.sample_local_into(Params::Slice(&local), out);
        }
        Ok(())
    }

    /// Writes `count` points at equally spaced parameters `a + (b − a)·k/(count − 1)` into
    /// `out` (`count·DIM` values); `count = 1` gives the start point.
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), count, C::DIM, self.degree())?;
        self.sample_local_into(Params::uniform(0.0, 1.0, count), out);
        Ok(())
    }

    /// Dense evaluation at local parameters: up to [`HORNER_MAX_DEGREE`] by Horner's rule on
    /// the power-basis form computed once (`n` multiply-adds per coordinate instead of
    /// de Casteljau's `n(n+1)/2` lerps; on the Cartesian points for a polynomial curve, on the
    /// homogeneous ones with one division for a rational curve), above that by de Casteljau
    /// with one scratch buffer. The ends `s = 0` and `s = 1` are the end control points exactly.
    fn sample_local_into(&self, params: Params, out: &mut [f64]) {
        let Some(piece) = self.power_form() else {
            let mut scratch = Vec::with_capacity(self.homogeneous.len());
            for (i, o) in (0..params.len()).zip(out.chunks_exact_mut(C::DIM)) {
                self.evaluate_local(params.get(i), &mut scratch).write_to(o);
            }
            return;
        };
        let (h, n) = (&self.homogeneous, self.degree());
        let ends = (self.project(h[0]), self.project(h[n]));
        let all = 0..params.len();
        if self.rational {
            horner_run(&piece, params, all, C::project, Some(ends), out);
        } else {
            let piece = piece.map(C::numerator);
            horner_run(&piece, params, all, |q| q, Some(ends), out);
        }
    }

    /// The homogeneous power form on `[0, 1]` for the dense kernel: `None` above
    /// [`HORNER_MAX_DEGREE`] or when a coefficient overflows (see [`PowerForm::is_finite`]).
    fn power_form(&self) -> Option<PowerForm<C::Homogeneous>> {
        let n = self.degree();
        if n > HORNER_MAX_DEGREE {
            return None;
        }
        let mut c = [<C::Homogeneous as crate::geom::Point>::ZERO; HORNER_MAX_DEGREE + 1];
        c[..=n].copy_from_slice(&self.homogeneous);
        to_power_form(&mut c[..=n]);
        let piece = PowerForm {
            c,
            degree: n,
            start: 0.0,
            scale: 1.0,
        };
        piece.is_finite().then_some(piece)
    }

    /// de Casteljau's triangle at `t` in Cartesian form: all levels concatenated, level 0 (the
    /// control points) first; `(n + 1)(n + 2)/2` points, the last one `P(t)`. For a rational
    /// curve each homogeneous point is projected.
    pub fn de_casteljau(&self, t: f64) -> Result<Vec<C>> {
        Ok(self
            .de_casteljau_homogeneous(t)?
            .into_iter()
            .map(|h| self.project(h))
            .collect())
    }

    /// de Casteljau's triangle on the homogeneous points (the construction in `(wx, wy, w)`
    /// space that the rational curve projects from).
    pub fn de_casteljau_homogeneous(&self, t: f64) -> Result<Vec<C::Homogeneous>> {
        let s = self.local_parameter(t)?;
        Ok(de_casteljau_triangle(&self.homogeneous, s))
    }

    /// Splits at `t`: the left curve has the triangle's top edge as control points, the right
    /// its hypotenuse (syllabus §2). Each half is parametrised on `[0, 1]`.
    ///
    /// # Errors
    /// A bad `t` (see [`BezierCurve::evaluate`]).
    pub fn split(&self, t: f64) -> Result<(Self, Self)> {
        let s = self.local_parameter(t)?;
        let (l, r) = split_points(&self.homogeneous, s);
        Ok((self.with_points(l), self.with_points(r)))
    }

    /// Degree elevation: the same curve (same interval) with one more control point,
    /// `Q_i = i/(n+1) P_{i−1} + (1 − i/(n+1)) P_i` (on homogeneous points when rational).
    ///
    /// # Errors
    /// [`Error::TooLarge`] above [`MAX_DEGREE`].
    pub fn elevate(&self) -> Result<Self> {
        if self.degree() + 1 > MAX_DEGREE {
            return Err(Error::TooLarge {
                what: "degree",
                value: self.degree() + 1,
                max: MAX_DEGREE,
            });
        }
        Ok(BezierCurve {
            homogeneous: elevate_points(&self.homogeneous),
            ..self.clone()
        })
    }
}
