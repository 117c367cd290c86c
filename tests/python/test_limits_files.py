"""MoveIt joint_limits.yaml and Pilz cartesian_limits.yaml."""

import os
import pathlib
import re

import numpy as np
import pytest

import dispkin
from dispkin.limits_files import (
    LimitsFileError,
    apply_moveit_joint_limits,
    read_moveit_joint_limits,
    read_pilz_cartesian_limits,
)

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"
MOVEIT = DATA / "limits" / "ur5e_joint_limits.yaml"
PILZ = DATA / "limits" / "pilz_cartesian_limits.yaml"
Q0 = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])


def ur5e():
    return dispkin.SerialArm.from_urdf(str(DATA / "urdf" / "arm_ur5e_dh.urdf"), "base_link", "tool0")


def test_moveit_file_is_read_with_its_flags():
    limits = read_moveit_joint_limits(MOVEIT)
    assert limits.default_velocity_scaling_factor == 0.5 and limits.default_acceleration_scaling_factor == 0.25
    assert limits.joints["shoulder_pan_joint"].max_velocity == 2.0
    assert limits.joints["elbow_joint"].min_position == -3.0
    assert limits.joints["wrist_1_joint"].max_acceleration is None  # has_acceleration_limits: false
    assert limits.joints["wrist_2_joint"].max_effort == 20.0
    assert "wrist_3_joint" not in limits.joints


def test_applied_limits_replace_the_urdf_ones_and_bind_in_the_retiming():
    arm = ur5e()
    updated, acceleration = apply_moveit_joint_limits(arm, MOVEIT)
    before, after = arm.joint_limits, updated.joint_limits
    np.testing.assert_array_equal(after.velocity, [2.0, 2.0, 2.5, 3.0, 3.0, before.velocity[5]])
    assert after.lower[2] == -3.0 and after.upper[2] == 3.0 and after.lower[0] == before.lower[0]
    assert after.effort[4] == 20.0 and after.effort[0] == before.effort[0]
    np.testing.assert_array_equal(acceleration, [6.0, 6.0, 8.0, np.inf, np.inf, np.inf])
    np.testing.assert_array_equal(arm.joint_limits.velocity, before.velocity)  # the original arm is unchanged

    a = updated.forward(Q0)
    turned = dispkin.Pose.from_xyzuvw([0, 0, 0, 0, 0, 0.5]) * a
    path = dispkin.Path.lin(a, dispkin.Pose(turned.quaternion, a.translation + np.array([0.25, -0.1, -0.1])))
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
    result = dispkin.retime(
        path,
        tool,
        dispkin.Limits(3.0, 300.0),
        updated,
        Q0,
        profile="trapezoid",
        method="optimal",
        joint_acceleration=acceleration,
    )
    dense = dispkin.check_joint_limits(result.trajectory, updated, Q0, samples_between=20).samples
    assert np.all(np.abs(dense["qd"]) <= after.velocity)
    assert np.all(np.abs(dense["qdd"][:, :3]) <= acceleration[:3])
    ratio = max(np.max(np.abs(dense["qd"]) / after.velocity), np.max(np.abs(dense["qdd"][:, :3]) / acceleration[:3]))
    assert ratio > 0.97  # the file's limits are the ones that bind


