"""Nothing panics across the boundary: mutated demonstration files and
random environment options and actions raise ValueError or TypeError (a
Rust panic would surface as RuntimeError or pyo3's PanicException, a
BaseException these tests would not catch)."""

import numpy as np
import pytest

import rlfd


def mutations(text: str, rng: np.random.Generator, n: int):
    alphabet = list(',.-e0123456789[]{}":\n abcNaN') + ["\r\n", "\ufeff", "\x00", "1e400", "nan"]
    for _ in range(n):
        chars = list(text)
        for _ in range(int(rng.integers(1, 6))):
            i = int(rng.integers(0, len(chars)))
            op = rng.integers(3)
            if op == 0:
                del chars[i]
            elif op == 1:
                chars.insert(i, alphabet[int(rng.integers(len(alphabet)))])
            else:
                chars[i] = alphabet[int(rng.integers(len(alphabet)))]
        yield "".join(chars)


@pytest.mark.parametrize("fmt", ["csv", "jsonl"])
def test_mutated_demonstration_files_raise_value_errors(fmt):
    base = rlfd.demonstrations.from_trajectories(
        [np.array([[0.08, 0.6], [0.1, 0.6], [0.1, 0.62]]), np.array([[0.5, 0.5], [0.5, 0.52]])],
        [np.array([1, 2]), np.array([2, 1])], ["x", "y"], 4,
    ).dumps(fmt)
    rng = np.random.default_rng(31)
    refused = 0
    for text in mutations(base, rng, 400):
        try:
            demos = rlfd.demonstrations.parse(text, fmt, name="fuzz", num_actions=4)
        except ValueError as e:
            assert str(e).startswith("fuzz"), str(e)
            assert "\n" not in str(e)
            refused += 1
        else:
            assert len(demos) >= 1
    assert refused > 100


def test_random_options_and_actions_raise_value_or_type_errors():
    rng = np.random.default_rng(7)
    values = [None, True, -1, 0, 1, 3, 4, 7, 2**70, 0.5, 9.0, 25.0, float("nan"), float("inf"), "low-detour",
              "x", [1], {"a": 1}]
    names = ["keepers", "takers", "region", "layout", "step", "max_episode_steps", "speed"]
    made = 0
    for _ in range(300):
        domain = ["maze", "mario", "keepaway"][int(rng.integers(3))]
        options = {names[int(rng.integers(len(names)))]: values[int(rng.integers(len(values)))]}
        try:
            env = rlfd._rlfd.Env(domain, options)
        except ValueError:
            continue
        made += 1
        env.reset(int(rng.integers(0, 2**32)))
        for _ in range(20):
            action = int(rng.integers(-2, env.num_actions + 2))
            try:
                *_, term, trunc, _ = env.step(action)
            except ValueError as e:
                assert "out of range" in str(e) or "has ended" in str(e)
                if "has ended" in str(e):
                    break
    assert made >= 10
