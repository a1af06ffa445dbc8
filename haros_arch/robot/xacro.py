"""Expand a xacro robot description statically, without running anything.

``expand(path, args, workspace)`` reads a ``.urdf.xacro`` (or a plain URDF / SDF file)
and returns the expanded document as xacro's in-order processing would make it:
``xacro:property`` (value, default, block), ``xacro:arg``, ``xacro:macro`` and its calls
(``name``, ``name:=default``, ``name:=^|default``, ``*block`` / ``**block`` parameters,
``xacro:insert_block``, ``xacro:call``), ``xacro:include`` (``$(find pkg)``, paths relative
to the including file), ``xacro:if`` / ``xacro:unless``, ``xacro:element`` /
``xacro:attribute``, ``${...}`` expressions and ``$(arg)``, ``$(find)``, ``$(env)``,
``$(optenv)``, ``$(eval)``, ``$(dirname)``.

Expressions go through the one safe evaluator (``launch.expression.evaluate``, the
configuration ``$(eval)`` has) with xacro's own table: Python's builtins, ``math``,
``xacro.load_yaml``, and the properties in scope as names: nothing from the workspace is
run. Text known in part is the readers' one partial value (``model.values.Value``): what
cannot be known (an argument nobody set, a package not found, a construct outside the
subset) is an ``Unknown`` part, written ``?``, and its reason is kept in
``Description.unknown``; an ``if`` whose value is not known
keeps its content, marked with the condition's text (``CONDITION`` attribute) so what is
under it can carry the condition. Files are read only inside the workspace and installed
packages; includes nest at most ``MAX_DEPTH`` deep, at most ``MAX_FILES`` files are read
and ``MAX_ELEMENTS`` elements made. Problems are diagnostics with the file and line.
"""

from __future__ import annotations

import copy
import math
import os
import re
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, NamedTuple, cast

import yaml
from lxml import etree

from .. import diagnostics as diag
from .. import safe_yaml
from ..evaluate.python import KeyAttributes
from ..files import read_bytes, read_text
from ..launch import expression
from ..launch.ros1.params import convert_value
from ..manifest import xml_parser
from ..model.diagnostic import Diagnostic
from ..model.location import Location
from ..model.values import UNKNOWN_MARK, Unknown, UnknownKind, Value
from ..share import configured, share_source
from ..workspace import Workspace

Element = etree._Element

# files of one description: robot description libraries include every file they have
# (robotnik_sensors' all_sensors.urdf.xacro includes 70)
MAX_FILES = 256
MAX_DEPTH = 32  # includes and macro calls nested
MAX_ELEMENTS = 50_000
MAX_TEXT = 100_000  # characters of one evaluated value
MAX_PARAMS_TEXT = 10_000  # characters of a macro's params
MAX_CHARACTERS = 20_000_000  # characters of all evaluated text
# an expression's evaluation steps (URDF arithmetic takes tens), and the seconds of
# processor time one description may take in all: many expressions each just under the
# step bound stop there. Processor time, not the clock: a machine busy with other work
# must not cut a description another run reads whole (a result may not depend on load)
EXPRESSION_LIMITS = expression.Limits(steps=20_000)
MAX_SECONDS = 20.0
MAX_FILE_BYTES = 4 * 1024 * 1024
# a private attribute on elements kept under an ``if`` whose value is not known
CONDITION = "{urn:haros-arch}condition"
FILE = "{urn:haros-arch}file"  # the file an element comes from (on roots and MARKED)
MARKED = ("plugin", "ros2_control")
# the namespace of a prefix no ``xmlns`` declares, in a file read as it is
UNDECLARED = "urn:haros-arch:undeclared:"
_TOKENS = re.compile(r"\$\$+[{(]|\$\{[^}]*\}|\$\([^)]*\)|[^$]+|\$[^{($]+|\$$|\$")
# the start of one parameter of a macro's ``params``, as xacro's ``re_macro_arg`` reads
# it: its name, ``:=`` (or ``=``) and the spaces after it
_MACRO_HEAD = re.compile(r"\s*([^\s:=]+?)\s*:?=", re.S)


def _undeclared(name: str) -> str:
    """``prefix:local`` of a prefix no ``xmlns`` declares, in a namespace of its own."""
    prefix, _, local = name.partition(":")
    return f"{{{UNDECLARED}{prefix}}}{local}"


def partial_text(text: str, reason: str) -> str | Value:
    """``text`` whose every ``?`` is a part not known for ``reason`` (a xacro argument
    given as a name with unknown parts); ``text`` itself when it has none."""
    if UNKNOWN_MARK not in text:
        return text
    pieces = text.split(UNKNOWN_MARK)
    parts: list[str | Unknown] = [pieces[0]]
    for piece in pieces[1:]:
        parts += [Unknown(reason), piece]
    return Value.of(*parts)


def _unknown(origin: str, causes: tuple[str, ...] = (),
             kind: UnknownKind = "unknown") -> Value:
    """One part not known: for ``origin``, or computed from unknowns with ``causes``."""
    return Value((Unknown(origin, kind, causes),))


class _Undecided(NamedTuple):
    """An ``if`` / ``unless`` whose value is not known: its text and why."""

    text: str
    reasons: tuple[str, ...]


