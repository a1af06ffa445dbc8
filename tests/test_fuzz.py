"""Every reader entry point, fed a few mutations of its fixtures: a diagnostic or its
documented error, never another exception, never past the time bound (``fuzzing.py``;
``scripts/fuzz SECONDS`` runs the same targets for longer)."""

from __future__ import annotations

import pytest

hypothesis = pytest.importorskip("hypothesis")

from fuzzing import TARGETS  # noqa: E402
from hypothesis import HealthCheck, given, settings  # noqa: E402

BRIEF = settings(max_examples=12, deadline=None, derandomize=True, database=None,
                 suppress_health_check=list(HealthCheck))


@pytest.mark.parametrize("name", sorted(TARGETS))
def test_reader_survives_mutated_inputs(name: str) -> None:
    target = TARGETS[name]

    @BRIEF
    @given(target.strategy())
    def check(data: bytes) -> None:
        target.check(data)

    check()
