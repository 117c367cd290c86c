"""Pose: matrices, composition, XYZUVW (with pivots and at gimbal lock), SE(3) exp/log.

References are written here in numpy: the quaternion's rotation matrix, Rx(U) Ry(V) Rz(W), and
the matrix exponential of the 4x4 twist matrix by a Taylor series.
"""

import math

import numpy as np
import pytest

import dispkin
from _helpers import (
    COUNT,
    axis_rotation,
    expm,
    quaternion_matrix,
    random_pose,
    random_quaternions,
    rng_for,
    twist_matrix,
    unit_vectors,
)

N = min(COUNT, 2000)  # per-case Python loops of cheap calls


def xyzuvw_matrix(v, pivot=np.zeros(3)):
    """x_w = R (x_b − p) + p + (X, Y, Z), R = Rx(U) Ry(V) Rz(W)."""
    r = axis_rotation(0, v[3]) @ axis_rotation(1, v[4]) @ axis_rotation(2, v[5])
    m = np.eye(4)
    m[:3, :3] = r
    m[:3, 3] = v[:3] + pivot - r @ pivot
    return m


def test_default_pose_is_the_identity():
    p = dispkin.Pose()
    assert np.array_equal(p.matrix(), np.eye(4))
    assert np.array_equal(p.quaternion, [1.0, 0.0, 0.0, 0.0])
    assert np.array_equal(p.translation, np.zeros(3))
    assert np.array_equal(p.log(), np.zeros(6))


def test_matrix_composition_inverse_and_transform_match_numpy():
    rng = rng_for("pose-matrix")
    qs = random_quaternions(rng, N)
    for i in range(N):
        t = rng.uniform(-1, 1, 3)
        p = dispkin.Pose(quaternion=qs[i], translation=t)
        m = p.matrix()
        assert m.shape == (4, 4) and m.dtype == np.float64
        np.testing.assert_allclose(m[:3, :3], quaternion_matrix(qs[i]), rtol=0, atol=2e-15)
        np.testing.assert_array_equal(m[:3, 3], t)
        np.testing.assert_array_equal(m[3], [0, 0, 0, 1])
        np.testing.assert_array_equal(p.rotation(), m[:3, :3])
        # the quaternion comes back (w, x, y, z), as given (up to the normalisation rounding)
        np.testing.assert_allclose(p.quaternion, qs[i], rtol=0, atol=3e-16)
        # from_matrix round trip
        assert dispkin.Pose.from_matrix(m).is_approx(p, 4e-15)
        # composition, inverse, transform (a few roundings each: 4e-15 on entries of size ~1)
        other = random_pose(rng)
        np.testing.assert_allclose((p * other).matrix(), m @ other.matrix(), rtol=0, atol=4e-15)
        np.testing.assert_allclose(p.inverse().matrix(), np.linalg.inv(m), rtol=0, atol=4e-15)
        assert (p * p.inverse()).is_approx(dispkin.Pose(), 1e-14)
        pts = rng.normal(size=(5, 3))
        np.testing.assert_allclose(p.transform(pts), pts @ m[:3, :3].T + t, rtol=0, atol=4e-15)
        np.testing.assert_allclose(p.transform(pts[0]), m[:3, :3] @ pts[0] + t, rtol=0, atol=4e-15)


def test_quaternion_within_tolerance_is_normalised():
    p = dispkin.Pose(quaternion=(1.0 + 5e-7, 0.0, 0.0, 0.0))
    assert np.array_equal(p.quaternion, [1.0, 0.0, 0.0, 0.0])
    q = np.array([1.0, 2.0, 3.0, 4.0]) / math.sqrt(30.0)
    assert np.linalg.norm(dispkin.Pose(quaternion=q * (1 - 5e-7)).quaternion) == pytest.approx(1.0, abs=1e-15)