@dataclass
class Description:
    """An expanded robot description: the document and how it was made."""

    path: str
    root: Element | None = None
    files: list[str] = field(default_factory=list)  # every file read, in order
    unknown: list[str] = field(default_factory=list)  # why some parts are ``?``
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def is_complete(self) -> bool:
        return self.root is not None and not self.unknown


@dataclass
class _Macro:
    name: str
    params: list[tuple[str, tuple[str | None, str | None] | None]]
    body: Element
    where: tuple[str, int]
    # the scope of the file included with ns= that defines it: its body sees that
    # file's properties first (others see the caller's, as xacro scopes them)
    home: _Scope | None = None


class _Scope:
    """Properties and macros, looked up through the enclosing scopes."""

    def __init__(self, parent: _Scope | None = None, namespace: bool = False) -> None:
        self.parent = parent
        self.namespace = namespace  # the scope of a file included with ns=
        self.values: dict[str, Any] = {}
        self.lazy: dict[str, str] = {}  # name -> unevaluated text
        self.macros: dict[str, _Macro] = {}
        self.namespaces: dict[str, _Scope] = {}  # xacro:include ns=: its own macros

    def owner(self, name: str) -> _Scope | None:
        scope: _Scope | None = self
        while scope is not None:
            if name in scope.values or name in scope.lazy:
                return scope
            scope = scope.parent
        return None

    def macro(self, name: str) -> _Macro | None:
        """The macro ``name`` (``ns.name``: of the file included with ``ns=``)."""
        head, dot, rest = name.partition(".")
        scope: _Scope | None = self
        while scope is not None:
            if not dot and name in scope.macros:
                return scope.macros[name]
            if dot and head in scope.namespaces:
                return scope.namespaces[head].macro(rest)
            scope = scope.parent
        return None

    def top(self) -> _Scope:
        scope = self
        while scope.parent is not None:
            scope = scope.parent
        return scope


class _Stop(Exception):
    """A bound was reached: the expansion ends here."""


def is_xacro(element: Any) -> bool:
    """A xacro element: one written with the declared prefix ``xacro``, whatever URI its
    ``xmlns:xacro`` gives (xacro matches the qualified tag, ``xacro:macro``:
    robotnik_sensors' orbbec_astra.urdf.xacro declares
    ``xmlns:xacro="http://wiki.ros.org/Sensors/OrbbecAstra"``), or one in a namespace
    whose URI names xacro."""
    if not isinstance(element.tag, str) or not element.tag.startswith("{") or \
            element.tag.startswith("{" + UNDECLARED):  # read as it is: no xacro runs
        return False
    return element.prefix == "xacro" or "xacro" in element.tag[1:element.tag.index("}")]


def line_of(element: Element | None) -> int:
    line = element.sourceline if element is not None else 0
    return line if isinstance(line, int) else 0


def local_name(element: Element) -> str:
    tag = element.tag if isinstance(element.tag, str) else ""
    return tag.rsplit("}", 1)[-1]


def expand(path: str, args: Mapping[str, str | Value], workspace: Workspace,
           environment: Mapping[str, str] | None = None,
           named_at: Location | None = None, by_xacro: bool = True,
           command: bool = False) -> Description:
    """The robot description in ``path`` expanded with ``args`` (``name:=value`` of the
    xacro command line). Never raises for bad input. ``named_at``: where the file is
    named (a launch file's xacro command), the place of what is said of the file itself
    before it is read (not there: its line 0 is no place to look). ``by_xacro``: the file
    goes through xacro, whose XML reader (minidom's, namespace-aware) rejects a prefix no
    ``xmlns`` declares; False: the tool that uses it reads it as it is (sdformat for
    ``gz sim``'s ``create -file``, urdfdom for a ``cat`` command's output, both
    tinyxml2), which keeps such a prefix as part of the name (gz-sim's custom sensors,
    ``<sensor type="custom" gz:type="dvl">``). ``command``: the launch runs the command
    that reads the file wherever it is loaded (no condition not known): a file that is
    not there, or (through xacro) not well-formed, makes it fail and the launch stop,
    ``ROBOT_DESCRIPTION_COMMAND_FAILS`` instead of ``ROBOT_DESCRIPTION_FILE``."""
    expander = _Expander(path, dict(args), workspace,
                         workspace.environment if environment is None else environment,
                         named_at, by_xacro)
    expander.command = command
    description = expander.description
    try:
        root = expander.read(path, None)
        if root is not None:
            expander.process(root, _Scope(), 0)
            description.root = root
    except _Stop:
        description.root = None
    except RecursionError:
        expander.report(None, "ROBOT_DESCRIPTION_LIMIT", detail="nested too deeply")
        description.root = None
    return description


