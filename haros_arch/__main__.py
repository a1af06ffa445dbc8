"""``python -m haros_arch``: the same command line as ``haros-arch``."""

import sys

from .cli import main

sys.exit(main())
