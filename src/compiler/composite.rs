//! `<composite>`: expands into ordinary bodies, joints, geoms, sites, tendons, equality
//! constraints, excludes and a skin of the model description.

use super::spec::*;

/// Composite types, in MJCF keyword order.
pub const TYPES: [&str; 8] = [
    "particle",
    "grid",
    "rope",
    "loop",
    "cloth",
    "box",
    "cylinder",
    "ellipsoid",
];
const PARTICLE: usize = 0;
const GRID: usize = 1;
const ROPE: usize = 2;
const LOOP: usize = 3;
const CLOTH: usize = 4;
const BOX: usize = 5;
const CYLINDER: usize = 6;

/// Element kinds: joint main, twist, stretch; tendon main, shear.
pub const JOINT: usize = 0;
pub const TWIST: usize = 1;
pub const STRETCH: usize = 2;
pub const TENDON: usize = 3;
pub const SHEAR: usize = 4;

/// Skin requested by a composite.
#[derive(Debug, Clone)]
pub struct CompSkin {
    pub texcoord: bool,
    pub material: String,
    pub rgba: [f32; 4],
    pub inflate: f32,
    pub subgrid: i32,
    pub group: i32,
}

impl Default for CompSkin {
    fn default() -> Self {
        CompSkin {
            texcoord: false,
            material: String::new(),
            rgba: [1.0; 4],
            inflate: 0.0,
            subgrid: 0,
            group: 0,
        }
    }
}

/// A `<composite>` element as read.
#[derive(Debug, Clone)]
pub struct Composite {
    pub prefix: String,
    pub kind: usize,
    pub count: [i32; 3],
    pub spacing: f64,
    pub offset: [f64; 3],
    pub pin: Vec<i32>,
    pub flatinertia: f64,
    pub solref_smooth: [f64; 2],
    pub solimp_smooth: [f64; 5],
    pub skin: Option<CompSkin>,
    /// which element kinds are requested
    pub add: [bool; 5],
    pub geom: Geom,
    pub site: Site,
    pub joints: [Joint; 5],
    pub tendons: [Tendon; 5],
    pub equalities: [Equality; 5],
}

impl Default for Composite {
    fn default() -> Self {
        let eq = Equality::default();
        Composite {
            prefix: String::new(),
            kind: 0,
            count: [1; 3],
            spacing: 0.0,
            offset: [0.0; 3],
            pin: Vec::new(),
            flatinertia: 0.0,
            solref_smooth: eq.solref,
            solimp_smooth: eq.solimp,
            skin: None,
            add: [false; 5],
            geom: Geom::default(),
            site: Site::default(),
            joints: Default::default(),
            tendons: Default::default(),
            equalities: Default::default(),
        }
    }
}

/// Objects outside the body tree that composites add to the model.
#[derive(Debug, Default)]
pub struct Added {
    pub tendons: Vec<Tendon>,
    pub equalities: Vec<Equality>,
    pub excludes: Vec<Exclude>,
    pub skins: Vec<Skin>,
}

fn soften(solref: &mut [f64; 2], solimp: &mut [f64; 5], hard: bool) {
    let (r, i) = if hard { (0.01, 0.99) } else { (0.02, 0.9) };
    solref[0] = r;
    solimp[0] = i;
    solimp[1] = i;
}

impl Composite {
    /// Type-specific defaults, set once the type and skin are known.
    pub fn set_defaults(&mut self) {
        let dim = self.count.iter().filter(|&&c| c > 1).count();
        let visible = self.skin.is_none()
            || matches!(self.kind, PARTICLE | ROPE | LOOP)
            || (self.kind == GRID && dim == 1);
        let group = if visible { 0 } else { 3 };
        self.geom.group = group;
        self.site.group = 3;
        for j in self.joints.iter_mut() {
            j.group = 3;
        }
        for t in self.tendons.iter_mut() {
            t.group = group;
        }
        match self.kind {
            PARTICLE => {
                self.geom.condim = 1;
                self.geom.priority = 1;
            }
            GRID => {
                let e = &mut self.equalities[TENDON];
                soften(&mut e.solref, &mut e.solimp, true);
            }
            LOOP => soften(&mut self.solref_smooth, &mut self.solimp_smooth, true),
            BOX..=7 => {
                self.geom.contype = 0;
                soften(&mut self.solref_smooth, &mut self.solimp_smooth, false);
                for e in self.equalities.iter_mut() {
                    soften(&mut e.solref, &mut e.solimp, false);
                }
                let e = &mut self.equalities[TENDON];
                soften(&mut e.solref, &mut e.solimp, true);
            }
            _ => {}
        }
    }
}

