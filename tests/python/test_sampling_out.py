"""Sampling into preallocated arrays: `out=` on every sampling method of Trajectory and
OverlappedTrajectory, and TrajectoryCursor, which writes one whole state per call for a control
loop. The numbers are those of the allocating methods bit for bit; a cursor's sample allocates
nothing, however many calls; an unusable `out` is refused by name before anything is written."""

import gc
import math
import sys
import tracemalloc
import weakref

import numpy as np
import pytest

import dispkin
from _helpers import rng_for

Cursor = dispkin.TrajectoryCursor
METHODS = {  # method -> the shape of one sample
    "sample": (4, 4),
    "sample_xyzuvw": (6,),
    "body_twist": (6,),
    "path_position": (),
    "path_velocity": (),
    "path_acceleration": (),
}
TRAJECTORY_ONLY = {"body_acceleration": (6,)}


def pose(x, y, z=0.0, w=0.0):
    return dispkin.Pose.from_xyzuvw([x, y, z, 0.0, 0.0, math.radians(w)])


def tool():
    ms = dispkin.MetricSet()
    ms.add_relative([[0.0, 0.0, 0.15], [0.02, 0.0, 0.1]])
    ms.add_sphere([0.0, 0.0, 0.0], 0.04)
    return ms


def program():
    """LIN, blended CIRC and SPLINE, then a LIN after a sharp corner: many sections and laws, a
    stop inside the path (two rest-to-rest pieces)."""
    a, b, c, d = pose(0, 0), pose(0.3, 0, 0, 10), pose(0.3, 0.2, 0, 30), pose(0, 0.2, 0.05, 40)
    path = dispkin.Path.lin(a, b, pivot=(0, 0, 0.1))
    path.then(dispkin.Path.circ(b, pose(0.45, 0.1, 0, 20), c, pivot=(0, 0, 0.1)), blend=0.03)
    path.then(dispkin.Path.spline([c, pose(0.15, 0.25, 0.02, 35), d], pivot=(0, 0, 0.1)), blend=0.02)
    path.then(dispkin.Path.lin(d, pose(0, 0, 0.05, 40), "screw", pivot=(0, 0, 0.1)))
    return dispkin.plan(path, tool(), dispkin.Limits(0.25, 1.0, 10.0))


@pytest.fixture(scope="module")
def traj():
    t = program()
    assert t.piece_count >= 2 and t.law_count > t.piece_count and len(t.section_lengths()) > 5
    return t


@pytest.fixture(scope="module")
def overlapped():
    a, via, b = pose(0, 0), pose(0.4, 0, 0, 17), pose(0.4, 0.4, 0, 34)
    limits = dispkin.Limits(0.2, 1.0, 8.0)
    before = dispkin.plan(dispkin.Path.lin(a, via), tool(), limits)
    after = dispkin.plan(dispkin.Path.lin(via, b), tool(), limits)
    return dispkin.OverlappedTrajectory(before, after, 0.2)


def bits(a):
    """The bit patterns of float64 numbers: equal exactly when the numbers are equal bit for bit
    (-0.0 and 0.0 differ), flattened to at least one dimension."""
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def test_out_is_written_in_place_and_returned_by_every_sampling_method(traj, overlapped):
    for obj, methods in ((traj, {**METHODS, **TRAJECTORY_ONLY}), (overlapped, METHODS)):
        times = np.linspace(-0.1, obj.duration + 0.1, 37)
        for name, tail in methods.items():
            method = getattr(obj, name)
            out = np.full((len(times),) + tail, np.nan)
            assert method(times, out=out) is out, name
            np.testing.assert_array_equal(bits(out), bits(method(times)), err_msg=name)
            one = np.full(tail if tail else (1,), np.nan)
            assert method(times[5], out=one) is one, name
            np.testing.assert_array_equal(bits(one), bits(method(times[5])), err_msg=name)


def test_a_number_samples_into_a_0d_or_a_1_element_array_where_it_returns_a_float(traj):
    t = 0.37 * traj.duration
    for name in ("path_position", "path_velocity", "path_acceleration"):
        value = getattr(traj, name)(t)
        assert type(value) is float
        for out in (np.full((), np.nan), np.full(1, np.nan)):
            assert getattr(traj, name)(t, out=out) is out
            assert bits(out).tolist() == bits([value]).tolist()
    with pytest.raises(ValueError, match=r"out: expected .* of shape \(\) or \(1,\), got shape \(2,\)"):
        traj.path_velocity(t, out=np.zeros(2))


def test_times_and_out_may_be_the_same_array(traj):
    t = np.linspace(0.0, traj.duration, 11)
    expected = traj.path_position(t)
    assert traj.path_position(t, out=t) is t
    np.testing.assert_array_equal(bits(t), bits(expected))


