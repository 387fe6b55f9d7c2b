//! Issue 14's surface additions against independent expectations: de Casteljau rows first =
//! columns first = `evaluate`; the matrix form against the notes' cubic `M` and a direct
//! polynomial evaluation; iso-curves against the surface; curvature of a sphere, plane,
//! cylinder and torus against their closed forms; revolution (a circle gives a torus exactly),
//! extrusion and ruled surfaces against their formulas; grid interpolation through every
//! point and against a scipy fixture. Runs natively and in Node.

mod common;

use common::*;
use splinelab::bspline::Parameterization;
use splinelab::prelude::*;
use splinelab::rational::ellipse_arc;
use splinelab::surface::{bezier_basis_matrix, extrude, interpolate_surface, revolve, ruled};
use splinelab::{BSplineCurve, BSplineSurface, DVec3};
use std::f64::consts::{FRAC_PI_2, PI, TAU};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// A bicubic patch with a bumpy net: `P_ij = (i, j, h_ij)`.
fn bicubic(weights: Option<&[f64]>) -> BSplineSurface {
    let heights = [
        [0.0, 1.0, -1.0, 0.5],
        [2.0, -1.5, 1.0, 0.0],
        [0.5, 2.5, -2.0, 1.0],
        [1.0, 0.0, 1.5, -0.5],
    ];
    let coords: Vec<f64> = (0..4)
        .flat_map(|i| (0..4).flat_map(move |j| [i as f64, j as f64 * 1.5, heights[i][j]]))
        .collect();
    BSplineSurface::bezier(&coords, 4, 4, weights).unwrap()
}

/// A 4 × 3 (degrees 3 × 2) patch, so the two directions differ.
fn cubic_by_quadratic() -> BSplineSurface {
    let mut rng = Rng::new(14);
    let coords: Vec<f64> = (0..12).flat_map(|_| rng.point3(2.0).to_array()).collect();
    BSplineSurface::bezier(&coords, 4, 3, None).unwrap()
}

const WEIGHTS: [f64; 16] = [
    1.0, 2.0, 0.5, 1.0, 1.5, 1.0, 3.0, 0.7, 1.0, 0.4, 1.0, 2.0, 1.0, 1.0, 0.8, 1.0,
];

