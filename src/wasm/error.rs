//! The error every binding throws: a JS `Error` whose `message` is the English text, with
//! `code` ([`Error::code`], e.g. `"knot-count"`) and `params` (the variant's fields, camelCase:
//! `{ expected: 9, got: 8, points: 5, degree: 3 }`), so a page can show the message in its own
//! language without reading the English (www/lib/core-errors.js does).

use crate::error::Error;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A thrown JS `Error`, from a crate [`Error`] (with `code` and `params`) or from a message
/// of the bindings' own (`ApiError::new`, code `"internal"`).
#[derive(Debug)]
pub struct ApiError(JsValue);

impl ApiError {
    /// An `Error` with `message` and code `"internal"`: a failure of the bindings themselves
    /// (the wasm memory is not what it should be), never of the caller's input.
    pub fn new(message: &str) -> Self {
        let error = js_sys::Error::new(message);
        set(&error, "code", &JsValue::from_str("internal"));
        ApiError(error.into())
    }
}

impl From<Error> for ApiError {
    fn from(err: Error) -> Self {
        let error = js_sys::Error::new(&err.to_string());
        set(&error, "code", &JsValue::from_str(err.code()));
        // Maps as plain objects: a flattened field (a typed expression's problem) serializes
        // as a map, which would otherwise become a JS Map.
        let serializer = serde_wasm_bindgen::Serializer::new().serialize_maps_as_objects(true);
        let params = err.serialize(&serializer).unwrap_or(JsValue::UNDEFINED);
        set(&error, "params", &params);
        ApiError(error.into())
    }
}

impl From<serde_wasm_bindgen::Error> for ApiError {
    /// A result the bindings could not turn into a JS value (an internal failure).
    fn from(err: serde_wasm_bindgen::Error) -> Self {
        ApiError::new(&err.to_string())
    }
}

impl From<ApiError> for JsValue {
    fn from(err: ApiError) -> JsValue {
        err.0
    }
}

/// `object[key] = value`; a failure (a frozen object) only loses the property.
fn set(object: &js_sys::Error, key: &str, value: &JsValue) {
    let _ = js_sys::Reflect::set(object, &JsValue::from_str(key), value);
}
