"""A clang error that names a header haros-arch synthesised says it without the run's
temporary folder: the same message in every run, and in the cache."""

from __future__ import annotations

from haros_arch.extract.cpp import error_detail


def test_a_clang_error_names_a_synthesised_header_without_the_run_s_folder() -> None:
    # Autoware's net_monitor.cpp:187, as a cold run said it
    said = ("conditional expression is ambiguous; 'haros_any::(unnamed enum at "
            "/tmp/haros-arch-cpp-nco2lj0m/haros_synthesised_names.h:124:3)' can be "
            "converted to 'haros_any' and vice versa")
    assert error_detail(said, "/tmp/haros-arch-cpp-nco2lj0m") == (
        "conditional expression is ambiguous; 'haros_any::(unnamed enum at "
        "haros_synthesised_names.h:124:3)' can be converted to 'haros_any' and vice versa")
    assert error_detail("expected ';'", "/tmp/haros-arch-cpp-x/") == "expected ';'"
