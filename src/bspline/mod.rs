//! B-spline curves, polynomial and rational (NURBS), in 2D and 3D (syllabus §3, §4).
//!
//! A B-spline curve of degree `p` with control points `P_0..P_n` and knots `u_0..u_{n+p+1}` is
//! `C(u) = Σ N_{i,p}(u) P_i` on the domain `[u_p, u_{n+1}]`; with weights it is rational,
//! `C(u) = Σ N_{i,p} w_i P_i / Σ N_{i,p} w_i`, evaluated on the homogeneous points
//! `(w_i P_i, w_i)` with one division at the end. Basis functions are right-continuous and
//! the last non-empty span is closed on the right, so `C(u_{n+1})` is the end of the curve
//! (`P_n` when clamped). A parameter outside the domain is an error, never clamped.
//!
//! ```
//! use glam::DVec2;
//! use splinelab::bspline::BSplineCurve;
//! // Knots 0^{p+1} 1^{p+1}: the B-spline is the Bézier curve.
//! let pts = [(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)].map(|(x, y)| DVec2::new(x, y));
//! let c = BSplineCurve::new(pts.to_vec(), 3, vec![0., 0., 0., 0., 1., 1., 1., 1.], None).unwrap();
//! assert_eq!(c.evaluate(0.25).unwrap(), DVec2::new(29.0 / 16.0, 23.0 / 16.0));
//! ```

mod basis;
mod construct;
mod de_boor;
mod insert;
mod knots;
mod matrix;
mod sample;

pub use basis::{basis_derivatives, basis_functions, BasisScratch};
pub use construct::{knot_vector, parameterize, phantom_points, KnotKind, Parameterization};
pub use de_boor::de_boor_triangle;
pub(crate) use insert::check_insertion;
pub use insert::{boehm_insert, KnotContinuity};
pub use knots::KnotVector;
pub use matrix::uniform_segment_matrix;

use crate::error::{check_finite, Error, Result};
use crate::geom::{
    check_out_len, check_weights, rational_derivative, Cartesian, Params, Point, MAX_DEGREE,
    MAX_DERIVATIVE_ORDER,
};

/// A polynomial or rational B-spline curve in 2D (`C = DVec2`) or 3D (`C = DVec3`).
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<C: Cartesian> {
    homogeneous: Vec<C::Homogeneous>,
    rational: bool,
    knots: KnotVector,
    /// For closed curves: the last `wrap` control points repeat the first `wrap` ones, and
    /// in-place edits keep them equal.
    wrap: usize,
}

