//! MJCF element tree to `ModelSpec`: sections in 2.2.2's order, defaults classes applied.

use super::tree::Element;
use crate::compiler::composite::{self, Added, CompSkin, Composite};
use crate::compiler::spec::*;

type R<T> = Result<T, String>;

/// Error naming the element and its line, as 2.2.2's XML errors do.
pub fn xerr(el: &Element, msg: &str) -> String {
    format!(
        "XML Error: {msg}\nElement '{}', line {}\n",
        el.name, el.line
    )
}

/// A number as C++ stream extraction reads it: overflow to infinity is a failure; "inf" and
/// "nan" (optionally negative) are accepted spelled out.
fn parse_real<T: std::str::FromStr + From<f32> + PartialEq + Copy + Into<f64>>(
    tok: &str,
) -> Option<T> {
    let body = tok.strip_prefix('-').unwrap_or(tok);
    let special = |s: &str| s.eq_ignore_ascii_case("inf") || s.eq_ignore_ascii_case("nan");
    if (tok.len() == 3 || (tok.len() == 4 && tok.starts_with('-'))) && special(body) {
        let v: f32 = if body.eq_ignore_ascii_case("inf") {
            f32::INFINITY
        } else {
            f32::NAN
        };
        let v = if tok.starts_with('-') { -v } else { v };
        return Some(T::from(v));
    }
    if !tok
        .bytes()
        .all(|b| b.is_ascii_digit() || b"+-.eE".contains(&b))
    {
        return None;
    }
    tok.parse::<T>().ok().filter(|v| !(*v).into().is_infinite())
}

/// Reads up to `out.len()` numbers of attribute `name`; returns how many (0: absent).
pub(crate) fn read_nums<T: std::str::FromStr + From<f32> + Copy + PartialEq + Into<f64>>(
    el: &Element,
    name: &str,
    out: &mut [T],
    required: bool,
    exact: bool,
) -> R<usize> {
    let Some(text) = el.attr(name) else {
        return if required {
            Err(xerr(el, &format!("required attribute missing: '{name}'")))
        } else {
            Ok(0)
        };
    };
    let mut toks = text.split_ascii_whitespace();
    let mut n = 0;
    if text.trim_ascii().is_empty() && !out.is_empty() {
        return Err(xerr(el, &format!("problem reading attribute '{name}'")));
    }
    while n < out.len() {
        let Some(tok) = toks.next() else { break };
        out[n] = parse_real::<T>(tok)
            .ok_or_else(|| xerr(el, &format!("problem reading attribute '{name}'")))?;
        #[allow(clippy::eq_op)]
        let nan = out[n] != out[n];
        if nan {
            crate::runtime::warning("XML contains a 'NaN'. Please check it carefully.");
        }
        n += 1;
    }
    // 2.2.2 reads tokens while its stream is not at the end: after trailing whitespace one more
    // read fails and leaves the last token in place, which fills the next value again
    if n > 0 && n < out.len() && text.ends_with(|c: char| c.is_ascii_whitespace()) {
        out[n] = out[n - 1];
        #[allow(clippy::eq_op)]
        if out[n] != out[n] {
            crate::runtime::warning("XML contains a 'NaN'. Please check it carefully.");
        }
        n += 1;
    }
    if exact && n < out.len() {
        return Err(xerr(
            el,
            &format!("attribute '{name}' does not have enough data"),
        ));
    }
    if toks.next().is_some() {
        return Err(xerr(el, &format!("attribute '{name}' has too much data")));
    }
    Ok(n)
}

fn nums(el: &Element, name: &str, out: &mut [f64]) -> R<bool> {
    Ok(read_nums(el, name, out, false, true)? > 0)
}

fn some_nums(el: &Element, name: &str, out: &mut [f64]) -> R<usize> {
    read_nums(el, name, out, false, false)
}

fn num(el: &Element, name: &str, out: &mut f64) -> R<bool> {
    nums(el, name, std::slice::from_mut(out))
}

fn rgba(el: &Element, out: &mut [f32; 4]) -> R<bool> {
    Ok(read_nums(el, "rgba", out, false, true)? > 0)
}

/// Single int as `sscanf("%d")` reads it: leading digits, trailing text ignored.
fn int(el: &Element, name: &str, out: &mut i32) -> R<bool> {
    let Some(text) = el.attr(name) else {
        return Ok(false);
    };
    let t = text.trim_start();
    let (sign, rest) = match t.as_bytes().first() {
        Some(b'-') => (-1i64, &t[1..]),
        Some(b'+') => (1, &t[1..]),
        _ => (1, t),
    };
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    if digits.is_empty() {
        return Err(xerr(
            el,
            &format!("single int expected in attribute {name}"),
        ));
    }
    // glibc converts through a long and truncates to int
    let v = digits
        .parse::<i64>()
        .map_or(if sign < 0 { i64::MIN } else { i64::MAX }, |v| v * sign);
    *out = v as i32;
    Ok(true)
}

fn text(el: &Element, name: &str, out: &mut String) -> bool {
    match el.attr(name) {
        Some(v) => {
            *out = v.to_string();
            true
        }
        None => false,
    }
}

/// Keyword attribute; returns the index into `keys`.
fn keyword(el: &Element, name: &str, keys: &[&str]) -> R<Option<usize>> {
    let Some(v) = el.attr(name) else {
        return Ok(None);
    };
    match keys.iter().position(|k| *k == v) {
        Some(i) => Ok(Some(i)),
        None => Err(xerr(el, &format!("invalid keyword: '{v}'"))),
    }
}

fn boolean(el: &Element, name: &str) -> R<Option<bool>> {
    Ok(keyword(el, name, &["false", "true"])?.map(|i| i == 1))
}

fn tf_auto(el: &Element, name: &str, out: &mut i32) -> R<()> {
    if let Some(i) = keyword(el, name, &["false", "true", "auto"])? {
        *out = i as i32;
    }
    Ok(())
}

fn user(el: &Element, out: &mut Vec<f64>) -> R<()> {
    let mut buf = [0.0; 1000];
    let n = some_nums(el, "user", &mut buf)?;
    if n > 0 {
        *out = buf[..n].to_vec();
    }
    Ok(())
}

const GEOM_TYPES: [&str; 8] = [
    "plane",
    "hfield",
    "sphere",
    "capsule",
    "ellipsoid",
    "cylinder",
    "box",
    "mesh",
];

fn alternative(el: &Element, alt: &mut Alt) -> R<()> {
    let read = el.attr("quat").is_some() as i32
        + nums(el, "axisangle", &mut alt.axisangle)? as i32
        + nums(el, "xyaxes", &mut alt.xyaxes)? as i32
        + nums(el, "zaxis", &mut alt.zaxis)? as i32
        + nums(el, "euler", &mut alt.euler)? as i32
        + nums(el, "fullinertia", &mut alt.fullinertia)? as i32;
    if read > 1 {
        return Err(xerr(
            el,
            "multiple orientation specifiers for the same field are not allowed",
        ));
    }
    Ok(())
}

fn one_joint(el: &Element, j: &mut Joint) -> R<()> {
    text(el, "name", &mut j.name);
    if let Some(i) = keyword(el, "type", &["free", "ball", "slide", "hinge"])? {
        j.kind = [
            JointType::Free,
            JointType::Ball,
            JointType::Slide,
            JointType::Hinge,
        ][i];
    }
    tf_auto(el, "limited", &mut j.limited)?;
    int(el, "group", &mut j.group)?;
    some_nums(el, "solreflimit", &mut j.solref_limit)?;
    some_nums(el, "solimplimit", &mut j.solimp_limit)?;
    some_nums(el, "solreffriction", &mut j.solref_friction)?;
    some_nums(el, "solimpfriction", &mut j.solimp_friction)?;
    nums(el, "pos", &mut j.pos)?;
    nums(el, "axis", &mut j.axis)?;
    nums(el, "springdamper", &mut j.springdamper)?;
    num(el, "stiffness", &mut j.stiffness)?;
    nums(el, "range", &mut j.range)?;
    num(el, "margin", &mut j.margin)?;
    num(el, "ref", &mut j.reference)?;
    num(el, "springref", &mut j.springref)?;
    num(el, "armature", &mut j.armature)?;
    num(el, "damping", &mut j.damping)?;
    num(el, "frictionloss", &mut j.frictionloss)?;
    user(el, &mut j.user)?;
    j.line = el.line;
    Ok(())
}

