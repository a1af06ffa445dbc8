"""Values given to a node class's constructor (``std::make_shared<T>(args)``, ``new
T(args)``, ``T obj(args)``, in the same file or in another file of the node) flow into
its parameters, its defaults and the members it initialises, so the names built from
them resolve: one call per value the node's files pass."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "constructors")
SRC = os.path.join(ROOT, "src", "relay2", "src")


def rows(result: CppResult) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.type, c.queue_size, c.location.file.rsplit("/", 1)[-1]
             if c.location.file else None, c.location.line) for c in result.calls]


@pytest.fixture(scope="module")
def relays() -> CppResult:
    sources = [os.path.join(SRC, "relays.cpp"), os.path.join(SRC, "relay_node.cpp")]
    return extract_cpp(sources, scan([ROOT]), cache_dir=None)


@pytest.fixture(scope="module")
def camera() -> CppResult:
    return extract_cpp([os.path.join(SRC, "camera.cpp")], scan([ROOT]), cache_dir=None)


def test_constructor_in_another_file(relays: CppResult) -> None:
    """make_shared, new and a local object in relays.cpp; the constructor, which keeps
    the output topic in a member, in relay_node.cpp."""
    assert rows(relays) == [
        ("publish", "chatter_relayed", "std_msgs/msg/String", 10, "relay_node.cpp", 9),
        ("publish", "right", "std_msgs/msg/String", 10, "relay_node.cpp", 9),
        ("publish", "down", "std_msgs/msg/String", 10, "relay_node.cpp", 9),
        ("subscribe", "chatter", "std_msgs/msg/String", 10, "relay_node.cpp", 10),
        ("subscribe", "left", "std_msgs/msg/String", 10, "relay_node.cpp", 10),
        ("subscribe", "up", "std_msgs/msg/String", 10, "relay_node.cpp", 10),
        ("publish", "chatter_relayed/status", "std_msgs/msg/String", 1, "relay_node.cpp", 16),
        ("publish", "right/status", "std_msgs/msg/String", 1, "relay_node.cpp", 16),
        ("publish", "down/status", "std_msgs/msg/String", 1, "relay_node.cpp", 16),
    ]
    assert not [d for d in relays.diagnostics if d.code == "CPP_DYNAMIC_NAME"]


def test_node_name_from_several_constructions_is_unknown(relays: CppResult) -> None:
    """Node(name) with "relay" (the default), "second" and "third": no one name."""
    assert relays.rosname == "?"


def test_defaults_of_the_constructor(camera: CppResult) -> None:
    """make_shared<CameraNode>(topic), topic a string variable: passing it on to a
    constructor does not change it."""
    assert rows(camera) == [
        ("publish", "image", "std_msgs/msg/String", 5, "camera.cpp", 14),
        ("publish", "camera_node/info", "std_msgs/msg/String", 1, "camera.cpp", 15),
    ]
    assert camera.rosname == "camera_node"
