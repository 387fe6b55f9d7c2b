//! Sketching: `fit_curve` and `oversketch` against independent expectations — samples of
//! known curves (circles, a cubic sampled at uneven speed with seeded jitter, polylines with
//! corners at known samples), every sample's distance to the result measured here by brute
//! force (a dense polyline of 10⁴ points per piece from an explicit Bernstein sum), continuity
//! checked by finite differences, and the oversketch invariant "outside the replaced part
//! nothing moved" checked point by point.
#![cfg(not(target_arch = "wasm32"))]

mod common;

use common::{bernstein_sum2, distance_to_polyline};
use splinelab::bezier::CompositeCurve;
use splinelab::fit::{fit_curve, oversketch, CurveFit, FitOptions, Smoothness};
use splinelab::prelude::*;
use splinelab::{DVec2, Error};
use std::f64::consts::{PI, TAU};

/// A tiny linear congruential generator (Knuth's MMIX constants): jitter in `[−a, a]`.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn jitter(&mut self, a: f64) -> DVec2 {
        DVec2::new(a * (2.0 * self.next() - 1.0), a * (2.0 * self.next() - 1.0))
    }
}

/// Dense points of every piece (10⁴ + 1 each) by the explicit Bernstein sum.
fn dense(curve: &CompositeCurve<DVec2>) -> Vec<Vec<DVec2>> {
    curve
        .pieces()
        .iter()
        .map(|p| {
            let ctrl = p.control_points();
            (0..=10_000)
                .map(|k| bernstein_sum2(&ctrl, None, k as f64 / 10_000.0))
                .collect()
        })
        .collect()
}

/// The largest distance from a sample to the curve (brute force over the dense polylines,
/// each sample against every piece whose padded box is near it).
fn max_distance(curve: &CompositeCurve<DVec2>, samples: &[DVec2]) -> f64 {
    let pieces = dense(curve);
    let boxes: Vec<(DVec2, DVec2)> = pieces
        .iter()
        .map(|v| {
            v.iter()
                .fold((v[0], v[0]), |(lo, hi), &p| (lo.min(p), hi.max(p)))
        })
        .collect();
    samples
        .iter()
        .map(|&q| {
            // Box distance is a lower bound: visit pieces nearest first, stop when no box is nearer.
            let mut order: Vec<(f64, usize)> = boxes
                .iter()
                .enumerate()
                .map(|(i, &(lo, hi))| ((q - q.clamp(lo, hi)).length(), i))
                .collect();
            order.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut best = f64::INFINITY;
            for (lower, i) in order {
                if lower >= best {
                    break;
                }
                best = best.min(distance_to_polyline(q, &pieces[i]));
            }
            best
        })
        .fold(0.0, f64::max)
}

/// Fits and checks every sample within `tol` by brute force; checks the report's shape.
fn fit_checked(samples: &[DVec2], tol: f64, options: &FitOptions) -> CurveFit<DVec2> {
    let fit = fit_curve(samples, tol, options).unwrap();
    let d = max_distance(&fit.curve, samples);
    assert!(d <= tol * (1.0 + 1e-6), "max distance {d} > {tol}");
    let r = &fit.report;
    assert_eq!(r.pieces.len(), fit.curve.pieces().len());
    assert_eq!(r.breaks.len(), r.pieces.len() - 1);
    for (k, p) in r.pieces.iter().enumerate() {
        assert!(p.max_error <= tol, "piece {k}: {}", p.max_error);
        if k + 1 < r.pieces.len() {
            assert_eq!(p.last, r.breaks[k]);
            assert_eq!(p.last, r.pieces[k + 1].first);
        }
    }
    // Every piece's reported error is its measured distance at its worst sample (±1e-9).
    for p in &r.pieces {
        if p.max_error > 0.0 && p.first < p.last {
            let piece = &fit.curve.pieces()[r.pieces.iter().position(|x| x == p).unwrap()];
            let one = CompositeCurve::new(vec![piece.clone()], &[0.0, 1.0]).unwrap();
            let brute = max_distance(&one, &[samples[p.worst]]);
            assert!(
                (brute - p.max_error).abs() <= 1e-5 * tol.max(1.0),
                "worst sample {}: brute {brute} vs reported {}",
                p.worst,
                p.max_error
            );
        }
    }
    fit
}

