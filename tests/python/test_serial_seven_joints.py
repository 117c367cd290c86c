"""Seven-joint arms (doc/inverse-kinematics.md §11): every IK solution at a value of the
redundancy parameter (a locked joint), checked by round trips on the Franka Panda
(example-robot-data) and a KUKA iiwa14 written from its published kinematics, and against IK-Geo
(the `ik-geo` package) on the 6R chain the locked joint leaves; following a path at one parameter
value without jumps; the serial features that invert the Jacobian (FollowedTrajectory, the
joint-limit check, re-timing) on the Panda."""

import pathlib

import numpy as np
import pytest

import dispkin
from test_serial_arm import panda_urdf_without_fingers, random_q

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

IIWA = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf" / "arm_iiwa14_dh.urdf"
SEED = 20261204
ROUND_TRIPS = 300  # per arm: a few ms (the 10⁵ of benchmarks/RESULTS.md run outside the suite)


def panda():
    return dispkin.SerialArm.from_urdf(panda_urdf_without_fingers(), "panda_link0", "panda_hand")


def iiwa():
    return dispkin.SerialArm.from_urdf(str(IIWA), "link_0", "tool0")


ARMS = {"panda": panda, "iiwa14": iiwa}


@pytest.fixture(params=sorted(ARMS), scope="module")
def arm(request):
    return ARMS[request.param]()


def wrapped(q):
    return np.remainder(np.asarray(q) + np.pi, 2.0 * np.pi) - np.pi


def test_the_iiwa14_ships_with_the_package():
    # dispkin.data.path("iiwa14.urdf") is the model these tests load from tests/data, byte for byte.
    shipped = pathlib.Path(dispkin.data.path("iiwa14.urdf"))
    assert "iiwa14.urdf" in dispkin.data.names() and shipped.read_bytes() == IIWA.read_bytes()
    arm = dispkin.SerialArm.from_urdf(str(shipped), "link_0", "tool0")
    assert arm.dof == 7 and arm.family == "locked_joint" and arm.redundancy.kind == "locked_joint"
    q = np.array([0.3, -0.5, 0.4, 1.1, -0.2, 0.7, 0.25])
    first = arm.inverse(arm.forward(q), q_ref=q)[0]
    assert np.max(np.abs(wrapped(first - q))) < 1e-9


def test_the_last_joint_is_the_parameter(arm):
    assert arm.dof == 7 and arm.family == "locked_joint"
    r = arm.redundancy
    assert r.kind == "locked_joint" and r.joint == 6 and r.joint_name == arm.joint_names[6]
    limits = arm.joint_limits
    assert (r.lower, r.upper) == (limits.lower[6], limits.upper[6])
    values = np.array(r.default_values)
    assert len(values) == 16 and np.all(np.diff(values) > 0) and r.lower < values[0] and values[-1] < r.upper
    q = random_q(np.random.default_rng(SEED), arm, 1)[0]
    assert r.value(q) == q[6]


def test_round_trips_find_the_generating_joints_first(arm):
    rng = np.random.default_rng(SEED + 1)
    worst_pose, worst_first = 0.0, 0.0
    for q in random_q(rng, arm, ROUND_TRIPS):
        pose = arm.forward(q)
        solutions = arm.inverse(pose, q_ref=q)
        assert len(solutions) >= 1, q
        worst_first = max(worst_first, np.abs(solutions[0] - q).max())
        for s in solutions:
            assert s[6] == q[6]  # every one at q_ref's parameter value
            worst_pose = max(worst_pose, np.abs(arm.forward(s).matrix() - pose.matrix()).max())
        at_value = arm.inverse(pose, redundancy=q[6])
        assert sorted(map(tuple, at_value)) == sorted(map(tuple, solutions))
        assert np.all(np.linalg.norm(solutions - q, axis=1)[:-1] <= np.linalg.norm(solutions - q, axis=1)[1:])
    assert worst_first <= 1e-9 and worst_pose <= 1e-10


def test_without_a_value_the_default_values_are_solved(arm):
    q = random_q(np.random.default_rng(SEED + 2), arm, 1)[0]
    pose = arm.forward(q)
    result = arm.inverse_solutions(pose, keep_outside_limits=True)
    assert not result.complete and result.family == "locked_joint"
    values = np.array(arm.redundancy.default_values)
    per_value = {v: 0 for v in values}
    for s in result.solutions:
        assert arm.forward(s).is_approx(pose, 1e-10)
        per_value[values[np.argmin(np.abs(values - s[6]))]] += 1
        assert np.min(np.abs(values - s[6])) <= 1e-9
    for v, count in per_value.items():
        assert count == len(arm.inverse_solutions(pose, keep_outside_limits=True, redundancy=v).solutions)
    assert arm.inverse_solutions(pose, redundancy=q[6]).complete


