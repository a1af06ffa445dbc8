"""A package that builds a library of its own from a folder (add_subdirectory) and lists
its services from a folder other than ``srv/``: fixtures/cpp/nested_library."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "nested_library")


def test_services_listed_from_another_folder_have_their_fields() -> None:
    source = os.path.join(ROOT, "src", "mapper_pkg", "src", "mapper.cpp")
    result = extract_cpp([source], scan([ROOT]), cache_dir=None, jobs=1)
    # srvs/SaveMap.srv is mapper_pkg/srv/SaveMap, with its fields (rosidl reads the
    # files its CMakeLists lists, from any folder)
    assert ("server", "save_map", "mapper_pkg/srv/SaveMap", 14) in [
        (c.kind, c.name, c.type, c.location.line) for c in result.calls]
    unknown = [d.message for d in result.diagnostics if d.code == "CPP_MESSAGE_UNKNOWN"]
    assert not any("save_map" in m for m in unknown)
    # ``bool compress false``: a field with a default value, read on line 18
    assert [d.message for d in result.diagnostics if "SaveMap" in d.message] == []
    # the library under lib/ is not read (its inline code would be walked in every
    # unit): its names are declared, and the publisher named by its constant is kept
    assert ("publish", "?", "std_msgs/msg/String", 13) in [
        (c.kind, c.name, c.type, c.location.line) for c in result.calls]
