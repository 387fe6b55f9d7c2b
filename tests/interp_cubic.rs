//! Section 5's cubic family against independent expectations: the defining equation of every
//! end condition checked on the result through derivatives, closed forms (Hermite basis,
//! polynomials reproduced by Lagrange, Runge's wiggle), hand-solved and densely solved linear
//! systems, and fixtures from scipy's CubicSpline
//! (`tests/fixtures/make_cubic_spline_fixtures.py`). Runs natively and in Node.

mod common;

use common::*;
use splinelab::bezier::BezierCurve;
use splinelab::interp::{
    self, hermite_basis, hermite_to_bezier, CubicSpline, EndCondition, LagrangeCurve,
};
use splinelab::prelude::*;
use splinelab::{DVec2, Error};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// Uneven parameters and 2D points used throughout.
fn data() -> (Vec<DVec2>, Vec<f64>) {
    (
        pts2(&[
            (0.0, 0.0),
            (1.0, 2.0),
            (3.0, 3.0),
            (5.0, 1.0),
            (6.0, 3.0),
            (8.0, 0.0),
        ]),
        vec![0.0, 0.7, 1.5, 3.1, 3.6, 5.0],
    )
}

/// The same data closed (last point = first) for periodic splines.
fn closed_data() -> (Vec<DVec2>, Vec<f64>) {
    let (mut p, t) = data();
    let n = p.len() - 1;
    p[n] = p[0];
    (p, t)
}

fn spline(end: EndCondition<DVec2>) -> CubicSpline<DVec2> {
    let (p, t) = if end == EndCondition::Periodic {
        closed_data()
    } else {
        data()
    };
    CubicSpline::interpolate(p, t, end).unwrap()
}

fn all_ends() -> Vec<EndCondition<DVec2>> {
    vec![
        EndCondition::Natural,
        EndCondition::Clamped {
            start: DVec2::new(1.5, -0.5),
            end: DVec2::new(-2.0, 1.0),
        },
        EndCondition::Quadratic,
        EndCondition::Bessel,
        EndCondition::NotAKnot,
        EndCondition::Periodic,
    ]
}

/// Every kind of spline on the data (C2 with each end, Hermite, cardinal, Catmull–Rom, Bessel).
fn every_spline() -> Vec<CubicSpline<DVec2>> {
    let (p, t) = data();
    let mut out: Vec<_> = all_ends().into_iter().map(spline).collect();
    let tangents = pts2(&[
        (1.0, 0.0),
        (0.0, 1.0),
        (2.0, 1.0),
        (1.0, -1.0),
        (0.5, 2.0),
        (1.0, 1.0),
    ]);
    out.push(CubicSpline::hermite(p.clone(), t.clone(), tangents).unwrap());
    out.push(CubicSpline::cardinal(p.clone(), t.clone(), 0.3).unwrap());
    out.push(CubicSpline::catmull_rom(p.clone(), 0.5, false).unwrap());
    out.push(CubicSpline::catmull_rom(p[..5].to_vec(), 0.5, true).unwrap());
    out.push(CubicSpline::bessel(p, t).unwrap());
    out
}

/// A value of `C^(order)` just left of `t_i`: C'' is linear on a piece, so the limit from the
/// left is extrapolated exactly from two interior values.
fn left_second_derivative(c: &CubicSpline<DVec2>, i: usize) -> DVec2 {
    let t = c.params();
    let (a, b) = (
        t[i - 1] + 0.25 * (t[i] - t[i - 1]),
        t[i - 1] + 0.75 * (t[i] - t[i - 1]),
    );
    let (fa, fb) = (c.derivative(a, 2).unwrap(), c.derivative(b, 2).unwrap());
    fa + (fb - fa) * ((t[i] - a) / (b - a))
}

/// The third derivative on the piece left of `t_i` (constant there).
fn left_third_derivative(c: &CubicSpline<DVec2>, i: usize) -> DVec2 {
    let t = c.params();
    c.derivative(0.5 * (t[i - 1] + t[i]), 3).unwrap()
}

/// Scale of the data, for relative tolerances.
const SCALE: f64 = 10.0;

#[test]
fn every_spline_interpolates_its_points() {
    for c in every_spline() {
        for (i, (&t, &p)) in c.params().iter().zip(c.points()).enumerate() {
            assert_close2(
                c.evaluate(t).unwrap(),
                p,
                1e-12 * SCALE,
                &format!("{:?} point {i}", c.rule()),
            );
        }
        let sampled = {
            let mut out = vec![0.0; c.params().len() * 2];
            c.sample_into(c.params(), &mut out).unwrap();
            out
        };
        for (i, p) in c.points().iter().enumerate() {
            assert_close2(
                DVec2::new(sampled[2 * i], sampled[2 * i + 1]),
                *p,
                1e-12 * SCALE,
                "sampled",
            );
        }
    }
}

#[test]
fn tangents_are_the_first_derivative_at_the_params() {
    for c in every_spline() {
        for (&t, &m) in c.params().iter().zip(c.tangents()) {
            assert_close2(c.derivative(t, 1).unwrap(), m, 1e-11 * SCALE, "C'(t_i)");
        }
    }
}

#[test]
fn c2_splines_have_continuous_second_derivatives() {
    for end in all_ends() {
        let c = spline(end);
        for i in 1..c.params().len() - 1 {
            let right = c.derivative(c.params()[i], 2).unwrap();
            assert_close2(
                left_second_derivative(&c, i),
                right,
                1e-10 * SCALE,
                &format!("{} C'' at t_{i}", end.name()),
            );
        }
    }
}

