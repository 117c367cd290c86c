"""The machine limits a job reads besides its `limits` section: limits files (MoveIt's
``joint_limits.yaml``, the Pilz planner's ``cartesian_limits.yaml``) and the `retime` section.

A MoveIt file replaces a serial arm's URDF velocity, effort and position limits (joints it
does not name keep theirs) and gives joint accelerations; a Pilz file gives the path velocity
and acceleration and adds the sphere around the tool centre that keeps the angular speed within
``max_rot_vel`` (see :mod:`dispkin.limits_files`). Which of the two a file is, its content says:
a ``joint_limits:`` mapping or the ``cartesian_limits:`` values.
"""

import math
from typing import Any, Dict, List, Optional

import numpy as np

from .. import limits_files
from .._core import Limits, MetricSet
from .model import KeyPath, Retime


def _kind(data: Any) -> Optional[str]:
    """ "moveit", "pilz" or None (neither), from the file's top-level keys."""
    if not isinstance(data, dict):
        return None
    if "joint_limits" in data:
        return "moveit"
    if "cartesian_limits" in data or "max_trans_vel" in data:
        return "pilz"
    return None


def read_limits_files(
    builder: Any, job: Dict[str, Any], metric_set: MetricSet
) -> Optional[limits_files.PilzCartesianLimits]:
    """limits_file: apply a MoveIt file to the arm (job["arm"], job["joint_acceleration"]), add a
    Pilz file's rotation sphere to the metric set; returns the Pilz limits (None without)."""
    value = builder.data.get("limits_file")
    job["limits_files"] = []
    if value is None:
        return None
    keys: List[KeyPath] = (
        [("limits_file",)] if isinstance(value, str) else [("limits_file", i) for i in range(len(value))]
    )
    pilz = None
    seen = set()
    for at in keys:
        path = builder.file(at)
        try:
            # Read once, under the input budget of job files; both readers take the document.
            document = limits_files.load_limits_file(path)
        except limits_files.LimitsFileError as error:
            raise builder.fail(at, str(error)) from error
        kind = _kind(document.data)
        if kind is None:
            raise builder.fail(
                at,
                f"{str(path)!r} is neither a MoveIt joint_limits.yaml (a `joint_limits:` mapping) "
                "nor a Pilz cartesian_limits.yaml (`cartesian_limits:` with max_trans_vel, ...)",
            )
        if kind in seen:
            raise builder.fail(
                at, f"a second {'MoveIt' if kind == 'moveit' else 'Pilz'} limits file: give one of each at most"
            )
        seen.add(kind)
        try:
            if kind == "moveit":
                if job.get("arm") is None:
                    raise builder.fail(
                        at, "a MoveIt joint_limits.yaml limits the joints of a serial arm: it needs machine.serial_arm"
                    )
                moveit = limits_files.read_moveit_joint_limits(document)
                job["arm"], job["joint_acceleration"] = limits_files.apply_moveit_joint_limits(job["arm"], moveit)
                job["joint_limits_from"] = f"MoveIt {path.name}"
            else:
                # Its max_rot_vel becomes the rotational limit (limits.angular_velocity).
                pilz = limits_files.read_pilz_cartesian_limits(document)
        except ValueError as error:  # LimitsFileError, or the arm refusing a limit of the file
            raise builder.fail(at, str(error)) from error
        job["limits_files"].append(path)
    return pilz


#: The limits the job gives in degrees (radians in the library), and their units.
_ANGULAR_UNITS = {"angular_velocity": "deg/s", "angular_acceleration": "deg/s²"}


def job_limits(builder: Any, pilz: Optional[limits_files.PilzCartesianLimits]) -> Limits:
    """The path limits: the `limits` section's, or a Pilz file's velocity and acceleration (then
    the section gives only jerk and profile)."""
    lim = builder.data["limits"]
    low, high = limits_files.LIMIT_RANGE
    for key, unit in _ANGULAR_UNITS.items():
        if key in lim:  # refused in the job's unit, not in the library's radians
            builder.degrees_in_range(("limits", key), lim[key], math.degrees(low), math.degrees(high), unit)
    # Angular limits are given in degrees (per second, per second squared), like the poses.
    angular = {key: math.radians(lim[key]) for key in _ANGULAR_UNITS if key in lim}
    if pilz is not None:
        for key in ("velocity", "acceleration", "angular_velocity"):
            if key in lim:
                raise builder.fail(
                    ("limits", key), f"{lim[key]!r}: given by the Pilz limits file too; give it in one place"
                )
        from_file = builder.call_section(("limits",), lim, pilz.limits, lim.get("jerk"))
        return builder.call_section(
            ("limits",),
            lim,
            Limits,
            from_file.velocity,
            from_file.acceleration,
            from_file.jerk,
            angular_velocity=from_file.angular_velocity,
            **angular,
        )
    for key in ("velocity", "acceleration"):
        if key not in lim:
            raise builder.fail(
                ("limits",), f"missing required key `{key}` (or a Pilz cartesian_limits.yaml in limits_file)"
            )
    return builder.call_section(
        ("limits",), lim, Limits, lim["velocity"], lim["acceleration"], lim.get("jerk"), **angular
    )


def read_retime(builder: Any, job: Dict[str, Any]) -> None:
    """retime: the method and joint accelerations, checked against the machine."""
    r = builder.data.get("retime")
    if r is None:
        return
    at: KeyPath = ("retime",)
    hexapod, arm = job.get("hexapod"), job.get("arm")
    if hexapod is None and arm is None:
        raise builder.fail(
            at, "re-timing keeps a machine's joint limits: it needs machine.hexapod or machine.serial_arm"
        )
    if hexapod is not None and r["method"] == "scaling":
        raise builder.fail(
            at + ("method",),
            "'scaling': a hexapod's leg speeds enter planning through its joint metric; "
            "re-time a hexapod with method: optimal",
        )
    acceleration = None
    if "joint_acceleration" in r:
        machine = hexapod if hexapod is not None else arm
        value = np.asarray(r["joint_acceleration"], dtype=float)
        if value.ndim == 0:
            value = np.full(machine.dof, float(value))
        if value.size != machine.dof:
            raise builder.fail(
                at + ("joint_acceleration",),
                f"{tuple(value.tolist())}: expected one value or {machine.dof} "
                f"({', '.join(machine.joint_names)}), got {value.size}",
            )
        if r["method"] == "scaling":
            raise builder.fail(
                at + ("joint_acceleration",),
                "the scaling method keeps joint velocities and efforts only; joint accelerations need method: optimal",
            )
        acceleration = value
        job["joint_acceleration"] = value
    elif r["method"] == "optimal":
        acceleration = job.get("joint_acceleration")
    job["retime"] = Retime(r["method"], acceleration)
