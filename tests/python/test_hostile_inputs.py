"""Hostile inputs and the input budget (doc/input-budget.md), the descriptions: JSON and XML
nested deep, many attributes, absurd URDF numbers and joint graphs, hexapod files too large, in
bad bytes or with absurd legs. Each case either gives dispkin's own error (naming the argument,
its value or the file's line) or the right answer; never a crash, a hang, an unbounded
allocation or a silently changed model (the children that catch them: _hostile.py). Wide joint
limits and long chains are in test_hostile_kinematics.py, job and limits files in
test_hostile_job_files.py.
"""

import json
import re
import time

import pytest

import dispkin

from _hostile import SLOWDOWN, hexapod_description, planar_urdf, refusal_in_child, robots_dir, run_isolated


# --- 1. JSON nested 10⁵ deep ----------------------------------------------------------------


@pytest.mark.parametrize("depth", [101, 70_000, 100_000, 500_000])
def test_deep_json_is_refused_by_its_nesting_depth(depth):
    message = refusal_in_child(f"dispkin.Hexapod.from_json('[' * {depth} + ']' * {depth})")
    assert "description nesting depth = 101: arrays and objects nest at most 100 deep" in message


def test_deeper_json_is_refused_by_its_size():
    message = refusal_in_child("dispkin.Hexapod.from_json('[' * 1_000_000 + ']' * 1_000_000)")
    assert message.startswith("description size = 2000000: more than 1048576 bytes, the limit of a hexapod description")


def test_json_nesting_up_to_the_limit_is_read():
    # 100 levels are parsed and then refused for what they are, not for their depth.
    with pytest.raises(ValueError, match=r"must be a JSON object"):
        dispkin.Hexapod.from_json("[" * 100 + "]" * 100)


def test_deep_json_file_through_load_and_a_job(tmp_path):
    deep = tmp_path / "deep.json"
    deep.write_text('{"a":' * 100_000 + "1" + "}" * 100_000)
    message = refusal_in_child(f"dispkin.Hexapod.load({str(deep)!r})")
    assert message.startswith(f"{deep}: description nesting depth = 101")
    job = tmp_path / "job.yaml"
    job.write_text(JOB_WITH_HEXAPOD_FILE.format(file="deep.json"))
    status, out, err = run_isolated(f"from dispkin import cli; sys.exit(cli.main(['check', {str(job)!r}]))")
    assert status == 1 and "Traceback" not in err, err
    assert "description nesting depth = 101" in err and f"{job}:2:" in err


JOB_WITH_HEXAPOD_FILE = """machine:
  hexapod: {{file: {file}}}
metric_set:
  points:
    - relative: [[0, 0, 0.3], [0.1, 0, 0.3], [0, 0.1, 0.3]]
moves:
  - lin: {{to: {{xyzuvw: [0.01, 0, 0.2, 0, 0, 0]}}}}
limits: {{velocity: 0.1, acceleration: 0.5, jerk: 5.0}}
"""


# --- 2. XML nested 4·10⁴ deep; 9. 4·10⁴ attributes on one element -------------------------


@pytest.mark.parametrize("depth", [101, 40_000, 200_000])
def test_deep_xml_is_refused_before_it_is_parsed(depth, tmp_path):
    deep = tmp_path / "deep.urdf"
    deep.write_text(
        planar_urdf().replace('<link name="l2"/>', '<link name="l2">' + "<a>" * depth + "</a>" * depth + "</link>")
    )
    message = refusal_in_child(f"dispkin.SerialArm.from_urdf({str(deep)!r}, 'base', 'l2')")
    assert (
        message.startswith(f'{deep}: URDF element at = "line 4, column ')
        and "nests deeper than 100 elements" in message
    )


def test_xml_nesting_up_to_the_limit_is_read():
    # <robot>, <link> and 98 more levels: loaded (urdfdom ignores unknown elements).
    inside = "<a>" * 98 + "</a>" * 98
    arm = dispkin.SerialArm.from_urdf(
        planar_urdf().replace('<link name="l2"/>', f'<link name="l2">{inside}</link>'), "base", "l2"
    )
    assert arm.dof == 2


@pytest.mark.parametrize("count", [101, 40_000, 200_000])
def test_many_attributes_are_refused_in_linear_time(count):
    attributes = "".join(f' a{i}="{i}"' for i in range(count))
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r'URDF element at = "line 1, column 1": has more than 100 attributes'):
        dispkin.SerialArm.from_urdf(planar_urdf(robot_attributes=attributes), "base", "l2")
    assert time.perf_counter() - start < 1.0 * SLOWDOWN  # was 34 s for 4·10⁴ (TinyXML's quadratic lookup)