#[test]
fn natural_ends_have_zero_curvature_vector() {
    let c = spline(EndCondition::Natural);
    let (a, b) = c.domain();
    assert_close2(
        c.derivative(a, 2).unwrap(),
        DVec2::ZERO,
        1e-12 * SCALE,
        "C''(t_0)",
    );
    assert_close2(
        c.derivative(b, 2).unwrap(),
        DVec2::ZERO,
        1e-12 * SCALE,
        "C''(t_n)",
    );
}

#[test]
fn quadratic_ends_are_parabolas() {
    let c = spline(EndCondition::Quadratic);
    let n = c.params().len() - 1;
    assert_close2(
        left_third_derivative(&c, 1),
        DVec2::ZERO,
        1e-11 * SCALE,
        "C''' on the first piece",
    );
    assert_close2(
        left_third_derivative(&c, n),
        DVec2::ZERO,
        1e-11 * SCALE,
        "C''' on the last piece",
    );
    // And the spline is not a parabola elsewhere.
    assert!(left_third_derivative(&c, 3).length() > 0.1);
}

#[test]
fn not_a_knot_has_no_third_derivative_jump_at_t1_and_tn_minus_1() {
    let c = spline(EndCondition::NotAKnot);
    let n = c.params().len() - 1;
    for i in [1, n - 1] {
        let right = c.derivative(c.params()[i], 3).unwrap();
        assert_close2(
            left_third_derivative(&c, i),
            right,
            1e-10 * SCALE,
            &format!("C''' jump at t_{i}"),
        );
    }
    // A real knot in between: the jump at t_2 is not zero.
    let jump = c.derivative(c.params()[2], 3).unwrap() - left_third_derivative(&c, 2);
    assert!(jump.length() > 0.1, "jump {jump}");
}

#[test]
fn periodic_ends_match_in_first_and_second_derivative() {
    let c = spline(EndCondition::Periodic);
    let (a, b) = c.domain();
    for order in [1, 2] {
        assert_close2(
            c.derivative(a, order).unwrap(),
            c.derivative(b, order).unwrap(),
            1e-11 * SCALE,
            &format!("order {order}"),
        );
    }
    assert!(c.is_closed());
    assert_eq!(c.system().unwrap().size(), 5);
    assert!(c.system().unwrap().corners.is_some());
}

#[test]
fn clamped_ends_take_the_given_tangents() {
    let c = spline(all_ends()[1]);
    let (a, b) = c.domain();
    assert_close2(
        c.derivative(a, 1).unwrap(),
        DVec2::new(1.5, -0.5),
        1e-12 * SCALE,
        "start",
    );
    assert_close2(
        c.derivative(b, 1).unwrap(),
        DVec2::new(-2.0, 1.0),
        1e-12 * SCALE,
        "end",
    );
}

/// The tangent at `t0` of the parabola through three points, by Newton's divided differences:
/// `q(t) = p0 + (t − t0) f[t0,t1] + (t − t0)(t − t1) f[t0,t1,t2]`, so
/// `q'(t0) = f[t0,t1] + (t0 − t1) f[t0,t1,t2]` (and likewise at `t2` by symmetry).
fn parabola_tangent(t: [f64; 3], p: [DVec2; 3], at: f64) -> DVec2 {
    let f01 = (p[1] - p[0]) / (t[1] - t[0]);
    let f12 = (p[2] - p[1]) / (t[2] - t[1]);
    let f012 = (f12 - f01) / (t[2] - t[0]);
    // q'(t) = f01 + (2t − t0 − t1) f012.
    f01 + f012 * (2.0 * at - t[0] - t[1])
}

#[test]
fn bessel_ends_and_tangents_are_the_parabolas_tangents() {
    let (p, t) = data();
    let n = p.len() - 1;
    let start = parabola_tangent([t[0], t[1], t[2]], [p[0], p[1], p[2]], t[0]);
    let end = parabola_tangent([t[n - 2], t[n - 1], t[n]], [p[n - 2], p[n - 1], p[n]], t[n]);
    let c = spline(EndCondition::Bessel);
    assert_close2(c.tangents()[0], start, 1e-12 * SCALE, "bessel end start");
    assert_close2(c.tangents()[n], end, 1e-12 * SCALE, "bessel end end");
    let b = CubicSpline::bessel(p.clone(), t.clone()).unwrap();
    assert_close2(b.tangents()[0], start, 1e-12 * SCALE, "besselSpline start");
    assert_close2(b.tangents()[n], end, 1e-12 * SCALE, "besselSpline end");
    for i in 1..n {
        let m = parabola_tangent([t[i - 1], t[i], t[i + 1]], [p[i - 1], p[i], p[i + 1]], t[i]);
        assert_close2(
            b.tangents()[i],
            m,
            1e-12 * SCALE,
            &format!("besselSpline m_{i}"),
        );
    }
}

