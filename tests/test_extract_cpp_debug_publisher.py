"""A helper class whose template member chooses its overload on rosidl's
``rosidl_generator_traits::is_message<T>`` and makes its publisher on first use, as
autoware_utils' ``DebugPublisher::publish`` does (fixtures/cpp/debug_publisher): the
stand-in of ``rosidl_runtime_cpp/traits.hpp`` declares the traits and each synthesised
interface header specialises them as rosidl_generator_cpp's do, so the call resolves;
its publisher is the call site's, named ``<ns>/<name>``, typed by the type the call
deduces from its message or writes as its template argument."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HERE = os.path.dirname(os.path.abspath(__file__))
FIXTURE = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "debug_publisher")


def _read(name: str) -> str:
    with open(os.path.join(FIXTURE, name), encoding="utf-8") as handle:
        return handle.read()


def test_a_publisher_chosen_on_rosidl_traits_is_the_call_sites(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg", "ament_cmake"),
                       "pkg/include/pkg/debug_publisher.hpp": _read("debug_publisher.hpp"),
                       "pkg/src/node.cpp": _read("node.cpp")})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name, c.type, c.location.line) for c in result.calls] == [
        ("publish", "filter/pose", "geometry_msgs/msg/PoseStamped", 33),
        ("publish", "filter/elapsed", "std_msgs/msg/Float64", 34)]
