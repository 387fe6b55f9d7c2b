//! The per-call result buffer behind `evaluateInto`, `derivativeInto` and their surface forms.
//!
//! A method returning `Vec<f64>` costs, per call, an allocation in the wasm heap, a new JS
//! `Float64Array`, a copy and a free (~130 ns of a ~140 ns `evaluate(t)`); a `&mut [f64]`
//! parameter is no better (the glue allocates, copies in, copies out and frees). So the hidden
//! `__…Scratch` methods write their one point into this fixed buffer in the wasm memory and
//! return its position; the JS `…Into(…, out)` methods that `scripts/glue.mjs` adds to the
//! generated glue read it through the glue's cached `Float64Array` of the whole memory (made
//! again when the memory grows) and copy the `dim` numbers into the caller's `out`. One wasm
//! call, no allocation on either side.
//!
//! Layout: `[dim, x, y, z]`. The returned value is the buffer's index in `Float64Array` units
//! (byte address / 8, never 0: the buffer is static data, above the stack), or 0 when the
//! call failed; the JS then calls the allocating method with the same arguments, which throws
//! the same error with its message (the failure path is the rare one, so it may cost more).

use crate::error::Error;
use crate::geom::Point;
use std::cell::Cell;

/// Numbers in the buffer: the dimension, then up to 3 coordinates.
const SCRATCH_LEN: usize = 4;

thread_local! {
    /// The buffer (wasm32 without threads: one static).
    static SCRATCH: Cell<[f64; SCRATCH_LEN]> = const { Cell::new([0.0; SCRATCH_LEN]) };
}

/// Writes `coords[..dim]` (dim ≤ 3) and returns the buffer's `Float64Array` index.
#[inline]
pub(crate) fn put_coords(dim: usize, coords: [f64; 3]) -> u32 {
    let [x, y, z] = coords;
    SCRATCH.with(|s| {
        s.set([dim as f64, x, y, z]);
        (s.as_ptr() as usize / std::mem::size_of::<f64>()) as u32
    })
}

/// A point (2D or 3D) into the buffer: its index, or 0 on an error.
#[inline]
pub(crate) fn put<P: Point>(point: Result<P, Error>) -> u32 {
    match point {
        Ok(p) => {
            let mut c = [0.0; 3];
            if let Some(head) = c.get_mut(..P::DIM) {
                p.write_to(head);
            }
            put_coords(P::DIM, c)
        }
        Err(_) => 0,
    }
}