/// Generated bodies: each with the index of its parent (None: the composite's body).
struct Gen<'a> {
    c: &'a Composite,
    root: &'a mut Body,
    nodes: Vec<(Option<usize>, Body)>,
    out: &'a mut Added,
    main_eq: &'a Equality,
}

impl Gen<'_> {
    fn body(&mut self, b: Option<usize>) -> &mut Body {
        match b {
            None => self.root,
            Some(i) => &mut self.nodes[i].1,
        }
    }

    fn add_body(&mut self, parent: Option<usize>, name: String, pos: [f64; 3]) -> usize {
        self.nodes.push((
            parent,
            Body {
                name,
                pos,
                ..Body::default()
            },
        ));
        self.nodes.len() - 1
    }

    fn geom(&self, name: String) -> Geom {
        Geom {
            name,
            ..self.c.geom.clone()
        }
    }

    fn site(&self, name: String) -> Site {
        Site {
            name,
            kind: 2,
            ..self.c.site.clone()
        }
    }

    fn joint(
        &self,
        kind: usize,
        name: String,
        jt: JointType,
        pos: [f64; 3],
        axis: [f64; 3],
    ) -> Joint {
        Joint {
            name,
            kind: jt,
            pos,
            axis,
            ..self.c.joints[kind].clone()
        }
    }

    /// Equality constraint on one joint or tendon, from the element kind's settings.
    fn fix(&mut self, kind: usize, eqtype: i32, name1: String) {
        self.out.equalities.push(Equality {
            kind: eqtype,
            name1,
            ..self.c.equalities[kind].clone()
        });
    }

    fn tendon(&mut self, kind: usize, name: String, path: Vec<Wrap>) {
        self.out.tendons.push(Tendon {
            name,
            path,
            ..self.c.tendons[kind].clone()
        });
    }

    /// Puts the generated bodies into the tree, keeping creation order among siblings.
    fn finish(self) {
        let n = self.nodes.len();
        let mut kids: Vec<Vec<Body>> = (0..n).map(|_| Vec::new()).collect();
        let mut top = Vec::new();
        let mut nodes = self.nodes;
        while let Some((parent, mut b)) = nodes.pop() {
            let k = nodes.len();
            let mut ch = std::mem::take(&mut kids[k]);
            ch.reverse();
            b.bodies.extend(ch);
            match parent {
                Some(p) => kids[p].push(b),
                None => top.push(b),
            }
        }
        top.reverse();
        self.root.bodies.extend(top);
    }
}

fn site_wrap(name: String) -> Wrap {
    Wrap {
        kind: 3,
        name,
        ..Wrap::default()
    }
}

