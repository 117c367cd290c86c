"""Side-by-side timing for the Python comparisons with peers (ik_vs_eaik.py, profile_vs_ruckig.py,
retime_vs_toppra.py): thread CPU time around a block of calls, the contenders' blocks alternating
within each round (the first contender changes from round to round), so that a change of machine
load falls on all of them alike. Wall-clock time on a shared machine swings such ratios
several-fold; CPU time of the calling thread does not count the time other processes take.
"""

from __future__ import annotations

import statistics
import time


def per_call(function, items):
    """A block: function(*item) for every item (function(item) if an item is not a tuple); the
    thread CPU time per item (seconds)."""
    start = time.thread_time_ns()
    for item in items:
        if isinstance(item, tuple):
            function(*item)
        else:
            function(item)
    return (time.thread_time_ns() - start) * 1e-9 / len(items)


def whole_batch(function, items):
    """A block: one call function(items); the thread CPU time per item (seconds)."""
    start = time.thread_time_ns()
    function(items)
    return (time.thread_time_ns() - start) * 1e-9 / len(items)


def repeated(function, repeats):
    """A block: function() `repeats` times; the thread CPU time per call (seconds)."""
    start = time.thread_time_ns()
    for _ in range(repeats):
        function()
    return (time.thread_time_ns() - start) * 1e-9 / repeats


def alternating_rounds(blocks, rounds):
    """{label: [seconds, one per round]}: every round runs each block (a callable returning its
    seconds) once, starting from a different one each round."""
    times = {label: [] for label in blocks}
    labels = list(blocks)
    for r in range(rounds):
        for label in labels[r % len(labels) :] + labels[: r % len(labels)]:
            times[label].append(blocks[label]())
    return times


def median_ratio(numerators, denominators):
    """The median over the rounds of numerator / denominator of the same round."""
    return statistics.median(n / d for n, d in zip(numerators, denominators))
