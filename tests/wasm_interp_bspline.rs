//! `interpolateBSpline`, `approximateBSpline` and `bsplineInterpolationSystem` at the JavaScript
//! boundary, in Node: the options object (names, types, unknown keys), thrown messages that name
//! the bad value, and the layout of the system object.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::js_message as message;
use js_sys::{Array, Object, Reflect};
use splinelab::wasm::interp::{
    approximate_bspline, bspline_interpolation_system, interpolate_bspline,
};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test as test;

fn arr(values: &[f64]) -> JsValue {
    js_sys::Float64Array::from(values).into()
}

/// A plain JS array of numbers (the documented alternative to a Float64Array).
fn plain(values: &[f64]) -> JsValue {
    values
        .iter()
        .map(|&v| JsValue::from_f64(v))
        .collect::<Array>()
        .into()
}

/// `{ key: value, … }`.
fn object(entries: &[(&str, JsValue)]) -> JsValue {
    let o = Object::new();
    for (k, v) in entries {
        Reflect::set(&o, &JsValue::from_str(k), v).unwrap();
    }
    o.into()
}

/// The Croatian notes' data: five points at 0..4 (integer coordinates), degree 2.
const POINTS: [f64; 10] = [0.0, 0.0, 2.0, 4.0, 4.0, 2.0, 6.0, 6.0, 8.0, 0.0];
const PARAMS: [f64; 5] = [0.0, 1.0, 2.0, 3.0, 4.0];
const KNOTS: [f64; 9] = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0];

fn croatian_options() -> JsValue {
    object(&[
        ("knots", plain(&KNOTS)),
        ("startDerivative", arr(&[2.0, 8.0])),
    ])
}

fn get(o: &JsValue, key: &str) -> JsValue {
    Reflect::get(o, &JsValue::from_str(key)).unwrap()
}

fn numbers_of(v: &JsValue) -> Vec<f64> {
    Array::from(v).iter().map(|x| x.as_f64().unwrap()).collect()
}

#[test]
fn croatian_example_through_the_js_api() {
    let c = interpolate_bspline(arr(&POINTS), 2.0, 2.0, arr(&PARAMS), croatian_options()).unwrap();
    // Hand-solved in tests/interp_bspline.rs: r = (0,0) (1,4) (3,4) (5,0) (7,12) (8,0).
    let want = [0.0, 0.0, 1.0, 4.0, 3.0, 4.0, 5.0, 0.0, 7.0, 12.0, 8.0, 0.0];
    for (g, w) in c.control_points().iter().zip(want) {
        assert!((g - w).abs() < 1e-14, "{:?}", c.control_points());
    }
    assert_eq!(c.knots(), KNOTS);
}

#[test]
fn system_layout() {
    let s = bspline_interpolation_system(arr(&POINTS), 2.0, 2.0, arr(&PARAMS), croatian_options())
        .unwrap();
    assert_eq!(get(&s, "size").as_f64(), Some(6.0));
    let matrix = numbers_of(&get(&s, "matrix"));
    assert_eq!(matrix.len(), 36);
    assert_eq!(&matrix[6..8], &[-2.0, 2.0]);
    assert_eq!(&matrix[13..15], &[0.5, 0.5]);
    assert_eq!(
        numbers_of(&get(&s, "rhs")),
        [0.0, 0.0, 2.0, 8.0, 2.0, 4.0, 4.0, 2.0, 6.0, 6.0, 8.0, 0.0]
    );
    assert_eq!(numbers_of(&get(&s, "solution")).len(), 12);
    assert_eq!(numbers_of(&get(&s, "knots")), KNOTS);
    let rows: Vec<String> = Array::from(&get(&s, "rows"))
        .iter()
        .map(|r| r.as_string().unwrap())
        .collect();
    assert_eq!(
        rows,
        [
            "point",
            "start-derivative",
            "point",
            "point",
            "point",
            "point"
        ]
    );
    // Both derivatives: the end row sits before the last point row.
    let opts = object(&[
        ("startDerivative", arr(&[1.0, 0.0])),
        ("endDerivative", arr(&[0.0, 1.0])),
    ]);
    let s = bspline_interpolation_system(arr(&POINTS), 2.0, 3.0, arr(&PARAMS), opts).unwrap();
    let rows: Vec<String> = Array::from(&get(&s, "rows"))
        .iter()
        .map(|r| r.as_string().unwrap())
        .collect();
    assert_eq!(rows[5], "end-derivative");
    assert_eq!(rows[6], "point");
}

