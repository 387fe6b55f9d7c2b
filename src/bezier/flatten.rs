//! Adaptive flattening: a polyline that provably stays within a tolerance of the curve, with a
//! proven estimate of its size made before any of it is built.

use super::{split_points, BezierCurve};
use crate::error::{check_tolerance, Error, Result};
use crate::geom::{Cartesian, Point};
use crate::prelude::*;

/// Most segments one call to [`BezierCurve::flatten`] may produce.
pub const MAX_FLATTEN_SEGMENTS: usize = 1 << 16;

/// Smallest tolerance accepted, relative to the size of the control polygon: below this,
/// rounding in the subdivided control points is of the order of the tolerance itself.
const MIN_RELATIVE_TOLERANCE: f64 = 1e-10;

/// Deepest halving of the curve when [`BezierCurve::flatten`] estimates its segment count:
/// at most `2^16` pieces, each costing one de Casteljau split.
const MAX_ESTIMATE_DEPTH: u32 = 16;

/// The estimate halves a piece while its second-difference bound asks for more than this many
/// segments: the bound tightens as the control net of a smaller piece nears the curve, so
/// pieces of ~64 segments make it close to the count really needed (a sum of ceilings over
/// pieces of 32 to 64 segments adds at most ~3 %; pieces of 16 made refusing 2–4× slower for
/// an estimate ~10 % lower).
const ESTIMATE_PIECE_SEGMENTS: f64 = 64.0;

/// Trials of the parameter step per segment once one step has passed: the step is predicted
/// from the error bound's `h²` scaling and bracketed, so ~3 trials are usual; after this many
/// the longest step that passed is taken. (Before any passes, every trial at least halves the
/// step, so that search ends when the step stops moving the parameter.)
const MAX_STEP_TRIALS: u32 = 32;

/// A step is taken at once when its error bound is at least this fraction of the tolerance
/// (the bound grows like `h²`, so the step is within ~1.5 % of the longest one allowed).
const STEP_ACCEPT: f64 = 0.97;

/// Largest factor by which one trial changes the step.
const STEP_FACTOR: f64 = 4.0;