def line_points(jacobian, origin):
    """A point on each joint axis at q = 0 from the geometric Jacobian's columns (v, w):
    v = w x (o - p), so o + w x v lies on the axis."""
    return np.array([origin + np.cross(jacobian[3:, i], jacobian[:3, i]) for i in range(jacobian.shape[1])])


def meeting_point(points, axes):
    """The point nearest (least squares) to the lines through points along unit axes."""
    a = sum(np.eye(3) - np.outer(w, w) for w in axes)
    b = sum((np.eye(3) - np.outer(w, w)) @ p for p, w in zip(points, axes))
    return np.linalg.solve(a, b)


def rotation_about_line(axis, point, angle):
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    r = np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = r, point - r @ point
    return m


def test_solution_sets_match_ik_geo_on_the_chain_left(arm):
    """IK-Geo's spherical-wrist solver on the 6R chain q₇ = θ leaves, read from the tip back
    (doc/inverse-kinematics.md eqs. 37b, 38): the same solutions as arm.inverse(pose, redundancy=θ)."""
    ik_geo = pytest.importorskip("ik_geo")
    zero = np.zeros(7)
    m = arm.forward(zero).matrix()
    m_inv = np.linalg.inv(m)
    axes = arm.jacobian(zero)[3:].T
    points = line_points(arm.jacobian(zero), m[:3, 3])
    # The reversed chain: axes 6, 5, …, 1 seen from the tip at q = 0; tip M⁻¹.
    h = np.array([m_inv[:3, :3] @ axes[5 - k] for k in range(6)])
    p_rev = np.array([m_inv[:3, :3] @ points[5 - k] + m_inv[:3, 3] for k in range(6)])
    wrist = meeting_point(p_rev[3:], h[3:])  # the arm's shoulder
    first = meeting_point(p_rev[:2], h[:2])  # axes 6 and 5 of the arm
    on_axis = [first, first, p_rev[2], wrist, wrist, wrist]
    p = np.array([on_axis[0]] + [on_axis[k + 1] - on_axis[k] for k in range(5)] + [m_inv[:3, 3] - wrist])
    solver = ik_geo.Robot.spherical_two_intersecting(h, p)
    rng = np.random.default_rng(SEED + 3)
    compared = 0
    for q in random_q(rng, arm, 40):
        theta = q[6]
        pose = arm.forward(q).matrix()
        target = pose @ m_inv @ rotation_about_line(axes[6], points[6], -theta) @ m
        target_rev = np.linalg.inv(target)
        # ik-geo reads (and its forward kinematics writes) the rotation matrix transposed.
        found = solver.get_ik((target_rev[:3, :3] @ m[:3, :3]).T, target_rev[:3, 3])
        theirs = [np.append(-np.array(x)[::-1], theta) for x, least_squares in found if not least_squares]
        theirs = [x for x in theirs if np.abs(arm.forward(x).matrix() - pose).max() <= 1e-8]
        ours = arm.inverse_solutions(
            dispkin.Pose.from_matrix(pose), keep_outside_limits=True, redundancy=theta
        ).solutions
        assert len(ours) == len(theirs), (q, len(ours), len(theirs))
        for x in theirs:
            assert min(np.abs(wrapped(s - x)).max() for s in ours) <= 1e-6
        compared += len(ours)
    assert compared >= 40 * 2