#[test]
fn params_may_be_a_kind() {
    let a = interpolate_bspline(
        arr(&POINTS),
        2.0,
        3.0,
        JsValue::from("uniform"),
        JsValue::UNDEFINED,
    )
    .unwrap();
    let b = interpolate_bspline(arr(&POINTS), 2.0, 3.0, arr(&PARAMS), JsValue::NULL).unwrap();
    assert_eq!(a.control_points(), b.control_points());
    assert!(message(interpolate_bspline(
        arr(&POINTS),
        2.0,
        3.0,
        JsValue::from("even"),
        JsValue::UNDEFINED
    ))
    .contains("\"even\""));
}

#[test]
fn options_are_checked_by_name_and_type() {
    let bad_key = object(&[("knot", plain(&KNOTS))]);
    assert_eq!(
        message(interpolate_bspline(arr(&POINTS), 2.0, 2.0, arr(&PARAMS), bad_key)),
        "options must be one of \"knots\", \"startDerivative\", \"endDerivative\", \"closed\", got \"knot\""
    );
    let wrong = object(&[("closed", JsValue::from("yes"))]);
    assert_eq!(
        message(interpolate_bspline(
            arr(&POINTS),
            2.0,
            2.0,
            arr(&PARAMS),
            wrong
        )),
        "closed must be a boolean, got string"
    );
    let wrong = object(&[("startDerivative", JsValue::from(3.0))]);
    assert!(message(interpolate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        arr(&PARAMS),
        wrong
    ))
    .starts_with("startDerivative must be an array of numbers"));
    let short = object(&[("endDerivative", arr(&[1.0]))]);
    assert_eq!(
        message(interpolate_bspline(
            arr(&POINTS),
            2.0,
            2.0,
            arr(&PARAMS),
            short
        )),
        "endDerivative must have 2 numbers, got 1"
    );
    assert_eq!(
        message(interpolate_bspline(
            arr(&POINTS),
            2.0,
            2.0,
            arr(&PARAMS),
            JsValue::from(5.0)
        )),
        "options must be an object, got number"
    );
    // approximateBSpline takes knots only.
    let closed = object(&[("closed", JsValue::TRUE)]);
    assert!(message(approximate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        4.0,
        arr(&PARAMS),
        closed
    ))
    .contains("got \"closed\""));
}

#[test]
fn errors_name_the_value() {
    assert!(message(interpolate_bspline(
        arr(&POINTS),
        2.0,
        11.0,
        arr(&PARAMS),
        JsValue::UNDEFINED
    ))
    .contains("degree must be 1..=10, got 11"));
    assert!(message(interpolate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        arr(&[0.0, 1.0, 1.0, 3.0, 4.0]),
        JsValue::UNDEFINED
    ))
    .contains("t_2 = 1 is not above t_1 = 1"));
    assert!(message(interpolate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        arr(&[0.0, 1.0]),
        JsValue::UNDEFINED
    ))
    .contains("one value per point (5), got 2"));
    assert!(message(approximate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        6.0,
        arr(&PARAMS),
        JsValue::UNDEFINED
    ))
    .contains("count = 6 control points is outside [degree + 1, number of points] = [3, 5]"));
    let closed = object(&[("closed", JsValue::TRUE)]);
    assert!(message(interpolate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        arr(&PARAMS),
        closed
    ))
    .contains("point 4"));
    assert_eq!(
        message(approximate_bspline(
            arr(&POINTS[..4]),
            2.0,
            3.0,
            4.0,
            arr(&PARAMS[..2]),
            JsValue::UNDEFINED
        )),
        "a least-squares B-spline of this degree (p + 1, at least 2) needs at least 4 data points, got 2"
    );
    assert_eq!(
        message(interpolate_bspline(
            arr(&POINTS[..4]),
            2.0,
            3.0,
            arr(&PARAMS[..2]),
            JsValue::UNDEFINED
        )),
        "an interpolating B-spline of this degree (p + 1 − end derivatives, at least 2) needs at least 4 data points, got 2"
    );
}

