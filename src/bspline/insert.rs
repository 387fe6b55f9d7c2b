//! Knot insertion (Boehm), refinement, Bézier extraction and continuity at the knots
//! (syllabus §3).

use super::{BSplineCurve, KnotVector};
use crate::bezier::BezierCurve;
use crate::error::{check_finite, Error, Result};
use crate::geom::{result_len, Cartesian, Point};

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

/// Inserting a knot `times` times where it already has multiplicity `s`: at most `p + 1` in all
/// (the curve breaks there), so more is [`Error::InsertionMultiplicity`]. `name` is the parameter's name in
/// the message (`None` for a curve, `"u"` or `"v"` for a surface).
///
/// This is the budget of the insertion loops (one Boehm pass per copy): `times ≤ p + 1 − s ≤
/// MAX_DEGREE + 1`. It compares `times` with the room left, `p + 1 − s` (`s ≤ p + 1` holds for
/// a valid knot vector), so a count near `usize::MAX` from JavaScript cannot wrap `s + times`
/// round to a small number and start billions of insertions.
pub(crate) fn check_insertion(
    name: Option<&'static str>,
    knot: f64,
    s: usize,
    times: usize,
    p: usize,
) -> Result<()> {
    if (p + 1).checked_sub(s).is_some_and(|room| times <= room) {
        return Ok(());
    }
    Err(Error::InsertionMultiplicity {
        name,
        knot,
        times,
        // Shown in the message only (the check above does not add); beyond usize the count
        // itself says enough.
        multiplicity: s.saturating_add(times),
        degree: p,
    })
}

/// Boehm's factor `α_i = (u − u_i)/(u_{i+p} − u_i)` for inserting `u` (degree `p`); a zero
/// denominator (impossible for `k − p + 1 <= i <= k` in a non-empty span `k`) counts as 0.
#[inline]
pub fn boehm_alpha(knots: &[f64], p: usize, i: usize, u: f64) -> f64 {
    let denominator = knots[i + p] - knots[i];
    if denominator == 0.0 {
        0.0
    } else {
        (u - knots[i]) / denominator
    }
}

/// The `p` factors of one Boehm insertion of `u` in span `k`:
/// `α_i = (u − u_i)/(u_{i+p} − u_i)` for `i = k − p + 1 ..= k`, in that order (the weights in
/// `Q_i = (1 − α_i) P_{i−1} + α_i P_i`).
pub fn boehm_alphas(knots: &[f64], p: usize, k: usize, u: f64) -> Vec<f64> {
    (k + 1 - p..=k)
        .map(|i| boehm_alpha(knots, p, i, u))
        .collect()
}

/// One Boehm insertion of `u` (in span `k` of `knots`, degree `p`) into `points`:
/// `Q_i = P_i` for `i <= k − p`; `Q_i = (1 − α_i) P_{i−1} + α_i P_i` with
/// `α_i = (u − u_i)/(u_{i+p} − u_i)` for `k − p + 1 <= i <= k`; `Q_i = P_{i−1}` for `i >= k + 1`.
pub fn boehm_insert<P: Point>(points: &[P], knots: &[f64], p: usize, k: usize, u: f64) -> Vec<P> {
    let mut out = Vec::with_capacity(points.len() + 1);
    out.extend_from_slice(&points[..=k - p]);
    for i in k - p + 1..=k {
        out.push(points[i - 1].lerp_to(points[i], boehm_alpha(knots, p, i, u)));
    }
    out.extend_from_slice(&points[k..]);
    out
}

/// Knot refinement of one control polygon (NURBS Book A5.4): the points and knots after
/// inserting every value of `x` into `knots` at once.
///
/// `x` must be non-empty, sorted, inside the domain and keep every multiplicity ≤ `p + 1`
/// (the callers check). The head `P_0..P_{a−p}` and tail `P_{b−1}..P_n` of the polygon are
/// copied (`a`, `b − 1` the spans of the first and last new knot); the new knots are then
/// inserted from the last to the first, each updating the `p` points around it with
/// `Q_{l−1} = α Q_{l−1} + (1 − α) Q_l`, `α = (ū_{k+l} − x_j)/(ū_{k+l} − u_{i−p+l})`:
/// O(n + m·p) for m new knots.
pub(crate) fn refine_points<P: Point>(
    knots: &KnotVector,
    pw: &[P],
    x: &[f64],
) -> (Vec<P>, Vec<f64>) {
    let u = knots.as_slice();
    let n = pw.len() - 1;
    let p = u.len() - pw.len() - 1;
    let m = n + p + 1;
    let r = x.len() - 1;
    let a = knots.span(x[0]);
    let b = knots.span(x[r]) + 1;
    let mut q = vec![P::ZERO; n + r + 2];
    let mut ubar = vec![0.0; m + r + 2];
    q[..=a - p].copy_from_slice(&pw[..=a - p]);
    for j in b - 1..=n {
        q[j + r + 1] = pw[j];
    }
    ubar[..=a].copy_from_slice(&u[..=a]);
    for j in b + p..=m {
        ubar[j + r + 1] = u[j];
    }
    let mut i = b + p - 1;
    let mut k = b + p + r;
    for j in (0..=r).rev() {
        while x[j] <= u[i] && i > a {
            q[k - p - 1] = pw[i - p - 1];
            ubar[k] = u[i];
            k -= 1;
            i -= 1;
        }
        q[k - p - 1] = q[k - p];
        for l in 1..=p {
            let ind = k - p + l;
            let alpha = ubar[k + l] - x[j];
            if alpha == 0.0 {
                q[ind - 1] = q[ind];
            } else {
                let alpha = alpha / (ubar[k + l] - u[i - p + l]);
                q[ind - 1] = q[ind - 1] * alpha + q[ind] * (1.0 - alpha);
            }
        }
        ubar[k] = x[j];
        k -= 1;
    }
    (q, ubar)
}

