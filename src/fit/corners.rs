//! Corner detection, ShortStraw-style (Wolin, Eoff & Hammond 2008), made robust to pointer
//! jitter.
//!
//! 1. Resample the stroke at a spacing `S = max(1.5·tol, diag/160, length/20000)` along its
//!    polyline: points `r_j` at arc length `j·S` (evenly around a closed stroke). Tying `S` to
//!    the tolerance and to the drawing's size makes the window span many jitter amplitudes.
//! 2. The *straw* at `r_j` is the chord `|r_{j+W} − r_{j−W}|` (`W = 4`): `2WS` on a straight
//!    run, `2WS·cos(θ/2)` at a corner turning by `θ`.
//! 3. A candidate is a local minimum of the straw (over `j ± W`, merging near duplicates)
//!    below `0.95 × median`.
//! 4. Its sample is the stroke sample within `±WS` of `r_j` farthest from the chord joining
//!    the stroke's points at arc lengths `j·S ∓ WS` (the apex `p`).
//! 5. It is a corner when the turning angle at the apex, `∠(p − X(σ − WS), X(σ + WS) − p)`
//!    (`X(σ)` the stroke's point at arc length `σ`, `σ` the apex's), is at least
//!    [`MIN_ANGLE`] (jitter shortens straws a little, it does not turn the chords by 40°), and
//!    the turn is concentrated: over half the window it is at least [`CONCENTRATION`] of the
//!    full one. A sharp corner turns as much at every scale; an arc of any radius turns
//!    exactly half as much over half the arc length (chords of arc `a` either side of a point
//!    of a circle of radius `ρ` turn by `a/ρ`).

use super::stroke::Stroke;
use crate::geom::Cartesian;

/// Half the straw window, in resampled points.
const W: usize = 4;

/// The smallest turning angle of a corner (radians, 40°).
pub(crate) const MIN_ANGLE: f64 = 40.0 * std::f64::consts::PI / 180.0;

/// The straw ratio below which a point may be a corner.
const STRAW_RATIO: f64 = 0.95;

/// The turning at half the window over the turning at the full window below which the bend
/// is round (1 for a sharp corner between straight runs, ½ for a circular arc).
const CONCENTRATION: f64 = 0.65;

/// The most resampled points.
const MAX_RESAMPLED: f64 = 20_000.0;

/// A corner at a stroke sample: `(index into stroke.pts, turning angle, straw / median)`.
pub(crate) type Found = (usize, f64, f64);

