"""The README's example runs (with 3 episodes instead of 150), and the root
README shows the same code as python/README.md."""

import pathlib
import re

import pytest

HERE = pathlib.Path(__file__).resolve().parent.parent


def example(readme: pathlib.Path) -> str:
    text = readme.read_text()
    match = re.search(r"```python\n(.*?)```", text[text.find("Linear SARSA") if "Linear SARSA" in text else 0:], re.S)
    assert match, f"{readme}: no example"
    return match.group(1)


def test_the_example_runs(capsys):
    code = example(HERE / "README.md")
    assert "range(150)" in code
    exec(compile(code.replace("range(150)", "range(3)"), "README.md", "exec"), {})
    lines = capsys.readouterr().out.strip().splitlines()
    assert [line.split(":")[0] for line in lines] == ["episode 0", "episode 1", "episode 2"]


def test_the_root_readme_shows_the_same_example():
    root = HERE.parent / "README.md"
    if not root.exists():
        pytest.skip("not in a clone of the repository")
    assert example(root) == example(HERE / "README.md")
