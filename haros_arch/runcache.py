"""A re-run with nothing changed, answered whole from the cache folder.

The model a run gives is kept in the cache folder the C++ units use
(``files.cache_folder``), in ``runs/``, found by a key over everything the
run reads: the project (as loaded, with the command line's arguments), the environment
(but the shell's own bookkeeping: ``$_``, ``$OLDPWD``, ``$PWD``, ``$SHLVL``), the current
folder, the options that change the model, this tool's own files, and a snapshot of the files
(``snapshot``): every file under the workspace's roots (by content), the files beside
the project file, its compile_commands and model files, the compile_commands.json files
the C++ stage would read, and the package folders of the installed prefixes the
environment names (by name and modification time: a package installed, removed or
upgraded changes its folder). A file changed inside an installed package without its
folder changing is not seen: ``--no-cache`` runs cold.

When only C++ files changed (the outer key, over every file but the content of C++
sources and headers, is that of a kept run), the pipeline extracts the C++ nodes again
from what the build files gave and answers with the kept run when every translation unit
gives what it gave; the other nodes read only files this key covers by content, so
their results stand (``pipeline._reread``).

Files larger than the readers read (``files.MAX_FILE_BYTES``: bags, maps, meshes) count
by size and modification time, so a cold run does not hash gigabytes. Content hashes are
kept in an index beside the entries, with each file's size and
modification time, so an unchanged file is not read again (as git's index does); a file
modified in the last seconds is hashed again on the next run (its time may not show a
second change in the same tick). Entries are JSON (never pickle: the folder may be in
the analysed workspace); one that does not read back is a miss.
"""

from __future__ import annotations

import contextlib
import copy
import dataclasses
import hashlib
import json
import os
import signal
import stat
import sys
import time
import weakref
from collections.abc import Callable, Iterable, Iterator, Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from . import __version__
from .collector import held_back
from .distro_guess import guessed_distro
from .files import CPP_FILES, MAX_FILE_BYTES, content_digest, write_whole
from .model.diagnostic import Diagnostic
from .model.finding import Finding
from .model.load import from_data
from .model.model import Model
from .model.serialise import model_to_data, to_data
from .project import Project
from .workspace import SKIP_FOLDERS, Workspace, installed_roots

if TYPE_CHECKING:
    from .relocate import Files, Maps

T = TypeVar("T")
FORMAT = 1
RACY_SECONDS = 2.0  # a file modified this recently is hashed again next time
KEEP = 20  # entries kept per workspace (a run's model and its findings, per project,
#           workspace state and environment: a few runs)
WORKSPACES = 8  # workspaces whose entries are kept: those of the newest runs
MAX_FILES = 200_000  # files in one snapshot; past it the run is not cached
# variables a shell sets on its own as one moves and runs commands (the current folder is
# in the key already): not inputs of a run
SHELL_BOOKKEEPING = frozenset({"_", "OLDPWD", "PWD", "SHLVL"})
TOOL = os.path.dirname(os.path.abspath(__file__))


MAX_OUTPUTS = 64  # the files this tool wrote last, remembered (``record_output``)


def _outputs_path() -> str | None:
    """Where the files this tool wrote are remembered: beside the cache folders
    (``$XDG_CACHE_HOME/haros-arch``); None with no home folder."""
    xdg = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return None if xdg.startswith("~") else os.path.join(xdg, "haros-arch", "outputs.json")


def _outputs() -> dict[str, list[int]]:
    """Each file this tool wrote (by absolute path): its size and modification time then."""
    where = _outputs_path()
    if where is None:
        return {}
    try:
        with open(where, encoding="utf-8") as handle:
            data = json.load(handle)
    except (OSError, ValueError):
        return {}
    found = data.get("outputs") if isinstance(data, dict) and (
        data.get("format") == FORMAT) else None
    return {k: v for k, v in found.items() if isinstance(v, list) and len(v) == 2} if (
        isinstance(found, dict)) else {}


def record_output(path: str) -> None:
    """Remember that this tool wrote ``path`` (a command's ``-o``): while it is as written,
    it is no input of a run (``Snapshot.file``). A model, report or SARIF file written
    beside the project file or in the workspace made every later run a new one."""
    where = _outputs_path()
    if where is None:
        return
    try:
        info = os.stat(path)
    except OSError:
        return
    found = _outputs()
    full = os.path.abspath(path)
    found.pop(full, None)
    found[full] = [info.st_size, info.st_mtime_ns]
    _write_json(where, {"format": FORMAT,
                        "outputs": dict(list(found.items())[-MAX_OUTPUTS:])})


