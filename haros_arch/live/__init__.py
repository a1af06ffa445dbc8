"""The running system (ROS 1): capture a live master's state and compare it to a model.

``capture(uri)`` reads nodes, topics with types, publishers, subscribers, services and
parameters over the master's XML-RPC API (Python's standard ``xmlrpc``; no ROS needed).
``compare(model_data, live_data, config)`` gives precision and recall per element kind,
with every missing and extra element listed.
"""

from .capture import CaptureError, capture
from .compare import Comparison, compare

__all__ = ["CaptureError", "Comparison", "capture", "compare"]
