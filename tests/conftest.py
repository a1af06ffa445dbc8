"""Shared helpers: fixture paths and a small workspace writer for inline cases."""

from __future__ import annotations

import atexit
import json
import os
import shutil
import tempfile
import textwrap
from pathlib import Path

import pytest


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's
        return True
    return True


def session_folder(parent: Path) -> Path:
    """This run's temporary folder, ``parent/<pid>``, removed when the run exits; the
    folders of runs no longer alive (killed before their exit handlers ran) are removed
    first, those of runs still going are kept."""
    parent.mkdir(parents=True, exist_ok=True)
    for child in parent.iterdir():
        if child.name.isdigit() and int(child.name) != os.getpid() and not _alive(
                int(child.name)):
            shutil.rmtree(child, ignore_errors=True)
    own = parent / str(os.getpid())
    own.mkdir(exist_ok=True)
    atexit.register(shutil.rmtree, own, True)
    return own


def _session() -> Path:
    """This run's folder: made at the first import of this module (it is imported as
    ``conftest`` and as ``tests.conftest``), the same one after."""
    said = os.environ.get("HAROS_ARCH_TEST_SESSION", "")
    if said and os.path.basename(said) == str(os.getpid()) and os.path.isdir(said):
        return Path(said)
    # pytest's own tmp_path stays where pytest keeps it (its last runs', for a look)
    os.environ.setdefault("PYTEST_DEBUG_TEMPROOT", tempfile.gettempdir())
    found = session_folder(Path(tempfile.gettempdir()) / f"haros-arch-tests-{os.getuid()}")
    os.environ["HAROS_ARCH_TEST_SESSION"] = str(found)
    return found


# everything else the suite puts in the temporary folder (the parse cache, the fuzzing
# workspace, the C++ stand-ins' folders, those of the processes it starts) is in one
# folder of this run: a run killed leaves nothing the next does not remove. The parse
# cache is the suite's own, never the user's ~/.cache (set before any test imports
# haros_arch, so every cache path is computed under it).
SESSION = _session()
tempfile.tempdir = os.environ["TMPDIR"] = str(SESSION)
os.environ["XDG_CACHE_HOME"] = str(SESSION / "cache")

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


def copied_old(source: Path, target: Path) -> Path:
    """A copy of the tree ``source`` at ``target``, every file dated long ago: the run
    cache's snapshot trusts a file's size and time only when it is not recent."""
    shutil.copytree(source, target)
    for folder, _dirs, files in os.walk(target):
        for name in files:
            os.utime(os.path.join(folder, name), (1_000_000_000, 1_000_000_000))
    return target


def unread_parameters(root: Path) -> list[str]:
    """The parameters ``haros-arch check`` of ``root``'s project.yaml says are set and
    never read (``parameter-set-not-read``), sorted."""
    from haros_arch.cli import main

    out = root / "check.json"
    main(["check", str(root / "project.yaml"), "--format", "json", "-o", str(out),
          "--fail-on", "never"])
    report = json.loads(out.read_text())
    return sorted(entity.removeprefix("parameter:")
                  for f in report["findings"] if f["rule"] == "parameter-set-not-read"
                  for entity in f.get("entities", []) if entity.startswith("parameter:"))


def only_case() -> str | None:
    """HAROS_ARCH_CASE=name narrows parametrised fixture tests to one case."""
    return os.environ.get("HAROS_ARCH_CASE")
