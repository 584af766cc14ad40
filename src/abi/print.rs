//! Text dump of a model in 2.2.2's `mj_printModel` layout: sizes, options, statistics, then every
//! array of the X-macro list grouped by the object it describes.

use super::view::Model;
use super::*;
use std::ffi::CString;
use std::fmt::Write as _;

/// Default number format of the dumps.
pub const FLOAT_FORMAT: &str = "% -9.2g";
const NAME_WIDTH: usize = 21;

/// One array of the model, typed for printing.
enum Column<'a> {
    Real(&'a [f64]),
    Single(&'a [f32]),
    Int(&'a [i32]),
    Byte(&'a [u8]),
    Text,
}

macro_rules! column {
    (mjtNum, $e:expr) => {
        Column::Real($e)
    };
    (float, $e:expr) => {
        Column::Single($e)
    };
    (int, $e:expr) => {
        Column::Int($e)
    };
    (mjtByte, $e:expr) => {
        Column::Byte($e)
    };
    (char, $e:expr) => {
        Column::Text
    };
}

macro_rules! model_columns {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        /// (name, object-count field, columns per object, data) of every model array.
        fn columns<'a>(mv: &Model<'a>) -> Vec<(&'static str, &'static str, usize, Column<'a>)> {
            vec![$((stringify!($name), stringify!($d1), dim2!(mv.raw, $($d2)+), column!($t, mv.$name())),)*]
        }
    };
}
mjmodel_pointers!(model_columns);

/// printf-style formatting of one number with a validated single-conversion format.
pub struct NumberFormat(CString);

impl NumberFormat {
    /// The format if it is a valid single float conversion (2.2.2's rules), else the default.
    pub fn new(format: &str) -> Result<Self, String> {
        validate_float_format(format)?;
        Ok(NumberFormat(
            CString::new(format).map_err(|_| "bad format")?,
        ))
    }

    pub fn default_format() -> Self {
        NumberFormat(CString::new(FLOAT_FORMAT).unwrap())
    }

    pub fn real(&self, out: &mut String, v: f64) {
        let mut buf = [0u8; 512];
        // SAFETY: the format was validated to take exactly one double.
        let n = unsafe {
            libc::snprintf(
                buf.as_mut_ptr() as *mut libc::c_char,
                buf.len(),
                self.0.as_ptr(),
                v,
            )
        };
        let n = (n.max(0) as usize).min(buf.len() - 1);
        out.push_str(&String::from_utf8_lossy(&buf[..n]));
    }
}

/// 2.2.2's check of a user float format: `%`, flags, width, precision, optional `L`, one of fgGeE.
pub fn validate_float_format(f: &str) -> Result<(), String> {
    if f.len() > 20 {
        return Err("Format string longer than limit of 20.".into());
    }
    let b = f.as_bytes();
    let mut i = 0;
    if b.first() != Some(&b'%') {
        return Err("Format string must start with '%'.".into());
    }
    i += 1;
    let mut seen = [0; 5];
    while let Some(k) = b.get(i).and_then(|c| b"-+ #0".iter().position(|x| x == c)) {
        seen[k] += 1;
        if seen[k] > 1 {
            return Err("Format string contains repeated flag.".into());
        }
        i += 1;
    }
    while b.get(i).is_some_and(|c| c.is_ascii_digit()) {
        i += 1;
    }
    if b.get(i) == Some(&b'.') {
        i += 1;
        while b.get(i).is_some_and(|c| c.is_ascii_digit()) {
            i += 1;
        }
    }
    if b.get(i) == Some(&b'L') {
        i += 1;
    }
    if !b.get(i).is_some_and(|c| b"fgGeE".contains(c)) {
        return Err("Format string specifier must be one of \"fgGeE\".".into());
    }
    i += 1;
    if i == b.len() {
        Ok(())
    } else {
        Err(format!(
            "Unable to match format string {f} with expected pattern for a single float."
        ))
    }
}

fn name(out: &mut String, s: &str) {
    let _ = write!(out, "{s:<NAME_WIDTH$}");
}

/// NUL-terminated string starting at `adr` in a char array.
pub fn c_str_at(chars: &[std::os::raw::c_char], adr: i32) -> String {
    let start = (adr.max(0) as usize).min(chars.len());
    let bytes: Vec<u8> = chars[start..]
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect();
    String::from_utf8_lossy(&bytes).into_owned()
}

/// The object classes of the dump: count field, heading, name-address array.
const CLASSES: &[(&str, &str, Option<&str>)] = &[
    ("nbody", "BODY", Some("name_bodyadr")),
    ("njnt", "JOINT", Some("name_jntadr")),
    ("nv", "DOF", None),
    ("ngeom", "GEOM", Some("name_geomadr")),
    ("nsite", "SITE", Some("name_siteadr")),
    ("ncam", "CAMERA", Some("name_camadr")),
    ("nlight", "LIGHT", Some("name_lightadr")),
    ("nmesh", "MESH", Some("name_meshadr")),
    ("nskin", "SKIN", Some("name_skinadr")),
    ("nhfield", "HEIGHTFIELD", Some("name_hfieldadr")),
    ("ntex", "TEXTURE", Some("name_texadr")),
    ("nmat", "MATERIAL", Some("name_matadr")),
    ("npair", "PAIR", Some("name_pairadr")),
    ("nexclude", "EXCLUDE", Some("name_excludeadr")),
    ("neq", "EQUALITY", Some("name_eqadr")),
    ("ntendon", "TENDON", Some("name_tendonadr")),
    ("nu", "ACTUATOR", Some("name_actuatoradr")),
    ("nsensor", "SENSOR", Some("name_sensoradr")),
];

/// The whole dump as text.
pub fn model_text(mv: Model, fmt: &NumberFormat, version: &str) -> String {
    let m = mv.raw;
    let mut o = String::new();
    let real = |o: &mut String, v: f64| fmt.real(o, v);
    let _ = write!(
        o,
        "MuJoCo version {version}\nmodel name     {}\n\n",
        c_str_at(mv.names(), 0)
    );
    for (n, v) in alloc::model_ints(m) {
        if v != 0 {
            name(&mut o, n);
            let _ = writeln!(o, " {v}");
        }
    }
    o.push('\n');
    let opt = &m.opt;
    let floats = [
        ("timestep", opt.timestep),
        ("apirate", opt.apirate),
        ("impratio", opt.impratio),
        ("tolerance", opt.tolerance),
        ("noslip_tolerance", opt.noslip_tolerance),
        ("mpr_tolerance", opt.mpr_tolerance),
        ("density", opt.density),
        ("viscosity", opt.viscosity),
        ("o_margin", opt.o_margin),
    ];
    for (n, v) in floats {
        name(&mut o, n);
        real(&mut o, v);
        o.push('\n');
    }
    let ints = [
        ("integrator", opt.integrator),
        ("collision", opt.collision),
        ("cone", opt.cone),
        ("jacobian", opt.jacobian),
        ("solver", opt.solver),
        ("iterations", opt.iterations),
        ("noslip_iterations", opt.noslip_iterations),
        ("mpr_iterations", opt.mpr_iterations),
        ("disableflags", opt.disableflags),
        ("enableflags", opt.enableflags),
    ];
    for (n, v) in ints {
        name(&mut o, n);
        let _ = writeln!(o, " {v}");
    }
    let vectors: [(&str, &[f64]); 5] = [
        ("gravity", &opt.gravity),
        ("wind", &opt.wind),
        ("magnetic", &opt.magnetic),
        ("o_solref", &opt.o_solref),
        ("o_solimp", &opt.o_solimp),
    ];
    for (n, v) in vectors {
        name(&mut o, n);
        for &x in v {
            real(&mut o, x);
            o.push(' ');
        }
        o.push('\n');
    }
    o.push('\n');
    name(&mut o, "totalmass");
    real(&mut o, mv.body_mass().iter().sum());
    o.push_str("\n\n");
    for (n, v) in [
        ("meaninertia", m.stat.meaninertia),
        ("meanmass", m.stat.meanmass),
        ("meansize", m.stat.meansize),
        ("extent", m.stat.extent),
    ] {
        name(&mut o, n);
        real(&mut o, v);
        o.push('\n');
    }
    name(&mut o, "center");
    for &c in &m.stat.center {
        real(&mut o, c);
    }
    o.push_str("\n\n");
    for (n, v) in [("qpos0", mv.qpos0()), ("qpos_spring", mv.qpos_spring())] {
        name(&mut o, n);
        for &x in v {
            real(&mut o, x);
            o.push(' ');
        }
        o.push_str("\n\n");
    }

    let cols = columns(&mv);
    let ints = alloc::model_ints(m);
    let count = |field: &str| {
        ints.iter()
            .find(|(n, _)| *n == field)
            .map_or(0, |(_, v)| (*v).max(0) as usize)
    };
    let name_adr = |field: &str, i: usize| -> i32 {
        cols.iter()
            .find(|c| c.0 == field)
            .and_then(|c| {
                if let Column::Int(a) = c.3 {
                    a.get(i).copied()
                } else {
                    None
                }
            })
            .unwrap_or(0)
    };
    for &(class, heading, names) in CLASSES {
        let n = count(class);
        for i in 0..n {
            let _ = writeln!(o, "\n{heading} {i}:");
            if let Some(field) = names {
                o.push_str("  ");
                name(&mut o, "name");
                let sep = if heading == "HEIGHTFIELD" { "  " } else { " " };
                let _ = writeln!(o, "{sep}{}", c_str_at(mv.names(), name_adr(field, i)));
            }
            for (cname, d1, sz, data) in &cols {
                if *d1 != class || cname.starts_with("name_") || *sz == 0 {
                    continue;
                }
                let row = i * sz..(i + 1) * sz;
                if matches!(data, Column::Text) {
                    continue;
                }
                o.push_str("  ");
                name(&mut o, cname);
                for j in row {
                    match data {
                        Column::Real(a) => real(&mut o, a[j]),
                        Column::Single(a) => real(&mut o, a[j] as f64),
                        Column::Int(a) => {
                            let _ = write!(o, " {}", a[j]);
                        }
                        Column::Byte(a) => {
                            let _ = write!(o, " {}", a[j]);
                        }
                        Column::Text => {}
                    }
                    o.push(' ');
                }
                o.push('\n');
            }
            if heading == "MESH" && mv.mesh_graphadr()[i] >= 0 {
                let g = mv.mesh_graphadr()[i] as usize;
                o.push_str("  ");
                name(&mut o, "qhull face");
                let _ = writeln!(o, " {}", mv.mesh_graph()[g + 1]);
                o.push_str("  ");
                name(&mut o, "qhull vert");
                let _ = writeln!(o, " {}", mv.mesh_graph()[g]);
            }
            if heading == "TENDON" {
                o.push_str("  path         \n");
                let adr = mv.tendon_adr()[i] as usize;
                for k in adr..adr + mv.tendon_num()[i].max(0) as usize {
                    let _ = write!(o, "    {} {} ", mv.wrap_type()[k], mv.wrap_objid()[k]);
                    real(&mut o, mv.wrap_prm()[k]);
                    o.push('\n');
                }
                o.push('\n');
            }
        }
        if n > 0 {
            o.push('\n');
        }
    }
    custom_text(&mut o, mv, fmt);
    keyframes_text(&mut o, mv, fmt);
    o
}

fn custom_text(o: &mut String, mv: Model, fmt: &NumberFormat) {
    let m = mv.raw;
    for i in 0..m.nnumeric.max(0) as usize {
        let _ = writeln!(o, "\nNUMERIC {i}:");
        let _ = writeln!(
            o,
            "  name         {}",
            c_str_at(mv.names(), mv.name_numericadr()[i])
        );
        let size = mv.numeric_size()[i].max(0) as usize;
        let _ = writeln!(o, "  size         {size}");
        o.push_str("  value       ");
        let adr = mv.numeric_adr()[i] as usize;
        for &v in &mv.numeric_data()[adr..adr + size] {
            fmt.real(o, v);
        }
        o.push('\n');
    }
    if m.nnumeric > 0 {
        o.push('\n');
    }
    for i in 0..m.ntext.max(0) as usize {
        let _ = writeln!(o, "\nTEXT {i}:");
        let _ = writeln!(
            o,
            "  name         {}",
            c_str_at(mv.names(), mv.name_textadr()[i])
        );
        let _ = writeln!(o, "  size         {}", mv.text_size()[i]);
        let _ = writeln!(
            o,
            "  value        {}",
            c_str_at(mv.text_data(), mv.text_adr()[i])
        );
    }
    if m.ntext > 0 {
        o.push('\n');
    }
    for i in 0..m.ntuple.max(0) as usize {
        let _ = writeln!(o, "\nTUPLE {i}:");
        let _ = writeln!(
            o,
            "  name         {}",
            c_str_at(mv.names(), mv.name_tupleadr()[i])
        );
        let size = mv.tuple_size()[i].max(0) as usize;
        let _ = writeln!(o, "  size         {size}");
        o.push_str("  elements\n");
        let adr = mv.tuple_adr()[i] as usize;
        for j in adr..adr + size {
            let _ = write!(
                o,
                "       {} {}, prm = ",
                object_type_name(mv.tuple_objtype()[j]),
                mv.tuple_objid()[j]
            );
            fmt.real(o, mv.tuple_objprm()[j]);
            o.push('\n');
        }
    }
    if m.ntuple > 0 {
        o.push('\n');
    }
}

/// `mju_type2Str` names of object types.
pub fn object_type_name(t: i32) -> &'static str {
    const NAMES: [&str; 24] = [
        "unknown", "body", "xbody", "joint", "dof", "geom", "site", "camera", "light", "mesh",
        "skin", "hfield", "texture", "material", "pair", "exclude", "equality", "tendon",
        "actuator", "sensor", "numeric", "text", "tuple", "key",
    ];
    NAMES.get(t.max(0) as usize).copied().unwrap_or("unknown")
}

