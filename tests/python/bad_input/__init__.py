"""The rows of the bad-input table (tests/python/test_bad_input_table.py), one module per API area,
imported by the table in this order:

* rows: ``row``, ``accepted``, ``section`` and the objects the rows share
* pose: Pose
* metric_set: MetricSet, dispkin.shapes, the convex hull
* disp_functions: distances, speeds, section lengths, interpolation
* paths: Path, JointPath, Section
* profiles: Profile
* planning: Limits, plan, Trajectory, overlaps, the motion stream
* hexapod: Hexapod
* frames: WorkToolFrames
* serial_arm: SerialArm
* joint_motion: check_joint_limits, retime, PTP moves of a UR5e
* limits_files: dispkin.limits_files
* job_files: dispkin.jobs.load_job and the command line
* hostile_inputs: nesting, sizes and counts, impossible numbers (doc/input-budget.md)
* pickled_states: objects rebuilt from wrong states
* batches: dispkin.batch and ``dispkin batch``
* job_events: stops, resumptions, speed overrides of a job
"""
