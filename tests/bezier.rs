//! Bézier curves against independent expectations: the syllabus' worked example, closed
//! forms, invariants, and an explicit Bernstein-sum evaluator. Runs natively and, through
//! wasm-bindgen-test, in Node.

mod common;

use common::*;
use splinelab::bezier::{self, bernstein, BezierCurve, Continuity, JoinRule};
use splinelab::geom::Cartesian;
use splinelab::prelude::*;
use splinelab::{DVec2, DVec3, Error};
use std::f64::consts::{FRAC_1_SQRT_2, PI};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// P0=(0,0), P1=(2,2), P2=(6,4), P3=(8,2) of the Greek notes (syllabus §2).
fn worked_example() -> BezierCurve<DVec2> {
    BezierCurve::new(
        pts2(&[(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)]),
        None,
    )
    .unwrap()
}

fn quarter_circle() -> BezierCurve<DVec2> {
    BezierCurve::new(
        pts2(&[(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]),
        Some(&[1.0, FRAC_1_SQRT_2, 1.0]),
    )
    .unwrap()
}

fn random_curve(rng: &mut Rng, degree: usize) -> Vec<DVec2> {
    (0..=degree).map(|_| rng.point2(10.0)).collect()
}

#[test]
fn worked_example_point_and_every_level_exactly() {
    let tri = worked_example().de_casteljau(0.25).unwrap();
    let expected = pts2(&[
        (0.0, 0.0),
        (2.0, 2.0),
        (6.0, 4.0),
        (8.0, 2.0),
        (0.5, 0.5),
        (3.0, 2.5),
        (6.5, 3.5),
        (9.0 / 8.0, 1.0),
        (31.0 / 8.0, 11.0 / 4.0),
        (29.0 / 16.0, 23.0 / 16.0),
    ]);
    assert_eq!(tri, expected);
    assert_eq!(
        worked_example().evaluate(0.25).unwrap(),
        DVec2::new(29.0 / 16.0, 23.0 / 16.0)
    );
}

#[test]
fn evaluation_matches_the_bernstein_sum() {
    let mut rng = Rng::new(7);
    for case in 0..50 {
        let degree = 1 + case % 8;
        let pts = random_curve(&mut rng, degree);
        let weights: Vec<f64> = (0..=degree).map(|_| rng.range(0.3, 3.0)).collect();
        let poly = BezierCurve::new(pts.clone(), None).unwrap();
        let rat = BezierCurve::new(pts.clone(), Some(&weights)).unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert_close2(
                poly.evaluate(t).unwrap(),
                bernstein_sum2(&pts, None, t),
                1e-12,
                "polynomial",
            );
            assert_close2(
                rat.evaluate(t).unwrap(),
                bernstein_sum2(&pts, Some(&weights), t),
                1e-12,
                "rational",
            );
        }
    }
}

#[test]
fn dense_sampling_equals_pointwise_evaluation() {
    let c = worked_example();
    let ts: Vec<f64> = (0..=100).map(|k| k as f64 / 100.0).collect();
    let mut out = vec![0.0; ts.len() * 2];
    c.sample_into(&ts, &mut out).unwrap();
    let mut uniform = vec![0.0; ts.len() * 2];
    c.sample_uniform_into(ts.len(), &mut uniform).unwrap();
    for (k, &t) in ts.iter().enumerate() {
        let p = c.evaluate(t).unwrap();
        assert_close2(DVec2::new(out[2 * k], out[2 * k + 1]), p, 1e-14, "sample");
        assert_close2(
            DVec2::new(uniform[2 * k], uniform[2 * k + 1]),
            p,
            1e-14,
            "uniform",
        );
    }
    assert_eq!(
        &uniform[200..],
        &[8.0, 2.0],
        "the last uniform sample is the end point"
    );
}

#[test]
fn bernstein_partition_of_unity_symmetry_and_maximum() {
    for n in 1..=10 {
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let sum: f64 = (0..=n).map(|i| bernstein(n, i, t)).sum();
            assert_close(sum, 1.0, 1e-14, "partition of unity");
            for i in 0..=n {
                let b = bernstein(n, i, t);
                assert!((0.0..=1.0).contains(&b));
                assert_close(b, bernstein(n, n - i, 1.0 - t), 1e-15, "symmetry");
            }
        }
        for i in 0..=n {
            // The maximum of B_i^n on [0, 1] is at t = i/n.
            let peak = bernstein(n, i, i as f64 / n as f64);
            for k in 0..=200 {
                assert!(bernstein(n, i, k as f64 / 200.0) <= peak + 1e-15);
            }
        }
    }
    assert_eq!(bernstein(3, 1, 0.5), 3.0 / 8.0);
    assert_eq!(bernstein(2, 3, 0.5), 0.0);
}

#[test]
fn split_halves_reproduce_the_curve() {
    let mut rng = Rng::new(11);
    for case in 0..20 {
        let pts = random_curve(&mut rng, 1 + case % 6);
        let c = BezierCurve::new(pts, None).unwrap();
        let t0 = rng.range(0.05, 0.95);
        let (l, r) = c.split(t0).unwrap();
        for k in 0..=10 {
            let s = k as f64 / 10.0;
            assert_close2(
                l.evaluate(s).unwrap(),
                c.evaluate(s * t0).unwrap(),
                1e-12,
                "left half",
            );
            assert_close2(
                r.evaluate(s).unwrap(),
                c.evaluate(t0 + s * (1.0 - t0)).unwrap(),
                1e-12,
                "right half",
            );
        }
    }
    // Left = top edge, right = hypotenuse of the worked example's triangle at 1/4.
    let (l, r) = worked_example().split(0.25).unwrap();
    assert_eq!(
        l.control_points(),
        pts2(&[
            (0.0, 0.0),
            (0.5, 0.5),
            (9.0 / 8.0, 1.0),
            (29.0 / 16.0, 23.0 / 16.0)
        ])
    );
    assert_eq!(
        r.control_points(),
        pts2(&[
            (29.0 / 16.0, 23.0 / 16.0),
            (31.0 / 8.0, 11.0 / 4.0),
            (6.5, 3.5),
            (8.0, 2.0)
        ])
    );
}

#[test]
fn rational_split_keeps_the_circle() {
    let (l, r) = quarter_circle().split(0.3).unwrap();
    for k in 0..=20 {
        let s = k as f64 / 20.0;
        assert_close(
            l.evaluate(s).unwrap().length(),
            1.0,
            1e-14,
            "left on circle",
        );
        assert_close(
            r.evaluate(s).unwrap().length(),
            1.0,
            1e-14,
            "right on circle",
        );
    }
}

#[test]
fn endpoint_derivative_formulas() {
    let c = worked_example();
    let p = c.control_points();
    let n = 3.0;
    assert_eq!(c.derivative(0.0, 1).unwrap(), (p[1] - p[0]) * n);
    assert_eq!(c.derivative(1.0, 1).unwrap(), (p[3] - p[2]) * n);
    assert_eq!(
        c.derivative(0.0, 2).unwrap(),
        (p[2] - p[1] * 2.0 + p[0]) * (n * (n - 1.0))
    );
    assert_eq!(
        c.derivative(1.0, 2).unwrap(),
        (p[3] - p[2] * 2.0 + p[1]) * (n * (n - 1.0))
    );
    assert_eq!(
        c.derivative(0.5, 3).unwrap(),
        (p[3] - p[2] * 3.0 + p[1] * 3.0 - p[0]) * 6.0
    );
    assert_eq!(
        c.derivative(0.5, 4).unwrap(),
        DVec2::ZERO,
        "order above the degree is zero"
    );
    assert_eq!(c.derivative(0.5, 0).unwrap(), c.evaluate(0.5).unwrap());
    // On [a, b] each order divides by (b − a).
    let on_ab = worked_example().with_interval(2.0, 6.0).unwrap();
    assert_eq!(on_ab.derivative(2.0, 1).unwrap(), (p[1] - p[0]) * (n / 4.0));
    assert_eq!(
        on_ab.derivative(6.0, 2).unwrap(),
        (p[3] - p[2] * 2.0 + p[1]) * (n * (n - 1.0) / 16.0)
    );
    assert_eq!(
        on_ab.evaluate(3.0).unwrap(),
        DVec2::new(29.0 / 16.0, 23.0 / 16.0)
    );
}

