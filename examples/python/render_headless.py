"""Headless rendering without a display: an OpenGL context from EGL or OSMesa (MUJOCO_GL), the
scene of models/arm3.xml drawn offscreen with mjv_updateScene + mjr_render, read back with
mjr_readPixels and written as a PNG (only the standard library: zlib and struct).

    MUJOCO_GL=egl python3 examples/python/render_headless.py [model.xml] [out.png]

MuJoCo 2.2.2's bindings have no mujoco.Renderer yet; this is what it would do."""

import hashlib
import os
import struct
import sys
import zlib

os.environ.setdefault("MUJOCO_GL", "egl")  # before importing mujoco: picks mujoco.GLContext

import mujoco  # noqa: E402
import numpy as np  # noqa: E402

WIDTH, HEIGHT = 320, 240


def write_png(path, rgb):
    """An 8-bit RGB PNG: rows with filter byte 0, one zlib stream."""
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(h))

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    with open(path, "wb") as f:
        f.write(png)
    return len(png)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "models/arm3.xml"
    out = sys.argv[2] if len(sys.argv) > 2 else "arm3.png"
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, "home"))

    # the context first, then MjrContext; the offscreen buffer must hold the image
    model.vis.global_.offwidth, model.vis.global_.offheight = WIDTH, HEIGHT
    gl = mujoco.GLContext(WIDTH, HEIGHT)
    gl.make_current()
    con = mujoco.MjrContext(model, mujoco.mjtFontScale.mjFONTSCALE_100)
    mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN, con)
    scene = mujoco.MjvScene(model, maxgeom=100)
    opt, pert = mujoco.MjvOption(), mujoco.MjvPerturb()
    cam = mujoco.MjvCamera()
    cam.type = mujoco.mjtCamera.mjCAMERA_FREE
    cam.lookat[:] = [0.3, 0.1, 0.0]
    cam.distance, cam.azimuth, cam.elevation = 1.3, 135.0, -40.0
    viewport = mujoco.MjrRect(0, 0, WIDTH, HEIGHT)
    rgb = np.zeros((HEIGHT, WIDTH, 3), dtype=np.uint8)
    depth = np.zeros((HEIGHT, WIDTH), dtype=np.float32)

    print("  time    pixels (sha256)                   mean rgb            depth range")
    for frame in range(4):
        for _ in range(100):  # 0.2 s of a constant push on the three motors
            data.ctrl[:] = [1.0, -0.5, 0.3]
            mujoco.mj_step(model, data)
        mujoco.mjv_updateScene(model, data, opt, pert, cam, mujoco.mjtCatBit.mjCAT_ALL, scene)
        mujoco.mjr_render(viewport, scene, con)
        mujoco.mjr_overlay(mujoco.mjtFontScale.mjFONTSCALE_100, mujoco.mjtGridPos.mjGRID_TOPLEFT,
                           viewport, f"t = {data.time:.1f} s", "", con)
        mujoco.mjr_readPixels(rgb, depth, viewport, con)
        image = np.flipud(rgb)  # OpenGL's rows run bottom-up
        mean = image.reshape(-1, 3).mean(axis=0)
        print(f"{data.time:6.3f}  {hashlib.sha256(image.tobytes()).hexdigest()[:32]}  "
              f"{mean[0]:6.2f} {mean[1]:6.2f} {mean[2]:6.2f}  "
              f"{depth.min():.6f}..{depth.max():.6f}  ngeom {scene.ngeom}")
    size = write_png(out, image)
    print(f"4 frames rendered; wrote {os.path.basename(out)}: {WIDTH}x{HEIGHT}, {size} bytes")
    con.free()
    gl.free()


if __name__ == "__main__":
    main()
