"""`dispkin check` fails exactly where `dispkin plan` would on seven-joint jobs (the Panda of
example-robot-data and the iiwa14 shipped in dispkin.data), with the redundancy parameter held
(`redundancy: q_start`) and moved (`redundancy: moved`, doc/inverse-kinematics.md §14): the same
message at the same key and the same exit status, never a traceback; jobs that pass pass both."""

import numpy as np
import pytest

import dispkin
from dispkin import cli

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

ARMS = {
    "panda": (
        "panda_link0",
        "panda_hand",
        [0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7],
        [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8],
    ),
    "iiwa14": ("link_0", "tool0", [0.3, 0.5, 0.2, -1.6, -0.3, 1.0, 0.4], [0.0, 0.3, 0.0, -1.4, 0.0, 1.0, 0.5]),
}
LIN = "lin: {by: {xyzuvw: [0.15, 0.1, -0.1, 0, 0, 20]}}"
FAR = "lin: {by: {xyzuvw: [1.5, 0, 0, 0, 0, 0]}}"  # out of reach of both arms
TURN = "lin: {by: {xyzuvw: [0, 0, 0, 0, 0, 170]}}"  # the tool turned about its axis


def seven_joint_job(tmp_path, arm, moves, redundancy="q_start", method="scaling", ptp=False):
    """A job for `arm` ("panda" or "iiwa14") with the Cartesian `moves` (one per line) and, with
    `ptp`, a PTP move to joints inside the arm's limits after them."""
    if arm == "panda":
        from test_serial_arm import panda_urdf_without_fingers

        urdf = tmp_path / "panda.urdf"
        urdf.write_text(panda_urdf_without_fingers())
    else:
        urdf = dispkin.data.path("iiwa14.urdf")
    base, tip, q_start, q_ptp = ARMS[arm]
    lines = [f"  - {move}" for move in moves] + ([f"  - ptp: {{joints: {q_ptp}}}"] if ptp else [])
    job = tmp_path / f"{arm}_{redundancy}_{method}.yaml"
    job.write_text(
        f"""name: seven
machine:
  serial_arm:
    urdf: {urdf}
    base_link: {base}
    tip_link: {tip}
    q_start: {q_start}
    redundancy: {redundancy}
metric_set:
  points:
    - relative: [[0, 0, 0.1]]
    - {{shape: sphere, radius: 0.05, center: [0, 0, 0]}}
moves:
"""
        + "\n".join(lines)
        + f"""
limits: {{velocity: 0.1, acceleration: 1.0, jerk: 10.0}}
retime: {{method: {method}}}
output: {{sample_period: 0.01}}
"""
    )
    return job


def check_and_plan(job, tmp_path, capsys):
    """(exit status, stderr) of `dispkin check` and of `dispkin plan` on `job`; cli.main returns
    (an exception out of it would be a traceback on the command line)."""
    capsys.readouterr()
    checked = cli.main(["check", str(job)]), capsys.readouterr().err
    planned = cli.main(["plan", str(job), "-o", str(tmp_path / "out")]), capsys.readouterr().err
    return checked, planned


def expect_the_same_failure(job, tmp_path, capsys, *words):
    (check_status, check_error), (plan_status, plan_error) = check_and_plan(job, tmp_path, capsys)
    assert check_status == plan_status == 1, (check_error, plan_error)
    assert check_error.startswith("dispkin check: ") and "Traceback" not in check_error + plan_error
    assert plan_error == check_error.replace("dispkin check:", "dispkin plan:")
    for word in words:
        assert word in check_error, check_error


@pytest.mark.parametrize("arm", sorted(ARMS))
def test_a_target_out_of_reach_fails_check_and_plan_alike(tmp_path, capsys, arm):
    for redundancy in ("q_start", "moved"):
        job = seven_joint_job(tmp_path, arm, [FAR], redundancy)
        expect_the_same_failure(job, tmp_path, capsys, "moves[0]", "poses[")


def test_a_joint_limit_in_the_way_fails_check_and_plan_alike(tmp_path, capsys):
    """At q_start's parameter value the iiwa14's turn runs into a joint limit (no solution within
    the limits) and the Panda's run downwards into the end of its branch (a joint step); moved,
    the Panda's does too."""
    for arm, move, redundancy, words in [
        ("iiwa14", TURN, "q_start", ["no inverse-kinematics solution within the joint limits"]),
        ("panda", "lin: {by: {xyzuvw: [0, 0, -0.5, 0, 0, 0]}}", "q_start", ["joint step"]),
        ("panda", "lin: {by: {xyzuvw: [0, 0, -0.5, 0, 0, 0]}}", "moved", ["joint step"]),
    ]:
        expect_the_same_failure(
            seven_joint_job(tmp_path, arm, [move], redundancy), tmp_path, capsys, "moves[0]", *words
        )


@pytest.mark.parametrize(
    "method, ptp, words",
    [("scaling", False, "did not converge"), ("optimal", False, "cannot follow"), ("optimal", True, "cannot follow")],
)
def test_a_moved_run_that_breaks_the_limits_when_planned_fails_check_and_plan_alike(
    tmp_path, capsys, method, ptp, words
):
    """The Panda turning its tool with the parameter moved: the joints can follow the poses, but
    the planned run cannot keep the joint limits (the scaling loop does not converge; the optimal
    re-timing's trajectory cannot be followed on its branch). Such a run is planned while the job
    is read, with or without a PTP move after it, so `check` meets the failure at the run's first
    move as `plan` does."""
    job = seven_joint_job(tmp_path, "panda", [TURN], "moved", method, ptp=ptp)
    expect_the_same_failure(job, tmp_path, capsys, "moves[0]", words)


@pytest.mark.parametrize("redundancy", ["q_start", "moved"])
def test_the_iiwa14_jobs_that_plan_pass_check(tmp_path, capsys, redundancy):
    """The iiwa14 shipped with dispkin: a LIN and a PTP move after it pass both commands, held and
    moved, re-timed optimally; the written joints start at q_start."""
    import csv

    job = seven_joint_job(tmp_path, "iiwa14", [LIN], redundancy, "optimal", ptp=True)
    (check_status, check_error), (plan_status, plan_error) = check_and_plan(job, tmp_path, capsys)
    assert (check_status, check_error, plan_status, plan_error) == (0, "", 0, "")
    rows = list(csv.reader((tmp_path / "out" / "seven.csv").open()))
    q = np.array(rows[1], dtype=float)[[rows[0].index(f"joint_a{k}.position") for k in range(1, 8)]]
    # Moved, FollowedTrajectory starts at q_start itself; held, the joints are the IK at the start
    # pose on q_start's branch (to rounding).
    np.testing.assert_allclose(q, ARMS["iiwa14"][2], rtol=0, atol=0 if redundancy == "moved" else 1e-12)
