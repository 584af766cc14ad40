//! URDF (root `<robot>`) to an MJCF element tree, with the conventions 2.2.2 applies: links
//! become bodies placed by their parent joint, a link named `world` is the world body,
//! visual geometry is dropped unless `discardvisual` is off, materials become geom colors,
//! and the `<mujoco>` child may carry compiler, option and size settings.

use super::tree::Element;
use crate::compiler::frame::{mulquat_unit, quat2mat, z2quat};
use crate::compiler::objects::{alt_set, Settings};
use crate::compiler::spec::Alt;

fn err(el: &Element, msg: &str) -> String {
    format!(
        "XML Error: {msg}\nElement '{}', line {}\n",
        el.name, el.line
    )
}

/// A generated element; like 2.2.2's URDF objects it has no source line (`_line` documents it).
fn new_el(name: &str, _line: i32) -> Element {
    Element {
        name: name.into(),
        attrs: Vec::new(),
        children: Vec::new(),
        line: -1,
    }
}

fn child<'a>(el: &'a Element, name: &str) -> Option<&'a Element> {
    el.children.iter().find(|c| c.name == name)
}

fn need_child<'a>(el: &'a Element, name: &str) -> Result<&'a Element, String> {
    child(el, name).ok_or_else(|| err(el, &format!("required sub-element missing: '{name}'")))
}

fn need_attr<'a>(el: &'a Element, key: &str) -> Result<&'a str, String> {
    el.attr(key)
        .ok_or_else(|| err(el, &format!("required attribute missing: '{key}'")))
}

/// `N` numbers of attribute `key` (None when absent), read as 2.2.2 reads attributes (exact
/// count; `_exact` documents the call site).
fn nums<const N: usize>(el: &Element, key: &str, _exact: bool) -> Result<Option<[f64; N]>, String> {
    let mut out = [0.0; N];
    let n = super::reader::read_nums(el, key, &mut out, false, true)?;
    Ok((n > 0).then_some(out))
}

fn req_nums<const N: usize>(el: &Element, key: &str, _exact: bool) -> Result<[f64; N], String> {
    let mut out = [0.0; N];
    super::reader::read_nums(el, key, &mut out, true, true)?;
    Ok(out)
}

fn text(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:?}"))
        .collect::<Vec<_>>()
        .join(" ")
}

fn boolean(el: Option<&Element>, key: &str, default: bool) -> bool {
    match el.and_then(|e| e.attr(key)) {
        Some("true") => true,
        Some("false") => false,
        _ => default,
    }
}

/// `<origin xyz rpy>` of `el` as position and unit quaternion (rpy: fixed X, Y, Z axes).
fn origin(el: &Element) -> Result<([f64; 3], [f64; 4]), String> {
    let mut pos = [0.0; 3];
    let mut quat = [1.0, 0.0, 0.0, 0.0];
    if let Some(o) = child(el, "origin") {
        if let Some(p) = nums::<3>(o, "xyz", false)? {
            pos = p;
        }
        if let Some(rpy) = nums::<3>(o, "rpy", false)? {
            let alt = Alt {
                euler: rpy,
                ..Alt::default()
            };
            let s = Settings {
                degree: false,
                eulerseq: b"XYZ",
            };
            alt_set(&alt, &mut quat, None, &s).map_err(|e| err(o, e))?;
        }
    }
    Ok((pos, quat))
}

fn set_pose(el: &mut Element, pos: &[f64; 3], quat: &[f64; 4], pos_key: &str, quat_key: &str) {
    el.attrs.push((pos_key.into(), text(pos)));
    el.attrs.push((quat_key.into(), text(quat)));
}

/// Material name to color, first definition with a color wins, searched through the document.
fn materials(el: &Element, out: &mut Vec<(String, [f32; 4])>) -> Result<(), String> {
    if el.name == "material" {
        if let Some(name) = el.attr("name") {
            if !out.iter().any(|(n, _)| n == name) {
                if let Some(color) = child(el, "color") {
                    out.push((name.to_string(), rgba(color)?));
                }
            }
        }
    }
    for c in &el.children {
        materials(c, out)?;
    }
    Ok(())
}

fn rgba(color: &Element) -> Result<[f32; 4], String> {
    let mut out = [0.0f32; 4];
    super::reader::read_nums(color, "rgba", &mut out, true, true)?;
    Ok(out)
}

struct Converter {
    strippath: bool,
    discardvisual: bool,
    materials: Vec<(String, [f32; 4])>,
    /// Mesh assets: name, file, scale.
    meshes: Vec<(String, String, [f64; 3])>,
}

fn strip_path(f: &str) -> &str {
    f.rfind(['/', '\\']).map_or(f, |p| &f[p + 1..])
}

