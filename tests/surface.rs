//! Tensor-product B-spline and NURBS surfaces against independent expectations: linear
//! precision (a net on the Greville abscissae reproduces a plane exactly), the NURBS cylinder
//! (every point at radius r exactly, normals radial), separable nets whose surface factors into
//! two curves already checked against scipy (points and every partial derivative), the grid
//! fast path against point evaluation, and the validation messages. Runs natively and in Node.

mod common;

use common::*;
use splinelab::{BSplineCurve, BSplineSurface, DVec2, DVec3};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// Greville abscissae `(u_{i+1} + … + u_{i+p})/p` of a knot vector.
fn greville(knots: &[f64], p: usize) -> Vec<f64> {
    (0..knots.len() - p - 1)
        .map(|i| knots[i + 1..=i + p].iter().sum::<f64>() / p as f64)
        .collect()
}

/// Flat row-major coordinates of `f(i, j)` on a rows × cols net.
fn net(rows: usize, cols: usize, f: impl Fn(usize, usize) -> DVec3) -> Vec<f64> {
    (0..rows)
        .flat_map(|i| (0..cols).map(move |j| (i, j)))
        .flat_map(|(i, j)| f(i, j).to_array())
        .collect()
}

#[test]
fn a_net_on_the_greville_abscissae_reproduces_a_plane() {
    // Non-uniform knots, degrees 3 × 2: S(u, v) = (u, v, 2u − 3v + 1) exactly.
    let ku = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 1.2, 2.0, 2.0, 2.0, 2.0];
    let kv = vec![1.0, 1.0, 1.0, 1.5, 3.0, 3.0, 3.0];
    let (gu, gv) = (greville(&ku, 3), greville(&kv, 2));
    let plane = |u: f64, v: f64| DVec3::new(u, v, 2.0 * u - 3.0 * v + 1.0);
    let coords = net(gu.len(), gv.len(), |i, j| plane(gu[i], gv[j]));
    let s = BSplineSurface::from_flat(&coords, gu.len(), gv.len(), 3, 2, ku, kv, None).unwrap();
    assert_eq!((s.rows(), s.cols()), (7, 4));
    for a in 0..=10 {
        for b in 0..=10 {
            let (u, v) = (0.2 * a as f64, 1.0 + 0.2 * b as f64);
            assert_close3(
                s.evaluate(u, v).unwrap(),
                plane(u, v),
                1e-14,
                &format!("S({u}, {v})"),
            );
            assert_close3(
                s.derivative(u, v, 1, 0).unwrap(),
                DVec3::new(1.0, 0.0, 2.0),
                1e-13,
                "S_u",
            );
            assert_close3(
                s.derivative(u, v, 0, 1).unwrap(),
                DVec3::new(0.0, 1.0, -3.0),
                1e-13,
                "S_v",
            );
            assert_close3(
                s.derivative(u, v, 1, 1).unwrap(),
                DVec3::ZERO,
                1e-12,
                "S_uv",
            );
            assert_close3(
                s.derivative(u, v, 4, 0).unwrap(),
                DVec3::ZERO,
                0.0,
                "above the degree",
            );
            // The plane's unit normal: (1, 0, 2) × (0, 1, −3) = (−2, 3, 1)/√14.
            let n = DVec3::new(-2.0, 3.0, 1.0) / 14f64.sqrt();
            assert_close3(s.normal(u, v).unwrap(), n, 1e-14, "normal");
        }
    }
}

/// The NURBS cylinder of radius `r` and height `h`: the 9-point circle (knots
/// `0,0,0,¼,¼,½,½,¾,¾,1,1,1`, corner weights √2/2) along u, a degree-1 segment along v.
fn cylinder(r: f64, h: f64) -> BSplineSurface {
    let coords = net(9, 2, |i, j| {
        DVec3::new(r * CIRCLE_POINTS[i].0, r * CIRCLE_POINTS[i].1, h * j as f64)
    });
    let weights: Vec<f64> = (0..18).map(|k| circle_weight(k / 2)).collect();
    let ku = CIRCLE_KNOTS.to_vec();
    BSplineSurface::from_flat(
        &coords,
        9,
        2,
        2,
        1,
        ku,
        vec![0.0, 0.0, 1.0, 1.0],
        Some(&weights),
    )
    .unwrap()
}

