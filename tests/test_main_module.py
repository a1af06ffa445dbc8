"""``python -m haros_arch`` runs the command line."""

import subprocess
import sys

from haros_arch import __version__


def test_python_dash_m_runs_the_cli() -> None:
    done = subprocess.run([sys.executable, "-m", "haros_arch", "--version"],
                          capture_output=True, text=True, timeout=60, check=False)
    assert done.returncode == 0 and __version__ in done.stdout