class Snapshot:
    """Content hashes of files by path, through a stat index kept in ``index_path``; the
    files this tool wrote (``record_output``), unchanged since, are left out."""

    def __init__(self, index_path: str) -> None:
        self.index_path = index_path
        self.index: dict[str, list[Any]] = {}
        try:
            with open(index_path, encoding="utf-8") as handle:
                data = json.load(handle)
            if isinstance(data, dict) and data.get("format") == FORMAT:
                self.index = {k: v for k, v in data.get("files", {}).items()
                              if isinstance(v, list) and len(v) == 3}
        except (OSError, ValueError):
            pass
        self.seen: dict[str, list[Any]] = {}
        self.digests: list[tuple[str, str]] = []
        self.inner: list[tuple[str, str]] = []  # files by content
        self.outer: list[tuple[str, str]] = []  # the same, C++ ones by name only
        self.complete = True
        self.now = time.time()
        self.written = _outputs()

    def file(self, path: str, info: os.stat_result) -> None:
        if self.written and self.written.get(os.path.abspath(path)) == [
                info.st_size, info.st_mtime_ns]:
            return  # an output of this tool, as it wrote it
        if len(self.seen) >= MAX_FILES:
            self.complete = False
            return
        known = self.index.get(path)
        if info.st_size > MAX_FILE_BYTES:  # more than the readers read (a bag, a map):
            digest = f"large {info.st_size} {info.st_mtime_ns}"  # by size and time
        elif known is not None and known[0] == info.st_size and known[1] == info.st_mtime_ns:
            digest = known[2]
        else:
            digest = content_digest(path) or "unreadable"
        self.outer.append((path, "c++" if path.endswith(CPP_FILES) else digest))
        self.inner.append((path, digest))
        if self.now - info.st_mtime > RACY_SECONDS:
            self.seen[path] = [info.st_size, info.st_mtime_ns, digest]

    def path(self, path: str) -> None:
        """A file (content) or a missing one, by its path."""
        try:
            info = os.stat(path)
        except OSError:
            self.digests.append((path, "missing"))
            return
        if stat.S_ISREG(info.st_mode):
            self.file(path, info)
        else:
            self.digests.append((path, "not a file"))

    def tree(self, top: str, skip: frozenset[str] = frozenset()) -> None:
        """Every file below ``top`` (links to folders followed once; dot entries and
        ``skip`` folders left out, as the workspace scan does)."""
        try:
            info = os.stat(top)
        except OSError:
            return
        # a folder is known by its device and inode (as the real path would tell, with
        # one stat where the real path takes one per part of the path)
        stack: list[tuple[str, tuple[int, int]]] = [(top, (info.st_dev, info.st_ino))]
        visited: set[tuple[int, int]] = set()
        while stack and self.complete:
            folder, identity = stack.pop()
            if identity in visited:
                continue
            visited.add(identity)
            try:
                entries = sorted(os.scandir(folder), key=lambda e: e.name)
            except OSError:
                continue
            self.digests.append((folder, "folder"))
            for entry in entries:
                if entry.name.startswith(".") or entry.name in skip:
                    continue
                try:
                    info = entry.stat()
                except OSError:
                    continue
                if stat.S_ISDIR(info.st_mode):
                    stack.append((entry.path, (info.st_dev, info.st_ino)))
                elif stat.S_ISREG(info.st_mode):
                    self.file(entry.path, info)

    def folders(self, top: str) -> None:
        """The folders directly in ``top``, by name and modification time."""
        try:
            entries = sorted(os.scandir(top), key=lambda e: e.name)
        except OSError:
            self.digests.append((top, "missing"))
            return
        for entry in entries:
            try:
                self.digests.append((entry.path, str(entry.stat().st_mtime_ns)))
            except OSError:
                continue

    def digest(self, outer: bool = False) -> str:
        """Of every file, or (``outer``) of every file but the content of C++ ones."""
        found = hashlib.sha256()
        for path, digest in self.digests:
            found.update(f"{path}\0{digest}\n".encode("utf-8", "replace"))
        for path, digest in self.outer if outer else self.inner:
            found.update(f"{path}\0{digest}\n".encode("utf-8", "replace"))
        return found.hexdigest()

    def copy(self) -> Snapshot:
        """Another snapshot of the same files, to add more to."""
        other = Snapshot.__new__(Snapshot)
        other.__dict__.update(self.__dict__)
        for name in ("seen", "digests", "inner", "outer"):
            setattr(other, name, copy.copy(getattr(self, name)))
        return other

    def save(self) -> None:
        if self.seen != self.index:
            _write_json(self.index_path, {"format": FORMAT, "files": self.seen})


def run_key(project: Project, env: Mapping[str, str], models: bool, folder: str,
            compile_commands: Iterable[str]) -> tuple[str, str] | None:
    """The key of a run of ``project``, and its outer key (C++ files by name only, not
    content); None when its files are too many to snapshot."""
    settled()
    snap = _snapshot(folder, project.workspace)
    group = _group(project.workspace)
    try:
        beside = sorted(os.scandir(project.folder), key=lambda e: e.name)
    except OSError:
        beside = []
    for entry in beside:
        if entry.is_file():
            snap.path(entry.path)
    for path in [*project.models, *([project.compile_commands] if project.compile_commands
                                    else []), *compile_commands]:
        full = os.path.join(project.folder, path)
        if os.path.isdir(full):
            snap.tree(full)
        else:
            snap.path(full)
    for root in installed_roots(env):
        snap.folders(root)
    if not snap.complete:
        return None
    snap.save()
    # locations are written relative to the current folder: it is an input too
    # (the distribution the workspace's files name: its git branch is no file snapshotted)
    head = [FORMAT, __version__, os.getcwd(), repr(project), _environment(env), models,
            guessed_distro(project, env)]
    key = f"{group}-{_digest(json.dumps([*head, snap.digest()]))}"
    _SOURCES[key] = {path: digest for path, digest in snap.inner
                     if path.endswith(CPP_FILES)}
    return key, f"{group}-{_digest(json.dumps([*head, snap.digest(outer=True)]))}"