BAD_OUT = [  # (description, out for 5 times of `sample`, what the message says it got)
    ("a list", [[[0.0] * 4] * 4] * 5, "got list"),
    ("a number", 3.0, "got float"),
    ("int64", np.zeros((5, 4, 4), dtype=np.int64), "got dtype int64"),
    ("float32", np.zeros((5, 4, 4), dtype=np.float32), "got dtype float32"),
    ("big-endian float64", np.zeros((5, 4, 4), dtype=">f8"), "got dtype >f8"),
    ("one sample too few", np.zeros((4, 4, 4)), "got shape (4, 4, 4)"),
    ("flat", np.zeros(80), "got shape (80,)"),
    ("every other row", np.zeros((10, 4, 4))[::2], "got a non-contiguous array (strides (256, 32, 8))"),
    ("Fortran order", np.asfortranarray(np.zeros((5, 4, 4))), "got a non-contiguous array (strides (8, 40, 160))"),
    ("read-only", np.frombuffer(bytes(5 * 16 * 8)).reshape(5, 4, 4), "got a read-only array"),
]


@pytest.mark.parametrize("description, out, got", BAD_OUT, ids=[b[0] for b in BAD_OUT])
def test_an_unusable_out_is_refused_naming_it_and_left_untouched(traj, description, out, got):
    before = np.array(out, copy=True) if isinstance(out, np.ndarray) else None
    with pytest.raises(ValueError) as info:
        traj.sample(np.linspace(0.0, traj.duration, 5), out=out)
    assert str(info.value) == f"out: expected a writeable C-contiguous float64 array of shape (5, 4, 4), {got}"
    if before is not None:
        np.testing.assert_array_equal(out, before)


def test_out_is_checked_for_each_method_and_number_of_times(traj, overlapped):
    with pytest.raises(ValueError, match=r"^out: expected .* of shape \(6,\), got shape \(1, 6\)$"):
        traj.body_twist(0.1, out=np.zeros((1, 6)))
    with pytest.raises(ValueError, match=r"^out: expected .* of shape \(3,\), got shape \(\)$"):
        overlapped.path_acceleration([0.1, 0.2, 0.3], out=np.zeros(()))
    with pytest.raises(ValueError, match=r"^out: expected .* of shape \(2, 6\), got dtype complex128$"):
        traj.body_acceleration([0.1, 0.2], out=np.zeros((2, 6), dtype=complex))


# --- TrajectoryCursor -------------------------------------------------------------------------


def expected_states(traj, times):
    """(N, 15) states in the cursor's layout, from the allocating methods."""
    times = np.asarray(times, dtype=float)
    out = np.empty((len(times), Cursor.SIZE))
    out[:, Cursor.XYZUVW] = traj.sample_xyzuvw(times)
    out[:, Cursor.BODY_TWIST] = traj.body_twist(times)
    out[:, Cursor.PATH_POSITION] = traj.path_position(times)
    out[:, Cursor.PATH_VELOCITY] = traj.path_velocity(times)
    out[:, Cursor.PATH_ACCELERATION] = traj.path_acceleration(times)
    return out


def test_the_layout_is_pose_twist_and_path_state():
    assert Cursor.SIZE == 15
    assert (Cursor.XYZUVW, Cursor.BODY_TWIST) == (slice(0, 6), slice(6, 12))
    assert (Cursor.PATH_POSITION, Cursor.PATH_VELOCITY, Cursor.PATH_ACCELERATION) == (12, 13, 14)


def cursor_states(cursor, times):
    out = np.empty(Cursor.SIZE)
    states = np.empty((len(times), Cursor.SIZE))
    for i, t in enumerate(times):
        assert cursor.sample(t, out) is out
        states[i] = out
    return states


