#!/usr/bin/env python3
"""Keeps dispkin's layers pointing down and its namespaces following its folders
(doc/architecture.md).

Every header under include/dispkin/ and every source under src/ belongs to a layer by its
folder: the core (include/dispkin/*.hpp, src/*.cpp), path/, planning/, and the plugins hexapod/
and serial/. A file may include its own layer and the layers below it, never a layer above it,
and one plugin never includes the other. The umbrella header dispkin/dispkin.hpp, which gathers
the whole API, is the one exception.

A file of a plugin opens dispkin's namespace only as the plugin's own, dispkin::hexapod or
dispkin::serial (or one inside it, such as dispkin::serial::detail); a file of the core, path or
planning layers opens dispkin or one inside it that is not a plugin's.

    scripts/check-layers.py [ROOT]      (ROOT: the repository, by default this script's parent)

Prints each offending #include or namespace as FILE:LINE: and exits 1 if there is any, 0
otherwise.

An installed header (include/dispkin/) names nothing of a `detail` namespace in what it makes
public: a declaration at namespace scope or among a class's public members, outside namespace
detail (public_detail.py).
"""

import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from public_detail import public_detail_uses  # noqa: E402

# Layer ranks; the two plugins share a rank and may not include each other.
RANKS = {"core": 0, "path": 1, "planning": 2, "hexapod": 3, "serial": 3}
UMBRELLA = "dispkin/dispkin.hpp"
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
PLUGINS = ("hexapod", "serial")
# What can hide a brace or the word namespace: comments, string and character literals.
NOT_CODE = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)
NAMESPACE = re.compile(r'\bnamespace\s+([A-Za-z_][\w:]*)?\s*\{|[{}]')
NAMED_NAMESPACE_NEXT = re.compile(r'\s*namespace\s+[A-Za-z_]')


def layer_of_include(target):
    """The layer of an include path written as dispkin/..., or None for anything else."""
    parts = target.split("/")
    if parts[0] != "dispkin" or len(parts) < 2:
        return None
    return parts[1] if len(parts) > 2 and parts[1] in RANKS else "core"


def layer_of_file(root, path):
    """The layer a file of include/dispkin/ or src/ belongs to."""
    relative = path.relative_to(root).parts
    inner = relative[2:] if relative[0] == "include" else relative[1:]
    return inner[0] if len(inner) > 1 and inner[0] in RANKS else "core"


def opened_namespaces(text):
    """(line, full name) of every named namespace the text opens, e.g. (12, "dispkin::serial"); one
    that opens another named one at once (`namespace dispkin {` `namespace serial {`) is a step
    towards that one and not reported by itself."""
    code = NOT_CODE.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    stack = []  # one entry per open brace: the namespace's name, "" for anything else
    for match in NAMESPACE.finditer(code):
        if match.group(0) == "}":
            if stack:
                stack.pop()
            continue
        name = match.group(1) or ""
        stack.append(name)
        if name and not NAMED_NAMESPACE_NEXT.match(code, match.end()):
            yield code.count("\n", 0, match.start()) + 1, "::".join(part for part in stack if part)


def namespace_of_layer(layer):
    """The namespace a layer's files open: a plugin's own, dispkin for the core layers."""
    return f"dispkin::{layer}" if layer in PLUGINS else "dispkin"


def namespace_fits(layer, name):
    expected = namespace_of_layer(layer)
    if not (name == expected or name.startswith(expected + "::")):
        return False
    parts = name.split("::")
    return layer in PLUGINS or len(parts) < 2 or parts[1] not in PLUGINS


def violations(root):
    root = pathlib.Path(root)
    files = sorted((root / "include" / "dispkin").rglob("*.hpp")) + sorted((root / "src").rglob("*.[ch]pp"))
    for path in files:
        if path == root / "include" / UMBRELLA:
            continue
        layer = layer_of_file(root, path)
        text = path.read_text(encoding="utf-8")
        for number, name in opened_namespaces(text):
            if name.split("::")[0] == "dispkin" and not namespace_fits(layer, name):
                yield (
                    f"{path.relative_to(root)}:{number}: the {layer} layer opens namespace {name}, "
                    f"not one inside {namespace_of_layer(layer)}"
                )
        if path.is_relative_to(root / "include"):
            for number, declaration in public_detail_uses(text):
                yield f"{path.relative_to(root)}:{number}: a public declaration names detail: {declaration[:120]}"
        for number, line in enumerate(text.splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = layer_of_include(match.group(1))
            if target is None or target == layer:
                continue
            if RANKS[target] > RANKS[layer] or RANKS[target] == RANKS[layer]:
                yield (
                    f"{path.relative_to(root)}:{number}: the {layer} layer includes {match.group(1)} "
                    f"of the {target} layer, which is not below it"
                )


def main(argv):
    root = argv[1] if len(argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    found = list(violations(root))
    for message in found:
        print(message)
    if found:
        print(
            f"check-layers: {len(found)} include(s) point up or across, namespace(s) differ from their "
            "folder or public declaration(s) name detail (doc/architecture.md)"
        )
        return 1
    print(
        "check-layers: every include points down, every namespace follows its folder and no public "
        "declaration names detail"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
