"""Which haros_arch a bench script measures: the one Python imports (PYTHONPATH, else
the installed one), never the script's own checkout by force.

A script that put its own checkout first on ``sys.path`` measured that checkout whatever
PYTHONPATH said, so two checkouts compared with one checkout's script were the same
code twice. Each script imports haros_arch plainly and calls ``announce`` first, which
says where it came from: run each checkout with its own PYTHONPATH.
"""

from __future__ import annotations

import os
import sys
from typing import TextIO


def folder() -> str:
    """The checkout (or site-packages folder) haros_arch is imported from."""
    import haros_arch

    return os.path.dirname(os.path.dirname(os.path.abspath(haros_arch.__file__)))


def announce(stream: TextIO | None = None) -> str:
    """Say ``haros_arch from FOLDER`` (on stderr unless told: most scripts' stdout is
    their result) and return the folder."""
    where = folder()
    print(f"haros_arch from {where}", file=stream or sys.stderr)
    return where
