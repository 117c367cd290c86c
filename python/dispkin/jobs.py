"""Job files: a planning job in YAML, validated against ``job.schema.json`` (shipped with the
package), built into the library's objects, planned and sampled.

``load_job(path)`` reads and validates a job and builds its machine, frames, metric set, path
and limits (a :class:`Job`); ``plan_job(job)`` plans it; ``sample_job(job, trajectory)`` samples
the trajectory into joint values (hexapod legs, serial-arm joints) and poses (a
:class:`JobSamples`); :mod:`dispkin.cli` writes these as CSV, JSON and a summary.

Every mistake in a job raises :class:`JobError` (a ValueError) whose message starts with
``FILE:LINE:COLUMN: key.path[index]: `` — the offending key, and where it is in the file.
"""

import dataclasses
import json
import math
import pathlib
import re
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._core import Hexapod, JointPath, Limits, MetricSet, Path, Pose, Trajectory, WorkToolFrames, max_point_speed, plan
from . import shapes

#: The JSON Schema of job files (draft 2020-12), shipped next to this module.
SCHEMA_PATH = pathlib.Path(__file__).resolve().with_name("job.schema.json")
#: Default sample period of the output (s).
DEFAULT_SAMPLE_PERIOD = 0.01
#: Time step (s) of the central differences that give joint accelerations from joint velocities.
ACCELERATION_STEP = 1e-4

KeyPath = Tuple[Union[str, int], ...]


class JobError(ValueError):
    """A job file that cannot be read, validated, built or planned; the message points at the
    offending key (``key.path[index]``) and, when known, its line and column in the file."""

    def __init__(self, message: str, key_path: KeyPath = (), line: Optional[int] = None):
        super().__init__(message)
        #: The offending key as a tuple of mapping keys and list indices (empty: the whole job).
        self.key_path = tuple(key_path)
        #: 1-based line of the key in the job file, when known.
        self.line = line


def format_key_path(key_path: Sequence[Union[str, int]]) -> str:
    """``('moves', 2, 'lin', 'to')`` -> ``moves[2].lin.to``; the empty path is ``(job)``."""
    text = ""
    for key in key_path:
        text += f"[{key}]" if isinstance(key, int) else (f".{key}" if text else str(key))
    return text or "(job)"


# --- reading YAML with line numbers ---------------------------------------------------------

try:
    import yaml
except ImportError as error:  # pragma: no cover - pyyaml is a dependency of the package
    raise ImportError("dispkin job files need PyYAML (pip install pyyaml)") from error


class _Loader(yaml.SafeLoader):
    """The safe loader, with YAML 1.2 floats: ``1e-3`` is a number, not the string '1e-3'."""


_Loader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:float"]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(
        r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+]?[0-9]+)?
            |[-+]?(?:[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)
            |[-+]?\.[0-9_]+(?:[eE][-+]?[0-9]+)?
            |[-+]?\.(?:inf|Inf|INF)
            |\.(?:nan|NaN|NAN))$""",
        re.X,
    ),
    list("-+0123456789."),
)


class _Source:
    """A job file's text, its data, and where each key path is (1-based line, column)."""

    def __init__(self, path: pathlib.Path):
        self.path = path
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as error:
            raise JobError(f"{path}: cannot read the job file: {error.strerror or error}") from error
        except UnicodeDecodeError as error:
            raise JobError(f"{path}: not a UTF-8 text file: {error}") from error
        self.marks: Dict[Tuple[str, ...], Tuple[int, int]] = {}
        try:
            # The reader checks for non-printable characters when it is made: inside the try.
            loader = _Loader(text)
        except yaml.reader.ReaderError as error:  # a control character: where, from its position
            before = text[: error.position]
            line, column = before.count("\n") + 1, len(before) - (before.rfind("\n") + 1) + 1
            raise JobError(f"{path}:{line}:{column}: not valid YAML: {error.reason} (character #x{error.character:04x})",
                           (), line) from error
        try:
            node = loader.get_single_node()
            if node is None:
                raise JobError(f"{path}: the job file is empty")
            self._walk(node, ())
            self.data = loader.construct_document(node)
        except yaml.MarkedYAMLError as error:
            mark = error.problem_mark or error.context_mark
            where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark else str(path)
            raise JobError(f"{where}: not valid YAML: {error.problem or error}", (), mark.line + 1 if mark else None) from error
        except yaml.YAMLError as error:
            raise JobError(f"{path}: not valid YAML: {error}") from error
        finally:
            loader.dispose()

    def _walk(self, node: Any, key_path: Tuple[str, ...]) -> None:
        self.marks.setdefault(key_path, (node.start_mark.line + 1, node.start_mark.column + 1))
        if isinstance(node, yaml.MappingNode):
            seen = set()
            for key_node, value_node in node.value:
                key = str(key_node.value)
                if key in seen:  # PyYAML would silently keep the last one
                    line, column = key_node.start_mark.line + 1, key_node.start_mark.column + 1
                    where = format_key_path(self._typed(key_path + (key,)))
                    raise JobError(f"{self.path}:{line}:{column}: {where}: duplicate key", key_path + (key,), line)
                seen.add(key)
                self.marks[key_path + (key,)] = (key_node.start_mark.line + 1, key_node.start_mark.column + 1)
                self._walk(value_node, key_path + (key,))
        elif isinstance(node, yaml.SequenceNode):
            for i, item in enumerate(node.value):
                self._walk(item, key_path + (str(i),))

    @staticmethod
    def _typed(key_path: Sequence[str]) -> KeyPath:
        return tuple(int(k) if k.isdigit() else k for k in key_path)

    def mark(self, key_path: Sequence[Union[str, int]]) -> Optional[Tuple[int, int]]:
        """(line, column) of the deepest part of key_path that is in the file."""
        keys = tuple(str(k) for k in key_path)
        while keys not in self.marks and keys:
            keys = keys[:-1]
        return self.marks.get(keys)

    def error(self, key_path: Sequence[Union[str, int]], message: str) -> JobError:
        """A JobError ``FILE:LINE:COLUMN: key.path: message``."""
        mark = self.mark(key_path)
        where = f"{self.path}:{mark[0]}:{mark[1]}" if mark else str(self.path)
        return JobError(f"{where}: {format_key_path(key_path)}: {message}", tuple(key_path), mark[0] if mark else None)


