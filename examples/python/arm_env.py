"""A dm_env.Environment around the three-link arm: reach a random target with the end site."""

import sys

import dm_env
import mujoco
import numpy as np
from dm_env import specs


class ArmReach(dm_env.Environment):
    def __init__(self, path="models/arm3.xml", seed=0, n_substeps=10, episode_steps=200):
        self.model = mujoco.MjModel.from_xml_path(path)
        self.data = mujoco.MjData(self.model)
        self.ee = mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_SITE, "ee")
        self.rng = np.random.RandomState(seed)
        self.n_substeps, self.episode_steps = n_substeps, episode_steps
        self.target = np.zeros(3)
        self.steps = 0

    def observation(self):
        return {
            "qpos": self.data.qpos.copy(),
            "qvel": self.data.qvel.copy(),
            "to_target": self.target - self.data.site_xpos[self.ee],
        }

    def reset(self):
        mujoco.mj_resetDataKeyframe(self.model, self.data, mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_KEY, "home"))
        angle, radius = self.rng.uniform(-np.pi, np.pi), self.rng.uniform(0.3, 0.8)
        self.target = np.array([radius * np.cos(angle), radius * np.sin(angle), 0.05])
        mujoco.mj_forward(self.model, self.data)
        self.steps = 0
        return dm_env.restart(self.observation())

    def step(self, action):
        self.data.ctrl[:] = action
        for _ in range(self.n_substeps):
            mujoco.mj_step(self.model, self.data)
        self.steps += 1
        obs = self.observation()
        reward = -float(np.linalg.norm(obs["to_target"]))
        if self.steps >= self.episode_steps:
            return dm_env.termination(reward, obs)
        return dm_env.transition(reward, obs)

    def observation_spec(self):
        nq, nv = self.model.nq, self.model.nv
        return {
            "qpos": specs.Array((nq,), np.float64, "qpos"),
            "qvel": specs.Array((nv,), np.float64, "qvel"),
            "to_target": specs.Array((3,), np.float64, "to_target"),
        }

    def action_spec(self):
        lo, hi = self.model.actuator_ctrlrange.T
        return specs.BoundedArray((self.model.nu,), np.float64, lo, hi, "ctrl")


def main():
    env = ArmReach(*(sys.argv[1:2] or []))
    spec = env.action_spec()
    rng = np.random.RandomState(1)
    for episode in range(3):
        ts, total = env.reset(), 0.0
        while not ts.last():
            ts = env.step(rng.uniform(spec.minimum, spec.maximum))
            total += ts.reward
        print(f"episode {episode}: return {total:.6f}, "
              f"final distance {np.linalg.norm(ts.observation['to_target']):.6f}")


if __name__ == "__main__":
    main()