class _Expander:
    def __init__(self, path: str, args: dict[str, Any], workspace: Workspace,
                 environment: Mapping[str, str], named_at: Location | None = None,
                 by_xacro: bool = True) -> None:
        self.description = Description(path)
        self.by_xacro = by_xacro
        self.command = False  # read by a command the launch runs (``expand``)
        self.named_at = named_at
        self.args = args
        self.workspace = workspace
        self.environment = environment
        self.elements = 0
        self.characters = 0  # of evaluated text made
        self.deadline = time.thread_time() + MAX_SECONDS
        self.files: list[str] = []  # the stack of files being read
        # the includes not read so far (their namespace, the file as written): a macro
        # called after one may be defined there (``_unread_source``)
        self.unread: list[tuple[str, str]] = []
        # the macros being expanded, each with how many conditions not decided enclosed
        # its call, and how many enclose the element at hand (``call``)
        self.expanding: list[tuple[int, int]] = []
        self.undecided = 0

    # -- diagnostics and unknowns ----------------------------------------------------------
    def where(self, element: Element | None) -> Any:
        if not self.files and self.named_at is not None:
            return self.named_at  # the top file, named there, not read yet
        path = self.files[-1] if self.files else self.description.path
        return self.workspace.location(path, line_of(element))

    def report(self, element: Element | None, code: str, **params: object) -> None:
        self.description.diagnostics.append(diag.make(code, self.where(element), **params))

    def _unread_source(self, name: str) -> str | None:
        """The first include not read so far (a package not found, a file that is not
        there or outside the workspace) that could define the macro ``name``: one
        without ``ns=``, or whose namespace prefixes ``name``. xacro reads in order, so
        an include after the call defines nothing for it."""
        return next((text for namespace, text in self.unread
                     if not namespace or name.startswith(namespace + ".")), None)

    def unknown(self, element: Element | None, reason: str) -> None:
        where = self.where(element)
        text = f"{reason} ({where.file}:{where.line})"
        if text not in self.description.unknown:
            self.description.unknown.append(text)

    # -- files -----------------------------------------------------------------------------
    def read(self, path: str, at: Element | None) -> Element | None:
        if len(self.description.files) >= MAX_FILES:
            self.report(at, "ROBOT_DESCRIPTION_LIMIT", detail=f"more than {MAX_FILES} files")
            raise _Stop
        path = _source(self.workspace, os.path.abspath(path))
        if not self.workspace.readable(path, self.environment):
            self.unknown(at, f"{self.workspace.relpath(path)} is outside the workspace")
            return None
        if os.path.isfile(path):
            data, found = read_bytes(path, self.where(at), MAX_FILE_BYTES)
            self.description.diagnostics.extend(found)
        else:
            made = configured(self.workspace, path)
            if made is None or made.text is None:
                detail = "no such file" if made is None else (
                    f"made by configure_file at {self.workspace.relpath(made.file)}:"
                    f"{made.line} from {self.workspace.relpath(made.input)}, but "
                    + made.unknown)
                self.report(at, "ROBOT_DESCRIPTION_COMMAND_FAILS" if self.command
                            and made is None else "ROBOT_DESCRIPTION_FILE",
                            path=self.workspace.relpath(path), detail=detail)
                self.unknown(at, f"{self.workspace.relpath(path)} does not exist"
                             if made is None else f"{self.workspace.relpath(path)}, "
                             f"{detail}")
                return None
            # the build writes it from its template: read as made, its lines the
            # template's (where what it says is written)
            data, path = made.text.encode(), made.input
        if data is None:
            self.unknown(at, f"{self.workspace.relpath(path)} is not read")
            return None
        try:
            root = self.parse(data, path)
        except etree.XMLSyntaxError as err:
            line = err.lineno or 0
            self.description.diagnostics.append(diag.make(
                "ROBOT_DESCRIPTION_COMMAND_FAILS" if self.command and self.by_xacro
                else "ROBOT_DESCRIPTION_FILE", self.workspace.location(path, line),
                path=self.workspace.relpath(path), detail=str(err.msg)))
            self.unknown(at, f"{self.workspace.relpath(path)} is not well-formed XML")
            return None
        self.description.files.append(path)
        root.set(FILE, path)
        return root

    def parse(self, data: bytes, path: str) -> Element:
        """The document in ``data``; raises ``XMLSyntaxError`` where the tool reading it
        would fail. Read as it is (not ``by_xacro``), a prefix no ``xmlns`` declares is
        no error: the element or attribute keeps it in its name."""
        parser = xml_parser()
        try:
            return etree.fromstring(data, parser, base_url=path)
        except etree.XMLSyntaxError:
            # the parser's own log: the exception's holds earlier parses' errors too
            errors = list(cast(Any, parser.error_log))
            if self.by_xacro or not errors or any(
                    e.domain != etree.ErrorDomains.NAMESPACE for e in errors):
                raise
        root = etree.fromstring(data, xml_parser(recover=True), base_url=path)
        for element in root.iter():  # lxml sets no name with an undeclared prefix
            tag = element.tag
            if isinstance(tag, str) and ":" in tag and not tag.startswith("{"):
                element.tag = _undeclared(tag)
            for key in [str(k) for k in element.attrib]:
                if ":" in key and not key.startswith("{"):
                    element.set(_undeclared(key), element.attrib.pop(key))
        return root

    # -- the walk --------------------------------------------------------------------------
    def process(self, root: Element, scope: _Scope, depth: int) -> None:
        """Expand the document ``root`` (a file's root element) in place."""
        self.files.append(root.get(FILE) or self.description.path)
        try:
            self.attributes(root, scope)
            self.children(root, scope, depth)
        finally:
            self.files.pop()

    def children(self, parent: Element, scope: _Scope, depth: int) -> None:
        if depth > MAX_DEPTH:
            self.report(parent, "ROBOT_DESCRIPTION_LIMIT",
                        detail=f"includes and macros nested deeper than {MAX_DEPTH}")
            raise _Stop
        if parent.text:
            parent.text = self.text_of(parent, parent.text, scope)
        made: list[Element] = []  # the children as they come out, put back at once
        for child in list(parent):
            self.elements += 1
            if self.elements > MAX_ELEMENTS:
                self.report(child, "ROBOT_DESCRIPTION_LIMIT",
                            detail=f"more than {MAX_ELEMENTS} elements")
                raise _Stop
            replacement = self.element(child, scope, depth) \
                if isinstance(child.tag, str) else None
            tail = self.text_of(parent, child.tail, scope) if child.tail else child.tail
            if replacement is None:
                child.tail = tail
                made.append(child)
                continue
            made.extend(replacement)
            if tail and tail.strip():  # text after a xacro element stays where it was
                if made:
                    made[-1].tail = (made[-1].tail or "") + tail
                else:
                    parent.text = (parent.text or "") + tail
        parent[:] = made

    def element(self, element: Element, scope: _Scope, depth: int) -> list[Element] | None:
        """Handle one child; a list replaces it (empty: removed), None keeps it."""
        if not is_xacro(element):
            if local_name(element) in MARKED and element.get(FILE) is None:
                element.set(FILE, self.files[-1] if self.files else self.description.path)
            self.attributes(element, scope)
            self.children(element, scope, depth)
            return None
        name = local_name(element)
        handler = _HANDLERS.get(name)
        if handler is not None:
            return handler(self, element, scope, depth)
        return self.call(element, name, scope, depth)

    def attributes(self, element: Element, scope: _Scope) -> None:
        for raw_key, raw_value in list(element.attrib.items()):
            key, value = str(raw_key), str(raw_value)
            if key.startswith("{urn:haros-arch}"):
                continue
            if key.startswith("{") and "xacro" in key:
                del element.attrib[key]
                continue
            element.set(key, self.text_of(element, value, scope))

    def content(self, element: Element, scope: _Scope, depth: int) -> list[Element]:
        """The processed children of ``element`` (its text and tails kept)."""
        self.children(element, scope, depth)
        return list(element)

    # -- values ----------------------------------------------------------------------------
    def text_of(self, element: Element, text: str, scope: _Scope) -> str:
        value = self.evaluate(element, text, scope)
        if isinstance(value, Value):
            for reason in value.origins:
                self.unknown(element, reason)
        made = _str(value)
        if made is not text:
            self.characters += len(made)
            if self.characters > MAX_CHARACTERS:
                self.report(element, "ROBOT_DESCRIPTION_LIMIT",
                            detail=f"more than {MAX_CHARACTERS} characters of values")
                raise _Stop
        return made

    def evaluate(self, element: Element, text: str, scope: _Scope) -> Any:
        """xacro's ``eval_text``: one ``${}`` or ``$()`` alone keeps its type."""
        if "$" not in text:
            return text
        parts: list[Any] = []
        for token in _TOKENS.findall(text):
            if token.startswith("$$"):
                parts.append(token[1:])
            elif token.startswith("${") and token.endswith("}"):
                parts.append(self.expression(element, token[2:-1], scope))
            elif token.startswith("$(") and token.endswith(")"):
                inner = self.evaluate(element, token[2:-1], scope)
                parts.append(self.extension(element, inner, scope))
            else:
                parts.append(token)
        if len(parts) == 1:
            return parts[0]
        texts = [part if isinstance(part, Value) else _str(part) for part in parts]
        if sum(len(_str(text)) for text in texts) > MAX_TEXT:
            self.report(element, "ROBOT_DESCRIPTION_LIMIT",
                        detail=f"a value longer than {MAX_TEXT} characters")
            raise _Stop
        if any(isinstance(text, Value) for text in texts):
            return Value.of(*texts)
        return "".join(str(text) for text in texts)

    def expression(self, element: Element, text: str, scope: _Scope,
                   of_args: bool = False) -> Any:
        """``${text}``; ``of_args``: the body of ``$(eval text)``, whose names are the
        xacro arguments (substitution_args' ``_eval``: roslaunch's table, then each
        argument's value as ``convert_value(.., 'auto')`` gives it), not properties."""
        inner = self.evaluate(element, text, scope)
        if isinstance(inner, Value):
            return _unknown(f"${{{text}}}", inner.origins)
        reasons: list[str] = []

        def argument(name: object) -> object:
            value = self.args.get(str(name))
            if value is None:
                raise KeyError(name)
            if isinstance(value, Value):
                reasons.extend(value.origins)
                return expression.Unknown(f"arg {name} is not known")
            return convert_value(value, "auto")

        def names(name: str) -> object:
            if of_args:
                return argument(name)
            if scope.owner(name) is None:
                source = self._unread_source(name)
                if source is None:
                    raise KeyError(name)
                # no fault of the file: an include not read may define it (legged_control's
                # ``urdf/$(arg robot_type)/const.xacro`` of an argument not known: each of
                # its 95 properties was a warning "name ... is not defined")
                reasons.append(f"property {name} is not defined here; it may be one of "
                               f"{source}, which is not read")
                return expression.Unknown(f"property {name} is not known")
            value = self.lookup(element, name, scope)
            if isinstance(value, Value):
                reasons.extend(value.origins)
                return expression.Unknown(f"property {name} is not known")
            if isinstance(value, etree._Element):
                return expression.Unknown(f"{name} is a block", "unsupported")
            return value

        # xacro's table: Python's builtins, math's names, and its own functions, as the
        # attributes of its ``xacro`` name (``load_yaml`` alone too, as xacro still has it)
        functions: dict[str, Any] = {**expression.BUILTINS, **expression.MATH,
                                     "load_yaml": self.load_yaml,
                                     "xacro.load_yaml": self.load_yaml}
        if of_args:
            functions = {**expression.BUILTINS, **expression.MATH, "arg": argument,
                         "true": True, "false": False, "True": True, "False": False}
        source = _str(inner)
        if time.thread_time() > self.deadline:
            self.report(element, "ROBOT_DESCRIPTION_LIMIT",
                        detail=f"expanding took more than {MAX_SECONDS:g} s of processor time")
            raise _Stop
        result = expression.evaluate(source, names, functions, EXPRESSION_LIMITS)
        if isinstance(result, expression.Unknown):
            if result.kind != "unknown":  # refused or wrong, not just unknown inputs
                self.report(element, "ROBOT_DESCRIPTION_XACRO",
                            detail=f"${{{text}}}: {result.reason}")
            return _unknown(f"${{{text}}}: {result.reason}", tuple(reasons), result.kind)
        return result

    def load_yaml(self, path: object) -> object:
        """``xacro.load_yaml(file)``: a workspace YAML file, read with the safe loader
        (bounded); relative to the file being read, as xacro's ``abs_filename_spec``."""
        if not isinstance(path, str):
            return expression.Unknown("load_yaml of a file not known")
        if not os.path.isabs(path):
            here = self.files[-1] if self.files else self.description.path
            path = os.path.join(os.path.dirname(here), path)
        path = _source(self.workspace, path)
        if not self.workspace.readable(path, self.environment) or not os.path.isfile(path):
            return expression.Unknown(f"{self.workspace.relpath(path)} is not read")
        text, found = read_text(path, self.workspace.location(path, 1), MAX_FILE_BYTES)
        self.description.diagnostics.extend(found)
        try:
            value = safe_yaml.load(text, _YamlLoader) if text is not None else None
        except yaml.YAMLError as err:
            problem = getattr(err, "problem", None) or type(err).__name__
            return expression.Unknown(f"{self.workspace.relpath(path)} is not YAML: "
                                      f"{problem}", "error")
        return expression.Unknown(f"{self.workspace.relpath(path)} is empty") \
            if value is None else _key_attributes(value)

    def lookup(self, element: Element, name: str, scope: _Scope) -> Any:
        owner = scope.owner(name)
        assert owner is not None
        if name in owner.lazy:
            text = owner.lazy.pop(name)
            owner.values[name] = _unknown(f"property {name} refers to itself")
            value = self.evaluate(element, text, owner)
            owner.values[name] = _literal(value)
        return owner.values[name]

    def extension(self, element: Element, inner: Any, scope: _Scope) -> Any:
        """``$(command args)``, roslaunch's substitution arguments as xacro has them."""
        if isinstance(inner, Value):
            return _unknown(f"$({inner.text})", inner.origins)
        words = _str(inner).split()
        if not words:
            return ""
        command, rest = words[0], words[1:]
        if command == "arg" and len(rest) == 1:
            if rest[0] in self.args:
                return self.args[rest[0]]
            self.report(element, "ROBOT_DESCRIPTION_XACRO",
                        detail=f"$(arg {rest[0]}) is not set")
            return _unknown(f"arg {rest[0]} is not set")
        if command == "find" and len(rest) == 1:
            found = self.workspace.find(rest[0])
            if found is None:
                return _unknown(f"package {rest[0]} {self.workspace.absence(rest[0])}")
            return found
        if command == "env" and len(rest) == 1:
            if rest[0] in self.environment:
                return self.environment[rest[0]]
            return _unknown(f"environment variable {rest[0]} is not set")
        if command == "optenv" and rest:
            return self.environment.get(rest[0], " ".join(rest[1:]))
        if command == "dirname" and not rest:
            return os.path.dirname(self.files[-1] if self.files else self.description.path)
        if command == "eval":
            body = _str(inner)[len("eval"):].strip()
            return self.expression(element, body, scope, of_args=True)
        self.report(element, "ROBOT_DESCRIPTION_XACRO",
                    detail=f"$({_str(inner)}) is not supported")
        return _unknown(f"$({_str(inner)}) is not supported", kind="unsupported")

    def condition(self, element: Element, scope: _Scope) -> bool | _Undecided:
        text = element.get("value")
        if text is None:
            self.report(element, "ROBOT_DESCRIPTION_XACRO",
                        detail=f"xacro:{local_name(element)} without value")
            return _Undecided(UNKNOWN_MARK, ("a condition without value",))
        value = self.evaluate(element, text, scope)
        if isinstance(value, Value):
            return _Undecided(text, value.origins)
        truth = _boolean(value)
        if truth is None:
            self.report(element, "ROBOT_DESCRIPTION_XACRO",
                        detail=f"condition {text!r} is {value!r}, not a boolean")
            return _Undecided(text, (f"condition {text!r} is not a boolean",))
        return truth

    # -- macro calls -----------------------------------------------------------------------
    def call(self, element: Element, name: str, scope: _Scope,
             depth: int) -> list[Element]:
        macro = scope.macro(name)
        if macro is None:
            source = self._unread_source(name)
            if source is not None:  # no fault of the file: the macro may be defined there
                self.unknown(element, f"macro {name} is not defined here; it may be one of "
                                      f"{source}, which is not read")
                return []
            self.report(element, "ROBOT_DESCRIPTION_XACRO",
                        detail=f"unknown macro xacro:{name}")
            self.unknown(element, f"macro {name} is not defined")
            return []
        inner = _Scope(macro.home or scope)
        given = {str(k): str(v) for k, v in element.attrib.items()}
        params = [p for p, _ in macro.params]
        for key, value in given.items():
            if key.startswith("{"):
                continue
            if key not in params:
                self.report(element, "ROBOT_DESCRIPTION_XACRO",
                            detail=f"invalid parameter {key} of macro {name}")
                continue
            inner.values[key] = _literal(self.evaluate(element, value, scope))
        blocks: list[Element] = []
        for child in [c for c in element if isinstance(c.tag, str)]:
            holder = etree.Element("block")  # blocks are evaluated in the caller's scope
            holder.append(copy.deepcopy(child))
            self.children(holder, scope, depth + 1)
            blocks.extend(holder)
        for param, default in macro.params:
            if param.startswith("*"):
                if not blocks:
                    self.report(element, "ROBOT_DESCRIPTION_XACRO",
                                detail=f"not enough blocks for macro {name}")
                    continue
                inner.values[param] = blocks.pop(0)
                continue
            if param in inner.values:
                continue
            if default is None:
                self.report(element, "ROBOT_DESCRIPTION_XACRO",
                            detail=f"parameter {param} of macro {name} is not given")
                inner.values[param] = _unknown(f"{param} is not given")
                continue
            forward, text = default
            if forward is not None and scope.owner(forward) is not None:
                inner.values[param] = self.lookup(element, forward, scope)
            elif text is not None:
                inner.values[param] = _literal(self.evaluate(element, text, scope))
            else:
                inner.values[param] = _unknown(f"{param} is not given")
        if any(key == id(macro) and undecided < self.undecided
               for key, undecided in self.expanding):
            # a macro calling itself under a condition not decided since its outer call
            # (reseq_description's ``loop`` while ``${module < n_modules}``, n_modules
            # read from a YAML file not there): how deep it recurses is not known, so the
            # recursion is that, not a description nested past the reader's bound
            self.unknown(element, f"macro {name} calls itself under a condition not known "
                                  "statically: how deep it recurses is not known")
            return []
        body = copy.deepcopy(macro.body)
        self.files.append(macro.where[0])
        self.expanding.append((id(macro), self.undecided))
        try:
            made = self.content(body, inner, depth + 1)
        finally:
            self.expanding.pop()
            self.files.pop()
        return made


