"""What the hostile-input tests share (test_hostile_inputs.py, test_hostile_kinematics.py,
test_hostile_job_files.py, test_urdf_format_text.py): a case that used to crash the interpreter
runs in a child process (a segmentation fault there is a failed test, not a dead test run); a
case that used to take the memory runs in a child whose address space is capped with
resource.setrlimit. And the texts they damage: a planar URDF, a hexapod description.
"""

import json
import os
import pathlib
import subprocess
import sys
import textwrap

import pytest

import dispkin


DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
# Under AddressSanitizer (`make sanitize-python` preloads it) everything runs several times
# slower, and its shadow memory cannot live in a capped address space: the time bounds below
# (hang guards, an order of magnitude above the measured times) stretch, the caps are left off.
SANITIZED = "libasan" in os.environ.get("LD_PRELOAD", "")
SLOWDOWN = 10.0 if SANITIZED else 1.0
UR5E = str(DATA / "urdf" / "arm_ur5e_dh.urdf")


def run_isolated(code, address_space=None, timeout=120):
    """Run `code` in a fresh interpreter (dispkin imported as in this one), with the address
    space capped at `address_space` bytes if given; returns (exit status, stdout, stderr)."""
    prelude = "import resource\n"
    if address_space is not None and not SANITIZED:
        prelude += f"resource.setrlimit(resource.RLIMIT_AS, ({address_space}, {address_space}))\n"
    prelude += "import dispkin, json, sys\n"
    done = subprocess.run(
        [sys.executable, "-c", prelude + textwrap.dedent(code)], capture_output=True, text=True, timeout=timeout
    )
    return done.returncode, done.stdout, done.stderr


def refusal_in_child(call, address_space=None):
    """The ValueError message `call` (Python source) raises in a child process; fails the test if
    the child crashes or the call returns."""
    code = "try:\n" + textwrap.indent(textwrap.dedent(call).strip(), "    ") + "\n"
    code += "except ValueError as error:\n    print(str(error)[:2000])\n    sys.exit(0)\nsys.exit(3)\n"
    status, out, err = run_isolated(code, address_space)
    assert status == 0, f"child exited with {status} (negative: killed by a signal): {err[-2000:]}"
    return out


def hexapod_description():
    return json.loads(dispkin.Hexapod.symmetric(0.15, 0.3, 0.1, 0.3, 0.2, 0.15, 0.32, 0.01).to_json())


def planar_urdf(joint_origin="0 0 0.1", inertial=None, robot_attributes=""):
    """A two-joint planar arm (base → l1 → l2), with parts to change."""
    inertial = (
        inertial
        or '<inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>'
    )
    return f"""<robot name="planar"{robot_attributes}>
  <link name="base"/>
  <link name="l1">{inertial}</link>
  <link name="l2"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="{joint_origin}"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" velocity="1" effort="1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/><origin xyz="0.5 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" velocity="1" effort="1"/></joint>
</robot>"""


def robots_dir():
    """example-robot-data's URDFs (a cmeel package: cmeel.prefix/share/example-robot-data/robots)."""
    import importlib.metadata

    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        pytest.skip("example-robot-data is not installed")
    return pathlib.Path(dist.locate_file("cmeel.prefix/share/example-robot-data/robots"))


def cli_in_child(command, address_space=None, timeout=120):
    """(exit status, stderr) of `dispkin COMMAND...` run in a child process."""
    status, out, err = run_isolated(f"from dispkin import cli; sys.exit(cli.main({command!r}))", address_space, timeout)
    assert "Traceback" not in err, err[-3000:]
    return status, err