/// Expands the composite into `body` and `out`; Err: 2.2.2's message.
pub fn expand(
    c: &Composite,
    body: &mut Body,
    global: bool,
    main_eq: &Equality,
    out: &mut Added,
) -> Result<(), String> {
    if global {
        return Err("Composite requires local coordinates".into());
    }
    if !(2..=4).contains(&c.geom.kind) {
        return Err("Composite geom type must be sphere, capsule or ellipsoid".into());
    }
    if !c.pin.len().is_multiple_of(2) {
        return Err("Pin coordinate number of must be multiple of 2".into());
    }
    if c.count.iter().any(|&n| n < 1) {
        return Err("Positive counts expected in composite".into());
    }
    if c.spacing < 1e-15 {
        return Err("Positive spacing expected in composite".into());
    }
    let mut dim = 0;
    let mut single = false;
    for &n in &c.count {
        if n == 1 {
            single = true;
        } else {
            dim += 1;
            if single {
                return Err("Singleton counts must come last".into());
            }
        }
    }
    if let Some(s) = &c.skin {
        if s.subgrid > 0 && (c.count[0] < 3 || c.count[1] < 3) {
            return Err("At least 3x3 required for skin subgrid".into());
        }
    }
    let mut g = Gen {
        c,
        root: body,
        nodes: Vec::new(),
        out,
        main_eq,
    };
    match c.kind {
        PARTICLE => particle(&mut g),
        GRID => grid(&mut g, dim)?,
        ROPE | LOOP => rope(&mut g, dim)?,
        CLOTH => cloth(&mut g, dim)?,
        _ => solid(&mut g, dim)?,
    }
    g.finish();
    Ok(())
}

fn particle(g: &mut Gen) {
    let c = g.c;
    let n = c.count;
    for ix in 0..n[0] {
        for iy in 0..n[1] {
            for iz in 0..n[2] {
                let idx = [ix, iy, iz];
                let pos: [f64; 3] = std::array::from_fn(|k| {
                    c.offset[k] + c.spacing * (idx[k] as f64 - 0.5 * n[k] as f64)
                });
                let b = g.add_body(None, String::new(), pos);
                for k in 0..3 {
                    let mut axis = [0.0; 3];
                    axis[k] = 1.0;
                    let j = g.joint(JOINT, String::new(), JointType::Slide, [0.0; 3], axis);
                    g.nodes[b].1.joints.push(j);
                }
                let mut geom = g.geom(String::new());
                geom.kind = 2;
                g.nodes[b].1.geoms.push(geom);
            }
        }
    }
}

fn grid(g: &mut Gen, dim: usize) -> Result<(), String> {
    let c = g.c;
    let p = &c.prefix;
    if dim > 2 {
        return Err("Grid can only be 1D or 2D".into());
    }
    if c.add[SHEAR] && dim != 2 {
        return Err("Shear requires 2D grid".into());
    }
    if c.skin.is_some() && dim != 2 {
        return Err("Skin requires 2D grid".into());
    }
    let n = c.count;
    for ix in 0..n[0] {
        for iy in 0..n[1] {
            let pos = [
                c.offset[0] + c.spacing * (ix as f64 - 0.5 * n[0] as f64),
                c.offset[1] + c.spacing * (iy as f64 - 0.5 * n[1] as f64),
                c.offset[2],
            ];
            let b = g.add_body(None, format!("{p}B{ix}_{iy}"), pos);
            let mut geom = g.geom(format!("{p}G{ix}_{iy}"));
            geom.kind = 2;
            let site = g.site(format!("{p}S{ix}_{iy}"));
            g.nodes[b].1.geoms.push(geom);
            g.nodes[b].1.sites.push(site);
            if c.pin.chunks(2).any(|q| q[0] == ix && q[1] == iy) {
                continue;
            }
            for k in 0..3 {
                let mut axis = [0.0; 3];
                axis[k] = 1.0;
                let j = g.joint(
                    JOINT,
                    format!("{p}J{k}_{ix}_{iy}"),
                    JointType::Slide,
                    [0.0; 3],
                    axis,
                );
                g.nodes[b].1.joints.push(j);
            }
        }
    }
    for i in 0..2 {
        let (sx, sy) = ((i == 0) as i32, (i == 1) as i32);
        for ix in 0..n[0] - sx {
            for iy in 0..n[1] - sy {
                let name = format!("{p}T{i}_{ix}_{iy}");
                let path = vec![
                    site_wrap(format!("{p}S{ix}_{iy}")),
                    site_wrap(format!("{p}S{}_{}", ix + sx, iy + sy)),
                ];
                g.tendon(TENDON, name.clone(), path);
                g.fix(TENDON, 3, name);
            }
        }
    }
    if c.add[SHEAR] {
        shear(g);
    }
    if let Some(s) = &c.skin {
        let skin = if s.subgrid > 0 {
            super::composite_skin::grid_subgrid(c, s)?
        } else {
            super::composite_skin::grid(c, s)
        };
        g.out.skins.push(skin);
    }
    Ok(())
}

