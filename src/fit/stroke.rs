//! The stroke as the fitters see it: the samples without repeated consecutive points, the
//! original index of each, and the cumulative chord length `s_k = Σ_{j<k} |Q_{j+1} − Q_j|`
//! (arc length of the polyline), with the point at any arc length by linear interpolation.

use crate::geom::Cartesian;

/// Deduplicated samples `pts[k]` (original index `orig[k]`) and their arc lengths `arc[k]`.
#[derive(Debug, Clone)]
pub(crate) struct Stroke<C: Cartesian> {
    /// The samples, no two consecutive ones equal.
    pub pts: Vec<C>,
    /// The original index of each sample.
    pub orig: Vec<usize>,
    /// Cumulative polyline length, `arc[0] = 0`.
    pub arc: Vec<f64>,
}

impl<C: Cartesian> Stroke<C> {
    /// The samples of `points` with consecutive repeats skipped (the first of a run is kept).
    pub fn new(points: &[C]) -> Self {
        Self::from_parts(points, 0..points.len())
    }

    /// From samples and their original indices (consecutive repeats dropped).
    pub fn from_parts(points: &[C], indices: impl IntoIterator<Item = usize>) -> Self {
        let mut pts = Vec::with_capacity(points.len());
        let mut orig = Vec::with_capacity(points.len());
        for (&p, i) in points.iter().zip(indices) {
            if pts.last() != Some(&p) {
                pts.push(p);
                orig.push(i);
            }
        }
        let mut s = Stroke {
            pts,
            orig,
            arc: Vec::new(),
        };
        s.recompute_arc();
        s
    }

    /// Recomputes `arc` from `pts`.
    pub fn recompute_arc(&mut self) {
        self.arc.clear();
        let mut total = 0.0;
        self.arc.push(0.0);
        for w in self.pts.windows(2) {
            total += (w[1] - w[0]).norm();
            self.arc.push(total);
        }
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.pts.len()
    }

    /// The total polyline length.
    pub fn length(&self) -> f64 {
        self.arc.last().copied().unwrap_or(0.0)
    }

    /// The point of the polyline at arc length `s`, clamped to `[0, length]`.
    pub fn point_at(&self, s: f64) -> C {
        let n = self.pts.len();
        if n == 1 || s <= 0.0 {
            return self.pts[0];
        }
        if s >= self.length() {
            return self.pts[n - 1];
        }
        // First k with arc[k] > s; then s lies in [arc[k−1], arc[k]).
        let k = self.arc.partition_point(|&a| a <= s).clamp(1, n - 1);
        let (a, b) = (self.arc[k - 1], self.arc[k]);
        let t = if b > a { (s - a) / (b - a) } else { 0.0 };
        self.pts[k - 1].lerp_to(self.pts[k], t)
    }

    /// The diagonal of the samples' bounding box.
    pub fn diagonal(&self) -> f64 {
        crate::geom::BoundingBox::of_points(&self.pts).map_or(0.0, |b| b.diagonal())
    }
}
