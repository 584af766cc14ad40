"""dm_control's suite: every domain and task loads; reset and 200 steps with seeded random
actions. Prints, per task, a digest of every observation and reward and the last values exactly."""

import hashlib
import sys

import numpy as np
from dm_control import suite
from dm_control.rl import control

STEPS = int(sys.argv[1]) if len(sys.argv) > 1 else 200
without = sys.argv[2:]  # domain/task names left out
for domain, task in suite.ALL_TASKS:
    if f"{domain}/{task}" in without:
        continue
    env = suite.load(domain, task, task_kwargs={"random": 7})
    spec = env.action_spec()
    rng = np.random.RandomState(0)
    digest = hashlib.sha256()
    ts = env.reset()
    total, note = 0.0, ""
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
    phys = env.physics
    print(f"{domain}/{task}: return {total.hex()} time {phys.data.time.hex()} "
          f"qpos0 {float(phys.data.qpos[0]).hex() if phys.model.nq else '-'} "
          f"digest {digest.hexdigest()[:32]}{note}", flush=True)
