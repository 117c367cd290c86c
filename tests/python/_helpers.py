"""Shared pieces of the pytest suite: random cases and independent numpy reference maths.

Nothing here calls the library to compute a value a test checks; the references are written from the
formulas of doc/disp-metric.md and doc/section-length.md directly (rotation matrices, chords,
speeds, a maximiser over a sphere surface).
"""

import os
import zlib
from dataclasses import dataclass, field
from typing import List, Tuple

import numpy as np

import dispkin

#: Seed and case count of every randomised oracle, overridable from the environment.
SEED = int(os.environ.get("DISPKIN_TEST_SEED", "20240611"))
COUNT = int(os.environ.get("DISPKIN_TEST_COUNT", "10000"))


def rng_for(name: str) -> np.random.Generator:
    """A generator seeded by SEED and the test's name: tests do not depend on their order."""
    return np.random.default_rng([SEED, zlib.crc32(name.encode())])


# --- rotations -------------------------------------------------------------------------------


def unit_vectors(rng: np.random.Generator, n: int) -> np.ndarray:
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def hat(w: np.ndarray) -> np.ndarray:
    """[w]x for a (..., 3) array."""
    w = np.asarray(w, dtype=float)
    m = np.zeros(w.shape[:-1] + (3, 3))
    m[..., 0, 1], m[..., 0, 2] = -w[..., 2], w[..., 1]
    m[..., 1, 0], m[..., 1, 2] = w[..., 2], -w[..., 0]
    m[..., 2, 0], m[..., 2, 1] = -w[..., 1], w[..., 0]
    return m


def quaternion_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrix of a unit quaternion (w, x, y, z), (..., 4) -> (..., 3, 3)."""
    q = np.asarray(q, dtype=float)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    m = np.empty(q.shape[:-1] + (3, 3))
    m[..., 0, 0] = 1 - 2 * (y * y + z * z)
    m[..., 0, 1] = 2 * (x * y - w * z)
    m[..., 0, 2] = 2 * (x * z + w * y)
    m[..., 1, 0] = 2 * (x * y + w * z)
    m[..., 1, 1] = 1 - 2 * (x * x + z * z)
    m[..., 1, 2] = 2 * (y * z - w * x)
    m[..., 2, 0] = 2 * (x * z - w * y)
    m[..., 2, 1] = 2 * (y * z + w * x)
    m[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return m


def axis_rotation(axis: int, angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    m = np.eye(3)
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def rotation_vector_matrix(w: np.ndarray) -> np.ndarray:
    """Rodrigues' formula, (3,) -> (3, 3)."""
    theta = np.linalg.norm(w)
    if theta == 0.0:
        return np.eye(3)
    k = hat(np.asarray(w) / theta)
    return np.eye(3) + np.sin(theta) * k + (1 - np.cos(theta)) * (k @ k)


def expm(a: np.ndarray) -> np.ndarray:
    """Matrix exponential by scaling and squaring of a Taylor series (an independent SE(3) exp)."""
    norm = np.abs(a).sum(axis=1).max()
    squarings = max(0, int(np.ceil(np.log2(norm / 0.25))) if norm > 0 else 0)
    b = a / 2.0**squarings
    result = np.eye(a.shape[0])
    term = np.eye(a.shape[0])
    for k in range(1, 30):
        term = term @ b / k
        result = result + term
    for _ in range(squarings):
        result = result @ result
    return result


def twist_matrix(xi: np.ndarray) -> np.ndarray:
    """The 4x4 matrix ([ω]x v; 0 0) of a twist (v, ω)."""
    m = np.zeros((4, 4))
    m[:3, :3] = hat(xi[3:])
    m[:3, 3] = xi[:3]
    return m


def random_quaternions(rng: np.random.Generator, n: int) -> np.ndarray:
    """Uniformly random unit quaternions (w, x, y, z), w >= 0."""
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    q[q[:, 0] < 0] *= -1
    return q


def random_pose(rng: np.random.Generator, translation_scale: float = 0.5) -> dispkin.Pose:
    return dispkin.Pose(
        quaternion=random_quaternions(rng, 1)[0],
        translation=rng.uniform(-translation_scale, translation_scale, 3),
    )


