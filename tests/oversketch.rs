//! `fit::oversketch` against invariants that do not use its code: the kept parts of the old
//! curve are exact sub-curves (evaluated through the old pieces), the seams are G1 (unit
//! tangents of the neighbouring pieces), the stroke's middle is within the tolerance (brute
//! force over a dense sampling), a closed curve stays closed, and far strokes are refused.

use glam::DVec2;
use splinelab::bezier::{BezierCurve, CompositeCurve};
use splinelab::fit::oversketch;

fn cubic(p: [(f64, f64); 4]) -> BezierCurve<DVec2> {
    BezierCurve::new(p.iter().map(|&(x, y)| DVec2::new(x, y)).collect(), None).unwrap()
}

/// Three cubics on [0, 1], [1, 2], [2, 3]: a wave through (0, 0), (3, 0), (6, 0), (9, 0), G1.
fn wave() -> CompositeCurve<DVec2> {
    CompositeCurve::new(
        vec![
            cubic([(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, 0.0)]),
            cubic([(3.0, 0.0), (4.0, -1.0), (5.0, -1.0), (6.0, 0.0)]),
            cubic([(6.0, 0.0), (7.0, 1.0), (8.0, 1.0), (9.0, 0.0)]),
        ],
        &[0.0, 1.0, 2.0, 3.0],
    )
    .unwrap()
}

/// The unit circle from four cubics (k = 0.5523), piece i from angle iπ/2, closed at (1, 0).
fn circle() -> CompositeCurve<DVec2> {
    let k = 0.552_284_749_8;
    let quarter = |i: usize| {
        let rot = |x: f64, y: f64| match i {
            0 => (x, y),
            1 => (-y, x),
            2 => (-x, -y),
            _ => (y, -x),
        };
        cubic([rot(1.0, 0.0), rot(1.0, k), rot(k, 1.0), rot(0.0, 1.0)])
    };
    CompositeCurve::new((0..4).map(quarter).collect(), &[0.0, 1.0, 2.0, 3.0, 4.0]).unwrap()
}

fn at(c: &CompositeCurve<DVec2>, t: f64) -> DVec2 {
    c.evaluate(t).unwrap()
}

/// The distance from `q` to the pieces `range` of `c`, by 4000 points per piece.
fn distance(c: &CompositeCurve<DVec2>, range: std::ops::Range<usize>, q: DVec2) -> f64 {
    let mut best = f64::INFINITY;
    for piece in &c.pieces()[range] {
        let (a, b) = piece.interval();
        let pts: Vec<DVec2> = (0..=4000)
            .map(|k| piece.evaluate(a + (b - a) * k as f64 / 4000.0).unwrap())
            .collect();
        for w in pts.windows(2) {
            let (d, e) = (w[1] - w[0], q - w[0]);
            let s = (e.dot(d) / d.length_squared().max(1e-300)).clamp(0.0, 1.0);
            best = best.min((e - d * s).length());
        }
    }
    best
}

/// Unit tangents at the end of piece i and the start of piece i + 1 agree.
fn assert_g1(c: &CompositeCurve<DVec2>, i: usize) {
    let (l, r) = (&c.pieces()[i], &c.pieces()[i + 1]);
    let tl = l.derivative(l.interval().1, 1).unwrap().normalize();
    let tr = r.derivative(r.interval().0, 1).unwrap().normalize();
    assert!((tl - tr).length() < 1e-9, "joint {i}: {tl} vs {tr}");
    let gap = (l.evaluate(l.interval().1).unwrap() - r.evaluate(r.interval().0).unwrap()).length();
    assert!(gap < 1e-12, "joint {i} gap {gap}");
}

/// A bump over the wave from t = 0.5 to 2.5: `C(0.5 + 2s) + (0, 0.8 sin πs)`.
fn bump(samples: usize) -> Vec<DVec2> {
    let c = wave();
    (0..samples)
        .map(|k| {
            let s = k as f64 / (samples - 1) as f64;
            at(&c, 0.5 + 2.0 * s) + DVec2::new(0.0, 0.8 * (std::f64::consts::PI * s).sin())
        })
        .collect()
}

#[test]
fn the_part_between_the_ends_is_replaced_and_nothing_else_moves() {
    let old = wave();
    let stroke = bump(200);
    let tol = 0.01;
    let o = oversketch(&old, &stroke, tol).unwrap();
    assert!(
        (o.replaced.0 - 0.5).abs() < 1e-6 && (o.replaced.1 - 2.5).abs() < 1e-6,
        "{:?}",
        o.replaced
    );
    let (first, end) = o.new_pieces;
    let n = o.curve.pieces().len();
    assert_eq!(first, 1, "the first half of piece 0 is kept");
    assert_eq!(end, n - 1, "the last half of piece 2 is kept");
    // The kept parts are the old curve on [0, t0] and [t1, 3], exactly.
    let (t0, t1) = o.replaced;
    for k in 0..=20 {
        let s = k as f64 / 20.0;
        let before = at(&o.curve, s) - at(&old, t0 * s);
        let after = at(&o.curve, (n - 1) as f64 + s) - at(&old, t1 + (3.0 - t1) * s);
        assert!(
            before.length() < 1e-12 && after.length() < 1e-12,
            "s = {s}: {before} {after}"
        );
    }
    assert_g1(&o.curve, first - 1);
    assert_g1(&o.curve, end - 1);
    // The stroke's middle (outside the blends at its ends) is within the tolerance.
    for &q in &stroke[50..150] {
        let d = distance(&o.curve, first..end, q);
        assert!(d <= tol * (1.0 + 1e-9), "{q}: {d}");
    }
}

