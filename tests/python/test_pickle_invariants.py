"""A pickle is input like any other: __setstate__ refuses a state that breaks what a constructed
object of the type satisfies (the same C++ checks run on both paths), names the type, the field and
the value in the house format, raises TypeError for a wrong type and ValueError for a bad value,
never crashes, and an object it accepts samples finite numbers within its own limits. Called on an
object that already exists, __setstate__ raises TypeError instead of silently doing nothing.
Random states and corruptions: test_pickle_properties.py."""

import copy
import math
import pickle
import subprocess
import sys
import textwrap

import pytest

import dispkin

from test_python_objects import Q0, blended_path

from _pickled import NAMES, assert_refused, fresh, named, plain, replaced, trajectory


# --- every type ---------------------------------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_every_type_round_trips_to_the_same_state(name):
    obj = named(name)
    for copied in [pickle.loads(pickle.dumps(obj, protocol)) for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1)] + [
        copy.copy(obj),
        copy.deepcopy(obj),
    ]:
        assert type(copied) is type(obj)
        assert plain(copied.__getstate__()) == plain(obj.__getstate__())


@pytest.mark.parametrize("name", NAMES)
def test_setstate_on_a_live_object_raises_and_changes_nothing(name):
    obj = named(name)
    before = plain(obj.__getstate__())
    with pytest.raises(TypeError, match=rf"^{name}\.__setstate__: the object already holds a {name}"):
        obj.__setstate__(obj.__getstate__())
    assert plain(obj.__getstate__()) == before


@pytest.mark.parametrize("name", NAMES)
def test_a_state_of_the_wrong_shape_is_refused_with_the_type_named(name):
    obj = named(name)
    cls = type(obj)
    state = obj.__getstate__()
    if isinstance(state, list):  # MetricSet: a list of groups
        assert_refused(cls, 42, TypeError, "expected a list of groups, got 42")
        assert_refused(cls, [(0, None)], ValueError, "state[0] (group) = (0, None): must be a tuple of 6 items, not 2")
        return
    assert_refused(cls, state + (0.0,), ValueError, f"state: expected a tuple of {len(state)} items, got (")
    # A Trajectory's state of 9 items is the layout before sections were kept once.
    shorter = state[:-2] if cls is dispkin.Trajectory else state[:-1]
    assert_refused(cls, shorter, ValueError, f"state: expected a tuple of {len(state)} items")
    assert_refused(cls, list(state), TypeError, f"state: expected a tuple of {len(state)} items, got [")


# --- the invariants, type by type ----------------------------------------------------------------


def test_pose_numbers_within_the_constructors_range():
    assert_refused(
        dispkin.Pose,
        ((1.0, 0.0, 0.0, 0.0), (1e300, 0.0, 0.0)),
        ValueError,
        "translation = (1e+300, 0, 0): must have coordinates within ±1e12 m",
    )
    assert_refused(
        dispkin.Pose,
        ((1.0, 0.0, 0.0, 0.0), (0.0, math.nan, 0.0)),
        ValueError,
        "translation = (0, nan, 0): must be finite",
    )
    assert_refused(
        dispkin.Pose,
        ((1.0, 1e-5, 0.0, 0.0), (0.0, 0.0, 0.0)),
        ValueError,
        "quaternion (w, x, y, z) = (1, 1e-05, 0, 0): must be a unit quaternion",
    )
    assert_refused(
        dispkin.Pose,
        ((1.0, 0.0, 0.0, 0.0), (0.0, 0.0)),
        ValueError,
        "state[1] (translation) = (0.0, 0.0): must be a tuple of 3 floats, not of shape (2,)",
    )
    assert_refused(
        dispkin.Pose,
        ((1.0, 0.0, 0.0, 0.0), (0.0, 0.0, "x")),
        TypeError,
        "state[1] (translation) = (0.0, 0.0, 'x'): must be a tuple of 3 floats",
    )
    # Within rounding of a unit quaternion the state is taken bit for bit.
    q = (math.cos(0.3), math.sin(0.3), 0.0, 0.0)
    assert fresh(dispkin.Pose, (q, (1e12, -1e12, 0.0))).__getstate__() == (q, (1e12, -1e12, 0.0))