fn one_geom(el: &Element, g: &mut Geom) -> R<()> {
    text(el, "name", &mut g.name);
    if let Some(i) = keyword(el, "type", &GEOM_TYPES)? {
        g.kind = i as i32;
    }
    some_nums(el, "size", &mut g.size)?;
    int(el, "contype", &mut g.contype)?;
    int(el, "conaffinity", &mut g.conaffinity)?;
    int(el, "condim", &mut g.condim)?;
    int(el, "group", &mut g.group)?;
    int(el, "priority", &mut g.priority)?;
    some_nums(el, "friction", &mut g.friction)?;
    num(el, "solmix", &mut g.solmix)?;
    some_nums(el, "solref", &mut g.solref)?;
    some_nums(el, "solimp", &mut g.solimp)?;
    num(el, "margin", &mut g.margin)?;
    num(el, "gap", &mut g.gap)?;
    text(el, "material", &mut g.material);
    text(el, "hfield", &mut g.hfield);
    text(el, "mesh", &mut g.mesh);
    num(el, "fitscale", &mut g.fitscale)?;
    if let Some(b) = boolean(el, "shellinertia")? {
        g.shellinertia = b;
    }
    rgba(el, &mut g.rgba)?;
    if let Some(i) = keyword(el, "fluidshape", &["none", "ellipsoid"])? {
        g.fluid_switch = i == 1;
    }
    some_nums(el, "fluidcoef", &mut g.fluid_coefs)?;
    user(el, &mut g.user)?;
    num(el, "mass", &mut g.mass)?;
    num(el, "density", &mut g.density)?;
    nums(el, "fromto", &mut g.fromto)?;
    nums(el, "pos", &mut g.pos)?;
    nums(el, "quat", &mut g.quat)?;
    alternative(el, &mut g.alt)?;
    g.line = el.line;
    Ok(())
}

/// Numbers of a text as `std::stringstream >> T` reads them: as many as parse, in order.
fn stream_numbers<T: std::str::FromStr + Copy + Into<f64>>(text: &str, float: bool) -> Vec<T> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    loop {
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        let start = i;
        if i < b.len() && matches!(b[i], b'+' | b'-') {
            i += 1;
        }
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        if float {
            if i < b.len() && b[i] == b'.' {
                i += 1;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
            }
            if i < b.len() && matches!(b[i], b'e' | b'E') {
                i += 1;
                if i < b.len() && matches!(b[i], b'+' | b'-') {
                    i += 1;
                }
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
            }
        }
        match text[start..i].parse::<T>() {
            Ok(v) if i > start && v.into().is_finite() => out.push(v),
            _ => return out,
        }
    }
}

fn one_mesh(el: &Element, m: &mut Mesh) -> R<()> {
    text(el, "name", &mut m.name);
    text(el, "file", &mut m.file);
    nums(el, "refpos", &mut m.refpos)?;
    nums(el, "refquat", &mut m.refquat)?;
    nums(el, "scale", &mut m.scale)?;
    if let Some(b) = boolean(el, "smoothnormal")? {
        m.smoothnormal = b;
    }
    let floats = |name: &str| el.attr(name).map(|t| stream_numbers::<f32>(t, true));
    if let Some(v) = floats("vertex") {
        m.vertex = v;
    }
    if let Some(v) = floats("normal") {
        m.normal = v;
    }
    if let Some(v) = floats("texcoord") {
        m.texcoord = v;
    }
    if let Some(t) = el.attr("face") {
        m.face = stream_numbers::<i32>(t, false);
    }
    m.line = el.line;
    Ok(())
}

fn one_site(el: &Element, s: &mut Site) -> R<()> {
    text(el, "name", &mut s.name);
    if let Some(i) = keyword(el, "type", &GEOM_TYPES)? {
        s.kind = i as i32;
    }
    some_nums(el, "size", &mut s.size)?;
    int(el, "group", &mut s.group)?;
    nums(el, "pos", &mut s.pos)?;
    nums(el, "quat", &mut s.quat)?;
    text(el, "material", &mut s.material);
    rgba(el, &mut s.rgba)?;
    nums(el, "fromto", &mut s.fromto)?;
    alternative(el, &mut s.alt)?;
    user(el, &mut s.user)?;
    s.line = el.line;
    Ok(())
}

const CAMLIGHT_MODES: [&str; 5] = ["fixed", "track", "trackcom", "targetbody", "targetbodycom"];

fn one_camera(el: &Element, c: &mut Camera) -> R<()> {
    text(el, "name", &mut c.name);
    text(el, "target", &mut c.target);
    if let Some(i) = keyword(el, "mode", &CAMLIGHT_MODES)? {
        c.mode = i as i32;
    }
    nums(el, "pos", &mut c.pos)?;
    nums(el, "quat", &mut c.quat)?;
    alternative(el, &mut c.alt)?;
    num(el, "fovy", &mut c.fovy)?;
    num(el, "ipd", &mut c.ipd)?;
    user(el, &mut c.user)?;
    c.line = el.line;
    Ok(())
}

fn floats<const N: usize>(el: &Element, name: &str, out: &mut [f32; N]) -> R<bool> {
    Ok(read_nums(el, name, out, false, true)? > 0)
}

fn one_light(el: &Element, l: &mut Light) -> R<()> {
    text(el, "name", &mut l.name);
    text(el, "target", &mut l.target);
    if let Some(i) = keyword(el, "mode", &CAMLIGHT_MODES)? {
        l.mode = i as i32;
    }
    for (name, out) in [
        ("directional", &mut l.directional),
        ("castshadow", &mut l.castshadow),
        ("active", &mut l.active),
    ] {
        if let Some(b) = boolean(el, name)? {
            *out = b;
        }
    }
    nums(el, "pos", &mut l.pos)?;
    nums(el, "dir", &mut l.dir)?;
    floats(el, "attenuation", &mut l.attenuation)?;
    read_nums(
        el,
        "cutoff",
        std::slice::from_mut(&mut l.cutoff),
        false,
        true,
    )?;
    read_nums(
        el,
        "exponent",
        std::slice::from_mut(&mut l.exponent),
        false,
        true,
    )?;
    floats(el, "ambient", &mut l.ambient)?;
    floats(el, "diffuse", &mut l.diffuse)?;
    floats(el, "specular", &mut l.specular)?;
    l.line = el.line;
    Ok(())
}

const ACTUATORS: [&str; 9] = [
    "general",
    "motor",
    "position",
    "velocity",
    "intvelocity",
    "damper",
    "cylinder",
    "adhesion",
    "muscle",
];

