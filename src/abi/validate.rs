//! Structural checks of a model from outside (MJB files): every index in range, as 2.2.2 checks,
//! so that no later computation reads outside an array.

use super::view::Model;
use super::*;

/// Number of objects of a type, -1 for "unknown" (no object), -2 for an invalid type.
fn num_objects(m: &mjModel, objtype: i32) -> i32 {
    match objtype {
        0 => -1,
        1 | 2 => m.nbody,
        3 => m.njnt,
        4 => m.nv,
        5 => m.ngeom,
        6 => m.nsite,
        7 => m.ncam,
        8 => m.nlight,
        9 => m.nmesh,
        10 => m.nskin,
        11 => m.nhfield,
        12 => m.ntex,
        13 => m.nmat,
        14 => m.npair,
        15 => m.nexclude,
        16 => m.neq,
        17 => m.ntendon,
        18 => m.nu,
        19 => m.nsensor,
        20 => m.nnumeric,
        21 => m.ntext,
        22 => m.ntuple,
        23 => m.nkey,
        _ => -2,
    }
}

/// Size of a sensor's output by type, as 2.2.2 defines it for validation; -1 if invalid.
fn sensor_size(sensor_type: i32, nuser_sensor: i32) -> i32 {
    match sensor_type {
        0 | 7..=14 | 17..=22 | 35 => 1,
        1..=6 | 16 | 23 | 25..=34 => 3,
        15 | 24 => 4,
        36 => nuser_sensor,
        _ => -1,
    }
}

/// Number of qpos and qvel entries of a joint type.
pub fn joint_sizes(jnt_type: i32) -> Option<(i32, i32)> {
    match jnt_type {
        0 => Some((7, 6)),
        1 => Some((4, 3)),
        2 | 3 => Some((1, 1)),
        _ => None,
    }
}

