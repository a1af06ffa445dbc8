"""A persistent cache of what each C++ translation unit gives.

An entry is found by a key over the tool (our version, libclang's, the stand-in
headers), the parse flags and the source text; it holds the calls, node name and
diagnostics, and the content hash of every header the parse read from the workspace or
synthesised. It is used only when all those headers are unchanged. Entries are JSON
(never pickle: the cache lives in the analysed workspace, which we do not trust); one
that does not read back is ignored.
"""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import hashlib
import json
import os
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
from typing import Any

from ... import __version__
from ...diagnostics import CATALOGUE, Diagnostic
from ...files import AUTO_CACHE, cache_folder, content_digest, write_whole
from ...model.conditions import Condition
from ...model.location import Location
from ...model.source import PrimitiveCall
from . import interfaces
from .headers import STANDIN
from .synthesis import HEADER_NAME

AUTO = AUTO_CACHE  # cache_dir value: the default folder (``files.cache_folder``)
default_folder = cache_folder
FORMAT = 2  # 2: the headers and digest on a first line of their own
GENERATED = "<generated>"


PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def tool_files() -> list[str]:
    """The files whose content keys the entries: every module and data file of this
    package's code (the extractor imports the model, the expression evaluator, the build
    readers and more from outside its folder: a change to any of them may change what a
    unit gives), the stand-in headers and the catalogue of interface definitions (which
    makes the headers of installed messages). The shipped interface models (JSON) and
    the report's assets are not read by the extractor."""
    found: list[str] = []
    for folder, dirs, files in os.walk(PACKAGE):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        found += [os.path.join(folder, name) for name in sorted(files)
                  if name.endswith((".py", ".yaml", ".lark"))]
    found += [os.path.join(folder, name)
              for folder, _dirs, files in sorted(os.walk(STANDIN)) for name in sorted(files)]
    found += [os.path.join(folder, name) for folder, _dirs, files
              in sorted(os.walk(interfaces.CATALOGUE)) for name in sorted(files)]
    return list(dict.fromkeys(found))


@functools.lru_cache(maxsize=1)
def tool_version() -> str:
    """Our version, libclang's, and a hash of ``tool_files`` (so a changed tool never reads
    an older one's entries)."""
    from . import toolchain

    digest = hashlib.sha256(f"{__version__}/{FORMAT}".encode())
    try:
        import clang.cindex as ci

        version = ci.conf.lib.clang_getClangVersion()
        digest.update(ci._CXString.from_result(version).encode())
    except Exception:  # an old binding: the rest still keys the cache
        digest.update(b"libclang")
    for path in tool_files():
        digest.update(os.path.relpath(path, PACKAGE).encode() + b"\0")
        with open(path, "rb") as handle:
            digest.update(handle.read())
    digest.update(repr(toolchain.base_arguments(False)).encode())
    return digest.hexdigest()


def key(path: str, text: str, args: Iterable[str], generated: str) -> str:
    digest = hashlib.sha256(tool_version().encode())
    digest.update(path.encode() + b"\0" + text.encode("utf-8", "replace") + b"\0")
    digest.update(_arguments_digest(tuple(args), generated).encode())
    return digest.hexdigest()


@functools.lru_cache(maxsize=256)
def _arguments_digest(args: tuple[str, ...], generated: str) -> str:
    """Of a unit's parse flags (a thousand include folders in a big workspace, the same
    for every unit of a package: hashed once)."""
    return hashlib.sha256(b"".join(arg.replace(generated, GENERATED).encode() + b"\0"
                                   for arg in args)).hexdigest()


def node_key(paths: Sequence[str], digests: Mapping[str, str], complete: bool,
             entry: str | None, loadable: Collection[str] = ()) -> str:
    """The key of what a node's translation units ``paths`` give together (``digests``:
    what each gave, ``CppBatch.units``), all of them read (``complete``) or not, built
    as the class ``entry``, with the classes the workspace declares for a loader
    (``loadable``): the same key, the same node result."""
    return hashlib.sha256(json.dumps(
        [tool_version(), [[path, digests.get(path)] for path in paths], complete, entry,
         sorted(loadable)]
    ).encode()).hexdigest()


def digest(result: dict[str, Any]) -> str:
    """Of a translation unit's result (``to_data``): equal digests, equal results."""
    return hashlib.sha256(json.dumps(result, sort_keys=True).encode()).hexdigest()


