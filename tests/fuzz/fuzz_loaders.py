"""atheris (libFuzzer for Python) targets: the C++ loaders through the Python package, as a
user reaches them. ``hexapod_json``: the bytes as a hexapod description
(``Hexapod.from_json``); ``urdf``: the bytes as URDF text (``SerialArm.from_urdf``, chain
``base`` → ``link2`` or ``base_link`` → ``tool0``, or the links of a first line ``@base tip``),
then forward kinematics and static torques at q = 0.

A finding is anything but the documented outcome — a loaded object, or a ValueError naming
what is wrong: another exception, a message that is not text, a crash of the extension (a
signal), a hang (libFuzzer's ``-timeout``) or non-finite output. The C++ code is not
instrumented here (``make fuzz`` builds the instrumented libFuzzer targets with clang); these
run in CI, in seconds, from the seeds and dictionaries of ``tests/fuzz/corpus/fuzz_<target>``
and ``tests/fuzz/dict/fuzz_<target>.dict`` (deep nesting, many attributes, huge numbers, bytes
that are not UTF-8).

``pickles``: the bytes as corruptions of valid pickled states (tests/fuzz/fuzz_pickles.py).

Usage: ``python tests/fuzz/fuzz_loaders.py {hexapod_json,urdf,pickles} [libFuzzer flags] CORPUS...``
"""

import sys

import atheris

with atheris.instrument_imports():
    import numpy as np

    import dispkin


def hexapod_json(data: bytes) -> None:
    try:
        hexapod = dispkin.Hexapod.from_json(data)
    except ValueError as error:
        str(error).encode("utf-8")  # the message is text
        return
    if not np.all(np.isfinite(hexapod.inverse(hexapod.home))):
        raise AssertionError("a loaded hexapod has non-finite legs at home")


def urdf(data: bytes) -> None:
    base, tip = "base_link", "tool0"
    if data.startswith(b"@"):
        header, _, data = data.partition(b"\n")
        names = header[1:].decode("utf-8", "replace").split()
        if len(names) == 2:
            base, tip = names
    if not data.lstrip().startswith(b"<"):
        return  # a path to a file, not a description
    try:
        arm = dispkin.SerialArm.from_urdf(data, base, tip)  # bytes: any byte reaches the parsers
        q = np.zeros(arm.dof)
        pose = arm.forward(q).matrix()
        torques = arm.static_torques(q)
    except ValueError as error:
        str(error).encode("utf-8")
        return
    if not (np.all(np.isfinite(pose)) and np.all(np.isfinite(torques))):
        raise AssertionError("a loaded arm gives non-finite kinematics or torques at q = 0")


def pickles(data: bytes) -> None:
    """The bytes as corruptions of valid pickled states (tests/fuzz/fuzz_pickles.py, imported on
    first use: it plans and re-times the objects whose states it corrupts)."""
    if "fuzz_pickles" not in sys.modules:
        with atheris.instrument_imports():  # its branches guide the fuzzer, as the loaders' do
            import fuzz_pickles  # noqa: F401
    sys.modules["fuzz_pickles"].pickles(data)


TARGETS = {"hexapod_json": hexapod_json, "urdf": urdf, "pickles": pickles}


def main() -> None:
    target = TARGETS[sys.argv.pop(1)]
    atheris.Setup(sys.argv, target)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
