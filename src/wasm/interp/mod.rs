//! The interpolation family (syllabus §5) for JavaScript.

mod global;

pub use global::{approximate_bspline, bspline_interpolation_system, interpolate_bspline};