impl<C: Cartesian> BezierCurve<C> {
    /// A polyline (both end points included) whose Hausdorff distance to the curve is at most
    /// `tolerance`, with few vertices.
    ///
    /// Each segment is the chord of a piece `[s0, s1]` of the curve whose subdivided control
    /// points certify the bound (convex hull property):
    /// - always: the largest distance of a control point to the chord segment;
    /// - polynomial pieces whose control points all project inside the chord: the curve's
    ///   distance to the chord is `|Σ B_i(s) d_i| <= (1 − 2^{1−n}) max |d_i|`, with `d_i` the
    ///   perpendicular offsets (the end offsets are 0 and `B_0 + B_n >= 2^{1−n}`);
    /// - polynomial pieces: `|P(s) − L(s)| <= (1 − 2^{1−n}) max |P_i − Q_i|` where `L` runs along
    ///   the chord and `Q_i` are the chord's own degree-`n` control points (linear precision);
    /// - always: the second-difference bound of [`BezierCurve::flatten_estimate`] for one step,
    ///   `n(n−1) (max |ΔΔ(w_i (P_i − c))| + R max |ΔΔw_i|) / (8 min w_i)`.
    ///
    /// The smallest bound is used. Pieces are chosen greedily from the start: the first trial
    /// continues the trend of the last two steps, the next ones follow the bound's growth (like
    /// `h²`, or measured by a secant on the last two trials), bracketed, until the bound is
    /// between 97 % and 100 % of the tolerance, so every segment is close to the longest one
    /// allowed (~1.6–2.4 trials per segment on a degree-64 curve). Cusps, loops and straight curves need no special case: the bounds hold for any
    /// control polygon. The piece after the current vertex is split off once per segment, so a
    /// trial costs one half de Casteljau triangle (O(n²)), allocation-free.
    ///
    /// Before any of that, [`BezierCurve::flatten_estimate`] bounds the number of segments
    /// needed; above [`MAX_FLATTEN_SEGMENTS`] the call fails at once.
    ///
    /// # Errors
    /// [`Error::InvalidTolerance`] for a tolerance that is not finite and > 0,
    /// [`Error::ToleranceTooSmall`] below `1e-10` × the control polygon's size;
    /// [`Error::TooLarge`] when the estimate (or, as a guard, the polyline) exceeds
    /// [`MAX_FLATTEN_SEGMENTS`] segments.
    pub fn flatten(&self, tolerance: f64) -> Result<Vec<C>> {
        self.check_flatten_tolerance(tolerance)?;
        let estimate = self.flatten_estimate(tolerance)?;
        let cps = self.control_points();
        let mut out = Vec::with_capacity(estimate.min(MAX_FLATTEN_SEGMENTS) + 1);
        out.push(cps[0]);
        let mut rest = self.homogeneous.clone(); // the curve on [s0, 1], as its own Bézier
        let mut work = Vec::with_capacity(rest.len());
        let mut piece = Vec::with_capacity(rest.len());
        let mut after = Vec::with_capacity(rest.len()); // the right part of the last trial
        let mut projected = Vec::with_capacity(rest.len());
        let mut bound = |rest: &[C::Homogeneous], tau: f64, after: &mut Vec<C::Homogeneous>| {
            split_into(rest, tau, &mut work, &mut piece, after);
            self.net_error_bound(&piece, &mut projected)
        };
        let mut s0 = 0.0;
        let (mut step, mut trend) = (1.0f64, 1.0f64);
        while s0 < 1.0 {
            // Steps are lengths in the global parameter; `rest` is on [s0, 1].
            let span = 1.0 - s0;
            let (mut good, mut bad) = (0.0f64, f64::INFINITY);
            // The first trial continues the steps' trend (their ratio varies slowly along a
            // smooth curve), so it usually lands in the accepted window at once.
            let mut h = (step * trend).min(span);
            let mut last = h;
            let mut previous: Option<(f64, f64)> = None; // (h, bound) of the last trial
            for trial in 0.. {
                let e = bound(&rest, h / span, &mut after);
                last = h;
                if e <= tolerance {
                    good = good.max(h);
                    if e >= STEP_ACCEPT * tolerance || good >= span {
                        break;
                    }
                } else {
                    bad = bad.min(h);
                }
                if good > 0.0 && (bad - good <= good / 64.0 || trial + 1 >= MAX_STEP_TRIALS) {
                    break;
                }
                // Aim at 98.5 % of the tolerance assuming the bound grows like h^k: k = 2 (a
                // smooth piece's sagitta), or measured from the last two trials (secant on
                // log e against log h), within [1, 4].
                let k = match previous {
                    Some((hp, ep)) if ep > 0.0 && e > 0.0 && hp != h => {
                        ((e / ep).ln() / (h / hp).ln()).clamp(1.0, 4.0)
                    }
                    _ => 2.0,
                };
                previous = Some((h, e));
                let mut ratio = if e > 0.0 {
                    (0.985 * tolerance / e).powf(1.0 / k)
                } else {
                    STEP_FACTOR
                };
                if good == 0.0 {
                    // Nothing passed yet: shrink by at least 10 % (halve after 8 trials), so
                    // the loop ends (at the latest when the step no longer moves s0:
                    // FlatteningStalled).
                    ratio = ratio.min(if trial < 8 { 0.9 } else { 0.5 });
                }
                let mut next = h * ratio.clamp(1.0 / STEP_FACTOR, STEP_FACTOR);
                if next <= good || next >= bad {
                    next = if bad.is_finite() && good > 0.0 {
                        0.5 * (good + bad)
                    } else if bad.is_finite() {
                        0.5 * bad
                    } else {
                        2.0 * good
                    };
                }
                h = next.min(span);
                if s0 + h <= s0 {
                    return Err(Error::FlatteningStalled { value: tolerance });
                }
            }
            if good <= 0.0 {
                return Err(Error::FlatteningStalled { value: tolerance });
            }
            trend = (good / step).clamp(0.5, 2.0);
            step = good;
            if good >= span {
                s0 = 1.0;
                out.push(cps[cps.len() - 1]);
            } else {
                if last == good {
                    std::mem::swap(&mut rest, &mut after);
                } else {
                    rest = split_points(&rest, good / span).1;
                }
                s0 += good;
                out.push(C::project(rest[0]));
            }
            if out.len() > MAX_FLATTEN_SEGMENTS + 1 {
                return Err(Error::TooLarge {
                    what: "flattening-segments",
                    value: out.len() - 1,
                    max: MAX_FLATTEN_SEGMENTS,
                });
            }
        }
        Ok(out)
    }

