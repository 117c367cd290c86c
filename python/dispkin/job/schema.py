"""Validating a job against its JSON Schema, ``job.schema.json`` (draft 2020-12, shipped with
the package), with messages that say what to write instead.

jsonschema's own messages quote whole sub-documents; here each violation names the offending
key and its place in the file, lists the keys allowed where an unknown one stands, and lists
the alternatives of a choice (a move is exactly one of lin, circ, spline, ptp). NaN, the
infinities and integers beyond ±2^53 are refused before the schema is consulted: JSON Schema
has no word for them.
"""

import json
import math
import pathlib
import re
from typing import Any, Dict, Optional, Tuple

from .model import JobError, KeyPath
from .reader import Source

#: The JSON Schema of job files (draft 2020-12), shipped next to the package's modules.
SCHEMA_PATH = pathlib.Path(__file__).resolve().parent.parent / "job.schema.json"


def load_schema() -> Dict[str, Any]:
    """The job-file JSON Schema as a dict."""
    return json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))


def _alternatives(schema: Dict[str, Any]) -> str:
    """The key sets of a oneOf whose branches each require keys, e.g. "`a` | `b` + `c`"."""
    options = ["`" + "` + `".join(branch.get("required", [])) + "`" for branch in schema.get("oneOf", [])]
    return " | ".join(options)


def _schema_error_message(error: Any) -> Tuple[KeyPath, str]:
    """The key path and a message for one jsonschema ValidationError."""
    key_path: KeyPath = tuple(error.absolute_path)
    if error.validator == "additionalProperties" and isinstance(error.instance, dict):
        allowed = set(error.schema.get("properties", {}))
        extra = sorted((k for k in error.instance if k not in allowed), key=str)  # YAML keys may be numbers
        if extra:
            known = ", ".join(sorted(allowed))
            return key_path + (str(extra[0]),), f"unknown key (allowed here: {known})"
    if error.validator == "oneOf" and isinstance(error.instance, dict):
        present = ", ".join(f"`{k}`" for k in error.instance) or "nothing"
        return key_path, f"expected exactly one of {_alternatives(error.schema)}; found {present}"
    if error.validator in ("minProperties", "maxProperties") and isinstance(error.instance, dict):
        choices = ", ".join(f"`{k}`" for k in error.schema.get("properties", {}))
        return key_path, f"expected exactly one of {choices}; found {len(error.instance)} key(s)"
    if error.validator == "anyOf" and "title" in error.schema:  # a value of one of several shapes
        return key_path, f"{error.instance!r}: expected {error.schema['title']}"
    if error.validator == "required":
        missing = re.match(r"'([^']*)'", error.message)
        return key_path, f"missing required key `{missing.group(1) if missing else error.message}`"
    if error.validator == "enum":
        return key_path, f"{error.instance!r} is not one of {', '.join(repr(v) for v in error.validator_value)}"
    if error.validator in ("minItems", "maxItems") and isinstance(error.instance, list):
        bound = "at least" if error.validator == "minItems" else "at most"
        return key_path, f"expected {bound} {error.validator_value} item(s), got {len(error.instance)}"
    return key_path, error.message


#: Largest integer a job may hold: every integer up to it is a double, as the library reads it
#: (beyond, an integer of 20 digits is a TypeError and one of 400 an OverflowError in Python).
MAX_INTEGER = 2**53


def _not_a_number(value: Any) -> Optional[str]:
    """Why a YAML number is no number of the library's (None when it is one)."""
    if isinstance(value, float) and not math.isfinite(value):
        return f"{value!r}: must be finite"
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > MAX_INTEGER:
        return f"an integer of {value.bit_length()} bits: numbers must be within ±2^53 ({MAX_INTEGER})"
    return None


def _bad_number(value: Any, key_path: KeyPath) -> Optional[Tuple[KeyPath, str]]:
    """The first key path under value holding NaN, an infinity or an integer beyond ±2^53,
    with the reason."""
    reason = _not_a_number(value)
    if reason is not None:
        return key_path, reason
    if isinstance(value, dict):
        for k, v in value.items():
            found = _bad_number(v, key_path + (k,))
            if found is not None:
                return found
    if isinstance(value, list):
        for i, v in enumerate(value):
            found = _bad_number(v, key_path + (i,))
            if found is not None:
                return found
    return None


def validate(source: Source) -> None:
    """Raise a JobError for every schema violation (all of them, in file order, in one message)."""
    import jsonschema

    if not isinstance(source.data, dict):
        raise source.error(
            (),
            f"a job is a mapping of keys (machine, metric_set, moves, limits, ...), got {type(source.data).__name__}",
        )
    bad = _bad_number(source.data, ())
    if bad is not None:
        raise source.error(*bad)
    validator = jsonschema.Draft202012Validator(load_schema())
    errors = []
    for error in validator.iter_errors(source.data):
        key_path, message = _schema_error_message(error)
        errors.append((source.mark(key_path) or (0, 0), key_path, message))
    if errors:
        errors.sort(key=lambda e: e[0])
        first = source.error(errors[0][1], errors[0][2])
        rest = [str(source.error(k, m)) for _, k, m in errors[1:]]
        raise JobError("\n".join([str(first)] + rest), first.key_path, first.line)