def test_xyzuvw_convention_and_round_trips():
    rng = rng_for("pose-xyzuvw")
    for _ in range(N):
        v = np.concatenate(
            [
                rng.uniform(-1, 1, 3),
                rng.uniform(-np.pi, np.pi, 1),
                rng.uniform(-np.pi / 2, np.pi / 2, 1),
                rng.uniform(-np.pi, np.pi, 1),
            ]
        )
        pivot = rng.uniform(-0.5, 0.5, 3) if rng.random() < 0.5 else np.zeros(3)
        p = dispkin.Pose.from_xyzuvw(v, pivot)
        np.testing.assert_allclose(p.matrix(), xyzuvw_matrix(v, pivot), rtol=0, atol=4e-15)
        # the pivot is where XYZ says, and the angles come back
        np.testing.assert_allclose(p.transform(pivot), pivot + v[:3], rtol=0, atol=1e-15)
        back = p.to_xyzuvw(pivot)
        np.testing.assert_allclose(back[[0, 1, 2, 4]], v[[0, 1, 2, 4]], rtol=0, atol=1e-12)
        # U and W: their split has condition number 1/cos V (exactly undefined at V = ±90°)
        np.testing.assert_allclose(back[[3, 5]], v[[3, 5]], rtol=0, atol=1e-13 + 1e-15 / np.cos(v[4]))
        # pose -> XYZUVW -> pose for any pose, with and without pivot
        q = random_pose(rng)
        w = q.to_xyzuvw(pivot)
        assert -np.pi <= w[3] <= np.pi and -np.pi / 2 <= w[4] <= np.pi / 2 and -np.pi <= w[5] <= np.pi
        assert dispkin.Pose.from_xyzuvw(w, pivot).is_approx(q, 1e-14)


def gimbal_lock_cases(rng, sign, n=200):
    for _ in range(n):
        u, w = rng.uniform(-np.pi, np.pi, 2)
        yield u, w, np.array([*rng.uniform(-1, 1, 3), u, sign * np.pi / 2, w])


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_xyzuvw_at_gimbal_lock(sign):
    # V = ±90°: Rz(W) then turns about the same world axis as Rx(U): Rx(U)Ry(±90°)Rz(W) =
    # Rx(U ± W)Ry(±90°), so only U ± W is defined; the pose must be reproduced.
    rng = rng_for(f"pose-gimbal-{sign}")
    for u, w, v in gimbal_lock_cases(rng, sign):
        p = dispkin.Pose.from_xyzuvw(v)
        back = p.to_xyzuvw()
        assert back[4] == pytest.approx(sign * np.pi / 2, abs=1e-15)
        assert abs(back[3]) <= np.pi and abs(back[5]) <= np.pi
        folded = math.remainder(back[3] + sign * back[5] - (u + sign * w), 2 * math.pi)
        assert folded == pytest.approx(0.0, abs=1e-12)
        assert dispkin.Pose.from_xyzuvw(back).is_approx(p, 4e-15)  # rounding of U ± W, sin, cos


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_xyzuvw_at_gimbal_lock_puts_the_whole_rotation_in_u(sign):
    # The documented convention at gimbal lock: W = 0 and U carries the rotation.
    rng = rng_for(f"pose-gimbal-{sign}")
    for u, w, v in gimbal_lock_cases(rng, sign):
        back = dispkin.Pose.from_xyzuvw(v).to_xyzuvw()
        assert back[5] == 0.0, (u, w, back)
        assert math.remainder(back[3] - (u + sign * w), 2 * math.pi) == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("delta", [1e-3, 1e-6, 1e-9, 1e-12, 1e-15])
def test_xyzuvw_close_to_gimbal_lock_reproduces_the_pose(delta):
    rng = rng_for(f"pose-near-gimbal-{delta}")
    for _ in range(200):
        v = np.array(
            [
                *rng.uniform(-1, 1, 3),
                rng.uniform(-np.pi, np.pi),
                rng.choice([-1, 1]) * (np.pi / 2 - delta),
                rng.uniform(-np.pi, np.pi),
            ]
        )
        p = dispkin.Pose.from_xyzuvw(v)
        back = p.to_xyzuvw()
        assert abs(back[4]) <= np.pi / 2
        assert dispkin.Pose.from_xyzuvw(back).is_approx(p, 1e-14)


