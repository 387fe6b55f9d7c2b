//! Rational curves: conics, exact circles and ellipses, projective invariance, and fixtures
//! from an independent homogeneous evaluation (`tests/fixtures/make_nurbs_fixtures.py`).

mod common;

use common::*;
use splinelab::bezier::BezierCurve;
use splinelab::bspline::BSplineCurve;
use splinelab::prelude::*;
use splinelab::rational::{self, ConicKind};
use splinelab::{DVec2, DVec3};
use std::f64::consts::{FRAC_1_SQRT_2, PI, TAU};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

fn circle(center: DVec2, r: f64, start: f64, sweep: f64) -> BSplineCurve<DVec2> {
    rational::ellipse_arc(center, DVec2::new(r, 0.0), DVec2::new(0.0, r), start, sweep).unwrap()
}

#[test]
fn full_circle_is_the_syllabus_nurbs_and_exactly_round() {
    let c = circle(DVec2::new(2.0, -1.0), 3.0, 0.0, TAU);
    assert_eq!(
        c.knots().as_slice(),
        &[0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0]
    );
    let w = c.weights();
    assert_eq!(w.len(), 9);
    for (i, &wi) in w.iter().enumerate() {
        assert_close(
            wi,
            if i % 2 == 0 { 1.0 } else { FRAC_1_SQRT_2 },
            1e-15,
            "weight",
        );
    }
    let mut out = vec![0.0; 2 * 2001];
    c.sample_uniform_into(2001, &mut out).unwrap();
    for p in out.chunks(2) {
        assert_close(
            (DVec2::new(p[0], p[1]) - DVec2::new(2.0, -1.0)).length(),
            3.0,
            1e-12 * 3.0,
            "radius",
        );
    }
    for k in 0..40 {
        let u = k as f64 / 40.0;
        assert_close(c.curvature(u).unwrap(), 1.0 / 3.0, 1e-12, "curvature 1/r");
    }
}

#[test]
fn arcs_of_any_sweep_are_exact_and_end_where_they_should() {
    for (start, sweep, pieces) in [
        (0.3, 0.5, 1),
        (0.0, PI / 2.0, 1),
        (1.0, 200f64.to_radians(), 3),
        (2.0, -135f64.to_radians(), 2),
        (-1.0, TAU, 4),
    ] {
        let c = circle(DVec2::ZERO, 1.5, start, sweep);
        assert_eq!(c.control_points().len(), 2 * pieces + 1, "sweep {sweep}");
        let (a, b) = c.domain();
        assert_close2(
            c.evaluate(a).unwrap(),
            DVec2::new(start.cos(), start.sin()) * 1.5,
            1e-14,
            "start",
        );
        assert_close2(
            c.evaluate(b).unwrap(),
            DVec2::new((start + sweep).cos(), (start + sweep).sin()) * 1.5,
            1e-14,
            "end",
        );
        for k in 0..=200 {
            let p = c.evaluate(k as f64 / 200.0).unwrap();
            assert_close(p.length(), 1.5, 1.5e-12, "on the circle");
        }
        // The arc turns the right way: the signed curvature has the sign of the sweep.
        assert_close(
            c.curvature(0.5).unwrap(),
            sweep.signum() / 1.5,
            1e-12,
            "signed curvature",
        );
    }
    assert!(rational::ellipse_arc(DVec2::ZERO, DVec2::X, DVec2::Y, 0.0, 0.0).is_err());
    assert!(rational::ellipse_arc(DVec2::ZERO, DVec2::X, DVec2::Y, 0.0, 7.0).is_err());
    assert!(rational::ellipse_arc(DVec2::ZERO, DVec2::X, DVec2::X * 2.0, 0.0, 1.0).is_err());
}