#[test]
fn de_casteljau_rows_first_equals_columns_first_equals_evaluate() {
    let mut rng = Rng::new(1);
    for surface in [bicubic(None), bicubic(Some(&WEIGHTS)), cubic_by_quadratic()] {
        let (rows, cols) = (surface.rows(), surface.cols());
        for _ in 0..20 {
            let (u, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
            let point = surface.evaluate(u, v).unwrap();
            let by_rows = surface.de_casteljau_patch(u, v, false).unwrap();
            let by_cols = surface.de_casteljau_patch(u, v, true).unwrap();
            // Sizes: one triangle per row (cols(cols+1)/2 points) and one over the rows.
            assert_eq!(by_rows.first.len(), rows * cols * (cols + 1) / 2);
            assert_eq!(by_rows.second.len(), rows * (rows + 1) / 2);
            assert_eq!(by_cols.first.len(), cols * rows * (rows + 1) / 2);
            assert_eq!(by_cols.second.len(), cols * (cols + 1) / 2);
            assert_close3(*by_rows.second.last().unwrap(), point, 1e-12, "rows first");
            assert_close3(
                *by_cols.second.last().unwrap(),
                point,
                1e-12,
                "columns first",
            );
            // Level 0 of row i's triangle is row i of the net; its last point is the iso
            // curve's point S(u_i-th row, v) = that row's Bézier curve at v, the first entry
            // of the column triangle.
            let net = surface.control_points();
            let tri = cols * (cols + 1) / 2;
            for i in 0..rows {
                assert_eq!(
                    &by_rows.first[i * tri..i * tri + cols],
                    &net[i * cols..(i + 1) * cols]
                );
                assert_close3(
                    by_rows.first[(i + 1) * tri - 1],
                    by_rows.second[i],
                    0.0,
                    "row results start the column triangle",
                );
            }
        }
    }
}

#[test]
fn the_matrix_form_is_the_notes_and_reproduces_evaluate() {
    assert_eq!(
        bezier_basis_matrix(3),
        vec![-1.0, 3.0, -3.0, 1.0, 3.0, -6.0, 3.0, 0.0, -3.0, 3.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]
    );
    assert_eq!(bezier_basis_matrix(1), vec![-1.0, 1.0, 1.0, 0.0]);
    let mut rng = Rng::new(2);
    for surface in [bicubic(None), cubic_by_quadratic()] {
        let form = surface.matrix_form().unwrap();
        let (rows, cols) = (surface.rows(), surface.cols());
        assert_eq!(form.basis_u, bezier_basis_matrix(rows - 1));
        assert_eq!(form.basis_v, bezier_basis_matrix(cols - 1));
        assert_eq!(form.coefficients.len(), rows * cols);
        for _ in 0..50 {
            let (u, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
            // [u^m … u 1] A [v^n … v 1]ᵀ, powers descending.
            let mut sum = DVec3::ZERO;
            for r in 0..rows {
                for c in 0..cols {
                    let weight = u.powi((rows - 1 - r) as i32) * v.powi((cols - 1 - c) as i32);
                    sum += form.coefficients[r * cols + c] * weight;
                }
            }
            assert_close3(sum, surface.evaluate(u, v).unwrap(), 1e-12, "U A Vᵀ");
        }
    }
    assert!(bicubic(Some(&WEIGHTS)).matrix_form().is_err());
}

/// A NURBS surface with non-uniform knots and weights, degrees 3 × 2, 5 × 4 net.
fn nurbs() -> BSplineSurface {
    let mut rng = Rng::new(3);
    let coords: Vec<f64> = (0..20).flat_map(|_| rng.point3(3.0).to_array()).collect();
    let weights: Vec<f64> = (0..20).map(|_| rng.range(0.5, 2.0)).collect();
    BSplineSurface::from_flat(
        &coords,
        5,
        4,
        3,
        2,
        vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0],
        vec![2.0, 2.0, 2.0, 2.7, 3.0, 3.0, 3.0],
        Some(&weights),
    )
    .unwrap()
}

#[test]
fn iso_curves_are_the_surface_along_the_line() {
    let mut rng = Rng::new(4);
    for surface in [nurbs(), bicubic(None), bicubic(Some(&WEIGHTS))] {
        let (u0, u1) = surface.knots_u().domain();
        let (v0, v1) = surface.knots_v().domain();
        for _ in 0..10 {
            let (u, v) = (rng.range(u0, u1), rng.range(v0, v1));
            let cu = surface.iso_curve_u(u).unwrap();
            let cv = surface.iso_curve_v(v).unwrap();
            assert_eq!(cu.is_rational(), surface.is_rational());
            assert_eq!(
                (cu.degree(), cv.degree()),
                (surface.degree_v(), surface.degree_u())
            );
            assert_eq!(cu.knots(), surface.knots_v());
            assert_eq!(cv.knots(), surface.knots_u());
            for k in 0..=10 {
                let t = k as f64 / 10.0;
                let (tu, tv) = (u0 + (u1 - u0) * t, v0 + (v1 - v0) * t);
                assert_close3(
                    cu.evaluate(tv).unwrap(),
                    surface.evaluate(u, tv).unwrap(),
                    1e-13,
                    "S(u, ·)",
                );
                assert_close3(
                    cv.evaluate(tu).unwrap(),
                    surface.evaluate(tu, v).unwrap(),
                    1e-13,
                    "S(·, v)",
                );
            }
        }
    }
    assert!(nurbs().iso_curve_u(1.5).is_err());
    assert!(nurbs().iso_curve_v(1.0).is_err());
}

#[test]
fn batched_curvatures_equal_the_single_call() {
    // The batched kernel (its own basis derivatives and quotient rule) against curvature(u, v)
    // (A2.3 and A4.4): NURBS 3 × 2 with a double knot in u, and a bilinear 1 × 1 patch.
    let mut rng = Rng::new(13);
    let coords: Vec<f64> = (0..30).flat_map(|_| rng.point3(3.0).to_array()).collect();
    let weights: Vec<f64> = (0..30).map(|_| rng.range(0.5, 2.0)).collect();
    let double_knot = BSplineSurface::from_flat(
        &coords,
        6,
        5,
        3,
        2,
        vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0],
        vec![0.0, 0.0, 0.0, 0.2, 0.7, 1.0, 1.0, 1.0],
        Some(&weights),
    )
    .unwrap();
    let bilinear = BSplineSurface::bezier(
        &[0.0, 0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 0.0, -0.5, 1.0, 1.0, 1.0],
        2,
        2,
        None,
    )
    .unwrap();
    for surface in [double_knot, bilinear, nurbs(), bicubic(Some(&WEIGHTS))] {
        let (u0, u1) = surface.knots_u().domain();
        let (v0, v1) = surface.knots_v().domain();
        let mut uvs: Vec<f64> = (0..200)
            .flat_map(|_| [rng.range(u0, u1), rng.range(v0, v1)])
            .collect();
        uvs.extend([u0, v0, u1, v1, 0.5 * (u0 + u1), v1]);
        let mut out = Vec::new();
        surface.curvatures_into(&uvs, &mut out).unwrap();
        assert_eq!(out.len(), uvs.len());
        for (pair, kh) in uvs.chunks(2).zip(out.chunks(2)) {
            let [k, h] = surface.curvature(pair[0], pair[1]).unwrap();
            let scale = 1.0 + k.abs() + h.abs();
            assert_close(kh[0], k, 1e-9 * scale * scale, &format!("K at {pair:?}"));
            assert_close(kh[1], h, 1e-9 * scale, &format!("H at {pair:?}"));
        }
    }
}