def _property(self: _Expander, element: Element, scope: _Scope, depth: int,
              ) -> list[Element]:
    name = element.get("name")
    if not name:
        self.report(element, "ROBOT_DESCRIPTION_XACRO", detail="xacro:property without name")
        return []
    name = self.text_of(element, name, scope)
    target = scope
    where = element.get("scope")
    if where == "global":
        target = scope.top()
    elif where == "parent" and scope.parent is not None:
        target = scope.parent
    if element.get("remove") in ("true", "1"):
        target.values.pop(name, None)
        target.lazy.pop(name, None)
        return []
    value, default = element.get("value"), element.get("default")
    if value is None and default is not None:
        if scope.owner(name) is not None:
            return []
        value = default
    if value is None:  # a block property
        target.values["**" + name] = element
        return []
    if target is scope and element.get("lazy_eval", "true") not in ("false", "0"):
        scope.values.pop(name, None)
        scope.lazy[name] = value
    else:
        target.lazy.pop(name, None)
        target.values[name] = _literal(self.evaluate(element, value, scope))
    return []


def _arg(self: _Expander, element: Element, scope: _Scope, depth: int) -> list[Element]:
    name = element.get("name")
    if not name:
        self.report(element, "ROBOT_DESCRIPTION_XACRO", detail="xacro:arg without name")
        return []
    if name not in self.args:
        default = element.get("default")
        if default is None:
            self.report(element, "ROBOT_DESCRIPTION_XACRO",
                        detail=f"xacro:arg {name} without default")
            return []
        value = self.evaluate(element, default, scope)
        self.args[name] = value if isinstance(value, Value) else _str(value)
    return []


