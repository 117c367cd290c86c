"""Building a validated job into the library's objects: the machine (a hexapod or a serial arm
from its URDF), the work and tool frames, the metric set, the moves joined into paths, the
limits and the output files; :func:`load_job` reads, validates and builds a job file.

The schema checks the shape of a job; what it cannot say (a file that does not exist, a
quaternion that is not a unit one, a pose the arm cannot reach, a blend of a move that starts
at rest) is checked here, and every such error, like every ValueError of the library's
constructors, is reported at the key it comes from.

The metric set is built by :mod:`.metric_set_section`, the moves by :mod:`.move_sequence`
(Cartesian moves in a row joined into one Path, each PTP move a JointPath of its own), the
limits files, retiming and events by :mod:`.machine_limits` and :mod:`.events`; this module
holds the machine, the frames, the limits, the output and what they share: every error at its
key path, the files a job reads, the poses of the moves.
"""

import json
import math
import pathlib
import re
import stat
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from .. import _core
from .._core import Hexapod, Limits, Pose, WorkToolFrames
from ..limits_files import PilzCartesianLimits
from .events import read_events
from .machine_limits import job_limits, read_limits_files, read_retime
from .metric_set_section import MetricSetSection
from .move_sequence import MoveSequence
from . import input_budget
from .model import DEFAULT_SAMPLE_PERIOD, Job, JobError, KeyPath, value_at
from .reader import Source
from .schema import validate

#: The longest file name (bytes) of Linux's file systems (NAME_MAX).
MAX_FILE_NAME_BYTES = 255


def echo(value: Any) -> str:
    """A value of the job for a message: its repr, at most 200 characters of it."""
    text = repr(value)
    return text if len(text) <= 200 else f"{text[:200]}… ({len(text)} characters)"


