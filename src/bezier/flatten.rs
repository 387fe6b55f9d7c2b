//! Adaptive flattening: a polyline that provably stays within a tolerance of the curve.

use super::{subsegment_points, BezierCurve};
use crate::error::{check_tolerance, Error, Result};
use crate::geom::Cartesian;
use crate::prelude::*;

/// Most segments one call to [`BezierCurve::flatten`] may produce.
pub const MAX_FLATTEN_SEGMENTS: usize = 1 << 16;

/// Smallest tolerance accepted, relative to the size of the control polygon: below this,
/// rounding in the subdivided control points is of the order of the tolerance itself.
const MIN_RELATIVE_TOLERANCE: f64 = 1e-10;

/// Bisection steps that refine each segment's end once it is bracketed: the segment then
/// reaches within 1/64 of the longest parameter step the error bound allows.
const BISECTION_STEPS: u32 = 6;

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
    ///   the chord and `Q_i` are the chord's own degree-`n` control points (linear precision).
    ///
    /// The smallest bound is used. Pieces are chosen greedily from the start: each step grows
    /// or shrinks the parameter step by factors of 2 until the bound brackets, then bisects, so
    /// every segment is close to the longest one allowed. Cusps, loops and straight curves need
    /// no special case: the bounds hold for any control polygon.
    ///
    /// # Errors
    /// [`Error::InvalidTolerance`] for a tolerance that is not finite and > 0, or below
    /// `1e-10` × the control polygon's size; [`Error::TooLarge`] when more than
    /// [`MAX_FLATTEN_SEGMENTS`] segments would be needed.
    pub fn flatten(&self, tolerance: f64) -> Result<Vec<C>> {
        check_tolerance(tolerance)?;
        let cps = self.control_points();
        let size = crate::geom::BoundingBox::of_points(&cps)
            .map(|b| b.diagonal())
            .unwrap_or(0.0);
        if tolerance < MIN_RELATIVE_TOLERANCE * size {
            return Err(Error::ToleranceTooSmall {
                value: tolerance,
                relative: MIN_RELATIVE_TOLERANCE,
                size,
            });
        }
        let mut scratch = Vec::with_capacity(cps.len());
        let mut out = vec![cps[0]];
        let mut s0 = 0.0;
        let mut step = 1.0f64;
        while s0 < 1.0 {
            let passes = |s1: f64| self.piece_error_bound(s0, s1) <= tolerance;
            let mut s1 = (s0 + step).min(1.0);
            let (mut good, mut bad);
            if passes(s1) {
                good = s1;
                bad = f64::NAN;
                while good < 1.0 {
                    let next = (s0 + 2.0 * (good - s0)).min(1.0);
                    if passes(next) {
                        good = next;
                    } else {
                        bad = next;
                        break;
                    }
                }
            } else {
                bad = s1;
                loop {
                    s1 = s0 + 0.5 * (bad - s0);
                    if s1 <= s0 {
                        return Err(Error::FlatteningStalled { value: tolerance });
                    }
                    if passes(s1) {
                        good = s1;
                        break;
                    }
                    bad = s1;
                }
            }
            if !bad.is_nan() {
                for _ in 0..BISECTION_STEPS {
                    let mid = 0.5 * (good + bad);
                    if passes(mid) {
                        good = mid;
                    } else {
                        bad = mid;
                    }
                }
            }
            step = good - s0;
            s0 = good;
            out.push(self.evaluate_local(s0, &mut scratch));
            if out.len() > MAX_FLATTEN_SEGMENTS + 1 {
                return Err(Error::TooLarge {
                    what: "number of flattening segments",
                    value: out.len() - 1,
                    max: MAX_FLATTEN_SEGMENTS,
                });
            }
        }
        Ok(out)
    }

    /// An upper bound on the distance between the piece `[s0, s1]` of the curve and its chord.
    pub(crate) fn piece_error_bound(&self, s0: f64, s1: f64) -> f64 {
        let piece = subsegment_points(&self.homogeneous, s0, s1);
        let pts: Vec<C> = piece.iter().map(|&h| self.project(h)).collect();
        let n = pts.len() - 1;
        let (first, last) = (pts[0], pts[n]);
        let inner = &pts[1..n];
        let hull = inner
            .iter()
            .map(|p| p.distance_to_segment(first, last))
            .fold(0.0, f64::max);
        if self.rational || n < 2 {
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