fn shear(g: &mut Gen) {
    let c = g.c;
    let p = &c.prefix;
    for ix in 0..c.count[0] - 1 {
        for iy in 0..c.count[1] - 1 {
            let name = format!("{p}TS{ix}_{iy}");
            let path = vec![
                site_wrap(format!("{p}S{ix}_{iy}")),
                site_wrap(format!("{p}S{}_{}", ix + 1, iy + 1)),
            ];
            g.tendon(SHEAR, name.clone(), path);
            g.fix(SHEAR, 3, name);
        }
    }
}

/// Leading decimal integer of `s` as `sscanf("%d")` reads it, and the rest.
fn scan_int(s: &str) -> Option<(i32, &str)> {
    let t = s.trim_start();
    let neg = t.starts_with('-');
    let body = t.strip_prefix(['-', '+']).unwrap_or(t);
    let len = body.bytes().take_while(|b| b.is_ascii_digit()).count();
    if len == 0 {
        return None;
    }
    let v = body[..len].parse::<i64>().unwrap_or(i64::MAX);
    let v = if neg { -v } else { v };
    Some((v as i32, &body[len..]))
}

/// The root body name's text after "{prefix}B", or the error 2.2.2 gives.
fn root_coords<'a>(c: &Composite, name: &'a str) -> Result<&'a str, String> {
    let head = format!("{}B", c.prefix);
    match name.strip_prefix(head.as_str()) {
        Some(rest) => Ok(rest),
        None => Err(format!("{head} must be the beginning of root body name")),
    }
}

fn rope(g: &mut Gen, dim: usize) -> Result<(), String> {
    let c = g.c;
    if dim != 1 {
        return Err("Rope must be one-dimensional".into());
    }
    let rest = root_coords(c, &g.root.name)?;
    let ox = match scan_int(rest) {
        Some((v, _)) => v,
        None => return Err("Root body name must contain X coordinate".into()),
    };
    if ox < 0 || ox >= c.count[0] {
        return Err("Root body coordinate out of range".into());
    }
    rope_body(g, None, ox, ox);
    let mut parent = None;
    for ix in ox..c.count[0] - 1 {
        parent = Some(rope_body(g, parent, ix, ix + 1));
    }
    parent = None;
    for ix in (1..=ox).rev() {
        parent = Some(rope_body(g, parent, ix, ix - 1));
    }
    if c.kind == LOOP {
        let p = &c.prefix;
        let (b1, b2) = (format!("{p}B0"), format!("{p}B{}", c.count[0] - 1));
        let mut eq = Equality {
            kind: 0,
            name1: b1.clone(),
            name2: b2.clone(),
            solref: c.solref_smooth,
            solimp: c.solimp_smooth,
            line: -1,
            ..g.main_eq.clone()
        };
        eq.data[..3].copy_from_slice(&[-0.5 * c.spacing, 0.0, 0.0]);
        g.out.equalities.push(eq);
        g.out.excludes.push(Exclude {
            body1: b1,
            body2: b2,
            ..Exclude::default()
        });
    }
    Ok(())
}