impl Converter {
    fn geom(&mut self, g: &Element, collision: bool) -> Result<Element, String> {
        let geometry = need_child(g, "geometry")?;
        let mut out = new_el("geom", g.line);
        let (kind, size): (&str, Vec<f64>) = if let Some(b) = child(geometry, "box") {
            (
                "box",
                req_nums::<3>(b, "size", true)?.map(|x| x / 2.0).to_vec(),
            )
        } else if let Some(c) = child(geometry, "cylinder") {
            let r = req_nums::<1>(c, "radius", true)?[0];
            let l = req_nums::<1>(c, "length", true)?[0];
            ("cylinder", vec![r, l / 2.0])
        } else if let Some(s) = child(geometry, "sphere") {
            ("sphere", req_nums::<1>(s, "radius", true)?.to_vec())
        } else if let Some(m) = child(geometry, "mesh") {
            let mut file = need_attr(m, "filename")?.to_string();
            let scale = nums::<3>(m, "scale", false)?.unwrap_or([1.0; 3]);
            if self.strippath {
                file = strip_path(&file).to_string();
            }
            let base = strip_path(&file);
            let mut name = base.rfind('.').map_or(base, |p| &base[..p]).to_string();
            let file = file.clone();
            match self.meshes.iter_mut().find(|(n, _, _)| *n == name) {
                None => self.meshes.push((name.clone(), file, scale)),
                // same mesh again: 2.2.2 reuses it and takes the newer file name
                Some(m) if m.2 == scale => m.1 = file,
                Some(_) => {
                    name.push('1');
                    self.meshes.push((name.clone(), file, scale));
                }
            }
            out.attrs.push(("mesh".into(), name));
            ("mesh", Vec::new())
        } else {
            return Err(err(geometry, "visual geometry specification not found"));
        };
        out.attrs.push(("type".into(), kind.into()));
        if !size.is_empty() {
            out.attrs.push(("size".into(), text(&size)));
        }
        if collision {
            out.attrs.push(("contype".into(), "1".into()));
            out.attrs.push(("conaffinity".into(), "1".into()));
        } else {
            for (k, v) in [
                ("contype", "0"),
                ("conaffinity", "0"),
                ("group", "1"),
                ("density", "0"),
            ] {
                out.attrs.push((k.into(), v.into()));
            }
        }
        let (pos, quat) = origin(g)?;
        set_pose(&mut out, &pos, &quat, "pos", "quat");
        Ok(out)
    }

    /// Inertial and geoms of one link, in document order.
    fn link(&mut self, link: &Element, body: &mut Element, is_world: bool) -> Result<(), String> {
        if let (Some(inertial), false) = (child(link, "inertial"), is_world) {
            let (pos, oquat) = origin(inertial)?;
            let mass = req_nums::<1>(need_child(inertial, "mass")?, "value", false)?[0];
            let ie = need_child(inertial, "inertia")?;
            let mut full = [0.0; 6];
            for (f, k) in full
                .iter_mut()
                .zip(["ixx", "iyy", "izz", "ixy", "ixz", "iyz"])
            {
                *f = req_nums::<1>(ie, k, false)?[0];
            }
            let alt = Alt {
                fullinertia: full,
                ..Alt::default()
            };
            let mut lquat = [1.0, 0.0, 0.0, 0.0];
            let mut diag = [0.0; 3];
            let s = Settings {
                degree: false,
                eulerseq: b"xyz",
            };
            // 2.2.2 ignores an inertia without positive eigenvalues here
            let _ = alt_set(&alt, &mut lquat, Some(&mut diag), &s);
            let iquat = mulquat_unit(&oquat, &lquat);
            let mut el = new_el("inertial", inertial.line);
            set_pose(&mut el, &pos, &iquat, "pos", "quat");
            el.attrs.push(("mass".into(), text(&[mass])));
            el.attrs.push(("diaginertia".into(), text(&diag)));
            body.children.push(el);
        }
        let mut color: Option<[f32; 4]> = None;
        for c in &link.children {
            let collision = c.name == "collision";
            if c.name == "visual" {
                if let Some(m) = child(c, "material") {
                    if let Some(col) = child(m, "color") {
                        color = Some(rgba(col)?);
                    } else {
                        let name = need_attr(m, "name")?;
                        if let Some((_, v)) = self.materials.iter().find(|(n, _)| n == name) {
                            color = Some(*v);
                        }
                    }
                }
                if self.discardvisual {
                    continue;
                }
            } else if !collision {
                continue;
            }
            let mut g = self.geom(c, collision)?;
            // 2.2.2 marks "no color" by a negative red
            if let Some(v) = color.filter(|v| v[0] >= 0.0) {
                let v = v.map(|x| x as f64);
                g.attrs.push(("rgba".into(), text(&v)));
            }
            body.children.push(g);
        }
        Ok(())
    }
}

