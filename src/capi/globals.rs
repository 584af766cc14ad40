//! Exported globals: name tables, the collision function table (the callbacks live in
//! `runtime::callbacks`).

use crate::abi::*;
use crate::runtime::callbacks;
use std::os::raw::c_char;

/// Pairwise collision functions by geom type, where 2.2.2 has one (upper triangle, not between
/// planes and height fields); every entry runs the narrow phase of the geoms' own types.
#[no_mangle]
pub static mut mjCOLLISIONFUNC: [[mjfCollision; 8]; 8] = collision_table();

const fn collision_table() -> [[mjfCollision; 8]; 8] {
    let mut t: [[mjfCollision; 8]; 8] = [[None; 8]; 8];
    let mut i = 0;
    while i < 8 {
        let mut j = i;
        while j < 8 {
            if !(i <= 1 && j <= 1) {
                t[i][j] = Some(super::engine::collide_pair);
            }
            j += 1;
        }
        i += 1;
    }
    t
}

/// A table of C string constants that C code can index like `const char*[N]`.
#[repr(transparent)]
pub struct StrTable<const N: usize>(pub [*const c_char; N]);
// SAFETY: the pointers address immutable 'static string literals.
unsafe impl<const N: usize> Sync for StrTable<N> {}

#[repr(transparent)]
pub struct StrTable3<const N: usize>(pub [[*const c_char; 3]; N]);
// SAFETY: as for StrTable.
unsafe impl<const N: usize> Sync for StrTable3<N> {}

macro_rules! c {
    ($s:literal) => {
        concat!($s, "\0").as_ptr() as *const c_char
    };
}

#[no_mangle]
pub static mjDISABLESTRING: StrTable<13> = StrTable([
    c!("Constraint"),
    c!("Equality"),
    c!("Frictionloss"),
    c!("Limit"),
    c!("Contact"),
    c!("Passive"),
    c!("Gravity"),
    c!("Clampctrl"),
    c!("Warmstart"),
    c!("Filterparent"),
    c!("Actuation"),
    c!("Refsafe"),
    c!("Sensor"),
]);

#[no_mangle]
pub static mjENABLESTRING: StrTable<5> = StrTable([
    c!("Override"),
    c!("Energy"),
    c!("Fwdinv"),
    c!("Sensornoise"),
    c!("MultiCCD"),
]);

#[no_mangle]
pub static mjTIMERSTRING: StrTable<13> = StrTable([
    c!("step"),
    c!("forward"),
    c!("inverse"),
    c!("position"),
    c!("velocity"),
    c!("actuation"),
    c!("acceleration"),
    c!("constraint"),
    c!("pos_kinematics"),
    c!("pos_inertia"),
    c!("pos_collision"),
    c!("pos_make"),
    c!("pos_project"),
]);

#[no_mangle]
pub static mjLABELSTRING: StrTable<14> = StrTable([
    c!("None"),
    c!("Body"),
    c!("Joint"),
    c!("Geom"),
    c!("Site"),
    c!("Camera"),
    c!("Light"),
    c!("Tendon"),
    c!("Actuator"),
    c!("Constraint"),
    c!("Skin"),
    c!("Selection"),
    c!("SelPoint"),
    c!("ContactForce"),
]);

#[no_mangle]
pub static mjFRAMESTRING: StrTable<8> = StrTable([
    c!("None"),
    c!("Body"),
    c!("Geom"),
    c!("Site"),
    c!("Camera"),
    c!("Light"),
    c!("Contact"),
    c!("World"),
]);

#[no_mangle]
pub static mjVISSTRING: StrTable3<23> = StrTable3([
    [c!("Convex &Hull"), c!("0"), c!("H")],
    [c!("Te&xture"), c!("1"), c!("X")],
    [c!("&Joint"), c!("0"), c!("J")],
    [c!("Camera"), c!("0"), c!("Q")],
    [c!("Act&uator"), c!("0"), c!("U")],
    [c!("Act&ivation"), c!("0"), c!(",")],
    [c!("Light"), c!("0"), c!("Z")],
    [c!("Tendon"), c!("1"), c!("V")],
    [c!("Range Finder"), c!("1"), c!("Y")],
    [c!("Co&nstraint"), c!("0"), c!("N")],
    [c!("&Inertia"), c!("0"), c!("I")],
    [c!("Scale Inertia"), c!("0"), c!("'")],
    [c!("Pertur&b Force"), c!("0"), c!("B")],
    [c!("Perturb &Object"), c!("1"), c!("O")],
    [c!("&Contact Point"), c!("0"), c!("C")],
    [c!("Contact &Force"), c!("0"), c!("F")],
    [c!("Contact S&plit"), c!("0"), c!("P")],
    [c!("&Transparent"), c!("0"), c!("T")],
    [c!("&Auto Connect"), c!("0"), c!("A")],
    [c!("Center of &Mass"), c!("0"), c!("M")],
    [c!("S&elect Point"), c!("0"), c!("E")],
    [c!("Static Bo&dy"), c!("1"), c!("D")],
    [c!("Skin"), c!("1"), c!(";")],
]);

#[no_mangle]
pub static mjRNDSTRING: StrTable3<10> = StrTable3([
    [c!("Shadow"), c!("1"), c!("S")],
    [c!("Wireframe"), c!("0"), c!("W")],
    [c!("Reflection"), c!("1"), c!("R")],
    [c!("Additive"), c!("0"), c!("L")],
    [c!("Skybox"), c!("1"), c!("K")],
    [c!("Fog"), c!("0"), c!("G")],
    [c!("Haze"), c!("1"), c!("/")],
    [c!("Segment"), c!("0"), c!(",")],
    [c!("Id Color"), c!("0"), c!(".")],
    [c!("Cull Face"), c!("1"), c!("")],
]);

/// Clears every engine callback.
#[no_mangle]
pub extern "C" fn mj_resetCallbacks() {
    callbacks::reset()
}

/// Licenses are gone since 2.1: activation always succeeds.
#[no_mangle]
pub extern "C" fn mj_activate(_filename: *const c_char) -> std::os::raw::c_int {
    1
}

/// Nothing to release (kept for compatibility, as in 2.2.2).
#[no_mangle]
pub extern "C" fn mj_deactivate() {}
