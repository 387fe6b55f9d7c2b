//! de Boor's algorithm and its triangle (syllabus §3).

use crate::geom::Point;

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
            let lo = knots[j + k - p];
            let hi = knots[j + 1 + k - r];
            let alpha = if hi == lo { 0.0 } else { (u - lo) / (hi - lo) };
            d[j] = d[j - 1].lerp_to(d[j], alpha);
        }
        out.extend_from_slice(&d[r..=p]);
    }
    out
}
