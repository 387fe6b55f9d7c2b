//! Curve/line intersection by recursive bounding-box subdivision (syllabus §2), with the boxes
//! visited kept for teaching.

use super::{de_casteljau_point, split_points, BezierCurve};
use crate::error::{check_finite, check_tolerance, Error, Result};
use crate::geom::{BoundingBox, Cartesian};
use crate::prelude::*;
use glam::{DVec2, DVec3};

/// Deepest subdivision level of the box recursion (2^-48 of the parameter range).
pub const MAX_INTERSECTION_DEPTH: u32 = 48;

/// Most boxes one search visits; past this the search stops refining (each remaining
/// candidate is still resolved by root refinement).
const MAX_VISITED_BOXES: usize = 100_000;

/// Bisection steps that refine a bracketed root (enough to reach adjacent doubles).
const ROOT_BISECTION_STEPS: u32 = 200;

/// One box of the subdivision search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VisitedBox {
    /// Subdivision depth (0 = the whole curve).
    pub depth: u32,
    /// The control points' bounding box of this piece.
    pub bounds: BoundingBox<DVec2>,
    /// Whether the line meets the box (within tolerance); missed boxes are pruned.
    pub hit: bool,
}

/// The result of [`BezierCurve::intersect_line`].
#[derive(Debug, Clone, PartialEq)]
pub struct LineIntersection {
    /// Sorted parameters (on the curve's interval) of the intersections, without duplicates.
    pub ts: Vec<f64>,
    /// Every box the recursion looked at, in visiting order.
    pub boxes: Vec<VisitedBox>,
}

