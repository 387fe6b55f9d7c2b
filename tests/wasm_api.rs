//! The JavaScript boundary, in Node: bad input becomes a thrown `Error` with a clear message,
//! never a trap, and the wrappers return the flat layouts the README documents.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::js_message as message;
use splinelab::prelude::*;
use splinelab::wasm::{self, JsBezierCurve};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test as test;

/// An array argument as the API takes it (a `JsValue`, so that JS `null` or a number gets a
/// clear error).
fn arr(values: &[f64]) -> JsValue {
    js_sys::Float64Array::from(values).into()
}

fn example() -> JsBezierCurve {
    JsBezierCurve::new(
        arr(&[0.0, 0.0, 2.0, 2.0, 6.0, 4.0, 8.0, 2.0]),
        2.0,
        JsValue::UNDEFINED,
    )
    .unwrap()
}

/// `error[key]` (undefined when absent).
fn field(error: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(error, &key.into()).unwrap()
}

/// A thrown Error carries `code` and `params` (the variant's fields, camelCase) besides the
/// English message, so a page can word it in its own language (README "Errors").
#[test]
fn errors_carry_code_and_params() {
    let knots = arr(&[0.0; 8]); // 5 cubic points need n + p + 2 = 9 knots
    let pts = arr(&[0.0, 0.0, 1.0, 1.0, 2.0, 0.0, 3.0, 1.0, 4.0, 0.0]);
    let e: JsValue = common::js_error(wasm::JsBSplineCurve::new(
        pts,
        2.0,
        3.0,
        knots,
        JsValue::UNDEFINED,
    ))
    .into();
    assert_eq!(field(&e, "code"), "knot-count");
    let params = field(&e, "params");
    for (key, value) in [
        ("expected", 9.0),
        ("got", 8.0),
        ("points", 5.0),
        ("degree", 3.0),
    ] {
        assert_eq!(field(&params, key).as_f64(), Some(value), "params.{key}");
    }
    // A subject is a key of error/phrase.rs, not English; snake_case fields become camelCase.
    let e: JsValue = common::js_error(JsBezierCurve::new(
        arr(&[0.0, 0.0]),
        2.0,
        JsValue::UNDEFINED,
    ))
    .into();
    assert_eq!(field(&e, "code"), "too-few-points");
    assert_eq!(field(&field(&e, "params"), "what"), "bezier-curve");
    // sampleGrid 5000 × 5000 of a patch: 600 MB of numbers, above the 256 MiB cap.
    let patch = wasm::JsBezierSurface::new(
        arr(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0]),
        2.0,
        2.0,
        JsValue::UNDEFINED,
    )
    .unwrap();
    let us = arr(&vec![0.5; 5000]);
    let e: JsValue = common::js_error(patch.sample_grid(us.clone(), us)).into();
    assert_eq!(field(&e, "code"), "result-too-large");
    assert_eq!(
        field(&field(&e, "params"), "valueBytes").as_f64(),
        Some(8.0)
    );
    // An error about one argument nests its cause as { code, params }.
    let e: JsValue = common::js_error(wasm::interpolate_surface(
        arr(&[0.0; 12]),
        2.0,
        2.0,
        3.0,
        1.0,
        JsValue::UNDEFINED,
    ))
    .into();
    assert_eq!(field(&e, "code"), "in-argument");
    let source = field(&field(&e, "params"), "source");
    assert_eq!(field(&source, "code"), "too-few-data-points");
    assert_eq!(
        field(&field(&source, "params"), "needed").as_f64(),
        Some(4.0)
    );
    // NotFinite names a subject and an index.
    let e: JsValue = common::js_error(JsBezierCurve::new(
        arr(&[0.0, 0.0, f64::NAN, 1.0]),
        2.0,
        JsValue::UNDEFINED,
    ))
    .into();
    let params = field(&e, "params");
    assert_eq!(field(&params, "what"), "coordinate");
    assert_eq!(field(&params, "index").as_f64(), Some(2.0));
    assert!(field(&params, "value").as_f64().unwrap().is_nan());
}

