//! Tensor-product Bézier, B-spline and NURBS surfaces (syllabus §6):
//!
//! `S(u, v) = Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) w_ij P_ij / Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) w_ij`
//!
//! over the control net `P_ij` (`i = 0..rows−1` along u, `j = 0..cols−1` along v) with knot
//! vectors `U` (degree `p`) and `V` (degree `q`), evaluated on homogeneous points
//! `(w P, w)` with one division at the end, on the domain `[u_p, u_rows] × [v_q, v_cols]`.
//! Points are 3D and stored row-major: point `(i, j)` is number `i·cols + j`. A Bézier patch
//! `ΣΣ B_i^m(u) B_j^n(v) P_ij` is the case of one span, knots `0 … 0 1 … 1`
//! ([`BSplineSurface::bezier`]).

use crate::bezier::split_points;
use crate::bspline::{basis_derivatives, basis_functions, boehm_insert, BasisScratch};
use crate::bspline::{check_degree, check_insertion, KnotVector};
use crate::error::{check_finite, Error, Result};
use crate::geom::{check_all_finite, check_weights, Params, MAX_DERIVATIVE_ORDER, MAX_SAMPLES};
use glam::{DVec3, DVec4};

/// Most vertices one [`BSplineSurface::tessellate`] call makes (about 2048 × 2048): with the
/// triangles, ~50 bytes each in the result.
pub const MAX_MESH_VERTICES: usize = 1 << 22;

/// A polynomial or rational (NURBS) tensor-product B-spline surface in 3D.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineSurface {
    /// Homogeneous control net `(w·x, w·y, w·z, w)`, row-major.
    net: Vec<DVec4>,
    rows: usize,
    cols: usize,
    rational: bool,
    knots_u: KnotVector,
    knots_v: KnotVector,
}

/// An error about the argument `name`, keeping its cause (the message says `name: cause`).
fn in_argument(name: &'static str, err: Error) -> Error {
    Error::InArgument {
        name,
        index: None,
        source: Box::new(err),
    }
}

