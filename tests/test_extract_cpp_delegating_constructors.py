"""A constructor that delegates to another (``Filter(nh, priv) : Filter(nh, priv, name)``)
gives the members what the constructor it delegates to gives them, with the arguments of
the delegation: robot_localization's ``RosFilter<T>`` reads its parameters through the
private handle the short constructor passes on. Before, the short constructor counted as
one that leaves the members at their defaults, so every read of a member handle was made
twice, once in the private namespace and once, wrongly, in the node's."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "delegating_constructors")


def _calls(source: str) -> list[tuple[str, str, str | None]]:
    found = extract_cpp([os.path.join(ROOT, "src", "filters", "src", source)],
                        scan([ROOT]), cache_dir=None)
    return [(c.kind, c.name, c.handle_namespace) for c in found.calls]


@pytest.mark.parametrize("source", ["templated_filter.cpp", "plain_filter.cpp"])
def test_a_delegating_constructor_passes_its_handles_on(source: str) -> None:
    # a class template keeps the delegation as an argument list, a class as a call
    assert _calls(source) == [
        ("read", "~frequency", "~"),
        ("publish", "odometry/filtered", None),
    ]


def test_the_delegation_is_one_construction_among_others() -> None:
    # ``Filter first(nh)`` delegates with ``NodeHandle("~")``; ``Filter second(nh,
    # NodeHandle("other"), 5)`` calls the full constructor itself: one read per handle,
    # and none in the node's own namespace, which no construction gives
    assert _calls("both_filter.cpp") == [
        ("read", "~frequency", "~"),
        ("read", "other/frequency", "other"),
    ]
