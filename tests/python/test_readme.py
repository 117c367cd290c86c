"""The Python snippets of the README and of doc/ run as written, against the installed package
and from an empty directory: a snippet that reads the checkout (tests/data, ...) fails here, as
it would for someone who installed the wheel (tests/wheel/run_wheel_test.sh runs the README's
again with the wheel itself)."""

import pathlib
import re

import pytest

import dispkin

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCUMENTS = [ROOT / "README.md", *sorted((ROOT / "doc").glob("*.md"))]


def python_blocks(path):
    return re.findall(r"```python\n(.*?)```", path.read_text(encoding="utf-8"), flags=re.S)


SNIPPETS = [(path, i, block) for path in DOCUMENTS for i, block in enumerate(python_blocks(path))]


def test_the_package_is_the_installed_one():
    package = pathlib.Path(dispkin.__file__).resolve().parent
    assert ROOT / "python" not in package.parents, f"dispkin imported from the checkout ({package})"


def test_readme_has_quick_starts():
    blocks = python_blocks(ROOT / "README.md")
    assert len(blocks) >= 2 and "dispkin.plan(" in blocks[0] and "dispkin.data.path(" in blocks[1]


@pytest.mark.parametrize("path,index,block", SNIPPETS, ids=[f"{p.relative_to(ROOT)}#{i}" for p, i, _ in SNIPPETS])
def test_snippet_runs(path, index, block, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace: dict = {"__name__": "__snippet__"}
    exec(compile(block, str(path), "exec"), namespace)  # noqa: S102 - our own documentation
    if path.name == "README.md" and index == 0:
        assert namespace["traj"].duration > 0 and namespace["poses"].shape == (1000, 4, 4)


def test_shipped_robot_data():
    assert "ur5e.urdf" in dispkin.data.names()
    urdf = pathlib.Path(dispkin.data.path("ur5e.urdf"))
    assert urdf.is_file() and ROOT / "python" not in urdf.resolve().parents
    # The shipped UR5e is the one the tests use (tests/data/urdf/arm_ur5e_dh.urdf links to it).
    assert urdf.read_bytes() == (ROOT / "tests" / "data" / "urdf" / "arm_ur5e_dh.urdf").read_bytes()
    with pytest.raises(ValueError, match="name = 'ur10.urdf'"):
        dispkin.data.path("ur10.urdf")