/// An error about element `index` of the list argument `name` (the message says
/// `name[index]: cause`).
fn in_element(name: &'static str, index: usize, err: Error) -> Error {
    Error::InArgument {
        name,
        index: Some(index),
        source: Box::new(err),
    }
}

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
            return Err(Error::NetCoordinateCount {
                rows,
                cols,
                got: coords.len(),
            });
        }
        check_all_finite(coords, "coordinate")?;
        check_degree(degree_u, rows).map_err(|e| in_argument("degreeU (rows along u)", e))?;
        check_degree(degree_v, cols).map_err(|e| in_argument("degreeV (columns along v)", e))?;
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
            check_all_finite(coords, "coordinate")?;
            return Err(Error::PatchTooSmall { rows, cols });
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
            return Err(Error::NetIndexOutOfRange {
                i,
                j,
                rows: self.rows,
                cols: self.cols,
            });
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
            check_finite(|| format!("coordinate {c} of the new point"), value)?;
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
        check_finite(|| format!("weight ({i}, {j})"), w)?;
        if w <= 0.0 {
            return Err(Error::NonPositiveWeight { index: k, value: w });
        }
        if let Some(h) = self.net.get_mut(k) {
            *h = (h.truncate() / h.w * w).extend(w);
        }
        self.rational = self.net.iter().any(|h| h.w != 1.0);
        Ok(())
    }

    /// `(u, v)` checked against the domain; the error names `u` or `v` and the range.
    fn check_uv(&self, u: f64, v: f64) -> Result<(f64, f64)> {
        Ok((
            self.knots_u.check_named("u", u)?,
            self.knots_v.check_named("v", v)?,
        ))
    }

    /// The homogeneous point `Σ Σ N_{i,p}(u) N_{j,q}(v) (w P)_ij` from the non-zero basis
    /// functions of the spans of `u` and `v` only: `(p + 1)(q + 1)` terms.
    fn homogeneous_at(&self, u: f64, v: f64) -> DVec4 {
        let (p, q) = (self.degree_u(), self.degree_v());
        let (ku, kv) = (self.knots_u.span(u), self.knots_v.span(v));
        let mut scratch = BasisScratch::default();
        let (mut nu, mut nv) = (vec![0.0; p + 1], vec![0.0; q + 1]);
        basis(&self.knots_u, ku, u, &mut nu, &mut scratch);
        basis(&self.knots_v, kv, v, &mut nv, &mut scratch);
        let mut sum = DVec4::ZERO;
        for (a, &na) in nu.iter().enumerate() {
            let row = (ku - p + a) * self.cols + kv - q;
            let Some(points) = self.net.get(row..row + q + 1) else {
                continue;
            };
            sum += na
                * points
                    .iter()
                    .zip(&nv)
                    .fold(DVec4::ZERO, |acc, (&h, &nb)| acc + nb * h);
        }
        sum
    }

    /// The point `S(u, v)`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for `u` or `v`.
    pub fn evaluate(&self, u: f64, v: f64) -> Result<DVec3> {
        let (u, v) = self.check_uv(u, v)?;
        let h = self.homogeneous_at(u, v);
        Ok(h.truncate() / h.w)
    }

    /// All partial derivatives `∂^{k+l} S / ∂u^k ∂v^l` with `k + l ≤ order`, as `skl[k][l]`:
    /// NURBS Book A3.6 on the homogeneous net (derivatives of the `p + 1` and `q + 1`
    /// non-zero basis functions, A2.3), then A4.4 for the quotient:
    /// `S_kl = (A_kl − Σ_{j=1..l} C(l,j) w_0j S_{k,l−j} − Σ_{i=1..k} C(k,i) w_i0 S_{k−i,l}
    ///          − Σ_{i=1..k} C(k,i) Σ_{j=1..l} C(l,j) w_ij S_{k−i,l−j}) / w`.
    fn derivatives(&self, u: f64, v: f64, order: usize) -> Vec<Vec<DVec3>> {
        let (p, q) = (self.degree_u(), self.degree_v());
        let (ku, kv) = (self.knots_u.span(u), self.knots_v.span(v));
        let nu = basis_derivatives(self.knots_u.as_slice(), ku, u, p, order.min(p));
        let nv = basis_derivatives(self.knots_v.as_slice(), kv, v, q, order.min(q));
        // Homogeneous derivatives A_kl (and w_kl in .w); zero beyond the degrees.
        let mut h = vec![vec![DVec4::ZERO; order + 1]; order + 1];
        let mut temp = vec![DVec4::ZERO; q + 1];
        for (k, nuk) in nu.iter().enumerate() {
            for (s, t) in temp.iter_mut().enumerate() {
                *t = nuk.iter().enumerate().fold(DVec4::ZERO, |acc, (r, &n)| {
                    acc + n * self
                        .net
                        .get((ku - p + r) * self.cols + kv - q + s)
                        .copied()
                        .unwrap_or(DVec4::ZERO)
                });
            }
            for (l, nvl) in nv.iter().enumerate().take(order + 1 - k) {
                h[k][l] = nvl
                    .iter()
                    .zip(&temp)
                    .fold(DVec4::ZERO, |acc, (&n, &t)| acc + n * t);
            }
        }
        if !self.rational {
            // w ≡ 1: the homogeneous derivatives are the derivatives (exactly zero above the
            // degrees, where the quotient rule would leave rounding noise).
            return h
                .iter()
                .map(|row| row.iter().map(|a| a.truncate()).collect())
                .collect();
        }
        let binomial = |n: usize, r: usize| -> f64 {
            (1..=r).fold(1.0, |acc, i| acc * (n + 1 - i) as f64 / i as f64)
        };
        let w0 = h[0][0].w;
        let mut s = vec![vec![DVec3::ZERO; order + 1]; order + 1];
        for k in 0..=order {
            for l in 0..=order - k {
                let mut value = h[k][l].truncate();
                for j in 1..=l {
                    value -= binomial(l, j) * h[0][j].w * s[k][l - j];
                }
                for i in 1..=k {
                    value -= binomial(k, i) * h[i][0].w * s[k - i][l];
                    let mut inner = DVec3::ZERO;
                    for j in 1..=l {
                        inner += binomial(l, j) * h[i][j].w * s[k - i][l - j];
                    }
                    value -= binomial(k, i) * inner;
                }
                s[k][l] = value / w0;
            }
        }
        s
    }

    /// The partial derivative `∂^{du+dv} S / ∂u^du ∂v^dv` at `(u, v)` (`S` itself for 0, 0).
    /// Orders above the degree give the zero vector on a polynomial surface.
    ///
    /// # Errors
    /// A bad `u` or `v`, and [`Error::TooLarge`] for `du + dv` above
    /// [`MAX_DERIVATIVE_ORDER`].
    pub fn derivative(&self, u: f64, v: f64, du: usize, dv: usize) -> Result<DVec3> {
        let (u, v) = self.check_uv(u, v)?;
        let order = du.saturating_add(dv);
        if order > MAX_DERIVATIVE_ORDER {
            return Err(Error::TooLarge {
                what: "derivative order du + dv",
                value: order,
                max: MAX_DERIVATIVE_ORDER,
            });
        }
        let s = self.derivatives(u, v, order);
        Ok(s.get(du)
            .and_then(|row| row.get(dv))
            .copied()
            .unwrap_or(DVec3::ZERO))
    }

    /// The unit normal `(S_u × S_v) / |S_u × S_v|` at `(u, v)`.
    ///
    /// Where one partial derivative vanishes — an edge collapsed to a point (a pole, the apex
    /// of a cone) or a degenerate corner — the normal is the limit from inside the domain: if
    /// `S_v = 0` along the line `u = const`, then `S_v(u + ε, v) ≈ ε S_uv` and the normal is
    /// `±S_u × S_uv` (the sign of `ε` that stays in the domain); likewise `±S_uv × S_v` where
    /// `S_u = 0`.
    ///
    /// # Errors
    /// A bad `u` or `v`, and [`Error::NoNormal`] where even the limit gives no direction: both
    /// partial derivatives vanish, or they are parallel (a fold).
    pub fn normal(&self, u: f64, v: f64) -> Result<DVec3> {
        let (u, v) = self.check_uv(u, v)?;
        let s = self.derivatives(u, v, 2);
        let (su, sv, suv) = (s[1][0], s[0][1], s[1][1]);
        // "Vanishes": rounding of a sum of equal points, far below the other derivative.
        let tiny = 1e-10 * su.length().max(sv.length());
        let inward = |at_end: bool| if at_end { -1.0 } else { 1.0 };
        let (a, b) = if sv.length() <= tiny {
            (inward(u >= self.knots_u.domain().1) * su, suv)
        } else if su.length() <= tiny {
            (inward(v >= self.knots_v.domain().1) * suv, sv)
        } else {
            (su, sv)
        };
        let cross = a.cross(b);
        if cross.length() <= 1e-12 * a.length() * b.length() {
            return Err(Error::NoNormal { u, v });
        }
        Ok(cross / cross.length())
    }

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

    /// Inserts `value` `times` times into the v knots: Boehm's algorithm on every row of the
    /// net (each row is a B-spline curve in v). `name` is the parameter's name in errors.
    fn insert_along_v(&self, name: &'static str, value: f64, times: usize) -> Result<Self> {
        let v = self.knots_v.check_named(name, value)?;
        let q = self.degree_v();
        check_insertion(Some(name), v, self.knots_v.multiplicity(v), times, q)?;
        let mut rows: Vec<Vec<DVec4>> = self
            .net
            .chunks_exact(self.cols)
            .map(<[DVec4]>::to_vec)
            .collect();
        let mut knots = self.knots_v.clone();
        for _ in 0..times {
            let k = knots.span(v);
            for row in &mut rows {
                *row = boehm_insert(row, knots.as_slice(), q, k, v);
            }
            let cols = rows.first().map_or(0, Vec::len);
            knots = KnotVector::new(knots.with_inserted(v, 1), q, cols)?;
        }
        let cols = knots.point_count();
        let mut net: Vec<DVec4> = rows.concat();
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
            knots_v: knots,
        })
    }

    /// The same surface with the knot `u` inserted `times` times: a new row of control points
    /// per insertion (Boehm's algorithm on every column); the shape does not change.
    ///
    /// # Errors
    /// A bad `u`; [`Error::InsertionMultiplicity`] when its multiplicity would exceed `p + 1`.
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

    /// A triangle mesh of the whole surface: `(nu + 1)(nv + 1)` vertices at equally spaced
    /// parameters (`nu` × `nv` quads, like three.js' `ParametricGeometry`), vertex `a·(nv + 1) + b`
    /// at `(u_a, v_b)`, unit normals from [`BSplineSurface::normal`] (where even its limit
    /// gives none, the mean of the adjacent triangles' normals), and two triangles per quad,
    /// counter-clockwise seen from the side the normals point to.
    ///
    /// # Errors
    /// [`Error::EmptyTessellation`] for `nu` or `nv` of 0, [`Error::TooLarge`] above
    /// [`MAX_MESH_VERTICES`] vertices.
    pub fn tessellate(&self, nu: usize, nv: usize) -> Result<Mesh> {
        if nu == 0 || nv == 0 {
            return Err(Error::EmptyTessellation { nu, nv });
        }
        let (cu, cv) = (nu.saturating_add(1), nv.saturating_add(1));
        checked_count(
            "tessellation vertices (nu + 1)(nv + 1)",
            cu,
            cv,
            MAX_MESH_VERTICES,
        )?;
        let grid = |(a, b): (f64, f64), n: usize| -> Vec<f64> {
            let params = Params::uniform(a, b, n + 1);
            (0..params.len()).map(|i| params.get(i)).collect()
        };
        let (us, vs) = (
            grid(self.knots_u.domain(), nu),
            grid(self.knots_v.domain(), nv),
        );
        let (points, mut normals, missing) = self.grid_with_normals(&us, &vs);
        let mut indices = Vec::with_capacity(6 * nu * nv);
        for a in 0..nu {
            for b in 0..nv {
                let v00 = (a * cv + b) as u32;
                let v10 = v00 + cv as u32;
                indices.extend_from_slice(&[v00, v10, v10 + 1, v00, v10 + 1, v00 + 1]);
            }
        }
        if !missing.is_empty() {
            // Where even the limit gives no normal: the sum of the adjacent triangles'
            // (area-weighted) normals, one pass over the triangles.
            let vertex = |k: usize| {
                points
                    .get(3 * k..3 * k + 3)
                    .map_or(DVec3::ZERO, DVec3::from_slice)
            };
            let mut sums = vec![DVec3::ZERO; cu * cv];
            for t in indices.chunks_exact(3) {
                let [i, j, k] = [t[0] as usize, t[1] as usize, t[2] as usize];
                let face = (vertex(j) - vertex(i)).cross(vertex(k) - vertex(i));
                for m in [i, j, k] {
                    if let Some(sum) = sums.get_mut(m) {
                        *sum += face;
                    }
                }
            }
            for k in missing {
                if let (Some(n), Some(sum)) = (normals.get_mut(3 * k..3 * k + 3), sums.get(k)) {
                    n.copy_from_slice(&sum.normalize_or_zero().to_array());
                }
            }
        }
        Ok(Mesh {
            positions: points.iter().map(|&x| x as f32).collect(),
            normals: normals.iter().map(|&x| x as f32).collect(),
            indices,
        })
    }

    /// Points and unit normals on the grid `us × vs` (parameters in the domain), u-major, flat,
    /// and the vertices where even [`BSplineSurface::normal`]'s limit gives no normal (their
    /// normal is left zero). As [`BSplineSurface::sample_grid_into`], with the first
    /// derivatives of the basis tabulated too: each u collapses the rows into the homogeneous
    /// curves `A(u, ·)` and `A_u(u, ·)`, and each v gives `A`, `A_u`, `A_v` with `q + 1` terms;
    /// then `S = A/w`, `S_u = (A_u − w_u S)/w`, `S_v = (A_v − w_v S)/w`. Where `S_u × S_v`
    /// degenerates, `normal` (with its limits) is asked instead.
    fn grid_with_normals(&self, us: &[f64], vs: &[f64]) -> (Vec<f64>, Vec<f64>, Vec<usize>) {
        let (p, q) = (self.degree_u(), self.degree_v());
        // The v basis and its derivative, once per v: the first column, then the q + 1 values
        // and the q + 1 derivatives.
        let (mut first, mut values, mut slopes) =
            (Vec::with_capacity(vs.len()), Vec::new(), Vec::new());
        let mut k = q;
        for &v in vs {
            k = self.knots_v.span_from(v, k);
            let d = basis_derivatives(self.knots_v.as_slice(), k, v, q, 1);
            first.push(k - q);
            values.extend_from_slice(d.first().map_or(&[][..], |r| &r[..]));
            slopes.extend_from_slice(d.get(1).map_or(&[][..], |r| &r[..]));
        }
        let len = 3 * us.len() * vs.len();
        let (mut points, mut normals) = (Vec::with_capacity(len), Vec::with_capacity(len));
        let mut missing = Vec::new();
        let (mut row, mut row_u) = (vec![DVec4::ZERO; self.cols], vec![DVec4::ZERO; self.cols]);
        let mut ku = p;
        for &u in us {
            ku = self.knots_u.span_from(u, ku);
            let d = basis_derivatives(self.knots_u.as_slice(), ku, u, p, 1);
            let (nu, dnu) = (
                d.first().map_or(&[][..], |r| &r[..]),
                d.get(1).map_or(&[][..], |r| &r[..]),
            );
            self.collapse_rows(ku, nu, &mut row);
            self.collapse_rows(ku, dnu, &mut row_u);
            for (((&v, &j0), nv), dnv) in vs
                .iter()
                .zip(&first)
                .zip(values.chunks_exact(q + 1))
                .zip(slopes.chunks_exact(q + 1))
            {
                let (Some(c), Some(cu)) = (row.get(j0..j0 + q + 1), row_u.get(j0..j0 + q + 1))
                else {
                    continue;
                };
                let (mut a, mut a_u, mut a_v) = (DVec4::ZERO, DVec4::ZERO, DVec4::ZERO);
                for b in 0..c.len().min(cu.len()).min(nv.len()).min(dnv.len()) {
                    a += nv[b] * c[b];
                    a_u += nv[b] * cu[b];
                    a_v += dnv[b] * c[b];
                }
                let inv_w = 1.0 / a.w;
                let point = a.truncate() * inv_w;
                let su = (a_u.truncate() - a_u.w * point) * inv_w;
                let sv = (a_v.truncate() - a_v.w * point) * inv_w;
                let cross = su.cross(sv);
                // normal()'s tests, squared: neither derivative vanishes (relative 1e-10), and
                // they are not parallel (relative 1e-12).
                let (lu, lv, lc) = (
                    su.length_squared(),
                    sv.length_squared(),
                    cross.length_squared(),
                );
                let tiny = 1e-20 * lu.max(lv);
                let normal = if lu > tiny && lv > tiny && lc > 1e-24 * lu * lv {
                    cross * (1.0 / lc.sqrt())
                } else {
                    self.normal(u, v).unwrap_or_else(|_| {
                        missing.push(points.len() / 3);
                        DVec3::ZERO
                    })
                };
                points.extend(point.to_array());
                normals.extend(normal.to_array());
            }
        }
        (points, normals, missing)
    }

    /// The u direction collapsed at one u of span `ku`: `row[j] = Σ_a weights[a] (wP)_{ku−p+a, j}`
    /// over the `p + 1` rows of the span (with the basis values `N_{ku−p+a,p}(u)`, the
    /// homogeneous curve `A(u, ·)`; with their derivatives, `A_u(u, ·)`).
    fn collapse_rows(&self, ku: usize, weights: &[f64], row: &mut [DVec4]) {
        row.fill(DVec4::ZERO);
        let first = ku - self.degree_u();
        for (net_row, &n) in self.net.chunks_exact(self.cols).skip(first).zip(weights) {
            for (r, &h) in row.iter_mut().zip(net_row) {
                *r += n * h;
            }
        }
    }

    /// `S(u_a, v_b)` for every `u_a` of `us` and `v_b` of `vs`, u-major (point `a·len(vs) + b`,
    /// 3 numbers each), into `out` (resized).
    ///
    /// The basis along v is computed once per `v_b`; each `u_a` then collapses the u
    /// direction into one homogeneous curve of `cols` points (`p + 1` rows blended), which is
    /// evaluated at every `v_b` with `q + 1` terms: per point `4(q + 1)` multiply-adds and one
    /// division. The same sums as [`BSplineSurface::evaluate`], grouped differently.
    ///
    /// # Errors
    /// A bad value in `us` or `vs` (named by index), and [`Error::TooLarge`] for more than
    /// [`MAX_SAMPLES`] points.
    pub fn sample_grid_into(&self, us: &[f64], vs: &[f64], out: &mut Vec<f64>) -> Result<()> {
        let points = checked_count(
            "grid points us.length·vs.length",
            us.len(),
            vs.len(),
            MAX_SAMPLES,
        )?;
        for (i, &u) in us.iter().enumerate() {
            self.knots_u
                .check_named("u", u)
                .map_err(|e| in_element("us", i, e))?;
        }
        for (j, &v) in vs.iter().enumerate() {
            self.knots_v
                .check_named("v", v)
                .map_err(|e| in_element("vs", j, e))?;
        }
        out.clear();
        out.resize(3 * points, 0.0);
        let (p, q) = (self.degree_u(), self.degree_v());
        let mut scratch = BasisScratch::default();
        // The v basis, once: the first column of each span and its q + 1 values.
        let mut first = Vec::with_capacity(vs.len());
        let mut table = vec![0.0; vs.len() * (q + 1)];
        let mut k = q;
        for (&v, values) in vs.iter().zip(table.chunks_exact_mut(q + 1)) {
            k = self.knots_v.span_from(v, k);
            basis(&self.knots_v, k, v, values, &mut scratch);
            first.push(k - q);
        }
        let mut nu = vec![0.0; p + 1];
        let mut row = vec![DVec4::ZERO; self.cols];
        let mut ku = p;
        for (&u, out_row) in us.iter().zip(out.chunks_exact_mut(3 * vs.len().max(1))) {
            ku = self.knots_u.span_from(u, ku);
            basis(&self.knots_u, ku, u, &mut nu, &mut scratch);
            self.collapse_rows(ku, &nu, &mut row);
            // Degrees 1–5 get a kernel whose inner loop the compiler unrolls.
            match q + 1 {
                2 => grid_row::<2>(&row, &first, &table, out_row),
                3 => grid_row::<3>(&row, &first, &table, out_row),
                4 => grid_row::<4>(&row, &first, &table, out_row),
                5 => grid_row::<5>(&row, &first, &table, out_row),
                6 => grid_row::<6>(&row, &first, &table, out_row),
                _ => grid_row_any(q + 1, &row, &first, &table, out_row),
            }
        }
        Ok(())
    }
}