fn one_actuator(el: &Element, a: &mut Actuator) -> R<()> {
    text(el, "name", &mut a.name);
    int(el, "group", &mut a.group)?;
    tf_auto(el, "ctrllimited", &mut a.ctrllimited)?;
    tf_auto(el, "forcelimited", &mut a.forcelimited)?;
    tf_auto(el, "actlimited", &mut a.actlimited)?;
    nums(el, "ctrlrange", &mut a.ctrlrange)?;
    nums(el, "forcerange", &mut a.forcerange)?;
    nums(el, "actrange", &mut a.actrange)?;
    nums(el, "lengthrange", &mut a.lengthrange)?;
    some_nums(el, "gear", &mut a.gear)?;
    // transmission: joint 0, jointinparent 1, slidercrank 2, tendon 3, site 4, body 5
    let mut cnt = 0;
    for (attr, trn) in [
        ("joint", 0),
        ("jointinparent", 1),
        ("tendon", 3),
        ("cranksite", 2),
        ("site", 4),
        ("body", 5),
    ] {
        if text(el, attr, &mut a.target) {
            a.trntype = trn;
            cnt += 1;
        }
    }
    if cnt > 1 {
        return Err(xerr(
            el,
            "actuator can have at most one of transmission target",
        ));
    }
    let r1 = num(el, "cranklength", &mut a.cranklength)?;
    let r2 = text(el, "slidersite", &mut a.slidersite);
    if (r1 || r2) && a.trntype != 2 && a.trntype != TRN_UNDEFINED {
        return Err(xerr(
            el,
            "cranklength and slidersite can only be used in slidercrank transmission",
        ));
    }
    if text(el, "refsite", &mut a.refsite) && a.trntype != 4 && a.trntype != TRN_UNDEFINED {
        return Err(xerr(el, "refsite can only be used with site transmission"));
    }
    match el.name.as_str() {
        "general" => {
            let dyn_kw = ["none", "integrator", "filter", "muscle", "user"];
            if let Some(i) = keyword(el, "dyntype", &dyn_kw)? {
                a.dyntype = i as i32;
            }
            if let Some(i) = keyword(el, "gaintype", &["fixed", "affine", "muscle", "user"])? {
                a.gaintype = i as i32;
            }
            if let Some(i) = keyword(el, "biastype", &["none", "affine", "muscle", "user"])? {
                a.biastype = i as i32;
            }
            some_nums(el, "dynprm", &mut a.dynprm)?;
            some_nums(el, "gainprm", &mut a.gainprm)?;
            some_nums(el, "biasprm", &mut a.biasprm)?;
        }
        "motor" => {
            a.gainprm[0] = 1.0;
            (a.dyntype, a.gaintype, a.biastype) = (0, 0, 0);
        }
        "position" | "velocity" => {
            let (gain, slot) = if el.name == "position" {
                ("kp", 1)
            } else {
                ("kv", 2)
            };
            a.biasprm = [0.0; 10];
            num(el, gain, &mut a.gainprm[0])?;
            a.biasprm[slot] = -a.gainprm[0];
            (a.dyntype, a.gaintype, a.biastype) = (0, 0, 1);
        }
        "intvelocity" => {
            a.biasprm = [0.0; 10];
            num(el, "kp", &mut a.gainprm[0])?;
            (a.dyntype, a.gaintype, a.biastype) = (1, 0, 1);
            a.actlimited = 1;
            a.biasprm[1] = -a.gainprm[0];
        }
        "damper" | "adhesion" => {
            a.gainprm = [0.0; 10];
            let slot = if el.name == "damper" { 2 } else { 0 };
            if el.name == "adhesion" {
                a.biasprm = [0.0; 10];
                a.gainprm[0] = 1.0;
            }
            num(
                el,
                if slot == 2 { "kv" } else { "gain" },
                &mut a.gainprm[slot],
            )?;
            if a.gainprm[slot] < 0.0 {
                let what = if slot == 2 {
                    "damping coefficient"
                } else {
                    "adhesion gain"
                };
                return Err(xerr(el, &format!("{what} cannot be negative")));
            }
            if slot == 2 {
                a.gainprm[2] = -a.gainprm[2];
            }
            read_nums(el, "ctrlrange", &mut a.ctrlrange, true, true)?;
            if a.ctrlrange[0] < 0.0 || a.ctrlrange[1] < 0.0 {
                let what = if slot == 2 { "damper" } else { "adhesion" };
                return Err(xerr(
                    el,
                    &format!("{what} control range cannot be negative"),
                ));
            }
            a.ctrllimited = 1;
            (a.dyntype, a.gaintype, a.biastype) = (0, if slot == 2 { 1 } else { 0 }, 0);
        }
        "muscle" => {
            // 2.2.2's muscle defaults replace values still at the generic defaults
            if a.dynprm[0] == 1.0 {
                a.dynprm[0] = 0.01;
            }
            if a.dynprm[1] == 0.0 {
                a.dynprm[1] = 0.04;
            }
            let muscle = [
                (1.0, 0.75),
                (0.0, 1.05),
                (0.0, -1.0),
                (0.0, 200.0),
                (0.0, 0.5),
                (0.0, 1.6),
                (0.0, 1.5),
                (0.0, 1.3),
                (0.0, 1.2),
            ];
            for (k, (generic, value)) in muscle.iter().enumerate() {
                if a.gainprm[k] == *generic {
                    a.gainprm[k] = *value;
                }
            }
            nums(el, "timeconst", &mut a.dynprm[..2])?;
            nums(el, "range", &mut a.gainprm[..2])?;
            for (k, n) in ["force", "scale", "lmin", "lmax", "vmax", "fpmax", "fvmax"]
                .iter()
                .enumerate()
            {
                num(el, n, &mut a.gainprm[k + 2])?;
            }
            let g = a.gainprm;
            a.biasprm[..9].copy_from_slice(&g[..9]);
            (a.dyntype, a.gaintype, a.biastype) = (3, 2, 2);
        }
        "cylinder" => {
            num(el, "timeconst", &mut a.dynprm[0])?;
            nums(el, "bias", &mut a.biasprm[..3])?;
            num(el, "area", &mut a.gainprm[0])?;
            let mut diameter = 0.0;
            if num(el, "diameter", &mut diameter)? {
                a.gainprm[0] = std::f64::consts::PI / 4.0 * diameter * diameter;
            }
            (a.dyntype, a.gaintype, a.biastype) = (2, 0, 1);
        }
        other => return Err(unsupported(el, other)),
    }
    user(el, &mut a.user)?;
    a.line = el.line;
    Ok(())
}

fn one_pair(el: &Element, p: &mut Pair, in_default: bool) -> R<()> {
    if !in_default {
        read_text(el, "geom1", &mut p.geom1)?;
        read_text(el, "geom2", &mut p.geom2)?;
    }
    text(el, "name", &mut p.name);
    int(el, "condim", &mut p.condim)?;
    some_nums(el, "solref", &mut p.solref)?;
    some_nums(el, "solimp", &mut p.solimp)?;
    num(el, "margin", &mut p.margin)?;
    num(el, "gap", &mut p.gap)?;
    some_nums(el, "friction", &mut p.friction)?;
    p.line = el.line;
    Ok(())
}

/// Required text attribute.
fn read_text(el: &Element, name: &str, out: &mut String) -> R<()> {
    if text(el, name, out) {
        Ok(())
    } else {
        Err(xerr(el, &format!("required attribute missing: '{name}'")))
    }
}

fn read_contact(spec: &mut ModelSpec, el: &Element) -> R<()> {
    for c in &el.children {
        let def = class_of(spec, c)?.unwrap_or(0);
        if c.name == "pair" {
            let mut p = spec.defaults[def].pair.clone();
            one_pair(c, &mut p, false)?;
            spec.pairs.push(p);
        } else {
            let mut e = Exclude {
                line: c.line,
                ..Exclude::default()
            };
            text(c, "name", &mut e.name);
            read_text(c, "body1", &mut e.body1)?;
            read_text(c, "body2", &mut e.body2)?;
            spec.excludes.push(e);
        }
    }
    Ok(())
}

/// mjtObj value of an object type name (0: unknown).
fn obj_type(name: &str) -> i32 {
    const NAMES: [&str; 23] = [
        "unknown", "body", "xbody", "joint", "dof", "geom", "site", "camera", "light", "mesh",
        "skin", "hfield", "texture", "material", "pair", "exclude", "equality", "tendon",
        "actuator", "sensor", "numeric", "text", "tuple",
    ];
    if name == "key" {
        return 23;
    }
    NAMES.iter().position(|n| *n == name).unwrap_or(0) as i32
}

/// Sensor element names in mjtSensor order, with the attribute naming their object and its mjtObj.
const SENSORS: [(&str, &str, i32); 34] = [
    ("touch", "site", 6),
    ("accelerometer", "site", 6),
    ("velocimeter", "site", 6),
    ("gyro", "site", 6),
    ("force", "site", 6),
    ("torque", "site", 6),
    ("magnetometer", "site", 6),
    ("rangefinder", "site", 6),
    ("jointpos", "joint", 3),
    ("jointvel", "joint", 3),
    ("tendonpos", "tendon", 17),
    ("tendonvel", "tendon", 17),
    ("actuatorpos", "actuator", 18),
    ("actuatorvel", "actuator", 18),
    ("actuatorfrc", "actuator", 18),
    ("ballquat", "joint", 3),
    ("ballangvel", "joint", 3),
    ("jointlimitpos", "joint", 3),
    ("jointlimitvel", "joint", 3),
    ("jointlimitfrc", "joint", 3),
    ("tendonlimitpos", "tendon", 17),
    ("tendonlimitvel", "tendon", 17),
    ("tendonlimitfrc", "tendon", 17),
    ("framepos", "", 0),
    ("framequat", "", 0),
    ("framexaxis", "", 0),
    ("frameyaxis", "", 0),
    ("framezaxis", "", 0),
    ("framelinvel", "", 0),
    ("frameangvel", "", 0),
    ("framelinacc", "", 0),
    ("frameangacc", "", 0),
    ("subtreecom", "body", 1),
    ("subtreelinvel", "body", 1),
];

