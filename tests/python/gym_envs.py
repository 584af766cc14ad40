"""Gymnasium 0.29.1's MuJoCo v4 environments: reset with a seed, 200 sampled steps. Prints per
environment a digest of every observation and reward and the return exactly."""

import hashlib
import sys
import warnings

import gymnasium as gym
import numpy as np

warnings.filterwarnings("ignore")
ENVS = ["Ant-v4", "HalfCheetah-v4", "Hopper-v4", "Humanoid-v4", "HumanoidStandup-v4",
        "InvertedDoublePendulum-v4", "InvertedPendulum-v4", "Pusher-v4", "Reacher-v4",
        "Swimmer-v4", "Walker2d-v4"]
STEPS = int(sys.argv[1]) if len(sys.argv) > 1 else 200
for name in ENVS:
    env = gym.make(name)
    obs, _ = env.reset(seed=3)
    env.action_space.seed(3)
    digest = hashlib.sha256(np.asarray(obs, dtype=np.float64).tobytes())
    total = 0.0
    for _ in range(STEPS):
        obs, reward, terminated, truncated, _ = env.step(env.action_space.sample())
        total += float(reward)
        digest.update(np.asarray(obs, dtype=np.float64).tobytes())
        digest.update(np.float64(reward).tobytes())
        if terminated or truncated:
            obs, _ = env.reset()
    print(f"{name}: return {total.hex()} digest {digest.hexdigest()[:32]}", flush=True)
    env.close()
