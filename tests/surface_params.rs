//! `grid_params`: the parameters `interpolate_surface` gives its grid, against hand-computed
//! values, and the surface through every point at them.

use splinelab::bspline::Parameterization;
use splinelab::surface::{grid_params, interpolate_surface};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// A 3 × 3 grid with rows along x at 0, 1, 3 and columns along y at 0, 2, 6 (heights 0).
fn grid() -> Vec<f64> {
    let xs = [0.0, 1.0, 3.0];
    let ys = [0.0, 2.0, 6.0];
    xs.iter()
        .flat_map(|&x| ys.iter().flat_map(move |&y| [x, y, 0.0]))
        .collect()
}

#[test]
fn grid_params_by_hand() {
    let points = grid();
    // Every column has steps 1, 2 (total 3): chord → 0, 1/3, 1; rows steps 2, 4 → 0, 1/3, 1.
    let (u, v) = grid_params(&points, 3, 3, Parameterization::Chord).unwrap();
    for (got, want) in u.iter().zip([0.0, 1.0 / 3.0, 1.0]) {
        assert!((got - want).abs() < 1e-15, "u {u:?}");
    }
    for (got, want) in v.iter().zip([0.0, 1.0 / 3.0, 1.0]) {
        assert!((got - want).abs() < 1e-15, "v {v:?}");
    }
    // Centripetal: steps 1, √2 → 0, 1/(1 + √2), 1; rows √2, 2 → 0, √2/(√2 + 2), 1.
    let (u, v) = grid_params(&points, 3, 3, Parameterization::Centripetal).unwrap();
    let r2 = 2f64.sqrt();
    assert!((u[1] - 1.0 / (1.0 + r2)).abs() < 1e-15, "u {u:?}");
    assert!((v[1] - r2 / (r2 + 2.0)).abs() < 1e-15, "v {v:?}");
    // Uniform: k / (n − 1) whatever the spacing.
    let (u, v) = grid_params(&points, 3, 3, Parameterization::Uniform).unwrap();
    assert_eq!(u, vec![0.0, 0.5, 1.0]);
    assert_eq!(v, vec![0.0, 0.5, 1.0]);
}

#[test]
fn grid_params_are_where_the_interpolant_meets_the_grid() {
    // A bumpy 4 × 5 grid, columns unevenly spaced and different per row.
    let mut points = Vec::new();
    for i in 0..4 {
        for j in 0..5 {
            let (x, y) = (i as f64 * 1.5 + 0.2 * j as f64, (j * j) as f64 * 0.7);
            points.extend([x, y, ((i * 7 + j * 3) % 5) as f64 * 0.4]);
        }
    }
    let kind = Parameterization::Centripetal;
    let (u, v) = grid_params(&points, 4, 5, kind).unwrap();
    let s = interpolate_surface(&points, 4, 5, 3, 2, kind).unwrap();
    for (i, &ui) in u.iter().enumerate() {
        for (j, &vj) in v.iter().enumerate() {
            let p = s.evaluate(ui, vj).unwrap();
            let q = &points[3 * (i * 5 + j)..3 * (i * 5 + j) + 3];
            assert!(
                (p.x - q[0]).abs() + (p.y - q[1]).abs() + (p.z - q[2]).abs() < 1e-9,
                "({i}, {j}): {p:?} against {q:?}"
            );
        }
    }
}

#[test]
fn grid_params_refuse_a_size_mismatch() {
    let err = grid_params(&grid()[..24], 3, 3, Parameterization::Chord).unwrap_err();
    assert!(err.to_string().contains('3'), "{err}");
}
