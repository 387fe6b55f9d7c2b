//! Surface/line intersection: box recursion on the Bézier patches, then Newton.

use super::{in_argument, BSplineSurface};
use crate::error::{check_coordinate_of, check_tolerance, Error, Result};
use glam::{DMat3, DVec3};

/// Deepest subdivision level of the box recursion below a Bézier patch.
pub const MAX_SURFACE_INTERSECTION_DEPTH: u32 = 32;

/// The work one search may spend on boxes, in units of `(p + 1)(q + 1)(p + q + 2)`, what
/// looking at and quartering one box of a degree-(p, q) patch costs (bounds of its net, then de
/// Casteljau along both directions): 50 000 boxes of a bicubic. Past it, every box still
/// pending starts a Newton refinement instead of being split. A work budget: a high-degree
/// surface would otherwise spend seconds on the same number of boxes.
pub const MAX_INTERSECTION_WORK: usize = 50_000 * 16 * 8;

/// A piece is split until its net is this close to a parallelogram (`2δ + |D|/4`, see
/// `flatness`) relative to its bounding box's diagonal: a line then meets it at most once,
/// unless it nearly lies in it, and Newton from its centre converges.
const FLAT_ENOUGH: f64 = 1e-2;

/// The boxes [`MAX_INTERSECTION_WORK`] pays for on a degree-(p, q) surface (at least one).
fn max_boxes(p: usize, q: usize) -> usize {
    (MAX_INTERSECTION_WORK / ((p + 1) * (q + 1) * (p + q + 2))).max(1)
}

/// Most Newton refinements one search runs, so at most this many hits. Past it the remaining
/// pieces are not refined: only a line lying in (or along) the surface, or a tolerance far
/// below the surface's size, leaves this many pieces, and a line in the surface gets a sample
/// of its points anyway. A work budget: 60 000 starts (each up to 40 steps, and each new hit
/// compared with those kept) took seconds.
pub const MAX_NEWTON_STARTS: usize = 1 << 12;

/// Newton steps from one start.
const MAX_NEWTON_STEPS: usize = 40;

impl BSplineSurface {
    /// Where the surface meets the infinite line `origin + s·direction`: `(u, v, s)` per hit,
    /// sorted by `s`, each with `|S(u, v) − (origin + s·direction)| ≤ tolerance` (model units;
    /// `s` is the foot of the perpendicular from `S(u, v)` to the line).
    ///
    /// **Search.** The Bézier patches ([`BSplineSurface::to_bezier_patches`]) are split at
    /// `(½, ½)` while the line meets the bounding box of their control points (grown by
    /// `tolerance`; the patch lies in the convex hull of its net, weights being > 0), until a
    /// piece is nearly a parallelogram (`2δ + |D|/4 ≤ 1e-2 ×` its diagonal), smaller than
    /// `tolerance`, or [`MAX_SURFACE_INTERSECTION_DEPTH`] deep, and while the boxes' work stays
    /// within [`MAX_INTERSECTION_WORK`]. Boxes the line misses are
    /// pruned, so a line missing the surface's bounding box costs one test per patch.
    ///
    /// **Refinement.** From each remaining piece's centre, Newton's method on
    /// `F(u, v, s) = S(u, v) − origin − s·direction = 0`, Jacobian `[S_u  S_v  −direction]`
    /// (damped by `1e-14·trace(JᵀJ)` so that a tangent line, where the Jacobian is singular,
    /// still converges to the nearest point), `(u, v)` kept in the domain. A result is kept
    /// when its point lies within `tolerance` of the line; hits whose points lie within
    /// `tolerance` of each other are merged (the first in the search is kept), so a hit on a
    /// patch seam is reported once. At most [`MAX_NEWTON_STARTS`] pieces are refined.
    ///
    /// **A line lying in the surface** (a segment of it on the surface) has infinitely many
    /// hits: the result is then a finite sample of that segment, at most one point per piece
    /// the search reaches (its Newton limit), merged to points at least `tolerance` apart —
    /// not the segment's ends. A tangent line gives its touching point when the nearest point
    /// is within `tolerance`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a coordinate of `origin` or `direction`, an error naming
    /// `direction` for a zero direction, [`Error::InvalidTolerance`] unless `tolerance` is
    /// finite and > 0.
    pub fn intersect_line(
        &self,
        origin: DVec3,
        direction: DVec3,
        tolerance: f64,
    ) -> Result<Vec<[f64; 3]>> {
        for (k, x) in origin.to_array().into_iter().enumerate() {
            check_coordinate_of("origin", k, x)?;
        }
        for (k, x) in direction.to_array().into_iter().enumerate() {
            check_coordinate_of("direction", k, x)?;
        }
        let length = direction.length();
        if length == 0.0 {
            return Err(in_argument(
                "direction",
                Error::NotPositive {
                    name: "length",
                    value: length,
                },
            ));
        }
        let tolerance = check_tolerance(tolerance)?;
        let unit = direction / length;
        let max_boxes = max_boxes(self.degree_u(), self.degree_v());
        let (starts, _) = self.boxes_on_line(origin, unit, tolerance, max_boxes)?;
        let mut hits: Vec<([f64; 3], DVec3)> = Vec::new();
        for (u, v) in starts.into_iter().take(MAX_NEWTON_STARTS) {
            let Some((u, v, point)) = self.newton_on_line(u, v, origin, direction)? else {
                continue;
            };
            let foot = origin + (point - origin).dot(unit) * unit;
            if (point - foot).length() > tolerance
                || hits.iter().any(|(_, q)| (*q - point).length() <= tolerance)
            {
                continue;
            }
            let s = (point - origin).dot(direction) / (length * length);
            // Few hits: kept sorted by s as they come (no sort instantiation in the wasm).
            let at = hits.partition_point(|(h, _)| h[2] <= s);
            hits.insert(at, ([u, v, s], point));
        }
        Ok(hits.into_iter().map(|(h, _)| h).collect())
    }

