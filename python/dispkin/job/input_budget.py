"""The input budget of job files (doc/input-budget.md), checked while the YAML is read,
before any Python object is built from it: a ten-line file cannot take the stack (nesting
1000 deep), the memory (an alias bomb expands to 10⁹ nodes) or the time of the commands.

The YAML parser yields events one by one without recursion; they are counted here, with every
alias counted as the whole subtree it repeats, so that the composer, the validator and the
builder, which walk the expanded tree, only ever see a bounded one.

The limits files a job names (MoveIt, Pilz: :mod:`dispkin.limits_files`) are read by the same
functions; `what` names the kind of file in messages and `fail` makes the error to raise
(a JobError for job files).
"""

import os
import pathlib
import stat
from typing import Any, Callable, Dict, List, Optional

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
#: Most entries of a job's `events`: each plans the rest of the motion anew from its state (a
#: few milliseconds on a path of 10² sections), so 10³ events take seconds, where the node limit
#: alone would allow 10⁵ of them and minutes.
MAX_EVENTS = 1000


#: Bytes read at a time: a file larger than the limit is never read beyond limit + one block.
READ_BLOCK = 2**20

#: Makes the error to raise from a message and its 1-based line (None: the whole file).
ErrorFactory = Callable[[str, Optional[int]], Exception]


def job_error(message: str, line: Optional[int] = None) -> JobError:
    """The JobError of a job file's message (no key: the whole file)."""
    return JobError(message, (), line)


def read_bounded(
    path: pathlib.Path, what: str = "job file", fail: ErrorFactory = job_error, limit: int = MAX_FILE_BYTES
) -> bytes:
    """The bytes of the file, refused beyond `limit` without being read further. A directory,
    a FIFO, a device or a socket is refused before anything is read: it is opened without
    blocking (a FIFO without a writer would wait for one forever) and looked at first.
    OSError when the file cannot be opened (it does not exist, no permission)."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    try:
        status = os.fstat(fd)
    except OSError:
        os.close(fd)
        raise
    if not stat.S_ISREG(status.st_mode):
        os.close(fd)  # (os.fdopen itself refuses a directory, with a less helpful message)
        if stat.S_ISDIR(status.st_mode):
            raise fail(f"{path}: is a directory, not a {what}", None)
        raise fail(f"{path}: is not a regular file (a FIFO, a device or a socket), not a {what}", None)
    with os.fdopen(fd, "rb") as f:
        # The size the file states, then what it holds (it may grow while read; /proc files state 0).
        data = bytearray()
        while status.st_size <= limit and len(data) <= limit:
            block = f.read(READ_BLOCK)
            if not block:
                break
            data += block
    if status.st_size > limit or len(data) > limit:
        raise fail(
            f"{path}: the {what} is larger than {limit} bytes, the limit of a {what} (doc/input-budget.md)", None
        )
    return bytes(data)


def decode_utf8(path: pathlib.Path, data: bytes, what: str = "job file", fail: ErrorFactory = job_error) -> str:
    """The text of the file's bytes; bytes that are not UTF-8 are refused at their line and
    column (of characters), with the byte itself shown."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line_start = data.rfind(b"\n", 0, error.start) + 1
        line = data.count(b"\n", 0, error.start) + 1
        column = len(data[line_start : error.start].decode("utf-8", errors="replace")) + 1
        raise fail(
            f"{path}:{line}:{column}: the {what} is not UTF-8 text: byte 0x{data[error.start]:02x} "
            f"({error.reason}); save it as UTF-8",
            line,
        ) from None


class _Collection:
    """A mapping or list being read: its anchor and its nodes (itself and all under it, aliases
    expanded)."""

    __slots__ = ("anchor", "nodes")

    def __init__(self, anchor: Optional[str]):
        self.anchor = anchor
        self.nodes = 1


def check_events(path: pathlib.Path, events: Any, what: str = "job", fail: ErrorFactory = job_error) -> None:
    """Raise the error ``FILE:LINE:COLUMN: (job): reason`` (`what` for job) at the first event
    of the YAML event stream beyond a limit: nesting, expanded nodes, aliases, scalar length."""
    stack: List[_Collection] = []
    anchored: Dict[str, int] = {}  # anchor -> nodes of its subtree, expanded
    total = 0
    aliases = 0

    def refuse(event: Any, reason: str) -> Exception:
        mark = event.start_mark
        return fail(
            f"{path}:{mark.line + 1}:{mark.column + 1}: ({what}): {reason} (doc/input-budget.md)", mark.line + 1
        )

    def count(event: Any, nodes: int) -> None:
        """`nodes` more values at `event`, in the whole job and in the collection being read."""
        nonlocal total
        total += nodes
        if stack:
            stack[-1].nodes += nodes
        if total > MAX_NODES:
            raise refuse(
                event, f"the {what} expands to more than {MAX_NODES} values (aliases counted as what they repeat)"
            )

    for event in events:
        if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
            if len(stack) >= MAX_DEPTH:
                raise refuse(event, f"mappings and lists nest deeper than {MAX_DEPTH} levels")
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
                raise refuse(event, f"a value of {len(event.value)} characters, more than {MAX_SCALAR_CHARS}")
            if event.anchor is not None:
                anchored[event.anchor] = 1
            count(event, 1)
        elif isinstance(event, yaml.AliasEvent):
            aliases += 1
            if any(open_.anchor == event.anchor for open_ in stack):
                raise refuse(
                    event, f"the alias *{event.anchor} is inside its own anchor: a {what} is a tree, not a cycle"
                )
            if aliases > MAX_ALIASES:
                raise refuse(event, f"more than {MAX_ALIASES} aliases")
            count(event, anchored.get(event.anchor, 1))
