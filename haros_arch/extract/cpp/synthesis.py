"""Permissive declarations for the names clang does not know, so that one unknown name
(a vendor library's type, a namespace whose header is missing, an unknown base class or
template) does not make a node's class invalid and cost it every call.

From the errors of a parse (``unknown type name 'X'``, ``use of undeclared identifier
'ns'``, ``no type named 'Y' in namespace 'ns'``, ``no template named 'T'``, ``expected
class name``, ``no member named 'm' in 'Synthesised'``) and the source text at each
error, ``Names`` collects what each unknown name is used as: a scope (``ns::``), a type,
a template (``T<``), a value. ``Names.header()`` renders them over one class,
``haros_any``, that can be built from anything, converts to anything, and has every
member it was asked for (static members of its own type, so ``obj.m(args)``,
``ptr->m`` and ``m`` as a value all parse); scopes become namespaces, or nested classes
when the name is also a type. A name read where C++ needs a constant (a case label,
an enumerator's initialiser, ``static_assert``, a ``constexpr`` initialiser, an array's
bound) is an enumerator instead, of a value of its own, and the permissive class
converts to an integral enum a ``switch`` can use. The header is prepended to the unit
(``-include``) and the unit parsed again in full, and that parse is kept when it has
fewer errors. With ``MAX_ROUNDS`` above 1, parses without function bodies look for
further waves of names first (a class made valid shows its other members); on real
workspaces they changed little and cost a parse each, so the default is one round.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import os
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from ...ctext import closing, code_only, integer_literal
from . import interfaces, msg_types

MAX_ROUNDS = 1  # rounds of declaring unknown names (0: none; more: probes for waves)
# full parses with the declared names: a second one only when the first leaves an error
# that can cost a call (``recall``) and that error names something not declared yet (a
# wave: a name that only shows once the classes around it are valid). The members read
# after ``.`` / ``->`` in the files with errors are declared from the first: a member
# of a vendor object is otherwise the usual second wave (fixtures/cpp/unknown_names/
# vendor_member.cpp, vendor_waves.cpp)
FULL_PARSES = 2
MAX_NAMES = 400  # names declared for one unit
HEADER_NAME = "haros_synthesised_names.h"
ANY = "haros_any"  # the permissive class every declared name is or derives from
# the members a unit uses on the classes of the Qt stand-in (haros_qt.h) that it does not
# declare: a base of its classes, defined with them here (mapviz's ``QWidget::
# setMaximumSize``, autorally's ``QPainter::drawRect``: a GUI node's constructor, where
# it makes its ROS calls, was an error at each; the stand-in cannot list all of Qt)
QT_MORE = "haros_qt_more"

_IDENT = re.compile(rb"[A-Za-z_]\w*")
_NAME_AT = re.compile(rb"[A-Za-z_]\w*(?:\s*::\s*(?:template\s+)?[A-Za-z_]\w*)*")
_SCOPE_BEFORE = re.compile(rb"(?:[A-Za-z_]\w*\s*::\s*)+$")


def _scope_before(window: bytes) -> re.Match[bytes] | None:
    """The scope (``a::b::``) ``window`` ends with, if any: only a window ending in
    ``::`` can match (a search of the pattern alone tries every position of it)."""
    return _SCOPE_BEFORE.search(window) if window.rstrip().endswith(b"::") else None


def _unscoped(window: bytes) -> bytes:
    """``window`` without the scope it ends with (``_scope_before``)."""
    before = _scope_before(window)
    return window[:before.start()] if before is not None else window

_KEYWORDS = frozenset({
    "const", "volatile", "unsigned", "signed", "int", "long", "short", "char", "bool",
    "double", "float", "void", "auto", "struct", "class", "typename", "template",
    "namespace", "public", "private", "protected", "virtual", "static", "return", "new",
    "delete", "operator", "this", "using", "typedef", "enum", "union", "if", "else",
    "for", "while", "do", "switch", "case", "default", "break", "continue", "sizeof",
    "true", "false", "nullptr", "decltype", "inline", "extern", "constexpr", "final",
    "override", "noexcept", "std", "haros_any"})

# message -> (how the name at the location is used: "type", "template", "any")
_MESSAGES: tuple[tuple[re.Pattern[str], str], ...] = (
    (re.compile(r"^unknown type name '([\w:]+)'"), "type"),
    (re.compile(r"^no type named '(\w+)' in namespace '([\w:]+)'"), "type"),
    (re.compile(r"^no template named '(\w+)' in namespace '([\w:]+)'"), "template"),
    (re.compile(r"^no template named '(\w+)'$"), "template"),
    (re.compile(r"^use of undeclared identifier '(\w+)'"), "any"),
    (re.compile(r"^no member named '(\w+)' in namespace '([\w:]+)'"), "any"),
    (re.compile(r"^expected class name$"), "type"),
    (re.compile(r"^unknown class name '(\w+)'"), "type"),
    # ``::isaac_ros::common::ParseQosString(..)`` in ``namespace nvidia::isaac_ros``, with
    # no global ``isaac_ros`` declared (isaac_ros_common's header missing): clang names
    # the nested namespace's name in its message
    (re.compile(r"^'(\w+)' is not a class, namespace, or enumeration$"), "any"),
)
_MEMBER = re.compile(
    r"^no member named '(\w+)' in '(?:const )?(?:(?:struct|class) )?([\w:]+)(<.*>)?'")
_MEMBER_TYPE = re.compile(  # ``Msg::_code_type``; ``Synthesised<T>::ConstPtr``
    r"^no type named '(\w+)' in '(?:const )?(?:(?:struct|class) )?([\w:]+)(<.*>)?'")
# a member of a declared class named where a declaration's type goes: the name, then
# the declared variable (``vendor::Reg<T>::Ptr reg(new vendor::Reg<T>());``, pcl-style
# code with a vendor's registration class). In a function body clang reads the unknown
# member as a value ("no member named"), not as a type ("no type named"); a static
# member there makes ``expected ';'`` and the variable undeclared, and every call on it
# (``reg->setThreads(pnh.param<int>("threads", 0))``) was lost with its ROS call
_MEMBER_DECLARING = re.compile(
    rb"\s*(?:[*&](?![&=])\s*)?(?:const\s+)?([A-Za-z_]\w*)\s*[(;={\[]")
_AMBIGUOUS = re.compile(r"^reference to '(\w+)' is ambiguous")
# a class of the code built from a declared value (bebop_driver's ``AbstractState(
# ARCONTROLLER_DICTIONARY_KEY_...)``, whose one constructor takes libARController's enum
# type, its header missing): the permissive value converts to the enum's declared class
# and, through ``operator T &``, to the class itself, for its copy constructor; a
# constant (an enumerator) converts to the declared class only
_CONSTRUCTION_AMBIGUOUS = re.compile(r"^call to constructor of '(?:const )?[\w:]+(?:<.*>)?' "
                                     r"is ambiguous")
_CALLED_AT = re.compile(rb"(?:[A-Za-z_]\w*\s*::\s*)*[A-Za-z_]\w*\s*[({]")
# a member of the permissive class that a class finds twice: through a declared base and
# through a real one (rtabmap's ``OdometryROS : public rclcpp::Node, public UThread``,
# once ``get_logger`` is read on some object): the real base's it is
_AMBIGUOUS_MEMBER = re.compile(r"^member '(\w+)' found in multiple base classes of different types")
# a pointer to one declared class given where a pointer to another is wanted (motoman's
# ``init(&default_tcp_connection_)``, a TcpClient for a SmplMsgConnection): the vendor's
# classes derive so
_POINTER_TO = re.compile(
    r"^(?:cannot initialize (?:a parameter|a variable|a member subobject|return object) "
    r"of type '(?:const )?([\w:]+) \*' with an [lr]value of type '(?:const )?([\w:]+) \*'"
    r"|(?:incompatible pointer types )?assigning to '(?:const )?([\w:]+) \*' from "
    r"(?:incompatible type )?'(?:const )?([\w:]+) \*')")
# a pointer to one declared class cast to a pointer to another (stage_ros'
# ``static_cast<Stg::Model*>(robot->positionmodel)``, a ``Stg::ModelPosition *``, in the
# arguments of its advertise calls): one derives from the other, either way round, so
# the cast is an up- or a down-cast
_CAST_UNRELATED = re.compile(
    r"^static_cast from '(?:const )?([\w:]+) \*' to '(?:const )?([\w:]+) \*', which are "
    r"not related by inheritance")
# a ``dynamic_cast`` of a pointer to a declared class (stage_ros' ``dynamic_cast<Stg::
# ModelRanger *>(mod)`` of a ``Stg::Model *``): the class has a virtual destructor
_NOT_POLYMORPHIC = re.compile(r"^'([\w:]+)' is not polymorphic")
# a value given to a declared template (``template <class... T>``), at the argument:
# boost::array<double, 9> (naoqi's camera infos, through a missing boost header),
# Eigen's DiagonalMatrix<double, 3>, Sophus::Vector<Scalar, M>
_VALUE_ARGUMENT = re.compile(r"^template argument for template type parameter must be a type")
# the same, in the note of a candidate of a call no overload takes (``_Error.notes``)
_NOT_CONVERTED = re.compile(
    r"^candidate .*no known conversion from '(?:const )?([\w:]+) \*' to "
    r"'(?:const )?([\w:]+) \*' for")
# a class the code only declares (``namespace libcamera { class CameraManager; }`` in
# camera_ros' own headers) and whose defining header is missing, used where C++ needs
# it complete: a field of it makes the class that holds it invalid, and every call in
# that class's code fails (camera_ros' CameraNode: its declare_parameter and
# create_publisher calls)
_INCOMPLETE = re.compile(
    r"^(?:field has |member access into |variable has |initialization of |)"
    r"incomplete (?:result )?type '(?:const )?(?:(?:struct|class) )?"
    r"([A-Za-z_]\w*(?:::[A-Za-z_]\w*)*)'")
_RECORD = re.compile(r"[a-z]\w*(?:::\w+)+")  # a message's struct: ``pkg::msg::Name``
# a name after ``.`` or ``->``; a number is matched whole first, with no name, so that
# the ``.`` of a float literal gives none (``1.e5``, ``2.f``: no member ``e5``, ``f``)
_AFTER_MEMBER = re.compile(rb"\b[0-9](?:[eEpP][-+]|[\w.])*|(?:\.|->)\s*([A-Za-z_]\w*)")
# a template argument that is a type's bare name, ``Name`` (``Names._arguments_after``)
_BARE_ARGUMENT = re.compile(rb"\s*([A-Z]\w*)\s*[,>]")
_TEMPLATE_SPAN = 400  # bytes searched back for the ``<`` of a template argument list
_VALUE_LITERAL = re.compile(rb"\s*(?:[-+(]?\s*[0-9]|(?:true|false|sizeof)\b)")
_VALUE_WRITTEN = re.compile(
    rb"\s*(?:[-+(]?\s*[0-9]|(?:true|false|sizeof)\b|[A-Z][A-Z0-9_]*\b(?!\s*(?:<|::)))")
_SCOPE_NAME_BEFORE = re.compile(rb"[A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*\s*$")
# a member template named with C++'s ``template`` keyword (``bb->template set<T>(k, v)``,
# where the object's type depends on a template parameter or is unknown)
# what is no code where members are read: comments, string and character literals,
# #include lines
_NOT_CODE = re.compile(
    rb'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|^[ \t]*#[ \t]*include[^\n]*',
    re.DOTALL | re.MULTILINE)
_TEMPLATE_MEMBER = re.compile(rb"(?:\.|->)\s*template\s+([A-Za-z_]\w*)\s*<")
_NOT_TEMPLATE = re.compile(
    r"^'(\w+)' following the 'template' keyword does not refer to a template")
# a member of a declared object called with template arguments (plansys2's
# ``factory.registerNodeType<ExecuteAction>("ExecuteAction");`` of BehaviorTree.CPP)
_NAMES_NO_TEMPLATE = re.compile(
    r"^'(\w+)' does not name a template but is followed by template arguments")
# the object of a member call written as a statement's start: a name, ``this->``, and
# members after ``.`` / ``->``
_STATEMENT_OBJECT = re.compile(
    rb"(?:^|[;{}])\s*(?:this\s*->\s*)?[A-Za-z_]\w*(?:\s*(?:\.|->)\s*[A-Za-z_]\w*)*"
    rb"\s*(?:\.|->)\s*$")
# the object of a member call written as an ``if`` or ``while`` condition's start
# (``if (profile.is<rs2::video_stream_profile>())``, realsense2_camera's): its value is
# only tested
_TESTED_OBJECT = re.compile(
    rb"\b(?:if|while)\s*\(\s*!?\s*(?:this\s*->\s*)?[A-Za-z_]\w*"
    rb"(?:\s*(?:\.|->)\s*[A-Za-z_]\w*)*\s*(?:\.|->)\s*$")
# the object of a member written as what a call returns: ``list_of("a")("b").``
_CALLED_OBJECT = re.compile(rb"\)\s*\.\s*$")
# a statement that assigns to a variable or member that exists (``a.b = ``, ``p_->x = ``;
# not a declaration, ``auto x = ``, nor ``==``)
_ASSIGNED = re.compile(rb"\s*(?:this\s*->\s*)?[A-Za-z_]\w*(?:\s*(?:\.|->)\s*[A-Za-z_]\w*)*"
                       rb"(?:\s*\[[^\[\];{}]*\])?\s*=(?!=)")
# a value read from a scope: ``Mode::FAST)``, ``case Mode::FAST:``, an enumerator of a
# vendor enum
_SCOPED_VALUE = re.compile(rb"::\s*([A-Za-z_]\w*)\s*(?=[);,\]}]|:(?!:))")
# the name written next is what an alias, a typedef or a using-declaration names
_ALIASED = re.compile(rb"(?:\busing\s+\w+\s*=|\btypedef|\busing)\s*(?:typename\s+)?(?:::\s*)?"
                      rb"(?:[A-Za-z_]\w*\s*::\s*)*$")


@functools.cache
def _qt_text() -> str:
    from .headers import QT, STANDIN

    with open(os.path.join(STANDIN, QT), encoding="utf-8") as handle:
        return code_only(handle.read())


@functools.cache
def _qt_classes() -> frozenset[str]:
    """The classes the Qt stand-in defines (``QT_MORE`` is a base of each)."""
    return frozenset(re.findall(r"\bclass (Q\w+)(?= :| \{)", _qt_text()))


def _template_called(text: bytes, end: int) -> bool:
    """Whether the template arguments at ``end`` (``<...>``) are followed by ``(``: a
    function template's call."""
    depth = 0
    for at in range(end, min(len(text), end + 400)):
        char = text[at:at + 1]
        if char == b"<":
            depth += 1
        elif char == b">":
            depth -= 1
            if depth == 0:
                return text[at + 1:at + 40].lstrip()[:1] == b"("
        elif char in b";{}" or (depth == 0 and not char.isspace()):
            return False
    return False


def _member_named(text: bytes, offset: int) -> bool:
    """Whether the name at ``offset``, with the scope written before it, follows ``.`` or
    ``->``: a member access naming the member with its class (``obj.Base::m``)."""
    return _unscoped(text[max(0, offset - 200):offset]).rstrip().endswith((b".", b"->"))


def _discarded_member_call(text: bytes, offset: int, name: str) -> bool:
    """Whether the member template ``name`` at ``offset`` is called as a whole statement,
    ``obj.name<T>(args);``, its result unused, or as a whole condition, ``if
    (obj.name<T>())`` (or its first operand before ``&&`` / ``||``), its result only
    tested, or called on what a chain of calls
    returns and assigned whole to a variable or member that exists (a builder's:
    ``names = boost::assign::list_of("a")("b").convert_to_container<ros::V_string>();``,
    Doosan's dsr_control, boost's header not read; the variable keeps its own type):
    declared a member template (any template arguments, any call
    arguments), nothing is then read from what it returns, whose own ROS calls would be
    lost (``x.get<T>("node")->create_publisher(...)``, which is better left an error
    and kept by its API name)."""
    if not text.startswith(name.encode(), offset):
        return False
    # or the whole of a condition (or its first operand), ``if (obj.name<T>())``
    tested = _TESTED_OBJECT.search(text[max(0, offset - 200):offset]) is not None
    if not tested and _STATEMENT_OBJECT.search(text[max(0, offset - 200):offset]) is None:
        # or the member of what a chain of calls returns, assigned whole (a builder)
        before = text[max(0, offset - 2000):offset]
        start = max(before.rfind(b";"), before.rfind(b"{"), before.rfind(b"}")) + 1
        if _CALLED_OBJECT.search(before) is None or _ASSIGNED.match(before, start) is None:
            return False
    pairs = {ord("<"): ord(">"), ord("("): ord(")")}
    stack: list[int] = []
    called = False
    for at in range(offset + len(name), min(len(text), offset + 2000)):
        char = text[at]
        if char in pairs:
            stack.append(pairs[char])
        elif stack and char == stack[-1]:
            stack.pop()
            called = called or (not stack and char == ord(")"))
        elif char in (ord(";"), ord("{"), ord("}")) and stack:
            return False
        elif not stack and not chr(char).isspace():
            return called and (char == ord(";") or (tested and char in b")&|"))
    return False


@functools.lru_cache(maxsize=1)
def _api_methods() -> frozenset[str]:
    """The API's methods (longer than four letters, as ``recall`` counts them: ``get`` /
    ``set`` / ``call`` are any class's), which stay the API's: a class built on a real
    node and a declared class would find such a member twice, and a call the parse
    cannot resolve is kept by that name; not a name too common to be the API's
    (``call_site``: realtime_tools' ``initialize``, which an unknown class's method of
    that name, kinematics_interface's, must still be)."""
    from . import api
    return frozenset(name for (_, name), row in api.ALL.items()
                     if len(name) > 4 and row.call_site)


# an alias declaration before the name: what it names is a type, whatever its case
# (foxglove_bridge's ``using ConnectionHandle = websocketpp::connection_hdl;``)
_ALIAS_DECLARED = re.compile(rb"(?:\busing\s+\w+\s*=|\btypedef)\s*(?:typename\s+)?"
                             rb"(?:::\s*)?(?:[A-Za-z_]\w*\s*::\s*)*$")


def _aliased(window: bytes) -> bool:
    """Whether ``window`` ends where an alias, typedef or using-declaration names what
    follows (``_ALIASED``; a window without either word cannot match)."""
    return (b"using" in window or b"typedef" in window) and _ALIASED.search(window) is not None


# where C++ needs a constant expression, the text before a name read as a value: a
# case label (``case vendor::MODE_A:``, ``case enum_value(Mode::FAST):``, ``case A | B:``),
# a ``static_assert``, a ``constexpr`` variable's initialiser, an array's bound
# (``char buf[VND_SIZE]``) or an enumerator's initialiser (``ok = vendor::FRAMING_OK,``);
# such a name is declared an enumerator, with a value of its own (``Names.header``)
_CONSTANT_SPAN = 400  # bytes before a name searched for its statement
_ENUM_SPAN = 4000  # bytes before a name searched for the brace of an enum's body
_CASE_WORDS = re.compile(rb"\b(?:case|static_assert)\b")
# ``case (`` then the scope written before a name: the label's value in parentheses
_CASE_OPEN = re.compile(rb"\bcase\s*\(\s*(?:[A-Za-z_]\w*\s*::\s*)*$")
_CONSTEXPR = re.compile(rb"\bconstexpr\b")
_COMBINING = (b"|", b"&", b"^", b"+", b"-")
# a declaration before ``[``: a type, then the declared name (``char errbuf_``,
# ``static uint8_t buf``), not an expression (``images[``, ``msg.data[``, ``x = table[``)
_DECLARED_ARRAY = re.compile(rb"^\s*(?:(?:static|const|constexpr|unsigned|signed|struct)\s+)*"
                             rb"(?!(?:return|case|delete|throw|else|do|goto)\b)"
                             rb"[A-Za-z_][\w:]*(?:\s*<[^;=()]*>)?[\s*&]+[A-Za-z_]\w*\[$")
_ENUM_HEAD = re.compile(rb"\benum\b(?:\s+(?:class|struct)\b)?(?:\s+[A-Za-z_]\w*)?"
                        rb"(?:\s*:\s*[\w:\s]+)?\s*$")
# the integers the code writes in case labels: no declared constant takes one of them
# (``case 0: ... case vendor::MODE_A:`` would be a duplicate case value)
_CASE_LITERAL = re.compile(rb"\bcase\s*\(?\s*(0[xX][0-9a-fA-F]+|\d+)[uUlL]*\s*\)?\s*:(?!:)")


# a class's head up to its body: the name (after any export macro) and its base list
_CLASS_HEAD = re.compile(
    rb"\b(?:class|struct)\s+(?:[A-Za-z_]\w*\s+)*?([A-Za-z_]\w*)\s*(?:final\s*)?:(?!:)([^{;]*)\{")
_ACCESS = re.compile(r"\b(?:public|protected|private|virtual)\b")


def _class_heads(code: bytes) -> list[tuple[str, list[str]]]:
    """The classes ``code`` defines with a base list, each with its bases' names as
    written, without their template arguments (``Singleton<OpenCRModule>``:
    ``Singleton``) or a leading ``::``."""
    heads = []
    for found in _CLASS_HEAD.finditer(code):
        written = found.group(2).decode(errors="replace")
        depth = 0
        part: list[str] = []
        parts: list[str] = []
        for char in written:  # the commas between bases, not within template arguments
            if char == "<":
                depth += 1
            elif char == ">":
                depth -= 1
            elif char == "," and depth == 0:
                parts.append("".join(part))
                part = []
                continue
            if depth == 0 and char != ">":
                part.append(char)
        parts.append("".join(part))
        bases = [re.sub(r"\s+", "", _ACCESS.sub("", p)).removeprefix("::") for p in parts]
        heads.append((found.group(1).decode(), [b for b in bases if b]))
    return heads


def _case_literals(text: bytes) -> set[int]:
    """The integers ``text`` writes in case labels (``_CASE_LITERAL``; a leading 0 is
    octal, as in C, and a number that is none is left out)."""
    values = (integer_literal(literal.decode()) for literal in _CASE_LITERAL.findall(text))
    return {value for value in values if value is not None}  # ``case 09:`` is not C


# the uses of a name read only as a value (a constant, of its kinds)
_VALUE_USES = frozenset({"value", "constant", "flag", "size"})


def _constant_at(name: str, text: bytes, offset: int, end: int) -> str | None:
    """How the ``name`` written from ``offset`` (the start of its qualified name or of
    its last part) to ``end`` is read where C++ needs a constant expression
    (``_CONSTANT_SPAN`` comments): "flag" when an operator combines it with another
    (``case A | B:``, ``N + 16``: the two need bits of their own, or ``A | B`` may be
    the value of a third), "size" for an array's bound or a template's argument (a
    value above the small ones: an initialiser may list more elements), "constant"
    else, None when it is not such a place."""
    # not the scope written before the name
    window = _unscoped(text[max(0, offset - _CONSTANT_SPAN):offset]).rstrip()
    after = text[end:end + 8].lstrip()[:2]
    kind = "flag" if window[-1:] in _COMBINING or (
        after[:1] in _COMBINING and after not in (b"->", b"||", b"&&")) else "constant"
    statement = window[max(window.rfind(b";"), window.rfind(b"{"), window.rfind(b"}")) + 1:]
    if window.endswith(b"[") and _DECLARED_ARRAY.search(statement):
        # an array's bound in its declaration (``buffer[N]`` is a subscript)
        return "size" if kind == "constant" else kind
    if _CONSTEXPR.search(statement):
        return kind
    argument = _value_start(window)
    if argument[-1:] in (b"<", b",") and _CONSTANT.fullmatch(name) and _template_argument(
            argument) and _TYPE_FIRST.search(argument) is None:
        # a template's argument in capitals (``std::array<std::string,
        # KUKA::FRI::LBRState::NUMBER_OF_JOINTS>``, the robot SDK's header missing): a
        # non-type argument needs a constant, as an array's bound does, and is often a
        # size (the array's initialiser lists the seven joints)
        return "size" if kind == "constant" else kind
    labels = list(_CASE_WORDS.finditer(statement))
    if labels and b":" not in statement[labels[-1].end():].replace(b"::", b""):
        return kind  # in the label's expression, up to its colon
    if _CONSTANT.fullmatch(name) and (
            (window.endswith(b"?") and _NUMBER_AFTER_COLON.match(text, end) is not None)
            or _NUMBER_BEFORE_COLON.search(window) is not None):
        # a constant in capitals one branch of a conditional whose other is a number
        # (vectornav's ``adjust ? COMMONGROUP_TIMESTARTUP : 0`` among the binary output
        # groups it ORs together, the SDK's header missing): a permissive value converts
        # to the number's type and is built from it, so clang finds the conditional
        # ambiguous; an enumerator only converts, as the library's own does. A bit of
        # its own: such a constant is a flag more often than not
        return "flag"
    return kind if _in_enum_body(text, offset) else None


# what may come between a template argument's start and a constant in it: a cast
# (``static_cast<int>(``), a parenthesis, an integer and an arithmetic operator (``3 *``)
_VALUE_PREFIX = re.compile(rb"(?:\bstatic_cast\s*<[^<>;{}()]*>\s*\(|\(|\b\d+[uUlL]*\s*[-+*])\s*$")


def _value_start(window: bytes) -> bytes:
    """``window`` (the text before a name) without the casts, parentheses and products
    by an integer the name is written in (``_VALUE_PREFIX``): nao_lola's ``std::array<float,
    3 * static_cast<int>(Leds::NUM_LEDS)>`` is a template's argument as ``<float, N>``."""
    window = window.rstrip()
    while (found := _VALUE_PREFIX.search(window)) is not None:
        window = window[:found.start()].rstrip()
    return window


# the standard's templates whose first argument is a type, right before a name: the name
# is that type (zed's ``std::unordered_set<sl::MODULE>``, the SDK's enum, which a
# constant made an error that left ZedCamera invalid), not a constant; so are boost's
# of those names and OpenCV's smart pointer (ORB_SLAM3_ROS2's ``cv::Ptr<cv::CLAHE>``
# member, an acronym's class: read as a constant, the class was invalid and every
# subscription of its constructor unresolved)
_TYPE_FIRST = re.compile(
    rb"(?:\b(?:std|boost)\s*::\s*(?:vector|set|unordered_set|multiset|unordered_multiset|"
    rb"map|unordered_map|multimap|unordered_multimap|list|forward_list|deque|queue|"
    rb"priority_queue|stack|shared_ptr|unique_ptr|weak_ptr|optional|atomic)"
    rb"|\bcv\s*::\s*Ptr)\s*<\s*$")


def _template_argument(window: bytes) -> bool:
    """Whether ``window`` (the text before a name, ending with ``<`` or ``,``) ends in
    a template's argument list."""
    return _argument_list_open(window) is not None


def _argument_list_open(window: bytes) -> int | None:
    """Where in ``window`` the template argument list it ends in opens (its ``<``):
    back to an unmatched ``<`` after a name, through balanced brackets, before any
    ``;``, ``{``, ``}`` or unmatched opening bracket; None when it ends in none."""
    depth, at = 0, len(window) - 1
    while at >= 0 and len(window) - at < _TEMPLATE_SPAN:
        char = window[at:at + 1]
        if char in b">)]":
            depth += 1
        elif char in b"([":
            if depth == 0:
                return None
            depth -= 1
        elif char == b"<":
            if depth == 0:
                return at if _SCOPE_NAME_BEFORE.search(
                    window[max(0, at - 200):at]) is not None else None
            depth -= 1
        elif char in b";{}":
            return None
        at -= 1
    return None


def _in_enum_body(text: bytes, offset: int) -> bool:
    """Whether ``offset`` is in an enumerator's initialiser: after an ``=`` in the body
    of an ``enum``, before the next enumerator."""
    start = max(0, offset - _ENUM_SPAN)
    brace = text.rfind(b"{", start, offset)
    if brace < 0 or max(text.rfind(b"}", brace, offset), text.rfind(b";", brace, offset)) >= 0:
        return False
    enumerator = text[max(brace, text.rfind(b",", brace, offset)) + 1:offset]
    return b"=" in enumerator and _ENUM_HEAD.search(text[max(start, brace - 200):brace]) is not None


_ALIAS_NAME = re.compile(rb"\busing\s+([A-Za-z_]\w*)\s*=")
_DECLARING = re.compile(rb"\b(?:using|typedef|namespace)\b")
_TYPE_AS_VALUE = re.compile(r"^expected '\(' for function-style cast or type construction")
_NAME_BEFORE = re.compile(rb"((?:[A-Za-z_]\w*\s*::\s*)*[A-Za-z_]\w*)\s*$")
_CONSTANT = re.compile(r"[A-Z][A-Z0-9]*(?:_[A-Z0-9]+)+|[A-Z]{2,}[0-9]*")
# the other branch of a conditional, an integer literal: after the name (``? NAME : 0``)
# or before it (``? 0 : NAME``)
_NUMBER_AFTER_COLON = re.compile(rb"\s*:(?!:)\s*\(?\s*(?:0[xX][0-9a-fA-F]+|\d+)[uUlL]*\s*\)?"
                                 rb"\s*[),;]")
_NUMBER_BEFORE_COLON = re.compile(rb"\?\s*\(?\s*(?:0[xX][0-9a-fA-F]+|\d+)[uUlL]*\s*\)?\s*:$")
# an unqualified name in capitals, two letters at least, not called: a macro or a
# constant of a missing header (robotis_math's ``DEGREE2RADIAN``, ``#define``d there), a
# value; a member is rarely written so
_CAPITALS = re.compile(r"[A-Z][A-Z0-9]*[A-Z][A-Z0-9]*")
# the text before a name, ending with an operator whose operand is a value: ``30 *
# DEGREE2RADIAN)``, ``x / K``, ``-K``, ``a && K``, ``c ? Vendor::K * 2.0 : 0.1`` (not ``->``:
# a member; not ``>`` nor ``<``: a template's argument list). A type never follows a
# ``*`` or ``&`` either: what does in a declaration is the declared name, never looked up
_OPERATOR_BEFORE = re.compile(rb"(?:[-+*/%^|&!?]|<<)$")


def _after_operator(window: bytes) -> bool:
    """Whether ``window``, the text before a name (its scope left out), ends with an
    operator that takes a value (``_OPERATOR_BEFORE``), or with the ``:`` of a
    conditional whose ``?`` is in the same statement."""
    code = code_only(window).rstrip()
    if _OPERATOR_BEFORE.search(code) is not None:
        return True
    if code.endswith(b":") and not code.endswith(b"::"):
        return b"?" in re.split(rb"[;{}]", code[:-1])[-1]
    return False
# an unqualified name of a C library: a constant in capitals with an underscore
# (``SDL_INIT_JOYSTICK``) or a function under a capitalised prefix (``SDL_GetError``,
# ``PhidgetNet_addServer``); members are rarely written so
_C_VENDOR = re.compile(r"[A-Z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)+")
# a name in capitals ending with an underscore, called: a function-like macro of a
# missing header (MRPT's ``ASSERT_(x)``, ``ASSERTMSG_(c, m)``, ``ASSERT_GT_(a, b)``);
# no member is written so
_CAPS_MACRO = re.compile(r"[A-Z][A-Z0-9]*(?:_[A-Z0-9]+)*_")
# a namespace, class, struct or enum the code defines (the first name of ``a::b``)
# (not a namespace alias, ``namespace stats = boost::accumulators;``, whose target may
# be unknown: novatel_gps_driver's ``stats::tag::min``, ``mean``, ... were one per parse)
_DEFINED = re.compile(
    rb"\b(?:namespace|class|struct|enum)\s+(?:class\s+|struct\s+)?([A-Za-z_]\w*)(?!\s*=)")
_USING = re.compile(rb"\busing\s+namespace\s+(?:::)?([A-Za-z_][\w:]*)\s*;")
# ``namespace arm = hebi::experimental::arm;``: a namespace alias and what it names
_NAMESPACE_ALIAS = re.compile(
    rb"\bnamespace\s+([A-Za-z_]\w*)\s*=\s*(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)\s*;")
# a type alias of a class template's specialisation, ``typedef PointMatcher<float> PM;`` /
# ``using PM = PointMatcher<float>;`` (libpointmatcher_ros' aliases.h): the alias and the
# qualified name of the template it names (``Names._alias_target``)
_TYPEDEF_TARGET = re.compile(
    rb"\btypedef\s+(?:typename\s+)?(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)\s*"
    rb"<[^;{}]*>\s*([A-Za-z_]\w*)\s*;")
_USING_TARGET = re.compile(
    rb"\busing\s+([A-Za-z_]\w*)\s*=\s*(?:typename\s+)?(?:::\s*)?"
    rb"([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)*)\s*<[^;{}]*>\s*;")
# ``using vendor::conn::Connection;``: a using-declaration of one qualified name
_USING_ONE = re.compile(
    rb"\busing\s+(?!namespace\b)(?:typename\s+)?(?:::\s*)?([A-Za-z_]\w*(?:\s*::\s*[A-Za-z_]\w*)+)\s*;")

# binary operators for any operand of a synthesised class (and nothing else); a number
# on the other side is taken by value: binding a reference to a constant would use it
# (odr-use), and a lambda that names a local constant so must capture it (book_ros2's
# object_tracker: ``msg->bbox.center.position.x / IMG_WIDTH`` in a subscription's
# callback, ``bbox`` of a message known only by name, was an error there)
# The arithmetic result is a ``haros_number``: a permissive value that converts to any
# type as every one does, but that no number converts to, so a conditional between it and
# a number has the number's type (abb_robot_driver's ``rotational ? 10.0*Constants::
# DEG_TO_RAD : 0.1``, Constants of a library not here, was ambiguous: a permissive value
# converts to ``double`` and is built from one), and one between it and another
# permissive value has the permissive base's (haros_any converts to no haros_number)
_BINARY = (("haros_number", "+ - / % | ^ & *"), ("bool", "== != < > <= >= && ||"))
_OPERATORS = "".join(
        f"template <class A, class B> typename haros_if<(__is_base_of(haros_any, A) || "
        f"__is_base_of(haros_any, B)) && !__is_arithmetic(A) && !__is_arithmetic(B), "
        f"{r}>::type operator{o}(const A &, const B &);\n"
        f"template <class A, class B> typename haros_if<__is_base_of(haros_any, A) && "
        f"__is_arithmetic(B), {r}>::type operator{o}(const A &, B);\n"
        f"template <class A, class B> typename haros_if<__is_arithmetic(A) && "
        f"__is_base_of(haros_any, B), {r}>::type operator{o}(A, const B &);\n"
        for r, ops in _BINARY for o in ops.split())
# compound assignments: members of the permissive class, and for an object of another
# type given a synthesised one (``flags |= vendor::BIT``); without them the integral
# conversion a switch needs (``operator haros_integral``) makes every built-in candidate
# viable, and the use ambiguous
_COMPOUND = ["+=", "-=", "*=", "/=", "%=", "|=", "&=", "^=", "<<=", ">>="]
_COMPOUND_MEMBERS = "".join(f"  template <class A> haros_any &operator{o}(A &&);\n"
                            for o in _COMPOUND)
_OPERATORS += "".join(
    f"template <class A, class B> typename haros_if<__is_base_of(haros_any, B) && "
    f"!__is_base_of(haros_any, A), A &>::type operator{o}(A &, const B &);\n"
    for o in _COMPOUND)
# shifts and the comma with a synthesised class on the left: Eigen's comma initialiser on
# a vendor's vector type, ``(gtsam::Vector(6) << 1e-2, 1e-2, ...).finished()`` (LIO-SAM's
# imuPreintegration.cpp:218-225); without them ``<<`` was ambiguous between the built-in
# shift (through ``operator haros_integral``) and the standard library's stream output
# (through ``operator T &``), and the comma left a ``double`` whose ``.finished()`` was an
# error, both in the constructor that makes the node's calls. A stream on the left
# (``std::cout << vendor_value``) keeps the standard library's operator
_OPERATORS += "".join(
    f"template <class A, class B> typename haros_if<__is_base_of(haros_any, A), "
    f"haros_any &>::type operator{o}(const A &, const B &);\n" for o in ("<<", ">>", ","))

_PRELUDE = """\
// haros_arch: permissive declarations of names the parse did not know
#pragma clang system_header
#include <string>  // std::to_string of a permissive value (below)
#include <memory>  // a cast of a permissive value to a shared_ptr (below)
enum haros_integral : long long {};
template <bool C, class R> struct haros_if {};
template <class R> struct haros_if<true, R> { typedef R type; };
struct haros_any;
struct haros_number;  // the result of arithmetic on a permissive value (_BINARY)
// the address of a permissive value converts to any pointer, as the value does to any
// type: realsense's ``readAndSetDynamicParam(nh1, ..., &(roi.min_x))`` takes an ``int *``,
// ``roi`` of librealsense's missing ``rs2::region_of_interest``, and clang kept the call,
// whose ``haros_any *`` converts to no ``int *``, as a recovery expression: no call of
// the function. Built from 0 or nullptr (``flag ? &value : 0``), from nothing else
struct haros_address {
  haros_address(decltype(nullptr)); haros_address(int);
  template <class T> operator T *() const;
  haros_any *operator->() const;
  haros_any &operator*() const;
};
struct haros_any {
  // the mark the std stand-ins know a permissive value by (haros_std.h's smart pointers)
  typedef void haros_permissive;
  template <class... A> haros_any(A &&...) {}
  // braces of braces (naoqi's ``boost::array<double, 9>{{556.8, 0, 309.4, ...}}``); not
  // an initializer_list, which list-initialisation would prefer for flat braces too
  // (``debug_{this, "~/debug"}``, the node given to a vendor's class: CPP_NODE_TO_UNKNOWN)
  template <decltype(sizeof 0) N> haros_any(const haros_any (&)[N]);
  template <class T, class = typename haros_if<!__is_same(T, haros_number), void>::type>
  operator T &() const;
  haros_any *operator->() const;
  haros_any &operator*() const;
  haros_address operator&() const;  // (above)
  template <class... A> haros_any &operator()(A &&...) const;
  // a braced list given to a permissive call, which no template parameter deduces (the
  // asio idiom ``*resolver.resolve({udp::v4(), host, port})`` of kuka_eki_hw_interface,
  // with <boost/asio.hpp> missing): a permissive value built from the list
  haros_any &operator()(const haros_any &) const;
  haros_any &operator()(const haros_any &, const haros_any &) const;
  haros_any &operator()(const haros_any &, const haros_any &, const haros_any &) const;
  // and a variable-length array, which no template deduces (OpenMower's ``uint8_t
  // buf[size]; crc.process_bytes(buf, size)``, boost/crc.hpp missing): the last resort
  haros_any &operator()(...) const;
  template <class A> haros_any &operator[](A &&) const;
  template <class A> haros_any &operator=(A &&);
  haros_any &operator++(); haros_any &operator--();
  haros_any &operator++(int); haros_any &operator--(int);
  bool operator!() const;
  haros_any operator-() const; haros_any operator+() const; haros_any operator~() const;
%s  operator haros_integral() const;
%s};
struct haros_number : haros_any { using haros_any::operator=; };
// a range-for over a permissive object (found by argument-dependent lookup, unless the
// code reads members begin / end of one, which then serve), and a structured binding of
// its elements as a pair's (mrpt_map_server's ``for (auto& [name, layer] : map.layers)``)
haros_any *begin(const haros_any &); haros_any *end(const haros_any &);
namespace std {
template <class T> struct tuple_size;
template <decltype(sizeof 0) I, class T> struct tuple_element;
template <> struct tuple_size<haros_any> { static constexpr decltype(sizeof 0) value = 2; };
template <decltype(sizeof 0) I> struct tuple_element<I, haros_any> { typedef haros_any type; };
// a standard function of one permissive value (franka's ``std::abs(state.q_d[i] -
// q_start[i])`` of libfranka's RobotState, ouster's ``std::to_string(mode)``): every
// standard overload takes it through a conversion, ambiguously; one of its own is exact
haros_any &abs(const haros_any &);
haros_any &fabs(const haros_any &);
haros_any &sqrt(const haros_any &);
haros_any &floor(const haros_any &);
haros_any &ceil(const haros_any &);
haros_any &round(const haros_any &);
haros_any &exp(const haros_any &);
haros_any &log(const haros_any &);
haros_any &sin(const haros_any &);
haros_any &cos(const haros_any &);
haros_any &tan(const haros_any &);
haros_any &isnan(const haros_any &);
haros_any &isinf(const haros_any &);
haros_any &isfinite(const haros_any &);
string to_string(const haros_any &);
// an element of a permissive object that is a variant or tuple, by type or by index
// (ur_robot_driver's ``std::get<std::string>(response.data.at("program_name"))``)
template <class T> T &get(const haros_any &);
template <decltype(sizeof 0) I> haros_any &get(const haros_any &);
// a permissive value cast as a shared_ptr of a known type (mrpt_map_server's
// ``std::dynamic_pointer_cast<mrpt::maps::CMetricMap>(obj)`` of an object read from an
// MRPT archive): no standard overload deduces its pointee
template <class T> shared_ptr<T> dynamic_pointer_cast(const haros_any &);
template <class T> shared_ptr<T> static_pointer_cast(const haros_any &);
template <class T> shared_ptr<T> const_pointer_cast(const haros_any &);
}
template <decltype(sizeof 0) I> haros_any &get(const haros_any &);
%s"""


# names of a library the stand-ins provide, by namespace, with the stand-in header that
# declares each: a name the parse did not know because the header that would have
# included the library's is missing (Autoware's scenario selector holds a
# ``boost::optional<rclcpp::Time>`` it never includes, lanelet2's headers do) is the
# library's, not a permissive one (``x = {}`` on that was ambiguous)
_PROVIDED: dict[str, dict[str, str]] = {
    "boost": {"optional": "boost/optional.hpp", "none": "boost/optional.hpp",
              "none_t": "boost/optional.hpp", "make_optional": "boost/optional.hpp",
              "circular_buffer": "boost/circular_buffer.hpp",
              "lexical_cast": "boost/lexical_cast.hpp", "format": "boost/format.hpp",
              "scoped_ptr": "boost/scoped_ptr.hpp"},
}


# names of the C++ standard library that code writes unqualified only where a
# ``using namespace std;`` (or ``using std::x;``) brings them: one the parse does not
# know, used unqualified, was brought by a header it lacks (youbot_driver's headers,
# which youbot_driver_ros_interface's ``stringstream topicName;`` and ``vector<string>``
# rely on), so it is std's, not a permissive name (a stream's writes are then read:
# ``values.Scope._stream_text``); names as common as a vendor's own (``set``, ``list``,
# ``function``, ``array``) are left to the permissive declaration
_STD_UNQUALIFIED = frozenset({
    "string", "wstring", "vector", "map", "multimap", "multiset", "deque", "pair",
    "unordered_map", "unordered_set", "priority_queue", "stringstream", "ostringstream",
    "istringstream", "ifstream", "ofstream", "fstream", "ostream", "istream", "cout",
    "cerr", "clog", "cin", "endl", "shared_ptr", "unique_ptr", "weak_ptr",
    "runtime_error", "invalid_argument", "out_of_range", "logic_error", "numeric_limits",
    "queue", "boolalpha", "noboolalpha", "setprecision", "setw", "setfill"})
# the values and functions among them (streams, manipulators): written unqualified in a
# class's method, they are not declared as an unknown member would be (a declaration
# there could shadow one of a base the parse lacks, ``_from_source``), but a
# ``using std::cerr;`` at namespace scope shadows no member: the class's own and its
# bases' are found first (ORB_SLAM3_ROS2's nodes write ``ss >> boolalpha >> flag`` and
# ``cerr << ... << endl`` in their constructors, ORB_SLAM3's headers missing)
_STD_VALUES = frozenset({
    "cout", "cerr", "clog", "cin", "endl", "boolalpha", "noboolalpha", "setprecision",
    "setw", "setfill"})


@dataclass
class _Name:
    """One unknown name (or a known namespace enclosing some) and its uses."""

    # scope, type, template, value; constant and flag (``_constant_at``)
    uses: set[str] = field(default_factory=set)
    known: bool = False  # a real namespace, reopened
    children: dict[str, _Name] = field(default_factory=dict)
    # the declared class a pointer to this one was given for (``_POINTER_TO``): its base
    base: str | None = None
    polymorphic: bool = False  # ``_NOT_POLYMORPHIC``: declared with a virtual destructor
    # the argument positions of a declared template that the code gives values
    # (``_VALUE_ARGUMENT``): non-type parameters there
    value_arguments: set[int] = field(default_factory=set)
    # the files (``Names._texts``, by id) whose uses of it were read for them: a text
    # read once gives nothing more (``Names._spread_values``)
    values_read: set[int] = field(default_factory=set)


_MACRO_SPAN = 4000  # bytes of a macro call searched for a name clang placed at the macro
_MACRO_NAME = re.compile(r"[A-Z][A-Z0-9_]*[A-Z0-9]")


def is_macro_name(name: str) -> bool:
    """Whether ``name`` is written as C and C++ write a macro's: capitals (two at least),
    digits and underscores."""
    return _MACRO_NAME.fullmatch(name) is not None


def _bare_macro(name: str, text: bytes, offset: int) -> bool:
    """Whether the unknown ``name`` at ``offset`` is a macro that stands for
    declarations: written in capitals, alone on its line (nothing after it but a
    comment), where a type would be followed by what it declares."""
    if not is_macro_name(name) or text[offset:offset + len(name)] != (
            name.encode()):
        return False
    start = text.rfind(b"\n", 0, offset) + 1
    end = text.find(b"\n", offset)
    line = text[start:end if end >= 0 else len(text)]
    after = line[offset - start + len(name):].split(b"//")[0].strip()
    return not line[:offset - start].strip() and not after


_MISSING_HEADER = re.compile(r"^header (\S+) not found")
# a declaration clang took for a function's that wants a body: a macro call that stands
# for declarations, written with no ``;`` (libqi's ``QI_REGISTER_OBJECT(Type, method)``
# at namespace scope, its header missing): defined empty, or the next ``}`` is taken for
# the body and the rest of the unit is lost
_BODY_EXPECTED = re.compile(r"^expected function body after function declarator")
_DECLARATION_MACRO = re.compile(
    rb"([A-Z][A-Z0-9]*(?:_[A-Z0-9]+)+)\s*\((?:[^;{}()]|\([^;{}()]*\))*\)")


# a function declared with a macro between its return type and its name, the macro's
# header missing: a calling convention or an export attribute (vrpn_client_ros'
# ``static void VRPN_CALLBACK handle_pose(void *userData, ...)``, VRPN's header
# missing). Clang reads the macro as the name of a variable of the return type and
# wants a ``;`` after it, where the function's name is: the function is lost, and its
# definition's body (the handler's advertise calls) with it. Defined empty.
_DECLARATOR_ENDED = re.compile(
    r"^expected ';' (?:at end of declaration list|after top level declarator)")
_MACRO_BEFORE = re.compile(rb"[\w*&>]\s+([A-Z][A-Z0-9_]*[A-Z0-9])\s*$")
_FUNCTION_NAMED = re.compile(rb"\s+(?:[A-Za-z_]\w*\s*::\s*)*~?[A-Za-z_]\w*\s*\(")


def _attribute_macro(text: bytes, offset: int) -> str | None:
    """The macro name written between a declaration's type and a function's name that
    ends before ``offset``, where clang wanted the declaration to end (``_DECLARATOR_
    ENDED``), if it is one: capitals, after a type's last word (or ``*``, ``&``,
    ``>``), and followed by a name and ``(``."""
    found = _MACRO_BEFORE.search(text, max(0, offset - 200), offset)
    if found is None or _FUNCTION_NAMED.match(text, offset) is None:
        return None
    start = text.rfind(b"\n", 0, found.start()) + 1
    if text[start:found.start()].lstrip().startswith(b"#"):
        return None  # a preprocessor line
    return found.group(1).decode()


def _declaration_macros(text: bytes, offset: int) -> list[str]:
    """The macros whose calls, one after another, are the whole declaration that ends
    before ``offset`` (from the last ``;``, ``{`` or ``}`` before it, comments left
    out), if it is such: clang reads ``A(..) B(..)`` as one declarator wanting a body
    (autoware_utils_geometry's ``BOOST_GEOMETRY_REGISTER_POINT_2D(..)`` then ``_3D(..)``
    and ``BOOST_GEOMETRY_REGISTER_RING(..)`` at namespace scope, Boost.Geometry's
    headers missing), so each is one of them."""
    window = text[max(0, offset - _MACRO_SPAN):offset]
    start = max(window.rfind(b";"), window.rfind(b"{"), window.rfind(b"}")) + 1
    statement = re.sub(rb"//[^\n]*|/\*.*?\*/", b" ", window[start:], flags=re.DOTALL).strip()
    found = _macro_calls(statement)
    if not found:
        return []
    # clang points at what follows the declarator: the macro calls written next, each
    # ending its line (before the next ``;``, ``{``, ``}`` or ``#``), are the same kind
    # of declaration
    after = text[offset:offset + _MACRO_SPAN]
    end = min((i for i in (after.find(b";"), after.find(b"{"), after.find(b"}"),
                           after.find(b"#")) if i >= 0), default=len(after))
    following = re.sub(rb"//[^\n]*|/\*.*?\*/", b" ", after[:end], flags=re.DOTALL).strip()
    return [*found, *_macro_calls(following, whole=False)]


def _macro_calls(statement: bytes, whole: bool = True) -> list[str]:
    """The macros of ``statement`` when it is macro calls one after another alone (else
    none); not ``whole``: those it starts with, each ending its line."""
    found: list[str] = []
    at = 0
    while at < len(statement):
        call = _DECLARATION_MACRO.match(statement, at)
        line_end = statement.find(b"\n", call.end()) if call is not None else -1
        if call is None or (not whole and statement[call.end():(
                line_end if line_end >= 0 else len(statement))].strip()):
            return [] if whole else found
        found.append(call.group(1).decode())
        at = call.end()
        while at < len(statement) and statement[at:at + 1].isspace():
            at += 1
    return found


def library_prefixes(messages: Iterable[str]) -> set[str]:
    """The words (before a ``_``, three letters or more) that start the folders and file
    names of the headers found missing (``header ogg/ogg.h not found``: ``ogg``;
    ``urg_c/urg_sensor.h``: ``urg``): the prefixes of the C libraries they declare, each
    also with ``lib`` before it, as C libraries often name their functions
    (``libvlc_new`` of <vlc/vlc.h>)."""
    found: set[str] = set()
    for message in messages:
        match = _MISSING_HEADER.match(message)
        if match is None:
            continue
        for part in re.split(r"[/\\]", match.group(1)):
            word = part.split(".")[0].split("_")[0]
            if len(word) >= 3 and word.isidentifier():
                found.add(word)
                if not word.startswith("lib"):
                    found.add("lib" + word)
    return found


_STATEMENT_END = re.compile(rb"[;{}]\s*$")
# what a statement may follow that is no statement's end: ``else``, ``do``
_BODY_KEYWORD = re.compile(rb"\b(?:else|do)\s*$")
# the keyword of a head in parentheses that a statement follows: ``if (...)``,
# ``if constexpr (...)``, ``while (...)``, ``for (...)``, ``switch (...)``
_HEAD_KEYWORD = re.compile(rb"\b(?:if(?:\s+constexpr)?|while|for|switch)\s*$")


def _statement_starts(text: bytes, start: int) -> bool:
    """Whether a statement begins at ``start``: after ``;``, ``{`` or ``}``, after
    ``else`` or ``do``, or as the body of an ``if`` / ``while`` / ``for`` / ``switch``
    without braces, after the ``)`` that closes its head (realsense2_camera's ``if
    (...)`` then ``console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_DEBUG);``)."""
    before = text[max(0, start - 64):start]
    if _STATEMENT_END.search(before) is not None or _BODY_KEYWORD.search(before):
        return True
    at = len(before.rstrip()) + max(0, start - 64) - 1
    if text[at:at + 1] != b")":
        return False
    opening = closing(text, at, backwards=True)  # back to the ``(`` it closes
    return opening is not None and _HEAD_KEYWORD.search(
        text[max(0, opening - 32):opening]) is not None


def _called_statement(text: bytes, start: int, end: int) -> bool:
    """Whether the name written from ``start`` to ``end`` begins a statement that is a
    call of it alone: a statement's start before it (``_statement_starts``), its
    parenthesised arguments, and ``;`` after them (``vendor::set_logger(logger);``)."""
    if not _statement_starts(text, start):
        return False
    at = end
    while at < len(text) and text[at:at + 1].isspace():
        at += 1
    if text[at:at + 1] != b"(":
        return False
    close = closing(text, at)
    return close is not None and text[close + 1:close + 64].lstrip()[:1] == b";"


_MEMBER_CALLED = re.compile(rb"(?:\.|->)\s*[A-Za-z_]\w*\s*$")
_ARGUMENT_SPAN = 400


def _member_call_argument(text: bytes, offset: int) -> bool:
    """Whether the name at ``offset`` begins an argument of a call of an object's member
    function, ``obj.f(a, NAME, b)`` / ``p->f(NAME)``: an expression there, so a value (a
    type as a whole argument is no C++), unlike a parameter of a declaration, ``void
    f(Type, int)``. ydlidar_ros2_driver's ``laser.setlidaropt(LidarPropSerialPort,
    value, size)``, its SDK's header missing."""
    before = text[max(0, offset - _ARGUMENT_SPAN):offset]
    if not before.rstrip().endswith((b"(", b",")):
        return False
    depth = 0
    for index in range(len(before) - 1, -1, -1):
        char = before[index:index + 1]
        if char in (b")", b"]", b"}"):
            depth += 1
        elif char in (b"[", b"{"):
            if depth == 0:
                return False
            depth -= 1
        elif char == b"(":
            if depth == 0:
                return _MEMBER_CALLED.search(before[:index]) is not None
            depth -= 1
        elif char == b";" and depth == 0:
            return False
    return False


def _template_arguments(text: bytes, start: int) -> list[tuple[int, int]]:
    """(index, offset) of each argument of the template argument list that starts at
    ``start`` (after its ``<``); empty when it does not close within a few hundred bytes."""
    found: list[tuple[int, int]] = [(0, start)]
    depth, at = 0, start
    while at < len(text) and at < start + _TEMPLATE_SPAN:
        char = text[at:at + 1]
        if char in b"<([{":
            depth += 1
        elif char in b")]}":
            depth -= 1
        elif char == b">":
            if depth == 0:
                return found
            depth -= 1
        elif char == b"," and depth == 0:
            found.append((len(found), at + 1))
        elif char == b";":
            break
        at += 1
    return []


def _names_a_declared_type(name: str, text: bytes, offset: int) -> bool:
    """Whether ``name``, written at ``offset`` (or just after: clang may point at the
    scope before it), is followed by a declarator (``_MEMBER_DECLARING``)."""
    found = re.compile(rb"::\s*" + re.escape(name.encode()) + rb"\b").search(
        text, max(0, offset - 2), offset + _TEMPLATE_SPAN)
    if found is None:
        return False
    declared = _MEMBER_DECLARING.match(text, found.end())
    return declared is not None and declared.group(1).decode() not in _KEYWORDS


# a call of a name with a ``_`` after a first word of letters and digits (not after a
# word, ``::``, ``.`` or ``->``): the first word is the prefix of a C library's functions
# where ``library_prefixes`` has it (``Names._spread_calls``)
# the prefixes of C runtimes the compiler brings (``-fopenmp``: OpenMP's ``omp_get_max_threads()``,
# ``omp_get_thread_num()``), whose header a unit often has only through another library's
# (hdl_global_localization's RANSAC through PCL's): an unqualified call under one, with no
# argument for argument-dependent lookup to find a friend by, is the runtime's (a value)
COMPILER_LIBRARIES = frozenset({"omp"})
_LIBRARY_CALL = re.compile(rb"(?<![\w:.>])(([A-Za-z0-9]+)_\w+)\s*\(")


def _initialised_member(text: bytes, found: re.Match[bytes], before: bytes) -> bool:
    """Whether the call ``found`` (a name and its ``(``) is an element of a constructor's
    initialiser list (cartographer's ``: odometry_sampler(ratio), imu_sampler(ratio) {``):
    after a ``:`` or ``,`` (``before``: its line up to the name, else the text before)
    and followed by a ``,`` or the body's ``{``."""
    ahead = text[max(0, found.start() - 200):found.start()].rstrip()
    last = (before or ahead)[-1:]
    if last not in (b":", b",") or (before or ahead).endswith(b"::"):
        return False
    close = closing(text, found.end() - 1, 2001)  # the call's ``(``
    return close is not None and text[close + 1:close + 200].lstrip()[:1] in (b",", b"{")


def _spelled_at(name: str, text: bytes, offset: int) -> int:
    """Where the unknown ``name`` an error is about is written: clang places an error
    in a macro's arguments at the macro (``RCLCPP_ERROR(logger, "%s", SDL_GetError())``
    is reported at ``RCLCPP_ERROR``); the name is then the first use of it in the
    macro call's text."""
    first = name.split("::")[0].encode()
    if not first or text[offset:offset + len(first)] == first:
        return offset
    found = re.compile(rb"(?<![\w.:>])" + re.escape(first) + rb"\b").search(
        text, offset, offset + _MACRO_SPAN)
    return found.start() if found is not None else offset


class Names:
    """The unknown names of one translation unit, collected over the rounds."""

    def __init__(self, packages: Iterable[str] = (),
                 declared: Callable[[str], frozenset[str]] | None = None,
                 libraries: Iterable[str] = (), qt: bool = False) -> None:
        """``packages``: those whose messages are known only by name (any package's
        ``pkg::msg::Name`` and ``*_msgs::Name`` count as well). ``declared``: the names
        the parse already has in a top-level namespace (a stand-in's class in a vendor
        namespace whose other names are unknown), never declared again. ``libraries``:
        the prefixes of the C libraries whose headers are missing (``library_prefixes``):
        an unqualified function under one (``ogg_stream_init(...)``) is the library's;
        so is one of OpenMP's runtime (``COMPILER_LIBRARIES``). ``qt``: whether the unit
        reads the Qt stand-in (``QT_MORE``)."""
        self.qt = qt
        self.packages = frozenset(packages)
        self.libraries = frozenset(libraries) | COMPILER_LIBRARIES
        self.declared = declared
        self.root = _Name(known=True)
        self.members: set[str] = set()
        self.qt_members: set[str] = set()  # members of the Qt stand-in's classes (QT_MORE)
        # the members written after C++'s ``template`` keyword: member templates (any
        # template arguments, any call arguments), not static members
        self.member_templates: set[str] = set()
        # unqualified functions the code calls that no lookup finds: friends of the
        # permissive class declared in it only, which argument-dependent lookup alone
        # finds, where an argument is a permissive value (ouster's ``to_string(info.
        # format.udp_profile_lidar)`` of the SDK's types); ordinary lookup never sees
        # them, so a member of a class is not hidden; one called with a permissive value
        # in a method of a class derived from a declared class may be that base's
        # method, which the visitor says (``CallFinder._of_unknown_base``)
        self.friends: set[str] = set()
        # those called in a free function (``main``, a helper: a function, no class's
        # method, so no member is hidden), declared at namespace scope, which
        # ordinary lookup finds whatever the arguments (lsd_slam's ``XInitThreads()`` of
        # the missing <X11/Xlib.h>: a friend takes no call without a permissive
        # argument); ``in_free``: the (file bytes' id, offset) of the errors of the
        # parse being read that are in a free function
        self.free: set[str] = set()
        self.in_free: set[tuple[int, int]] = set()
        # the errors in a method of a class whose bases the parse reads whole: a name
        # called there is no member of an unread base, so, in a unit with a header
        # missing (``libraries``), a function of it as in a free function (ros_phoenix's
        # ``c_SetPhoenixDiagnosticsStartTime(1)`` of CTRE's missing C API, in a
        # constructor of a ComponentManager); with none, the code's own error
        self.in_read: set[tuple[int, int]] = set()
        # the members read where C++ needs a constant (``case Mode::FAST:``): enumerators
        self.constants: set[str] = set()
        self.flags: set[str] = set()  # those an operator combines (``_constant_at``)
        self.taken: set[int] = set()  # the integers of the case labels read (``_CASE_LITERAL``)
        # record -> the members the code uses on it: the fields of messages known only
        # by name (their synthesised struct opens a hook, ``interfaces.fields_hook``),
        # and the member types it names (``ResponseStatus::_code_type``)
        self.fields: dict[str, set[str]] = {}
        self.types: dict[str, set[str]] = {}
        self.using: set[str] = set()  # namespaces named by ``using namespace``
        # the qualified names of using-declarations: ``using vendor::conn::Connection;``
        self.brought: set[str] = set()
        self.aliases: set[str] = set()  # names the code declares: ``using Mode = ...;``
        # namespace aliases the code declares, by name: what each names, its parts
        self.namespace_aliases: dict[str, list[str]] = {}
        # aliases of a class template's specialisation, by name: the template's parts
        self.template_aliases: dict[str, list[str]] = {}
        # unknown names that made a use ambiguous (the real declaration was invalid only
        # until other names were declared): no longer declared
        self.withdrawn: set[str] = set()
        # members of the permissive class a class also finds in a real base
        # (``_AMBIGUOUS_MEMBER``): no longer declared
        self.withdrawn_members: set[str] = set()
        # unknown macros written alone on their line (``EIGEN_MAKE_ALIGNED_OPERATOR_NEW``
        # in a class body, its header not reached): defined empty, not declared as types
        self.macros: set[str] = set()
        # unknown function-like macros written as a whole declaration (``_BODY_EXPECTED``)
        self.declaration_macros: set[str] = set()
        self._read: set[int] = set()  # the files whose using-directives were read
        self._texts: list[bytes] = []  # those files, code only (``code_only``)
        # the classes they define with the bases written in their heads (``_CLASS_HEAD``)
        self._heads: list[tuple[str, list[str]]] = []
        self._heads_read = 0  # the texts whose heads are in ``_heads``
        # those of them derived from a declared base, as of (count, heads read)
        self._derived_heads: tuple[tuple[int, int], frozenset[str]] = ((-1, -1), frozenset())
        self._defined: set[str] = set()  # the names they define (see ``_spread``)
        self._spread_done: set[tuple[int, str]] = set()  # (file, name) looked for
        self.count = 0
        self.changed = 0  # names declared before whose declaration changed since

    def learn(self, errors: Iterable[tuple[str, bytes | None, int]]) -> bool:
        """Read ``(message, source bytes of its file, byte offset)`` errors; True when a
        name was learnt that was not known before."""
        before = (self.count, len(self.members), len(self.withdrawn),
                  len(self.withdrawn_members), self.changed)
        errors = list(errors)
        for _message, text, _offset in errors:
            if text is not None and id(text) not in self._read:
                self._read.add(id(text))
                self._texts.append(code_only(text))
                self._defined.update(m.decode() for m in _DEFINED.findall(text))
                self.using.update(m.decode() for m in _USING.findall(text))
                # not ``using Base::Base;``: a class's inherited constructors
                self.brought.update(one for one in (re.sub(r"\s+", "", m.decode())
                                                    for m in _USING_ONE.findall(text))
                                    if one.split("::")[-2:-1] != one.split("::")[-1:])
                self.aliases.update(m.decode() for m in _ALIAS_NAME.findall(text))
                for alias, target in _NAMESPACE_ALIAS.findall(text):
                    self.namespace_aliases.setdefault(alias.decode(), re.sub(
                        rb"\s+", b"", target).decode().split("::"))
                for target, alias in _TYPEDEF_TARGET.findall(text):
                    self.template_aliases.setdefault(alias.decode(), re.sub(
                        rb"\s+", b"", target).decode().split("::"))
                for alias, target in _USING_TARGET.findall(text):
                    self.template_aliases.setdefault(alias.decode(), re.sub(
                        rb"\s+", b"", target).decode().split("::"))
                self.taken.update(_case_literals(text))
        for message, text, offset in errors:
            if self.count >= MAX_NAMES:
                break
            self._learn_one(message, text, offset)
            if _BODY_EXPECTED.match(message) and text is not None and _declaration_macros(
                    text, offset):
                # a declaration clang took for a function's swallowed what follows it:
                # the errors after it are of that reading (the classes it hid are
                # "undeclared"), not names to declare; the next parse shows the real ones
                break
        self._spread()
        return (self.count, len(self.members), len(self.withdrawn),
                len(self.withdrawn_members), self.changed) != before

    def _spread(self) -> None:
        """Every qualified use of an unknown top-level name in the files read: clang
        reports only the first unknown name of a declaration (``std::map<vendor::Key,
        vendor::Value>``); each of the others would be the error of another parse."""
        # not a name the code defines somewhere (``namespace autoware::planning {``): it
        # was unknown where clang met it first, and is real further on
        unknown = [name for name, node in self.root.children.items() if not node.known
                   and name not in self._defined]
        # and a namespace alias of one (``stats::tag::min`` after ``namespace stats =
        # vendor::accumulators;``), each use its target's (``_from_source``)
        unknown += [alias for alias, target in self.namespace_aliases.items()
                    if target[0] in unknown and alias not in self.root.children]
        # and an alias of a specialisation of one (``PM::TransformationParameters::
        # Identity(4, 4)`` after ``typedef PointMatcher<float> PM;``): the names nested in
        # the template, the third wave of errors otherwise (the template, its nested
        # class, the member of that), past the parses a unit gets
        unknown += [alias for alias, target in self.template_aliases.items()
                    if target[0] in unknown and alias not in self.root.children
                    and alias not in unknown]
        for text in self._texts:
            todo = [name for name in unknown if (id(text), name) not in self._spread_done]
            if not todo:
                continue
            self._spread_done.update((id(text), name) for name in todo)
            words = b"|".join(re.escape(name.encode()) for name in sorted(todo, key=len)[::-1])
            for found in re.finditer(rb"(?<![\w:.>])(" + words + rb")\s*::\s*(\w*)", text):
                if self.count >= MAX_NAMES:
                    return
                if self.declared is not None and found.group(2).decode() in self.declared(
                    found.group(1).decode()
                ):
                    continue  # the stand-ins have it (autoware_utils' polling subscriber)
                self._from_source(text, found.start(), "any", [])
        self._spread_calls()
        self._spread_values()
        self._spread_arguments()

    def _spread_arguments(self) -> None:
        """An unknown name known so far only as a scope (``Feedback::Integrated``, a
        namespace) that the files read give whole as a template's argument
        (``MotorNode<vendor::Falcon, Config, Feedback, Mode>``): a type, a class whose
        members the scope's uses name. clang reports the first unknown name of a
        template's argument list and skips the rest of it, so the list alone never said
        so: declared a namespace, the argument was an error ("unexpected namespace name")
        that hid the next one, and the class derived from that template stayed invalid
        (ros_phoenix's TalonFXNode, phoenix_nodes.hpp:9, and every call in its methods)."""
        scopes: list[tuple[list[str], _Name]] = []
        stack: list[tuple[list[str], _Name]] = [([], self.root)]
        while stack:
            path, node = stack.pop()
            for name, child in node.children.items():
                stack.append(([*path, name], child))
                if not child.known and child.uses == {"scope"} and (
                        path or name not in self._defined):
                    scopes.append(([*path, name], child))
        unknown = [name for name, node in self.root.children.items() if not node.known
                   and name not in self._defined]
        if unknown:
            words = b"|".join(re.escape(name.encode()) for name in sorted(unknown, key=len)[::-1])
            first = re.compile(rb"[<,]\s*(?:::\s*)?(" + words + rb")\b(?!\s*<)")
            for text in self._texts:
                if (id(text), "\0arguments") not in self._spread_done:
                    self._spread_done.add((id(text), "\0arguments"))
                    for found in first.finditer(text):
                        self._arguments_after(text, found.start(1))
        for path, node in scopes:
            written = rb"\s*::\s*".join(re.escape(p.encode()) for p in path)
            pattern = re.compile(rb"[<,]\s*(?:::\s*)?(" + written + rb")\s*[,>]")
            for text in self._texts:
                key = (id(text), "\0argument " + "::".join(path))
                if key in self._spread_done:
                    continue
                self._spread_done.add(key)
                for found in pattern.finditer(text):
                    start = found.start(1)
                    if _template_argument(text[max(0, start - _TEMPLATE_SPAN):start]):
                        node.uses.add("type")
                        self.count += 1
                        break
                if "type" in node.uses:
                    break

    def _arguments_after(self, text: bytes, offset: int) -> None:
        """The arguments after the unknown name at ``offset`` in the template argument
        list it is in (``MotorNode<vendor::Falcon, FalconConfig, FalconMode>``): clang
        skips the rest of a list at its first unknown name, so each of the others would
        be the error of another parse, one more per argument (ros_phoenix's
        ``TalonFXControlMode``, phoenix_nodes.hpp:9, was still an error after the two
        parses). Each one written as a type's bare name (``Name``, not a constant's
        ``NAME``) that no file read defines, aliases or brings, and that the parse does
        not declare at global scope or in a namespace a ``using namespace`` names, is
        declared a type; those before the unknown name were read by clang."""
        opened = _argument_list_open(text[max(0, offset - _TEMPLATE_SPAN):offset])
        if opened is None:
            return
        start = max(0, offset - _TEMPLATE_SPAN) + opened + 1
        brought = {one.split("::")[-1] for one in self.brought}
        for _index, at in _template_arguments(text, start):
            if at <= offset:
                continue
            found = _BARE_ARGUMENT.match(text, at)
            if found is None:
                continue
            name = found.group(1).decode()
            if name in self.root.children or name in self._defined or name in _KEYWORDS \
                    or name in self.aliases or name in brought or _CAPITALS.fullmatch(name) \
                    or self.count >= MAX_NAMES:
                continue
            if self.declared is not None and any(
                    name in self.declared(scope) for scope in ("", *sorted(
                        u for u in self.using if "::" not in u))):
                continue  # the parse has it (a header read without errors), at global
                # scope or in a namespace a ``using namespace`` brings
            self.root.children[name] = _Name(uses={"type"})
            self.count += 1

    def _spread_values(self) -> None:
        """The value arguments of every use of the declared templates in the files read
        (``_value_argument``): clang reports one per template-id and parse, and only
        once the template is declared (A-LOAM's ``ceres::AutoDiffCostFunction<
        LidarEdgeFactor, 3, 4, 3>``, naoqi's ``boost::array<double, 9>``)."""
        stack: list[tuple[str, _Name]] = [("", self.root)]
        while stack:
            name, node = stack.pop()
            stack.extend(node.children.items())
            if "template" not in node.uses or node.known:
                continue
            # a number, true / false, sizeof: a name in capitals may be a type
            # parameter here (``vendor::Foo<T>``); one an error says is a value counts
            texts = [text for text in self._texts if id(text) not in node.values_read]
            if not texts:
                continue
            node.values_read.update(id(text) for text in texts)
            pattern = re.compile(rb"(?<![\w.])" + re.escape(name.encode()) + rb"\s*<")
            for text in texts:
                for found in pattern.finditer(text):
                    for index, offset in _template_arguments(text, found.end()):
                        if index not in node.value_arguments and _VALUE_LITERAL.match(
                                text, offset):
                            node.value_arguments.add(index)
                            self.count += 1

    def _spread_calls(self) -> None:
        """Every call in the files read of a function named after a C library whose
        header is missing (``library_prefixes``): clang reports one unknown name of a
        statement, and none in a declaration whose type is unknown (gscam's ``GstCaps *caps
        = gst_app_sink_get_caps(...)``: ``GstCaps`` first, the function only on the next
        parse, which the rounds had run out of, so the function that makes the node's
        publishers kept an error). Not a name written on its line after another word or
        a ``*`` / ``&`` (a declaration of the workspace's own), nor one ending in ``_``
        (motoman's ``robot_id_(robot_id)``, a member initialised, under ``robot``)."""
        if not self.libraries:
            return
        # a prefix has no ``_`` (``library_prefixes``): one of letters and digits is the
        # whole run of them a name starts with, so every call of a name with a ``_`` is
        # found once and its first word looked up (a pattern of all the prefixes tried
        # each one at every place of the text); other prefixes by that pattern
        prefixes = {p.encode() for p in self.libraries}
        plain = all(p.isascii() and p.isalnum() for p in self.libraries)
        pattern = _LIBRARY_CALL if plain else re.compile(
            rb"(?<![\w:.>])((" + b"|".join(re.escape(p) for p in sorted(
                prefixes, key=len)[::-1]) + rb")_\w+)\s*\(")
        for text in self._texts:
            if (id(text), "\0calls") in self._spread_done:
                continue
            self._spread_done.add((id(text), "\0calls"))
            for found in pattern.finditer(text):
                if found.group(2) not in prefixes:
                    continue
                if self.count >= MAX_NAMES:
                    return
                name = found.group(1).decode()
                if name in self.root.children or name in self.friends or name.endswith("_"):
                    continue  # (``robot_id_(id)``: a member in an initialiser list)
                before = text[text.rfind(b"\n", 0, found.start()) + 1:found.start()].rstrip()
                last = before[-1:]
                word = last.isalnum() or last == b"_"
                if last and (last in b"*&" or (word and not before.endswith(b"return"))):
                    continue
                if _initialised_member(text, found, before):
                    continue
                self._from_source(text, found.start(), "any", [])

    def read_members(self, texts: Iterable[bytes]) -> None:
        """Every name the code reads after ``.`` or ``->``, and every value it reads from
        a scope (``Mode::FAST``), as a member of the declared classes (a member of a
        vendor object is an error only once its class is declared: the next wave), but
        the API's own methods. Not as member templates where the code does not say it
        names one: ``x.get<T>("node")`` is better left an error, so that the calls on
        what it returns are kept by their API name (a declared template returns an
        object whose API calls then fail); a name after C++'s ``template`` keyword
        (``bb->template set<T>("node", node_)``) is one (``member_templates``)."""
        for text in texts:
            if text is not None:
                members, templates, taken, constants, flags = _members_of(text)
                self.members |= members
                self.member_templates |= templates
                self.taken |= taken
                self.constants |= constants
                self.flags |= flags

    def _learn_one(self, message: str, text: bytes | None, offset: int) -> None:
        if message == "expected namespace name" and text is not None:
            self._using_namespace(text, offset)
            return
        if _BODY_EXPECTED.match(message):
            for macro in _declaration_macros(text, offset) if text is not None else []:
                if macro not in self.declaration_macros:
                    self.declaration_macros.add(macro)
                    self.count += 1
            return
        if _DECLARATOR_ENDED.match(message):
            attribute = _attribute_macro(text, offset) if text is not None else None
            if attribute is not None and attribute not in self.macros:
                self.macros.add(attribute)
                self.count += 1
            return
        template = _NOT_TEMPLATE.match(message)
        if template is not None:
            if template.group(1) not in self.member_templates:
                self.member_templates.add(template.group(1))
                self.count += 1
            return
        named = _NAMES_NO_TEMPLATE.match(message)
        if named is not None:
            name = named.group(1)
            if text is not None and name not in self.member_templates and (
                    name not in _api_methods()) and _discarded_member_call(text, offset, name):
                self.member_templates.add(name)
                self.count += 1
            return
        incomplete = _INCOMPLETE.match(message)
        if incomplete is not None:
            self._complete(incomplete.group(1))
            return
        converted = _NOT_CONVERTED.match(message)
        if converted is not None:
            self._derive(converted.group(1), converted.group(2))
            return
        pointer = _POINTER_TO.match(message)
        if pointer is not None:
            wanted, given = (pointer.group(1), pointer.group(2)) if pointer.group(1) else (
                pointer.group(3), pointer.group(4))
            self._derive(given, wanted)
            return
        if _VALUE_ARGUMENT.match(message):
            if text is not None:
                self._value_argument(text, offset)
            return
        cast = _CAST_UNRELATED.match(message)
        if cast is not None:
            self._derive(cast.group(1), cast.group(2))
            return
        polymorphic = _NOT_POLYMORPHIC.match(message)
        if polymorphic is not None:
            path = self._class_path(polymorphic.group(1))
            if path is not None and not self._node("::".join(path)).polymorphic:
                self._node("::".join(path)).polymorphic = True
                self.count += 1
            return
        ambiguous = _AMBIGUOUS.match(message)
        if ambiguous is not None:
            self.withdrawn.add(ambiguous.group(1))
            return
        twice = _AMBIGUOUS_MEMBER.match(message)
        if twice is not None:
            if twice.group(1) in self.members | self.member_templates:
                self.withdrawn_members.add(twice.group(1))
            return
        if _TYPE_AS_VALUE.match(message):
            if text is not None:
                self._a_value(text, offset)
            return
        if _CONSTRUCTION_AMBIGUOUS.match(message):
            if text is not None:
                self._constant_arguments(text, offset)
            return
        member_type = _MEMBER_TYPE.match(message)
        if member_type is not None and "namespace" not in message:
            name, record = member_type.group(1), member_type.group(2)
            if self._synthesised(record) and record != "haros_any":
                node = self._node(record)
                if name not in node.children:
                    node.children[name] = _Name(uses={"type"})
                    self.count += 1
            elif self._message(record) and name not in self.types.get(record, ()):
                self.types.setdefault(record, set()).add(name)
                self.count += 1
            return
        member = _MEMBER.match(message)
        if member is not None and "namespace" not in message:
            name, record = member.group(1), member.group(2)
            if name in _KEYWORDS:
                return
            if record in _qt_classes():
                if name not in self.qt_members:
                    self.qt_members.add(name)
                    self.count += 1
                return
            if member.group(3) and not self._synthesised(record):
                return
            if self._synthesised(record) and record != "haros_any" and text is not None \
                    and _names_a_declared_type(name, text, offset):
                node = self._node(record)
                if name not in node.children:
                    node.children[name] = _Name(uses={"type"})
                    self.count += 1
            elif self._synthesised(record):
                self.members.add(name)
            elif self._message(record) and name not in self.fields.get(record, ()):
                self.fields.setdefault(record, set()).add(name)
                self.count += 1
            elif self._derives_from_declared(record.split("::")[-1]):
                # a class of the code derived from a declared one, asked for a member it
                # does not declare (ROBOTIS-OP3's ``OpenCRModule::getInstance()``, the
                # static of its framework's ``Singleton<OpenCRModule>`` base): the
                # base's, a member of the permissive class it derives from
                self.members.add(name)
            return
        for pattern, use in _MESSAGES:
            match = pattern.match(message)
            if match is None:
                continue
            if text is None:
                return
            if match.lastindex:
                offset = _spelled_at(match.group(1), text, offset)
            if use == "type" and match.lastindex == 1 and _bare_macro(
                    match.group(1), text, offset):
                if match.group(1) not in self.macros:
                    self.macros.add(match.group(1))
                    self.count += 1
                return
            scope = match.group(2).split("::") if match.lastindex == 2 else []
            self._from_source(text, offset, use, scope)
            return

    def _from_source(self, text: bytes, offset: int, use: str, scope: list[str]) -> None:
        """The qualified name written at ``offset``: the unknown part and what follows."""
        if _namespace_alias_at(text, offset) is not None:
            # a namespace alias's target (clang's ``use of undeclared identifier
            # 'vendor'`` first, or its spread): namespaces, not a value at the end
            self._using_namespace(text, offset)
            return
        found = _NAME_AT.match(text, offset)
        if found is None:
            return
        written = [p.strip().removeprefix(b"template").strip().decode()
                   for p in found.group(0).split(b"::")]
        if not scope and len(written) > 1 and written[0] in self.namespace_aliases and (
                self.namespace_aliases[written[0]][0] != "std"):
            # ``arm::Arm`` where the code declares ``namespace arm = vendor::arm;``: the
            # target's name (a top-level ``arm`` would clash with the alias)
            written = [*self.namespace_aliases[written[0]], *written[1:]]
        if not scope and written[0] in self.template_aliases and (
                self._unknown_root(self.template_aliases[written[0]][0])):
            if len(written) < 3:
                return  # ``PM::DataPoints``: the template's member, as its errors say
            # ``PM::TransformationParameters::Identity``: the class nested in the template
            # and its member, declared in the template the alias names
            written = [*self.template_aliases[written[0]], *written[1:]]
        if not scope:  # the known scope written before the name: ``known::``
            window = text[max(0, offset - 200):offset]
            before = _scope_before(window)
            if before is not None:
                scope = [p.strip().decode() for p in before.group(0).split(b"::") if p.strip()]
                if "std" in scope:
                    return  # never reopen the standard library
        if any(p in _KEYWORDS for p in written) or any(p in _KEYWORDS for p in scope):
            return
        rest = text[found.end():found.end() + 2]
        owner = [*scope, *written[:-1]]
        if owner and rest.lstrip()[:1] == b"<" and (_member_named(text, offset) or (
                _template_called(text, found.end())
                and self._class_path("::".join(owner)) is not None)):
            # a member named with its class and given template arguments, ``sensor->
            # rs2::sensor::is<rs2::depth_sensor>()`` (realsense2_camera's
            # rs_node_setup.cpp) or ``rs2::sensor::is<T>()`` in a method of a class
            # derived from it (its ros_sensor.h): a member template of the permissive
            # class, not a type in that scope (which made every ``sensor.is<T>()`` an
            # error)
            if written[-1] not in self.member_templates:
                self.member_templates.add(written[-1])
                self.count += 1
            return
        window = text[max(0, offset - 200):offset]
        if use == "any" and ((written[-1][:1].isupper() and _aliased(window)) or (
                (b"using" in window or b"typedef" in window)
                and _ALIAS_DECLARED.search(window) is not None)):
            # ``using Mode = vendor::Mode;``, ``using vendor::msg::Limit;``: a type (a
            # lowercase name a using-declaration brings is more often a function; one
            # an alias declaration names is a type)
            use = "type"
        last = self._last_use(use, rest)
        if last == "type" and use == "any" and rest.lstrip()[:1] not in (b"(", b"{") and (
                _after_operator(_unscoped(window))):
            # ``(30 * DEGREE2RADIAN)``, ``c ? Vendor::K * 2.0 : x``: an operand, a value
            # (a type there, but a functional cast's, would be a syntax error; one use read
            # as a type made every other use an error, "does not refer to a value")
            last = "value"
        if last == "type" and use == "any" and (
            rest.lstrip()[:1] in (b")", b",", b"}") or (
                rest.lstrip()[:1] == b">" and _template_argument(window.rstrip())
                and _TYPE_FIRST.search(_unscoped(window)) is None)
        ) and (
            _CONSTANT.fullmatch(written[-1])
            or text[max(0, offset - 8):offset].rstrip().endswith(b"=")
            or (len(written) == 1 and _member_call_argument(text, offset))
            or (rest.lstrip()[:1] == b")" and _CASE_OPEN.search(
                text[max(0, offset - _CONSTANT_SPAN):offset]) is not None)
        ):
            # ``f(vendor::MODE_A)``, ``x = vendor::FRAMING_OK,``: an enumerator or a
            # constant read as a value (a class there would be a syntax error), and one
            # a template's argument list ends with (``std::array<T, vendor::SIZE>``); so is
            # one in parentheses after ``case`` (kobuki's ``case (ecl::OpenError):``,
            # where a type is a cast with no operand)
            last = "value"
        if last == "type" and use == "any" and rest.lstrip()[:1] not in (b"(", b"{") and (
                text[max(0, offset - 8):offset].rstrip()[-2:] in (b"==", b"!=")):
            # ``err != UVC_SUCCESS && n == 1``: an operand of a comparison is a value
            # whatever follows it (``&&`` there is no rvalue reference's; a type could
            # only be a functional cast, ``x != T(...)``)
            last = "value"
        if last == "type" and use == "any" and (scope or len(written) > 1) and (
                _called_statement(text, offset, found.end())):
            # ``spdlog::set_default_logger(logger);`` (spdlog's headers missing): a
            # statement of a call alone is a function's call; a class there would make
            # it a declaration of ``logger``, which the line before declares already
            last = "value"
        if use == "any" and not scope and len(written) == 1 and (
            last == "value" or rest.lstrip()[:1] == b"("
        ) and not (written[-1] in _STD_VALUES and written[-1] not in self._defined):
            called = rest.lstrip()[:1] == b"("
            if not _C_VENDOR.fullmatch(written[-1]) and not (
                not called and _CAPITALS.fullmatch(written[-1])
            ) and not (
                called and "_" in written[-1]
                and written[-1].split("_")[0] in self.libraries
            ) and not (called and _CAPS_MACRO.fullmatch(written[-1])):
                if called and ((id(text), offset) in self.in_free or (
                        self.libraries - COMPILER_LIBRARIES
                        and (id(text), offset) in self.in_read)) and (
                        written[-1] not in _api_methods()):
                    # (a name called again in a free function stays free: made a friend
                    # too it was declared neither way, ``free - friends``; subt's
                    # ``EndsWith(a, "/x") || EndsWith(a, "/y")``)
                    if written[-1] not in self.free:
                        self.free.add(written[-1])
                        self.count += 1
                elif called and written[-1] not in self.friends and (
                        written[-1] not in _api_methods()):
                    # (an API method's name stays an error: a call the parse cannot
                    # resolve is kept by that name, the friend would take it)
                    self.friends.add(written[-1])
                    self.count += 1
                    if self.qt:
                        # in a unit with the Qt stand-in, a method of a class derived
                        # from one of its classes (mapviz's ``adjustSize()``, multires'
                        # ``centralWidget()`` in a QMainWindow) may be the base's
                        self.qt_members.add(written[-1])
                # a value given as a whole argument of an object's method in a free
                # function (``main``), where no class member can be shadowed: a constant
                # of a missing header, declared at namespace scope as a qualified one is
                # (ydlidar_ros2_driver's main passes the SDK's ``LidarPropSerialPort`` to
                # ``laser.setlidaropt(...)``); not an object whose method is called
                # (``unknown.load()`` stays an error where a wrapper's call may hide)
                free_value = not called and last == "value" and (
                    (id(text), offset) in self.in_free) and _member_call_argument(
                        text, offset)
                if not called and not free_value and self._derives_from_declared(None):
                    # a variable a class derived from a declared one reads is often the
                    # base's (ROBOTIS-OP3's modules set their framework base's
                    # ``module_name_``): a member of the permissive class, which only
                    # such a class (or a permissive value) finds, so nothing is shadowed
                    self.members.add(written[-1])
                if not free_value:
                    return  # an unqualified function or variable: in a class, often a
                    # member clang could not find (an invalid base); declaring it would
                    # shadow it
            # but a C library's constant or prefixed function, whose header is missing
            # (``SDL_Init(SDL_INIT_JOYSTICK | SDL_INIT_HAPTIC)``, ``SDL_GetError()``; a
            # lowercase one named after the missing header: ``ogg_stream_init(...)`` of
            # <ogg/ogg.h>), is no member: a value (a call is the value's ``operator()``)
            last = "value"
        if written[0] in self.aliases and (not scope or len(written) > 1):
            # ``Mode::FAST`` where the code declares ``using Mode = vendor::Mode;``: not
            # a name of its own (it would clash with the alias), a member of what the
            # alias names once that is declared; also reached through the namespace of
            # the alias (mavros' ``plugin::MTYPE::FENCE``: declared a namespace there,
            # ``using MTYPE = ...`` was a redefinition and the class that uses it invalid);
            # the alias alone through its namespace is still declared there (mavros'
            # ``ftf::Covariance3d``, an alias whose own target the parse does not know)
            if len(written) == 2 and written[1] not in self.members:
                self.members.add(written[1])
            return
        node = self.root
        for part in scope:
            node = node.children.setdefault(part, _Name(known=True))
        for i, part in enumerate(written):
            if part not in node.children:
                node.children[part] = _Name()
                self.count += 1
            node = node.children[part]
            if not node.known:
                node.uses.add("scope" if i < len(written) - 1 else last)
        # not a name called (``UINT64_C(0x9e37)`` in a constexpr initialiser: a macro
        # whose header is missing, a function for the parse)
        kind = _constant_at(written[-1], text, offset, found.end()) if (
            last == "value" and not node.known
            and text[found.end():found.end() + 16].lstrip()[:1] != b"(") else None
        if kind is not None and not {"constant", kind} <= node.uses:
            node.uses.update(("constant", kind))
            self.count += 1

    def _using_namespace(self, text: bytes, offset: int) -> None:
        """``using namespace vn::math;`` of a namespace the parse does not know, no name
        of it written qualified (vectornav's driver: its SDK's headers missing, the
        names it uses from ``vn::math``, ``vn::sensors``, ``vn::xplat`` all written
        bare): declared, each part a namespace, so the directive is valid and the
        names it brings are found in it (``_found_by_using``)."""
        start = text.rfind(b"using", max(0, offset - 200), offset + 1)
        found = _USING.match(text, start) if start != -1 else None
        if found is None or not start <= offset <= found.end():
            # or a namespace alias of one, ``namespace arm = hebi::experimental::arm;``
            # (HEBI's kits, the vendor's headers missing): what it names, declared so
            found = _namespace_alias_at(text, offset)
            if found is None:
                return
        node = self.root
        for part in re.sub(rb"\s+", b"", found.group(found.lastindex or 1)).decode().split("::"):
            if not part or part in _KEYWORDS:
                return
            child = node.children.get(part)
            if child is None:
                child = node.children[part] = _Name()
                self.count += 1
            if not child.known and child.uses != {"scope"} and child.uses <= _VALUE_USES:
                # a name the failed directive made a value (``use of undeclared
                # identifier``) is the namespace the directive needs
                child.uses = {"scope"}
                self.changed += 1
            node = child

    def _complete(self, qualified: str) -> None:
        """A class declared but never defined, which the code uses complete
        (``_INCOMPLETE``): defined permissively, in its namespaces. Not when a file read
        defines it (its definition is then real, if out of this parse's reach), nor a
        class of the standard library, nor one whose scopes are not all namespaces the
        files read open (a nested class cannot be defined from outside its class)."""
        parts = qualified.split("::")
        if parts[0] == "std" or any(p in _KEYWORDS for p in parts):
            return
        name = re.escape(parts[-1].encode())
        defined = re.compile(rb"\b(?:class|struct)\s+(?:[A-Z][A-Z0-9_]*\s+)*" + name +
                             rb"\s*(?:final\s*)?[:{]")
        if any(defined.search(text) for text in self._texts):
            return
        node = self.root
        for i, part in enumerate(parts[:-1]):
            child = node.children.get(part)
            if child is None:
                opened = re.compile(rb"\bnamespace\s+(?:\w+\s*::\s*)*" + re.escape(
                    part.encode()) + rb"\b")
                # (a namespace the parse has at the top or directly in one there:
                # Gazebo's ``gazebo::physics``, which its stand-in opens)
                if not (self.declared is not None and (
                        self.declared(part) if i == 0 else (
                            i == 1 and part in self.declared(parts[0])))) and (
                        not any(opened.search(text) for text in self._texts)):
                    return
                child = node.children[part] = _Name(known=True)
            if not _is_namespace(child):
                return
            node = child
        if parts[-1] not in node.children:
            node.children[parts[-1]] = _Name(uses={"type"})
            self.count += 1

    def _a_value(self, text: bytes, offset: int) -> None:
        """A name declared as a class and read as a value (``f(vendor::MODE_A, x)``:
        after a comma, it looked like a template argument): declared as a value."""
        found = _NAME_BEFORE.search(text[max(0, offset - 200):offset])
        if found is None:
            return
        parts = [p.strip().decode() for p in found.group(1).split(b"::") if p.strip()]
        node: _Name | None = self.root
        for part in parts:
            node = node.children.get(part) if node is not None else None
        if node is not None and not node.known and not node.children and \
                node.uses == {"type"}:
            node.uses = {"value"}
            self.count += 1

    def _constant_arguments(self, text: bytes, offset: int) -> None:
        """The arguments of the construction written at ``offset`` (``C(a, b)``,
        ``C{a}``) that are declared values named as constants (``_CONSTANT``): declared
        as constants (enumerators), which no class converts to but through a
        constructor (``_CONSTRUCTION_AMBIGUOUS``)."""
        called = _CALLED_AT.match(text, offset)
        if called is None:
            return
        depth, start, at, arguments = 0, called.end(), called.end(), []
        while at < len(text) and at - called.end() < _TEMPLATE_SPAN:
            char = text[at:at + 1]
            if char in b"([{":
                depth += 1
            elif char in b")]}" and depth:
                depth -= 1
            elif char in b")]}" or (char == b"," and not depth):
                arguments.append(text[start:at])
                start = at + 1
                if char != b",":
                    break
            at += 1
        for argument in arguments:
            parts = [p.strip().decode() for p in argument.split(b"::")]
            if not parts or not all(re.fullmatch(r"[A-Za-z_]\w*", p) for p in parts) or (
                    not _CONSTANT.fullmatch(parts[-1])):
                continue
            node: _Name | None = self.root
            for part in parts:
                node = node.children.get(part) if node is not None else None
            if node is not None and not node.known and not node.children and (
                    node.uses == {"value"}):
                node.uses.add("constant")
                self.changed += 1  # a name declared already: no more of MAX_NAMES

    @staticmethod
    def _last_use(use: str, after: bytes) -> str:
        if after.startswith(b"<"):
            return "template"
        if use != "any":
            return use
        rest = after.lstrip()
        if not rest or rest[:1] in b"(){},>&*" or _IDENT.match(rest):
            return "type"
        return "value"

    def _node(self, qualified: str) -> _Name:
        node = self.root
        for part in qualified.split("::"):
            node = node.children[part]
        return node

    def _derives_from_declared(self, name: str | None) -> bool:
        """Whether a class the files read define (named ``name``; any when None) has a
        base the parse did not know (a declared name, or the permissive class)."""
        for text in self._texts[self._heads_read:]:  # (read only when asked)
            self._heads.extend(_class_heads(text))
        self._heads_read = len(self._texts)
        if not self._heads:
            return False
        key = (self.count, len(self._heads))
        if self._derived_heads[0] != key:  # (again only once a name or a file was learnt)
            self._derived_heads = (key, frozenset(
                head for head, bases in self._heads if any(
                    self._synthesised(base) or self._class_path(base) is not None
                    for base in bases)))
        derived = self._derived_heads[1]
        return bool(derived) if name is None else name in derived

    def _unknown_root(self, name: str) -> bool:
        """Whether ``name`` is a top-level name declared here (not the code's own)."""
        node = self.root.children.get(name)
        return node is not None and not node.known and name not in self._defined

    def _synthesised(self, qualified: str) -> bool:
        if qualified == "haros_any":
            return True
        node = self.root
        for part in qualified.split("::"):
            if part not in node.children:
                return False
            node = node.children[part]
        return not node.known

    def _class_path(self, written: str) -> list[str] | None:
        """The path of the one declared class (in namespaces only) that ``written``
        names, as clang prints it (unqualified after a using-declaration): None when
        none or several are."""
        parts = [p for p in written.split("::") if p]
        found: list[list[str]] = []
        stack: list[tuple[list[str], _Name]] = [([], self.root)]
        while stack:
            path, node = stack.pop()
            for name, child in node.children.items():
                if child.known or _is_namespace(child):
                    stack.append(([*path, name], child))
                elif [*path, name][-len(parts):] == parts and "template" not in child.uses:
                    found.append([*path, name])
        if len(found) > 1:  # the one a using-declaration or -directive brings
            found = [f for f in found if "::".join(f) in self.brought
                     or "::".join(f[:-1]) in self.using]
        return found[0] if len(found) == 1 else None

    def _value_argument(self, text: bytes, offset: int) -> None:
        """The argument at ``offset`` of a declared template's use is a value: its
        position (the commas before it in the argument list) takes a non-type
        parameter. Only a value written as one: a number, ``true`` / ``false``,
        ``sizeof``, a name in capitals (``M``, ``N_SCANS``); not a name the parse
        declared a value that names a type (``absl::make_unique<carto::io::Builder>``)."""
        if not _VALUE_WRITTEN.match(text, offset):
            return
        depth, index, at = 0, 0, offset - 1
        while at >= 0 and offset - at < _TEMPLATE_SPAN:
            char = text[at:at + 1]
            if char in b">)]}":
                depth += 1
            elif char in b"([{":
                if depth == 0:
                    return  # not in a template argument list
                depth -= 1
            elif char == b"<":
                if depth == 0:
                    break
                depth -= 1
            elif char == b"," and depth == 0:
                index += 1
            elif char == b";":
                return
            at -= 1
        else:
            return
        name = _SCOPE_NAME_BEFORE.search(text[max(0, at - 200):at])
        if name is None:
            return
        path = self._template_path(re.sub(rb"\s+", b"", name.group(0)).decode())
        if path is None:
            return
        node = self._node("::".join(path))
        if index not in node.value_arguments:
            node.value_arguments.add(index)
            self.count += 1

    def _template_path(self, written: str) -> list[str] | None:
        """The path of the one declared template ``written`` names (``_class_path``'s
        look-up, for templates)."""
        parts = [p for p in written.split("::") if p]
        found: list[list[str]] = []
        stack: list[tuple[list[str], _Name]] = [([], self.root)]
        while stack:
            path, node = stack.pop()
            for name, child in node.children.items():
                if "template" in child.uses and [*path, name][-len(parts):] == parts:
                    found.append([*path, name])
                if child.known or _is_namespace(child) or child.children:
                    stack.append(([*path, name], child))
        return found[0] if len(found) == 1 else None

    def _derive(self, given: str, wanted: str) -> None:
        derived, base = self._class_path(given), self._class_path(wanted)
        if derived is None or base is None or derived == base:
            return
        node = self._node("::".join(derived))
        qualified = "::".join(base)
        seen: set[str] = {"::".join(derived)}  # no cycle of bases
        at: str | None = qualified
        while at is not None and at not in seen:
            seen.add(at)
            at = self._node(at).base
        if at is None and node.base is None:
            node.base = qualified
            self.count += 1

    def _derived(self, hidden: set[str], values: _Values) -> list[str]:
        """The classes with a base (``_derive``), defined after every other name, bases
        first, each in its namespaces: ``struct B : ::vendor::A`` (its place in the tree
        holds a declaration)."""
        pending: list[tuple[list[str], _Name]] = []
        stack: list[tuple[list[str], _Name]] = [
            ([name], child) for name, child in self.root.children.items() if name not in hidden]
        while stack:
            path, node = stack.pop()
            if node.base is not None:
                pending.append((path, node))
            elif node.known or _is_namespace(node):
                stack.extend(([*path, name], child) for name, child in node.children.items())
        lines: list[str] = []
        done: set[str] = set()
        while pending:
            ready = [(p, n) for p, n in pending if n.base in done or
                     self._node(n.base or "").base is None]
            if not ready:
                break
            for path, node in sorted(ready, key=lambda item: item[0]):
                base = "::" + (node.base or "")
                node_base, node.base = node.base, None
                body = _render(path[-1], node, "", nested=False, values=values,
                               withdrawn=self.withdrawn)
                node.base = node_base
                if not body or not body[0].startswith(("struct ", "template")):
                    continue
                head = body[0].replace(": haros_any {", f": {base} {{", 1)
                inherit = f"  using {base}::{base.rsplit('::', 1)[-1]};"
                body = [head, inherit, *(line for line in body[1:]
                                         if line.strip() != "using haros_any::haros_any;")]
                lines += [*(f"namespace {p} {{" for p in path[:-1]), *body,
                          "}" * (len(path) - 1)]
                done.add("::".join(path))
            pending = [(p, n) for p, n in pending if "::".join(p) not in done and
                       (p, n) not in ready]
        return lines

    def header(self) -> str:
        values = _Values(self.taken)
        kept = self.members - self.withdrawn_members
        members = "".join(f"  static haros_any {m};\n" for m in sorted(kept)
                          if m not in self.constants and m not in self.member_templates)
        members += "".join(
            f"  template <class... T, class... A> static haros_any &{m}(const A &...);\n"
            for m in sorted(self.member_templates - self.constants - self.withdrawn_members))
        members += "".join(f"  enum : int {{ {m} = {values.next(m in self.flags)} }};\n"
                           for m in sorted(self.constants & kept))
        members += "".join(f"  template <class... A> friend haros_any &{f}(const A &...);\n"
                           for f in sorted(self.friends - self.members - self.member_templates))
        lines = [_PRELUDE % (_COMPOUND_MEMBERS, members, _OPERATORS)]
        # (not a name also declared as a type, scope or template: a function of its name
        # would hide it, ``struct`` needed wherever it is named; moveit_setup_assistant's
        # ``TiXmlElement(...)``, a construction, beside ``TiXmlElement *``)
        lines += [f"template <class... A> haros_any &{f}(const A &...);"
                  for f in sorted(self.free - self.friends - self.root.children.keys())]
        if self.qt_members:
            lines += [f"#define {QT_MORE.upper()}_DEFINED", f"struct {QT_MORE} {{",
                      *(f"  static haros_any {m};" for m in sorted(self.qt_members)), "};"]
        lines += [f"#define {name}" for name in sorted(self.macros)]
        lines += [f"#define {name}(...)" for name in sorted(self.declaration_macros)]
        # static: a field reads as ``msg.f`` and a constant as ``Msg::F``, and the
        # message stays the plain struct it was (no member to construct or copy); a
        # constant read where C++ needs one (``case Msg::Goal::TOOL_CONTACT:``) is an
        # enumerator of a value of its own
        lines += [f"#define {interfaces.fields_macro(record)} " + " ".join(
            [*(f"typedef haros_any {t};" for t in sorted(self.types.get(record, ()))),
             *(f"enum : int {{ {f} = {values.next(f in self.flags)} }};"
               if f in self.constants else f"static haros_any {f};"
               for f in sorted(self.fields.get(record, ())))])
            for record in sorted({*self.fields, *self.types})]
        hidden = self._found_by_using()
        included = self._included(hidden)
        from_std = self._from_std(hidden)
        lines += [f"using std::{name};" for name in sorted(from_std)]
        for name, node in sorted(self.root.children.items()):
            if name in hidden or name in from_std:
                continue
            if name in included:  # included, not declared again (in ``boost`` reopened too)
                provided = included[name]
                lines += [f"#include <{header}>" for header in sorted(
                    {_PROVIDED[name][n] for n in provided})]
                node = dataclasses.replace(node, children={
                    n: child for n, child in node.children.items() if n not in provided})
                if not node.children:
                    continue
            lines.extend(_render(name, node, "", nested=False, values=values,
                                 withdrawn=self.withdrawn))
        lines += self._derived(hidden, values)
        return "\n".join(lines) + "\n"

    def _message(self, record: str) -> bool:
        """Whether ``record`` may be the struct of a message known only by name."""
        return _RECORD.fullmatch(record) is not None and (
            record.split("::")[0] in self.packages
            or msg_types.written_type(record, None) is not None)

    def _found_by_using(self) -> set[str]:
        """Unknown names used unqualified that a ``using namespace`` of a namespace
        declared here also gives (``Pose2`` and ``karto::Pose2`` after ``using namespace
        karto``), or a using-declaration of that one name (``using
        vendor::conn::Connection;``, motoman's SmplMsgConnection): declared once, in the
        namespace (with what was learnt of the unqualified one), or the unqualified use
        is ambiguous (the using-declaration conflicts with it)."""
        found: set[str] = set()
        # each namespace a ``using namespace`` names, with all its names; each
        # using-declaration (``using vendor::conn::Connection;``), with its one name
        wanted = [(space, None) for space in sorted(self.using)] + [
            (one.rpartition("::")[0], one.rpartition("::")[2]) for one in sorted(self.brought)]
        for space, only in wanted:
            node: _Name | None = self.root
            for part in space.split("::"):
                node = node.children.get(part) if node is not None else None
            if node is None or node is self.root:
                continue
            for name, child in node.children.items():
                top = self.root.children.get(name)
                if (only is not None and name != only) or child.known or top is None or \
                        top.known or name in found or _holds(top, child):
                    # merging a name into one under it would make the names a cycle
                    # that every later walk of them follows for ever
                    continue
                if only is not None and top.uses and top.uses <= _VALUE_USES:
                    # a name the code reads only as a value: not the type that the
                    # using-declaration's line suggests of a capitalised name
                    # (``using nav2_costmap_2d::LETHAL_OBSTACLE;``)
                    child.uses = set(top.uses)
                _merge(child, top)
                found.add(name)
        return found

    def _from_std(self, hidden: set[str]) -> set[str]:
        """The unknown top-level names that are the standard library's, brought by a
        ``using`` the parse did not see (``_STD_UNQUALIFIED``): not one the code
        defines or aliases itself, nor one a ``using`` of a namespace declared here
        gives (``hidden``)."""
        return {name for name, node in self.root.children.items()
                if name in _STD_UNQUALIFIED and not node.known and name not in hidden
                and name not in self._defined and name not in self.aliases}

    def _included(self, hidden: set[str]) -> dict[str, set[str]]:
        """The names the stand-ins provide (``_PROVIDED``) that ``header`` includes
        instead of declaring, by their top-level namespace (not one ``hidden``, declared
        in the namespace a ``using`` names)."""
        found: dict[str, set[str]] = {}
        for name, node in self.root.children.items():
            provided = {n for n in node.children if n in _PROVIDED.get(name, {})}
            if provided and name not in hidden:
                found[name] = provided
        return found

    def _not_declared(self) -> set[int]:
        """The nodes of the names ``header`` does not declare permissively: those the
        stand-ins provide, with what was learnt under them, and a namespace not known
        that holds nothing else."""
        skipped: set[int] = set()
        hidden = self._found_by_using()
        stack = [self.root.children[name] for name in self._from_std(hidden)]
        while stack:
            node = stack.pop()
            skipped.add(id(node))
            stack.extend(node.children.values())
        for name, provided in self._included(hidden).items():
            top = self.root.children[name]
            stack = [top.children[n] for n in provided]
            while stack:
                node = stack.pop()
                skipped.add(id(node))
                stack.extend(node.children.values())
            if set(top.children) == provided:
                skipped.add(id(top))
        return skipped

    def included(self) -> list[str]:
        """The qualified names ``header`` includes a stand-in's declaration for."""
        return sorted(f"{top}::{name}" for top, names in self._included(
            self._found_by_using()).items() for name in names)

    def declared_count(self) -> int:
        """How many names (and members, friends, ...) were learnt, less the names of the
        tree ``header`` includes from a stand-in rather than declares permissively."""
        skipped = self._not_declared()
        stack = [self.root]
        dropped = 0
        while stack:
            node = stack.pop()
            stack.extend(node.children.values())
            dropped += id(node) in skipped and not node.known
        return self.count - dropped

    def first(self, limit: int = 5) -> list[str]:
        """The qualified names of the first few names declared permissively."""
        skipped = self._not_declared()
        found: list[str] = []
        stack = [("", self.root)]
        while stack and len(found) < limit:
            prefix, node = stack.pop(0)
            for name, child in node.children.items():
                qualified = f"{prefix}{name}"
                if id(child) in skipped:
                    continue
                if not child.known and len(found) < limit:
                    found.append(qualified)
                stack.append((qualified + "::", child))
        # then the members declared on messages known only by name (a unit may declare
        # nothing else: ``Limits::SPEED_PARAM`` in a call's arguments)
        for record in sorted(self.fields):
            for member in sorted(self.fields[record]):
                if len(found) < limit:
                    found.append(f"{record}::{member}")
        found.extend(f"{f}()" for f in sorted(self.friends | self.free)[
            :max(0, limit - len(found))])
        return found

    def __bool__(self) -> bool:
        return bool(self.count or self.members or self.fields or self.types)


@functools.lru_cache(maxsize=512)
def _members_of(text: bytes) -> tuple[frozenset[str], frozenset[str], frozenset[int],
                                      frozenset[str], frozenset[str]]:
    """What ``Names.read_members`` learns of one file: the members, the member
    templates, the case labels' integers, the constants and the flags it names. Kept
    per text: every unit of a package reads the same headers."""
    skip = _KEYWORDS | _api_methods()
    members: set[str] = set()
    templates: set[str] = set()
    constants: set[str] = set()
    flags: set[str] = set()
    # in code only: a comment's sentence ends in ``.`` too (a sentence of OpenMower's
    # xesc headers ended before ``size_t``), and an #include names ``.hpp``: a member
    # ``size_t`` of the permissive class hid the type in every class derived from one
    # (``boost::noncopyable``)
    code = _NOT_CODE.sub(b" ", text)
    members.update(n for n in (m.decode() for m in _AFTER_MEMBER.findall(code))
                   if n and n not in skip)
    # ``x->template get<T>()`` says itself that it names a template
    templates.update(n for n in (m.decode() for m in _TEMPLATE_MEMBER.findall(code))
                     if n not in skip)
    taken = _case_literals(text)
    for found in _SCOPED_VALUE.finditer(text):  # not ``using A = ns::A;``
        line = text[text.rfind(b"\n", 0, found.start()) + 1:found.start()]
        name = found.group(1).decode()
        if name not in skip and not _DECLARING.search(line):
            members.add(name)
            # a member of every declared class: a name in capitals only
            # (``std::is_enum<T>::value`` in a static_assert is no constant of a
            # vendor's, and ``msg.value`` is assigned)
            kind = _constant_at(name, text, found.start(1), found.end(1)) if (
                _CONSTANT.fullmatch(name) or _C_VENDOR.fullmatch(name)) else None
            if kind is not None:
                constants.add(name)
                if kind == "flag":
                    flags.add(name)
    return (frozenset(members), frozenset(templates), frozenset(taken),
            frozenset(constants), frozenset(flags))


def _holds(node: _Name, other: _Name) -> bool:
    """Whether ``other`` is ``node`` or a name under it."""
    seen: set[int] = set()
    stack = [node]
    while stack:
        one = stack.pop()
        if one is other:
            return True
        if id(one) not in seen:
            seen.add(id(one))
            stack.extend(one.children.values())
    return False


def _merge(into: _Name, other: _Name) -> None:
    into.uses |= other.uses
    for name, child in other.children.items():
        if name in into.children:
            _merge(into.children[name], child)
        else:
            into.children[name] = child


class _Values:
    """The values of the declared constants: each its own (two case labels of one value
    are an error), none that a case label of the code writes; small (an enum of
    ``uint8_t`` takes them), but those an operator combines, which get a bit of their
    own above the small ones (``case A | B:`` is then no other constant's value) while
    bits last, and sizes (an array's bound, a template's argument), from ``FIRST_SIZE``
    up, which an initialiser of a few elements fits."""

    FIRST_BIT, LAST_BIT = 16, 30

    FIRST_SIZE = 64

    def __init__(self, taken: set[int]) -> None:
        self._used = set(taken)
        self._bits = iter(range(self.FIRST_BIT, self.LAST_BIT + 1))

    def next(self, flag: bool = False, size: bool = False) -> int:
        if flag:
            bit = next(self._bits, None)
            if bit is not None:
                return 1 << bit
        value = next(v for v in itertools.count(self.FIRST_SIZE if size else 1)
                     if v not in self._used)
        self._used.add(value)
        return value


# functions by the standard's names for making an owned object: what each returns
_SMART_FACTORIES = {"make_unique": "unique_ptr", "make_shared": "shared_ptr"}
# the Windows data types' integral names (Microsoft's "Windows Data Types"), which vendors'
# C SDKs define on Linux too, as the same integers (IDS uEye's ueye.h: ``typedef int32_t
# INT``; PEAK's PCANBasic.h: ``DWORD``, ``WORD``, ``BYTE``): a unit whose SDK header is
# missing binds them to its own integers (ueye_cam's ``setGain(..., INT& master_gain)``
# given a dynamic_reconfigure config's ``int`` member), which a permissive class refuses
_WINDOWS_INTEGERS = {
    "BOOL": "int", "BOOLEAN": "unsigned char", "BYTE": "unsigned char", "CHAR": "char",
    "UCHAR": "unsigned char", "SHORT": "short", "USHORT": "unsigned short",
    "WORD": "unsigned short", "INT": "int", "UINT": "unsigned int", "LONG": "int",
    "ULONG": "unsigned int", "DWORD": "unsigned int", "LONGLONG": "long long",
    "ULONGLONG": "unsigned long long", "DWORDLONG": "unsigned long long",
    "INT8": "signed char", "UINT8": "unsigned char", "INT16": "short",
    "UINT16": "unsigned short", "INT32": "int", "UINT32": "unsigned int",
    "INT64": "long long", "UINT64": "unsigned long long", "DOUBLE": "double",
    "FLOAT": "float",
}


def _render(name: str, node: _Name, indent: str, nested: bool, values: _Values,
            withdrawn: set[str] | frozenset[str] = frozenset()) -> list[str]:
    if name in withdrawn and not node.known:
        return []
    space = _is_namespace(node) and not nested
    inner: list[str] = []
    for child, sub in sorted(node.children.items()):
        inner.extend(_render(child, sub, indent + "  ", nested=not space, values=values,
                             withdrawn=withdrawn))
    if space:
        return [f"{indent}namespace {name} {{", *inner, f"{indent}}}"]
    if node.base is not None and not nested:
        return [f"{indent}struct {name};"]  # defined after its base (``Names._derived``)
    if node.uses - {"flag", "size"} == {"value", "constant"} and not node.children:
        # read where C++ needs a constant: an enumerator (an unnamed enum's, which
        # converts to any integer and makes ``enum_value(X)``'s underlying type), that
        # is still compared, passed and assigned as a value
        return [f"{indent}enum : int {{ {name} = "
                f"{values.next('flag' in node.uses, 'size' in node.uses)} }};"]
    if node.uses <= _VALUE_USES:
        return [f"{indent}{'static ' if nested else 'extern '}haros_any {name};"]
    if not nested and "type" in node.uses and not node.uses & {"scope", "template"} \
            and not node.children and name in _WINDOWS_INTEGERS:
        # (read as a value too where it is a cast's type, ``(INT) 2000``, or sizeof's)
        return [f"{indent}typedef {_WINDOWS_INTEGERS[name]} {name};"]
    if name in _SMART_FACTORIES and "template" in node.uses and not node.children:
        # a library's back-port of std::make_unique / make_shared (Kimera-VIO's
        # ``VIO::make_unique<image_transport::ImageTransport>(nh_)``, its header missing):
        # by that name it constructs its template argument from its arguments and owns it,
        # as the standard one does, so the object it makes keeps its class (a handle's
        # namespace, a member assigned with it) instead of the permissive class's
        return [f"{indent}template <class T, class... A> {'static ' if nested else ''}"
                f"std::{_SMART_FACTORIES[name]}<T> {name}(A &&...);"]
    head = "template <class... T> " if "template" in node.uses else ""
    if head and node.value_arguments:
        # a value at each position the code gives one, a type elsewhere, any number
        # of types after (each with a default, for the uses that give fewer)
        head = "template <" + ", ".join(
            f"long long V{i} = 0" if i in node.value_arguments else f"class T{i} = haros_any"
            for i in range(max(node.value_arguments) + 1)) + ", class... T> "
    # the address of an object of a declared type is a pointer to it, not the
    # permissive address a permissive value's is: a template's ``T *`` deduces it
    # (RoboRTS' ``ReadProtoFromTextFile(path, &config)``, its protobuf class declared)
    return [f"{indent}{head}struct {name} : haros_any {{",
            f"{indent}  using haros_any::haros_any;",
            f"{indent}  using haros_any::operator=;",
            f"{indent}  {name} *operator&();",
            f"{indent}  const {name} *operator&() const;",
            *([f"{indent}  virtual ~{name}();"] if node.polymorphic else []),
            *inner, f"{indent}}};"]


def _namespace_alias_at(text: bytes, offset: int) -> re.Match[bytes] | None:
    """The namespace alias (``namespace arm = hebi::experimental::arm;``) whose target
    ``offset`` is in, if it is in one."""
    start = text.rfind(b"namespace", max(0, offset - 200), offset + 1)
    found = _NAMESPACE_ALIAS.match(text, start) if start != -1 else None
    return found if found is not None and found.start(2) <= offset <= found.end() else None


def _is_namespace(node: _Name) -> bool:
    return node.known or node.uses <= {"scope"}
