"""Graph assembly: launch declarations meet node models and become a Computation Graph.

``build`` instantiates every node's calls; ``apply_node_hints`` / ``apply_hints`` merge
the project file's extraction hints; ``find_candidates`` lists what unknown names may be.
"""

from .build import build, external_containers
from .candidates import find_candidates
from .hints import apply_hints, apply_node_hints, prune_orphans

__all__ = ["apply_hints", "apply_node_hints", "build", "external_containers",
           "find_candidates", "prune_orphans"]
