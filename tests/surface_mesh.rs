//! Meshes, Bézier extraction, seams and line intersection of surfaces, against independent
//! expectations: a mesh's uvs evaluate to its positions; the adaptive mesh is within its
//! tolerance at every triangle's centroid and edge midpoints (through the uvs), crack-free
//! (every edge shared by two triangles or on the domain boundary, found from the uvs), and a
//! plane gets two triangles per Bézier patch; Bézier patches reproduce the parent at mapped
//! parameters; seams measure `c ≥ p − r` and see a C² net across a double knot; lines hit
//! known points, miss, hit a plane once and a saddle twice. Runs natively and in Node.

mod common;

use common::*;
use splinelab::surface::Mesh;
use splinelab::{BSplineSurface, DVec3};
use std::collections::HashMap;
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// Flat row-major coordinates of `f(i, j)` on a rows × cols net.
fn net(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> DVec3) -> Vec<f64> {
    let mut out = Vec::new();
    for i in 0..rows {
        for j in 0..cols {
            out.extend(f(i, j).to_array());
        }
    }
    out
}

/// Greville abscissae `(u_{i+1} + … + u_{i+p})/p` of a knot vector.
fn greville(knots: &[f64], p: usize) -> Vec<f64> {
    (0..knots.len() - p - 1)
        .map(|i| knots[i + 1..=i + p].iter().sum::<f64>() / p as f64)
        .collect()
}

const KU: [f64; 10] = [0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 2.0, 2.0, 2.0, 2.0];
const KV: [f64; 8] = [1.0, 1.0, 1.0, 1.5, 2.2, 3.0, 3.0, 3.0];

/// A curved bicubic × biquadratic B-spline surface (6 × 5 net, 3 × 3 spans): a wavy sheet,
/// rational when `weighted`.
fn wavy(weighted: bool) -> BSplineSurface {
    let (gu, gv) = (greville(&KU, 3), greville(&KV, 2));
    let mut rng = Rng::new(11);
    let coords = net(6, 5, |i, j| {
        DVec3::new(
            gu[i],
            gv[j],
            (2.0 * gu[i]).sin() * gv[j].cos() + rng.range(-0.2, 0.2),
        )
    });
    let weights: Vec<f64> = (0..30).map(|_| rng.range(0.6, 1.8)).collect();
    BSplineSurface::from_flat(
        &coords,
        6,
        5,
        3,
        2,
        KU.to_vec(),
        KV.to_vec(),
        weighted.then_some(&weights[..]),
    )
    .unwrap()
}

/// `(u, v)` of vertex `k` and its position, as f64.
fn vertex(mesh: &Mesh, k: usize) -> ((f64, f64), DVec3) {
    (
        (mesh.uvs[2 * k] as f64, mesh.uvs[2 * k + 1] as f64),
        DVec3::new(
            mesh.positions[3 * k] as f64,
            mesh.positions[3 * k + 1] as f64,
            mesh.positions[3 * k + 2] as f64,
        ),
    )
}

/// Every vertex's position is `S(uv)` (to f32 rounding), and the arrays have matching lengths.
fn assert_uvs_are_positions(s: &BSplineSurface, mesh: &Mesh, what: &str) {
    let n = mesh.positions.len() / 3;
    assert_eq!(mesh.uvs.len(), 2 * n, "{what}: uvs length");
    assert_eq!(mesh.normals.len(), 3 * n, "{what}: normals length");
    for k in 0..n {
        let ((u, v), p) = vertex(mesh, k);
        // The f32 uv moves the point by up to |S_u|·|Δu| ≈ 3·1e-7.
        assert_close3(
            s.evaluate(u, v).unwrap(),
            p,
            2e-6,
            &format!("{what}: vertex {k}"),
        );
    }
}

#[test]
fn uvs_are_the_parameters_of_the_positions() {
    for weighted in [false, true] {
        let s = wavy(weighted);
        let mesh = s.tessellate(7, 5).unwrap();
        assert_eq!(mesh.uvs.len(), 2 * 8 * 6);
        // Vertex a·(nv + 1) + b at the equally spaced (u_a, v_b).
        assert_close(
            mesh.uvs[2 * 13] as f64,
            2.0 / 7.0 * 2.0,
            1e-7,
            "u of vertex 13",
        );
        assert_close(mesh.uvs[2 * 13 + 1] as f64, 1.4, 1e-7, "v of vertex 13");
        assert_uvs_are_positions(&s, &mesh, "uniform");
        assert_uvs_are_positions(&s, &s.tessellate_adaptive(0.01).unwrap(), "adaptive");
    }
}

