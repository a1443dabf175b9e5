"""Per-step cost from Python and vector throughput, beside Gymnasium's CartPole
in the same window.

    python python/benchmarks/throughput.py [--seconds 2]

Single environments: ``env.step(a)`` on the unwrapped environment, and
through the wrappers ``gymnasium.make`` adds (order enforcing, the passive
checker, the time limit), with
uniformly random actions drawn beforehand (so the measurement is the step,
not NumPy's generator), resetting at each episode's end; microseconds per
step. Vector environments: ``envs.step(actions)`` with random actions for N
instances (autoreset included); environment steps per second. CartPole-v1 is
measured the same way (its vector form is Gymnasium's own NumPy
``CartPoleVectorEnv``). Each figure is the best of three timed runs of about
``--seconds`` each.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import gymnasium as gym
import numpy as np

import rlfd


def single(env_id: str, seconds: float, wrapped: bool) -> float:
    env = gym.make(env_id)
    if not wrapped:
        env = env.unwrapped
    n = env.action_space.n
    actions = np.random.default_rng(0).integers(0, n, 1_000_000).tolist()
    best = float("inf")
    for run in range(3):
        env.reset(seed=run)
        steps, i = 0, 0
        start = time.perf_counter()
        deadline = start + seconds
        while True:
            for _ in range(1000):
                _, _, term, trunc, _ = env.step(actions[i])
                i += 1
                if term or trunc:
                    env.reset()
            steps += 1000
            if i > 990_000:
                i = 0
            now = time.perf_counter()
            if now >= deadline:
                break
        best = min(best, (now - start) / steps)
    return best * 1e6


def vector(make, num_envs: int, n_actions: int, seconds: float) -> float:
    envs = make(num_envs)
    rng = np.random.default_rng(0)
    batches = [rng.integers(0, n_actions, num_envs) for _ in range(256)]
    best = 0.0
    for run in range(3):
        envs.reset(seed=run)
        calls = 0
        start = time.perf_counter()
        deadline = start + seconds
        while True:
            for b in batches[:64]:
                envs.step(b)
            calls += 64
            now = time.perf_counter()
            if now >= deadline:
                break
        best = max(best, calls * num_envs / (now - start))
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=2.0)
    parser.add_argument("--num-envs", type=int, default=64)
    args = parser.parse_args()
    s, n = args.seconds, args.num_envs
    print(f"# {platform.processor() or platform.machine()}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.2f}, "
          f"Python {platform.python_version()}, gymnasium {gym.__version__}, numpy {np.__version__}")
    print("| environment | single env, µs/step (unwrapped) | single env, µs/step (gym.make's wrappers) "
          "| vector env, steps/s (N = %d) |" % n)
    print("|---|---|---|---|")
    rows = [
        ("rlfd/Maze-v0", lambda k: rlfd.make_vec("rlfd/Maze-v0", k), 4),
        ("rlfd/Mario-v0", lambda k: rlfd.make_vec("rlfd/Mario-v0", k), 12),
        ("rlfd/Keepaway-3v2-v0", lambda k: rlfd.make_vec("rlfd/Keepaway-3v2-v0", k), 3),
        ("CartPole-v1", lambda k: gym.make_vec("CartPole-v1", num_envs=k, vectorization_mode="vector_entry_point"), 2),
    ]
    for env_id, make, actions in rows:
        bare = single(env_id, s, wrapped=False)
        made = single(env_id, s, wrapped=True)
        sps = vector(make, n, actions, s)
        print(f"| {env_id} | {bare:.2f} | {made:.2f} | {sps:,.0f} |")


if __name__ == "__main__":
    main()
