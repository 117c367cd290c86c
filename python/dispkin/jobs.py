"""Job files: a planning job in YAML, validated against ``job.schema.json`` (shipped with the
package), built into the library's objects, planned and sampled.

``load_job(path)`` reads and validates a job and builds its machine, frames, metric set, path
and limits (a :class:`Job`); ``plan_job(job)`` plans it and applies its events (stops,
resumptions, speed overrides: ``apply_events``); ``sample_job(job, trajectory)`` samples
the trajectory into joint values (hexapod legs, serial-arm joints) and poses (a
:class:`JobSamples`); :mod:`dispkin.cli` writes these as CSV, JSON and a summary.

Every mistake in a job raises :class:`JobError` (a ValueError) whose message starts with
``FILE:LINE:COLUMN: key.path[index]:`` — the offending key, and where it is in the file.

The names live in the modules of :mod:`dispkin.job` (reader, schema, model, builder, events,
planning, sampling, summary, violations, export); this module gathers them in one place.
"""

from .job.builder import load_job
from .job.events import OVERRIDE_RANGE, apply_events, describe_events
from .job.export import POSE_COLUMNS, csv_header, time_from_start, trajectory_json, write_csv
from .job.model import DEFAULT_SAMPLE_PERIOD, Event, Job, JobError, KeyPath, Move, Part, Retime, format_key_path
from .job.planning import JobTrajectory, plan_job
from .job.sampling import ACCELERATION_STEP, JobSamples, group_sets, sample_job, sample_times
from .job.schema import SCHEMA_PATH, load_schema, validate
from .job.summary import BINDING_FRACTION, summarize, summary_text
from .job.violations import Violation, check_samples

__all__ = [
    "ACCELERATION_STEP",
    "BINDING_FRACTION",
    "DEFAULT_SAMPLE_PERIOD",
    "Event",
    "Job",
    "JobError",
    "JobSamples",
    "JobTrajectory",
    "KeyPath",
    "Move",
    "OVERRIDE_RANGE",
    "POSE_COLUMNS",
    "Part",
    "Retime",
    "SCHEMA_PATH",
    "Violation",
    "apply_events",
    "check_samples",
    "csv_header",
    "describe_events",
    "format_key_path",
    "group_sets",
    "load_job",
    "load_schema",
    "plan_job",
    "sample_job",
    "sample_times",
    "summarize",
    "summary_text",
    "time_from_start",
    "trajectory_json",
    "validate",
    "write_csv",
]
