"""The fuzzers' seed and crash corpus (tests/fuzz/corpus) replayed as tests through the package:
every URDF and hexapod description there loads (a URDF with its kinematics and torques at
q = 0) or is refused with a ValueError, in a child
process (a crash of the extension is a failed test), never anything else. Files named bad_*
must be refused and the others must load. Under `make sanitize-python` this runs with ASan.
"""

import pathlib
import subprocess
import sys

import pytest

CORPUS = pathlib.Path(__file__).resolve().parents[1] / "fuzz" / "corpus"

REPLAY = r"""
import pathlib, sys
import dispkin
for name in sys.argv[2:]:
    data = pathlib.Path(name).read_bytes()
    try:
        if sys.argv[1] == "fuzz_urdf":
            base, tip = "base_link", "tool0"
            if data.startswith(b"@"):
                header, _, data = data.partition(b"\n")
                base, tip = header[1:].decode().split()
            arm = dispkin.SerialArm.from_urdf(data, base, tip)
            arm.forward([0.0] * arm.dof)
            arm.static_torques([0.0] * arm.dof)
        else:
            dispkin.Hexapod.from_json(data)
        print("loaded", pathlib.Path(name).name)
    except ValueError as error:
        str(error).encode("utf-8")
        print("refused", pathlib.Path(name).name)
"""


@pytest.mark.parametrize("target", ["fuzz_urdf", "fuzz_hexapod_json"])
def test_the_corpus_loads_or_is_refused_never_a_crash(target):
    files = sorted((CORPUS / target).iterdir())
    done = subprocess.run(
        [sys.executable, "-c", REPLAY, target, *map(str, files)], capture_output=True, text=True, timeout=300
    )
    assert done.returncode == 0, done.stderr[-3000:]
    outcome = dict(line.split(" ", 1)[::-1] for line in done.stdout.splitlines())
    assert sorted(outcome) == sorted(f.name for f in files)
    for name, result in outcome.items():
        if name.startswith("bad_"):
            assert result == "refused", name
        elif not name.startswith("finding_"):
            assert result == "loaded", name
