"""Plots of planned trajectories (matplotlib; ``pip install dispkin[plot]``).

Each function draws into a matplotlib Axes (a new figure when none is given) and returns it,
so it works in notebooks and scripts alike; ``save`` writes a figure to a PNG file.
"""

from typing import Any, Optional, Sequence

import numpy as np

from ._core import Hexapod, MetricSet, Path, Pose, Trajectory, max_point_speed


def _axes(ax: Optional[Any]) -> Any:
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=(7, 3.5), constrained_layout=True)
    return ax


def sample_times(trajectory: Trajectory, step: float = 1e-3) -> np.ndarray:
    """Times from 0 to the trajectory's duration, `step` seconds apart (the end included)."""
    count = max(2, int(np.ceil(trajectory.duration / step)) + 1)
    return np.linspace(0.0, trajectory.duration, count)


def point_speed(
    trajectory: Trajectory,
    metric_set: MetricSet,
    system_velocity: Optional[float] = None,
    step: float = 1e-3,
    ax: Optional[Any] = None,
) -> Any:
    """The path velocity s-dot and the DISP speed of the set over time — the fastest point's
    speed, each group's scaled by system_velocity / its own limit (so that every curve is held
    to the same line) — with the system velocity as a dashed line. `system_velocity` is needed
    when a group has its own limit."""
    ax = _axes(ax)
    t = sample_times(trajectory, step)
    poses, twists = trajectory.sample(t), trajectory.body_twist(t)
    fastest = [max_point_speed(metric_set, Pose.from_matrix(m), xi, system_velocity) for m, xi in zip(poses, twists)]
    ax.plot(t, trajectory.path_velocity(t), label="path velocity ṡ", lw=2, alpha=0.6)
    ax.plot(t, fastest, label="fastest point (group-scaled)", lw=1)
    if system_velocity is not None:
        ax.axhline(system_velocity, color="k", ls="--", lw=1, label="system velocity")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("speed (m/s)")
    ax.legend(loc="lower center")
    return ax


def leg_lengths(hexapod: Hexapod, trajectory: Trajectory, step: float = 1e-3, ax: Optional[Any] = None) -> Any:
    """The six leg lengths over time, with the tightest leg range as dashed lines."""
    ax = _axes(ax)
    t = sample_times(trajectory, step)
    legs = hexapod.inverse(trajectory.sample(t))
    for i in range(6):
        ax.plot(t, legs[:, i] * 1000.0, label=f"leg {i + 1}")
    ax.axhline(float(np.max(hexapod.leg_min)) * 1000.0, color="k", ls="--", lw=1)
    ax.axhline(float(np.min(hexapod.leg_max)) * 1000.0, color="k", ls="--", lw=1)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("leg length (mm)")
    ax.legend(ncol=3, fontsize="small")
    return ax


def joint_limits(
    time: np.ndarray,
    names: Sequence[str],
    positions: np.ndarray,
    velocities: np.ndarray,
    lower: np.ndarray,
    upper: np.ndarray,
    velocity_limits: np.ndarray,
    axes: Optional[Sequence[Any]] = None,
) -> Sequence[Any]:
    """Joints (or hexapod legs) against their limits, on two axes: each joint's position as a
    fraction of its range (0 = lower, 1 = upper; continuous joints, whose range is infinite, are
    left out) and its speed as a fraction of its velocity limit, both with the limits as dashed
    lines. `positions` and `velocities` are (N, dof) arrays over `time` (e.g. from
    dispkin.jobs.sample_job or check_joint_limits' samples). Returns the two axes."""
    if axes is None:
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True, constrained_layout=True)
    ax_position, ax_speed = axes
    for j, name in enumerate(names):
        if np.isfinite(lower[j]) and np.isfinite(upper[j]):
            ax_position.plot(time, (positions[:, j] - lower[j]) / (upper[j] - lower[j]), label=name)
        ax_speed.plot(time, np.abs(velocities[:, j]) / velocity_limits[j], label=name)
    for ax, label in ((ax_position, "position in its range"), (ax_speed, "|speed| / limit")):
        ax.axhline(1.0, color="k", ls="--", lw=1)
        ax.set_ylabel(label)
        ax.legend(ncol=3, fontsize="small")
    ax_position.axhline(0.0, color="k", ls="--", lw=1)
    ax_speed.set_xlabel("time (s)")
    return axes


def path_xy(
    path: Path,
    pivot: Sequence[float] = (0.0, 0.0, 0.0),
    ax: Optional[Any] = None,
    samples: int = 2000,
    label: Optional[str] = None,
    **style: Any,
) -> Any:
    """The pivot's track in the x–y plane (metres), sampled at `samples` values of u."""
    ax = _axes(ax)
    matrices = np.asarray(path.sample(np.linspace(0.0, 1.0, samples)))
    p = np.asarray(pivot, dtype=float)
    track = matrices[:, :3, :3] @ p + matrices[:, :3, 3]
    ax.plot(track[:, 0], track[:, 1], label=label, **style)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal", adjustable="datalim")
    return ax


def save(axes: Sequence[Any], path: str) -> None:
    """Write the figure(s) of `axes` (one or several Axes of one figure) to a PNG file."""
    figure = axes[0].figure
    figure.savefig(path, dpi=110)
