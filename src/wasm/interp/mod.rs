//! The interpolation family (syllabus §5) for JavaScript.
