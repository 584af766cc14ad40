//! Equality constraints: object ids and anchors, then their arrays.

use super::*;

pub(super) fn compile(
    specs: Vec<Equality>,
    bodies: &[FBody],
    joints: &[FJoint],
    tendons: &[Tendon],
    global: bool,
) -> Result<Vec<(Equality, [i32; 2])>, CError> {
    let mut equalities = Vec::new();
    for (id, mut e) in specs.into_iter().enumerate() {
        let name = e.name.clone();
        let err = |m: String| CError::at(m, &name, id, e.line);
        let find = |n: &str| -> Option<usize> {
            match e.kind {
                0 | 1 => find_body(bodies, n),
                2 => joints.iter().position(|j| j.spec.name == n),
                3 => tendons.iter().position(|t| t.name == n),
                _ => None,
            }
        };
        if !(0..=3).contains(&e.kind) {
            return Err(err(format!(
                "invalid type in equality constraint '{name}' (id = {id})'"
            )));
        }
        let o1 = find(&e.name1).ok_or_else(|| {
            err(format!(
                "unknown element '{}' in equality constraint {id}",
                e.name1
            ))
        })?;
        let mut o2 = -1i32;
        if !e.name2.is_empty() {
            o2 = find(&e.name2).ok_or_else(|| {
                err(format!(
                    "unknown element '{}' in equality constraint {id}",
                    e.name2
                ))
            })? as i32;
        }
        if global && e.kind <= 1 {
            // anchors are given in world coordinates: connect in body1, weld in body2 (if named)
            let frame = if e.kind == 0 {
                Some(o1)
            } else if o2 >= 0 {
                Some(o2 as usize)
            } else {
                None
            };
            if let Some(f) = frame {
                let (bp, bq) = (bodies[f].gpos, bodies[f].gquat);
                let a = local_pos(&[e.data[0], e.data[1], e.data[2]], &bp, &bq);
                e.data[..3].copy_from_slice(&a);
            }
        }
        if e.kind <= 1 && o2 == -1 {
            o2 = 0;
        }
        if o1 as i32 == o2 {
            return Err(err(format!(
                "element '{}' is repeated in equality constraint {id}",
                e.name1
            )));
        }
        if e.kind == 2 {
            let scalar = |k: JointType| matches!(k, JointType::Hinge | JointType::Slide);
            let k2 = if o2 >= 0 {
                joints[o2 as usize].spec.kind
            } else {
                JointType::Hinge
            };
            if !scalar(joints[o1].spec.kind) || !scalar(k2) {
                return Err(err(format!(
                    "only HINGE and SLIDE joint allowed in constraint '{name}' (id = {id})"
                )));
            }
        }
        let _ = &mut e;
        equalities.push((e, [o1 as i32, o2]));
    }
    Ok(equalities)
}

impl Compiled {
    pub(super) fn fill_equalities(&self, m: &mut ModelMut) {
        for (i, (e, ids)) in self.equalities.iter().enumerate() {
            m.eq_type[i] = e.kind;
            m.eq_obj1id[i] = ids[0];
            m.eq_obj2id[i] = ids[1];
            m.eq_active[i] = e.active as u8;
            put(m.eq_solref, i, &e.solref);
            put(m.eq_solimp, i, &e.solimp);
            put(m.eq_data, i, &e.data);
        }
    }
}