#[test]
fn the_nurbs_cylinder_is_round_and_its_normals_radial() {
    let (r, h) = (2.5, 4.0);
    let s = cylinder(r, h);
    assert!(s.is_rational());
    for a in 0..=40 {
        for b in 0..=4 {
            let (u, v) = (a as f64 / 40.0, b as f64 / 4.0);
            let p = s.evaluate(u, v).unwrap();
            assert_close(
                p.truncate().length(),
                r,
                1e-14 * r,
                &format!("radius at ({u}, {v})"),
            );
            assert_close(p.z, h * v, 1e-14, "height is linear in v");
            // Counter-clockwise in u, upward in v: S_u × S_v points outward.
            let n = s.normal(u, v).unwrap();
            assert_close3(
                n,
                (p.truncate() / r).extend(0.0),
                1e-13,
                &format!("normal at ({u}, {v})"),
            );
        }
    }
    // The quarter points of the circle are control points.
    assert_close3(
        s.evaluate(0.25, 0.5).unwrap(),
        DVec3::new(0.0, r, 2.0),
        1e-15,
        "S(1/4, 1/2)",
    );
}

#[test]
fn a_separable_net_factors_into_two_curves_with_all_their_derivatives() {
    // P_ij = (x_i, y_j, a_i·b_j), w_ij = α_i·β_j: S(u, v) = (X(u), Y(v), A(u)·B(v)) where
    // (X, A) is the NURBS curve through (x_i, a_i) with weights α_i and (Y, B) the one through
    // (y_j, b_j) with weights β_j (Σ_j N_j β_j y_j/Σ_j N_j β_j does not depend on u).
    let mut rng = Rng::new(7);
    let (rows, cols, p, q) = (6, 5, 3, 2);
    let ku = vec![0.0, 0.0, 0.0, 0.0, 0.4, 0.7, 1.0, 1.0, 1.0, 1.0];
    let kv = vec![-1.0, -1.0, -1.0, 0.5, 0.5, 2.0, 2.0, 2.0];
    let cu: Vec<DVec2> = (0..rows).map(|_| rng.point2(3.0)).collect();
    let cv: Vec<DVec2> = (0..cols).map(|_| rng.point2(3.0)).collect();
    let alpha: Vec<f64> = (0..rows).map(|_| rng.range(0.5, 2.0)).collect();
    let beta: Vec<f64> = (0..cols).map(|_| rng.range(0.5, 2.0)).collect();
    let coords = net(rows, cols, |i, j| {
        DVec3::new(cu[i].x, cv[j].x, cu[i].y * cv[j].y)
    });
    let weights: Vec<f64> = (0..rows)
        .flat_map(|i| beta.iter().map(|b| alpha[i] * b).collect::<Vec<_>>())
        .collect();
    let s = BSplineSurface::from_flat(
        &coords,
        rows,
        cols,
        p,
        q,
        ku.clone(),
        kv.clone(),
        Some(&weights),
    )
    .unwrap();
    let curve_u = BSplineCurve::new(cu, p, ku, Some(&alpha)).unwrap();
    let curve_v = BSplineCurve::new(cv, q, kv, Some(&beta)).unwrap();
    for a in 0..=12 {
        for b in 0..=12 {
            let (u, v) = (a as f64 / 12.0, -1.0 + 3.0 * b as f64 / 12.0);
            for du in 0..=3 {
                for dv in 0..=3 - du {
                    let (x, y) = (
                        curve_u.derivative(u, du).unwrap(),
                        curve_v.derivative(v, dv).unwrap(),
                    );
                    let expected = DVec3::new(
                        if dv == 0 { x.x } else { 0.0 },
                        if du == 0 { y.x } else { 0.0 },
                        x.y * y.y,
                    );
                    let got = s.derivative(u, v, du, dv).unwrap();
                    let tol = 1e-11 * (1.0 + expected.length());
                    assert_close3(
                        got,
                        expected,
                        tol,
                        &format!("∂^({du},{dv}) S at ({u}, {v})"),
                    );
                }
            }
        }
    }
}

