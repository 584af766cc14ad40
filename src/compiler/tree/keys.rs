//! Keyframes: sizes checked against the model's, then the key arrays (missing entries default
//! to qpos0, zeros, mocap body poses).

use super::*;

impl Compiled {
    pub(super) fn check_keys(&self) -> Result<(), CError> {
        let (h, keys) = (&self.header, &self.keys);
        for (id, k) in keys.iter().enumerate() {
            let kerr = |what: &str, n: i32| {
                CError::at(
                    format!("key {id}: invalid {what} size, expected length {n}"),
                    &k.name,
                    id,
                    -1,
                )
            };
            let checks = [
                (&k.qpos, h.nq, "qpos"),
                (&k.qvel, h.nv, "qvel"),
                (&k.act, h.na, "act"),
                (&k.mpos, 3 * h.nmocap, "mpos"),
                (&k.mquat, 4 * h.nmocap, "mquat"),
                (&k.ctrl, h.nu, "ctrl"),
            ];
            for (v, n, what) in checks {
                if !v.is_empty() && v.len() != n as usize {
                    return Err(kerr(what, n));
                }
            }
        }
        Ok(())
    }

    pub(super) fn fill_keys(&self, m: &mut ModelMut) {
        let h = &self.header;
        let nv = h.nv as usize;
        let (nq, na, nu, nmocap) = (
            h.nq as usize,
            h.na as usize,
            h.nu as usize,
            h.nmocap as usize,
        );
        for (i, k) in self.keys.iter().enumerate() {
            m.key_time[i] = k.time;
            let qpos = if k.qpos.is_empty() {
                m.qpos0.to_vec()
            } else {
                k.qpos.clone()
            };
            m.key_qpos[i * nq..(i + 1) * nq].copy_from_slice(&qpos);
            if !k.qvel.is_empty() {
                m.key_qvel[i * nv..(i + 1) * nv].copy_from_slice(&k.qvel);
            }
            if !k.act.is_empty() {
                m.key_act[i * na..(i + 1) * na].copy_from_slice(&k.act);
            }
            for (b, body) in self.bodies.iter().enumerate() {
                if body.mocapid >= 0 {
                    let id = body.mocapid as usize;
                    let pos = [
                        m.body_pos[3 * b],
                        m.body_pos[3 * b + 1],
                        m.body_pos[3 * b + 2],
                    ];
                    let quat: Vec<f64> = m.body_quat[4 * b..4 * b + 4].to_vec();
                    if k.mpos.is_empty() {
                        m.key_mpos[3 * (i * nmocap + id)..3 * (i * nmocap + id) + 3]
                            .copy_from_slice(&pos);
                    }
                    if k.mquat.is_empty() {
                        m.key_mquat[4 * (i * nmocap + id)..4 * (i * nmocap + id) + 4]
                            .copy_from_slice(&quat);
                    }
                }
            }
            if !k.mpos.is_empty() {
                m.key_mpos[i * 3 * nmocap..(i + 1) * 3 * nmocap].copy_from_slice(&k.mpos);
            }
            if !k.mquat.is_empty() {
                m.key_mquat[i * 4 * nmocap..(i + 1) * 4 * nmocap].copy_from_slice(&k.mquat);
            }
            if !k.ctrl.is_empty() {
                m.key_ctrl[i * nu..(i + 1) * nu].copy_from_slice(&k.ctrl);
            }
            // quaternions normalized when copied and again when the model is finalized
            for _ in 0..2 {
                for (j, jt) in self.joints.iter().enumerate() {
                    let adr = i * nq + m.jnt_qposadr[j] as usize;
                    match jt.spec.kind {
                        JointType::Ball => normalize4_engine(&mut m.key_qpos[adr..adr + 4]),
                        JointType::Free => normalize4_engine(&mut m.key_qpos[adr + 3..adr + 7]),
                        _ => {}
                    }
                }
            }
            for j in 0..nmocap {
                let adr = 4 * (i * nmocap + j);
                normalize4_engine(&mut m.key_mquat[adr..adr + 4]);
            }
        }
    }
}
