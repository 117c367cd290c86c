"""URDF text that urdfdom would hand to printf as a format: every spelling of '%' — literal,
numeric character references zero-padded or wrapping at 2³² as TinyXML decodes them, the low
byte of a code point in a document declared Latin-1, CDATA — is refused by name before urdfdom
reads it, through SerialArm.from_urdf, unpickling a SerialArm and `dispkin check`.

Each call runs in a child process: a format-string crash kills the child, not the suite.
"""

import pickle

import pytest

import dispkin
from _hostile import planar_urdf, refusal_in_child, run_isolated

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

# Spellings of '%' as TinyXML decodes them: its decimal and hexadecimal multipliers are 32-bit
# and wrap (16⁸ = 2³² ≡ 0), leading zeros are read without limit, 'X' is not a hex marker.
PERCENT = [
    "%",
    "&#37;",
    "&#x25;",
    "&#0000000000000000000000000000037;",
    "&#x00000000000000000000000025;",
    "&#x100000025;",
    "&#xABCDEF0100000025;",
    "&#x1234567800000025;",
]

# Where urdfdom builds messages from the text: names, attribute values it fails to read, text.
PLACES = {
    "link name": lambda p: planar_urdf().replace('<link name="l2"/>', f'<link name="l2{p}n"/>'),
    "joint origin": lambda p: planar_urdf(joint_origin=f"0 0 0.1{p}n"),
    "joint type": lambda p: planar_urdf().replace('type="revolute"', f'type="rev{p}s"', 1),
    "robot attribute": lambda p: planar_urdf(robot_attributes=f' version="1.{p}n"'),
    "material name": lambda p: planar_urdf().replace(
        '<link name="base"/>',
        f'<link name="base"><visual><geometry><box size="1 1 1"/></geometry><material name="m{p}s"/></visual></link>',
    ),
    "element text": lambda p: planar_urdf().replace('<link name="base"/>', f'<link name="base">{p}n{p}n</link>'),
}


def from_urdf_call(text):
    return f"dispkin.SerialArm.from_urdf({text!r}, 'base', 'l2')"


# Every spelling in one place, and the hardest spelling in every place (a child process each).
CASES = [("link name", s) for s in PERCENT] + [(p, "&#x1234567800000025;") for p in sorted(PLACES) if p != "link name"]


@pytest.mark.parametrize("place, spelling", CASES)
def test_every_spelling_of_a_percent_sign_is_refused(place, spelling):
    message = refusal_in_child(from_urdf_call(PLACES[place](spelling)))
    assert "contains '%'" in message and "printf" in message, message
    assert "URDF line " in message  # where it is


def test_the_low_byte_of_a_latin1_reference_is_refused():
    text = '<?xml version="1.0" encoding="ISO-8859-1"?>\n' + PLACES["link name"]("&#293;")
    message = refusal_in_child(from_urdf_call(text))
    assert 'attribute "name" = "l2%n"' in message, message
    # The same reference in UTF-8 is the character U+0125, no '%': the document loads.
    dispkin.SerialArm.from_urdf(PLACES["link name"]("&#293;").replace("l2&#293;n", "l2"), "base", "l2")


def test_cdata_text_is_refused():
    message = refusal_in_child(
        from_urdf_call(planar_urdf().replace('<link name="base"/>', '<link name="base"><![CDATA[%n%s]]></link>'))
    )
    assert 'text = "%n%s"' in message, message


def test_a_percent_sign_in_a_comment_is_read():
    arm = dispkin.SerialArm.from_urdf(
        planar_urdf().replace("<link name=\"base\"/>", "<!-- 100% steel, &#37; --><link name=\"base\"/>"), "base", "l2"
    )
    assert arm.dof == 2


def test_a_reference_to_another_character_is_read():
    text = (
        planar_urdf().replace('<link name="l2"/>', '<link name="l2&#x26;b"/>').replace('link="l2"', 'link="l2&#38;b"')
    )
    arm = dispkin.SerialArm.from_urdf(text, "base", "l2&b")
    assert arm.tip_link == "l2&b"


@pytest.mark.parametrize("spelling", ["&#x100000025;", "&#0000000000000000000037;"])
def test_unpickling_an_arm_reads_its_urdf_through_the_same_check(spelling):
    arm = dispkin.SerialArm.from_urdf(planar_urdf(), "base", "l2")
    state = list(arm.__getstate__())
    state[0] = PLACES["joint origin"](spelling)
    assert pickle.loads(pickle.dumps(arm)).forward([0.1, 0.2]).isclose(arm.forward([0.1, 0.2]))
    message = refusal_in_child(f"""
        import pickle
        arm = dispkin.SerialArm.__new__(dispkin.SerialArm)
        arm.__setstate__(pickle.loads({pickle.dumps(tuple(state))!r}))
    """)
    assert "contains '%'" in message, message


def test_a_job_naming_such_a_urdf_exits_with_a_message(tmp_path):
    urdf = tmp_path / "arm.urdf"
    urdf.write_text(PLACES["joint origin"]("&#x100000025;"))
    job = tmp_path / "job.yaml"
    job.write_text(f"""name: j
machine:
  serial_arm: {{urdf: {urdf}, base_link: base, tip_link: l2, q_start: [0.1, 0.2]}}
metric_set: {{points: [{{relative: [[0, 0, 0]]}}]}}
moves:
  - lin: {{by: {{xyzuvw: [0.01, 0, 0, 0, 0, 0]}}}}
limits: {{velocity: 0.1, acceleration: 0.5, jerk: 5.0}}
""")
    status, out, err = run_isolated(f"from dispkin.cli import main\nsys.exit(main(['check', {str(job)!r}]))")
    assert status > 0, (status, err[-2000:])
    assert "Traceback" not in err and "contains '%'" in err, err[-2000:]
