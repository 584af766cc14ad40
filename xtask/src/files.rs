//! What an installation holds, and the texts of its pkg-config, CMake and Debian files. Every
//! path inside them is computed from the file's own location: an installation can be moved.

use crate::VERSION;
use std::path::{Path, PathBuf};

pub enum Content {
    Copy(PathBuf),
    Text(String),
    Link(String),
}

pub struct InstallFile {
    /// path under the prefix
    pub rel: String,
    pub content: Content,
}

/// `..` once per component of `rel`: from `prefix/rel` back to the prefix.
fn up(rel: &str) -> String {
    let n = Path::new(rel).components().count();
    vec![".."; n].join("/")
}

/// Headers, libraries, pkg-config file and CMake package, in install order.
pub fn install_set(root: &Path, release: &Path, libdir: &str) -> Vec<InstallFile> {
    let mut out = Vec::new();
    let inc = root.join("include/mujoco");
    let mut headers: Vec<PathBuf> = std::fs::read_dir(&inc)
        .unwrap_or_else(|e| panic!("{}: {e}", inc.display()))
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "h"))
        .collect();
    headers.sort();
    for h in headers {
        let name = h.file_name().unwrap().to_string_lossy().into_owned();
        out.push(InstallFile {
            rel: format!("include/mujoco/{name}"),
            content: Content::Copy(h),
        });
    }
    let so = format!("libmujoco.so.{VERSION}");
    out.push(InstallFile {
        rel: format!("{libdir}/{so}"),
        content: Content::Copy(release.join("libmujoco.so")),
    });
    let v3 = release.join(crate::HWCAPS_V3).join(&so);
    if v3.exists() {
        out.push(InstallFile {
            rel: format!("{libdir}/{}/{so}", crate::HWCAPS_V3),
            content: Content::Copy(v3),
        });
    }
    out.push(InstallFile {
        rel: format!("{libdir}/libmujoco.so"),
        content: Content::Link(so),
    });
    out.push(InstallFile {
        rel: format!("{libdir}/libmujoco.a"),
        content: Content::Copy(release.join("libmujoco.a")),
    });
    out.push(InstallFile {
        rel: format!("{libdir}/pkgconfig/mujoco.pc"),
        content: Content::Text(pkg_config(libdir)),
    });
    let cmake = format!("{libdir}/cmake/mujoco");
    out.push(InstallFile {
        rel: format!("{cmake}/mujocoConfig.cmake"),
        content: Content::Text(cmake_config(&cmake, libdir)),
    });
    out.push(InstallFile {
        rel: format!("{cmake}/mujocoConfigVersion.cmake"),
        content: Content::Text(cmake_version()),
    });
    out
}

/// What libmujoco.a needs besides itself (rustc's native-static-libs for this target).
const STATIC_LIBS: &str = "-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc";

fn pkg_config(libdir: &str) -> String {
    format!(
        "prefix=${{pcfiledir}}/{up}\n\
         libdir=${{prefix}}/{libdir}\n\
         includedir=${{prefix}}/include\n\
         \n\
         Name: mujoco\n\
         Description: rujoco: the MuJoCo {VERSION} physics engine API, in Rust\n\
         Version: {VERSION}\n\
         Cflags: -I${{includedir}}\n\
         Libs: -L${{libdir}} -lmujoco\n\
         Libs.private: {STATIC_LIBS}\n",
        up = up(&format!("{libdir}/pkgconfig")),
    )
}

fn cmake_config(cmake: &str, libdir: &str) -> String {
    format!(
        r#"# rujoco's CMake package: find_package(mujoco) gives the target mujoco::mujoco, as
# MuJoCo {VERSION}'s own package does. Paths are found from this file's location.
get_filename_component(_mujoco_prefix "${{CMAKE_CURRENT_LIST_DIR}}/{up}" ABSOLUTE)
if(NOT TARGET mujoco::mujoco)
  add_library(mujoco::mujoco SHARED IMPORTED)
  set_target_properties(mujoco::mujoco PROPERTIES
    IMPORTED_LOCATION "${{_mujoco_prefix}}/{libdir}/libmujoco.so.{VERSION}"
    IMPORTED_SONAME "libmujoco.so.{VERSION}"
    INTERFACE_INCLUDE_DIRECTORIES "${{_mujoco_prefix}}/include")
endif()
if(NOT TARGET mujoco::mujoco_static)
  add_library(mujoco::mujoco_static STATIC IMPORTED)
  set_target_properties(mujoco::mujoco_static PROPERTIES
    IMPORTED_LOCATION "${{_mujoco_prefix}}/{libdir}/libmujoco.a"
    INTERFACE_INCLUDE_DIRECTORIES "${{_mujoco_prefix}}/include"
    INTERFACE_LINK_LIBRARIES "gcc_s;util;rt;pthread;m;dl")
endif()
unset(_mujoco_prefix)
"#,
        up = up(cmake),
    )
}

