"""Writes tests/BAD_INPUT.md from the table in test_bad_input_table.py.

Usage: python tests/python/make_bad_input_table.py
"""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

import test_bad_input_table  # noqa: E402

test_bad_input_table.MARKDOWN_PATH.write_text(test_bad_input_table.markdown())
print(f"wrote {test_bad_input_table.MARKDOWN_PATH} ({len(test_bad_input_table.ROWS)} rows)")