#[test]
fn two_and_three_points_give_the_line_and_the_parabola() {
    let p = pts2(&[(0.0, 0.0), (3.0, 6.0)]);
    for end in [
        EndCondition::Natural,
        EndCondition::Quadratic,
        EndCondition::Bessel,
        EndCondition::NotAKnot,
    ] {
        let c = CubicSpline::interpolate(p.clone(), vec![0.0, 3.0], end).unwrap();
        assert_close2(
            c.evaluate(1.0).unwrap(),
            DVec2::new(1.0, 2.0),
            1e-14,
            end.name(),
        );
    }
    // Not-a-knot through three points of a parabola reproduces it.
    let f = |t: f64| DVec2::new(t, t * t - 2.0 * t);
    let t = vec![0.0, 1.0, 3.0];
    let c = CubicSpline::interpolate(t.iter().map(|&x| f(x)).collect(), t, EndCondition::NotAKnot)
        .unwrap();
    for k in 0..=30 {
        let x = k as f64 / 10.0;
        assert_close2(c.evaluate(x).unwrap(), f(x), 1e-13, "parabola");
    }
}

#[test]
fn not_a_knot_reproduces_a_cubic() {
    let f = |t: f64| DVec2::new(t * t * t - t, 2.0 - t * t + 0.5 * t * t * t);
    let t = vec![-1.0, -0.2, 0.5, 1.1, 2.0, 2.5];
    let c = CubicSpline::interpolate(t.iter().map(|&x| f(x)).collect(), t, EndCondition::NotAKnot)
        .unwrap();
    for k in 0..=35 {
        let x = -1.0 + k as f64 / 10.0;
        assert_close2(c.evaluate(x).unwrap(), f(x), 1e-12, "cubic");
    }
}