# --- validation ------------------------------------------------------------------------------


def load_schema() -> Dict[str, Any]:
    """The job-file JSON Schema as a dict."""
    return json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))


def _alternatives(schema: Dict[str, Any]) -> str:
    """The key sets of a oneOf whose branches each require keys, e.g. "`a` | `b` + `c`"."""
    options = ["`" + "` + `".join(branch.get("required", [])) + "`" for branch in schema.get("oneOf", [])]
    return " | ".join(options)


def _schema_error_message(error: Any) -> Tuple[KeyPath, str]:
    """The key path and a message for one jsonschema ValidationError."""
    key_path: KeyPath = tuple(error.absolute_path)
    if error.validator == "additionalProperties" and isinstance(error.instance, dict):
        allowed = set(error.schema.get("properties", {}))
        extra = sorted((k for k in error.instance if k not in allowed), key=str)  # YAML keys may be numbers
        if extra:
            known = ", ".join(sorted(allowed))
            return key_path + (str(extra[0]),), f"unknown key (allowed here: {known})"
    if error.validator == "oneOf" and isinstance(error.instance, dict):
        present = ", ".join(f"`{k}`" for k in error.instance) or "nothing"
        return key_path, f"expected exactly one of {_alternatives(error.schema)}; found {present}"
    if error.validator in ("minProperties", "maxProperties") and isinstance(error.instance, dict):
        choices = ", ".join(f"`{k}`" for k in error.schema.get("properties", {}))
        return key_path, f"expected exactly one of {choices}; found {len(error.instance)} key(s)"
    if error.validator == "required":
        missing = re.match(r"'([^']*)'", error.message)
        return key_path, f"missing required key `{missing.group(1) if missing else error.message}`"
    if error.validator == "enum":
        return key_path, f"{error.instance!r} is not one of {', '.join(repr(v) for v in error.validator_value)}"
    if error.validator in ("minItems", "maxItems") and isinstance(error.instance, list):
        bound = "at least" if error.validator == "minItems" else "at most"
        return key_path, f"expected {bound} {error.validator_value} item(s), got {len(error.instance)}"
    return key_path, error.message


def _non_finite(value: Any, key_path: KeyPath) -> Optional[KeyPath]:
    """The first key path under value holding NaN or an infinity."""
    if isinstance(value, float) and not math.isfinite(value):
        return key_path
    if isinstance(value, dict):
        for k, v in value.items():
            found = _non_finite(v, key_path + (k,))
            if found is not None:
                return found
    if isinstance(value, list):
        for i, v in enumerate(value):
            found = _non_finite(v, key_path + (i,))
            if found is not None:
                return found
    return None


def _lookup(data: Any, key_path: KeyPath) -> Any:
    for key in key_path:
        data = data[key]
    return data


def validate(source: _Source) -> None:
    """Raise a JobError for every schema violation (all of them, in file order, in one message)."""
    import jsonschema

    if not isinstance(source.data, dict):
        raise source.error((), f"a job is a mapping of keys (machine, metric_set, moves, limits, ...), got {type(source.data).__name__}")
    bad = _non_finite(source.data, ())
    if bad is not None:
        raise source.error(bad, f"{_lookup(source.data, bad)!r}: must be finite")
    validator = jsonschema.Draft202012Validator(load_schema())
    errors = []
    for error in validator.iter_errors(source.data):
        key_path, message = _schema_error_message(error)
        errors.append((source.mark(key_path) or (0, 0), key_path, message))
    if errors:
        errors.sort(key=lambda e: e[0])
        first = source.error(errors[0][1], errors[0][2])
        rest = [str(source.error(k, m)) for _, k, m in errors[1:]]
        raise JobError("\n".join([str(first)] + rest), first.key_path, first.line)


# --- building ----------------------------------------------------------------------------------


@dataclasses.dataclass
class Move:
    """One move of a job as built: its kind, its Path (a JointPath for a PTP move), the blend
    with the previous move (m)."""

    kind: str
    path: Union[Path, JointPath]
    blend: Optional[float]


@dataclasses.dataclass
class Part:
    """A stretch of a job planned as one: a run of Cartesian moves (lin, circ, spline) joined
    into one Path, or one PTP move (a JointPath, at rest at both ends)."""

    #: "path" or "ptp".
    kind: str
    path: Union[Path, JointPath]
    #: The arm's joints at the part's start (serial-arm jobs; None otherwise).
    q_start: Optional[np.ndarray]
    #: Indices of its moves in Job.moves.
    moves: List[int]


@dataclasses.dataclass
class Job:
    """A validated job, built into the library's objects (see :func:`load_job`)."""

    #: The job file.
    file: pathlib.Path
    #: The job's name (default: the file's stem).
    name: str
    #: The points whose speed is limited, including a hexapod's leg group (rule (a)).
    metric_set: MetricSet
    #: The moves joined into one path (platform / flange poses in base coordinates); None when
    #: the job has PTP moves (then see `parts`).
    path: Optional[Path]
    #: The moves one by one.
    moves: List[Move]
    limits: Limits
    #: "scurve" or "trapezoid".
    profile: str
    #: The point of the platform/flange (its coordinates, m) that moves on lines and arcs.
    pivot: np.ndarray
    frames: Optional[WorkToolFrames] = None
    hexapod: Optional[Hexapod] = None
    #: Rule (b): plan with the hexapod as joint metric.
    joint_metric: bool = False
    #: Rule (a): the metric-set group holding the upper leg joints to the leg speed.
    leg_speed_group: Optional[int] = None
    arm: Optional[Any] = None
    q_start: Optional[np.ndarray] = None
    #: Output period (s) and file names (relative to the output directory).
    sample_period: float = DEFAULT_SAMPLE_PERIOD
    outputs: Dict[str, str] = dataclasses.field(default_factory=dict)
    #: The job in stretches planned as one: Cartesian runs and PTP moves, in order.
    parts: List[Part] = dataclasses.field(default_factory=list)

    @property
    def has_ptp(self) -> bool:
        """Whether a move is a PTP move (the job is then planned part by part)."""
        return any(part.kind == "ptp" for part in self.parts)

    @property
    def machine(self) -> str:
        """"hexapod", "serial_arm" or "none"."""
        return "hexapod" if self.hexapod is not None else "serial_arm" if self.arm is not None else "none"

    @property
    def joint_names(self) -> List[str]:
        """The joints of the output: the legs, the arm's joints, or none."""
        if self.hexapod is not None:
            return list(self.hexapod.joint_names)
        if self.arm is not None:
            return list(self.arm.joint_names)
        return []


