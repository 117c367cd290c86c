"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area: Pickled
states: every pickled object rebuilt from a state that is wrong."""

import dispkin

from .rows import A, B, LIMITS, NAN, V, good_set, row, section, trajectory
from .joint_motion import Q_UR, ur5e, ur_path

section("Pickled states")


def unpickled(cls, state):
    """What pickle.loads does with `state`: a new instance, then __setstate__."""
    obj = cls.__new__(cls)
    obj.__setstate__(state)
    return obj


def trajectory_state(change):
    """The state of trajectory() with `change(state as a list)` applied."""
    s = list(trajectory().__getstate__())
    change(s)
    return tuple(s)


def faster_law(s, factor=1000.0):
    """Every law of a Trajectory state run `factor` times faster (v × f, a × f², j × f³)."""
    scale = lambda x: (x[0], x[1] * factor, x[2] * factor**2, x[3] * factor**3)  # noqa: E731
    runs, pieces = s[2]
    s[2] = (
        runs,
        tuple(
            (
                (
                    k,
                    tuple((d / factor, j * factor**3, scale(a), scale(b)) for d, j, a, b in ph),
                    tuple(t / factor for t in ts),
                    S,
                    peak * factor,
                    scale(x0),
                    scale(x1),
                ),
                s0,
            )
            for (k, ph, ts, S, peak, x0, x1), s0 in pieces
        ),
    )


def jumping_section(s):
    """A LIN section appended 8.6 m along x from where the path ends."""
    last = s[0][-1]
    end = last[2] if last[0] == "lin" else None
    start = end[:4] + (end[4] + 8.6,) + end[5:]
    s[0] = s[0] + (("lin", start, start[:4] + (start[4] + 0.1,) + start[5:], "decoupled", (0.0, 0.0, 0.0)),)
    s[1] = s[1] + (0.1,)
    if s[9]:  # the trajectory's sections as parts of the sections of item 0: the new one whole
        s[9] = s[9] + ((len(s[0]) - 1, 0.0, 1.0),)


def short_report_sample():
    """A JointLimitReport state whose sample 1 has two joint positions where the others have six."""
    report = dispkin.check_joint_limits(dispkin.plan(ur_path(), good_set(), LIMITS), ur5e(), Q_UR).__getstate__()
    samples = list(report[0])
    samples[1] = samples[1][:2] + (samples[1][2][:2],) + samples[1][3:]
    return (tuple(samples),) + report[1:]


row(
    "Pose.__setstate__",
    "translation beyond the numeric range (1e300 m)",
    lambda: unpickled(dispkin.Pose, ((1.0, 0.0, 0.0, 0.0), (1e300, 0.0, 0.0))),
    V,
    "Pose.__setstate__: translation = (1e+300, 0, 0): must have coordinates within ±1e12 m",
)
row(
    "Pose.__setstate__",
    "NaN translation",
    lambda: unpickled(dispkin.Pose, ((1.0, 0.0, 0.0, 0.0), (NAN, 0.0, 0.0))),
    V,
    "Pose.__setstate__: translation = (nan, 0, 0): must be finite",
)
row(
    "Pose.__setstate__",
    "a str for the translation",
    lambda: unpickled(dispkin.Pose, ((1.0, 0.0, 0.0, 0.0), "origin")),
    TypeError,
    "Pose.__setstate__: state[1] (translation) = 'origin': must be a tuple of 3 floats",
)
row(
    "Pose.__setstate__",
    "a state of 3 items",
    lambda: unpickled(dispkin.Pose, (1, 2, 3)),
    V,
    "Pose.__setstate__: state: expected a tuple of 2 items, got (1, 2, 3)",
)
row(
    "Pose.__setstate__",
    "called on a live Pose (was ignored)",
    lambda: A.__setstate__(B.__getstate__()),
    TypeError,
    "Pose.__setstate__: the object already holds a Pose",
)
row(
    "Limits.__setstate__",
    "an int-typed field is a str",
    lambda: unpickled(dispkin.Limits, (0.1, "1", None, None, None)),
    TypeError,
    "Limits.__setstate__: state[1] (acceleration) = '1': must be a float",
)
row(
    "Limits.__setstate__",
    "velocity 1e300",
    lambda: unpickled(dispkin.Limits, (1e300, 1.0, None, None, None)),
    V,
    "Limits.__setstate__: velocity = 1e+300: must be in [1e-12, 1e12]",
)
row(
    "Trajectory.__setstate__",
    "laws 1000 times over the velocity-limit curve",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(faster_law)),
    V,
    "Trajectory.__setstate__: time_law pieces[0] peak velocity = 100: must be at most the velocity limit over its span, 0.1 m/s",
)
row(
    "Trajectory.__setstate__",
    "a section 8.6 m away from the one before (the path jumps)",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(jumping_section)),
    V,
    "must start where the path ends (gap 8.6",
)
row(
    "Trajectory.__setstate__",
    "section lengths twice the law's distance",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(1, tuple(2 * L for L in s[1])))),
    V,
    "Trajectory.__setstate__: time_law distance = ",
)
row(
    "Trajectory.__setstate__",
    "a stopped motion without its stop",
    lambda: unpickled(
        dispkin.Trajectory, tuple(s[:5] + ((),) + s[6:] for s in [trajectory().stopped_at(0.5).__getstate__()])[0]
    ),
    V,
    "Trajectory.__setstate__: time_law distance = ",
)
row(
    "Trajectory.__setstate__",
    "override factor 0",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(8, 0.0))),
    V,
    "Trajectory.__setstate__: override_factor = 0: must be in [0.001, 10]",
)
row(
    "Trajectory.__setstate__",
    "a cut law cut after its end",
    lambda: unpickled(
        dispkin.Trajectory,
        tuple(
            s[:2] + ((s[2][0], tuple(p if len(p) == 2 else p[:2] + (1e6,) for p in s[2][1])),) + s[3:]
            for s in [trajectory().with_override(0.5, 0.5).__getstate__()]
        )[0],
    ),
    V,
    "cut time = 1000000",
)
row(
    "Trajectory.__setstate__",
    "a law's distance 1e308",
    lambda: unpickled(
        dispkin.Trajectory,
        trajectory_state(
            lambda s: s.__setitem__(
                2, (s[2][0], ((s[2][1][0][0][:3] + (1e308,) + s[2][1][0][0][4:], 0.0),) + s[2][1][1:])
            )
        ),
    ),
    V,
    "Trajectory.__setstate__: state[2] (time_law.pieces[0].profile) end.s = ",
)
row(
    "Trajectory.__setstate__",
    "NaN section length",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(1, (NAN,) + s[1][1:]))),
    V,
    "Trajectory.__setstate__: state[1] (section_lengths[0]) = nan: must be finite",
)
row(
    "Trajectory.__setstate__",
    "an int where a run count is a str",
    lambda: unpickled(dispkin.Trajectory, trajectory_state(lambda s: s.__setitem__(2, ("1",) + s[2][1:]))),
    TypeError,
    "Trajectory.__setstate__: state[2] (time_law.runs) = '1': must be an int",
)
row(
    "Profile.__setstate__",
    "phase velocities 1000 times its peak",
    lambda: unpickled(
        dispkin.Profile,
        (
            lambda k, ph, ts, S, peak, a, b: (
                k,
                tuple((d, j, (x[0], x[1] * 1000, x[2], x[3]), (y[0], y[1] * 1000, y[2], y[3])) for d, j, x, y in ph),
                ts,
                S,
                peak,
                a,
                b,
            )
        )(*dispkin.Profile.trapezoid(1.0, 0.5, 1.0).__getstate__()),
    ),
    V,
    "Profile.__setstate__: phases[0].end (s, v, a) = (",
)
row(
    "JointLimitReport.__setstate__",
    "per-sample arrays of different sizes (read past the buffer)",
    lambda: unpickled(dispkin.JointLimitReport, short_report_sample()),
    V,
    "JointLimitReport.__setstate__: samples[1].q size = 2: must be 6, as in samples[0]",
)
row(
    "SerialArm.__setstate__",
    "an int for the URDF text",
    lambda: unpickled(dispkin.SerialArm, (5,) + ur5e().__getstate__()[1:]),
    TypeError,
    "SerialArm.__setstate__: state[0] (urdf) = 5: must be a str",
)
row(
    "LegViolation.__setstate__",
    "leg index 7",
    lambda: unpickled(dispkin.LegViolation, (7, 0.1, 0.15, 0.32, 0.05)),
    V,
    "LegViolation.__setstate__: leg = 7: must be a leg index 0 to 5",
)