/// Points on a circle of radius `r` from angle `a0` to `a1`, `n + 1` samples.
fn arc(r: f64, a0: f64, a1: f64, n: usize) -> Vec<DVec2> {
    (0..=n)
        .map(|i| {
            let a = a0 + (a1 - a0) * i as f64 / n as f64;
            DVec2::new(r * a.cos(), r * a.sin())
        })
        .collect()
}

/// A polyline through `vertices` sampled every `step`, with jitter; returns the samples and
/// the sample index of each inner vertex.
fn polyline(vertices: &[DVec2], step: f64, jitter: f64, seed: u64) -> (Vec<DVec2>, Vec<usize>) {
    let mut rng = Lcg(seed);
    let mut out = Vec::new();
    let mut at = Vec::new();
    for w in vertices.windows(2) {
        if !out.is_empty() {
            at.push(out.len());
        }
        let n = ((w[1] - w[0]).length() / step).ceil() as usize;
        for k in 0..n {
            out.push(w[0].lerp(w[1], k as f64 / n as f64) + rng.jitter(jitter));
        }
    }
    out.push(*vertices.last().unwrap() + rng.jitter(jitter));
    (out, at)
}

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

#[test]
fn a_half_circle_takes_few_pieces_and_no_corner() {
    let samples = arc(100.0, 0.0, PI, 200);
    let fit = fit_checked(&samples, 0.5, &FitOptions::default());
    println!("half circle tol 0.5: {} pieces", fit.curve.pieces().len());
    assert!(fit.curve.pieces().len() <= 3);
    assert!(fit.report.corners.is_empty());
    assert!(!fit.report.closed);
}

#[test]
fn a_full_circle_closes_itself_in_four_to_six_pieces() {
    // The last sample a little before the first: closed by proximity.
    let samples = arc(100.0, 0.0, TAU * 0.995, 400);
    let fit = fit_checked(&samples, 0.1, &FitOptions::default());
    let k = fit.curve.pieces().len();
    println!("circle tol 1e-3 r: {k} pieces");
    assert!(fit.report.closed);
    assert!((4..=6).contains(&k), "{k} pieces");
    assert!(fit.report.corners.is_empty());
    let (a, b) = fit.curve.domain();
    assert_eq!(
        fit.curve.evaluate(a).unwrap(),
        fit.curve.evaluate(b).unwrap()
    );
    // Smooth at the seam: unit tangents agree.
    let t0 = fit.curve.derivative(a, 1).unwrap().normalize();
    let t1 = fit.curve.derivative(b, 1).unwrap().normalize();
    assert!((t0 - t1).length() < 1e-9, "{t0} {t1}");
}

/// A cubic Bézier sampled at uneven speed with jitter ±0.25: one piece at tolerance 1.
#[test]
fn a_sampled_cubic_is_one_piece() {
    let ctrl = [v(0.0, 0.0), v(60.0, 150.0), v(220.0, 140.0), v(300.0, 10.0)];
    let mut rng = Lcg(7);
    let samples: Vec<DVec2> = (0..=150)
        .map(|i| {
            let s = i as f64 / 150.0;
            let t = s * s * (3.0 - 2.0 * s); // slow at both ends
            bernstein_sum2(&ctrl, None, t) + rng.jitter(0.25)
        })
        .collect();
    let fit = fit_checked(&samples, 1.0, &FitOptions::default());
    assert!(fit.report.corners.is_empty(), "{:?}", fit.report.corners);
    assert_eq!(fit.curve.pieces().len(), 1, "{:?}", fit.report);
}

#[test]
fn a_jittered_circle_has_no_corner() {
    for seed in 1..=5 {
        let mut rng = Lcg(seed);
        let samples: Vec<DVec2> = arc(80.0, 0.0, TAU * 0.98, 300)
            .into_iter()
            .map(|p| p + rng.jitter(0.5))
            .collect();
        let fit = fit_checked(&samples, 1.0, &FitOptions::default());
        assert!(
            fit.report.corners.is_empty(),
            "seed {seed}: {:?}",
            fit.report.corners
        );
        assert!(fit.report.closed);
        println!(
            "jittered circle seed {seed}: {} pieces",
            fit.curve.pieces().len()
        );
        // A wave with round peaks (radius 15 on a 400-wide drawing).
        let wave: Vec<DVec2> = (0..=600)
            .map(|i| {
                let t = i as f64 / 600.0 * 4.0 * PI;
                v(30.0 * t, 60.0 * t.sin()) + rng.jitter(0.5)
            })
            .collect();
        let fit = fit_checked(&wave, 1.0, &FitOptions::default());
        assert!(
            fit.report.corners.is_empty(),
            "wave, seed {seed}: {:?}",
            fit.report.corners
        );
    }
}