/// `out` (from `sample_grid_into(us, vs)`) holds `S(u_a, v_b)` at point `a·len(vs) + b`.
fn assert_grid_is_points(
    s: &BSplineSurface,
    us: &[f64],
    vs: &[f64],
    out: &[f64],
    tol: f64,
    what: &str,
) {
    assert_eq!(out.len(), us.len() * vs.len() * 3, "{what}: grid size");
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            let k = 3 * (a * vs.len() + b);
            let got = DVec3::new(out[k], out[k + 1], out[k + 2]);
            assert_close3(
                got,
                s.evaluate(u, v).unwrap(),
                tol,
                &format!("{what} grid point ({u}, {v})"),
            );
        }
    }
}

#[test]
fn the_grid_fast_path_equals_point_evaluation() {
    // Unsorted and repeated parameters, the ends of the domain, a knot of multiplicity 2.
    let s = cylinder(1.0, 2.0);
    let us = [0.0, 1.0, 0.25, 0.6, 0.6, 0.999, 0.5, 0.1];
    let vs = [1.0, 0.0, 0.3, 0.7];
    let mut out = vec![7.0; 3];
    s.sample_grid_into(&us, &vs, &mut out).unwrap();
    assert_eq!(out.len(), us.len() * vs.len() * 3);
    assert_grid_is_points(&s, &us, &vs, &out, 1e-15, "");
    s.sample_grid_into(&[], &vs, &mut out).unwrap();
    assert!(out.is_empty());

    // Every degree along v (the unrolled kernels for q = 1..5 and the general loop), random
    // rational nets on non-uniform knots.
    let mut rng = Rng::new(11);
    for q in 1..=7 {
        let (rows, cols, p) = (5, q + 3, 2);
        let mut clamped = |n: usize, d: usize| -> Vec<f64> {
            let mut k = vec![0.0; d + 1];
            let mut t = 0.0;
            for _ in 0..n - d - 1 {
                t += rng.range(0.5, 1.5);
                k.push(t);
            }
            t += rng.range(0.5, 1.5);
            k.extend(std::iter::repeat_n(t, d + 1));
            k
        };
        let (ku, kv) = (clamped(rows, p), clamped(cols, q));
        let coords: Vec<f64> = (0..rows * cols)
            .flat_map(|_| rng.point3(2.0).to_array())
            .collect();
        let weights: Vec<f64> = (0..rows * cols).map(|_| rng.range(0.5, 2.0)).collect();
        let (bu, bv) = (ku[ku.len() - 1], kv[kv.len() - 1]);
        let s =
            BSplineSurface::from_flat(&coords, rows, cols, p, q, ku, kv, Some(&weights)).unwrap();
        let us: Vec<f64> = (0..=9).map(|a| bu * a as f64 / 9.0).collect();
        let vs: Vec<f64> = (0..=13).map(|b| bv * b as f64 / 13.0).collect();
        s.sample_grid_into(&us, &vs, &mut out).unwrap();
        assert_grid_is_points(&s, &us, &vs, &out, 1e-14, &format!("q = {q}"));
    }
}

