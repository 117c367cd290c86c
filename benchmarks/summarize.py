#!/usr/bin/env python3
"""Turn Google Benchmark JSON files (each run with --benchmark_repetitions=N) into the Markdown
table of a dated entry of benchmarks/history/. Per benchmark: the median wall time per call (with several
files, the median of the runs' medians and the range of those medians), items/s and GB/s
(10^9 bytes/s) derived from it. Standard library only.

    python3 benchmarks/summarize.py run1.json [run2.json ...]
"""

import json
import statistics
import sys

_UNIT_NS = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def _format_time(ns):
    if ns >= 1e6:
        return f"{ns / 1e6:.2f} ms"
    if ns >= 1e3:
        return f"{ns / 1e3:.1f} µs"
    return f"{ns:.1f} ns"


def _format_rate(value):
    for factor, prefix in ((1e9, " G"), (1e6, " M"), (1e3, " k")):
        if value >= factor:
            return f"{value / factor:.4g}{prefix}"
    return f"{value:.4g}"


def _medians(path):
    """run name -> (median wall ns, items per call or None, bytes per call or None)."""
    with open(path, encoding="utf-8") as handle:
        data = json.load(handle)
    out = {}
    for entry in data["benchmarks"]:
        if entry.get("run_type") != "aggregate" or entry.get("aggregate_name") != "median":
            continue
        ns = entry["real_time"] * _UNIT_NS[entry.get("time_unit", "ns")]
        # Google Benchmark divides counters by CPU time; times it back to get the count per call.
        cpu_seconds = entry["cpu_time"] * _UNIT_NS[entry.get("time_unit", "ns")] * 1e-9
        items = entry.get("items_per_second")
        size = entry.get("bytes_per_second")
        out[entry["run_name"]] = (
            ns,
            items * cpu_seconds if items else None,
            size * cpu_seconds if size else None,
        )
    return out


def main(paths):
    runs = [_medians(p) for p in paths]  # counters are taken from the last file
    names = list(runs[-1])
    several = len(runs) > 1
    header = "| benchmark | median time / call |" + (" range over runs |" if several else "")
    print(header + " items/s | GB/s |")
    print("|---|---:|" + ("---:|" if several else "") + "---:|---:|")
    for name in names:
        times = [run[name][0] for run in runs if name in run]
        _, items, size = runs[-1][name]
        t = statistics.median(times)
        row = f"| `{name}` | {_format_time(t)} |"
        if several:
            row += f" {_format_time(min(times))} – {_format_time(max(times))} |"
        row += f" {_format_rate(round(items) / (t * 1e-9)) if items else '—'} |"
        row += f" {f'{round(size) / t:.2f}' if size else '—'} |"
        print(row)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