#: The keys of a metric_set.points entry that only a `shape` entry uses.
_SHAPE_PARAMETERS = ("center", "centre", "radius", "size", "subdivisions", "count", "circumscribed")


class _Builder:
    """Turns validated job data into library objects; every error names its key path."""

    def __init__(self, source: _Source):
        self.source = source
        self.data = source.data
        self.directory = source.path.resolve().parent

    def fail(self, key_path: KeyPath, message: str) -> JobError:
        return self.source.error(key_path, message)

    def call(self, key_path: KeyPath, function: Any, *args: Any, **kwargs: Any) -> Any:
        """function(*args, **kwargs), its ValueError / RuntimeError re-raised at key_path."""
        try:
            return function(*args, **kwargs)
        except JobError:
            raise
        except (ValueError, RuntimeError) as error:
            raise self.fail(key_path, str(error)) from error

    def file(self, key_path: KeyPath) -> pathlib.Path:
        path = pathlib.Path(_lookup(self.data, key_path))
        path = path if path.is_absolute() else self.directory / path
        if not path.is_file():
            raise self.fail(key_path, f"file {str(path)!r} does not exist")
        return path

    # Poses ---------------------------------------------------------------------------------

    def raw_pose(self, key_path: KeyPath) -> Pose:
        """A pose as written: XYZUVW (m, degrees) or quaternion + translation."""
        d = _lookup(self.data, key_path)
        if "xyzuvw" in d:
            x = list(map(float, d["xyzuvw"]))
            return self.call(key_path + ("xyzuvw",), Pose.from_xyzuvw, x[:3] + [math.radians(a) for a in x[3:]])
        q = np.asarray(d["quaternion"], dtype=float)
        norm = float(np.linalg.norm(q))
        if abs(norm - 1.0) > 1e-6:  # no silent normalisation of a mistyped quaternion
            raise self.fail(key_path + ("quaternion",), f"{tuple(q.tolist())}: must be a unit quaternion (w, x, y, z), norm is {norm:.9g}")
        return self.call(key_path, Pose, q / norm, d["translation"])

    def pose(self, key_path: KeyPath, frames: Optional[WorkToolFrames]) -> Pose:
        """A commanded pose as the platform/flange pose: with frames, the job's pose is the tool
        frame in the work frame."""
        pose = self.raw_pose(key_path)
        return frames.platform_pose(pose) if frames is not None else pose

    # Sections of the job ---------------------------------------------------------------------

    def machine(self, job: Dict[str, Any]) -> None:
        machine = self.data.get("machine")
        if not machine:
            return
        if "hexapod" in machine:
            h = machine["hexapod"]
            at: KeyPath = ("machine", "hexapod")
            if "file" in h:
                job["hexapod"] = self.call(at + ("file",), Hexapod.load, str(self.file(at + ("file",))))
            elif "description" in h:
                job["hexapod"] = self.call(at + ("description",), Hexapod.from_json, json.dumps(h["description"]))
            else:
                s = dict(h["symmetric"])
                for angle in ("base_gap", "platform_gap"):
                    s[angle] = math.radians(s[angle])
                job["hexapod"] = self.call(at + ("symmetric",), Hexapod.symmetric, **s)
            job["joint_metric"] = bool(h.get("joint_metric", False))
        else:
            if not hasattr(_core, "SerialArm"):
                raise self.fail(("machine", "serial_arm"), "this build of dispkin has no serial-arm plugin (DISPKIN_BUILD_SERIAL=OFF)")
            a = machine["serial_arm"]
            at = ("machine", "serial_arm")
            urdf = self.file(at + ("urdf",))
            arm = self.call(at, _core.SerialArm.from_urdf, str(urdf), a["base_link"], a["tip_link"])
            q_start = np.asarray(a["q_start"], dtype=float)
            if q_start.size != arm.dof:
                raise self.fail(at + ("q_start",), f"{tuple(q_start.tolist())}: expected {arm.dof} joint values ({', '.join(arm.joint_names)}), got {q_start.size}")
            job["arm"], job["q_start"] = arm, q_start

    def frames(self, job: Dict[str, Any]) -> None:
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

    def metric_set(self, job: Dict[str, Any]) -> MetricSet:
        m = self.data["metric_set"]
        metric_set = MetricSet()
        for i, entry in enumerate(m.get("points", [])):
            at: KeyPath = ("metric_set", "points", i)
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
        populated = set(metric_set.groups)  # set_group_speed adds the group even without points
        groups_seen = set()
        for i, g in enumerate(m.get("groups", [])):
            if g["group"] not in populated:
                raise self.fail(("metric_set", "groups", i, "group"), f"{g['group']}: no points belong to this group")
            if g["group"] in groups_seen:
                raise self.fail(("metric_set", "groups", i, "group"), f"{g['group']}: group given twice")
            groups_seen.add(g["group"])
            self.call(("metric_set", "groups", i), metric_set.set_group_speed, g["group"], g["speed"])
        hexapod = job.get("hexapod")
        leg_group = (self.data.get("machine") or {}).get("hexapod", {}).get("leg_speed_group")
        if hexapod is not None and leg_group is not None:
            at = ("machine", "hexapod", "leg_speed_group")
            if leg_group in metric_set.groups:
                raise self.fail(at, f"{leg_group}: the metric set already has group {leg_group}; the legs need a group of their own")
            self.call(at, hexapod.add_leg_speed_group, metric_set, leg_group)
            job["leg_speed_group"] = leg_group
        if metric_set.point_count == 0 and metric_set.sphere_count == 0:
            raise self.fail(("metric_set",), "the metric set has no points: give metric_set.points (or a hexapod leg_speed_group)")
        self.call(("metric_set",), metric_set.require_well_formed)
        return metric_set

    def shape(self, metric_set: MetricSet, entry: Dict[str, Any], at: KeyPath, group: int) -> None:
        kind = entry["shape"]
        # `center` as the API spells it; `centre`, the spelling of earlier job files, still reads.
        if "center" in entry and "centre" in entry:
            raise self.fail(at + ("centre",), "`centre` is an alias of `center`: give one of them, not both")
        center = entry.get("center", entry.get("centre", (0.0, 0.0, 0.0)))
        absolute = bool(entry.get("absolute", False))
        unused = {"icosahedron": ("size", "subdivisions", "count"), "icosphere": ("size", "count", "circumscribed"),
                  "box": ("radius", "subdivisions", "count", "circumscribed"),
                  "sphere": ("size", "subdivisions", "count", "circumscribed"),
                  "spherical_shell": ("size", "subdivisions", "circumscribed")}[kind]
        for key in unused:
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

    def start(self, job: Dict[str, Any]) -> Pose:
        if "start" in self.data:
            return self.pose(("start",), job["frames"])
        if job.get("hexapod") is not None:
            return job["hexapod"].home
        if job.get("arm") is not None:
            return job["arm"].forward(job["q_start"])
        raise self.fail((), "missing required key `start` (only a machine gives a default start pose)")

    def moves(self, job: Dict[str, Any], start: Pose) -> Tuple[Optional[Path], List[Move], List[Part]]:
        frames, pivot = job["frames"], job["pivot"]
        arm = job.get("arm")
        q_current = job.get("q_start")  # serial arm: the joints at `current` are the IK branch nearest to it
        current = start
        built: List[Move] = []
        parts: List[Part] = []
        run: List[Tuple[int, Path, Any, Any]] = []  # the Cartesian moves since the last PTP move

        def close_run() -> None:
            nonlocal q_current
            if not run:
                return
            whole = self.call(("moves", run[0][0], built[run[0][0]].kind), run[0][2], *run[0][3])  # a copy: then() appends in place
            for i, path, _, _ in run[1:]:
                blend = built[i].blend
                self.call(("moves", i, "blend") if blend is not None else ("moves", i), whole.then, path, blend=blend)
            q_run = self.joints_at(arm, ("moves", run[0][0]), whole.start, q_current) if arm is not None else None
            parts.append(Part("path", whole, q_run, [i for i, _, _, _ in run]))
            if arm is not None:  # the joints at the run's end: the branch followed along its geometry
                poses = [Pose.from_matrix(m) for m in np.asarray(whole.sample(np.linspace(0.0, 1.0, 201)))]
                q_current = self.call(("moves", run[-1][0]), arm.follow, poses, q_run)[-1]
            run.clear()

        for i, move in enumerate(self.data["moves"]):
            at: KeyPath = ("moves", i)
            blend = move.get("blend")
            if blend is not None and i == 0:
                raise self.fail(at + ("blend",), f"{blend}: the first move has no previous move to blend with")
            if "ptp" in move:
                if blend is not None:
                    raise self.fail(at + ("blend",), f"{blend}: a PTP move starts and ends at rest; it does not blend with the previous move")
                close_run()
                q_a, q_b, end = self.ptp(job, at, current, q_current)
                path = self.call(at + ("ptp",), Path.ptp, q_a, q_b)
                built.append(Move("ptp", path, None))
                parts.append(Part("ptp", path, q_a, [i]))
                current, q_current = end, q_b
                continue
            if blend is not None and built[-1].kind == "ptp":
                raise self.fail(at + ("blend",), f"{blend}: the previous move is a PTP move, which ends at rest; nothing to blend with")
            if "lin" in move:
                lin = move["lin"]
                if "to" in lin:
                    end = self.pose(at + ("lin", "to"), frames)
                else:
                    end = self.relative_end(current, at + ("lin", "by"), frames)
                constructor, arguments = Path.lin, (current, end, lin.get("interpolation", "decoupled"), pivot)
                kind = "lin"
            elif "circ" in move:
                via = self.pose(at + ("circ", "via"), frames)
                end = self.pose(at + ("circ", "to"), frames)
                constructor, arguments = Path.circ, (current, via, end, pivot)
                kind = "circ"
            else:
                spline = move["spline"]
                through = [self.pose(at + ("spline", "through", k), frames) for k in range(len(spline["through"]))]
                end = self.pose(at + ("spline", "to"), frames)
                constructor, arguments = Path.spline, ([current, *through, end], pivot)
                kind = "spline"
            path = self.call(at + (kind,), constructor, *arguments)
            built.append(Move(kind, path, blend))
            run.append((i, path, constructor, arguments))
            current = end
        close_run()
        whole_path = parts[0].path if len(parts) == 1 and parts[0].kind == "path" else None
        return whole_path, built, parts

    def joints_at(self, arm: Any, key_path: KeyPath, pose: Pose, q_reference: np.ndarray) -> np.ndarray:
        """The arm's joints at `pose`: q_reference itself when it reaches the pose, else the
        inverse-kinematics solution (within the limits) nearest to it."""
        if arm.forward(q_reference).is_approx(pose, 1e-9):
            return np.asarray(q_reference, dtype=float)
        solutions = self.call(key_path, arm.inverse, pose)
        if not solutions:
            raise self.fail(key_path, "the arm cannot reach this pose within its joint limits (no inverse-kinematics solution)")
        return np.asarray(_core.SerialArm.nearest(solutions, q_reference))

    def ptp(self, job: Dict[str, Any], at: KeyPath, current: Pose, q_current: Optional[np.ndarray]) -> Tuple[np.ndarray, np.ndarray, Pose]:
        """(q_a, q_b, end pose) of a PTP move: the target as joints (radians / metres) or as a
        pose (the IK solution nearest to the joints at the move's start)."""
        if job.get("hexapod") is not None:
            raise self.fail(at + ("ptp",), "PTP moves are planned for serial arms only: dispkin has no DISP bound for a "
                            "straight line in a hexapod's leg space yet. Use a lin move (the platform on a line; the legs "
                            "follow by inverse kinematics).")
        arm = job.get("arm")
        if arm is None:
            raise self.fail(at + ("ptp",), "a PTP move moves joints: it needs machine.serial_arm")
        q_a = self.joints_at(arm, at, current, q_current)
        ptp = self.data["moves"][at[1]]["ptp"]
        if "joints" in ptp:
            q_b = np.asarray(ptp["joints"], dtype=float)
            if q_b.size != arm.dof:
                raise self.fail(at + ("ptp", "joints"), f"{tuple(q_b.tolist())}: expected {arm.dof} joint values ({', '.join(arm.joint_names)}), got {q_b.size}")
            limits = arm.joint_limits
            for k in range(arm.dof):
                if not limits.lower[k] <= q_b[k] <= limits.upper[k]:
                    raise self.fail(at + ("ptp", "joints", k), f"{q_b[k]!r}: outside the position limits [{limits.lower[k]:g}, {limits.upper[k]:g}] of joint {arm.joint_names[k]!r}")
        else:
            target = self.pose(at + ("ptp", "to"), job["frames"])
            q_b = self.joints_at(arm, at + ("ptp", "to"), target, q_a)
        if np.array_equal(q_a, q_b):
            raise self.fail(at + ("ptp",), "the target equals the joints at the move's start: a PTP move must move")
        return q_a, q_b, arm.forward(q_b)

    def relative_end(self, current: Pose, key_path: KeyPath, frames: Optional[WorkToolFrames]) -> Pose:
        """`by`: translation added in base (or work) coordinates, rotation about the tool's own axes."""
        delta = self.raw_pose(key_path)
        if frames is None:
            return Pose(quaternion=(current * Pose(quaternion=delta.quaternion)).quaternion,
                        translation=current.translation + delta.translation)
        tool = frames.tool_in_work(current)
        moved = Pose(quaternion=(tool * Pose(quaternion=delta.quaternion)).quaternion, translation=tool.translation + delta.translation)
        return frames.platform_pose(moved)

    def limits(self) -> Tuple[Limits, str]:
        lim = self.data["limits"]
        profile = lim.get("profile", "scurve")
        if profile == "scurve" and "jerk" not in lim:
            raise self.fail(("limits",), "missing key `jerk`: the scurve profile (the default) needs a jerk limit; give one or set profile: trapezoid")
        return self.call(("limits",), Limits, lim["velocity"], lim["acceleration"], lim.get("jerk")), profile

    def output(self, job: Dict[str, Any], name: str) -> None:
        out = self.data.get("output") or {}
        job["sample_period"] = float(out.get("sample_period", DEFAULT_SAMPLE_PERIOD))
        files = {"csv": f"{name}.csv", "json": f"{name}.json", "summary": f"{name}.summary.txt"}
        for key in files:
            if key in out:
                if pathlib.PurePath(out[key]).name != out[key]:
                    raise self.fail(("output", key), f"{out[key]!r}: a file name, not a path (the directory is `-o OUTDIR`)")
                files[key] = out[key]
        job["outputs"] = files


