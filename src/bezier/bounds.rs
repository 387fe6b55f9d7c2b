//! The tight bounding box (from the extremes of each coordinate) and the crossings of the
//! control polygon with a line.

use super::{de_casteljau_point, split_points, BezierCurve};
use crate::geom::{BoundingBox, Cartesian};
use crate::prelude::*;

impl<C: Cartesian> BezierCurve<C> {
    /// The tight axis-aligned bounding box of the curve itself (not of its control polygon),
    /// found per axis by branch and bound on subdivided control polygons (convex hull property):
    /// each bound is within `1e-12` relative of the true extreme.
    pub fn bounding_box(&self) -> BoundingBox<C> {
        let cps = self.control_points();
        let mut min = cps[0].min_by_coord(cps[cps.len() - 1]);
        let mut max = cps[0].max_by_coord(cps[cps.len() - 1]);
        let mut lo = [0.0; 3];
        let mut hi = [0.0; 3];
        for k in 0..C::DIM {
            hi[k] = self.extreme(k, 1.0, max.coord(k));
            lo[k] = -self.extreme(k, -1.0, -min.coord(k)) + 0.0; // + 0.0 turns −0 into 0
        }
        min = C::from_slice(&lo[..C::DIM]);
        max = C::from_slice(&hi[..C::DIM]);
        BoundingBox { min, max }
    }

    /// `max_t sign·P(t)[axis]` (so `−min` for `sign = −1`), starting from the known lower bound `start` (an end point).
    fn extreme(&self, axis: usize, sign: f64, start: f64) -> f64 {
        self.extreme_counted(axis, sign, start).0
    }

    /// [`BezierCurve::extreme`] and the number of pieces it examined.
    fn extreme_counted(&self, axis: usize, sign: f64, start: f64) -> (f64, usize) {
        /// Subdivision depth after which a piece's hull bound is accepted as is.
        const MAX_DEPTH: u32 = 60;
        let mut pieces = 0;
        /// Most pieces examined: past it each remaining piece's hull bound is accepted as is
        /// (still an upper bound). Curves take ~100; coordinates that overflow (an end point of
        /// −∞ makes `best + accuracy` NaN, so nothing is ever pruned) would otherwise split to
        /// the depth cap, 2^60 pieces — the API fuzz found boundingBox() hanging on one.
        const MAX_PIECES: usize = 1 << 12;
        let scale = self
            .control_points()
            .iter()
            .fold(0.0f64, |m, p| m.max(p.coord(axis).abs()))
            .max(f64::MIN_POSITIVE);
        let accuracy = 1e-13 * scale;
        let mut best = start;
        let mut stack = vec![(self.homogeneous.clone(), 0u32)];
        while let Some((pts, depth)) = stack.pop() {
            pieces += 1;
            let coords = pts.iter().map(|&h| sign * self.project(h).coord(axis));
            let upper = coords.fold(f64::NEG_INFINITY, f64::max);
            if upper <= best + accuracy {
                continue;
            }
            let mid = sign
                * self
                    .project(de_casteljau_point(&pts, 0.5, &mut Vec::new()))
                    .coord(axis);
            best = best.max(mid);
            if depth >= MAX_DEPTH || pieces >= MAX_PIECES {
                best = best.max(upper);
                continue;
            }
            let (l, r) = split_points(&pts, 0.5);
            stack.push((l, depth + 1));
            stack.push((r, depth + 1));
        }
        (best, pieces)
    }

    /// Number of times the infinite line through `p0` and `p1` crosses the control polygon
    /// (2D; a vertex on the line counts once where the polygon passes through). Used to show
    /// the variation diminishing property: the curve crosses no more often.
    pub fn polygon_line_crossings(&self, p0: C, p1: C) -> usize {
        let d = p1 - p0;
        let side = |p: C| C::cross_norm(d, p - p0);
        let mut count = 0;
        let mut prev_sign = 0.0;
        for p in self.control_points() {
            let s = side(p);
            let sign = if s > 0.0 {
                1.0
            } else if s < 0.0 {
                -1.0
            } else {
                0.0
            };
            if sign != 0.0 {
                if prev_sign != 0.0 && sign != prev_sign {
                    count += 1;
                }
                prev_sign = sign;
            }
        }
        count
    }
}

#[cfg(test)]
mod tests {
    use super::BezierCurve;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use glam::DVec2;

    #[test]
    fn overflowing_homogeneous_points_end_the_search() {
        // Finite points and weights whose products overflow (x·w = −∞; the fuzz's x = −1e308 is
        // now refused as a coordinate, so x = −1e120, the largest allowed, with the same
        // weights): the API fuzz found boundingBox() of such a curve (split from a circular arc
        // centred at x = −1e308) running for minutes.
        let weights = [
            2.4636665425729007,
            1.1952868450047331e308,
            1.174269291320791e308,
            1.1538690437544182e308,
        ];
        let yw = [
            -0.94935108668173,
            -4.4426325190583735e307,
            -1.3728633629450694e307,
            9.471882720169021e306,
        ];
        let points = (0..4)
            .map(|i| DVec2::new(-1e120, yw[i] / weights[i]))
            .collect();
        let curve = BezierCurve::new(points, Some(&weights)).unwrap();
        // bounding_box() starts the x search from the end points' x: −∞.
        let (x, pieces) = curve.extreme_counted(0, 1.0, f64::NEG_INFINITY);
        // the budget, then the pieces still on the stack (one per level at most)
        assert!(pieces <= (1 << 12) + 64, "{pieces} pieces");
        // Every point has x = −1e120, the true maximum; an overflowed search may give no number.
        assert!(x.is_nan() || x.is_infinite() || x == -1e120, "{x}");
        let b = curve.bounding_box();
        assert!(
            (b.max.y - 0.0821).abs() < 1e-3 && (b.min.y + 0.3853).abs() < 1e-3,
            "{b:?}"
        );
    }
}
