//! B-spline curves against independent expectations: the Croatian quadratic example (with the
//! syllabus' corrected polynomials), the notes' matrices, Bézier special cases, invariants of
//! knot insertion and extraction, and fixtures from scipy's BSpline
//! (`tests/fixtures/make_bspline_fixtures.py`). Runs natively and in Node.

mod common;

use common::*;
use splinelab::bezier::{self, BezierCurve};
use splinelab::bspline::{self, BSplineCurve, KnotKind, Parameterization};
use splinelab::prelude::*;
use splinelab::{DVec2, DVec3};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// The quadratic example of the Croatian notes: p = 2, six points, U = [0,0,0,1,2,3,4,4,4].
fn croatian() -> BSplineCurve<DVec2> {
    let pts = pts2(&[
        (0.0, 0.0),
        (1.0, 2.0),
        (3.0, 3.0),
        (5.0, 1.0),
        (6.0, 3.0),
        (8.0, 0.0),
    ]);
    BSplineCurve::new(
        pts,
        2,
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0],
        None,
    )
    .unwrap()
}

/// The syllabus' basis polynomials of the Croatian example: N_{i,2}(u), piece by piece.
fn croatian_basis(i: usize, u: f64) -> f64 {
    let span = (u.floor() as usize).min(3);
    match (i, span) {
        (0, 0) => (1.0 - u).powi(2),
        (1, 0) => u * (4.0 - 3.0 * u) / 2.0,
        (1, 1) => (2.0 - u).powi(2) / 2.0,
        (2, 0) => u * u / 2.0,
        (2, 1) => (-2.0 * u * u + 6.0 * u - 3.0) / 2.0,
        (2, 2) => (3.0 - u).powi(2) / 2.0,
        (3, 1) => (u - 1.0).powi(2) / 2.0,
        (3, 2) => (-2.0 * u * u + 10.0 * u - 11.0) / 2.0,
        (3, 3) => (4.0 - u).powi(2) / 2.0,
        (4, 2) => (u - 2.0).powi(2) / 2.0,
        (4, 3) => (-3.0 * u * u + 20.0 * u - 32.0) / 2.0,
        (5, 3) => (u - 3.0).powi(2),
        _ => 0.0,
    }
}

#[test]
fn croatian_example_basis_matches_the_corrected_polynomials() {
    let c = croatian();
    for k in 0..=400 {
        let u = k as f64 / 100.0;
        let basis = c.basis(u).unwrap();
        for (i, &b) in basis.iter().enumerate() {
            assert_close(b, croatian_basis(i, u), 1e-14, &format!("N_{i},2({u})"));
        }
    }
    // The notes print +11 in N_{3,2} on [2, 3]; the value at u = 2.5 tells them apart.
    assert_close(c.basis(2.5).unwrap()[3], 0.75, 1e-15, "N_3,2(2.5)");
}

#[test]
fn non_zero_basis_is_the_span_and_its_p_plus_1_polynomials() {
    let c = croatian();
    // The span of u in U = [0,0,0,1,2,3,4,4,4]: floor(u) + 2, and the last span (k = 5) at u = 4.
    for (u, span) in [
        (0.0, 2),
        (0.5, 2),
        (1.0, 3),
        (2.5, 4),
        (3.0, 5),
        (3.99, 5),
        (4.0, 5),
    ] {
        let (k, values) = c.basis_non_zero(u).unwrap();
        assert_eq!(k, span, "span of {u}");
        assert_eq!(values.len(), 3, "p + 1 values at {u}");
        for (j, &v) in values.iter().enumerate() {
            let i = k - 2 + j;
            assert_close(v, croatian_basis(i, u), 1e-14, &format!("N_{i},2({u})"));
        }
    }
    // The syllabus' worked values at u = 5/2: 1/8, 3/4, 1/8 for N_2, N_3, N_4.
    let (_, values) = c.basis_non_zero(2.5).unwrap();
    assert_eq!(values, vec![0.125, 0.75, 0.125]);
    let err = c.basis_non_zero(4.5).unwrap_err().to_string();
    assert!(err.contains("4.5") && err.contains("[0, 4]"), "{err}");
}

#[test]
fn segment_matrices_match_the_notes() {
    let c = croatian();
    // Global form on [1, 2]: columns N_{1,2}, N_{2,2}, N_{3,2} = (2−u)²/2, (−2u²+6u−3)/2, (u−1)²/2.
    let m = c.segment_matrix(3, false).unwrap();
    let expected = [[0.5, -1.0, 0.5], [-2.0, 3.0, -1.0], [2.0, -1.5, 0.5]];
    for (r, row) in expected.iter().enumerate() {
        for (j, &e) in row.iter().enumerate() {
            assert_close(m[r][j], e, 1e-14, &format!("global M[{r}][{j}]"));
        }
    }
    // Local form of both interior spans: the periodic segment.
    let periodic = [[0.5, -1.0, 0.5], [-1.0, 1.0, 0.0], [0.5, 0.5, 0.0]];
    for k in [3, 4] {
        let m = c.segment_matrix(k, true).unwrap();
        for (r, row) in periodic.iter().enumerate() {
            for (j, &e) in row.iter().enumerate() {
                assert_close(m[r][j], e, 1e-14, &format!("span {k} M[{r}][{j}]"));
            }
        }
    }
    let q = bspline::uniform_segment_matrix(2);
    let cubic = bspline::uniform_segment_matrix(3);
    let expected_cubic = [
        [-1.0, 3.0, -3.0, 1.0],
        [3.0, -6.0, 3.0, 0.0],
        [-3.0, 0.0, 3.0, 0.0],
        [1.0, 4.0, 1.0, 0.0],
    ];
    for r in 0..3 {
        for j in 0..3 {
            assert_close(q[r][j], periodic[r][j], 1e-15, "uniform quadratic");
        }
    }
    for r in 0..4 {
        for j in 0..4 {
            assert_close(
                cubic[r][j],
                expected_cubic[r][j] / 6.0,
                1e-15,
                "uniform cubic",
            );
        }
    }
    assert!(c.segment_matrix(1, true).is_err());
}