# the C++ files of each run's snapshot (``run_key``), by path: their content digests
_SOURCES: dict[str, dict[str, str]] = {}


def sources(key: str) -> dict[str, str]:
    """The content digest of each C++ file the run ``key`` snapshotted, by path."""
    return dict(_SOURCES.get(key, {}))


def _group(roots: Iterable[str]) -> str:
    """The name that begins the entries of runs over the workspace ``roots`` (a project's
    workspace folders): the cache folder is pruned workspace by workspace (``_prune``)."""
    return _digest(repr([os.path.abspath(r) for r in roots]))[:GROUP_LENGTH]


GROUP_LENGTH = 16
INDEX = "index.json"  # the end of a workspace's stat index's name: ``<group>-index.json``


def _snapshot(folder: str, roots: Iterable[str]) -> Snapshot:
    """A snapshot of this tool's files and of every file under ``roots`` (a project's
    workspace folders), through the index the cache folder keeps for those roots; within
    ``one_snapshot``, made once for those roots."""
    full = [os.path.abspath(r) for r in roots]
    key = (folder, tuple(full))
    if _SHARED is not None and key in _SHARED:
        return _SHARED[key].copy()
    snap = Snapshot(os.path.join(folder, "runs", f"{_group(full)}-{INDEX}"))
    snap.tree(TOOL, frozenset({"__pycache__"}))
    for root in full:
        snap.tree(root, SKIP_FOLDERS)
    if _SHARED is not None:
        _SHARED[key] = snap.copy()
    return snap


# the snapshots of workspace trees ``one_snapshot`` shares, by cache folder and roots
_SHARED: dict[tuple[str, tuple[str, ...]], Snapshot] | None = None


@contextlib.contextmanager
def one_snapshot() -> Iterator[None]:
    """Within: each workspace's files are snapshotted once, for the key of the choice of
    configurations (``kept``) and then the run's key (``run_key``), moments apart in one
    command (a no-change re-run of navigation2's folder walked its 2,000 files twice)."""
    global _SHARED
    outer = _SHARED
    if outer is None:
        _SHARED = {}
    try:
        yield
    finally:
        _SHARED = outer


def _environment(env: Mapping[str, str]) -> list[tuple[str, str]]:
    return sorted(kv for kv in env.items() if kv[0] not in SHELL_BOOKKEEPING)


def kept(folder: str, kind: str, roots: Iterable[str], env: Mapping[str, str],
         inputs: object, compute: Callable[[], T], save: Callable[[T], object],
         read: Callable[[Any], T]) -> T:
    """What ``compute`` gives from ``inputs`` (JSON data) and what it may read: the files
    under ``roots`` (by content), the installed packages ``env`` names (their folders, as
    a run's key has them) and ``env`` itself; kept in the cache folder as entry ``kind``
    and read back while none of these changed. For work done before a run's own key
    can be made: the choice of configurations for a folder without a project file,
    which loads every launch file of the workspace (``autoproject.root_launch_files``),
    is most of a no-change re-run of such a folder."""
    settled()
    roots = list(roots)
    snap = _snapshot(folder, roots)
    for root in installed_roots(env):
        snap.folders(root)
    if not snap.complete:
        return compute()
    snap.save()
    key = _digest(json.dumps([FORMAT, __version__, kind, os.getcwd(), _environment(env),
                              inputs, snap.digest()]))
    return _entry_or(folder, _entry(folder, f"{_group(roots)}-{kind}-{key}"), kind, compute,
                     save, read)


def compile_commands_of(project: Project, env: Mapping[str, str]) -> list[str]:
    """The compile_commands.json files the C++ stage would look for (found or not)."""
    from .compile_commands import find

    roots = [os.path.abspath(r) for r in project.workspace]
    workspace = Workspace(root=roots[0] if roots else os.getcwd(), roots=roots,
                          environment=dict(env))
    return find(workspace)


# the entry of each model this process ran or read back: its findings are kept with it
_KEPT: weakref.WeakKeyDictionary[Model, tuple[str, str]] = weakref.WeakKeyDictionary()


# how a model's entry is written (``store``): the digest of the model's JSON text, then
# the text; read back, the text is decoded only when the model is used (``KeptModel``)
MODEL_HEAD = b'{"digest": "'
MODEL_MIDDLE = b'", "model": '
DIGEST_LENGTH = 64


class _Decoded:
    """A field of a ``KeptModel``, read and written on its decoded model."""

    def __set_name__(self, owner: type, name: str) -> None:
        self.name = name

    def __get__(self, model: KeptModel | None, owner: type | None = None) -> Any:
        return self if model is None else getattr(model.whole(), self.name)

    def __set__(self, model: KeptModel, value: Any) -> None:
        setattr(model.whole(), self.name, value)


