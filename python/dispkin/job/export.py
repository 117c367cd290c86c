"""Writing a sampled job: a CSV table, and a JSON document that loads as a ROS
``trajectory_msgs/JointTrajectory`` (header, joint_names, points[].positions / velocities /
accelerations / effort / time_from_start) with the poses, speeds and the summary under the one
key ``dispkin`` (see doc/job-output.md).
"""

import pathlib
from typing import Any, Dict, List, Union

import numpy as np

from .model import Job
from .sampling import JobSamples

#: The pose columns of the CSV file: XYZUVW, metres and degrees.
POSE_COLUMNS = ["x_m", "y_m", "z_m", "u_deg", "v_deg", "w_deg"]


def time_from_start(t: float) -> Dict[str, int]:
    """ROS builtin_interfaces/Duration {sec, nanosec} of t seconds (t >= 0)."""
    nanoseconds = int(round(t * 1e9))
    return {"sec": nanoseconds // 1_000_000_000, "nanosec": nanoseconds % 1_000_000_000}


def csv_header(samples: JobSamples) -> List[str]:
    """Columns of the CSV file: time, each joint's position / velocity / acceleration / effort,
    the pose as XYZUVW, the path velocity, the fastest point's speed, each group's speed."""
    columns = ["time_s"]
    for kind, array in (
        ("position", samples.positions),
        ("velocity", samples.velocities),
        ("acceleration", samples.accelerations),
        ("effort", samples.effort),
    ):
        if array.shape[1]:
            columns += [f"{name}.{kind}" for name in samples.joint_names]
    columns += POSE_COLUMNS + ["path_velocity_mps", "fastest_point_speed_mps"]
    columns += [f"group_{g}_speed_mps" for g in samples.group_speeds]
    return columns


def write_csv(samples: JobSamples, path: Union[str, pathlib.Path]) -> None:
    """The samples as CSV (header csv_header(samples); floats with 17 significant digits)."""
    table = np.column_stack(
        [
            samples.time,
            samples.positions,
            samples.velocities,
            samples.accelerations,
            samples.effort,
            samples.xyzuvw,
            samples.path_velocity,
            samples.fastest_point_speed,
            *samples.group_speeds.values(),
        ]
    )
    np.savetxt(path, table, delimiter=",", header=",".join(csv_header(samples)), comments="", fmt="%.17g")


def ros_pose(row: np.ndarray) -> Dict[str, Dict[str, float]]:
    """A geometry_msgs/Pose {position {x, y, z}, orientation {x, y, z, w}} from a row
    (x, y, z, qx, qy, qz, qw) of JobSamples.poses."""
    x, y, z, qx, qy, qz, qw = (float(v) for v in row)
    return {"position": {"x": x, "y": y, "z": z}, "orientation": {"x": qx, "y": qy, "z": qz, "w": qw}}


def trajectory_json(job: Job, samples: JobSamples, summary: Dict[str, Any]) -> Dict[str, Any]:
    """The samples as a ROS trajectory_msgs/JointTrajectory (header, joint_names, points with
    positions / velocities / accelerations / effort / time_from_start {sec, nanosec}) with
    dispkin's extras under the one key ``dispkin``: the poses as geometry_msgs/Pose (position,
    and the orientation as a quaternion in ROS order x, y, z, w) and as XYZUVW (m, degrees), the
    times, the path velocity, the fastest point's speed, each group's speed and the summary."""
    points = []
    for k, t in enumerate(samples.time):
        points.append(
            {
                "positions": samples.positions[k].tolist(),
                "velocities": samples.velocities[k].tolist(),
                "accelerations": samples.accelerations[k].tolist(),
                "effort": samples.effort[k].tolist(),
                "time_from_start": time_from_start(float(t)),
            }
        )
    frame = "tool frame in the work frame" if job.frames is not None else "platform/flange in base coordinates"
    return {
        "header": {"stamp": {"sec": 0, "nanosec": 0}, "frame_id": ""},
        "joint_names": samples.joint_names,
        "points": points,
        "dispkin": {
            "job": job.name,
            "poses": [ros_pose(row) for row in samples.poses],
            "pose_frame": frame,
            "pose_units": "position in m; orientation a unit quaternion (x, y, z, w), ROS order",
            "poses_xyzuvw": samples.xyzuvw.tolist(),
            "xyzuvw_units": "x, y, z in m; u, v, w in degrees",
            "time": samples.time.tolist(),
            "path_velocity": samples.path_velocity.tolist(),
            "fastest_point_speed": samples.fastest_point_speed.tolist(),
            "group_speeds": {str(g): s.tolist() for g, s in samples.group_speeds.items()},
            "summary": summary,
        },
    }