#[test]
fn hermite_basis_closed_forms() {
    for k in 0..=20 {
        let s = k as f64 / 20.0;
        let h = hermite_basis(s);
        let expected = [
            2.0 * s.powi(3) - 3.0 * s * s + 1.0,
            -2.0 * s.powi(3) + 3.0 * s * s,
            s.powi(3) - 2.0 * s * s + s,
            s.powi(3) - s * s,
        ];
        for (j, (&g, &e)) in h.iter().zip(&expected).enumerate() {
            assert_close(g, e, 1e-15, &format!("H{j}({s})"));
        }
        assert_close(h[0] + h[1], 1.0, 1e-15, "H0 + H1");
    }
    assert_eq!(hermite_basis(0.0), [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(hermite_basis(1.0), [0.0, 1.0, 0.0, 0.0]);
}

#[test]
fn hermite_piece_in_bezier_form() {
    let (p0, p1) = (DVec2::new(0.0, 0.0), DVec2::new(4.0, 1.0));
    let (m0, m1) = (DVec2::new(3.0, 3.0), DVec2::new(6.0, -3.0));
    // On an interval of length Δ = 2 the tangents w.r.t. t scale by 2 in the local s.
    let q = hermite_to_bezier(p0, m0, p1, m1, 2.0);
    assert_eq!(q, [p0, DVec2::new(2.0, 2.0), DVec2::new(0.0, 3.0), p1]);
    let bezier = BezierCurve::new(q.to_vec(), None).unwrap();
    for k in 0..=10 {
        let s = k as f64 / 10.0;
        let h = hermite_basis(s);
        let expected = p0 * h[0] + p1 * h[1] + (m0 * h[2] + m1 * h[3]) * 2.0;
        assert_close2(
            bezier.evaluate(s).unwrap(),
            expected,
            1e-14,
            "Bézier = Hermite",
        );
    }
}

#[test]
fn conversions_give_the_same_curve() {
    for c in every_spline() {
        let bezier = c.to_bezier().unwrap();
        let bspline = c.to_bspline().unwrap();
        let n = c.piece_count();
        let expected_points = match c.rule() {
            interp::TangentRule::Spline(_) => n + 3,
            _ => 2 * n + 2,
        };
        assert_eq!(
            bspline.control_points().len(),
            expected_points,
            "{:?}",
            c.rule()
        );
        assert_eq!(bezier.pieces().len(), n);
        let (a, b) = c.domain();
        assert_eq!(bspline.domain(), (a, b));
        for k in 0..=200 {
            let t = a + (b - a) * k as f64 / 200.0;
            let p = c.evaluate(t).unwrap();
            assert_close2(bezier.evaluate(t).unwrap(), p, 1e-12 * SCALE, "toBezier");
            assert_close2(
                bspline.evaluate(t).unwrap(),
                p,
                1e-11 * SCALE,
                &format!("toBSpline {:?} at {t}", c.rule()),
            );
            for order in 1..=2 {
                let d = c.derivative(t, order).unwrap();
                assert_close2(
                    bspline.derivative(t, order).unwrap(),
                    d,
                    1e-9 * SCALE,
                    "toBSpline derivative",
                );
            }
        }
    }
}

#[test]
fn derivatives_above_three_are_zero_and_sampling_matches_evaluation() {
    let c = spline(EndCondition::Natural);
    assert_eq!(c.derivative(1.0, 4).unwrap(), DVec2::ZERO);
    // Unsorted and repeated parameters: the walk falls back to a search.
    let ts = [4.9, 0.1, 0.7, 0.7, 5.0, 0.0, 3.3, 1.5, 1.49];
    for order in 0..=3 {
        let mut out = vec![0.0; ts.len() * 2];
        c.sample_derivatives_into(&ts, order, &mut out).unwrap();
        for (k, &t) in ts.iter().enumerate() {
            let d = c.derivative(t, order).unwrap();
            assert_eq!(
                DVec2::new(out[2 * k], out[2 * k + 1]),
                d,
                "order {order} at {t}"
            );
        }
    }
    assert!(matches!(
        c.evaluate(5.1),
        Err(Error::ParameterOutOfRange { .. })
    ));
    assert!(matches!(
        c.evaluate(-0.1),
        Err(Error::ParameterOutOfRange { .. })
    ));
}

#[test]
fn set_point_equals_a_rebuild() {
    let (mut p, t) = data();
    let moved = DVec2::new(2.5, -1.0);
    let mut edited = every_spline();
    p[2] = moved;
    for c in &mut edited {
        c.set_point(2, moved).unwrap();
    }
    let (mut closed, _) = closed_data();
    closed[2] = moved;
    let n = p.len() - 1;
    let rebuilt_tangents = pts2(&[
        (1.0, 0.0),
        (0.0, 1.0),
        (2.0, 1.0),
        (1.0, -1.0),
        (0.5, 2.0),
        (1.0, 1.0),
    ]);
    let mut rebuilt: Vec<_> = all_ends()
        .into_iter()
        .map(|e| {
            let pts = if e == EndCondition::Periodic {
                closed.clone()
            } else {
                p.clone()
            };
            CubicSpline::interpolate(pts, t.clone(), e).unwrap()
        })
        .collect();
    rebuilt.push(CubicSpline::hermite(p.clone(), t.clone(), rebuilt_tangents).unwrap());
    rebuilt.push(CubicSpline::cardinal(p.clone(), t.clone(), 0.3).unwrap());
    rebuilt.push(CubicSpline::catmull_rom(p.clone(), 0.5, false).unwrap());
    rebuilt.push(CubicSpline::catmull_rom(p[..5].to_vec(), 0.5, true).unwrap());
    rebuilt.push(CubicSpline::bessel(p.clone(), t.clone()).unwrap());
    for (e, r) in edited.iter().zip(&rebuilt) {
        assert_eq!(e, r, "{:?}", e.rule());
    }
    // A closed spline moves its first and last point together.
    let mut c = spline(EndCondition::Periodic);
    c.set_point(n, moved).unwrap();
    assert_eq!(c.points()[0], moved);
    assert_eq!(c.points()[n], moved);
    // A failed edit leaves the spline unchanged.
    let mut cr = CubicSpline::catmull_rom(data().0, 0.5, false).unwrap();
    let before = cr.clone();
    assert!(cr.set_point(1, data().0[0]).is_err());
    assert_eq!(cr, before);
}

#[test]
fn catmull_rom_uniform_equals_cardinal_with_zero_tension() {
    let (p, _) = data();
    let uniform: Vec<f64> = (0..p.len()).map(|i| i as f64).collect();
    let cr = CubicSpline::catmull_rom(p.clone(), 0.0, false).unwrap();
    let card = CubicSpline::cardinal(p, uniform.clone(), 0.0).unwrap();
    assert_eq!(cr.params(), uniform.as_slice());
    for (a, b) in cr.tangents().iter().zip(card.tangents()) {
        assert_close2(*a, *b, 1e-14, "tangent");
    }
}

#[test]
fn cardinal_tangents_closed_form() {
    let (p, t) = data();
    let c = CubicSpline::cardinal(p.clone(), t.clone(), 0.25).unwrap();
    let m = c.tangents();
    assert_close2(m[0], (p[1] - p[0]) * 0.75 / (t[1] - t[0]), 1e-14, "m_0");
    assert_close2(m[2], (p[3] - p[1]) * 0.75 / (t[3] - t[1]), 1e-14, "m_2");
    assert_close2(m[5], (p[5] - p[4]) * 0.75 / (t[5] - t[4]), 1e-14, "m_5");
}

/// Whether the polyline crosses itself (segments that are not neighbours intersect).
fn self_intersects(v: &[DVec2]) -> bool {
    let cross = |a: DVec2, b: DVec2| a.x * b.y - a.y * b.x;
    for i in 0..v.len() - 1 {
        for j in i + 2..v.len() - 1 {
            let (p, r) = (v[i], v[i + 1] - v[i]);
            let (q, s) = (v[j], v[j + 1] - v[j]);
            let d = cross(r, s);
            if d == 0.0 {
                continue;
            }
            let u = cross(q - p, s) / d;
            let w = cross(q - p, r) / d;
            if (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&w) {
                return true;
            }
        }
    }
    false
}

#[test]
fn centripetal_has_no_loop_where_uniform_has_one() {
    // Two close points between two far ones: with uniform parameters the middle piece's
    // tangents (p_2 − p_0)/2 = (9, 3) and (p_3 − p_1)/2 = (9, −3) put its inner Bézier points at
    // (3, 1) and (−2, 1), crossed: a loop.
    let p = pts2(&[(-17.0, -6.0), (0.0, 0.0), (1.0, 0.0), (18.0, -6.0)]);
    let uniform = CubicSpline::catmull_rom(p.clone(), 0.0, false).unwrap();
    let centripetal = CubicSpline::catmull_rom(p, 0.5, false).unwrap();
    let samples = |c: &CubicSpline<DVec2>, order| {
        let (a, b) = c.domain();
        (0..=2000)
            .map(|k| {
                c.derivative(a + (b - a) * k as f64 / 2000.0, order)
                    .unwrap()
            })
            .collect::<Vec<_>>()
    };
    assert!(
        self_intersects(&samples(&uniform, 0)),
        "uniform should loop"
    );
    assert!(
        !self_intersects(&samples(&centripetal, 0)),
        "centripetal loops"
    );
    let min_speed = samples(&centripetal, 1)
        .iter()
        .map(|v| v.length())
        .fold(f64::INFINITY, f64::min);
    assert!(min_speed > 0.05, "centripetal speed {min_speed}");
}

#[test]
fn closed_catmull_rom_wraps() {
    let p = pts2(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
    let c = CubicSpline::catmull_rom(p, 1.0, true).unwrap();
    assert_eq!(c.piece_count(), 4);
    assert_eq!(c.points()[4], DVec2::ZERO);
    assert_eq!(c.params(), &[0.0, 2.0, 4.0, 6.0, 8.0]);
    assert_eq!(c.tangents()[0], c.tangents()[4]);
    // By symmetry the tangent at (0, 0) points along the diagonal of its neighbours.
    assert_close2(c.tangents()[0], DVec2::new(0.5, -0.5), 1e-15, "m_0");
    // The same cycle with its first point repeated at the end gives the same spline.
    let repeated = pts2(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (0.0, 0.0)]);
    assert_eq!(CubicSpline::catmull_rom(repeated, 1.0, true).unwrap(), c);
}

#[test]
fn lagrange_reproduces_polynomials_of_degree_n() {
    let f = |t: f64| DVec2::new(2.0 * t.powi(4) - t + 1.0, t.powi(3) - 3.0 * t * t);
    let t = vec![-1.0, -0.3, 0.2, 0.9, 1.6];
    let c = LagrangeCurve::new(t.iter().map(|&x| f(x)).collect(), &t).unwrap();
    for k in 0..=26 {
        let x = -1.0 + k as f64 * 0.1;
        assert_close2(c.evaluate(x).unwrap(), f(x), 1e-12, &format!("P({x})"));
        let basis = c.basis(x).unwrap();
        assert_close(basis.iter().sum(), 1.0, 1e-13, "Σ L_i");
        // The basis at x weights the points into P(x).
        let weighted = c
            .points()
            .iter()
            .zip(&basis)
            .fold(DVec2::ZERO, |acc, (&p, &l)| acc + p * l);
        assert_close2(weighted, f(x), 1e-12, "Σ L_i p_i");
    }
    // Exactly p_i at a node, and the basis is e_i there.
    assert_eq!(c.evaluate(0.2).unwrap(), f(0.2));
    assert_eq!(c.basis(0.2).unwrap(), vec![0.0, 0.0, 1.0, 0.0, 0.0]);
    // L_1 closed form at x = 0.5: Π_{j≠1} (x − t_j)/(t_1 − t_j).
    let l1: f64 = [0usize, 2, 3, 4]
        .iter()
        .map(|&j| (0.5 - t[j]) / (t[1] - t[j]))
        .product();
    assert_close(c.basis(0.5).unwrap()[1], l1, 1e-14, "L_1(0.5)");
}

#[test]
fn lagrange_set_point_recomputes_a_spacing_and_keeps_given_params() {
    let p = pts2(&[(0.0, 0.0), (3.0, 4.0), (4.0, 4.0), (8.0, 1.0)]);
    let moved = DVec2::new(6.0, 4.0);
    // Chord spacing: after the move the parameters are the moved polygon's cumulative leg
    // lengths, by hand: |(3,4)| = 5, |(3,0)| = 3, |(2,−3)| = √13.
    let chord = splinelab::bspline::Parameterization::Chord;
    let mut c = LagrangeCurve::with_params(p.clone(), chord.into()).unwrap();
    c.set_point(2, moved).unwrap();
    let expected = [0.0, 5.0, 8.0, 8.0 + 13f64.sqrt()];
    for (got, want) in c.params().iter().zip(expected) {
        assert_close(*got, want, 1e-14, "chord param after the move");
    }
    assert_close2(
        c.evaluate(8.0).unwrap(),
        moved,
        1e-12,
        "P(t_2) = the moved point",
    );
    // Given parameters stay.
    let mut g = LagrangeCurve::new(p, &[0.0, 1.0, 2.0, 3.0]).unwrap();
    g.set_point(2, moved).unwrap();
    assert_eq!(g.params(), &[0.0, 1.0, 2.0, 3.0]);
    assert_close2(
        g.evaluate(2.0).unwrap(),
        moved,
        1e-12,
        "P(2) = the moved point",
    );
}

#[test]
fn lagrange_basis_curves_are_the_product_formula_i_major() {
    // Uneven params on [1, 4]; 7 samples at t_k = 1 + k/2, which hit the nodes 1, 2.5 and 4.
    let t = [1.0, 2.5, 3.0, 4.0];
    let p = pts2(&[(0.0, 0.0), (1.0, 3.0), (3.0, 2.0), (4.0, -1.0)]);
    let c = LagrangeCurve::new(p, &t).unwrap();
    let count = 7;
    let curves = c.basis_curves(count).unwrap();
    assert_eq!(curves.len(), t.len() * count);
    for k in 0..count {
        let x = 1.0 + 0.5 * k as f64;
        let mut sum = 0.0;
        for i in 0..t.len() {
            // L_i(x) = Π_{j≠i} (x − t_j)/(t_i − t_j), written out here (not the barycentric form).
            let expected: f64 = (0..t.len())
                .filter(|&j| j != i)
                .map(|j| (x - t[j]) / (t[i] - t[j]))
                .product();
            assert_close(curves[i * count + k], expected, 1e-13, "L_i(t_k)");
            sum += curves[i * count + k];
        }
        assert_close(sum, 1.0, 1e-13, "Σ L_i = 1");
    }
    // A cap on (n + 1)·count, not only on count.
    assert!(c.basis_curves(1 << 23).is_err());
}

#[test]
fn aitken_triangle_ends_at_the_polynomial() {
    let p = pts2(&[(0.0, 0.0), (1.0, 3.0), (3.0, 2.0), (4.0, -1.0)]);
    let t = [0.0, 1.0, 2.5, 4.0];
    let c = LagrangeCurve::new(p.clone(), &t).unwrap();
    let x = 1.7;
    let tri = c.aitken(x).unwrap();
    assert_eq!(tri.len(), 10);
    assert_eq!(&tri[..4], p.as_slice());
    // Level 1: the line through p_i, p_{i+1} at x, by hand.
    let line = |i: usize| p[i] + (p[i + 1] - p[i]) * ((x - t[i]) / (t[i + 1] - t[i]));
    for i in 0..3 {
        assert_close2(tri[4 + i], line(i), 1e-14, &format!("p_{i}^1"));
    }
    assert_close2(tri[9], c.evaluate(x).unwrap(), 1e-13, "apex");
}

#[test]
fn runge_function_wiggles_near_the_ends() {
    // Eleven equally spaced nodes of 1/(1 + 25x²) on [−1, 1]: the interpolant's largest error,
    // near x = ±0.96, is about 1.9156 (the classic Runge example), while at 0 it is exact.
    let runge = |x: f64| 1.0 / (1.0 + 25.0 * x * x);
    let t: Vec<f64> = (0..=10).map(|i| -1.0 + 0.2 * i as f64).collect();
    let c = LagrangeCurve::new(t.iter().map(|&x| DVec2::new(x, runge(x))).collect(), &t).unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..=2000 {
        let x = -1.0 + k as f64 / 1000.0;
        let p = c.evaluate(x).unwrap();
        assert_close(p.x, x, 1e-13, "linear precision in x");
        worst = worst.max((p.y - runge(x)).abs());
    }
    assert!((1.91..1.92).contains(&worst), "max error {worst}");
}

#[test]
fn barycentric_form_is_stable_on_25_chebyshev_points() {
    let f = |t: f64| DVec2::new(t.exp(), (3.0 * t).sin());
    let t: Vec<f64> = (0..25)
        .map(|k| -(std::f64::consts::PI * k as f64 / 24.0).cos())
        .collect();
    let c = LagrangeCurve::new(t.iter().map(|&x| f(x)).collect(), &t).unwrap();
    for k in 0..=1000 {
        let x = -1.0 + k as f64 / 500.0;
        assert_close2(c.evaluate(x).unwrap(), f(x), 1e-13, &format!("at {x}"));
    }
}

/// Gaussian elimination with partial pivoting on a dense matrix (row-major), for comparison.
#[allow(clippy::needless_range_loop)]
fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .unwrap();
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..n {
            let f = a[row][col] / a[col][col];
            for k in col..n {
                a[row][k] -= f * a[col][k];
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x
}

#[test]
fn tridiagonal_solvers_against_hand_and_dense_solutions() {
    // [[2,1,0],[1,3,1],[0,1,2]] x = [4,10,8] has x = [1,2,3].
    let x = interp::solve_tridiagonal(
        &[1.0, 1.0],
        &[2.0, 3.0, 2.0],
        &[1.0, 1.0],
        &[4.0, 10.0, 8.0],
        "test",
    )
    .unwrap();
    for (g, e) in x.iter().zip([1.0, 2.0, 3.0]) {
        assert_close(*g, e, 1e-14, "Thomas");
    }
    // Cyclic 4×4 with corners 1: [[4,1,0,1],[1,4,1,0],[0,1,4,1],[1,0,1,4]] x = [10,12,18,20]
    // has x = [1,2,3,4].
    let x = interp::solve_cyclic(
        &[1.0; 3],
        &[4.0; 4],
        &[1.0; 3],
        [1.0, 1.0],
        &[10.0, 12.0, 18.0, 20.0],
        "test",
    )
    .unwrap();
    for (g, e) in x.iter().zip([1.0, 2.0, 3.0, 4.0]) {
        assert_close(*g, e, 1e-14, "cyclic");
    }
    // Random diagonally dominant systems against the dense solve.
    let mut rng = Rng::new(7);
    for size in [1usize, 2, 3, 5, 9, 17] {
        let lower: Vec<f64> = (1..size).map(|_| rng.range(-1.0, 1.0)).collect();
        let upper: Vec<f64> = (1..size).map(|_| rng.range(-1.0, 1.0)).collect();
        let diagonal: Vec<f64> = (0..size).map(|_| rng.range(3.0, 5.0)).collect();
        let corners = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
        let rhs: Vec<f64> = (0..size).map(|_| rng.range(-5.0, 5.0)).collect();
        for cyclic in [false, true] {
            let mut a = vec![vec![0.0; size]; size];
            for i in 0..size {
                a[i][i] = diagonal[i];
                if i + 1 < size {
                    a[i + 1][i] += lower[i];
                    a[i][i + 1] += upper[i];
                }
            }
            if cyclic {
                a[0][size - 1] += corners[0];
                a[size - 1][0] += corners[1];
            }
            let expected = dense_solve(a, rhs.clone());
            let got = if cyclic {
                interp::solve_cyclic(&lower, &diagonal, &upper, corners, &rhs, "test")
            } else {
                interp::solve_tridiagonal(&lower, &diagonal, &upper, &rhs, "test")
            }
            .unwrap();
            for (g, e) in got.iter().zip(&expected) {
                assert_close(*g, *e, 1e-12, &format!("size {size} cyclic {cyclic}"));
            }
        }
    }
}

#[test]
fn singular_systems_are_errors_not_divisions_by_zero() {
    let e = interp::solve_tridiagonal(&[1.0], &[1.0, 1.0], &[1.0], &[1.0, 2.0], "the test system")
        .unwrap_err();
    assert_eq!(
        e,
        Error::SingularSystem {
            what: "the test system",
            row: 1
        }
    );
    let e = interp::solve_tridiagonal(&[1.0], &[0.0, 1.0], &[1.0], &[1.0, 2.0], "t").unwrap_err();
    assert_eq!(e, Error::SingularSystem { what: "t", row: 0 });
    // Cyclic: rows all (1, 1, 0, …, 1)-like sums that repeat make it singular.
    assert!(
        interp::solve_cyclic(&[1.0; 2], &[-2.0; 3], &[1.0; 2], [1.0, 1.0], &[0.0; 3], "t").is_err()
    );
}

/// scipy's CubicSpline: tangents at the params and derivatives 0..3 at many t.
#[test]
fn fixtures_from_scipy_cubic_spline() {
    let text = include_str!("fixtures/cubic_spline_scipy.txt");
    let mut spline: Option<CubicSpline<DVec2>> = None;
    let mut scale = 1.0;
    let mut checked = 0;
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let mut words = line.split_whitespace();
        let tag = words.next().unwrap();
        if tag == "spline" {
            let end = words.next().unwrap();
            let nums: Vec<f64> = words.map(|w| w.parse().unwrap()).collect();
            let count = nums[0] as usize;
            let t = nums[1..1 + count].to_vec();
            let coords = &nums[1 + count..1 + 3 * count];
            let tangents = &nums[1 + 3 * count..];
            let v = |k: usize| DVec2::new(tangents[k], tangents[k + 1]);
            let start = (!tangents.is_empty()).then(|| v(0));
            let finish = (!tangents.is_empty()).then(|| v(2));
            let condition = EndCondition::parse(end, start, finish).unwrap();
            let points: Vec<DVec2> = coords.chunks(2).map(DVec2::from_slice).collect();
            scale = points
                .iter()
                .map(|p| p.abs().max_element())
                .fold(1.0, f64::max);
            spline = Some(CubicSpline::interpolate(points, t, condition).unwrap());
            continue;
        }
        let nums: Vec<f64> = words.map(|w| w.parse().unwrap()).collect();
        let c = spline.as_ref().unwrap();
        match tag {
            "tangent" => {
                let i = nums[0] as usize;
                assert_close2(
                    c.tangents()[i],
                    DVec2::new(nums[1], nums[2]),
                    1e-12 * scale,
                    line,
                );
            }
            "eval" => {
                let (t, order) = (nums[0], nums[1] as usize);
                let got = c.derivative(t, order).unwrap();
                let expected = DVec2::new(nums[2], nums[3]);
                // Relative to the data and to the value (derivatives grow like 1/Δ^order).
                let tol = 1e-12 * (scale + expected.abs().max_element());
                assert_close2(got, expected, tol, line);
            }
            other => panic!("unknown fixture line {other}"),
        }
        checked += 1;
    }
    assert!(checked > 1000, "only {checked} fixture values");
}

#[test]
fn natural_spline_worked_example() {
    // (0,0), (1,1), (2,0) at t = 0, 1, 2. Rows: 2m_0 + m_1 = 3s_0, m_0 + 4m_1 + m_2 = 3(s_0 + s_1),
    // m_1 + 2m_2 = 3s_1 with s_0 = (1, 1), s_1 = (1, −1): x gives m = 1 everywhere, y by
    // symmetry m_1 = 0 and 2m_0 = 3, so m = (1, 1.5), (1, 0), (1, −1.5).
    let c = CubicSpline::interpolate(
        pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]),
        vec![0.0, 1.0, 2.0],
        EndCondition::Natural,
    )
    .unwrap();
    let expected = pts2(&[(1.0, 1.5), (1.0, 0.0), (1.0, -1.5)]);
    for (g, e) in c.tangents().iter().zip(&expected) {
        assert_close2(*g, *e, 1e-15, "m_i");
    }
    let system = c.system().unwrap();
    assert_eq!(system.diagonal, vec![2.0, 4.0, 2.0]);
    assert_eq!(system.lower, vec![1.0, 1.0]);
    assert_eq!(system.upper, vec![1.0, 1.0]);
    assert_eq!(system.rhs, pts2(&[(3.0, 3.0), (6.0, 0.0), (3.0, -3.0)]));
    // C(0.5) = p_0 + m_0/2 + c/4 + d/8 with c = 3s_0 − 2m_0 − m_1, d = m_0 + m_1 − 2s_0:
    // y: c = 0, d = −0.5, so y = 0.75 − 0.0625.
    assert_close2(
        c.evaluate(0.5).unwrap(),
        DVec2::new(0.5, 0.6875),
        1e-15,
        "C(0.5)",
    );
}

