"""controller_manager's launch helpers (``controller_manager.launch_utils``), as the
static Python interpreter knows them: rows of ``python_api.API``, never ros2_control's code.

``generate_load_controller_launch_description(name, controller_type, params_file,
extra_spawner_args)`` and ``generate_controllers_spawner_launch_description(names,
controller_params_files=..., extra_spawner_args=...)`` (and its ``_from_dict`` form)
return a launch description that declares ``controller_manager_name`` (default
``controller_manager``) and ``unload_on_kill`` (default ``false``) and starts one
``controller_manager spawner`` with the controller names, ``--controller-manager`` and
that argument, a ``--param-file`` per file given, ``--unload-on-kill`` when the argument
is ``true``, then the extra arguments. ``controller_type`` is accepted and not passed on,
as Humble's and Jazzy's code does (the type comes from the parameter files). The action
classes are built with the interpreter's own rows, as the helper's code builds them.
"""

from __future__ import annotations

import ast
from typing import TYPE_CHECKING, Any

from ...model.values import Unknown
from .python_methods import Args, Builder, Kwargs, arg

if TYPE_CHECKING:
    from .python import Interpreter


def _spawner(i: Interpreter, names: Any, files: Any, extra: Any, n: ast.AST) -> Any:
    if not isinstance(names, (list, tuple)):
        return i.unsupported(n, "controller names not known statically")
    if files is not None and not isinstance(files, (list, tuple)):
        return i.unsupported(n, "controller parameter files not known statically")
    if extra is not None and not isinstance(extra, (list, tuple)):
        return i.unsupported(n, "extra spawner arguments not known statically")
    config = i.api["LaunchConfiguration"]
    words: list[Any] = [*names, "--controller-manager",
                        config(i, ["controller_manager_name"], {}, n)]
    for path in files or ():
        if path:
            words += ["--param-file", path]
    words.append(i.api["PythonExpression"](i, [[
        '"--unload-on-kill"', ' if "true" == "', config(i, ["unload_on_kill"], {}, n),
        '" else ""']], {}, n))
    words += list(extra or ())
    declare = i.api["DeclareLaunchArgument"]
    return i.api["LaunchDescription"](i, [[
        declare(i, ["controller_manager_name"], {"default_value": "controller_manager"}, n),
        declare(i, ["unload_on_kill"], {"default_value": "false"}, n),
        i.api["Node"](i, [], {"package": "controller_manager", "executable": "spawner",
                              "arguments": words, "shell": True, "output": "screen"}, n),
    ]], {}, n)


def spawners(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``generate_controllers_spawner_launch_description(names, [controller_type,]
    controller_params_files=None, extra_spawner_args=[])``."""
    # Humble's second parameter is ``controller_type`` (unused), Jazzy's the files
    files_at = 1 if len(a) > 1 and isinstance(a[1], (list, tuple)) else 2
    return _spawner(i, arg(a, k, 0, "controller_names"),
                    arg(a, k, files_at, "controller_params_files"),
                    arg(a, k, files_at + 1, "extra_spawner_args"), n)


def spawners_from_dict(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``..._from_dict({name: file | [files] | None}, extra_spawner_args=[])``."""
    info = arg(a, k, 0, "controller_info_dict")
    if not isinstance(info, dict):
        return i.unsupported(n, "controller dict not known statically")
    files: list[Any] = []
    for value in info.values():
        if isinstance(value, (list, tuple)):
            files.extend(value)
        elif value:
            files.append(value)
    return _spawner(i, list(info), files, arg(a, k, 1, "extra_spawner_args"), n)


def load_controller(i: Interpreter, a: Args, k: Kwargs, n: ast.AST) -> Any:
    """``generate_load_controller_launch_description(name, controller_type=None,
    controller_params_file=None, extra_spawner_args=[])``."""
    name = arg(a, k, 0, "controller_name")
    if isinstance(name, Unknown):
        return i.unsupported(n, "controller name not known statically")
    path = arg(a, k, 2, "controller_params_file")
    return _spawner(i, [name], [path] if path else None,
                    arg(a, k, 3, "extra_spawner_args"), n)


CONTROLLER_MANAGER: dict[str, Builder] = {
    "generate_load_controller_launch_description": load_controller,
    "generate_controllers_spawner_launch_description": spawners,
    "generate_controllers_spawner_launch_description_from_dict": spawners_from_dict,
}