#[test]
fn constructor_errors_name_the_bad_value() {
    assert_eq!(
        message(JsBezierCurve::new(
            arr(&[0.0, 0.0]),
            2.0,
            JsValue::UNDEFINED
        )),
        "a Bézier curve needs at least 2 control points, got 1"
    );
    assert!(message(JsBezierCurve::new(
        arr(&[0.0, 0.0, 1.0]),
        2.0,
        JsValue::UNDEFINED
    ))
    .contains("coordinate count 3"));
    assert_eq!(
        message(JsBezierCurve::new(arr(&[0.0; 8]), 4.0, JsValue::UNDEFINED)),
        "dim must be 2 or 3, got 4"
    );
    assert_eq!(
        message(JsBezierCurve::new(arr(&[0.0; 8]), 1.0, JsValue::UNDEFINED)),
        "dim must be 2 or 3, got 1"
    );
    assert!(message(JsBezierCurve::new(
        arr(&[0.0, f64::NAN, 1.0, 1.0]),
        2.0,
        JsValue::UNDEFINED
    ))
    .contains("coordinate 1 is NaN"));
    assert!(message(JsBezierCurve::new(
        arr(&[0.0, 0.0, 1.0, 1.0]),
        2.0,
        arr(&[1.0, 0.0])
    ))
    .contains("weight 1 is 0"));
    assert!(message(JsBezierCurve::new(
        arr(&[0.0, 0.0, 1.0, 1.0]),
        2.0,
        arr(&[1.0])
    ))
    .contains("got 1"));
    // dim is checked before the coordinate count (the documented validation order).
    assert!(
        message(JsBezierCurve::new(arr(&[0.0; 5]), 5.0, JsValue::UNDEFINED))
            .starts_with("dim must be 2 or 3")
    );
}

#[test]
fn numbers_in_messages_print_as_javascript_prints_them() {
    let c = example();
    // Rust would print these as "-0.0000001", "100000000000000000000000" and "-inf".
    assert_eq!(
        message(c.evaluate(-1e-7)),
        "t = -1e-7 is outside the domain [0, 1]"
    );
    assert_eq!(
        message(c.evaluate(1e23)),
        "t = 1e+23 is outside the domain [0, 1]"
    );
    assert!(message(c.evaluate(f64::NEG_INFINITY)).contains("t is -Infinity;"));
}

#[test]
fn counts_indices_and_degrees_must_be_whole_numbers() {
    // wasm-bindgen's usize would have made these 2, 4294967295, 0 and 0 without a word.
    let mut c = example();
    assert_eq!(
        message(JsBezierCurve::new(arr(&[0.0; 8]), 2.5, JsValue::UNDEFINED)),
        "dim must be a whole number from 0 to 4294967295, got 2.5"
    );
    assert_eq!(
        message(c.set_control_point(-1.0, arr(&[1.0, 1.0]))),
        "i must be a whole number from 0 to 4294967295, got -1"
    );
    assert!(message(c.sample_uniform(f64::NAN)).contains("count must be a whole number"));
    assert!(message(c.derivative(0.5, 1e10)).contains("got 10000000000"));
    assert!(message(c.sample_uniform_view(f64::INFINITY)).contains("got Infinity"));
    let pts = [0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 5.0, 1.0];
    assert!(message(splinelab::wasm::JsCompositeBezier::new(
        arr(&pts),
        2.0,
        arr(&[1.0, 1.5]),
        JsValue::UNDEFINED
    ))
    .contains("degrees 1 must be a whole number"));
    let knots = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
    let b =
        splinelab::wasm::JsBSplineCurve::new(arr(&pts), 2.0, 2.0, arr(&knots), JsValue::UNDEFINED)
            .unwrap();
    assert!(message(b.insert_knot(1.0, Some(0.5))).contains("times must be a whole number"));
    // Whole numbers pass, −0 included.
    assert_eq!(c.sample_uniform(-0.0).unwrap().len(), 0);
    assert_eq!(c.derivative(0.5, 1.0).unwrap().len(), 2);
}

