"""Golden results of the ROS 2 bring-up fixtures (fixtures/launch_ros2).

Each case launches one file of the fixture workspace with some arguments; the node
declarations and parameters it gives are compared with ``expected/<case>.json``, which
were checked by hand against what launch_ros does. ``HAROS_ARCH_CASE=name`` runs one
case; ``HAROS_ARCH_GOLDEN=write`` rewrites the files (review the diff before committing).
"""

from __future__ import annotations

import json
import os
from typing import Any

import pytest
from conftest import FIXTURES, only_case

from haros_arch.launch import load
from haros_arch.launch.model import LaunchModel
from haros_arch.workspace import scan

ROOT = FIXTURES / "launch_ros2"
CASES: dict[str, tuple[str, dict[str, str]]] = {
    "bringup_composed": ("rover_bringup/launch/bringup_launch.py", {}),
    "bringup_plain_namespaced": ("rover_bringup/launch/bringup_launch.py", {
        "use_composition": "False", "namespace": "scout", "use_namespace": "true"}),
    "fleet_plain": ("rover_bringup/launch/fleet_launch.py", {}),
    "fleet_composed": ("rover_bringup/launch/fleet_launch.py", {"use_composition": "True"}),
    "sensors_xml": ("rover_sensors/launch/sensors.launch.xml", {
        "robot": "rover1", "use_imu": "false", "lidar_model": "x2"}),
    "camera_yaml": ("rover_sensors/launch/camera.launch.yaml", {"fps": "60"}),
}


def summary(model: LaunchModel) -> dict[str, Any]:
    def short(path: str) -> str:
        return path.replace(str(ROOT), "$WS")

    return {
        "nodes": [{
            "name": n.name, "package": n.package, "executable": n.executable,
            "namespace": n.namespace, "remaps": [list(r) for r in n.remaps],
            "args": n.args, "conditions": [f"{c.statement}: {c.text}" for c in n.conditions],
            "composable": n.composable, "container": n.container,
            "ros_version": n.ros_version, "file": n.location.file, "line": n.location.line,
        } for n in model.nodes],
        "params": {p.name: short(p.value) if isinstance(p.value, str) else p.value
                   for p in model.params},
        "param_owners": sorted({str(p.node) for p in model.params}),
        "param_keys_consistent": all(p.name == f"{p.node}/{p.key}" for p in model.params),
        "conditional_params": sorted(p.name for p in model.params if p.conditions),
        "args": {k: short(v) if isinstance(v, str) else v for k, v in model.args.items()},
        "files": model.files,
        "diagnostics": sorted(f"{d.code} {d.location.file}:{d.location.line}"
                              for d in model.diagnostics),
    }


@pytest.mark.parametrize("case", [c for c in CASES if only_case() in (None, c)])
def test_golden(case: str) -> None:
    path, args = CASES[case]
    workspace = scan([str(ROOT / "src")], {})
    model = load(str(ROOT / "src" / path), workspace, args, {})
    got = summary(model)
    golden = ROOT / "expected" / f"{case}.json"
    if os.environ.get("HAROS_ARCH_GOLDEN") == "write":
        golden.write_text(json.dumps(got, indent=1, sort_keys=True) + "\n")
    expected = json.loads(golden.read_text())
    assert got == expected