/// A random valid knot vector for `count` points of degree `p`, with some repeated knots.
fn random_knots(rng: &mut Rng, count: usize, p: usize, clamped: bool) -> Vec<f64> {
    let m = count + p + 1;
    loop {
        let mut k: Vec<f64> = (0..m)
            .map(|_| (rng.range(0.0, 10.0) * 2.0).round() / 2.0)
            .collect();
        k.sort_by(f64::total_cmp);
        if clamped {
            for i in 0..=p {
                k[i] = k[0];
                k[m - 1 - i] = k[m - 1];
            }
        }
        if let Ok(kv) = bspline::KnotVector::new(k.clone(), p, count) {
            let _ = kv;
            return k;
        }
    }
}

#[test]
fn partition_of_unity_and_non_negativity_on_random_knots() {
    let mut rng = Rng::new(17);
    for case in 0..60 {
        let p = 1 + case % 5;
        let count = p + 1 + (case % 7);
        let knots = random_knots(&mut rng, count, p, case % 2 == 0);
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let c = BSplineCurve::new(pts, p, knots.clone(), None).unwrap();
        let (a, b) = c.domain();
        for k in 0..=50 {
            let u = a + (b - a) * k as f64 / 50.0;
            let basis = c.basis(u).unwrap();
            let sum: f64 = basis.iter().sum();
            assert_close(
                sum,
                1.0,
                1e-13,
                &format!("seed 17 case {case}: Σ N at u = {u}, knots {knots:?}"),
            );
            assert!(
                basis.iter().all(|&v| v >= -1e-15),
                "non-negative: {basis:?}"
            );
            assert!(
                basis.iter().filter(|&&v| v != 0.0).count() <= p + 1,
                "at most p + 1 non-zero"
            );
        }
    }
}

#[test]
fn bezier_knots_give_the_bezier_curve_and_de_boor_is_de_casteljau() {
    let pts = pts2(&[(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)]);
    let b = BSplineCurve::new(
        pts.clone(),
        3,
        vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        None,
    )
    .unwrap();
    let bez = BezierCurve::new(pts.clone(), None).unwrap();
    for k in 0..=20 {
        let t = k as f64 / 20.0;
        assert_close2(
            b.evaluate(t).unwrap(),
            bez.evaluate(t).unwrap(),
            1e-14,
            "B-spline = Bézier",
        );
    }
    // On Bézier knots, de Boor's α is t at every step: the triangles coincide.
    let tri = b.de_boor(0.25).unwrap();
    assert_eq!(tri.len(), 10);
    assert_eq!(tri, bez.de_casteljau(0.25).unwrap());
    assert_eq!(*tri.last().unwrap(), DVec2::new(29.0 / 16.0, 23.0 / 16.0));
}

#[test]
fn de_boor_triangle_ends_at_the_point() {
    let c = croatian();
    for k in 0..=16 {
        let u = k as f64 / 4.0;
        let tri = c.de_boor(u).unwrap();
        assert_eq!(tri.len(), 6);
        assert_close2(
            *tri.last().unwrap(),
            c.evaluate(u).unwrap(),
            1e-14,
            "de Boor = basis sum",
        );
    }
}

#[test]
fn de_boor_alphas_of_the_croatian_example_by_hand() {
    // u = 3/2 in span k = 3 of U = [0,0,0,1,2,3,4,4,4], p = 2:
    // r = 1: α_1 = (u − u_2)/(u_4 − u_2) = 3/4, α_2 = (u − u_3)/(u_5 − u_3) = 1/4;
    // r = 2: α_2 = (u − u_3)/(u_4 − u_3) = 1/2.
    let (k, alphas) = croatian().de_boor_alphas(1.5).unwrap();
    assert_eq!(k, 3);
    let got: Vec<_> = alphas
        .iter()
        .map(|a| (a.level, a.j, a.lo, a.hi, a.denominator, a.value))
        .collect();
    assert_eq!(
        got,
        vec![
            (1, 1, 2, 4, 2.0, 0.75),
            (1, 2, 3, 5, 2.0, 0.25),
            (2, 2, 3, 4, 1.0, 0.5),
        ]
    );
}

#[test]
fn de_boor_alphas_on_bezier_knots_are_all_t() {
    // Knots 0^4 1^4: every α_j^r = (t − 0)/(1 − 0) = t, the de Casteljau factor.
    let pts = pts2(&[(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)]);
    let b = BSplineCurve::new(pts, 3, vec![0., 0., 0., 0., 1., 1., 1., 1.], None).unwrap();
    let (k, alphas) = b.de_boor_alphas(0.25).unwrap();
    assert_eq!(k, 3);
    assert_eq!(alphas.len(), 6);
    let order: Vec<_> = alphas.iter().map(|a| (a.level, a.j)).collect();
    assert_eq!(order, vec![(1, 1), (1, 2), (1, 3), (2, 2), (2, 3), (3, 3)]);
    assert!(alphas
        .iter()
        .all(|a| a.value == 0.25 && a.denominator == 1.0));
    assert!(b.de_boor_alphas(1.5).is_err());
    assert!(b.de_boor_alphas(f64::NAN).is_err());
}