/// The circle or arc `center + cos θ a + sin θ b`, θ from `start` over `sweep`, as an exact NURBS.
fn arc(center: DVec3, a: DVec3, b: DVec3, start: f64, sweep: f64) -> BSplineCurve<DVec3> {
    ellipse_arc(center, a, b, start, sweep).unwrap()
}

#[test]
fn a_revolved_half_circle_is_a_sphere() {
    let r = 2.5;
    // From the south pole to the north pole through (r, 0, 0), in the xz plane.
    let profile = arc(
        DVec3::ZERO,
        DVec3::new(r, 0.0, 0.0),
        DVec3::new(0.0, 0.0, r),
        -FRAC_PI_2,
        PI,
    );
    let sphere = revolve(&profile, DVec3::ZERO, DVec3::Z, TAU).unwrap();
    assert_eq!((sphere.rows(), sphere.degree_u()), (9, 2));
    let mut rng = Rng::new(5);
    for _ in 0..100 {
        let (u, v) = (rng.range(0.0, 1.0), rng.range(0.02, 0.98));
        let p = sphere.evaluate(u, v).unwrap();
        assert_close(p.length(), r, 1e-12, "on the sphere");
        let [k, h] = sphere.curvature(u, v).unwrap();
        assert_close(k, 1.0 / (r * r), 1e-12, "K = 1/r²");
        assert_close(h.abs(), 1.0 / r, 1e-12, "|H| = 1/r");
        // H's sign goes with the normal: towards the centre means H > 0.
        let n = sphere.normal(u, v).unwrap();
        assert_eq!(h > 0.0, n.dot(p) < 0.0, "sign of H with the normal");
    }
    // At a pole S_u = 0: the single call names (u, v), the batched form writes NaN.
    let e = sphere.curvature(0.3, 0.0).unwrap_err();
    assert_eq!(e.code(), "no-normal");
    assert!(e.to_string().contains("(u, v) = (0.3, 0)"), "{e}");
    let mut out = Vec::new();
    sphere
        .curvatures_into(&[0.3, 0.0, 0.3, 0.5], &mut out)
        .unwrap();
    assert!(out[0].is_nan() && out[1].is_nan());
    assert_close(out[2], 1.0 / (r * r), 1e-12, "batched K");
}

