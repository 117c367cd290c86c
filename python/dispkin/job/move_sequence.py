"""The moves of a job (``start``, ``moves``): Cartesian moves in a row joined into one Path and
blended where the job asks, each PTP move a JointPath of its own; on a serial arm the joints at
each part's start are the inverse-kinematics branch followed from ``q_start``. A section of the
job builder (:mod:`.builder`), whose ``fail``, ``call``, ``call_section`` and poses it uses."""

import dataclasses
import functools
import types
from typing import Any, Callable, Dict, List, NamedTuple, Optional, Tuple

import numpy as np

from .. import _core
from .._core import Path, Pose
from .model import KeyPath, Move, Part, value_at
from .planning import plan_run

#: The smallest blend_weight: the blend's ends lie at this share of each move from the corner,
#: and within 1e-6 of a section's end they snap to it (a rotation-vector blend then has nothing
#: to blend; a nested-SLERP blend rounds to no length, or to 10⁵ sections of 1e-20 m).
MIN_BLEND_WEIGHT = 1e-5
#: The smallest blend (m of geometric size), as Path.blended builds no smaller one.
MIN_BLEND = 1e-9

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


class MoveSequence:
    """The start and moves sections of the job builder."""

    data: Dict[str, Any]
    fail: Any
    call: Any
    call_section: Any
    pose: Any
    relative_end: Any
    #: What a Cartesian run is planned under (metric_set, limits, profile, corner_tolerance; set
    #: before the moves are read): a run that moves the redundancy parameter before a PTP move is
    #: planned as it is read.
    run_planning: Dict[str, Any]

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
        on an arm, the joints at its end are the branch followed along its geometry. With the
        redundancy parameter moved, the run is planned as it is read and they are where the planned
        run ends (planned_end): reading the job meets every failure of planning the run."""
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
            if moved:
                moves.q_current = self.planned_end(job, moves.parts[-1], first.index)
        run.clear()

    def planned_end(self, job: Dict[str, Any], part: Part, first: int) -> np.ndarray:
        """The joints where a run that moves the redundancy parameter ends: θ(s) lives on the
        planned path (its sections and lengths, doc/inverse-kinematics.md eqs. 49–50), so the run is
        planned now, as plan_job would plan it (and then takes this plan), and followed as the
        samples follow it (FollowedTrajectory.from_start). A PTP move after it starts there; `dispkin
        check` and `dispkin plan` both read the job, so both meet a failure of this plan."""
        settings = dict(self.run_planning, arm=job["arm"], redundancy_rule=job["redundancy_rule"])
        settings.update(retime=job.get("retime"), hexapod=None, joint_metric=False)
        at: KeyPath = ("moves", first)
        part.trajectory = self.call(at, plan_run, types.SimpleNamespace(**settings), part.path, part.q_start)
        followed = self.call(
            at,
            _core.FollowedTrajectory.from_start,
            part.trajectory,
            job["arm"],
            part.q_start,
            redundancy_rule=job["redundancy_rule"],
        )
        return np.asarray(followed.end, dtype=float)

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
