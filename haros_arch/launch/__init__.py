"""Launch files: which node instances and parameters a configuration starts.

Entry point: ``load(path, workspace, args, environment)`` picks the interpreter by the
launch system the file is written for (``dialect.ros_version``).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from ..workspace import Workspace
from .dialect import ros_version
from .model import LaunchModel, NodeDecl, ParamDecl, without_tests

if TYPE_CHECKING:
    from ..models.launch_files import ModelledFiles

__all__ = ["LaunchModel", "NodeDecl", "ParamDecl", "load", "without_tests"]


def load(path: str, workspace: Workspace, args: Mapping[str, str] | None = None,
         environment: Mapping[str, str] | None = None,
         models: ModelledFiles | None = None) -> LaunchModel:
    """``models``: the ROS 1 launch files of packages not here that their interface
    models hold (``models.launch_files``)."""
    # the readers imported here: what only asks a file's dialect (a re-run that the
    # cache answers, ``autoproject``) imports neither
    if ros_version(path, workspace) == 2:  # by content, then package, then name
        from . import ros2

        return ros2.load(path, workspace, args, environment)
    from . import ros1

    return ros1.load(path, workspace, args, environment, models)
