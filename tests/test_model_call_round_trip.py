"""A call reads back as it was written (``model.load.call_from_data`` of
``serialise.to_data``): every text field of ``PrimitiveCall`` set, one at a time. A link's
call that lost one (``loads_given``, navigation2's ``<id>.plugin`` reads) made the model
read back otherwise, and ``runcache.store`` keeps no such model: every re-run of
navigation2's bringup with nothing changed ran whole (4 s, not under 2)."""

from __future__ import annotations

import dataclasses

import pytest

from haros_arch.model.load import call_from_data
from haros_arch.model.serialise import to_data
from haros_arch.model.source import PrimitiveCall

TEXTS = [f.name for f in dataclasses.fields(PrimitiveCall)
         if str(f.type).replace(" ", "") in ("str|None", "Optional[str]")]


def test_there_are_text_fields() -> None:
    assert {"loads_given", "namespace_param", "name_param", "transport"} <= set(TEXTS)


@pytest.mark.parametrize("name", TEXTS)
def test_a_text_field_reads_back(name: str) -> None:
    call = dataclasses.replace(PrimitiveCall("read", "x"), **{name: "some_value"})
    assert call_from_data(to_data(call)) == call
