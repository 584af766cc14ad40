"""Gymnasium 0.29.1's MuJoCo v4 environments: reset with a seed, STEPS sampled steps. Prints per
environment a digest of every observation and reward and the return exactly.

With --render (needs MUJOCO_GL=egl or osmesa), each environment is made with
render_mode="rgb_array" (and "depth_array" for DEPTH_ENVS) at a small size, and env.render()
frames at reset, half way and at the end go into a pixel digest printed, after the physics
digest, with the figures of the last frame."""

import hashlib
import sys
import warnings

import gymnasium as gym
import numpy as np

warnings.filterwarnings("ignore")
ENVS = ["Ant-v4", "HalfCheetah-v4", "Hopper-v4", "Humanoid-v4", "HumanoidStandup-v4",
        "InvertedDoublePendulum-v4", "InvertedPendulum-v4", "Pusher-v4", "Reacher-v4",
        "Swimmer-v4", "Walker2d-v4"]
DEPTH_ENVS = ["Hopper-v4", "Pusher-v4"]
WIDTH, HEIGHT = 64, 48
args = sys.argv[1:]
RENDER = "--render" in args
args = [a for a in args if a != "--render"]
STEPS = int(args[0]) if args else 200


def run(name, mode):
    kw = dict(render_mode=mode, width=WIDTH, height=HEIGHT) if mode else {}
    env = gym.make(name, **kw)
    obs, _ = env.reset(seed=3)
    env.action_space.seed(3)
    digest = hashlib.sha256(np.asarray(obs, dtype=np.float64).tobytes())
    pixels, frames, frame = hashlib.sha256(), 0, None

    def grab():
        nonlocal frames, frame
        frame = env.render()
        assert frame.shape[:2] == (HEIGHT, WIDTH) and frame.min() != frame.max(), "a blank frame"
        pixels.update(np.ascontiguousarray(frame).tobytes())
        frames += 1

    if mode:
        grab()
    total = 0.0
    for step in range(STEPS):
        obs, reward, terminated, truncated, _ = env.step(env.action_space.sample())
        total += float(reward)
        digest.update(np.asarray(obs, dtype=np.float64).tobytes())
        digest.update(np.float64(reward).tobytes())
        if terminated or truncated:
            obs, _ = env.reset()
        if mode and step + 1 in (STEPS // 2, STEPS):
            grab()
    line = f"{name}: return {total.hex()} digest {digest.hexdigest()[:32]}"
    if mode:
        line += (f" {mode}: {frames} frames {frame.shape} {frame.dtype} "
                 f"pixels {pixels.hexdigest()[:32]} last sum {float(frame.sum()).hex()}")
    print(line, flush=True)
    env.close()


for name in ENVS:
    if not RENDER:
        run(name, None)
        continue
    run(name, "rgb_array")
    if name in DEPTH_ENVS:
        run(name, "depth_array")