#[test]
fn arrays_and_strings_of_the_wrong_type_are_named() {
    // Arrays and strings arrive as JsValues: null, undefined, a number or an object get a clear
    // Error naming the argument instead of a TypeError in the glue, a number read as an empty
    // array, or (a number passed as a string) a read out of bounds of the wasm memory.
    assert_eq!(
        message(JsBezierCurve::new(JsValue::NULL, 2.0, JsValue::UNDEFINED)),
        "points must be an array of numbers (Float64Array or number[]), got null"
    );
    let mut c = example();
    assert!(message(c.sample(JsValue::UNDEFINED)).ends_with("got undefined"));
    assert!(message(c.sample(JsValue::from(3))).ends_with("got number"));
    assert!(
        message(c.set_control_point(0.0, js_sys::Object::new().into())).ends_with("got object")
    );
    assert!(message(c.sample(JsValue::from("0.5"))).starts_with("ts must be an array"));
    // A plain array and other typed arrays are read as numbers.
    let plain: JsValue = js_sys::Array::of2(&JsValue::from(0.0), &JsValue::from(1.0)).into();
    assert_eq!(c.sample(plain).unwrap(), vec![0.0, 0.0, 8.0, 2.0]);
    let float32: JsValue = js_sys::Float32Array::from(&[0.5f32][..]).into();
    assert_eq!(c.sample(float32).unwrap(), vec![4.0, 2.5]);
    let pts = [0.0, 0.0, 1.0, 2.0, 3.0, 3.0];
    assert!(message(splinelab::wasm::JsBSplineCurve::new(
        arr(&pts),
        2.0,
        2.0,
        JsValue::from(4),
        JsValue::UNDEFINED
    ))
    .starts_with("knots must be an array of numbers"));
    // An optional array: null and undefined mean none, a number is refused.
    assert!(JsBezierCurve::new(arr(&pts), 2.0, JsValue::NULL).is_ok());
    assert!(
        message(JsBezierCurve::new(arr(&pts), 2.0, JsValue::from(1)))
            .starts_with("weights must be an array")
    );
    let kind = |value: JsValue| {
        message(splinelab::wasm::bspline::knot_vector(
            arr(&pts),
            2.0,
            2.0,
            value,
        ))
    };
    assert_eq!(kind(JsValue::NULL), "kind must be a string, got null");
    assert_eq!(
        kind(JsValue::UNDEFINED),
        "kind must be a string, got undefined"
    );
    assert_eq!(
        kind(JsValue::from(1.5)),
        "kind must be a string, got number"
    );
    assert_eq!(
        kind(js_sys::Object::new().into()),
        "kind must be a string, got object"
    );
    // parameterize's kind may also be a number: the exponent alpha in [0, 1].
    assert!(message(splinelab::wasm::bspline::parameterize(
        arr(&pts),
        2.0,
        JsValue::from(7)
    ))
    .contains("alpha = 7 is outside [0, 1]"));
    // An optional string: undefined takes the default, a number is refused.
    let joined = wasm::bezier::join_bezier(
        &example(),
        &example(),
        JsValue::from("C1"),
        JsValue::UNDEFINED,
    );
    assert!(joined.is_ok());
    assert!(message(wasm::bezier::join_bezier(
        &example(),
        &example(),
        JsValue::from("C1"),
        JsValue::from(2)
    ))
    .contains("adjust must be a string, got number"));
    // The curve is unharmed.
    assert_eq!(c.sample(arr(&[1.0])).unwrap(), vec![8.0, 2.0]);
}

