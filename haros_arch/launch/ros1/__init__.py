"""ROS 1 launch files (roslaunch XML)."""

from .loader import load

__all__ = ["load"]