class _Builder(MetricSetSection, MoveSequence):
    """Turns validated job data into library objects; every error names its key path.

    The sections fill `job`, the keyword arguments of :class:`Job` beyond the metric set, the
    moves and the limits, in the order of load_job: the machine first (the metric set may take
    a hexapod's leg group, the start pose may be the machine's home), then the frames (every
    pose of the moves is a tool pose in the work frame).
    """

    def __init__(self, source: Source):
        self.source = source
        self.data = source.data
        self.directory = source.path.resolve().parent
        #: The files the job reads besides itself (URDF, hexapod file, limits files).
        self.inputs: List[pathlib.Path] = []

    def fail(self, key_path: KeyPath, message: str) -> JobError:
        """The error `message` at key_path of the job file (to raise)."""
        return self.source.error(key_path, message)

    def call(self, key_path: KeyPath, function: Any, *args: Any, **kwargs: Any) -> Any:
        """function(*args, **kwargs), its ValueError / RuntimeError re-raised at key_path."""
        try:
            return function(*args, **kwargs)
        except JobError:
            raise
        except (ValueError, RuntimeError) as error:
            raise self.fail(key_path, str(error)) from error

    def call_section(
        self,
        at: KeyPath,
        written: Dict[str, Any],
        function: Any,
        *args: Any,
        elsewhere: Optional[KeyPath] = None,
        **kwargs: Any,
    ) -> Any:
        """function(*args, **kwargs) on the values of the mapping at `at` (`written`: as the job
        gives them); a ValueError / RuntimeError ``name = value: reason`` naming one of its keys
        is re-raised at that key with the value as written, any other at `elsewhere` (default
        `at`). (Keys whose units the job converts, degrees, are checked before: the reason would
        give radians.)"""
        try:
            return function(*args, **kwargs)
        except JobError:
            raise
        except (ValueError, RuntimeError) as error:
            named = re.match(r"(\w+)(?:\[\d+\])? = .*?: (.*)$", str(error), re.S)
            if named and named.group(1) in written:
                key = named.group(1)
                raise self.fail(at + (key,), f"{written[key]!r}: {named.group(2)}") from error
            raise self.fail(at if elsewhere is None else elsewhere, str(error)) from error

    def degrees_in_range(
        self, at: KeyPath, value: float, low: float, high: float, unit: str, *, high_open: bool = False
    ) -> None:
        """A value the job gives in degrees (`unit`: deg, deg/s, deg/s²) within [low, high] (or
        [low, high) with high_open), refused with the value as written and the range in the
        job's unit."""
        if not (low <= value < high if high_open else low <= value <= high):
            raise self.fail(at, f"{value!r}: must be in [{low:.6g}, {high:.6g}{')' if high_open else ']'} {unit}")

    def file(self, key_path: KeyPath) -> pathlib.Path:
        """The existing regular file named at key_path, relative to the job file's directory
        (a directory, a FIFO or a device is refused for what it is: reading a FIFO would wait
        for a writer). Every such file is an input of the job (Job.inputs)."""
        path = pathlib.Path(value_at(self.data, key_path))
        path = path if path.is_absolute() else self.directory / path
        try:
            mode = path.stat().st_mode
        except OSError as error:
            reason = (
                "does not exist"
                if isinstance(error, FileNotFoundError)
                else f"cannot be read: {error.strerror or error}"
            )
            raise self.fail(key_path, f"file {str(path)!r} {reason}") from None
        except ValueError as error:  # a NUL character: no file has such a name
            raise self.fail(key_path, f"{str(path)!r}: not a file name: {error}") from None
        if stat.S_ISDIR(mode):
            raise self.fail(key_path, f"{str(path)!r}: is a directory, not a file")
        if not stat.S_ISREG(mode):
            raise self.fail(key_path, f"{str(path)!r}: is not a regular file (a FIFO, a device or a socket)")
        self.inputs.append(path)
        return path

    # Poses ---------------------------------------------------------------------------------

    def raw_pose(self, key_path: KeyPath) -> Pose:
        """A pose as written: XYZUVW (m, degrees) or quaternion + translation."""
        d = value_at(self.data, key_path)
        if "xyzuvw" in d:
            x = list(map(float, d["xyzuvw"]))
            return self.call(key_path + ("xyzuvw",), Pose.from_xyzuvw, x[:3] + [math.radians(a) for a in x[3:]])
        q = np.asarray(d["quaternion"], dtype=float)
        norm = float(np.linalg.norm(q))
        if abs(norm - 1.0) > 1e-6:  # no silent normalisation of a mistyped quaternion
            raise self.fail(
                key_path + ("quaternion",),
                f"{tuple(q.tolist())}: must be a unit quaternion (w, x, y, z), norm is {norm:.9g}",
            )
        return self.call(key_path, Pose, q / norm, d["translation"])

    def pose(self, key_path: KeyPath, frames: Optional[WorkToolFrames]) -> Pose:
        """A commanded pose as the platform/flange pose: with frames, the job's pose is the tool
        frame in the work frame."""
        pose = self.raw_pose(key_path)
        return frames.platform_pose(pose) if frames is not None else pose

    def relative_end(self, current: Pose, key_path: KeyPath, frames: Optional[WorkToolFrames]) -> Pose:
        """`by`: translation added in base (or work) coordinates, rotation about the tool's own axes."""
        delta = self.raw_pose(key_path)
        if frames is None:
            return Pose(
                quaternion=(current * Pose(quaternion=delta.quaternion)).quaternion,
                translation=current.translation + delta.translation,
            )
        tool = frames.tool_in_work(current)
        moved = Pose(
            quaternion=(tool * Pose(quaternion=delta.quaternion)).quaternion,
            translation=tool.translation + delta.translation,
        )
        return frames.platform_pose(moved)

    # The machine and the frames ----------------------------------------------------------------

    def machine(self, job: Dict[str, Any]) -> None:
        """machine: a hexapod or a serial arm, or none (poses only)."""
        machine = self.data.get("machine")
        if not machine:
            return
        if "hexapod" in machine:
            self.hexapod(job, machine["hexapod"])
        else:
            self.serial_arm(job, machine["serial_arm"])

    def hexapod(self, job: Dict[str, Any], h: Dict[str, Any]) -> None:
        """machine.hexapod: from a file, an inline description, or the symmetric parameters."""
        at: KeyPath = ("machine", "hexapod")
        if "file" in h:
            job["hexapod"] = self.call(at + ("file",), Hexapod.load, str(self.file(at + ("file",))))
        elif "description" in h:
            job["hexapod"] = self.call(at + ("description",), Hexapod.from_json, json.dumps(h["description"]))
        else:
            s = dict(h["symmetric"])
            for angle in ("base_gap", "platform_gap"):  # degrees in the file, radians in the API
                # Hexapod.symmetric takes a gap in [0, 2π/3): a pair's joints stay apart from the next pair's.
                self.degrees_in_range(at + ("symmetric", angle), s[angle], 0.0, 120.0, "deg", high_open=True)
                s[angle] = math.radians(s[angle])
            job["hexapod"] = self.call_section(at + ("symmetric",), h["symmetric"], Hexapod.symmetric, **s)
        job["joint_metric"] = bool(h.get("joint_metric", False))

    def serial_arm(self, job: Dict[str, Any], a: Dict[str, Any]) -> None:
        """machine.serial_arm: the chain base_link .. tip_link of a URDF, and its start joints."""
        at: KeyPath = ("machine", "serial_arm")
        if not hasattr(_core, "SerialArm"):
            raise self.fail(at, "this build of dispkin has no serial-arm plugin (DISPKIN_BUILD_SERIAL=OFF)")
        urdf = self.file(at + ("urdf",))
        arm = self.call(at, _core.SerialArm.from_urdf, str(urdf), a["base_link"], a["tip_link"])
        q_start = np.asarray(a["q_start"], dtype=float)
        if q_start.size != arm.dof:
            raise self.fail(
                at + ("q_start",),
                f"{tuple(q_start.tolist())}: expected {arm.dof} joint values ({', '.join(arm.joint_names)}), got {q_start.size}",
            )
        if "redundancy" in a and arm.redundancy.kind == "none":
            raise self.fail(
                at + ("redundancy",),
                f"{a['redundancy']}: the arm ({arm.dof} joints, family {arm.family}) has no redundancy parameter",
            )
        job["arm"], job["q_start"] = arm, q_start
        if a.get("redundancy") == "moved":
            job["redundancy_rule"] = _core.RedundancyRule()

    def frames(self, job: Dict[str, Any]) -> None:
        """frames: the work and tool frames, and the pivot (by default the tool frame's origin)."""
        f = self.data.get("frames") or {}
        frames = None
        if "work" in f or "tool" in f:
            work = self.raw_pose(("frames", "work")) if "work" in f else None
            tool = self.raw_pose(("frames", "tool")) if "tool" in f else None
            frames = self.call(("frames",), WorkToolFrames, work, tool)
        job["frames"] = frames
        if "pivot" in f:
            job["pivot"] = np.asarray(f["pivot"], dtype=float)
        else:
            job["pivot"] = frames.pivot if frames is not None else np.zeros(3)

    # Limits and output -------------------------------------------------------------------------

    def limits(self, pilz: Optional[PilzCartesianLimits]) -> Tuple[Limits, str]:
        """limits: (the path's velocity, acceleration and jerk limits, with the tool's angular
        limits when given, the profile); velocity, acceleration and the angular velocity come
        from a Pilz limits file when the job has one."""
        lim = self.data["limits"]
        profile = lim.get("profile", "scurve")
        if profile == "scurve" and "jerk" not in lim:
            raise self.fail(
                ("limits",),
                "missing key `jerk`: the scurve profile (the default) needs a jerk limit; give one or set profile: trapezoid",
            )
        return job_limits(self, pilz), profile

    def corner_tolerance(self) -> float:
        """limits.corner_tolerance (m, default 0: every corner stops)."""
        return float(self.data["limits"].get("corner_tolerance", 0.0))

    def output(self, job: Dict[str, Any], name: str) -> None:
        """output: the sample period and the file names (default: from the job's name)."""
        out = self.data.get("output") or {}
        job["sample_period"] = float(out.get("sample_period", DEFAULT_SAMPLE_PERIOD))
        if job["sample_period"] < input_budget.MIN_SAMPLE_PERIOD:
            raise self.fail(
                ("output", "sample_period"),
                f"{job['sample_period']!r}: must be at least "
                f"{input_budget.MIN_SAMPLE_PERIOD:g} s (doc/input-budget.md)",
            )
        files = {"csv": f"{name}.csv", "json": f"{name}.json", "summary": f"{name}.summary.txt"}
        for key in files:
            if key in out:
                self.output_name(("output", key), out[key])
                files[key] = out[key]
            elif len(files[key].encode("utf-8")) > MAX_FILE_NAME_BYTES:
                at: KeyPath = ("name",) if "name" in self.data else ()
                raise self.fail(
                    at,
                    f"{echo(name)}: the output file name {echo(files[key])} made from it is longer than "
                    f"{MAX_FILE_NAME_BYTES} bytes, the longest file name: give a shorter name, or output.{key}",
                )
        keys = list(files)
        for i, key in enumerate(keys):
            for earlier in keys[:i]:
                if files[key] == files[earlier]:
                    raise self.fail(
                        ("output", key),
                        f"{files[key]!r}: the same file as output.{earlier}: each output needs a name of its own",
                    )
        job["outputs"] = files

    def output_name(self, at: KeyPath, value: str) -> None:
        """An output file name: one name (the directory is `-o OUTDIR`), not . or .., at most
        MAX_FILE_NAME_BYTES bytes."""
        if value in ("", ".", "..") or "\0" in value or pathlib.PurePath(value).name != value:
            raise self.fail(at, f"{echo(value)}: a file name, not a path (the directory is `-o OUTDIR`)")
        if len(value.encode("utf-8")) > MAX_FILE_NAME_BYTES:
            raise self.fail(at, f"{echo(value)}: longer than {MAX_FILE_NAME_BYTES} bytes, the longest file name")