    /// The search of [`BSplineSurface::intersect_line`]: the `(u, v)` centres of the pieces
    /// Newton starts from, and the number of boxes looked at (at most `max_boxes`, plus the
    /// four of the last split).
    fn boxes_on_line(
        &self,
        origin: DVec3,
        unit: DVec3,
        tolerance: f64,
        max_boxes: usize,
    ) -> Result<(Vec<(f64, f64)>, usize)> {
        let mut starts = Vec::new();
        let mut stack: Vec<_> = self
            .pieces()?
            .into_iter()
            .map(|p| (p.patch, p.u, p.v, 0u32))
            .collect();
        let mut visited = 0usize;
        while let Some((patch, u, v, depth)) = stack.pop() {
            visited += 1;
            let (lo, hi) = patch.net_bounds();
            let (lo, hi) = (lo - DVec3::splat(tolerance), hi + DVec3::splat(tolerance));
            if !line_meets_box(origin, unit, lo, hi) {
                continue;
            }
            let diagonal = (hi - lo).length();
            let f = patch.flatness();
            let flat = 2.0 * f.deviation + 0.25 * f.twist <= FLAT_ENOUGH * diagonal;
            if flat
                || diagonal <= 3.0 * tolerance
                || depth >= MAX_SURFACE_INTERSECTION_DEPTH
                || visited + stack.len() >= max_boxes
            {
                starts.push((0.5 * (u.0 + u.1), 0.5 * (v.0 + v.1)));
                continue;
            }
            let (um, vm) = (0.5 * (u.0 + u.1), 0.5 * (v.0 + v.1));
            let [a, b, c, d] = patch.quarters()?;
            stack.push((d, (um, u.1), (vm, v.1), depth + 1));
            stack.push((c, (um, u.1), (v.0, vm), depth + 1));
            stack.push((b, (u.0, um), (vm, v.1), depth + 1));
            stack.push((a, (u.0, um), (v.0, vm), depth + 1));
        }
        Ok((starts, visited))
    }