#[test]
fn method_errors_are_thrown_not_trapped() {
    let mut c = example();
    assert_eq!(
        message(c.evaluate(1.5)),
        "t = 1.5 is outside the domain [0, 1]"
    );
    assert!(message(c.derivative(f64::INFINITY, 1.0)).contains("t is Infinity"));
    assert!(message(c.set_control_point(7.0, arr(&[1.0, 1.0]))).contains("index 7 is out of range"));
    assert_eq!(
        message(c.set_control_point(0.0, arr(&[1.0, 1.0, 1.0]))),
        "a point needs 2 coordinates, got 3"
    );
    assert!(message(c.set_weight(0.0, 0.0)).contains("weight 0 is 0"));
    assert!(message(c.sample(arr(&[0.0, 2.0]))).contains("t = 2"));
    assert!(message(c.sample_uniform(f64::from(u32::MAX))).contains("too large"));
    assert!(message(c.flatten(-1.0)).contains("tolerance -1"));
    assert!(message(c.split(-0.5)).contains("t = -0.5"));
    assert!(message(wasm::bezier::bernstein(3.0, 4.0, 0.5)).contains("index 4"));
    assert!(message(wasm::bezier::bernstein(3.0, 1.0, 1.5)).contains("t = 1.5"));
    let c3 = JsBezierCurve::new(arr(&[0.0; 6]), 3.0, JsValue::UNDEFINED).unwrap();
    assert!(message(c3.intersect_line(0.0, 0.0, 1.0, 0.0, 1e-9)).contains("2D curves"));
    assert!(message(wasm::bezier::join_bezier(
        &example(),
        &c3,
        JsValue::from("C1"),
        JsValue::UNDEFINED
    ))
    .contains("same dim"));
    assert!(message(wasm::bezier::join_bezier(
        &example(),
        &example(),
        JsValue::from("C9"),
        JsValue::UNDEFINED
    ))
    .contains("\"C9\""));
    // After all that the curve still works.
    assert_eq!(c.evaluate(0.25).unwrap(), vec![29.0 / 16.0, 23.0 / 16.0]);
}

#[test]
fn flat_layouts() {
    let c = example();
    assert_eq!(c.de_casteljau(0.25).unwrap().len(), 10 * 2);
    assert_eq!(c.de_casteljau_homogeneous(0.25).unwrap().len(), 10 * 3);
    assert_eq!(c.sample_uniform(5.0).unwrap().len(), 10);
    assert_eq!(c.domain(), vec![0.0, 1.0]);
    assert_eq!(c.weights(), vec![1.0; 4]);
    assert_eq!(c.bounding_box().len(), 4);
    let boxes = c.intersect_line_boxes(0.0, 1.0, 8.0, 1.0, 1e-6).unwrap();
    assert_eq!(boxes.len() % 6, 0);
    assert_eq!(boxes[0], 0.0, "the first box is the whole curve at depth 0");
    let halves = c.split(0.5).unwrap();
    assert_eq!(halves.len(), 2);
    assert_eq!(
        halves[0].control_points()[6..],
        halves[1].control_points()[..2]
    );
    let basis = wasm::bezier::bernstein_basis(3.0, 5.0).unwrap();
    assert_eq!(basis.len(), 4 * 5);
    assert_eq!((basis[0], basis[4], basis[19]), (1.0, 0.0, 1.0));
}

#[test]
fn composite_checks_its_layout() {
    use splinelab::wasm::JsCompositeBezier;
    let pts = [0.0, 0.0, 1.0, 1.0, 2.0, 0.0, 2.0, 0.0, 3.0, -1.0, 4.0, 0.0];
    let c = JsCompositeBezier::new(arr(&pts), 2.0, arr(&[2.0, 2.0]), JsValue::UNDEFINED).unwrap();
    assert_eq!(c.domain(), vec![0.0, 2.0]);
    assert_eq!(c.evaluate(2.0).unwrap(), vec![4.0, 0.0]);
    assert!(message(JsCompositeBezier::new(
        arr(&pts),
        2.0,
        arr(&[2.0, 3.0]),
        JsValue::UNDEFINED
    ))
    .contains("need 7 control points"));
    assert!(message(JsCompositeBezier::new(
        arr(&pts),
        2.0,
        arr(&[2.0, 2.0]),
        arr(&[0.0, 1.0])
    ))
    .contains("3 breakpoints"));
    assert!(message(JsCompositeBezier::new(
        arr(&pts),
        2.0,
        arr(&[0.0, 5.0]),
        JsValue::UNDEFINED
    ))
    .contains("degree >= 1"));
    assert!(message(c.piece(2.0)).contains("index 2"));
}

