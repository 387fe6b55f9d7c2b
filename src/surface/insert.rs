//! Knot insertion along u or v, and splitting a Bézier patch into four.

use super::BSplineSurface;
use crate::bezier::split_points;
use crate::bspline::{check_insertion, refine_points, KnotVector};
use crate::error::Result;
use glam::DVec4;

impl BSplineSurface {
    /// The same surface with u and v swapped (rows become columns): `S'(v, u) = S(u, v)`.
    fn transposed(&self) -> Self {
        let net = (0..self.cols)
            .flat_map(|j| (0..self.rows).map(move |i| (i, j)))
            .map(|(i, j)| {
                self.net
                    .get(i * self.cols + j)
                    .copied()
                    .unwrap_or(DVec4::ZERO)
            })
            .collect();
        BSplineSurface {
            net,
            rows: self.cols,
            cols: self.rows,
            rational: self.rational,
            knots_u: self.knots_v.clone(),
            knots_v: self.knots_u.clone(),
        }
    }

    /// Inserts `value` `times` times into the v knots: checked like a curve's insertion, then
    /// one refinement pass ([`BSplineSurface::refined_v`]) with `value` repeated `times` times.
    /// `name` is the parameter's name in errors.
    fn insert_along_v(&self, name: &'static str, value: f64, times: usize) -> Result<Self> {
        let v = self.knots_v.check_named(name, value)?;
        check_insertion(
            Some(name),
            v,
            self.knots_v.multiplicity(v),
            times,
            self.degree_v(),
        )?;
        self.refined_v(&vec![v; times])
    }

    /// The same surface with every value of `x` inserted into the v knots at once: A5.4
    /// ([`refine_points`]) on every row of the net, O(rows · (cols + m·q)) for m new knots.
    /// `x` must be sorted, inside the v domain and keep every multiplicity ≤ `q + 1`.
    pub(super) fn refined_v(&self, x: &[f64]) -> Result<Self> {
        if x.is_empty() {
            return Ok(self.clone());
        }
        let mut net = Vec::with_capacity(self.rows * (self.cols + x.len()));
        let mut knots = Vec::new();
        for row in self.net.chunks_exact(self.cols) {
            let (q, ubar) = refine_points(&self.knots_v, row, x);
            net.extend(q);
            knots = ubar;
        }
        let cols = self.cols + x.len();
        if !self.rational {
            // Keep polynomial weights exactly 1 ((1 − α)·1 + α·1 may round).
            for h in &mut net {
                h.w = 1.0;
            }
        }
        Ok(BSplineSurface {
            net,
            rows: self.rows,
            cols,
            rational: self.rational,
            knots_u: self.knots_u.clone(),
            knots_v: KnotVector::new(knots, self.degree_v(), cols)?,
        })
    }

    /// [`BSplineSurface::refined_v`] along u (on the transposed net).
    pub(super) fn refined_u(&self, x: &[f64]) -> Result<Self> {
        Ok(self.transposed().refined_v(x)?.transposed())
    }

    /// The same surface with the knot `u` inserted `times` times: a new row of control points
    /// per insertion (Boehm's algorithm on every column); the shape does not change.
    ///
    /// # Errors
    /// A bad `u`; [`crate::Error::InsertionMultiplicity`] when its multiplicity would exceed `p + 1`.
    pub fn insert_knot_u(&self, u: f64, times: usize) -> Result<Self> {
        Ok(self
            .transposed()
            .insert_along_v("u", u, times)?
            .transposed())
    }

    /// The same surface with the knot `v` inserted `times` times: a new column per insertion
    /// (Boehm's algorithm on every row).
    ///
    /// # Errors
    /// As [`BSplineSurface::insert_knot_u`].
    pub fn insert_knot_v(&self, v: f64, times: usize) -> Result<Self> {
        self.insert_along_v("v", v, times)
    }

    /// A Bézier patch (as made by [`BSplineSurface::bezier`]) split at `(u0, v0)` into four
    /// patches, each on `[0, 1]²`: `[u ≤ u0 & v ≤ v0, u ≤ u0 & v ≥ v0, u ≥ u0 & v ≤ v0,
    /// u ≥ u0 & v ≥ v0]`. De Casteljau at `v0` on every row, then at `u0` on every column of
    /// both halves (the syllabus' subdivision into four patches).
    ///
    /// # Errors
    /// A `u0` or `v0` outside `[0, 1]` or not finite.
    pub fn split_bezier(&self, u0: f64, v0: f64) -> Result<[Self; 4]> {
        let (u0, v0) = self.check_uv(u0, v0)?;
        let split_u = |surface: &Self| -> (Self, Self) {
            let (low, high) = surface.transposed().split_rows(u0);
            (low.transposed(), high.transposed())
        };
        let (low_v, high_v) = self.split_rows(v0);
        let ((a, c), (b, d)) = (split_u(&low_v), split_u(&high_v));
        Ok([a, b, c, d])
    }

    /// A Bézier patch split at `v0` (de Casteljau on every row): the nets of `v ≤ v0` and
    /// `v ≥ v0`, each on `[0, 1]` in v.
    fn split_rows(&self, v0: f64) -> (Self, Self) {
        let (mut low, mut high) = (
            Vec::with_capacity(self.net.len()),
            Vec::with_capacity(self.net.len()),
        );
        for row in self.net.chunks_exact(self.cols) {
            let (l, h) = split_points(row, v0);
            low.extend(l);
            high.extend(h);
        }
        (
            BSplineSurface {
                net: low,
                ..self.clone()
            },
            BSplineSurface {
                net: high,
                ..self.clone()
            },
        )
    }
}