#[test]
fn bad_surfaces_and_parameters_are_refused_with_a_message() {
    let ku = || vec![0.0, 0.0, 1.0, 1.0];
    let flat = net(2, 2, |i, j| DVec3::new(i as f64, j as f64, 0.0));
    let make = |coords: &[f64], rows, cols, p, q, ku: Vec<f64>, kv: Vec<f64>, w: Option<&[f64]>| {
        BSplineSurface::from_flat(coords, rows, cols, p, q, ku, kv, w)
            .unwrap_err()
            .to_string()
    };
    let e = make(&flat[..11], 2, 2, 1, 1, ku(), ku(), None);
    assert!(
        e.contains("rows·cols·3 = 2·2·3 = 12") && e.contains("got 11"),
        "{e}"
    );
    let mut nan = flat.clone();
    nan[4] = f64::NAN;
    assert!(make(&nan, 2, 2, 1, 1, ku(), ku(), None).contains("coordinate 4"));
    let e = make(&flat, 2, 2, 2, 1, ku(), ku(), None);
    assert!(e.contains("degreeU") && e.contains("p+1 = 3"), "{e}");
    let e = make(&flat, 2, 2, 1, 1, ku(), vec![0.0, 0.0, 1.0], None);
    assert!(e.starts_with("knotsV: ") && e.contains("got 3"), "{e}");
    let e = make(&flat, 2, 2, 1, 1, vec![0.0, 1.0, 0.5, 1.0], ku(), None);
    assert!(
        e.starts_with("knotsU: ") && e.contains("must not decrease"),
        "{e}"
    );
    let e = make(&flat, 2, 2, 1, 1, ku(), ku(), Some(&[1.0, 1.0, 0.0, 1.0]));
    assert!(e.contains("weight") && e.contains('2'), "{e}");
    let e = make(&flat, usize::MAX, 2, 1, 1, ku(), ku(), None);
    assert!(e.contains("rows·cols"), "{e}");

    let s = BSplineSurface::from_flat(&flat, 2, 2, 1, 1, ku(), ku(), None).unwrap();
    let e = s.evaluate(0.5, 1.5).unwrap_err().to_string();
    assert!(e.contains("v = 1.5") && e.contains("[0, 1]"), "{e}");
    assert!(s
        .evaluate(f64::NAN, 0.5)
        .unwrap_err()
        .to_string()
        .contains('u'));
    assert!(s
        .derivative(0.5, 0.5, 20, 20)
        .unwrap_err()
        .to_string()
        .contains("40"));
    let e = s
        .sample_grid_into(&[0.5], &[0.2, 2.0], &mut Vec::new())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("vs[1]: ") && e.contains("v = 2"), "{e}");
    // No direction at all: every control point the same.
    let point = net(2, 2, |_, _| DVec3::ONE);
    let s = BSplineSurface::from_flat(&point, 2, 2, 1, 1, ku(), ku(), None).unwrap();
    let e = s.normal(0.0, 0.5).unwrap_err().to_string();
    assert!(e.contains("no normal at (u, v) = (0, 0.5)"), "{e}");
}

/// A planar fan in z = 0 with the row `apex` (0 or 1) of a 2 × 2 net collapsed to the origin.
fn fan_net(apex: usize) -> Vec<f64> {
    net(2, 2, |i, j| {
        if i == apex {
            DVec3::ZERO
        } else {
            DVec3::new(1.0, j as f64 - 0.5, 0.0)
        }
    })
}