def test_limits_and_frames_name_the_field():
    assert_refused(
        dispkin.Limits, (1e300, 1.0, None, None, None), ValueError, "velocity = 1e+300: must be in [1e-12, 1e12]"
    )
    assert_refused(
        dispkin.Limits, (1.0, 1.0, "fast", None, None), TypeError, "state[2] (jerk) = 'fast': must be a float or None"
    )
    assert_refused(dispkin.WorkToolFrames, (1, dispkin.Pose()), TypeError, "state[0] (work) = 1: must be a Pose")
    # None, and a Pose without a value, were taken by pybind11 for arguments of another overload.
    assert_refused(dispkin.WorkToolFrames, (dispkin.Pose(), None), TypeError, "state[1] (tool) = None: must be a Pose")
    assert_refused(
        dispkin.WorkToolFrames,
        (dispkin.Pose.__new__(dispkin.Pose), dispkin.Pose()),
        TypeError,
        "state[0] (work) = ",
        "must be a Pose",
    )


def scaled_profile(state, factor, peak=True):
    """A Profile state run `factor` times faster (velocities × f, accelerations × f², jerks × f³);
    the peak velocity too only if `peak`."""
    kind, phases, times, distance, peak_velocity, start, end = state
    scale = lambda x: (x[0], x[1] * factor, x[2] * factor**2, x[3] * factor**3)  # noqa: E731
    phases = tuple((d / factor, j * factor**3, scale(a), scale(b)) for d, j, a, b in phases)
    return (
        kind,
        phases,
        tuple(t / factor for t in times),
        distance,
        peak_velocity * (factor if peak else 1.0),
        scale(start),
        scale(end),
    )


def test_a_profile_must_be_a_law():
    state = named("Profile").__getstate__()
    assert_refused(
        dispkin.Profile,
        scaled_profile(state, 1000.0, peak=False),
        ValueError,
        ".v = ",
        "must be within [0, peak_velocity = 0.25]",
    )
    assert_refused(
        dispkin.Profile, replaced(state, (3,), 2 * state[3]), ValueError, "end.s = 0.3: must be the distance 0.6"
    )
    assert_refused(
        dispkin.Profile,
        replaced(state, (1, 2, 3, 1), 1e308),
        ValueError,
        "phases[2].end (s, v, a) = (0.045, 1e+308, 0): must be (s = ",
    )
    assert_refused(
        dispkin.Profile, replaced(state, (4,), math.inf), ValueError, "state[4] (peak_velocity) = inf: must be finite"
    )
    assert_refused(
        dispkin.Profile,
        replaced(state, (0,), "cubic"),
        ValueError,
        "state[0] (kind) = 'cubic': must be 'scurve' or 'trapezoid'",
    )
    assert_refused(
        dispkin.Profile,
        replaced(state, (2,), state[2][:-1]),
        ValueError,
        "state[2] (times)",
        "one time more than there are phases",
    )
    assert_refused(
        dispkin.Profile,
        replaced(state, (1, 0, 0), "1"),
        TypeError,
        "state[1] (phases[0].duration) = '1': must be a float",
    )
    # A law run consistently faster is still a law: a Profile alone has no limits but its own.
    faster = fresh(dispkin.Profile, scaled_profile(state, 2.0))
    assert faster.duration == pytest.approx(named("Profile").duration / 2, rel=1e-12)


def without_section(s, i):
    """A Trajectory state with section i of item 0 left out, and its parts (item 9) and their lengths."""
    parts = s[9] or tuple((k, 0.0, 1.0) for k in range(len(s[0])))
    kept = [k for k, p in enumerate(parts) if p[0] != i]
    new_parts = tuple((p[0] - (p[0] > i), p[1], p[2]) for p in parts if p[0] != i)
    return (s[0][:i] + s[0][i + 1 :], tuple(s[1][k] for k in kept)) + s[2:9] + (new_parts,)