fn read_sensors(spec: &mut ModelSpec, el: &Element) -> R<()> {
    for c in &el.children {
        let mut s = Sensor::default();
        text(c, "name", &mut s.name);
        num(c, "cutoff", &mut s.cutoff)?;
        num(c, "noise", &mut s.noise)?;
        user(c, &mut s.user)?;
        let mut tmp = String::new();
        if let Some(k) = SENSORS.iter().position(|x| x.0 == c.name) {
            s.kind = k as i32;
            let (_, attr, objtype) = SENSORS[k];
            if attr.is_empty() {
                read_text(c, "objtype", &mut tmp)?;
                s.objtype = obj_type(&tmp);
                read_text(c, "objname", &mut s.objname)?;
                if !c.name.ends_with("acc") {
                    if text(c, "reftype", &mut tmp) {
                        s.reftype = obj_type(&tmp);
                        read_text(c, "refname", &mut s.refname)?;
                    } else if text(c, "refname", &mut tmp) {
                        return Err(xerr(
                            c,
                            &format!("refname '{tmp}' given but reftype is missing"),
                        ));
                    }
                }
            } else {
                s.objtype = objtype;
                read_text(c, attr, &mut s.objname)?;
            }
        } else {
            match c.name.as_str() {
                "subtreeangmom" => {
                    s.kind = 34;
                    s.objtype = 1;
                    read_text(c, "body", &mut s.objname)?;
                }
                "clock" => s.kind = 35,
                _ => {
                    s.kind = 36;
                    read_text(c, "objtype", &mut tmp)?;
                    s.objtype = obj_type(&tmp);
                    read_text(c, "objname", &mut s.objname)?;
                    if c.attr("dim").is_none() {
                        return Err(xerr(c, "required attribute missing: 'dim'"));
                    }
                    int(c, "dim", &mut s.dim)?;
                    let stage = ["none", "pos", "vel", "acc"];
                    s.needstage = keyword(c, "needstage", &stage)?
                        .ok_or_else(|| xerr(c, "required attribute missing: 'needstage'"))?
                        as i32;
                    let dt = ["real", "positive", "axis", "quaternion"];
                    s.datatype = keyword(c, "datatype", &dt)?
                        .ok_or_else(|| xerr(c, "required attribute missing: 'datatype'"))?
                        as i32;
                }
            }
        }
        spec.sensors.push(s);
    }
    Ok(())
}

fn one_equality(el: &Element, e: &mut Equality, in_default: bool) -> R<()> {
    let kinds = ["connect", "weld", "joint", "tendon", "distance"];
    e.kind = kinds
        .iter()
        .position(|k| *k == el.name)
        .map_or(-1, |k| k as i32);
    if !in_default {
        text(el, "name", &mut e.name);
        let (a1, a2) = match e.kind {
            0 | 1 => ("body1", "body2"),
            2 => ("joint1", "joint2"),
            3 => ("tendon1", "tendon2"),
            4 => {
                return Err(xerr(
                    el,
                    "support for distance equality contraints was removed in MuJoCo 2.2.2",
                ))
            }
            _ => return Err(xerr(el, "unrecognized equality constraint type")),
        };
        read_text(el, a1, &mut e.name1)?;
        text(el, a2, &mut e.name2);
        match e.kind {
            0 => {
                read_nums(el, "anchor", &mut e.data[..3], true, true)?;
            }
            1 => {
                nums(el, "relpose", &mut e.data[3..10])?;
                num(el, "torquescale", &mut e.data[10])?;
                if !nums(el, "anchor", &mut e.data[..3])? {
                    e.data[..3].fill(0.0);
                }
            }
            _ => {
                nums(el, "polycoef", &mut e.data[..5])?;
            }
        }
    }
    if let Some(b) = boolean(el, "active")? {
        e.active = b;
    }
    some_nums(el, "solref", &mut e.solref)?;
    some_nums(el, "solimp", &mut e.solimp)?;
    e.line = el.line;
    Ok(())
}

fn one_tendon(el: &Element, t: &mut Tendon) -> R<()> {
    text(el, "name", &mut t.name);
    int(el, "group", &mut t.group)?;
    text(el, "material", &mut t.material);
    tf_auto(el, "limited", &mut t.limited)?;
    num(el, "width", &mut t.width)?;
    some_nums(el, "solreflimit", &mut t.solref_limit)?;
    some_nums(el, "solimplimit", &mut t.solimp_limit)?;
    some_nums(el, "solreffriction", &mut t.solref_friction)?;
    some_nums(el, "solimpfriction", &mut t.solimp_friction)?;
    nums(el, "range", &mut t.range)?;
    num(el, "margin", &mut t.margin)?;
    num(el, "stiffness", &mut t.stiffness)?;
    num(el, "damping", &mut t.damping)?;
    num(el, "frictionloss", &mut t.frictionloss)?;
    num(el, "springlength", &mut t.springlength)?;
    rgba(el, &mut t.rgba)?;
    user(el, &mut t.user)?;
    t.line = el.line;
    Ok(())
}

fn read_tendons(spec: &mut ModelSpec, el: &Element) -> R<()> {
    for c in &el.children {
        let def = class_of(spec, c)?.unwrap_or(0);
        let mut t = spec.defaults[def].tendon.clone();
        one_tendon(c, &mut t)?;
        for w in &c.children {
            let mut wrap = Wrap {
                line: w.line,
                ..Wrap::default()
            };
            match w.name.as_str() {
                "site" => {
                    wrap.kind = 3;
                    read_text(w, "site", &mut wrap.name)?;
                }
                "geom" => {
                    wrap.kind = 4;
                    read_text(w, "geom", &mut wrap.name)?;
                    text(w, "sidesite", &mut wrap.sidesite);
                }
                "pulley" => {
                    wrap.kind = 2;
                    read_nums(
                        w,
                        "divisor",
                        std::slice::from_mut(&mut wrap.prm),
                        true,
                        true,
                    )?;
                }
                "joint" => {
                    wrap.kind = 1;
                    read_text(w, "joint", &mut wrap.name)?;
                    read_nums(w, "coef", std::slice::from_mut(&mut wrap.prm), true, true)?;
                }
                _ => return Err(xerr(w, "unknown wrap type")),
            }
            t.path.push(wrap);
        }
        spec.tendons.push(t);
    }
    Ok(())
}

fn one_material(el: &Element, m: &mut Material) -> R<()> {
    text(el, "name", &mut m.name);
    text(el, "texture", &mut m.texture);
    if let Some(b) = boolean(el, "texuniform")? {
        m.texuniform = b;
    }
    floats(el, "texrepeat", &mut m.texrepeat)?;
    f1(el, "emission", &mut m.emission)?;
    f1(el, "specular", &mut m.specular)?;
    f1(el, "shininess", &mut m.shininess)?;
    f1(el, "reflectance", &mut m.reflectance)?;
    floats(el, "rgba", &mut m.rgba)?;
    m.line = el.line;
    Ok(())
}

fn read_assets(spec: &mut ModelSpec, el: &Element) -> R<()> {
    for c in &el.children {
        let def = class_of(spec, c)?.unwrap_or(0);
        match c.name.as_str() {
            "texture" => {
                let mut t = Texture {
                    line: c.line,
                    ..Texture::default()
                };
                if let Some(i) = keyword(c, "type", &["2d", "cube", "skybox"])? {
                    t.kind = i as i32;
                }
                text(c, "name", &mut t.name);
                int(c, "width", &mut t.width)?;
                int(c, "height", &mut t.height)?;
                nums(c, "rgb1", &mut t.rgb1)?;
                nums(c, "rgb2", &mut t.rgb2)?;
                nums(c, "markrgb", &mut t.markrgb)?;
                num(c, "random", &mut t.random)?;
                if let Some(i) = keyword(c, "builtin", &["none", "gradient", "checker", "flat"])? {
                    t.builtin = i as i32;
                }
                if let Some(i) = keyword(c, "mark", &["none", "edge", "cross", "random"])? {
                    t.mark = i as i32;
                }
                t.hflip = boolean(c, "hflip")?.unwrap_or(false);
                t.vflip = boolean(c, "vflip")?.unwrap_or(false);
                if let Some(g) = c.attr("gridsize") {
                    for (k, v) in g.split_whitespace().take(2).enumerate() {
                        t.gridsize[k] = v
                            .parse()
                            .map_err(|_| xerr(c, "problem reading attribute 'gridsize'"))?;
                    }
                }
                text(c, "gridlayout", &mut t.gridlayout);
                let files = [
                    "file",
                    "fileright",
                    "fileleft",
                    "fileup",
                    "filedown",
                    "filefront",
                    "fileback",
                ];
                for (k, f) in files.iter().enumerate() {
                    text(c, f, &mut t.file_names[k]);
                }
                spec.textures.push(t);
            }
            "mesh" => {
                let mut m = spec.defaults[def].mesh.clone();
                m.density = spec.defaults[def].geom.density;
                one_mesh(c, &mut m)?;
                spec.meshes.push(m);
            }
            "hfield" => {
                let mut hf = HField {
                    line: c.line,
                    ..HField::default()
                };
                text(c, "name", &mut hf.name);
                text(c, "file", &mut hf.file);
                int(c, "nrow", &mut hf.nrow)?;
                int(c, "ncol", &mut hf.ncol)?;
                read_nums(c, "size", &mut hf.size, true, true)?;
                spec.hfields.push(hf);
            }
            "skin" => spec.skins.push(read_skin(c)?),
            "material" => {
                let mut m = spec.defaults[def].material.clone();
                one_material(c, &mut m)?;
                spec.materials.push(m);
            }
            other => return Err(unsupported(c, other)),
        }
    }
    Ok(())
}

