//! Exported globals: engine callbacks, name tables, the collision function table.

use crate::abi::*;
use std::os::raw::c_char;

#[no_mangle]
pub static mut mjcb_passive: mjfGeneric = None;
#[no_mangle]
pub static mut mjcb_control: mjfGeneric = None;
#[no_mangle]
pub static mut mjcb_contactfilter: mjfConFilt = None;
#[no_mangle]
pub static mut mjcb_sensor: mjfSensor = None;
#[no_mangle]
pub static mut mjcb_time: mjfTime = None;
#[no_mangle]
pub static mut mjcb_act_dyn: mjfAct = None;
#[no_mangle]
pub static mut mjcb_act_gain: mjfAct = None;
#[no_mangle]
pub static mut mjcb_act_bias: mjfAct = None;

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
pub unsafe extern "C" fn mj_resetCallbacks() {
    mjcb_passive = None;
    mjcb_control = None;
    mjcb_contactfilter = None;
    mjcb_sensor = None;
    mjcb_time = None;
    mjcb_act_bias = None;
    mjcb_act_gain = None;
    mjcb_act_dyn = None;
}

/// Licenses are gone since 2.1: activation always succeeds.
#[no_mangle]
pub extern "C" fn mj_activate(_filename: *const c_char) -> std::os::raw::c_int {
    1
}

/// Nothing to release (kept for compatibility, as in 2.2.2).
#[no_mangle]
pub extern "C" fn mj_deactivate() {}

/// Calls the user's mjcb_control or mjcb_passive (`passive`); false when it is not set.
pub fn call_generic(passive: bool, m: &mjModel, d: &mut mjData) -> bool {
    // SAFETY: plain reads of the callback globals, as the C library does; the callback gets
    // the model and data the engine works on, as in 2.2.2.
    unsafe {
        let cb = if passive {
            std::ptr::addr_of!(mjcb_passive).read()
        } else {
            std::ptr::addr_of!(mjcb_control).read()
        };
        match cb {
            Some(f) => {
                f(m, d);
                true
            }
            None => false,
        }
    }
}

/// Which actuator callback: dynamics, gain or bias.
#[derive(Clone, Copy)]
pub enum ActCallback {
    Dyn,
    Gain,
    Bias,
}

/// Calls mjcb_act_dyn, mjcb_act_gain or mjcb_act_bias for actuator `i`; None when not set.
pub fn call_act(which: ActCallback, m: &mjModel, d: &mut mjData, i: usize) -> Option<f64> {
    // SAFETY: as in call_generic.
    unsafe {
        let cb = match which {
            ActCallback::Dyn => std::ptr::addr_of!(mjcb_act_dyn).read(),
            ActCallback::Gain => std::ptr::addr_of!(mjcb_act_gain).read(),
            ActCallback::Bias => std::ptr::addr_of!(mjcb_act_bias).read(),
        };
        cb.map(|f| f(m, d, i as i32))
    }
}

/// Calls mjcb_sensor for a stage; false when it is not set.
pub fn call_sensor(m: &mjModel, d: &mut mjData, stage: i32) -> bool {
    // SAFETY: as in call_generic.
    unsafe {
        match std::ptr::addr_of!(mjcb_sensor).read() {
            Some(f) => {
                f(m, d, stage);
                true
            }
            None => false,
        }
    }
}

/// Calls mjcb_contactfilter for a geom pair (true: discard); None when it is not set.
pub fn call_contactfilter(m: &mjModel, d: &mut mjData, g1: usize, g2: usize) -> Option<bool> {
    // SAFETY: as in call_generic.
    unsafe {
        std::ptr::addr_of!(mjcb_contactfilter)
            .read()
            .map(|f| f(m, d, g1 as i32, g2 as i32) != 0)
    }
}

/// Is mjcb_time set?
pub fn time_set() -> bool {
    // SAFETY: as in call_generic.
    unsafe { std::ptr::addr_of!(mjcb_time).read().is_some() }
}

/// mjcb_time(), or None when it is not set.
pub fn call_time() -> Option<f64> {
    // SAFETY: as in call_generic.
    unsafe { std::ptr::addr_of!(mjcb_time).read().map(|f| f()) }
}