impl BezierCurve<DVec2> {
    /// Where the curve meets the infinite line through `p0` and `p1`.
    ///
    /// The control polygon's bounding box is tested against the line; a box the line misses
    /// by more than `tolerance` is pruned, the others are split at the middle until they are
    /// smaller than `tolerance` (or the whole piece lies within `tolerance` of the line). Runs
    /// of adjacent candidate pieces are then resolved on the signed distance
    /// `D(s) = Σ B_i(s) w_i d_i` (`d_i` the control points' signed distances): every sign
    /// change is refined by bisection to machine precision, and a run without one (a tangency
    /// or near miss) gives the parameter where `|D|` is smallest. Each returned `t` has its
    /// point within `tolerance` of the line; results whose points lie within `tolerance` of
    /// each other are merged, so a root exactly on a split point is reported once.
    ///
    /// A curve lying on the line (every control point within `tolerance` of it) gives the two
    /// ends of its interval, `[a, b]`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a bad coordinate, [`Error::DegenerateLine`] when `p0 == p1`,
    /// [`Error::InvalidTolerance`] unless `tolerance` is finite and > 0.
    pub fn intersect_line(&self, p0: DVec2, p1: DVec2, tolerance: f64) -> Result<LineIntersection> {
        for (k, v) in [p0.x, p0.y, p1.x, p1.y].into_iter().enumerate() {
            check_finite(["x0", "y0", "x1", "y1"][k], None, v)?;
        }
        check_tolerance(tolerance)?;
        let dir = (p1 - p0)
            .try_normalize()
            .ok_or(Error::DegenerateLine { x: p0.x, y: p0.y })?;
        let signed = |p: DVec2| dir.perp_dot(p - p0);
        // Homogeneous signed distances: D(s) = Σ B_i(s) w_i d_i has the sign of the distance.
        let distance_coeffs: Vec<f64> = self
            .homogeneous
            .iter()
            .map(|&h| {
                let w = DVec2::weight_of(h);
                dir.perp_dot(DVec2::numerator(h) - p0 * w)
            })
            .collect();
        let to_t = |s: f64| self.a + (self.b - self.a) * s;
        let cps = self.control_points();
        let mut boxes = Vec::new();
        if cps.iter().all(|&p| signed(p).abs() <= tolerance) {
            boxes.push(VisitedBox {
                depth: 0,
                bounds: BoundingBox::of_points(&cps).expect("a curve has points"),
                hit: true,
            });
            return Ok(LineIntersection {
                ts: vec![self.a, self.b],
                boxes,
            });
        }

        // Depth-first, left half first, so candidate pieces come out in parameter order.
        let mut candidates: Vec<(f64, f64)> = Vec::new();
        let mut stack: Vec<(Vec<DVec3>, f64, f64, u32)> =
            vec![(self.homogeneous.clone(), 0.0, 1.0, 0)];
        while let Some((pts, s0, s1, depth)) = stack.pop() {
            let projected: Vec<DVec2> = pts.iter().map(|&h| self.project(h)).collect();
            let bounds = BoundingBox::of_points(&projected).expect("a piece has points");
            let corners = [
                bounds.min,
                DVec2::new(bounds.min.x, bounds.max.y),
                bounds.max,
                DVec2::new(bounds.max.x, bounds.min.y),
            ];
            let (lo, hi) = corners
                .iter()
                .map(|&c| signed(c))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), d| {
                    (lo.min(d), hi.max(d))
                });
            let hit = lo <= tolerance && hi >= -tolerance;
            if boxes.len() < MAX_VISITED_BOXES {
                boxes.push(VisitedBox { depth, bounds, hit });
            }
            if !hit {
                continue;
            }
            let on_line = projected.iter().all(|&p| signed(p).abs() <= tolerance);
            if on_line
                || bounds.diagonal() <= tolerance
                || depth >= MAX_INTERSECTION_DEPTH
                || boxes.len() >= MAX_VISITED_BOXES
            {
                candidates.push((s0, s1));
                continue;
            }
            let (l, r) = split_points(&pts, 0.5);
            let mid = 0.5 * (s0 + s1);
            stack.push((r, mid, s1, depth + 1));
            stack.push((l, s0, mid, depth + 1));
        }

        // Resolve runs of touching candidate pieces.
        let mut scratch = Vec::with_capacity(distance_coeffs.len());
        let mut distance = |s: f64| de_casteljau_point(&distance_coeffs, s, &mut scratch);
        let mut roots: Vec<f64> = Vec::new();
        let mut run_start = 0;
        while run_start < candidates.len() {
            let mut run_end = run_start;
            while run_end + 1 < candidates.len()
                && candidates[run_end + 1].0 <= candidates[run_end].1
            {
                run_end += 1;
            }
            let run = &candidates[run_start..=run_end];
            let before = roots.len();
            // Sign changes across the run's piece boundaries.
            let mut prev_s = run[0].0;
            let mut prev_d = distance(prev_s);
            if prev_d == 0.0 {
                roots.push(prev_s);
            }
            for &(_, s1) in run {
                let d = distance(s1);
                if d == 0.0 {
                    roots.push(s1);
                } else if prev_d != 0.0 && (d > 0.0) != (prev_d > 0.0) {
                    roots.push(bisect(&mut distance, prev_s, s1, prev_d));
                }
                prev_s = s1;
                prev_d = d;
            }
            if roots.len() == before {
                // No sign change: a tangency or a near miss within tolerance.
                let (s_lo, s_hi) = (run[0].0, run[run.len() - 1].1);
                let s = minimize_abs(&mut distance, s_lo, s_hi);
                let p = self.evaluate_local(s, &mut Vec::new());
                if signed(p).abs() <= tolerance {
                    roots.push(s);
                }
            }
            run_start = run_end + 1;
        }
        roots.sort_unstable_by(f64::total_cmp);
        // Merge results whose points are within tolerance of each other.
        let mut ts: Vec<f64> = Vec::with_capacity(roots.len());
        let mut last_point: Option<DVec2> = None;
        let mut eval_scratch = Vec::new();
        for s in roots {
            let p = self.evaluate_local(s, &mut eval_scratch);
            if let Some(q) = last_point {
                if (p - q).length() <= tolerance {
                    continue;
                }
            }
            last_point = Some(p);
            ts.push(to_t(s));
        }
        Ok(LineIntersection { ts, boxes })
    }
}

/// Bisection for a root of `f` in `[a, b]` where `f(a) = fa` and `f(b)` have opposite signs;
/// stops when the interval no longer shrinks in floating point.
fn bisect(f: &mut impl FnMut(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    for _ in 0..ROOT_BISECTION_STEPS {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            break;
        }
        let fm = f(mid);
        if fm == 0.0 {
            return mid;
        }
        if (fm > 0.0) == (fa > 0.0) {
            a = mid;
            fa = fm;
        } else {
            b = mid;
        }
    }
    if f(a).abs() <= f(b).abs() {
        a
    } else {
        b
    }
}

/// The argument of the smallest `|f|` on `[a, b]`: a coarse scan, then golden-section search
/// around the best sample.
fn minimize_abs(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    const SCAN: usize = 16;
    const GOLDEN_STEPS: u32 = 80;
    let h = (b - a) / SCAN as f64;
    let best = (0..=SCAN)
        .map(|k| a + h * k as f64)
        .map(|s| (s, f(s).abs()))
        .fold(
            (a, f64::INFINITY),
            |best, c| if c.1 < best.1 { c } else { best },
        );
    let (mut lo, mut hi) = ((best.0 - h).max(a), (best.0 + h).min(b));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..GOLDEN_STEPS {
        let x1 = hi - g * (hi - lo);
        let x2 = lo + g * (hi - lo);
        if f(x1).abs() <= f(x2).abs() {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let mid = 0.5 * (lo + hi);
    if f(best.0).abs() <= f(mid).abs() {
        best.0
    } else {
        mid
    }
}
