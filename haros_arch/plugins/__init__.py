"""Plugins: classes that pluginlib loads into a host node, and the hosts that load them.

``classes`` reads a package's exported plugin descriptions down to the library targets
that build each class (nodelets and host plugins become ``Node`` models); ``hosts`` is
the table of which host parameters name which plugins; ``attach`` gives a host instance
of a configuration the calls of the plugins its parameters name (imported by
``graph.build`` as ``plugins.attach``; not re-exported here, as it needs ``launch``).
"""

from .classes import (
    Files,
    Library,
    exported_classes,
    library_name,
    loaded_bases,
    named_loads,
    narrow,
    plugin_classes,
)

__all__ = ["Files", "Library", "exported_classes", "library_name", "loaded_bases",
           "named_loads", "narrow", "plugin_classes"]
