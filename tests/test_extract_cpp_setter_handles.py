"""A handle member that a setter, not a constructor, gives its value: open_vins'
``ov_core::YamlParser`` keeps a ``std::shared_ptr<ros::NodeHandle> nh`` that main sets
with ``set_node_handler(nh)`` and reads its settings through it in
``parse_config(name, ...)``, a wrapper of ``nh->getParam(name, ...)``. The wrapper's
summary was made before the unit's member writes were read, so the member counted as
one nothing sets, and a handle not known made the reads the node's own: run_subscribe_msckf
read ``/verbosity`` and ``/use_stereo`` instead of ``/ov_msckf/verbosity`` (set by the
launch file)."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "setter_handles")
SRC = os.path.join(ROOT, "src", "config_reader", "src")


def _reads(*sources: str) -> list[tuple[str, str | None]]:
    found = extract_cpp([os.path.join(SRC, s) for s in sources], scan([ROOT]),
                        cache_dir=None)
    return [(c.name, c.handle_namespace) for c in found.calls if c.kind == "read"]


def test_a_wrapper_reads_on_the_handle_its_setter_was_given() -> None:
    assert _reads("estimator.cpp") == [("~imu_topic", "~")]


def test_a_handle_another_file_sets_is_not_the_nodes_own() -> None:
    # tracker_setup.cpp holds the parser whose handle tracker.cpp sets through the
    # header's ``set_node_handler(nh)``: what tracker.cpp passes, its private handle (it
    # was read as the node's own ``camera_topic``, then as not known there)
    assert _reads("tracker.cpp", "tracker_setup.cpp") == [("~camera_topic", "~")]