impl<C: Cartesian> BSplineCurve<C> {
    /// A curve of degree `degree` through validated control points, knots and optional
    /// weights.
    ///
    /// # Errors
    /// In the documented order: [`Error::NotFinite`] for coordinates, [`Error::DegreeZero`],
    /// [`Error::TooFewPointsForDegree`] for fewer than `p + 1` points, [`Error::TooLarge`]
    /// above [`MAX_DEGREE`], then the knot errors of [`KnotVector::new`], then weights.
    pub fn new(
        points: Vec<C>,
        degree: usize,
        knots: Vec<f64>,
        weights: Option<&[f64]>,
    ) -> Result<Self> {
        for (i, p) in points.iter().enumerate() {
            for k in 0..C::DIM {
                check_finite(|| format!("coordinate {}", i * C::DIM + k), p.coord(k))?;
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
                check_finite(|| format!("coordinate {}", i * C::DIM + k), p.coord(k))?;
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

    /// True when some weight differs from 1.
    pub fn is_rational(&self) -> bool {
        self.rational
    }

    /// For a closed curve, how many control points at the end repeat the first ones (0 if open).
    pub fn wrapped(&self) -> usize {
        self.wrap
    }

    /// The Cartesian control points `P_i` (a closed curve includes the repeated ones).
    pub fn control_points(&self) -> Vec<C> {
        self.homogeneous.iter().map(|&h| self.project(h)).collect()
    }

    /// The weights (all 1 for a polynomial curve).
    pub fn weights(&self) -> Vec<f64> {
        self.homogeneous.iter().map(|&h| C::weight_of(h)).collect()
    }

    /// The homogeneous control points `(w_i P_i, w_i)`.
    pub fn homogeneous_points(&self) -> &[C::Homogeneous] {
        &self.homogeneous
    }

    #[inline]
    pub(crate) fn project(&self, h: C::Homogeneous) -> C {
        if self.rational {
            C::project(h)
        } else {
            C::numerator(h)
        }
    }

    /// `C(u)` from the `p + 1` non-zero basis functions (O(p²)).
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `u`.
    pub fn evaluate(&self, u: f64) -> Result<C> {
        let u = self.knots.check_parameter(u)?;
        let mut basis = vec![0.0; self.degree() + 1];
        let k = self.knots.span(u);
        Ok(self.evaluate_in_span(k, u, &mut basis, &mut BasisScratch::default()))
    }

    #[inline]
    fn evaluate_in_span(
        &self,
        k: usize,
        u: f64,
        basis: &mut [f64],
        scratch: &mut BasisScratch,
    ) -> C {
        let p = self.degree();
        basis_functions(self.knots.as_slice(), k, u, p, basis, scratch, None);
        let mut h = C::Homogeneous::ZERO;
        for (j, &b) in basis.iter().enumerate() {
            h = h + self.homogeneous[k - p + j] * b;
        }
        self.project(h)
    }

    /// Writes `C(u)` for every `u` of `us` into `out` (point-major). All parameters are checked
    /// first; spans are found from the previous one (sorted input walks the knots once), and
    /// one set of buffers serves every point.
    pub fn sample_into(&self, us: &[f64], out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), us.len(), C::DIM)?;
        for &u in us {
            self.knots.check_parameter(u)?;
        }
        self.sample_params_into(Params::Slice(us), out);
        Ok(())
    }

    /// Writes `count` points at equally spaced parameters over the domain (ends included;
    /// `count = 1` gives the start point, as for Bézier curves).
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), count, C::DIM)?;
        let (a, b) = self.domain();
        self.sample_params_into(Params::uniform(a, b, count), out);
        Ok(())
    }

    /// The derivative of order `order` at `u` (order 0 = the point): homogeneous derivatives
    /// `Σ N^{(d)}_{i,p}(u) P^w_i` from the basis derivatives, then the quotient rule for
    /// rational curves. Above the degree a polynomial curve's derivative is zero.
    ///
    /// # Errors
    /// A bad `u`; [`Error::TooLarge`] for a rational curve above order 32.
    pub fn derivative(&self, u: f64, order: usize) -> Result<C> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        if !self.rational && order > p {
            return Ok(C::ZERO);
        }
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "derivative order of a rational curve",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        let k = self.knots.span(u);
        let ders = basis_derivatives(self.knots.as_slice(), k, u, p, order);
        let homogeneous: Vec<C::Homogeneous> = ders
            .iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .fold(C::Homogeneous::ZERO, |acc, (j, &b)| {
                        acc + self.homogeneous[k - p + j] * b
                    })
            })
            .collect();
        if self.rational {
            Ok(rational_derivative::<C>(&homogeneous))
        } else {
            Ok(C::numerator(homogeneous[order]))
        }
    }

    /// Curvature at `u` (see [`crate::geom::curvature`]: signed in 2D, `+∞` at zero velocity).
    pub fn curvature(&self, u: f64) -> Result<f64> {
        Ok(crate::geom::curvature(
            self.derivative(u, 1)?,
            self.derivative(u, 2)?,
        ))
    }

    /// The control points of the derivative curves of the homogeneous curve, orders
    /// `0..=order` (NURBS Book eq. 3.8): `P^(k)_i = (p − k + 1)/(u_{i+p+1} − u_{i+k})
    /// (P^(k−1)_{i+1} − P^(k−1)_i)`; the `k`-th is a B-spline of degree `p − k` whose value at `u`
    /// is `Σ_j N_{s−p+k+j, p−k}(u) P^(k)_{s−p+j}` on the original knots (`s` the span of `u`).
    fn derivative_points(&self, order: usize) -> Vec<Vec<C::Homogeneous>> {
        let p = self.degree();
        let u = self.knots.as_slice();
        let mut out = vec![self.homogeneous.clone()];
        for k in 1..=order.min(p) {
            let prev = &out[k - 1];
            let next = (0..prev.len() - 1)
                .map(|i| {
                    let d = u[i + p + 1] - u[i + k];
                    if d == 0.0 {
                        C::Homogeneous::ZERO
                    } else {
                        (prev[i + 1] - prev[i]) * ((p - k + 1) as f64 / d)
                    }
                })
                .collect();
            out.push(next);
        }
        out
    }

    /// Writes the derivative of order `order` at every `u` of `us` into `out` (point-major),
    /// walking the spans once for sorted input: the derivative control points are computed
    /// once, then each point costs `order + 1` basis evaluations and no allocation (the
    /// quotient rule for rational curves runs on the stack).
    ///
    /// # Errors
    /// A bad parameter, [`Error::TooLarge`] above [`MAX_DERIVATIVE_ORDER`], a wrong `out` length.
    pub fn sample_derivatives_into(&self, us: &[f64], order: usize, out: &mut [f64]) -> Result<()> {
        check_out_len(out.len(), us.len(), C::DIM)?;
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "derivative order",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        for &u in us {
            self.knots.check_parameter(u)?;
        }
        let p = self.degree();
        if !self.rational && order > p {
            out.fill(0.0);
            return Ok(());
        }
        // The derivative control points serve the per-point path only: made on first use, so
        // a first derivative sampled densely (every run in the power form) never builds them.
        let mut points: Option<Vec<Vec<C::Homogeneous>>> = None;
        let mut basis = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        let mut homogeneous = vec![C::Homogeneous::ZERO; order + 1];
        let knots = self.knots.as_slice();
        let mut general = |us: &[f64], out: &mut [f64]| {
            let points = points.get_or_insert_with(|| self.derivative_points(order));
            let mut s = p;
            for (&u, o) in us.iter().zip(out.chunks_exact_mut(C::DIM)) {
                s = self.knots.span_from(u, s);
                for (k, h) in homogeneous.iter_mut().enumerate() {
                    *h = C::Homogeneous::ZERO;
                    if k > p {
                        continue;
                    }
                    let q = p - k;
                    basis_functions(knots, s, u, q, &mut basis[..=q], &mut scratch, None);
                    for (j, &b) in basis[..=q].iter().enumerate() {
                        *h = *h + points[k][s - p + j] * b;
                    }
                }
                let d = if self.rational {
                    rational_derivative::<C>(&homogeneous)
                } else {
                    C::numerator(homogeneous[order])
                };
                d.write_to(o);
            }
        };
        if order == 1 {
            self.first_derivatives_into(us, out, |run, o| general(&us[run], o));
        } else {
            general(us, out);
        }
        Ok(())
    }

    /// `N_{i,p}(u)` for every `i = 0..=n` (zero outside the span's `p + 1`).
    pub fn basis(&self, u: f64) -> Result<Vec<f64>> {
        let (k, local) = self.basis_non_zero(u)?;
        let p = self.degree();
        let mut all = vec![0.0; self.homogeneous.len()];
        if let Some(slot) = all.get_mut(k - p..=k) {
            slot.copy_from_slice(&local);
        }
        Ok(all)
    }

    /// The span `k` of `u` (`u_k ≤ u < u_{k+1}`, a non-empty span; `u = b` is in the last one)
    /// and the `p + 1` basis functions that can be non-zero there, `N_{k−p,p}(u) … N_{k,p}(u)`
    /// (NURBS Book A2.1 and A2.2; they sum to 1). O(p²) whatever the number of points.
    pub fn basis_non_zero(&self, u: f64) -> Result<(usize, Vec<f64>)> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        let k = self.knots.span(u);
        let mut local = vec![0.0; p + 1];
        basis_functions(
            self.knots.as_slice(),
            k,
            u,
            p,
            &mut local,
            &mut BasisScratch::default(),
            None,
        );
        Ok((k, local))
    }

    /// The triangular table of the Cox–de Boor recurrence at `u`: level `r = 0..=p` holds
    /// `N_{k−r,r}(u) … N_{k,r}(u)` for the span `k` of `u`. Returns `(k, levels)`.
    pub fn basis_table(&self, u: f64) -> Result<(usize, Vec<Vec<f64>>)> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        let k = self.knots.span(u);
        let mut local = vec![0.0; p + 1];
        let mut levels = Vec::with_capacity(p + 1);
        basis_functions(
            self.knots.as_slice(),
            k,
            u,
            p,
            &mut local,
            &mut BasisScratch::default(),
            Some(&mut levels),
        );
        Ok((k, levels))
    }

    /// All basis functions sampled at `count` equally spaced parameters over the domain, for
    /// plotting: `N_{i,p}(u_j)` at index `i·count + j` (i-major). One pass over the spans.
    pub fn basis_curves(&self, count: usize) -> Result<Vec<f64>> {
        let n1 = self.homogeneous.len();
        check_out_len(count.saturating_mul(n1), count.saturating_mul(n1), 1)?;
        let (a, b) = self.domain();
        let p = self.degree();
        let step = if count > 1 {
            (b - a) / (count - 1) as f64
        } else {
            0.0
        };
        let mut out = vec![0.0; n1 * count];
        let mut local = vec![0.0; p + 1];
        let mut scratch = BasisScratch::default();
        let mut k = p;
        for j in 0..count {
            let u = if j + 1 == count {
                b
            } else {
                a + step * j as f64
            };
            k = self.knots.span_from(u, k);
            basis_functions(
                self.knots.as_slice(),
                k,
                u,
                p,
                &mut local,
                &mut scratch,
                None,
            );
            for (r, &v) in local.iter().enumerate() {
                out[(k - p + r) * count + j] = v;
            }
        }
        Ok(out)
    }

    /// The derivatives of every basis function at `u`: row `d = 0..=order` holds
    /// `N^{(d)}_{i,p}(u)` for `i = 0..=n`, flattened row by row.
    pub fn basis_derivatives_at(&self, u: f64, order: usize) -> Result<Vec<f64>> {
        let u = self.knots.check_parameter(u)?;
        if order > MAX_DEGREE {
            return Err(Error::TooLarge {
                what: "order",
                value: order,
                max: MAX_DEGREE,
            });
        }
        let p = self.degree();
        let n1 = self.homogeneous.len();
        let k = self.knots.span(u);
        let ders = basis_derivatives(self.knots.as_slice(), k, u, p, order);
        let mut out = vec![0.0; (order + 1) * n1];
        for (d, row) in ders.iter().enumerate() {
            out[d * n1 + k - p..=d * n1 + k].copy_from_slice(row);
        }
        Ok(out)
    }

    /// de Boor's triangle at `u` in Cartesian form (levels concatenated, the `p + 1` active
    /// points first, `C(u)` last). Rational curves run on homogeneous points, then project.
    pub fn de_boor(&self, u: f64) -> Result<Vec<C>> {
        Ok(self
            .de_boor_homogeneous(u)?
            .into_iter()
            .map(|h| self.project(h))
            .collect())
    }

    /// de Boor's triangle on the homogeneous points.
    pub fn de_boor_homogeneous(&self, u: f64) -> Result<Vec<C::Homogeneous>> {
        let u = self.knots.check_parameter(u)?;
        let k = self.knots.span(u);
        Ok(de_boor_triangle(
            &self.homogeneous,
            self.knots.as_slice(),
            self.degree(),
            k,
            u,
        ))
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
        let count = self.homogeneous.len();
        if i >= count {
            return Err(Error::IndexOutOfRange { index: i, count });
        }
        for k in 0..C::DIM {
            check_finite(|| format!("coordinate {k} of the new point"), p.coord(k))?;
        }
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
        let count = self.homogeneous.len();
        if i >= count {
            return Err(Error::IndexOutOfRange { index: i, count });
        }
        check_finite(|| format!("weight {i}"), w)?;
        if w <= 0.0 {
            return Err(Error::NonPositiveWeight { index: i, value: w });
        }
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
