"""Building a validated job into the library's objects: the machine (a hexapod or a serial arm
from its URDF), the work and tool frames, the metric set, the moves joined into paths, the
limits and the output files; :func:`load_job` reads, validates and builds a job file.

The schema checks the shape of a job; what it cannot say (a file that does not exist, a
quaternion that is not a unit one, a pose the arm cannot reach, a blend of a move that starts
at rest) is checked here, and every such error, like every ValueError of the library's
constructors, is reported at the key it comes from.

Cartesian moves (lin, circ, spline) in a row are joined into one Path, planned as one and
blended where the job asks; a PTP move is a JointPath of its own, at rest at both ends. On a
serial arm the joints at each part's start are the inverse-kinematics branch followed from
``q_start`` along the moves before it.
"""

import dataclasses
import functools
import json
import math
import pathlib
import re
import stat
from typing import Any, Callable, Dict, List, NamedTuple, Optional, Tuple, Union

import numpy as np

from .. import _core, shapes
from .._core import Hexapod, Limits, MetricSet, Path, Pose, WorkToolFrames
from ..limits_files import PilzCartesianLimits
from .events import read_events
from .machine_limits import job_limits, read_limits_files, read_retime
from . import input_budget
from .model import DEFAULT_SAMPLE_PERIOD, Job, JobError, KeyPath, Move, Part, value_at
from .reader import Source
from .schema import validate

#: The keys of a metric_set.points entry that only a `shape` entry uses.
_SHAPE_PARAMETERS = ("center", "centre", "radius", "size", "subdivisions", "count", "circumscribed")

#: Per shape, the shape parameters it does not take (the schema allows all of them on every shape).
_NOT_PARAMETERS_OF = {
    "icosahedron": ("size", "subdivisions", "count"),
    "icosphere": ("size", "count", "circumscribed"),
    "box": ("radius", "subdivisions", "count", "circumscribed"),
    "sphere": ("size", "subdivisions", "count", "circumscribed"),
    "spherical_shell": ("size", "subdivisions", "circumscribed"),
}

#: The smallest blend_weight: the blend's ends lie at this share of each move from the corner,
#: and within 1e-6 of a section's end they snap to it (a rotation-vector blend then has nothing
#: to blend; a nested-SLERP blend rounds to no length, or to 10⁵ sections of 1e-20 m).
MIN_BLEND_WEIGHT = 1e-5
#: The smallest blend (m of geometric size), as Path.blended builds no smaller one.
MIN_BLEND = 1e-9

#: The longest file name (bytes) of Linux's file systems (NAME_MAX).
MAX_FILE_NAME_BYTES = 255


def echo(value: Any) -> str:
    """A value of the job for a message: its repr, at most 200 characters of it."""
    text = repr(value)
    return text if len(text) <= 200 else f"{text[:200]}… ({len(text)} characters)"


#: Samples of a Cartesian run's geometry along which the arm's joints are followed to its end.
_FOLLOW_SAMPLES = 201


class _RunMove(NamedTuple):
    """A Cartesian move of the current run: its index, its Path, and how to build it again
    (Path.then appends in place, so the run's first move is built anew to become the run)."""

    index: int
    path: Path
    constructor: Callable[..., Path]
    arguments: Tuple[Any, ...]


@dataclasses.dataclass
class _Moves:
    """The moves read so far: the pose (and on an arm the joints) where they end, the moves and
    parts built, and the Cartesian moves since the last PTP move (the run not yet a part)."""

    current: Pose
    #: Serial arm: the joints at `current`; the next inverse-kinematics branch is the one nearest.
    q_current: Optional[np.ndarray]
    built: List[Move] = dataclasses.field(default_factory=list)
    parts: List[Part] = dataclasses.field(default_factory=list)
    run: List[_RunMove] = dataclasses.field(default_factory=list)