/// Corners of open polylines found at the vertices (±2 samples), nothing else.
#[test]
fn polyline_corners_are_found_at_the_vertices() {
    let shapes: Vec<Vec<DVec2>> = vec![
        // Three sides of a square.
        vec![v(0.0, 0.0), v(100.0, 0.0), v(100.0, 100.0), v(0.0, 100.0)],
        // A triangle's outline, open.
        vec![v(0.0, 0.0), v(120.0, 0.0), v(60.0, 100.0), v(20.0, 30.0)],
        // A zigzag.
        vec![
            v(0.0, 0.0),
            v(40.0, 50.0),
            v(80.0, 0.0),
            v(120.0, 50.0),
            v(160.0, 0.0),
            v(200.0, 50.0),
        ],
    ];
    for (k, shape) in shapes.iter().enumerate() {
        for seed in 1..=4 {
            let (samples, at) = polyline(shape, 2.0, 0.5, seed);
            let fit = fit_checked(&samples, 1.0, &FitOptions::default());
            let found: Vec<usize> = fit.report.corners.iter().map(|c| c.index).collect();
            assert_eq!(
                found.len(),
                at.len(),
                "shape {k} seed {seed}: {found:?} vs {at:?}"
            );
            for (f, a) in found.iter().zip(&at) {
                assert!(
                    f.abs_diff(*a) <= 2,
                    "shape {k} seed {seed}: {found:?} vs {at:?}"
                );
            }
            // Straight sides between corners: one piece each.
            assert_eq!(fit.curve.pieces().len(), at.len() + 1, "shape {k}");
            for c in &fit.report.corners {
                assert!(c.angle > 0.7 && c.straw < 0.95, "{c:?}");
                assert!(fit.report.breaks.contains(&c.index));
            }
        }
    }
}

#[test]
fn a_closed_square_has_four_corners() {
    let square = [
        v(0.0, 0.0),
        v(100.0, 0.0),
        v(100.0, 100.0),
        v(0.0, 100.0),
        v(0.0, 0.0),
    ];
    // Start in the middle of a side, so no corner sits at the stroke's ends.
    let mut shifted = vec![v(50.0, 0.0)];
    shifted.extend_from_slice(&square[1..]);
    shifted.push(v(50.0, 0.0));
    for (name, shape) in [
        ("from a corner", &square[..]),
        ("from a side", &shifted[..]),
    ] {
        let (samples, _) = polyline(shape, 2.0, 0.4, 3);
        let fit = fit_checked(&samples, 1.0, &FitOptions::default());
        assert!(fit.report.closed, "{name}");
        assert_eq!(
            fit.report.corners.len(),
            4,
            "{name}: {:?}",
            fit.report.corners
        );
        assert_eq!(fit.curve.pieces().len(), 4, "{name}");
        let (a, b) = fit.curve.domain();
        assert_eq!(
            fit.curve.evaluate(a).unwrap(),
            fit.curve.evaluate(b).unwrap()
        );
        // The curve starts at a corner.
        let start = fit.curve.evaluate(a).unwrap();
        assert!(
            square.iter().any(|&c| (c - start).length() < 3.0),
            "{name}: starts at {start}"
        );
    }
}

/// Without corner detection every joint is smooth (G1): unit tangents agree.
#[test]
fn g1_joints_share_the_unit_tangent() {
    let mut rng = Lcg(11);
    let samples: Vec<DVec2> = (0..=600)
        .map(|i| {
            let t = i as f64 / 600.0 * 4.0 * PI;
            v(30.0 * t, 60.0 * t.sin() * (1.0 + 0.2 * t)) + rng.jitter(0.3)
        })
        .collect();
    let options = FitOptions {
        corners: false,
        ..FitOptions::default()
    };
    let fit = fit_checked(&samples, 0.5, &options);
    assert!(fit.curve.pieces().len() >= 3);
    println!("sine wave tol 0.5: {} pieces", fit.curve.pieces().len());
    for j in 1..fit.curve.pieces().len() {
        let left = fit.curve.pieces()[j - 1].derivative(j as f64, 1).unwrap();
        let right = fit.curve.pieces()[j].derivative(j as f64, 1).unwrap();
        let (l, r) = (left.normalize(), right.normalize());
        assert!((l - r).length() < 1e-9, "joint {j}: {l} vs {r}");
    }
}

