"""PEP 517 backend: MuJoCo 2.2.2's Python bindings on rujoco.

Builds rujoco (cargo) when its library is missing or older than its sources, fetches the
bindings' sdist from PyPI (or takes RUJOCO_MUJOCO_SDIST), builds it against rujoco's headers and
library with Debian's abseil, Eigen and pybind11, and returns the wheel of the package `mujoco`
2.2.2 with rujoco's libmujoco.so.2.2.2 inside (on x86-64 also its x86-64-v3 build, in
mujoco/glibc-hwcaps/x86-64-v3/, which the loader takes on a CPU that has AVX2).
"""

import glob
import os
import re
import shutil
import subprocess
import sys
import tarfile

VERSION = "2.2.2"
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get("RUJOCO_ROOT", os.path.dirname(HERE))

# Debian packages the build needs: (package, file that shows it is installed)
DEBIAN_DEPS = [
    ("cmake", "/usr/bin/cmake"),
    ("g++", "/usr/bin/g++"),
    ("libabsl-dev", "/usr/include/absl/container/flat_hash_map.h"),
    ("libeigen3-dev", "/usr/include/eigen3/Eigen/Dense"),
    ("pybind11-dev", "/usr/include/pybind11/pybind11.h"),
]


def _log(msg):
    print(f"rujoco: {msg}", file=sys.stderr, flush=True)


def _run(cmd, **kw):
    _log(" ".join(cmd))
    subprocess.run(cmd, check=True, **kw)


def _debian_deps():
    missing = [p for p, f in DEBIAN_DEPS if not os.path.exists(f)]
    if not missing:
        return
    if os.geteuid() == 0 and shutil.which("apt-get"):
        _log(f"installing {' '.join(missing)}")
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        _run(["apt-get", "install", "-y", "-q", *missing], env=env)
        return
    raise RuntimeError(
        "building MuJoCo's Python bindings on rujoco needs the Debian packages "
        f"{' '.join(missing)}: sudo apt-get install {' '.join(missing)}"
    )


def _target_dir():
    t = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    return t if os.path.isabs(t) else os.path.join(ROOT, t)


def _newest_source(root):
    newest = 0.0
    for sub in ("src", "build.rs", "Cargo.toml", "vendor"):
        p = os.path.join(root, sub)
        if os.path.isfile(p):
            newest = max(newest, os.path.getmtime(p))
        for d, _, files in os.walk(p):
            for f in files:
                newest = max(newest, os.path.getmtime(os.path.join(d, f)))
    return newest


HWCAPS_V3 = os.path.join("glibc-hwcaps", "x86-64-v3")


def _rujoco_library():
    """The baseline library; its x86-64-v3 build (AVX2) beside it on x86-64, in the
    glibc-hwcaps/ directory where the loader takes it on a CPU that has AVX2."""
    lib = os.path.join(_target_dir(), "release", "libmujoco.so")
    v3 = _v3_library()
    newest = _newest_source(ROOT)

    def older(path, than):
        return not os.path.exists(path) or os.path.getmtime(path) < than

    if older(lib, newest) or (v3 and older(v3, os.path.getmtime(lib))):
        cargo = shutil.which("cargo") or os.path.expanduser("~/.cargo/bin/cargo")
        if not os.path.exists(cargo):
            raise RuntimeError("cargo not found: install Rust (https://rustup.rs)")
        _run([cargo, "build", "--release"], cwd=ROOT)
        if v3:
            _run([cargo, "xtask", "hwcaps"], cwd=ROOT)
    return lib


def _v3_library():
    """Where `cargo xtask hwcaps` puts the x86-64-v3 build; None off x86-64 Linux."""
    if sys.platform != "linux" or os.uname().machine != "x86_64":
        return None
    return os.path.join(_target_dir(), "release", HWCAPS_V3, f"libmujoco.so.{VERSION}")


def _add_to_wheel(wheel, files):
    """Rewrites the wheel with `files` ({path in the wheel: file}) added and listed in RECORD."""
    import base64
    import hashlib
    import zipfile
    tmp = wheel + ".tmp"
    with zipfile.ZipFile(wheel) as src, zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as dst:
        record = None
        for item in src.infolist():
            if item.filename.endswith(".dist-info/RECORD"):
                record = (item, src.read(item).decode())
            else:
                dst.writestr(item, src.read(item))
        lines = record[1].rstrip("\n").split("\n")
        for name, path in files.items():
            data = open(path, "rb").read()
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.external_attr = 0o755 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            dst.writestr(info, data)
            digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=")
            lines.insert(len(lines) - 1, f"{name},sha256={digest.decode()},{len(data)}")
        dst.writestr(record[0], "\n".join(lines) + "\n")
    os.replace(tmp, wheel)