def macro_params(text: str) -> list[tuple[str, tuple[str | None, str | None] | None]]:
    """A macro's ``params`` as xacro reads them: each name with (the name it forwards
    with ``^``, its default) or None when it has no default.

    xacro matches each parameter with a regular expression whose default is
    ``\\$\\{.*?\\}|\\$\\(.*?\\)|(?:'.*?'|".*?"|[^\\s'"]+)+|`` followed by a space or
    the end: a quoted part stretches over later quotes when that is what lets a space
    follow (``robot_ns:=\'\'\'`` is one default, three quotes), and its backtracking is
    exponential on an unterminated quote. Here each suffix's outcome is computed once,
    from the right, so the whole text is read in linear time with xacro's result."""
    size = len(text)

    def free(at: int) -> bool:  # a default may end here: a space or the end follows
        return at >= size or text[at].isspace()

    # after[p]: where a run of quoted and unquoted parts starting at p ends before a
    # space (xacro's choice: the nearest closing quote that lets the rest end so), or -1
    after = [-1] * (size + 1)
    after[size] = size
    nearest = {"'": -1, '"': -1}  # the first such quote at or after p + 1 with after[+1]
    closing = {"}": [-1] * (size + 1), ")": [-1] * (size + 1)}  # the first one after
    for at in range(size - 1, -1, -1):
        char = text[at]
        if char.isspace():
            after[at] = at
        elif char in nearest:
            after[at] = after[nearest[char] + 1] if nearest[char] >= 0 else -1
        else:
            after[at] = after[at + 1]
        if char in nearest and after[at + 1] >= 0:
            nearest[char] = at
        for mark, table in closing.items():
            table[at] = at if char == mark and free(at + 1) else table[at + 1]

    def default_end(at: int) -> int:
        """Where the default starting at ``at`` ends, or -1."""
        for opening, mark in (("${", "}"), ("$(", ")")):
            if text.startswith(opening, at) and closing[mark][at + 2] >= 0:
                return closing[mark][at + 2] + 1
        if at < size and not text[at].isspace() and after[at] >= 0:
            return after[at]
        return at if free(at) else -1

    params: list[tuple[str, tuple[str | None, str | None] | None]] = []
    at = 0
    while at < size and text[at].isspace():
        at += 1
    while at < size:
        head = _MACRO_HEAD.match(text, at)
        found = None
        if head is not None:
            start = head.end()
            spaced = start
            while spaced < size and text[spaced].isspace():
                spaced += 1
            # xacro's order: every space taken, then ``^|``, ``^`` or no forward; then
            # fewer spaces, where only an empty default fits
            for forward in ("^|", "^", ""):
                if text.startswith(forward, spaced):
                    end = default_end(spaced + len(forward))
                    if end >= 0:
                        found = (bool(forward), spaced + len(forward), end)
                        break
            if found is None and spaced > start:
                found = (False, spaced - 1, spaced - 1)
        if found is None:
            words = text[at:].split(None, 1)
            params.append((words[0], None))
            at = size - len(words[1]) if len(words) > 1 else size
            continue
        forwarded, begin, end = found
        name = head.group(1) if head is not None else ""
        params.append((name, (name if forwarded else None, text[begin:end] or None)))
        at = end
        while at < size and text[at].isspace():
            at += 1
    return params


