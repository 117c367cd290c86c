"""doc/planning.md §8 item 2 (doc/disp-metric.md eq. 27): the vertex shortcut.

A point's speed ‖v + ω × p‖ and its chord ‖(R2 − R1) p + (t2 − t1)‖ are convex in p, so
random points inside the convex hull of a cloud (convex combinations, half of them pushed close
to the boundary) never move faster or farther than the fastest / farthest hull vertex. The
vertices come from the library (convex_hull_vertices, MetricSet.reduce_to_hull, Qhull) and the
maxima over them from max_point_speed / disp_distance; the interior speeds and chords are
computed here in numpy. Relative and absolute clouds, including flat and collinear ones.
"""

import numpy as np

import dispkin
from _helpers import COUNT, hat, random_pose, rng_for, unit_vectors

INTERIOR_SAMPLES = 64
RELATIVE = 1e-12


def random_cloud(rng, i):
    n = int(rng.integers(4, 30))
    kind = i % 5
    if kind == 0:  # Gaussian blob
        return rng.normal(scale=0.3, size=(n, 3))
    if kind == 1:  # box corners plus points inside
        return np.vstack(
            [dispkin.shapes.box(rng.uniform(0.05, 0.5, 3), rng.normal(size=3)), rng.uniform(-0.02, 0.02, (n, 3))]
        )
    if kind == 2:  # flat: coplanar
        normal = unit_vectors(rng, 1)[0]
        p = rng.normal(scale=0.3, size=(n, 3))
        return p - np.outer(p @ normal, normal)
    if kind == 3:  # collinear
        return rng.normal(size=3) + np.outer(rng.normal(size=n), unit_vectors(rng, 1)[0])
    return dispkin.shapes.icosphere(rng.uniform(0.05, 0.5), 1, rng.normal(size=3))  # every point a vertex


def interior_points(rng, cloud):
    """Convex combinations of the cloud (and the cloud itself): half with Dirichlet(1) weights,
    half with those weights raised to the 20th power, which puts them close to the vertices,
    edges and faces."""
    weights = rng.exponential(size=(INTERIOR_SAMPLES, len(cloud)))
    weights[1::2] **= 20
    weights /= weights.sum(axis=1, keepdims=True)
    return np.vstack([weights @ cloud, cloud])


def test_interior_points_never_exceed_the_hull_vertex_maximum():
    rng = rng_for("oracle2")
    for i in range(COUNT):
        cloud = random_cloud(rng, i)
        vertices = dispkin.convex_hull_vertices(cloud)
        # Every vertex is an exact copy of an input point.
        assert (vertices[:, None, :] == cloud[None, :, :]).all(axis=2).any(axis=1).all(), i
        inside = interior_points(rng, cloud)
        twist = rng.normal(size=6)
        pose, pose_b = random_pose(rng), random_pose(rng)
        r, t = pose.rotation(), pose.translation
        r_b, t_b = pose_b.rotation(), pose_b.translation

        relative, absolute = dispkin.MetricSet(), dispkin.MetricSet()
        relative.add_relative(vertices)
        absolute.add_absolute(vertices)

        # Speed: relative points at p, absolute points at body position Rᵀ(p − t).
        speed_rel = np.linalg.norm(twist[:3] + inside @ hat(twist[3:]).T, axis=1).max()
        body = (inside - t) @ r
        speed_abs = np.linalg.norm(twist[:3] + body @ hat(twist[3:]).T, axis=1).max()
        vmax_rel = dispkin.max_point_speed(relative, pose, twist)
        vmax_abs = dispkin.max_point_speed(absolute, pose, twist)
        assert speed_rel <= vmax_rel * (1 + RELATIVE), (i, speed_rel, vmax_rel)
        assert speed_abs <= vmax_abs * (1 + RELATIVE), (i, speed_abs, vmax_abs)

        if relative.is_well_formed():  # collinear clouds are not: they cannot see every motion
            chord_rel = np.linalg.norm(inside @ (r_b - r).T + (t_b - t), axis=1).max()
            chord_abs = np.linalg.norm(inside @ (r_b.T - r.T).T - (r_b.T @ t_b - r.T @ t), axis=1).max()
            assert chord_rel <= dispkin.disp_distance(relative, pose, pose_b) * (1 + RELATIVE), i
            assert chord_abs <= dispkin.disp_distance(absolute, pose, pose_b) * (1 + RELATIVE), i


def test_reduce_to_hull_keeps_every_distance_and_length():
    rng = rng_for("oracle2-reduce")
    for i in range(min(COUNT, 2000)):
        full = dispkin.MetricSet()
        full.add_relative(random_cloud(rng, i % 3), group=0)
        full.add_absolute(random_cloud(rng, i % 3), group=2)
        full.add_sphere(rng.normal(size=3), 0.1, group=2)
        full.set_group_speed(2, 0.5)
        reduced = full.reduce_to_hull()
        assert reduced.groups == full.groups
        assert reduced.group_speed(2) == 0.5 and reduced.group_speed(0) is None
        assert reduced.point_count <= full.point_count and reduced.sphere_count == 1
        a, b, twist = random_pose(rng), random_pose(rng), rng.normal(size=6)
        for f in (
            lambda s: dispkin.max_point_speed(s, a, twist, system_velocity=0.25),
            lambda s: dispkin.disp_distance(s, a, b, system_velocity=0.25),
            lambda s: dispkin.section_length(s, a, b, "screw", system_velocity=0.25),
            lambda s: dispkin.section_length(s, a, b, "decoupled", pivot=(0.1, 0, 0), system_velocity=0.25),
        ):
            full_value, reduced_value = f(full), f(reduced)
            assert abs(full_value - reduced_value) <= 1e-14 * full_value, (i, full_value, reduced_value)
