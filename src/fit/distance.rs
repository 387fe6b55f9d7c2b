//! The measured distance from a sample `q` to a cubic piece: `min_u |C(u) − q|` over `[0, 1]`.
//!
//! The piece is sampled at [`COARSE`] + 1 equally spaced parameters; the sample closest to `q`
//! brackets the minimiser in `[u_{k−1}, u_{k+1}]`, where the root of `g(u) = (C(u) − q)·C'(u)`
//! is found by Newton's method safeguarded by bisection (a step that leaves the bracket is
//! replaced by the midpoint), to `10⁻¹⁴` in `u`. The bracket's ends are candidates too.
//!
//! [`measure`] finds the largest distance over a run of samples without the full search for
//! most of them: the distance to *some* point of the piece bounds the distance to the piece
//! from above, so a sample whose bound (two Newton steps from the previous sample's parameter)
//! does not exceed the largest measured distance so far cannot be the worst.

use super::cubic::Cubic;
use crate::geom::Cartesian;

/// Coarse intervals of the bracketing search.
pub(crate) const COARSE: usize = 32;

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

/// The distance from `q` to `cubic` and the parameter of the closest point.
pub(crate) fn closest<C: Cartesian>(cubic: &Cubic<C>, coarse: &Coarse<C>, q: C) -> (f64, f64) {
    let mut k = 0;
    let mut best = f64::INFINITY;
    for (j, &p) in coarse.pts.iter().enumerate() {
        let d = (p - q).dot_with(p - q);
        if d < best {
            best = d;
            k = j;
        }
    }
    let h = 1.0 / COARSE as f64;
    let mid = k as f64 * h;
    let mut result = (best.sqrt(), mid);
    let lo = k.saturating_sub(1) as f64 * h;
    let hi = (k + 1).min(COARSE) as f64 * h;
    // The distance decreases from mid towards the side where g = (C − q)·C' says so.
    let (a, b) = if slope(cubic, q, mid) > 0.0 {
        (lo, mid)
    } else {
        (mid, hi)
    };
    for u in [a, b, refine(cubic, q, a, b)] {
        let d = (cubic.eval(u) - q).norm();
        if d < result.0 {
            result = (d, u);
        }
    }
    result
}

/// `g(u) = (C(u) − q)·C'(u)`, half the derivative of `|C(u) − q|²`.
fn slope<C: Cartesian>(cubic: &Cubic<C>, q: C, u: f64) -> f64 {
    let (p, d1, _) = cubic.eval2(u);
    (p - q).dot_with(d1)
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
