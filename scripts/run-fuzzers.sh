#!/usr/bin/env bash
# Runs each libFuzzer target of tests/fuzz for FUZZ_SECONDS (default 60) from its seed corpus
# and prints one line per target: executions, rate, result. Called by `make fuzz` after the
# build; targets may be named as arguments (default: all). New corpus entries go to
# $FUZZ_BUILD/corpus/<target>, crashes to $FUZZ_BUILD/artifacts/<target>/, logs to
# $FUZZ_BUILD/logs/<target>.log. Exits non-zero if any target found something.
set -uo pipefail
cd "$(dirname "$0")/.."

build=${FUZZ_BUILD:-build/fuzz}
seconds=${FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_pose fuzz_metric fuzz_profile fuzz_path_plan fuzz_hexapod_json fuzz_urdf fuzz_serial_ik)
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"

failed=0
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t" "$build/logs"
  log="$build/logs/$t.log"
  "$build/tests/fuzz/$t" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" \
    "$build/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  if [ $rc -eq 0 ]; then
    result="no finding"
  else
    result="FINDING: $(grep -m1 -E 'dispkin fuzz finding|ERROR:|runtime error' "$log") (see $log)"
    failed=1
  fi
  printf '%-18s %12s executions in %ss (%s/s): %s\n' "$t" "${runs:-?}" "$seconds" "${rate:-?}" "$result"
done
exit $failed
