"""One version string: CMakeLists.txt's project(VERSION), dispkin.__version__ (from the C++
dispkin::version), the installed distribution's metadata and the newest CHANGELOG entry."""

import re
from importlib import metadata
from pathlib import Path

import dispkin

ROOT = Path(__file__).resolve().parents[2]


def cmake_version():
    match = re.search(r"project\(dispkin VERSION ([0-9]+\.[0-9]+\.[0-9]+)", (ROOT / "CMakeLists.txt").read_text())
    assert match
    return match.group(1)


def test_version_is_the_cmake_project_version():
    assert dispkin.__version__ == cmake_version()
    assert dispkin._core.__version__ == cmake_version()
    assert metadata.version("dispkin") == cmake_version()


def test_changelog_newest_entry_names_the_version():
    newest = re.search(r"^## \[([0-9.]+)\]", (ROOT / "CHANGELOG.md").read_text(), re.MULTILINE)
    assert newest and newest.group(1) == cmake_version()
