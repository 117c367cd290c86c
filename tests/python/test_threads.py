"""Python threads: the long calls release the interpreter lock while their C++ part runs, and two
threads running them at once get the same results as one, bit for bit.

No timing is asserted (benchmarks/threads_scaling.py measures the speed-up). Whether a call
released the lock is seen directly: with the switch interval raised, a second thread only runs
Python code while the first one has released the lock, so it counts only while a call that
releases runs.
"""

import pathlib
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import dispkin
from _helpers import rng_for

pytestmark = pytest.mark.skipif(not hasattr(dispkin, "SerialArm"), reason="built without the serial-arm plugin")

URDF = pathlib.Path(__file__).resolve().parents[1] / "data" / "urdf" / "arm_ur5e_dh.urdf"
Q0 = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])


def ur5e():
    return dispkin.SerialArm.from_urdf(str(URDF), "base_link", "tool0")


def tool(points=0):
    """An icosahedron around the tool point, and `points` more points in a 10 cm cube."""
    s = dispkin.MetricSet()
    s.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
    if points:
        s.add_relative(rng_for("threads-tool").uniform(-0.05, 0.05, size=(points, 3)) + [0, 0, 0.1])
    return s


def path(arm):
    """A LIN, a CIRC and a LIN from the arm's pose at Q0, blended at the corners."""
    a = arm.forward(Q0)
    t = np.asarray(a.translation)
    at = lambda dx, dy, dz: dispkin.Pose(a.quaternion, t + np.array([dx, dy, dz]))  # noqa: E731
    return (
        dispkin.Path.lin(a, at(0.1, 0.0, 0.0))
        .then(dispkin.Path.circ(at(0.1, 0.0, 0.0), at(0.15, 0.05, 0.0), at(0.1, 0.1, 0.0)), blend=0.02)
        .then(dispkin.Path.lin(at(0.1, 0.1, 0.0), at(0.0, 0.1, -0.05)), blend=0.02)
    )


LIMITS = dispkin.Limits(1.0, 10.0, 100.0)


def ik_poses(arm, count):
    qs = rng_for("threads-ik").uniform(-np.pi, np.pi, size=(count, 6))
    return np.array([np.asarray(arm.forward(q).matrix()) for q in qs])


# Each workload: a function of nothing that returns arrays (compared bit for bit).
def plan_and_sample():
    arm = ur5e()
    traj = dispkin.plan(path(arm), tool(), LIMITS, corner_tolerance=0.01)
    times = np.linspace(0.0, traj.duration, 400)
    return [np.array([traj.duration]), traj.sample(times), traj.body_twist(times), traj.path_velocity(times)]


def inverse_batch():
    arm = ur5e()
    return arm.inverse_many(ik_poses(arm, 300))


def retime_and_check():
    arm = ur5e()
    result = dispkin.retime(path(arm), tool(), dispkin.Limits(3.0, 100.0, 4000.0), arm, Q0)
    report = dispkin.check_joint_limits(result.trajectory, arm, Q0)
    return [np.array([result.trajectory.duration, report.velocity_factor, report.acceleration_factor])] + [
        report.samples[key] for key in ("q", "qd", "qdd", "static_torque", "dynamic_torque")
    ]


def ptp_plan():
    arm = ur5e()
    move = dispkin.plan(dispkin.Path.ptp(Q0, Q0 + 0.5), tool(), LIMITS, robot=arm)
    times = np.linspace(0.0, move.duration, 200)
    return [np.array([move.duration]), move.joint_positions(times), move.sample(times)]


WORKLOADS = [plan_and_sample, inverse_batch, retime_and_check, ptp_plan]


