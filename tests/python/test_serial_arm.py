"""SerialArm from Python on real robot descriptions (the `example-robot-data` package: UR5,
Franka Panda and Kinova Jaco2 j2s6s200 URDFs), checked against an independent model: pinocchio (`pin`) forward
kinematics and RNEA torques on random states."""

import importlib.metadata
import pathlib
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import dispkin

pin = pytest.importorskip("pinocchio")

DATA = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf"
SEED = 20261122
COUNT = 200


def robots_dir():
    """example-robot-data (a cmeel package, no Python module) installs its URDFs under
    cmeel.prefix/share/example-robot-data/robots."""
    try:
        dist = importlib.metadata.distribution("example-robot-data")
    except importlib.metadata.PackageNotFoundError:
        pytest.skip("example-robot-data is not installed")
    return pathlib.Path(dist.locate_file("cmeel.prefix/share/example-robot-data/robots"))


def ur5_urdf():
    return (robots_dir() / "ur_description" / "urdf" / "ur5_robot.urdf").read_text()


def panda_urdf_without_fingers():
    """panda.urdf without its two prismatic fingers: SerialArm leaves subtrees on movable joints
    out of the dynamics, pinocchio would lock them in; without them both describe the same arm."""
    root = ET.fromstring((robots_dir() / "panda_description" / "urdf" / "panda.urdf").read_text())
    for joint in list(root.findall("joint")):
        if joint.get("type") == "prismatic":
            child = joint.find("child").get("link")
            root.remove(joint)
            root.remove(next(link for link in root.findall("link") if link.get("name") == child))
    return ET.tostring(root, encoding="unicode")


def kinova_urdf():
    return (robots_dir() / "kinova_description" / "robots" / "kinova.urdf").read_text()


def to_pinocchio_q(model, q):
    """pinocchio's configuration of joint values q: a continuous joint is (cos q, sin q)."""
    out = pin.neutral(model)
    for j, value in zip(range(1, model.njoints), q):
        joint = model.joints[j]
        if joint.nq == 2:
            out[joint.idx_q : joint.idx_q + 2] = (np.cos(value), np.sin(value))
        else:
            out[joint.idx_q] = value
    return out


def pinocchio_model(urdf_text):
    model = pin.buildModelFromXML(urdf_text)
    return model, model.createData()


def random_q(rng, arm, n):
    limits = arm.joint_limits
    lo = np.where(np.isfinite(limits.lower), limits.lower, -np.pi)
    hi = np.where(np.isfinite(limits.upper), limits.upper, np.pi)
    return rng.uniform(lo, hi, size=(n, arm.dof))


ROBOTS = {
    "ur5": (ur5_urdf, "world", "tool0"),
    "panda": (panda_urdf_without_fingers, "panda_link0", "panda_hand"),
    "kinova": (kinova_urdf, "base", "j2s6s200_end_effector"),  # continuous joints 1, 4, 6
}


@pytest.fixture(params=sorted(ROBOTS))
def robot(request):
    text_of, base, tip = ROBOTS[request.param]
    text = text_of()
    arm = dispkin.SerialArm.from_urdf(text, base, tip)
    model, data = pinocchio_model(text)
    # The same joints in the same order (pinocchio orders them depth first, as the chain is).
    assert [model.names[i] for i in range(1, model.njoints)] == arm.joint_names
    return request.param, arm, model, data, tip


def test_forward_matches_pinocchio(robot):
    name, arm, model, data, tip = robot
    frame = model.getFrameId(tip)
    worst = 0.0
    for q in random_q(np.random.default_rng(SEED), arm, COUNT):
        pin.framesForwardKinematics(model, data, to_pinocchio_q(model, q))
        worst = max(worst, np.abs(arm.forward(q).matrix() - data.oMf[frame].homogeneous).max())
    assert worst <= 1e-9, name