fn read_custom(spec: &mut ModelSpec, el: &Element) -> R<()> {
    let c = &mut spec.custom;
    for e in &el.children {
        let mut name = String::new();
        read_text(e, "name", &mut name)?;
        match e.name.as_str() {
            "numeric" => {
                let mut size = 0;
                let given = int(e, "size", &mut size)?;
                let mut buf = vec![0.0; 501];
                let cap = if given {
                    size.clamp(0, 501) as usize
                } else {
                    501
                };
                let len = some_nums(e, "data", &mut buf[..cap])?;
                if !given {
                    size = len as i32;
                }
                if !(1..=500).contains(&size) {
                    return Err(xerr(e, "custom field size must be between 1 and 500"));
                }
                buf.truncate(size as usize);
                c.numerics.push((name, e.line, buf));
            }
            "text" => {
                let mut data = String::new();
                read_text(e, "data", &mut data)?;
                if data.is_empty() {
                    return Err(xerr(e, "text field cannot be empty"));
                }
                c.texts.push((name, e.line, data));
            }
            _ => {
                let mut elems = Vec::new();
                for o in e.children.iter().filter(|o| o.name == "element") {
                    let mut t = String::new();
                    read_text(o, "objtype", &mut t)?;
                    let kind = obj_type(&t);
                    if kind == 0 {
                        return Err(xerr(o, "unknown object type"));
                    }
                    let mut oname = String::new();
                    read_text(o, "objname", &mut oname)?;
                    let mut prm = 0.0;
                    num(o, "prm", &mut prm)?;
                    elems.push((kind, oname, prm));
                }
                c.tuples.push((name, e.line, elems));
            }
        }
    }
    Ok(())
}

fn unsupported(el: &Element, what: &str) -> String {
    xerr(
        el,
        &format!("'{what}' is not supported by this MJCF reader yet"),
    )
}

fn find_class(spec: &ModelSpec, name: &str) -> Option<usize> {
    spec.defaults.iter().position(|d| d.name == name)
}

/// Class named by the element's `class` attribute, if any.
fn class_of(spec: &ModelSpec, el: &Element) -> R<Option<usize>> {
    match el.attr("class") {
        Some(c) => find_class(spec, c)
            .map(Some)
            .ok_or_else(|| xerr(el, "unknown default class")),
        None => Ok(None),
    }
}

fn read_default(spec: &mut ModelSpec, el: &Element, parent: Option<usize>) -> R<()> {
    let mut name = el.attr("class").unwrap_or("").to_string();
    let id = match parent {
        None => {
            if name.is_empty() {
                name = "main".into();
            }
            spec.defaults[0].name = name;
            0
        }
        Some(p) => {
            if name.is_empty() {
                return Err(xerr(el, "empty class name"));
            }
            if find_class(spec, &name).is_some() {
                return Err(xerr(el, "repeated default class name"));
            }
            let mut d = spec.defaults[p].clone();
            d.name = name;
            d.parent = Some(p);
            spec.defaults.push(d);
            spec.defaults.len() - 1
        }
    };
    for c in &el.children {
        let d = &mut spec.defaults[id];
        match c.name.as_str() {
            "joint" => one_joint(c, &mut d.joint)?,
            "geom" => one_geom(c, &mut d.geom)?,
            "site" => one_site(c, &mut d.site)?,
            "camera" => one_camera(c, &mut d.camera)?,
            "light" => one_light(c, &mut d.light)?,
            "pair" => one_pair(c, &mut d.pair, true)?,
            "material" => one_material(c, &mut d.material)?,
            "equality" => one_equality(c, &mut d.equality, true)?,
            "tendon" => one_tendon(c, &mut d.tendon)?,
            "mesh" => one_mesh(c, &mut d.mesh)?,
            n if ACTUATORS.contains(&n) => one_actuator(c, &mut d.actuator)?,
            "default" => {}
            other => return Err(unsupported(c, other)),
        }
    }
    for c in el.children.iter().filter(|c| c.name == "default") {
        read_default(spec, c, Some(id))?;
    }
    Ok(())
}

fn read_body(
    spec: &ModelSpec,
    el: &Element,
    body: &mut Body,
    def: usize,
    world: bool,
    added: &mut Added,
) -> R<()> {
    if world && !el.attrs.is_empty() {
        return Err(xerr(el, "World body cannot have attributes"));
    }
    for c in &el.children {
        let cdef = class_of(spec, c)?.unwrap_or(def);
        match c.name.as_str() {
            "inertial" => {
                if world {
                    return Err(xerr(c, "World body cannot have inertia"));
                }
                body.explicit_inertial = true;
                read_nums(c, "pos", &mut body.ipos, true, true)?;
                nums(c, "quat", &mut body.iquat)?;
                read_nums(c, "mass", std::slice::from_mut(&mut body.mass), true, true)?;
                nums(c, "diaginertia", &mut body.inertia)?;
                alternative(c, &mut body.ialt)?;
            }
            "joint" | "freejoint" => {
                if world {
                    return Err(xerr(c, "World body cannot have joints"));
                }
                if c.name == "joint" {
                    let mut j = spec.defaults[cdef].joint.clone();
                    one_joint(c, &mut j)?;
                    body.joints.push(j);
                } else {
                    let mut j = Joint {
                        kind: JointType::Free,
                        ..Joint::default()
                    };
                    text(c, "name", &mut j.name);
                    int(c, "group", &mut j.group)?;
                    j.line = -1;
                    body.joints.push(j);
                }
            }
            "geom" => {
                let mut g = spec.defaults[cdef].geom.clone();
                one_geom(c, &mut g)?;
                if !(g.contype == 0 && g.conaffinity == 0 && spec.compiler.discardvisual) {
                    body.geoms.push(g);
                }
            }
            "site" => {
                let mut s = spec.defaults[cdef].site.clone();
                one_site(c, &mut s)?;
                body.sites.push(s);
            }
            "camera" => {
                let mut cam = spec.defaults[cdef].camera.clone();
                one_camera(c, &mut cam)?;
                body.cameras.push(cam);
            }
            "light" => {
                let mut light = spec.defaults[cdef].light.clone();
                one_light(c, &mut light)?;
                body.lights.push(light);
            }
            "body" => {
                let mut childdef = def;
                if let Some(cc) = c.attr("childclass") {
                    childdef = find_class(spec, cc)
                        .ok_or_else(|| xerr(c, "unknown default childclass"))?;
                }
                let mut child = Body {
                    line: c.line,
                    ..Body::default()
                };
                text(c, "name", &mut child.name);
                nums(c, "pos", &mut child.pos)?;
                nums(c, "quat", &mut child.quat)?;
                if let Some(m) = boolean(c, "mocap")? {
                    child.mocap = m;
                }
                alternative(c, &mut child.alt)?;
                user(c, &mut child.user)?;
                read_body(spec, c, &mut child, childdef, false, added)?;
                body.bodies.push(child);
            }
            "composite" => {
                let comp = read_composite(c)?;
                composite::expand(
                    &comp,
                    body,
                    spec.compiler.global,
                    &spec.defaults[0].equality,
                    added,
                )
                .map_err(|e| xerr(c, &e))?;
            }
            other => return Err(unsupported(c, other)),
        }
    }
    Ok(())
}