#[test]
fn curvature_of_a_plane_and_of_a_cylinder() {
    // A plane: a bicubic net on a tilted plane z = x − 2y, bent parametrisation.
    let coords: Vec<f64> = (0..4)
        .flat_map(|i| {
            (0..4).flat_map(move |j| {
                let (x, y) = (
                    i as f64 + 0.3 * (j * j) as f64,
                    j as f64 - 0.2 * (i * i) as f64,
                );
                [x, y, x - 2.0 * y]
            })
        })
        .collect();
    let plane = BSplineSurface::bezier(&coords, 4, 4, None).unwrap();
    let mut out = Vec::new();
    let uvs: Vec<f64> = (0..=10)
        .flat_map(|k| [k as f64 / 10.0, 1.0 - k as f64 / 10.0])
        .collect();
    plane.curvatures_into(&uvs, &mut out).unwrap();
    for (i, kh) in out.chunks(2).enumerate() {
        assert_close(kh[0], 0.0, 1e-12, &format!("plane K at {i}"));
        assert_close(kh[1], 0.0, 1e-12, &format!("plane H at {i}"));
    }
    // A cylinder: the circle of radius r extruded along its axis.
    let r = 0.75;
    let circle = arc(
        DVec3::new(1.0, -2.0, 0.5),
        DVec3::new(r, 0.0, 0.0),
        DVec3::new(0.0, r, 0.0),
        0.0,
        TAU,
    );
    let cylinder = extrude(&circle, DVec3::new(0.0, 0.0, 3.0)).unwrap();
    let mut rng = Rng::new(6);
    for _ in 0..50 {
        let (u, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        let [k, h] = cylinder.curvature(u, v).unwrap();
        assert_close(k, 0.0, 1e-12, "cylinder K");
        assert_close(h.abs(), 1.0 / (2.0 * r), 1e-12, "cylinder |H| = 1/(2r)");
    }
}

#[test]
fn a_revolved_circle_lies_on_the_torus() {
    let (big_r, r) = (3.0, 1.0);
    // The circle of radius r about (R, 0, 0) in the xz plane, from the outer equator.
    let circle = arc(
        DVec3::new(big_r, 0.0, 0.0),
        DVec3::new(r, 0.0, 0.0),
        DVec3::new(0.0, 0.0, r),
        0.0,
        TAU,
    );
    for (angle, rows) in [(TAU, 9), (1.0, 3), (2.0, 5), (4.0, 7), (5.0, 9)] {
        let torus = revolve(&circle, DVec3::ZERO, DVec3::Z, angle).unwrap();
        assert_eq!(torus.rows(), rows, "arcs for angle {angle}");
        let mut rng = Rng::new(7);
        for _ in 0..200 {
            let (u, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
            let p = torus.evaluate(u, v).unwrap();
            // (√(x² + y²) − R)² + z² = r².
            let distance = ((p.x.hypot(p.y) - big_r).powi(2) + p.z * p.z).sqrt();
            assert_close(distance, r, 1e-12, "on the torus");
        }
        // u = 1 is the profile turned by the whole angle.
        let end = torus.evaluate(1.0, 0.0).unwrap();
        assert_close3(
            end,
            DVec3::new(big_r + r, 0.0, 0.0).rotate_axis_z(angle),
            1e-12,
            "turned by angle",
        );
    }
    let torus = revolve(&circle, DVec3::ZERO, DVec3::Z, TAU).unwrap();
    for u in [0.0, 0.1, 0.37, 0.5, 0.9] {
        let [k, _] = torus.curvature(u, 0.0).unwrap();
        assert_close(k, 1.0 / (r * (big_r + r)), 1e-12, "K at the outer equator");
        let [k, _] = torus.curvature(u, 0.5).unwrap();
        assert_close(k, -1.0 / (r * (big_r - r)), 1e-12, "K at the inner equator");
    }
}

trait RotateZ {
    fn rotate_axis_z(self, angle: f64) -> Self;
}

impl RotateZ for DVec3 {
    fn rotate_axis_z(self, angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        DVec3::new(c * self.x - s * self.y, s * self.x + c * self.y, self.z)
    }
}

#[test]
fn revolving_about_a_tilted_axis_keeps_distances_to_it() {
    // A cubic B-spline profile (polynomial) about the axis through (1, 2, 3) along (1, 1, 0):
    // every point of row u stays at the profile point's distance from the axis and height along it.
    let profile = BSplineCurve::new(
        vec![
            DVec3::new(2.0, 0.0, 3.0),
            DVec3::new(3.0, 1.0, 5.0),
            DVec3::new(1.0, -1.0, 6.0),
            DVec3::new(4.0, 0.0, 7.0),
            DVec3::new(0.5, 0.5, 9.0),
        ],
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.6, 1.5, 1.5, 1.5, 1.5],
        None,
    )
    .unwrap();
    let (o, d) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(1.0, 1.0, 0.0));
    let axis = d.normalize();
    let surface = revolve(&profile, o, d, 3.0).unwrap();
    assert!(surface.is_rational());
    assert_eq!(surface.knots_v(), profile.knots());
    let mut rng = Rng::new(8);
    for _ in 0..100 {
        let (u, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.5));
        let (p, q) = (
            surface.evaluate(u, v).unwrap(),
            profile.evaluate(v).unwrap(),
        );
        let along = |x: DVec3| (x - o).dot(axis);
        let radius = |x: DVec3| (x - o - axis * along(x)).length();
        assert_close(along(p), along(q), 1e-12, "height along the axis");
        assert_close(radius(p), radius(q), 1e-12, "distance from the axis");
        assert_close3(
            surface.evaluate(0.0, v).unwrap(),
            q,
            1e-12,
            "u = 0 is the profile",
        );
    }
}

