"""The type stubs python/dispkin/_core.pyi against stubs generated from the built module.

pybind11-stubgen (requirements-dev.txt; ``make stubs`` writes the same stubs to build/stubs)
generates stubs of dispkin._core from the signatures and docstrings pybind11 records. The
module is the truth; the checked-in stubs are hand-written so that they can say more. The rule:

* every class, function, method and property of the generated stubs is in _core.pyi (methods
  that ``object`` already has with the same meaning, such as ``__repr__``, excepted), and every
  public name of _core.pyi is in the generated stubs;
* a function or method has the same parameters: names, kinds (positional, keyword-only), and
  defaults, equal as Python values (``(0, 0, 0) == (0.0, 0.0, 0.0)``); a default the generator
  cannot write as an expression (``...``) only has to be there. ``argN`` is pybind11's name for
  an unnamed argument, which can only be passed by position: any name matches it;
* static methods are static in both, properties are properties in both, with a setter in
  _core.pyi exactly when the module has one;
* overloads: every generated signature matches one hand-written signature of that name, and
  every hand-written one matches a generated one (hand-written overloads may split one module
  signature by argument type, e.g. ``point_speed`` returns a float for one point);
* types are NOT compared: _core.pyi may spell them more precisely than the module's docstrings
  (``_ArrayLike`` for ``typing.Any``, ``List[Profile]`` for ``list``).

The submodule ``dispkin._core.shapes`` is typed in _core.pyi as ``shapes: _ShapesModule``, a
Protocol whose static methods are its functions; they are compared with the generated
``_core/shapes.pyi`` by the same rule.
"""

import ast
import pathlib
import subprocess
import sys

import pytest

pytest.importorskip("pybind11_stubgen")

ROOT = pathlib.Path(__file__).resolve().parents[2]
HAND_WRITTEN = ROOT / "python" / "dispkin" / "_core.pyi"
MISSING = object()  # no default
UNPRINTABLE = object()  # a default the generator wrote as `...`
# Methods every object has; the generated stubs list some (__repr__) for every class.
OBJECT_METHODS = {name for name in dir(object) if name != "__init__"}


