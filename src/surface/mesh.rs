//! Triangle meshes for WebGL: uniform tessellation with normals.

use super::{checked_count, BSplineSurface, MAX_MESH_VERTICES};
use crate::bspline::basis_derivatives;
use crate::error::SurfaceError;
use crate::error::{Error, Result};
use crate::geom::{check_work, Params};
use glam::{DVec3, DVec4};

/// Most vertices of one mesh whose normal is taken from [`BSplineSurface::normal`]'s limits
/// (where `S_u × S_v` degenerates: a pole, a collapsed edge, derivatives that underflow). Each
/// costs a few surface evaluations; past this, such vertices take the mean of the adjacent
/// triangles' normals, as those where even the limit gives none. A work budget: a surface
/// degenerate everywhere (a huge parameter interval) would otherwise spend seconds here.
pub const MAX_LIMIT_NORMALS: usize = 1 << 14;

impl BSplineSurface {
    /// A triangle mesh of the whole surface: `(nu + 1)(nv + 1)` vertices at equally spaced
    /// parameters (`nu` × `nv` quads, like three.js' `ParametricGeometry`), vertex `a·(nv + 1) + b`
    /// at `(u_a, v_b)` (kept in [`Mesh::uvs`]), unit normals from [`BSplineSurface::normal`] (where
    /// even its limit gives none, or past [`MAX_LIMIT_NORMALS`] such vertices, the mean of the
    /// adjacent triangles' normals), and two triangles per quad, counter-clockwise seen from the
    /// side the normals point to.
    ///
    /// # Errors
    /// [`SurfaceError::EmptyTessellation`] for `nu` or `nv` of 0, [`Error::TooLarge`] above
    /// [`MAX_MESH_VERTICES`] vertices or the work budget [`crate::geom::MAX_SAMPLE_WORK`].
    pub fn tessellate(&self, nu: usize, nv: usize) -> Result<Mesh> {
        if nu == 0 || nv == 0 {
            return Err(Error::Surface(SurfaceError::EmptyTessellation { nu, nv }));
        }
        let (cu, cv) = (nu.saturating_add(1), nv.saturating_add(1));
        let vertices = checked_count("tessellation-vertices", cu, cv, MAX_MESH_VERTICES)?;
        let units = 2 * (self.degree_u() + 1) * (self.degree_v() + 1) + 128;
        check_work("tessellation-work", vertices, units)?;
        let grid = |(a, b): (f64, f64), n: usize| -> Vec<f64> {
            let params = Params::uniform(a, b, n + 1);
            (0..params.len()).map(|i| params.get(i)).collect()
        };
        let (us, vs) = (
            grid(self.knots_u.domain(), nu),
            grid(self.knots_v.domain(), nv),
        );
        let (points, mut normals, missing) = self.grid_with_normals(&us, &vs, MAX_LIMIT_NORMALS);
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
    /// degenerates, `normal` (with its limits) is asked instead, at most `max_limits` times.
    pub(super) fn grid_with_normals(
        &self,
        us: &[f64],
        vs: &[f64],
        max_limits: usize,
    ) -> (Vec<f64>, Vec<f64>, Vec<usize>) {
        let mut limits = 0;
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
                    limits += 1;
                    let limit = if limits <= max_limits {
                        self.normal(u, v).ok()
                    } else {
                        None
                    };
                    limit.unwrap_or_else(|| {
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

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn limit_normals_past_the_budget_come_from_the_triangles() {
        // A flat bilinear patch whose row u = 0 collapses to one point: S_v = 0 there, so each
        // of the 5 vertices of that row needs the limit; the normal is +z everywhere.
        let coords = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0];
        let s = BSplineSurface::bezier(&coords, 2, 2, None).unwrap();
        let grid = [0.0, 0.25, 0.5, 0.75, 1.0];
        let (_, normals, missing) = s.grid_with_normals(&grid, &grid, usize::MAX);
        assert!(missing.is_empty(), "every limit exists: {missing:?}");
        let (points, mut capped, missing) = s.grid_with_normals(&grid, &grid, 2);
        assert_eq!(
            missing,
            [2, 3, 4],
            "past 2 limits, the row's other vertices wait"
        );
        let mut indices = Vec::new();
        for a in 0..4u32 {
            for b in 0..4u32 {
                let v00 = a * 5 + b;
                indices.extend_from_slice(&[v00, v00 + 5, v00 + 6, v00, v00 + 6, v00 + 1]);
            }
        }
        fill_missing_normals(&points, &mut capped, &indices, &missing);
        // Vertex 4, the corner of the collapsed row, touches only degenerate triangles: the
        // fallback leaves it zero, so it is not compared.
        for (k, (n, c)) in normals
            .chunks(3)
            .zip(capped.chunks(3))
            .enumerate()
            .filter(|(k, _)| *k != 4)
        {
            let z = n[2].signum();
            assert!((n[2].abs() - 1.0).abs() < 1e-12, "vertex {k}: {n:?}");
            assert!((c[2] - z).abs() < 1e-12, "vertex {k}: {c:?} against {n:?}");
        }
    }
}