@pytest.mark.parametrize(
    "order", ["forward at 1 kHz", "backward", "random", "beyond the ends", "jumps and next cycles"]
)
def test_the_cursor_gives_the_sampling_methods_numbers_bit_for_bit(traj, order):
    rng = rng_for("cursor_" + order)
    forward = np.arange(0.0, traj.duration + 0.0005, 0.001)
    jumps = rng.uniform(0.0, traj.duration, 2000)
    times = {
        "forward at 1 kHz": forward,
        "backward": forward[::-1],
        "random": rng.uniform(0.0, traj.duration, 5000),
        "beyond the ends": np.concatenate(
            [
                [-1.0, -1e-300, -0.0, 0.0],
                traj.duration + np.array([0.0, 1e-9, 1.0, 1e6]),
                [-5.0, traj.duration * 0.5, 1e9],
            ]
        ),
        # A jump anywhere, then the next cycle, again and again.
        "jumps and next cycles": np.stack([jumps, jumps + 0.001], axis=1).ravel(),
    }[order]
    cursor = traj.cursor()
    got = cursor_states(cursor, times.tolist())
    np.testing.assert_array_equal(bits(got), bits(expected_states(traj, times)))
    assert cursor.t == times[-1]
    # And those of one number at a time (each found by binary search).
    for t, state in list(zip(times, got))[:: max(1, len(times) // 200)]:
        one = np.concatenate(
            [
                traj.sample_xyzuvw(t),
                traj.body_twist(t),
                [traj.path_position(t), traj.path_velocity(t), traj.path_acceleration(t)],
            ]
        )
        np.testing.assert_array_equal(bits(state), bits(one))


def test_the_cursor_keeps_its_state_and_its_trajectory(traj):
    cursor = traj.cursor()
    assert type(cursor) is Cursor and cursor.trajectory is traj
    assert cursor.t is None and cursor.section == 0 and repr(cursor) == "TrajectoryCursor(t=None, section=0)"
    state = cursor.sample(0.8 * traj.duration)  # without out: a new array
    assert state.shape == (15,) and state.dtype == np.float64
    np.testing.assert_array_equal(bits(state), bits(expected_states(traj, [0.8 * traj.duration])[0]))
    assert cursor.t == 0.8 * traj.duration
    assert cursor.section > 0 and repr(cursor) == f"TrajectoryCursor(t={cursor.t!r}, section={cursor.section})"
    # The section is the one where the path position lies.
    s = state[Cursor.PATH_POSITION]
    starts = np.concatenate([[0.0], np.cumsum(traj.section_lengths())])
    assert starts[cursor.section] - 1e-9 <= s <= starts[cursor.section + 1] + 1e-9
    # Two cursors of one trajectory are independent.
    other = traj.cursor()
    assert other.t is None and other.section == 0


def test_the_cursor_keeps_its_trajectory_alive():
    t = program()
    alive = weakref.ref(t)
    cursor, expected = t.cursor(), t.sample_xyzuvw(0.5)
    del t
    gc.collect()
    assert alive() is not None
    np.testing.assert_array_equal(cursor.sample(0.5)[Cursor.XYZUVW], expected)
    del cursor
    gc.collect()
    assert alive() is None


def test_the_cursor_refuses_a_time_that_is_not_finite_and_an_unusable_out(traj):
    cursor = traj.cursor()
    out = np.zeros(15)
    for bad in (math.nan, math.inf, -math.inf):
        with pytest.raises(ValueError, match=f"^t = {bad}: must be finite"):
            cursor.sample(bad, out)
    assert cursor.t is None and not out.any()
    with pytest.raises(
        ValueError, match=r"^out: expected a writeable C-contiguous float64 array of shape \(15,\), got shape \(17,\)$"
    ):
        cursor.sample(0.1, np.zeros(17))
    with pytest.raises(ValueError, match=r"^out: expected .* of shape \(15,\), got a read-only array$"):
        cursor.sample(0.1, np.frombuffer(bytes(120)))
    with pytest.raises(TypeError):
        cursor.sample("0.1", out)


def allocated_over(sample, out, times):
    """Net growth of the memory traced by tracemalloc and of the interpreter's allocated blocks
    over one call of sample(t, out) per time, gc off: (blocks, bytes, peak bytes above the start)."""
    gc.collect()
    gc.disable()
    try:
        blocks, (traced, _) = sys.getallocatedblocks(), tracemalloc.get_traced_memory()
        tracemalloc.reset_peak()
        for t in times:
            sample(t, out)
        blocks_after, (traced_after, peak) = sys.getallocatedblocks(), tracemalloc.get_traced_memory()
    finally:
        gc.enable()
    return blocks_after - blocks, traced_after - traced, peak - traced


def test_a_control_loop_of_cursor_samples_allocates_nothing(traj):
    """10 000 cycles of a 1 kHz loop reusing one `out`: neither the memory traced by tracemalloc
    (numpy reports its array buffers to it) nor the interpreter's count of allocated blocks grows
    with the number of calls, and the traced peak stays within a few objects of the start. A new
    array per call (without `out`) would not leave the peak so low."""
    times = [(k * 0.001) % (traj.duration + 0.5) for k in range(10_000)]  # Python floats, made beforehand
    out = np.empty(Cursor.SIZE)
    sample = traj.cursor().sample
    tracemalloc.start()
    try:
        allocated_over(sample, out, times[:100])  # the first calls may fill caches
        few = allocated_over(sample, out, times[:1_000])
        many = allocated_over(sample, out, times)
        # The same loop with a new array per call, for scale.
        fresh = allocated_over(lambda t, _: sample(t), out, times[:1_000])
    finally:
        tracemalloc.stop()
    blocks, traced, peak = many
    assert abs(blocks - few[0]) <= 2 and abs(blocks) <= 16, (few, many)
    assert abs(traced) <= 512 and abs(traced - few[1]) <= 512, (few, many)
    assert peak <= 512 and peak < fresh[2], (many, fresh)
    assert sys.getrefcount(out) == 2  # no reference to `out` kept by the cursor
