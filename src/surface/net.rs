//! The control net: building a surface (B-spline or Bézier patch), reading it, and the
//! in-place edits of a drag.

use super::{checked_count, in_argument, BSplineSurface};
use crate::bspline::{check_degree, KnotVector};
use crate::error::SurfaceError;
use crate::error::{check_coordinate, check_finite, Error, Result};
use crate::geom::{check_all_coordinates, check_weights, MAX_SAMPLES};
use glam::{DVec3, DVec4};

impl BSplineSurface {
    /// A surface from flat coordinates `[x00, y00, z00, x01, …]` (row-major, `rows·cols·3`
    /// numbers), degrees `p` (along u, the rows) and `q` (along v, the columns), knot vectors of
    /// `rows + p + 1` and `cols + q + 1` values, and optional weights (`rows·cols`, all > 0).
    ///
    /// # Errors
    /// In this order: the coordinate count, a non-finite coordinate, a degree of 0 or one that
    /// needs more rows or columns than given, the knot vectors (as [`KnotVector::new`], the
    /// message prefixed with `knotsU` or `knotsV`), then the weights.
    #[allow(clippy::too_many_arguments)]
    pub fn from_flat(
        coords: &[f64],
        rows: usize,
        cols: usize,
        degree_u: usize,
        degree_v: usize,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        weights: Option<&[f64]>,
    ) -> Result<Self> {
        let count = checked_count("rows·cols", rows, cols, MAX_SAMPLES)?;
        if coords.len() != 3 * count {
            return Err(Error::Surface(SurfaceError::NetCoordinateCount {
                rows,
                cols,
                got: coords.len(),
            }));
        }
        check_all_coordinates(coords, "coordinate")?;
        check_degree(degree_u, rows).map_err(|e| in_argument("degree-u-rows", e))?;
        check_degree(degree_v, cols).map_err(|e| in_argument("degree-v-columns", e))?;
        let knots_u =
            KnotVector::new(knots_u, degree_u, rows).map_err(|e| in_argument("knotsU", e))?;
        let knots_v =
            KnotVector::new(knots_v, degree_v, cols).map_err(|e| in_argument("knotsV", e))?;
        if let Some(w) = weights {
            check_weights(w, count)?;
        }
        let net = coords
            .chunks_exact(3)
            .enumerate()
            .map(|(k, c)| {
                let w = weights.and_then(|w| w.get(k)).copied().unwrap_or(1.0);
                DVec4::new(w * c[0], w * c[1], w * c[2], w)
            })
            .collect();
        Ok(BSplineSurface {
            net,
            rows,
            cols,
            rational: weights.is_some_and(|w| w.iter().any(|&wi| wi != 1.0)),
            knots_u,
            knots_v,
        })
    }

    /// The tensor-product Bézier patch `P(u, v) = Σ Σ B_i^m(u) B_j^n(v) P_ij` (rational with
    /// weights) of a `rows × cols` net: degrees `m = rows − 1`, `n = cols − 1`, on `[0, 1]²` —
    /// the B-spline surface with knots `0 … 0 1 … 1` (`rows` and `cols` of each).
    ///
    /// # Errors
    /// As [`BSplineSurface::from_flat`]; fewer than 2 rows or columns is a degree of 0.
    pub fn bezier(
        coords: &[f64],
        rows: usize,
        cols: usize,
        weights: Option<&[f64]>,
    ) -> Result<Self> {
        if rows.checked_mul(cols).and_then(|c| c.checked_mul(3)) == Some(coords.len())
            && (rows < 2 || cols < 2)
        {
            check_all_coordinates(coords, "coordinate")?;
            return Err(Error::Surface(SurfaceError::PatchTooSmall { rows, cols }));
        }
        // Bounded by the coordinate count, which from_flat checks first.
        let clamped = |count: usize| -> Vec<f64> {
            let count = count.min(coords.len() + 1);
            (0..2 * count)
                .map(|i| if i < count { 0.0 } else { 1.0 })
                .collect()
        };
        Self::from_flat(
            coords,
            rows,
            cols,
            rows.saturating_sub(1),
            cols.saturating_sub(1),
            clamped(rows),
            clamped(cols),
            weights,
        )
    }

    /// Number of rows of the net (control points along u), `n + 1`.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns of the net (control points along v), `m + 1`.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Degree `p` along u.
    pub fn degree_u(&self) -> usize {
        self.knots_u.degree()
    }

    /// Degree `q` along v.
    pub fn degree_v(&self) -> usize {
        self.knots_v.degree()
    }

    /// Whether some weight differs from 1.
    pub fn is_rational(&self) -> bool {
        self.rational
    }

    /// The knot vector along u.
    pub fn knots_u(&self) -> &KnotVector {
        &self.knots_u
    }

    /// The knot vector along v.
    pub fn knots_v(&self) -> &KnotVector {
        &self.knots_v
    }

    /// The control points, row-major.
    pub fn control_points(&self) -> Vec<DVec3> {
        self.net.iter().map(|h| h.truncate() / h.w).collect()
    }

    /// The weights, row-major (all 1 for a polynomial surface).
    pub fn weights(&self) -> Vec<f64> {
        self.net.iter().map(|h| h.w).collect()
    }

    /// The flat index of control point `(i, j)`, checked.
    fn index(&self, i: usize, j: usize) -> Result<usize> {
        if i >= self.rows || j >= self.cols {
            return Err(Error::Surface(SurfaceError::NetIndexOutOfRange {
                i,
                j,
                rows: self.rows,
                cols: self.cols,
            }));
        }
        Ok(i * self.cols + j)
    }

    /// Moves control point `(i, j)` to `p` in place, keeping its weight: the drag path.
    ///
    /// # Errors
    /// An index out of range, a coordinate that is not finite.
    pub fn set_control_point(&mut self, i: usize, j: usize, p: DVec3) -> Result<()> {
        let k = self.index(i, j)?;
        for (c, value) in p.to_array().into_iter().enumerate() {
            check_coordinate("new-point-coordinate", Some(c), value)?;
        }
        if let Some(h) = self.net.get_mut(k) {
            *h = (p * h.w).extend(h.w);
        }
        Ok(())
    }

    /// Sets the weight of control point `(i, j)` in place, keeping the point.
    ///
    /// # Errors
    /// An index out of range, [`Error::NotFinite`], [`Error::NonPositiveWeight`].
    pub fn set_weight(&mut self, i: usize, j: usize, w: f64) -> Result<()> {
        let k = self.index(i, j)?;
        check_finite("weight", Some(k), w)?;
        if w <= 0.0 {
            return Err(Error::NonPositiveWeight { index: k, value: w });
        }
        if let Some(h) = self.net.get_mut(k) {
            *h = (h.truncate() / h.w * w).extend(w);
        }
        self.rational = self.net.iter().any(|h| h.w != 1.0);
        Ok(())
    }
}