/// `mj_validateReferences`: the first problem found, in 2.2.2's words.
pub fn validate_references(mv: Model) -> Option<&'static str> {
    let m = mv.raw;
    macro_rules! nums {
        (_) => {
            None
        };
        ($n:ident) => {
            Some(mv.$n())
        };
    }
    macro_rules! refs {
        ($($adr:ident, $nadr:ident, $ntarget:ident, $num:tt;)*) => {$(
            let nums: Option<&[i32]> = nums!($num);
            for i in 0..m.$nadr.max(0) as usize {
                let lo = mv.$adr()[i];
                let num = nums.map_or(1, |n| n[i]);
                if num < 0 {
                    return Some(concat!("Invalid model: m->", stringify!($num), " is negative."));
                }
                if lo as i64 + num as i64 > m.$ntarget as i64 || lo < -1 {
                    return Some(concat!("Invalid model: ", stringify!($adr), " out of bounds."));
                }
            }
        )*};
    }
    refs! {
        body_parentid, nbody, nbody, _;
        body_rootid, nbody, nbody, _;
        body_weldid, nbody, nbody, _;
        body_mocapid, nbody, nmocap, _;
        body_jntadr, nbody, njnt, body_jntnum;
        body_dofadr, nbody, nv, body_dofnum;
        body_geomadr, nbody, ngeom, body_geomnum;
        jnt_qposadr, njnt, nq, _;
        jnt_dofadr, njnt, nv, _;
        jnt_bodyid, njnt, nbody, _;
        dof_bodyid, nv, nbody, _;
        dof_jntid, nv, njnt, _;
        dof_parentid, nv, nv, _;
        dof_Madr, nv, nM, _;
        geom_bodyid, ngeom, nbody, _;
        geom_matid, ngeom, nmat, _;
        site_bodyid, nsite, nbody, _;
        site_matid, nsite, nmat, _;
        cam_bodyid, ncam, nbody, _;
        cam_targetbodyid, ncam, nbody, _;
        light_bodyid, nlight, nbody, _;
        light_targetbodyid, nlight, nbody, _;
        mesh_vertadr, nmesh, nmeshvert, mesh_vertnum;
        mesh_texcoordadr, nmesh, nmeshtexvert, _;
        mesh_faceadr, nmesh, nmeshface, mesh_facenum;
        mesh_graphadr, nmesh, nmeshgraph, _;
        skin_matid, nskin, nmat, _;
        skin_vertadr, nskin, nskinvert, skin_vertnum;
        skin_texcoordadr, nskin, nskintexvert, _;
        skin_faceadr, nskin, nskinface, skin_facenum;
        skin_boneadr, nskin, nskinbone, skin_bonenum;
        skin_bonevertadr, nskinbone, nskinbonevert, skin_bonevertnum;
        skin_bonebodyid, nskinbone, nbody, _;
        skin_bonevertid, nskinbonevert, nskinvert, _;
        pair_geom1, npair, ngeom, _;
        pair_geom2, npair, ngeom, _;
        tendon_adr, ntendon, nwrap, tendon_num;
        tendon_matid, ntendon, nmat, _;
        numeric_adr, nnumeric, nnumericdata, numeric_size;
        text_adr, ntext, ntextdata, text_size;
        tuple_adr, ntuple, ntupledata, tuple_size;
        name_bodyadr, nbody, nnames, _;
        name_jntadr, njnt, nnames, _;
        name_geomadr, ngeom, nnames, _;
        name_siteadr, nsite, nnames, _;
        name_camadr, ncam, nnames, _;
        name_lightadr, nlight, nnames, _;
        name_meshadr, nmesh, nnames, _;
        name_skinadr, nskin, nnames, _;
        name_hfieldadr, nhfield, nnames, _;
        name_texadr, ntex, nnames, _;
        name_matadr, nmat, nnames, _;
        name_pairadr, npair, nnames, _;
        name_excludeadr, nexclude, nnames, _;
        name_eqadr, neq, nnames, _;
        name_tendonadr, ntendon, nnames, _;
        name_actuatoradr, nu, nnames, _;
        name_sensoradr, nsensor, nnames, _;
        name_numericadr, nnumeric, nnames, _;
        name_textadr, ntext, nnames, _;
        name_tupleadr, ntuple, nnames, _;
        name_keyadr, nkey, nnames, _;
    }

    for i in 0..m.nbody.max(0) as usize {
        if i > 0 && mv.body_parentid()[i] >= i as i32 {
            return Some("Invalid model: bad body_parentid.");
        }
        if mv.body_rootid()[i] > i as i32 {
            return Some("Invalid model: bad body_rootid.");
        }
        if mv.body_weldid()[i] > i as i32 {
            return Some("Invalid model: bad body_weldid.");
        }
    }
    for i in 0..m.njnt.max(0) as usize {
        let Some((npos, nvel)) = joint_sizes(mv.jnt_type()[i]) else {
            return Some("Invalid model: jnt_type out of bounds.");
        };
        let (qadr, dadr) = (mv.jnt_qposadr()[i], mv.jnt_dofadr()[i]);
        if qadr as i64 + npos as i64 > m.nq as i64 || qadr < 0 {
            return Some("Invalid model: jnt_qposadr out of bounds.");
        }
        if dadr as i64 + nvel as i64 > m.nv as i64 || dadr < 0 {
            return Some("Invalid model: jnt_dofadr out of bounds.");
        }
    }
    for i in 0..m.nv.max(0) as usize {
        if mv.dof_parentid()[i] >= i as i32 {
            return Some("Invalid model: bad dof_parentid.");
        }
    }
    for i in 0..m.ngeom.max(0) as usize {
        if !(0..=6).contains(&mv.geom_condim()[i]) {
            return Some("Invalid model: geom_condim out of bounds.");
        }
        let id = mv.geom_dataid()[i];
        let limit = match mv.geom_type()[i] {
            1 => Some(m.nhfield),
            7 => Some(m.nmesh),
            _ => None,
        };
        if limit.is_some_and(|n| id >= n || id < -1) {
            return Some("Invalid model: geom_dataid out of bounds.");
        }
    }
    for i in 0..m.nhfield.max(0) as usize {
        let adr = mv.hfield_adr()[i];
        if adr as i64 + mv.hfield_nrow()[i] as i64 * mv.hfield_ncol()[i] as i64
            > m.nhfielddata as i64
            || adr < 0
        {
            return Some("Invalid model: hfield_adr out of bounds.");
        }
    }
    for i in 0..m.ntex.max(0) as usize {
        let adr = mv.tex_adr()[i];
        if adr as i64 + 3 * mv.tex_height()[i] as i64 * mv.tex_width()[i] as i64 > m.ntexdata as i64
            || adr < 0
        {
            return Some("Invalid model: tex_adr out of bounds.");
        }
    }
    let body_pair = |sig: i32| ((sig & 0xFFFF) - 1, (sig >> 16) - 1);
    for &sig in mv.pair_signature() {
        let (b1, b2) = body_pair(sig);
        if b1 >= m.nbody || b1 < 0 {
            return Some("Invalid model: pair_body1 out of bounds.");
        }
        if b2 >= m.nbody || b2 < 0 {
            return Some("Invalid model: pair_body2 out of bounds.");
        }
    }
    for i in 0..m.neq.max(0) as usize {
        let (o1, o2) = (mv.eq_obj1id()[i], mv.eq_obj2id()[i]);
        let (n, min2) = match mv.eq_type()[i] {
            0 | 1 => (m.nbody, 0),
            2 => (m.njnt, -1),
            3 => (m.ntendon, -1),
            4 => return Some("distance equality constraints are no longer supported"),
            _ => continue,
        };
        if o1 >= n || o1 < 0 {
            return Some("Invalid model: eq_obj1id out of bounds.");
        }
        if o2 >= n || o2 < min2 {
            return Some("Invalid model: eq_obj2id out of bounds.");
        }
    }
    for i in 0..m.nwrap.max(0) as usize {
        let n = match mv.wrap_type()[i] {
            1 => m.njnt,
            3 => m.nsite,
            4 | 5 => m.ngeom,
            _ => continue,
        };
        let id = mv.wrap_objid()[i];
        if id >= n || id < 0 {
            return Some("Invalid model: wrap_objid out of bounds.");
        }
    }
    for i in 0..m.nu.max(0) as usize {
        let (id, slider) = (mv.actuator_trnid()[2 * i], mv.actuator_trnid()[2 * i + 1]);
        let bad = |id: i32, n: i32| id < 0 || id >= n;
        let out = match mv.actuator_trntype()[i] {
            0 | 1 => bad(id, m.njnt),
            3 => bad(id, m.ntendon),
            4 => bad(id, m.nsite),
            2 => bad(id, m.nsite) || bad(slider, m.nsite),
            _ => false,
        };
        if out {
            return Some("Invalid model: actuator_trnid out of bounds.");
        }
    }
    for i in 0..m.nsensor.max(0) as usize {
        let size = sensor_size(mv.sensor_type()[i], m.nuser_sensor);
        if size < 0 {
            return Some("Invalid model: Bad sensor_type.");
        }
        let adr = mv.sensor_adr()[i];
        if adr < 0 || adr as i64 + size as i64 > m.nsensordata as i64 {
            return Some("Invalid model: sensor_adr out of bounds.");
        }
        let nobj = num_objects(m, mv.sensor_objtype()[i]);
        if nobj == -2 {
            return Some("Invalid model: invalid sensor_objtype");
        }
        let id = mv.sensor_objid()[i];
        if nobj != -1 && (id < 0 || id >= nobj) {
            return Some("Invalid model: invalid sensor_objid");
        }
        let nref = num_objects(m, mv.sensor_reftype()[i]);
        if nref == -2 {
            return Some("Invalid model: invalid sensor_reftype");
        }
        let rid = mv.sensor_refid()[i];
        if nref != -1 && (rid < -1 || rid >= nref) {
            return Some("Invalid model: invalid sensor_refid");
        }
    }
    for &sig in mv.exclude_signature() {
        let (b1, b2) = body_pair(sig);
        if b1 >= m.nbody || b1 < 0 {
            return Some("Invalid model: exclude_body1 out of bounds.");
        }
        if b2 >= m.nbody || b2 < 0 {
            return Some("Invalid model: exclude_body2 out of bounds.");
        }
    }
    for i in 0..m.ntuple.max(0) as usize {
        let size = mv.tuple_size()[i];
        if size > 0 && mv.tuple_adr()[i] < 0 {
            return Some("Invalid model: tuple_adr out of bounds.");
        }
        for j in 0..size.max(0) as usize {
            let adr = mv.tuple_adr()[i] as usize + j;
            let nobj = num_objects(m, mv.tuple_objtype()[adr]);
            if nobj == -2 {
                return Some("Invalid model: invalid tuple_objtype");
            }
            let id = mv.tuple_objid()[adr];
            if nobj != -1 && (id < 0 || id >= nobj) {
                return Some("Invalid model: invalid tuple_objid");
            }
        }
    }
    None
}
