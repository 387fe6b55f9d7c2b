//! Knot insertion (Boehm), refinement, Bézier extraction and continuity at the knots
//! (syllabus §3).

use super::{BSplineCurve, KnotVector};
use crate::bezier::BezierCurve;
use crate::error::{check_finite, Error, Result};
use crate::geom::{Cartesian, Point};

/// The continuity at one distinct interior knot: multiplicity `r` gives `C^{p−r}`
/// (`continuity = −1` for `r = p + 1`, where the curve may break).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KnotContinuity {
    /// The knot value.
    pub knot: f64,
    /// How many times it appears.
    pub multiplicity: usize,
    /// `p − r` (−1: no continuity guaranteed).
    pub continuity: i32,
}

/// One Boehm insertion of `u` (in span `k` of `knots`, degree `p`) into `points`:
/// `Q_i = P_i` for `i <= k − p`; `Q_i = (1 − α_i) P_{i−1} + α_i P_i` with
/// `α_i = (u − u_i)/(u_{i+p} − u_i)` for `k − p + 1 <= i <= k`; `Q_i = P_{i−1}` for `i >= k + 1`.
pub fn boehm_insert<P: Point>(points: &[P], knots: &[f64], p: usize, k: usize, u: f64) -> Vec<P> {
    let mut out = Vec::with_capacity(points.len() + 1);
    out.extend_from_slice(&points[..=k - p]);
    for i in k - p + 1..=k {
        let denominator = knots[i + p] - knots[i];
        let alpha = if denominator == 0.0 {
            0.0
        } else {
            (u - knots[i]) / denominator
        };
        out.push(points[i - 1].lerp_to(points[i], alpha));
    }
    out.extend_from_slice(&points[k..]);
    out
}

impl<C: Cartesian> BSplineCurve<C> {
    /// The same curve with the knot `u` inserted `times` times (Boehm's algorithm, once per
    /// insertion): the shape does not change, the control polygon moves towards the curve.
    ///
    /// # Errors
    /// A bad `u`; [`Error::Mismatch`] when the multiplicity of `u` would exceed `p + 1`.
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<Self> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        let s = self.knots.multiplicity(u);
        if s + times > p + 1 {
            return Err(Error::Mismatch {
                message: format!(
                    "inserting knot {u} {times} time(s) would give it multiplicity {}; a degree-{p} curve allows at most p+1 = {}",
                    s + times,
                    p + 1
                ),
            });
        }
        let mut points = self.homogeneous.clone();
        let mut knots = self.knots.clone();
        for _ in 0..times {
            let k = knots.span(u);
            points = boehm_insert(&points, knots.as_slice(), p, k, u);
            knots = KnotVector::new(knots.with_inserted(u, 1), p, points.len())?;
        }
        if !self.rational {
            // Keep polynomial weights exactly 1 ((1 − α)·1 + α·1 may round).
            for h in &mut points {
                *h = C::numerator(*h).to_homogeneous(1.0);
            }
        }
        Ok(BSplineCurve {
            homogeneous: points,
            rational: self.rational,
            knots,
            wrap: 0,
        })
    }

    /// Knot refinement: inserts every value of `us` (in any order; repeated values raise the
    /// multiplicity) and returns the refined curve, same shape.
    ///
    /// # Errors
    /// As [`BSplineCurve::insert_knot`] for each value.
    pub fn refine(&self, us: &[f64]) -> Result<Self> {
        let mut sorted = us.to_vec();
        for (i, &u) in sorted.iter().enumerate() {
            check_finite(|| format!("knot {i} to insert"), u)?;
        }
        sorted.sort_by(f64::total_cmp);
        let mut curve = self.clone();
        for u in sorted {
            curve = curve.insert_knot(u, 1)?;
        }
        curve.wrap = 0;
        Ok(curve)
    }

    /// Bézier extraction: every distinct knot of the domain is raised to multiplicity `p`,
    /// after which the `p + 1` control points of each non-empty span are that span's Bézier
    /// control points. Returns the segments in span order, each on its own `t ∈ [0, 1]`
    /// (rational segments keep their weights).
    pub fn to_bezier(&self) -> Result<Vec<BezierCurve<C>>> {
        let p = self.degree();
        let (a, b) = self.domain();
        let mut values: Vec<f64> = self
            .knots
            .as_slice()
            .iter()
            .copied()
            .filter(|&u| u >= a && u <= b)
            .collect();
        values.dedup();
        let mut curve = self.clone();
        for u in values {
            let s = curve.knots.multiplicity(u);
            if s < p {
                curve = curve.insert_knot(u, p - s)?;
            }
        }
        curve
            .knots
            .spans()
            .map(|k| {
                let segment = curve.homogeneous[k - p..=k].to_vec();
                if curve.rational {
                    BezierCurve::from_homogeneous(segment)
                } else {
                    BezierCurve::new(segment.into_iter().map(C::numerator).collect(), None)
                }
            })
            .collect()
    }

    /// The continuity guaranteed at each distinct knot strictly inside the domain:
    /// multiplicity `r` gives `C^{p−r}`.
    pub fn knot_continuity(&self) -> Vec<KnotContinuity> {
        let p = self.degree() as i32;
        self.knots
            .interior_breaks()
            .into_iter()
            .map(|(knot, r)| KnotContinuity {
                knot,
                multiplicity: r,
                continuity: p - r as i32,
            })
            .collect()
    }
}
