"""06 — dispkin in a controller's loop: moves streamed in while the motion runs, a feed hold that
stops on the path, a resumption and a speed override of 50 %, sampled at 1 kHz.

A MotionStream always plans its tail to rest at the last pose it was given, so the motion is safe
whenever the next move is late; a move that comes while the motion runs is joined to it from its
state without a stop (corners blended within 2 mm). Every request at time t leaves what was
sampled before t as it was. The loop samples into one preallocated array (out=), so it does not
allocate per cycle. The plot shows the path speed through the stop and the override. (The C++
twin, with a worker thread that plans while the cycle samples, is 06_control_loop.cpp.)
"""

import math

import numpy as np

import dispkin


def program(count):
    poses = [
        dispkin.Pose.from_xyzuvw([0.08 * k, 0.03 * (k % 2), 0.0, 0.0, 0.0, math.radians(4.0 * k)])
        for k in range(count + 1)
    ]
    return [dispkin.Path.lin(a, b) for a, b in zip(poses, poses[1:])]


tool = dispkin.MetricSet()
tool.add_relative(dispkin.shapes.icosahedron(0.02, [0, 0, 0]))  # around the flange
tool.add_relative(dispkin.shapes.icosahedron(0.02, [0, 0, 0.2]))  # around the tool tip
limits = dispkin.Limits(velocity=0.2, acceleration=1.0, jerk=10.0)

moves = program(12)
stream = dispkin.MotionStream(tool, limits, corner_tolerance=0.002)
stream.append(moves.pop(0), 0.0)

dt, t = 1e-3, 0.0
events = {"stop": 1.5, "resume": 2.5, "override": 3.5}
done_events = set()
speed = np.empty(1)
times, speeds = [], []
while True:
    # Requests: stream a move while less than a second is planned ahead; the events at their times.
    if moves and stream.duration - t < 1.0:
        stream.append(moves.pop(0), t)
    for name, at in events.items():
        if name not in done_events and t >= at:
            done_events.add(name)
            {
                "stop": lambda: stream.stop(t),
                "resume": lambda: stream.resume(t),
                "override": lambda: stream.set_override(t, 0.5),
            }[name]()
    stream.path_velocity(np.array([t]), out=speed)  # one cycle's sample, into the same array
    times.append(t)
    speeds.append(speed[0])
    if not moves and len(done_events) == len(events) and stream.done(t):
        break
    t += dt

speeds = np.array(speeds)
print(f"{len(times)} cycles of 1 ms; {stream.leg_count} leg(s): the motion never stopped between moves")
print(
    f"highest path speed {speeds.max():.4f} m/s (limit {limits.velocity}); at rest during the hold: "
    f"{bool(np.all(speeds[(np.array(times) > 2.2) & (np.array(times) < 2.5)] < 1e-9))}"
)
after = np.array(times) > events["override"] + 0.5
print(f"after the override: at most {speeds[after].max():.4f} m/s (50 % of {limits.velocity})")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:  # plotting is optional
    plt = None
if plt is not None:
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(times, speeds, label="path speed (the bound of every tool point)")
    for name, at in events.items():
        ax.axvline(at, color="grey", linestyle="--")
        ax.text(at, limits.velocity * 1.02, name, ha="center")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("m/s")
    ax.set_ylim(0, limits.velocity * 1.12)
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig("06_control_loop.png", dpi=120)
    print("wrote 06_control_loop.png")
