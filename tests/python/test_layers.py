"""The layer check (scripts/check-layers.py, doc/architecture.md): the repository passes it, and
an include that points up or across a plugin, or a namespace that is not its folder's, is reported
with its file and line."""

import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "check-layers.py"


def run(root):
    return subprocess.run([sys.executable, str(SCRIPT), str(root)], capture_output=True, text=True)


def write(root, relative, text):
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")


def test_the_repository_keeps_its_layers():
    result = run(ROOT)
    assert result.returncode == 0, result.stdout


def test_downward_includes_pass(tmp_path):
    write(tmp_path, "include/dispkin/pose.hpp", "#pragma once\n")
    write(tmp_path, "include/dispkin/path/path.hpp", '#include "dispkin/pose.hpp"\n')
    write(tmp_path, "include/dispkin/planning/planner.hpp", '#include "dispkin/path/path.hpp"\n')
    write(tmp_path, "src/serial/ptp.cpp", '#include "dispkin/planning/planner.hpp"\n#include "local.hpp"\n')
    write(tmp_path, "include/dispkin/dispkin.hpp", '#include "dispkin/serial/ptp.hpp"\n')  # the umbrella
    assert run(tmp_path).returncode == 0


def test_an_upward_include_is_reported_with_its_line(tmp_path):
    write(tmp_path, "include/dispkin/pose.hpp", "#pragma once\n\n#include <dispkin/planning/planner.hpp>\n")
    result = run(tmp_path)
    assert result.returncode == 1
    assert "include/dispkin/pose.hpp:3: the core layer includes dispkin/planning/planner.hpp" in result.stdout


def test_one_plugin_including_the_other_is_reported(tmp_path):
    write(tmp_path, "src/hexapod/hexapod.cpp", '#include "dispkin/serial/serial_arm.hpp"\n')
    result = run(tmp_path)
    assert result.returncode == 1
    assert "src/hexapod/hexapod.cpp:1: the hexapod layer includes dispkin/serial/serial_arm.hpp" in result.stdout


def test_namespaces_that_follow_their_folders_pass(tmp_path):
    write(tmp_path, "include/dispkin/pose.hpp", "namespace dispkin {\nnamespace detail {\n}\n}  // namespace dispkin\n")
    write(tmp_path, "src/path/path.cpp", "namespace dispkin {\nnamespace {\n}  // namespace\n}  // namespace dispkin\n")
    write(tmp_path, "include/dispkin/serial/ptp.hpp", "namespace dispkin {\nnamespace serial {\n}\n}\n")
    write(
        tmp_path,
        "src/serial/ptp.cpp",
        '// namespace dispkin {\nconst char* s = "namespace dispkin {";\nnamespace dispkin::serial::detail {\n}\n',
    )
    write(tmp_path, "src/hexapod/hexapod.cpp", "namespace dispkin::hexapod {\nnamespace {\n}\n}\n")
    assert run(tmp_path).returncode == 0


def test_a_plugin_file_in_the_core_namespace_is_reported_with_its_line(tmp_path):
    write(tmp_path, "include/dispkin/hexapod/hexapod.hpp", "#pragma once\n\nnamespace dispkin {\nclass Hexapod;\n}\n")
    result = run(tmp_path)
    assert result.returncode == 1
    assert (
        "include/dispkin/hexapod/hexapod.hpp:3: the hexapod layer opens namespace dispkin, "
        "not one inside dispkin::hexapod"
    ) in result.stdout


def test_a_core_file_in_a_plugin_namespace_is_reported(tmp_path):
    write(tmp_path, "src/planning/planner.cpp", "namespace dispkin {\nnamespace serial {\nvoid f();\n}\n}\n")
    write(tmp_path, "src/serial/ptp.cpp", "namespace dispkin::hexapod::detail {\n}\n")
    result = run(tmp_path)
    assert result.returncode == 1
    assert "src/planning/planner.cpp:2: the planning layer opens namespace dispkin::serial" in result.stdout
    assert "src/serial/ptp.cpp:1: the serial layer opens namespace dispkin::hexapod::detail" in result.stdout


def test_a_public_declaration_naming_detail_is_reported_with_its_line(tmp_path):
    write(
        tmp_path,
        "include/dispkin/pose.hpp",
        "namespace dispkin {\nnamespace detail {\nstruct Kernel {};\n}  // namespace detail\n"
        "class Pose {\n public:\n  void apply(const detail::Kernel& k);\n};\n}  // namespace dispkin\n",
    )
    result = run(tmp_path)
    assert result.returncode == 1
    assert "include/dispkin/pose.hpp:7: a public declaration names detail: void apply(const detail::Kernel& k)" in (
        result.stdout
    )


def test_detail_in_bodies_private_members_and_friends_passes(tmp_path):
    write(
        tmp_path,
        "include/dispkin/pose.hpp",
        "namespace dispkin {\nnamespace detail {\nstruct Kernel {};\ninline int f() { return 1; }\n}\n"
        "inline int g() { return detail::f(); }  // detail::Kernel in a comment\n"
        "class Pose {\n  detail::Kernel kernel_;\n public:\n  Pose() : x_(detail::f()) {}\n"
        " private:\n  friend struct detail::Kernel;\n  int x_;\n};\n}  // namespace dispkin\n",
    )
    assert run(tmp_path).returncode == 0, run(tmp_path).stdout