#[test]
fn bspline_boundary() {
    use splinelab::wasm::{bspline as b, JsBSplineCurve};
    let pts = [0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 5.0, 1.0, 6.0, 3.0, 8.0, 0.0];
    let knots = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0];
    let c = JsBSplineCurve::new(arr(&pts), 2.0, 2.0, arr(&knots), JsValue::UNDEFINED).unwrap();
    assert_eq!(c.domain(), vec![0.0, 4.0]);
    assert_eq!(c.de_boor(1.5).unwrap().len(), 6 * 2);
    assert_eq!(c.basis(1.5).unwrap().len(), 6);
    assert_eq!(c.span(1.5).unwrap(), 3);
    assert_eq!(c.span(4.0).unwrap(), 5);
    assert_eq!(c.basis_non_zero(2.5).unwrap(), vec![0.125, 0.75, 0.125]);
    assert!(message(c.span(f64::NAN)).contains("NaN"));
    assert!(message(c.basis_non_zero(-1.0)).contains("-1"));
    assert_eq!(c.to_bezier().unwrap().len(), 4);
    assert_eq!(c.insert_knot(1.5, None).unwrap().knots().len(), 10);
    assert_eq!(
        c.segment_matrix(3.0, None).unwrap(),
        vec![0.5, -1.0, 0.5, -1.0, 1.0, 0.0, 0.5, 0.5, 0.0]
    );
    assert_eq!(
        message(JsBSplineCurve::new(
            arr(&pts),
            4.0,
            2.0,
            arr(&knots),
            JsValue::UNDEFINED
        )),
        "dim must be 2 or 3, got 4"
    );
    assert!(message(JsBSplineCurve::new(
        arr(&pts),
        2.0,
        2.0,
        arr(&knots[..8]),
        JsValue::UNDEFINED
    ))
    .contains("n+p+2"));
    assert!(message(JsBSplineCurve::new(
        arr(&pts),
        2.0,
        0.0,
        arr(&knots),
        JsValue::UNDEFINED
    ))
    .contains("degree must be at least 1"));
    assert!(message(JsBSplineCurve::new(
        arr(&pts),
        2.0,
        6.0,
        arr(&knots),
        JsValue::UNDEFINED
    ))
    .contains("degree 6 needs at least"));
    assert!(message(c.evaluate(-1.0)).contains("u = -1 is outside the domain [0, 4]"));
    assert!(message(c.insert_knot(0.0, Some(1.0))).contains("multiplicity 4"));
    assert!(message(c.segment_matrix(0.0, None)).contains("span 0"));
    assert!(
        message(b::knot_vector(arr(&pts), 2.0, 2.0, JsValue::from("open"))).contains("\"open\"")
    );
    assert!(message(b::parameterize(
        arr(&[0.0, 0.0, 0.0, 0.0]),
        2.0,
        JsValue::from("chord")
    ))
    .contains("coincide"));
    assert!(message(b::phantom_points(arr(&pts), 2.0, 2.0)).contains("even"));
    assert!(message(b::uniform_segment_matrix(0.0)).contains("degree must be"));
    assert_eq!(
        b::knot_vector(arr(&pts), 2.0, 2.0, JsValue::from("clamped")).unwrap(),
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0]
    );
}

#[test]
fn rational_constructors_and_projective_maps() {
    use splinelab::wasm::rational as r;
    let c = r::circle(1.0, 2.0, 3.0).unwrap();
    let p = c.evaluate(0.3).unwrap();
    assert!(((p[0] - 1.0).hypot(p[1] - 2.0) - 3.0).abs() < 1e-12);
    assert_eq!(c.weights().len(), 9);
    assert!(message(r::circle(0.0, 0.0, -1.0)).contains("r must be > 0, got -1"));
    assert!(message(r::circular_arc(0.0, 0.0, 1.0, 0.0, 0.0)).contains("sweep"));
    assert!(message(r::ellipse(0.0, 0.0, 1.0, f64::NAN, None)).contains("ry is NaN"));
    assert!(message(r::ellipse_arc(
        arr(&[0.0, 0.0]),
        arr(&[1.0, 0.0, 0.0]),
        arr(&[0.0, 1.0]),
        0.0,
        1.0
    ))
    .contains("same length"));
    assert_eq!(
        r::ellipse_arc(
            arr(&[0.0; 3]),
            arr(&[1.0, 0.0, 0.0]),
            arr(&[0.0, 0.0, 1.0]),
            0.0,
            1.0
        )
        .unwrap()
        .dim(),
        3
    );
    assert!(
        message(r::circular_arc_bezier(arr(&[0.0, 0.0, 1.0, 1.0, 3.0, 0.0]))).contains("isosceles")
    );
    assert!(
        message(r::circular_arc_bezier(arr(&[0.0, 0.0, 1.0, 1.0]))).contains("3 control points")
    );
    assert_eq!(r::conic_kind(1.0, 2.0, 1.0).unwrap(), "hyperbola");
    assert!(message(r::conic_kind(1.0, -2.0, 1.0)).contains("weight 1 is -2"));
    let bez = JsBezierCurve::new(
        arr(&[0.0, 0.0, 1.0, 1.0, 2.0, 0.0]),
        2.0,
        JsValue::UNDEFINED,
    )
    .unwrap();
    assert!(message(bez.projective_map(arr(&[1.0; 8]))).contains("9 numbers"));
    assert!(
        message(bez.projective_map(arr(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0])))
            .contains("singular")
    );
    let shifted = bez
        .projective_map(arr(&[1.0, 0.0, 5.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]))
        .unwrap();
    assert_eq!(
        shifted.evaluate(0.5).unwrap(),
        vec![6.0, 0.5],
        "row-major: translation in the last column"
    );
    assert!(
        message(c.projective_map(arr(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.5])))
            .contains("weights must stay > 0")
    );
}

