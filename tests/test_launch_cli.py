"""`haros-arch launch` on a ROS 2 Python launch file shows components and their container."""

from __future__ import annotations

import json

from conftest import ROOT

from haros_arch.cli import main


def test_launch_dump_of_the_rover(capsys):
    code = main(["launch", "demo_rover", "launch/rover.launch.py",
                 "--workspace", str(ROOT / "examples/src"), "--format", "json"])
    assert code == 0
    data = json.loads(capsys.readouterr().out)
    nodes = {n["name"]: n for n in data["nodes"]}
    lidar = nodes["/rover/lidar_filter"]
    assert (lidar["ros_version"], lidar["composable"], lidar["container"]) == (
        2, True, "/rover/rover_container")
    assert lidar["executable"] == "demo_rover::LidarFilter"
    assert lidar["remaps"] == [["scan", "lidar/scan"]]
    assert data["parameters"]["/rover/safety_stop/stop_distance"] == 0.5
    assert data["parameters"]["/rover/lidar_filter/min_range"] == 0.25