@pytest.mark.parametrize(
    "text, message",
    [
        ("joint_limits: 3", "joint_limits: missing"),
        (
            "joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n",
            "joint_limits.elbow_joint.max_velocity: missing",
        ),
        (
            "joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: -1\n",
            "joint_limits.elbow_joint.max_velocity = -1: must be > 0",
        ),
        (
            "joint_limits:\n  elbow_joint:\n    has_velocity_limits: yes please\n",
            "joint_limits.elbow_joint.has_velocity_limits = 'yes please': must be true or false",
        ),
        (
            "joint_limits:\n  elbow_joint:\n    has_acceleration_limits: true\n    max_acceleration: .nan\n",
            "joint_limits.elbow_joint.max_acceleration = nan: must be finite",
        ),
        (
            "joint_limits:\n  elbow_joint:\n    has_position_limits: true\n    min_position: 1\n    max_position: 1\n",
            "must have min_position < max_position",
        ),
        (
            "default_velocity_scaling_factor: 2\njoint_limits: {}\n",
            "default_velocity_scaling_factor = 2: must be in (0, 1]",
        ),
        ("joint_limits: [", "not valid YAML"),
    ],
)
def test_bad_moveit_files_name_the_key(tmp_path, text, message):
    file = tmp_path / "joint_limits.yaml"
    file.write_text(text)
    with pytest.raises(LimitsFileError) as error:
        read_moveit_joint_limits(file)
    assert message in str(error.value) and str(file) in str(error.value)


def test_a_joint_the_arm_does_not_have_is_an_error(tmp_path):
    file = tmp_path / "joint_limits.yaml"
    file.write_text("joint_limits:\n  elbow:\n    has_velocity_limits: true\n    max_velocity: 1.0\n")
    with pytest.raises(LimitsFileError, match=r"joint_limits\.elbow: not a joint of the arm"):
        apply_moveit_joint_limits(ur5e(), file)
    with pytest.raises(
        LimitsFileError, match="missing.yaml: the limits file cannot be read: No such file or directory"
    ):
        read_moveit_joint_limits(tmp_path / "missing.yaml")


def test_pilz_limits_and_the_rotation_sphere():
    pilz = read_pilz_cartesian_limits(PILZ)
    assert (pilz.max_trans_vel, pilz.max_trans_acc, pilz.max_trans_dec, pilz.max_rot_vel) == (1.0, 2.25, -5.0, 1.57)
    limits = pilz.limits()
    assert limits.velocity == 1.0 and limits.acceleration == 2.25 and limits.angular_velocity == 1.57
    assert pilz.limits(angular=False).angular_velocity is None
    assert pilz.rotation_sphere_radius == pytest.approx(1.0 / 1.57)
    # A pure turn of the tool: with the sphere in the set, the angular speed stays <= max_rot_vel.
    tool = dispkin.MetricSet()
    tool.add_relative([0.0, 0.0, 0.0])
    pilz.add_rotation_sphere(tool)
    start = dispkin.Pose.from_xyzuvw([0.4, 0.1, 0.3, 0, 0, 0])
    path = dispkin.Path.lin(start, start * dispkin.Pose.from_xyzuvw([0, 0, 0, 0.0, 0.0, 2.5]))
    traj = dispkin.plan(path, tool, pilz.limits(jerk=20.0, angular=False))
    poses = traj.sample(np.linspace(0, traj.duration, 2001))
    angles = [
        np.arccos(np.clip((np.trace(np.linalg.inv(a[:3, :3]) @ b[:3, :3]) - 1) / 2, -1, 1))
        for a, b in zip(poses[:-1], poses[1:])
    ]
    omega = np.array(angles) / (traj.duration / 2000)
    assert omega.max() <= pilz.max_rot_vel * (1 + 1e-3) and omega.max() > 0.99 * pilz.max_rot_vel


def test_pilz_angular_limit_binds_on_a_combined_move():
    # The rotational limit itself: on a move that turns and translates, the angular speed never
    # exceeds max_rot_vel and one of the two limits runs at its value in the cruise.
    pilz = read_pilz_cartesian_limits(PILZ)
    tool = dispkin.MetricSet()
    tool.add_relative([0.0, 0.0, 0.0])
    start = dispkin.Pose.from_xyzuvw([0.4, 0.1, 0.3, 0, 0, 0])
    path = dispkin.Path.lin(start, start * dispkin.Pose.from_xyzuvw([1.0, 0, 0, 0.0, 0.0, 150.0]))
    traj = dispkin.plan(path, tool, pilz.limits(jerk=20.0))
    twist = traj.body_twist(np.linspace(0, traj.duration, 4001))
    omega = np.linalg.norm(twist[:, 3:], axis=1)
    speed = np.linalg.norm(twist[:, :3], axis=1)
    assert omega.max() <= pilz.max_rot_vel * (1 + 1e-9) and speed.max() <= pilz.max_trans_vel * (1 + 1e-9)
    assert max(omega.max() / pilz.max_rot_vel, speed.max() / pilz.max_trans_vel) >= 0.995