#[test]
fn derivatives_match_central_differences() {
    let mut rng = Rng::new(5);
    for case in 0..20 {
        let degree = 2 + case % 5;
        let pts = random_curve(&mut rng, degree);
        let w: Vec<f64> = (0..=degree).map(|_| rng.range(0.5, 2.0)).collect();
        for c in [
            BezierCurve::new(pts.clone(), None).unwrap(),
            BezierCurve::new(pts, Some(&w)).unwrap(),
        ] {
            let (t, h) = (rng.range(0.2, 0.8), 1e-5);
            let fd1 = (c.evaluate(t + h).unwrap() - c.evaluate(t - h).unwrap()) / (2.0 * h);
            let fd2 = (c.evaluate(t + h).unwrap() - c.evaluate(t).unwrap() * 2.0
                + c.evaluate(t - h).unwrap())
                / (h * h);
            let d1 = c.derivative(t, 1).unwrap();
            let d2 = c.derivative(t, 2).unwrap();
            assert_close2(d1, fd1, 1e-6 * (1.0 + d1.length()), "first derivative");
            assert_close2(d2, fd2, 1e-3 * (1.0 + d2.length()), "second derivative");
        }
    }
}

#[test]
fn hodograph_is_the_derivative() {
    let c = worked_example().with_interval(1.0, 3.0).unwrap();
    let h = c.hodograph().unwrap();
    assert_eq!(h.degree(), 2);
    for k in 0..=8 {
        let t = 1.0 + 2.0 * k as f64 / 8.0;
        assert_close2(
            h.evaluate(t).unwrap(),
            c.derivative(t, 1).unwrap(),
            1e-13,
            "hodograph",
        );
    }
    assert!(quarter_circle().hodograph().is_err());
}

#[test]
fn rational_quarter_circle_is_on_the_unit_circle() {
    let c = quarter_circle();
    for k in 0..=1000 {
        let p = c.evaluate(k as f64 / 1000.0).unwrap();
        assert_close(p.length(), 1.0, 1e-12, "radius");
    }
    assert_close(
        c.arc_length(None).unwrap(),
        PI / 2.0,
        1e-12 * PI,
        "quarter circle length",
    );
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        assert_close(c.curvature(t).unwrap(), 1.0, 1e-12, "curvature 1/r");
        // The tangent is perpendicular to the radius.
        assert_close(
            c.derivative(t, 1).unwrap().dot(c.evaluate(t).unwrap()),
            0.0,
            1e-12,
            "tangent ⟂ radius",
        );
    }
}

#[test]
fn weights_all_equal_reproduce_the_polynomial_and_scaling_changes_nothing() {
    let pts = worked_example().control_points();
    let poly = worked_example();
    let equal = BezierCurve::new(pts.clone(), Some(&[2.5; 4])).unwrap();
    let w = [1.0, 3.0, 0.5, 2.0];
    let rat = BezierCurve::new(pts.clone(), Some(&w)).unwrap();
    let scaled = BezierCurve::new(pts, Some(&w.map(|x| x * 7.0))).unwrap();
    for k in 0..=16 {
        let t = k as f64 / 16.0;
        assert_close2(
            equal.evaluate(t).unwrap(),
            poly.evaluate(t).unwrap(),
            1e-13,
            "equal weights",
        );
        assert_close2(
            scaled.evaluate(t).unwrap(),
            rat.evaluate(t).unwrap(),
            1e-13,
            "scaled weights",
        );
    }
}

#[test]
fn elevation_reversal_and_affine_maps_keep_the_curve() {
    let mut rng = Rng::new(3);
    for case in 0..20 {
        let pts = random_curve(&mut rng, 1 + case % 6);
        let c = BezierCurve::new(pts.clone(), None).unwrap();
        let e = c.elevate().unwrap();
        assert_eq!(e.degree(), c.degree() + 1);
        let r = c.reversed();
        let (m, shift) = (
            glam::DMat2::from_cols_array(&[1.5, 0.3, -0.7, 0.9]),
            DVec2::new(3.0, -1.0),
        );
        let mapped = BezierCurve::new(pts.iter().map(|&p| m * p + shift).collect(), None).unwrap();
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let p = c.evaluate(t).unwrap();
            assert_close2(e.evaluate(t).unwrap(), p, 1e-12, "elevated");
            assert_close2(r.evaluate(1.0 - t).unwrap(), p, 1e-12, "reversed");
            assert_close2(
                mapped.evaluate(t).unwrap(),
                m * p + shift,
                1e-12,
                "affine invariance",
            );
        }
    }
}

#[test]
fn curve_stays_in_the_control_hull_box_and_the_tight_box_is_tight() {
    let mut rng = Rng::new(9);
    for case in 0..20 {
        let pts = random_curve(&mut rng, 2 + case % 5);
        let c = BezierCurve::new(pts.clone(), None).unwrap();
        let hull = splinelab::geom::BoundingBox::of_points(&pts).unwrap();
        let tight = c.bounding_box();
        let mut seen_min = DVec2::splat(f64::INFINITY);
        let mut seen_max = DVec2::splat(f64::NEG_INFINITY);
        for k in 0..=4000 {
            let p = c.evaluate(k as f64 / 4000.0).unwrap();
            assert!(
                p.cmpge(hull.min).all() && p.cmple(hull.max).all(),
                "convex hull"
            );
            assert!(
                p.cmpge(tight.min - 1e-12).all() && p.cmple(tight.max + 1e-12).all(),
                "tight box contains {p}"
            );
            seen_min = seen_min.min(p);
            seen_max = seen_max.max(p);
        }
        // Dense sampling gets within (step²)-size of the true extremes.
        assert_close2(tight.min, seen_min, 1e-4, "tight min");
        assert_close2(tight.max, seen_max, 1e-4, "tight max");
    }
    // A parabola's apex: y = x² mirrored, (0,0), (1,2), (2,0) has max y = 1 at t = 1/2.
    let b = BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)]), None)
        .unwrap()
        .bounding_box();
    assert_close(b.max.y, 1.0, 1e-12, "apex");
    assert_eq!((b.min, b.max.x), (DVec2::ZERO, 2.0));
}

