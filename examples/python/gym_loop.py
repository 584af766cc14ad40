"""A short Gymnasium loop on a MuJoCo environment (Gymnasium 0.29.1's v4 environments)."""

import sys

import gymnasium as gym

name = sys.argv[1] if len(sys.argv) > 1 else "HalfCheetah-v4"
env = gym.make(name)
obs, _ = env.reset(seed=42)
env.action_space.seed(42)
total = 0.0
for step in range(1000):
    obs, reward, terminated, truncated, _ = env.step(env.action_space.sample())
    total += reward
    if terminated or truncated:
        obs, _ = env.reset()
print(f"{name}: 1000 steps, total reward {total:.6f}, x velocity {env.unwrapped.data.qvel[0]:.6f}")
env.close()