class KeptModel(Model):
    """A kept run's model, decoded from its entry's text the first time a field is
    asked for: a re-run with nothing changed that needs only what is kept with the run
    (``check``'s findings and diagnostics, ``extract -q``'s document) never decodes it
    (51 MB of JSON for navigation2's 33 configurations, half of such a re-run). The text
    was checked against its digest when read (``load``)."""

    def __init__(self, text: bytes, project: str) -> None:  # no dataclass fields set
        self._text: bytes | None = text
        self._whole: Model | None = None
        self._name = project

    def whole(self) -> Model:
        if self._whole is None:
            assert self._text is not None
            with held_back():
                data = json.loads(self._text)
            self._whole = from_data(data)
            self._text = None
        return self._whole

    def data(self) -> dict[str, Any] | None:
        """``model_to_data`` of the model while it is not decoded: its text read as JSON
        (the text is what ``model_to_data`` gave, read back the same, or that renumbered
        by ``relocated``); None once decoded (it may have changed since)."""
        if self._text is None:
            return None
        with held_back():  # a million dictionaries that live on
            return dict(json.loads(self._text))

    @property
    def project(self) -> str:
        return self._name if self._whole is None else self._whole.project

    @project.setter
    def project(self, value: str) -> None:
        self.whole().project = value

    # the other fields: the decoded model's
    packages = _Decoded()
    configurations = _Decoded()
    diagnostics = _Decoded()


def model_data(model: Model) -> dict[str, Any]:
    """``model_to_data(model)``; of a kept model not decoded yet, its text read as JSON,
    without making the model's objects to write them again: a report or ``extract``'s
    document after a run that renumbered the kept model (navigation2: 1.9 s of CPU
    instead of 5.0)."""
    found = model.data() if isinstance(model, KeptModel) else None
    return model_to_data(model) if found is None else found


def _model_text(content: bytes) -> bytes | None:
    """The model's JSON text of an entry's content, when its digest says it is the text
    ``store`` wrote; else None."""
    head = len(MODEL_HEAD) + DIGEST_LENGTH + len(MODEL_MIDDLE)
    if not (content.startswith(MODEL_HEAD) and content.endswith(b"}")
            and content[head - len(MODEL_MIDDLE):head] == MODEL_MIDDLE):
        return None
    text = content[head:-1]
    digest = content[len(MODEL_HEAD):len(MODEL_HEAD) + DIGEST_LENGTH]
    return text if hashlib.sha256(text).hexdigest().encode() == digest else None


def load(folder: str, key: str, project: str = "") -> Model | None:
    """The model kept under ``key`` (``project``: its name), decoded when first used
    (``KeptModel``); None when there is none, or its entry is not as it was written."""
    settled()
    found = _model_entry(folder, key)
    if found is None:
        return None
    model = KeptModel(found[1], project)
    _KEPT[model] = (folder, found[0])
    return model


def _model_entry(folder: str, key: str) -> tuple[str, bytes] | None:
    """The key of the model entry ``key`` names (itself, or the one its alias names,
    ``store_alias``: one hop) and the model's JSON text there; None when there is none,
    or its entry is not as it was written."""
    try:
        with open(_entry(folder, key), "rb") as handle:
            content = handle.read()
        if not content.startswith(MODEL_HEAD):
            data = json.loads(content)
            if not isinstance(data, dict) or not isinstance(data.get("same_as"), str):
                return None
            key = data["same_as"]
            with open(_entry(folder, key), "rb") as handle:
                content = handle.read()
    except (OSError, ValueError):
        return None
    text = _model_text(content)
    return None if text is None else (key, text)


def diagnostics(model: Model, compute: Callable[[], list[Diagnostic]]) -> list[Diagnostic]:
    """``check``'s diagnostics (those no rule reports) of a kept model's run: read back
    when that run gave them before, else computed and kept."""
    from .model.load import diagnostic_from_data

    return _with_run(model, "diagnostics", "", compute, to_data,
                     lambda data: [diagnostic_from_data(d) for d in data])


def summary(model: Model, verbose: bool, compute: Callable[[], list[str]]) -> list[str]:
    """``extract``'s summary of a kept model's run (lines of rich markup): read back when
    that run printed it before, else computed and kept (a summary needs the model
    decoded: 2.9 s of a 3.4 s re-run on navigation2)."""
    return _with_run(model, "summary", "verbose" if verbose else "", compute, list,
                     lambda data: [str(line) for line in data])


# within ``background``: the stores still writing, forked processes (their ids)
_BACKGROUND: list[list[int]] = []


@contextlib.contextmanager
def background() -> Iterator[None]:
    """Within the block, a run's model is kept by a forked copy of this process (its
    serialisation and read-back check, seconds on a large workspace) while the command
    goes on with what it does with the model (queries, a report, a document) on the
    other processor; every store has ended when the block is left, so the cache is as
    a store in line leaves it. Where the process cannot fork (not Linux), a store is
    made in line. A stop (Ctrl-C, SIGTERM) ends the stores under way: an entry is
    written whole or not at all."""
    pending: list[int] = []
    _BACKGROUND.append(pending)
    stopped = True
    try:
        yield
        stopped = False
    finally:
        _BACKGROUND.remove(pending)
        _settle(pending, stop=stopped)