#[test]
fn a_stroke_drawn_backwards_replaces_the_same_part() {
    let old = wave();
    let mut stroke = bump(200);
    let forward = oversketch(&old, &stroke, 0.01).unwrap();
    stroke.reverse();
    let backward = oversketch(&old, &stroke, 0.01).unwrap();
    assert!((forward.replaced.0 - backward.replaced.0).abs() < 1e-9);
    assert!((forward.replaced.1 - backward.replaced.1).abs() < 1e-9);
    // Same direction as the curve: the new part runs from t0 to t1.
    let (first, _) = backward.new_pieces;
    let piece = &backward.curve.pieces()[first];
    let start = piece.evaluate(piece.interval().0).unwrap();
    assert!((start - at(&old, 0.5)).length() < 1e-9, "{start}");
}

#[test]
fn a_stroke_from_the_end_extends_the_curve() {
    let old = wave();
    let stroke: Vec<DVec2> = (0..=100)
        .map(|k| {
            let s = k as f64 / 100.0;
            DVec2::new(9.0 + 3.0 * s, -2.0 * s * s)
        })
        .collect();
    let o = oversketch(&old, &stroke, 0.01).unwrap();
    assert_eq!(o.replaced, (3.0, 3.0));
    assert_eq!(o.new_pieces.0, 3, "every old piece is kept");
    for i in 0..3 {
        for k in 0..=10 {
            let s = k as f64 / 10.0;
            let d = at(&o.curve, i as f64 + s) - at(&old, i as f64 + s);
            assert!(d.length() < 1e-12, "piece {i} moved by {d}");
        }
    }
    let (_, end) = o.curve.domain();
    assert!((at(&o.curve, end) - DVec2::new(12.0, -2.0)).length() <= 0.01);
    assert_g1(&o.curve, 2);
    // From the start instead: the stroke ends at (0, 0) coming from the left.
    let lead: Vec<DVec2> = (0..=100)
        .map(|k| DVec2::new(-3.0 + 0.03 * k as f64, 1.0 - 0.01 * k as f64))
        .collect();
    let o = oversketch(&old, &lead, 0.01).unwrap();
    assert_eq!(o.replaced, (0.0, 0.0));
    let (first, end) = o.new_pieces;
    assert_eq!(first, 0);
    assert_eq!(o.curve.pieces().len(), end + 3);
    assert!((at(&o.curve, 0.0) - DVec2::new(-3.0, 1.0)).length() <= 0.01);
    assert_g1(&o.curve, end - 1);
}

#[test]
fn a_closed_curve_stays_closed_across_its_seam() {
    let old = circle();
    // From 30° below the seam at (1, 0) to 30° above it, bulging out to radius 1.3.
    let stroke: Vec<DVec2> = (0..=150)
        .map(|k| {
            let s = k as f64 / 150.0;
            let angle = (-30.0 + 60.0 * s).to_radians();
            let r = 1.0 + 0.3 * (std::f64::consts::PI * s).sin();
            DVec2::new(r * angle.cos(), r * angle.sin())
        })
        .collect();
    let o = oversketch(&old, &stroke, 0.005).unwrap();
    let (t0, t1) = o.replaced;
    assert!(t0 > t1, "across the seam: {t0} > {t1}");
    assert!(
        (t0 - 4.0 + 1.0 / 3.0).abs() < 0.02 && (t1 - 1.0 / 3.0).abs() < 0.02,
        "{:?}",
        o.replaced
    );
    let c = &o.curve;
    let n = c.pieces().len();
    let (a, b) = c.domain();
    assert!((at(c, a) - at(c, b)).length() < 1e-12, "closed");
    for i in 0..n - 1 {
        assert_g1(c, i);
    }
    // The old curve's far side (90°, 180°, 270°) did not move.
    for t in [1.0, 2.0, 3.0] {
        let d = distance(c, 0..n, at(&old, t));
        assert!(d < 1e-6, "t = {t}: {d}");
    }
    // The bulge is drawn: the point at 0° is at radius 1.3.
    assert!(
        (distance(c, o.new_pieces.0..o.new_pieces.1, DVec2::new(1.3, 0.0))) <= 0.005 * (1.0 + 1e-9)
    );
}

#[test]
fn far_strokes_are_refused_with_the_distances() {
    let far: Vec<DVec2> = (0..10).map(|k| DVec2::new(k as f64, 5.0)).collect();
    let e = oversketch(&wave(), &far, 0.01).unwrap_err();
    assert_eq!(e.code(), "stroke-far-from-curve");
    assert!(e.to_string().starts_with("the stroke starts 4.44"), "{e}");
    // On a closed curve one end on it is not enough.
    let out: Vec<DVec2> = (0..10)
        .map(|k| DVec2::new(1.0 + 0.3 * k as f64, 0.0))
        .collect();
    assert_eq!(
        oversketch(&circle(), &out, 0.01).unwrap_err().code(),
        "stroke-far-from-curve"
    );
    // The stroke's own checks come first.
    assert_eq!(
        oversketch(&wave(), &[DVec2::ZERO], 0.01)
            .unwrap_err()
            .code(),
        "too-few-data-points"
    );
    assert_eq!(
        oversketch(&wave(), &bump(10), 0.0).unwrap_err().code(),
        "invalid-tolerance"
    );
    let nan = vec![DVec2::new(f64::NAN, 0.0), DVec2::ONE];
    assert_eq!(
        oversketch(&wave(), &nan, 0.01).unwrap_err().code(),
        "not-finite"
    );
}

#[test]
fn oversketch_time() {
    let stroke = bump(300);
    let old = wave();
    let start = std::time::Instant::now();
    let runs = 50;
    for _ in 0..runs {
        oversketch(&old, &stroke, 0.01).unwrap();
    }
    println!(
        "oversketch of 300 samples: {:?} per call",
        start.elapsed() / runs
    );
}
