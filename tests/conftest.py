"""Shared helpers: fixture paths and a small workspace writer for inline cases."""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
import textwrap
from pathlib import Path

import pytest

# the suite's parse cache is its own, never the user's ~/.cache (set before any test imports
# haros_arch, so every cache path is computed under it)
os.environ["XDG_CACHE_HOME"] = tempfile.mkdtemp(prefix="haros-arch-test-cache-")
atexit.register(shutil.rmtree, os.environ["XDG_CACHE_HOME"], True)

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"


@pytest.fixture
def write_tree(tmp_path: Path):
    """Write ``{relative path: text}`` under tmp_path and return the folder."""

    def write(files: dict[str, str]) -> Path:
        for rel, text in files.items():
            path = tmp_path / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(textwrap.dedent(text).lstrip("\n"))
        return tmp_path

    return write


def package_xml(name: str, build_type: str | None = None) -> str:
    export = f"<export><build_type>{build_type}</build_type></export>" if build_type else ""
    return (f'<?xml version="1.0"?>\n<package format="2"><name>{name}</name>'
            f"<version>0.1.0</version><description>d</description>"
            f'<maintainer email="a@b.c">m</maintainer><license>MIT</license>{export}'
            "</package>\n")


def only_case() -> str | None:
    """HAROS_ARCH_CASE=name narrows parametrised fixture tests to one case."""
    return os.environ.get("HAROS_ARCH_CASE")