#[test]
fn normals_at_collapsed_edges_are_the_limits_from_inside() {
    let ku = || vec![0.0, 0.0, 1.0, 1.0];
    // A planar fan: row 0 (u = 0) collapsed to the apex, so S_v = 0 there; every normal of a
    // plane is the plane's, (0, 0, 1) here (S_u points away from the apex, S_v along +y).
    let fan = fan_net(0);
    let s = BSplineSurface::from_flat(&fan, 2, 2, 1, 1, ku(), ku(), None).unwrap();
    for v in [0.0, 0.3, 1.0] {
        assert_close3(
            s.normal(0.0, v).unwrap(),
            DVec3::Z,
            1e-15,
            &format!("fan apex, v = {v}"),
        );
        assert_close3(s.normal(0.5, v).unwrap(), DVec3::Z, 1e-15, "fan inside");
    }
    // The same fan with the apex at the far end (u = 1), and one collapsed at v = 1: the limits
    // keep the orientation of the inside.
    let flipped = fan_net(1);
    let s = BSplineSurface::from_flat(&flipped, 2, 2, 1, 1, ku(), ku(), None).unwrap();
    let inside = s.normal(0.5, 0.5).unwrap();
    assert_close3(s.normal(1.0, 0.5).unwrap(), inside, 1e-15, "apex at u = 1");
    let columns = net(2, 2, |i, j| {
        if j == 1 {
            DVec3::ZERO
        } else {
            DVec3::new(i as f64 - 0.5, 1.0, 0.0)
        }
    });
    let s = BSplineSurface::from_flat(&columns, 2, 2, 1, 1, ku(), ku(), None).unwrap();
    let inside = s.normal(0.5, 0.5).unwrap();
    assert_close3(s.normal(0.3, 1.0).unwrap(), inside, 1e-15, "apex at v = 1");
    // A cone over the NURBS circle, apex in row 0: the normal at the apex along each ruling is
    // the limit of the normals approaching it.
    let cone = net(2, 9, |i, j| {
        if i == 0 {
            DVec3::new(0.0, 0.0, 2.0)
        } else {
            DVec3::new(CIRCLE_POINTS[j].0, CIRCLE_POINTS[j].1, 0.0)
        }
    });
    let weights: Vec<f64> = (0..18).map(|k| circle_weight(k % 9)).collect();
    let kv = CIRCLE_KNOTS.to_vec();
    let s = BSplineSurface::from_flat(&cone, 2, 9, 1, 2, ku(), kv, Some(&weights)).unwrap();
    for v in [0.0, 0.1, 0.25, 0.6] {
        let apex = s.normal(0.0, v).unwrap();
        assert_close3(
            apex,
            s.normal(1e-7, v).unwrap(),
            1e-6,
            &format!("cone apex, v = {v}"),
        );
        // The cone z = 2(1 − r): every normal makes the angle with z whose cosine is 1/√5.
        assert_close(apex.z.abs(), 1.0 / 5f64.sqrt(), 1e-14, "cone opening");
    }
}

/// `B_i^n(t)` from its definition.
fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    let c = (1..=i).fold(1.0, |acc, k| acc * (n + 1 - k) as f64 / k as f64);
    c * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
}

/// A random rational Bézier patch of `rows × cols` points and its defining double sum.
fn bezier_patch(
    rng: &mut Rng,
    rows: usize,
    cols: usize,
) -> (BSplineSurface, impl Fn(f64, f64) -> DVec3) {
    let points: Vec<DVec3> = (0..rows * cols).map(|_| rng.point3(2.0)).collect();
    let weights: Vec<f64> = (0..rows * cols).map(|_| rng.range(0.5, 2.0)).collect();
    let coords: Vec<f64> = points.iter().flat_map(|p| p.to_array()).collect();
    let s = BSplineSurface::bezier(&coords, rows, cols, Some(&weights)).unwrap();
    let sum = move |u: f64, v: f64| {
        let (mut num, mut den) = (DVec3::ZERO, 0.0);
        for i in 0..rows {
            for j in 0..cols {
                let b =
                    bernstein(rows - 1, i, u) * bernstein(cols - 1, j, v) * weights[i * cols + j];
                num += b * points[i * cols + j];
                den += b;
            }
        }
        num / den
    };
    (s, sum)
}

