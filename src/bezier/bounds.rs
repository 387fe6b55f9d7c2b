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
        /// Subdivision depth after which a piece's hull bound is accepted as is.
        const MAX_DEPTH: u32 = 60;
        let scale = self
            .control_points()
            .iter()
            .fold(0.0f64, |m, p| m.max(p.coord(axis).abs()))
            .max(f64::MIN_POSITIVE);
        let accuracy = 1e-13 * scale;
        let mut best = start;
        let mut stack = vec![(self.homogeneous.clone(), 0u32)];
        while let Some((pts, depth)) = stack.pop() {
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
            if depth >= MAX_DEPTH {
                best = best.max(upper);
                continue;
            }
            let (l, r) = split_points(&pts, 0.5);
            stack.push((l, depth + 1));
            stack.push((r, depth + 1));
        }
        best
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
