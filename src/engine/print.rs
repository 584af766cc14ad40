//! Text dump of a model in 2.2.2's `mj_printModel` layout: sizes, options, statistics, then every
//! array of the X-macro list grouped by the object it describes.

use crate::abi::view::{self, Model};
use crate::abi::*;
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

/// Columns per object of an X-macro row.
macro_rules! width {
    ($m:expr, @ $f:ident * $k:literal) => {
        ($m.$f.max(0) as usize) * $k
    };
    ($m:expr, $k:expr) => {
        $k as usize
    };
}

macro_rules! model_columns {
    ($(($t:ident, $name:ident, $d1:ident, $($d2:tt)+)),* $(,)?) => {
        /// (name, object-count field, columns per object, data) of every model array.
        fn columns<'a>(mv: &Model<'a>) -> Vec<(&'static str, &'static str, usize, Column<'a>)> {
            vec![$((stringify!($name), stringify!($d1), width!(mv.raw, $($d2)+), column!($t, mv.$name())),)*]
        }
    };
}
crate::mjmodel_pointers!(model_columns);

/// How the dumps write one real number (the C API formats with the caller's printf format).
pub trait NumberWriter {
    fn real(&self, out: &mut String, v: f64);
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
pub fn model_text(mv: Model, fmt: &dyn NumberWriter, version: &str) -> String {
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

fn custom_text(o: &mut String, mv: Model, fmt: &dyn NumberWriter) {
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
fn keyframes_text(o: &mut String, mv: Model, fmt: &dyn NumberWriter) {
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

/// True when constraint Jacobians are stored sparse (`mj_isSparse`).
pub fn is_sparse(m: &mjModel) -> bool {
    m.opt.jacobian == mjtJacobian::mjJAC_SPARSE as i32
        || (m.opt.jacobian == mjtJacobian::mjJAC_AUTO as i32 && m.nv >= 60)
}

/// Dense nv x nv matrix from the tree-sparse storage of qM or qLD.
fn tree_to_dense(mv: Model, packed: &[f64]) -> Vec<f64> {
    let nv = mv.raw.nv.max(0) as usize;
    let mut full = vec![0.0; nv * nv];
    super::jacobian::full_m(&mv, &mut full, packed);
    full
}

/// Dense rows x cols matrix from compressed-row storage.
fn rows_to_dense(
    mat: &[f64],
    rows: usize,
    cols: usize,
    rownnz: &[i32],
    rowadr: &[i32],
    colind: &[i32],
) -> Vec<f64> {
    let mut full = vec![0.0; rows * cols];
    for r in 0..rows {
        let adr = rowadr[r].max(0) as usize;
        for k in adr..adr + rownnz[r].max(0) as usize {
            full[r * cols + colind[k] as usize] = mat[k];
        }
    }
    full
}

struct DataPrinter<'f> {
    o: String,
    fmt: &'f dyn NumberWriter,
}

impl DataPrinter<'_> {
    fn array(&mut self, label: &str, nr: usize, nc: usize, data: &[f64]) {
        if nr == 0 || nc == 0 {
            return;
        }
        let _ = write!(self.o, "{label}\n  ");
        for r in 0..nr {
            for c in 0..nc {
                self.fmt.real(&mut self.o, data[c + r * nc]);
                self.o.push(' ');
            }
            self.o.push_str("\n  ");
        }
        self.o.push('\n');
    }

    fn ints(&mut self, label: &str, n: usize, data: &[i32]) {
        if n == 0 {
            return;
        }
        let _ = write!(self.o, "{label}\n  ");
        for &v in &data[..n] {
            let _ = write!(self.o, "{v} ");
            self.o.push_str("\n  ");
        }
        self.o.push('\n');
    }

    fn sparse(
        &mut self,
        label: &str,
        mat: &[f64],
        nr: usize,
        rownnz: &[i32],
        rowadr: &[i32],
        colind: &[i32],
    ) {
        let _ = write!(self.o, "{label}\n  ");
        for r in 0..nr {
            let adr = rowadr[r].max(0) as usize;
            for k in adr..adr + rownnz[r].max(0) as usize {
                let _ = write!(self.o, "{}: ", colind[k]);
                self.fmt.real(&mut self.o, mat[k]);
                self.o.push_str("  ");
            }
            self.o.push_str("\n  ");
        }
        self.o.push('\n');
    }

    fn vector(&mut self, label: &str, data: &[f64]) {
        self.o.push_str(label);
        for &v in data {
            self.fmt.real(&mut self.o, v);
            self.o.push(' ');
        }
        self.o.push('\n');
    }
}

/// The whole `mj_printData` dump as text.
pub fn data_text(mv: Model, d: &view::Data, fmt: &dyn NumberWriter) -> String {
    let m = mv.raw;
    let h = &*d.raw;
    let mut p = DataPrinter {
        o: String::new(),
        fmt,
    };
    p.o.push_str("SIZES\n");
    for (n, v) in [
        ("nstack", h.nstack),
        ("nbuffer", h.nbuffer),
        ("pstack", h.pstack),
        ("maxuse_stack", h.maxuse_stack),
        ("maxuse_con", h.maxuse_con),
        ("maxuse_efc", h.maxuse_efc),
        ("solver_iter", h.solver_iter),
        ("solver_nnz", h.solver_nnz),
        ("ne", h.ne),
        ("nf", h.nf),
        ("nefc", h.nefc),
        ("ncon", h.ncon),
    ] {
        p.o.push_str("  ");
        name(&mut p.o, n);
        let _ = writeln!(p.o, " {v}");
    }
    p.o.push('\n');
    if h.warning.iter().map(|w| w.number).sum::<i32>() != 0 {
        p.o.push_str("WARNING\n");
        for (i, w) in h.warning.iter().enumerate() {
            if w.number != 0 {
                let _ = writeln!(
                    p.o,
                    "    {i}:  lastinfo = {}   number = {}",
                    w.lastinfo, w.number
                );
            }
        }
        p.o.push('\n');
    }
    if h.timer.iter().map(|t| t.duration).sum::<f64>() != 0.0 {
        p.o.push_str("TIMER\n");
        for (i, t) in h.timer.iter().enumerate() {
            let _ = write!(p.o, "    {i}:  duration = ");
            fmt.real(&mut p.o, t.duration);
            let _ = writeln!(p.o, "   number = {}", t.number);
        }
        p.o.push('\n');
    }
    if h.solver_iter != 0 {
        p.o.push_str("SOLVER STAT\n");
        let _ = writeln!(p.o, "  solver_iter = {}", h.solver_iter);
        let _ = writeln!(p.o, "  solver_nnz = {}", h.solver_nnz);
        for (i, s) in h
            .solver
            .iter()
            .take(h.solver_iter.max(0) as usize)
            .enumerate()
        {
            let _ = write!(p.o, "    {i}:  improvement = ");
            fmt.real(&mut p.o, s.improvement);
            p.o.push_str("  gradient = ");
            fmt.real(&mut p.o, s.gradient);
            p.o.push_str("  lineslope = ");
            fmt.real(&mut p.o, s.lineslope);
            p.o.push('\n');
            let _ = writeln!(
                p.o,
                "        nactive = {}   nchange = {}   neval = {}   nupdate = {}",
                s.nactive, s.nchange, s.neval, s.nupdate
            );
        }
        p.vector("solver_fwdinv = ", &h.solver_fwdinv);
        p.o.push('\n');
    }
    p.vector("ENERGY = ", &h.energy);
    p.o.push('\n');
    p.o.push_str("TIME = ");
    fmt.real(&mut p.o, h.time);
    p.o.push_str("\n\n");

    let (nq, nv, na, nu, nbody) = (
        m.nq as usize,
        m.nv as usize,
        m.na as usize,
        m.nu as usize,
        m.nbody as usize,
    );
    let (njnt, ngeom, nsite, ncam, nlight) = (
        m.njnt as usize,
        m.ngeom as usize,
        m.nsite as usize,
        m.ncam as usize,
        m.nlight as usize,
    );
    let (ntendon, nmocap, nefc) = (
        m.ntendon as usize,
        m.nmocap as usize,
        h.nefc.max(0) as usize,
    );
    p.array("QPOS", nq, 1, d.qpos);
    p.array("QVEL", nv, 1, d.qvel);
    p.array("ACT", na, 1, d.act);
    p.array("QACC_WARMSTART", nv, 1, d.qacc_warmstart);
    p.array("CTRL", nu, 1, d.ctrl);
    p.array("QFRC_APPLIED", nv, 1, d.qfrc_applied);
    p.array("XFRC_APPLIED", nbody, 6, d.xfrc_applied);
    p.array("MOCAP_POS", nmocap, 3, d.mocap_pos);
    p.array("MOCAP_QUAT", nmocap, 4, d.mocap_quat);
    p.array("QACC", nv, 1, d.qacc);
    p.array("ACT_DOT", na, 1, d.act_dot);
    p.array("USERDATA", m.nuserdata as usize, 1, d.userdata);
    p.array("SENSOR", m.nsensordata as usize, 1, d.sensordata);
    p.array("XPOS", nbody, 3, d.xpos);
    p.array("XQUAT", nbody, 4, d.xquat);
    p.array("XMAT", nbody, 9, d.xmat);
    p.array("XIPOS", nbody, 3, d.xipos);
    p.array("XIMAT", nbody, 9, d.ximat);
    p.array("XANCHOR", njnt, 3, d.xanchor);
    p.array("XAXIS", njnt, 3, d.xaxis);
    p.array("GEOM_XPOS", ngeom, 3, d.geom_xpos);
    p.array("GEOM_XMAT", ngeom, 9, d.geom_xmat);
    p.array("SITE_XPOS", nsite, 3, d.site_xpos);
    p.array("SITE_XMAT", nsite, 9, d.site_xmat);
    p.array("CAM_XPOS", ncam, 3, d.cam_xpos);
    p.array("CAM_XMAT", ncam, 9, d.cam_xmat);
    p.array("LIGHT_XPOS", nlight, 3, d.light_xpos);
    p.array("LIGHT_XDIR", nlight, 3, d.light_xdir);
    p.array("SUBTREE_COM", nbody, 3, d.subtree_com);
    p.array("CDOF", nv, 6, d.cdof);
    p.array("CINERT", nbody, 10, d.cinert);
    p.array("TEN_LENGTH", ntendon, 1, d.ten_length);
    let sparse = is_sparse(m);
    if !sparse {
        p.array("TEN_MOMENT", ntendon, nv, d.ten_J);
    } else {
        p.ints("TEN_J_ROWNNZ", ntendon, d.ten_J_rownnz);
        p.ints("TEN_J_ROWADR", ntendon, d.ten_J_rowadr);
        p.sparse(
            "TEN_J",
            d.ten_J,
            ntendon,
            d.ten_J_rownnz,
            d.ten_J_rowadr,
            d.ten_J_colind,
        );
    }
    for i in 0..ntendon {
        let num = d.ten_wrapnum[i].max(0) as usize;
        let _ = writeln!(p.o, "TENDON {i}: {num} wrap points");
        let adr = d.ten_wrapadr[i].max(0) as usize;
        for j in adr..adr + num {
            let _ = write!(p.o, "    {}:  ", d.wrap_obj[j]);
            p.vector("", &d.wrap_xpos[3 * j..3 * j + 3]);
        }
        p.o.push('\n');
    }
    p.array("ACTUATOR_LENGTH", nu, 1, d.actuator_length);
    p.array("ACTUATOR_MOMENT", nu, nv, d.actuator_moment);
    p.array("CRB", nbody, 10, d.crb);
    p.array("QM", nv, nv, &tree_to_dense(mv, d.qM));
    p.array("QLD", nv, nv, &tree_to_dense(mv, d.qLD));
    p.array("QLDIAGINV", nv, 1, d.qLDiagInv);
    p.array("QLDIAGSQRTINV", nv, 1, d.qLDiagSqrtInv);
    for (label, v) in [
        ("D_rownnz", &d.D_rownnz[..nv]),
        ("D_rowadr", &d.D_rowadr[..nv]),
        ("D_colind", &d.D_colind[..]),
    ] {
        name(&mut p.o, label);
        for x in v {
            let _ = write!(p.o, "{x} ");
        }
        p.o.push_str("\n\n");
    }
    let qderiv = rows_to_dense(d.qDeriv, nv, nv, d.D_rownnz, d.D_rowadr, d.D_colind);
    p.array("QDERIV", nv, nv, &qderiv);
    let qlu = rows_to_dense(d.qLU, nv, nv, d.D_rownnz, d.D_rowadr, d.D_colind);
    p.array("QLU", nv, nv, &qlu);
    p.o.push_str("CONTACT\n");
    for (i, c) in d.contact.iter().take(h.ncon.max(0) as usize).enumerate() {
        let _ = write!(
            p.o,
            "  {i}:\n     dim           {}\n     geom          {} {}\n",
            c.dim, c.geom1, c.geom2
        );
        let _ = write!(
            p.o,
            "     exclude       {}\n     efc_address   {}\n",
            c.exclude, c.efc_address
        );
        p.vector("     solref       ", &c.solref);
        p.vector("     solimp       ", &c.solimp);
        p.vector("     dist         ", &[c.dist]);
        p.vector("     includemargin", &[c.includemargin]);
        p.vector("     pos          ", &c.pos);
        p.vector("     frame        ", &c.frame);
        p.vector("     friction     ", &c.friction);
        p.vector("     mu           ", &[c.mu]);
    }
    if h.ncon > 0 {
        p.o.push('\n');
    }
    p.ints("EFC_TYPE", nefc, d.efc_type);
    p.ints("EFC_ID", nefc, d.efc_id);
    if !sparse {
        p.array("EFC_J", nefc, nv, d.efc_J);
        p.array("EFC_AR", nefc, nefc, d.efc_AR);
    } else {
        p.ints("EFC_J_ROWNNZ", nefc, d.efc_J_rownnz);
        p.ints("EFC_J_ROWADR", nefc, d.efc_J_rowadr);
        p.sparse(
            "EFC_J",
            d.efc_J,
            nefc,
            d.efc_J_rownnz,
            d.efc_J_rowadr,
            d.efc_J_colind,
        );
        p.ints("EFC_AR_ROWNNZ", nefc, d.efc_AR_rownnz);
        p.ints("EFC_AR_ROWADR", nefc, d.efc_AR_rowadr);
        p.sparse(
            "EFC_AR",
            d.efc_AR,
            nefc,
            d.efc_AR_rownnz,
            d.efc_AR_rowadr,
            d.efc_AR_colind,
        );
    }
    p.array("EFC_POS", nefc, 1, d.efc_pos);
    p.array("EFC_MARGIN", nefc, 1, d.efc_margin);
    p.array("EFC_FRICTIONLOSS", nefc, 1, d.efc_frictionloss);
    p.array("EFC_DIAGAPPROX", nefc, 1, d.efc_diagApprox);
    p.array("EFC_KBIP", nefc, 4, d.efc_KBIP);
    p.array("EFC_D", nefc, 1, d.efc_D);
    p.array("EFC_R", nefc, 1, d.efc_R);
    p.array("TEN_VELOCITY", ntendon, 1, d.ten_velocity);
    p.array("ACTUATOR_VELOCITY", nu, 1, d.actuator_velocity);
    p.array("CVEL", nbody, 6, d.cvel);
    p.array("CDOF_DOT", nv, 6, d.cdof_dot);
    p.array("QFRC_BIAS", nv, 1, d.qfrc_bias);
    p.array("QFRC_PASSIVE", nv, 1, d.qfrc_passive);
    p.array("EFC_VEL", nefc, 1, d.efc_vel);
    p.array("EFC_AREF", nefc, 1, d.efc_aref);
    p.array("SUBTREE_LINVEL", nbody, 3, d.subtree_linvel);
    p.array("SUBTREE_ANGMOM", nbody, 3, d.subtree_angmom);
    p.array("ACTUATOR_FORCE", nu, 1, d.actuator_force);
    p.array("QFRC_ACTUATOR", nv, 1, d.qfrc_actuator);
    p.array("QFRC_SMOOTH", nv, 1, d.qfrc_smooth);
    p.array("QACC_SMOOTH", nv, 1, d.qacc_smooth);
    p.array("EFC_B", nefc, 1, d.efc_b);
    p.array("EFC_FORCE", nefc, 1, d.efc_force);
    p.ints("EFC_STATE", nefc, d.efc_state);
    p.array("QFRC_CONSTRAINT", nv, 1, d.qfrc_constraint);
    p.array("QFRC_INVERSE", nv, 1, d.qfrc_inverse);
    p.array("CACC", nbody, 6, d.cacc);
    p.array("CFRC_INT", nbody, 6, d.cfrc_int);
    p.array("CFRC_EXT", nbody, 6, d.cfrc_ext);
    p.o
}
