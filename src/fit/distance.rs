//! The measured distance from a sample `q` to a cubic piece: `min_u |C(u) − q|` over `[0, 1]`.
//!
//! The piece is sampled at [`COARSE`] + 1 equally spaced parameters; each local minimum `k`
//! of those samples' distances to `q` brackets a minimiser in `[u_{k−1}, u_k]` or
//! `[u_k, u_{k+1}]`, where the root of `g(u) = (C(u) − q)·C'(u)` is found by Newton's method
//! safeguarded by bisection (a step that leaves the bracket is replaced by the midpoint), to
//! `10⁻¹⁵` in `u`; plain Newton steps from the sample (kept in the bracket) catch a minimum
//! between a local maximum and the sample near a cusp. The samples themselves are candidates
//! too.
//!
//! [`measure`] finds the largest distance over a run of samples without the full search for
//! most of them: the distance to *some* point of the piece bounds the distance to the piece
//! from above, so a sample whose bound (two Newton steps from the previous sample's parameter)
//! does not exceed the largest measured distance so far cannot be the worst.

use super::cubic::Cubic;
use crate::geom::Cartesian;

/// Coarse intervals of the bracketing search.
pub(crate) const COARSE: usize = 32;

/// Plain Newton steps from each local minimum of the coarse distances.
const NEWTON_STEPS: usize = 12;

/// Coarse samples nearest `q` that also seed plain Newton iterations.
const EXTRA_SEEDS: usize = 8;

/// The most local minima of the coarse distances refined.
const MAX_BRACKETS: usize = 4;

/// The coarse polyline of a piece.
pub(crate) struct Coarse<C> {
    pts: [C; COARSE + 1],
}

impl<C: Cartesian> Coarse<C> {
    /// Samples `cubic` at `k / COARSE`.
    pub fn new(cubic: &Cubic<C>) -> Self {
        let mut pts = [C::ZERO; COARSE + 1];
        for (k, p) in pts.iter_mut().enumerate() {
            *p = cubic.eval(k as f64 / COARSE as f64);
        }
        Coarse { pts }
    }
}

/// Inserts `candidate` into `nearest`, which holds the smallest distances seen so far in
/// ascending order (earlier candidates first among equals), when it is smaller than the last.
/// A fixed-size insertion instead of sorting every coarse sample: `slice::sort` would add
/// ~8 KB of wasm for one call.
fn keep_nearest<const N: usize>(nearest: &mut [(f64, usize); N], candidate: (f64, usize)) {
    let mut i = N;
    while i > 0 && candidate.0 < nearest[i - 1].0 {
        if i < N {
            nearest[i] = nearest[i - 1];
        }
        i -= 1;
    }
    if i < N {
        nearest[i] = candidate;
    }
}

/// The distance from `q` to `cubic` and the parameter of the closest point: every local
/// minimum of the coarse distances (at most [`MAX_BRACKETS`], nearest first) brackets a
/// candidate on each side, refined by [`refine`].
pub(crate) fn closest<C: Cartesian>(cubic: &Cubic<C>, coarse: &Coarse<C>, q: C) -> (f64, f64) {
    let mut d2 = [0.0; COARSE + 1];
    for (d, &p) in d2.iter_mut().zip(&coarse.pts) {
        *d = (p - q).dot_with(p - q);
    }
    let mut minima = [(f64::INFINITY, 0usize); MAX_BRACKETS];
    for k in 0..=COARSE {
        let left = k == 0 || d2[k] <= d2[k - 1];
        let right = k == COARSE || d2[k] <= d2[k + 1];
        if left && right {
            keep_nearest(&mut minima, (d2[k], k));
        }
    }
    let h = 1.0 / COARSE as f64;
    let mut result = (f64::INFINITY, 0.0);
    for &(d, k) in &minima {
        if !d.is_finite() {
            continue;
        }
        let mid = k as f64 * h;
        if d.sqrt() < result.0 {
            result = (d.sqrt(), mid);
        }
        let lo = k.saturating_sub(1) as f64 * h;
        let hi = (k + 1).min(COARSE) as f64 * h;
        // Near a cusp the distance can rise and fall again inside one coarse step, with no
        // sign change of g at the bracket's ends: plain Newton from the sample covers that.
        let mut v = mid;
        for _ in 0..NEWTON_STEPS {
            v = cubic.newton(q, v).clamp(lo, hi);
        }
        for u in [refine(cubic, q, lo, mid), refine(cubic, q, mid, hi), v] {
            let e = (cubic.eval(u) - q).norm();
            if e < result.0 {
                result = (e, u);
            }
        }
    }
    // Newton from the other samples nearest `q` as well (a fold between two samples).
    let mut seeds = [(f64::INFINITY, 0usize); EXTRA_SEEDS];
    for (k, &d) in d2.iter().enumerate() {
        keep_nearest(&mut seeds, (d, k));
    }
    for &(_, k) in &seeds {
        let mut v = k as f64 * h;
        for _ in 0..NEWTON_STEPS {
            v = cubic.newton(q, v);
        }
        let e = (cubic.eval(v) - q).norm();
        if e < result.0 {
            result = (e, v);
        }
    }
    result
}