def test_q_ref_orders_a_six_joint_arm_too_and_bad_arguments_are_named():
    ur5e = dispkin.SerialArm.from_urdf(str(IIWA.parent / "arm_ur5e_dh.urdf"), "base_link", "tool0")
    assert ur5e.redundancy.kind == "none"
    q = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
    ordered = ur5e.inverse(ur5e.forward(q), q_ref=q)
    assert np.abs(ordered[0] - q).max() <= 1e-9 and len(ordered) == len(ur5e.inverse(ur5e.forward(q)))
    with pytest.raises(ValueError, match="redundancy = 0.5: the arm has no redundancy parameter"):
        ur5e.inverse(ur5e.forward(q), redundancy=0.5)
    with pytest.raises(ValueError, match="redundancy"):
        ur5e.redundancy.value(q)
    a = panda()
    qp = random_q(np.random.default_rng(SEED + 4), a, 1)[0]
    with pytest.raises(ValueError, match="either redundancy or q_ref"):
        a.inverse(a.forward(qp), redundancy=0.1, q_ref=qp)
    with pytest.raises(ValueError, match="redundancy = nan"):
        a.inverse(a.forward(qp), redundancy=float("nan"))
    with pytest.raises(TypeError, match="redundancy"):
        a.inverse(a.forward(qp), redundancy="q7")
    with pytest.raises(ValueError, match="q_ref"):
        a.inverse(a.forward(qp), q_ref=qp[:6])


def lin_poses(arm, q, offset, count):
    a = arm.forward(q)
    return [dispkin.Pose(a.quaternion, a.translation + offset * k / (count - 1)) for k in range(count)]


def test_follow_starts_at_q_start_and_never_jumps(arm):
    rng = np.random.default_rng(SEED + 5)
    limits = arm.joint_limits
    middle = 0.5 * (limits.lower + limits.upper)
    followed = 0
    for q in middle + 0.5 * (random_q(rng, arm, 20) - middle):  # the inner half of the ranges
        poses = lin_poses(arm, q, rng.uniform(-0.05, 0.05, 3), 26)
        try:
            path = arm.follow(poses, q)
        except RuntimeError as e:
            assert "joint step" in str(e) or "no inverse-kinematics solution" in str(e)
            continue
        followed += 1
        assert np.abs(path[0] - q).max() <= 1e-9
        assert np.abs(np.diff(path, axis=0)).max() <= 0.3
        for pose, x in zip(poses, path):
            assert np.abs(arm.forward(x).matrix() - pose.matrix()).max() <= 1e-10
        try:
            kept = arm.follow(poses, q, move_redundancy=False)
        except RuntimeError:
            continue  # the branch at q_start's value ends where the moved one goes on
        assert np.all(kept[:, 6] == q[6])  # without the rule the parameter stays at q_start's value
        assert np.array_equal(arm.follow(poses, q, max_rate=0.0), kept)
    assert followed >= 10


def test_the_parameter_moves_at_most_at_the_rule_s_rate(arm):
    """doc/inverse-kinematics.md (eq. 45): from pose k − 1 to pose k the parameter moves by at
    most ρ times the joints' travel at the previous value (the nearest solution there), and it
    does move on a path whose joints near their limits."""
    rng = np.random.default_rng(SEED + 6)
    rate, moved = 0.2, 0.0
    for q in random_q(rng, arm, 6):
        poses = lin_poses(arm, q, rng.uniform(-0.05, 0.05, 3), 21)
        try:
            path = arm.follow(poses, q, max_rate=rate)
        except RuntimeError:
            continue
        for k in range(1, len(path)):
            at_previous = arm.inverse(poses[k], q_ref=path[k - 1])[0]  # nearest first, at θ_{k−1}
            travel = np.linalg.norm(at_previous - path[k - 1])
            assert abs(path[k, 6] - path[k - 1, 6]) <= rate * travel + 1e-12
        moved = max(moved, np.abs(path[:, 6] - q[6]).max())
    assert moved > 1e-3


def barrier_margin(arm, path):
    """The smallest distance of any joint to its nearer limit, as a fraction of its half range."""
    limits = arm.joint_limits
    half = 0.5 * (limits.upper - limits.lower)
    return np.min(np.minimum(limits.upper - path, path - limits.lower) / half)


def test_the_rule_keeps_the_arm_away_from_the_limits_a_fixed_parameter_runs_into(arm):
    """LIN moves of 0.15 m per axis from the inner 60 % of the ranges: the rule follows every path
    the fixed parameter follows, and some on which the branch at q_start's value ends (at a joint
    limit); on the paths both follow its joints keep farther from the limits on average."""
    rng = np.random.default_rng(SEED + 8)
    limits = arm.joint_limits
    middle = 0.5 * (limits.lower + limits.upper)
    rescued, margins = 0, []
    for q in middle + 0.6 * (random_q(rng, arm, 40) - middle):
        poses = lin_poses(arm, q, rng.uniform(-0.15, 0.15, 3), 61)
        try:
            kept = arm.follow(poses, q, move_redundancy=False)
        except RuntimeError:
            kept = None
        try:
            moved = arm.follow(poses, q)
        except RuntimeError:
            assert kept is None, "the rule lost a path the fixed parameter follows"
            continue
        assert np.abs(moved[0] - q).max() <= 1e-9 and np.abs(np.diff(moved, axis=0)).max() <= 0.3
        if kept is None:
            rescued += 1
        else:
            margins.append((barrier_margin(arm, moved), barrier_margin(arm, kept)))
    margins = np.array(margins)
    assert rescued >= 1 and len(margins) >= 10
    assert margins[:, 0].mean() > margins[:, 1].mean()