#[test]
fn periodic_with_three_points_has_equal_tangents() {
    // scipy's closed form for three points: every tangent (Δ_0 s_1 + Δ_1 s_0)/(Δ_0 + Δ_1).
    let p = pts2(&[(0.0, 0.0), (2.0, 1.0), (0.0, 0.0)]);
    let t = vec![0.0, 1.0, 3.0];
    let c = CubicSpline::interpolate(p.clone(), t, EndCondition::Periodic).unwrap();
    let (s0, s1) = ((p[1] - p[0]) / 1.0, (p[2] - p[1]) / 2.0);
    let m = (s1 * 1.0 + s0 * 2.0) / 3.0;
    for g in c.tangents() {
        assert_close2(*g, m, 1e-15, "m");
    }
}

#[test]
fn bspline_forms_have_the_syllabus_knots() {
    let c = spline(EndCondition::Natural);
    let b = c.to_bspline().unwrap();
    let t = c.params();
    let mut knots = vec![t[0]; 4];
    knots.extend_from_slice(&t[1..5]);
    knots.extend_from_slice(&[t[5]; 4]);
    assert_eq!(b.knots().as_slice(), knots.as_slice());
    // The control polygon starts with p_0 and p_0 + Δ_0 m_0/3.
    let cp = b.control_points();
    assert_eq!(cp[0], c.points()[0]);
    assert_close2(
        cp[1],
        c.points()[0] + c.tangents()[0] * (t[1] / 3.0),
        1e-14,
        "d_1",
    );
    let h = CubicSpline::bessel(data().0, data().1)
        .unwrap()
        .to_bspline()
        .unwrap();
    assert_eq!(h.knots().as_slice().len(), 8 + 2 * 4);
    assert_eq!(h.knots().as_slice()[4..6], [t[1], t[1]]);
}

