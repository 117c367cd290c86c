"""The rows of the bad-input table (tests/python/test_bad_input_table.py) and what the rows of
every API area share: `row`, `accepted` and `section` append to R, in the order the area
modules of this package are imported; the objects most rows start from (a metric set, a
hexapod, poses, a line, limits); the temporary directory of the files rows write.
"""

import atexit
import json
import math
import pathlib
import shutil
import tempfile

import numpy as np

import dispkin

NAN, INF = float("nan"), float("inf")


def good_set():
    s = dispkin.MetricSet()
    s.add_relative(np.eye(3))
    return s


def collinear_set():
    s = dispkin.MetricSet()
    s.add_relative([[0, 0, 0], [1, 0, 0], [2, 0, 0]])
    return s


def hexapod():
    return dispkin.Hexapod.symmetric(0.15, math.radians(20), 0.10, math.radians(20), 0.20, 0.15, 0.32, 0.01)


def hexapod_json(**change):
    d = json.loads(hexapod().to_json())
    d.update(change)
    return json.dumps(d)


LEGS = json.loads(hexapod().to_json())["legs"]


def leg_changed(**change):
    legs = json.loads(json.dumps(LEGS))
    legs[0].update(change)
    return legs


def without(key):
    d = json.loads(hexapod().to_json())
    del d[key]
    return json.dumps(d)


A = dispkin.Pose()
B = dispkin.Pose.from_xyzuvw([0.1, 0.0, 0.0, 0.0, 0.0, 0.5])
C = dispkin.Pose.from_xyzuvw([0.1, 0.1, 0.0, 0.0, 0.0, 0.0])
XI = [0.1, 0.0, 0.0, 0.0, 0.0, 1.0]
LINE = dispkin.Path.lin(A, B)
LIMITS = dispkin.Limits(0.1, 1.0, 10.0)
TRAPEZOID_LIMITS = dispkin.Limits(0.1, 1.0)


def trajectory():
    return dispkin.plan(dispkin.Path.lin(hexapod().home, hexapod().home * B), good_set(), LIMITS)


def overlapped():
    """A LIN to B and one on to C, overlapped by 0.1 s."""
    return dispkin.OverlappedTrajectory(
        dispkin.plan(LINE, good_set(), LIMITS), dispkin.plan(dispkin.Path.lin(B, C), good_set(), LIMITS), 0.1
    )


# (entry point, bad input, call, exception, message fragment). The fragment is matched with
# re.search after re.escape, so write it literally; it contains the argument and the value.
R = []
_SECTION = [None]


def section(title):
    """Rows from here on form a section of the table under `title`."""
    _SECTION[0] = title


def row(entry, bad, call, exc, fragment, xfail=None):
    R.append(
        dict(
            entry=entry, bad=bad, call=call, exc=exc, fragment=fragment, xfail=xfail, section=_SECTION[0], accepted=None
        )
    )


def accepted(entry, bad, call, check, reason):
    """A row whose input is accepted by design (`reason`): the call returns, and check(result)
    holds the documented behaviour."""
    R.append(
        dict(
            entry=entry,
            bad=bad,
            call=call,
            exc=None,
            fragment="",
            xfail=None,
            section=_SECTION[0],
            accepted=reason,
            check=check,
        )
    )


V = ValueError  # rejections of bad arguments are ValueError; a pose path without a solution is RuntimeError

_TMP = tempfile.mkdtemp(prefix="dispkin_bad_input_")
atexit.register(shutil.rmtree, _TMP, ignore_errors=True)
MALFORMED = pathlib.Path(_TMP) / "malformed.json"
MALFORMED.write_text("{\"format\": \"dispkin.hexapod\", \"legs\": [")