/// C1: the derivative is continuous, checked by one-sided finite differences at each joint.
#[test]
fn c1_joints_have_equal_derivatives() {
    let mut rng = Lcg(5);
    let open: Vec<DVec2> = (0..=600)
        .map(|i| {
            let t = i as f64 / 600.0 * 4.0 * PI;
            v(30.0 * t, 60.0 * t.sin() * (1.0 + 0.2 * t)) + rng.jitter(0.3)
        })
        .collect();
    let closed = arc(50.0, 0.0, TAU * 0.995, 200);
    for (samples, tol) in [(&open, 0.5), (&closed, 0.25)] {
        let options = FitOptions {
            smoothness: Smoothness::C1,
            corners: false,
            ..FitOptions::default()
        };
        let fit = fit_checked(samples, tol, &options);
        let c = &fit.curve;
        let k = c.pieces().len();
        println!("C1 fit: {k} pieces");
        let h = 1e-6;
        let joints: Vec<(f64, f64)> = (1..k).map(|j| (j as f64, j as f64)).collect();
        let mut all = joints;
        if fit.report.closed {
            all.push((k as f64, 0.0));
        }
        for (left_t, right_t) in all {
            // One-sided differences from the evaluated curve.
            let left = (c.evaluate(left_t).unwrap() - c.evaluate(left_t - h).unwrap()) / h;
            let right = (c.evaluate(right_t + h).unwrap() - c.evaluate(right_t).unwrap()) / h;
            let scale = left.length().max(1.0);
            assert!(
                (left - right).length() <= 1e-3 * scale,
                "joint at {left_t}: {left} vs {right}"
            );
        }
    }
}

#[test]
fn degenerate_strokes_do_not_fail() {
    let o = FitOptions::default();
    // Two samples: one straight piece.
    let two = [v(0.0, 0.0), v(3.0, 4.0)];
    let fit = fit_checked(&two, 0.1, &o);
    assert_eq!(fit.curve.pieces().len(), 1);
    let mid = fit.curve.evaluate(0.5).unwrap();
    assert!((mid - v(1.5, 2.0)).length() < 1e-12);
    // All samples equal: one degenerate piece at the point.
    let same = [v(2.0, 2.0); 5];
    let fit = fit_curve(&same, 0.1, &o).unwrap();
    assert_eq!(fit.curve.pieces().len(), 1);
    assert!((fit.curve.evaluate(0.3).unwrap() - v(2.0, 2.0)).length() < 1e-12);
    assert_eq!(fit.report.pieces[0].max_error, 0.0);
    // Repeated samples are skipped; collinear strokes are straight.
    let mut repeated = Vec::new();
    for i in 0..50 {
        let p = v(i as f64, 2.0 * i as f64);
        repeated.push(p);
        repeated.push(p);
    }
    let fit = fit_checked(&repeated, 0.01, &o);
    assert_eq!(fit.curve.pieces().len(), 1);
    assert!(fit.report.corners.is_empty());
    // A back-and-forth line: a reversal is a corner.
    let (samples, at) = polyline(&[v(0.0, 0.0), v(100.0, 0.0), v(20.0, 0.0)], 1.0, 0.0, 1);
    let fit = fit_checked(&samples, 0.5, &o);
    assert_eq!(fit.report.corners.len(), 1);
    assert!(fit.report.corners[0].index.abs_diff(at[0]) <= 2);
    assert!(fit.report.corners[0].angle > 3.0);
}

#[test]
fn bad_input_is_a_coded_error() {
    let o = FitOptions::default();
    let good = arc(10.0, 0.0, 1.0, 10);
    assert!(matches!(
        fit_curve(&[v(0.0, 0.0), v(f64::NAN, 1.0)], 1.0, &o),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        fit_curve(&[v(0.0, 0.0)], 1.0, &o),
        Err(Error::TooFewDataPoints { .. })
    ));
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            fit_curve(&good, tol, &o),
            Err(Error::InvalidTolerance { .. })
        ));
    }
}

