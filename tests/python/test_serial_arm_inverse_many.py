"""SerialArm.inverse as a (k, n) array, and SerialArm.inverse_many: the same solutions pose by
pose, whatever form the poses take, and bad poses named by their index."""

import pathlib

import numpy as np
import pytest

import dispkin
from _helpers import rng_for

DATA = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf"
ARMS = {
    "ur5e": ("arm_ur5e_dh.urdf", "base_link", "tool0"),  # three parallel axes, ±2π limits
    "kr6": ("arm_kr6_like_dh.urdf", "base_link", "flange"),  # spherical wrist, narrower limits
    "planar": ("arm_planar_two_link.urdf", "base", "payload"),  # numeric fallback
}


def arm_named(name):
    file, base, tip = ARMS[name]
    return dispkin.SerialArm.from_urdf(str(DATA / file), base, tip)


def random_poses(arm, rng, count):
    """Poses of random joint vectors within one turn and the limits, and a few out of reach."""
    lower = np.maximum(arm.joint_limits.lower, -np.pi)
    upper = np.minimum(arm.joint_limits.upper, np.pi)
    poses = [np.asarray(arm.forward(q).matrix()) for q in rng.uniform(lower, upper, size=(count, arm.dof))]
    far = np.eye(4)
    far[:3, 3] = (50.0, 0.0, 0.0)  # 50 m away: no solution
    return np.array(poses[: count // 2] + [far] + poses[count // 2 :])


@pytest.mark.parametrize("name", sorted(ARMS))
def test_inverse_is_a_k_by_n_array_of_the_solutions(name):
    arm = arm_named(name)
    for pose in random_poses(arm, rng_for(f"inverse-array-{name}"), 20):
        solutions = arm.inverse(pose)
        assert isinstance(solutions, np.ndarray) and solutions.dtype == np.float64
        assert solutions.ndim == 2 and solutions.shape[1] == arm.dof
        assert solutions.flags["C_CONTIGUOUS"]
        result = arm.inverse_solutions(pose)
        assert len(result.solutions) == len(solutions)
        for row, q in zip(solutions, result.solutions):
            assert np.array_equal(row, q)
            assert arm.forward(row).is_approx(dispkin.Pose.from_matrix(pose), 1e-10)
    far = np.eye(4)
    far[:3, 3] = (50.0, 0.0, 0.0)
    assert arm.inverse(far).shape == (0, arm.dof)


def test_inverse_reads_every_form_of_a_pose_alike():
    # A Pose, C- and Fortran-ordered float64 arrays (read in place), other dtypes and nested
    # lists (converted by numpy) are one pose: the same solutions, bit for bit.
    arm = arm_named("ur5e")
    for m in random_poses(arm, rng_for("inverse-forms"), 10):
        expected = arm.inverse(dispkin.Pose.from_matrix(m))
        strided = np.stack([m, m], axis=-1)[..., 0]  # float64, neither C nor Fortran order
        assert not strided.flags["C_CONTIGUOUS"] and not strided.flags["F_CONTIGUOUS"]
        forms = [np.ascontiguousarray(m), np.asfortranarray(m), m.tolist(), m.astype(np.longdouble), strided]
        for form in forms:
            assert np.array_equal(arm.inverse(form), expected)
        assert np.array_equal(
            arm.inverse(m, offer_equivalents=True), arm.inverse(dispkin.Pose.from_matrix(m), offer_equivalents=True)
        )


@pytest.mark.parametrize("name", sorted(ARMS))
@pytest.mark.parametrize("equivalents", [False, True])
def test_inverse_many_is_inverse_pose_by_pose(name, equivalents):
    arm = arm_named(name)
    poses = random_poses(arm, rng_for(f"inverse-many-{name}"), 30)
    expected = [arm.inverse(m, offer_equivalents=equivalents) for m in poses]
    as_poses = [dispkin.Pose.from_matrix(m) for m in poses]
    mixed = [p if k % 2 else m for k, (p, m) in enumerate(zip(as_poses, poses))]
    for given in (poses, np.asfortranarray(poses), list(poses), as_poses, mixed, tuple(as_poses)):
        found = arm.inverse_many(given, offer_equivalents=equivalents)
        assert isinstance(found, list) and len(found) == len(poses)
        for f, e in zip(found, expected):
            assert f.shape == e.shape and f.shape[1:] == (arm.dof,)
            assert np.array_equal(f, e)
    assert any(len(f) == 0 for f in expected) and any(len(f) > 0 for f in expected)


def test_inverse_many_of_no_poses_is_an_empty_list():
    arm = arm_named("kr6")
    assert arm.inverse_many(np.zeros((0, 4, 4))) == []
    assert arm.inverse_many([]) == []


@pytest.mark.parametrize(
    "poses, message",
    [
        (np.zeros((4, 4)), "poses: expected an array of shape (N, 4, 4) or a sequence of Poses, got shape (4, 4)"),
        (
            np.zeros((3, 4, 3)),
            "poses: expected an array of shape (N, 4, 4) or a sequence of Poses, got shape (3, 4, 3)",
        ),
        (np.zeros((2, 16)), "poses: expected an array of shape (N, 4, 4) or a sequence of Poses, got shape (2, 16)"),
        ("poses", "poses: expected an array of shape (N, 4, 4) or a sequence of Poses of numbers, got str"),
        ([np.eye(4), np.eye(3)], "poses[1]: expected an array of shape (4, 4), got shape (3, 3)"),
    ],
)
def test_inverse_many_refuses_a_wrong_shape(poses, message):
    with pytest.raises(ValueError) as info:
        arm_named("ur5e").inverse_many(poses)
    assert str(info.value) == message


def test_inverse_many_names_the_pose_that_is_not_finite_or_not_rigid():
    arm = arm_named("ur5e")
    good = np.asarray(arm.forward(np.full(6, 0.3)).matrix())
    nan = good.copy()
    nan[1, 3] = np.nan
    sheared = good.copy()
    sheared[0, 1] += 0.1
    bottom = good.copy()
    bottom[3, 0] = 1.0
    for bad, index, start in [
        (nan, 2, "poses[2] matrix = ("),
        (sheared, 1, "poses[1] rotation = ("),
        (bottom, 0, "poses[0] matrix last row = (1, 0, 0, 1)"),
    ]:
        poses = [good, good, good]
        poses[index] = bad
        for given in (np.array(poses), poses):
            with pytest.raises(ValueError) as info:
                arm.inverse_many(given)
            assert str(info.value).startswith(start), str(info.value)
    with pytest.raises(ValueError, match="must be finite"):
        arm.inverse_many(np.array([good, nan]))