class Cache:
    """Entries in ``folder``; ``generated`` is this run's folder of synthesised headers."""

    def __init__(self, folder: str, generated: str,
                 synthesised: Mapping[str, str] | None = None,
                 remake: Callable[[str], str | None] | None = None) -> None:
        self.folder = os.path.join(folder, "cpp")
        self.nodes = os.path.join(folder, "cpp-nodes")  # node results (``store_node``)
        self.generated = generated
        self.synthesised = {} if synthesised is None else synthesised  # path -> text, unwritten
        # a synthesised header this run has not made (yet): made now, when it is one a
        # parse makes on demand (a message header a unit uses unincluded), its text or
        # None. On disk from an earlier run it may be, or not: a run that parses removes
        # what it did not make (``headers._sync``), and its units would miss for good
        self.remake = remake
        self._digests: dict[str, str | None] = {}  # a header shared by entries: hashed once
        # the same for the headers of the entries stored: as read from disk after the
        # parse (a header the run synthesised while parsing is there by then)
        self._stored: dict[str, str] = {}

    def _fingerprint(self, path: str) -> str | None:
        if path not in self._digests:
            text = self.synthesised.get(path)
            if text is None and self.remake is not None and path.startswith(
                    self.generated + os.sep):
                text = self.remake(path)
            self._digests[path] = content_digest(path) if text is None else hashlib.sha256(
                text.encode("utf-8")).hexdigest()
        return self._digests[path]

    def load(self, entry: str, wanted: bool = True) -> tuple[dict[str, Any] | None, str] | None:
        """The stored result for key ``entry`` if its headers are unchanged, and its
        ``digest`` (kept with it); without ``wanted`` only the digest (the result, on
        the entry's second line, is not read: a run that only compares digests reads
        one short line per unit)."""
        try:
            with open(os.path.join(self.folder, entry + ".json"), encoding="utf-8") as handle:
                head = json.loads(handle.readline())
                for name, hashed in head["headers"]:
                    if self._fingerprint(name.replace(GENERATED, self.generated, 1)) != hashed:
                        return None
                kept = head["digest"]
                if not isinstance(kept, str):
                    return None
                if not wanted:
                    return None, kept
                result: dict[str, Any] = json.loads(handle.read())["result"]
            return result, kept
        except (OSError, ValueError, KeyError, TypeError):
            return None

    def load_node(self, key: str) -> dict[str, Any] | None:
        """A node's result kept under ``node_key`` (``store_node``), as data."""
        try:
            with open(os.path.join(self.nodes, f"{key}.json"), encoding="utf-8") as handle:
                data = json.load(handle)
            return data["result"] if isinstance(data.get("result"), dict) else None
        except (OSError, ValueError, AttributeError):
            return None

    def store_node(self, key: str, text: str) -> None:
        """Keep a node's result under ``node_key`` (``text``: the JSON of ``{"result":
        to_data(...)}``): made of its units' results alone, it is what they give while
        they give what they gave."""
        with contextlib.suppress(OSError):  # a cache not written is no cache, no error
            write_whole(os.path.join(self.nodes, f"{key}.json"), text)

    def store(self, entry: str, headers: Iterable[str], result: str, result_digest: str
              ) -> None:
        """Keep a unit's result (the JSON text of its ``to_data``, and the ``digest`` of
        that data) under ``entry``, with the digests of the headers it read."""
        listed = []
        derived = os.path.join(self.generated, HEADER_NAME)
        for name in headers:
            if name == derived:  # the names declared for this unit: never on disk, and
                continue  # made from the source and the other headers, which are listed
            hashed = self._stored.get(name)
            if hashed is None:
                hashed = content_digest(name)
                if hashed is None:
                    return
                self._stored[name] = hashed
            listed.append([name.replace(self.generated, GENERATED, 1), hashed])
        # two lines: what tells whether the entry holds and its digest, then the result
        # (``load`` without ``wanted`` reads only the first); ``dumps``: C's encoder
        # (``dump`` to a file always takes Python's)
        text = json.dumps({"headers": listed, "digest": result_digest}) + (
            '\n{"result": ' + result + "}")
        with contextlib.suppress(OSError):  # a cache not written is no cache, no error
            write_whole(os.path.join(self.folder, entry + ".json"), text)


# -- the result as JSON ----------------------------------------------------------------

_SCALARS = frozenset({str, int, float, bool, type(None)})
_FIELDS: dict[type, tuple[str, ...]] = {}  # a dataclass's field names, by its type


