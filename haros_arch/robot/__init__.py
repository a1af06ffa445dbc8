"""Robot descriptions: xacro expanded statically, and the Gazebo plugins they load.

``xacro.expand`` reads a description without running anything; ``gazebo_plugins`` is the
table of what each plugin library publishes, subscribes to and serves; ``attach`` gives
the Gazebo node instance of a configuration the calls of the plugins of the descriptions
its spawners hand it (imported by ``graph.build``; not re-exported, as it needs
``launch``).
"""

from .xacro import Description, expand

__all__ = ["Description", "expand"]