/// Integers of attribute `name` (up to `out.len()`); returns how many.
fn ints(el: &Element, name: &str, out: &mut [i32], required: bool) -> R<usize> {
    let Some(text) = el.attr(name) else {
        return if required {
            Err(xerr(el, &format!("required attribute missing: '{name}'")))
        } else {
            Ok(0)
        };
    };
    let mut toks = text.split_ascii_whitespace();
    let bad = || xerr(el, &format!("problem reading attribute '{name}'"));
    if toks.clone().next().is_none() {
        return Err(bad());
    }
    let mut n = 0;
    while n < out.len() {
        let Some(tok) = toks.next() else { break };
        out[n] = tok.parse().map_err(|_| bad())?;
        n += 1;
    }
    if toks.next().is_some() {
        return Err(xerr(el, &format!("attribute '{name}' has too much data")));
    }
    Ok(n)
}

/// Numbers of a free-length list attribute, read as C++ stream extraction reads them: each
/// number is the longest prefix that looks like one; reading stops at the first failure (no
/// number, or out of range).
fn list<T: ListNum>(el: &Element, name: &str) -> Option<Vec<T>> {
    let text = el.attr(name)?;
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut k = 0;
    loop {
        while k < b.len() && b[k].is_ascii_whitespace() {
            k += 1;
        }
        let start = k;
        if k < b.len() && (b[k] == b'+' || b[k] == b'-') {
            k += 1;
        }
        let digits = |k: &mut usize| {
            let s = *k;
            while *k < b.len() && b[*k].is_ascii_digit() {
                *k += 1;
            }
            *k > s
        };
        let mut any = digits(&mut k);
        if T::REAL {
            if k < b.len() && b[k] == b'.' {
                k += 1;
                any |= digits(&mut k);
            }
            if any && k < b.len() && (b[k] == b'e' || b[k] == b'E') {
                k += 1;
                if k < b.len() && (b[k] == b'+' || b[k] == b'-') {
                    k += 1;
                }
                digits(&mut k);
            }
        }
        match T::convert(&text[start..k]) {
            Some(v) if any => out.push(v),
            _ => return Some(out),
        }
    }
}

trait ListNum: Sized {
    const REAL: bool;
    fn convert(s: &str) -> Option<Self>;
}

impl ListNum for f32 {
    const REAL: bool = true;
    fn convert(s: &str) -> Option<f32> {
        s.parse::<f32>().ok().filter(|v| v.is_finite())
    }
}

impl ListNum for i32 {
    const REAL: bool = false;
    fn convert(s: &str) -> Option<i32> {
        s.parse::<i32>().ok()
    }
}

fn skin_group(el: &Element, out: &mut i32) -> R<()> {
    int(el, "group", out)?;
    if !(0..6).contains(out) {
        return Err(xerr(el, "skin group must be between 0 and 5"));
    }
    Ok(())
}

fn read_skin(el: &Element) -> R<Skin> {
    let mut s = Skin {
        line: el.line,
        ..Skin::default()
    };
    text(el, "name", &mut s.name);
    text(el, "file", &mut s.file);
    text(el, "material", &mut s.material);
    skin_group(el, &mut s.group)?;
    rgba(el, &mut s.rgba)?;
    read_nums(
        el,
        "inflate",
        std::slice::from_mut(&mut s.inflate),
        false,
        true,
    )?;
    s.vert = list(el, "vertex").unwrap_or_default();
    s.texcoord = list(el, "texcoord").unwrap_or_default();
    s.face = list(el, "face").unwrap_or_default();
    for b in el.children.iter().filter(|b| b.name == "bone") {
        let mut bone = Bone::default();
        read_text(b, "body", &mut bone.body)?;
        read_nums(b, "bindpos", &mut bone.bindpos, true, true)?;
        read_nums(b, "bindquat", &mut bone.bindquat, true, true)?;
        let mut t = String::new();
        read_text(b, "vertid", &mut t)?;
        bone.vertid = list(b, "vertid").unwrap_or_default();
        read_text(b, "vertweight", &mut t)?;
        bone.vertweight = list(b, "vertweight").unwrap_or_default();
        s.bones.push(bone);
    }
    Ok(s)
}

fn read_composite(el: &Element) -> R<Composite> {
    use composite::{JOINT, SHEAR, STRETCH, TENDON, TWIST};
    let mut c = Composite::default();
    text(el, "prefix", &mut c.prefix);
    match keyword(el, "type", &composite::TYPES)? {
        Some(k) => c.kind = k,
        None => return Err(xerr(el, "required attribute missing: 'type'")),
    }
    ints(el, "count", &mut c.count, true)?;
    read_nums(
        el,
        "spacing",
        std::slice::from_mut(&mut c.spacing),
        true,
        true,
    )?;
    nums(el, "offset", &mut c.offset)?;
    num(el, "flatinertia", &mut c.flatinertia)?;
    if let Some(e) = el.children.iter().find(|e| e.name == "skin") {
        let mut s = CompSkin::default();
        if let Some(b) = boolean(e, "texcoord")? {
            s.texcoord = b;
        }
        text(e, "material", &mut s.material);
        rgba(e, &mut s.rgba)?;
        read_nums(
            e,
            "inflate",
            std::slice::from_mut(&mut s.inflate),
            false,
            true,
        )?;
        int(e, "subgrid", &mut s.subgrid)?;
        skin_group(e, &mut s.group)?;
        c.skin = Some(s);
    }
    c.set_defaults();
    some_nums(el, "solrefsmooth", &mut c.solref_smooth)?;
    some_nums(el, "solimpsmooth", &mut c.solimp_smooth)?;
    if let Some(e) = el.children.iter().find(|e| e.name == "geom") {
        let g = &mut c.geom;
        if let Some(i) = keyword(e, "type", &GEOM_TYPES)? {
            g.kind = i as i32;
        }
        some_nums(e, "size", &mut g.size)?;
        int(e, "contype", &mut g.contype)?;
        int(e, "conaffinity", &mut g.conaffinity)?;
        int(e, "condim", &mut g.condim)?;
        int(e, "group", &mut g.group)?;
        int(e, "priority", &mut g.priority)?;
        some_nums(e, "friction", &mut g.friction)?;
        num(e, "solmix", &mut g.solmix)?;
        some_nums(e, "solref", &mut g.solref)?;
        some_nums(e, "solimp", &mut g.solimp)?;
        num(e, "margin", &mut g.margin)?;
        num(e, "gap", &mut g.gap)?;
        text(e, "material", &mut g.material);
        rgba(e, &mut g.rgba)?;
        num(e, "mass", &mut g.mass)?;
        num(e, "density", &mut g.density)?;
    }
    if let Some(e) = el.children.iter().find(|e| e.name == "site") {
        let s = &mut c.site;
        some_nums(e, "size", &mut s.size)?;
        int(e, "group", &mut s.group)?;
        text(e, "material", &mut s.material);
        rgba(e, &mut s.rgba)?;
    }
    // `limited` of joints and tendons is not read by 2.2.2
    for e in el.children.iter().filter(|e| e.name == "joint") {
        let k = match keyword(e, "kind", &["main", "twist", "stretch"])? {
            Some(k) => [JOINT, TWIST, STRETCH][k],
            None => return Err(xerr(e, "required attribute missing: 'kind'")),
        };
        c.add[k] = true;
        let eq = &mut c.equalities[k];
        some_nums(e, "solreffix", &mut eq.solref)?;
        some_nums(e, "solimpfix", &mut eq.solimp)?;
        let j = &mut c.joints[k];
        int(e, "group", &mut j.group)?;
        some_nums(e, "solreflimit", &mut j.solref_limit)?;
        some_nums(e, "solimplimit", &mut j.solimp_limit)?;
        some_nums(e, "solreffriction", &mut j.solref_friction)?;
        some_nums(e, "solimpfriction", &mut j.solimp_friction)?;
        num(e, "stiffness", &mut j.stiffness)?;
        nums(e, "range", &mut j.range)?;
        num(e, "margin", &mut j.margin)?;
        num(e, "armature", &mut j.armature)?;
        num(e, "damping", &mut j.damping)?;
        num(e, "frictionloss", &mut j.frictionloss)?;
    }
    for e in el.children.iter().filter(|e| e.name == "tendon") {
        let k = match keyword(e, "kind", &["main", "shear"])? {
            Some(k) => [TENDON, SHEAR][k],
            None => return Err(xerr(e, "required attribute missing: 'kind'")),
        };
        c.add[k] = true;
        let eq = &mut c.equalities[k];
        some_nums(e, "solreffix", &mut eq.solref)?;
        some_nums(e, "solimpfix", &mut eq.solimp)?;
        let t = &mut c.tendons[k];
        int(e, "group", &mut t.group)?;
        some_nums(e, "solreflimit", &mut t.solref_limit)?;
        some_nums(e, "solimplimit", &mut t.solimp_limit)?;
        some_nums(e, "solreffriction", &mut t.solref_friction)?;
        some_nums(e, "solimpfriction", &mut t.solimp_friction)?;
        nums(e, "range", &mut t.range)?;
        num(e, "margin", &mut t.margin)?;
        num(e, "stiffness", &mut t.stiffness)?;
        num(e, "damping", &mut t.damping)?;
        num(e, "frictionloss", &mut t.frictionloss)?;
        text(e, "material", &mut t.material);
        rgba(e, &mut t.rgba)?;
        num(e, "width", &mut t.width)?;
    }
    for e in el.children.iter().filter(|e| e.name == "pin") {
        let mut coord = [0; 2];
        ints(e, "coord", &mut coord, true)?;
        c.pin.extend_from_slice(&coord);
    }
    Ok(c)
}

