//! The JavaScript boundary of sketching, in Node: option and argument errors are coded and
//! name the bad value, the `…Report` forms have the documented shapes, every sample of a
//! stroke lies within the tolerance of what comes back (measured here by dense sampling, not by
//! the fitter), and the CompositeBezier methods the sketch demo edits with (`controlPoints`,
//! `degrees`, `setControlPoint`, `sampleUniform`) agree with a hand-written Bernstein sum.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::{assert_close, bernstein_sum2, distance_to_polyline, js_error};
use splinelab::wasm::bezier::JsCompositeBezier;
use splinelab::wasm::fit::{fit_bspline_report, fit_curve, fit_curve_report, oversketch_report};
use splinelab::DVec2;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test as test;

fn get(object: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(object, &JsValue::from_str(key)).unwrap()
}

/// `{ key: value, … }` from JS values.
fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let o = js_sys::Object::new();
    for (k, v) in entries {
        js_sys::Reflect::set(&o, &JsValue::from_str(k), v).unwrap();
    }
    o.into()
}

/// A half circle of radius 100 from (100, 0) to (−100, 0), 201 samples, flat.
fn half_circle() -> Vec<f64> {
    (0..=200)
        .flat_map(|i| {
            let a = std::f64::consts::PI * i as f64 / 200.0;
            [100.0 * a.cos(), 100.0 * a.sin()]
        })
        .collect()
}

fn flat(points: &[f64]) -> JsValue {
    js_sys::Float64Array::from(points).into()
}

/// The largest distance from a sample to the curve sampled at 4001 points (brute force).
fn max_distance(curve: &JsCompositeBezier, samples: &[f64]) -> f64 {
    let dense: Vec<DVec2> = curve
        .sample_uniform(4001.0)
        .unwrap()
        .chunks(2)
        .map(|c| DVec2::new(c[0], c[1]))
        .collect();
    samples
        .chunks(2)
        .map(|c| distance_to_polyline(DVec2::new(c[0], c[1]), &dense))
        .fold(0.0, f64::max)
}

#[test]
fn composite_bezier_edits_in_place_and_samples() {
    // Two cubics meeting at (3, 0).
    let points = [
        0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 3.0, 0.0, //
        3.0, 0.0, 4.0, -2.0, 5.0, -2.0, 6.0, 0.0,
    ];
    let mut c =
        JsCompositeBezier::new(flat(&points), 2.0, flat(&[3.0, 3.0]), JsValue::UNDEFINED).unwrap();
    assert_eq!(c.dim(), 2);
    assert_eq!(c.control_points(), points.to_vec());
    assert_eq!(c.degrees(), vec![3, 3]);
    c.set_control_point(1.0, 1.0, flat(&[4.0, -6.0])).unwrap();
    let moved: Vec<DVec2> = [(3.0, 0.0), (4.0, -6.0), (5.0, -2.0), (6.0, 0.0)]
        .iter()
        .map(|&(x, y)| DVec2::new(x, y))
        .collect();
    // Piece 1 lives on [1, 2]: t = 1.5 is its middle.
    let expected = bernstein_sum2(&moved, None, 0.5);
    let got = c.evaluate(1.5).unwrap();
    assert_close(got[0], expected.x, 1e-12, "x");
    assert_close(got[1], expected.y, 1e-12, "y");
    // Piece 0 did not follow.
    assert_eq!(&c.control_points()[..8], &points[..8]);
    // Three uniform samples over [0, 2]: the start, the joint, the end.
    assert_eq!(
        c.sample_uniform(3.0).unwrap(),
        vec![0.0, 0.0, 3.0, 0.0, 6.0, 0.0]
    );
    for (piece, i, name) in [
        (2.0, 0.0, "index-out-of-range"),
        (0.0, 4.0, "index-out-of-range"),
    ] {
        let e: JsValue = js_error(c.set_control_point(piece, i, flat(&[0.0, 0.0]))).into();
        assert_eq!(get(&e, "code"), name);
    }
    let e: JsValue = js_error(c.set_control_point(0.0, 1.0, flat(&[f64::NAN, 0.0]))).into();
    assert_eq!(get(&e, "code"), "not-finite");
}

#[test]
fn fit_curve_report_has_the_documented_shape_and_keeps_the_tolerance() {
    let samples = half_circle();
    let report = fit_curve_report(flat(&samples), 2.0, 0.5, JsValue::UNDEFINED).unwrap();
    // The same call without the report gives the same curve.
    let curve = fit_curve(flat(&samples), 2.0, 0.5, JsValue::UNDEFINED).unwrap();
    let reported = get(&report, "curve");
    assert_eq!(
        get(&reported, "pieceCount").as_f64(),
        Some(curve.piece_count() as f64)
    );
    let pieces = js_sys::Array::from(&get(&report, "pieces"));
    assert_eq!(pieces.length() as usize, curve.piece_count());
    assert!(get(&report, "breaks").is_instance_of::<js_sys::Uint32Array>());
    assert_eq!(
        js_sys::Uint32Array::from(get(&report, "breaks")).length() as usize,
        curve.piece_count() - 1,
        "an open curve has a break per inner joint"
    );
    assert_eq!(get(&report, "closed"), JsValue::FALSE);
    for piece in pieces.iter() {
        let e = get(&piece, "maxError").as_f64().unwrap();
        assert!(
            e <= 0.5,
            "a piece's measured error {e} is within the tolerance"
        );
        let (first, last) = (get(&piece, "first"), get(&piece, "last"));
        assert!(first.as_f64().unwrap() < last.as_f64().unwrap());
        let worst = get(&piece, "worst").as_f64().unwrap();
        assert!(first.as_f64().unwrap() <= worst && worst <= last.as_f64().unwrap());
    }
    assert!(
        js_sys::Array::from(&get(&report, "corners")).length() == 0,
        "a circle has no corner"
    );
    let d = max_distance(&curve, &samples);
    assert!(d <= 0.5 + 1e-3, "every sample within the tolerance: {d}");
}

