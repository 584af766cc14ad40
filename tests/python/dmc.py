"""dm_control's suite: every domain and task loads; reset and STEPS steps with seeded random
actions. Prints, per task, a digest of every observation and reward and the last values exactly.

With --render (needs MUJOCO_GL=egl or osmesa), the first task of each model (a domain's tasks
mostly share one) also renders through physics.render at reset, half way and at the end: RGB
from the free camera (-1) and from camera 0 where the model has one, and at the end a depth and a
segmentation image (and, for height fields, RGB again after a second reset); its line ends with a
digest of all the pixel arrays and the figures of the last RGB frame, the other tasks' lines
with the task whose frames stand for theirs.

Usage: dmc.py [STEPS] [--render] [DOMAIN/TASK ...] [-DOMAIN/TASK ...]"""

import hashlib
import sys

import numpy as np
from dm_control import suite
from dm_control.rl import control

args = sys.argv[1:]
RENDER = "--render" in args
args = [a for a in args if a != "--render"]
STEPS = int(args[0]) if args else 200
# domain/task names: "-name" leaves a task out; given names alone, only those run
only = [a for a in args[1:] if not a.startswith("-")]
without = [a[1:] for a in args[1:] if a.startswith("-")]
HEIGHT, WIDTH = 48, 64


def render(phys, pixels, frames, final):
    """RGB from each camera (and depth, segmentation when final) into the pixel digest."""
    cameras = [-1] + ([0] if phys.model.ncam else [])
    last = None
    for cam in cameras:
        last = phys.render(HEIGHT, WIDTH, camera_id=cam)
        assert last.shape == (HEIGHT, WIDTH, 3) and last.dtype == np.uint8
        assert last.min() != last.max(), "a blank frame"
        pixels.update(last.tobytes())
    frames[0] += len(cameras)
    if final:
        depth = phys.render(HEIGHT, WIDTH, camera_id=cameras[-1], depth=True)
        seg = phys.render(HEIGHT, WIDTH, camera_id=cameras[-1], segmentation=True)
        pixels.update(np.ascontiguousarray(depth, dtype=np.float32).tobytes())
        pixels.update(np.ascontiguousarray(seg, dtype=np.int32).tobytes())
        frames[0] += 2
        return (f"{frames[0]} frames, rgb sum {int(last.sum())} "
                f"depth min {float(depth.min()).hex()} max {float(depth.max()).hex()} "
                f"segments {len(np.unique(seg[..., 0]))}")
    return None


def model_key(domain, m):
    """What tells a domain's models apart: tasks with the same key render alike."""
    return (domain, m.nbody, m.ngeom, m.nmesh, m.ntex, m.nhfield, m.nmat, m.ncam, m.nlight)


rendered = {}  # model key -> the task that rendered it
for domain, task in suite.ALL_TASKS:
    if f"{domain}/{task}" in without or (only and f"{domain}/{task}" not in only):
        continue
    env = suite.load(domain, task, task_kwargs={"random": 7})
    spec = env.action_spec()
    rng = np.random.RandomState(0)
    digest, pixels, frames = hashlib.sha256(), hashlib.sha256(), [0]
    key = model_key(domain, env.physics.model)
    stand_in = rendered.get(key)
    render_task = RENDER and stand_in is None
    if render_task:
        rendered[key] = f"{domain}/{task}"
    ts = env.reset()
    if render_task:
        render(env.physics, pixels, frames, False)
    total, note, figures = 0.0, "", ""
    for step in range(STEPS):
        try:
            ts = env.step(rng.uniform(spec.minimum, spec.maximum, spec.shape))
        except control.PhysicsError as e:  # diverged under random actions: same on both sides
            note = f" physics error at step {step}: {e}"
            break
        total += ts.reward or 0.0
        for k in sorted(ts.observation):
            digest.update(np.ascontiguousarray(ts.observation[k], dtype=np.float64).tobytes())
        digest.update(np.float64(ts.reward or 0.0).tobytes())
        if render_task and step + 1 == STEPS // 2:
            render(env.physics, pixels, frames, False)
    phys = env.physics
    if render_task:
        last = render(phys, pixels, frames, True)
        if phys.model.nhfield:  # a new terrain goes up through mjr_uploadHField at reset
            env.reset()
            render(env.physics, pixels, frames, False)
            last += f", after a second reset {frames[0]} frames"
        figures = f" pixels {pixels.hexdigest()[:32]} {last}"
    elif RENDER:
        figures = f" rendered with {stand_in}"
    print(f"{domain}/{task}: return {total.hex()} time {phys.data.time.hex()} "
          f"qpos0 {float(phys.data.qpos[0]).hex() if phys.model.nq else '-'} "
          f"digest {digest.hexdigest()[:32]}{figures}{note}", flush=True)
