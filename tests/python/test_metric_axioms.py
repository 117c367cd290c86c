"""doc/planning.md §8 item 1: the DISP distance is a metric, and it is the chord distance of
doc/disp-metric.md eqs. 18–19.

For random well-formed sets of every family (relative / coplanar / absolute points, a single
ball, collinear relative points with an absolute plane, mixtures) and random poses, under the
Euclidean, max and L1 norms: d(T, T) = 0, symmetry, the triangle inequality, d > 0 for
T1 ≠ T2 — and d equals the largest chord computed here in numpy (points directly; balls under
the max and L1 norms from the dual-norm closed form max_s s·(A c + w) + ρ‖Aᵀ s‖; balls under
the Euclidean norm by maximising over the surface).
"""

import numpy as np

import dispkin
from _helpers import (
    COUNT,
    DUAL_EXTREME_POINTS,
    MOTION_KINDS,
    NORMS,
    SET_FAMILIES,
    chord_maps,
    maximise_norm_on_sphere,
    random_pose,
    random_set,
    relative_motion,
    rng_for,
    rotation_vector_matrix,
)

RELATIVE = 1e-12  # rounding of the same quantity computed along two paths
ABSOLUTE = 1e-14  # metres: rounding of differences of rotation matrices times lengths of ~1 m


def reference_distance(spec, pose_a, pose_b, norm, euclidean_spheres, case):
    """The largest chord over the set's points (and balls, except Euclidean balls, which are
    appended to `euclidean_spheres` for a vectorised maximisation)."""
    (a_rel, w_rel), (a_abs, w_abs) = chord_maps(pose_a, pose_b)
    best = 0.0
    if len(spec.relative):
        best = max(best, NORMS[norm](spec.relative @ a_rel.T + w_rel).max())
    if len(spec.absolute):
        best = max(best, NORMS[norm](spec.absolute @ a_abs.T + w_abs).max())
    for spheres, (a, w) in ((spec.relative_spheres, (a_rel, w_rel)), (spec.absolute_spheres, (a_abs, w_abs))):
        for c, r in spheres:
            if norm == "euclidean":
                euclidean_spheres.append((case, a, w, c, r))
            else:
                s = DUAL_EXTREME_POINTS[norm]
                best = max(best, np.max(s @ (a @ c + w) + r * np.linalg.norm(s @ a, axis=1)))
    return best


def test_metric_axioms_and_chord_definition_on_random_sets():
    rng = rng_for("oracle1")
    norms = list(NORMS)
    d_ab, d_ba, d_ac, d_bc, d_aa, ref = (np.zeros((COUNT, 3)) for _ in range(6))
    euclidean_spheres = []
    for i in range(COUNT):
        spec = random_set(rng, SET_FAMILIES[i % len(SET_FAMILIES)])
        s = spec.build()
        assert s.is_well_formed(), spec
        a = random_pose(rng)
        b = a * relative_motion(rng, MOTION_KINDS[i % len(MOTION_KINDS)])
        c = random_pose(rng) if i % 3 else b * relative_motion(rng, "tiny")
        for k, norm in enumerate(norms):
            d_ab[i, k] = dispkin.disp_distance(s, a, b, norm=norm)
            d_ba[i, k] = dispkin.disp_distance(s, b, a, norm=norm)
            d_ac[i, k] = dispkin.disp_distance(s, a, c, norm=norm)
            d_bc[i, k] = dispkin.disp_distance(s, b, c, norm=norm)
            d_aa[i, k] = dispkin.disp_distance(s, a, a, norm=norm)
            ref[i, k] = reference_distance(spec, a, b, norm, euclidean_spheres, i)

    assert np.all(d_aa <= ABSOLUTE), np.unravel_index(np.argmax(d_aa), d_aa.shape)
    assert np.all(d_ab > 0.0), np.unravel_index(np.argmin(d_ab), d_ab.shape)
    assert np.all(np.abs(d_ab - d_ba) <= RELATIVE * d_ab + ABSOLUTE), np.unravel_index(
        np.argmax(np.abs(d_ab - d_ba) / d_ab), d_ab.shape
    )
    slack = d_ab + d_bc - d_ac
    assert np.all(slack >= -(RELATIVE * d_ac + ABSOLUTE)), np.unravel_index(np.argmin(slack), slack.shape)

    # Euclidean balls: the best surface point found (a lower bound of the true largest chord).
    if euclidean_spheres:
        cases, a, w, c, r = (np.array(x) for x in zip(*euclidean_spheres))
        found = maximise_norm_on_sphere(a, w, c, r, rng)
        np.maximum.at(ref[:, 0], cases, found)
    low = d_ab - ref * (1 - RELATIVE) + ABSOLUTE
    assert np.all(low >= 0), np.unravel_index(np.argmin(low), low.shape)
    # Points and polyhedral-norm balls are exact here; Euclidean balls within 1e-6 of the
    # best surface point found.
    high = ref * (1 + np.array([1e-6, RELATIVE, RELATIVE])) + ABSOLUTE - d_ab
    assert np.all(high >= 0), np.unravel_index(np.argmin(high), high.shape)


def test_distance_sees_a_rotation_about_the_line_through_two_points():
    # The motion a well-formed set must not miss: a turn about the line through two of its
    # points moves only the third, by its distance to the line times 2 sin(φ/2).
    rng = rng_for("oracle1-line")
    for _ in range(min(COUNT, 2000)):
        p = rng.normal(scale=0.3, size=(3, 3))
        s = dispkin.MetricSet()
        s.add_relative(p)
        d = (p[1] - p[0]) / np.linalg.norm(p[1] - p[0])
        phi = 10.0 ** rng.uniform(-8, np.log10(np.pi))
        r = rotation_vector_matrix(phi * d)
        m = np.eye(4)
        m[:3, :3], m[:3, 3] = r, p[0] - r @ p[0]
        a = random_pose(rng)
        b = a * dispkin.Pose.from_matrix(m)
        off_line = np.linalg.norm((p[2] - p[0]) - ((p[2] - p[0]) @ d) * d)
        expected = 2 * np.sin(phi / 2) * off_line
        got = dispkin.disp_distance(s, a, b)
        assert got > 0.0
        assert abs(got - expected) <= 1e-9 * expected + 1e-14, (p, phi, got, expected)


def test_group_weights_scale_the_distance():
    # d = max over groups of d_g · v_sys / v_g (doc/disp-metric.md eq. 17; the DISP patent
    # JP7742490B2, M3/M4); a group without a limit has weight 1.
    rng = rng_for("oracle1-groups")
    for _ in range(200):
        first, second = random_set(rng, "relative"), random_set(rng, "absolute")
        both = first.build()
        both.add_absolute(second.absolute, group=3)
        both.set_group_speed(3, v3 := rng.uniform(0.01, 1.0))
        v_sys = rng.uniform(0.01, 1.0)
        a, b = random_pose(rng), random_pose(rng)
        for norm in NORMS:
            expected = max(
                dispkin.disp_distance(first.build(), a, b, norm=norm),
                dispkin.disp_distance(second.build(), a, b, norm=norm) * v_sys / v3,
            )
            got = dispkin.disp_distance(both, a, b, norm=norm, system_velocity=v_sys)
            assert got == expected or abs(got - expected) <= 1e-15 * expected
