//! Cross-checks of a model read from outside (MJB files) beyond 2.2.2's reference checks: every
//! size agrees with the arrays that define it, every enum is in range and every index or address
//! the engine follows stays inside its array. 2.2.2 trusts these and may crash; we refuse the
//! model at load with the field named.

use super::validate::joint_sizes;
use super::view::Model;

/// Builds the refusal message.
fn bad(what: &str) -> String {
    format!("Invalid model: {what}.")
}

/// `v` in `lo..hi` (as i64, so that no sum overflows).
fn within(v: i64, lo: i64, hi: i64) -> bool {
    v >= lo && v < hi
}

/// Every value of `vals` in `lo..hi`, else the field's name (by the least and the greatest:
/// one pass without a branch per value).
fn all_within(vals: &[i32], lo: i64, hi: i64, what: &str) -> Result<(), String> {
    let (least, most) = vals
        .iter()
        .fold((i32::MAX, i32::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    match vals.is_empty() || (within(least as i64, lo, hi) && within(most as i64, lo, hi)) {
        true => Ok(()),
        false => Err(bad(&format!("{what} out of range"))),
    }
}

/// The model's first inconsistency, if any.
pub fn check(mv: Model) -> Result<(), String> {
    sizes(&mv)?;
    ids(&mv)?;
    enums(&mv)?;
    tree(&mv)?;
    meshes(&mv)?;
    skins(&mv)?;
    tendons(&mv)?;
    actuators(&mv)?;
    data_ranges(&mv)?;
    Ok(())
}

fn sizes(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    let data_sizes = [
        (m.nmocap, "nmocap"),
        (m.na, "na"),
        (m.nM, "nM"),
        (m.nemax, "nemax"),
        (m.njmax, "njmax"),
        (m.nconmax, "nconmax"),
        (m.nstack, "nstack"),
        (m.nuserdata, "nuserdata"),
        (m.nsensordata, "nsensordata"),
        (m.nnames, "nnames"),
    ];
    for (v, name) in data_sizes {
        if v < 0 {
            return Err(bad(&format!("m->{name} is negative")));
        }
    }
    Ok(())
}

/// Ids that name an object that must exist (2.2.2's reference check lets -1 through).
fn ids(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    let (nbody, njnt, ngeom) = (m.nbody as i64, m.njnt as i64, m.ngeom as i64);
    let required: [(&[i32], i64, &str); 14] = [
        (mv.body_parentid(), nbody, "body_parentid"),
        (mv.body_rootid(), nbody, "body_rootid"),
        (mv.body_weldid(), nbody, "body_weldid"),
        (mv.jnt_bodyid(), nbody, "jnt_bodyid"),
        (mv.dof_bodyid(), nbody, "dof_bodyid"),
        (mv.dof_jntid(), njnt, "dof_jntid"),
        (mv.geom_bodyid(), nbody, "geom_bodyid"),
        (mv.site_bodyid(), nbody, "site_bodyid"),
        (mv.cam_bodyid(), nbody, "cam_bodyid"),
        (mv.light_bodyid(), nbody, "light_bodyid"),
        (mv.skin_bonebodyid(), nbody, "skin_bonebodyid"),
        (mv.pair_geom1(), ngeom, "pair_geom1"),
        (mv.pair_geom2(), ngeom, "pair_geom2"),
        (mv.eq_obj1id(), i64::MAX, "eq_obj1id"),
    ];
    for (vals, n, name) in required {
        all_within(vals, 0, n, name)?;
    }
    // an address of a non-empty span points somewhere (2.2.2 lets -1 through)
    let spans: [(&[i32], &[i32], &str); 10] = [
        (mv.body_jntadr(), mv.body_jntnum(), "body_jntadr"),
        (mv.body_dofadr(), mv.body_dofnum(), "body_dofadr"),
        (mv.body_geomadr(), mv.body_geomnum(), "body_geomadr"),
        (mv.mesh_vertadr(), mv.mesh_vertnum(), "mesh_vertadr"),
        (mv.mesh_faceadr(), mv.mesh_facenum(), "mesh_faceadr"),
        (mv.skin_vertadr(), mv.skin_vertnum(), "skin_vertadr"),
        (mv.skin_faceadr(), mv.skin_facenum(), "skin_faceadr"),
        (mv.skin_boneadr(), mv.skin_bonenum(), "skin_boneadr"),
        (
            mv.skin_bonevertadr(),
            mv.skin_bonevertnum(),
            "skin_bonevertadr",
        ),
        (mv.tuple_adr(), mv.tuple_size(), "tuple_adr"),
    ];
    for (adr, num, name) in spans {
        if adr.iter().zip(num).any(|(&a, &n)| n > 0 && a < 0) {
            return Err(bad(&format!("{name} out of bounds")));
        }
    }
    Ok(())
}

fn enums(mv: &Model) -> Result<(), String> {
    let o = &mv.raw.opt;
    let opts = [
        (o.integrator, 3, "opt.integrator"),
        (o.collision, 3, "opt.collision"),
        (o.cone, 2, "opt.cone"),
        (o.jacobian, 3, "opt.jacobian"),
        (o.solver, 3, "opt.solver"),
    ];
    for (v, n, name) in opts {
        if !within(v as i64, 0, n) {
            return Err(bad(&format!("{name} out of range")));
        }
    }
    all_within(mv.geom_type(), 0, 8, "geom_type")?;
    all_within(mv.site_type(), 0, 8, "site_type")?;
    all_within(mv.cam_mode(), 0, 5, "cam_mode")?;
    all_within(mv.light_mode(), 0, 5, "light_mode")?;
    all_within(mv.tex_type(), 0, 3, "tex_type")?;
    all_within(mv.eq_type(), 0, 5, "eq_type")?;
    all_within(mv.wrap_type(), 0, 6, "wrap_type")?;
    all_within(mv.actuator_trntype(), 0, 6, "actuator_trntype")?;
    all_within(mv.actuator_dyntype(), 0, 5, "actuator_dyntype")?;
    all_within(mv.actuator_gaintype(), 0, 4, "actuator_gaintype")?;
    all_within(mv.actuator_biastype(), 0, 4, "actuator_biastype")?;
    all_within(mv.sensor_datatype(), 0, 4, "sensor_datatype")?;
    all_within(mv.sensor_needstage(), 0, 4, "sensor_needstage")?;
    all_within(mv.geom_condim(), 1, 7, "geom_condim")?;
    all_within(mv.pair_dim(), 1, 7, "pair_dim")?;
    Ok(())
}

/// Joints, dofs and bodies: qpos/qvel layout, the dof tree and the sparse inertia addresses.
fn tree(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    let (mut nq, mut nv) = (0i64, 0i64);
    for j in 0..m.njnt.max(0) as usize {
        let (jq, jv) = joint_sizes(mv.jnt_type()[j]).ok_or_else(|| bad("jnt_type out of range"))?;
        if mv.jnt_qposadr()[j] as i64 != nq || mv.jnt_dofadr()[j] as i64 != nv {
            return Err(bad("jnt_qposadr or jnt_dofadr inconsistent with jnt_type"));
        }
        nq += jq as i64;
        nv += jv as i64;
    }
    if nq != m.nq as i64 || nv != m.nv as i64 {
        return Err(bad("nq or nv inconsistent with the joints"));
    }
    let nbody = m.nbody.max(0) as usize;
    for b in 1..nbody {
        if mv.body_parentid()[b] as usize >= b {
            return Err(bad("body_parentid not before the body"));
        }
    }
    let mut mocap_seen = vec![false; m.nmocap as usize];
    for &id in mv.body_mocapid() {
        if id >= 0 {
            let seen = &mut mocap_seen[id as usize];
            if *seen {
                return Err(bad("body_mocapid repeated"));
            }
            *seen = true;
        }
    }
    // the dof tree: parents first; each row of the sparse inertia holds the dof and its
    // ancestors, at consecutive addresses
    let mut madr = 0i64;
    for i in 0..m.nv.max(0) as usize {
        let p = mv.dof_parentid()[i];
        if p >= i as i32 {
            return Err(bad("dof_parentid not before the dof"));
        }
        // depth-first: a dof's parent is the dof before it or one of that dof's ancestors
        // (each subtree a run of dofs, as the compiler numbers them; the factorization's
        // pull relies on it)
        if p >= 0 && !ancestor_or_self(mv, p as usize, i - 1) {
            return Err(bad("dof_parentid not in depth-first order"));
        }
        let depth = if p < 0 {
            1
        } else {
            1 + ancestors(mv, p as usize)
        };
        if mv.dof_Madr()[i] as i64 != madr {
            return Err(bad("dof_Madr inconsistent with dof_parentid"));
        }
        madr += depth;
        let left = (m.nv as i64) - i as i64;
        if !within(mv.dof_simplenum()[i] as i64, 0, left + 1) {
            return Err(bad("dof_simplenum out of range"));
        }
        let jnt = mv.dof_jntid()[i] as usize;
        if mv.jnt_bodyid()[jnt] != mv.dof_bodyid()[i] {
            return Err(bad("dof_bodyid inconsistent with dof_jntid"));
        }
    }
    if madr != m.nM as i64 {
        return Err(bad("nM inconsistent with dof_parentid"));
    }
    Ok(())
}

/// Is dof `a` dof `i` or one of its ancestors? (Parents come first, so this ends.)
fn ancestor_or_self(mv: &Model, a: usize, mut i: usize) -> bool {
    while i > a {
        match mv.dof_parentid()[i] {
            p if p < 0 => return false,
            p => i = p as usize,
        }
    }
    i == a
}

/// Number of ancestors of dof `i`, itself included (the parents come first, so this ends).
fn ancestors(mv: &Model, mut i: usize) -> i64 {
    let mut n = 1;
    while mv.dof_parentid()[i] >= 0 {
        i = mv.dof_parentid()[i] as usize;
        n += 1;
    }
    n
}

fn meshes(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    for k in 0..m.nmesh.max(0) as usize {
        let nvert = mv.mesh_vertnum()[k] as i64;
        let (fadr, fnum) = (mv.mesh_faceadr()[k] as usize, mv.mesh_facenum()[k] as usize);
        all_within(
            &mv.mesh_face()[3 * fadr..3 * (fadr + fnum)],
            0,
            nvert,
            "mesh_face",
        )?;
        let tadr = mv.mesh_texcoordadr()[k] as i64;
        if tadr >= 0 && tadr + nvert > m.nmeshtexvert as i64 {
            return Err(bad("mesh_texcoordadr out of bounds"));
        }
        let gadr = mv.mesh_graphadr()[k];
        if gadr >= 0 {
            graph(&mv.mesh_graph()[gadr as usize..], nvert)?;
        }
    }
    Ok(())
}

/// A convex hull graph: numvert, numface, vert_edgeadr[numvert], vert_globalid[numvert],
/// edge_localid[numvert + 3 numface], face_globalid[3 numface].
fn graph(g: &[i32], nvert: i64) -> Result<(), String> {
    let err = || bad("mesh_graph out of range");
    if g.len() < 2 || g[0] < 0 || g[1] < 0 {
        return Err(err());
    }
    let (nv, nf) = (g[0] as i64, g[1] as i64);
    let nedge = nv + 3 * nf;
    let len = 2 + 2 * nv + nedge + 3 * nf;
    if len > g.len() as i64 {
        return Err(err());
    }
    let (nv, nedge) = (nv as usize, nedge as usize);
    let edgeadr = &g[2..2 + nv];
    let globalid = &g[2 + nv..2 + 2 * nv];
    let edges = &g[2 + 2 * nv..2 + 2 * nv + nedge];
    let faces = &g[2 + 2 * nv + nedge..len as usize];
    all_within(edgeadr, 0, nedge as i64, "mesh_graph")?;
    all_within(globalid, 0, nvert, "mesh_graph")?;
    all_within(edges, -1, nv as i64, "mesh_graph")?;
    all_within(faces, 0, nvert, "mesh_graph")?;
    Ok(())
}

fn skins(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    for k in 0..m.nskin.max(0) as usize {
        let nvert = mv.skin_vertnum()[k] as i64;
        let (fadr, fnum) = (mv.skin_faceadr()[k] as usize, mv.skin_facenum()[k] as usize);
        all_within(
            &mv.skin_face()[3 * fadr..3 * (fadr + fnum)],
            0,
            nvert,
            "skin_face",
        )?;
        let tadr = mv.skin_texcoordadr()[k] as i64;
        if tadr >= 0 && tadr + nvert > m.nskintexvert as i64 {
            return Err(bad("skin_texcoordadr out of bounds"));
        }
        let (badr, bnum) = (mv.skin_boneadr()[k] as usize, mv.skin_bonenum()[k] as usize);
        for b in badr..badr + bnum {
            let (vadr, vnum) = (
                mv.skin_bonevertadr()[b] as usize,
                mv.skin_bonevertnum()[b] as usize,
            );
            all_within(
                &mv.skin_bonevertid()[vadr..vadr + vnum],
                0,
                nvert,
                "skin_bonevertid",
            )?;
        }
    }
    Ok(())
}

/// Tendon paths: inside the wrap arrays; in a spatial path a pulley is followed by a site, a
/// geom sits between two sites, and side sites are sites.
fn tendons(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    let (wtype, wprm) = (mv.wrap_type(), mv.wrap_prm());
    for t in 0..m.ntendon.max(0) as usize {
        let (adr, num) = (mv.tendon_adr()[t] as i64, mv.tendon_num()[t] as i64);
        if adr < 0 || num < 0 || adr + num > m.nwrap as i64 {
            return Err(bad("tendon_adr out of bounds"));
        }
        let (adr, num) = (adr as usize, num as usize);
        let path = &wtype[adr..adr + num];
        // 1 joint, 2 pulley, 3 site, 4 sphere, 5 cylinder
        if path.contains(&1) {
            if path.iter().any(|&w| w != 1) {
                return Err(bad("tendon mixes joints and spatial wraps"));
            }
            continue;
        }
        for (k, &w) in path.iter().enumerate() {
            let prev = if k > 0 { path[k - 1] } else { 0 };
            let next = path.get(k + 1).copied().unwrap_or(0);
            let ok = match w {
                2 => next == 3,
                3 => true,
                4 | 5 => prev == 3 && next == 3,
                _ => false,
            };
            if !ok {
                return Err(bad("tendon path out of order"));
            }
            if w >= 4 {
                let side = wprm[adr + k];
                if !(side >= -1.0 && side < m.nsite as f64) || side != side.trunc() {
                    return Err(bad("wrap_prm side site out of range"));
                }
            }
        }
    }
    Ok(())
}

/// Stateful actuators come last, one activation each: act index = i - (nu - na).
fn actuators(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    let dyn_ = mv.actuator_dyntype();
    let stateful = dyn_.iter().filter(|&&d| d != 0).count() as i64;
    if stateful != m.na as i64 {
        return Err(bad("na inconsistent with actuator_dyntype"));
    }
    let first = m.nu.max(0) as usize - stateful as usize;
    if dyn_[first..].contains(&0) {
        return Err(bad("stateless actuator after a stateful one"));
    }
    for i in 0..m.nu.max(0) as usize {
        // slider-crank: the second id is the slider site
        if mv.actuator_trntype()[i] == 2 {
            let s = mv.actuator_trnid()[2 * i + 1];
            if !within(s as i64, 0, m.nsite as i64) {
                return Err(bad("actuator_trnid out of bounds"));
            }
        }
    }
    Ok(())
}

/// Custom data, text and names: addresses and sizes inside their arrays, names terminated.
fn data_ranges(mv: &Model) -> Result<(), String> {
    let m = mv.raw;
    let spans = [
        (
            mv.numeric_adr(),
            mv.numeric_size(),
            m.nnumericdata,
            "numeric_adr",
        ),
        (mv.text_adr(), mv.text_size(), m.ntextdata, "text_adr"),
    ];
    for (adr, size, total, name) in spans {
        for (&a, &s) in adr.iter().zip(size) {
            if a < 0 || s < 0 || a as i64 + s as i64 > total as i64 {
                return Err(bad(&format!("{name} out of bounds")));
            }
        }
    }
    let nnames = m.nnames as i64;
    if nnames > 0 && mv.names()[nnames as usize - 1] != 0 {
        return Err(bad("names not terminated"));
    }
    let name_adrs = [
        mv.name_bodyadr(),
        mv.name_jntadr(),
        mv.name_geomadr(),
        mv.name_siteadr(),
        mv.name_camadr(),
        mv.name_lightadr(),
        mv.name_meshadr(),
        mv.name_skinadr(),
        mv.name_hfieldadr(),
        mv.name_texadr(),
        mv.name_matadr(),
        mv.name_pairadr(),
        mv.name_excludeadr(),
        mv.name_eqadr(),
        mv.name_tendonadr(),
        mv.name_actuatoradr(),
        mv.name_sensoradr(),
        mv.name_numericadr(),
        mv.name_textadr(),
        mv.name_tupleadr(),
        mv.name_keyadr(),
    ];
    for adrs in name_adrs {
        all_within(adrs, 0, nnames.max(1), "name address")?;
    }
    Ok(())
}