/// A non-uniform cubic B-spline on [0, 2].
fn cubic_a() -> BSplineCurve<DVec3> {
    BSplineCurve::new(
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 2.0, 0.5),
            DVec3::new(2.5, 1.0, -0.5),
            DVec3::new(4.0, 3.0, 1.0),
            DVec3::new(5.0, 0.0, 0.0),
            DVec3::new(6.0, 1.0, 2.0),
        ],
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.25, 2.0, 2.0, 2.0, 2.0],
        None,
    )
    .unwrap()
}

/// A quadratic B-spline on [1, 3] with an interior knot at 2 (normalised ½).
fn quadratic_b() -> BSplineCurve<DVec3> {
    BSplineCurve::new(
        vec![
            DVec3::new(0.0, 0.0, 4.0),
            DVec3::new(2.0, -1.0, 5.0),
            DVec3::new(4.0, 2.0, 4.5),
            DVec3::new(6.0, 0.0, 6.0),
        ],
        2,
        vec![1.0, 1.0, 1.0, 2.0, 3.0, 3.0, 3.0],
        None,
    )
    .unwrap()
}

#[test]
fn extrusion_is_the_curve_plus_v_times_the_direction() {
    let d = DVec3::new(0.5, -1.0, 2.0);
    let a = cubic_a();
    let s = extrude(&a, d).unwrap();
    assert_eq!(
        (s.rows(), s.cols(), s.degree_u(), s.degree_v()),
        (6, 2, 3, 1)
    );
    let circle = arc(DVec3::ZERO, DVec3::X, DVec3::Y, 0.3, 4.0);
    let sc = extrude(&circle, d).unwrap();
    let mut rng = Rng::new(9);
    for _ in 0..100 {
        let (u, v) = (rng.range(0.0, 2.0), rng.range(0.0, 1.0));
        assert_close3(
            s.evaluate(u, v).unwrap(),
            a.evaluate(u).unwrap() + v * d,
            1e-12,
            "C(u) + v d",
        );
        let t = u / 2.0;
        assert_close3(
            sc.evaluate(t, v).unwrap(),
            circle.evaluate(t).unwrap() + v * d,
            1e-12,
            "rational",
        );
    }
}

