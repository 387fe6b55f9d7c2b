//! Bézier curves, polynomial and rational, in 2D and 3D (syllabus §1–2, rational form §4).
//!
//! A Bézier curve of degree `n` with control points `P_0..P_n` on the interval `[a, b]` is
//! `P(t) = Σ B_i^n(s) P_i` with the local parameter `s = (t − a)/(b − a)` and the Bernstein
//! polynomials `B_i^n(s) = C(n, i) s^i (1 − s)^(n − i)`. With weights `w_i > 0` it is rational:
//! `P(t) = Σ B_i^n(s) w_i P_i / Σ B_i^n(s) w_i`, evaluated as the polynomial curve of the
//! homogeneous points `(w_i P_i, w_i)` followed by one division. The default interval is `[0, 1]`;
//! a parameter outside the interval is an [`Error::ParameterOutOfRange`], never clamped.
//!
//! ```
//! use glam::DVec2;
//! use splinelab::bezier::BezierCurve;
//! // The worked example of the Greek notes (syllabus §2).
//! let pts = [(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
//! let curve = BezierCurve::new(pts.to_vec(), None).unwrap();
//! assert_eq!(curve.evaluate(0.25).unwrap(), DVec2::new(29.0 / 16.0, 23.0 / 16.0));
//! ```

mod arc_length;
mod composite;
mod de_casteljau;
mod derivative;
mod flatten;
mod intersect;

pub use arc_length::{arc_lengths, FAST_PATH_RELATIVE_ERROR, RULE_RHO};
pub use composite::{
    check_continuity, from_polynomial, join, CompositeCurve, Continuity, JoinRule,
};
pub use de_casteljau::{
    bernstein, de_casteljau_point, de_casteljau_triangle, differences, elevate_points, horner,
    horner_fixed, horner_with_derivative_fixed, power_coefficients, split_points,
    subsegment_points, to_power_form,
};
pub(crate) use de_casteljau::{horner_run, PowerForm};
pub use flatten::MAX_FLATTEN_SEGMENTS;
pub use intersect::{LineIntersection, VisitedBox, MAX_INTERSECTION_DEPTH};

use crate::error::{check_finite, Error, Result};
use crate::geom::{check_all_finite, BoundingBox, Cartesian, Params};

/// Highest degree accepted by the constructors (de Casteljau costs O(n²) per point and such
/// degrees are of no practical use: the syllabus recommends piecewise curves above ~5).
pub const MAX_DEGREE: usize = 64;

pub use crate::geom::MAX_SAMPLES;

/// Highest degree sampled by Horner's rule on the power basis; the power form's coefficients
/// grow like `C(n, k) 2^k` and would lose digits to cancellation at high degrees.
pub const HORNER_MAX_DEGREE: usize = de_casteljau::DENSE_MAX_DEGREE;
use crate::geom::{check_out_len, check_weights};

/// A polynomial or rational Bézier curve in 2D (`C = DVec2`) or 3D (`C = DVec3`).
///
/// Control points are stored in homogeneous form `(w_i P_i, w_i)`; a polynomial curve has all
/// weights 1 and is evaluated without the final division, so integer examples stay exact.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<C: Cartesian> {
    homogeneous: Vec<C::Homogeneous>,
    rational: bool,
    a: f64,
    b: f64,
}

impl<C: Cartesian> BezierCurve<C> {
    /// A curve on `[0, 1]` through the given control points; `weights` (one per point, each
    /// finite and > 0) makes it rational.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 2 points, [`Error::TooLarge`] above
    /// [`MAX_DEGREE`], [`Error::NotFinite`] for NaN/infinite numbers, [`Error::WeightCount`] and
    /// [`Error::NonPositiveWeight`] for bad weights.
    pub fn new(points: Vec<C>, weights: Option<&[f64]>) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                needed: 2,
                got: points.len(),
                what: "a Bézier curve",
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
                check_finite(|| format!("coordinate {}", i * C::DIM + k), p.coord(k))?;
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
        check_finite(|| "a".into(), a)?;
        check_finite(|| "b".into(), b)?;
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

    /// True when some weight differs from 1.
    pub fn is_rational(&self) -> bool {
        self.rational
    }