def test_a_urdf_beyond_the_size_limit_is_refused_unread(tmp_path):
    big = tmp_path / "big.urdf"
    big.write_text(planar_urdf() + " " * (16 * 2**20))
    with pytest.raises(ValueError, match=r"big.urdf\": is larger than 16777216 bytes, the limit of a URDF"):
        dispkin.SerialArm.from_urdf(str(big), "base", "l2")


# --- 5, 6, 7. URDF numbers and joint graph ----------------------------------------------------

INERTIA = '<inertia ixx="{ixx}" ixy="0" ixz="0" iyy="{iyy}" iyz="0" izz="{izz}"/>'


@pytest.mark.parametrize(
    "inertial, fragment",
    [
        (
            '<inertial><mass value="nan"/>' + INERTIA.format(ixx=0.1, iyy=0.1, izz=0.1) + "</inertial>",
            'link "l1" inertial mass = nan: must be finite (line 3)',
        ),
        (
            '<inertial><mass value="inf"/>' + INERTIA.format(ixx=0.1, iyy=0.1, izz=0.1) + "</inertial>",
            'link "l1" inertial mass = inf: must be finite (line 3)',
        ),
        (
            '<inertial><mass value="1"/>' + INERTIA.format(ixx="nan", iyy=0.1, izz=0.1) + "</inertial>",
            'link "l1" inertial inertia ixx = nan: must be finite',
        ),
        (
            '<inertial><origin xyz="0 nan 0"/><mass value="1"/>'
            + INERTIA.format(ixx=0.1, iyy=0.1, izz=0.1)
            + "</inertial>",
            'link "l1" inertial origin xyz = (0, nan, 0): must be finite',
        ),
        (
            '<inertial><mass value="1e300"/>' + INERTIA.format(ixx=0.1, iyy=0.1, izz=0.1) + "</inertial>",
            'link "l1" inertial mass = 1e+300: must be within ±1e12',
        ),
        (
            '<inertial><mass value="heavy"/>' + INERTIA.format(ixx=0.1, iyy=0.1, izz=0.1) + "</inertial>",
            'link "l1" inertial mass = "heavy": must be a number (line 3)',
        ),
        (
            '<inertial><mass value="-1"/>' + INERTIA.format(ixx=0.1, iyy=0.1, izz=0.1) + "</inertial>",
            'link "l1" inertial mass = -1: must be finite and not negative',
        ),
    ],
)
def test_impossible_inertial_numbers_are_refused(inertial, fragment):
    with pytest.raises(ValueError) as info:
        dispkin.SerialArm.from_urdf(planar_urdf(inertial=inertial), "base", "l2")
    assert fragment in str(info.value)


@pytest.mark.parametrize(
    "ixx, iyy, izz, fragment",
    [
        (-0.1, 0.1, 0.1, "(-0.1, 0, 0, 0.1, 0, 0.1): is not positive semidefinite"),
        (
            0.11,
            0.003,
            0.12,
            "(0.11, 0, 0, 0.003, 0, 0.12): is not the inertia of a body: its principal moments break the triangle inequality",
        ),
    ],
)
def test_impossible_inertias_load_for_kinematics_and_refuse_dynamics(ixx, iyy, izz, fragment):
    # Such inertias are common on links no chain uses (TIAGo's antennas, iCub's head): the
    # arm loads, its kinematics work, and its torques name the link instead of being wrong.
    inertial = '<inertial><mass value="1"/>' + INERTIA.format(ixx=ixx, iyy=iyy, izz=izz) + "</inertial>"
    arm = dispkin.SerialArm.from_urdf(planar_urdf(inertial=inertial), "base", "l2")
    assert len(arm.inverse(arm.forward([0.3, 0.4]))) > 0
    with pytest.raises(ValueError) as info:
        arm.static_torques([0.3, 0.4])
    assert str(info.value).startswith(
        'link "l1" inertial inertia (ixx, ixy, ixz, iyy, iyz, izz) = '
    ) and fragment in str(info.value)
    assert 'the torques of robot "planar" need a rigid body\'s inertia on every link from base_link to tip_link' in str(
        info.value
    )


def test_possible_inertias_on_the_edge_are_accepted():
    # A thin rod (0, m l²/12, m l²/12) and a flat plate (a, b, a + b) meet the inequality exactly.
    for ixx, iyy, izz in [(0.0, 0.1, 0.1), (0.02, 0.03, 0.05)]:
        inertial = '<inertial><mass value="1"/>' + INERTIA.format(ixx=ixx, iyy=iyy, izz=izz) + "</inertial>"
        assert dispkin.SerialArm.from_urdf(planar_urdf(inertial=inertial), "base", "l2").dof == 2