/// Adds rope element `ix1` as a child of `parent` (the root itself when `ix == ix1`).
fn rope_body(g: &mut Gen, parent: Option<usize>, ix: i32, ix1: i32) -> usize {
    let c = g.c;
    let p = &c.prefix;
    let root = ix == ix1;
    let dx = c.spacing * (ix1 - ix) as f64;
    let mut b = parent;
    if !root {
        let i = g.add_body(parent, format!("{p}B{ix1}"), [dx, 0.0, 0.0]);
        if c.kind == LOOP {
            let alpha = 2.0 * std::f64::consts::PI / c.count[0] as f64;
            let r = 0.5 * c.spacing * (std::f64::consts::PI - alpha).sin() / (0.5 * alpha).sin();
            let s = if ix1 > ix { 1.0 } else { -1.0 };
            let body = &mut g.nodes[i].1;
            body.pos = [s * r * (0.5 * alpha).cos(), r * (0.5 * alpha).sin(), 0.0];
            body.quat = [(s * 0.5 * alpha).cos(), 0.0, 0.0, (s * 0.5 * alpha).sin()];
        }
        b = Some(i);
    }
    let mut geom = g.geom(format!("{p}G{ix1}"));
    geom.pos = [0.0; 3];
    geom.quat = [0.5f64.sqrt(), 0.0, 0.5f64.sqrt(), 0.0];
    g.body(b).geoms.push(geom);
    if root {
        return usize::MAX;
    }
    let jpos = [-0.5 * dx, 0.0, 0.0];
    for i in 0..2 {
        let mut axis = [0.0; 3];
        axis[i + 1] = 1.0;
        let j = g.joint(
            JOINT,
            format!("{p}J{i}_{ix1}"),
            JointType::Hinge,
            jpos,
            axis,
        );
        g.body(b).joints.push(j);
    }
    if c.add[TWIST] {
        let name = format!("{p}JT{ix1}");
        let j = g.joint(TWIST, name.clone(), JointType::Hinge, jpos, [1.0, 0.0, 0.0]);
        g.body(b).joints.push(j);
        g.fix(TWIST, 2, name);
    }
    if c.add[STRETCH] {
        let name = format!("{p}JS{ix1}");
        let j = g.joint(
            STRETCH,
            name.clone(),
            JointType::Slide,
            jpos,
            [1.0, 0.0, 0.0],
        );
        g.body(b).joints.push(j);
        g.fix(STRETCH, 2, name);
    }
    b.unwrap()
}

fn cloth(g: &mut Gen, dim: usize) -> Result<(), String> {
    let c = g.c;
    let p = &c.prefix;
    if dim != 2 {
        return Err("Cloth must be two-dimensional".into());
    }
    let rest = root_coords(c, &g.root.name)?;
    let coords = scan_int(rest).and_then(|(x, r)| {
        let r = r.strip_prefix('_')?;
        // %c takes any character, but only '_' passes the check below
        scan_int(r).map(|(y, _)| (x, y))
    });
    let Some((ox, oy)) = coords else {
        return Err("Root body name must contain X_Y coordinates".into());
    };
    let n = c.count;
    if ox < 0 || ox >= n[0] || oy < 0 || oy >= n[1] {
        return Err("Root body coordinates out of range".into());
    }
    cloth_body(g, None, ox, oy, ox, oy);
    // center column, then rows to the right and to the left, each with its columns
    for dir in [0, 1, -1] {
        let mut ix = ox;
        let mut px: Option<usize> = None;
        loop {
            if dir != 0 {
                let ix1 = (ix + dir).clamp(0, n[0] - 1);
                if ix1 == ix {
                    break;
                }
                px = Some(cloth_body(g, px, ix, oy, ix1, oy));
                ix = ix1;
            }
            for ydir in [1, -1] {
                let mut iy = oy;
                let mut py = px;
                loop {
                    let iy1 = (iy + ydir).clamp(0, n[1] - 1);
                    if iy1 == iy {
                        break;
                    }
                    py = Some(cloth_body(g, py, ix, iy, ix, iy1));
                    iy = iy1;
                }
            }
            if dir == 0 {
                break;
            }
        }
    }
    for iy in (0..n[1]).filter(|&iy| iy != oy) {
        for ix in 0..n[0] - 1 {
            let name = format!("{p}T{ix}_{iy}");
            let path = vec![
                site_wrap(format!("{p}S{ix}_{iy}")),
                site_wrap(format!("{p}S{}_{iy}", ix + 1)),
            ];
            g.tendon(TENDON, name.clone(), path);
            g.fix(TENDON, 3, name);
        }
    }
    if c.add[SHEAR] {
        shear(g);
    }
    if let Some(s) = &c.skin {
        let skin = if s.subgrid > 0 {
            super::composite_skin::grid_subgrid(c, s)?
        } else {
            super::composite_skin::grid(c, s)
        };
        g.out.skins.push(skin);
    }
    Ok(())
}