#[test]
fn sample_views_see_the_same_numbers_without_a_copy() {
    use splinelab::wasm::JsBSplineCurve;
    let mut bezier = example();
    let copy = bezier.sample_uniform(9.0).unwrap();
    let view = bezier.sample_uniform_view(9.0).unwrap();
    assert_eq!(view.to_vec(), copy);
    // The view is the curve's buffer in the wasm memory, not a copy of it.
    let memory = wasm_bindgen::memory().unchecked_into::<js_sys::WebAssembly::Memory>();
    assert_eq!(JsValue::from(view.buffer()), memory.buffer());
    // Bernstein form at t = 1/2 of (0,0) (2,2) (6,4) (8,2): (0 + 3·2 + 3·6 + 8)/8, (0 + 6 + 12 + 2)/8.
    assert_eq!(
        bezier.sample_view(arr(&[0.5])).unwrap().to_vec(),
        vec![4.0, 2.5]
    );
    assert!(message(bezier.sample_view(arr(&[1.5]))).contains("1.5"));
    assert!(message(bezier.sample_uniform_view(f64::from(u32::MAX))).contains("count"));
    // A failed call leaves the curve usable.
    assert_eq!(
        bezier.sample_uniform_view(2.0).unwrap().to_vec(),
        vec![0.0, 0.0, 8.0, 2.0]
    );

    let pts = [0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 5.0, 1.0, 6.0, 3.0, 8.0, 0.0];
    let knots = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0];
    let mut c = JsBSplineCurve::new(arr(&pts), 2.0, 2.0, arr(&knots), JsValue::UNDEFINED).unwrap();
    let us: Vec<f64> = (0..=40).map(|k| k as f64 / 10.0).collect();
    assert_eq!(
        c.sample_view(arr(&us)).unwrap().to_vec(),
        c.sample(arr(&us)).unwrap()
    );
    assert_eq!(
        c.sample_uniform_view(41.0).unwrap().to_vec(),
        c.sample_uniform(41.0).unwrap()
    );
    assert!(message(c.sample_view(arr(&[5.0]))).contains("outside the domain [0, 4]"));
}

/// A bilinear patch over the unit square with z = x·y (degree 1 × 1: S(u, v) = (u, v, uv)).
const BILINEAR: [f64; 12] = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0];

/// [`BILINEAR`] as a degree-1 × 1 `BSplineSurface` on knots 0 0 1 1 both ways.
fn bilinear_bspline() -> splinelab::wasm::JsBSplineSurface {
    let knots = || arr(&[0.0, 0.0, 1.0, 1.0]);
    splinelab::wasm::JsBSplineSurface::new(
        arr(&BILINEAR),
        2.0,
        2.0,
        1.0,
        1.0,
        knots(),
        knots(),
        JsValue::UNDEFINED,
    )
    .unwrap()
}