/// Any version up to 2.2.2 is satisfied (CMake's AnyNewerVersion, as MuJoCo's package says);
/// 64-bit only.
fn cmake_version() -> String {
    format!(
        r#"set(PACKAGE_VERSION "{VERSION}")
if(PACKAGE_FIND_VERSION_RANGE)
  if((PACKAGE_FIND_VERSION_RANGE_MIN STREQUAL "INCLUDE" AND PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION_MIN)
     OR (PACKAGE_FIND_VERSION_RANGE_MAX STREQUAL "INCLUDE" AND PACKAGE_VERSION VERSION_GREATER PACKAGE_FIND_VERSION_MAX)
     OR (PACKAGE_FIND_VERSION_RANGE_MAX STREQUAL "EXCLUDE" AND PACKAGE_VERSION VERSION_GREATER_EQUAL PACKAGE_FIND_VERSION_MAX))
    set(PACKAGE_VERSION_COMPATIBLE FALSE)
  else()
    set(PACKAGE_VERSION_COMPATIBLE TRUE)
  endif()
elseif(PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
    set(PACKAGE_VERSION_EXACT TRUE)
  endif()
endif()
if(NOT "${{CMAKE_SIZEOF_VOID_P}}" STREQUAL "" AND NOT "${{CMAKE_SIZEOF_VOID_P}}" STREQUAL "8")
  math(EXPR installedBits "8 * 8")
  set(PACKAGE_VERSION "${{PACKAGE_VERSION}} (${{installedBits}}bit)")
  set(PACKAGE_VERSION_UNSUITABLE TRUE)
endif()
"#
    )
}

/// The package's version: MuJoCo's, then ours.
fn deb_version() -> String {
    format!("{VERSION}+rujoco{}", env!("CARGO_PKG_VERSION"))
}

pub fn deb_name() -> String {
    format!("rujoco_{}_amd64.deb", deb_version())
}

pub fn control(size_kb: u64) -> String {
    format!(
        "Package: rujoco\n\
         Version: {v}\n\
         Architecture: amd64\n\
         Maintainer: rujoco developers <rujoco@localhost>\n\
         Installed-Size: {size_kb}\n\
         Depends: libc6 (>= 2.34), libgcc-s1\n\
         Provides: libmujoco2.2.2 (= {v}), libmujoco-dev (= {v})\n\
         Conflicts: libmujoco2.2.2, libmujoco-dev\n\
         Replaces: libmujoco2.2.2, libmujoco-dev\n\
         Section: libs\n\
         Priority: optional\n\
         Homepage: https://mujoco.org\n\
         Description: MuJoCo {VERSION} physics engine, in Rust (drop-in library)\n \
         rujoco is a physics engine written in Rust with the C ABI, headers and numerical\n \
         results of MuJoCo {VERSION}: libmujoco.so.{VERSION}, the headers, a pkg-config file\n \
         and the CMake package. Installing it moves every program built for Debian's\n \
         libmujoco2.2.2 onto rujoco; removing it brings Debian's library back.\n",
        v = deb_version(),
    )
}

pub fn copyright() -> String {
    "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n\
     Upstream-Name: rujoco\n\n\
     Files: *\n\
     License: Apache-2.0\n \
     On Debian systems, the full text of the Apache License 2.0 is in\n \
     /usr/share/common-licenses/Apache-2.0.\n\n\
     Files: vendor/qhull/*\n\
     Copyright: 1993-2020 C.B. Barber, The Geometry Center\n\
     License: Qhull\n \
     See the file COPYING.txt of qhull 2020.2.\n"
        .to_string()
}