    /// The checks of [`BezierCurve::flatten`]'s tolerance: finite and > 0, and not below
    /// rounding at the size of the control polygon.
    fn check_flatten_tolerance(&self, tolerance: f64) -> Result<()> {
        check_tolerance(tolerance)?;
        let size = crate::geom::BoundingBox::of_points(&self.control_points())
            .map(|b| b.diagonal())
            .unwrap_or(0.0);
        if tolerance < MIN_RELATIVE_TOLERANCE * size {
            return Err(Error::ToleranceTooSmall {
                value: tolerance,
                relative: MIN_RELATIVE_TOLERANCE,
                size,
            });
        }
        Ok(())
    }

    /// A number of segments that provably suffices to flatten the curve within `tolerance`,
    /// computed before any flattening: [`BezierCurve::flatten`] fails with it at once when it
    /// exceeds [`MAX_FLATTEN_SEGMENTS`].
    ///
    /// **The bound.** On a piece with homogeneous control points `H_i = (w_i (P_i − c), w_i)`
    /// (coordinates centred at `c`, the middle of the points' bounding box), cut `[0, 1]` into
    /// `N` equal steps `h = 1/N` and take the chords of the homogeneous curve `H(s)`. With
    /// `E = H − L` the error of linear interpolation, `|E(s)| ≤ h²/8 · max |H''|` (the Green's
    /// function of `E'' = H''` with `E = 0` at the step's ends integrates to
    /// `(s − s_k)(s_{k+1} − s)/2 ≤ h²/8`), and `|H''| ≤ n(n−1) max |ΔΔH_i|` (the second
    /// hodograph's control points). The curve point is `P = H_xyz/H_w` and the chord's point
    /// `Q = L_xyz/L_w` (the projection of a homogeneous chord is the chord), so
    /// `P − Q = (E_xyz − Q E_w)/H_w`, and with `|Q − c| ≤ R = max |P_i − c|` and
    /// `H_w ≥ min w_i`:
    ///
    /// `|P − Q| ≤ h² n(n−1) (max |ΔΔ(w_i (P_i − c))| + R max |ΔΔw_i|) / (8 min w_i)`,
    ///
    /// so `N = ⌈sqrt(n(n−1) (D + R D_w) / (8 · tolerance · min w))⌉` steps suffice; for a
    /// polynomial piece this is `n(n−1) max |ΔΔP_i| / (8 N²) ≤ tolerance`.
    ///
    /// **The estimate.** The bound of the whole control net overstates a high degree's
    /// curvature by up to `n(n−1)`; the estimate halves the curve (de Casteljau) while a
    /// piece's bound exceeds 64 segments, to depth 16, and adds up the pieces' counts — 1 for
    /// a piece whose control points already certify one chord (the bounds of
    /// [`BezierCurve::flatten`]). The halving stops as soon as the finished pieces exceed the
    /// cap, so refusing costs ~`MAX_FLATTEN_SEGMENTS / 32` splits. It is an upper bound
    /// on what a uniform step per piece needs, usually within a few tens of percent of the
    /// greedy polyline's count.
    ///
    /// # Errors
    /// [`Error::TooLarge`] (naming the count reached and the tolerance's cap) when the
    /// estimate exceeds [`MAX_FLATTEN_SEGMENTS`]; the tolerance is not checked here.
    pub fn flatten_estimate(&self, tolerance: f64) -> Result<usize> {
        let mut projected = Vec::with_capacity(self.homogeneous.len());
        let mut stack = vec![(self.homogeneous.clone(), 0u32)];
        let mut total = 0usize;
        while let Some((net, depth)) = stack.pop() {
            let count = if self.net_error_bound(&net, &mut projected) <= tolerance {
                1.0
            } else {
                (second_difference_bound::<C>(&net) / tolerance)
                    .sqrt()
                    .max(1.0)
            };
            if count > ESTIMATE_PIECE_SEGMENTS && depth < MAX_ESTIMATE_DEPTH {
                let (left, right) = split_points(&net, 0.5);
                stack.push((right, depth + 1));
                stack.push((left, depth + 1));
                continue;
            }
            total = total.saturating_add(if count.is_finite() && count < 1e18 {
                count.ceil() as usize
            } else {
                usize::MAX
            });
            if total > MAX_FLATTEN_SEGMENTS {
                return Err(Error::TooLarge {
                    what: "flattening-segments-estimated",
                    value: total,
                    max: MAX_FLATTEN_SEGMENTS,
                });
            }
        }
        Ok(total)
    }