/// The checks of an adaptive mesh: within `tolerance` at centroids and edge midpoints,
/// crack-free, counter-clockwise seen from the normals.
fn assert_adaptive_mesh(s: &BSplineSurface, tolerance: f64, what: &str) -> Mesh {
    let mesh = s.tessellate_adaptive(tolerance).unwrap();
    assert_uvs_are_positions(s, &mesh, what);
    let size = 4.0; // the coordinates are below 4: f32 rounding of positions ~ 4·6e-8
    let slack = 2e-6 * size;
    let mut edges: HashMap<[u64; 4], usize> = HashMap::new();
    for t in mesh.indices.chunks_exact(3) {
        let vs: Vec<_> = t.iter().map(|&k| vertex(&mesh, k as usize)).collect();
        // Centroid and edge midpoints: the interpolated uv's surface point against the
        // triangle's point with the same barycentric weights.
        let third = 1.0 / 3.0;
        for w in [
            [third, third, third],
            [0.5, 0.5, 0.0],
            [0.0, 0.5, 0.5],
            [0.5, 0.0, 0.5],
        ] {
            let uv = (0..3).fold((0.0, 0.0), |acc, k| {
                (acc.0 + w[k] * vs[k].0 .0, acc.1 + w[k] * vs[k].0 .1)
            });
            let on_triangle = (0..3).fold(DVec3::ZERO, |acc, k| acc + w[k] * vs[k].1);
            let d = (s.evaluate(uv.0, uv.1).unwrap() - on_triangle).length();
            assert!(
                d <= tolerance + slack,
                "{what}: {d} > {tolerance} at {uv:?}"
            );
        }
        // Counter-clockwise in (u, v), the side S_u × S_v points to.
        let (a, b, c) = (vs[0].0, vs[1].0, vs[2].0);
        let area = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        assert!(
            area > 0.0,
            "{what}: triangle {t:?} is not counter-clockwise in (u, v)"
        );
        for (k, l) in [(0, 1), (1, 2), (2, 0)] {
            let key =
                |x: (f64, f64)| [(x.0 as f32).to_bits() as u64, (x.1 as f32).to_bits() as u64];
            let (p, q) = (key(vs[k].0), key(vs[l].0));
            let edge = if p < q {
                [p[0], p[1], q[0], q[1]]
            } else {
                [q[0], q[1], p[0], p[1]]
            };
            *edges.entry(edge).or_default() += 1;
        }
    }
    // Crack-free: an edge used once lies on the domain boundary (both ends on one side).
    let ((ua, ub), (va, vb)) = (s.knots_u().domain(), s.knots_v().domain());
    for (edge, count) in &edges {
        let uv = |i: usize| {
            (
                f32::from_bits(edge[i] as u32) as f64,
                f32::from_bits(edge[i + 1] as u32) as f64,
            )
        };
        let (p, q) = (uv(0), uv(2));
        let on_side = (p.0 == ua && q.0 == ua)
            || (p.0 == ub && q.0 == ub)
            || (p.1 == va && q.1 == va)
            || (p.1 == vb && q.1 == vb);
        match count {
            2 => {}
            1 => assert!(
                on_side,
                "{what}: edge {p:?}–{q:?} has one triangle inside the domain (a crack)"
            ),
            n => panic!("{what}: edge {p:?}–{q:?} shared by {n} triangles"),
        }
    }
    mesh
}

