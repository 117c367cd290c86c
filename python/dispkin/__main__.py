"""``python -m dispkin``: the command line (see :mod:`dispkin.cli`)."""

import sys

from .cli import main

sys.exit(main())