#[test]
fn ellipses_and_3d_circles_are_exact() {
    // A rotated ellipse: semi-axes 4 and 1.5 at 30°.
    let (rx, ry, phi) = (4.0, 1.5, PI / 6.0);
    let ex = DVec2::new(phi.cos(), phi.sin());
    let ey = DVec2::new(-phi.sin(), phi.cos());
    let c = rational::ellipse_arc(DVec2::new(1.0, 2.0), ex * rx, ey * ry, 0.0, TAU).unwrap();
    for k in 0..=400 {
        let q = c.evaluate(k as f64 / 400.0).unwrap() - DVec2::new(1.0, 2.0);
        let (x, y) = (q.dot(ex) / rx, q.dot(ey) / ry);
        assert_close(x * x + y * y, 1.0, 1e-12, "on the ellipse");
    }
    // A circle of radius 2 in the plane x + y + z = 0 around (1, 1, 1).
    let u = DVec3::new(1.0, -1.0, 0.0).normalize() * 2.0;
    let v = DVec3::new(1.0, 1.0, -2.0).normalize() * 2.0;
    let c3 = rational::ellipse_arc(DVec3::ONE, u, v, 0.0, TAU).unwrap();
    for k in 0..=100 {
        let p = c3.evaluate(k as f64 / 100.0).unwrap() - DVec3::ONE;
        assert_close(p.length(), 2.0, 2e-12, "3D radius");
        assert_close(p.dot(DVec3::ONE), 0.0, 1e-12, "in the plane");
    }
}

#[test]
fn conics_are_classified_by_the_middle_weight() {
    assert_eq!(
        rational::conic_kind(1.0, 0.5, 1.0).unwrap(),
        ConicKind::Ellipse
    );
    assert_eq!(
        rational::conic_kind(1.0, 1.0, 1.0).unwrap(),
        ConicKind::Parabola
    );
    assert_eq!(
        rational::conic_kind(1.0, 2.0, 1.0).unwrap(),
        ConicKind::Hyperbola
    );
    // Only the shape factor w1²/(w0 w2) matters.
    assert_eq!(
        rational::conic_kind(4.0, 2.0, 1.0).unwrap(),
        ConicKind::Parabola
    );
    assert_eq!(
        rational::conic_kind(4.0, 1.9, 1.0).unwrap(),
        ConicKind::Ellipse
    );
    assert!(rational::conic_kind(1.0, 0.0, 1.0)
        .unwrap_err()
        .to_string()
        .contains("weight 1 is 0"));
    // A parabola (w1 = 1) is the polynomial quadratic; a hyperbola branch satisfies its
    // implicit equation: the quadratic with P0=(1,0), P1=(0,0), P2=(0,1) and w1 = k lies on
    // the conic x·y·4k² = (1 − x − y)² (the standard implicit form of the rational quadratic).
    for k in [0.5, 1.0, 2.0, 3.0] {
        let c = BezierCurve::new(
            pts2(&[(1.0, 0.0), (0.0, 0.0), (0.0, 1.0)]),
            Some(&[1.0, k, 1.0]),
        )
        .unwrap();
        for j in 0..=20 {
            let p = c.evaluate(j as f64 / 20.0).unwrap();
            assert_close(
                4.0 * k * k * p.x * p.y,
                (1.0 - p.x - p.y).powi(2),
                1e-13,
                "implicit conic",
            );
        }
    }
}

#[test]
fn isosceles_triangles_give_circular_arcs() {
    let q = rational::circle_arc_from_triangle(
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    )
    .unwrap();
    assert_close(
        q.weights()[1],
        FRAC_1_SQRT_2,
        1e-15,
        "quarter circle weight",
    );
    // A 120° arc: the angle at P1 is 60°, so w1 = sin 30° = 1/2. Centre where the normals at
    // the ends meet: for P0 = (−√3, 0), P1 = (0, 1)·… take an equilateral triangle.
    let (p0, p1, p2) = (
        DVec2::new(-3f64.sqrt(), 0.0),
        DVec2::new(0.0, 3.0),
        DVec2::new(3f64.sqrt(), 0.0),
    );
    let arc = rational::circle_arc_from_triangle(p0, p1, p2).unwrap();
    assert_close(arc.weights()[1], 0.5, 1e-15, "w1 = sin 30°");
    // The normal at P0 is perpendicular to P1 − P0; by symmetry the centre is on x = 0.
    let dir = (p1 - p0).perp();
    let center = p0 + dir * (-p0.x / dir.x);
    let r = (p0 - center).length();
    for k in 0..=50 {
        assert_close(
            (arc.evaluate(k as f64 / 50.0).unwrap() - center).length(),
            r,
            1e-12,
            "on the circle",
        );
    }
    // A sharp angle at P1: θ = 2·atan(1e-6), so w1 = sin(θ/2) = 1e-6/√(1 + 1e-12). Through
    // acos(cos θ) this lost five digits (cos θ = 1 − 2e-12).
    let sharp = rational::circle_arc_from_triangle(
        DVec2::new(1.0, 1e-6),
        DVec2::ZERO,
        DVec2::new(1.0, -1e-6),
    )
    .unwrap();
    let expected = 1e-6 / (1.0 + 1e-12f64).sqrt();
    assert_close(
        sharp.weights()[1],
        expected,
        1e-9 * expected,
        "w1 of a sharp angle",
    );
    assert!(rational::circle_arc_from_triangle(
        DVec2::ZERO,
        DVec2::new(1.0, 1.0),
        DVec2::new(3.0, 0.0)
    )
    .unwrap_err()
    .to_string()
    .contains("isosceles"));
    assert!(rational::circle_arc_from_triangle(DVec2::ZERO, DVec2::X, DVec2::X * 2.0).is_err());
}