def _settle(pending: list[int], stop: bool = False) -> None:
    """Wait for the stores ``pending`` (ended first with SIGTERM when ``stop``)."""
    while pending:
        pid = pending.pop()
        if stop:
            with contextlib.suppress(OSError):
                os.kill(pid, signal.SIGTERM)
        while True:
            try:
                os.waitpid(pid, 0)
            except InterruptedError:
                continue
            except ChildProcessError:
                pass
            break


def settled() -> None:
    """Wait for the stores under way (before reading the cache folder: a run of the
    same process after one whose store was forked reads what it wrote)."""
    for pending in _BACKGROUND:
        _settle(pending)


def store(folder: str, key: str, model: Model) -> None:
    """Keep ``model`` under ``key`` when it reads back as it is, then prune the cache
    folder (``_prune``); within ``background``, from a forked process (the model as it is
    now, whatever this process does with it after)."""
    if _forked(lambda: _store(folder, key, model)):
        # the run's findings, document or page are kept with it (``_with_run``); if
        # the model turns out not to read back, they are kept for a run that is not
        _KEPT[model] = (folder, key)
        return
    _store(folder, key, model)


def _forked(work: Callable[[], None]) -> bool:
    """Within ``background``, ``work`` done by a forked copy of this process (which ends
    after it, running no exit handler of the run); False when there is none to do it
    (outside the block, not Linux, no process to spare): the caller does it in line."""
    if not (_BACKGROUND and hasattr(os, "fork") and sys.platform.startswith("linux")):
        return False
    settled()
    try:
        pid = os.fork()
    except OSError:
        return False
    if pid == 0:
        code = 1
        try:
            work()
            code = 0
        finally:
            os._exit(code)
    _BACKGROUND[-1].append(pid)
    return True


def _store(folder: str, key: str, model: Model) -> None:
    with held_back():  # the model's data, and the model it reads back as, live on
        data = model_to_data(model)
        # in the model's own order: read back, its documents list every field and key
        # as a run without the cache does (a QoS profile's keys sorted read back in
        # another order than the extraction made them, and `extract -o` differed)
        text, parts = _json_parts(data)
        same = json.dumps(model_to_data(from_data(json.loads(text)))) == text
    if not same:
        return  # a model that does not read back whole is not kept (never a wrong one)
    _KEPT[model] = (folder, key)
    _write_json(_entry(folder, key + PARTS), parts)
    _write_model(folder, key, text)


def kept_as(model: Model, key: str) -> bool:
    """Whether ``model`` is the one kept under ``key`` (``relocated`` wrote it)."""
    kept = _KEPT.get(model)
    return kept is not None and kept[1] == key


def _write_model(folder: str, key: str, text: str) -> None:
    body = text.encode("utf-8")
    _write_bytes(_entry(folder, key), MODEL_HEAD + hashlib.sha256(body).hexdigest().encode()
                 + MODEL_MIDDLE + body + b"}")
    _prune(folder)


PARTS = "-parts"  # an entry beside a model's: where its text holds each top-level field
# the fields of a model's text a run after an edit of C++ sources compares (``relocated``)
BEFORE_GRAPH = ("packages", "diagnostics")


def _json_parts(data: dict[str, Any]) -> tuple[str, dict[str, list[Any]]]:
    """``json.dumps(data)``, and where each of its fields' values begins and ends (and,
    for those of ``BEFORE_GRAPH``, where each of their items ends)."""
    pieces = ["{"]
    parts: dict[str, list[Any]] = {}
    at = 1
    for index, (name, value) in enumerate(data.items()):
        head = (", " if index else "") + json.dumps(name) + ": "
        ends: list[int] = []
        if name in BEFORE_GRAPH and isinstance(value, list):
            items = [json.dumps(item) for item in value]
            body = "[" + ", ".join(items) + "]"
            end = at + len(head) + 1  # after the bracket
            for number, item in enumerate(items):
                end += (2 if number else 0) + len(item)
                ends.append(end)
        else:
            body = json.dumps(value)
        pieces += [head, body]
        at += len(head)
        parts[name] = [at, at + len(body), ends]
        at += len(body)
    pieces.append("}")
    return "".join(pieces), parts


