//! The errors of surfaces: control nets, normals, tessellation, swept and revolved surfaces
//! ([`super::Error::Surface`]).

use super::message::Num;
use std::fmt;

/// What can go wrong with a surface: the variants of [`super::Error::Surface`].
#[derive(Debug, Clone, PartialEq)]
// In the wasm build the fields become a thrown Error's `params` (camelCase), as `Error`'s do.
#[cfg_attr(
    all(target_arch = "wasm32", target_os = "unknown"),
    derive(serde::Serialize),
    serde(untagged, rename_all_fields = "camelCase")
)]
pub enum SurfaceError {
    /// Surface coordinates that do not fill the net: `BSplineSurface::from_flat(&[0.0; 10], 2, 2, …)`.
    NetCoordinateCount {
        /// Rows of the net.
        rows: usize,
        /// Columns of the net.
        cols: usize,
        /// Number of coordinates given.
        got: usize,
    },
    /// A Bézier patch with a single row or column: `BSplineSurface::bezier(&coords, 1, 3, None)`.
    PatchTooSmall {
        /// Rows given.
        rows: usize,
        /// Columns given.
        cols: usize,
    },
    /// A control point `(i, j)` outside the net: `surface.set_control_point(5, 0, p)` on a 4 × 4
    /// net.
    NetIndexOutOfRange {
        /// Row index.
        i: usize,
        /// Column index.
        j: usize,
        /// Rows of the net.
        rows: usize,
        /// Columns of the net.
        cols: usize,
    },
    /// No surface normal at `(u, v)`, even in the limit: `surface.normal(u, v)` on a patch whose
    /// rows all coincide.
    NoNormal {
        /// u.
        u: f64,
        /// v.
        v: f64,
    },
    /// A tessellation with no quads one way: `surface.tessellate(0, 4)`.
    EmptyTessellation {
        /// Quads along u.
        nu: usize,
        /// Quads along v.
        nv: usize,
    },
    /// A direction that must not be the zero vector is: `surface::revolve(&c, o, DVec3::ZERO, τ)`.
    ZeroDirection {
        /// The argument's name ("axisDirection").
        name: &'static str,
    },
    /// An operation defined for polynomial patches only was asked of a rational one:
    /// `matrix_form()` on a patch with weights.
    NeedsPolynomial {
        /// The operation ("matrixForm").
        operation: &'static str,
    },
}

impl SurfaceError {
    /// The variant's stable kebab-case code ([`super::Error::code`]).
    pub fn code(&self) -> &'static str {
        match self {
            SurfaceError::NetCoordinateCount { .. } => "net-coordinate-count",
            SurfaceError::PatchTooSmall { .. } => "patch-too-small",
            SurfaceError::NetIndexOutOfRange { .. } => "net-index-out-of-range",
            SurfaceError::NoNormal { .. } => "no-normal",
            SurfaceError::EmptyTessellation { .. } => "empty-tessellation",
            SurfaceError::ZeroDirection { .. } => "zero-direction",
            SurfaceError::NeedsPolynomial { .. } => "needs-polynomial",
        }
    }
}

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SurfaceError::NetCoordinateCount { rows, cols, got } => write!(
                f,
                "points must hold rows·cols·3 = {rows}·{cols}·3 = {} coordinates, got {got}",
                rows.saturating_mul(*cols).saturating_mul(3)
            ),
            SurfaceError::PatchTooSmall { rows, cols } => write!(
                f,
                "a Bézier patch needs at least 2 rows and 2 columns (degree ≥ 1 each way), got {rows} × {cols}"
            ),
            SurfaceError::NetIndexOutOfRange { i, j, rows, cols } => write!(
                f,
                "control point (i, j) = ({i}, {j}) is out of range: the net has {rows} × {cols} points (i in 0..={}, j in 0..={})",
                rows.saturating_sub(1),
                cols.saturating_sub(1)
            ),
            SurfaceError::NoNormal { u, v } => write!(
                f,
                "the surface has no normal at (u, v) = ({}, {}): ∂S/∂u × ∂S/∂v = 0 there, even in the limit from inside the domain",
                Num(*u),
                Num(*v)
            ),
            SurfaceError::EmptyTessellation { nu, nv } => write!(
                f,
                "tessellate needs at least 1 quad each way, got nu = {nu}, nv = {nv}"
            ),
            SurfaceError::ZeroDirection { name } => {
                write!(f, "{name} must not be the zero vector (it gives no direction)")
            }
            SurfaceError::NeedsPolynomial { operation } => write!(
                f,
                "{operation} works on polynomial patches; this one has weights (a rational patch has a denominator)"
            ),
        }
    }
}
