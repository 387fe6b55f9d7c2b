//! The B-spline curve type: construction and validation, accessors, and the in-place edits of
//! a drag (which keep the wrapped points of a closed curve equal).

use super::{BSplineCurve, KnotVector};
use crate::error::{check_coordinate, Error, Result};
use crate::geom::check::{check_point_edit, check_weight_edit};
use crate::geom::{check_weights, Cartesian, MAX_DEGREE};
use crate::prelude::*;

impl<C: Cartesian> BSplineCurve<C> {
    /// A curve of degree `degree` through validated control points, knots and optional
    /// weights.
    ///
    /// # Errors
    /// In the documented order: [`Error::NotFinite`], [`Error::CoordinateTooLarge`] for
    /// coordinates, [`Error::DegreeZero`], [`Error::TooFewPointsForDegree`] for fewer than `p + 1`
    /// points, [`Error::TooLarge`] above [`MAX_DEGREE`], then the knot errors of
    /// [`KnotVector::new`], then weights.
    pub fn new(
        points: Vec<C>,
        degree: usize,
        knots: Vec<f64>,
        weights: Option<&[f64]>,
    ) -> Result<Self> {
        for (i, p) in points.iter().enumerate() {
            for k in 0..C::DIM {
                check_coordinate("coordinate", Some(i * C::DIM + k), p.coord(k))?;
            }
        }
        check_degree(degree, points.len())?;
        let knots = KnotVector::new(knots, degree, points.len())?;
        let homogeneous = match weights {
            None => points.iter().map(|&p| p.to_homogeneous(1.0)).collect(),
            Some(w) => {
                check_weights(w, points.len())?;
                points
                    .iter()
                    .zip(w)
                    .map(|(&p, &wi)| p.to_homogeneous(wi))
                    .collect()
            }
        };
        let rational = weights.is_some_and(|w| w.iter().any(|&wi| wi != 1.0));
        Ok(BSplineCurve {
            homogeneous,
            rational,
            knots,
            wrap: 0,
        })
    }

    /// From flat coordinates `[x0, y0, (z0,) x1, …]` (see [`BSplineCurve::new`]).
    pub fn from_flat(
        coords: &[f64],
        degree: usize,
        knots: Vec<f64>,
        weights: Option<&[f64]>,
    ) -> Result<Self> {
        Self::new(
            crate::geom::points_from_flat(coords)?,
            degree,
            knots,
            weights,
        )
    }

    /// A closed (periodic) curve through the cycle `P_0..P_n`: the first `p` points are
    /// repeated at the end and the knots are uniform (`u_i = i`), so the curve closes with
    /// full continuity `C^{p−1}`; its domain is `[p, n + p + 1]`. Edits keep the copies equal.
    ///
    /// # Errors
    /// As [`BSplineCurve::new`]; a closed curve needs at least `p + 1` distinct points.
    pub fn closed(points: Vec<C>, degree: usize, weights: Option<&[f64]>) -> Result<Self> {
        for (i, p) in points.iter().enumerate() {
            for k in 0..C::DIM {
                check_coordinate("coordinate", Some(i * C::DIM + k), p.coord(k))?;
            }
        }
        check_degree(degree, points.len())?;
        if let Some(w) = weights {
            check_weights(w, points.len())?;
        }
        let mut wrapped = points.clone();
        wrapped.extend_from_slice(&points[..degree]);
        let w: Option<Vec<f64>> = weights.map(|w| {
            let mut v = w.to_vec();
            v.extend_from_slice(&w[..degree]);
            v
        });
        let knots = (0..wrapped.len() + degree + 1).map(|i| i as f64).collect();
        let mut curve = Self::new(wrapped, degree, knots, w.as_deref())?;
        curve.wrap = degree;
        Ok(curve)
    }

    /// Marks the last `wrap` control points as copies of the first `wrap` (which the caller has
    /// made equal, with knots whose gaps repeat with the period): a closed curve built by
    /// periodic interpolation, whose edits then keep the copies equal.
    pub(crate) fn with_wrapped(mut self, wrap: usize) -> Self {
        self.wrap = wrap.min(self.homogeneous.len() / 2);
        self
    }

    /// Degree `p`.
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The knot vector.
    pub fn knots(&self) -> &KnotVector {
        &self.knots
    }

    /// The domain `[u_p, u_{n+1}]`.
    pub fn domain(&self) -> (f64, f64) {
        self.knots.domain()
    }

    /// For a closed curve, how many control points at the end repeat the first ones (0 if open).
    pub fn wrapped(&self) -> usize {
        self.wrap
    }

    /// The span index `k` of `u` (`u_k <= u < u_{k+1}`; the last span is closed).
    pub fn span(&self, u: f64) -> Result<usize> {
        Ok(self.knots.span(self.knots.check_parameter(u)?))
    }

    /// Moves control point `i` in place (for a closed curve, its repeated copy too).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`].
    pub fn set_control_point(&mut self, i: usize, p: C) -> Result<()> {
        check_point_edit(i, self.homogeneous.len(), p)?;
        for j in self.copies_of(i) {
            let w = C::weight_of(self.homogeneous[j]);
            self.homogeneous[j] = p.to_homogeneous(w);
        }
        Ok(())
    }

    /// Sets weight `i` in place (for a closed curve, its copy's too).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`], [`Error::NonPositiveWeight`].
    pub fn set_weight(&mut self, i: usize, w: f64) -> Result<()> {
        check_weight_edit(i, self.homogeneous.len(), w)?;
        for j in self.copies_of(i) {
            let p = self.project(self.homogeneous[j]);
            self.homogeneous[j] = p.to_homogeneous(w);
        }
        self.rational = self.homogeneous.iter().any(|&h| C::weight_of(h) != 1.0);
        Ok(())
    }

    /// The indices that hold the same point as `i` (itself, plus its copy on a closed curve).
    fn copies_of(&self, i: usize) -> impl Iterator<Item = usize> {
        let distinct = self.homogeneous.len() - self.wrap;
        let base = if i >= distinct { i - distinct } else { i };
        let copy = (base < self.wrap).then_some(base + distinct);
        std::iter::once(base).chain(copy)
    }
}

/// Checks the degree against the number of points: `1 <= p <= n` and `p <= MAX_DEGREE`.
pub(crate) fn check_degree(degree: usize, points: usize) -> Result<()> {
    if degree == 0 {
        return Err(Error::DegreeZero {});
    }
    if degree > MAX_DEGREE {
        return Err(Error::TooLarge {
            what: "degree",
            value: degree,
            max: MAX_DEGREE,
        });
    }
    if points < degree + 1 {
        return Err(Error::TooFewPointsForDegree {
            degree,
            got: points,
        });
    }
    Ok(())
}

crate::curve::impl_curve_traits!(BSplineCurve, domain);