def plain(value: Any) -> Any:
    """``dataclasses.asdict`` of a value made of dataclasses, lists, tuples and dicts,
    without its deep copies (a tuple becomes a list, as JSON writes either): a unit's or
    a node's result holds thousands of calls, each with its location and conditions,
    and ``asdict`` was most of the time a cold run spent keeping node results."""
    kind = type(value)
    if kind in _SCALARS:
        return value
    names = _FIELDS.get(kind)
    if names is None and dataclasses.is_dataclass(value) and not isinstance(value, type):
        names = _FIELDS[kind] = tuple(f.name for f in dataclasses.fields(value))
    if names is not None:
        return {name: plain(getattr(value, name)) for name in names}
    if isinstance(value, (list, tuple)):
        return [plain(item) for item in value]
    if isinstance(value, dict):
        return {key: plain(item) for key, item in value.items()}
    return value


def to_data(calls: list[PrimitiveCall], rosname: str | None,
            diagnostics: list[Diagnostic],
            facts: list[tuple[str, int, str, str]] | None = None,
            node_names: list[tuple[str, str]] | None = None,
            constructions: list[tuple[str, str]] | None = None,
            unseen: list[str] | None = None,
            made_under: list[tuple[str, tuple[Condition, ...]]] | None = None,
            uses: list[tuple[str, str]] | None = None,
            defines: list[str] | None = None,
            handed: list[str] | None = None,
            unseen_in: list[tuple[str, str]] | None = None,
            passed: list[tuple[str, str]] | None = None,
            hidden: list[str] | None = None,
            registered: list[tuple[str, str]] | None = None,
            loads_in: list[str] | None = None,
            node_handed: list[tuple[str, str]] | None = None) -> dict[str, Any]:
    return {"calls": [plain(c) for c in calls], "rosname": rosname,
            "diagnostics": [plain(d) for d in diagnostics],
            "facts": [list(f) for f in facts or ()],
            "node_names": [list(n) for n in node_names or ()],
            "constructions": [list(n) for n in constructions or ()],
            "unseen": list(unseen or ()),
            "made_under": [[made, [plain(c) for c in under]]
                           for made, under in made_under or ()],
            "uses": [list(n) for n in uses or ()], "defines": list(defines or ()),
            "handed": list(handed or ()), "unseen_in": [list(n) for n in unseen_in or ()],
            "passed": [list(n) for n in passed or ()], "hidden": list(hidden or ()),
            "registered": [list(n) for n in registered or ()],
            "loads_in": list(loads_in or ()),
            "node_handed": [list(n) for n in node_handed or ()]}


def from_data(data: dict[str, Any]) -> tuple[
        list[PrimitiveCall], str | None, list[Diagnostic], list[tuple[str, int, str, str]],
        list[tuple[str, str]], list[tuple[str, str]], list[str],
        list[tuple[str, tuple[Condition, ...]]], list[tuple[str, str]], list[str], list[str],
        list[tuple[str, str]], list[tuple[str, str]], list[str], list[tuple[str, str]],
        list[str], list[tuple[str, str]]]:
    """Raises ValueError / TypeError / KeyError for data that is not ours."""
    calls = calls_from_data(data["calls"])
    made_under = []
    for made, under in data.get("made_under", ()):
        if not isinstance(made, str):
            raise TypeError("made_under")
        made_under.append((made, _conditions(under)))
    # the severity comes from today's catalogue, not from when the entry was written
    diagnostics = [Diagnostic(**{**d, "location": Location(**d["location"]),
                                 "also": tuple(Location(**w) for w in d.get("also", ())),
                                 "severity": _severity(d["code"], d["severity"])})
                   for d in data["diagnostics"]]
    rosname = data["rosname"]
    if rosname is not None and not isinstance(rosname, str):
        raise TypeError("rosname")
    facts = []
    for usr, index, value, site in data.get("facts", ()):
        if not (isinstance(usr, str) and isinstance(index, int) and isinstance(value, str)
                and isinstance(site, str)):
            raise TypeError("facts")
        facts.append((usr, index, value, site))
    unseen, defines = data.get("unseen", []), data.get("defines", [])
    handed, hidden = data.get("handed", []), data.get("hidden", [])
    loads_in = data.get("loads_in", [])
    for key, words in (("unseen", unseen), ("defines", defines), ("handed", handed),
                       ("hidden", hidden), ("loads_in", loads_in)):
        if not (isinstance(words, list) and all(isinstance(word, str) for word in words)):
            raise TypeError(key)
    return (calls, rosname, diagnostics, facts, _pairs(data, "node_names"),
            _pairs(data, "constructions"), unseen, made_under, _pairs(data, "uses"), defines,
            handed, _pairs(data, "unseen_in"), _pairs(data, "passed"), hidden,
            _pairs(data, "registered"), loads_in, _pairs(data, "node_handed"))