#[test]
fn bspline_surface_from_js() {
    use splinelab::wasm::JsBSplineSurface;
    let points = BILINEAR;
    let knots = || arr(&[0.0, 0.0, 1.0, 1.0]);
    let mut s = bilinear_bspline();
    assert_eq!(
        (s.rows(), s.cols(), s.degree_u(), s.degree_v(), s.rational()),
        (2, 2, 1, 1, false)
    );
    assert_eq!(s.domain_v(), vec![0.0, 1.0]);
    assert_eq!(s.control_points(), points.to_vec());
    assert_eq!(s.evaluate(0.5, 0.25).unwrap(), vec![0.5, 0.25, 0.125]);
    assert_eq!(
        s.derivative(0.5, 0.25, 1.0, 1.0).unwrap(),
        vec![0.0, 0.0, 1.0]
    );
    let grid = s
        .sample_grid(arr(&[0.0, 0.5]), arr(&[0.25, 1.0, 0.5]))
        .unwrap();
    assert_eq!(grid.len(), 2 * 3 * 3);
    assert_eq!(grid[3 * 3..3 * 4].to_vec(), vec![0.5, 0.25, 0.125]);
    let view = s
        .sample_grid_view(arr(&[0.0, 0.5]), arr(&[0.25, 1.0, 0.5]))
        .unwrap();
    assert_eq!(view.to_vec(), grid);
    // Arguments are checked like every other call's.
    assert!(message(s.derivative(0.5, 0.5, 1.5, 0.0)).contains("du must be a whole number"));
    assert!(message(s.evaluate(0.5, -1.0)).contains("v = -1"));
    assert!(message(s.sample_grid(JsValue::NULL, arr(&[0.5])))
        .contains("us must be an array of numbers"));
    assert!(message(JsBSplineSurface::new(
        arr(&points),
        2.0,
        2.5,
        1.0,
        1.0,
        knots(),
        knots(),
        JsValue::UNDEFINED
    ))
    .contains("cols must be a whole number"));
    assert!(message(JsBSplineSurface::new(
        arr(&points),
        2.0,
        2.0,
        1.0,
        1.0,
        knots(),
        arr(&[0.0, 1.0]),
        JsValue::UNDEFINED
    ))
    .starts_with("knotsV: "));
}

#[test]
fn bezier_surfaces_and_meshes_from_js() {
    use splinelab::wasm::JsBezierSurface;
    let points = BILINEAR;
    let patch = JsBezierSurface::new(arr(&points), 2.0, 2.0, JsValue::UNDEFINED).unwrap();
    assert_eq!((patch.degree_u(), patch.degree_v()), (1, 1));
    assert_eq!(patch.evaluate(0.5, 0.25).unwrap(), vec![0.5, 0.25, 0.125]);
    let pieces = patch.split(0.5, 0.5).unwrap();
    assert_eq!(pieces.len(), 4);
    assert_eq!(pieces[3].evaluate(0.0, 0.0).unwrap(), vec![0.5, 0.5, 0.25]);
    let mesh = patch.tessellate(2.0, 3.0).unwrap();
    let get = |key: &str| js_sys::Reflect::get(&mesh, &key.into()).unwrap();
    let positions = get("positions").dyn_into::<js_sys::Float32Array>().unwrap();
    let normals = get("normals").dyn_into::<js_sys::Float32Array>().unwrap();
    let indices = get("indices").dyn_into::<js_sys::Uint32Array>().unwrap();
    assert_eq!(
        (positions.length(), normals.length(), indices.length()),
        (36, 36, 36)
    );
    assert_eq!(indices.to_vec()[..6], [0, 4, 5, 0, 5, 1]);
    assert!(message(patch.tessellate(2.0, f64::NAN)).contains("nv must be a whole number"));
    assert!(message(JsBezierSurface::new(
        arr(&points),
        1.0,
        4.0,
        JsValue::UNDEFINED
    ))
    .contains("at least 2 rows"));

    let s = bilinear_bspline();
    let refined = s
        .insert_knot_u(0.5, None)
        .unwrap()
        .insert_knot_v(0.25, Some(1.0))
        .unwrap();
    assert_eq!((refined.rows(), refined.cols()), (3, 3));
    assert_eq!(refined.knots_v(), vec![0.0, 0.0, 0.25, 1.0, 1.0]);
    assert_eq!(refined.evaluate(0.5, 0.25).unwrap(), vec![0.5, 0.25, 0.125]);
    assert!(message(s.insert_knot_u(0.5, Some(3.0))).contains("multiplicity 3"));
}