/// A spiral of a million jittered samples, and a tolerance far below the jitter: both return
/// within the tolerance (timed, printed only).
#[test]
fn huge_strokes_and_tiny_tolerances_return() {
    let mut rng = Lcg(99);
    let million: Vec<DVec2> = (0..1_000_000)
        .map(|i| {
            let t = i as f64 / 1_000_000.0 * 12.0 * PI;
            v(t * 40.0 * t.cos(), t * 40.0 * t.sin()) + rng.jitter(0.5)
        })
        .collect();
    let start = std::time::Instant::now();
    let fit = fit_curve(&million, 1.0, &FitOptions::default()).unwrap();
    println!(
        "1M samples: {} pieces in {:?}",
        fit.curve.pieces().len(),
        start.elapsed()
    );
    let max = fit
        .report
        .pieces
        .iter()
        .map(|p| p.max_error)
        .fold(0.0, f64::max);
    assert!(max <= 1.0);
    let small: Vec<DVec2> = million[..20_000].to_vec();
    let start = std::time::Instant::now();
    let fit = fit_curve(&small, 1e-9, &FitOptions::default()).unwrap();
    println!(
        "20k jittered samples at 1e-9: {} pieces in {:?}",
        fit.curve.pieces().len(),
        start.elapsed()
    );
    let max = fit
        .report
        .pieces
        .iter()
        .map(|p| p.max_error)
        .fold(0.0, f64::max);
    assert!(max <= 1e-9, "{max}");
}

/// Time per 1000 samples on pointer-like strokes (printed, not asserted).
#[test]
fn speed_per_thousand_samples() {
    let mut rng = Lcg(3);
    let wave: Vec<DVec2> = (0..=1000)
        .map(|i| {
            let t = i as f64 / 1000.0 * 6.0 * PI;
            v(20.0 * t, 80.0 * t.sin()) + rng.jitter(0.5)
        })
        .collect();
    let (square, _) = polyline(
        &[
            v(0.0, 0.0),
            v(300.0, 0.0),
            v(300.0, 300.0),
            v(0.0, 300.0),
            v(0.0, 0.0),
        ],
        1.2,
        0.5,
        2,
    );
    for (name, s) in [("wave", &wave), ("square", &square)] {
        for tol in [0.5, 1.0, 2.0] {
            let start = std::time::Instant::now();
            let runs = 20;
            let mut pieces = 0;
            for _ in 0..runs {
                pieces = fit_curve(s, tol, &FitOptions::default())
                    .unwrap()
                    .curve
                    .pieces()
                    .len();
            }
            let per =
                start.elapsed().as_secs_f64() / runs as f64 * 1000.0 / s.len() as f64 * 1000.0;
            println!("{name} tol {tol}: {pieces} pieces, {per:.3} ms per 1000 samples");
        }
    }
}

/// The old curve's point at `t` (outside the replaced part) lies on the new curve at the
/// parameter the split maps it to, to 1e-12; whole kept pieces are bit-identical.
fn check_kept(old: &CompositeCurve<DVec2>, o: &splinelab::fit::Oversketch<DVec2>) {
    let (t0, t1) = o.replaced;
    let (first, end) = o.new_pieces;
    let new = &o.curve;
    let (a, b) = old.domain();
    let i0 = (t0.floor() as usize).min(old.pieces().len() - 1);
    // Pieces wholly before t0.
    for j in 0..i0.min(first) {
        assert_eq!(
            old.pieces()[j].control_points(),
            new.pieces()[j].control_points(),
            "piece {j} kept"
        );
    }
    // The old curve's points before t0 and after t1.
    for k in 0..=400 {
        let t = a + (b - a) * k as f64 / 400.0;
        let p = old.evaluate(t).unwrap();
        let mapped = if t0 == a && t1 == a {
            // Prepended: everything shifts by the new pieces.
            t + end as f64
        } else if t <= t0 {
            if t < i0 as f64 || t0 == i0 as f64 {
                t
            } else {
                i0 as f64 + (t - i0 as f64) / (t0 - i0 as f64)
            }
        } else if t >= t1 {
            let i1 = (t1.floor() as usize).min(old.pieces().len() - 1);
            let s1 = t1 - i1 as f64;
            if t < (i1 + 1) as f64 || t1 >= old.pieces().len() as f64 {
                // In the split piece: new piece `end` on [end, end + 1].
                if s1 > 0.0 {
                    end as f64 + (t - t1) / (1.0 - s1)
                } else {
                    end as f64 + (t - i1 as f64)
                }
            } else {
                t + end as f64 - i1 as f64
            }
        } else {
            continue;
        };
        let q = new.evaluate(mapped.min(new.domain().1)).unwrap();
        assert!(
            (p - q).length() <= 1e-12 * (1.0 + p.length()),
            "old t = {t} ({p}) moved to {q} (new t = {mapped})"
        );
    }
    // G1 seams.
    for j in [first, end] {
        if j == 0 || j >= new.pieces().len() {
            continue;
        }
        let l = new.pieces()[j - 1]
            .derivative(j as f64, 1)
            .unwrap()
            .normalize();
        let r = new.pieces()[j].derivative(j as f64, 1).unwrap().normalize();
        assert!((l - r).length() < 1e-9, "seam at {j}: {l} vs {r}");
        let pl = new.pieces()[j - 1].evaluate(j as f64).unwrap();
        let pr = new.pieces()[j].evaluate(j as f64).unwrap();
        assert!((pl - pr).length() <= 1e-12 * (1.0 + pl.length()));
    }
}