def test_a_trajectory_must_keep_its_own_limits_and_join_up():
    traj = trajectory()
    s = traj.__getstate__()
    runs, pieces = s[2]
    faster = (runs, tuple((scaled_profile(p, 1000.0), s0) for p, s0 in pieces))
    assert_refused(
        dispkin.Trajectory,
        s[:2] + (faster,) + s[3:],
        ValueError,
        "time_law pieces[0] peak velocity = 250: must be at most the velocity limit over its span, 0.25 m/s",
    )
    # A section left out, with its parts: the next one starts where the one before the gap did
    # not end.
    assert_refused(
        dispkin.Trajectory,
        without_section(s, 1),
        ValueError,
        "sections[1].start = (",
        "must start where the path ends (gap ",
    )
    # An 8.6 m jump: the last section moved away along x.
    last = list(s[0][-1])
    assert last[0] == "lin"
    moved = lambda p: p[:4] + (p[4] + 8.6,) + p[5:]  # noqa: E731
    jumped = s[0][:-1] + (tuple([last[0], moved(last[1]), moved(last[2])] + last[3:]),)
    assert_refused(
        dispkin.Trajectory, (jumped,) + s[1:], ValueError, f"sections[{len(jumped) - 1}].start = (", "gap 8.6"
    )
    assert_refused(
        dispkin.Trajectory,
        (s[0], tuple(2 * L for L in s[1])) + s[2:],
        ValueError,
        "time_law distance = ",
        "must be the path length, the sum of the section lengths",
    )
    assert_refused(
        dispkin.Trajectory,
        (s[0], s[1][:-1]) + s[2:],
        ValueError,
        "state[1] (section_lengths) = (",
        "must hold one length per section",
    )
    assert_refused(
        dispkin.Trajectory,
        (s[0], (math.nan,) + s[1][1:]) + s[2:],
        ValueError,
        "state[1] (section_lengths[0]) = nan: must be finite",
    )
    huge = replaced(s, (2, 1, 0, 0, 3), 1e308)
    assert_refused(
        dispkin.Trajectory,
        huge,
        ValueError,
        "state[2] (time_law.pieces[0].profile) end.s = ",
        "must be the distance 1e+308",
    )
    assert_refused(
        dispkin.Trajectory,
        replaced(s, (2, 1, 0, 0, 3), "x"),
        TypeError,
        "state[2] (time_law.pieces[0].profile.distance) = 'x': must be a float",
    )
    assert_refused(
        dispkin.Trajectory,
        replaced(s, (3, 0, 2), 2.5e14),
        ValueError,
        "speed_limits[0].limit = 2.5e+14: must be in (0, 1e12]",
    )
    assert_refused(dispkin.Trajectory, replaced(s, (2, 0), 0), ValueError, "time_law runs = 0: must be at least 1")
    assert_refused(
        dispkin.Trajectory, replaced(s, (0, 0, 1, 4), 1e300), ValueError, "sections[0].start translation = (1e+300"
    )


def test_a_path_must_join_up_and_stay_in_range():
    s = blended_path().__getstate__()
    assert_refused(
        dispkin.Path, replaced(s, (0, 0, 1, 4), 1e300), ValueError, "sections[0].start translation = (1e+300"
    )
    assert_refused(dispkin.Path, replaced(s, (0, 0, 0), "line"), ValueError, "state[0] (sections[0].kind) = 'line'")
    assert_refused(
        dispkin.Path, replaced(s, (4,), (0, 10**6)), ValueError, "state[4] (move_starts[1]) = 1000000: must be in [0, "
    )
    assert_refused(dispkin.JointPath, (Q0, Q0[:3]), ValueError, "q_end size = 3: must equal q_start size 6")


def report_state_with_one_sample_short(report_state):
    """The report's state with sample 3's q two joints long: the arrays then disagree in size."""
    samples = list(report_state[0])
    sample = list(samples[3])
    sample[2] = sample[2][:2]
    samples[3] = tuple(sample)
    return (tuple(samples),) + report_state[1:]


def test_report_arrays_must_agree_in_size():
    report = named("JointLimitReport")
    broken = report_state_with_one_sample_short(report.__getstate__())
    assert_refused(dispkin.JointLimitReport, broken, ValueError, "samples[3].q size = 2: must be 6, as in samples[0]")
    optimal = named("OptimalRetimeResult").__getstate__()
    assert_refused(
        dispkin.OptimalRetimeResult,
        (optimal[0], broken) + optimal[2:],
        ValueError,
        "state[1] (report) samples[3].q size = 2: must be 6",
    )
    scaled = named("RetimeResult").__getstate__()
    assert_refused(dispkin.RetimeResult, scaled[:3] + (broken,), ValueError, "state[3] (report) samples[3].q size = 2")
    assert_refused(
        dispkin.JointLimitReport,
        replaced(report.__getstate__(), (3,), 9),
        ValueError,
        "velocity_joint = 9: must be -1 (none) or a joint index below 6",
    )
    assert_refused(
        dispkin.JointLimitReport,
        replaced(report.__getstate__(), (4,), 10**9),
        ValueError,
        "state[4] (velocity_sample) = 1000000000: must be in [0, ",
    )
    assert_refused(
        dispkin.OptimalRetimeResult, optimal[:8] + (optimal[8][:-1],) + optimal[9:], ValueError, "grid_speed size = "
    )


