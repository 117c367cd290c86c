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
# installed here on first use. Its seeds are examples/jobs and tests/data/jobs.
set -uo pipefail
cd "$(dirname "$0")/.."

build=${FUZZ_BUILD:-build/fuzz}
seconds=${FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_pose fuzz_metric fuzz_profile fuzz_path_plan fuzz_hexapod_json fuzz_urdf fuzz_serial_ik fuzz_jobs)
venv=${VENV:-.venv}
if [ -n "${FUZZ_RUNS:-}" ]; then stop=(-runs="$FUZZ_RUNS"); seconds="(${FUZZ_RUNS} runs)"; else stop=(-max_total_time="$seconds"); fi
export UBSAN_OPTIONS="print_stacktrace=1"

failed=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t" "$build/logs"
  log="$build/logs/$t.log"
  if [ "$t" = fuzz_jobs ]; then
    if ! "$venv/bin/python" -c "import atheris" 2>/dev/null; then
      "$venv/bin/python" -m pip install -q -r requirements-fuzz.txt || { echo "fuzz_jobs: cannot install atheris"; failed=1; continue; }
    fi
    # The seeds (copied: libFuzzer adds to the first corpus directory only).
    cp -n examples/jobs/*.yaml tests/data/jobs/*.yaml "$build/corpus/$t/"
    FUZZ_JOBS_SCRATCH="$build/jobs_scratch" "$venv/bin/python" tests/fuzz/fuzz_jobs.py "${stop[@]}" -timeout=20 \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" "$build/corpus/$t" >"$log" 2>&1
  else
    "$build/tests/fuzz/$t" "${stop[@]}" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" \
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
