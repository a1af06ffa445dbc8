"""The local arguments a ROS 2 node is built with: ``rclcpp::NodeOptions::arguments``.

rcl keeps a node's own arguments apart from the process's (the command line a launch
file gives: ``-r __ns:=/robot1``, ``-r __node:=name``) and looks at them first: a
``__ns`` or ``__node`` rule of the node's own names it whatever the launch passes
(``_rcl_remap_name`` in rcl's remap.c: the local rules, then the global ones when
``use_global_arguments``). Code does this to put a node where it wants it
(``rclcpp::NodeOptions().arguments({"--ros-args", "-r", "__ns:=/x"})`` handed to the
node's constructor), and the helper nodes of libraries name themselves so
(``"__node:=" + name``).

``local_arguments`` reads the words of such a list where this unit shows them: the
options written at the construction (``NodeOptions().arguments({...})``, through the
other setters of the chain), a local variable of the function whose ``arguments``
are set before the construction, or a parameter of the function (a node class's
constructor, ``: Node("x", options)``) that every call of it in the unit gives such
options (main's ``std::make_shared<C>(options)``). Where the options come from code the
unit does not show, none are known: the node is named as before.
"""

from __future__ import annotations

from clang.cindex import Cursor, CursorKind

from .call_sites import argument
from .expressions import strip
from .values import Scope, initializer, method_object, render

MAX_DEPTH = 4  # parameters followed to their callers, setters of a chain
NODE_OPTIONS = "NodeOptions"
_SET = "arguments"


def local_arguments(expr: Cursor, scope: Scope, depth: int = 0) -> list[str] | None:
    """The words of the local arguments the ``rclcpp::NodeOptions`` expression ``expr``
    carries (``?`` for a part not known here); None where it sets none this unit shows,
    or its callers disagree."""
    if depth > MAX_DEPTH:
        return None
    expr = strip(expr)
    if expr.kind == CursorKind.CALL_EXPR:
        target = expr.referenced
        if target is None:
            return None
        if target.kind == CursorKind.CONSTRUCTOR:
            # ``NodeOptions(options)`` copies them; ``NodeOptions()`` has none
            given = [c for c in expr.get_children() if c.kind.is_expression()]
            return local_arguments(given[0], scope, depth + 1) if len(given) == 1 and (
                _options(given[0])) else None
        parent = target.semantic_parent
        if parent is None or parent.spelling != NODE_OPTIONS:
            return None
        written = list(expr.get_arguments())
        if target.spelling == _SET and len(written) == 1:
            return _words(written[0], scope)
        # another setter of the chain (``start_parameter_services(false)``) returns the
        # same options
        held = method_object(expr)
        return local_arguments(held, scope, depth + 1) if held is not None else None
    if expr.kind != CursorKind.DECL_REF_EXPR or expr.referenced is None:
        return None
    decl = expr.referenced
    if decl.kind == CursorKind.PARM_DECL:
        return _passed(decl, scope, depth)
    if decl.kind != CursorKind.VAR_DECL or scope.body is None:
        return None
    # the last ``options.arguments(list)`` before ``expr``, else what it was made with
    found: list[str] | None = None
    for node in scope.body.walk_preorder():
        if node.kind != CursorKind.CALL_EXPR or node.spelling != _SET or (
                node.extent.start.offset >= expr.extent.start.offset):
            continue
        held = method_object(node)
        written = list(node.get_arguments())
        if held is not None and strip(held).kind == CursorKind.DECL_REF_EXPR and (
                strip(held).referenced == decl) and len(written) == 1:
            found = _words(written[0], scope)
    if found is not None:
        return found
    value = initializer(decl)
    return local_arguments(value, scope, depth + 1) if value is not None else None


def _passed(parm: Cursor, scope: Scope, depth: int) -> list[str] | None:
    """What every call in the unit of the function of ``parm`` gives it."""
    function = parm.semantic_parent
    sites = scope.sites
    if function is None or sites is None:
        return None
    params = [c for c in function.get_children() if c.kind == CursorKind.PARM_DECL]
    index = next((i for i, p in enumerate(params) if p == parm), None)
    if index is None:
        return None
    seen: list[list[str] | None] = []
    for call, caller in sites.callers(function):
        given = argument(call, parm, index)
        seen.append(local_arguments(given, sites.scope(caller), depth + 1)
                    if given is not None else None)
    if not seen or any(words != seen[0] for words in seen):
        return None
    return seen[0]


def _words(expr: Cursor, scope: Scope) -> list[str] | None:
    """The strings of a list of words: a braced list, or a local variable made with one
    and not changed after (``std::vector<std::string> args = {...}``)."""
    expr = strip(expr)
    if expr.kind == CursorKind.DECL_REF_EXPR and expr.referenced is not None and (
            expr.referenced.kind == CursorKind.VAR_DECL):
        decl = expr.referenced
        if scope.body is not None and any(
                node.kind == CursorKind.CALL_EXPR and node.spelling != _SET
                and (held := method_object(node)) is not None
                and strip(held).kind == CursorKind.DECL_REF_EXPR
                and strip(held).referenced == decl
                for node in scope.body.walk_preorder()):
            return None  # filled by its methods (``push_back``): not read here
        value = initializer(decl)
        return _words(value, scope) if value is not None else None
    lists = [node for node in expr.walk_preorder() if node.kind == CursorKind.INIT_LIST_EXPR]
    if not lists:
        return None
    return [render(scope.string(element)) for element in lists[0].get_children()
            if element.kind.is_expression()]


def _options(expr: Cursor) -> bool:
    """Whether ``expr`` is a ``NodeOptions``."""
    return strip(expr).type.get_canonical().get_declaration().spelling == NODE_OPTIONS
