//! The surface methods of issue 14 that teach and measure: iso-curves, curvature (both
//! classes), and on `BezierSurface` de Casteljau's construction and the matrix form.

use super::bezier::{flatten_points, JsBezierCurve};
use super::bspline::JsBSplineCurve;
use super::surface::{JsBSplineSurface, JsBezierSurface};
use super::{numbers, object_of, string_arg};
use crate::bezier::BezierCurve;
use crate::error::Error;
use crate::prelude::*;
use crate::surface::BSplineSurface;
use crate::wasm::ApiError;
use wasm_bindgen::prelude::*;

/// `S.curvature(u, v)` and `S.curvatures(uvs)` on the core surface.
fn curvature(surface: &BSplineSurface, u: f64, v: f64) -> Result<Vec<f64>, ApiError> {
    Ok(surface.curvature(u, v)?.to_vec())
}

/// `S.curvatures(uvs)`: `[K0, H0, K1, H1, …]`.
fn curvatures(surface: &BSplineSurface, uvs: &JsValue) -> Result<Vec<f64>, ApiError> {
    let uvs = numbers("uvs", uvs)?;
    let mut out = Vec::new();
    surface.curvatures_into(&uvs, &mut out)?;
    Ok(out)
}

/// The methods both surface classes gain; `$curve` wraps an iso-curve for JavaScript.
macro_rules! surface_teaching_methods {
    ($class:ident, $js:ident, $curve:ident => $wrap:expr, $curve_ty:ty) => {
        #[wasm_bindgen(js_class = $js)]
        impl $class {
            /// The curve at constant u, running in v (3D, rational when the surface is): the
            /// columns of the net blended by the u basis at u.
            #[wasm_bindgen(js_name = isoCurveU)]
            pub fn iso_curve_u(&self, u: f64) -> Result<$curve_ty, ApiError> {
                let $curve = self.inner.iso_curve_u(u)?;
                Ok($wrap)
            }

            /// The curve at constant v, running in u (3D, rational when the surface is).
            #[wasm_bindgen(js_name = isoCurveV)]
            pub fn iso_curve_v(&self, v: f64) -> Result<$curve_ty, ApiError> {
                let $curve = self.inner.iso_curve_v(v)?;
                Ok($wrap)
            }

            /// `[K, H]` at (u, v): Gaussian and mean curvature from the exact first and second
            /// derivatives, H signed with the normal S_u × S_v normalised (H > 0 where the
            /// surface bends towards it). Throws naming (u, v) where there is no normal (a pole,
            /// a collapsed edge, a fold).
            pub fn curvature(&self, u: f64, v: f64) -> Result<Vec<f64>, ApiError> {
                curvature(&self.inner, u, v)
            }

            /// `[K0, H0, K1, H1, …]` (Float64Array) for the flat (u, v) pairs of `uvs` (a mesh's
            /// Float32Array uvs are accepted: values within single-precision rounding of the
            /// domain are clamped into it). Where there is no normal both numbers are NaN.
            pub fn curvatures(
                &self,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")]
                uvs: JsValue,
            ) -> Result<Vec<f64>, ApiError> {
                curvatures(&self.inner, &uvs)
            }
        }
    };
}

surface_teaching_methods!(JsBSplineSurface, BSplineSurface, c => JsBSplineCurve::from_3d(c), JsBSplineCurve);
surface_teaching_methods!(
    JsBezierSurface,
    BezierSurface,
    c => JsBezierCurve::from_3d(BezierCurve::from_homogeneous(c.homogeneous_points().to_vec())?),
    JsBezierCurve
);

#[wasm_bindgen(js_class = BezierSurface)]
impl JsBezierSurface {
    /// De Casteljau's construction at (u, v), flat xyz (rational patches: projected points).
    /// `order = "rows"` (default) → `{ rows, column }`: each row i of the net (0..m) with its
    /// triangle in v ((n+1)(n+2)/2 points, levels concatenated as the curves' `deCasteljau`),
    /// rows concatenated, then the triangle in u over the m+1 row results. `order = "columns"`
    /// → `{ columns, row }`: each column's triangle in u, then the row's in v. Both end at
    /// `evaluate(u, v)`.
    #[wasm_bindgen(
        js_name = deCasteljau,
        unchecked_return_type = "{ rows: Float64Array; column: Float64Array } | { columns: Float64Array; row: Float64Array }"
    )]
    pub fn de_casteljau(
        &self,
        u: f64,
        v: f64,
        #[wasm_bindgen(unchecked_optional_param_type = "\"rows\" | \"columns\"")] order: JsValue,
    ) -> Result<JsValue, ApiError> {
        let order = string_arg("order", &order, Some("rows"))?;
        let columns_first = match order.as_str() {
            "rows" => false,
            "columns" => true,
            other => {
                return Err(Error::UnknownOption {
                    name: "order",
                    value: other.into(),
                    expected: "\"rows\", \"columns\"",
                }
                .into())
            }
        };
        let d = self.inner.de_casteljau_patch(u, v, columns_first)?;
        let (first, second) = (flatten_points(&d.first), flatten_points(&d.second));
        if columns_first {
            object_of(&[("columns", &first), ("row", &second)])
        } else {
            object_of(&[("rows", &first), ("column", &second)])
        }
    }

    /// The matrix form `S(u, v) = [u^m … u 1] · A · [v^n … v 1]ᵀ` of a polynomial patch:
    /// `{ basisU, basisV, coefficients }` with `basisU` = M_m ((m+1)² numbers, row-major, row r
    /// holding the coefficients of u^(m−r) in B_0..B_m; the cubic's is [−1 3 −3 1; 3 −6 3 0;
    /// −3 3 0 0; 1 0 0 0]), `basisV` = M_n, and `coefficients` = A = M_m P M_nᵀ, flat
    /// (m+1)(n+1)·3 (xyz per entry, row-major). Throws for a rational patch.
    #[wasm_bindgen(
        js_name = matrixForm,
        unchecked_return_type = "{ basisU: Float64Array; basisV: Float64Array; coefficients: Float64Array }"
    )]
    pub fn matrix_form(&self) -> Result<JsValue, ApiError> {
        let form = self.inner.matrix_form()?;
        object_of(&[
            ("basisU", &form.basis_u),
            ("basisV", &form.basis_v),
            ("coefficients", &flatten_points(&form.coefficients)),
        ])
    }
}
