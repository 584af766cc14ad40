//! Spatial algebra, quaternions, small dense and sparse linear algebra.