#[test]
fn matrix_form_evaluation_of_the_croatian_example_by_hand() {
    let c = croatian();
    // Span 3 (u ∈ [1, 2]) at t = 1/2, u = 3/2: [1/4 1/2 1] M gives the syllabus' basis values
    // N_{1,2} = (2 − u)²/2 = 1/8, N_{2,2} = (−2u² + 6u − 3)/2 = 3/4, N_{3,2} = (u − 1)²/2 = 1/8;
    // the point is (1/8)(1, 2) + (3/4)(3, 3) + (1/8)(5, 1) = (3, 21/8).
    let f = c.evaluate_matrix_form(3, 0.5).unwrap();
    assert_eq!(f.monomials, vec![0.25, 0.5, 1.0]);
    assert_eq!(f.basis, vec![0.125, 0.75, 0.125]);
    assert_eq!(f.point, DVec2::new(3.0, 2.625));
    // The first span (u ∈ [0, 1]) at t = 1/2: N_{0,2} = (1 − u)² = 1/4, N_{1,2} = u(4 − 3u)/2 = 5/8,
    // N_{2,2} = u²/2 = 1/8; the point (5/8)(1, 2) + (1/8)(3, 3) = (1, 13/8).
    let f = c.evaluate_matrix_form(2, 0.5).unwrap();
    assert_eq!(f.basis, vec![0.25, 0.625, 0.125]);
    assert_eq!(f.point, DVec2::new(1.0, 1.625));
    // t = 1 is the end of the segment: [1 1 1] M is the basis at u_{k+1}.
    let f = c.evaluate_matrix_form(5, 1.0).unwrap();
    assert_eq!(f.monomials, vec![1.0, 1.0, 1.0]);
    assert_eq!(f.point, DVec2::new(8.0, 0.0));
    assert!(c.evaluate_matrix_form(3, 1.5).is_err());
    assert!(c.evaluate_matrix_form(3, -0.25).is_err());
    assert!(c.evaluate_matrix_form(3, f64::NAN).is_err());
    assert!(c.evaluate_matrix_form(0, 0.5).is_err());
    assert!(c.evaluate_matrix_form(6, 0.5).is_err());
    assert!(c.evaluate_matrix_form(usize::MAX, 0.5).is_err());
}

#[test]
fn clamped_curves_interpolate_their_end_points() {
    let c = croatian();
    assert_eq!(c.evaluate(0.0).unwrap(), DVec2::new(0.0, 0.0));
    assert_eq!(c.evaluate(4.0).unwrap(), DVec2::new(8.0, 0.0));
    // End derivatives of a clamped curve: p (P1 − P0)/(u_{p+1} − u_1).
    assert_close2(
        c.derivative(0.0, 1).unwrap(),
        DVec2::new(2.0, 4.0),
        1e-14,
        "start tangent",
    );
    assert_close2(
        c.derivative(4.0, 1).unwrap(),
        DVec2::new(4.0, -6.0),
        1e-14,
        "end tangent",
    );
}

#[test]
fn insertion_alphas_of_the_croatian_example_by_hand() {
    // U = [0,0,0,1,2,3,4,4,4], p = 2, α_i = (s − u_i)/(u_{i+2} − u_i), i = k − 1, k.
    let c = croatian();
    // s = 3/2 in span 3: α_2 = (3/2 − 0)/(2 − 0) = 3/4, α_3 = (3/2 − 1)/(3 − 1) = 1/4.
    assert_eq!(c.insertion_alphas(1.5).unwrap(), (3, vec![0.75, 0.25]));
    // s = 7/2 in span 5: α_4 = (7/2 − 2)/(4 − 2) = 3/4, α_5 = (7/2 − 3)/(4 − 3) = 1/2.
    assert_eq!(c.insertion_alphas(3.5).unwrap(), (5, vec![0.75, 0.5]));
    // s = 4, the end of the domain, is in the last span: α_4 = 2/2, α_5 = 1/1.
    assert_eq!(c.insertion_alphas(4.0).unwrap(), (5, vec![1.0, 1.0]));
    assert!(c.insertion_alphas(4.5).is_err());
    assert!(c.insertion_alphas(f64::INFINITY).is_err());
}

#[test]
fn knot_insertion_matches_a_hand_computed_case_and_keeps_the_curve() {
    let c = croatian();
    let p = c.control_points();
    let r = c.insert_knot(1.5, 1).unwrap();
    assert_eq!(
        r.knots().as_slice(),
        &[0.0, 0.0, 0.0, 1.0, 1.5, 2.0, 3.0, 4.0, 4.0, 4.0]
    );
    // α_2 = (1.5 − 0)/(2 − 0) = 3/4, α_3 = (1.5 − 1)/(3 − 1) = 1/4.
    let expected = vec![
        p[0],
        p[1],
        p[1] * 0.25 + p[2] * 0.75,
        p[2] * 0.75 + p[3] * 0.25,
        p[3],
        p[4],
        p[5],
    ];
    assert_eq!(r.control_points(), expected);
    assert_eq!(r.weights(), vec![1.0; 7]);
    let mut rng = Rng::new(23);
    for case in 0..30 {
        let pdeg = 1 + case % 4;
        let count = pdeg + 2 + case % 5;
        let knots = random_knots(&mut rng, count, pdeg, case % 3 != 0);
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let w: Vec<f64> = (0..count).map(|_| rng.range(0.5, 2.0)).collect();
        let c = BSplineCurve::new(pts, pdeg, knots, Some(&w)).unwrap();
        let (a, b) = c.domain();
        let u = rng.range(a, b);
        let times = 1 + case % 2;
        let Ok(r) = c.insert_knot(u, times) else {
            continue;
        };
        assert_eq!(r.control_points().len(), count + times);
        for k in 0..=40 {
            let s = a + (b - a) * k as f64 / 40.0;
            assert_close2(
                r.evaluate(s).unwrap(),
                c.evaluate(s).unwrap(),
                1e-11,
                &format!("case {case}: insertion keeps C({s})"),
            );
        }
        let refined = c.refine(&[a + 0.3 * (b - a), a + 0.7 * (b - a), a + 0.3 * (b - a)]);
        if let Ok(refined) = refined {
            for k in 0..=40 {
                let s = a + (b - a) * k as f64 / 40.0;
                assert_close2(
                    refined.evaluate(s).unwrap(),
                    c.evaluate(s).unwrap(),
                    1e-11,
                    "refinement keeps the curve",
                );
            }
        }
    }
}

