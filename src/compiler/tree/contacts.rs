//! Contact pairs and exclusions, sorted by body signature, and their arrays.

use super::*;

/// Pairs as (pair, geom ids, body signature), excludes as (name, body signature).
#[allow(clippy::type_complexity)]
pub(super) fn compile(
    pair_specs: Vec<Pair>,
    exclude_specs: Vec<Exclude>,
    geoms: &[FGeom],
    bodies: &[FBody],
) -> Result<(Vec<(Pair, [i32; 2], i32)>, Vec<(String, i32)>), CError> {
    let signature = |b1: usize, b2: usize| (((b1 + 1) << 16) + b2 + 1) as i32;
    let mut pairs = Vec::new();
    for (id, p) in pair_specs.into_iter().enumerate() {
        let perr = |m: String| CError::at(m, &p.name, id, p.line);
        if ![1, 3, 4, 6].contains(&p.condim) {
            return Err(perr(format!("invalid condim in collision {id}")));
        }
        let find = |n: &str| geoms.iter().position(|g| g.spec.name == n);
        let Some(mut g1) = find(&p.geom1) else {
            return Err(perr(format!(
                "geom '{}' not found in collision {id}",
                p.geom1
            )));
        };
        let Some(mut g2) = find(&p.geom2) else {
            return Err(perr(format!(
                "geom '{}' not found in collision {id}",
                p.geom2
            )));
        };
        if geoms[g1].body > geoms[g2].body {
            std::mem::swap(&mut g1, &mut g2);
        }
        let sig = signature(geoms[g1].body, geoms[g2].body);
        pairs.push((p, [g1 as i32, g2 as i32], sig));
    }
    let mut excludes = Vec::new();
    for (id, e) in exclude_specs.into_iter().enumerate() {
        let find = |n: &str| find_body(bodies, n);
        let missing = |n: &str| {
            CError::at(
                format!("body '{n}' not found in bodypair {id}"),
                &e.name,
                id,
                e.line,
            )
        };
        let b1 = find(&e.body1).ok_or_else(|| missing(&e.body1))?;
        let b2 = find(&e.body2).ok_or_else(|| missing(&e.body2))?;
        excludes.push((e.name.clone(), signature(b1.min(b2), b1.max(b2))));
    }
    pairs.sort_by_key(|p| p.2);
    excludes.sort_by_key(|e| e.1);
    Ok((pairs, excludes))
}

impl Compiled {
    pub(super) fn fill_contacts(&self, m: &mut ModelMut) {
        for (i, (p, g, sig)) in self.pairs.iter().enumerate() {
            m.pair_dim[i] = p.condim;
            m.pair_geom1[i] = g[0];
            m.pair_geom2[i] = g[1];
            m.pair_signature[i] = *sig;
            put(m.pair_solref, i, &p.solref);
            put(m.pair_solimp, i, &p.solimp);
            m.pair_margin[i] = p.margin;
            m.pair_gap[i] = p.gap;
            put(m.pair_friction, i, &p.friction);
        }
        for (i, e) in self.excludes.iter().enumerate() {
            m.exclude_signature[i] = e.1;
        }
    }
}
