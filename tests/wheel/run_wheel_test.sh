#!/usr/bin/env bash
# The repaired wheel as a newcomer with only Python gets it: installed with pip into a fresh
# venv, then, in a mount namespace where the system's copies of the libraries it bundles
# (Qhull, urdfdom, console_bridge, TinyXML, Orocos KDL, SLEEF) are hidden under empty files, the
# Python snippets of the README and the user guide run from an empty directory, and `dispkin plan` plans an example job.
#   tests/wheel/run_wheel_test.sh WHEEL_DIR WORK_DIR
# Needs root (or CAP_SYS_ADMIN) for `unshare -m`; fails if it cannot hide the libraries.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
wheel_dir=$(cd "$1" && pwd)
work=$2
python=${PYTHON:-python3}

shopt -s nullglob
wheels=("$wheel_dir"/dispkin-*.whl)
[ ${#wheels[@]} -eq 1 ] || { echo "wheel test: expected one wheel in $wheel_dir, found ${#wheels[@]}" >&2; exit 1; }
wheel=${wheels[0]}
echo "wheel test: $(basename "$wheel") ($(du -k "$wheel" | cut -f1) KiB)"

# The libraries auditwheel must have put inside (dispkin.libs/, names with a hash).
bundled=(libqhull_r liburdfdom_model libconsole_bridge libtinyxml liborocos-kdl libsleef)
contents=$("$python" -m zipfile -l "$wheel")
for lib in "${bundled[@]}"; do
  grep -q "dispkin.libs/$lib-" <<<"$contents" || { echo "wheel test: $lib is not bundled in the wheel" >&2; exit 1; }
done

rm -rf "$work"
mkdir -p "$work/run"
work=$(cd "$work" && pwd)
"$python" -m venv "$work/venv"
start=$(date +%s.%N)
"$work/venv/bin/python" -m pip install -q --disable-pip-version-check "$wheel"
echo "wheel test: pip install into a fresh venv took $("$python" -c "import sys; print(round(float(sys.argv[2]) - float(sys.argv[1]), 1))" "$start" "$(date +%s.%N)") s"

# The system's copies, by the names the dynamic loader knows them (all versions present).
hidden=()
for lib in "${bundled[@]}"; do
  while read -r path; do
    real=$(readlink -f "$path")
    [[ " ${hidden[*]-} " == *" $real "* ]] || hidden+=("$real")
  done < <(ldconfig -p | awk -v l="$lib" '$1 ~ "^"l"\\.so" {print $NF}')
done
[ ${#hidden[@]} -gt 0 ] || { echo "wheel test: none of ${bundled[*]} is on this system: nothing to hide" >&2; exit 1; }
: >"$work/empty"

cp "$here/run_snippets.py" "$work/run_snippets.py"
cp "$root/README.md" "$root/doc/user-guide.md" "$work/"
cp "$root/examples/jobs/hexapod_scan.yaml" "$work/hexapod_scan.yaml"
export WHEEL_TEST_HIDDEN="${hidden[*]}" WHEEL_TEST_WORK="$work"
unshare -m --propagation private bash -euo pipefail -c '
  for f in $WHEEL_TEST_HIDDEN; do mount --bind "$WHEEL_TEST_WORK/empty" "$f"; done
  # The hiding works: the system copy no longer loads.
  first=${WHEEL_TEST_HIDDEN%% *}
  if "$WHEEL_TEST_WORK/venv/bin/python" -I -c "import ctypes, sys; ctypes.CDLL(sys.argv[1])" "$first" 2>/dev/null; then
    echo "wheel test: $first still loads inside the namespace" >&2; exit 1
  fi
  echo "wheel test: hid ${WHEEL_TEST_HIDDEN}"
  cd "$WHEEL_TEST_WORK/run"
  "$WHEEL_TEST_WORK/venv/bin/python" -I "$WHEEL_TEST_WORK/run_snippets.py" "$WHEEL_TEST_WORK/README.md" "$WHEEL_TEST_WORK/user-guide.md"
  "$WHEEL_TEST_WORK/venv/bin/python" -I -c "import dispkin, sys; assert hasattr(dispkin, \"SerialArm\"), \"no serial plugin\"; arm = dispkin.SerialArm.from_urdf(dispkin.data.path(\"ur5e.urdf\"), \"base_link\", \"tool0\"); print(\"wheel test: UR5e\", arm.dof, \"joints,\", len(arm.inverse(arm.forward([0.3, -1.2, 1.5, -0.4, 1.1, 0.2]))), \"IK solutions\")"
  "$WHEEL_TEST_WORK/venv/bin/dispkin" plan "$WHEEL_TEST_WORK/hexapod_scan.yaml" -o "$WHEEL_TEST_WORK/run/out" >"$WHEEL_TEST_WORK/plan.log"
  echo "wheel test: dispkin plan wrote $(ls "$WHEEL_TEST_WORK/run/out" | tr "\n" " ")"
'
echo "wheel test: passed"