def generate(directory):
    """Runs pybind11-stubgen on dispkin._core into `directory`; fails on any error it reports
    (e.g. a C++ type in a signature, which means a binding registered in the wrong order)."""
    result = subprocess.run(
        [sys.executable, "-m", "pybind11_stubgen", "--exit-code", "-o", str(directory), "dispkin._core"],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    package = pathlib.Path(directory) / "dispkin" / "_core"
    return (package / "__init__.pyi").read_text(), (package / "shapes.pyi").read_text()


def default_value(node):
    if node is None:
        return MISSING
    if isinstance(node, ast.Constant) and node.value is Ellipsis:
        return UNPRINTABLE
    return ast.literal_eval(node)


def parameters(function, drop_self):
    """((name, kind, default), ...) of a def, without self."""
    a = function.args
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
    out = [(p.arg, "positional", default_value(d)) for p, d in zip(positional, defaults)]
    if a.vararg:
        out.append((a.vararg.arg, "*args", MISSING))
    out += [(p.arg, "keyword-only", default_value(d)) for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    if a.kwarg:
        out.append((a.kwarg.arg, "**kwargs", MISSING))
    return tuple(out[1:] if drop_self else out)


def decorators(function):
    names = set()
    for d in function.decorator_list:
        text = ast.unparse(d)
        names.add(text.rsplit(".", 1)[-1] if text.endswith("overload") else text)
    return names


def members(body, prefix, in_class):
    """name -> {"kind": ..., "signatures": [...], "setter": bool} for the defs and classes of a body."""
    out = {}
    for node in body:
        if isinstance(node, ast.ClassDef):
            out[prefix + node.name] = {"kind": "class", "signatures": [], "setter": False}
            out.update(members(node.body, prefix + node.name + ".", True))
        elif isinstance(node, ast.FunctionDef):
            names = decorators(node)
            key = prefix + node.name
            if any(n.endswith(".setter") for n in names):
                out[key]["setter"] = True
                continue
            kind = (
                "property"
                if "property" in names
                else "staticmethod"
                if "staticmethod" in names
                else ("method" if in_class else "function")
            )
            entry = out.setdefault(key, {"kind": kind, "signatures": [], "setter": False})
            assert entry["kind"] == kind, key
            entry["signatures"].append(parameters(node, drop_self=in_class and kind != "staticmethod"))
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            out[prefix + node.target.id] = {"kind": "attribute", "signatures": [], "setter": False}
        elif isinstance(node, ast.ImportFrom) and node.level == 1:  # `from . import shapes`: a submodule
            for alias in node.names:
                out[prefix + (alias.asname or alias.name)] = {"kind": "attribute", "signatures": [], "setter": False}
    return out


def same_parameters(generated, hand):
    if len(generated) != len(hand):
        return False
    for (g_name, g_kind, g_default), (h_name, h_kind, h_default) in zip(generated, hand):
        unnamed = g_name.startswith("arg") and g_name[3:].isdigit()
        if (g_name != h_name and not unnamed) or g_kind != h_kind:
            return False
        if g_default is MISSING or h_default is MISSING:
            if g_default is not h_default:
                return False
        elif g_default is not UNPRINTABLE and (h_default is UNPRINTABLE or g_default != h_default):
            return False
    return True


def hand_written(path=HAND_WRITTEN):
    """The members of _core.pyi, with the _ShapesModule protocol's static methods as shapes.*."""
    tree = ast.parse(path.read_text())
    found = members(tree.body, "", False)
    for key in [k for k in found if k.startswith("_ShapesModule.")]:
        entry = found.pop(key)
        entry["kind"] = "function"
        found["shapes." + key.split(".", 1)[1]] = entry
    return {k: v for k, v in found.items() if not k.split(".")[0].startswith("_") or k == "__version__"}


def generated_members(directory):
    core, shapes = generate(directory)
    found = members(ast.parse(core).body, "", False)
    found.update(members(ast.parse(shapes).body, "shapes.", False))
    return {k: v for k, v in found.items() if k.rsplit(".", 1)[-1] not in OBJECT_METHODS | {"__all__"}}


def mismatches(generated, hand):
    """Every way the hand-written stubs differ from the generated ones (empty: they agree)."""
    problems = []
    for name, g in sorted(generated.items()):
        h = hand.get(name)
        if h is None:
            problems.append(f"{name}: in the module, missing from _core.pyi")
            continue
        if g["kind"] != h["kind"]:
            problems.append(f"{name}: a {g['kind']} in the module, a {h['kind']} in _core.pyi")
            continue
        if g["setter"] != h["setter"]:
            problems.append(f"{name}: setter in the module: {g['setter']}, in _core.pyi: {h['setter']}")
        for signature in g["signatures"]:
            if not any(same_parameters(signature, other) for other in h["signatures"]):
                problems.append(
                    f"{name}: module signature {format_signature(signature)} not in _core.pyi "
                    f"({', '.join(format_signature(s) for s in h['signatures'])})"
                )
        for signature in h["signatures"]:
            if not any(same_parameters(other, signature) for other in g["signatures"]):
                problems.append(f"{name}: _core.pyi signature {format_signature(signature)} not in the module")
    for name in sorted(set(hand) - set(generated)):
        if name.rsplit(".", 1)[-1] not in OBJECT_METHODS:
            problems.append(f"{name}: in _core.pyi, not in the module")
    return problems


def format_signature(signature):
    parts = []
    for name, kind, default in signature:
        text = {"*args": "*", "**kwargs": "**"}.get(kind, "") + name
        if default is UNPRINTABLE:
            text += "=..."
        elif default is not MISSING:
            text += f"={default!r}"
        parts.append(("*, " if kind == "keyword-only" else "") + text)
    return "(" + ", ".join(parts) + ")"


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    return generated_members(tmp_path_factory.mktemp("stubs"))


def test_hand_written_stubs_match_the_generated_ones(generated):
    problems = mismatches(generated, hand_written())
    assert not problems, "\n".join(problems)


def test_the_comparison_finds_mismatches(generated, tmp_path):
    """The rule above is enforced: a renamed parameter, a changed default, a missing method, a
    property stubbed as a method and a stub of a name the module lacks are each reported."""
    text = HAND_WRITTEN.read_text()
    broken = {
        "def add_sphere(self, center:": "def add_sphere(self, centre:",
        "tol: float = 1e-9": "tol: float = 1e-8",
        "    def reduce_to_hull(self) -> MetricSet: ...\n": "",
        "    @property\n    def point_count(self) -> int: ...": "    def point_count(self) -> int: ...",
        "class Limits:": "def gone() -> None: ...\n\nclass Limits:",
    }
    expected = ["MetricSet.add_sphere", "Pose.is_approx", "MetricSet.reduce_to_hull", "MetricSet.point_count", "gone"]
    for (old, new), name in zip(broken.items(), expected):
        assert old in text, old
        path = tmp_path / "broken.pyi"
        path.write_text(text.replace(old, new, 1))
        problems = mismatches(generated, hand_written(path))
        assert any(p.startswith(name + ":") for p in problems), (old, problems)
