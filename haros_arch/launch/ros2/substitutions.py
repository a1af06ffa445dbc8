"""ROS 2 substitutions: the ``$(...)`` syntax of XML/YAML and their static values.

``parse`` turns attribute text into ``Text`` (nested substitutions and quoted arguments
as the launch frontend grammar has them). ``Evaluator`` computes a ``Text`` in a scope:
what cannot be known (an unset argument, ``$(command)``, an environment variable not
in the configuration) becomes an ``Unknown`` part, with a diagnostic where it matters.
``$(eval)`` and ``PythonExpression`` go through our safe evaluator, never ``eval``.
"""

from __future__ import annotations

import functools
import math
import os
import re
from typing import TYPE_CHECKING

from ...files import read_text
from ...model.location import Location
from ...model.values import Unknown, Value
from ...share import install_prefix, lib_executables, share_source
from .. import expression
from ..model import package_not_found
from . import entities as e

if TYPE_CHECKING:
    from .runner import Runner, Scope

MAX_FILE_CONTENT = 64 * 1024
MAX_TEXT = 100_000
MAX_NESTING = 50  # $( inside $( ... deeper than any real file; deeper is refused
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_-]*")


# executables whose input the analysis reads itself, never running them (robot/attach.py)
_READ_HERE = frozenset({"xacro", "xacro.py"})

class SubstitutionSyntax(Exception):
    """Attribute text whose ``$(...)`` cannot be parsed."""


# -- parsing -----------------------------------------------------------------------
def parse(raw: str) -> e.Text:
    """``"$(var ns)/scan"`` -> ``(Var(("ns",)), "/scan")``."""
    parts, pos = _fragments(raw, 0, stop="", depth=0)
    if pos != len(raw):
        raise SubstitutionSyntax(f"unexpected ')' at column {pos + 1}")
    return parts


def _fragments(raw: str, pos: int, stop: str, depth: int) -> tuple[e.Text, int]:
    """Literal text and substitutions up to a character in ``stop`` (not consumed).

    A backslash escapes the character after it, as launch's grammar and its
    ``replace_escaped_characters`` have it: ``\\'`` is ``'``, ``\\$(`` is no
    substitution, ``\\)`` does not end an argument; in an argument a backslash before a
    space stays (the space ends the argument)."""
    out: list[str | e.Subst] = []
    buf: list[str] = []
    special = _special(stop)
    while pos < len(raw):
        found = special.search(raw, pos)  # literal text up to it, in one step
        end = len(raw) if found is None else found.start()
        if end > pos:
            buf.append(raw[pos:end])
            pos = end
            continue
        char = raw[pos]
        if char == "\\" and pos + 1 < len(raw) and not (stop and raw[pos + 1] in " \t\n"):
            buf.append(raw[pos + 1])
            pos += 2
            continue
        if raw.startswith("$(", pos):
            if buf:
                out.append("".join(buf))
                buf = []
            subst, pos = _substitution(raw, pos + 2, depth + 1)
            out.append(subst)
            continue
        if stop and char in stop:
            break
        if stop and char in "'\"":
            if buf:
                out.append("".join(buf))
                buf = []
            quoted, pos = _quoted(raw, pos + 1, char, depth)
            out.extend(quoted)
            continue
        buf.append(char)
        pos += 1
    if buf:
        out.append("".join(buf))
    return tuple(out), pos


@functools.cache  # a few stops: "", an argument's, each quote
def _special(stop: str) -> re.Pattern[str]:
    """The characters that end a run of literal text in ``_fragments`` (with ``stop``) or
    ``_quoted`` (``stop``: the quote): a backslash, ``$``, and in an argument its stops
    and the quotes (a parameter file of nav2's size is read for its substitutions once
    per node: a character at a time, that took most of a launch's time)."""
    chars = "\\$" + stop + ("'\"" if stop else "")
    return re.compile(f"[{re.escape(chars)}]")