/// Cusp: (t², t³) on [−1, 1]; loop; nearly straight; a high-degree wiggle; a rational arc.
fn hard_curves() -> Vec<(&'static str, BezierCurve<DVec2>)> {
    let cusp = bezier::from_polynomial(
        &pts2(&[(0.0, 0.0), (0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]),
        -1.0,
        1.0,
    )
    .unwrap();
    vec![
        ("cusp", cusp),
        (
            "loop",
            BezierCurve::new(
                pts2(&[(0.0, 0.0), (4.0, 3.0), (-1.0, 3.0), (3.0, 0.0)]),
                None,
            )
            .unwrap(),
        ),
        (
            "straight",
            BezierCurve::new(
                pts2(&[(0.0, 0.0), (1.0, 1e-7), (2.0, -1e-7), (3.0, 0.0)]),
                None,
            )
            .unwrap(),
        ),
        (
            "collinear backtrack",
            BezierCurve::new(
                pts2(&[(0.0, 0.0), (3.0, 0.0), (-1.0, 0.0), (2.0, 0.0)]),
                None,
            )
            .unwrap(),
        ),
        (
            "degree 7",
            BezierCurve::new(
                pts2(&[
                    (0.0, 0.0),
                    (1.0, 5.0),
                    (2.0, -5.0),
                    (3.0, 5.0),
                    (4.0, -5.0),
                    (5.0, 5.0),
                    (6.0, -5.0),
                    (7.0, 0.0),
                ]),
                None,
            )
            .unwrap(),
        ),
        ("worked example", worked_example()),
        ("quarter circle", quarter_circle()),
    ]
}

#[test]
fn flatten_honours_the_tolerance_on_hard_curves() {
    for (name, c) in hard_curves() {
        let pts = c.control_points();
        let w = c.weights();
        for tol in [0.1, 1e-3, 1e-5] {
            let poly = c.flatten(tol).unwrap();
            assert_eq!(poly[0], pts[0], "{name}: starts at P0");
            assert_eq!(
                *poly.last().unwrap(),
                *pts.last().unwrap(),
                "{name}: ends at Pn"
            );
            let mut worst = 0.0f64;
            for k in 0..=20_000 {
                let p = bernstein_sum2(&pts, Some(&w), k as f64 / 20_000.0);
                worst = worst.max(distance_to_polyline(p, &poly));
            }
            assert!(
                worst <= tol * (1.0 + 1e-9),
                "{name}, tolerance {tol}: a curve point is {worst} from the polyline"
            );
        }
    }
}

/// Levien's estimate of the fewest chords: `∫ sqrt(|κ| / (8 tol)) ds` (a chord of a circle of
/// radius R with sagitta tol subtends sqrt(8 tol / R)), integrated here by the midpoint rule on
/// the Bernstein-sum evaluator.
fn levien_estimate(pts: &[DVec2], tol: f64) -> f64 {
    let steps = 20_000;
    let h = 1.0 / steps as f64;
    (0..steps)
        .map(|k| {
            let t = (k as f64 + 0.5) * h;
            let e = 1e-4;
            let (a, b, c) = (
                bernstein_sum2(pts, None, t - e),
                bernstein_sum2(pts, None, t),
                bernstein_sum2(pts, None, t + e),
            );
            let d1 = (c - a) / (2.0 * e);
            let d2 = (c - b * 2.0 + a) / (e * e);
            let speed = d1.length();
            let kappa = d1.perp_dot(d2).abs() / speed.powi(3);
            (kappa / (8.0 * tol)).sqrt() * speed * h
        })
        .sum()
}

#[test]
fn flatten_uses_close_to_the_fewest_segments() {
    let cases = [
        ("worked example", worked_example().control_points()),
        (
            "arch",
            pts2(&[(0.0, 0.0), (0.0, 3.0), (4.0, 3.0), (4.0, 0.0)]),
        ),
        (
            "s-curve",
            pts2(&[(0.0, 0.0), (3.0, 4.0), (1.0, -3.0), (4.0, 1.0)]),
        ),
    ];
    for (name, pts) in cases {
        let c = BezierCurve::new(pts.clone(), None).unwrap();
        for tol in [1e-2, 1e-3, 1e-4] {
            let segments = c.flatten(tol).unwrap().len() - 1;
            let estimate = levien_estimate(&pts, tol);
            println!("flatten {name} tolerance {tol:e}: {segments} segments, Levien estimate {estimate:.1}");
            assert!(
                (segments as f64) <= 1.05 * estimate + 2.0,
                "{name}, tolerance {tol}: {segments} segments, Levien's estimate {estimate:.1}"
            );
        }
    }
}

#[test]
fn line_intersections_at_known_roots() {
    // x = t, y = (t − 1/4)(t − 1/2)(t − 3/4) as a Bézier curve: roots at 1/4, 1/2 (the first
    // split point of the recursion) and 3/4.
    let cubic = bezier::from_polynomial(
        &pts2(&[
            (0.0, -3.0 / 32.0),
            (1.0, 11.0 / 16.0),
            (0.0, -1.5),
            (0.0, 1.0),
        ]),
        0.0,
        1.0,
    )
    .unwrap();
    let r = cubic
        .intersect_line(DVec2::new(-1.0, 0.0), DVec2::new(2.0, 0.0), 1e-10)
        .unwrap();
    assert_eq!(r.ts.len(), 3, "{:?}", r.ts);
    for (t, e) in r.ts.iter().zip([0.25, 0.5, 0.75]) {
        assert_close(*t, e, 1e-12, "root");
    }
    assert!(r.boxes.iter().any(|b| !b.hit), "some boxes are pruned");
    assert!(r.boxes[0].depth == 0 && r.boxes[0].hit);

    // Tangency: y = (t − 1/2)² touches y = 0 once.
    let parabola =
        bezier::from_polynomial(&pts2(&[(0.0, 0.25), (1.0, -1.0), (0.0, 1.0)]), 0.0, 1.0).unwrap();
    let r = parabola
        .intersect_line(DVec2::ZERO, DVec2::X, 1e-9)
        .unwrap();
    assert_eq!(r.ts.len(), 1, "{:?}", r.ts);
    assert_close(r.ts[0], 0.5, 1e-6, "tangency");
    // Just above: no intersection; a line through an end point: t = 0 once.
    assert!(parabola
        .intersect_line(DVec2::new(0.0, -0.01), DVec2::new(1.0, -0.01), 1e-9)
        .unwrap()
        .ts
        .is_empty());
    let ends = parabola
        .intersect_line(DVec2::new(0.0, 0.25), DVec2::new(1.0, 0.25), 1e-9)
        .unwrap();
    assert_eq!(ends.ts.len(), 2, "{:?}", ends.ts);
    assert_close(ends.ts[0], 0.0, 1e-12, "start");
    assert_close(ends.ts[1], 1.0, 1e-12, "end");

    // Rational: the diagonal meets the quarter circle at t = 1/2 (symmetry).
    let r = quarter_circle()
        .intersect_line(DVec2::ZERO, DVec2::ONE, 1e-10)
        .unwrap();
    assert_eq!(r.ts.len(), 1);
    assert_close(r.ts[0], 0.5, 1e-12, "circle");

    // On an interval [2, 4] the parameters are global.
    let r = cubic
        .clone()
        .with_interval(2.0, 4.0)
        .unwrap()
        .intersect_line(DVec2::ZERO, DVec2::X, 1e-10)
        .unwrap();
    assert_close(r.ts[1], 3.0, 1e-12, "global parameter");

    // A curve lying on the line gives the ends of its interval.
    let flat = BezierCurve::new(pts2(&[(0.0, 1.0), (2.0, 1.0), (5.0, 1.0)]), None).unwrap();
    assert_eq!(
        flat.intersect_line(DVec2::new(0.0, 1.0), DVec2::new(1.0, 1.0), 1e-9)
            .unwrap()
            .ts,
        vec![0.0, 1.0]
    );
}

#[test]
fn line_intersections_on_random_curves_are_sorted_distinct_and_on_the_line() {
    let mut rng = Rng::new(21);
    for case in 0..40 {
        let c = BezierCurve::new(random_curve(&mut rng, 2 + case % 6), None).unwrap();
        let (p0, p1) = (rng.point2(5.0), rng.point2(5.0));
        let tol = 1e-9;
        let r = c.intersect_line(p0, p1, tol).unwrap();
        let dir = (p1 - p0).normalize();
        for w in r.ts.windows(2) {
            assert!(w[0] < w[1], "sorted and distinct: {:?}", r.ts);
        }
        for &t in &r.ts {
            assert!(
                dir.perp_dot(c.evaluate(t).unwrap() - p0).abs() <= tol,
                "t = {t} is on the line"
            );
        }
        // Every sign change of the distance along a fine scan is found.
        let d = |t: f64| dir.perp_dot(bernstein_sum2(&c.control_points(), None, t) - p0);
        let changes = (0..2000)
            .filter(|&k| (d(k as f64 / 2000.0) > 0.0) != (d((k + 1) as f64 / 2000.0) > 0.0))
            .count();
        assert!(
            r.ts.len() >= changes,
            "case {case}: {} roots, {changes} sign changes",
            r.ts.len()
        );
        assert!(r.ts.len() <= c.degree(), "at most n roots");
        // Variation diminishing: the curve crosses no more often than the polygon.
        assert!(changes <= c.polygon_line_crossings(p0, p1));
    }
}

#[test]
fn arc_length_against_closed_forms() {
    // y = x² on [0, 1]: (2√5 + asinh 2)/4.
    let parabola = BezierCurve::new(pts2(&[(0.0, 0.0), (0.5, 0.0), (1.0, 1.0)]), None).unwrap();
    let exact = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
    assert_close(
        parabola.arc_length(None).unwrap(),
        exact,
        1e-12 * exact,
        "parabola",
    );
    // The cusp (t², t³) on [−1, 1]: 2·(13^{3/2} − 8)/27.
    let cusp = &hard_curves()[0].1;
    let exact = 2.0 * (13f64.powf(1.5) - 8.0) / 27.0;
    assert_close(cusp.arc_length(None).unwrap(), exact, 1e-12 * exact, "cusp");
    // A straight cubic with uneven speed: the chord.
    let line = BezierCurve::new(
        pts2(&[(0.0, 0.0), (3.0, 4.0), (3.0, 4.0), (6.0, 8.0)]),
        None,
    )
    .unwrap();
    assert_close(line.arc_length(None).unwrap(), 10.0, 1e-12 * 10.0, "line");
    // A semicircle from two rational quarters, in 3D.
    let q3 = BezierCurve::new(
        vec![
            DVec3::new(2.0, 0.0, 1.0),
            DVec3::new(2.0, 2.0, 1.0),
            DVec3::new(0.0, 2.0, 1.0),
        ],
        Some(&[1.0, FRAC_1_SQRT_2, 1.0]),
    )
    .unwrap();
    assert_close(
        q3.arc_length(None).unwrap(),
        PI,
        1e-12 * PI,
        "quarter circle of radius 2",
    );
}

#[test]
fn arc_length_meets_every_requested_accuracy_on_closed_forms() {
    // (curve, exact length): a line with uneven speed, y = x² as a quadratic and as its degree
    // elevation (a cubic with a linear hodograph), the cusp (t², t³) on [0, 1], the same
    // parabola 1000 times larger (the accuracy is absolute), and a rational quarter circle.
    let parabola = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
    let curves = [
        (
            pts2(&[(0.0, 0.0), (3.0, 4.0), (3.0, 4.0), (6.0, 8.0)]),
            None,
            10.0,
        ),
        (pts2(&[(0.0, 0.0), (0.5, 0.0), (1.0, 1.0)]), None, parabola),
        (
            pts2(&[
                (0.0, 0.0),
                (1.0 / 3.0, 0.0),
                (2.0 / 3.0, 1.0 / 3.0),
                (1.0, 1.0),
            ]),
            None,
            parabola,
        ),
        (
            pts2(&[(0.0, 0.0), (0.0, 0.0), (1.0 / 3.0, 0.0), (1.0, 1.0)]),
            None,
            (13f64.powf(1.5) - 8.0) / 27.0,
        ),
        (
            pts2(&[(0.0, 0.0), (500.0, 0.0), (1000.0, 1000.0)]),
            None,
            1000.0 * parabola,
        ),
        (
            pts2(&[(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]),
            Some(vec![1.0, FRAC_1_SQRT_2, 1.0]),
            PI / 2.0,
        ),
    ];
    for (points, weights, exact) in curves {
        let c = BezierCurve::new(points, weights.as_deref()).unwrap();
        for accuracy in [0.3, 1e-2, 1e-3, 1e-4, 1e-6, 1e-9, 1e-12] {
            let got = c.arc_length(Some(accuracy)).unwrap();
            assert!(
                (got - exact).abs() <= accuracy,
                "length {got} vs {exact} at accuracy {accuracy} (error {:e})",
                (got - exact).abs()
            );
            let batch = bezier::arc_lengths::<DVec2>(
                &c.control_points()
                    .iter()
                    .flat_map(|p| [p.x, p.y])
                    .collect::<Vec<_>>(),
                c.degree(),
                Some(accuracy),
            );
            if weights.is_none() {
                assert_eq!(
                    batch.unwrap()[0],
                    got,
                    "arcLengths = arcLength at {accuracy}"
                );
            }
        }
    }
}

#[test]
fn a_loose_arc_length_accuracy_holds_on_random_cubics() {
    // Random cubics (control points in a square of side 10), against the adaptive
    // method at 1e-14: the error stays within each requested accuracy.
    let mut rng = Rng::new(20_260_509);
    for accuracy in [1e-2, 1e-3, 1e-5, 1e-8] {
        let mut worst: f64 = 0.0;
        for _ in 0..2000 {
            let c = BezierCurve::new(random_curve(&mut rng, 3), None).unwrap();
            let reference = c.arc_length_adaptive(Some(1e-14)).unwrap();
            let got = c.arc_length(Some(accuracy)).unwrap();
            worst = worst.max((got - reference).abs());
        }
        assert!(
            worst <= accuracy,
            "worst error {worst:e} at accuracy {accuracy:e}"
        );
    }
}

#[test]
fn curvature_of_known_curves() {
    // y = x² at the apex: κ = 2, turning left.
    let parabola = BezierCurve::new(pts2(&[(-1.0, 1.0), (0.0, -1.0), (1.0, 1.0)]), None).unwrap();
    assert_close(parabola.curvature(0.5).unwrap(), 2.0, 1e-12, "apex");
    assert_close(
        parabola.reversed().curvature(0.5).unwrap(),
        -2.0,
        1e-12,
        "sign flips",
    );
    let line = BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 1.0)]), None).unwrap();
    assert_eq!(line.curvature(0.3).unwrap(), 0.0);
    assert_eq!(
        hard_curves()[0].1.curvature(0.0).unwrap(),
        f64::INFINITY,
        "cusp"
    );
}

