"""Equation citations and the benchmark table (doc/development.md, "Citing the maths"): the
repository passes scripts/check-citations.py and benchmarks/results_table.py --check, and each
reports a citation without a file, an equation or file that does not exist, numbers out of order,
and a figure its dated entry does not hold, with file and line."""

import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
EQ, EQS = "eq" + ".", "eqs" + "."  # so that this file's own examples are not citations of the repository
CITATIONS = ROOT / "scripts" / "check-citations.py"
RESULTS = ROOT / "benchmarks" / "results_table.py"


def run(*args):
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True)


def write(root, relative, text):
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")


def test_the_repository_cites_equations_that_exist():
    result = run(CITATIONS, ROOT)
    assert result.returncode == 0, result.stdout


def test_benchmark_table_is_what_the_script_writes():
    result = run(RESULTS, "--check")
    assert result.returncode == 0, result.stdout


DOC = f"# Planning\n\n```text\ns = a + b        (1)\nv = s / t        (2)\n```\n\nBy (1), {EQ} 2 follows.\n"


def test_resolved_citations_pass(tmp_path):
    write(tmp_path, "doc/planning.md", DOC)
    write(
        tmp_path,
        "src/planner.cpp",
        f"// The sum (doc/planning.md {EQ} 1; its rate {EQ} 2).\n"
        f"// Both (doc/planning.md {EQS} 1–2), wrapped: (doc/planning.md\n// {EQS} 1, 2).\n",
    )
    result = run(CITATIONS, tmp_path)
    assert result.returncode == 0, result.stdout


def test_each_bad_citation_is_reported_with_its_line(tmp_path):
    write(tmp_path, "doc/planning.md", DOC)
    write(
        tmp_path,
        "include/dispkin/planner.hpp",
        f"#pragma once\n//! The sum ({EQ} 1).\n//! (doc/planning.md {EQ} 3)\n//! (doc/missing.md {EQ} 1)\n"
        f"//! (doc/planning.md {EQS} (1–4))\n",
    )
    result = run(CITATIONS, tmp_path)
    assert result.returncode == 1
    assert f"include/dispkin/planner.hpp:2: '{EQ} 1' names no file" in result.stdout
    assert f"include/dispkin/planner.hpp:3: '{EQ} 3' of doc/planning.md: no equation (3) there" in result.stdout
    assert f"include/dispkin/planner.hpp:4: '{EQ} 1' cites doc/missing.md, which does not exist" in result.stdout
    assert (
        f"include/dispkin/planner.hpp:5: '{EQS} (1–4)' of doc/planning.md: no equation (3), (4) there" in result.stdout
    )


def test_equations_out_of_order_or_twice_are_reported(tmp_path):
    write(tmp_path, "doc/planning.md", "```text\na        (1)\nb        (3)\nc        (2)\nd        (3)\n```\n")
    result = run(CITATIONS, tmp_path)
    assert result.returncode == 1
    assert "doc/planning.md:4: equation (2) after (3)" in result.stdout
    assert "doc/planning.md:5: equation (3) after (3)" in result.stdout


def test_a_figure_not_in_its_entry_is_refused(tmp_path):
    write(tmp_path, "history/2026-12-01-planner.md", "# Planner\n\n| `plan_lin` | 50.3 µs |\n")
    write(tmp_path, "figures.tsv", "planner\t`plan_lin`\t50.3 µs\t2026-12-01-planner.md\n")
    assert run(RESULTS, "--root", tmp_path).returncode == 0
    assert "[2026-12-01](history/2026-12-01-planner.md)" in (tmp_path / "RESULTS.md").read_text(encoding="utf-8")
    assert run(RESULTS, "--root", tmp_path, "--check").returncode == 0
    write(tmp_path, "figures.tsv", "planner\t`plan_lin`\t40 µs\t2026-12-01-planner.md\n")
    result = run(RESULTS, "--root", tmp_path, "--check")
    assert result.returncode == 1
    assert "figures.tsv:1: no line of 2026-12-01-planner.md holds both '`plan_lin`' and '40 µs'" in result.stdout
    write(tmp_path, "figures.tsv", "planner\t`plan_lin`\t50.3 µs\t2026-12-02-gone.md\n")
    assert "history entry '2026-12-02-gone.md' does not exist" in run(RESULTS, "--root", tmp_path).stdout