@pytest.mark.parametrize(
    "text, message",
    [
        (
            "cartesian_limits:\n  max_trans_vel: 1\n  max_trans_acc: 2\n  max_trans_dec: 5\n  max_rot_vel: 1\n",
            "cartesian_limits.max_trans_dec = 5: must be < 0",
        ),
        (
            "cartesian_limits:\n  max_trans_vel: 1\n  max_trans_acc: 2\n  max_trans_dec: -5\n",
            "cartesian_limits.max_rot_vel: missing",
        ),
        (
            "max_trans_vel: fast\nmax_trans_acc: 2\nmax_trans_dec: -5\nmax_rot_vel: 1\n",
            "max_trans_vel = 'fast': must be a number",
        ),
        ("- 1\n- 2\n", "cartesian_limits: missing"),
    ],
)
def test_bad_pilz_files_name_the_key(tmp_path, text, message):
    file = tmp_path / "cartesian_limits.yaml"
    file.write_text(text)
    with pytest.raises(LimitsFileError) as error:
        read_pilz_cartesian_limits(file)
    assert message in str(error.value)


# --- read under the input budget of job files --------------------------------------------


def test_errors_name_the_line_and_column_of_the_key(tmp_path):
    file = tmp_path / "joint_limits.yaml"
    file.write_text("joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: -1\n")
    with pytest.raises(LimitsFileError) as error:
        read_moveit_joint_limits(file)
    assert str(error.value) == f"{file}:4:5: joint_limits.elbow_joint.max_velocity = -1: must be > 0"
    pilz = tmp_path / "cartesian_limits.yaml"
    pilz.write_text(
        "cartesian_limits:\n  max_trans_vel: 1\n  max_trans_acc: 2\n  max_trans_dec: -5\n  max_rot_vel: 1e300\n"
    )
    with pytest.raises(LimitsFileError) as error:
        read_pilz_cartesian_limits(pilz)
    assert str(error.value).startswith(f"{pilz}:5:3: cartesian_limits.max_rot_vel = 1e+300: must be in [1e-12, 1e+12]")


def test_numbers_are_yaml_1_2_as_in_job_files(tmp_path):
    file = tmp_path / "joint_limits.yaml"
    file.write_text("joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: 2e0\n")
    assert read_moveit_joint_limits(file).joints["elbow_joint"].max_velocity == 2.0


@pytest.mark.parametrize(
    "text, message",
    [
        (
            "joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: 1" + "0" * 400 + "\n",
            ":4:5: joint_limits.elbow_joint.max_velocity = an integer of 1329 bits: must be within ±2^53",
        ),
        (
            "joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: 1" + "0" * 4400 + "\n",
            ":4:19: (limits file): a value of 4401 characters, more than 4096",
        ),
        (
            "joint_limits: " + "[" * 1000 + "]" * 1000 + "\n",
            ":1:46: (limits file): mappings and lists nest deeper than 32 levels",
        ),
        (
            "joint_limits:\n  elbow_joint:\n    has_effort_limits: true\n    max_effort: 1e300\n",
            ":4:5: joint_limits.elbow_joint.max_effort = 1e+300: must be in [1e-12, 1e+12] in magnitude",
        ),
        (
            "joint_limits:\n  elbow_joint: &e {has_velocity_limits: true, max_velocity: *e}\n",
            ":2:61: (limits file): the alias *e is inside its own anchor: a limits file is a tree, not a cycle",
        ),
    ],
)
def test_hostile_moveit_files_are_refused_at_their_place(tmp_path, text, message):
    file = tmp_path / "joint_limits.yaml"
    file.write_text(text)
    with pytest.raises(LimitsFileError) as error:
        read_moveit_joint_limits(file)
    assert str(error.value).startswith(str(file)) and message in str(error.value), str(error.value)
    assert len(str(error.value)) < 1000