#[test]
fn continuity_answers_the_italian_exercise() {
    // x(t) = 1 − t² on [0, 1), then three candidate pieces on [1, 2]; as graphs (t, x(t)).
    let first =
        bezier::from_polynomial(&pts2(&[(0.0, 1.0), (1.0, 0.0), (0.0, -1.0)]), 0.0, 1.0).unwrap();
    let piece = |c0: f64, c1: f64, c2: f64| {
        bezier::from_polynomial(&pts2(&[(0.0, c0), (1.0, c1), (0.0, c2)]), 1.0, 2.0).unwrap()
    };
    let check = |second| bezier::check_continuity(&first, &second, 1e-9).unwrap();
    assert_eq!(check(piece(2.0, 0.0, -1.0)).c, -1, "2 − t²: not C0");
    assert_eq!(
        check(piece(3.0, -4.0, 1.0)).c,
        1,
        "t² − 4t + 3: C1 (not C2)"
    );
    assert_eq!(check(piece(1.0, -2.0, 1.0)).c, 0, "t² − 2t + 1: C0, not C1");
    // The same polynomial on both sides is C∞.
    assert_eq!(check(piece(1.0, 0.0, -1.0)).c, Continuity::INFINITE);
}

#[test]
fn joining_rules_produce_the_continuity_they_promise() {
    let left = worked_example();
    let right = BezierCurve::new(
        pts2(&[(9.0, 0.0), (10.0, -2.0), (12.0, 1.0), (14.0, 0.0)]),
        None,
    )
    .unwrap();
    for (rule, c, g) in [
        (JoinRule::C0, 0, 0),
        (JoinRule::G1, 0, 1),
        (JoinRule::C1, 1, 1),
        (JoinRule::C2, 2, 2),
    ] {
        let (l, r) = bezier::join(&left, &right, rule, true).unwrap();
        assert_eq!(
            l, left,
            "{rule:?}: adjusting the right piece leaves the left one"
        );
        let k = bezier::check_continuity(&l, &r, 1e-9).unwrap();
        assert_eq!((k.c, k.g), (c, g), "{rule:?}");
        // The free points stay where they were: C2 for two cubics leaves only Q3 (and P0).
        assert_eq!(r.control_points()[3], right.control_points()[3]);
        let (l2, r2) = bezier::join(&left, &right, rule, false).unwrap();
        assert_eq!(
            r2, right,
            "{rule:?}: adjusting the left piece leaves the right one"
        );
        assert_eq!(
            bezier::check_continuity(&l2, &r2, 1e-9).unwrap().c,
            c,
            "{rule:?} from the left"
        );
    }
    // Syllabus C1 for cubics on unit intervals: Q1 − Q0 = P3 − P2.
    let (_, r) = bezier::join(&left, &right, JoinRule::C1, true).unwrap();
    assert_eq!(
        r.control_points()[1] - r.control_points()[0],
        DVec2::new(2.0, -2.0)
    );
    // Unequal intervals scale the tangent: n/h0 (P3 − P2) = m/h1 (Q1 − Q0).
    let wide = right.clone().with_interval(1.0, 3.0).unwrap();
    let (_, r) = bezier::join(&left, &wide, JoinRule::C1, true).unwrap();
    assert_eq!(
        r.control_points()[1] - r.control_points()[0],
        DVec2::new(4.0, -4.0)
    );
    assert_eq!(bezier::check_continuity(&left, &r, 1e-9).unwrap().c, 1);
}

