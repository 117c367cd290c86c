"""The rows of the bad-input table (tests/python/test_bad_input_table.py) of one area:
WorkToolFrames."""

import numpy as np

import dispkin

from .rows import NAN, V, good_set, row

# --- WorkToolFrames -----------------------------------------------------------------------
FRAMES = dispkin.WorkToolFrames()
row(
    "WorkToolFrames(...)",
    "NaN work matrix",
    lambda: dispkin.WorkToolFrames(work=np.full((4, 4), NAN)),
    V,
    "matrix = (nan",
)
row(
    "WorkToolFrames(...)",
    "wrong shape tool (3, 3)",
    lambda: dispkin.WorkToolFrames(tool=np.eye(3)),
    V,
    "tool: expected an array of shape (4, 4), got shape (3, 3)",
)
row(
    "WorkToolFrames.platform_pose", "NaN matrix", lambda: FRAMES.platform_pose(np.full((4, 4), NAN)), V, "matrix = (nan"
)
row(
    "WorkToolFrames.tool_in_work",
    "wrong shape (6,)",
    lambda: FRAMES.tool_in_work([0, 0, 0.2, 0, 0, 0]),
    V,
    "platform: expected an array of shape (4, 4), got shape (6,)",
)
row(
    "WorkToolFrames.platform_pose_xyzuvw",
    "NaN U",
    lambda: FRAMES.platform_pose_xyzuvw([0, 0, 0, NAN, 0, 0]),
    V,
    "xyzuvw = (0, 0, 0, nan, 0, 0)",
)
row(
    "WorkToolFrames.platform_pose_xyzuvw",
    "wrong size (5)",
    lambda: FRAMES.platform_pose_xyzuvw([0] * 5),
    V,
    "xyzuvw: expected an array of shape (6,), got shape (5,)",
)
row(
    "WorkToolFrames.add_tool_envelope",
    "zero radius",
    lambda: FRAMES.add_tool_envelope(good_set(), 0.0),
    V,
    "radius = 0",
)
row(
    "WorkToolFrames.add_tool_envelope",
    "NaN radius",
    lambda: FRAMES.add_tool_envelope(good_set(), NAN, "sphere"),
    V,
    "radius = nan",
)
row(
    "WorkToolFrames.add_tool_envelope",
    "unknown envelope",
    lambda: FRAMES.add_tool_envelope(good_set(), 0.1, "cube"),
    V,
    "envelope = \"cube\": must be \"icosahedron\" or \"sphere\"",
)
row(
    "WorkToolFrames.add_work_envelope",
    "negative radius",
    lambda: FRAMES.add_work_envelope(good_set(), -0.1),
    V,
    "radius = -0.1",
)
row(
    "WorkToolFrames.add_work_envelope",
    "negative group",
    lambda: FRAMES.add_work_envelope(good_set(), 0.1, group=-1),
    V,
    "group = -1",
)