#[test]
fn the_adaptive_mesh_is_within_tolerance_and_crack_free() {
    for weighted in [false, true] {
        let s = wavy(weighted);
        let mut last = 0;
        for tolerance in [0.05, 0.01, 0.002] {
            let what = format!("weighted {weighted}, tolerance {tolerance}");
            let mesh = assert_adaptive_mesh(&s, tolerance, &what);
            let triangles = mesh.indices.len() / 3;
            assert!(
                triangles > last,
                "{what}: {triangles} triangles, not more than {last}"
            );
            last = triangles;
        }
    }
    // A patch flat on one side and curved on the other gets leaves of different depths
    // (T-junctions to include).
    let coords = net(4, 4, |i, j| {
        let z = if i == 3 {
            1.5 * (j as f64 - 1.5).abs()
        } else {
            0.0
        };
        DVec3::new(i as f64, j as f64, z)
    });
    let s = BSplineSurface::bezier(&coords, 4, 4, None).unwrap();
    let mesh = assert_adaptive_mesh(&s, 0.01, "one curved edge");
    let areas: Vec<f64> = mesh
        .indices
        .chunks_exact(3)
        .map(|t| {
            let [a, b, c] = [0, 1, 2].map(|k| vertex(&mesh, t[k] as usize).0);
            (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
        })
        .collect();
    let (min, max) = areas.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &a| {
        (lo.min(a), hi.max(a))
    });
    assert!(max >= 16.0 * min, "leaves of one size only: {min} … {max}");
}

#[test]
fn a_plane_gets_two_triangles_per_bezier_patch() {
    // An affine net on the Greville abscissae: S(u, v) = (u, v, 2u − 3v + 1), 3 × 3 patches.
    let (gu, gv) = (greville(&KU, 3), greville(&KV, 2));
    let coords = net(6, 5, |i, j| {
        DVec3::new(gu[i], gv[j], 2.0 * gu[i] - 3.0 * gv[j] + 1.0)
    });
    let s = BSplineSurface::from_flat(&coords, 6, 5, 3, 2, KU.to_vec(), KV.to_vec(), None).unwrap();
    let mesh = assert_adaptive_mesh(&s, 1e-6, "plane");
    assert_eq!(mesh.indices.len() / 3, 2 * 9);
    assert_eq!(mesh.positions.len() / 3, 16);
    let corners = net(2, 2, |i, j| DVec3::new(i as f64, 2.0 * j as f64, 0.5));
    let bilinear = BSplineSurface::bezier(&corners, 2, 2, None).unwrap();
    let mesh = bilinear.tessellate_adaptive(1e-9).unwrap();
    assert_eq!((mesh.indices.len(), mesh.positions.len()), (6, 12));
}

#[test]
fn bezier_patches_reproduce_the_surface() {
    // Clamped with a double knot, and unclamped uniform (domain [u_3, u_6]), both rational.
    let clamped = {
        let ku = vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 1.5, 2.0, 2.0, 2.0, 2.0];
        let mut rng = Rng::new(5);
        let coords = net(7, 5, |_, _| rng.point3(3.0));
        let w: Vec<f64> = (0..35).map(|_| rng.range(0.5, 2.0)).collect();
        BSplineSurface::from_flat(&coords, 7, 5, 3, 2, ku, KV.to_vec(), Some(&w)).unwrap()
    };
    let unclamped = {
        let ku: Vec<f64> = (0..10).map(|i| i as f64).collect();
        let kv: Vec<f64> = (0..8).map(|i| 0.5 * i as f64).collect();
        let mut rng = Rng::new(6);
        let coords = net(6, 5, |_, _| rng.point3(3.0));
        let w: Vec<f64> = (0..30).map(|_| rng.range(0.5, 2.0)).collect();
        BSplineSurface::from_flat(&coords, 6, 5, 3, 2, ku, kv, Some(&w)).unwrap()
    };
    for (s, spans_u, spans_v) in [(clamped, 3, 3), (unclamped, 3, 3)] {
        let patches = s.to_bezier_patches().unwrap();
        assert_eq!(patches.len(), spans_u * spans_v);
        let breaks = |k: &[f64], (a, b): (f64, f64)| {
            let mut v: Vec<f64> = k.iter().copied().filter(|t| (a..=b).contains(t)).collect();
            v.dedup();
            v
        };
        let bu = breaks(s.knots_u().as_slice(), s.knots_u().domain());
        let bv = breaks(s.knots_v().as_slice(), s.knots_v().domain());
        for (k, patch) in patches.iter().enumerate() {
            assert_eq!((patch.rows(), patch.cols()), (4, 3));
            assert!(patch.is_rational());
            let (a, b) = (k / spans_v, k % spans_v);
            for (x, y) in [(0.0, 0.0), (0.3, 0.8), (1.0, 0.5), (0.6, 1.0)] {
                let u = bu[a] + x * (bu[a + 1] - bu[a]);
                let v = bv[b] + y * (bv[b + 1] - bv[b]);
                assert_close3(
                    patch.evaluate(x, y).unwrap(),
                    s.evaluate(u, v).unwrap(),
                    1e-12,
                    &format!("patch {k} at ({x}, {y})"),
                );
            }
        }
    }
}