def _quoted(raw: str, pos: int, quote: str, depth: int) -> tuple[e.Text, int]:
    """A quoted argument: backslash escapes, nested substitutions, up to ``quote``."""
    out: list[str | e.Subst] = []
    buf: list[str] = []
    special = _special(quote)
    while pos < len(raw):
        found = special.search(raw, pos)
        end = len(raw) if found is None else found.start()
        if end > pos:
            buf.append(raw[pos:end])
            pos = end
            continue
        char = raw[pos]
        if char == "\\" and pos + 1 < len(raw):
            buf.append(raw[pos + 1])
            pos += 2
            continue
        if raw.startswith("$(", pos):
            if buf:
                out.append("".join(buf))
                buf = []
            subst, pos = _substitution(raw, pos + 2, depth + 1)
            out.append(subst)
            continue
        if char == quote:
            if buf:
                out.append("".join(buf))
            return tuple(out), pos + 1
        buf.append(char)
        pos += 1
    raise SubstitutionSyntax(f"unclosed quote {quote}")


def _substitution(raw: str, pos: int, depth: int) -> tuple[e.Subst, int]:
    if depth > MAX_NESTING:
        raise SubstitutionSyntax(f"substitutions nested more than {MAX_NESTING} deep "
                                 f"at column {pos - 1}")
    match = _NAME.match(raw, pos)
    if match is None:
        raise SubstitutionSyntax(f"substitution without a name at column {pos + 1}")
    name = match.group(0)
    pos = match.end()
    args: list[e.Text] = []
    while True:
        while pos < len(raw) and raw[pos].isspace():
            pos += 1
        if pos >= len(raw):
            raise SubstitutionSyntax(f"$({name} ...) is not closed")
        if raw[pos] == ")":
            return make(name, args, raw), pos + 1
        arg, pos = _fragments(raw, pos, stop=" \t\n)", depth=depth)
        args.append(arg)


def make(name: str, args: list[e.Text], raw: str) -> e.Subst:
    """The substitution object for ``$(name args...)``."""
    def arity(low: int, high: int) -> None:
        if not low <= len(args) <= high:
            raise SubstitutionSyntax(f"$({name}) takes {low}..{high} arguments, "
                                     f"got {len(args)}")

    if name in ("var", "env", "optenv"):
        arity(1, 2)
        default = args[1] if len(args) > 1 else (("",) if name == "optenv" else None)
        cls = e.Var if name == "var" else e.Env
        return cls(args[0], default)
    if name == "for-var":
        arity(1, 2)
        return e.LoopVar(args[0], args[1] if len(args) > 1 else None)
    if name == "index":
        arity(1, 1)
        return e.LoopVar(args[0])
    if name in ("find-pkg-share", "find-pkg-prefix", "find"):
        arity(1, 1)
        return e.FindPackage(args[0], share=name != "find-pkg-prefix")
    if name == "find-exec":
        arity(1, 1)
        return e.FindExec(args[0])
    if name == "exec-in-pkg":
        arity(2, 2)
        return e.FindExec(args[0], args[1])
    if name == "param":
        arity(1, 2)
        return e.GlobalParam(args[0], args[1] if len(args) > 1 else None)
    if name in ("launch_log_dir", "log_dir"):
        arity(0, 0)
        return e.Opaque("the launch log folder is only known at run time", report=False)
    if name == "eval":
        arity(1, 64)
        if len(args) == 2:  # $(eval 'expression' 'module,...'): the modules it may use
            return e.Eval(args[0], modules=True)
        joined: list[str | e.Subst] = []
        for index, arg in enumerate(args):
            joined.extend(((" ",) if index else ()) + arg)
        return e.Eval(tuple(joined))
    if name == "anon":
        arity(1, 1)
        return e.Anon(args[0])
    if name in ("dirname", "filename"):
        arity(0, 0)
        return e.ThisFile(directory=name == "dirname")
    if name in ("not", "and", "or", "equals", "not-equals", "if", "any", "all"):
        arity(*{"not": (1, 1), "and": (2, 2), "or": (2, 2), "equals": (2, 2),
                "not-equals": (2, 2), "if": (2, 3), "any": (0, 64), "all": (0, 64)}[name])
        return e.Logic(name.replace("-", ""), tuple(args), frontend=True)
    if name == "command":
        origin = f"$(command) is never run; its output is unknown: {raw}"
        return e.Command(args[0], origin) if args else e.Opaque(origin)
    if name == "file-content":
        arity(1, 1)
        return e.FileContent(args[0])
    raise SubstitutionSyntax(f"unknown substitution $({name})")


