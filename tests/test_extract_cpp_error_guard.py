"""A header that stops the compiler unless a macro is defined (``#ifndef X`` /
``#error``, or ``#if defined(X)`` ... ``#else`` / ``#error``: beluga's
ndt_sensor_model.hpp needs BELUGA_HAS_HDF5, which its CMake gives its target only where
HDF5 is found) declared nothing for the parse, and the names the node takes from it
were lost. Every build that compiles the unit defines the macro, so the unit is parsed
with it, and says so."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "cpp" / "error_guard"


def test_a_macro_an_error_directive_demands_is_defined_for_the_parse() -> None:
    result = extract_cpp([str(FIXTURE / "src" / "ranger.cpp")], scan([str(FIXTURE)]),
                         cache_dir=None, jobs=1)
    calls = sorted((c.kind, c.name, c.queue_size) for c in result.calls)
    assert calls == [("publish", "ranges", 5), ("subscribe", "imu/data", 10)]
    said = sorted(d.message for d in result.diagnostics if d.code == "CPP_MACRO_DEMANDED")
    assert len(said) == 2
    assert "SENSING_HAS_IMU" in said[0] and "include/sensing/imu.hpp:13" in said[0]
    assert "SENSING_HAS_LIDAR" in said[1] and "include/sensing/ranges.hpp:7" in said[1]
    assert not any(d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")
                   for d in result.diagnostics)