def test_bad_rule_values_are_named():
    arm = panda()
    q = np.array([0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7])
    for name, value in [("gain", -1.0), ("max_rate", float("nan")), ("singularity_weight", float("inf"))]:
        with pytest.raises(ValueError, match=f"redundancy_rule.{name}"):
            arm.follow([arm.forward(q)], q, **{name: value})


def panda_lin():
    a = panda()
    q = np.array([0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7])
    start = a.forward(q)
    end = dispkin.Pose(start.quaternion, start.translation + np.array([0.15, 0.1, -0.1]))
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
    return a, q, dispkin.Path.lin(start, end), tool


def test_panda_lin_is_followed_checked_and_retimed():
    a, q, path, tool = panda_lin()
    traj = dispkin.plan(path, tool, dispkin.Limits(1.0, 20.0, 400.0))
    followed = dispkin.FollowedTrajectory.from_start(traj, a, q)
    assert followed.dof == 7 and np.abs(followed.start - q).max() <= 1e-12
    t = np.linspace(0.0, traj.duration, 41)
    positions, velocities = followed.joint_positions(t), followed.joint_velocities(t)
    assert np.abs(positions[:, 6] - q[6]).max() <= 1e-12 and np.all(velocities[:, 6] == 0.0)
    assert np.all(followed.joint_accelerations(t)[:, 6] == 0.0)
    assert np.abs(followed.sample(t) - traj.sample(t)).max() <= 1e-6
    assert np.abs(np.diff(positions, axis=0)).max() <= 0.3
    report = dispkin.check_joint_limits(traj, a, q)
    assert report.samples["q"].shape[1] == 7
    np.testing.assert_allclose(report.samples["q"][0], q, atol=1e-9)
    # Scaling keeps the limits at the instants it checks: the check at those instants agrees.
    scaled = dispkin.retime(path, tool, dispkin.Limits(1.5, 400.0, 1e5), a, q, method="scaling", samples_between=50)
    again = dispkin.check_joint_limits(scaled.trajectory, a, q, samples_between=50)
    assert scaled.report.within_limits and again.velocity_factor <= 1.0 and again.acceleration_factor <= 1.0
    # The optimal re-timing keeps the joint speeds and torques between its instants too (its dense check).
    optimal = dispkin.retime(path, tool, dispkin.Limits(1.5, 400.0), a, q, profile="trapezoid", method="optimal")
    dense = dispkin.check_joint_limits(optimal.trajectory, a, q, samples_between=30)
    limits = a.joint_limits
    assert np.all(np.abs(dense.samples["qd"]) <= limits.velocity)
    assert np.all(np.abs(dense.samples["static_torque"] + dense.samples["dynamic_torque"]) <= limits.effort)
    assert np.all(dense.samples["qd"][:, 6] == 0.0)


PANDA_JOB = """name: panda_lin_and_ptp
machine:
  serial_arm:
    urdf: {urdf}
    base_link: panda_link0
    tip_link: panda_hand
    q_start: [0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7]
    {redundancy}
metric_set:
  points:
    - relative: [[0, 0, 0.1]]
    - {{shape: sphere, radius: 0.05, center: [0, 0, 0]}}
moves:
  - lin: {{by: {{xyzuvw: [0.15, 0.1, -0.1, 0, 0, 20]}}}}
  - ptp: {{by_pose_of: null}}
limits: {{velocity: 0.1, acceleration: 1.0, jerk: 10.0}}
retime: {{method: scaling}}
output: {{sample_period: 0.01}}
"""


def panda_job(tmp_path, urdf_text, redundancy="redundancy: q_start", ptp=True):
    urdf = tmp_path / "panda.urdf"
    urdf.write_text(urdf_text)
    text = PANDA_JOB.format(urdf=urdf, redundancy=redundancy)
    if ptp:
        text = text.replace("  - ptp: {by_pose_of: null}", "  - ptp: {joints: [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8]}")
    else:
        text = text.replace("  - ptp: {by_pose_of: null}\n", "")
    job = tmp_path / "job.yaml"
    job.write_text(text)
    return job


