"""The resource limits of job files (doc/resource-limits.md), checked while the YAML is read,
before any Python object is built from it: a ten-line file cannot take the stack (nesting
1000 deep), the memory (an alias bomb expands to 10⁹ nodes) or the time of the commands.

The YAML parser yields events one by one without recursion; they are counted here, with every
alias counted as the whole subtree it repeats, so that the composer, the validator and the
builder, which walk the expanded tree, only ever see a bounded one.
"""

import pathlib
from typing import Any, Dict, List, Optional

import yaml

from .model import JobError

#: Largest job file (bytes). 10⁴ moves of a few lines each are about 2 MB.
MAX_FILE_BYTES = 32 * 2**20
#: Deepest nesting of mappings and lists; a job is 6 deep. The composer, the schema validator
#: and the builder recurse once or more per level, within Python's limit of 1000 frames.
MAX_DEPTH = 32
#: Most nodes (mappings, lists, scalars) of the job with every alias expanded: 10⁴ moves of
#: about 20 nodes each are 2·10⁵. Reading, validating and building a job just below it takes
#: about 150 MB and a few seconds (the key path of every node is kept for messages).
MAX_NODES = 500_000
#: Most aliases (*name) in a job: a real job repeats a pose or a tool now and then.
MAX_ALIASES = 10_000
#: Longest scalar (characters): file names and numbers. Python refuses to read an integer of
#: more than 4300 digits anyway.
MAX_SCALAR_CHARS = 4096
#: Most samples `dispkin plan` writes: the trajectory's duration over output.sample_period.
MAX_SAMPLES = 10_000_000
#: Shortest output.sample_period (s): a microsecond, below any controller's cycle.
MIN_SAMPLE_PERIOD = 1e-6


def read_bounded(path: pathlib.Path) -> bytes:
    """The bytes of the job file, refused beyond MAX_FILE_BYTES without being read further."""
    with open(path, "rb") as f:
        data = f.read(MAX_FILE_BYTES + 1)
    if len(data) > MAX_FILE_BYTES:
        raise JobError(f"{path}: the job file is larger than {MAX_FILE_BYTES} bytes, the limit of a job "
                       "(doc/resource-limits.md)")
    return data


class _Collection:
    """A mapping or list being read: its anchor and its nodes (itself and all under it, aliases
    expanded)."""

    __slots__ = ("anchor", "nodes")

    def __init__(self, anchor: Optional[str]):
        self.anchor = anchor
        self.nodes = 1


def check_events(path: pathlib.Path, events: Any) -> None:
    """Raise a JobError ``FILE:LINE:COLUMN: (job): reason`` at the first event of the YAML
    event stream beyond a limit: nesting, expanded nodes, aliases, scalar length."""
    stack: List[_Collection] = []
    anchored: Dict[str, int] = {}  # anchor -> nodes of its subtree, expanded
    total = 0
    aliases = 0

    def fail(event: Any, reason: str) -> JobError:
        mark = event.start_mark
        return JobError(f"{path}:{mark.line + 1}:{mark.column + 1}: (job): {reason} (doc/resource-limits.md)",
                        (), mark.line + 1)

    def count(event: Any, nodes: int) -> None:
        """`nodes` more values at `event`, in the whole job and in the collection being read."""
        nonlocal total
        total += nodes
        if stack:
            stack[-1].nodes += nodes
        if total > MAX_NODES:
            raise fail(event, f"the job expands to more than {MAX_NODES} values (aliases counted as what they repeat)")

    for event in events:
        if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
            if len(stack) >= MAX_DEPTH:
                raise fail(event, f"mappings and lists nest deeper than {MAX_DEPTH} levels")
            count(event, 1)
            stack.append(_Collection(event.anchor))
        elif isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
            done = stack.pop()
            if done.anchor is not None:
                anchored[done.anchor] = done.nodes
            if stack:  # already in the total, value by value
                stack[-1].nodes += done.nodes
        elif isinstance(event, yaml.ScalarEvent):
            if len(event.value) > MAX_SCALAR_CHARS:
                raise fail(event, f"a value of {len(event.value)} characters, more than {MAX_SCALAR_CHARS}")
            if event.anchor is not None:
                anchored[event.anchor] = 1
            count(event, 1)
        elif isinstance(event, yaml.AliasEvent):
            aliases += 1
            if any(open_.anchor == event.anchor for open_ in stack):
                raise fail(event, f"the alias *{event.anchor} is inside its own anchor: a job is a tree, not a cycle")
            if aliases > MAX_ALIASES:
                raise fail(event, f"more than {MAX_ALIASES} aliases")
            count(event, anchored.get(event.anchor, 1))