@pytest.mark.parametrize("workload", WORKLOADS, ids=lambda w: w.__name__)
def test_two_threads_give_the_results_of_one_bit_for_bit(workload):
    alone = workload()
    results = [None, None]
    errors = []

    def run(k):
        try:
            results[k] = [workload() for _ in range(3)]
        except BaseException as error:  # noqa: BLE001 (reported below)
            errors.append(error)

    threads = [threading.Thread(target=run, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for runs in results:
        for found in runs:
            assert len(found) == len(alone)
            for f, a in zip(found, alone):
                assert f.dtype == a.dtype and f.shape == a.shape
                assert np.array_equal(f, a, equal_nan=True)


def other_thread_ran_during(call, attempts=5, seconds=0.2):
    """Whether a second Python thread ran while call() ran, in one of `attempts` runs of calls
    lasting `seconds` together (a thread woken on a busy machine may wait milliseconds for a
    core). The switch interval is raised far above that, so the second thread gets the lock
    from this one only when a call releases it (or this thread waits, which it does not between
    reading the counter and the calls)."""
    start = time.perf_counter()
    call()
    repeats = max(1, int(np.ceil(seconds / max(time.perf_counter() - start, 1e-6))))
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1
            time.sleep(0)  # hands the lock back to a thread that waits for it

    interval = sys.getswitchinterval()
    sys.setswitchinterval(30.0)
    spinner = threading.Thread(target=count)
    try:
        spinner.start()
        for _ in range(attempts):
            before = counter[0]
            for _ in range(repeats):
                call()
            if counter[0] != before:
                return True
        return False
    finally:
        stop.set()
        spinner.join()
        sys.setswitchinterval(interval)


@pytest.fixture(scope="module")
def long_calls():
    """{name: call} of calls that take well over 10 µs."""
    arm = ur5e()
    p = path(arm)
    big = tool(points=20000)
    traj = dispkin.plan(p, tool(), LIMITS)
    move = dispkin.plan(dispkin.Path.ptp(Q0, Q0 + 0.5), tool(), LIMITS, robot=arm)
    hexapod = dispkin.Hexapod.symmetric(0.15, np.radians(20), 0.10, np.radians(20), 0.20, 0.15, 0.32, 0.01)
    hex_path = dispkin.Path.lin(
        hexapod.home, dispkin.Pose.from_xyzuvw([0.02, 0.01, 0.01, 0.05, 0.0, 0.1]) * hexapod.home
    )
    hex_traj = dispkin.plan(hex_path, tool(), dispkin.Limits(0.05, 0.5, 5.0))
    poses = ik_poses(arm, 2000)
    times = np.linspace(0.0, traj.duration, 20000)
    cloud = rng_for("threads-cloud").normal(size=(20000, 3))
    a, b = p.start, p.end
    follow_poses = [p.sample(u) for u in np.linspace(0.0, 1.0, 1000)]
    return dict(
        [
            ("plan", lambda: dispkin.plan(p, big, LIMITS)),
            ("plan with corner_tolerance", lambda: dispkin.plan(p, big, LIMITS, corner_tolerance=0.01)),
            (
                "plan with a Hexapod joint metric",
                lambda: dispkin.plan(hex_path, big, dispkin.Limits(0.05, 0.5, 5.0), joint_metric=hexapod),
            ),
            ("plan PTP", lambda: dispkin.plan(dispkin.Path.ptp(Q0, Q0 + 0.5), big, LIMITS, robot=arm)),
            ("retime", lambda: dispkin.retime(p, tool(), dispkin.Limits(3.0, 100.0, 4000.0), arm, Q0)),
            (
                "retime optimal",
                lambda: dispkin.retime(
                    p,
                    tool(),
                    dispkin.Limits(3.0, 100.0),
                    arm,
                    Q0,
                    profile="trapezoid",
                    method="optimal",
                    grid_intervals=50,
                ),
            ),
            ("check_joint_limits", lambda: dispkin.check_joint_limits(traj, arm, Q0, samples_between=200)),
            (
                "SerialArm.check_joint_limits",
                lambda: arm.check_joint_limits(move, np.linspace(0.0, move.duration, 5000)),
            ),
            ("SerialArm.inverse_many", lambda: arm.inverse_many(poses)),
            ("SerialArm.inverse with the 2π copies", lambda: arm.inverse(poses[0], offer_equivalents=True)),
            ("SerialArm.follow", lambda: arm.follow(follow_poses, Q0)),
            ("SerialArm.follow_trajectory", lambda: arm.follow_trajectory(traj, times[::10], Q0)),
            ("Trajectory.sample", lambda: traj.sample(times)),
            ("JointTrajectory.sample", lambda: move.joint_positions(times)),
            ("Path.sample", lambda: p.sample(np.linspace(0.0, 1.0, 20000))),
            ("Path.section_lengths", lambda: p.section_lengths(big)),
            ("section_length", lambda: dispkin.section_length(big, a, b)),
            ("disp_distance", lambda: dispkin.disp_distance(big, a, b)),
            ("convex_hull_vertices", lambda: dispkin.convex_hull_vertices(cloud)),
            ("MetricSet.reduce_to_hull", lambda: big.reduce_to_hull()),
            ("Hexapod.check", lambda: hexapod.check(hex_traj, 1e-5)),
            ("Hexapod.leg_section_lengths", lambda: hexapod.leg_section_lengths(hex_path, 0.05)),
            ("retime Hexapod", lambda: dispkin.retime(hex_path, tool(), dispkin.Limits(0.05, 0.5), hexapod)),
        ]
    )


LONG_CALLS = [
    "plan",
    "plan with corner_tolerance",
    "plan with a Hexapod joint metric",
    "plan PTP",
    "retime",
    "retime optimal",
    "check_joint_limits",
    "SerialArm.check_joint_limits",
    "SerialArm.inverse_many",
    "SerialArm.inverse with the 2π copies",
    "SerialArm.follow",
    "SerialArm.follow_trajectory",
    "Trajectory.sample",
    "JointTrajectory.sample",
    "Path.sample",
    "Path.section_lengths",
    "section_length",
    "disp_distance",
    "convex_hull_vertices",
    "MetricSet.reduce_to_hull",
    "Hexapod.check",
    "Hexapod.leg_section_lengths",
    "retime Hexapod",
]


def test_every_long_call_is_checked(long_calls):
    assert sorted(long_calls) == sorted(LONG_CALLS)


@pytest.mark.parametrize("name", LONG_CALLS)
def test_long_calls_let_other_threads_run(long_calls, name):
    assert other_thread_ran_during(long_calls[name]), f"{name} kept the interpreter lock"


def test_a_short_call_keeps_the_lock():
    # The check itself: a call that never releases the lock lets no other thread run.
    arm = ur5e()
    assert not other_thread_ran_during(lambda: arm.forward(Q0), attempts=2)


# --- objects a released call reads -----------------------------------------------------------
# A MetricSet and a Path can be changed from Python (add_*, set_group_speed, then). A call that
# reads one with the lock released marks it, and changing it meanwhile raises RuntimeError; the
# mark goes when the call returns, also by an exception. Run in a child process: before the
# marks, another thread adding groups crashed the interpreter.

RACE = """
import sys, threading
import numpy as np
import dispkin
sys.setswitchinterval(1e-5)
a = dispkin.Pose()
b = dispkin.Pose.from_xyzuvw([0.3, 0.1, 0.0, 0.4, 0.2, 0.1])
path = dispkin.Path.lin(a, b)
for k in range(1, 21):
    c = dispkin.Pose.from_xyzuvw([0.3 + 0.01 * (k % 2), 0.1 + 0.01 * k, 0.0, 0.4, 0.2, 0.1 + 0.01 * k])
    path.then(dispkin.Path.lin(b, c), blend=0.003)
    b = c
metric = dispkin.MetricSet()
metric.add_relative(dispkin.shapes.icosphere(0.1, 2))
limits = dispkin.Limits(0.5, 2.0, 20.0)
done = threading.Event()
durations, refused, added = [], [], [0]

def planner():
    for _ in range(5):
        t = dispkin.plan(path, metric, limits, corner_tolerance=1e-4)
        durations.append(t.duration)
        assert np.isfinite(t.sample(np.linspace(0, t.duration, 50))[1]).all()
    done.set()

def changer():
    group = 1
    while not done.is_set():
        try:
            CHANGE
            added[0] += 1
        except RuntimeError as error:
            refused.append(str(error))
        group += 1

threads = [threading.Thread(target=planner), threading.Thread(target=changer)]
for t in threads: t.start()
for t in threads: t.join()
assert len(durations) == 5 and all(np.isfinite(durations)), durations
print(len(refused), added[0], refused[0] if refused else "")
"""

CHANGES = {
    "MetricSet.add_relative": "metric.add_relative([0.0, 0.0, 0.01 * (group % 7)], group=group)",
    "MetricSet.add_sphere": "metric.add_sphere([0.0, 0.0, 0.1], 0.01, group=group)",
    "MetricSet.set_group_speed": "metric.set_group_speed(group, 1.0)",
    "Path.then": "path.then(dispkin.Path.lin(path.sample(1.0), path.sample(1.0) * dispkin.Pose.from_xyzuvw([1e-3, 0, 0, 0, 0, 0])))",
}


@pytest.mark.parametrize("method", sorted(CHANGES))
def test_changing_an_object_a_plan_reads_is_refused_never_a_crash(method):
    code = RACE.replace("CHANGE", CHANGES[method])
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, f"exit {done.returncode} (negative: a signal): {done.stderr[-3000:]}"
    refused, _, first = done.stdout.strip().split(" ", 2)
    assert int(refused) > 0, "the other thread never met a running plan"
    assert first.startswith(method + ": the object is being read by a call running in another thread"), first


def test_the_mark_goes_when_a_released_call_fails():
    empty = dispkin.MetricSet()
    line = dispkin.Path.lin(dispkin.Pose(), dispkin.Pose.from_xyzuvw([0.1, 0, 0, 0, 0, 0]))
    with pytest.raises(ValueError, match="is not well-formed"):
        dispkin.plan(line, empty, dispkin.Limits(0.5, 2.0, 20.0))
    empty.add_relative([[0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1]])  # no longer marked
    line.then(dispkin.Path.lin(line.sample(1.0), dispkin.Pose.from_xyzuvw([0.2, 0, 0, 0, 0, 0])))
    assert len(line) == 2
