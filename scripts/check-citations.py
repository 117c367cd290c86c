#!/usr/bin/env python3
"""Keeps dispkin's equation citations pointing at equations that exist (doc/development.md).

The maths lives in doc/*.md, each equation numbered at the end of its line, after two spaces or
more: ``s_k = Σ_{i<k} L_i        (1)``. Code, tests and documents cite them as
``doc/planning.md eq. 21``, ``doc/section-length.md eqs. 25–27`` or ``doc/retiming.md (eq. 28)``.
A citation names its file on its own line: ``(doc/section-length.md eq. 1; screw eq. 4)`` cites
eq. 4 of doc/section-length.md too; so does a citation on the next line, where the text wraps. Inside doc/X.md an ``eq. N`` with no file on its line is
X.md's own.

Checked: every ``eq. N`` / ``eqs. N–M, K`` in include/, src/, python/, doc/, tests/, README.md and
CHANGELOG.md has a
file, the file exists, and every number cited (each one of a range) is an equation of it; every
document numbers its equations once each and in increasing order.

    scripts/check-citations.py [ROOT]      (ROOT: the repository, by default this script's parent)

Prints each offence as FILE:LINE: and exits 1 if there is any, 0 otherwise.
"""

import pathlib
import re
import sys

SCANNED = ("include", "src", "python", "doc", "tests")
TOP_LEVEL = ("README.md", "CHANGELOG.md")
SUFFIXES = {".hpp", ".cpp", ".h", ".py", ".pyi", ".md", ".txt"}
SKIPPED = {"build", ".venv", "__pycache__", "_build"}
LABEL = re.compile(r"\s{2,}\((\d+)\)\s*$")
DOC = re.compile(r"\bdoc/([\w.-]+\.md)\b")
NUMBER = r"\d+(?:\s*[–-]\s*\d+)?"
CITATION = re.compile(r"\beqs?\.\s*(\()?(" + NUMBER + r"(?:\s*(?:,|and)\s*" + NUMBER + r")*)(?(1)\))")


def equation_labels(text):
    """[(line number, label)] of a document, in order."""
    return [(n, int(m.group(1))) for n, line in enumerate(text.splitlines(), 1) if (m := LABEL.search(line))]


def cited_numbers(numbers):
    """Every number of '20, 23', '25–27' or '5 and 6'."""
    out = []
    for part in re.split(r"\s*(?:,|and)\s*", numbers):
        ends = [int(x) for x in re.split(r"\s*[–-]\s*", part)]
        out.extend(range(ends[0], ends[-1] + 1) if len(ends) == 2 else ends)
    return out


def scanned_files(root):
    yield from (root / name for name in TOP_LEVEL if (root / name).is_file())
    for top in SCANNED:
        for path in sorted((root / top).rglob("*")):
            if path.suffix in SUFFIXES and path.is_file() and not SKIPPED & set(path.relative_to(root).parts):
                yield path


def check(root):
    problems = []
    docs = {}
    for path in sorted((root / "doc").glob("*.md")):
        labels = equation_labels(path.read_text(encoding="utf-8"))
        docs[path.name] = {label for _, label in labels}
        last = 0
        for line, label in labels:
            if label <= last:
                problems.append(
                    f"doc/{path.name}:{line}: equation ({label}) after ({last}): number them once each, in order"
                )
            last = max(last, label)
    for path in scanned_files(root):
        relative = path.relative_to(root).as_posix()
        if relative == "scripts/check-citations.py":
            continue
        own = path.name if relative.startswith("doc/") and path.parent == root / "doc" else None
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
        for n, line in enumerate(lines, 1):
            files = [(m.start(), m.group(1)) for m in DOC.finditer(line)]
            before = list(DOC.finditer(lines[n - 2])) if n > 1 else []
            if before:  # a sentence wrapped after naming its file
                files.insert(0, (-1, before[-1].group(1)))
            for m in CITATION.finditer(line):
                named = [name for start, name in files if start < m.start()]
                name = named[-1] if named else own
                text = m.group(0)
                if name is None:
                    problems.append(f"{relative}:{n}: '{text}' names no file (write doc/NAME.md {text})")
                elif name not in docs:
                    problems.append(f"{relative}:{n}: '{text}' cites doc/{name}, which does not exist")
                else:
                    missing = [x for x in cited_numbers(m.group(2)) if x not in docs[name]]
                    if missing:
                        problems.append(
                            f"{relative}:{n}: '{text}' of doc/{name}: no equation "
                            + ", ".join(f"({x})" for x in missing)
                            + " there"
                        )
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[1])
    problems = check(root)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