def load_job(path: Union[str, pathlib.Path]) -> Job:
    """Read, validate and build the job file at `path` (see the module docstring); raises
    JobError pointing at the offending key and line."""
    source = _Source(pathlib.Path(path))
    validate(source)
    builder = _Builder(source)
    name = source.data.get("name") or source.path.stem
    safe_name = re.sub(r"[^A-Za-z0-9_.-]+", "_", name)
    job: Dict[str, Any] = {}
    builder.machine(job)
    builder.frames(job)
    metric_set = builder.metric_set(job)
    start = builder.start(job)
    path_, moves, parts = builder.moves(job, start)
    limits, profile = builder.limits()
    builder.output(job, safe_name)
    return Job(file=source.path, name=name, metric_set=metric_set, path=path_, moves=moves, limits=limits,
               profile=profile, parts=parts, **job)


# --- planning and sampling ---------------------------------------------------------------------


class JobTrajectory:
    """A job's trajectory when it has PTP moves: its parts (Cartesian runs planned as one
    Trajectory, PTP moves as a JointTrajectory) one after the other in time; every PTP move
    starts and ends at rest, so the parts join at rest. Samples like a Trajectory (poses, body
    twists, s-dot; s counts on across the parts)."""

    def __init__(self, parts: List[Tuple[Part, Any]]):
        #: (Part, its Trajectory or JointTrajectory), in order.
        self.parts = parts
        durations = [float(t.duration) for _, t in parts]
        #: When each part starts (s).
        self.start_times = np.concatenate([[0.0], np.cumsum(durations)[:-1]])
        lengths = [float(t.length) for _, t in parts]
        self._start_s = np.concatenate([[0.0], np.cumsum(lengths)[:-1]])
        #: Seconds.
        self.duration = float(np.sum(durations))
        #: The DISP arc length of all parts, m.
        self.length = float(np.sum(lengths))
        #: Rest-to-rest pieces: a Cartesian run's own, one per PTP move.
        self.piece_count = int(sum(t.piece_count if p.kind == "path" else 1 for p, t in parts))

    def part_indices(self, times: np.ndarray) -> np.ndarray:
        """The part each time belongs to (a time on a junction: the later part, both at rest there)."""
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)), 0.0, self.duration)
        return np.clip(np.searchsorted(self.start_times, t, side="right") - 1, 0, len(self.parts) - 1)

    def _gather(self, times: Any, method: str, tail: Tuple[int, ...]) -> np.ndarray:
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)), 0.0, self.duration)
        which = self.part_indices(t)
        out = np.zeros((len(t),) + tail)
        for k, (_, traj) in enumerate(self.parts):
            mask = which == k
            if np.any(mask):
                out[mask] = np.asarray(getattr(traj, method)(t[mask] - self.start_times[k])).reshape((-1,) + tail)
        return out

    def sample(self, times: Any) -> np.ndarray:
        """Poses at `times`, (N, 4, 4)."""
        return self._gather(times, "sample", (4, 4))

    def sample_xyzuvw(self, times: Any) -> np.ndarray:
        """Poses at `times`, (N, 6) XYZUVW (m, radians)."""
        return self._gather(times, "sample_xyzuvw", (6,))

    def body_twist(self, times: Any) -> np.ndarray:
        """Body twists (v, omega) at `times`, (N, 6)."""
        return self._gather(times, "body_twist", (6,))

    def path_velocity(self, times: Any) -> np.ndarray:
        """s-dot at `times`, (N,), m/s."""
        return self._gather(times, "path_velocity", ())

    def path_position(self, times: Any) -> np.ndarray:
        """s at `times`, (N,), m, counted from the job's start."""
        t = np.atleast_1d(np.asarray(times, dtype=float))
        return self._gather(t, "path_position", ()) + self._start_s[self.part_indices(t)]