def rotation_angle(q_wxyz: np.ndarray) -> float:
    """Rotation angle in [0, π] of a unit quaternion."""
    return 2.0 * np.arctan2(np.linalg.norm(q_wxyz[1:]), abs(q_wxyz[0]))


def relative_motion(rng: np.random.Generator, kind: str) -> dispkin.Pose:
    """A relative motion a⁻¹b of a chosen family: generic, pure translation, pure rotation,
    tiny, rotation angle near π."""
    if kind == "translation":
        return dispkin.Pose(translation=rng.uniform(-0.5, 0.5, 3))
    axis = unit_vectors(rng, 1)[0]
    angle = {
        "generic": rng.uniform(0.0, np.pi),
        "rotation": rng.uniform(0.0, np.pi),
        "tiny": 10.0 ** rng.uniform(-9, -4),
        "near_pi": np.pi - 10.0 ** rng.uniform(-6, -2),
    }[kind]
    q = np.concatenate(([np.cos(angle / 2)], np.sin(angle / 2) * axis))
    t = np.zeros(3) if kind == "rotation" else rng.uniform(-0.5, 0.5, 3) * (1e-6 if kind == "tiny" else 1.0)
    return dispkin.Pose(quaternion=q, translation=t)


MOTION_KINDS = ["generic", "generic", "generic", "translation", "rotation", "tiny", "near_pi"]


# --- metric sets -----------------------------------------------------------------------------


@dataclass
class SetSpec:
    """A metric set as plain arrays, for the numpy references, and the library object."""

    relative: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    absolute: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    relative_spheres: List[Tuple[np.ndarray, float]] = field(default_factory=list)
    absolute_spheres: List[Tuple[np.ndarray, float]] = field(default_factory=list)

    def build(self) -> dispkin.MetricSet:
        s = dispkin.MetricSet()
        if len(self.relative):
            s.add_relative(self.relative)
        if len(self.absolute):
            s.add_absolute(self.absolute)
        for c, r in self.relative_spheres:
            s.add_sphere(c, r)
        for c, r in self.absolute_spheres:
            s.add_sphere(c, r, absolute=True)
        return s


SET_FAMILIES = ["relative", "flat", "absolute", "sphere", "absolute_sphere", "collinear_plus_plane", "mixed"]


def random_set(rng: np.random.Generator, family: str) -> SetSpec:
    """A random well-formed set of the given family."""
    spec = SetSpec()
    if family == "relative":  # a cloud moving with the tool
        spec.relative = rng.normal(scale=0.3, size=(rng.integers(3, 7), 3))
    elif family == "flat":  # coplanar relative points: still spans a plane
        n = unit_vectors(rng, 1)[0]
        p = rng.normal(scale=0.3, size=(rng.integers(3, 6), 3))
        spec.relative = p - np.outer(p @ n, n) + rng.normal(scale=0.2, size=3)
    elif family == "absolute":  # a protected zone only
        spec.absolute = rng.uniform(-1.0, 1.0, size=(rng.integers(3, 6), 3))
    elif family == "sphere":  # a single ball of positive radius is well-formed on its own
        spec.relative_spheres = [(rng.normal(scale=0.3, size=3), rng.uniform(0.01, 0.3))]
    elif family == "absolute_sphere":
        spec.absolute_spheres = [(rng.uniform(-1.0, 1.0, 3), rng.uniform(0.01, 0.3))]
    elif family == "collinear_plus_plane":  # collinear relative points, absolute points spanning a plane
        d = unit_vectors(rng, 1)[0]
        spec.relative = rng.normal(scale=0.1, size=3) + np.outer(rng.uniform(-0.5, 0.5, 3), d)
        spec.absolute = rng.uniform(-1.0, 1.0, size=(3, 3))
    elif family == "mixed":
        spec.relative = rng.normal(scale=0.3, size=(rng.integers(1, 4), 3))
        spec.absolute = rng.uniform(-1.0, 1.0, size=(rng.integers(1, 4), 3))
        spec.relative_spheres = [(rng.normal(scale=0.3, size=3), rng.choice([0.0, rng.uniform(0.01, 0.3)]))]
        spec.absolute_spheres = [(rng.uniform(-1.0, 1.0, 3), rng.uniform(0.01, 0.3))]
    else:
        raise AssertionError(family)
    return spec


