"""pytest configuration of the Python suite.

DISPKIN_TEST_SEED and DISPKIN_TEST_COUNT (default 10000 cases per oracle) set the random cases;
see _helpers.py. numpy's BLAS is kept to one thread: the suite's arrays are small, and
threads only fight over the cores.
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")


def pytest_report_header(config):
    from _helpers import COUNT, SEED

    return f"dispkin oracles: DISPKIN_TEST_SEED={SEED} DISPKIN_TEST_COUNT={COUNT}"