def test_a_panda_job_checks_and_plans(tmp_path, capsys):
    from dispkin import cli

    job = panda_job(tmp_path, panda_urdf_without_fingers())
    assert cli.main(["check", str(job)]) == 0
    assert "redundancy: joint panda_joint7" in capsys.readouterr().out
    assert cli.main(["plan", str(job), "-o", str(tmp_path / "out")]) == 0
    import csv

    rows = list(csv.reader((tmp_path / "out" / "panda_lin_and_ptp.csv").open()))
    header, first = rows[0], np.array(rows[1], dtype=float)
    joints = [header.index(f"panda_joint{k}.position") for k in range(1, 8)]
    np.testing.assert_allclose(first[joints], [0.1, -0.4, 0.2, -2.0, 0.1, 1.8, 0.7], atol=1e-9)


def test_check_fails_where_plan_would_on_seven_joints_without_a_parameter(tmp_path, capsys):
    """The Panda with its shoulder moved off axis 1 has no redundancy parameter: a lin move cannot
    be followed, and `check` says so at the move as `plan` does; `redundancy:` is refused for it."""
    from dispkin import cli
    import xml.etree.ElementTree as ET

    root = ET.fromstring(panda_urdf_without_fingers())
    next(j for j in root.findall("joint") if j.get("name") == "panda_joint2").find("origin").set("xyz", "0.03 0 0")
    text = ET.tostring(root, encoding="unicode")
    job = panda_job(tmp_path, text, redundancy="", ptp=False)
    assert cli.main(["check", str(job)]) == 1
    check_error = capsys.readouterr().err
    assert "moves[0].lin" in check_error and "redundancy parameter" in check_error
    assert cli.main(["plan", str(job), "-o", str(tmp_path / "out")]) == 1
    assert capsys.readouterr().err == check_error.replace("dispkin check:", "dispkin plan:")
    job = panda_job(tmp_path, text, ptp=False)
    assert cli.main(["check", str(job)]) == 1
    assert "machine.serial_arm.redundancy" in capsys.readouterr().err


def test_follow_refuses_a_jump_where_the_branch_ends():
    """Paths from joints anywhere in the Panda's ranges: some leave the branch at q_start's q₇ (it
    runs into a joint limit); there follow names the pose instead of jumping, and indeed every
    solution at that q₇ is more than the bound away from the joints at the pose before."""
    arm = panda()
    rng = np.random.default_rng(SEED + 5)
    refused = 0
    for q in random_q(rng, arm, 20):
        poses = lin_poses(arm, q, rng.uniform(-0.05, 0.05, 3), 26)
        try:
            arm.follow(poses, q, move_redundancy=False)
        except RuntimeError as e:
            if "joint step" not in str(e):
                continue
            k = int(str(e).split("poses[")[1].split("]")[0])
            before = arm.follow(poses[:k], q, move_redundancy=False)[-1]
            solutions = arm.inverse(poses[k], redundancy=q[6])
            assert len(solutions) and np.abs(solutions - before).max(axis=1).min() > 0.3
            refused += 1
    assert refused >= 1


def test_the_seven_joint_example_job_plans_from_q_start(tmp_path):
    from dispkin import cli
    import csv

    job = pathlib.Path(__file__).resolve().parents[2] / "examples" / "jobs" / "iiwa14_lin_move.yaml"
    assert cli.main(["check", str(job)]) == 0
    assert cli.main(["plan", str(job), "-o", str(tmp_path), "--plot"]) == 0
    pngs = sorted(tmp_path.glob("*.png"))
    assert pngs and all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in pngs)
    rows = list(csv.reader((tmp_path / "iiwa14_lin_move.csv").open()))
    table = np.array(rows[1:], dtype=float)
    q = table[:, [rows[0].index(f"joint_a{k}.position") for k in range(1, 8)]]
    np.testing.assert_allclose(q[0], [0.3, 0.5, 0.2, -1.6, -0.3, 1.0, 0.4], atol=1e-9)
    assert np.abs(q[:, 6] - 0.4).max() <= 1e-9 and np.abs(np.diff(q, axis=0)).max() <= 0.3