    /// The parameter interval `[a, b]` (default `[0, 1]`).
    pub fn interval(&self) -> (f64, f64) {
        (self.a, self.b)
    }

    /// The Cartesian control points `P_i`.
    pub fn control_points(&self) -> Vec<C> {
        self.homogeneous.iter().map(|&h| self.project(h)).collect()
    }

    /// The weights `w_i` (all 1 for a polynomial curve).
    pub fn weights(&self) -> Vec<f64> {
        self.homogeneous.iter().map(|&h| C::weight_of(h)).collect()
    }

    /// The homogeneous control points `(w_i P_i, w_i)`.
    pub fn homogeneous_points(&self) -> &[C::Homogeneous] {
        &self.homogeneous
    }

    /// Maps a homogeneous point to Cartesian: a division for rational curves, none otherwise.
    #[inline]
    pub(crate) fn project(&self, h: C::Homogeneous) -> C {
        if self.rational {
            C::project(h)
        } else {
            C::numerator(h)
        }
    }

    /// The local parameter `s = (t − a)/(b − a)` of `t`, checked to lie in `[a, b]`.
    pub fn local_parameter(&self, t: f64) -> Result<f64> {
        check_finite(|| "t".into(), t)?;
        if t < self.a || t > self.b {
            return Err(Error::ParameterOutOfRange {
                name: "t",
                value: t,
                min: self.a,
                max: self.b,
            });
        }
        Ok(self.to_local(t))
    }

    #[inline]
    fn to_local(&self, t: f64) -> f64 {
        if self.a == 0.0 && self.b == 1.0 {
            t
        } else {
            ((t - self.a) / (self.b - self.a)).clamp(0.0, 1.0)
        }
    }