def _macro(self: _Expander, element: Element, scope: _Scope, depth: int) -> list[Element]:
    name = element.get("name") or ""
    if name.startswith("xacro:"):
        name = name[len("xacro:"):]
    if not name or "." in name or name == "call":
        self.report(element, "ROBOT_DESCRIPTION_XACRO", detail=f"invalid macro name {name!r}")
        return []
    params: list[tuple[str, tuple[str | None, str | None] | None]] = []
    rest = element.get("params") or ""
    if len(rest) > MAX_PARAMS_TEXT:
        self.report(element, "ROBOT_DESCRIPTION_LIMIT",
                    detail=f"macro {name} has parameters longer than {MAX_PARAMS_TEXT} "
                           "characters")
        raise _Stop
    params.extend(macro_params(rest))
    path = self.files[-1] if self.files else self.description.path
    scope.macros[name] = _Macro(name, params, element, (path, line_of(element)),
                                scope if scope.namespace else None)
    return []


def _include(self: _Expander, element: Element, scope: _Scope, depth: int) -> list[Element]:
    spec = element.get("filename")
    if not spec:
        self.report(element, "ROBOT_DESCRIPTION_XACRO", detail="xacro:include without filename")
        return []
    namespace = self.text_of(element, element.get("ns") or "", scope)
    value = self.evaluate(element, spec, scope)
    if isinstance(value, Value):
        self.unknown(element, f"included file {value.text} is not known: "
                              + "; ".join(dict.fromkeys(value.origins)))
        self.unread.append((namespace, spec))
        return []
    path = _str(value)
    if not path:
        return []
    if not os.path.isabs(path):
        here = self.files[-1] if self.files else self.description.path
        path = os.path.join(os.path.dirname(here), path)
    optional = element.get("optional") in ("true", "1")
    if optional and not os.path.isfile(path):
        return []
    root = self.read(path, element)
    if root is None:
        self.unread.append((namespace, spec))
        return []
    if namespace:  # its macros and properties are its own, called as ns.name
        inner = _Scope(scope, namespace=True)
        scope.namespaces[namespace] = inner
        scope = inner
    self.process(root, scope, depth + 1)
    return list(root)