def random_7r_urdf(rng):
    """A 7R arm of random link offsets and axis directions (no closed form: family general)."""
    links = "".join(f'<link name="l{k}"/>' for k in range(8))
    joints = ""
    for k in range(7):
        xyz = " ".join(f"{v:.6f}" for v in rng.uniform(-0.2, 0.2, 3) + np.array([0.0, 0.0, 0.15]))
        rpy = " ".join(f"{v:.6f}" for v in rng.uniform(-np.pi, np.pi, 3))
        joints += (
            f'<joint name="j{k + 1}" type="revolute"><parent link="l{k}"/><child link="l{k + 1}"/>'
            f'<origin xyz="{xyz}" rpy="{rpy}"/><axis xyz="0 0 1"/>'
            f'<limit lower="-2.9" upper="2.9" effort="100" velocity="2"/></joint>'
        )
    return f'<robot name="random_7r">{links}{joints}</robot>'


def test_a_random_7r_arm_solves_from_a_near_start_by_newton_first():
    """doc/inverse-kinematics.md (eq. 46): given q_ref near a solution, the general family answers
    with the one solution Newton's method reaches from it (no search: a single solution), near the
    generating joints; wide_search adds the search's samples; following a path from q_start
    starts at q_start and reproduces every pose."""
    rng = np.random.default_rng(SEED + 7)
    arm = dispkin.SerialArm.from_urdf(random_7r_urdf(rng), "l0", "l7")
    assert arm.family == "general" and arm.redundancy.kind == "none"
    for q in 0.7 * random_q(rng, arm, 30):
        pose = arm.forward(q)
        near = q + rng.uniform(-0.05, 0.05, 7)
        result = arm.inverse_solutions(pose, q_ref=near)
        assert not result.complete and len(result.solutions) == 1
        s = result.solutions[0]
        assert np.abs(arm.forward(s).matrix() - pose.matrix()).max() <= 1e-10
        d = np.linalg.norm(q - near)
        assert np.linalg.norm(s - near) <= d + d * d  # the nearest, to first order
    wide = arm.inverse_solutions(pose, q_ref=near, wide_search=True, max_attempts=8)
    assert len(wide.solutions) > 1 and np.allclose(wide.solutions[0], s, atol=1e-9)
    poses = lin_poses(arm, q, np.array([0.02, -0.01, 0.01]), 21)
    path = arm.follow(poses, q)
    assert np.abs(path[0] - q).max() <= 1e-9 and np.abs(np.diff(path, axis=0)).max() <= 0.05
    for pose, x in zip(poses, path):
        assert np.abs(arm.forward(x).matrix() - pose.matrix()).max() <= 1e-10


def test_a_pose_out_of_reach_at_the_held_parameter_names_the_parameter():
    """TIAGo's arm (example-robot-data) has its first joint as parameter: along this LIN the pose
    leaves what the six other joints reach with arm_1_joint held at 0.5 (no solution there, even
    outside the limits); the check says so, naming the parameter and its value, and the rule that
    moves the parameter follows the same trajectory."""
    from test_serial_arm import robots_dir

    urdf = robots_dir() / "tiago_description" / "robots" / "tiago_no_hand.urdf"
    a = dispkin.SerialArm.from_urdf(urdf.read_text(), "torso_lift_link", "arm_7_link")
    assert a.redundancy.kind == "locked_joint" and a.redundancy.joint_name == "arm_1_joint"
    q = np.array([0.5, 0.3, -1.0, 1.2, 0.1, 0.6, 0.2])
    start = a.forward(q)
    end = dispkin.Pose(start.quaternion, start.translation + np.array([0.05, 0.05, -0.05]))
    tool = dispkin.MetricSet()
    tool.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
    traj = dispkin.plan(dispkin.Path.lin(start, end), tool, dispkin.Limits(0.5, 5.0, 100.0))
    with pytest.raises(
        RuntimeError,
        match=r"no inverse-kinematics solution with its redundancy parameter "
        r"arm_1_joint at 0\.5 rad",
    ) as raised:
        dispkin.check_joint_limits(traj, a, q)
    t = float(str(raised.value).split("the pose at t = ")[1].split(" s")[0])
    pose = traj.sample([t])[0]
    assert len(a.inverse_solutions(pose, keep_outside_limits=True, redundancy=0.5).solutions) == 0
    report = dispkin.check_joint_limits(traj, a, q, redundancy_rule=dispkin.RedundancyRule())
    np.testing.assert_allclose(report.samples["q"][0], q, atol=1e-9)
