"""Finding ROS calls (roscpp, rclcpp and the libraries on them) in a parsed translation unit.

Every function defined in the workspace's own files that holds a call the walk acts on
(``CallFinder._gives``) is walked with the stack of control statements around each
expression (``conditions.ConditionReader``); a call whose target is a row of
``api.ALL`` becomes a ``PrimitiveCall``. A call's location is the line and
column of the called function's name (``advertise`` in ``n.advertise<M>(...)``), or of
the constructed object for a constructor.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import os
import re
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING, Any

from clang.cindex import Cursor, CursorKind, StorageClass, TranslationUnit, Type, TypeKind, conf

from ... import diagnostics as diag
from ...ctext import code_only
from ...diagnostics import Diagnostic
from ...model.conditions import (
    EACH_STATEMENT,
    ELEMENT_PARAMETER,
    RUN_ONCE_STATEMENTS,
    Condition,
)
from ...model.location import Location
from ...model.source import (
    JOINED,
    LOADED,
    PROCESS_HANDLE,
    ROS_ARGUMENT,
    SDF_ELEMENT,
    PrimitiveCall,
    counted_mark,
    loaded_mark,
)
from ...model.source import WORDS as EACH_WORD
from ...model.values import UNKNOWN_MARK
from ...plugins.classes import base_name, loader_bases
from ...plugins.hosts import TRANSPORT_PARAM
from . import api, call_conditions, links, msg_types, parameter_library, reconfigure, synthesis
from .call_sites import (
    CallSites,
    base_keys,
    callee_of,
    constructor_values,
    delegation,
    dependent_new,
    parameter_places,
    value_text,
)
from .call_types import CallTypes, factory_made, row_class
from .call_types import callee as callee_of_call
from .conditions import ConditionReader
from .cursors import children_in, from_standin, overloads, release, root
from .expressions import (
    binary_operator,
    constructed_arguments,
    constructed_name,
    first_operand,
)
from .handles import (
    Namespaces,
    binds_handle,
    callback,
    callback_name,
    holds_handle,
    in_main,
    is_handle,
    is_ros2_node,
    join_name,
    looked_up,
    normalise,
    own_functions_only,
    points_to_handle,
    qualified_name,
    record_class,
)
from .headers import REPLACED
from .links import (
    DEFAULT_MARK,
    MEMBER_MARK,
    PARAMETER,
    Fact,
    argument_facts,
    constructed_by,
    parameter_mark,
)
from .members import MemberWrites, member_of
from .node_options import NODE_OPTIONS, local_arguments
from .owners import (
    _is_node,
    binds_own_member,
    class_bases,
    constructed_bases,
    constructed_class,
    construction_dropped,
    constructors_here,
    handle_node,
    node_arguments,
    node_construction,
    opaque_constructor,
    options_arguments,
    owner_of,
    registered_alias,
    registered_class,
    static_class,
    unseen_construction,
)
from .qos import qos as qos_of
from .reach import CLASSES, FUNCTIONS, reachable
from .ros2_interfaces import snake_case
from .tested import Key, TestedCalls, unit_tested
from .tested import key as key_of
from .values import (
    _INTEGRAL,
    ARGUMENTS_LEFT,
    PLACEHOLDER,
    SEPARATOR,
    NodeName,
    NodeNamespace,
    ProgramArgument,
    ProgramOption,
    Scope,
    SearchedName,
    _textual,
    argument_of,
    initializer,
    literal,
    method_object,
    option_of,
    own_name,
    own_name_run,
    permissive_conversion,
    permissive_held,
    program_argument,
    program_arguments,
    render,
    strip,
    topic_base,
    unwritten_global,
    written_arguments,
)
from .values import _walk as walk_cursors
from .values import key_of as place_of
from .wrappers import FACTORY_NAMES, Wrappers, called_name, is_constructor, of_class_template
from .writes import (
    const_array,
    default_constructed,
    may_write,
    out_argument,
    searched_key,
    writes_of,
)

if TYPE_CHECKING:
    from ...launch.ros2.naming import RosArgs

WORDS = re.compile(rb"[A-Za-z_]\w*")  # the identifiers (and keywords) of a text
_QUALIFIED = re.compile(rb"[A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*")  # and as written, qualified
CONTAINERS = frozenset({
    CursorKind.NAMESPACE, CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
    CursorKind.CLASS_TEMPLATE, CursorKind.LINKAGE_SPEC, CursorKind.UNEXPOSED_DECL,
    CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION,
})
# the maker of what the initialisers of the unit's variables of namespace scope name
# (``CallFinder.uses``): it runs where the program runs (``extract.cpp._reached``)
STATIC = "<static initialisation>"
_API_NAMES = frozenset(
    [name for _, name in [*api.ALL, *api.NODE_NAME, *api.RCLCPP_NODE_NAME,
                          *api.STANDIN_NODE_NAME, *api.FACTORIES]]
    + [parameter_library.LISTENER])
MAX_DEPTH = 16
# how many variables or members holding a name ``_held_source`` follows, one in another
_MAX_HELD = 3
# a class template's parameters, in order (the index of a construction's type argument)
_TEMPLATE_PARAMETERS = (CursorKind.TEMPLATE_TYPE_PARAMETER,
                        CursorKind.TEMPLATE_NON_TYPE_PARAMETER,
                        CursorKind.TEMPLATE_TEMPLATE_PARAMETER)
_MAX_CONSTANT_ELEMENTS = 64  # a constant list longer than this is read as unknown
# a nodelet's lookup name as a launch file gives it (``pkg/Name``, a C++ type)
_LOOKUP_NAME = re.compile(r"[A-Za-z_][\w/:]*")
# the text after a call whose result the code looks one key up in (``_looked_up``)
_LOOKUP = re.compile(rb"\s*(?:(?:\.|->)\s*(?:find|count|contains|at|end)\s*\(|\[)")
# where a call's name comes from: a ``Source`` (the parameter, its default, the
# parameter the default holds), then ``EACH`` when the name is each element of that list
# parameter in turn (PrimitiveCall.name_each) and the (line, column) of the range-based
# for that walks it, then the parameters whose values fill the name's further ``?``, one
# each in order ([parameter, its default]: ``PrimitiveCall.name_more``)
# ``PrimitiveCall.stores`` of a read into a member the unit also writes otherwise
OTHER_WRITES = "!"
NameSource = tuple[str | None, str | None, str | None, str | None, tuple[int, int] | None,
                   list[list[str | None]] | None]
EACH = "."


# the words of a type that hold an object of a class rather than name it
# (``_held_classes``)
_TYPE_WORDS = re.compile(r"[A-Za-z_][\w:]*")
_OBJECTS = (CursorKind.FIELD_DECL, CursorKind.VAR_DECL, CursorKind.PARM_DECL)
_HOLDERS = frozenset({"std::shared_ptr", "std::unique_ptr", "boost::shared_ptr", "const",
                      "volatile", "std::weak_ptr", "Ptr", "SharedPtr", "UniquePtr",
                      "pluginlib::UniquePtr", "std::function", "void"})


# a call in C code: a name and its parenthesis, but a statement's keyword's
_C_CALL = re.compile(rb"\b(?!(?:if|for|while|switch|return|sizeof)\b)[A-Za-z_]\w*\s*\(")


def _c_without_calls(function: Cursor, main: str, source: Any) -> bool:
    """Whether ``function`` is a function of a C source ``main`` (a ``.c`` file, written
    in C: no class, template or constructor) whose text calls nothing: it makes no ROS
    call and no call site, and the fields it writes are of C structs, which hold no
    handle. mav_control_rw's CVXGEN solver (ldl.c) has a 27,000-line ``ldl_factor`` of
    assignments and ifs alone, whose walks (conditions, members, wrappers) took 30 s of
    CPU and 1.8 GB for nothing."""
    start, end = function.extent.start, function.extent.end
    if start.file is None or end.file is None or start.file.name != main or (
            end.file.name != main):
        return False
    data = source.get(main)
    if data is None:
        return False
    body = data[start.offset:end.offset]
    opening = body.find(b"{")
    return opening >= 0 and _C_CALL.search(body, opening) is None


def _held_classes(ctype: Type) -> list[str]:
    """The class words of type ``ctype`` as written, its holders left out
    (``std::shared_ptr<karto::ScanSolver>``, ``pluginlib::UniquePtr<T>``, ``T *``), and
    none for a value declared permissively."""
    return [w for w in _TYPE_WORDS.findall(ctype.spelling)
            if w not in _HOLDERS and w != synthesis.ANY]


def _aliased_holder(ctype: Type, held: list[str]) -> bool:
    """Whether ``ctype`` is written as a plain alias (``typedef std::shared_ptr<T>
    ClassSharedPtr``, ``Ptr``) whose words name no class it holds (``held``: none, or the
    alias's own name), not a template written with its arguments."""
    if "<" in ctype.spelling or len(held) > 1:
        return False
    decl = ctype.get_declaration()
    return decl is not None and decl.kind in (
        CursorKind.TYPEDEF_DECL, CursorKind.TYPE_ALIAS_DECL) and (
        not held or held[0].rsplit("::", 1)[-1] == decl.spelling)


class ChoiceName(str):
    """One of the values a call's name may hold (``Scope.written_choices``,
    ``Scope.branch_written``): the call with it is made under ``conditions`` (the sides
    of the ``if`` statements, the case of the ``switch``, that decide it), and it is a
    key ``searchParam`` found when ``searched``."""

    conditions: tuple[Condition, ...]
    searched: bool

    def __new__(cls, name: str, conditions: tuple[Condition, ...], searched: bool
                ) -> ChoiceName:
        made = super().__new__(cls, name)
        made.conditions, made.searched = conditions, searched
        return made


class ArgumentName(str):
    """A call's name whose one ``?`` is the process's ``program_arg``-th command-line
    argument (``values.ProgramArgument``): ``PrimitiveCall.name_arg``."""

    program_arg: int

    def __new__(cls, name: str, program_arg: int) -> ArgumentName:
        made = super().__new__(cls, name)
        made.program_arg = program_arg
        return made


class OptionName(str):
    """A call's name whose one ``?`` is a getopt option's argument
    (``values.ProgramOption``): ``PrimitiveCall.name_option`` and ``name_getopt``."""

    option: ProgramOption

    def __new__(cls, name: str, option: ProgramOption) -> OptionName:
        made = super().__new__(cls, name)
        made.option = option
        return made


class BelowName(str):
    """A call's name whose one ``?`` begins it and is the topic of a publisher or
    subscription the code made (``values.TopicOf``), as resolved and remapped:
    ``PrimitiveCall.name_below``, that topic's name as written."""

    base: str

    def __new__(cls, name: str, base: str) -> BelowName:
        made = super().__new__(cls, name)
        made.base = base
        return made


class EachName(str):
    """A call's name for one element of a constant list the code walks in a loop (its
    ``at``): the call is made once per element, so that loop is no condition of it."""

    at: tuple[int, int]

    def __new__(cls, name: str, at: tuple[int, int]) -> EachName:
        made = super().__new__(cls, name)
        made.at = at
        return made


class SelfName(str):
    """A call's name whose one ``?`` is the node's own name without its namespace
    (``values.NodeBaseName``): ``PrimitiveCall.name_self``."""


# the calls of a prefix and a map: declare_parameters declares the map's keys under the
# prefix; the others read what the node has under it
_PREFIXED = ("declare_parameters", "get_parameters", "get_parameters_by_prefix")


class PrefixName(str):
    """The prefix of a ROS 2 read of every parameter under it (rclcpp's
    ``get_parameters(prefix, map)``): ``PrimitiveCall.under``."""


# builtin types a variable of static storage starts as zero of (C++'s zero-initialisation)
_ZEROED: dict[TypeKind, object] = {
    TypeKind.BOOL: False, TypeKind.INT: 0, TypeKind.UINT: 0, TypeKind.LONG: 0,
    TypeKind.ULONG: 0, TypeKind.LONGLONG: 0, TypeKind.ULONGLONG: 0, TypeKind.SHORT: 0,
    TypeKind.USHORT: 0, TypeKind.FLOAT: 0.0, TypeKind.DOUBLE: 0.0,
}
# the classes the API rows model: their construction is a call we read
_API_CLASSES = frozenset(owner for owner, _ in [*api.ALL, *api.OPTIONS]) | api.HANDLE_CLASSES


def _implements_row(function: Cursor) -> bool:
    """Whether ``function`` defines a function or constructor of a row of ``api.ALL``
    of a library whose headers our stand-ins give in place of its own (``REPLACED``:
    image_transport's ``create_camera_publisher`` in its own image_transport.cpp): a call
    of it anywhere is that row's call, not its body's. Not a row describing our stand-in
    only (``standin_only``), nor one of a library whose own headers a workspace package
    of it wins with (ros2_control's ``auto_declare``, topic_tools' ``ShapeShifter``: a
    wrapper of the node's calls as written there)."""
    if function.kind not in FUNCTIONS or function.semantic_parent is None:
        return False
    owner = qualified_name(function.semantic_parent)
    row = api.ALL.get((owner, function.spelling))
    return row is not None and not row.standin_only and owner.split("::")[0] in REPLACED
# what can build an object (``_unseen_class``)
_MAKES = frozenset({CursorKind.CALL_EXPR, CursorKind.VAR_DECL, CursorKind.CXX_NEW_EXPR})

MAX_WRAPPED = 4  # wrappers of wrappers whose returned value is followed (_gives_value)
MAX_SITE_DEPTH = 3  # constructors of constructors whose sites' conditions are followed
_ALIASES = frozenset({CursorKind.TYPEDEF_DECL, CursorKind.TYPE_ALIAS_DECL,
                      CursorKind.TYPE_ALIAS_TEMPLATE_DECL})
_PREPROCESSED = frozenset({CursorKind.MACRO_INSTANTIATION, CursorKind.INCLUSION_DIRECTIVE})
_PARAM_KINDS = ("read", "declare")
CAMERA_INFO = "sensor_msgs/CameraInfo"  # an image_transport camera's sibling topic
# rclcpp::Parameter's typed accessors and the parameter type each asks for
_TAKEN_AS = {"as_int": "int", "as_double": "double", "as_string": "str", "as_bool": "bool",
             "as_integer_array": "int[]", "as_double_array": "double[]",
             "as_string_array": "str[]", "as_bool_array": "bool[]",
             "as_byte_array": msg_types.BYTE_ARRAY}
_VALUE_METHODS = frozenset({"c_str", "str", "as_string", "as_int", "as_double", "as_bool",
                            "get_value", "value_to_string", "get_parameter_value",
                            # SDFormat's ``GetElement("key")->GetValue()->GetAsString()``
                            # (api.SDF)
                            "GetValue", "GetAsString"})




_TEMPLATE_CLASSES = frozenset({CursorKind.CLASS_TEMPLATE,
                               CursorKind.CLASS_TEMPLATE_PARTIAL_SPECIALIZATION})


def _chosen_method(call: Cursor, owned: Callable[[str], bool]) -> tuple[str, str] | None:
    """The method name and the written type of the object of ``call``, a member call
    clang leaves unresolved in a template because the object's class is a class
    template of the workspace specialised on the template's parameters
    (``adapter_.init(...)``, ``adapter_`` a ``HwAdapter`` = ``Adapter<I, S>``): which
    class, primary or partial specialisation, and so which method, each instantiation
    chooses; None for any other call."""
    children = list(call.get_children())
    if not children or children[0].kind != CursorKind.MEMBER_REF_EXPR or (
            children[0].referenced is not None):
        return None
    member = children[0]
    objects = [c for c in member.get_children() if c.kind.is_expression()]
    if not objects:
        return None
    kind = objects[0].type.get_canonical()
    if kind.kind in (TypeKind.POINTER, TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        kind = kind.get_pointee()
    cls = kind.get_declaration()
    where = cls.location.file if cls is not None else None
    if cls is None or cls.kind not in _TEMPLATE_CLASSES or where is None or (
            not owned(where.name)):
        return None
    end = objects[0].extent.end.offset
    tokens = [t.spelling for t in member.get_tokens() if t.extent.start.offset >= end]
    while tokens and tokens[0] in (".", "->", "template"):
        tokens.pop(0)
    if not tokens or not (tokens[0][0].isalpha() or tokens[0][0] == "_"):
        return None
    return tokens[0], objects[0].type.spelling


def _written(argument: Cursor, call: Cursor) -> str:
    """An argument of ``call`` as written (its tokens, at most 60 characters). One that a
    macro's body writes (sbus_bridge's ``GET_PARAM(name)``, whose expansion gives
    ``pnh_``) has no text of its own inside the call's: its extent is the whole
    invocation, whose tokens libclang takes from the macro's definition to the place it
    is invoked; then its own name (``pnh_``)."""
    start, end, whole = argument.extent.start, argument.extent.end, call.extent
    if (start.file is not None and whole.start.file is not None
            and start.file.name == whole.start.file.name
            and whole.start.offset < start.offset <= end.offset <= whole.end.offset):
        return "".join(t.spelling for t in argument.get_tokens())[:60]
    named = argument.referenced if argument.referenced is not None else argument
    return named.spelling or argument.spelling or "?"


def _declared_constructors(cls: Cursor) -> list[str]:
    """The USRs of the constructors ``cls`` declares (none when one has no USR, or it
    declares none: its implicit ones have no code anywhere to read)."""
    found = [child.canonical.get_usr() for child in (cls.get_definition() or cls).get_children()
             if child.kind == CursorKind.CONSTRUCTOR]
    return found if all(found) else []


def _value_method(call: Cursor, children: list[Cursor]) -> bool:
    """Whether ``call`` is a method that gives its object's value: ``_VALUE_METHODS``,
    or rclcpp's ``ParameterValue::get<T>()`` (``declare_parameter(name,
    PARAMETER_STRING).get<std::string>()``; ``get`` of any other class, a smart
    pointer's, is not)."""
    if not children or children[0].kind != CursorKind.MEMBER_REF_EXPR:
        return False
    if call.spelling in _VALUE_METHODS:
        return True
    if call.spelling != "get":
        return False
    objects = [c for c in children[0].get_children() if c.kind.is_expression()]
    return bool(objects) and objects[0].type.get_canonical().spelling.removeprefix(
        "const ").split("<")[0] == "rclcpp::ParameterValue"


# the parameter a value is read from: its name, its default when known (one ``?`` where
# the default holds another parameter's value) and that other parameter's name
Source = tuple[str, str | None, str | None]



def header_folder(name: str, headers: Sequence[str]) -> str | None:
    """The first folder of one of the missing ``headers`` (as included) in whose path,
    below that folder, the first part of the namespace of the class ``name`` is a folder
    or the file's stem: ``moveit`` for ``robot_model_loader::RobotModelLoader`` and
    ``<moveit/robot_model_loader/robot_model_loader.h>`` (MoveIt's headers share one
    folder over several packages, each class in a namespace named as its folder)."""
    first = name.lstrip(":").split("::", 1)[0]
    for header in headers:
        parts = header.split("/")
        if len(parts) >= 2 and first in {*parts[1:-1], os.path.splitext(parts[-1])[0]}:
            return parts[0]
    return None


def named_header_folder(name: str, headers: Sequence[str]) -> str | None:
    """The first folder of the missing header (as included) that names the class
    ``name`` when its namespace's first part names none (``header_folder``): the file's
    stem is the class's name in snake case or ends in it (grvc-ual's
    ``grvc::ual::BackendMavros`` of ``<ual_backend_mavros/ual_backend_mavros.h>``,
    ``grvc::ual::UAL`` of ``<uav_abstraction_layer/ual.h>``), else a later part of the
    namespace is a folder below the first or the stem. The folder names the package
    itself, not the beginning of several packages' names, as ``header_folder``'s may."""
    names = name.lstrip(":").split("::")
    if len(names) < 2:
        return None
    split = [(parts, os.path.splitext(parts[-1])[0])
             for parts in (header.split("/") for header in headers) if len(parts) >= 2]
    own = snake_case(names[-1])
    for parts, stem in split:
        if stem == own or stem.endswith("_" + own):
            return parts[0]
    for part in names[1:-1]:
        for parts, stem in split:
            if part in {*parts[1:-1], stem}:
                return parts[0]
    return None


class CallFinder:
    """Collects the primitive calls and the node name of one translation unit."""

    def __init__(self, tu: TranslationUnit, source: dict[str, bytes],
                 owned: Callable[[str], bool], where: Callable[[Cursor], Location],
                 ros2: bool = False, declared: str | None = None,
                 clients: Callable[..., str | None] | None = None,
                 local: Callable[[str], bool] | None = None,
                 ros_class: Callable[[str], bool] | None = None,
                 missing_headers: Sequence[str] = ()) -> None:
        self.tu = tu
        # ROS 1: the headers the unit includes that are empty stand-ins, as included
        # (``_header_package``)
        self.missing_headers = missing_headers
        # whether a class the parse knows only as a name declared permissively
        # (qualified) may be a ROS package's, whose code may make ROS calls
        # (``extract.cpp.ros_classes``); None: any may
        self.ros_class = ros_class
        # whether a file is of the unit's own package (``reachable``; None: every file)
        self.local = local or (lambda _name: True)
        # ROS 1: whether a class of a package (both by name) may make ROS calls in code
        # of its own, not handed the node (``_unseen_class``); None in ROS 2
        self.clients = clients
        self._classes_said: set[str] = set()
        # the header of the names declared permissively (``synthesis``): a call of one
        # given the node hands it to code nobody reads (``_to_unknown``)
        self.declared = declared
        self._unknown: set[tuple[str, int]] = set()  # the calls said so
        self.source = source
        self.owned = functools.lru_cache(maxsize=None)(owned)  # asked for every cursor
        self.where = where
        self.reader = ConditionReader(source, where)
        self.macros: dict[str, str] = {}
        self.ros2 = ros2
        self.types = CallTypes(ros2)
        self.namespaces = Namespaces(self.macros, source)
        # fixed-name calls already found
        self._fixed: set[tuple[str, str, str | None, bool, str | None]] = set()
        # ROS 2 parameter -> its declared default, and the parameter it holds (``Source``)
        self._declared: dict[str, tuple[str, str | None]] = {}
        # the place of a read whose value a typed accessor takes (rclcpp's
        # ``get_parameter("x").as_int()``): the type it asks for
        self._taken_as: dict[tuple[str, int], str] = {}
        # the keys each declare_parameters(prefix, map) of the unit declared under its
        # prefix (None: a map whose keys are not known), for get_parameters(prefix, out)
        self._prefix_keys: dict[str, list[str] | None] = {}
        self.calls: list[PrimitiveCall] = []
        self._held_depth = 0  # variables holding a name followed now (``_held_source``)
        self.functions: list[Cursor] = []
        # the definitions of its headers the unit's code does not reach (``reachable``)
        self.unreached: list[Cursor] = []
        # the variables outside functions whose initialisers may use a function
        # (``std::map<std::string, Handler> handlers = {{"a", &readA}}``): read for
        # ``call_conditions.site_facts``' uses only
        self.globals: list[Cursor] = []
        # the class and macro definitions of the workspace's files by name (``reachable``)
        self._texts: dict[bytes, list[Cursor]] = {}
        # (file, line) of the calls of an API function's name that the parse resolved,
        # ROS or not (``set_parameters`` of a parameter client): read, so not hidden
        self.resolved: set[tuple[str, int]] = set()
        # (file, line, function) of the calls the parse could not resolve and the walk
        # keeps by their name (``CPP_CALL_UNRESOLVED``): clang's error about such a call
        # itself hides no other (``recall``)
        self.kept_unresolved: set[tuple[str, int, str]] = set()
        self.sites: CallSites | None = None
        self._scope: Scope | None = None  # of the function being walked
        self.rosname: str | None = None
        # node names made in constructors no call in this unit makes (``_node_name``)
        self.rosname_unbuilt: list[str] = []
        # every rclcpp node the file constructs: (owner, name), in the order met; the
        # owner (``owner_of``) is the class whose constructor names it (``: Node("x")``)
        # or the free function that makes it (``make_shared<rclcpp::Node>("x")`` in main)
        self.node_names: list[tuple[str, str]] = []
        # (name, rule) for each ``__ns`` / ``__node`` rule a node of ``node_names`` is
        # built with in its own arguments (``node_options``): the launch's do not replace
        # what it sets
        self.local_rules: list[tuple[str, str]] = []
        self._root: Any = None  # the unit's cursor as a node (``run``), until ``release``
        self._owner: str | None = None  # of the function being walked
        # the placeholder that starts a parameter of the constructor being walked, whose
        # calls named after it are made only where the class is constructed (``_emit``)
        self._constructor: tuple[str, str] | None = None
        # whether the function being walked is a free function (no member can hold a
        # constructor's parameter there: only its own parameters, ``_made_in``)
        self._free = False
        # the USR of the header function template whose dependent construction is
        # being emitted (``_made_in``)
        self._made_by: str | None = None
        self._template: str | None = None  # of the function being walked (``_function``)
        self._template_name = ""  # that function's name
        # reads that return whether the parameter is there, where they are
        self._status_reads: list[tuple[Key, PrimitiveCall]] = []
        # of every function walked: those reads, and the variables outliving a function
        # that reads wrote and that a function tests for being empty (``unit_tested``)
        self._unit_status_reads: list[tuple[Key, PrimitiveCall]] = []
        self._lasting_passed: dict[Key, list[Key]] = {}
        self._lasting_tested: set[Key] = set()
        # (owner, class of the workspace it constructs): the class's calls are made on
        # its constructor's node when it names none itself (a device object given the
        # node's handle)
        self.constructions: list[tuple[str, str]] = []
        # (owner, owner of a function of the workspace its code calls or refers to: a
        # free function ``ns::f()``, a method's class): what ``main()`` runs, with the
        # constructions (``extract.cpp._reached``)
        self.uses: list[tuple[str, str]] = []
        # (owner of the node, class of the workspace) for each call of a method of the
        # class that hands it a node (``_node_handed``)
        self.node_handed: list[tuple[str, str]] = []
        self.defines: list[str] = []  # the owners of the unit's definitions
        # the classes the unit registers for a container, nodelet manager or host to
        # construct (``owners.registered_class``): (class, class) for each, then
        # (class, base) for its bases of the workspace, transitively
        self.registered: list[tuple[str, str]] = []
        # the owners whose code creates a plugin class it names (``CppResult.loads_in``)
        self.loads_in: set[str] = set()
        # the owners whose code hands the node to code the parse does not read
        # (CPP_NODE_PASSED, CPP_NODE_TO_UNKNOWN); "" where no owner is known
        self.handed: set[str] = set()
        # (owner, class) of those that build a class of another package with the node
        # (CPP_NODE_PASSED): a library the executable links may hold its code
        self.passed: set[tuple[str, str]] = set()
        # (owner, name) of the functions and classes the parse does not know that the
        # owner hands the node to (CPP_NODE_TO_UNKNOWN): the name may be the workspace's
        # own code that the parse lost, which runs where the owner does
        self.handed_to: set[tuple[str, str]] = set()
        # each construction of a class of the workspace and its source conditions
        self.made_under: list[tuple[str, tuple[Condition, ...]]] = []
        self.diagnostics: list[Diagnostic] = []
        # the words of the declarations of the classes the unit constructs without the
        # code of their constructor: what those build is not seen (``links.resolve``)
        self.unseen: set[bytes] = set()
        # each of those words -> the classes whose declaration holds it: a name there is
        # looked up from that class (``_reached`` counts it where the class is built)
        self.unseen_in: dict[bytes, set[str]] = {}
        # the same words of a construction whose constructor is known, by its USR: unseen
        # unless a unit of the node defines that constructor (``links.OPAQUE``)
        self.opaque_words: dict[str, set[bytes]] = {}
        self.facts: list[Fact] = []  # what this file passes to other files' functions
        self.wrappers = Wrappers(self)  # the file's functions that wrap the ROS API
        self.members: MemberWrites | None = None
        # a local's place -> the parameter it holds the value of, if any (_held_parameters)
        self._held: dict[tuple[str, int], str | None] = {}
        # the list and field each local or parameter of a condition holds an element of
        self._held_each: dict[tuple[str, int], tuple[str, str] | None] = {}
        # a call's place -> the parameter whose value it returns, if any (_held_call)
        self._held_calls: dict[tuple[str, int], str | None] = {}
        # a wrapper call's place -> whether it returns the parameter's value (_gives_value)
        self._value_calls: dict[tuple[str, int], bool] = {}
        # a wrapper call's place -> whether it may return no value (_gives_status)
        self._status_calls: dict[tuple[str, int], bool] = {}
        # parameter reads and the member variable each stores its value in
        self._stored: list[tuple[PrimitiveCall, Cursor, Key | None]] = []
        # the names of the ROS 1 reads that fill each local ``XmlRpcValue`` (by place):
        # the parameter its members are of (``_struct_path``)
        self._struct_reads: dict[tuple[str, int], list[str]] = {}
        # (file, offset) of the macro expansions and #includes of the workspace's files:
        # a function's text that holds one does not show all its code
        self.opaque: list[tuple[str, int]] = []
        # the functions whose bodies hold calls the unit makes, by USR
        # (``call_conditions.site_facts``' ``holding``)
        self._holding: dict[str, Cursor] = {}

    def run(self) -> None:
        self._root = self.namespaces.unit_root = root(self.tu)
        self.namespaces.owned = self.owned
        # (what the unit's own code cannot reach by name is left to the units that do)
        every = list(self._definitions(self._root, top=True))
        self.functions = reachable(every, self.tu.spelling, self.source, self.globals,
                                   self._texts, self.local)
        if self.tu.spelling.endswith(".c"):
            self.functions = [f for f in self.functions
                              if not _c_without_calls(f, self.tu.spelling, self.source)]
        # a function of the API the rows model, defined in the workspace: the package's
        # own implementation of that API (image_transport's create_camera_publisher,
        # topic_tools' ShapeShifter::advertise, when that package is modelled); each call
        # of it is the row's call at its site, so its body is no code of the node's
        self.functions = [f for f in self.functions if not _implements_row(f)]
        kept = {id(f) for f in self.functions}
        self.unreached = [f for f in every if id(f) not in kept]
        # an object of namespace scope built with arguments (OpenMower's
        # ``StateSubscriber<Status> status_state_subscriber{"/ll/mower_status"};``) calls
        # its constructor as a function's local does: a site of what it passes
        self.sites = self.namespaces.sites = CallSites(
            [*self.functions, *filter(_constructed_global, self.globals)], self.macros,
            self.source, external=True, main=self.tu.spelling)
        self.sites.handle_namespace = self.namespaces.value_namespace
        self.members = self.namespaces.members = MemberWrites(self.functions, self.source,
                                                              self.opaque)
        self.wrappers.build()
        self.wrappers.read_inside(self._conditions_of)
        walked: set[int] = set()
        for function in self.functions:
            if self._gives(function):
                walked.add(id(function))
                self._function(function)
        self._lasting_tests([f for f in self.functions if id(f) not in walked])
        handled = unit_tested(self._lasting_passed, self._lasting_tested)
        for site, read in self._unit_status_reads:
            read.tested = read.tested or site in handled
        # the member's writes are all these reads, of one parameter (nav2's
        # TwistSubscriber: each of its two constructors reads enable_stamped_cmd_vel
        # into is_stamped_ with the same default), grouped by call site: one site may
        # make two calls (nav2's declare_or_get_parameter: a declaration and a read)
        stored: dict[tuple[str, int], dict[object, list[PrimitiveCall]]] = {}
        members: dict[tuple[str, int], Cursor] = {}
        calls: dict[tuple[str, int], set[Key]] = {}
        for read, member, made_at in self._stored:
            members[place_of(member)] = member
            stored.setdefault(place_of(member), {}).setdefault(
                read.location, []).append(read)
            if made_at is not None:
                calls.setdefault(place_of(member), set()).add(made_at)
        for key, sites in stored.items():
            member = members[key]
            made = [[(r.kind, r.name, r.handle_namespace, r.has_default, r.default,
                      r.conditions) for r in reads] for reads in sites.values()]
            usr = member.get_usr() or None
            also = self._constants(member, len(sites), calls.get(key, set())) if all(
                m == made[0] for m in made) else None
            for reads in sites.values():
                for read in reads:
                    # what another file of the node names with the member is the
                    # parameter's value when these reads are its only writes here
                    # (``extract.cpp._members_named``); OTHER_WRITES: not only they
                    read.stores = usr if also == [] or usr is None else OTHER_WRITES + usr
                    if also is not None:
                        read.variable = member.spelling
                        read.also = also or None
        self.registered = self._registered()
        self.facts = argument_facts(self.sites, self.namespaces, self.owned, self._marked,
                                    self._site_conditions, self._struct_text,
                                    self.types.message,
                                    {cls for cls, base in self.registered if cls == base})
        self.facts.extend(call_conditions.site_facts(
            self.functions, self.sites, self.reader, self.owned, self._enter, self._walked,
            self.globals, self.declared, self._holding.values(), self.source.get))
        self.facts.extend(links.opaque_facts(self.functions, self.tu.spelling,
                                             self.opaque_words))
        self.facts.extend(links.member_facts(self.functions, self.tu.spelling,
                                             self._member_value))
        if self.sites is not None and self.sites.external:
            self.facts.extend(links.assigned_facts(self.functions, self.tu.spelling,
                                                   self.sites, self.namespaces))
        if any(is_handle(variable) for variable in self.globals):
            # (a unit with no global handle has none to give: its functions are not
            # walked for global writes)
            self.facts.extend(links.global_facts(
                ((usr, links.origin_marked(render(parts), origin))
                 for usr, parts, origin in self.namespaces.global_handles(self.tu)),
                self.tu.spelling))
        self.uses.extend(self._uses())
        # the owners the unit's code defines, not a workspace header's: a header's
        # function is every including unit's, and runs in none of them by being reached
        # in another (a stand-in's macro, gtest's TEST, defines the unit's own)
        # (and the class of each static method it defines: C++ calls one by its bare name
        # only in its class, so code elsewhere that writes the name alone calls no such
        # method, ``_reached``'s ``_named``: scenario_simulator_v2's
        # ``LaneletLoader::load`` is not called by a word ``load`` beside an error)
        main = self.tu.spelling
        self.defines = list(dict.fromkeys(
            owner for f in self.functions
            if (where := f.location.file) is None or where.name == main
            or not self.owned(where.name)
            for owner in (owner_of(f), *static_class(f))))
        self.wrappers.preorder.clear()
        self.wrappers.references.clear()
        for call in self.calls:  # get_parameter("p") of a declare_parameter("p", default)
            if call.name_param is not None and call.name_default is None and (
                call.name_param in self._declared
            ):
                call.name_default, call.default_param = self._declared[call.name_param]
            if call.name_more:  # and each further parameter of the name the same way
                call.name_more = [[p, d if d is not None or p not in self._declared
                                   else self._declared[p][0], *joined]
                                  for p, d, *joined in call.name_more]

    def _uses(self) -> list[tuple[str, str]]:
        """(owner, owner of the workspace function it calls or names) for each function
        of the unit: a call ``f(x)``, ``Cls::make()``, ``obj.method()``, or a function
        handed on (``&f``, a callback), read from the references ``Wrappers.build`` keeps
        of each function's subtree (its lambdas' too); an overloaded name as every
        declaration it may be."""
        found: dict[tuple[str, str], None] = dict.fromkeys(self.uses)
        # what a variable of namespace scope names in its initialiser runs before main()
        # (gtest's TEST_F registers its test class so)
        for variable in self.globals:
            for node in variable.walk_preorder():
                if node.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
                    found.update(dict.fromkeys(self._used(STATIC, node)))
        for function in self.functions:
            references = self.wrappers.references.get(id(function))
            if not references:
                continue
            owner = owner_of(function)
            for reference in references:
                found.update(dict.fromkeys(self._used(owner, reference)))
        return [use for use in found if use not in self.uses]

    def _registered(self) -> list[tuple[str, str]]:
        """``registered``: what the unit's registration macros register."""
        found: dict[tuple[str, str], None] = {}
        for variable in self.globals:
            cls = registered_class(variable, self.owned)
            name = qualified_name(cls) if cls is not None else ""
            if cls is not None and name:
                found[(name, name)] = None
                alias = registered_alias(variable)
                if alias is not None and alias != name:
                    # the alias a plugin description names, its class reached from it
                    found[(alias, alias)] = found[(alias, name)] = None
                found.update(dict.fromkeys(class_bases(cls, self.owned)))
        return list(found)

    def _used(self, owner: str, reference: Cursor) -> Iterator[tuple[str, str]]:
        """(owner, owner of each workspace function ``reference`` may name), and of the
        classes it gives that function as template arguments (a ``run<NodeT>()`` that
        makes a NodeT)."""
        targets = overloads(reference) if (
            reference.kind == CursorKind.OVERLOADED_DECL_REF) else [reference.referenced]
        for target in targets:
            if target is None or target.kind not in FUNCTIONS:
                continue
            # the template arguments written after the name, not the class before it
            # (``Planner::footprint(nh)`` runs a static method: it builds no Planner)
            at = reference.location.offset
            given = [child.referenced for child in reference.get_children()
                     if child.kind == CursorKind.TYPE_REF and child.location.offset > at]
            for used in (target, *given):
                where = used.location.file if used is not None else None
                if where is None or not self.owned(where.name):
                    continue
                name = owner_of(used) if used.kind in FUNCTIONS else qualified_name(used)
                if name and name != owner:
                    yield owner, name

    def _member_value(self, field: Cursor) -> str | None:
        """The namespace of a handle member, or the text of a string member, as the
        unit's constructors of its class give it (``links.member_facts``; a string's
        with a constructor's parameters as placeholders, ``CallSites.member_elsewhere``);
        None for any other member, and for a string no constructor gives a known value
        or another function writes."""
        if holds_handle(field) or binds_handle(field) or points_to_handle(field):
            found, origin = self.namespaces.member_origin(field)
            return links.origin_marked(render(found), origin)
        if msg_types.param_type(field.type) != "str" or self.sites is None:
            return None
        return self.sites.constructed_text(field)

    def unit_cursor(self) -> Any:
        """The unit's cursor as a node (``run``), until ``release``."""
        return self._root

    def release(self) -> None:
        """Free the unit's nodes (``cursors.release``) once everything is read from
        them: no cursor of the unit may be used after this."""
        if self._root is not None:
            release(self._root)
            self._root = None
        self.functions = []
        self.globals = []
        self._holding = {}

    def _walked(self, function: Cursor) -> tuple[list[Cursor], list[Cursor]] | None:
        """The function's calls (among other nodes) and references to declarations,
        each in preorder, as the wrappers' walk kept them (None: not kept)."""
        nodes = self.wrappers.preorder.get(id(function))
        references = self.wrappers.references.get(id(function))
        return None if nodes is None or references is None else (nodes, references)

    def _enter(self, function: Cursor, scope: Scope | None = None) -> None:
        """Ready the condition reader for ``function``'s body (``_conditions_at``): the
        locals its tests read that hold a parameter's value or a constant, read in
        ``scope`` (the function's own, from the call sites, by default)."""
        if scope is None and self.sites is not None:
            scope = self.sites.scope(function)
        if scope is None:
            self.reader.enter(function, ARGUMENTS_LEFT, None, None)
            return
        self.reader.enter(function, ARGUMENTS_LEFT,
                          functools.partial(self._held_parameters, scope=scope),
                          functools.partial(self._held_constants, scope=scope),
                          functools.partial(self._held_elements, scope=scope),
                          # (the unit's scope of the function lives as long as the unit)
                          key=id(scope) if self.sites is not None
                          and scope is self.sites.scope(function) else None)

    def _constants(self, member: Cursor, sites: int, reads: set[Key]) -> list[object] | None:
        """The member's writes in the file besides the reads (``sites`` of them, made at
        ``reads``), when each assigns a literal: their values (none: ``[]``); None when
        another write does something else (``++``, a computed value, an out argument)."""
        assert self.members is not None
        extra = self.members.writes(member) - sites
        if extra == 0:
            return []
        values = [value for value, _ in self.members.assignments(member)
                  if key_of(strip(value)) not in reads]
        if extra < 0 or len(values) != extra:
            return None
        scope = Scope(None, self.macros, self.source, self.sites)
        found: list[object] = []
        for value in values:
            if strip(value).kind not in _LITERALS:
                return None
            literal = _literal(value, scope)
            if literal is None:
                return None
            if literal not in found:
                found.append(literal)
        return found

    def _definitions(self, parent: Cursor, top: bool = False) -> Iterator[Cursor]:
        for cursor in children_in(parent, self.owned):  # in the workspace's files
            where = cursor.location.file
            kind = cursor.kind
            if kind in _PREPROCESSED:
                self.opaque.append((where.name, cursor.location.offset))
            elif kind == CursorKind.MACRO_DEFINITION:
                self._texts.setdefault(cursor.spelling.encode(), []).append(cursor)
                tokens = [t.spelling for t in cursor.get_tokens()]
                if len(tokens) == 2:
                    self.macros[tokens[0]] = tokens[1]
            elif kind in FUNCTIONS and cursor.is_definition():
                yield cursor
            elif kind == CursorKind.FIELD_DECL:
                self._field(cursor)
                self.types.specialised(cursor.type, parent)
                if initializer(cursor) is not None:
                    yield cursor  # a default member initialiser: walked like a function
            elif kind in (CursorKind.CXX_BASE_SPECIFIER, CursorKind.VAR_DECL):
                # a class template's specialisations: a base, a global (a plugin's
                # export, ``PLUGINLIB_EXPORT_CLASS(DriveOnHeading<>, Behavior)``)
                self.types.specialised(cursor.type, parent)
                if kind == CursorKind.VAR_DECL:
                    self.globals.append(cursor)
            elif kind in _ALIASES:  # (``reachable``: what naming the alias names)
                if parent.kind not in CLASSES:  # (a member's is its class's text)
                    self._texts.setdefault(cursor.spelling.encode(), []).append(cursor)
            elif kind in CONTAINERS:
                if kind in CLASSES and cursor.is_definition():
                    self._texts.setdefault(cursor.spelling.split("<")[0].encode(),
                                           []).append(cursor)
                if cursor.spelling in ("TypeAdapter", "ImplicitTypeAdapter"):
                    self.types.adapter(cursor)
                yield from self._definitions(cursor)

    def _lasting_tests(self, others: list[Cursor]) -> None:
        """The tests for being empty in ``others`` (functions the walk left out: a
        callback that makes no ROS call) of the variables outliving their function that
        a status read wrote and that no walked function tested (``unit_tested``)."""
        sites = {site for site, _ in self._unit_status_reads}
        pending = {held for held, made in self._lasting_passed.items()
                   if held not in self._lasting_tested and not sites.isdisjoint(made)}
        if not pending:
            return
        for function in others:
            references = self.wrappers.references.get(id(function))
            if not references or not any(
                r.referenced is not None and key_of(r.referenced) in pending
                for r in references
            ):
                continue
            tested = TestedCalls(self.reader)
            for node in function.walk_preorder():  # (``preorder`` keeps calls alone)
                tested.visit(node)
            self._lasting_tested.update(tested.lasting_tested)

    def _gives(self, function: Cursor) -> bool:
        """Whether the walk of ``function`` (``_function``) can find anything: a call of
        an API function's or a wrapper's name, a call kept as a recovery expression of
        an unresolved row's name, a construction of a class of the workspace. Read over
        the function's nodes without the conditions (``_function`` walks no others);
        a function without one adds nothing, and its walk is left out."""
        names, rows = self.wrappers.names, self._unresolved_rows()
        nodes = self.wrappers.preorder.get(id(function))
        if self.clients is not None and function.kind == CursorKind.CONSTRUCTOR:
            self._unseen_members(function)
        dependent = False  # a call that depends on a template parameter, of no wrapper
        if not self.ros2 and any(c.kind == CursorKind.PARM_DECL and is_struct_value(c.type)
                                 for c in function.get_children()):
            return True  # it may read the parameter a struct it is given holds
        for node in function.walk_preorder() if nodes is None else nodes:
            kind = node.kind
            if kind in _MAKES:
                self._unseen_class(node)  # in every function, walked or not
                self._dependent_made(node)
            if kind == CursorKind.CALL_EXPR:
                self._to_unknown(node, function)  # in every function, walked or not
                spelling = node.spelling
                if spelling == "operator()":
                    self._vendor_member_call(node)  # (so too in the walk, after a return)
                if spelling == "operator[]" and not self.ros2 and _struct_subscript(node):
                    return True  # a struct parameter's member read by key
                if spelling == "bind" and _bound_api(node) is not None:
                    return True
                if spelling in _API_NAMES or (spelling and spelling in names) or (
                    not spelling and _recovered_name(node) in rows
                ) or constructed_class(node, self.owned) is not None:
                    return True
                if not spelling and names:
                    # ``_call`` takes it as a wrapper's call: one the unit's wrappers
                    # match (``Wrappers.emit``) or one clang resolved gives something
                    if node.referenced is not None or self.wrappers.calls_wrapper(node):
                        return True
                    self._library_method(node)  # in every function, walked or not
                    dependent = True
            elif kind == CursorKind.UNEXPOSED_EXPR and not node.spelling and (
                _recovered_name(node) in rows
            ):
                return True
            if kind == CursorKind.CALL_EXPR and not node.spelling and (
                _dependent_made(node) is not None or _dependent_listener(node) is not None
            ):
                return True
            if kind == CursorKind.CXX_NEW_EXPR and (
                    _lost_new(node) is not None or self._parameter_made(node) is not None):
                return True
        # a walk of a function whose only such call is another template's gives what the
        # rest of ``_function``'s loop gives: a member initialiser clang lost, a
        # construction of a class whose code the unit does not have
        return dependent and (
            (function.kind == CursorKind.CONSTRUCTOR and bool(_lost_initialisers(function)))
            or any(node.kind == CursorKind.CALL_EXPR
                   and opaque_constructor(node, self.owned) is not None
                   for node in (function.walk_preorder() if nodes is None else nodes)))

    def _built_class(self, function: Cursor) -> str | None:
        """``links.CLASS_BUILT`` and the class's USR for a method (not static) of a class
        (not a class template) that declares constructors, none of which this unit
        calls: the method runs on objects built in the node's other files, its calls
        under what every such construction shares (navigation2's collision monitor
        builds its ``VelocityPolygon`` only ``if (polygon_type == "velocity_polygon")``,
        whose ``getParameters`` reads ``velocity_polygons``); else None."""
        if function.kind != CursorKind.CXX_METHOD or function.is_static_method() or (
                self.sites is None):
            return None
        owner = function.semantic_parent
        definition = owner.get_definition() if owner is not None and owner.kind in (
            CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL) else None
        if definition is None:
            return None
        constructors = [c for c in definition.get_children()
                        if c.kind == CursorKind.CONSTRUCTOR]
        if not constructors or any(self.sites.callers(c) for c in constructors):
            return None
        usr = definition.get_usr()
        return f"{links.CLASS_BUILT}{usr}" if usr else None

    def _scope_of(self, function: Cursor) -> Scope:
        """The scope of ``function``'s body: the unit's one (``CallSites.scope``), whose
        writes are read from the body once, whichever walk asks first."""
        if self.sites is not None:
            return self.sites.scope(function)
        return Scope(function, self.macros, self.source, self.sites)

    def _function(self, function: Cursor) -> None:
        scope = self._scope = self._scope_of(function)
        self._owner = owner_of(function)
        self._constructor = None
        self._free = function.kind == CursorKind.FUNCTION_DECL
        # of a class, not a class template: a template's constructions name its
        # specialisations, which a unit that derives from it may not show
        if function.kind != CursorKind.FIELD_DECL and is_constructor(function) and (
            not of_class_template(function)
        ):
            usr = function.canonical.get_usr()
            if usr:
                self._constructor = (usr, f"{PLACEHOLDER}{usr}{SEPARATOR}")
        # a function template of a header: what it makes for any node type (a
        # dependent ``make_shared``) is made only where a file of the node calls it
        self._template = function.canonical.get_usr() if (
            function.kind == CursorKind.FUNCTION_TEMPLATE and function.location.file
            is not None and function.location.file.name != self.tu.spelling) else None
        self._template_name = function.spelling.split("<")[0]
        tested, self._status_reads = TestedCalls(self.reader), []
        first = len(self.calls)
        # a constructor's calls exist where the class is constructed: under the
        # conditions of its construction sites in this file; a file that constructs it
        # nowhere leaves them to the node's other files (``built_in``)
        made_under = self._constructed_under(function, 0)
        built_in = self._constructor[0] if self._constructor is not None and (
            self.sites is not None and not self.sites.callers(function)) else (
            self._built_class(function))
        # main(argc, argv): its conditions over them are over the program's arguments (set
        # after the construction sites, whose walk enters their own functions)
        self._enter(function, scope)
        stack: list[tuple[Cursor, tuple[Condition, ...]]] = [
            (child, made_under) for child in reversed(list(function.get_children()))
            if child.kind != CursorKind.PARM_DECL]
        lost = _lost_initialisers(function) if function.kind == CursorKind.CONSTRUCTOR else {}
        while stack:
            node, conditions = stack.pop()
            if lost and node.kind == CursorKind.UNEXPOSED_EXPR and place_of(node) in lost:
                self._lost_initialiser(node, *lost[place_of(node)], conditions, scope)
            if node.kind == CursorKind.CXX_NEW_EXPR and (
                    unresolved := _lost_new(node)) is not None:
                self._lost_initialiser(node, *unresolved, conditions, scope)
            if node.kind == CursorKind.CALL_EXPR and node.spelling in _TAKEN_AS:
                self._typed_accessor(node)
            if node.kind == CursorKind.CALL_EXPR and node.spelling == "operator[]" and (
                    not self.ros2):
                self._struct_read(node, conditions, scope)
            if node.kind == CursorKind.CALL_EXPR and (
                    method := node.referenced) is not None and (
                    method.kind == CursorKind.CXX_METHOD):
                self._node_handed(method, written_arguments(node), scope)
            if node.kind == CursorKind.CALL_EXPR and (
                node.spelling in _API_NAMES or node.spelling in self.wrappers.names
            ):
                self._call(node, conditions, scope)
                if node.referenced is not None and node.location.file is not None:
                    self.resolved.add((node.location.file.name, node.location.line))
            elif node.kind in (CursorKind.UNEXPOSED_EXPR, CursorKind.CALL_EXPR) and (
                not node.spelling and _recovered_name(node) in self._unresolved_rows()
            ):
                self._unresolved(node, conditions, scope)
            elif node.kind == CursorKind.CALL_EXPR and not node.spelling:
                self._dependent(node, conditions, scope)
            elif node.kind == CursorKind.CALL_EXPR and node.spelling == "operator()":
                self._vendor_member_call(node)
            elif node.kind == CursorKind.CALL_EXPR and node.spelling == api.NODELET_LOAD[1]:
                self._nodelet_load(node, conditions, scope)
            elif node.kind == CursorKind.CALL_EXPR and node.spelling == "bind":
                bound = _bound_api(node)
                if bound is not None:  # the call the bound function object makes
                    self._emit(bound, node, written_arguments(node)[1:], None, conditions,
                               scope)
            if node.kind == CursorKind.CALL_EXPR:
                self._construction(node, conditions)
                self._to_unknown(node, function)
            elif node.kind == CursorKind.VAR_DECL:
                self._default_construction(node, conditions)
            elif node.kind == CursorKind.CXX_NEW_EXPR and (
                    newly := dependent_new(node)) is not None:
                # its argument list is a site of the constructor (``CallSites``)
                self._class_made(newly[1].semantic_parent, conditions)
            elif node.kind == CursorKind.CXX_NEW_EXPR and (
                    given := self._parameter_made(node)) is not None:
                self._class_made(given, conditions)
            if node.kind in _MAKES:
                self._unseen_class(node)
            tested.visit(node)
            stack.extend(self.reader.below(node, conditions))
        if not self.ros2:
            self._struct_parameters(function, made_under, scope)
        for site, read in self._status_reads:
            read.tested = read.tested or (site in tested.keys and site not in tested.required)
            if site in tested.required and read.kind == "read":
                # a read whose absence fails the program (``CHECK(nh.getParam("x",
                # x_))``, ``if (!nh.getParam(..)) { ROS_ERROR(..); return false; }``)
                # has no default, whatever the variable held before it
                read.has_default = False
        self._unit_status_reads.extend(self._status_reads)
        for held, made in tested.lasting_passed.items():
            self._lasting_passed.setdefault(held, []).extend(made)
        self._lasting_tested.update(tested.lasting_tested)
        # a function's calls exist where it is called: under the conditions its call
        # sites in the node's files share (``call_conditions``), joined per node
        called_in = function.canonical.get_usr() if call_conditions.eligible(function) else None
        if called_in and len(self.calls) > first:
            self._holding.setdefault(called_in, function)
        for call in self.calls[first:]:
            call.built_in = call.built_in or built_in
            call.called_in = call.called_in or called_in or None
            # a read or declaration without a default in a ``try`` block whose handler
            # catches rclcpp's exception for it (navigation2's collision monitor reads
            # the deprecated ``max_points`` so, only to warn when it is set)
            if self.ros2 and call.kind in ("read", "declare") and not call.has_default and any(
                c in self.reader.handled for c in call.conditions
            ):
                call.tested = True

    def _looked_up(self, call: Cursor) -> bool:
        """Whether the code only looks one key up in what ``call`` returns: the text
        after it is ``.find(``, ``.count(``, ``.contains(``, ``.at(``, ``.end(`` or ``[``."""
        end = call.extent.end
        data = self.source.get(end.file.name) if end.file is not None else None
        return data is not None and _LOOKUP.match(data, end.offset) is not None

    def _constructed_under(self, function: Cursor, depth: int) -> tuple[Condition, ...]:
        """The conditions under which this file constructs the class of the constructor
        ``function``: those every construction site shares (HectorDrawings, made only
        ``if (p_pub_drawings)``), with those of the sites of the constructor that
        constructs it; none where a site is unconditional, or the file constructs the
        class nowhere (another file, or a loader, may)."""
        if self.sites is None or depth > MAX_SITE_DEPTH or not is_constructor(function):
            return ()
        sites = self.sites.callers(function)
        if not sites or len(sites) > CallSites.MAX_SITES:
            return ()
        shared: tuple[Condition, ...] | None = None
        for call, caller in sites:
            # (a constructor that leaves its base to C++ is the base's site itself)
            found = () if call == caller else self._conditions_at(caller, call)
            if found is None:
                return ()
            if caller.kind != CursorKind.FIELD_DECL and is_constructor(caller):
                found = self._constructed_under(caller, depth + 1) + found
            shared = found if shared is None else tuple(c for c in shared if c in found)
            if not shared:
                return ()
        return shared or ()

    def _site_conditions(self, function: Cursor, call: Cursor) -> tuple[Condition, ...]:
        """The source conditions under which ``function`` makes ``call`` (a construction
        of another file's class): none where it is not found."""
        found = self._conditions_at(function, call)
        return tuple(c for c in found or () if c.kind == "source")

    def _conditions_at(self, function: Cursor, call: Cursor) -> tuple[Condition, ...] | None:
        """The source conditions of ``call`` in the body of ``function`` (None when it is
        not found there), as ``_function`` reads them."""
        return self._conditions_of(function, [call]).get(place_of(call))

    def _conditions_of(self, function: Cursor, calls: list[Cursor]
                       ) -> dict[object, tuple[Condition, ...]]:
        """``_conditions_at`` of each of ``calls`` in one walk of ``function``, by the
        call's place (a call not found there is left out)."""
        wanted = {place_of(call): call.kind for call in calls}
        self._enter(function)
        stack: list[tuple[Cursor, tuple[Condition, ...]]] = [
            (child, ()) for child in reversed(list(function.get_children()))
            if child.kind != CursorKind.PARM_DECL]
        found: dict[object, tuple[Condition, ...]] = {}
        while stack:
            node, conditions = stack.pop()
            if node.kind in wanted.values():  # a delegation too
                place = place_of(node)
                if wanted.get(place) == node.kind and place not in found:
                    found[place] = conditions
                    if len(found) == len(wanted):
                        break
            stack.extend(self.reader.below(node, conditions))
        return found

    # -- one call ---------------------------------------------------------------------

    def _row(self, call: Cursor) -> tuple[api.RosFunction | None, Cursor | None]:
        """The API row a call matches and the class whose template argument types it; a
        row of our stand-in only (``standin_only``) where the function is the stand-in's
        (with navigation2's sources in the workspace, its own code is read)."""
        spec, cls = self._any_row(call)
        if spec is not None and spec.ros2_only and not self.ros2:
            return None, None  # ROS 1's library makes no ROS call there
        if spec is not None and spec.standin_only and not from_standin(
                cls if cls is not None and cls.kind != CursorKind.NO_DECL_FOUND
                else call.referenced):
            return None, None
        return spec, cls

    def _any_row(self, call: Cursor) -> tuple[api.RosFunction | None, Cursor | None]:
        target = call.referenced
        if target is None:
            return None, None
        key = (qualified_name(target.semantic_parent), target.spelling)
        if key in api.FACTORIES:
            decl = factory_made(call)
            if decl is None:
                return None, None
            decl = row_class(decl)
            return api.ALL.get((qualified_name(decl), decl.spelling)), decl
        if target.kind == CursorKind.CONSTRUCTOR:
            made = call.type.get_canonical().get_declaration()
            if key not in api.ALL and made.kind != CursorKind.NO_DECL_FOUND:
                base = row_class(made)
                if base != made:
                    return api.ALL.get((qualified_name(base), base.spelling)), base
            return api.ALL.get(key), made
        spec = api.ALL.get(key)
        if spec is not None and "class" in spec.type_from:
            callee = callee_of_call(call)
            objects = [c for c in callee.get_children() if c.kind.is_expression()]
            if not objects and target.is_static_method():  # ``C<M>::create_subscription``
                return spec, target.semantic_parent
            return spec, record_class(objects[0]) if objects else None
        return spec, None

    def _call(self, call: Cursor, conditions: tuple[Condition, ...], scope: Scope) -> None:
        constructor = self._constructor
        target = call.referenced
        if constructor is not None and target is not None and (
            target.kind == CursorKind.CXX_METHOD and target.is_virtual_method()
        ):
            # a virtual method the constructor calls (a plugin's ``initialize(name)``)
            # is also called by code nobody sees here (its host): its calls are made
            # whether or not the class is constructed with the name
            self._constructor = None
        try:
            if self.wrappers.emit(call, conditions, scope):
                return
        finally:
            self._constructor = constructor
        if target is None:
            if not self._dependent(call, conditions, scope):
                self._unresolved(call, conditions, scope)
            return
        key = (qualified_name(target.semantic_parent), target.spelling)
        args = written_arguments(call)
        if key in api.NODE_NAME:
            index = api.NODE_NAME[key].get(len(args))
            if index is not None:
                self.rosname = render(scope.string(args[index]))
            return
        made = target.semantic_parent if target.spelling == parameter_library.LISTENER else None
        if key in api.FACTORIES:
            decl = made = factory_made(call)
            if decl is not None:
                key = (qualified_name(decl), decl.spelling)
        declared = parameter_library.listener_parameters(made)
        if declared is not None:
            self._listener(call, args, declared, conditions, scope)
            return
        node_name = api.RCLCPP_NODE_NAME.get(key)
        # the stand-in's class, not the real one: named by its constructor's parameters
        standin = node_name is None and key in api.STANDIN_NODE_NAME and self.ros2 and (
            from_standin(made or target))
        if standin:
            node_name = parameter_places(callee_of(call), api.STANDIN_NODE_NAME[key])
        if node_name is not None or standin:
            if node_name is not None:
                self._node_name(node_name, args, scope, self._local_node(call, scope), call)
            switch = api.IMPLICIT_SWITCH.get(key)
            if not (switch is not None and switch < len(args)
                    and scope.boolean(args[switch]) is False):
                for implicit in api.IMPLICIT.get(key, ()):
                    self._emit(implicit, call, args, None, conditions, scope)
            self._unread_node(call, made or target.semantic_parent)
            return
        spec, cls = self._row(call)
        if spec is not None and len(args) == 1 and record_class(args[0]) is not None and (
            qualified_name(record_class(args[0])) in api.OPTION_CLASSES
        ):
            filled = self._options(args[0], scope)
            if filled is not None:
                fill_spec, fill_call, fill_scope = filled
                self._emit(fill_spec, fill_call, written_arguments(fill_call), None,
                           conditions, fill_scope, at=call, at_scope=scope)
                return
        if spec is not None:
            self._emit(spec, call, args, cls, conditions, scope)

    def _nodelet_load(self, call: Cursor, conditions: tuple[Condition, ...],
                      scope: Scope) -> None:
        """nodelet::Loader's ``load(name, type, ...)`` with the node's own name and a
        class written as text, not under a condition (image_view's wrapper executable):
        the nodelet runs as this node (``CPP_NODELET_IN_PROCESS``; the graph gives its
        instances the class's calls). Any other stays a load by name
        (``CPP_PLUGINS_LOADED``, found in the unit's text)."""
        target, args = call.referenced, written_arguments(call)
        if target is None or len(args) < 2 or (
                qualified_name(target.semantic_parent), target.spelling) != api.NODELET_LOAD:
            return
        name, cls = render(scope.string(args[0])), render(scope.string(args[1]))
        if conditions or name != "~" or not _LOOKUP_NAME.fullmatch(cls) or (
                len(args) > 2 and not self._own_remappings(args[2], scope)):
            return
        self.diagnostics.append(diag.make("CPP_NODELET_IN_PROCESS", self.where(call),
                                          cls=cls))

    def _own_remappings(self, given: Cursor, scope: Scope) -> bool:
        """Whether the remappings a nodelet load is given add none to the node's own: a
        local map made empty or from ``ros::names::getRemappings()`` that its function
        uses only as the remappings of nodelet loads (roscpp then remaps the nodelet's
        names as the node's). A map the code fills (image_proc's
        ``remappings["image_mono"] = ...``), or of another origin, is not known here."""
        given = strip(given)
        decl = given.referenced if given.kind == CursorKind.DECL_REF_EXPR else None
        if decl is None or decl.kind != CursorKind.VAR_DECL or scope.body is None:
            return False
        init = initializer(decl)
        if init is not None and not default_constructed(init):
            made = strip(init)
            copied = written_arguments(made) if made.kind == CursorKind.CALL_EXPR and (
                made.referenced is not None
                and made.referenced.kind == CursorKind.CONSTRUCTOR) else []
            source = strip(copied[0]) if len(copied) == 1 else made
            if source.kind != CursorKind.CALL_EXPR or source.spelling != "getRemappings":
                return False
        loads: list[tuple[int, int]] = []  # where each load's remappings are written
        uses: list[int] = []
        for node in walk_cursors(scope.body):
            if node.kind == CursorKind.CALL_EXPR and node.spelling == api.NODELET_LOAD[1]:
                written = written_arguments(node)
                if len(written) > 2:
                    loads.append((written[2].extent.start.offset,
                                  written[2].extent.end.offset))
            elif node.kind == CursorKind.DECL_REF_EXPR and node.referenced == decl:
                uses.append(node.extent.start.offset)
        return all(any(start <= use <= end for start, end in loads) for use in uses)

    def _handed_to(self, owner: str, name: str, call: Cursor) -> None:
        """``owner`` hands the node to ``call`` of a function or class the parse does not
        know: keep the owner (``handed``), the callee's own name (``handed_to``:
        ``rmf_utils::make_impl<Implementation>``'s ``make_impl``), and the classes of the
        workspace the call names (its template arguments: ``Implementation``) as used by
        the owner, what the code it is handed to may build of the executable's."""
        self.handed.add(owner)
        own = WORDS.findall(name.split("<", 1)[0].encode())
        if own:
            self.handed_to.add((owner, own[-1].decode()))
        where = call.extent.start.file
        data = self.source.get(where.name) if where is not None and owner else None
        if data is None:
            return
        # the parse keeps no reference of a permissive call's template arguments: each
        # name the call writes, as C++ looks it up from the owner's scopes (a method's
        # class, then the namespaces around it); a name that is no class is no owner
        scopes = owner.removesuffix("()").split("::")[:-1 if owner.endswith("()") else None]
        for written in _QUALIFIED.findall(
                data[call.extent.start.offset:call.extent.end.offset]):
            path = re.sub(rb"\s+", b"", written).decode()
            for depth in range(len(scopes), -1, -1):
                made = "::".join([*scopes[:depth], path])
                if made != owner and (owner, made) not in self.uses:
                    self.uses.append((owner, made))

    def _unread_node(self, call: Cursor, cls: Cursor | None) -> None:
        """A node class of our stand-ins whose own calls no row says (``HAROS_UNREAD``:
        ros2_control's ControllerManager beyond its services): the node is partial,
        ``CPP_NODE_UNREAD`` where it is made."""
        if cls is None or not _unread(cls) or place_of(call) in self._unknown:
            return
        self._unknown.add(place_of(call))
        self.diagnostics.append(diag.make("CPP_NODE_UNREAD", self.where(call),
                                          name=qualified_name(cls)))

    @functools.cached_property
    def _unresolved_names(self) -> set[str]:
        """The names of the functions the unit calls where the parse could not resolve
        the call (``nav::declare_or_get_parameter(this, name, value)`` in a member
        template: no declaration is known, only the name written)."""
        found: set[str] = set()
        for calls in self.wrappers.preorder.values():
            for call in calls:
                if call.kind == CursorKind.CALL_EXPR and call.referenced is None:
                    found.add(call.spelling or _recovered_name(call))
        found.discard("")
        return found

    def _dependent(self, call: Cursor, conditions: tuple[Condition, ...],
                   scope: Scope) -> bool:
        """Emit a dependent ``make_shared`` of an API class (``_dependent_made``); made,
        in a header's function template, only where a file of the node calls it."""
        made = _dependent_made(call)
        declared = _dependent_listener(call) if made is None else None
        if made is None and declared is None:
            return False
        self._made_by = self._template
        try:
            if made is not None:
                before = len(self.calls)
                self._emit(made[0], call, written_arguments(call), made[1], conditions,
                           scope)
                if made[0].fixed_name is None and len(self.calls) > before:
                    # its name from arguments that depend on the template's parameters,
                    # as for a ``new`` clang kept unresolved (``_lost_initialiser``)
                    self.diagnostics.append(diag.make(
                        "CPP_CALL_UNRESOLVED", self.calls[before].location,
                        function=made[1].spelling, type=self.calls[before].type or "?"))
            elif declared is not None:
                self._listener(call, written_arguments(call), declared, conditions, scope)
        finally:
            self._made_by = None
        return True

    def _library_method(self, call: Cursor) -> None:
        """A call a template leaves unresolved, of a name a wrapper of the unit has, on
        an object the code declares of a class of a ROS client library: that class's
        method, not the wrapper, so no call is hidden there (``resolved``, read by
        ``recall``). Autoware's fusion node template publishes with
        ``pub_ptr_->publish(msg)``, ``pub_ptr_`` a ``typename
        rclcpp::Publisher<ExportObj>::SharedPtr``, in a unit where autoware_utils'
        ``DebugPublisher::publish`` makes publishers."""
        name = _recovered_name(call)
        if not name or name not in self.wrappers.names or call.location.file is None:
            return
        obj = method_object(call)
        declared = obj.referenced if obj is not None else None
        if declared is None or declared.kind not in (
                CursorKind.FIELD_DECL, CursorKind.VAR_DECL, CursorKind.PARM_DECL):
            return
        written = declared.type.spelling.removeprefix("const ").removeprefix("typename ")
        if written.split("::", 1)[0] in _CLIENT_NAMESPACES:
            self.resolved.add((call.location.file.name, call.location.line))

    def _unresolved(self, call: Cursor, conditions: tuple[Condition, ...],
                    scope: Scope) -> None:
        """A call clang could not resolve, kept when its name is an API function's: its
        name and values read as usual, its type as written (``?`` when that is not a
        ROS interface), and a diagnostic that says so."""
        recovered = call.kind != CursorKind.CALL_EXPR or not call.spelling
        function = _recovered_name(call) if recovered else call.spelling
        spec = self._unresolved_rows().get(function)
        if self.ros2 and function in api.UNRESOLVED_ACTION and (
                "rclcpp_action" in _callee_text(call)):
            spec = api.UNRESOLVED_ACTION[function]
        elif spec is None or spec.kind == "action-server":
            return
        if function in api.UNRESOLVED_FREE and not any(
                api.ALL.get((qualified_name(d.semantic_parent), d.spelling)) is spec
                for d in looked_up(call)):
            return  # another function of that name, or one the lookup did not find
        if spec.standin_only:  # a dependent call of a stand-in's function (of nav2's
            # declare_parameter_if_not_declared in a template): one of the overloads its
            # name may be is the stand-in's row
            if not any(from_standin(d) and api.ALL.get(
                    (qualified_name(d.semantic_parent), d.spelling)) is not None
                       for d in looked_up(call)):
                return
            spec = dataclasses.replace(spec, standin_only=False)
        elif own_functions_only(call):  # one of the code's own functions of that name,
            # read: no call hidden there (``recall``)
            if call.location.file is not None:
                self.resolved.add((call.location.file.name, call.location.line))
            return
        if spec.name_candidates or (self.ros2 and spec.on_handle):
            # ROS 2: made on the node itself, in its namespace
            spec = dataclasses.replace(spec, name_candidates=(), on_handle=False)
        args = ([c for c in list(call.get_children())[1:] if c.kind.is_expression()]
                if call.kind != CursorKind.CALL_EXPR else written_arguments(call))
        before = len(self.calls)
        # in a function template of a header (a call on an object of a template
        # parameter's type, ``params.template param<bool>("use_const_inf_matrix", false)``
        # of hdl_graph_slam's InformationMatrixCalculator::load<ParamServer>): made only
        # where a file of the node calls the template, as ``_dependent`` makes its class,
        # unless a call of the unit the parse could not resolve either may call it (nav2's
        # declare_or_get_parameter<ParamType, NodeT>, called from its LifecycleNode's
        # member template, names no function a fact can say is called: its reads of
        # warn_on_missing_params stay the node's)
        made_by = self._made_by
        if made_by is None and self._template is not None and (
            self._template_name not in self._unresolved_names
        ):
            self._made_by = self._template
        try:
            self._emit(spec, call, args, None, conditions, scope)
        finally:
            self._made_by = made_by
        if len(self.calls) == before:
            return
        written = _written_template(call)
        # a parameter's type as written (``node.template declare_parameter<double>("t",
        # 34)`` declares a double), before the value's
        written_param = (msg_types.written_param_type(written)
                         if spec.kind in ("read", "write", "declare") else None)
        for index in range(before, len(self.calls)):
            made = self.calls[index]
            if written_param is not None and made.type != written_param:
                self.calls[index] = dataclasses.replace(made, type=written_param)
            elif (made.type is None and spec.kind not in ("read", "write", "declare")) or (
                made.type == "?"
            ):
                self.calls[index] = dataclasses.replace(
                    made, type=msg_types.written_type(written, self.ros2, True)
                    or self._class_parameter_type(written, scope, [made.name]) or "?")
        self.diagnostics.append(diag.make(
            "CPP_CALL_UNRESOLVED", self.calls[before].location, function=function,
            type=_shown_type(self.calls[before].type)))
        if call.location.file is not None:
            self.kept_unresolved.add((call.location.file.name, call.location.line, function))

    def _class_parameter_type(self, written: str, scope: Scope,
                              names: list[str]) -> str | None:
        """The type of an unresolved call whose template argument is written as a type
        parameter of the class template whose method makes it
        (``rclcpp_action::create_client<T>(node, getActionName())`` in MoveIt's
        ``ActionBasedControllerHandle<T>``'s constructor): the type each construction
        gives it (``_construction_type``); None for any other."""
        function = scope.body
        template = function.semantic_parent if function is not None else None
        if template is None or template.kind != CursorKind.CLASS_TEMPLATE:
            return None
        parameters = [c.spelling for c in template.get_children()
                      if c.kind in _TEMPLATE_PARAMETERS]
        if written not in parameters:
            return None
        return self._construction_type(template, parameters.index(written), names)

    def _lost_initialiser(self, init: Cursor, spec: api.RosFunction, made: Cursor,
                          conditions: tuple[Condition, ...], scope: Scope) -> None:
        """A member of an API class (``action_server_(nh, "follow", boost::bind(...))``)
        whose initialiser clang could not resolve (it names a method an error made
        invalid), or a ``new`` of one that it kept unresolved (``_lost_new``): the
        construction kept as the class's row reads its arguments, its type from the
        member's (the new-expression's), and a diagnostic that says so."""
        args = [c for c in init.get_children() if c.kind.is_expression()]
        if init.kind == CursorKind.CXX_NEW_EXPR and len(args) == 1 and (
                args[0].kind == CursorKind.UNEXPOSED_EXPR and not args[0].spelling):
            args = [c for c in args[0].get_children() if c.kind.is_expression()]  # (a, b)
        before = len(self.calls)
        self._emit(spec, init, args, made, conditions, scope)
        if len(self.calls) > before:
            self.diagnostics.append(diag.make(
                "CPP_CALL_UNRESOLVED", self.calls[before].location, function=made.spelling,
                type=self.calls[before].type or "?"))

    def _per_construction_type(self, function: Cursor, names: list[str]) -> str | None:
        """The type of a call whose callback takes a type parameter of the class
        template it is a member of (``CallTypes.template_parameter``), as a placeholder
        of the constructor that builds the object, which each construction fills with
        its template argument (``links.TYPE_ARGUMENT``): the constructor whose
        placeholders the name holds, else the template's one constructor; None when
        that is not one."""
        found = self.types.template_parameter(function)
        return None if found is None else self._construction_type(*found, names)

    def _construction_type(self, template: Cursor, index: int,
                           names: list[str]) -> str | None:
        """The placeholder of the type argument ``index`` of the class template
        ``template`` that each construction fills (``_per_construction_type``); the
        constructor is marked, so that its constructions are read (``passing_sites``)
        where no name holds its placeholder."""
        constructors = {c.canonical.get_usr(): c for c in template.get_children()
                        if c.kind == CursorKind.CONSTRUCTOR}
        constructors.pop("", None)
        marked = {usr for name in names for usr in links.marked_usrs(name)} & set(
            constructors)
        chosen = marked if marked else set(constructors)
        if len(chosen) != 1:
            return None
        usr = chosen.pop()
        if self.sites is not None:
            self.sites.marked.add(place_of(constructors[usr].canonical))
        return f"{PLACEHOLDER}{usr}{SEPARATOR}{links.TYPE_ARGUMENT + index}{PLACEHOLDER}"

    def _unresolved_rows(self) -> dict[str, api.RosFunction]:
        return api.UNRESOLVED_ROS2 if self.ros2 else api.UNRESOLVED_ROS1

    def _construction(self, call: Cursor, conditions: tuple[Condition, ...] = ()) -> None:
        """Record that the function being walked constructs a class of the workspace;
        say so when that class is another package's, built here with the node and
        defined elsewhere (``CPP_NODE_PASSED``: its calls on the node are not read)."""
        made = opaque_constructor(call, self.owned)
        opaque, constructor = made if made is not None else (None, None)
        if opaque is not None and opaque.location.file is not None:
            # its class's declaration: the members it may construct, unseen here
            data = self.source.get(opaque.location.file.name)
            usr = constructor.canonical.get_usr() if constructor is not None else ""
            if data is not None:
                # not the class's own name, which its declaration writes and its
                # constructor (read where it is defined) does not construct again
                words = set(WORDS.findall(_declared_code(opaque, data))) - {
                    opaque.spelling.encode()}
                # made through a factory (``std::make_shared<C>(options)``), which may
                # call any of the class's declared constructors: unseen until another
                # unit of the node has the code of each (rtabmap_odom's main builds
                # RGBDOdometry, whose one constructor rgbd_odometry.cpp defines)
                every = [usr] if usr else _declared_constructors(opaque)
                if every:
                    # unseen here only: another unit of the node may have the
                    # constructor's code (``links.OPAQUE``)
                    for each in every:
                        self.opaque_words.setdefault(each, set()).update(words)
                else:
                    self.unseen.update(words)
                    for word in words:
                        self.unseen_in.setdefault(word, set()).add(qualified_name(opaque))
        unseen = unseen_construction(call, self.owned) if opaque is not None else None
        if unseen is not None:
            cls, given = unseen
            here, there = self.where(call), self.where(cls)
            if there.package and there.package != here.package:
                self.handed.add(self._owner or "")
                self.passed.add((self._owner or "", qualified_name(cls)))
                self.diagnostics.append(diag.make(
                    "CPP_NODE_PASSED", here, cls=qualified_name(cls), package=there.package,
                    given="".join(t.spelling for t in given.get_tokens())[:60]))
        name = constructed_class(call, self.owned)
        if name is not None and name == self._owner and (name, name) not in self.uses:
            self.uses.append((name, name))  # a class's own factory makes it: it is made
        if name is not None and self._owner is not None and name != self._owner:
            self.made_under.append((name, tuple(c for c in conditions if c.kind == "source")))
            if (self._owner, name) not in self.constructions:
                self.constructions.append((self._owner, name))
            for pair in constructed_bases(call, self.owned):
                if pair not in self.constructions:
                    self.constructions.append(pair)

    def _dependent_made(self, node: Cursor) -> None:
        """A construction of a class template of the workspace whose constructor the
        parse cannot choose, its arguments depending on a template parameter
        (component_interface_utils' ``make_shared<NodeInterface<NodeT>>(node)`` in
        NodeAdaptor's constructor template; ``NodeInterface<NodeT> i(node)``, ``new
        NodeInterface<NodeT>(node)``): no call names the constructor, so any of them may
        run; its class's name is unseen, as where an error hides a construction
        (``links.resolve`` keeps the calls of that class's constructors)."""
        kind = node.kind
        children = list(node.get_children())
        if kind == CursorKind.CALL_EXPR:
            head = children[0] if children and node.referenced is None else None
            if head is None or called_name(head) not in FACTORY_NAMES:
                return
            refs = list(head.get_children())
        elif kind == CursorKind.VAR_DECL:
            init = children[-1] if children else None
            if init is None or init.kind != CursorKind.UNEXPOSED_EXPR or (
                    init.referenced is not None):
                return
            refs = children
        else:
            refs = children
        for ref in refs:
            template = ref.referenced if ref.kind == CursorKind.TEMPLATE_REF else None
            if template is not None and template.kind == CursorKind.CLASS_TEMPLATE and (
                    (where := template.location.file) is not None and self.owned(where.name)):
                self.unseen.add(template.spelling.encode())
                return

    def _parameter_made(self, node: Cursor) -> Cursor | None:
        """The class a ``new P(args)`` of a class template's type parameter ``P``
        constructs: the one every specialisation of the template the unit names gives
        for ``P`` (``CallTypes.bound``), else ``P``'s default argument (rosserial_server's
        ``TcpServer<>``, ``template<typename Session = Session<tcp::socket>>``, whose
        ``new Session(io_service_)`` builds each client's session); None for another
        ``new``, or a parameter with neither."""
        written = next((child for child in node.get_children()
                        if child.kind == CursorKind.TYPE_REF), None)
        decl = written.referenced if written is not None else None
        if decl is None or decl.kind != CursorKind.TEMPLATE_TYPE_PARAMETER:
            return None
        bound = self.types.bound(decl)
        if bound is not None:
            made = bound.get_canonical().get_declaration()
        else:  # the default argument: ``= Session<tcp::socket>`` or ``= Session``
            made = next((child.referenced for child in decl.get_children()
                         if child.kind in (CursorKind.TEMPLATE_REF, CursorKind.TYPE_REF)
                         and child.referenced is not None), None)
        if made is None or made.kind == CursorKind.NO_DECL_FOUND:
            return None
        if made.kind not in CLASSES:
            return None
        template = conf.lib.clang_getSpecializedCursorTemplate(made)
        return template if template is not None and template.kind == (
            CursorKind.CLASS_TEMPLATE) else made

    def _default_construction(self, variable: Cursor,
                              conditions: tuple[Condition, ...]) -> None:
        """Record the construction of a class of the workspace by a variable declared
        without an initialiser whose construction the parse did not keep
        (``construction_dropped``), as ``_construction`` records one it kept."""
        self._class_made(construction_dropped(variable, self.owned), conditions)

    def _class_made(self, cls: Cursor | None, conditions: tuple[Condition, ...]) -> None:
        """Record the construction of ``cls``, a class of the workspace, where the parse
        kept no call of its constructor, as ``_construction`` records one it kept."""
        if cls is not None and ((where := cls.location.file) is None
                                or not self.owned(where.name)):
            return
        name = qualified_name(cls) if cls is not None else ""
        if not name or self._owner is None or name == self._owner:
            return
        self.made_under.append((name, tuple(c for c in conditions if c.kind == "source")))
        for pair in ((self._owner, name), *class_bases(cls, self.owned)):
            if pair not in self.constructions:
                self.constructions.append(pair)

    def _unseen_class(self, node: Cursor) -> None:
        """ROS 1: say where ``node`` builds an object of a class of another ROS package
        whose code this parse does not have (``_unseen_of``): ``CPP_CLASS_UNSEEN``. A
        variable of the class (``ns::C c(args);``), ``new ns::C(...)``,
        ``make_shared<ns::C>(...)``, or a call of a constructor of the workspace; a
        call of a name declared permissively is no construction (``tf::pointMsgToTF(a,
        b)`` is a function, unknown to the parse as a type or not)."""
        if self.clients is None:
            return
        kind = node.kind
        if kind == CursorKind.VAR_DECL:
            if node.type.get_canonical().kind == TypeKind.RECORD:
                # ``C c = f();`` keeps what ``f`` returns: built where ``f`` built it
                self._say_unseen(node.type.get_canonical().get_declaration(), node,
                                 not _copy_initialised(node))
        elif kind == CursorKind.CXX_NEW_EXPR:
            made = node.type.get_canonical().get_pointee()
            if made.kind == TypeKind.RECORD:
                self._say_unseen(made.get_declaration(), node, True)
        elif kind == CursorKind.CALL_EXPR:
            target = node.referenced
            if target is None:
                return
            if target.kind == CursorKind.CONSTRUCTOR:
                made = target.semantic_parent
                outer = made.semantic_parent if made is not None else None
                if outer is not None and outer.kind in (
                    CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL
                ) and made.location.file is not None and (
                        made.location.file.name == self.declared) and (
                        made.spelling[:1].islower()):
                    # ``C::getInstance()`` of a class declared permissively: its static
                    # member, which the parse reads as a nested class, gives an object
                    # of C (a singleton, a factory): C's code runs here (a nested
                    # class's own, ``MoveGroupInterface::Plan plan;``, is data)
                    self._say_unseen(outer, node, True)
                else:
                    self._say_unseen(made, node, False)
            elif (qualified_name(target.semantic_parent), target.spelling) in api.FACTORIES:
                made_cls = factory_made(node)
                if made_cls is not None:
                    self._say_unseen(made_cls, node, True)

    def _unseen_members(self, constructor: Cursor) -> None:
        """ROS 1: the members of the constructor's class that it builds by value, whose
        class is one ``_unseen_of`` finds, at their initialiser (``costmap_ros_("costmap",
        tf_)``), else at their declaration (built by default, which the code does not
        write: ``base_local_planner::TrajectoryPlannerROS planner_;``)."""
        if not constructor.is_definition():
            return
        owner = constructor.semantic_parent
        if owner is None:
            return
        named = {place_of(child.referenced): child for child in constructor.get_children()
                 if child.kind == CursorKind.MEMBER_REF and child.referenced is not None}
        for member in owner.get_children():
            if member.kind == CursorKind.FIELD_DECL and (
                member.type.get_canonical().kind == TypeKind.RECORD
            ):
                self._say_unseen(member.type.get_canonical().get_declaration(),
                                 named.get(place_of(member), member), True)

    def _say_unseen(self, cls: Cursor | None, at: Cursor, declared: bool) -> None:
        found = self._unseen_of(cls, declared) if cls is not None else None
        if found is None:
            return
        name, package = found
        self._classes_said.add(name)
        self.diagnostics.append(diag.make("CPP_CLASS_UNSEEN", self.where(at), cls=name,
                                          package=package))

    def _unseen_of(self, cls: Cursor, declared: bool) -> tuple[str, str] | None:
        """The class (qualified) and ROS package of ``cls`` when it is a class of another
        ROS package whose constructor's code the parse does not have: one the parse
        knows only as a name declared permissively (its header is missing) in the
        namespace of a package, built where the code names it as a type
        (``declared``), or a class of another workspace package that declares a
        constructor the unit has no code of; when the ``clients`` predicate accepts
        the package and the class. A class the API rows model (``tf::TransformListener``,
        an actionlib client, one that inherits such a class's constructors) is read by
        its row; one of a package the stand-in headers provide is no client's."""
        assert self.clients is not None
        if cls.kind not in (CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
                            CursorKind.CLASS_TEMPLATE):
            return None
        where = cls.location.file
        if where is None:
            return None
        name = qualified_name(cls)
        if not name or name in self._classes_said or (
                "::" not in name and where.name != self.declared):
            return None
        if where.name == self.declared:
            if not declared or cls.spelling == synthesis.ANY or cls.spelling.endswith("Ptr"):
                return None  # ``pkg::NameConstPtr``: a message's pointer, as ROS 1 names it
            parent = cls.semantic_parent
            if parent is not None and parent.kind in (
                    CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL, CursorKind.CLASS_TEMPLATE):
                return None  # a class's own type (``MoveGroupInterface::Plan plan;``): data
            if msg_types.written_type(name, False) is not None:
                return None  # a message no header declares (``vendor_msgs::Pose``): data
            package = name.split("::", 1)[0]
        elif self.owned(where.name):
            package = self.where(cls).package or ""
            here = self.where(self.tu.cursor).package
            definition = cls.get_definition() or cls
            if not package or package == here or constructors_here(cls) or not any(
                child.kind == CursorKind.CONSTRUCTOR for child in definition.get_children()
            ):
                return None  # a class without constructors of its own runs no code
        elif _unread(cls):
            # a class our stand-ins declare only so that code using it parses, whose
            # calls no row says (ROS 1 costmap_2d's Costmap2DROS): its package is the
            # stand-in's, whose code is not read, when the unit may include it
            package = name.split("::", 1)[0]
            found = None if name in _API_CLASSES else self.clients(package, name, True)
            return (name, found) if found else None
        else:
            return None
        if name in _API_CLASSES or qualified_name(row_class(cls)) in _API_CLASSES:
            return None
        found = self.clients(package, name)
        if not found and where.name == self.declared:
            top = header_folder(name, self.missing_headers)
            if top is not None:
                found = self.clients(top, name, header=True)
            named = named_header_folder(name, self.missing_headers) if not found else None
            if named is not None:
                found = self.clients(named, name)
        return (name, found) if found else None

    def _to_unknown(self, call: Cursor, function: Cursor | None = None) -> None:
        """Say when ``call`` gives the node to a function or class the parse knows only
        as a name declared permissively (its package is not in the workspace:
        ``CPP_NODE_TO_UNKNOWN``, the node is partial): what it does with the node is
        not read. So does an unqualified call that the permissive class's friend takes
        (``synthesis.Names.friends``) in a method of ``function``'s class derived from a
        class declared permissively: it may be that base's method, run on the object."""
        if call.referenced is None:
            self._to_chosen_class(call, function)
            return
        unknown = self._unknown_callee(call)
        if unknown is None:
            return
        key = place_of(call)
        if key in self._unknown:
            return
        # a class not read built with a NodeOptions is a node of its own in this
        # process (raspimouse_ros2_examples' line_follower builds raspimouse::Raspimouse
        # beside its own node): its interface is unseen as well
        given = node_arguments(call) or options_arguments(call)
        if given and binds_own_member(call, given):
            return  # a callback binding: the member's calls are read where it is defined
        if given and self._listener_registration(call, given, function):
            return  # the vendor sees the object as its own base: it calls the overrides
        if given and self._of_loaded_base(call):
            return  # the class pluginlib loads makes the calls: said where it loads
        # the function's own owner: ``_gives`` asks before any walk of it sets ``_owner``
        owner = (owner_of(function) if function is not None else self._owner) or ""
        if not given and self._of_unknown_base(unknown, function):
            self._unknown.add(key)
            self._handed_to(owner, call.spelling, call)
            self.diagnostics.append(diag.make(
                "CPP_NODE_TO_UNKNOWN", self.where(call), given="this", name=call.spelling))
            return
        if given:  # once per place (a conversion of the made object starts there too)
            self._unknown.add(key)
            name = call.spelling if unknown is call.referenced else qualified_name(unknown)
            if not name or name == synthesis.ANY or name.startswith("operator"):
                # a declared class's construction (its constructor is the permissive
                # base's) or a call on such an object: the type, else the text
                name = call.type.spelling
                if not name or synthesis.ANY in name:
                    name = "".join(itertools.takewhile(
                        lambda word: word not in ("(", "{"),
                        (t.spelling for t in itertools.islice(call.get_tokens(), 24))))
            self._handed_to(owner, name, call)
            self.diagnostics.append(diag.make(
                "CPP_NODE_TO_UNKNOWN", self.where(call), given=_written(given[0], call),
                name=name))

    def _to_chosen_class(self, call: Cursor, function: Cursor | None) -> None:
        """Say when ``call``, in a template, gives the node to a method of an object whose
        class the template's arguments choose, a class template of the workspace
        (``_chosen_method``): ros_controllers' JointTrajectoryController calls
        ``hw_iface_adapter_.init(joints_, controller_nh_)`` on a
        ``HardwareInterfaceAdapter<HardwareInterface, State>``, whose specialisations for
        velocity and effort interfaces read PID gains and ``velocity_ff`` on that handle
        and those for position interfaces nothing. The parse walks the template, not
        each instantiation, so which ``init`` runs is not known: what it does with the
        node is not read, the node is partial (``CPP_NODE_TO_UNKNOWN``), not complete."""
        chosen = _chosen_method(call, self.owned)
        given = node_arguments(call) if chosen is not None else []
        if chosen is None or not given:
            return
        key = place_of(call)
        if key in self._unknown:
            return
        self._unknown.add(key)
        method, cls = chosen
        owner = (owner_of(function) if function is not None else self._owner) or ""
        self._handed_to(owner, method, call)
        self.diagnostics.append(diag.make(
            "CPP_NODE_TO_UNKNOWN", self.where(call), given=_written(given[0], call),
            name=f"{method} of {cls}, a class the template's arguments choose"))

    def _of_loaded_base(self, call: Cursor) -> bool:
        """Whether ``call`` is a method of an object held as the base class that a
        pluginlib ClassLoader written beside it (in the file declaring the object, or
        the call's) loads: slam_toolbox's ``solver_->Configure(shared_from_this())``,
        ``solver_`` a ``std::shared_ptr<karto::ScanSolver>`` and the class's
        ``pluginlib::ClassLoader<karto::ScanSolver> solver_loader_``. The class loaded
        makes what calls there are: ``CPP_PLUGINS_LOADED`` says so at the load, or the
        graph gives them (``api.PLUGINLIB_CLASS``); the base's declaration is no code."""
        # the object the callee is read from, first and innermost in the callee's
        # expression (through a smart pointer's ``operator->``, or a permissive value's
        # call operator: ``solver_`` before ``solver_->Configure``)
        children = list(call.get_children())
        named = sorted((((c.extent.start.offset, c.extent.end.offset), c.referenced) for c in (
            walk_cursors(children[0]) if children else ()) if c.kind in (
            CursorKind.MEMBER_REF_EXPR, CursorKind.DECL_REF_EXPR) and c.referenced is not None
            and c.referenced.kind in _OBJECTS), key=lambda each: each[0])
        if not named:
            return False
        decl = named[0][1]
        held = _held_classes(decl.type)  # the innermost: a container's element's
        if not held or decl.location.file is None or call.location.file is None:
            return False
        base = base_name(held[-1])
        for name in dict.fromkeys((decl.location.file.name, call.location.file.name)):
            data = self.source.get(name)
            if data and b"ClassLoader" in data and base in loader_bases(
                    data.decode("utf-8", "replace")):
                return True
        return False

    def _listener_registration(self, call: Cursor, given: list[Cursor],
                               function: Cursor | None) -> bool:
        """Whether ``call`` gives the object itself (``this``, ``*this``) to a function
        or to an object's method of a namespace that a base of the object's class
        declared permissively is of: a listener registration (mqtt_client's
        ``client_->set_callback(*this)``, its class deriving Paho's ``mqtt::callback``),
        where the vendor's code has the object as that base of its own and calls the
        class's overrides, read where they are defined."""
        if function is None or not all(
                "".join(t.spelling for t in arg.get_tokens()) in ("this", "*this")
                for arg in given):
            return False
        owner = function.semantic_parent
        if owner is None or owner.kind not in (CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL,
                                               CursorKind.CLASS_TEMPLATE):
            return False
        spaces = set()
        for base in owner.get_children():
            if base.kind == CursorKind.CXX_BASE_SPECIFIER:
                decl = base.type.get_canonical().get_declaration()
                if decl is not None and self._declared_here(decl):
                    spaces.add(qualified_name(decl).split("::")[0])
        return bool(spaces) and self._vendor_space(call) in spaces

    def _vendor_space(self, call: Cursor) -> str | None:
        """The top namespace of what ``call`` runs when it is declared permissively: the
        function's, or the class of the object a member is called on."""
        target = call.referenced
        name = qualified_name(target) if target is not None and self._declared_here(
            target) else ""
        if "::" in name and name.split("::")[0] != synthesis.ANY:
            return name.split("::")[0]
        callee = first_operand(call)
        if callee is None or callee.kind != CursorKind.MEMBER_REF_EXPR:
            return None
        subject = next((c for c in callee.get_children() if c.kind.is_expression()), None)
        if subject is None:
            return None
        kind = subject.type.get_canonical()
        if kind.kind == TypeKind.POINTER:
            kind = kind.get_pointee()
        decl = kind.get_declaration()
        if decl is None or not self._declared_here(decl):
            return None
        return qualified_name(decl).split("::")[0]

    def _vendor_member_call(self, call: Cursor) -> None:
        """A call of an API function's name that the parse resolved to a member of a class
        declared permissively (its header is missing: mqtt_client's ``client_->subscribe(
        topic, qos)`` on Paho's ``mqtt::async_client``) is no ROS call left unread, in
        ROS 2 code: such an object communicates only through a node it is given, which
        ``_to_unknown`` says where it is given (``resolved``, so not CPP_CALL_MISSED).
        In ROS 1 code, where any class may make its own NodeHandle, only a member of an
        object whose class is declared permissively in the namespace of a library that
        ``clients`` says makes no ROS calls (boost, a system library): kuka_eki_hw_interface's
        ``resolver.resolve({udp::v4(), host, port})`` of asio, with <boost/asio.hpp>
        missing, is no tf listener's ``resolve``."""
        if not self.ros2 and self.clients is None:
            return
        callee = first_operand(call)
        if callee is None or callee.kind not in (CursorKind.MEMBER_REF_EXPR,
                                                 CursorKind.DECL_REF_EXPR):
            return
        target = callee.referenced
        if callee.spelling in _API_NAMES and target is not None and self._declared_here(
                target) and callee.location.file is not None and (
                    self.ros2 or self._of_library_object(callee)):
            self.resolved.add((callee.location.file.name, callee.location.line))

    def _of_library_object(self, callee: Cursor) -> bool:
        """ROS 1: whether member ``callee`` is read on an object of a class declared
        permissively in a namespace whose package ``clients`` says makes no ROS calls."""
        assert self.clients is not None
        if callee.kind != CursorKind.MEMBER_REF_EXPR:
            return False
        base = next(callee.get_children(), None)
        if base is None:
            return False
        kind = base.type.get_canonical()
        if kind.kind in (TypeKind.POINTER, TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
            kind = kind.get_pointee()
        cls = kind.get_declaration()
        if cls is None or cls.kind not in (CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL) or (
                not self._declared_here(cls)) or cls.spelling == synthesis.ANY:
            return False
        name = qualified_name(cls)
        return "::" in name and not self.clients(name.split("::", 1)[0], name)

    def _of_unknown_base(self, callee: Cursor, function: Cursor | None) -> bool:
        """Whether ``callee`` is a friend of the permissive class (an unqualified function
        no lookup found) called in a method of a class with a base declared permissively,
        directly or through the workspace's classes: the base's own method, for C++."""
        if function is None or function.kind not in (
                CursorKind.CXX_METHOD, CursorKind.CONSTRUCTOR, CursorKind.DESTRUCTOR,
                CursorKind.FUNCTION_TEMPLATE):
            return False
        if synthesis.is_macro_name(callee.spelling):
            # a macro of a missing header (the DJI SDK's ``DSTATUS(...)`` logging in
            # Onboard-SDK-ROS's VehicleWrapper, derived from its ``Setup``): no method
            return False
        lexical, semantic = callee.lexical_parent, callee.semantic_parent
        if lexical is None or lexical.spelling != synthesis.ANY or (
                semantic is not None and semantic.spelling == synthesis.ANY):
            return False  # not declared in the class as a friend: its member
        owner = function.semantic_parent
        if owner is None or self.declared is None or not any(
                where == self.declared for where, _ in base_keys(owner, named=True)):
            return False
        # a base of a library that is no ROS package's runs no ROS call: realsense2_camera's
        # RosSensor calls librealsense's ``get_info`` of its base ``rs2::sensor``
        return self.ros_class is None or any(
            self.ros_class(name) for name in self._permissive_bases(owner))

    def _permissive_bases(self, cls: Cursor, depth: int = 0) -> list[str]:
        """The qualified names of ``cls``'s bases declared permissively, transitively
        through the workspace's classes (those an unqualified name may find)."""
        found: list[str] = []
        if depth > 8:
            return found
        for base in cls.get_children():
            if base.kind != CursorKind.CXX_BASE_SPECIFIER or (
                    base.type.get_canonical().kind != TypeKind.RECORD):
                continue
            decl = base.type.get_canonical().get_declaration()
            where = decl.location.file
            if where is not None and where.name == self.declared:
                found.append(qualified_name(decl))
                continue
            definition = decl.get_definition()
            if definition is not None:
                found.extend(self._permissive_bases(definition, depth + 1))
        return found

    def _unknown_callee(self, call: Cursor) -> Cursor | None:
        """What ``call`` runs whose code the parse does not have: a function or class
        declared permissively (in the synthesised header), a class a stand-in declares
        only so that code using it parses (``HAROS_UNREAD``: nav2_costmap_2d's
        CostmapSubscriber), built directly or by ``make_shared`` / ``make_unique``."""
        target = call.referenced
        if target is None:
            return None
        if target.spelling in FACTORY_NAMES and (
            qualified_name(target.semantic_parent), target.spelling
        ) in api.FACTORIES:
            made = factory_made(call)
            return made if made is not None and (
                self._declared_here(made) or _unread(made)) else None
        if self._declared_here(target):
            return target
        if target.kind == CursorKind.CONSTRUCTOR and _unread(target.semantic_parent):
            return target.semantic_parent
        return None

    def _declared_here(self, decl: Cursor) -> bool:
        """Whether ``decl`` is in the header of names declared permissively."""
        where = decl.location.file
        return where is not None and self.declared is not None and where.name == self.declared

    def _options(self, expr: Cursor,
                 scope: Scope) -> tuple[api.RosFunction, Cursor, Scope] | None:
        """The ``ops.init<M>(...)`` or ``Options::create<M>(...)`` call that filled the
        options object ``expr`` (in this function, else in any function of the file), or
        the constructor of a local one given its topic (``ros::AdvertiseOptions
        opts(topic, 1, md5sum, datatype, definition)``)."""
        expr = strip(expr)
        decl = expr.referenced if expr.kind in (
            CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
        if decl is None:
            return None
        value = scope.variable(decl)
        if value is not None:
            inner = _creator(value)
            if inner is not None:
                return inner[0], inner[1], scope
        made = strip(initializer(decl)) if decl.kind == CursorKind.VAR_DECL and (
            initializer(decl) is not None) else None
        if made is not None and made.kind == CursorKind.CALL_EXPR and (
                made.referenced is not None
                and made.referenced.kind == CursorKind.CONSTRUCTOR):
            row = api.OPTIONS.get((qualified_name(made.referenced.semantic_parent),
                                   made.referenced.spelling))
            if row is not None and len(written_arguments(made)) > 1:
                return row, made, scope
        for function in [scope.body, *self.functions]:
            if function is None:
                continue
            for node in function.walk_preorder():
                if node.kind != CursorKind.CALL_EXPR or node.spelling not in (
                        "init", "create", "initByFullCallbackType"):
                    continue
                target = node.referenced
                row = api.OPTIONS.get((qualified_name(target.semantic_parent), node.spelling)
                                      ) if target is not None else None
                callee = callee_of_call(node)
                objects = [c for c in callee.get_children() if c.kind.is_expression()]
                if row is not None and objects and strip(objects[0]).referenced == decl:
                    found = scope if function == scope.body else self._scope_of(function)
                    return row, node, found
        return None

    def _node_handed(self, method: Cursor, args: list[Cursor], scope: Scope) -> None:
        """(owner of the node, class) in ``node_handed`` for a call of a method of a
        class of the workspace, not a node class itself, that hands it a node: the
        owner of a method's local node variable (``_local_node``) when the argument is
        that variable, else the calling function's owner (its node: a member, a
        parameter, ``*this``, main's node)."""
        cls = method.semantic_parent
        where = cls.location.file if cls is not None and args else None
        if method.is_static_method() or where is None or not self.owned(where.name) or (
                self._owner is None or cls.kind not in CLASSES or is_ros2_node(cls)):
            return
        for arg in args:
            if not _is_node(arg):
                continue
            holder = self._owner
            ref = _referenced_variable(arg)
            value = initializer(ref) if ref is not None else None
            made = node_construction(value)
            if made is not None:
                holder = self._local_node(made[0], scope) or holder
            pair = (holder, qualified_name(cls))
            # a method handing the node it holds on to another of its class hands the
            # class nothing new
            if holder != pair[1] and pair not in self.node_handed:
                self.node_handed.append(pair)

    def _local_node(self, call: Cursor, scope: Scope) -> str | None:
        """The owner of the node a method's construction ``call`` makes when it
        initialises a local variable of the method (``rclcpp::Node parameters("npv", "",
        options)``): that variable, as ``handle_node`` names it for the calls made on it,
        not the method's class, whose other calls (on a member node reference it was
        given) are not made on that node. sbg_ros2_driver's SbgDevice reads its
        parameters through such a local node and publishes on the node main() gives it:
        all its calls were taken for the local node's. None for any other construction:
        a base's (``: Node("x")``), a member's, or a free function's (main's node is
        what the classes it builds are given)."""
        owner = self._owner
        if owner is None or owner.endswith("()") or scope.body is None:
            return None
        for node in scope.body.walk_preorder():
            if node.kind != CursorKind.VAR_DECL:
                continue
            value = initializer(node)
            for _ in range(MAX_DEPTH):  # through the implicit casts and copies around it
                if value is None:
                    break
                value = strip(value)
                if value == call:
                    if (owner, node.get_usr()) not in self.uses:
                        self.uses.append((owner, node.get_usr()))  # the method holds it
                    return node.get_usr()
                inner = [c for c in value.get_children() if c.kind.is_expression()]
                value = inner[0] if len(inner) == 1 else None
        return None

    def _node_name(self, where: tuple[int, int], args: list[Cursor], scope: Scope,
                   owner: str | None = None, call: Cursor | None = None) -> None:
        name_arg, ns_arg = where
        if name_arg >= len(args):
            return
        # the local rules of the node of its owner: a class's base (``: Node("x",
        # options)``), a free function's node or a local one (not a helper node a
        # class keeps beside its own, which has none of its calls: nav2's client nodes)
        own = (owner is not None and owner != self._owner) or (
            self._owner is not None and self._owner.endswith("()")) or (
            call is not None and _base_initialiser(call, scope.body))
        owner = owner or self._owner
        local = _local_rules(args, scope) if own else None
        rules: list[str] = []
        if local is not None and local.node_name is not None:
            name = local.node_name  # its own ``__node:=`` rule names it, as rcl does
            rules.append(f"__node:={name}")
        elif any(_renames_itself(arg) for arg in args):
            return  # its own ``__node:=`` argument names it at run time (nav2's helpers)
        else:
            name = render(scope.string(args[name_arg]))
        if local is not None and local.namespace is not None:
            # its own ``__ns:=`` rule: that namespace, whatever the code and the launch
            # give (rcl wants it fully qualified; one that is not is not a rule)
            namespace = local.namespace.strip("/")
            name = f"/{namespace}/{name}" if namespace else f"/{name}"
            rules.append(f"__ns:={local.namespace}")
        elif ns_arg < len(args) and (
            strip(args[ns_arg]).type.get_canonical().get_declaration().spelling != "NodeOptions"
        ):
            namespace = render(scope.string(args[ns_arg])).strip("/")
            if namespace:
                name = f"/{namespace}/{name}"
        for rule in rules:
            if (name, rule) not in self.local_rules:
                self.local_rules.append((name, rule))
        if owner is not None and (owner, name) not in self.node_names:
            self.node_names.append((owner, name))
        made_in = self._made_in(name, None)
        if made_in is not None:
            # named by the parameters of a constructor no call in this unit makes (a
            # base class's ``Node(name, ns, options)`` beside the ``Node(name, options)``
            # its subclass calls): the node's name only where a file of the node calls
            # that constructor (``links.node_rosnames``)
            self.rosname_unbuilt.append(links.unbuilt_name(made_in, name))
        elif self.rosname is None or links.is_unbuilt_name(self.rosname):
            self.rosname = name

    def _emit(self, spec: api.RosFunction, call: Cursor, args: list[Cursor],
              cls: Cursor | None, conditions: tuple[Condition, ...], scope: Scope,
              at: Cursor | None = None, at_scope: Scope | None = None) -> None:
        """Emit ``call`` of ``spec`` (``_emit_one``), once per constructor when its name
        or handle reads a member the class's constructors initialise differently
        (``CallSites.member``): each made only where a file of the node calls that
        constructor (``made_in``; a default constructor also where none of the others
        is called, as a loader makes the class), or each kept when this file constructs
        the class by several."""
        if spec.kind == "declare" and self.ros2 and spec.name_arg < len(args):
            conditions = self.reader.declared_anyway(conditions, args[spec.name_arg])
        sites = self.sites
        if sites is None or self._made_by is not None or sites.forks is not None:
            self._emit_one(spec, call, args, cls, conditions, scope, at, at_scope)
            return
        first = len(self.calls)
        sites.forks = []
        try:
            self._emit_one(spec, call, args, cls, conditions, scope, at, at_scope)
            fork = sites.forks[0] if sites.forks else None
        finally:
            sites.forks = None
        if fork is None:
            return
        made = [None if fork.local else constructed_by(c) for _, c in fork.options]
        for emitted in self.calls[first:]:
            emitted.made_in = emitted.made_in or made[0]
        for (_, constructor), made_in in zip(fork.options[1:], made[1:], strict=True):
            sites.choice = (fork.field, place_of(constructor))
            self._made_by = made_in
            try:
                self._emit_one(spec, call, args, cls, conditions, scope, at, at_scope)
            finally:
                sites.choice = self._made_by = None

    def _name_choice(self, expr: Cursor | None, scope: Scope
                     ) -> list[tuple[Cursor, Condition]] | None:
        """The two sides of a name chosen by a test this scope does not decide, ``test ?
        "a" : "b"`` (as written, or the value of a local written once), each with its
        condition (``if`` / ``else`` the test, as a statement's), when both are names
        known in full; else None. depthai's ``rectify ? "right/image_rect" :
        "right/image_raw"`` over a local holding a parameter: two publishers the graph
        decides from the parameter, where the name was ``?``."""
        node = _constructed_from(expr) if expr is not None else None
        for _depth in range(MAX_CHOICE_DEPTH):
            if node is None or node.kind == CursorKind.CONDITIONAL_OPERATOR:
                break
            decl = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
            if decl is None or decl.kind != CursorKind.VAR_DECL:
                return None
            value = scope.variable(decl)
            node = _constructed_from(value) if value is not None else None
        if node is None or node.kind != CursorKind.CONDITIONAL_OPERATOR or (
            expr is None or _known(scope.string(expr))
        ):
            return None
        children = [c for c in node.get_children() if c.kind.is_expression()]
        if len(children) != 3:
            return None
        test, yes, no = children
        if not (_known(scope.string(yes)) and _known(scope.string(no))):
            return None
        return [(yes, self.reader.choice(node, "if", test)),
                (no, self.reader.choice(node, "else", test))]

    def _inner_choice(self, expr: Cursor | None, scope: Scope
                      ) -> tuple[tuple[str, int], list[tuple[bool, Condition]]] | None:
        """A name made of a value chosen by a test this scope does not decide, with
        other text: ``prefix + "joint_states"`` where ``prefix`` is a local written once
        with ``use_local_topics ? "~/" : ""`` (ros2_controllers' joint_state_broadcaster,
        whose ``/joint_states`` was ``?joint_states``). The one ``?:`` the name's value
        holds (through locals written once, ``MAX_CHOICE_DEPTH`` deep), with each side
        (true: its first) under its condition, when the name is known in full with
        either side; else None."""
        if expr is None or _known(scope.string(expr)):
            return None
        found: list[Cursor] = []
        stack = [(expr, 0)]
        seen = 0
        while stack and seen < MAX_CHOICE_NODES:
            node, depth = stack.pop()
            seen += 1
            node = strip(node)
            if node.kind == CursorKind.CONDITIONAL_OPERATOR:
                if place_of(node) not in scope.chosen:
                    found.append(node)
                continue
            if node.kind == CursorKind.DECL_REF_EXPR:
                decl = node.referenced
                value = scope.variable(decl) if decl is not None and (
                    decl.kind == CursorKind.VAR_DECL) else None
                if value is not None and depth < MAX_CHOICE_DEPTH:
                    stack.append((value, depth + 1))
                continue
            stack.extend((child, depth) for child in node.get_children()
                         if child.kind.is_expression())
        if len(found) != 1:
            return None
        node = found[0]
        children = [c for c in node.get_children() if c.kind.is_expression()]
        if len(children) != 3:
            return None
        place = place_of(node)
        for truth in (True, False):
            scope.chosen[place] = truth
            try:
                known = _known(scope.string(expr))
            finally:
                del scope.chosen[place]
            if not known:
                return None
        return place, [(True, self.reader.choice(node, "if", children[0])),
                       (False, self.reader.choice(node, "else", children[0]))]

    def _emit_counted(self, spec: api.RosFunction, call: Cursor, args: list[Cursor],
                      cls: Cursor | None, conditions: tuple[Condition, ...], scope: Scope,
                      at: Cursor | None, at_scope: Scope | None, name: Cursor) -> bool:
        """Emit ``call``, made in a counting loop up to a parameter's value (``for (int
        i = 0; i < waypoint_num_; i++)`` after ``nh.param("fsm/waypoint_num",
        waypoint_num_, -1)``) with a name whose one unknown run is the loop's variable
        (``"fsm/waypoint" + to_string(i) + "_x"``), named by each turn of the loop
        (``PrimitiveCall.name_each`` ``COUNTED``, the bound's parameter its
        ``name_param``; the graph fills the turns from the value the configuration gives
        it); the loop is then the condition of each turn (``EACH_STATEMENT``). False
        when no loop of ``conditions`` is such a loop for this name."""
        for loop in conditions:
            found = self.reader.counted_to.get(loop)
            if found is None:
                continue
            variable, start, inclusive, bound = found
            if variable in scope.bound or not self._named_by_turn(name, scope, variable, start):
                continue
            shift = self._turn_shift(name, scope, variable, start)
            source = self._parameter_source(bound, scope, 0, value=True)
            param = _held_name(source)
            if shift is None or param is None:
                continue
            each = dataclasses.replace(loop, statement=EACH_STATEMENT)
            made = len(self.calls)
            self._emit_one(spec, call, args, cls,
                           tuple(each if c is loop else c for c in conditions), scope,
                           at, at_scope)
            mark = counted_mark(start, inclusive, shift)
            for index in range(made, len(self.calls)):
                done = self.calls[index]
                if done.name.count("?") == 1 and done.name_param is None:
                    # (a handle's namespace another file passes, and the parameter read
                    # on it, are filled together: ``links.resolve``)
                    self.calls[index] = dataclasses.replace(done, name_param=param,
                                                            name_each=mark)
            return True
        return False

    @staticmethod
    def _turn_shift(name: Cursor, scope: Scope, key: tuple[str, int], start: int) -> int | None:
        """What the one unknown run of the name ``name`` holds is the counting loop's
        variable ``key`` plus this, as decimal text (0 for ``to_string(i)``, 1 for
        denso_robot_control's ``ss << "joint_" << i + 1``), read from the names of the
        turns ``start`` and the next; None when the name is not known in full for a
        turn, or its run is no such value (``2 * i``, ``names[i]``)."""
        parts = scope.string(name)
        if sum(part is None for part in parts) != 1 or not _known(
                tuple(part for part in parts if part is not None)):
            return None
        index = parts.index(None)
        head = "".join(part or "" for part in parts[:index])
        tail = "".join(part or "" for part in parts[index + 1:])
        held: list[int] = []
        for turn in (start, start + 1):
            scope.bound[key] = turn
            try:
                turned = scope.string(name)
            finally:
                del scope.bound[key]
            if not _known(turned):
                return None
            text = "".join(part or "" for part in turned)
            run = text[len(head):len(text) - len(tail)]
            if not (text.startswith(head) and text.endswith(tail)
                    and len(text) >= len(head) + len(tail)
                    and re.fullmatch(r"-?\d+", run)):
                return None
            held.append(int(run) - turn)
        return held[0] if held[0] == held[1] else None

    @staticmethod
    def _named_by_turn(name: Cursor, scope: Scope, key: tuple[str, int], turn: int) -> bool:
        """Whether the name ``name`` holds, not known in full, is another with a
        counting loop's variable ``key`` at ``turn``: it is made of that variable
        (VINS-Mono's ``"path_" + to_string(i)``)."""
        before = scope.string(name)
        if _known(before):
            return False
        scope.bound[key] = turn
        try:
            return scope.string(name) != before
        finally:
            del scope.bound[key]

    def _emit_one(self, spec: api.RosFunction, call: Cursor, args: list[Cursor],
                  cls: Cursor | None, conditions: tuple[Condition, ...], scope: Scope,
                  at: Cursor | None = None, at_scope: Scope | None = None) -> None:
        """Emit ``call`` of ``spec``; ``at`` is the call that makes it, when another one
        (``nh.subscribe(ops)`` for ``ops.init<M>(...)``) gives its location and handle."""
        if spec.standin_only and not from_standin(
                cls if cls is not None and cls.kind != CursorKind.NO_DECL_FOUND
                else (at or call).referenced):
            return  # the class of that name is not our stand-in's: its code is read
        if spec.value_only:
            return  # a value a name may take (``_parameter``), no call
        given = spec
        if self.ros2 and spec.ros2 is not None:
            spec = spec.ros2  # the call as ROS 2's library makes it
        if spec.not_looked_up and self._looked_up(at or call):
            return
        shift, handle_arg = 0, spec.handle_arg
        if spec.optional_handle and args and is_handle(args[0]):
            shift, handle_arg = 1, 0
        # roscpp's ``ros::param::search(ns, key, result)``: the key searched from ``ns``
        # (kuka-lwr's controllers: ``search(n.getNamespace(), "robot_description", r)``)
        search_from = args[0] if spec.search_from_node and len(args) == 3 else None
        if search_from is not None:
            shift = 1

        def arg(index: int | None) -> Cursor | None:
            if index is None or index + shift >= len(args):
                return None
            return args[index + shift]

        counted = [c for c in conditions if c in self.reader.counted]
        if counted:  # a counting loop over literal bounds runs its body: no condition
            name = arg(spec.name_arg) if spec.fixed_name is None else None
            for loop in counted:
                variable, turns = self.reader.counted[loop]
                if name is None or not turns or variable in scope.bound or not (
                        self._named_by_turn(name, scope, variable, turns[0])):
                    continue
                rest = tuple(c for c in conditions if c is not loop)
                for turn in turns:  # a name made of its variable: one call per turn
                    scope.bound[variable] = turn
                    try:
                        self._emit_one(given, call, args, cls, rest, scope, at, at_scope)
                    finally:
                        del scope.bound[variable]
                return
            conditions = tuple(c for c in conditions if c not in self.reader.counted)
        named = arg(spec.name_arg) if spec.fixed_name is None else None
        if named is not None and any(c in self.reader.counted_to for c in conditions) and (
                self._emit_counted(given, call, args, cls, conditions, scope, at, at_scope,
                                   named)):
            return
        choice = self._name_choice(arg(spec.name_arg), scope) if (
            spec.fixed_name is None) else None
        if choice is not None:  # one call per side, each under its side of the test
            index = spec.name_arg + shift
            for side, condition in choice:
                self._emit_one(given, call, [*args[:index], side, *args[index + 1:]], cls,
                               (*conditions, condition), scope, at, at_scope)
            return
        inner = self._inner_choice(arg(spec.name_arg), scope) if (
            spec.fixed_name is None) else None
        if inner is None and spec.transport is not None and spec.transport.startswith(
                UNKNOWN_MARK):  # a transport chosen so (fiducials' ``TransportHints(
            # is_compressed ? "compressed" : "raw")``): one call per side, as for a name
            inner = self._inner_choice(self._transport_given(spec, arg, args[shift:]), scope)
        if inner is not None:  # the same, the test's value read once per side
            place, sides = inner
            for truth, condition in sides:
                scope.chosen[place] = truth
                try:
                    self._emit_one(given, call, args, cls, (*conditions, condition), scope,
                                   at, at_scope)
                finally:
                    del scope.chosen[place]
            return

        site = at or call
        callee = callee_of_call(site)
        target = site.referenced
        location = self.where(site if target is not None and (
            target.kind == CursorKind.CONSTRUCTOR) else callee)
        # made on a node the library makes for it, given no node (``RosFunction.own_node``)
        own_node = self.ros2 and spec.own_node and all(
            not is_handle(a) and a.type.get_canonical().kind == TypeKind.BOOL
            for a in args[1:])
        # ROS 1: the same library objects (tf2_ros' and tf's listeners) given no handle
        # subscribe on a ``ros::NodeHandle()`` they make, roscpp's of the process (a
        # nodelet's manager's); given one, on that handle, as it was made (``origin``)
        library_handle = not self.ros2 and spec.own_node
        names: list[tuple[str, NameSource | None]]
        namespace: str | None = None
        elsewhere: list[str] = []  # members read for the name that other files set
        name_expr: Cursor | None = None
        # the string whose value is the namespace's one unknown run (ROS 1)
        unknown_from: tuple[Cursor, Scope] | None = None
        unknown_parts: list[tuple[Cursor, Scope]] = []  # each of its runs' (ROS 1)
        root = False  # made on a ROS 1 controller's root handle (``handles.controller_root``)
        origin: str | None = None  # where that handle was made (``handles.Namespaces.origin``)
        if spec.fixed_name is not None:
            if spec.handle_default is not None:  # relative to the handle given
                handle = next((a for a in args if is_handle(a)), None)
                namespace = spec.handle_default if handle is None else normalise(render(
                    self.namespaces.of(handle, scope)))
                if handle is not None:
                    unknown_from, root = self.namespaces.unknown_from, self.namespaces.root
                    origin = self.namespaces.origin
                    unknown_parts = list(self.namespaces.unknown_parts)
            elif library_handle:
                handle = next((a for a in args if is_handle(a)), None)
                if handle is None:
                    origin = None if in_main(scope) else PROCESS_HANDLE
                else:
                    self.namespaces.of(handle, scope)
                    origin = self.namespaces.origin
            # once per node (and handle): per owner when the file names several nodes,
            # apart on a node the library makes (``own_node``, ROS 1's ``origin``)
            once = self._owner if self._owner in dict(self.node_names) else ""
            key = (spec.kind, join_name(namespace or "", spec.fixed_name), once, own_node,
                   origin if library_handle else None)
            if key in self._fixed:
                return
            self._fixed.add(key)
            names = [(spec.fixed_name, None)]
        else:
            name_expr = arg(spec.name_arg)
            if (spec.name_suffix is not None or spec.name_required) and (
                name_expr is not None and msg_types.param_type(name_expr.type) != "str"
            ):
                # SyncParametersClient(node, qos): no remote, the node; filters'
                # FilterChain::configure(XmlRpcValue&, ns): a chain given, not read
                name_expr = None
            for index in spec.name_candidates:
                if index < len(args) and msg_types.param_type(args[index].type) == "str":
                    name_expr = args[index]
                    break
            if name_expr is None and spec.default_name is None and (
                    spec.name_suffix is None or spec.name_required):
                return
            sites = self.sites
            if sites is not None:
                sites.elsewhere.clear()
            names = [(spec.default_name or "", None)] if name_expr is None else self._names(
                spec, call, name_expr, args, scope)
            elsewhere = list(sites.elsewhere) if sites is not None else []
            if spec.name_prefix is not None:
                names = [(spec.name_prefix + name, source) for name, source in names]
            if spec.search_from_node and len(args) == 2:
                names = [(name if not name or name.startswith(("/", "~", UNKNOWN_MARK))
                          else "~" + name, source) for name, source in names]
            if spec.empty_is_none:
                names = [(name, source) for name, source in names if name]
                if not names:
                    return
            if spec.name_suffix is not None:  # a parameter client: the remote's services
                names = [(_prefixed(name, spec) + spec.name_suffix if spec.suffix_appended
                          else join_name(name or "~", spec.name_suffix), source)
                         for name, source in names]
        if spec.loads == api.PLUGINLIB_CLASS:
            self._class_load(names, conditions, location, site.type, name_expr, scope)
            return
        owner = self._owner
        # node->create_x(...), node = rclcpp::Node::make_shared("x"); a parameter read
        # on it too (``n.get_parameter_or(...)`` of ``rclcpp::Node n("x")``), which
        # takes no namespace from its object
        if spec.on_handle or spec.kind in ("read", "declare", "write"):
            made = handle_node(callee)
            if made is not None:
                owner = made[0]
                if self._owner is not None and (self._owner, owner) not in self.uses:
                    self.uses.append((self._owner, owner))  # the function holds it
                self._node_name(api.RCLCPP_NODE_NAME[made[2]], written_arguments(made[1]),
                                at_scope or scope, owner, made[1])
        if spec.fixed_name is None:
            if spec.on_handle:
                namespace = render(self.namespaces.of_call(site, callee, at_scope or scope))
                unknown_from, root = self.namespaces.unknown_from, self.namespaces.root
                origin = self.namespaces.origin
                unknown_parts = list(self.namespaces.unknown_parts)
            elif handle_arg is not None and handle_arg < len(args):
                namespace = render(self.namespaces.of(args[handle_arg], scope))
                unknown_from, root = self.namespaces.unknown_from, self.namespaces.root
                origin = self.namespaces.origin
                unknown_parts = list(self.namespaces.unknown_parts)
            elif search_from is not None:
                handle = _namespace_holder(search_from)
                if handle is not None:  # ``n.getNamespace()``: as ``n.searchParam(key)``
                    namespace = render(self.namespaces.of(handle, scope))
                    unknown_from, root = self.namespaces.unknown_from, self.namespaces.root
                    origin = self.namespaces.origin
                    unknown_parts = list(self.namespaces.unknown_parts)
                else:
                    namespace = render(scope.string(search_from))
            elif spec.process_names and not self.ros2 and not in_main(scope):
                origin = PROCESS_HANDLE  # this_node's names: a nodelet's manager's
        function = callback(args, None if spec.callback_arg is None
                            else spec.callback_arg + shift)
        ctype = self.types.of_call(spec, call, args, function, cls, scope)
        if ctype is None and function is not None and "callback" in spec.type_from:
            ctype = self._per_construction_type(function, [n for n, _ in names])
        if ctype is None and spec.kind == "read":
            ctype = self._taken_as.get(place_of(call))
        if ctype is None and spec.kind in ("read", "declare") and (
            site.kind == CursorKind.CALL_EXPR and site.spelling in self.wrappers.names
            and _returns_its_parameter_type(site)
        ):
            # a wrapper function template that returns a value of its template parameter
            # (navigation2's ``declare_or_get_parameter<std::string>(node, name)``, which
            # declares by ``rclcpp::ParameterValue{ParameterT{}}.get_type()``): the type
            # its call returns here
            ctype = msg_types.param_type(site.type)
        qos = None
        queue = scope.integer(arg(spec.queue_arg)) if arg(spec.queue_arg) is not None else None
        if self.ros2 and arg(spec.qos_arg) is not None:
            qos = qos_of(arg(spec.qos_arg), scope)
            queue = qos.get("depth") if qos else None
        latch_expr = arg(spec.latch_arg)
        latch = spec.latched or (latch_expr is not None and scope.boolean(latch_expr) is True)
        # a declaration whose default holds another parameter's value keeps it, for the
        # names its node's other files take from this parameter (``cpp._node_result``)
        holds: tuple[str | None, str | None] = (None, None)
        if spec.kind == "declare" and len(names) == 1:
            declared = self._parameter(spec, call, scope)
            if declared is not None and declared[1] is not None:
                self._declared[declared[0]] = (declared[1], declared[2])
                if declared[2] is not None:
                    holds = (declared[1], declared[2])
        has_default, default = self._default(spec, args, scope)
        has_default = has_default or spec.library_default
        # rclcpp's declare_parameter(name, rclcpp::PARAMETER_STRING) leaves a parameter no
        # override sets uninitialised and does not throw (node_parameters.cpp): only a
        # later read that needs the value fails, as with rclpy's declaration of a type
        # (phidgets_drivers: then ``if (get_parameter("server_name", server_name_))``)
        typed_only = spec.kind == "declare" and spec.default_arg is not None and (
            spec.default_arg < len(args)
        ) and msg_types.parameter_type_constant(args[spec.default_arg]) is not None
        # so does Foxy's declare_parameter(name), whose default is an uninitialised
        # ParameterValue (Galactic deprecated it, Humble removed it; limo_ros2's
        # limo_base declares so, then reads with get_parameter_or and a default), but
        # not declare_parameter<T>(name), which returns the value
        typed_only = typed_only or (
            spec.kind == "declare" and spec.default_arg is not None and self.ros2
            and spec.default_arg >= len(args) and not spec.per_element
            and not _written_template(call) and spec.fixed_type is None)
        if spec.kind in ("read", "declare"):
            default = _converted(default, ctype)
        program_arg = program_argument(arg(spec.type_arg), scope) if (
            spec.kind == "write") else None
        status = _status_read(spec, site, len(args) - shift)
        if status is not None and site.kind == CursorKind.CALL_EXPR and (
            self._gives_value(site)
        ):
            status = None  # a wrapper that returns the value (ublox's getRosBoolean)
        transport = spec.transport
        chosen: dict[str, Any] = {}
        if transport is not None and transport.startswith(UNKNOWN_MARK):
            transport, chosen = self._transport(spec, transport, arg, args[shift:], scope)
        base = arg(spec.name_arg)
        if transport is not None and self.ros2 and base is not None and scope.resolved(base):
            transport += "="  # a base the code resolved and remapped (image_pipeline's)
        # ros::names::resolve("imu") + "/data": roscpp resolves and remaps "imu" in the
        # node's namespace, whatever the handle's, then the rest within it, as it does a
        # handle's namespace (graph.build._handle_name): the prefix is the call's
        prefix = scope.names_prefix(base) if not self.ros2 and base is not None else None
        if transport is not None and transport.endswith("/") and prefix is not None:
            # a base roscpp resolved and remapped for the code (republish's
            # ``nh.resolveName("in")``): the transport's topic is named below it as it is
            transport = transport[:-1]
        # the handle's namespace holds a parameter's value (pointgrey's stereo nodelet:
        # ``ros::NodeHandle lnh(nh, firstcam)``, ``firstcam`` read from
        # ``first_namespace``, default "left"): the graph puts it in the place of the
        # ``?`` of each name given on that handle, as for a name that holds one
        one_unknown = unknown_from is not None and not self.ros2 and (
            namespace is not None and namespace.count("?") == 1)
        held = self._parameter_source(unknown_from[0], unknown_from[1], 0) if (
            one_unknown and unknown_from is not None) else None
        # ... or each element of a list parameter in turn (costmap_2d's ``ros::NodeHandle
        # target_layer(nh, plugin_name)``, ``plugin_name`` each ``plugins[i]["name"]``)
        each = self._each_element(unknown_from[0], unknown_from[1]) if (
            one_unknown and unknown_from is not None and held is None) else None
        held_source = (*held, None, None, None) if held is not None else (
            (each[0], None, None, each[2], each[1], None) if each is not None
            and each[0] is not None else None)
        # ... or, a Gazebo plugin's handle whose namespace has several unknown runs, each
        # a child element of its SDF: all of them, in order (hector's sonar plugin serves
        # its dynamic_reconfigure on ``ros::NodeHandle(*node_handle_, topic_)``)
        sdf_parts = self._sdf_parts(namespace, unknown_parts) if (
            held is None and not self.ros2) else None
        for written, source in names:
            if spec.resolved and "?" in written:
                continue  # a name resolved for the code that is not known: nothing to tell
            # getName() is "~": only as the start of a name is it the node's own name
            name = _private(written[:1] + written[1:].replace("~", "?"))
            handle_namespace = None
            if prefix is not None and (written == prefix or written.startswith(prefix + "/")):
                handle_namespace = prefix
            elif namespace is not None and self.ros2 and name.startswith(UNKNOWN_MARK):
                pass  # on a sub-node: rclcpp extends a relative name only, and a name
                # that begins unknown may be global (``rosname.resolve``): as it is
            elif namespace is not None:
                name = join_name(namespace, name)
                if namespace and not self.ros2 and not _private(written).startswith(
                        ("/", "~")):
                    handle_namespace = namespace
            if source is None and held_source is not None and (
                handle_namespace == namespace and name.count("?") == 1
            ):
                source = held_source
            if isinstance(written, EachName):
                # one element of a constant list: the loop over it runs that turn
                conditions = tuple(c for c in conditions if not (
                    c.statement in ("for", "while")
                    and (c.location.line, c.location.column) == written.at))
            if source is not None and source[4] is not None:
                # the loop over the list: one call per element, each made by that
                # element's turn (the graph drops it where it knows the elements)
                conditions = tuple(dataclasses.replace(c, statement=EACH_STATEMENT) if (
                    c.statement in ("for", "while")
                    and (c.location.line, c.location.column) == source[4]
                ) else c for c in conditions)
            # a Gazebo plugin's handle in the namespace its SDF gives, and a name its SDF
            # gives too: both filled from the description (robot.attach)
            namespace_param = held[0] if (
                held is not None and source is not None and handle_namespace == namespace
                and held[0].startswith(SDF_ELEMENT) and name.count("?") == 2) else (
                sdf_parts if handle_namespace == namespace else None)
            made_in = self._made_in(name, handle_namespace)
            name_member = self._run_member(name_expr, scope, name, placed=True) if (
                source is None and spec.fixed_name is None
                and not isinstance(written, BelowName)) else None
            self.calls.append(PrimitiveCall(
                kind=spec.kind, name=name, type=ctype, queue_size=queue, qos=qos,
                latch=latch, callback=callback_name(function),
                conditions=(*conditions, *written.conditions) if isinstance(
                    written, ChoiceName) else conditions,
                location=location,
                name_param=source[0] if source else None,
                name_default=source[1] if source else holds[0],
                default_param=source[2] if source else holds[1],
                name_each=source[3] if source else None,
                name_more=source[5] if source else None,
                has_default=has_default or isinstance(written, PrefixName),
                default=default, tested=typed_only, under=isinstance(written, PrefixName),
                declared_only=self.ros2 and spec.kind == "read" and (
                    isinstance(written, PrefixName) or (written == "~" and (
                        call.spelling == "list_parameters" or call.spelling in _PREFIXED))),
                searched=spec.searched or isinstance(written, SearchedName) or (
                    isinstance(written, ChoiceName) and written.searched),
                keys_only=not self.ros2 and spec.kind == "read" and (spec.presence or keys_only(
                    arg(spec.out_arg), scope, self.owned)),
                handle_namespace=handle_namespace,
                root_handle=root and not self.ros2 and not _private(written).startswith(
                    ("/", "~")),
                handle_origin=PROCESS_HANDLE if own_node else None if self.ros2 else (
                    None if spec.process_names and name.startswith("/") else origin),
                deletes=spec.deletes, node_name=owner, transport=transport, **chosen,
                made_in=made_in, program_arg=program_arg,
                name_arg=written.program_arg if isinstance(written, ArgumentName) and (
                    name.count("?") == 1) else None, name_member=name_member,
                name_self=isinstance(written, SelfName) and name.count("?") == 1,
                name_below=written.base if isinstance(written, BelowName) else None,
                **_option_fields(written, name),
                loads=spec.loads, namespace_param=namespace_param,
                argument=spec.argument, resolved=spec.resolved))
            if status is not None:
                self._status_reads.append((status, self.calls[-1]))
            filled = strip(arg(spec.out_arg)) if spec.kind == "read" and not self.ros2 and (
                arg(spec.out_arg) is not None) else None
            if filled is not None and filled.kind == CursorKind.DECL_REF_EXPR and (
                    filled.referenced is not None
                    and filled.referenced.kind == CursorKind.VAR_DECL
                    and is_struct_value(filled.referenced.type)):
                self._struct_reads.setdefault(place_of(filled.referenced), []).append(name)
            member = self._member(spec, call, shift) if len(names) == 1 else None
            if member is not None:
                self._stored.append((self.calls[-1], member, key_of(call)))
            if "?" in name and PLACEHOLDER not in name and elsewhere:
                # a member whose class's constructors this unit does not define
                self.diagnostics.append(diag.make(
                    "CPP_NAME_MEMBER_ELSEWHERE", location, kind=spec.kind, name=name,
                    member=", ".join(elsewhere)))
            elif "?" in name and PLACEHOLDER not in name:
                self.diagnostics.append(diag.make(
                    "CPP_DYNAMIC_NAME", location, kind=spec.kind, name=name))
            for kind, sibling, stype in spec.siblings:
                if not sibling:  # the same name the other way (a bond's topic)
                    full = name
                elif spec.name_suffix is not None:  # beside it, in the remote node's name
                    full = name.removesuffix(spec.name_suffix) + sibling
                elif kind in ("declare", "read") and name.startswith("/"):
                    full = sibling  # the node's own parameter beside a global topic
                else:
                    full = sibling if sibling.startswith("/") else join_name(
                        _name_namespace(name), sibling)
                # beside a server on a handle given (dynamic_reconfigure's topics): in the
                # same handle's namespace, filled from the call sites as the server is
                # and a camera's camera_info, in the image topic's namespace, on its handle
                camera = stype == CAMERA_INFO and bool(spec.transport)
                # a name beside the call's (``name_suffix``) is made from it, its handle's
                # namespace too: on that handle, whose namespace the call sites may give
                # (joint_limits_interface's ``getJointLimits(joint, nh_, limits)`` on the
                # handle a constructor of another file took: ``<ns>/joint_limits/?/...``)
                on_handle = (spec.handle_default is not None or camera or not sibling or (
                    spec.name_suffix is not None and handle_namespace is not None
                    and name.startswith(handle_namespace))) and not sibling.startswith("/")
                sibling_namespace = handle_namespace if on_handle else None
                self.calls.append(PrimitiveCall(
                    kind=kind, name=full, type=self.types.ros_type(stype), queue_size=queue,
                    latch=latch, conditions=conditions, location=location,
                    # a library's own parameter (diagnostic_updater's period) has its
                    # default there
                    has_default=kind in ("declare", "read"),
                    handle_namespace=sibling_namespace, node_name=owner,
                    root_handle=root and on_handle and not full.startswith(("/", "~")),
                    handle_origin=PROCESS_HANDLE if own_node else (
                        origin if (on_handle or library_handle) and not self.ros2
                        else None),
                    made_in=self._made_in(full, sibling_namespace),
                    camera_of=name if camera else None))
                if held is not None and namespace and sibling_namespace == namespace and (
                    full.count("?") == 1 and full.startswith(namespace + "/")
                ):
                    beside = self.calls[-1]
                    beside.name_param, beside.name_default, beside.default_param = held
                elif sdf_parts is not None and namespace and sibling_namespace == namespace:
                    self.calls[-1].namespace_param = sdf_parts
            if spec.reconfigure:
                self._reconfigured(call, cls, name, handle_namespace, conditions, location,
                                   owner, sdf_parts if sdf_parts is not None and (
                                       handle_namespace == namespace) else None)

    def _class_load(self, names: list[tuple[str, NameSource | None]],
                    conditions: tuple[Condition, ...], location: Location,
                    made: Type, name_expr: Cursor | None = None,
                    scope: Scope | None = None) -> None:
        """pluginlib's ClassLoader creating the class whose lookup name is wholly the value
        of a parameter the node reads (``api.PLUGINLIB_CLASS``): a read of that parameter
        marked ``loads``, with the loader's base class (the class of the pointer ``made``)
        and the default the code gives it; any other name makes none. The parameter's
        name may hold each element of a list parameter in turn, as the read that gives
        the value says (nav2's ``type = get_plugin_type_param(node, ids[i])``, reading
        ``<id>.plugin`` for each id of ``edge_cost_functions``): the read is one per
        element, each loading its class (``plugins.attach.chains``)."""
        # (none where the load is made in a template, on a type its use gives: ros_canopen's
        # ClassAllocator<T>::allocateInstance, named through its callers)
        held = _held_classes(made) if made.kind != TypeKind.DEPENDENT else []
        if _aliased_holder(made, held):
            # a wrapper's own name for what it returns (ros_canopen's GuardedClassLoader<T>
            # ``ClassSharedPtr``, ``std::shared_ptr<T>``): the class it holds
            held = _held_classes(made.get_canonical())
        base = held[0] if held else ""
        loads = f"{api.PLUGINLIB_CLASS}:{base}" if base else api.PLUGINLIB_CLASS
        for written, source in names:
            if source is None and UNKNOWN_MARK not in written and _LOOKUP_NAME.fullmatch(
                    written) and all(c.statement in RUN_ONCE_STATEMENTS for c in conditions):
                # a class written in the code, loaded whenever the code runs: the node
                # runs it (``CPP_PLUGIN_IN_PROCESS``; the graph gives its instances the
                # class's calls, as a nodelet's it runs under its own name)
                self.diagnostics.append(diag.make("CPP_PLUGIN_IN_PROCESS", location,
                                                  cls=written))
                self.loads_in.add(self._owner or "")
                continue
            if written != UNKNOWN_MARK or source is None or source[0] is None or (
                    source[3] is not None or source[5] is not None):
                continue  # a class written in the code, or not known
            each = None
            if UNKNOWN_MARK in source[0]:
                each = self._read_element(source[0], name_expr, scope)
                if each is None:
                    continue
                # the loop over the list is the element's turn, as for that read
                conditions = tuple(dataclasses.replace(c, statement=EACH_STATEMENT) if (
                    c.statement in ("for", "while") and c.location in each[2]
                ) else c for c in conditions)
            # read on a handle a caller passes (jsk_aerial_robot's AerialRobotBase(nh,
            # nh_private) reads on ``nh_``): named on that handle, as the read the code
            # makes there is (``links.resolve``), so the public handle's "" gives
            # ``name``, not the global ``/name``
            self.calls.append(PrimitiveCall(
                kind="read", name=source[0], type="str", conditions=conditions,
                location=location, has_default=source[1] is not None, default=source[1],
                loads=loads, node_name=self._owner,
                handle_namespace=links.placeholder_namespace(source[0]),
                name_param=each[0] if each else None, name_each=each[1] if each else None,
                name_default=each[3] if each else None))

    def _read_element(self, name: str, expr: Cursor | None, scope: Scope | None,
                      ) -> tuple[str, str | None, list[Location], str | None] | None:
        """(the list parameter, ``name_each``, the places of the loops over it, None) of
        the read named ``name`` whose value the variable ``expr`` holds, when that read's
        name holds each element of the list in turn: the read this unit emitted where
        the variable's value is computed; or (the parameter, None, [], its default) when
        that read's name holds another parameter's value (navigation2's route server:
        ``plugin_type_ = get_plugin_type_param(node, graph_file_loader_id)``, a member,
        reads ``<value of graph_file_loader>.plugin``)."""
        if expr is None or scope is None:
            return None
        expr = strip(expr)
        decl = expr.referenced if expr.kind in (
            CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
        value = None
        if decl is not None and decl.kind == CursorKind.VAR_DECL:
            value = scope.variable(decl)
        elif decl is not None and decl.kind == CursorKind.FIELD_DECL:
            value = scope.assigned(decl, expr)
        if value is None:
            return None
        where = self.where(value)
        for call in reversed(self.calls):
            if call.kind == "read" and call.name == name and call.name_param and (
                    call.location.file == where.file and call.location.line == where.line):
                if call.name_each == EACH:
                    return call.name_param, call.name_each, [
                        c.location for c in call.conditions
                        if c.statement == EACH_STATEMENT], None
                if call.name_each is None and not call.name_more and (
                        name.count(UNKNOWN_MARK) == 1):
                    return call.name_param, None, [], call.name_default
        return None

    def _reconfigured(self, call: Cursor, cls: Cursor | None, name: str,
                      namespace: str | None, conditions: tuple[Condition, ...],
                      location: Location, owner: str | None,
                      namespace_param: str | None = None) -> None:
        """The parameters a dynamic_reconfigure server of a synthesised config reads
        when it starts (``reconfigure``): each field of the config, in the namespace of
        the server's own service ``name`` (its handle's), with the .cfg's default; its
        ``namespace_param`` is the server's (a Gazebo plugin's SDF elements)."""
        config = None
        for made in (call.type, cls.type if cls is not None else None):
            canonical = made.get_canonical() if made is not None else None
            if canonical is not None and canonical.get_num_template_arguments() > 0:
                config = canonical.get_template_argument_type(0).get_declaration()
                break
        found = reconfigure.parameters(config)
        if found is None:
            return
        head = _name_namespace(name)
        # a partial config: its parameters named at run time are some under the namespace
        unknown = [("?", None, None)] if found[1] else []
        for parameter, kind, default in [*found[0], *unknown]:
            full = join_name(head, parameter)
            # it writes them back too, the values it read (a parameter not set takes
            # its default): no write is said, which would make every parameter "set by
            # the node" and undecide the conditions over it (amcl's use_map_topic)
            self.calls.append(PrimitiveCall(
                kind="read", name=full, type=kind, conditions=conditions,
                location=location, has_default=True, default=default,
                handle_namespace=namespace, node_name=owner,
                made_in=self._made_in(full, namespace), namespace_param=namespace_param))

    def _made_in(self, name: str, namespace: str | None) -> str | None:
        """The USR of the constructor being walked when ``name`` (or the handle's
        ``namespace``) holds the placeholder of one of its parameters: no call in this
        unit constructs the class, and the call is made only where one does."""
        if self._made_by is not None:
            return self._made_by
        if self._constructor is None:
            # a free function whose calls in this unit all pass it a parameter of one
            # constructor: its calls named after it are made only where that
            # constructor runs (voxblox's ``TsdfServer(nh, nh_private)`` alone calls
            # ``getMeshIntegratorConfigFromRosParam(nh_private)`` in tsdf_server.cc;
            # esdf_server builds its TsdfServer by another constructor)
            return links.constructor_marked(f"{name}{namespace or ''}") if (
                self._free) else None
        usr, mark = self._constructor
        return usr if mark in name or mark in (namespace or "") else None

    def _listener(self, call: Cursor, args: list[Cursor],
                  declared: list[tuple[str, str | None, bool, Any, str | None]],
                  conditions: tuple[Condition, ...], scope: Scope) -> None:
        """A generate_parameter_library ``ParamListener`` built on a node (or its
        parameters interface) and an optional prefix: one declare per parameter of its
        YAML (``parameter_library``), on that node, under the prefix: a ROS 2 node's own
        parameters, whichever handle of it (the node, ``get_node()``, its parameters
        interface) the listener is given. A parameter of a ``__map_`` is one declare
        named by each element of the list parameter it maps over (``name_each``)."""
        target = call.referenced
        location = self.where(call if target is not None and (
            target.kind == CursorKind.CONSTRUCTOR) else callee_of_call(call))
        prefix = next((render(scope.string(a)) for a in args[1:]
                       if msg_types.param_type(a.type) == "str"), "")
        if prefix and not prefix.endswith("."):
            prefix += "."
        for name, kind, has_default, default, listed in declared:
            full = prefix + name
            self.calls.append(PrimitiveCall(
                kind="declare", name=full, type=kind, conditions=conditions,
                location=location, has_default=has_default,
                default=default if has_default else None, node_name=self._owner,
                name_param=prefix + listed if listed is not None else None,
                name_each="." if listed is not None else None))
            if "?" in full:
                self.diagnostics.append(diag.make(
                    "CPP_DYNAMIC_NAME", location, kind="declare", name=full))

    def _names(self, spec: api.RosFunction, call: Cursor, expr: Cursor, args: list[Cursor],
               scope: Scope) -> list[tuple[str, NameSource | None]]:
        """The names a call gives (several for set_parameters({...})), each with the
        parameter its value comes from, if any: (parameter, its default, and ``.`` when
        the name is each element of that list parameter in turn)."""
        if spec.per_element:
            if call.spelling == "list_parameters":
                # each prefix's namespace whole (``PrimitiveCall.under``); "" or no
                # prefix at all (``list_parameters({}, 0)``): every parameter, ``~``
                if "".join(t.spelling for t in expr.get_tokens()) == "{}":
                    return [("~", None)]
                prefixes = [self._name(e, scope)[0] for e in _elements(expr)]
                return [(PrefixName(prefix + ".") if prefix else "~", None)
                        if "?" not in prefix else ("?", None) for prefix in prefixes]
            if call.spelling in _PREFIXED and len(args) >= 2:
                prefix = render(scope.string(expr))
                declared = self._prefix_keys.get(prefix)
                if call.spelling != "declare_parameters" and "?" not in prefix \
                        and not declared:
                    # get_parameters(prefix, out) reads every parameter the node has
                    # under the prefix (``PrimitiveCall.under``), as its parameters
                    # interface's get_parameters_by_prefix does; "": all of them, ``~``
                    return [(PrefixName(prefix + ".") if prefix else "~", None)]
                given = next((i for i, a in enumerate(args) if a == expr), None)
                keys = _map_keys(args[given + 1], scope) if (
                    call.spelling == "declare_parameters" and given is not None
                    and given + 1 < len(args)) else None
                if call.spelling == "declare_parameters":
                    known = self._prefix_keys.get(prefix, [])
                    self._prefix_keys[prefix] = None if keys is None or known is None \
                        else [*known, *keys]
                elif "?" not in prefix:
                    # what the unit declared under the prefix (teleop_twist_joy's
                    # axis_linear.x, .y, .z): a node that declares its parameters has
                    # only those there, whatever the configuration sets beside them
                    keys = declared
                return [((prefix + "." if prefix else "") + key, None)
                        for key in (keys or ["?"])]
            return [self._name(e, scope) for e in _elements(expr, scope=scope)]
        named = self._name(expr, scope)
        if "?" not in named[0] or named[1] is not None:
            return [named]
        constant = self._constant_each(expr, scope, named[0])
        if constant is not None:
            # each element of a constant list the loop walks (navigation2's controller
            # server declares ``default_ids_[i] + ".plugin"`` for its default ids)
            values, at = constant
            return [(EachName(named[0].replace("?", value, 1), at), None)
                    for value in values]
        # a key the writes that may reach the call disagree on, each known: one call
        # per value it may hold, each under its side of the ``if`` that decides it
        # (costmap_2d's searched key, or the fallback if the search finds nothing)
        choices = scope.written_choices(expr)
        if choices is None:
            return self._branch_names(expr, scope) or self._member_names(
                expr, scope) or [named]
        first, side, branch, in_then = choices
        tested = next(iter(branch.get_children()))
        out: list[tuple[str, NameSource | None]] = []
        for parts, statement in ((first, "else" if in_then else "if"),
                                 (side, "if" if in_then else "else")):
            parts = own_name(parts)
            out.append((ChoiceName(render(parts), (self.reader.choice(
                branch, statement, tested),), len(parts) == 1 and isinstance(
                    parts[0], SearchedName)), None))
        return out

    def _member_names(self, expr: Cursor, scope: Scope
                      ) -> list[tuple[str, NameSource | None]] | None:
        """A name made of a member that this function sets in a side of an ``if``
        before, and that holds its first value otherwise (``Scope.member_choices``:
        DOBOT's ``kRobotName``, set only ``if (robotNumber > 1)``): one name per value,
        each under its side of that ``if``. None when not so."""
        found = scope.member_choices(expr)
        if found is None:
            return None
        member, before, side, branch, in_then = found
        tested = next(iter(branch.get_children()))
        out: list[tuple[str, NameSource | None]] = []
        held = place_of(member)
        for value, statement in ((before, "else" if in_then else "if"),
                                 (side, "if" if in_then else "else")):
            scope.fixed[held] = value
            try:
                parts = own_name(scope.string(expr))
            finally:
                del scope.fixed[held]
            out.append((ChoiceName(render(parts), (self.reader.choice(
                branch, statement, tested),), False), None))
        return out if out[0][0] != out[1][0] else None

    def _branch_names(self, expr: Cursor, scope: Scope
                      ) -> list[tuple[str, NameSource | None]] | None:
        """A local name written with a known text in each case of a ``switch`` (each
        side of an ``if`` / ``else`` chain) before the call (``Scope.branch_written``):
        one name per write, under the conditions the walk gives that write's statement
        inside the ``switch`` or ``if`` (ariac2021ws's service chosen by the AGV: four
        clients, each under its ``case``, where the name was ``?``). None when not so
        written, or a value is not known in full."""
        found = scope.branch_written(expr)
        if found is None:
            return None
        statement, writes = found
        names: list[tuple[str, tuple[Condition, ...]]] = []
        for offset, value in writes:
            parts = own_name(scope.string(value))
            if None in parts:
                return None
            conditions = self._conditions_inside(statement, offset)
            if conditions is None:
                return None
            names.append((render(parts), conditions))
        if len({name for name, _ in names}) == 1:
            return [(names[0][0], None)]  # the same text whichever runs
        return [(ChoiceName(name, conditions, False), None) for name, conditions in names]

    def _conditions_inside(self, statement: Cursor, offset: int
                       ) -> tuple[Condition, ...] | None:
        """The conditions the walk gives what starts at ``offset`` inside the control
        statement ``statement``, relative to it (``ConditionReader.branches``)."""
        out: tuple[Condition, ...] = ()
        node = statement
        for _depth in range(MAX_DEPTH):
            if node.extent.start.offset == offset and node is not statement:
                return out
            below = self.reader.below(node, ())
            inside = [(child, extra) for child, extra in below
                      if child.extent.start.offset <= offset <= child.extent.end.offset]
            if not inside:
                return None
            node, extra = inside[-1]  # (``below`` gives them last first)
            out += extra
        return None

    def _name(self, expr: Cursor, scope: Scope) -> tuple[str, NameSource | None]:
        inner = strip(expr)
        named = constructed_name(inner, api.RCLCPP_PARAMETER) or _built_parameter(inner, scope)
        if named is not None:
            return (render(scope.string(named)), None)
        with program_arguments():
            written = scope.string(expr)
        parts = own_name(written)
        name = render(parts)
        argument = argument_of(parts)
        if argument is not None:
            return (ArgumentName(name, argument), None)
        option = option_of(parts)
        if option is not None:
            return (OptionName(name, option), None)
        if own_name_run(written, parts):
            return (SelfName(name), None)
        below = topic_base(parts)
        if below is not None:
            return (BelowName(name, below), None)
        if len(parts) == 1 and isinstance(parts[0], SearchedName):
            return (SearchedName(name), None)  # the key ``searchParam`` found
        if None not in parts:
            return (name, None)
        if name.count("?") != 1:
            return (name, self._first_parameter(expr, scope, name.count("?"))
                    or self._held_source(inner, scope, name))
        # the one unknown part: the whole name, or a run of it that the text around keeps
        # (``"/" + robot_name + "/base_feedback"``; a wrapper's ``before`` and ``after``)
        unknown = [inner] if inner.kind == CursorKind.DECL_REF_EXPR or _subscript(
            inner) is not None or _element_field(inner) is not None else _unknown_operands(
            expr, scope)
        one = strip(unknown[0]) if len(unknown) == 1 else _string_of_variable(inner)
        if one is None and not unknown and inner.kind == CursorKind.CALL_EXPR:
            one = inner  # what a method returns (``layer->getName()``: ``LOADED``)
        each = self._each_element(one, scope) if one is not None else None
        if each is not None:
            # ``for (std::string topic : topics_) create_subscription(topic, ..)`` over a
            # list parameter (create3_sim's hazards_vector_publisher), or a name made of
            # the element (``polygon_name + ".type"``, navigation2's collision monitor;
            # ``ids[i] + ".plugin"`` in a loop counting ``i`` up to ``ids.size()``, its
            # controller server): one call per element of the value the configuration
            # gives it, in the place of the ``?`` (graph.element_calls); or each word of
            # a string parameter (``while (ss >> source)``, ``EACH_WORD``)
            listed, at, mark = each
            return (name, (listed, None, None, mark, at, None) if (
                listed is not None or mark.startswith(LOADED)) else None)
        searched = self._searched_key_source(inner, scope)
        if searched is not None:
            # the name ``searchParam(key, name)`` found for a key a parameter holds
            # (arm_kinematics' ``nh.param("urdf_xml", urdf_xml, ...)`` then
            # ``searchParam(urdf_xml, full)`` and ``getParam(full, ...)``): the read of
            # the parameter searched for, named as that parameter's value is
            return (SearchedName(name), (*searched, None, None, None))
        # a parameter's value: the graph puts it in the place of the ``?``
        source = self._parameter_source(expr, scope, 0)
        if source is None and len(unknown) == 1 and unknown[0] is not inner:
            source = self._parameter_source(unknown[0], scope, 0)
        if source is None and inner.kind == CursorKind.DECL_REF_EXPR:
            # a local that holds a parameter's value with text around it (OpenMower's
            # ``std::string target_topic = topic + "/converted";``): that parameter, as
            # when the call writes the same text
            held = scope.variable(inner.referenced) if inner.referenced is not None and (
                inner.referenced.kind == CursorKind.VAR_DECL) else None
            operands = _unknown_operands(held, scope) if held is not None else []
            if len(operands) == 1:
                source = self._parameter_source(operands[0], scope, 0)
        if source is None and len(unknown) > 1:
            # several parameters' values joined in the one ``?`` (doosan's ``"/" + name +
            # model + "/stop"``): each, the graph joins them where all are set
            return (name, self._first_parameter(expr, scope, 1))
        if source is None:
            return (name, self._held_source(inner, scope, name))
        return (name, (*source, None, None, None))

    def _held_source(self, inner: Cursor, scope: Scope, name: str) -> NameSource | None:
        """The parameters that name a call whose name is a variable or member holding a
        text made around their values (a local, or a member this body or its class's
        constructor assigns: pddl_problem_generator.cpp builds ``"/" << knowledge_base <<
        "/domain/name"`` in a string stream in its constructor, keeps it in a member and
        names a client with it in another method), read where that text is made, when
        it renders as the call's name; else None."""
        decl = inner.referenced if inner.kind in (
            CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
        if decl is None or self._held_depth >= _MAX_HELD:
            return None
        held: tuple[Cursor, Scope] | None = None
        if decl.kind == CursorKind.VAR_DECL:
            value = scope.variable(decl)
            held = (value, scope) if value is not None else None
        elif decl.kind == CursorKind.FIELD_DECL:
            value = scope.assigned(decl, inner) if inner.kind == CursorKind.MEMBER_REF_EXPR \
                else None
            held = (value, scope) if value is not None else scope.field(decl)
        if held is None:
            return None
        self._held_depth += 1
        try:
            made, source = self._name(held[0], held[1])
        finally:
            self._held_depth -= 1
        return source if source is not None and str(made) == str(name) and not isinstance(
            made, (ArgumentName, OptionName, SelfName, BelowName, SearchedName)) else None

    def _constant_each(self, expr: Cursor, scope: Scope, name: str
                       ) -> tuple[list[str], tuple[int, int]] | None:
        """The values of ``name``'s one ``?`` and the place of the loop, when it is each
        element in turn of a constant list of strings written here (a ``const`` member
        or variable, or a constant array, initialised with a braced list of texts all
        known, none empty) that a loop of this body walks (``_element_loop``)."""
        if name.count("?") != 1 or isinstance(name, (ArgumentName, SelfName, BelowName)):
            return None
        one = _unknown_operand(expr, scope)
        if one is None:
            return None
        made = written_arguments(one) if one.kind == CursorKind.CALL_EXPR and (
            one.referenced is not None and one.referenced.kind == CursorKind.CONSTRUCTOR
        ) else []
        if len(made) == 1:
            one = strip(made[0])  # ``std::string(name)``
        walk, over, mark = _element_loop(one, scope)
        if walk is None or over is None or mark != EACH:
            return None
        values = self._constant_list(over, scope, 0)
        return None if values is None else (
            list(values), (walk.location.line, walk.location.column))

    def _constant_list(self, expr: Cursor, scope: Scope, depth: int
                       ) -> tuple[str, ...] | None:
        """The texts of a list initialised with a braced list of known, non-empty texts
        and never changed: a ``const`` member or variable, a constant array, a local
        written once, or a function's parameter every call of this file passes one such
        list (Autoware's ADAPI planning node hands its ``factor_topics`` to
        ``init_factors``, which subscribes to each)."""
        held = strip(expr)
        decl = held.referenced if held.kind in (
            CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
        if decl is None:
            return None
        if decl.kind == CursorKind.PARM_DECL:
            if depth >= 4 or scope.sites is None or not scope.is_parameter(decl):
                return None
            return scope.sites.agreed(
                decl, lambda arg, at: self._constant_list(arg, at, depth + 1), None)
        if decl.kind not in (CursorKind.VAR_DECL, CursorKind.FIELD_DECL):
            return None
        value: Cursor | None = None
        if decl.kind == CursorKind.FIELD_DECL and not decl.type.is_const_qualified() and (
            not const_array(decl)
        ):
            # a member the constructors initialise alike and nothing here changes
            # (navigation2's smoother server: ``default_ids_{"simple_smoother"}``)
            held_member = self._unchanged_member(decl)
            if held_member is None:
                return None
            value, scope = held_member
        elif not decl.type.is_const_qualified() and not const_array(decl) and (
            not _read_only(decl, scope)
        ):
            return None
        value = scope.variable(decl) if value is None else value
        items = _elements(value) if value is not None else []
        if not items or len(items) > _MAX_CONSTANT_ELEMENTS or (
                len(items) == 1 and strip(items[0]) == strip(value)):
            return None
        values = tuple(render(scope.string(item)) for item in items)
        if any(not v or "?" in v or PLACEHOLDER in v for v in values):
            return None
        return values

    def _unchanged_member(self, field: Cursor) -> tuple[Cursor, Scope] | None:
        """The value, and the scope to read it in, that every constructor of ``field``'s
        class in this unit initialises the member with, alike, when no function of the
        unit writes it or calls a method that changes it (``_CHANGING``); else None."""
        if self.sites is None or self.members is None:
            return None
        options = constructor_values(field, self.source)
        if not options or any(value is None for value, _ in options) or len(
                {value_text(value) for value, _ in options}) != 1:
            return None
        key = key_of(field)
        for function in self.members.naming(field):
            for node in walk_cursors(function):
                for write in writes_of(node, self.source):
                    if write.variable is not None and key_of(write.variable) == key and (
                        write.whole or out_argument(write) or write.at.spelling in _CHANGING
                        or write.at.kind != CursorKind.CALL_EXPR
                    ):
                        return None
        value, constructor = options[0]
        return (value, self.sites.scope(constructor)) if value is not None else None

    def _each_element(self, expr: Cursor, scope: Scope, depth: int = 0
                      ) -> tuple[str | None, tuple[int, int] | None, str] | None:
        """(the list parameter, the place of the loop that walks it, how it gives its
        elements: ``PrimitiveCall.name_each``) when ``expr`` is each element of a list
        (or word of a string) in turn; the parameter None when the list is no
        parameter's, the place None when no loop of this body walks it. The element
        may be a variable holding it (``auto service_name = target + "/get_state"``),
        a function's parameter every call of this file passes it to, or the parameter
        of a lambda a standard algorithm calls with each element of a range
        (raspimouse's lifecycle_node_manager: ``std::all_of(names.begin(),
        names.end(), [&](std::string s) { return change_state(s, ...); })``, ``names``
        the list its main reads from ``components``)."""
        if depth > MAX_DEPTH:
            return None
        expr = strip(expr)
        field = _element_field(expr)
        walk, over, mark = _element_loop(field[0] if field else expr, scope)
        if field is not None:
            mark = field[1] if mark == EACH else ""  # a field of each element in turn
        if walk is not None and over is not None and mark:
            listed = self._parameter_source(over, scope, 0)
            return (listed[0] if listed is not None else None,
                    (walk.location.line, walk.location.column), mark)
        if expr.kind == CursorKind.MEMBER_REF_EXPR and expr.referenced is not None and (
            expr.referenced.kind == CursorKind.FIELD_DECL and scope.sites is not None
        ):
            # a member its class's constructor in this file keeps from its parameter,
            # which each construction passes an element (a ``Polygon(node, name)`` per
            # element of ``polygons``, reading ``name_ + ".points"``)
            held = scope.field(expr.referenced)
            if held is None:
                return None
            value = strip(held[0])
            inner = [c for c in value.get_children() if c.kind.is_expression()]
            if value.kind == CursorKind.CALL_EXPR and value.referenced is not None and (
                    value.referenced.kind == CursorKind.CONSTRUCTOR and len(inner) == 1):
                value = inner[0]  # the string's copy: ``name_(name)``
            return self._each_element(value, held[1], depth + 1)
        loaded = _loaded_element(expr, scope)
        if loaded is not None:
            # what a method returns of each plugin object a loop walks in the container
            # the node keeps them in (``LOADED``: no parameter; the host row says which
            # plugins are kept there)
            return None, (loaded[0].location.line, loaded[0].location.column), loaded[1]
        decl = expr.referenced if expr.kind == CursorKind.DECL_REF_EXPR else None
        if decl is None:
            return None
        if decl.kind == CursorKind.PARM_DECL:
            ranged = scope.algorithm_range(decl)
            if ranged is not None:
                listed = self._parameter_source(ranged[1], scope, 0)
                return (listed[0], None, EACH) if listed is not None else None
            if scope.sites is not None and scope.is_parameter(decl):
                passed = scope.sites.agreed(decl, lambda arg, site: self._each_element(
                    arg, site, depth + 1), None)
                return (passed[0], None, passed[2]) if passed is not None and (
                    passed[0] is not None) else None
            return None
        held = scope.variable(decl)
        if held is None:
            return None
        operands = _unknown_operands(held, scope)
        inner = strip(held)
        if not operands and (inner.kind == CursorKind.DECL_REF_EXPR or _element_field(
                inner) is not None):
            operands = [inner]
        if len(operands) != 1 or None not in scope.string(held) or (
                scope.string(held).count(None) != 1):
            return None
        found = self._each_element(operands[0], scope, depth + 1)
        return found if found is not None and found[0] is not None else None

    def _first_parameter(self, expr: Cursor, scope: Scope, runs: int) -> NameSource | None:
        """A name of several unknown runs whose first is a parameter's value
        (mrpt_map_server's ``pub_mm_topic_ + "/" + layerName + "_gridmap"``): the
        parameter, which the graph puts in the place of the first ``?``, and when every
        other run is a parameter's value too (ros_kortex's ``"/" + robot_name + "/" +
        prefix + ...``), those parameters for the other ``?`` in order (``name_more``).
        A run of several operands, each a parameter's value (``prefix + arm``), is its
        parameters in order, each after the first JOINED to it. None when the first run
        is anything else, or the runs are not the name's ``?``."""
        grouped = _unknown_runs(expr, scope)
        if len(grouped) != runs:
            return None
        first, *rest = [[self._parameter_source(each, scope, 0) for each in run]
                        for run in grouped]
        source = first[0]
        if source is None:
            return None
        # the others: every one a parameter's, or the name keeps only the first, alone
        joined = len(first) > 1
        if joined and not all(s is not None and known_name(s[0]) for s in first[1:]):
            return None
        more = [[s[0], s[1]] + ([JOINED] if i else []) for run in rest
                for i, s in enumerate(run) if s is not None and known_name(s[0])]
        if len(more) != sum(len(run) for run in rest):
            return (*source, None, None, None) if not joined else None
        more = [[s[0], s[1], JOINED] for s in first[1:] if s is not None] + more
        return (*source, None, None, more or None)

    def _name_member(self, expr: Cursor | None) -> str | None:
        """The USR of the member ``expr`` is, when no function of this unit writes it
        (a base class's member that a subclass's constructor in another file sets:
        topic_tools' ``output_topic_``), else None."""
        inner = strip(expr) if expr is not None else None
        field = inner.referenced if inner is not None and inner.kind in (
            CursorKind.MEMBER_REF_EXPR, CursorKind.DECL_REF_EXPR) else None
        if field is None or field.kind != CursorKind.FIELD_DECL or self.members is None or (
            self.members.writes(field) != 0
        ):
            return None
        return field.get_usr() or None

    def _run_member(self, expr: Cursor | None, scope: Scope, name: str,
                    placed: bool = False) -> str | None:
        """The USR of the member that is the one unknown run of ``name`` (the value of
        ``expr``), when no function of this unit writes it (``_name_member``): nav2's
        controller server publishes on ``params_->odom_topic + ...``, a field of a struct
        that its ParameterHandler fills from a parameter in another file. ``placed``: a
        call's own name, where what the callers of this function pass (a handle given to
        the constructor: the handle's namespace) may stand before that run (Weston
        Robot's messengers advertise ``odom_frame_`` on the handle their constructor
        takes; main reads the parameter into ``messenger.odom_frame_``)."""
        if expr is None or name.count("?") != 1 or (PLACEHOLDER in name and not placed):
            return None
        return self._member_of(expr, scope, 0)

    def _member_of(self, expr: Cursor, scope: Scope, depth: int) -> str | None:
        """``_run_member`` of the one unknown operand of ``expr``; a parameter of the
        function: of what every call of this unit passes for it, when all agree (nav2's
        ``OdomSmoother(node, duration, params_->odom_topic)`` subscribes to its
        constructor's ``odom_topic``)."""
        one = _unknown_operand(expr, scope)
        if one is None:
            return None
        decl = one.referenced if one.kind == CursorKind.DECL_REF_EXPR else None
        if decl is not None and decl.kind == CursorKind.PARM_DECL:
            if depth >= 4 or scope.sites is None or not scope.is_parameter(decl):
                return None
            return scope.sites.agreed(
                decl, lambda arg, at: self._member_of(arg, at, depth + 1), None)
        return self._name_member(one)

    def _held_parameters(self, tested: Cursor, scope: Scope) -> tuple[tuple[str, str], ...]:
        """The locals ``tested`` names that hold a parameter's value: each written once,
        by a read (or declaration) of a parameter with a known name; and the calls it
        makes that return a parameter's value (a function of the workspace that returns
        what it reads, ublox's ``getRosBoolean(node_, "nmea.set")``; rclcpp's
        ``node_->get_parameter("x").as_bool()``), each by its text."""
        found: dict[str, str] = {}
        stack = [tested]
        while stack:
            node = stack.pop()
            if node.kind == CursorKind.CALL_EXPR:
                key = place_of(node)
                if key not in self._held_calls:
                    self._held_calls[key] = self._held_call(node, scope)
                parameter = self._held_calls[key]
                text = self.reader.text(node) if parameter is not None else "?"
                if parameter is not None and text != "?":
                    found[text] = parameter
                    continue  # what it reads is not read again
            if node.kind == CursorKind.MEMBER_REF_EXPR:
                # a field of a generate_parameter_library ``Params`` struct (``params_.
                # use_local_topics``): the parameter of that name, which the listener
                # declares on the node
                field = parameter_library.field_parameter(node)
                text = self.reader.text(node) if field is not None else "?"
                if field is not None and text != "?":
                    found[text] = field
                    continue
                member = self._held_member(node, scope)
                text = self.reader.text(node) if member is not None else "?"
                if member is not None and text != "?":
                    found[text] = member
                    continue
            stack.extend(reversed(list(node.get_children())))
            decl = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
            if decl is None or decl.kind != CursorKind.VAR_DECL or decl.spelling in found or (
                decl.semantic_parent is None or decl.semantic_parent.kind not in FUNCTIONS
            ):
                continue
            # a local's one value is its function's: asked once per unit, whichever walk
            # (the function's own, a construction site's) meets the condition
            key = place_of(decl)
            if key not in self._held:
                self._held[key] = _held_name(self._parameter_source(
                    node, scope, 0, value=True))
            parameter = self._held[key]
            if parameter is not None:
                found[decl.spelling] = parameter
        return tuple(sorted(found.items()))

    def _held_member(self, expr: Cursor, scope: Scope) -> str | None:
        """The parameter a member ``expr`` names holds: its one write in the unit's
        functions is a read of that parameter (teleop_twist_joy's ``param<bool>("is_3D",
        pimpl_->is_3D, false)``, then ``if (pimpl_->is_3D)``); None for a member written
        otherwise too (a callback's toggle) or by no read the unit sees. A member of the
        object itself (``use_filter_``, ``this->use_filter_``) is not asked: the graph
        knows it by name from the reads that store it (``PrimitiveCall.variable``)."""
        member = expr.referenced
        if member is None or member.kind != CursorKind.FIELD_DECL or self.members is None:
            return None
        base = next(iter(expr.get_children()), None)
        if base is None or strip(base).kind == CursorKind.CXX_THIS_EXPR:
            return None
        key = place_of(expr)
        if key not in self._held:
            self._held[key] = _held_name(self._parameter_source(
                expr, scope, 0, value=True)) if self.members.writes(member) == 1 else None
        return self._held[key]

    def _held_constants(self, tested: Cursor, scope: Scope
                        ) -> tuple[tuple[str, int | bool], ...]:
        """The constants ``tested`` names, each with its value: a ``const`` variable of
        integer or bool type whose one value is a literal (neonavigation_common's
        ``const int current_level = 1;`` at namespace scope), or a variable of a
        namespace that no source of its package writes after its literal
        (``values.unwritten_global``)."""
        found: dict[str, int | bool] = {}
        for node in tested.walk_preorder():
            decl = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
            if decl is None or decl.kind != CursorKind.VAR_DECL or (
                not decl.type.is_const_qualified() and not unwritten_global(decl)
            ):
                continue
            kind = decl.type.get_canonical().kind
            value: int | bool | None = None
            if kind == TypeKind.BOOL:
                value = scope.boolean(node)
            elif kind in _INTEGRAL:
                value = scope.integer(node)
            if value is not None:
                found[decl.spelling] = value
        return tuple(sorted(found.items()))

    def _held_elements(self, tested: Cursor, scope: Scope
                       ) -> tuple[tuple[str, str, str], ...]:
        """The names ``tested`` uses that hold each element of a list parameter in turn,
        or a field of it (``plugin_type`` of costmap_2d's ``copyParentParameters``, each
        caller passing ``static_cast<std::string>(plugins[i]["type"])``): (name, the
        list parameter, the field)."""
        found: dict[str, tuple[str, str]] = {}
        for node in tested.walk_preorder():
            decl = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
            if decl is None or decl.kind not in (CursorKind.VAR_DECL, CursorKind.PARM_DECL) or (
                decl.spelling in found or msg_types.param_type(node.type) != "str"
            ):
                continue  # (a list's elements that name calls are strings)
            # a local's or parameter's elements are its function's: asked once per unit
            key = place_of(decl)
            if key not in self._held_each:
                each = self._each_element(node, scope)
                # (a list read on a handle another file's caller names: links.resolve
                # fills its placeholders, site by site)
                self._held_each[key] = (each[0], each[2]) if each is not None and (
                    each[0] is not None and (known_name(each[0]) or _on_passed_handle(
                        each[0])) and each[2] != EACH_WORD) else None
                if self._held_each[key] is None and decl.kind == CursorKind.VAR_DECL:
                    self._held_each[key] = self._element_parameter(decl, node, scope)
            held = self._held_each[key]
            if held is not None:
                found[decl.spelling] = held
        return tuple(sorted((name, listed, field) for name, (listed, field) in found.items()))

    def _element_parameter(self, decl: Cursor, use: Cursor, scope: Scope
                           ) -> tuple[str, str] | None:
        """(the list parameter, ``ELEMENT_PARAMETER`` and the parameter's name) for a
        local ``decl`` written once with the value of a parameter named by each element
        of a list parameter in turn, with text around it (navigation2's collision
        monitor: ``const std::string polygon_type = node->declare_or_get_parameter<
        std::string>(polygon_name + ".type")`` for each ``polygon_name`` of
        ``polygons``): the graph decides a condition on the local per element, by the
        parameter that element names (``graph.build._element_conditions``); else None."""
        held = scope.variable(decl)
        call = strip(held) if held is not None else None
        if call is None or call.kind != CursorKind.CALL_EXPR:
            return None
        source = self._parameter_source(use, scope, 0, value=True)
        name = source[0] if source is not None else None
        if name is None or name.count(UNKNOWN_MARK) != 1 or PLACEHOLDER in name or (
                PARAMETER in name):
            return None
        calls = [call]
        children = list(call.get_children())
        if _value_method(call, children):  # ``get_parameter(name).as_string()``
            objects = [c for c in children[0].get_children() if c.kind.is_expression()]
            calls += [strip(o) for o in objects[:1] if strip(o).kind == CursorKind.CALL_EXPR]
        after = name.split(UNKNOWN_MARK, 1)[1]
        for each_call in calls:
            for arg in written_arguments(each_call):
                if msg_types.param_type(arg.type) != "str":
                    continue
                written, each = self._name(arg, scope)
                if each is None or each[3] != EACH or not isinstance(each[0], str) or (
                    not known_name(each[0]) or str(written).count(UNKNOWN_MARK) != 1
                ) or str(written).split(UNKNOWN_MARK, 1)[1] != after:
                    continue
                return each[0], f"{ELEMENT_PARAMETER}{name}"
        return None

    def _typed_accessor(self, call: Cursor) -> None:
        """``get_parameter("x").as_int()``: the read (visited after this call, its
        object) asks for an int; rclcpp throws when the parameter holds another type."""
        inner = method_object(call)
        inner = strip(inner) if inner is not None else None
        if inner is not None and inner.kind == CursorKind.CALL_EXPR and (
                inner.spelling == "get_parameter"):
            self._taken_as[place_of(inner)] = _TAKEN_AS[call.spelling]

    def _held_call(self, call: Cursor, scope: Scope) -> str | None:
        """The parameter whose value ``call`` returns, named as its read is (with the
        namespace of the handle it is given), when its name is known: a call of a
        function of the workspace that returns the value of the parameter it reads or
        declares (``_gives_value``), or an API read or declaration that returns the
        value (``param<T>(name, default)``, ``declare_parameter(name, default)``,
        ``get_parameter(name).as_bool()``); None for any other call (one that returns
        whether the parameter is there: ``getParam(name, v)``)."""
        spec, _ = self._row(call)
        children = list(call.get_children())
        if spec is None and _value_method(call, children):
            objects = [c for c in children[0].get_children() if c.kind.is_expression()]
            inner = strip(objects[0]) if objects else None
            if inner is None or inner.kind != CursorKind.CALL_EXPR:
                return None
            spec, _ = self._row(inner)
            if spec is None or not self._returns_read(spec, inner):
                return None
            source = self._parameter(spec, inner, scope)
            return source[0] if source is not None and known_name(source[0]) else None
        if spec is not None:
            if not self._returns_read(spec, call) or not _scalar(call.type):
                return None
            source = self._parameter(spec, call, scope)
            return source[0] if source is not None and known_name(source[0]) else None
        if call.spelling not in self.wrappers.names:
            return self._returned_parameter(call)
        if not self._gives_value(call):
            return None
        names = set()
        for row, named in self.wrappers.parameter_calls(call, scope):
            source = self._parameter(row, call, named)
            if source is None:
                return None
            names.add(source[0])
        one = names.pop() if len(names) == 1 else None
        return one if one is not None and known_name(one) else None

    def _returned_parameter(self, call: Cursor) -> str | None:
        """The parameter whose value ``call`` of a function of the workspace that is no
        wrapper returns: every ``return`` of its body returns one local of it that
        holds the value of a read of a parameter of known name (neonavigation_common's
        ``int getCompat() { int compat(default_level); ros::NodeHandle("/").param(
        "neonavigation_compatible", compat, compat); return compat; }``); else None."""
        callee = call.referenced
        function = callee.get_definition() if callee is not None else None
        if function is None or function.kind not in FUNCTIONS or from_standin(function):
            return None
        returned: set[tuple[str, int]] = set()
        first: Cursor | None = None
        for statement in _returns(function):
            values = [strip(c) for c in statement.get_children() if c.kind.is_expression()]
            decl = values[0].referenced if len(values) == 1 and (
                values[0].kind == CursorKind.DECL_REF_EXPR) else None
            if decl is None or decl.kind != CursorKind.VAR_DECL or (
                decl.semantic_parent != function
            ):
                return None
            returned.add(place_of(decl))
            first = first or values[0]
        if first is None or len(returned) != 1:
            return None
        source = self._parameter_source(first, self._scope_of(function), 0, value=True)
        return source[0] if source is not None and known_name(source[0]) else None

    def _returns_read(self, spec: api.RosFunction, call: Cursor) -> bool:
        """Whether ``call`` of the API row ``spec`` is a read or declaration that returns
        the parameter's value (or rclcpp's parameter object), not whether it is there."""
        if self.ros2 and spec.ros2 is not None:
            spec = spec.ros2
        if spec.kind not in _PARAM_KINDS or spec.per_element:
            return False
        args = list(call.get_arguments())
        shift = 1 if spec.optional_handle and args and is_handle(args[0]) else 0
        if spec.kind == "read" and spec.out_arg is not None and not (
            len(args) - shift <= spec.out_arg or (
                spec.default_arg is not None and len(args) - shift <= spec.default_arg)
        ):
            return False  # ``getParam(name, v)``, ``param(name, v, d)``: the status
        return not (spec.kind == "read" and spec.out_arg is None and (
            call.type.get_canonical().kind == TypeKind.BOOL and spec.default_arg is None))

    def _gives_value(self, call: Cursor, depth: int = 0) -> bool:
        """Whether ``call`` of functions of the workspace that read or declare a
        parameter (wrappers) returns the parameter's value: each function it may call
        returns, at every ``return``, the value of a read or declaration it makes as a
        wrapper (ublox's ``getRosBoolean``: ``get_parameter(name, ret)``, then ``return
        ret``; a ``bool getBool(nh, n) { bool v = false; nh.param(n, v, false); return
        v; }``). One that returns whether the read found the parameter (``return
        nh.getParam(n, v)``, ``return true``) does not."""
        key = place_of(call)
        known = self._value_calls.get(key)
        if known is not None:
            return known
        called = self.wrappers.called(call)
        answer = bool(called) and depth < MAX_WRAPPED and all(
            self._returns_value(function, wrapper, depth) for wrapper, function in called)
        self._value_calls[key] = answer
        return answer

    def _gives_status(self, call: Cursor, depth: int = 0) -> bool:
        """Whether ``call`` of functions of the workspace may return something else than
        a parameter's value: a function it may call returns a ``true`` / ``false``
        literal, or what a read returns about the parameter being there (``return
        nh.getParam(n, v)``), or calls such a function in a ``return``."""
        key = place_of(call)
        known = self._status_calls.get(key)
        if known is not None:
            return known
        self._status_calls[key] = False  # (a recursion)
        answer = False
        for _, function in self.wrappers.called(call) if depth < MAX_WRAPPED else ():
            for statement in _returns(function):
                values = [strip(c) for c in statement.get_children() if c.kind.is_expression()]
                if not values or values[0].kind != CursorKind.CALL_EXPR:
                    answer = answer or (bool(values) and values[0].kind == (
                        CursorKind.CXX_BOOL_LITERAL_EXPR))
                    continue
                spec, _ = self._row(values[0])
                answer = answer or (not self._returns_read(spec, values[0]) if spec is not None
                                    else self._gives_status(values[0], depth + 1))
        self._status_calls[key] = answer
        return answer

    def _returns_value(self, function: Cursor, wrapper: tuple[str, int], depth: int) -> bool:
        scope = self._scope_of(function)
        returns = _returns(function)
        if not returns:
            return False
        for statement in returns:
            values = [c for c in statement.get_children() if c.kind.is_expression()]
            if len(values) != 1 or not self._read_value(values[0], wrapper, scope, depth):
                return False
        return True

    def _read_value(self, expr: Cursor, wrapper: tuple[str, int], scope: Scope,
                    depth: int) -> bool:
        """Whether ``expr`` in the function ``wrapper`` is the value of a read or
        declaration that the function makes as a wrapper (its name from its
        parameters): the call itself, a typed value of it (``.as_bool()``), or a local
        written once that it read into (its out argument) or was initialised by."""
        expr = strip(expr)
        if expr.kind == CursorKind.DECL_REF_EXPR:
            decl = expr.referenced
            if decl is None or decl.kind != CursorKind.VAR_DECL:
                return False
            # its writes: its initialiser, and the one call it is passed to by reference
            # (None), which must be the read; nothing else
            writes = scope.writes.get(place_of(decl), [])
            start, end = decl.extent.start.offset, decl.extent.end.offset
            passed = scope.passed_to(decl)
            if sum(w is None for w in writes) != (passed is not None) or any(
                w is not None and not start <= w.extent.start.offset <= end for w in writes
            ):
                return False
            if passed is not None:
                call, index = passed
                spec, _ = self._row(call)
                if spec is not None and self.ros2 and spec.ros2 is not None:
                    spec = spec.ros2
                return spec is not None and spec.kind in _PARAM_KINDS and (
                    spec.out_arg == index) and self.wrappers.inner_of(call) == wrapper
            return len(writes) == 1 and writes[0] is not None and self._read_value(
                writes[0], wrapper, scope, depth)
        if expr.kind != CursorKind.CALL_EXPR:
            return False
        children = list(expr.get_children())
        if _value_method(expr, children):
            objects = [c for c in children[0].get_children() if c.kind.is_expression()]
            return bool(objects) and self._read_value(objects[0], wrapper, scope, depth)
        if self.wrappers.inner_of(expr) != wrapper:
            return False
        spec, _ = self._row(expr)
        if spec is not None:
            return self._returns_read(spec, expr)
        return self._gives_value(expr, depth + 1)

    def _struct_path(self, expr: Cursor, scope: Scope, depth: int = 0
                     ) -> tuple[str | None, ...] | None:
        """The parameter a ROS 1 ``XmlRpcValue`` holds, as the parts of its name (None:
        an unknown run): the local variable a read fills (that read's name), a member of
        a struct it holds (``i->second``: ``name/?``), a member by key (``v[key]``:
        ``name/key``), a function's parameter (what its calls pass,
        ``CallSites.agreed``: a placeholder when they are in other files, which
        ``links`` fills from ``argument_facts``). None: no parameter's value."""
        if depth > MAX_DEPTH:
            return None
        inner = strip(expr)
        found = _subscript(inner)
        if found is not None:  # a member by key (a list's element is the list's value)
            base = self._struct_path(found[0], scope, depth + 1) if _textual(
                found[1]) else None
            return None if base is None else (*base, "/", *scope.string(found[1]))
        over = struct_member_of(inner, scope)
        if over is not None:
            base = self._struct_path(over, scope, depth + 1)
            return None if base is None else (*base, "/", None)
        decl = inner if inner.kind == CursorKind.PARM_DECL else (
            inner.referenced if inner.kind == CursorKind.DECL_REF_EXPR else None)
        if decl is not None and decl.kind == CursorKind.VAR_DECL:
            names = set(self._struct_reads.get(place_of(decl), ()))
            return (names.pop(),) if len(names) == 1 else None
        if decl is not None and decl.kind == CursorKind.PARM_DECL and (
                scope.sites is not None and is_struct_value(decl.type)):
            unknown: tuple[str | None, ...] = (None,)
            value = scope.sites.agreed(decl, lambda arg, site: (None if _local(
                arg) else self._struct_path(arg, site, depth + 1)) or unknown, unknown)
            return value if isinstance(value, tuple) and value != (None,) else None
        return None

    def _struct_text(self, expr: Cursor, scope: Scope) -> str | None:
        """``_struct_path`` as a fact's value (``links.argument_facts``)."""
        if _local(expr):
            return None  # a struct read whole (its own read reads all of it)
        path = self._struct_path(expr, scope) if is_struct_value(expr.type) else None
        return render(path) if path is not None and path[0] is not None else None

    def _struct_read(self, call: Cursor, conditions: tuple[Condition, ...],
                     scope: Scope) -> None:
        """A read of one member, by key, of an ``XmlRpcValue`` struct that is a member of
        a struct parameter read whole (``i->second[key]``) or a function's parameter
        (``config_node[key]``, given such a member): its own read (the read of the whole
        struct reads the keys alone: ``keys_only``). A member of a local variable a read
        fills is read by that read."""
        found = _subscript(call)
        if found is None or not is_struct_value(strip(found[0]).type) or not _textual(
                found[1]):
            return
        base = strip(found[0])
        while (below := _subscript(base)) is not None:
            base = strip(below[0])
        if base.kind == CursorKind.DECL_REF_EXPR and base.referenced is not None and (
                base.referenced.kind == CursorKind.VAR_DECL):
            return
        self._struct_emit(call, conditions, scope)

    def _struct_emit(self, expr: Cursor, conditions: tuple[Condition, ...],
                     scope: Scope) -> None:
        path = self._struct_path(expr, scope)
        if path is None or path[0] is None:
            return  # no parameter's (or one not known: its own read is whole)
        self.calls.append(PrimitiveCall(kind="read", name=render(path), conditions=conditions,
                                        location=self.where(expr), struct_member=True))

    def _struct_parameters(self, function: Cursor, conditions: tuple[Condition, ...],
                           scope: Scope) -> None:
        """A read, whole, of the parameter each ``XmlRpcValue`` parameter of ``function``
        holds when its code uses it otherwise than by key (``_read_by_key``)."""
        for parm in function.get_children():
            if parm.kind == CursorKind.PARM_DECL and is_struct_value(parm.type) and (
                    not _read_by_key(parm, scope, self.owned)):
                self._struct_emit(parm, conditions, scope)

    def _marked(self, expr: Cursor, scope: Scope) -> str | None:
        """A string passed to another file's function whose one unknown run is a
        parameter's value, with that parameter marked (``links.parameter_mark``)."""
        name, source = self._name(expr, scope)
        if source is None and not isinstance(name, BelowName):
            # a member another file writes (``params_->odom_topic``): the member marked,
            # which the node's files name by the parameter stored there
            # (``extract.cpp._members_named``)
            usr = self._run_member(expr, scope, name)
            return parameter_mark(name, MEMBER_MARK + usr, None) if usr else None
        if source is not None and source[0] is None and (source[3] or "").startswith(
                LOADED) and PLACEHOLDER not in name:
            return parameter_mark(name, "", source[3])  # each plugin kept: no parameter
        # (a parameter named after what other files pass is not known until they are
        # read: its name stays unknown; but for one read on a handle whose namespace
        # they pass, filled site by site as the name is: costmap_2d's ``plugins`` on
        # the handle of the costmap's name)
        if source is None or source[0] is None or PLACEHOLDER in name or not (
                known_name(source[0]) or _on_passed_handle(source[0])):
            return None
        # the parameters joined to it in the one ``?`` (``prefix + arm``), if that is all
        more = source[5] or []
        if more and not (name.count("?") == 1 and source[3] is None and all(
                len(entry) > 2 and entry[2] == JOINED and isinstance(entry[0], str)
                and known_name(entry[0]) for entry in more)):
            return None
        default = source[1] if source[2] is None and source[1] is not None and not (
            {UNKNOWN_MARK, PLACEHOLDER, PARAMETER, DEFAULT_MARK} & set(source[1])) else None
        return parameter_mark(name, source[0], source[3],
                              [str(entry[0]) for entry in more], default)

    @staticmethod
    def _given_back(call: Cursor, index: int, scope: Scope) -> tuple[Cursor, Scope] | None:
        """What the function ``call`` calls (defined in this unit) assigns to its
        parameter ``index``, taken by non-const reference, for the caller's variable
        passed there (``Scope.given_back``), with the scope of that function's body."""
        if scope.sites is None:
            return None
        function = callee_of(call)
        definition = function.get_definition() if function is not None else None
        if definition is None or definition.kind not in (
                CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD):
            return None
        parms = list(definition.get_arguments())
        if index >= len(parms):
            return None
        body = scope.sites.scope(definition)
        handed = body.given_back(parms[index])
        return None if handed is None else (handed, body)

    def _read_through(self, call: Cursor, index: int, scope: Scope) -> Source | None:
        """The parameter a helper of the unit reads into the caller's variable, given to
        it by non-const reference as its parameter ``index``, when its body hands that
        parameter, as the out argument, to one ROS read of a parameter (rm_engineer's
        config loaders: ``declare_get("joint_cmd_topic", cfg.joint_cmd_topic)`` of a
        lambda ``[&](const std::string& name, auto& value) { node.declare_parameter(name,
        value); node.get_parameter(name, value); }``); the read's name is the caller's
        argument where it is another parameter of the helper, the default what the
        variable holds before the call. A read named on a handle's namespace is left."""
        if scope.sites is None:
            return None
        function = callee_of(call)
        definition = function.get_definition() if function is not None else None
        if definition is None or definition.kind not in (
                CursorKind.FUNCTION_DECL, CursorKind.CXX_METHOD,
                CursorKind.FUNCTION_TEMPLATE):
            return None
        parms = [c for c in definition.get_children() if c.kind == CursorKind.PARM_DECL]
        outer = written_arguments(call)
        if call.spelling.startswith("operator") and len(outer) == len(parms) + 1:
            outer, index = outer[1:], index - 1  # a lambda's call lists its object first
        if not 0 <= index < len(parms) or len(outer) != len(parms):
            return None
        ptype = parms[index].type
        if ptype.kind != TypeKind.LVALUEREFERENCE or ptype.get_pointee().is_const_qualified():
            return None
        body = scope.sites.scope(definition)
        parm = parms[index]
        if any(write is not None for write in body.writes.get(place_of(parm), [])):
            return None  # assigned a value of its own too
        reads: list[tuple[api.RosFunction, list[Cursor]]] = []
        for node in definition.walk_preorder():
            if node.kind != CursorKind.CALL_EXPR:
                continue
            spec, _ = self._row(node)
            args = written_arguments(node)
            if spec is None or spec.kind != "read" or spec.out_arg is None or (
                    spec.out_arg >= len(args)):
                continue
            out = strip(args[spec.out_arg])
            if out.kind == CursorKind.DECL_REF_EXPR and out.referenced == parm:
                reads.append((spec, args))
        if len(reads) != 1:
            return None
        spec, args = reads[0]
        if spec.on_handle or spec.handle_arg is not None or spec.value_only or (
                spec.argument or spec.name_arg >= len(args)):
            return None
        named = strip(args[spec.name_arg])
        given = named.referenced if named.kind == CursorKind.DECL_REF_EXPR else None
        parts = scope.string(outer[parms.index(given)]) if given in parms else (
            body.string(named))
        if not _known(parts):
            return None
        kept = _kept_value(outer[index], scope)[1]
        return render(parts), kept if isinstance(kept, str) else None, None

    def _searched_key_source(self, expr: Cursor, scope: Scope) -> Source | None:
        """The parameter whose value is the key of the ``searchParam(key, result)`` that
        last wrote the variable ``expr`` (its result), if it is one."""
        if expr.kind != CursorKind.DECL_REF_EXPR or expr.referenced is None:
            return None
        passed = scope.passed_to(expr.referenced, expr)
        if passed is None:
            return None
        call, index = passed
        key = searched_key(call)
        if key is None or index != len(written_arguments(call)) - 1:
            return None
        return self._parameter_source(key, scope, 1)

    def _sdf_parts(self, namespace: str | None, parts: list[tuple[Cursor, Scope]]
                   ) -> str | None:
        """The SDF elements (``sdf:key``) that give a handle's namespace each of its
        unknown runs, in order, joined by spaces (``PrimitiveCall.namespace_param``),
        when it has several and a Gazebo plugin's SDF gives each; else None."""
        count = namespace.count("?") if namespace is not None else 0
        if count < 2 or len(parts) != count:
            return None
        keys: list[str] = []
        for expr, scope in parts:
            found = self._parameter_source(expr, scope, 0)
            if found is None or not (found[0] or "").startswith(SDF_ELEMENT):
                return None
            keys.append(found[0])
        return " ".join(keys)

    def _transport(self, spec: api.RosFunction, transport: str,
                   arg: Callable[[int | None], Cursor | None], args: list[Cursor],
                   scope: Scope) -> tuple[str, dict[str, Any]]:
        """An image_transport subscriber's transport (``PrimitiveCall.transport``) and
        the fields that say what gives a ``?`` one: the transport the ROS 2 code passes
        (``transport_arg`` of the row; not written: ``raw``, create_subscription's
        default; the ``getTransport()`` of TransportHints: as if given them), else the
        TransportHints it is given: their parameter, else their default."""
        mark = transport[len(UNKNOWN_MARK):]  # ``/``: a ROS 1 Subscriber
        if spec.transport_arg is None:
            made = self._hints_given(spec, args)
            return (transport, {}) if made is None else self._hinted(transport, made, scope)
        given = arg(spec.transport_arg)
        if given is None:
            return "raw" + mark, {}
        made = self._hints_read(given)
        if made is not None:  # ``hints.getTransport()``
            return self._hinted(transport, made, scope)
        text, chosen = self._transport_value(given, scope)
        if text is not None:
            return text + mark, {}
        return transport, {**chosen, "transport_fixed": True}

    def _transport_given(self, spec: api.RosFunction,
                         arg: Callable[[int | None], Cursor | None], args: list[Cursor]
                         ) -> Cursor | None:
        """The expression whose text is a ``?`` transport (``_transport``): what the ROS
        2 code passes, else the default of the TransportHints it is given or reads."""
        made = self._hints_given(spec, args) if spec.transport_arg is None else (
            self._hints_read(given) if (given := arg(spec.transport_arg)) is not None
            else None)
        if made is None:
            return arg(spec.transport_arg) if spec.transport_arg is not None else None
        at = 1 if self.ros2 else 0
        return made[at] if len(made) > at else None

    def _transport_value(self, given: Cursor, scope: Scope) -> tuple[str | None, dict[str, Any]]:
        """The transport text ``given`` holds, else the fields that say what gives it (a
        program argument, a parameter's value, ``?``: not known)."""
        with program_arguments():
            parts = scope.string(given)
        text = render(parts)
        if text and UNKNOWN_MARK not in text:
            return text, {}
        index = argument_of(parts)
        if index is not None:  # republish's ``argv[1]``
            return None, {"transport_arg": index}
        source = self._parameter_source(given, scope, 0)
        if source is None:
            return None, {"transport_default": UNKNOWN_MARK}
        chosen: dict[str, Any] = {"transport_param": source[0]}
        if source[1] is not None:
            chosen["transport_default"] = source[1]
        return None, chosen

    def _hinted(self, transport: str, made: list[Cursor], scope: Scope
                ) -> tuple[str, dict[str, Any]]:
        """A ``?`` transport chosen by TransportHints made with the arguments ``made``
        (ROS 1 default transport, roscpp hints, handle, parameter name; ROS 2 node,
        default transport, parameter name): their default (none: ``raw``), which their
        parameter overrides. A parameter other than ``image_transport`` (rtabmap's
        ``TransportHints(this, "raw", "depth_transport")``) is said as the parameter
        that gives the transport, its default the hints' text (else not known)."""
        at, name_at = (1, 2) if self.ros2 else (0, 3)
        default = made[at] if len(made) > at else None
        text, chosen = (None, {}) if default is None else self._transport_value(
            default, scope)
        if text is not None and text != "raw":
            chosen = {"transport_default": text}
        parameter = render(scope.string(made[name_at])) if len(made) > name_at else (
            TRANSPORT_PARAM)
        if parameter == TRANSPORT_PARAM:
            return transport, chosen
        return transport, {
            "transport_fixed": True, "transport_default": text or (
                UNKNOWN_MARK if default is not None else "raw"),
            "transport_param": parameter if self.ros2 or UNKNOWN_MARK in parameter else (
                "~" + parameter)}

    def _hints_given(self, spec: api.RosFunction, args: list[Cursor]) -> list[Cursor] | None:
        """The arguments of the TransportHints an image_transport subscriber is given
        after its callback (or queue size): ROS 1 ``TransportHints("compressed", ...)``
        or a string, which converts to them (as their one argument); ROS 2 a pointer to
        ``TransportHints(node, "compressed")``; also a variable made so. None when it is
        given none (``raw``, unless the node's parameter says)."""
        written = [i for i in (spec.name_arg, spec.queue_arg, spec.callback_arg)
                   if i is not None]
        for given in args[max(written) + 1:]:
            inner = strip(given)
            if inner.kind == CursorKind.UNARY_OPERATOR:  # ``&hints``
                inner = first_operand(inner) or inner
            if not self.ros2 and _textual(inner):
                return [inner]
            made = self._hints_made(inner)
            if made is not None:
                return made
        return None

    def _hints_read(self, given: Cursor) -> list[Cursor] | None:
        """The arguments of the TransportHints whose ``getTransport()`` ``given`` is."""
        inner = strip(given)
        if inner.kind != CursorKind.CALL_EXPR or inner.spelling != "getTransport":
            return None
        held = method_object(inner)
        return None if held is None else self._hints_made(strip(held))

    def _hints_made(self, inner: Cursor) -> list[Cursor] | None:
        """The arguments TransportHints ``inner`` are made with: a construction, or a
        variable that one initialises."""
        made = constructed_arguments(inner, api.IMAGE_HINTS)
        decl = inner.referenced if inner.kind == CursorKind.DECL_REF_EXPR else None
        if made is None and decl is not None and decl.kind == CursorKind.VAR_DECL:
            init = initializer(decl)
            made = constructed_arguments(init, api.IMAGE_HINTS) if init is not None else None
        return made

    def _parameter_source(self, expr: Cursor, scope: Scope,
                          depth: int, value: bool = False) -> Source | None:
        """The parameter (name, default) whose value ``expr`` holds, if it is one.
        ``value``: only a value a condition may stand for (``_held_parameters``): not
        what a read returns about the parameter being there (``bool found =
        nh.getParam("x", v)``), nor a wrapper's result unless it returns what it reads
        (``_gives_status``)."""
        expr = strip(expr)
        if depth > MAX_DEPTH:
            return None
        if expr.kind in (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR):
            decl = expr.referenced
            if decl is None:
                return None
            passed = scope.passed_to(decl, expr)
            if passed is not None:
                call, index = passed
                if searched_key(call) is not None:
                    return None  # searchParam's result: the name it found, no value
                spec, _ = self._row(call)
                if spec is not None and spec.out_arg == index and spec.kind in _PARAM_KINDS:
                    read = self._parameter(spec, call, scope, depth)
                    writes = scope.values_written(decl, expr) if (
                        read is not None and read[1] is None) else []
                    values = [each for each in writes if each is not None]
                    if read is not None and len(values) == 1 and len(writes) == 2 and (
                            _known(parts := scope.string(values[0]))):
                        # the one literal the body writes it beside the read, which
                        # writes it by reference (ROS 1's ``if (!pnh.getParam("topic",
                        # topic)) topic = "scan";``): the value where it is not set
                        return read[0], render(parts), read[2]
                    if read is not None and scope.written_between(decl, call, expr) and (
                            scope.written_before(decl, expr) is None):
                        # written again after the read, where that write may not run
                        # before this use (Autoware's image_rectifier: ``if (ns != "/")
                        # topic = ns + topic;``): not the parameter's value alone
                        return None
                    return read
                handed = self._given_back(call, index, scope) if spec is None else None
                if handed is not None:
                    return self._parameter_source(handed[0], handed[1], depth + 1, value)
                if spec is None and not (
                        call.extent.start.offset <= expr.extent.start.offset
                        and expr.extent.end.offset <= call.extent.end.offset):
                    # (a use after the call, not the argument it is given as: a
                    # condition on ``hasBoolean(this, "flag", flag)`` is the helper's
                    # answer, not what it stores)
                    through = self._read_through(call, index, scope)
                    if through is not None:
                        return through
            if scope.sites is not None and scope.is_parameter(decl):
                # a function's parameter: the parameter every call of the file passes
                # (nav2's ``CostmapSubscriber(node, costmap_topic)``, the topic a local
                # read from ``costmap_topic``)
                return scope.sites.agreed(
                    decl, lambda arg, site: self._parameter_source(
                        arg, site, depth + 1, value), None)
            written = scope.variable(decl)
            # a member, as Scope.string reads it: what this body assigned it before here
            # (``topic_ = declare_parameter("publisher_topic", "x");`` then
            # ``create_publisher(topic_, ..)`` in one constructor), else what a constructor
            # of its class gives it, read in that constructor
            if written is None and expr.kind == CursorKind.MEMBER_REF_EXPR and (
                decl.kind == CursorKind.FIELD_DECL
            ):
                written = scope.assigned(decl, expr)
            if written is None:
                held = self._host_value_or_default(decl, expr, scope, depth, value)
                if held is not None:
                    return held
                found = scope.field(decl)
                if found is None and expr.kind == CursorKind.MEMBER_REF_EXPR:
                    return self._written_once(decl, depth, value)
                return None if found is None else self._parameter_source(
                    found[0], found[1], depth + 1, value)
            return self._parameter_source(written, scope, depth + 1, value)
        if expr.kind != CursorKind.CALL_EXPR:
            return None
        spec, _ = self._row(expr)
        if spec is not None and spec.value_only and spec.name_arg >= len(
                written_arguments(expr)):
            # ``GetElement("key")->Get<T>()``: the value of its object
            held = method_object(expr)
            return self._parameter_source(held, scope, depth + 1, value) if (
                held is not None) else None
        if expr.spelling == "operator->":
            # a shared pointer's object (SDFormat's ``GetElement("key")->GetValue()``)
            held = next((c for c in expr.get_children()
                         if strip(c).spelling != "operator->"), None)
            return self._parameter_source(held, scope, depth + 1, value) if (
                held is not None) else None
        if spec is not None and spec.resolved:
            # a name roscpp resolves (``ros::names::resolve(topic)``): the parameter its
            # argument holds, if any; the row is a read only for the remap it marks
            arguments = written_arguments(expr)
            return self._parameter_source(arguments[spec.name_arg], scope, depth + 1, value) \
                if spec.name_arg < len(arguments) else None
        if spec is not None and spec.kind in _PARAM_KINDS:
            # (for a value, not ``bool found = nh.getParam("x", v)``: whether x is there)
            return self._parameter(spec, expr, scope, depth) if not value or (
                self._returns_read(spec, expr)) else None
        if spec is None and (not value or not self._gives_status(expr)):
            # a wrapper's call: the parameter when every read or declaration it makes
            # names the same one
            sources = [self._parameter(row, expr, named, depth)
                       for row, named in self.wrappers.parameter_calls(expr, scope)]
            known = [s for s in sources if s is not None]
            if known and len(known) == len(sources) and all(s[0] == known[0][0] for s in known):
                return next((s for s in known if s[1] is not None), known[0])
        children = list(expr.get_children())
        if _value_method(expr, children):
            objects = [c for c in children[0].get_children() if c.kind.is_expression()]
            return self._parameter_source(
                objects[0], scope, depth + 1, value) if objects else None
        inner = [c for c in children if c.kind.is_expression()]
        if expr.referenced is None or (
            expr.referenced.kind == CursorKind.CONSTRUCTOR and len(inner) == 1
        ):
            return self._parameter_source(
                inner[-1], scope, depth + 1, value) if inner else None
        return None

    def _host_value_or_default(self, decl: Cursor, expr: Cursor, scope: Scope, depth: int,
                               value: bool) -> Source | None:
        """A variable the body writes twice, a parameter's or a host's value
        (``api.RosFunction.value_only``) and a literal: the value with the literal as
        its default, unless the read gives its own. Gazebo plugins write ``topic_ =
        "imu"; if (_sdf->HasElement("topicName")) topic_ = _sdf->Get<std::string>(
        "topicName");`` (or the literal in the ``else``); slam_toolbox ``solver_plugin =
        "solver_plugins::CeresSolver"``, declares the parameter with it, then
        ``solver_plugin = get_parameter("solver_plugin").as_string()``."""
        written = scope.values_written(decl, expr)
        values = [each for each in written if each is not None]
        if len(values) != len(written):
            return None
        return self._literal_or_parameter(values, scope, depth, value)

    def _literal_or_parameter(self, written: list[Cursor], scope: Scope, depth: int,
                              value: bool) -> Source | None:
        """Of the two values a variable is written, one a literal and the other a
        parameter's or a host's value: that value, the literal its default unless the
        read gives its own (``_host_value_or_default``, ``_written_once``)."""
        if len(written) != 2:
            return None
        for index, each in enumerate(written):
            other = written[1 - index]
            parts = scope.string(other)
            if not _known(parts):
                continue
            source = self._parameter_source(each, scope, depth + 1, value)
            if source is not None and source[0].startswith(SDF_ELEMENT):
                return source[0], render(parts), None
            if source is not None and UNKNOWN_MARK not in source[0]:
                return source[0], render(parts) if source[1] is None else source[1], source[2]
        return None

    def _written_once(self, member: Cursor, depth: int,
                      value: bool = False) -> Source | None:
        """The parameter a member holds when its one write in the file's functions is a
        read or declaration of that parameter, in another method than the one using it
        (rplidar_ros' ``init_param()``, which the constructor calls before it makes the
        publisher: ``get_parameter("topic_name", topic_name_)``, ``frame_ =
        declare_parameter("frame_id", ..)``), or when one method writes it a literal and
        that parameter's value (slam_toolbox's ``setParams()``: ``map_name_ =
        std::string("/map")``, then ``map_name_ = get_parameter("map_name").as_string()``:
        ``_literal_or_parameter``)."""
        if self.members is None or member.kind != CursorKind.FIELD_DECL:
            return None
        writes = self.members.writes(member)
        assigned = self.members.assignments(member) if writes in (1, 2) else []
        if writes == 2 and len(assigned) == 2 and assigned[0][1] == assigned[1][1]:
            return self._literal_or_parameter([written for written, _ in assigned],
                                              self._scope_of(assigned[0][1]), depth, value)
        if writes != 1:
            return None
        if len(assigned) == 1:
            written, function = assigned[0]
            return self._parameter_source(
                written, self._scope_of(function), depth + 1, value)
        if assigned:
            return None
        for function in self.members.naming(member):
            for node in function.walk_preorder():
                if node.kind != CursorKind.CALL_EXPR:
                    continue
                spec, _ = self._row(node)
                if spec is not None and self.ros2 and spec.ros2 is not None:
                    spec = spec.ros2
                if spec is None:
                    # the member given by reference to a helper that reads a parameter
                    # into it (``_read_through``)
                    for index, arg in enumerate(written_arguments(node)):
                        held = strip(arg)
                        if held.kind == CursorKind.MEMBER_REF_EXPR and (
                                held.referenced == member):
                            found = self._read_through(node, index, self._scope_of(function))
                            if found is not None:
                                return found
                    continue
                if spec.kind not in _PARAM_KINDS or spec.out_arg is None:
                    continue
                args = list(node.get_arguments())
                shift = 1 if spec.optional_handle and args and is_handle(args[0]) else 0
                if self._member(spec, node, shift) == member:
                    return self._parameter(
                        spec, node, self._scope_of(function), depth + 1)
        return None

    def _parameter(self, spec: api.RosFunction, call: Cursor,
                   scope: Scope, depth: int = 0) -> Source | None:
        """The parameter a read or declaration names: its name, its default when known
        (with one ``?`` where it holds another parameter's value), and that parameter."""
        args = written_arguments(call)
        if spec.name_arg >= len(args):
            return None
        name = render(scope.string(args[spec.name_arg]))
        if spec.value_only:
            # the host's value; where the host gives none, the code's default when it
            # writes one (gazebo_plugins' ``getParameter<T>(value, "tag", default)``)
            given = args[spec.default_arg] if spec.default_arg is not None and (
                spec.default_arg < len(args)) else None
            parts = scope.string(given) if given is not None else None
            return (spec.name_prefix or "") + name, render(parts) if (
                parts is not None and _known(parts)) else None, None
        if spec.argument:
            return ROS_ARGUMENT + name, None, None
        if spec.on_handle:
            name = join_name(render(self.namespaces.of_call(call, callee_of_call(call), scope)),
                             name)
        elif spec.handle_arg is not None and spec.handle_arg < len(args):
            # a wrapper given its handle (``getBool(pnh, "use_x")``): that handle's
            # namespace, as the read it makes is named (``~use_x``)
            name = join_name(render(self.namespaces.of(args[spec.handle_arg], scope)), name)
        default: str | None = None
        other: str | None = None
        index = spec.default_arg
        if index is not None and index >= len(args) and spec.out_arg == len(args) - 1:
            index = spec.out_arg  # nh.param<T>(name, default) returns the value
        if index is None and spec.kind == "read" and spec.out_arg is not None \
                and spec.out_arg < len(args):
            # ``get_parameter("topic_odometry", topic_)`` leaves the variable as it was
            # when the parameter is not set: what it holds before is the default
            # (mrpt_reactivenav2d's ``std::string subTopicOdometry_ = "/odom";``)
            kept = _kept_value(args[spec.out_arg], scope)[1]
            default = kept if isinstance(kept, str) else None
        if index is not None and index < len(args):
            parts = scope.string(args[index])
            if _known(parts):
                default = render(parts)
            elif spec.out_arg is not None and spec.out_arg < len(args) \
                    and index != spec.out_arg and _same_variable(args[index], args[spec.out_arg]):
                kept = _kept_value(args[spec.out_arg], scope)[1]  # param("t", t, t)
                default = kept if isinstance(kept, str) else None
            elif depth < MAX_DEPTH and parts.count(None) == 1:
                # another parameter's value with text around it (topic_tools' relay:
                # ``declare_parameter("output_topic", input + "_relay")``)
                unknown = _unknown_operands(args[index], scope)
                source = self._parameter_source(unknown[0], scope, depth + 1) if len(
                    unknown) == 1 else None
                if source is not None and source[0] != name and "?" not in source[0]:
                    default, other = render(parts), source[0]
        return (name, default, other)

    def _member(self, spec: api.RosFunction, call: Cursor, shift: int) -> Cursor | None:
        """The member variable a parameter read stores its value in: its out argument
        (passed by reference), or the member its result is assigned to."""
        if spec.kind not in _PARAM_KINDS or self.members is None:
            return None
        member = None
        if spec.out_arg is not None:
            index, args = spec.out_arg + shift, list(call.get_arguments())
            if index < len(args) and may_write(call, index):
                member = member_of(args[index])
        if member is None:
            member = self.members.assigned(call)
        return member

    @staticmethod
    def _default(spec: api.RosFunction, args: list[Cursor],
                 scope: Scope) -> tuple[bool, object]:
        """Whether a parameter read gives a default, and its value when it is a literal."""
        index = spec.default_arg
        if index is None:
            if spec.kind == "read" and spec.out_arg is not None and spec.out_arg < len(args):
                return _kept_value(args[spec.out_arg], scope)
            return False, None
        if index >= len(args) and spec.out_arg == len(args) - 1:
            index = spec.out_arg  # nh.param<T>(name, default) returns the value
        if index >= len(args):
            return False, None
        if msg_types.parameter_type_constant(args[index]) is not None:
            return False, None  # declare_parameter(name, rclcpp::PARAMETER_DOUBLE): typed
        value = _literal(msg_types.held_value(args[index]), scope)
        if value is None and spec.out_arg is not None and spec.out_arg < len(args) \
                and index != spec.out_arg and _same_variable(args[index], args[spec.out_arg]):
            # ``nh.param("topic", topic, topic)``: the default is what the variable holds
            # before the call (costmap_converter: a local initialised with a literal)
            value = _kept_value(args[spec.out_arg], scope)[1]
        return True, value

    def _field(self, field: Cursor) -> None:
        """A member whose mere construction is a primitive (a tf broadcaster)."""
        decl = field.type.get_canonical().get_declaration()
        if decl is None or decl.kind == CursorKind.NO_DECL_FOUND:
            return
        decl = row_class(decl)
        spec = api.ALL.get((qualified_name(decl), decl.spelling))
        if spec is None or (spec.fixed_name is None and spec.default_name is None) or not (
                _default_constructible(decl)):
            # a class that takes arguments (camera_info_manager's, given a handle) is
            # made where a constructor initialises the member, whose call is that one
            return
        if _initialised(field):
            return  # each constructor builds it with its initialiser: that call is it
        # made with each object of the class: the class's call (none where nothing
        # builds one, ``extract.cpp._unbuilt``)
        held, self._owner = self._owner, owner_of(field)
        try:
            self._emit(spec, field, [], decl, (),
                       Scope(None, self.macros, self.source, self.sites))
        finally:
            self._owner = held


def _declared_code(cls: Cursor, data: bytes) -> bytes:
    """The code of a class's declaration whose words are what its constructor may build
    unseen: its comments and the insides of its literals blanked (``code_only``: words of
    prose build nothing; nav2's Costmap2DROS explains itself as a "child-LifecycleNode"),
    and, for a class that is a ROS 2 node of its own, the node classes it derives from:
    its constructor builds those bases as its own node, which that construction names,
    not another node of the process (the controller server's costmap, a
    ``nav2::LifecycleNode``, left the server's own name unknown)."""
    extent = cls.extent
    start, end = extent.start.offset, extent.end.offset
    code = bytearray(code_only(data)[start:end])
    if is_ros2_node(cls):
        for base in cls.get_children():
            if base.kind != CursorKind.CXX_BASE_SPECIFIER:
                continue
            decl = base.type.get_canonical().get_declaration()
            if not is_ros2_node(decl):
                continue
            first, last = base.extent.start.offset - start, base.extent.end.offset - start
            if 0 <= first <= last <= len(code):
                code[first:last] = b" " * (last - first)
    return bytes(code)


def _shown_type(ctype: str | None) -> str:
    """A call's type as a diagnostic says it: ``?`` for none, or one each construction
    gives (``CallFinder._per_construction_type``)."""
    return ctype if ctype and PLACEHOLDER not in ctype else "?"


UNREAD = "haros_unread"  # the annotation of a stand-in's class whose calls no row says


def _unread(cls: Cursor | None) -> bool:
    """Whether ``cls`` is a class of our stand-ins marked ``HAROS_UNREAD``: declared so
    that code using it parses, while what it makes on the node it is given is not
    described (nav2_costmap_2d's CostmapSubscriber subscribes to a costmap topic)."""
    return cls is not None and from_standin(cls) and any(
        child.kind == CursorKind.ANNOTATE_ATTR and child.spelling == UNREAD
        for child in cls.get_children())


def _initialised(field: Cursor) -> bool:
    """Whether no constructor of the member's class builds ``field`` by default (nor by
    its default member initialiser, which the declaration stands for): the class declares
    constructors and each of them that this unit defines with a body names the member
    among its initialisers or delegates to another constructor (mavros' ``Router``:
    ``diagnostic_updater(this, 1.0)``, whose construction is the call); with none of
    them defined here, the unit that defines them tells. A class with no constructor of
    its own, or one that leaves the member out (or ``= default``), builds it by
    default."""
    owner = field.semantic_parent
    if owner is None or field.kind != CursorKind.FIELD_DECL:
        return False
    if initializer(field) is not None:
        # a default member initialiser (``Updater diagnostic_updater_{this};``,
        # ``TransformListener tf_listener_{tf_buffer_};``) builds it wherever a
        # constructor does not: the declaration stands for that construction in every
        # unit that sees it (its walk as a function adds no second one)
        return False
    constructors = [c for c in owner.get_children() if c.kind == CursorKind.CONSTRUCTOR]
    if not constructors:
        return False
    where = place_of(field)
    for declared in constructors:
        if declared.is_deleted_method():
            continue
        definition = declared.get_definition()
        if definition is None:
            continue
        children = list(definition.get_children())
        if not any(c.kind == CursorKind.COMPOUND_STMT for c in children):
            if declared.is_copy_constructor() or declared.is_move_constructor():
                continue  # copies the member
            return False  # ``= default``: each member built by default
        if delegation(definition) is not None:
            continue
        if not any(c.kind == CursorKind.MEMBER_REF and c.referenced is not None
                   and place_of(c.referenced) == where and index + 1 < len(children)
                   and _construction(children[index + 1])
                   for index, c in enumerate(children)):
            return False
    return True


def _construction(expression: Cursor) -> bool:
    """Whether a member initialiser's expression is a construction the walk reads as a
    call: a constructor's call, under the implicit nodes around it. In a class template
    an initialiser given a dependent argument (ouster_ros'
    ``OusterStaticTransformsBroadcaster<NodeT>``: ``tf_bcast(parent)``, ``parent`` a
    ``NodeT*``) is a list of its arguments and calls nothing yet: the member's
    declaration stands for its construction there (its /tf_static publisher was lost)."""
    while expression.kind == CursorKind.UNEXPOSED_EXPR:
        inner = list(expression.get_children())
        if len(inner) != 1:
            return False
        expression = inner[0]
    return expression.kind == CursorKind.CALL_EXPR


def _default_constructible(cls: Cursor) -> bool:
    """Whether a member of class ``cls`` can be made with no argument: it declares no
    constructor, or one whose parameters all have defaults."""
    constructors = [c for c in cls.get_children() if c.kind == CursorKind.CONSTRUCTOR]
    return not constructors or any(
        all(any(child.kind.is_expression() for child in p.get_children())
            for p in c.get_children() if p.kind == CursorKind.PARM_DECL)
        for c in constructors)




# classes whose VAR_DECL children are static data members


def _copy_initialised(var: Cursor) -> bool:
    """Whether a variable's declaration is ``T name = ...`` (its value copied or moved
    from an expression), not ``T name(...)``, ``T name{...}`` nor ``T name;``."""
    tokens = [t.spelling for t in itertools.islice(var.get_tokens(), 64)]
    for index, token in enumerate(tokens[:-1]):
        if token == var.spelling:
            return tokens[index + 1] == "="
    return False


def _same_variable(a: Cursor, b: Cursor) -> bool:
    """Two arguments that name one variable (``x``, ``x``; ``this->x_``, ``x_``)."""
    first, second = strip(a), strip(b)
    names = (CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR)
    return (first.kind in names and second.kind in names and first.referenced is not None
            and first.referenced == second.referenced)


def _kept_value(out: Cursor, scope: Scope) -> tuple[bool, object]:
    """A read into ``out`` that leaves it as it is when the parameter is not there (ROS
    1's ``getParam(name, out)``, rclcpp's ``get_parameter(name, out)``) has a default
    when ``out`` holds a value before it: a local written with an initialiser
    (``bool unreliable = false;``), a variable of static storage of a builtin type
    (topic_tools' ``bool g_lazy;``, zero), a member its class initialises, a static
    data member whose definition is in another file (a value, not known here). Its
    value when that is a literal."""
    target = strip(out)
    decl = target.referenced if target.kind in (
        CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) else None
    if decl is None:
        return False, None
    value: Cursor | None = None
    where = scope
    if decl.kind == CursorKind.VAR_DECL:
        definition = decl.get_definition()
        member = decl.semantic_parent is not None and decl.semantic_parent.kind in CLASSES
        init = initializer(definition or decl)
        if init is not None and not default_constructed(init):
            value = init
        elif init is None and member and definition is None:
            # a static data member defined in another file of the node (usb_cam's
            # ``std::string AbstractV4LUSBCam::io_method_name = "mmap";``): it holds
            # a value there, whether zero or another is not known in this file
            return True, None
        elif init is None and decl.type.get_canonical().kind in _ZEROED and (
            decl.storage_class == StorageClass.STATIC
            or member
            or decl.semantic_parent is None
            or decl.semantic_parent.kind in (CursorKind.NAMESPACE,
                                             CursorKind.TRANSLATION_UNIT)
        ):
            zero = _ZEROED[decl.type.get_canonical().kind]
            return True, zero
        elif init is None and not member and (held := scope.held_before(decl, target))[0]:
            # a local declared bare and written before the read, whatever runs
            # (base_local_planner's ``backup_vel = -0.1;`` then ``getParam("backup_vel",
            # backup_vel)`` and ``getParam("escape_vel", backup_vel)``): the value of the
            # last write when nothing else may write it between
            if held[1] is None:
                return True, None
            value = held[1]
    elif decl.kind == CursorKind.FIELD_DECL:
        found = scope.field(decl, initial=True)  # what it holds before the read
        if found is not None:
            value, where = found
    if value is None:
        return False, None
    return True, _literal(value, where)


_LITERALS = (CursorKind.CXX_BOOL_LITERAL_EXPR, CursorKind.INTEGER_LITERAL,
             CursorKind.STRING_LITERAL)


def _converted(value: object, ptype: str | None) -> object:
    """A literal default as the call converts it to the type it reads or declares
    (``param<bool>(name, "false")``: a string literal is a pointer that is not null, so
    true; ``param<double>(name, 10)``: 10.0); None where C++ has no implicit conversion
    we can follow (a pointer to a number, a number to std::string)."""
    if value is None or ptype not in ("bool", "int", "double", "str"):
        return value
    if ptype == "bool":
        return True if isinstance(value, str) else bool(value)
    if isinstance(value, str):
        return value if ptype == "str" else None
    if ptype == "str" or not isinstance(value, (bool, int, float)):
        return None
    return float(value) if ptype == "double" else int(value)


def _literal(expr: Cursor, scope: Scope) -> object:
    """A default's value when it is a literal (a boolean, a number, signed or not, a
    known string, a braced list of them), else None."""
    for read in (scope.boolean, scope.integer, scope.number):
        value = read(expr)
        if value is not None:
            return value
    parts = scope.string(expr)
    if parts and _known(parts):
        return render(parts)
    return _list_literal(expr, scope)


MAX_LIST_DEPTH = 12  # the wrappers between an argument and its braced list
MAX_CHOICE_DEPTH = 4  # the locals between a name argument and its ``?:``
MAX_CHOICE_NODES = 200  # the expression nodes read for the ``?:`` a name holds


def _returns_its_parameter_type(call: Cursor) -> bool:
    """Whether ``call`` calls a specialisation of a function template whose declared
    return type is one of the template's type parameters (``template<typename T> T
    get(node, name)``)."""
    callee = call.referenced
    template = conf.lib.clang_getSpecializedCursorTemplate(callee) if callee is not None \
        else None
    if template is None or template.kind != CursorKind.FUNCTION_TEMPLATE:
        return False
    returned = template.result_type
    if returned.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        returned = returned.get_pointee()
    spelled = returned.spelling.removeprefix("const ").strip()
    return any(c.kind == CursorKind.TEMPLATE_TYPE_PARAMETER and c.spelling == spelled
               for c in template.get_children())


def _scalar(ctype: Type) -> bool:
    """A builtin type (``bool``, ``int``, ``double``, ...) or a pointer."""
    kind = ctype.get_canonical().kind
    return kind == TypeKind.POINTER or TypeKind.BOOL.value <= kind.value <= (
        TypeKind.LONGDOUBLE.value)


def _list_literal(expr: Cursor, scope: Scope) -> object:
    """A braced list of literals that is the whole expression (``{"left", "right"}``,
    ``std::vector<std::string>{"front", "back"}``, through the conversions and
    constructions clang wraps it in), each item a literal; None otherwise."""
    node = expr
    for _ in range(MAX_LIST_DEPTH):
        if node.kind == CursorKind.INIT_LIST_EXPR:
            items = [_literal(item, scope) for item in node.get_children()]
            if not items or not all(isinstance(item, str | int | float) for item in items):
                return None
            if _scalar(node.type):  # ``bool warn{false}``: a scalar braced, not a list
                return items[0] if len(items) == 1 else None
            return items
        inner = [c for c in node.get_children() if c.kind not in (
            CursorKind.TYPE_REF, CursorKind.TEMPLATE_REF, CursorKind.NAMESPACE_REF)]
        if len(inner) != 1 or not inner[0].kind.is_expression():
            return None
        node = inner[0]
    return None


def _returns(function: Cursor) -> list[Cursor]:
    """The ``return`` statements of ``function``'s body (not those of its lambdas)."""
    found: list[Cursor] = []
    stack = [c for c in function.get_children() if c.kind == CursorKind.COMPOUND_STMT]
    while stack:
        node = stack.pop()
        if node.kind == CursorKind.RETURN_STMT:
            found.append(node)
        elif node.kind != CursorKind.LAMBDA_EXPR:
            stack.extend(node.get_children())
    return found


def _status_read(spec: api.RosFunction, site: Cursor, count: int) -> Key | None:
    """Where a parameter read is that returns whether the parameter is there
    (``hasParam``, ``getParam(name, out)``, ``get_parameter(name, out)``, ``param(name,
    out, default)``), to mark it ``tested`` when its result is a condition; None for
    other calls (``param<T>(name, default)`` and ``get_parameter(name)`` return the
    value)."""
    if spec.kind != "read" or spec.per_element:
        return None
    if spec.out_arg is not None and (count <= spec.out_arg or (
            spec.default_arg is not None and count <= spec.default_arg)):
        return None
    result = site.type.get_canonical().kind
    if site.kind == CursorKind.CALL_EXPR and site.referenced is not None and (
            result != TypeKind.BOOL):
        return None
    return key_of(site)


def _factory_refs(call: Cursor) -> list[Cursor] | None:
    """The references written in the name of ``std::make_shared<...>(args)`` (a factory
    of ``FACTORY_NAMES``, of std or boost) that a template leaves unresolved because an
    argument depends on its parameters; None for another call."""
    children = list(call.get_children())
    head = children[0] if children else None
    if head is None or head.kind != CursorKind.DECL_REF_EXPR or (
        _recovered_name(call) not in FACTORY_NAMES
    ):
        return None
    refs = list(head.get_children())
    if not any(r.kind == CursorKind.NAMESPACE_REF and r.spelling in ("std", "boost")
               for r in refs):
        return None
    return refs


def _dependent_class(call: Cursor) -> Cursor | None:
    """The class ``C`` of such a ``make_shared<C>(args)`` (``_factory_refs``), when ``C``
    is a class, not a template."""
    refs = _factory_refs(call)
    if refs is None:
        return None
    classes = [r.referenced for r in refs if r.kind == CursorKind.TYPE_REF
               and r.referenced is not None]
    if len(classes) != 1 or classes[0].kind not in (CursorKind.CLASS_DECL,
                                                    CursorKind.STRUCT_DECL):
        return None
    return classes[0]


def _dependent_listener(call: Cursor
                        ) -> list[tuple[str, str | None, bool, Any, str | None]] | None:
    """The parameters of a generate_parameter_library ``ParamListener`` that a
    dependent ``std::make_shared<ParamListener>(...)`` builds: in a member of a class
    template, ``get_node()`` is called on the implicit ``this``, which depends on the
    template's parameters (ros2_controllers' gripper_controllers); None for another
    call."""
    return parameter_library.listener_parameters(_dependent_class(call))


def _dependent_made(call: Cursor) -> tuple[api.RosFunction, Cursor] | None:
    """The API row and class of ``std::make_shared<C>(args)`` (a factory of
    ``api.FACTORIES``) that a template leaves unresolved because an argument depends on
    its parameters, when ``C`` is a class, not a template, whose construction has a row:
    nav2's ``create_transform_listener(buffer, node)`` makes a
    ``std::make_shared<nav2::TransformListener>(buffer, node)``; or a class template of
    the API: MoveIt's ``ActionBasedControllerHandle<T>`` makes its action client with
    ``std::make_shared<actionlib::SimpleActionClient<T>>(getActionName(), true)``,
    named by its arguments as far as they are known."""
    cls = _dependent_class(call)
    # else a class template of the API whose arguments depend on the template's
    # parameters (jsk_pcl_ros' ColorFilter<Comparison, Config> builds
    # ``make_shared<dynamic_reconfigure::Server<Config>>(*pnh_)``): its row, the
    # arguments not known
    made = row_class(cls) if cls is not None else _dependent_template(call)
    if made is None:
        return None
    spec = api.ALL.get((qualified_name(made), made.spelling))
    if spec is None:
        return None
    return spec, made


def _dependent_template(call: Cursor) -> Cursor | None:
    """The class template ``T`` of such a ``make_shared<T<A...>>(args)``
    (``_factory_refs``), its arguments depending on the template's parameters."""
    refs = _factory_refs(call)
    if refs is None:
        return None
    templates = [r.referenced for r in refs if r.kind == CursorKind.TEMPLATE_REF
                 and r.referenced is not None
                 and r.referenced.kind == CursorKind.CLASS_TEMPLATE]
    return templates[0] if len(templates) == 1 else None


def _lost_initialisers(constructor: Cursor
                       ) -> dict[tuple[str, int], tuple[api.RosFunction, Cursor]]:
    """The member initialisers of ``constructor`` that build a member of an API class
    (a row of ``api.ALL`` named as its class) but hold no call of its constructor: an
    expression clang kept unresolved, as where an argument names a method an error made
    invalid (industrial_core's ``action_server_(node_, "joint_trajectory_action",
    boost::bind(&JointTrajectoryAction::goalCB, this, _1), ...)`` when ``goalCB`` takes
    a type the parse does not have). By the place of that expression, with the row and
    the member's class."""
    found: dict[tuple[str, int], tuple[api.RosFunction, Cursor]] = {}
    children = list(constructor.get_children())
    for member, init in itertools.pairwise(children):
        if member.kind != CursorKind.MEMBER_REF or init.kind != CursorKind.UNEXPOSED_EXPR:
            continue
        made = member.type.get_canonical().get_declaration()
        if made.kind == CursorKind.NO_DECL_FOUND:
            continue
        base = row_class(made)
        spec = api.ALL.get((qualified_name(base), base.spelling))
        if spec is None or any(
            node.kind == CursorKind.CALL_EXPR and node.referenced is not None
            and node.referenced.kind == CursorKind.CONSTRUCTOR
            and node.referenced.semantic_parent is not None
            and node.referenced.semantic_parent.canonical == made.canonical
            for node in init.walk_preorder()
        ):
            continue
        found[place_of(init)] = (spec, base)
    return found


def _lost_new(expr: Cursor) -> tuple[api.RosFunction, Cursor] | None:
    """The API row and class of ``new C(args)`` (``expr``, a new-expression), ``C`` a
    class of a row named as it, that holds no call of a constructor of ``C``: clang keeps
    only the argument list where an argument depends on a template's parameters
    (ros_controllers' JointTrajectoryController<...>::init: ``new ActionServer(
    controller_nh_, "follow_joint_trajectory", std::bind(&JointTrajectoryController::
    goalCB, this, _1), ...)``)."""
    made = expr.type.get_canonical().get_pointee()
    decl = made.get_declaration()
    # ``C`` a class, or a class template given the template's own parameter (bwi_common's
    # InterruptableActionServer<ActionSpec>: ``new actionlib::ActionServer<ActionSpec>(
    # n_, name, ...)``, a type clang leaves dependent)
    if made.kind != TypeKind.RECORD and not (
            made.kind == TypeKind.UNEXPOSED and decl.kind == CursorKind.CLASS_TEMPLATE):
        return None
    if decl.kind == CursorKind.NO_DECL_FOUND:
        return None
    children = list(expr.get_children())
    if any(node.kind == CursorKind.CALL_EXPR and (
            (node.referenced is not None and node.referenced.kind == CursorKind.CONSTRUCTOR)
            or node.spelling == decl.spelling.split("<")[0]) for node in children):
        return None  # a call of the constructor, resolved or not: read as such
    if not any(node.kind.is_expression() for node in children):
        return None  # ``new C`` or ``new C()``: no arguments, no name
    base = row_class(decl)
    spec = api.ALL.get((qualified_name(base), base.spelling))
    return None if spec is None else (spec, base)


# the namespaces of the ROS client libraries' classes: a method of one of them called on
# an object declared of it is no wrapper of the unit (``_library_method``)
_CLIENT_NAMESPACES = frozenset({"rclcpp", "rclcpp_lifecycle", "rclcpp_action", "ros",
                                "actionlib", "image_transport"})


def _recovered_name(expr: Cursor) -> str:
    """The function a call clang kept only as a recovery expression names
    (``this->declare_parameter(...)`` on an invalid class), or ""."""
    children = list(expr.get_children())
    if len(children) < 2:
        return ""
    head = children[0]
    if head.kind == CursorKind.OVERLOADED_DECL_REF:
        return head.spelling
    if head.kind in (CursorKind.MEMBER_REF_EXPR, CursorKind.DECL_REF_EXPR):
        if head.spelling:
            return head.spelling
        inner = [c for c in head.get_children() if c.kind == CursorKind.OVERLOADED_DECL_REF]
        if inner:
            return inner[-1].spelling
        # ``obj->f`` on an object of an invalid type: the name after the last -> or .
        name = ""
        tokens = [t.spelling for t in itertools.islice(head.get_tokens(), 40)]
        for before, token in itertools.pairwise(tokens):
            if before in ("->", ".", "template") and token.isidentifier() and (
                token != "template"  # node->template create_service<T>(...)
            ):
                name = token
        return name
    return ""


def _callee_text(call: Cursor) -> str:
    """The tokens of a call before its arguments (``rclcpp_action::create_server<A>``)."""
    text = []
    for count, token in enumerate(call.get_tokens()):
        if token.spelling == "(" or count > 60:
            break
        text.append(token.spelling)
    return "".join(text)


def _written_template(call: Cursor) -> str:
    """The first template argument as written in the call (``pkg::msg::Foo``)."""
    text = _callee_text(call)
    start = text.find("<")
    if start < 0:
        return ""
    depth, end = 0, len(text)
    for i in range(start, len(text)):
        depth += {"<": 1, ">": -1}.get(text[i], 0)
        if depth == 0 or (depth == 1 and text[i] == ","):
            end = i
            break
    return text[start + 1:end]


def _creator(expr: Cursor, depth: int = 0) -> tuple[api.RosFunction, Cursor] | None:
    """``Options::create<M>(...)`` in ``expr`` (through copies and conversions)."""
    expr = strip(expr)
    if expr.kind != CursorKind.CALL_EXPR or depth > 4:
        return None
    target = expr.referenced
    if target is not None and target.spelling == "create":
        row = api.OPTIONS.get((qualified_name(target.semantic_parent), "create"))
        return (row, expr) if row is not None else None
    inner = [c for c in expr.get_children() if c.kind.is_expression()]
    return _creator(inner[-1], depth + 1) if len(inner) == 1 else None


def _constructed_from(expr: Cursor) -> Cursor:
    """``expr`` through the conversions and one-argument constructions clang wraps a
    value in (``std::string`` from ``const char *``)."""
    node = strip(expr)
    for _depth in range(MAX_CHOICE_DEPTH):
        if node.kind != CursorKind.CALL_EXPR or (
            node.referenced is not None and node.referenced.kind != CursorKind.CONSTRUCTOR
        ):
            break
        inner = [c for c in node.get_children() if c.kind.is_expression()]
        if len(inner) != 1:
            break
        node = strip(inner[0])
    return node


def _known(parts: tuple[str | None, ...]) -> bool:
    """A value with no unknown part and no placeholder for what other calls pass."""
    return all(part is not None and PLACEHOLDER not in part
               and not isinstance(part, (NodeName, NodeNamespace)) for part in parts)


def _prefixed(name: str, spec: api.RosFunction) -> str:
    """A name argument as the prefix ``spec.name_suffix`` is appended to: as written, or
    (``prefix_normalised``) with a ``.`` after it unless empty or ending with one."""
    if spec.prefix_normalised and name and not name.endswith("."):
        return name + "."
    return name


def _private(name: str) -> str:
    """ROS 2's ``~/name`` written the ROS 1 way, ``~name``."""
    return "~" + name[2:] if name.startswith("~/") else name


# what may be asked of a namespace read whole without reading its values
_KEYS_ONLY_METHODS = frozenset({"getType", "size", "valid", "hasMember"})


def keys_only(expr: Cursor | None, scope: Scope,
              owned: Callable[[str], bool] | None = None) -> bool:
    """Whether ``expr``, the ``XmlRpcValue`` a ROS 1 read fills, is a local variable its
    function uses for the keys alone: besides the read, only ``getType()``, ``size()``,
    ``valid()``, ``hasMember(k)`` and loops over it (range-based, whose variable is
    named only as ``.first``: mavros' distance_sensor, ``for (auto &pair : map_dict)``
    then ``create_item(this, pair.first)``; or from ``begin()`` to ``end()``) whose
    members' values (``pair.second``, ``i->second``) are read by key alone
    (``_read_by_key``: each such read is a call of its own, ``CallFinder._struct_read``).
    Any other use (passed on, indexed, its entries' values) reads the values."""
    inner = strip(expr) if expr is not None else None
    decl = inner.referenced if inner is not None and (
        inner.kind == CursorKind.DECL_REF_EXPR) else None
    if decl is None or decl.kind != CursorKind.VAR_DECL or scope.body is None or (
            "XmlRpcValue" not in decl.type.get_canonical().spelling):
        return False
    loops: list[Cursor] = []
    for node, parent in _with_parents(scope.body):
        if node.kind != CursorKind.DECL_REF_EXPR or node.referenced != decl or (
                node == inner):
            continue
        if parent is not None and parent.kind == CursorKind.MEMBER_REF_EXPR and (
                parent.spelling in _KEYS_ONLY_METHODS
                or (parent.spelling in ("begin", "end") and owned is not None)):
            continue
        if parent is not None and parent.kind == CursorKind.CXX_FOR_RANGE_STMT:
            variable = next((c for c in parent.get_children()
                             if c.kind == CursorKind.VAR_DECL), None)
            if variable is not None:
                loops.append(variable)
                continue
        return False
    iterators = _iterators(decl, scope) if owned is not None else []
    for node, parent in _with_parents(scope.body):
        if node.kind == CursorKind.MEMBER_REF_EXPR and node.spelling == "second" and (
                owned is not None):
            over = struct_member_of(node, scope)
            if over is not None and strip(over).referenced == decl and not _read_by_key(
                    node, scope, owned):
                return False
            continue
        if node.kind != CursorKind.DECL_REF_EXPR or (
                node.referenced not in loops and node.referenced not in iterators):
            continue
        if parent is not None and parent.kind == CursorKind.MEMBER_REF_EXPR and (
                parent.spelling == "first" or (parent.spelling == "second"
                                               and owned is not None)):
            continue  # a member's value: read by key alone (above)
        if node.referenced in iterators and (_in_loop_header(
                node, node.referenced, scope) or (
                    parent is not None and parent.kind == CursorKind.CALL_EXPR
                    and parent.spelling == "operator->")):
            continue  # ``i = v.begin(); i != v.end(); ++i``, ``i->first``, ``i->second``
        return False
    return True


def is_struct_value(type_: Type) -> bool:
    """Whether ``type_`` is ROS 1's ``XmlRpc::XmlRpcValue`` (or a reference to one)."""
    if type_.kind in (TypeKind.LVALUEREFERENCE, TypeKind.RVALUEREFERENCE):
        type_ = type_.get_pointee()
    return type_.get_canonical().get_declaration().spelling == "XmlRpcValue"


def _iterators(decl: Cursor, scope: Scope) -> list[Cursor]:
    """The iterators the ``for`` loops of the body start at ``decl.begin()``."""
    found: list[Cursor] = []
    for loop in walk_cursors(scope.body) if scope.body is not None else ():
        header = _loop_start(loop)
        if header is None:
            continue
        variable, container = header
        held = strip(container)
        if held.kind == CursorKind.DECL_REF_EXPR and held.referenced == decl:
            found.append(variable)
    return found


def _loop_start(loop: Cursor) -> tuple[Cursor, Cursor] | None:
    """(the iterator, the container) of a ``for`` loop whose first part starts an
    iterator at ``container.begin()`` (``for (i = v.begin(); ...)``, ``for (auto i =
    v.begin(); ...)``), else None."""
    if loop.kind != CursorKind.FOR_STMT:
        return None
    init = next(iter(loop.get_children()), None)
    if init is None:
        return None
    begins = [n for n in walk_cursors(init)
              if n.kind == CursorKind.MEMBER_REF_EXPR and n.spelling == "begin"]
    objects = [c for c in begins[0].get_children() if c.kind.is_expression()] if (
        len(begins) == 1) else []
    container = {place_of(n) for o in objects for n in walk_cursors(o)}
    targets = [n for n in walk_cursors(init) if n.kind == CursorKind.VAR_DECL] or [
        n.referenced for n in walk_cursors(init) if n.kind == CursorKind.DECL_REF_EXPR
        and n.referenced is not None and n.referenced.kind == CursorKind.VAR_DECL
        and place_of(n) not in container]
    return (targets[0], objects[0]) if len(targets) == 1 and objects else None


def _in_loop_header(node: Cursor, variable: Cursor, scope: Scope) -> bool:
    """Whether ``node`` is in the header of the ``for`` loop that starts ``variable``."""
    for loop in walk_cursors(scope.body) if scope.body is not None else ():
        header = _loop_start(loop)
        if header is None or not _same(header[0], variable):
            continue
        parts = list(loop.get_children())[:-1]  # all but the body
        return any(_same(n, node) for part in parts for n in walk_cursors(part))
    return False


def struct_member_of(expr: Cursor, scope: Scope) -> Cursor | None:
    """The ``XmlRpcValue`` struct whose member's value ``expr`` is: ``pair.second`` of a
    range-based ``for`` over it, ``i->second`` of an iterator a ``for`` loop starts at
    its ``begin()``; else None."""
    inner = strip(expr)
    if inner.kind != CursorKind.MEMBER_REF_EXPR or inner.spelling != "second":
        return None
    held = next((strip(c) for c in inner.get_children() if c.kind.is_expression()), None)
    if held is not None and held.kind == CursorKind.CALL_EXPR and (
            held.spelling == "operator->"):
        held = next((strip(c) for c in held.get_children()
                     if strip(c).kind == CursorKind.DECL_REF_EXPR
                     and strip(c).referenced is not None
                     and strip(c).referenced.kind == CursorKind.VAR_DECL), None)
    decl = held.referenced if held is not None and (
        held.kind == CursorKind.DECL_REF_EXPR) else None
    if decl is None or decl.kind != CursorKind.VAR_DECL:
        return None
    walk = scope.range_of(decl)
    if walk is not None:
        over = list(walk.get_children())[1]
        return over if is_struct_value(strip(over).type) else None
    for loop in walk_cursors(scope.body) if scope.body is not None else ():
        header = _loop_start(loop)
        if header is not None and _same(header[0], decl) and is_struct_value(
                strip(header[1]).type):
            return header[1]
    return None


def _bound_api(call: Cursor) -> api.RosFunction | None:
    """The API row of the free function ``std::bind`` / ``boost::bind`` binds, with the
    arguments after it (ros_canopen's ``std::bind(ros::service::call<SwitchController>,
    "controller_manager/switch_controller", srv)``, run in a ``boost::thread``): the
    call the function object makes, read as made where it is bound; None for any other
    bind (a method, a lambda, a function of no row)."""
    target = call.referenced
    space = target.semantic_parent if target is not None else None
    if target is None or space is None or space.spelling not in ("std", "boost"):
        return None
    args = written_arguments(call)
    bound = strip(args[0]) if args else None
    if bound is not None and bound.kind == CursorKind.UNARY_OPERATOR:  # ``&f``
        inner = [c for c in bound.get_children() if c.kind.is_expression()]
        bound = strip(inner[0]) if len(inner) == 1 else None
    function = bound.referenced if bound is not None and (
        bound.kind == CursorKind.DECL_REF_EXPR) else None
    if function is None or function.kind != CursorKind.FUNCTION_DECL:
        return None
    spec = api.ALL.get((qualified_name(function.semantic_parent), function.spelling))
    return spec if spec is not None and not spec.on_handle else None


def _local(expr: Cursor) -> bool:
    """Whether ``expr`` is a local variable (a struct handed on whole: what a read
    fills is read whole by it, and one no read fills is no parameter's)."""
    inner = strip(expr)
    return inner.kind == CursorKind.DECL_REF_EXPR and inner.referenced is not None and (
        inner.referenced.kind == CursorKind.VAR_DECL)


def _same(one: Cursor | None, other: Cursor | None) -> bool:
    """Whether two cursors are the same one: by place and kind."""
    return one is not None and other is not None and one.kind == other.kind and (
        place_of(one) == place_of(other))


def _struct_subscript(call: Cursor) -> bool:
    """Whether ``call`` (an ``operator[]``) takes a member of an ``XmlRpcValue``."""
    found = _subscript(call)
    return found is not None and is_struct_value(strip(found[0]).type)


def _read_by_key(value: Cursor, scope: Scope, owned: Callable[[str], bool]) -> bool:
    """Whether the ``XmlRpcValue`` ``value`` (a struct's member, ``i->second``; or its
    function's parameter) is used by key alone: each use asks only its type or keys
    (``_KEYS_ONLY_METHODS``), takes one of its members by key (``v[key]``: a read of
    its own), or hands it to a function of the workspace that takes an
    ``XmlRpcValue`` (whose own code reads it so, or reads it whole)."""
    decl = value if value.kind == CursorKind.PARM_DECL else None
    for node, parent in _with_parents(scope.body) if scope.body is not None else ():
        if decl is not None:
            if node.kind != CursorKind.DECL_REF_EXPR or node.referenced != decl:
                continue
        elif not _same(node, value):
            continue
        if parent is not None and parent.kind == CursorKind.MEMBER_REF_EXPR and (
                parent.spelling in _KEYS_ONLY_METHODS):
            continue
        found = _subscript(parent) if parent is not None else None
        if found is not None and _same(strip(found[0]), node):
            continue
        if parent is not None and _handed_to_reader(parent, node, owned):
            continue
        return False
    return True


def _referenced_variable(arg: Cursor) -> Cursor | None:
    """The variable an argument names, through ``*`` and implicit conversions
    (``*node``, ``node``); None for any other expression."""
    expr: Cursor | None = strip(arg)
    for _ in range(MAX_DEPTH):
        if expr is None or expr.kind == CursorKind.DECL_REF_EXPR:
            break
        inner = [c for c in expr.get_children() if c.kind.is_expression()]
        expr = strip(inner[0]) if len(inner) == 1 else None
    decl = expr.referenced if expr is not None else None
    return decl if decl is not None and decl.kind == CursorKind.VAR_DECL else None


def _handed_to_reader(call: Cursor, arg: Cursor, owned: Callable[[str], bool]) -> bool:
    """Whether ``call`` passes ``arg`` to a function (or constructor) of the workspace
    whose parameter there is an ``XmlRpcValue``."""
    target = call.referenced if call.kind == CursorKind.CALL_EXPR else None
    if target is None or target.kind not in (CursorKind.CONSTRUCTOR, CursorKind.CXX_METHOD,
                                             CursorKind.FUNCTION_DECL):
        return False
    where = target.location.file
    if where is None or not owned(where.name):
        return False
    args = written_arguments(call)
    params = [c for c in target.get_children() if c.kind == CursorKind.PARM_DECL]
    index = next((i for i, a in enumerate(args) if _same(strip(a), arg)), None)
    return index is not None and index < len(params) and is_struct_value(params[index].type)


def _with_parents(root: Cursor) -> Iterator[tuple[Cursor, Cursor | None]]:
    """Every cursor under ``root`` with the one it is a child of (through the implicit
    casts clang puts between them)."""
    stack: list[tuple[Cursor, Cursor | None]] = [(root, None)]
    while stack:
        node, parent = stack.pop()
        yield node, parent
        through = parent if node.kind == CursorKind.UNEXPOSED_EXPR else node
        stack.extend((child, through) for child in node.get_children())


def _map_keys(expr: Cursor, scope: Scope) -> list[str] | None:
    """The keys of the map given to ``declare_parameters(prefix, map)`` when it is
    written there, or is a local variable whose initialiser is and that nothing else in
    the body names, with string literals as keys (``std::map<std::string, int64_t>
    m{{"x", 5L}, {"y", -1L}};``: teleop_twist_joy's ``axis_linear`` map), else None."""
    inner = strip(expr)
    decl = inner.referenced if inner.kind == CursorKind.DECL_REF_EXPR else None
    value: Cursor | None = expr  # the map written in the call: std::map<..>{{"k", v}}
    if decl is not None:
        if decl.kind != CursorKind.VAR_DECL or scope.body is None:
            return None
        uses = sum(1 for node in walk_cursors(scope.body)
                   if node.kind == CursorKind.DECL_REF_EXPR and node.referenced is not None
                   and node.referenced == decl)
        value = scope.variable(decl) if uses == 1 else None
    if value is None:
        return None
    keys: list[str] = []
    for element in _elements(value):
        parts = [c for c in strip(element).get_children() if c.kind.is_expression()]
        first = strip(parts[0]) if parts else None
        key = literal(first.spelling) if first is not None and (
            first.kind == CursorKind.STRING_LITERAL) else None
        if key is None or element == value:
            return None
        keys.append(key)
    return keys or None



def _built_parameter(inner: Cursor, scope: Scope) -> Cursor | None:
    """The name argument of the ``rclcpp::Parameter`` construction that the local
    variable ``inner`` reads holds there (``Scope.held_before``: the last write that
    always runs before the read, no other use of the variable between them, a call it
    is passed to by reference or a branch's write): vanttec_usv's obstacle publisher
    writes ``m3.name`` by ``rclcpp::Parameter updated_param("m3.name", new_prefix);
    this->set_parameter(updated_param);``, and rclcpp names the parameter written by the
    object's own name. None for any other expression."""
    decl = inner.referenced if inner.kind == CursorKind.DECL_REF_EXPR else None
    if decl is None or decl.kind != CursorKind.VAR_DECL:
        return None
    _held, value = scope.held_before(decl, inner)
    return None if value is None else constructed_name(value, api.RCLCPP_PARAMETER)


def _elements(expr: Cursor, depth: int = 0, scope: Scope | None = None) -> list[Cursor]:
    """The elements of a braced list argument (``{a, b}``), else the argument itself;
    with the ``scope`` of the call, also those of the braced list a local variable it
    reads holds there (``Scope.held_before``: ``std::vector<rclcpp::Parameter>
    params{rclcpp::Parameter("a", 1)}; set_parameters(params);``)."""
    inner = strip(expr)
    if inner.kind == CursorKind.INIT_LIST_EXPR:
        return [c for c in inner.get_children() if c.kind.is_expression()]
    if inner.kind == CursorKind.CALL_EXPR and depth < 3:
        children = [c for c in inner.get_children() if c.kind.is_expression()]
        if len(children) == 1:
            found = _elements(children[0], depth + 1)
            if len(found) != 1 or found[0] != children[0]:
                return found
    decl = inner.referenced if inner.kind == CursorKind.DECL_REF_EXPR else None
    if scope is not None and decl is not None and decl.kind == CursorKind.VAR_DECL:
        _held, value = scope.held_before(decl, inner)
        found = _elements(value, depth + 1) if value is not None else [expr]
        if len(found) != 1 or found[0] != value:
            return found
    return [expr]


def _local_rules(args: list[Cursor], scope: Scope) -> RosArgs | None:
    """The ``__ns`` and ``__node`` rules among the local arguments of the
    ``NodeOptions`` a node construction is given (``node_options``), as rcl reads them
    after ``--ros-args`` (a ``__ns`` known not to be fully qualified is no rule); None
    where none is known."""
    from ...launch.ros2.naming import parse_ros_args, split_arguments

    for arg in args:
        if strip(arg).type.get_canonical().get_declaration().spelling != NODE_OPTIONS:
            continue
        words = local_arguments(arg, scope)
        if not words:
            return None
        found = parse_ros_args(split_arguments(words)[1], None)
        # (a value not wholly known here leaves the node as the code and the launch
        # name it: ``"__ns:=" + add_namespaces(parent, local)``)
        if found.namespace is not None and (
                not _plain_rule(found.namespace) or not found.namespace.startswith("/")):
            found.namespace = None
        if found.node_name is not None and not _plain_rule(found.node_name):
            found.node_name = None
        return found
    return None


def _base_initialiser(call: Cursor, function: Cursor | None) -> bool:
    """Whether ``call`` initialises a base of the class of constructor ``function``
    (``: rclcpp::Node("x", options)``, after the base's name; not a member's)."""
    if function is None or function.kind != CursorKind.CONSTRUCTOR:
        return False
    start, end = call.extent.start.offset, call.extent.end.offset
    before = None
    for child in function.get_children():
        if child.kind.is_expression() and (
                child.extent.start.offset <= start and end <= child.extent.end.offset):
            return before is not None and before.kind in (
                CursorKind.TYPE_REF, CursorKind.TEMPLATE_REF)
        before = child
    return False


def _plain_rule(value: str) -> bool:
    """Whether a rule's value is wholly known text (no part unknown, none a parameter's)."""
    return bool(value) and UNKNOWN_MARK not in value and PLACEHOLDER not in value


def _renames_itself(arg: Cursor) -> bool:
    """Whether a node's options carry a ``__node:=`` remap of their own: node-local
    arguments win over the process's, so neither the name in code nor a launch
    ``name=`` names that node (nav2's internal client nodes, made as ``"_"``)."""
    expr = strip(arg)
    if expr.type.get_canonical().get_declaration().spelling != "NodeOptions":
        return False
    target = expr.referenced if expr.kind == CursorKind.DECL_REF_EXPR else None
    source = target if target is not None and target.kind == CursorKind.VAR_DECL else expr
    if _names_node_rule(source, 400):
        return True
    # the options' arguments a local list the function fills: eloquent's and foxy's
    # nav2_util::LifecycleNode pushes ``"__node:=" + get_name() + "_rclcpp_node"`` into
    # ``new_args``, then builds ``rclcpp::Node("_", ns, NodeOptions(options).arguments(
    # new_args))``: a rule of that function's, where the list is written
    looked: set[int] = set()  # the functions looked through (each local's own)
    for node in source.walk_preorder():
        local = node.referenced if node.kind == CursorKind.DECL_REF_EXPR else None
        function = local.semantic_parent if local is not None and (
            local.kind == CursorKind.VAR_DECL) else None
        if function is None or function.kind not in FUNCTIONS or function.hash in looked:
            continue
        looked.add(function.hash)
        if _names_node_rule(function, MAX_RULE_TOKENS):
            return True
    return False


MAX_RULE_TOKENS = 4000  # of a function looked through for a ``__node:=`` rule


def _namespace_holder(expr: Cursor) -> Cursor | None:
    """The roscpp NodeHandle whose ``getNamespace()`` ``expr`` is (the namespace it
    resolves names in), else None."""
    call = strip(expr)
    target = call.referenced if call.kind == CursorKind.CALL_EXPR else None
    parent = target.semantic_parent if target is not None else None
    if target is None or target.spelling != "getNamespace" or parent is None or (
            qualified_name(parent) != "ros::NodeHandle") or written_arguments(call):
        return None
    return method_object(call)


def _names_node_rule(cursor: Cursor, limit: int) -> bool:
    """Whether the first ``limit`` tokens of ``cursor`` hold a ``__node:=`` rule."""
    for count, token in enumerate(cursor.get_tokens()):
        if count > limit:
            return False
        if "__node:=" in token.spelling:
            return True
    return False


def _on_passed_handle(name: str) -> bool:
    """Whether a parameter's name is a ROS 1 handle's namespace that another file
    passes (one placeholder, first) and a known name in it: ``~<name>/plugins``."""
    head, slash, rest = name.partition(f"{PLACEHOLDER}/")
    start, mark, _ = head.partition(PLACEHOLDER)
    return bool(slash) and mark == PLACEHOLDER and start in ("", "~", "/", "~/") and (
        known_name(rest)) and head.count(PLACEHOLDER) == 1


def _held_name(source: Source | None) -> str | None:
    """The parameter a condition's name holds the value of (``Condition.parameters``):
    known here, or read on a handle another file passes (``links`` fills it)."""
    if source is None or not (known_name(source[0]) or _on_passed_handle(source[0])):
        return None
    return source[0]


def known_name(name: str) -> bool:
    """A parameter's name known in this file: no unknown run, no placeholder of what
    another file passes, no parameter mark."""
    return not any(mark in name for mark in ("?", PLACEHOLDER, PARAMETER))


def _subscript(expr: Cursor) -> tuple[Cursor, Cursor] | None:
    """(container, index) of ``container[index]`` (a vector's ``operator[]`` or an
    array's subscript), else None."""
    if expr.kind == CursorKind.CALL_EXPR and expr.spelling == "operator[]":
        args = written_arguments(expr)
    elif expr.kind == CursorKind.ARRAY_SUBSCRIPT_EXPR:
        args = [c for c in expr.get_children() if c.kind.is_expression()]
    else:
        return None
    return (args[0], args[1]) if len(args) == 2 else None


def _element_field(expr: Cursor) -> tuple[Cursor, str] | None:
    """(the element, the field) of a string taken from a field of a list's element
    (``static_cast<std::string>(plugins[i]["name"])``: ROS 1's XmlRpcValue, an array of
    structs that ``getParam`` fills; costmap_2d's ``plugins``, move_base's
    ``recovery_behaviors``), through the string's copy and the value's conversion to a
    string, else None."""
    for _ in range(MAX_DEPTH):
        expr = strip(expr)
        target = expr.referenced if expr.kind == CursorKind.CALL_EXPR else None
        children = [c for c in expr.get_children() if c.kind.is_expression()]
        if target is not None and target.kind == CursorKind.CONSTRUCTOR and (
                len(children) == 1):
            expr = children[0]  # std::string(..), a copy of the converted value
        elif target is not None and target.kind == CursorKind.CONVERSION_FUNCTION:
            held = method_object(expr)  # value.operator std::string &()
            if held is None:
                return None
            expr = held
        else:
            break
    found = _subscript(expr)
    if found is None:
        return None
    key = strip(found[1])
    field = literal(key.spelling) if key.kind == CursorKind.STRING_LITERAL else None
    return (found[0], field) if field and field not in (".", EACH_WORD) else None


def _string_of_variable(expr: Cursor) -> Cursor | None:
    """The variable a string is constructed from (``std::string(s)``, the argument a
    function that wraps a ROS call is given for the name it completes), else None."""
    if expr.kind != CursorKind.CALL_EXPR or expr.referenced is None or (
            expr.referenced.kind != CursorKind.CONSTRUCTOR):
        return None
    children = [c for c in expr.get_children() if c.kind.is_expression()]
    held = strip(children[0]) if len(children) == 1 else None
    return held if held is not None and held.kind == CursorKind.DECL_REF_EXPR else None


def _unknown_operand(expr: Cursor, scope: Scope) -> Cursor | None:
    """The one operand of the string ``expr`` whose value is not known: itself when it
    names a variable, a member or an element (``list[i]``), else the one unknown
    operand of its concatenation; None when there are several or none."""
    inner = strip(expr)
    operands = [inner] if inner.kind in (
        CursorKind.DECL_REF_EXPR, CursorKind.MEMBER_REF_EXPR) or _subscript(
        inner) is not None else _unknown_operands(expr, scope)
    return strip(operands[0]) if len(operands) == 1 else None


# the methods of the standard containers and strings that change their object
_CHANGING = frozenset({
    "push_back", "emplace_back", "push_front", "emplace_front", "pop_back", "pop_front",
    "insert", "emplace", "erase", "clear", "resize", "assign", "swap", "append",
    "replace", "operator=", "operator+=", "reserve", "shrink_to_fit", "splice", "sort",
    "remove", "remove_if", "unique", "merge", "reverse", "operator>>"})


def _read_only(variable: Cursor, scope: Scope) -> bool:
    """Whether the body of ``scope`` only reads the local ``variable``: every use is an
    argument a call may not change (a value or a const reference), the object of a
    const method, or the range of a range-based ``for``."""
    if scope.body is None:
        return False
    key = place_of(variable)
    uses = safe = 0
    for node in walk_cursors(scope.body):
        kind = node.kind
        if kind == CursorKind.DECL_REF_EXPR:
            if node.referenced is not None and place_of(node.referenced) == key:
                uses += 1
        elif kind == CursorKind.CXX_FOR_RANGE_STMT:
            children = list(node.get_children())
            ranged = strip(children[1]) if len(children) > 1 else None
            if ranged is not None and ranged.kind == CursorKind.DECL_REF_EXPR and (
                    ranged.referenced is not None and place_of(ranged.referenced) == key):
                safe += 1
        elif kind == CursorKind.CALL_EXPR:
            target = node.referenced
            held = method_object(node)
            held = strip(held) if held is not None else None
            if held is not None and held.kind == CursorKind.DECL_REF_EXPR and (
                held.referenced is not None and place_of(held.referenced) == key
            ):
                if target is None or not target.is_const_method():
                    return False
                safe += 1
            for index, arg in enumerate(written_arguments(node)):
                arg = strip(arg)
                if arg.kind == CursorKind.DECL_REF_EXPR and arg.referenced is not None and (
                        place_of(arg.referenced) == key):
                    if may_write(node, index):
                        return False
                    safe += 1
    return uses == safe


def _element_loop(expr: Cursor, scope: Scope
                  ) -> tuple[Cursor | None, Cursor | None, str]:
    """The loop that makes ``expr`` each element of a list in turn, that list's
    expression, and how the list gives its elements (``PrimitiveCall.name_each``): a
    range-based ``for``'s variable, or ``list[i]`` in a ``for`` counting ``i`` from 0 up
    to ``list.size()`` (``EACH``); a ``while (stream >> word)`` over a string stream made
    of a string (``EACH_WORD``)."""
    if expr.kind == CursorKind.DECL_REF_EXPR and expr.referenced is not None:
        walk = scope.range_of(expr.referenced)
        if walk is not None:
            return walk, list(walk.get_children())[1], EACH
        words = scope.words_loop(expr.referenced)
        return (words[0], words[1], EACH_WORD) if words is not None else (
            None, None, EACH)
    found = _subscript(expr)
    if found is None:
        return None, None, EACH
    container, index = found[0], strip(found[1])
    if index.kind != CursorKind.DECL_REF_EXPR or index.referenced is None:
        return None, None, EACH
    walk = scope.counted_loop(index.referenced, container)
    return (walk, container, EACH) if walk is not None else (None, None, EACH)


def _loaded_element(expr: Cursor, scope: Scope) -> tuple[Cursor, str] | None:
    """(the loop, ``LOADED`` mark) when ``expr`` calls a method, with no argument, of the
    variable of a range-based ``for`` over a container a function returns (a local
    holding it, dereferenced or not): ``for (auto & layer : *layered_costmap_->
    getPlugins())`` ... ``layer->getName()``. Which plugins that container holds is not
    in the code the unit sees (the host adds each object it loads through another
    class's method): the host row says it (``hosts.Slot.kept``)."""
    expr = strip(expr)
    method = expr.referenced if expr.kind == CursorKind.CALL_EXPR else None
    if method is None or method.kind != CursorKind.CXX_METHOD or written_arguments(expr):
        return None
    held = method_object(expr)
    element = _dereferenced(held) if held is not None else None
    if element is None or element.kind != CursorKind.DECL_REF_EXPR or (
            element.referenced is None):
        return None
    walk = scope.range_of(element.referenced)
    if walk is None:
        return None
    container = _dereferenced(list(walk.get_children())[1])
    if container is not None and container.kind == CursorKind.DECL_REF_EXPR and (
            container.referenced is not None
            and container.referenced.kind == CursorKind.VAR_DECL):
        value = scope.variable(container.referenced)
        container = _dereferenced(value) if value is not None else None
    giver = container.referenced if container is not None and (
        container.kind == CursorKind.CALL_EXPR) else None
    if giver is None or giver.kind not in (CursorKind.CXX_METHOD, CursorKind.FUNCTION_DECL):
        return None
    return walk, loaded_mark(_function_name(giver), _function_name(method),
                             _cast_tested(walk, expr, element.referenced))


def _cast_tested(walk: Cursor, expr: Cursor, element: Cursor) -> str | None:
    """The class (qualified) the loop ``walk`` tests its element is of before ``expr``:
    ``expr`` in the branch of an ``if`` over a local (``x``, ``x != nullptr``) that holds
    ``std::dynamic_pointer_cast<C>(element)`` or ``dynamic_cast<C *>(..element..)``
    (navigation2's Costmap2DROS publishes only its layers that are CostmapLayers)."""
    body = list(walk.get_children())[-1]
    at = expr.extent.start.offset
    key = key_of(element)
    for node in walk_cursors(body):
        children = list(node.get_children())
        # ``if (auto x = ...)`` / ``if (auto x = ...; x)``: the declaration first
        declared = children[0] if children and children[0].kind in (
            CursorKind.VAR_DECL, CursorKind.DECL_STMT) else None
        children = children[1:] if declared is not None else children
        if node.kind != CursorKind.IF_STMT or len(children) < 2 or not (
                children[1].extent.start.offset <= at <= children[1].extent.end.offset):
            continue
        test = strip(children[0])
        # ``x``, ``x != nullptr`` (a smart pointer's ``operator!=``, ``operator bool``)
        tested = [test, *(strip(c) for c in test.get_children())] if (
            test.kind == CursorKind.BINARY_OPERATOR or (
                test.kind == CursorKind.CALL_EXPR and test.spelling.startswith("operator"))
        ) else [test]
        locals_ = [each.referenced for each in tested if each.kind == CursorKind.DECL_REF_EXPR]
        if declared is not None and declared.kind == CursorKind.VAR_DECL:
            locals_.append(declared)  # a condition's variable: its test is its value
        for local in locals_:
            if local is None or local.kind != CursorKind.VAR_DECL:
                continue
            made = initializer(local)
            cls = _cast_class(strip(made), key) if made is not None else None
            if cls is not None:
                return cls
    return None


def _cast_class(made: Cursor, element: Any) -> str | None:
    """The class ``made`` casts the loop's ``element`` to, dynamically; else None."""
    if made.kind == CursorKind.CALL_EXPR and made.spelling == "dynamic_pointer_cast":
        target = made.type.get_canonical()
        cls = target.get_template_argument_type(0) if (
            target.get_num_template_arguments() > 0) else None
    elif made.kind == CursorKind.CXX_DYNAMIC_CAST_EXPR:
        cls = made.type.get_canonical().get_pointee()
    else:
        return None
    if cls is None or not any(c.kind == CursorKind.DECL_REF_EXPR and c.referenced is not None
                              and key_of(c.referenced) == element
                              for c in walk_cursors(made)):
        return None
    decl = cls.get_canonical().get_declaration()
    return qualified_name(decl) or None if decl.kind in (
        CursorKind.CLASS_DECL, CursorKind.STRUCT_DECL) else None


def _function_name(function: Cursor) -> str:
    """A function's (or method's) qualified name: ``demo::Stack::getLayers``."""
    owner = qualified_name(function.semantic_parent)
    return f"{owner}::{function.spelling}" if owner else function.spelling


def _dereferenced(expr: Cursor) -> Cursor | None:
    """``expr`` without a dereference (``*p``, a smart pointer's ``operator*`` or
    ``operator->``) around it."""
    expr = strip(expr)
    for _ in range(MAX_DEPTH):
        if expr.kind == CursorKind.UNARY_OPERATOR and expr.spelling in ("*", ""):
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            if len(inner) != 1:
                return expr
            tokens = [t.spelling for t in expr.get_tokens()][:1]
            if tokens != ["*"]:
                return expr
            expr = strip(inner[0])
        elif expr.kind == CursorKind.CALL_EXPR and expr.spelling in ("operator*",
                                                                      "operator->"):
            inner = [c for c in expr.get_children() if c.kind.is_expression()]
            operands = [c for c in inner if strip(c).spelling != expr.spelling]
            if len(operands) != 1:
                return expr
            expr = strip(operands[0])
        else:
            return expr
    return expr


def _constructed_global(variable: Cursor) -> bool:
    """Whether ``variable``, of namespace scope, is built by a constructor call that
    passes it arguments."""
    parent = variable.semantic_parent
    if parent is None or parent.kind not in (CursorKind.NAMESPACE,
                                             CursorKind.TRANSLATION_UNIT):
        return False
    made = initializer(variable)
    made = strip(made) if made is not None else None
    return made is not None and made.kind == CursorKind.CALL_EXPR and (
        made.referenced is not None and made.referenced.kind == CursorKind.CONSTRUCTOR
    ) and any(c.kind.is_expression() for c in made.get_children())


def _unknown_operands(expr: Cursor, scope: Scope) -> list[Cursor]:
    """The operands of a string concatenation (``a + b + c``) whose value is not known,
    in the order written; empty when ``expr`` is no concatenation."""
    return [each for each in _concatenated(expr, scope) if each is not None]


def _unknown_runs(expr: Cursor, scope: Scope) -> list[list[Cursor]]:
    """The operands ``_unknown_operands`` gives, grouped by the ``?`` of the name they
    make (``values.render``): operands with no known text between them are one run
    (ros_kortex's ``"/" + robot_name + "/" + prefix + arm + "_controller"``: [robot_name],
    [prefix, arm])."""
    runs: list[list[Cursor]] = []
    apart = True  # known text since the last unknown operand
    for each in _concatenated(expr, scope):
        if each is None:
            apart = True
        elif apart or not runs:
            runs.append([each])
            apart = False
        else:
            runs[-1].append(each)
    return runs


def _concatenated(expr: Cursor, scope: Scope, depth: int = 0) -> list[Cursor | None]:
    """The unknown operands of a string concatenation in the order written, with None
    where known text stands between them (before, between or after: an operand whose
    own value begins or ends with known text gives it too)."""
    expr = strip(expr)
    if depth > MAX_DEPTH:
        return []
    children = [c for c in expr.get_children() if c.kind.is_expression()]
    if expr.kind == CursorKind.CALL_EXPR and expr.spelling == "operator+":
        operands = written_arguments(expr)
    elif expr.kind == CursorKind.BINARY_OPERATOR and len(children) == 2 and (
            binary_operator(expr, children) == "+"):
        operands = children
    elif expr.kind == CursorKind.CALL_EXPR and expr.referenced is not None and (
            expr.referenced.kind == CursorKind.CONSTRUCTOR and len(children) == 1):
        return _concatenated(children[0], scope, depth + 1)  # std::string(a + b)
    elif permissive_conversion(expr):
        # a concatenation with a permissive value (``prefix + "/" + layer``, the layer of
        # a library the parse does not have), converted to the string the call takes
        held = permissive_held(expr)
        return [] if held is None else _concatenated(held, scope, depth + 1)
    elif expr.kind == CursorKind.CALL_EXPR and expr.spelling == "str" and (
            streamed := scope.stream_operands(expr)) is not None:
        # what a local string stream was written (``ss << "/" << base << "/goals";
        # ss.str()``), as the operands of a concatenation
        operands = streamed
    else:
        return []
    found: list[Cursor | None] = []
    for operand in operands:
        parts = scope.string(operand)
        if None not in parts:
            if any(_text(part) for part in parts):
                found.append(None)
            continue
        inner = _concatenated(operand, scope, depth + 1)
        if any(each is not None for each in inner):
            found += inner
            continue
        found += [None] if _text(parts[0]) else []
        found.append(operand)
        found += [None] if _text(parts[-1]) else []
    return found


def _text(part: str | None) -> bool:
    """Whether a part of a string's value is text a name shows (``values.render``), not
    empty and no ``?``."""
    return bool(part) and not isinstance(part, (NodeName, ProgramArgument, ProgramOption))


def _name_namespace(name: str) -> str:
    """The namespace of a call's name, as written (``~image_raw``: ``~``): where the
    names beside it go (a server's topics, a camera's camera_info, a reconfigure
    server's parameters). A last segment not known (``?``, or ``cam?``) may hold more
    segments at run time: its namespace is not known either (depthai's camera publisher
    of ``pubConfig.topicName + pubConfig.topicSuffix``, a name not known at all, has its
    camera_info somewhere, ``?/camera_info``, not ``camera_info`` at the node's
    namespace)."""
    head, slash, last = name.rpartition("/")
    if UNKNOWN_MARK in last and PLACEHOLDER not in last:
        return f"{head}/{UNKNOWN_MARK}" if slash else (
            "~" + UNKNOWN_MARK if name.startswith("~") else UNKNOWN_MARK)
    return head if slash else ("~" if name.startswith("~") else "")


def _option_fields(written: str, name: str) -> dict[str, Any]:
    """The fields of a call whose name's one ``?`` is a getopt option's argument
    (``OptionName``): ``PrimitiveCall.name_option``, ``name_getopt``,
    ``name_option_default``, ``name_option_null``."""
    if not isinstance(written, OptionName) or name.count("?") != 1:
        return {}
    option = written.option
    return {"name_option": option.flags, "name_getopt": option.spec,
            "name_option_default": option.default, "name_option_null": option.null}
