//! MJCF reader: XML text into a model description (`crate::compiler::spec`), defaults applied.

pub mod include;
pub mod reader;
pub mod schema;
pub mod tree;
pub mod urdf;
pub mod writer;
