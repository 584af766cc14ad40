"""The three-link arm of models/arm3.xml: forward kinematics from site_xpos, damped-least-squares
inverse kinematics through mj_jacSite, and PD tracking of a circling target through the motors."""

import sys

import mujoco
import numpy as np


def ik_solve(model, scratch, site, target, damping=0.05, iters=3):
    """DLS iterations on scratch.qpos; returns the final position error."""
    jacp = np.zeros((3, model.nv))
    for it in range(iters + 1):
        mujoco.mj_forward(model, scratch)
        err = target - scratch.site_xpos[site]
        if it == iters:
            return np.linalg.norm(err)
        mujoco.mj_jacSite(model, scratch, jacp, None, site)
        dq = jacp.T @ np.linalg.solve(jacp @ jacp.T + damping**2 * np.eye(3), err)
        mujoco.mj_integratePos(model, scratch.qpos, dq, 1)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "models/arm3.xml"
    model = mujoco.MjModel.from_xml_path(path)
    data, scratch = mujoco.MjData(model), mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, "home"))
    ee = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, "ee")

    mujoco.mj_forward(model, data)
    print("forward kinematics at home:", np.array2string(data.site_xpos[ee], precision=6))

    joints = model.actuator_trnid[:, 0]
    qadr, vadr = model.jnt_qposadr[joints], model.jnt_dofadr[joints]
    lo, hi = model.actuator_ctrlrange.T
    kp, kd, worst = 20.0, 3.0, 0.0
    print("  time    target x  target y   ee x      ee y     error")
    for step in range(1, 2501):
        t = data.time
        target = np.array([0.45 + 0.15 * np.cos(t), 0.15 + 0.15 * np.sin(t), 0.05])
        scratch.qpos[:] = data.qpos
        ik_solve(model, scratch, ee, target)
        u = kp * (scratch.qpos[qadr] - data.qpos[qadr]) - kd * data.qvel[vadr]
        data.ctrl[:] = np.clip(u, lo, hi)
        mujoco.mj_step(model, data)
        p = data.site_xpos[ee]
        err = np.hypot(p[0] - target[0], p[1] - target[1])
        if step > 1000:
            worst = max(worst, err)
        if step % 250 == 0:
            print(f"{data.time:6.3f}  {target[0]:9.6f} {target[1]:9.6f} "
                  f"{p[0]:9.6f} {p[1]:9.6f}  {err:.6f}")
    print(f"worst tracking error after 2 s: {worst:.6f}")
    return 0 if worst < 0.05 else 2


if __name__ == "__main__":
    sys.exit(main())