/// The corners of `stroke` (a closed stroke's last sample repeats its first), in order.
pub(crate) fn find<C: Cartesian>(stroke: &Stroke<C>, closed: bool, tol: f64) -> Vec<Found> {
    let n = stroke.len();
    let total = stroke.length();
    let mut spacing = (1.5 * tol).max(stroke.diagonal() / 160.0);
    spacing = spacing.max(total / MAX_RESAMPLED);
    if total.is_nan() || total <= 0.0 || spacing.is_nan() || total / spacing < (4 * W + 2) as f64 {
        return Vec::new();
    }
    // Resample: m points at arc length j·S (closed: m evenly, wrapping; open: m + 1 with the end).
    let m = (total / spacing).floor() as usize;
    let (count, step) = if closed {
        (m, total / m as f64)
    } else {
        (m + 1, spacing)
    };
    let r: Vec<C> = (0..count)
        .map(|j| stroke.point_at(j as f64 * step))
        .collect();
    let at = |j: isize| -> Option<C> {
        if closed {
            Some(r[j.rem_euclid(count as isize) as usize])
        } else if j >= 0 && (j as usize) < count {
            Some(r[j as usize])
        } else {
            None
        }
    };
    let w = W as isize;
    let straws: Vec<f64> = (0..count as isize)
        .map(|j| match (at(j - w), at(j + w)) {
            (Some(a), Some(b)) => (b - a).norm(),
            _ => f64::INFINITY,
        })
        .collect();
    let mut sorted: Vec<f64> = straws.iter().copied().filter(|s| s.is_finite()).collect();
    if sorted.is_empty() {
        return Vec::new();
    }
    // The same sort as the rest of the crate's f64 sorts (one copy of its code in the wasm):
    // `select_nth_unstable_by` would add its own ~5 KB for an O(n) instead of O(n log n) on
    // at most MAX_RESAMPLED values.
    sorted.sort_unstable_by(f64::total_cmp);
    let median = sorted[sorted.len() / 2];
    if median.is_nan() || median <= 0.0 {
        return Vec::new();
    }
    let straw = |j: isize| -> f64 {
        if closed {
            straws[j.rem_euclid(count as isize) as usize]
        } else if j >= 0 && (j as usize) < count {
            straws[j as usize]
        } else {
            f64::INFINITY
        }
    };
    let mut found: Vec<Found> = Vec::new();
    for j in 0..count as isize {
        let s = straw(j);
        if s.is_nan() || s >= STRAW_RATIO * median {
            continue;
        }
        // A strict minimum against earlier neighbours, not above later ones: one per dip.
        let minimum = (1..=w).all(|k| straw(j - k) > s && straw(j + k) >= s);
        if !minimum {
            continue;
        }
        let h = W as f64 * step;
        let index = apex(stroke, closed, j as f64 * step, h);
        // An open stroke's ends are no corners: the window must see both sides.
        if !closed && (stroke.arc[index] < 0.5 * h || stroke.arc[index] > total - 0.5 * h) {
            continue;
        }
        // The turn at the apex sample, over the full window and half of it.
        let around = |d: f64| {
            let si = stroke.arc[index];
            let at = |s: f64| {
                if closed {
                    stroke.point_at(super::wrap(s, total))
                } else {
                    stroke.point_at(s.clamp(0.0, total))
                }
            };
            let p = stroke.pts[index];
            turning(p - at(si - d), at(si + d) - p)
        };
        let angle = around(h);
        if angle < MIN_ANGLE || around(0.5 * h) < CONCENTRATION * angle {
            continue;
        }
        found.push((index, angle, s / median));
    }
    // A closed stroke's last sample is its first.
    for f in &mut found {
        if closed && f.0 == n - 1 {
            f.0 = 0;
        }
    }
    // In sample order (a stable insertion sort: a handful of corners, and no ~5 KB of
    // `slice::sort_by_key` in the wasm), one per sample.
    for i in 1..found.len() {
        let mut j = i;
        while j > 0 && found[j - 1].0 > found[j].0 {
            found.swap(j - 1, j);
            j -= 1;
        }
    }
    found.dedup_by_key(|f| f.0);
    if !closed {
        found.retain(|f| f.0 > 0 && f.0 < n - 1);
    }
    found
}

/// The angle between `a` and `b` (0 when either vanishes).
pub(crate) fn turning<C: Cartesian>(a: C, b: C) -> f64 {
    let (na, nb) = (a.norm(), b.norm());
    if !(na > 0.0 && nb > 0.0) {
        return 0.0;
    }
    (a.dot_with(b) / (na * nb)).clamp(-1.0, 1.0).acos()
}

/// The sample with arc length in `σ ± h` (wrapping when closed) farthest from the chord of the
/// stroke's points at `σ − h` and `σ + h`.
fn apex<C: Cartesian>(stroke: &Stroke<C>, closed: bool, sigma: f64, h: f64) -> usize {
    let n = stroke.len();
    let total = stroke.length();
    let wrap = |s: f64| {
        if closed {
            super::wrap(s, total)
        } else {
            s.clamp(0.0, total)
        }
    };
    let (a, b) = (
        stroke.point_at(wrap(sigma - h)),
        stroke.point_at(wrap(sigma + h)),
    );
    let start = wrap(sigma - h);
    let mut k = stroke.arc.partition_point(|&s| s < start).min(n - 1);
    let mut best = (-1.0, k);
    // Walk forward over at most 2h of arc (and at most 4096 samples, evenly strided).
    let first = k;
    let mut covered = 0.0;
    let span_end = {
        let e = stroke.arc.partition_point(|&s| s <= wrap(sigma + h));
        if e >= first {
            e - first
        } else {
            e + n - first
        }
    };
    let stride = (span_end / 4096).max(1);
    let mut steps = 0;
    while covered <= 2.0 * h && steps <= span_end {
        let d = stroke.pts[k].distance_to_segment(a, b);
        if d > best.0 {
            best = (d, k);
        }
        let next = if k + stride < n {
            k + stride
        } else if closed {
            (k + stride) - (n - 1)
        } else {
            break;
        };
        let ds = if next > k {
            stroke.arc[next] - stroke.arc[k]
        } else {
            total - stroke.arc[k] + stroke.arc[next]
        };
        covered += ds;
        k = next;
        steps += stride;
    }
    best.1
}
