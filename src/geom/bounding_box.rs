//! Axis-aligned bounding boxes of control points.

use super::Point;

/// Axis-aligned bounding box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingBox<P> {
    /// Component-wise minimum.
    pub min: P,
    /// Component-wise maximum.
    pub max: P,
}

impl<P: Point> BoundingBox<P> {
    /// The box of a non-empty set of points (`None` for an empty slice).
    pub fn of_points(points: &[P]) -> Option<Self> {
        let first = *points.first()?;
        Some(points.iter().fold(
            BoundingBox {
                min: first,
                max: first,
            },
            |b, &p| b.including(p),
        ))
    }
    /// The smallest box containing `self` and `p`.
    pub fn including(self, p: P) -> Self {
        BoundingBox {
            min: self.min.min_by_coord(p),
            max: self.max.max_by_coord(p),
        }
    }
    /// Length of the diagonal.
    pub fn diagonal(&self) -> f64 {
        (self.max - self.min).norm()
    }
}