#[test]
fn oversketch_replaces_only_the_part_between_the_stroke_ends() {
    let old = fit_curve(&arc(100.0, 0.0, PI, 200), 0.5, &FitOptions::default())
        .unwrap()
        .curve;
    let stroke = arc(103.0, 0.3 * PI, 0.7 * PI, 40);
    let start = std::time::Instant::now();
    let o = oversketch(&old, &stroke, 0.5).unwrap();
    println!("oversketch: {:?}", start.elapsed());
    let (t0, t1) = o.replaced;
    let (a, b) = old.domain();
    assert!(a < t0 && t0 < t1 && t1 < b, "{:?}", o.replaced);
    check_kept(&old, &o);
    // The stroke's middle half (outside the blends onto the curve) is within the tolerance.
    let d = max_distance(&o.curve, &stroke[stroke.len() / 4..=3 * stroke.len() / 4]);
    assert!(d <= 0.5 * (1.0 + 1e-6), "{d}");
    // Drawn the other way: the same part is replaced.
    let mut reversed = stroke.clone();
    reversed.reverse();
    let r = oversketch(&old, &reversed, 0.5).unwrap();
    assert!((r.replaced.0 - t0).abs() < 1e-6 && (r.replaced.1 - t1).abs() < 1e-6);
}

#[test]
fn oversketch_from_an_end_extends_the_curve() {
    let old = fit_curve(&arc(100.0, 0.0, PI, 200), 0.5, &FitOptions::default())
        .unwrap()
        .curve;
    // From the end (−100, 0) straight down.
    let stroke: Vec<DVec2> = (0..=50).map(|i| v(-100.0, -2.0 * i as f64)).collect();
    let o = oversketch(&old, &stroke, 0.5).unwrap();
    let (_, b) = old.domain();
    assert!((o.replaced.1 - b).abs() < 1e-12, "{:?}", o.replaced);
    assert!(o.curve.pieces().len() > old.pieces().len());
    let end = o.curve.evaluate(o.curve.domain().1).unwrap();
    assert!((end - v(-100.0, -100.0)).length() < 1e-9, "{end}");
    check_kept(&old, &o);
    // A stroke far from the curve says nothing about which part to redraw: refused.
    let far: Vec<DVec2> = (0..=20).map(|i| v(130.0, -20.0 - 3.0 * i as f64)).collect();
    let e = oversketch(&old, &far, 0.5).unwrap_err();
    assert_eq!(e.code(), "stroke-far-from-curve");
}

#[test]
fn oversketch_keeps_a_closed_curve_closed() {
    let old = fit_curve(
        &arc(100.0, 0.0, TAU * 0.995, 300),
        0.25,
        &FitOptions::default(),
    )
    .unwrap();
    assert!(old.report.closed);
    let old = old.curve;
    // Across the seam at angle 0: from −0.2π to 0.2π, outside.
    let stroke = arc(104.0, -0.2 * PI, 0.2 * PI, 60);
    let o = oversketch(&old, &stroke, 0.25).unwrap();
    let c = &o.curve;
    let (a, b) = c.domain();
    let (p, q) = (c.evaluate(a).unwrap(), c.evaluate(b).unwrap());
    assert!((p - q).length() < 1e-9, "closed: {p} {q}");
    // The far side of the circle did not move: (−100, 0) is still on the curve.
    let far = max_distance(c, &[v(-100.0, 0.0), v(0.0, 100.0), v(0.0, -100.0)]);
    assert!(far < 0.26, "{far}");
    let d = max_distance(c, &stroke[stroke.len() / 4..=3 * stroke.len() / 4]);
    assert!(d <= 0.25 * (1.0 + 1e-6), "{d}");
}
