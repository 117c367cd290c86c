"""Progress of long commands on stderr: what is being done and how far it got.

On a terminal one line is rewritten in place (carriage return), at most every `interval`
seconds; on a pipe or a file (only when forced: ``dispkin plan --progress``) a full line is
written at most every `interval` seconds, so logs stay readable. Disabled, it prints nothing.
"""

import time
from typing import Optional, TextIO


class Progress:
    """Reports stages ("planning", "sampling 1200/33583") to `stream` when enabled."""

    def __init__(self, stream: Optional[TextIO], prefix: str, interval: float = 0.5):
        #: Where to write; None: nothing is written.
        self.stream = stream
        self.prefix = prefix
        self.interval = interval
        self._terminal = bool(stream is not None and stream.isatty())
        self._last = -float("inf")
        self._width = 0

    @classmethod
    def for_stderr(cls, stream: TextIO, prefix: str, force: bool = False, quiet: bool = False) -> "Progress":
        """Enabled when `stream` is a terminal or `force`; never with `quiet`."""
        enabled = not quiet and (force or stream.isatty())
        return cls(stream if enabled else None, prefix)

    @property
    def enabled(self) -> bool:
        """Whether anything is written."""
        return self.stream is not None

    def _write(self, text: str, final: bool = False) -> None:
        if self.stream is None:
            return
        if self._terminal:
            padding = " " * max(0, self._width - len(text))
            self.stream.write("\r" + text + padding + ("\n" if final else ""))
            self._width = 0 if final else len(text)
        else:
            self.stream.write(text + "\n")
        self.stream.flush()

    def stage(self, name: str) -> None:
        """A new stage starts (always shown)."""
        self._last = time.monotonic()
        self._write(f"{self.prefix}: {name}")

    def step(self, name: str, done: int, total: int) -> None:
        """`done` of `total` items of stage `name` (shown at most every `interval` seconds, and at the end)."""
        now = time.monotonic()
        if done < total and now - self._last < self.interval:
            return
        self._last = now
        self._write(f"{self.prefix}: {name} {done}/{total} ({100.0 * done / max(total, 1):.0f} %)")

    def finish(self, text: str = "done") -> None:
        """The last line."""
        self._write(f"{self.prefix}: {text}", final=True)
