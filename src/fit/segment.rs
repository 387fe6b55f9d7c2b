//! The global segmentation: the fewest pieces that keep every sample within the tolerance.
//!
//! Between two consecutive fixed joints (the stroke's ends and its corners) the breaks are
//! chosen by *furthest reach*: from a break `s`, the next break is the furthest sample `e`
//! such that one cubic fits `s..=e` (found by galloping from the previous piece's length,
//! then bisection). For interval covering this greedy rule is optimal when feasibility is
//! monotone (a run that fits has every sub-run fitting): any cover with `k` pieces has its
//! `j`-th break no further than the greedy one, by induction on `j`. It is not Schneider's
//! split at the worst sample, whose pieces overlap in what they could have covered.
//!
//! At a smooth break both pieces use one tangent direction, estimated from the stroke
//! (the difference of the mean positions of 8 points each side, at arc lengths up to `h` away,
//! `h` a fifth of the piece's length but at least two tolerances), so every smooth joint is G1
//! by construction. Corners and open ends have free handles. With C1 a piece after a smooth
//! joint starts with the previous piece's end handle (fixed, not only its direction), so the
//! search picks the breaks that the C1 constraint can live with, and every piece is checked
//! with it; a closed C1 curve's last piece ends with the first piece's start handle.

use super::cubic::{Cubic, End, Fitter};
use super::stroke::Stroke;
use crate::geom::Cartesian;

/// A fitted piece over the samples `a..=b`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Piece<C> {
    /// First sample.
    pub a: usize,
    /// Last sample.
    pub b: usize,
    /// The cubic.
    pub cubic: Cubic<C>,
}

/// How the segmentation treats the stroke.
pub(crate) struct Layout<'a, C> {
    /// Fixed joints: `0`, the corners, `n − 1`, in order.
    pub limits: &'a [usize],
    /// Closed without corners: the tangent at the seam (sample 0 = sample n − 1).
    pub seam: Option<C>,
    /// Tangent constraints at the very start and end (oversketch seams), overriding free ends.
    pub ends: (Option<C>, Option<C>),
    /// C1 smooth joints: a piece after a smooth joint starts with the previous piece's end
    /// handle (piece `i` on `[i, i + 1]`: `P_3 − P_2 = Q_1 − Q_0`).
    pub c1: bool,
}

/// Fits pieces over the whole stroke.
pub(crate) fn segment<C: Cartesian>(
    stroke: &Stroke<C>,
    layout: &Layout<C>,
    tol: f64,
    fitter: &mut Fitter,
) -> Vec<Piece<C>> {
    let n = stroke.len();
    let mut pieces = Vec::new();
    let mut guess = 8usize;
    let last_limit = layout.limits.len() - 1;
    let mut first_handle: Option<C> = None;
    for (w, span) in layout.limits.windows(2).enumerate() {
        let (lo, hi) = (span[0], span[1]);
        let cyclic = layout.seam.is_some();
        let fixed_end = |at_start: bool| -> End<C> {
            let tangent = if at_start {
                layout.seam.or(if w == 0 { layout.ends.0 } else { None })
            } else {
                layout.seam.or(if w + 1 == last_limit {
                    layout.ends.1
                } else {
                    None
                })
            };
            tangent.map_or(End::Free, End::Dir)
        };
        let mut s = lo;
        let mut start = fixed_end(true);
        while s < hi {
            let try_end = |fitter: &mut Fitter, e: usize| {
                let (end, joint) = if e == hi {
                    // A C1 seam: the last piece ends with the first piece's start handle.
                    let end = match first_handle {
                        Some(h) if s > lo => End::Handle(h),
                        _ => fixed_end(false),
                    };
                    (end, None)
                } else {
                    let h = (0.2 * (stroke.arc[e] - stroke.arc[s])).max(2.0 * tol);
                    let t = tangent(stroke, e, h, (lo, hi), cyclic && n > 2);
                    (t.map_or(End::Free, End::Dir), t)
                };
                let fit = fitter.fit(stroke, s, e, start, end, tol);
                (fit, joint)
            };
            // The whole rest of the span first when the piece is the span's first or the rest
            // is not much longer than the last piece (straight runs, small shapes; a run to a
            // free end may fit where shorter runs to an estimated tangent do not); else gallop
            // from the last piece's length.
            // `bad`: the nearest end known not to fit (`hi + 1`: none known).
            let mut bad = hi + 1;
            let mut good = None;
            if s == lo || hi - s <= 16 * guess {
                let (fit, joint) = try_end(fitter, hi);
                if fit.ok {
                    good = Some((hi, fit.cubic, joint));
                } else {
                    bad = hi;
                }
            }
            let best = match good {
                Some(g) => g,
                None => {
                    // Gallop down until a run fits (a single segment always does)…
                    let mut e = (s + guess.max(2)).min(hi).min(bad - 1);
                    let mut good = loop {
                        let (fit, joint) = try_end(fitter, e);
                        if fit.ok || e == s + 1 {
                            break (e, fit.cubic, joint);
                        }
                        bad = e;
                        e = s + (e - s) / 2;
                    };
                    // …then up until one does not…
                    loop {
                        let next = (s + 2 * (good.0 - s)).min(hi);
                        if next >= bad || next == good.0 {
                            break;
                        }
                        let (fit, joint) = try_end(fitter, next);
                        if fit.ok {
                            good = (next, fit.cubic, joint);
                        } else {
                            bad = next;
                            break;
                        }
                    }
                    // …then bisect between the furthest good and the nearest bad.
                    while bad <= hi && bad - good.0 > 1 {
                        let m = good.0 + (bad - good.0) / 2;
                        let (fit, joint) = try_end(fitter, m);
                        if fit.ok {
                            good = (m, fit.cubic, joint);
                        } else {
                            bad = m;
                        }
                    }
                    good
                }
            };
            let (e, cubic, joint) = best;
            guess = e - s;
            pieces.push(Piece { a: s, b: e, cubic });
            start = match joint {
                Some(_) if layout.c1 => End::Handle(cubic.ctrl[3] - cubic.ctrl[2]),
                Some(d) => End::Dir(d),
                None => End::Free,
            };
            if pieces.len() == 1 && layout.c1 && layout.seam.is_some() {
                first_handle = Some(cubic.ctrl[1] - cubic.ctrl[0]);
            }
            s = e;
        }
    }
    pieces
}

/// The unit tangent of the stroke at sample `i`: the mean of the points at arc lengths
/// `σ_i + h·k/8` (`k = 1..8`) minus the mean of those at `σ_i − h·k/8`, the arc lengths kept
/// within the span `lo..=hi` (wrapping around a cyclic stroke). `None` when it vanishes.
pub(crate) fn tangent<C: Cartesian>(
    stroke: &Stroke<C>,
    i: usize,
    h: f64,
    (lo, hi): (usize, usize),
    cyclic: bool,
) -> Option<C> {
    let total = stroke.length();
    let (smin, smax) = (stroke.arc[lo], stroke.arc[hi]);
    let si = stroke.arc[i];
    let at = |s: f64| {
        if cyclic {
            stroke.point_at(super::wrap(s, total))
        } else {
            stroke.point_at(s.clamp(smin, smax))
        }
    };
    let mut sum = C::ZERO;
    for k in 1..=8 {
        let d = h * k as f64 / 8.0;
        sum = sum + at(si + d) - at(si - d);
    }
    let n = sum.norm();
    (n > 0.0 && n.is_finite()).then(|| sum * (1.0 / n))
}
