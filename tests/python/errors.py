"""The seed's common errors, as a user meets them from Python: the messages must be the
reference's."""

import mujoco
import numpy as np


def attempt(name, f):
    try:
        f()
        print(f"{name}: no error")
    except Exception as e:  # the bindings raise ValueError / mujoco.FatalError
        print(f"{name}: {type(e).__name__}: {e}")


attempt("xml parse error", lambda: mujoco.MjModel.from_xml_string(
    "<mujoco>\n<worldbody>\n<body>\n<geom size='1'>\n</body>\n</worldbody>\n</mujoco>"))
attempt("unknown element", lambda: mujoco.MjModel.from_xml_string(
    "<mujoco>\n<worldbody>\n<bogus/>\n</worldbody>\n</mujoco>"))
attempt("timestep <= 0", lambda: mujoco.MjModel.from_xml_string(
    "<mujoco><option timestep='0'/><worldbody/></mujoco>"))
attempt("bad attribute value", lambda: mujoco.MjModel.from_xml_string(
    "<mujoco><worldbody><geom size='x'/></worldbody></mujoco>"))
attempt("missing file", lambda: mujoco.MjModel.from_xml_path("/nonexistent/model.xml"))

m = mujoco.MjModel.from_xml_string(
    "<mujoco><worldbody><body><joint name='j'/><geom size='.1'/></body></worldbody>"
    "<actuator><motor joint='j'/></actuator></mujoco>")
d = mujoco.MjData(m)


def set_ctrl():
    d.ctrl = np.zeros(3)


attempt("ctrl size mismatch", set_ctrl)


def negative_timestep_step():
    m.opt.timestep = -0.01
    mujoco.mj_step(m, d)
    print("  time after a step with timestep -0.01:", d.time.hex())


attempt("step with negative timestep", negative_timestep_step)
attempt("missing GL context",
        lambda: mujoco.MjrContext(m, mujoco.mjtFontScale.mjFONTSCALE_150))
d.qpos[0] = np.nan
mujoco.mj_step(m, d)
print("nan qpos: warning count", d.warning[mujoco.mjtWarning.mjWARN_BADQPOS].number)