def relocated(folder: str, earlier: str, counts: Any, key: str, model: Model,
              changed: Iterable[str], root: str, project: str) -> Model | None:
    """The model of the run ``earlier`` with the lines of the C++ files ``changed``
    moved (``relocate``), kept under ``key`` with its findings and diagnostics, when
    ``model`` (this run's, its nodes extracted, no configuration built yet) has what
    that run's had then (the first of its packages and diagnostics: ``counts`` of each
    before its configurations were built, which may add more) but for those lines;
    else None."""
    from .relocate import Files

    settled()
    entry = _model_entry(folder, earlier)
    if entry is None:
        return None
    earlier, text = entry[0], entry[1].decode("utf-8")
    try:
        with open(_entry(folder, earlier + PARTS), encoding="utf-8") as handle:
            parts = json.load(handle)
        data = model_to_data(model)
        before = []
        for name in BEFORE_GRAPH:
            count = counts[name]
            if not isinstance(count, int) or count != len(data[name]):
                return None
            start = int(parts[name][0])
            before.append(text[start:int(parts[name][2][count - 1])] + "]" if count
                          else "[]")
    except (OSError, ValueError, KeyError, TypeError, IndexError):
        return None
    files = Files(changed, root)
    maps = files.line_maps("\0".join(before),
                           "\0".join(json.dumps(data[name]) for name in BEFORE_GRAPH))
    if maps is None:
        return None
    moved = _renumbered_parts(files, text, parts, maps)
    if moved is None:
        return None
    # the earlier run's findings and diagnostics, which must renumber, and ``extract``'s
    # summary lines (their places are the model's and its diagnostics'): one that does
    # not, or that lists places of a changed file by line alone, is made again when
    # asked (it decodes the whole model)
    kept: list[tuple[str, str]] = []
    for kind, needed in (("findings", True), ("diagnostics", True), ("summary", False)):
        for name in _run_entries(folder, earlier, kind):
            try:
                with open(os.path.join(folder, "runs", name), encoding="utf-8") as handle:
                    text = handle.read()
                found = files.renumbered(text, maps)
                if kind == "summary" and found is not None and _bare(text, changed, root):
                    found = None
            except (OSError, ValueError):
                continue
            if found is not None:
                kept.append((key + name[len(earlier):], found))
            elif needed:
                return None
    new_text, new_parts = moved
    _write_json(_entry(folder, key + PARTS), new_parts)
    for name, found in kept:
        _write_text(os.path.join(folder, "runs", name), found)
    if not _forked(lambda: _write_model(folder, key, new_text)):  # for later runs
        _write_model(folder, key, new_text)
    result = KeptModel(new_text.encode("utf-8"), project)
    _KEPT[result] = (folder, key)
    _MOVED[result] = _Moved(earlier, files, maps, list(changed), root)
    return result


def _bare(summary: str, changed: Iterable[str], root: str) -> bool:
    """Whether a kept summary's lines list places of a ``changed`` file by line alone
    (``report.text.bare_places``); True when they do not read as lines."""
    from .report.text import bare_places

    lines = json.loads(summary).get("summary")  # as ``_entry_or`` keeps it
    if not isinstance(lines, list) or not all(isinstance(line, str) for line in lines):
        return True
    top = os.path.abspath(root)
    names = [spelling for path in changed for spelling in (
        os.path.abspath(path), os.path.relpath(os.path.abspath(path), top))]
    return bare_places(lines, names)


def _run_entries(folder: str, key: str, kind: str) -> list[str]:
    """The names of the entries of kind ``kind`` the run ``key`` kept (one per inputs)."""
    try:
        return [entry.name for entry in os.scandir(os.path.join(folder, "runs"))
                if entry.name.startswith(f"{key}-{kind}-")]
    except OSError:
        return []


@dataclasses.dataclass(frozen=True)
class _Moved:
    """How ``relocated`` made a model of an earlier run's: to renumber, when asked, what
    else that run kept that is written only for some commands (``extract``'s document)."""

    earlier: str
    files: Files
    maps: Maps
    changed: list[str]
    root: str


_MOVED: weakref.WeakKeyDictionary[Model, _Moved] = weakref.WeakKeyDictionary()


def _moved_document(model: Model, folder: str, inputs: str) -> str | None:
    """``extract``'s document of a model ``relocated`` made, under ``inputs`` (its
    findings, as text): the earlier run's document under the same findings before the
    move, renumbered; None when there is none, or when the places of the changed files
    it holds are not, one for one, those of the model and the findings (a location
    written in a form not read as one: the document is then made)."""
    from .relocate import Files

    moved = _MOVED.get(model)
    # the model's text, to compare the document's places with (not once it is decoded:
    # the model may have changed since)
    kept = model._text if isinstance(model, KeptModel) else None
    if moved is None or kept is None:
        return None
    earlier = _earlier_text(folder, moved, "document", inputs)
    if earlier is None:
        return None
    indented = Files(moved.changed, moved.root, indented=True)
    found = indented.renumbered(earlier, moved.maps)
    if found is None:
        return None
    held = sorted(indented.places(found)[1])
    places = moved.files.places(kept.decode("utf-8"))[1] + moved.files.places(inputs)[1]
    if held != sorted(places):
        return None
    return found


def _earlier_text(folder: str, moved: _Moved, kind: str, inputs: str) -> str | None:
    """The text the earlier run of a model ``relocated`` made kept as ``kind`` under
    ``inputs`` before the move (``_kept_text``); None when it kept none."""
    backwards = {path: {new: old for old, new in lines.items()}
                 for path, lines in moved.maps.items()}
    before = moved.files.renumbered(inputs, backwards)
    if before is None:
        return None
    try:
        with open(os.path.join(folder, "runs",
                               f"{moved.earlier}-{kind}-{_digest(before)}.txt"),
                  encoding="utf-8", newline="") as handle:
            return handle.read()
    except (OSError, ValueError):
        return None


_PAGE_SOURCES = ',"sources":'