#[test]
fn a_ruled_surface_interpolates_linearly_between_its_curves() {
    let (a, b) = (cubic_a(), quadratic_b());
    let s = ruled(&a, &b).unwrap();
    assert_eq!((s.degree_u(), s.degree_v(), s.cols()), (3, 1, 2));
    assert_eq!(s.knots_u().domain(), (0.0, 1.0));
    let mut rng = Rng::new(10);
    for _ in 0..200 {
        let (t, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        let (pa, pb) = (
            a.evaluate(2.0 * t).unwrap(),
            b.evaluate(1.0 + 2.0 * t).unwrap(),
        );
        assert_close3(
            s.evaluate(t, v).unwrap(),
            (1.0 - v) * pa + v * pb,
            1e-12,
            "(1 − v) A + v B",
        );
    }
    // The other way round gives the same net with the columns swapped.
    let swapped = ruled(&b, &a).unwrap();
    assert_close3(
        swapped.evaluate(0.3, 0.25).unwrap(),
        s.evaluate(0.3, 0.75).unwrap(),
        1e-12,
        "swap",
    );
}

#[test]
fn a_ruled_surface_raises_a_curve_with_a_break_piece_by_piece() {
    // A quadratic with a triple knot at 1 (a corner where the curve may jump) against the
    // cubic: the degree is raised on each side of the break.
    let broken = BSplineCurve::new(
        vec![
            DVec3::new(0.0, 0.0, 3.0),
            DVec3::new(1.0, 1.0, 3.0),
            DVec3::new(2.0, 0.0, 3.5),
            DVec3::new(2.5, -1.0, 3.0),
            DVec3::new(3.0, 0.5, 4.0),
            DVec3::new(4.0, 0.0, 3.0),
        ],
        2,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0],
        None,
    )
    .unwrap();
    let a = cubic_a();
    let s = ruled(&a, &broken).unwrap();
    assert_eq!(s.degree_u(), 3);
    let mut rng = Rng::new(12);
    for _ in 0..200 {
        let (t, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        let (pa, pb) = (
            a.evaluate(2.0 * t).unwrap(),
            broken.evaluate(2.0 * t).unwrap(),
        );
        assert_close3(
            s.evaluate(t, v).unwrap(),
            (1.0 - v) * pa + v * pb,
            1e-12,
            "(1 − v) A + v B",
        );
    }
}

#[test]
fn a_ruled_surface_between_a_closed_b_spline_and_a_circle() {
    // An unclamped (closed, uniform knots) cubic and a rational circle: the rulings join A(u)
    // to B(u) — ends exact, every point on the segment.
    let a = BSplineCurve::closed(
        vec![
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.5, 0.2),
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(0.0, -1.0, -0.3),
        ],
        3,
        None,
    )
    .unwrap();
    let b = arc(DVec3::new(0.0, 0.0, 2.0), DVec3::X, DVec3::Y, 0.0, TAU);
    let s = ruled(&a, &b).unwrap();
    assert!(s.is_rational());
    let (a0, a1) = a.domain();
    let mut rng = Rng::new(11);
    for _ in 0..100 {
        let (t, v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        let pa = a.evaluate(a0 + (a1 - a0) * t).unwrap();
        let pb = b.evaluate(t).unwrap();
        assert_close3(s.evaluate(t, 0.0).unwrap(), pa, 1e-12, "v = 0 is A");
        assert_close3(s.evaluate(t, 1.0).unwrap(), pb, 1e-12, "v = 1 is B");
        let p = s.evaluate(t, v).unwrap();
        let off_line = (p - pa).cross(pb - pa).length() / (pb - pa).length();
        assert_close(off_line, 0.0, 1e-12, "on the segment");
    }
}

/// A 6 × 5 grid of points over a wavy sheet.
fn grid() -> Vec<f64> {
    (0..6)
        .flat_map(|i| {
            (0..5).flat_map(move |j| {
                let (x, y) = (
                    i as f64 + 0.1 * (j as f64).powi(2),
                    1.3 * j as f64 + 0.05 * (i * i) as f64,
                );
                [x, y, (0.7 * x).sin() * (0.5 * y).cos()]
            })
        })
        .collect()
}

#[test]
fn interpolate_surface_passes_through_every_grid_point() {
    let points = grid();
    for kind in [
        Parameterization::Uniform,
        Parameterization::Chord,
        Parameterization::Centripetal,
    ] {
        for (p, q) in [(3, 2), (1, 1), (5, 4), (2, 3)] {
            let s = interpolate_surface(&points, 6, 5, p, q, kind).unwrap();
            assert_eq!(
                (s.rows(), s.cols(), s.degree_u(), s.degree_v()),
                (6, 5, p, q)
            );
            // The parameters, recomputed here: per column steps |Δ|^α over their total,
            // averaged over the columns (likewise rows for v).
            let alpha = kind.alpha();
            let at = |i: usize, j: usize| DVec3::from_slice(&points[3 * (i * 5 + j)..]);
            let params = |n: usize, lines: usize, pt: &dyn Fn(usize, usize) -> DVec3| -> Vec<f64> {
                let mut avg = vec![0.0; n];
                for l in 0..lines {
                    let steps: Vec<f64> = (1..n)
                        .map(|k| (pt(k, l) - pt(k - 1, l)).length().powf(alpha))
                        .collect();
                    let total: f64 = steps.iter().sum();
                    let mut c = 0.0;
                    for k in 0..n {
                        if k > 0 {
                            c += steps[k - 1];
                        }
                        avg[k] += c / total / lines as f64;
                    }
                }
                avg
            };
            let us = params(6, 5, &|k, l| at(k, l));
            let vs = params(5, 6, &|k, l| at(l, k));
            for (i, &u) in us.iter().enumerate() {
                for (j, &v) in vs.iter().enumerate() {
                    assert_close3(
                        s.evaluate(u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)).unwrap(),
                        at(i, j),
                        1e-10,
                        &format!("{kind} degrees {p}×{q}, point ({i}, {j})"),
                    );
                }
            }
        }
    }
}