/// A root of `g` in `[lo, hi]` when `g(lo) < 0 < g(hi)` (Newton's method, a step that leaves
/// the bracket replaced by bisection), else the end where `|C − q|` may be smallest.
fn refine<C: Cartesian>(cubic: &Cubic<C>, q: C, mut lo: f64, mut hi: f64) -> f64 {
    let g = |u: f64| {
        let (p, d1, d2) = cubic.eval2(u);
        let r = p - q;
        (r.dot_with(d1), d1.dot_with(d1) + r.dot_with(d2))
    };
    let (glo, ghi) = (g(lo).0, g(hi).0);
    if glo >= 0.0 || ghi <= 0.0 {
        return if glo >= 0.0 { lo } else { hi };
    }
    let mut u = 0.5 * (lo + hi);
    for _ in 0..100 {
        let (f, df) = g(u);
        if f == 0.0 {
            return u;
        }
        if f < 0.0 {
            lo = u;
        } else {
            hi = u;
        }
        let step = if df > 0.0 { u - f / df } else { f64::NAN };
        let next = if step > lo && step < hi {
            step
        } else {
            0.5 * (lo + hi)
        };
        if (next - u).abs() <= 1e-15 || hi - lo <= 1e-15 {
            return next;
        }
        u = next;
    }
    u
}

/// The largest measured distance from `samples` to `cubic` and the index (into `samples`) of
/// the sample at that distance.
pub(crate) fn measure<C: Cartesian>(cubic: &Cubic<C>, samples: &[C]) -> (f64, usize) {
    let coarse = Coarse::new(cubic);
    let mut worst = (0.0, 0);
    let mut u = 0.0;
    for (i, &q) in samples.iter().enumerate() {
        u = cubic.newton(q, cubic.newton(q, u));
        let bound = (cubic.eval(u) - q).norm();
        if bound <= worst.0 {
            continue;
        }
        let (mut d, v) = closest(cubic, &coarse, q);
        if d <= bound {
            u = v;
        } else {
            // The coarse bracket missed the branch Newton found (a tight loop): keep that.
            d = bound;
        }
        if d > worst.0 {
            worst = (d, i);
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn keep_nearest_holds_the_smallest_in_ascending_order() {
        let d = [5.0, 1.0, 4.0, 1.0, 9.0, 2.0, 6.0];
        let mut nearest = [(f64::INFINITY, 0usize); 3];
        for (k, &x) in d.iter().enumerate() {
            keep_nearest(&mut nearest, (x, k));
        }
        // The three smallest, ties in the order seen.
        assert_eq!(nearest, [(1.0, 1), (1.0, 3), (2.0, 5)]);
    }

    #[test]
    fn distance_to_a_straight_cubic_is_the_distance_to_the_segment() {
        let c = Cubic::new([
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(3.0, 0.0),
        ]);
        let coarse = Coarse::new(&c);
        for (q, d) in [
            (DVec2::new(1.3, 2.0), 2.0),
            (DVec2::new(-3.0, 4.0), 5.0),
            (DVec2::new(4.0, 0.0), 1.0),
        ] {
            let (got, _) = closest(&c, &coarse, q);
            assert!((got - d).abs() < 1e-12, "{got} vs {d}");
        }
        let samples = [
            DVec2::new(0.5, 0.1),
            DVec2::new(2.0, -0.3),
            DVec2::new(2.5, 0.2),
        ];
        assert_eq!(measure(&c, &samples).1, 1);
    }
}
