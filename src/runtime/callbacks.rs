//! The user's engine callbacks (mjcb_*): the registry and the calls the engine makes.

use crate::abi::*;

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

/// Clears every engine callback.
pub fn reset() {
    // SAFETY: plain stores to the callback globals, as the C library does.
    unsafe {
        mjcb_passive = None;
        mjcb_control = None;
        mjcb_contactfilter = None;
        mjcb_sensor = None;
        mjcb_time = None;
        mjcb_act_bias = None;
        mjcb_act_gain = None;
        mjcb_act_dyn = None;
    }
}

/// Is any callback set that receives the model and data (all but mjcb_time)?
pub fn any_engine_callback() -> bool {
    // SAFETY: plain reads of the callback globals, as the C library does.
    unsafe {
        std::ptr::addr_of!(mjcb_passive).read().is_some()
            || std::ptr::addr_of!(mjcb_control).read().is_some()
            || std::ptr::addr_of!(mjcb_contactfilter).read().is_some()
            || std::ptr::addr_of!(mjcb_sensor).read().is_some()
            || std::ptr::addr_of!(mjcb_act_bias).read().is_some()
            || std::ptr::addr_of!(mjcb_act_gain).read().is_some()
            || std::ptr::addr_of!(mjcb_act_dyn).read().is_some()
    }
}

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

/// Is mjcb_contactfilter set?
pub fn contactfilter_set() -> bool {
    // SAFETY: as in call_generic.
    unsafe { std::ptr::addr_of!(mjcb_contactfilter).read().is_some() }
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