def _sdist(work):
    given = os.environ.get("RUJOCO_MUJOCO_SDIST")
    if given:
        return given
    cache = os.path.join(_target_dir(), "python", "sdist")
    found = glob.glob(os.path.join(cache, f"mujoco-{VERSION}.tar.gz"))
    if found:
        return found[0]
    os.makedirs(cache, exist_ok=True)
    _run([sys.executable, "-m", "pip", "download", "--no-deps", "--no-binary", ":all:",
          "-d", cache, f"mujoco=={VERSION}"])
    return os.path.join(cache, f"mujoco-{VERSION}.tar.gz")


def _patch(src):
    """Debian's abseil, Eigen and pybind11 instead of fetching them; abseil without string_view
    overloads in the name lookup; the modules in the order of their compile times, longest
    first (enums.cc, structs.cc and functions.cc take three-quarters of the build), so that a
    parallel build runs the short ones beside them, not after them."""
    cm = os.path.join(src, "mujoco", "CMakeLists.txt")
    text = open(cm).read()
    text = text.replace("USE_SYSTEM_PACKAGE\n  OFF", "USE_SYSTEM_PACKAGE\n  ON")
    text = text.replace("  _structs\n  indexers.cc\n  serialization.h\n  structs.cc\n",
                        "  _structs\n  structs.cc\n  indexers.cc\n  serialization.h\n")
    modules = {}
    for m in re.finditer(r"mujoco_pybind11_module\(\s*(_\w+)[^)]*\)\n", text):
        modules[m.group(1)] = m.group(0)
    order = ["_enums", "_structs", "_functions", "_render", "_errors", "_callbacks", "_rollout",
             "_constants"]
    if sorted(modules) == sorted(order):
        at = min(text.index(b) for b in modules.values())
        for block in modules.values():
            text = text.replace(block, "")
        text = text[:at] + "".join(modules[n] for n in order) + text[at:]
    # RUJOCO_O0_SOURCES (a CMake list): sources compiled at -O0, for builds that trade the
    # bindings' speed for build time (the tests' build)
    text += ("\nif(RUJOCO_O0_SOURCES)\n"
             "  set_source_files_properties(${RUJOCO_O0_SOURCES} PROPERTIES COMPILE_OPTIONS -O0)\n"
             "endif()\n")
    open(cm, "w").write(text)
    ix = os.path.join(src, "mujoco", "indexers.cc")
    text = open(ix).read()
    text = text.replace("name_to_id_.field.find(name)", "name_to_id_.field.find(std::string(name))")
    open(ix, "w").write(text)


def _stage(work, lib):
    """MUJOCO_PATH for the sdist's setup.py: rujoco's headers and library."""
    stage = os.path.join(work, "rujoco")
    shutil.rmtree(stage, ignore_errors=True)
    os.makedirs(os.path.join(stage, "lib"))
    shutil.copytree(os.path.join(ROOT, "include"), os.path.join(stage, "include"))
    so = os.path.join(stage, "lib", f"libmujoco.so.{VERSION}")
    shutil.copyfile(os.path.realpath(lib), so)
    os.symlink(f"libmujoco.so.{VERSION}", os.path.join(stage, "lib", "libmujoco.so"))
    return stage


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    _debian_deps()
    other = os.environ.get("RUJOCO_BINDINGS_MUJOCO_PATH")
    if other:  # another MuJoCo 2.2.2 (include/, lib/): the tests' reference bindings
        stage, work = other, os.path.join(_target_dir(), "python", "build-other")
    else:
        lib = _rujoco_library()
        work = os.path.join(_target_dir(), "python", "build")
    os.makedirs(work, exist_ok=True)
    if not other:
        stage = _stage(work, lib)
    src = os.path.join(work, f"mujoco-{VERSION}")
    shutil.rmtree(src, ignore_errors=True)
    with tarfile.open(_sdist(work)) as t:
        t.extractall(work)
    _patch(src)
    env = dict(os.environ, MUJOCO_PATH=stage)
    env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
    out = os.path.join(work, "dist")
    shutil.rmtree(out, ignore_errors=True)
    _run([sys.executable, "setup.py", "-q", "bdist_wheel", "-d", out], cwd=src, env=env)
    wheel = glob.glob(os.path.join(out, f"mujoco-{VERSION}-*.whl"))[0]
    v3 = None if other else _v3_library()
    if v3:
        _add_to_wheel(wheel, {f"mujoco/{HWCAPS_V3}/libmujoco.so.{VERSION}": v3})
    shutil.copy(wheel, wheel_directory)
    return os.path.basename(wheel)


def get_requires_for_build_wheel(config_settings=None):
    return []


REQUIRES = ["absl-py", "glfw", "numpy", "pyopengl"]


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    """The bindings' metadata without building them (pip would otherwise build twice)."""
    info = os.path.join(metadata_directory, f"mujoco-{VERSION}.dist-info")
    os.makedirs(info, exist_ok=True)
    lines = ["Metadata-Version: 2.1", "Name: mujoco", f"Version: {VERSION}",
             "Summary: MuJoCo Physics Simulator (bindings built on rujoco)",
             "Requires-Python: >=3.7"]
    lines += [f"Requires-Dist: {r}" for r in REQUIRES]
    with open(os.path.join(info, "METADATA"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return os.path.basename(info)