#[test]
fn catmull_rom_open_ends_follow_the_phantom_points() {
    let (p, _) = data();
    let c = CubicSpline::catmull_rom(p.clone(), 0.5, false).unwrap();
    let t = c.params().to_vec();
    let n = p.len() - 1;
    // Phantom 2p_0 − p_1 at t_0 − Δ_0: the tangent is the chord slope s_0 (likewise at the end).
    assert_close2(c.tangents()[0], (p[1] - p[0]) / (t[1] - t[0]), 1e-14, "m_0");
    assert_close2(
        c.tangents()[n],
        (p[n] - p[n - 1]) / (t[n] - t[n - 1]),
        1e-14,
        "m_n",
    );
    // Centripetal parameters: cumulative square roots of the chord lengths.
    for i in 0..n {
        assert_close(
            t[i + 1] - t[i],
            (p[i + 1] - p[i]).length().sqrt(),
            1e-14,
            "Δ_i",
        );
    }
}

#[test]
fn splines_in_3d() {
    let p: Vec<splinelab::DVec3> = (0..7)
        .map(|i| {
            let a = i as f64 * 0.9;
            splinelab::DVec3::new(a.cos(), a.sin(), 0.3 * a)
        })
        .collect();
    let c = CubicSpline::catmull_rom(p.clone(), 0.5, false).unwrap();
    let s =
        CubicSpline::interpolate(p.clone(), c.params().to_vec(), EndCondition::NotAKnot).unwrap();
    for spline in [c, s] {
        let b = spline.to_bspline().unwrap();
        for (&t, &q) in spline.params().iter().zip(&p) {
            assert_close3(spline.evaluate(t).unwrap(), q, 1e-14, "3D point");
            assert_close3(b.evaluate(t).unwrap(), q, 1e-13, "3D B-spline");
        }
    }
}

