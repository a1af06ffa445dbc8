"""Golden tests of the build-file stage: every fixture under fixtures/build/ is a small
workspace shaped like real packages; ``expected.yaml`` beside it is the node -> sources
map (with kind, language, conditions and the declaring location) and the diagnostics.

HAROS_ARCH_CASE=<fixture> narrows the run to one case.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from conftest import FIXTURES, only_case

from haros_arch import cmake, pysetup
from haros_arch.workspace import scan

CASES = sorted(p.name for p in (FIXTURES / "build").iterdir() if (p / "expected.yaml").is_file())


def build_model(root: Path) -> dict:
    """The whole build-file stage over a workspace, as plain data."""
    ws = scan([str(root)], {})
    nodes: dict[str, dict] = {}
    diagnostics: list[str] = []
    for name in sorted(ws.packages):
        package = ws.packages[name]
        entry = pysetup.parse_package if package.build_type == "ament_python" else (
            cmake.parse_package)
        found_nodes, found = entry(package, ws)
        for node in found_nodes:
            nodes[node.name] = {
                "kind": node.kind, "language": node.language, "sources": node.sources,
                "conditions": [str(c) for c in node.conditions],
                "declared": f"{node.location.file}:{node.location.line}",
            }
        diagnostics.extend(f"{d.code} {d.location.file}:{d.location.line}" for d in found)
    return {"nodes": nodes, "diagnostics": sorted(diagnostics)}


@pytest.mark.parametrize("case", [c for c in CASES if only_case() in (None, c)])
def test_build_fixture(case: str) -> None:
    root = FIXTURES / "build" / case
    expected = yaml.safe_load((root / "expected.yaml").read_text())
    got = build_model(root)
    assert got["nodes"] == expected["nodes"]
    assert got["diagnostics"] == sorted(expected.get("diagnostics") or [])


def test_every_fixture_has_a_golden_file() -> None:
    folders = sorted(p.name for p in (FIXTURES / "build").iterdir() if p.is_dir())
    assert folders == CASES and len(CASES) >= 7