#[test]
fn approximation_and_closed_curves_from_js() {
    let fit = approximate_bspline(
        arr(&POINTS),
        2.0,
        2.0,
        4.0,
        plain(&PARAMS),
        JsValue::UNDEFINED,
    )
    .unwrap();
    let cp = fit.control_points();
    assert_eq!(cp.len(), 8);
    assert_eq!(&cp[..2], &[0.0, 0.0]);
    assert_eq!(&cp[6..], &[8.0, 0.0]);
    let ring = [0.0, 0.0, 2.0, 0.0, 2.0, 2.0, 0.0, 2.0, 0.0, 0.0];
    let closed = object(&[("closed", JsValue::TRUE)]);
    let c = interpolate_bspline(arr(&ring), 2.0, 3.0, arr(&PARAMS), closed).unwrap();
    assert_eq!(c.wrapped(), 3);
    assert_eq!(c.domain(), [0.0, 4.0]);
}

#[test]
fn three_dimensional_points_and_plain_arrays() {
    let points = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 1.0, -1.0, 4.0, 4.0, 2.0];
    let params = [0.0, 1.0, 2.5, 3.0];
    let c =
        interpolate_bspline(plain(&points), 3.0, 3.0, plain(&params), JsValue::UNDEFINED).unwrap();
    for (i, &t) in params.iter().enumerate() {
        let p = c.evaluate(t).unwrap();
        for k in 0..3 {
            assert!((p[k] - points[3 * i + k]).abs() < 1e-13, "C(t_{i}) = {p:?}");
        }
    }
    let opts = object(&[("startDerivative", arr(&[1.0, 0.0]))]);
    assert_eq!(
        message(interpolate_bspline(
            arr(&points),
            3.0,
            3.0,
            arr(&params),
            opts
        )),
        "startDerivative must have 3 numbers, got 2"
    );
    let fit = approximate_bspline(
        arr(&points),
        3.0,
        1.0,
        3.0,
        arr(&params),
        JsValue::UNDEFINED,
    )
    .unwrap();
    assert_eq!(fit.control_points().len(), 9);
}

#[test]
fn closed_system_is_cyclic_and_all_point_rows() {
    let ring = [0.0, 0.0, 2.0, 0.0, 3.0, 1.0, 2.0, 2.0, 0.0, 2.0, 0.0, 0.0];
    let params = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
    let closed = object(&[("closed", JsValue::TRUE)]);
    let s = bspline_interpolation_system(arr(&ring), 2.0, 3.0, arr(&params), closed).unwrap();
    assert_eq!(get(&s, "size").as_f64(), Some(5.0));
    let matrix = numbers_of(&get(&s, "matrix"));
    // Row 4 (t = 4): N = 1/6, 2/3, 1/6 in columns 4, 0, 1.
    let sixth = 1.0 / 6.0;
    for (j, want) in [(4, sixth), (0, 2.0 / 3.0), (1, sixth), (2, 0.0), (3, 0.0)] {
        assert!((matrix[20 + j] - want).abs() < 1e-15, "{matrix:?}");
    }
    let rows = Array::from(&get(&s, "rows"));
    assert!(rows
        .iter()
        .all(|r| r.as_string().as_deref() == Some("point")));
    assert_eq!(numbers_of(&get(&s, "knots")).len(), 5 + 3 + 3 + 1);
    // Too large: 65 unknowns.
    let many: Vec<f64> = (0..130)
        .map(|i| f64::from(i % 7) + f64::from(i / 2))
        .collect();
    let ts: Vec<f64> = (0..65).map(f64::from).collect();
    assert!(message(bspline_interpolation_system(
        arr(&many),
        2.0,
        3.0,
        arr(&ts),
        JsValue::UNDEFINED
    ))
    .contains("at most 64"));
}