/// `s(u, v)` against `sum(u, v)` on the `(steps + 1)²` grid of [0, 1]².
fn assert_is_the_sum(
    s: &BSplineSurface,
    sum: &impl Fn(f64, f64) -> DVec3,
    steps: usize,
    tol: f64,
    what: &str,
) {
    for a in 0..=steps {
        for b in 0..=steps {
            let (u, v) = (a as f64 / steps as f64, b as f64 / steps as f64);
            assert_close3(
                s.evaluate(u, v).unwrap(),
                sum(u, v),
                tol,
                &format!("{what} at ({u}, {v})"),
            );
        }
    }
}

#[test]
fn a_bezier_patch_is_the_bernstein_double_sum_and_splits_into_four() {
    let mut rng = Rng::new(3);
    let (s, sum) = bezier_patch(&mut rng, 4, 3);
    assert_eq!((s.degree_u(), s.degree_v()), (3, 2));
    assert_is_the_sum(&s, &sum, 8, 1e-14, "P");
    // The four pieces of a split at (0.3, 0.6), each on [0, 1]², reparametrise the quarters.
    let (u0, v0) = (0.3, 0.6);
    let pieces = s.split_bezier(u0, v0).unwrap();
    let maps: [(f64, f64, f64, f64); 4] = [
        (0.0, u0, 0.0, v0),
        (0.0, u0, v0, 1.0),
        (u0, 1.0, 0.0, v0),
        (u0, 1.0, v0, 1.0),
    ];
    for (piece, (ua, ub, va, vb)) in pieces.iter().zip(maps) {
        assert_eq!((piece.rows(), piece.cols()), (4, 3));
        for (x, y) in [(0.0, 0.0), (0.5, 0.25), (1.0, 0.7), (0.2, 1.0)] {
            let whole = sum(ua + x * (ub - ua), va + y * (vb - va));
            assert_close3(
                piece.evaluate(x, y).unwrap(),
                whole,
                1e-14,
                &format!("piece [{ua}, {ub}]×[{va}, {vb}] at ({x}, {y})"),
            );
        }
    }
    let e = BSplineSurface::bezier(&[0.0; 6], 1, 2, None)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("at least 2 rows and 2 columns") && e.contains("1 × 2"),
        "{e}"
    );
    assert!(s
        .split_bezier(0.5, 1.5)
        .unwrap_err()
        .to_string()
        .contains("v = 1.5"));
}

#[test]
fn knot_insertion_adds_a_row_or_a_column_and_keeps_the_shape() {
    let mut rng = Rng::new(5);
    let (s, sum) = bezier_patch(&mut rng, 4, 4);
    let refined = s
        .insert_knot_u(0.4, 2)
        .unwrap()
        .insert_knot_v(0.7, 1)
        .unwrap();
    assert_eq!((refined.rows(), refined.cols()), (6, 5));
    assert_eq!(
        refined.knots_u().as_slice(),
        &[0.0, 0.0, 0.0, 0.0, 0.4, 0.4, 1.0, 1.0, 1.0, 1.0]
    );
    assert_eq!(
        refined.knots_v().as_slice(),
        &[0.0, 0.0, 0.0, 0.0, 0.7, 1.0, 1.0, 1.0, 1.0]
    );
    assert_is_the_sum(&refined, &sum, 10, 1e-13, "S after insertion");
    let e = refined.insert_knot_u(0.4, 3).unwrap_err().to_string();
    assert!(e.contains("u = 0.4") && e.contains("multiplicity 5"), "{e}");
    assert!(s
        .insert_knot_v(-0.1, 1)
        .unwrap_err()
        .to_string()
        .contains("v = -0.1"));
    // A polynomial surface keeps weights of exactly 1.
    let plane = net(3, 3, |i, j| DVec3::new(i as f64, j as f64, 0.0));
    let p = BSplineSurface::bezier(&plane, 3, 3, None)
        .unwrap()
        .insert_knot_u(0.37, 1)
        .unwrap();
    assert!(!p.is_rational() && p.weights().iter().all(|&w| w == 1.0));
}

