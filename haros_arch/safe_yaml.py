"""YAML from the workspace, read with bounds: the safe loader, at most ``MAX_NODES`` values
with aliases expanded (no "billion laughs"), at most ``MAX_DEPTH`` levels of nesting.

Every reader of YAML the workspace holds (rosparam files and ``<rosparam>`` in ROS 1, ROS 2
parameter files, ROS 2 YAML launch files, ``yaml.safe_load`` in Python launch files) goes
through ``load`` / ``compose``; a document past a bound raises ``YAMLLimit``, a
``yaml.YAMLError``, so each reader's existing handling of bad YAML says so.
"""

from __future__ import annotations

import functools
import pickle
import re
import threading
from collections import OrderedDict
from typing import Any, cast

import yaml

_CParser: Any  # libyaml's parser, when PyYAML was built with it
try:
    from yaml import cyaml as _cyaml

    _CParser = getattr(_cyaml, "CParser")  # noqa: B009 (not in the stubs' exports)
except ImportError:  # pragma: no cover - the wheels have it
    _CParser = None

MAX_NODES = 100_000
MAX_DEPTH = 100
MAX_OPEN_BRACKETS = 1_000  # "[" / "{" open at once in the text, checked before it is read


class YAMLLimit(yaml.YAMLError):
    """The document passes a bound, or holds a number Python refuses to read."""


def _parser(loader: type[yaml.SafeLoader]) -> Any:
    """``loader`` with libyaml's scanner and parser, when PyYAML has it: the same
    resolver and constructors (the tags and implicit types of ``loader``, ours too), the
    events read in C (a parameter file of nav2's size: 4 ms instead of 30 ms, read once
    per node that is given it). A loader with its own ``__init__`` is kept as it is."""
    if _CParser is None or loader.__init__ is not yaml.SafeLoader.__init__:
        return loader
    found = _FAST.get(loader)
    if found is None:

        def start(self: Any, stream: str) -> None:
            _CParser.__init__(self, stream)
            yaml.constructor.SafeConstructor.__init__(self)
            yaml.resolver.Resolver.__init__(self)

        found = _FAST[loader] = type(f"Fast{loader.__name__}", (_CParser, loader),
                                     {"__init__": start})
    return found


_FAST: dict[type, Any] = {}


def _reader(loader: type[yaml.SafeLoader], text: str) -> Any:
    """A reader of ``text`` (``_parser``); the pure one for text libyaml cannot take (lone
    surrogates, which it cannot encode: the pure reader says what is wrong, a YAML
    error)."""
    fast = _parser(loader)
    if fast is not loader:
        try:
            return fast(text)
        except UnicodeEncodeError:
            pass
    return loader(text)


def compose(text: str, loader: type[yaml.SafeLoader] = yaml.SafeLoader) -> yaml.Node | None:
    """The document's node tree, checked against the bounds."""
    _check_flow_depth(text)
    reader = _reader(loader, text)
    try:
        node = reader.get_single_node()
    except RecursionError:
        raise YAMLLimit(f"YAML nested more than {MAX_DEPTH} levels deep") from None
    except ValueError as err:  # int() of a huge number in a %YAML directive
        raise YAMLLimit(f"YAML cannot be read: {err}") from None
    finally:
        reader.dispose()
    if node is not None:
        check(node)
    return node


def load_with_lines(text: str, loader: type[yaml.SafeLoader] = yaml.SafeLoader
                    ) -> tuple[Any, Any]:
    """``load`` of ``text``, and from the same read where each of its keys is written:
    the document's mappings with each value replaced by the 1-based line of its key (a
    mapping below a key keeps its own keys), None for a document that is no mapping.
    Findings about a parameter of a file point at its key."""
    return _document(text, loader, lines=True)


def _key_lines(node: yaml.Node, depth: int = 0) -> Any:
    """The key lines of a composed node (``load_with_lines``); a key given twice in one
    mapping keeps the keys of both mappings (as rcl merges them:
    ``naming.ParamFileLoader``), the later's lines first."""
    if not isinstance(node, yaml.MappingNode) or depth > MAX_DEPTH:
        return None
    out: dict[str, Any] = {}
    for key, item in node.value:
        if isinstance(key, yaml.ScalarNode):
            inner = _key_lines(item, depth + 1)
            before = out.get(key.value)
            if isinstance(before, dict) and isinstance(inner, dict):
                inner = merged(before, inner)
            out[key.value] = key.start_mark.line + 1 if inner is None else inner
    return out