#[test]
fn extracted_bezier_segments_reproduce_the_curve() {
    let mut rng = Rng::new(29);
    for case in 0..30 {
        let p = 1 + case % 4;
        let count = p + 1 + case % 6;
        let knots = random_knots(&mut rng, count, p, case % 2 == 0);
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let w: Vec<f64> = (0..count)
            .map(|_| {
                if case % 3 == 0 {
                    rng.range(0.5, 2.0)
                } else {
                    1.0
                }
            })
            .collect();
        let c = BSplineCurve::new(pts, p, knots, Some(&w)).unwrap();
        let segments = c.to_bezier().unwrap();
        let spans: Vec<usize> = c.knots().spans().collect();
        assert_eq!(
            segments.len(),
            spans.len(),
            "one segment per non-empty span"
        );
        let u = c.knots().as_slice();
        for (seg, &k) in segments.iter().zip(&spans) {
            assert_eq!(seg.degree(), p);
            for j in 0..=10 {
                // At a break (multiplicity p + 1) the curve takes the right piece's value.
                if j == 10
                    && k + 1 < c.control_points().len()
                    && c.knots().multiplicity(u[k + 1]) > p
                {
                    continue;
                }
                let t = j as f64 / 10.0;
                let s = u[k] + (u[k + 1] - u[k]) * t;
                assert_close2(
                    seg.evaluate(t).unwrap(),
                    c.evaluate(s).unwrap(),
                    1e-11,
                    &format!("case {case} span {k}"),
                );
            }
        }
    }
}

#[test]
fn derivative_matches_the_control_point_difference_formula() {
    // C'(u) = Σ N_{i,p−1}(u) Q_i with Q_i = p (P_{i+1} − P_i)/(u_{i+p+1} − u_{i+1}) on the knots
    // without their first and last value.
    let mut rng = Rng::new(31);
    for case in 0..20 {
        let p = 2 + case % 3;
        let count = p + 2 + case % 4;
        let knots = random_knots(&mut rng, count, p, true);
        if knots
            .windows(2)
            .any(|w| w[0] == w[1] && w[0] > knots[0] && w[1] < knots[knots.len() - 1])
        {
            continue; // keep the derivative continuous for this comparison
        }
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let c = BSplineCurve::new(pts.clone(), p, knots.clone(), None).unwrap();
        let q: Vec<DVec2> = (0..count - 1)
            .map(|i| (pts[i + 1] - pts[i]) * (p as f64 / (knots[i + p + 1] - knots[i + 1])))
            .collect();
        let d = BSplineCurve::new(q, p - 1, knots[1..knots.len() - 1].to_vec(), None).unwrap();
        let (a, b) = c.domain();
        for k in 0..=30 {
            let u = a + (b - a) * k as f64 / 30.0;
            assert_close2(
                c.derivative(u, 1).unwrap(),
                d.evaluate(u).unwrap(),
                1e-10,
                &format!("case {case} u = {u}"),
            );
        }
        assert_eq!(
            c.derivative(a, p + 1).unwrap(),
            DVec2::ZERO,
            "order above the degree"
        );
    }
}

#[test]
fn closed_curves_join_with_full_continuity() {
    let pts = pts2(&[(0.0, 0.0), (4.0, 0.0), (5.0, 3.0), (2.0, 5.0), (-1.0, 3.0)]);
    for p in 1..=4 {
        let c = BSplineCurve::closed(pts.clone(), p, None).unwrap();
        assert_eq!(c.control_points().len(), pts.len() + p);
        let (a, b) = c.domain();
        assert_eq!((a, b), (p as f64, (pts.len() + p) as f64));
        for order in 0..p {
            assert_close2(
                c.derivative(a, order).unwrap(),
                c.derivative(b, order).unwrap(),
                1e-12,
                &format!("p = {p}, C^{order} at the seam"),
            );
        }
        // Dragging a wrapped point moves its copy.
        let mut d = c.clone();
        d.set_control_point(0, DVec2::new(1.0, -1.0)).unwrap();
        if p > 0 {
            assert_eq!(d.control_points()[pts.len()], DVec2::new(1.0, -1.0));
        }
        assert_close2(
            d.evaluate(a).unwrap(),
            d.evaluate(b).unwrap(),
            1e-12,
            "still closed after an edit",
        );
    }
}

#[test]
fn knot_multiplicity_lowers_continuity_as_the_table_says() {
    // Cubic: interior knot multiplicity 1, 2, 3, 4 → C2, C1, C0, break (the Croatian table).
    let pts: Vec<DVec2> = pts2(&[
        (0.0, 0.0),
        (1.0, 3.0),
        (3.0, 4.0),
        (5.0, 1.0),
        (6.0, 4.0),
        (8.0, 2.0),
        (9.0, 5.0),
        (11.0, 0.0),
    ]);
    for r in 1..=4usize {
        let mut knots = vec![0.0; 4];
        knots.extend(std::iter::repeat_n(1.0, r));
        let rest = pts.len() + 4 - knots.len() - 4;
        knots.extend((0..rest).map(|i| 2.0 + i as f64));
        let end = knots[knots.len() - 1] + 1.0;
        knots.extend([end; 4]);
        let c = BSplineCurve::new(pts.clone(), 3, knots, None).unwrap();
        let at_one = c
            .knot_continuity()
            .into_iter()
            .find(|k| k.knot == 1.0)
            .unwrap();
        assert_eq!((at_one.multiplicity, at_one.continuity), (r, 3 - r as i32));
        // Independent check: the Bézier segments on either side of u = 1, placed on their spans.
        let segs = c.to_bezier().unwrap();
        let u = c.knots().as_slice();
        let spans: Vec<usize> = c.knots().spans().collect();
        let i = spans.iter().position(|&k| u[k] == 1.0).unwrap();
        let left = segs[i - 1]
            .clone()
            .with_interval(u[spans[i - 1]], 1.0)
            .unwrap();
        let right = segs[i].clone().with_interval(1.0, u[spans[i] + 1]).unwrap();
        let found = bezier::check_continuity(&left, &right, 1e-9).unwrap();
        assert_eq!(found.c, 3 - r as i32, "multiplicity {r}");
    }
}