#[test]
fn tessellation_is_the_grid_with_normals_and_outward_triangles() {
    let s = cylinder(1.0, 2.0);
    let (nu, nv) = (8, 3);
    let mesh = s.tessellate(nu, nv).unwrap();
    assert_eq!(mesh.positions.len(), 3 * (nu + 1) * (nv + 1));
    assert_eq!(mesh.normals.len(), mesh.positions.len());
    assert_eq!(mesh.indices.len(), 6 * nu * nv);
    let at = |v: &[f32], k: u32| {
        DVec3::new(
            v[3 * k as usize] as f64,
            v[3 * k as usize + 1] as f64,
            v[3 * k as usize + 2] as f64,
        )
    };
    for a in 0..=nu {
        for b in 0..=nv {
            let k = (a * (nv + 1) + b) as u32;
            let (u, v) = (a as f64 / nu as f64, b as f64 / nv as f64);
            assert_close3(
                at(&mesh.positions, k),
                s.evaluate(u, v).unwrap(),
                1e-6,
                "vertex",
            );
            assert_close3(
                at(&mesh.normals, k),
                s.normal(u, v).unwrap(),
                1e-6,
                "vertex normal",
            );
        }
    }
    // Every triangle faces the way its vertices' normals point (outward on the cylinder).
    for t in mesh.indices.chunks_exact(3) {
        let [p0, p1, p2] = [
            at(&mesh.positions, t[0]),
            at(&mesh.positions, t[1]),
            at(&mesh.positions, t[2]),
        ];
        let face = (p1 - p0).cross(p2 - p0);
        assert!(
            face.dot(at(&mesh.normals, t[0])) > 0.0,
            "triangle {t:?} faces inward"
        );
    }
    assert!(s
        .tessellate(0, 4)
        .unwrap_err()
        .to_string()
        .contains("nu = 0"));
    let e = s.tessellate(3000, 3000).unwrap_err().to_string();
    assert!(
        e.contains("tessellation vertices") && e.contains("9006001"),
        "{e}"
    );
    // A collapsed edge in a mesh: the apex vertices take the limit normal, the plane's.
    let knots = || vec![0.0, 0.0, 1.0, 1.0];
    let fan = BSplineSurface::from_flat(&fan_net(0), 2, 2, 1, 1, knots(), knots(), None).unwrap();
    let fan_mesh = fan.tessellate(4, 4).unwrap();
    for k in 0..25 {
        assert_close3(
            at(&fan_mesh.normals, k),
            DVec3::Z,
            1e-7,
            &format!("fan mesh normal {k}"),
        );
    }
    // A corner where both partial derivatives vanish (P00 = P01 = P10 on a biquadratic): no
    // limit either, so the vertex gets the mean of its triangles' normals, close to its
    // neighbours'.
    let corner = net(3, 3, |i, j| match (i, j) {
        (0, 0) | (0, 1) | (1, 0) => DVec3::ZERO,
        _ => DVec3::new(i as f64, j as f64, 0.1 * (i * j) as f64),
    });
    let s = BSplineSurface::bezier(&corner, 3, 3, None).unwrap();
    assert!(s.normal(0.0, 0.0).is_err());
    let mesh = s.tessellate(16, 16).unwrap();
    let n0 = at(&mesh.normals, 0);
    assert_close(n0.length(), 1.0, 1e-6, "fallback normal is a unit vector");
    assert!(
        n0.dot(at(&mesh.normals, 17 + 1)) > 0.9,
        "fallback normal {n0} agrees with the neighbours'"
    );
}

