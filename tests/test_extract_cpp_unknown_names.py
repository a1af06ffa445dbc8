"""Names the stand-in headers do not know never stop a run nor cost a node its calls:
fixtures/cpp/unknown_names."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "unknown_names")
SOURCES = os.path.join(ROOT, "src", "vendor_node", "src")


def extract(name: str) -> CppResult:
    return extract_cpp([os.path.join(SOURCES, name)], scan([ROOT]), cache_dir=None, jobs=1)


def rows(result: CppResult) -> list[tuple[str, str, str | None, int]]:
    return [(c.kind, c.name, c.type, c.location.line) for c in result.calls]


def codes(result: CppResult) -> list[str]:
    return [d.code for d in result.diagnostics]


def test_unbound_name_in_a_value_is_unknown_not_a_crash() -> None:
    result = extract("unbound_name.cpp")
    assert ("publish", "?", "std_msgs/msg/String", 11) in rows(result)


def test_qt_module_headers_beside_their_folders() -> None:
    result = extract("qt_umbrella.cpp")
    assert rows(result) == [("publish", "frames", "std_msgs/msg/String", 13)]
    assert "CPP_INCLUDE_MISSING" not in codes(result)
    assert "CPP_PARSE_ERROR" not in codes(result)