#[test]
fn parameterizations_and_knot_vectors_follow_the_notes() {
    let pts = pts2(&[
        (0.0, 0.0),
        (3.0, 4.0),
        (3.0, 4.0 + 9.0),
        (3.0 + 16.0, 13.0),
        (19.0, 13.0 + 1.0),
    ]);
    assert_eq!(
        bspline::parameterize(&pts, Parameterization::Uniform).unwrap(),
        vec![0.0, 1.0, 2.0, 3.0, 4.0]
    );
    assert_eq!(
        bspline::parameterize(&pts, Parameterization::Chord).unwrap(),
        vec![0.0, 5.0, 14.0, 30.0, 31.0]
    );
    let cen = bspline::parameterize(&pts, Parameterization::Centripetal).unwrap();
    assert_close(cen[4], 5f64.sqrt() + 3.0 + 4.0 + 1.0, 1e-14, "centripetal");
    // n = 4, p = 2.
    assert_eq!(
        bspline::knot_vector(&pts, 2, KnotKind::Uniform).unwrap(),
        (0..8).map(|i| i as f64).collect::<Vec<_>>()
    );
    assert_eq!(
        bspline::knot_vector(&pts, 2, KnotKind::Clamped).unwrap(),
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]
    );
    // Interior knots at the first n − p = 2 cumulative lengths; ends at the first 3 legs' total.
    assert_eq!(
        bspline::knot_vector(&pts, 2, KnotKind::Chord).unwrap(),
        vec![0.0, 0.0, 0.0, 5.0, 14.0, 30.0, 30.0, 30.0]
    );
    let k = bspline::knot_vector(&pts, 2, KnotKind::Centripetal).unwrap();
    assert_close(k[3], 5f64.sqrt(), 1e-15, "centripetal knot");
    assert_close(k[7], 5f64.sqrt() + 7.0, 1e-14, "centripetal end");
    let repeated = pts2(&[(0.0, 0.0), (1.0, 1.0), (1.0, 1.0), (2.0, 0.0)]);
    let e = bspline::parameterize(&repeated, Parameterization::Chord)
        .unwrap_err()
        .to_string();
    assert!(e.contains("points 1 and 2 coincide"), "{e}");
    assert!(bspline::knot_vector(&repeated, 2, KnotKind::Centripetal).is_err());
}

#[test]
fn phantom_points_make_a_uniform_cubic_pass_through_the_ends() {
    let pts = pts2(&[(0.0, 0.0), (2.0, 3.0), (5.0, 3.0), (7.0, 0.0)]);
    let ghost = bspline::phantom_points(&pts, 3).unwrap();
    assert_eq!(
        ghost[0],
        DVec2::new(-2.0, -3.0),
        "P_−1 = 2P_0 − P_1, collinear with P_0 P_1"
    );
    let knots = bspline::knot_vector(&ghost, 3, KnotKind::Uniform).unwrap();
    let c = BSplineCurve::new(ghost, 3, knots, None).unwrap();
    let (a, b) = c.domain();
    assert_close2(c.evaluate(a).unwrap(), pts[0], 1e-14, "starts at P0");
    assert_close2(c.evaluate(b).unwrap(), pts[3], 1e-14, "ends at Pn");
    assert!(bspline::phantom_points(&pts, 2).is_err());
}

#[test]
fn nurbs_circle_has_radius_exactly_one() {
    let pts = pts2(&CIRCLE_POINTS);
    let w: Vec<f64> = (0..9).map(circle_weight).collect();
    let knots = CIRCLE_KNOTS.to_vec();
    let c = BSplineCurve::new(pts, 2, knots, Some(&w)).unwrap();
    let mut out = vec![0.0; 2 * 1001];
    c.sample_uniform_into(1001, &mut out).unwrap();
    c.sample_uniform_into(0, &mut []).unwrap(); // count 0: nothing to write, no underflow
    for p in out.chunks(2) {
        assert_close(p[0].hypot(p[1]), 1.0, 1e-12, "radius");
    }
    for k in 1..10 {
        let u = k as f64 / 10.0;
        let d1 = c.derivative(u, 1).unwrap();
        assert_close(
            d1.dot(c.evaluate(u).unwrap()),
            0.0,
            1e-12,
            "tangent ⟂ radius",
        );
    }
    // 3D: the same circle lifted to z = 2 stays there.
    let pts3: Vec<DVec3> = c.control_points().iter().map(|p| p.extend(2.0)).collect();
    let c3 = BSplineCurve::new(pts3, 2, c.knots().as_slice().to_vec(), Some(&w)).unwrap();
    assert_close(c3.evaluate(0.3).unwrap().z, 2.0, 1e-15, "z");
}

#[test]
fn dense_sampling_equals_pointwise_evaluation() {
    let c = croatian();
    let us: Vec<f64> = (0..=200).map(|k| 4.0 * k as f64 / 200.0).rev().collect();
    let mut out = vec![0.0; us.len() * 2];
    c.sample_into(&us, &mut out).unwrap();
    for (k, &u) in us.iter().enumerate() {
        let e = c.evaluate(u).unwrap();
        assert_close2(
            DVec2::new(out[2 * k], out[2 * k + 1]),
            e,
            1e-13 * (1.0 + e.length()),
            &format!("u = {u} (unsorted input)"),
        );
    }
    let curves = c.basis_curves(41).unwrap();
    for i in 0..6 {
        for j in 0..41 {
            assert_close(
                curves[i * 41 + j],
                croatian_basis(i, j as f64 / 10.0),
                1e-14,
                "basis curve",
            );
        }
    }
}

