"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Hostile
inputs (doc/input-budget.md): nesting, sizes and counts, wide joint limits, impossible numbers,
the command line."""

import os
import pathlib

import numpy as np

from dispkin import jobs
from dispkin import limits_files
import dispkin

from .rows import A, B, LEGS, LIMITS, V, accepted, good_set, hexapod_json, leg_changed, row, section
from .serial_arm import URDF, arm
from .joint_motion import Q_UR, ur5e, ur_path
from .job_files import ExitStatus, GOOD_JOB, JOB_DIR, job_file, run_cli

# --- hostile inputs (doc/input-budget.md) -----------------------------------------------
PLANAR_URDF = (URDF / "arm_planar_two_link.urdf").read_text()


def planar(old, new):
    assert old in PLANAR_URDF, old
    return dispkin.SerialArm.from_urdf(PLANAR_URDF.replace(old, new, 1), "base", "link2")


def ur5e_within(bound):
    return ur5e().with_joint_limits(lower=[-bound] * 6, upper=[bound] * 6)


def hostile_job(name, text):
    return jobs.load_job(job_file(name, text))


HOSTILE_JOB_TAIL = "start: {xyzuvw: [0, 0, 0, 0, 0, 0]}\nmoves:\n  - lin: {to: {xyzuvw: [0.1, 0, 0, 0, 0, 0]}}\nlimits: {velocity: 0.1, acceleration: 1.0, jerk: 10}\n"
BOMB = "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1]\n" + "".join(
    f"{c}: &{c} [{', '.join(['*' + p] * 9)}]\n" for p, c in zip("abcdefgh", "bcdefghi")
)

section("Nesting depth")
row(
    "Hexapod.from_json",
    "arrays nested 10⁵ deep (was a segmentation fault)",
    lambda: dispkin.Hexapod.from_json("[" * 100_000 + "]" * 100_000),
    V,
    "description nesting depth = 101: arrays and objects nest at most 100 deep",
)
row(
    "Hexapod.from_json",
    "objects nested 101 deep",
    lambda: dispkin.Hexapod.from_json('{"a":' * 101 + "1" + "}" * 101),
    V,
    "description nesting depth = 101",
)
row(
    "SerialArm.from_urdf",
    "XML nested 4·10⁴ deep (was a segmentation fault)",
    lambda: planar('<link name="base"/>', '<link name="base"/>' + "<a>" * 40_000 + "</a>" * 40_000),
    V,
    "nests deeper than 100 elements",
)
row(
    "jobs.load_job",
    "lists nested 1000 deep (was a RecursionError)",
    lambda: hostile_job("deep.yaml", "name: " + "[" * 1000 + "]" * 1000 + "\n"),
    V,
    "deep.yaml:1:38: (job): mappings and lists nest deeper than 32 levels",
)
row(
    "jobs.load_job",
    "an alias inside its own anchor",
    lambda: hostile_job("cycle.yaml", "metric_set: &m\n  points: [*m]\n"),
    V,
    "cycle.yaml:2:12: (job): the alias *m is inside its own anchor",
)

section("Sizes and counts")
row(
    "Hexapod.from_json",
    "text over 1 MiB",
    lambda: dispkin.Hexapod.from_json(" " * (2**20 + 1)),
    V,
    "description size = 1048577: more than 1048576 bytes, the limit of a hexapod description",
)
row(
    "Hexapod.from_json",
    "6000 legs (message not echoing them)",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=LEGS * 1000)),
    V,
    ", … 6000 items]\": must be an array of 6 leg objects",
)
row(
    "SerialArm.from_urdf",
    "4·10⁴ attributes on <robot> (was 34 s)",
    lambda: planar(
        '<robot name="planar_two_link"', '<robot name="planar_two_link"' + "".join(f' a{i}="1"' for i in range(40_000))
    ),
    V,
    "has more than 100 attributes",
)
row(
    "jobs.load_job",
    "an alias bomb (9 lines, 3.9·10⁸ values)",
    lambda: hostile_job("bomb.yaml", BOMB),
    V,
    "bomb.yaml:6:32: (job): the job expands to more than 500000 values",
)
row(
    "jobs.load_job",
    "a value of 5000 characters",
    lambda: hostile_job("long.yaml", "name: " + "x" * 5000 + "\n"),
    V,
    "long.yaml:1:7: (job): a value of 5000 characters, more than 4096",
)
row(
    "jobs.load_job",
    "sample_period 1e-9",
    lambda: hostile_job("tiny.yaml", GOOD_JOB + "output: {sample_period: 1.0e-9}\n"),
    V,
    "tiny.yaml:9:10: output.sample_period: 1e-09: must be at least 1e-06 s",
)
row(
    "jobs.load_job",
    "integer beyond 64 bits",
    lambda: hostile_job("huge.yaml", GOOD_JOB.replace("jerk: 5.0", "jerk: 123456789012345678901234567890")),
    V,
    "huge.yaml:8:44: limits.jerk: an integer of 97 bits: numbers must be within ±2^53",
)

section("Inverse kinematics with wide joint limits")
accepted(
    "SerialArm.inverse",
    "joint limits ±1e16 rad",
    lambda: ur5e_within(1e16).inverse(ur5e().forward(Q_UR)),
    lambda solutions: len(solutions) == 8 and all(np.abs(q).max() <= np.pi + 1e-9 for q in solutions),
    "the 8 distinct solutions, every joint the 2π copy nearest 0 (was: none)",
)
row(
    "SerialArm.inverse",
    "2π copies of ±100 rad limits (was 23.6 GB)",
    lambda: ur5e_within(100.0).inverse(ur5e().forward(Q_UR), offer_equivalents=True),
    V,
    "offer_equivalents = \"true\": asks for the 2π copies of the 8 solutions inside the joint limits",
)

section("URDF numbers and joint graph")
row(
    "SerialArm.from_urdf",
    "NaN mass (was dropped)",
    lambda: planar('<mass value="2.0"/>', '<mass value="nan"/>'),
    V,
    'link "link1" inertial mass = nan: must be finite (line 22)',
)
row(
    "SerialArm.from_urdf",
    "infinite mass",
    lambda: planar('<mass value="2.0"/>', '<mass value="inf"/>'),
    V,
    'link "link1" inertial mass = inf: must be finite',
)
row(
    "SerialArm.from_urdf",
    "NaN ixx",
    lambda: planar('ixx="0.11"', 'ixx="nan"'),
    V,
    'link "link1" inertial inertia ixx = nan: must be finite',
)
row(
    "SerialArm.from_urdf",
    "NaN inertial origin",
    lambda: planar('<origin xyz="0.4 0 0"', '<origin xyz="0.4 nan 0"'),
    V,
    'link "link1" inertial origin xyz = (0.4, nan, 0): must be finite',
)
row(
    "SerialArm.torques",
    "a link with a negative principal moment",
    lambda: planar('ixx="0.11"', 'ixx="-0.11"').static_torques([0, 0]),
    V,
    'link "link1" inertial inertia (ixx, ixy, ixz, iyy, iyz, izz) = (-0.11, 0, 0, 0.01, 0, 0.12): is not positive semidefinite',
)
row(
    "SerialArm.torques",
    "a link breaking the triangle inequality",
    lambda: planar('ixx="0.11"', 'ixx="0.5"').static_torques([0, 0]),
    V,
    "(0.5, 0, 0, 0.01, 0, 0.12): is not the inertia of a body: its principal moments break the triangle inequality",
)
row(
    "SerialArm.from_urdf",
    "joint origin 1e300 m",
    lambda: planar('<origin xyz="0 0 0.3"', '<origin xyz="0 0 1e300"'),
    V,
    'joint "mount_joint" origin xyz = (0, 0, 1e+300): must be within ±1e12',
)
row(
    "SerialArm.from_urdf",
    "mass not a number",
    lambda: planar('<mass value="2.0"/>', '<mass value="2 kg"/>'),
    V,
    'link "link1" inertial mass = "2 kg": must be a number',
)
row(
    "SerialArm.from_urdf",
    "a link with two parent joints (was: one dropped)",
    lambda: planar(
        "</robot>", '<joint name="again" type="fixed"><parent link="base"/><child link="link2"/></joint></robot>'
    ),
    V,
    'link = "link2": is the child of two joints, "elbow" and "again"',
)

section("Hexapod descriptions and encodings")
row(
    "Hexapod.from_json",
    "leg speed 5e-324 (was accepted)",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed=5e-324))),
    V,
    "leg_speed[0] = 4.94065645841e-324: must be in [1e-12, 1e12]",
)
row(
    "Hexapod.from_json",
    "leg speed 1e300",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(speed=1e300))),
    V,
    "leg_speed[0] = 1e+300: must be in [1e-12, 1e12]",
)
row(
    "Hexapod.from_json",
    "misspelt per-leg key",
    lambda: dispkin.Hexapod.from_json(hexapod_json(legs=leg_changed(sped=0.01))),
    V,
    "legs[0].sped = 0.01: unknown key (allowed here: base, platform, min, max, speed)",
)
row(
    "Hexapod.from_json",
    "invalid UTF-8 in a string (was UnicodeDecodeError)",
    lambda: dispkin.Hexapod.from_json(hexapod_json(units="m").encode().replace(b'"m"', b'"m\xff"')),
    V,
    "ill-formed UTF-8 byte; last read: '\"m\\xff",
)
row(
    "Hexapod.load",
    "invalid UTF-8 bytes in the file",
    lambda: dispkin.Hexapod.load(job_file("latin1.json", hexapod_json(units="m").encode().replace(b'"m"', b'"m\xe9"'))),
    V,
    "ill-formed UTF-8 byte; last read: '\"m\\xe9",
)

section("Ignored arguments and degenerate geometry")
row(
    "retime",
    "scaling method with joint_acceleration (was ignored)",
    lambda: dispkin.retime(ur_path(), good_set(), LIMITS, ur5e(), Q_UR, joint_acceleration=np.ones(6)),
    V,
    'joint_acceleration = (1, 1, 1, 1, 1, 1): is not a limit of method="scaling"',
)
row(
    "Path.circ",
    "via 1e-9 m off the line beyond the end (was a 9.4·10⁷ m arc)",
    lambda: dispkin.Path.circ(A, dispkin.Pose.from_xyzuvw([0.2, 1e-9, 0, 0, 0, 0]), B),
    V,
    "via = (0.2, 1e-09, 0): is almost collinear with the start and end points and outside the segment between them",
)

section("URDF text, per-move limits and gravity")
PERCENT_LINK = '<robot name="r"><link name="l{}n"/></robot>'
for spelling, bad in [
    ("&#0000000000000000000000037;", "'%' as a zero-padded decimal character reference"),
    ("&#x100000025;", "'%' as a hexadecimal reference TinyXML wraps at 2^32"),
    ("&#4294967333;", "'%' as a decimal reference wrapping at 2^32 (Latin-1 document)"),
]:
    text = PERCENT_LINK.format(spelling)
    if "4294967333" in spelling:
        text = '<?xml version="1.0" encoding="ISO-8859-1"?>' + text
    row(
        "SerialArm.from_urdf",
        bad,
        lambda text=text: dispkin.SerialArm.from_urdf(text, "l%n", "b"),
        V,
        '<link> attribute "name" = "l%n": contains \'%\' (character references decoded)',
    )
row(
    "Path.lin",
    "move velocity 1e-17 (below the numeric range)",
    lambda: dispkin.Path.lin(A, B, velocity=1e-17),
    V,
    "velocity = 1e-17: must be in [1e-12, 1e12]",
)
row(
    "Path.lin",
    "move acceleration 1e13",
    lambda: dispkin.Path.lin(A, B, acceleration=1e13),
    V,
    "acceleration = 1e+13: must be in [1e-12, 1e12]",
)
row(
    "Path.circ",
    "move velocity 5e-324",
    lambda: dispkin.Path.circ(A, dispkin.Pose.from_xyzuvw([0.1, 0.05, 0, 0, 0, 0]), B, velocity=5e-324),
    V,
    "velocity = 4.94065645841e-324: must be in [1e-12, 1e12]",
)
row(
    "jobs.load_job",
    "a move's velocity 1e-17 before more moves (the trajectory ended after the first)",
    lambda: jobs.load_job(
        job_file(
            "tiny_move_velocity.yaml",
            data=[
                (
                    "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}\n",
                    "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}\n    velocity: 1.0e-17\n"
                    "  - lin: {to: {xyzuvw: [0.1, 0.02, 0, 10, 0, 30]}}\n",
                )
            ],
        )
    ),
    V,
    "tiny_move_velocity.yaml:8:5: moves[0].velocity: 1e-17: must be in [1e-12, 1e12]",
)
row(
    "SerialArm.gravity",
    "gravity 1e308 (NaN torques)",
    lambda: setattr(arm(), "gravity", [0, 0, 1e308]),
    V,
    "gravity = (0, 0, 1e+308): must have coordinates within ±1e12 m/s²",
)

section("Command line, second round")
UR_JOB = """name: ur
machine:
  serial_arm: {{urdf: {urdf}, base_link: base_link, tip_link: tool0, q_start: [0.0, -1.9, 1.9, -1.57, -1.57, 0.0]}}
