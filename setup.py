"""Build hook: D3 goes into the wheel at build time, from the npm package (never from the
repository, which does not hold it). Everything else is in pyproject.toml."""

from __future__ import annotations

import os
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
NPM_D3 = os.path.join(HERE, "node_modules", "d3", "dist", "d3.min.js")


def _d3() -> str | None:
    """A d3.min.js to package: $HAROS_ARCH_D3, else the npm package (``npm ci`` when npm is
    there and the lock file pins it)."""
    given = os.environ.get("HAROS_ARCH_D3")
    if given and os.path.isfile(given):
        return given
    if not os.path.isfile(NPM_D3) and shutil.which("npm") and os.path.isfile(
            os.path.join(HERE, "package-lock.json")):
        subprocess.run(["npm", "ci", "--no-audit", "--no-fund", "--loglevel=error"],
                       cwd=HERE, check=False)
    return NPM_D3 if os.path.isfile(NPM_D3) else None


class BuildPyWithD3(build_py):
    def run(self) -> None:
        super().run()
        target = os.path.join(self.build_lib, "haros_arch", "viz", "vendor", "d3.min.js")
        if os.path.isfile(target):
            return
        source = _d3()
        if source is None:
            print("warning: D3 not found (no npm, no node_modules, HAROS_ARCH_D3 unset): "
                  "'haros-arch report' of this build will need HAROS_ARCH_D3")
            return
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(source, target)


setup(cmdclass={"build_py": BuildPyWithD3})