#[test]
fn basis_table_is_the_cox_de_boor_triangle() {
    let (k, levels) = croatian().basis_table(1.5).unwrap();
    assert_eq!(k, 3);
    assert_eq!(levels[0], vec![1.0]);
    // Level 1 on span [1, 2): N_{2,1} = (2 − u)/(2 − 1), N_{3,1} = (u − 1)/(2 − 1).
    assert_eq!(levels[1], vec![0.5, 0.5]);
    for (j, v) in levels[2].iter().enumerate() {
        assert_close(*v, croatian_basis(1 + j, 1.5), 1e-15, "level 2");
    }
}

/// The scipy fixtures: `curve` blocks followed by evaluations, derivatives and basis values.
#[test]
fn fixtures_from_scipy_bspline() {
    let text = include_str!("fixtures/bspline_scipy.txt");
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
                let p = nums[0] as usize;
                let count = nums[1] as usize;
                let knots = nums[2..2 + count + p + 1].to_vec();
                let coords = &nums[2 + count + p + 1..];
                curve = Some(BSplineCurve::from_flat(coords, p, knots, None).unwrap());
            }
            "eval" => {
                let c = curve.as_ref().unwrap();
                let (u, order) = (nums[0], nums[1] as usize);
                let got = c.derivative(u, order).unwrap();
                let scale = 1.0 + nums[2].abs().max(nums[3].abs());
                assert_close2(
                    got,
                    DVec2::new(nums[2], nums[3]),
                    1e-12 * scale,
                    &format!("order {order} at u = {u}"),
                );
                checked += 1;
            }
            "basis" => {
                let c = curve.as_ref().unwrap();
                let got = c.basis(nums[0]).unwrap();
                for (i, (&g, &e)) in got.iter().zip(&nums[1..]).enumerate() {
                    assert_close(g, e, 1e-13, &format!("N_{i} at u = {}", nums[0]));
                }
                checked += 1;
            }
            other => panic!("unknown fixture line {other}"),
        }
    }
    assert!(checked > 100, "only {checked} fixture values");
}

#[test]
fn bad_input_gives_clear_errors() {
    let pts = pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 1.0)]);
    let err = |p: usize, k: Vec<f64>, w: Option<&[f64]>| {
        BSplineCurve::new(pts.clone(), p, k, w)
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        err(2, vec![0.0; 6], None),
        "knot vector must have n+p+2 = 3 + 2 + 2 = 7 values, got 6"
    );
    assert!(err(2, vec![0.0, 0.0, 0.0, 2.0, 1.0, 3.0, 3.0], None)
        .contains("u_4 = 1 comes after u_3 = 2"));
    assert!(err(2, vec![0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0], None).contains("empty"));
    assert!(err(2, vec![0.0, 0.0, 0.0, f64::NAN, 1.0, 1.0, 1.0], None).contains("knot 3 is NaN"));
    assert_eq!(
        err(0, vec![0.0; 5], None),
        "degree must be at least 1, got 0"
    );
    assert_eq!(
        err(4, vec![0.0; 9], None),
        "degree 4 needs at least p+1 = 5 control points, got 4"
    );
    assert!(err(
        2,
        vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
        Some(&[1.0, 1.0, -1.0, 1.0])
    )
    .contains("weight 2 is -1"));
    let c = croatian();
    assert_eq!(
        c.evaluate(4.5).unwrap_err().to_string(),
        "u = 4.5 is outside the domain [0, 4]"
    );
    assert!(c
        .evaluate(f64::NAN)
        .unwrap_err()
        .to_string()
        .contains("u is NaN"));
    assert!(c
        .insert_knot(4.0, 1)
        .unwrap_err()
        .to_string()
        .contains("multiplicity 4"));
    assert!(c
        .insert_knot(2.0, 3)
        .unwrap_err()
        .to_string()
        .contains("at most p+1 = 3"));
    assert!(
        c.insert_knot(2.0, 2).is_ok(),
        "multiplicity p + 1 inside is allowed (a break)"
    );
    let mut m = c.clone();
    assert!(m
        .set_control_point(6, DVec2::ZERO)
        .unwrap_err()
        .to_string()
        .contains("index 6"));
    assert!(KnotKind::parse("open")
        .unwrap_err()
        .to_string()
        .contains("\"open\""));
}

#[test]
fn repeated_control_points_keep_c2_but_a_triple_point_makes_a_corner() {
    // Uniform cubic with P3 repeated: the Croatian table's control-point multiplicity. Measured
    // at the knot where the repeated points are all active, between the Bézier segments.
    let measure = |pts: Vec<DVec2>| {
        let knots = bspline::knot_vector(&pts, 3, KnotKind::Uniform).unwrap();
        let c = BSplineCurve::new(pts, 3, knots, None).unwrap();
        let segs = c.to_bezier().unwrap();
        let u = c.knots().as_slice().to_vec();
        let spans: Vec<usize> = c.knots().spans().collect();
        (1..segs.len())
            .map(|i| {
                let l = segs[i - 1]
                    .clone()
                    .with_interval(u[spans[i - 1]], u[spans[i - 1] + 1])
                    .unwrap();
                let r = segs[i]
                    .clone()
                    .with_interval(u[spans[i]], u[spans[i] + 1])
                    .unwrap();
                bezier::check_continuity(&l, &r, 1e-9).unwrap()
            })
            .collect::<Vec<_>>()
    };
    let base = pts2(&[
        (0.0, 0.0),
        (1.0, 3.0),
        (3.0, 4.0),
        (5.0, 1.0),
        (6.0, 4.0),
        (8.0, 2.0),
    ]);
    let mut triple = base.clone();
    triple.splice(3..3, [base[3], base[3]]);
    let joints = measure(triple);
    assert!(joints.iter().all(|k| k.c >= 2), "C2 everywhere: {joints:?}");
    assert!(
        joints.iter().any(|k| k.g == 0),
        "a corner where the velocity vanishes: {joints:?}"
    );
    let joints = measure(base);
    assert!(joints.iter().all(|k| k.c >= 2 && k.g == 2), "{joints:?}");
}