def _conditional(negate: bool) -> Callable[[_Expander, Element, _Scope, int], list[Element]]:
    def handle(self: _Expander, element: Element, scope: _Scope,
               depth: int) -> list[Element]:
        truth = self.condition(element, scope)
        if isinstance(truth, bool):
            return self.content(element, scope, depth) if truth != negate else []
        for reason in truth.reasons:
            self.unknown(element, reason)
        where = self.where(element)
        text = f"{'unless' if negate else 'if'} {truth.text} ({where.file}:{where.line})"
        self.undecided += 1
        try:
            made = self.content(element, scope, depth)
        finally:
            self.undecided -= 1
        for child in made:
            if isinstance(child.tag, str):
                before = child.get(CONDITION)
                child.set(CONDITION, f"{before}; {text}" if before else text)
        return made
    return handle


def _insert_block(self: _Expander, element: Element, scope: _Scope,
                  depth: int) -> list[Element]:
    name = element.get("name") or ""
    for key, whole in (("**" + name, False), ("*" + name, True)):
        if scope.owner(key) is not None:
            block = self.lookup(element, key, scope)
            if isinstance(block, etree._Element):
                made = copy.deepcopy(block)
                if whole:
                    self.attributes(made, scope)
                    self.children(made, scope, depth + 1)
                    return [made]
                return self.content(made, scope, depth + 1)
    self.report(element, "ROBOT_DESCRIPTION_XACRO", detail=f"undefined block {name}")
    return []


