//! de Boor's algorithm and its triangle (syllabus §3).

use crate::geom::Point;

/// The blending factor of step `(r, j)` of de Boor's algorithm at `u` in span `k`:
/// `α_j^r = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p})`. A zero denominator (only possible
/// outside a non-empty span) counts as `α = 0`.
#[inline]
pub fn de_boor_alpha(knots: &[f64], p: usize, k: usize, r: usize, j: usize, u: f64) -> f64 {
    let lo = knots[j + k - p];
    let hi = knots[j + 1 + k - r];
    if hi == lo {
        0.0
    } else {
        (u - lo) / (hi - lo)
    }
}

/// One α of de Boor's triangle, with what a lecture needs to write its fraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeBoorAlpha {
    /// The level `r = 1..=p` the α makes.
    pub level: usize,
    /// The index `j = r..=p` of the point `d_j^r` it makes.
    pub j: usize,
    /// Knot index of the numerator's knot and of the denominator's lower knot: `j + k − p`.
    pub lo: usize,
    /// Knot index of the denominator's upper knot: `j + 1 + k − r`.
    pub hi: usize,
    /// The denominator `u_hi − u_lo` (> 0 in a non-empty span).
    pub denominator: f64,
    /// `α_j^r = (u − u_lo) / (u_hi − u_lo)`.
    pub value: f64,
}

/// Every α of de Boor's triangle at `u` in span `k` (degree `p`): level `r = 1..=p` in order,
/// within a level `j = r..=p` ascending (the order of the points of that level in
/// [`de_boor_triangle`]); `p(p+1)/2` in all.
/// `α_j^r = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p})`, the factor in
/// `d_j^r = (1 − α_j^r) d_{j−1}^{r−1} + α_j^r d_j^{r−1}`.
pub fn de_boor_alphas(knots: &[f64], p: usize, k: usize, u: f64) -> Vec<DeBoorAlpha> {
    let mut out = Vec::with_capacity(p * (p + 1) / 2);
    for r in 1..=p {
        for j in r..=p {
            let (lo, hi) = (j + k - p, j + 1 + k - r);
            out.push(DeBoorAlpha {
                level: r,
                j,
                lo,
                hi,
                denominator: knots[hi] - knots[lo],
                value: de_boor_alpha(knots, p, k, r, j, u),
            });
        }
    }
    out
}

/// de Boor's triangle at `u` in span `k`: level 0 holds the `p + 1` active points
/// `d_j = P_{j+k−p}`, and for `r = 1..=p`, `j = r..=p`:
/// `α = (u − u_{j+k−p}) / (u_{j+1+k−r} − u_{j+k−p})`, `d_j ← (1 − α) d_{j−1} + α d_j`.
/// Returns every level concatenated (level `r` has `p + 1 − r` points; `(p+1)(p+2)/2` in all,
/// the last one is `C(u)`). A zero denominator (only possible outside a non-empty span) counts
/// as `α = 0`.
pub fn de_boor_triangle<P: Point>(
    points: &[P],
    knots: &[f64],
    p: usize,
    k: usize,
    u: f64,
) -> Vec<P> {
    let mut d: Vec<P> = points[k - p..=k].to_vec();
    let mut out = Vec::with_capacity((p + 1) * (p + 2) / 2);
    out.extend_from_slice(&d);
    for r in 1..=p {
        for j in (r..=p).rev() {
            let alpha = de_boor_alpha(knots, p, k, r, j, u);
            d[j] = d[j - 1].lerp_to(d[j], alpha);
        }
        out.extend_from_slice(&d[r..=p]);
    }
    out
}