/// Keyframes, each field printed only where it differs from the defaults (2.2.2's rules,
/// including how its running flag decides what is printed).
fn keyframes_text(o: &mut String, mv: Model, fmt: &NumberFormat) {
    let m = mv.raw;
    let (nq, nv, na, nu, nmocap) = (
        m.nq as usize,
        m.nv as usize,
        m.na as usize,
        m.nu as usize,
        m.nmocap as usize,
    );
    let row = |a: &[f64], i: usize, n: usize| a[i * n..(i + 1) * n].to_vec();
    let line = |o: &mut String, label: String, v: &[f64]| {
        o.push_str(&label);
        for &x in v {
            fmt.real(o, x);
        }
        o.push('\n');
    };
    for i in 0..m.nkey.max(0) as usize {
        let kname = c_str_at(mv.names(), mv.name_keyadr()[i]);
        if !kname.is_empty() {
            let _ = writeln!(o, "key_name{i}    {kname}");
        }
        if mv.key_time()[i] != 0.0 {
            let _ = writeln!(o, "key_time{i}    {:.4}", mv.key_time()[i]);
        }
        let mut k = 0;
        let qpos = row(mv.key_qpos(), i, nq);
        if qpos.iter().zip(mv.qpos0()).any(|(a, b)| a != b) {
            k = 1;
        }
        if k == 1 {
            line(o, format!("key_qpos{i}   "), &qpos);
        }
        let qvel = row(mv.key_qvel(), i, nv);
        if qvel.iter().any(|&x| x != 0.0) {
            k = 2;
        }
        if k == 2 {
            line(o, format!("key_qvel{i}   "), &qvel);
        }
        let act = row(mv.key_act(), i, na);
        if act.iter().any(|&x| x != 0.0) {
            k = 3;
        }
        if k == 3 {
            line(o, format!("key_act{i}   "), &act);
        }
        let mpos = row(mv.key_mpos(), i, 3 * nmocap);
        let mquat = row(mv.key_mquat(), i, 4 * nmocap);
        let mocap_differs = |key: &[f64], body: &[f64], w: usize| {
            mv.body_mocapid().iter().enumerate().any(|(j, &id)| {
                id >= 0 && (0..w).any(|c| body[w * j + c] != key[w * id as usize + c])
            })
        };
        if nmocap > 0 && mocap_differs(&mpos, mv.body_pos(), 3) {
            k = 4;
        }
        if k == 4 {
            line(o, format!("key_mpos{i}   "), &mpos);
        }
        if nmocap > 0 && mocap_differs(&mquat, mv.body_quat(), 4) {
            k = 5;
        }
        if k == 5 {
            line(o, format!("key_mquat{i}   "), &mquat);
        }
        let ctrl = row(mv.key_ctrl(), i, nu);
        if ctrl.iter().any(|&x| x != 0.0) {
            k = 6;
        }
        if k == 6 {
            line(o, format!("key_ctrl{i}   "), &ctrl);
        }
        if k != 0 {
            o.push('\n');
        }
    }
}