// --- scipy fixture (tests/fixtures/make_surface_interp_fixtures.py). ----------------------------

#[test]
fn interpolate_surface_matches_scipy() {
    let text = include_str!("fixtures/surface_interp_scipy.txt");
    let mut checked = 0;
    let mut lines = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .peekable();
    while let Some(header) = lines.next() {
        let words: Vec<&str> = header.split_whitespace().collect();
        assert_eq!(words[0], "case");
        let kind = Parameterization::parse(words[1]).unwrap();
        let n: Vec<usize> = words[2..6].iter().map(|w| w.parse().unwrap()).collect();
        let (p, q, rows, cols) = (n[0], n[1], n[2], n[3]);
        let mut record = |tag: &str| -> Vec<f64> {
            let line = lines.next().unwrap();
            let mut words = line.split_whitespace();
            assert_eq!(words.next(), Some(tag));
            words.map(|w| w.parse().unwrap()).collect()
        };
        let (points, knots_u, knots_v, control) = (
            record("points"),
            record("knotsu"),
            record("knotsv"),
            record("control"),
        );
        let what = format!("{} {p}×{q} on {rows}×{cols}", words[1]);
        let s = interpolate_surface(&points, rows, cols, p, q, kind).unwrap();
        for (ours, theirs) in [
            (s.knots_u().as_slice(), &knots_u),
            (s.knots_v().as_slice(), &knots_v),
        ] {
            assert_eq!(ours.len(), theirs.len(), "{what}: knots");
            for (a, b) in ours.iter().zip(theirs.iter()) {
                assert_close(*a, *b, 1e-14, &format!("{what}: knot"));
            }
        }
        for (k, (a, b)) in s.control_points().iter().zip(control.chunks(3)).enumerate() {
            assert_close3(*a, DVec3::from_slice(b), 1e-11, &format!("{what}: P_{k}"));
            checked += 1;
        }
        while lines.peek().is_some_and(|l| l.starts_with("value")) {
            let v: Vec<f64> = lines
                .next()
                .unwrap()
                .split_whitespace()
                .skip(1)
                .map(|w| w.parse().unwrap())
                .collect();
            assert_close3(
                s.evaluate(v[0], v[1]).unwrap(),
                DVec3::new(v[2], v[3], v[4]),
                1e-11,
                &format!("{what}: S({}, {})", v[0], v[1]),
            );
            checked += 1;
        }
    }
    assert!(checked > 200, "checked {checked}");
}
