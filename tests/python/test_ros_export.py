"""The JSON trajectory `dispkin plan` writes loads as a ROS trajectory_msgs/JointTrajectory, with
dispkin's extras under the one key `dispkin` and the poses as geometry_msgs/Pose (quaternion in
ROS order x, y, z, w)."""

import json
import pathlib

import numpy as np
import pytest

import dispkin
from dispkin import cli, jobs

ROOT = pathlib.Path(__file__).resolve().parents[2]
JOBS = ROOT / "examples" / "jobs"

# trajectory_msgs/JointTrajectory and trajectory_msgs/JointTrajectoryPoint, field by field.
JOINT_TRAJECTORY = {"header", "joint_names", "points"}
POINT = {"positions", "velocities", "accelerations", "effort", "time_from_start"}


def written(job_file, tmp_path, capsys):
    assert cli.main(["plan", str(job_file), "-o", str(tmp_path)]) == 0
    capsys.readouterr()
    job = jobs.load_job(job_file)
    return job, json.loads((tmp_path / job.outputs["json"]).read_text())


@pytest.mark.parametrize("name", ["hexapod_scan.yaml", "ur5e_lin_move.yaml", "blended_tool_move.yaml"])
def test_the_document_is_a_joint_trajectory_with_one_key_of_extras(name, tmp_path, capsys):
    job, document = written(JOBS / name, tmp_path, capsys)
    assert set(document) == JOINT_TRAJECTORY | {"dispkin"}
    assert document["header"] == {"stamp": {"sec": 0, "nanosec": 0}, "frame_id": ""}
    assert document["joint_names"] == job.joint_names
    dof = len(job.joint_names)
    for point in document["points"]:
        assert set(point) == POINT
        assert len(point["positions"]) == len(point["velocities"]) == len(point["accelerations"]) == dof
        assert set(point["time_from_start"]) == {"sec", "nanosec"}
        assert all(isinstance(v, int) for v in point["time_from_start"].values())
    times = [p["time_from_start"]["sec"] + 1e-9 * p["time_from_start"]["nanosec"] for p in document["points"]]
    np.testing.assert_allclose(times, document["dispkin"]["time"], atol=1e-9)
    assert np.all(np.diff(times) > 0)


@pytest.mark.parametrize("name", ["hexapod_scan.yaml", "ur5e_lin_move.yaml"])
def test_poses_are_ros_poses_with_the_quaternion_in_ros_order(name, tmp_path, capsys):
    job, document = written(JOBS / name, tmp_path, capsys)
    extras = document["dispkin"]
    assert "(x, y, z, w), ROS order" in extras["pose_units"]
    traj = jobs.plan_job(job)
    t = np.asarray(extras["time"])
    for k in (0, len(t) // 3, len(t) - 1):
        expected = dispkin.Pose.from_matrix(traj.sample([t[k]])[0])
        if job.frames is not None:
            expected = job.frames.tool_in_work(expected)
        ros = extras["poses"][k]
        assert set(ros) == {"position", "orientation"}
        position = [ros["position"][a] for a in "xyz"]
        x, y, z, w = (ros["orientation"][a] for a in "xyzw")
        np.testing.assert_array_equal(position, expected.translation)
        np.testing.assert_array_equal([w, x, y, z], expected.quaternion)  # dispkin's order is (w, x, y, z)
        # The same pose as the XYZUVW columns (degrees) say.
        xyzuvw = np.asarray(extras["poses_xyzuvw"][k])
        again = dispkin.Pose.from_xyzuvw(np.concatenate([xyzuvw[:3], np.radians(xyzuvw[3:])]))
        assert again.isclose(dispkin.Pose([w, x, y, z], position), abs_tol=1e-9)