#[test]
fn in_place_edits_match_a_rebuilt_curve() {
    let mut c = worked_example();
    c.set_control_point(2, DVec2::new(5.0, 6.0)).unwrap();
    let rebuilt = BezierCurve::new(
        pts2(&[(0.0, 0.0), (2.0, 2.0), (5.0, 6.0), (8.0, 2.0)]),
        None,
    )
    .unwrap();
    assert_eq!(c, rebuilt);
    c.set_weight(1, 2.0).unwrap();
    assert!(c.is_rational());
    assert_eq!(c.weights(), vec![1.0, 2.0, 1.0, 1.0]);
    assert_eq!(c.control_points()[1], DVec2::new(2.0, 2.0));
    c.set_weight(1, 1.0).unwrap();
    assert!(!c.is_rational(), "all weights 1 again: polynomial");
}

fn message(e: Error) -> String {
    e.to_string()
}

#[test]
fn bad_input_gives_clear_errors() {
    let err2 =
        |c: &[f64], w: Option<&[f64]>| message(BezierCurve::<DVec2>::from_flat(c, w).unwrap_err());
    assert_eq!(
        err2(&[0.0, 0.0], None),
        "a Bézier curve needs at least 2 control points, got 1"
    );
    assert!(
        err2(&[0.0, 0.0, 1.0], None).contains("coordinate count 3 is not a multiple of dim = 2")
    );
    assert!(err2(&[0.0, 0.0, f64::NAN, 1.0], None).contains("coordinate 2 is NaN"));
    assert!(err2(&[0.0, f64::INFINITY, 1.0, 1.0], None)
        .contains(&format!("coordinate 1 is {INFINITY_TEXT}")));
    assert!(err2(&[0.0, 0.0, 1.0, 1.0], Some(&[1.0]))
        .contains("one value per control point (2), got 1"));
    assert!(err2(&[0.0, 0.0, 1.0, 1.0], Some(&[1.0, 0.0])).contains("weight 1 is 0"));
    assert!(err2(&[0.0, 0.0, 1.0, 1.0], Some(&[-2.0, 1.0])).contains("weight 0 is -2"));
    assert!(err2(&[0.0, 0.0, 1.0, 1.0], Some(&[1.0, f64::NAN])).contains("weight 1 is NaN"));
    assert_eq!(
        message(splinelab::geom::check_dim(4).unwrap_err()),
        "dim must be 2 or 3, got 4"
    );
    let c = worked_example();
    assert_eq!(
        message(c.evaluate(1.5).unwrap_err()),
        "t = 1.5 is outside the domain [0, 1]"
    );
    assert_eq!(
        message(c.evaluate(-0.1).unwrap_err()),
        "t = -0.1 is outside the domain [0, 1]"
    );
    assert!(message(c.evaluate(f64::NAN).unwrap_err()).contains("t is NaN"));
    assert!(message(c.split(2.0).unwrap_err()).contains("t = 2"));
    let mut m = c.clone();
    assert!(message(m.set_control_point(4, DVec2::ZERO).unwrap_err())
        .contains("index 4 is out of range"));
    assert!(message(
        m.set_control_point(0, DVec2::new(f64::NAN, 0.0))
            .unwrap_err()
    )
    .contains("NaN"));
    assert!(message(m.set_weight(9, 1.0).unwrap_err()).contains("index 9"));
    assert!(message(m.set_weight(0, -1.0).unwrap_err()).contains("weight 0 is -1"));
    assert_eq!(m, c, "failed edits leave the curve unchanged");
    assert!(message(c.flatten(0.0).unwrap_err()).contains("tolerance 0"));
    assert!(message(c.flatten(1e-300).unwrap_err()).contains("tolerance"));
    assert!(
        message(c.intersect_line(DVec2::ONE, DVec2::ONE, 1e-9).unwrap_err())
            .contains("two different points")
    );
    assert!(message(
        c.intersect_line(DVec2::ZERO, DVec2::ONE, f64::NAN)
            .unwrap_err()
    )
    .contains("tolerance NaN"));
    assert!(message(c.clone().with_interval(1.0, 1.0).unwrap_err()).contains("[1, 1] is empty"));
    let mut out = vec![0.0; 4];
    assert!(message(c.sample_into(&[0.5, 1.2], &mut out).unwrap_err()).contains("t = 1.2"));
    assert!(message(JoinRule::parse("C3").unwrap_err()).contains("\"C3\""));
}

#[test]
fn composite_curves_use_the_global_parameter_and_report_each_joint() {
    // Three quadratic pieces of y = x² (x = t on [0, 3]) are one polynomial: C∞ at both joints;
    // then a kink at t = 2 by moving the third piece's middle point.
    let piece = |a: f64| {
        bezier::from_polynomial(&pts2(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]), a, a + 1.0).unwrap()
    };
    let pieces = vec![piece(0.0), piece(1.0), piece(2.0)];
    let c = bezier::CompositeCurve::new(pieces.clone(), &[0.0, 1.0, 2.0, 3.0]).unwrap();
    for k in 0..=30 {
        let t = k as f64 / 10.0;
        assert_close2(
            c.evaluate(t).unwrap(),
            DVec2::new(t, t * t),
            1e-12,
            "y = x²",
        );
    }
    assert_eq!(
        c.piece_index(1.0).unwrap(),
        1,
        "right-continuous at a joint"
    );
    assert_eq!(
        c.piece_index(3.0).unwrap(),
        2,
        "the end belongs to the last piece"
    );
    let k = c.continuity(1e-9).unwrap();
    assert_eq!(
        k.iter().map(|k| k.c).collect::<Vec<_>>(),
        vec![Continuity::INFINITE; 2]
    );
    // The same kink made in place: piece 2's middle point moves, the others stay.
    let mut c = bezier::CompositeCurve::new(pieces, &[0.0, 1.0, 2.0, 3.0]).unwrap();
    c.set_control_point(2, 1, DVec2::new(2.5, 5.0)).unwrap();
    let k = c.continuity(1e-9).unwrap();
    assert_eq!((k[1].c, k[1].g), (0, 0), "a corner at t = 2");
    assert_eq!(k[0].c, Continuity::INFINITE, "pieces 0 and 1 untouched");
    // Piece 2 on [2, 3] with points (2, 4), (2.5, 5), (3, 9): its middle is ¼(2, 4) + ½(2.5, 5) + ¼(3, 9).
    assert_close2(
        c.evaluate(2.5).unwrap(),
        DVec2::new(2.5, 5.75),
        1e-12,
        "moved piece",
    );
    assert!(
        c.set_control_point(3, 0, DVec2::ZERO).is_err(),
        "no piece 3"
    );
    assert!(
        c.set_control_point(0, 3, DVec2::ZERO).is_err(),
        "a quadratic has 3 points"
    );
    assert!(bezier::CompositeCurve::new(vec![piece(0.0)], &[0.0]).is_err());
    assert!(c.evaluate(3.5).unwrap_err().to_string().contains("[0, 3]"));
}