#[test]
fn projective_maps_map_the_curve() {
    // A perspective map with no weight crossing zero on this curve.
    let m = glam::DMat3::from_cols_array(&[1.0, 0.2, 0.1, -0.3, 0.9, 0.05, 2.0, 1.0, 1.0]);
    let apply = |p: DVec2| {
        let h = m * p.extend(1.0);
        h.truncate() / h.z
    };
    let bez = BezierCurve::new(
        pts2(&[(0.0, 0.0), (1.0, 2.0), (3.0, 2.5), (4.0, 0.0)]),
        Some(&[1.0, 2.0, 0.5, 1.0]),
    )
    .unwrap();
    let mapped = rational::projective_map_bezier(&bez, &m).unwrap();
    let nurbs = circle(DVec2::new(1.0, 1.0), 1.0, 0.0, TAU);
    let mapped_nurbs = rational::projective_map_bspline(&nurbs, &m).unwrap();
    for k in 0..=50 {
        let t = k as f64 / 50.0;
        assert_close2(
            mapped.evaluate(t).unwrap(),
            apply(bez.evaluate(t).unwrap()),
            1e-12,
            "Bézier image",
        );
        assert_close2(
            mapped_nurbs.evaluate(t).unwrap(),
            apply(nurbs.evaluate(t).unwrap()),
            1e-12,
            "NURBS image",
        );
    }
    // An affine map leaves the weights alone (polynomial stays polynomial).
    let affine = glam::DMat3::from_cols_array(&[2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0]);
    let poly = BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]), None).unwrap();
    assert!(!rational::projective_map_bezier(&poly, &affine)
        .unwrap()
        .is_rational());
    // A map that sends a control point across the line at infinity is refused.
    let flip = glam::DMat3::from_cols_array(&[1.0, 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
    let e = rational::projective_map_bezier(&bez, &flip)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("control point 1 to weight 0") && e.contains("weights must stay > 0"),
        "{e}"
    );
}

#[test]
fn rational_operations_keep_the_shape() {
    let c = circle(DVec2::ZERO, 1.0, 0.0, TAU);
    let r = c.insert_knot(0.1, 2).unwrap().refine(&[0.6, 0.9]).unwrap();
    for seg in r.to_bezier().unwrap() {
        let e = seg.elevate().unwrap();
        let (l, rt) = e.split(0.3).unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            for curve in [&seg, &e, &l, &rt] {
                assert_close(
                    curve.evaluate(t).unwrap().length(),
                    1.0,
                    1e-12,
                    "still on the circle",
                );
            }
        }
    }
}

#[test]
fn fixtures_from_homogeneous_scipy_evaluation() {
    let text = include_str!("fixtures/nurbs_scipy.txt");
    let mut curve: Option<BSplineCurve<DVec2>> = None;
    let mut checked = 0;
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let mut words = line.split_whitespace();
        let tag = words.next().unwrap();
        let nums: Vec<f64> = words.map(|w| w.parse().unwrap()).collect();
        match tag {
            "curve" => {
                let (p, count) = (nums[0] as usize, nums[1] as usize);
                let knots = nums[2..2 + count + p + 1].to_vec();
                let rows = &nums[2 + count + p + 1..];
                let pts: Vec<DVec2> = rows.chunks(3).map(|r| DVec2::new(r[0], r[1])).collect();
                let w: Vec<f64> = rows.chunks(3).map(|r| r[2]).collect();
                curve = Some(BSplineCurve::new(pts, p, knots, Some(&w)).unwrap());
            }
            "eval" => {
                let c = curve.as_ref().unwrap();
                let got = c.derivative(nums[0], nums[1] as usize).unwrap();
                let scale = 1.0 + nums[2].abs().max(nums[3].abs());
                assert_close2(
                    got,
                    DVec2::new(nums[2], nums[3]),
                    1e-11 * scale,
                    &format!("order {} at u = {}", nums[1], nums[0]),
                );
                checked += 1;
            }
            other => panic!("unknown fixture line {other}"),
        }
    }
    assert!(checked >= 150, "only {checked} fixture values");
}

