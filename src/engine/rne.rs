//! Recursive Newton-Euler: bias forces (gravity, Coriolis, centrifugal) and M*qacc.

use super::linalg::{dot6, row};
use super::{disabled, Data, EngineError, Model};
use crate::abi::mjtDisableBit_;
use crate::math::*;

/// result = M(qpos)*qacc + C(qpos,qvel); without the inertial term when `qacc` is None (mj_rne).
pub fn rne_with(
    m: &Model,
    d: &mut Data,
    qacc: Option<&[f64]>,
    result: &mut [f64],
) -> Result<(), EngineError> {
    let nbody = m.raw.nbody as usize;
    let nv = m.raw.nv as usize;
    d.arena.scope(|a| -> Result<(), EngineError> {
        let cacc = a.alloc(6 * nbody)?;
        let cfrc = a.alloc(6 * nbody)?;
        if !disabled(m, mjtDisableBit_::mjDSBL_GRAVITY) {
            let g = m.raw.opt.gravity;
            cacc[3] = -g[0];
            cacc[4] = -g[1];
            cacc[5] = -g[2];
        }
        for i in 1..nbody {
            let bda = m.body_dofadr()[i].max(0) as usize;
            let n = m.body_dofnum()[i] as usize;
            let p = m.body_parentid()[i] as usize;
            let tmp = mul_dof_vec(&d.cdof_dot[6 * bda..], &d.qvel[bda..], n);
            for k in 0..6 {
                cacc[6 * i + k] = cacc[6 * p + k] + tmp[k];
            }
            if let Some(qacc) = qacc {
                let tmp = mul_dof_vec(&d.cdof[6 * bda..], &qacc[bda..], n);
                for k in 0..6 {
                    cacc[6 * i + k] += tmp[k];
                }
            }
            let ci = &d.cinert[10 * i..10 * i + 10];
            let cv = row::<6>(d.cvel, i);
            let f = mul_inert_vec(ci, &row(cacc, i));
            let tmp = mul_inert_vec(ci, &cv);
            let tmp1 = cross_force(&cv, &tmp);
            for k in 0..6 {
                cfrc[6 * i + k] = f[k] + tmp1[k];
            }
        }
        cfrc[..6].fill(0.0);
        for i in (1..nbody).rev() {
            let p = m.body_parentid()[i] as usize;
            if p != 0 {
                for k in 0..6 {
                    cfrc[6 * p + k] += cfrc[6 * i + k];
                }
            }
        }
        for i in 0..nv {
            let b = m.dof_bodyid()[i] as usize;
            result[i] = dot6(&d.cdof[6 * i..6 * i + 6], &cfrc[6 * b..6 * b + 6]);
        }
        Ok(())
    })
}

/// qfrc_bias by abbreviated RNE (no acceleration term).
pub fn rne_bias(m: &Model, d: &mut Data) -> Result<(), EngineError> {
    let nv = m.raw.nv as usize;
    let out = std::mem::take(&mut d.qfrc_bias);
    let r = rne_with(m, d, None, &mut out[..nv]);
    d.qfrc_bias = out;
    r
}