def calls_from_data(data: Iterable[Any]) -> list[PrimitiveCall]:
    """Calls as ``to_data`` writes them (``plain``); ValueError / TypeError / KeyError for
    data that is not ours."""
    calls = []
    for item in data:
        item = dict(item)
        item["location"] = Location(**item["location"])
        item["conditions"] = _conditions(item["conditions"])
        calls.append(PrimitiveCall(**item))
    return calls


def other_key(header: str, digest: str, first: int, last: int, release: str,
              ros2: bool) -> str:
    """The key of what the parse announcing the client library's version ``release``
    ("29.6.0") read in the branch of lines ``first`` to ``last`` of ``header`` (content
    ``digest``), kept from run to run (``extract.cpp._other_version``)."""
    return hashlib.sha256(json.dumps([tool_version(), header, digest, first, last, release,
                                      ros2]).encode()).hexdigest()


def load_other(folder: str, key: str, generated: str
               ) -> tuple[tuple[PrimitiveCall, ...] | None] | None:
    """What ``store_other`` kept under ``key`` (the branch's calls, or None when that
    parse did not read it whole), in a 1-tuple; None when nothing is kept or a header
    that parse read has changed since."""
    try:
        with open(os.path.join(folder, key + ".json"), encoding="utf-8") as handle:
            data = json.load(handle)
        for name, hashed in data["headers"]:
            if content_digest(name.replace(GENERATED, generated, 1)) != hashed:
                return None
        calls = data["calls"]
        return (None,) if calls is None else (tuple(calls_from_data(calls)),)
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None


def store_other(folder: str, key: str, headers: Iterable[str], generated: str,
                calls: Sequence[PrimitiveCall] | None) -> None:
    """Keep what a parse with another version read in a branch (``load_other``), with
    the digests of the headers it read."""
    listed = []
    for name in sorted(set(headers)):
        hashed = content_digest(name)
        if hashed is None:
            return
        listed.append([name.replace(generated, GENERATED, 1), hashed])
    text = json.dumps({"headers": listed, "calls": None if calls is None
                       else [plain(c) for c in calls]})
    with contextlib.suppress(OSError):  # a cache not written is no cache, no error
        write_whole(os.path.join(folder, key + ".json"), text)


def conditions_text(conditions: Iterable[Condition]) -> str:
    """Conditions as one string (a ``links.CONDITIONS`` fact's value)."""
    return json.dumps([plain(c) for c in conditions], sort_keys=True)


@functools.lru_cache(maxsize=4096)
def conditions_of_text(text: str) -> tuple[Condition, ...]:
    """The conditions ``conditions_text`` wrote; ValueError / TypeError / KeyError for
    text that is not such. Remembered: a node's facts repeat the same few texts (every
    unit that includes a header gives its call sites again), and conditions are frozen."""
    return _conditions(json.loads(text))


def _conditions(data: Any) -> tuple[Condition, ...]:
    """JSON's lists back as the tuples ``Condition`` holds (a list of runs would differ
    from the default ``()`` and be written in the model)."""
    return tuple(Condition(**{**c, "location": Location(**c["location"]), "parameters": tuple(
        (str(local), str(param)) for local, param in c["parameters"]) if c.get(
        "parameters") else None, "runs": tuple(c.get("runs") or ()), "constants": tuple(
        (str(name), value) for name, value in c["constants"]) if c.get(
        "constants") else None, "elements": tuple(
        (str(name), str(listed), str(field)) for name, listed, field in c["elements"]) if c.get(
        "elements") else None}) for c in data)


def _pairs(data: dict[str, Any], key: str) -> list[tuple[str, str]]:
    pairs = []
    for first, second in data.get(key, ()):
        if not (isinstance(first, str) and isinstance(second, str)):
            raise TypeError(key)
        pairs.append((first, second))
    return pairs


def _severity(code: str, stored: str) -> Any:
    entry = CATALOGUE.get(code)
    return entry.severity if entry is not None else stored
