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


def test_time_bound_reports_an_alarm_the_example_swallowed() -> None:
    """The alarm's Hang can land in a gc callback or a library's ``except``, which
    drop it: the bound still reports the example as past its time."""
    import contextlib
    import time

    from fuzzing import Hang, time_bound

    with pytest.raises(Hang), time_bound(0.05):
        end = time.monotonic() + 0.5
        while time.monotonic() < end:
            with contextlib.suppress(Hang):
                time.sleep(0.01)