@pytest.mark.parametrize(
    "data, where",
    [
        (
            b"joint_limits:\n  elbow_joint: # d\xe9mo\n    has_velocity_limits: true\n",
            ":2:19: the limits file is not UTF-8 text: byte 0xe9",
        ),
        ("joint_limits: {}\n".encode("utf-16"), ":1:1: the limits file is not UTF-8 text: byte 0xff"),
    ],
)
def test_bytes_that_are_not_utf8_are_refused_at_their_line_and_column(tmp_path, data, where):
    file = tmp_path / "joint_limits.yaml"
    file.write_bytes(data)
    with pytest.raises(LimitsFileError, match=re.escape(str(file) + where)):
        read_moveit_joint_limits(file)


def test_a_utf8_byte_order_mark_is_read(tmp_path):
    file = tmp_path / "joint_limits.yaml"
    file.write_bytes(b"\xef\xbb\xbfjoint_limits:\n  elbow_joint: {has_velocity_limits: true, max_velocity: 1.5}\n")
    assert read_moveit_joint_limits(file).joints["elbow_joint"].max_velocity == 1.5


def test_a_file_beyond_the_size_limit_is_refused_unread(tmp_path):
    file = tmp_path / "joint_limits.yaml"
    with open(file, "wb") as f:  # 2 GB, sparse: nothing of it is read
        f.truncate(2 * 2**30)
    with pytest.raises(LimitsFileError, match=r"the limits file is larger than 33554432 bytes"):
        read_moveit_joint_limits(file)


def test_a_directory_fifo_or_device_is_named_for_what_it_is(tmp_path):
    with pytest.raises(LimitsFileError, match=r": is a directory, not a limits file"):
        read_moveit_joint_limits(tmp_path)
    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)  # opened without a writer: reading it would wait forever
    with pytest.raises(LimitsFileError, match=r"fifo\.yaml: is not a regular file \(a FIFO, a device or a socket\)"):
        read_pilz_cartesian_limits(fifo)
    with pytest.raises(LimitsFileError, match=r"/dev/null: is not a regular file"):
        read_moveit_joint_limits("/dev/null")


SEEDS = pathlib.Path(__file__).resolve().parents[1] / "fuzz" / "corpus" / "fuzz_limits_files"


@pytest.mark.parametrize("seed", sorted(SEEDS.iterdir()), ids=lambda p: p.name)
def test_the_fuzzing_seeds_read_or_are_refused(seed):
    # valid_* seeds read as one kind of limits file; bad_* seeds are refused by both readers.
    outcomes = []
    for reader in (read_moveit_joint_limits, read_pilz_cartesian_limits):
        try:
            reader(seed)
            outcomes.append("read")
        except LimitsFileError as error:
            assert str(error).startswith(str(seed)) and len(str(error)) < 2000
            outcomes.append("refused")
    assert outcomes.count("read") == (1 if seed.name.startswith("valid_") else 0), outcomes


@pytest.mark.parametrize("tagged, shown", [("!!float fast", "'fast' is no float"), ("!!int 1x", "'1x' is no int")])
def test_a_value_its_tag_cannot_make_is_refused_at_its_place(tmp_path, tagged, shown):
    file = tmp_path / "joint_limits.yaml"
    file.write_text(f"joint_limits:\n  elbow_joint:\n    has_velocity_limits: true\n    max_velocity: {tagged}\n")
    with pytest.raises(LimitsFileError, match=re.escape(f"{file}:4:19: not valid YAML: {shown}")):
        read_moveit_joint_limits(file)