def _dynamic_call(self: _Expander, element: Element, scope: _Scope,
                  depth: int) -> list[Element]:
    name = self.evaluate(element, element.get("macro") or "", scope)
    if isinstance(name, Value) or not name:
        self.unknown(element, "xacro:call of a macro whose name is not known")
        return []
    del element.attrib["macro"]
    return self.call(element, _str(name), scope, depth)


def _named_element(self: _Expander, element: Element, scope: _Scope,
                   depth: int) -> list[Element]:
    name = ""
    for key, value in element.attrib.items():
        if str(key).endswith("}name"):
            name = self.text_of(element, str(value), scope)
    if not name or UNKNOWN_MARK in name or not re.fullmatch(r"[A-Za-z_][\w.\-:]*", name):
        self.unknown(element, "xacro:element whose name is not known")
        return []
    made = etree.Element(name)
    made.sourceline = element.sourceline
    for key, value in element.attrib.items():
        if not str(key).endswith("}name"):
            made.set(key, value)
    made.text = element.text
    for child in list(element):
        made.append(child)
    self.attributes(made, scope)
    self.children(made, scope, depth)
    return [made]


def _attribute(self: _Expander, element: Element, scope: _Scope,
               depth: int) -> list[Element]:
    name = self.text_of(element, element.get("name") or "", scope)
    value = self.text_of(element, element.get("value") or "", scope)
    parent = element.getparent()
    if parent is not None and re.fullmatch(r"[A-Za-z_][\w.\-]*", name):
        parent.set(name, value)
    else:
        self.report(element, "ROBOT_DESCRIPTION_XACRO", detail="invalid xacro:attribute")
    return []


_HANDLERS: dict[str, Callable[[_Expander, Element, _Scope, int], list[Element]]] = {
    "property": _property, "arg": _arg, "macro": _macro, "include": _include,
    "if": _conditional(False), "unless": _conditional(True),
    "insert_block": _insert_block, "call": _dynamic_call, "element": _named_element,
    "attribute": _attribute,
}


def _key_attributes(value: Any) -> Any:
    """What xacro's ``load_yaml`` gives: each mapping, nested ones too (in lists as
    well), reads its keys as attributes (``${inertial.origin.xyz}``)."""
    if isinstance(value, dict):
        return KeyAttributes((k, _key_attributes(v)) for k, v in value.items())
    if isinstance(value, list):
        return [_key_attributes(v) for v in value]
    return value


class _YamlLoader(yaml.SafeLoader):
    """The safe loader with xacro's angle tags: ``!degrees 90`` is radians,
    ``!radians pi/2`` an expression of the safe evaluator."""


def _angle(factor: float) -> Callable[[yaml.SafeLoader, yaml.Node], Any]:
    def construct(loader: yaml.SafeLoader, node: yaml.Node) -> Any:
        text = loader.construct_scalar(node)  # type: ignore[arg-type]
        value = expression.evaluate(str(text), None, expression.MATH)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return float(value) * factor
        raise yaml.constructor.ConstructorError(None, None, f"angle {text!r} is not a number",
                                                node.start_mark)
    return construct


_YamlLoader.add_constructor("!degrees", _angle(math.pi / 180.0))
_YamlLoader.add_constructor("!radians", _angle(1.0))


def _source(workspace: Workspace, path: str) -> str:
    """The file ``path`` names: itself, or, for a path in a ROS 2 package's share folder
    (``$(find pkg)/ros2_control/x.xacro`` installed from ``description/ros2_control``),
    the source file its install rules put there."""
    return path if os.path.isfile(path) else share_source(workspace, path)


def _literal(value: Any) -> Any:
    """xacro's ``_eval_literal``: property text that reads as a number or boolean."""
    if not isinstance(value, str):
        return value
    if len(value) >= 2 and value[0] == value[-1] == "'":
        return value[1:-1]
    if "_" in value:
        return value
    for convert in (int, float):
        try:
            return convert(value)
        except (ValueError, OverflowError):
            pass
    return {"true": True, "True": True, "false": False, "False": False}.get(value, value)


def _boolean(value: Any) -> bool | None:
    """xacro's ``get_boolean_value``."""
    if isinstance(value, str):
        if value in ("true", "True"):
            return True
        if value in ("false", "False"):
            return False
        try:
            return bool(int(value))
        except ValueError:
            try:
                number = float(value)
            except ValueError:
                return None
            return bool(number) if number in (0.0, 1.0) else None
    try:
        return bool(value)
    except Exception:  # a value of ours (never the workspace's code) with a bad __bool__
        return None


def _str(value: Any) -> str:
    if isinstance(value, Value):
        return value.text
    return str(value)