def keys_twice(text: str, loader: type[yaml.SafeLoader] = yaml.SafeLoader,
               merging: bool = True) -> list[tuple[tuple[str, ...], int, int]]:
    """The keys one mapping of the document writes twice where the later value replaces
    the earlier (with ``merging``, not both mappings, which rcl merges: ``merged``; PyYAML,
    roslaunch's ``<rosparam>`` reader, replaces a mapping whole too): each as the keys
    down to it, the line of its first writing and of the later, 1-based. rcl's parameter
    file parser and PyYAML keep the later value without a word (wato_monorepo's
    nuscenes_config.yaml before 7871674c wrote publish_clusters_topic twice, the second
    meant for another parameter). Nothing for a text that is no YAML (its reader says
    so)."""
    return list(_keys_twice(text, cast(Any, loader), merging))


@functools.lru_cache(maxsize=64)  # a file given to many nodes is read for each
def _keys_twice(text: str, loader: Any, merging: bool = True
                ) -> tuple[tuple[tuple[str, ...], int, int], ...]:
    try:
        node = compose(text, loader)
    except (yaml.YAMLError, ValueError, RecursionError):
        return ()
    found: list[tuple[tuple[str, ...], int, int]] = []
    _twice(node, (), found, 0, merging)
    return tuple(found)


def _twice(node: Any, path: tuple[str, ...], found: list[tuple[tuple[str, ...], int, int]],
           depth: int, merging: bool = True) -> None:
    if isinstance(node, yaml.SequenceNode) and depth <= MAX_DEPTH:
        for index, item in enumerate(node.value):
            _twice(item, (*path, str(index)) if path else path, found, depth + 1, merging)
        return
    if not isinstance(node, yaml.MappingNode) or depth > MAX_DEPTH:
        return
    seen: dict[str, tuple[yaml.Node, int]] = {}
    for key, item in node.value:
        if not isinstance(key, yaml.ScalarNode) or key.tag == "tag:yaml.org,2002:merge":
            continue
        line = key.start_mark.line + 1
        before = seen.get(key.value)
        if before is not None and not (merging and isinstance(before[0], yaml.MappingNode)
                                       and isinstance(item, yaml.MappingNode)):
            found.append(((*path, key.value), before[1], line))
        seen[key.value] = (item, line)
        _twice(item, (*path, key.value), found, depth + 1, merging)


def merged(first: dict[Any, Any], second: dict[Any, Any]) -> dict[Any, Any]:
    """Two mappings key by key, the second's over the first's, mappings under one key
    merged in turn (rcl's reading of a parameter file that writes a key twice; the key
    lines of such a file)."""
    out = dict(first)
    for key, value in second.items():
        before = out.get(key)
        out[key] = merged(before, value) if isinstance(before, dict) and isinstance(
            value, dict) else value
    return out


# a lone plain scalar (a launch parameter's text: ``1``, ``true``, ``/map``, ``0.5``, ``~``):
# resolved and constructed as the full reader would, without its scanner and parser (a
# file with tens of thousands of parameter values read each through those took minutes)
_PLAIN = re.compile(r"[A-Za-z0-9_.+/~][A-Za-z0-9_.+/~-]*|-[A-Za-z0-9_.+/~][A-Za-z0-9_.+/~-]*")
_SCALARS = yaml.SafeLoader("")


def _plain_scalar(text: str) -> tuple[bool, Any]:
    if not _PLAIN.fullmatch(text) or text.startswith(("---", "...")):
        return False, None
    tag = _SCALARS.resolve(yaml.ScalarNode, text, (True, False))
    construct = yaml.SafeLoader.yaml_constructors.get(tag)
    if construct is None:
        return False, None
    try:
        return True, construct(_SCALARS, yaml.ScalarNode(tag, text))
    except ValueError as err:  # an integer of more than 4300 digits
        raise YAMLLimit(f"YAML cannot be read: {err}") from None


def load(text: str, loader: type[yaml.SafeLoader] = yaml.SafeLoader) -> Any:
    """``yaml.safe_load`` with the bounds (one document)."""
    if loader is yaml.SafeLoader:
        done, value = _plain_scalar(text)
        if done:
            return value
    return _document(text, loader, lines=False)[0]


# Documents read again: a launch gives one parameter file to many nodes (nav2's bringup:
# twenty, each reading the file, then the text its rewrite dumped and substituted), and
# the workspace's launch files are each loaded to find the configurations, then again.
# What a read gave is kept, pickled (each reader gets its own fresh objects, aliases
# shared as the reader made them), by text and loader, for texts of at least
# ``_KEPT_FROM`` characters, at most ``_KEPT_CHARACTERS`` of them in all (least recently
# read dropped first). A text the reader refuses is read (and refused) again.
_KEPT_FROM = 512
_KEPT_CHARACTERS = 32_000_000
_kept: OrderedDict[tuple[str, type, bool], bytes] = OrderedDict()
_kept_size = [0]
_kept_lock = threading.Lock()