/// `a · b`, the size of a net, grid or mesh, checked against `max` (`what` names it).
fn checked_count(what: &'static str, a: usize, b: usize, max: usize) -> Result<usize> {
    a.checked_mul(b)
        .filter(|&n| n <= max)
        .ok_or(Error::TooLarge {
            what,
            value: a.saturating_mul(b),
            max,
        })
}

/// The `p + 1` basis functions of `knots` that can be non-zero at `t` in span `k`, into `out`.
fn basis(knots: &KnotVector, k: usize, t: f64, out: &mut [f64], scratch: &mut BasisScratch) {
    basis_functions(knots.as_slice(), k, t, knots.degree(), out, scratch, None);
}

/// A triangle mesh ready for WebGL: see [`BSplineSurface::tessellate`].
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Vertex positions, xyz.
    pub positions: Vec<f32>,
    /// Unit vertex normals, xyz.
    pub normals: Vec<f32>,
    /// Three vertex indices per triangle.
    pub indices: Vec<u32>,
}

/// One row of a grid: the homogeneous curve `row` (the u direction collapsed) at every v, from
/// the first column `first[b]` of each v's span and its `Q1 = q + 1` basis values in `table`,
/// projected into `out` (3 numbers per v).
#[inline]
fn grid_row<const Q1: usize>(row: &[DVec4], first: &[usize], table: &[f64], out: &mut [f64]) {
    for ((&j0, values), xyz) in first
        .iter()
        .zip(table.chunks_exact(Q1))
        .zip(out.chunks_exact_mut(3))
    {
        let (Some(points), Ok(values)) = (row.get(j0..j0 + Q1), <&[f64; Q1]>::try_from(values))
        else {
            continue;
        };
        let mut h = DVec4::ZERO;
        for b in 0..Q1 {
            h += values[b] * points[b];
        }
        let inv = 1.0 / h.w;
        xyz.copy_from_slice(&[h.x * inv, h.y * inv, h.z * inv]);
    }
}

/// [`grid_row`] for any `q + 1`.
fn grid_row_any(q1: usize, row: &[DVec4], first: &[usize], table: &[f64], out: &mut [f64]) {
    for ((&j0, values), xyz) in first
        .iter()
        .zip(table.chunks_exact(q1))
        .zip(out.chunks_exact_mut(3))
    {
        let h = row
            .get(j0..j0 + q1)
            .unwrap_or(&[])
            .iter()
            .zip(values)
            .fold(DVec4::ZERO, |acc, (&c, &n)| acc + n * c);
        let inv = 1.0 / h.w;
        xyz.copy_from_slice(&[h.x * inv, h.y * inv, h.z * inv]);
    }
}
