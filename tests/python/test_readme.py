"""The README's Python code runs as written (a quick start that does not run is worse than none)."""

import pathlib
import re

README = pathlib.Path(__file__).resolve().parents[2] / "README.md"


def python_blocks():
    return re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)


def test_readme_has_a_python_quick_start():
    assert python_blocks()


def test_readme_python_blocks_run():
    namespaces = []
    for block in python_blocks():
        namespace: dict = {}
        exec(compile(block, str(README), "exec"), namespace)  # noqa: S102 - our own documentation
        namespaces.append(namespace)
    # The quick start (the first block) plans a trajectory; later blocks (serial arms) run too.
    assert "traj" in namespaces[0] and namespaces[0]["traj"].duration > 0
