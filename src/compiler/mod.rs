//! Model description to `mjModel`.