#[test]
fn set_point_recomputes_a_spacing() {
    use splinelab::bspline::Parameterization;
    let (mut p, _) = data();
    let mut c = CubicSpline::bessel(p.clone(), Parameterization::Centripetal).unwrap();
    p[3] = DVec2::new(4.0, 4.0);
    c.set_point(3, p[3]).unwrap();
    let rebuilt = CubicSpline::bessel(p.clone(), Parameterization::Centripetal).unwrap();
    assert_eq!(c, rebuilt);
    assert_eq!(
        c.params(),
        splinelab::bspline::parameterize(&p, Parameterization::Centripetal).unwrap()
    );
    // Exponent α: cumulative |Δp|^α.
    let alpha = Parameterization::from_alpha(0.3).unwrap();
    let t = splinelab::bspline::parameterize(&p, alpha).unwrap();
    assert_close(t[1], (p[1] - p[0]).length().powf(0.3), 1e-15, "t_1");
    assert_eq!(
        Parameterization::from_alpha(0.0).unwrap(),
        Parameterization::Uniform
    );
    assert_eq!(
        Parameterization::from_alpha(1.0).unwrap(),
        Parameterization::Chord
    );
}

#[test]
fn hermite_basis_derivatives_at_the_ends() {
    let d0 = interp::hermite_basis_derivative(0.0);
    let d1 = interp::hermite_basis_derivative(1.0);
    assert_eq!(d0, [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(d1, [0.0, 0.0, 0.0, 1.0]);
    let h = 1e-6;
    for k in 1..10 {
        let s = k as f64 / 10.0;
        let (a, b) = (hermite_basis(s - h), hermite_basis(s + h));
        let d = interp::hermite_basis_derivative(s);
        for j in 0..4 {
            assert_close(d[j], (b[j] - a[j]) / (2.0 * h), 1e-8, "central difference");
        }
    }
}
