"""dispkin: robot trajectories under a point-set speed limit (the Euclidean DISP metric).

Poses (:class:`Pose`), metric sets (:class:`MetricSet`), point-set builders
(:mod:`dispkin.shapes`), and the DISP functions: chord distance, point and sphere speeds and
exact section lengths; :func:`batch` plans many job files on local processes or a Dask
cluster. Units: metres, radians, seconds. Arrays in and out are float64 numpy
arrays; bad input raises ValueError naming the argument and the value.
"""

from . import _core
from ._core import (
    Hexapod,
    LegExcursion,
    LegViolation,
    TrajectoryCheck,
    WorkspaceCheck,
    WorkToolFrames,
    JointPath,
    Limits,
    MetricSet,
    Path,
    MotionStream,
    OverlappedTrajectory,
    Trajectory,
    TrajectoryCursor,
    Pose,
    Profile,
    convex_hull_vertices,
    disp_distance,
    interpolate,
    jerk_limited_duration_bound,
    plan,
    max_point_speed,
    point_speed,
    section_length,
    sphere_speed,
    velocity_limited_chain,
    velocity_limited_law,
    xyzuvw_for_new_pivot,
)
from . import data, shapes
from .batches import batch

# The serial-arm plugin (URDF via urdfdom into Orocos KDL) is there when the build has it
# (CMake option DISPKIN_BUILD_SERIAL, on by default).
if hasattr(_core, "SerialArm"):
    from ._core import (
        FollowedTrajectory,
        InverseResult,
        JointLimitReport,
        JointLimits,
        JointTrajectory,
        OptimalRetimeResult,
        OverlappedJointTrajectory,
        OverlappedMixedTrajectory,
        RetimeResult,
        Redundancy,
        RedundancyRule,
        SerialArm,
        check_joint_limits,
        retime,
    )

#: The library version, the one set in CMakeLists.txt (``project(dispkin VERSION ...)``).
__version__: str = _core.__version__

__all__ = [
    "Hexapod",
    "LegExcursion",
    "LegViolation",
    "TrajectoryCheck",
    "WorkspaceCheck",
    "WorkToolFrames",
    "JointPath",
    "Limits",
    "MetricSet",
    "Path",
    "MotionStream",
    "OverlappedTrajectory",
    "Trajectory",
    "TrajectoryCursor",
    "Pose",
    "Profile",
    "__version__",
    "batch",
    "convex_hull_vertices",
    "data",
    "disp_distance",
    "interpolate",
    "jerk_limited_duration_bound",
    "plan",
    "max_point_speed",
    "point_speed",
    "section_length",
    "shapes",
    "sphere_speed",
    "velocity_limited_chain",
    "velocity_limited_law",
    "xyzuvw_for_new_pivot",
]
if hasattr(_core, "SerialArm"):
    __all__ += [
        "FollowedTrajectory",
        "InverseResult",
        "JointLimitReport",
        "JointLimits",
        "JointTrajectory",
        "OptimalRetimeResult",
        "OverlappedJointTrajectory",
        "OverlappedMixedTrajectory",
        "RetimeResult",
        "Redundancy",
        "RedundancyRule",
        "SerialArm",
        "check_joint_limits",
        "retime",
    ]