metric_set:
  points:
    - relative: [[0, 0, 0.15]]
    - {{shape: sphere, radius: 0.04, center: [0, 0, 0]}}
moves:
  - lin: {{by: {{xyzuvw: [0.2, 0.1, -0.1, 0, 0, 30]}}}}
limits: {{velocity: 0.25, acceleration: 1.0, jerk: 10.0}}
"""


def ur_job(name, *lines):
    """The UR5e LIN move of examples/jobs/ur5e_lin_move.yaml in the job directory, `lines` appended."""
    return pathlib.Path(
        job_file(name, UR_JOB.format(urdf=URDF / "arm_ur5e_dh.urdf") + "".join(line + "\n" for line in lines))
    ).name


def named_limits_file(name, text):
    path = JOB_DIR / name
    path.write_bytes(text) if isinstance(text, bytes) else path.write_text(text)
    return str(path)


def effort_limit(joint, value):
    return f"joint_limits:\n  {joint}:\n    has_effort_limits: true\n    max_effort: {value}\n"


def special(name, make):
    """A FIFO or directory `name` in the job directory (made once)."""
    path = JOB_DIR / name
    if not path.exists():
        make(path)
    return path.name


# Eight anchors, each repeating the one before nine times: 9^8 = 4.3e7 values from nine lines.
BOMB_LIMITS = (
    "a: &a [x, x, x, x, x, x, x, x, x]\n"
    + "".join(f"{c}: &{c} [" + ", ".join([f"*{p}"] * 9) + "]\n" for p, c in zip("abcdefg", "bcdefgh"))
    + "joint_limits: {elbow_joint: *h}\n"
)

# Between the samples (every 0.01 s) shoulder_pan_joint needs 3.927 N·m, at them at most 3.842.
row(
    "cli.main",
    "plan: an effort limit broken only between samples (was exit 0)",
    lambda: run_cli(
        "plan",
        ur_job(
            "effort_between.yaml",
            f"limits_file: {named_limits_file('pan_3.9.yaml', effort_limit('shoulder_pan_joint', 3.9))}",
        ),
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 3: dispkin plan: effort_between.yaml: the trajectory breaks 1 machine limit(s) (use --allow-violations to accept it):\n"
    "  effort of shoulder_pan_joint: ",
)
row(
    "cli.main",
    "plan: a static torque beyond its effort limit (was a RuntimeError traceback)",
    lambda: run_cli(
        "plan",
        ur_job(
            "effort_static.yaml",
            f"limits_file: {named_limits_file('lift_5.yaml', effort_limit('shoulder_lift_joint', 5.0))}",
        ),
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 3: dispkin plan: effort_static.yaml: the trajectory breaks 1 machine limit(s) (use --allow-violations to accept it):\n"
    "  effort of shoulder_lift_joint: ",
)
row(
    "cli.main",
    "plan: output.csv '..' (was an IsADirectoryError traceback)",
    lambda: run_cli("plan", ur_job("dotdot.yaml", "output: {csv: '..'}"), "-o", "out"),
    ExitStatus,
    "exit status 1: dispkin plan: dotdot.yaml:11:10: output.csv: '..': a file name, not a path (the directory is `-o OUTDIR`)",
)
row(
    "cli.main",
    "plan: a 300-character job name (was an OSError traceback)",
    lambda: run_cli(
        "plan",
        pathlib.Path(job_file("long_name.yaml", data=[("metric_set:", "name: " + "n" * 300 + "\nmetric_set:")])).name,
        "-o",
        "out",
    ),
    ExitStatus,
    "exit status 1: dispkin plan: long_name.yaml:1:1: name: 'nnnnn",
)
row(
    "cli.main",
    "plan -o naming an existing file (was a FileExistsError traceback)",
    lambda: run_cli(
        "plan",
        pathlib.Path(job_file("to_file.yaml")).name,
        "-o",
        pathlib.Path(job_file("a_file.txt", "not a directory\n")).name,
    ),
    ExitStatus,
    "exit status 1: dispkin plan: -o OUTDIR = 'a_file.txt': is not a directory",
)
row(
    "cli.main",
    "plan: output.csv is the job file itself (was overwritten)",
    lambda: run_cli(
        "plan", pathlib.Path(job_file("itself.yaml", GOOD_JOB + "output: {csv: itself.yaml}\n")).name, "-o", "."
    ),
    ExitStatus,
    "exit status 1: dispkin plan: itself.yaml:9:10: output.csv: 'itself.yaml': 'itself.yaml' is the job file (itself.yaml): an input is never overwritten",
)
row(
    "cli.main",
    "plan: output.summary is the job's limits file (was overwritten)",
    lambda: run_cli(
        "plan",
        ur_job(
            "over_limits.yaml",
            f"limits_file: {named_limits_file('pan_4.yaml', effort_limit('shoulder_pan_joint', 4.0))}",
            "output: {summary: pan_4.yaml}",
        ),
        "-o",
        ".",
    ),
    ExitStatus,
    "output.summary: 'pan_4.yaml': 'pan_4.yaml' is a file the job reads (",
)
row(
    "cli.main",
    "check: limits_file a FIFO (was 'does not exist')",
    lambda: run_cli("check", ur_job("fifo_limits.yaml", f"limits_file: {special('limits.fifo', os.mkfifo)}")),
    ExitStatus,
    "fifo_limits.yaml:11:1: limits_file: ",
)
row(
    "cli.main",
    "check: limits_file a directory (was 'does not exist')",
    lambda: run_cli("check", ur_job("dir_limits.yaml", f"limits_file: {special('limits.dir', os.mkdir)}")),
    ExitStatus,
    "limits.dir': is a directory, not a file",
)
row(
    "cli.main",
    "check: the job file is a FIFO (would wait for a writer)",
    lambda: run_cli("check", special("job.fifo", os.mkfifo)),
    ExitStatus,
    "exit status 1: dispkin check: job.fifo: is not a regular file (a FIFO, a device or a socket), not a job file",
)
row(
    "read_moveit_joint_limits",
    "alias bomb of 9 lines (was 1 GB and a 226 MB message)",
    lambda: limits_files.read_moveit_joint_limits(named_limits_file("bomb_limits.yaml", BOMB_LIMITS)),
    limits_files.LimitsFileError,
    "(limits file): the limits file expands to more than 500000 values",
)
row(
    "read_moveit_joint_limits",
    "nesting 1000 deep (was a RecursionError)",
    lambda: limits_files.read_moveit_joint_limits(
        named_limits_file("deep_limits.yaml", "joint_limits: " + "[" * 1000 + "]" * 1000 + "\n")
    ),
    limits_files.LimitsFileError,
    "deep_limits.yaml:1:46: (limits file): mappings and lists nest deeper than 32 levels",
)
row(
    "read_moveit_joint_limits",
    "a 401-digit integer (was an OverflowError)",
    lambda: limits_files.read_moveit_joint_limits(
        named_limits_file("bigint_limits.yaml", effort_limit("elbow_joint", "1" + "0" * 400))
    ),
    limits_files.LimitsFileError,
    "bigint_limits.yaml:4:5: joint_limits.elbow_joint.max_effort = an integer of 1329 bits: must be within ±2^53",
)
row(
    "read_moveit_joint_limits",
    "a Latin-1 byte (was a UnicodeDecodeError)",
    lambda: limits_files.read_moveit_joint_limits(
        named_limits_file("latin1_limits.yaml", b"joint_limits:\n  elbow_joint: # d\xe9mo\n")
    ),
    limits_files.LimitsFileError,
    "latin1_limits.yaml:2:19: the limits file is not UTF-8 text: byte 0xe9",
)
row(
    "read_pilz_cartesian_limits",
    "max_rot_vel 1e300 (was accepted)",
    lambda: limits_files.read_pilz_cartesian_limits(
        named_limits_file(
            "pilz_big.yaml", "max_trans_vel: 1\nmax_trans_acc: 2\nmax_trans_dec: -5\nmax_rot_vel: 1e300\n"
        )
    ),
    limits_files.LimitsFileError,
    "pilz_big.yaml:4:1: max_rot_vel = 1e+300: must be in [1e-12, 1e+12] in magnitude",
)
row(
    "jobs.load_job",
    "nested-SLERP blend_weight 1e-300 (was 'planning failed: segments[0].length = 0')",
    lambda: jobs.load_job(
        job_file(
            "tiny_weight.yaml",
            data=[
                (
                    "  - lin: {to: {xyzuvw: [0.05, 0.02, 0, 10, 0, 30]}}",
                    "  - lin: {to: {xyzuvw: [0.05, 0, 0, 0, 0, 0]}}\n"
                    "  - lin: {to: {xyzuvw: [0.05, 0.05, 0, 0, 0, 30]}}\n"
                    "    blend_weight: 1e-300\n    orientation_blend: nested_slerp",
                )
            ],
        )
    ),
    V,
    "tiny_weight.yaml:9:5: moves[1].blend_weight: 1e-300: must be at least 1e-05",
)
row(
    "jobs.load_job",
    "angular_velocity 1e300 deg/s (was shown in rad/s at `limits`)",
    lambda: jobs.load_job(job_file("angular.yaml", data=[("jerk: 5.0}", "jerk: 5.0, angular_velocity: 1e300}")])),
    V,
    "angular.yaml:8:55: limits.angular_velocity: 1e+300: must be in [5.72958e-11, 5.72958e+13] deg/s",
)