#[test]
fn rational_bernstein_basis_by_hand() {
    // The weights demo's default: weights 1, 3, 1, 1 at t = 1/2, B = 1/8, 3/8, 3/8, 1/8:
    // w_i B_i = 1/8, 9/8, 3/8, 1/8, Σ = 14/8, so R = 1/14, 9/14, 3/14, 1/14, and
    // Σ R_i P_i = (13/7, 18/7) (the hand-computed point of tests/e2e/checks/weights.mjs).
    let pts = pts2(&[(0.0, 0.0), (1.0, 3.0), (4.0, 3.0), (5.0, 0.0)]);
    let c = BezierCurve::new(pts.clone(), Some(&[1.0, 3.0, 1.0, 1.0])).unwrap();
    let r = c.rational_basis(0.5).unwrap();
    let expected = [1.0 / 14.0, 9.0 / 14.0, 3.0 / 14.0, 1.0 / 14.0];
    for (i, (&got, want)) in r.iter().zip(expected).enumerate() {
        assert!(
            (got - want).abs() < 1e-15,
            "R_{i}(1/2) = {got}, expected {want}"
        );
    }
    let point = pts
        .iter()
        .zip(&r)
        .fold(DVec2::ZERO, |acc, (&p, &ri)| acc + p * ri);
    assert!((point - DVec2::new(13.0 / 7.0, 18.0 / 7.0)).length() < 1e-14);
    // Ends: R_0(0) = 1 and R_3(1) = 1 whatever the weights.
    assert_eq!(c.rational_basis(0.0).unwrap(), vec![1.0, 0.0, 0.0, 0.0]);
    assert_eq!(c.rational_basis(1.0).unwrap(), vec![0.0, 0.0, 0.0, 1.0]);
    // The quarter circle: weights 1, √2/2, 1 at t = 1/2 give 1, √2, 1 over 2 + √2.
    let q = BezierCurve::new(
        pts2(&[(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]),
        Some(&[1.0, FRAC_1_SQRT_2, 1.0]),
    )
    .unwrap();
    let r = q.rational_basis(0.5).unwrap();
    let d = 2.0 + 2f64.sqrt();
    for (got, want) in r.iter().zip([1.0 / d, 2f64.sqrt() / d, 1.0 / d]) {
        assert!((got - want).abs() < 1e-15, "{got} vs {want}");
    }
    // A polynomial curve: the Bernstein values (t = 1/4: 27/64, 27/64, 9/64, 1/64).
    let p = BezierCurve::new(pts, None).unwrap();
    assert_eq!(
        p.rational_basis(0.25).unwrap(),
        vec![27.0 / 64.0, 27.0 / 64.0, 9.0 / 64.0, 1.0 / 64.0]
    );
    assert!(c.rational_basis(1.5).is_err());
    assert!(c.rational_basis(f64::NAN).is_err());
}

/// The negative-weights demo's triangle with weights 1, w1, 1.
fn negative_weights_poles(w1: f64, count: usize) -> rational::RationalPoles<DVec2> {
    let pts = pts2(&[(0.0, 0.0), (2.0, 3.0), (4.0, 0.0)]);
    rational::rational_poles(&pts, &[1.0, w1, 1.0], count).unwrap()
}

#[test]
fn rational_poles_of_the_quadratic_by_hand() {
    // w(t) = (1−t)² + 2w₁t(1−t) + t² = 1 − 2(1 − w₁)t(1 − t) is 0 where t(1−t) = 1/(2(1 − w₁)):
    // w₁ = −2: t = 1/2 ± √3/6; w₁ = −1.5: t = 1/2 ± √5/10; w₁ > −1: never.
    for (w1, half_gap) in [(-2.0, 3f64.sqrt() / 6.0), (-1.5, 5f64.sqrt() / 10.0)] {
        let poles = negative_weights_poles(w1, 5);
        assert_eq!(poles.roots.len(), 2, "w1 = {w1}: {:?}", poles.roots);
        assert_close(poles.roots[0], 0.5 - half_gap, 1e-14, "first pole");
        assert_close(poles.roots[1], 0.5 + half_gap, 1e-14, "second pole");
        // The numerator there: N = 2t(1−t)w₁P₁ + t²P₂ with t(1−t) = 1/(2(1 − w₁)).
        for (&t0, d) in poles.roots.iter().zip(&poles.directions) {
            let s = 1.0 / (2.0 * (1.0 - w1));
            let n = DVec2::new(2.0, 3.0) * (2.0 * s * w1) + DVec2::new(4.0, 0.0) * (t0 * t0);
            assert_close2(*d, n / n.length(), 1e-12, "pole direction");
        }
    }
    for w1 in [-0.5, 0.0, 1.0, 3.0] {
        let poles = negative_weights_poles(w1, 3);
        assert!(
            poles.roots.is_empty() && poles.directions.is_empty(),
            "w1 = {w1}"
        );
    }
    // w₁ = −1: w(t) = (1 − 2t)² touches 0 once, at 1/2, where N = (P₀ − 2P₁ + P₂)/4 = (0, −3/2).
    let poles = negative_weights_poles(-1.0, 3);
    assert_eq!(poles.roots, vec![0.5]);
    assert_eq!(poles.directions, vec![DVec2::new(0.0, -1.0)]);
    // Samples at t = 0, 1/2, 1 for w₁ = −2: (0, 0, 1), (P₀ + 2w₁P₁ + P₂, 2 + 2w₁)/4 =
    // (−1, −3, −1/2) (so P(1/2) = (2, 6)), (4, 0, 1).
    let poles = negative_weights_poles(-2.0, 3);
    assert_eq!(
        poles.samples,
        vec![
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(-1.0, -3.0, -0.5),
            DVec3::new(4.0, 0.0, 1.0)
        ]
    );
    assert!(negative_weights_poles(-2.0, 0).samples.is_empty());
}

#[test]
fn rational_poles_of_a_cubic_and_at_an_end() {
    // w(t) = (t − 1/4)(t − 1/2)(t − 3/4) = t³ − 3t²/2 + 11t/16 − 3/32 in Bernstein form:
    // b₀ = w(0) = −3/32, b₁ = w(0) + w'(0)/3 = 13/96, b₂ = w(1) − w'(1)/3 = −13/96, b₃ = 3/32.
    let pts = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 2.0, 0.0),
        DVec3::new(2.0, 2.0, 1.0),
        DVec3::new(3.0, 0.0, 1.0),
    ];
    let weights = [-3.0 / 32.0, 13.0 / 96.0, -13.0 / 96.0, 3.0 / 32.0];
    let poles = rational::rational_poles(&pts, &weights, 2).unwrap();
    assert_eq!(poles.roots.len(), 3, "{:?}", poles.roots);
    for (got, want) in poles.roots.iter().zip([0.25, 0.5, 0.75]) {
        assert_close(*got, want, 1e-12, "cubic root");
    }
    assert!(poles
        .directions
        .iter()
        .all(|d| (d.length() - 1.0).abs() < 1e-12));
    assert_eq!(poles.samples.len(), 2);
    // w₀ = 0: w(t) = 2t(1 − t) + t² = t(2 − t) is 0 at t = 0 only, where N(0) = w₀P₀ = 0.
    let pts = pts2(&[(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
    let poles = rational::rational_poles(&pts, &[0.0, 1.0, 1.0], 2).unwrap();
    assert_eq!(poles.roots, vec![0.0]);
    assert_eq!(poles.directions, vec![DVec2::ZERO]);
}

#[test]
fn rational_poles_validates_its_input() {
    let pts = pts2(&[(0.0, 0.0), (2.0, 3.0), (4.0, 0.0)]);
    let err = rational::rational_poles(&pts, &[0.0, 0.0, 0.0], 3).unwrap_err();
    assert_eq!(err, splinelab::Error::AllWeightsZero { count: 3 });
    assert!(err.to_string().contains("all 3 weights are 0"));
    assert!(rational::rational_poles(&pts[..1], &[1.0], 3).is_err());
    assert!(rational::rational_poles(&pts, &[1.0, 1.0], 3).is_err());
    assert!(rational::rational_poles(&pts, &[1.0, f64::NAN, 1.0], 3).is_err());
    assert!(rational::rational_poles(&pts, &[1.0, -1.0, 1.0], usize::MAX).is_err());
    let bad = pts2(&[(0.0, 0.0), (f64::INFINITY, 3.0), (4.0, 0.0)]);
    assert!(rational::rational_poles(&bad, &[1.0, -1.0, 1.0], 3).is_err());
}
