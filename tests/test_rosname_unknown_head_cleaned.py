"""A name that begins with an unknown part keeps that part as written, but the known
rest is cleaned as roscpp cleans every name it resolves: tuw_multi_robot's multi-robot
controller subscribes ``robot_names_[i] + "/" + topic_ctrl_`` with ``topic_ctrl_``
``"/ctrl"``, written ``?//ctrl``. Shown so, its pattern (``.*//ctrl``) matched no
robot's ``/robot_0/ctrl``, and the name was printed with an empty segment."""

from __future__ import annotations

from haros_arch.model.rosname import RosName


def test_an_empty_segment_after_an_unknown_head_is_cleaned() -> None:
    name = RosName.make("?//ctrl", "/ns/", "/ns/node")
    assert name.given == "?//ctrl"
    assert name.full == "?/ctrl"
    assert name.matches("/robot_0/ctrl") and name.matches("/ctrl")
    assert RosName.make("?/a//b/", "/").full == "?/a/b"


def test_an_unknown_head_keeps_what_it_is() -> None:
    for given in ("?", "?/cmd_vel", "?_odom", "??/x"):
        assert RosName.make(given, "/ns/").full == given
