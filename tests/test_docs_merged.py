"""The documents are whole: no merge's conflict markers left in README.md, bench/README.md
or DESIGN notes (a word merge of two branches' paragraphs once left them in a landed
README, mid-sentence)."""

from __future__ import annotations

import re

import pytest
from conftest import ROOT

MARKERS = re.compile(r"^(<{7}|>{7}) |<{7} \S+|>{7} \S+|^={7}$", re.M)


@pytest.mark.parametrize("name", ["README.md", "bench/README.md"])
def test_no_conflict_markers(name: str) -> None:
    text = (ROOT / name).read_text(encoding="utf-8")
    found = [text[max(0, m.start() - 40):m.end() + 40] for m in MARKERS.finditer(text)]
    assert found == []