/// Parent joint of a link: pose of the child body and its joints.
fn joint(j: &Element, body: &mut Element) -> Result<(), String> {
    let kind = need_attr(j, "type")?;
    let name = need_attr(j, "name")?;
    let (pos, quat) = origin(j)?;
    set_pose(body, &pos, &quat, "pos", "quat");
    let axis = match child(j, "axis") {
        Some(a) => req_nums::<3>(a, "xyz", false)?,
        None => [1.0, 0.0, 0.0],
    };
    let mk = |name: String, kind: &str, axis: Option<[f64; 3]>| {
        let mut el = new_el("joint", j.line);
        el.attrs.push(("name".into(), name));
        el.attrs.push(("type".into(), kind.into()));
        if let Some(a) = axis {
            el.attrs.push(("pos".into(), "0 0 0".into()));
            el.attrs.push(("axis".into(), text(&a)));
        }
        el
    };
    let mut joints = match kind {
        "revolute" | "continuous" => vec![mk(name.into(), "hinge", Some(axis))],
        "prismatic" => vec![mk(name.into(), "slide", Some(axis))],
        "floating" => vec![mk(name.into(), "free", None)],
        "planar" => {
            let mat = quat2mat(&z2quat(&axis));
            vec![
                mk(
                    format!("{name}_TX"),
                    "slide",
                    Some([mat[0], mat[3], mat[6]]),
                ),
                mk(
                    format!("{name}_TY"),
                    "slide",
                    Some([mat[1], mat[4], mat[7]]),
                ),
                mk(format!("{name}_RZ"), "hinge", Some(axis)),
            ]
        }
        "fixed" => return Ok(()),
        // 2.2.2 crashes on an unknown type; it is an error here
        _ => return Err(err(j, "invalid joint type in URDF joint definition")),
    };
    if let Some(d) = child(j, "dynamics") {
        let damping = nums::<1>(d, "damping", false)?;
        let friction = nums::<1>(d, "friction", false)?;
        for (i, el) in joints.iter_mut().enumerate() {
            // the first joint takes both; the others of a planar joint copy them (0 if unset)
            if let Some(v) = damping.map(|v| v[0]).or((i > 0).then_some(0.0)) {
                el.attrs.push(("damping".into(), text(&[v])));
            }
            if let Some(v) = friction.map(|v| v[0]).or((i > 0).then_some(0.0)) {
                el.attrs.push(("frictionloss".into(), text(&[v])));
            }
        }
    }
    let first = &mut joints[0];
    match child(j, "limit") {
        Some(l) => {
            let lo = nums::<1>(l, "lower", false)?.map_or(0.0, |v| v[0]);
            let hi = nums::<1>(l, "upper", false)?.map_or(0.0, |v| v[0]);
            let limited = !lo.is_nan() && !hi.is_nan() && lo < hi;
            // effort only bounds actuators, which URDF cannot define; read for its errors
            nums::<1>(l, "effort", false)?;
            first.attrs.push(("range".into(), text(&[lo, hi])));
            first.attrs.push(("limited".into(), limited.to_string()));
        }
        None => first.attrs.push(("limited".into(), "false".into())),
    }
    // the other joints of a planar joint keep the default limited flag
    body.children.extend(joints);
    Ok(())
}