fn read_compiler(spec: &mut ModelSpec, el: &Element) -> R<()> {
    let c = &mut spec.compiler;
    if let Some(b) = boolean(el, "autolimits")? {
        c.autolimits = b;
    }
    num(el, "boundmass", &mut c.boundmass)?;
    num(el, "boundinertia", &mut c.boundinertia)?;
    num(el, "settotalmass", &mut c.settotalmass)?;
    if let Some(b) = boolean(el, "balanceinertia")? {
        c.balanceinertia = b;
    }
    for flag in [
        "strippath",
        "fitaabb",
        "convexhull",
        "usethread",
        "fusestatic",
        "exactmeshinertia",
    ] {
        if let Some(b) = boolean(el, flag)? {
            match flag {
                "strippath" => c.strippath = b,
                "convexhull" => c.convexhull = b,
                "exactmeshinertia" => c.exactmeshinertia = b,
                "fitaabb" => c.fitaabb = b,
                "fusestatic" => c.fusestatic = b,
                _ => {}
            }
        }
    }
    text(el, "meshdir", &mut c.meshdir);
    text(el, "texturedir", &mut c.texturedir);
    if let Some(i) = keyword(el, "coordinate", &["local", "global"])? {
        c.global = i == 1;
    }
    if let Some(i) = keyword(el, "angle", &["radian", "degree"])? {
        c.degree = i == 1;
    }
    if let Some(seq) = el.attr("eulerseq") {
        if seq.len() != 3 {
            return Err(xerr(el, "euler format must have length 3"));
        }
        c.eulerseq.copy_from_slice(seq.as_bytes());
    }
    if let Some(b) = boolean(el, "discardvisual")? {
        c.discardvisual = b;
    }
    if let Some(i) = keyword(el, "inertiafromgeom", &["false", "true", "auto"])? {
        c.inertiafromgeom = [
            InertiaFromGeom::False,
            InertiaFromGeom::True,
            InertiaFromGeom::Auto,
        ][i];
    }
    let mut range = [0.0f64; 2];
    if nums(el, "inertiagrouprange", &mut range)? {
        c.inertiagrouprange = range.map(|x| x as i32);
    }
    if let Some(lr) = el.children.iter().find(|x| x.name == "lengthrange") {
        if let Some(i) = keyword(lr, "mode", &["none", "muscle", "muscleuser", "all"])? {
            c.lr_mode = i as i32;
        }
        if let Some(b) = boolean(lr, "useexisting")? {
            c.lr_useexisting = b;
        }
        if let Some(b) = boolean(lr, "uselimit")? {
            c.lr_uselimit = b;
        }
        for (k, n) in [
            "accel",
            "maxforce",
            "timeconst",
            "timestep",
            "inttotal",
            "inteval",
            "tolrange",
        ]
        .into_iter()
        .enumerate()
        {
            num(lr, n, &mut c.lr_numbers[k])?;
        }
    }
    Ok(())
}

fn read_option(spec: &mut ModelSpec, el: &Element) -> R<()> {
    let o = &mut spec.option;
    num(el, "timestep", &mut o.timestep)?;
    num(el, "apirate", &mut o.apirate)?;
    num(el, "impratio", &mut o.impratio)?;
    num(el, "tolerance", &mut o.tolerance)?;
    num(el, "noslip_tolerance", &mut o.noslip_tolerance)?;
    num(el, "mpr_tolerance", &mut o.mpr_tolerance)?;
    nums(el, "gravity", &mut o.gravity)?;
    nums(el, "wind", &mut o.wind)?;
    nums(el, "magnetic", &mut o.magnetic)?;
    num(el, "density", &mut o.density)?;
    num(el, "viscosity", &mut o.viscosity)?;
    num(el, "o_margin", &mut o.o_margin)?;
    some_nums(el, "o_solref", &mut o.o_solref)?;
    some_nums(el, "o_solimp", &mut o.o_solimp)?;
    let kws: [(&str, &[&str], &mut i32); 5] = [
        (
            "integrator",
            &["Euler", "RK4", "implicit"],
            &mut o.integrator,
        ),
        (
            "collision",
            &["all", "predefined", "dynamic"],
            &mut o.collision,
        ),
        ("cone", &["pyramidal", "elliptic"], &mut o.cone),
        ("jacobian", &["dense", "sparse", "auto"], &mut o.jacobian),
        ("solver", &["PGS", "CG", "Newton"], &mut o.solver),
    ];
    for (name, keys, out) in kws {
        if let Some(i) = keyword(el, name, keys)? {
            *out = i as i32;
        }
    }
    int(el, "iterations", &mut o.iterations)?;
    int(el, "noslip_iterations", &mut o.noslip_iterations)?;
    int(el, "mpr_iterations", &mut o.mpr_iterations)?;
    let flags: Vec<&Element> = el.children.iter().filter(|c| c.name == "flag").collect();
    if flags.len() > 1 {
        return Err(xerr(flags[1], "repeated element: 'flag'"));
    }
    if let Some(f) = flags.first() {
        const DISABLE: [&str; 13] = [
            "constraint",
            "equality",
            "frictionloss",
            "limit",
            "contact",
            "passive",
            "gravity",
            "clampctrl",
            "warmstart",
            "filterparent",
            "actuation",
            "refsafe",
            "sensor",
        ];
        const ENABLE: [&str; 5] = ["override", "energy", "fwdinv", "sensornoise", "multiccd"];
        for (bit, name) in DISABLE.iter().enumerate() {
            if let Some(on) = keyword(f, name, &["disable", "enable"])? {
                let mask = 1 << bit;
                o.disableflags = if on == 1 {
                    o.disableflags & !mask
                } else {
                    o.disableflags | mask
                };
            }
        }
        for (bit, name) in ENABLE.iter().enumerate() {
            if let Some(on) = keyword(f, name, &["disable", "enable"])? {
                let mask = 1 << bit;
                o.enableflags = if on == 1 {
                    o.enableflags | mask
                } else {
                    o.enableflags & !mask
                };
            }
        }
    }
    Ok(())
}

fn read_size(spec: &mut ModelSpec, el: &Element) -> R<()> {
    int(el, "njmax", &mut spec.njmax)?;
    int(el, "nconmax", &mut spec.nconmax)?;
    int(el, "nstack", &mut spec.nstack)?;
    int(el, "nuserdata", &mut spec.nuserdata)?;
    int(el, "nkey", &mut spec.nkey)?;
    let names = [
        "body", "jnt", "geom", "site", "cam", "tendon", "actuator", "sensor",
    ];
    for (i, n) in names.iter().enumerate() {
        let attr = format!("nuser_{n}");
        int(el, &attr, &mut spec.nuser[i])?;
        if spec.nuser[i] < -1 {
            return Err(xerr(el, &format!("{attr} must be >= -1")));
        }
    }
    Ok(())
}