def test_torques_match_pinocchio_rnea(robot):
    name, arm, model, data, _ = robot
    assert np.array_equal(arm.gravity, [0.0, 0.0, -9.81])
    assert np.allclose(model.gravity.linear, arm.gravity)
    rng = np.random.default_rng(SEED + 1)
    worst = 0.0
    for q in random_q(rng, arm, COUNT):
        qd = rng.uniform(-2.0, 2.0, arm.dof)
        qdd = rng.uniform(-5.0, 5.0, arm.dof)
        tau = arm.torques(q, qd, qdd)
        worst = max(worst, np.abs(tau - pin.rnea(model, data, to_pinocchio_q(model, q), qd, qdd)).max())
        assert np.array_equal(arm.static_torques(q), arm.torques(q, np.zeros(arm.dof), np.zeros(arm.dof)))
    assert worst <= 1e-9, name


def test_jacobian_matches_pinocchio(robot):
    name, arm, model, data, tip = robot
    frame = model.getFrameId(tip)
    for q in random_q(np.random.default_rng(SEED + 2), arm, 20):
        pin.computeJointJacobians(model, data, to_pinocchio_q(model, q))
        pin.updateFramePlacements(model, data)
        # LOCAL_WORLD_ALIGNED: tip-origin velocity and angular velocity in base axes.
        j = pin.getFrameJacobian(model, data, frame, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
        assert arm.jacobian(q).shape == (6, arm.dof)
        assert np.abs(arm.jacobian(q) - j).max() <= 1e-9, name
        assert (
            np.abs(arm.body_jacobian(q) - pin.getFrameJacobian(model, data, frame, pin.ReferenceFrame.LOCAL)).max()
            <= 1e-9
        )


def test_ur5_inverse_is_complete_and_contains_q():
    arm = dispkin.SerialArm.from_urdf(ur5_urdf(), "base_link", "tool0")
    assert arm.family == "three_parallel"
    assert arm.dof == 6
    assert arm.joint_names[0] == "shoulder_pan_joint"
    rng = np.random.default_rng(SEED + 3)
    for q in random_q(rng, arm, 50):
        pose = arm.forward(q)
        result = arm.inverse_solutions(pose)
        assert result.complete and result.family == "three_parallel"
        assert all(result.within_limits)
        solutions = arm.inverse(pose)
        assert all(s.shape == (6,) for s in solutions)
        # One joint vector per branch, each joint the 2π copy nearest 0: q up to whole turns.
        assert min(np.abs(np.remainder(s - q + np.pi, 2 * np.pi) - np.pi).max() for s in solutions) <= 1e-9
        assert all(np.abs(s).max() <= np.pi + 1e-9 for s in solutions)  # + the polish's rounding
        # The copies on request: q itself among them.
        assert min(np.abs(s - q).max() for s in arm.inverse(pose, offer_equivalents=True)) <= 1e-9
        for s in solutions:
            assert arm.forward(s).is_approx(pose, 1e-10)
        assert np.array_equal(
            arm.nearest(solutions, q + 1e-3),
            solutions[int(np.argmin([np.linalg.norm(s - q - 1e-3) for s in solutions]))],
        )


def test_kinova_jaco2_spherical_wrist_with_continuous_joints():
    arm = dispkin.SerialArm.from_urdf(kinova_urdf(), "base", "j2s6s200_end_effector")
    assert arm.family == "spherical_wrist"
    limits = arm.joint_limits
    continuous = ~np.isfinite(limits.lower)
    assert list(continuous) == [True, False, False, True, False, True]
    for q in random_q(np.random.default_rng(SEED + 5), arm, 50):
        pose = arm.forward(q)
        result = arm.inverse_solutions(pose)
        assert result.complete
        assert min(np.abs(s - q).max() for s in result.solutions) <= 1e-9
        for s in result.solutions:
            assert arm.forward(s).is_approx(pose, 1e-10)
            # continuous joints come back in (-pi, pi], limited ones inside their limits
            assert np.all(np.abs(s[continuous]) <= np.pi)
            assert np.all(s[~continuous] >= limits.lower[~continuous] - 1e-10)
            assert np.all(s[~continuous] <= limits.upper[~continuous] + 1e-10)


def test_seven_joints_without_a_closed_form_fall_back_to_the_search():
    """The Panda with joint 2 moved 3 cm off axis 1: no locked end joint leaves a 6R closed form
    (its shoulder no longer meets in a point), so the numeric search runs."""
    root = ET.fromstring(panda_urdf_without_fingers())
    origin = next(j for j in root.findall("joint") if j.get("name") == "panda_joint2").find("origin")
    origin.set("xyz", "0.03 0 0")
    arm = dispkin.SerialArm.from_urdf(ET.tostring(root, encoding="unicode"), "panda_link0", "panda_hand")
    assert arm.family == "general" and arm.dof == 7 and arm.redundancy.kind == "none"
    q = random_q(np.random.default_rng(SEED + 4), arm, 1)[0]
    pose = arm.forward(q)
    result = arm.inverse_solutions(pose, max_attempts=20, time_budget=1.0)
    assert not result.complete
    assert result.solutions, "a reachable pose of a redundant arm gave no solution"
    limits = arm.joint_limits
    for s in result.solutions:
        assert arm.forward(s).is_approx(pose, 1e-10)
        assert np.all(s >= limits.lower - 1e-10) and np.all(s <= limits.upper + 1e-10)


def test_limits_and_the_planar_arm_from_a_file():
    arm = dispkin.SerialArm.from_urdf(str(DATA / "arm_planar_two_link.urdf"), "base", "payload")
    limits = arm.joint_limits
    assert np.array_equal(limits.lower, [-3.0, -np.inf])
    assert np.array_equal(limits.upper, [3.0, np.inf])
    assert np.array_equal(limits.velocity, [2.0, 3.0])
    assert np.array_equal(limits.effort, [100.0, 50.0])
    assert arm.family == "general"
    q = np.array([0.4, -1.1])
    solutions = arm.inverse(arm.forward(q))
    assert len(solutions) == 1 and np.abs(solutions[0] - q).max() <= 1e-9
    path = arm.follow([arm.forward(q + 0.01 * k) for k in range(5)], q)
    assert path.shape == (5, 2) and np.abs(path - (q + 0.01 * np.arange(5)[:, None])).max() <= 1e-9
    # The XML text itself works too (a string starting with '<').
    same = dispkin.SerialArm.from_urdf((DATA / "arm_planar_two_link.urdf").read_text(), "base", "payload")
    assert same.forward(q).is_approx(arm.forward(q), 0.0)
    assert "planar_two_link" in repr(arm)


def test_configuration_flags_of_ur5():
    arm = dispkin.SerialArm.from_urdf(ur5_urdf(), "base_link", "tool0")
    q = np.array([0.3, -1.0, 1.2, -0.5, 0.8, 0.1])
    flags = arm.configuration(q)
    assert all(f in (-1, 1) for f in flags)
    flipped = q.copy()
    flipped[4] = -q[4]
    assert arm.configuration(flipped)[2] == -flags[2]


def ur5e_dh():
    return dispkin.SerialArm.from_urdf(str(DATA / "arm_ur5e_dh.urdf"), "base_link", "tool0")


def test_joint_velocities_are_the_least_squares_solution_of_the_body_jacobian():
    rng = np.random.default_rng(SEED + 7)
    planar = dispkin.SerialArm.from_urdf(str(DATA / "arm_planar_two_link.urdf"), "base", "payload")
    for arm in (ur5e_dh(), planar):
        q = random_q(rng, arm, 50)
        twists = rng.uniform(-1.0, 1.0, size=(50, 6))
        expected = np.array([np.linalg.lstsq(arm.body_jacobian(qk), xi, rcond=None)[0] for qk, xi in zip(q, twists)])
        np.testing.assert_allclose(arm.joint_velocities(q, twists), expected, rtol=0, atol=1e-9)
    with pytest.raises(ValueError, match="body_twists"):
        planar.joint_velocities(np.zeros((3, 2)), np.zeros((2, 6)))


def lin_trajectory(arm, q0):
    """A LIN of ~0.1 m with a small turn from forward(q0), planned for a 50 mm ball on the tool."""
    a = arm.forward(q0)
    b = arm.forward(q0 + np.array([0.2, -0.15, 0.2, 0.1, -0.1, 0.3]))
    metric_set = dispkin.MetricSet()
    metric_set.add_relative(dispkin.shapes.icosahedron(0.05, (0.0, 0.0, 0.1)))
    return dispkin.plan(dispkin.Path.lin(a, b), metric_set, dispkin.Limits(0.2, 1.0, 10.0), "scurve")


def test_follow_trajectory_is_follow_with_jacobian_velocities_and_central_differences():
    """The joint samples of a job, computed in C++, against the same recipe written out here:
    follow() from q_start, lstsq on the body Jacobian, and central differences of q-dot over
    +-h (one-sided at the ends) with each neighbour followed from its sample's q."""
    arm = ur5e_dh()
    q0 = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
    traj = lin_trajectory(arm, q0)
    t = np.linspace(0.0, traj.duration, 41)
    h = 1e-4
    q, qd, qdd = arm.follow_trajectory(traj, t, q0, h)
    assert q.shape == qd.shape == qdd.shape == (41, 6)

    def follow(times, references):
        poses = [dispkin.Pose.from_matrix(m) for m in np.asarray(traj.sample(times))]
        return np.array([arm.follow([pose], ref)[0] for pose, ref in zip(poses, references)])

    def velocities(times, joints):
        twists = np.asarray(traj.body_twist(times))
        return np.array([np.linalg.lstsq(arm.body_jacobian(qk), xi, rcond=None)[0] for qk, xi in zip(joints, twists)])

    positions = arm.follow([dispkin.Pose.from_matrix(m) for m in np.asarray(traj.sample(t))], q0)
    np.testing.assert_allclose(q, positions, rtol=0, atol=1e-9)
    np.testing.assert_allclose(qd, velocities(t, positions), rtol=0, atol=1e-9)
    before, after = np.maximum(t - h, 0.0), np.minimum(t + h, traj.duration)
    rates = [velocities(times, follow(times, positions)) for times in (before, after)]
    np.testing.assert_allclose(qdd, (rates[1] - rates[0]) / (after - before)[:, None], rtol=0, atol=1e-6)
    # The joints leave q0 continuously, and q-dot is the derivative of q.
    np.testing.assert_allclose(q[0], q0, rtol=0, atol=1e-9)
    numeric = (q[2:] - q[:-2]) / (t[2:] - t[:-2])[:, None]
    assert np.abs(numeric - qd[1:-1]).max() <= 2e-2 * (1.0 + np.abs(numeric).max())
    with pytest.raises(ValueError, match="difference_step"):
        arm.follow_trajectory(traj, t, q0, 0.0)


def test_check_joint_limits_of_a_ptp_move_is_the_patent_factors_of_its_joint_line():
    arm = ur5e_dh()
    q_a = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])
    q_b = q_a + np.array([0.8, 0.4, -0.6, 0.5, 0.7, -0.9])
    metric_set = dispkin.MetricSet()
    metric_set.add_relative(dispkin.shapes.icosahedron(0.05, (0.0, 0.0, 0.1)))
    traj = dispkin.plan(dispkin.Path.ptp(q_a, q_b), metric_set, dispkin.Limits(1.0, 4.0, 40.0), robot=arm)
    t = np.linspace(0.0, traj.duration, 201)
    report = arm.check_joint_limits(traj, t)
    q, qd, qdd = traj.joint_positions(t), traj.joint_velocities(t), traj.joint_accelerations(t)
    limits = arm.joint_limits
    stated = np.isfinite(limits.velocity)
    assert report.velocity_factor == pytest.approx(np.max(np.abs(qd[:, stated]) / limits.velocity[stated]), rel=1e-12)
    effort = np.asarray(limits.effort)
    factors = []
    for qk, qdk, qddk in zip(q, qd, qdd):
        static = np.asarray(arm.static_torques(qk))
        dynamic = np.asarray(arm.torques(qk, qdk, qddk)) - static
        factors.append(np.max(np.abs(dynamic) / (effort - np.abs(static))))
    assert report.acceleration_factor == pytest.approx(max(factors), rel=1e-12)
    assert report.position_excess == 0.0
