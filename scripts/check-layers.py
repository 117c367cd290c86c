#!/usr/bin/env python3
"""Keeps dispkin's layers pointing down (doc/architecture.md).

Every header under include/dispkin/ and every source under src/ belongs to a layer by its
folder: the core (include/dispkin/*.hpp, src/*.cpp), path/, planning/, and the plugins hexapod/
and serial/. A file may include its own layer and the layers below it, never a layer above it,
and one plugin never includes the other. The umbrella header dispkin/dispkin.hpp, which gathers
the whole API, is the one exception.

    scripts/check-layers.py [ROOT]      (ROOT: the repository, by default this script's parent)

Prints each offending #include as FILE:LINE: and exits 1 if there is any, 0 otherwise.
"""
import pathlib
import re
import sys

# Layer ranks; the two plugins share a rank and may not include each other.
RANKS = {"core": 0, "path": 1, "planning": 2, "hexapod": 3, "serial": 3}
UMBRELLA = "dispkin/dispkin.hpp"
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


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


def violations(root):
    root = pathlib.Path(root)
    files = sorted((root / "include" / "dispkin").rglob("*.hpp")) + sorted((root / "src").rglob("*.[ch]pp"))
    for path in files:
        if path == root / "include" / UMBRELLA:
            continue
        layer = layer_of_file(root, path)
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = layer_of_include(match.group(1))
            if target is None or target == layer:
                continue
            if RANKS[target] > RANKS[layer] or RANKS[target] == RANKS[layer]:
                yield (f"{path.relative_to(root)}:{number}: the {layer} layer includes {match.group(1)} "
                       f"of the {target} layer, which is not below it")


def main(argv):
    root = argv[1] if len(argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    found = list(violations(root))
    for message in found:
        print(message)
    if found:
        print(f"check-layers: {len(found)} include(s) point up or across (doc/architecture.md)")
        return 1
    print("check-layers: every include points down")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