def load_job(path: Union[str, pathlib.Path]) -> Job:
    """Read, validate and build the job file at `path` (see :mod:`dispkin.jobs`); raises
    JobError pointing at the offending key and line."""
    source = Source(pathlib.Path(path))
    validate(source)
    builder = _Builder(source)
    name = source.data.get("name") or source.path.stem
    safe_name = re.sub(r"[^A-Za-z0-9_.-]+", "_", name)  # the default output file names
    job: Dict[str, Any] = {}
    builder.machine(job)
    builder.frames(job)
    metric_set = builder.metric_set(job)
    pilz = read_limits_files(builder, job, metric_set)  # before the moves: they keep the arm's limits
    start = builder.start(job)
    # Before the moves: a run that moves the redundancy parameter before a PTP move is planned as
    # it is read (MoveSequence.planned_end).
    limits, profile = builder.limits(pilz)
    read_retime(builder, job)
    job["corner_tolerance"] = builder.corner_tolerance()
    builder.run_planning = dict(
        metric_set=metric_set, limits=limits, profile=profile, corner_tolerance=job["corner_tolerance"]
    )
    path_, moves, parts = builder.moves(job, start)
    read_events(builder, job, parts)
    builder.output(job, safe_name)
    return Job(
        file=source.path,
        name=name,
        metric_set=metric_set,
        path=path_,
        moves=moves,
        limits=limits,
        profile=profile,
        parts=parts,
        source=source,
        inputs=builder.inputs,
        **job,
    )