/// Adds cloth element (ix1, iy1) as a child of `parent` (the root itself when the same).
fn cloth_body(g: &mut Gen, parent: Option<usize>, ix: i32, iy: i32, ix1: i32, iy1: i32) -> usize {
    let c = g.c;
    let p = &c.prefix;
    let root = ix == ix1 && iy == iy1;
    let dx = c.spacing * (ix1 - ix) as f64;
    let dy = c.spacing * (iy1 - iy) as f64;
    let b = if root {
        parent
    } else {
        Some(g.add_body(parent, format!("{p}B{ix1}_{iy1}"), [dx, dy, 0.0]))
    };
    let mut geom = g.geom(format!("{p}G{ix1}_{iy1}"));
    geom.pos = [0.0; 3];
    geom.quat = if (ix1 + iy1) % 2 != 0 {
        [0.5f64.sqrt(), 0.5f64.sqrt(), 0.0, 0.0]
    } else {
        [0.5; 4]
    };
    if c.flatinertia > 0.0 {
        let mass = if geom.mass.is_nan() {
            geom.density * volume(&geom)
        } else {
            geom.mass
        };
        let h = 0.5 * c.spacing;
        let s = [h, h, h * c.flatinertia];
        let body = g.body(b);
        body.mass = mass;
        body.ipos = [0.0; 3];
        body.iquat = [1.0, 0.0, 0.0, 0.0];
        body.inertia = [
            mass * (s[1] * s[1] + s[2] * s[2]) / 3.0,
            mass * (s[0] * s[0] + s[2] * s[2]) / 3.0,
            mass * (s[0] * s[0] + s[1] * s[1]) / 3.0,
        ];
        body.explicit_inertial = true;
    }
    g.body(b).geoms.push(geom);
    let mut site = g.site(format!("{p}S{ix1}_{iy1}"));
    site.pos = [0.0; 3];
    site.quat = [1.0, 0.0, 0.0, 0.0];
    g.body(b).sites.push(site);
    if root {
        return usize::MAX;
    }
    let jpos = [-dx, -dy, 0.0];
    for i in 0..2 {
        let mut axis = [0.0; 3];
        if ix != ix1 {
            axis[i + 1] = 1.0;
        } else {
            axis[2 * i] = 1.0;
        }
        let j = g.joint(
            JOINT,
            format!("{p}J{i}_{ix1}_{iy1}"),
            JointType::Hinge,
            jpos,
            axis,
        );
        g.body(b).joints.push(j);
    }
    let along = if ix != ix1 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    if c.add[TWIST] {
        let name = format!("{p}JT{ix1}_{iy1}");
        let j = g.joint(TWIST, name.clone(), JointType::Hinge, jpos, along);
        g.body(b).joints.push(j);
        g.fix(TWIST, 2, name);
    }
    if c.add[STRETCH] {
        let name = format!("{p}JS{ix1}_{iy1}");
        let j = g.joint(STRETCH, name.clone(), JointType::Slide, jpos, along);
        g.body(b).joints.push(j);
        g.fix(STRETCH, 2, name);
    }
    b.unwrap()
}

/// Volume of a primitive geom, as the compiler computes it.
fn volume(g: &Geom) -> f64 {
    let s = g.size;
    let pi = std::f64::consts::PI;
    match g.kind {
        2 => 4.0 * pi * s[0] * s[0] * s[0] / 3.0,
        3 => pi * (s[0] * s[0] * 2.0 * s[1] + 4.0 * s[0] * s[0] * s[0] / 3.0),
        5 => pi * s[0] * s[0] * 2.0 * s[1],
        4 => 4.0 * pi * s[0] * s[1] * s[2] / 3.0,
        6 => s[0] * s[1] * s[2] * 8.0,
        _ => 0.0,
    }
}

