//! C entry points.