#[test]
fn seams_measure_the_continuity() {
    // Cubic in u: knots 0.5 (r = 1), 1.0 (r = 2), 1.5 (r = 3), 1.8 (r = 4, a gap); quadratic in
    // v: 1.5 (r = 1), 2.2 (r = 2). A random net is no smoother than the multiplicity allows.
    let ku = vec![
        0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.5, 1.5, 1.5, 1.8, 1.8, 1.8, 1.8, 2.0, 2.0, 2.0, 2.0,
    ];
    let kv = vec![1.0, 1.0, 1.0, 1.5, 2.2, 2.2, 3.0, 3.0, 3.0];
    let (rows, cols) = (ku.len() - 4, kv.len() - 3);
    let mut rng = Rng::new(9);
    let coords = net(rows, cols, |_, _| rng.point3(2.0));
    let s = BSplineSurface::from_flat(&coords, rows, cols, 3, 2, ku, kv, None).unwrap();
    let (u, v) = s.seams().unwrap();
    assert_eq!(u, vec![(0.5, 2), (1.0, 1), (1.5, 0), (1.8, -1)]);
    assert_eq!(v, vec![(1.5, 1), (2.2, 0)]);
    // A C² surface (simple knots) with a knot inserted once more: double knots, still C².
    let smooth = wavy(true);
    let doubled = smooth
        .insert_knot_u(0.4, 1)
        .unwrap()
        .insert_knot_v(2.2, 1)
        .unwrap();
    assert_eq!(doubled.knots_u().multiplicity(0.4), 2);
    let (u, v) = doubled.seams().unwrap();
    assert_eq!(u, vec![(0.4, 2), (1.0, 2)]);
    assert_eq!(v, vec![(1.5, 1), (2.2, 1)]);
    // A Bézier patch has none.
    let patch = BSplineSurface::bezier(
        &net(3, 3, |i, j| DVec3::new(i as f64, j as f64, 0.0)),
        3,
        3,
        None,
    )
    .unwrap();
    assert_eq!(patch.seams().unwrap(), (vec![], vec![]));
}

/// The hits as `(u, v, s)`, checked: each point within `tolerance` of the line.
fn hits(s: &BSplineSurface, o: DVec3, d: DVec3, tolerance: f64) -> Vec<[f64; 3]> {
    let hits = s.intersect_line(o, d, tolerance).unwrap();
    for h in &hits {
        let gap = (s.evaluate(h[0], h[1]).unwrap() - (o + h[2] * d)).length();
        assert!(gap <= tolerance, "hit {h:?} is {gap} from the line");
    }
    hits
}