    /// Damped Newton on `S(u, v) − origin − s·direction = 0` from `(u, v)`, `(u, v)` clamped to
    /// the domain: the last `(u, v, S(u, v))`, or `None` if a step failed (a singular system).
    fn newton_on_line(
        &self,
        mut u: f64,
        mut v: f64,
        origin: DVec3,
        direction: DVec3,
    ) -> Result<Option<(f64, f64, DVec3)>> {
        let ((ua, ub), (va, vb)) = (self.knots_u.domain(), self.knots_v.domain());
        let mut point = self.evaluate(u, v)?;
        let mut s = (point - origin).dot(direction) / direction.length_squared();
        for _ in 0..MAX_NEWTON_STEPS {
            let (su, sv) = (self.derivative(u, v, 1, 0)?, self.derivative(u, v, 0, 1)?);
            let f = point - origin - s * direction;
            let j = DMat3::from_cols(su, sv, -direction);
            let jt = j.transpose();
            let normal = jt * j;
            let damping = 1e-14 * (normal.x_axis.x + normal.y_axis.y + normal.z_axis.z);
            let system = normal + DMat3::from_diagonal(DVec3::splat(damping));
            if system.determinant().abs() <= f64::MIN_POSITIVE {
                return Ok(None);
            }
            let step = -(system.inverse() * (jt * f));
            if !step.is_finite() {
                return Ok(None);
            }
            let (nu, nv) = ((u + step.x).clamp(ua, ub), (v + step.y).clamp(va, vb));
            let moved = (nu - u).abs() + (nv - v).abs();
            u = nu;
            v = nv;
            s += step.z;
            point = self.evaluate(u, v)?;
            if moved <= 1e-15 * ((ub - ua) + (vb - va)) {
                break;
            }
        }
        Ok(Some((u, v, point)))
    }

    /// The bounding box `(min, max)` of the Cartesian control points.
    fn net_bounds(&self) -> (DVec3, DVec3) {
        self.net.iter().map(|h| h.truncate() / h.w).fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(p), hi.max(p)),
        )
    }
}

/// Whether the infinite line `origin + s·unit` meets the box `[lo, hi]` (slab test).
fn line_meets_box(origin: DVec3, unit: DVec3, lo: DVec3, hi: DVec3) -> bool {
    let (mut enter, mut leave) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..3 {
        let (o, d, a, b) = (origin[k], unit[k], lo[k], hi[k]);
        if d == 0.0 {
            if o < a || o > b {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((a - o) / d, (b - o) / d);
        enter = enter.max(t0.min(t1));
        leave = leave.min(t0.max(t1));
    }
    enter <= leave
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn the_work_budget_gives_fewer_boxes_to_higher_degrees() {
        assert_eq!(max_boxes(3, 3), 50_000, "a bicubic keeps its 50 000 boxes");
        assert_eq!(max_boxes(30, 2), MAX_INTERSECTION_WORK / (31 * 3 * 34));
        assert!(max_boxes(64, 64) >= 1);
    }

    #[test]
    fn the_box_search_stops_at_its_budget() {
        // A ruling of an extruded degree-24 wiggle lies in the surface: the pieces along it
        // split until flat; with a budget of 16 boxes the search stops early, and Newton from
        // the pieces it has still finds the line's points on the surface.
        let n = 24;
        let mut seed = 7u32;
        let mut random = move || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            f64::from(seed >> 8) / f64::from(1u32 << 24) * 2.0 - 1.0
        };
        let points: Vec<DVec3> = (0..=n)
            .map(|i| DVec3::new(i as f64 / n as f64, random(), 0.0))
            .collect();
        let knots = [vec![0.0; n + 1], vec![1.0; n + 1]].concat();
        let curve = crate::BSplineCurve::new(points, n, knots, None).unwrap();
        let s = crate::surface::extrude(&curve, DVec3::Z).unwrap();
        let origin = s.evaluate(0.37, 0.5).unwrap();
        let (_, free) = s
            .boxes_on_line(origin, DVec3::Z, 1e-12, usize::MAX)
            .unwrap();
        let (starts, capped) = s.boxes_on_line(origin, DVec3::Z, 1e-12, 16).unwrap();
        assert!(free > 16, "the budget must bind: {free} boxes without it");
        assert!(capped <= 16 + 4, "{capped} boxes, budget 16");
        assert!(!starts.is_empty());
    }
}