#[test]
fn dense_derivatives_equal_the_pointwise_derivative() {
    let mut rng = Rng::new(37);
    for case in 0..24 {
        let p = 1 + case % 4;
        let count = p + 2 + case % 5;
        let knots = random_knots(&mut rng, count, p, case % 2 == 0);
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let w: Vec<f64> = (0..count).map(|_| rng.range(0.5, 2.0)).collect();
        let c =
            BSplineCurve::new(pts, p, knots, if case % 3 == 0 { None } else { Some(&w) }).unwrap();
        let (a, b) = c.domain();
        let us: Vec<f64> = (0..=60).map(|k| a + (b - a) * k as f64 / 60.0).collect();
        for order in 0..=3 {
            let mut out = vec![0.0; us.len() * 2];
            c.sample_derivatives_into(&us, order, &mut out).unwrap();
            for (k, &u) in us.iter().enumerate() {
                let e = c.derivative(u, order).unwrap();
                let got = DVec2::new(out[2 * k], out[2 * k + 1]);
                assert_close2(
                    got,
                    e,
                    1e-9 * (1.0 + e.length()),
                    &format!("case {case} order {order} u = {u}"),
                );
            }
        }
    }
}

#[test]
fn fast_dense_sampling_equals_the_pointwise_path_for_every_degree() {
    let mut rng = Rng::new(43);
    for case in 0..35 {
        let p = 1 + case % 7; // degrees 1–5 use the unrolled kernels, 6–7 the generic path
        let count = p + 1 + case % 6;
        let knots = random_knots(&mut rng, count, p, case % 2 == 1);
        let pts: Vec<DVec3> = (0..count).map(|_| rng.point3(5.0)).collect();
        let w: Vec<f64> = (0..count).map(|_| rng.range(0.5, 2.0)).collect();
        let c =
            BSplineCurve::new(pts, p, knots, if case % 3 == 0 { None } else { Some(&w) }).unwrap();
        let (a, b) = c.domain();
        let us: Vec<f64> = (0..=97).map(|k| a + (b - a) * k as f64 / 97.0).collect();
        let mut out = vec![0.0; us.len() * 3];
        c.sample_into(&us, &mut out).unwrap();
        let mut uniform = vec![0.0; us.len() * 3];
        c.sample_uniform_into(us.len(), &mut uniform).unwrap();
        for (k, &u) in us.iter().enumerate() {
            let e = c.evaluate(u).unwrap();
            let tol = 1e-12 * (1.0 + e.length());
            assert_close3(
                DVec3::from_slice(&out[3 * k..]),
                e,
                tol,
                &format!("case {case}, p = {p}, u = {u}"),
            );
            assert_close3(DVec3::from_slice(&uniform[3 * k..]), e, tol, "uniform");
        }
        // One sample is the start of the domain (as for Bézier curves); none writes nothing.
        let mut one = [0.0; 3];
        c.sample_uniform_into(1, &mut one).unwrap();
        let start = c.evaluate(a).unwrap();
        assert_close3(
            DVec3::from_slice(&one),
            start,
            1e-12 * (1.0 + start.length()),
            "count = 1",
        );
        c.sample_uniform_into(0, &mut []).unwrap();
        // Mixed densities: long runs take the per-span power form, short ones the basis
        // functions; every knot and both domain ends are sampled exactly too.
        let mut mixed: Vec<f64> = c.knots().as_slice()[p..count + 1].to_vec();
        mixed.extend((0..40).map(|_| rng.range(a, b)));
        let dense_at = rng.range(a, b);
        mixed.extend((0..30).map(|k| dense_at + (b - dense_at) * k as f64 / 30.0));
        mixed.sort_by(f64::total_cmp);
        let mut out = vec![0.0; mixed.len() * 3];
        c.sample_into(&mixed, &mut out).unwrap();
        for (k, &u) in mixed.iter().enumerate() {
            let e = c.evaluate(u).unwrap();
            assert_close3(
                DVec3::from_slice(&out[3 * k..]),
                e,
                1e-12 * (1.0 + e.length()),
                &format!("mixed: case {case}, p = {p}, u = {u}"),
            );
        }
    }
}

#[test]
fn one_pass_refinement_equals_repeated_insertion() {
    let mut rng = Rng::new(53);
    for case in 0..30 {
        let p = 1 + case % 4;
        let count = p + 2 + case % 6;
        let knots = random_knots(&mut rng, count, p, case % 2 == 0);
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let w: Vec<f64> = (0..count).map(|_| rng.range(0.5, 2.0)).collect();
        let c =
            BSplineCurve::new(pts, p, knots, if case % 3 == 0 { None } else { Some(&w) }).unwrap();
        let (a, b) = c.domain();
        let mut us: Vec<f64> = (0..1 + case % 5).map(|_| rng.range(a, b)).collect();
        us.push(a + 0.5 * (b - a));
        us.push(a + 0.5 * (b - a));
        if case % 2 == 1 {
            us.extend([a, b]); // the domain's ends, where an unclamped vector has room
        }
        let Ok(refined) = c.refine(&us) else { continue };
        let mut sorted = us.clone();
        sorted.sort_by(f64::total_cmp);
        let mut one_by_one = c.clone();
        for &u in &sorted {
            one_by_one = one_by_one.insert_knot(u, 1).unwrap();
        }
        assert_eq!(
            refined.knots().as_slice(),
            one_by_one.knots().as_slice(),
            "case {case}"
        );
        for (x, y) in refined
            .control_points()
            .iter()
            .zip(one_by_one.control_points())
        {
            assert_close2(*x, y, 1e-12, &format!("case {case}: refined point"));
        }
    }
    let c = croatian();
    assert!(c
        .refine(&[2.0, 2.0, 2.0])
        .unwrap_err()
        .to_string()
        .contains("multiplicity 4"));
    assert!(c
        .refine(&[5.0])
        .unwrap_err()
        .to_string()
        .contains("u = 5 is outside"));
    assert_eq!(c.refine(&[]).unwrap().control_points(), c.control_points());
}