def _moved_page(model: Model, folder: str, inputs: str) -> str | None:
    """The report page of a model ``relocated`` made, under ``inputs`` (its workspace
    root and findings, as text): the earlier run's page under the same findings before
    the move, its data renumbered and the lines it shows of the changed files read again
    (``viz.sources``); None when there is none, when its data holds fewer places of the
    changed files than the model and the findings (one written in a form not read as a
    place), or when the lines shown come near the page's bound (which lines of which
    files it keeps could change)."""
    from .relocate import Files
    from .viz.html import PAGE_DATA, json_for_script
    from .viz.sources import MAX_LINE_CHARS, MAX_TOTAL_CHARS, file_snippets, shown_cost

    moved = _MOVED.get(model)
    kept = model._text if isinstance(model, KeptModel) else None
    if moved is None or kept is None:
        return None
    earlier = _earlier_text(folder, moved, "report", inputs)
    if earlier is None:
        return None
    start = earlier.find(PAGE_DATA) + len(PAGE_DATA)
    end = earlier.find("</script>", start)
    data = earlier[start:end]
    cut = data.rfind(_PAGE_SOURCES + "{")  # after the model and findings, before folders
    try:
        sources, after = json.JSONDecoder().raw_decode(data, cut + len(_PAGE_SOURCES))
        root = json.loads(inputs)[0]
    except (ValueError, IndexError, TypeError, KeyError):
        return None
    if start < len(PAGE_DATA) or end < 0 or cut < 0 or not isinstance(sources, dict):
        return None
    files = Files(moved.changed, moved.root, page=True)
    head = files.renumbered(data[:cut], moved.maps)
    if head is None or len(files.places(head)[1]) < (
            len(moved.files.places(kept.decode("utf-8"))[1])
            + len(moved.files.places(inputs)[1])):
        return None

    def cost(shown: Any) -> int:
        return sum(shown_cost(line) for line in shown.values()) if isinstance(
            shown, dict) else MAX_TOTAL_CHARS

    # the earlier page showed every line it wanted (a line shown takes at most this)
    if sum(cost(shown) for shown in sources.values()) > MAX_TOTAL_CHARS - (
            4 * MAX_LINE_CHARS + 8):
        return None
    changed = {os.path.abspath(path) for path in moved.changed}
    for name in [name for name in sources if os.path.abspath(
            os.path.join(moved.root, name)) in changed]:
        del sources[name]
    wanted: dict[str, set[int]] = {}
    for spelling, line in files.locations(head):
        if line > 0:
            wanted.setdefault(json.loads(f'"{spelling}"'), set()).add(line)
    folders = [root] if isinstance(root, str) else list(root)
    for name, lines in wanted.items():
        shown, _left = file_snippets(folders, name, lines, MAX_TOTAL_CHARS)
        if shown:
            sources[name] = shown
    if sum(cost(shown) for shown in sources.values()) > MAX_TOTAL_CHARS:
        return None
    return "".join((earlier[:start], head, _PAGE_SOURCES,
                    json_for_script(dict(sorted(sources.items()))), data[after:],
                    earlier[end:]))


def _renumbered_parts(files: Files, text: str, parts: dict[str, Any],
                      maps: Maps) -> tuple[str, dict[str, list[Any]]] | None:
    """A model's text renumbered (``relocate.Files.renumbered``) field by field, and
    where each field now is."""
    pieces: list[str] = []
    new_parts: dict[str, list[Any]] = {}
    at = 0
    length = 0
    for name, (start, end, ends) in sorted(parts.items(), key=lambda item: item[1][0]):
        head = files.renumbered(text[at:start], maps)
        if head is None:
            return None
        pieces.append(head)
        length += len(head)
        begin, new_ends = length, []
        for stop in [*ends, end]:  # item by item: where each now ends
            piece = files.renumbered(text[start:stop], maps)
            if piece is None:
                return None
            pieces.append(piece)
            length += len(piece)
            new_ends.append(length)
            start = stop
        new_parts[name] = [begin, length, new_ends[:-1]]
        at = end
    tail = files.renumbered(text[at:], maps)
    if tail is None:
        return None
    pieces.append(tail)
    return "".join(pieces), new_parts


def store_alias(folder: str, key: str, same_as: str, outer: str | None = None) -> None:
    """Run ``key`` gives the model (and findings) of run ``same_as`` (found through the
    ``outer`` key's record, which stays as long as they do)."""
    try:
        os.utime(_entry(folder, same_as))  # the newest again: kept as long as its alias
        if outer is not None:
            os.utime(_entry(folder, outer + "-outer"))
    except OSError:
        return
    _write(_entry(folder, key), {"same_as": same_as}, folder)


def store_outer(folder: str, outer: str, key: str, extraction: dict[str, Any]) -> None:
    """Under the outer key: the run's key and what its source extraction was given and
    gave (``pipeline``'s record), to try again when only C++ files changed."""
    _write(_entry(folder, outer + "-outer"), {"key": key, "extraction": extraction}, folder)