# -- evaluation ----------------------------------------------------------------------
def unseen_declaration(name: str, unseen: tuple[tuple[Location, str], ...],
                       here: Location) -> str:
    """Why launch configuration ``name``, not seen declared, is not known to be unset:
    the places of the actions not seen before it (``line N`` in the file of ``here``,
    else ``file:line``), the first two, with what each was."""
    def place(where: Location) -> str:
        return (f"line {where.line}" if where.file == here.file
                else f"{where.file}:{where.line}")

    shown = "; ".join(f"{place(where)}, {what}" for where, what in unseen[:2])
    more = f"; and {len(unseen) - 2} more" if len(unseen) > 2 else ""
    return (f"launch argument {name} is not seen declared (undecided: what was not read "
            f"may declare it: {shown}{more})")


class Evaluator:
    def __init__(self, runner: Runner, scope: Scope, location: Location) -> None:
        self.runner = runner
        self.scope = scope
        self.location = location

    def report(self, code: str, **params: object) -> None:
        self.runner.report(code, self.location, **params)

    def value(self, t: e.Text) -> Value:
        parts: list[str | Value] = []
        for part in t:
            parts.append(part if isinstance(part, str) else self.one(part))
        # one substitution's value as it is: a rewritten file's path keeps its file
        result = parts[0] if len(parts) == 1 and isinstance(parts[0], Value) else (
            Value.of(*parts))
        if len(result.text) > MAX_TEXT:
            self.report("LAUNCH_PY_BUDGET", detail=f"a value longer than {MAX_TEXT}")
            return Value.unknown("too long")
        return result

    def known(self, t: e.Text) -> str | None:
        return self.value(t).literal

    def one(self, subst: e.Subst) -> Value:
        handler = getattr(self, "s_" + type(subst).__name__, None)
        if handler is None:
            return Value.unknown(type(subst).__name__)
        result = handler(subst)
        assert isinstance(result, Value)
        return result

    def s_Var(self, s: e.Var) -> Value:
        name = self.known(s.name)
        if name is None:
            self.runner.hidden("a launch configuration whose name is not known statically",
                               self.location)
            return Value.unknown("launch configuration with an unknown name")
        self.runner.config_read(name)
        if name not in self.scope.configs and not self.scope.unseen:
            self.runner.read_unset.add(name)
        if name in self.scope.configs:
            found = self.scope.configs[name]
            if found is None:
                self.report("LAUNCH_ARG_UNSET", name=name)
                return Value.unknown(f"var {name}")
            return found
        if s.tested:
            # launch's test of a configuration nothing set is unequal, silently
            # (interbotix_xslocobot_nav tested slam_toolbox_mode, declared slam_mode);
            # one an action not seen may set is not known (below)
            if not self.scope.unseen:
                self.report("LAUNCH_CONDITION_UNSET", name=name)
                return self.value(s.default or ("",))
        elif s.default is not None:
            return self.value(s.default)
        if self.scope.unseen:
            # declared, maybe, by what the reader could not see: undecided, not unset
            self.report("LAUNCH_UNKNOWN_VALUE", detail=unseen_declaration(
                name, self.scope.unseen, self.location))
            return Value.unknown(f"var {name}")
        self.report("LAUNCH_ARG_UNSET", name=name)
        return Value.unknown(f"var {name}")

    def s_LoopVar(self, s: e.LoopVar) -> Value:
        """A value of the iteration being performed (launch's locals: the innermost
        iteration's over those around it); its default when no iteration has it; else
        launch raises (SubstitutionFailure)."""
        name = self.known(s.name)
        if name is None:
            return Value.unknown("ForEach value with an unknown name")
        for values in reversed(self.runner.loop_values):
            if values is None:
                return Value.unknown(f"for-var {name}")  # an iteration not known
            if name in values:
                return Value.of(values[name])
        if s.default is not None:
            return self.value(s.default)
        self.report("LAUNCH_BAD_VALUE", detail=f"for-var / index {name} is not a value of "
                    "a ForEach or ForLoop iteration here: launch raises "
                    "SubstitutionFailure")
        return Value.unknown(f"for-var {name}")

    def s_Env(self, s: e.Env) -> Value:
        name = self.known(s.name)
        if name is None:
            return Value.unknown("environment variable with an unknown name")
        if name in self.scope.environment:
            return Value.of(self.scope.environment[name])
        if name in self.runner.environment_unsure and (
                name + "\0unset" not in self.scope.environment):
            return Value.unknown(f"env {name}")  # written by a launch file under a test
        if name in self.runner.environment and name + "\0unset" not in self.scope.environment:
            return Value.of(self.runner.environment[name])
        if s.default is not None:
            return self.value(s.default)
        return Value.unknown(f"env {name}")

    def s_FindPackage(self, s: e.FindPackage) -> Value:
        name = self.known(s.package)
        # used by the file that wrote it, when another file's action performs it
        written = s.written if s.written is not None and s.written.file and (
            s.written.file != self.location.file) else self.location
        self.runner.uses(self.value(s.package).text, written,
                         self.scope.conditions, self.runner.chosen_by(s.package), s.tried)
        if name is None:
            return Value.unknown("package with an unknown name")
        found = self.runner.workspace.find(name)
        if found is None and self.runner.workspace.surely_absent(name):
            # a letter or two from a package here (most likely a typo), or no package's
            # name at all: the launch fails
            if not s.said:
                self.report("PACKAGE_NOT_FOUND", name=name,
                            why=self.runner.workspace.absence(name))
            return package_not_found(name)
        if found is None:  # installed on the robot, perhaps: unknown here, as in ROS 1
            self.report("LAUNCH_UNKNOWN_VALUE", detail=(
                f"package {name} {self.runner.workspace.absence(name)}"))
            return package_not_found(name)
        if s.share:
            return Value.of(found)
        prefix = install_prefix(self.runner.workspace, name)
        if prefix is None:
            self.report("LAUNCH_UNKNOWN_VALUE", detail=f"package {name} has no install "
                        "prefix (found outside an ament prefix)")
            return Value.unknown(f"install prefix of {name}")
        return Value.of(prefix)

    def s_FindExec(self, s: e.FindExec) -> Value:
        name = self.known(s.name)
        if name is None:
            return Value.unknown("executable with an unknown name")
        if s.package is not None:
            return self.in_package(name, s.package)
        if "/" in name:
            return Value.of(name)  # which() takes a path as it is
        if name in _READ_HERE:
            # a tool whose input this analysis reads itself (a robot description's
            # xacro): the command names it, wherever it is installed
            return Value.of(name)
        path = self.env_value("PATH")
        for folder in (path or "").split(os.pathsep):
            candidate = os.path.join(folder, name)
            if folder and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
                return Value.of(candidate)
        if name == "ros2":
            # ros2cli's command: ``ros2 launch`` is one of its verbs, so it is on the
            # PATH of any launch (ouster-ros' ``$(find-exec ros2) lifecycle set ...``)
            return Value.of(name)
        self.report("LAUNCH_UNKNOWN_VALUE", detail=f"executable {name} is not found on "
                    "the PATH of the configuration")
        return Value.unknown(f"find-exec {name}")

    def in_package(self, executable: str, package_text: e.Text) -> Value:
        """``$(exec-in-pkg)``: ``<prefix>/lib/<pkg>/<exe>`` when the package installs it."""
        package = self.known(package_text)
        self.runner.uses(self.value(package_text).text, self.location,
                         self.scope.conditions, self.runner.chosen_by(package_text))
        if package is None:
            return Value.unknown("package with an unknown name")
        workspace = self.runner.workspace
        prefix = install_prefix(workspace, package)
        if prefix is None:
            if workspace.find(package) is None:
                self.report("LAUNCH_UNKNOWN_VALUE", detail=f"package {package} is not in "
                            "the workspace nor installed here")
            else:
                self.report("LAUNCH_UNKNOWN_VALUE", detail=f"package {package} has no "
                            "install prefix (found outside an ament prefix)")
            return Value.unknown(f"exec-in-pkg {executable} {package}")
        path = os.path.join(prefix, "lib", package, executable)
        own = workspace.packages.get(package)
        if own is not None and executable in lib_executables(own, workspace):
            return Value.of(path)
        if own is None and os.path.isfile(path):
            return Value.of(path)
        self.report("LAUNCH_UNKNOWN_VALUE", detail=f"package {package} installs no "
                    f"executable {executable} in lib/{package}")
        return Value.unknown(f"exec-in-pkg {executable} {package}")

    def env_value(self, name: str) -> str | None:
        """An environment variable as the launch sees it here (set_env / unset_env)."""
        if name in self.scope.environment:
            return self.scope.environment[name]
        if name in self.runner.environment_unsure:
            return None
        if name in self.runner.environment and name + "\0unset" not in self.scope.environment:
            return self.runner.environment[name]
        return None

    def s_GlobalParam(self, s: e.GlobalParam) -> Value:
        """``$(param name)``: the value a ``SetParameter`` in scope gave ``name``."""
        name = self.known(s.name)
        if name is None:
            return Value.unknown("parameter with an unknown name")
        for key, value, _ in self.scope.params:
            if key == name:
                return _param_text(value, self)
        if s.default is not None:
            return self.value(s.default)
        self.report("LAUNCH_UNKNOWN_VALUE", detail=f"$(param {name}): no SetParameter "
                    "in scope sets it")
        return Value.unknown(f"param {name}")

    def s_Eval(self, s: e.Eval) -> Value:
        source = self.value(s.expression)
        if source.literal is None:
            return Value.unknown("expression with unknown parts")
        result = expression.evaluate(source.literal, None, {**expression.BUILTINS,
                                                            **expression.MATH})
        if isinstance(result, expression.Unknown):
            if result.kind == "syntax":
                # known whole and no expression: launch's eval raises SyntaxError when
                # it performs it (odas_ros' ROS 1 `$(eval arg('rviz') or ...)` in XML)
                self.report("LAUNCH_BAD_VALUE", detail=(
                    f"$(eval) / PythonExpression of {source.literal!r}: SyntaxError "
                    f"({result.reason}); the launch fails here"))
            elif (result.kind == "undefined" and not s.modules
                  and not expression.eval_knows(expression.undefined_name(result))):
                # launch's eval has Python's builtins and math's names, nothing else
                # (a launch configuration is $(var x), not x): NameError when performed
                self.report("LAUNCH_BAD_VALUE", detail=(
                    f"$(eval) / PythonExpression of {source.literal!r}: NameError "
                    f"({result.reason}: launch evaluates it with Python's builtins and "
                    "math's names only); the launch fails here"))
            elif result.kind != "unknown":
                self.report("LAUNCH_UNSUPPORTED",
                            detail=f"expression {source.literal!r}: {result.reason}")
            return Value.unknown(result.reason)
        return Value.of(str(result))

    def s_Anon(self, s: e.Anon) -> Value:
        name = self.value(s.name).text
        return Value.of(name + "_", self.runner.anon.setdefault(name, Unknown("anon")))

    def s_ThisFile(self, s: e.ThisFile) -> Value:
        path = self.scope.file
        return Value.of(os.path.dirname(path) if s.directory else path)

    def truth_of(self, value: Value, what: str, typed: bool = False) -> bool | None:
        """A condition's truth (``true``/``1``/``false``/``0``, any case, as
        ``IfCondition``); ``typed``: a boolean as ``$(not)``/``$(and)``/``$(or)``/``$(if)``
        read it (also YAML's ``yes``/``no``/``on``/``off``)."""
        literal = value.literal
        if literal is None:
            return None
        lowered = literal.strip().lower()
        if lowered in ("true", "1") or (typed and lowered in _YAML_TRUE):
            return True
        if lowered in ("false", "0") or (typed and lowered in _YAML_FALSE):
            return False
        self.report("LAUNCH_BAD_VALUE", detail=f"{what} \"{literal}\" is not a boolean")
        return None

    def s_Logic(self, s: e.Logic) -> Value:
        if s.op in ("equals", "notequals"):
            left, right = (self.value(op) for op in s.operands)
            if left.literal is None or right.literal is None:
                return Value.unknown("equals with unknown operands")
            same = equal(left.literal, right.literal)
            return Value.of(str(same != (s.op == "notequals")).lower())
        if s.op == "asbool":  # nav2_common's LaunchConfigAsBool: never an error
            literal = self.value(s.operands[0]).literal
            if literal is None:
                return Value.unknown("LaunchConfigAsBool of an unknown value")
            truth = literal.strip().lower() in ("true", "1", "yes", "on")
            return Value.of(str(truth))
        if s.op == "if":
            test = self.truth_of(self.value(s.operands[0]), "$(if)", typed=True)
            if test is None:
                return Value.unknown("$(if) with an unknown condition")
            if test:
                return self.value(s.operands[1])
            return self.value(s.operands[2]) if len(s.operands) > 2 else Value()
        if s.frontend and s.op in ("any", "all"):
            self.report("LAUNCH_BAD_VALUE", detail=f"$({s.op} ...) cannot be built by "
                        "launch's XML/YAML front end (jazzy to rolling: its parse passes "
                        "'args=' to a constructor taking *args); the real launch fails "
                        "here. Evaluated as meant")
        truths = [self.truth_of(self.value(op), f"$({s.op})", typed=True)
                  for op in s.operands]
        result: bool | None
        if s.op == "not":
            result = None if truths[0] is None else not truths[0]
        elif s.op in ("and", "all"):
            result = False if False in truths else (None if None in truths else True)
        else:  # or, any
            result = True if True in truths else (None if None in truths else False)
        return Value.unknown(f"$({s.op})") if result is None else Value.of(str(result).lower())

    def s_NodeParamsIn(self, s: e.NodeParamsIn) -> Value:
        """nav2_common's ``HasNodeParams``: does the YAML file have a top-level key for
        the node (as written, no wildcards)."""
        document = self.runner.param_file(e.ParamFile(s.path), self.scope, self.location)
        if document is None:
            return Value.unknown("HasNodeParams of a file not read")
        return Value.of(str(isinstance(document, dict) and s.node in document))

    def s_PathJoin(self, s: e.PathJoin) -> Value:
        """The parts joined as ``os.path.join`` joins them (launch's
        ``PathJoinSubstitution.perform``): an absolute part starts the path again, a
        separator goes between two parts unless the path so far is empty or ends with
        one (clearpath's ``PathJoinSubstitution(['/', namespace, 'platform',
        'joint_states'])`` with no namespace is ``/platform/joint_states``, was
        ``///platform/joint_states``); after a part not known, one goes in. A ``pathlib``
        path's empty part adds nothing."""
        joined = Value()
        dropped = None  # the absolute part that started the path again
        for piece in s.parts:
            value = self.value(piece)
            if value.literal == "" and s.python == e.PATHLIB:
                continue  # a pathlib path drops an empty part: no trailing separator
            if value.literal is not None and value.literal.startswith("/"):
                if joined.parts:
                    dropped = value.literal
                joined = value
                continue
            last = joined.parts[-1] if joined.parts else ""
            joined = Value.of(joined, value) if isinstance(last, str) and (
                not last or last.endswith("/")) else Value.of(joined, "/", value)
        if dropped is not None:
            self.report("LAUNCH_PATH_JOIN_ABSOLUTE", part=dropped, path=joined.text)
        return joined

    def s_FileContent(self, s: e.FileContent) -> Value:
        path = self.value(s.path).literal
        if path is None:
            return Value.unknown("file-content of an unknown path")
        full = os.path.realpath(share_source(self.runner.workspace, path))
        if not self.runner.workspace.readable(full):
            self.report("LAUNCH_UNSUPPORTED", detail=f"$(file-content) of {path} outside "
                        "the workspace and installed packages is not read")
            return Value.unknown("file outside the workspace")
        content, found = read_text(full, self.runner.workspace.location(full),
                                   MAX_FILE_CONTENT)
        self.runner.model.diagnostics.extend(found)
        return Value.unknown("unreadable file") if content is None else Value.of(content)

    def s_FileRef(self, s: e.FileRef) -> Value:
        # the path, which the file's rewrites go with where it is read as parameters
        # (``Runner.param_file``): a launch argument's value passes both on
        return Value(self.value(s.file.path).parts, file=s.file)

    def s_Command(self, s: e.Command) -> Value:
        """Never run (nothing of the workspace is executed): an unknown value, said as a
        ROS 1 ``command=`` is (``LAUNCH_UNKNOWN_VALUE``), with the command line that the
        robot descriptions read the xacro file of (``command_outputs``)."""
        line = self.value(s.command).text
        # its words as paths relative to the workspace, as every message says them
        shown = " ".join(self.runner.workspace.relpath(w) if os.path.isabs(w) else w
                         for w in line.split(" "))
        shown = shown if len(shown) <= 160 else shown[:157] + "..."
        self.report("LAUNCH_UNKNOWN_VALUE", detail=f'command "{shown}" is not run')
        output = Value.unknown(s.origin if s.origin != e.COMMAND_NOT_RUN else
                               f"Command is never run; its output is unknown: {shown}")
        self.runner.command_outputs.append((output.parts[0], line))  # type: ignore[arg-type]
        return output

    def s_Literal(self, s: e.Literal) -> Value:
        return self.value(s.text)

    def s_Performed(self, s: e.Performed) -> Value:
        for read in s.reads:  # what its perform() performs; said where it is not set
            self.value(read)
        return Value.unknown(s.origin)

    def s_Opaque(self, s: e.Opaque) -> Value:
        if s.report:
            self.report("LAUNCH_BAD_VALUE" if s.refused else "LAUNCH_UNSUPPORTED",
                        detail=s.origin)
        return Value.unknown(s.origin)

    # -- conditions ------------------------------------------------------------------
    def truth(self, cond: e.Cond) -> bool | None:
        value = self.value(cond.expression)
        if cond.equals is not None:
            expected = self.value(cond.equals)
            if value.literal is None or expected.literal is None:
                return None
            result: bool | None = value.literal == expected.literal
        else:
            result = self.truth_of(value, "condition")
        if result is None:
            return None
        return (not result) if cond.negate else result


def _param_text(value: object, ev: Evaluator) -> Value:
    """A ``SetParameter`` value as ``$(param)`` gives it: ``str()`` of the typed value."""
    from .nodes import convert

    typed = convert(value, ev)
    return Value.unknown("parameter value not known statically") if typed is None else (
        Value.of(str(typed)))


_YAML_TRUE = frozenset(("yes", "on"))
_YAML_FALSE = frozenset(("no", "off"))


def equal(left: str, right: str) -> bool:
    """``EqualsSubstitution``: booleans by truth (``1`` equals ``True``), numbers by value
    (``math.isclose``), anything else as text."""
    bools = ("true", "false", "1", "0")
    if left.lower() in bools and right.lower() in bools:
        return (left.lower() in ("true", "1")) == (right.lower() in ("true", "1"))
    try:
        return math.isclose(float(left), float(right))
    except ValueError:
        return left == right
