"""Reading a long job file: libyaml's C parser against PyYAML's pure-Python one, and the whole of
`load_job` (reading, schema, building the moves), on a generated 2000-move pose list.

    .venv/bin/python benchmarks/job_reading.py [--moves 2000] [--rounds 5]

Thread CPU time per read, the two parsers alternating within each round (cpu_rounds.py), medians.
"""

import argparse
import pathlib
import statistics
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import cpu_rounds  # noqa: E402

from dispkin import jobs  # noqa: E402
from dispkin.job import reader  # noqa: E402


def pose_list_job(moves: int) -> str:
    """A CAM-like program: a sphere and a tip, LINs of a few millimetres, every corner blended."""
    lines = [
        "metric_set:",
        "  points:",
        "    - {shape: sphere, radius: 0.1}",
        "    - {shape: icosahedron, radius: 0.02, center: [0, 0, 0.2]}",
        "start: {xyzuvw: [0, 0, 0, 0, 0, 0]}",
        "moves:",
    ]
    for k in range(1, moves + 1):
        x, y = 0.002 * k, 0.004 * (k % 2)
        blend = ", blend: 0.0005" if k > 1 else ""
        lines.append(f"  - {{lin: {{to: {{xyzuvw: [{x:.4f}, {y:.4f}, 0, 0, 0, {0.001 * k:.4f}]}}}}{blend}}}")
    lines.append("limits: {velocity: 0.1, acceleration: 1.0, jerk: 10}")
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--moves", type=int, default=2000)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as directory:
        job = pathlib.Path(directory) / "long.yaml"
        job.write_text(pose_list_job(args.moves))
        size = job.stat().st_size
        fast = reader._FastLoader

        def read(loader):
            def block():
                reader._FastLoader = loader
                try:
                    return cpu_rounds.repeated(lambda: reader.Source(job), 1)
                finally:
                    reader._FastLoader = fast

            return block

        times = cpu_rounds.alternating_rounds(
            {
                "libyaml": read(fast),
                "pure Python": read(None),
                "load_job": lambda: cpu_rounds.repeated(lambda: jobs.load_job(job), 1),
            },
            args.rounds,
        )
    print(f"{args.moves} moves, {size} bytes; medians of {args.rounds} rounds")
    for label, seconds in times.items():
        print(f"  {label:12s} {statistics.median(seconds) * 1e3:8.1f} ms")
    print(f"  pure Python / libyaml: {cpu_rounds.median_ratio(times['pure Python'], times['libyaml']):.1f}")


if __name__ == "__main__":
    main()