def plan_job(job: Job) -> Union[Trajectory, JobTrajectory]:
    """The job's trajectory: plan(job.path, job.metric_set, job.limits, job.profile), with the
    hexapod as joint metric when the job asks for rule (b). A job with PTP moves is planned
    part by part (a JobTrajectory): each Cartesian run as one path, each PTP move on the arm."""
    joint_metric = job.hexapod if job.joint_metric else None
    try:
        if not job.has_ptp:
            return plan(job.path, job.metric_set, job.limits, job.profile, joint_metric=joint_metric)
        planned = []
        for part in job.parts:
            if part.kind == "ptp":
                planned.append((part, plan(part.path, job.metric_set, job.limits, job.profile, robot=job.arm)))
            else:
                planned.append((part, plan(part.path, job.metric_set, job.limits, job.profile, joint_metric=joint_metric)))
        return JobTrajectory(planned)
    except (ValueError, RuntimeError) as error:
        raise JobError(f"{job.file}: planning failed: {error}") from error


def sample_times(duration: float, period: float) -> np.ndarray:
    """0, period, 2 period, ... and the end `duration` itself (a last gap shorter than
    period / 1000 is merged into the end)."""
    count = int(math.floor(duration / period + 1e-9))
    times = np.arange(count + 1) * period
    if duration - times[-1] > period * 1e-3:
        times = np.append(times, duration)
    else:
        times[-1] = duration
    return times


