//! The surfaces' adaptive meshes, Bézier extraction, seams and line intersection for
//! JavaScript: a second `impl` block per class (the first is in `surface.rs`).

use super::bezier::point_from;
use super::numbers;
use super::surface::{mesh_to_js, JsBSplineSurface, JsBezierSurface};
use crate::error::Error;
use crate::wasm::ApiError;
use glam::DVec3;
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

/// A 3D point argument (3 numbers), the error naming it.
fn point_arg(name: &'static str, value: &JsValue) -> Result<DVec3, ApiError> {
    let coords = numbers(name, value)?;
    point_from::<DVec3>(&coords).map_err(|e| {
        Error::InArgument {
            name,
            index: None,
            source: Box::new(e),
        }
        .into()
    })
}

/// Sets `object[key] = value`.
fn set(object: &js_sys::Object, key: &str, value: &JsValue) -> Result<(), ApiError> {
    js_sys::Reflect::set(object, &JsValue::from_str(key), value)
        .map(|_| ())
        .map_err(|_| ApiError::new("could not build the result object"))
}

/// `[knot, c, knot, c, …]` of a list of seams.
fn flat_seams(seams: &[(f64, i32)]) -> Float64Array {
    let mut flat = Vec::with_capacity(2 * seams.len());
    for &(knot, c) in seams {
        flat.extend_from_slice(&[knot, f64::from(c)]);
    }
    Float64Array::from(&flat[..])
}

/// The methods both surface classes share, on their `inner: BSplineSurface`.
macro_rules! surface_mesh_methods {
    ($class:ident, $js:ident) => {
        #[wasm_bindgen(js_class = $js)]
        impl $class {
            /// A mesh `{ positions, normals, uvs, indices }` (as `tessellate`) within `tolerance`
            /// (model units, > 0) of the surface: every point of every triangle lies within
            /// `tolerance` of the surface point at its interpolated (u, v). A quadtree over the
            /// Bézier patches split by control-net flatness; no cracks between leaves of
            /// different depth; a plane gets 2 triangles per patch. Throws for a tolerance ≤ 0
            /// or NaN and for more than 2^16 vertices.
            #[wasm_bindgen(js_name = tessellateAdaptive, unchecked_return_type = "{ positions: Float32Array; normals: Float32Array; uvs: Float32Array; indices: Uint32Array }")]
            pub fn tessellate_adaptive(&self, tolerance: f64) -> Result<JsValue, ApiError> {
                mesh_to_js(&self.inner.tessellate_adaptive(tolerance)?)
            }

            /// Where the surface meets the infinite line origin + s·direction: Float64Array
            /// `[u, v, s, …]` per hit, sorted by s, each point within `tolerance` of the line,
            /// hits closer than `tolerance` merged. Box recursion on the Bézier patches, then
            /// Newton. A line lying in the surface gives a finite sample of the overlap. Throws
            /// for a zero direction or a tolerance ≤ 0.
            #[wasm_bindgen(js_name = intersectLine)]
            pub fn intersect_line(
                &self,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")] origin: JsValue,
                #[wasm_bindgen(unchecked_param_type = "Float64Array | number[]")]
                direction: JsValue,
                tolerance: f64,
            ) -> Result<Vec<f64>, ApiError> {
                let origin = point_arg("origin", &origin)?;
                let direction = point_arg("direction", &direction)?;
                let hits = self.inner.intersect_line(origin, direction, tolerance)?;
                Ok(hits.concat())
            }

            /// The measured continuity across every distinct interior knot: `{ u: Float64Array
            /// [knot, c, …], v: Float64Array [knot, c, …] }`, c the largest k ≤ degree with
            /// derivatives of orders 0..k equal across the seam (relative 1e-9), −1 for a gap.
            /// Empty lists on a Bézier patch.
            #[wasm_bindgen(unchecked_return_type = "{ u: Float64Array; v: Float64Array }")]
            pub fn seams(&self) -> Result<JsValue, ApiError> {
                let (u, v) = self.inner.seams()?;
                let object = js_sys::Object::new();
                set(&object, "u", &flat_seams(&u).into())?;
                set(&object, "v", &flat_seams(&v).into())?;
                Ok(object.into())
            }
        }
    };
}

surface_mesh_methods!(JsBSplineSurface, BSplineSurface);
surface_mesh_methods!(JsBezierSurface, BezierSurface);

#[wasm_bindgen(js_class = BSplineSurface)]
impl JsBSplineSurface {
    /// One `BezierSurface` (on [0, 1]²) per non-empty span pair, u spans outer: patch
    /// a·(spans in v) + b is the a-th u span × the b-th v span. Rational surfaces give rational
    /// patches.
    #[wasm_bindgen(js_name = toBezierPatches)]
    pub fn to_bezier_patches(&self) -> Result<Vec<JsBezierSurface>, ApiError> {
        Ok(self
            .inner
            .to_bezier_patches()?
            .into_iter()
            .map(JsBezierSurface::wrap)
            .collect())
    }
}
