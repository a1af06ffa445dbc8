"""Launch files: which node instances and parameters a configuration starts.

Entry point: ``load(path, workspace, args, environment)`` picks the interpreter by the
file's format.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..workspace import Workspace
from . import ros1, ros2
from .model import LaunchModel, NodeDecl, ParamDecl

__all__ = ["LaunchModel", "NodeDecl", "ParamDecl", "load"]


def load(path: str, workspace: Workspace, args: Mapping[str, str] | None = None,
         environment: Mapping[str, str] | None = None) -> LaunchModel:
    if ros2.is_ros2(path):  # .py / .yaml / .launch.xml, or ROS 2 tags (exec=, <let>, ...)
        return ros2.load(path, workspace, args, environment)
    return ros1.load(path, workspace, args, environment)
