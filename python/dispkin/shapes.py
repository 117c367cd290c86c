"""Point-set builders for metric sets, and how well they approximate a sphere.

Each builder returns an (N, 3) float64 array of points in metres, ready for
``MetricSet.add_relative`` / ``add_absolute``. A sphere is best added exactly with
``MetricSet.add_sphere``; the polyhedra are for tools and controllers that only take points.
"""

from typing import Dict, Iterable, Union

import numpy as np

from . import _core

box = _core.shapes.box
icosahedron = _core.shapes.icosahedron
icosphere = _core.shapes.icosphere
spherical_shell = _core.shapes.spherical_shell

__all__ = ["box", "icosahedron", "icosphere", "spherical_shell", "sphere_approximation_errors"]


def sphere_approximation_errors(
    twist,
    radius: float,
    center=(0.0, 0.0, 0.0),
    subdivisions: Union[int, Iterable[int]] = (1, 2, 3),
) -> Dict[str, float]:
    """How far point-set stand-ins for a sphere are from its exact speed, for one motion.

    For the body twist ``twist`` = (v, ω) (6,) (m/s, rad/s, body coordinates) and the ball of
    ``radius`` (metres) around ``center`` (body coordinates), returns a dict name -> relative
    error (fastest vertex speed / exact sphere speed - 1; negative means the stand-in
    under-estimates the sphere) for:

    - ``"icosahedron_inscribed"``: the 12 vertices on the sphere (under-estimates);
    - ``"icosahedron_circumscribed"``: faces touching the sphere (over-estimates, by at most
      25.8 %);
    - ``"icosphere_<k>"`` for each k in ``subdivisions``: the icosahedron subdivided k times and
      scaled to circumscribe (over-estimates, converging to 0 as k grows).

    Speeds are the library's ``point_speed`` and exact ``sphere_speed``.
    """
    exact = _core.sphere_speed(twist, center, radius)
    if exact == 0.0:
        raise ValueError(
            f"twist = {tuple(np.asarray(twist, dtype=float).tolist())}: the sphere does not move "
            "under this twist, so relative errors are undefined"
        )
    if isinstance(subdivisions, (int, np.integer)):
        subdivisions = (int(subdivisions),)

    def relative_error(points: np.ndarray) -> float:
        return float(np.max(_core.point_speed(twist, points))) / exact - 1.0

    errors = {
        "icosahedron_inscribed": relative_error(icosahedron(radius, center, circumscribed=False)),
        "icosahedron_circumscribed": relative_error(icosahedron(radius, center, circumscribed=True)),
    }
    for k in subdivisions:
        errors[f"icosphere_{int(k)}"] = relative_error(icosphere(radius, int(k), center))
    return errors
