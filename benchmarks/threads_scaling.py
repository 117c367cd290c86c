"""Two Python threads against one: the wall time of a fixed workload.

dispkin's long calls release the interpreter lock while their C++ part runs
(python/src/interpreter_lock.hpp), so two threads each running half of a workload should take
half the wall time of one thread running all of it, on a machine with two free cores. Each
workload below is a list of units of work; per round the script runs

- 1 thread:  both units, one after the other, in the main thread;
- 2 threads: one unit in each of two threads at once;

alternating which goes first from round to round, and prints per workload the median wall time
of each and their ratio (the speed-up; 2.0 at best on two cores), the median over rounds of the
per-round ratio, and the process CPU time over the wall time of each (how many cores were busy
on average: 1.0 for one thread and 2.0 for two threads running in parallel all the time; less
means the threads waited for the lock, or for a core the machine's other load held). The results
of the two threads are checked to be those of one thread, bit for bit.

Workloads:
- plan: plan() of a LIN-CIRC-LIN path with blended corners under a 2000-point metric set, then
  the trajectory sampled at 2000 times;
- inverse_many: SerialArm.inverse_many of 4000 poses of the UR5e;
- retime: retime(method="scaling") of the same path on the UR5e and check_joint_limits of the
  result;
- control: hashlib.sha256 of 50 MB, no dispkin: a C call known to release the lock for all its
  work, so its speed-up is what the machine allows at the moment (on a machine whose cores are
  busy with other work it falls short of 2 as dispkin's do).

Run:  .venv/bin/python benchmarks/threads_scaling.py [--rounds 7]
(build the binding first: make python). Wall time is the quantity here, so the machine's load
matters: note it (uptime) with the figures. No timing is asserted anywhere; this only prints.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import pathlib
import platform
import statistics
import threading
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # numpy's BLAS threads would compete for the two cores
import numpy as np  # noqa: E402

import dispkin  # noqa: E402

URDF = pathlib.Path(__file__).resolve().parents[1] / "tests" / "data" / "urdf" / "arm_ur5e_dh.urdf"
Q0 = np.array([0.3, -1.2, 1.5, -1.9, -1.57, 0.2])


def ur5e():
    return dispkin.SerialArm.from_urdf(str(URDF), "base_link", "tool0")


def tool(points):
    s = dispkin.MetricSet()
    s.add_relative(dispkin.shapes.icosahedron(0.05, [0, 0, 0.1]))
    if points:
        s.add_relative(np.random.default_rng(7).uniform(-0.05, 0.05, size=(points, 3)) + [0, 0, 0.1])
    return s


def path(arm):
    a = arm.forward(Q0)
    t = np.asarray(a.translation)

    def at(dx, dy, dz):
        return dispkin.Pose(a.quaternion, t + np.array([dx, dy, dz]))

    return (
        dispkin.Path.lin(a, at(0.1, 0.0, 0.0))
        .then(dispkin.Path.circ(at(0.1, 0.0, 0.0), at(0.15, 0.05, 0.0), at(0.1, 0.1, 0.0)), blend=0.02)
        .then(dispkin.Path.lin(at(0.1, 0.1, 0.0), at(0.0, 0.1, -0.05)), blend=0.02)
    )


def plan_unit():
    arm = ur5e()
    p, s = path(arm), tool(2000)
    limits = dispkin.Limits(1.0, 10.0, 100.0)

    def unit():
        traj = dispkin.plan(p, s, limits, corner_tolerance=0.01)
        return traj.sample(np.linspace(0.0, traj.duration, 2000))

    return unit


def inverse_many_unit():
    arm = ur5e()
    qs = np.random.default_rng(11).uniform(-np.pi, np.pi, size=(4000, 6))
    poses = np.array([np.asarray(arm.forward(q).matrix()) for q in qs])

    def unit():
        return np.concatenate(arm.inverse_many(poses))

    return unit


def retime_unit():
    arm = ur5e()
    p, s = path(arm), tool(0)

    def unit():
        result = dispkin.retime(p, s, dispkin.Limits(3.0, 100.0, 4000.0), arm, Q0)
        samples = dispkin.check_joint_limits(result.trajectory, arm, Q0).samples
        return np.concatenate([samples[key] for key in ("q", "qd", "qdd", "static_torque", "dynamic_torque")], axis=1)

    return unit


def control_unit():
    data = np.random.default_rng(13).bytes(50_000_000)

    def unit():
        return np.frombuffer(hashlib.sha256(data).digest(), dtype=np.uint8)

    return unit


WORKLOADS = {"plan": plan_unit, "inverse_many": inverse_many_unit, "retime": retime_unit, "control": control_unit}


def one_thread(unit):
    start, cpu = time.perf_counter(), time.process_time()
    results = [unit(), unit()]
    return time.perf_counter() - start, time.process_time() - cpu, results


def two_threads(unit):
    results = [None, None]
    ready = threading.Barrier(3)

    def run(k):
        ready.wait()
        results[k] = unit()

    threads = [threading.Thread(target=run, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    start, cpu = time.perf_counter(), time.process_time()
    ready.wait()
    for t in threads:
        t.join()
    return time.perf_counter() - start, time.process_time() - cpu, results


def measure(name, make_unit, rounds):
    unit = make_unit()
    reference = unit()
    one, two, ratios, busy_one, busy_two = [], [], [], [], []
    for r in range(rounds):
        order = (one_thread, two_threads) if r % 2 == 0 else (two_threads, one_thread)
        walls = {}
        for runner in order:
            wall, cpu, results = runner(unit)
            for found in results:
                if not np.array_equal(found, reference):
                    raise RuntimeError(f"{name}: a result differs from the one-thread result")
            walls[runner] = wall
            (busy_two if runner is two_threads else busy_one).append(cpu / wall)
        one.append(walls[one_thread])
        two.append(walls[two_threads])
        ratios.append(walls[one_thread] / walls[two_threads])
    print(
        f"  {name:14s} 1 thread {statistics.median(one) * 1e3:8.1f} ms   2 threads {statistics.median(two) * 1e3:8.1f} ms"
        f"   speed-up {statistics.median(one) / statistics.median(two):.2f}"
        f" (per round: median {statistics.median(ratios):.2f}, {min(ratios):.2f} – {max(ratios):.2f})"
        f"   cores busy: 1 thread {statistics.median(busy_one):.2f}, 2 threads {statistics.median(busy_two):.2f}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=7, help="alternating rounds, medians are printed (default 7)")
    parser.add_argument("--only", choices=sorted(WORKLOADS), help="run one workload")
    args = parser.parse_args()
    load = os.getloadavg()
    print(
        f"dispkin {dispkin.__version__}, numpy {np.__version__}, Python {platform.python_version()}, "
        f"{platform.machine()}, {os.cpu_count()} cores, load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; "
        f"wall time (time.perf_counter), median of {args.rounds} alternating rounds, two units of work each"
    )
    for name, make_unit in WORKLOADS.items():
        if args.only in (None, name):
            measure(name, make_unit, args.rounds)


if __name__ == "__main__":
    main()
