"""Every public name of the package has a docstring.

Public: the classes, functions, methods and properties of the compiled module dispkin._core and
its submodule shapes, and the module-level functions and classes (with their methods and
properties) that the Python modules of the package define; names starting with "_" are
private, except ``__init__`` (a constructor's arguments need explaining). A pybind11 docstring
starts with the generated signature line(s); each signature must be followed by text, so every
overload of an overloaded function is documented too.
"""

import importlib
import inspect
import re

import dispkin
from dispkin import _core

PYTHON_MODULES = [
    "dispkin",
    "dispkin.jobs",
    "dispkin.job",
    "dispkin.job.reader",
    "dispkin.job.schema",
    "dispkin.job.model",
    "dispkin.job.builder",
    "dispkin.job.events",
    "dispkin.job.planning",
    "dispkin.job.sampling",
    "dispkin.job.summary",
    "dispkin.job.export",
    "dispkin.job.violations",
    "dispkin.job.machine_limits",
    "dispkin.job.metric_set_section",
    "dispkin.job.move_sequence",
    "dispkin.cli",
    "dispkin.progress",
    "dispkin.commands",
    "dispkin.demo",
    "dispkin.limits_files",
    "dispkin.plots",
    "dispkin.shapes",
]


def undocumented_pybind(name, obj):
    """'' if obj's docstring documents it (every overload), else why not."""
    text = obj.__doc__ or ""
    if isinstance(obj, property):
        return "" if text.strip() else "no docstring"
    short = name.rsplit(".", 1)[-1]
    signature = re.compile(rf"^(\d+\. )?{re.escape(short)}\(.*$", re.M)
    lines = [line for line in text.splitlines() if line.strip() != "Overloaded function."]
    text = "\n".join(lines)
    starts = list(signature.finditer(text))
    if not starts:
        return "" if text.strip() else "no docstring"
    chunks = []
    for i, m in enumerate(starts):
        end = starts[i + 1].start() if i + 1 < len(starts) else len(text)
        if m.group(0).startswith(f"{short}(*args, **kwargs)") and i + 1 < len(starts):
            continue  # the header of an overloaded function
        chunks.append(text[m.end() : end])
    return "" if all(c.strip() for c in chunks) else "a signature without text"


def core_names():
    """(qualified name, object) of every public name of dispkin._core."""
    for name, obj in vars(_core).items():
        if name.startswith("_"):
            continue
        if inspect.ismodule(obj):
            for sub, fn in vars(obj).items():
                if not sub.startswith("_"):
                    yield f"{name}.{sub}", fn
            continue
        yield name, obj
        if inspect.isclass(obj):
            for member, value in vars(obj).items():
                if member == "__init__" or not member.startswith("_"):
                    yield f"{name}.{member}", value.__func__ if isinstance(value, staticmethod) else value


def test_every_public_name_of_the_compiled_module_is_documented():
    problems = []
    for name, obj in core_names():
        if inspect.isclass(obj) or inspect.ismodule(obj):
            reason = "" if (obj.__doc__ or "").strip() else "no docstring"
        else:
            reason = undocumented_pybind(name, obj)
        if reason:
            problems.append(f"dispkin._core.{name}: {reason}")
    assert _core.shapes.__doc__.strip()
    assert not problems, "\n".join(problems)


def test_every_public_name_of_the_python_modules_is_documented():
    problems = []
    for module_name in PYTHON_MODULES:
        module = importlib.import_module(module_name)
        if not (module.__doc__ or "").strip():
            problems.append(module_name)
        for name, obj in vars(module).items():
            if name.startswith("_") or getattr(obj, "__module__", None) != module_name:
                continue
            if not (inspect.isfunction(obj) or inspect.isclass(obj)):
                continue
            if not (obj.__doc__ or "").strip():
                problems.append(f"{module_name}.{name}")
            if inspect.isclass(obj):
                for member, value in vars(obj).items():
                    if member.startswith("_"):
                        continue
                    if isinstance(value, (staticmethod, classmethod)):
                        value = value.__func__
                    if (inspect.isfunction(value) or isinstance(value, property)) and not (value.__doc__ or "").strip():
                        problems.append(f"{module_name}.{name}.{member}")
    assert not problems, "\n".join(problems)


def test_the_check_sees_a_missing_docstring():
    """The signature-stripping rule does not take a bare signature for documentation."""

    class Bare:
        __doc__ = "f(self: X, a: int) -> None\n"

    class Overloaded:
        __doc__ = (
            "f(*args, **kwargs)\nOverloaded function.\n\n1. f(a: int) -> None\n\nFirst.\n\n2. f(a: str) -> None\n\n"
        )

    class Documented:
        __doc__ = "f(self: X, a: int) -> None\n\nDoes f.\n"

    assert undocumented_pybind("X.f", Bare()) == "a signature without text"
    assert undocumented_pybind("f", Overloaded()) == "a signature without text"
    assert undocumented_pybind("X.f", Documented()) == ""
    assert dispkin.Path.ptp.__doc__ and not undocumented_pybind("Path.ptp", dispkin.Path.ptp)