/// Normalizes the first `n` entries unless they are (nearly) zero.
fn normvec(v: &mut [f64; 3], n: usize) {
    let nrm: f64 = v[..n].iter().map(|x| x * x).sum();
    if nrm < 1e-14 {
        return;
    }
    let nrm = nrm.sqrt();
    for x in v[..n].iter_mut() {
        *x /= nrm;
    }
}

/// Box, cylinder or ellipsoid: a shell of bodies on slider joints around a center geom.
fn solid(g: &mut Gen, dim: usize) -> Result<(), String> {
    let c = g.c;
    let p = &c.prefix;
    if dim != 3 {
        return Err("Box and ellipsoid must be three-dimensional".into());
    }
    let mut center = g.geom(format!("{p}Gcenter"));
    center.kind = 2;
    center.pos = [0.0; 3];
    center.size = [center.size[0] * 2.0, 0.0, 0.0];
    g.root.geoms.push(center);
    let tname = format!("{p}T");
    let tendon_at = g.out.tendons.len();
    g.tendon(TENDON, tname.clone(), Vec::new());
    let n = c.count;
    let size: [f64; 3] = std::array::from_fn(|k| 0.5 * c.spacing * (n[k] - 1) as f64);
    let shell = |x: i32, y: i32, z: i32| {
        x == 0 || x == n[0] - 1 || y == 0 || y == n[1] - 1 || z == 0 || z == n[2] - 1
    };
    for ix in 0..n[0] {
        for iy in 0..n[1] {
            for iz in 0..n[2] {
                if !shell(ix, iy, iz) {
                    continue;
                }
                let idx = [ix, iy, iz];
                let mut pos: [f64; 3] =
                    std::array::from_fn(|k| 2.0 * idx[k] as f64 / (n[k] - 1) as f64 - 1.0);
                match c.kind {
                    BOX => {}
                    CYLINDER => {
                        let l0 = pos[0].abs().max(pos[1].abs());
                        normvec(&mut pos, 2);
                        pos[0] *= l0;
                        pos[1] *= l0;
                    }
                    _ => normvec(&mut pos, 3),
                }
                for k in 0..3 {
                    pos[k] *= size[k];
                }
                let b = g.add_body(None, format!("{p}B{ix}_{iy}_{iz}"), pos);
                let mut z = pos;
                normvec(&mut z, 3);
                g.nodes[b].1.alt.zaxis = z;
                let mut geom = g.geom(format!("{p}G{ix}_{iy}_{iz}"));
                if geom.kind == 3 {
                    geom.pos[2] = -(geom.size[0] + geom.size[1]);
                } else {
                    geom.kind = 2;
                    geom.pos[2] = -geom.size[0];
                }
                g.nodes[b].1.geoms.push(geom);
                let jname = format!("{p}J{ix}_{iy}_{iz}");
                let j = g.joint(
                    JOINT,
                    jname.clone(),
                    JointType::Slide,
                    [0.0; 3],
                    [0.0, 0.0, 1.0],
                );
                g.nodes[b].1.joints.push(j);
                g.fix(JOINT, 2, jname.clone());
                g.out.tendons[tendon_at].path.push(Wrap {
                    kind: 1,
                    name: jname.clone(),
                    prm: 1.0,
                    ..Wrap::default()
                });
                for k in 0..3 {
                    let mut j1 = idx;
                    j1[k] = (j1[k] + 1).min(n[k] - 1);
                    if shell(j1[0], j1[1], j1[2]) && j1 != idx {
                        g.out.equalities.push(Equality {
                            kind: 2,
                            name1: jname.clone(),
                            name2: format!("{p}J{}_{}_{}", j1[0], j1[1], j1[2]),
                            solref: c.solref_smooth,
                            solimp: c.solimp_smooth,
                            line: -1,
                            ..g.main_eq.clone()
                        });
                    }
                }
            }
        }
    }
    g.fix(TENDON, 3, tname);
    if let Some(s) = &c.skin {
        let skin = super::composite_skin::solid(c, s);
        g.out.skins.push(skin);
    }
    Ok(())
}
