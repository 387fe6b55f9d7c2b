//! Triangle meshes for WebGL: uniform tessellation with normals.

use super::{checked_count, BSplineSurface, MAX_MESH_VERTICES};
use crate::bspline::basis_derivatives;
use crate::error::{Error, Result};
use crate::geom::Params;
use glam::{DVec3, DVec4};

impl BSplineSurface {
    /// A triangle mesh of the whole surface: `(nu + 1)(nv + 1)` vertices at equally spaced
    /// parameters (`nu` × `nv` quads, like three.js' `ParametricGeometry`), vertex `a·(nv + 1) + b`
    /// at `(u_a, v_b)` (kept in [`Mesh::uvs`]), unit normals from [`BSplineSurface::normal`] (where even its limit
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
        checked_count("tessellation-vertices", cu, cv, MAX_MESH_VERTICES)?;
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
        fill_missing_normals(&points, &mut normals, &indices, &missing);
        let mut uvs = Vec::with_capacity(2 * cu * cv);
        for &u in &us {
            for &v in &vs {
                uvs.extend_from_slice(&[u as f32, v as f32]);
            }
        }
        Ok(Mesh {
            positions: points.iter().map(|&x| x as f32).collect(),
            normals: normals.iter().map(|&x| x as f32).collect(),
            uvs,
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
}

/// Where even the limit gives no normal (vertices `missing`, normal left zero): the sum of the
/// adjacent triangles' (area-weighted) normals, normalised; one pass over the triangles.
pub(super) fn fill_missing_normals(
    points: &[f64],
    normals: &mut [f64],
    indices: &[u32],
    missing: &[usize],
) {
    if missing.is_empty() {
        return;
    }
    let vertex = |k: usize| {
        points
            .get(3 * k..3 * k + 3)
            .map_or(DVec3::ZERO, DVec3::from_slice)
    };
    let mut sums = vec![DVec3::ZERO; points.len() / 3];
    for t in indices.chunks_exact(3) {
        let [i, j, k] = [t[0] as usize, t[1] as usize, t[2] as usize];
        let face = (vertex(j) - vertex(i)).cross(vertex(k) - vertex(i));
        for m in [i, j, k] {
            if let Some(sum) = sums.get_mut(m) {
                *sum += face;
            }
        }
    }
    for &k in missing {
        if let (Some(n), Some(sum)) = (normals.get_mut(3 * k..3 * k + 3), sums.get(k)) {
            n.copy_from_slice(&sum.normalize_or_zero().to_array());
        }
    }
}

/// A triangle mesh ready for WebGL: see [`BSplineSurface::tessellate`].
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    /// Vertex positions, xyz.
    pub positions: Vec<f32>,
    /// Unit vertex normals, xyz.
    pub normals: Vec<f32>,
    /// The surface parameters `(u, v)` of each vertex (same order): position `k` is
    /// `S(uvs[2k], uvs[2k + 1])`.
    pub uvs: Vec<f32>,
    /// Three vertex indices per triangle.
    pub indices: Vec<u32>,
}
