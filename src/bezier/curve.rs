//! The Bézier curve type: construction and validation, the interval `[a, b]`, accessors, and
//! the in-place edits of a drag.

use super::{BezierCurve, MAX_DEGREE};
use crate::error::{check_coordinate, check_finite, check_in_range, Error, Result};
use crate::geom::check::{check_point_edit, check_weight_edit};
use crate::geom::{check_all_finite, check_weights, Cartesian};
use crate::prelude::*;

impl<C: Cartesian> BezierCurve<C> {
    /// A curve on `[0, 1]` through the given control points; `weights` (one per point, each
    /// finite and > 0) makes it rational.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 points, [`Error::TooLarge`] above [`MAX_DEGREE`],
    /// [`Error::NotFinite`] for NaN/infinite numbers, [`Error::CoordinateTooLarge`] beyond `1e120`,
    /// [`Error::WeightCount`] and [`Error::NonPositiveWeight`] for bad weights.
    pub fn new(points: Vec<C>, weights: Option<&[f64]>) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                needed: 2,
                got: points.len(),
                what: "bezier-curve",
            });
        }
        if points.len() - 1 > MAX_DEGREE {
            return Err(Error::TooLarge {
                what: "degree",
                value: points.len() - 1,
                max: MAX_DEGREE,
            });
        }
        for (i, p) in points.iter().enumerate() {
            for k in 0..C::DIM {
                check_coordinate("coordinate", Some(i * C::DIM + k), p.coord(k))?;
            }
        }
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
        Ok(BezierCurve {
            homogeneous,
            rational,
            a: 0.0,
            b: 1.0,
        })
    }

    /// Builds a curve from flat coordinates `[x0, y0, (z0,) x1, …]` (see [`BezierCurve::new`]).
    pub fn from_flat(coords: &[f64], weights: Option<&[f64]>) -> Result<Self> {
        Self::new(crate::geom::points_from_flat(coords)?, weights)
    }

    /// A curve from homogeneous control points (weights taken from the last coordinate, which
    /// must be > 0), on `[0, 1]`.
    pub fn from_homogeneous(homogeneous: Vec<C::Homogeneous>) -> Result<Self> {
        let weights: Vec<f64> = homogeneous.iter().map(|&h| C::weight_of(h)).collect();
        check_all_finite(&weights, "weight")?;
        let points = homogeneous
            .iter()
            .zip(&weights)
            .map(|(&h, &w)| if w > 0.0 { C::project(h) } else { C::ZERO })
            .collect();
        Self::new(points, Some(&weights))
    }

    /// The same curve re-parametrised onto `[a, b]` (affine reparametrisation: the control
    /// points do not change; derivatives are divided by `(b − a)` per order).
    ///
    /// # Errors
    /// [`Error::NotFinite`], or [`Error::InvalidInterval`] unless `a < b`.
    pub fn with_interval(mut self, a: f64, b: f64) -> Result<Self> {
        check_finite("a", None, a)?;
        check_finite("b", None, b)?;
        if a >= b || !(b - a).is_finite() {
            return Err(Error::InvalidInterval { a, b });
        }
        self.a = a;
        self.b = b;
        Ok(self)
    }

    /// Degree `n` (number of control points − 1).
    pub fn degree(&self) -> usize {
        self.homogeneous.len() - 1
    }

    /// The parameter interval `[a, b]` (default `[0, 1]`).
    pub fn interval(&self) -> (f64, f64) {
        (self.a, self.b)
    }

    /// The local parameter `s = (t − a)/(b − a)` of `t`, checked to lie in `[a, b]`.
    pub fn local_parameter(&self, t: f64) -> Result<f64> {
        check_in_range("t", t, (self.a, self.b))?;
        Ok(self.to_local(t))
    }

    #[inline]
    pub(super) fn to_local(&self, t: f64) -> f64 {
        if self.a == 0.0 && self.b == 1.0 {
            t
        } else {
            ((t - self.a) / (self.b - self.a)).clamp(0.0, 1.0)
        }
    }

    /// A curve with the same rationality on `[0, 1]` and the given homogeneous points.
    pub(super) fn with_points(&self, homogeneous: Vec<C::Homogeneous>) -> Self {
        BezierCurve {
            homogeneous,
            rational: self.rational,
            a: 0.0,
            b: 1.0,
        }
    }

    /// The same curve traced backwards: control points (and weights) in reverse order.
    pub fn reversed(&self) -> Self {
        let mut homogeneous = self.homogeneous.clone();
        homogeneous.reverse();
        BezierCurve {
            homogeneous,
            ..self.clone()
        }
    }

    /// Moves control point `i` to `p` in place, keeping its weight (the drag path: no
    /// rebuild, only `p` is validated).
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`], [`Error::CoordinateTooLarge`].
    pub fn set_control_point(&mut self, i: usize, p: C) -> Result<()> {
        check_point_edit(i, self.homogeneous.len(), p)?;
        let w = C::weight_of(self.homogeneous[i]);
        self.homogeneous[i] = p.to_homogeneous(w);
        Ok(())
    }

    /// Sets weight `i` in place, keeping the Cartesian point; a curve whose weights become all 1
    /// is polynomial again.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`], [`Error::NonPositiveWeight`].
    pub fn set_weight(&mut self, i: usize, w: f64) -> Result<()> {
        check_weight_edit(i, self.homogeneous.len(), w)?;
        let p = self.project(self.homogeneous[i]);
        self.homogeneous[i] = p.to_homogeneous(w);
        self.rational = self.homogeneous.iter().any(|&h| C::weight_of(h) != 1.0);
        Ok(())
    }
}

crate::curve::impl_curve_traits!(BezierCurve, interval);