@dataclasses.dataclass
class JobSamples:
    """The sampled trajectory of a job, row k at time[k]. Joint arrays are (N, dof) and empty
    (N, 0) without a machine; effort is (N, 0) for hexapods (no leg dynamics in the model)."""

    time: np.ndarray
    joint_names: List[str]
    #: Leg lengths (m) or joint values (rad / m).
    positions: np.ndarray
    #: Their time derivatives: analytic (leg Jacobian / body Jacobian times the body twist).
    velocities: np.ndarray
    #: Central differences of the analytic velocities over ACCELERATION_STEP.
    accelerations: np.ndarray
    #: Joint torques / forces (N·m, N) by recursive Newton–Euler for serial arms.
    effort: np.ndarray
    #: XYZUVW of the commanded pose (the tool frame in the work frame with frames, else the
    #: platform/flange pose): metres and DEGREES.
    xyzuvw: np.ndarray
    #: Path velocity s-dot (m/s).
    path_velocity: np.ndarray
    #: Speed of the fastest point of the whole metric set (m/s, not scaled by group limits).
    fastest_point_speed: np.ndarray
    #: Per group: the speed of its fastest point (m/s).
    group_speeds: Dict[int, np.ndarray]


def group_sets(metric_set: MetricSet) -> Dict[int, MetricSet]:
    """Each group of the metric set on its own (group 0 in each, no speed limit)."""
    out = {}
    for group in metric_set.groups:
        one = MetricSet()
        relative, absolute = metric_set.relative_points(group), metric_set.absolute_points(group)
        if len(relative):
            one.add_relative(relative)
        if len(absolute):
            one.add_absolute(absolute)
        for center, radius, is_absolute in metric_set.spheres(group):
            one.add_sphere(center, radius, is_absolute)
        out[group] = one
    return out


def _joint_velocities(job: Job, poses: np.ndarray, twists: np.ndarray, q: np.ndarray) -> np.ndarray:
    if job.hexapod is not None:
        return np.array([job.hexapod.leg_jacobian(m) @ xi for m, xi in zip(poses, twists)])
    # Body twist = J_body(q) q-dot; least squares also covers arms with fewer than 6 joints.
    return np.array([np.linalg.lstsq(job.arm.body_jacobian(qk), xi, rcond=None)[0] for qk, xi in zip(q, twists)])


def _joint_positions(job: Job, poses: np.ndarray, q_reference: np.ndarray) -> np.ndarray:
    if job.hexapod is not None:
        return np.asarray(job.hexapod.inverse(poses))
    try:
        return np.asarray(job.arm.follow([Pose.from_matrix(m) for m in poses], q_reference))
    except (ValueError, RuntimeError) as error:
        raise JobError(f"{job.file}: the serial arm cannot follow the trajectory: {error}") from error