def test_exp_matches_the_matrix_exponential_and_log_inverts_it():
    rng = rng_for("pose-exp-log")
    for i in range(N):
        angle = [rng.uniform(0, np.pi - 1e-6), 1e-8, 1e-12, 1e-4, np.pi - 1e-9, rng.uniform(0, 3)][i % 6]
        xi = np.concatenate([rng.uniform(-1, 1, 3), angle * unit_vectors(rng, 1)[0]])
        p = dispkin.Pose.exp(xi)
        np.testing.assert_allclose(p.matrix(), expm(twist_matrix(xi)), rtol=0, atol=1e-14)
        np.testing.assert_allclose(p.log(), xi, rtol=0, atol=1e-12)


def test_exp_log_at_zero_angle_and_at_pi():
    v = np.array([0.3, -0.2, 0.1])
    p = dispkin.Pose.exp(np.concatenate([v, np.zeros(3)]))
    assert np.array_equal(p.matrix()[:3, :3], np.eye(3)) and np.array_equal(p.translation, v)
    assert np.array_equal(dispkin.Pose(translation=v).log(), np.concatenate([v, np.zeros(3)]))
    # Exactly π: both axis signs are the same rotation; exp(log(T)) must give T back.
    rng = rng_for("pose-pi")
    for _ in range(200):
        axis = unit_vectors(rng, 1)[0]
        t = rng.uniform(-1, 1, 3)
        p = dispkin.Pose(quaternion=np.concatenate(([0.0], axis)), translation=t)
        xi = p.log()
        assert np.linalg.norm(xi[3:]) == pytest.approx(np.pi, abs=1e-15)
        assert dispkin.Pose.exp(xi).is_approx(p, 1e-14)


def test_log_of_any_pose_inverts_exp():
    rng = rng_for("pose-any-log")
    for _ in range(N):
        p = random_pose(rng)
        xi = p.log()
        assert np.linalg.norm(xi[3:]) <= np.pi + 1e-15
        assert dispkin.Pose.exp(xi).is_approx(p, 1e-14)


def test_rotated_about_pivot_keeps_the_pivot_in_place():
    rng = rng_for("pose-pivot")
    for _ in range(N):
        p, orientation = random_pose(rng), random_pose(rng)
        pivot = rng.uniform(-0.5, 0.5, 3)
        turned = p.rotated_about_pivot(orientation, pivot)
        np.testing.assert_allclose(turned.transform(pivot), p.transform(pivot), rtol=0, atol=1e-15)
        np.testing.assert_allclose(turned.rotation(), orientation.rotation(), rtol=0, atol=0)


def test_is_approx_and_repr():
    p = dispkin.Pose(translation=(0.1, 0.2, 0.3))
    assert p.is_approx(dispkin.Pose(translation=(0.1, 0.2, 0.3 + 1e-10)))  # default tol 1e-9
    assert not p.is_approx(dispkin.Pose(translation=(0.1, 0.2, 0.3 + 1e-8)))
    assert not p.is_approx(dispkin.Pose(translation=(0.1, 0.2, 0.3 + 1e-8)), tol=1e-9)
    assert p.is_approx(dispkin.Pose(translation=(0.1, 0.2, 0.3 + 1e-8)), tol=1e-7)
    q = dispkin.Pose.from_xyzuvw([0.05, 0.02, 0, 0.1, 0.2, 0.3])
    text = repr(q)
    assert text.startswith("Pose(quaternion=(") and "translation=(0.05, 0.02, 0.0)" in text
    # The repr evaluates back to the pose (the constructor renormalises the quaternion: 1 ulp).
    assert eval(text, {"Pose": dispkin.Pose}).is_approx(q, 1e-15)