    /// An upper bound on the distance between the Bézier curve with homogeneous control points
    /// `piece` and its chord (the bounds listed at [`BezierCurve::flatten`]); `pts` is scratch
    /// for the projected points.
    fn net_error_bound(&self, piece: &[C::Homogeneous], pts: &mut Vec<C>) -> f64 {
        pts.clear();
        pts.extend(piece.iter().map(|&h| self.project(h)));
        let n = pts.len() - 1;
        let (first, last) = (pts[0], pts[n]);
        let inner = &pts[1..n];
        let hull = inner
            .iter()
            .map(|p| p.distance_to_segment(first, last))
            .fold(0.0, f64::max);
        if n < 2 {
            return hull;
        }
        let hull = hull.min(second_difference_bound::<C>(piece));
        if self.rational {
            return hull;
        }
        let factor = 1.0 - 0.5f64.powi(n as i32 - 1);
        let chord = last - first;
        let len2 = chord.dot_with(chord);
        // Offsets from the chord's own control points Q_i = first + (i/n)·chord.
        let parametric = inner
            .iter()
            .enumerate()
            .map(|(k, &p)| (p - (first + chord * ((k + 1) as f64 / n as f64))).norm())
            .fold(0.0, f64::max)
            * factor;
        let mut bound = hull.min(parametric);
        if len2 > 0.0 {
            let mut inside = true;
            let mut perpendicular = 0.0f64;
            for &p in inner {
                let v = p - first;
                let u = v.dot_with(chord) / len2;
                inside &= (0.0..=1.0).contains(&u);
                perpendicular = perpendicular.max((v - chord * u).norm());
            }
            if inside {
                bound = bound.min(perpendicular * factor);
            }
        }
        bound
    }
}

/// [`split_points`] into caller's buffers: the left part of `points` split at `s` (the top
/// edge `p_0^r(s)` of de Casteljau's triangle) into `left`, the right part (the hypotenuse
/// `p_{n−r}^r(s)`) into `right`, with `work` as scratch; no allocation once the buffers have
/// grown.
fn split_into<P: Point>(
    points: &[P],
    s: f64,
    work: &mut Vec<P>,
    left: &mut Vec<P>,
    right: &mut Vec<P>,
) {
    let n = points.len() - 1;
    work.clear();
    work.extend_from_slice(points);
    left.clear();
    left.push(points[0]);
    right.clear();
    right.resize(n + 1, points[n]);
    for r in 1..=n {
        for i in 0..=n - r {
            work[i] = work[i].lerp_to(work[i + 1], s);
        }
        left.push(work[0]);
        right[n - r] = work[n - r];
    }
}

/// `n(n−1) (D + R D_w) / (8 min w)`: a bound on the distance between the Bézier curve with
/// homogeneous control points `net` and its chord, and `h²` times it for the chords of equal
/// steps `h` (see [`BezierCurve::flatten_estimate`]); 0 for a line (`n < 2`).
fn second_difference_bound<C: Cartesian>(net: &[C::Homogeneous]) -> f64 {
    let n = net.len() - 1;
    if n < 2 {
        return 0.0;
    }
    let point = |h: C::Homogeneous| C::project(h);
    let (mut lo, mut hi) = (point(net[0]), point(net[0]));
    let mut min_w = f64::INFINITY;
    for &h in net {
        lo = lo.min_by_coord(point(h));
        hi = hi.max_by_coord(point(h));
        min_w = min_w.min(C::weight_of(h));
    }
    let c = (lo + hi) * 0.5;
    let radius = net
        .iter()
        .map(|&h| (point(h) - c).norm())
        .fold(0.0, f64::max);
    // w_i (P_i − c) = numerator(H_i) − w_i c.
    let centred = |h: C::Homogeneous| C::numerator(h) - c * C::weight_of(h);
    let (mut dd, mut dd_w) = (0.0f64, 0.0f64);
    for i in 0..n - 1 {
        let (a, b, d) = (net[i], net[i + 1], net[i + 2]);
        dd = dd.max((centred(a) - centred(b) * 2.0 + centred(d)).norm());
        dd_w = dd_w.max((C::weight_of(a) - 2.0 * C::weight_of(b) + C::weight_of(d)).abs());
    }
    (n * (n - 1)) as f64 * (dd + radius * dd_w) / (8.0 * min_w)
}