fn f1(el: &Element, name: &str, out: &mut f32) -> R<()> {
    read_nums(el, name, std::slice::from_mut(out), false, true).map(|_| ())
}

fn read_visual(spec: &mut ModelSpec, el: &Element) -> R<()> {
    let v = &mut spec.visual;
    for c in &el.children {
        match c.name.as_str() {
            "global" => {
                let g = &mut v.global;
                for (n, out) in [
                    ("fovy", &mut g.fovy),
                    ("ipd", &mut g.ipd),
                    ("azimuth", &mut g.azimuth),
                    ("elevation", &mut g.elevation),
                    ("linewidth", &mut g.linewidth),
                    ("glow", &mut g.glow),
                ] {
                    f1(c, n, out)?;
                }
                int(c, "offwidth", &mut g.offwidth)?;
                int(c, "offheight", &mut g.offheight)?;
            }
            "quality" => {
                let q = &mut v.quality;
                int(c, "shadowsize", &mut q.shadowsize)?;
                int(c, "offsamples", &mut q.offsamples)?;
                int(c, "numslices", &mut q.numslices)?;
                int(c, "numstacks", &mut q.numstacks)?;
                int(c, "numquads", &mut q.numquads)?;
            }
            "headlight" => {
                let h = &mut v.headlight;
                floats(c, "ambient", &mut h.ambient)?;
                floats(c, "diffuse", &mut h.diffuse)?;
                floats(c, "specular", &mut h.specular)?;
                int(c, "active", &mut h.active)?;
            }
            "map" => {
                let m = &mut v.map;
                for (n, out) in [
                    ("stiffness", &mut m.stiffness),
                    ("stiffnessrot", &mut m.stiffnessrot),
                    ("force", &mut m.force),
                    ("torque", &mut m.torque),
                    ("alpha", &mut m.alpha),
                    ("fogstart", &mut m.fogstart),
                    ("fogend", &mut m.fogend),
                    ("znear", &mut m.znear),
                    ("zfar", &mut m.zfar),
                    ("haze", &mut m.haze),
                    ("shadowclip", &mut m.shadowclip),
                    ("shadowscale", &mut m.shadowscale),
                    ("actuatortendon", &mut m.actuatortendon),
                ] {
                    f1(c, n, out)?;
                }
            }
            "scale" => {
                let m = &mut v.scale;
                for (n, out) in [
                    ("forcewidth", &mut m.forcewidth),
                    ("contactwidth", &mut m.contactwidth),
                    ("contactheight", &mut m.contactheight),
                    ("connect", &mut m.connect),
                    ("com", &mut m.com),
                    ("camera", &mut m.camera),
                    ("light", &mut m.light),
                    ("selectpoint", &mut m.selectpoint),
                    ("jointlength", &mut m.jointlength),
                    ("jointwidth", &mut m.jointwidth),
                    ("actuatorlength", &mut m.actuatorlength),
                    ("actuatorwidth", &mut m.actuatorwidth),
                    ("framelength", &mut m.framelength),
                    ("framewidth", &mut m.framewidth),
                    ("constraint", &mut m.constraint),
                    ("slidercrank", &mut m.slidercrank),
                ] {
                    f1(c, n, out)?;
                }
            }
            "rgba" => {
                let r = &mut v.rgba;
                for (n, out) in [
                    ("fog", &mut r.fog),
                    ("haze", &mut r.haze),
                    ("force", &mut r.force),
                    ("inertia", &mut r.inertia),
                    ("joint", &mut r.joint),
                    ("actuator", &mut r.actuator),
                    ("actuatornegative", &mut r.actuatornegative),
                    ("actuatorpositive", &mut r.actuatorpositive),
                    ("com", &mut r.com),
                    ("camera", &mut r.camera),
                    ("light", &mut r.light),
                    ("selectpoint", &mut r.selectpoint),
                    ("connect", &mut r.connect),
                    ("contactpoint", &mut r.contactpoint),
                    ("contactforce", &mut r.contactforce),
                    ("contactfriction", &mut r.contactfriction),
                    ("contacttorque", &mut r.contacttorque),
                    ("contactgap", &mut r.contactgap),
                    ("rangefinder", &mut r.rangefinder),
                    ("constraint", &mut r.constraint),
                    ("slidercrank", &mut r.slidercrank),
                    ("crankbroken", &mut r.crankbroken),
                ] {
                    floats(c, n, out)?;
                }
            }
            _ => {}
        }
    }
    Ok(())
}

fn read_statistic(spec: &mut ModelSpec, el: &Element) -> R<()> {
    for (i, n) in ["meaninertia", "meanmass", "meansize", "extent"]
        .iter()
        .enumerate()
    {
        num(el, n, &mut spec.stat_override[i])?;
    }
    nums(el, "center", &mut spec.center)?;
    Ok(())
}

fn read_keys(spec: &mut ModelSpec, el: &Element) -> R<()> {
    for k in &el.children {
        let mut key = Key::default();
        text(k, "name", &mut key.name);
        num(k, "time", &mut key.time)?;
        let mut buf = vec![0.0; 1000];
        let fields: [(&str, &mut Vec<f64>); 6] = [
            ("qpos", &mut key.qpos),
            ("qvel", &mut key.qvel),
            ("act", &mut key.act),
            ("mpos", &mut key.mpos),
            ("mquat", &mut key.mquat),
            ("ctrl", &mut key.ctrl),
        ];
        for (name, out) in fields {
            let n = some_nums(k, name, &mut buf)?;
            if n > 0 {
                *out = buf[..n].to_vec();
            }
        }
        spec.keys.push(key);
    }
    Ok(())
}

/// Reads a checked MJCF tree.
pub fn read(root: &Element) -> R<ModelSpec> {
    let mut spec = ModelSpec::default();
    text(root, "model", &mut spec.modelname);
    let sections = |name: &'static str| root.children.iter().filter(move |c| c.name == name);
    for s in sections("compiler") {
        read_compiler(&mut spec, s)?;
    }
    for s in sections("option") {
        read_option(&mut spec, s)?;
    }
    for s in sections("size") {
        read_size(&mut spec, s)?;
    }
    for s in sections("visual") {
        read_visual(&mut spec, s)?;
    }
    for s in sections("statistic") {
        read_statistic(&mut spec, s)?;
    }
    for s in sections("default") {
        read_default(&mut spec, s, None)?;
    }
    for s in sections("custom") {
        read_custom(&mut spec, s)?;
    }
    for s in sections("asset") {
        read_assets(&mut spec, s)?;
    }
    for s in sections("worldbody") {
        let mut world = std::mem::take(&mut spec.world);
        let mut added = Added::default();
        let r = read_body(&spec, s, &mut world, 0, true, &mut added);
        spec.world = world;
        r?;
        spec.tendons.extend(added.tendons);
        spec.equalities.extend(added.equalities);
        spec.excludes.extend(added.excludes);
        spec.skins.extend(added.skins);
    }
    for s in sections("contact") {
        read_contact(&mut spec, s)?;
    }
    for s in sections("equality") {
        for c in &s.children {
            let def = class_of(&spec, c)?.unwrap_or(0);
            let mut e = spec.defaults[def].equality.clone();
            one_equality(c, &mut e, false)?;
            spec.equalities.push(e);
        }
    }
    for s in sections("tendon") {
        read_tendons(&mut spec, s)?;
    }
    for s in sections("actuator") {
        for a in &s.children {
            let def = class_of(&spec, a)?.unwrap_or(0);
            let mut act = spec.defaults[def].actuator.clone();
            if !ACTUATORS.contains(&a.name.as_str()) {
                return Err(unsupported(a, &a.name));
            }
            one_actuator(a, &mut act)?;
            spec.actuators.push(act);
        }
    }
    for s in sections("sensor") {
        read_sensors(&mut spec, s)?;
    }
    for s in sections("keyframe") {
        read_keys(&mut spec, s)?;
    }
    const KNOWN: [&str; 15] = [
        "compiler",
        "option",
        "size",
        "visual",
        "statistic",
        "default",
        "worldbody",
        "asset",
        "custom",
        "contact",
        "equality",
        "tendon",
        "actuator",
        "sensor",
        "keyframe",
    ];
    for c in &root.children {
        if !KNOWN.contains(&c.name.as_str()) && !c.children.is_empty() {
            return Err(unsupported(c, &c.name));
        }
    }
    Ok(spec)
}
