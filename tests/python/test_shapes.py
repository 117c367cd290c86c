"""Shape builders and how well they stand in for a sphere (doc/disp-metric.md eq. 26), checked
geometrically in numpy: vertex radii, face distances, containment via the support function, speed
bounds."""

import math

import numpy as np
import pytest

import dispkin
from dispkin import shapes
from _helpers import COUNT, rng_for, sphere_speed_reference


def icosahedron_faces(v):
    """The 20 faces of a regular icosahedron: triples of mutually nearest neighbours."""
    d = np.linalg.norm(v[:, None] - v[None], axis=2)
    edge = np.min(d[d > 0])
    adjacent = np.abs(d - edge) <= 1e-12 * edge
    return [
        (i, j, k)
        for i in range(12)
        for j in range(i + 1, 12)
        for k in range(j + 1, 12)
        if adjacent[i, j] and adjacent[j, k] and adjacent[i, k]
    ]


def test_inscribed_icosahedron_has_its_vertices_on_the_sphere():
    center, radius = np.array([0.1, -0.2, 0.3]), 0.25
    v = shapes.icosahedron(radius, center, circumscribed=False)
    assert v.shape == (12, 3)
    np.testing.assert_allclose(np.linalg.norm(v - center, axis=1), radius, rtol=1e-15)
    faces = icosahedron_faces(v - center)
    assert len(faces) == 20  # regular: 30 equal edges, 20 equilateral faces
    d = np.linalg.norm((v - center)[:, None] - (v - center)[None], axis=2)
    assert np.isclose(
        np.min(d[d > 0]), radius * 4 / math.sqrt(10 + 2 * math.sqrt(5)), rtol=1e-14
    )  # edge of a regular icosahedron


def test_circumscribed_icosahedron_has_its_faces_touching_the_sphere():
    center, radius = np.array([0.1, -0.2, 0.3]), 0.25
    v = shapes.icosahedron(radius, center) - center
    faces = icosahedron_faces(v)
    assert len(faces) == 20
    # distance of each face plane from the centre = the sphere's radius
    for i, j, k in faces:
        n = np.cross(v[j] - v[i], v[k] - v[i])
        assert abs(abs(n @ v[i]) / np.linalg.norm(n) - radius) <= 1e-15
    assert np.linalg.norm(v, axis=1) / radius == pytest.approx(
        np.full(12, 1.2584), abs=5e-5
    )  # doc/disp-metric.md eq. 26


@pytest.mark.parametrize("k", [0, 1, 2, 3])
def test_icosphere_counts_radius_and_containment(k):
    rng = rng_for(f"icosphere-{k}")
    center, radius = rng.normal(size=3), 0.2
    v = shapes.icosphere(radius, k, center) - center
    assert v.shape == (10 * 4**k + 2, 3)
    r = np.linalg.norm(v, axis=1)
    np.testing.assert_allclose(r, r[0], rtol=1e-14)  # all vertices on one sphere
    if k == 0:
        np.testing.assert_allclose(v, shapes.icosahedron(radius, center) - center, rtol=0, atol=1e-15)
    # Its hull facets (triangles of near neighbours with every vertex on one side) lie at
    # distance >= ρ from the centre, and the nearest ones touch the ball: it contains the ball
    # and is no bigger than needed.
    distances = facet_distances(v)
    assert len(distances) == 20 * 4**k
    assert distances.min() == pytest.approx(radius, rel=1e-14)


def facet_distances(v):
    """Distances from the origin of the planes of the convex hull's triangular facets."""
    d = np.linalg.norm(v[:, None] - v[None], axis=2)
    near = np.argsort(d, axis=1)[:, 1:7]
    out = {}
    for i in range(len(v)):
        for j in near[i]:
            for k in near[i]:
                if j < k and i < min(j, k) and k in near[j]:
                    n = np.cross(v[j] - v[i], v[k] - v[i])
                    n /= np.linalg.norm(n)
                    side = (v - v[i]) @ n
                    if side.max() <= 1e-12 or side.min() >= -1e-12:
                        out[(i, j, k)] = abs(n @ v[i])
    return np.array(list(out.values()))


def test_box_and_spherical_shell():
    corners = shapes.box((0.2, 0.4, 0.6), (1.0, 2.0, 3.0))
    expected = {(1.0 + sx * 0.1, 2.0 + sy * 0.2, 3.0 + sz * 0.3) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)}
    assert {tuple(np.round(c, 15)) for c in corners} == {tuple(np.round(c, 15)) for c in expected}
    shell = shapes.spherical_shell(0.3, 100, (0.0, 0.0, 1.0))
    assert shell.shape == (100, 3)
    np.testing.assert_allclose(np.linalg.norm(shell - [0, 0, 1], axis=1), 0.3, rtol=1e-14)
    np.testing.assert_allclose(shell.mean(axis=0), [0, 0, 1], atol=0.3 * 0.02)  # evenly spread
    s = dispkin.MetricSet()
    s.add_relative(shell)
    assert s.is_well_formed()


def test_sphere_approximation_errors_bounds_and_values():
    rng = rng_for("sphere-approximation")
    n = min(COUNT, 1000)
    twists = rng.normal(size=(n, 6))
    twists[::4, 3:] = 0.0  # pure translations: every stand-in is exact
    centers, radii = rng.normal(scale=0.3, size=(n, 3)), rng.uniform(0.01, 0.5, n)
    exact_reference = sphere_speed_reference(twists, centers, radii, rng)
    for i in range(n):
        errors = shapes.sphere_approximation_errors(twists[i], radii[i], centers[i], subdivisions=(1, 2, 3))
        assert list(errors) == [
            "icosahedron_inscribed",
            "icosahedron_circumscribed",
            "icosphere_1",
            "icosphere_2",
            "icosphere_3",
        ]
        # independently: fastest vertex speed in numpy over the surface maximum found here
        for name, vertices in [
            ("icosahedron_inscribed", shapes.icosahedron(radii[i], centers[i], circumscribed=False)),
            ("icosahedron_circumscribed", shapes.icosahedron(radii[i], centers[i])),
            ("icosphere_2", shapes.icosphere(radii[i], 2, centers[i])),
        ]:
            fastest = np.linalg.norm(twists[i, :3] + np.cross(twists[i, 3:], vertices), axis=1).max()
            assert errors[name] == pytest.approx(fastest / exact_reference[i] - 1, abs=1e-6)
        assert errors["icosahedron_inscribed"] <= 1e-15  # vertices on the sphere: never above it
        assert -1e-15 <= errors["icosahedron_circumscribed"] <= 0.2584  # at most 25.8 % above
        for k in (1, 2, 3):
            # vertices at radius R_k: at most ‖ω‖(R_k − ρ) faster, and the exact speed is >= ‖ω‖ρ
            r_k = np.linalg.norm(shapes.icosphere(1.0, k)[0])
            assert -1e-15 <= errors[f"icosphere_{k}"] <= r_k - 1 + 1e-15
        if i % 4 == 0:
            assert all(abs(e) <= 1e-15 for e in errors.values())
    assert list(shapes.sphere_approximation_errors(twists[1], 0.1, subdivisions=4)) == [
        "icosahedron_inscribed",
        "icosahedron_circumscribed",
        "icosphere_4",
    ]
