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


def test_package_xml_is_a_ros2_cmake_package_of_this_version():
    """package.xml (colcon, ROS 2): valid for catkin_pkg (the parser colcon-ros uses), format 3,
    the CMake build type, this version, and a key for every library CMakeLists.txt looks for."""
    import xml.etree.ElementTree as ET

    from catkin_pkg.package import parse_package

    parsed = parse_package(str(ROOT / "package.xml"))  # raises InvalidPackage on a malformed file
    parsed.validate()
    assert parsed.package_format == 3 and parsed.get_build_type() == "cmake"
    package = ET.parse(ROOT / "package.xml").getroot()
    assert package.tag == "package" and package.get("format") == "3"
    assert package.findtext("name") == "dispkin"
    assert package.findtext("version") == cmake_version()
    assert package.findtext("export/build_type") == "cmake"
    assert package.find("maintainer").get("email") and package.findtext("license") == "BSD-3-Clause"
    keys = {e.text for e in package if e.tag in ("depend", "build_depend")}
    cmake = (ROOT / "CMakeLists.txt").read_text()
    needed = {
        "Eigen3": "eigen",
        "Qhull": "libqhull",
        "nlohmann_json": "nlohmann-json-dev",
        "urdfdom": "urdfdom",
        "TinyXML": "tinyxml",
        "OrocosKDL": "liborocos-kdl-dev",
        "SLEEF": "libsleef-dev",
    }
    for cmake_name, key in needed.items():
        assert f"dispkin_find_dependency({cmake_name} " in cmake, cmake_name
        assert key in keys, key
