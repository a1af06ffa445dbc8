"""The running system: capture its graph and compare it to a model.

``capture(uri)`` reads a ROS 1 master's nodes, topics with types, publishers, subscribers,
services and parameters over its XML-RPC API (Python's standard ``xmlrpc``; no ROS needed).
``capture_ros2(domain, seconds)`` reads a ROS 2 system from DDS discovery and
``capture_bag(path)`` a recorded ROS 1 or ROS 2 bag; both need the optional ``live`` extra
(Cyclone DDS's Python binding, ``rosbags``) and say so when it is missing.
``compare(model_data, live_data, config)`` gives precision and recall per element kind,
with every missing and extra element listed.
"""

from .bag import capture_bag
from .capture import CaptureError, capture
from .compare import Comparison, compare
from .dds import capture_ros2

__all__ = ["CaptureError", "Comparison", "capture", "capture_bag", "capture_ros2", "compare"]
