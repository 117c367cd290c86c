"""Runs every ```python block of the Markdown files given, each in a fresh namespace, in the
current directory, with whatever `dispkin` the interpreter imports (the wheel test runs it with
an installed wheel, from an empty directory, so a snippet that reads the checkout fails).

    python run_snippets.py README.md doc/*.md
"""

import pathlib
import re
import sys


def python_blocks(path: pathlib.Path) -> list[str]:
    return re.findall(r"```python\n(.*?)```", path.read_text(encoding="utf-8"), flags=re.S)


def main(paths: list[str]) -> int:
    ran = 0
    for name in paths:
        for block in python_blocks(pathlib.Path(name)):
            exec(compile(block, name, "exec"), {"__name__": "__snippet__"})  # noqa: S102 - our own documentation
            ran += 1
    if ran == 0:
        print(f"run_snippets: no ```python block in {paths}", file=sys.stderr)
        return 1
    import dispkin

    print(
        f"run_snippets: {ran} snippet(s) of {len(paths)} file(s) ran with dispkin {dispkin.__version__} from {pathlib.Path(dispkin.__file__).parent}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