def _document(text: str, loader: type[yaml.SafeLoader], lines: bool) -> tuple[Any, Any]:
    """The document of ``text`` read with the bounds, and its key lines if asked."""
    if len(text) < _KEPT_FROM:
        return _read_document(text, loader, lines)
    key = (text, loader, lines)
    with _kept_lock:
        found = _kept.get(key)
        if found is not None:
            _kept.move_to_end(key)
    if found is not None:
        return pickle.loads(found)  # our own bytes, of the safe loader's values
    read = _read_document(text, loader, lines)
    try:
        data = pickle.dumps(read, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # a value pickle cannot write is only not kept
        return read
    size = len(text) + len(data)
    if size <= _KEPT_CHARACTERS:
        with _kept_lock:
            if key not in _kept:
                _kept[key] = data
                _kept_size[0] += size
            while _kept_size[0] > _KEPT_CHARACTERS:
                (old_text, _, _), old_data = _kept.popitem(last=False)
                _kept_size[0] -= len(old_text) + len(old_data)
    return read


def _read_document(text: str, loader: type[yaml.SafeLoader], lines: bool
                   ) -> tuple[Any, Any]:
    _check_flow_depth(text)
    reader = _reader(loader, text)
    try:
        if getattr(loader, "documents_merged", False):
            return _merged_documents(reader, lines)
        node = reader.get_single_node()
        if node is None:
            return None, None
        check(node)
        return reader.construct_document(node), _key_lines(node) if lines else None
    except RecursionError:
        raise YAMLLimit(f"YAML nested more than {MAX_DEPTH} levels deep") from None
    except ValueError as err:  # an integer of more than 4300 digits, a %YAML directive
        raise YAMLLimit(f"YAML cannot be read: {err}") from None
    finally:
        reader.dispose()


def _merged_documents(reader: Any, lines: bool) -> tuple[Any, Any]:
    """The documents of a stream read as one, for a loader whose ``documents_merged``
    says so (rcl's parameter file parser passes over the document start and end events):
    their mappings merged in order (``merged``), as a key written twice is; a stream
    holding a document that is no mapping beside another is refused as the single
    document reader refuses it."""
    nodes: list[yaml.Node] = []
    while reader.check_node():
        node = reader.get_node()
        if node is not None:
            check(node)
            nodes.append(node)
    values = [reader.construct_document(node) for node in nodes]
    kept = [(node, value) for node, value in zip(nodes, values, strict=True)
            if value is not None]
    if not kept:
        return None, None
    if len(kept) == 1:
        node, value = kept[0]
        return value, _key_lines(node) if lines else None
    if not all(isinstance(value, dict) for _, value in kept):
        raise yaml.composer.ComposerError(
            "expected a single document in the stream", kept[0][0].start_mark,
            "but found another document", kept[1][0].start_mark)
    document: dict[Any, Any] = {}
    where: dict[Any, Any] = {}
    for node, value in kept:
        document = merged(document, value)
        if lines:
            where = merged(where, _key_lines(node) or {})
    return document, where if lines else None


def _check_flow_depth(text: str) -> None:
    """Refuse ``[[[[...`` before the reader sees it: the scanner's work grows with the
    square of the flow nesting (a 200,000-deep document never ends). Brackets in quoted
    text count too; no real file has a thousand of them open at once."""
    if text.count("[") + text.count("{") <= MAX_OPEN_BRACKETS:
        return
    depth = 0
    for char in text:
        if char in "[{":
            depth += 1
            if depth > MAX_OPEN_BRACKETS:
                raise YAMLLimit(f"YAML nested more than {MAX_DEPTH} levels deep")
        elif char in "]}" and depth:
            depth -= 1


def check(root: yaml.Node) -> None:
    """Count values with aliases expanded and measure the nesting; refuse documents past
    the bounds before anything is constructed from them."""
    count = 0
    stack: list[tuple[yaml.Node, int]] = [(root, 1)]
    while stack:
        node, depth = stack.pop()
        count += 1
        if count > MAX_NODES:
            raise YAMLLimit(f"YAML document has more than {MAX_NODES} values "
                            "(aliases expanded)")
        if depth > MAX_DEPTH:
            raise YAMLLimit(f"YAML nested more than {MAX_DEPTH} levels deep")
        if isinstance(node, yaml.SequenceNode):
            stack.extend((item, depth + 1) for item in node.value)
        elif isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                stack.extend(((key, depth + 1), (value, depth + 1)))