#[test]
fn teaching_data_wrappers_return_the_documented_layouts() {
    // The Croatian quadratic: U = [0,0,0,1,2,3,4,4,4]; at u = 3/2 (span 3) by hand:
    // de Boor α: r = 1: (u − u_2)/(u_4 − u_2) = 3/4, (u − u_3)/(u_5 − u_3) = 1/4; r = 2: 1/2.
    let pts = [0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 5.0, 1.0, 6.0, 3.0, 8.0, 0.0];
    let knots = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0];
    let c =
        splinelab::wasm::JsBSplineCurve::new(arr(&pts), 2.0, 2.0, arr(&knots), JsValue::UNDEFINED)
            .unwrap();
    assert_eq!(
        c.de_boor_alphas(1.5).unwrap(),
        vec![
            1.0, 1.0, 2.0, 4.0, 2.0, 0.75, //
            1.0, 2.0, 3.0, 5.0, 2.0, 0.25, //
            2.0, 2.0, 3.0, 4.0, 1.0, 0.5,
        ]
    );
    assert!(message(c.de_boor_alphas(5.0)).contains("outside the domain"));
    // Boehm at s = 3/2: span 3, α_2 = 3/4, α_3 = 1/4.
    let boehm = c.insertion_alphas(1.5).unwrap();
    let get = |o: &JsValue, key: &str| js_sys::Reflect::get(o, &key.into()).unwrap();
    assert_eq!(get(&boehm, "span").as_f64(), Some(3.0));
    let alphas: Vec<f64> = js_sys::Array::from(&get(&boehm, "alphas"))
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(alphas, vec![0.75, 0.25]);
    // Matrix form of span 3 at t = 1/2: [1/4 1/2 1], [1/8 3/4 1/8], the point (3, 21/8).
    assert_eq!(
        c.evaluate_matrix_form(3.0, 0.5).unwrap(),
        vec![0.25, 0.5, 1.0, 0.125, 0.75, 0.125, 3.0, 2.625]
    );
    assert!(message(c.evaluate_matrix_form(3.0, 2.0)).contains("outside the domain [0, 1]"));
    assert!(message(c.evaluate_matrix_form(-1.0, 0.5)).contains("whole number"));
    // Rational basis of weights 1, 3, 1, 1 at t = 1/2: 1/14, 9/14, 3/14, 1/14 (within rounding).
    let w = JsBezierCurve::new(
        arr(&[0.0, 0.0, 1.0, 3.0, 4.0, 3.0, 5.0, 0.0]),
        2.0,
        arr(&[1.0, 3.0, 1.0, 1.0]),
    )
    .unwrap();
    let r = w.rational_basis(0.5).unwrap();
    for (got, want) in r.iter().zip([1.0, 9.0, 3.0, 1.0]) {
        assert!((got - want / 14.0).abs() < 1e-15);
    }
    assert!(message(w.rational_basis(f64::NAN)).contains("finite"));
    // rationalPoles with w₁ = −1: one double zero at t = 1/2, direction (0, −1).
    let poles = splinelab::wasm::rational::rational_poles(
        arr(&[0.0, 0.0, 2.0, 3.0, 4.0, 0.0]),
        2.0,
        arr(&[1.0, -1.0, 1.0]),
        3.0,
    )
    .unwrap();
    let typed = |key: &str| js_sys::Float64Array::from(get(&poles, key)).to_vec();
    assert_eq!(typed("roots"), vec![0.5]);
    assert_eq!(typed("directions"), vec![0.0, -1.0]);
    assert_eq!(typed("samples").len(), 9);
    assert!(message(splinelab::wasm::rational::rational_poles(
        arr(&[0.0, 0.0, 2.0, 3.0, 4.0, 0.0]),
        2.0,
        arr(&[0.0, 0.0, 0.0]),
        3.0,
    ))
    .contains("all 3 weights are 0"));
    assert!(message(splinelab::wasm::rational::rational_poles(
        arr(&[0.0, 0.0, 2.0, 3.0, 4.0, 0.0]),
        2.0,
        JsValue::NULL,
        3.0,
    ))
    .contains("weights"));
}
