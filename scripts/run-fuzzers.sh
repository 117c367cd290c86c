#!/usr/bin/env bash
# Runs each libFuzzer target of tests/fuzz for FUZZ_SECONDS (default 60) from its seed corpus
# and prints one line per target: executions, rate, result. Called by `make fuzz` after the
# build; targets may be named as arguments (default: all). New corpus entries go to
# $FUZZ_BUILD/corpus/<target>, crashes to $FUZZ_BUILD/artifacts/<target>/, logs to
# $FUZZ_BUILD/logs/<target>.log. Exits non-zero if any target found something.
# FUZZ_RUNS=N stops each target after N executions instead (-runs=N; FUZZ_SECONDS then unused).
#
# fuzz_jobs is the Python job-file fuzzer (tests/fuzz/fuzz_jobs.py, atheris): it runs in .venv
# with the installed dispkin package (`make python`); atheris comes from requirements-fuzz.txt,
# installed here on first use. Its seeds are examples/jobs and tests/data/jobs. py_fuzz_urdf and
# py_fuzz_hexapod_json (tests/fuzz/fuzz_loaders.py) fuzz the C++ loaders the same way, through
# the package, without clang: `make fuzz-ci` runs the three for a short time. fuzz_limits_files
# (tests/fuzz/fuzz_limits_files.py, atheris) fuzzes MoveIt and Pilz limits files, alone and named
# by a job; its seeds are tests/fuzz/corpus/fuzz_limits_files. py_fuzz_pickles
# (fuzz_loaders.py pickles, tests/fuzz/fuzz_pickles.py) unpickles corrupted states of every type.
set -uo pipefail
cd "$(dirname "$0")/.."

build=${FUZZ_BUILD:-build/fuzz}
seconds=${FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_pose fuzz_metric fuzz_profile fuzz_path_plan fuzz_hexapod_json fuzz_urdf fuzz_serial_ik fuzz_jobs
  fuzz_limits_files py_fuzz_pickles)
# The dictionary of a target (tests/fuzz/dict/<target>.dict: deep nesting, aliases, huge numbers,
# bytes that are not UTF-8), when it has one; py_<loader> shares the C++ target's.
dict_of() { local d="tests/fuzz/dict/${1#py_}.dict"; [ -f "$d" ] && echo "-dict=$d"; }
venv=${VENV:-.venv}
if [ -n "${FUZZ_RUNS:-}" ]; then stop=(-runs="$FUZZ_RUNS"); seconds="(${FUZZ_RUNS} runs)"; else stop=(-max_total_time="$seconds"); fi
export UBSAN_OPTIONS="print_stacktrace=1"

failed=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t" "$build/logs"
  log="$build/logs/$t.log"
  if [ "$t" = fuzz_jobs ] || [ "$t" = fuzz_limits_files ] || [ "${t#py_}" != "$t" ]; then
    if ! "$venv/bin/python" -c "import atheris" 2>/dev/null; then
      "$venv/bin/python" -m pip install -q -r requirements-fuzz.txt || { echo "$t: cannot install atheris"; failed=1; continue; }
    fi
  fi
  if [ "${t#py_}" != "$t" ]; then
    # py_fuzz_hexapod_json, py_fuzz_urdf: the C++ loaders through the installed package
    # (tests/fuzz/fuzz_loaders.py), from the C++ target's seeds.
    loader=${t#py_fuzz_}
    "$venv/bin/python" tests/fuzz/fuzz_loaders.py "$loader" "${stop[@]}" -timeout=60 $(dict_of "${t#py_}") \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" "$build/corpus/$t" "tests/fuzz/corpus/${t#py_}" >"$log" 2>&1
  elif [ "$t" = fuzz_jobs ]; then
    # The seeds (copied: libFuzzer adds to the first corpus directory only).
    cp -n examples/jobs/*.yaml tests/data/jobs/*.yaml "$build/corpus/$t/"
    # -timeout=60: instrumented, PyYAML reads the 1000-level seed in seconds, not milliseconds.
    FUZZ_JOBS_SCRATCH="$build/jobs_scratch" "$venv/bin/python" tests/fuzz/fuzz_jobs.py "${stop[@]}" -timeout=60 $(dict_of "$t") \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" "$build/corpus/$t" >"$log" 2>&1
  elif [ "$t" = fuzz_limits_files ]; then
    # MoveIt / Pilz limits files (tests/fuzz/fuzz_limits_files.py), read alone and through a job.
    FUZZ_LIMITS_SCRATCH="$build/limits_scratch" "$venv/bin/python" tests/fuzz/fuzz_limits_files.py "${stop[@]}" -timeout=60 \
      $(dict_of "$t") -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" "$build/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1
  else
    "$build/tests/fuzz/$t" "${stop[@]}" $(dict_of "$t") -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" \
      "$build/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1
  fi
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  if [ $rc -eq 0 ]; then
    result="no finding"
  else
    result="FINDING: $(grep -m1 -E 'dispkin fuzz finding|ERROR:|runtime error|Uncaught Python exception' "$log") (see $log)"
    failed=1
  fi
  printf '%-18s %12s executions in %s s (%s/s): %s\n' "$t" "${runs:-?}" "$seconds" "${rate:-?}" "$result"
done
exit $failed