# --- references --------------------------------------------------------------------------------


def pose_arrays(pose: dispkin.Pose) -> Tuple[np.ndarray, np.ndarray]:
    return pose.rotation(), pose.translation


NORMS = {
    "euclidean": lambda u: np.linalg.norm(u, axis=-1),
    "max": lambda u: np.abs(u).max(axis=-1),
    "l1": lambda u: np.abs(u).sum(axis=-1),
}

#: Extreme points of the dual unit ball of each polyhedral norm: ‖u‖ = max over s of s·u.
DUAL_EXTREME_POINTS = {
    "max": np.vstack([np.eye(3), -np.eye(3)]),
    "l1": np.array([[a, b, c] for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)], dtype=float),
}


def chord_maps(pose_a: dispkin.Pose, pose_b: dispkin.Pose):
    """(A, w) with chord(x) = A x + w, for relative objects (world chord Tb x − Ta x) and for
    absolute objects (body chord Tb⁻¹ x − Ta⁻¹ x) — doc/disp-metric.md eq. 20."""
    ra, ta = pose_arrays(pose_a)
    rb, tb = pose_arrays(pose_b)
    relative = (rb - ra, tb - ta)
    absolute = (rb.T - ra.T, -(rb.T @ tb - ra.T @ ta))
    return relative, absolute


def maximise_norm_on_sphere(a, w, center, radius, rng, starts=32, iterations=30, initial=None):
    """max over ‖x − c‖ = ρ of ‖A x + w‖, for stacks A (n, 3, 3), w (n, 3), c (n, 3), ρ (n,).

    f(u) = ‖ρ A u + A c + w‖ is convex in u, so the step u ← ∇(f²)/‖∇(f²)‖ (the point of the
    sphere maximising the linearisation) never decreases f: a projected gradient ascent with an
    infinite step. Started from random points and from the ± right singular vectors of A, it
    returns the best surface point found: a true sample of the surface (a lower bound of the
    maximum), which converges to the maximum. `initial` (n, k, 3) adds unit start directions.
    """
    a = np.asarray(a, dtype=float)
    n = a.shape[0]
    radius = np.asarray(radius, dtype=float).reshape(n, 1)
    offset = np.einsum("nij,nj->ni", a, np.asarray(center, dtype=float)) + w  # A c + w
    u = rng.normal(size=(n, starts, 3))
    _, _, vt = np.linalg.svd(a)
    u[:, :6] = np.concatenate([vt, -vt], axis=1)
    if initial is not None:
        u = np.concatenate([u, np.asarray(initial, dtype=float)], axis=1)
    u /= np.linalg.norm(u, axis=-1, keepdims=True)
    # Written out per component: batched 3x3 products are slow in einsum/matmul.
    ra = [[radius * a[:, i, j, None] for j in range(3)] for i in range(3)]  # ρ A, (n, 1) each

    def image(u):  # ρ A u + A c + w, as three (n, k) arrays
        return [ra[i][0] * u[0] + ra[i][1] * u[1] + ra[i][2] * u[2] + offset[:, i, None] for i in range(3)]

    u = [u[..., 0], u[..., 1], u[..., 2]]
    for _ in range(iterations):
        y = image(u)
        g = [ra[0][j] * y[0] + ra[1][j] * y[1] + ra[2][j] * y[2] for j in range(3)]  # ρ Aᵀ y ∝ ∇(f²)
        gn = np.sqrt(g[0] ** 2 + g[1] ** 2 + g[2] ** 2)
        moving = gn > 0
        scale = np.where(moving, 1.0 / np.where(moving, gn, 1.0), 1.0)
        u = [np.where(moving, g[j] * scale, u[j]) for j in range(3)]
    y = image(u)
    return np.sqrt(y[0] ** 2 + y[1] ** 2 + y[2] ** 2).max(axis=1)


def sphere_speed_reference(twists, centers, radii, rng, starts=32, iterations=30, initial=None):
    """Largest speed ‖v + ω × x‖ over the surfaces of balls (x = c + ρu): ‖A x + v‖ with A = [ω]x."""
    twists = np.asarray(twists, dtype=float)
    return maximise_norm_on_sphere(hat(twists[:, 3:]), twists[:, :3], centers, radii, rng, starts, iterations, initial)
