//! Capabilities shared by every curve type, as small traits with default methods (kurbo's
//! `ParamCurve` pattern): what can be written once in terms of a few required methods is
//! written here once, and [`crate::bezier::BezierCurve`], [`crate::bspline::BSplineCurve`] and
//! [`crate::bezier::CompositeCurve`] implement the required part.
//!
//! - [`ParamCurve`]: a domain and points on it; dense sampling into a buffer by default.
//! - [`ParamCurveDeriv`]: derivatives; the curvature from the first two by default.
//! - [`ControlPolygon`]: curves stored as homogeneous control points `(w_i P_i, w_i)`; the
//!   Cartesian points, the weights and their bounding box by default.
//!
//! Bring them into scope with `use splinelab::prelude::*;`.

use crate::error::Result;
use crate::geom::{check_out_len, BoundingBox, Cartesian, Params, Point};

/// A curve `C(t)` over a closed parameter domain `[a, b]`.
pub trait ParamCurve {
    /// The point type: `DVec2` or `DVec3`.
    type Point: Cartesian;

    /// The parameter domain `[a, b]` (`[0, 1]` for a Bézier curve unless re-parametrised,
    /// `[u_p, u_{n+1}]` for a B-spline).
    fn domain(&self) -> (f64, f64);

    /// The degree whose `(p + 1)²` prices one point in the dense-sampling work budget
    /// ([`crate::geom::MAX_SAMPLE_WORK`]): the curve's degree, the highest piece's for a
    /// piecewise curve.
    fn sample_degree(&self) -> usize;

    /// The point at `t`.
    ///
    /// # Errors
    /// [`crate::Error::NotFinite`] or [`crate::Error::ParameterOutOfRange`] for a `t` outside
    /// the domain (never clamped).
    fn evaluate(&self, t: f64) -> Result<Self::Point>;

    /// Writes `C(t)` for every `t` of `ts` into `out` (point-major, `ts.len()·DIM` numbers).
    /// The default evaluates point by point without allocating; curve types with a dense
    /// kernel (span walking, Horner on the power form) override it.
    ///
    /// # Errors
    /// [`crate::Error::BufferLength`] for a wrong `out` length, then as [`Self::evaluate`] for
    /// the first bad parameter (the points before it are written).
    fn sample_into(&self, ts: &[f64], out: &mut [f64]) -> Result<()> {
        let dim = Self::Point::DIM;
        check_out_len(out.len(), ts.len(), dim, self.sample_degree())?;
        for (&t, o) in ts.iter().zip(out.chunks_exact_mut(dim)) {
            self.evaluate(t)?.write_to(o);
        }
        Ok(())
    }

    /// Writes `count` points at the equally spaced parameters `a + (b − a)·k/(count − 1)` (the
    /// last exactly `b`; `count = 1` gives the start point) into `out`.
    ///
    /// # Errors
    /// [`crate::Error::BufferLength`] for a wrong `out` length.
    fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<()> {
        let dim = Self::Point::DIM;
        check_out_len(out.len(), count, dim, self.sample_degree())?;
        let (a, b) = self.domain();
        let params = Params::uniform(a, b, count);
        for (k, o) in out.chunks_exact_mut(dim).enumerate() {
            self.evaluate(params.get(k))?.write_to(o);
        }
        Ok(())
    }
}

/// A curve with derivatives of any order.
pub trait ParamCurveDeriv: ParamCurve {
    /// The derivative `C^(order)(t)` (order 0 is the point; above the degree of a polynomial
    /// curve, the zero vector).
    ///
    /// # Errors
    /// As [`ParamCurve::evaluate`]; [`crate::Error::TooLarge`] for a rational curve above
    /// [`crate::geom::MAX_DERIVATIVE_ORDER`].
    fn derivative(&self, t: f64, order: usize) -> Result<Self::Point>;

    /// Curvature at `t` from the first two derivatives: in 2D the signed
    /// `κ = (x'y'' − y'x'') / |C'|³` (positive where the curve turns counter-clockwise), in 3D
    /// `κ = |C' × C''| / |C'|³ >= 0`; `+∞` where the velocity vanishes (a cusp, or an end whose
    /// neighbouring control point coincides with it), 0 on a straight piece (see
    /// [`crate::geom::curvature`]).
    ///
    /// # Errors
    /// As [`ParamCurveDeriv::derivative`].
    fn curvature(&self, t: f64) -> Result<f64> {
        Ok(crate::geom::curvature(
            self.derivative(t, 1)?,
            self.derivative(t, 2)?,
        ))
    }
}

/// A curve stored as homogeneous control points `(w_i P_i, w_i)`: polynomial curves have
/// every `w_i = 1` and are projected without a division.
pub trait ControlPolygon: ParamCurve {
    /// The homogeneous control points `(w_i P_i, w_i)`.
    fn homogeneous_points(&self) -> &[<Self::Point as Cartesian>::Homogeneous];

    /// Whether any weight differs from 1.
    fn is_rational(&self) -> bool;

    /// Maps a homogeneous point to Cartesian: a division by `w` for rational curves, none
    /// otherwise (so integer examples of polynomial curves stay exact).
    #[inline]
    fn project(&self, h: <Self::Point as Cartesian>::Homogeneous) -> Self::Point {
        if self.is_rational() {
            Self::Point::project(h)
        } else {
            Self::Point::numerator(h)
        }
    }

    /// The Cartesian control points `P_i` (a closed B-spline includes the repeated ones).
    fn control_points(&self) -> Vec<Self::Point> {
        self.homogeneous_points()
            .iter()
            .map(|&h| self.project(h))
            .collect()
    }

    /// The weights `w_i` (all 1 for a polynomial curve).
    fn weights(&self) -> Vec<f64> {
        self.homogeneous_points()
            .iter()
            .map(|&h| Self::Point::weight_of(h))
            .collect()
    }

    /// The bounding box of the control points, which contains the curve (convex hull
    /// property, weights > 0). `None` only for a curve without points, which the constructors
    /// reject.
    fn control_box(&self) -> Option<BoundingBox<Self::Point>> {
        BoundingBox::of_points(&self.control_points())
    }
}

/// Implements [`ParamCurve`] and [`ControlPolygon`] for a curve type `$ty<C>` with the same
/// fields and inherent methods as `BezierCurve` and `BSplineCurve` (`homogeneous`, `rational`;
/// `evaluate`, `sample_into`, `sample_uniform_into`), the domain given by its method `$domain`.
macro_rules! impl_curve_traits {
    ($ty:ident, $domain:ident) => {
        impl<C: $crate::geom::Cartesian> $crate::curve::ParamCurve for $ty<C> {
            type Point = C;

            fn domain(&self) -> (f64, f64) {
                $ty::$domain(self)
            }

            fn sample_degree(&self) -> usize {
                self.degree()
            }

            fn evaluate(&self, t: f64) -> $crate::error::Result<C> {
                $ty::evaluate(self, t)
            }

            fn sample_into(&self, params: &[f64], out: &mut [f64]) -> $crate::error::Result<()> {
                $ty::sample_into(self, params, out)
            }

            fn sample_uniform_into(
                &self,
                count: usize,
                out: &mut [f64],
            ) -> $crate::error::Result<()> {
                $ty::sample_uniform_into(self, count, out)
            }
        }

        impl<C: $crate::geom::Cartesian> $crate::curve::ControlPolygon for $ty<C> {
            fn homogeneous_points(&self) -> &[C::Homogeneous] {
                &self.homogeneous
            }

            fn is_rational(&self) -> bool {
                self.rational
            }
        }
    };
}
pub(crate) use impl_curve_traits;
