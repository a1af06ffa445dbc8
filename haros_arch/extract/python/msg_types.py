"""Message, service and action types from Python names, and ``from x.msg import *``.

A type is known by the qualified name its class is imported under
(``std_msgs.msg.String``); it is written in the canonical form of its ROS version:
``std_msgs/String`` in ROS 1, ``std_msgs/msg/String`` in ROS 2. ROS 1 actions are
written without the ``Action`` suffix of their spec class (``actionlib_tutorials/
Fibonacci`` for ``FibonacciAction``).
"""

from __future__ import annotations

from ...workspace import Workspace

INTERFACE_MODULES = ("msg", "srv", "action")
_ACTION_PARTS = ("Action", "ActionGoal", "ActionResult", "ActionFeedback", "Goal", "Result",
                 "Feedback")


def ros_type(qualname: str, version: int, action: bool = False) -> str | None:
    """The ROS type named by a qualified Python name, or None if it names no interface."""
    parts = [p for p in qualname.split(".") if not p.startswith("_")]
    if len(parts) < 3 or parts[-2] not in INTERFACE_MODULES:
        return None
    package, module, name = parts[-3], parts[-2], parts[-1]
    if version == 1:
        if action and module == "msg" and name.endswith("Action") and len(name) > 6:
            name = name[: -len("Action")]
        return f"{package}/{name}"
    return f"{package}/{module}/{name}"


def interface_names(workspace: Workspace, package: str, module: str) -> set[str] | None:
    """The class names ``from package.module import *`` brings in, from the package's
    message, service and action definitions (``interfaces.definition_files``: its
    ``msg/``, ``srv/`` and ``action/`` folders and the others its build lists); None when
    the package cannot be found."""
    root = workspace.find(package)
    if root is None:
        return None
    from ...plugins.classes import remembered

    return remembered("interface names", f"{root}\n{module}", workspace,
                      lambda: _names(root, module))


def _names(root: str, module: str) -> set[str]:
    names: set[str] = set()
    if module == "msg":
        names |= _stems(root, "msg", ".msg")
        for stem in _stems(root, "action", ".action"):  # ROS 1 generates action messages
            names |= {stem + part for part in _ACTION_PARTS}
    elif module == "srv":
        for stem in _stems(root, "srv", ".srv"):
            names |= {stem, stem + "Request", stem + "Response"}
    elif module == "action":
        names |= _stems(root, "action", ".action")
    return names


def _stems(root: str, folder: str, suffix: str) -> set[str]:
    from ..cpp.interfaces import definition_files

    return {name[: -len(suffix)] for name in definition_files(root, folder)
            if name.endswith(suffix)}


def constant(workspace: Workspace, qualname: str, attr: str,
             version: int) -> str | int | float | bool | None:
    """The value of the constant ``attr`` of the message class ``qualname``
    (``sam_msgs.msg.Topics`` and ``DVL_TOPIC``: the class attribute rosidl / genpy make
    of ``string DVL_TOPIC = 'core/dvl'``), from its definition in the workspace, else in
    the shipped catalogue; None when the class names no message or has no such
    constant (``interfaces.constant_value``: a ROS 2 string without its quotes)."""
    parts = [p for p in qualname.split(".") if not p.startswith("_")]
    if len(parts) < 3 or parts[-2] != "msg" or not attr.isupper():
        return None
    package, name = parts[-3], parts[-1]
    from ...plugins.classes import remembered
    from ..cpp import interfaces

    root = workspace.find(package)
    key = f"{root or package}\n{name}\n{version}"
    fields = remembered("message constants", key, workspace,
                        lambda: _constants(root, package, name, version == 2))
    found = fields.get(attr)
    return interfaces.constant_value(found[0], found[1], version == 2) if found else None


def _constants(root: str | None, package: str, name: str,
               ros2: bool) -> dict[str, tuple[str, str]]:
    """The constants of message ``package/name`` (type and text, by name)."""
    from ..cpp import interfaces

    text = None
    path = interfaces.definition_files(root, "msg").get(name + ".msg") if root else None
    if path is not None:
        try:
            with open(path, encoding="utf-8", errors="replace") as handle:
                text = handle.read()
        except OSError:
            text = None
    if text is None:
        text = interfaces.known(package, name, ros2=ros2, kinds=("msg",))
    if text is None:
        return {}
    sections = interfaces.parse_definition(package, name, text).sections
    return {fld.name: (fld.type, fld.constant) for fld in sections[0]
            if fld.constant is not None}
