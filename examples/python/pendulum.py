"""The minimal loop: load a model, step it, read the state (models/pendulum.xml)."""

import sys

import mujoco

path = sys.argv[1] if len(sys.argv) > 1 else "models/pendulum.xml"
model = mujoco.MjModel.from_xml_path(path)
data = mujoco.MjData(model)
mujoco.mj_resetDataKeyframe(model, data, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, "tilted"))

hinge = model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, "hinge")]
print("step      time     angle      velocity")
for step in range(1, 10001):
    mujoco.mj_step(model, data)
    if step % 1000 == 0:
        print(f"{step:5d}  {data.time:8.3f}  {data.qpos[hinge]:9.6f}  {data.qvel[hinge]:9.6f}")