def load_outer(folder: str, outer: str) -> tuple[str, dict[str, Any]] | None:
    try:
        with open(_entry(folder, outer + "-outer"), encoding="utf-8") as handle:
            data = json.load(handle)
        return str(data["key"]), dict(data["extraction"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


def findings(model: Model, inputs: str, compute: Callable[[], list[Finding]]
             ) -> list[Finding]:
    """The findings of a kept model's run under ``inputs`` (the rules and roots, as
    text): read back when that model's run gave them before, else computed and kept."""
    settled()
    from .diff import finding_from_data

    return _with_run(model, "findings", inputs, compute, to_data,
                     lambda data: [finding_from_data(f) for f in data])


def page(model: Model, inputs: str, compute: Callable[[], str]) -> str:
    """The report page of a kept model's run under ``inputs`` (its findings and
    workspace root, as text): read back when that run wrote it before, else rendered
    and kept with the run (the page quotes the workspace's sources, which the run's key
    covers)."""
    return _kept_text(model, "report", inputs, compute)


def document(model: Model, inputs: str, compute: Callable[[], str]) -> str:
    """``extract``'s JSON text of a kept model's run under ``inputs`` (its findings, as
    text): read back when that run wrote it before, else made and kept with the run
    (the text is the model's document, which the run's key covers)."""
    return _kept_text(model, "document", inputs, compute)


def _kept_text(model: Model, kind: str, inputs: str, compute: Callable[[], str]) -> str:
    """``_with_run`` for a text (a page, a document of megabytes), kept as the text
    itself: read back without decoding JSON."""
    kept = _KEPT.get(model)
    if kept is None:
        return compute()
    folder, key = kept
    entry = os.path.join(folder, "runs", f"{key}-{kind}-{_digest(inputs)}.txt")
    try:
        with open(entry, encoding="utf-8", newline="") as handle:
            return handle.read()
    except (OSError, ValueError):
        pass
    moved = (_moved_document(model, folder, inputs) if kind == "document"
             else _moved_page(model, folder, inputs) if kind == "report" else None)
    found = compute() if moved is None else moved
    _write_text(entry, found)
    _prune(folder)
    return found


def _with_run(model: Model, kind: str, inputs: str, compute: Callable[[], T],
              save: Callable[[T], object], read: Callable[[Any], T]) -> T:
    """What ``compute`` gives for a kept model's run under ``inputs``, kept with the run
    as entry ``kind``: read back when that run kept it before."""
    kept = _KEPT.get(model)
    if kept is None:
        return compute()
    folder, key = kept
    return _entry_or(folder, _entry(folder, f"{key}-{kind}-{_digest(inputs)}"), kind,
                     compute, save, read)


def _entry_or(folder: str, entry: str, kind: str, compute: Callable[[], T],
              save: Callable[[T], object], read: Callable[[Any], T]) -> T:
    """What ``entry`` keeps as ``kind`` (``read`` from its data), else what ``compute``
    gives, kept there (``save`` makes its data)."""
    try:
        with open(entry, encoding="utf-8") as handle:
            return read(json.load(handle)[kind])
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        pass
    found = compute()
    _write(entry, {kind: save(found)}, folder)
    return found


def _write(entry: str, data: object, folder: str) -> None:
    """Write an entry, then prune the cache folder (``_prune``)."""
    _write_json(entry, data)
    _prune(folder)


def _prune(folder: str) -> None:
    """Keep the newest ``KEEP`` entries of each workspace's runs (their names begin with
    its ``_group``), and the entries of the ``WORKSPACES`` workspaces run last: several
    workspaces checked in turn keep their runs, and a workspace no longer analysed
    leaves nothing behind, its stat index neither. Names of an earlier version of this
    tool (no group) go as one workspace's."""
    runs = os.path.join(folder, "runs")
    groups: dict[str, list[tuple[int, str]]] = {}
    indexes: dict[str, list[tuple[int, str]]] = {}
    try:
        for entry in os.scandir(runs):
            if not entry.name.endswith((".json", ".txt")):
                continue
            group = _group_of(entry.name)
            index = entry.name == f"{group}-{INDEX}" or (
                not group and entry.name.startswith("index-"))
            (indexes if index else groups).setdefault(group, []).append(
                (entry.stat().st_mtime_ns, entry.path))
    except OSError:
        return
    newest = sorted(groups.keys() | indexes.keys(), reverse=True,
                    key=lambda g: max(groups.get(g, []) + indexes.get(g, [])))
    for rank, group in enumerate(newest):
        kept = KEEP if rank < WORKSPACES else 0
        gone = sorted(groups.get(group, []), reverse=True)[kept:]
        if rank >= WORKSPACES:
            gone += indexes.get(group, [])
        for _time, path in gone:
            with contextlib.suppress(OSError):
                os.remove(path)


def _group_of(name: str) -> str:
    """The workspace group an entry's file name begins with; "" for none."""
    head = name[:GROUP_LENGTH]
    if name[GROUP_LENGTH:GROUP_LENGTH + 1] == "-" and all(c in "0123456789abcdef"
                                                          for c in head):
        return head
    return ""


def _entry(folder: str, key: str) -> str:
    return os.path.join(folder, "runs", key + ".json")


def _digest(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8", "replace")).hexdigest()


def _write_json(path: str, data: object) -> None:
    _write_text(path, json.dumps(data))


def _write_bytes(path: str, data: bytes) -> None:
    """Write a file whole or not at all (``files.write_whole``)."""
    with contextlib.suppress(OSError):  # a cache not written is no cache, no error
        write_whole(path, data)


def _write_text(path: str, text: str) -> None:
    """Write a file whole or not at all (``files.write_whole``)."""
    with contextlib.suppress(OSError):  # a cache not written is no cache, no error
        write_whole(path, text)