/// `arc_lengths` of `curves` given back to back equals `arc_length` of each, bit for bit.
fn assert_batch_is_single<C: Cartesian>(
    curves: &[BezierCurve<C>],
    degree: usize,
    accuracy: Option<f64>,
) {
    let mut flat = vec![0.0; curves.len() * (degree + 1) * C::DIM];
    let points = curves.iter().flat_map(|c| c.control_points());
    for (p, o) in points.zip(flat.chunks_exact_mut(C::DIM)) {
        p.write_to(o);
    }
    let batch = bezier::arc_lengths::<C>(&flat, degree, accuracy).unwrap();
    for (c, l) in curves.iter().zip(&batch) {
        assert_eq!(*l, c.arc_length(accuracy).unwrap(), "degree {degree}");
    }
}

#[test]
fn batched_arc_lengths_equal_the_single_ones() {
    let mut rng = Rng::new(41);
    let curves: Vec<BezierCurve<DVec2>> = (0..30)
        .map(|_| BezierCurve::new(random_curve(&mut rng, 3), None).unwrap())
        .collect();
    assert_batch_is_single(&curves, 3, None);
    assert!(bezier::arc_lengths::<DVec2>(&[0.0; 7], 3, None)
        .unwrap_err()
        .to_string()
        .contains("do not split"));
}