class _Builder:
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

    # The metric set ----------------------------------------------------------------------------

    def metric_set(self, job: Dict[str, Any]) -> MetricSet:
        """metric_set: its points, lists or shapes, the group speeds, and a hexapod's leg group."""
        m = self.data["metric_set"]
        metric_set = MetricSet()
        for i, entry in enumerate(m.get("points", [])):
            self.points(metric_set, entry, ("metric_set", "points", i))
        self.group_speeds(metric_set, m.get("groups", []))
        self.leg_speed_group(job, metric_set)
        if metric_set.point_count == 0 and metric_set.sphere_count == 0:
            raise self.fail(
                ("metric_set",), "the metric set has no points: give metric_set.points (or a hexapod leg_speed_group)"
            )
        self.call(("metric_set",), metric_set.require_well_formed)
        return metric_set

    def points(self, metric_set: MetricSet, entry: Dict[str, Any], at: KeyPath) -> None:
        """One metric_set.points entry: a list of relative or absolute points, or a shape."""
        group = entry.get("group", 0)
        if "shape" not in entry:  # the schema allows the shape keys everywhere; only shapes use them
            for key in _SHAPE_PARAMETERS:
                if key in entry:
                    raise self.fail(at + (key,), "a parameter of shapes only, not of a list of points")
        if "relative" in entry:
            self.call(at + ("relative",), metric_set.add_relative, entry["relative"], group)
        elif "absolute" in entry and "shape" not in entry:
            self.call(at + ("absolute",), metric_set.add_absolute, entry["absolute"], group)
        else:
            self.shape(metric_set, entry, at, group)

    def shape(self, metric_set: MetricSet, entry: Dict[str, Any], at: KeyPath, group: int) -> None:
        """A shape entry: an exact sphere, or the points of an icosahedron, icosphere, box or
        spherical shell (relative unless `absolute: true`)."""
        kind = entry["shape"]
        # `center` as the API spells it; `centre`, the spelling of earlier job files, still reads.
        if "center" in entry and "centre" in entry:
            raise self.fail(at + ("centre",), "`centre` is an alias of `center`: give one of them, not both")
        center = entry.get("center", entry.get("centre", (0.0, 0.0, 0.0)))
        absolute = bool(entry.get("absolute", False))
        for key in _NOT_PARAMETERS_OF[kind]:
            if key in entry:
                raise self.fail(at + (key,), f"not a parameter of shape {kind!r}")
        if kind == "sphere":
            self.call(at, metric_set.add_sphere, center, entry["radius"], absolute, group)
            return
        if kind == "icosahedron":
            points = self.call(at, shapes.icosahedron, entry["radius"], center, entry.get("circumscribed", True))
        elif kind == "icosphere":
            points = self.call(at, shapes.icosphere, entry["radius"], entry["subdivisions"], center)
        elif kind == "box":
            points = self.call(at, shapes.box, entry["size"], center)
        else:
            points = self.call(at, shapes.spherical_shell, entry["radius"], entry["count"], center)
        add = metric_set.add_absolute if absolute else metric_set.add_relative
        self.call(at, add, points, group)

    def group_speeds(self, metric_set: MetricSet, groups: List[Dict[str, Any]]) -> None:
        """metric_set.groups: a speed limit of its own for a group that has points."""
        populated = set(metric_set.groups)  # set_group_speed adds the group even without points
        groups_seen = set()
        for i, g in enumerate(groups):
            if g["group"] not in populated:
                raise self.fail(("metric_set", "groups", i, "group"), f"{g['group']}: no points belong to this group")
            if g["group"] in groups_seen:
                raise self.fail(("metric_set", "groups", i, "group"), f"{g['group']}: group given twice")
            groups_seen.add(g["group"])
            self.call(("metric_set", "groups", i), metric_set.set_group_speed, g["group"], g["speed"])

    def leg_speed_group(self, job: Dict[str, Any], metric_set: MetricSet) -> None:
        """machine.hexapod.leg_speed_group (rule (a)): the upper leg joints as a group of their
        own, held to the leg speed."""
        hexapod = job.get("hexapod")
        leg_group = (self.data.get("machine") or {}).get("hexapod", {}).get("leg_speed_group")
        if hexapod is None or leg_group is None:
            return
        at: KeyPath = ("machine", "hexapod", "leg_speed_group")
        if leg_group in metric_set.groups:
            raise self.fail(
                at, f"{leg_group}: the metric set already has group {leg_group}; the legs need a group of their own"
            )
        self.call(at, hexapod.add_leg_speed_group, metric_set, leg_group)
        job["leg_speed_group"] = leg_group

    # The moves ---------------------------------------------------------------------------------

    def start(self, job: Dict[str, Any]) -> Pose:
        """start, or the machine's own start: a hexapod's home, the arm's pose at q_start."""
        if "start" in self.data:
            return self.pose(("start",), job["frames"])
        if job.get("hexapod") is not None:
            return job["hexapod"].home
        if job.get("arm") is not None:
            return job["arm"].forward(job["q_start"])
        raise self.fail((), "missing required key `start` (only a machine gives a default start pose)")

    def moves(self, job: Dict[str, Any], start: Pose) -> Tuple[Optional[Path], List[Move], List[Part]]:
        """moves, in order from `start`: (the whole path when the job is one Cartesian run, else
        None; the moves; the parts planned one after the other)."""
        moves = _Moves(current=start, q_current=job.get("q_start"))
        for i, move in enumerate(self.data["moves"]):
            at: KeyPath = ("moves", i)
            blend = move.get("blend")
            self.blend_keys(at, move)
            if i == 0:
                for key in ("blend", "blend_weight"):
                    if key in move:
                        raise self.fail(at + (key,), f"{move[key]}: the first move has no previous move to blend with")
            if "ptp" in move:
                for key in ("velocity", "acceleration"):
                    if key in move:
                        raise self.fail(
                            at + (key,),
                            f"{move[key]}: a PTP move runs under the joint limits and `limits`; "
                            "a move's own speed is for lin, circ and spline moves",
                        )
                self.ptp_move(job, moves, at, blend if blend is not None else move.get("blend_weight"))
            else:
                self.cartesian_move(job, moves, at, move, blend)
        self.close_run(job, moves)
        parts = moves.parts
        whole_path = parts[0].path if len(parts) == 1 and parts[0].kind == "path" else None
        return whole_path, moves.built, parts

    def blend_keys(self, at: KeyPath, move: Dict[str, Any]) -> None:
        """A blend is given by its size (`blend`, m) or as the share of both moves (`blend_weight`,
        the Mamezou article's w), not both; `orientation_blend` says how it turns the tool and needs one of them."""
        if "blend" in move and "blend_weight" in move:
            raise self.fail(
                at + ("blend_weight",),
                f"{move['blend_weight']}: give the blend by its size (`blend`, m) "
                "or as a share of both moves (`blend_weight`), not both",
            )
        if "blend_weight" in move and move["blend_weight"] < MIN_BLEND_WEIGHT:
            raise self.fail(
                at + ("blend_weight",),
                f"{move['blend_weight']!r}: must be at least {MIN_BLEND_WEIGHT:g}: a smaller share "
                "puts the blend's ends within 1e-06 of the corner, where they meet it, and leaves no blend",
            )
        if "blend" in move and move["blend"] < MIN_BLEND:
            raise self.fail(
                at + ("blend",),
                f"{move['blend']!r}: must be at least {MIN_BLEND:g} m, the smallest blend dispkin builds",
            )
        if "orientation_blend" in move and "blend" not in move and "blend_weight" not in move:
            raise self.fail(
                at + ("orientation_blend",),
                f"{move['orientation_blend']}: there is no blend to shape; give `blend` (m) or `blend_weight`",
            )

    def ptp_move(self, job: Dict[str, Any], moves: _Moves, at: KeyPath, blend: Optional[float]) -> None:
        """A PTP move: the run before it becomes a part, the move a part of its own."""
        if blend is not None:
            raise self.fail(
                at + ("blend",),
                f"{blend}: a PTP move starts and ends at rest; it does not blend with the previous move",
            )
        self.close_run(job, moves)
        q_a, q_b, end = self.ptp(job, at, moves.current, moves.q_current)
        path = self.call(at + ("ptp",), Path.ptp, q_a, q_b)
        moves.built.append(Move("ptp", path, None))
        moves.parts.append(Part("ptp", path, q_a, [at[1]]))
        moves.current, moves.q_current = end, q_b

    def cartesian_move(
        self, job: Dict[str, Any], moves: _Moves, at: KeyPath, move: Dict[str, Any], blend: Optional[float]
    ) -> None:
        """A lin, circ or spline move from the current pose, added to the current run."""
        for key in ("blend", "blend_weight"):
            if key in move and moves.built[-1].kind == "ptp":
                raise self.fail(
                    at + (key,),
                    f"{move[key]}: the previous move is a PTP move, which ends at rest; nothing to blend with",
                )
        kind = "lin" if "lin" in move else "circ" if "circ" in move else "spline"
        arm = job.get("arm")
        if arm is not None and arm.dof != 6 and arm.redundancy.kind == "none":
            raise self.fail(
                at + (kind,),
                f"a {kind} move on a serial arm is followed by inverting its Jacobian: the arm needs 6 joints, "
                f"or 7 with a redundancy parameter; it has {arm.dof} (family {arm.family})",
            )
        section = {"lin": self.lin, "circ": self.circ, "spline": self.spline}[kind]
        constructor, arguments, end = section(job, at, moves.current)
        # The move's own speed and acceleration (keywords of Path.lin / circ / spline).
        own = {key: move[key] for key in ("velocity", "acceleration") if key in move}
        if own:
            constructor = functools.partial(constructor, **own)
        # The move's own limits are reported at their keys (`moves[i].velocity`), the rest at the move.
        path = self.call_section(at, own, constructor, *arguments, elsewhere=at + (kind,))
        moves.built.append(
            Move(kind, path, blend, move.get("blend_weight"), move.get("orientation_blend", "rotation_vector"))
        )
        moves.run.append(_RunMove(at[1], path, constructor, arguments))
        moves.current = end

    def lin(self, job: Dict[str, Any], at: KeyPath, current: Pose) -> Tuple[Callable[..., Path], Tuple[Any, ...], Pose]:
        """A lin move: (Path.lin, its arguments, the end pose); the end is absolute (`to`) or
        relative to the current pose (`by`)."""
        lin = value_at(self.data, at + ("lin",))
        if "to" in lin:
            end = self.pose(at + ("lin", "to"), job["frames"])
        else:
            end = self.relative_end(current, at + ("lin", "by"), job["frames"])
        return Path.lin, (current, end, lin.get("interpolation", "decoupled"), job["pivot"]), end

    def circ(
        self, job: Dict[str, Any], at: KeyPath, current: Pose
    ) -> Tuple[Callable[..., Path], Tuple[Any, ...], Pose]:
        """A circ move: (Path.circ, its arguments, the end pose); the arc runs through `via`."""
        via = self.pose(at + ("circ", "via"), job["frames"])
        end = self.pose(at + ("circ", "to"), job["frames"])
        return Path.circ, (current, via, end, job["pivot"]), end

    def spline(
        self, job: Dict[str, Any], at: KeyPath, current: Pose
    ) -> Tuple[Callable[..., Path], Tuple[Any, ...], Pose]:
        """A spline move: (Path.spline, its arguments, the end pose) through the `through` poses."""
        spline = value_at(self.data, at + ("spline",))
        through = [self.pose(at + ("spline", "through", k), job["frames"]) for k in range(len(spline["through"]))]
        end = self.pose(at + ("spline", "to"), job["frames"])
        return Path.spline, ([current, *through, end], job["pivot"]), end

    def close_run(self, job: Dict[str, Any], moves: _Moves) -> None:
        """The Cartesian moves since the last PTP move joined (and blended) into one Path, a part;
        on an arm, the joints at its end are the branch followed along its geometry."""
        run = moves.run
        if not run:
            return
        arm = job.get("arm")
        first = run[0]
        whole = self.call(("moves", first.index, moves.built[first.index].kind), first.constructor, *first.arguments)
        for later in run[1:]:
            move = moves.built[later.index]
            if move.blend_weight is not None:
                self.call(
                    ("moves", later.index, "blend_weight"),
                    whole.then,
                    later.path,
                    weight=move.blend_weight,
                    orientation_blend=move.orientation_blend,
                )
            elif move.blend is not None:
                self.call(
                    ("moves", later.index, "blend"),
                    whole.then,
                    later.path,
                    blend=move.blend,
                    orientation_blend=move.orientation_blend,
                )
            else:
                self.call(("moves", later.index), whole.then, later.path)
        q_run = self.joints_at(arm, ("moves", first.index), whole.start, moves.q_current) if arm is not None else None
        moves.parts.append(Part("path", whole, q_run, [m.index for m in run]))
        if arm is not None:
            poses = [Pose.from_matrix(m) for m in np.asarray(whole.sample(np.linspace(0.0, 1.0, _FOLLOW_SAMPLES)))]
            # The parameter as the followers take it: held, or moved by the same rule.
            moved = job.get("redundancy_rule") is not None
            moves.q_current = self.call(("moves", run[-1].index), arm.follow, poses, q_run, move_redundancy=moved)[-1]
        run.clear()

    def moved_redundancy(self, job: Dict[str, Any], parts: List[Part]) -> None:
        """`redundancy: moved` where the followers can take it: the optimal re-timing holds the
        parameter, and a PTP move after a Cartesian run would start from joints the run reaches
        only once planned (doc/inverse-kinematics.md §14)."""
        if job.get("redundancy_rule") is None:
            return
        at = ("machine", "serial_arm", "redundancy")
        retime = job.get("retime")
        if retime is not None and retime.method == "optimal":
            raise self.fail(at, "moved: not with retime method optimal (its grid holds the parameter); use scaling")
        kinds = [part.kind for part in parts]
        for k, part in enumerate(parts):
            if part.kind == "ptp" and "path" in kinds[:k]:
                raise self.fail(
                    ("moves", part.moves[0], "ptp"),
                    "a PTP move after a Cartesian move with `redundancy: moved`: its start joints are the run's "
                    "end, known only once the run is planned; use `redundancy: q_start`",
                )

    def joints_at(self, arm: Any, key_path: KeyPath, pose: Pose, q_reference: np.ndarray) -> np.ndarray:
        """The arm's joints at `pose`: q_reference itself when it reaches the pose, else the
        inverse-kinematics solution (within the limits) on its branch, the one nearest to it
        (SerialArm.follow)."""
        if arm.forward(q_reference).is_approx(pose, 1e-9):
            return np.asarray(q_reference, dtype=float)
        if arm.redundancy.kind != "none":
            # A redundant arm: the solution nearest q_reference at its redundancy value
            # (doc/inverse-kinematics.md eq. 41 keeps that value along the moves).
            solutions = arm.inverse(pose, q_ref=q_reference)
            if len(solutions) == 0:
                raise self.fail(
                    key_path,
                    f"the arm cannot reach this pose within its joint limits with {arm.redundancy.joint_name} "
                    f"at {arm.redundancy.value(q_reference):g} rad, its value at the start (no inverse-kinematics solution)",
                )
            return np.asarray(solutions[0])
        try:
            return np.asarray(arm.follow([pose], q_reference)[0])
        except RuntimeError as error:
            raise self.fail(
                key_path, "the arm cannot reach this pose within its joint limits (no inverse-kinematics solution)"
            ) from error
        except ValueError as error:
            raise self.fail(key_path, str(error)) from error

    def ptp(
        self, job: Dict[str, Any], at: KeyPath, current: Pose, q_current: Optional[np.ndarray]
    ) -> Tuple[np.ndarray, np.ndarray, Pose]:
        """(q_a, q_b, end pose) of a PTP move: the target as joints (radians / metres) or as a
        pose (the IK solution nearest to the joints at the move's start)."""
        if job.get("hexapod") is not None:
            raise self.fail(
                at + ("ptp",),
                "PTP moves are planned for serial arms only: dispkin has no DISP bound for a "
                "straight line in a hexapod's leg space yet. Use a lin move (the platform on a line; the legs "
                "follow by inverse kinematics).",
            )
        arm = job.get("arm")
        if arm is None:
            raise self.fail(at + ("ptp",), "a PTP move moves joints: it needs machine.serial_arm")
        q_a = self.joints_at(arm, at, current, q_current)
        ptp = value_at(self.data, at + ("ptp",))
        if "joints" in ptp:
            q_b = self.ptp_joints(arm, at + ("ptp", "joints"), ptp["joints"])
        else:
            target = self.pose(at + ("ptp", "to"), job["frames"])
            q_b = self.joints_at(arm, at + ("ptp", "to"), target, q_a)
        if np.array_equal(q_a, q_b):
            raise self.fail(at + ("ptp",), "the target equals the joints at the move's start: a PTP move must move")
        return q_a, q_b, arm.forward(q_b)

    def ptp_joints(self, arm: Any, at: KeyPath, joints: List[float]) -> np.ndarray:
        """A PTP target given as joints: one value per joint, each inside its position limits."""
        q_b = np.asarray(joints, dtype=float)
        if q_b.size != arm.dof:
            raise self.fail(
                at,
                f"{tuple(q_b.tolist())}: expected {arm.dof} joint values ({', '.join(arm.joint_names)}), got {q_b.size}",
            )
        limits = arm.joint_limits
        for k in range(arm.dof):
            if not limits.lower[k] <= q_b[k] <= limits.upper[k]:
                raise self.fail(
                    at + (k,),
                    f"{q_b[k]!r}: outside the position limits [{limits.lower[k]:g}, {limits.upper[k]:g}] of joint {arm.joint_names[k]!r}",
                )
        return q_b

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
    path_, moves, parts = builder.moves(job, start)
    limits, profile = builder.limits(pilz)
    read_retime(builder, job)
    builder.moved_redundancy(job, parts)
    read_events(builder, job, parts)
    job["corner_tolerance"] = builder.corner_tolerance()
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