def _cartesian_joint_states(job: Job, trajectory: Trajectory, t: np.ndarray, q_reference: Optional[np.ndarray]) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Joint positions, velocities and accelerations along a Cartesian trajectory at `t`."""
    poses, twists = np.asarray(trajectory.sample(t)), np.asarray(trajectory.body_twist(t))
    n = len(t)
    positions = _joint_positions(job, poses, q_reference)
    velocities = _joint_velocities(job, poses, twists, positions)
    # Accelerations: central differences of the analytic velocity, one-sided at the ends.
    before, after = np.maximum(t - ACCELERATION_STEP, 0.0), np.minimum(t + ACCELERATION_STEP, trajectory.duration)
    rates = []
    for times in (before, after):
        p, xi = np.asarray(trajectory.sample(times)), np.asarray(trajectory.body_twist(times))
        q = None
        if job.arm is not None:  # the same branch: each neighbour follows from its sample
            q = np.array([_joint_positions(job, p[k : k + 1], positions[k])[0] for k in range(n)])
        rates.append(_joint_velocities(job, p, xi, q))
    accelerations = (rates[1] - rates[0]) / (after - before)[:, None]
    return positions, velocities, accelerations


def sample_job(job: Job, trajectory: Union[Trajectory, JobTrajectory], period: Optional[float] = None) -> JobSamples:
    """Sample the job's trajectory every `period` seconds (default: the job's sample_period).
    PTP moves give their joints directly (q, q-dot, q-double-dot of the joint line); Cartesian
    moves follow the inverse-kinematics branch continuous from the joints at their start."""
    t = sample_times(trajectory.duration, period or job.sample_period)
    poses, twists = np.asarray(trajectory.sample(t)), np.asarray(trajectory.body_twist(t))
    n = len(t)
    if job.machine == "none":
        empty = np.zeros((n, 0))
        positions = velocities = accelerations = effort = empty
    else:
        if isinstance(trajectory, JobTrajectory):
            dof = job.arm.dof
            positions, velocities, accelerations = np.zeros((n, dof)), np.zeros((n, dof)), np.zeros((n, dof))
            which = trajectory.part_indices(t)
            for k, (part, traj) in enumerate(trajectory.parts):
                mask = which == k
                if not np.any(mask):
                    continue
                local = np.clip(t[mask] - trajectory.start_times[k], 0.0, traj.duration)
                if part.kind == "ptp":
                    states = (traj.joint_positions(local), traj.joint_velocities(local), traj.joint_accelerations(local))
                else:
                    states = _cartesian_joint_states(job, traj, local, part.q_start)
                positions[mask], velocities[mask], accelerations[mask] = states
        else:
            positions, velocities, accelerations = _cartesian_joint_states(job, trajectory, t, job.q_start if job.arm is not None else None)
        if job.arm is not None:
            effort = np.array([job.arm.torques(q, qd, qdd) for q, qd, qdd in zip(positions, velocities, accelerations)])
        else:
            effort = np.zeros((n, 0))
    if job.frames is not None:
        xyzuvw = np.array([job.frames.xyzuvw(Pose.from_matrix(m)) for m in poses])
    else:
        xyzuvw = np.array([Pose.from_matrix(m).to_xyzuvw() for m in poses])
    xyzuvw[:, 3:] = np.degrees(xyzuvw[:, 3:])
    group_speeds = {}
    for group, one in group_sets(job.metric_set).items():
        group_speeds[group] = np.array([max_point_speed(one, Pose.from_matrix(m), xi) for m, xi in zip(poses, twists)])
    fastest = np.max(np.vstack(list(group_speeds.values())), axis=0)
    return JobSamples(t, job.joint_names, positions, velocities, accelerations, effort, xyzuvw,
                      np.asarray(trajectory.path_velocity(t)), fastest, group_speeds)


# --- summary and files -------------------------------------------------------------------------

#: A limit counts as binding when the trajectory reaches this fraction of it.
BINDING_FRACTION = 0.99


def summarize(job: Job, trajectory: Trajectory, samples: JobSamples) -> Dict[str, Any]:
    """Duration, per-group peak point speed against its limit, the machine's own limits, and
    which limit binds (the highest ratio peak / limit, if it reaches BINDING_FRACTION)."""
    v = job.limits.velocity
    ratios: Dict[str, float] = {}
    groups = {}
    for group, speeds in samples.group_speeds.items():
        limit = job.metric_set.group_speed(group) or v
        k = int(np.argmax(speeds))
        groups[str(group)] = {"peak_speed": float(speeds[k]), "time": float(samples.time[k]), "limit": float(limit),
                              "ratio": float(speeds[k] / limit)}
        ratios[f"speed of group {group} ({limit:g} m/s)"] = float(speeds[k] / limit)
    summary: Dict[str, Any] = {
        "job": job.name,
        "machine": job.machine,
        "moves": [m.kind + (f" (blend {m.blend:g} m)" if m.blend else "") for m in job.moves],
        "duration": float(trajectory.duration),
        "length": float(trajectory.length),
        "rest_to_rest_pieces": int(trajectory.piece_count),
        "profile": job.profile,
        "limits": {"velocity": v, "acceleration": job.limits.acceleration, "jerk": job.limits.jerk},
        "sample_period": float(job.sample_period),
        "samples": int(len(samples.time)),
        "peak_path_velocity": float(np.max(samples.path_velocity)),
        "groups": groups,
    }
    if job.hexapod is not None:
        check = job.hexapod.check_trajectory(trajectory, min(job.sample_period, 1e-3))
        leg_ratio = float(np.max(check.max_speed / job.hexapod.leg_speed))
        summary["legs"] = {"min_length": check.min_length.tolist(), "max_length": check.max_length.tolist(),
                           "max_speed": check.max_speed.tolist(), "leg_speed": job.hexapod.leg_speed.tolist(),
                           "within_limits": bool(check.ok)}
        ratios["leg speed"] = leg_ratio
    if job.arm is not None:
        if isinstance(trajectory, JobTrajectory):
            summary["joints"] = _joint_report_of_parts(job, trajectory)
        else:
            report = _core.check_joint_limits(trajectory, job.arm, job.q_start)
            summary["joints"] = {"velocity_factor": float(report.velocity_factor),
                                 "acceleration_factor": float(report.acceleration_factor),
                                 "position_excess": float(report.position_excess),
                                 "within_limits": bool(report.within_limits)}
        ratios["joint velocity (URDF)"] = summary["joints"]["velocity_factor"]
        ratios["joint effort (URDF)"] = summary["joints"]["acceleration_factor"]
    name, ratio = max(ratios.items(), key=lambda item: item[1])
    summary["binding"] = name if ratio >= BINDING_FRACTION else (
        "acceleration / jerk of the path (no speed limit is reached: the moves are too short to cruise)")
    summary["highest_ratio"] = {"limit": name, "ratio": ratio}
    return summary


def _joint_report_of_parts(job: Job, trajectory: JobTrajectory) -> Dict[str, Any]:
    """The seed's factors over a job with PTP moves: check_joint_limits on each Cartesian run
    (from the joints at its start); for a PTP move FVEL = max |q-dot_i| / q-dot-max_i and FACC =
    max |tau_dyn,i| / (tau-max_i - |tau_sta,i|) at 1 ms samples of its joint line (which stays
    inside the position limits: both ends do, and the range is a box)."""
    arm = job.arm
    limits = arm.joint_limits
    velocity_factor = acceleration_factor = position_excess = 0.0
    for part, traj in trajectory.parts:
        if part.kind == "path":
            report = _core.check_joint_limits(traj, arm, part.q_start)
            velocity_factor = max(velocity_factor, float(report.velocity_factor))
            acceleration_factor = max(acceleration_factor, float(report.acceleration_factor))
            position_excess = max(position_excess, float(report.position_excess))
            continue
        t = np.linspace(0.0, traj.duration, max(2, int(math.ceil(traj.duration / 1e-3)) + 1))
        q, qd, qdd = traj.joint_positions(t), traj.joint_velocities(t), traj.joint_accelerations(t)
        stated = np.isfinite(limits.velocity)
        if np.any(stated):
            velocity_factor = max(velocity_factor, float(np.max(np.abs(qd[:, stated]) / limits.velocity[stated])))
        if len(limits.effort) and np.any(np.isfinite(limits.effort)):
            effort = np.asarray(limits.effort)
            for qk, qdk, qddk in zip(q, qd, qdd):
                static = np.asarray(arm.static_torques(qk))
                dynamic = np.asarray(arm.torques(qk, qdk, qddk)) - static
                room = effort - np.abs(static)
                finite = np.isfinite(effort)
                acceleration_factor = max(acceleration_factor, float(np.max(np.abs(dynamic[finite]) / room[finite])))
    return {"velocity_factor": velocity_factor, "acceleration_factor": acceleration_factor,
            "position_excess": position_excess,
            "within_limits": bool(velocity_factor <= 1.0 and acceleration_factor <= 1.0 and position_excess == 0.0)}


def summary_text(summary: Dict[str, Any]) -> str:
    """The summary as lines of text (what `dispkin plan` prints)."""
    s = summary
    lim = s["limits"]
    jerk = f", j = {lim['jerk']:g} m/s³" if lim["jerk"] is not None else ""
    lines = [
        f"job {s['job']}: {len(s['moves'])} move(s) ({', '.join(s['moves'])}), machine: {s['machine']}",
        f"  duration {s['duration']:.4f} s, {s['rest_to_rest_pieces']} rest-to-rest piece(s), path length {s['length']:.6f} m",
        f"  limits: v = {lim['velocity']:g} m/s, a = {lim['acceleration']:g} m/s²{jerk}, profile {s['profile']}",
        f"  peak path velocity {s['peak_path_velocity']:.6f} m/s ({s['samples']} samples, every {s['sample_period']:g} s)",
    ]
    for group, g in s["groups"].items():
        lines.append(f"  group {group}: peak point speed {g['peak_speed']:.6f} m/s at t = {g['time']:.3f} s, "
                     f"limit {g['limit']:g} m/s ({100 * g['ratio']:.1f} %)")
    if "legs" in s:
        legs = s["legs"]
        lines.append(f"  legs: {1000 * min(legs['min_length']):.3f} .. {1000 * max(legs['max_length']):.3f} mm, fastest "
                     f"{1000 * max(legs['max_speed']):.4f} mm/s (limit {1000 * min(legs['leg_speed']):g} mm/s); "
                     f"within limits: {legs['within_limits']}")
    if "joints" in s:
        j = s["joints"]
        lines.append(f"  joints: velocity factor {j['velocity_factor']:.4f}, effort factor {j['acceleration_factor']:.4f} "
                     f"(<= 1 is within the URDF limits); within limits: {j['within_limits']}")
    lines.append(f"  binding limit: {s['binding']}")
    return "\n".join(lines) + "\n"


def time_from_start(t: float) -> Dict[str, int]:
    """ROS builtin_interfaces/Duration {sec, nanosec} of t seconds (t >= 0)."""
    nanoseconds = int(round(t * 1e9))
    return {"sec": nanoseconds // 1_000_000_000, "nanosec": nanoseconds % 1_000_000_000}


POSE_COLUMNS = ["x_m", "y_m", "z_m", "u_deg", "v_deg", "w_deg"]


def csv_header(samples: JobSamples) -> List[str]:
    """Columns of the CSV file: time, each joint's position / velocity / acceleration / effort,
    the pose as XYZUVW, the path velocity, the fastest point's speed, each group's speed."""
    columns = ["time_s"]
    for kind, array in (("position", samples.positions), ("velocity", samples.velocities),
                        ("acceleration", samples.accelerations), ("effort", samples.effort)):
        if array.shape[1]:
            columns += [f"{name}.{kind}" for name in samples.joint_names]
    columns += POSE_COLUMNS + ["path_velocity_mps", "fastest_point_speed_mps"]
    columns += [f"group_{g}_speed_mps" for g in samples.group_speeds]
    return columns


def write_csv(samples: JobSamples, path: Union[str, pathlib.Path]) -> None:
    """The samples as CSV (header csv_header(samples); floats with 17 significant digits)."""
    table = np.column_stack([samples.time, samples.positions, samples.velocities, samples.accelerations, samples.effort,
                             samples.xyzuvw, samples.path_velocity, samples.fastest_point_speed,
                             *samples.group_speeds.values()])
    np.savetxt(path, table, delimiter=",", header=",".join(csv_header(samples)), comments="", fmt="%.17g")


def trajectory_json(job: Job, samples: JobSamples, summary: Dict[str, Any]) -> Dict[str, Any]:
    """The samples as a dict with the fields of ROS trajectory_msgs/JointTrajectory
    (joint_names, points[].positions/velocities/accelerations/effort/time_from_start), plus
    poses_xyzuvw, path_velocity, fastest_point_speed, group_speeds and the summary."""
    points = []
    for k, t in enumerate(samples.time):
        points.append({"positions": samples.positions[k].tolist(), "velocities": samples.velocities[k].tolist(),
                       "accelerations": samples.accelerations[k].tolist(), "effort": samples.effort[k].tolist(),
                       "time_from_start": time_from_start(float(t))})
    return {
        "joint_names": samples.joint_names,
        "points": points,
        "poses_xyzuvw": samples.xyzuvw.tolist(),
        "pose_units": "x, y, z in m; u, v, w in degrees",
        "pose_frame": "tool frame in the work frame" if job.frames is not None else "platform/flange in base coordinates",
        "time": samples.time.tolist(),
        "path_velocity": samples.path_velocity.tolist(),
        "fastest_point_speed": samples.fastest_point_speed.tolist(),
        "group_speeds": {str(g): s.tolist() for g, s in samples.group_speeds.items()},
        "summary": summary,
    }