@pytest.mark.parametrize("origin", ["1e300 0 0", "0 0 -1e13", "0 0 inf"])
def test_absurd_joint_origins_are_refused(origin):
    with pytest.raises(ValueError, match=r'joint "j1" origin xyz = \(.*\): must be'):
        dispkin.SerialArm.from_urdf(planar_urdf(joint_origin=origin), "base", "l2")


def test_a_link_with_two_parent_joints_is_refused():
    second = (
        '<joint name="j3" type="revolute"><parent link="base"/><child link="l2"/>'
        '<axis xyz="0 0 1"/><limit lower="-3" upper="3" velocity="1" effort="1"/></joint>'
    )
    with pytest.raises(ValueError, match=r'link = "l2": is the child of two joints, "j2" and "j3" \(line \d+\)'):
        dispkin.SerialArm.from_urdf(planar_urdf().replace("</robot>", second + "</robot>"), "base", "l2")


def test_every_example_robot_data_urdf_still_loads():
    # The number checks refuse nothing of the real robots of example-robot-data.
    import xml.etree.ElementTree as ET

    checked = 0
    for urdf in sorted(robots_dir().glob("*/*/*.urdf")):
        root = ET.parse(urdf).getroot()
        joints = [j for j in root.iter("joint") if j.get("type") in ("revolute", "continuous")]
        if not joints:
            continue
        j = joints[0]
        parent, child = j.find("parent").get("link"), j.find("child").get("link")
        try:
            assert dispkin.SerialArm.from_urdf(str(urdf), parent, child).dof == 1, urdf
        except ValueError as error:  # refused by an older rule (e.g. a revolute joint with lower = upper)
            for new_check in (
                "URDF element at",
                "must be a number",
                "must be within ±1e12",
                "must be finite (line",
                "is the child of two joints",
                "nests deeper",
                "attributes",
            ):
                assert new_check not in str(error), str(error)
            continue
        checked += 1
    assert checked >= 20


# --- 12, 13, 15. hexapod descriptions: size, bytes, legs -------------------------------------


def test_a_huge_hexapod_file_is_refused_unread_with_a_short_message(tmp_path):
    d = hexapod_description()
    d["legs"] = d["legs"] * 20_000  # 120 000 legs, 9 MB
    big = tmp_path / "big.json"
    big.write_text(json.dumps(d))
    start = time.perf_counter()
    with pytest.raises(ValueError) as info:
        dispkin.Hexapod.load(str(big))
    assert time.perf_counter() - start < 0.5 * SLOWDOWN  # was 9.6 s for 163 MB
    assert "is larger than 1048576 bytes, the limit of a hexapod description" in str(info.value)
    assert len(str(info.value)) < 400


def test_a_many_legged_description_under_the_size_limit_is_not_echoed():
    d = hexapod_description()
    d["legs"] = d["legs"] * 1000  # 6000 legs, 800 kB
    with pytest.raises(ValueError) as info:
        dispkin.Hexapod.from_json(json.dumps(d))
    message = str(info.value)
    assert message.startswith('legs = "[{"base":') and message.endswith(
        ', … 6000 items]": must be an array of 6 leg objects'
    )
    assert len(message) < 300


def test_invalid_utf8_in_a_hexapod_string_is_dispkins_own_error(tmp_path):
    text = json.dumps(hexapod_description()).replace('"m, m/s"', '"m\\u00e9"').encode().replace(b"\\u00e9", b"\xe9\xff")
    broken = tmp_path / "broken.json"
    broken.write_bytes(text)
    with pytest.raises(ValueError) as info:
        dispkin.Hexapod.load(str(broken))
    assert "is not JSON" in str(info.value) and "\\xe9" in str(info.value)


@pytest.mark.parametrize("speed, shown", [(5e-324, "4.94065645841e-324"), (1e300, "1e+300"), (0.0, "0"), (-1.0, "-1")])
def test_leg_speeds_outside_the_numeric_range_are_refused_at_load(speed, shown):
    d = hexapod_description()
    d["legs"][3]["speed"] = speed
    with pytest.raises(ValueError, match=rf"^leg_speed\[3\] = {re.escape(shown)}: must be in \[1e-12, 1e12\]"):
        dispkin.Hexapod.from_json(json.dumps(d))


def test_a_misspelt_leg_key_is_refused_by_name():
    d = hexapod_description()
    d["legs"][2]["sped"] = d["legs"][2].pop("speed")
    with pytest.raises(
        ValueError, match=r"^legs\[2\]\.sped = 0\.01: unknown key \(allowed here: base, platform, min, max, speed\)"
    ):
        dispkin.Hexapod.from_json(json.dumps(d))
