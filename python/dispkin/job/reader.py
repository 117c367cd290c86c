"""Reading a job file: its YAML, and where every key stands in the text.

A :class:`Source` holds a job file's data together with the line and column of each key path,
so that any later mistake (of the schema, of the values, of planning) can be reported as
``FILE:LINE:COLUMN: key.path: reason``. Numbers follow YAML 1.2: ``1e-3`` is a float, where
PyYAML's YAML 1.1 resolver would read the string '1e-3'. Duplicate keys are refused instead of
silently keeping the last one.
"""

import pathlib
import re
from typing import Any, Dict, Optional, Sequence, Tuple, Union

from . import input_budget
from .model import JobError, KeyPath, format_key_path

try:
    import yaml
except ImportError as error:  # pragma: no cover - pyyaml is a dependency of the package
    raise ImportError("dispkin job files need PyYAML (pip install pyyaml)") from error


class _Loader(yaml.SafeLoader):
    """The safe loader, with YAML 1.2 floats: ``1e-3`` is a number, not the string '1e-3'."""


_Loader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:float"]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(
        r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+]?[0-9]+)?
            |[-+]?(?:[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)
            |[-+]?\.[0-9_]+(?:[eE][-+]?[0-9]+)?
            |[-+]?\.(?:inf|Inf|INF)
            |\.(?:nan|NaN|NAN))$""",
        re.X,
    ),
    list("-+0123456789."),
)

# The same loader on libyaml's C parser and composer (PyYAML's wheels are built with it): the same
# events, nodes and marks, some ten times faster on long programs. A file it finds no valid YAML is
# read again by the pure-Python parser, whose messages say where and why in characters.
_FastLoader: Optional[type] = None
if getattr(yaml, "__with_libyaml__", False):

    class _FastLoader(yaml.CSafeLoader):  # type: ignore[no-redef]
        """_Loader on libyaml."""

    _FastLoader.yaml_implicit_resolvers = _Loader.yaml_implicit_resolvers


# What PyYAML's constructors raise for a scalar their tag cannot make: `!!float abc` (ValueError),
# `!!int` with nothing after it (IndexError), `!!bool maybe` (KeyError), `!!timestamp x`
# (AttributeError), a huge `!!float` (OverflowError).
_UNTYPED = (ValueError, TypeError, OverflowError, LookupError, AttributeError)


class Source:
    """A job file's text, its data, and where each key path is (1-based line, column).

    Limits files are read by it too, under the same input budget: `what` names the kind of
    file in messages ("job", "limits file") and `fail` makes the error to raise (a JobError for
    job files)."""

    def __init__(self, path: pathlib.Path, what: str = "job", fail: input_budget.ErrorFactory = input_budget.job_error):
        #: The file.
        self.path = path
        self._what, self._fail = what, fail
        text = self._read_text(path)
        #: (line, column) of each key path in the file, keys and indices as strings.
        self.marks: Dict[Tuple[str, ...], Tuple[int, int]] = {}
        #: The file's data as YAML gives it (validated later, see dispkin.job.schema).
        self.data: Any = self._parse(text)

    def _read_text(self, path: pathlib.Path) -> str:
        what = f"{self._what} file" if self._what == "job" else self._what
        try:
            data = input_budget.read_bounded(path, what, self._fail)
        except OSError as error:
            reason = f"cannot read the {what}" if self._what == "job" else f"the {what} cannot be read"
            raise self._fail(f"{path}: {reason}: {error.strerror or error}", None) from error
        return input_budget.decode_utf8(path, data, what, self._fail)

    def _parse(self, text: str) -> Any:
        """The data of the YAML text, recording each key path's place on the way."""
        if _FastLoader is not None:
            try:
                return self._parse_with(_FastLoader, text)
            except yaml.YAMLError:
                self.marks.clear()
        try:
            return self._parse_with(_Loader, text)
        except yaml.reader.ReaderError as error:  # a control character: where, from its position
            before = text[: error.position]
            line, column = before.count("\n") + 1, len(before) - (before.rfind("\n") + 1) + 1
            raise self._fail(
                f"{self.path}:{line}:{column}: not valid YAML: {error.reason} (character #x{error.character:04x})",
                line,
            ) from error
        except yaml.YAMLError as error:
            raise self._explained(error) from error

    def _parse_with(self, loader_class: type, text: str) -> Any:
        """_parse with this loader; PyYAML's errors are raised as they are."""
        path, fail = self.path, self._fail
        loader = loader_class(text)  # PyYAML's reader checks for non-printable characters here
        try:
            # The budget first, from the parser's events: nothing is built beyond them.
            input_budget.check_events(path, yaml.parse(text, Loader=loader_class), self._what, fail)
            node = loader.get_single_node()
            if node is None:
                raise fail(f"{path}: the {self._what}{' file' if self._what == 'job' else ''} is empty", None)
            self._walk(node, ())
            try:
                return loader.construct_document(node)
            except _UNTYPED as error:  # `!!float abc`, `!!int` alone: the tag's constructor fails
                raise self._untyped(loader, node, error) from error
        finally:
            loader.dispose()

    def _explained(self, error: Any) -> Exception:
        """The file's error for PyYAML's error."""
        path, fail = self.path, self._fail
        if isinstance(error, yaml.MarkedYAMLError):
            mark = error.problem_mark or error.context_mark
            where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark else str(path)
            return fail(f"{where}: not valid YAML: {error.problem or error}", mark.line + 1 if mark else None)
        return fail(f"{path}: not valid YAML: {error}", None)

    def _untyped(self, loader: Any, root: Any, error: Exception) -> Exception:
        """The error of a scalar its tag cannot make (``!!float abc``, ``!!int 1x``), at the
        first such scalar's line and column (each scalar constructed again, alone, to find it)."""
        pending = [root]
        while pending:  # depth first, in the order of the file (nesting is bounded by now)
            node = pending.pop()
            if isinstance(node, yaml.ScalarNode):
                loader.recursive_objects.clear()  # what the failed construction left behind
                try:
                    loader.construct_object(node)
                except _UNTYPED as failed:
                    mark = node.start_mark
                    value = node.value if len(node.value) <= 200 else node.value[:200] + "…"
                    return self._fail(
                        f"{self.path}:{mark.line + 1}:{mark.column + 1}: not valid YAML: {value!r} is no "
                        f"{node.tag.rsplit(':', 1)[-1]} ({failed})",
                        mark.line + 1,
                    )
            else:
                children = (
                    [n for pair in node.value for n in pair] if isinstance(node, yaml.MappingNode) else list(node.value)
                )
                pending.extend(reversed(children))
        return self._fail(f"{self.path}: not valid YAML: {error}", None)

    def _walk(self, node: Any, key_path: Tuple[str, ...]) -> None:
        self.marks.setdefault(key_path, (node.start_mark.line + 1, node.start_mark.column + 1))
        if isinstance(node, yaml.MappingNode):
            seen = set()
            for key_node, value_node in node.value:
                key = str(key_node.value)
                if key in seen:  # PyYAML would silently keep the last one
                    line, column = key_node.start_mark.line + 1, key_node.start_mark.column + 1
                    where = format_key_path(self._typed(key_path + (key,)))
                    raise self._duplicate(
                        f"{self.path}:{line}:{column}: {where}: duplicate key", key_path + (key,), line
                    )
                seen.add(key)
                self.marks[key_path + (key,)] = (key_node.start_mark.line + 1, key_node.start_mark.column + 1)
                self._walk(value_node, key_path + (key,))
        elif isinstance(node, yaml.SequenceNode):
            for i, item in enumerate(node.value):
                self._walk(item, key_path + (str(i),))

    def _duplicate(self, message: str, key_path: Tuple[str, ...], line: int) -> Exception:
        if self._fail is input_budget.job_error:
            return JobError(message, key_path, line)
        return self._fail(message, line)

    @staticmethod
    def _typed(key_path: Sequence[str]) -> KeyPath:
        return tuple(int(k) if k.isdigit() else k for k in key_path)

    def mark(self, key_path: Sequence[Union[str, int]]) -> Optional[Tuple[int, int]]:
        """(line, column) of the deepest part of key_path that is in the file."""
        keys = tuple(str(k) for k in key_path)
        while keys not in self.marks and keys:
            keys = keys[:-1]
        return self.marks.get(keys)

    def error(self, key_path: Sequence[Union[str, int]], message: str) -> JobError:
        """A JobError ``FILE:LINE:COLUMN: key.path: message``."""
        mark = self.mark(key_path)
        where = f"{self.path}:{mark[0]}:{mark[1]}" if mark else str(self.path)
        return JobError(f"{where}: {format_key_path(key_path)}: {message}", tuple(key_path), mark[0] if mark else None)
