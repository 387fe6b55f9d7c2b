//! The JavaScript layouts of the surfaces' meshes, Bézier patches, seams and line hits, in
//! Node: `{ positions, normals, uvs, indices }` with matching lengths (uvs evaluate to the
//! positions), `toBezierPatches` as BezierSurfaces, `seams` as flat `[knot, c, …]`,
//! `intersectLine` as flat `[u, v, s, …]`, and thrown errors naming the bad value.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::js_message as message;
use splinelab::wasm::{JsBSplineSurface, JsBezierSurface};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test as test;

fn arr(values: &[f64]) -> JsValue {
    js_sys::Float64Array::from(values).into()
}

/// A bicubic × biquadratic B-spline, 5 × 4 net, knots 0.5 (u) and 2 (v) inside, a bump in
/// the middle, rational.
fn surface() -> JsBSplineSurface {
    let mut points = Vec::new();
    for i in 0..5 {
        for j in 0..4 {
            let z = if (i, j) == (2, 1) || (i, j) == (2, 2) {
                1.0
            } else {
                0.0
            };
            points.extend_from_slice(&[i as f64 * 0.25, 1.0 + j as f64, z]);
        }
    }
    let weights: Vec<f64> = (0..20).map(|k| 1.0 + 0.05 * k as f64).collect();
    JsBSplineSurface::new(
        arr(&points),
        5.0,
        4.0,
        3.0,
        2.0,
        arr(&[0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]),
        arr(&[1.0, 1.0, 1.0, 2.0, 3.0, 3.0, 3.0]),
        arr(&weights),
    )
    .unwrap()
}

/// A typed-array field of a mesh object, as f64.
fn field(object: &JsValue, name: &str) -> Vec<f64> {
    let value = js_sys::Reflect::get(object, &JsValue::from_str(name)).unwrap();
    js_sys::Array::from(&value)
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect()
}

/// The mesh's arrays have one entry per vertex each, and every uv evaluates to its position.
fn check_mesh(s: &JsBSplineSurface, mesh: &JsValue) -> usize {
    for (key, kind) in [
        ("positions", "Float32Array"),
        ("normals", "Float32Array"),
        ("uvs", "Float32Array"),
        ("indices", "Uint32Array"),
    ] {
        let value = js_sys::Reflect::get(mesh, &JsValue::from_str(key)).unwrap();
        let name = value
            .dyn_ref::<js_sys::Object>()
            .unwrap()
            .constructor()
            .name();
        assert_eq!(String::from(name), kind, "{key}");
    }
    let (positions, normals, uvs) = (
        field(mesh, "positions"),
        field(mesh, "normals"),
        field(mesh, "uvs"),
    );
    let n = positions.len() / 3;
    assert_eq!((normals.len(), uvs.len()), (3 * n, 2 * n));
    assert!(field(mesh, "indices").iter().all(|&k| (k as usize) < n));
    for k in 0..n {
        let p = s.evaluate(uvs[2 * k], uvs[2 * k + 1]).unwrap();
        for c in 0..3 {
            assert!((p[c] - positions[3 * k + c]).abs() < 1e-5, "vertex {k}");
        }
    }
    field(mesh, "indices").len() / 3
}

#[test]
fn meshes_carry_uvs() {
    let s = surface();
    let uniform = s.tessellate(4.0, 3.0).unwrap();
    assert_eq!(check_mesh(&s, &uniform), 24);
    let uvs = field(&uniform, "uvs");
    assert_eq!(uvs[..4], [0.0, 1.0, 0.0, f64::from((5.0f64 / 3.0) as f32)]);
    let coarse = check_mesh(&s, &s.tessellate_adaptive(0.05).unwrap());
    let fine = check_mesh(&s, &s.tessellate_adaptive(0.002).unwrap());
    assert!(coarse >= 2 * 4 && fine > coarse, "{coarse} {fine}");
    assert_eq!(
        message(s.tessellate_adaptive(0.0)),
        "tolerance 0 is not usable: it must be a finite number > 0"
    );
    assert!(message(s.tessellate_adaptive(f64::NAN)).contains("tolerance NaN"));
}

#[test]
fn bezier_patches_seams_and_line_hits() {
    let s = surface();
    let patches: Vec<JsBezierSurface> = s.to_bezier_patches().unwrap();
    assert_eq!(patches.len(), 4);
    // Patch 1 is u ∈ [0, 0.5] × v ∈ [2, 3]; its corner (1, 0) is S(0.5, 2).
    assert_eq!((patches[1].degree_u(), patches[1].degree_v()), (3, 2));
    assert!(patches[1].rational());
    let (a, b) = (
        patches[1].evaluate(1.0, 0.0).unwrap(),
        s.evaluate(0.5, 2.0).unwrap(),
    );
    for c in 0..3 {
        assert!((a[c] - b[c]).abs() < 1e-12);
    }
    let seams = s.seams().unwrap();
    assert_eq!(field(&seams, "u"), vec![0.5, 2.0]);
    assert_eq!(field(&seams, "v"), vec![2.0, 1.0]);
    let seams = patches[0].seams().unwrap();
    assert!(field(&seams, "u").is_empty() && field(&seams, "v").is_empty());

    // A vertical line through S(0.3, 1.7): a hit there, as [u, v, s].
    let p = s.evaluate(0.3, 1.7).unwrap();
    let hits = s
        .intersect_line(arr(&[p[0], p[1], -4.0]), arr(&[0.0, 0.0, 2.0]), 1e-9)
        .unwrap();
    assert_eq!(hits.len(), 3, "{hits:?}");
    assert!(
        (hits[0] - 0.3).abs() < 1e-7 && (hits[1] - 1.7).abs() < 1e-7,
        "{hits:?}"
    );
    assert!((hits[2] - (p[2] + 4.0) / 2.0).abs() < 1e-7, "{hits:?}");
    assert!(s
        .intersect_line(arr(&[9.0, 9.0, 9.0]), arr(&[1.0, 0.0, 0.0]), 1e-6)
        .unwrap()
        .is_empty());
    assert_eq!(
        message(s.intersect_line(arr(&[0.0; 3]), arr(&[0.0; 3]), 1e-6)),
        "direction: its length must be > 0, got 0"
    );
    assert!(
        message(s.intersect_line(arr(&[0.0; 2]), arr(&[0.0, 0.0, 1.0]), 1e-6))
            .starts_with("origin: ")
    );
    assert!(
        message(s.intersect_line(JsValue::NULL, arr(&[0.0, 0.0, 1.0]), 1e-6))
            .contains("origin must be an array of numbers")
    );
}