/// A clamped knot vector for `count` points of degree `p` whose interior knots are the whole
/// numbers 1, 2, … with multiplicities cycling through `mults`; also returns how many distinct
/// interior knots it has.
fn knots_with_multiplicities(count: usize, p: usize, mults: &[usize]) -> (Vec<f64>, usize) {
    let interior = count - p - 1;
    let mut knots = vec![0.0; p + 1];
    let mut distinct = 0;
    while knots.len() < p + 1 + interior {
        distinct += 1;
        let r = mults[distinct % mults.len()].min(p + 1 + interior - knots.len());
        knots.extend(std::iter::repeat_n(distinct as f64, r));
    }
    let end = distinct as f64 + 1.0;
    knots.extend([end; 4][..p + 1].iter());
    (knots, distinct)
}

#[test]
fn a_long_curve_splits_into_one_bezier_piece_per_distinct_knot_plus_one() {
    // 3000 points: the extraction is one refinement pass (it was one Boehm insertion per knot,
    // O(n²)). Pieces are checked by the Bernstein sum against the curve's de Boor evaluation.
    let mut rng = Rng::new(41);
    let count = 3000;
    for (p, rational) in [(3, false), (3, true), (2, true)] {
        let (knots, distinct) = knots_with_multiplicities(count, p, &[1, 1, 2, 3]);
        let pts: Vec<DVec2> = (0..count).map(|_| rng.point2(5.0)).collect();
        let w: Vec<f64> = (0..count).map(|_| rng.range(0.5, 2.0)).collect();
        let c = BSplineCurve::new(pts, p, knots, rational.then_some(&w[..])).unwrap();
        let pieces = c.to_bezier().unwrap();
        assert_eq!(
            pieces.len(),
            distinct + 1,
            "degree {p}, rational {rational}"
        );
        for (k, piece) in pieces.iter().enumerate() {
            assert_eq!(piece.degree(), p);
            let (a, b) = (k as f64, k as f64 + 1.0);
            let cps = piece.control_points();
            let w = piece.weights();
            for j in 0..=7 {
                // The end of a piece at a knot of multiplicity p + 1 may differ from the curve's
                // right-continuous value there; stop short of it.
                let s = j as f64 / 7.0 * (1.0 - 1e-9);
                let u = a + s * (b - a);
                assert_close2(
                    bernstein_sum2(&cps, Some(&w), s),
                    c.evaluate(u).unwrap(),
                    1e-9,
                    &format!("degree {p}, piece {k} at u = {u}"),
                );
            }
        }
    }
}

#[test]
fn dense_sampling_stays_finite_where_the_power_form_overflows() {
    // Degree 5, control points ±1e120 alternating (the largest coordinates allowed) with every
    // weight 1e187, so the homogeneous points are ±1e307: the power form's coefficients reach
    // 2^5·1e307 and overflow, while de Casteljau and de Boor (convex combinations) and the
    // first derivative (5·(H1 − H0) = 1e308 homogeneous) stay finite. The dense paths must then
    // give what the per-point ones give, not NaN. (Equal weights: the curve is the polynomial
    // one, its points within ±1e120 and its derivative within 5·2e120.)
    let points: Vec<DVec2> = (0..6)
        .map(|i| {
            let s = if i % 2 == 0 { 1e120 } else { -1e120 };
            DVec2::new(s, -s)
        })
        .collect();
    let weights = [1e187; 6];
    let bezier = BezierCurve::new(points.clone(), Some(&weights)).unwrap();
    let mut dense = vec![0.0; 2 * 50];
    bezier.sample_uniform_into(50, &mut dense).unwrap();
    for (k, o) in dense.chunks_exact(2).enumerate() {
        let p = bezier.evaluate(k as f64 / 49.0).unwrap();
        assert!(p.is_finite(), "the point itself is finite");
        let got = DVec2::new(o[0], o[1]);
        assert!(
            (got - p).abs().max_element() <= 1e-14 * 1e120,
            "Bézier sample {k}: {got} vs {p}"
        );
    }
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0];
    let bspline = BSplineCurve::new(points, 5, knots, Some(&weights)).unwrap();
    let us: Vec<f64> = (0..50).map(|k| k as f64 / 49.0).collect();
    bspline.sample_into(&us, &mut dense).unwrap();
    let mut derivatives = vec![0.0; 2 * 50];
    bspline
        .sample_derivatives_into(&us, 1, &mut derivatives)
        .unwrap();
    for (k, &u) in us.iter().enumerate() {
        let p = bspline.evaluate(u).unwrap();
        let got = DVec2::new(dense[2 * k], dense[2 * k + 1]);
        assert!(
            (got - p).abs().max_element() <= 1e-14 * 1e120,
            "B-spline sample {k}: {got} vs {p}"
        );
        let d = bspline.derivative(u, 1).unwrap();
        assert!(d.is_finite(), "the derivative itself is finite");
        let got = DVec2::new(derivatives[2 * k], derivatives[2 * k + 1]);
        assert!(
            (got - d).abs().max_element() <= 1e-14 * 1e121,
            "derivative {k}: {got} vs {d}"
        );
    }
}