#[test]
fn edits_in_place_equal_a_rebuilt_surface() {
    let mut rng = Rng::new(9);
    let coords: Vec<f64> = (0..4 * 3)
        .flat_map(|_| rng.point3(1.0).to_array())
        .collect();
    let weights: Vec<f64> = (0..12).map(|_| rng.range(0.5, 2.0)).collect();
    let knots_u = vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let knots_v = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    let build = |c: &[f64], w: &[f64]| {
        BSplineSurface::from_flat(c, 4, 3, 2, 2, knots_u.clone(), knots_v.clone(), Some(w)).unwrap()
    };
    let mut s = build(&coords, &weights);
    let moved = DVec3::new(0.3, -0.2, 1.5);
    s.set_control_point(2, 1, moved).unwrap();
    s.set_weight(0, 2, 3.0).unwrap();
    let (mut c2, mut w2) = (coords.clone(), weights.clone());
    c2[3 * (2 * 3 + 1)..3 * (2 * 3 + 1) + 3].copy_from_slice(&moved.to_array());
    w2[2] = 3.0;
    let rebuilt = build(&c2, &w2);
    for (u, v) in [(0.0, 0.0), (0.3, 0.8), (0.5, 0.5), (1.0, 0.2)] {
        assert_close3(
            s.evaluate(u, v).unwrap(),
            rebuilt.evaluate(u, v).unwrap(),
            1e-14,
            &format!("S({u}, {v})"),
        );
    }
    let e = s
        .set_control_point(4, 0, DVec3::ZERO)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("(4, 0) is out of range") && e.contains("4 × 3"),
        "{e}"
    );
    assert!(s
        .set_weight(1, 1, 0.0)
        .unwrap_err()
        .to_string()
        .contains("> 0"));
    assert!(s
        .set_control_point(0, 0, DVec3::new(f64::NAN, 0.0, 0.0))
        .unwrap_err()
        .to_string()
        .contains("coordinate 0"));
}

#[test]
fn equal_weights_give_the_polynomial_patch_whose_corners_and_normals_are_right() {
    let mut rng = Rng::new(14);
    let points: Vec<f64> = (0..4 * 5)
        .flat_map(|_| rng.point3(3.0).to_array())
        .collect();
    let polynomial = BSplineSurface::bezier(&points, 4, 5, None).unwrap();
    // Any common weight cancels in Σ B w P / Σ B w: the same surface, and the same derivatives.
    let rational = BSplineSurface::bezier(&points, 4, 5, Some(&[2.5; 20])).unwrap();
    let corner = |i: usize, j: usize| DVec3::from_slice(&points[(i * 5 + j) * 3..]);
    for (u, v, i, j) in [
        (0.0, 0.0, 0, 0),
        (0.0, 1.0, 0, 4),
        (1.0, 0.0, 3, 0),
        (1.0, 1.0, 3, 4),
    ] {
        assert_close3(
            polynomial.evaluate(u, v).unwrap(),
            corner(i, j),
            1e-14,
            "corner",
        );
    }
    for _ in 0..50 {
        let (u, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        let what = format!("at ({u}, {v})");
        assert_close3(
            rational.evaluate(u, v).unwrap(),
            polynomial.evaluate(u, v).unwrap(),
            1e-13,
            &what,
        );
        for (du, dv) in [(1, 0), (0, 1), (1, 1)] {
            assert_close3(
                rational.derivative(u, v, du, dv).unwrap(),
                polynomial.derivative(u, v, du, dv).unwrap(),
                1e-11,
                &what,
            );
        }
        // The normal is a unit vector orthogonal to both partial derivatives, on the side of
        // S_u × S_v.
        let n = polynomial.normal(u, v).unwrap();
        let su = polynomial.derivative(u, v, 1, 0).unwrap();
        let sv = polynomial.derivative(u, v, 0, 1).unwrap();
        assert!(
            (n.length() - 1.0).abs() < 1e-14,
            "|n| = {} {what}",
            n.length()
        );
        assert!(n.dot(su).abs() < 1e-12 * su.length(), "n·S_u {what}");
        assert!(n.dot(sv).abs() < 1e-12 * sv.length(), "n·S_v {what}");
        assert!(
            n.dot(su.cross(sv)) > 0.0,
            "n on the side of S_u × S_v {what}"
        );
    }
}
