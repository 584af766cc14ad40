//! Symbols 2.2.2 exports outside mujoco.h not implemented yet: each reports that through `mju_error`.

#![allow(unused_variables, unused_imports)]

use crate::abi::*;
use std::os::raw::{c_char, c_int, c_void};

use super::pending;
