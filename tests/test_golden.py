"""Golden models: each fixtures/<case>/ with an expected.json is extracted and compared.

HAROS_ARCH_CASE=<case> narrows the run to one case; HAROS_ARCH_UPDATE_GOLDEN=1 rewrites
the expected files (review the diff before committing it).
"""

from __future__ import annotations

import json
import os

import pytest
from conftest import FIXTURES, only_case

from haros_arch.model.serialise import model_to_data
from haros_arch.pipeline import analyse
from haros_arch.project import load

CASES = sorted(p.parent.name for p in FIXTURES.glob("*/expected.json"))
if only_case():
    CASES = [c for c in CASES if c == only_case()]

# a clean environment: no ROS_PACKAGE_PATH or ROS_VERSION from the machine running tests
ENV = {"PATH": os.environ.get("PATH", "")}


def extract(case: str) -> dict:
    project = load(str(FIXTURES / case / "project.yaml"))
    return json.loads(json.dumps(model_to_data(analyse(project, ENV))))


@pytest.mark.parametrize("case", CASES)
def test_golden_model(case):
    expected_path = FIXTURES / case / "expected.json"
    actual = extract(case)
    if os.environ.get("HAROS_ARCH_UPDATE_GOLDEN"):
        expected_path.write_text(json.dumps(actual, indent=2) + "\n")
    assert actual == json.loads(expected_path.read_text())