#[test]
fn closed_and_c1_options_are_honoured() {
    // A full circle, its last sample a little before the first.
    let samples: Vec<f64> = (0..200)
        .flat_map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 200.0;
            [50.0 * a.cos(), 50.0 * a.sin()]
        })
        .collect();
    let options = object(&[("closed", JsValue::TRUE), ("continuity", "C1".into())]);
    let c = fit_curve(flat(&samples), 2.0, 0.25, options).unwrap();
    let points = c.control_points();
    let n = points.len();
    assert_eq!(
        &points[n - 2..],
        &points[..2],
        "closed: the last piece ends at the start"
    );
    let ks = c.continuity(Some(1e-6)).unwrap();
    for k in js_sys::Array::from(&ks).iter() {
        assert!(get(&k, "c").as_f64().unwrap() >= 1.0, "every joint C1");
    }
    assert!(max_distance(&c, &samples) <= 0.25 + 1e-3);
}

#[test]
fn fit_bspline_report_keeps_the_tolerance() {
    let samples = half_circle();
    let report = fit_bspline_report(flat(&samples), 2.0, 3.0, 0.5, JsValue::UNDEFINED).unwrap();
    let e = get(&report, "maxError").as_f64().unwrap();
    assert!(e <= 0.5, "measured error {e}");
    assert_eq!(get(&report, "closed"), JsValue::FALSE);
    let curve = get(&report, "curve");
    assert_eq!(get(&curve, "degree").as_f64(), Some(3.0));
}

#[test]
fn oversketch_report_names_the_replaced_part() {
    let samples = half_circle();
    let c = fit_curve(flat(&samples), 2.0, 0.5, JsValue::UNDEFINED).unwrap();
    // A stroke over the middle of the arc, a little outside it.
    let stroke: Vec<f64> = (0..=40)
        .flat_map(|i| {
            let a = std::f64::consts::PI * (0.3 + 0.4 * i as f64 / 40.0);
            [103.0 * a.cos(), 103.0 * a.sin()]
        })
        .collect();
    let report = oversketch_report(&c, flat(&stroke), 2.0, 0.5).unwrap();
    let replaced = common::float64_field(&report, "replaced");
    let (a, b) = (c.domain()[0], c.domain()[1]);
    assert!(
        a < replaced[0] && replaced[0] < replaced[1] && replaced[1] < b,
        "{replaced:?}"
    );
    assert!(get(&report, "newPieces").is_instance_of::<js_sys::Uint32Array>());
}

#[test]
fn bad_input_is_a_coded_error_naming_the_value() {
    let samples = half_circle();
    let cases: Vec<(Result<JsCompositeBezier, _>, &str, &str)> = vec![
        (
            fit_curve(flat(&[0.0, 0.0]), 2.0, 1.0, JsValue::UNDEFINED),
            "too-few-data-points",
            "stroke",
        ),
        (
            fit_curve(
                flat(&[0.0, f64::NAN, 1.0, 1.0]),
                2.0,
                1.0,
                JsValue::UNDEFINED,
            ),
            "not-finite",
            "NaN",
        ),
        (
            fit_curve(flat(&samples), 2.0, 0.0, JsValue::UNDEFINED),
            "invalid-tolerance",
            "0",
        ),
        (
            fit_curve(flat(&samples), 2.0, f64::NAN, JsValue::UNDEFINED),
            "invalid-tolerance",
            "NaN",
        ),
        (
            fit_curve(flat(&samples), 4.0, 1.0, JsValue::UNDEFINED),
            "invalid-dimension",
            "4",
        ),
        (
            fit_curve(flat(&samples[..5]), 2.0, 1.0, JsValue::UNDEFINED),
            "coordinate-count",
            "5",
        ),
        (
            fit_curve(
                flat(&samples),
                2.0,
                1.0,
                object(&[("smooth", JsValue::TRUE)]),
            ),
            "unknown-option",
            "smooth",
        ),
        (
            fit_curve(
                flat(&samples),
                2.0,
                1.0,
                object(&[("continuity", "G2".into())]),
            ),
            "unknown-option",
            "G2",
        ),
        (
            fit_curve(
                flat(&samples),
                2.0,
                1.0,
                object(&[("closed", "yes".into())]),
            ),
            "argument-type",
            "closed",
        ),
        (
            fit_curve(flat(&samples), 2.0, 1.0, JsValue::from_f64(3.0)),
            "argument-type",
            "options",
        ),
        (
            fit_curve(JsValue::from_str("0,0"), 2.0, 1.0, JsValue::UNDEFINED),
            "argument-type",
            "points",
        ),
    ];
    for (result, code, named) in cases {
        let e = js_error(result);
        let message: String = e.message().into();
        let e: JsValue = e.into();
        assert_eq!(get(&e, "code"), code, "{message}");
        assert!(message.contains(named), "{message} names {named}");
    }
    let c = fit_curve(flat(&samples), 2.0, 1.0, JsValue::UNDEFINED).unwrap();
    let e: JsValue = js_error(oversketch_report(
        &c,
        flat(&[0.0, 0.0, 1.0, 0.0, 0.0]),
        3.0,
        1.0,
    ))
    .into();
    assert_eq!(get(&e, "code"), "dimension-mismatch");
}
