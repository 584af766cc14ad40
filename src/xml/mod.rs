//! MJCF and URDF readers: XML into a model description.