    /// The point `P(t)` by de Casteljau's algorithm (O(n²)).
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `t`.
    pub fn evaluate(&self, t: f64) -> Result<C> {
        let s = self.local_parameter(t)?;
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
        check_out_len(out.len(), ts.len(), C::DIM)?;
        for (i, &t) in ts.iter().enumerate() {
            check_finite(|| format!("parameter {i}"), t)?;
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
        check_out_len(out.len(), count, C::DIM)?;
        self.sample_local_into(Params::uniform(0.0, 1.0, count), out);
        Ok(())
    }

    /// Dense evaluation at local parameters: up to [`HORNER_MAX_DEGREE`] by Horner's rule on
    /// the power-basis form computed once (`n` multiply-adds per coordinate instead of
    /// de Casteljau's `n(n+1)/2` lerps; on the Cartesian points for a polynomial curve, on the
    /// homogeneous ones with one division for a rational curve), above that by de Casteljau
    /// with one scratch buffer. The ends `s = 0` and `s = 1` are the end control points exactly.
    fn sample_local_into(&self, params: Params, out: &mut [f64]) {
        let n = self.degree();
        if n > HORNER_MAX_DEGREE {
            let mut scratch = Vec::with_capacity(self.homogeneous.len());
            for (i, o) in (0..params.len()).zip(out.chunks_exact_mut(C::DIM)) {
                self.evaluate_local(params.get(i), &mut scratch).write_to(o);
            }
            return;
        }
        let h = &self.homogeneous;
        let ends = (self.project(h[0]), self.project(h[n]));
        let mut c = [<C::Homogeneous as crate::geom::Point>::ZERO; HORNER_MAX_DEGREE + 1];
        c[..=n].copy_from_slice(h);
        to_power_form(&mut c[..=n]);
        let piece = PowerForm {
            c,
            degree: n,
            start: 0.0,
            scale: 1.0,
        };
        let all = 0..params.len();
        if self.rational {
            horner_run(&piece, params, all, C::project, Some(ends), out);
        } else {
            let piece = piece.map(C::numerator);
            horner_run(&piece, params, all, |q| q, Some(ends), out);
        }
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

    /// A curve with the same rationality on `[0, 1]` and the given homogeneous points.
    fn with_points(&self, homogeneous: Vec<C::Homogeneous>) -> Self {
        BezierCurve {
            homogeneous,
            rational: self.rational,
            a: 0.0,
            b: 1.0,
        }
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
    /// [`Error::IndexOutOfRange`], [`Error::NotFinite`].
    pub fn set_control_point(&mut self, i: usize, p: C) -> Result<()> {
        let count = self.homogeneous.len();
        if i >= count {
            return Err(Error::IndexOutOfRange { index: i, count });
        }
        for k in 0..C::DIM {
            check_finite(|| format!("coordinate {k} of the new point"), p.coord(k))?;
        }
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
        let count = self.homogeneous.len();
        if i >= count {
            return Err(Error::IndexOutOfRange { index: i, count });
        }
        check_finite(|| format!("weight {i}"), w)?;
        if w <= 0.0 {
            return Err(Error::NonPositiveWeight { index: i, value: w });
        }
        let p = self.project(self.homogeneous[i]);
        self.homogeneous[i] = p.to_homogeneous(w);
        self.rational = self.homogeneous.iter().any(|&h| C::weight_of(h) != 1.0);
        Ok(())
    }

    /// The tight axis-aligned bounding box of the curve itself (not of its control polygon),
    /// found per axis by branch and bound on subdivided control polygons (convex hull property):
    /// each bound is within `1e-12` relative of the true extreme.
    pub fn bounding_box(&self) -> BoundingBox<C> {
        let cps = self.control_points();
        let mut min = cps[0].min_by_coord(cps[cps.len() - 1]);
        let mut max = cps[0].max_by_coord(cps[cps.len() - 1]);
        let mut lo = [0.0; 3];
        let mut hi = [0.0; 3];
        for k in 0..C::DIM {
            hi[k] = self.extreme(k, 1.0, max.coord(k));
            lo[k] = -self.extreme(k, -1.0, -min.coord(k)) + 0.0; // + 0.0 turns −0 into 0
        }
        min = C::from_slice(&lo[..C::DIM]);
        max = C::from_slice(&hi[..C::DIM]);
        BoundingBox { min, max }
    }

    /// `max_t sign·P(t)[axis]` (so `−min` for `sign = −1`), starting from the known lower bound `start` (an end point).
    fn extreme(&self, axis: usize, sign: f64, start: f64) -> f64 {
        /// Subdivision depth after which a piece's hull bound is accepted as is.
        const MAX_DEPTH: u32 = 60;
        let scale = self
            .control_points()
            .iter()
            .fold(0.0f64, |m, p| m.max(p.coord(axis).abs()))
            .max(f64::MIN_POSITIVE);
        let accuracy = 1e-13 * scale;
        let mut best = start;
        let mut stack = vec![(self.homogeneous.clone(), 0u32)];
        while let Some((pts, depth)) = stack.pop() {
            let coords = pts.iter().map(|&h| sign * self.project(h).coord(axis));
            let upper = coords.fold(f64::NEG_INFINITY, f64::max);
            if upper <= best + accuracy {
                continue;
            }
            let mid = sign
                * self
                    .project(de_casteljau_point(&pts, 0.5, &mut Vec::new()))
                    .coord(axis);
            best = best.max(mid);
            if depth >= MAX_DEPTH {
                best = best.max(upper);
                continue;
            }
            let (l, r) = split_points(&pts, 0.5);
            stack.push((l, depth + 1));
            stack.push((r, depth + 1));
        }
        best
    }

    /// Number of times the infinite line through `p0` and `p1` crosses the control polygon
    /// (2D; a vertex on the line counts once where the polygon passes through). Used to show
    /// the variation diminishing property: the curve crosses no more often.
    pub fn polygon_line_crossings(&self, p0: C, p1: C) -> usize {
        let d = p1 - p0;
        let side = |p: C| C::cross_norm(d, p - p0);
        let mut count = 0;
        let mut prev_sign = 0.0;
        for p in self.control_points() {
            let s = side(p);
            let sign = if s > 0.0 {
                1.0
            } else if s < 0.0 {
                -1.0
            } else {
                0.0
            };
            if sign != 0.0 {
                if prev_sign != 0.0 && sign != prev_sign {
                    count += 1;
                }
                prev_sign = sign;
            }
        }
        count
    }
}