#[test]
fn arc_length_of_a_cusp_away_from_dyadic_points() {
    // (t², t³) on [−1, 2]: the cusp sits at s = 1/3. ∫|t|√(4 + 9t²) dt = ((13^{3/2} − 8) + (40^{3/2} − 8))/27.
    let cusp = bezier::from_polynomial(
        &pts2(&[(0.0, 0.0), (0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]),
        -1.0,
        2.0,
    )
    .unwrap();
    let exact = (13f64.powf(1.5) - 8.0 + 40f64.powf(1.5) - 8.0) / 27.0;
    assert_close(
        cusp.arc_length(None).unwrap(),
        exact,
        1e-12 * exact,
        "cusp at s = 1/3",
    );
}

#[test]
fn dense_sampling_matches_de_casteljau_for_every_degree() {
    // Horner's rule on the power basis up to degree 5, de Casteljau above: both against the
    // independent Bernstein sum.
    let mut rng = Rng::new(47);
    for degree in 1..=9 {
        for rational in [false, true] {
            let pts = random_curve(&mut rng, degree);
            let w: Vec<f64> = (0..=degree).map(|_| rng.range(0.5, 2.0)).collect();
            let c = BezierCurve::new(pts.clone(), rational.then_some(w.as_slice())).unwrap();
            let ts: Vec<f64> = (0..=50).map(|k| k as f64 / 50.0).collect();
            let mut out = vec![0.0; 2 * ts.len()];
            c.sample_into(&ts, &mut out).unwrap();
            for (k, &t) in ts.iter().enumerate() {
                let e = bernstein_sum2(&pts, rational.then_some(w.as_slice()), t);
                assert_close2(
                    DVec2::new(out[2 * k], out[2 * k + 1]),
                    e,
                    1e-12 * (1.0 + e.length()),
                    &format!("degree {degree}, t = {t}"),
                );
            }
            // A uniform grid hits both ends exactly.
            let mut grid = vec![0.0; 2 * 51];
            c.sample_uniform_into(51, &mut grid).unwrap();
            assert_eq!(
                DVec2::from_slice(&grid),
                c.evaluate(0.0).unwrap(),
                "grid start"
            );
            assert_eq!(
                DVec2::from_slice(&grid[100..]),
                c.evaluate(1.0).unwrap(),
                "grid end"
            );
            // count = 0 writes nothing (the uniform loop once computed `count − 1` here).
            c.sample_uniform_into(0, &mut []).unwrap();
            let mut one = [0.0; 2];
            c.sample_uniform_into(1, &mut one).unwrap();
            assert_eq!(
                DVec2::from_slice(&one),
                c.evaluate(0.0).unwrap(),
                "count = 1: the start"
            );
            if !rational {
                assert_eq!(DVec2::new(out[0], out[1]), pts[0], "exact start");
                assert_eq!(DVec2::new(out[100], out[101]), pts[degree], "exact end");
            }
        }
    }
}

// ---- arc length: the 2D fast path against the adaptive method and closed forms -------------

/// The adaptive method at 100× the fast path's accuracy: the independent reference.
fn adaptive_reference(c: &BezierCurve<DVec2>) -> f64 {
    let cps = c.control_points();
    let polygon: f64 = cps.windows(2).map(|w| (w[1] - w[0]).length()).sum();
    c.arc_length_adaptive(Some(1e-15 * polygon.max(f64::MIN_POSITIVE)))
        .unwrap()
}

/// Checks the fast path (`arc_length(None)`) against the adaptive reference, relatively.
#[track_caller]
fn check_against_adaptive(points: Vec<DVec2>, tol: f64, what: &str) -> f64 {
    let c = BezierCurve::new(points, None).unwrap();
    let (fast, reference) = (c.arc_length(None).unwrap(), adaptive_reference(&c));
    let rel = if reference == 0.0 {
        fast.abs()
    } else {
        (fast - reference).abs() / reference
    };
    assert!(
        rel <= tol,
        "{what}: fast {fast:e}, adaptive {reference:e}, relative difference {rel:e}"
    );
    rel
}

/// Complex product of points read as `x + iy`.
fn cmul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

/// The cubic through `p0` whose hodograph, read as a complex polynomial, is
/// `z'(t) = a (t − r1)(t − r2)`: integrating, `P(t) = p0 + c0 t + c1 t²/2 + c2 t³/3` with
/// `c2 = a`, `c1 = −a (r1 + r2)`, `c0 = a r1 r2`, and power → Bézier:
/// `P1 = P0 + p1/3`, `P2 = P0 + 2p1/3 + p2/3`, `P3 = P0 + p1 + p2 + p3`.
fn cubic_with_hodograph_roots(p0: DVec2, a: DVec2, r1: DVec2, r2: DVec2) -> Vec<DVec2> {
    let (c2, c1, c0) = (a, -cmul(a, r1 + r2), cmul(a, cmul(r1, r2)));
    let (p1, p2, p3) = (c0, c1 / 2.0, c2 / 3.0);
    vec![
        p0,
        p0 + p1 / 3.0,
        p0 + 2.0 * p1 / 3.0 + p2 / 3.0,
        p0 + p1 + p2 + p3,
    ]
}

#[test]
fn arc_length_fast_path_matches_the_adaptive_method_on_random_curves() {
    let mut rng = Rng::new(2024);
    let mut worst: f64 = 0.0;
    for i in 0..2000 {
        worst = worst.max(check_against_adaptive(
            random_curve(&mut rng, 3),
            1e-13,
            &format!("random cubic {i}"),
        ));
    }
    for i in 0..300 {
        let q = random_curve(&mut rng, 2);
        worst = worst.max(check_against_adaptive(
            q.clone(),
            1e-13,
            &format!("random quadratic {i}"),
        ));
        // The same quadratic degree-elevated to a cubic: the same length.
        let elevated = vec![
            q[0],
            q[0] + (q[1] - q[0]) * (2.0 / 3.0),
            q[2] + (q[1] - q[2]) * (2.0 / 3.0),
            q[2],
        ];
        let (l2, l3) = (
            BezierCurve::new(q, None).unwrap().arc_length(None).unwrap(),
            BezierCurve::new(elevated, None)
                .unwrap()
                .arc_length(None)
                .unwrap(),
        );
        assert_close(l3, l2, 1e-13 * l2, "quadratic as a cubic");
    }
    // Unit-square cubics, as in the benchmark: their hodograph roots are near [0, 1].
    for i in 0..1000 {
        let p: Vec<DVec2> = (0..4)
            .map(|_| DVec2::new(rng.range(0.0, 1.0), rng.range(0.0, 1.0)))
            .collect();
        worst = worst.max(check_against_adaptive(
            p,
            1e-13,
            &format!("unit-square cubic {i}"),
        ));
    }
    println!("worst relative difference on random curves: {worst:e}");
}

#[test]
fn arc_length_fast_path_on_cusps_near_cusps_and_degenerate_curves() {
    let mut rng = Rng::new(77);
    let mut worst: f64 = 0.0;
    let mut check = |r1: DVec2, r2: DVec2, what: &str, rng: &mut Rng| {
        for _ in 0..20 {
            let a = rng.point2(3.0);
            let p0 = rng.point2(5.0);
            let pts = cubic_with_hodograph_roots(p0, a, r1, r2);
            worst = worst.max(check_against_adaptive(pts, 1e-13, what));
        }
    };
    for x in [0.0, 0.25, 1.0 / 3.0, 0.5, 0.61803398875, 0.9, 1.0] {
        for other in [
            DVec2::new(0.4, 0.3),
            DVec2::new(2.0, -1.0),
            DVec2::new(x, 0.0),
        ] {
            check(DVec2::new(x, 0.0), other, &format!("cusp at {x}"), &mut rng);
            for eps in [1e-3, 1e-6, 1e-9, 1e-12] {
                check(
                    DVec2::new(x, eps),
                    other,
                    &format!("near-cusp at {x} + {eps}i"),
                    &mut rng,
                );
            }
        }
    }
    for x in [-1e-3, -1e-9, -1e-14, 1.0 + 1e-14, 1.0 + 1e-6, 1.1] {
        for eps in [0.0, 1e-12, 1e-8, 1e-4] {
            check(
                DVec2::new(x, eps),
                DVec2::new(0.5, 0.2),
                &format!("root just outside at {x} + {eps}i"),
                &mut rng,
            );
        }
    }
    for r in [
        DVec2::new(0.5, 0.1),
        DVec2::new(0.3, 1e-7),
        DVec2::new(0.7, 0.0),
    ] {
        check(r, r, &format!("double root {r}"), &mut rng);
        check(
            r,
            DVec2::new(r.x, -r.y),
            &format!("conjugate pair {r}"),
            &mut rng,
        );
    }
    println!("worst relative difference on cusps and near-cusps: {worst:e}");

    // Degenerate curves.
    let p = DVec2::new(3.0, -2.0);
    assert_eq!(
        BezierCurve::new(vec![p; 4], None)
            .unwrap()
            .arc_length(None)
            .unwrap(),
        0.0
    );
    assert_eq!(
        bezier::arc_lengths::<DVec2>(&[1.0, 2.0, 1.0, 2.0, 1.0, 2.0], 2, None).unwrap(),
        vec![0.0]
    );
    // Collinear control points, the middle ones beyond the ends: the curve doubles back.
    for _ in 0..50 {
        let (o, d) = (rng.point2(5.0), rng.point2(1.0));
        let s: Vec<f64> = (0..4).map(|_| rng.range(-2.0, 2.0)).collect();
        check_against_adaptive(s.iter().map(|&s| o + d * s).collect(), 1e-13, "collinear");
    }
    // A line: the chord.
    let line = BezierCurve::new(pts2(&[(1.0, 1.0), (4.0, 5.0)]), None).unwrap();
    assert_close(line.arc_length(None).unwrap(), 5.0, 1e-15 * 5.0, "line");
}

#[test]
fn arc_length_of_straight_cubics_with_stops_has_a_closed_form() {
    // z' = a (t − r1)(t − r2) with a, r1, r2 real: a straight line traversed at speed
    // |a| |(t − r1)(t − r2)|, stopping (and reversing) at r1 and r2 when they lie in [0, 1].
    // ∫ |(t − r1)(t − r2)| dt by the antiderivative of t³/3 − (r1 + r2) t²/2 + r1 r2 t, piecewise
    // between the sorted roots.
    let exact = |a: f64, r1: f64, r2: f64| {
        let f = |t: f64| t * t * t / 3.0 - (r1 + r2) * t * t / 2.0 + r1 * r2 * t;
        let mut cuts = vec![0.0];
        for r in [r1.min(r2), r1.max(r2)] {
            if r > 0.0 && r < 1.0 {
                cuts.push(r);
            }
        }
        cuts.push(1.0);
        a.abs()
            * cuts
                .windows(2)
                .map(|w| (f(w[1]) - f(w[0])).abs())
                .sum::<f64>()
    };
    for (r1, r2) in [
        (0.3, 0.3),
        (0.5, 0.5),
        (0.0, 0.0),
        (1.0, 1.0),
        (0.2, 0.7),
        (1.0 / 3.0, 2.0 / 3.0),
        (0.0, 1.0),
        (-0.5, 0.4),
        (0.25, 1.5),
    ] {
        let a = DVec2::new(1.5, -2.0);
        let pts = cubic_with_hodograph_roots(
            DVec2::new(1.0, 1.0),
            a,
            DVec2::new(r1, 0.0),
            DVec2::new(r2, 0.0),
        );
        let l = BezierCurve::new(pts, None)
            .unwrap()
            .arc_length(None)
            .unwrap();
        let e = exact(a.length(), r1, r2);
        assert_close(l, e, 1e-13 * e, &format!("roots {r1}, {r2}"));
    }
}

/// Closed form of the quadratic Bézier's length: the hodograph is `u t + v` with
/// `u = 2(P0 − 2P1 + P2)`, `v = 2(P1 − P0)`; `|u t + v| = √A · √((t + B/2A)² + m)` with
/// `A = u·u`, `B = 2 u·v`, `C = v·v`, `m = C/A − (B/2A)² ≥ 0`, and
/// `∫ √(w² + m) dw = (w √(w² + m) + m asinh(w/√m))/2` (`w |w|/2` when `m = 0`).
/// Also returns the size of the terms, for the conditioning of the difference.
fn quadratic_length_closed_form(p: &[DVec2]) -> (f64, f64) {
    let u = 2.0 * (p[0] - 2.0 * p[1] + p[2]);
    let v = 2.0 * (p[1] - p[0]);
    let (a, b, c) = (u.dot(u), 2.0 * u.dot(v), v.dot(v));
    if a == 0.0 {
        return (c.sqrt(), c.sqrt());
    }
    let shift = b / (2.0 * a);
    let m = (c / a - shift * shift).max(0.0);
    let g = |w: f64| {
        if m == 0.0 {
            0.5 * w * w.abs()
        } else {
            0.5 * (w * (w * w + m).sqrt() + m * (w / m.sqrt()).asinh())
        }
    };
    let (g1, g0) = (g(1.0 + shift), g(shift));
    (a.sqrt() * (g1 - g0), a.sqrt() * (g1.abs() + g0.abs()))
}

#[test]
fn quadratic_arc_length_matches_the_closed_form() {
    let parabola = pts2(&[(0.0, 0.0), (0.5, 0.0), (1.0, 1.0)]);
    let (exact, _) = quadratic_length_closed_form(&parabola);
    assert_close(
        exact,
        (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0,
        1e-15,
        "the closed form itself",
    );
    let mut rng = Rng::new(5);
    let mut well_conditioned = 0;
    for i in 0..2000 {
        let p = random_curve(&mut rng, 2);
        let (exact, size) = quadratic_length_closed_form(&p);
        let l = BezierCurve::new(p, None).unwrap().arc_length(None).unwrap();
        // The closed form is a difference; its own rounding is ~1e-16 × the terms' size.
        let tol = 1e-13 * exact + 4e-16 * size;
        if size <= 10.0 * exact {
            well_conditioned += 1;
        }
        assert_close(l, exact, tol, &format!("random quadratic {i}"));
    }
    assert!(well_conditioned > 1800, "{well_conditioned}");
    // Near-cusps of quadratics: the control points almost collinear with P1 beyond the end.
    for eps in [1e-3, 1e-6, 1e-9, 1e-12, 0.0] {
        let p = pts2(&[(0.0, 0.0), (2.0, eps), (1.0, 0.0)]);
        let (exact, size) = quadratic_length_closed_form(&p);
        let l = BezierCurve::new(p, None).unwrap().arc_length(None).unwrap();
        assert_close(
            l,
            exact,
            1e-13 * exact + 4e-16 * size,
            &format!("eps {eps}"),
        );
    }
}

#[test]
fn batched_arc_lengths_equal_the_single_ones_for_every_path() {
    let mut rng = Rng::new(8);
    for degree in 1..=5 {
        let curves: Vec<BezierCurve<DVec2>> = (0..20)
            .map(|_| BezierCurve::new(random_curve(&mut rng, degree), None).unwrap())
            .collect();
        for accuracy in [None, Some(1e-12), Some(1e-13), Some(0.5)] {
            assert_batch_is_single(&curves, degree, accuracy);
        }
    }
    let curves: Vec<BezierCurve<DVec3>> = (0..10)
        .map(|_| BezierCurve::new((0..4).map(|_| rng.point3(5.0)).collect(), None).unwrap())
        .collect();
    assert_batch_is_single(&curves, 3, None);
    // A planar cubic in 3D (z = 0) takes the adaptive path and agrees with the 2D fast path.
    let c2 = random_curve(&mut rng, 3);
    let c3: Vec<DVec3> = c2.iter().map(|p| p.extend(0.0)).collect();
    let (l2, l3) = (
        BezierCurve::new(c2, None)
            .unwrap()
            .arc_length(None)
            .unwrap(),
        BezierCurve::new(c3, None)
            .unwrap()
            .arc_length(None)
            .unwrap(),
    );
    assert_close(l2, l3, 1e-12 * l2, "planar 3D curve");
}

#[test]
fn batched_arc_lengths_report_bad_input_as_before() {
    let mut rng = Rng::new(9);
    let good: Vec<f64> = (0..3)
        .flat_map(|_| random_curve(&mut rng, 3))
        .flat_map(|p| [p.x, p.y])
        .collect();
    for (bad, text) in [
        (f64::NAN, "coordinate 5 is NaN".to_string()),
        (f64::INFINITY, format!("coordinate 5 is {INFINITY_TEXT}")),
    ] {
        let mut flat = good.clone();
        flat[8 + 5] = bad;
        let err = bezier::arc_lengths::<DVec2>(&flat, 3, None).unwrap_err();
        // The same error as building that curve (compared as text: NaN ≠ NaN).
        assert!(matches!(err, Error::NotFinite { .. }));
        assert_eq!(
            message(err.clone()),
            message(BezierCurve::<DVec2>::from_flat(&flat[8..16], None).unwrap_err())
        );
        assert!(message(err).contains(&text));
    }
    assert!(
        message(bezier::arc_lengths::<DVec2>(&good[..15], 3, None).unwrap_err())
            .contains("15 coordinates do not split")
    );
    assert!(
        message(bezier::arc_lengths::<DVec2>(&good, 0, None).unwrap_err()).contains("do not split")
    );
    assert!(
        message(bezier::arc_lengths::<DVec2>(&[], 3, None).unwrap_err()).contains("do not split")
    );
    for accuracy in [0.0, -1.0, f64::NAN] {
        assert!(matches!(
            bezier::arc_lengths::<DVec2>(&good, 3, Some(accuracy)).unwrap_err(),
            Error::InvalidTolerance { .. }
        ));
    }
}

#[test]
fn arc_length_with_an_accuracy_below_rounding_still_returns() {
    // 1e-16 absolute on a curve ~20 long cannot be met in floating point; the quadrature's
    // work budget ends the refinement with an estimate as good as the default one.
    let mut rng = Rng::new(61);
    let pts: Vec<DVec2> = (0..6).map(|_| rng.point2(20.0)).collect();
    let c = BezierCurve::new(pts, None).unwrap();
    let tight = c.arc_length(Some(1e-16)).unwrap();
    let default = c.arc_length(None).unwrap();
    assert_close(tight, default, 1e-12 * default, "tight vs default accuracy");
}

/// The capability traits: curvature written once (the default method) agrees between a Bézier
/// curve, the same curve as a B-spline and as a one-piece composite; the default dense sampling
/// of a composite curve matches point evaluation.
#[test]
fn capability_traits_agree_across_curve_types() {
    use splinelab::bezier::CompositeCurve;
    let pts = pts2(&[(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)]);
    let bez = BezierCurve::new(pts.clone(), None).unwrap();
    let bsp =
        splinelab::BSplineCurve::new(pts, 3, vec![0., 0., 0., 0., 1., 1., 1., 1.], None).unwrap();
    let comp = CompositeCurve::new(vec![bez.clone()], &[0.0, 1.0]).unwrap();
    for t in [0.0, 0.3, 0.5, 1.0] {
        let k = bez.curvature(t).unwrap();
        assert_close(bsp.curvature(t).unwrap(), k, 1e-12, "B-spline curvature");
        assert_close(comp.curvature(t).unwrap(), k, 1e-12, "composite curvature");
    }
    let ts = [0.0, 0.25, 0.75, 1.0];
    let mut out = [0.0; 8];
    ParamCurve::sample_into(&comp, &ts, &mut out).unwrap();
    for (k, &t) in ts.iter().enumerate() {
        let p = bez.evaluate(t).unwrap();
        assert_close2(
            DVec2::new(out[2 * k], out[2 * k + 1]),
            p,
            1e-12,
            "composite sample",
        );
    }
    let mut uniform = [0.0; 6];
    comp.sample_uniform_into(3, &mut uniform).unwrap();
    assert_eq!(&uniform[4..], &[8.0, 2.0]);
    assert_eq!(bez.control_box().unwrap().max, DVec2::new(8.0, 4.0));
    assert!(ParamCurve::sample_into(&comp, &[2.0], &mut [0.0; 2]).is_err());
}

/// A degree-64 curve: 65 seeded random control points in [0, 100]², with weights in
/// [0.5, 2] when `rational` (the hostile case of issue 15: a fine tolerance on it used to take
/// seconds before failing).
fn degree_64(rational: bool) -> BezierCurve<DVec2> {
    let mut rng = Rng::new(64);
    let pts: Vec<DVec2> = (0..65)
        .map(|_| DVec2::new(rng.range(0.0, 100.0), rng.range(0.0, 100.0)))
        .collect();
    let w: Vec<f64> = (0..65).map(|_| rng.range(0.5, 2.0)).collect();
    BezierCurve::new(pts, rational.then_some(&w[..])).unwrap()
}

#[test]
fn flatten_refuses_a_too_fine_tolerance_from_its_estimate() {
    for rational in [false, true] {
        let c = degree_64(rational);
        let e = c.flatten(3e-8).unwrap_err();
        let m = e.to_string();
        assert!(matches!(e, Error::TooLarge { .. }), "{m}");
        // The refusal comes from the estimate made before flattening, not from the guard.
        assert!(m.contains("estimated before flattening"), "{m}");
        assert!(m.contains("at most 65536"), "{m}");
        assert!(c.flatten_estimate(3e-8).is_err());
    }
}

#[test]
fn flatten_estimate_is_never_below_the_polyline_it_bounds() {
    // The estimate is a count of equal steps per piece that provably suffices; the greedy
    // polyline (near the fewest chords) must not need more.
    let mut curves = hard_curves();
    curves.push(("degree 64", degree_64(false)));
    curves.push(("rational degree 64", degree_64(true)));
    for (name, c) in curves {
        for tol in [0.1, 1e-3, 1e-4] {
            let segments = c.flatten(tol).unwrap().len() - 1;
            let estimate = c.flatten_estimate(tol).unwrap();
            assert!(
                segments <= estimate,
                "{name}, tolerance {tol}: {segments} segments, estimate {estimate}"
            );
        }
    }
}

#[test]
fn flatten_of_a_degree_64_curve_stays_within_the_tolerance() {
    for rational in [false, true] {
        let c = degree_64(rational);
        let (pts, w) = (c.control_points(), c.weights());
        for tol in [1e-2, 1e-3] {
            let poly = c.flatten(tol).unwrap();
            assert_eq!((poly[0], poly[poly.len() - 1]), (pts[0], pts[64]));
            let mut worst = 0.0f64;
            for k in 0..=2000 {
                let p = bernstein_sum2(&pts, Some(&w), k as f64 / 2000.0);
                worst = worst.max(distance_to_polyline(p, &poly));
            }
            assert!(
                worst <= tol * (1.0 + 1e-9),
                "rational {rational}, tolerance {tol}: a curve point is {worst} from the polyline"
            );
        }
    }
}