#[test]
fn lines_meet_surfaces_where_expected() {
    let s = wavy(true);
    let mut rng = Rng::new(21);
    for _ in 0..10 {
        let (u0, v0) = (rng.range(0.0, 2.0), rng.range(1.0, 3.0));
        let p = s.evaluate(u0, v0).unwrap();
        let d = rng.point3(1.0) + DVec3::new(0.0, 0.0, 1.5);
        let found = hits(&s, p - 2.0 * d, d, 1e-9);
        assert!(
            found
                .iter()
                .any(|h| (h[0] - u0).abs() < 1e-6 && (h[1] - v0).abs() < 1e-6),
            "no hit at ({u0}, {v0}): {found:?}"
        );
    }
    // Outside the bounding box: nothing.
    assert!(hits(
        &s,
        DVec3::new(0.0, 0.0, 50.0),
        DVec3::new(1.0, 1.0, 0.0),
        1e-6
    )
    .is_empty());
    // A plane S(u, v) = (u, v, 2u − 3v + 1) and a vertical line through (0.3, 1.4): once, at
    // s = 2·0.3 − 3·1.4 + 1 + 5 (the line starts at z = −5, direction (0, 0, 2): s halves it).
    let (gu, gv) = (greville(&KU, 3), greville(&KV, 2));
    let coords = net(6, 5, |i, j| {
        DVec3::new(gu[i], gv[j], 2.0 * gu[i] - 3.0 * gv[j] + 1.0)
    });
    let plane =
        BSplineSurface::from_flat(&coords, 6, 5, 3, 2, KU.to_vec(), KV.to_vec(), None).unwrap();
    let found = hits(
        &plane,
        DVec3::new(0.3, 1.4, -5.0),
        DVec3::new(0.0, 0.0, 2.0),
        1e-10,
    );
    assert_eq!(found.len(), 1, "{found:?}");
    let z = 2.0 * 0.3 - 3.0 * 1.4 + 1.0;
    assert_close(found[0][0], 0.3, 1e-12, "u");
    assert_close(found[0][1], 1.4, 1e-12, "v");
    assert_close(found[0][2], (z + 5.0) / 2.0, 1e-12, "s");
    // A line lying in the plane: a finite sample of the overlap, each point on the line.
    let along = hits(
        &plane,
        DVec3::new(0.0, 1.0, 1.0 - 3.0),
        DVec3::new(1.0, 0.5, 0.5),
        1e-8,
    );
    assert!(!along.is_empty() && along.len() <= 9, "{along:?}");
    for pair in along.windows(2) {
        assert!(pair[1][2] - pair[0][2] > 1e-8, "{along:?}");
    }
    // The saddle z = x² − y² over [−1, 1]² (x = 2u − 1, y = 2v − 1; x² has Bernstein
    // coefficients 1, −1, 1) and the line y = 0.3, z = 0.25 along x: x² = 0.34, twice.
    let c = [1.0, -1.0, 1.0];
    let coords = net(3, 3, |i, j| {
        DVec3::new(i as f64 - 1.0, j as f64 - 1.0, c[i] - c[j])
    });
    let saddle = BSplineSurface::bezier(&coords, 3, 3, None).unwrap();
    let found = hits(
        &saddle,
        DVec3::new(-3.0, 0.3, 0.25),
        DVec3::new(1.0, 0.0, 0.0),
        1e-10,
    );
    assert_eq!(found.len(), 2, "{found:?}");
    let x = 0.34f64.sqrt();
    for (h, x) in found.iter().zip([-x, x]) {
        assert_close(h[0], (x + 1.0) / 2.0, 1e-10, "u of a saddle hit");
        assert_close(h[1], 0.65, 1e-10, "v of a saddle hit");
        assert_close(h[2], x + 3.0, 1e-10, "s of a saddle hit");
    }
}

/// A line lying in a surface has infinitely many hits: the search reports a sample, at most
/// `MAX_NEWTON_STARTS` points (60 000 Newton starts took seconds). Here
/// a flat strip of 5000 bilinear patches along x, and the line y = ½ in it: one hit per patch
/// it crosses, capped; a line across the strip still meets it once.
#[test]
fn a_line_lying_in_a_surface_is_sampled_by_at_most_max_newton_starts() {
    use splinelab::surface::MAX_NEWTON_STARTS;
    let cols = 5001;
    let coords = net(2, cols, |i, j| DVec3::new(j as f64, i as f64, 0.0));
    let knots_v: Vec<f64> = [0.0]
        .into_iter()
        .chain((0..cols).map(|j| j as f64))
        .chain([(cols - 1) as f64])
        .collect();
    let s = BSplineSurface::from_flat(
        &coords,
        2,
        cols,
        1,
        1,
        vec![0.0, 0.0, 1.0, 1.0],
        knots_v,
        None,
    )
    .unwrap();
    let along = hits(&s, DVec3::new(-1.0, 0.5, 0.0), DVec3::X, 1e-9);
    assert_eq!(
        along.len(),
        MAX_NEWTON_STARTS,
        "a sample of the line, capped"
    );
    let across = hits(
        &s,
        DVec3::new(2500.25, 0.5, 1.0),
        DVec3::new(0.0, 0.0, -1.0),
        1e-9,
    );
    assert_eq!(across.len(), 1, "{across:?}");
    assert!((across[0][2] - 1.0).abs() < 1e-9);
}