impl<C: Cartesian> BSplineCurve<C> {
    /// The same curve with the knot `u` inserted `times` times (Boehm's algorithm, once per
    /// insertion): the shape does not change, the control polygon moves towards the curve.
    ///
    /// # Errors
    /// A bad `u`; [`Error::InsertionMultiplicity`] when the multiplicity of `u` would exceed `p + 1`.
    pub fn insert_knot(&self, u: f64, times: usize) -> Result<Self> {
        let u = self.knots.check_parameter(u)?;
        let p = self.degree();
        check_insertion(None, u, self.knots.multiplicity(u), times, p)?;
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

    /// What one insertion of `u` would use, for showing Boehm's rule: the span `k` of `u`
    /// (`u_k <= u < u_{k+1}`) and `α_i = (u − u_i)/(u_{i+p} − u_i)` for `i = k − p + 1 ..= k`.
    /// Only `u` is checked (not whether its multiplicity allows one more insertion).
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for a bad `u`.
    pub fn insertion_alphas(&self, u: f64) -> Result<(usize, Vec<f64>)> {
        let u = self.knots.check_parameter(u)?;
        let k = self.knots.span(u);
        Ok((k, boehm_alphas(self.knots.as_slice(), self.degree(), k, u)))
    }

    /// Knot refinement: inserts every value of `us` (in any order; repeated values raise the
    /// multiplicity) in one pass and returns the refined curve, same shape.
    ///
    /// NURBS Book A5.4 ([`refine_points`]): O(n + m·p) for m new knots instead of m separate
    /// insertions.
    ///
    /// # Errors
    /// A value outside the domain or not finite (naming it), a knot whose multiplicity would
    /// exceed `p + 1`, or [`Error::ResultTooLarge`] for a result above
    /// [`crate::geom::MAX_RESULT_BYTES`].
    pub fn refine(&self, us: &[f64]) -> Result<Self> {
        result_len(
            "refine-result",
            // Two lengths of arrays in memory: their sum cannot overflow.
            &[self.homogeneous.len() + us.len(), C::DIM + 1],
        )?;
        let mut x = us.to_vec();
        for (i, &u) in x.iter().enumerate() {
            check_finite("knot-to-insert", Some(i), u)?;
            self.knots.check_parameter(u)?;
        }
        x.sort_unstable_by(f64::total_cmp);
        let p = self.degree();
        for run in x.chunk_by(|a, b| a == b) {
            check_insertion(None, run[0], self.knots.multiplicity(run[0]), run.len(), p)?;
        }
        self.refined_sorted(&x)
    }

    /// [`BSplineCurve::refine`] by values already checked: sorted, in the domain, multiplicities
    /// allowed.
    fn refined_sorted(&self, x: &[f64]) -> Result<Self> {
        if x.is_empty() {
            let mut same = self.clone();
            same.wrap = 0;
            return Ok(same);
        }
        let p = self.degree();
        let (mut q, ubar) = refine_points(&self.knots, &self.homogeneous, x);
        if !self.rational {
            // Keep polynomial weights exactly 1 ((1 − α)·1 + α·1 may round).
            for h in &mut q {
                *h = C::numerator(*h).to_homogeneous(1.0);
            }
        }
        let knots = KnotVector::new(ubar, p, q.len())?;
        Ok(BSplineCurve {
            homogeneous: q,
            rational: self.rational,
            knots,
            wrap: 0,
        })
    }

    /// Bézier extraction: every distinct knot of the domain is raised to multiplicity `p`,
    /// after which the `p + 1` control points of each non-empty span are that span's Bézier
    /// control points. Returns the segments in span order, each on its own `t ∈ [0, 1]`
    /// (rational segments keep their weights): one per distinct interior knot, plus one.
    ///
    /// All the insertions are one refinement (NURBS Book A5.4, [`refine_points`]), O(n·p) for
    /// n control points: a 20 000-point cubic in milliseconds, where one Boehm pass per knot
    /// was O(n²) (8.6 s).
    pub fn to_bezier(&self) -> Result<Vec<BezierCurve<C>>> {
        let p = self.degree();
        let curve = self.refined_sorted(&self.knots.extraction_knots())?;
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
