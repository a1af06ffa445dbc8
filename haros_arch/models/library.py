"""Find the interface model of a package: the user's files first, then the shipped ones.

Shipped models live in ``haros_arch/models/data/<distro>/<package>.json``; a project
lists its own (files or folders of ``*.json``) under ``models:``, and those win. A model
for a package is read once, when a configuration first needs it. A file that cannot be
read is a ``MODEL_INVALID`` diagnostic and is not used.
"""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Iterable

from .. import diagnostics as diag
from ..diagnostics import Diagnostic
from ..files import read_text
from ..model.location import Location
from .format import InterfaceModel, ModelFileError, from_document

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


class Library:
    """Interface models by (distribution, package)."""

    def __init__(self, user_paths: Iterable[str] = (), shipped: str | None = DATA) -> None:
        self.shipped = shipped
        self.diagnostics: list[Diagnostic] = []
        self.user: dict[tuple[str | None, str], InterfaceModel] = {}
        self._shipped: dict[tuple[str, str], InterfaceModel | None] = {}
        for path in user_paths:
            for file in _model_files(path, self.diagnostics):
                model = read_model(file, self.diagnostics)
                if model is not None:
                    self.user.setdefault((model.distro, model.package), model)

    def find(self, package: str, distro: str) -> InterfaceModel | None:
        """The model of ``package`` for ``distro``: a user's for that distribution or
        for any (a file without ``distro``), else the shipped one."""
        found = self.user.get((distro, package)) or self.user.get((None, package))
        if found is not None:
            return found
        key = (distro, package)
        if key not in self._shipped:
            self._shipped[key] = self._read_shipped(distro, package)
        return self._shipped[key]

    def distributions(self) -> set[str]:
        """The distributions some model is for: the user's and the shipped ones."""
        return {d for d, _ in self.user if d is not None} | set(_folders(self.shipped))

    def _read_shipped(self, distro: str, package: str) -> InterfaceModel | None:
        if self.shipped is None or "/" in distro + package or package.startswith("."):
            return None
        path = os.path.join(self.shipped, distro, package + ".json")
        if not os.path.isfile(path):
            return None
        return read_model(path, self.diagnostics)


@functools.lru_cache(maxsize=1)
def shipped_packages() -> frozenset[str]:
    """The packages a shipped interface model exists for, in any distribution: ROS
    packages the tool knows by name (sound_play, mavros, rosserial_python, ...)."""
    found: set[str] = set()
    for distro in _folders(DATA):
        try:
            files = os.listdir(os.path.join(DATA, distro))
        except OSError:
            continue
        found.update(f.removesuffix(".json") for f in files if f.endswith(".json"))
    return frozenset(found)


def _folders(path: str | None) -> list[str]:
    """The distribution folders of a model data folder (none where it cannot be read)."""
    try:
        names = os.listdir(path) if path is not None else []
    except OSError:
        return []
    return [n for n in names if os.path.isdir(os.path.join(path or "", n))]


def _model_files(path: str, found: list[Diagnostic]) -> list[str]:
    if os.path.isdir(path):
        return sorted(os.path.join(path, f) for f in os.listdir(path) if f.endswith(".json"))
    if not os.path.isfile(path):
        found.append(diag.make("MODEL_INVALID", Location(file=path),
                               detail="no such file or folder"))
        return []
    return [path]


def read_model(path: str, found: list[Diagnostic]) -> InterfaceModel | None:
    """One model file; problems become diagnostics at the file."""
    where = Location(file=os.path.relpath(path) if not path.startswith(DATA) else
                     "haros_arch/models/data/" + os.path.relpath(path, DATA))
    text, problems = read_text(path, where)
    if text is None:
        found.extend(problems)
        return None
    try:
        data = json.loads(text)
    except RecursionError:
        found.append(diag.make("MODEL_INVALID", where, detail="nested too deeply"))
        return None
    except ValueError as error:
        line = getattr(error, "lineno", 0)
        found.append(diag.make("MODEL_INVALID", Location(file=where.file, line=line),
                               detail=f"not JSON: {getattr(error, 'msg', error)}"))
        return None
    try:
        return from_document(data, path)
    except ModelFileError as error:
        found.append(diag.make("MODEL_INVALID", where, detail=str(error)))
        return None