/// Converts a URDF document (root `<robot>`) to the MJCF tree 2.2.2 would build.
pub fn convert(robot: &Element) -> Result<Element, String> {
    let mjc = child(robot, "mujoco");
    let user_compiler = mjc.and_then(|m| child(m, "compiler"));
    let mut conv = Converter {
        strippath: boolean(user_compiler, "strippath", true),
        discardvisual: boolean(user_compiler, "discardvisual", true),
        materials: Vec::new(),
        meshes: Vec::new(),
    };
    let fusestatic = boolean(user_compiler, "fusestatic", true);
    materials(robot, &mut conv.materials)?;

    let mut root = new_el("mujoco", robot.line);
    if let Some(name) = robot.attr("name") {
        root.attrs.push(("model".into(), name.into()));
    }
    let mut defaults = new_el("compiler", robot.line);
    defaults.attrs.push(("strippath".into(), "true".into()));
    defaults.attrs.push(("discardvisual".into(), "true".into()));
    let fuse = if fusestatic { "true" } else { "false" };
    defaults.attrs.push(("fusestatic".into(), fuse.into()));
    root.children.push(defaults);
    if let Some(c) = user_compiler {
        let mut c = c.clone();
        c.attrs.retain(|(k, _)| k != "fusestatic");
        root.children.push(c);
    }
    let mut frame = new_el("compiler", robot.line);
    frame.attrs.push(("coordinate".into(), "local".into()));
    frame.attrs.push(("angle".into(), "radian".into()));
    root.children.push(frame);
    for sec in ["option", "size"] {
        if let Some(s) = mjc.and_then(|m| child(m, sec)) {
            root.children.push(s.clone());
        }
    }

    // link tree from the joints
    let links: Vec<&Element> = robot.children.iter().filter(|c| c.name == "link").collect();
    let mut names: Vec<&str> = Vec::new();
    for l in &links {
        let n = need_attr(l, "name")?;
        if names.contains(&n) {
            return Err("XML Error: repeated URDF name: ".into());
        }
        names.push(n);
    }
    let mut parent: Vec<Option<usize>> = vec![None; links.len()];
    let mut parent_joint: Vec<Option<&Element>> = vec![None; links.len()];
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); links.len()];
    for j in robot.children.iter().filter(|c| c.name == "joint") {
        let p = need_attr(need_child(j, "parent")?, "link")?;
        let c = need_attr(need_child(j, "child")?, "link")?;
        let (Some(ip), Some(ic)) = (
            names.iter().position(|n| *n == p),
            names.iter().position(|n| *n == c),
        ) else {
            return Err(err(j, "URDF joint parent or child missing"));
        };
        if parent[ic].is_some() {
            return Err(err(j, "URDF body has multiple parents:"));
        }
        if c == "world" {
            return Err(err(j, "a parent of the URDF world link is not implemented"));
        }
        parent[ic] = Some(ip);
        parent_joint[ic] = Some(j);
        children[ip].push(ic);
    }

    let mut world = new_el("worldbody", robot.line);
    // links not reached from a root (a cycle) are never placed, as in 2.2.2
    for (i, p) in parent.iter().enumerate() {
        if p.is_none() {
            let tree = Tree {
                links: &links,
                names: &names,
                parent_joint: &parent_joint,
                children: &children,
            };
            tree.build(i, &mut conv, &mut world)?;
        }
    }
    if !conv.meshes.is_empty() {
        let mut asset = new_el("asset", robot.line);
        for (name, file, scale) in &conv.meshes {
            let mut m = new_el("mesh", robot.line);
            m.attrs.push(("name".into(), name.clone()));
            m.attrs.push(("file".into(), file.clone()));
            m.attrs.push(("scale".into(), text(scale)));
            asset.children.push(m);
        }
        root.children.push(asset);
    }
    root.children.push(world);
    Ok(root)
}

struct Tree<'a> {
    links: &'a [&'a Element],
    names: &'a [&'a str],
    parent_joint: &'a [Option<&'a Element>],
    children: &'a [Vec<usize>],
}

impl Tree<'_> {
    /// Writes link `i` and its subtree into `out`: a body per link (static links are fused by
    /// the compiler's `fusestatic`, which the conversion turns on unless the model turns it off).
    fn build(&self, i: usize, conv: &mut Converter, out: &mut Element) -> Result<(), String> {
        let link = self.links[i];
        if self.names[i] == "world" {
            conv.link(link, out, true)?;
            for &c in &self.children[i] {
                self.build(c, conv, out)?;
            }
            return Ok(());
        }
        let mut body = new_el("body", link.line);
        body.attrs.push(("name".into(), self.names[i].into()));
        if let Some(j) = self.parent_joint[i] {
            joint(j, &mut body)?;
        }
        conv.link(link, &mut body, false)?;
        for &c in &self.children[i] {
            self.build(c, conv, &mut body)?;
        }
        out.children.push(body);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meshes_become_assets_named_after_their_files() {
        let src = r#"<robot name="m"><link name="world"/><link name="a">
            <collision><geometry><mesh filename="package://p/meshes/part.stl" scale="2 2 2"/></geometry></collision>
            <collision><geometry><mesh filename="package://p/meshes/part.stl" scale="3 2 2"/></geometry></collision>
            <collision><geometry><mesh filename="other/part.stl" scale="2 2 2"/></geometry></collision>
            </link><joint name="j" type="floating"><parent link="world"/><child link="a"/></joint></robot>"#;
        let mjcf = convert(&crate::xml::tree::parse(src).unwrap()).unwrap();
        let asset = mjcf.children.iter().find(|c| c.name == "asset").unwrap();
        let meshes: Vec<(&str, &str, &str)> = asset
            .children
            .iter()
            .map(|m| {
                (
                    m.attr("name").unwrap(),
                    m.attr("file").unwrap(),
                    m.attr("scale").unwrap(),
                )
            })
            .collect();
        assert_eq!(
            meshes,
            [
                ("part", "part.stl", "2.0 2.0 2.0"),
                ("part1", "part.stl", "3.0 2.0 2.0")
            ]
        );
        let world = mjcf
            .children
            .iter()
            .find(|c| c.name == "worldbody")
            .unwrap();
        let geoms: Vec<&str> = world.children[0]
            .children
            .iter()
            .filter_map(|g| g.attr("mesh"))
            .collect();
        assert_eq!(geoms, ["part", "part1", "part"]);
    }
}