def test_broken_report_sizes_do_not_crash_the_interpreter():
    """The per-sample arrays of a report whose sizes disagree were read past their heap buffers
    (garbage, or a segmentation fault): run in a child, so that a regression fails this test
    instead of killing pytest."""
    code = textwrap.dedent("""
        import pickle, sys
        sys.path.insert(0, sys.argv[1])
        import dispkin
        from test_pickle_invariants import named, report_state_with_one_sample_short
        report = named("JointLimitReport")
        state = report_state_with_one_sample_short(report.__getstate__())
        optimal = named("OptimalRetimeResult").__getstate__()
        for cls, s in ((dispkin.JointLimitReport, state), (dispkin.OptimalRetimeResult, (optimal[0], state) + optimal[2:])):
            obj = cls.__new__(cls)
            try:
                obj.__setstate__(s)
            except ValueError:
                continue
            print("accepted", cls.__name__, (obj.report if hasattr(obj, "report") else obj).samples["q"].shape)
        print("done")
    """)
    here = str(__import__("pathlib").Path(__file__).parent)
    done = subprocess.run([sys.executable, "-c", code, here], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, (
        f"child exited with {done.returncode} (negative: killed by a signal): {done.stderr[-2000:]}"
    )
    assert done.stdout == "done\n", done.stdout


def test_machine_results_must_be_consistent():
    v = named("LegViolation").__getstate__()
    assert_refused(dispkin.LegViolation, replaced(v, (0,), 7), ValueError, "leg = 7: must be a leg index 0 to 5")
    assert_refused(
        dispkin.LegViolation, replaced(v, (4,), 2 * v[4]), ValueError, "excess = ", "how far the length lies outside"
    )
    assert_refused(dispkin.LegViolation, replaced(v, (0,), 1.5), TypeError, "state[0] (leg) = 1.5: must be an int")
    w = named("WorkspaceCheck").__getstate__()
    lengths = tuple(w[0].tolist())
    assert_refused(
        dispkin.WorkspaceCheck,
        ((lengths[0] + 1.0,) + lengths[1:], w[1]),
        ValueError,
        "violations[0].length = ",
        "must be the length of leg",
    )
    e = named("LegExcursion").__getstate__()
    assert_refused(
        dispkin.LegExcursion,
        replaced(e, (0,), "width"),
        ValueError,
        "state[0] (kind) = 'width': must be 'length' or 'speed'",
    )
    assert_refused(
        dispkin.LegExcursion,
        replaced(e, (4,), e[3] + 1.0),
        ValueError,
        "must have start_time <= worst_time <= end_time",
    )
    c = named("TrajectoryCheck").__getstate__()
    assert_refused(
        dispkin.TrajectoryCheck, (c[1], c[0] - 1.0) + c[2:], ValueError, "min_length = (", "must not exceed max_length"
    )
    assert_refused(
        dispkin.TrajectoryCheck,
        c[:3] + ([e[:3] + (math.nan,) + e[4:]],),
        ValueError,
        "excursions[0].(start_time, end_time, worst_time) = (",
    )
    assert_refused(dispkin.Hexapod, (42,), TypeError, "state[0] (json) = 42: must be a str")


def test_arm_states_name_the_field():
    a = named("SerialArm").__getstate__()
    assert_refused(dispkin.SerialArm, replaced(a, (0,), 5), TypeError, "state[0] (urdf) = 5: must be a str")
    assert_refused(dispkin.SerialArm, replaced(a, (0,), "<robot"), ValueError)
    limits = a[3]
    swapped = (limits[1], limits[0]) + limits[2:]
    assert_refused(
        dispkin.SerialArm, replaced(a, (3,), swapped), ValueError, "(lower, upper) = (", "must have lower < upper"
    )
    j = named("JointLimits").__getstate__()
    assert_refused(dispkin.JointLimits, (j[0], j[1][:2]) + j[2:], ValueError, "upper size = 2: must be the dof 6")
    assert_refused(dispkin.JointLimits, j[:2] + (j[2] * 0.0,) + j[3:], ValueError, "joint 0 velocity = 0: must be > 0")
    r = named("InverseResult").__getstate__()
    assert_refused(dispkin.InverseResult, (r[0], r[1][:-1]) + r[2:], ValueError, "within_limits size = ")
    assert_refused(dispkin.InverseResult, r[:3] + ("magic",), ValueError, "state[3] (family) = 'magic'")
    m = named("MetricSet").__getstate__()
    group = m[0]
    assert_refused(dispkin.MetricSet, [(group[0], group[1], [[0.0, math.nan, 0.0]]) + group[3:]], ValueError, "nan")
    assert_refused(dispkin.MetricSet, [("0",) + group[1:]], TypeError, "state[0] (group.id) = '0': must be an int")
